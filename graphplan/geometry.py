"""Plane geometry of the drawing board, knowing nothing of linkages.

Points and directions are complex numbers (x + iy).  Lines of action are
crossed with shapely, as a draughtsman crosses two lines with a ruler, and
every crossing reports the angle at which the lines meet: a shallow angle
means a reading that magnifies drawing errors.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from shapely import LineString, Point

from .errors import GraphplanError

# Two lines of one plan that cross farther than this many times the size of
# the figure from their points are taken as parallel: off the board.
_REACH = 1e3
# Each line is drawn this much beyond the crossing, so that it is found inside both segments.
_RUN_ON = 1.01


class ParallelLinesError(GraphplanError, ArithmeticError):
    """Two lines of action that do not cross: the construction is singular there."""

    def __init__(self, first: str, second: str) -> None:
        self.first, self.second = first, second
        super().__init__(f"the lines of action {first} and {second} are parallel, so they fix no point")


@dataclass(frozen=True)
class Line:
    """A line through ``through`` along ``direction`` (any length, not zero); ``label`` names it."""

    through: complex
    direction: complex
    label: str = ""

    @property
    def unit(self) -> complex:
        return self.direction / abs(self.direction)


def crossing_angle_deg(first: Line, second: Line) -> float:
    """The acute angle between two lines, in degrees (90 is best, 0 is parallel)."""
    sine = abs((first.unit.conjugate() * second.unit).imag)
    return math.degrees(math.asin(min(1.0, sine)))


def cross_lines(first: Line, second: Line, size: float) -> complex:
    """Where two lines of action cross; ``size`` is the extent of the figure they belong to.

    Raises
    ------
    ParallelLinesError
        when the lines do not cross within the board (parallel or nearly so).
    """
    # Drawn from the first line's point, each line just long enough to reach the crossing: the
    # crossing is then found to the precision its own distance allows, not the board's size.
    origin = first.through
    apart = second.through - origin
    sine = abs((first.unit.conjugate() * second.unit).imag)
    if apart == 0 and sine > 0:
        return origin
    if not sine > 0 or abs(apart) > _REACH * max(size, 1e-300) * sine:
        raise ParallelLinesError(first.label, second.label)
    reach = _RUN_ON * abs(apart) / sine
    segments = [LineString([_xy(start - reach * line.unit), _xy(start + reach * line.unit)])
                for line, start in ((first, 0j), (second, apart))]
    found = segments[0].intersection(segments[1])
    if not isinstance(found, Point) or found.is_empty:
        raise ParallelLinesError(first.label, second.label)
    return origin + complex(found.x, found.y)


def similar_point(image_a: complex, image_b: complex, a: complex, b: complex, p: complex) -> complex:
    """The image of P given the images of A and B: the figure a-b-p similar to A-B-P, lettered the same way.

    This is the similarity theorem of the plans: the image of a link is its
    figure turned and scaled, never mirrored, so one complex ratio carries it.
    """
    return image_a + (image_b - image_a) * (p - a) / (b - a)


def perpendicular_foot(centre: complex, through: complex, unit: complex) -> complex:
    """The foot of the perpendicular from ``centre`` to the line through ``through`` along ``unit``."""
    return through + ((centre - through) * unit.conjugate()).real * unit


def turned(vector: complex, sense: float) -> complex:
    """``vector`` turned by 90° counter-clockwise (``sense`` > 0) or clockwise (``sense`` < 0)."""
    return vector * (1j if sense > 0 else -1j)


def direction_deg(vector: complex) -> float:
    return math.degrees(cmath.phase(vector))


def _xy(z: complex) -> tuple[float, float]:
    return (z.real, z.imag)
