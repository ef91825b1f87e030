"""[dynamics]' motor torques, rotor inertia, off_at, start speed, and the crank's speed the dynamics takes as its mean
speed, took any number: a torque of 1e-12 N·m stalled every machine and was told as the motor's weakness, an off_at
past the run's end switched nothing off, a start of 1e5 rad/s and a crank of 1e-3 rad/s sized and ran machines no
one builds.  Each is now refused beyond what machines have, at its key with its value; values near the bounds, every
fixture and test scene and the starters still load, and the flywheel starter runs."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from scene_texts import POWER_CYCLE_PRESS

from graphplan import scene
from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.starters import starter

# A press known by its resisting power, driven through a gear by a motor: the flywheel starter's numbers.
PRESS = "\n" + POWER_CYCLE_PRESS + "{extra}\n[dynamics.motor]\n{motor}\n"
KLOSS = {"kind": '"kloss"', "power": "4000.0", "overload": "2.2", "synchronous_rpm": "1500", "rated_rpm": "1440",
         "gear_ratio": "14.4", "rotor_inertia": "0.02"}
LINEAR = {"kind": '"linear"', "stall_torque": "600.0", "no_load_rpm": "1500", "gear_ratio": "14.4"}
CONSTANT = {"kind": '"constant"', "torque": "30.0", "gear_ratio": "14.4"}
MEAN_OMEGA = 100 * math.pi / 30  # the press's rpm = 100 in rad/s


def _press(motor: dict[str, str], extra: str = "", **changed: str | None) -> str:
    keys = {**motor, **changed}
    return PRESS.format(extra=extra, motor="\n".join(f"{key} = {value}" for key, value in keys.items()
                                                     if value is not None))


def _refusal(text: str) -> str:
    with pytest.raises(SceneError) as refused:
        scene.loads(text)
    return str(refused.value)


# --- the motor's torques ------------------------------------------------------------------------------------------

TORQUE_BOUNDS = ("must be within 1e-06–1e+08 N·m, as motors drive machines (a watch's stepper some micronewton-metres, "
                 "a 4 kW induction motor some 26 N·m, a grinding mill's ring motor some 10 MN·m)")


@pytest.mark.parametrize(("motor", "key", "value", "hint"), [
    (CONSTANT, "torque", "1e-12", "; a slip of the exponent?"),
    (CONSTANT, "torque", "3e8", "; N·mm typed for N·m? (the scene's torques are in N·m: 3e+08 N·mm is 300000 N·m)"),
    (CONSTANT, "torque", "1e12", "; a slip of the exponent?"),
    (LINEAR, "stall_torque", "1e-10", "; a slip of the exponent?"),
    (LINEAR, "stall_torque", "5e-7", ""),
    (LINEAR, "stall_torque", "6e10", "; N·mm typed for N·m? (the scene's torques are in N·m: 6e+10 N·mm is 6e+07 N·m)"),
])
def test_a_motor_torque_no_motor_gives_is_refused_at_its_key(motor, key, value, hint):
    expected = f"dynamics.motor.{key}: {TORQUE_BOUNDS} (got {float(value)!r}){hint}"
    assert _refusal(_press(motor, **{key: value})) == expected


@pytest.mark.parametrize("torque", ["0.0", "-30.0"])
def test_a_constant_motor_driving_nothing_or_backwards_is_refused(torque):
    assert _refusal(_press(CONSTANT, torque=torque)) == ("dynamics.motor.torque: must be > 0, the torque the motor "
                                                         "drives the machine with (a run-down with the motor off is "
                                                         f"off_at's) (got {float(torque)!r})")


@pytest.mark.parametrize(("motor", "key", "value"), [
    (CONSTANT, "torque", "2e-6"), (CONSTANT, "torque", "9e7"), (LINEAR, "stall_torque", "2e-6"),
    (LINEAR, "stall_torque", "9e7"),
])
def test_a_motor_torque_near_the_bounds_is_the_motors_torque_at_rest(motor, key, value):
    loaded = scene.loads(_press(motor, **{key: value})).dynamics.motion.motor
    assert loaded.characteristic(0.0) == float(value)


def test_a_linear_motors_points_giving_a_stall_torque_no_motor_has_are_refused_with_it():
    # The line through 6e10 N·m at rest and nought at 1500 rpm: its stall torque is the first point's.
    message = _refusal(_press(LINEAR, stall_torque=None, no_load_rpm=None, points="[[0.0, 6e10], [1500.0, 0.0]]"))
    assert message.startswith("dynamics.motor.points: gives a torque outside 1e-06–1e+08 N·m, as motors drive machines")
    assert "(their line gives 6e+10 N·m at rest, its stall torque) (got [[0.0, 60000000000.0], [1500.0, 0.0]])" \
        in message
    # 3e7 N·m at 750 rpm, half the no-load speed, puts the stall torque at twice it, 6e7: within the bounds.
    points = "[[750.0, 3e7], [1500.0, 0.0]]"
    assert scene.loads(_press(LINEAR, stall_torque=None, no_load_rpm=None, points=points)).dynamics.motion.motor \
        .stall_torque == pytest.approx(6e7, rel=1e-12)


def test_a_linear_motors_point_no_motor_has_is_refused_even_where_its_line_is_a_motors():
    # 60 N·m at rest and −4e10 N·m at 1e12 rpm: the line's no-load speed is 60·1e12/(4e10 + 60), some 1500 rpm, and
    # its stall torque 60 N·m, both a motor's; the second point is two exponents' slips.
    assert 60 * 1e12 / (4e10 + 60) == pytest.approx(1500, rel=1e-6)
    message = _refusal(_press(LINEAR, stall_torque=None, no_load_rpm=None, points="[[0.0, 60.0], [1e12, -4e10]]"))
    assert message == ("dynamics.motor.points[1]: must be within ±1000000 rpm and ±1e+08 N·m, the speeds motors turn "
                       "at and the torques they give (got [1000000000000.0, -40000000000.0]); a slip of the exponent?")


# --- the rotor's inertia ------------------------------------------------------------------------------------------

@pytest.mark.parametrize(("inertia", "hint"), [("2e8", ""), ("1e12", "; a slip of the exponent?")])
def test_a_rotor_inertia_no_motor_has_is_refused_at_its_key(inertia, hint):
    message = _refusal(_press(CONSTANT, rotor_inertia=inertia))
    assert message == ("dynamics.motor.rotor_inertia: must be at most 1e+08 kg·m², as motors' rotors are built (a 4 kW "
                       "induction motor's some 0.02, a megawatt one's some tens, a pumped-storage motor-generator's "
                       "some 1e7): it comes to the driving shaft times the gear ratio's square "
                       f"(got {float(inertia)!r}){hint}")


@pytest.mark.parametrize("inertia", ["0.0", "1e-12", "9e7"])
def test_a_rotor_inertia_within_the_bound_comes_to_the_shaft_times_the_gears_square(inertia):
    motor = scene.loads(_press(CONSTANT, rotor_inertia=inertia)).dynamics.motion.motor
    assert motor.reduced_inertia == pytest.approx(float(inertia) * 14.4 ** 2, rel=1e-12)


# --- off_at -------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("off_at", ["5.0", "7.5"])
def test_an_off_at_at_or_past_the_runs_end_is_refused_at_the_motors_key(off_at):
    message = _refusal(_press(KLOSS, extra="duration = 5.0", off_at=off_at))
    assert message == (f"dynamics.motor.off_at: is at or past the run's end, dynamics.duration = 5 s, so the motor is "
                       "never switched off: give an off_at below the duration to see the run-down, or leave it out "
                       f"(got {float(off_at)!r})")


def test_an_off_at_before_the_runs_end_is_kept():
    assert scene.loads(_press(KLOSS, extra="duration = 5.0", off_at="4.9")).dynamics.motion.motor_off_at == 4.9


def test_an_off_at_of_more_turns_than_a_run_integrates_is_refused_before_integrating():
    refused = scene.loads(_press(KLOSS, off_at="1e6")).machine_dynamics()
    with pytest.raises(SceneError) as told:
        refused.refuse()
    message = str(told.value)
    found = re.fullmatch(r"dynamics\.motor\.off_at: 1e\+06 s is some (\S+) turns at the running speed, (\S+) rad/s; "
                         r"a run integrates at most 100000 turns, and runs down once the motor is off: give an off_at "
                         r"of at most (\S+) s \(got 1000000\.0\)", message)
    assert found, message
    turns, speed, most = (float(group) for group in found.groups())
    # The motor runs the press near its rated 1440 rpm through the gear of 14.4: 100 rpm at the shaft.
    assert speed == pytest.approx(MEAN_OMEGA, rel=0.05)
    assert turns == pytest.approx(1e6 * speed / (2 * math.pi), rel=5e-3)
    assert most == pytest.approx(2 * math.pi * 100_000 / speed, rel=1e-2)
    # An off_at within the turns a run takes is let be.
    scene.loads(_press(KLOSS, off_at=f"{0.9 * most:g}")).machine_dynamics().refuse()


# --- the start's speed --------------------------------------------------------------------------------------------

@pytest.mark.parametrize(("start", "key", "bounds", "hint"), [
    ("{ omega = 2e4 }", "omega", "10472 rad/s (100000 rpm)", ""),
    ("{ rpm = 2e5 }", "rpm", "100000 rpm", ""),
    ("{ rpm = 1e12 }", "rpm", "100000 rpm", "; a slip of the exponent?"),
    ("{ omega = 0.0, driving_omega = 1e9 }", "driving_omega", "10472 rad/s (100000 rpm)", "; a slip of the exponent?"),
])
def test_a_start_faster_than_any_shaft_turns_is_refused_at_its_key(start, key, bounds, hint):
    clutch = "clutch = { torque = 500, engage_at = 0.1 }\n" if "driving" in key else ""
    message = _refusal(_press(KLOSS, extra=f"{clutch}start = {start}"))
    typed = float(start.split(f"{key} = ")[1].rstrip(" }"))
    assert message == (f"dynamics.start.{key}: must be at most {bounds}, as the driving shaft of a machine turns (a "
                       "press's some 10–100 rpm, an engine's up to some 10 000): the run starts the shaft at this "
                       f"speed (got {typed!r}){hint}")


def test_a_start_far_beyond_the_mean_speed_typed_in_rpm_is_refused_with_the_rpm_question():
    # 2900 rad/s, a 2-pole motor's rev/min, is 2900/10.472 = 277 times the press's 100 rpm.
    message = _refusal(_press(KLOSS, extra="duration = 1.0\nstart = { omega = 2900 }"))
    assert message.startswith(f"dynamics.start.omega: 2900 rad/s is {2900 / MEAN_OMEGA:.3g} times the machine's mean "
                              f"speed, {MEAN_OMEGA:.4g} rad/s (dynamics.rpm): a run starts from rest or runs down from "
                              "about its speed, and one from more than 200 times it is no machine's (got 2900.0); ")
    assert message.endswith("dynamics.start.omega = 2900 rad/s is 27693 rpm: a motor's speed in rev/min typed for "
                            "rad/s? 2900 rpm is 303.69 rad/s: write dynamics.start.rpm = 2900")


def test_a_start_far_beyond_the_mean_speed_in_rpm_is_told_in_rpm_without_the_question():
    message = _refusal(_press(KLOSS, extra="duration = 1.0\nstart = { rpm = 25000 }"))
    assert message == (f"dynamics.start.rpm: 2.5e+04 rpm ({25000 * math.pi / 30:.4g} rad/s) is 250 times the "
                       f"machine's mean speed, {MEAN_OMEGA:.4g} rad/s (dynamics.rpm): a run starts from rest or runs "
                       "down from about its speed, and one from more than 200 times it is no machine's (got 25000.0)")


def test_a_start_within_the_bound_of_the_mean_speed_is_read_as_typed():
    # 190 times the mean: a slip still, but one the run integrates over a short duration and the rpm warning asks.
    start = scene.loads(_press(KLOSS, extra=f"duration = 0.1\nstart = {{ omega = {190 * MEAN_OMEGA!r} }}")) \
        .dynamics.motion.start
    assert start.omega == pytest.approx(190 * MEAN_OMEGA, rel=1e-15)


# --- the crank's speed, where [dynamics] takes it as the mean speed -----------------------------------------------

def _shaper(driver_speed: str, dynamics_extra: str = "") -> str:
    text = starter("shaper", "en")
    assert "rpm     = -60.0" in text and "[dynamics]" in text
    return text.replace("rpm     = -60.0", driver_speed, 1).replace("[dynamics]", "[dynamics]\n" + dynamics_extra, 1)


@pytest.mark.parametrize(("speed", "key", "bounds", "hint"), [
    ("omega = 1e-3", "omega", "0.1047–10472 rad/s (1–100000 rpm)", ""),
    ("rpm = -0.5", "rpm", "1–100000 rpm", ""),
    ("rpm = 1e9", "rpm", "1–100000 rpm", "; a slip of the exponent?"),
])
def test_a_crank_speed_the_dynamics_takes_is_bounded_as_its_own_mean_speed(speed, key, bounds, hint):
    message = _refusal(_shaper(speed))
    assert message.startswith(f"driver.{key}: must be within {bounds}, as a shaft a flywheel evens out turns")
    typed = float(speed.split(" = ")[1])
    assert message.endswith("; dynamics gives no rpm or omega of its own and takes the crank's as the machine's mean "
                            f"speed (give dynamics.rpm for the machine's own) (got {typed!r}){hint}")


def test_a_crank_turned_slowly_for_its_plans_alone_is_let_be_where_the_dynamics_gives_its_own_speed():
    loaded = scene.loads(_shaper("omega = 1e-3", "rpm = 60.0"))
    assert loaded.driver.omega == 1e-3 and loaded.dynamics.omega == pytest.approx(2 * math.pi, rel=1e-15)


def _model_only(driver_speed: str) -> str:
    """The shaper with a [dynamics] of the equivalent model alone: no delta, no motor."""
    text = _shaper(driver_speed)
    head, dynamics = text.split("[dynamics]", 1)
    kept = [line for line in dynamics.split("\n") if not re.match(r"(delta|flywheel_shaft_rpm|motor|start|duration)\b",
                                                                    line)]
    return head + "[dynamics]" + "\n".join(kept)


def test_a_crank_turned_slowly_is_let_be_where_the_dynamics_gives_only_the_equivalent_model():
    # Je = Σ m·(vS/ω1)² + JS·(ω/ω1)² and Me = Σ F·v·cos α/ω1 are ratios of speeds: no mean speed enters them.
    loaded = scene.loads(_model_only("omega = 1e-3"))
    assert loaded.dynamics.delta is None and loaded.dynamics.motion is None and loaded.driver.omega == 1e-3


def test_a_crank_speed_a_motor_alone_runs_about_is_refused_without_a_flywheel_in_the_words():
    text = _model_only("omega = 1e-3").replace("[dynamics]", "[dynamics]\nmotor = { kind = \"constant\", torque = 5.0 }"
                                                 "\nduration = 1.0", 1)
    message = _refusal(text)
    assert message.startswith("driver.omega: must be within 0.1047–10472 rad/s (1–100000 rpm)")
    assert "the equation of motion runs the motor through its gear about it" in message
    assert "delta" not in message.split("(got")[0]


def test_a_start_far_beyond_the_cranks_speed_is_told_against_the_crank():
    # The crank turns at 60 rpm, 2π rad/s: a start of 1450 rad/s is 1450/2π = 231 times it.
    message = _refusal(_shaper("rpm     = -60.0", "duration = 1.0\nstart = { omega = 1450 }"))
    assert message.startswith(f"dynamics.start.omega: 1450 rad/s is {1450 / (2 * math.pi):.3g} times the machine's "
                              "mean speed, 6.283 rad/s (driver.rpm)")


# --- what must still load and run ---------------------------------------------------------------------------------

@pytest.mark.parametrize("path", sorted(Path("fixtures").glob("*.toml")) + sorted(Path("tests/scenes").glob("*.toml")),
                         ids=str)
def test_every_fixture_and_test_scene_still_loads(path):
    scene.load(path)


@pytest.mark.parametrize("kind", ["flywheel", "shaper", "slider-crank", "crank-rocker", "slotted-lever", "triad",
                                  "rotor"])
def test_every_starter_still_loads(kind):
    scene.loads(starter(kind, "en"))


def test_the_flywheel_starter_written_by_new_still_runs(tmp_path, capsys):
    written = tmp_path / "flywheel.toml"
    assert main(["new", "flywheel", "--out", str(written)]) == 0
    assert main(["run", str(written), "--out", str(tmp_path / "out"), "--only", "dynamics"]) == 0
    assert "error" not in capsys.readouterr().err


# --- a rotor's inertia in kg·cm², told by the time the motor takes to run its own rotor up ---------------------------

def _warnings(tmp_path, capsys, text: str) -> list[str]:
    scene_file = tmp_path / "press.toml"
    scene_file.write_text('[scene]\ntitle = "Press"\n' + text, encoding="utf-8")
    capsys.readouterr()
    assert main(["check", str(scene_file)]) == 0
    return [line for line in capsys.readouterr().out.splitlines() if line.startswith("warning: ")]


def _told_of_the_scene(text: str) -> list[str]:
    """The warnings ``check`` prints of the press as the scene gives it, without the outcomes of its motion (a
    stall), which it integrates first: a rotor that runs up for a minute takes that motion many seconds to settle,
    and no outcome is a line about the rotor's inertia (the Kloss motor's test above reads ``check`` itself)."""
    from graphplan.deliverables import chosen, outcome_warnings

    press = scene.loads('[scene]\ntitle = "Press"\n' + text)
    return outcome_warnings(press, chosen(press, None), None)


def _run_up(line: str) -> float:
    return float(re.search(r"takes the motor ([0-9.e+]+) s to run its own rotor up", line).group(1))


def test_a_kloss_motors_rotor_in_kg_cm2_is_asked_of_by_its_run_up_time(tmp_path, capsys):
    # The rotor alone at the rated torque: ωN = 1440 rpm, MN = P/ωN, t = J·ωN/MN = 200·150.80/26.526 = 1137 s.
    rated = 1440 * math.pi / 30
    seconds = 200.0 * rated / (4000.0 / rated)
    (line,) = [line for line in _warnings(tmp_path, capsys, _press(KLOSS, rotor_inertia="200.0"))
               if "rotor_inertia" in line]
    assert _run_up(line) == pytest.approx(seconds, rel=1e-3)
    assert line.endswith("kg·cm² typed for kg·m²? (200 kg·cm² is dynamics.motor.rotor_inertia = 0.02)")
    # As given, 0.02 kg·m², the rotor runs up in 0.11 s: nothing to ask.
    assert not [line for line in _warnings(tmp_path, capsys, _press(KLOSS)) if "rotor_inertia" in line]


@pytest.mark.parametrize(("inertia", "told"), [(300.0, True), (200.0, False)])
def test_a_linear_motors_rotor_is_weighed_at_its_stall_torque_and_no_load_speed(inertia, told):
    # t = J·ω0/M0 with ω0 = 1500 rpm and M0 = 600 N·m: 78.5 s for 300 kg·m², over the 60 s; 52.4 s for 200, under.
    seconds = inertia * (1500 * math.pi / 30) / 600.0
    assert (seconds > 60.0) == told
    lines = [line for line in _told_of_the_scene(_press(LINEAR, rotor_inertia=repr(inertia))) if "rotor_inertia" in line]
    assert [_run_up(line) == pytest.approx(seconds, rel=1e-3) for line in lines] == ([True] if told else [])


@pytest.mark.parametrize(("inertia", "told"), [(200.0, True), (10.0, False)])
def test_a_constant_motors_rotor_is_weighed_at_its_torque_and_the_machines_speed_through_its_gear(inertia, told):
    """A constant torque has no speed of its own, and its rotor in kg·cm² passed with no word: it runs at the
    press's 100 rpm times the gear's 14.4.  t = J·u·ωm/M: 1005 s for 200 kg·m² at 30 N·m, 50.3 s for 10."""
    seconds = inertia * 14.4 * MEAN_OMEGA / 30.0
    assert (seconds > 60.0) == told
    lines = [line for line in _told_of_the_scene(_press(CONSTANT, rotor_inertia=repr(inertia)))
             if "rotor_inertia" in line]
    assert [_run_up(line) == pytest.approx(seconds, rel=1e-3) for line in lines] == ([True] if told else [])
    if told:
        assert lines[0].endswith(f"kg·cm² typed for kg·m²? ({inertia:g} kg·cm² is dynamics.motor.rotor_inertia = "
                                 f"{inertia / 1e4:g})")


def test_a_constant_motors_rotor_is_weighed_at_the_cranks_speed_where_the_dynamics_give_none():
    # The crank-rocker starter with a [dynamics] table of no speed of its own: the crank's |ω1| is the mean.
    from graphplan.deliverables import outcome_warnings

    text = starter("crank-rocker", "en") + ('\n[dynamics]\ndelta = 0.05\n[dynamics.motor]\nkind = "constant"\n'
                                            "torque = 5.0\ngear_ratio = 10.0\nrotor_inertia = 100.0\n")
    machine = scene.loads(text)
    assert machine.dynamics.omega is None
    lines = [line for line in outcome_warnings(machine, ("dynamics",), None) if "rotor_inertia" in line]
    seconds = 100.0 * 10.0 * abs(machine.driver.omega) / 5.0
    assert [_run_up(line) == pytest.approx(seconds, rel=1e-3) for line in lines] == [True]


def test_a_kloss_motors_power_in_kilowatts_is_left_to_the_stall_not_blamed_on_its_rotor(tmp_path, capsys):
    # power = 4 for 4 kW: the rotor takes 1000 times its 0.11 s, 114 s, which the kilowatts explain alone.
    lines = _warnings(tmp_path, capsys, _press(KLOSS, power="4.0"))
    assert not [line for line in lines if "rotor_inertia" in line]
    assert sum("kilowatts typed for watts?" in line for line in lines) == 1


def test_a_sub_kilowatt_kloss_motors_rotor_in_kg_cm2_is_asked_of_with_its_power_too():
    # 750 W at 1440 rpm: MN = 750/150.80 = 4.9736 N·m; J = 20 (kg·cm² meant) takes 20·150.80/4.9736 = 606 s, which
    # a power in kilowatts (750 kW, 0.606 s) would explain as well as a rotor in kg·cm² (0.002 kg·m², 0.061 s).
    # The scene as read, before any stall can tell of kilowatts: both are asked, neither left unsaid.
    rated = 1440 * math.pi / 30
    seconds = 20.0 * rated / (750.0 / rated)
    (line,) = [line for line in _told_of_the_scene(_press(KLOSS, power="750.0", rotor_inertia="20.0"))
               if "rotor_inertia" in line]
    assert _run_up(line) == pytest.approx(seconds, rel=1e-3)
    assert "(20 kg·cm² is dynamics.motor.rotor_inertia = 0.002)" in line
    assert line.endswith("; or dynamics.motor.power = 750 W typed in kilowatts? (750 kW is dynamics.motor.power = "
                         "750000)")
    # A 4 kW motor's rotor in kg·cm² is no question of its power.
    (line,) = [line for line in _told_of_the_scene(_press(KLOSS, rotor_inertia="200.0")) if "rotor_inertia" in line]
    assert "kilowatts" not in line
