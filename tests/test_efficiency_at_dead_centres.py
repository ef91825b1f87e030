"""The efficiency at a slider-crank's dead centres, where a load resisting the piston takes no power.

The massless central slider-crank (crank r, rod l, rod angle β with sin β = r·sin φ / l), a force P against the
piston's motion and f in the guide alone: the rod is a two-force member, its force S = P/(cos β − f·|sin β|) from
the piston's equilibrium across and along the guide, and Mb = S·(xA·eʸ − yA·eˣ) with e the rod's direction from A
to B.  At a dead centre A lies on the guide and e along it: N = 0 and Mb0 = Mb = 0, so η is 0 (the loads take no
power; scene-format-extensions' `efficiency`), whatever f is; elsewhere η = Mb0/Mb = 1 − f·|tan β|.

The linear system leaves Mb0 and Mb there as rounding noise of either sign (−9·10⁻¹⁵ N·m beside 100 N·m): judged
against each other, η came out 1 and the cycle's note said the loads drive the driver at both dead centres.
"""

from __future__ import annotations

import numpy as np
import pytest
from scene_texts import central_slider_crank

from graphplan.analysis import analyse
from graphplan.report import forces as force_report
from graphplan.report.results import results
from graphplan.scene import loads as scene_from_text

RADIUS, ROD, PUSH = 0.1, 0.4, 1000.0


def scene_text(f: float, omega: float) -> str:
    # Started at 30° as the user's scene was: 180° and 0° are then reached by adding steps, not given.
    return central_slider_crank(RADIUS, ROD, omega) + f"""
[[loads]]
kind = "force"
link = 4
point = "B"
value = {PUSH}
angle = 0.0
resisting = true
[[friction]]
joint = "B"
links = [4, 1]
f = {f}
[positions]
count = 12
start = 30.0
plans = [5, 11]
"""


def closed_form(phi: np.ndarray, f: float, omega: float) -> tuple[np.ndarray, np.ndarray]:
    """(Mb0, Mb) of the massless slider-crank at crank angles ``phi``."""
    a = RADIUS * np.exp(1j * phi)
    beta = np.arcsin(RADIUS * np.sin(phi) / ROD)
    b = a.real + ROD * np.cos(beta)
    e = (b - a) / ROD
    # The piston's velocity decides the sense its resistance and friction push; the rod pushes it on along it.
    v_b = -omega * RADIUS * (np.sin(phi) + RADIUS * np.sin(2 * phi) / (2 * ROD * np.cos(beta)))
    sense = np.sign(v_b)

    def moment(friction: float) -> np.ndarray:
        rod_force = sense * PUSH / (np.cos(beta) - friction * np.abs(np.sin(beta)))
        return rod_force * (a.real * e.imag - a.imag * e.real)

    return moment(0.0), moment(f)


@pytest.mark.parametrize(("f", "omega"), [(0.15, 10.0), (0.15, -10.0), (0.0, 10.0), (0.3, 7.3)])
def test_the_efficiency_is_zero_at_both_dead_centres_and_the_loads_drive_nothing_there(f, omega):
    analysis = analyse(scene_from_text(scene_text(f, omega)))
    phi = analysis.motion.link(2).angle
    ideal, rubbing = closed_form(phi, f, omega)
    dead = np.isclose(np.abs(np.sin(phi)), 0.0, atol=1e-9)
    assert dead.sum() == 2
    np.testing.assert_allclose(analysis.equilibrium.balancing, ideal, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(analysis.with_friction.balancing, rubbing, rtol=1e-9, atol=1e-9)
    assert np.all(ideal[~dead] * omega > 0)   # the driver delivers power everywhere else
    expected = np.where(dead, 0.0, ideal / np.where(dead, 1.0, rubbing))
    np.testing.assert_allclose(expected[~dead], 1.0 - f * np.abs(np.tan(np.arcsin(RADIUS * np.sin(phi[~dead]) / ROD))),
                               rtol=1e-12)

    written = results(analysis)
    efficiency = [entry["equilibrium"]["friction"]["efficiency"] for entry in written["positions"]]
    np.testing.assert_allclose(efficiency, expected, rtol=1e-9, atol=1e-12)
    assert [written["positions"][index]["equilibrium"]["friction"]["balancing_moment"]
            for index in np.flatnonzero(dead)] == [0.0, 0.0]
    assert force_report.cycle_notes(analysis) == []
    assert "drive the driver" not in force_report.markdown(analysis)
    assert not [w for w in analysis.warnings if w.code == "reverse-self-locking"]
    cycle = [eta for _, _, _, eta, _ in force_report.cycle_rows(analysis)]
    np.testing.assert_allclose(cycle, expected, rtol=1e-9, atol=1e-12)


def test_a_force_sheet_at_a_dead_centre_names_its_zero_efficiency_mb0_over_mb():
    """With a journal's friction the driver still drives at a dead centre (Mb = ρ·|R| > 0, Mb0 = 0): η = Mb0/Mb =
    0.  The sentence named it Mb/Mb0, which divides by the zero."""
    text = scene_text(0.15, 10.0).replace("plans = [5, 11]", "plans = [6, 12]") + (
        '[[friction]]\njoint = "O"\nf = 0.2\nradius = 0.05\n')
    analysis = analyse(scene_from_text(text))
    for plan in analysis.plans:
        assert abs(np.sin(analysis.motion.link(2).angle[plan.index])) < 1e-9
        # The rod along the guide takes P, and so does the crank's pivot: Mb = ρ·P, against the turning.
        assert plan.with_friction.balancing == pytest.approx(0.2 * 0.05 * PUSH, rel=1e-9)
        line = force_report.friction_lines(analysis, plan)[0]
        assert line.endswith("efficiency η = Mb0/Mb = 0."), line


def test_where_the_friction_locks_every_position_but_the_dead_centres_their_mb_is_written_0():
    """f = 50 in the guide jams the piston wherever cos β − f·|sin β| ≤ 0, every position but the dead centres;
    there N = 0 and Mb = 0.  results.json wrote −9.18e-15: judged against its own largest, the noise itself."""
    f = 50.0
    analysis = analyse(scene_from_text(scene_text(f, 10.0)))
    phi = analysis.motion.link(2).angle
    beta = np.arcsin(RADIUS * np.sin(phi) / ROD)
    dead = np.isclose(np.abs(np.sin(phi)), 0.0, atol=1e-9)
    np.testing.assert_array_equal(analysis.with_friction.locked, np.cos(beta) - f * np.abs(np.sin(beta)) <= 0)
    np.testing.assert_array_equal(analysis.with_friction.locked, ~dead)
    written = [entry["equilibrium"]["friction"] for entry in results(analysis)["positions"]]
    assert [entry["balancing_moment"] for entry in written] == [0.0 if at else None for at in dead]
    assert [entry["efficiency"] for entry in written] == [0.0 if at else None for at in dead]
