"""Where ω is largest and smallest, and which plan position is which point, are told on the dynamics drawing.

A course project marks on ΔT(φ) the crank angles of ωmax and ωmin, and numbers the plan positions' points on the
energy–mass diagram as on the other diagrams; the note names the angles of ωmax and ωmin also where no flywheel is
needed.  Each is checked against ``results.json`` read through the drawing's own scales: μφ and μT as its scale line
states them, the origin where its axes start.  The speed itself is worked out afresh from the results' arrays,
ω = √(2·(T0 + ΔT)/(Je + JF)), so that the marks are checked to stand where the machine runs fastest and slowest,
not merely where the code says.
"""

from __future__ import annotations

import json
import math
import re
from xml.etree import ElementTree

import numpy as np
import pytest
from test_no_flywheel_said_in_words import HEAVY_CRANK
from test_no_flywheel_said_in_words import run as run_compressor

from graphplan.cli import main

SVG = "{http://www.w3.org/2000/svg}"
TANGENT_COLOUR = "#b22222"


@pytest.fixture(scope="module")
def shaper_dynamics(tmp_path_factory) -> tuple[ElementTree.Element, dict]:
    """The shaper of ``graphplan new shaper``: a velocity plan at each of its twelve positions, δ = 0.05.  Its
    dynamics.svg and results.json, run once for the two tests that read them (each ran the same run)."""
    tmp_path = tmp_path_factory.mktemp("shaper")
    scene = tmp_path / "shaper.toml"
    assert main(["new", "shaper", "--out", str(scene)]) == 0
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
    return ElementTree.parse(out / "dynamics.svg").getroot(), json.loads((out / "results.json").read_text("utf-8"))


def _group(drawing: ElementTree.Element, name: str) -> ElementTree.Element:
    return next(g for g in drawing.iter(f"{SVG}g") if g.get("id") == name)


def _texts(group: ElementTree.Element) -> list[tuple[str, float, float]]:
    return [("".join(t.itertext()), float(t.get("x")), float(t.get("y"))) for t in group.iter(f"{SVG}text")]


def _segments(group: ElementTree.Element, colour: str | None = None) -> list[tuple[float, float, float, float]]:
    """The two-point paths of a group (its straight lines), as (x0, y0, x1, y1) in the SVG's mm, y down."""
    found = []
    for path in group.iter(f"{SVG}path"):
        if colour is not None and path.get("stroke") != colour:
            continue
        numbers = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", path.get("d"))]
        if len(numbers) == 4 and path.get("fill") == "none":
            found.append(tuple(numbers))
    return found


def _scale(group: ElementTree.Element, pattern: str) -> float:
    """A scale factor as the diagram's scale line writes it."""
    for text, _, _ in _texts(group):
        match = re.search(pattern, text)
        if match:
            return float(match.group(1))
    raise AssertionError(f"no {pattern} on the diagram")


def _speed(dynamics: dict) -> np.ndarray:
    """ω at every sample from energy alone: T = T0 + ΔT = (Je + JF)·ω²/2."""
    energy = dynamics["kinetic_energy_start"] + np.array(dynamics["kinetic_energy_change"])
    inertia = np.array(dynamics["reduced_inertia"]) + dynamics["flywheel_inertia"]
    return np.sqrt(2.0 * energy / inertia)


def test_the_angles_of_omega_max_and_omega_min_are_marked_on_the_energy_diagram(shaper_dynamics):
    drawing, results = shaper_dynamics
    dynamics = results["dynamics"]
    energy = _group(drawing, "energy")
    degrees_per_mm = _scale(energy, r"μφ = ([\d.]+)°/mm")
    joules_per_mm = _scale(energy, r"μT = ([\d.]+) J/mm")
    # The φ axis: the horizontal shaft the diagram's arrows start with; its start is φ = 0, ΔT = 0.
    axis = next(s for s in _segments(energy) if s[1] == s[3] and s[2] > s[0] + 100.0)
    origin_x, origin_y = axis[0], axis[1]
    travel = np.degrees(np.array(dynamics["travel"]))
    speed = _speed(dynamics)
    assert float(np.max(speed[:-1])) == pytest.approx(dynamics["omega_max"], rel=1e-6)
    marks = [s for s in _segments(energy, TANGENT_COLOUR) if s[0] == s[2]]
    labels = {text: (x, y) for text, x, y in _texts(energy) if text in ("ωmax", "ωmin")}
    assert set(labels) == {"ωmax", "ωmin"}
    for name, index in (("ωmax", int(np.argmax(speed[:-1]))), ("ωmin", int(np.argmin(speed[:-1])))):
        assert travel[index] == pytest.approx(dynamics[f"{name.replace('ω', 'omega_')}_travel_deg"], abs=1e-6)
        x = origin_x + travel[index] / degrees_per_mm
        at = [s for s in marks if abs(s[0] - x) < 0.01]
        # A tick across the axis and an ordinate from the axis to the curve's ΔT there.
        assert any(min(s[1], s[3]) < origin_y < max(s[1], s[3]) for s in at), name
        curve_y = origin_y - dynamics["kinetic_energy_change"][index] / joules_per_mm
        assert any(sorted((s[1], s[3])) == pytest.approx(sorted((origin_y, curve_y)), abs=0.002) for s in at), name
        # Its name beside it: nearer its own tick than the other's.
        label_x, label_y = labels[name]
        assert math.hypot(label_x - x, label_y - origin_y) < 10.0, name
    assert abs(labels["ωmax"][0] - (origin_x + travel[int(np.argmax(speed[:-1]))] / degrees_per_mm)) < abs(
        labels["ωmax"][0] - (origin_x + travel[int(np.argmin(speed[:-1]))] / degrees_per_mm))


def test_the_plan_positions_are_numbered_on_the_energy_mass_diagram(shaper_dynamics):
    drawing, results = shaper_dynamics
    dynamics = results["dynamics"]
    diagram = _group(drawing, "energy-mass")
    mass_per_mm = _scale(diagram, r"μJ = ([\d.]+) kg·m²/mm")
    joules_per_mm = _scale(diagram, r"μT = ([\d.]+) J/mm")
    # The Je axis: the one horizontal arrow's shaft, from the origin Je = 0, ΔT = 0.
    (axis,) = [s for s in _segments(diagram, "black") if s[1] == s[3] and s[2] - s[0] > 50.0]
    origin_x, origin_y = axis[0], axis[1]
    dots = [(float(c.get("cx")), float(c.get("cy"))) for c in diagram.iter(f"{SVG}circle")
            if c.get("fill") == "black"]
    texts = _texts(diagram)
    angles = np.array(dynamics["angle_deg"])
    numbered = [plan["index"] for plan in dynamics["plans"]]
    assert len(numbered) >= 12
    expected = {}
    for position in results["positions"]:
        if position["index"] not in numbered:
            continue
        # The model's sample at the position's crank angle: Je and ΔT there.
        turn = np.abs((angles - position["driver"]["angle_deg"] + 180.0) % 360.0 - 180.0)
        sample = int(np.argmin(turn))
        assert turn[sample] < 1e-6
        expected[position["index"]] = (origin_x + dynamics["reduced_inertia"][sample] / mass_per_mm,
                                       origin_y - dynamics["kinetic_energy_change"][sample] / joules_per_mm)
    assert sorted(expected) == sorted(numbered)
    for number, (x, y) in expected.items():
        assert any(math.hypot(x - cx, y - cy) < 0.01 for cx, cy in dots), number
        # Its number beside it, nearer its own point than any other position's.
        near = [(tx, ty) for text, tx, ty in texts if text == str(number) and math.hypot(tx - x, ty - y) < 10.0
                and all(math.hypot(tx - x, ty - y) <= math.hypot(tx - ox, ty - oy) + 1e-9
                        for other, (ox, oy) in expected.items() if other != number)]
        assert len(near) == 1, number


@pytest.mark.parametrize(("locale", "speed"), [("en", "ωmax = {high} rad/s at φ = {angle}°"),
                                               ("ru", "ωmax = {high} рад/с при φ = {angle}°"),
                                               ("zh", "在 φ = {angle}° 时 ωmax = {high} rad/s")])
def test_the_note_names_the_angles_of_the_extreme_speeds_where_no_flywheel_is_needed(tmp_path, locale, speed):
    _, note, dynamics = run_compressor(tmp_path, locale, 500.0, HEAVY_CRANK)
    assert dynamics["flywheel_inertia"] == 0.0
    omega = _speed(dynamics)
    mark = "," if locale == "ru" else "."
    for name, index in (("max", int(np.argmax(omega[:-1]))), ("min", int(np.argmin(omega[:-1])))):
        angle = dynamics[f"omega_{name}_angle_deg"]
        assert angle == pytest.approx(dynamics["angle_deg"][index] % 360.0, abs=1e-6)
        told = speed.replace("max", name).format(
            high=f"{dynamics[f'omega_{name}']:.5g}".replace(".", mark), angle=f"{angle:.4g}".replace(".", mark))
        assert told in note, (told, [line for line in note.splitlines() if "ωmax" in line])
