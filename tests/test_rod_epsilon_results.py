"""An RPR's rod, which turns with its cylinder, has its ε in results.json and in the note's accelerations table.

The acceleration plan lays off no tangential component of the rod (its point E is laid off similar to the
cylinder's image), so ε3 is the cylinder's reading ε4.  A script reading results.json finds it under the rod's own
name with the pointer ``same_as``; a student reading the note finds a row ``ε3 = ε4`` where ω3 has its row.  The
value is checked against a central difference of the rod's angle taken from the geometry here (the rod's line
through C, ``offset`` to the left of it looking toward the block at A), not from the program's solver.
"""

import dataclasses
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from scene_texts import oscillating_cylinder

import graphplan
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown
from graphplan.report.results import results

OFFSET = 0.02
CRANK, PIVOT_C = 0.08, 0.30  # m: the scene's lOA and O→C along x
CRANK_OMEGA = 120 * 2 * math.pi / 60  # 120 rpm, uniform: ε3 = ω2²·d²φ3/dφ2²
STEP = 1e-3  # rad of the crank
EXTENSIONS = Path(__file__).resolve().parent.parent / "docs" / "scene-format-extensions.md"


def _scene(locale: str = "en"):
    """The oscillating cylinder with plans at all twelve positions, so that every position has its ε3 read."""
    text = oscillating_cylinder(OFFSET).replace("plans = [4, 10]", f"plans = {list(range(1, 13))}")
    return dataclasses.replace(graphplan.load_text(text), locale=locale)


def _rod_angle(crank: np.ndarray) -> np.ndarray:
    """The rod's direction u (rad, up to a constant): A − C = s·u + e·n, n the left normal of u, so u is the direction
    of C→A less asin(e/|CA|); C→A's direction taken as A→C's less 180°, A→C pointing along +x, away from atan2's cut
    at ±180°."""
    a = CRANK * np.exp(1j * crank)
    return np.angle(PIVOT_C - a) - np.arcsin(OFFSET / np.abs(a - PIVOT_C))


def _rod_epsilon(crank: float) -> float:
    angle = _rod_angle(np.array([crank - STEP, crank, crank + STEP]))
    return CRANK_OMEGA**2 * (angle[2] - 2 * angle[1] + angle[0]) / STEP**2


@pytest.fixture(scope="module")
def document():
    return json.loads(json.dumps(results(analyse(_scene()))))


def test_the_rods_epsilon_is_in_results_json_as_the_cylinders_reading(document):
    positions = document["positions"]
    cranks = np.radians([entry["driver"]["angle_deg"] for entry in positions])
    # The geometry here is the solver's: the rod turns by as much as the program's link 3 between any two positions.
    turned = np.unwrap(_rod_angle(cranks)) - np.unwrap(np.radians([entry["links"]["3"]["angle_deg"]
                                                                   for entry in positions]))
    assert turned == pytest.approx(np.full(len(turned), turned[0]), abs=1e-9)
    assert len(positions) == 12 and all("plans" in entry for entry in positions)
    for entry, crank in zip(positions, cranks, strict=True):
        expected = _rod_epsilon(float(crank))
        links = entry["links"]
        assert links["3"]["epsilon"] == pytest.approx(links["4"]["epsilon"], rel=1e-9)
        assert links["3"]["epsilon"] == pytest.approx(expected, rel=1e-5, abs=1e-4), entry["index"]
        acceleration = entry["plans"]["acceleration"]
        assert acceleration["same_as"] == {"epsilon3": "epsilon4"}
        assert acceleration["values"]["epsilon3"] == acceleration["values"]["epsilon4"]
        # The plan as constructed is exact up to the intersection's rounding.
        assert acceleration["values"]["epsilon3"] == pytest.approx(expected, rel=1e-5, abs=1e-4), entry["index"]
        # No pointer where ω3 is read off the rod's own segment.
        assert "same_as" not in entry["plans"]["velocity"]
        assert "omega3" in entry["plans"]["velocity"]["values"]
    # The error table keeps ε3 out: ε4's row is its reading.
    assert not [row for row in document["errors"] if row["quantity"] == "epsilon3"]
    assert any(line.startswith("| `positions[].plans.acceleration.same_as` |")
               for line in EXTENSIONS.read_text(encoding="utf-8").splitlines())


def _number(cell: str) -> float:
    return float(cell.replace("−", "-").replace(",", ".").replace("\u202f", "").replace(" ", ""))


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_notes_accelerations_table_has_the_rods_epsilon_row(locale):
    analysis = analyse(_scene(locale))
    lines = note_markdown(analysis).splitlines()
    drivers = graphplan.solve(_scene()).driver
    found = [i for i, line in enumerate(lines) if line.startswith("| ε3 = ε4 |")]
    assert len(found) == len(analysis.plans) == 12
    for i, position in zip(found, analysis.plans, strict=True):
        expected = _rod_epsilon(float(drivers[position.index]))
        row = [cell.strip() for cell in lines[i].strip("|").split("|")]
        above = [cell.strip() for cell in lines[i - 1].strip("|").split("|")]
        # Right under ε4's row, read off the same segment, in the same unit: the table of accelerations.
        assert above[0] == "ε4" and row[1:4] == above[1:4] and row[5] == above[5]
        assert re.fullmatch(r"\S+/\S+²", row[5]), row
        for cell in (row[3], row[4]):
            assert _number(cell) == pytest.approx(expected, rel=6e-5, abs=1e-4), (position.number, row)
    # No such row among the velocities: ω3 has its own there.
    assert not any(line.startswith("| ω3 = ") for line in lines)
    assert any(line.startswith("| ω3 |") for line in lines)
