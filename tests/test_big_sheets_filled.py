"""On a big sheet with room the kinematic diagrams and the dynamics are drawn larger, filling it as a course
project does, at whole millimetres per interval and standard scales that agree with what is drawn."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.dynamics import equivalent_model_of
from graphplan.flywheel import flywheel_for
from graphplan.kinematic_diagrams import of_analysis
from graphplan.render.dynamics import Redrawings, layout
from graphplan.render.primitives import Polyline, Text
from graphplan.render.sheet import course_sheets, diagrams_panel, dynamics_panel, dynamics_sheet, kinematics_sheet
from graphplan.scales import standard_scale


@pytest.fixture(scope="module")
def shaper():
    return analyse(graphplan.load("fixtures/shaper_six_bar.toml"))


def _share(rect, frame):
    """The share of the frame's area a drawing's bounds take."""
    return (rect[2] - rect[0]) * (rect[3] - rect[1]) / ((frame[2] - frame[0]) * (frame[3] - frame[1]))


def _layer(sheet, name):
    return next(layer for layer in sheet.layers if layer.name == name)


def _written(sheet, prefix):
    return " ".join(item.text for layer in sheet.layers if layer.name.startswith(prefix)
                    for item in layer.items if isinstance(item, Text))


def _number(pattern, text):
    return float(re.search(pattern, text).group(1))


def test_the_kinematic_diagrams_fill_an_a1_sheet_at_whole_mm_per_interval_and_standard_scales(shaper):
    panel = diagrams_panel(shaper, "A1")
    (alone,) = kinematics_sheet([panel], "A1")
    # Alone on the sheet, half its drawing field (the usual 240 mm axis and 50 mm fields took a fifth).
    assert _share(alone.panels["diagrams"], alone.frame) >= 0.45
    # Beside a plan sheet on the course's sheet, as tall as the frame nearly (a third of it before).
    sheets = course_sheets(shaper, "A1", diagrams=(panel,))
    (shared,) = [sheet for sheet in sheets if "diagrams" in sheet.panels]
    rect, frame = shared.panels["diagrams"], shared.frame
    assert (rect[3] - rect[1]) >= 0.8 * (frame[3] - frame[1])
    assert _share(rect, frame) >= 0.3

    record = of_analysis(shaper)
    intervals = record.intervals
    for sheet in (alone, shared):
        written = _written(sheet, "diagrams-")
        # The φ axis as drawn: from the first position's tick to the last's (the cycle's first again).
        ticks = sorted({item.points[0][0] for item in _layer(sheet, "diagrams-displacement-axes").items
                        if isinstance(item, Polyline) and item.points[0][0] == item.points[1][0]})
        drawn_axis = ticks[-1] - ticks[0]
        length = _number(r"L = ([0-9.]+) mm", written)
        assert drawn_axis == pytest.approx(length, abs=1e-6)
        assert length > 240.0 or sheet is shared
        per_interval = length / intervals
        assert per_interval == pytest.approx(round(per_interval), abs=1e-9)
        # μφ = 2π/L as written, to its four digits.
        mu_phi = _number(r"μφ = 2π/L = ([0-9.]+) rad/mm", written)
        assert mu_phi == pytest.approx(2 * math.pi / drawn_axis, rel=5e-4)
        # μs standard, and the displacement curve drawn at it: its height times μs is the stroke.
        mu_s = _number(r"μs = ([0-9.]+) m/mm", written)
        assert standard_scale(mu_s) == pytest.approx(mu_s, rel=1e-12)
        curve = _layer(sheet, "diagrams-displacement-curves").items[0]
        heights = [y for _, y in curve.points]
        assert (max(heights) - min(heights)) * mu_s == pytest.approx(float(np.ptp(record.s)), rel=1e-9)
        # μv = μs/(μt·H1), H1 a whole millimetre: the rays start at the pole H1 left of the origin.
        pole = _number(r"H₁ = ([0-9.]+) mm", written)
        assert pole == int(pole)
        rays = [item for item in _layer(sheet, "diagrams-velocity-rays").items if isinstance(item, Polyline)]
        origin = min(item.points[1][0] for item in rays)
        assert origin - min(item.points[0][0] for item in rays) == pytest.approx(pole, abs=1e-6)
        mu_t = mu_phi / record.driver_speed
        mu_v = _number(r"μv = μs/\(μt·H₁\) = ([0-9.]+)", written)
        assert mu_v == pytest.approx(mu_s / (mu_t * pole), rel=5e-4)


def test_the_kinematic_diagrams_stay_as_they_were_on_a_sheet_they_already_fill(shaper):
    usual = diagrams_panel(shaper, "none")
    assert diagrams_panel(shaper, "A3").layers == usual.layers
    assert not diagrams_panel(shaper, "A3").alternatives
    # Whatever way a sheet takes, the usual one is the last, for a sheet with little room left.
    assert diagrams_panel(shaper, "A1").ways[-1].layers == usual.layers


def test_the_dynamics_fill_an_a1_sheet_at_a_standard_angle_scale(shaper):
    model = equivalent_model_of(shaper)
    flywheel = flywheel_for(model, 0.05)
    usual = layout(model, flywheel)
    (before,) = dynamics_sheet([dynamics_panel(usual, "en")], "A1")
    (sheet,) = dynamics_sheet([dynamics_panel(usual, "en", Redrawings(model, flywheel), "A1")], "A1")
    grown, was = _share(sheet.panels["dynamics"], sheet.frame), _share(before.panels["dynamics"], before.frame)
    assert grown >= 0.5 and grown > was * 1.15
    written = _written(sheet, "dynamics-moments")
    degrees = _number(r"μφ = ([0-9.]+)°/mm", written)
    assert degrees in (1.0, 1.5, 2.0)
    # The cycle drawn as long as μφ says: the ticks of 0° and 360° that far apart.
    ticks = {item.text: item.at[0] for item in _layer(sheet, "dynamics-moments").items
             if isinstance(item, Text) and item.anchor == "middle" and item.text in ("0", "360")}
    assert ticks["360"] - ticks["0"] == pytest.approx(360.0 / degrees, abs=1e-6)


def test_je_turned_runs_at_its_own_angle_scale_so_that_the_cycle_above_may_run_longer(shaper):
    """Je(φ) turned under the energy–mass diagram shares its axis of Je with that diagram, not its φ with the
    cycle's diagrams beside it: on A1 the cycle runs at 1°/mm while Je(φ) runs shorter (at 1°/mm it was as tall
    as the cycle is long, and held the whole drawing at 1.5°/mm).  Each is drawn as long as its own μφ says."""
    model = equivalent_model_of(shaper)
    flywheel = flywheel_for(model, 0.05)
    (sheet,) = dynamics_sheet([dynamics_panel(layout(model, flywheel), "en", Redrawings(model, flywheel),
                                              "A1")], "A1")
    above = _number(r"μφ = ([0-9.]+)°/mm", _written(sheet, "dynamics-moments"))
    turned = _number(r"μφ = ([0-9.]+)°/mm", _written(sheet, "dynamics-inertia"))
    assert above == 1.0 and turned > above
    column = _layer(sheet, "dynamics-inertia")
    ticks = {item.text: item.at[1] for item in column.items
             if isinstance(item, Text) and item.anchor == "end" and item.text in ("0", "360")}
    assert ticks["0"] - ticks["360"] == pytest.approx(360.0 / turned, abs=1e-6)
    # The curve over the whole cycle, Je across at the energy–mass diagram's μJ, φ down at the column's μφ.
    curve = next(item for item in column.items if isinstance(item, Polyline) and len(item.points) > 2)
    heights = [y for _, y in curve.points]
    assert max(heights) - min(heights) == pytest.approx(360.0 / turned, rel=1e-9)
    mu_j = _number(r"μJ = ([0-9.]+) kg·m²/mm", _written(sheet, "dynamics-inertia"))
    widths = [x for x, _ in curve.points]
    assert max(widths) - min(widths) == pytest.approx(float(np.ptp(model.inertia)) / mu_j, rel=1e-9)
