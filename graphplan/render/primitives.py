"""Drawing primitives in paper millimetres, y up, and the symbols built from them.

A drawing is a list of :class:`Layer` objects, each a named list of
primitives.  Layouts (one module per drawing) compute primitives from
records; a backend (:mod:`graphplan.render.svg`) only translates them.
Symbols (pins, frame pivots, slider blocks, hatching) are drawn once in a
unit frame and placed by :func:`place`, so that their shape lives in one place.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Iterable, Sequence

Point = tuple[float, float]


@dataclass(frozen=True)
class Stroke:
    """Line style: width in mm, colour, dash pattern in mm (empty for solid)."""

    width: float = 0.35
    colour: str = "black"
    dash: tuple[float, ...] = ()


@dataclass(frozen=True)
class Polyline:
    points: tuple[Point, ...]
    stroke: Stroke = Stroke()
    closed: bool = False
    fill: str | None = None


@dataclass(frozen=True)
class Circle:
    centre: Point
    radius: float
    stroke: Stroke = Stroke()
    fill: str | None = "white"


@dataclass(frozen=True)
class Text:
    """Text at ``at``; ``anchor`` is start, middle or end; ``size`` is the cap height in mm."""

    at: Point
    text: str
    size: float = 3.5
    anchor: str = "middle"
    colour: str = "black"
    weight: str = "normal"


Primitive = Polyline | Circle | Text


@dataclass(frozen=True)
class Layer:
    """A named group of primitives (an svg ``<g id=...>``, a DXF layer)."""

    name: str
    items: tuple[Primitive, ...] = field(default_factory=tuple)


THIN = Stroke(0.25)
MAIN = Stroke(0.7)
BOLD = Stroke(1.0)


def place(points: Iterable[Point], at: Point, angle: float = 0.0, scale: float = 1.0) -> tuple[Point, ...]:
    """Points of a symbol drawn in its unit frame, turned by ``angle`` and moved to ``at``."""
    c, s = math.cos(angle), math.sin(angle)
    return tuple((at[0] + scale * (c * x - s * y), at[1] + scale * (s * x + c * y)) for x, y in points)


def hatching(start: Point, end: Point, side: float = -1.0, pitch: float = 2.0, depth: float = 2.0,
             stroke: Stroke = THIN) -> list[Polyline]:
    """The ground line from ``start`` to ``end`` with hatch strokes on one side (side −1: right of start→end)."""
    length = math.dist(start, end)
    if length == 0:
        return []
    angle = math.atan2(end[1] - start[1], end[0] - start[0])
    lines = [Polyline((start, end), stroke)]
    count = max(1, int(length / pitch))
    for k in range(count + 1):
        x = k * length / count
        lines.append(Polyline(place(((x, 0.0), (x - depth, side * depth)), start, angle), stroke))
    return lines


def frame_pivot(at: Point, size: float = 5.0) -> list[Primitive]:
    """A fixed revolute: the pin on a small triangle standing on hatched ground."""
    half = 0.7 * size
    left, right = (at[0] - half, at[1] - size), (at[0] + half, at[1] - size)
    items: list[Primitive] = [Polyline((at, left, right), MAIN, closed=True, fill="white")]
    items.extend(hatching((left[0] - 1.0, left[1]), (right[0] + 1.0, right[1]), side=-1.0, pitch=1.5, depth=1.5))
    items.append(pin(at))
    return items


def pin(at: Point, radius: float = 1.3) -> Circle:
    """A revolute joint."""
    return Circle(at, radius, MAIN, "white")


def slider_block(at: Point, angle: float, length: float = 10.0, height: float = 5.0,
                 stroke: Stroke = MAIN) -> Polyline:
    """A slider block centred at ``at`` with its long side along ``angle``."""
    half_l, half_h = length / 2, height / 2
    corners = ((-half_l, -half_h), (half_l, -half_h), (half_l, half_h), (-half_l, half_h))
    return Polyline(place(corners, at, angle), stroke, closed=True, fill="white")


def dot_marker(at: Point, radius: float = 0.6, colour: str = "black") -> Circle:
    return Circle(at, radius, Stroke(0.1, colour), colour)


def bounds(layers: Sequence[Layer]) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) of every primitive, text by its anchor point with a margin for its size."""
    xs: list[float] = []
    ys: list[float] = []
    for layer in layers:
        for item in layer.items:
            if isinstance(item, Polyline):
                xs.extend(p[0] for p in item.points)
                ys.extend(p[1] for p in item.points)
            elif isinstance(item, Circle):
                xs.extend((item.centre[0] - item.radius, item.centre[0] + item.radius))
                ys.extend((item.centre[1] - item.radius, item.centre[1] + item.radius))
            else:
                width = 0.6 * item.size * len(item.text)
                x0 = {"start": 0.0, "middle": -width / 2, "end": -width}[item.anchor]
                xs.extend((item.at[0] + x0, item.at[0] + x0 + width))
                ys.extend((item.at[1], item.at[1] + item.size))
    if not xs:
        return (0.0, 0.0, 1.0, 1.0)
    return (min(xs), min(ys), max(xs), max(ys))
