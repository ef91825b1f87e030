"""Friction that holds the loads driving a mechanism over a stretch between two analysed positions.

An engine's massless central slider-crank (crank r, rod l, rod angle β with sin β = r·sin φ / l): the gas force P
drives the piston toward the crank over the expansion stroke, from top dead centre (φ = 0) to bottom (φ = 180°),
and the crank's pivot O has a journal with friction circle ρ.  The rod is a two-force member and the crank's pivot
takes its force S = P/cos β, so without friction Mb0 = −S·r·sin(φ + β) (the gas drives: Mb0·ω < 0), and with it
Mb = Mb0 + sign(ω)·ρ·S.  Just past each dead centre r·sin(φ + β) < ρ: the driver must drive the engine (η′ ≤ 0)
from φ = 0 to φ + β = arcsin(ρ/r), and again from φ + β = 180° − arcsin(ρ/r) to 180°.  The dead centres are
positions (Mb0 = 0: η = 0, no warning of their own), and no other position falls in the stretches: they went
untold (the user's engine: 0°–3.880° and 174.661°–180°).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_texts import central_slider_crank
from scipy.optimize import brentq

from graphplan.analysis import analyse
from graphplan.report import forces as force_report
from graphplan.scene import loads as scene_from_text

RADIUS, ROD, GAS, JOURNAL_F, JOURNAL_R = 0.05, 0.19, 4500.0, 0.08, 0.025
RHO = JOURNAL_F * JOURNAL_R


def engine(omega: float) -> str:
    return central_slider_crank(RADIUS, ROD, omega) + f"""
[[loads]]
kind = "force"
link = 4
point = "B"
value = {GAS}
angle = 180.0
during = "working"
[[friction]]
joint = "O"
f = {JOURNAL_F}
radius = {JOURNAL_R}
[positions]
count = 24
start = "extreme"
number_from = 0
working = {{ link = 4, sense = "backward" }}
"""


def held_ends_deg() -> tuple[float, float]:
    """The crank's turn from top dead centre (degrees) where r·sin(φ + β) = ρ, on each side of the stroke."""
    def lever(theta: float) -> float:
        return RADIUS * math.sin(theta + math.asin(RADIUS * math.sin(theta) / ROD)) - RHO

    return (math.degrees(brentq(lever, 1e-9, math.pi / 2, xtol=1e-14)),
            math.degrees(brentq(lever, math.pi / 2, math.pi - 1e-9, xtol=1e-14)))


@pytest.mark.parametrize("omega", [157.08, -157.08])
def test_the_stretches_past_both_dead_centres_where_the_friction_holds_the_gas_are_warned_of(omega):
    analysis = analyse(scene_from_text(engine(omega)))
    sense = math.copysign(1.0, omega)
    first, second = held_ends_deg()
    assert 0.0 < first < 15.0 and 165.0 < second < 180.0   # each between two positions 15° apart

    # The closed form's balancing moments where the gas acts, against the linear system's.
    phi = analysis.motion.link(2).angle
    turned = np.degrees(sense * phi) % 360.0
    acting = (turned > 1e-6) & (turned < 180.0 - 1e-6)
    beta = np.arcsin(RADIUS * np.sin(phi) / ROD)
    rod_force = GAS / np.cos(beta)
    ideal = -rod_force * RADIUS * np.sin(phi + beta)
    np.testing.assert_allclose(analysis.equilibrium.balancing[acting], ideal[acting], rtol=1e-9)
    np.testing.assert_allclose(analysis.with_friction.balancing[acting], ideal[acting] + sense * RHO * rod_force[acting],
                               rtol=1e-9)
    assert not [w for w in analysis.warnings if w.code == "reverse-self-locking"]

    spans = analysis.turned_round_spans
    numbers = analysis.positions.numbers
    assert [(numbers[span.after], numbers[span.after + 1]) for span in spans] == [(0, 1), (11, 12)]
    ends = [(float(np.degrees(sense * span.start)) % 360.0, float(np.degrees(sense * span.end)) % 360.0)
            for span in spans]
    # The dead centres are the positions' own coordinates; the other ends to the sweep's 0.001°.
    assert ends[0][0] == pytest.approx(0.0, abs=1e-9) or ends[0][0] == pytest.approx(360.0, abs=1e-9)
    assert ends[0][1] == pytest.approx(first, abs=1e-3)
    assert ends[1][0] == pytest.approx(second, abs=1e-3)
    assert ends[1][1] == pytest.approx(180.0, abs=1e-9)

    told = [w for w in analysis.warnings if w.code == "reverse-self-locking-between"]
    assert [w.position for w in told] == [span.after for span in spans]
    describe = analysis.mechanism.driver.describe
    assert told[0].detail.startswith(f"between positions 0 and 1, from {describe(spans[0].start)} to "
                                     f"{describe(spans[0].end)}, the loads would drive the mechanism, but the "
                                     "friction in the pairs holds them, however large those that drive it there")
    sentences = force_report.locked_between_lines(analysis)
    assert len(sentences) == 2 and sentences[1].startswith("Between positions 11 and 12, from φ = ")
    assert all(sentence in force_report.markdown(analysis) for sentence in sentences)


def test_a_machine_whose_loads_never_drive_it_has_no_such_stretch():
    resisting = engine(157.08).replace('during = "working"', 'during = "working"\nresisting = true')
    analysis = analyse(scene_from_text(resisting))
    assert analysis.turned_round_spans == ()
    assert not [w for w in analysis.warnings if w.code.startswith("reverse-self-locking")]


def test_where_the_loads_barely_outweigh_each_other_the_friction_holding_the_rest_is_no_lock():
    """A moment M on the crank drives it against P on the piston (Mb0 = −M − P·r·sin(φ + β)/cos β): where the two
    come to cancel, the friction ρ·S at O outweighs what is left over a few degrees (−ρ·S ≤ Mb0 < 0: the driver
    must drive), but M alone puts no force on the pivot and turns the mechanism freely.  No self-locking: the
    shaper starter's inertia loads and weights warned so three times."""
    rho, moment, push = 0.005, 50.0, 1000.0
    text = central_slider_crank(0.1, 0.4, 10.0) + f"""
[[loads]]
kind = "force"
link = 4
point = "B"
value = {push}
angle = 180.0
[[loads]]
kind = "moment"
link = 2
value = {moment}
[[friction]]
joint = "O"
f = 0.1
radius = {rho / 0.1}
[positions]
count = 12
"""
    analysis = analyse(scene_from_text(text))

    def balancing(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        beta = np.arcsin(0.1 * np.sin(phi) / 0.4)
        ideal = -moment - push * 0.1 * np.sin(phi + beta) / np.cos(beta)
        return ideal, ideal + rho * push / np.cos(beta)

    phi = analysis.motion.link(2).angle
    ideal, rubbing = balancing(phi)
    np.testing.assert_allclose(analysis.equilibrium.balancing, ideal, rtol=1e-9)
    np.testing.assert_allclose(analysis.with_friction.balancing, rubbing, rtol=1e-9)
    dense = np.radians(np.linspace(0.0, 360.0, 36001))
    ideal, rubbing = balancing(dense)
    held = (ideal < 0) & (rubbing >= 0)
    assert held.sum() * 0.01 > 2.0   # the friction holds the surplus over degrees, at 0.01° a sample
    assert not held[np.isin(np.round(np.degrees(dense), 6), np.round(np.degrees(phi) % 360.0, 6))].any()
    assert analysis.turned_round_spans == ()
    assert not [w for w in analysis.warnings if w.code.startswith("reverse-self-locking")]
