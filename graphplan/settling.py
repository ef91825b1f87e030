"""The reactions with friction in the pairs: the fixed point x = G(x) of a solve that takes each pair's
friction from the reactions it finds (a friction force f·|R|, a friction moment ρ·|R|).

Solved first as the textbook repeats the construction, each time with the friction of the last one,
which settles geometrically at the friction's gain (the spectral radius of G's Jacobian J).  Where the
gain is near 1 (a rod at 44° to a guide of f = 1 settles by 0.96 a step) or above it (a piston driving
its crank against a guide of f tan β > 1 overshoots by more each time), the friction is instead brought
in from none to all of it: the reactions are linear in the loads, so with a share λ of the friction
G_λ(x) = x₀ + λ·(G(x) − x₀), x₀ the reactions without friction, and Newton's method follows the solution
from λ = 0 to 1.  The position locks itself where that path ends on the way: the driving load grows
without bound as det(I − λJ) reaches 0, and past it no equilibrium joins on to the frictionless one.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

# A solution has settled when no unknown moves by more than this share of the largest.
CONVERGED = 1e-13
# Repetitions of the construction before the friction is brought in by steps.
MAX_ITERATIONS = 200
# The steps of the friction's share, and Newton's steps at each (the Jacobian by forward differences of
# relative size _DIFFERENCE, taken at a share's start, and again where a step does not shrink tenfold: the
# map is linear in the reactions but for their moduli).
SHARE_STEPS = 16
NEWTON_STEPS = 40
_DIFFERENCE = 1e-7
# Newton's method has settled a share that is not the last when its step is this small.
_ON_THE_WAY = 1e-10
# The last share's steps settle within this many machine epsilons times the condition number of I − J.
_ROUNDING_SLACK = 100.0


def settle(repeat: Callable[[np.ndarray], np.ndarray], start: np.ndarray,
           settled: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The fixed point of ``repeat`` joined on to ``start``, the unknowns without friction, row by row (one
    row of unknowns per position).

    ``repeat`` maps every row at once (shape (m, n) to (m, n)); rows already ``settled`` (a singular position's)
    are kept as they are.  Returns the unknowns, the solves each row took, and which rows lock.
    """
    unknowns = np.array(start)
    done = np.zeros(len(unknowns), dtype=bool) if settled is None else settled.copy()
    iterations = np.zeros(len(unknowns), dtype=int)
    # A self-locking position's unknowns grow step by step to inf and NaN: numpy's warnings would be noise.
    with np.errstate(over="ignore", invalid="ignore"):
        for step in range(1, MAX_ITERATIONS + 1):
            again = repeat(unknowns)
            change = _largest(again - unknowns)
            unknowns = np.where(done[:, None], unknowns, again)
            iterations = np.where(done, iterations, step)
            # A position blown up never settles: its change is NaN, or inf against an inf size.
            done |= (change <= CONVERGED * _largest(again)) & np.all(np.isfinite(again), axis=1)
            if done.all():
                return unknowns, iterations, ~done
        rest = ~done
        if not np.iscomplexobj(unknowns):
            found, solves, locked = _by_shares(repeat, np.asarray(start, dtype=float), rest)
        else:
            found, solves, locked = _by_shares(_in_real_parts(repeat), _real_parts(np.asarray(start)), rest)
            found = found.view(complex)
    unknowns[rest] = found[rest]
    return unknowns, iterations + solves, locked


def _by_shares(repeat: Callable[[np.ndarray], np.ndarray], ideal: np.ndarray,
               rows: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Newton's method on x − x₀ − λ·(G(x) − x₀) = 0 at λ = 1/SHARE_STEPS … 1 for the ``rows`` asked for, each
    share from the last one's solution: the solutions, Newton's steps taken, and the rows whose path ended
    (locked)."""
    identity = np.eye(ideal.shape[1])
    unknowns, solves = ideal.copy(), np.zeros(len(ideal), dtype=int)
    going = rows & np.all(np.isfinite(ideal), axis=1)
    for share in np.arange(1, SHARE_STEPS + 1) / SHARE_STEPS:
        if not going.any():
            break
        at = repeat(unknowns)
        slope = identity - share * _jacobian(repeat, unknowns, at)
        # Still on the path that starts at I (λ = 0) where det(I − λJ) has not passed 0.
        going &= np.all(np.isfinite(slope), axis=(1, 2))
        going[going] &= np.linalg.det(slope[going]) > 0
        # Near a lock I − λJ is nearly singular and amplifies the rounding of each solve by its condition
        # number: the last share's steps settle at that, not below.
        floor = np.full(len(unknowns), CONVERGED)
        floor[going] = np.fmax(CONVERGED, _ROUNDING_SLACK * np.finfo(float).eps * np.linalg.cond(slope[going]))
        settled = ~going
        last_step = np.full(len(unknowns), np.inf)
        for _ in range(NEWTON_STEPS):
            active = going & ~settled
            if not active.any():
                break
            residual = unknowns[active] - ideal[active] - share * (at[active] - ideal[active])
            step = np.linalg.solve(slope[active], -residual[..., None])[..., 0]
            unknowns[active] += step
            solves += active
            at = repeat(unknowns)
            # Judged against the loads' own size too: friction may take nearly all of a reaction, whose
            # rounding is still the loads'.
            size = np.fmax(_largest(unknowns[active]), _largest(ideal[active]))
            small = _largest(step) <= (floor[active] if share == 1.0 else _ON_THE_WAY) * size
            settled[active] |= small
            going &= np.all(np.isfinite(unknowns), axis=1)
            # The Jacobian taken at the share's start serves while each step shrinks tenfold; near a lock the
            # solution moves far within a share, and the slope is taken again where it has got to.
            slow = np.zeros(len(unknowns), dtype=bool)
            slow[active] = _largest(step) > 0.1 * last_step[active]
            last_step[active] = _largest(step)
            again = going & ~settled & slow
            if again.any():
                slope[again] = identity - share * _jacobian(repeat, unknowns, at)[again]
        going &= settled
    return unknowns, solves, rows & ~going


def _real_parts(values: np.ndarray) -> np.ndarray:
    """Complex rows as rows of their real and imaginary parts, side by side."""
    return np.ascontiguousarray(values, dtype=complex).view(float).copy()


def _in_real_parts(repeat: Callable[[np.ndarray], np.ndarray]) -> Callable[[np.ndarray], np.ndarray]:
    return lambda real: _real_parts(repeat(np.ascontiguousarray(real).view(complex)))


def _largest(values: np.ndarray) -> np.ndarray:
    """The largest magnitude in each row; fmax skips NaN as nanmax does, and gives NaN for a row of them
    without a warning."""
    return np.fmax.reduce(np.abs(values), axis=1)


def _jacobian(repeat: Callable[[np.ndarray], np.ndarray], unknowns: np.ndarray, at: np.ndarray) -> np.ndarray:
    """dG/dx of every row by forward differences, each column nudged in every row at once."""
    rows, count = unknowns.shape
    nudge = _DIFFERENCE * np.maximum(_largest(unknowns), np.finfo(float).tiny)
    jacobian = np.empty((rows, count, count))
    for column in range(count):
        moved = unknowns.copy()
        moved[:, column] += nudge
        jacobian[:, :, column] = (repeat(moved) - at) / nudge[:, None]
    return jacobian


__all__ = ["CONVERGED", "MAX_ITERATIONS", "NEWTON_STEPS", "SHARE_STEPS", "settle"]
