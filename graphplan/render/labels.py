"""Placing labels where they cover nothing: the first free spot around each anchor.

A label is tried at eight spots around its point, nearest first in the
preferred direction; a spot is free when the label's box meets no obstacle
(the drawn lines, the boxes of labels already placed).  Shapely does the
intersection tests.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

from shapely.geometry import LineString, Point, box
from shapely.geometry import Polygon as ShapelyPolygon
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from .primitives import CHARACTER_WIDTH, Arrow, Circle, Polyline, Primitive, Text, text_extent


# The least space between two labels (mm).
LABEL_SPACING = 0.8


@dataclass(frozen=True)
class Anchor:
    """A label to place: its text, the point it names, the direction it prefers (radians)."""

    at: tuple[float, float]
    text: str
    size: float = 3.0
    prefer: float = math.pi / 4
    colour: str = "black"


def text_box(text: Text) -> BaseGeometry:
    """The box a text covers on the paper (:func:`~graphplan.render.primitives.text_extent`)."""
    return box(*text_extent(text))


def obstacles_of(items: Sequence[Primitive]) -> list[BaseGeometry]:
    """The shapes of drawn primitives that a label must not cover."""
    shapes: list[BaseGeometry] = []
    for item in items:
        if isinstance(item, Polyline) and len(item.points) >= 2:
            shapes.append(LineString(item.points + ((item.points[0],) if item.closed else ())))
        elif isinstance(item, Arrow):
            shapes.append(LineString((item.start, item.end)))
            shapes.append(ShapelyPolygon(item.tip().points))
        elif isinstance(item, Circle):
            shapes.append(Point(item.centre).buffer(item.radius))
        elif isinstance(item, Text):
            shapes.append(text_box(item))
    return shapes


def place_labels(anchors: Sequence[Anchor], obstacles: Sequence[BaseGeometry], gap: float = 1.2) -> list[Text]:
    """Texts for ``anchors``, each at the cheapest spot around its point.

    Another label is never covered when any spot avoids it.  A spot costs
    for every drawn shape it covers (a point, an arrowhead or a text three
    times a line), for every other labelled point it stands about as near
    to as to its own, and for its distance from the point, so that a letter
    crosses one thin line rather than wander off to where it could name a
    neighbour.  Ties go to the preferred direction.
    """
    placed: list[Text] = []
    fixed = list(obstacles)
    heavy = [shape.geom_type in ("Polygon", "MultiPolygon") for shape in fixed]
    tree = STRtree(fixed) if fixed else None
    placed_boxes: list[BaseGeometry] = []
    points = [Point(anchor.at) for anchor in anchors]
    for index, anchor in enumerate(anchors):
        best, best_cost = None, math.inf
        neighbours = [p for k, p in enumerate(points) if k != index and p.distance(points[index]) > 1e-9]
        for ring, order, candidate in _candidates(anchor, gap):
            shape = text_box(candidate)
            hits = sum(3 if heavy[i] else 1 for i in tree.query(shape) if fixed[i].intersects(shape)) \
                if tree is not None else 0
            overlaps = sum(1 for b in placed_boxes if b.intersects(shape))
            # A label nearer another labelled point than its own would name the wrong one.
            own = shape.distance(points[index])
            misleading = sum(1 for p in neighbours if shape.distance(p) < own + 0.8)
            cost = 1000 * overlaps + 5 * hits + 8 * misleading + 3.5 * ring + order * 0.01
            if cost < best_cost:
                best, best_cost = candidate, cost
        assert best is not None
        placed.append(best)
        # Kept apart by a little more than touching, so that two letters never read as one (s5g).
        placed_boxes.append(text_box(best).buffer(LABEL_SPACING, join_style=2))
    return placed


def _candidates(anchor: Anchor, gap: float):
    """(ring, order, text) at sixteen directions on four rings, the preferred direction first on each ring."""
    width = CHARACTER_WIDTH * anchor.size * len(anchor.text)
    for ring, radius in enumerate((gap, gap + 0.6 * anchor.size, gap + 1.4 * anchor.size, gap + 2.5 * anchor.size)):
        for order, k in enumerate((0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6, 7, -7, 8)):
            direction = anchor.prefer + k * math.pi / 8
            dx, dy = math.cos(direction), math.sin(direction)
            # Push the box's near edge, not its centre, out to the radius.
            x = anchor.at[0] + dx * (radius + width / 2)
            y = anchor.at[1] + dy * (radius + 0.55 * anchor.size) - 0.45 * anchor.size
            yield ring, order, Text((x, y), anchor.text, anchor.size, "middle", anchor.colour)


def open_direction(at: tuple[float, float], items: Sequence[Primitive], default: float = math.pi / 4,
                   reach: float = 0.3) -> float:
    """The direction (radians) from ``at`` into the widest gap between the lines drawn from it.

    Every segment of a polyline or arrow that ends at ``at`` (within
    ``reach`` mm) leaves it in one direction; one that passes through it
    leaves in two.  A label put in the middle of the widest gap sits clear
    of them all, as a draughtsman puts a letter in the open angle.
    """
    directions: list[float] = []
    x, y = at
    for item in items:
        if isinstance(item, Arrow):
            segments = [(item.start, item.end)]
        elif isinstance(item, Polyline):
            points = item.points + ((item.points[0],) if item.closed else ())
            segments = list(zip(points, points[1:]))
        else:
            continue
        for (x0, y0), (x1, y1) in segments:
            dx, dy = x1 - x0, y1 - y0
            length2 = dx * dx + dy * dy
            if length2 <= reach * reach:
                continue
            t = ((x - x0) * dx + (y - y0) * dy) / length2
            t = min(1.0, max(0.0, t))
            if math.hypot(x0 + t * dx - x, y0 + t * dy - y) > reach:
                continue
            if math.hypot(x1 - x, y1 - y) > reach:
                directions.append(math.atan2(y1 - y, x1 - x))
            if math.hypot(x0 - x, y0 - y) > reach:
                directions.append(math.atan2(y0 - y, x0 - x))
    if not directions:
        return default
    directions.sort()
    gaps = [(directions[(k + 1) % len(directions)] - d) % (2 * math.pi) or 2 * math.pi
            for k, d in enumerate(directions)]
    widest = max(range(len(gaps)), key=lambda k: (round(gaps[k], 9), -k))
    return directions[widest] + gaps[widest] / 2
