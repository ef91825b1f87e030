"""[dynamics]' mean speed and the motor's gear ratio, power, speeds and slip took any positive number: rpm = 1e-12 sized
a flywheel 1e24 times the one at 1 rpm (it goes as 1/ωm²), a gear ratio of 1e12 left the shaft a turn in ages, and a
Kloss motor of 1e-12 W had no torque, and each ran without a word.  Each is now refused beyond what any machine has,
naming its key and the value; a real value near each bound still loads and, for the flywheel, is sized as
ΔWmax/(ωm²·δ) works it out by hand."""

from __future__ import annotations

import math

import pytest
from scene_texts import POWER_CYCLE_PRESS

from graphplan import scene
from graphplan.errors import SceneError
from graphplan.units import RPM

# A shaft known by its resisting torque alone: 100 N·m over the first half turn, 300 over the second, the driving
# torque constant at their mean, 200.  The surplus work rises by 100·π over the first half and falls back over the
# second, so ΔWmax = 100·π J, and with no inertia of its own the flywheel is ΔWmax/(ωm²·δ).
SHAFT = """
[dynamics]
{speed}
delta = 0.05
resisting_torque = [[0, 100], [180, 100], [180, 300], [360, 300]]
driving = "constant"
inertia = 0.0
"""
DELTA_W_MAX = 100.0 * math.pi

# A press known by its resisting power, driven through a gear by a Kloss motor: the flywheel starter's numbers.
PRESS = "\n" + POWER_CYCLE_PRESS + "[dynamics.motor]\n{motor}\n"
KLOSS = {"kind": '"kloss"', "power": "4000.0", "overload": "2.2", "synchronous_rpm": "1500", "rated_rpm": "1440",
         "gear_ratio": "14.4"}
LINEAR = {"kind": '"linear"', "stall_torque": "60.0", "no_load_rpm": "1500", "gear_ratio": "14.4",
          "rotor_inertia": "0.02"}


def _press(motor: dict[str, str], **changed: str) -> str:
    keys = {**motor, **changed}
    return PRESS.format(motor="\n".join(f"{key} = {value}" for key, value in keys.items() if value is not None))


def _refusal(text: str) -> str:
    with pytest.raises(SceneError) as refused:
        scene.loads(text)
    return str(refused.value)


@pytest.mark.parametrize(("speed", "key", "shown"), [
    ("rpm = 1e-12", "rpm", "must be within 1–100000 rpm"),
    ("rpm = 0.5", "rpm", "must be within 1–100000 rpm"),
    ("rpm = 2e5", "rpm", "must be within 1–100000 rpm"),
    ("omega = 1e-12", "omega", "must be within 0.1047–10472 rad/s (1–100000 rpm)"),
    ("omega = 2e4", "omega", "must be within 0.1047–10472 rad/s (1–100000 rpm)"),
])
def test_a_mean_speed_no_flywheel_turns_at_is_refused_at_its_key(speed, key, shown):
    message = _refusal(SHAFT.format(speed=speed))
    typed = speed.split(" = ")[1]
    assert message.startswith(f"dynamics.{key}: {shown}")
    assert f"(got {float(typed)!r})" in message


def test_a_mean_speed_far_beyond_is_asked_about_its_exponent_and_the_flywheel_it_would_give():
    message = _refusal(SHAFT.format(speed="rpm = 1e-12"))
    # The flywheel goes as 1/ωm²: at 1e-12 rpm, (1/1e-12)² times the one at 1 rpm.
    assert "1e+24 times the one at 1 rpm" in message
    assert message.endswith("; a slip of the exponent?")
    assert "exponent" not in _refusal(SHAFT.format(speed="rpm = 0.5"))


@pytest.mark.parametrize("speed", ["rpm = 1.5", "omega = 0.15", "rpm = 90000"])
def test_a_mean_speed_near_the_bounds_sizes_the_flywheel_as_worked_by_hand(speed):
    key, typed = speed.split(" = ")
    omega = float(typed) * (RPM if key == "rpm" else 1.0)
    flywheel = scene.loads(SHAFT.format(speed=speed)).machine_dynamics().flywheel
    assert flywheel.inertia == pytest.approx(DELTA_W_MAX / (omega ** 2 * 0.05), rel=1e-6)


@pytest.mark.parametrize("ratio", ["1e12", "1e-12", "200000", "0.0005"])
def test_a_gear_ratio_no_gear_has_is_refused_at_its_key(ratio):
    message = _refusal(_press(KLOSS, gear_ratio=ratio))
    assert message.startswith("dynamics.motor.gear_ratio: must be within 0.001–100000, the motor's speed over the "
                              "driving shaft's")
    assert f"(got {float(ratio)!r})" in message
    assert message.endswith("a slip of the exponent?") == (ratio in ("1e12", "1e-12"))


@pytest.mark.parametrize("ratio", ["0.002", "50000"])
def test_a_gear_ratio_near_the_bounds_still_loads_as_typed(ratio):
    motor = scene.loads(_press(KLOSS, gear_ratio=ratio)).dynamics.motion.motor
    assert motor.gear_ratio == float(ratio)


@pytest.mark.parametrize(("power", "hint"), [
    ("1e-12", "; a slip of the exponent?"),
    ("0.75", "; kilowatts typed for watts? (the scene's power is in W, 0.75 kW is power = 750)"),
    ("2e9", ""),
])
def test_a_kloss_motor_of_a_power_no_motor_has_is_refused_at_its_key(power, hint):
    message = _refusal(_press(KLOSS, power=power))
    assert message == (f"dynamics.motor.power: must be within 1 W–1000 MW, as induction motors are built (a fan's "
                       "some watts, a rolling mill's some tens of megawatts): Kloss' torques are in proportion to it "
                       f"(got {float(power)!r}){hint}")


@pytest.mark.parametrize("power", ["1.5", "5e8"])
def test_a_kloss_motors_power_near_the_bounds_gives_its_rated_torque(power):
    motor = scene.loads(_press(KLOSS, power=power)).dynamics.motion.motor
    # The rated torque is P/ωN, ωN the rated speed, 1440 rpm.
    assert motor.characteristic(1440 * RPM) == pytest.approx(float(power) / (1440 * RPM), rel=1e-9)


@pytest.mark.parametrize(("motor", "key", "speed", "changed"), [
    (KLOSS, "synchronous_rpm", "1e12", {}),
    (KLOSS, "synchronous_rpm", "2e6", {"rated_rpm": None, "rated_slip": "0.04"}),
    (KLOSS, "rated_rpm", "0.5", {"synchronous_rpm": None, "rated_slip": "0.04"}),
    (KLOSS, "rated_rpm", "1e-12", {}),
    (LINEAR, "no_load_rpm", "1e-12", {}),
    (LINEAR, "no_load_rpm", "5e6", {}),
])
def test_a_motor_speed_no_motor_turns_at_is_refused_at_its_key(motor, key, speed, changed):
    message = _refusal(_press(motor, **changed, **{key: speed}))
    assert message.startswith(f"dynamics.motor.{key}: must be within 1–1000000 rpm, as motors turn (a low-speed "
                              "hydraulic one some tens")
    assert f"(got {float(speed)!r})" in message


def test_a_linear_motors_points_whose_line_no_motor_follows_are_refused_with_its_no_load_speed():
    # The line through 60 N·m at rest and nought at 2e9 rpm (an exponent slipped into the second point's speed).
    text = _press(LINEAR, stall_torque=None, no_load_rpm=None, points="[[0.0, 60.0], [2e9, 0.0]]")
    assert _refusal(text) == ("dynamics.motor.points: gives a speed outside 1–1000000 rpm, as motors turn (a "
                              "low-speed hydraulic one some tens, a 50 Hz induction one up to 3000, a high-speed "
                              "spindle some 100 000) (their line gives no torque at 2e+09 rpm, its no-load speed) (got "
                              "[[0.0, 60.0], [2000000000.0, 0.0]]); a slip of the exponent?")
    # A stall point at rest is what such a motor's catalogue gives: a real line through it loads.
    motor = scene.loads(_press(LINEAR, stall_torque=None, no_load_rpm=None, points="[[0.0, 60.0], [750.0, 30.0]]"))
    assert motor.dynamics.motion.motor.no_load == pytest.approx(1500 * RPM, rel=1e-12)


@pytest.mark.parametrize(("changed", "speed"), [({"no_load_rpm": "2"}, 2.0), ({"no_load_rpm": "900000"}, 9e5)])
def test_a_linear_motors_speed_near_the_bounds_still_loads(changed, speed):
    motor = scene.loads(_press(LINEAR, **changed)).dynamics.motion.motor
    # Its line falls from the stall torque at rest to nought at the no-load speed, on the motor's own shaft.
    assert motor.characteristic(speed * RPM) == pytest.approx(0.0, abs=1e-9)
    assert motor.characteristic(0.0) == 60.0


@pytest.mark.parametrize("slip", ["1e-12", "0.0005", "0.6"])
def test_a_rated_slip_no_induction_motor_has_is_refused_at_its_key(slip):
    message = _refusal(_press(KLOSS, rated_rpm=None, rated_slip=slip))
    assert message.startswith("dynamics.motor.rated_slip: must be within 0.001–0.5, as induction motors slip")
    assert f"(got {float(slip)!r})" in message


def test_a_rated_speed_a_hair_below_the_synchronous_is_refused_for_the_slip_it_gives():
    message = _refusal(_press(KLOSS, rated_rpm="1499.99999"))
    assert message.startswith("dynamics.motor.rated_rpm: gives a rated slip outside 0.001–0.5")
    assert "the slip 1 − rated_rpm/synchronous_rpm is 6.67e-09" in message
    assert "(got 1499.99999)" in message


@pytest.mark.parametrize("slip", ["0.0015", "0.45"])
def test_a_rated_slip_near_the_bounds_still_loads_as_typed(slip):
    motor = scene.loads(_press(KLOSS, rated_rpm=None, rated_slip=slip)).dynamics.motion.motor
    assert motor.rated_slip == float(slip)
