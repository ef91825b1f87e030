"""The equivalent model of a machine against calculations that do not use it.

* The reduced moment of inertia Je is checked against the kinetic energy T = Σ(½·m·vS² + ½·JS·ω²)
  with every velocity a central difference of the solved *positions* (never the solver's
  velocities): Je = 2T/ω1².
* Its derivative dJe/dψ, from the accelerations, against a central difference of Je itself.
* The reduced moment Me against the whole mechanism's equilibrium (``statics.equilibrium``, one
  linear system of all links with d'Alembert's loads): the balancing moment's power
  Mb·ω1 = −Me·|ω1| + dT/dt, with dT/dt = ½·(dJe/dψ)·|ω1|³ at a steady crank.
* A centric slider-crank in closed form (x_B, θ3 and their derivatives written out by hand).
* The resisting work of the ratchet's window against M·(share of the swing)·(swing of the rocker).
* The plan positions' reduction read off the velocity plans against the analytic one.
* The drawing: its layers and scales, its tangents through their intercepts, and it renders.

Every fixture is checked (they all carry masses, inertias and loads).
"""

from __future__ import annotations

import dataclasses
import functools
import math
import re
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest

from graphplan.analysis import analyse
from graphplan.dynamics import (
    DEFAULT_COUNT,
    EquivalentModel,
    equivalent_model,
    equivalent_model_of,
    plan_reductions,
)
from graphplan.flywheel import flywheel_for
from graphplan.loads import activity, link_loads, motion_state
from graphplan.mechanism import build
from graphplan.motion import solve
from graphplan.positions import make_positions
from graphplan.render.dynamics import dynamics_svg, layout, scales_for
from graphplan.render.primitives import Arrow, Polyline, Text, bounds_of
from graphplan.render.sheet import dynamics_panel, dynamics_sheet
from graphplan.scene import load, loads
from graphplan.statics import equilibrium

FIXTURE_DIR = Path(__file__).resolve().parent.parent / "fixtures"
FIXTURES = sorted(path.stem for path in FIXTURE_DIR.glob("*.toml"))
# The fixtures whose crank turns round: a cycle to reduce over (a slider's travel or a lever's swing is none).
CRANKS = [name for name in FIXTURES if load(FIXTURE_DIR / f"{name}.toml").driver.cyclic]


@functools.cache
def scene_of(name: str):
    return load(FIXTURE_DIR / f"{name}.toml")


@functools.cache
def model_of(name: str, constant: str = "auto") -> EquivalentModel:
    return equivalent_model_of(analyse(scene_of(name)), constant=constant)


def solved_at(scene, values):
    """The analytic motion at driver coordinates ``values``, on the branches of the scene's positions."""
    mechanism = build(scene)
    return mechanism, solve(mechanism, values, make_positions(mechanism).reference)


def _derivative(function, values: np.ndarray, h: float) -> np.ndarray:
    """The 4th-order central difference of ``function`` (an array over ``values``) at ``values``."""
    return (8 * (function(values + h) - function(values - h)) - (function(values + 2 * h) - function(values - 2 * h))) / (12 * h)


def _kinetic_inertia(scene, values: np.ndarray, h: float) -> np.ndarray:
    """2T/v1² from velocities that are central differences of the positions alone."""
    mechanism = build(scene)
    reference = make_positions(mechanism).reference
    motions = {}

    def position(shifted):
        key = float(shifted[0] - values[0])
        if key not in motions:
            motions[key] = solve(mechanism, shifted, reference)
        return motions[key]

    total = np.zeros(len(values))
    for number in mechanism.moving_links:
        spec = scene.links.get(number)
        if spec is None:
            continue
        if spec.mass > 0:
            r_prime = _derivative(lambda q, c=spec.centre: np.broadcast_to(position(q).points[c].r, q.shape), values, h)
            total += spec.mass * np.abs(r_prime) ** 2
        if spec.inertia > 0:
            def angle(q, n=number):
                # Unwrapped about the link's angle at the unshifted position: differences stay small.
                here = np.broadcast_to(np.asarray(position(values).links[n].angle, dtype=float), q.shape)
                there = np.broadcast_to(np.asarray(position(q).links[n].angle, dtype=float), q.shape)
                return here + np.angle(np.exp(1j * (there - here)))
            total += spec.inertia * _derivative(angle, values, h) ** 2
    return total


# --- the reduced moment of inertia ------------------------------------------------------------


@pytest.mark.parametrize("name", FIXTURES)
def test_reduced_inertia_is_twice_the_kinetic_energy_over_the_driver_speed_squared(name):
    model = model_of(name)
    scene = scene_of(name)
    h = 1e-4 if model.turning else 1e-5 * abs(scene.driver.travel[1] - scene.driver.travel[0])
    # dr/dq²·q̇² over q̇²: the driver's speed cancels, so Je is a pure function of position.
    expected = _kinetic_inertia(scene, model.driver, h)
    np.testing.assert_allclose(model.inertia, expected, rtol=1e-8, atol=1e-10 * float(np.max(expected)))
    assert np.all(model.inertia > 0)
    np.testing.assert_allclose(sum(model.link_inertia.values()), model.inertia, rtol=1e-14)


@pytest.mark.parametrize("name", FIXTURES)
def test_slope_of_the_reduced_inertia_from_accelerations_matches_its_finite_difference(name):
    model = model_of(name)
    scene = scene_of(name)
    mechanism = build(scene)
    h = 1e-4 if model.turning else 1e-5 * abs(scene.driver.travel[1] - scene.driver.travel[0])

    def inertia(values):
        _, motion = solved_at(scene, values)
        return equivalent_model(mechanism, motion).inertia

    # dJe/dψ = sense·dJe/dq: ψ runs the way the driver moves.
    expected = model.sense * _derivative(inertia, model.driver, h)
    scale = float(np.max(np.abs(expected)))
    np.testing.assert_allclose(model.inertia_slope, expected, rtol=0, atol=1e-7 * scale)


def test_driver_acceleration_of_the_scene_does_not_enter_the_reduction():
    """Je and dJe/dψ are position functions: a scene's ε1 ≠ 0 changes the accelerations, not them."""
    scene = scene_of("ratchet_crank_rocker")
    accelerating = dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, epsilon=35.0))
    steady, speeding = equivalent_model_of(scene), equivalent_model_of(accelerating)
    np.testing.assert_allclose(speeding.inertia, steady.inertia, rtol=1e-12)
    np.testing.assert_allclose(speeding.inertia_slope, steady.inertia_slope, rtol=0,
                               atol=1e-10 * float(np.max(np.abs(steady.inertia_slope))))


# --- the reduced moment: the power balance of the whole mechanism ------------------------------


@pytest.mark.parametrize("name", FIXTURES)
def test_reduced_moment_balances_the_equilibrium_of_all_links(name):
    """Mb·v1 + Me·|v1| − dT/dt = 0 with Mb from the linear system of every link's equilibrium."""
    model = model_of(name, "none")
    scene = scene_of(name)
    mechanism = build(scene)
    positions = make_positions(mechanism)
    motion = solve(mechanism, model.driver, positions.reference)
    acting = activity(mechanism, positions, motion)
    balance = equilibrium(mechanism, motion, link_loads(mechanism, motion_state(motion), acting))
    driver = scene.driver
    velocity = driver.omega if model.turning else driver.velocity
    rate = driver.epsilon if model.turning else driver.acceleration
    power_of_loads = model.moment * model.speed
    energy_rate = 0.5 * model.inertia_slope * model.speed ** 3 + model.inertia * velocity * rate
    residual = balance.balancing * velocity + power_of_loads - energy_rate
    scale = float(np.max(np.abs(balance.balancing * velocity)))
    assert not np.any(balance.singular)
    np.testing.assert_allclose(residual, 0.0, atol=1e-8 * scale)


def test_each_side_of_the_moment_has_its_own_loads():
    """The ratchet's only load resists: with nothing taken constant, the driving moment is zero."""
    model = model_of("ratchet_crank_rocker", "none")
    assert model.constant == "none"
    assert np.all(model.driving == 0.0)
    # The weights' work over a cycle is zero; the resistance's is −M·Δθ (checked below): Ar > 0.
    assert model.resisting_work[-1] > 0


# --- a slider-crank in closed form -------------------------------------------------------------

SLIDER_CRANK = """
[scene]
gravity = 0.0
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
length = 0.35
guide = { through = "O", angle = 0.0 }
assembly = "forward"
[points]
S2 = { link = 2, from = "O", toward = "A", at = 0.04 }
[links.2]
mass = 3.0
centre = "S2"
inertia = 0.01
[links.3]
inertia = 0.02
[links.4]
mass = 2.5
centre = "B"
[[loads]]
kind = "force"
link = 4
point = "B"
value = 100.0
angle = 180.0
"""


def test_slider_crank_in_closed_form():
    r, l, m2, s2, j2, j3, m4, force = 0.1, 0.35, 3.0, 0.04, 0.01, 0.02, 2.5, 100.0
    model = equivalent_model_of(loads(SLIDER_CRANK))
    phi = model.driver
    root = np.sqrt(l**2 - r**2 * np.sin(phi) ** 2)
    x1 = -r * np.sin(phi) - r**2 * np.sin(phi) * np.cos(phi) / root               # dxB/dφ
    x2 = -r * np.cos(phi) - r**2 * (np.cos(2 * phi) / root + r**2 * np.sin(phi) ** 2 * np.cos(phi) ** 2 / root**3)
    t1 = -r * np.cos(phi) / root                                                   # dθ3/dφ, sin θ3 = −r·sin φ / l
    t2 = r * np.sin(phi) / root - r**3 * np.sin(phi) * np.cos(phi) ** 2 / root**3
    inertia = m2 * s2**2 + j2 + j3 * t1**2 + m4 * x1**2
    slope = 2 * j3 * t1 * t2 + 2 * m4 * x1 * x2
    np.testing.assert_allclose(model.inertia, inertia, rtol=1e-12)
    np.testing.assert_allclose(model.inertia_slope, slope, rtol=0, atol=1e-11 * float(np.max(np.abs(slope))))
    # The massless crank's share is its constant moment of inertia about O.
    np.testing.assert_allclose(model.link_inertia[2], m2 * s2**2 + j2, rtol=1e-14)
    # A force of 100 N along −x on the piston gives F·vB/ω1 = −100·dxB/dφ.  The piston's travel over a cycle
    # is zero, so it does no work over the cycle: it goes with the resistances, as a weight does, and the
    # constant driving moment that balances it is none.
    np.testing.assert_allclose(model.resisting, -force * x1, rtol=0, atol=1e-10 * force * r)
    assert model.constant == "driving" and model.resisting_loads == ("loads[0]",) and model.driving_loads == ()
    np.testing.assert_allclose(model.driving, 0.0, atol=1e-9 * force * r)


def test_massless_links_with_a_piston_mass_give_m_times_the_velocity_ratio_squared():
    """Je = m·(vB/ω1)², the textbook's first example of a reduced inertia."""
    text = SLIDER_CRANK.replace("inertia = 0.01\n", "").replace("[links.3]\ninertia = 0.02\n", "")
    text = text.replace("mass = 3.0\ncentre = \"S2\"\n", "mass = 0.0\n")
    model = equivalent_model_of(loads(text))
    scene = loads(text)
    _, motion = solved_at(scene, model.driver)
    velocity = motion.point("B").v
    np.testing.assert_allclose(model.inertia, 2.5 * (velocity[:, 0] ** 2 + velocity[:, 1] ** 2) / 10.0**2, rtol=1e-13)


# --- the works ----------------------------------------------------------------------------------


def test_resisting_work_of_the_ratchet_is_the_moment_times_its_share_of_the_swing():
    """1500 N·m against the rocker over the first 0.881 of its working swing: Ar = 1500·0.881·Δθ4.

    The window's ends are found by bisection and put into the sweep; without them the work of
    the jump would be off by up to ½·M·Δψ (about 0.8 % at 360 steps).
    """
    scene = scene_of("ratchet_crank_rocker")
    mechanism = build(scene)
    positions = make_positions(mechanism)
    ends = solve(mechanism, np.array(positions.extremes), positions.reference)
    angles = np.asarray(ends.links[4].angle)
    swing = abs(float(np.angle(np.exp(1j * (angles[1] - angles[0])))))
    model = model_of("ratchet_crank_rocker")
    assert len(model.coordinate) > DEFAULT_COUNT + 1   # the window's ends were put in
    # The weights do no work over a cycle; what is left of their trapezoid sum is O(Δψ²).
    assert model.resisting_work[-1] == pytest.approx(1500.0 * 0.881 * swing, rel=1e-4)


@pytest.mark.parametrize("name", CRANKS)
def test_constant_driving_moment_balances_the_cycle(name):
    model = model_of(name)
    assert abs(model.imbalance) <= 1e-9 * float(np.max(model.resisting_work))
    np.testing.assert_allclose(model.energy, model.driving_work - model.resisting_work, rtol=0, atol=1e-12)
    if model.constant == "driving":
        np.testing.assert_allclose(model.driving, model.resisting_work[-1] / (2 * math.pi), rtol=1e-12)


def test_engine_keeps_its_gas_force_and_takes_the_resistance_constant():
    model = model_of("engine_slider_crank")
    assert model.constant == "resisting"
    raw = model_of("engine_slider_crank", "none")
    np.testing.assert_allclose(model.driving, raw.driving)
    # The weights stay on the resisting side; only a constant is added to them.
    difference = model.resisting - raw.resisting
    np.testing.assert_allclose(difference, difference[0], rtol=1e-12)


def test_slider_driver_gives_a_translating_equivalent_link():
    model = model_of("slider_driven")
    assert model.kind == "slider" and not model.turning
    assert model.coordinate[-1] == pytest.approx(0.20)
    # The rod's own 6 kg moves with the driver: me is at least that.
    assert np.all(model.inertia >= 6.0)
    with pytest.raises(ValueError, match="turning driver"):
        flywheel_for(model, 0.05)


# --- the plans ----------------------------------------------------------------------------------


@pytest.mark.parametrize("name", FIXTURES)
def test_reduction_read_off_the_velocity_plans_matches_the_analytic_one(name):
    analysis = analyse(scene_of(name))
    reductions = plan_reductions(analysis)
    assert [r.number for r in reductions] == [plan.number for plan in analysis.plans]
    assert reductions
    for reduction in reductions:
        assert abs(reduction.inertia_error_percent) < 1e-7
        assert reduction.moment == pytest.approx(reduction.moment_exact, rel=1e-8, abs=1e-9)
    # And the model of the analysis carries them; where a plan position is a sample of the sweep
    # (a crank's, every 30°), the sweep's Je there is the plan's exact one.
    model = model_of(name)
    assert model.plans == reductions
    for reduction in reductions:
        same = np.flatnonzero(np.isclose(model.driver, reduction.driver, rtol=0, atol=1e-12))
        if model.turning:
            assert len(same)
        for index in same:
            assert model.inertia[index] == pytest.approx(reduction.inertia_exact, rel=1e-12)


# --- bad arguments ------------------------------------------------------------------------------


def test_bad_arguments_are_named():
    scene = scene_of("engine_slider_crank")
    with pytest.raises(ValueError, match="constant must be one of"):
        equivalent_model_of(scene, constant="motor")
    with pytest.raises(ValueError, match=r"constant='driving' replaces the driving moment.*loads\[0\]"):
        equivalent_model_of(scene, constant="driving")
    with pytest.raises(ValueError, match="count must be an integer >= 2"):
        equivalent_model_of(scene, count=1)
    mechanism, motion = solved_at(scene, np.array([1.0, 0.5]))
    with pytest.raises(ValueError, match="follow the driver's motion"):
        equivalent_model(mechanism, motion)
    with pytest.raises(ValueError, match=r"acting must have shape \(1, 2\)"):
        equivalent_model(*solved_at(scene, np.array([0.5, 1.0])), np.ones((2, 2), dtype=bool))


# --- the drawing --------------------------------------------------------------------------------


def _layer(layers, name):
    return next(layer for layer in layers if layer.name == name)


def test_dynamics_sheet_draws_every_diagram_with_its_scale():
    model = model_of("ratchet_crank_rocker")
    flywheel = flywheel_for(model, 0.05, shaft_rpm=1440.0)
    layers = layout(model, flywheel)
    names = [layer.name for layer in layers]
    assert names == ["moments", "works", "energy", "energy-mass", "inertia", "results", "title"]
    texts = " ".join(item.text for layer in layers for item in layer.items if isinstance(item, Text))
    for scale in ("μM = ", "μA = ", "μT = ", "μJ = ", "μφ = 2°/mm"):
        assert scale in texts
    scales = scales_for(model)
    # Each diagram fills its field at a standard scale, no more than its field.
    assert float(np.ptp(model.energy)) / scales.energy <= 55.0 + 1e-9
    assert float(np.max(model.inertia)) / scales.inertia <= 80.0 + 1e-9


def test_tangents_of_the_energy_mass_diagram_cut_ab_off_the_energy_axis():
    model = model_of("shaper_six_bar")
    flywheel = flywheel_for(model, 0.05)
    scales = scales_for(model)
    layers = layout(model, flywheel, scales=scales)
    mass = _layer(layers, "energy-mass")
    # The ΔT axis of the energy–mass diagram is its vertical line at Je = 0; find its x on the sheet.
    tangents = [item for item in mass.items if isinstance(item, Polyline) and item.stroke.colour == "#b22222"]
    assert len(tangents) == 2
    origin_y = _layer(layers, "energy").items[0].start[1]   # the φ axis of ΔT(φ): ΔT = 0 on both diagrams
    axis_x = min(point[0] for line in tangents for point in line.points)
    for line, tangent in zip(tangents, (flywheel.upper, flywheel.lower)):
        (x0, y0), (x1, y1) = line.points
        assert (y1 - y0) / (x1 - x0) == pytest.approx(tangent.slope * scales.inertia / scales.energy, rel=1e-9)
        assert x0 == pytest.approx(axis_x)
        assert y0 - origin_y == pytest.approx(tangent.intercept / scales.energy, abs=1e-9)
    ab = (flywheel.upper.intercept - flywheel.lower.intercept) / scales.energy
    assert any(isinstance(item, Text) and item.text == f"ab = {ab:.1f} mm" for item in mass.items)
    # J_F = ab·μT/(ωmax²/2 − ωmin²/2): the drawing's segment gives the flywheel.
    assert ab * scales.energy / (flywheel.upper.slope - flywheel.lower.slope) == pytest.approx(flywheel.inertia)


def test_the_steep_tangents_of_a_fast_machine_stay_by_their_curve(tmp_path):
    """tan ψ grows as ωm²: at 1000 rpm the shaper's tangents, drawn from the ΔT axis to past the curve, made the
    energy–mass diagram 3.4 m tall (30 m at 3000 rpm) and the run refused it, on advice that did not help, while
    check said ok (a teacher's variants).  Each is drawn only across the band of its curve, at its slope and
    through the point it touches: the diagram is as tall at 3000 rpm as at 1000, and the run draws it."""
    from importlib import resources

    from graphplan.cli import main

    template = resources.files("graphplan").joinpath("templates/shaper.toml").read_text(encoding="utf-8")
    # The μl the run chooses for these sheets when the scene leaves it out (the largest drawing on the fewest
    # sheets), given: the run then draws the same sheets without laying the linkage's drawings out at every μl it
    # weighs (two thirds of its time), which have nothing to do with the dynamics drawing in question.
    template, given = re.subn(r"^# length_scale .*$", "length_scale = 0.004", template, count=1, flags=re.MULTILINE)
    assert given == 1
    heights = []
    for rpm in (-1000.0, -3000.0):
        text = re.sub(r"^rpm .*$", f"rpm = {rpm}", template, count=1, flags=re.MULTILINE)
        model = equivalent_model_of(analyse(loads(text)))
        flywheel = flywheel_for(model, 0.05)
        scales = scales_for(model)
        mass = _layer(layout(model, flywheel, scales=scales), "energy-mass")
        curve = next(item for item in mass.items if isinstance(item, Polyline) and item.closed)
        tangents = [item for item in mass.items if isinstance(item, Polyline) and item.stroke.colour == "#b22222"]
        for line, tangent in zip(tangents, (flywheel.upper, flywheel.lower), strict=True):
            (x0, y0), (x1, y1) = line.points
            slope = tangent.slope * scales.inertia / scales.energy
            assert slope > 10.0   # steep: the case in point
            assert (y1 - y0) / (x1 - x0) == pytest.approx(slope, rel=1e-9)
            touch_x, touch_y = curve.points[tangent.touch]   # the curve's points are the model's samples, in order
            assert touch_y - y0 == pytest.approx(slope * (touch_x - x0), rel=1e-6, abs=1e-6)
        _, bottom, _, top = bounds_of(mass.items)
        heights.append(top - bottom)
        scene = tmp_path / f"fast_{-rpm:.0f}.toml"
        scene.write_text(text, encoding="utf-8")
        assert main(["run", str(scene), "--out", str(tmp_path / f"out_{-rpm:.0f}"), "--only", "dynamics,sheets"]) == 0
    assert heights[1] < 1.5 * heights[0] and heights[0] < 1000.0


def test_dynamics_sheet_renders_the_same_every_time():
    cairosvg = pytest.importorskip("cairosvg")
    model = model_of("engine_slider_crank")
    flywheel = flywheel_for(model, 0.02)
    svg = dynamics_svg(model, flywheel)
    assert svg == dynamics_svg(model, flywheel)
    assert cairosvg.svg2png(bytestring=svg.encode())[:8] == b"\x89PNG\r\n\x1a\n"
    translated = dynamics_svg(model, flywheel, {"dyn_title": "Динамика машины"})
    assert "Динамика машины" in translated
    # The shaper's Me goes negative: its ticks carry a true minus sign, as every other drawing's numbers do.
    shaper = dynamics_svg(model_of("shaper_six_bar"), flywheel_for(model_of("shaper_six_bar"), 0.05))
    assert re.search(r">−\d", shaper) and not re.search(r">-\d", shaper)


def test_slider_driver_sheet_has_no_energy_mass_diagram():
    layers = layout(model_of("slider_driven"))
    names = [layer.name for layer in layers]
    assert "energy-mass" not in names and "inertia" in names and "results" not in names


def test_the_energy_mass_diagram_is_graduated_in_je_as_je_of_phi_under_it():
    model = model_of("shaper_six_bar")
    layers = layout(model, flywheel_for(model, 0.05))

    def ticks(name):  # (x of each short upright stroke across the layer's axis of Je, its number)
        items = _layer(layers, name).items
        (axis,) = [item for item in items if isinstance(item, Arrow) and item.start[1] == item.end[1]]
        y = axis.start[1]
        strokes = [item for item in items if isinstance(item, Polyline) and len(item.points) == 2
                   and item.points[0][0] == item.points[1][0] and item.points[0][1] < y < item.points[1][1]]
        numbers = {round(item.at[0], 6): item.text for item in items if isinstance(item, Text)}
        return [(stroke.points[0][0], numbers.get(round(stroke.points[0][0], 6))) for stroke in strokes]

    above, below = ticks("energy-mass"), ticks("inertia")
    assert len(above) >= 3 and above == below
    # The step is round and the numbers are Je at μJ: x = Je/μJ from the ΔT axis at x of the first tick's Je.
    scales = scales_for(model)
    values = [float(text) for _, text in above]
    origin = above[0][0] - values[0] / scales.inertia
    assert [x for x, _ in above] == pytest.approx([origin + value / scales.inertia for value in values])


def test_the_dynamics_stands_whole_on_an_a1_and_in_its_diagrams_on_smaller_sheets():
    model = model_of("shaper_six_bar")
    layers = layout(model, flywheel_for(model, 0.05))
    (whole,) = dynamics_sheet([dynamics_panel(layers, "en")], "A1")
    assert list(whole.panels) == ["dynamics"]
    written = [item.text for layer in whole.layers if layer.name == "title-block" for item in layer.items
               if isinstance(item, Text)]
    assert "Dynamics of the machine" in written
    diagrams = {f"dynamics-{layer.name}" for layer in layers if layer.name != "title"}
    for size in ("A2", "A3", "A4"):
        sheets = dynamics_sheet([dynamics_panel(layers, "en")], size)
        placed = [name for sheet in sheets for name in sheet.panels]
        # The energy–mass diagram and Je(φ) under it stand together where a sheet holds the two.
        shown = {part for name in placed
                 for part in (("dynamics-energy-mass", "dynamics-inertia") if name == "dynamics-flywheel" else (name,))}
        assert shown == diagrams and len(placed) == len(set(placed)), size
        for sheet in sheets:
            x0, y0, x1, y1 = sheet.frame
            for rect in sheet.panels.values():
                assert x0 <= rect[0] and rect[2] <= x1 and y0 <= rect[1] and rect[3] <= y1, size


def test_a_run_names_the_angle_of_its_dynamics_from_the_first_position_and_keeps_the_columns_apart(tmp_path):
    # The diagrams run from the first position (ψ = 0 there), while the note's φ of ωmax is the crank's own
    # angle: the axis says where it starts.  A longer name than "φ, °" moves the energy–mass diagram clear of it.
    from shapely.geometry import box

    from graphplan.cli import main
    from graphplan.render.labels import text_box

    scene = tmp_path / "shaper.toml"
    scene.write_text(Path("fixtures/shaper_six_bar.toml").read_text(encoding="utf-8") + "\n[dynamics]\ndelta = 0.05\n",
                     encoding="utf-8")
    first = int(load(scene).positions.number_from)
    model = model_of("shaper_six_bar")
    words = {"dyn_angle_axis": f"φ, ° from position {first}"}
    layers = {layer.name: layer for layer in layout(model, flywheel_for(model, 0.05), words)}
    names = [item for layer in ("moments", "works", "energy") for item in layers[layer].items
             if isinstance(item, Text) and item.text == words["dyn_angle_axis"]]
    assert len(names) == 3
    energy_mass = box(*bounds_of(layers["energy-mass"].items))
    assert not any(text_box(name).intersects(energy_mass) for name in names)
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
    assert (out / "dynamics.svg").read_text(encoding="utf-8").count(f"φ, ° from position {first}") == 4


def test_a_diagram_load_enters_the_reduced_moment_by_its_diagram_and_switches_only_where_it_starts_and_stops():
    # The shaper's cut as a diagram rising over the first tenth of the stroke: the model took the load whole
    # wherever its window was open (a step of 145 N·m where the diagram starts from nought), and put a switch's
    # two samples at every sample of the ramp (415 samples for 361).
    text = (FIXTURE_DIR / "shaper_six_bar.toml").read_text(encoding="utf-8").replace(
        "value     = 2000.0       # N, cutting force", "").replace(
        "during    = { from = 0.05, to = 0.95 }", "diagram   = [[0.05, 0.0], [0.1, 2000.0], [0.9, 2000.0], [0.95, 0.0]]")
    assert "diagram" in text
    scene = loads(text)
    model = equivalent_model_of(analyse(scene), 360, constant="none")
    mechanism = build(scene)
    positions = make_positions(mechanism)
    motion = solve(mechanism, model.driver, positions.reference)
    balance = equilibrium(mechanism, motion, link_loads(mechanism, motion_state(motion),
                                                        activity(mechanism, positions, motion)))
    velocity, rate = scene.driver.omega, scene.driver.epsilon
    energy_rate = 0.5 * model.inertia_slope * model.speed ** 3 + model.inertia * velocity * rate
    residual = balance.balancing * velocity + model.moment * model.speed - energy_rate
    np.testing.assert_allclose(residual, 0.0, atol=1e-8 * float(np.max(np.abs(balance.balancing * velocity))))
    # The diagram sets in from nought and ends at nought: no jump anywhere, and a switch's two samples at each of
    # its four vertices at most (where it starts, turns its two corners and stops).
    assert len(model.coordinate) <= 361 + 2 * 4
    steps = np.abs(np.diff(model.resisting))
    assert float(np.max(steps)) < 0.25 * float(np.max(np.abs(model.resisting)))


def test_the_mean_reduced_inertia_is_its_mean_over_the_turn_not_over_the_samples():
    """A force of the working stroke switches on and off: the model samples both sides of each jump, and the
    plain mean of its samples counted those crank angles twice (a teacher's compressor: Je,mean 0.077741 against
    0.078043 kg·m²)."""
    scene = loads(COMPRESSOR)
    model = equivalent_model_of(analyse(scene))
    assert np.sum(np.diff(model.coordinate) < 1e-9) >= 2  # the jumps sampled on both sides
    turn = np.linspace(0.0, 2 * math.pi, 3600, endpoint=False)
    by_energy = _kinetic_inertia(scene, turn, 1e-4)
    assert model.mean_inertia == pytest.approx(float(np.mean(by_energy)), rel=1e-6)
    assert abs(float(np.mean(model.inertia)) - model.mean_inertia) > 1e-3 * model.mean_inertia


# The slider-crank above with its piston force a resistance of the working stroke alone: it switches on and off.
COMPRESSOR = SLIDER_CRANK.replace('angle = 180.0\n', 'angle = 180.0\nresisting = true\nduring = "working"\n') + """
[positions]
count = 12
start = "extreme"
working = { link = 4, sense = "backward" }
[dynamics]
delta = 0.04
count = 360
"""


def test_the_note_shows_the_dynamics_in_parts_each_printed_at_a_readable_size(tmp_path):
    """Whole, the dynamics drawing (two columns, 400 mm wide) printed on the note's 170 × 200 mm figure with letters
    about 1 mm high; the note shows it in parts, each at half size or larger, nothing of it left out or shown twice."""
    from graphplan.cli import main
    from graphplan.render.dynamics import TITLE_LAYER

    page_width, page_height, least = 170.0, 200.0, 0.5   # A4's line and a figure's room, as note_parts.py sets them

    def print_scale(svg_file):
        root = ElementTree.parse(svg_file).getroot()
        width, height = (float(root.get(key).removesuffix("mm")) for key in ("width", "height"))
        return min(page_width / width, page_height / height)

    def groups(svg_file):
        return [group.get("id") for group in ElementTree.parse(svg_file).getroot()
                if group.tag.endswith("}g") and len(group)]

    scene = tmp_path / "shaper.toml"
    scene.write_text(Path("fixtures/shaper_six_bar.toml").read_text(encoding="utf-8") + "\n[dynamics]\ndelta = 0.05\n",
                     encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    parts = sorted(out.glob("dynamics-*.svg"), key=lambda path: int(path.stem.split("-")[1]))
    assert print_scale(out / "dynamics.svg") < least and len(parts) >= 2
    assert all(print_scale(part) >= least for part in parts)
    shown = [name for part in parts for name in groups(part)]
    assert sorted(shown) == sorted(groups(out / "dynamics.svg")) and TITLE_LAYER in groups(parts[0])
    note = (out / "note.md").read_text(encoding="utf-8")
    assert [f"dynamics-{k}.svg" for k in range(1, len(parts) + 1)] == re.findall(r"\]\((dynamics[-\d]*\.svg)\)", note)


@pytest.mark.parametrize("name", CRANKS)
def test_the_ordinate_is_ticked_down_to_within_half_a_step_of_the_lowest_value(name):
    """The engine's resisting moment, a constant −71.6 N·m, ran under an ordinate ticked 0, 100, 200 alone: under
    the φ numbers it read as a second abscissa (a hunt's zh dynamics sheet).  The ordinate now runs on to the tick
    under a value that lies over half a step under the lowest tick."""
    model = model_of(name)
    layers = {layer.name: layer for layer in layout(model)}
    for diagram, curves in (("moments", (model.driving, model.resisting)),
                            ("works", (model.driving_work, model.resisting_work)), ("energy", (model.energy,))):
        ticks = sorted(float(item.text.replace("−", "-")) for item in layers[diagram].items
                       if isinstance(item, Text) and item.anchor == "end")
        step = ticks[1] - ticks[0]
        lowest = min(float(np.min(curve)) for curve in curves)
        assert lowest >= ticks[0] - step / 2 - 1e-9, (diagram, ticks, lowest)
    if name == "engine_slider_crank":
        moments = sorted(float(item.text.replace("−", "-")) for item in layers["moments"].items
                         if isinstance(item, Text) and item.anchor == "end")
        assert moments[0] < 0 and moments[0] <= float(np.min(model.resisting))


def test_a_swing_s_energy_mass_curve_runs_from_its_first_position_to_its_last_and_does_not_close():
    """A rocking crank's model is run once over its swing: Je at its end differs from Je at its start, and the
    energy–mass curve drawn closed ran a false chord from its last point back to its first (through the Je axis's
    tick labels on the double rocker).  A cycle's curve still closes on itself."""
    from graphplan.dynamics import equivalent_model_of

    model = equivalent_model_of(analyse(load(Path(__file__).parent.parent / "fixtures" / "double_rocker_swing.toml")))
    assert not model.cyclic and model.inertia[-1] != pytest.approx(model.inertia[0], rel=1e-3)
    scales = scales_for(model)
    (curve, *_) = next(layer.items for layer in layout(model, None, None, scales) if layer.name == "energy-mass")
    assert isinstance(curve, Polyline) and not curve.closed
    # Its ends are the swing's first and last samples, at the drawing's own scales (the layer is moved as a whole).
    (x0, y0), (x1, y1) = curve.points[0], curve.points[-1]
    assert x1 - x0 == pytest.approx((model.inertia[-1] - model.inertia[0]) / scales.inertia, rel=1e-9)
    assert y1 - y0 == pytest.approx((model.energy[-1] - model.energy[0]) / scales.energy, rel=1e-9, abs=1e-9)
