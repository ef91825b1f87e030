"""The force analysis four ways: group by group as drawn, on Zhukovsky's lever, all links at once, by power.

* The polygons (``forces.force_plan``) cut the mechanism into its groups and close each one's force
  polygon from the plans of the instant: inertia loads from the acceleration plan.
* The linear system (``statics.equilibrium``) writes every equation of every moving link and solves
  them together from the analytic motion.
* Zhukovsky's lever (``lever.lever``) turns the velocity plan as constructed and balances the loads on it.
* The power balance ``Mb·ω1 = −Σ(F·v + M·ω)`` needs no reaction at all.

They must agree to 1e-9 at every position of every fixture and of the variants with guides on
moving links, with masses, moments of inertia and external loads put on every link (the fixtures
mostly carry none).  A closed form of the slider-crank and the load windows of the ratchet are
checked on their own.
"""

from __future__ import annotations

import dataclasses
import functools
import json
import math
from pathlib import Path
from types import MappingProxyType

import numpy as np
import pytest
from test_joint_friction import PUSH, RADIUS, ROD, slider_crank
from test_motion_against_finite_differences import CASES

import graphplan
from graphplan.analysis import analyse, instant
from graphplan.forces import force_plan
from graphplan.kinematics import cross
from graphplan.lever import lever
from graphplan.loads import activity, has_loads, link_loads, motion_state, plan_state
from graphplan.mechanism import build
from graphplan.plans import acceleration_plan, velocity_plan
from graphplan.scene import LinkSpec, LoadSpec
from graphplan.statics import balancing_by_power, equilibrium

RELATIVE = 1e-9
RATCHET = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"


def loaded(scene):
    """``scene`` with a mass, a centre, a moment of inertia on every moving link, a force on the last
    link and a resisting moment on the last before it that turns (different numbers per link, so that no
    two loads cancel by symmetry)."""
    mechanism = build(scene)
    links = {}
    for rank, number in enumerate(mechanism.moving_links):
        centre = max(mechanism.fixed_on[number])
        links[number] = LinkSpec(number, f"links.{number}", 2.0 + rank, centre, 0.05 * (rank + 1))
    last = mechanism.moving_links[-1]
    # The resisting moment on a link that turns: one that never turns (a slider) has no sense for it, and is refused.
    before = next(link for link in reversed(mechanism.moving_links[:-1]) if link not in mechanism.translating)
    external = (LoadSpec("loads[0]", "force", last, 300.0, False, "always", min(mechanism.fixed_on[last]), 30.0),
                LoadSpec("loads[1]", "moment", before, 50.0, True, "always", None, None))
    return dataclasses.replace(scene, links=MappingProxyType(links), loads=external)


# Four tests read each case's analysis and equilibrium, which they leave as they are: made once.
@functools.cache
def solved(case: str):
    analysis = analyse(loaded(CASES[case]()))
    motion = analysis.motion
    acting = activity(analysis.mechanism, analysis.positions, motion)
    loads = link_loads(analysis.mechanism, motion_state(motion), acting)
    return analysis, acting, loads, equilibrium(analysis.mechanism, motion, loads)


@pytest.mark.parametrize("case", sorted(CASES))
def test_polygons_and_lever_agree_with_the_linear_system_at_every_position(case):
    analysis, acting, _, exact = solved(case)
    mechanism, motion = analysis.mechanism, analysis.motion
    checked = 0
    for index in range(motion.count):
        if exact.singular[index] or index in motion.singular:
            continue
        where, directions = instant(motion, index)
        velocity = velocity_plan(mechanism, where, directions)
        acceleration = acceleration_plan(mechanism, where, directions, velocity)
        loads = link_loads(mechanism, plan_state(mechanism, where, velocity, acceleration), acting[:, index:index + 1])
        drawn = force_plan(mechanism, where, directions, loads)
        largest = max(abs(reaction.force[index]) for reaction in exact.reactions)
        assert set(drawn.reactions) == {reaction.name for reaction in exact.reactions}
        for name, found in drawn.reactions.items():
            expected = exact.reaction(name)
            assert abs(found.force - expected.force[index]) <= RELATIVE * largest, (case, index, name)
            if expected.sliding:
                assert abs(found.offset - expected.offset[index]) <= RELATIVE * (1 + abs(expected.offset[index])), (
                    case, index, name)
        assert drawn.balancing == pytest.approx(exact.balancing[index], rel=RELATIVE, abs=RELATIVE * largest)
        on_the_lever = lever(mechanism, where, velocity, loads).balancing
        assert on_the_lever == pytest.approx(drawn.balancing, rel=RELATIVE, abs=RELATIVE * largest)
        checked += 1
    assert checked >= motion.count - 1


@pytest.mark.parametrize("case", sorted(CASES))
def test_an_inertia_resultant_displaced_by_mu_over_fu_changes_nothing_but_the_drawing(case):
    """Fu displaced by h = Mu/Fu instead of Fu and Mu: the same reactions and balancing load by the
    system, the polygons, the lever and the power balance; the shift's moment about the centre is Mu."""
    analysis, _, loads, exact = solved(case)
    scene = dataclasses.replace(analysis.scene, inertia="displaced")
    shifted = analyse(scene)
    mechanism, motion = shifted.mechanism, shifted.motion
    moved = link_loads(mechanism, motion_state(motion), activity(mechanism, shifted.positions, motion))
    couples = {load.name: load.moment for load in loads if load.name.startswith("Mu")}
    displaced = [load for load in moved if load.name.startswith("Fu") and np.any(load.offset != 0)]
    # The yoke's links translate or turn about their centres: nothing to displace.
    assert displaced or case == "scotch_yoke"
    for load in displaced:
        mu = couples[f"Mu{load.link}"]
        left = next((other.moment for other in moved if other.name == f"Mu{load.link}"), 0.0)
        np.testing.assert_allclose(cross(load.offset, load.force) + left, mu, atol=1e-9 * np.max(np.abs(mu)))
    good = ~exact.singular
    again = equilibrium(mechanism, motion, moved)
    scale = np.max(np.abs(exact.balancing[good]))
    np.testing.assert_allclose(again.balancing[good], exact.balancing[good], atol=RELATIVE * scale)
    np.testing.assert_allclose(balancing_by_power(mechanism, motion_state(motion), moved)[good],
                               exact.balancing[good], atol=RELATIVE * scale)
    for position in shifted.plans:
        if position.forces is None:
            continue
        assert position.forces.balancing == pytest.approx(exact.balancing[position.index], abs=RELATIVE * scale)
        assert position.lever.balancing == pytest.approx(exact.balancing[position.index], abs=RELATIVE * scale)


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_power_balance_gives_the_balancing_load_of_the_linear_system(case):
    analysis, _, loads, exact = solved(case)
    by_power = balancing_by_power(analysis.mechanism, motion_state(analysis.motion), loads)
    good = ~exact.singular
    scale = np.max(np.abs(exact.balancing[good]))
    assert np.max(np.abs(by_power[good] - exact.balancing[good])) <= RELATIVE * scale


@pytest.mark.parametrize("case", sorted(CASES))
def test_every_moving_link_is_in_equilibrium_with_the_reactions_found(case):
    """Put every reaction back on its two links: each link's forces and moments must sum to zero."""
    analysis, _, loads, exact = solved(case)
    mechanism, motion = analysis.mechanism, analysis.motion
    index = int(np.flatnonzero(~exact.singular)[0])
    force = {number: 0j for number in mechanism.moving_links}
    moment = {number: 0.0 for number in mechanism.moving_links}

    def apply(link, value, at, couple=0.0):
        if link in force:
            force[link] += value
            moment[link] += (np.conj(at) * value).imag + couple

    for load in loads:
        value = complex(np.atleast_1d(load.force)[index if np.ndim(load.force) else 0])
        couple = float(np.atleast_1d(load.moment)[index if np.ndim(load.moment) else 0])
        at = complex(np.atleast_1d(motion.points[load.point].r)[index]) if load.is_force else 0j
        apply(load.link, value, at, couple)
    for reaction in exact.reactions:
        joint = complex(np.atleast_1d(motion.points[reaction.joint].r)[index])
        value = complex(reaction.force[index])
        if reaction.sliding:
            u = complex(np.atleast_1d(motion.slide(reaction.target).u)[index] if np.ndim(motion.slide(reaction.target).u)
                        else motion.slide(reaction.target).u)
            joint = joint + reaction.offset[index] * u
        apply(reaction.target, value, joint)
        apply(reaction.source, -value, joint)
    driver = mechanism.driver
    if driver.kind == "crank":
        moment[driver.link] += exact.balancing[index]
    else:
        u = complex(np.atleast_1d(motion.slide(driver.link).u)[0])
        apply(driver.link, exact.balancing[index] * u, complex(np.atleast_1d(motion.points[driver.joint].r)[index]))
    scale = max(abs(complex(r.force[index])) for r in exact.reactions)
    for number in mechanism.moving_links:
        assert abs(force[number]) <= RELATIVE * scale
        assert abs(moment[number]) <= RELATIVE * scale


def test_slider_crank_torque_matches_its_closed_form():
    """Massless central slider-crank, a force P on the piston against +x: the crank needs
    Mb = −P·r·sin(φ + β)/cos β (β the rod's angle, sin β = r·sin φ / l), the classic result."""
    analysis = analyse(slider_crank(""))
    motion = analysis.motion
    acting = activity(analysis.mechanism, analysis.positions, motion)
    loads = link_loads(analysis.mechanism, motion_state(motion), acting)
    found = equilibrium(analysis.mechanism, motion, loads).balancing
    phi = motion.driver
    beta = np.arcsin(RADIUS * np.sin(phi) / ROD)
    expected = -PUSH * RADIUS * np.sin(phi + beta) / np.cos(beta)
    np.testing.assert_allclose(found, expected, rtol=1e-12, atol=1e-9 * PUSH * RADIUS)


def test_the_ratchet_resistance_acts_over_its_window_of_the_working_stroke():
    """1500 N·m over the first 0.881 of the rocker's working swing: the rocker's own angle decides."""
    analysis = analyse(graphplan.load(CASES["ratchet_crank_rocker"].args[0]))
    mechanism, motion = analysis.mechanism, analysis.motion
    share_acting = activity(mechanism, analysis.positions, motion)[0]
    assert set(np.unique(share_acting)) <= {0.0, 1.0}  # a constant load acts fully or not at all
    acting = share_acting == 1.0
    rocker = np.degrees(motion.link(4).angle)
    start, end = (np.degrees(float(np.atleast_1d(x)[0])) for x in (
        graphplan.solve(mechanism.scene, driver=np.array([e])).link(4).angle for e in analysis.positions.extremes))
    def turned(angle):  # degrees turned, the short way round
        return (angle + 180.0) % 360.0 - 180.0

    share = turned(rocker - start) / turned(end - start)
    working = np.array([stroke == "working" for stroke in analysis.positions.strokes])
    np.testing.assert_array_equal(acting, working & (share <= 0.881 + 1e-12))
    assert acting.sum() == 4
    loads = link_loads(mechanism, motion_state(motion), activity(mechanism, analysis.positions, motion))
    resistance = next(load for load in loads if load.name == "M4")
    omega = motion.link(4).omega
    moving = acting & (np.abs(omega) > 1e-6)
    assert np.all(resistance.moment[moving] * omega[moving] < 0)
    assert np.all(resistance.moment[~acting] == 0)


TANGENT = Path(__file__).resolve().parent.parent / "fixtures" / "tangent_mechanism_prp.toml"


def test_a_load_diagram_follows_the_ram_over_its_working_stroke():
    """The shaper's cutting force as a useful-resistance diagram: run-in over the first tenth of the
    ram's travel, full over the middle, run-out over the last.  The ram's own displacement from its
    extremes decides, and the force opposes the ram's motion."""
    diagram = ((0.05, 0.0), (0.1, 1500.0), (0.9, 1500.0), (0.95, 0.0))
    base = graphplan.load(TANGENT)
    resistance = dataclasses.replace(base.loads[0], value=1500.0, during=(0.05, 0.95), diagram=diagram)
    scene = dataclasses.replace(base, loads=(resistance,), positions=dataclasses.replace(base.positions, count=72))
    analysis = analyse(scene)
    mechanism, motion = analysis.mechanism, analysis.motion
    ram = motion.point("B")  # x, y columns
    start, end = (float(graphplan.solve(scene, driver=np.array([e])).point("B").r[0, 0])
                  for e in analysis.positions.extremes)
    share = (ram.r[:, 0] - start) / (end - start)
    working = np.array([stroke == "working" for stroke in analysis.positions.strokes])
    expected = np.where(working, np.interp(share, *np.array(diagram).T, left=0.0, right=0.0), 0.0)
    loads = link_loads(mechanism, motion_state(motion), activity(mechanism, analysis.positions, motion))
    force = next(load for load in loads if load.name == "F6").force
    np.testing.assert_allclose(np.abs(force), expected, atol=1e-9)
    assert 0 < np.count_nonzero((expected > 0) & (expected < 1500.0)) < np.count_nonzero(expected)
    assert np.all(force.real * ram.v[:, 0] <= 0)
    # The polygons and the system see the same diagram.
    exact = equilibrium(mechanism, motion, loads).balancing
    for position in analysis.plans:
        assert position.forces.balancing == pytest.approx(exact[position.index], rel=RELATIVE)


def test_no_masses_and_no_loads_means_no_force_analysis():
    scene = dataclasses.replace(CASES["scotch_yoke"](), links=MappingProxyType({}), loads=())
    assert not has_loads(build(scene))
    assert has_loads(build(loaded(scene)))


def test_a_load_in_one_stroke_needs_the_working_link():
    scene = loaded(CASES["scotch_yoke"]())
    scene = dataclasses.replace(scene, loads=(dataclasses.replace(scene.loads[0], during="working"),),
                                positions=dataclasses.replace(scene.positions, working=None))
    with pytest.raises(graphplan.SceneError, match=r"loads\[0\]\.during: a load that acts in one stroke needs positions.working"):
        build(scene)


def test_a_wrong_first_guess_of_sense_shows_as_a_negative_component():
    """The across component is assumed turned +90° from its link; where that is wrong the moment
    equation gives a negative value, and the reaction found is still right (checked above)."""
    analysis, acting, _, _ = solved("ratchet_crank_rocker")
    signs = set()
    for position in analysis.plans:
        loads = link_loads(analysis.mechanism, plan_state(analysis.mechanism, position.positions, position.velocity,
                                                           position.acceleration),
                           acting[:, position.index:position.index + 1])
        drawn = force_plan(analysis.mechanism, position.positions, position.directions, loads)
        for group in drawn.groups:
            signs.update(equation.value > 0 for equation in group.moments if equation.unknown.endswith("τ"))
    assert signs == {True, False}


def test_marghitu_slider_crank_reproduces_the_published_reaction():
    """Marghitu, Mechanisms and Robots Analysis with MATLAB (Springer 2009), ch. 4, the R-RRT example,
    p. 144, Eqs. (4.51)-(4.52): the crank's force on the rod F12 = (−(400 + 7√2)/4, 5(84 + √2)/4) N,
    graphplan's R23 (docs/sources/kinetostatic-example.md).  The page with its driving moment was not
    found; the balancing moment is held to the power balance instead."""
    scene = graphplan.load(Path(__file__).parent / "scenes" / "marghitu_slider_crank_forces.toml")
    analysis = analyse(scene)
    (position,) = analysis.plans
    published = complex(-(400 + 7 * math.sqrt(2)) / 4, 5 * (84 + math.sqrt(2)) / 4)
    assert abs(position.forces.reactions["R23"].force - published) <= 1e-9 * abs(published)
    assert abs(analysis.equilibrium.reaction("R23").force[0] - published) <= 1e-9 * abs(published)
    by_power = balancing_by_power(analysis.mechanism, motion_state(analysis.motion), analysis.loads)
    assert position.forces.balancing == pytest.approx(float(by_power[0]), rel=1e-12)
    assert position.lever.balancing == pytest.approx(position.forces.balancing, rel=1e-12)


def test_results_and_forces_table_carry_the_force_analysis(tmp_path):
    from graphplan.cli import main

    assert main(["run", str(RATCHET), "--out", str(tmp_path)]) == 0
    document = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    analysis = analyse(graphplan.load(RATCHET))
    exact = analysis.equilibrium
    for entry, index in zip(document["positions"], range(analysis.motion.count)):
        assert entry["equilibrium"]["balancing_moment"] == pytest.approx(exact.balancing[index], rel=1e-11)
        if entry["index"] in (5, 11):
            forces = entry["forces"]
            assert set(forces) >= {"reactions", "balancing_moment", "lever_balancing_moment", "polygon_scale"}
            assert forces["lever_balancing_moment"] == pytest.approx(forces["balancing_moment"], rel=1e-9)
            for name, (x, y) in forces["reactions"].items():
                assert complex(x, y) == pytest.approx(complex(exact.reaction(name).force[index]), rel=1e-9)
        else:
            assert "forces" not in entry
    table = (tmp_path / "forces.md").read_text(encoding="utf-8")
    for name in ("R12", "R23", "R34", "R14"):
        assert f"| {name} |" in table
    by_power = balancing_by_power(analysis.mechanism, motion_state(analysis.motion), analysis.loads)
    written = f"{by_power[5]:.6g}".replace(".", ",")  # a Russian table writes a decimal comma
    assert table.count(f"| рычаг Жуковского | {written} |") == 1  # position 5, read against the power balance


def test_the_balancing_diagram_is_drawn_only_when_asked_and_the_same_every_time(tmp_path):
    import subprocess
    import sys

    script = ("import sys; from graphplan.cli import main; "
              f"main(['run', {str(RATCHET)!r}, '--out', {str(tmp_path / 'plain')!r}]); "
              "print('matplotlib' in sys.modules)")
    plain = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert plain.stdout.strip().endswith("False")
    assert not (tmp_path / "plain" / "balancing.svg").exists()
    import matplotlib

    from graphplan.cli import main

    before = {key: matplotlib.rcParams[key] for key in ("font.family", "svg.hashsalt", "svg.fonttype")}
    # The figure with the plan of positions alone beside it: --figures adds it to what --only asks for, and the
    # figure is drawn from the analysis, the same whatever else the run draws (the full run is the plain one above).
    for run in ("first", "second"):
        assert main(["run", str(RATCHET), "--out", str(tmp_path / run), "--only", "positions", "--figures"]) == 0
    # The figure's fonts and hash salt are its own: the user's later plots keep theirs.
    assert {key: matplotlib.rcParams[key] for key in before} == before
    first = (tmp_path / "first" / "balancing.svg").read_bytes()
    assert first == (tmp_path / "second" / "balancing.svg").read_bytes()
    assert "уравновешивающий момент".encode() in first  # the scene's locale (ru), not English
    assert b"balancing moment" not in first
