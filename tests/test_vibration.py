"""Vibration from rotating unbalance against closed-form limits, the integrated ODE and published examples.

The steady amplitude and phase of M·x'' + c·x' + k·x = m·e·ω²·sin ωt are
checked against scipy.integrate.solve_ivp run from rest until the free
motion has died out (e^−40), the steady cycle fitted by least squares; the
force passed to the base and the motion of a machine on a moving base the
same way.  The limits r → 0, r = 1, r → ∞ are checked against their closed
forms; the shaft stiffness against the unit-load (Maxwell–Mohr) integral by
scipy.integrate.quad; the isolation design against scipy.optimize.brentq;
the damping from a resonance amplitude against Thomson's Example 3.2-1 and
the peak found by scipy.optimize.minimize_scalar.  Sources in
docs/sources/vibration.md.
"""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad, solve_ivp, trapezoid
from scipy.optimize import brentq, minimize_scalar

from graphplan.errors import SceneError
from graphplan.locale import strings
from graphplan.reader import Table
from graphplan.report.vibration_plots import magnification_figure, transmissibility_figure, words_for
from graphplan.vibration import (
    RPM,
    VibrationSpec,
    circular_second_moment,
    critical_speed,
    damping_from_phase,
    damping_from_resonance,
    damping_ratio,
    displacement_transmissibility,
    displacement_transmissibility_phase,
    force_magnification,
    isolation_frequency_ratio,
    isolation_stiffness,
    natural_frequency,
    phase,
    read_vibration,
    series_mount_stiffness,
    shaft_stiffness,
    steady_state,
    transmissibility,
    unbalance_magnification,
    vibration_results,
)

ratios = st.floats(0.0, 20.0)
dampings = st.floats(0.0, 2.0)


# --- the integrated equation of motion ------------------------------------------------------------


def fitted_cycles(rhs, omega, settle, *outputs):
    """Integrate ``rhs`` from rest for ``settle`` s plus four periods; fit each ``output(t, y)`` as A·sin ωt + B·cos ωt.

    Returns (amplitude, lag) of each output = amplitude·sin(ωt − lag), the lag in (−π, π].
    """
    period = 2 * math.pi / omega
    t_end = settle + 4 * period
    times = np.linspace(settle, t_end, 801)
    solution = solve_ivp(rhs, (0.0, t_end), [0.0, 0.0], method="DOP853", t_eval=times, rtol=1e-11, atol=1e-14)
    assert solution.success
    basis = np.column_stack([np.sin(omega * times), np.cos(omega * times)])
    fits = []
    for output in outputs:
        (a, b), *_ = np.linalg.lstsq(basis, output(solution.t, solution.y), rcond=None)
        fits.append((math.hypot(a, b), math.atan2(-b, a)))
    return fits


MACHINE = {"M": 10.0, "k": 1000.0, "me": 0.02}   # ωn = 10 rad/s


@pytest.mark.parametrize("r", [0.3, 0.9, 1.0, 1.7, 3.0])
@pytest.mark.parametrize("zeta", [0.05, 0.3])
def test_amplitude_phase_and_transmitted_force_agree_with_the_integrated_motion(r, zeta):
    mass, stiffness, unbalance = MACHINE["M"], MACHINE["k"], MACHINE["me"]
    omega_n = math.sqrt(stiffness / mass)
    c = 2 * zeta * math.sqrt(stiffness * mass)
    omega = r * omega_n
    force = unbalance * omega ** 2

    def rhs(t, y):
        return [y[1], (force * math.sin(omega * t) - c * y[1] - stiffness * y[0]) / mass]

    (amplitude, lag), (transmitted, _) = fitted_cycles(rhs, omega, 40 / (zeta * omega_n), lambda t, y: y[0],
                                                       lambda t, y: stiffness * y[0] + c * y[1])
    spec = VibrationSpec(mass=mass, unbalance=unbalance, stiffness=stiffness, damping_ratio=zeta, omega=omega)
    response = steady_state(spec)
    assert response.amplitude == pytest.approx(amplitude, rel=1e-7)
    assert response.phase == pytest.approx(lag % (2 * math.pi), abs=1e-7)
    assert response.transmitted_force == pytest.approx(transmitted, rel=1e-7)


@pytest.mark.parametrize("r", [0.5, 1.0, 2.5])
def test_a_machine_on_a_moving_base_follows_the_displacement_transmissibility(r):
    mass, stiffness, zeta, lift = 2.0, 800.0, 0.15, 0.003
    omega_n = math.sqrt(stiffness / mass)
    c = 2 * zeta * math.sqrt(stiffness * mass)
    omega = r * omega_n

    def rhs(t, y):
        base, base_velocity = lift * math.sin(omega * t), lift * omega * math.cos(omega * t)
        return [y[1], (-c * (y[1] - base_velocity) - stiffness * (y[0] - base)) / mass]

    [(amplitude, lag)] = fitted_cycles(rhs, omega, 40 / (zeta * omega_n), lambda t, y: y[0])
    assert displacement_transmissibility(r, zeta) * lift == pytest.approx(amplitude, rel=1e-7)
    assert displacement_transmissibility_phase(r, zeta) == pytest.approx(lag % (2 * math.pi), abs=1e-7)


@pytest.mark.parametrize("r", [0.5, 1.0, 2.5])
def test_an_unbalance_on_a_moving_base_moves_as_the_two_added_by_the_integrated_motion(r):
    """Unbalance and base motion were worked out as two problems, the force to the base as if it stood still; the
    tester's ODE gave 0.000702 m for both together (r = 2.5)."""
    mass, stiffness, zeta, unbalance, lift = 40.0, 160000.0, 0.1, 0.01, 0.002
    omega_n = math.sqrt(stiffness / mass)
    c = 2 * zeta * math.sqrt(stiffness * mass)
    omega = r * omega_n

    def base(t):
        return lift * math.sin(omega * t), lift * omega * math.cos(omega * t)

    def rhs(t, y):
        position, velocity = base(t)
        return [y[1], (unbalance * omega ** 2 * math.sin(omega * t) - c * (y[1] - velocity)
                       - stiffness * (y[0] - position)) / mass]

    (amplitude, lag), (relative, _), (force, _) = fitted_cycles(
        rhs, omega, 40 / (zeta * omega_n), lambda t, y: y[0], lambda t, y: y[0] - lift * np.sin(omega * t),
        lambda t, y: stiffness * (y[0] - lift * np.sin(omega * t)) + c * (y[1] - lift * omega * np.cos(omega * t)))
    spec = VibrationSpec(mass=mass, unbalance=unbalance, stiffness=stiffness, damping_ratio=zeta, omega=omega,
                         base_amplitude=lift)
    combined = steady_state(spec).combined
    assert combined.amplitude == pytest.approx(amplitude, rel=1e-7)
    assert combined.phase == pytest.approx(lag % (2 * math.pi), abs=1e-7)
    assert combined.relative == pytest.approx(relative, rel=1e-7)
    assert combined.transmitted_force == pytest.approx(force, rel=1e-7)
    document = vibration_results(spec)["combined"]
    assert document["amplitude"] == pytest.approx(amplitude, rel=1e-7)
    assert document["transmitted_force"] == pytest.approx(force, rel=1e-7)
    if r == 2.5:
        assert amplitude == pytest.approx(0.000702, abs=5e-7)


def test_a_base_moving_alone_gives_no_lag_for_the_unbalance_it_has_not():
    """results.json gave phase_deg = 164.9° beside an amplitude of 0: the contract's keys stay, the lag is null."""
    spec = VibrationSpec(mass=40.0, unbalance=0.0, stiffness=160000.0, damping_ratio=0.15, omega=107.5,
                         base_amplitude=0.002)
    document = vibration_results(spec)
    assert {"amplitude", "phase_deg", "transmissibility"} <= document.keys()
    assert document["amplitude"] == 0 and document["phase_deg"] is None and document["transmitted_force"] == 0
    assert "combined" not in document and document["base_excitation"]["phase_deg"] > 0


# --- closed-form limits -----------------------------------------------------------------------------------


@pytest.mark.parametrize("zeta", [0.0, 0.05, 0.2, 0.7, 1.5])
def test_far_below_resonance_the_machine_barely_moves_and_passes_the_whole_force(zeta):
    r = 1e-4
    assert unbalance_magnification(r, zeta) == pytest.approx(r * r, rel=1e-6)
    assert transmissibility(r, zeta) == pytest.approx(1.0, abs=1e-6)
    assert phase(r, zeta) == pytest.approx(2 * zeta * r, abs=1e-10)
    assert unbalance_magnification(0.0, zeta) == 0.0 and transmissibility(0.0, zeta) == 1.0


@pytest.mark.parametrize("zeta", [0.01, 0.1, 0.5, 1.0])
def test_at_resonance_the_amplitude_is_one_over_two_zeta_and_lags_a_quarter_turn(zeta):
    assert unbalance_magnification(1.0, zeta) == pytest.approx(1 / (2 * zeta), rel=1e-15)
    assert force_magnification(1.0, zeta) == pytest.approx(1 / (2 * zeta), rel=1e-15)
    assert phase(1.0, zeta) == pytest.approx(math.pi / 2, abs=1e-15)
    assert transmissibility(1.0, zeta) == pytest.approx(math.sqrt(1 + 4 * zeta ** 2) / (2 * zeta), rel=1e-15)


@pytest.mark.parametrize("zeta", [0.0, 0.1, 0.5])
def test_far_above_resonance_the_machine_turns_about_the_common_centre(zeta):
    r = 1e4
    assert unbalance_magnification(r, zeta) == pytest.approx(1.0, rel=1e-6)
    assert phase(r, zeta) == pytest.approx(math.pi, abs=1e-3)
    # TR → 2ζ/r with damping, 1/r² without.
    assert transmissibility(r, zeta) == pytest.approx(2 * zeta / r if zeta else 1 / r ** 2, rel=1e-3)


def test_undamped_resonance_is_unbounded():
    assert unbalance_magnification(1.0, 0.0) == math.inf
    assert transmissibility(1.0, 0.0) == math.inf
    with pytest.raises(ValueError, match="no bound"):
        VibrationSpec(mass=1.0, unbalance=0.01, stiffness=100.0, damping_ratio=0.0, omega=10.0)


@given(dampings)
def test_every_damping_passes_the_whole_force_at_root_two(zeta):
    assert transmissibility(math.sqrt(2), zeta) == pytest.approx(1.0, rel=1e-12)


@given(ratios, dampings)
def test_the_unbalance_response_is_r_squared_times_the_force_response(r, zeta):
    if r == 1 and zeta == 0:
        return
    assert unbalance_magnification(r, zeta) == pytest.approx(r * r * force_magnification(r, zeta), rel=1e-12)
    assert 0 <= phase(r, zeta) <= math.pi


def test_the_functions_broadcast_over_arrays():
    r = np.linspace(0, 3, 7)
    zeta = np.array([[0.1], [0.2]])
    values = transmissibility(r, zeta)
    assert values.shape == (2, 7)
    assert values[1, 3] == transmissibility(r[3], 0.2)
    assert isinstance(unbalance_magnification(0.5, 0.1), float)
    with pytest.raises(ValueError, match="zeta: must be >= 0"):
        phase(1.0, -0.1)


# --- shafts and critical speeds ---------------------------------------------------------------------------


def unit_load_stiffness(length, a, support, ei):
    """1/δ with δ = ∫ M·m/EI dx for a unit load at the disc (Maxwell–Mohr), integrated by quad."""
    if support == "cantilever":
        deflection, _ = quad(lambda x: (a - x) ** 2, 0, a)
    else:
        b = length - a

        def moment(x):
            return b * x / length if x <= a else a * (length - x) / length

        deflection, _ = quad(lambda x: moment(x) ** 2, 0, length, points=[a])
    return ei / deflection


@pytest.mark.parametrize(("support", "a"), [("simply_supported", 0.5), ("simply_supported", 0.2),
                                             ("simply_supported", 0.93), ("cantilever", 1.0), ("cantilever", 0.4)])
def test_shaft_stiffness_agrees_with_the_unit_load_integral(support, a):
    modulus, second, length = 2.1e11, 3.0e-8, 1.0
    expected = unit_load_stiffness(length, a, support, modulus * second)
    assert shaft_stiffness(modulus, second, length, a, support) == pytest.approx(expected, rel=1e-10)


def test_a_central_disc_gives_48_ei_over_l_cubed():
    assert shaft_stiffness(2e11, 1e-8, 0.8) == pytest.approx(48 * 2e11 * 1e-8 / 0.8 ** 3, rel=1e-15)
    assert shaft_stiffness(2e11, 1e-8, 0.8, support="cantilever") == pytest.approx(3 * 2e11 * 1e-8 / 0.8 ** 3)


def test_critical_speed_of_a_rotor_disc_in_the_middle_of_a_shaft():
    # GATE (Mechanical) question, as solved at studyadda.com (question bank, vibration analysis):
    # a 10 kg disc in the middle of a massless steel shaft, d = 30 mm, 500 mm between simple
    # bearings, E = 2.1e11 Pa.  Solution: k = 48EI/l³ = 3 206 309 N/m, fc = 90 Hz (answer B).
    k = shaft_stiffness(2.1e11, circular_second_moment(0.030), 0.5)
    assert k == pytest.approx(3_206_309, abs=1)
    assert critical_speed(k, 10.0) / (2 * math.pi) == pytest.approx(90, abs=0.5)


def test_bad_shafts_say_what_is_wrong():
    with pytest.raises(ValueError, match="between the bearings"):
        shaft_stiffness(2e11, 1e-8, 1.0, 1.0)
    with pytest.raises(ValueError, match="on the shaft"):
        shaft_stiffness(2e11, 1e-8, 1.0, 1.5, "cantilever")
    with pytest.raises(ValueError, match="support: must be one of"):
        shaft_stiffness(2e11, 1e-8, 1.0, support="fixed")  # type: ignore[arg-type]


# --- design and identification ----------------------------------------------------------------------------


@pytest.mark.parametrize("wanted", [0.05, 0.2, 0.5, 0.9])
@pytest.mark.parametrize("zeta", [0.0, 0.05, 0.2, 0.6])
def test_the_isolating_ratio_agrees_with_brent(wanted, zeta):
    expected = brentq(lambda r: transmissibility(r, zeta) - wanted, math.sqrt(2), 1e4, xtol=1e-14, rtol=1e-14)
    assert isolation_frequency_ratio(wanted, zeta) == pytest.approx(expected, rel=1e-11)


@settings(max_examples=80)
@given(st.floats(1e-3, 0.999), st.floats(0.0, 1.0))
def test_the_isolating_ratio_gives_the_wanted_transmissibility(wanted, zeta):
    r = isolation_frequency_ratio(wanted, zeta)
    assert r > math.sqrt(2)
    assert transmissibility(r, zeta) == pytest.approx(wanted, rel=1e-9)


def test_undamped_isolation_by_hand_and_the_stiffness_that_gives_it():
    # Without damping TR = 1/(r² − 1): TR = 0.1 needs r² = 11.
    assert isolation_frequency_ratio(0.1, 0.0) == pytest.approx(math.sqrt(11), rel=1e-14)
    k = isolation_stiffness(100.0, 100.0, 0.1, 0.0)
    assert k == pytest.approx(100.0 * 100.0 ** 2 / 11, rel=1e-14)
    with pytest.raises(ValueError, match=r"wanted: a transmissibility that isolates must be in \(0, 1\)"):
        isolation_frequency_ratio(1.2, 0.1)


def test_damping_from_resonance_and_far_above_thomson_example_3_2_1():
    # W.T. Thomson, "Theory of Vibration with Applications", 4th ed. (Prentice Hall 1993; Taylor &
    # Francis reprint 2010), Sec. 3.2, Example 3.2-1, p. 57: a counterrotating eccentric-weight
    # exciter gives 0.60 cm at resonance and approaches 0.08 cm far above it (the statement and the
    # start of the solution: digilib.universitaspertamina.ac.id/ebook/Theory of Vibration with
    # Applications/files/basic-html/page70.html).  Eq. (3.2-4) at resonance, (m·e/M)/(2ζ) = 0.60 cm,
    # and far above it, m·e/M = 0.08 cm, give ζ = 0.08/(2 × 0.60) = 0.0667.
    zeta = damping_from_resonance(0.60, 0.08)
    assert zeta == pytest.approx(0.0667, abs=5e-5)
    # The machine so damped gives the two readings back: m·e/M = 0.08 cm.
    assert 0.08 * unbalance_magnification(1.0, zeta) == pytest.approx(0.60, rel=1e-12)
    assert 0.08 * unbalance_magnification(1e5, zeta) == pytest.approx(0.08, rel=1e-9)


@pytest.mark.parametrize("zeta", [0.02, 0.0667, 0.2, 0.5])
def test_damping_from_the_peak_amplitude(zeta):
    peak = minimize_scalar(lambda r: -unbalance_magnification(r, zeta), bounds=(1.0, 3.0), method="bounded",
                           options={"xatol": 1e-12})
    assert damping_from_resonance(-peak.fun, 1.0, at="peak") == pytest.approx(zeta, rel=1e-7)


def test_damping_ratio_and_natural_frequency():
    assert damping_ratio(20.0, 1000.0, 10.0) == pytest.approx(0.1)
    assert natural_frequency(1000.0, 10.0) == pytest.approx(10.0)
    with pytest.raises(ValueError, match="mass: must be > 0"):
        natural_frequency(1000.0, 0.0)


# --- the scene table and the results --------------------------------------------------------------------


def read(data):
    return read_vibration(Table(data, "vibration"))


def test_a_table_with_the_parts_of_the_unbalance_rpm_and_a_damping_coefficient():
    spec = read({"mass": 100.0, "unbalanced_mass": 2.0, "eccentricity": 0.01, "stiffness": 1.0e5,
                 "damping": 400.0, "rpm": 600.0, "transmissibility": 0.1})
    assert spec.unbalance == pytest.approx(0.02) and spec.omega == pytest.approx(600 * RPM)
    assert spec.damping_ratio == pytest.approx(400 / (2 * math.sqrt(1e5 * 100)))
    assert spec.transmissibility == 0.1


def test_a_table_with_a_shaft_for_the_stiffness():
    spec = read({"mass": 10.0, "unbalance": 1e-4, "omega": 300.0, "damping_ratio": 0.02,
                 "shaft": {"modulus": 2.1e11, "diameter": 0.03, "length": 0.5}})
    assert spec.stiffness == pytest.approx(3_206_309, abs=1)
    overhung = read({"mass": 10.0, "unbalance": 1e-4, "omega": 300.0,
                     "shaft": {"modulus": 2e11, "second_moment": 1e-8, "length": 0.5, "position": 0.3,
                               "support": "cantilever"}})
    assert overhung.stiffness == pytest.approx(3 * 2e11 * 1e-8 / 0.3 ** 3)
    assert overhung.damping_ratio == 0.0


@pytest.mark.parametrize(("data", "message"), [
    ({"unbalance": 0.01, "stiffness": 1e4, "omega": 10}, "vibration.mass: is required but missing"),
    ({"mass": 1, "stiffness": 1e4, "omega": 10}, r"vibration.unbalance: is required \(m·e, kg·m\)"),
    ({"mass": 1, "unbalance": 0.01, "unbalanced_mass": 0.1, "stiffness": 1e4, "omega": 10},
     "vibration.unbalance: give either unbalance"),
    ({"mass": 1, "unbalanced_mass": 2, "eccentricity": 0.01, "stiffness": 1e4, "omega": 10},
     r"vibration.unbalanced_mass: must not exceed mass \(1 kg\)"),
    ({"mass": 1, "unbalanced_mass": 0.2, "stiffness": 1e4, "omega": 10},
     "vibration.eccentricity: is required with unbalanced_mass"),
    ({"mass": 1, "unbalance": 0.01, "omega": 10}, r"vibration.stiffness: is required \(or shaft\)"),
    ({"mass": 1, "unbalance": 0.01, "stiffness": 1e4, "shaft": {}, "omega": 10},
     "vibration.shaft: give either stiffness or shaft, not both"),
    ({"mass": 1, "unbalance": 0.01, "stiffness": 1e4}, r"vibration.omega: is required but missing: give omega \(rad/s\) or rpm \(rev/min\)"),
    ({"mass": 1, "unbalance": 0.01, "stiffness": 1e4, "omega": 10, "rpm": 100},
     "vibration.rpm: give either omega or rpm"),
    ({"mass": 1, "unbalance": 0.01, "stiffness": 1e4, "omega": -10}, r"vibration.omega: must be > 0 \(got -10\)"),
    ({"mass": 1, "unbalance": 0.01, "stiffness": 1e4, "omega": 10, "damping_ratio": 0.1, "damping": 3},
     "vibration.damping: give either damping_ratio or damping"),
    ({"mass": 1, "unbalance": 0.01, "stiffness": 1e4, "omega": 10, "transmissibility": 1.5},
     "vibration.transmissibility: must be below 1"),
    ({"mass": 1, "unbalance": 0.01, "stiffness": 100, "omega": 10},
     "vibration.omega: is the natural frequency and there is no damping"),
    ({"mass": 1, "unbalance": 0.01, "omega": 10, "shaft": {"modulus": 2e11, "diameter": 0.01, "length": 1,
                                                           "position": 1.0}},
     "vibration.shaft.position: the disc must lie between the bearings"),
    ({"mass": 1, "unbalance": 0.01, "omega": 10, "shaft": {"modulus": 2e11, "diameter": 0.01, "length": 1,
                                                           "support": "clamped"}},
     "vibration.shaft.support: must be one of simply_supported, cantilever"),
    ({"mass": 1, "unbalance": 0.01, "omega": 10, "shaft": {"modulus": 2e11, "diameter": 0.01,
                                                           "second_moment": 1e-9, "length": 1}},
     "vibration.shaft.diameter: give either second_moment or diameter"),
    # A typo in the shaft was told as "second_moment: is required but missing".
    ({"mass": 1, "unbalance": 0.01, "omega": 10, "shaft": {"modulus": 2e11, "diamter": 0.03, "length": 1}},
     r"^vibration.shaft.diamter: unknown key; did you mean 'diameter'\?$"),
    ({"mass": 1, "unbalance": 0.01, "omega": 10, "shaft": {"modulus": 2e11, "second_momnet": 1e-8, "length": 1}},
     r"^vibration.shaft.second_momnet: unknown key; did you mean 'second_moment'\?$"),
    ({"mass": 1, "unbalance": 0.01, "omega": 10, "shaft": {"modulus": 2e11, "length": 1}},
     r"^vibration.shaft.diameter: is required .*: give diameter or second_moment$"),
    ({"mass": 1, "unbalance": 0.01, "stiffness": 1e4, "omega": 10, "dampingratio": 0.1},
     "vibration.dampingratio: unknown key; did you mean 'damping_ratio'"),
])
def test_a_bad_table_names_the_key(data, message):
    with pytest.raises(SceneError, match=message):
        read(data)


_MACHINE = {"mass": 100.0, "unbalance": 0.02, "stiffness": 1e5, "rpm": 600.0}


@pytest.mark.parametrize(("speed", "bounds", "slip"), [
    ({"omega": 1e12}, r"0\.1047–104720 rad/s \(1–1 000 000 rpm\)", True),
    ({"omega": 1e-12}, r"0\.1047–104720 rad/s \(1–1 000 000 rpm\)", True),
    ({"rpm": 1e7}, "1–1 000 000 rpm", False),
    ({"rpm": 0.5}, "1–1 000 000 rpm", False),
])
def test_a_speed_no_machine_s_rotor_turns_at_is_refused_with_the_force_it_would_give(speed, bounds, slip):
    """omega = 1e12 ran, without a word, to an exciting force of 10²² N and mounts of 10²⁵ N/m."""
    data = {key: value for key, value in _MACHINE.items() if key != "rpm"} | speed
    (key, value), = speed.items()
    omega = value if key == "omega" else value * math.pi / 30.0
    with pytest.raises(SceneError) as refused:
        read(data)
    message = str(refused.value)
    assert re.match(rf"^vibration\.{key}: must be within {bounds}, as a machine's rotor turns", message), message
    force = float(re.search(r"the exciting force m·e·ω² would be (\S+) N", message)[1])
    assert force == pytest.approx(0.02 * omega ** 2, rel=5e-3)
    assert message.endswith("a slip of the exponent?") is slip


@pytest.mark.parametrize(("modulus", "hint"), [(2.1e5, "; MPa typed for Pa? 210000 MPa is modulus = 2.1e+11"),
                                               (210.0, "; GPa typed for Pa? 210 GPa is modulus = 2.1e+11"),
                                               (5e12, "")])
def test_a_shaft_modulus_no_shaft_is_made_of_is_refused_with_the_unit_it_was_typed_in(modulus, hint):
    """Steel's 2.1e5 typed in MPa made a 50 mm shaft k = 3 N/m, its critical speed 1.7 rpm, without a word."""
    data = {key: value for key, value in _MACHINE.items() if key != "stiffness"}
    with pytest.raises(SceneError) as refused:
        read(data | {"shaft": {"modulus": modulus, "diameter": 0.05, "length": 1.0}})
    assert str(refused.value) == ("vibration.shaft.modulus: must be within 1e+09–1.2e+12 Pa, as shafts are made "
                                  f"(steel's 2.1e11, a polymer's some 3e9): E is in Pa (got {modulus!r}){hint}")
    # A nylon shaft's 3e9 and a hard metal's 6.5e11 are taken.
    for taken in (3e9, 6.5e11):
        assert read(data | {"shaft": {"modulus": taken, "diameter": 0.05, "length": 1.0}}).shaft.modulus == taken


@pytest.mark.parametrize("rpm", [1.0, 1e6])
def test_the_slowest_and_the_fastest_rotor_s_speeds_are_taken(rpm):
    assert read(_MACHINE | {"rpm": rpm}).omega == pytest.approx(rpm * math.pi / 30.0)


@pytest.mark.parametrize(("replaced", "given", "message"), [
    # "stiffness: is required (or shaft)" of a table that gave it, under the textbook's k.
    ("stiffness", {"k": 1e5}, r"^vibration.k: unknown key; .* stiffness: write stiffness = 100000.0$"),
    ("unbalance", {"me": 0.02}, r"^vibration.me: unknown key; .* unbalance: write unbalance = 0.02$"),
    (None, {"zeta": 0.1}, r"^vibration.zeta: unknown key; .* damping_ratio: write damping_ratio = 0.1$"),
    (None, {"ζ": 0.1}, r"^vibration.ζ: unknown key; .* damping_ratio: write damping_ratio = 0.1$"),
    (None, {"c": 400.0}, r"^vibration.c: unknown key; .* damping: write damping = 400.0$"),
    (None, {"TR": 0.2}, r"^vibration.TR: unknown key; .* transmissibility: write transmissibility = 0.2$"),
    (None, {"Y": 0.001}, r"^vibration.Y: unknown key; .* base_amplitude: write base_amplitude = 0.001$"),
    ("stiffness", {"shaft": {"E": 2.1e11, "d": 0.03, "length": 0.5}},
     r"^vibration.shaft.E: unknown key; .* modulus: write modulus = 210000000000.0$"),
    ("stiffness", {"shaft": {"modulus": 2.1e11, "d": 0.03, "length": 0.5}},
     r"^vibration.shaft.d: unknown key; .* diameter: write diameter = 0.03$"),
    ("stiffness", {"shaft": {"modulus": 2.1e11, "I": 4e-8, "length": 0.5}},
     r"^vibration.shaft.I: unknown key; .* second_moment: write second_moment = 4e-08$"),
    ("stiffness", {"shaft": {"modulus": 2.1e11, "diameter": 0.03, "L": 0.5}},
     r"^vibration.shaft.L: unknown key; .* length: write length = 0.5$"),
    ("stiffness", {"shaft": {"modulus": 2.1e11, "diameter": 0.03, "length": 0.5, "a": 0.2}},
     r"^vibration.shaft.a: unknown key; .* position: write position = 0.2$"),
])
def test_a_machine_given_by_the_textbooks_symbols_is_told_the_key_to_write(replaced, given, message):
    data = {key: value for key, value in _MACHINE.items() if key != replaced} | given
    with pytest.raises(SceneError, match=message):
        read(data)


def test_results_carry_the_contract_keys():
    spec = VibrationSpec(mass=100.0, unbalance=0.02, stiffness=1.0e5, damping_ratio=0.1, omega=60.0,
                         transmissibility=0.2)
    document = vibration_results(spec)
    r = 60.0 / math.sqrt(1e3)
    assert document["frequency_ratio"] == pytest.approx(r)
    assert document["amplitude"] == pytest.approx(0.02 / 100 * unbalance_magnification(r, 0.1))
    assert document["phase_deg"] == pytest.approx(math.degrees(phase(r, 0.1)))
    assert document["transmissibility"] == pytest.approx(transmissibility(r, 0.1))
    assert document["transmitted_force"] == pytest.approx(0.02 * 60.0 ** 2 * document["transmissibility"])
    assert document["critical_speed_rpm"] == pytest.approx(math.sqrt(1e3) * 60 / (2 * math.pi))
    isolation = document["isolation"]
    assert transmissibility(isolation["frequency_ratio"], 0.1) == pytest.approx(0.2)
    assert isolation["stiffness"] == pytest.approx(100.0 * (60.0 / isolation["frequency_ratio"]) ** 2)
    assert "isolation" not in vibration_results(VibrationSpec(1.0, 0.01, 100.0, 0.1, 5.0))


# --- the figures ---------------------------------------------------------------------------------------------


def test_the_figures_are_svg_with_a_curve_for_each_damping_and_the_same_bytes_every_time(tmp_path):
    zetas = (0.1, 0.25, 0.5)
    first = magnification_figure(tmp_path / "a.svg", zetas, operating=(1.3, 0.1))
    second = magnification_figure(tmp_path / "b.svg", zetas, operating=(1.3, 0.1))
    text = first.read_text(encoding="utf-8")
    assert text.startswith("<?xml") and "<svg" in text
    assert first.read_bytes() == second.read_bytes()
    for zeta in zetas:  # the working point's own ζ = 0.1 named as the machine's
        assert f"<!-- ζ = {zeta:g} -->" in text or f"<!-- ζ = {zeta:g}: this machine -->" in text
    assert "<!-- working point -->" in text
    other = transmissibility_figure(tmp_path / "nested" / "t.svg", zetas).read_text(encoding="utf-8")
    assert "<!-- isolation: r &gt; √2 -->" in other or "<!-- isolation: r > √2 -->" in other
    with pytest.raises(ValueError, match=r"zetas\[1\]: a damping ratio must be >= 0"):
        transmissibility_figure(tmp_path / "x.svg", (0.1, -0.2))


@pytest.mark.parametrize("figure", [magnification_figure, transmissibility_figure])
@pytest.mark.parametrize("working", [(1.3, 0.1), (3.14, 0.15), (6.02, 0.05), (20.0, 0.01)])
def test_the_working_point_stands_inside_the_plot(figure, working):
    # The axes ran to r = 3 and 5 whatever the machine: a fast one's point fell off the plot its legend named it in.
    import io
    import re

    stream = io.StringIO()
    figure(stream, operating=working)
    text = stream.getvalue()
    corners = [float(v) for v in re.search(r'<g id="patch_2">\s*<path d="M ([\d.]+) ([\d.]+)\s*L ([\d.]+) ([\d.]+)',
                                             text).groups()]
    left, bottom, right = corners[0], corners[1], corners[2]
    top = float(re.search(r'<g id="patch_2">\s*<path d="M [\d.]+ [\d.]+\s*L [\d.]+ [\d.]+\s*L [\d.]+ ([\d.]+)',
                          text).group(1))
    # The point as plotted, before the legend repeats its marker: the first use of the marker's colour.
    x, y = (float(v) for v in re.search(r'<use xlink:href="#\w+" x="(-?[\d.]+)" y="(-?[\d.]+)" style="fill: #a83a1f',
                                        text).groups())
    assert left < x < right and top < y < bottom


def test_nothing_imports_matplotlib_until_a_figure_is_drawn():
    code = ("import sys, graphplan.vibration, graphplan.report.vibration_plots, graphplan.rotor_balancing, "
            "graphplan.render.balancing; print('matplotlib' in sys.modules)")
    output = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert output.strip() == "False"


@given(r=st.floats(min_value=0.05, max_value=20.0).filter(lambda r: abs(r - 1.0) > 1e-3),
       zeta=st.floats(min_value=1e-3, max_value=2.0))
def test_damping_from_the_lag_undoes_the_lag_of_the_damping(r, zeta):
    assert damping_from_phase(r, phase(r, zeta)) == pytest.approx(zeta, rel=1e-7)


def test_damping_from_a_lag_measured_on_the_integrated_motion():
    """A machine integrated to its steady state: the lag of x behind the force read off the motion gives ζ."""
    omega_n, zeta, r = 10.0, 0.15, 1.6
    omega = r * omega_n
    motion = solve_ivp(lambda t, y: [y[1], math.sin(omega * t) - 2 * zeta * omega_n * y[1] - omega_n ** 2 * y[0]],
                       (0.0, 40.0), [0.0, 0.0], rtol=1e-10, atol=1e-12, dense_output=True)
    # Over a whole number of late periods x = X·sin(ωt − φ): its sine and cosine parts give the lag.
    t = np.linspace(40.0 - 10 * 2 * math.pi / omega, 40.0, 20001)
    x = motion.sol(t)[0]
    in_phase, quadrature = trapezoid(x * np.sin(omega * t), t), trapezoid(x * np.cos(omega * t), t)
    lag = math.atan2(-quadrature, in_phase)
    assert damping_from_phase(r, lag) == pytest.approx(zeta, rel=1e-4)


@pytest.mark.parametrize("r, lag, message", [(1.0, math.pi / 2, "at resonance"), (0.5, 2.0, "below resonance"),
                                             (2.0, 0.3, "below resonance"), (2.0, math.pi, "less than π"),
                                             (0.5, 0.0, "lag")])
def test_a_lag_that_says_nothing_of_the_damping_is_refused(r, lag, message):
    with pytest.raises(ValueError, match=message):
        damping_from_phase(r, lag)


def test_next_to_no_damping_at_resonance_is_an_infinite_response_without_a_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert unbalance_magnification(1.0, 1e-310) == math.inf
        assert force_magnification(1.0, 1e-310) == math.inf


def test_the_note_says_how_the_scene_gave_its_stiffness_and_damping(tmp_path):
    # c = 3000 N·s/m on 400 kN/m under 250 kg is ζ = 0.15; the isolating mounts are designed at that ζ, which the
    # same dampers on them would not give.  A shaft's stiffness is no mount's: the bearings carry the force.
    from graphplan.cli import main

    mounts = tmp_path / "mounts.toml"
    mounts.write_text('[scene]\ntitle = "Compressor"\nlocale = "en"\n[vibration]\nmass = 250.0\nunbalance = 0.1\n'
                      'stiffness = 400000.0\ndamping = 3000.0\nrpm = 1200.0\ntransmissibility = 0.1\n', encoding="utf-8")
    assert main(["run", str(mounts), "--out", str(tmp_path / "a")]) == 0
    note = (tmp_path / "a" / "note.md").read_text(encoding="utf-8")
    zeta = 3000.0 / (2.0 * math.sqrt(400000.0 * 250.0))
    assert f"ζ = c/(2·√(k·M)) = 3000/(2·√(400000·250)) = {zeta:.5g}" in note
    omega = 1200.0 * math.pi / 30.0
    ratio = isolation_frequency_ratio(0.1, zeta)
    designed = 250.0 * (omega / ratio) ** 2
    assert f"c = 2ζ·√(k·M) = {2.0 * zeta * math.sqrt(designed * 250.0):.5g} N·s/m" in note
    assert f"would give ζ = {zeta * math.sqrt(400000.0 / designed):.5g}" in note
    shaft = tmp_path / "shaft.toml"
    shaft.write_text('[scene]\ntitle = "Rotor"\nlocale = "en"\n[vibration]\nmass = 50.0\nunbalance = 0.005\n'
                     'damping_ratio = 0.02\nrpm = 3000.0\nshaft = { modulus = 2.1e11, diameter = 0.05, length = 0.8 }\n',
                     encoding="utf-8")
    assert main(["run", str(shaft), "--out", str(tmp_path / "b")]) == 0
    note = (tmp_path / "b" / "note.md").read_text(encoding="utf-8")
    assert "turns on its shaft" in note and "the bearings pass" in note and "mounts" not in note


# --- resonance without damping, and nothing to excite the machine -------------------------------------------


def _run(tmp_path, body, capsys):
    from graphplan.cli import main

    scene = tmp_path / "machine.toml"
    scene.write_text('[scene]\ntitle = "Machine"\n[vibration]\n' + body, encoding="utf-8")
    code = main(["run", str(scene), "--out", str(tmp_path / "out")])
    return code, capsys.readouterr()


def test_a_damping_too_small_to_matter_near_resonance_is_warned_of_as_none_is(tmp_path, capsys):
    """ζ = 1e-9 at r = 0.99999 left a 20 N unbalance force shaking the machine 8.9 m with no word, where ζ = 0 is
    warned of (a teacher's variant); a real damping near resonance, M·X/(m·e) below 10, is not."""
    natural = math.sqrt(1e5 / 100.0)
    omega = 0.99999 * natural
    r, zeta = omega / natural, 1e-9
    magnification = r * r / math.sqrt((1 - r * r) ** 2 + (2 * zeta * r) ** 2)
    code, told = _run(tmp_path, f"mass = 100.0\nunbalance = 0.02\nstiffness = 1e5\nomega = {omega!r}\n"
                                f"damping_ratio = {zeta}\n", capsys)
    assert code == 0
    assert f"with little damping (ζ = 0.000000001): the amplitude X = {0.02 / 100.0 * magnification:.5g} m is " \
           f"{magnification:.5g} times m·e/M" in told.out
    from graphplan.cli import main

    assert main(["check", str(tmp_path / "machine.toml")]) == 0   # check warns as run does
    assert "warning: vibration: ω within" in capsys.readouterr().out
    (tmp_path / "damped").mkdir()
    code, told = _run(tmp_path / "damped", f"mass = 100.0\nunbalance = 0.02\nstiffness = 1e5\nomega = {omega!r}\n"
                                          "damping_ratio = 0.2\n", capsys)
    assert code == 0 and "warning" not in told.out


@pytest.mark.parametrize(("given", "zeta"), [({"damping_ratio": 1e-12}, None), ({"damping": 1e-9}, 1e-9 / (2.0 * math.sqrt(1e5 * 100.0)))])
def test_a_damping_the_note_would_write_as_none_is_refused(given, zeta):
    """ζ = 1e-12 near resonance was warned of as "little damping (ζ = 0)"; the note, too, wrote it 0."""
    (key, value), = given.items()
    with pytest.raises(SceneError) as refused:
        read({"mass": 100.0, "unbalance": 0.02, "stiffness": 1e5, "omega": 30.0} | given)
    message = str(refused.value)
    worked = f"it gives ζ = c/(2·√(k·M)) = {zeta:.3g}, which " if zeta else ""
    assert message == (f"vibration.{key}: {worked}must be above 1e-10, the size the note and the drawings write as "
                       "0, or 0 for none (the damping ratio ζ is a share of the critical damping) "
                       f"(got {value!r})"), message
    assert read({"mass": 100.0, "unbalance": 0.02, "stiffness": 1e5, "omega": 30.0, key: 0.0}).damping_ratio == 0


def test_an_undamped_speed_a_rounding_off_resonance_is_refused_as_resonance(tmp_path, capsys):
    # The teacher's ω = 31.6227766017 for √(1e5/100) = 31.62277660168…: X = 1.95e8 m was written without a word.
    natural = math.sqrt(1e5 / 100.0)
    assert 0 < abs(31.6227766017 / natural - 1) < 1e-6
    with pytest.raises(SceneError, match=r"^vibration.omega: is the natural frequency and there is no damping"):
        read({"mass": 100.0, "unbalance": 0.02, "stiffness": 1e5, "omega": 31.6227766017})
    code, told = _run(tmp_path, "mass = 100.0\nunbalance = 0.02\nstiffness = 1e5\nomega = 31.6227766017\n", capsys)
    assert code == 2 and "vibration.omega: is the natural frequency" in told.err and not (tmp_path / "out").exists()
    with pytest.raises(ValueError, match="omega: at resonance without damping"):
        VibrationSpec(mass=100.0, unbalance=0.02, stiffness=1e5, damping_ratio=0.0, omega=31.6227766017)


def test_an_undamped_speed_near_resonance_gives_its_amplitude_and_a_warning(tmp_path, capsys):
    omega, natural = 33.0, math.sqrt(1e5 / 100.0)
    r = omega / natural
    amplitude = 0.02 / 100.0 * r * r / abs(1 - r * r)  # M·X/(m·e) = r²/|1 − r²| without damping
    code, told = _run(tmp_path, f"mass = 100.0\nunbalance = 0.02\nstiffness = 1e5\nomega = {omega}\n", capsys)
    assert code == 0
    assert f"warning: vibration: no damping and ω within {abs(r - 1) * 100:.2g} % of the natural frequency" in told.out
    assert f"X = {amplitude:.5g} m" in told.out
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["vibration"]
    assert document["amplitude"] == pytest.approx(amplitude, rel=1e-11)
    (tmp_path / "far").mkdir()  # r = 1.26: no warning
    code, told = _run(tmp_path / "far", "mass = 100.0\nunbalance = 0.02\nstiffness = 1e5\nomega = 40.0\n", capsys)
    assert code == 0 and "warning" not in told.out
    assert read({"mass": 100.0, "unbalance": 0.02, "stiffness": 1e5, "omega": natural * (1 + 2e-6)}).omega > natural


def test_a_machine_that_nothing_excites_is_refused_naming_the_unbalance(tmp_path, capsys):
    # unbalance = 0 and no base_amplitude: the teacher's scene was run, and a phase of 172° given for no force.
    with pytest.raises(SceneError, match=r"^vibration.unbalance: is 0 and the base does not move"):
        read({"mass": 100.0, "unbalance": 0.0, "stiffness": 1e5, "damping_ratio": 0.1, "rpm": 600.0})
    with pytest.raises(SceneError, match=r"^vibration.eccentricity: is 0 and the base does not move"):
        read({"mass": 100.0, "unbalanced_mass": 1.0, "eccentricity": 0.0, "stiffness": 1e5, "rpm": 600.0})
    code, told = _run(tmp_path, "mass = 100.0\nunbalance = 0.0\nstiffness = 1e5\ndamping_ratio = 0.1\nrpm = 600.0\n",
                      capsys)
    assert code == 2 and told.err.count("\n") == 1 and not (tmp_path / "out").exists()
    assert read({"mass": 100.0, "unbalance": 0.0, "stiffness": 1e5, "rpm": 600.0, "base_amplitude": 0.001}).unbalance == 0


# --- the plots: the machine's own damping, the isolating mounts, a moving base ----------------------------------


@pytest.mark.parametrize("figure", [magnification_figure, transmissibility_figure])
@pytest.mark.parametrize(("zeta", "added"), [(0.12, True), (0.1, False), (0.8, True)])
def test_the_machines_own_damping_is_a_highlighted_curve_through_its_working_point(figure, zeta, added):
    # The ζ curves were a fixed set: ζ = 0.12 or 0.8 left the working point off every drawn curve.
    import io

    stream = io.StringIO()
    figure(stream, operating=(1.3, zeta))
    text = stream.getvalue()
    assert f"<!-- ζ = {zeta:g}: this machine -->" in text and f"<!-- ζ = {zeta:g} -->" not in text
    drawn = sum(f"<!-- ζ = {value:g} -->" in text for value in (0.05, 0.1, 0.15, 0.25, 0.375, 0.5, 1.0))
    assert drawn == 7 - (not added)


def test_next_to_no_damping_is_plotted_as_none_is_with_its_working_point_on_the_top_edge():
    """ζ = 1e-9 ran the ordinate to 5·10⁸ (its peak 1/(2ζ)), every other curve and the working point flat at nought,
    where ζ = 0 is cut at a little above the set's highest peak (ζ = 0.05: 1/(2ζ√(1 − ζ²)))."""
    import io
    import re

    def ticks_and_point(zeta):
        stream = io.StringIO()
        magnification_figure(stream, operating=(0.998426, zeta))
        text = stream.getvalue()
        ticks = [float(tick) for tick in re.findall(r'<g id="ytick_\d+">.*?<!-- (.*?) -->', text, re.DOTALL)]
        return ticks, re.findall(r"<!-- (working point.*?) -->", text)

    r = 0.998426
    working = r * r / math.hypot(1 - r * r, 2e-9 * r)
    ticks, point = ticks_and_point(1e-9)
    assert max(ticks) <= 1.15 / (2 * 0.05 * math.sqrt(1 - 0.05 ** 2)) and min(ticks) == 0
    assert ticks_and_point(0.0) == (ticks, point) == (ticks, [f"working point, off the scale: {working:.3g}"])
    stream = io.StringIO()
    transmissibility_figure(stream, operating=(r, 1e-9))
    tr = math.hypot(1, 2e-9 * r) / math.hypot(1 - r * r, 2e-9 * r)
    assert f"<!-- working point, off the scale: {tr:.3g} -->" in stream.getvalue()


def test_the_isolating_mounts_design_point_is_marked_where_the_wanted_transmissibility_is_met():
    import io

    zeta, wanted = 0.1, 0.2
    # r where TR(r, ζ) = 0.2 above √2, found by Brent's method on the formula itself.
    ratio = brentq(lambda r: math.hypot(1, 2 * zeta * r) / math.hypot(1 - r * r, 2 * zeta * r) - wanted, 1.5, 20.0)
    stream = io.StringIO()
    transmissibility_figure(stream, operating=(1.99, zeta), design=(ratio, wanted))
    assert f"<!-- isolating mounts: TR = 0.2 at r = {ratio:.3g} -->" in stream.getvalue()


def test_a_machine_on_a_moving_base_with_no_unbalance_is_not_plotted_as_a_rotating_unbalance(tmp_path, capsys):
    code, _ = _run(tmp_path, "mass = 20.0\nunbalance = 0.0\nstiffness = 2.0e4\ndamping_ratio = 0.05\nrpm = 1200\n"
                             "base_amplitude = 0.0005\n", capsys)
    assert code == 0
    magnification = (tmp_path / "out" / "vibration_magnification.svg").read_text(encoding="utf-8")
    transmitted = (tmp_path / "out" / "vibration_transmissibility.svg").read_text(encoding="utf-8")
    assert "Rotating unbalance" not in magnification and "<!-- Moving base: the motion relative to the base -->" \
        in magnification and "<!-- relative motion Z/Y -->" in magnification
    assert "Force transmitted" not in transmitted and "<!-- motion transmissibility X/Y -->" in transmitted
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert "Figure 1. Moving base: the motion relative to the base" in note and "Rotating unbalance" not in note


def test_no_operand_of_the_note_runs_to_more_digits_than_are_read(tmp_path):
    """A cantilever rotor at 1500 rpm: no few digits of ω made every equation come out as written, and the note
    printed ω = 157.07963267948966 rad/s four times."""
    import re

    from graphplan.cli import main

    scene = tmp_path / "cantilever.toml"
    scene.write_text('[scene]\ntitle = "V4"\nlocale = "en"\n[vibration]\nmass = 10.0\nunbalance = 0.0005\n'
                     'shaft = { modulus = 2.0e11, second_moment = 4.0e-8, length = 0.5, position = 0.4, '
                     'support = "cantilever" }\nrpm = 1500.0\ntransmissibility = 0.3\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    written = re.findall(r"ω = ([\d.]+) rad/s", note)
    assert written and all(float(value) == pytest.approx(1500 * math.pi / 30, rel=1e-5) for value in written)
    assert max(len(re.sub(r"\D", "", number).strip("0")) for number in re.findall(r"\d+\.\d+", note)) <= 8


def test_isolating_mounts_that_would_sag_more_than_any_spring_are_warned_of(tmp_path, capsys):
    """TR = 0.2 at 60 rpm: r = √(1 + 1/TR) at ζ = 0 makes k = M·(ω/r)², whose sag M·g/k = g·r²/ω² is 1.5 m
    whatever the machine weighs.  The design was given without a word."""
    from graphplan.cli import main

    scene = tmp_path / "slow.toml"
    scene.write_text('[scene]\ntitle = "slow"\n[vibration]\nmass = 100.0\nunbalance = 0.02\nstiffness = 1e5\n'
                     'rpm = 60.0\ntransmissibility = 0.2\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    (line,) = [line for line in capsys.readouterr().out.splitlines() if "would sag" in line]
    omega = 2 * math.pi
    sag = 9.80665 * (1 + 1 / 0.2) / omega ** 2
    assert f"would sag by M·g/k = {sag:.3g} m" in line
    scene.write_text(scene.read_text(encoding="utf-8").replace("rpm = 60.0", "rpm = 1500.0"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "fast")]) == 0
    assert "would sag" not in capsys.readouterr().out


def _ratio_for(wanted, zeta):
    """r > √2 where TR(r, ζ) = wanted, by Brent's method on the formula itself."""
    return brentq(lambda r: math.hypot(1, 2 * zeta * r) / math.hypot(1 - r * r, 2 * zeta * r) - wanted,
                  math.sqrt(2.0) + 1e-12, 1e5)


@pytest.mark.parametrize(("rpm", "zeta", "wanted", "offered"), [
    (900.0, 2.0, 0.3, {"damping", "tr", "speed"}),  # the tester's: r = 12.8 at ζ = 2, 2.08 undamped
    (211.0, 0.2, 0.1, {"tr", "speed"}),  # undamped r² = 11 is out of reach too, r = √2 is not
    (60.0, 0.0, 0.2, {"speed"}),  # even r = √2 sags 0.5 m at 60 rpm
])
def test_the_sag_warning_offers_only_what_brings_the_mounts_within_the_limit(tmp_path, capsys, rpm, zeta, wanted,
                                                                             offered):
    """The sag g·r²/ω² was called the speed's and the TR's alone ("a larger TR or a higher speed is not" out of
    reach), damping never named; but the r that gives a TR grows with ζ.  Each remedy offered must bring the sag
    within 100 mm by itself, only just, and none left out may."""
    import re

    g, most = 9.80665, 0.1
    omega = rpm * math.pi / 30

    def sag(r, speed=omega):
        return g * r * r / speed ** 2

    code, told = _run(tmp_path, f"mass = 50.0\nunbalance = 0.01\nstiffness = 2e5\ndamping_ratio = {zeta}\n"
                                f"rpm = {rpm}\ntransmissibility = {wanted}\n", capsys)
    assert code == 0
    (line,) = [line for line in told.out.splitlines() if "would sag" in line]
    assert f"would sag by M·g/k = {sag(_ratio_for(wanted, zeta)):.3g} m" in line
    assert "alone" not in line
    found = {"damping": re.search(r"damping ζ ≤ ([\d.]+)", line), "tr": re.search(r"TR ≥ ([\d.]+)", line),
             "speed": re.search(r"a speed of ([\d.]+) rpm or more", line)}
    assert {name for name, match in found.items() if match} == offered
    if "damping" in offered:
        most_zeta = float(found["damping"].group(1))
        assert sag(_ratio_for(wanted, most_zeta)) <= most < sag(_ratio_for(wanted, 1.01 * most_zeta))
    elif zeta > 0:  # less damping would not do: even none sags too much
        assert sag(math.sqrt(1 + 1 / wanted)) > most
    if "tr" in offered:
        least = float(found["tr"].group(1))
        assert sag(_ratio_for(least, zeta)) <= most < sag(_ratio_for(0.99 * least, zeta))
    else:  # every TR below 1 needs r > √2
        assert sag(math.sqrt(2.0)) > most
    fastest = float(found["speed"].group(1)) * math.pi / 30
    assert sag(_ratio_for(wanted, zeta), fastest) <= most < sag(_ratio_for(wanted, zeta), 0.99 * fastest)


@pytest.mark.parametrize(("stiffness", "rpm", "zeta", "wanted", "designed_is"), [
    (200.0, 6000.0, 0.1, 0.01, "stiffer"),  # the tester's: r = 314 already passes TR = 0.00064
    (2e5, 900.0, 2.0, 0.3, "softer"),
])
def test_the_isolating_mounts_are_compared_with_the_present_ones_as_they_are(tmp_path, capsys, stiffness, rpm, zeta,
                                                                             wanted, designed_is):
    """Mounts 230 times stiffer were called "the softer mounts", and the note never said the present ones already
    passed a fifteenth of the TR asked for."""
    omega = rpm * math.pi / 30
    designed = 50.0 * (omega / _ratio_for(wanted, zeta)) ** 2
    r = omega / math.sqrt(stiffness / 50.0)
    present = math.hypot(1, 2 * zeta * r) / math.hypot(1 - r * r, 2 * zeta * r)
    code, _ = _run(tmp_path, f"mass = 50.0\nunbalance = 0.01\nstiffness = {stiffness}\ndamping_ratio = {zeta}\n"
                             f"rpm = {rpm}\ntransmissibility = {wanted}\n", capsys)
    assert code == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    # The present dampers, c = 2ζ·√(k·M), on the designed mounts: ζ·√(k/k_designed).
    assert f"on these {designed_is} mounts, would give ζ = {zeta * math.sqrt(stiffness / designed):.5g})" in note
    assert ("softer" if designed_is == "stiffer" else "stiffer") not in note
    already = f"The present mounts (r = {r:.5g}) already pass TR = {present:.5g}, less than the {wanted:g} asked for"
    assert (already in note) == (present < wanted)


def test_a_bound_offered_is_written_without_an_exponent_and_on_its_safe_side():
    from graphplan.vibration import _rounded

    assert _rounded(1.234e-5, down=True) == "0.0000123" and _rounded(1.234e-5, down=False) == "0.0000124"
    assert _rounded(1219.6, down=False) == "1220" and _rounded(0.3921, down=True) == "0.392"


# --- the warnings recorded in the files, not only printed ----------------------------------------------------


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_speed_near_resonance_is_recorded_in_the_results_and_cautioned_in_the_note(tmp_path, capsys, locale):
    """ω = 30 rad/s on k/M = 1000 s⁻² without damping was warned of on the console only: results.json and the
    note said nothing, and the amplitude stood in the note as if it were the machine's."""
    code, told = _run(tmp_path, "mass = 100.0\nunbalance = 0.02\nstiffness = 1e5\nomega = 30.0\n", capsys)
    assert code == 0 and "warning: vibration: no damping" in told.out
    r = 30.0 / math.sqrt(1e5 / 100.0)
    (found,) = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["vibration"]["warnings"]
    # r to the note's five digits (0.94868), where the detail wrote 0.948683 beside it.
    assert found["code"] == "near-resonance" and f"(r = {r:.5g})" in found["detail"]
    amplitude = 0.02 / 100.0 * r * r / abs(1 - r * r)
    assert f"X = {amplitude:.5g} m" in found["detail"]
    from graphplan.cli import main

    assert main(["run", str(tmp_path / "machine.toml"), "--locale", locale, "--only", "note",
                 "--out", str(tmp_path / locale)]) == 0
    note = (tmp_path / locale / "note.md").read_text(encoding="utf-8")
    caution = {"en": "Caution: there is no damping", "ru": "Внимание: демпфирования нет", "zh": "注意：系统无阻尼"}
    share = f"{abs(r - 1) * 100:.2g}".replace(".", "," if locale == "ru" else ".")
    (line,) = [line for line in note.splitlines() if line.startswith(caution[locale])]
    assert f"{share} %" in line and f"r = {r:.5g}".replace(".", "," if locale == "ru" else ".") in line


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_isolating_mounts_no_spring_could_be_are_recorded_and_cautioned_in_the_note(tmp_path, capsys, locale):
    """TR = 0.01 at ζ = 1 and 600 rpm needs r = 200: mounts of 9.87 N/m sagging 99 m, which the note offered as the
    design without a word and results.json recorded as one."""
    g, omega = 9.80665, 600 * math.pi / 30
    code, told = _run(tmp_path, "mass = 100.0\nunbalance = 0.02\nstiffness = 1e5\ndamping_ratio = 1.0\n"
                                "rpm = 600.0\ntransmissibility = 0.01\n", capsys)
    assert code == 0 and "would sag" in told.out
    sag = g * _ratio_for(0.01, 1.0) ** 2 / omega ** 2
    (found,) = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["vibration"]["warnings"]
    assert found["code"] == "mounts-sag" and f"would sag by M·g/k = {sag:.3g} m" in found["detail"]
    from graphplan.cli import main

    assert main(["run", str(tmp_path / "machine.toml"), "--locale", locale, "--only", "note",
                 "--out", str(tmp_path / locale)]) == 0
    note = (tmp_path / locale / "note.md").read_text(encoding="utf-8")
    caution = {"en": "Caution: the isolating mounts", "ru": "Внимание: рассчитанные выше виброизоляторы",
               "zh": "注意：上面算出的隔振器"}
    (line,) = [line for line in note.splitlines() if line.startswith(caution[locale])]
    written = f"{sag:.3g}".replace(".", "," if locale == "ru" else ".")
    assert f"M·g/k = {written} " in line


def test_a_machine_with_nothing_to_warn_of_records_an_empty_list(tmp_path, capsys):
    code, told = _run(tmp_path, "mass = 100.0\nunbalance = 0.02\nstiffness = 1e5\ndamping_ratio = 0.1\n"
                                "rpm = 600.0\ntransmissibility = 0.2\n", capsys)
    assert code == 0 and "warning" not in told.out
    results = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    assert results["vibration"]["warnings"] == []
    assert "Caution" not in (tmp_path / "out" / "note.md").read_text(encoding="utf-8")


def test_a_balanced_machine_on_a_shaken_base_near_resonance_warns_of_the_motion_it_makes(tmp_path, capsys):
    """With no unbalance the warning gave "the amplitude X = 0 m grows without bound": the unbalance's, which is none;
    the machine moves X = Y·TR."""
    omega = 0.99 * math.sqrt(1e5 / 100.0)
    code, told = _run(tmp_path, f"mass = 100.0\nunbalance = 0.0\nstiffness = 1e5\nomega = {omega!r}\n"
                                "base_amplitude = 0.01\n", capsys)
    assert code == 0
    r = 0.99
    assert f"X = {0.01 / abs(1 - r * r):.5g} m grows without bound" in told.out


@pytest.mark.parametrize(("locale", "base", "both", "rotor"), [
    ("en", "Vibration from base excitation", "Vibration from the rotating unbalance and base excitation",
     "critical speed"),
    ("ru", "Колебания при кинематическом возбуждении (от движения основания)",
     "Колебания от вращающегося дисбаланса и движения основания", "критическая частота вращения"),
    ("zh", "基础激励引起的振动", "回转不平衡与基础激励引起的振动", "临界转速"),
])
def test_the_vibration_section_is_titled_by_what_excites_the_machine(tmp_path, capsys, locale, base, both, rotor):
    """A vehicle on a road (no unbalance, a moving base) was "Vibration from the rotating unbalance" with "the
    critical speed" of a rotor it has not; its numbers stay."""
    from graphplan.cli import main

    road = "mass = 1200.0\nunbalance = 0.0\nstiffness = 4.0e5\ndamping_ratio = 0.5\nomega = 5.8178\nbase_amplitude = 0.05\n"
    code, _ = _run(tmp_path, road, capsys)
    assert code == 0
    assert main(["run", str(tmp_path / "machine.toml"), "--locale", locale, "--only", "note",
                 "--out", str(tmp_path / locale)]) == 0
    note = (tmp_path / locale / "note.md").read_text(encoding="utf-8")
    (heading,) = re.findall(r"^## \d+\.? (.+)$", note, flags=re.MULTILINE)
    assert heading == base and rotor not in note
    natural = math.sqrt(4.0e5 / 1200.0)
    mark = "," if locale == "ru" else "."
    assert f"= {natural:.5g} ".replace(".", mark) in note and f"{natural * 30 / math.pi:.5g}".replace(".", mark) in note
    (tmp_path / "both").mkdir()
    code, _ = _run(tmp_path / "both", road.replace("unbalance = 0.0", "unbalance = 0.5"), capsys)
    assert main(["run", str(tmp_path / "both" / "machine.toml"), "--locale", locale, "--only", "note",
                 "--out", str(tmp_path / "both" / locale)]) == 0
    note = (tmp_path / "both" / locale / "note.md").read_text(encoding="utf-8")
    assert re.findall(r"^## \d+\.? (.+)$", note, flags=re.MULTILINE) == [both] and rotor in note


def test_isolating_mounts_far_above_resonance_do_not_squeeze_the_resonance_into_the_axis_edge():
    """TR = 0.01 at ζ = 1 needs r = 200: the linear axis ran to 240 and the working point at r = 1.99, with the
    whole resonance, stood in its first percent.  Where the plot reaches that far, r runs on a log axis."""
    import io

    zeta, wanted = 1.0, 0.01
    ratio = brentq(lambda r: math.hypot(1, 2 * zeta * r) / math.hypot(1 - r * r, 2 * zeta * r) - wanted, 1.5, 1e4)
    stream = io.StringIO()
    transmissibility_figure(stream, operating=(1.99, zeta), design=(ratio, wanted))
    text = stream.getvalue()
    left, right = (float(v) for v in re.search(r'<g id="patch_2">\s*<path d="M ([\d.]+) [\d.]+\s*L ([\d.]+) ',
                                                text).groups())

    def marker(colour):
        return float(re.search(rf'<use xlink:href="#\w+" x="(-?[\d.]+)" y="-?[\d.]+" style="fill: {colour}',
                               text).group(1))

    working, design = marker("#a83a1f"), marker("#1f7a3a")
    assert left + 0.2 * (right - left) < working < left + 0.6 * (right - left)
    assert working < design < right
    # On a log axis equal ratios are equal distances: from r = 1.99 to 200 is log(200/1.99) of the decade's width.
    decade = (design - working) / math.log10(ratio / 1.99)
    assert (right - design) == pytest.approx(decade * math.log10(math.ceil(1.2 * ratio) / ratio), rel=0.02)


# --- isolating a disc on a shaft: the mounts are in series with the shaft ---------------------------------------

# The hunter's disc: 20 kg on a simply supported shaft, E = 2.1e11 Pa, d = 30 mm, L = 0.8 m, a = 0.3 m, 3000 rpm.
_SHAFT_DISC = ('mass = 20.0\nunbalance = 0.001\nshaft = {{ modulus = 2.1e11, diameter = {diameter}, length = 0.8, '
               'position = 0.3 }}\ndamping_ratio = 0.05\nrpm = {rpm}\ntransmissibility = 0.1\n')


def _shaft_k(diameter):
    """The shaft's stiffness at the disc from δ = F·a²·b²/(3·E·I·L), I = π·d⁴/64."""
    second = math.pi * diameter ** 4 / 64.0
    return 3.0 * 2.1e11 * second * 0.8 / (0.3 ** 2 * 0.5 ** 2)


def test_series_mounts_give_the_total_with_the_shaft_and_none_where_the_shaft_is_softer():
    assert series_mount_stiffness(1.0e5, 4.0e5) == pytest.approx(1.0 / (1.0 / 1.0e5 - 1.0 / 4.0e5), rel=1e-14)
    assert series_mount_stiffness(4.0e5, 4.0e5) is None and series_mount_stiffness(5.0e5, 4.0e5) is None


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_disc_on_a_shaft_is_isolated_by_mounts_in_series_with_the_shaft(tmp_path, capsys, locale):
    """M·(ω/r)² is the whole support's stiffness: the note called it the mounts' (170 810 N/m), where mounts under
    the bearings, in series with the 890 640 N/m shaft, must be 211 334 N/m."""
    code, _ = _run(tmp_path, _SHAFT_DISC.format(diameter=0.03, rpm=3000.0), capsys)
    assert code == 0
    omega, shaft = 3000.0 * math.pi / 30.0, _shaft_k(0.03)
    total = 20.0 * (omega / _ratio_for(0.1, 0.05)) ** 2
    mounts = 1.0 / (1.0 / total - 1.0 / shaft)
    # The shaft on those mounts, ζ kept, passes the 0.1 asked for.
    together = shaft * mounts / (shaft + mounts)
    r = omega / math.sqrt(together / 20.0)
    assert math.hypot(1, 0.1 * r) / math.hypot(1 - r * r, 0.1 * r) == pytest.approx(0.1, rel=1e-9)
    isolation = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["vibration"]["isolation"]
    assert isolation["stiffness"] == pytest.approx(total, rel=1e-9)
    assert isolation["mount_stiffness"] == pytest.approx(mounts, rel=1e-9)
    from graphplan.cli import main

    assert main(["run", str(tmp_path / "machine.toml"), "--locale", locale, "--only", "note",
                 "--out", str(tmp_path / locale)]) == 0
    note = (tmp_path / locale / "note.md").read_text(encoding="utf-8")
    found = re.search(r"km = k·ks/\(ks − k\) = [^=]+ = (\d+(?:[.,]\d+)?) ", note)
    written = float(found.group(1).replace(",", "."))
    assert abs(written - mounts) <= 0.5 * 10 ** (math.floor(math.log10(mounts)) - 4)
    assert {"en": "mounts of stiffness", "ru": "опоры жёсткостью", "zh": "隔振器刚度 k"}[locale] not in note
    assert {"en": "present mounts", "ru": "Нынешние опоры", "zh": "现有隔振器"}[locale] not in note


def test_a_shaft_softer_than_the_support_asked_for_needs_no_mounts(tmp_path, capsys):
    """d = 10 mm: the shaft alone (11 000 N/m) is softer than the 170 805 N/m the isolation asks for at most, so it
    already passes less than TR = 0.1; no mount in series could stiffen it to k, and none is needed."""
    code, told = _run(tmp_path, _SHAFT_DISC.format(diameter=0.01, rpm=3000.0), capsys)
    assert code == 0 and "warning" not in told.out
    shaft, omega = _shaft_k(0.01), 3000.0 * math.pi / 30.0
    assert 20.0 * (omega / _ratio_for(0.1, 0.05)) ** 2 > shaft
    vibration = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["vibration"]
    assert vibration["isolation"]["mount_stiffness"] is None
    r = omega / math.sqrt(shaft / 20.0)
    tr = math.hypot(1, 0.1 * r) / math.hypot(1 - r * r, 0.1 * r)
    assert vibration["transmissibility"] == pytest.approx(tr, rel=1e-9) and tr < 0.1
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert f"already passes TR = {tr:.4g}" in note and "it needs no mounts" in note
    assert "km =" not in note and "present mounts" not in note
    plot = (tmp_path / "out" / "vibration_transmissibility.svg").read_text(encoding="utf-8")
    assert "isolating support: TR = 0.1" in plot and "isolating mounts" not in plot


def test_mounts_under_a_shafts_bearings_sag_what_the_shafts_own_bending_leaves(tmp_path, capsys):
    """At 300 rpm the support must be 1708 N/m: the disc sinks g·r²/ω² = 0.115 m, of which the shaft bends 0.22 mm
    and the mounts sag the rest, M·g/km."""
    code, told = _run(tmp_path, _SHAFT_DISC.format(diameter=0.03, rpm=300.0), capsys)
    assert code == 0 and "warning: vibration: the mounts under the shaft's bearings" in told.out
    g, omega, shaft = 9.80665, 300.0 * math.pi / 30.0, _shaft_k(0.03)
    total = 20.0 * (omega / _ratio_for(0.1, 0.05)) ** 2
    mounts = total * shaft / (shaft - total)
    sag = 20.0 * g / mounts
    assert sag == pytest.approx(g * _ratio_for(0.1, 0.05) ** 2 / omega ** 2 - 20.0 * g / shaft, rel=1e-9)
    (found,) = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["vibration"]["warnings"]
    assert found["code"] == "mounts-sag" and f"k_m = {mounts:.5g} N/m" in found["detail"]
    assert f"M·g/k_m = {sag:.3g} m" in found["detail"]
    # The speed that brings the mounts within 0.1 m: g·r²/ω² − M·g/ks = 0.1.
    least = _ratio_for(0.1, 0.05) * math.sqrt(g / (0.1 + 20.0 * g / shaft)) * 30.0 / math.pi
    assert f"a speed of {math.ceil(least)} rpm or more" in found["detail"]


# --- the force a moving base's mounts pass ---------------------------------------------------------------------


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_force_a_moving_bases_mounts_pass_is_given_beside_its_transmissibility(tmp_path, capsys, locale):
    """An instrument on a shaken floor wrote transmitted_force = 0 beside TR = 0.857: the mounts pass
    (k + i·c·ω)·(x − y), 190 N, which only a machine with an unbalance too was told of."""
    mass, k, zeta, rpm, base = 50.0, 5.0e4, 0.2, 450.0, 0.002
    code, _ = _run(tmp_path, f'mass = {mass}\nunbalance = 0.0\nstiffness = {k}\ndamping_ratio = {zeta}\nrpm = {rpm}\n'
                             f'base_amplitude = {base}\n', capsys)
    assert code == 0
    omega = rpm * math.pi / 30.0
    c = 2.0 * zeta * math.sqrt(k * mass)
    # M·x″ + c·(x′ − y′) + k·(x − y) = 0 with y = Y·e^{iωt}: (k − M·ω² + i·c·ω)·X = (k + i·c·ω)·Y.
    motion = (k + 1j * c * omega) * base / (k - mass * omega ** 2 + 1j * c * omega)
    force = abs((k + 1j * c * omega) * (motion - base))
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["vibration"]
    assert document["base_excitation"]["transmitted_force"] == pytest.approx(force, rel=1e-10)
    assert document["transmitted_force"] == 0.0  # the unbalance's alone, as documented
    from graphplan.cli import main

    assert main(["run", str(tmp_path / "machine.toml"), "--locale", locale, "--only", "note",
                 "--out", str(tmp_path / locale)]) == 0
    note = (tmp_path / locale / "note.md").read_text(encoding="utf-8")
    found = re.search(r"TR·M·ω²·Y = [^=]+ = (\d+(?:[.,]\d+)?) [NН]", note)
    assert found and abs(float(found.group(1).replace(",", ".")) - force) <= 0.5 * 10 ** (math.floor(math.log10(force)) - 4)


# --- at resonance itself ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_machine_at_resonance_is_said_to_run_at_it_not_within_nought_of_it(tmp_path, capsys, locale):
    """ω = ωn with ζ = 0.002 read "within 0 % of the natural frequency … grows steeply nearer resonance"."""
    code, told = _run(tmp_path, "mass = 100.0\nunbalance = 0.01\nstiffness = 1.0e6\ndamping_ratio = 0.002\n"
                                "omega = 100.0\n", capsys)
    assert code == 0
    magnification = 1.0 / (2.0 * 0.002)  # r²/√((1 − r²)² + (2ζr)²) at r = 1
    assert "ω at the natural frequency (r = 1): the machine runs at resonance" in told.out and "within 0" not in told.out
    assert f"X = {0.01 / 100.0 * magnification:.5g} m is {magnification:.5g} times m·e/M" in told.out
    from graphplan.cli import main

    assert main(["run", str(tmp_path / "machine.toml"), "--locale", locale, "--only", "note",
                 "--out", str(tmp_path / locale)]) == 0
    note = (tmp_path / locale / "note.md").read_text(encoding="utf-8")
    start = {"en": "Caution: the machine runs at resonance (r = 1)", "ru": "Внимание: машина работает в резонансе (r = 1)",
             "zh": "注意：机器在共振状态下运行（r = 1）"}[locale]
    (line,) = [line for line in note.splitlines() if line.startswith(start)]
    assert f"{magnification:g}" in line and "0 %" not in line


def test_an_undamped_machine_at_resonance_to_the_digits_shown_is_said_to_run_at_it(tmp_path, capsys):
    """r = 1.000003: outside the 10⁻⁶ that is refused as resonance, but r = 1 to the five digits the console and the
    note write it to."""
    r = 1.000003
    code, told = _run(tmp_path, f"mass = 100.0\nunbalance = 0.01\nstiffness = 1.0e6\nomega = {100.0 * r!r}\n", capsys)
    assert code == 0 and f"{r:.5g}" == "1"
    assert "no damping and ω at the natural frequency to five digits (r = 1)" in told.out
    assert f"X = {0.01 / 100.0 * r * r / abs(1 - r * r):.5g} m" in told.out
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert "Caution: there is no damping and the machine runs at resonance to the digits shown (r = 1)" in note


# --- a linkage's crank gives its speed ----------------------------------------------------------------------------

_ENGINE_MOUNTS = "\n[vibration]\nmass = 60.0\nunbalance = 0.08\nstiffness = 4.0e5\ndamping_ratio = 0.08\n"


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_linkages_vibration_without_a_speed_turns_at_its_cranks(tmp_path, capsys, locale):
    """The engine's crank turns at 1500 rpm; [vibration] with no rpm was refused (vibration.omega: is required)."""
    from pathlib import Path

    from graphplan.cli import main

    scene = tmp_path / "engine.toml"
    scene.write_text(Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8").replace(
        'locale  = "en"', f'locale  = "{locale}"') + _ENGINE_MOUNTS, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "vibration,note"]) == 0
    omega = 1500.0 * 2.0 * math.pi / 60.0
    r = omega / math.sqrt(4.0e5 / 60.0)
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["vibration"]
    assert document["frequency_ratio"] == pytest.approx(r, rel=1e-10)
    assert document["exciting_force"] == pytest.approx(0.08 * omega ** 2, rel=1e-10)
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    said = {"en": "The machine turns at the crank's speed n = 1500 rpm (ω = 157.08 rad/s)",
            "ru": "Машина вращается с частотой вращения кривошипа n = 1500 об/мин (ω = 157,08 рад/с)",
            "zh": "机器以曲柄的转速 n = 1500 r/min（ω = 157.08 rad/s）回转"}[locale]
    assert said in note


def test_a_linkage_whose_driver_has_no_steady_turning_speed_still_needs_one_in_vibration(tmp_path, capsys):
    """A slider driver, a rocking crank, a crank speeding up: no one speed to take, and the refusal stays."""
    from pathlib import Path

    from graphplan.cli import main

    engine = Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8")
    for name, text in (("slider", Path("fixtures/slider_driven.toml").read_text(encoding="utf-8")),
                       ("rocking", engine.replace("epsilon = 0.0", "epsilon = 0.0\nswing = [0.0, 120.0]")),
                       ("speeding", engine.replace("epsilon = 0.0", "epsilon = 10.0"))):
        scene = tmp_path / f"{name}.toml"
        scene.write_text(text + _ENGINE_MOUNTS, encoding="utf-8")
        assert main(["check", str(scene)]) == 2, name
        assert "vibration.omega: is required but missing: give omega (rad/s) or rpm (rev/min)" in \
            capsys.readouterr().err, name


# --- the lag at resonance -------------------------------------------------------------------------------------------


@pytest.mark.parametrize(("function", "at_resonance"), [
    (phase, lambda zeta: math.pi / 2),  # tan φ = 2ζ/0
    (displacement_transmissibility_phase, lambda zeta: math.atan(1.0 / (2.0 * zeta))),  # tan φ = 2ζ/(2ζ)²
])
def test_at_resonance_the_lag_is_a_quarter_turn_without_damping(function, at_resonance):
    """phase(1, 0) was atan2(0, 0) = 0, "in phase", where every ζ > 0 lags by π/2 and so does the limit ζ → 0; a
    moving base's lag at r = 1, atan(1/(2ζ)), tends to π/2 too."""
    for zeta in (1e-300, 1e-9, 0.05, 2.0):
        assert function(1.0, zeta) == pytest.approx(at_resonance(zeta), rel=1e-12)
    assert function(1.0, 0.0) == math.pi / 2
    lags = function(np.array([0.5, 1.0, 2.0]), np.array([0.0, 0.0, 0.0]))
    assert list(lags) == [0.0, math.pi / 2, math.pi]


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_an_instrument_shaken_near_resonance_is_told_of_its_base_not_of_a_speed_it_runs_at(tmp_path, capsys, locale):
    """An instrument on a shaken floor near resonance was told "the speed is within 1 % of the natural frequency …
    run the machine farther from it", with the magnification of an unbalance it has not: it runs at no speed, its
    base shakes it X/Y times as far, and the way out is its mounts."""
    natural = math.sqrt(1e5 / 100.0)
    code, told = _run(tmp_path, f"mass = 100.0\nunbalance = 0.0\nstiffness = 1e5\ndamping_ratio = 0.01\n"
                                f"omega = {0.99 * natural!r}\nbase_amplitude = 0.01\n", capsys)
    assert code == 0
    # X/Y = √(1 + (2ζr)²)/√((1 − r²)² + (2ζr)²) at r = 0.99, ζ = 0.01: √(1 + 0.0198²)/√(0.0199² + 0.0198²) = 35.63.
    r, zeta = 0.99, 0.01
    ratio = math.hypot(1.0, 2 * zeta * r) / math.hypot(1 - r * r, 2 * zeta * r)
    assert ratio == pytest.approx(35.63, rel=1e-3)
    (line,) = [line for line in told.out.splitlines() if "warning: vibration:" in line]
    assert "the base's ω within 1 % of the natural frequency" in line
    assert f"the instrument moves X = {0.01 * ratio:.5g} m, {ratio:.5g} times the base's Y" in line
    assert "run the machine" not in line
    from graphplan.cli import main

    assert main(["run", str(tmp_path / "machine.toml"), "--locale", locale, "--only", "note",
                 "--out", str(tmp_path / locale)]) == 0
    note = (tmp_path / locale / "note.md").read_text(encoding="utf-8")
    text = strings(locale)
    mark = "," if locale == "ru" else "."
    caution = text["note_vib_caution_resonance_base"].format(
        share="1", ratio="0.99".replace(".", mark), zeta="0.01".replace(".", mark),
        tr=f"{ratio:.5g}".replace(".", mark))
    assert caution in note, note
    machine = {"en": "machine", "ru": "машин", "zh": "机器"}[locale]
    assert machine not in caution


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_an_instrument_s_plots_name_the_instrument_not_a_machine(locale):
    text = strings(locale)
    instrument = VibrationSpec(mass=100.0, unbalance=0.0, stiffness=1e5, damping_ratio=0.1, omega=20.0,
                               base_amplitude=0.01)
    words = words_for(instrument, text)
    assert words["vib_zeta_machine"] == text["vib_zeta_instrument"]
    assert words["vib_transmissibility_title"] == text["vib_motion_title"]
    machine = {"en": "machine", "ru": "машин", "zh": "机器"}[locale]
    assert machine not in words["vib_zeta_machine"] + words["vib_transmissibility_title"]
    # A machine with an unbalance keeps its own words.
    unbalanced = VibrationSpec(mass=100.0, unbalance=0.02, stiffness=1e5, damping_ratio=0.1, omega=20.0)
    assert words_for(unbalanced, text) is text


@pytest.mark.parametrize(("rpm", "warned"), [(600.0, True), (590.0, False)])
def test_an_instrument_is_warned_of_by_the_times_its_base_s_motion_it_makes(tmp_path, capsys, rpm, warned):
    """50 kg on 2·10⁵ N/m with ζ = 0.05, its floor shaking 1 mm at 600 rpm, r = 0.9935: it moves 10.03 times as far
    as its floor, and was not warned of, its growth judged by M·X/(m·e) = 9.85 of an unbalance it has not.  At 590
    rpm it moves less than 10 times as far, as a machine's magnification below 10 is not warned of."""
    omega = rpm * 2 * math.pi / 60
    r, zeta = omega / math.sqrt(2e5 / 50.0), 0.05
    times = math.hypot(1.0, 2 * zeta * r) / math.hypot(1 - r * r, 2 * zeta * r)   # X/Y, by hand
    assert (times >= 10) == warned
    code, told = _run(tmp_path, f"mass = 50.0\nunbalance = 0.0\nstiffness = 2e5\ndamping_ratio = {zeta}\n"
                                f"rpm = {rpm}\nbase_amplitude = 0.001\n", capsys)
    assert code == 0
    lines = [line for line in told.out.splitlines() if "warning: vibration:" in line]
    assert bool(lines) == warned
    if warned:
        assert f"{times:.5g} times the base's Y" in lines[0]
        codes = [each["code"] for each in json.loads((tmp_path / "out" / "results.json").read_text(
            encoding="utf-8"))["vibration"]["warnings"]]
        assert codes == ["near-resonance"]


@pytest.mark.parametrize(("locale", "said"), [
    ("en", r"TR ≥ ([\d.]+) at ζ = 8"), ("ru", r"TR ≥ ([\d,]+) при ζ = 8"), ("zh", r"，或在 ζ = 8 时 TR ≥ ([\d.]+)")])
def test_the_note_gives_the_least_transmissibility_at_the_damping_it_holds_at(tmp_path, capsys, locale, said):
    """The note's sag caution wrote "TR ≥ 0.786" bare where the console wrote "TR ≥ 0.786 at ζ = 8": the bound holds
    at the scene's ζ alone (undamped, TR ≥ 0.786 is another r).  The Chinese ran its "or" into the symbol, "或TR"."""
    g, most, zeta, wanted, rpm = 9.80665, 0.1, 8.0, 0.1, 1200.0
    omega = rpm * math.pi / 30
    body = (f"mass = 200.0\nunbalanced_mass = 0.5\neccentricity = 0.01\nstiffness = 4.0e5\ndamping_ratio = {zeta:g}\n"
            f"rpm = {rpm}\ntransmissibility = {wanted}\n")
    scene = tmp_path / "machine.toml"
    scene.write_text(f'[scene]\ntitle = "Machine"\nlocale = "{locale}"\n[vibration]\n' + body, encoding="utf-8")
    from graphplan.cli import main

    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "note"]) == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    found = re.search(said, note)
    assert found, note
    least = float(found.group(1).replace(",", "."))
    assert g * _ratio_for(least, zeta) ** 2 / omega ** 2 <= most < g * _ratio_for(0.99 * least, zeta) ** 2 / omega ** 2
    assert "或TR" not in note
