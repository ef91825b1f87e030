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


def _three(value: float) -> str:
    """Three significant digits written whole, as the warnings write them: 31800, not 3.18e+04."""
    return f"{float(f'{value:.3g}'):.12g}"


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
    assert err.startswith(f"graphplan: error: dynamics.motor: its torque on the shaft, {25.0 * 20.0:.5g} N·m, "
                          f"exceeds the mean resistance, {_press_mean_resistance():.5g} N·m, at every speed")
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


# --- masses in grams -----------------------------------------------------------------------------------------------

STEEL = 7850.0


def _run(tmp_path: Path, text: str, capsys) -> tuple[str, dict, str]:
    import json

    out = tmp_path / "out"
    assert main(["run", str(_scene(tmp_path, text)), "--out", str(out), "--only", "note"]) == 0
    told = capsys.readouterr().out  # the warnings, under what the run wrote
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return told, results, (out / "note.md").read_text(encoding="utf-8")


def _in_grams(results: dict) -> list[str]:
    return [warning["detail"] for warning in results["warnings"] if warning["code"] == "masses-in-grams"]


def _with_crank(mass: float, inertia: float, centre: str = "S2") -> str:
    """The crank-rocker starter with its crank OA = 0.175 m given a mass; S2 lies 0.08 m out along it."""
    text = starter("crank-rocker", "en")
    crank = f'[links.2]\nmass    = {mass!r}\ncentre  = "{centre}"\ninertia = {inertia!r}\n'
    return text.replace("[links.3]", crank + "[links.3]", 1)


@pytest.mark.parametrize("inertia", [0.0102, 1000 * 0.0102])  # J from the true mass, or from the grams as well
def test_a_cranks_mass_in_grams_is_warned_of_by_its_inertia(tmp_path, capsys, inertia):
    """A 4 kg steel crank, 0.175 m, J = m·l²/12 = 0.0102 kg·m², its mass typed as 4000 (grams): the crank was left
    out of the bound, for the flywheel or counterweights it may carry. A steel body of mass m whose J about its
    centre is J covers at most the disc of radius √(2J/m) (area 2π·J/m) in the plane, so it is at least
    m / (ρ·2π·J/m) long along its axis: 31.8 km, or 31.8 m with J in grams too, no crank's 0.175 m × 50."""
    bar = STEEL * 0.175 * 0.175 ** 2  # a solid steel bar 0.175 m square, 42.1 kg
    depth = 4000.0 / (STEEL * 2 * math.pi * inertia / 4000.0)
    words = (f"links.2.mass = 4000 kg on a link 0.175 m long (A–O), heavier than a solid steel bar of that length "
             f"({_three(bar)} kg), and too compact for a flywheel or counterweights: with links.2.inertia = "
             f"{inertia:g} kg·m², as steel it would reach {_three(depth)} m along its axis: grams typed for kg? "
             "4000 g is links.2.mass = 4")
    told, results, note = _run(tmp_path, _with_crank(4000.0, inertia), capsys)
    assert words in told and any(words in detail for detail in _in_grams(results))
    assert "the masses were probably given in grams" in note
    told, results, _ = _run(tmp_path, _with_crank(4.0, 0.0102), capsys)
    assert not _in_grams(results) and "grams typed for kg" not in told


@pytest.mark.parametrize(("mass", "inertia", "centre", "what"), [
    (400.0, 60.0, "O", "a flywheel of 400 kg on the crank, its centre on the axis"),
    (400.0, 60.0, "S2", "the same flywheel lumped with its centre left at the crank's"),
    (60.0, 0.6, "A", "an eccentric's sheave 0.2 m in radius, 0.06 m thick, its centre at the pin"),
    (60.0, 0.02, "A", "a crankshaft's throw lumped at the pin, 3.6 m long as steel"),
    (60.0, 0.0, "S2", "a heavy crank given no inertia: nothing tells a bar from a sheave"),
])
def test_a_crank_that_carries_more_than_a_bar_is_not_warned_of(tmp_path, capsys, mass, inertia, centre, what):
    assert mass > STEEL * 0.175 ** 3  # each is heavier than the bar bound, 42.1 kg
    _, results, _ = _run(tmp_path, _with_crank(mass, inertia, centre), capsys)
    assert not _in_grams(results), what


def _long_crank_rocker(rocker_mass: float, lever_mass: float) -> str:
    """The crank-rocker starter ten times as large (a pumpjack's size), its links 40 kg a metre."""
    text = starter("crank-rocker", "en")
    for old, new in [("C = [0.0, 0.55]", "C = [0.0, 5.5]"), ("length  = 0.175", "length  = 1.75"),
                     ("omega   = -17.0", "omega   = -1.7"), ("lengths  = [0.55, 0.325]", "lengths  = [5.5, 3.25]"),
                     ("at = 0.08", "at = 0.8"), ("at = 0.24", "at = 2.4"), ("at = 0.14", "at = 1.4"),
                     ("mass    = 17.0\ncentre  = \"S3\"\ninertia = 0.51",
                      f"mass    = {rocker_mass!r}\ncentre  = \"S3\"\ninertia = 555.0"),
                     ("mass    = 17.0\ncentre  = \"S4\"\ninertia = 0.18",
                      f"mass    = {lever_mass!r}\ncentre  = \"S4\"\ninertia = 115.0"),
                     ("value     = 1500.0", "value     = 150000.0")]:
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


def test_a_long_links_mass_in_grams_is_warned_of(tmp_path, capsys):
    """220 kg over 5.5 m and 130 kg over 3.25 m typed in grams: the cube bound, ρ·l³ (1.31e6 and 2.69e5 kg), let
    both by; no link is thicker than a metre square, 7850 kg a metre."""
    told, results, _ = _run(tmp_path, _long_crank_rocker(220000.0, 130000.0), capsys)
    details = " ".join(_in_grams(results))
    for key, mass, length in (("links.3", 220000.0, 5.5), ("links.4", 130000.0, 3.25)):
        bar = f"({_three(STEEL * length)} kg): grams typed for kg? {mass:g} g is {key}.mass = {mass / 1000:g}"
        words = (f"{key}.mass = {mass:g} kg on a link {_three(length)} m long", bar)
        assert all(part in details and part in told for part in words)
    _, results, _ = _run(tmp_path, _long_crank_rocker(220.0, 130.0), capsys)
    assert not _in_grams(results)


# --- a disc's radius in millimetres --------------------------------------------------------------------------------

def _disc(radii: tuple[float, float, float], correction: float | None, planes: str = "0.0, 0.08, 0.16",
          plane: float = 0.04) -> str:
    """The rotor starter balanced in one plane, at z = ``plane``, its masses at the radii given and in the planes
    given."""
    text = starter("rotor", "en")
    zs = [z.strip() for z in planes.split(",")]
    for old, radius, z in zip(("radius = 0.05, angle = 0.0, plane = 0.0", "radius = 0.06, angle = -60.0, plane = 0.08",
                               "radius = 0.04, angle = 135.0, plane = 0.16"), radii, zs, strict=True):
        assert old in text
        angle = old.split("angle = ")[1].split(",")[0]
        text = text.replace(old, f"radius = {radius!r}, angle = {angle}, plane = {z}", 1)
    text = text.replace("planes = [0.04, 0.22]", f"planes = [{plane!r}]", 1)
    line = "correction_radius = 0.05"
    return text.replace(line, "" if correction is None else f"correction_radius = {correction!r}", 1)


def _run_rotor(tmp_path: Path, text: str, capsys) -> tuple[str, list[dict], str]:
    import json

    out = tmp_path / "out"
    assert main(["run", str(_scene(tmp_path, text)), "--out", str(out), "--only", "note,balancing"]) == 0
    told = capsys.readouterr().out
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    in_mm = [warning for warning in results["balancing"]["warnings"] if warning["code"] == "lengths-in-mm"]
    return told, in_mm, (out / "note.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("correction", [None, 50.0])
def test_a_discs_radii_in_millimetres_among_planes_in_metres_are_warned_of(tmp_path, capsys, correction):
    """Radii 50, 60, 40 (mm) over masses 0.16 m apart along the axis, corrected in one plane: below the 150 m of any
    rotor, and with no correction radius in metres to set them against; a disc 0.16 m thick is no 60 m across."""
    told, in_mm, note = _run_rotor(tmp_path, _disc((50.0, 60.0, 40.0), correction), capsys)
    words = (f"balancing.masses[1].radius = 60 m is {60.0 / 0.16:.3g} times the 0.16 m its masses and correction "
             "plane lie apart along the axis, from balancing.masses[0].plane to balancing.masses[2].plane")
    assert f"warning: balancing: {words}" in told and "as millimetres, balancing.masses[1].radius = 0.06" in told
    assert any(words in warning["detail"] for warning in in_mm)
    assert f"mass 2's radius, 60 m, is {60.0 / 0.16:.3g} times the 0.16 m" in note


@pytest.mark.parametrize(("radii", "planes", "plane", "what"), [
    ((0.05, 0.06, 0.04), "0.0, 0.08, 0.16", 0.04, "the starter's rotor in metres, statically balanced"),
    # A circular saw's blade, 0.3 m in radius and 3 mm thick, its masses on both faces: 100 times.
    ((0.3, 0.25, 0.3), "0.0, 0.003, 0.0", 0.0015, "a saw blade"),
    ((0.4, 0.5, 0.45), "0.0, 0.02, 0.01", 0.01, "a flywheel's rim 1 m across, 20 mm wide"),
])
def test_a_real_disc_is_not_told_its_radii_are_millimetres(tmp_path, capsys, radii, planes, plane, what):
    _, in_mm, _ = _run_rotor(tmp_path, _disc(radii, None, planes, plane), capsys)
    assert not in_mm, what


def test_the_disc_warning_is_in_every_language_of_the_note():
    from graphplan.locale import strings

    for locale in ("en", "ru", "zh"):
        text = strings(locale)["note_len_thin_disc"]
        assert all(field in text for field in ("{name}", "{value}", "{ratio}", "{other}", "{limit}")), locale


# --- no real scene told --------------------------------------------------------------------------------------------

ROOT = Path(__file__).resolve().parent.parent
SCENES = sorted((ROOT / "fixtures").glob("*.toml")) + sorted((ROOT / "tests" / "scenes").glob("*.toml"))
STARTERS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad", "flywheel", "rotor")


@pytest.mark.parametrize("scene", [*SCENES, *STARTERS], ids=lambda scene: getattr(scene, "name", scene))
def test_no_fixture_test_scene_or_starter_is_told_of_these_slips(tmp_path, scene):
    """Among them the engine's and the compressor's counterweighted cranks, 1.1 and 1.4 times the bar of their
    length, and the rotor starter's masses 0.16 m apart at radii to 0.06 m."""
    from graphplan.analysis import analyse
    from graphplan.deliverables import outcome_warnings
    from graphplan.scene import load

    loaded = load(_scene(tmp_path, starter(scene, "en")) if isinstance(scene, str) else scene)
    pieces = ("note", *(piece for piece in ("dynamics", "vibration", "balancing") if getattr(loaded, piece)))
    told = list(outcome_warnings(loaded, pieces, None))
    if loaded.driver is not None:
        warnings = analyse(loaded).warnings
        assert not [warning for warning in warnings
                    if warning.code in ("masses-in-grams", "centre-as-share", "load-in-kn")]
        told += [warning.detail for warning in warnings]
    assert not [line for line in told if "too compact for a flywheel" in line or "lie apart along the axis" in line]
