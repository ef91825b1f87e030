"""A stall's and an off-design run's lines beside the warning of a gear ratio that does not fit the machine's speed.

Through gear_ratio = 40 where the press's 1440 rpm motor needs 14.4, the gear line said the ratio should be smaller and
the stall's advice, on the next line, "a stronger motor, a larger gear ratio": a larger one slows the shaft more.  With
the ratio left out (1, too small), both lines asked for a larger one, the stall's without its number; and a run that
settled off the flywheel's speed told "a motor, gear ratio or speed that agree with each other" under the gear line that
names the ratio that fits.  Each line now says what the other does not, and the note advises as the console does.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from graphplan.cli import main
from tests.test_console_note_numbers import MEAN_RESISTANCE, RPM, _flywheel_scene, _kloss_steady_speed, _printed

# The flywheel starter's press and motor: 1500/1440 rpm, λ = 2.2, at 100 rpm; 3677 W punching, 367.7 W idling.
RATED = 1440.0 * RPM
PUNCHING, IDLING = 3677.0 / (100.0 * RPM), 367.7 / (100.0 * RPM)


def _run(tmp_path: Path, capsys, motor: str) -> tuple[list[str], str]:
    """The dynamics' warnings and the note of the starter run with its motor line made ``motor``."""
    scene = _flywheel_scene(tmp_path, r"^motor = .*$", motor)
    _printed(capsys)
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    told = [line.removeprefix("warning: ") for line in _printed(capsys).splitlines()
            if line.startswith("warning: dynamics")]
    return told, (out / "note.md").read_text(encoding="utf-8")


def _kloss(power: float, gear_ratio: str) -> str:
    return (f'motor = {{ kind = "kloss", power = {power}, overload = 2.2, synchronous_rpm = 1500, rated_rpm = 1440'
            f'{gear_ratio}, rotor_inertia = 0.02 }}')


def _gear_line(told: list[str], ratio: str) -> str:
    (line,) = [line for line in told if line.startswith(f"dynamics.motor.gear_ratio = {ratio}")]
    # gear_ratio is ω_motor/ω_shaft: 1440 rpm over the press's 100 rpm.
    assert f"here {1440.0 / 100.0:.3g} " in line
    return line


def test_a_stall_through_a_gear_ratio_too_large_is_not_advised_a_larger_one(tmp_path, capsys):
    told, note = _run(tmp_path, capsys, _kloss(300.0, ", gear_ratio = 40"))
    # Through 40 the motor's 1440 rpm turns the shaft at 36 rpm, under the 100/1.5 the gear line is told below.
    gear = _gear_line(told, "40")
    assert f"turns the driving shaft at {1440.0 / 40.0:g} rpm through it" in gear and 1440.0 / 40.0 < 100.0 / 1.5
    # Its largest torque on the shaft, u·λ·P/ωN, is short of the mean resistance: no speed keeps the press turning.
    assert 40.0 * 2.2 * 300.0 / RATED < MEAN_RESISTANCE
    (stall,) = [line for line in told if line.startswith("dynamics: the machine stalls")]
    assert "a stronger motor, a larger gear ratio" not in stall
    assert stall.endswith("(a stronger motor, or a start unloaded through a clutch; not a larger gear ratio: "
                          "dynamics.motor.gear_ratio = 40 already turns the shaft well below the machine's speed)")
    time, angle = re.search(r"stalls at t = ([\d.]+) s, φ = ([\d.]+)°", stall).groups()
    (paragraph,) = [para for para in note.split("\n\n") if para.startswith("The machine does not reach its steady")]
    assert f"coming to rest at t = {time} s at φ = {angle}°" in paragraph
    assert "a larger starting torque, a larger gear ratio" not in paragraph
    assert "not a larger gear ratio: through the one given, u = 40, the motor already turns" in paragraph


def test_a_gear_ratio_of_1_typed_is_not_called_the_default(tmp_path, capsys):
    """gear_ratio = 1.0 written in the scene was told "(the default where it is left out)", as though not there."""
    told, _ = _run(tmp_path, capsys, _kloss(4000.0, ", gear_ratio = 1.0"))
    line = _gear_line(told, "1: the motor's rated speed")
    assert "default" not in line


def test_a_gear_ratio_left_out_is_asked_for_once_with_its_number(tmp_path, capsys):
    told, note = _run(tmp_path, capsys, _kloss(4000.0, ""))
    _gear_line(told, "1 (the default where it is left out)")
    # At rest the motor gives 2·Mmax/(1/sk + sk), sk = sN·(λ + √(λ² − 1)), against the idling 35.113 N·m.
    slip = 1.0 - 1440.0 / 1500.0
    critical = slip * (2.2 + math.sqrt(2.2 ** 2 - 1.0))
    starting = 2.0 * 2.2 * 4000.0 / RATED / (1.0 / critical + critical)
    (unmoved,) = [line for line in told if line.startswith("dynamics: the machine does not start")]
    torque, resisting = re.search(r"the driving torque, ([\d.]+) N·m, does not overcome the resistance there, "
                                  r"([\d.]+) N·m", unmoved).groups()
    assert (float(torque), float(resisting)) == (pytest.approx(starting, abs=5e-4), pytest.approx(IDLING, abs=5e-4))
    assert f"the driving torque on the shaft, {torque} N·m, does not overcome the resistance there, Mr = {resisting}" \
        in note
    # The gear line gives the larger ratio with its number; the stall's line points to it, not asking again.
    assert "a larger gear ratio" not in unmoved
    assert "(the gear ratio told for dynamics.motor.gear_ratio, a stronger motor, or a start from another angle)" \
        in unmoved
    # The note has no gear line: its advice of a larger ratio is the one the console gives.
    assert "A motor with a larger starting torque, a larger gear ratio, or a start from another angle" in note


def test_a_run_settled_off_its_flywheel_s_speed_through_a_wrong_gear_ratio_is_told_through_it(tmp_path, capsys):
    told, note = _run(tmp_path, capsys, _kloss(4000.0, ", gear_ratio = 40"))
    _gear_line(told, "40")
    (off,) = [line for line in told if "% off the" in line]
    assert off.startswith("dynamics: through dynamics.motor.gear_ratio = 40 the motor runs the machine at ωm = ")
    assert "agree with each other" not in off and "(" not in off
    settled = re.search(r"ωm = ([\d.]+) rad/s", off).group(1)
    assert f"mean speed in time 2π/T = {settled} rad/s" in note
    assert float(settled) == pytest.approx(_kloss_steady_speed(40.0), rel=1e-3)
    assert len(told) == 2


def test_a_gear_ratio_that_fits_keeps_the_off_design_advice(tmp_path, capsys):
    # 1440/13 = 110.8 rpm is within 1.5 times the press's 100: no gear line, and the off-design line advises.
    told, _ = _run(tmp_path, capsys, _kloss(4000.0, ", gear_ratio = 13.0"))
    assert 1.0 / 1.5 < 1440.0 / 13.0 / 100.0 < 1.5
    (off,) = told
    assert off.startswith("dynamics: the motor runs the machine at ωm = ")
    assert off.endswith(" (a motor, gear ratio or speed that agree with each other)")


def test_a_gear_ratio_typed_the_wrong_way_up_is_given_the_ratio_that_fits_once(tmp_path, capsys):
    # The starter's gearbox typed as the shaft's speed over the motor's, 1/14.4: the motor's 1440 rpm turns the shaft
    # at some 20 700 rpm, and at rest gives it u·M(0), short of the idling resistance.  The gear line gives the ratio
    # that fits, 14.4, the motor's speed over the shaft's, and the stall's advice points to it; the stall's line then
    # asked whether the ratio was inverted, 1/0.0694 = 14.41: the same advice a second time, in check as in run.
    slip = 1.0 - 1440.0 / 1500.0
    critical = slip * (2.2 + math.sqrt(2.2 ** 2 - 1.0))
    starting = 2.0 * 2.2 * 4000.0 / RATED / (1.0 / critical + critical)
    assert 0.0694 * starting < IDLING < starting / 0.0694
    told, note = _run(tmp_path, capsys, _kloss(4000.0, ", gear_ratio = 0.0694"))
    assert main(["check", str(tmp_path / "press.toml")]) == 0
    checked = [line.removeprefix("warning: ") for line in _printed(capsys).splitlines()
               if line.startswith("warning: dynamics")]
    assert checked == told
    gear = _gear_line(told, "0.0694")
    (unmoved,) = [line for line in told if line.startswith("dynamics: the machine does not start")]
    assert unmoved.endswith("(the gear ratio told for dynamics.motor.gear_ratio, a stronger motor, or a start from "
                            "another angle)")
    # The ratio that fits, and the words that say which way up a ratio is, once among the lines: the gear line's.
    assert [line for line in told if "14.4" in line] == [gear] and gear.count("14.4") == 1
    assert sum(line.count("ω_motor/ω_shaft") + line.count("the motor's speed over the shaft's") for line in told) == 1
    assert not [line for line in told if "inverted" in line]
    # The note has no gear line: it advises a larger ratio once, as for a ratio left out.
    assert note.count("a larger gear ratio") == 1
