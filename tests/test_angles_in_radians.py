"""An angle typed in radians where the scene takes degrees: a cylinder axis at 1.5708 for 90° ran the engine with its
piston along x, a load at 3.1416 for 180° pushed the piston away from the crank, a swing of [0.5236, 1.0472] rocked
the lever through half a degree, all without a word.  Each is told at the key, with the fraction of π it is and the
degrees likely meant; angles a drawing is laid off at are not."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from test_motion_against_finite_differences import _HUNG_ON_THE_RATCHET, _hung_on_the_ratchet

from graphplan.errors import AssemblyError
from graphplan.scene import loads

# Scenes given their slips on purpose: scene.analyse() warns of each with a UserWarning, as the command line does,
# and these tests read the analysis's warnings themselves.
pytestmark = pytest.mark.filterwarnings(r"ignore:[a-z]+(-[a-z]+)+\b:UserWarning")

ENGINE = Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8")
ROCKER = Path("fixtures/double_rocker_swing.toml").read_text(encoding="utf-8")


def _edited(text: str, old: str, new: str) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def _told(text: str) -> list[str]:
    return [warning.detail for warning in loads(text).analyse().warnings if warning.code == "angle-in-radians"]


@pytest.mark.parametrize(("text", "old", "key", "radians", "of_pi"), [
    (ENGINE, 'guide    = { through = "O", angle = 0.0 }', "groups[0].guide.angle", math.pi / 2, "π/2"),
    (ENGINE, "angle     = 180.0", "loads[0].angle", math.pi, "π"),
    (ENGINE, "angle     = 180.0", "loads[0].angle", -3.0 * math.pi / 4, "−3π/4"),
    (ENGINE, 'start       = "extreme"', "positions.start", math.pi / 4, "π/4"),
], ids=["guide", "load", "negative", "start"])
def test_an_angle_typed_in_radians_is_told_with_the_degrees_meant(text, old, key, radians, of_pi):
    typed = round(radians, 4)  # as a student types it off a calculator
    value = {"groups[0].guide.angle": f'guide    = {{ through = "O", angle = {typed} }}',
             "loads[0].angle": f"angle     = {typed}", "positions.start": f"start       = {typed}"}[key]
    (detail,) = _told(_edited(text, old, value))
    meant = round(math.degrees(radians))
    assert detail == (f"{key} = {typed:g} is {of_pi} in radians: the scene's angles are in degrees, so it is taken as "
                      f"{typed:g}°; give {meant} if {meant}° is meant")


def test_an_rpp_s_slot_angle_typed_in_radians_is_told():
    """The scotch yoke's slot at 1.5708 to its guide: a slot nearly along the guide, its block thrown far along it."""
    yoke = Path("fixtures/scotch_yoke.toml").read_text(encoding="utf-8")
    told = _told(_edited(yoke, "angle  = 90.0                             #", "angle  = 1.5708   #"))
    assert told == [("groups[0].angle = 1.5708 is π/2 in radians: the scene's angles are in degrees, so it is taken "
                     "as 1.5708°; give 90 if 90° is meant")]


def test_a_triad_s_slot_angle_typed_in_radians_is_told():
    """A triad's slot at 2.0944 to the ternary link's BD for 120°: the block slides in another slot, which the
    ratchet's triad assembles in too, so nothing else stops it."""
    group = _HUNG_ON_THE_RATCHET["ratchet+triad-slot"]
    slotted = _hung_on_the_ratchet(_edited(group, "slots = { G = { angle = -77.0 } }",
                                           "slots = { G = { angle = 2.0944 } }"))
    told = [warning.detail for warning in slotted().analyse().warnings if warning.code == "angle-in-radians"]
    assert told == [("groups[1].slots.G.angle = 2.0944 is 2π/3 in radians: the scene's angles are in degrees, so it is "
                     "taken as 2.0944°; give 120 if 120° is meant")]
    assert not [warning for warning in _hung_on_the_ratchet(group)().analyse().warnings
                if warning.code == "angle-in-radians"]


def test_both_ends_of_a_swing_typed_in_radians_are_told():
    """The engine's crank swung over [0.5236, 1.0472]: half a degree, which it can, so the run goes on, told."""
    swinging = _edited(_edited(ENGINE, "epsilon = 0.0\n", "epsilon = 0.0\nswing = [0.5236, 1.0472]\n"),
                       'start       = "extreme"', "")
    told = _told(swinging)
    assert [detail.split(" in radians")[0] for detail in told] == ["driver.swing[0] = 0.5236 is π/6",
                                                                   "driver.swing[1] = 1.0472 is π/3"]
    assert [detail.rsplit("give ", 1)[1] for detail in told] == ["30 if 30° is meant", "60 if 60° is meant"]


def test_a_swing_in_radians_the_mechanism_cannot_reach_is_refused_with_the_degrees_meant():
    """The double rocker reaches 13.1° … 70.5° only: a swing typed in radians stops it at its first position, and
    the refusal says the swing is in radians (30° … 60°, which it reaches), not where else to swing it."""
    with pytest.raises(AssemblyError) as refused:
        loads(_edited(ROCKER, "swing   = [20.0, 65.0]", "swing   = [0.5236, 1.0472]")).analyse()
    message = str(refused.value)
    assert "driver.swing[0] = 0.5236 is π/6 in radians" in message and "give 30 if 30° is meant" in message
    assert "driver.swing[1] = 1.0472 is π/3 in radians" in message and "give 60 if 60° is meant" in message
    assert "keep driver.swing within" not in message
    assert len(loads(_edited(ROCKER, "swing   = [20.0, 65.0]", "swing   = [30.0, 60.0]")).analyse().positions.numbers)


@pytest.mark.parametrize("angle", ["90.0", "3.0", "1.2", "0.0", "47.124"],
                         ids=["degrees", "a whole degree", "no π", "zero", "beyond a turn in radians"])
def test_an_angle_in_degrees_is_not_told(angle):
    """3° is a whole degree a drawing is laid off at; 1.2 is no fraction of π a course's angle would be; 47.124° is
    15π to three decimals, but no angle typed in radians runs past a turn."""
    assert not _told(_edited(ENGINE, 'guide    = { through = "O", angle = 0.0 }',
                             f'guide    = {{ through = "O", angle = {angle} }}'))


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_note_says_so_under_its_initial_data(locale):
    """The note handed in says so too: the console's line is gone by then, and its drawings lay the guide off at
    1.57°."""
    from graphplan.locale import strings
    from graphplan.report.note import note_markdown

    slipped = _edited(ENGINE, 'guide    = { through = "O", angle = 0.0 }', 'guide    = { through = "O", angle = 1.5708 }')
    said = strings(locale)["note_warning_angle_in_radians"]
    assert said in note_markdown(loads(_edited(slipped, 'locale  = "en"', f'locale  = "{locale}"')).analyse())
    assert said not in note_markdown(loads(_edited(ENGINE, 'locale  = "en"', f'locale  = "{locale}"')).analyse())
