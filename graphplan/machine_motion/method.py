"""The running speed of a machine and the solver its equations call for: stiff or not."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from scipy.integrate import RK45
from scipy.optimize import brentq

from .drive import REST, Brake, Clutch, Motor, Start
from .integrator import Equations
from .shaft import TWO_PI, Machine, periodic_spline

# Above this value of (largest decay rate |∂f/∂ω|) × (the step RK45 takes for accuracy) the explicit
# step would be held by stability instead: Dormand–Prince's RK45 is stable on the negative real
# axis up to h·|λ| ≈ 3.3.
STIFFNESS_THRESHOLD = 3.0
# The angles over a turn at which the mean resistance and inertia are taken.
_TURN = np.linspace(0.0, TWO_PI, 64, endpoint=False)
# The angles over a turn at which a resistance given as a function is averaged, and the work it takes summed, for
# a verdict on a runaway: a reduced moment has kinks at the dead centres (a load switched on where the speed is
# nought), where 64 equal steps missed the mean by 1e-3 of it.
_FINE_TURN = np.linspace(0.0, TWO_PI, 4096, endpoint=False)


class EndlessRun(ValueError):
    """A run that could not end, refused before anything is integrated.

    ``problem`` says why in words; ``key`` is the argument of :func:`~graphplan.machine_motion.simulate` it is told
    at, ``scene_key`` the key below the scene's ``[dynamics]`` table that asked for it (``motor.off_at``), so that a
    scene's refusal names the key as the user typed it rather than the argument."""

    def __init__(self, key: str, scene_key: str, problem: str) -> None:
        self.key = key
        self.scene_key = scene_key
        self.problem = problem
        super().__init__(f"{key}: {problem}")


def _over_a_turn(function: Callable[[float], float]) -> float:
    """The mean of ``function`` of the crank angle over a turn, on equal steps (the trapezoidal rule of a periodic
    function)."""
    return float(np.mean([function(phi) for phi in _TURN]))


def running_speed(machine: Machine, motor: Motor, start: Start = REST, duration: float | None = None) -> float:
    """A scale for the running speed of the shaft, rad/s, where the motor's torque meets the mean resistance.

    Used to judge stiffness and the cycle time; for a constant torque against a resistance that
    does not grow with speed there is no such speed, and the start's speed (or the speed reached
    after ``duration`` at the mean surplus torque) stands in.
    """
    surplus = _mean_surplus(machine, motor)
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
    inertia = _over_a_turn(machine.je) + motor.reduced_inertia
    reached = given + max(surplus(given), 0.0) / inertia * (duration or 1.0)
    return max(reached, 1e-3)


def run_down_time(machine: Machine, inertia: float, speed: float, brake_torque: float = 0.0) -> float | None:
    """How long the machine of reduced inertia Je (mean over a turn) plus ``inertia`` takes to come to rest from
    ``speed`` against its mean resistance at rest and a brake's torque, at that deceleration: (J·ω)/M.  None where
    nothing but the speed holds it back (a damping alone stops it only in the limit)."""
    holding = _over_a_turn(lambda phi: machine.mr(phi, 0.0)) + brake_torque
    if not holding > 0:
        return None
    total = _over_a_turn(machine.je) + inertia
    return total * speed / holding


def speeds_up_without_end(machine: Machine, motor: Motor) -> tuple[float, float] | None:
    """(the motor's torque, the mean resistance) where a motor whose torque does not fall with speed (a constant
    one) outpulls the mean resistance at every speed up to 2³⁰ rad/s: the machine has no steady state.  None
    where some speed balances them."""
    if motor.shaft_no_load_speed is not None:
        return None
    surplus = _mean_surplus(machine, motor)
    # A torque equal to the mean resistance but for rounding balances it at any speed: no runaway.
    if any(surplus(omega) <= 1e-9 * abs(motor.shaft_torque(omega)) for omega in 2.0 ** np.arange(0, 31)):
        return None
    fastest = 2.0 ** 30
    return motor.shaft_torque(fastest), motor.shaft_torque(fastest) - surplus(fastest)


def runaway_time_to(machine: Machine, motor: Motor, start: Start, speed: float) -> tuple[float, float] | None:
    """(the time, s, and the turns) a motor that outpulls the mean resistance at every speed
    (:func:`speeds_up_without_end`) takes to run the machine from ``start`` up to ``speed``, at the mean surplus at
    the start's speed, as :func:`running_speed` reaches the run's end with it; None where it does not outpull, or the
    start is already as fast."""
    if speeds_up_without_end(machine, motor) is None:
        return None
    given = max(start.omega, start.driving_omega or 0.0)
    surplus = _mean_surplus(machine, motor)(given)
    if not (surplus > 0 and speed > given):
        return None
    inertia = _over_a_turn(machine.je) + motor.reduced_inertia
    return inertia * (speed - given) / surplus, inertia * (speed ** 2 - given ** 2) / (2.0 * surplus) / TWO_PI


def stalls_in_its_first_turn(machine: Machine, motor: Motor, start: Start = REST) -> bool:
    """Whether a machine whose resistance depends on the angle alone, driven through a rigid drive by a motor of
    constant torque, comes to rest within its first turn from ``start``.

    The equation of motion is d(½·(Je + Jrotor)·ω²)/dφ = Md − Mr(φ): the kinetic energy at the start plus the
    work of Md − Mr from there must stay above nought.  Where the work over a turn is a surplus, every later turn
    starts with more energy than this one did, so a machine that passes its first turn never stalls."""
    phi0 = start.angle
    angles = phi0 + np.append(_FINE_TURN, TWO_PI)
    surplus = np.array([motor.shaft_torque(0.0) - machine.mr(phi, 0.0) for phi in angles])
    work = np.concatenate(([0.0], np.cumsum(0.5 * (surplus[1:] + surplus[:-1]) * np.diff(angles))))
    energy = 0.5 * (machine.je(phi0) + motor.reduced_inertia) * start.omega ** 2
    return bool(energy + np.min(work[1:]) <= 0.0) or (start.omega == 0.0 and surplus[0] <= 0.0)


def refuse_runaway(machine: Machine, motor: Motor, to_the_steady_state: bool = True, start: Start = REST,
                   clutch: Clutch | None = None) -> None:
    """Raise :class:`EndlessRun` (a :class:`ValueError`) where a run goes on ``to_the_steady_state`` (no duration,
    brake or switching off ends it) and the motor outpulls the resistance at every speed
    (:func:`speeds_up_without_end`): it would never end.  A motor that outpulls the mean resistance but not its
    peaks may stall from ``start`` before it gains the speed to carry the machine past them
    (:func:`stalls_in_its_first_turn`): that run ends at the stall, and is not refused."""
    if not to_the_steady_state:
        return
    outpulled = speeds_up_without_end(machine, motor)
    if outpulled is not None and clutch is None and machine.resists_by_angle_alone \
            and stalls_in_its_first_turn(machine, motor, start):
        return
    if outpulled is not None and clutch is not None and clutch.torque <= outpulled[1]:
        # The machine's side is driven by what the clutch passes, no more than its torque: short of the mean
        # resistance, the machine loses speed turn by turn however fast the motor spins the driving half, and comes
        # to rest where Mr outpulls the clutch (from rest, at once) and is held there: the run ends at that stall.
        return
    if outpulled is not None:
        from ..render.numerals import number

        # The torque on the shaft is the motor's times its gear ratio: the motor's table as a whole is told.  Both
        # as the note and the console's warning of a run given a duration write them: 245.79, where 245.789 read
        # as another number.
        raise EndlessRun("motor", "motor", f"its torque on the shaft, {number(outpulled[0])} N·m, exceeds the mean "
                         f"resistance, {number(outpulled[1])} N·m, at every speed: the machine speeds up without end "
                         "and has no steady state; give a dynamics.duration (s), more resistance, or a motor whose "
                         "torque falls with speed (dynamics.motor kind = \"linear\" or \"kloss\")")


def refuse_endless_run_down(machine: Machine, brake: Brake | None) -> None:
    """Raise :class:`EndlessRun` (a :class:`ValueError`) for a run-down (the motor switched off, no duration) that
    nothing brings to rest: the resistance at rest takes no work over a turn on the average (the weights alone give
    back on the way down what they take on the way up) and no brake's torque holds the machine, so that it turns,
    or swings, for ever.  A brake's damping alone slows it only in the limit."""
    brake_torque, brake_damping = (brake.torque, brake.damping) if brake is not None else (0.0, 0.0)
    values = [machine.mr(phi, 0.0) for phi in _FINE_TURN]
    resisting = float(np.mean(values))
    scale = max(abs(v) for v in values)
    # The weights' moment averages to nought but for rounding, either side of it.
    if resisting + brake_torque > 1e-9 * scale:
        return
    if abs(resisting) <= 1e-9 * scale:
        resisting = 0.0
    damping = (f"; the brake's damping, {brake_damping:g} N·m·s, slows it only in the limit and never to rest"
               if brake_damping > 0 else "")
    raise EndlessRun("motor_off_at", "motor.off_at", "switches the motor off, and the machine has nothing to take "
                     f"its energy: its resistance, {resisting:.4g} N·m on the average over a turn, takes no work from "
                     "it turn by turn (weights give back on the way down what they take on the way up) and no brake "
                     f"holds it{damping}, so it never comes to rest; give a brake that holds it, dynamics.brake = "
                     "{ torque, damping, at } with torque > 0 (N·m; at: when it comes on, s), or a "
                     "dynamics.duration (s)")


def _mean_surplus(machine: Machine, motor: Motor):
    """The motor's torque less the resistance's mean over a turn, as a function of the speed (N·m).

    A resistance with jumps depends on the angle alone and is integrated piece by piece, and samples over
    the turn through the periodic spline the machine takes them by; a function of the angle and speed is
    averaged over :data:`_FINE_TURN`'s equal steps."""
    if machine.resists_by_angle_alone:
        mean = mean_resistance(machine)
        return lambda omega: motor.shaft_torque(omega) - mean

    def surplus(omega: float) -> float:
        return motor.shaft_torque(omega) - float(np.mean([machine.mr(phi, omega) for phi in _FINE_TURN]))
    return surplus


def mean_resistance(machine: Machine) -> float:
    """The mean over a turn of a resistance that depends on the angle alone, N·m: integrated exactly as the
    machine takes it (piece by piece where it jumps, the periodic spline through samples)."""
    if machine.moment is not None:
        return machine.moment.mean()
    values = np.asarray(machine.resisting, dtype=float)
    if values.ndim == 0:
        return float(values)
    return float(periodic_spline(values).integrate(0.0, TWO_PI)) / TWO_PI


def is_stiff(stiffness: float) -> bool:
    """Whether a stiffness number (:func:`choose_method`) calls for an implicit method."""
    return stiffness > STIFFNESS_THRESHOLD


def choose_method(equations: Equations, omega_run: float, rtol: float, atol: float) -> tuple[str, str, float]:
    """The solver for these equations, the reason in words, and the stiffness number.

    The stiffness number is the largest decay rate ``−∂(dω/dt)/∂ω`` over a turn and over speeds
    up to the running speed and the motor's no-load speed (a steep motor characteristic gives most of
    it: ``|dMd/dω|/J``),
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
    # An induction motor is steepest at nought slip (M′ = 2·Mmax/sk), a little above the running speed and
    # between the probes above: its synchronous speed on the shaft is probed too.
    if motor.shaft_no_load_speed is not None:
        speeds = np.append(speeds, motor.shaft_no_load_speed)
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
    # The threshold follows the stiffness number it is set against; the cycle, a time, comes after it.
    number = (f"largest decay rate |∂f/∂ω| = {decay:.3g} 1/s (time constant {1 / decay:.3g} s) × RK45's step "
              f"for accuracy {step:.3g} s = {stiffness:.3g}") if decay > 0 else \
             f"no decaying mode: |∂f/∂ω| = 0 × RK45's step for accuracy {step:.3g} s = {stiffness:.3g}"
    cycle = f"cycle {period:.3g} s"
    if is_stiff(stiffness):
        return "LSODA", (f"auto: stiff, stability would hold the explicit step ({number} > {STIFFNESS_THRESHOLD}; "
                         f"{cycle}): LSODA"), stiffness
    method = "DOP853" if rtol < 1e-8 else "RK45"
    return method, f"auto: not stiff ({number} ≤ {STIFFNESS_THRESHOLD}; {cycle}): {method}", stiffness


def _explicit_step(equations: Equations, omega_run: float, rtol: float, atol: float) -> float:
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
