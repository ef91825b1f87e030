"""The turns of the driving shaft in a run, their extreme speeds and δ, and the steady state."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from .shaft import TWO_PI

# Samples per cycle when its extreme speeds are looked for (then refined by a parabola).
SAMPLES_PER_CYCLE = 256


@dataclass(frozen=True)
class Cycle:
    """One turn of the driving shaft (from φ0 + 2πk to φ0 + 2π(k+1))."""

    index: int
    start: float
    period: float
    max_speed: float
    min_speed: float

    @property
    def mean_speed(self) -> float:
        """The time-averaged speed 2π/T, rad/s."""
        return TWO_PI / self.period

    @property
    def middle_speed(self) -> float:
        """ωm = (ωmax + ωmin)/2, rad/s: the mean of the textbook δ."""
        return 0.5 * (self.max_speed + self.min_speed)

    @property
    def delta(self) -> float:
        """The coefficient of speed fluctuation δ = (ωmax − ωmin)/ωm."""
        return (self.max_speed - self.min_speed) / self.middle_speed


@dataclass(frozen=True)
class SteadyState:
    """The periodic regime: the values of its last cycle, and when it was reached."""

    cycle: Cycle
    reached_at: float
    first_cycle: int

    @property
    def mean_speed(self) -> float:
        return self.cycle.mean_speed

    @property
    def max_speed(self) -> float:
        return self.cycle.max_speed

    @property
    def min_speed(self) -> float:
        return self.cycle.min_speed

    @property
    def delta(self) -> float:
        return self.cycle.delta

    @property
    def period(self) -> float:
        return self.cycle.period


def _extreme(values: np.ndarray, largest: bool) -> float:
    """The largest (smallest) of equally spaced samples, refined by the parabola through its neighbours."""
    i = int(np.argmax(values) if largest else np.argmin(values))
    if i == 0 or i == values.size - 1:
        return float(values[i])
    y0, y1, y2 = values[i - 1], values[i], values[i + 1]
    curvature = y0 - 2.0 * y1 + y2
    if curvature == 0:
        return float(y1)
    offset = 0.5 * (y0 - y2) / curvature
    return float(y1 - 0.25 * (y0 - y2) * offset)


def find_cycles(t: np.ndarray, phi: np.ndarray, dense: Callable[[np.ndarray], np.ndarray],
                limit: int | None = None) -> tuple[Cycle, ...]:
    """Every complete turn of the driving shaft from its angle at the start, with its extreme speeds.

    ``limit`` keeps the cost bounded on long runs: only the last ``limit`` turns are analysed
    (their indices still count from the start).
    """
    if t.size < 2:
        return ()
    reach = np.maximum.accumulate(phi)
    origin = phi[0]
    turns = math.floor((reach[-1] - origin) / TWO_PI + 1e-12)
    if turns < 1:
        return ()
    first = 0 if limit is None else max(0, turns - limit)
    targets = origin + TWO_PI * np.arange(first, turns + 1)
    bounds = _crossings(t, phi, reach, dense, targets)
    fractions = np.linspace(0.0, 1.0, SAMPLES_PER_CYCLE + 1)
    grid = bounds[:-1, None] + (bounds[1:] - bounds[:-1])[:, None] * fractions[None, :]
    speeds = dense(grid.ravel())[1].reshape(grid.shape)
    return tuple(Cycle(index=first + k, start=float(bounds[k]), period=float(bounds[k + 1] - bounds[k]),
                       max_speed=_extreme(speeds[k], True), min_speed=_extreme(speeds[k], False))
                 for k in range(bounds.size - 1))


def _crossings(t: np.ndarray, phi: np.ndarray, reach: np.ndarray, dense: Callable[[np.ndarray], np.ndarray],
               targets: np.ndarray) -> np.ndarray:
    """The times the shaft's angle passes ``targets``: Newton's method on the dense output, all at once.

    Each crossing is bracketed by two steps; Newton's steps (dφ/dt = ω) are kept inside the
    bracket, and the rare crossing that has not converged (ω near zero) is found by brentq.
    """
    upper = np.clip(np.searchsorted(reach, targets, side="left"), 1, t.size - 1)
    lo, hi = t[upper - 1], t[upper]
    rise = phi[upper] - phi[upper - 1]
    share = np.where(rise > 0, (targets - phi[upper - 1]) / np.where(rise > 0, rise, 1.0), 1.0)
    guess = np.where(hi > lo, lo + np.clip(share, 0.0, 1.0) * (hi - lo), hi)
    guess[targets <= phi[0]] = t[0]
    for _ in range(6):
        state = dense(guess)
        speed = np.where(state[1] > 0, state[1], np.inf)
        guess = np.clip(guess - (state[0] - targets) / speed, lo, hi)
    miss = np.abs(dense(guess)[0] - targets) > 1e-10 * np.maximum(1.0, np.abs(targets))
    for k in np.flatnonzero(miss & (hi > lo)):
        goal = targets[k]
        if (dense(lo[k])[0] - goal) * (dense(hi[k])[0] - goal) <= 0:
            guess[k] = brentq(lambda s, goal=goal: dense(s)[0] - goal, lo[k], hi[k], xtol=1e-14 * max(1.0, hi[k]))
    return guess


def refined(cycle: Cycle, dense: Callable[[np.ndarray], np.ndarray]) -> Cycle:
    """``cycle`` with its extreme speeds found on the dense output to the solver's accuracy.

    The parabola through the samples round an extreme is exact to its sampling where ω is smooth; where a
    jump of the resistance makes a corner of ω (its extreme there), the parabola overshoots the corner (a
    press: 6.52046 for 6.52003 rad/s, δ off in its third digit).  Brent's bounded search on the two
    sampling intervals round the sample goes to the corner as well as to a smooth extreme.
    """
    from scipy.optimize import minimize_scalar  # imported here: only the steady cycle is refined

    times = cycle.start + cycle.period * np.linspace(0.0, 1.0, SAMPLES_PER_CYCLE + 1)
    speeds = dense(times)[1]
    found = []
    for sign in (-1.0, 1.0):  # the largest speed, then the smallest
        i = int(np.argmin(sign * speeds))
        low, high = times[max(i - 1, 0)], times[min(i + 1, times.size - 1)]
        best = minimize_scalar(lambda s, sign=sign: sign * float(dense(np.array([s]))[1, 0]), bounds=(low, high),
                               method="bounded", options={"xatol": 1e-12 * max(1.0, abs(high))})
        found.append(float(speeds[i]) if best.fun > sign * speeds[i] else sign * float(best.fun))
    return Cycle(index=cycle.index, start=cycle.start, period=cycle.period, max_speed=found[0], min_speed=found[1])


def find_steady_state(cycles: tuple[Cycle, ...], tolerance: float) -> SteadyState | None:
    """The first run of cycles in which the mean speed and δ have stopped changing.

    Each cycle's change from the one before, ``d = max(|Δωm|/ωm, |Δδ|)``, falls geometrically
    while the transient dies out; the distance still to go is about ``d/(1 − r)`` with ``r`` the
    ratio of successive changes (capped at 0.95).  The regime is steady where that is within
    ``tolerance``; its values are those of the last cycle before it changes again (a brake, the
    motor switched off).
    """
    changes = [math.inf]
    for before, after in itertools.pairwise(cycles):
        changes.append(max(abs(after.mean_speed - before.mean_speed) / after.mean_speed,
                           abs(after.delta - before.delta)))

    def settled(k: int) -> bool:
        if k < 2:
            return False
        ratio = min(changes[k] / changes[k - 1], 0.95) if changes[k - 1] > 0 else 0.0
        return changes[k] / (1.0 - ratio) <= tolerance

    first = next((k for k in range(len(cycles)) if settled(k)), None)
    if first is None:
        return None
    last = first
    while last + 1 < len(cycles) and settled(last + 1):
        last += 1
    return SteadyState(cycle=cycles[last], reached_at=cycles[first].start, first_cycle=cycles[first].index)
