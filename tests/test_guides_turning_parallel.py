"""A PRP group whose guides turn through parallel: its joint goes off to infinity, so the crank cannot get there.

The simplest tangent mechanism: the first guide runs along the crank through its pivot O, the ram's guide is
the line y = h, so the ram stands at x = h·cot φ and runs off to infinity at φ = 0° and 180°. It was accepted
with the crank turning round (the ram 1.96 m out at one position, 0.77 m the other way at the next, with only
a "may change assembly" warning), or refused as a singular position where a sample fell on 180° exactly.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.errors import AssemblyError

HEIGHT = 0.3


def tangent(start: float | None, swing: tuple[float, float] | None = None, guide_angle: float = 0.0) -> str:
    driver_run = f"swing = [{swing[0]}, {swing[1]}]" if swing else ""
    first = f"start = {start}" if start is not None else ""
    return f"""
[frame]
points = {{ O = [0.0, 0.0] }}
lines  = {{ ram = {{ through = [0.0, {HEIGHT}], angle = {guide_angle} }} }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 2.0
{driver_run}
[[groups]]
kind = "PRP"
links = [3, 4]
joints = ["B"]
guides = [{{ link = 2, through = "O", angle = 0.0 }}, "ram"]
[positions]
count = 12
{first}
"""


@pytest.mark.parametrize("start", [21.3, 20.0, 30.0])
def test_a_crank_turning_the_guides_through_parallel_is_refused_with_its_reach(start):
    with pytest.raises(AssemblyError) as raised:
        analyse(graphplan.load_text(tangent(start)))
    message = str(raised.value)
    assert "B goes off to infinity" in message or "B would be at infinity" in message
    # The guides run parallel where the crank's direction is the ram's, sin φ = 0: the reach is 0°…180°.
    low, high = map(float, re.search(r"reaches only from (-?[\d.]+)° to (-?[\d.]+)°", message).groups())
    assert (low, high) == pytest.approx((0.0, 180.0), abs=0.01)
    assert "(at each end its two guides run parallel)" in message and "driver.swing = [" in message


def test_the_reach_follows_the_ram_s_guide_and_the_side_the_first_position_is_on():
    """The ram's guide at 25°: parallel at φ = 25° and 205°; the first position at 230° is on the far side."""
    with pytest.raises(AssemblyError) as raised:
        analyse(graphplan.load_text(tangent(230.0, guide_angle=25.0)))
    low, high = map(float, re.search(r"reaches only from (-?[\d.]+)° to (-?[\d.]+)°", str(raised.value)).groups())
    assert (low % 360.0, high % 360.0) == pytest.approx((205.0, 25.0), abs=0.01)


def test_a_swing_between_the_parallels_is_solved_as_the_tangent_law_gives():
    analysis = analyse(graphplan.load_text(tangent(None, swing=(30.0, 150.0))))
    phi = analysis.motion.driver
    ram = analysis.motion.point("B")
    np.testing.assert_allclose(ram.r[:, 0], HEIGHT / np.tan(phi), rtol=1e-12)
    # ẋ = −h·ω/sin²φ
    np.testing.assert_allclose(ram.v[:, 0], -HEIGHT * 2.0 / np.sin(phi) ** 2, rtol=1e-10)


def test_values_past_a_parallel_are_refused_in_the_python_interface_too():
    scene = graphplan.load_text(tangent(None, swing=(30.0, 150.0)))
    graphplan.solve(scene, driver=np.radians([40.0, 170.0]))
    with pytest.raises(AssemblyError, match=r"at φ = 190° \(driver\[1\]\) .*B goes off to infinity"):
        graphplan.solve(scene, driver=np.radians([40.0, 190.0]))
    assert math.isfinite(float(graphplan.solve(scene, driver=[math.radians(179.0)]).point("B").r[0, 0]))
    # Taken at the caller's first value, 190°, the reach is the other side's, and the values are what to keep in it.
    with pytest.raises(AssemblyError) as raised:
        graphplan.solve(scene, driver=np.radians([190.0, 40.0]))
    low, high = map(float, re.search(r"reaches only from (-?[\d.]+)° to (-?[\d.]+)°", str(raised.value)).groups())
    assert (low, high) == pytest.approx((180.0, 360.0), abs=0.01)
    assert str(raised.value).endswith("keep the values within one of these")
