"""A moment over the turn that jumps: smooth between its jumps, and the jumps where they are.

A load that acts over part of the stroke (a press's punching, a shaper's cut) makes the reduced
moment jump.  A periodic spline through samples of it rings round each jump (12 % of the jump on
either side for the quintic one the shaft takes, the integral kept) and moves the steady δ in its
fourth digit and a stall's threshold; :class:`PiecewiseMoment` keeps each piece between two jumps
smooth on its own and tells the integrator where the jumps are, so that it stops at each and goes
on with the next piece (:mod:`graphplan.machine_motion.integrator`).  A corner (a load switched on
at an extreme, where it does no work yet; a vertex of a load's diagram) is taken as a jump of
nought: a spline through it rang by 0.7 N·m at a compressor's peak of 157 N·m, and missed the mean
by the trapezoid's error.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike
from scipy.interpolate import make_interp_spline

TWO_PI = 2.0 * math.pi
# Samples of a piece closer than this share of its usual step stand for one another: a load's switch found by
# bisection a hair from a sample of the sweep (or from the turn's end, where the last piece is carried on into
# the first) would pin a quintic spline between two nearly equal abscissae, and a rounding's difference between
# their values, over a hair, is a slope that rang by ±100 N·m over a degree of a compressor's turn.  A sample
# dropped a hundredth of a step from another loses nothing a spline through the rest would not give back.
_CROWDED = 1e-2
# A step of the moment smaller than this share of its largest value is no jump: where a load switches on or off at
# an extreme, the speed ratio there is nought and the two sides differ only by the switch's place found a hair off
# it (a compressor's 4 kN at a piston speed ratio of 10⁻¹¹, 2.6·10⁻⁷ N·m); taken as continuous, a real step this
# small would move the turn's work by a hundred-thousandth of a step's share of the peak.
_JUMP = 1e-5


class PiecewiseMoment:
    """A moment over one turn from its samples, an angle given twice being a jump.

    ``angles`` rise from 0 to 2π (both ends given); where an angle is given twice, the first value
    is the one reached from the left and the second the one it jumps to (the same value: a corner).
    Unequal values at 0 and 2π, or 2π given twice, are a jump at 0.  Between two jumps the samples
    are interpolated by a spline of degree 5 (lower where a piece has fewer samples), each piece on
    its own.
    """

    def __init__(self, angles: ArrayLike, values: ArrayLike) -> None:
        x = np.asarray(angles, dtype=float)
        y = np.asarray(values, dtype=float)
        if x.ndim != 1 or x.shape != y.shape or x.size < 2:
            raise ValueError("a piecewise moment needs as many angles as values, at least two")
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
            raise ValueError("a piecewise moment's angles and values must be finite")
        if x[0] != 0.0 or abs(x[-1] - TWO_PI) > 1e-9 or np.any(np.diff(x) < 0):
            raise ValueError("a piecewise moment's angles must rise from 0 to 2π (an angle given twice is a jump)")
        x = x.copy()
        # The turn's ends as a sweep reaches them, a rounding off: a jump given there keeps its two samples at one
        # angle (a switch a hair before 2π, made one angle by exact_jumps, is a jump at 2π, the same as at 0).
        x[np.abs(x - TWO_PI) <= 1e-9] = TWO_PI
        x[np.abs(x) <= 1e-9] = 0.0
        cuts = np.flatnonzero(np.diff(x) == 0) + 1
        # A sample alone between two jumps at one angle spans nothing (a jump at 2π given as the turn's last).
        pieces = [(px, py) for px, py in zip(np.split(x, cuts), np.split(y, cuts), strict=True) if px.size > 1]
        if not pieces:
            raise ValueError("a piecewise moment needs two samples between its jumps somewhere")
        # The turn's ends are one place: values there a rounding apart (a sweep's two ends) are no jump, unless
        # an angle given twice there says it is one (a corner).
        scale = float(np.max(np.abs(y)))
        given_twice = x[1] == x[0] or x[-1] == x[-2]
        closing_jump = given_twice or abs(pieces[-1][1][-1] - pieces[0][1][0]) > _JUMP * scale
        if len(pieces) > 1 and not closing_jump:
            # No jump at 0: the turn's last piece goes on into its first (a sample of it a hair before 2π and
            # the first piece's at 0 crowding together at the seam: _smooth keeps one).
            (last_x, last_y), (first_x, first_y) = pieces[-1], pieces[0]
            pieces = [(np.concatenate([last_x[:-1] - TWO_PI, first_x]), np.concatenate([last_y[:-1], first_y])),
                      *pieces[1:-1]]
        self._starts = [float(px[0]) for px, _ in pieces]
        self._spans = [(float(px[0]), float(px[-1])) for px, _ in pieces]
        self._middles = [(float(px[0]) + float(px[-1])) / 2.0 for px, _ in pieces]
        self._pieces = [_smooth(px, py) for px, py in pieces]
        jumped = len(pieces) > 1 or closing_jump
        by_angle = sorted((start % TWO_PI, k) for k, start in enumerate(self._starts)) if jumped else []
        #: Where the moment jumps within [0, 2π), rising; and the piece that begins at each.
        self.jumps = tuple(angle for angle, _ in by_angle)
        self.pieces_from = tuple(k for _, k in by_angle)

    def piece_at(self, phi: float) -> int:
        """The piece the moment is on at ``phi`` (at a jump, the one that begins there)."""
        origin = self._starts[0]
        return bisect.bisect_right(self._starts, origin + (phi - origin) % TWO_PI) - 1

    def on_piece(self, piece: int, phi: float) -> float:
        """Piece ``piece`` at ``phi`` (rad), carried on smoothly past its ends: a solver's step may look a little
        beyond a jump before its event stops it there."""
        middle = self._middles[piece]
        return float(self._pieces[piece](phi - TWO_PI * round((phi - middle) / TWO_PI)))

    def __call__(self, phi: float) -> float:
        return self.on_piece(self.piece_at(phi), phi)

    def mean(self) -> float:
        """The moment's mean over the turn, ∫M dφ/2π, integrated exactly piece by piece: samples at equal
        steps miss a jump's place by up to a step, and with it the mean by a step's share of the jump."""
        total = 0.0
        for piece, (start, end) in zip(self._pieces, self._spans, strict=True):
            if hasattr(piece, "integrate"):
                total += float(piece.integrate(start, end))
            else:
                total += piece(start) * (end - start)
        return total / TWO_PI


def exact_jumps(angles: ArrayLike, values: ArrayLike, *, gap: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """Samples of a sweep over a turn (0 to 2π) whose load switches and diagrams' vertices were found by
    bisection, two samples a hair apart (closer than ``gap`` rad) on either side of each, as
    :class:`PiecewiseMoment` reads them: each such place one angle given twice, with the values on its two sides
    where they differ by more than :data:`_JUMP` of the moment's largest (a jump), else the first twice (a
    corner).  Samples closer than :data:`_CROWDED` of the sweep's step to such a place stand for it, and are
    left out; such a place that close to the turn's ends is one at 0 (2π given twice), as a load switched at the
    dead centre where the turn starts, found a hair either side of it, is."""
    x = np.array(angles, dtype=float)
    y = np.array(values, dtype=float)
    close = np.diff(x) <= gap
    if not np.any(close):
        return x, y
    scale = float(np.max(np.abs(y)))
    near = _CROWDED * float(np.median(np.diff(x)[~close])) if not np.all(close) else 0.0
    # Each run of samples a hair apart is one place: its first sample the value from the left, its last the right.
    edges = np.diff(np.concatenate([[0], close.astype(int), [0]]))
    places = []
    for first, last in zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1), strict=True):
        angle, left, right = x[first], y[first], y[last]
        if abs(right - left) <= _JUMP * scale:
            right = left
        if places and angle - places[-1][0] <= near:
            places[-1] = (places[-1][0], places[-1][1], right)
        else:
            places.append((angle, left, right))
    start, end = x[0], x[-1]
    at_start = [place for place in places if place[0] - start <= near]
    at_end = [place for place in places if end - place[0] <= near]
    inside = [place for place in places if place not in at_start and place not in at_end]
    alone = np.ones(x.size, dtype=bool)
    for angle, _, _ in places:
        alone &= np.abs(x - angle) > near
    points = [(angle, value) for angle, value in zip(x[alone], y[alone], strict=True)
              if not (at_start or at_end) or near < angle - start and near < end - angle]
    for angle, left, right in inside:
        points += [(angle, left), (angle, right)]
    points.sort(key=lambda point: point[0])  # stable: a place's left side stays before its right
    if at_start or at_end:
        # The turn's ends: the value after the dead centre at 0, the value before it at 2π, and 2π given twice;
        # the samples at the ends themselves where the place near them is a corner (the others are a hair off).
        after, before = y[0], y[-1]
        if at_start and abs(at_start[-1][2] - after) > _JUMP * scale:
            after = at_start[-1][2]
        if at_end and abs(at_end[0][1] - before) > _JUMP * scale:
            before = at_end[0][1]
        if abs(after - before) <= _JUMP * scale:
            after = before
        points = [(start, after), *points, (end, before), (end, after)]
    found = np.array(points, dtype=float)
    return found[:, 0].copy(), found[:, 1].copy()


def _smooth(x: np.ndarray, y: np.ndarray) -> Callable[[float], float]:
    """A spline through one piece's samples: quintic where it has six or more, lower where fewer."""
    x, y = _uncrowded(x, y)
    if x.size == 1 or x[-1] == x[0]:
        value = float(y[-1])
        return lambda phi: value
    degree = 5 if x.size >= 6 else 3 if x.size >= 4 else 1
    spline = make_interp_spline(x, y, k=degree)
    spline.extrapolate = True
    return spline


def _uncrowded(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """One piece's samples without those closer than :data:`_CROWDED` of its usual step to the last one kept, or
    to the piece's end: the ends, where it jumps, are kept."""
    steps = np.diff(x)
    steps = steps[steps > 0]
    if x.size <= 2 or steps.size == 0:
        return x, y
    near = _CROWDED * float(np.median(steps))
    kept = [0]
    for i in range(1, x.size - 1):
        if x[i] - x[kept[-1]] > near and x[-1] - x[i] > near:
            kept.append(i)
    kept.append(x.size - 1)
    return x[kept], y[kept]
