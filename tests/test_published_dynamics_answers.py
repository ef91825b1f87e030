"""Printed answers of published worked examples, asserted against graphplan's dynamics modules.

The other dynamics tests check against independent calculations; these assert the numbers that a
published source prints, to the precision it prints them.  Every number below was read in a
retrieved copy of its source; where it is, what the data are and what could not be found is in
docs/sources/machine-motion.md, flywheel.md, vibration.md and rotor-balancing.md.

* R.S. Khurmi & J.K. Gupta, *A Textbook of Theory of Machines*, S. Chand, chapter 16 "Turning
  Moment Diagrams and Flywheel", Examples 16.1, 16.2, 16.3, 16.12, 16.13 and 16.15 (pp. 573-594),
  as reworked, with their printed results, by the FOSSEE Python Textbook Companion
  ``Theory_Of_Machines/ch16.ipynb`` (GitHub FOSSEE/Python-Textbook-Companions, commit
  dfe3c858e90bb33c32f84a46e0a17cdd93b38e11).  The data are the companion's variables; the
  book's own statements were not retrieved.
* The quiz keys of the Virtual Labs experiments "Force transmissibility" and "Base excitation"
  of NITK Surathkal (GitHub SOLVE-NITK/MDMV-II, commit 6c5ca4314d9c04f0146fd63b91f8e5876f0778da).

A printed value "x.y" is read as the interval x.y ± 0.05 (half a unit of its last digit); a value
the companion prints with ``%d`` (which truncates) as [n, n + 1).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from graphplan.flywheel import flywheel_inertia, omega_to_rpm, rpm_to_omega, speed_fluctuation, speed_limits
from graphplan.machine_motion import RPM, ConstantTorque, Machine, Start, simulate
from graphplan.vibration import (
    VibrationSpec,
    phase,
    steady_state,
    transmissibility,
    unbalance_magnification,
)


def assert_prints_as(value: float, printed: float, decimals: int) -> None:
    """``value`` rounds to ``printed`` at ``decimals`` places (half a unit of the last printed digit)."""
    half_unit = 0.5 * 10.0 ** -decimals
    assert abs(value - printed) <= half_unit * (1 + 1e-9), f"{value!r} does not print as {printed!r}"


def assert_truncates_to(value: float, printed: int) -> None:
    """``value`` prints as ``printed`` with C's ``%d`` (the companion's format), which truncates."""
    assert printed <= value < printed + 1, f"{value!r} does not print as {printed!r} with %d"


def start_speed_for_middle_speed(surplus, inertia: float, middle_speed: float) -> float:
    """The speed at φ = 0 for which (ωmax + ωmin)/2 = ``middle_speed`` over the steady cycle.

    At constant inertia with no speed-dependent torque the energy integral gives
    ω(φ)² = ω0² + 2·W(φ)/J with W(φ) the surplus work from φ = 0 (a closed form passed in), so
    ωmax and ωmin follow from W's extremes.  The textbooks' n is this middle speed.
    """
    work = surplus(np.linspace(0.0, 2 * math.pi, 36001))
    highest, lowest = float(work.max()), float(work.min())

    def middle(start_speed: float) -> float:
        fastest = math.sqrt(start_speed ** 2 + 2 * highest / inertia)
        slowest = math.sqrt(start_speed ** 2 + 2 * lowest / inertia)
        return 0.5 * (fastest + slowest) - middle_speed

    least = math.sqrt(max(0.0, -2 * lowest / inertia)) * (1 + 1e-12)
    return brentq(middle, least, 10 * middle_speed, xtol=1e-13)


# --- the machine's motion (graphplan.machine_motion.simulate) -----------------------------------


def test_khurmi_16_2_flywheel_spun_up_by_a_constant_torque():
    # A 2500 kg flywheel, k = 1 m, started from rest by 1500 N·m.  Printed: α = 0.6 rad/s² and,
    # after 10 s, a kinetic energy of 45.0 kN·m.
    inertia = 2500 * 1.0 ** 2
    motion = simulate(Machine(inertia), ConstantTorque(1500.0), duration=10.0, rtol=1e-10)
    _, speed = motion.state_at(10.0)
    assert_prints_as(speed / 10.0, 0.6, 1)
    assert_prints_as(0.5 * inertia * speed ** 2 / 1000, 45.0, 1)


# Khurmi & Gupta, Example 16.12: engine torque 5000 + 600 sin 2θ N·m against a resisting torque
# 5000 + 500 sin θ N·m on a flywheel of 500 kg at k = 0.4 m, mean speed 150 rpm.  Reduced to the
# shaft: a constant 5000 N·m motor against Mr = 5000 + 500 sin φ − 600 sin 2φ.
KHURMI_16_12_INERTIA = 500 * 0.4 ** 2


def khurmi_16_12_motion():
    surplus = lambda phi: 600 * np.sin(phi) ** 2 + 500 * (np.cos(phi) - 1)  # ∫(600 sin 2θ − 500 sin θ)
    start = start_speed_for_middle_speed(surplus, KHURMI_16_12_INERTIA, 150 * RPM)
    machine = Machine(KHURMI_16_12_INERTIA, resisting=lambda phi, omega: 5000 + 500 * math.sin(phi)
                      - 600 * math.sin(2 * phi))
    return simulate(machine, ConstantTorque(5000.0), start=Start(omega=start), rtol=1e-10)


def test_khurmi_16_12_speed_fluctuation_of_the_integrated_motion():
    # Printed: total fluctuation of speed 6.1 %.  The steady cycle found by integration, not the
    # flywheel formula ΔE/(I·ω²), must give it.
    steady = khurmi_16_12_motion().steady
    assert steady is not None
    assert steady.cycle.middle_speed == pytest.approx(150 * RPM, rel=1e-6)
    assert_prints_as(100 * steady.delta, 6.1, 1)


def test_khurmi_16_12_extreme_accelerations_of_the_integrated_motion():
    # Printed: the acceleration is greatest, 3.46 rad/s², at θ = 35° and least, 12.2 rad/s²
    # (a deceleration), at θ = 127.6°.  The book finds them from a quadratic in cos θ, so its
    # angles lie in [0°, 180°]: they are the extremes over the first half-turn.  (Over the whole
    # turn the largest acceleration is +12.2 rad/s² at 232.4°, the mirror of the least one.)
    # The acceleration is read off the integrated speed by central differences.
    motion = khurmi_16_12_motion()
    cycle = motion.steady.cycle
    times = np.linspace(cycle.start, cycle.start + cycle.period, 40001)
    step = 1e-5
    acceleration = (motion.state_at(times + step)[1] - motion.state_at(times - step)[1]) / (2 * step)
    angle = np.degrees(motion.state_at(times)[0]) % 360.0
    first_half = angle <= 180.0
    largest = np.argmax(np.where(first_half, acceleration, -np.inf))
    least = np.argmin(np.where(first_half, acceleration, np.inf))
    assert_prints_as(acceleration[largest], 3.46, 2)
    assert_truncates_to(angle[largest], 35)  # printed with %d
    assert_prints_as(-acceleration[least], 12.2, 1)
    assert_prints_as(angle[least], 127.6, 1)


# Khurmi & Gupta, Example 16.13: engine torque 5000 + 1500 sin 3θ N·m, flywheel I = 1000 kg·m²,
# 300 rpm.
KHURMI_16_13_INERTIA = 1000.0


def khurmi_16_13_motion(resisting, surplus):
    start = start_speed_for_middle_speed(surplus, KHURMI_16_13_INERTIA, 300 * RPM)
    machine = Machine(KHURMI_16_13_INERTIA, resisting=resisting)
    return simulate(machine, ConstantTorque(5000.0), start=Start(omega=start), rtol=1e-10)


def test_khurmi_16_13_engine_against_a_constant_resisting_torque():
    # Printed: power 157.1 kW; fluctuation of speed 0.1 % with a constant resisting torque.
    motion = khurmi_16_13_motion(lambda phi, omega: 5000 - 1500 * math.sin(3 * phi),
                                 lambda phi: 500 * (1 - np.cos(3 * phi)))
    steady = motion.steady
    assert_prints_as(5000 * steady.mean_speed / 1000, 157.1, 1)
    assert_prints_as(100 * steady.delta, 0.1, 1)


@pytest.mark.xfail(strict=True, reason=(
    "the FOSSEE companion's 0.020 % for Khurmi 16.13 (resisting 5000 + 600 sin θ) is provably wrong: "
    "its code integrates between θB = sin(radians(√0.65)) = 0.014° and 180° − θB instead of between the "
    "zeros sin θ = √0.65 of the net torque; the surplus W = 500(1 − cos 3θ) − 600(1 − cos θ) ranges over "
    "728.3 − (−928.3) = 1656.5 J, so δ = 1656.5/(1000·(10π)²) = 0.168 %"))
def test_khurmi_16_13_engine_against_a_varying_resisting_torque_companion_printout():
    motion = khurmi_16_13_motion(lambda phi, omega: 5000 + 600 * math.sin(phi) - 1500 * math.sin(3 * phi),
                                 lambda phi: 500 * (1 - np.cos(3 * phi)) - 600 * (1 - np.cos(phi)))
    assert_prints_as(100 * motion.steady.delta, 0.020, 3)


# --- the flywheel formulas (graphplan.flywheel) ---------------------------------------------------


def test_khurmi_16_1_speed_limits_of_a_flywheel():
    # 6.5 t at k = 1.8 m, ΔE = 56 kN·m, mean speed 120 rpm.  Printed: 121 rpm and 119 rpm.
    omega = rpm_to_omega(120.0)
    delta = speed_fluctuation(56e3, omega, 6500 * 1.8 ** 2)
    fastest, slowest = speed_limits(omega, delta)
    assert round(omega_to_rpm(fastest)) == 121
    assert round(omega_to_rpm(slowest)) == 119


def test_khurmi_16_3_flywheel_mass_from_the_work_per_cycle():
    # 300 kW at 90 rpm; ΔE is 0.1 of the work per cycle; speed within ±0.5 % (δ = 0.01);
    # k = 2 m.  Printed (with %d): 5628 kg.
    work_per_cycle = 300e3 * 60 / 90
    inertia = flywheel_inertia(0.1 * work_per_cycle, rpm_to_omega(90.0), 0.01)
    assert_truncates_to(inertia / 2.0 ** 2, 5628)


def test_khurmi_16_15_flywheel_rim_with_the_speed_rounded_as_printed():
    # 150 kW at 80 rpm, ΔE = 0.1 of the work per cycle, δ = 0.04; the rim, of radius of gyration
    # 1 m, gives 95 % of the inertia.  Printed: 3787 kg.  The solution rounds ω = 8.3776 rad/s to
    # 8.4 before squaring; with it the rim is 3786.7 kg, with the exact ω 3807 kg (0.5 % more), so
    # the printed figure is reproduced only with the printed rounding, as the assertions show.
    delta_e = 0.1 * 150e3 * 60 / 80
    rim_as_printed = 0.95 * flywheel_inertia(delta_e, 8.4, 0.04) / 1.0 ** 2
    rim_exact = 0.95 * flywheel_inertia(delta_e, rpm_to_omega(80.0), 0.04) / 1.0 ** 2
    assert_prints_as(rim_as_printed, 3787, 0)
    assert round(rim_exact) != 3787
    assert rim_exact / rim_as_printed == pytest.approx((8.4 / rpm_to_omega(80.0)) ** 2, rel=1e-12)


# --- rotating unbalance and transmissibility (graphplan.vibration) -------------------------------


def test_nitk_force_transmissibility_at_resonance():
    # Post-test Q4: ζ = 0.1, r = 1 gives a force transmissibility of 5.1 (answer d).
    assert_prints_as(transmissibility(1.0, 0.1), 5.1, 1)
    # Post-test Q1: the response lags the force by 90° at resonance ("true"), whatever the damping.
    np.testing.assert_allclose(np.degrees(phase(1.0, np.array([0.05, 0.1, 0.5, 1.0]))), 90.0, rtol=1e-12)


def test_nitk_transmissibility_is_one_at_root_two():
    # Pre-test Q3: with ζ = 1, TR = 1 at the frequency ratio 1.414 (answer b).
    ratio = brentq(lambda r: transmissibility(r, 1.0) - 1.0, 1.01, 5.0, xtol=1e-12)
    assert_prints_as(ratio, 1.414, 3)


@pytest.mark.parametrize("omega", [300.0, 2866 * RPM], ids=["300 rad/s", "2866 rpm"])
def test_nitk_force_of_a_rotating_unbalance(omega):
    # Pre-test Q4 (300 rad/s) and base-excitation post-test Q1 (2866 rev/min): 20 g at 10 mm
    # gives 18 N.  The mount (any) does not change the exciting force m·e·ω².
    for mass, stiffness in ((50.0, 2e5), (400.0, 7e6)):
        spec = VibrationSpec(mass=mass, unbalance=0.020 * 0.010, stiffness=stiffness, damping_ratio=0.1,
                             omega=omega)
        assert_prints_as(steady_state(spec).exciting_force, 18, 0)


@pytest.mark.xfail(strict=True, reason=(
    "the NITK base-excitation post-test key (Q3: Y = 5 mm, r = 0.87, ζ = 0.2 → 1.75 mm) is provably wrong "
    "as an amplitude: X/Y = √(1 + (2ζr)²)/√((1 − r²)² + (2ζr)²) = 1.0588/0.4245 = 2.494 ≥ 1 for every r < √2, "
    "so X = 12.47 mm > Y; the motion relative to the base, Z/Y = r²/0.4245 = 1.783, is 8.92 mm"))
def test_nitk_base_excitation_amplitude_quiz_key():
    base_amplitude, ratio, zeta = 5.0, 0.87, 0.2
    absolute = base_amplitude * transmissibility(ratio, zeta)
    relative = base_amplitude * unbalance_magnification(ratio, zeta)
    assert any(abs(value - 1.75) <= 0.005 for value in (absolute, relative))
