"""A warning about the scene as a whole (analysis.SCENE_WIDE_WARNINGS) reaches the note as well as the console: a
student who missed the console's line handed in a note of 550-m links that said nothing of them."""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import numpy as np
import pytest
from test_lengths_in_millimetres import scaled
from test_stroke_choice import SLOTTED_BY_A_SLIDER, crusher

import graphplan
from graphplan.analysis import SCENE_WIDE_WARNINGS, analyse
from graphplan.locale import strings
from graphplan.motion import solve
from graphplan.report.note import note_markdown

LOCALES = ("en", "ru", "zh")
CAUTION = {"en": "Caution: ", "ru": "Внимание: ", "zh": "注意："}


def _note(scene, locale: str) -> str:
    return note_markdown(analyse(dataclasses.replace(scene, locale=locale)))


def _other_cautions(note: str, locale: str) -> str:
    """The note without its caution that the slotted link's resisting load turns round within its working stroke
    (its point D on the arc rises and then sinks there): true of the scene, and not the caution these tests ask."""
    return note.replace(strings(locale)["note_warning_resisting_turns_round"], "")


@pytest.mark.parametrize("locale", LOCALES)
def test_lengths_in_millimetres_are_told_in_the_note_under_the_initial_data(locale):
    note = _note(graphplan.load(scaled(1000.0)), locale)
    told = strings(locale)["note_warning_lengths_in_mm"].split("{")[0]
    assert told.startswith(CAUTION[locale]) and told in note
    # Under the table of the dimensions it is about, before the plans.
    assert note.index("| 550 ") < note.index(told) < note.index("\n## 3")
    assert CAUTION[locale] not in _note(graphplan.load(scaled(1.0)), locale)


def _fixture_slipped(path: str, old: str, new: str, *drop: str) -> graphplan.scene.Scene:
    text = Path(path).read_text(encoding="utf-8")
    assert text.count(old) == 1
    text = text.replace(old, new)
    for line in drop:  # the scales that would refuse the drawings the slip swells: the run then writes its note
        text = "\n".join(row for row in text.split("\n") if not row.startswith(line))
    return graphplan.load_text(text)


def _written(value: float, locale: str) -> str:
    """A length as the note writes it here, to its fifth digit (7.5e-05 as 0.000075, 3.0 as 3)."""
    return f"{float(f'{value:.5g}'):.8f}".rstrip("0").rstrip(".").replace(".", "," if locale == "ru" else ".")


@pytest.mark.parametrize("locale", LOCALES)
def test_a_crank_a_thousandth_of_itself_is_told_in_the_note_with_what_was_meant(locale):
    """The yoke's crank typed 7.5e-05 m, its centre 0.025 m out, the scales left to the program: the drawings fit,
    the run writes its note, which said the dimensions were larger than any machine's and probably millimetres.  It
    names the length as the note does (lOA), 0.025 / 7.5e-05 = 333 times shorter, and the 0.075 m meant."""
    note = _note(_fixture_slipped("fixtures/scotch_yoke.toml", "length  = 0.075", "length  = 7.5e-05",
                                  "length_scale", "velocity_pole", "acceleration_pole"), locale)
    told = strings(locale)["note_warning_length_a_thousandth"].format(
        length="lOA", value=_written(7.5e-05, locale), meant=_written(0.075, locale), times=round(0.025 / 7.5e-05))
    assert told in note and "driver.length" not in note  # the note's reader has no scene to look a key up in
    assert strings(locale)["note_warning_lengths_in_mm"].split("{")[0] not in note


@pytest.mark.parametrize("locale", LOCALES)
def test_a_centre_far_off_its_link_is_told_in_the_note_with_where_it_was_meant(locale):
    """The triad's S6 3 m to the left of B (0.06 m along BD) on a link whose sides are 0.12, 0.108 and 0.108 m:
    |0.06 + 3j| / 0.12 = 25 times the link's span; with the offset in metres, |0.06 + 0.003j| from B."""
    slipped = _fixture_slipped("fixtures/triad_class_iii.toml", "at = 0.06, offset = 0.03 }", "at = 0.06, offset = 3.0 }")
    # Without sheets: μl is then fitted to the plan of positions, not chosen by laying the course sheets out, which
    # S6's inertia loads, crowding every force sheet, made a minute of each locale's run; the warning is the same.
    note = _note(dataclasses.replace(slipped, drawing=dataclasses.replace(slipped.drawing, sheet="none")), locale)
    told = strings(locale)["note_warning_point_far_off"].format(
        point="S6", start="B", reach=_written(abs(0.06 + 3j), locale), meant=_written(abs(0.06 + 0.003j), locale),
        times=round(abs(0.06 + 3j) / 0.12))
    assert told in note and "points.S6" not in note
    assert strings(locale)["note_warning_lengths_in_mm"].split("{")[0] not in note


@pytest.mark.parametrize("locale", LOCALES)
def test_a_working_sense_never_taken_is_told_in_the_note(locale):
    idle = graphplan.scene.loads(SLOTTED_BY_A_SLIDER.replace("SENSE", "cw"))
    note = _note(idle, locale)
    assert strings(locale)["note_warning_idle_throughout"].format(link=4) in note
    assert CAUTION[locale] not in _other_cautions(
        _note(graphplan.scene.loads(SLOTTED_BY_A_SLIDER.replace("SENSE", "ccw")), locale), locale)


@pytest.mark.parametrize("locale", LOCALES)
def test_every_scene_wide_warning_has_the_note_s_sentence(locale):
    text = strings(locale)
    assert [code for code in sorted(SCENE_WIDE_WARNINGS) if "note_warning_" + code.replace("-", "_") not in text] == []


@pytest.mark.parametrize("locale", LOCALES)
def test_a_load_of_an_idle_stroke_never_reached_is_told_in_the_note(locale):
    scene = SLOTTED_BY_A_SLIDER.replace("SENSE", "ccw")
    note = _note(graphplan.scene.loads(scene.replace('during = "working"', 'during = "idle"')), locale)
    assert strings(locale)["note_warning_working_throughout"].format(link=4) in note
    assert CAUTION[locale] not in _other_cautions(_note(graphplan.scene.loads(scene), locale), locale)


@pytest.mark.parametrize("locale", LOCALES)
def test_a_working_link_that_turns_back_more_than_twice_is_told_in_the_note_after_its_strokes(locale, tmp_path):
    """The crusher's jaw turns back four times a turn; the strokes paragraph names two extremes as if it swung once,
    and only the console said they were a choice.  The note now gives the turning-back angles, found here
    independently as the zeros of the jaw's angle's derivative by finite differences on a 0.01° grid."""
    analysis = analyse(dataclasses.replace(graphplan.load(crusher(tmp_path, '"extreme"')), locale=locale))
    grid = np.radians(np.arange(0.0, 360.0, 0.01))
    jaw = solve(analysis.mechanism, grid, analysis.positions.reference).point("E").r  # link 6 turns about F
    angle = np.unwrap(np.arctan2(jaw[:, 1] - 1.20, jaw[:, 0] + 0.50))
    rate = np.gradient(angle, grid)
    turning = np.flatnonzero(np.sign(rate) != np.sign(np.roll(rate, -1)))
    mark = "," if locale == "ru" else "."
    note = note_markdown(analysis)
    told = next(line for line in note.splitlines() if line.startswith(CAUTION[locale]) and " 4 " in line)
    printed = [float(value.replace(mark, ".")) for value in re.findall(r"(\d+[.,]\d\d)°", told)]
    assert len(turning) == len(printed) == 4
    assert printed == pytest.approx(sorted(np.degrees(grid[turning]) % 360.0), abs=0.02)
    # Right after the strokes paragraph that names the two extremes it qualifies.
    paragraphs = note.split("\n\n")
    here = next(k for k, paragraph in enumerate(paragraphs) if told in paragraph)
    assert paragraphs[here - 1].startswith(strings(locale)["note_strokes"].split("{")[0])
    straight = dataclasses.replace(graphplan.load("fixtures/stephenson_six_bar.toml"), locale=locale)
    assert CAUTION[locale] not in note_markdown(analyse(straight))
