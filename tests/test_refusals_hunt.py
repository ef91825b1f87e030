"""Scenes graphplan must refuse, each at the key to change and with why, found by a hunt for gaps in its refusals.

* A resisting force whose point can never move along the force's line (a point of a slider on a frame guide with
  the force square to the guide, or a frame point a link turns about) has no motion to resist at any position.
* An RPR whose slide runs farther from the lever's pivot C than the block's pivot A comes: the block cannot reach the
  slide. The refusal names the offset's key and both distances, at the position where it fails and, where it fails
  at every angle, at A's farthest from C over the turn (checked against the circle A runs on).
* Balancing masses' or correction planes' names that look alike in other characters (a Cyrillic А beside the Latin
  A): the polygons and the note would letter two products alike. Each is refused saying which character is which,
  as the linkage's point names are.
"""

from __future__ import annotations

import math
import re
import unicodedata

import numpy as np
import pytest
from scene_texts import offset_slotted_lever, slider_crank_with_a_resisting_force

import graphplan
from graphplan.errors import AssemblyError

# --- a resisting force with no motion to resist -------------------------------------------------------------------

# A slider-crank: crank OA = 0.1 m about O, rod AB = 0.35 m, slider 4 at B on a frame guide through O at
# `guide_deg`; a resisting force of 100 N at B along `force_deg`. B's velocity is along the guide at every crank
# angle (the slider only translates along it), so its part along the force is |vB|·cos(force − guide).
def _slider_crank(guide_deg: float = 0.0, force_deg: float = 90.0, link: int = 4, point: str = "B") -> str:
    return slider_crank_with_a_resisting_force("Slider-crank with a resisting force on its slider", guide_deg,
                                               force_deg, link, point) + "[positions]\ncount = 12\n"


@pytest.mark.parametrize(("guide_deg", "force_deg"), [(0.0, 90.0), (0.0, -90.0), (30.0, 120.0), (30.0, 300.0)])
def test_a_resisting_force_square_to_its_sliders_frame_guide_is_refused(guide_deg, force_deg):
    text = _slider_crank(guide_deg, force_deg)
    # The slider's point moves along the guide alone: along the force's line its speed is rounding at every angle.
    motion = graphplan.solve(graphplan.load_text(_slider_crank(guide_deg, guide_deg)),
                             driver=np.radians(np.arange(0.0, 360.0, 1.0)))
    along = np.array([math.cos(math.radians(force_deg)), math.sin(math.radians(force_deg))])
    speed = motion.point("B").v
    assert np.all(np.abs(speed @ along) <= 1e-12 * np.abs(speed).max())
    with pytest.raises(graphplan.SceneError) as caught:
        graphplan.build(graphplan.load_text(text))
    assert str(caught.value) == (
        f"loads[0].resisting: B on link 4 moves only along its frame guide (at {guide_deg:g}°), square to the "
        f"force's line (at {force_deg:g}°), so it has no motion along that line to resist at any position: "
        "turn the force along the guide or the guide along the force, or give it a set sense (resisting = false)")


@pytest.mark.parametrize(("guide_deg", "force_deg"), [(0.0, 180.0), (0.0, 89.0), (30.0, 45.0)])
def test_a_resisting_force_with_a_part_along_the_guide_is_taken(guide_deg, force_deg):
    mechanism = graphplan.build(graphplan.load_text(_slider_crank(guide_deg, force_deg)))
    assert len(mechanism.scene.loads) == 1


def test_a_resisting_force_square_to_the_guide_with_a_set_sense_is_taken():
    """Of a set sense, the force square to the guide is a load the guide takes: it stays."""
    text = _slider_crank().replace("resisting = true", "resisting = false")
    assert len(graphplan.build(graphplan.load_text(text)).scene.loads) == 1


def test_a_resisting_force_at_the_pivot_a_link_turns_about_is_refused():
    # O is a frame point: the crank turns about it, and it never moves along any line.
    with pytest.raises(graphplan.SceneError) as caught:
        graphplan.build(graphplan.load_text(_slider_crank(force_deg=30.0, link=2, point="O")))
    assert str(caught.value) == (
        "loads[0].resisting: O is a point of the frame (link 2 turns about it), so it never moves and a force there "
        "has no motion to resist: put the force at a point that moves, or give it a set sense (resisting = false)")


def test_a_resisting_force_square_to_a_named_frame_line_is_refused():
    text = _slider_crank().replace("guide = { through = [0.0, 0.0], angle = 0.0 }", 'guide = "x"').replace(
        "points = { O = [0.0, 0.0] }", 'points = { O = [0.0, 0.0] }\nlines = { x = { through = [0.0, 0.0], angle = 0.0 } }')
    with pytest.raises(graphplan.SceneError, match=r"^loads\[0\]\.resisting: B on link 4 moves only along"):
        graphplan.build(graphplan.load_text(text))


# --- an RPR's slide out of its block's reach ----------------------------------------------------------------------

# A slotted lever: crank OA = 0.15 m about O = (0, 0), the lever turning about C = (0.06, −0.04) m, its slide
# `offset` m to the left of C. A runs on the circle of 0.15 m about O, so |CA| ranges between 0.15 − |OC| and
# 0.15 + |OC|, |OC| = √(0.06² + 0.04²) = 0.0721110 m: 0.0778890 m to 0.2221110 m, the farthest where A stands
# opposite C across O, at φ = atan2(0.04, −0.06) = 146.3099°. The block pivoted at A reaches a slide |offset| m
# from C only where |CA| > |offset|.
def offset_slot(offset: float) -> str:
    return offset_slotted_lever(offset) + """
[positions]
count = 12
start = 90.0
"""


OC = math.hypot(0.06, 0.04)


def _rpr_refusal(offset: float) -> AssemblyError:
    with pytest.raises(AssemblyError) as caught:
        graphplan.solve(graphplan.load_text(offset_slot(offset)))
    return caught.value


@pytest.mark.parametrize("offset", [0.5, -0.5])
def test_an_rpr_slide_farther_from_c_than_a_ever_comes_names_the_offset_and_a_s_farthest(offset):
    message = str(_rpr_refusal(offset))
    # The first position, φ = 90°: A = (0, 0.15), |CA| = √(0.06² + 0.19²).
    ca = math.hypot(0.06, 0.19)
    head = (f"A cannot be assembled at position 1 (φ = 90°) in group II(3,4): the slide runs 0.5 m from C "
            f"but A is only {ca:.6g} m from C, so the block at A cannot reach it; the scene's keys "
            f"that set it: groups[0].offset = {offset}, driver.length = 0.15, frame.points.O, frame.points.C; ")
    assert message.startswith(head), message
    farthest = 0.15 + OC
    tail = message[len(head):]
    found = re.fullmatch(r"the mechanism assembles at no angle of link 2: A comes no farther than ([\d.]+) m from C "
                         r"\(at φ = ([\d.]+)°\), short of the slide's 0\.5 m: give groups\[0\]\.offset a size up to "
                         r"([\d.]+) m", tail)
    assert found, tail
    assert float(found[1]) == pytest.approx(farthest, abs=1e-6)
    assert float(found[2]) == pytest.approx(math.degrees(math.atan2(0.04, -0.06)), abs=0.01)
    # The size advised is one the block reaches, to four figures: below the farthest, not up to it.
    assert farthest - 1e-4 <= float(found[3]) < farthest
    assert "check the lengths" not in message


def test_an_rpr_slide_out_of_reach_at_some_angles_names_the_offset_the_distance_and_the_angle():
    message = str(_rpr_refusal(0.1))
    # Position 8 of 12 from 90°: φ = 90° + 7·30° = 300°, A = 0.15·(cos 300°, sin 300°).
    a = complex(0.15 * math.cos(math.radians(300.0)), 0.15 * math.sin(math.radians(300.0)))
    ca = abs(a - complex(0.06, -0.04))
    assert ca < 0.1
    assert message.startswith(
        f"A cannot be assembled at position 8 (φ = 300°) in group II(3,4): the slide runs 0.1 m from C "
        f"but A is only {ca:.6g} m from C, so the block at A cannot reach it; the scene's keys "
        "that set it: groups[0].offset = 0.1, driver.length = 0.15, frame.points.O, frame.points.C; link 2 reaches "
        "only from "), message


# --- balancing names that look alike --------------------------------------------------------------------------------

# Two masses in two planes, balanced in planes at 0 and 1 m; names and the planes' names filled in per test. The
# Latin A is U+0041 and the Cyrillic А U+0410; the Latin B U+0042 and the Cyrillic В U+0412: drawn alike, the
# polygons and the note would letter two products mArA.
LATIN_A, CYRILLIC_A, LATIN_B, CYRILLIC_B = "A", "\u0410", "B", "\u0412"
ROTOR = """
[scene]
title = "Rotor"
[balancing]
masses = [ {{ mass = 2.0, radius = 0.1, angle = 30.0, plane = 0.3, name = "{first}" }},
           {{ mass = 1.0, radius = 0.1, angle = 200.0, plane = 0.8, name = "{second}" }} ]
planes = [0.0, 1.0]
{plane_names}
"""


def _rotor_refusal(first: str, second: str, plane_names: str = "") -> str:
    with pytest.raises(graphplan.SceneError) as caught:
        graphplan.load_text(ROTOR.format(first=first, second=second, plane_names=plane_names))
    return str(caught.value)


def test_two_masses_whose_names_look_alike_are_refused_saying_which_character_is_which():
    assert CYRILLIC_A != LATIN_A and unicodedata.name(CYRILLIC_A) == "CYRILLIC CAPITAL LETTER A"
    assert _rotor_refusal(LATIN_A, CYRILLIC_A) == (
        f"balancing.masses[1].name: looks the same as the name of balancing.masses[0] ('A'), and the polygons and the "
        f"note would letter both alike; '{CYRILLIC_A}' has the Cyrillic '{CYRILLIC_A}' (U+0410) where 'A' has the "
        f"Latin 'A' (U+0041): name the two apart (got '{CYRILLIC_A}')")


def test_two_correction_planes_whose_names_look_alike_are_refused_saying_which_character_is_which():
    message = _rotor_refusal("1", "2", f'plane_names = ["{LATIN_B}", "{CYRILLIC_B}"]')
    assert message == (
        f"balancing.plane_names: '{CYRILLIC_B}' looks the same as 'B', and the polygons and the note would letter "
        f"both alike; '{CYRILLIC_B}' has the Cyrillic '{CYRILLIC_B}' (U+0412) where 'B' has the Latin 'B' (U+0042): "
        f'name the two apart (got ["B", "{CYRILLIC_B}"])')


def test_a_plane_named_like_a_mass_in_other_characters_is_refused_saying_which_character_is_which():
    # The plane A's correction m·r would read mArA, as mass А's does.
    message = _rotor_refusal(CYRILLIC_A, "2", f'plane_names = ["{LATIN_A}", "R"]')
    assert message.startswith(
        "balancing.plane_names: the product of correction plane 'A' and that of balancing.masses[0] (named "
        f"'{CYRILLIC_A}') would both read mArA on the polygons and in the note"), message
    # Told at the planes' key, the plane's name first.
    assert f"'A' has the Latin 'A' (U+0041) where '{CYRILLIC_A}' has the Cyrillic '{CYRILLIC_A}' (U+0410)" in message


def test_the_balancing_specification_refuses_names_that_look_alike_too():
    from graphplan.rotor_balancing import BalancingSpec, RotatingMass

    with pytest.raises(ValueError, match=r"^masses\[1\]\.name: looks the same as the name of an earlier mass \('A'\); "
                                         r".*\(U\+0410\) where 'A' has the Latin 'A' \(U\+0041\)"):
        BalancingSpec([RotatingMass(1, 0.1, 0, name=LATIN_A), RotatingMass(1, 0.1, 90, name=CYRILLIC_A)])
    with pytest.raises(ValueError, match=r"^plane_names: .*\(U\+0412\) where 'B' has the Latin 'B' \(U\+0042\)"):
        BalancingSpec([RotatingMass(1, 0.1, 0, plane=0.3)], planes=(0.0, 1.0), plane_names=(LATIN_B, CYRILLIC_B))
    # Names that look apart stay.
    assert BalancingSpec([RotatingMass(1, 0.1, 0, name="A"), RotatingMass(1, 0.1, 90, name="D")]).plane_names == ("b",)
