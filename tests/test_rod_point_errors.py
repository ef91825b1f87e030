"""The error tables of a mechanism with a point on an RPR's block or rod (an oscillating cylinder's piston rod end):
the rod turns with the cylinder, so its ε is the cylinder's, and the tables say so where every other turning link
has an ε row of its own.

The acceleration plan lays the rod's point e off similar to the cylinder's pa4 (ae = pa4·lAE/lCA4, turned as pa4
is); it lays off no tangential component of the rod, so no segment of it gives ε3 but the cylinder's n4a4.  The
value the tables and the note give for ε3 is checked against a finite difference of the rod's own angle over
neighbouring crank angles, within what the drafting precision allows on the segment it is read from."""

import math

import numpy as np
import pytest
from scene_texts import oscillating_cylinder

import graphplan
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown
from graphplan.report.tables import markdown

CRANK_OMEGA = 120 * 2 * math.pi / 60  # rpm, uniform: d²φ3/dt² = ω2²·d²φ3/dφ2²
STEP = 1e-3  # rad of the crank


def _rod_rates(scene, crank: float) -> tuple[float, float]:
    """ω3 and ε3 by central differences of the rod's angle at neighbouring crank angles."""
    angle = np.unwrap(np.asarray(graphplan.solve(scene, [crank - STEP, crank, crank + STEP]).link(3).angle))
    first = (angle[2] - angle[0]) / (2 * STEP)
    second = (angle[2] - 2 * angle[1] + angle[0]) / STEP**2
    return CRANK_OMEGA * first, CRANK_OMEGA**2 * second


@pytest.mark.parametrize("offset", [0.0, 0.02])
def test_the_rods_epsilon_is_read_as_the_cylinders_and_the_tables_say_so(offset):
    scene = graphplan.load_text(oscillating_cylinder(offset))
    analysis = analyse(scene)
    table, note = markdown(analysis), note_markdown(analysis)
    precision = scene.drawing.drafting_precision
    drivers = graphplan.solve(scene).driver
    for position in analysis.plans:
        omega, epsilon = _rod_rates(scene, float(drivers[position.index]))
        rows = {(row.quantity, row.source): row.plan for row in position.errors}
        readings = {reading.quantity: reading for reading in position.readings}
        # ω3 is read off the rod's own segment ae of the velocity plan.
        slack = precision * position.velocity.scale / readings["omega3"].length
        for source in ("construction", "drafting"):
            assert rows["omega3", source] == pytest.approx(omega, abs=slack)
        # ε3: no segment of the rod's own; the cylinder's n4a4 gives it, within the drafting of that segment.
        assert ("epsilon3", "construction") not in rows
        slack = precision * position.acceleration.scale / readings["epsilon4"].length
        for source in ("construction", "drafting"):
            assert rows["epsilon4", source] == pytest.approx(epsilon, abs=slack)
        # The note reads ε3 as ε4, with its value and its sense, where it gives the readings of the plan.
        value = f"{abs(rows['epsilon4', 'construction']):.5g}"
        sense = "counter-clockwise" if epsilon > 0 else "clockwise"
        assert f"- ε3 = ε4 = {value} rad/s², {sense}" in note, note
    # No invented row: the table tells why ε3 has none, and where its value is.
    assert "| ε3 |" not in table
    assert "ε3 = ε4: link 3 turns with link 4" in table, table.split("## ")[0]
    assert "ε3 = ε4: link 3 turns with link 4" in note


def test_a_slotted_lever_without_a_point_on_its_block_says_nothing_of_the_block():
    # The block has one point (A): no ω3 row, no ε3 row, and nothing to say of either.
    analysis = analyse(graphplan.load("fixtures/quick_return_slotted_lever.toml"))
    assert "turns with" not in markdown(analysis)
    assert "ε3 = ε4" not in note_markdown(analysis)
