"""A force along a line that turns: ``[[loads]] kind = "force"`` with ``along = "D"`` in place of ``angle``.

A hydraulic cylinder pinned to the frame at D that pushes a link at B, or a spring between two points, acts along
the line DB as it turns.  Nothing here reads graphplan's loads to find that line: the unit vector e from D to B is
worked out in the test from the analytic positions (``analysis.motion``'s r), and

* the balancing moment of the linear system at every position is that of virtual work, Mb = −Σ F·(vB·e)/ω1
  (a resisting force's F = −|F|·sign(vB·e), against B's motion along the line);
* the same force given at the fixed angle of DB at one position gives the same reactions there;
* the force polygons and Zhukovsky's lever at the plan positions give the linear system's balancing moment, and
  the polygons its reactions;
* the dynamics' reduced moment of the force is F·(vB·e)/|ω1|;
* a bad ``along`` is refused at its key path.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.dynamics import equivalent_model_of
from graphplan.errors import SceneError
from graphplan.mechanism import build
from graphplan.report.forces import external_load_lines
from graphplan.scene import loads as scene_of_text

# A crank-rocker (lOA = 0.1, lAB = 0.4, lBC = 0.3, lOC = 0.35) with a frame pin D for a cylinder, and E on the
# coupler for a spring; no gravity, so that the loads' power is the scene's loads' alone.
CRANK_ROCKER = """
[scene]
gravity = 0.0
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.35, 0.0], D = [0.05, 0.42] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 12.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.4, 0.3]
assembly = "left"
[points]
E = { link = 3, from = "A", toward = "B", at = 0.2, offset = 0.08 }
S4 = { link = 4, from = "C", toward = "B", at = 0.15 }
[positions]
count = 12
plans = [2, 7]
"""

# A slider-crank (r = 0.1, l = 0.35) whose slider a cylinder pinned at D, above and behind the guide, pulls.
SLIDER_CRANK = """
[scene]
gravity = 0.0
[frame]
link = 1
points = { O = [0.0, 0.0], D = [-0.1, 0.25] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = -9.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.35
guide = { through = "O", angle = 0.0 }
assembly = "forward"
[positions]
count = 12
plans = [3, 8]
"""

MASSES = """
[links.2]
mass = 2.0
centre = "A"
inertia = 0.01
[links.3]
mass = 3.0
centre = "E"
inertia = 0.04
[links.4]
mass = 2.5
centre = "S4"
inertia = 0.03
"""


def _force(link: int, point: str, value: float, direction: str, extra: str = "") -> str:
    return f'\n[[loads]]\nkind = "force"\nlink = {link}\npoint = "{point}"\nvalue = {value}\n{direction}\n{extra}'


def _with_loads(base: str, added: str) -> str:
    """``base`` with ``added`` loads put before its [positions] table."""
    at = base.index("\n[positions]")
    return base[:at] + added + base[at:]


# Each case: its scene and its forces as (link, point, value, the point it acts along, resisting).
CASES = {
    "cylinder from the frame on the rocker": (CRANK_ROCKER, [(4, "B", 800.0, "D", False)]),
    "spring from the coupler pulling the rocker": (CRANK_ROCKER, [(4, "S4", -300.0, "E", False)]),
    "resisting cylinder on the rocker": (CRANK_ROCKER, [(4, "B", 600.0, "D", True)]),
    "cylinder pulling the slider": (SLIDER_CRANK, [(4, "B", -500.0, "D", False)]),
    "resisting cylinder and a spring on the slider": (SLIDER_CRANK, [(4, "B", 400.0, "D", True),
                                                                     (4, "B", 150.0, "A", False)]),
}


def _text(case: str) -> str:
    base, forces = CASES[case]
    return _with_loads(base, "".join(_force(link, point, value, f'along = "{far}"',
                                            "resisting = true\n" if resisting else "")
                                     for link, point, value, far, resisting in forces))


@functools.cache
def analysis(case: str):
    return analyse(scene_of_text(_text(case)))


def _xy(array) -> np.ndarray:
    array = np.asarray(array, dtype=float)
    return array[..., 0] + 1j * array[..., 1]


def _line(motion, point: str, far: str) -> np.ndarray:
    """The unit vector from ``far`` to ``point`` at each position of ``motion``."""
    reach = _xy(motion.point(point).r) - _xy(motion.point(far).r)
    return reach / np.abs(reach)


def _along(direction, vector) -> np.ndarray:
    return (np.conj(direction) * vector).real


def _powers(case: str, motion) -> np.ndarray:
    """Σ F·(v·e) of the case's forces at each position of ``motion``: a resisting force against v·e."""
    total = np.zeros(motion.count)
    for _, point, value, far, resisting in CASES[case][1]:
        speed = _along(_line(motion, point, far), _xy(motion.point(point).v))
        force = -abs(value) * np.sign(speed) if resisting else value
        total = total + force * speed
    return total


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_balancing_moment_at_every_position_is_that_of_virtual_work(case):
    found = analysis(case)
    expected = -_powers(case, found.motion) / found.scene.driver.omega
    scale = float(np.max(np.abs(expected)))
    assert scale > 1.0
    np.testing.assert_allclose(found.equilibrium.balancing, expected, rtol=0, atol=1e-9 * scale)


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_polygons_and_the_lever_agree_with_the_linear_system(case):
    found = analysis(case)
    drawn = [plan for plan in found.plans if plan.forces is not None]
    assert len(drawn) == 2
    for plan in drawn:
        exact = float(found.equilibrium.balancing[plan.index])
        scale = float(np.max(np.abs(found.equilibrium.balancing)))
        assert plan.forces.balancing == pytest.approx(exact, abs=1e-7 * scale), plan.number
        assert plan.lever.balancing == pytest.approx(exact, abs=1e-7 * scale), plan.number
        for reaction in plan.forces.reactions.values():
            solved = complex(found.equilibrium.reaction(reaction.name).force[plan.index])
            assert abs(reaction.force - solved) <= 1e-7 * max(abs(solved), 1.0), (plan.number, reaction.name)


@pytest.mark.parametrize("index", [0, 5, 9])
def test_the_same_force_at_the_fixed_angle_of_its_line_gives_the_same_reactions_there(index):
    turning = analysis("cylinder from the frame on the rocker")
    direction = _line(turning.motion, "B", "D")[index]
    angle = math.degrees(math.atan2(direction.imag, direction.real))
    fixed = analyse(scene_of_text(_with_loads(CRANK_ROCKER, _force(4, "B", 800.0, f"angle = {angle!r}"))))
    assert fixed.equilibrium.balancing[index] == pytest.approx(turning.equilibrium.balancing[index], rel=1e-12)
    for reaction in turning.equilibrium.reactions:
        there = complex(fixed.equilibrium.reaction(reaction.name).force[index])
        assert abs(complex(reaction.force[index]) - there) <= 1e-9 * abs(there), reaction.name
    # Where DB has turned most from there, the fixed line is no longer DB's: the two differ.
    lines = _line(turning.motion, "B", "D")
    other = int(np.argmax(np.abs(np.angle(lines / direction))))
    assert abs(math.degrees(np.angle(lines[other] / direction))) > 5.0
    assert abs(fixed.equilibrium.balancing[other] - turning.equilibrium.balancing[other]) > 1e-3 * abs(
        turning.equilibrium.balancing[other])


@pytest.mark.parametrize("case", ["resisting cylinder on the rocker", "resisting cylinder and a spring on the slider"])
def test_a_resisting_force_along_the_line_opposes_its_point_s_motion_along_it(case):
    found = analysis(case)
    (load,) = [each for each in found.loads if each.name in ("F4", "F4.1")]
    motion = found.motion
    direction = _line(motion, "B", "D")
    force = np.asarray(load.force)
    # On the line DB at every position, of the value's size, and against B's motion along it where B moves.
    np.testing.assert_allclose(np.abs(force), 600.0 if case.endswith("rocker") else 400.0, rtol=1e-12)
    np.testing.assert_allclose((np.conj(direction) * force).imag, 0.0, atol=1e-9)
    speed = _along(direction, _xy(motion.point("B").v))
    moving = np.abs(speed) > 1e-6 * np.max(np.abs(speed))
    assert moving.sum() >= 10
    assert np.all(_along(force, _xy(motion.point("B").v))[moving] < 0)
    # Both senses occur over the turn: the force turns round with the motion, not with the line.
    pushing = _along(direction, force)
    assert np.any(pushing[moving] > 0) and np.any(pushing[moving] < 0)


def test_the_reduced_moment_of_the_force_is_its_power_over_the_crank_speed():
    text = _text("spring from the coupler pulling the rocker").replace("\n[positions]", MASSES + "\n[positions]")
    text = _with_loads(text, _force(4, "B", 800.0, 'along = "D"'))
    scene = scene_of_text(text)
    model = equivalent_model_of(analyse(scene), constant="none")
    motion = graphplan.solve(scene, driver=np.asarray(model.driver))
    power = 0.0
    for point, value, far in (("S4", -300.0, "E"), ("B", 800.0, "D")):
        power = power + value * _along(_line(motion, point, far), _xy(motion.point(point).v))
    expected = power / abs(scene.driver.omega)
    np.testing.assert_allclose(model.moment, expected, rtol=0, atol=1e-9 * float(np.max(np.abs(expected))))


def test_forces_md_names_the_line_the_force_acts_along():
    found = analysis("cylinder from the frame on the rocker")
    plan = next(plan for plan in found.plans if plan.forces is not None)
    (line,) = [line for line in external_load_lines(found, plan) if "F4" in line]
    assert "along the line DB" in line


def _error(text: str) -> SceneError:
    with pytest.raises(SceneError) as caught:
        build(scene_of_text(text))
    return caught.value


def test_an_unknown_point_to_act_along_is_named_with_the_one_meant():
    error = _error(_with_loads(CRANK_ROCKER, _force(4, "B", 800.0, 'along = "d"')))
    assert error.where == "loads[0].along"
    assert "did you mean 'D'?" in str(error) and "(got 'd')" in str(error)
    assert "A, B, C, D, E, O, S4" in str(error)


def test_along_and_angle_together_are_refused():
    error = _error(_with_loads(CRANK_ROCKER, _force(4, "B", 800.0, 'along = "D"\nangle = 30.0')))
    assert error.where == "loads[0].along" and "not both" in str(error)


def test_a_force_with_neither_along_nor_angle_asks_for_either():
    error = _error(_with_loads(CRANK_ROCKER, _force(4, "B", 800.0, "")))
    assert error.where == "loads[0].angle" and "is required but missing" in str(error) and "or along" in str(error)


def test_along_the_force_s_own_point_is_refused():
    error = _error(_with_loads(CRANK_ROCKER, _force(4, "B", 800.0, 'along = "B"')))
    assert error.where == "loads[0].along" and "own point 'B'" in str(error)


def test_along_on_a_moment_is_refused():
    text = _with_loads(CRANK_ROCKER, '\n[[loads]]\nkind = "moment"\nlink = 4\nvalue = 50.0\nalong = "D"\n')
    error = _error(text)
    assert error.where == "loads[0].along" and "a moment acts on its whole link" in str(error)


def test_a_point_that_meets_the_force_s_point_is_refused_with_the_position():
    # B3 on the coupler stands where its pin B is, at every position: no line between them.
    text = CRANK_ROCKER.replace("[points]\n", '[points]\nB3 = { link = 3, from = "A", toward = "B", at = 0.4 }\n')
    with pytest.raises(SceneError) as caught:
        analyse(scene_of_text(_with_loads(text, _force(4, "B", 800.0, 'along = "B3"'))))
    assert caught.value.where == "loads[0].along"
    assert "B3 meets B at position 1" in str(caught.value)


def test_a_resisting_force_along_the_pivot_its_point_turns_about_is_refused():
    # B turns about C: it moves square to CB at every position, and the force would act nowhere.
    with pytest.raises(SceneError) as caught:
        analyse(scene_of_text(_with_loads(CRANK_ROCKER, _force(4, "B", 800.0, 'along = "C"', "resisting = true\n"))))
    assert caught.value.where == "loads[0].resisting" and "never moves along the line from C" in str(caught.value)


def test_a_resisting_force_that_turns_round_in_its_window_is_told_toward_and_away_from_its_point():
    base = CRANK_ROCKER.replace("plans = [2, 7]", 'plans = [2, 7]\nworking = { link = 4, sense = "ccw" }')
    swing = np.angle(_xy(analyse(scene_of_text(base)).motion.point("B").r) - 0.35)
    # D on the rocker's line at the middle of its swing, beyond B: B moves toward D, then away from it.
    middle = 0.35 + 0.6 * np.exp(1j * (swing.max() + swing.min()) / 2)
    text = base.replace("D = [0.05, 0.42]", f"D = [{float(middle.real)!r}, {float(middle.imag)!r}]")
    found = analyse(scene_of_text(_with_loads(text, _force(4, "B", 800.0, 'along = "D"',
                                                           'resisting = true\nduring = "working"\n'))))
    (warning,) = [warning for warning in found.warnings if warning.code == "resisting-turns-round"]
    speed = _along(_line(found.motion, "B", "D"), _xy(found.motion.point("B").v))
    acting = np.asarray(found.loads[-1].force) != 0
    toward = [str(number) for number, each, on in zip(found.positions.numbers, speed, acting, strict=True)
              if on and each < 0]
    assert toward and f"acts away from D at positions {', '.join(toward)}" in warning.detail
    assert "turns round toward D at positions" in warning.detail
