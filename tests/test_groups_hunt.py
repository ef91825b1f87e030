"""What the groups tell the user in less common configurations, checked against hand geometry.

* Where a crank cannot turn round (or a slider's travel runs out), the refusal says what stops the mechanism at
  each end of its reach. That is a geometric fact of the group that stops it, and it differs by kind: an RRR's two
  links stand in line, an RRP's rod stands square to its guide, an RPR with an offset slide has its block at the
  foot of the perpendicular from the lever's pivot, a triad's three legs' lines meet in one point. Each is checked
  here at the end the message names, from the positions solved just inside it.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from scene_texts import offset_slotted_lever, slider_crank_with_a_resisting_force

import graphplan
from graphplan.errors import AssemblyError
from graphplan.loads import motion_state, resisted_sense
from graphplan.motion import solve as solve_motion

# A slider-crank whose rod is too short to reach the guide on every turn: crank OA = 0.1 m about O, the guide the
# line y = −0.05 m, the rod AB = 0.09 m. A is 0.1·sin φ + 0.05 m from the guide, which AB reaches while
# sin φ ≤ 0.4: the reach ends at φ = asin 0.4 = 23.578° and 180° − 23.578°, where A's distance is AB itself, so
# that B is the foot of A's perpendicular and the rod stands square to the guide (no two links in line there).
SHORT_ROD = """
[scene]
title = "Slider-crank with a short rod"
[frame]
link = 1
points = { O = [0.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.09
guide = { through = [0.0, -0.05], angle = 0.0 }
assembly = "forward"
[positions]
count = 12
"""

# A slotted lever whose slide runs 0.1 m to the left of its pivot C = (0.06, −0.04) m, driven by a crank
# OA = 0.15 m: the block assembles while |CA| > 0.1 m, and at each end of the crank's reach |CA| = 0.1 m, the
# block at the foot of the perpendicular from C on the slide.
OFFSET_SLOT = offset_slotted_lever(0.1) + """
[positions]
count = 12
start = 90.0
"""

# The fixture's class III triad with a crank of 0.09 m in place of 0.05 m: it stops short of a turn.
TRIAD = """
[scene]
title = "Crank and a class III triad that stops short of a turn"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.22, 0.0], E = [0.10, 0.35] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.09
omega = 10.0
[[groups]]
kind = "triad"
links = [3, 4, 5, 6]
joints = ["A", "B", "C", "D", "E", "F"]
lengths = [0.135, 0.108, 0.189]
sides = [0.12, 0.108, 0.108]
near = { B = [0.14, 0.10], D = [0.26, 0.10], F = [0.20, 0.19] }
[positions]
count = 12
"""

# A slider driving a second slider through a rod: A runs along the x axis, B along the line x = 0.1 m; the rod
# AB = 0.25 m reaches B while |xA − 0.1| ≤ 0.25, so up to s = 0.35 m, where AB lies along the x axis, square to
# B's guide.
SLIDER_AND_SHORT_ROD = """
[scene]
title = "Slider driving a slider through a rod"
[frame]
link = 1
points = { G = [0.0, 0.0] }
[driver]
kind = "slider"
link = 2
joint = "A"
guide = { through = "G", angle = 0.0 }
travel = [0.0, 0.5]
velocity = 0.5
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.25
guide = { through = [0.1, 0.0], angle = 90.0 }
assembly = "forward"
[positions]
count = 9
"""


def _refusal(text: str) -> AssemblyError:
    with pytest.raises(AssemblyError) as caught:
        graphplan.solve(graphplan.load_text(text))
    return caught.value


def _reach_ends_deg(message: str) -> list[float]:
    (span,) = re.findall(r"reaches only from (-?[\d.]+)° to (-?[\d.]+)°", message)
    return [float(end) for end in span]


def _at(scene, degrees: float) -> dict[str, complex]:
    motion = graphplan.solve(scene, driver=np.radians([degrees]))
    return {name: complex(*motion.point(name).r[0]) for name in motion.points}


def test_an_rrp_whose_rod_cannot_reach_its_guide_says_the_rod_stands_square_to_it():
    message = str(_refusal(SHORT_ROD))
    assert "(at each end the rod stands square to the guide)" in message
    assert "two links stand in line" not in message
    ends = _reach_ends_deg(message)
    reach = math.degrees(math.asin(0.4))
    assert sorted(end % 360.0 for end in ends) == pytest.approx([reach, 180.0 - reach], abs=0.01)


def test_an_rpr_with_an_offset_slide_says_its_block_stands_at_the_foot_of_the_pivots_perpendicular():
    message = str(_refusal(OFFSET_SLOT))
    assert "(at each end the block stands at the foot of the perpendicular from the lever's pivot to the slide)" \
        in message
    scene = graphplan.load_text(OFFSET_SLOT)
    for end, inward in zip(_reach_ends_deg(message), (0.001, -0.001)):
        points = _at(scene, end + inward)
        # |CA| comes down to the offset there: CA is then square to the slide, whose line is 0.1 m from C.
        assert abs(points["A"] - points["C"]) == pytest.approx(0.1, abs=2e-5)


def test_a_triad_that_stops_a_crank_says_its_three_legs_lines_meet_in_one_point():
    message = str(_refusal(TRIAD))
    assert "(at each end the lines of its three legs meet in one point)" in message
    mechanism = graphplan.build(graphplan.load_text(TRIAD))

    def at(degrees: float) -> dict[str, complex]:
        """The points at one crank angle, solved as graphplan.solve solves them but without its refusal's reach
        advice, which took seconds at each failing middle of the bisection."""
        motion = solve_motion(mechanism, np.radians([degrees]), None, indexed=True)
        return {name: complex(*motion.point(name).r[0]) for name in motion.points}

    def miss(degrees: float) -> float:
        """How far the line EF passes from where the lines AB and CD cross, in m."""
        p = at(degrees)
        ab, cd, ef = p["B"] - p["A"], p["D"] - p["C"], p["F"] - p["E"]
        cross = (lambda u, v: (u.conjugate() * v).imag)
        crossing = p["A"] + ab * cross(p["C"] - p["A"], cd) / cross(ab, cd)
        return abs(cross(ef, crossing - p["E"])) / abs(ef)

    def last_assembled(inside: float, outside: float) -> float:
        """The end of the reach between two crank angles, by bisection on whether the triad assembles."""
        for _ in range(40):
            middle = 0.5 * (inside + outside)
            try:
                at(middle)
                inside = middle
            except graphplan.GraphplanError:
                outside = middle
        return inside

    low, high = _reach_ends_deg(message)
    # Inside the reach the lines miss one another by centimetres; at the ends (the message's, rounded inward to
    # 0.01°, found again to 1e-12°) by nothing.
    assert miss(0.5 * (low + high)) > 0.05
    for named, outward in ((low, -0.02), (high, 0.02)):
        assert miss(last_assembled(named, named + outward)) < 1e-6


def test_a_slider_whose_rod_runs_out_of_reach_says_what_stops_it_at_the_end_of_the_travel():
    message = str(_refusal(SLIDER_AND_SHORT_ROD))
    assert "an end inside the travel typed is a dead centre: the rod stands square to the guide" in message
    assert "two links stand in line" not in message
    (end,) = re.findall(r"assembles only from s = 0 m to s = ([\d.]+) m", message)
    assert float(end) == pytest.approx(0.35, abs=1e-5)


# --- a load that never acts ----------------------------------------------------------------------------------------

# A slider-crank (crank 0.1 m, rod 0.35 m, the slider 4 on the x axis) with a resisting moment put on the slider.
SLIDER_WITH_A_MOMENT = slider_crank_with_a_resisting_force("Slider-crank with a moment on its slider") + """
[[loads]]
kind = "moment"
link = %d
value = 40.0
resisting = true
[positions]
count = 12
"""


def test_a_resisting_moment_on_a_link_that_never_turns_is_refused_at_its_key():
    # The slider keeps its direction at every crank angle (ω4 ≡ 0): a moment against its turning has no sense to
    # take and does no work, so the force analysis had dropped it at every position ("not acting here").
    turning = graphplan.solve(graphplan.load_text(SLIDER_WITH_A_MOMENT % 3), driver=np.radians(np.arange(360.0)))
    assert not np.any(turning.link(4).omega) and not np.any(turning.link(4).epsilon)
    with pytest.raises(graphplan.SceneError) as caught:
        graphplan.build(graphplan.load_text(SLIDER_WITH_A_MOMENT % 4))
    assert str(caught.value) == (
        "loads[1].resisting: link 4 never turns (it slides on a guide that does not turn), so a moment resisting its "
        'turning never acts: put the moment on a link that turns, or resist the motion with a force (kind = "force", '
        "point, angle)")


def test_a_resisting_moment_on_the_scotch_yokes_block_is_refused_a_driving_one_is_taken():
    """The yoke's block slides in a slot that does not turn: it keeps its direction as the yoke does."""
    text = (Path(__file__).resolve().parent.parent / "fixtures" / "scotch_yoke.toml").read_text(encoding="utf-8")
    moment = '\n[[loads]]\nkind = "moment"\nlink = 3\nvalue = 5.0\nresisting = %s\n'
    with pytest.raises(graphplan.SceneError, match=r"^loads\[1\]\.resisting: link 3 never turns"):
        graphplan.build(graphplan.load_text(text + moment % "true"))
    # A moment of a set sense on it is a load the slot takes as a couple: it stays.
    assert len(graphplan.build(graphplan.load_text(text + moment % "false")).scene.loads) == 2


# A slider-crank whose slider 4 runs along the x axis, with a resisting force square to the guide put on it: the
# slider never moves along the force's line, so there is no motion for it to resist, and it does nothing.
SQUARE_RESISTANCE = """
[[loads]]
kind = "force"
link = 4
point = "B"
value = 500.0
angle = 90.0
resisting = true
"""


def _forces_of(text: str, folder: Path) -> list[dict]:
    from graphplan.cli import main

    assert main(["run", str(_written(text, folder)), "--out", str(folder / "out")]) == 0
    document = json.loads((folder / "out" / "results.json").read_text(encoding="utf-8"))
    return [{key: position.get(key) for key in ("forces", "equilibrium")} for position in document["positions"]]


def _written(text: str, folder: Path) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "scene.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_a_resisting_force_square_to_the_only_motion_of_its_point_takes_no_sense_from_rounding():
    base = SLIDER_WITH_A_MOMENT % 3
    motion = graphplan.solve(graphplan.load_text(base))
    square = graphplan.load_text(base + SQUARE_RESISTANCE).loads[-1]
    # Along its line (the y axis) the slider neither moves nor is about to: its v and a there are rounding.
    assert np.all(np.abs(motion.point("B").v[:, 1]) < 1e-12) and np.all(np.abs(motion.point("B").a[:, 1]) < 1e-9)
    # Its sense was taken from the rounding's sign, so that it pushed the slider up at some positions and down at
    # others, and the guide's reaction R14 jumped by 1000 N from one to the next: it has none.
    assert not np.any(resisted_sense(square, motion_state(motion)))
    # Such a force acts nowhere, and a scene that gives one is refused where it says resisting (it is a slip).
    with pytest.raises(graphplan.SceneError, match=r"^loads\[2\]\.resisting: B on link 4 moves only along its"):
        graphplan.build(graphplan.load_text(base + SQUARE_RESISTANCE))


# A parallelogram (crank OA = rocker CB = 0.1 m, coupler AB = OC = 0.3 m) with a resisting moment on its coupler 3,
# which keeps its direction (ω3 = ε3 = 0) from 15° to 165° of the crank; past the toggle at 180° the solution goes on
# in the crossed (antiparallelogram) branch, where the coupler turns.
PARALLELOGRAM = """
[scene]
title = "Parallelogram with a resisting moment on its coupler"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.3, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.3, 0.1]
assembly = "left"
[points]
S3 = { link = 3, from = "A", toward = "B", at = 0.15 }
[links.3]
mass = 2.0
centre = "S3"
inertia = 0.02
[positions]
count = 12
start = 15.0
plans = [1, 4]
"""

COUPLER_MOMENT = '\n[[loads]]\nkind = "moment"\nlink = 3\nvalue = 30.0\nresisting = true\n'


def test_a_resisting_moment_on_a_coupler_that_keeps_its_direction_acts_on_no_plan_either(tmp_path):
    motion = graphplan.solve(graphplan.load_text(PARALLELOGRAM))
    assert np.all(np.abs(motion.link(3).omega[:6]) < 1e-12) and np.all(np.abs(motion.link(3).epsilon[:6]) < 1e-9)
    with_it = _forces_of(PARALLELOGRAM + COUPLER_MOMENT, tmp_path / "with")
    without = _forces_of(PARALLELOGRAM, tmp_path / "without")
    # The plans of one instant have a crank at constant speed and a coupler that keeps its direction: every ε there
    # is rounding, the largest too, against which the coupler's had seemed a turning about to begin.
    for position in range(6):
        for part in ("forces", "equilibrium"):
            if without[position][part] is None:
                continue
            for name, force in without[position][part]["reactions"].items():
                assert with_it[position][part]["reactions"][name] == pytest.approx(force, abs=1e-6), (position, name)


# --- an RPR's side --------------------------------------------------------------------------------------------------

SLOTTED_LEVER = """
[scene]
title = "Slotted lever"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.0, -0.2] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
"""


@pytest.mark.parametrize("key", ['assembly = "left"', "near = [0.1, 0.0]"])
def test_an_rpr_given_an_assembly_is_told_that_offset_s_sign_is_its_side(key):
    """The other dyads take assembly or near; an RPR refused them as a bare "unknown key"."""
    with pytest.raises(graphplan.SceneError) as refused:
        graphplan.load_text(SLOTTED_LEVER + key + "\n")
    assert refused.value.where == f"groups[0].{key.split()[0]}"
    assert "an RPR has one assembly" in str(refused.value)
    assert "the slide runs that far to the left of C, looking along the lever toward the block" in str(refused.value)


def test_an_rpr_s_positive_offset_puts_its_slide_to_the_left_of_c_along_the_lever():
    """What the refusal above says of the sign, checked: A − C across the lever's direction u (θ4) is +e."""
    motion = graphplan.solve(graphplan.load_text(SLOTTED_LEVER + "offset = 0.03\n"),
                             driver=np.radians([30.0, 100.0, 200.0, 300.0]))
    # u × (A − C), the z of the cross product: numpy 2 deprecates np.cross of plane vectors.
    across = [np.cos(theta) * (a[1] + 0.2) - np.sin(theta) * a[0]
              for a, theta in zip(motion.point("A").r, motion.link(4).angle, strict=True)]
    assert np.allclose(across, 0.03, atol=1e-12)
