"""Run-downs against independent calculations: a coast-down against a resisting moment with jumps (each jump must be
taken where the shaft reaches it, however long the solver's steps while coasting), and a brake that cannot hold an
unbalanced crank at rest."""

from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import graphplan
from graphplan.starters import starter

# A machine known by its resisting diagram alone: piecewise constant Mr (N·m) with three jumps, a constant Je.
STEPS = [(0.0, 90.0, 40.0), (90.0, 200.0, 200.0), (200.0, 360.0, 10.0)]
INERTIA = 5.0


def _diagram_scene(start_deg: float, rpm: float, brake: float | None = None) -> dict:
    points = [[a, m] for a0, a1, m in STEPS for a in (a0, a1)]
    dynamics = {"rpm": rpm, "resisting_torque": points, "driving": "constant", "inertia": INERTIA,
                "motor": {"kind": "constant", "torque": 50.0, "off_at": 0.0},
                "start": {"rpm": rpm, "angle_deg": start_deg}}
    if brake is not None:
        dynamics["brake"] = {"torque": brake, "at": 0.0}
    return {"scene": {"title": "coast-down", "locale": "en"}, "dynamics": dynamics}


def _closed_form_stop(start_deg: float, omega: float, brake: float = 0.0) -> tuple[float, float]:
    """Where and when the coast stops: within each piece Je·ω²/2 falls by (Mr + brake)·Δφ and ω falls linearly
    in time at (Mr + brake)/Je. The stop's angle is counted from the start (degrees), not wrapped."""
    energy, t, travelled = 0.5 * INERTIA * omega ** 2, 0.0, 0.0
    angle = start_deg % 360.0
    while True:
        a1, moment = next((a1, m) for a0, a1, m in STEPS if a0 <= angle < a1)
        torque = moment + brake
        span = math.radians(a1 - angle)
        if energy > torque * span:
            after = math.sqrt(2.0 * (energy - torque * span) / INERTIA)
            t += INERTIA * (omega - after) / torque
            energy -= torque * span
            omega = after
            travelled += a1 - angle
            angle = a1 % 360.0
        else:
            t += INERTIA * omega / torque
            return t, travelled + math.degrees(energy / torque)


@pytest.mark.parametrize("start_deg", [0.0, 30.0, 89.0, 91.0, 150.0, 199.0, 250.0, 330.0])
@pytest.mark.parametrize("rpm", [20.0, 60.0])
def test_coast_down_takes_every_jump_of_the_resistance(start_deg, rpm):
    motion = graphplan.load(_diagram_scene(start_deg, rpm)).machine_dynamics().motion
    omega = rpm * math.pi / 30.0
    t_stop, travelled = _closed_form_stop(start_deg, omega)
    assert motion.stopped_at == pytest.approx(t_stop, rel=1e-6)
    assert math.degrees(float(motion.phi[-1] - motion.phi[0])) == pytest.approx(travelled, abs=1e-4)


@pytest.mark.parametrize(("rpm", "brake", "start_deg"),
                         [(20.0, 5.0, 330.0), (60.0, 15.0, 0.0), (60.0, 15.0, 180.0), (60.0, 60.0, 45.0)])
def test_braked_coast_down_takes_every_jump_of_the_resistance(rpm, brake, start_deg):
    motion = graphplan.load(_diagram_scene(start_deg, rpm, brake=brake)).machine_dynamics().motion
    t_stop, travelled = _closed_form_stop(start_deg, rpm * math.pi / 30.0, brake=brake)
    assert motion.stopped_at == pytest.approx(t_stop, rel=1e-6)
    assert math.degrees(float(motion.phi[-1] - motion.phi[0])) == pytest.approx(travelled, abs=1e-4)


def _fine_stop(inertia: float, mr, phi0: float, omega0: float, brake: float = 0.0) -> tuple[float, float]:
    """A fine fixed-step integration of J·dω/dt = −Mr(φ) − brake to the stop: steps of 0.2 ms, so that no jump
    of Mr can be stepped over, and the last step cut where ω reaches 0."""
    def rest(t, y):
        return y[1]
    rest.terminal, rest.direction = True, -1
    solution = solve_ivp(lambda t, y: [y[1], -(mr(y[0]) + brake) / inertia], (0.0, 100.0), [phi0, omega0],
                         events=rest, max_step=2e-4, rtol=1e-10, atol=1e-10)
    return float(solution.t_events[0][0]), float(solution.y_events[0][0][0])


@pytest.mark.parametrize("start_deg", [0.0, 30.0, 119.0, 121.0])
def test_press_starter_coasts_down_as_a_fine_step_integration(start_deg):
    """The ``flywheel`` starter (a press: Mr idles for a third of the turn and punches for two) coasting from
    100 rpm with the motor off: stopped where a fine-step integration of the same machine stops."""
    scene = tomllib.loads(starter("flywheel"))
    scene["dynamics"]["motor"]["off_at"] = 0.0
    scene["dynamics"]["start"] = {"rpm": 100.0, "angle_deg": start_deg}
    dynamics = graphplan.load(scene).machine_dynamics()
    motion = dynamics.motion
    machine = dynamics.machine
    inertia = machine.je(0.0) + dynamics.spec.motion.motor.reduced_inertia
    omega_m = 100.0 * math.pi / 30.0
    idle, punching = 367.7 / omega_m, 3677.0 / omega_m

    def mr(phi):
        return idle if math.degrees(phi) % 360.0 < 120.0 else punching
    t_stop, phi_stop = _fine_stop(inertia, mr, math.radians(start_deg), omega_m)
    assert motion.stopped_at == pytest.approx(t_stop, abs=2e-4)
    assert float(motion.phi[-1]) == pytest.approx(phi_stop, abs=2e-5)
    assert dynamics.rest_angle_deg() == pytest.approx(math.degrees(phi_stop) % 360.0, abs=1e-3)


def test_press_starter_runs_down_with_a_brake_as_a_fine_step_integration():
    """The starter switched off at 6 s with a 100 N·m brake: from its state then, the run-down ends where a
    fine-step integration ends it (at 10.11 s, 144.1°, not at 9.21 s, 36.1°, as a hunt's own model had it)."""
    scene = tomllib.loads(starter("flywheel"))
    scene["dynamics"]["motor"]["off_at"] = 6.0
    scene["dynamics"]["brake"] = {"torque": 100.0, "at": 6.0}
    dynamics = graphplan.load(scene).machine_dynamics()
    motion = dynamics.motion
    inertia = dynamics.machine.je(0.0) + dynamics.spec.motion.motor.reduced_inertia
    omega_m = 100.0 * math.pi / 30.0
    idle, punching = 367.7 / omega_m, 3677.0 / omega_m

    def mr(phi):
        return idle if math.degrees(phi) % 360.0 < 120.0 else punching
    phi0, omega0 = np.asarray(motion.state_at(6.0), dtype=float)
    t_stop, phi_stop = _fine_stop(inertia, mr, float(phi0), float(omega0), brake=100.0)
    assert motion.stopped_at == pytest.approx(6.0 + t_stop, abs=2e-4)
    assert float(motion.phi[-1]) == pytest.approx(phi_stop, abs=2e-5)


# An unbalanced crank: 20 kg at 0.05 m from its pivot (the rest of the linkage massless), run by a motor that is
# switched off at 1 s while a brake comes on. Its Mr is its weight's moment alone, m·g·r·cos θ.
MASS, RADIUS, G = 20.0, 0.05, 9.81


def _pendulum_scene(brake: float) -> dict:
    return {
        "scene": {"title": "unbalanced crank", "locale": "en", "gravity": G},
        "frame": {"link": 1, "points": {"O": [0.0, 0.0]}},
        "driver": {"kind": "crank", "link": 2, "pivot": "O", "joint": "A", "length": 0.06, "rpm": 600.0},
        "groups": [{"kind": "RRP", "links": [3, 4], "joints": ["A", "B"], "length": 0.24,
                    "guide": {"through": "O", "angle": 0.0}, "assembly": "forward"}],
        "points": {"S2": {"link": 2, "from": "O", "toward": "A", "at": RADIUS}},
        "links": {"2": {"mass": MASS, "centre": "S2", "inertia": 0.01}},
        "positions": {"count": 12, "number_from": 1},
        "dynamics": {"motor": {"kind": "kloss", "power": 4000.0, "overload": 2.2, "synchronous_rpm": 1500,
                               "rated_rpm": 1440, "gear_ratio": 2.4, "rotor_inertia": 0.01, "off_at": 1.0},
                     "brake": {"torque": brake, "at": 1.0}},
    }


def _weight_moment(theta: float) -> float:
    return MASS * G * RADIUS * math.cos(theta)


def _swing_to_rest(inertia: float, theta: float, omega: float, brake: float,
                   moment=_weight_moment, max_step: float = 1e-3) -> tuple[float, float, int]:
    """The crank from (θ, ω) with the motor off: J·dω/dt = −Mr(θ) − brake·sign(ω), Mr the weight's moment
    m·g·r·cos θ, the brake holding it at rest while that moment is within its torque. When and where it rests for
    good, and how often it turned back on the way."""
    t, turned_back = 0.0, 0
    while True:
        sense = 1.0 if omega > 0 or (omega == 0 and -moment(theta) > 0) else -1.0

        def rest(_, y, sense=sense):
            return sense * y[1]
        rest.terminal, rest.direction = True, -1
        solution = solve_ivp(lambda _, y, sense=sense: [y[1], (-moment(y[0]) - sense * brake) / inertia],
                             (t, t + 100.0), [theta, omega], events=rest, rtol=1e-12, atol=1e-12, max_step=max_step)
        t, theta, omega = float(solution.t_events[0][0]), float(solution.y_events[0][0][0]), 0.0
        if abs(moment(theta)) <= brake:
            return t, theta, turned_back
        turned_back += 1


@pytest.mark.parametrize("brake", [2.0, 5.0, 6.0, 9.0, 12.0])
def test_a_brake_holds_an_unbalanced_crank_only_where_its_torque_outdoes_the_weight(brake):
    dynamics = graphplan.load(_pendulum_scene(brake)).machine_dynamics()
    motion = dynamics.motion
    rest = math.radians(dynamics.rest_angle_deg())
    assert abs(_weight_moment(rest)) <= brake * (1 + 1e-9)  # the brake holds it where it rests
    model = dynamics.model
    for when, name in motion.events:
        if name == "turns back":  # and where it turned back, the weight outpulled the brake
            phi = float(motion.state_at(when)[0])
            assert abs(_weight_moment(float(model.driver[0]) + model.sense * phi)) > brake
    # The same crank integrated here from its state when the motor goes off.
    inertia = dynamics.machine.je(0.0) + dynamics.spec.motion.motor.reduced_inertia
    assert dynamics.machine.je(2.0) == pytest.approx(dynamics.machine.je(0.0), rel=1e-9)
    phi0, omega0 = (float(v) for v in motion.state_at(1.0))
    t_rest, theta, turned_back = _swing_to_rest(inertia, float(model.driver[0]) + model.sense * phi0,
                                                model.sense * omega0, brake)
    assert motion.stopped_at == pytest.approx(1.0 + t_rest, abs=1e-4)
    assert dynamics.rest_angle_deg() == pytest.approx(math.degrees(theta) % 360.0, abs=1e-3)
    assert sum(name == "turns back" for _, name in motion.events) == turned_back
    assert dynamics.machine.reversible


@pytest.mark.parametrize(("start", "omega"), [(0.5, 3.0), (1.0, 0.0), (5.5, 6.0), (3.0, 9.0)])
def test_a_machine_that_turns_back_takes_the_jumps_of_its_moment_either_way(start, omega):
    """A reversible Mr with two jumps (6·cos φ + 3 up to φ = 2 rad, 6·cos φ − 6/(2π − 2) from there to the
    turn's end: no work over a turn, as weights that act both ways) and a 2 N·m brake: the machine swings across the jumps both ways until the brake
    holds it, as a fine-step integration has it."""
    from graphplan.machine_motion import Brake, ConstantTorque, Machine, PiecewiseMoment, Start, simulate
    LOW = -6.0 / (2.0 * math.pi - 2.0)

    def exact(phi):
        phi %= 2.0 * math.pi
        return 6.0 * math.cos(phi) + (LOW if phi >= 2.0 else 3.0)
    first, second = np.linspace(0.0, 2.0, 81), np.linspace(2.0, 2.0 * math.pi, 201)
    moment = PiecewiseMoment(np.concatenate([first, second]),
                             np.concatenate([6.0 * np.cos(first) + 3.0, 6.0 * np.cos(second) + LOW]))
    machine = Machine(inertia=0.5, resisting=moment, reversible=True)
    motion = simulate(machine, ConstantTorque(0.0), start=Start(omega=omega, angle=start),
                      brake=Brake(torque=2.0, at=0.0), motor_off_at=0.0, rtol=1e-10)
    t_rest, phi, turned_back = _swing_to_rest(0.5, start, omega, 2.0, moment=exact, max_step=1e-4)
    assert turned_back >= 1
    assert sum(name == "turns back" for _, name in motion.events) == turned_back
    assert motion.stopped_at == pytest.approx(t_rest, abs=1e-4)
    assert float(motion.phi[-1]) == pytest.approx(phi, abs=1e-4)


@pytest.mark.parametrize("damping", [None, 0.05])
def test_a_run_down_with_nothing_to_take_its_energy_is_told_so(damping, tmp_path):
    """The unbalanced crank switched off with no brake (or a brake of damping alone): its weight gives back over a
    turn what it takes, so it never comes to rest. It was run until the equation of motion had been evaluated
    300000 times and blamed on the motor's speed, the gear ratio and the inertias."""
    from graphplan.cli import main
    from graphplan.errors import GraphplanError

    scene = _pendulum_scene(5.0)
    if damping is None:
        del scene["dynamics"]["brake"]
    else:
        scene["dynamics"]["brake"] = {"torque": 0.0, "damping": damping, "at": 1.0}
    with pytest.raises(GraphplanError) as caught:
        assert graphplan.load(scene).machine_dynamics().motion is None  # raises first
    told = str(caught.value)
    assert "nothing to take its energy" in told and "never comes to rest" in told and "brake" in told
    assert "too slow or too stiff" not in told and "gear ratio" not in told
    assert ("only in the limit" in told) == (damping is not None)
    # check says the same, before anything is integrated.
    from test_scene_errors import to_toml
    path = tmp_path / "swing.toml"
    path.write_text(to_toml(scene), encoding="utf-8")
    assert main(["check", str(path)]) == 2
