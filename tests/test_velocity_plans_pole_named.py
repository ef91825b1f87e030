"""An oversized velocity_plans_pole (the pole of the velocity plans of every position) is refused under its own key
and value, with a value of it that fits: it was blamed on velocity_pole, quoting that key's value, and following
the advice changed nothing.  One so small that the plans of every position are specks is told, as a velocity_pole
that small is, under its own key: the plan sheets' larger plans hid it."""

from __future__ import annotations

import re

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.plans import spread
from graphplan.render.drawings import below_reading, refuse_beyond_paper
from graphplan.starters import starter


def shaper_with_poles(velocity_plans_pole: float) -> str:
    text = starter("shaper")
    assert "velocity_plans" in text and re.search(r"(?m)^velocity_pole\s*=", text)
    return re.sub(r"(?m)^velocity_pole(\s*)=.*$", f"velocity_pole = 100.0\nvelocity_plans_pole = {velocity_plans_pole}",
                  text)


def test_an_oversized_velocity_plans_pole_is_named_with_its_own_value_and_a_fitting_one() -> None:
    analysis = analyse(graphplan.load_text(shaper_with_poles(100000.0)))
    with pytest.raises(graphplan.SceneError) as caught:
        refuse_beyond_paper(analysis)
    message = str(caught.value)
    assert message.startswith("drawing.velocity_plans_pole: draws the velocity plan of position ")
    assert message.endswith("(got 100000.0)")
    offered = float(re.search(r"give (\d+) \(a 120 mm plan\)", message)[1])
    # At pole P mm for the crank pin's velocity vA, a plan whose points lie `spread` apart is spread·P/|vA| mm across.
    grid = [position.velocity for position in analysis.velocity_plans]
    pin = analysis.mechanism.driver.joint
    largest = max(spread(plan) * offered / max(abs(other.value(pin)) for other in grid) for plan in grid)
    assert 100.0 < largest <= 120.0
    refuse_beyond_paper(analyse(graphplan.load_text(shaper_with_poles(offered))))


def test_a_velocity_plans_pole_too_small_to_read_is_told_under_its_own_key_with_one_that_reads() -> None:
    analysis = analyse(graphplan.load_text(shaper_with_poles(0.001)))
    told = below_reading(analysis)
    assert len(told) == 1 and told[0].startswith("drawing.velocity_plans_pole: draws the largest velocity plan "), told
    offered = float(re.search(r"too small to read; (\d+) draws it 120 mm", told[0])[1])
    # The same independent measure as above: at pole P a plan is spread·P/|vA| mm across.
    grid = [position.velocity for position in analysis.velocity_plans]
    pin = analysis.mechanism.driver.joint
    largest = max(spread(plan) * offered / max(abs(other.value(pin)) for other in grid) for plan in grid)
    assert 100.0 < largest <= 120.0
    assert below_reading(analyse(graphplan.load_text(shaper_with_poles(offered)))) == []
