"""A ТММ teacher's review of the first sheet: extremes, strokes, K, and the kinematic diagrams' accuracy.

Each quantity is recomputed here from the offset slider-crank's own closure (the pin A on the crank circle, the
slider B on its guide e above O), not from graphplan's solvers.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from graphplan import accuracy, scene

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"

# fixtures/offset_slider_crank.toml: r = lOA, l = lAB, the guide e above O, ω counter-clockwise.
CRANK, ROD, OFFSET, OMEGA = 0.08, 0.26, 0.08, 6.3


def slider_x(phi: np.ndarray) -> np.ndarray:
    """B's abscissa on its guide y = e, the rod ahead of the pin (the fixture's "forward" assembly)."""
    return CRANK * np.cos(phi) + np.sqrt(ROD**2 - (OFFSET - CRANK * np.sin(phi)) ** 2)


def extended_dead_centre() -> float:
    """The crank's angle where O, A, B line up with A between them: sin φ = e/(l + r)."""
    return math.asin(OFFSET / (ROD + CRANK))


@pytest.fixture(scope="module")
def study_case():
    return accuracy.prepare(scene.load(FIXTURES / "offset_slider_crank.toml"), "offset_slider_crank")


def test_the_extremes_strokes_and_K_are_the_closure_s_own(study_case):
    extended = extended_dead_centre()
    folded = math.pi + math.asin(OFFSET / (ROD - CRANK))
    theta = folded - math.pi - extended
    positions = study_case.positions
    got = [math.degrees(value) % 360.0 for value in positions.extremes]
    assert got == pytest.approx([math.degrees(extended), math.degrees(folded)], abs=1e-6)
    working, idle = positions.stroke_turns(1.0)
    # K = φw/φi = (180° + θ)/(180° − θ), θ between the rod's two extreme positions.
    assert working / idle == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-9)


def test_the_accuracy_study_s_diagrams_take_the_acceleration_as_the_diagram_draws_it(study_case):
    """The acceleration diagram's ordinate at a position is the chord between the slopes of the two intervals
    beside it, (s₊ − 2s + s₋)/h²; the study took the chord through the neighbours of the chords through the
    neighbours, two steps either side, and wrote four times the diagram's own error (14 % for 3.7 %)."""
    step = 2.0 * math.pi / len(study_case.values)
    phi = extended_dead_centre() + step * np.arange(len(study_case.values))
    s = slider_x(phi)
    tiny = 1e-4
    exact = (slider_x(phi + tiny) - 2.0 * s + slider_x(phi - tiny)) / tiny**2 * OMEGA**2
    drawn = (np.roll(s, -1) - 2.0 * s + np.roll(s, 1)) / step**2 * OMEGA**2
    twice_neighbours = (np.roll(s, -2) - 2.0 * s + np.roll(s, 2)) / (2.0 * step) ** 2 * OMEGA**2
    drawn_error = float(np.max(np.abs(drawn - exact)) / np.max(np.abs(exact)))
    wide_error = float(np.max(np.abs(twice_neighbours - exact)) / np.max(np.abs(exact)))
    row = accuracy.diagram(study_case, 1)
    largest = max(row.errors["acceleration"])
    # aB is among the quantities compared, so the largest is at least its error; the wide chords' is far off.
    assert largest >= drawn_error * (1.0 - 1e-6)
    assert largest < 0.5 * wide_error


def test_the_note_gives_theta_and_the_stroke_from_the_dead_centres(tmp_path):
    """The first sheet's text: θ between the rod's extreme positions, K = (180° + θ)/(180° − θ), and the stroke H
    the plan of positions dimensions, each from the closure's own dead centres."""
    import re

    from graphplan.cli import main

    extended = extended_dead_centre()
    folded = math.pi + math.asin(OFFSET / (ROD - CRANK))
    rod_extended = extended                                        # O, A, B in line: the rod along the crank
    rod_folded = math.atan2(OFFSET - CRANK * math.sin(folded), slider_x(np.array(folded)) - CRANK * math.cos(folded))
    theta = math.degrees(rod_extended - rod_folded) % 360.0
    theta = min(theta, 360.0 - theta)
    stroke = float(slider_x(np.array(extended)) - slider_x(np.array(folded)))
    out = tmp_path / "out"
    assert main(["run", str(FIXTURES / "offset_slider_crank.toml"), "--out", str(out), "--only", "note",
                 "--locale", "en"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    said = re.search(r"θ = \|φw − φi\|/2 = ([\d.]+)°.*K = \(180° \+ θ\)/\(180° − θ\) = ([\d.]+);", note)
    assert said, "the note gives no θ with K = (180° + θ)/(180° − θ)"
    assert float(said.group(1)) == pytest.approx(theta, rel=1e-4)
    assert float(said.group(2)) == pytest.approx((180.0 + theta) / (180.0 - theta), rel=1e-3)
    travel = re.search(r"plan of positions: the stroke H = ([\d.]+) m\.", note)
    assert travel and float(travel.group(1)) == pytest.approx(stroke, rel=1e-3)
