"""A motor's rpm typed as rad/s is warned of at every speed of [dynamics] and [vibration] the scene gives in rad/s
(the mean omega, a run's start.omega and start.driving_omega), naming the key, its value and the rpm it reads as,
and beyond the console where those tables' other warnings go: the note (an unusual delta, lengths in millimetres)
and results.json's vibration.warnings; a speed that is no motor's, and no fixture or starter, is not told."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.starters import starter

SLIP = "rev/min typed for rad/s"
CLUTCH = "clutch = { torque = 500, engage_at = 0.1 }\n"
MACHINE = ('[scene]\ntitle = "Machine"\n[vibration]\nmass = 100.0\nunbalance = 0.02\nstiffness = 1e5\n'
           "damping_ratio = 0.1\n")
# What the note calls each of [dynamics]' speeds.
ROLES = {"omega": "the mean speed of the driving shaft", "start.omega": "the speed the run starts at",
         "start.driving_omega": "the speed the clutch's driving half starts at"}


def _flywheel(extra: str, mean: str = "rpm   = 100 ") -> str:
    """The flywheel starter (a press run by a Kloss motor) with ``extra`` keys added to its [dynamics]."""
    text = starter("flywheel", "en")
    assert "rpm   = 100 " in text and "[dynamics]\n" in text
    return text.replace("rpm   = 100 ", mean, 1).replace("[dynamics]\n", "[dynamics]\n" + extra, 1)


def _run(tmp_path: Path, text: str, capsys, only: str) -> tuple[str, dict, str]:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", only]) == 0
    return (capsys.readouterr().out, json.loads((out / "results.json").read_text(encoding="utf-8")),
            (out / "note.md").read_text(encoding="utf-8"))


def _rpm_words(key: str, omega: float) -> str:
    """The console's words on ``key = omega`` typed in rev/min, worked out here."""
    return (f"{key} = {omega:g} rad/s is {omega * 30.0 / math.pi:.5g} rpm: a motor's speed in rev/min typed for "
            f"rad/s? {omega:g} rpm is {omega * math.pi / 30.0:.5g} rad/s: write {key.removesuffix('omega')}rpm = "
            f"{omega:g}")


@pytest.mark.parametrize(("extra", "mean", "key", "omega"), [
    ("duration = 1.0\nstart = { omega = 1450 }\n", "rpm   = 100 ", "start.omega", 1450.0),
    (CLUTCH + "duration = 1.0\nstart = { omega = 10, driving_omega = 1440 }\n", "rpm   = 100 ",
     "start.driving_omega", 1440.0),
    ("", "omega = 960", "omega", 960.0),
])
def test_each_dynamics_speed_typed_in_rpm_is_warned_of_and_told_in_the_note(tmp_path, capsys, extra, mean, key,
                                                                             omega):
    told, _, note = _run(tmp_path, _flywheel(extra, mean), capsys, "note,dynamics")
    assert f"warning: {_rpm_words(f'dynamics.{key}', omega)}" in told
    assert told.count(SLIP) == 1
    assert f"Caution: {ROLES[key]} ω = {omega:g} rad/s (" in note
    assert f"it was probably meant in rpm ({omega:g} rpm is ω = " in note


def test_a_start_too_fast_to_integrate_is_refused_with_the_rpm_question(tmp_path, capsys):
    scene = tmp_path / "scene.toml"
    scene.write_text(_flywheel("start = { omega = 1450 }\n"), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    refusal = capsys.readouterr().err
    assert "dynamics.start.omega: 1450 rad/s is" in refusal
    assert _rpm_words("dynamics.start.omega", 1450.0) in refusal


def test_a_vibration_omega_typed_in_rpm_reaches_results_and_the_note(tmp_path, capsys):
    told, results, note = _run(tmp_path, MACHINE + "omega = 2880\n", capsys, "note,vibration")
    words = _rpm_words("vibration.omega", 2880.0)
    assert f"warning: vibration: {words}" in told
    assert {"code": "speed-in-rpm", "detail": words} in results["vibration"]["warnings"]
    assert "Caution: the speed ω = 2880 rad/s (" in note
    assert "it was probably meant in rpm (2880 rpm is ω = " in note


def test_speeds_that_are_no_motors_are_not_told(tmp_path, capsys):
    extra = CLUTCH + "duration = 1.0\nstart = { omega = 150, driving_omega = 150 }\n"
    told, _, note = _run(tmp_path, _flywheel(extra, "omega = 150"), capsys, "note,dynamics")
    assert SLIP not in told and "a motor's speed in revolutions" not in note
    told, results, note = _run(tmp_path, MACHINE + "omega = 150\n", capsys, "note,vibration")
    assert SLIP not in told and "a motor's speed in revolutions" not in note
    assert "speed-in-rpm" not in {warning["code"] for warning in results["vibration"]["warnings"]}


@pytest.mark.parametrize("kind", ["flywheel", "rotor", "shaper"])
def test_no_starter_is_told_of_a_speed_in_rpm(tmp_path, capsys, kind):
    from graphplan.scene import load

    scene = tmp_path / "scene.toml"
    scene.write_text(starter(kind, "en"), encoding="utf-8")
    pieces = ["note", *(piece for piece in ("dynamics", "vibration", "balancing") if getattr(load(scene), piece))]
    told, results, note = _run(tmp_path, starter(kind, "en"), capsys, ",".join(pieces))
    assert SLIP not in told and "a motor's speed in revolutions" not in note
    assert "speed-in-rpm" not in json.dumps(results)


@pytest.mark.parametrize("scene", sorted(Path("fixtures").glob("*.toml")) + sorted(Path("tests/scenes").glob("*.toml")),
                         ids=str)
def test_no_fixture_or_test_scene_has_a_dynamics_or_vibration_speed_in_rpm(scene):
    from graphplan.flywheel import speed_warnings
    from graphplan.scene import load
    from graphplan.vibration import speed_warning

    loaded = load(scene)
    assert loaded.dynamics is None or speed_warnings(loaded.dynamics) == []
    assert loaded.vibration is None or speed_warning(loaded.vibration) is None
