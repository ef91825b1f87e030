"""The ratchet crank-rocker against the exact values of its worked example.

Source: ../shared/fixtures-data.md, "What the example printed, and what the exact solution gives":
the exact column at position 5, ω4 at position 11, the extended dead centre at φ = 115.048°, and the
working stroke of 169.95° of crank rotation.  Those values were computed for this geometry
independently of graphplan; they are printed to 4–5 significant digits, so they are checked to half
a unit of the last printed digit.
"""

import math

import numpy as np
import pytest

import graphplan
from graphplan.positions import make_positions

FIXTURE = "fixtures/ratchet_crank_rocker.toml"


@pytest.fixture(scope="module")
def motion():
    return graphplan.solve(graphplan.load(FIXTURE))


def speed(vectors, index):
    return float(np.hypot(*vectors[index]))


@pytest.mark.parametrize("point, printed_v", [("B", 0.7005), ("S3", 1.7452), ("E", 1.6002)])
def test_velocities_at_position_5(motion, point, printed_v):
    assert speed(motion.point(point).v, 5) == pytest.approx(printed_v, abs=0.00005)


def test_relative_velocity_ba_at_position_5(motion):
    relative = motion.point("B").v[5] - motion.point("A").v[5]
    assert float(np.hypot(*relative)) == pytest.approx(2.9613, abs=0.00005)


@pytest.mark.parametrize("point, printed_a", [("B", 33.270), ("S3", 42.863), ("S4", 14.332), ("E", 44.663)])
def test_accelerations_at_position_5(motion, point, printed_a):
    assert speed(motion.point(point).a, 5) == pytest.approx(printed_a, abs=0.0005)


def test_angular_velocities_and_senses_at_position_5(motion):
    assert motion.link(3).omega[5] == pytest.approx(-5.3842, abs=0.00005)   # cw
    assert motion.link(4).omega[5] == pytest.approx(2.1554, abs=0.00005)    # ccw
    assert motion.link(3).epsilon[5] == pytest.approx(-18.314, abs=0.0005)  # cw
    assert motion.link(4).epsilon[5] == pytest.approx(-102.265, abs=0.0005) # cw


def test_idle_stroke_omega4_at_position_11(motion):
    # The example's computer value 6.39152 rad/s, clockwise.
    assert motion.link(4).omega[11] == pytest.approx(-6.39152, abs=0.000005)


def test_positions_start_at_the_extended_dead_centre():
    positions = make_positions(graphplan.build(graphplan.load(FIXTURE)))
    first = math.degrees(positions.values[0]) % 360
    assert first == pytest.approx(115.048, abs=0.0005)
    # Crank and coupler in line: the law of cosines in triangle O–C–B with OB = OA + AB.
    ob, oc, bc = 0.175 + 0.55, 0.55, 0.325
    angle_cob = math.degrees(math.acos((ob**2 + oc**2 - bc**2) / (2 * ob * oc)))
    assert first == pytest.approx(90 + angle_cob, abs=1e-9)


def test_working_stroke_takes_169_95_degrees_of_crank_rotation():
    positions = make_positions(graphplan.build(graphplan.load(FIXTURE)))
    start, end = (math.degrees(v) % 360 for v in positions.extremes)
    assert (start - end) % 360 == pytest.approx(169.95, abs=0.005)   # the crank turns clockwise
    assert positions.strokes[:6] == ("working",) * 6
    assert positions.strokes[6:] == ("idle",) * 6


def test_rocker_swing_is_67_63_degrees():
    scene = graphplan.load(FIXTURE)
    positions = make_positions(graphplan.build(scene))
    extremes = graphplan.solve(scene, driver=np.array(positions.extremes))
    difference = extremes.link(4).angle[0] - extremes.link(4).angle[1]
    swing = math.degrees(abs(math.remainder(difference, 2 * math.pi)))
    assert swing == pytest.approx(67.63, abs=0.005)
