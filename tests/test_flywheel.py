"""The flywheel against published worked examples and against the equation of motion.

Published examples, reproduced to their printed precision (sources in docs/sources/flywheel.md):

* a shaper driven at constant power against 367.7 W for a third of the cycle and 3677 W for the
  rest (Sun Huan et al., *机械原理*, exercise in the chapter on speed fluctuation);
* R.S. Khurmi and J.K. Gupta, *Theory of Machines*, chapter 16: Example 16.4 (loop areas of a
  turning-moment diagram), Example 16.9 (a four-stroke gas engine's triangular diagram) and
  Example 16.12 (an engine torque against a varying resisting torque).

A linkage's flywheel from the energy–mass diagram is checked by integrating the equation of
motion of the equivalent link, d(ω²)/dψ = (2·Me − Je′·ω²)/(JF + Je), with scipy's solve_ivp:
the speed it finds must swing between ωm·(1 ± δ/2), and a machine whose Je is constant must
get the same flywheel from all three methods.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import json
import math
import re
from pathlib import Path
from types import MappingProxyType

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq

from graphplan.analysis import analyse
from graphplan.dynamics import equivalent_model_of
from graphplan.errors import SceneError
from graphplan.flywheel import (
    dynamics_results,
    fluctuation,
    fluctuation_from_areas,
    flywheel_for,
    flywheel_from_spec,
    flywheel_inertia,
    moved_inertia,
    omega_to_rpm,
    read_dynamics,
    rpm_to_omega,
    speed_fluctuation,
    speed_limits,
)
from graphplan.reader import Table
from graphplan.scene import LinkSpec, load

FIXTURE_DIR = Path(__file__).resolve().parent.parent / "fixtures"


@functools.cache
def model_of(name: str, constant: str = "auto"):
    return equivalent_model_of(analyse(load(FIXTURE_DIR / f"{name}.toml")), constant=constant)


# --- published examples -------------------------------------------------------------------------


def test_shaper_flywheel_from_a_power_cycle():
    """Sun Huan et al., 机械原理: the shaper's crank at n = 100 rpm, 367.7 W for its 120° idle stroke,
    3677 W for the rest, driven at constant power, δ = 0.05; the flywheel on the crank and on a
    1440 rpm motor shaft.  Printed: P = 2573.9 W, ΔWmax = 441.24 J, JF = 80.473 kg·m², JF′ = 0.388 kg·m².
    """
    period = 60.0 / 100.0
    cycle = fluctuation([0.0, period / 3, period], resisting=[367.7, 3677.0], steps=True)
    assert round(cycle.mean, 1) == 2573.9
    assert round(cycle.delta_w_max, 2) == 441.24
    # The speed is greatest where the idle stroke ends, least where it begins.
    assert cycle.x_max == pytest.approx(period / 3) and cycle.x_min in (0.0, period)
    inertia = flywheel_inertia(cycle.delta_w_max, rpm_to_omega(100.0), 0.05)
    assert round(inertia, 3) == 80.473
    assert round(moved_inertia(inertia, 100.0, 1440.0), 3) == 0.388
    # The same cycle as a torque diagram over the crank angle: M = P/ω, the same surplus.
    omega = rpm_to_omega(100.0)
    torque = fluctuation([0.0, 2 * math.pi / 3, 2 * math.pi], resisting=[367.7 / omega, 3677.0 / omega], steps=True)
    assert torque.delta_w_max == pytest.approx(cycle.delta_w_max, rel=1e-14)
    assert torque.mean * omega == pytest.approx(cycle.mean, rel=1e-14)


@pytest.mark.parametrize("apex", [0.5, 0.25, 0.8])
def test_four_stroke_gas_engine_with_a_triangular_diagram(apex):
    """Khurmi & Gupta, Example 16.9: 20 kW at 300 rpm, expansion work three times the compression
    work, suction and exhaust negligible, both diagrams triangles, speed within ±2 %.  Printed:
    I = 255.4 kg·m².  The area of a triangle above the mean line does not depend on where its apex
    lies, so neither does the flywheel.
    """
    work = 20e3 * 60.0 / (300.0 / 2)          # J per cycle: one working stroke every two turns
    compression, expansion = work / 2, 3 * work / 2
    pi = math.pi
    angles = np.array([0.0, pi, pi + apex * pi, 2 * pi, 2 * pi + apex * pi, 3 * pi, 4 * pi])
    torque = np.array([0.0, 0.0, -2 * compression / pi, 0.0, 2 * expansion / pi, 0.0, 0.0])
    cycle = fluctuation(angles, torque)
    assert cycle.mean * 4 * pi == pytest.approx(work, rel=1e-14)
    inertia = flywheel_inertia(cycle.delta_w_max, rpm_to_omega(300.0), 0.04)
    assert round(inertia, 1) == 255.4


def test_petrol_engine_from_the_loop_areas_of_its_turning_moment_diagram():
    """Khurmi & Gupta, Example 16.4: 1 mm = 5 N·m and 1 mm = 1°; loops 295, 685, 40, 340, 960, 270 mm²
    above and below the mean line in turn; 36 kg at k = 150 mm, 1800 rpm.  Printed: ΔE = 985 mm² =
    86 N·m (E + 295 − (E − 690)), CS = 0.003.
    """
    cycle = fluctuation_from_areas([295, -685, 40, -340, 960, -270], scale=5.0 * math.pi / 180)
    assert cycle.delta_w_max / (5.0 * math.pi / 180) == pytest.approx(985.0)
    assert round(cycle.delta_w_max) == 86
    assert (cycle.x_max, cycle.x_min) == (1.0, 4.0)
    assert round(speed_fluctuation(cycle.delta_w_max, rpm_to_omega(1800.0), 36 * 0.15**2), 3) == 0.003


def test_engine_against_a_varying_resisting_torque():
    """Khurmi & Gupta, Example 16.12: T = 5000 + 600 sin 2θ against 5000 + 500 sin θ N·m, 500 kg at
    k = 0.4 m, 150 rpm.  Printed: ΔE = 1204 N·m, total fluctuation 6.1 %; the net torque's zeros at
    0°, 65.4°, 180°, 294.6°, the speed least at 180° and greatest at 65.4° (and 294.6°).
    """
    theta = np.linspace(0.0, 2 * math.pi, 3601)
    cycle = fluctuation(theta, 5000 + 600 * np.sin(2 * theta), 5000 + 500 * np.sin(theta))
    assert cycle.mean is None
    assert round(cycle.delta_w_max) == 1204
    # In closed form: W(θ) = 600 sin²θ + 500 (cos θ − 1), greatest where cos θ = 5/12, least at 180°.
    top = 600 * (1 - (5 / 12) ** 2) + 500 * (5 / 12 - 1)
    assert cycle.delta_w_max == pytest.approx(top + 1000.0, rel=1e-6)
    assert round(100 * speed_fluctuation(cycle.delta_w_max, rpm_to_omega(150.0), 500 * 0.4**2), 1) == 6.1
    assert math.degrees(cycle.x_min) == pytest.approx(180.0, abs=0.1)
    assert round(math.degrees(cycle.x_max), 1) in (65.4, 294.6)


# --- the standalone functions against quadrature -------------------------------------------------


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_piecewise_linear_diagram_surplus_is_exact(seed):
    """The surplus range of a piecewise-linear diagram, found at its vertices and the net's zeros,
    against scipy's quad of the interpolated diagram between those zeros (found by brentq)."""
    rng = np.random.default_rng(seed)
    x = np.sort(np.concatenate([[0.0, 2 * math.pi], rng.uniform(0.0, 2 * math.pi, 10)]))
    torque = rng.uniform(-200.0, 800.0, len(x))
    cycle = fluctuation(x, torque)

    def net(t):
        return float(np.interp(t, x, torque)) - cycle.mean

    marks = [0.0]
    fine = np.linspace(0.0, 2 * math.pi, 20001)
    values = np.array([net(t) for t in fine])
    for k in np.flatnonzero(values[:-1] * values[1:] < 0):
        marks.append(brentq(net, fine[k], fine[k + 1], xtol=1e-14))
    marks.append(2 * math.pi)
    surplus = np.cumsum([0.0] + [quad(net, a, b, points=x[(x > a) & (x < b)], epsabs=1e-12)[0]
                                 for a, b in itertools.pairwise(marks)])
    assert cycle.delta_w_max == pytest.approx(float(np.ptp(surplus)), rel=1e-9)
    assert abs(cycle.imbalance) < 1e-9 * float(np.sum(np.abs(torque)))


def test_speed_limits_and_moving_the_flywheel():
    fastest, slowest = speed_limits(100.0, 0.04)
    assert (fastest, slowest) == pytest.approx((102.0, 98.0))
    assert (fastest - slowest) / ((fastest + slowest) / 2) == pytest.approx(0.04)
    # Moving to a faster shaft keeps ½·J·ω² the same at every instant.
    assert 0.5 * moved_inertia(80.0, 100.0, 1440.0) * rpm_to_omega(1440.0) ** 2 == pytest.approx(
        0.5 * 80.0 * rpm_to_omega(100.0) ** 2)
    assert omega_to_rpm(rpm_to_omega(1234.5)) == pytest.approx(1234.5)
    assert flywheel_inertia(100.0, 10.0, 0.1, inertia=2.0) == pytest.approx(100.0 / 10.0 - 2.0)


def test_bad_arguments_of_the_standalone_functions_are_named():
    with pytest.raises(ValueError, match="give the driving or the resisting load"):
        fluctuation([0.0, 1.0])
    with pytest.raises(ValueError, match="increasing"):
        fluctuation([1.0, 0.0], [1.0, 2.0])
    with pytest.raises(ValueError, match="resisting must have 1 values, not 2"):
        fluctuation([0.0, 1.0], resisting=[1.0, 2.0], steps=True)
    with pytest.raises(ValueError, match="finite"):
        fluctuation([0.0, 1.0], [1.0, math.nan])
    with pytest.raises(ValueError, match="delta must lie between 0 and 2"):
        flywheel_inertia(10.0, 10.0, 0.0)
    with pytest.raises(ValueError, match="omega_mean must be a positive number"):
        flywheel_inertia(10.0, -10.0, 0.05)
    with pytest.raises(ValueError, match="speeds must be > 0"):
        moved_inertia(1.0, 100.0, 0.0)
    with pytest.raises(ValueError, match="scale must be a positive number"):
        fluctuation_from_areas([1.0, -1.0], 0.0)


# --- a linkage's flywheel -----------------------------------------------------------------------


def _integrated_speed(model, flywheel):
    """ω over the cycle from the equation of motion of the equivalent link, started at the flywheel's ω0."""
    psi = model.coordinate
    # Piecewise linear between the samples (a window's jump lies between two samples a hair apart).
    def rate(t, y):
        moment = np.interp(t, psi, model.moment)
        inertia = np.interp(t, psi, model.inertia)
        slope = np.interp(t, psi, model.inertia_slope)
        return [(2.0 * moment - slope * y[0]) / (flywheel.inertia + inertia)]
    start = [float(flywheel.omega[0]) ** 2]
    # A window's two sides may share an abscissa with a sample: solve at each abscissa once.
    where, first = np.unique(psi, return_index=True)
    found = solve_ivp(rate, (0.0, float(psi[-1])), start, t_eval=where, rtol=1e-10, atol=1e-10,
                      max_step=2 * math.pi / 360)
    assert found.success
    return np.sqrt(found.y[0]), first


@pytest.mark.parametrize("name", ["ratchet_crank_rocker", "shaper_six_bar", "engine_slider_crank"])
def test_energy_mass_flywheel_keeps_the_equation_of_motion_within_delta(name):
    model = model_of(name)
    flywheel = flywheel_for(model, 0.05)
    fastest, slowest = speed_limits(model.speed, 0.05)
    assert flywheel.omega_max == pytest.approx(fastest, rel=1e-12)
    assert flywheel.omega_min == pytest.approx(slowest, rel=1e-12)
    omega, first = _integrated_speed(model, flywheel)
    # A steady cycle: the speed comes back to where it started.
    assert omega[-1] == pytest.approx(omega[0], rel=1e-5)
    assert (omega.max() - omega.min()) / model.speed == pytest.approx(0.05, rel=2e-3)
    assert (omega.max() + omega.min()) / 2 == pytest.approx(model.speed, rel=1e-5)
    np.testing.assert_allclose(omega, flywheel.omega[first], rtol=1e-4)
    # Both tangents hold the curve between them and touch it where the speed is greatest and least.
    assert np.all(model.energy - flywheel.upper.slope * model.inertia <= flywheel.upper.intercept + 1e-9)
    assert np.all(model.energy - flywheel.lower.slope * model.inertia >= flywheel.lower.intercept - 1e-9)
    assert flywheel.omega[flywheel.upper.touch] == pytest.approx(flywheel.omega_max, rel=1e-12)
    assert flywheel.omega[flywheel.lower.touch] == pytest.approx(flywheel.omega_min, rel=1e-12)


def test_constant_reduced_inertia_gives_one_flywheel_by_every_method():
    """With Je constant the energy–mass curve is a vertical segment: its tangents cut off exactly
    ΔWmax, and JF = ΔWmax/(ωm²δ) − Je by all three methods."""
    scene = load(FIXTURE_DIR / "ratchet_crank_rocker.toml")
    only_crank = {2: LinkSpec(2, "links.2", 16.0, "S2", 0.0)}
    model = equivalent_model_of(dataclasses.replace(scene, links=MappingProxyType(only_crank)))
    np.testing.assert_allclose(model.inertia, 16.0 * 0.08**2, rtol=1e-13)
    flywheel = flywheel_for(model, 0.03)
    expected = float(np.ptp(model.energy)) / (17.0**2 * 0.03) - 16.0 * 0.08**2
    assert flywheel.inertia == pytest.approx(expected, rel=1e-10)
    assert flywheel.approximate == pytest.approx(expected, rel=1e-12)
    assert flywheel.mertsalov == pytest.approx(expected, rel=1e-12)
    assert flywheel.constant_inertia == pytest.approx(16.0 * 0.08**2)


def test_flywheel_options_and_refusals():
    model = model_of("ratchet_crank_rocker")
    moved = flywheel_for(model, 0.05, shaft_rpm=1440.0)
    assert moved.moved == pytest.approx(moved.inertia * (omega_to_rpm(17.0) / 1440.0) ** 2)
    slower = flywheel_for(model, 0.05, omega_mean=10.0)
    assert (slower.omega_max, slower.omega_min) == pytest.approx(speed_limits(10.0, 0.05))
    # Slower, the same energy swing needs more inertia: about (17/10)² as much.
    assert slower.inertia > 2.5 * moved.inertia
    with pytest.raises(ValueError, match="not periodic"):
        flywheel_for(model_of("engine_slider_crank", "none"), 0.05)
    with pytest.raises(ValueError, match="delta must lie between 0 and 2"):
        flywheel_for(model, 2.5)


# --- the scene's [dynamics] table ---------------------------------------------------------------


def test_dynamics_table_is_read_with_its_keys_checked():
    spec = read_dynamics(Table({"delta": 0.05, "rpm": 100.0, "flywheel_shaft_rpm": 1440.0,
                                "motor": {"kind": "constant", "torque": 50.0}, "duration": 2.0}, "dynamics"))
    assert spec.delta == 0.05 and spec.omega == pytest.approx(100.0 * math.pi / 30.0)
    assert spec.flywheel_shaft_rpm == 1440.0 and spec.constant == "auto" and spec.count == 360
    assert spec.motion.motor.torque == 50.0 and spec.motion.duration == 2.0
    assert read_dynamics(Table({"delta": 0.05}, "dynamics")).motion is None
    with pytest.raises(SceneError, match=r"dynamics\.motor: is required"):
        read_dynamics(Table({"brake": {"torque": 10.0}}, "dynamics"))
    assert read_dynamics(Table({}, "dynamics")).delta is None
    model = model_of("ratchet_crank_rocker")
    asked = flywheel_from_spec(model, spec)
    assert asked.inertia == pytest.approx(flywheel_for(model, 0.05, spec.omega).inertia)
    assert asked.moved == pytest.approx(asked.inertia * (100.0 / 1440.0) ** 2)
    assert flywheel_from_spec(model, read_dynamics(Table({}, "dynamics"))) is None


@pytest.mark.parametrize(("data", "message"), [
    ({"detla": 0.05}, "dynamics.detla: unknown key; did you mean 'delta'?"),
    ({"delta": 0.0}, "dynamics.delta: must be > 0 (got 0.0)"),
    ({"delta": 2.5}, "dynamics.delta: must be < 2"),
    ({"rpm": 100.0, "omega": 10.0}, "dynamics.rpm: give either omega or rpm, not both"),
    ({"constant": "motor"}, "dynamics.constant: must be one of auto, driving, resisting, none"),
    ({"count": 5}, "dynamics.count: must be >= 12 (got 5)"),
    ({"flywheel_shaft_rpm": "fast"}, "dynamics.flywheel_shaft_rpm: must be a number, not a string"),
    # A shaft speed no flywheel turns at moved a flywheel 1e16 times the crank's (1e-6 rpm) without a word.
    ({"delta": 0.05, "flywheel_shaft_rpm": 1e-6}, "dynamics.flywheel_shaft_rpm: must be within 1–100000 rpm"),
    ({"delta": 0.05, "flywheel_shaft_rpm": 2e6}, "dynamics.flywheel_shaft_rpm: must be within 1–100000 rpm"),
    # Without δ no flywheel is sized, and the shaft it was to be moved to was passed over without a word.
    ({"flywheel_shaft_rpm": 1450.0}, ("dynamics.flywheel_shaft_rpm: moves the flywheel sized for delta to another "
                                      "shaft, but no delta is given")),
])
def test_bad_dynamics_table_names_the_key(data, message):
    with pytest.raises(SceneError) as caught:
        read_dynamics(Table(data, "dynamics"))
    assert str(caught.value).startswith(message)


# --- results ------------------------------------------------------------------------------------


def test_results_carry_the_contract_keys():
    model = model_of("shaper_six_bar")
    flywheel = flywheel_for(model, 0.05, shaft_rpm=1440.0)
    found = json.loads(json.dumps(dynamics_results(model, flywheel)))
    for key in ("reduced_inertia", "reduced_moment", "delta_w_max", "flywheel_inertia", "omega_max", "omega_min"):
        assert key in found
    count = len(model.coordinate)
    assert all(len(found[key]) == count for key in ("reduced_inertia", "reduced_moment", "angle_deg", "omega",
                                                      "kinetic_energy_change"))
    assert found["flywheel_inertia"] == pytest.approx(flywheel.inertia, rel=1e-11)
    assert found["delta_w_max"] == pytest.approx(flywheel.delta_w_max, rel=1e-11)
    assert found["omega_max"] == pytest.approx(model.speed * 1.025, rel=1e-11)
    assert found["flywheel_inertia_moved"] == pytest.approx(flywheel.moved, rel=1e-11)
    assert found["omega_max_angle_deg"] == pytest.approx(
        math.degrees(model.driver[flywheel.index_max]) % 360.0, rel=1e-11)
    assert [entry["index"] for entry in found["plans"]] == [plan.number for plan in model.plans]
    bare = dynamics_results(model_of("slider_driven"))
    assert bare["equivalent_link"] == "translating" and "flywheel_inertia" not in bare
    assert len(bare["displacement"]) == len(bare["reduced_inertia"])


@pytest.mark.parametrize("driving,too_little", [
    ('kind = "moment"\nlink = 2\nvalue = -100.0', True),     # 628 J a turn, against 1560 J: too little
    ('kind = "moment"\nlink = 2\nvalue = -1000.0', False),   # 6283 J a turn: too much
])
def test_work_that_does_not_balance_is_told_a_way_out_the_program_then_takes(tmp_path, capsys, driving, too_little):
    """A scene with driving and resisting loads whose work over the cycle differs was told "take one moment
    constant (constant='driving' or 'resisting')", and either was then refused: it gives both sides.  The way out
    it is told now, leaving a side out or adding the moment that balances the work, is checked as it says."""
    from graphplan.cli import main

    text = (Path("fixtures") / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    text += f"\n[[loads]]\n{driving}\n\n[dynamics]\ndelta = 0.05\n"
    scene = tmp_path / "unbalanced.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    told = capsys.readouterr().err
    assert "so the motion is not periodic; a constant moment" in told and "gives both (driving loads[1]; resisting " \
        "loads[0])" in told
    added = re.search(r'\[\[loads\]\] kind = "moment", link = 2, (value = \S+?)(?:,| \(N·m)( resisting = true)?',
                      told)
    assert bool(added[2]) is not too_little
    dropped = "loads[1]" if too_little else "loads[0]"
    assert f"leave out the {'driving' if too_little else 'resisting'} loads ({dropped})" in told
    scene.write_text(text.replace("\n[dynamics]", f"\n[[loads]]\nkind = \"moment\"\nlink = 2\n{added[1]}\n"
                                  f"{'resisting = true' if added[2] else ''}\n\n[dynamics]"), encoding="utf-8")
    assert main(["check", str(scene)]) == 0, capsys.readouterr().err
    first, second = text.index("[[loads]]"), text.rindex("[[loads]]")
    left = text[:second] + text[text.index("[dynamics]"):] if too_little else \
        text[:first] + text[text.index("[positions]"):]
    scene.write_text(left, encoding="utf-8")
    assert main(["check", str(scene)]) == 0, capsys.readouterr().err


@pytest.mark.parametrize("delta,warned", [(0.2, False), (0.25, True), (1.5, True)])
def test_a_delta_above_what_machines_run_with_is_worked_out_and_warned_of(tmp_path, capsys, delta, warned):
    """δ = 1.5 passed without a word: ωmin = ωm·(1 − δ/2) stays above nought up to δ < 2 and the tangents' slopes
    ωm²·(1 ± δ/2)²/2 are exact there, so the flywheel is worked out, but a speed swinging (2 + δ)/(2 − δ) to 1 is
    no steady running: a percentage typed for a fraction, most likely."""
    from graphplan.cli import main

    text = (FIXTURE_DIR / "ratchet_crank_rocker.toml").read_text(encoding="utf-8") + f"\n[dynamics]\ndelta = {delta}\n"
    scene = tmp_path / "uneven.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    told = capsys.readouterr().out
    ratio = (2 + delta) / (2 - delta)
    assert ("dynamics.delta: " in told) is warned
    if warned:
        assert f"ωmax/ωmin = (2 + δ)/(2 − δ) = {ratio:.3g}" in told and f"is δ = {delta / 100:g}" in told
        # The flywheel is the one that keeps the speed within the ratio asked for.
        flywheel = flywheel_for(model_of("ratchet_crank_rocker"), delta)
        assert flywheel.omega_max / flywheel.omega_min == pytest.approx(ratio, rel=1e-9)
    for locale, caution in (("en", "Caution: δ = "), ("ru", "Внимание: δ = "), ("zh", "注意：δ = ")):
        scene.write_text(re.sub(r'(?m)^locale\s*=.*$', f'locale = "{locale}"', text), encoding="utf-8")
        out = tmp_path / locale
        assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
        note = (out / "note.md").read_text(encoding="utf-8")
        assert (caution in note) is warned, locale
    capsys.readouterr()
