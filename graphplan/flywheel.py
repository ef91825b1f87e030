"""The flywheel: the fluctuation of speed over a steady cycle, and the moment of inertia that limits it.

Over a steady cycle the driving and resisting work balance, but not at every instant: the
surplus work ``ΔW(x) = ∫(driving − resisting)`` swings between a largest and a smallest value,
and ``ΔWmax`` (their difference, the range of the surplus) is the energy the flywheel must take
in and give back.  With the coefficient of speed fluctuation ``δ = (ωmax − ωmin)/ωm`` and
``ωm = (ωmax + ωmin)/2``, so that ``ωmax,min = ωm·(1 ± δ/2)``:

* approximate method (the machine's reduced inertia J taken constant):
  ``J_F = ΔWmax/(ωm²·δ) − J``, since ``½·(J_F + J)·(ωmax² − ωmin²) = (J_F + J)·ωm²·δ``;
* Mertsalov's method (a linkage's variable Je): the energy of the links whose reduced inertia
  varies is taken at the mean speed, ``T_II = ½·(Je − Jc)·ωm²``; the rest, ``ΔW − T_II``, swings
  the flywheel with the links of constant reduced inertia Jc (the crank):
  ``J_F = range(ΔW − T_II)/(ωm²·δ) − Jc``;
* exact method, Wittenbauer's energy–mass diagram: the curve ΔT(Je) over the cycle and its two
  tangents of slopes ``ωmax²/2`` and ``ωmin²/2`` (in J per kg·m²; on paper ``tan ψ = (μJ/μT)·ω²/2``).
  They meet at the true origin of kinetic energy and inertia, ``(−J_F, −T0)``, so that
  ``J_F = (b_max − b_min)/(ωmax²/2 − ωmin²/2)`` from their intercepts ``b`` on the ΔT axis.

The tangent slopes are exact here (``(1 ± δ/2)²``); many textbooks write ``ωm²·(1 ± δ)/2``,
dropping δ²/4, which changes J_F by a share of order δ²/4.

A flywheel moved to a shaft turning at n′ (geared to the crank's n) needs ``J_F·(n/n′)²``.

The standalone functions (:func:`fluctuation`, :func:`fluctuation_from_areas`,
:func:`flywheel_inertia`, :func:`moved_inertia`) need no linkage: a power cycle over time, or a
torque diagram over the crank angle, given as steps, as piecewise-linear vertices or as samples.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike
from scipy.integrate import cumulative_trapezoid, trapezoid

from .dynamics import CONSTANT_CHOICES, DEFAULT_COUNT, EquivalentModel, diagram_model
from .errors import SceneError
from .kinematics import read_only
from .reader import Table, check_xy
from .rounding import RELATIVE_NOISE
from .table_keys import keys_of_other_tables
from .units import (
    MOST_MOTOR_SLIP,
    RPM,
    exponent_slip,
    motor_speed_in_rpm,
    nearest_synchronous_rpm,
    percentage_question,
    rpm_question,
)

# A cycle whose work is left over by more than this share of the work done is not steady: the floor under the
# integration's own error (EquivalentModel.work_uncertainty), below which a mismatch is not told from it.
_BALANCE = 1e-6
# Share of the largest reduced inertia under which a link's share counts as constant (Mertsalov's Jc).
_CONSTANT_SHARE = 1e-9
#: The largest coefficient of speed fluctuation machines are built to run with (crushers and punches 1/5; pumps
#: 1/5…1/30, machine tools 1/20…1/50, generators 1/100…1/300).  Above it, up to δ < 2 where ωmin = ωm·(1 − δ/2)
#: reaches nought, the flywheel is still worked out, and rightly (the tangents' slopes ωm²·(1 ± δ/2)²/2 are exact,
#: not the small-δ ωm²·(1 ± δ)/2), so it is not refused; but a speed swinging ωmax/ωmin = (2 + δ)/(2 − δ) is no
#: steady running, and such a δ is more likely a percentage typed for a fraction: it is warned of.
LARGEST_USUAL_DELTA = 0.2
#: The smallest δ a flywheel is sized for: the evenest machines, alternators, run at some 1/300.  δ = 1e-14 sized a
#: press's flywheel 1e14 times too heavy for its motor to bring to speed, and the run advised a longer duration.
SMALLEST_DELTA = 1e-4


# --- standalone: a cycle of torque or power ---------------------------------------------------


@dataclass(frozen=True)
class Fluctuation:
    """The surplus work over one cycle.

    ``x`` is the abscissa (crank angle in rad, or time in s), with every zero of the net load
    put in, so that the extremes of ``surplus`` (J) lie on samples; ``mean`` is the constant
    load (N·m or W) taken to balance the cycle, None when both sides were given.
    """

    x: np.ndarray
    surplus: np.ndarray
    mean: float | None = None

    @property
    def delta_w_max(self) -> float:
        """ΔWmax: the largest surplus less the smallest (J)."""
        return float(np.max(self.surplus) - np.min(self.surplus))

    @property
    def x_max(self) -> float:
        """Where the surplus is largest: the speed is greatest there."""
        return float(self.x[int(np.argmax(self.surplus))])

    @property
    def x_min(self) -> float:
        """Where the surplus is smallest: the speed is least there."""
        return float(self.x[int(np.argmin(self.surplus))])

    @property
    def imbalance(self) -> float:
        """The surplus left at the end of the cycle (zero for a steady one)."""
        return float(self.surplus[-1])


def fluctuation(x: ArrayLike, driving: ArrayLike | None = None, resisting: ArrayLike | None = None, *,
                steps: bool = False) -> Fluctuation:
    """The surplus work ``∫(driving − resisting) dx`` over one cycle from ``x[0]``.

    Parameters
    ----------
    x
        The abscissa, increasing: crank angles (rad) with torques (N·m), or times (s) with powers (W).
    driving, resisting
        The driving and resisting load at ``x`` (piecewise linear between the points), or with
        ``steps`` on each interval ``[x[i], x[i+1])`` (one value fewer than ``x``).  A side
        left out is the constant that balances the cycle (its mean).
    steps
        Whether the loads are steps, constant over each interval (a power cycle), rather than
        vertices of a piecewise-linear diagram (a torque diagram, or samples of one).

    Returns
    -------
    Fluctuation
        The surplus at ``x`` and at every zero of the net load between, exact for the data as given.
    """
    x = _vector("x", x)
    if len(x) < 2 or not np.all(np.diff(x) > 0):
        raise ValueError("x must have at least two values, increasing")
    size = len(x) - 1 if steps else len(x)
    if driving is None and resisting is None:
        raise ValueError("give the driving or the resisting load (or both); a side left out is taken constant")
    drive = None if driving is None else _vector("driving", driving, size)
    resist = None if resisting is None else _vector("resisting", resisting, size)
    widths = np.diff(x)
    span = float(x[-1] - x[0])

    def mean_of(values: np.ndarray) -> float:
        return float(np.dot(values, widths) if steps else trapezoid(values, x)) / span

    mean = None
    if drive is None:
        mean = mean_of(resist)
        drive = np.full(size, mean)
    elif resist is None:
        mean = mean_of(drive)
        resist = np.full(size, mean)
    net = drive - resist
    if steps:
        return Fluctuation(x, np.concatenate([[0.0], np.cumsum(net * widths)]), mean)
    x, net = _with_zeros(x, net)
    return Fluctuation(x, cumulative_trapezoid(net, x, initial=0.0), mean)


def fluctuation_from_areas(areas: ArrayLike, scale: float = 1.0) -> Fluctuation:
    """The surplus from the signed areas of a torque diagram between it and the mean line, in order.

    ``areas`` are the loops above (+) and below (−) the mean torque line as measured on the
    drawing (mm²), ``scale`` the energy one unit of area stands for (J/mm², μM·μφ).  ``x`` of
    the result counts the loops' ends, 0 at the start.
    """
    areas = _vector("areas", areas)
    if not scale > 0 or not math.isfinite(scale):
        raise ValueError(f"scale must be a positive number, not {scale!r}")
    return Fluctuation(np.arange(len(areas) + 1, dtype=float), scale * np.concatenate([[0.0], np.cumsum(areas)]))


def flywheel_inertia(delta_w_max: float, omega_mean: float, delta: float, inertia: float = 0.0) -> float:
    """J_F = ΔWmax/(ωm²·δ) − J: the approximate method, the machine's own reduced inertia J constant."""
    _check_speed(omega_mean, delta)
    if not delta_w_max >= 0:
        raise ValueError(f"delta_w_max must be >= 0, not {delta_w_max!r}")
    return delta_w_max / (omega_mean * omega_mean * delta) - inertia


def speed_fluctuation(delta_w_max: float, omega_mean: float, inertia: float) -> float:
    """δ = ΔWmax/(J·ωm²): the coefficient of fluctuation that an inertia J allows."""
    if not inertia > 0:
        raise ValueError(f"inertia must be > 0, not {inertia!r}")
    _check_speed(omega_mean, 1.0)
    return delta_w_max / (inertia * omega_mean * omega_mean)


def moved_inertia(inertia: float, speed: float, to_speed: float) -> float:
    """J·(n/n′)²: the inertia on a shaft turning at ``to_speed`` that does what ``inertia`` does at ``speed``."""
    if not speed > 0 or not to_speed > 0:
        raise ValueError(f"speeds must be > 0, not {speed!r} and {to_speed!r}")
    return inertia * (speed / to_speed) ** 2


def speed_limits(omega_mean: float, delta: float) -> tuple[float, float]:
    """(ωmax, ωmin) = ωm·(1 ± δ/2), from δ = (ωmax − ωmin)/ωm and ωm = (ωmax + ωmin)/2."""
    _check_speed(omega_mean, delta)
    return omega_mean * (1 + delta / 2), omega_mean * (1 - delta / 2)


def rpm_to_omega(rpm: float) -> float:
    """ω = π·n/30."""
    return rpm * RPM


def omega_to_rpm(omega: float) -> float:
    return omega / RPM


# --- a linkage's flywheel -----------------------------------------------------------------------


@dataclass(frozen=True)
class Tangent:
    """A line ΔT = slope·Je + intercept of the energy–mass diagram, touching the curve at sample ``touch``."""

    slope: float
    intercept: float
    touch: int


@dataclass(frozen=True)
class Flywheel:
    """The flywheel of an equivalent model for δ at the mean speed ωm.

    ``inertia`` is the exact J_F of the energy–mass diagram (``upper`` and ``lower`` its
    tangents of slopes ωmax²/2 and ωmin²/2); ``approximate`` and ``mertsalov`` are the two
    simpler methods.  ``omega`` is the crank's speed over the cycle with the flywheel of
    ``inertia`` fitted, ``kinetic_energy_start`` the machine's kinetic energy at the first
    sample.  ``moved`` is J_F on the shaft turning at ``shaft_rpm``, when one is given.
    ``required`` is the tangents' J_F with its sign: ≤ 0 where the machine's own inertia keeps it
    within δ, and then no flywheel is mounted (``inertia`` 0) and ``omega`` is the speed the machine
    has with its own inertia alone, at the same ωm = (ωmax + ωmin)/2, within ``reached`` ≤ δ.
    """

    delta: float
    omega_mean: float
    delta_w_max: float
    inertia: float
    approximate: float
    mertsalov: float
    constant_inertia: float
    upper: Tangent
    lower: Tangent
    kinetic_energy_start: float
    omega: np.ndarray
    shaft_rpm: float | None = None
    moved: float | None = None
    required: float = 0.0

    def __post_init__(self) -> None:
        # Handed out as it is (scene.machine_dynamics().flywheel.omega): written in place, it changed the speeds
        # the results and the note read after.
        read_only(self.omega)

    def __repr__(self) -> str:
        # The dataclass's own repr printed the speed at every sample: 5 700 characters on a notebook's line.
        return (f"<Flywheel for δ = {self.delta:.4g} at ωm = {self.omega_mean:.4g} rad/s: JF = {self.inertia:.5g} "
                f"kg·m², ΔWmax = {self.delta_w_max:.5g} J>")

    @property
    def reached(self) -> float:
        """The δ the machine has with the flywheel mounted: the one asked for, or less without a flywheel."""
        return (self.omega_max - self.omega_min) / self.omega_mean

    @property
    def omega_max(self) -> float:
        return float(np.max(self.omega))

    @property
    def omega_min(self) -> float:
        return float(np.min(self.omega))

    # The last sample closes the cycle at the first one's state: left out, the fastest and slowest samples are
    # never taken at 360° for 0° as rounding has the speed there a hair higher or lower.
    @property
    def index_max(self) -> int:
        return int(np.argmax(self.omega[:-1]))

    @property
    def index_min(self) -> int:
        return int(np.argmin(self.omega[:-1]))


def _balancing_advice(model: EquivalentModel) -> str:
    """What balances the cycle's work: a side left out taken constant, or where the scene gives both sides (a
    constant moment replaces a side, so ``constant`` has none to replace), a side left out or the moment that
    balances them added on the driving link."""
    driving, resisting = model.driving_loads, model.resisting_loads
    # A side is left out where no load is on it, the resisting one where none is marked resisting: the loads given
    # as driving that take work are kept with the weights, as a constant resisting moment keeps them.
    moved = {where for load in model.moved for where in load.loads}
    given = (("driving", driving), ("resisting", [where for where in resisting if where not in moved]))
    absent = [side for side, loads in given if not loads]
    if absent:
        return f'take the {absent[0]} moment constant (constant = "{absent[0]}")'
    # The mean moment that makes up the work left over: a driving one in the sense of the crank's turn where the
    # resistance takes more, a resisting one where the driving loads give more.
    moment = abs(model.imbalance) / float(model.coordinate[-1] - model.coordinate[0])
    if model.imbalance < 0:
        added = f"value = {model.sense * moment:.7g} (N·m, in the sense link {model.link} turns)"
        dropped, kept, both = "driving", "resistance", ", ".join(driving)
    else:
        added = f"value = {moment:.7g}, resisting = true"
        dropped, kept, both = "resisting", "driving loads", ", ".join(resisting)
    return ('a constant moment (constant = "driving" or "resisting") replaces a side the scene leaves out, and it '
            f"gives both (driving {', '.join(driving)}; resisting {', '.join(resisting)}): leave out the {dropped} "
            f"loads ({both}) for a constant {dropped} moment to balance the {kept}, or add the moment that balances "
            f'the work on the driving link: [[loads]] kind = "moment", link = {model.link}, {added}')


def flywheel_for(model: EquivalentModel, delta: float, omega_mean: float | None = None, *,
                 shaft_rpm: float | None = None) -> Flywheel:
    """The flywheel that keeps a turning equivalent model within δ at ``omega_mean`` (default: the driver's |ω1|).

    The cycle must be steady: its driving and resisting work must balance (see
    :attr:`EquivalentModel.constant`).
    """
    if not (model.turning and model.cyclic):
        raise ValueError("a flywheel needs a turning driver over a cycle; this model's driver "
                         f"{'rocks over a swing' if model.turning else 'is a slider'}")
    omega_mean = model.speed if omega_mean is None else omega_mean
    _check_speed(omega_mean, delta)
    energy, inertia = model.energy, model.inertia
    work = max(float(np.max(np.abs(model.driving_work))), float(np.max(np.abs(model.resisting_work))), 1e-300)
    # A mismatch within the integration's own error is no mismatch: refused, a student told to add a moment of
    # that size would be fitting the quadrature, not the machine.
    if abs(model.imbalance) > max(_BALANCE * work, model.work_uncertainty):
        raise ValueError(f"the driving and resisting work differ by {model.imbalance:.6g} J over the cycle, so the "
                         f"motion is not periodic; {_balancing_advice(model)}")
    delta_w_max = float(np.max(energy) - np.min(energy))
    if delta_w_max <= RELATIVE_NOISE * work and not np.any(inertia > 0):
        # No flywheel is needed where ΔT never changes, but with no Je of its own the machine's kinetic energy is 0 at
        # every speed: its start T0 and its speed are 0/0, and the rounding left in ΔT (10⁻¹⁶ J) sized a flywheel of
        # 10⁻¹⁵ kg·m² that "held" the speed within δ, or the root search met NaN where ΔT is 0 exactly.
        raise ValueError("the driving and resisting moments balance at every angle (ΔT = 0 over the cycle) and the "
                         "machine has no moment of inertia of its own (Je = 0): nothing fixes its kinetic energy, so "
                         "neither its speed nor a flywheel can be found; give its inertia (dynamics.inertia without "
                         "a linkage, the links' mass and inertia with one), or loads that vary over the cycle")
    approximate = flywheel_inertia(delta_w_max, omega_mean, delta, model.mean_inertia)

    peak = float(np.max(inertia))
    constant = sum((model.mean_over_run(share) for share in model.link_inertia.values()
                    if np.ptp(share) <= _CONSTANT_SHARE * peak), 0.0)
    varying_energy = 0.5 * (inertia - constant) * omega_mean * omega_mean
    mertsalov = flywheel_inertia(float(np.ptp(energy - varying_energy)), omega_mean, delta, constant)

    fastest, slowest = speed_limits(omega_mean, delta)
    upper = _tangent(energy, inertia, 0.5 * fastest * fastest, above=True)
    lower = _tangent(energy, inertia, 0.5 * slowest * slowest, above=False)
    required = (upper.intercept - lower.intercept) / (upper.slope - lower.slope)
    if required > 0:
        mounted = required
        start = upper.slope * required - upper.intercept   # T0: both tangents pass through (−J_F, −T0)
    else:
        # A negative flywheel cannot be mounted: the machine turns with its own inertia, the faster for it.
        mounted = 0.0
        start = _start_energy(energy, inertia, omega_mean)
    omega = _speed(start, energy, inertia + mounted)
    moved = None
    if shaft_rpm is not None:
        moved = moved_inertia(mounted, omega_to_rpm(omega_mean), shaft_rpm)
    return Flywheel(delta=delta, omega_mean=omega_mean, delta_w_max=delta_w_max, inertia=mounted,
                    approximate=approximate, mertsalov=mertsalov, constant_inertia=constant, upper=upper,
                    lower=lower, kinetic_energy_start=start, omega=omega, shaft_rpm=shaft_rpm, moved=moved,
                    required=required)


def _speed(start: float, energy: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """ω = √(2·(T0 + ΔT)/J) over the cycle."""
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.sqrt(np.maximum(2.0 * (start + energy), 0.0) / inertia)


def _start_energy(energy: np.ndarray, inertia: np.ndarray, omega_mean: float) -> float:
    """T0 at which the machine of ``inertia`` alone turns at ``omega_mean`` = (ωmax + ωmin)/2.

    The mean of the extremes rises with T0; from the T0 at which the speed just touches zero (a
    machine that keeps within δ < 2 turns faster) to the one at which even its slowest point turns
    at ωm, it crosses ωm once.  With a constant J this gives δ = ΔWmax/(J·ωm²) exactly.
    """
    from scipy.optimize import brentq  # here: scipy.optimize takes a second to import, and few machines need it

    def middle_less_mean(start: float) -> float:
        omega = _speed(start, energy, inertia)
        return 0.5 * (float(np.max(omega)) + float(np.min(omega))) - omega_mean

    low = -float(np.min(energy))
    high = float(np.max(0.5 * omega_mean * omega_mean * inertia - energy))
    if middle_less_mean(low) >= 0.0:
        return low
    if middle_less_mean(high) <= 0.0:
        return high
    return float(brentq(middle_less_mean, low, high, xtol=1e-14 * max(abs(high), 1.0), rtol=1e-15))


def _tangent(energy: np.ndarray, inertia: np.ndarray, slope: float, above: bool) -> Tangent:
    """The line of ``slope`` that touches the curve (Je, ΔT) from above (or below)."""
    offsets = energy - slope * inertia
    touch = int(np.argmax(offsets) if above else np.argmin(offsets))
    return Tangent(slope, float(offsets[touch]), touch)


# --- the scene's [dynamics] table ---------------------------------------------------------------

#: Keys of ``[dynamics]`` that the equation of motion reads (:func:`graphplan.machine_motion.read_motion`).
MOTION_KEYS = ("motor", "brake", "clutch", "start", "duration", "method", "rtol", "steady_tolerance")
#: The load diagrams of a ``[dynamics]`` table without a linkage, over one turn of the shaft.
DIAGRAM_KEYS = ("resisting_torque", "resisting_power", "driving_torque", "driving_power")
# Keys that only a scene without a linkage reads: with one, its loads and masses are reduced from the mechanism.
_DIAGRAM_ONLY = (*DIAGRAM_KEYS, "driving", "resisting", "inertia")
# The keys that size a flywheel: its δ, the mean speed it is sized at, the shaft it may be moved to.
_FLYWHEEL_KEYS = ("delta", "rpm", "omega", "flywheel_shaft_rpm")

# Keys of one table of [dynamics]' motion that a student writes in another, the motor's gear_ratio beside delta
# or a start inside the motor's braces (the docs list them in one row): each is told where it goes.
_MOTOR_KEYS = ("kind", "gear_ratio", "rotor_inertia", "off_at", "stall_torque", "no_load_rpm", "points", "power",
               "overload", "synchronous_rpm", "rated_rpm", "rated_slip")
_OWN_KEYS = ("motor", "brake", "clutch", "start", "duration", "method", "rtol", "steady_tolerance", "delta",
             "flywheel_shaft_rpm", "constant", "count")
_NESTED_KEYS = {"brake": ("damping",), "clutch": ("engage_at",), "start": ("angle_deg", "driving_rpm", "driving_omega")}


# The flywheel moved to another shaft is J·(n/n_shaft)²: a shaft speed no flywheel turns at (1e-6 rpm, a slip of
# the exponent) made it 1e16 times the crank's without a word.  The slowest flywheels, a large press's or a rolling
# mill's, turn at tens of rev/min; the fastest, a storage flywheel's of composite, at some 50 000.
SLOWEST_FLYWHEEL_SHAFT_RPM = 1.0
FASTEST_FLYWHEEL_SHAFT_RPM = 100_000.0
# The flywheel for δ is ΔWmax/(ωm²·δ): a mean speed no shaft with a flywheel turns at (rpm = 1e-12, a slip of the
# exponent) made it 1e24 times the one at 1 rpm without a word.  The shafts a flywheel evens out turn within the
# flywheel's own bounds: a large press's main shaft at some 10 rev/min, an engine's crank at up to some 10 000.
SLOWEST_MEAN_RPM = SLOWEST_FLYWHEEL_SHAFT_RPM
FASTEST_MEAN_RPM = FASTEST_FLYWHEEL_SHAFT_RPM
# A run's start speed (the shaft's, or a clutch's driving half's) over the machine's mean speed: a machine starts from
# rest, or runs down from about its running speed (an overspeed trip's 1.1–1.2).  A nameplate's 1450 rpm typed as
# start.omega under a press's 100 rpm is some 140 times it, which the run still integrates and the rpm warning asks
# about; 200 times it and more no run means, where the run could still be short enough to be integrated.
FASTEST_START_OVER_MEAN = 200.0


def misplaced_keys(where: str, path: str) -> dict[str, str]:
    """The keys the table at ``where`` (``path``, the ``[dynamics]`` table, or one nested in it) does not take but
    another of ``path``'s tables does, each with the path of that table, for :meth:`Table.done`'s ``elsewhere``."""
    homes = {key: f"{path}.motor" for key in _MOTOR_KEYS}
    for table, keys in _NESTED_KEYS.items():
        homes.update({key: f"{path}.{table}" for key in keys})
    if where != path:
        homes.update({key: path for key in _OWN_KEYS})
    return {key: home for key, home in homes.items() if home != where}


def _done(table: Table) -> None:
    """Reject the ``[dynamics]`` table's first key nobody took, telling a key of another table, or of a table
    nested in it, where it goes."""
    table.done(elsewhere={**keys_of_other_tables("dynamics"), **misplaced_keys(table.path, table.path)})


_SIDES = ("driving", "resisting")


@dataclass(frozen=True)
class LoadDiagram:
    """One side's load over a turn of the shaft, from a ``[dynamics]`` table without a linkage.

    ``angles_deg`` rise from 0 to 360 (an angle given twice is a jump), the load is piecewise linear
    between them: a torque (N·m) or a power (W) by ``quantity``.  A resisting load's values are what
    the resistance takes (positive).
    """

    key: str
    side: str
    quantity: str
    angles_deg: tuple[float, ...]
    values: tuple[float, ...]

    def torques(self, omega_mean: float) -> np.ndarray:
        """The load as a moment on the shaft (N·m): a power P becomes M = P/ωm at the mean speed."""
        values = np.asarray(self.values, dtype=float)
        return values / omega_mean if self.quantity == "power" else values

    def work(self, omega_mean: float) -> float:
        """The work over the turn (J): exact for the piecewise-linear diagram."""
        return float(trapezoid(self.torques(omega_mean), np.radians(self.angles_deg)))


@dataclass(frozen=True)
class DynamicsSpec:
    """The scene's ``[dynamics]`` table.

    ``delta`` is the coefficient of speed fluctuation (None: no flywheel asked for);
    ``omega`` the mean speed of the driver (rad/s, None: the driver's own |ω1|);
    ``flywheel_shaft_rpm`` a shaft the flywheel is moved to; ``constant`` which reduced moment
    balances the cycle; ``count`` the samples of the cycle; ``motion`` the equation of motion to
    integrate (a :class:`~graphplan.machine_motion.MotionSpec`: the motor, a brake, a clutch), or None.
    A scene without a linkage gives ``diagrams`` (one or two :class:`LoadDiagram`, a side each) and
    the machine's own constant reduced ``inertia`` instead.
    """

    where: str
    delta: float | None = None
    omega: float | None = None
    flywheel_shaft_rpm: float | None = None
    constant: str = "auto"
    count: int = DEFAULT_COUNT
    motion: Any = None
    diagrams: tuple[LoadDiagram, ...] = ()
    inertia: float = 0.0
    # The key the mean speed was given under, rpm or omega (None: not given), to name it where it looks mistyped.
    speed_key: str | None = None


def read_dynamics(table: Table, linkage: bool = True, once_over: str | None = None, driver: Any = None) -> DynamicsSpec:
    """The ``[dynamics]`` table, every key checked; the equation of motion's by its own reader.

    Without a ``linkage`` the table must give a load diagram (:data:`DIAGRAM_KEYS`), and may not
    give ``constant``; with one, no diagram.  ``once_over`` names the driver's key whose range its
    positions run over once (``driver.swing``, ``driver.travel``), None for a crank that turns
    round: such a run has an equivalent model, but neither a flywheel, which evens out the speed
    from turn to turn, nor the equation of motion, which is integrated over the turns.  ``driver``, a crank's
    record (``where``, ``omega``, ``rpm``), gives the mean speed where the table gives none, bounded as the table's.
    """
    if linkage:
        for key in _DIAGRAM_ONLY:
            if table.has(key):
                # The flywheel starter's driving = "constant" is the diagram scene's spelling of the linkage's key.
                spelt = f'; with a linkage write constant = "{key}"' if key in _SIDES and \
                    table.data[key] == "constant" else ""
                raise SceneError(table.where(key), "is for a scene without a linkage: this one has [frame] and "
                                 "[driver], whose loads and masses ([[loads]], [links.N]) are reduced to its driving "
                                 "link instead; leave it out, or leave out the linkage" + spelt)
    if once_over is not None:
        for key in (*_FLYWHEEL_KEYS, *MOTION_KEYS):
            if table.has(key):
                what = "the flywheel, which evens out a crank's speed from turn to turn" if key in _FLYWHEEL_KEYS \
                    else "the equation of motion, integrated over the turns of a crank"
                raise SceneError(table.where(key), f"is for {what}; this scene's positions run once over {once_over}, "
                                 "over which [dynamics] gives the equivalent model only: leave it out")
    delta = table.number("delta", None, positive=True)
    if delta is not None and delta < SMALLEST_DELTA:
        raise SceneError(table.where("delta"), f"must be at least {SMALLEST_DELTA:g}: the evenest machines, "
                         "alternators, run at some 1/300 = 0.0033, and the flywheel for delta is ΔWmax/(ωm²·δ), "
                         f"{SMALLEST_DELTA / delta:.3g} times the one for {SMALLEST_DELTA:g} here", delta,
                         hint="; a slip of the exponent?" if delta < SMALLEST_DELTA / 1000 else "")
    if delta is not None and not delta < 2:
        # δ = 5 for 5 % is the slip a student makes; delta_warning tells it below 2, this refusal must as well.
        raise SceneError(table.where("delta"), "must be < 2: ωmin = ωm·(1 − δ/2) must stay > 0", delta,
                         hint=(f"; {percentage_question(delta, 'δ')}" if delta / 100 < 2 else
                               "; a slip of the exponent?" if delta >= 2000 else ""))
    speed_key = next((key for key in ("rpm", "omega") if table.has(key)), None)
    omega = table.speed(None, positive=True)
    if speed_key is not None:
        _refuse_mean_speed(table, speed_key, omega)
    elif driver is not None and once_over is None and (delta is not None or any(map(table.has, MOTION_KEYS))):
        # The equivalent model alone takes no speed (Je and Me are ratios of speeds): a crank turned slowly for its
        # plans is let be until a flywheel is sized at its speed or a motor run about it.
        _refuse_driver_mean_speed(driver, table.path, sized=delta is not None)
    shaft = table.number("flywheel_shaft_rpm", None, positive=True)
    if shaft is not None and not SLOWEST_FLYWHEEL_SHAFT_RPM <= shaft <= FASTEST_FLYWHEEL_SHAFT_RPM:
        raise SceneError(table.where("flywheel_shaft_rpm"), f"must be within {SLOWEST_FLYWHEEL_SHAFT_RPM:g}–"
                         f"{FASTEST_FLYWHEEL_SHAFT_RPM:g} rpm, as a flywheel's shaft turns (a press's some 100–500, "
                         "a storage flywheel's up to some 50 000): the flywheel moved there is (n/n_shaft)² times "
                         "the one on the crank", shaft)
    if shaft is not None and delta is None:
        raise SceneError(table.where("flywheel_shaft_rpm"), "moves the flywheel sized for delta to another shaft, but "
                         "no delta is given, so no flywheel is sized: give delta (the coefficient of speed "
                         "fluctuation, 0.05 for 5 %), or leave flywheel_shaft_rpm out", shaft)
    count = table.integer("count", DEFAULT_COUNT, minimum=12, maximum=100_000)
    if not linkage:
        return _read_diagram_dynamics(table, DynamicsSpec(where=table.path, delta=delta, omega=omega,
                                                          flywheel_shaft_rpm=shaft, count=count, speed_key=speed_key))
    constant = table.choice("constant", CONSTANT_CHOICES, "auto")
    motion = None
    if any(table.has(key) for key in MOTION_KEYS):
        from .machine_motion import read_motion

        motion = read_motion(table, table.path)
        if omega is not None:
            _refuse_start_over_mean(motion, omega, table.where(speed_key))
        elif driver is not None:
            _refuse_start_over_mean(motion, abs(driver.omega), f"{driver.where}.{_driver_speed_key(driver)}")
    _done(table)
    return DynamicsSpec(where=table.path, delta=delta, omega=omega, flywheel_shaft_rpm=shaft, constant=constant,
                        count=count, motion=motion, speed_key=speed_key)


def _refuse_mean_speed(table: Table, key: str, omega: float) -> None:
    """Raise :class:`SceneError` at ``key`` (``rpm`` or ``omega``, ``omega`` rad/s as read) for a mean speed outside
    :data:`SLOWEST_MEAN_RPM`–:data:`FASTEST_MEAN_RPM`, told in the unit it was typed in."""
    _refuse_mean_speed_at(table.where(key), table.data[key], key == "rpm", omega)


def _driver_speed_key(driver: Any) -> str:
    """The key the crank's speed was typed under: ``rpm`` where the scene gave it so, else ``omega``."""
    return "omega" if driver.rpm is None else "rpm"


def _refuse_driver_mean_speed(driver: Any, path: str, sized: bool) -> None:
    """Raise :class:`SceneError` at the crank's ``omega`` or ``rpm`` where ``[dynamics]`` (at ``path``), giving no
    mean speed of its own, takes the crank's, and that is outside the mean speeds a flywheel is sized at (``sized``:
    one is, for its delta) or a motor runs a machine about: a crank turned slowly or fast for its plans alone gives
    the flywheel and the run nothing a machine has."""
    key = _driver_speed_key(driver)
    typed = driver.rpm if key == "rpm" else driver.omega
    _refuse_mean_speed_at(f"{driver.where}.{key}", typed, key == "rpm", abs(driver.omega),
                          f"; {path} gives no rpm or omega of its own and takes the crank's as the machine's mean "
                          f"speed (give {path}.rpm for the machine's own)", sized=sized)


def _refuse_mean_speed_at(where: str, typed: float, in_rpm: bool, omega: float, taken: str = "",
                          sized: bool = True) -> None:
    """Raise :class:`SceneError` at ``where`` for a mean speed (``omega`` rad/s, its size, ``typed`` in rpm or rad/s
    as ``in_rpm`` says) outside :data:`SLOWEST_MEAN_RPM`–:data:`FASTEST_MEAN_RPM`, told in the unit it was typed in;
    ``taken`` says where it was taken as the mean speed from; ``sized``: a flywheel is sized at it (else only the
    equation of motion is run about it)."""
    rpm = abs(typed) if in_rpm else omega / RPM
    if SLOWEST_MEAN_RPM <= rpm <= FASTEST_MEAN_RPM:
        return
    bounds = (f"{SLOWEST_MEAN_RPM:g}–{FASTEST_MEAN_RPM:g} rpm" if in_rpm else
              f"{SLOWEST_MEAN_RPM * RPM:.4g}–{FASTEST_MEAN_RPM * RPM:.5g} rad/s ({SLOWEST_MEAN_RPM:g}–"
              f"{FASTEST_MEAN_RPM:g} rpm)")
    nearest = SLOWEST_MEAN_RPM if rpm < SLOWEST_MEAN_RPM else FASTEST_MEAN_RPM
    slip = exponent_slip(rpm, SLOWEST_MEAN_RPM, FASTEST_MEAN_RPM)
    why = (f"the flywheel for delta is ΔWmax/(ωm²·δ), {(nearest / rpm) ** 2:.3g} times the one at {nearest:g} rpm "
           "here" if sized else "the equation of motion runs the motor through its gear about it")
    raise SceneError(where, f"must be within {bounds}, as a shaft a flywheel evens out turns (a press's "
                     f"some 10–100 rpm, an engine's up to some 10 000): {why}{taken}", typed, hint=slip)


def _refuse_start_over_mean(motion: Any, mean: float, mean_key: str) -> None:
    """Raise :class:`SceneError` at the start's speed (``start.omega``, ``start.rpm``, or a clutch's driving half's)
    where it is more than :data:`FASTEST_START_OVER_MEAN` times the machine's ``mean`` speed (rad/s, ``mean_key``'s),
    asking whether rev/min were typed for rad/s where it reads as a motor's speed."""
    start = motion.start
    for key, omega in zip(motion.start_keys, (start.omega, start.driving_omega), strict=True):
        if omega is None or omega <= FASTEST_START_OVER_MEAN * mean:
            continue
        where = f"{motion.where}.start.{key}"
        in_rpm = not key.endswith("omega")
        given = f"{omega / RPM:.4g} rpm ({omega:.4g} rad/s)" if in_rpm else f"{omega:.4g} rad/s"
        typed = (f"; {rpm_question(where, omega, where.removesuffix('omega') + 'rpm')}"
                 if not in_rpm and motor_speed_in_rpm(omega) else "")
        value = float(f"{omega / RPM:.12g}") if in_rpm else omega
        raise SceneError(where, f"{given} is {omega / mean:.3g} times the machine's mean speed, {mean:.4g} rad/s "
                         f"({mean_key}): a run starts from rest or runs down from about its speed, and one from more "
                         f"than {FASTEST_START_OVER_MEAN:g} times it is no machine's", value, hint=typed)


def _read_diagram_dynamics(table: Table, spec: DynamicsSpec) -> DynamicsSpec:
    """The rest of a ``[dynamics]`` table without a linkage: its load diagrams and the machine's inertia."""
    if table.has("constant"):
        raise SceneError(table.where("constant"), 'is for a linkage\'s reduced moments; with a load diagram the side '
                         'not given is constant (write driving = "constant" or resisting = "constant")')
    if spec.omega is None:
        table.misspelt("omega", "rpm")
        raise SceneError(table.where("omega"), "is required but missing: give omega (rad/s) or rpm (rev/min), the "
                         "mean speed of the shaft the load diagram is drawn over (there is no driver to take it from)")
    diagrams: dict[str, LoadDiagram] = {}
    for key in DIAGRAM_KEYS:
        if table.has(key):
            side, quantity = key.split("_")
            if side in diagrams:
                raise SceneError(table.where(key), f"give {side}_torque or {side}_power, not both")
            diagrams[side] = _read_load_diagram(table, key, side, quantity)
    if not diagrams:
        raise SceneError(table.path, "needs a load diagram (resisting_torque, resisting_power, driving_torque or "
                         "driving_power), or a linkage ([frame] and [driver]) to reduce the loads from")
    for side in _SIDES:
        if table.has(side):
            table.choice(side, ("constant",))
            if side in diagrams:
                raise SceneError(table.where(side), f'says the {side} side is constant, but {diagrams[side].key} '
                                 "gives its diagram: leave one out")
    inertia = table.number("inertia", 0.0, non_negative=True)
    motion = _read_diagram_motion(table, diagrams, inertia, spec.delta)
    if motion is not None:
        _refuse_start_over_mean(motion, spec.omega, table.where(spec.speed_key))
    _done(table)
    omega = spec.omega
    if len(diagrams) == 2:
        constant = "none"
        driven, resisted = diagrams["driving"].work(omega), diagrams["resisting"].work(omega)
        if not abs(driven - resisted) <= _BALANCE * max(abs(driven), abs(resisted)):
            raise SceneError(table.path, f"the driving work ({driven:.6g} J) and the resisting work ({resisted:.6g} J) "
                             "over the turn differ, so the motion is not periodic: give one side only (it is then "
                             "taken constant) or make them balance")
    else:
        (side, given), = diagrams.items()
        constant = "driving" if side == "resisting" else "resisting"
        if not given.work(omega) > 0:
            raise SceneError(table.where(given.key), f"does {given.work(omega):.6g} J of work over the turn: a "
                             f"{side} load must do positive work for a constant {constant} one to balance it")
    ordered = tuple(diagrams[side] for side in _SIDES if side in diagrams)
    return dataclasses.replace(spec, constant=constant, diagrams=ordered, inertia=inertia, motion=motion)


def _read_diagram_motion(table: Table, diagrams: dict[str, LoadDiagram], inertia: float, delta: float | None):
    """The equation of motion of a machine known by its load diagrams, or None when the table asks for none.

    The motor takes the place of the constant driving side, so the resistance must be a diagram;
    the shaft's inertia is the machine's own ``inertia`` and the flywheel sized for ``delta``.
    """
    if not any(table.has(key) for key in MOTION_KEYS):
        return None
    from .machine_motion import read_motion

    motion = read_motion(table, table.path)
    if "resisting" not in diagrams:
        raise SceneError(table.where("motor"), "drives the machine in place of its driving side, so the resistance "
                         "must be a diagram: give resisting_torque or resisting_power")
    if inertia == 0 and delta is None:
        raise SceneError(table.where("inertia"), "the equation of motion needs the machine's inertia: give inertia "
                         "(kg·m², the machine's own, > 0) or delta (a flywheel sized for it)")
    return motion


def _read_load_diagram(table: Table, key: str, side: str, quantity: str) -> LoadDiagram:
    """[crank angle in degrees, value] pairs from 0 to 360, the angles never falling; a jump gives one twice."""
    where = table.where(key)
    points = [check_xy(item, at) for at, item in table.items(key)]
    if len(points) < 2:
        raise SceneError(where, "must have at least two points [crank angle in degrees, value]")
    angles = [angle for angle, _ in points]
    # The order first: two points typed the wrong way round leave the ends misread, and the turn's ends told of
    # them would send the student to the first and last points, which are right.
    for k in range(1, len(angles)):
        if angles[k] < angles[k - 1]:
            raise SceneError(f"{where}[{k}]", "crank angles must not fall (an angle given twice is a jump)", angles[k])
        if k >= 2 and angles[k] == angles[k - 1] == angles[k - 2]:
            raise SceneError(f"{where}[{k}]", "an angle may be given at most twice (the two sides of a jump)",
                             angles[k])
    if angles[0] != 0.0 or angles[-1] != 360.0:
        # A turn that ends at 2π, as rounded to a few digits, is the diagram typed in radians.
        radians = math.isclose(angles[-1], 2 * math.pi, rel_tol=1e-3)
        hint = (f"; radians? {angles[-1]:g} rad is 360°: the diagram's crank angles are in degrees (multiply them "
                "by 180/π)") if radians else ""
        raise SceneError(where, "must run over the whole turn: its angles from 0 to 360 degrees",
                         [angles[0], angles[-1]], hint=hint)
    if side == "resisting":
        # The resisting side is turned against the shaft as it stands, so a negative value would drive it; a [[loads]]
        # resisting diagram is refused for the same sign.  A driving diagram may go negative (an engine's compression).
        for k, ((_, value), (_, item)) in enumerate(zip(points, table.items(key), strict=True)):
            if value < 0:
                raise SceneError(f"{where}[{k}]", "must be >= 0: a resisting diagram gives what the resistance takes",
                                 item[1], hint="; a load that helps the shaft over part of the turn drives it: a "
                                 "driving diagram (driving_torque or driving_power) may go negative, a resisting one "
                                 "may not")
    return LoadDiagram(key=key, side=side, quantity=quantity, angles_deg=tuple(angles),
                       values=tuple(value for _, value in points))


def diagram_model_of(spec: DynamicsSpec) -> EquivalentModel:
    """The equivalent model of a ``[dynamics]`` table without a linkage: its load diagrams at the mean speed."""
    if not spec.diagrams or spec.omega is None:
        raise ValueError("the [dynamics] table gives no load diagram and mean speed: its model needs a linkage")
    sides: dict[str, Any] = {side: None for side in _SIDES}
    for diagram in spec.diagrams:
        sides[diagram.side] = (np.radians(diagram.angles_deg), diagram.torques(spec.omega))
    return diagram_model(spec.omega, sides["driving"], sides["resisting"], inertia=spec.inertia, count=spec.count)


def unusual_speed_swing(delta: float | None) -> float | None:
    """ωmax/ωmin = (2 + δ)/(2 − δ), how far the speed swings over the turn, where δ is above
    :data:`LARGEST_USUAL_DELTA` (the warning's and the note's caution); None where δ is a usual one or not given."""
    if delta is None or delta <= LARGEST_USUAL_DELTA:
        return None
    return (2 + delta) / (2 - delta)


def delta_warning(spec: DynamicsSpec) -> str | None:
    """A line for the command line where ``delta`` is above :data:`LARGEST_USUAL_DELTA`, else None."""
    delta = spec.delta
    ratio = unusual_speed_swing(delta)
    if ratio is None:
        return None
    return (f"{spec.where}.delta: {delta:g} is above the {LARGEST_USUAL_DELTA:g} of the most unevenly running "
            f"machines (crushers, punches): the speed swings ωmax/ωmin = (2 + δ)/(2 − δ) = {ratio:.3g} over the turn; "
            f"{percentage_question(delta, 'δ')}")


def rpm_typed_speeds(spec: DynamicsSpec) -> list[tuple[str, str, float]]:
    """Each speed of the table given in rad/s that reads as a motor's speed in rev/min
    (:func:`~graphplan.units.motor_speed_in_rpm`), as (what it is: ``mean``, ``start`` or ``driving``, its key
    path, its value): the mean ``omega``, and a run's ``start.omega`` and ``start.driving_omega``, which a student
    types off the same nameplate."""
    where = spec.where
    speeds = [("mean", f"{where}.omega", spec.omega)]
    start = getattr(spec.motion, "start", None)
    if start is not None:
        speeds += [("start", f"{where}.start.omega", start.omega),
                   ("driving", f"{where}.start.driving_omega", start.driving_omega)]
    return [(role, key, omega) for role, key, omega in speeds if omega is not None and motor_speed_in_rpm(omega)]


def speed_warnings(spec: DynamicsSpec) -> list[str]:
    """A line for the command line for each of :func:`rpm_typed_speeds`, with the rpm key to write instead."""
    return [rpm_question(key, omega, key.removesuffix("omega") + "rpm") for _, key, omega in rpm_typed_speeds(spec)]


#: How near (relative) the [dynamics] mean speed must come to the crank's speed in the other unit to be told as it:
#: a student rounds 25.1327 rad/s to 25.13, 25.1 or 25; a flywheel sized at 9.55 times the crank's speed, or at
#: its 9.55th part, within that, is no machine's design.
UNIT_SLIP_TOLERANCE = 0.02


@dataclass(frozen=True)
class SpeedUnitSlip:
    """``[dynamics]``' mean speed typed as the crank's own in the other unit: ``key`` (``rpm`` or ``omega``) is
    given ``typed``, the number the crank's speed has in the unit of the other key; ``crank_omega`` (rad/s) and
    ``crank_rpm`` are the driver's speed; the flywheel is sized at ``sized`` rad/s instead."""

    where: str
    key: str
    typed: float
    crank_omega: float
    crank_rpm: float
    sized: float

    @property
    def meant_key(self) -> str:
        return "omega" if self.key == "rpm" else "rpm"

    @property
    def ratio(self) -> float:
        """How many times faster (above 1) or slower (below 1) than the crank the flywheel is sized at."""
        return self.sized / self.crank_omega

    @property
    def times_off(self) -> float:
        """How many times off the crank's speed the flywheel is sized at, faster or slower (1 or more)."""
        return max(self.ratio, 1 / self.ratio)


def crank_omega(driver) -> float | None:
    """The driver's ω (rad/s) where it is a crank, which a ``[dynamics]`` mean speed or a motor through its gear is
    compared with; None for a slider driver or no driver."""
    return driver.omega if driver is not None and driver.kind == "crank" else None


def speed_unit_slip(spec: DynamicsSpec, crank_omega: float | None) -> SpeedUnitSlip | None:
    """The ``[dynamics]`` mean speed where it is the crank's speed ``crank_omega`` (rad/s, the driver's; None
    without a crank that turns round) as a number in the other unit, within :data:`UNIT_SLIP_TOLERANCE`:
    ``rpm = 25.13`` beside a crank of 25.13 rad/s (240 rev/min), or ``omega = 240`` beside one of 240 rev/min.
    The flywheel is then sized at a tenth of the crank's speed or ten times it, J_F some 91 times too large or too
    small, without another word: a motor's run, where there is one, only finds the speed off."""
    if spec.speed_key is None or spec.omega is None or not crank_omega:
        return None
    crank = abs(crank_omega)
    typed = spec.omega / RPM if spec.speed_key == "rpm" else spec.omega
    other = crank if spec.speed_key == "rpm" else crank / RPM  # the crank's speed in the unit of the other key
    if not abs(typed / other - 1.0) <= UNIT_SLIP_TOLERANCE:
        return None
    return SpeedUnitSlip(where=spec.where, key=spec.speed_key, typed=typed, crank_omega=crank, crank_rpm=crank / RPM,
                         sized=spec.omega)


def speed_unit_warning(spec: DynamicsSpec, crank_omega: float | None) -> str | None:
    """The command line's line for :func:`speed_unit_slip`, or None."""
    slip = speed_unit_slip(spec, crank_omega)
    if slip is None:
        return None
    from .render.numerals import number

    given, meant = ("rev/min", "rad/s") if slip.key == "rpm" else ("rad/s", "rev/min")
    # The note's digits (its caution says the same): 25.13 rad/s here beside the note's 25.133 read as two speeds.
    pace = f"{number(slip.times_off, 3)} times {'slower' if slip.ratio < 1 else 'faster'}"
    size = "large" if slip.ratio < 1 else "small"
    # The typed value as the scene has it (to six digits), a key's own number.
    # A motor whose gear brings it to the crank's speed bears the reading out (and the gear is weighed against the
    # crank's speed, gear_mismatch, not against the one typed).
    motor = getattr(spec.motion, "motor", None)
    own = _motor_own_speed(motor)
    fits = (f"; the motor's {own[1]} speed through {slip.where}.motor.gear_ratio = {motor.gear_ratio:g} turns the "
            f"shaft at {number(own[0] / motor.gear_ratio / RPM)} rpm, near the crank's {number(slip.crank_rpm)}"
            if own is not None and gear_mismatch(spec, crank_omega) is None else "")
    return (f"{slip.where}.{slip.key} = {slip.typed:g} {given} is the crank's speed in {meant} (driver: "
            f"{number(slip.crank_omega)} rad/s, {number(slip.crank_rpm)} rpm): typed in the wrong unit? The flywheel is "
            f"sized at {number(slip.sized)} rad/s, {pace} than the crank turns, and J_F comes out some "
            f"{slip.times_off ** 2:.0f} times too {size}: write {slip.where}.{slip.meant_key} = "
            f"{slip.typed:g}, or leave the speed out for the driver's{fits}")


#: How far (a factor either way) the motor's speed through its gear may lie from the machine's mean speed before
#: it is told: a Kloss motor runs a few per cent of slip below its rated speed, a linear one below its no-load speed
#: by its load, never by half; a gear_ratio left out (1) or turned round is off by the whole ratio.
GEAR_MISMATCH = 1.5


@dataclass(frozen=True)
class GearMismatch:
    """``[dynamics]``' motor whose ``speed`` (its ``what``: rated or no-load, rad/s) through its ``gear_ratio`` turns
    the driving shaft ``at_shaft`` (rad/s), far (:data:`GEAR_MISMATCH`) from the machine's ``mean`` speed."""

    where: str
    gear_ratio: float
    what: str
    speed: float
    at_shaft: float
    mean: float
    # The mean speed is the crank's, where [dynamics]' own was typed in the other unit (speed_unit_slip): a ratio
    # fitted to the mistyped speed would be advised for a machine that does not run at it.
    against_crank: bool = False

    @property
    def fitting_ratio(self) -> float:
        """The gear ratio that brings the motor's speed to the machine's: ω_motor/ω_shaft."""
        return self.speed / self.mean

    @property
    def too_large(self) -> bool:
        """Whether the ratio turns the shaft too slowly: a larger one, which a stall would call for, slows it more."""
        return self.at_shaft < self.mean


def gear_mismatch(spec: DynamicsSpec, crank_omega: float | None) -> GearMismatch | None:
    """Where ``[dynamics]``' motor, through its ``gear_ratio``, would turn the driving shaft at a speed far
    (:data:`GEAR_MISMATCH`) from the machine's mean speed (``rpm`` or ``omega``, else the crank's ``crank_omega``);
    None where it fits, or the motor has no speed of its own (a constant torque)."""
    from .machine_motion import KlossMotor

    motor = getattr(spec.motion, "motor", None)
    # A mean speed typed in the other unit is told on its own line: the gear is weighed against the crank's.
    against_crank = speed_unit_slip(spec, crank_omega) is not None
    mean = _mean_speed(spec, crank_omega, against_crank)
    own = _motor_own_speed(motor)
    if mean is None or own is None:
        return None
    speed, what = own
    at_shaft = speed / motor.gear_ratio
    # A linear motor loaded to half its stall torque runs at half its no-load speed: told only well above that.
    most = GEAR_MISMATCH if isinstance(motor, KlossMotor) else 2 * GEAR_MISMATCH
    if 1.0 / GEAR_MISMATCH <= at_shaft / mean <= most:
        return None
    return GearMismatch(where=spec.where, gear_ratio=motor.gear_ratio, what=what, speed=speed, at_shaft=at_shaft,
                        mean=mean, against_crank=against_crank)


def _mean_speed(spec: DynamicsSpec, crank_omega: float | None, against_crank: bool | None = None) -> float | None:
    """The machine's mean speed a motor is weighed against (rad/s): ``[dynamics]``' ``rpm`` or ``omega``, else the
    crank's ``crank_omega``; None with neither.  ``against_crank``: whether that mean speed reads as the crank's in
    the other unit (:func:`speed_unit_slip`), worked out here where not given."""
    # A mean speed typed in the other unit is told on its own line: the motor is weighed against the crank's.
    if against_crank is None:
        against_crank = speed_unit_slip(spec, crank_omega) is not None
    return spec.omega if spec.omega is not None and not against_crank else abs(crank_omega) if crank_omega else None


def _motor_own_speed(motor) -> tuple[float, str] | None:
    """A motor's own speed (rad/s, on its shaft) and what it is, its rated or no-load speed; None for a motor of no
    speed of its own (a constant torque) or none."""
    from .machine_motion import KlossMotor, LinearMotor

    if isinstance(motor, KlossMotor):
        return motor.synchronous_speed * (1.0 - motor.rated_slip), "rated"
    if isinstance(motor, LinearMotor):
        return motor.no_load, "no-load"
    return None


def gear_warning(spec: DynamicsSpec, crank_omega: float | None) -> str | None:
    """The command line's line for :func:`gear_mismatch`, with the gear ratio that fits, or None.  A motor of 955 rpm
    with the gear_ratio left out stalls the machine, or runs it four times too fast, and the stall's advice (a
    stronger motor) leads astray."""
    found = gear_mismatch(spec, crank_omega)
    if found is None:
        return None
    from .render.numerals import number

    left_out = found.gear_ratio == 1.0 and not getattr(spec.motion, "gear_ratio_given", False)
    unset = " (the default where it is left out)" if left_out else ""
    runs = (f"the crank turns at (not the {spec.where}.{spec.speed_key} typed in the other unit, told above)"
            if found.against_crank else "the machine runs at")
    # The motor's speed and the machine's as the note writes them (1455.5 rpm, not 1456); the shaft's speed in rpm
    # and the ratios the note does not write.
    return (f"{found.where}.motor.gear_ratio = {found.gear_ratio:g}{unset}: the motor's {found.what} speed, "
            f"{number(found.speed / RPM)} rpm, turns the driving shaft at {found.at_shaft / RPM:.4g} rpm through it, "
            f"{found.at_shaft / found.mean:.3g} times the {number(found.mean / RPM)} rpm {runs}; "
            f"gear_ratio is ω_motor/ω_shaft, here {found.fitting_ratio:.3g} (or a motor of another speed)")


@dataclass(frozen=True)
class OddSynchronousSpeed:
    """``[dynamics]``' Kloss motor given a ``synchronous_rpm`` (``typed``) that no 50 or 60 Hz motor has, 60·f/p:
    ``nearest`` is the one nearest it.  ``rated_typed``: it lies a nameplate's slip below that one (1450 under 1500),
    a rated speed typed for the synchronous one.  ``motor`` is the motor as given and ``corrected`` the one with the
    nearest synchronous speed and its other key kept as typed (rated_rpm or rated_slip), None where the rated speed
    typed is not below it."""

    where: str
    typed: float
    nearest: float
    motor: Any
    corrected: Any

    @property
    def rated_typed(self) -> bool:
        return (1.0 - MOST_MOTOR_SLIP) * self.nearest <= self.typed < self.nearest

    def torques_at_rest(self) -> tuple[float, float] | None:
        """The motor's torque at rest on the driving shaft (N·m), as given and with the nearest synchronous speed,
        where the nearest gives it more (the slip typed too small, sk with it); None where it does not."""
        if self.corrected is None:
            return None
        given, corrected = (motor.gear_ratio * motor.characteristic(0.0) for motor in (self.motor, self.corrected))
        return (given, corrected) if corrected > given else None


def odd_synchronous_speed(spec: DynamicsSpec) -> OddSynchronousSpeed | None:
    """Where ``[dynamics]``' Kloss motor is given a ``synchronous_rpm`` that is no synchronous speed 60·f/p of a 50 or
    60 Hz motor (:func:`~graphplan.units.nearest_synchronous_rpm`): a rated 1450 typed for the synchronous 1500 gives
    the motor a slip, and so a starting torque, far too small, and the stall that follows was advised a stronger
    motor.  None where it is one, or the scene gave the motor no synchronous_rpm."""
    from .machine_motion import KlossMotor

    motion = spec.motion
    motor = getattr(motion, "motor", None)
    if not isinstance(motor, KlossMotor) or "synchronous_rpm" not in motion.kloss_keys:
        return None
    typed = motor.synchronous_speed / RPM
    nearest = nearest_synchronous_rpm(typed)
    if nearest is None:
        return None
    synchronous = nearest * RPM
    drive = {"gear_ratio": motor.gear_ratio, "rotor_inertia": motor.rotor_inertia}
    if "rated_slip" in motion.kloss_keys:
        corrected = KlossMotor(motor.power, synchronous, motor.rated_slip, motor.overload, **drive)
    elif motor.rated_speed < synchronous:
        corrected = KlossMotor(motor.power, synchronous, 1.0 - motor.rated_speed / synchronous, motor.overload,
                               **drive)
    else:
        corrected = None
    return OddSynchronousSpeed(where=spec.where, typed=typed, nearest=nearest, motor=motor, corrected=corrected)


def synchronous_warning(spec: DynamicsSpec) -> str | None:
    """The command line's line for :func:`odd_synchronous_speed`, naming the nearest synchronous speed, or None."""
    odd = odd_synchronous_speed(spec)
    if odd is None:
        return None
    from .render.numerals import number

    typed, nearest = number(odd.typed), number(odd.nearest)
    # The typed value as the note writes it: 1450, not the 1450.0 a float's repr gives.
    asked = f"; {nearest} with a rated {typed}? " if odd.rated_typed else f"; the nearest is {nearest}: "
    return (f"{odd.where}.motor.synchronous_rpm = {typed} is no synchronous speed of a 50 or 60 Hz motor (60·f/p)"
            f"{asked}Kloss' slip, s = 1 − ω/ωs, and the motor's whole characteristic are reckoned from it")


# A motor runs its own rotor up to speed at its own torque in some milliseconds (a servo) to a few seconds (a large
# induction motor, whose inertia constant H = J·ω²/2P stays under some 1.5 s): t = J·ω/M, 0.11 s for the flywheel
# starter's 4 kW motor.  A rotor_inertia that takes over SLOWEST_OWN_RUN_UP_S is one typed in kg·cm² (10 000 times
# the kg·m², the servo catalogues' unit: 1100 s for that motor), or the motor's torque is a thousandth of its own,
# its power typed in kilowatts; within the bounds either way, so it is asked, not refused.
SLOWEST_OWN_RUN_UP_S = 60.0


def rotor_inertia_warning(spec: DynamicsSpec, kilowatts_asked: bool = False,
                          crank_omega: float | None = None) -> str | None:
    """The command line's line where ``[dynamics]``' motor would take more than :data:`SLOWEST_OWN_RUN_UP_S` to run
    its own rotor up to its speed at its own torque (a Kloss motor's rated ones, a linear one's no-load speed and
    stall torque, a constant one's torque and the machine's mean speed, ``rpm`` or ``omega`` else ``crank_omega``,
    through its gear: J·ω/M): the rotor's inertia typed in kg·cm²; None for a motor with no rotor given, a constant
    one of no torque or with no mean speed to go by, or one that runs it up in time.  A Kloss motor under 1000 W
    that would run it up in time at a thousand times its power may have its power in kilowatts instead: where the
    stall's line asks that (``kilowatts_asked``) nothing is said here; elsewhere both are asked (a 750 W motor is as
    likely as a 750 kW one typed 750, and a machine it starts tells no stall)."""
    from .machine_motion import ConstantTorque, KlossMotor, LinearMotor

    motor = getattr(spec.motion, "motor", None)
    if isinstance(motor, KlossMotor):
        speed, torque, named = motor.rated_speed, motor.rated_torque, "J·ωN/MN"
    elif isinstance(motor, LinearMotor):
        speed, torque, named = motor.no_load, motor.stall_torque, "J·ω0/M0"
    elif isinstance(motor, ConstantTorque) and motor.torque and (mean := _mean_speed(spec, crank_omega)):
        # A constant torque has no speed of its own: the rotor runs at the machine's, through the gear.
        speed, torque, named = mean * motor.gear_ratio, abs(motor.torque), "J·u·ωm/M"
    else:
        return None
    inertia = motor.rotor_inertia
    seconds = inertia * speed / torque
    if not seconds > SLOWEST_OWN_RUN_UP_S:
        return None
    # A Kloss motor's power in kilowatts (4 for 4000 W) makes its torque a thousandth and the time a thousandfold.
    in_kilowatts = isinstance(motor, KlossMotor) and motor.power < 1000 and seconds / 1000 <= SLOWEST_OWN_RUN_UP_S
    if in_kilowatts and kilowatts_asked:
        return None
    from .render.numerals import number

    key = f"{spec.where}.motor"
    power = (f"; or {key}.power = {number(motor.power)} W typed in kilowatts? ({number(motor.power)} kW is "
             f"{key}.power = {number(motor.power * 1000)})" if in_kilowatts else "")
    return (f"{key}.rotor_inertia = {number(inertia)} kg·m² takes the motor {number(seconds, 4)} s to run its own "
            f"rotor up at its own torque ({named} = {number(inertia)}·{number(speed, 4)}/{number(torque, 4)}), "
            f"where a motor's takes some milliseconds to a few seconds: kg·cm² typed for kg·m²? ({number(inertia)} "
            f"kg·cm² is {key}.rotor_inertia = {number(inertia / 10_000)}){power}")


def flywheel_from_spec(model: EquivalentModel, spec: DynamicsSpec) -> Flywheel | None:
    """The flywheel the scene's ``[dynamics]`` asks for, or None when it gives no δ."""
    if spec.delta is None:
        return None
    return flywheel_for(model, spec.delta, spec.omega, shaft_rpm=spec.flywheel_shaft_rpm)


# --- results ------------------------------------------------------------------------------------


def dynamics_results(model: EquivalentModel, flywheel: Flywheel | None = None) -> dict[str, Any]:
    """The dynamics part of ``results.json``: SI, angles in degrees, unrounded (the writer rounds).

    ``driving_loads`` and ``resisting_loads``: the scene's loads on each side by their key paths, sorted by their
    work over the run (:mod:`graphplan.dynamics`).  Per sample of the cycle: ``angle_deg`` (the driver's coordinate: crank angle in degrees, or
    displacement in m under ``displacement``), ``travel`` (ψ), ``reduced_inertia``,
    ``reduced_inertia_slope``, ``reduced_moment`` (= ``driving_moment`` + ``resisting_moment``),
    ``driving_work``, ``resisting_work``, ``kinetic_energy_change``; then the flywheel.
    """
    turning = model.turning
    found: dict[str, Any] = {
        "equivalent_link": "turning" if turning else "translating",
        "driver_link": model.link or None,  # a model made from load diagrams has no link
        "constant": model.constant,
        "driving_loads": list(model.driving_loads),
        "resisting_loads": list(model.resisting_loads),
    }
    if turning:
        found["angle_deg"] = _numbers(np.degrees(model.driver) % 360.0)
    else:
        found["displacement"] = _numbers(model.driver)
    found.update({
        "travel": _numbers(model.coordinate),
        "reduced_inertia": _numbers(model.inertia),
        "reduced_inertia_slope": _numbers(model.inertia_slope),
        "reduced_moment": _numbers(model.moment),
        "driving_moment": _numbers(model.driving),
        "resisting_moment": _numbers(model.resisting),
        "driving_work": _numbers(model.driving_work),
        "resisting_work": _numbers(model.resisting_work),
        "kinetic_energy_change": _numbers(model.energy),
        "delta_w_max": float(np.ptp(model.energy)),
        "plans": [{"index": plan.number, "reduced_inertia": float(plan.inertia),
                   "reduced_inertia_exact": float(plan.inertia_exact),
                   "reduced_inertia_error_percent": float(plan.inertia_error_percent),
                   "reduced_moment": float(plan.moment), "reduced_moment_exact": float(plan.moment_exact),
                   "reduced_moment_error_percent": float(plan.moment_error_percent)} for plan in model.plans],
    })
    if flywheel is not None:
        found.update({
            "delta": float(flywheel.delta),
            "omega_mean": float(flywheel.omega_mean),
            "flywheel_inertia": float(flywheel.inertia),
            "flywheel_inertia_required": float(flywheel.required),
            "delta_reached": float(flywheel.reached),
            "flywheel_inertia_approximate": float(flywheel.approximate),
            "flywheel_inertia_mertsalov": float(flywheel.mertsalov),
            "constant_reduced_inertia": float(flywheel.constant_inertia),
            "kinetic_energy_start": float(flywheel.kinetic_energy_start),
            "omega": _numbers(flywheel.omega),
            "omega_max": float(flywheel.omega_max),
            "omega_min": float(flywheel.omega_min),
            "omega_max_angle_deg": float(math.degrees(model.driver[flywheel.index_max]) % 360.0),
            "omega_min_angle_deg": float(math.degrees(model.driver[flywheel.index_min]) % 360.0),
            "omega_max_travel_deg": float(math.degrees(model.coordinate[flywheel.index_max])),
            "omega_min_travel_deg": float(math.degrees(model.coordinate[flywheel.index_min])),
            "flywheel_shaft_rpm": None if flywheel.shaft_rpm is None else float(flywheel.shaft_rpm),
            "flywheel_inertia_moved": None if flywheel.moved is None else float(flywheel.moved),
        })
    return found


def _numbers(values: np.ndarray) -> list[float]:
    return [float(v) for v in values]


# --- checks -------------------------------------------------------------------------------------


def _check_speed(omega_mean: float, delta: float) -> None:
    if not (isinstance(omega_mean, (int, float)) and math.isfinite(omega_mean) and omega_mean > 0):
        raise ValueError(f"omega_mean must be a positive number (rad/s), not {omega_mean!r}")
    if not (isinstance(delta, (int, float)) and 0 < delta < 2):
        raise ValueError(f"delta must lie between 0 and 2 (ωmin = ωm·(1 − δ/2) > 0), not {delta!r}")


def _vector(name: str, values: ArrayLike, size: int | None = None) -> np.ndarray:
    try:
        array = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a sequence of numbers") from None
    if array.ndim != 1 or not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be a 1-D sequence of finite numbers")
    if size is not None and len(array) != size:
        raise ValueError(f"{name} must have {size} values, not {len(array)}")
    return array


def _with_zeros(x: np.ndarray, net: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The piecewise-linear ``net`` with its zeros between vertices put in (the surplus turns there)."""
    crossing = np.flatnonzero(net[:-1] * net[1:] < 0)
    if len(crossing) == 0:
        return x, net
    share = net[crossing] / (net[crossing] - net[crossing + 1])
    zeros = x[crossing] + share * (x[crossing + 1] - x[crossing])
    order = np.argsort(np.concatenate([x, zeros]), kind="stable")
    return np.concatenate([x, zeros])[order], np.concatenate([net, np.zeros(len(zeros))])[order]


__all__ = [
    "DIAGRAM_KEYS",
    "GEAR_MISMATCH",
    "LARGEST_USUAL_DELTA",
    "MOTION_KEYS",
    "UNIT_SLIP_TOLERANCE",
    "DynamicsSpec",
    "Fluctuation",
    "Flywheel",
    "GearMismatch",
    "LoadDiagram",
    "OddSynchronousSpeed",
    "SpeedUnitSlip",
    "Tangent",
    "crank_omega",
    "delta_warning",
    "diagram_model_of",
    "dynamics_results",
    "fluctuation",
    "fluctuation_from_areas",
    "flywheel_for",
    "flywheel_from_spec",
    "flywheel_inertia",
    "gear_mismatch",
    "gear_warning",
    "misplaced_keys",
    "moved_inertia",
    "odd_synchronous_speed",
    "omega_to_rpm",
    "read_dynamics",
    "rpm_to_omega",
    "rpm_typed_speeds",
    "speed_fluctuation",
    "speed_limits",
    "speed_unit_slip",
    "speed_unit_warning",
    "speed_warnings",
    "synchronous_warning",
    "unusual_speed_swing",
]
