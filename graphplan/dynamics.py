"""The equivalent (dynamic) model of a machine: every mass and every load reduced to the driver.

The driver becomes an *equivalent link* whose kinetic energy and power are those of the whole
mechanism.  For a crank turning at ω1 (a turning equivalent link):

    Je(φ) = Σ [m·(vS/ω1)² + JS·(ω/ω1)²]          reduced moment of inertia, kg·m²
    Me(φ) = Σ [F·v + M·ω] / ω1                  reduced moment of the loads, N·m

over the moving links (the crank's own m·(vS/ω1)² + JS is its moment of inertia about its pivot)
and over the external loads and the weights (never the inertia loads: their power is the change
of the kinetic energy itself).  The ratios vS/ω1, ω/ω1 depend on the position alone, so the model
holds at any speed.  Differentiating Je along the motion at ε1 = 0 (vS = r′·ω1, aS = r″·ω1²):

    dJe/dφ = 2 Σ [m·vS·aS + JS·ω·ε] / ω1³

A slider driver moving at v1 becomes a translating equivalent link: the reduced mass
me = Σ [m·(vS/v1)² + JS·(ω/v1)²] (kg) and the reduced force Fe = Σ [F·v + M·ω] / v1 (N).

Signs.  The model runs along the driver's *travel*: ψ, the angle (or distance) the driver has
moved from the first position in its own sense, so that ``dψ/dt = |ω1|``.  A reduced moment is
positive when it drives the motion on (``Me·|ω1|`` is the power the loads put in), so the works
read as the textbook draws them: ``Ad = ∫Md dψ`` and ``Ar = −∫Mr dψ``, both positive, and the
kinetic energy changes by ``ΔT = Ad − Ar``.

Driving and resisting.  A scene load is sorted by its work over the run (the crank's cycle, the
swing or the travel), ``∫Me dψ`` of the load alone.  A load marked ``resisting = true`` is a
resistance.  The other loads drive where their work is positive, and are counted with the
resistances, as the weights are, where it is zero (within :data:`NO_WORK` of the work they give and
take) or negative: a payload given as a force of fixed direction that a cylinder lifts, a force that
opposes a swing all over it.  Such loads along one line at one point (moments on one link) are one
force given over several strokes, and are sorted as one: an engine's gas force, given as one load a
stroke, takes work on compression but gives more on expansion, and drives; a compressor's takes
work over the cycle, and resists.  Unless the scene gives both sides, one side is taken constant so
that the work over the run balances, as the textbook takes the motor's moment constant: the
driving moment (a cylinder's push) when no load drives, the resisting moment when no load is
marked resisting (the weights, and the loads counted with them, kept).

The reduction is also made from the velocity plans of the plan positions and of the positions of
``positions.velocity_plans`` (ratios read off the plans), so that the two can be compared
(:class:`PlanReduction`).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from types import MappingProxyType
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike
from scipy.integrate import cumulative_simpson, cumulative_trapezoid, trapezoid

from .kinematics import dot, norm2, read_only
from .loads import (
    State,
    activity,
    activity_at,
    link_loads,
    load_corners_at,
    motion_state,
    plan_state,
    power,
    with_switches,
)
from .mechanism import Mechanism, build
from .memo import OwnedMemo
from .motion import Motion, solve
from .positions import PositionSet, make_positions
from .scene import Scene

if TYPE_CHECKING:
    from .analysis import Analysis

#: Samples of the driver's cycle (or travel) in the dense sweep of :func:`equivalent_model_of`.
DEFAULT_COUNT = 360
#: Which reduced moment is taken constant so that the work over the cycle balances.
CONSTANT_CHOICES = ("auto", "driving", "resisting", "none")


@dataclass(frozen=True)
class PlanReduction:
    """The reduction at one plan position: read off its velocity plan, and from the analytic motion.

    ``inertia`` and ``moment`` are from the plans (ratios ``ps·μV/ω1`` of the plan);
    ``inertia_exact`` and ``moment_exact`` from the analytic solution at the same position.
    """

    number: int
    index: int
    driver: float
    inertia: float
    moment: float
    inertia_exact: float
    moment_exact: float

    @property
    def inertia_error_percent(self) -> float:
        return _percent(self.inertia, self.inertia_exact)

    @property
    def moment_error_percent(self) -> float:
        return _percent(self.moment, self.moment_exact)


def _percent(value: float, exact: float) -> float:
    """The error of ``value`` in percent of ``exact``; a plan that reads a nonzero value where it is zero: inf."""
    if value == exact:
        return 0.0
    return 100.0 * (value - exact) / abs(exact) if exact else math.inf


class ConstantSideError(ValueError):
    """``constant`` asks a side to be taken constant that the scene gives loads on.

    ``constant``, the side asked for; ``loads``, the key paths of the scene's loads on it; ``ways_out``, the choices
    that keep the scene's loads as they are (``"none"``, and the other side where the scene gives no loads on it);
    ``noun``, what a side is: a crank's ``"moment"``, a slider driver's ``"force"``.
    """

    def __init__(self, constant: str, loads: tuple[str, ...], ways_out: tuple[str, ...], noun: str) -> None:
        self.constant, self.loads, self.ways_out, self.noun = constant, loads, ways_out, noun
        super().__init__(f"constant={constant!r} replaces the {constant} {noun}, but the scene gives {constant} loads "
                         f"({', '.join(loads)}); take " + " or ".join(f"constant={way!r}" for way in ways_out))


@dataclass(frozen=True)
class MovedLoad:
    """A load the scene gives as driving (``resisting = false``) that gives no work over the run, counted with the
    resistances: ``loads``, its key paths (a force given over several strokes, or a window each, along one line at
    one point, is their sum, and is sorted as one), and ``work``, its work over the run (J), zero or negative (a
    spring's, which goes with the weights whatever its work, of either sign)."""

    loads: tuple[str, ...]
    work: float


@dataclass(frozen=True)
class EquivalentModel:
    """The equivalent link of a machine over its cycle (a crank) or its travel (a slider driver).

    Attributes
    ----------
    kind
        ``"crank"``: a turning equivalent link (Je in kg·m², moments in N·m, ψ in rad);
        ``"slider"``: a translating one (me in kg, forces in N, ψ in m).
    link
        The driver's link number; 0 for a model made from load diagrams alone (:func:`diagram_model`).
    speed
        |ω1| (rad/s) or |v1| (m/s): the speed the analysis ran at; the ratios do not depend on it.
    sense
        +1 when the driver's coordinate grows as it moves (ccw crank, slider along +u), else −1.
    driver
        The driver's coordinate at each sample: crank angle φ (rad) or displacement s (m).
    coordinate
        ψ: the driver's travel from the first sample, in its own sense (0 … 2π for a crank).
    inertia, inertia_slope
        Je and dJe/dψ at each sample (kg·m² and kg·m²/rad, or kg and kg/m).
    link_inertia
        Each moving link's share of Je.
    driving, resisting
        The reduced moments of the driving loads and of the resistances with the weights,
        positive when they drive the motion on (so ``resisting`` is mostly ≤ 0).
    constant
        ``"driving"`` or ``"resisting"``: the side taken constant to balance the work over the
        cycle; ``"none"`` when both are as the scene gives them.
    breaks
        The samples (indices) where the moments may have a corner or a jump: the run's ends and the two sides of
        each place where a load switches or its diagram turns a corner, put in a hair apart (a linkage's: the pairs
        closer than :data:`_PAIR` of the run).  The works are integrated by Simpson's rule over each stretch
        between two, where the moments are smooth; a model from load diagrams gives every sample (its moments are
        straight between its vertices, where the trapezoidal rule is exact).
    plans
        The reduction read off the velocity plans of the plan positions.
    cyclic
        True when the samples close a cycle (a crank turning round, a load diagram's turn); False
        when they run once over a rocking crank's swing or a slider's travel.
    driving_loads, resisting_loads
        The scene's loads on each side by their key paths (``loads[1]``), sorted by their work over the run (see
        the module's notes), for the advice where the work does not balance.
    moved
        The loads the scene gives as driving (``resisting = false``) that are counted with the resistances, as
        :class:`MovedLoad`: each with its work over the run, zero or negative.
    """

    kind: str
    link: int
    speed: float
    sense: float
    driver: np.ndarray
    coordinate: np.ndarray
    inertia: np.ndarray
    inertia_slope: np.ndarray
    link_inertia: Mapping[int, np.ndarray]
    driving: np.ndarray
    resisting: np.ndarray
    constant: str
    breaks: np.ndarray
    plans: tuple[PlanReduction, ...] = ()
    cyclic: bool = True
    driving_loads: tuple[str, ...] = ()
    resisting_loads: tuple[str, ...] = ()
    moved: tuple[MovedLoad, ...] = ()

    def __post_init__(self) -> None:
        # Handed out as they are (scene.machine_dynamics().model.inertia): Je made its fluctuation in place
        # (je -= je.mean()) changed the flywheel and the motion worked out from the model after.
        for name in ("driver", "coordinate", "inertia", "inertia_slope", "driving", "resisting", "breaks"):
            read_only(getattr(self, name))
        for share in self.link_inertia.values():
            read_only(share)

    def __repr__(self) -> str:
        # The dataclass's own repr printed every array: 28 000 characters on a notebook's line.
        unit = "kg·m²" if self.turning else "kg"
        link = f"link {self.link}" if self.link else "the load diagrams"
        return (f"<EquivalentModel of {link} ({self.kind}): Je {float(np.min(self.inertia)):.4g} … "
                f"{float(np.max(self.inertia)):.4g} {unit}, {len(self.driver)} samples>")

    @property
    def turning(self) -> bool:
        return self.kind == "crank"

    @property
    def moment(self) -> np.ndarray:
        """Me = Md + Mr: the reduced moment of every load but the inertia loads."""
        return self.driving + self.resisting

    def mean_over_run(self, values: np.ndarray) -> float:
        """The mean of ``values`` over the run, ∫ dψ / ψ: a plain mean of the samples would count twice each
        point sampled on both sides of a jump of the loads."""
        span = float(self.coordinate[-1] - self.coordinate[0])
        return float(self.integral(values)[-1]) / span if span else float(np.mean(values))

    def integral(self, values: np.ndarray) -> np.ndarray:
        """∫ values dψ from the first sample to each: Simpson's rule on each smooth stretch between
        :attr:`breaks`."""
        return _integral(values, self.coordinate, self.breaks)

    @cached_property
    def work_uncertainty(self) -> float:
        """How far the integrated work over the run may be off (J): the trapezoidal rule's total of the net moment
        less Simpson's.  The trapezoid's error is of the step squared, Simpson's of its fourth power on a smooth
        stretch, so their difference is the trapezoid's error, and more than Simpson's; where a corner falls
        between two samples unseen, both are off by as much, and the difference says so."""
        trapezoid_total = float(trapezoid(self.moment, self.coordinate)) if self.moment.size > 1 else 0.0
        return abs(trapezoid_total - float(self.integral(self.moment)[-1]))

    @property
    def inertia_is_constant(self) -> bool:
        """Je the same all the cycle (a flywheel sized from load diagrams alone): the energy–mass diagram is then a
        vertical segment, and the flywheel's three methods agree."""
        return float(np.ptp(self.inertia)) <= 1e-12 * float(np.max(np.abs(self.inertia), initial=0.0))

    @property
    def inertia_is_nought(self) -> bool:
        """Je nought all the cycle: the machine's own reduced moment of inertia taken as zero (the flywheel starter's
        press), which the note and the drawing leave out of JF and of the equation of motion rather than write
        "− 0" and "Je = 0 kg·m² is the machine's inertia"."""
        return not np.any(self.inertia)

    @property
    def mean_inertia(self) -> float:
        """Je,mean: Je averaged over the run."""
        return self.mean_over_run(self.inertia)

    @cached_property
    def driving_work(self) -> np.ndarray:
        """Ad(ψ) = ∫ Md dψ from the first sample (J)."""
        return read_only(self.integral(self.driving))

    @cached_property
    def resisting_work(self) -> np.ndarray:
        """Ar(ψ) = −∫ Mr dψ from the first sample (J): positive when the resistances take work."""
        return read_only(-self.integral(self.resisting))

    @property
    def energy(self) -> np.ndarray:
        """ΔT(ψ) = Ad − Ar: the change of the kinetic energy from the first sample (J)."""
        return self.driving_work - self.resisting_work

    @property
    def imbalance(self) -> float:
        """ΔT at the last sample: the work left over by a cycle (zero when the cycle balances)."""
        return float(self.energy[-1])

    def kinetic_energy(self, speed: float | None = None) -> np.ndarray:
        """½·Je·ω1² (or ½·me·v1²) at the driver's ``speed`` (default: the analysis speed) (J)."""
        speed = self.speed if speed is None else speed
        return 0.5 * self.inertia * speed * speed


def equivalent_model(mechanism: Mechanism, motion: Motion, acting: np.ndarray | None = None, *,
                     constant: str = "auto", plans: Sequence[PlanReduction] = ()) -> EquivalentModel:
    """The equivalent model over the positions of ``motion`` (a cycle, or a slider's travel).

    Parameters
    ----------
    mechanism, motion
        The mechanism and its analytic motion over the samples, in the order the driver moves.
    acting
        :func:`graphplan.loads.activity` of the scene's loads at the samples; None lets every load act.
    constant
        Which reduced moment is taken constant so that the work over the samples balances:
        ``"auto"`` (the driving one when no load drives, the loads sorted by their work over the run as the
        module's notes say, else the resisting one when none is marked resisting, else none), ``"driving"``,
        ``"resisting"`` or ``"none"``.
    plans
        Reductions of the plan positions to keep with the model (:func:`plan_reductions`).
    """
    if constant not in CONSTANT_CHOICES:
        raise ValueError(f"constant must be one of {', '.join(CONSTANT_CHOICES)}, not {constant!r}")
    driver = mechanism.driver
    count = motion.count
    if count < 2:
        raise ValueError("an equivalent model needs at least two positions of the driver")
    velocity, rate = driver.coordinate_speed, driver.coordinate_acceleration
    speed, sense = abs(velocity), math.copysign(1.0, velocity)
    values = np.asarray(motion.driver, dtype=float)
    coordinate = sense * (values - values[0])
    if np.any(np.diff(coordinate) < 0):
        raise ValueError("the positions must follow the driver's motion: its travel may not go back")

    state = motion_state(motion)
    shares = _link_inertia(mechanism, state, velocity, count)
    inertia = sum(shares.values(), np.zeros(count))
    # dJe/dt = 2Σ[m vS·aS + JS ω ε]/v1² at a steady driver; the driver's own rate is taken out of
    # the accelerations first (aS = r″·v1² + r′·a1), so that a scene's ε1 ≠ 0 does not enter.
    slope = np.zeros(count)
    for number, spec in _massive(mechanism):
        if spec.mass > 0:
            point = motion.points[spec.centre]
            steady = point.a - rate * point.v / velocity
            slope = slope + spec.mass * _full(dot(point.v, steady), count)
        if spec.inertia > 0:
            link = motion.links[number]
            steady_epsilon = link.epsilon - rate * link.omega / velocity
            slope = slope + spec.inertia * _full(link.omega * steady_epsilon, count)
    slope = 2.0 * slope / (velocity * velocity * speed)

    weights, load_powers = _powers(mechanism, state, acting, count)
    loads = mechanism.scene.loads
    breaks = _breaks_of(coordinate)
    drives, moved = _sides(loads, [share / speed for share in load_powers], coordinate, breaks)
    driving = sum((share for share, on in zip(load_powers, drives, strict=True) if on), np.zeros(count)) / speed
    resisting = sum((share for share, on in zip(load_powers, drives, strict=True) if not on), weights) / speed
    driving_loads = tuple(load.where for load, on in zip(loads, drives, strict=True) if on)
    resisting_loads = tuple(load.where for load, on in zip(loads, drives, strict=True) if not on)
    driving, resisting, chosen = _balanced(coordinate, driving, resisting, constant, driving_loads,
                                           tuple(load.where for load in loads if load.resisting), breaks,
                                           "moment" if driver.kind == "crank" else "force")
    return EquivalentModel(kind=driver.kind, link=driver.link, speed=speed, sense=sense, driver=values,
                           coordinate=coordinate, inertia=inertia, inertia_slope=slope,
                           link_inertia=MappingProxyType(shares), driving=driving, resisting=resisting,
                           constant=chosen, plans=tuple(plans), cyclic=driver.cyclic,
                           driving_loads=driving_loads, resisting_loads=resisting_loads, moved=moved,
                           breaks=breaks)


def equivalent_model_of(source: Analysis | Scene, count: int = DEFAULT_COUNT, *,
                        constant: str = "auto") -> EquivalentModel:
    """The equivalent model of a scene (or of an analysis) over ``count`` steps of the driver.

    A crank's cycle starts at the first analysed position and is sampled at ``count + 1``
    equally spaced angles (the last one closes the cycle); a slider's travel likewise.  Where a
    load's window opens or closes between two samples, the angle is found by bisection and put
    in, once on each side, so that the works integrate the jump exactly.  The plan positions of
    an analysis are reduced from their plans as well (:attr:`EquivalentModel.plans`).
    """
    if not isinstance(count, int) or isinstance(count, bool) or count < 2:
        raise ValueError(f"count must be an integer >= 2, not {count!r}")
    if isinstance(source, Scene):
        mechanism = build(source)
        return _model_over(mechanism, make_positions(mechanism), None, count, constant)
    # `check` weighs an analysis's dynamics three times (what the run would refuse, the dynamics overflowing the
    # sheets, the stall it warns of), each asking for the model afresh: made once while the analysis lives.
    return _MODELS.get(source, (count, constant),
                       lambda: _model_over(source.mechanism, source.positions, source, count, constant))


_MODELS: OwnedMemo[EquivalentModel] = OwnedMemo()


def _model_over(mechanism: Mechanism, positions: PositionSet, analysis: Analysis | None, count: int,
                constant: str) -> EquivalentModel:
    """The equivalent model over ``count`` steps of the driver, reduced from ``analysis``'s plans where given."""
    driver = mechanism.driver
    if driver.cyclic:
        sweep = positions.values[0] + driver.sense * np.linspace(0.0, 2.0 * math.pi, count + 1)
    else:
        sweep = np.linspace(driver.travel[0], driver.travel[1], count + 1)
        if (sweep[-1] - sweep[0]) * driver.sense < 0:  # run the travel (the swing) the way the driver moves
            sweep = sweep[::-1]
    sweep = _with_switches(mechanism, positions, sweep)
    motion = solve(mechanism, sweep, positions.reference)
    acting = activity_at(mechanism, positions, sweep)
    reductions = plan_reductions(analysis) if analysis is not None else ()
    return equivalent_model(mechanism, motion, acting, constant=constant, plans=reductions)


def diagram_model(speed: float, driving: tuple[ArrayLike, ArrayLike] | None = None,
                  resisting: tuple[ArrayLike, ArrayLike] | None = None, *, inertia: float = 0.0,
                  count: int = DEFAULT_COUNT) -> EquivalentModel:
    """The equivalent model of a machine given by its load diagrams alone, with no linkage.

    Parameters
    ----------
    speed
        The shaft's mean speed ωm (rad/s).
    driving, resisting
        ``(angles, moments)``: vertices of the driving moment and of the resisting one (what the
        resistance takes, positive) over one turn, angles in rad rising from 0 to 2π, the moments
        piecewise linear between them; an angle given twice is a jump.  A side left out (None) is
        the constant moment that balances the work over the turn.
    inertia
        The machine's own reduced moment of inertia, taken constant (kg·m²).
    count
        Equal steps of the turn sampled besides the vertices, for the drawing.

    The samples hold every vertex (both sides of a jump) and every zero of the net moment, so that
    the works and ΔWmax are exact for the diagrams as given.
    """
    if not (math.isfinite(speed) and speed > 0):
        raise ValueError(f"speed must be a positive number (rad/s), not {speed!r}")
    if not (math.isfinite(inertia) and inertia >= 0):
        raise ValueError(f"inertia must be a number >= 0 (kg·m²), not {inertia!r}")
    if not isinstance(count, int) or isinstance(count, bool) or count < 2:
        raise ValueError(f"count must be an integer >= 2, not {count!r}")
    if driving is None and resisting is None:
        raise ValueError("give the driving or the resisting diagram (or both); a side left out is taken constant")
    sides = {name: None if given is None else _turn_diagram(name, given)
             for name, given in (("driving", driving), ("resisting", resisting))}
    turn = 2.0 * math.pi
    vertices = np.concatenate([angles for angles, _ in filter(None, sides.values())])
    even = np.linspace(0.0, turn, count + 1)
    # An even sample a rounding away from a vertex would be a sliver of an interval: the vertex stands for it.
    near = np.min(np.abs(even[:, None] - vertices[None, :]), axis=1) <= 1e-9 * turn
    single = np.unique(np.concatenate([even[~near], vertices]))
    jumps = np.unique(np.concatenate([angles[1:][np.diff(angles) == 0] for angles, _ in filter(None, sides.values())]))
    samples = np.sort(np.concatenate([single, jumps]), kind="stable")
    # At a jump the first of its two samples takes the value before it, the second the value after.
    first = np.concatenate([[True], np.diff(samples) > 0])
    second_of_jump = ~first
    before = np.zeros(len(samples), dtype=bool)
    before[np.flatnonzero(second_of_jump) - 1] = True
    values = {name: None if given is None else _at(*given, samples, before) for name, given in sides.items()}
    chosen = "none"
    for name, other in (("driving", "resisting"), ("resisting", "driving")):
        if values[name] is None:
            chosen = name
            values[name] = np.full(len(samples), float(trapezoid(values[other], samples)) / turn)
    drive, resist = values["driving"], values["resisting"]
    samples, drive, resist = _with_net_zeros(samples, drive, resist)
    return EquivalentModel(kind="crank", link=0, speed=float(speed), sense=1.0, driver=samples, coordinate=samples,
                           inertia=np.full(len(samples), float(inertia)), inertia_slope=np.zeros(len(samples)),
                           link_inertia=MappingProxyType({0: np.full(len(samples), float(inertia))}),
                           driving=drive, resisting=-resist, constant=chosen, breaks=np.arange(len(samples)))


def _turn_diagram(name: str, given: tuple[ArrayLike, ArrayLike]) -> tuple[np.ndarray, np.ndarray]:
    """The vertices of a diagram over one turn, checked."""
    try:
        angles, moments = (np.asarray(part, dtype=float) for part in given)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be (angles, moments), two sequences of numbers") from None
    if angles.ndim != 1 or angles.shape != moments.shape or len(angles) < 2:
        raise ValueError(f"{name} needs as many angles as moments, at least two")
    if not (np.all(np.isfinite(angles)) and np.all(np.isfinite(moments))):
        raise ValueError(f"{name} must hold finite numbers")
    if angles[0] != 0.0 or abs(angles[-1] - 2.0 * math.pi) > 1e-12 or np.any(np.diff(angles) < 0):
        raise ValueError(f"{name}'s angles must rise from 0 to 2π (an angle given twice is a jump)")
    if np.any((np.diff(angles)[1:] == 0) & (np.diff(angles)[:-1] == 0)):
        raise ValueError(f"{name} gives an angle more than twice; a jump needs two")
    angles = angles.copy()
    angles[np.abs(angles - 2.0 * math.pi) <= 1e-12] = 2.0 * math.pi
    return angles, moments


def _at(angles: np.ndarray, moments: np.ndarray, x: np.ndarray, before: np.ndarray) -> np.ndarray:
    """The piecewise-linear diagram at ``x``: where ``before`` (a jump's first side), the value reached from the left."""
    last = len(angles) - 2
    index = np.where(before, np.searchsorted(angles, x, side="left") - 1, np.searchsorted(angles, x, side="right") - 1)
    index = np.clip(index, 0, last)
    width = angles[index + 1] - angles[index]
    with np.errstate(invalid="ignore", divide="ignore"):
        share = np.where(width > 0, (x - angles[index]) / np.where(width > 0, width, 1.0), np.where(before, 0.0, 1.0))
    return moments[index] + share * (moments[index + 1] - moments[index])


def _with_net_zeros(x: np.ndarray, drive: np.ndarray, resist: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The samples with every zero of ``drive − resist`` between two of them put in: the surplus turns there."""
    net = drive - resist
    crossing = np.flatnonzero((net[:-1] * net[1:] < 0) & (np.diff(x) > 0))
    if len(crossing) == 0:
        return x, drive, resist
    share = net[crossing] / (net[crossing] - net[crossing + 1])
    zeros = x[crossing] + share * (x[crossing + 1] - x[crossing])
    between = drive[crossing] + share * (drive[crossing + 1] - drive[crossing])
    order = np.argsort(np.concatenate([x, zeros]), kind="stable")
    return (np.concatenate([x, zeros])[order], np.concatenate([drive, between])[order],
            np.concatenate([resist, between])[order])


def plan_reductions(analysis: Analysis) -> tuple[PlanReduction, ...]:
    """Je and Me from the velocity plan of each plan position and of each position of
    ``positions.velocity_plans``, beside the analytic values there, in the order of the positions."""
    mechanism, motion = analysis.mechanism, analysis.motion
    driver = mechanism.driver
    velocity = driver.omega if driver.kind == "crank" else driver.velocity
    speed = abs(velocity)
    acting = activity(mechanism, analysis.positions, motion)
    exact_state = motion_state(motion)
    exact_inertia = sum(_link_inertia(mechanism, exact_state, velocity, motion.count).values(), np.zeros(motion.count))
    exact_power = _total_power(mechanism, exact_state, acting, motion.count)
    found = []
    for plan in analysis.drawn_velocities:  # only velocities enter: no acceleration is read
        index = plan.index
        state = plan_state(mechanism, plan.positions, plan.velocity, None)
        column = acting[:, index:index + 1]
        inertia = float(sum(_link_inertia(mechanism, state, velocity, 1).values(), np.zeros(1))[0])
        moment = float(_total_power(mechanism, state, column, 1)[0]) / speed
        found.append(PlanReduction(plan.number, index, float(motion.driver[index]), inertia, moment,
                                   float(exact_inertia[index]), float(exact_power[index]) / speed))
    return tuple(found)


def _massive(mechanism: Mechanism):
    """(number, spec) of every moving link with a mass or a moment of inertia."""
    links = mechanism.scene.links
    for number in mechanism.moving_links:
        spec = links.get(number)
        if spec is not None and (spec.mass > 0 or spec.inertia > 0):
            yield number, spec


def _link_inertia(mechanism: Mechanism, state: State, velocity: float, count: int) -> dict[int, np.ndarray]:
    """Each link's m·(vS/v1)² + JS·(ω/v1)² (an array over the state's positions)."""
    shares = {}
    for number, spec in _massive(mechanism):
        share = np.zeros(count)
        if spec.mass > 0:
            share = share + spec.mass * _full(norm2(state.points[spec.centre].v), count)
        if spec.inertia > 0:
            omega = state.links[number].omega
            share = share + spec.inertia * _full(omega * omega, count)
        shares[number] = share / (velocity * velocity)
    return shares


def _powers(mechanism: Mechanism, state: State, acting: np.ndarray | None,
            count: int) -> tuple[np.ndarray, list[np.ndarray]]:
    """The power of the weights, and of each scene load (W), over the positions.

    Each scene load's power is that of all the loads with it alone acting, less that of all the
    loads with none acting: what :func:`graphplan.loads.link_loads` makes of it, and nothing else.
    """
    scene = mechanism.scene
    loads = scene.loads
    if acting is None:
        acting = np.ones((len(loads), count))
    # A diagram's load acts by its share of the largest value (0…1), not all or nothing.
    acting = np.asarray(acting, dtype=float)
    if acting.shape != (len(loads), count):
        raise ValueError(f"acting must have shape {(len(loads), count)} (loads, positions), not {acting.shape}")
    weights = np.zeros(count)
    for number, spec in _massive(mechanism):
        if spec.mass > 0 and scene.gravity != 0:
            # G = m·g along −y: its power is −m·g·vSy.
            weights = weights - spec.mass * scene.gravity * _full(state.points[spec.centre].v.imag, count)
    if not loads:
        return weights, []
    silent = np.zeros_like(acting)
    base = _full(power(link_loads(mechanism, state, silent), state), count)
    shares = []
    for row in range(len(loads)):
        alone = silent.copy()
        alone[row] = acting[row]
        shares.append(_full(power(link_loads(mechanism, state, alone), state), count) - base)
    return weights, shares


def _total_power(mechanism: Mechanism, state: State, acting: np.ndarray | None, count: int) -> np.ndarray:
    """The power of the weights and of every scene load (W), over the positions."""
    weights, shares = _powers(mechanism, state, acting, count)
    return sum(shares, weights)


#: A load's work over the run within this share of the work it gives and takes, ∫|Me| dψ, is none: a force of fixed
#: direction on a crank turning round does none over the cycle, but the sum over the samples leaves some 10⁻⁶ of
#: it where a load's window puts samples in unevenly (10⁻⁵ at 36 samples a turn).
NO_WORK = 1e-4


def _sides(loads: Sequence, moments: Sequence[np.ndarray], coordinate: np.ndarray, breaks: np.ndarray
           ) -> tuple[list[bool], tuple[MovedLoad, ...]]:
    """Whether each scene load drives, by its reduced moment's work over the run, and the loads given as driving
    that are counted with the resistances.

    A load given as resisting resists.  The other loads along one line at one point (a moment: on one link) are
    one force, given over several strokes or windows (a gas force as its indicator diagram, one load a stroke),
    and are sorted as one: they drive where their work is positive, and go with the weights where it is zero
    (within :data:`NO_WORK` of the work they give and take) or negative.  A spring goes with the weights whatever
    its work: like them it is the machine's own, giving back what it takes, and no constant moment stands for it.
    """
    forces: dict[tuple, list[int]] = {}
    for row, load in enumerate(loads):
        if not load.resisting:
            forces.setdefault(_line(load), []).append(row)
    drives = [False] * len(loads)
    moved = []
    for rows in forces.values():
        work = sum(float(_integral(moments[row], coordinate, breaks)[-1]) for row in rows)
        given = sum(float(_integral(np.abs(moments[row]), coordinate, breaks)[-1]) for row in rows)
        if work > NO_WORK * given and not loads[rows[0]].spring:
            for row in rows:
                drives[row] = True
        else:
            moved.append(MovedLoad(tuple(loads[row].where for row in rows), work if abs(work) > NO_WORK * given
                                   else 0.0))
    return drives, tuple(moved)


def _line(load) -> tuple:
    """What makes loads one force: its kind, link, point and direction, or the point its line runs to (a moment: its
    kind and link)."""
    if load.kind == "moment":
        return load.kind, load.link
    if load.spring:   # a spring's force is its length's, one force of its own beside any other on its line
        return load.kind, load.link, load.point, "spring", load.along
    if load.along is not None:   # a line that turns is the one through the point it is along
        return load.kind, load.link, load.point, "along", load.along
    return load.kind, load.link, load.point, round((load.angle_deg or 0.0) % 360.0, 9) % 360.0


def _balanced(coordinate: np.ndarray, driving: np.ndarray, resisting: np.ndarray, constant: str,
              drives: Sequence[str], resists: Sequence[str], breaks: np.ndarray,
              noun: str = "moment") -> tuple[np.ndarray, np.ndarray, str]:
    """The moments with one side made constant so that their work over the samples balances; ``drives`` are the
    scene's driving loads, ``resists`` those it gives as resisting (the loads given as driving that go with the
    weights are kept with them); ``noun``, what a side is (a slider driver's is a force)."""
    if constant == "auto":
        constant = "driving" if not drives else "resisting" if not resists else "none"
    if constant == "none":
        return driving, resisting, constant
    replaced = drives if constant == "driving" else resists
    if replaced:
        # The other side is a way out only where the scene gives no loads on it either.
        other = "resisting" if constant == "driving" else "driving"
        kept = resists if constant == "driving" else drives
        raise ConstantSideError(constant, tuple(replaced), ("none",) if kept else (other, "none"), noun)
    travel = float(coordinate[-1] - coordinate[0])
    if travel <= 0:
        raise ValueError("the driver does not move over the samples, so no constant moment balances their work")
    # Every load on the replaced side is absent, so what is left of ``resisting`` is the weights, and the loads
    # counted with them, kept.
    level = -float(_integral(driving + resisting, coordinate, breaks)[-1]) / travel
    if constant == "driving":
        return driving + level, resisting, constant
    return driving, resisting + level, constant


def _with_switches(mechanism: Mechanism, positions: PositionSet, sweep: np.ndarray) -> np.ndarray:
    """``sweep`` with the two sides put in of every place where a load's window opens or closes, a vertex of its
    diagram lies (its value turns a corner there, and the reduced moment with it) or a resisting load's link
    turns back (the load turns round with its motion): the works are integrated by Simpson's rule between them,
    where the moments are smooth."""
    if not mechanism.scene.loads:
        return sweep
    return with_switches(sweep, lambda values: load_corners_at(mechanism, positions, values))


#: Samples closer than this share of the run are the two sides of one place where the loads switch or turn a
#: corner (the bisection puts them 10⁻¹² of a step apart): they bound the smooth stretches the works are integrated
#: over.
_PAIR = 1e-9


def _breaks_of(coordinate: np.ndarray) -> np.ndarray:
    """The run's ends and both samples of every pair closer than :data:`_PAIR` of the run."""
    span = float(abs(coordinate[-1] - coordinate[0]))
    close = np.flatnonzero(np.diff(coordinate) <= _PAIR * span)
    return np.unique(np.concatenate([[0, len(coordinate) - 1], close, close + 1]))


def _integral(values: np.ndarray, coordinate: np.ndarray, breaks: np.ndarray) -> np.ndarray:
    """∫ values dψ from the first sample to each: Simpson's rule (scipy's, for unequal steps) on each stretch
    between two breaks, whose values are smooth; the trapezoid across a stretch of two samples."""
    values = np.asarray(values, dtype=float)
    if len(breaks) == len(coordinate):   # every sample a break (a load diagram's vertices): the trapezoid, at once
        return cumulative_trapezoid(values, coordinate, initial=0.0)
    found = np.zeros(len(coordinate))
    for start, stop in itertools.pairwise(breaks):
        stretch = slice(start, stop + 1)
        found[stretch] = found[start] + cumulative_simpson(values[stretch], x=coordinate[stretch], initial=0.0)
    return found


def _full(value, count: int) -> np.ndarray:
    return np.broadcast_to(np.asarray(value, dtype=float), (count,))


__all__ = ["CONSTANT_CHOICES", "DEFAULT_COUNT", "NO_WORK", "ConstantSideError", "EquivalentModel", "MovedLoad",
           "PlanReduction", "diagram_model", "equivalent_model", "equivalent_model_of", "plan_reductions"]
