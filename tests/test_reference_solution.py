"""The 50-digit reference of graphplan/reference.py: it satisfies the mechanism's constraints, and graphplan agrees with it.

The constraint checks are written here from the mechanism's definition, not from the reference's
own closure equations: every pair of points fixed on one link keeps its distance and moves as a
rigid body with the link's ω and ε (vP − vQ = iω·QP, aP − aQ = (iε − ω²)·QP); every point that
slides on a line stays on it at its offset, with the line turning with its link; the crank's pin
stays on its circle.  Each holds with its first and second time derivatives, at 50 digits, to
1e-40 of the mechanism's size.

Cases: every fixture and the variants of the finite-difference tests (guides on moving links for
RRP, RPP and a triad's sliding leg, a PRP between two moving links, an offset slot).
"""

from __future__ import annotations

import numpy as np
import pytest
from mpmath import mp, mpc, mpf
from test_motion_against_finite_differences import CASES, scene_of

import graphplan
from graphplan import reference
from graphplan.mechanism import build

AGREEMENT = 1e-12
CLOSURE = mpf("1e-40")


@pytest.fixture(scope="module", params=sorted(CASES))
def case(request):
    scene = scene_of(request.param)  # its positions found once, for the reference and graphplan.solve alike
    values = reference.scene_positions(scene)
    return scene, build(scene), values, reference.solve_reference(scene, values)


def test_graphplan_agrees_with_the_reference_to_1e_12(case):
    scene, _, values, exact = case
    motion = graphplan.solve(scene)
    assert np.array_equal(motion.driver, values)
    worst = reference.relative_difference(exact, motion)
    assert max(worst.values()) <= AGREEMENT, worst


def test_the_reference_closes_its_own_equations_to_1e_40(case):
    *_, exact = case
    assert max(reference.worst_residual(exact)) <= 1e-40


def _size(instant) -> mpf:
    return max(abs(r) for r, _, _ in instant.points.values()) or mpf(1)


def _rates(instant, link, frame):
    return (mpf(0), mpf(0), mpf(0)) if link == frame else instant.links[link]


def test_points_of_one_link_move_as_a_rigid_body(case):
    scene, mechanism, _, exact = case
    with mp.workdps(reference.DPS):
        for instant in exact.instants:
            tolerance = CLOSURE * _size(instant)
            for link, names in mechanism.fixed_on.items():
                _, omega, epsilon = _rates(instant, link, scene.frame_link)
                names = sorted(names)
                for i, p in enumerate(names):
                    for q in names[i + 1:]:
                        (rp, vp, ap), (rq, vq, aq) = instant.points[p], instant.points[q]
                        arm = rp - rq
                        assert abs(vp - vq - 1j * omega * arm) <= tolerance * max(1, abs(omega)), (link, p, q)
                        assert abs(ap - aq - (1j * epsilon - omega ** 2) * arm) <= tolerance * max(1, abs(epsilon), omega ** 2)


def test_link_lengths_hold_at_50_digits(case):
    scene, mechanism, _, exact = case
    with mp.workdps(reference.DPS):
        for instant in exact.instants:
            tolerance = CLOSURE * _size(instant)
            pairs = []
            driver = scene.driver
            if driver.kind == "crank":
                pairs.append((driver.pivot, driver.joint, driver.length))
            for group in mechanism.groups:
                if group.kind == "RRR":
                    a, b, c = group.joints
                    pairs += [(a, b, group.lengths[0]), (c, b, group.lengths[1])]
                elif group.kind == "RRP":
                    pairs.append((*group.joints, group.length))
                elif group.kind == "triad":
                    pairs += [(group.joints[2 * n], group.joints[2 * n + 1], group.lengths[n]) for n in group.turning_legs]
            for first, second, length in pairs:
                (r1, v1, a1), (r2, v2, a2) = instant.points[first], instant.points[second]
                d, dv, da = r2 - r1, v2 - v1, a2 - a1
                assert abs(abs(d) - mpf(length)) <= tolerance
                # d/dt |d|² = 2 d·ḋ = 0 and d²/dt² |d|² = 2 (d·d̈ + |ḋ|²) = 0
                assert abs(mp.re(mp.conj(d) * dv)) <= tolerance * max(1, abs(dv))
                assert abs(mp.re(mp.conj(d) * da) + abs(dv) ** 2) <= tolerance * max(1, abs(da), abs(dv) ** 2)


def _lines(scene, mechanism):
    """(point, through, link carrying the line, angle from the link's reference line, offset) of every slide.

    Angles that add up are added at 50 digits: their double sum would be off by 1e-17.
    """
    def guide_of(guide):
        if guide.line is not None:
            guide = scene.frame_lines[guide.line]
        link = scene.frame_link if guide.link is None else guide.link
        return guide.through, link, guide.angle

    lines = []
    if scene.driver.kind == "slider":
        lines.append((scene.driver.joint, *guide_of(scene.driver.guide), 0.0))
    for group in mechanism.groups:
        if group.kind == "RRP":
            lines.append((group.joints[1], *guide_of(group.guide), 0.0))
        elif group.kind == "PRP":
            lines += [(group.joints[0], *guide_of(g), o) for g, o in zip(group.guide_pair, group.offsets)]
        elif group.kind == "RPP":
            through, link, angle = guide_of(group.guide)
            lines += [(group.joints[1], through, link, angle, 0.0),
                      (group.joints[0], group.joints[1], link, mpf(angle) + mpf(group.angle), 0.0)]
        elif group.kind == "RPR":
            lines.append((group.joints[0], group.joints[1], group.links[1], 0.0, group.offset))
        elif group.kind == "triad":
            lines += [(group.new_joints()[n], *guide_of(group.leg_guides[n]), 0.0) for n in group.sliding_legs]
            # A slot turns with the ternary link (its reference line BD) and runs through the leg's inner joint.
            lines += [(group.joints[2 * n], group.joints[2 * n + 1], group.ternary, group.leg_slots[n], 0.0)
                      for n in group.slotted_legs]
    return lines


def test_sliding_points_stay_on_their_lines(case):
    """Im(ū·(P − T)) = offset, with u = e^{i(θ + α)} turning with its link: u̇ = iω·u, ü = (iε − ω²)·u."""
    scene, mechanism, _, exact = case
    with mp.workdps(reference.DPS):
        for instant in exact.instants:
            tolerance = CLOSURE * _size(instant)
            for point, through, link, angle, offset in _lines(scene, mechanism):
                if isinstance(through, str):
                    rt, vt, at = instant.points[through]
                else:
                    rt, vt, at = mpc(*through), mpc(0), mpc(0)
                theta, omega, epsilon = _rates(instant, link, scene.frame_link)
                u = mp.expj(theta + mpf(angle))
                du, ddu = 1j * omega * u, (1j * epsilon - omega ** 2) * u
                rp, vp, ap = instant.points[point]
                d, dv, da = rp - rt, vp - vt, ap - at
                scale = max(1, abs(dv), abs(da), abs(omega), omega ** 2, abs(epsilon))
                assert abs(mp.im(mp.conj(u) * d) - mpf(offset)) <= tolerance, (point, through)
                assert abs(mp.im(mp.conj(du) * d + mp.conj(u) * dv)) <= tolerance * scale
                assert abs(mp.im(mp.conj(ddu) * d + 2 * mp.conj(du) * dv + mp.conj(u) * da)) <= tolerance * scale ** 2


def test_a_jet_differentiates_like_the_calculus():
    """The reference's derivatives come from its jet arithmetic: check it on e^{iθ}/√(1 + θ²) against mpmath.diff."""
    with mp.workdps(reference.DPS):
        t0 = mpf("0.7")

        def f(t):
            return mp.expj(3 * t) / mp.sqrt(1 + t * t)

        theta = reference.Jet(t0, mpf(1), mpf(0))
        jet = reference.expi(3 * theta) / reference.sqrt(1 + theta * theta)
        assert abs(jet.d0 - f(t0)) < mpf("1e-45")
        assert abs(jet.d1 - mp.diff(f, t0)) < mpf("1e-40")
        assert abs(jet.d2 - mp.diff(f, t0, 2)) < mpf("1e-40")


def test_a_toggle_has_no_reference():
    """At a toggle the closure's Jacobian is singular: the reference refuses instead of guessing."""
    from test_singular_positions import TOGGLE

    scene = graphplan.scene.loads(TOGGLE)
    with pytest.raises(reference.ReferenceSolutionError, match="singular|no 50-digit"):
        reference.solve_reference(scene, [np.pi])
