"""More of a student's slips: a run that could not end told at the scene's key that asked for it (the motor's table,
its ``off_at``), not at a bare ``motor`` under ``dynamics``; and values typed in another unit that still run, warned
of where the existing bounds did not reach, while no fixture, test scene or starter is."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from console import without_progress

from graphplan.cli import main
from graphplan.starters import starter

RPM = math.pi / 30.0


def _scene(tmp_path: Path, text: str, name: str = "scene.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _flywheel(motor: str) -> str:
    text = starter("flywheel", "en")
    old = next(line for line in text.splitlines() if line.startswith("motor = "))
    return text.replace(old, f"motor = {motor}", 1)


# --- a run that could not end --------------------------------------------------------------------------------------

def _press_mean_resistance() -> float:
    """The starter's press: 367.7 W over 120° and 3677 W over 240° at 100 rpm, as a mean torque (N·m)."""
    return (367.7 * 120.0 + 3677.0 * 240.0) / 360.0 / (100.0 * RPM)


@pytest.mark.parametrize("command", ["run", "check"])
def test_a_runaway_constant_motor_is_told_at_the_motors_key(tmp_path, capsys, command):
    scene = _scene(tmp_path, _flywheel('{ kind = "constant", torque = 25.0, gear_ratio = 20.0 }'))
    out = tmp_path / "out"
    argv = [command, str(scene)] + (["--out", str(out)] if command == "run" else [])
    assert main(argv) == 2
    err = without_progress(capsys.readouterr().err).strip()
    assert err.startswith(f"graphplan: error: dynamics.motor: its torque on the shaft, {25.0 * 20.0:.6g} N·m, "
                          f"exceeds the mean resistance, {_press_mean_resistance():.6g} N·m, at every speed")
    assert "dynamics: motor" not in err and not out.exists()


LINKAGE_RUN_DOWN = """\
[scene]
title = "An unbalanced crank switched off"
gravity = 9.81
[frame]
link = 1
points = { O = [0.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.06
rpm = 600.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.24
guide = { through = "O", angle = 0.0 }
assembly = "forward"
[points.S2]
link = 2
from = "O"
toward = "A"
at = 0.05
[links.2]
mass = 20.0
centre = "S2"
inertia = 0.01
[positions]
count = 12
[dynamics.motor]
kind = "kloss"
power = 4000.0
overload = 2.2
synchronous_rpm = 1500
rated_rpm = 1440
gear_ratio = 2.4
off_at = 1.0
"""


@pytest.mark.parametrize("command", ["run", "check"])
def test_a_run_down_nothing_brings_to_rest_is_told_at_the_motors_off_at(tmp_path, capsys, command):
    """The crank's weight alone resists: it gives back on the way down what it takes on the way up."""
    scene = _scene(tmp_path, LINKAGE_RUN_DOWN)
    out = tmp_path / "out"
    argv = [command, str(scene)] + (["--out", str(out)] if command == "run" else [])
    assert main(argv) == 2
    err = without_progress(capsys.readouterr().err).strip()
    assert err.startswith("graphplan: error: dynamics.motor.off_at: switches the motor off, and the machine has "
                          "nothing to take its energy")
    assert "never comes to rest" in err and "dynamics: motor" not in err and not out.exists()


def test_the_python_interface_names_its_own_arguments():
    from graphplan.machine_motion import ConstantTorque, Machine, simulate

    with pytest.raises(ValueError, match=r"^motor: its torque on the shaft, 10 N·m, exceeds the mean resistance"):
        simulate(Machine(inertia=1.0, resisting=4.0), ConstantTorque(10.0))
    with pytest.raises(ValueError, match=r"^motor_off_at: switches the motor off"):
        simulate(Machine(inertia=1.0, resisting=0.0), ConstantTorque(10.0), motor_off_at=1.0)


@pytest.mark.parametrize(("points", "told"), [
    ("[[100, 40], [100, 30]]", "the two points need different speeds (got 100 rpm twice)"),
    ("[[100, 40], [200, 50]]", "the torque must fall as the speed rises (got 40 N·m at 100 rpm, 50 N·m at 200 rpm)"),
    # The line through them: M = −5 − 0.05·(n − 100), nought at 0 rpm.
    ("[[100, -5], [200, -10]]", "the line through them gives the motor no torque at rest, 0 N·m at 0 rpm"),
])
def test_a_linear_motors_points_are_told_in_the_units_they_were_typed_in(tmp_path, capsys, points, told):
    """They were told in rad/s (10.471975511965976 twice), and a line that gives no torque at rest as 'must be a
    finite number > 0 (got 0.0)'."""
    assert main(["check", str(_scene(tmp_path, _flywheel(f'{{ kind = "linear", points = {points} }}')))]) == 2
    err = without_progress(capsys.readouterr().err).strip()
    assert err.startswith(f"graphplan: error: dynamics.motor.points: {told}")
