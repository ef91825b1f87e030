"""Three slips a student makes that ran without a word: a damping ratio of 1 typed for 1 %, a rotor's balancing
masses typed in grams, a driving crank's mass typed in grams with no inertia to judge it by.  Each bound is checked
against a hand calculation written here, and a sensible value (ζ = 0.05, 0.2 kg at 0.1 m, a 2 kg crank of 0.1 m)
against no warning."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

import graphplan
from graphplan.cli import main
from graphplan.starters import starter
from graphplan.units import STEEL_DENSITY
from graphplan.vibration import damping_warning

STEEL = 7850.0  # kg/m³


def _scene(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _changed(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


def _run(tmp_path: Path, text: str, capsys, only: str) -> tuple[str, dict]:
    out = tmp_path / "out"
    assert main(["run", str(_scene(tmp_path, text)), "--out", str(out), "--only", only]) == 0
    told = capsys.readouterr().out
    return told, json.loads((out / "results.json").read_text(encoding="utf-8"))


# --- ζ = 1 typed for 1 % -------------------------------------------------------------------------------------------

def _rotor_with_damping(zeta: str) -> str:
    return _changed(starter("rotor", "en"), "damping_ratio = 0.1 ", f"damping_ratio = {zeta} ")


def test_a_damping_ratio_of_one_is_asked_whether_it_is_one_percent(tmp_path, capsys) -> None:
    """ζ = 1 is critical damping, which no mount has; typed as 1 it is 1 %, ζ = 0.01 (1/100, by hand)."""
    scene = graphplan.load_text(_rotor_with_damping("1"))
    line = damping_warning(scene.vibration)
    assert line is not None and line.startswith("vibration.damping_ratio: ζ = 1 is read as a ratio, critical damping")
    assert line.endswith("a percentage typed for a fraction? (1 % is ζ = 0.01)")
    told, _ = _run(tmp_path, _rotor_with_damping("1"), capsys, "vibration")
    assert "vibration.damping_ratio: ζ = 1 is read as a ratio" in told


@pytest.mark.parametrize("zeta", ["0.05", "0.7", "0.999"])
def test_a_damping_ratio_below_one_is_not_told(zeta) -> None:
    """0.05 a rubber mount's, 0.7 an instrument's design damping: real, so no word."""
    assert damping_warning(graphplan.load_text(_rotor_with_damping(zeta)).vibration) is None


# --- a rotor's masses in grams -------------------------------------------------------------------------------------

def _disc(masses: tuple[float, ...], radii: tuple[float, ...], correction: float = 0.1) -> str:
    """A disc balanced in one plane, every mass in it, its correction at ``correction`` m."""
    listed = ",\n           ".join(f"{{ mass = {mass!r}, radius = {radius!r}, angle = {angle!r} }}"
                                   for mass, radius, angle in zip(masses, radii, (0.0, 100.0, 230.0, 300.0)))
    return (f'[scene]\ntitle = "Disc"\nlocale = "en"\n\n[balancing]\nmasses = [ {listed} ]\n'
            f"correction_radius = {correction!r}\n")


def _in_grams(results: dict) -> list[str]:
    return [found["detail"] for found in results["balancing"]["warnings"] if found["code"] == "masses-in-grams"]


# A disc whose largest length is 0.1 m (its correction's radius and its masses' farthest): the masses of a rotor weigh
# together at most solid steel filling a cylinder twice that in radius and long, π·(0.2 m)²·0.2 m·7850 kg/m³.
DISC_BOUND = math.pi * 0.2 ** 2 * 0.2 * STEEL  # 197.3 kg


def test_a_discs_masses_in_grams_are_warned_of(tmp_path, capsys) -> None:
    """200, 150 and 250 g on a disc 0.1 m in radius typed as kg: 600 kg, three times the cylinder's 197 kg."""
    assert 600.0 > DISC_BOUND
    told, results = _run(tmp_path, _disc((200.0, 150.0, 250.0), (0.1, 0.08, 0.1)), capsys, "balancing,note")
    words = (f"balancing.masses[2].mass = 250 kg, the masses 600 kg together, on a rotor 0.1 m in radius "
             f"(balancing.masses[0].radius) and 0.1 m long (its radius: its masses and planes lie 0 m apart along the "
             f"axis, within a disc's thickness): heavier than solid steel filling a cylinder twice that in radius and "
             f"in length ({DISC_BOUND:.3g} kg): grams typed for kg? 250 g is balancing.masses[2].mass = 0.25")
    assert f"warning: balancing: {words}" in told
    assert any(words in detail for detail in _in_grams(results))
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert (f"Caution: the masses weigh 600 kg together, more than solid steel filling a cylinder twice the rotor's "
            f"size, 0.2 m in radius and 0.2 m long, {DISC_BOUND:.3g} kg: they look typed in grams. As grams the "
            "heaviest, 250 g, is 0.25 kg.") in note


@pytest.mark.parametrize(("masses", "told"), [((70.0, 60.0, 70.0), True), ((65.0, 60.0, 65.0), False),
                                              ((0.2, 0.15, 0.25), False)])
def test_the_discs_bound_is_the_steel_cylinders(tmp_path, capsys, masses, told) -> None:
    """200 kg in all is over the hand-computed 197.3 kg, 190 kg under it; 0.2 kg at 0.1 m is a real disc's mass."""
    assert (sum(masses) > DISC_BOUND) == told
    _, results = _run(tmp_path, _disc(masses, (0.1, 0.08, 0.1)), capsys, "balancing")
    assert bool(_in_grams(results)) == told


KHURMI_DISC = _disc((200.0, 300.0, 240.0, 260.0), (0.2, 0.15, 0.25, 0.3), correction=0.2)
KHURMI_SHAFT = """[scene]
title = "Shaft"
[balancing]
masses = [ { mass = 200.0, radius = 0.08, angle = 0.0, plane = 0.0 },
           { mass = 300.0, radius = 0.07, angle = 45.0, plane = 0.3 },
           { mass = 400.0, radius = 0.06, angle = 115.0, plane = 0.4 },
           { mass = 200.0, radius = 0.08, angle = 235.0, plane = 0.7 } ]
planes = [0.1, 0.5]
correction_radius = 0.1
"""
ONE_ECCENTRIC_FLYWHEEL = """[scene]
title = "Flywheel"
[balancing]
masses = [ { mass = 500.0, radius = 0.002, angle = 0.0 } ]
"""


@pytest.mark.parametrize("text", [KHURMI_DISC, KHURMI_SHAFT, ONE_ECCENTRIC_FLYWHEEL],
                         ids=["khurmi-one-plane", "khurmi-two-planes", "one-eccentric-disc"])
def test_heavy_textbook_rotors_are_not_told_their_masses_are_grams(tmp_path, capsys, text) -> None:
    """Khurmi's 1000 kg within 0.3 m (by hand π·0.6²·0.6·7850 = 5328 kg) and 1100 kg along 0.7 m (67 700 kg) are
    heavy for their size but in kg; a single mass's radius may be a whole disc's eccentricity, which bounds nothing."""
    _, results = _run(tmp_path, text, capsys, "balancing")
    assert not _in_grams(results)


def _shaft(masses: tuple[float, ...], radii: tuple[float, ...], correction: float | None) -> str:
    """A rotor balanced in two planes 0.3 m apart, its masses in planes 0, 0.15 and 0.3 m along the axis."""
    listed = ",\n           ".join(f"{{ mass = {mass!r}, radius = {radius!r}, angle = {angle!r}, plane = {plane!r} }}"
                                   for mass, radius, angle, plane in zip(masses, radii, (0.0, 100.0, 230.0),
                                                                         (0.0, 0.15, 0.3)))
    corrected = "" if correction is None else f"correction_radius = {correction!r}\n"
    return (f'[scene]\ntitle = "Shaft"\nlocale = "en"\n\n[balancing]\nmasses = [ {listed} ]\n'
            f"planes = [0.0, 0.3]\n{corrected}")


# A rotor whose masses and corrections turn within 0.05 m of its axis over 0.3 m along it: the masses of a rotor weigh
# together at most solid steel filling a cylinder twice that radius and twice that length, π·(0.1 m)²·0.6 m·ρ.  Its
# largest length, the span, would bound it by a cylinder 0.6 m in radius, π·(0.6 m)²·0.6 m·ρ = 5327 kg.
SHAFT_BOUND = math.pi * 0.1 ** 2 * 0.6 * STEEL_DENSITY  # 148.0 kg


def test_a_two_plane_rotors_masses_in_grams_are_warned_of(tmp_path, capsys) -> None:
    """200, 150 and 250 g at 0.03–0.05 m over 0.3 m typed as kg: 600 kg, four times the cylinder's 148 kg, though
    less than one as wide as the rotor is long."""
    assert 600.0 > SHAFT_BOUND and 600.0 < math.pi * 0.6 ** 2 * 0.6 * STEEL_DENSITY
    told, results = _run(tmp_path, _shaft((200.0, 150.0, 250.0), (0.03, 0.05, 0.04), 0.05), capsys, "balancing,note")
    words = (f"balancing.masses[2].mass = 250 kg, the masses 600 kg together, on a rotor 0.05 m in radius "
             f"(balancing.masses[1].radius) and 0.3 m long (the masses' and planes' span along the axis): heavier than "
             f"solid steel filling a cylinder twice that in radius and in length ({SHAFT_BOUND:.3g} kg): grams typed "
             f"for kg? 250 g is balancing.masses[2].mass = 0.25")
    assert f"warning: balancing: {words}" in told
    assert [detail for detail in _in_grams(results) if words in detail] == _in_grams(results) != []
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert (f"Caution: the masses weigh 600 kg together, more than solid steel filling a cylinder twice the rotor's "
            f"size, 0.1 m in radius and 0.6 m long, {SHAFT_BOUND:.3g} kg: they look typed in grams.") in note


@pytest.mark.parametrize(("masses", "told"), [((50.0, 50.0, 50.0), True), ((45.0, 50.0, 45.0), False),
                                              ((0.2, 0.15, 0.25), False)])
def test_the_two_plane_rotors_bound_weighs_its_radius_and_length_apart(tmp_path, capsys, masses, told) -> None:
    """150 kg in all is over the hand-computed 148.0 kg, 140 kg under it; 0.2 kg at 0.05 m is a real rotor's mass."""
    assert (sum(masses) > SHAFT_BOUND) == told
    _, results = _run(tmp_path, _shaft(masses, (0.03, 0.05, 0.04), 0.05), capsys, "balancing")
    assert bool(_in_grams(results)) == told


def test_eccentric_discs_on_a_shaft_without_a_correction_radius_are_not_told(tmp_path, capsys) -> None:
    """Discs of 500, 400 and 500 kg keyed 2–3 mm off their centres: the eccentricities bound no rotor's radius
    (π·(0.006 m)²·0.6 m·ρ = 0.53 kg), so without a correction radius the rotor is taken as wide as it is long,
    π·(0.6 m)²·0.6 m·ρ = 5327 kg; with one of 0.2 m, π·(0.4 m)²·0.6 m·ρ = 2367 kg, more than their 1400 kg."""
    eccentric = (500.0, 400.0, 500.0), (0.002, 0.003, 0.002)
    assert 1400.0 < math.pi * 0.6 ** 2 * 0.6 * STEEL_DENSITY and 1400.0 < math.pi * 0.4 ** 2 * 0.6 * STEEL_DENSITY
    for correction in (None, 0.2):
        _, results = _run(tmp_path, _shaft(*eccentric, correction), capsys, "balancing")
        assert not _in_grams(results)


def _steel_reach_over_the_shaft(mass: float) -> float:
    """How far from the axis solid steel of ``mass`` (kg) reaches as a cylinder as long as the shaft, 0.3 m."""
    return math.sqrt(mass / (STEEL * math.pi * 0.3))


@pytest.mark.parametrize(("masses", "radii"), [((500.0, 500.0), (0.002, 0.002)),
                                              ((500.0, 400.0, 500.0), (0.002, 0.003, 0.002))],
                         ids=["two-discs", "three-discs"])
def test_heavy_eccentric_discs_corrected_near_the_axis_are_not_told(tmp_path, capsys, masses, radii) -> None:
    """Discs of 500 kg keyed 2–3 mm off their centres, corrected at 0.01 m (on a collar of the shaft: their own
    radius is not in the scene), were told they were grams: as kg they outweigh the cylinder the radii give,
    π·(0.02 m)²·0.6 m·ρ = 5.92 kg, but typed in grams they would too, for no lump fixed out where it turns is larger
    than the circle it turns in: 1 or 1.4 kg of solid steel over the shaft's 0.3 m reaches 11.6 or 13.8 mm from the
    axis, past the 2–3 mm they turn at.  Their radii are eccentricities, which grams would not explain."""
    assert sum(masses) > math.pi * 0.02 ** 2 * 0.6 * STEEL
    assert _steel_reach_over_the_shaft(sum(masses) / 1000) > max(radii)
    told, results = _run(tmp_path, _shaft(masses, radii, 0.01), capsys, "balancing")
    assert not _in_grams(results) and "grams typed for kg" not in told


# At radii to 0.01 m over 0.3 m, corrected at 0.01 m, masses of 700 and 800 (kg) both outweigh the cylinder the radii
# give, π·(0.02 m)²·0.6 m·ρ = 5.92 kg.  As grams, solid steel filling the circle the farthest turns in over the shaft,
# π·(0.01 m)²·0.3 m·ρ = 0.740 kg, holds 0.7 kg (lumps fixed out where they turn, a slip) but not 0.8 kg (bodies round
# the axis whatever the unit, their radii eccentricities).
LUMPS_AT_ONE_CENTIMETRE = math.pi * 0.01 ** 2 * 0.3 * STEEL  # 0.740 kg


@pytest.mark.parametrize(("masses", "told"), [((200.0, 300.0, 200.0), True), ((250.0, 300.0, 250.0), False)])
def test_masses_are_told_grams_only_where_as_grams_they_lie_within_their_radii(tmp_path, capsys, masses,
                                                                               told) -> None:
    assert sum(masses) > math.pi * 0.02 ** 2 * 0.6 * STEEL
    assert (sum(masses) / 1000 <= LUMPS_AT_ONE_CENTIMETRE) == told
    assert (_steel_reach_over_the_shaft(sum(masses) / 1000) <= 0.01) == told
    _, results = _run(tmp_path, _shaft(masses, (0.01, 0.008, 0.01), 0.01), capsys, "balancing")
    assert bool(_in_grams(results)) == told


# --- a crank's mass in grams, no inertia given ---------------------------------------------------------------------

def _crank_of_a_tenth(mass: float) -> str:
    """The crank-rocker starter with its crank OA = 0.1 m given ``mass`` at S2 and no inertia."""
    text = _changed(starter("crank-rocker", "en"), "length  = 0.175", "length  = 0.1")
    return _changed(text, "[links.3]", f'[links.2]\nmass    = {mass!r}\ncentre  = "S2"\n\n[links.3]')


# The crank, 0.1 m, may carry a throw's webs and counterweights: a solid steel cylinder twice its length in radius and
# twice it long holds them, π·(0.2 m)²·0.2 m·7850 kg/m³.
CRANK_BOUND = math.pi * 0.2 ** 2 * 0.2 * STEEL  # 197.3 kg


def test_a_cranks_mass_in_grams_without_inertia_is_warned_of(tmp_path, capsys) -> None:
    """500 g of a 0.1 m crank typed as 500: over the cylinder's 197 kg and the bar's 0.1 m square, 7.85 kg."""
    bar = STEEL * 0.1 * 0.1 ** 2
    words = (f"links.2.mass = 500 kg on a link 0.1 m long (A–O), heavier than a solid steel bar of that length "
             f"({bar:.3g} kg), and than a steel cylinder 0.2 m in radius and long (2 × max(l, 0.1 m)), which holds a "
             f"crankshaft's throw with its counterweights ({CRANK_BOUND:.3g} kg; a flywheel on the crank: give "
             "links.2.inertia): grams typed for kg? 500 g is links.2.mass = 0.5")
    told, results = _run(tmp_path, _crank_of_a_tenth(500.0), capsys, "note")
    assert words in told
    assert any(found["code"] == "masses-in-grams" and words in found["detail"] for found in results["warnings"])


@pytest.mark.parametrize(("mass", "told"), [(2.0, False), (190.0, False), (200.0, True)])
def test_the_cranks_bound_is_the_steel_cylinders(tmp_path, capsys, mass, told) -> None:
    """A course's 2 kg crank of 0.1 m is not told, nor 190 kg under the hand-computed 197.3 kg; 200 kg is."""
    assert (mass > CRANK_BOUND) == told
    _, results = _run(tmp_path, _crank_of_a_tenth(mass), capsys, "note")
    assert any(found["code"] == "masses-in-grams" for found in results["warnings"]) == told


# --- the starters say nothing new ----------------------------------------------------------------------------------

@pytest.mark.parametrize("kind", ["rotor", "flywheel"])
def test_the_starters_run_without_these_warnings(tmp_path, capsys, kind) -> None:
    path = tmp_path / f"{kind}.toml"
    assert main(["new", kind, "--out", str(path)]) == 0
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    told = capsys.readouterr().out
    assert "grams typed for kg" not in told and "read as a ratio" not in told
