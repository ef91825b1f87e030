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
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from .primitives import Circle, Polyline, Primitive, Text

# Width of a character as a fraction of the cap height (DejaVu Sans, mixed text).
CHARACTER_WIDTH = 0.75


@dataclass(frozen=True)
class Anchor:
    """A label to place: its text, the point it names, the direction it prefers (radians)."""

    at: tuple[float, float]
    text: str
    size: float = 3.0
    prefer: float = math.pi / 4
    colour: str = "black"


def text_box(text: Text) -> BaseGeometry:
    width = CHARACTER_WIDTH * text.size * len(text.text)
    x0 = {"start": 0.0, "middle": -width / 2, "end": -width}[text.anchor]
    return box(text.at[0] + x0, text.at[1] - 0.25 * text.size, text.at[0] + x0 + width, text.at[1] + 1.1 * text.size)


def obstacles_of(items: Sequence[Primitive]) -> list[BaseGeometry]:
    shapes: list[BaseGeometry] = []
    for item in items:
        if isinstance(item, Polyline) and len(item.points) >= 2:
            shapes.append(LineString(item.points + ((item.points[0],) if item.closed else ())))
        elif isinstance(item, Circle):
            shapes.append(Point(item.centre).buffer(item.radius))
        elif isinstance(item, Text):
            shapes.append(text_box(item))
    return shapes


def place_labels(anchors: Sequence[Anchor], obstacles: Sequence[BaseGeometry], gap: float = 1.2) -> list[Text]:
    """Texts for ``anchors``, each at the first free spot, or where it covers the least.

    Another label is never covered when any spot avoids it; lines may be
    crossed in a crowded drawing, as few as possible.
    """
    placed: list[Text] = []
    fixed = list(obstacles)
    tree = STRtree(fixed) if fixed else None
    placed_boxes: list[BaseGeometry] = []
    for anchor in anchors:
        best, best_cost = None, math.inf
        for order, candidate in enumerate(_candidates(anchor, gap)):
            shape = text_box(candidate)
            hits = sum(1 for i in tree.query(shape) if fixed[i].intersects(shape)) if tree is not None else 0
            overlaps = sum(1 for b in placed_boxes if b.intersects(shape))
            cost = 1000 * overlaps + 10 * hits + order * 0.01
            if cost < best_cost:
                best, best_cost = candidate, cost
            if overlaps == 0 and hits == 0:
                break
        assert best is not None
        placed.append(best)
        placed_boxes.append(text_box(best))
    return placed


def _candidates(anchor: Anchor, gap: float):
    width = CHARACTER_WIDTH * anchor.size * len(anchor.text)
    for radius in (gap, gap + anchor.size, gap + 2.5 * anchor.size):
        for k in (0, 1, -1, 2, -2, 3, -3, 4):
            direction = anchor.prefer + k * math.pi / 4
            dx, dy = math.cos(direction), math.sin(direction)
            # Push the box's near edge, not its centre, out to the radius.
            x = anchor.at[0] + dx * (radius + width / 2)
            y = anchor.at[1] + dy * (radius + 0.55 * anchor.size) - 0.45 * anchor.size
            yield Text((x, y), anchor.text, anchor.size, "middle", anchor.colour)
