"""A Kloss motor given a synchronous speed that no 50 or 60 Hz motor has is warned of, and a stall it explains is
advised to it first.

``synchronous_rpm = 1450, rated_rpm = 1430`` (a nameplate's speed typed for the synchronous one) went through without a
word: Kloss' slip came out 1.4 % in place of 4.7 %, the motor's starting torque a third of its own, and the stall that
followed was advised "a stronger motor, a larger gear ratio".  A synchronous speed is 60·f/p: the console, the note's
caution (en, ru, zh) and the stall's advice now name the nearest.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.units import MOTOR_SYNCHRONOUS_RPM, nearest_synchronous_rpm
from tests.test_console_note_numbers import _flywheel_scene, _printed

RPM = 2.0 * math.pi / 60.0


def _synchronous_speeds() -> set[float]:
    """60·f/p for f = 50 and 60 Hz and up to eight pairs of poles, written out by hand."""
    return {3000.0, 1500.0, 1000.0, 750.0, 600.0, 500.0, 3000.0 / 7, 375.0,
            3600.0, 1800.0, 1200.0, 900.0, 720.0, 3600.0 / 7, 450.0}


@pytest.mark.parametrize(("typed", "nearest"), [
    (1450.0, 1500.0), (1430.0, 1500.0), (2900.0, 3000.0), (960.0, 1000.0), (1550.0, 1500.0), (700.0, 720.0),
    (1500.0, None), (428.6, None), (514.0, None), (3600.0, None), (375.0, None), (200.0, None),
])
def test_the_nearest_synchronous_speed_is_named_only_where_the_typed_one_is_none(typed, nearest):
    speeds = _synchronous_speeds()
    is_one = any(abs(typed / speed - 1.0) <= 0.002 for speed in speeds)
    # Below 0.9 of the slowest (375) the 60·f/p crowd together and nothing is said.
    expected = None if is_one or typed < 0.9 * 375.0 else min(speeds, key=lambda speed: abs(typed / speed - 1.0))
    assert expected == nearest
    if nearest:
        assert nearest_synchronous_rpm(typed) == pytest.approx(nearest)
    else:
        assert nearest_synchronous_rpm(typed) is None


def test_the_speed_in_rpm_warning_keeps_its_speeds_down_to_720():
    assert MOTOR_SYNCHRONOUS_RPM == (3600, 3000, 1800, 1500, 1200, 1000, 900, 750, 720)


def _starting_torque_on_shaft(power: float, overload: float, synchronous_rpm: float, rated_rpm: float,
                              gear_ratio: float) -> float:
    """u·2·Mmax/(1/sk + sk), Mmax = λ·P/ωN, sk = sN·(λ + √(λ² − 1)), sN = 1 − nN/ns: Kloss' torque at rest."""
    slip = 1.0 - rated_rpm / synchronous_rpm
    critical = slip * (overload + math.sqrt(overload ** 2 - 1.0))
    most = overload * power / (rated_rpm * RPM)
    return gear_ratio * 2.0 * most / (1.0 / critical + critical)


def _run(tmp_path: Path, capsys, synchronous: str, locale: str = "en") -> tuple[list[str], str]:
    scene = _flywheel_scene(tmp_path, r"synchronous_rpm = 1500", f"synchronous_rpm = {synchronous}")
    _printed(capsys)
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note", "--locale", locale]) == 0
    told = [line.removeprefix("warning: ") for line in _printed(capsys).splitlines() if line.startswith("warning: ")]
    return told, (out / "note.md").read_text(encoding="utf-8")


def test_a_rated_speed_typed_for_the_synchronous_one_is_told_and_the_stall_advised_to_it(tmp_path, capsys):
    # The starter's 4 kW motor, λ = 2.2, rated 1440 rpm through 14.4, given a synchronous 1450 in place of 1500.
    told, note = _run(tmp_path, capsys, "1450")
    (line,) = [line for line in told if "synchronous_rpm" in line and not line.startswith("dynamics:")]
    assert line.startswith("dynamics.motor.synchronous_rpm = 1450 is no synchronous speed of a 50 or 60 Hz motor "
                           "(60·f/p); 1500 with a rated 1450?")
    given = _starting_torque_on_shaft(4000.0, 2.2, 1450.0, 1440.0, 14.4)
    corrected = _starting_torque_on_shaft(4000.0, 2.2, 1500.0, 1440.0, 14.4)
    (stall,) = [line for line in told if line.startswith("dynamics: the machine stalls")]
    found = re.search(r"\(first the synchronous speed told for dynamics\.motor\.synchronous_rpm: at 1500 rpm the motor "
                      r"gives the shaft ([\d.]+) N·m at rest, not ([\d.]+); then a stronger motor", stall)
    assert found, stall
    assert float(found.group(1)) == pytest.approx(corrected, rel=1e-4)
    assert float(found.group(2)) == pytest.approx(given, rel=1e-4)
    assert "given as 1450 rpm, which no 50 or 60 Hz motor has" in note and "synchronous speed of 1500 rpm" in note
    assert (f"the motor would give the driving shaft {found.group(1)} N·m at rest, not {found.group(2)} N·m"
            in note)


def test_a_synchronous_speed_above_the_nearest_is_told_but_not_blamed_for_torque(tmp_path, capsys):
    # 1550 with a rated 1440 gives the motor more slip than 1500 would, so more torque at rest, not less.
    assert _starting_torque_on_shaft(4000.0, 2.2, 1550.0, 1440.0, 14.4) > \
        _starting_torque_on_shaft(4000.0, 2.2, 1500.0, 1440.0, 14.4)
    told, note = _run(tmp_path, capsys, "1550")
    assert told == [("dynamics.motor.synchronous_rpm = 1550 is no synchronous speed of a 50 or 60 Hz motor (60·f/p); "
                     "the nearest is 1500: Kloss' slip, s = 1 − ω/ωs, and the motor's whole characteristic are "
                     "reckoned from it")]
    assert "(ns = 60·f/p; the nearest is 1500 rpm)" in note


def test_a_true_synchronous_speed_and_one_worked_out_from_the_rated_point_are_not_told(tmp_path, capsys):
    told, note = _run(tmp_path, capsys, "1500")
    assert not [line for line in told if "synchronous" in line] and "no 50 or 60 Hz motor" not in note
    # rated_rpm with rated_slip: the synchronous speed 1440/(1 − 0.035) = 1492.2 is worked out, not typed.
    (tmp_path / "slip").mkdir()
    scene = _flywheel_scene(tmp_path / "slip", r"synchronous_rpm = 1500", "rated_slip = 0.035")
    assert 1440.0 / (1 - 0.035) != pytest.approx(1500.0, rel=0.002)
    _printed(capsys)
    assert main(["check", str(scene)]) == 0, _printed(capsys)
    assert "no synchronous speed" not in _printed(capsys)


@pytest.mark.parametrize(("locale", "words"), [("ru", ("1450 об/мин", "1500 об/мин")),
                                               ("zh", ("1450 r/min", "1500 r/min"))])
def test_the_note_s_caution_is_in_the_scene_s_language(tmp_path, capsys, locale, words):
    _, note = _run(tmp_path, capsys, "1450", locale)
    caution = [para for para in note.split("\n\n") if "60·f/p" in para]
    assert len(caution) == 1 and all(word in caution[0] for word in words)
