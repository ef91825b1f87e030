"""A pair at relative rest at a position rubs with its full friction against the motion about to begin, as the
docs say of `[[friction]]`; their `loads` row said such a pair's friction load was 0.

The massless central slider-crank (crank r, rod l, a force P along −x on the piston) with a journal of friction
circle ρ at the wrist pin B only.  At φ = 90° and 270° the rod stops turning (ω3 = −r·ω·cos φ/(l·cos θ3) = 0) and
is about to turn with ε3 = r·ω²·sin φ/(l·cos θ3): the piston turns against the rod at −ε3.  The rod carries a
force through A (no friction there) and a couple at B: with F the force on it at B, the piston's equilibrium along
the frictionless guide gives Fx = −P, and the rod's moment about A (B − A) × F = s·ρ·|F| (s the sign of ε3)
gives Fy; the friction load on the piston is Mf34 = s·ρ·|F|, counter-clockwise positive.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_texts import central_slider_crank
from scipy.optimize import brentq

from graphplan.analysis import analyse
from graphplan.report.results import results
from graphplan.scene import loads as scene_from_text

RADIUS, ROD, PUSH, OMEGA, RHO = 0.1, 0.4, 1000.0, 10.0, 0.2 * 0.02

SCENE = central_slider_crank(RADIUS, ROD, OMEGA) + f"""
[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
value = {PUSH}
[[friction]]
joint = "B"
links = [3, 4]
f = 0.2
radius = 0.02
[positions]
count = 4
start = 0.0
plans = [2]
"""


def wrist_pin_friction(phi: float) -> float:
    """Mf34 of the pin at rest in the rod at crank angle ``phi`` (cos φ = 0)."""
    theta = -math.asin(RADIUS * math.sin(phi) / ROD)
    rod = ROD * complex(math.cos(theta), math.sin(theta))          # B − A
    sense = math.copysign(1.0, RADIUS * OMEGA ** 2 * math.sin(phi) / (ROD * math.cos(theta)))

    def moment(fy: float) -> float:
        force = complex(-PUSH, fy)
        return (rod.conjugate() * force).imag - sense * RHO * abs(force)

    fy = brentq(moment, -10.0 * PUSH, 10.0 * PUSH, xtol=1e-12)
    return sense * RHO * abs(complex(-PUSH, fy))


def test_a_journal_at_relative_rest_rubs_its_full_friction_against_the_turning_about_to_begin():
    analysis = analyse(scene_from_text(SCENE))
    phi = analysis.motion.link(2).angle
    written = results(analysis)["positions"]
    for index in (1, 3):
        assert math.cos(phi[index]) == pytest.approx(0.0, abs=1e-12)
        assert abs(analysis.motion.link(3).omega[index]) < 1e-12 * OMEGA
        expected = wrist_pin_friction(float(phi[index]))
        assert abs(expected) > 0.9 * RHO * PUSH
        assert written[index]["equilibrium"]["friction"]["loads"]["Mf34"] == pytest.approx(expected, rel=1e-9)
    plan = written[1]["forces"]["friction"]["loads"]["Mf34"]
    assert plan == pytest.approx(wrist_pin_friction(float(phi[1])), rel=1e-6)
    assert np.sign(plan) == 1.0   # ε3 > 0 at 90°: the piston about to turn clockwise in the rod
