"""Zhukovsky's lever with friction: arms that are one perpendicular are drawn and named once.

Several couples' forces on the lever with friction act along one line (the inertia moment's and the journals'
friction moments' couples of one link put their forces at the same two images across it; the crank's couples lie on
the balancing force's line), so their arms from the pole p are one perpendicular: the lever names it once and every
term on that line takes that name in ΣMp.  Checked here against each term's perpendicular from the pole worked out
from the lever's points (the velocity plan's images turned 90° clockwise, at the scale the lever is drawn at): every
arm name's length, drawn or given under the lever, is each of its terms' own distance, and there are as many names
as distinct perpendiculars, numbered h1, h2, … without a gap.
"""

from __future__ import annotations

import collections
import functools
import math
import re

import pytest
from lever_equation import unfactored
from scene_texts import journal_friction

from graphplan.analysis import analyse
from graphplan.render import drawings
from graphplan.render import forces as force_layout
from graphplan.render.primitives import Polyline, svg_id
from graphplan.scene import loads as scene_of_text
from graphplan.starters import starter

# A crank-rocker (`graphplan new crank-rocker`) with friction in its four journals.
CRANK_ROCKER_WITH_FRICTION = starter("crank-rocker") + journal_friction({"O": 0.02, "A": 0.015, "B": 0.015, "C": 0.02})
# The scene's drafting precision (mm): two perpendiculars whose feet are closer are one on the drawing.
PRECISION_MM = 0.5


@functools.cache
def lever_drawing(number: int):
    found = analyse(scene_of_text(CRANK_ROCKER_WITH_FRICTION))
    position = next(position for position in found.plans if position.number == number)
    sheet = drawings.force_sheet(found, position, with_friction=True)
    (drawing,) = [drawing for row in force_layout.rows(sheet).drawings for drawing in row if drawing.name == "lever"]
    return position, sheet, drawing


def _feet(sheet) -> dict[str, complex]:
    """Each load's foot of the perpendicular from the pole to its line on the drawn lever (mm), Fb's too."""
    lever, velocity, drawn_at = sheet.lever, sheet.velocity, sheet.lever_drawn_scale
    lines = [(term.name, velocity.points[term.image] + term.shift, term.force) for term in lever.terms if term.image]
    lines.append(("Fb", velocity.points[lever.balancing_image], lever.balancing_force))
    feet = {}
    for name, point, force in lines:
        if force == 0:
            continue
        at = -1j * point / drawn_at  # turned 90° clockwise
        unit = force / abs(force)
        feet[name] = at - (at.real * unit.real + at.imag * unit.imag) * unit
    return feet


def _equation(drawing) -> list[tuple[str, str]]:
    (line,) = [line for line in drawing.caption if line.startswith("ΣMp:")]
    return re.findall(r"([^\s+−]+)·(h\w+)", unfactored(line))


def _arm_lengths(drawing, terms: list[tuple[str, str]]) -> dict[str, float]:
    """Each arm name's length on the drawing (mm): its perpendicular drawn from the pole, or given under the lever."""
    arm_of = dict(terms)
    lengths = {}
    for layer in drawing.layers:
        if not layer.name.startswith("lever-arm-"):
            continue
        for item in layer.items:
            if isinstance(item, Polyline) and item.points[0] == (0.0, 0.0):
                name = next(name for name in arm_of if layer.name == svg_id("lever-arm", name))
                assert arm_of[name] not in lengths, f"{arm_of[name]} drawn twice"
                lengths[arm_of[name]] = math.dist(*item.points)
    for line in drawing.caption:
        for arm, value in re.findall(r"(h\w+) = ([\d.]+) mm", line):
            lengths.setdefault(arm, float(value))
    return lengths


@pytest.mark.parametrize("number", [5, 11])
def test_each_term_s_arm_is_its_own_perpendicular(number):
    _, sheet, drawing = lever_drawing(number)
    terms = _equation(drawing)
    feet = _feet(sheet)
    lengths = _arm_lengths(drawing, terms)
    for name, arm in terms:
        assert lengths[arm] == pytest.approx(abs(feet[name]), abs=PRECISION_MM), (name, arm)
    # Terms named alike are one perpendicular: their feet stand together.
    for name, arm in terms:
        for other, other_arm in terms:
            if arm == other_arm:
                assert abs(feet[name] - feet[other]) <= PRECISION_MM, (name, other)


@pytest.mark.parametrize("number", [5, 11])
def test_one_name_for_each_distinct_perpendicular_numbered_without_a_gap(number):
    _, sheet, drawing = lever_drawing(number)
    terms = _equation(drawing)
    feet = _feet(sheet)
    # The distinct perpendiculars of the equation's terms, gathered here by their feet.
    distinct: list[complex] = []
    for name, _ in terms:
        foot = feet[name]
        if not any(abs(foot - other) <= PRECISION_MM and abs(foot) > PRECISION_MM for other in distinct):
            distinct.append(foot)
    names = {arm for _, arm in terms}
    assert len(names) == len(distinct)
    numbered = sorted(int(arm[1:]) for arm in names if arm != "hb")
    assert numbered == list(range(1, len(numbered) + 1))
    # Terms on different perpendiculars keep different names.
    for name, arm in terms:
        for other, other_arm in terms:
            if abs(feet[name] - feet[other]) > PRECISION_MM:
                assert arm != other_arm, (name, other)


def test_the_friction_lever_shares_arms_at_position_5():
    """The case that crowded h4, h11, h15 at one foot: fewer names than terms, and Fb's line shared too."""
    _, _, drawing = lever_drawing(5)
    terms = _equation(drawing)
    assert len({arm for _, arm in terms}) < len(terms)
    assert sum(arm == "hb" for _, arm in terms) > 1


@pytest.mark.parametrize("number", [5, 11])
def test_a_shared_arm_is_taken_out_of_brackets_once_each_load_keeping_its_moment_s_sign(number):
    """ΣMp writes the loads on one perpendicular as one term, (A − B)·h: each arm once, hb once for the loads and
    once for the unknown Fb; multiplied out, every load's sign is its moment's about the pole."""
    _, sheet, drawing = lever_drawing(number)
    (line,) = [line for line in drawing.caption if line.startswith("ΣMp:")]
    written = collections.Counter(re.findall(r"·(h\w+)", line))
    assert all(count == 1 for arm, count in written.items() if arm != "hb") and written["hb"] <= 2, line
    assert "(" in line  # the journals' friction couples share their links' inertia couples' lines
    moments = {term.name: term.moment for term in sheet.lever.terms}
    for sign, name in re.findall(r"([+−]) ([^\s+−]+)·h\w+", unfactored(line.replace("ΣMp: ", "ΣMp: + "))):
        if name != "Fb":
            assert (sign == "−") == (moments[name] < 0), (name, line)


@pytest.mark.parametrize("number", [5, 11])
def test_the_balancing_moment_stands(number):
    position, sheet, _ = lever_drawing(number)
    assert sheet.lever.balancing == pytest.approx(position.with_friction.balancing, rel=1e-6)
