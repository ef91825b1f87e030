"""A resisting moment that jumps (a press's punching, a load over part of the stroke) in the equation of motion.

The reduced moment is taken piece by piece between its jumps (:class:`PiecewiseMoment`), the integration stopped
at each jump, and the steady turn's extreme speeds found on the dense output, corners included.  Checked against
closed forms (constant torques: constant acceleration on each piece) and against an integration written here,
with the jumps as solve_ivp events, of the same equation.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from graphplan.cli import main
from graphplan.machine_motion import (
    ConstantTorque,
    KlossMotor,
    Machine,
    PiecewiseMoment,
    simulate,
)

TWO_PI = 2.0 * math.pi
PUNCH = (math.radians(200.0), math.radians(300.0))  # the punching's window on the turn
LIGHT, HEAVY = 500.0 / TWO_PI, 8000.0 / TWO_PI      # N·m: 500 W and 8 kW at 60 rpm


def press_moment() -> PiecewiseMoment:
    return PiecewiseMoment([0.0, PUNCH[0], PUNCH[0], PUNCH[1], PUNCH[1], TWO_PI],
                           [LIGHT, LIGHT, HEAVY, HEAVY, LIGHT, LIGHT])


def test_a_piecewise_moment_is_its_samples_between_its_jumps_and_jumps_where_an_angle_is_given_twice():
    moment = press_moment()
    assert moment.jumps == pytest.approx(PUNCH)
    for degrees, value in ((0, LIGHT), (100, LIGHT), (199.999, LIGHT), (200, HEAVY), (299.999, HEAVY), (300, LIGHT),
                           (359.999, LIGHT), (360 + 250, HEAVY), (-100, HEAVY), (-30, LIGHT)):
        assert moment(math.radians(degrees)) == pytest.approx(value, rel=1e-12), degrees
    # A smooth piece is its spline: a sine's samples every 10°, with a jump at 90°, give the sine between them.
    angles = np.concatenate([np.radians(np.arange(0, 91, 10)), np.radians(np.arange(90, 361, 10))])
    values = np.where(np.arange(angles.size) < 10, np.sin(angles), np.sin(angles) + 5.0)
    wavy = PiecewiseMoment(angles, values)
    assert wavy.jumps == pytest.approx((0.0, math.pi / 2)) or wavy.jumps == pytest.approx((math.pi / 2,))
    for degrees in (33.0, 57.0, 145.0, 271.0):
        phi = math.radians(degrees)
        assert wavy(phi) == pytest.approx(math.sin(phi) + (5.0 if degrees > 90 else 0.0), abs=2e-6)
    # Carried on past its end, a piece stays its own curve: what a solver's step looks at beyond a jump.
    piece = wavy.piece_at(math.radians(80.0))
    assert wavy.on_piece(piece, math.radians(91.0)) == pytest.approx(math.sin(math.radians(91.0)), abs=1e-4)


@pytest.mark.parametrize("method", ["RK45", "DOP853", "Radau", "LSODA"])
def test_against_constant_torques_each_piece_is_constant_acceleration(method):
    """J = 10 kg·m², M = 1000 N·m: ε = (M − Mr)/J on each piece, φ(t) a parabola from jump to jump."""
    inertia, torque, duration = 10.0, 1000.0, 1.2
    motion = simulate(Machine(inertia=inertia, resisting=press_moment()), ConstantTorque(torque), duration=duration,
                      rtol=1e-10, method=method)
    # The closed form, phase by phase.
    t, phi, omega, expected = 0.0, 0.0, 0.0, {}
    ends = [PUNCH[0], PUNCH[1], TWO_PI]
    k, base = 0, 0.0
    queries = (0.25, 0.5, 0.8, 1.2)
    while t < duration:
        resisting = HEAVY if k == 1 else LIGHT
        epsilon = (torque - resisting) / inertia
        target = base + ends[k]
        # φ + ω·τ + ½ε·τ² = target
        tau = (-omega + math.sqrt(omega * omega + 2.0 * epsilon * (target - phi))) / epsilon
        for q in queries:
            if t <= q < t + tau:
                s = q - t
                expected[q] = (phi + omega * s + 0.5 * epsilon * s * s, omega + epsilon * s)
        t, phi, omega = t + tau, target, omega + epsilon * tau
        k = (k + 1) % 3
        base += TWO_PI if k == 0 else 0.0
    found = motion.state_at(np.array(queries))
    for j, q in enumerate(queries):
        assert found[0, j] == pytest.approx(expected[q][0], rel=1e-8), q
        assert found[1, j] == pytest.approx(expected[q][1], rel=1e-8), q


def independent_press(motor: KlossMotor, inertia: float, until: float):
    """The press on its motor, integrated here with DOP853 at rtol 1e-12 between the jumps (events)."""
    def drive(omega: float) -> float:
        return motor.shaft_torque(omega)

    total = inertia + motor.reduced_inertia
    ends = [PUNCH[0], PUNCH[1], TWO_PI]
    y, t, k, base = np.array([0.0, 0.0]), 0.0, 0, 0.0
    pieces, corners = [], []
    while t < until:
        resisting, target = (HEAVY if k == 1 else LIGHT), base + ends[k]

        def rhs(_t, state, resisting=resisting):
            return [state[1], (drive(state[1]) - resisting) / total]

        def reached(_t, state, target=target):
            return state[0] - target

        reached.terminal, reached.direction = True, 1.0
        solution = solve_ivp(rhs, (t, until), y, method="DOP853", rtol=1e-12, atol=1e-12, events=reached,
                             dense_output=True)
        pieces.append((solution.t[0], solution.t[-1], solution.sol))
        t, y = solution.t[-1], solution.y[:, -1].copy()
        if solution.status == 1:
            y = solution.y_events[0][-1].copy()
            corners.append((t, y[1]))
            k = (k + 1) % 3
            base += TWO_PI if k == 0 else 0.0
    return pieces, corners


def test_the_steady_turn_of_a_press_whose_punching_jumps_is_the_exact_equations():
    """A press's 8 kW punching over 100° of a 60 rpm turn on an induction motor: ω has corners at the jumps, where
    its extremes are.  A spline through samples of Mr rang 12 % round each jump and the parabola through ω's samples
    overshot the corner: δ came out 0.04777 for 0.04764."""
    motor = KlossMotor(power=5500.0, synchronous_speed=1000 * math.pi / 30, rated_slip=0.04, overload=2.5,
                       gear_ratio=16.0, rotor_inertia=0.05)
    inertia = 2.0 + 474.408921929
    motion = simulate(Machine(inertia=inertia, resisting=press_moment()), motor)
    cycle = motion.steady.cycle
    pieces, corners = independent_press(motor, inertia, cycle.start + cycle.period)
    # The same turn, on the independent solution: its extremes at its corners or where dω/dt = 0 between them.
    times = np.linspace(cycle.start, cycle.start + cycle.period, 200_001)
    inside = [(sol, times[(times >= a) & (times < b)]) for a, b, sol in pieces]
    speeds = np.concatenate([sol(chosen)[1] for sol, chosen in inside if chosen.size])
    speeds = np.concatenate([speeds, [w for when, w in corners if cycle.start <= when <= cycle.start + cycle.period]])
    high, low = float(speeds.max()), float(speeds.min())
    assert cycle.max_speed == pytest.approx(high, rel=1e-7)
    assert cycle.min_speed == pytest.approx(low, rel=1e-7)
    assert cycle.delta == pytest.approx(2.0 * (high - low) / (high + low), rel=1e-5)


def test_a_scene_whose_load_diagram_jumps_runs_on_its_pieces(tmp_path):
    """The same press as a scene: its power diagram's jumps reach the equation of motion as jumps, and the steady
    values are those of the exact equations above."""
    scene = tmp_path / "press.toml"
    scene.write_text("""\
[scene]
title = "Crank press"
[dynamics]
rpm = 60
delta = 0.08
inertia = 2.0
resisting_power = [[0, 500], [200, 500], [200, 8000], [300, 8000], [300, 500], [360, 500]]
motor = { kind = "kloss", power = 5500.0, overload = 2.5, synchronous_rpm = 1000, rated_rpm = 960, gear_ratio = 16, rotor_inertia = 0.05 }
""", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    found = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]
    motor = KlossMotor(power=5500.0, synchronous_speed=1000 * math.pi / 30, rated_slip=0.04, overload=2.5,
                       gear_ratio=16.0, rotor_inertia=0.05)
    exact = simulate(Machine(inertia=2.0 + found["flywheel_inertia"], resisting=press_moment()), motor,
                     method="DOP853", rtol=1e-11).steady.cycle
    motion = found["motion"]
    assert motion["delta"] == pytest.approx(exact.delta, rel=1e-4)
    assert motion["omega_max"] == pytest.approx(exact.max_speed, rel=1e-6)
    assert motion["omega_min"] == pytest.approx(exact.min_speed, rel=1e-6)

    # The note's sentence reproduces its δ from the numbers it prints: (ωmax − ωmin) over the textbook's
    # ωm = (ωmax + ωmin)/2, which it names beside the time mean 2π/T (the two differ in the third digit).
    import re

    note = (out / "note.md").read_text(encoding="utf-8")
    high, low, delta, middle = (float(re.search(pattern, note).group(1)) for pattern in (
        r"ωmax = ([\d.]+) rad/s, ωmin", r"ωmin = ([\d.]+) rad/s;", r"δ = \(ωmax − ωmin\)/ωm = (\d+\.\d+)",
        r"ωm = \(ωmax \+ ωmin\)/2 = ([\d.]+)"))
    assert middle == pytest.approx((high + low) / 2, rel=1e-4)
    assert delta == pytest.approx((high - low) / middle, rel=1e-3)
    assert f"2π/T = {motion['omega_mean']:.5g}" in note


def test_a_linkage_whose_load_acts_over_part_of_the_stroke_gives_the_equation_of_motion_its_jumps():
    # The shaper's cut over 5…95 % of the working stroke: the model's sweep puts the two sides of each switch a
    # hair apart; the equation of motion takes them as one angle given twice, a jump, not as a spline's ramp.
    from pathlib import Path

    from graphplan.analysis import analyse
    from graphplan.loads import activity
    from graphplan.machine_dynamics import MachineDynamics
    from graphplan.motion import solve
    from graphplan.scene import loads

    root = Path(__file__).resolve().parent.parent
    text = (root / "fixtures" / "shaper_six_bar.toml").read_text(encoding="utf-8") + (
        '\n[dynamics]\ndelta = 0.05\nmotor = { kind = "kloss", power = 3000.0, overload = 2.2, '
        'synchronous_rpm = 1500.0, rated_rpm = 1440.0, gear_ratio = 24.7 }\n')
    analysis = analyse(loads(text))
    dynamics = MachineDynamics(analysis)
    angles, moments = dynamics.resisting
    jumps = np.flatnonzero(np.diff(angles) == 0)
    assert len(jumps) == 2
    positions, mechanism = analysis.positions, analysis.mechanism
    driver = mechanism.driver
    for k in jumps:
        # Just before and just after, the cut is off and on (or on and off): the window's ends.
        around = positions.values[0] + driver.sense * (angles[k] + np.array([-1e-6, 1e-6]))
        padded = np.concatenate([[positions.extremes[0]], around])
        acting = activity(mechanism, positions, solve(mechanism, padded, positions.reference))[:, 1:]
        assert acting[0, 0] != acting[0, 1]
        assert abs(moments[k + 1] - moments[k]) > 100.0  # N·m: the cut's 2 kN at the ram's speed ratio
    assert dynamics.motion.steady is not None


def test_a_jump_a_rounding_from_the_turns_end_is_a_jump_at_its_start():
    # A switch bisected to a hair before 2π, its two sides made one angle, and the sweep's last sample at 2π less
    # a rounding: one jump at 0 ≡ 2π, not a spline through three samples 1e-14 rad apart.
    hair = TWO_PI - 3e-12
    moment = PiecewiseMoment([0.0, 1.0, 2.0, 3.0, 3.0, 4.0, 5.0, 6.0, hair, hair],
                             [50.0, 50.0, 50.0, 50.0, 10.0, 10.0, 10.0, 10.0, 10.0, 50.0])
    assert moment.jumps == (0.0, 3.0)
    assert moment(0.0) == pytest.approx(50.0) and moment(6.2) == pytest.approx(10.0)
    assert moment(TWO_PI + 0.5) == pytest.approx(50.0) and moment(2.9) == pytest.approx(50.0)
