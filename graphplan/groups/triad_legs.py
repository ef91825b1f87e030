"""How long a triad's turning leg may be for the crank to turn round, or to assemble at all: the nearest and the
farthest its inner joint can be from its outer joint with the other two legs as given, at every angle of the turn (or
at some angle of it).

Left without one leg, the ternary link keeps one freedom: turned to ψ, each of the other two legs holds B on a circle
or a line (its track carried back by B's side to its corner, as :meth:`Triad.assemblies` turns the link round), B is
where the two meet, and the free leg's corner follows.  Its distance from its outer joint over every ψ, at each angle
of the crank, gives the lengths that close the triad there; a length closes it all round only between the largest
nearest and the least farthest.  That is needed, not enough: the assembly the scene follows may still fold where
the distance has an extreme of its own between them, which a student is told of as the reach's ends.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

# The turn sampled at _COARSE_ANGLES angles first, then again over a coarse step either side of the angle that binds at
# _FINE_WINDOW angles a side, picked from the motion before the group (``before``, solved every hundredth of a degree):
# the bound at the coarse angle alone is off in its fourth figure.
_COARSE_ANGLES = 180
_FINE_WINDOW = 40
# The ternary link's turns sampled at each angle, then at the binding angle and its neighbours _FINE_TURNS times as
# finely: near where two legs' tracks just touch, the corner runs as √ψ, and a coarse sweep steps far along it there.
_TURNS = 1024
_FINE_TURNS = 64
# A free leg whose corner can run off more than this many times the triad's size (a slider's guide and a slot run
# parallel) has no upper bound to give.
_UNBOUNDED = 100.0


@dataclass(frozen=True)
class LegReach:
    """The lengths of one turning leg that close the triad at every angle of the turn (or at some angle), the others
    as given: from ``nearest`` to ``farthest`` (m; ``farthest`` None where no length is too long); or none,
    ``nearest`` None, where at the crank's angle ``shut_at`` (rad) the other two legs close at no turn of the ternary
    link, whatever this one's length (at some angle: where they close at none, or the lengths that close it at one
    angle or another leave a gap)."""

    leg: int
    nearest: float | None
    farthest: float | None
    shut_at: float | None = None


# Which of a leg's distances bounds it, nearest (0) or farthest (1), and whether by its largest over the angles:
# all round the turn, the largest nearest and the least farthest; at some angle, the least nearest and the largest
# farthest.
_ALL_ROUND = ((0, True), (1, False))
_SOMEWHERE = ((0, False), (1, True))


def leg_reaches(triad, before, somewhere: bool = False) -> tuple[LegReach, ...]:
    """Each turning leg's :class:`LegReach` over ``before``, the motion of the groups before the triad over the
    whole turn (with ``somewhere``, over the angles they assemble at), in the scene's assembly; the ternary link's
    corners run the way the scene's sketch has them."""
    tracks = triad.tracks_over(lambda name: before.points[name].r, before.guide, before.count)
    local = triad.local_corners(triad.sketched_turn)
    count = len(before.driver)
    coarse = np.unique(np.linspace(0, count - 1, _COARSE_ANGLES + 1).round().astype(int))
    turns = np.linspace(0.0, 2.0 * math.pi, _TURNS + 1)
    reaches = []
    for leg in triad.turning_legs:
        distances = _distances(tracks, local, leg, coarse, turns)
        closes = np.isfinite(distances[0])
        if somewhere and not (closes.any() and _one_span(*distances)):
            reaches.append(LegReach(leg, None, None))
            continue
        if not somewhere and not closes.all():
            reaches.append(LegReach(leg, None, None, shut_at=float(before.driver[coarse[np.argmin(closes)]])))
            continue
        low, high = (_refined(tracks, local, leg, coarse, _at(distances, bound), bound)
                     for bound in (_SOMEWHERE if somewhere else _ALL_ROUND))
        reaches.append(LegReach(leg, low, None if high > _UNBOUNDED * triad.size else high))
    return tuple(reaches)


def _one_span(nearest: np.ndarray, farthest: np.ndarray) -> bool:
    """Whether the lengths from ``nearest`` to ``farthest`` at each angle where they close join into one span."""
    closes = np.isfinite(nearest)
    order = np.argsort(nearest[closes])
    reached = np.maximum.accumulate(farthest[closes][order])
    return bool(np.all(nearest[closes][order][1:] <= reached[:-1]))


def _refined(tracks, local, leg: int, coarse: np.ndarray, binding: int, bound: tuple[int, bool]) -> float:
    """The ``bound`` (:data:`_ALL_ROUND`, :data:`_SOMEWHERE`) at its coarse angle ``binding``, found again among the
    motion's samples about it, then with the link's turns swept finely there and at its neighbours."""
    start = coarse[max(binding - 1, 0)]
    stop = coarse[min(binding + 1, len(coarse) - 1)]
    angles = np.unique(np.linspace(start, stop, 2 * _FINE_WINDOW + 1).round().astype(int))
    at = _at(_distances(tracks, local, leg, angles, np.linspace(0.0, 2.0 * math.pi, _TURNS + 1)), bound)
    angles = angles[max(at - 1, 0):at + 2]
    distances = _distances(tracks, local, leg, angles, np.linspace(0.0, 2.0 * math.pi, _TURNS * _FINE_TURNS + 1))
    return float(distances[bound[0]][_at(distances, bound)])


def _at(distances: tuple[np.ndarray, np.ndarray], bound: tuple[int, bool]) -> int:
    """Where the ``bound`` is among the angles ``distances`` are at."""
    of, largest = bound
    return int((np.nanargmax if largest else np.nanargmin)(distances[of]))


def _distances(tracks, local, leg: int, angles: np.ndarray, turns: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The nearest and farthest (m) the free ``leg``'s corner comes to its outer joint over the ternary link's
    ``turns`` (rad), at each of the crank's samples ``angles``; NaN where the other two legs close at no turn."""
    from .triad import _carried_back, _meet  # the triad's own geometry, which imports this module

    held = [n for n in range(3) if n != leg]
    nearest = np.empty(len(angles))
    farthest = np.empty(len(angles))
    # A few thousand angle-by-turn samples at a time: the whole grid of a fine sweep would take a gigabyte.
    rows = max(1, 2_000_000 // len(turns))
    rotation = np.exp(1j * turns)[None, :]
    for first in range(0, len(angles), rows):
        taken = angles[first:first + rows]
        shaped = [track.taken(taken[:, None]) for track in tracks]  # a column of angles against a row of turns
        spans = []
        for sign in (1, -1):
            one, other = (_carried_back(shaped[n], local[n] * rotation, rotation) for n in held)
            with np.errstate(invalid="ignore"):
                b = _meet(one, other, sign)
            spans.append(np.abs(b + local[leg] * rotation - shaped[leg].centre))
        both = np.concatenate(spans, axis=1)
        finite = np.isfinite(both)
        closes = finite.any(axis=1)
        nearest[first:first + rows] = np.where(closes, np.min(np.where(finite, both, np.inf), axis=1), np.nan)
        farthest[first:first + rows] = np.where(closes, np.max(np.where(finite, both, -np.inf), axis=1), np.nan)
    return nearest, farthest


__all__ = ["LegReach", "leg_reaches"]
