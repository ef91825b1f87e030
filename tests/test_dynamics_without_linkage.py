"""A flywheel sized from a load diagram alone: a ``[dynamics]`` table with no [frame] and no [driver].

The press is the shaper of Sun Huan et al., *机械原理* (exercise of the chapter 机械的运转及其速度波动的调节;
see docs/sources/flywheel.md §1): 367.7 W over the 120° idle stroke, 3677 W over the rest, n = 100 rpm,
δ = 0.05, driven at constant power.  Printed: P = 2573.9 W, ΔWmax = 441.24 J, JF = 80.473 kg·m², and
0.388 kg·m² on the 1440 rpm motor shaft.  tests/test_flywheel.py checks the same numbers in code; here
they come out of a scene run through the command line.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from console import without_progress
from scene_texts import POWER_CYCLE_PRESS
from sheet_texts import flat

from graphplan.cli import main
from graphplan.dynamics import diagram_model

ROOT = Path(__file__).resolve().parent.parent
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"

PRESS = ('[scene]\ntitle = "Flywheel of a punching press from its power cycle"\n' + POWER_CYCLE_PRESS
         + "flywheel_shaft_rpm = 1440\n")


def run(tmp_path: Path, text: str) -> tuple[int, Path]:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    return main(["run", str(scene), "--out", str(out)]), out


def dynamics_of(tmp_path: Path, text: str) -> dict:
    status, out = run(tmp_path, text)
    assert status == 0
    return json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]


def test_press_flywheel_from_its_power_cycle_matches_the_published_answers(tmp_path):
    found = dynamics_of(tmp_path, PRESS)
    assert round(found["delta_w_max"], 2) == 441.24
    assert round(found["flywheel_inertia"], 3) == 80.473
    assert round(found["flywheel_inertia_moved"], 3) == 0.388
    # The driving side is the constant that balances the cycle: the motor's mean power.
    assert found["constant"] == "driving"
    assert round(found["driving_moment"][0] * found["omega_mean"], 1) == 2573.9
    # A constant Je: the three methods are one, and the speed swings by δ about ωm.
    assert found["flywheel_inertia_approximate"] == pytest.approx(found["flywheel_inertia"], rel=1e-12)
    assert found["flywheel_inertia_mertsalov"] == pytest.approx(found["flywheel_inertia"], rel=1e-12)
    omega = 100 * math.pi / 30
    assert found["omega_max"] == pytest.approx(omega * 1.025, rel=1e-9)
    assert found["omega_min"] == pytest.approx(omega * 0.975, rel=1e-9)
    assert found["omega_max_angle_deg"] == pytest.approx(120.0)   # the end of the idle stroke
    assert found["driver_link"] is None


@pytest.mark.parametrize("towards", [0.0, math.inf])
def test_the_slowest_instant_is_the_start_of_the_cycle_whichever_way_rounding_falls(tmp_path, towards):
    """The speed is lowest where the punching ends and the idle stroke begins: at 0°, which the cycle's last sample
    repeats as 360°.  A speed a last bit off 100 rpm must not move it from the one to the other."""
    omega = math.nextafter(100 * math.pi / 30, towards)
    found = dynamics_of(tmp_path, PRESS.replace("rpm = 100", f"omega = {omega!r}"))
    assert found["omega_min_angle_deg"] == 0.0 and found["omega_min_travel_deg"] == 0.0
    assert found["omega_max_travel_deg"] == pytest.approx(120.0)


def test_the_machines_own_inertia_is_taken_off_the_flywheel(tmp_path):
    found = dynamics_of(tmp_path, PRESS.replace("inertia = 0.0", "inertia = 30.0"))
    assert found["flywheel_inertia"] == pytest.approx(441.24 / ((100 * math.pi / 30) ** 2 * 0.05) - 30.0, rel=1e-9)


def test_a_constant_je_gives_one_flywheel_with_no_energy_mass_diagram_named(tmp_path):
    """With no linkage Je is the machine's own and constant: the note and the drawing named the energy–mass
    diagram and its segment ab, which are not drawn, for a JF that is ΔWmax/(ωm²·δ) − Je exactly."""
    status, out = run(tmp_path, PRESS.replace("inertia = 0.0", "inertia = 30.0"))
    assert status == 0
    expected = 441.24 / ((100 * math.pi / 30) ** 2 * 0.05) - 30.0
    note = (out / "note.md").read_text(encoding="utf-8")
    assert re.search(r"with Je = 30 kg·m² the same all the cycle, JF = ΔWmax/\(ωm²·δ\) − Je = [\d.]+/\([\d.]+²·0\.05\) "
                     r"− 30 = ([\d.]+) kg·m², exactly", note)
    written = float(re.search(r"− 30 = ([\d.]+) kg·m², exactly", note)[1])
    assert written == pytest.approx(expected, rel=5e-5)
    drawing = flat((out / "dynamics.svg").read_text(encoding="utf-8"))
    assert "ab·μT" not in drawing and "energy–mass" not in drawing and "(Je constant)" in drawing
    assert "energy–mass diagram, with Je variable" not in note


def test_the_same_cycle_as_a_torque_diagram(tmp_path):
    omega = 100 * math.pi / 30
    low, high = 367.7 / omega, 3677.0 / omega
    text = PRESS.replace("resisting_power = [[0, 367.7], [120, 367.7], [120, 3677], [360, 3677]]",
                         f"resisting_torque = [[0, {low!r}], [120, {low!r}], [120, {high!r}], [360, {high!r}]]")
    found = dynamics_of(tmp_path, text)
    assert found["delta_w_max"] == pytest.approx(441.24, rel=1e-10)


@pytest.mark.parametrize(("start", "end"), [(0.0, 90.0), (45.0, 200.0), (300.0, 360.0)])
def test_a_rectangular_resisting_torque_against_a_constant_drive(tmp_path, start, end):
    """M over a window of width β (rad) and 0 elsewhere, driven at the mean M·β/2π: the surplus is
    the area over the mean line inside the window, (M − M·β/2π)·β, in closed form."""
    torque, beta = 800.0, math.radians(end - start)
    points = [[0, 0.0], [start, 0.0], [start, torque], [end, torque], [end, 0.0], [360, 0.0]]
    points = [p for k, p in enumerate(points) if not (k and p == points[k - 1])]   # a window at 0 or 360
    text = (f"[dynamics]\nrpm = 60\ndelta = 0.1\nresisting_torque = {json.dumps(points)}\n")
    found = dynamics_of(tmp_path, text)
    expected = (torque - torque * beta / (2 * math.pi)) * beta
    assert found["delta_w_max"] == pytest.approx(expected, rel=1e-12)
    assert found["flywheel_inertia"] == pytest.approx(expected / ((2 * math.pi) ** 2 * 0.1), rel=1e-10)


def test_a_driving_diagram_whose_mean_falls_between_vertices():
    """A triangular driving torque (0 → T at 180° → 0) against a constant resistance T/2: the net
    crosses zero at 90° and 270°, between the vertices; the surplus from 90° to 270° is T·π/4."""
    peak = 1000.0
    model = diagram_model(10.0, driving=([0.0, math.pi, 2 * math.pi], [0.0, peak, 0.0]), count=12)
    assert model.constant == "resisting"
    assert np.ptp(model.energy) == pytest.approx(peak * math.pi / 4, rel=1e-12)
    assert model.imbalance == pytest.approx(0.0, abs=1e-9)


def test_both_sides_given_must_balance(tmp_path):
    text = ("[dynamics]\nrpm = 100\ndelta = 0.05\n"
            "resisting_torque = [[0, 10], [180, 10], [180, 30], [360, 30]]\n"
            "driving_torque = [[0, 20], [360, 20]]\n")
    found = dynamics_of(tmp_path, text)
    assert found["constant"] == "none"
    assert found["delta_w_max"] == pytest.approx(10.0 * math.pi, rel=1e-12)


def test_the_drawing_of_a_scene_without_a_linkage_renders(tmp_path):
    cairosvg = pytest.importorskip("cairosvg")
    status, out = run(tmp_path, PRESS)
    assert status == 0 and (out / "dynamics.svg").exists()
    png = cairosvg.svg2png(url=str(out / "dynamics.svg"))
    assert png.startswith(b"\x89PNG") and len(png) > 10_000


DIAGRAM = "resisting_power = [[0, 367.7], [120, 367.7], [120, 3677], [360, 3677]]"


@pytest.mark.parametrize(("change", "message"), [
    ((DIAGRAM, "resisting_power = [[0, 367.7]]"),
     "dynamics.resisting_power: must have at least two points"),
    ((DIAGRAM, "resisting_power = [[0, 367.7], [200, 367.7], [120, 3677], [360, 3677]]"),
     "dynamics.resisting_power[2]: crank angles must not fall"),
    ((DIAGRAM, "resisting_power = [[0, 367.7], [120, 367.7], [120, 3677], [400, 3677]]"),
     "dynamics.resisting_power: must run over the whole turn"),
    ((DIAGRAM, "resisting_power = [[-10, 367.7], [120, 367.7], [120, 3677], [360, 3677]]"),
     "dynamics.resisting_power: must run over the whole turn"),
    ((DIAGRAM, "resisting_power = [[0, 1], [120, 1], [120, 2], [120, 3], [360, 3]]"),
     "dynamics.resisting_power[3]: an angle may be given at most twice"),
    ((DIAGRAM, DIAGRAM + "\nresisting_torque = [[0, 1], [360, 1]]"),
     "dynamics.resisting_power: give resisting_torque or resisting_power, not both"),
    ((DIAGRAM + '\ndriving = "constant"', "driving_torque = [[0, -5], [360, -5]]"),
     "dynamics.driving_torque: does -"),
    # What the resistance takes is never negative, as a [[loads]] resisting diagram's value: its index is named.
    ((DIAGRAM, "resisting_power = [[0, 500], [200, -100], [360, 500]]"),
     "dynamics.resisting_power[1]: must be >= 0: a resisting diagram gives what the resistance takes (got -100)"),
    ((DIAGRAM, "resisting_torque = [[0, 5], [120, 5], [120, -0.5], [360, 3]]"),
     "dynamics.resisting_torque[2]: must be >= 0"),
    ((DIAGRAM, ""), "dynamics: needs a load diagram"),
    (("rpm = 100", "rpm = -100"), "dynamics.rpm: must be > 0"),
    (("rpm = 100", ""), "dynamics.omega: is required but missing: give omega (rad/s) or rpm (rev/min)"),
    (("delta = 0.05", "delta = 3"), "dynamics.delta: must be < 2"),
    (("inertia = 0.0", "inertia = -1.0"), "dynamics.inertia: must be >= 0"),
    (('driving = "constant"', 'driving = "motor"'), "dynamics.driving: must be one of constant"),
    (('driving = "constant"', 'resisting = "constant"'), "dynamics.resisting: says the resisting side is constant"),
    (('driving = "constant"', 'constant = "driving"'), "dynamics.constant: is for a linkage"),
    (('driving = "constant"', 'motor = { kind = "constant", torque = 50 }\nrtol = 2'), "dynamics.rtol: must be < 1"),
    # Without δ (nor the shaft its flywheel would be moved to) the machine's own inertia is all the motor turns.
    ((PRESS[PRESS.index("delta"):], PRESS[PRESS.index("resisting_power"):].replace(
        "flywheel_shaft_rpm = 1440", 'motor = { kind = "constant", torque = 50 }')),
     "dynamics.inertia: the equation of motion needs the machine's inertia"),
    (("delta = 0.05\n", ""), ("dynamics.flywheel_shaft_rpm: moves the flywheel sized for delta to another shaft, but no "
                              "delta is given")),
    ((DIAGRAM + '\ndriving = "constant"',
      'driving_torque = [[0, 10], [180, 30], [360, 10]]\nmotor = { kind = "constant", torque = 50 }'),
     "dynamics.motor: drives the machine in place of its driving side, so the resistance must be a diagram"),
    (('driving = "constant"', "driving_torque = [[0, 300], [360, 300]]"), "dynamics: the driving work"),
    ((DIAGRAM, DIAGRAM + "\ndriving_torque = [[0, 300], [360, 300]]"),
     "dynamics.driving: says the driving side is constant, but driving_torque gives its diagram"),
    (("inertia = 0.0", "inertia = 0.0\n[positions]\ncount = 12"), "positions: describes a mechanism"),
])
def test_bad_input_exits_2_naming_the_key_and_writes_nothing(tmp_path, capsys, change, message):
    old, new = change
    assert old in PRESS
    status, out = run(tmp_path, PRESS.replace(old, new))
    err = capsys.readouterr().err
    assert status == 2 and not out.exists()
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"graphplan: error: {message}"), err


def test_a_driving_diagram_may_go_negative_as_an_engine_s_compression_stroke_does(tmp_path):
    # The docs let a driving value be negative: an engine's torque over its compression stroke.  Its mean over the turn,
    # (−100 + 300)/2 = 100 N·m for the triangle, is the constant resisting moment that balances it.
    text = PRESS.replace(DIAGRAM + '\ndriving = "constant"',
                         'driving_torque = [[0, -100], [180, 300], [360, -100]]\nresisting = "constant"')
    found = dynamics_of(tmp_path, text)
    assert found["constant"] == "resisting"
    assert min(found["driving_moment"]) == pytest.approx(-100.0)
    assert found["resisting_moment"] == pytest.approx([-100.0] * len(found["resisting_moment"]), rel=1e-9)


def test_a_linkage_with_a_load_diagram_is_refused(tmp_path, capsys):
    text = RATCHET.read_text(encoding="utf-8") + "\n[dynamics]\ndelta = 0.05\n" + DIAGRAM + "\n"
    status, out = run(tmp_path, text)
    err = capsys.readouterr().err
    assert status == 2 and not out.exists()
    assert err.strip().splitlines() == [err.strip()]
    assert err.startswith("graphplan: error: dynamics.resisting_power: is for a scene without a linkage")


# --- the equation of motion of a machine known by its load diagram -------------------------------

MOTOR = 'motor = { kind = "linear", stall_torque = 2000, no_load_rpm = 110 }'


def test_the_press_runs_up_on_a_linear_motor_to_the_speed_where_the_mean_torques_balance(tmp_path):
    """The press's power cycle, as torques at its 100 rpm, driven by M = Ms·(1 − ω/ω0) through the flywheel
    sized for δ = 0.05.  Over a steady turn the work of the motor equals that of the resistance, so
    Ms·(1 − ω̄/ω0) = M̄r with ω̄ the angle-mean speed: the balance speed, to within the fluctuation's δ²."""
    found = dynamics_of(tmp_path, PRESS.replace("inertia = 0.0", "inertia = 0.0\n" + MOTOR))
    motion = found["motion"]
    stall, no_load = 2000.0, 110 * math.pi / 30
    mean_resisting = (367.7 / 3 + 3677.0 * 2 / 3) / (100 * math.pi / 30)
    balance = no_load * (1 - mean_resisting / stall)
    assert motion["omega_mean"] == pytest.approx(balance, rel=0.05 ** 2)
    assert motion["flywheel_inertia"] == pytest.approx(found["flywheel_inertia"], rel=1e-12)
    # The flywheel held δ = ΔWmax/(J·ω²) at the mean speed; the motor's slope also damps the swing.
    estimate = found["delta_w_max"] / (found["flywheel_inertia"] * motion["omega_mean"] ** 2)
    assert 0.9 * estimate < motion["delta"] < estimate
    assert 0 < motion["start_up_time"] < motion["steady_after"] < motion["duration"]


KLOSS = ('motor = { kind = "kloss", power = 4000.0, overload = 2.2, synchronous_rpm = 1500, rated_rpm = 1440, '
         'gear_ratio = 14.4, rotor_inertia = 0.02 }')


def test_the_steady_turn_at_the_default_tolerance_holds_the_four_digits_the_note_writes(tmp_path):
    """The press on an induction motor, integrated as a scene is by default, against the same run by DOP853 at
    rtol 1e-12 (the other method, four orders tighter): the steady ωm, ωmax, ωmin and δ agree within 1e-4, inside
    the fourth digit the note writes them to (at the old default, rtol 1e-6, δ was 4e-4 off)."""
    runs = {}
    for name, keys in (("default", ""), ("tight", 'method = "DOP853"\nrtol = 1e-12\n')):
        (tmp_path / name).mkdir()
        runs[name] = dynamics_of(tmp_path / name, PRESS.replace("inertia = 0.0", "inertia = 0.0\n" + keys + KLOSS))["motion"]
    assert runs["tight"]["method"] == "DOP853"
    for key in ("omega_mean", "omega_max", "omega_min", "delta"):
        assert runs["default"][key] == pytest.approx(runs["tight"][key], rel=1e-4), key


def test_without_a_flywheel_the_machines_own_inertia_carries_the_swing(tmp_path):
    """No δ: the machine runs on its own 200 kg·m², and the swing grows as that inertia is smaller."""
    text = PRESS.replace("delta = 0.05\n", "").replace("flywheel_shaft_rpm = 1440\n", "").replace(
        "inertia = 0.0", "inertia = 200.0\n" + MOTOR)
    found = dynamics_of(tmp_path, text)
    motion = found["motion"]
    assert motion["flywheel_inertia"] == 0.0
    estimate = found["delta_w_max"] / (200.0 * motion["omega_mean"] ** 2)
    assert 0.9 * estimate < motion["delta"] < estimate


@pytest.mark.parametrize("gear_ratio, warned", [(14.4, False), (12.0, True)])
def test_a_motor_that_settles_away_from_the_flywheel_s_speed_is_warned_of(tmp_path, capsys, gear_ratio, warned):
    """Geared 1440/12 the motor runs the press near 120 rpm where its flywheel was sized at 100: δ is then not
    the one asked for, and only a sentence of the note said so (a teacher's variants with a new rpm)."""
    text = PRESS.replace("inertia = 0.0", "inertia = 0.0\n" + KLOSS.replace("14.4", f"{gear_ratio}"))
    status, out = run(tmp_path, text)
    assert status == 0
    lines = [line for line in capsys.readouterr().out.splitlines() if line.startswith("warning: dynamics: the motor")]
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    sized = 100 * math.pi / 30
    assert (abs(motion["omega_mean"] / sized - 1) > 0.05) == warned
    assert len(lines) == warned
    if warned:
        # As the note writes them: ωm to five digits and δ to four, their noughts kept; the speed asked, 100 rpm.
        speed, delta = motion["omega_mean"], motion["delta"]
        assert f"ωm = {speed:.{4 - math.floor(math.log10(speed))}f} rad/s" in lines[0]
        assert f"the {sized:.5g} rad/s" in lines[0]
        assert f"δ = {delta:.{3 - math.floor(math.log10(delta))}f}" in lines[0]


# --- a student's own integrations of the press (solve_ivp in the test, closed forms) -------------

OMEGA_PRESS = 100 * math.pi / 30
# The press's resistance as torques at its 100 rpm: light over the idle 120°, heavy over the rest.
LIGHT, HEAVY = 367.7 / OMEGA_PRESS, 3677.0 / OMEGA_PRESS
MEAN_RESISTANCE = (LIGHT + 2.0 * HEAVY) / 3.0
# ΔWmax in closed form: the constant drive gains on the light stroke what the heavy one takes back.
DELTA_W_MAX = (MEAN_RESISTANCE - LIGHT) * 2.0 * math.pi / 3.0


def press_resistance(phi: float) -> float:
    return LIGHT if math.degrees(phi) % 360.0 < 120.0 else HEAVY


def steady_turn_by_solve_ivp(shaft_torque, inertia: float, end: float) -> tuple[float, float]:
    """(ωm = 2π/T, δ = (ωmax − ωmin)/((ωmax + ωmin)/2)) of the last whole turn of the press run up from rest on a
    shaft of constant ``inertia``, integrated here with scipy alone."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq

    run = solve_ivp(lambda t, y: [y[1], (shaft_torque(y[1]) - press_resistance(y[0])) / inertia], (0.0, end),
                    [0.0, 0.0], rtol=1e-10, atol=1e-12, max_step=2e-3, dense_output=True)
    turns = int(run.y[0, -1] / (2 * math.pi)) - 1
    begin, finish = (brentq(lambda t, k=k: run.sol(t)[0] - 2 * math.pi * k, 0.0, end) for k in (turns, turns + 1))
    omega = run.sol(np.linspace(begin, finish, 20001))[1]
    return 2 * math.pi / (finish - begin), (omega.max() - omega.min()) / ((omega.max() + omega.min()) / 2)


def test_only_the_rotor_is_reduced_by_the_gear_ratio_squared(tmp_path):
    """inertia = 50 kg·m² is on the press's own shaft: the shaft turns with 50 + JF + 0.02·14.4² kg·m², not with
    50·14.4²; a student's solve_ivp of that shaft gives ωm = 7.800 rad/s and δ = 0.0845."""
    motor = ('motor = { kind = "linear", stall_torque = 60.0, no_load_rpm = 1500, gear_ratio = 14.4, '
             'rotor_inertia = 0.02 }')
    found = dynamics_of(tmp_path, PRESS.replace("inertia = 0.0", "inertia = 50.0\n" + motor))
    flywheel = DELTA_W_MAX / (OMEGA_PRESS ** 2 * 0.05) - 50.0
    assert found["flywheel_inertia"] == pytest.approx(flywheel, rel=1e-9)
    no_load = 1500 * math.pi / 30
    mean, delta = steady_turn_by_solve_ivp(lambda w: 14.4 * 60.0 * (1 - 14.4 * w / no_load),
                                           50.0 + flywheel + 0.02 * 14.4 ** 2, 30.0)
    assert found["motion"]["omega_mean"] == pytest.approx(mean, rel=1e-4)
    assert found["motion"]["delta"] == pytest.approx(delta, rel=2e-3)


J100_DIRECT = PRESS.replace("inertia = 0.0", "inertia = 100.0\n"
                            'motor = { kind = "linear", stall_torque = 864.0, no_load_rpm = 104.1666666667 }')


def test_a_machine_heavier_than_its_flywheel_gets_none_and_turns_with_its_own_inertia(tmp_path):
    """100 kg·m² of its own where δ = 0.05 asks for 80.47: no flywheel is mounted (it was −19.53 in results.json
    and in the equation of motion), and the speed swings by the δ = ΔWmax/(J·ωm²) the machine has."""
    found = dynamics_of(tmp_path, J100_DIRECT)
    assert found["flywheel_inertia"] == 0.0
    assert found["flywheel_inertia_required"] == pytest.approx(DELTA_W_MAX / (OMEGA_PRESS ** 2 * 0.05) - 100.0,
                                                               rel=1e-9)
    reached = DELTA_W_MAX / (100.0 * OMEGA_PRESS ** 2)
    assert found["delta_reached"] == pytest.approx(reached, rel=1e-9)
    assert found["omega_max"] == pytest.approx(OMEGA_PRESS * (1 + reached / 2), rel=1e-9)
    assert found["omega_min"] == pytest.approx(OMEGA_PRESS * (1 - reached / 2), rel=1e-9)
    assert found["motion"]["flywheel_inertia"] == 0.0
    no_load = 104.1666666667 * math.pi / 30
    mean, delta = steady_turn_by_solve_ivp(lambda w: 864.0 * (1 - w / no_load), 100.0, 25.0)
    assert found["motion"]["omega_mean"] == pytest.approx(mean, rel=1e-4)
    assert found["motion"]["delta"] == pytest.approx(delta, rel=2e-3)
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert "JF = −19.527 kg·m² ≤ 0" in note and f"δ = {reached:.4f}" in note


FLAT = """\
[scene]
title = "A constant resistance"
[dynamics]
rpm = 100
delta = 0.05
resisting_torque = [[0, 245.789], [360, 245.789]]
driving = "constant"
inertia = 1.0
"""


def test_a_machine_with_no_fluctuation_turns_at_its_mean_speed_without_a_flywheel(tmp_path):
    found = dynamics_of(tmp_path, FLAT)
    assert found["flywheel_inertia"] == 0.0 and found["flywheel_inertia_required"] == pytest.approx(-1.0)
    assert found["delta_reached"] == 0.0
    assert found["omega_max"] == pytest.approx(OMEGA_PRESS, rel=1e-10)
    assert found["omega_min"] == pytest.approx(OMEGA_PRESS, rel=1e-10)


def test_a_constant_motor_against_a_constant_resistance_is_refused_as_a_runaway_not_for_its_inertia(tmp_path, capsys):
    """inertia = 1 was given: the −1 kg·m² flywheel no longer cancels it; 17.5·14.4 = 252 N·m > 245.79 N·m, the mean
    resistance to the note's five digits."""
    status, out = run(tmp_path, FLAT + 'motor = { kind = "constant", torque = 17.5, gear_ratio = 14.4 }\n')
    err = without_progress(capsys.readouterr().err).strip()
    assert status == 2 and not out.exists()
    assert err == (f"graphplan: error: dynamics.motor: its torque on the shaft, {17.5 * 14.4:.5g} N·m, exceeds the "
                   "mean resistance, 245.79 N·m, at every speed: the machine speeds up without end and has no "
                   "steady state; give a dynamics.duration (s), more resistance, or a motor whose torque falls with "
                   'speed (dynamics.motor kind = "linear" or "kloss")')


BORDER = f"""\
[scene]
title = "A motor just short of the mean resistance"
[dynamics]
rpm = 100
delta = 0.05
resisting_torque = [[0, {LIGHT!r}], [120, {LIGHT!r}], [120, {HEAVY!r}], [360, {HEAVY!r}]]
driving = "constant"
motor = {{ kind = "constant", torque = 17.0, gear_ratio = 14.4 }}
"""


def test_a_motor_below_the_exact_mean_resistance_stalls_rather_than_being_refused(tmp_path):
    """244.8 N·m against a mean of (M1 + 2·M2)/3 = 245.79 N·m (64 samples made it 242.5 and refused a runaway):
    from rest the press gains over the light 120° and loses over the heavy stroke; by the energy balance it stops
    where 244.8·φ = ∫Mr dφ, inside its first turn, which a solve_ivp of the same shaft confirms in time."""
    from scipy.integrate import solve_ivp

    found = dynamics_of(tmp_path, BORDER)["motion"]
    drive = 17.0 * 14.4
    stop = (2 * math.pi / 3 * (HEAVY - LIGHT)) / (HEAVY - drive)   # drive·φ = M1·2π/3 + M2·(φ − 2π/3)
    assert found["stalled_at_angle_deg"] == pytest.approx(math.degrees(stop), abs=1e-3)
    inertia = DELTA_W_MAX / (OMEGA_PRESS ** 2 * 0.05)
    stopped = solve_ivp(lambda t, y: [y[1], (drive - press_resistance(y[0])) / inertia], (0.0, 30.0), [0.0, 0.0],
                        rtol=1e-10, atol=1e-12, max_step=2e-3, events=lambda t, y: y[1] if t > 0.1 else 1.0)
    assert found["stalled_at"] == pytest.approx(float(stopped.t_events[0][0]), rel=1e-5)


def test_the_time_and_place_of_a_run_down_are_written(tmp_path):
    """Switched off at 10 s the press runs down: results.json and the note give when and where it comes to rest
    (12.3157 s by a student's solve_ivp, repeated here)."""
    from scipy.integrate import solve_ivp

    motor = ('motor = { kind = "linear", stall_torque = 60.0, no_load_rpm = 1500, gear_ratio = 14.4, '
             'rotor_inertia = 0.02, off_at = 10.0 }')
    found = dynamics_of(tmp_path, PRESS.replace("inertia = 0.0", "inertia = 0.0\n" + motor))
    motion = found["motion"]
    inertia = found["flywheel_inertia"] + 0.02 * 14.4 ** 2
    no_load = 1500 * math.pi / 30

    def torque(t, omega):
        return 14.4 * 60.0 * (1 - 14.4 * omega / no_load) if t < 10.0 else 0.0

    def at_rest(t, y):
        return y[1] if t > 10.0 else 1.0
    at_rest.terminal = True
    own = solve_ivp(lambda t, y: [y[1], (torque(t, y[1]) - press_resistance(y[0])) / inertia], (0.0, 30.0),
                    [0.0, 0.0], rtol=1e-10, atol=1e-12, max_step=2e-3, events=at_rest)
    assert motion["stopped_at"] == pytest.approx(float(own.t_events[0][0]), rel=1e-5)
    assert motion["stopped_at_angle_deg"] == pytest.approx(math.degrees(own.y_events[0][0][0]) % 360.0, abs=0.01)
    assert "stalled_at" not in motion
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert (f"The motor is switched off at t = 10 s: the machine runs down and comes to rest at "
            f"t = {motion['stopped_at']:.4g} s") in note


@pytest.mark.parametrize(("off_at", "message"), [
    ("-1", "dynamics.motor.off_at: must be >= 0 (got -1)"),
    ("0", "dynamics.motor.off_at: switches the motor off as a run from rest begins"),
])
def test_a_motor_switched_off_before_a_run_from_rest_is_refused(tmp_path, capsys, off_at, message):
    motor = f'motor = {{ kind = "constant", torque = 50, off_at = {off_at} }}'
    status, out = run(tmp_path, PRESS.replace("inertia = 0.0", "inertia = 0.0\n" + motor))
    err = capsys.readouterr().err.strip()
    assert status == 2 and not out.exists()
    assert len(err.splitlines()) == 1 and err.startswith(f"graphplan: error: {message}"), err


def test_a_motor_switched_off_at_the_start_runs_a_machine_down_from_its_starting_speed(tmp_path):
    """off_at = 0 with a start at speed is a run-down from that speed: with the constant resistance Mr and J, it
    stops at t = J·ω0/Mr."""
    text = FLAT + ('motor = { kind = "constant", torque = 17.0, gear_ratio = 14.4, off_at = 0 }\n'
                   "start = { omega = 10.0 }\n")
    motion = dynamics_of(tmp_path, text)["motion"]
    assert motion["stopped_at"] == pytest.approx(1.0 * 10.0 / 245.789, rel=1e-6)


def test_the_integrator_s_reason_sets_the_threshold_against_the_stiffness_number(tmp_path):
    motion = dynamics_of(tmp_path, BORDER)["motion"]
    assert re.search(r"= 0 ≤ 3\.0; cycle [\d.e+]+ s\): RK45$", motion["method_reason"]), motion["method_reason"]


def test_the_flywheel_s_new_shaft_speed_is_drawn_as_the_scene_gives_it_and_the_note_writes_it(tmp_path):
    """n′ = 1462.5 rpm: the note wrote 1462.5, the drawing 1462 (four digits, half to even)."""
    status, out = run(tmp_path, PRESS.replace("flywheel_shaft_rpm = 1440", "flywheel_shaft_rpm = 1462.5"))
    assert status == 0
    drawn = (out / "dynamics.svg").read_text(encoding="utf-8")
    assert "1462.5 rpm" in drawn and "1462 rpm" not in drawn
    assert "n′ = 1462.5 rpm" in (out / "note.md").read_text(encoding="utf-8")
    # JF′ = JF·(n/n′)²
    found = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]
    assert found["flywheel_inertia_moved"] == pytest.approx(found["flywheel_inertia"] * (100 / 1462.5) ** 2, rel=1e-9)
