"""The note says at which positions the mechanism is near a singular one, in its own language.

The scene: the ratchet's crank-rocker with its coupler made so long that at the crank's 270° (position 3, the pin
farthest from C) coupler and rocker stand all but in line. The angle there is worked out here by the law of cosines
from the lengths alone, independently of the solver, so that the test knows the warning is due.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown

RATCHET = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"
COUPLER, ROCKER, FRAME, CRANK = 0.400005, 0.325, 0.55, 0.175


def near_toggle(locale: str) -> str:
    text = RATCHET.read_text(encoding="utf-8")
    text = text.replace("lengths  = [0.55, 0.325]", f"lengths  = [{COUPLER}, {ROCKER}]")
    text = re.sub(r'start\s*=\s*"extreme".*', "start       = 0.0", text)
    text = re.sub(r"\[measured\.5\][^\[]*", "", text)  # the readings of the fixture's own lengths
    return text.replace('locale  = "ru"', f'locale  = "{locale}"')


def _note_without_diagrams(analysis) -> str:
    """The note with no kinematic diagrams, which a run refuses to draw so near the toggle (their acceleration
    diagram would be half a metre tall) and so tells the scene to leave out of output.include."""
    return note_markdown(analysis, tells_diagrams=False)


def test_the_coupler_and_rocker_stand_all_but_in_line_at_position_3():
    farthest = FRAME + CRANK  # the pin below O, on the line OC: the crank at 270°, three 30° steps clockwise
    cosine = (COUPLER**2 + ROCKER**2 - farthest**2) / (2 * COUPLER * ROCKER)
    assert 180.0 - math.degrees(math.acos(cosine)) < graphplan.motion.ILL_CONDITIONED_DEG


@pytest.mark.parametrize(("locale", "words"), [
    ("en", "near a singular position"),
    ("ru", "близок к особому положению"),
    ("zh", "接近奇异位置"),
])
def test_the_note_names_the_position_near_a_singular_one(locale, words):
    analysis = analyse(graphplan.load_text(near_toggle(locale)))
    flagged = {int(analysis.positions.numbers[w.position]) for w in analysis.warnings if w.code == "ill-conditioned"}
    assert flagged == {3}
    said = [line for line in _note_without_diagrams(analysis).splitlines() if words in line]
    assert len(said) == 1
    assert re.search(r"(?<![\d.,])3(?![\d.,])", said[0])


def test_a_note_of_a_mechanism_far_from_singular_says_nothing_of_it():
    note = note_markdown(analyse(graphplan.load(RATCHET)))
    assert "близок к особому положению" not in note


@pytest.mark.parametrize(("locale", "words"), [
    ("en", "passes close to a singular position"),
    ("ru", "проходит вблизи особого положения"),
    ("zh", "经过奇异位置附近"),
])
def test_the_note_names_the_positions_a_singular_one_lies_between(locale, words):
    """Started at 15°, the positions step over the crank's 270° between position 3 (−75°) and 4 (−105°): none of
    them is near the singular position, but the mechanism passes it between them."""
    scene = graphplan.load_text(near_toggle(locale).replace("start       = 0.0", "start       = 15.0"))
    analysis = analyse(scene)
    assert {w.code for w in analysis.warnings} == {"toggle-between"}
    said = [line for line in _note_without_diagrams(analysis).splitlines() if words in line]
    assert len(said) == 1
    assert "3–4" in said[0]
