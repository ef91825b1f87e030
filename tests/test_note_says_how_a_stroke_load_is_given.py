"""The note's load-diagram paragraph says how the scene gave each load over a stroke.

A load given as one value over the working stroke (`during = "working"`) or over a window of it is drawn on the load
diagram as a rectangle, but the scene gave no diagram: the note said of every such load that it was "given by its
load diagram", which sent a reader looking for a diagram in the assignment.  What the scene gave is read here from
the scene's own text, not from graphplan's records.
"""

from __future__ import annotations

import dataclasses
import tomllib
from pathlib import Path

import pytest
from test_student_probe_dynamics_ru import COMPRESSOR  # the piston's diagram: a load that is a diagram

import graphplan
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown

FIXTURES = Path(__file__).parent.parent / "fixtures"


def paragraph(note: str, start: str) -> str:
    (found,) = [line for line in note.splitlines() if line.startswith(start)]
    return found


@pytest.mark.parametrize(("locale", "start", "over_stroke", "diagram_said"), [
    ("en", "The loads of link 4", "F4 = 4500 N over the whole working stroke", "by their load diagram"),
    ("ru", "Нагрузки звена 4", "F4 = 4500 Н на всём рабочем ходу", "заданы диаграммой нагрузок"),
    ("zh", "构件 4 的载荷", "F4 = 4500 N，作用于整个工作行程", "由载荷线图给出"),
])
def test_a_value_over_the_working_stroke_is_said_as_given(locale, start, over_stroke, diagram_said):
    tables = tomllib.loads((FIXTURES / "engine_slider_crank.toml").read_text(encoding="utf-8"))
    (load,) = [load for load in tables["loads"] if load.get("during") == "working"]
    assert "diagram" not in load and load["value"] == 4500.0
    scene = dataclasses.replace(graphplan.load(FIXTURES / "engine_slider_crank.toml"), locale=locale)
    said = paragraph(note_markdown(analyse(scene)), start)
    assert over_stroke in said
    assert diagram_said not in said, said


def test_a_window_is_said_with_its_ends():
    tables = tomllib.loads((FIXTURES / "offset_slider_crank.toml").read_text(encoding="utf-8"))
    (load,) = [load for load in tables["loads"] if isinstance(load.get("during"), dict)]
    window = load["during"]
    said = paragraph(note_markdown(analyse(graphplan.load(FIXTURES / "offset_slider_crank.toml"))), "The loads of")
    assert (f"= {load['value']:g} N from {window['from']:g} to {window['to']:g} of the working stroke") in said


def test_a_diagram_is_said_to_be_one():
    scene = graphplan.load_text(COMPRESSOR)
    said = paragraph(note_markdown(analyse(scene)), "Нагрузки звена 4")
    assert "F4 — диаграммой нагрузок" in said and "ходу" not in said


@pytest.mark.parametrize(("locale", "start", "one", "two"), [
    ("en", "The loads of link 4", "the plan position {} is the one with force sheets",
     "the plan positions {} are those with force sheets"),
    ("ru", "Нагрузки звена 4", "для положения {} построен лист силового расчёта",
     "для положений {} построены листы силового расчёта"),
])
def test_the_plan_positions_with_force_sheets_are_counted_in_the_words(locale, start, one, two):
    """«для положений 3 построены листы» of one position: the words follow how many there are."""
    scene = dataclasses.replace(graphplan.load(FIXTURES / "engine_slider_crank.toml"), locale=locale)
    numbers = [plan.number for plan in analyse(scene).plans if plan.forces is not None]
    assert len(numbers) >= 2
    said = paragraph(note_markdown(analyse(scene)), start)
    mark = ", "
    assert two.format(mark.join(map(str, numbers))) in said, said
    single = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, plans=(numbers[0],)))
    said = paragraph(note_markdown(analyse(single)), start)
    assert one.format(numbers[0]) in said, said
