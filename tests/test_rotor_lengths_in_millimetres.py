"""Lengths typed in millimetres in [balancing] and [vibration]: a rotor's mass at 80 m beside a correction at 0.1 m
gave 1680 kg of correction for a 5 kg rotor, a shaft 30 m thick whirled harmlessly, and nothing was said.  Warned of
as the linkage's lengths are, with each key and its value, on the console, in results.json and in the note; never
for a real machine, a fixture or a starter."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.starters import starter

FIXTURES = sorted(Path("fixtures").glob("*.toml"))
STARTERS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad", "flywheel", "rotor")


def _run(tmp_path, body, capsys, locale="en"):
    scene = tmp_path / "machine.toml"
    scene.write_text(f'[scene]\ntitle = "Machine"\nlocale = "{locale}"\n' + body, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    told = capsys.readouterr().out
    return told, json.loads((out / "results.json").read_text(encoding="utf-8")), (out / "note.md").read_text(
        encoding="utf-8")


ROTOR_IN_MM = ("[balancing]\nmasses = [{ mass = 2.0, radius = 80.0, angle = 0.0, plane = 0.0 },\n"
               "          { mass = 3.0, radius = 60.0, angle = 120.0, plane = 0.2 }]\n"
               "planes = [0.05, 0.3]\ncorrection_radius = 0.1\n")


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_rotors_radii_in_millimetres_beside_a_correction_radius_in_metres_are_warned_of(tmp_path, capsys, locale):
    told, results, note = _run(tmp_path, ROTOR_IN_MM, capsys, locale)
    ratio = 80.0 / 0.1
    line = f"balancing.masses[0].radius = 80 m is {ratio:g} times balancing.correction_radius = 0.1 m"
    assert f"warning: balancing: {line}" in told and "are some lengths in millimetres?" in told
    (found,) = results["balancing"]["warnings"]
    assert found["code"] == "lengths-in-mm" and line in found["detail"]
    words = {"en": f"Caution: as metres, mass 1's radius, 80 m, is {ratio:g} times the correction radius in plane L",
             "ru": "Внимание: если считать в метрах, радиус массы 1, 80 м, более чем в 200 раз превышает радиус "
                   f"корректирующей массы в плоскости L, 0,1 м (отношение {ratio:g})",
             "zh": f"注意：若按米计，质量 1 的半径 80 m 是平面 L 校正半径 0.1 m 的 {ratio:g} 倍"}[locale]
    assert words in note
    assert "balancing.masses" not in note  # the note's reader has no scene to look a key up in


def test_a_rotor_in_millimetres_throughout_is_told_by_its_length_and_its_radii(tmp_path, capsys):
    """Every length in mm: the correction masses come out right, their products a thousand times too large."""
    told, results, _ = _run(tmp_path, "[balancing]\nmasses = [{ mass = 2.0, radius = 200.0, angle = 0.0, plane = 0.0 },"
                                       "\n  { mass = 3.0, radius = 60.0, angle = 120.0, plane = 900.0 }]\n"
                                       "planes = [100.0, 1200.0]\ncorrection_radius = 160.0\n", capsys)
    (found,) = results["balancing"]["warnings"]
    assert "balancing.masses[0].radius = 200 m is a radius larger than any rotor's (over 150 m)" in found["detail"]
    assert "balancing.correction_radius = 160 m" in found["detail"]
    assert f"balancing.planes[1] = 1200 m lies {1200.0 - 0.0:g} m from balancing.masses[0].plane = 0 m" in found["detail"]
    assert "divide them by 1000" in told


def test_a_machines_shaft_in_millimetres_is_warned_of(tmp_path, capsys):
    """The hunter's V8: d = 30 and L = 800 meant as millimetres whirled at 0.126 mm, the shaft absurdly stiff."""
    told, results, note = _run(tmp_path, "[vibration]\nmass = 20.0\nunbalanced_mass = 0.5\neccentricity = 2.0\n"
                                         "shaft = { modulus = 2.1e11, diameter = 30.0, length = 800.0 }\n"
                                         "damping_ratio = 0.05\nrpm = 3000.0\n", capsys)
    line = ("vibration.shaft.diameter = 30 m is thicker than any shaft (over 5 m); vibration.shaft.length = 800 m is "
            "longer than any shaft between its bearings (over 50 m)")
    assert f"warning: vibration: {line}" in told
    (found,) = results["vibration"]["warnings"]
    assert found["code"] == "lengths-in-mm" and found["detail"].startswith(line)
    assert "Caution: as metres, the shaft's diameter d = 30 m is larger than any shaft's" in note


def test_an_eccentricity_and_a_second_moment_in_millimetres_are_warned_of(tmp_path, capsys):
    second = math.pi * 30.0 ** 4 / 64.0  # a 30 mm shaft's I in mm⁴
    _, results, _ = _run(tmp_path, "[vibration]\nmass = 20.0\nunbalanced_mass = 0.5\neccentricity = 200.0\n"
                                   f"shaft = {{ modulus = 2.1e11, second_moment = {second!r}, length = 0.8 }}\n"
                                   "damping_ratio = 0.05\nrpm = 3000.0\n", capsys)
    (found,) = results["vibration"]["warnings"]
    assert "vibration.eccentricity = 200 m is larger than any rotor's radius (over 150 m)" in found["detail"]
    limit = math.pi * 5.0 ** 4 / 64.0
    assert f"vibration.shaft.second_moment = {second:g} m⁴ is more than any shaft's (over {limit:.3g} m⁴" \
           in found["detail"]
    assert "a second moment of area by 10¹²" in found["detail"]


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_base_amplitude_in_millimetres_is_told_by_the_speed_it_gives_the_base(tmp_path, capsys, locale):
    """Y = 2 meant as 2 mm at 450 rpm moves the floor at 94 m/s; or ω was given in rev/min."""
    omega = 450.0 * 2.0 * math.pi / 60.0
    told, results, note = _run(tmp_path, "[vibration]\nmass = 50.0\nunbalance = 0.0\nstiffness = 2.0e5\n"
                                         "damping_ratio = 0.2\nrpm = 450.0\nbase_amplitude = 2.0\n", capsys, locale)
    speed = 2.0 * omega
    line = f"vibration.base_amplitude = 2 m at ω = {omega:.4g} rad/s moves the base at Y·ω = {speed:.4g} m/s"
    assert line in told and "unless ω is too large" in told
    assert any(found["code"] == "lengths-in-mm" and line in found["detail"]
               for found in results["vibration"]["warnings"])
    written = f"{speed:.4g}".replace(".", "," if locale == "ru" else ".")
    assert f"Y·ω = {written} " in note


@pytest.mark.parametrize("body", [
    # A wind turbine's blade at 40 m, corrected at the same radius: a real machine.
    ("[balancing]\nmasses = [{ mass = 900.0, radius = 40.0, angle = 0.0 }, { mass = 880.0, radius = 40.0, angle = 120.0 }]"
     "\ncorrection_radius = 40.0\n"),
    # A disc's eccentricity of 0.05 mm corrected at 0.2 m: the correction far outside the mass is real.
    "[balancing]\nmasses = [{ mass = 10.0, radius = 5.0e-5, angle = 30.0 }]\ncorrection_radius = 0.2\n",
    # A turbine-generator rotor 12 m long on a 0.6 m shaft; a floor shaken 0.5 mm at 1500 rpm.
    ("[vibration]\nmass = 2000.0\nunbalance = 0.01\nshaft = { modulus = 2.1e11, diameter = 0.6, length = 12.0 }\n"
     "damping_ratio = 0.02\nrpm = 1500.0\nbase_amplitude = 0.0005\n"),
])
def test_real_machines_are_not_told_their_lengths_are_millimetres(tmp_path, capsys, body):
    told, results, note = _run(tmp_path, body, capsys)
    part = "balancing" if body.startswith("[balancing]") else "vibration"
    assert "lengths-in-mm" not in {found["code"] for found in results[part]["warnings"]}
    assert "millimetres" not in told and "millimetres" not in note


@pytest.mark.parametrize("scene", [*FIXTURES, *STARTERS], ids=str)
def test_no_fixture_or_starter_is_told_its_lengths_are_millimetres(tmp_path, capsys, scene):
    if isinstance(scene, str):
        path = tmp_path / f"{scene}.toml"
        path.write_text(starter(scene, "en"), encoding="utf-8")
    else:
        path = scene
    assert main(["check", str(path)]) == 0
    assert "millimetres" not in capsys.readouterr().out
