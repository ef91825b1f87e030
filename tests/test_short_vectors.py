"""Vectors too short to draw are named on the sheet with their values (issue 6: plans stay legible
when the vectors of one plan differ by 10⁴ in length)."""

from __future__ import annotations

from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render import plans
from graphplan.render.drawings import plan_sheet
from graphplan.render.svg import to_svg

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="module")
def tiny_coupler():
    """A coupler 1000 times shorter than the rocker: its normal accelerations ω²·l are far under a millimetre."""
    return analyse(graphplan.load(ROOT / "bench" / "extreme" / "ratio_1_to_1000.toml"))


def test_the_short_normal_accelerations_are_named_with_their_values(tiny_coupler):
    plan = next(p for p in tiny_coupler.plans if p.number == 4)
    short = dict(plans.too_short(plan.acceleration, "acceleration"))
    motion, where = tiny_coupler.motion, plan.positions
    for name, link, (start, end) in (("aBAⁿ", 3, ("A", "B")), ("aBCⁿ", 4, ("C", "B"))):
        omega = motion.link(link).omega[plan.index]
        exact = omega ** 2 * abs(where[end] - where[start])  # the normal component, from the analytic ω
        assert short[name] == pytest.approx(exact, rel=1e-9), name
        assert exact / plan.acceleration.scale < plans.ZERO_MM  # it is indeed under the pencil
    svg = to_svg(plans.layout(plan_sheet(tiny_coupler, plan.index, plan.velocity, plan.acceleration)))
    assert "not drawn, shorter than 0.25 mm:" in svg
    assert f"aBAⁿ = {short['aBAⁿ']:.3g} m/s²" in svg


def test_a_plan_whose_vectors_all_show_says_nothing_of_short_ones():
    analysis = analyse(graphplan.load(ROOT / "fixtures" / "ratchet_crank_rocker.toml"))
    plan = next(p for p in analysis.plans if p.number == 5)
    lengths = [abs(built.mm(vector.end) - built.mm(vector.start))
               for built in (plan.velocity, plan.acceleration) for step in built.steps for vector in step.vectors]
    assert all(length >= plans.ZERO_MM or length < 1e-9 for length in lengths)  # nothing under the pencil
    svg = to_svg(plans.layout(plan_sheet(analysis, plan.index, plan.velocity, plan.acceleration)))
    assert "shorter than" not in svg and "короче" not in svg
