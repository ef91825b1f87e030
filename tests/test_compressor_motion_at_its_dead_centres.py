"""A compressor's motion where its loads switch at the dead centres, against an integration written here.

A single-acting compressor: the compression diagram on the forward stroke, 200 N of suction on the backward one,
the cycle starting at the bottom dead centre.  Both loads switch where the piston stands still, so Mr has corners
there but no jump; the sweep finds each switch a hair (10⁻⁹…10⁻⁶ rad) off the dead centre, and a rounding's
difference between the two sides once passed for a jump, whose near-coincident samples made the integrator's
spline ring by ±100 N·m over the first degree of the turn: a false stall at 0.2°.  The machine here is written
afresh from the slider-crank's closed form (velocity ratios by central differences, the loads by the stroke's
share), integrated with solve_ivp.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid, quad, solve_ivp

from graphplan.analysis import analyse
from graphplan.machine_dynamics import MachineDynamics
from graphplan.machine_motion import PiecewiseMoment
from graphplan.machine_motion.moment import exact_jumps
from graphplan.scene import loads

R, L, A3 = 0.06, 0.24, 0.08                   # crank, rod, rod's centre from A (m)
M2, J2, M3, J3, M4 = 5.0, 0.02, 2.0, 0.012, 3.0
G = 9.81
COMPRESSION = ([0.0, 0.5, 0.8, 0.9, 1.0], [0.0, 300.0, 1500.0, 4000.0, 4000.0])
SUCTION = 200.0
# A Kloss motor through a gear: 1.5 kW, λ = 2.2, 1500/1440 rpm, u = 2.9, its rotor 0.003 kg·m².
POWER, OVERLOAD, SYNCHRONOUS, RATED, GEAR, ROTOR = 1500.0, 2.2, 1500.0, 1440.0, 2.9, 0.003

SCENE = f"""
[scene]
title = "Compressor"
gravity = {G}

[frame]
link = 1
points = {{ O = [0.0, 0.0] }}

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {R}
rpm = 600.0

[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = {L}
guide = {{ through = "O", angle = 0.0 }}
assembly = "forward"

[points]
S3 = {{ link = 3, from = "A", toward = "B", at = {A3} }}

[links.2]
mass = {M2}
centre = "O"
inertia = {J2}
[links.3]
mass = {M3}
centre = "S3"
inertia = {J3}
[links.4]
mass = {M4}
centre = "B"

[[loads]]
kind = "force"
link = 4
point = "B"
angle = 0.0
resisting = true
diagram = [[0.0, 0.0], [0.5, 300.0], [0.8, 1500.0], [0.9, 4000.0], [1.0, 4000.0]]

[[loads]]
kind = "force"
link = 4
point = "B"
angle = 0.0
resisting = true
stroke = {{ link = 4, sense = "backward" }}
diagram = [[0.0, {SUCTION}], [1.0, {SUCTION}]]

[positions]
count = 12
start = "extreme"
working = {{ link = 4, sense = "forward" }}

[drawing]
sheet = "none"
"""


def _b(phi):
    return R * np.cos(phi) + np.sqrt(L * L - (R * np.sin(phi)) ** 2)


def _s3(phi):
    a = R * np.exp(1j * phi)
    return a + A3 * (_b(phi) - a) / L


def _rod(phi):
    return np.angle(_b(phi) - R * np.exp(1j * phi))


def _rate(function, phi, h=1e-6):
    return (function(phi + h) - function(phi - h)) / (2 * h)


def inertia(psi):
    """Je at the travel ψ from the bottom dead centre (φ = π + ψ)."""
    phi = math.pi + psi
    return J2 + M3 * abs(_rate(_s3, phi)) ** 2 + J3 * _rate(_rod, phi) ** 2 + M4 * _rate(_b, phi) ** 2


def resistance(psi):
    """Mr (N·m, positive where it resists): the gas on the piston against its motion, and the rod's weight."""
    phi = math.pi + psi
    speed = _rate(_b, phi)
    if psi % (2 * math.pi) < math.pi:   # forward, from the bottom dead centre: compression by the stroke's share
        force = np.interp((_b(phi) - (L - R)) / (2 * R), *COMPRESSION)
    else:
        force = SUCTION
    return force * abs(speed) + G * M3 * _rate(_s3, phi).imag


def machine_dynamics(motion: str = "", rpm: float = 500.0) -> MachineDynamics:
    return MachineDynamics(analyse(loads(SCENE + f"\n[dynamics]\ndelta = 0.2\nrpm = {rpm}\n" + motion)))


def test_the_integrators_resistance_is_the_compressors_own_at_the_dead_centre_where_its_turn_starts():
    dynamics = machine_dynamics('motor = { kind = "constant", torque = 30.0 }\n')
    near = np.radians(np.concatenate([np.linspace(0.0, 3.0, 301), np.linspace(357.0, 360.0, 301)]))
    exact = np.array([resistance(psi) for psi in near])
    taken = np.array([dynamics.machine.mr(psi, 1.0) for psi in near])
    peak = max(abs(resistance(psi)) for psi in np.linspace(0.0, 2 * math.pi, 721))
    # The ringing was ±102 N·m of a 159 N·m peak; the samples there lie within 0.06 N·m of one another.
    assert np.max(np.abs(taken - exact)) < 1e-4 * peak
    assert taken.min() >= exact.min() - 1e-4 * peak and taken.max() <= exact.max() + 1e-4 * peak


def test_a_rounding_between_the_two_sides_of_a_switch_is_no_jump_and_a_real_step_is():
    angles = np.array([0.0, 1.0, 2.0, 2.0 + 1e-14, 3.0, 4.0, 5.0, 6.0, 2 * math.pi])
    # 2.6e-7 N·m on a 159 N·m scale: a load of 4 kN switched at a dead centre found a hair off it.
    values = np.array([0.0, 80.0, 159.0, 159.0 + 2.6e-7, 100.0, 50.0, 20.0, 5.0, 0.0])
    x, y = exact_jumps(angles, values)
    corner = np.flatnonzero(np.diff(x) == 0)
    assert len(corner) == 1 and y[corner[0]] == y[corner[0] + 1]  # a corner: one angle twice, one value
    stepped = values.copy()
    stepped[3:8] += 40.0
    x, y = exact_jumps(angles, stepped)
    k = np.flatnonzero(np.diff(x) == 0)[0]
    assert y[k + 1] - y[k] == pytest.approx(40.0 + 2.6e-7)


def test_samples_crowding_the_seam_of_the_turn_do_not_make_its_spline_ring():
    # A smooth moment with a step up at 90° and down at 270°, and at the turn's seam, inside the piece carried on
    # from 270° into the turn's first, what a sweep leaves: a sample 1.4e-9 rad before 2π and one 1.6e-6 rad
    # after 0, whose values differ from their neighbours' by roundings, not by the curve.
    def curve(phi):
        return 10.0 + 3.0 * np.cos(phi) + (20.0 if math.pi / 2 <= phi % (2 * math.pi) < 1.5 * math.pi else 0.0)

    steps = np.linspace(0.0, 2 * math.pi, 73)
    angles = np.sort(np.concatenate([steps, [1.63e-6, math.pi / 2, 1.5 * math.pi, 2 * math.pi - 1.4e-9]]))
    values = np.array([curve(phi) for phi in angles])
    for place in (math.pi / 2, 1.5 * math.pi):   # the first of the two samples is the value reached from the left
        first = int(np.flatnonzero(np.isclose(angles, place, rtol=0.0, atol=1e-12))[0])
        angles[first + 1] = angles[first]
        values[first] = curve(place - 1e-9)
    values[1] += 1.2e-8
    values[-2] -= 1.2e-8
    moment = PiecewiseMoment(angles, values)
    assert moment.jumps == pytest.approx((math.pi / 2, 1.5 * math.pi))
    near = np.radians(np.linspace(-3.0, 3.0, 601))
    taken = np.array([moment(phi) for phi in near])
    exact = np.array([curve(phi) for phi in near])
    # A quintic spline through the curve's samples every 5° is good to 1e-6; through the crowded ones it rang.
    assert np.max(np.abs(taken - exact)) < 1e-6 * 33.0


def test_a_compressor_started_from_rest_stalls_at_its_compression_peak_as_an_integration_written_here_does():
    dynamics = machine_dynamics(f'motor = {{ kind = "kloss", power = {POWER}, overload = {OVERLOAD}, '
                                f'synchronous_rpm = {SYNCHRONOUS}, rated_rpm = {RATED}, gear_ratio = {GEAR}, '
                                f'rotor_inertia = {ROTOR} }}\n')
    motion = dynamics.motion
    flywheel = dynamics.flywheel_inertia   # the flywheel mounted is the run's input; its size is checked elsewhere

    synchronous = SYNCHRONOUS * math.pi / 30
    rated_slip = 1.0 - RATED / SYNCHRONOUS
    greatest = OVERLOAD * POWER / (RATED * math.pi / 30)
    critical = rated_slip * (OVERLOAD + math.sqrt(OVERLOAD ** 2 - 1.0))

    def driving(omega):
        slip = 1.0 - GEAR * omega / synchronous
        return GEAR * 2.0 * greatest / (slip / critical + critical / slip)

    def slope(psi):
        return (inertia(psi + 1e-5) - inertia(psi - 1e-5)) / 2e-5

    def equations(t, state):
        psi, omega = state
        return [omega, (driving(omega) - resistance(psi) - 0.5 * slope(psi) * omega ** 2)
                / (inertia(psi) + flywheel + ROTOR * GEAR ** 2)]

    def stops(t, state):
        return state[1] if t > 1e-3 else 1.0
    stops.terminal, stops.direction = True, -1
    solution = solve_ivp(equations, (0.0, 3.0), [0.0, 0.0], rtol=1e-10, atol=1e-12, max_step=2e-4, events=stops)
    stall_time, stall_travel = solution.t[-1], solution.y[0, -1]
    assert 0.1 < stall_time < 0.3 and math.radians(140.0) < stall_travel < math.radians(160.0)

    assert motion.stalled_at == pytest.approx(stall_time, rel=2e-3)
    assert math.degrees(motion.phi[-1]) == pytest.approx(math.degrees(stall_travel), abs=0.1)
    # The crank's own angle: position 1 is the bottom dead centre, 180°.
    assert dynamics.stall_angle_deg() == pytest.approx(180.0 + math.degrees(stall_travel), abs=0.1)


def _smooth_stretches():
    """The travels between the corners of Mr: the dead centres and the compression diagram's vertices."""
    shares = np.array(COMPRESSION[0][1:-1])
    # The piston's share of the forward stroke at travel ψ is (B − (L − R))/2R; solved for ψ by bisection.
    corners = []
    for share in shares:
        low, high = 0.0, math.pi
        for _ in range(200):
            middle = 0.5 * (low + high)
            if (_b(math.pi + middle) - (L - R)) / (2 * R) < share:
                low = middle
            else:
                high = middle
        corners.append(low)
    ends = [0.0, *corners, math.pi, 2 * math.pi]
    return list(itertools.pairwise(ends))



def exact_mean() -> float:
    """Mr's mean over the turn, by adaptive quadrature between its corners."""
    return sum(quad(resistance, a, b, limit=200, epsabs=1e-12)[0] for a, b in _smooth_stretches()) / (2 * math.pi)


def test_the_integrators_resistance_keeps_the_compression_diagrams_corners_and_its_mean():
    dynamics = machine_dynamics('motor = { kind = "constant", torque = 30.0 }\n')
    moment = dynamics.machine.resisting
    turn = np.linspace(0.0, 2 * math.pi, 3601)
    exact = np.array([resistance(psi) for psi in turn])
    taken = np.array([dynamics.machine.mr(psi, 1.0) for psi in turn])
    # A spline through the corners of the diagram's vertices rang by 0.7 N·m of the 159 N·m peak.
    assert np.max(np.abs(taken - exact)) < 1e-4 * np.max(np.abs(exact))
    assert isinstance(moment, PiecewiseMoment)
    mean = exact_mean()
    assert moment.mean() == pytest.approx(mean, rel=1e-7)
    # The constant driving moment the flywheel is sized with balances the same work (the trapezoid's: 1e-4 less).
    assert dynamics.model.driving[0] == pytest.approx(mean, rel=1e-7)


def test_a_constant_motor_at_the_mean_resistance_turns_the_compressor_periodically():
    # Md = the exact mean of Mr: the energy integral ½·J(φ)·ω² = ½·J(0)·ω0² + ∫(Md − Mr) dφ then repeats every
    # turn.  The integrator's Mr, 0.17 N·m above it on the average, slowed it by 0.17 rad/s a turn.
    mean, omega0 = exact_mean(), 1500.0 * math.pi / 30
    dynamics = machine_dynamics(f'motor = {{ kind = "constant", torque = {mean!r} }}\n'
                                f'start = {{ omega = {omega0!r}, angle_deg = 180.0 }}\nduration = 0.3\n', rpm=1500.0)
    motion = dynamics.motion
    fastest = np.array([cycle.max_speed for cycle in motion.cycles])
    assert len(fastest) >= 6
    assert np.ptp(fastest) < 1e-6 * fastest[0]

    travel = np.linspace(0.0, 2 * math.pi, 72_001)
    shaft = np.array([inertia(psi) for psi in travel]) + dynamics.flywheel_inertia
    surplus = cumulative_trapezoid(mean - np.array([resistance(psi) for psi in travel]), travel, initial=0.0)
    speed = np.sqrt((shaft[0] * omega0 ** 2 + 2.0 * surplus) / shaft)
    assert fastest == pytest.approx(np.max(speed), rel=1e-6)
