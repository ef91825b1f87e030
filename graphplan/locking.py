"""Where the friction in the pairs locks the mechanism between the analysed positions.

The equilibrium with friction is solved at the analysed positions, and a position where no driving load
moves the mechanism is warned of.  A mechanism can as well lock for a few degrees between two of them (its
transmission angle falls below the friction's reach and rises again) with both positions moving: the cycle
is swept densely, and each run of locked samples is narrowed to where the locking begins and
ends.  So is each run where the friction turns the power flow round, holding loads that would drive the
mechanism so that the driver must drive it (η′ ≤ 0): an engine's gas force just past its dead centre.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from .forces import Load
from .joint_friction import FrictionPair
from .loads import activity_at, link_loads, motion_state, power
from .mechanism import Mechanism
from .motion import Motion, solve
from .positions import PositionSet
from .statics import balancing_scale, equilibrium, turned_round

# Each round divides the brackets by the grid: a sweep's 1° narrowed to about 0.001°.
_GRID, _ROUNDS = 32, 2


@dataclass(frozen=True)
class LockedSpan:
    """A stretch of the driver's motion where the friction locks the mechanism (or, of
    :func:`turned_round_between`, holds the loads that would drive it), between two analysed positions
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

    def locked(values: np.ndarray, motion: Motion | None = None) -> np.ndarray:
        return _locked(mechanism, positions, friction, values, motion)

    spans, middles = _stretches(mechanism, positions, locked, sweep, locked(sweep, swept))
    culprits = pairs_that_lock(mechanism, positions, friction, middles)
    return tuple(replace(found, pairs=pairs) for found, pairs in zip(spans, culprits, strict=True))


def turned_round_between(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
                         sweep: np.ndarray, swept: Motion) -> tuple[LockedSpan, ...]:
    """The stretches between the analysed positions where the loads would drive the mechanism but ``friction``
    holds them, and the driver must drive it (:func:`statics.turned_round`), as :func:`locked_between` finds
    its; rounding of a zero Mb0 is judged against the sweep's largest.

    Only where it holds the loads that drive there alone as well (η′ ≤ 0 however large they are: an engine's
    gas force whose lever is shorter than the friction circle), the self-locking of the textbooks: near every
    place where the loads' powers come to cancel (the inertia loads of a shaper's ram overtaking its weights)
    friction outweighs what is left of them over a degree or so, which says nothing of the mechanism."""
    if not friction:
        return ()
    # The sweep's own balancing gives the scale and its flags: solved once, not again for each.
    swept_balancing = _balancings(mechanism, positions, friction, sweep, swept)
    scale = balancing_scale(swept_balancing[0][0])

    def turned(balancings: tuple[tuple[np.ndarray, np.ndarray, np.ndarray], ...]) -> np.ndarray:
        (ideal, rubbing, moving), (alone, alone_rubbing, alone_moving) = balancings
        return (moving & turned_round(mechanism, ideal, rubbing, scale)
                & alone_moving & turned_round(mechanism, alone, alone_rubbing, scale))

    def held(values: np.ndarray) -> np.ndarray:
        return turned(_balancings(mechanism, positions, friction, values))

    return tuple(_stretches(mechanism, positions, held, sweep, turned(swept_balancing))[0])


def _stretches(mechanism: Mechanism, positions: PositionSet, flagged: Callable[[np.ndarray], np.ndarray],
               sweep: np.ndarray, marked: np.ndarray) -> tuple[list[LockedSpan], np.ndarray]:
    """The runs of the sweep where ``flagged`` (at driver coordinates) holds, ``marked`` at the sweep's own samples,
    narrowed at both ends, between two analysed positions; with the middle of each."""
    cyclic = mechanism.driver.cyclic
    samples = sweep
    if cyclic:
        marked, samples = marked[:-1], sweep[:-1]
    if not marked.any() or marked.all():
        return [], np.zeros(0)
    step = float(sweep[1] - sweep[0])
    before = np.roll(marked, 1) if cyclic else np.concatenate([[False], marked[:-1]])
    after = np.roll(marked, -1) if cyclic else np.concatenate([marked[1:], [False]])
    firsts, lasts = np.flatnonzero(marked & ~before), np.flatnonzero(marked & ~after)
    if cyclic and lasts[0] < firsts[0]:   # the run over the start of the sweep ends first
        lasts = np.roll(lasts, -1)
    starts = _narrowed(flagged, samples[firsts] - step, samples[firsts], open_end=(not cyclic) & (firsts == 0))
    ends = _narrowed(flagged, samples[lasts] + step, samples[lasts],
                     open_end=(not cyclic) & (lasts == len(samples) - 1))
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
            middles.append(start + 0.5 * length * span)
            spans.append(LockedSpan(place, _at_position(start, positions, step, cyclic),
                                    _at_position(end, positions, step, cyclic)))
    return spans, np.array(middles)


def _at_position(value: float, positions: PositionSet, step: float, cyclic: bool) -> float:
    """An end narrowed to within its precision of an analysed position (that is not flagged itself: a dead centre
    where the loads take no power) is that position's coordinate: φ = 0°, not 0.000488°."""
    gaps = positions.values - value
    if cyclic:
        gaps = (gaps + np.pi) % (2.0 * np.pi) - np.pi   # the nearer way round
    nearest = int(np.argmin(np.abs(gaps)))
    if abs(gaps[nearest]) > abs(step) / _GRID ** _ROUNDS:
        return float(value)
    position = float(positions.values[nearest])
    # The position's own coordinate, in the turn the sweep has reached (a gap's sum would leave rounding of it).
    return position + 2.0 * np.pi * round((value - position) / (2.0 * np.pi)) if cyclic else position


def pairs_that_lock(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
                    values: np.ndarray) -> tuple[tuple[FrictionPair, ...], ...]:
    """At each driver coordinate of ``values``, where ``friction`` locks the mechanism: the pairs whose friction
    alone locks it there, none where only the pairs' together does.  What the user changes to free it."""
    values = np.asarray(values, dtype=float)
    if len(friction) == 1:
        return tuple(friction for _ in values)
    if len(values) == 0:
        return ()
    motion, _, loads = _loads_at(mechanism, positions, values, None)
    alone = [_locks(mechanism, motion, loads, (pair,)) for pair in friction]
    return tuple(tuple(pair for pair, locks in zip(friction, alone, strict=True) if locks[k])
                 for k in range(len(values)))


def _narrowed(flagged: Callable[..., np.ndarray], free: np.ndarray, held: np.ndarray,
              open_end: np.ndarray) -> np.ndarray:
    """Where ``flagged`` begins to hold between each ``free`` driver coordinate and its ``held`` (flagged)
    neighbour; at an ``open_end`` (the end of a travel, flagged) the flagged sample itself.

    Each round solves a grid across every bracket at once, not a bisection's midpoint at a time: a locked
    position takes the settling its longest way, and a few solves of many positions cost what one does."""
    free, held = free.astype(float), held.astype(float)
    rows = np.arange(len(free))
    for _ in range(_ROUNDS):
        grid = np.linspace(free, held, _GRID + 1, axis=1)
        now = flagged(grid.ravel()).reshape(grid.shape)
        now[:, -1] = True
        first = np.maximum(np.argmax(now, axis=1), 1)
        free, held = grid[rows, first - 1], grid[rows, first]
    return np.where(open_end, held, 0.5 * (free + held))


def _locked(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
            values: np.ndarray, motion: Motion | None = None) -> np.ndarray:
    """Whether the friction locks the mechanism at each driver coordinate of ``values``."""
    if len(values) == 0:
        return np.zeros(0, dtype=bool)
    motion, _, loads = _loads_at(mechanism, positions, values, motion)
    return _locks(mechanism, motion, loads, friction)


def _locks(mechanism: Mechanism, motion: Motion, loads: tuple[Load, ...],
           friction: tuple[FrictionPair, ...]) -> np.ndarray:
    """Whether ``friction`` locks the mechanism under ``loads`` in ``motion`` (a singular position does not lock:
    its own warning tells of it)."""
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        found = equilibrium(mechanism, motion, loads, friction)
    return found.locked & ~found.singular


def _balancings(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
                values: np.ndarray, motion: Motion | None = None
                ) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray], ...]:
    """The balancing load without and with ``friction`` at each driver coordinate of ``values``, and where the
    mechanism moves with it (neither singular nor locked): of all the loads, then of the loads alone that give the
    mechanism power there (the others 0); the motion and the loads found once for both."""
    if len(values) == 0:
        empty = np.zeros(0), np.zeros(0), np.zeros(0, dtype=bool)
        return empty, empty
    motion, state, loads = _loads_at(mechanism, positions, values, motion)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        driving = tuple(_where(np.asarray(power((load,), state)) > 0, load) for load in loads)
        found = []
        for chosen in (loads, driving):
            ideal, rubbing = (equilibrium(mechanism, motion, chosen, rubs) for rubs in ((), friction))
            found.append((ideal.balancing, rubbing.balancing, ~rubbing.locked & ~rubbing.singular & ~ideal.singular))
    return tuple(found)


def _loads_at(mechanism: Mechanism, positions: PositionSet, values: np.ndarray,
              motion: Motion | None) -> tuple[Motion, object, tuple[Load, ...]]:
    """The motion at each driver coordinate of ``values`` (``motion`` where known), its state, and the loads there."""
    if motion is None:
        motion = solve(mechanism, values, positions.reference, tolerant=True)
    acting = activity_at(mechanism, positions, values, tolerant=True)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        state = motion_state(motion)
        return motion, state, link_loads(mechanism, state, acting)


def _where(keep: np.ndarray, load: Load) -> Load:
    """``load`` where ``keep``, nothing elsewhere."""
    return replace(load, force=np.where(keep, load.force, 0j), moment=np.where(keep, load.moment, 0.0))


__all__ = ["LockedSpan", "locked_between", "pairs_that_lock", "turned_round_between"]
