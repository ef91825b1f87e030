"""Friction in the pairs: the friction circle at the joints, sliding friction in the guides.

Checked against closed forms of the massless central slider-crank (a force P on the piston, crank
angle φ, rod angle β with sin β = r·sin φ / l):

* friction f in the guide only: Mb = −P·r·sin(φ + β) / (cos β − f·s·|sin β|), s the sign of the
  piston's velocity; the pair locks itself where the denominator is not positive;
* friction in the crank's journal only (friction circle ρ = f·r_j): the rod force does not change,
  and Mb = Mb0 + sign(ω)·ρ·|R12|.

Then the polygons with friction against the linear system with friction on the ratchet, and the
efficiency: 1 without friction, below 1 with it wherever the driver delivers power.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest
from scene_texts import central_slider_crank

import graphplan
from graphplan.analysis import analyse
from graphplan.joint_friction import friction_loads, friction_pairs
from graphplan.loads import Rates, State
from graphplan.report.results import results
from graphplan.scene import FrictionSpec
from graphplan.scene import loads as scene_from_text
from graphplan.statics import Pair

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
RADIUS, ROD, PUSH, OMEGA = 0.1, 0.4, 1000.0, 10.0


def slider_crank(friction: str) -> graphplan.Scene:
    return scene_from_text(slider_crank_text(friction))


def slider_crank_text(friction: str) -> str:
    return central_slider_crank(RADIUS, ROD, OMEGA, named_guide=True) + f"""
[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
value = {PUSH}
[positions]
count = 24
start = 7.5
plans = [1, 5, 9, 17]
{friction}
"""


def rod_angle(phi: np.ndarray) -> np.ndarray:
    return np.arcsin(RADIUS * np.sin(phi) / ROD)


def test_guide_friction_matches_the_closed_form_and_locks_where_it_must():
    f = 5.0  # large enough that the piston jams near mid-stroke, where tan β > 1/f
    analysis = analyse(slider_crank(f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}'))
    exact = analysis.with_friction
    phi = analysis.motion.driver
    beta = rod_angle(phi)
    piston = np.sign(analysis.motion.point("B").v[:, 0])
    denominator = np.cos(beta) - f * piston * np.abs(np.sin(beta))
    free = denominator > 0.05
    expected = -PUSH * RADIUS * np.sin(phi + beta) / denominator
    np.testing.assert_allclose(exact.balancing[free & (piston > 0)], expected[free & (piston > 0)], rtol=1e-10)
    assert not exact.locked[free & (piston > 0)].any()
    jammed = (denominator < -0.05) & (piston > 0)
    assert jammed.any() and exact.locked[jammed].all()
    assert (exact.iterations[free & (piston > 0)] >= 1).all()


def _guide_friction(f: float, plans: str = "[18, 19]"):
    """The slider-crank with friction f in its guide alone; the closed form's denominator and expected Mb."""
    text = slider_crank_text(f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}')
    analysis = analyse(scene_from_text(text.replace("plans = [1, 5, 9, 17]", f"plans = {plans}")))
    phi = analysis.motion.driver
    beta = rod_angle(phi)
    piston = np.sign(analysis.motion.point("B").v[:, 0])
    denominator = np.cos(beta) - f * piston * np.abs(np.sin(beta))
    return analysis, piston, denominator, -PUSH * RADIUS * np.sin(phi + beta) / denominator


@pytest.mark.parametrize("gain", [0.963, 0.9997])
def test_guide_friction_of_a_gain_near_one_settles_at_the_closed_form_instead_of_locking(gain):
    """At f·tan β = 0.963 the repeated construction settles by 0.963 a step: 200 repetitions left it 5e-4
    off, and positions 18 and 19 were reported self-locking where the closed form moves them (found by a
    user's own solver); Newton's method carries the repetitions on, in the linear system and the polygons.
    At 0.9997 the Jacobian of the share before the last was too far off to settle the last one (a second
    user's solver): it is taken again where the solution has got to.  The polygons, 3000 times the ones
    without friction, take a μF of their own."""
    from graphplan.forces import POLYGON_FIELD_MM, polygon_extent

    steepest = np.abs(np.tan(rod_angle(np.radians(7.5 + 15.0 * np.arange(24))))).max()
    f = gain / steepest
    analysis, piston, denominator, expected = _guide_friction(f)
    exact, ahead = analysis.with_friction, piston > 0
    assert (f * np.abs(np.tan(rod_angle(analysis.motion.driver))))[ahead].max() == pytest.approx(gain)
    assert (denominator[ahead] > 0).all()
    np.testing.assert_allclose(exact.balancing[ahead], expected[ahead], rtol=1e-9)
    assert not exact.locked.any()
    for position in analysis.plans:
        assert piston[position.index] > 0 and not position.with_friction.locked
        assert position.with_friction.balancing == pytest.approx(expected[position.index], rel=1e-9)
        for group in position.with_friction.groups:
            assert polygon_extent(group.polygon) / group.scale <= 2 * POLYGON_FIELD_MM


def test_results_of_the_positions_that_move_stand_beside_those_that_lock():
    """One locked position's reactions, grown without bound, made every other position's rounding noise in
    results.json: their balancing moments and reactions were written 0."""
    from graphplan.report.results import results

    analysis, piston, _, expected = _guide_friction(5.0)
    exact = analysis.with_friction
    assert exact.locked.any() and not exact.locked.all()
    written = [position["equilibrium"]["friction"] for position in results(analysis)["positions"]]
    for i, entry in enumerate(written):
        assert entry["self_locking"] == bool(exact.locked[i])
        if not exact.locked[i]:
            assert entry["balancing_moment"] == pytest.approx(exact.balancing[i], rel=1e-9, abs=1e-9)
    moving = ~exact.locked & (piston > 0)
    assert moving.any()
    np.testing.assert_allclose([written[i]["balancing_moment"] for i in np.flatnonzero(moving)], expected[moving],
                               rtol=1e-9)


def test_a_friction_past_any_number_locks_the_positions_it_jams_without_calling_them_singular():
    """At f = 10⁶ the repetitions blow up to inf and NaN: the polygons' lines pointed nowhere and the position
    was said to have no force plan at all ("lines of action parallel"), and the linear system's NaN
    reactions passed for settled (self_locking false, every value null)."""
    analysis, _, denominator, _ = _guide_friction(1e6, "[6, 18]")
    exact = analysis.with_friction
    jammed = denominator <= 0
    assert jammed.any() and exact.locked[jammed].all()
    assert not exact.locked[~jammed].any() and np.isfinite(exact.balancing[~jammed]).all()
    assert not [w for w in analysis.warnings if w.code == "singular"]
    for position in analysis.plans:
        assert position.forces is not None and position.with_friction.locked == bool(jammed[position.index])


def test_journal_friction_adds_the_friction_circle_moment():
    f, journal = 0.15, 0.02
    analysis = analyse(slider_crank(f'[[friction]]\njoint = "O"\nf = {f}\nradius = {journal}'))
    ideal, rubbing = analysis.equilibrium, analysis.with_friction
    circle = f * journal
    frame_on_crank = np.abs(ideal.reaction("R12").force)
    expected = ideal.balancing + np.sign(OMEGA) * circle * frame_on_crank
    np.testing.assert_allclose(rubbing.balancing, expected, rtol=1e-12, atol=1e-12 * PUSH * RADIUS)
    np.testing.assert_allclose(np.abs(rubbing.reaction("R12").force), frame_on_crank, rtol=1e-12)


@pytest.mark.parametrize(("position", "phi"), [(1, 0.0), (13, np.pi)])
def test_a_slide_at_rest_rubs_against_the_sliding_about_to_begin(position, phi):
    """At the dead centres the piston stops (its velocity zero, or rounding's ±1e-17) and turns back, the way its
    acceleration points: a_B = −r·ω²·(cos φ + λ·cos 2φ).  The guide's friction f·m·g (the weight the only normal
    force, the rod lying along the axis) opposes that, so the rod pushes the piston with R34x = P − Ff + m·a_B."""
    f, mass, g = 0.2, 5.0, 9.81
    text = slider_crank_text(f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}\n[links.4]\nmass = {mass}\n'
                             'centre = "B"')
    text = text.replace("gravity = 0.0", f"gravity = {g}").replace("start = 7.5", "start = 0.0")
    analysis = analyse(scene_from_text(text.replace("plans = [1, 5, 9, 17]", "plans = [1, 13]")))
    index = position - 1
    assert analysis.motion.driver[index] == pytest.approx(phi)
    assert abs(analysis.motion.point("B").v[index, 0]) < 1e-12
    acceleration = -RADIUS * OMEGA**2 * (np.cos(phi) + RADIUS / ROD * np.cos(2 * phi))
    rubbing = -np.sign(acceleration) * f * mass * g
    expected = PUSH - rubbing + mass * acceleration
    assert analysis.with_friction.reaction("R34").force[index].real == pytest.approx(expected, rel=1e-12)
    drawn = next(plan for plan in analysis.plans if plan.number == position).with_friction
    assert drawn.reactions["R34"].force.real == pytest.approx(expected, rel=1e-9)


def test_a_journal_at_rest_rubs_against_the_turning_about_to_begin():
    """A rocker at its extreme (ω4 zero but for rounding against the crank's 10 rad/s) about to turn clockwise:
    the friction circle's moment on it is counter-clockwise, ρ·|R14|; with nothing about to turn there is none."""
    spec = FrictionSpec("friction[0]", "C", None, 0.1, 0.02, None)
    (pair,) = friction_pairs((spec,), [Pair("R14", False, "C", 1, 4)])
    reaction = {"R14": 300.0 + 400.0j}
    for omega in (1e-17, -1e-17, 0.0):
        state = State({}, {1: Rates(0.0, 0.0), 2: Rates(10.0, 0.0), 4: Rates(omega, -20.0)})
        moments = {load.name: load.moment for load in friction_loads((pair,), state, reaction)}
        assert moments["Mf14"] == pytest.approx(pair.radius * 500.0) and moments["Mf41"] == -moments["Mf14"]
    resting = State({}, {1: Rates(0.0, 0.0), 2: Rates(10.0, 0.0), 4: Rates(0.0, 0.0)})
    assert all(load.moment == 0 for load in friction_loads((pair,), resting, reaction))


def ratchet_with_friction(f: float):
    scene = graphplan.load(Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml")
    specs = tuple(FrictionSpec(f"friction[{k}]", joint, None, f, 0.02, None) for k, joint in enumerate("OABC"))
    return analyse(dataclasses.replace(scene, friction=specs))


def test_polygons_with_friction_agree_with_the_linear_system_with_friction():
    analysis = ratchet_with_friction(0.12)
    exact = analysis.with_friction
    for position in analysis.plans:
        drawn, i = position.with_friction, position.index
        assert drawn.iterations >= 2 and not drawn.locked
        largest = max(abs(r.force[i]) for r in exact.reactions)
        for name, found in drawn.reactions.items():
            assert abs(found.force - exact.reaction(name).force[i]) <= 1e-9 * largest
        assert drawn.balancing == pytest.approx(exact.balancing[i], rel=1e-9)
        assert drawn.balancing != pytest.approx(position.forces.balancing, rel=1e-3)


def test_efficiency_is_one_without_friction_and_below_one_with_it():
    no_friction = ratchet_with_friction(0.0)
    np.testing.assert_allclose(no_friction.with_friction.balancing, no_friction.equilibrium.balancing, rtol=1e-13)
    analysis = ratchet_with_friction(0.12)
    ideal, rubbing = analysis.equilibrium.balancing, analysis.with_friction.balancing
    omega = analysis.mechanism.driver.omega
    driving = ideal * omega > 0
    assert driving.any()
    efficiency = ideal[driving] / rubbing[driving]
    assert np.all(efficiency < 1) and np.all(efficiency > 0.5)


@pytest.mark.parametrize(("entry", "where", "message"), [
    ('joint = "Q"\nf = 0.1\nradius = 0.01', "friction[0].joint", "names no pair of the mechanism"),
    ('joint = "B"\nf = 0.1\nradius = 0.01', "friction[0].links", "joint B has several pairs: say which with links"),
    ('joint = "O"\nf = 0.1', "friction[0].radius", "the pair at O turns: give its journal radius"),
    ('joint = "B"\nlinks = [1, 4]\nf = 0.1\nradius = 0.01', "friction[0].radius", "the pair at B slides"),
    ('joint = "O"\nf = -0.1\nradius = 0.01', "friction[0].f", "must be >= 0"),
    ('joint = "O"\nf = 0.1\nradius = 0.01\ngroove_half_angle = 30', "friction[0].groove_half_angle", "turns: a groove"),
    ('joint = "B"\nlinks = [1, 4]\nf = 0.1\ngroove_half_angle = 95', "friction[0].groove_half_angle",
     "must be at most 90 degrees: the angle between a flank and the groove's plane of symmetry, 90 for a flat guide"),
    ('joint = "O"\nf = 0.1\nradius = 30.0', "friction[0].radius",
     ("a journal of radius 30 m at O is larger than the links it joins (link 2 A–O: 0.1 m): a pin cannot be wider "
      "than the links it is on, and its friction circle ρ = 3 m would change every reaction and the efficiency; the "
      "radius is in metres (in millimetres? 30 mm is 0.03 m)")),
    ('joint = "B"\nlinks = [3, 4]\nf = 0.1\nradius = 0.5', "friction[0].radius",
     "a journal of radius 0.5 m at B is larger than the links it joins (link 3 A–B: 0.4 m)"),
])
def test_bad_friction_entries_name_their_key(entry, where, message):
    with pytest.raises(graphplan.SceneError) as raised:
        analyse(slider_crank("[[friction]]\n" + entry))
    assert str(raised.value).startswith(where) and message in str(raised.value)


def test_a_journal_in_millimetres_is_refused_before_anything_is_written(tmp_path, capsys):
    """A crank-rocker's frame journal typed as 30 (mm) was taken for 30 m: ρ = 3 m round a 0.175 m crank, η = 0.035
    and every drawing rescaled, and neither check nor run said a word."""
    from graphplan.cli import main

    text = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    scene = tmp_path / "journal_in_mm.toml"
    scene.write_text(text + '[[friction]]\njoint = "O"\nf = 0.1\nradius = 30.0\n', encoding="utf-8")
    for command in (["check", str(scene)], ["run", str(scene), "--out", str(tmp_path / "out")]):
        assert main(command) == 2
        assert ("graphplan: error: friction[0].radius: a journal of radius 30 m at O is larger than the links it "
                "joins (the frame C–O: 0.55 m; link 2 A–O: 0.175 m)") in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_a_journal_wider_than_one_of_its_links_is_an_eccentric_and_is_taken():
    """An eccentric's sheave is wider than its crank is long: a journal is refused only where it is wider than
    every link it joins."""
    analysis = analyse(slider_crank('[[friction]]\njoint = "A"\nf = 0.1\nradius = 0.2'))
    assert RADIUS < 0.2 < ROD and analysis.friction[0].radius == pytest.approx(0.02)


def test_efficiency_is_not_defined_where_friction_turns_the_power_flow_round():
    from graphplan.statics import efficiency

    mechanism = analyse(slider_crank("")).mechanism  # ω > 0: a positive Mb drives
    assert efficiency(mechanism, 10.0, 12.5) == pytest.approx(0.8)   # the driver drives, friction costs
    assert efficiency(mechanism, -10.0, -8.0) == pytest.approx(0.8)  # the loads drive it back, friction takes a share
    assert np.isnan(efficiency(mechanism, -1.0, 2.0))                # friction makes the driver drive after all


def test_each_position_the_friction_locks_is_warned_of():
    """Locked positions showed only as a word in the tables and the note: no warning on the command line or in
    results.json's warnings, where a user looks first."""
    analysis = analyse(slider_crank('[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 5.0'))
    locked = set(np.flatnonzero(analysis.with_friction.locked))
    assert locked
    warned = {w.position for w in analysis.warnings if w.code == "self-locking"}
    assert warned == locked
    assert not [w for w in analyse(slider_crank("")).warnings if w.code == "self-locking"]

    # Where it locks at positions, the stretches round them are theirs: none is told again as between positions.
    assert not analysis.locked_spans and not [w for w in analysis.warnings if w.code == "self-locking-between"]


def test_a_lock_between_two_positions_that_move_is_found_where_the_closed_form_puts_it(tmp_path):
    """f = 3.9 in the guide locks the slider-crank only while f·tan β > 1 about φ = 270°, 13° in all: positions
    18 and 19, 7.5° either side, both move, and the lock went unreported (found by a teacher's own sweep)."""
    from graphplan.cli import main
    from graphplan.report import forces as force_report

    f = 3.9
    text = slider_crank_text(f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}')
    analysis = analyse(scene_from_text(text))
    assert not analysis.with_friction.locked.any()
    # The closed form: cos β − f·|sin β| = 0 where tan β = 1/f, sin φ = (l/r)·sin β, the piston moving forward.
    edge = np.degrees(np.arcsin(ROD / RADIUS * np.sin(np.arctan(1.0 / f))))   # 83.46°: φ from 180° + edge
    low, high = 180.0 + edge, 360.0 - edge
    (span,) = analysis.locked_spans
    assert np.degrees([span.start, span.end]) % 360.0 == pytest.approx([low, high], abs=1e-3)
    numbers = analysis.positions.numbers
    assert (numbers[span.after], numbers[span.after + 1]) == (18, 19)
    (warning,) = [w for w in analysis.warnings if w.code == "self-locking-between"]
    assert warning.position == span.after and "between positions 18 and 19" in warning.detail
    assert f"from φ = {low:.6g}° to φ = {high:.6g}°" in warning.detail
    sentence = f"Between positions 18 and 19, from φ = {low:.5g}° to φ = {high:.5g}°"
    assert sentence in force_report.markdown(analysis)
    scene = tmp_path / "locks.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "forces"]) == 0
    written = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    assert [(w["position"], w["code"]) for w in written["warnings"] if w["code"].startswith("self-locking")] == \
        [(18, "self-locking-between")]
    # A smaller friction never locks: f·tan β stays below 1 all the cycle.
    assert not analyse(slider_crank('[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 3.5')).locked_spans

LARGE_JOURNALS = """
[scene]
gravity = 9.81
[frame]
points = { O = [0.0, 0.0], C = [0.40, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.10
omega = -15.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.35, 0.25]
assembly = "left"
[points]
S3 = { link = 3, from = "A", toward = "B", at = 0.175 }
S4 = { link = 4, from = "C", toward = "B", at = 0.125 }
[links.3]
mass = 5.0
centre = "S3"
inertia = 0.06
[links.4]
mass = 4.0
centre = "S4"
inertia = 0.03
[[loads]]
kind = "moment"
link = 4
value = 200.0
resisting = true
during = "always"
[positions]
count = 360
start = 0.0
plans = [325, 326]
""" + "".join(f'[[friction]]\njoint = "{joint}"\nf = 0.4\nradius = 0.3\n' for joint in "OABC")


def test_friction_circles_a_hair_short_of_locking_settle_in_the_system_and_the_polygons_alike():
    """A crank-rocker whose journals' friction circles are 0.12 m: at φ = 36° and 35° the friction's gain is
    0.9997 and 0.9985.  The Jacobian taken at the last share's start was too far off there for Newton's
    method to settle, and the positions were reported locked; a user's own continuation moves them with
    Mb = −734 475 and −137 985 N·m, which the polygons, constructed apart from the linear system, give too."""
    analysis = analyse(scene_from_text(LARGE_JOURNALS))
    exact = analysis.with_friction
    for position, independent in zip(analysis.plans, (-734475.0, -137985.0), strict=True):
        i = position.index
        assert not exact.locked[i] and not position.with_friction.locked
        assert exact.balancing[i] == pytest.approx(independent, rel=1e-5)
        assert position.with_friction.balancing == pytest.approx(exact.balancing[i], rel=1e-8)


def test_a_friction_circle_wider_than_the_rod_is_long_is_refused():
    """A massless rod carries its force along a line through the frictionless wrist pin B tangent to the friction
    circle at the crank pin A: there is none when ρ exceeds the rod's length AB, and every position locked, each
    warned of alike.  Only an f no material has makes ρ = f·r wider than the links (r is no wider): refused, as a
    journal wider than them is; one just inside the rod is taken."""
    journal = 0.01
    with pytest.raises(graphplan.SceneError, match=r"^friction\[0\]\.f: makes the friction circle at A"):
        analyse(slider_crank(f'[[friction]]\njoint = "A"\nf = {1.01 * ROD / journal:g}\nradius = {journal}'))
    taken = analyse(slider_crank(f'[[friction]]\njoint = "A"\nf = {0.99 * ROD / journal:g}\nradius = {journal}'))
    assert taken.friction[0].radius == pytest.approx(0.99 * ROD)


def test_a_friction_that_overflows_the_repetitions_is_a_lock_not_a_settled_position():
    """ρ = 10 m at the ratchet's rocker pivot, thirty times the rocker (refused now: ρ = 0.5 m, inside the frame's
    0.55 m, overflows them as well): the repetitions overflowed to inf,
    inf ≤ 1e-13·inf passed for settled, and positions came out not locking with an efficiency of 2e-305, a
    balancing moment of -4e307 or none at all.  Whatever locks, a position that moves must have a finite
    balancing moment that takes at least the frictionless power (friction only takes power)."""
    scene = graphplan.load(FIXTURES / "ratchet_crank_rocker.toml")
    analysis = analyse(dataclasses.replace(scene, friction=(FrictionSpec("friction[0]", "C", None, 50.0, 0.01, None),)))
    ideal, rubbing = analysis.equilibrium, analysis.with_friction
    omega, written = scene.driver.omega, results(analysis)["positions"]
    for index, locked in enumerate(rubbing.locked):
        entry = written[index]["equilibrium"]["friction"]
        assert entry["self_locking"] is bool(locked)
        if not locked:
            assert np.isfinite(rubbing.balancing[index]) and abs(rubbing.balancing[index]) < 1e9
            assert rubbing.balancing[index] * omega >= ideal.balancing[index] * omega
            assert 0 < entry["efficiency"] <= 1


def test_a_groove_of_half_angle_90_is_a_flat_guide():
    """θ = 90° puts the flanks across the load, f' = f/sin 90° = f: the same as no groove at all."""
    flat = analyse(slider_crank('[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 0.15'))
    groove = analyse(slider_crank('[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 0.15\ngroove_half_angle = 90'))
    np.testing.assert_allclose(groove.with_friction.balancing, flat.with_friction.balancing, rtol=1e-12)


def test_a_balancing_load_without_friction_that_is_rounding_of_zero_gives_an_efficiency_of_zero():
    """At an extreme position the loads take no power: Mb0 is 0 but for rounding, of either sign.  η came out
    6e-16 (or null, and the note printed Mb0 = −0.000000000184468) where all the driver's power goes into friction."""
    from graphplan.statics import efficiency, rounded_zero, turned_round

    mechanism = analyse(slider_crank("")).mechanism
    ideal, rubbing = np.array([1.84e-10, -1.84e-10, 0.0, 2.0]), np.full(4, 5.0 * np.sign(OMEGA))
    np.testing.assert_array_equal(efficiency(mechanism, ideal, rubbing), [0.0, 0.0, 0.0, 0.4])
    np.testing.assert_array_equal(rounded_zero(ideal, rubbing), [0.0, 0.0, 0.0, 2.0])
    assert not turned_round(mechanism, ideal, rubbing).any()


def test_a_friction_entry_naming_no_joint_is_refused_without_a_force_analysis_too():
    """A scene without masses or loads leaves its friction out (check says so: test_deliverables); its entries
    are checked all the same, so that giving the masses later does not turn up a typo then."""
    text = slider_crank_text('[[friction]]\njoint = "Q"\nf = 0.1\nradius = 0.02')
    unloaded = text[:text.index("[[loads]]")] + text[text.index("[positions]"):]
    with pytest.raises(graphplan.SceneError, match=r"^friction\[0\]"):
        analyse(scene_from_text(unloaded))
