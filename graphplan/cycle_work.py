"""The efficiency over the cycle: the works of the balancing load over a crank's turn without and with friction.

Over a whole cycle the inertia loads and the weights do no work, so the driver's work without friction,
``A0 = ∫Mb0 dφ``, is the work of the useful resistances (less that of any driving loads), and with the pairs'
friction it is ``A = ∫Mb dφ``; the efficiency over the cycle is ``η = A0/A = Aпс/Aдв``.  Where the loads drive
the driver over the cycle (``A0 < 0``) it is ``A/A0``, as the instantaneous η is (:func:`statics.efficiency`).

The balancing load jumps wherever a load's window opens or closes, a resisting load's motion turns back, or a
pair's relative motion turns back (its friction turns round, and the other pairs' reactions with it), and its
slope jumps there.  Summed over even steps across them the works were off in the fourth digit at 1° (η 0.92459
for 0.92478 of a press), so each such place is found by bisection and put into the sweep once on each side,
and Simpson's rule integrates the smooth pieces between them.  Where the friction locks the mechanism anywhere on the
cycle, it does not run through a cycle, and there is no efficiency over it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .joint_friction import FrictionPair, turning_sense
from .loads import (
    SWITCH_TOLERANCE,
    activity_at,
    link_loads,
    motion_state,
    resisted_sense,
    sense_of_motion,
    with_switches,
)
from .mechanism import Mechanism
from .motion import Motion, solve
from .positions import PositionSet
from .statics import efficiency, equilibrium

# Steps of the driver's turn summed over, besides the places where the balancing load jumps.
CYCLE_SAMPLES = 360
# The driver's work without friction is none (no useful resistance, only inertia and weights) where it is this
# share of ∫|Mb0| dφ: Simpson's rule over pieces cut at the switches leaves about 1e-9 of a zero at 1°.
_ROUNDING_OF_ZERO = 1e-6


@dataclass(frozen=True)
class CycleWork:
    """The driver's works over one turn of the crank (J): ``without_friction`` A0 = ∫Mb0 dφ, ``with_friction``
    A = ∫Mb dφ, and ``efficiency`` η over the cycle.

    ``locked``: the friction locks the mechanism somewhere on the cycle; it runs through no cycle, so
    ``with_friction`` and ``efficiency`` are NaN.  ``efficiency`` is NaN too where the friction takes more than
    the loads put in over a cycle they drive (η ≤ 0).  ``samples`` counts the driver positions summed over.
    """

    without_friction: float
    with_friction: float
    efficiency: float
    locked: bool
    loads_drive: bool
    samples: int

    @property
    def friction(self) -> float:
        """Aтр = A − A0: the work the friction takes over the cycle."""
        return self.with_friction - self.without_friction


def cycle_work(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...], *,
               locked_elsewhere: bool = False, count: int = CYCLE_SAMPLES) -> CycleWork | None:
    """The works over the crank's turn from the first position, and η over the cycle; None for a driver that
    does not turn round, without friction, or where the turn passes a singular position (no work is a number
    there).  ``locked_elsewhere``: the analysis found the mechanism locked at a position or between two."""
    driver = mechanism.driver
    if not driver.cyclic or not friction:
        return None
    from scipy.integrate import trapezoid  # imported here: a third of a cold run, and only friction needs it

    even = positions.values[0] + driver.sense * np.linspace(0.0, 2.0 * math.pi, count + 1)
    sweep = with_switches(even, lambda values: _state(mechanism, positions, friction, values))
    motion = solve(mechanism, sweep, positions.reference, tolerant=True)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        loads = link_loads(mechanism, motion_state(motion), activity_at(mechanism, positions, sweep, tolerant=True))
        ideal = equilibrium(mechanism, motion, loads)
        rubbing = equilibrium(mechanism, motion, loads, friction)
    if ideal.singular.any() or not np.isfinite(ideal.balancing).all():
        return None
    without = _integral(ideal.balancing, sweep)
    if abs(without) <= _ROUNDING_OF_ZERO * float(trapezoid(np.abs(ideal.balancing), np.abs(sweep - sweep[0]))):
        without = 0.0
    locked = locked_elsewhere or bool(rubbing.locked.any())
    turn = float(sweep[-1] - sweep[0])   # ±2π: the works as mean balancing moments, signed as the driver turns
    loads_drive = without < 0   # summed along the motion, a work is the driver's whichever way it turns
    if locked:
        return CycleWork(without, math.nan, math.nan, True, loads_drive, len(sweep))
    work = _integral(rubbing.balancing, sweep)
    eta = float(efficiency(mechanism, without / turn, work / turn))
    return CycleWork(without, work, eta, False, loads_drive, len(sweep))


def _integral(values: np.ndarray, sweep: np.ndarray) -> float:
    """∫ values d(sweep): Simpson's rule over each smooth piece, the slivers a switch's two sides leave between
    the pieces by the trapezoid (they hold no work to speak of, but a jump's two values)."""
    from scipy.integrate import simpson, trapezoid

    step = float(np.max(np.abs(np.diff(sweep))))
    cuts = np.flatnonzero(np.abs(np.diff(sweep)) <= 2.0 * SWITCH_TOLERANCE * step) + 1
    pieces = np.split(np.arange(len(sweep)), cuts)
    total = sum(float(simpson(values[piece], x=sweep[piece])) for piece in pieces if len(piece) > 1)
    return total + sum(float(trapezoid(values[cut - 1:cut + 1], sweep[cut - 1:cut + 1])) for cut in cuts)


def _state(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
           values: np.ndarray) -> np.ndarray:
    """At each driver coordinate: which loads act, the sense each resisting load opposes and the sense each pair
    with friction rubs in (a row each)."""
    motion = solve(mechanism, values, positions.reference, tolerant=True)
    with np.errstate(invalid="ignore"):
        return np.vstack([activity_at(mechanism, positions, values, tolerant=True) > 0,
                          *_resisted(mechanism, motion), *_senses(friction, motion)])


def _resisted(mechanism: Mechanism, motion: Motion) -> list[np.ndarray]:
    """The sense of the motion each resisting load opposes, as :func:`loads.link_loads` turns it against it."""
    state = motion_state(motion)
    return [np.broadcast_to(resisted_sense(load, state), (motion.count,))
            for load in mechanism.scene.loads if load.resisting]


def _senses(friction: tuple[FrictionPair, ...], motion: Motion) -> list[np.ndarray]:
    """The sense of each pair's relative motion, as :func:`joint_friction.friction_loads` rubs against it."""
    state = motion_state(motion)
    slides = {slide.slider: slide for slide in motion.slides}
    senses = []
    for pair in friction:
        if pair.sliding:
            slide = slides[pair.target]
            senses.append(sense_of_motion(slide.velocity, slide.acceleration, state.moving_scale))
        else:
            senses.append(turning_sense(pair, state))
    return [np.broadcast_to(sense, (motion.count,)) for sense in senses]


__all__ = ["CYCLE_SAMPLES", "CycleWork", "cycle_work"]
