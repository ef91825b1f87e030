"""The places the works' integration breaks at are part of every equivalent model, given by whoever makes it.

A linkage's model breaks its run at its ends and at both samples of each place the loads switch or turn a corner,
which the sweep puts in 10⁻¹² of a step apart (so no two other samples lie within 10⁻⁹ of the run); a model from
load diagrams breaks at every sample (straight between its vertices, where the trapezoid is exact).  No model
is left to find them afterwards.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from graphplan.analysis import analyse
from graphplan.dynamics import EquivalentModel, diagram_model, equivalent_model_of
from graphplan.scene import load

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


def test_a_model_cannot_be_made_without_its_breaks():
    field = {f.name: f for f in dataclasses.fields(EquivalentModel)}["breaks"]
    assert field.default is dataclasses.MISSING and field.default_factory is dataclasses.MISSING


@pytest.mark.parametrize("name", ["shaper_six_bar", "engine_slider_crank"])
def test_a_linkage_model_breaks_at_its_ends_and_at_both_sides_of_each_switch(name):
    model = equivalent_model_of(analyse(load(FIXTURES / f"{name}.toml")))
    coordinate = model.coordinate
    span = abs(coordinate[-1] - coordinate[0])
    pairs = [i for i in range(len(coordinate) - 1) if coordinate[i + 1] - coordinate[i] <= 1e-9 * span]
    expected = sorted({0, len(coordinate) - 1, *pairs, *(i + 1 for i in pairs)})
    assert model.breaks.tolist() == expected
    # ∫ dψ over the run is the run itself, whichever stretches Simpson's rule is taken over.
    assert model.integral(np.ones(len(coordinate)))[-1] == pytest.approx(span, rel=1e-12)


def test_a_diagram_model_breaks_at_every_sample():
    model = diagram_model(10.0, driving=([0.0, math.pi, 2 * math.pi], [0.0, 100.0, 0.0]), count=12)
    assert model.breaks.tolist() == list(range(len(model.coordinate)))
    # The triangle's area, ½·2π·100, exactly: the trapezoid on straight pieces.
    assert model.integral(model.driving)[-1] == pytest.approx(math.pi * 100.0, rel=1e-12)
