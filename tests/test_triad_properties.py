"""Triads of every shape: the fixture is one geometry, these are drawn at random.

A triad is built backwards from a pose: the crank pin A, the ternary link's corners B, D, F (either
way round) and the frame pivots C, E are drawn at random, and the lengths are measured off them.
The sketch is that pose, so the assembly graphplan finds at the first position must be it.  Then,
at that position, the same independent checks the fixtures get:

* the analytic velocities against central finite differences of the positions;
* the plans (Assur's point Σ, the third joint, similarity) against the analytic solution;
* the force polygons and Zhukovsky's lever against the linear system of statics, with masses,
  moments of inertia and external loads on every link.

Poses near a singular position (the three binary links' lines nearly through one point) are set
aside: the group's conditioning must be well clear of the warning limit.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from test_forces_against_statics import loaded

import graphplan
from graphplan.analysis import instant
from graphplan.errors import SingularPositionError
from graphplan.forces import force_plan
from graphplan.lever import lever
from graphplan.loads import activity, link_loads, motion_state, plan_state
from graphplan.motion import solve
from graphplan.plans import acceleration_plan, velocity_plan
from graphplan.positions import make_positions
from graphplan.scene import loads
from graphplan.statics import equilibrium

RELATIVE = 1e-9
# The group's normalised Jacobian determinant must be at least this: far from a singular position.
WELL_CONDITIONED = 0.2
GROUP = "III(3,4,5,6)"

_TEXT = """
[scene]
title = "A random triad"
gravity = 9.81

[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [{C.real!r}, {C.imag!r}], E = [{E.real!r}, {E.imag!r}] }}

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {crank!r}
omega = {omega!r}
epsilon = {epsilon!r}

[[groups]]
kind = "triad"
links = [3, 4, 5, 6]
joints = ["A", "B", "C", "D", "E", "F"]
lengths = [{AB!r}, {CD!r}, {EF!r}]
sides = [{BD!r}, {DF!r}, {FB!r}]
near = {{ B = [{B.real!r}, {B.imag!r}], D = [{D.real!r}, {D.imag!r}], F = [{F.real!r}, {F.imag!r}] }}

[positions]
count = 1
start = {start!r}
plans = [1]
"""


@st.composite
def triads(draw):
    """A scene and the pose it was built from (B, D, F at the first position)."""
    unit = st.floats(0.0, 2 * math.pi)
    crank = round(draw(st.floats(0.03, 0.08)), 9)
    start = round(draw(st.floats(0.0, 359.0)), 6)
    a = crank * cmath.exp(1j * math.radians(start))
    centre = a + draw(st.floats(0.12, 0.25)) * cmath.exp(1j * draw(unit))
    size = draw(st.floats(0.06, 0.14))
    turn, clockwise = draw(unit), draw(st.booleans())
    # The corners' angles round the centre: a triangle of no sliver, either way round.
    spread = [0.0, draw(st.floats(1.6, 2.6)), draw(st.floats(3.7, 4.7))]
    corners = [centre + size * cmath.exp(1j * (turn + (-1 if clockwise else 1) * angle)) for angle in spread]
    b, d, f = corners
    c = d + draw(st.floats(0.08, 0.2)) * cmath.exp(1j * draw(unit))
    e = f + draw(st.floats(0.08, 0.2)) * cmath.exp(1j * draw(unit))
    # Coordinates to the nanometre, so that the scene holds them exactly and the lengths fit them.
    b, c, d, e, f = (complex(round(z.real, 9), round(z.imag, 9)) for z in (b, c, d, e, f))
    text = _TEXT.format(C=c, E=e, B=b, D=d, F=f, crank=crank, start=start,
                        omega=draw(st.sampled_from([-12.0, 8.0])), epsilon=draw(st.sampled_from([0.0, -30.0, 45.0])),
                        AB=abs(b - a), CD=abs(d - c), EF=abs(f - e), BD=abs(d - b), DF=abs(f - d), FB=abs(b - f))
    return loads(text), {"B": b, "D": d, "F": f}


def _well_conditioned(motion) -> bool:
    return not motion.singular and float(np.min(np.abs(motion.conditioning[GROUP]))) >= WELL_CONDITIONED


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=triads())
def test_a_random_triad_closes_in_its_sketch_and_its_plans_and_forces_agree(case):
    scene, pose = case
    try:
        motion = graphplan.solve(scene)
    except SingularPositionError:
        assume(False)
    assume(_well_conditioned(motion))
    for name, expected in pose.items():
        assert abs(complex(*motion.point(name).r[0]) - expected) <= 1e-9, f"{name} is not the sketched pose"

    # The analytic velocities are the derivatives of the positions.
    step = 1e-6
    start = math.radians(scene.positions.start)
    around = graphplan.solve(scene, driver=[start - step, start + step])
    omega = scene.driver.omega
    for name in ("B", "D", "F"):
        r = around.point(name).r
        difference = (r[1] - r[0]) / (2 * step) * omega
        assert np.allclose(difference, motion.point(name).v[0], rtol=0, atol=1e-6 * abs(omega)), name

    # The plans, built from the pose alone, against the analytic solution.
    mechanism = graphplan.build(scene)
    where, directions = instant(motion, 0)
    velocity = velocity_plan(mechanism, where, directions)
    acceleration = acceleration_plan(mechanism, where, directions, velocity)
    assert set(velocity.auxiliary) == {"Σ6"}
    v_scale = max(abs(complex(*motion.point(name).v[0])) for name in motion.points)
    a_scale = max(abs(complex(*motion.point(name).a[0])) for name in motion.points)
    for name in motion.points:
        assert abs(velocity.value(name) - complex(*motion.point(name).v[0])) <= RELATIVE * v_scale, f"v{name}"
        assert abs(acceleration.value(name) - complex(*motion.point(name).a[0])) <= RELATIVE * a_scale, f"a{name}"
    for link in mechanism.moving_links:
        exact = motion.link(link)
        assert velocity.rates[link] == pytest.approx(exact.omega[0], rel=RELATIVE, abs=RELATIVE * v_scale)
        assert acceleration.rates[link] == pytest.approx(exact.epsilon[0], rel=RELATIVE, abs=RELATIVE * a_scale)

    # The force polygons and the lever against all equations of statics at once.
    # (Only this position: the crank of a random triad need not turn the whole way round.)
    mechanism = graphplan.build(loaded(scene))
    positions = make_positions(mechanism)
    motion = solve(mechanism, positions.values, positions.reference, positions.numbers)
    acting = activity(mechanism, positions, motion)
    exact = equilibrium(mechanism, motion, link_loads(mechanism, motion_state(motion), acting))
    assume(not exact.singular[0])
    loads_drawn = link_loads(mechanism, plan_state(mechanism, where, velocity, acceleration), acting[:, 0:1])
    drawn = force_plan(mechanism, where, directions, loads_drawn)
    largest = max(abs(reaction.force[0]) for reaction in exact.reactions)
    assert set(drawn.reactions) == {reaction.name for reaction in exact.reactions}
    for name, found in drawn.reactions.items():
        assert abs(found.force - exact.reaction(name).force[0]) <= RELATIVE * largest, name
    assert drawn.balancing == pytest.approx(exact.balancing[0], rel=RELATIVE, abs=RELATIVE * largest)
    on_the_lever = lever(mechanism, where, velocity, loads_drawn).balancing
    assert on_the_lever == pytest.approx(drawn.balancing, rel=RELATIVE, abs=RELATIVE * largest)
