"""The equations of motion of each phase (rigid, clutch open, slipping, locked) and the integrator that
runs them segment by segment with :func:`scipy.integrate.solve_ivp`, switching at events and at set times."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from .drive import Brake, Clutch, Motor, Start
from .shaft import TWO_PI, Machine

RIGID, OPEN, SLIP_FORWARD, SLIP_BACKWARD, LOCKED = "rigid", "open", "slip+", "slip-", "locked"
# The event where a resisting moment with jumps (shaft.Machine.moment) jumps.
_JUMP = "Mr jumps"
# The method a segment falls back on where another cannot start again after a jump.
_ROBUST = "Radau"


class Equations:
    """The right-hand sides of each phase.

    Without a clutch the state is ``[φ, ω]``; with one ``[φ, ω, ω_d, θ_slip]``: the driving half's
    speed reduced to the shaft and the angle the clutch has slipped through.

    A body at rest whose torques cannot move it forward is *held* (the passive resistances hold
    it): its derivatives are zero for the whole segment.  A moving body follows its equation
    without that switch, so the right-hand side stays smooth and the solver finds the instant it
    comes to rest as an event (a switch inside a step would stall the step-size control).

    A machine whose Mr acts whichever way it turns (:attr:`Machine.reversible`: its weights alone), run down with
    the motor off and no clutch, turns back from rest where Mr outpulls the brake, whose torque holds it at most
    (static friction); :attr:`sense` is the way it moves in the segment, and the brake acts against it.
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
        # The piece of a resisting moment with jumps the segment is on (the integrator sets it): within a segment
        # Mr is that piece's smooth curve, carried on past the jump that ends the segment.
        self.piece: int | None = None
        # The way the machine moves in the segment: +1 forward, −1 back (only a reversible machine turns back).
        self.sense = 1.0

    def motor_on(self, t: float) -> bool:
        return self.motor_off_at is None or t < self.motor_off_at

    def driving(self, t: float, speed: float) -> float:
        return self.motor.shaft_torque(speed) if self.motor_on(self.clock) else 0.0

    def braking(self, t: float, omega: float) -> float:
        brake = self.brake
        if brake is None or self.clock < brake.at:
            return 0.0
        if self.sense < 0:
            return -brake.torque + brake.damping * min(omega, 0.0)
        return brake.torque + brake.damping * max(omega, 0.0)

    def passive(self, t: float, phi: float, omega: float) -> float:
        """Everything on the machine but the drive: −Mr − Mb − ½·Je'·ω²."""
        m = self.machine
        mr = m.mr(phi, omega) if self.piece is None else m.moment.on_piece(self.piece, phi)
        return -mr - self.braking(t, omega) - 0.5 * m.je_slope(phi) * omega * omega

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
        self.sense = 1.0
        if phase == RIGID and self.turns_back() and (y[1] < 0.0 or (y[1] == 0.0 and self.pulled_back(t, y[0]))):
            self.sense = -1.0
            return
        if phase in (RIGID, LOCKED):
            driving, passive = self.driving(t, y[1]), self.passive(t, y[0], y[1])
            self.machine_held = y[1] <= 0.0 and not _overcomes(driving, passive)
            return
        torque = self.clutch_torque(phase)
        self.machine_held = y[1] <= 0.0 and not _overcomes(torque, self.passive(t, y[0], y[1]))
        self.driving_held = y[2] <= 0.0 and not _overcomes(self.driving(t, y[2]), -torque)

    def turns_back(self) -> bool:
        """Whether the machine may turn back now: its Mr acts both ways, the motor is off and no clutch."""
        return self.machine.reversible and self.clutch is None and not self.motor_on(self.clock)

    def pulled_back(self, t: float, phi: float) -> bool:
        """Whether Mr at rest at ``phi`` turns the machine back against the brake's static torque."""
        brake = self.brake
        holding = brake.torque if brake is not None and self.clock >= brake.at else 0.0
        moment = self.machine.moment
        resisting = self.machine.mr(phi, 0.0) if moment is None else moment(phi)
        return _overcomes(resisting, -holding)

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


class Integrator:
    """Integrates phase by phase; stops at times where the equations change and at state events."""

    def __init__(self, equations: Equations, start: Start, method: str, rtol: float, atol: float,
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
        # The next jump of Mr ahead (the turn's start and its index among the jumps), where Mr has jumps.
        moment = equations.machine.moment
        self._jump: tuple[float, int] | None = None
        # The way the machine moved when the jump ahead was aimed at (a machine that turns back aims anew).
        self._jump_sense = 1.0
        self._restarted_at_jump = False
        # What the run had to do otherwise than asked, for its notes.
        self.fallbacks: list[str] = []
        if moment is not None and moment.jumps:
            equations.piece = moment.piece_at(self.y[0])
            base = math.floor(self.y[0] / TWO_PI) * TWO_PI
            self._jump = next((turn, k) for turn in (base, base + TWO_PI) for k, jump in enumerate(moment.jumps)
                              if turn + jump > self.y[0])
        self.pieces: list[tuple[float, float, Any]] = []
        self.times: list[np.ndarray] = []
        self.states: list[np.ndarray] = []
        self.events: list[tuple[float, str]] = []
        self.finished = False
        # When a clutch engaged after the start found the machine held at rest for good (None: it did not).
        self.held_from: float | None = None
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
        sense = eq.sense
        if not eq.machine_held:
            events.append((_event(lambda t, y: sense * y[1], -1.0), "stopped"))
        if self.phase in (OPEN, SLIP_FORWARD, SLIP_BACKWARD) and not eq.driving_held:
            events.append((_event(lambda t, y: y[2], -1.0), "driving half stopped"))
        if self._jump is not None and not eq.machine_held:
            turn, k = self._jump
            at = turn + eq.machine.moment.jumps[k]
            events.append((_event(lambda t, y: sense * (y[0] - at), 1.0), _JUMP))
        return events

    def _aim_jumps(self) -> None:
        """Aim at the next jump of Mr the way the machine now moves, and take the piece it is on (it turns back)."""
        sense = self._jump_sense = self.eq.sense
        moment = self.eq.machine.moment
        if self._jump is None:
            return
        phi, count = self.y[0], len(moment.jumps)
        base = math.floor(phi / TWO_PI) * TWO_PI
        if sense > 0:
            self._jump = next((turn, k) for turn in (base, base + TWO_PI) for k, jump in enumerate(moment.jumps)
                              if turn + jump > phi)
            self.eq.piece = moment.pieces_from[self._jump[1] - 1]
        else:
            self._jump = next((turn, k) for turn in (base, base - TWO_PI) for k in reversed(range(count))
                              if turn + moment.jumps[k] < phi)
            self.eq.piece = moment.pieces_from[self._jump[1]]

    def _on_event(self, name: str) -> None:
        if name == _JUMP:  # not an event of the run: Mr goes on with its next piece
            moment = self.eq.machine.moment
            turn, k = self._jump
            if self._jump_sense < 0:  # turning back: on with the piece that ends at the jump
                self.eq.piece = moment.pieces_from[k - 1]
                self._jump = (turn, k - 1) if k > 0 else (turn - TWO_PI, len(moment.jumps) - 1)
                return
            self.eq.piece = moment.pieces_from[k]
            self._jump = (turn, k + 1) if k + 1 < len(moment.jumps) else (turn + TWO_PI, 0)
            return
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
        moving = self.eq.sense
        self._finish_if_held_at_rest()
        if name == "stopped" and not self.finished and self.phase == RIGID and self.eq.sense != moving:
            # At rest for an instant only: Mr outpulls the brake, and the machine turns back.
            self.events[-1] = (self.t, "turns back")

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
        """Whether the machine is at rest and held there for good: turning as one body, the motor switched off
        or too weak to move it at this angle; or, its clutch slipping forward, the clutch's capacity too small
        to move it while the motor keeps the driving half turning.  Nothing more will happen then, since no later
        switch (a brake, the motor off) drives it harder and a body at rest keeps its angle."""
        if self.y[1] > 0.0:
            return False
        if self.phase == SLIP_FORWARD:
            return self._held_by_slipping_clutch()
        if self.phase not in (RIGID, LOCKED):
            return False
        self.eq.settle(self.phase, self.t, self.y)
        return self.eq.machine_held

    def _held_by_slipping_clutch(self) -> bool:
        """The machine at rest against a clutch that slips at its capacity and will go on slipping: the driving
        half, ``J·dω_d/dt = Md(ω_d) − Tc``, slows down no further than the fastest speed below its own at which
        the motor gives the capacity or more (a speed the flow cannot pass), so while there is one above zero
        it never comes down to the machine's rest to lock.  Its own speed alone would not do: it settles where
        Md = Tc, which its rounding puts a hair either side."""
        eq = self.eq
        eq.settle(self.phase, self.t, self.y)
        if not (eq.machine_held and eq.motor_on(self.t)):
            return False
        speeds = self.y[2] * np.linspace(0.0, 1.0, 257)[1:]
        return any(eq.driving(self.t, speed) >= eq.clutch.torque for speed in speeds)

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
            # A clutch engaged later than the start that slips with the machine held at rest ends the run there, as
            # one engaged at the start does: the run went on to its end saying the machine "still speeds up at ω = 0".
            self._finish_if_held_at_rest()
            if self.finished:
                self.held_from = t
        elif self.phase == LOCKED and abs(self._needed_torque(t)) > eq.clutch.torque * (1.0 + 1e-12):
            self.events.append((t, "clutch slips"))
            self.phase = SLIP_FORWARD if self._needed_torque(t) > 0 else SLIP_BACKWARD

    # -- integration --

    def advance(self, t_end: float) -> None:
        while not self.finished and self.t < t_end:
            self.eq.clock = self.t
            self.eq.settle(self.phase, self.t, self.y)
            if self.eq.sense != self._jump_sense:
                self._aim_jumps()
            stop = min([b for b in self.boundaries if b > self.t] + [t_end])
            events = self._events()
            if self._restarted_at_jump and self.method != _ROBUST:
                # Started afresh at a jump of Mr, a multistep method may find no step it can take in a run of
                # extreme stiffness (LSODA, a turn in 4e13 s through a gear ratio of 1e15); the implicit
                # Runge–Kutta method needs no history and takes the segment.  The failed try's warnings are
                # its own, not the run's.
                with warnings.catch_warnings(record=True) as caught:
                    warnings.simplefilter("always")
                    solution = self._solved(stop, events)
                if solution.status == -1:
                    self.fallbacks.append(f"{self.method} could not start again at t = {self.t:.6g} s after a jump "
                                          f"of Mr ({solution.message}); {_ROBUST} took that stretch")
                    solution = self._solved(stop, events, _ROBUST)
                else:
                    for warning in caught:
                        warnings.showwarning(warning.message, warning.category, warning.filename, warning.lineno)
            else:
                solution = self._solved(stop, events)
            self._restarted_at_jump = False
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
            else:
                fired = None
            passed = self._passed_jump(solution, started)
            if passed is not None:
                # The jump of Mr was stepped over: cut the segment there and go on with the next piece.
                self.t, self.y = passed
                self.times[-1] = np.append(solution.t[solution.t < self.t], self.t)
                self.states[-1] = np.column_stack([solution.y[:, solution.t < self.t], self.y])
                self.pieces[-1] = (solution.t[0], self.t, solution.sol)
                fired = _JUMP
            if fired is not None:
                self._restarted_at_jump = fired == _JUMP
                self._count_stall(started)
                self._on_event(fired)
            elif stop in self.boundaries:
                self._on_boundary(stop)

    def _passed_jump(self, solution: Any, started: float) -> tuple[float, np.ndarray] | None:
        """Where a segment passed the jump of Mr ahead without its event seeing it, else None.

        The event is seen only where ``φ − φ_jump`` changes sign between the ends of a solver's step.  A machine
        coasting against a piecewise constant Mr is followed in long steps, and the moving equations go on
        smoothly through ω = 0: within one step φ passes the jump, turns back and ends below it, and the
        segment ends at the stop with the first piece's Mr carried on past its end.  Up to its end (the first
        rest, or a switch) the segment moves forward, so φ there is the farthest it came."""
        if self._jump is None or self.eq.machine_held or self.t <= started:
            return None
        turn, k = self._jump
        at = turn + self.eq.machine.moment.jumps[k]
        if not self.eq.sense * (self.y[0] - at) > 0:
            return None
        sol = solution.sol
        when = brentq(lambda s: float(sol(s)[0]) - at, started, self.t, xtol=1e-14 * max(1.0, abs(self.t)),
                      rtol=4 * np.finfo(float).eps)
        state = np.asarray(sol(when), dtype=float).copy()
        state[0] = at
        return when, state

    def _solved(self, stop: float, events: list[tuple[Callable[[float, np.ndarray], float], str]],
                method: str | None = None) -> Any:
        return solve_ivp(self._counted(self.eq.rhs(self.phase)), (self.t, stop), self.y, method=method or self.method,
                         rtol=self.rtol, atol=self.atol, dense_output=True, events=[e for e, _ in events] or None)

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
