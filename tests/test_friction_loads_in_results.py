"""results.json gives each pair's friction load, at the plan positions and at every position, checked
against closed forms of the massless central slider-crank of test_joint_friction (a force P on the
piston, rod angle β with sin β = r·sin φ / l, s the sign of the piston's velocity):

* friction f in the guide only: the rod pushes the piston with T = P / (cos β − f·s·|sin β|), the
  guide's normal reaction is T·sin β, and the friction on the piston is −s·f·|T·sin β| along the axis;
* friction in the crank's journal only (ρ = f·r_j): the reaction R12 keeps its magnitude P / cos β, and
  the friction moment on the crank is −sign(ω)·ρ·P / cos β, against its turning.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_joint_friction import OMEGA, PUSH, rod_angle, slider_crank

from graphplan.analysis import analyse
from graphplan.report.results import results


def test_the_guide_s_friction_force_is_f_times_the_normal_reaction_against_the_piston_s_motion():
    f = 0.15
    analysis = analyse(slider_crank(f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}'))
    document = results(analysis)
    phi = analysis.motion.driver
    beta = rod_angle(phi)
    piston = np.sign(analysis.motion.point("B").v[:, 0])
    push = PUSH / (np.cos(beta) - f * piston * np.abs(np.sin(beta)))
    expected = -piston * f * np.abs(push * np.sin(beta))
    found = [position["equilibrium"]["friction"]["loads"]["Ff14"] for position in document["positions"]]
    np.testing.assert_allclose([x for x, _ in found], expected, rtol=1e-9, atol=1e-9 * PUSH)
    np.testing.assert_allclose([y for _, y in found], 0.0, atol=1e-9 * PUSH)
    planned = [position for position in document["positions"] if "forces" in position]
    assert len(planned) == 4
    for position in planned:
        assert position["forces"]["friction"]["loads"]["Ff14"] == pytest.approx(
            position["equilibrium"]["friction"]["loads"]["Ff14"], rel=1e-9, abs=1e-9 * PUSH)


def test_the_journal_s_friction_moment_is_rho_times_the_reaction_against_the_crank_s_turning():
    f, journal = 0.1, 0.02
    analysis = analyse(slider_crank(f'[[friction]]\njoint = "O"\nf = {f}\nradius = {journal}'))
    document = results(analysis)
    beta = rod_angle(analysis.motion.driver)
    expected = -np.sign(OMEGA) * f * journal * PUSH / np.cos(beta)
    found = [position["equilibrium"]["friction"]["loads"]["Mf12"] for position in document["positions"]]
    np.testing.assert_allclose(found, expected, rtol=1e-9)
    for position in (p for p in document["positions"] if "forces" in p):
        assert position["forces"]["friction"]["loads"]["Mf12"] == pytest.approx(
            position["equilibrium"]["friction"]["loads"]["Mf12"], rel=1e-9)


def test_a_position_that_locks_has_no_friction_loads():
    """With f = 5 the guide locks near mid-stroke on the piston's way out, where cos β − f·|sin β| ≤ 0 (see
    test_joint_friction): its loads are null there, and numbers where it moves."""
    f = 5.0
    analysis = analyse(slider_crank(f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}'))
    locked = np.asarray(analysis.with_friction.locked, dtype=bool)
    assert locked.any() and not locked.all()
    loads = [position["equilibrium"]["friction"]["loads"] for position in results(analysis)["positions"]]
    assert [entry is None for entry in loads] == list(locked)
    assert all(np.isfinite(entry["Ff14"]).all() for entry in loads if entry is not None)
