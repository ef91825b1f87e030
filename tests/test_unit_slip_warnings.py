"""A fresh student's slips, tried as scenes: a choice among keys got wrong (neither, both, a bad value in one) is
told at the key at fault, naming every choice where none is given; and values typed in the wrong unit that still
run (an rpm typed as rad/s, a mass in grams, an eccentricity or a radius in millimetres) are warned of, naming the
key, its value and what was likely meant, while no fixture, test scene or starter is."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.starters import starter

STARTERS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad", "flywheel", "rotor")
SCENES = sorted(Path("fixtures").glob("*.toml")) + sorted(Path("tests/scenes").glob("*.toml"))


def _scene(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _refusal(tmp_path: Path, text: str, capsys) -> str:
    assert main(["check", str(_scene(tmp_path, text))]) == 2
    return capsys.readouterr().err.strip()


def _edited(kind: str, old: str, new: str) -> str:
    text = starter(kind, "en")
    assert old in text
    return text.replace(old, new, 1)


MACHINE = '[scene]\ntitle = "Machine"\n[vibration]\nmass = 100.0\n'
SHEET = "resisting_power = [[0, 367.7], [120, 367.7], [120, 3677], [360, 3677]]\n"
KLOSS = ('motor = { kind = "kloss", power = 4000.0, overload = 2.2, synchronous_rpm = 1500, rated_rpm = 1440, '
         'gear_ratio = 14.4 }')


# --- a choice among keys -------------------------------------------------------------------------------------------

@pytest.mark.parametrize(("text", "told"), [
    # Neither: told at the first choice, naming all of them.
    (_edited("crank-rocker", "omega   = -17.0", ""),
     "driver.omega: is required but missing: give omega (rad/s) or rpm (rev/min)"),
    (MACHINE + "unbalance = 0.02\nrpm = 600\n", "vibration.stiffness: is required (or shaft)"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\n", "vibration.omega: is required but missing: give omega (rad/s) "
                                                     "or rpm (rev/min)"),
    (MACHINE + "stiffness = 1e5\nrpm = 600\n", "vibration.unbalance: is required (m·e, kg·m), or unbalanced_mass "
                                               "and eccentricity"),
    (MACHINE + "unbalance = 0.02\nshaft = { modulus = 2e11, length = 1.0 }\nrpm = 600\n",
     "vibration.shaft.diameter: is required (the shaft's diameter, m), or second_moment (I, m⁴)"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\n' + SHEET,
     "dynamics.omega: is required but missing: give omega (rad/s) or rpm (rev/min)"),
    (_edited("crank-rocker", 'assembly = "left"', ""),
     "groups[0].assembly: is required but missing: left or right chooses the branch the group assembles in (or "
     "near = [x, y]"),
    # Half of a pair: told at the half left out, with the other way to give it.
    (MACHINE + "unbalanced_mass = 1.0\nstiffness = 1e5\nrpm = 600\n",
     "vibration.eccentricity: is required with unbalanced_mass: the unbalanced mass's distance e from the axis, m; "
     "or give unbalance (m·e, kg·m) alone in place of both"),
    (MACHINE + "eccentricity = 0.01\nstiffness = 1e5\nrpm = 600\n",
     "vibration.unbalanced_mass: is required with eccentricity: the unbalanced mass m, kg; or give unbalance (m·e, "
     "kg·m) alone in place of both"),
    # Both: told at a key, never at the table alone, naming both.
    (_edited("crank-rocker", "omega   = -17.0", "omega = -17.0\nrpm = 160"),
     "driver.rpm: give either omega or rpm, not both"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\nshaft = { modulus = 2e11, diameter = 0.05, length = 1.0 }\n"
               "rpm = 600\n", "vibration.shaft: give either stiffness or shaft, not both"),
    (_edited("crank-rocker", 'assembly = "left"', 'assembly = "left"\nnear = [0.3, 0.6]'),
     "groups[0].near: give either assembly or near, not both"),
    (_edited("crank-rocker", "velocity_pole      = 150.0", "velocity_pole = 150.0\nvelocity_scale = 0.01"),
     "drawing.velocity_scale: give either velocity_pole or velocity_scale, not both"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = 100\n' + SHEET
     + KLOSS.replace("rated_rpm = 1440", "rated_rpm = 1440, rated_slip = 0.04") + "\n",
     "dynamics.motor.rated_slip: give two of synchronous_rpm, rated_rpm, rated_slip, not all three"),
    # A bad value in one: told at that one, not at the other.
    (_edited("crank-rocker", "omega   = -17.0", 'rpm = "160"'), "driver.rpm: must be a number, not a string"),
    (MACHINE + "unbalance = 0.02\nstiffness = -1e5\nrpm = 600\n", "vibration.stiffness: must be > 0"),
    (MACHINE + "unbalance = 0.02\nshaft = 5\nrpm = 600\n", "vibration.shaft: must be a table, not an integer"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\nrpm = 0\n", "vibration.rpm: must be > 0"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\nomega = -3\n", "vibration.omega: must be > 0"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = -100\n' + SHEET, "dynamics.rpm: must be > 0"),
    (_edited("crank-rocker", 'assembly = "left"', "near = 5"), "groups[0].near: must be a point [x, y]"),
    (_edited("crank-rocker", 'assembly = "left"', 'assembly = "up"'), "groups[0].assembly: must be one of left, "
                                                                      "right"),
])
def test_a_choice_got_wrong_is_told_at_the_key_at_fault(tmp_path, capsys, text, told):
    assert told in _refusal(tmp_path, text, capsys)
