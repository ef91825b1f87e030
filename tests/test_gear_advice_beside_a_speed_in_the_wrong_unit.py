"""The gear ratio is weighed against the crank's speed where [dynamics]' mean speed was typed in the other unit.

``rpm = 6.2832`` under [dynamics] beside a crank of 6.2832 rad/s: the first warning rightly said rad/s were typed as
rpm (write omega = 6.2832); a second then advised gear_ratio = 228, the ratio that fits the mistyped 6.2832 rpm, for a
motor whose 23.8333 already brings its 1430 rpm to the crank's 60.  The gear is now weighed against the crank's speed
(and told, where it does not fit that either, as weighed against it), and the stall's advice, on the console and in
the note, puts the mistyped speed first.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from scene_texts import crank_press

from graphplan.cli import main

RPM = 2.0 * math.pi / 60.0

PRESS = crank_press("delta = 0.1\nrpm = 6.2832\ncount = 720\nflywheel_shaft_rpm = 1430.0\nmotor = { kind = \"kloss\", "
                    "power = 2200.0, overload = 2.3, synchronous_rpm = 1500.0, rated_rpm = 1430.0, "
                    "gear_ratio = 23.8333333, rotor_inertia = 0.005 }\n", header='locale = "en"',
                    positions="plans = [3]")


def _run(tmp_path: Path, capsys, text: str) -> tuple[list[str], str]:
    scene = tmp_path / "press.toml"
    scene.write_text(text, encoding="utf-8")
    capsys.readouterr()
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    printed = capsys.readouterr()
    told = [line.removeprefix("warning: ") for line in (printed.out + printed.err).splitlines()
            if line.startswith("warning: ")]
    return told, (out / "note.md").read_text(encoding="utf-8")


def test_a_gear_that_fits_the_crank_is_not_refitted_to_the_mistyped_speed(tmp_path, capsys):
    told, note = _run(tmp_path, capsys, PRESS)
    # Through 23.8333 the motor's rated 1430 rpm is the crank's 60 rpm; the mistyped 6.2832 rpm would want 1430/6.2832.
    assert 1430.0 / 23.8333333 == pytest.approx(60.0, rel=1e-6)
    assert not [line for line in told if line.startswith("dynamics.motor.gear_ratio")]
    assert f"{1430.0 / 6.2832:.3g}" == "228" and not [line for line in told if "228" in line]
    (unit,) = [line for line in told if line.startswith("dynamics.rpm = 6.2832")]
    assert unit.endswith("; the motor's rated speed through dynamics.motor.gear_ratio = 23.8333 turns the shaft at 60 "
                         "rpm, near the crank's 60")
    # The flywheel was sized at 6.2832 rev/min = 0.65797 rad/s: (1/RPM)² = 91 times the crank's own speed's flywheel.
    sized = 6.2832 * RPM
    (stall,) = [line for line in told if line.startswith("dynamics: the machine stalls")]
    found = re.search(r"\(first the mean speed told for dynamics\.rpm: the flywheel run with, sized at ([\d.]+) rad/s, "
                      r"is some (\d+) times too large; then a stronger motor, a larger gear ratio", stall)
    assert found, stall
    assert float(found.group(1)) == pytest.approx(sized, rel=1e-4) and int(found.group(2)) == round(1.0 / RPM ** 2)
    assert (f"the machine was run with the flywheel sized at ωm = {found.group(1)} rad/s, some {found.group(2)} times "
            "too heavy") in note


def test_a_gear_that_fits_neither_speed_is_told_as_weighed_against_the_crank(tmp_path, capsys):
    told, _ = _run(tmp_path, capsys, PRESS.replace("gear_ratio = 23.8333333", "gear_ratio = 5"))
    (gear,) = [line for line in told if line.startswith("dynamics.motor.gear_ratio = 5")]
    # 1430/5 = 286 rpm at the shaft, 4.77 times the crank's 60 rpm; the ratio that fits, 1430/60 = 23.8.
    assert (f"turns the driving shaft at {1430.0 / 5:.4g} rpm through it, {1430.0 / 5 / 60.0:.3g} times the 60 rpm the "
            "crank turns at (not the dynamics.rpm typed in the other unit, told above); gear_ratio is "
            f"ω_motor/ω_shaft, here {1430.0 / 60.0:.3g} ") in gear
    (unit,) = [line for line in told if line.startswith("dynamics.rpm = 6.2832")]
    assert "near the crank's" not in unit
