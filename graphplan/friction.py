"""Friction in kinematic pairs and the efficiency of machines: the textbook cases as formulas.

The friction chapter of a theory-of-machines course, one small function per
formula: the friction angle and circle; a slider on a flat and on an inclined
plane; the V-groove and the cylindrical slider; square and triangular screw
threads; journal and thrust (pivot, collar) bearings; machines in series, in
parallel and mixed.  Dry (Coulomb) friction throughout: the friction force is
``f·N``, against the relative velocity.

Conventions
-----------
SI units: forces in N, lengths in m, moments in N·m.  Every angle is in
radians, in and out (``math.radians`` at the call site).  ``f`` is the
coefficient of sliding friction (-), ``f ≥ 0``; ``φ = atan f`` its angle.

Every function takes numbers or numpy arrays, which broadcast together, and
returns a float for scalar arguments and an array otherwise.  Arguments are
checked: a value outside its range raises :class:`~graphplan.errors.FrictionError`
naming the argument, the offending value and, in an array, its index.

Self-locking
------------
A formula whose value exists is returned as it is, sign included, so that an
array of angles may run across the self-locking boundary:

* the force or torque that keeps the *reverse* motion (lowering, loosening)
  uniform is positive when it holds the load back and negative when it must
  drive the motion: negative means self-locking;
* the efficiency of the reverse motion, driven by the load, is ``≤ 0`` when
  the pair is self-locking: the textbook criterion (the load cannot drive
  the motion however large it is).

The incline and the thread also have a ``*_self_locking`` predicate.  Only
a *driving* quantity that does not exist, because no finite force of the
given kind can drive the asked motion (the slider jams), raises
:class:`~graphplan.errors.SelfLockingError`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal, Union

import numpy as np
from numpy.typing import ArrayLike

from .errors import FrictionError, SelfLockingError
from .kinematics import Scalar

HALF_PI = math.pi / 2

#: Flank half-angle β of the ISO metric thread (60° included angle).
METRIC_FLANK_HALF_ANGLE = math.radians(30)
#: Flank half-angle β of the ISO metric trapezoidal thread (30° included angle).
TRAPEZOIDAL_FLANK_HALF_ANGLE = math.radians(15)

# Reduced coefficient over f for a close-fitting half-cylinder under a radial load Q
# (contact over γ ∈ [−π/2, π/2] from the load's line).  New: uniform pressure p, so
# Q = 2·p·r·l while ΣN = π·p·r·l.  Run in: the wear is the same along the load, so the
# pressure is p0·cos γ, Q = (π/2)·p0·r·l and ΣN = 2·p0·r·l.
_CLOSE_FIT = {"new": math.pi / 2, "run_in": 4 / math.pi}


# --- argument checks -------------------------------------------------------------------------


def _real(argument: str, value: ArrayLike) -> np.ndarray:
    try:
        array = np.asarray(value)
    except (TypeError, ValueError):
        raise FrictionError(argument, "must be a real number or an array of real numbers", value) from None
    # Booleans are rejected: True is a number to numpy but never a coefficient or a length.
    if array.dtype.kind not in "iuf":
        raise FrictionError(argument, "must be a real number or an array of real numbers", value)
    array = array.astype(float)
    _require(argument, array, np.isfinite(array), "must be finite")
    return array


def _require(argument: str, array: np.ndarray, ok: ArrayLike, problem: str,
             error: type[FrictionError] = FrictionError) -> None:
    """Raise ``error`` naming the first element of ``array`` (broadcast with ``ok``) where ``ok`` is false."""
    ok = np.asarray(ok)
    if ok.all():
        return
    ok, array = np.broadcast_arrays(ok, array)
    index = tuple(int(i) for i in np.argwhere(~ok)[0])
    if index:
        problem += f", at index {index[0] if len(index) == 1 else index}"
    raise error(argument, problem, float(array[index]))


def _nonnegative(argument: str, value: ArrayLike, what: str = "") -> np.ndarray:
    array = _real(argument, value)
    _require(argument, array, array >= 0, f"must be ≥ 0{what}")
    return array


def _positive(argument: str, value: ArrayLike) -> np.ndarray:
    array = _real(argument, value)
    _require(argument, array, array > 0, "must be > 0")
    return array


def _coefficient(value: ArrayLike, argument: str = "f") -> np.ndarray:
    return _nonnegative(argument, value, " (a coefficient of friction)")


_INTERVALS = {
    "[0, π/2)": lambda a: (a >= 0) & (a < HALF_PI),
    "(0, π/2)": lambda a: (a > 0) & (a < HALF_PI),
    "(0, π/2]": lambda a: (a > 0) & (a <= HALF_PI),
    "(−π/2, π/2)": lambda a: (a > -HALF_PI) & (a < HALF_PI),
}


def _angle(argument: str, value: ArrayLike, interval: str) -> np.ndarray:
    array = _real(argument, value)
    _require(argument, array, _INTERVALS[interval](array), f"must be in {interval}, an angle in radians")
    return array


def _choice(argument: str, value: object, options: tuple[str, ...]) -> str:
    if not isinstance(value, str) or value not in options:
        raise FrictionError(argument, f"must be one of {', '.join(map(repr, options))}", value)
    return value


def _efficiency(argument: str, value: ArrayLike) -> np.ndarray:
    array = _real(argument, value)
    _require(argument, array, (array >= 0) & (array <= 1), "must be an efficiency in [0, 1]")
    return array


def _out(value: np.ndarray) -> Scalar:
    return float(value) if np.ndim(value) == 0 else value


def _flag(value: np.ndarray) -> bool | np.ndarray:
    return bool(value) if np.ndim(value) == 0 else value


# --- the friction angle and circle -----------------------------------------------------------


def friction_angle(f: ArrayLike) -> Scalar:
    """The friction angle φ = atan f (rad): the greatest tilt of a pair's reaction from its normal.

    ``f`` is the coefficient of sliding friction (-), ``f ≥ 0``.
    """
    return _out(np.arctan(_coefficient(f)))


def friction_circle_radius(f: ArrayLike, radius: ArrayLike) -> Scalar:
    """The radius of the friction circle ρ = f·r (m) of a turning pair.

    The reaction of a turning pair in motion is tangent to this circle, on the
    side that makes its moment oppose the relative rotation.  ``f`` is the
    pair's coefficient (-): the reduced one of :func:`journal_coefficient` for
    a journal; ``r`` is the journal's radius (m).  For a loose journal touching
    along one line, ``f = journal_coefficient(f0, contact="loose")`` gives the
    exact ρ = r·sin φ.
    """
    return _out(_coefficient(f) * _positive("radius", radius))


# --- sliders on planes -----------------------------------------------------------------------


def flat_plane_force(load: ArrayLike, f: ArrayLike, push_angle: ArrayLike) -> Scalar:
    """The force P (N) that slides a block uniformly along a horizontal plane.

    P = f·Q / (cos δ + f·sin δ) = Q·sin φ / cos(δ − φ), from P·cos δ = f·N and
    N = Q − P·sin δ.  ``load`` Q is the block's weight (N); ``push_angle`` δ
    (rad) is the force's angle above the plane, positive for a pull that
    lifts the block, negative for a push that presses it down, in (−π/2, π/2).
    The force is least at δ = φ.

    Raises :class:`SelfLockingError` when δ ≤ φ − π/2: a force pressing that
    steeply adds more friction than it pushes, and no such force moves the block.
    """
    q = _nonnegative("load", load)
    coefficient = _coefficient(f)
    delta = _angle("push_angle", push_angle, "(−π/2, π/2)")
    phi = np.arctan(coefficient)
    _require("push_angle", delta, delta > phi - HALF_PI,
             "no force at this angle moves the block: it presses into the plane at δ ≤ φ − π/2",
             SelfLockingError)
    return _out(q * np.sin(phi) / np.cos(delta - phi))


Motion = Literal["up", "down"]
Force = Literal["horizontal", "parallel"]


def incline_horizontal_force(load: ArrayLike, incline_angle: ArrayLike, f: ArrayLike, *,
                             motion: Motion) -> Scalar:
    """The horizontal force F (N) that keeps a slider moving uniformly up or down an incline.

    F = Q·tan(α + φ) up, F = Q·tan(α − φ) down, with Q the slider's weight
    (N), α the incline's angle (rad) in [0, π/2), φ = atan f.  F is positive
    when it points into the incline (the sense that raises the slider).
    Down, a positive F holds the load back; a negative one (α < φ) must drive
    the slider down: the incline is self-locking.

    Raises :class:`SelfLockingError` up when α + φ ≥ π/2: the horizontal
    force then presses the slider into the incline harder than it pushes it
    along, and no horizontal force raises it.
    """
    q = _nonnegative("load", load)
    alpha = _angle("incline_angle", incline_angle, "[0, π/2)")
    phi = np.arctan(_coefficient(f))
    if _choice("motion", motion, ("up", "down")) == "up":
        _require("incline_angle", alpha, alpha + phi < HALF_PI,
                 "no horizontal force raises the slider: α + φ ≥ π/2, it jams", SelfLockingError)
        return _out(q * np.tan(alpha + phi))
    return _out(q * np.tan(alpha - phi))


def incline_parallel_force(load: ArrayLike, incline_angle: ArrayLike, f: ArrayLike, *,
                           motion: Motion) -> Scalar:
    """The force F (N) along the incline that keeps a slider moving uniformly up or down it.

    F = Q·(sin α + f·cos α) up, F = Q·(sin α − f·cos α) down, with Q the
    slider's weight (N) and α the incline's angle (rad) in [0, π/2).  F is
    positive up the incline.  Down, a positive F holds the load back; a
    negative one (α < φ) must drive the slider down: the incline is self-locking.
    """
    q = _nonnegative("load", load)
    alpha = _angle("incline_angle", incline_angle, "[0, π/2)")
    coefficient = _coefficient(f)
    sense = 1.0 if _choice("motion", motion, ("up", "down")) == "up" else -1.0
    return _out(q * (np.sin(alpha) + sense * coefficient * np.cos(alpha)))


def incline_efficiency(incline_angle: ArrayLike, f: ArrayLike, *, motion: Motion, force: Force) -> Scalar:
    """The efficiency η (-) of raising or lowering a slider on an incline.

    Raising (the driving force does the work, the load's rise is the useful work):

    * horizontal force: η = tan α / tan(α + φ)
    * force along the incline: η = tan α / (tan α + f)

    Lowering (the load drives, the holding force's work is the useful work):

    * horizontal force: η' = tan(α − φ) / tan α
    * force along the incline: η' = 1 − f / tan α

    α is the incline's angle (rad) in (0, π/2), φ = atan f.  η' ≤ 0 (α ≤ φ)
    means self-locking.  Raises :class:`SelfLockingError` for a horizontal
    force raising the slider when α + φ ≥ π/2 (see :func:`incline_horizontal_force`).
    """
    alpha = _angle("incline_angle", incline_angle, "(0, π/2)")
    coefficient = _coefficient(f)
    phi = np.arctan(coefficient)
    up = _choice("motion", motion, ("up", "down")) == "up"
    horizontal = _choice("force", force, ("horizontal", "parallel")) == "horizontal"
    if horizontal and up:
        _require("incline_angle", alpha, alpha + phi < HALF_PI,
                 "no horizontal force raises the slider: α + φ ≥ π/2, it jams", SelfLockingError)
        return _out(np.tan(alpha) / np.tan(alpha + phi))
    if horizontal:
        return _out(np.tan(alpha - phi) / np.tan(alpha))
    if up:
        return _out(np.tan(alpha) / (np.tan(alpha) + coefficient))
    return _out(1 - coefficient / np.tan(alpha))


def incline_self_locking(incline_angle: ArrayLike, f: ArrayLike) -> bool | np.ndarray:
    """Whether a slider stays put on an incline under its own weight: α ≤ φ.

    α is the incline's angle (rad) in [0, π/2), φ = atan f.
    """
    alpha = _angle("incline_angle", incline_angle, "[0, π/2)")
    return _flag(alpha <= np.arctan(_coefficient(f)))


# --- sliders in grooves ----------------------------------------------------------------------


def vee_groove_coefficient(f: ArrayLike, groove_half_angle: ArrayLike) -> Scalar:
    """The reduced (virtual) coefficient f' = f / sin θ (-) of a wedge slider in a V-groove.

    θ (rad), in (0, π/2], is the angle between each flank and the groove's
    plane of symmetry, along which the load Q acts; θ = π/2 is a flat plane.
    The flanks' normal forces add up to Q / sin θ, so the friction force is f'·Q.
    """
    theta = _angle("groove_half_angle", groove_half_angle, "(0, π/2]")
    return _out(_coefficient(f) / np.sin(theta))


CloseFit = Literal["new", "run_in"]


def cylindrical_slider_coefficient(f: ArrayLike, *, contact: CloseFit) -> Scalar:
    """The reduced coefficient f' (-) of a cylindrical slider in a half-cylindrical guide.

    The slider touches the guide over half its circumference; the friction
    force is f'·Q, with Q the load across the guide.

    * ``contact="new"``: uniform pressure, f' = (π/2)·f ≈ 1.57·f;
    * ``contact="run_in"``: pressure p0·cos γ (even wear along the load), f' = (4/π)·f ≈ 1.27·f.

    These are the two ends of the textbook's range f' = (1.27 … 1.57)·f.
    """
    coefficient = _coefficient(f)
    return _out(_CLOSE_FIT[_choice("contact", contact, tuple(_CLOSE_FIT))] * coefficient)


# --- screw threads ---------------------------------------------------------------------------


def thread_lead_angle(lead: ArrayLike, pitch_diameter: ArrayLike) -> Scalar:
    """The thread's lead angle ψ = atan(p_h / (π·d2)) (rad).

    ``lead`` p_h (m) is the axial advance in one turn: the pitch times the
    number of starts; ``pitch_diameter`` d2 (m) is the mean diameter of the thread.
    """
    return _out(np.arctan(_positive("lead", lead) / (math.pi * _positive("pitch_diameter", pitch_diameter))))


def thread_friction_angle(f: ArrayLike, flank_half_angle: ArrayLike = 0.0) -> Scalar:
    """The reduced friction angle φ' = atan(f / cos β) (rad) of a thread.

    β (rad), in [0, π/2), is the flank's angle to the plane normal to the
    axis: 0 for a square (rectangular) thread, :data:`METRIC_FLANK_HALF_ANGLE`
    (30°) for a metric one, :data:`TRAPEZOIDAL_FLANK_HALF_ANGLE` (15°) for a
    trapezoidal one.  The inclined flank takes a normal force 1/cos β times
    the axial load's.
    """
    beta = _angle("flank_half_angle", flank_half_angle, "[0, π/2)")
    return _out(np.arctan(_coefficient(f) / np.cos(beta)))


Turning = Literal["tighten", "loosen"]


def thread_torque(load: ArrayLike, pitch_diameter: ArrayLike, lead_angle: ArrayLike, f: ArrayLike, *,
                  motion: Turning, flank_half_angle: ArrayLike = 0.0) -> Scalar:
    """The torque T (N·m) in the thread that turns a nut uniformly against or with its axial load.

    T = Q·(d2/2)·tan(ψ + φ') tightening (raising a screw jack's load),
    T = Q·(d2/2)·tan(ψ − φ') loosening (lowering it): the square thread is an
    incline of angle ψ unwound from the pitch cylinder, pushed by a
    horizontal force at radius d2/2.  Q is the axial load (N), d2 the pitch
    diameter (m), ψ the lead angle (rad, :func:`thread_lead_angle`) in
    (0, π/2), φ' the reduced friction angle (:func:`thread_friction_angle`).

    Loosening, a positive T holds the load back; a negative one (ψ < φ')
    must drive the nut: the thread is self-locking.  The friction of a nut's
    or a collar's bearing face comes on top: :func:`pivot_friction_moment`.

    Raises :class:`SelfLockingError` tightening when ψ + φ' ≥ π/2.
    """
    q = _nonnegative("load", load)
    radius = _positive("pitch_diameter", pitch_diameter) / 2
    psi = _angle("lead_angle", lead_angle, "(0, π/2)")
    phi = np.asarray(thread_friction_angle(f, flank_half_angle))
    if _choice("motion", motion, ("tighten", "loosen")) == "tighten":
        _require("lead_angle", psi, psi + phi < HALF_PI,
                 "no torque tightens the thread: ψ + φ' ≥ π/2, it jams", SelfLockingError)
        return _out(q * radius * np.tan(psi + phi))
    return _out(q * radius * np.tan(psi - phi))


def thread_efficiency(lead_angle: ArrayLike, f: ArrayLike, *, motion: Turning,
                      flank_half_angle: ArrayLike = 0.0) -> Scalar:
    """The efficiency (-) of a screw pair, thread friction only.

    Tightening (the torque drives, raising the load is the useful work):
    η = tan ψ / tan(ψ + φ').  Loosening (the axial load drives the nut round):
    η' = tan(ψ − φ') / tan ψ, ≤ 0 when the thread is self-locking (ψ ≤ φ').
    ψ is the lead angle (rad) in (0, π/2), φ' the reduced friction angle of
    :func:`thread_friction_angle`.

    Raises :class:`SelfLockingError` tightening when ψ + φ' ≥ π/2.
    """
    psi = _angle("lead_angle", lead_angle, "(0, π/2)")
    phi = np.asarray(thread_friction_angle(f, flank_half_angle))
    if _choice("motion", motion, ("tighten", "loosen")) == "tighten":
        _require("lead_angle", psi, psi + phi < HALF_PI,
                 "no torque tightens the thread: ψ + φ' ≥ π/2, it jams", SelfLockingError)
        return _out(np.tan(psi) / np.tan(psi + phi))
    return _out(np.tan(psi - phi) / np.tan(psi))


def thread_self_locking(lead_angle: ArrayLike, f: ArrayLike,
                        flank_half_angle: ArrayLike = 0.0) -> bool | np.ndarray:
    """Whether the axial load cannot turn the screw pair by itself: ψ ≤ φ'.

    ψ is the lead angle (rad) in (0, π/2), φ' = atan(f / cos β) the reduced friction angle.
    """
    psi = _angle("lead_angle", lead_angle, "(0, π/2)")
    return _flag(psi <= np.asarray(thread_friction_angle(f, flank_half_angle)))


# --- bearings --------------------------------------------------------------------------------

JournalContact = Literal["loose", "new", "run_in"]


def journal_coefficient(f: ArrayLike, *, contact: JournalContact) -> Scalar:
    """The reduced coefficient f' (-) of a journal (radial) bearing: M = f'·Q·r.

    * ``contact="loose"``: a journal with clearance touches along one line,
      which climbs until the reaction leans by φ: f' = sin φ = f / √(1 + f²) ≈ f;
    * ``contact="new"``: a close fit over half the journal, unworn, uniform
      pressure: f' = (π/2)·f ≈ 1.57·f;
    * ``contact="run_in"``: the same after running in, pressure p0·cos γ:
      f' = (4/π)·f ≈ 1.27·f.
    """
    coefficient = _coefficient(f)
    if _choice("contact", contact, ("loose", *_CLOSE_FIT)) == "loose":
        return _out(coefficient / np.sqrt(1 + coefficient**2))
    return _out(_CLOSE_FIT[contact] * coefficient)


def journal_friction_moment(load: ArrayLike, radius: ArrayLike, f: ArrayLike, *,
                            contact: JournalContact) -> Scalar:
    """The friction moment M = f'·Q·r (N·m) of a journal bearing.

    Q is the radial load (N), r the journal's radius (m), f' the reduced
    coefficient of :func:`journal_coefficient` for the ``contact``.  The
    reaction is tangent to the friction circle of radius f'·r.
    """
    q = _nonnegative("load", load)
    r = _positive("radius", radius)
    return _out(np.asarray(journal_coefficient(f, contact=contact)) * q * r)


def pivot_friction_moment(load: ArrayLike, f: ArrayLike, outer_radius: ArrayLike,
                          inner_radius: ArrayLike = 0.0, *, contact: CloseFit) -> Scalar:
    """The friction moment M (N·m) of a flat thrust bearing: a pivot, a collar, a nut's face.

    The axial load Q (N) presses a ring of radii r ≤ ρ ≤ R (m) (r = 0: a solid pivot):

    * ``contact="new"``: uniform pressure, M = (2/3)·f·Q·(R³ − r³)/(R² − r²),
      = (2/3)·f·Q·R for a solid pivot;
    * ``contact="run_in"``: even wear, p·ρ = const, M = (1/2)·f·Q·(R + r),
      = (1/2)·f·Q·R for a solid pivot.
    """
    q = _nonnegative("load", load)
    coefficient = _coefficient(f)
    outer = _positive("outer_radius", outer_radius)
    inner = _nonnegative("inner_radius", inner_radius)
    _require("inner_radius", inner, inner < outer, "must be < outer_radius")
    # The coefficient multiplies last: the moment then keeps its order between the two contacts for any f,
    # a tiny one too, where a product of it and 2/3 would round to zero first.
    if _choice("contact", contact, tuple(_CLOSE_FIT)) == "new":
        return _out(coefficient * (2 / 3 * q * (outer**3 - inner**3) / (outer**2 - inner**2)))
    return _out(coefficient * (q * (outer + inner) / 2))


def cone_friction_moment(load: ArrayLike, f: ArrayLike, outer_radius: ArrayLike, inner_radius: ArrayLike,
                         semi_angle: ArrayLike, *, contact: CloseFit) -> Scalar:
    """The friction moment M (N·m) of a conical face: a cone clutch, a conical pivot.

    The axial load W (N) presses a cone of semi-angle α (rad, 0 < α ≤ π/2) over
    the radii r ≤ ρ ≤ R (m).  The normal pressure on the face carries W through
    its axial share sin α, so every formula of :func:`pivot_friction_moment`
    gains cosec α (α = π/2 is the flat collar itself):

    * ``contact="new"``: uniform pressure, M = (2/3)·f·W·(R³ − r³)/(R² − r²)·cosec α;
    * ``contact="run_in"``: even wear, M = f·W·(R + r)/2·cosec α = f·W·Rm·cosec α.
    """
    alpha = _angle("semi_angle", semi_angle, "(0, π/2]")
    flat = pivot_friction_moment(load, f, outer_radius, inner_radius, contact=contact)
    return _out(np.asarray(flat) / np.sin(alpha))


# --- efficiency of machines ------------------------------------------------------------------


def series_efficiency(efficiencies: Sequence[ArrayLike]) -> Scalar:
    """η = η1·η2·…·ηk (-): machines in series, each driving the next with its whole output."""
    if len(efficiencies) == 0:
        raise FrictionError("efficiencies", "must hold at least one efficiency", efficiencies)
    stages = [_efficiency(f"efficiencies[{i}]", eta) for i, eta in enumerate(efficiencies)]
    return _out(np.prod(np.broadcast_arrays(*stages), axis=0))


def parallel_efficiency(efficiencies: Sequence[ArrayLike], input_powers: Sequence[ArrayLike]) -> Scalar:
    """η = Σ ηi·Pi / Σ Pi (-): machines in parallel sharing one input power.

    ``input_powers`` Pi (W) are the powers the branches take in: absolute, or
    any numbers in their proportion (the shares); Pi ≥ 0, Σ Pi > 0.
    """
    if len(efficiencies) == 0:
        raise FrictionError("efficiencies", "must hold at least one efficiency", efficiencies)
    if len(efficiencies) != len(input_powers):
        raise FrictionError("input_powers", f"must hold one power per efficiency ({len(efficiencies)})",
                            input_powers)
    etas = [_efficiency(f"efficiencies[{i}]", eta) for i, eta in enumerate(efficiencies)]
    powers = [_nonnegative(f"input_powers[{i}]", p) for i, p in enumerate(input_powers)]
    total = np.sum(np.broadcast_arrays(*powers), axis=0)
    _require("input_powers", total, total > 0, "must not all be 0")
    return _out(sum(eta * p for eta, p in zip(etas, powers)) / total)


def loss_coefficient(efficiency: ArrayLike) -> Scalar:
    """The loss coefficient ψ = 1 − η (-): the fraction of the input power lost.

    η ≤ 1; the reverse efficiency η' ≤ 0 of a self-locking pair gives ψ ≥ 1.
    """
    eta = _real("efficiency", efficiency)
    _require("efficiency", eta, eta <= 1, "must be ≤ 1")
    return _out(1 - eta)


Stage = Union[float, "Series", "Parallel"]


def _stage(argument: str, stage: object) -> Series | Parallel | Scalar:
    return stage if isinstance(stage, (Series, Parallel)) else _out(_efficiency(argument, stage))


def _stage_efficiency(stage: Series | Parallel | Scalar) -> Scalar:
    return stage.efficiency if isinstance(stage, (Series, Parallel)) else stage


def _share(argument: str, share: object) -> float:
    array = _nonnegative(argument, share)
    if array.ndim != 0:
        raise FrictionError(argument, "must be one number", share)
    return float(array)


@dataclass(frozen=True)
class Series:
    """Stages one after another, each taking the whole output of the one before.

    A stage is an efficiency (-) or a :class:`Series` or :class:`Parallel`;
    ``Series([0.95, Parallel([0.9, Series([0.8, 0.9])], shares=[0.6, 0.4])])``
    is a motor and gearbox driving two branches.
    """

    stages: Sequence[Stage]

    def __post_init__(self) -> None:
        if len(self.stages) == 0:
            raise FrictionError("stages", "must hold at least one stage", self.stages)
        object.__setattr__(self, "stages",
                           tuple(_stage(f"stages[{i}]", stage) for i, stage in enumerate(self.stages)))

    @property
    def efficiency(self) -> Scalar:
        """η = Π ηi over the stages."""
        return series_efficiency([_stage_efficiency(stage) for stage in self.stages])


@dataclass(frozen=True)
class Parallel:
    """Branches that share one input power: branch i takes the fraction shares[i] / Σ shares.

    A branch is an efficiency (-) or a :class:`Series` or :class:`Parallel`;
    the shares are input powers (W) or numbers in their proportion.
    """

    branches: Sequence[Stage]
    shares: Sequence[float]

    def __post_init__(self) -> None:
        if len(self.branches) == 0 or len(self.branches) != len(self.shares):
            raise FrictionError("shares", f"must hold one share per branch ({len(self.branches)})",
                                self.shares)
        object.__setattr__(self, "branches",
                           tuple(_stage(f"branches[{i}]", branch) for i, branch in enumerate(self.branches)))
        shares = tuple(_share(f"shares[{i}]", share) for i, share in enumerate(self.shares))
        if sum(shares) == 0:
            raise FrictionError("shares", "must not all be 0", self.shares)
        object.__setattr__(self, "shares", shares)

    @property
    def efficiency(self) -> Scalar:
        """η = Σ ηi·si / Σ si over the branches, si their shares of the input power."""
        return parallel_efficiency([_stage_efficiency(branch) for branch in self.branches], self.shares)
