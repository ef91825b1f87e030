"""A student's own compressor, in Russian, through the dynamics sheet: the slips a fresh user made in [dynamics].

The scene is a crank-slider compressor written from scratch (not a starter): crank 0.07 m at 240 rev/min, rod
0.28 m, a piston resisted by the gas over the compression stroke, δ = 0.04 and an induction motor by Kloss.
"""

from __future__ import annotations

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
    told = refusal(COMPRESSOR + MOTOR.replace("rotor_inertia = 0.02 }", "rotor_inertia = 0.02, start = { angle_deg = 0.0 } }"))
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
