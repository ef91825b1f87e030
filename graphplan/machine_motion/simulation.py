"""A run of the machine: :func:`simulate` integrates it and returns a :class:`MachineMotion`; two shafts
joined by a clutch (:func:`engage_clutch`)."""

from __future__ import annotations

import dataclasses
import enum
import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import brentq

from ..kinematics import read_only
from ..rounding import noise_floor
from .cycles import Cycle, SteadyState, find_cycles, find_steady_state, refined
from .drive import REST, Brake, Clutch, ConstantTorque, Motor, Start, require_positive
from .integrator import MOST_EVALUATIONS, Equations, Integrator
from .method import choose_method, is_stiff, refuse_endless_run_down, refuse_runaway, run_down_time, running_speed
from .shaft import TWO_PI, Machine

METHODS = ("auto", "RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")

# The least relative tolerance the solvers take: scipy raises a smaller one to this, with a warning.
SMALLEST_RTOL = 100 * float(np.finfo(float).eps)
#: The loosest steady_tolerance: a turn's ωm within 0.1 % of the next's and δ within 0.001, a third of the evenest
#: machines' (an alternator's 1/300).  A looser one took the start-up's own turns for the steady state (1e6 put it
#: before the machine had reached its speed), and reported their ωm and δ as the machine's.
LARGEST_STEADY_TOLERANCE = 1e-3
# The relative tolerance a run takes unless told: the note gives the steady ωm and δ to four digits, and at
# 1e-6 the steady cycles' δ wandered in the fourth (a machine with a jump in its resistance: 0.02999 against
# 0.02997; the class III triad's 0.01991 against 0.01995), for the tenth of a second that 1e-8 costs.
DEFAULT_RTOL = 1e-8
# With no duration, how many turns' time at the running speed a run waits at most for a steady state.
MOST_CYCLES = 2000


class Stall(enum.Enum):
    """What fell short where a run stalled with the motor on; each value ends the names of the locale's sentences
    that tell it (``motion_stalled_braked``, ``note_dyn_stalled_braked``)."""

    MOTOR = "stalled"  # having turned the machine, the motor cannot carry it past the resistance
    CLUTCH = "stalled_clutch"  # having turned the machine, the clutch slipping at its torque cannot
    BRAKE = "stalled_braked"  # the brake, applied as the motor drove it, brought it to rest against the motor
    BRAKE_CLUTCH = "stalled_braked_clutch"  # or against the clutch, slipping at a torque that beats Mr alone
    NEVER_STARTS = "never_starts"  # the motor cannot move it from where it stands
    NEVER_STARTS_CLUTCH = "never_starts_clutch"  # nor can the clutch, slipping at its torque from the start
    NEVER_STARTS_BRAKED = "never_starts_braked"  # what drives it would, but not against the brake on from the start


@dataclass(frozen=True, eq=False)
class MachineMotion:
    """The integrated motion.

    ``t``, ``phi``, ``omega`` are at the solver's steps (a step is repeated where the state jumps,
    as when the clutch locks); :meth:`state_at` interpolates between them.  ``driving_omega`` is
    the clutch's driving half (None without a clutch), ``motor_torque`` the motor's torque on the
    shaft at the steps, ``slip_energy`` the work lost in the clutch (J) up to the steady state, or over the
    whole run where it reaches none, and ``steady_slip_energy`` the work it loses in the steady turn (0 where
    it stays locked through it; None without a clutch or a steady state).  ``stopped_at`` is when the
    machine came to rest for good, and ``stalled_at`` the same time when the motor was still on: it
    could not carry the machine past the resistance there (``phi[-1]``), and the run ends at it (where the
    clutch still slips then, its capacity fell short, :attr:`stalled_slipping`).  ``brake`` and ``clutch`` are the
    run's (None without one), and ``stall`` what fell short where it stalled (None where it did not).
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
    steady_slip_energy: float | None
    nfev: int
    njev: int
    nlu: int
    notes: tuple[str, ...]
    _dense: Callable[[np.ndarray], np.ndarray] = field(repr=False)
    brake: Brake | None = None
    clutch: Clutch | None = None
    stall: Stall | None = None

    def __post_init__(self) -> None:
        # Handed out as they are (scene.machine_dynamics().motion.omega): ω turned into rpm in place changed what
        # the results, the note and motion.svg read of the motion after.
        for array in (self.t, self.phi, self.omega, self.driving_omega, self.motor_torque):
            read_only(array)

    def __repr__(self) -> str:
        # The dataclass's own repr printed every step: 34 000 characters on a notebook's line.
        ending = (f", stalled at {self.stalled_at:.4g} s" if self.stalled_at is not None
                  else f", at rest from {self.stopped_at:.4g} s" if self.stopped_at is not None
                  else ", steady" if self.steady is not None else "")
        # A machine run down to rest reads ω 0 there, not the -1.11e-15 its integration leaves, as results.json does.
        floor = noise_floor(self.omega)
        lowest, highest = (0.0 if abs(value) < floor else value
                           for value in (float(np.min(self.omega)), float(np.max(self.omega))))
        return (f"<MachineMotion ({self.method}): {len(self.t)} steps over {float(self.t[-1]):.4g} s, ω "
                f"{lowest:.4g} … {highest:.4g} rad/s{ending}>")

    @property
    def stiff(self) -> bool:
        """Whether stability, not accuracy, would hold an explicit method's step (:func:`choose_method`)."""
        return is_stiff(self.stiffness)

    @property
    def stalled_at_angle_deg(self) -> float | None:
        """Where the machine stalled: the driving shaft's angle within its turn (degrees); None if it did not."""
        return None if self.stalled_at is None else math.degrees(float(self.phi[-1])) % 360.0

    @property
    def turned(self) -> bool:
        """Whether the driving shaft turned at all in the run (one that never starts keeps its angle)."""
        return bool(np.any(self.phi != self.phi[0]))

    @property
    def steady_slip_power(self) -> float | None:
        """The clutch's loss in the steady turn as a power (W): its work a turn over the turn's period; None where
        there is no steady turn or no clutch."""
        if self.steady is None or self.steady_slip_energy is None:
            return None
        return self.steady_slip_energy / self.steady.period

    @property
    def stalled_slipping(self) -> bool:
        """Whether the clutch slipped as the machine stalled: its capacity, not the motor, fell short of the
        resistance."""
        return self.stalled_at is not None and self.driving_omega is not None and \
            float(self.driving_omega[-1]) > float(self.omega[-1])

    @property
    def torque_at_rest(self) -> float:
        """The torque that reached the machine's shaft where it stood, for one that never turned (N·m): the clutch's
        capacity where the clutch slips as it stalls, else the motor's at the run's start."""
        return self.clutch.torque if self.stalled_slipping else float(self.motor_torque[0])

    @property
    def stall_brake(self) -> Brake | None:
        """The run's brake where it is what holds the machine where it stalled (:attr:`stall` ``BRAKE``,
        ``BRAKE_CLUTCH`` or ``NEVER_STARTS_BRAKED``); None where something else fell short, or it did not stall."""
        return self.brake if self.stall in (Stall.BRAKE, Stall.BRAKE_CLUTCH, Stall.NEVER_STARTS_BRAKED) else None

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


def simulate(machine: Machine, motor: Motor, *, duration: float | None = None, start: Start = REST,
             brake: Brake | None = None, clutch: Clutch | None = None, motor_off_at: float | None = None,
             method: str = "auto", rtol: float = DEFAULT_RTOL, atol: float | None = None,
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
    if not (isinstance(steady_tolerance, (int, float)) and 0 < steady_tolerance <= LARGEST_STEADY_TOLERANCE):
        raise ValueError(f"steady_tolerance: must be > 0 and at most {LARGEST_STEADY_TOLERANCE:g} "
                         f"(got {steady_tolerance!r})")
    if duration is not None:
        require_positive("simulate", "duration", duration)
    if atol is not None:
        require_positive("simulate", "atol", atol)
    if clutch is None and start.driving_omega is not None:
        raise ValueError("start.driving_omega: only with a clutch")
    if isinstance(max_cycles, bool) or not isinstance(max_cycles, int) or max_cycles < 3:
        raise ValueError(f"max_cycles: must be an integer >= 3 (got {max_cycles!r})")
    refuse_runaway(machine, motor, duration is None and brake is None and motor_off_at is None, start, clutch)
    if duration is None and motor_off_at is not None:
        refuse_endless_run_down(machine, brake)
    equations = Equations(machine, motor, brake, clutch, motor_off_at)
    omega_run = running_speed(machine, motor, start, duration)
    atol = atol if atol is not None else 1e-3 * rtol * max(omega_run, 1e-3)
    if method == "auto":
        chosen, reason, stiffness = choose_method(equations, omega_run, rtol, atol)
    else:
        _, _, stiffness = choose_method(equations, omega_run, rtol, atol)
        chosen, reason = method, f"{method}: as asked (stiffness number {stiffness:.3g})"
    tolerance = max(steady_tolerance, 10.0 * rtol)
    # The regime a run settles in: a brake that comes on while the motor drives gives a braked steady state, and
    # the one before it is not the machine's; a motor switched off leaves the one before it, then runs down.
    settles_after = brake.at if brake is not None and motor_off_at is None else -math.inf
    notes = []
    integrator = Integrator(equations, start, chosen, rtol, atol, max_evaluations)
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
        run_down = motor_off_at is not None
        if run_down:
            # A run-down lasts until the machine stops, however many turns that takes: long enough for it at
            # the mean resistance alone (a clutch's halves locked together first), twice over.
            inertia = equations.rotor + (clutch.inertia if clutch is not None else 0.0)
            speed = max(start.omega, start.driving_omega or 0.0)
            stopping = run_down_time(machine, inertia, speed, brake.torque if brake is not None else 0.0)
            if stopping is not None:
                limit = max(limit, max(motor_off_at, brake.at if brake is not None else 0.0, start.time)
                            + 2.0 * stopping)
        while True:
            integrator.advance(min(integrator.t + 20.0 * period, limit))
            if integrator.finished:
                break
            if not run_down:
                t, y = np.concatenate(integrator.times), np.concatenate(integrator.states, axis=1)
                cycles = find_cycles(t, y[0], integrator.dense(), limit=max_cycles)
                if find_steady_state(_after(cycles, settles_after), tolerance) is not None:
                    break
            if integrator.t >= limit:
                notes.append(f"stopped after {max_cycles} cycles' time ({limit - start.time:.6g} s) "
                             f"without {'stopping' if run_down else 'a steady state'}")
                break
    t = np.concatenate(integrator.times)
    y = np.concatenate(integrator.states, axis=1)
    if integrator.fallbacks:
        count = len(integrator.fallbacks)
        notes.append(integrator.fallbacks[0] + (f"; so at {count} jumps in all" if count > 1 else ""))
    if not np.any(y[1] > 0):
        notes.append("the machine did not move: the driving torque at rest does not overcome the resistance")
    dense = integrator.dense()
    cycles = find_cycles(t, y[0], dense, limit=max_cycles)
    steady = find_steady_state(_after(cycles, settles_after), tolerance)
    if steady is not None:
        # The values the run reports, to the solver's accuracy (a corner of ω where Mr jumps included).
        exact = _uniform_where_only_creeping(refined(steady.cycle, dense), dense, rtol)
        steady = dataclasses.replace(steady, cycle=exact)
        cycles = tuple(exact if cycle.index == exact.index else cycle for cycle in cycles)
    speed_row = 2 if clutch is not None else 1
    torque = np.array([motor.shaft_torque(speed) if equations.motor_on(ti) else 0.0
                       for ti, speed in zip(t, y[speed_row], strict=True)])
    slip_energy, steady_slip_energy = 0.0, None
    if clutch is not None:
        slip_energy = clutch.torque * float(y[3, -1])
        if steady is not None:
            # A clutch that cannot pass the resistance's peaks slips and locks again every turn for as long as the
            # run goes on: the total to the run's end says only where it stopped.  The start-up's loss ends
            # where the steady state begins, and the steady turn's own loss is given apart.
            cycle = steady.cycle
            slipped = dense(np.array([steady.reached_at, cycle.start, cycle.start + cycle.period]))[3]
            slip_energy = clutch.torque * float(slipped[0])
            steady_slip_energy = clutch.torque * float(slipped[2] - slipped[1])
    stops = [when for when, name in integrator.events if name == "stopped"]
    stopped_at = stops[-1] if stops and y[1, -1] == 0.0 else None
    stalled_at = start.time if never_starts else (
        stopped_at if stopped_at is not None and equations.motor_on(stopped_at) else integrator.held_from)
    motion = MachineMotion(t=t, phi=y[0], omega=y[1], driving_omega=y[2] if clutch is not None else None,
                           motor_torque=torque, cycles=cycles, steady=steady, method=chosen, method_reason=reason,
                           stiffness=stiffness, events=tuple(integrator.events), stopped_at=stopped_at,
                           stalled_at=stalled_at, slip_energy=slip_energy, steady_slip_energy=steady_slip_energy,
                           nfev=integrator.nfev, njev=integrator.njev, nlu=integrator.nlu, notes=tuple(notes),
                           _dense=dense, brake=brake, clutch=clutch)
    return dataclasses.replace(motion, stall=_stall(motion, machine))


def _uniform_where_only_creeping(cycle: Cycle, dense: Callable[[np.ndarray], np.ndarray], rtol: float) -> Cycle:
    """``cycle`` turning uniformly at 2π/T where its speed swings no more than it creeps over the turn and the
    solver's tolerance allow.

    A periodic speed that rises (or falls) all through a turn is a constant one: what the turn shows is the tail of
    the start-up, which the steady state's tolerance lets through, and the solver's error, not a fluctuation.  A
    machine of constant Je and Mr on a clutch and a straight motor reached its steady state with ω still rising
    4.8·10⁻⁹ rad/s over the turn, and its note gave δ = 0.000000000523 for a machine that turns uniformly; run
    by RK45 from near its speed, the same machine's turn wandered 10⁻⁷ rad/s, rtol·ω, within the turn."""
    ends = dense(np.array([cycle.start, cycle.start + cycle.period]))[1]
    creep = abs(float(ends[1] - ends[0]))
    if cycle.max_speed - cycle.min_speed > creep + rtol * abs(cycle.middle_speed):
        return cycle
    uniform = cycle.mean_speed
    return dataclasses.replace(cycle, max_speed=uniform, min_speed=uniform)


def _stall(motion: MachineMotion, machine: Machine) -> Stall | None:
    """What fell short where the machine stalled (None where it did not).  Where the shaft never turned: the torque
    that reached it at rest (:attr:`~MachineMotion.torque_at_rest`) against Mr there, a brake on from the start
    blamed only where that torque overcomes Mr alone (the machine would start without it), else the clutch where it
    slips, or the motor.  Where it turned: the brake where it was on by the time the machine came to rest, unless the
    clutch still slips at a capacity short of Mr there; else the clutch where it slips, or the motor.  (A motor that
    came to rest against the brake is not weighed against Mr there: it may have carried the machine past it.)"""
    if motion.stalled_at is None:
        return None
    brake = motion.brake

    def brake_holds(time: float) -> bool:  # a damping alone takes nothing at rest
        return brake is not None and brake.torque != 0 and brake.at <= time

    if not motion.turned:
        if brake_holds(float(motion.t[0])) and motion.torque_at_rest > machine.mr(float(motion.phi[0]), 0.0):
            return Stall.NEVER_STARTS_BRAKED
        return Stall.NEVER_STARTS_CLUTCH if motion.stalled_slipping else Stall.NEVER_STARTS
    if motion.stalled_slipping:
        held = brake_holds(motion.stalled_at) and motion.clutch.torque > machine.mr(float(motion.phi[-1]), 0.0)
        return Stall.BRAKE_CLUTCH if held else Stall.CLUTCH
    return Stall.BRAKE if brake_holds(motion.stalled_at) else Stall.MOTOR


def _after(cycles: tuple[Cycle, ...], moment: float) -> tuple[Cycle, ...]:
    """The cycles that start at ``moment`` or later."""
    return tuple(cycle for cycle in cycles if cycle.start >= moment)


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
        require_positive("engage_clutch", name, value)
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
