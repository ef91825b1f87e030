"""On a big sheet with room the kinematic diagrams, the dynamics and the rotor's balancing polygons are drawn larger,
filling it as a course project does, at whole millimetres per interval and standard scales that agree with what is
drawn."""

from __future__ import annotations

import json
import math
import re
from xml.etree import ElementTree

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.dynamics import equivalent_model_of
from graphplan.flywheel import flywheel_for
from graphplan.kinematic_diagrams import of_analysis
from graphplan.render.dynamics import Redrawings, layout
from graphplan.render.primitives import Polyline, Text
from graphplan.render.sheet import course_sheets, diagrams_panel, dynamics_panel, dynamics_sheet, kinematics_sheet
from graphplan.scales import standard_scale
from graphplan.starters import starter


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


def _balancing_drawn(svg_path) -> tuple[dict[str, float], dict[str, float], float]:
    """Of a drawing of the rotor's balancing: each plane's correction drawn (mm, tail to tip), the μ its caption
    gives, and the drawing's width (mm) over its polygons and captions."""
    svg = "{http://www.w3.org/2000/svg}"
    root = ElementTree.parse(svg_path).getroot()
    lengths, scales, xs = {}, {}, []
    for group in root.iter(f"{svg}g"):
        name = group.get("id", "")
        found = re.fullmatch(r"(?:balancing-(?:\d+-)?)?plane-(\w+)-m(\w+)r(\w+)", name)
        if found and found.group(1) == found.group(2) == found.group(3):
            shaft, head = (re.findall(r"(-?[\d.]+),(-?[\d.]+)", path.get("d")) for path in group.iter(f"{svg}path"))
            lengths[found.group(1)] = math.dist(map(float, shaft[0]), map(float, head[0]))
        found = re.fullmatch(r"(?:balancing-(?:\d+-)?)?plane-(\w+)-caption", name)
        if found:
            words = " ".join("".join(text.itertext()) for text in group.iter(f"{svg}text"))
            scales[found.group(1)] = _number(r"μ = ([0-9.]+) kg·m/mm", words)
            xs += [float(text.get("x")) for text in group.iter(f"{svg}text")]
        if re.match(r"(?:balancing-(?:\d+-)?)?plane-", name):
            xs += [float(value) for path in group.iter(f"{svg}path")
                   for value, _ in re.findall(r"(-?[\d.]+),(-?[\d.]+)", path.get("d"))]
    return lengths, scales, max(xs) - min(xs) if xs else 0.0


def test_the_balancing_polygons_fill_an_a1_sheet_each_correction_as_long_as_its_caption_s_scale_draws_it(tmp_path):
    """The rotor starter's two polygons stood at their own drawing's scales in the middle of an A1, a twentieth of it
    drawn on; on a sheet with room they are drawn larger, at standard scales, each correction as long as its
    mass-radius product (results.json) over the μ its caption gives."""
    scene = tmp_path / "rotor.toml"
    scene.write_text(starter("rotor"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--sheet", "A1"]) == 0
    out = tmp_path / "out"
    corrections = {plane["plane"]: plane["mass_radius"]
                   for plane in json.loads((out / "results.json").read_text(encoding="utf-8"))["balancing"]["planes"]}
    own_lengths, own_scales, _ = _balancing_drawn(out / "rotor_balancing.svg")
    lengths, scales, drawn_width = _balancing_drawn(out / "sheet_1.svg")
    assert set(lengths) == set(scales) == set(corrections) == {"L", "R"}
    for plane, product in corrections.items():
        assert scales[plane] == standard_scale(scales[plane])
        assert scales[plane] < own_scales[plane]  # drawn larger than in the drawing's own file
        assert lengths[plane] == pytest.approx(product / scales[plane], abs=0.05)
        assert own_lengths[plane] == pytest.approx(product / own_scales[plane], abs=0.05)
    frame = ElementTree.parse(out / "sheet_1.svg").getroot()
    sheet_width = float(frame.get("viewBox").split(",")[2])
    assert drawn_width > 0.6 * sheet_width


def test_the_balancing_polygons_stay_as_they_were_on_a_sheet_that_holds_them_only_apart(tmp_path):
    """On an upright A4 the two planes stand one under the other at the drawing's own scales: no larger way fits."""
    scene = tmp_path / "rotor.toml"
    scene.write_text(starter("rotor"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--sheet", "A4"]) == 0
    _, own_scales, _ = _balancing_drawn(tmp_path / "out" / "rotor_balancing.svg")
    drawn = {}
    for path in sorted((tmp_path / "out").glob("sheet_*.svg")):
        drawn.update(_balancing_drawn(path)[1])
    assert drawn == own_scales
