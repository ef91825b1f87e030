"""A force along a turning line (``[[loads]]`` with ``along = "D"``) shows on its group cut free where it comes
from: its line of action, thin dash-dot, from its point to D, and D lettered at its end (no pivot: the group is cut
free of the frame and of the cylinder or spring).

Where the line must run is worked out here from the scene's numbers, not read from graphplan's loads: D from
``[frame]``, B where the coupler's circle about A and the rocker's about C cross (A on the crank at the position's
angle), E on the coupler 0.2 m along AB and 0.08 m to its left; each mapped onto the SVG through the sheet's μl, the
y axis flipped, the drawing's offset taken from A's pin and checked on C's.
"""

from __future__ import annotations

import cmath
import functools
import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import shapely
from test_along_load_drawn import CRANK, FRAME, SCENES, _b
from test_force_along_a_turning_line import CRANK_ROCKER, _force, _with_loads

from graphplan.analysis import analyse
from graphplan.render import drawings
from graphplan.render import forces as force_layout
from graphplan.render.labels import text_box
from graphplan.render.primitives import Polyline, Text
from graphplan.render.svg import to_svg
from graphplan.scene import loads as scene_of_text

SVG = "{http://www.w3.org/2000/svg}"
GROUP = "body-II-3-4"
# The SVG's three decimals and the arithmetic's rounding (mm).
CLOSE_MM = 0.01
# A pin's radius on a group cut free (mm): the pins are the white circles of its links' layer.
PIN_RADIUS_MM = 1.3


# The cylinder's force at B given at a fixed angle instead: no line to draw.
AT_AN_ANGLE = _with_loads(CRANK_ROCKER, _force(4, "B", 800.0, "angle = 30.0"))


@functools.cache
def analysis(name: str):
    return analyse(scene_of_text(AT_AN_ANGLE if name == "at an angle" else SCENES[name]))


def _e(crank_angle: float) -> complex:
    """E: 0.2 m from A toward B and 0.08 m to the left of AB."""
    a = CRANK * cmath.exp(1j * crank_angle)
    unit = (_b(crank_angle) - a) / abs(_b(crank_angle) - a)
    return a + 0.2 * unit + 0.08 * 1j * unit


def _sheet(name: str, which: int):
    found = analysis(name)
    position = found.plans[which]
    sheet = drawings.force_sheet(found, position)
    return sheet, float(np.atleast_1d(found.motion.links[2].angle)[position.index])


def _svg_groups(name: str, which: int) -> tuple[dict[str, ET.Element], float, float]:
    sheet, angle = _sheet(name, which)
    root = ET.fromstring(to_svg(force_layout.layout(sheet)))
    return {item.get("id"): item for item in root.iter(f"{SVG}g")}, sheet.length_scale, angle


def _path_points(path: ET.Element) -> list[complex]:
    return [complex(float(x), float(y)) for x, y in re.findall(r"(-?[\d.]+),(-?[\d.]+)", path.get("d"))]


def _paper(offset: complex, scale: float):
    """A point of the mechanism (m) on the SVG's page (mm, y down)."""
    return lambda point: offset + complex(point.real, -point.imag) / scale


CASES = {"cylinder": ("B", _b), "spring": ("B", _b), "spring on the coupler's E": ("E", _e)}


@pytest.mark.parametrize("which", [0, 1])
@pytest.mark.parametrize("name", sorted(CASES))
def test_the_line_of_action_runs_from_the_point_to_d(name, which):
    groups, scale, angle = _svg_groups(name, which)
    a = CRANK * cmath.exp(1j * angle)
    pins = [complex(float(item.get("cx")), float(item.get("cy"))) for item in groups[f"{GROUP}-links"]
            if item.tag == f"{SVG}circle" and item.get("fill") == "white"
            and float(item.get("r")) == pytest.approx(PIN_RADIUS_MM)]
    # The offset that puts A on one of the pins and C on another: the group's drawing as placed on the sheet.
    offsets = [pin - complex(a.real, -a.imag) / scale for pin in pins]
    (offset,) = [offset for offset in offsets
                 if any(abs(pin - _paper(offset, scale)(FRAME["C"])) < CLOSE_MM for pin in pins)]
    paper = _paper(offset, scale)
    point_name, where = CASES[name]
    point, d = paper(where(angle)), paper(FRAME["D"])
    paths = [item for item in groups[f"{GROUP}-along-lines"] if item.tag == f"{SVG}path"]
    (line,) = [path for path in paths if path.get("stroke-dasharray")]
    start, end = _path_points(line)
    assert abs(start - point) < CLOSE_MM and abs(end - d) < CLOSE_MM, point_name
    # Thin and dash-dot: four dashes to a period, a long one and a dot.
    assert float(line.get("stroke-width")) < 0.3 and len(line.get("stroke-dasharray").split()) == 4
    # D marked with a dot at the line's end and lettered nearby; no other pin or pivot drawn there.
    dots = [complex(float(item.get("cx")), float(item.get("cy"))) for item in groups[f"{GROUP}-along-lines"]
            if item.tag == f"{SVG}circle"]
    assert len(dots) == 1 and abs(dots[0] - d) < CLOSE_MM
    assert not any(abs(pin - d) < 1.0 for pin in pins)
    letters = {item.text: complex(float(item.get("x")), float(item.get("y"))) for item in groups[f"{GROUP}-labels"]}
    assert abs(letters["D"] - d) < 8.0  # mm: by its point


@pytest.mark.parametrize("which", [0, 1])
@pytest.mark.parametrize("name", sorted(CASES))
def test_no_label_of_the_group_lies_on_the_line(name, which):
    sheet, _ = _sheet(name, which)
    layers = {layer.name: layer for layer in force_layout.layout(sheet)}
    drawn = shapely.MultiLineString([item.points for item in layers[f"{GROUP}-along-lines"].items
                                     if isinstance(item, Polyline)])
    texts = [item for item in layers[f"{GROUP}-labels"].items if isinstance(item, Text)]
    assert texts
    for text in texts:
        assert not text_box(text).intersects(drawn), text.text


def test_a_scene_without_a_load_along_a_line_draws_none():
    groups, _, _ = _svg_groups("at an angle", 0)
    assert not [name for name in groups if name and name.endswith("-along-lines")]
    assert f"{GROUP}-links" in groups


def test_the_line_is_along_the_force():
    """The force's arrow at its point lies on the line (pushing away from D or pulling toward it)."""
    for name in CASES:
        sheet, _ = _sheet(name, 0)
        layers = {layer.name: layer for layer in force_layout.layout(sheet)}
        (line,) = [item for item in layers[f"{GROUP}-along-lines"].items
                   if isinstance(item, Polyline) and item.stroke.dash]
        (start, end) = (complex(*line.points[0]), complex(*line.points[1]))
        load = next(item for item in layers[f"{GROUP}-forces"].items if item.key.endswith(("F4", "F3")))
        unit = (end - start) / abs(end - start)
        for tip in (load.start, load.end):
            across = ((complex(*tip) - start) / unit).imag
            assert abs(across) < 1e-6 * max(1.0, abs(complex(*tip) - start)), name
        assert math.isfinite(abs(end - start))


@pytest.mark.parametrize("which", [0, 1])
@pytest.mark.parametrize("name", sorted(CASES))
def test_the_cylinder_or_spring_is_cut_off_at_its_point_where_its_arrow_leaves_the_line_to_d_free(name, which):
    """Where the force's arrow stands on the far side of its point from D (a push drawn from its point, or onto it
    from beyond), a short piece of the rod or of the spring runs from the point toward D and ends in a cut; where
    the arrow runs toward D (a pull) it would lie on it, and there is none."""
    sheet, _ = _sheet(name, which)
    layers = {layer.name: layer for layer in force_layout.layout(sheet)}
    items = [item for item in layers[f"{GROUP}-along-lines"].items if isinstance(item, Polyline)]
    (line,) = [item for item in items if item.stroke.dash]
    point, d = complex(*line.points[0]), complex(*line.points[-1])
    unit = (d - point) / abs(d - point)
    load = next(item for item in layers[f"{GROUP}-forces"].items if item.key.endswith(("F4", "F3")))
    toward_d = max(((complex(*tip) - point) / unit).real for tip in (load.start, load.end))
    pieces = [item for item in items if not item.stroke.dash]
    if toward_d > 0.5:
        assert not pieces
        return
    assert pieces, "the arrow leaves the line to D free"
    piece, cut = pieces
    # From the point toward D, within a few millimetres of it, its middle on the line DB (a spring zig-zags across).
    along = [((complex(*p) - point) / unit).real for p in piece.points]
    across = [((complex(*p) - point) / unit).imag for p in piece.points]
    assert along[0] == pytest.approx(0.0, abs=1e-9) and 0.0 < along[-1] <= 8.0
    assert across[0] == pytest.approx(0.0, abs=1e-9) and across[-1] == pytest.approx(0.0, abs=1e-9)
    assert max(abs(value) for value in across) < 2.0
    is_spring = "spring" in name
    assert (len(piece.points) > 2) == is_spring
    # The cut crosses the line at the piece's end.
    ends = [complex(*p) for p in cut.points]
    sides = [((end - point) / unit).imag for end in ends]
    assert sides[0] * sides[1] < 0
    middle = (ends[0] + ends[1]) / 2
    assert abs(middle - (point + along[-1] * unit)) < 0.01
