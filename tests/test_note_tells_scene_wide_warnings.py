"""A warning about the scene as a whole (analysis.SCENE_WIDE_WARNINGS) reaches the note as well as the console: a
student who missed the console's line handed in a note of 550-m links that said nothing of them."""

from __future__ import annotations

import dataclasses

import pytest
from test_lengths_in_millimetres import scaled
from test_stroke_choice import SLOTTED_BY_A_SLIDER

import graphplan
from graphplan.analysis import SCENE_WIDE_WARNINGS, analyse
from graphplan.locale import strings
from graphplan.report.note import note_markdown

LOCALES = ("en", "ru", "zh")
CAUTION = {"en": "Caution: ", "ru": "Внимание: ", "zh": "注意："}


def _note(scene, locale: str) -> str:
    return note_markdown(analyse(dataclasses.replace(scene, locale=locale)))


@pytest.mark.parametrize("locale", LOCALES)
def test_lengths_in_millimetres_are_told_in_the_note_under_the_initial_data(locale):
    note = _note(graphplan.load(scaled(1000.0)), locale)
    told = strings(locale)["note_warning_lengths_in_mm"].split("{")[0]
    assert told.startswith(CAUTION[locale]) and told in note
    # Under the table of the dimensions it is about, before the plans.
    assert note.index("| 550 ") < note.index(told) < note.index("\n## 3")
    assert CAUTION[locale] not in _note(graphplan.load(scaled(1.0)), locale)


@pytest.mark.parametrize("locale", LOCALES)
def test_a_working_sense_never_taken_is_told_in_the_note(locale):
    idle = graphplan.scene.loads(SLOTTED_BY_A_SLIDER.replace("SENSE", "cw"))
    note = _note(idle, locale)
    assert strings(locale)["note_warning_idle_throughout"].format(link=4) in note
    assert CAUTION[locale] not in _note(graphplan.scene.loads(SLOTTED_BY_A_SLIDER.replace("SENSE", "ccw")), locale)


@pytest.mark.parametrize("locale", LOCALES)
def test_every_scene_wide_warning_has_the_note_s_sentence(locale):
    text = strings(locale)
    assert [code for code in sorted(SCENE_WIDE_WARNINGS) if "note_warning_" + code.replace("-", "_") not in text] == []


@pytest.mark.parametrize("locale", LOCALES)
def test_a_load_of_an_idle_stroke_never_reached_is_told_in_the_note(locale):
    scene = SLOTTED_BY_A_SLIDER.replace("SENSE", "ccw")
    note = _note(graphplan.scene.loads(scene.replace('during = "working"', 'during = "idle"')), locale)
    assert strings(locale)["note_warning_working_throughout"].format(link=4) in note
    assert CAUTION[locale] not in _note(graphplan.scene.loads(scene), locale)
