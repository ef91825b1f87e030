"""The machine's motion in time: its equation of motion reduced to the driving shaft, integrated.

The machine is reduced to its driving shaft (the dynamic model of a course in the theory of
machines): a reduced moment of inertia ``Je(φ)`` and the reduced moments of the forces.  Its
equation of motion in the differential form is

    Je(φ)·dω/dt + ½·(dJe/dφ)·ω² = Md(ω) − Mr(φ, ω) − Mb(ω)

with ``Md`` the motor's torque on the shaft, ``Mr`` the reduced moment of the resisting forces
(positive when it resists forward motion; a driving force reduced to the shaft enters with a
minus sign) and ``Mb`` a brake.  As a first-order system in ``(φ, ω)`` it is integrated with
:func:`scipy.integrate.solve_ivp`.

* :class:`Machine` takes ``Je``, ``dJe/dφ`` and ``Mr`` as numbers, callables or periodic samples
  on an equally spaced grid over one turn ``[0, 2π)``, interpolated by a periodic quintic spline
  (:func:`scipy.interpolate.make_interp_spline`).
* Motors: :class:`ConstantTorque`, :class:`LinearMotor` (``Md = M0·(1 − ω/ω0)``) and
  :class:`KlossMotor` (an induction motor by Kloss' formula), each with a gear ratio
  ``u = ω_motor/ω_shaft`` and the rotor's inertia, reduced to the shaft as ``J·u²``.
* :class:`Brake`: a constant and a speed-proportional braking torque switched on at a time.
* :class:`Clutch`: a friction clutch between the driving half (the motor's rotor and what turns
  with it) and the machine; it slips with a constant torque until the speeds are equal, then
  locks (solve_ivp events find both instants) and slips again if the torque it must pass
  exceeds its capacity.
* :func:`simulate` integrates a start-up from rest (or from a given state), the steady state
  (found when the cycle's mean speed and its coefficient of speed fluctuation δ stop changing)
  and a run-down, and returns the time histories with each cycle's ``ωm``, ``ωmax``, ``ωmin``
  and ``δ``.
* :func:`read_motion` reads the motion's keys of the scene's ``[dynamics]`` table.

Conventions
-----------
SI units, angles in radians, speeds in rad/s (revolutions per minute only in the scene keys
named ``*_rpm``).  The driving shaft turns forward, ``ω ≥ 0``: at rest the resisting forces and
the brake are passive (they hold the machine but cannot turn it backwards).

δ is the textbook one, ``(ωmax − ωmin)/ωm`` with ``ωm = (ωmax + ωmin)/2``, for which the
flywheel relation ``ΔWmax = Je·ωm²·δ`` is exact at constant ``Je``; the time-averaged speed of a
cycle, ``2π/T``, is given as well.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike
from scipy.integrate import RK45, solve_ivp
from scipy.interpolate import BSpline, make_interp_spline
from scipy.optimize import brentq

from .errors import SceneError
from .reader import Table, check_number

TWO_PI = 2.0 * math.pi
#: rad/s in one revolution per minute.
RPM = TWO_PI / 60.0

METHODS = ("auto", "RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")
MOTOR_KINDS = ("constant", "linear", "kloss")

# Above this value of (largest decay rate |∂f/∂ω|) × (the step RK45 takes for accuracy) the explicit
# step would be held by stability instead: Dormand–Prince's RK45 is stable on the negative real
# axis up to h·|λ| ≈ 3.3.
STIFFNESS_THRESHOLD = 3.0
# The degree of the periodic spline through samples over a turn (see periodic_spline).
SPLINE_DEGREE = 5
# Samples per cycle when its extreme speeds are looked for (then refined by a parabola).
SAMPLES_PER_CYCLE = 256


# --- functions of the crank angle ------------------------------------------------------------


def periodic_spline(samples: ArrayLike, name: str = "samples") -> BSpline:
    """A periodic quintic spline through samples taken at ``φ = 2π·i/n``, ``i = 0 … n−1``.

    The spline repeats with period 2π; its ``derivative()`` is the slope over φ.  Quintic, not
    cubic: the equation of motion carries ``dJe/dφ``, and a cubic spline's slope is only once
    continuously differentiable, so the high-order solvers lose their order at every knot (in
    the energy test of ``tests/test_machine_motion.py`` a cubic spline through 72 samples let
    ``½·Je·ω²`` drift by 4e-7 at rtol 1e-10, the quintic one by 3e-10, as the exact function).
    """
    values = np.asarray(samples, dtype=float)
    if values.ndim != 1 or values.size < SPLINE_DEGREE + 1:
        raise ValueError(f"{name}: needs at least {SPLINE_DEGREE + 1} samples over one turn, equally spaced on "
                         f"[0, 2π) (got shape {values.shape})")
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        raise ValueError(f"{name}: must be finite, at index {bad[0]} (got {values[bad[0]]!r})")
    grid = np.linspace(0.0, TWO_PI, values.size + 1)
    spline = make_interp_spline(grid, np.append(values, values[0]), k=SPLINE_DEGREE, bc_type="periodic")
    spline.extrapolate = "periodic"
    return spline


def _angle_function(value: Any, name: str) -> tuple[Callable[[float], float], BSpline | None]:
    """A number, samples over one turn or a callable of φ, as a callable (and the spline, if any)."""
    if callable(value):
        return value, None
    array = np.asarray(value, dtype=float) if not isinstance(value, (str, bytes)) else None
    if array is None or array.dtype.kind not in "iuf":
        raise ValueError(f"{name}: must be a number, samples over one turn or a function of φ (got {value!r})")
    if array.ndim == 0:
        constant = float(array)
        if not math.isfinite(constant):
            raise ValueError(f"{name}: must be finite (got {constant!r})")
        return (lambda phi: constant), None
    spline = periodic_spline(array, name)
    return spline, spline


@dataclass(frozen=True, eq=False)
class Machine:
    """The machine reduced to its driving shaft.

    Parameters
    ----------
    inertia
        ``Je(φ)``, kg·m²: a number, samples over one turn ``[0, 2π)`` equally spaced, or a
        callable of φ.
    resisting
        ``Mr``, N·m, positive when it resists forward motion: a number, samples of ``Mr(φ)``
        over one turn, or a callable ``Mr(φ, ω)``.
    inertia_slope
        ``dJe/dφ``, kg·m²/rad: samples or a callable of φ.  Taken from the spline when
        ``inertia`` is samples, zero when it is a number; required when it is a callable.
    """

    inertia: Any
    resisting: Any = 0.0
    inertia_slope: Any = None
    _je: Callable[[float], float] = field(init=False, repr=False)
    _je_slope: Callable[[float], float] = field(init=False, repr=False)
    _mr: Callable[[float, float], float] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        je, spline = _angle_function(self.inertia, "inertia")
        if self.inertia_slope is not None:
            slope, _ = _angle_function(self.inertia_slope, "inertia_slope")
        elif spline is not None:
            slope = spline.derivative()
        elif not callable(self.inertia):
            slope = lambda phi: 0.0  # a constant Je has no slope
        else:
            raise ValueError("inertia_slope: is required when inertia is a function of φ "
                             "(give dJe/dφ as a function or as samples over one turn)")
        if callable(self.resisting):
            resisting = self.resisting
        else:
            of_angle, _ = _angle_function(self.resisting, "resisting")
            resisting = lambda phi, omega: of_angle(phi)
        object.__setattr__(self, "_je", je)
        object.__setattr__(self, "_je_slope", slope)
        object.__setattr__(self, "_mr", resisting)
        angles = np.linspace(0.0, TWO_PI, 721)
        values = np.array([float(je(a)) for a in angles])
        if not np.all(np.isfinite(values)) or values.min() <= 0:
            where = int(np.argmin(np.where(np.isfinite(values), values, -np.inf)))
            raise ValueError(f"inertia: must be > 0 over the whole turn (Je = {float(values[where]):g} kg·m² "
                             f"at φ = {math.degrees(angles[where]):.1f}°: the links have no mass that moves there)")

    def je(self, phi: float) -> float:
        """The reduced moment of inertia Je(φ), kg·m²."""
        return float(self._je(phi))

    def je_slope(self, phi: float) -> float:
        """dJe/dφ, kg·m²/rad."""
        return float(self._je_slope(phi))

    def mr(self, phi: float, omega: float) -> float:
        """The reduced moment of the resisting forces Mr(φ, ω), N·m."""
        return float(self._mr(phi, omega))


# --- motors, brake, clutch -----------------------------------------------------------------


def _require_positive(owner: str, name: str, value: float) -> None:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise ValueError(f"{owner}.{name}: must be a finite number > 0 (got {value!r})")


def _require_non_negative(owner: str, name: str, value: float) -> None:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
        raise ValueError(f"{owner}.{name}: must be a finite number >= 0 (got {value!r})")


class _Motor:
    """What every motor shares: the gear to the driving shaft and the rotor's inertia."""

    gear_ratio: float
    rotor_inertia: float

    def _check_drive(self) -> None:
        _require_positive(type(self).__name__, "gear_ratio", self.gear_ratio)
        _require_non_negative(type(self).__name__, "rotor_inertia", self.rotor_inertia)

    def characteristic(self, motor_speed: float) -> float:  # pragma: no cover - every motor has one
        """The torque on the motor's own shaft at its own speed, N·m."""
        raise NotImplementedError

    @property
    def no_load_speed(self) -> float | None:
        """The motor's speed at zero torque, rad/s; None for a constant torque."""
        return None

    def shaft_torque(self, shaft_speed: float) -> float:
        """The motor's torque reduced to the driving shaft, N·m: ``u·M(u·ω)`` (an ideal gear)."""
        u = self.gear_ratio
        return u * self.characteristic(u * shaft_speed)

    @property
    def reduced_inertia(self) -> float:
        """The rotor's inertia reduced to the driving shaft, ``J·u²``, kg·m²."""
        return self.rotor_inertia * self.gear_ratio ** 2

    @property
    def shaft_no_load_speed(self) -> float | None:
        """The driving shaft's speed at which the motor gives no torque, rad/s."""
        speed = self.no_load_speed
        return None if speed is None else speed / self.gear_ratio


@dataclass(frozen=True)
class ConstantTorque(_Motor):
    """A driving torque independent of speed, N·m on the motor's shaft."""

    torque: float
    gear_ratio: float = 1.0
    rotor_inertia: float = 0.0

    def __post_init__(self) -> None:
        if not (isinstance(self.torque, (int, float)) and math.isfinite(self.torque)):
            raise ValueError(f"ConstantTorque.torque: must be a finite number (got {self.torque!r})")
        self._check_drive()

    def characteristic(self, motor_speed: float) -> float:
        return float(self.torque)


@dataclass(frozen=True)
class LinearMotor(_Motor):
    """A straight characteristic ``M = M0·(1 − ω/ω0)``: stall torque M0, no-load speed ω0 (rad/s)."""

    stall_torque: float
    no_load: float
    gear_ratio: float = 1.0
    rotor_inertia: float = 0.0

    def __post_init__(self) -> None:
        _require_positive("LinearMotor", "stall_torque", self.stall_torque)
        _require_positive("LinearMotor", "no_load", self.no_load)
        self._check_drive()

    @classmethod
    def through(cls, first: tuple[float, float], second: tuple[float, float], **drive: float) -> LinearMotor:
        """The straight line through two points ``(speed rad/s, torque N·m)`` of the characteristic."""
        (w1, m1), (w2, m2) = first, second
        if w1 == w2:
            raise ValueError(f"LinearMotor.through: the two points need different speeds (got {w1!r} twice)")
        slope = (m2 - m1) / (w2 - w1)
        if not slope < 0:
            raise ValueError(f"LinearMotor.through: the torque must fall as the speed rises (slope {slope!r} N·m·s)")
        stall = m1 - slope * w1
        return cls(stall_torque=stall, no_load=-stall / slope, **drive)

    @property
    def no_load_speed(self) -> float:
        return self.no_load

    def characteristic(self, motor_speed: float) -> float:
        return self.stall_torque * (1.0 - motor_speed / self.no_load)


@dataclass(frozen=True)
class KlossMotor(_Motor):
    """An induction motor by Kloss' formula ``M = 2·Mmax/(s/sk + sk/s)``.

    Parameters
    ----------
    power
        Rated power, W.
    synchronous_speed
        ω_s, rad/s (``2π·n_s/60``).
    rated_slip
        s_n, the slip at the rated point.
    overload
        λ = Mmax/Mrated > 1.
    """

    power: float
    synchronous_speed: float
    rated_slip: float
    overload: float
    gear_ratio: float = 1.0
    rotor_inertia: float = 0.0

    def __post_init__(self) -> None:
        _require_positive("KlossMotor", "power", self.power)
        _require_positive("KlossMotor", "synchronous_speed", self.synchronous_speed)
        if not (isinstance(self.rated_slip, (int, float)) and 0 < self.rated_slip < 1):
            raise ValueError(f"KlossMotor.rated_slip: must be between 0 and 1 (got {self.rated_slip!r})")
        if not (isinstance(self.overload, (int, float)) and math.isfinite(self.overload) and self.overload > 1):
            raise ValueError(f"KlossMotor.overload: must be > 1, it is Mmax/Mrated (got {self.overload!r})")
        self._check_drive()

    @classmethod
    def from_rated_speed(cls, power: float, rated_speed: float, rated_slip: float, overload: float,
                         **drive: float) -> KlossMotor:
        """From the rated (not synchronous) speed, rad/s: ``ω_s = ω_n/(1 − s_n)``."""
        _require_positive("KlossMotor", "rated_speed", rated_speed)
        if not (isinstance(rated_slip, (int, float)) and 0 < rated_slip < 1):
            raise ValueError(f"KlossMotor.rated_slip: must be between 0 and 1 (got {rated_slip!r})")
        return cls(power, rated_speed / (1.0 - rated_slip), rated_slip, overload, **drive)

    @property
    def rated_speed(self) -> float:
        """ω_n = ω_s·(1 − s_n), rad/s."""
        return self.synchronous_speed * (1.0 - self.rated_slip)

    @property
    def rated_torque(self) -> float:
        """M_n = P/ω_n, N·m."""
        return self.power / self.rated_speed

    @property
    def max_torque(self) -> float:
        """Mmax = λ·M_n, N·m."""
        return self.overload * self.rated_torque

    @property
    def critical_slip(self) -> float:
        """s_k = s_n·(λ + √(λ² − 1)): the root of Kloss' formula through the rated point on the stable branch."""
        lam = self.overload
        return self.rated_slip * (lam + math.sqrt(lam * lam - 1.0))

    @property
    def no_load_speed(self) -> float:
        return self.synchronous_speed

    def characteristic(self, motor_speed: float) -> float:
        # 2·Mmax/(s/sk + sk/s) written so that it is finite at s = 0 (and negative above ω_s).
        s = 1.0 - motor_speed / self.synchronous_speed
        sk = self.critical_slip
        return 2.0 * self.max_torque * s * sk / (s * s + sk * sk)


Motor = ConstantTorque | LinearMotor | KlossMotor


@dataclass(frozen=True)
class Brake:
    """A braking torque on the driving shaft from time ``at`` on: ``torque + damping·ω``."""

    torque: float = 0.0
    damping: float = 0.0
    at: float = 0.0

    def __post_init__(self) -> None:
        _require_non_negative("Brake", "torque", self.torque)
        _require_non_negative("Brake", "damping", self.damping)
        if not (isinstance(self.at, (int, float)) and math.isfinite(self.at)):
            raise ValueError(f"Brake.at: must be a finite time (got {self.at!r})")
        if self.torque == 0 and self.damping == 0:
            raise ValueError("Brake: needs torque > 0 or damping > 0")


@dataclass(frozen=True)
class Clutch:
    """A friction clutch between the driving half and the machine's driving shaft.

    Parameters
    ----------
    torque
        The torque it passes while slipping (its capacity), N·m.
    engage_at
        When it is engaged, s; before that the machine is not driven.
    inertia
        The driving half's inertia besides the motor's rotor, reduced to the driving shaft, kg·m².
    """

    torque: float
    engage_at: float = 0.0
    inertia: float = 0.0

    def __post_init__(self) -> None:
        _require_positive("Clutch", "torque", self.torque)
        _require_non_negative("Clutch", "inertia", self.inertia)
        if not (isinstance(self.engage_at, (int, float)) and math.isfinite(self.engage_at)):
            raise ValueError(f"Clutch.engage_at: must be a finite time (got {self.engage_at!r})")


@dataclass(frozen=True)
class Start:
    """The state at the start: the shaft's angle (rad) and speed (rad/s), and with a clutch the
    driving half's speed reduced to the shaft (default: that of the shaft)."""

    omega: float = 0.0
    angle: float = 0.0
    driving_omega: float | None = None
    time: float = 0.0

    def __post_init__(self) -> None:
        _require_non_negative("Start", "omega", self.omega)
        if self.driving_omega is not None:
            _require_non_negative("Start", "driving_omega", self.driving_omega)
        for name in ("angle", "time"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value)):
                raise ValueError(f"Start.{name}: must be a finite number (got {value!r})")


REST = Start()


# --- results ---------------------------------------------------------------------------------


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


@dataclass(frozen=True, eq=False)
class MachineMotion:
    """The integrated motion.

    ``t``, ``phi``, ``omega`` are at the solver's steps (a step is repeated where the state jumps,
    as when the clutch locks); :meth:`state_at` interpolates between them.  ``driving_omega`` is
    the clutch's driving half (None without a clutch), ``motor_torque`` the motor's torque on the
    shaft at the steps, ``slip_energy`` the work lost in the clutch (J).  ``stopped_at`` is when the
    machine came to rest for good, and ``stalled_at`` the same time when the motor was still on: it
    could not carry the machine past the resistance there (``phi[-1]``), and the run ends at it.
    """

    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    driving_omega: np.ndarray | None
    motor_torque: np.ndarray
    cycles: tuple[Cycle, ...]
    steady: SteadyState | None
    method: str
    method_reason: str
    stiffness: float
    events: tuple[tuple[float, str], ...]
    stopped_at: float | None
    stalled_at: float | None
    slip_energy: float
    nfev: int
    njev: int
    nlu: int
    notes: tuple[str, ...]
    _dense: Callable[[np.ndarray], np.ndarray] = field(repr=False)

    @property
    def stiff(self) -> bool:
        """Whether stability, not accuracy, would hold an explicit method's step (:func:`choose_method`)."""
        return is_stiff(self.stiffness)

    @property
    def stalled_at_angle_deg(self) -> float | None:
        """Where the machine stalled: the driving shaft's angle within its turn (degrees); None if it did not."""
        return None if self.stalled_at is None else math.degrees(float(self.phi[-1])) % 360.0

    def state_at(self, times: ArrayLike) -> np.ndarray:
        """The state ``[φ, ω, …]`` at the given times (rows are the components)."""
        return self._dense(np.asarray(times, dtype=float))

    def event_time(self, name: str) -> float | None:
        """The first time the named event happened (``"clutch locked"``, ``"brake on"``, …)."""
        return next((t for t, text in self.events if text == name), None)

    def start_up_time(self, percent: float = 5.0) -> float | None:
        """The time after which ω stays within ``percent`` % of ωm around the steady range.

        The band is ``[ωmin − p·ωm, ωmax + p·ωm]`` of the steady state, so that a machine with
        δ > 0 counts as started once its speed no longer leaves the band of the steady
        fluctuation widened by ``p``; with δ = 0 it is the usual ``|ω − ωm| ≤ p·ωm``.  None
        when no steady state was found.
        """
        if not percent > 0:
            raise ValueError(f"percent: must be > 0 (got {percent!r})")
        if self.steady is None:
            return None
        cycle = self.steady.cycle
        margin = percent / 100.0 * cycle.middle_speed
        low, high = cycle.min_speed - margin, cycle.max_speed + margin
        window = self.t <= cycle.start + cycle.period
        outside = np.flatnonzero(window & ((self.omega < low) | (self.omega > high)))
        if outside.size == 0:
            return float(self.t[0])
        i = outside[-1]
        if i + 1 >= self.t.size or self.t[i + 1] <= self.t[i]:
            return float(self.t[min(i + 1, self.t.size - 1)])
        bound = low if self.omega[i] < low else high
        return float(brentq(lambda s: self.state_at(s)[1] - bound, self.t[i], self.t[i + 1], xtol=1e-13))


# --- the equations ---------------------------------------------------------------------------

RIGID, OPEN, SLIP_FORWARD, SLIP_BACKWARD, LOCKED = "rigid", "open", "slip+", "slip-", "locked"


class _Equations:
    """The right-hand sides of each phase.

    Without a clutch the state is ``[φ, ω]``; with one ``[φ, ω, ω_d, θ_slip]``: the driving half's
    speed reduced to the shaft and the angle the clutch has slipped through.

    A body at rest whose torques cannot move it forward is *held* (the passive resistances hold
    it): its derivatives are zero for the whole segment.  A moving body follows its equation
    without that switch, so the right-hand side stays smooth and the solver finds the instant it
    comes to rest as an event (a switch inside a step would stall the step-size control).
    """

    def __init__(self, machine: Machine, motor: Motor, brake: Brake | None, clutch: Clutch | None,
                 motor_off_at: float | None) -> None:
        self.machine = machine
        self.motor = motor
        self.brake = brake
        self.clutch = clutch
        self.motor_off_at = motor_off_at
        self.rotor = motor.reduced_inertia
        if clutch is not None:
            self.driving_inertia = clutch.inertia + self.rotor
            if not self.driving_inertia > 0:
                raise ValueError("Clutch: the driving half needs an inertia > 0 "
                                 "(give Clutch.inertia or the motor's rotor_inertia)")
        # The switches (brake on, motor off) are read at this time, not at the solver's t: the
        # integrator sets it to the start of each segment, so that a switch at a segment's end
        # cannot leak into its last step or its events.
        self.clock = -math.inf
        self.machine_held = False
        self.driving_held = False

    def motor_on(self, t: float) -> bool:
        return self.motor_off_at is None or t < self.motor_off_at

    def driving(self, t: float, speed: float) -> float:
        return self.motor.shaft_torque(speed) if self.motor_on(self.clock) else 0.0

    def braking(self, t: float, omega: float) -> float:
        brake = self.brake
        if brake is None or self.clock < brake.at:
            return 0.0
        return brake.torque + brake.damping * max(omega, 0.0)

    def passive(self, t: float, phi: float, omega: float) -> float:
        """Everything on the machine but the drive: −Mr − Mb − ½·Je'·ω²."""
        m = self.machine
        return -m.mr(phi, omega) - self.braking(t, omega) - 0.5 * m.je_slope(phi) * omega * omega

    def clutch_torque(self, phase: str) -> float:
        """The torque the slipping clutch passes to the machine (signed), zero when open."""
        if phase == SLIP_FORWARD:
            return self.clutch.torque
        if phase == SLIP_BACKWARD:
            return -self.clutch.torque
        return 0.0

    def settle(self, phase: str, t: float, y: np.ndarray) -> None:
        """Decide, at a segment's start, which bodies are held at rest."""
        self.machine_held = self.driving_held = False
        if phase in (RIGID, LOCKED):
            driving, passive = self.driving(t, y[1]), self.passive(t, y[0], y[1])
            self.machine_held = y[1] <= 0.0 and not _overcomes(driving, passive)
            return
        torque = self.clutch_torque(phase)
        self.machine_held = y[1] <= 0.0 and not _overcomes(torque, self.passive(t, y[0], y[1]))
        self.driving_held = y[2] <= 0.0 and not _overcomes(self.driving(t, y[2]), -torque)

    def rigid(self, t: float, y: np.ndarray) -> list[float]:
        if self.machine_held:
            return [0.0, 0.0]
        phi, omega = y[0], y[1]
        net = self.driving(t, omega) + self.passive(t, phi, omega)
        return [omega, net / (self.machine.je(phi) + self.rotor)]

    def _machine_side(self, t: float, phi: float, omega: float, clutch_torque: float) -> tuple[float, float]:
        if self.machine_held:
            return 0.0, 0.0
        return omega, (clutch_torque + self.passive(t, phi, omega)) / self.machine.je(phi)

    def _driving_side(self, t: float, speed: float, clutch_torque: float) -> float:
        if self.driving_held:
            return 0.0
        return (self.driving(t, speed) - clutch_torque) / self.driving_inertia

    def open(self, t: float, y: np.ndarray) -> list[float]:
        dphi, domega = self._machine_side(t, y[0], y[1], 0.0)
        return [dphi, domega, self._driving_side(t, y[2], 0.0), 0.0]

    def slipping(self, phase: str) -> Callable[[float, np.ndarray], list[float]]:
        torque = self.clutch_torque(phase)
        sense = 1.0 if torque > 0 else -1.0

        def rhs(t: float, y: np.ndarray) -> list[float]:
            dphi, domega = self._machine_side(t, y[0], y[1], torque)
            return [dphi, domega, self._driving_side(t, y[2], torque), sense * (y[2] - y[1])]
        return rhs

    def locked_acceleration(self, t: float, y: np.ndarray) -> float:
        if self.machine_held:
            return 0.0
        phi, omega = y[0], y[1]
        net = self.driving(t, omega) + self.passive(t, phi, omega)
        return net / (self.machine.je(phi) + self.driving_inertia)

    def locked(self, t: float, y: np.ndarray) -> list[float]:
        if self.machine_held:
            return [0.0, 0.0, 0.0, 0.0]
        a = self.locked_acceleration(t, y)
        return [y[1], a, a, 0.0]

    def transmitted(self, t: float, y: np.ndarray) -> float:
        """The torque the locked clutch passes from the driving half to the machine."""
        return self.driving(t, y[1]) - self.driving_inertia * self.locked_acceleration(t, y)

    def rhs(self, phase: str) -> Callable[[float, np.ndarray], list[float]]:
        if phase == RIGID:
            return self.rigid
        if phase == OPEN:
            return self.open
        if phase == LOCKED:
            return self.locked
        return self.slipping(phase)


def _event(function: Callable[[float, np.ndarray], float], direction: float) -> Callable[[float, np.ndarray], float]:
    function.terminal = True  # type: ignore[attr-defined]
    function.direction = direction  # type: ignore[attr-defined]
    return function


def _overcomes(driving: float, passive: float) -> bool:
    """Whether a torque moves a body at rest against the passive ones: by more than their rounding, so that a
    motor exactly equal to the resistance (equal but for the last bits of a conversion) holds it at rest."""
    return driving + passive > 1e-12 * (abs(driving) + abs(passive))


# How many times a run evaluates the equation of motion at most (a run to the steady state takes a few thousand;
# this many is some ten seconds).  A motion the scene makes too slow or too stiff to follow (a gear ratio of
# 1e15, which leaves the shaft a turn in 10^13 s) would otherwise integrate for hours.
MOST_EVALUATIONS = 300_000


class _Integrator:
    """Integrates phase by phase; stops at times where the equations change and at state events."""

    def __init__(self, equations: _Equations, start: Start, method: str, rtol: float, atol: float,
                 max_evaluations: int | None = MOST_EVALUATIONS) -> None:
        self.eq = equations
        self.method = method
        self.max_evaluations = max_evaluations
        self.evaluations = 0
        self.rtol = rtol
        self.atol = atol
        self.t = float(start.time)
        clutch = equations.clutch
        if clutch is None:
            self.y = np.array([start.angle, start.omega], dtype=float)
        else:
            driving = start.omega if start.driving_omega is None else start.driving_omega
            self.y = np.array([start.angle, start.omega, driving, 0.0], dtype=float)
        self.boundaries = sorted({b for b in self._switch_times() if b > self.t})
        self.pieces: list[tuple[float, float, Any]] = []
        self.times: list[np.ndarray] = []
        self.states: list[np.ndarray] = []
        self.events: list[tuple[float, str]] = []
        self.finished = False
        self.nfev = self.njev = self.nlu = 0
        self._stalls = 0
        equations.clock = self.t
        for t, name in self._switch_names():
            if t <= self.t:
                self.events.append((self.t, name))
        if clutch is None:
            self.phase = RIGID
        elif clutch.engage_at <= self.t:
            self.phase = self._engaged_phase()
        else:
            self.phase = OPEN

    def _switch_names(self) -> list[tuple[float, str]]:
        eq = self.eq
        names = []
        if eq.brake is not None:
            names.append((eq.brake.at, "brake on"))
        if eq.motor_off_at is not None:
            names.append((eq.motor_off_at, "motor off"))
        if eq.clutch is not None:
            names.append((eq.clutch.engage_at, "clutch engaged"))
        return names

    def _switch_times(self) -> list[float]:
        return [t for t, _ in self._switch_names()]

    # -- phase changes --

    def _engaged_phase(self) -> str:
        """The phase of an engaged clutch in the present state: slipping one way or locked."""
        difference = self.y[2] - self.y[1]
        if abs(difference) > 1e-12 * max(1.0, abs(self.y[1]), abs(self.y[2])):
            return SLIP_FORWARD if difference > 0 else SLIP_BACKWARD
        return self._lock()

    def _lock(self) -> str:
        """Equal speeds: lock if the clutch can pass the torque that needs, else slip the way it pulls."""
        eq = self.eq
        je = eq.machine.je(self.y[0])
        common = max((je * self.y[1] + eq.driving_inertia * self.y[2]) / (je + eq.driving_inertia), 0.0)
        self.y[1] = self.y[2] = common
        needed = self._needed_torque(self.t)
        if abs(needed) <= eq.clutch.torque * (1.0 + 1e-12):
            return LOCKED
        return SLIP_FORWARD if needed > 0 else SLIP_BACKWARD

    def _needed_torque(self, t: float) -> float:
        """The torque the clutch would have to pass to keep both halves locked in the present state."""
        self.eq.settle(LOCKED, t, self.y)
        return self.eq.transmitted(t, self.y)

    def _events(self) -> list[tuple[Callable[[float, np.ndarray], float], str]]:
        eq = self.eq
        events = []
        if self.phase in (SLIP_FORWARD, SLIP_BACKWARD):
            sense = 1.0 if self.phase == SLIP_FORWARD else -1.0
            events.append((_event(lambda t, y: sense * (y[2] - y[1]), -1.0), "clutch locked"))
        elif self.phase == LOCKED:
            capacity = eq.clutch.torque
            events.append((_event(lambda t, y: capacity - abs(eq.transmitted(t, y)), -1.0), "clutch slips"))
        # Coming to rest switches the passive resistances from moving to holding: the moving
        # equations go on smoothly through ω = 0, where this event stops them.
        if not eq.machine_held:
            events.append((_event(lambda t, y: y[1], -1.0), "stopped"))
        if self.phase in (OPEN, SLIP_FORWARD, SLIP_BACKWARD) and not eq.driving_held:
            events.append((_event(lambda t, y: y[2], -1.0), "driving half stopped"))
        return events

    def _on_event(self, name: str) -> None:
        self.events.append((self.t, name))
        if name == "clutch locked":
            self.phase = self._lock()
        elif name == "clutch slips":
            self.phase = SLIP_FORWARD if self._needed_torque(self.t) > 0 else SLIP_BACKWARD
        elif name == "stopped":
            self.y[1] = 0.0
            if self.phase == LOCKED:
                self.y[2] = 0.0
                self.phase = self._lock()  # at rest the motor may pull harder than the clutch can pass
        elif name == "driving half stopped":
            self.y[2] = 0.0
        self._finish_if_held_at_rest()

    def _counted(self, rhs: Callable[[float, np.ndarray], list[float]]) -> Callable[[float, np.ndarray], list[float]]:
        """``rhs`` that stops the run once it has been evaluated :attr:`max_evaluations` times."""
        def counted(t: float, y: np.ndarray) -> list[float]:
            self.evaluations += 1
            if self.max_evaluations is not None and self.evaluations > self.max_evaluations:
                raise ArithmeticError(
                    f"the equation of motion was evaluated {self.max_evaluations} times by t = {t:.4g} s without "
                    f"the run ending: the motion is too slow or too stiff to follow (look at the motor's speed, "
                    f"its gear ratio and the inertias)")
            return rhs(t, y)
        return counted

    def held_at_rest(self) -> bool:
        """Whether the machine, turning as one body, is at rest and held there: the motor switched off or too
        weak to move it at this angle.  Nothing more will happen then, since no later switch (a brake, the
        motor off) drives it harder and a body at rest keeps its angle."""
        if self.phase not in (RIGID, LOCKED) or self.y[1] > 0.0:
            return False
        self.eq.settle(self.phase, self.t, self.y)
        return self.eq.machine_held

    def _finish_if_held_at_rest(self) -> None:
        self.finished = self.held_at_rest()
        if self.finished:
            self.times.append(np.array([self.t]))
            self.states.append(self.y[:, None].copy())

    def _on_boundary(self, t: float) -> None:
        self.eq.clock = t
        for when, name in self._switch_names():
            if when == t:
                self.events.append((t, name))
        eq = self.eq
        if eq.clutch is not None and eq.clutch.engage_at == t and self.phase == OPEN:
            self.phase = self._engaged_phase()
        elif self.phase == LOCKED and abs(self._needed_torque(t)) > eq.clutch.torque * (1.0 + 1e-12):
            self.events.append((t, "clutch slips"))
            self.phase = SLIP_FORWARD if self._needed_torque(t) > 0 else SLIP_BACKWARD

    # -- integration --

    def advance(self, t_end: float) -> None:
        while not self.finished and self.t < t_end:
            self.eq.clock = self.t
            self.eq.settle(self.phase, self.t, self.y)
            stop = min([b for b in self.boundaries if b > self.t] + [t_end])
            events = self._events()
            solution = solve_ivp(self._counted(self.eq.rhs(self.phase)), (self.t, stop), self.y, method=self.method,
                                 rtol=self.rtol, atol=self.atol, dense_output=True,
                                 events=[e for e, _ in events] or None)
            if solution.status == -1:
                raise ArithmeticError(f"the integration failed at t = {self.t:.6g} s in phase "
                                      f"{self.phase!r}: {solution.message}")
            self.nfev += solution.nfev
            self.njev += solution.njev
            self.nlu += solution.nlu
            started = self.t
            self.pieces.append((solution.t[0], solution.t[-1], solution.sol))
            self.times.append(solution.t)
            self.states.append(solution.y)
            self.t = float(solution.t[-1])
            self.y = solution.y[:, -1].copy()
            if solution.status == 1:
                fired = next(name for (_, name), hits in zip(events, solution.t_events, strict=True) if hits.size)
                self.y = solution.y_events[[name for _, name in events].index(fired)][-1].copy()
                self._count_stall(started)
                self._on_event(fired)
            elif stop in self.boundaries:
                self._on_boundary(stop)

    def _count_stall(self, started: float) -> None:
        if self.t - started > 1e-12 * max(1.0, abs(self.t)):
            self._stalls = 0
            return
        self._stalls += 1
        if self._stalls > 20:
            raise ArithmeticError(f"the clutch switches between locking and slipping without moving on at "
                                  f"t = {self.t:.9g} s (phase {self.phase!r}); check its torque against the loads")

    # -- results --

    def dense(self) -> Callable[[np.ndarray], np.ndarray]:
        starts = np.array([p[0] for p in self.pieces])
        interpolants = [p[2] for p in self.pieces]
        size = self.y.size

        def evaluate(times: np.ndarray) -> np.ndarray:
            times = np.asarray(times, dtype=float)
            flat = np.atleast_1d(times).ravel()
            index = np.clip(np.searchsorted(starts, flat, side="right") - 1, 0, len(starts) - 1)
            out = np.empty((size, flat.size))
            for piece in np.unique(index):
                chosen = index == piece
                out[:, chosen] = interpolants[piece](flat[chosen]).reshape(size, -1)
            return out.reshape((size,) + times.shape)
        return evaluate


# --- cycles and the steady state -------------------------------------------------------------


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


# --- the method ------------------------------------------------------------------------------


# The least relative tolerance the solvers take: scipy raises a smaller one to this, with a warning.
SMALLEST_RTOL = 100 * float(np.finfo(float).eps)

# The most turns of the shaft a scene's run integrates: a start-up and a steady state take tens to hundreds; a
# duration of many more is a slip of the unit, and would hold the run for hours.
MOST_TURNS = 100_000
# With no duration, how many turns' time at the running speed a run waits at most for a steady state.
MOST_CYCLES = 2000


def running_speed(machine: Machine, motor: Motor, start: Start = REST, duration: float | None = None) -> float:
    """A scale for the running speed of the shaft, rad/s, where the motor's torque meets the mean resistance.

    Used to judge stiffness and the cycle time; for a constant torque against a resistance that
    does not grow with speed there is no such speed, and the start's speed (or the speed reached
    after ``duration`` at the mean surplus torque) stands in.
    """
    angles = np.linspace(0.0, TWO_PI, 64, endpoint=False)

    def surplus(omega: float) -> float:
        return motor.shaft_torque(omega) - float(np.mean([machine.mr(a, omega) for a in angles]))

    tiny = 1e-9
    top = motor.shaft_no_load_speed
    if top is not None:
        if surplus(tiny * top) > 0 > surplus(top):
            return float(brentq(surplus, tiny * top, top, xtol=1e-12 * top))
        return top * (1.0 - getattr(motor, "rated_slip", 0.0))
    given = max(start.omega, start.driving_omega or 0.0)
    top = max(given, 1.0)
    for _ in range(30):
        if surplus(top) < 0:
            return float(brentq(surplus, 0.0, top, xtol=1e-12 * top)) if surplus(0.0) > 0 else top
        top *= 2.0
    inertia = float(np.mean([machine.je(a) for a in angles])) + motor.reduced_inertia
    reached = given + max(surplus(given), 0.0) / inertia * (duration or 1.0)
    return max(reached, 1e-3)


def is_stiff(stiffness: float) -> bool:
    """Whether a stiffness number (:func:`choose_method`) calls for an implicit method."""
    return stiffness > STIFFNESS_THRESHOLD


def choose_method(equations: _Equations, omega_run: float, rtol: float, atol: float) -> tuple[str, str, float]:
    """The solver for these equations, the reason in words, and the stiffness number.

    The stiffness number is the largest decay rate ``−∂(dω/dt)/∂ω`` over a turn and over speeds
    up to the running speed (a steep motor characteristic gives most of it: ``|dMd/dω|/J``),
    times the step RK45 takes for accuracy near the running speed (:func:`_explicit_step`).
    Above ``STIFFNESS_THRESHOLD`` stability, not accuracy, would hold the explicit step: LSODA
    is chosen (it switches to BDF where the problem is stiff and back to Adams where it is not;
    fastest on the stiff case of ``bench/integrators.py``).  Otherwise RK45, or DOP853 below
    rtol 1e-8, where its higher order pays.
    """
    machine, motor = equations.machine, equations.motor
    inertia_driving = equations.driving_inertia if equations.clutch is not None else 0.0
    angles = np.linspace(0.0, TWO_PI, 24, endpoint=False)
    speeds = omega_run * np.array([0.05, 0.25, 0.5, 0.75, 0.9, 0.97, 1.0, 1.03])
    on = equations.motor_off_at is None or equations.motor_off_at > 0

    def acceleration(phi: float, omega: float) -> float:
        drive = motor.shaft_torque(omega) if on else 0.0
        net = drive - machine.mr(phi, omega) - 0.5 * machine.je_slope(phi) * omega * omega
        if equations.brake is not None:
            net -= equations.brake.damping * omega
        return net / (machine.je(phi) + equations.rotor + inertia_driving)

    decay = 0.0
    for omega in speeds:
        h = 1e-6 * max(omega_run, 1e-6)
        for phi in angles:
            slope = (acceleration(phi, omega + h) - acceleration(phi, omega - h)) / (2.0 * h)
            decay = max(decay, -slope)
    if equations.clutch is not None and on:
        # While slipping the driving half answers to the motor alone: often the stiffest part.
        for omega in speeds:
            h = 1e-6 * max(omega_run, 1e-6)
            slope = (motor.shaft_torque(omega + h) - motor.shaft_torque(omega - h)) / (2.0 * h)
            decay = max(decay, -slope / equations.driving_inertia)
    step = _explicit_step(equations, omega_run, rtol, atol)
    stiffness = decay * step
    period = TWO_PI / omega_run
    scale = (f"largest decay rate |∂f/∂ω| = {decay:.3g} 1/s (time constant {1 / decay:.3g} s) × RK45's step "
             f"for accuracy {step:.3g} s = {stiffness:.3g}; cycle {period:.3g} s") if decay > 0 else \
            f"no decaying mode (|∂f/∂ω| = 0); RK45's step for accuracy {step:.3g} s, cycle {period:.3g} s"
    if is_stiff(stiffness):
        return "LSODA", (f"auto: stiff, stability would hold the explicit step ({scale} > {STIFFNESS_THRESHOLD}): "
                         "LSODA"), stiffness
    method = "DOP853" if rtol < 1e-8 else "RK45"
    return method, f"auto: not stiff ({scale} ≤ {STIFFNESS_THRESHOLD}): {method}", stiffness


def _explicit_step(equations: _Equations, omega_run: float, rtol: float, atol: float) -> float:
    """The step RK45 takes for accuracy alone near the running speed.

    The motor's torque is frozen at its value at the running speed (and a brake left out), so
    that the step follows what the resistance and the inertia ask, not the stability limit the
    steep characteristic would impose; a few dozen steps from the running state.
    """
    period = TWO_PI / omega_run
    machine = equations.machine
    inertia = equations.rotor + (equations.driving_inertia if equations.clutch is not None else 0.0)
    on = equations.motor_off_at is None or equations.motor_off_at > 0
    drive = equations.motor.shaft_torque(omega_run) if on else 0.0

    def frozen(t: float, y: np.ndarray) -> np.ndarray:
        phi, omega = y
        net = drive - machine.mr(phi, omega) - 0.5 * machine.je_slope(phi) * omega * omega
        return np.array([omega, net / (machine.je(phi) + inertia)])

    solver = RK45(frozen, 0.0, np.array([0.0, omega_run]), t_bound=50.0 * period, rtol=rtol, atol=atol)
    steps = []
    while len(steps) < 40 and solver.status == "running" and solver.t < period:
        before = solver.t
        solver.step()
        steps.append(solver.t - before)
    tail = steps[len(steps) // 2:] or [period]
    return float(np.median(tail))


# --- simulate --------------------------------------------------------------------------------


def simulate(machine: Machine, motor: Motor, *, duration: float | None = None, start: Start = REST,
             brake: Brake | None = None, clutch: Clutch | None = None, motor_off_at: float | None = None,
             method: str = "auto", rtol: float = 1e-6, atol: float | None = None,
             steady_tolerance: float = 1e-4, max_cycles: int = MOST_CYCLES,
             max_evaluations: int | None = MOST_EVALUATIONS) -> MachineMotion:
    """Integrate the machine's motion.

    Parameters
    ----------
    machine, motor
        The machine reduced to its driving shaft and the motor that drives it.
    duration
        How long to integrate, s.  None: until the steady state is found (or, with the motor
        switched off, until the machine stops), at most ``max_cycles`` turns.
    start
        The initial state (default: at rest at φ = 0).
    brake, clutch, motor_off_at
        A brake, a clutch, and when the motor is switched off (s).
    method
        ``"auto"`` (see :func:`choose_method`) or a :func:`scipy.integrate.solve_ivp` method.
    rtol, atol
        The solver's tolerances (``atol`` defaults to ``1e-3·rtol`` times the running speed).
    steady_tolerance
        How close the cycles must have settled (relative ωm, absolute δ); never below 10·rtol.
    max_cycles
        With no duration, how many turns at most; on any run, how many of the last turns are
        analysed for the cycles and the steady state.
    max_evaluations
        How many evaluations of the equation of motion before the run is given up with an
        :class:`ArithmeticError`; None: no limit (a benchmark of explicit methods on a stiff machine).
    """
    if method not in METHODS:
        raise ValueError(f"method: must be one of {', '.join(METHODS)} (got {method!r})")
    if not (isinstance(rtol, (int, float)) and SMALLEST_RTOL <= rtol < 1):
        raise ValueError(f"rtol: must be from {SMALLEST_RTOL:.3g} (100 machine epsilons, the solvers' least) "
                         f"to below 1 (got {rtol!r})")
    if duration is not None:
        _require_positive("simulate", "duration", duration)
    if atol is not None:
        _require_positive("simulate", "atol", atol)
    if clutch is None and start.driving_omega is not None:
        raise ValueError("start.driving_omega: only with a clutch")
    if isinstance(max_cycles, bool) or not isinstance(max_cycles, int) or max_cycles < 3:
        raise ValueError(f"max_cycles: must be an integer >= 3 (got {max_cycles!r})")
    equations = _Equations(machine, motor, brake, clutch, motor_off_at)
    omega_run = running_speed(machine, motor, start, duration)
    atol = atol if atol is not None else 1e-3 * rtol * max(omega_run, 1e-3)
    if method == "auto":
        chosen, reason, stiffness = choose_method(equations, omega_run, rtol, atol)
    else:
        _, _, stiffness = choose_method(equations, omega_run, rtol, atol)
        chosen, reason = method, f"{method}: as asked (stiffness number {stiffness:.3g})"
    tolerance = max(steady_tolerance, 10.0 * rtol)
    notes = []
    integrator = _Integrator(equations, start, chosen, rtol, atol, max_evaluations)
    # A motor too weak to start the machine where it stands: one turn's time at rest shows it.
    equations.clock = start.time
    never_starts = equations.motor_on(start.time) and integrator.held_at_rest()
    cycles: tuple[Cycle, ...] = ()
    steady = None
    if duration is not None:
        integrator.advance(start.time + duration)
    elif never_starts:
        integrator.advance(start.time + TWO_PI / omega_run)
    else:
        period = TWO_PI / omega_run
        limit = start.time + max_cycles * period
        run_down = motor_off_at is not None or brake is not None
        while True:
            integrator.advance(min(integrator.t + 20.0 * period, limit))
            if integrator.finished:
                break
            if not run_down:
                t, y = np.concatenate(integrator.times), np.concatenate(integrator.states, axis=1)
                cycles = find_cycles(t, y[0], integrator.dense(), limit=max_cycles)
                if find_steady_state(cycles, tolerance) is not None:
                    break
            if integrator.t >= limit:
                notes.append(f"stopped after {max_cycles} cycles' time ({limit - start.time:.6g} s) "
                             f"without {'stopping' if run_down else 'a steady state'}")
                break
    t = np.concatenate(integrator.times)
    y = np.concatenate(integrator.states, axis=1)
    if not np.any(y[1] > 0):
        notes.append("the machine did not move: the driving torque at rest does not overcome the resistance")
    dense = integrator.dense()
    cycles = find_cycles(t, y[0], dense, limit=max_cycles)
    steady = find_steady_state(cycles, tolerance)
    speed_row = 2 if clutch is not None else 1
    torque = np.array([motor.shaft_torque(speed) if equations.motor_on(ti) else 0.0
                       for ti, speed in zip(t, y[speed_row], strict=True)])
    slip_energy = clutch.torque * float(y[3, -1]) if clutch is not None else 0.0
    stops = [when for when, name in integrator.events if name == "stopped"]
    stopped_at = stops[-1] if stops and y[1, -1] == 0.0 else None
    stalled_at = start.time if never_starts else (
        stopped_at if stopped_at is not None and equations.motor_on(stopped_at) else None)
    return MachineMotion(t=t, phi=y[0], omega=y[1], driving_omega=y[2] if clutch is not None else None,
                         motor_torque=torque, cycles=cycles, steady=steady, method=chosen, method_reason=reason,
                         stiffness=stiffness, events=tuple(integrator.events), stopped_at=stopped_at,
                         stalled_at=stalled_at,
                         slip_energy=slip_energy, nfev=integrator.nfev, njev=integrator.njev, nlu=integrator.nlu,
                         notes=tuple(notes), _dense=dense)


@dataclass(frozen=True)
class ClutchEngagement:
    """Two shafts joined by a friction clutch: the speeds, when they lock and the energy lost."""

    motion: MachineMotion
    lock_time: float | None
    common_speed: float | None
    slip_energy: float


def engage_clutch(driving_inertia: float, driving_speed: float, driven_inertia: float, driven_speed: float,
                  clutch_torque: float, *, driving_torque: float = 0.0, driven_torque: float = 0.0,
                  duration: float | None = None, rtol: float = 1e-9) -> ClutchEngagement:
    """Two shafts with constant torques on them, joined at t = 0 by a clutch of constant capacity.

    ``driving_torque`` and ``driven_torque`` act on each shaft in its sense of rotation (negative
    resists).  Integrated by :func:`simulate` (the driven shaft as a machine of constant inertia,
    the driving one as the clutch's driving half) until the shafts lock and a while after, or
    for ``duration``.
    """
    for name, value in (("driving_inertia", driving_inertia), ("driven_inertia", driven_inertia),
                        ("clutch_torque", clutch_torque)):
        _require_positive("engage_clutch", name, value)
    machine = Machine(inertia=driven_inertia, resisting=-driven_torque)
    clutch = Clutch(torque=clutch_torque, engage_at=0.0, inertia=driving_inertia)
    if duration is None:
        # The relative speed closes at a rate of at least Tc·(1/J1 + 1/J2) − |M1|/J1 − |M2|/J2 ...
        closing = clutch_torque * (1 / driving_inertia + 1 / driven_inertia) \
            - driving_torque / driving_inertia + driven_torque / driven_inertia
        gap = abs(driving_speed - driven_speed)
        duration = 1.2 * gap / abs(closing) if closing != 0 and gap > 0 else 1.0
    motion = simulate(machine, ConstantTorque(driving_torque), duration=duration, clutch=clutch,
                      start=Start(omega=driven_speed, driving_omega=driving_speed), method="DOP853", rtol=rtol)
    lock = motion.event_time("clutch locked")
    common = float(motion.state_at(lock)[1]) if lock is not None else None
    return ClutchEngagement(motion=motion, lock_time=lock, common_speed=common, slip_energy=motion.slip_energy)


# --- the scene's [dynamics] keys -------------------------------------------------------------


@dataclass(frozen=True)
class MotionSpec:
    """What the scene asks of the machine's motion; :meth:`run` integrates it for a machine."""

    motor: Motor
    motor_off_at: float | None = None
    brake: Brake | None = None
    clutch: Clutch | None = None
    start: Start = REST
    duration: float | None = None
    method: str = "auto"
    rtol: float = 1e-6
    steady_tolerance: float = 1e-4

    def run(self, machine: Machine) -> MachineMotion:
        omega_run = running_speed(machine, self.motor, self.start, self.duration)
        if self.duration is not None and self.duration * omega_run > TWO_PI * MOST_TURNS:
            raise ValueError(f"duration: {self.duration:g} s is some {self.duration * omega_run / TWO_PI:.3g} "
                             f"turns at the running speed, {omega_run:.4g} rad/s; a run integrates at most "
                             f"{MOST_TURNS} turns")
        # A start far above the running speed (rpm given as rad/s a thousandfold) slows down over more turns
        # than a run integrates, each resolved step by step: the run would hang rather than fail.
        fastest = max(self.start.omega, self.start.driving_omega or 0.0)
        span = self.duration if self.duration is not None else MOST_CYCLES * TWO_PI / omega_run
        if fastest * span > TWO_PI * MOST_TURNS:
            raise ValueError(f"start: {fastest:.4g} rad/s is {fastest / omega_run:.3g} times the running speed, "
                             f"{omega_run:.4g} rad/s; the run could take some {fastest * span / TWO_PI:.3g} turns, "
                             f"and it integrates at most {MOST_TURNS}")
        return simulate(machine, self.motor, duration=self.duration, start=self.start, brake=self.brake,
                        clutch=self.clutch, motor_off_at=self.motor_off_at, method=self.method, rtol=self.rtol,
                        steady_tolerance=self.steady_tolerance)


def _speed(table: Table, omega_key: str, rpm_key: str, default: Any) -> Any:
    """A speed given as rad/s under ``omega_key`` or as rev/min under ``rpm_key`` (not both)."""
    if table.has(omega_key) and table.has(rpm_key):
        raise SceneError(table.where(rpm_key), f"give either {omega_key} or {rpm_key}, not both")
    if table.has(rpm_key):
        return table.number(rpm_key, non_negative=True) * RPM
    return table.number(omega_key, default, non_negative=True)


def _read_motor(table: Table) -> tuple[Motor, float | None]:
    kind = table.choice("kind", MOTOR_KINDS)
    drive = {"gear_ratio": table.number("gear_ratio", 1.0, positive=True),
             "rotor_inertia": table.number("rotor_inertia", 0.0, non_negative=True)}
    off_at = table.number("off_at", None)
    if kind == "constant":
        motor: Motor = ConstantTorque(table.number("torque"), **drive)
    elif kind == "linear":
        if table.has("points"):
            for key in ("stall_torque", "no_load_rpm"):
                if table.has(key):
                    raise SceneError(table.where(key), "give either points or stall_torque with no_load_rpm, not both")
            pairs = table.items("points", length=2)
            points = []
            for where, item in pairs:
                if not isinstance(item, list) or len(item) != 2:
                    raise SceneError(where, "must be a point [rpm, torque N·m]", item)
                points.append((check_number(item[0], f"{where}[0]") * RPM, check_number(item[1], f"{where}[1]")))
            try:
                motor = LinearMotor.through(points[0], points[1], **drive)
            except ValueError as error:
                raise SceneError(table.where("points"), str(error).split(": ", 1)[1]) from None
        else:
            motor = LinearMotor(table.number("stall_torque", positive=True),
                                table.number("no_load_rpm", positive=True) * RPM, **drive)
    else:
        power = table.number("power", positive=True)
        overload = table.number("overload")
        if not overload > 1:
            raise SceneError(table.where("overload"), "must be > 1 (it is Mmax/Mrated)", overload)
        given = [k for k in ("synchronous_rpm", "rated_rpm", "rated_slip") if table.has(k)]
        if len(given) != 2:
            raise SceneError(table.path, "give two of synchronous_rpm, rated_rpm, rated_slip "
                             f"(got {', '.join(given) or 'none'})")
        synchronous = table.number("synchronous_rpm", None, positive=True)
        rated = table.number("rated_rpm", None, positive=True)
        slip = table.number("rated_slip", None)
        if slip is not None and not 0 < slip < 1:
            raise SceneError(table.where("rated_slip"), "must be between 0 and 1", slip)
        if slip is None:
            if not rated < synchronous:
                raise SceneError(table.where("rated_rpm"), f"must be below synchronous_rpm ({synchronous!r})", rated)
            slip = 1.0 - rated / synchronous
        elif synchronous is None:
            synchronous = rated / (1.0 - slip)
        motor = KlossMotor(power, synchronous * RPM, slip, overload, **drive)
    table.done()
    return motor, off_at


def _read_brake(table: Table) -> Brake:
    torque = table.number("torque", 0.0, non_negative=True)
    damping = table.number("damping", 0.0, non_negative=True)
    at = table.number("at", 0.0)
    if torque == 0 and damping == 0:
        raise SceneError(table.path, "needs torque > 0 or damping > 0")
    table.done()
    return Brake(torque=torque, damping=damping, at=at)


def _read_clutch(table: Table) -> Clutch:
    clutch = Clutch(torque=table.number("torque", positive=True), engage_at=table.number("engage_at", 0.0),
                    inertia=table.number("inertia", 0.0, non_negative=True))
    table.done()
    return clutch


def _read_start(value: Any, where: str, clutch: Clutch | None) -> Start:
    if isinstance(value, str):
        if value != "rest":
            raise SceneError(where, "must be \"rest\" or a table {omega or rpm, angle_deg, driving_omega or "
                             "driving_rpm}", value)
        return REST
    table = Table(value, where)
    omega = _speed(table, "omega", "rpm", 0.0)
    angle = math.radians(table.number("angle_deg", 0.0))
    driving = _speed(table, "driving_omega", "driving_rpm", None)
    if driving is not None and clutch is None:
        key = "driving_omega" if table.has("driving_omega") else "driving_rpm"
        raise SceneError(table.where(key), "only with a clutch")
    table.done()
    return Start(omega=omega, angle=angle, driving_omega=driving)


def read_motion(table_or_dict: Table | Mapping[str, Any], path: str = "dynamics") -> MotionSpec:
    """The motion's keys of the scene's ``[dynamics]`` table.

    ``motor`` (required), ``brake``, ``clutch``, ``start``, ``duration``, ``method``, ``rtol``,
    ``steady_tolerance``.  A :class:`~graphplan.reader.Table` is read for these keys only and its
    owner calls ``done()``; a plain mapping is read whole, so any other key in it is unknown.
    """
    owned = isinstance(table_or_dict, Table)
    table = table_or_dict if owned else Table(dict(table_or_dict) if isinstance(table_or_dict, Mapping)
                                              else table_or_dict, path)
    motor, off_at = _read_motor(table.table("motor"))
    brake_table = table.table("brake", None)
    clutch_table = table.table("clutch", None)
    brake = _read_brake(brake_table) if brake_table is not None else None
    clutch = _read_clutch(clutch_table) if clutch_table is not None else None
    if clutch is not None and clutch.inertia + motor.reduced_inertia <= 0:
        raise SceneError(clutch_table.where("inertia"), "the clutch's driving half needs an inertia: "
                         "give clutch.inertia or motor.rotor_inertia")
    start = _read_start(table.raw("start", "rest"), table.where("start"), clutch)
    duration = table.number("duration", None, positive=True)
    method = table.choice("method", METHODS, "auto")
    rtol = table.number("rtol", 1e-6, positive=True)
    if not rtol < 1:
        raise SceneError(table.where("rtol"), "must be < 1", rtol)
    if rtol < SMALLEST_RTOL:
        raise SceneError(table.where("rtol"), f"must be at least {SMALLEST_RTOL:.3g}: 100 machine epsilons, the "
                         "least the solvers take", rtol)
    steady_tolerance = table.number("steady_tolerance", 1e-4, positive=True)
    if not owned:
        table.done()
    return MotionSpec(motor=motor, motor_off_at=off_at, brake=brake, clutch=clutch, start=start, duration=duration,
                      method=method, rtol=rtol, steady_tolerance=steady_tolerance)
