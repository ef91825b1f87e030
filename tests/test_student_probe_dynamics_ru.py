"""A student's own compressor, in Russian, through the dynamics sheet: the slips a fresh user made in [dynamics].

The scene is a crank-slider compressor written from scratch (not a starter): crank 0.07 m at 240 rev/min, rod
0.28 m, a piston resisted by the gas over the compression stroke, δ = 0.04 and an induction motor by Kloss.
"""

from __future__ import annotations

import math

import pytest

import graphplan
from graphplan.errors import SceneError

COMPRESSOR = """
[scene]
title   = "Поршневой компрессор"
locale  = "ru"
gravity = 9.81

[frame]
link   = 1
points = { O = [0.0, 0.0] }

[driver]
kind    = "crank"
link    = 2
pivot   = "O"
joint   = "A"
length  = 0.07
rpm     = 240.0

[[groups]]
kind     = "RRP"
links    = [3, 4]
joints   = ["A", "B"]
length   = 0.28
guide    = { through = "O", angle = 0.0 }
assembly = "forward"

[points]
S3 = { link = 3, from = "A", toward = "B", at = 0.09 }

[links.2]
mass    = 6.0
centre  = "O"
inertia = 0.04
[links.3]
mass    = 3.5
centre  = "S3"
inertia = 0.03
[links.4]
mass    = 4.0
centre  = "B"

[[loads]]
kind      = "force"
link      = 4
point     = "B"
angle     = 180.0
resisting = true
diagram   = [[0.0, 300.0], [0.5, 1500.0], [0.8, 5000.0], [0.85, 7000.0], [1.0, 7000.0]]

[positions]
count   = 12
start   = "extreme"
working = { link = 4, sense = "forward" }
plans   = [3]

[dynamics]
delta = 0.04
"""

MOTOR = ('motor = { kind = "kloss", power = 5500.0, overload = 2.0, synchronous_rpm = 1000.0, rated_rpm = 955.0, '
         'gear_ratio = 4.0, rotor_inertia = 0.02 }\n')


def refusal(text: str) -> str:
    with pytest.raises(SceneError) as caught:
        graphplan.load_text(text)
    return str(caught.value)


# --- a key written in the wrong table of [dynamics] -------------------------------------------------------------


def test_start_inside_the_motor_is_sent_to_dynamics():
    # The docs list start with the motor's keys; written inside its braces it was "unknown key", no more.
    started = "rotor_inertia = 0.02, start = { angle_deg = 0.0 } }"
    told = refusal(COMPRESSOR + MOTOR.replace("rotor_inertia = 0.02 }", started))
    assert told.startswith("dynamics.motor.start: unknown key; start is a key of dynamics, not of dynamics.motor")
    assert "write it under [dynamics]" in told and "start = { angle_deg = 0.0 }" in told


def test_gear_ratio_beside_delta_is_sent_into_the_motor():
    # Was "did you mean 'duration'?", the nearest key of [dynamics] by spelling, which sends the student astray.
    told = refusal(COMPRESSOR + MOTOR.replace(", gear_ratio = 4.0", "") + "gear_ratio = 4.0\n")
    assert told.startswith("dynamics.gear_ratio: unknown key; gear_ratio is a key of dynamics.motor")
    assert "write it inside motor = { …, gear_ratio = 4.0 }" in told
    assert "duration" not in told


def test_duration_inside_the_motor_is_sent_to_dynamics():
    told = refusal(COMPRESSOR + MOTOR.replace("rotor_inertia = 0.02 }", "rotor_inertia = 0.02, duration = 5.0 }"))
    assert told.startswith("dynamics.motor.duration: unknown key; duration is a key of dynamics")
    assert "gear_ratio" not in told  # was "did you mean 'gear_ratio'?"


def test_a_motor_key_in_the_start_table_is_sent_beside_it_into_the_motor():
    told = refusal(COMPRESSOR + MOTOR + "start = { angle_deg = 0.0, rotor_inertia = 0.01 }\n")
    assert told.startswith("dynamics.start.rotor_inertia: unknown key; rotor_inertia is a key of dynamics.motor")
    assert "write it inside motor = { …, rotor_inertia = 0.01 }" in told


def test_a_misspelt_key_is_still_told_its_spelling():
    told = refusal(COMPRESSOR + MOTOR.replace("gear_ratio", "gear_ration"))
    assert told == "dynamics.motor.gear_ration: unknown key; did you mean 'gear_ratio'?"


# --- the mean speed typed in the other unit ------------------------------------------------------------------------


def flywheel_inertia(scene_text: str) -> float:
    return graphplan.load_text(scene_text).machine_dynamics().flywheel.inertia


def test_rad_per_second_typed_as_rpm_is_warned_with_the_key_and_said_in_the_note(tmp_path):
    # 240 rev/min is 25.1327 rad/s; the student copies 25.13 under rpm. Nothing said so: the flywheel came out
    # some (30/π)² = 91 times too large, and only a motor's run, where there was one, found the speed off.
    crank = 240.0 * math.pi / 30.0
    typed = 25.13
    assert abs(typed / crank - 1) < 0.01
    text = COMPRESSOR + f"rpm = {typed}\n"
    sized = typed * math.pi / 30.0
    done = graphplan.load_text(text).write(tmp_path / "out", only=["dynamics", "note"])
    told = [line for line in done.warnings if line.startswith("dynamics.rpm")]
    assert len(told) == 1, done.warnings
    line = told[0]
    assert "dynamics.rpm = 25.13 rev/min is the crank's speed in rad/s" in line
    assert f"sized at {sized:.5g} rad/s" in line
    assert f"{crank / sized:.3g} times slower" in line
    assert f"some {(30 / math.pi) ** 2:.0f} times too large" in line
    assert "write dynamics.omega = 25.13" in line
    # The claim checked: the flywheel for the same δ, sized at 2.63 rad/s and at 25.13, differs by about ω².
    right = flywheel_inertia(COMPRESSOR + f"omega = {typed}\n")
    wrong = flywheel_inertia(text)
    assert 0.95 * (crank / sized) ** 2 < wrong / right < 1.05 * (crank / sized) ** 2
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    caution = next(par for par in note.split("\n\n") if par.startswith("Внимание: средняя угловая скорость"))
    assert "задана частотой вращения n = 25,13 об/мин" in caution
    assert f"ωср = {sized:.4f}".replace(".", ",") in caution
    assert f"примерно в {(30 / math.pi) ** 2:.0f} раз больше нужного" in caution
    assert "dynamics." not in caution  # the note's reader has no scene to look a key up in


def test_rpm_typed_as_rad_per_second_is_warned():
    text = COMPRESSOR + "omega = 240.0\n"
    scene = graphplan.load_text(text)
    from graphplan.flywheel import speed_unit_warning

    line = speed_unit_warning(scene.dynamics, scene.driver.omega)
    assert line is not None
    assert line.startswith("dynamics.omega = 240 rad/s is the crank's speed in rev/min")
    assert f"{240.0 / (240.0 * math.pi / 30.0):.3g} times faster" in line
    assert "times too small: write dynamics.rpm = 240" in line


@pytest.mark.parametrize("speed", ["rpm = 240.0", "omega = 25.13", "rpm = 250.0", "omega = 30.0", ""])
def test_a_speed_in_its_own_unit_is_not_told(speed):
    from graphplan.flywheel import speed_unit_warning

    scene = graphplan.load_text(COMPRESSOR + speed + "\n")
    assert speed_unit_warning(scene.dynamics, scene.driver.omega) is None


# --- a motor whose speed the gear ratio does not bring to the machine's -------------------------------------------


def gear_line(text: str) -> str | None:
    from graphplan.flywheel import gear_warning

    scene = graphplan.load_text(text)
    return gear_warning(scene.dynamics, scene.driver.omega)


def test_a_gear_ratio_left_out_is_told_with_the_one_that_fits():
    # The motor's nameplate copied without its gearbox: u = 1, the crank driven at the motor's 955 rpm where the
    # compressor turns at 240. The run stalls, and the stall's advice (a stronger motor) alone led astray.
    line = gear_line(COMPRESSOR + MOTOR.replace(", gear_ratio = 4.0", ""))
    assert line is not None
    assert line.startswith("dynamics.motor.gear_ratio = 1 (the default where it is left out): the motor's rated speed, "
                           "955 rpm,")
    rated = 1000.0 * (1 - 0.045)          # synchronous_rpm·(1 − sN), sN = 1 − 955/1000
    assert f"{rated / 240.0:.3g} times the 240 rpm" in line
    assert f"here {rated / 240.0:.3g}" in line


def test_a_gear_ratio_turned_round_is_told():
    line = gear_line(COMPRESSOR + MOTOR.replace("gear_ratio = 4.0", "gear_ratio = 0.25"))
    assert line is not None and line.startswith("dynamics.motor.gear_ratio = 0.25: ")
    assert f"at {955.0 / 0.25:.4g} rpm through it" in line
    assert f"here {955.0 / 240.0:.3g}" in line


def test_a_gear_ratio_that_fits_is_not_told():
    assert gear_line(COMPRESSOR + MOTOR) is None          # 955/4 = 239 rpm for the machine's 240
    assert gear_line(COMPRESSOR + 'motor = { kind = "constant", torque = 30.0, gear_ratio = 1.0 }\n') is None


@pytest.mark.parametrize("kind", ["asynchronous", "induction", "асинхронный"])
def test_an_induction_motor_by_its_name_is_sent_to_kloss(kind):
    told = refusal(COMPRESSOR + MOTOR.replace('kind = "kloss"', f'kind = "{kind}"'))
    assert told == f"dynamics.motor.kind: must be one of constant, linear, kloss; did you mean 'kloss'? (got '{kind}')"


# --- the count of the model's steps in words --------------------------------------------------------------------


@pytest.mark.parametrize(("count", "words"), [(361, "361 шаг"), (362, "362 шага"), (360, "360 шагов")])
def test_the_steps_of_the_cycle_are_counted_in_the_form_the_number_takes(tmp_path, count, words):
    # Was "по циклу (шагов: 360)", a form's label where a note writes the count with its noun; and the noun
    # follows the number as Russian declines it (1, 21 … шаг; 2–4 шага; 5–20 шагов).
    graphplan.load_text(COMPRESSOR + f"count = {count}\n").write(tmp_path / "out", only=["dynamics", "note"])
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert f"по циклу ({words}) они взяты из аналитического решения" in note
    assert "шагов:" not in note
