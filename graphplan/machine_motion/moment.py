"""A moment over the turn that jumps: smooth between its jumps, and the jumps where they are.

A load that acts over part of the stroke (a press's punching, a shaper's cut) makes the reduced
moment jump.  A periodic spline through samples of it rings round each jump (12 % of the jump on
either side for the quintic one the shaft takes, the integral kept) and moves the steady δ in its
fourth digit and a stall's threshold; :class:`PiecewiseMoment` keeps each piece between two jumps
smooth on its own and tells the integrator where the jumps are, so that it stops at each and goes
on with the next piece (:mod:`graphplan.machine_motion.integrator`).
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike
from scipy.interpolate import make_interp_spline

TWO_PI = 2.0 * math.pi
# Samples closer than this (rad) to the end of their piece stand for that end: a load's switch found by
# bisection a hair from a sample of the sweep would pin the spline between two nearly equal abscissae.
_CROWDED = 1e-6


class PiecewiseMoment:
    """A moment over one turn from its samples, an angle given twice being a jump.

    ``angles`` rise from 0 to 2π (both ends given); where an angle is given twice, the first value
    is the one reached from the left and the second the one it jumps to.  Unequal values at 0 and
    2π are a jump at 0.  Between two jumps the samples are interpolated by a spline of degree 5
    (lower where a piece has fewer samples), each piece on its own.
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
        closing_jump = pieces[-1][1][-1] != pieces[0][1][0]
        if len(pieces) > 1 and not closing_jump:
            # No jump at 0: the turn's last piece goes on into its first.
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
    """Samples of a sweep whose load switches were found by bisection, two samples a hair apart (closer than
    ``gap`` rad) on either side of each: where their values differ, a jump, given at one angle twice as
    :class:`PiecewiseMoment` reads it; where they do not (a diagram's load setting in from nought), one sample."""
    x = np.array(angles, dtype=float)
    y = np.array(values, dtype=float)
    scale = float(np.max(np.abs(y))) if y.size else 0.0
    keep = np.ones(x.size, dtype=bool)
    for i in np.flatnonzero(np.diff(x) <= gap):
        if abs(y[i + 1] - y[i]) > 1e-9 * scale:
            x[i + 1] = x[i]
        else:
            keep[i + 1] = False
    return x[keep], y[keep]


def _smooth(x: np.ndarray, y: np.ndarray) -> Callable[[float], float]:
    """A spline through one piece's samples: quintic where it has six or more, lower where fewer."""
    keep = np.ones(x.size, dtype=bool)
    keep[1:-1] = (x[1:-1] - x[0] > _CROWDED) & (x[-1] - x[1:-1] > _CROWDED)
    x, y = x[keep], y[keep]
    if x.size == 1 or x[-1] == x[0]:
        value = float(y[-1])
        return lambda phi: value
    degree = 5 if x.size >= 6 else 3 if x.size >= 4 else 1
    spline = make_interp_spline(x, y, k=degree)
    spline.extrapolate = True
    return spline
