"""A force along a turning line (``[[loads]]`` with ``along``) is drawn on the mechanism as what it is: a spring's
zig-zag or a cylinder's barrel and rod, between the point it is along and its own point, pinned at both.

Read from the layers the SVG is written from (and, for the labels, from the SVG itself): the plan of positions at its
first bold position and the plan sheets.  Where the ends should stand is worked out here from the scene's numbers: D
from ``[frame]``, B where the circles of the coupler about A and of the rocker about C cross (A on the crank at the
driver's angle of the position), both at the drawing's μl; a drawing moved into its field on a plan sheet is matched
by the offset its spring's start stands at, which the frame's pins must then share.
"""

from __future__ import annotations

import cmath
import functools
import itertools
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import shapely
from drawn_lines import stroked_path
from test_force_along_a_turning_line import CRANK_ROCKER, _force, _with_loads
from test_positions_labels_clear import _ink
from test_spring_load import _spring

from graphplan.analysis import analyse
from graphplan.render import drawings, plans, positions
from graphplan.render.primitives import PIN_RADIUS_MM, Circle, Layer, Polyline, Text, spring
from graphplan.render.svg import to_svg
from graphplan.scene import loads as scene_of_text

SVG = "{http://www.w3.org/2000/svg}"
# CRANK_ROCKER's numbers: the frame points, the crank, the coupler and the rocker (m).
FRAME = {"O": 0j, "C": 0.35 + 0j, "D": 0.05 + 0.42j}
CRANK, COUPLER, ROCKER = 0.1, 0.4, 0.3
# Where a drawn point is taken to stand on its point (mm): the SVG's three decimals and the arithmetic's rounding.
CLOSE_MM = 0.01

SCENES = {
    "spring": _with_loads(CRANK_ROCKER, _spring(4, "B", "D", 4000.0, 0.1)),
    "cylinder": _with_loads(CRANK_ROCKER, _force(4, "B", 800.0, 'along = "D"')),
    "spring on the coupler's E": _with_loads(CRANK_ROCKER, _spring(3, "E", "D", 2500.0, 0.6)),
    "none": CRANK_ROCKER,
}


@functools.cache
def analysis(name: str):
    return analyse(scene_of_text(SCENES[name]))


def _b(crank_angle: float) -> complex:
    """B where the coupler from A and the rocker from C cross, on the left of A→C (the scene's assembly)."""
    a = CRANK * cmath.exp(1j * crank_angle)
    c = FRAME["C"]
    span = abs(c - a)
    along = (COUPLER ** 2 - ROCKER ** 2 + span ** 2) / (2 * span)
    unit = (c - a) / span
    return a + along * unit + math.sqrt(COUPLER ** 2 - along ** 2) * 1j * unit


def _positions(name: str) -> tuple[list[Layer], float, float]:
    """The plan of positions' layers, its μl and the crank's angle at its first bold position."""
    found = analysis(name)
    plan = drawings.positions_plan(found)
    return positions.layout(plan), plan.length_scale, float(np.atleast_1d(found.emphasised.links[2].angle)[0])


def _plan_sheet(name: str, which: int = 0) -> tuple[list[Layer], float, float]:
    """A plan sheet's layers, its μl and the crank's angle at its position."""
    found = analysis(name)
    index = found.plans[which].index
    sheet = drawings.plan_sheet(found, index)
    return plans.layout(sheet), sheet.length_scale, float(np.atleast_1d(found.motion.links[2].angle)[index])


def _layer(layers: list[Layer], name: str) -> Layer:
    return next(layer for layer in layers if layer.name == name)


def _xy(point) -> complex:
    return complex(point[0], point[1])


# (the drawing, the layer of its springs and cylinders, of its frame, of its links' pins)
DRAWINGS = {"positions": (_positions, "load-links", "frame", "extremes"),
            "plan sheet": (_plan_sheet, "mechanism-load-links", "mechanism-frame", "mechanism-links")}


def _letter(layers: list[Layer], drawing: str) -> float:
    """The height the drawing letters its points at, read off its label "D"."""
    labels = "labels" if drawing == "positions" else "mechanism-labels"
    return next(item.size for item in _layer(layers, labels).items if isinstance(item, Text) and item.text == "D")


@pytest.mark.parametrize("drawing", sorted(DRAWINGS))
def test_the_spring_s_zig_zag_runs_from_d_to_b(drawing):
    make, loads_layer, frame_layer, _ = DRAWINGS[drawing]
    layers, scale, angle = make("spring")
    (spring,) = _layer(layers, loads_layer).items
    assert isinstance(spring, Polyline) and not spring.closed
    points = [_xy(point) for point in spring.points]
    offset = points[0] - FRAME["D"] / scale
    assert abs(points[-1] - offset - _b(angle) / scale) < CLOSE_MM
    # D's pin on the frame stands where the spring starts, among O's and C's at the same offset.
    centres = [_xy(item.centre) - offset for item in _layer(layers, frame_layer).items if isinstance(item, Circle)]
    for name in ("O", "C", "D"):
        assert min(abs(centre - FRAME[name] / scale) for centre in centres) < CLOSE_MM, name
    # Straight at its ends, between them zig-zagging across the line DB as wide as the lettering is high.
    unit = (points[-1] - points[0]) / abs(points[-1] - points[0])
    across = [((point - points[0]) / unit).imag for point in points]
    along = [((point - points[0]) / unit).real for point in points]
    assert across[:2] == pytest.approx([0.0, 0.0], abs=1e-9) and across[-2:] == pytest.approx([0.0, 0.0], abs=1e-9)
    letter = _letter(layers, drawing)
    assert max(across) - min(across) == pytest.approx(letter, rel=1e-9)
    assert all(b > a for a, b in itertools.pairwise(along))
    # The zig-zag's waves are as long as the lettering is high however long the spring is: its leads take the rest.
    zigzag = along[-2] - along[1]
    assert zigzag == pytest.approx(5 * letter, rel=1e-9)
    assert along[1] == pytest.approx(along[-1] - along[-2], rel=1e-9) and along[1] > zigzag
    # Thin beside the links.
    links = [item for item in _layer(layers, DRAWINGS[drawing][3]).items if isinstance(item, Polyline)]
    assert spring.stroke.width < min(link.stroke.width for link in links)


@pytest.mark.parametrize("drawing", sorted(DRAWINGS))
def test_the_cylinder_s_barrel_starts_at_d_and_its_rod_ends_at_b(drawing):
    make, loads_layer, _, _ = DRAWINGS[drawing]
    layers, scale, angle = make("cylinder")
    items = _layer(layers, loads_layer).items
    lead, barrel, piston, rod = items
    d = _xy(lead.points[0])
    offset = d - FRAME["D"] / scale
    b = _b(angle) / scale + offset
    assert abs(_xy(rod.points[-1]) - b) < CLOSE_MM
    unit = (b - d) / abs(b - d)

    def along(point) -> float:
        return ((_xy(point) - d) / unit).real

    def across(point) -> float:
        return ((_xy(point) - d) / unit).imag

    # The barrel: a rectangle on the line DB, from the lead's end (a pin's reach from D) part of the way to B.
    assert barrel.closed and len(barrel.points) == 4
    near, far = min(along(point) for point in barrel.points), max(along(point) for point in barrel.points)
    assert near == pytest.approx(along(lead.points[-1]), abs=1e-9) and 0.0 < near < 3.0
    assert 5.0 < far - near and far < abs(b - d) - 1.0  # mm: a barrel, and the rod out of it to B's pin
    letter = _letter(layers, drawing)
    assert sorted(across(point) for point in barrel.points) == pytest.approx([-letter / 2] * 2 + [letter / 2] * 2)
    # The piston across the barrel inside it, and the rod from it on DB out to B.
    assert along(piston.points[0]) == pytest.approx(along(piston.points[1]), abs=1e-9)
    assert near < along(piston.points[0]) < far
    assert _xy(rod.points[0]) == pytest.approx(d + along(piston.points[0]) * unit, abs=1e-9)
    assert all(abs(across(point)) < 1e-9 for point in (*lead.points, *rod.points))


def test_the_cylinder_s_barrel_and_rod_keep_their_lengths_as_it_extends():
    lengths = []
    for which in (0, 1):
        layers, scale, angle = _plan_sheet("cylinder", which)
        lead, barrel, _, rod = _layer(layers, "mechanism-load-links").items
        d = _xy(lead.points[0])
        sides = sorted(abs(_xy(barrel.points[k]) - _xy(barrel.points[k - 1])) for k in range(4))
        lengths.append((abs(_b(angle) - FRAME["D"]), sides[-1] * scale,
                        abs(_xy(rod.points[-1]) - _xy(rod.points[0])) * scale, abs(_xy(rod.points[-1]) - d) * scale))
    (first, barrel_1, rod_1, drawn_1), (second, barrel_2, rod_2, drawn_2) = lengths
    assert abs(second - first) > 0.05  # m: it extends between the two plan positions
    assert (drawn_1, drawn_2) == pytest.approx((first, second), rel=1e-6)
    assert barrel_2 == pytest.approx(barrel_1, rel=1e-9) and rod_2 == pytest.approx(rod_1, rel=1e-9)


@pytest.mark.parametrize("drawing", sorted(DRAWINGS))
@pytest.mark.parametrize("scene", ["spring", "cylinder"])
def test_d_is_drawn_as_a_fixed_pivot_where_it_was_a_dot(drawing, scene):
    make, _, frame_layer, _ = DRAWINGS[drawing]
    for name, pivot in ((scene, True), ("none", False)):
        layers, scale, _ = make(name)
        items = _layer(layers, frame_layer).items
        # A pivot is a white triangle with its apex at its point, a loose frame point a small black dot.
        apexes = [_xy(item.points[0]) for item in items
                  if isinstance(item, Polyline) and item.closed and item.fill == "white" and len(item.points) == 3]
        # The drawing's offset: where O's apex stands, C's 0.35 m to its right.
        o_apex = next(apex for apex in apexes
                      if any(abs(other - apex - FRAME["C"] / scale) < CLOSE_MM for other in apexes))
        offset = o_apex - FRAME["O"] / scale
        at_d = [apex for apex in apexes if abs(apex - offset - FRAME["D"] / scale) < CLOSE_MM]
        marks = items if drawing == "positions" else _layer(layers, "mechanism-points").items
        dots = [item for item in marks if isinstance(item, Circle) and item.fill == "black"
                and abs(_xy(item.centre) - offset - FRAME["D"] / scale) < CLOSE_MM]
        assert (len(at_d), len(dots)) == ((1, 0) if pivot else (0, 1)), name


def test_a_spring_on_a_point_that_is_no_joint_gets_a_pin_there():
    found = analysis("spring on the coupler's E")
    e = complex(np.atleast_1d(found.emphasised.points["E"].r)[0])
    # E from the scene: 0.2 m along AB from A, 0.08 m to its left.
    layers, scale, angle = _positions("spring on the coupler's E")
    a = CRANK * cmath.exp(1j * angle)
    unit = (_b(angle) - a) / abs(_b(angle) - a)
    assert e == pytest.approx(a + (0.2 + 0.08j) * unit, abs=1e-9)
    pins = [item for item in _layer(layers, "extremes").items
            if isinstance(item, Circle) and item.fill == "white" and abs(_xy(item.centre) - e / scale) < CLOSE_MM]
    assert len(pins) == 1
    (spring,) = _layer(layers, "load-links").items
    assert abs(_xy(spring.points[-1]) - e / scale) < CLOSE_MM


@pytest.mark.parametrize("drawing", sorted(DRAWINGS))
def test_a_scene_without_such_loads_draws_no_spring_or_cylinder(drawing):
    make, loads_layer, _, _ = DRAWINGS[drawing]
    layers, _, _ = make("none")
    assert not [layer for layer in layers if "load-links" in layer.name]
    assert any(layer.name == loads_layer for layer in make("spring")[0])


def _load_lines(root: ET.Element, group_id: str) -> list[shapely.Geometry]:
    """The spring's or the cylinder's paths in the SVG, each widened by half its stroke."""
    group = next(group for group in root.iter(f"{SVG}g") if group.get("id") == group_id)
    return [stroked_path(item) for item in group.iter(f"{SVG}path")]


@pytest.mark.parametrize("drawing", sorted(DRAWINGS))
@pytest.mark.parametrize("scene", ["spring", "cylinder", "spring on the coupler's E"])
def test_no_label_sits_on_the_spring_or_the_cylinder(drawing, scene):
    make, loads_layer, _, _ = DRAWINGS[drawing]
    root = ET.fromstring(to_svg(make(scene)[0]))
    lines = shapely.union_all(_load_lines(root, loads_layer))
    texts = [element for element in root.iter(f"{SVG}text") if (element.text or "").strip()]
    assert texts
    met = [element.text for element in texts if _ink(element).intersects(lines)]
    assert not met


def test_a_short_spring_squeezes_its_zig_zag_between_leads_clear_of_its_pins_and_a_shorter_one_is_a_line():
    letter, start, end = 3.0, (10.0, 5.0), (10.0, 17.0)  # mm: 12 mm upward, too short for five waves of 3 mm
    points = [_xy(point) for point in spring(start, end, letter).points]
    assert points[0] == _xy(start) and points[-1] == pytest.approx(_xy(end))
    # Each lead reaches past its pin's circle; the waves share what is left and keep their width.
    assert abs(points[1] - points[0]) == pytest.approx(abs(points[-1] - points[-2]))
    assert abs(points[1] - points[0]) > PIN_RADIUS_MM
    assert abs(points[-2] - points[1]) == pytest.approx(12.0 - 2 * abs(points[1] - points[0]))
    assert max(point.real for point in points) - min(point.real for point in points) == pytest.approx(letter)
    assert len(spring((0.0, 0.0), (2 * PIN_RADIUS_MM, 0.0), letter).points) == 2
