"""Where the friction in the pairs locks the mechanism between the analysed positions.

The equilibrium with friction is solved at the analysed positions, and a position where no driving load
moves the mechanism is warned of.  A mechanism can as well lock for a few degrees between two of them (its
transmission angle falls below the friction's reach and rises again) with both positions moving: the cycle
is swept densely, and each run of locked samples is narrowed to where the locking begins and
ends.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .joint_friction import FrictionPair
from .loads import activity_at, link_loads, motion_state
from .mechanism import Mechanism
from .motion import Motion, solve
from .positions import PositionSet
from .statics import equilibrium

# Each round divides the brackets by the grid: a sweep's 1° narrowed to about 0.001°.
_GRID, _ROUNDS = 32, 2


@dataclass(frozen=True)
class LockedSpan:
    """A stretch of the driver's motion where the friction locks the mechanism, between two analysed positions
    that move: ``after`` is the index of the one before it; ``start`` and ``end`` are driver coordinates (rad
    or m), in the order the driver moves."""

    after: int
    start: float
    end: float
    # The pairs whose friction alone locks it there (:func:`pairs_that_lock`, at the stretch's middle).
    pairs: tuple[FrictionPair, ...] = ()


def locked_between(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
                   sweep: np.ndarray, swept: Motion) -> tuple[LockedSpan, ...]:
    """The stretches between the analysed positions where ``friction`` locks the mechanism.

    ``sweep`` is the driver's dense sweep over the cycle (its last sample closing a crank's turn) or over
    the travel, in the order the driver moves; ``swept`` the motion there.  A stretch that holds an analysed
    position is that position's to tell, and is left out.
    """
    if not friction:
        return ()
    cyclic = mechanism.driver.cyclic
    locked = _locked(mechanism, positions, friction, sweep, swept)
    samples = sweep
    if cyclic:
        locked, samples = locked[:-1], sweep[:-1]
    if not locked.any() or locked.all():
        return ()
    step = float(sweep[1] - sweep[0])
    before = np.roll(locked, 1) if cyclic else np.concatenate([[False], locked[:-1]])
    after = np.roll(locked, -1) if cyclic else np.concatenate([locked[1:], [False]])
    firsts, lasts = np.flatnonzero(locked & ~before), np.flatnonzero(locked & ~after)
    if cyclic and lasts[0] < firsts[0]:   # the run over the start of the sweep ends first
        lasts = np.roll(lasts, -1)
    starts = _narrowed(mechanism, positions, friction, samples[firsts] - step, samples[firsts],
                       open_end=~cyclic & (firsts == 0))
    ends = _narrowed(mechanism, positions, friction, samples[lasts] + step, samples[lasts],
                     open_end=~cyclic & (lasts == len(samples) - 1))
    span = float(sweep[-1] - sweep[0])
    analysed = (positions.values - sweep[0]) / span
    spans, middles = [], []
    for start, end in zip(starts, ends, strict=True):
        low = (start - sweep[0]) / span
        length = (end - start) / span % 1.0 if cyclic else (end - start) / span
        inside = ((analysed - low) % 1.0 if cyclic else analysed - low)
        if np.any((inside >= 0.0) & (inside <= length)):
            continue
        place = int(np.searchsorted(analysed, low % 1.0 if cyclic else low)) - 1
        if place < 0 and cyclic:
            place = len(analysed) - 1
        if 0 <= place < len(analysed) - (0 if cyclic else 1):
            spans.append(LockedSpan(place, float(start), float(end)))
            middles.append(start + 0.5 * length * span)
    culprits = pairs_that_lock(mechanism, positions, friction, np.array(middles))
    return tuple(replace(found, pairs=pairs) for found, pairs in zip(spans, culprits, strict=True))


def pairs_that_lock(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
                    values: np.ndarray) -> tuple[tuple[FrictionPair, ...], ...]:
    """At each driver coordinate of ``values``, where ``friction`` locks the mechanism: the pairs whose friction
    alone locks it there, none where only the pairs' together does.  What the user changes to free it."""
    values = np.asarray(values, dtype=float)
    if len(friction) == 1:
        return tuple(friction for _ in values)
    alone = [_locked(mechanism, positions, (pair,), values) for pair in friction]
    return tuple(tuple(pair for pair, locks in zip(friction, alone, strict=True) if locks[k])
                 for k in range(len(values)))


def _narrowed(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
              free: np.ndarray, held: np.ndarray, open_end: np.ndarray) -> np.ndarray:
    """Where the locking begins between each ``free`` driver coordinate and its ``held`` (locked) neighbour;
    at an ``open_end`` (the end of a travel, locked) the locked sample itself.

    Each round solves a grid across every bracket at once, not a bisection's midpoint at a time: a locked
    position takes the settling its longest way, and a few solves of many positions cost what one does."""
    free, held = free.astype(float), held.astype(float)
    rows = np.arange(len(free))
    for _ in range(_ROUNDS):
        grid = np.linspace(free, held, _GRID + 1, axis=1)
        now = _locked(mechanism, positions, friction, grid.ravel()).reshape(grid.shape)
        now[:, -1] = True
        first = np.maximum(np.argmax(now, axis=1), 1)
        free, held = grid[rows, first - 1], grid[rows, first]
    return np.where(open_end, held, 0.5 * (free + held))


def _locked(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
            values: np.ndarray, motion: Motion | None = None) -> np.ndarray:
    """Whether the friction locks the mechanism at each driver coordinate of ``values`` (a singular one does
    not lock: its own warning tells of it)."""
    if len(values) == 0:
        return np.zeros(0, dtype=bool)
    if motion is None:
        motion = solve(mechanism, values, positions.reference, tolerant=True)
    acting = activity_at(mechanism, positions, values, tolerant=True)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        loads = link_loads(mechanism, motion_state(motion), acting)
        found = equilibrium(mechanism, motion, loads, friction)
    return found.locked & ~found.singular


__all__ = ["LockedSpan", "locked_between", "pairs_that_lock"]
