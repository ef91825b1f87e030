"""Words of the note a reviewer marked in Russian and Chinese: a rocker's swing ψ called the output link's
"перемещение" or its 行程 (a slider's stroke), where the textbook says угол размаха коромысла and 摇杆摆角; the
Russian "его даёт выбор рабочим хода…", no sentence; "ведущее звено" for the link the cycle's works are reckoned on,
the начальное звено; Table 2's guides in Chinese without the spaces the note puts between Chinese and Latin text."""

from __future__ import annotations

import functools
import math
import re

import numpy as np
import pytest
from scene_texts import crank_rocker_working_its_quicker_stroke

import graphplan
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown
from graphplan.starters import starter


@functools.cache
def _analysis(name: str, locale: str):
    return analyse(graphplan.scene.loads(starter(name, locale)))


@functools.cache
def _note(name: str, locale: str) -> str:
    return note_markdown(_analysis(name, locale))


def _swing_degrees(analysis) -> float:
    """The output link's swing between its extreme positions, from its angle over a dense sweep (the motion alone)."""
    working = analysis.scene.positions.working.link
    turn = np.linspace(0.0, 2.0 * np.pi, 20001)
    angle = np.unwrap(np.asarray(graphplan.solve(analysis.scene, turn).links[working].angle, dtype=float))
    return math.degrees(float(angle.max() - angle.min()))


@pytest.mark.parametrize(("name", "locale", "words"), [
    ("crank-rocker", "ru", "угол размаха коромысла ψ = "), ("crank-rocker", "zh", "摇杆摆角 ψ = "),
    ("slotted-lever", "ru", "угол размаха кулисы ψ = "), ("slotted-lever", "zh", "导杆摆角 ψ = "),
    ("crank-rocker", "en", "the rocker's swing ψ = ")])
def test_a_rocking_output_link_s_travel_is_its_swing(name, locale, words):
    note = _note(name, locale)
    assert "Перемещение выходного звена" not in note and "行程（标注在位置图上）" not in note
    found = re.search(rf"{re.escape(words)}(\d+[.,]\d)°", note)
    assert found, note[:3000]
    assert float(found[1].replace(",", ".")) == pytest.approx(_swing_degrees(_analysis(name, locale)), abs=0.051)


@pytest.mark.parametrize(("locale", "words"), [("ru", "ход H = "), ("zh", "行程 H = "), ("en", "the stroke H = ")])
def test_a_slider_s_travel_stays_its_stroke(locale, words):
    assert words in _note("slider-crank", locale)


def test_the_russian_note_says_how_the_working_stroke_is_made_the_slower_in_a_sentence():
    # The starter works in its slower stroke: worked in its quicker one, the note says how to make it the slower.
    note = note_markdown(analyse(graphplan.scene.loads(crank_rocker_working_its_quicker_stroke("ru"))))
    assert "K < 1" in note and "выбор рабочим" not in note
    assert "для этого рабочим ходом следует принять движение выходного звена в обратную сторону" in note


def test_the_russian_cycle_s_works_are_the_initial_link_s():
    note = _note("shaper", "ru")
    cycle = note[note.index("Уравновешивающий момент за цикл"):]
    assert "начальное звено" in cycle and "ведущее звено" not in cycle and "ведущему звену" not in cycle


def test_the_chinese_table_2_spaces_its_latin_from_its_chinese():
    note = _note("shaper", "zh")
    assert re.search(r"\| 距 O 0\.\d+ m，与 x 轴成 0° \|", note), note[:2500]
