"""A student's machine-dynamics problems with no linkage, written from the docs alone: a press's and an engine's
flywheel from their moment diagrams, a start-up by an induction motor (Kloss) then a brake or a clutch, static and
dynamic balancing of a rotor, a machine on springs and a shaft's critical speed.  Every answer is worked out here
independently (closed forms; the equation of motion by scipy's solve_ivp) and compared with results.json; then the
slips a student makes (δ = 5 for 5 %, a transmissibility in per cent, angles in radians) and what they are told."""

from __future__ import annotations

import cmath
import json
import math
from pathlib import Path

import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from graphplan.cli import main

KLOSS = ('motor = { kind = "kloss", power = 4000.0, overload = 2.2, synchronous_rpm = 1500, rated_rpm = 1440, '
         'gear_ratio = 14.4, rotor_inertia = 0.02%s }\n')
MACHINE = """\
[scene]
title = "Start-up of a machine"
[dynamics]
rpm = 100
inertia = 12.0
resisting_torque = [[0, 200], [360, 200]]
"""


def run(tmp_path: Path, text: str, name: str = "scene") -> tuple[int, Path]:
    scene = tmp_path / f"{name}.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / name
    # The note and its drawings are left out to keep the file fast; results.json comes with any piece.
    only = ",".join(piece for piece in ("dynamics", "balancing", "vibration") if f"[{piece}]" in text)
    return main(["run", str(scene), "--out", str(out), "--only", only]), out


def results(tmp_path: Path, text: str, name: str = "scene") -> dict:
    status, out = run(tmp_path, text, name)
    assert status == 0
    return json.loads((out / "results.json").read_text(encoding="utf-8"))


def flywheel_inertia(delta_w: float, rpm: float, delta: float) -> float:
    return delta_w / ((rpm * math.pi / 30) ** 2 * delta)


def test_press_flywheel_from_a_stepped_resisting_diagram(tmp_path):
    found = results(tmp_path, """\
[scene]
title = "Punch press"
[dynamics]
rpm = 120
delta = 0.1
resisting_torque = [[0, 100], [90, 100], [90, 1500], [180, 1500], [180, 100], [360, 100]]
driving = "constant"
inertia = 2.0
""")["dynamics"]
    mean = (100 * 270 + 1500 * 90) / 360
    # Over the punching quarter turn the resistance outpulls the constant drive: the one excess area is ΔWmax.
    delta_w = (1500 - mean) * math.pi / 2
    assert found["delta_w_max"] == pytest.approx(delta_w, rel=1e-9)
    assert found["flywheel_inertia"] == pytest.approx(flywheel_inertia(delta_w, 120, 0.1) - 2.0, rel=1e-9)
    assert (found["omega_max_angle_deg"], found["omega_min_angle_deg"]) == (90.0, 180.0)


def test_engine_flywheel_from_a_driving_diagram_with_a_negative_stroke(tmp_path):
    found = results(tmp_path, """\
[scene]
title = "Engine"
[dynamics]
rpm = 1500
delta = 0.02
driving_torque = [[0, 0], [90, 600], [180, 0], [270, -100], [360, 0]]
resisting = "constant"
""")["dynamics"]
    mean = (600 * math.pi / 2 - 100 * math.pi / 2) / (2 * math.pi)
    assert -found["resisting_moment"][0] == pytest.approx(mean, rel=1e-9)
    # The drive stays above its mean only inside its first triangle, between the two crossings.
    crossing = mean / 600 * 90
    delta_w = 0.5 * (600 - mean) * math.radians(180 - 2 * crossing)
    assert found["delta_w_max"] == pytest.approx(delta_w, rel=1e-9)
    assert found["flywheel_inertia"] == pytest.approx(flywheel_inertia(delta_w, 1500, 0.02), rel=1e-9)


def kloss_on_the_shaft(omega: float) -> float:
    synchronous = 1500 * math.pi / 30
    rated_slip = 1 - 1440 / 1500
    rated_torque = 4000 / (synchronous * (1 - rated_slip))
    critical = rated_slip * (2.2 + math.sqrt(2.2 ** 2 - 1))
    slip = 1 - 14.4 * omega / synchronous
    if slip == 0:
        return 0.0  # the unloaded clutch half reaches the synchronous speed, where Kloss' torque vanishes
    return 14.4 * 2 * 2.2 * rated_torque / (slip / critical + critical / slip)


INERTIA = 12.0 + 0.02 * 14.4 ** 2


def start_up(until: float):
    return solve_ivp(lambda t, y: [(kloss_on_the_shaft(y[0]) - 200.0) / INERTIA], (0.0, until), [0.0],
                     method="LSODA", rtol=1e-11, atol=1e-12, dense_output=True)


def test_start_up_by_an_induction_motor_and_its_brake(tmp_path):
    motion = results(tmp_path, MACHINE + KLOSS % ", off_at = 5.0" + "brake = { torque = 300.0, at = 5.0 }\n")
    motion = motion["dynamics"]["motion"]
    solution = start_up(12.0)
    steady = solution.y[0, -1]
    assert motion["omega_mean"] == pytest.approx(steady, rel=1e-6)
    within_five_percent = brentq(lambda t: solution.sol(t)[0] - 0.95 * steady, 0.0, 12.0)
    assert motion["start_up_time"] == pytest.approx(within_five_percent, rel=1e-5)
    # Motor off and brake on at 5 s: the brake and the resistance stop it at a constant rate.
    assert motion["stopped_at"] == pytest.approx(5.0 + INERTIA * solution.sol(5.0)[0] / (200.0 + 300.0), rel=1e-6)


def test_start_up_through_a_clutch(tmp_path):
    motion = results(tmp_path, MACHINE + KLOSS % "" + "clutch = { torque = 500.0, engage_at = 1.0, inertia = 1.0 }\n"
                     "duration = 6.0\n")["dynamics"]["motion"]
    driving_half, torque = 1.0 + 0.02 * 14.4 ** 2, 500.0
    alone = solve_ivp(lambda t, y: [kloss_on_the_shaft(y[0]) / driving_half], (0.0, 1.0), [0.0], method="LSODA",
                      rtol=1e-11, atol=1e-12)

    def locked(t, y):
        return y[0] - y[1]
    locked.terminal = True
    slipping = solve_ivp(lambda t, y: [(kloss_on_the_shaft(y[0]) - torque) / driving_half, (torque - 200.0) / 12.0,
                                       torque * (y[0] - y[1])],
                         (1.0, 6.0), [alone.y[0, -1], 0.0, 0.0], method="LSODA", rtol=1e-11, atol=1e-12,
                         events=locked)
    assert motion["clutch_locked_at"] == pytest.approx(slipping.t[-1], rel=1e-6)
    assert motion["clutch_common_speed"] == pytest.approx(slipping.y[1, -1], rel=1e-6)
    assert motion["slip_energy"] == pytest.approx(slipping.y[2, -1], rel=1e-5)


def product(mass: float, radius: float, angle: float) -> complex:
    return mass * radius * cmath.exp(1j * math.radians(angle))


def test_dynamic_balancing_of_four_masses_in_two_planes(tmp_path):
    masses = [(2.0, 0.10, 0.0, 0.10), (3.0, 0.08, 90.0, 0.20), (1.5, 0.12, 210.0, 0.30), (2.5, 0.05, 300.0, 0.15)]
    rows = ",\n".join(f"{{ mass = {m}, radius = {r}, angle = {a}, plane = {z} }}" for m, r, a, z in masses)
    planes = results(tmp_path, f"""\
[scene]
title = "Rotor"
[balancing]
masses = [ {rows} ]
planes = [0.0, 0.4]
correction_radius = 0.1
""")["balancing"]["planes"]
    right = -sum(product(m, r, a) * z for m, r, a, z in masses) / 0.4
    left = -sum(product(m, r, a) for m, r, a, _ in masses) - right
    for plane, correction in zip(planes, (left, right), strict=True):
        assert plane["mass_radius"] == pytest.approx(abs(correction), rel=1e-9)
        assert plane["angle_deg"] == pytest.approx(math.degrees(cmath.phase(correction)) % 360, abs=1e-7)
        assert plane["mass"] == pytest.approx(abs(correction) / 0.1, rel=1e-9)


def test_static_balancing_of_a_disc(tmp_path):
    masses = [(2.0, 0.10, 0.0), (3.0, 0.08, 90.0), (1.5, 0.12, 210.0)]
    rows = ", ".join(f"{{ mass = {m}, radius = {r}, angle = {a} }}" for m, r, a in masses)
    (plane,) = results(tmp_path, f"[balancing]\nmasses = [ {rows} ]\ncorrection_radius = 0.15\n")["balancing"]["planes"]
    correction = -sum(product(*mass) for mass in masses)
    assert plane["mass_radius"] == pytest.approx(abs(correction), rel=1e-9)
    assert plane["angle_deg"] == pytest.approx(math.degrees(cmath.phase(correction)) % 360, abs=1e-7)


def transmissibility(ratio: float, zeta: float) -> float:
    return math.hypot(1, 2 * zeta * ratio) / math.hypot(1 - ratio ** 2, 2 * zeta * ratio)


def test_machine_on_springs_amplitude_transmissibility_and_isolation(tmp_path):
    found = results(tmp_path, """\
[vibration]
mass = 200.0
unbalance = 0.05
stiffness = 4.0e5
damping_ratio = 0.05
rpm = 900
transmissibility = 0.1
""")["vibration"]
    mass, unbalance, stiffness, zeta = 200.0, 0.05, 4.0e5, 0.05
    omega = 900 * math.pi / 30
    damping = 2 * zeta * math.sqrt(stiffness * mass)
    ratio = omega / math.sqrt(stiffness / mass)
    amplitude = unbalance * omega ** 2 / math.hypot(stiffness - mass * omega ** 2, damping * omega)
    assert found["amplitude"] == pytest.approx(amplitude, rel=1e-9)
    assert found["transmissibility"] == pytest.approx(transmissibility(ratio, zeta), rel=1e-9)
    assert found["transmitted_force"] == pytest.approx(transmissibility(ratio, zeta) * unbalance * omega ** 2,
                                                       rel=1e-9)
    isolating = brentq(lambda r: transmissibility(r, zeta) - 0.1, 1.5, 100.0, xtol=1e-14)
    assert found["isolation"]["stiffness"] == pytest.approx(mass * (omega / isolating) ** 2, rel=1e-8)


def test_critical_speed_of_a_shaft_with_a_disc_midway(tmp_path):
    found = results(tmp_path, """\
[vibration]
mass = 20.0
unbalanced_mass = 0.01
eccentricity = 0.05
shaft = { modulus = 2.1e11, diameter = 0.03, length = 0.8 }
rpm = 1500
""")["vibration"]
    stiffness = 48 * 2.1e11 * (math.pi * 0.03 ** 4 / 64) / 0.8 ** 3
    assert found["critical_speed"] == pytest.approx(math.sqrt(stiffness / 20.0), rel=1e-9)
    assert found["critical_speed_rpm"] == pytest.approx(math.sqrt(stiffness / 20.0) * 30 / math.pi, rel=1e-9)
    omega = 1500 * math.pi / 30
    assert found["amplitude"] == pytest.approx(0.01 * 0.05 * omega ** 2 / abs(stiffness - 20.0 * omega ** 2),
                                               rel=1e-9)


def refusal(tmp_path: Path, capsys, text: str) -> str:
    status, out = run(tmp_path, text)
    assert status == 2
    assert not out.exists()
    return capsys.readouterr().err


def test_delta_of_five_for_five_percent_is_refused_as_a_percentage(tmp_path, capsys):
    err = refusal(tmp_path, capsys, "[dynamics]\nrpm = 120\ndelta = 5\ndriving = \"constant\"\n"
                  "resisting_torque = [[0, 100], [90, 100], [90, 1500], [180, 1500], [180, 100], [360, 100]]\n")
    assert "dynamics.delta: must be < 2" in err
    assert "5 % is δ = 0.05" in err


def test_transmissibility_in_percent_is_refused_as_a_percentage(tmp_path, capsys):
    err = refusal(tmp_path, capsys, "[vibration]\nmass = 200.0\nunbalance = 0.05\nstiffness = 4.0e5\nrpm = 900\n"
                  "transmissibility = 10\n")
    assert "vibration.transmissibility: must be below 1" in err
    assert "10 % is TR = 0.1" in err


def test_dynamics_asked_of_a_rotor_names_the_table_it_lacks_not_a_mechanism(tmp_path, capsys):
    scene = tmp_path / "rotor.toml"
    scene.write_text("[balancing]\nmasses = [ { mass = 2.0, radius = 0.1, angle = 0.0 } ]\n", encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "dynamics"]) == 2
    err = capsys.readouterr().err
    # A load diagram alone gives the dynamics: no mechanism is missing, the [dynamics] table is.
    assert "--only[0]: 'dynamics' needs a [dynamics] table" in err
    assert "mechanism" not in err
    assert not (tmp_path / "out").exists()


RADIANS = """\
[balancing]
masses = [ { mass = 2.0, radius = 0.10, angle = 0.0 }, { mass = 3.0, radius = 0.08, angle = 1.5708 },
           { mass = 1.5, radius = 0.12, angle = 3.665 } ]
correction_radius = 0.15
"""


def test_angles_typed_in_radians_are_warned_of_on_the_console_in_the_results_and_in_the_note(tmp_path, capsys):
    scene = tmp_path / "rotor.toml"
    scene.write_text(RADIANS, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "balancing,note", "--locale", "ru"]) == 0
    printed = capsys.readouterr().out
    assert "warning: balancing: every mass's angle lies within 2π" in printed
    assert "as radians these are 0, 90, 210°" in printed
    (warning,) = json.loads((out / "results.json").read_text(encoding="utf-8"))["balancing"]["warnings"]
    assert warning["code"] == "angles-in-radians"
    note = (out / "note.md").read_text(encoding="utf-8")
    # The Russian note's decimal commas must not run into the list's separators.
    assert "в радианах они были бы 0; 90; 210°" in note
    assert "(0; 1,5708; 3,665)" in note


@pytest.mark.parametrize("angles", [(0.0, 90.0, 210.0), (0.0, 1.0, 5.0), (0.0, 7.5, 3.5)])
def test_angles_in_degrees_are_not_taken_for_radians(tmp_path, angles):
    rows = ", ".join(f"{{ mass = 2.0, radius = 0.1, angle = {angle} }}" for angle in angles)
    found = results(tmp_path, f"[balancing]\nmasses = [ {rows} ]\n")["balancing"]
    assert found["warnings"] == []


def test_rated_slip_in_percent_is_refused_as_a_percentage(tmp_path, capsys):
    err = refusal(tmp_path, capsys, MACHINE + 'motor = { kind = "kloss", power = 4000.0, overload = 2.2, '
                  'synchronous_rpm = 1500, rated_slip = 4, gear_ratio = 14.4 }\n')
    assert "dynamics.motor.rated_slip: must be between 0 and 1 (got 4.0)" in err
    assert "4 % is rated_slip = 0.04" in err


@pytest.mark.parametrize("key", ["brake = { torque = 300.0 }", "clutch = { torque = 500.0, inertia = 1.0 }"])
def test_a_brake_or_a_clutch_without_a_motor_is_told_what_asks_for_the_motor(tmp_path, capsys, key):
    err = refusal(tmp_path, capsys, MACHINE + key + "\n")
    asking = key.split(" ")[0]
    assert f"dynamics.motor: is required with dynamics.{asking}" in err
    assert "off_at" in err


def test_a_kloss_motor_whose_power_was_typed_in_kilowatts_is_told_so(tmp_path, capsys):
    text = MACHINE + KLOSS.replace("power = 4000.0", "power = 4.0") % ""
    assert main(["check", str(_written(tmp_path, text))]) == 0
    printed = capsys.readouterr().out
    assert "the machine does not start" in printed
    assert "power = 4 W: kilowatts typed for watts? (the scene's power is in W, 4 kW is power = 4000)" in printed


def test_a_motor_truly_too_weak_is_not_told_of_kilowatts(tmp_path, capsys):
    text = MACHINE.replace("[[0, 200], [360, 200]]", "[[0, 2000], [360, 2000]]") + KLOSS % ""
    assert main(["check", str(_written(tmp_path, text))]) == 0
    printed = capsys.readouterr().out
    assert "the machine does not start" in printed
    assert "kilowatts" not in printed


def _written(tmp_path: Path, text: str) -> Path:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    return scene
