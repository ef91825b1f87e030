"""Dimensions drawn as a drafter draws them: a slider's stroke H between extension lines, a rocker's swing ψ as an
arc between its two extreme positions, each with arrowheads at its ends.

In paper millimetres (y up); the values are the caller's text.  A stroke's text is set level beside the middle of
its dimension line on the outer side, where nothing else is drawn; a swing's is left to the caller's label placer.
"""

from __future__ import annotations

import cmath
import math

import shapely
from shapely.geometry.base import BaseGeometry

from . import lettering
from .labels import LABEL_GAP_MM, ink_of
from .primitives import Point, Polyline, Primitive, Stroke, Text, arrowhead, text_extent, to_complex, to_xy

DIMENSION_STROKE = Stroke(0.25)
# ESKD 2.307: extension lines run 1 to 5 mm past the dimension line; arrowheads about 2.5 mm; text 3.5 mm
# (lettering.DIMENSION).
_PAST_MM = 2.0
_HEAD_MM = 2.5
_TEXT_MM = lettering.DIMENSION
_TEXT_GAP_MM = 1.0
# How far another label keeps off a dimension's lines and text (mm): as far as a label stands off its own point.  A
# position's number set level just over a stroke's extension line, as close as a dimension's own text stands to its
# line, read as that line's number (the Scotch yoke's 8, over the end of its stroke H).
CLEARANCE_MM = LABEL_GAP_MM


def linear(start: Point, end: Point, outward: complex, offset: float, text: str,
           size: float = _TEXT_MM) -> list[Primitive]:
    """The distance from ``start`` to ``end`` dimensioned ``offset`` mm away from them along ``outward`` (a
    direction, made square to the measured line), its text ``size`` mm high."""
    a, b = to_complex(start), to_complex(end)
    along = b - a
    if abs(along) == 0:
        return []
    u = along / abs(along)
    normal = u * 1j if ((u * 1j).conjugate() * outward).real >= 0 else -u * 1j
    line_a, line_b = a + offset * normal, b + offset * normal
    items: list[Primitive] = [Polyline((to_xy(p + 0.5 * normal), to_xy(q + _PAST_MM * normal)), DIMENSION_STROKE)
                              for p, q in ((a, line_a), (b, line_b))]
    items.append(Polyline((to_xy(line_a), to_xy(line_b)), DIMENSION_STROKE))
    angle = cmath.phase(u)
    items += [arrowhead(to_xy(line_b), angle, _HEAD_MM), arrowhead(to_xy(line_a), angle + math.pi, _HEAD_MM)]
    items.append(_beside(0.5 * (line_a + line_b), normal, text, size))
    return items


def angular(centre: Point, radius: float, start: float, sweep: float) -> list[Primitive]:
    """The angle from the ray at ``start`` through ``sweep`` (radians, ccw positive) about ``centre``, as an arc
    of ``radius`` mm headed at both ends; its text is the caller's to place (the rays' lines crowd round it)."""
    if radius <= 0 or sweep == 0:
        return []
    c = to_complex(centre)
    steps = max(8, int(abs(sweep) / math.radians(3)))
    arc = tuple(to_xy(c + cmath.rect(radius, start + sweep * k / steps)) for k in range(steps + 1))
    turning = math.copysign(math.pi / 2, sweep)
    # Each head points along the arc, away from its middle.
    heads = [arrowhead(arc[-1], start + sweep + turning, _HEAD_MM), arrowhead(arc[0], start - turning, _HEAD_MM)]
    return [Polyline(arc, DIMENSION_STROKE), *heads]


def kept_clear(items: list[Primitive]) -> list[BaseGeometry]:
    """The room of a dimension's ``items`` (its lines, arrowheads and text) that other labels keep out of: their ink
    grown by :data:`CLEARANCE_MM`."""
    shapes = ink_of(items)
    return list(shapely.buffer(shapes, CLEARANCE_MM)) if shapes else []


def _beside(at: complex, outward: complex, text: str, size: float) -> Text:
    """``text`` set level just clear of ``at`` on the side ``outward`` (a unit direction)."""
    probe = Text((0.0, 0.0), text, size)
    left, bottom, right, top = text_extent(probe)
    half_width, half_height = (right - left) / 2, (top - bottom) / 2
    clear = abs(outward.real) * half_width + abs(outward.imag) * half_height + _TEXT_GAP_MM
    centre = at + clear * outward
    # Text stands on its baseline: lowered by half its height (and what text_extent counts below it).
    return Text((centre.real, centre.imag - (top + bottom) / 2), text, size)
