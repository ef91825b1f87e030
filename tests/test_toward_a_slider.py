"""A named point placed ``toward`` a slider on its link lies on the slider's side of ``from``.

docs/scene-format-extensions.md: "`[points]` `toward` may be a slider on the link | the direction is then that of
the slide line". The line is the slide's; "toward" says which way along it: from ``from`` toward where the slider
is (at the crank's 0°, whatever the start; a travel's first end). A slot's own direction is no answer: an RPP's block
or a triad's may sit on the slot's negative side, and the point was once put on the far side of ``from``
(bug hunt 7, F1). Every expectation here is computed from the scene's dimensions, not from graphplan's solve.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_plans_against_analytic import _hung

import graphplan
from graphplan.analysis import analyse

# The hunter's scene (m4): a crank, a slotted lever (RPR) and an RPP whose guide is on the lever through H at 30°
# to it, its slot at 70° to the guide; the block is pinned to the crank's point E. The block sits on the slot's
# negative side at every position (s from F −0.038 … −0.105 m).
LEVER_RPP = """
[scene]
title = "RPP on a moving guide"
locale = "en"
gravity = 9.81

[frame]
link = 1
points = { C = [0.0, 0.0], O = [0.0, 0.30] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.12
omega = 6.0
epsilon = -8.0

[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]

[[groups]]
kind = "RPP"
links = [5, 6]
joints = ["E", "F"]
guide = { link = 4, through = "H", angle = 30.0 }
angle = 70.0

[points]
S2 = { link = 2, from = "O", toward = "A", at = 0.05 }
E  = { link = 2, from = "O", toward = "A", at = 0.06, offset = 0.05 }
S4 = { link = 4, from = "C", toward = "A", at = 0.25 }
H  = { link = 4, from = "C", toward = "A", at = 0.20, offset = 0.03 }
S6 = { link = 6, from = "F", toward = "E", at = 0.03, offset = 0.02 }

[links.2]
mass = 4.0
centre = "S2"
inertia = 0.01
[links.3]
mass = 1.0
centre = "A"
inertia = 0.001
[links.4]
mass = 10.0
centre = "S4"
inertia = 0.3
[links.5]
mass = 0.8
centre = "E"
inertia = 0.002
[links.6]
mass = 3.0
centre = "S6"
inertia = 0.02

[[loads]]
kind = "force"
link = 6
point = "S6"
value = 200.0
angle = 250.0
resisting = false
during = "always"

[positions]
count = 12
start = 10.0
number_from = 1

[drawing]
sheet = "none"
"""

G = 9.81
OMEGA, EPSILON = 6.0, -8.0
MASSES = {2: (4.0, 0.01, "S2"), 3: (1.0, 0.001, "A"), 4: (10.0, 0.3, "S4"), 5: (0.8, 0.002, "E"),
          6: (3.0, 0.02, "S6")}
LOAD = 200.0 * complex(math.cos(math.radians(250.0)), math.sin(math.radians(250.0)))


def _e(angle):
    return np.exp(1j * angle)


def _lever_rpp(phi: float) -> tuple[dict[str, complex], dict[int, float]]:
    """The points and the links' angles at crank angle ``phi``, by closed form: A on the crank, the lever through C
    and A, E on the crank, F where the slot through E crosses the guide through H, S6 0.03 m from F toward E."""
    o, c = 0.30j, 0j
    a = o + 0.12 * _e(phi)
    u = (a - c) / abs(a - c)
    h = c + (0.20 + 0.03j) * u
    e = o + (0.06 + 0.05j) * _e(phi)
    guide = u * _e(math.radians(30.0))
    slot = guide * _e(math.radians(70.0))
    s_guide, _ = np.linalg.solve([[guide.real, slot.real], [guide.imag, slot.imag]], [(e - h).real, (e - h).imag])
    f = h + s_guide * guide
    s6 = f + (0.03 + 0.02j) * (e - f) / abs(e - f)
    points = {"A": a, "E": e, "F": f, "S2": o + 0.05 * _e(phi), "S4": c + 0.25 * u, "S6": s6}
    angles = {2: phi, 3: float(np.angle(u)), 4: float(np.angle(u)), 5: float(np.angle(slot)),
              6: float(np.angle(guide))}
    return points, angles


def _rates(phi: float, step: float = 1e-4):
    """Positions, velocities and accelerations of the points and links at ``phi`` by five-point differences in the
    crank angle: v = f′·ω, a = f″·ω² + f′·ε."""
    samples = [_lever_rpp(phi + k * step) for k in (-2, -1, 0, 1, 2)]

    def derivatives(values):
        first = (values[0] - 8 * values[1] + 8 * values[3] - values[4]) / (12 * step)
        second = (-values[0] + 16 * values[1] - 30 * values[2] + 16 * values[3] - values[4]) / (12 * step * step)
        return values[2], first * OMEGA, second * OMEGA ** 2 + first * EPSILON

    points = {name: derivatives([s[0][name] for s in samples]) for name in samples[2][0]}
    links = {n: derivatives(np.unwrap([s[1][n] for s in samples])) for n in samples[2][1]}
    return points, links


def _balancing_by_power(phi: float) -> float:
    """Mb·ω2 + Σ(F·v + M·ω) = 0 over the weights, the d'Alembert loads −m·aS, −J·ε and the 200 N force at S6."""
    points, links = _rates(phi)
    power = 0.0
    for link, (mass, inertia, centre) in MASSES.items():
        _, v, a = points[centre]
        force = -mass * a - 1j * mass * G + (LOAD if link == 6 else 0)
        _, omega, epsilon = links[link]
        power += (force * v.conjugate()).real - inertia * epsilon * omega
    return -power / OMEGA


def test_a_point_toward_an_rpp_s_block_lies_on_the_block_s_side_of_from():
    scene = graphplan.load_text(LEVER_RPP)
    motion = graphplan.solve(scene)
    s6 = motion.point("S6").r
    for index, phi in enumerate(motion.driver):
        expected = _lever_rpp(float(phi))[0]["S6"]
        assert complex(*s6[index]) == pytest.approx(expected, abs=1e-12)
    # Position 1 (φ = 10°), as the hunter measured it: 0.03 m from F toward E = (0.0450, 0.3810), not (−0.0211, 0.3522).
    assert complex(*s6[0]) == pytest.approx(0.044997 + 0.380957j, abs=1e-6)


def test_the_balancing_moment_with_that_centre_of_mass_holds_the_power_balance():
    analysis = analyse(graphplan.load_text(LEVER_RPP))
    balancing = analysis.equilibrium.balancing
    for index, phi in enumerate(analysis.motion.driver):
        assert balancing[index] == pytest.approx(_balancing_by_power(float(phi)), rel=1e-6, abs=1e-6)
    assert balancing[0] == pytest.approx(11.822, abs=1e-3)  # 9.594 N·m with S6 on the far side of F


SCOTCH_YOKE = """
[scene]
title = "Scotch yoke"
locale = "en"

[frame]
link = 1
points = { O = [0.0, 0.0] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.075
omega = 12.0

[[groups]]
kind = "RPP"
links = [3, 4]
joints = ["A", "B"]
guide = { through = [0.0, 0.0], angle = 90.0 }
angle = 90.0

[points]
Q = { link = 4, from = "B", toward = "A", at = 0.05, offset = 0.02 }

[positions]
count = 12
start = START
"""


@pytest.mark.parametrize("start", [0.0, 30.0, 150.0, 180.0])
def test_a_point_toward_a_scotch_yoke_s_pin_lies_on_the_pin_s_side_at_the_crank_s_nought(start):
    """The yoke's slot runs along −x (the guide up, the slot at 90° to it): the pin is on its negative side at the
    crank's 0°, at x = +0.075. The point is on the pin's side there, whatever the run's start (a start of 150° put it
    on the other side of the guide, as the pin is there), and rides with the yoke, which translates: B→Q is the same
    at every position, and in a solve at other values."""
    scene = graphplan.load_text(SCOTCH_YOKE.replace("START", str(start)))
    pin_x = 0.075 * math.cos(0.0)
    toward = complex(math.copysign(1.0, pin_x), 0.0)
    for motion in (graphplan.solve(scene), graphplan.solve(scene, driver=np.radians(start + 120.0 + np.arange(5.0)))):
        bq = motion.point("Q").r - motion.point("B").r
        for index in range(motion.count):
            assert complex(*bq[index]) == pytest.approx((0.05 + 0.02j) * toward, abs=1e-12)


def test_a_point_toward_a_triad_s_block_lies_on_the_block_s_side_of_from():
    """The ratchet's triad with two slotted legs: M8 is placed 0.05 m from G toward the block pinned at E, along
    G's slot (at −77° from G→K on the ternary link 8), 0.04 m to its left; E is on the slot's negative side."""
    motion = graphplan.solve(_hung("ratchet+triad-two-slots"))  # M8 as the docstring says

    def r(name):
        xy = motion.point(name).r
        return xy[:, 0] + 1j * xy[:, 1]

    g, k, e, m8 = r("G"), r("K"), r("E"), r("M8")
    slot = (k - g) / np.abs(k - g) * _e(math.radians(-77.0))
    sense = math.copysign(1.0, float(((e[0] - g[0]) * slot[0].conjugate()).real))
    assert sense < 0  # the case the slot's own direction gets wrong
    np.testing.assert_allclose(m8, g + (0.05 + 0.04j) * sense * slot, rtol=0, atol=1e-12)
