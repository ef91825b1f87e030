"""A teacher's review of the machine's motion: each run of the equation of motion set against its own integration
(scipy's solve_ivp at tight tolerances on a right-hand side written here, Kloss' formula written here), and what
the note and the plot say of it."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scene_texts import POWER_CYCLE_PRESS
from scipy.integrate import solve_ivp

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.machine_motion import LinearMotor, Machine, Start, simulate
from graphplan.report.motion_plots import motion_plot

# A machine of constant Je and Mr joined to a straight-line motor by a friction clutch: its steady state is a
# uniform turn, Md(ω) = Mr.
CLUTCH_SCENE = """[scene]
title = "Clutch"
[dynamics]
rpm = 100
inertia = 30.0
resisting_torque = [[0, 150.0], [360, 150.0]]
motor = { kind = "linear", stall_torque = 60.0, no_load_rpm = 1500, gear_ratio = 14.0, rotor_inertia = 0.03 }
clutch = { torque = 400.0, engage_at = 2.0, inertia = 2.0 }
"""


def _run(tmp_path, text):
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return results["dynamics"]["motion"], (out / "note.md").read_text(encoding="utf-8")


def _clutch_run_of_my_own():
    """The clutch scene integrated here: the driving half spun up alone, slipping at 400 N·m, then locked."""
    gear, no_load = 14.0, 1500.0 * math.pi / 30.0
    driving, driven, capacity, resisting = 0.03 * gear ** 2 + 2.0, 30.0, 400.0, 150.0

    def motor(speed):
        return gear * 60.0 * (1.0 - gear * speed / no_load)

    spun = solve_ivp(lambda t, y: [motor(y[0]) / driving], (0.0, 2.0), [0.0], rtol=1e-12, atol=1e-12)

    def locked(t, y):
        return y[0] - y[1]

    locked.terminal = True
    slipping = solve_ivp(lambda t, y: [(motor(y[0]) - capacity) / driving, (capacity - resisting) / driven,
                                       capacity * (y[0] - y[1])],
                         (2.0, 10.0), [spun.y[0, -1], 0.0, 0.0], rtol=1e-12, atol=1e-12, events=locked)
    uniform = no_load / gear * (1.0 - resisting / (gear * 60.0))
    return slipping.t[-1], slipping.y[1, -1], slipping.y[2, -1], uniform


def test_a_machine_that_settles_to_a_uniform_turn_is_told_delta_0_not_the_start_ups_last_creep(tmp_path):
    motion, note = _run(tmp_path, CLUTCH_SCENE)
    lock, common, slip_energy, uniform = _clutch_run_of_my_own()
    assert abs(motion["clutch_locked_at"] - lock) < 1e-6
    assert abs(motion["clutch_common_speed"] - common) < 1e-6
    assert abs(motion["slip_energy"] - slip_energy) < 1e-5 * slip_energy
    # Constant Je, constant Mr, a motor whose torque depends on ω alone: ω is constant once it is periodic.
    assert motion["delta"] == 0.0
    assert motion["omega_max"] == motion["omega_min"]
    assert abs(motion["omega_max"] - uniform) < 1e-6 * uniform
    assert "δ = (ωmax − ωmin)/ωm = 0." in note
    assert "0.0000000" not in note


def test_the_plot_of_a_uniform_turn_does_not_stretch_its_creep_over_the_axis():
    # The scene's machine after the clutch has locked: Je + Jrot·u² + Jcl, started a hair below its uniform speed.
    gear, no_load = 14.0, 1500.0 * math.pi / 30.0
    motor = LinearMotor(stall_torque=60.0, no_load=no_load, gear_ratio=gear, rotor_inertia=0.03)
    machine = Machine(inertia=30.0 + 2.0, resisting=150.0)
    uniform = no_load / gear * (1.0 - 150.0 / (gear * 60.0))
    motion = simulate(machine, motor, start=Start(omega=0.9 * uniform))
    assert motion.steady is not None and motion.steady.delta == 0.0
    figure = motion_plot(motion, strings("en"))
    low, high = figure.axes[-1].get_ylim()
    # The axis spans a share of ω one can see, not the 10⁻⁹ the start-up leaves.
    assert (high - low) > 1e-3 * uniform
    assert low < uniform < high


def test_a_fluctuating_steady_turn_keeps_its_delta_against_my_own_integration(tmp_path):
    # The flywheel starter's press: Mr steps between two values; the Kloss motor through a gear.
    motion, _ = _run(tmp_path, '[scene]\ntitle = "Press"\n' + POWER_CYCLE_PRESS + (
        'motor = { kind = "kloss", power = 4000.0, overload = 2.2, synchronous_rpm = 1500, rated_rpm = 1440, '
        "gear_ratio = 14.4, rotor_inertia = 0.02 }\n"))
    synchronous, rated = 1500 * math.pi / 30, 1440 * math.pi / 30
    slip, overload, gear = 1 - rated / synchronous, 2.2, 14.4
    breakdown = overload * 4000.0 / rated
    critical = slip * (overload + math.sqrt(overload ** 2 - 1))

    def kloss(speed):
        s = 1 - speed / synchronous
        return 2 * breakdown / (s / critical + critical / s)

    mean = 100 * math.pi / 30
    light, heavy = 367.7 / mean, 3677 / mean
    excess = (light + 2 * heavy) / 3 - light
    inertia = excess * 2 * math.pi / 3 / (0.05 * mean ** 2) + 0.02 * gear ** 2
    # Turn by turn, each stretch of constant Mr on its own, to the 16th turn.
    t, state, speeds = 0.0, [0.0, 0.0], []
    for stretch in range(32):
        moment = light if stretch % 2 == 0 else heavy
        end = (stretch // 2) * 2 * math.pi + (2 * math.pi / 3 if stretch % 2 == 0 else 2 * math.pi)

        def reached(t, y, end=end):
            return y[0] - end

        reached.terminal = True
        part = solve_ivp(lambda t, y, m=moment: [y[1], (gear * kloss(gear * y[1]) - m) / inertia], (t, t + 30),
                         state, method="DOP853", rtol=1e-12, atol=1e-12, events=reached, dense_output=True)
        if stretch >= 30:
            speeds.append(part.sol(np.linspace(part.t[0], part.t[-1], 4001))[1])
        t, state = part.t[-1], list(part.y[:, -1])
    turn = np.concatenate(speeds)
    delta = (turn.max() - turn.min()) / ((turn.max() + turn.min()) / 2)
    assert abs(motion["delta"] - delta) < 1e-5 * delta
    assert abs(motion["omega_max"] - turn.max()) < 1e-6 * turn.max()
    assert abs(motion["omega_min"] - turn.min()) < 1e-6 * turn.min()


# A press known by its resisting torque alone, a triangle over its first half turn, driven by a straight-line motor.
TRIANGLE_SCENE = """[scene]
title = "Triangle"
[dynamics]
rpm = 100
inertia = 20.0
resisting_torque = [[0, 100.0], [90, 300.0], [180, 100.0], [360, 100.0]]
motor = { kind = "linear", points = [[1400, 20.0], [1450, 10.0]], gear_ratio = 14.5 }
"""


def _triangle(degrees):
    degrees %= 360.0
    return float(np.interp(degrees, [0.0, 90.0, 180.0, 360.0], [100.0, 300.0, 100.0, 100.0]))


def test_a_load_diagrams_vertices_are_corners_of_mr_not_splined_through():
    from graphplan import load_text
    from graphplan.machine_dynamics import MachineDynamics

    machine = MachineDynamics(load_text(TRIANGLE_SCENE)).machine
    for degrees in (0.5, 89.5, 90.5, 179.5, 180.5, 359.5, 45.0, 270.0):
        assert abs(machine.mr(math.radians(degrees), 10.0) - _triangle(degrees)) < 1e-9, degrees


def test_the_steady_turn_under_a_diagram_with_vertices_matches_my_own_integration(tmp_path):
    motion, _ = _run(tmp_path, TRIANGLE_SCENE)
    # Two points of the line: M0 = 20 + 0.2·1400 = 300 N·m at rest, none at 1500 rpm.
    gear, stall, no_load, inertia = 14.5, 300.0, 1500 * math.pi / 30, 20.0
    ends = (math.pi / 2, math.pi, 2 * math.pi)  # each stretch of the turn straight, integrated on its own
    t, state, speeds, times = 0.0, [0.0, 0.0], [], []
    for stretch in range(3 * 30):
        end = (stretch // 3) * 2 * math.pi + ends[stretch % 3]

        def reached(t, y, end=end):
            return y[0] - end

        reached.terminal = True
        part = solve_ivp(lambda t, y, end=end: [y[1], (gear * stall * (1 - gear * y[1] / no_load)
                                                       - _triangle(math.degrees(min(y[0], end - 1e-12)))) / inertia],
                         (t, t + 30), state, method="DOP853", rtol=1e-12, atol=1e-12, events=reached, dense_output=True)
        if stretch >= 3 * 29:
            speeds.append(part.sol(np.linspace(part.t[0], part.t[-1], 4001))[1])
            times.append(part.t[[0, -1]])
        t, state = part.t[-1], list(part.y[:, -1])
    turn = np.concatenate(speeds)
    delta = (turn.max() - turn.min()) / ((turn.max() + turn.min()) / 2)
    assert abs(motion["delta"] - delta) < 1e-6 * delta
    assert abs(motion["omega_min"] - turn.min()) < 1e-7 * turn.min()
    assert abs(motion["omega_mean"] - 2 * math.pi / (times[-1][1] - times[0][0])) < 1e-7 * turn.min()


def test_kloss_torque_at_its_slips_is_the_textbooks():
    from graphplan.machine_motion import KlossMotor

    power, synchronous, slip, overload = 4000.0, 1000 * math.pi / 30, 0.05, 2.5
    motor = KlossMotor(power, synchronous, slip, overload)
    rated = power / (synchronous * (1 - slip))
    critical = slip * (overload + math.sqrt(overload ** 2 - 1))
    for s in (1.0, 0.5, critical, 0.1, slip, 0.01, -0.02):
        mine = 2 * overload * rated / (s / critical + critical / s)
        assert abs(motor.characteristic(synchronous * (1 - s)) - mine) < 1e-12 * overload * rated, s
    assert abs(motor.characteristic(synchronous * (1 - slip)) - rated) < 1e-12 * rated
    assert abs(motor.characteristic(synchronous * (1 - critical)) - overload * rated) < 1e-12 * rated
    assert motor.characteristic(synchronous) == 0.0


def close(value):
    return pytest.approx(value, rel=1e-9)


def _response(mass, unbalance, stiffness, damping, omega, base):
    """The machine's steady motion as complex amplitudes of e^{iωt}: M·x″ + c·(x′ − y′) + k·(x − y) = m·e·ω²."""
    receptance = 1 / (stiffness - mass * omega ** 2 + 1j * damping * omega)
    return unbalance * omega ** 2 * receptance, (stiffness + 1j * damping * omega) * base * receptance


def test_vibration_on_a_moving_base_with_isolation_matches_the_closed_forms(tmp_path):
    from scipy.optimize import brentq

    scene = tmp_path / "scene.toml"
    for mass, unbalance, stiffness, zeta, rpm, base, wanted in ((250.0, 0.05, 4e5, 0.075, 1200.0, 5e-4, 0.1),
                                                                 (100.0, 0.02, 1e5, 0.3, 250.0, 1e-3, 0.4),
                                                                 (60.0, 0.01, 2e6, 0.02, 3000.0, 2e-4, 0.05)):
        scene.write_text(f"""[scene]\ntitle = "Mounts"\n[vibration]\nmass = {mass}\nunbalance = {unbalance}
stiffness = {stiffness}\ndamping_ratio = {zeta}\nrpm = {rpm}\nbase_amplitude = {base}\ntransmissibility = {wanted}
""", encoding="utf-8")
        out = tmp_path / f"out{rpm:g}"
        assert main(["run", str(scene), "--out", str(out)]) == 0
        found = json.loads((out / "results.json").read_text(encoding="utf-8"))["vibration"]
        omega = rpm * math.pi / 30
        damping = 2 * zeta * math.sqrt(stiffness * mass)
        by_unbalance, by_base = _response(mass, unbalance, stiffness, damping, omega, base)
        r = omega / math.sqrt(stiffness / mass)
        transmissibility = math.hypot(1, 2 * zeta * r) / math.hypot(1 - r * r, 2 * zeta * r)
        assert found["frequency_ratio"] == close(r)
        assert found["amplitude"] == close(abs(by_unbalance))
        assert found["phase_deg"] == close(-math.degrees(np.angle(by_unbalance)) % 360)
        assert found["magnification"] == close(mass * abs(by_unbalance) / unbalance)
        assert found["transmissibility"] == close(transmissibility)
        assert found["transmitted_force"] == close(abs((stiffness + 1j * damping * omega) * by_unbalance))
        moved = found["base_excitation"]
        assert moved["amplitude"] == close(abs(by_base))
        assert moved["phase_deg"] == close(-math.degrees(np.angle(by_base)) % 360)
        assert moved["relative_amplitude"] == close(abs(by_base - base))
        both = found["combined"]
        assert both["amplitude"] == close(abs(by_unbalance + by_base))
        assert both["transmitted_force"] == close(
            abs((stiffness + 1j * damping * omega) * (by_unbalance + by_base - base)))
        design = brentq(lambda q, z=zeta, tr=wanted: math.hypot(1, 2 * z * q) / math.hypot(1 - q * q, 2 * z * q) - tr,
                        math.sqrt(2) * 1.000001, 1e4, xtol=1e-14)
        assert found["isolation"]["frequency_ratio"] == close(design)
        assert found["isolation"]["stiffness"] == close(mass * (omega / design) ** 2)
        assert found["critical_speed"] == close(math.sqrt(stiffness / mass))


@pytest.mark.parametrize("planes", [None, [0.2], [0.0, 0.6]])
def test_the_balancing_corrections_close_the_force_and_the_couple_as_my_own_algebra_does(tmp_path, planes):
    masses = [(2.0, 0.1, 30.0, 0.0), (3.0, 0.08, 150.0, 0.1), (1.5, 0.12, 260.0, 0.3)]
    on_axis = planes is None  # a disc: every mass in one plane
    rows = ",\n".join(f"{{ mass = {m}, radius = {r}, angle = {a}" + ("" if on_axis else f", plane = {z}") + " }"
                      for m, r, a, z in masses)
    scene = tmp_path / "scene.toml"
    scene.write_text(f"[scene]\ntitle = \"Rotor\"\n[balancing]\nmasses = [{rows}]\ncorrection_radius = 0.09\n"
                     + ("" if on_axis else f"planes = {planes}\n"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    found = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["balancing"]
    products = [m * r * np.exp(1j * math.radians(a)) for m, r, a, _ in masses]
    force = sum(products)
    couple = 0.0 if on_axis else sum(p * z for p, (*_, z) in zip(products, masses, strict=True))
    if planes is None or len(planes) == 1:
        corrections = [-force]
    else:
        left, right = planes
        far = (-couple + force * left) / (right - left)
        corrections = [-force - far, far]
    for plane, correction in zip(found["planes"], corrections, strict=True):
        assert plane["mass_radius"] == close(abs(correction))
        assert plane["angle_deg"] == close(math.degrees(np.angle(correction)) % 360)
        assert plane["mass"] == close(abs(correction) / 0.09)
    left_over = 0.0 if on_axis else abs(couple + sum(c * z for c, z in zip(corrections, planes, strict=True)))
    assert found["residual"]["moment"] == pytest.approx(left_over, rel=1e-9, abs=1e-15)
