"""The scale a hand-drawn plan was laid off at, as the ``measured-far-off`` warning advises it: the advice must be the
value the student drew at, and following it must make readings exact at that value agree with the construction.

Every reading here is computed from the analytic motion (``graphplan.solve``), not from the program's plans: a plan
laid off with the driver's vector pa (or πa) at P mm has μ = |v_A| / P, so a segment of it is |v| · P / |v_A| mm.
"""

import dataclasses
import re

import pytest

import graphplan
from graphplan.analysis import analyse

FIXTURE = "fixtures/ratchet_crank_rocker.toml"
POSITION = 5  # numbered from 0: the motion's index 5
# Segment → the point (or the pair, B relative to A) whose velocity / acceleration it stands for.
SEGMENTS = {"pb": ("B",), "ab": ("B", "A"), "pe": ("E",), "ps3": ("S3",)}


def _magnitude(motion, attribute, points, index):
    values = [complex(*getattr(motion.point(name), attribute)[index]) for name in points]
    return abs(values[0] - values[1]) if len(values) == 2 else abs(values[0])


def readings_at(motion, kind, pole, index=POSITION):
    """The segments of a plan laid off with the driver's vector at ``pole`` mm, read to 0.01 mm."""
    attribute = "v" if kind == "velocity" else "a"
    driver = _magnitude(motion, attribute, ("A",), index)
    return {name: round(_magnitude(motion, attribute, points, index) * pole / driver, 2)
            for name, points in SEGMENTS.items()}


def far_off(analysis):
    return [w for w in analysis.warnings if w.code == "measured-far-off"]


@pytest.mark.parametrize("kind", ["velocity", "acceleration"])
@pytest.mark.parametrize("pole", [120.0, 95.0, 180.0])
def test_a_plan_drawn_at_a_whole_pole_distance_is_advised_that_distance(kind, pole):
    """A plan drawn at exactly 120 mm was advised velocity_pole = 125 (the coarsest round step within 5 %), and
    every reading taken at 125 was 4 % off though the drawing had no error of its own."""
    scene = graphplan.load(FIXTURE)
    # The scene's plans at 60 mm: every reading well beyond the 15 % the warning needs.
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, **{f"{kind}_pole": 60.0}))
    readings = readings_at(graphplan.solve(scene), kind, pole)
    measured = dataclasses.replace(scene, measured={POSITION: {kind: readings}})
    (warning,) = far_off(analyse(measured))
    assert f"give `[drawing] {kind}_pole = {pole:g}`" in warning.detail, warning.detail
    within = float(re.search(r"every reading is within ([\d.]+) % of the plan", warning.detail)[1])
    assert within < 0.1
    # Following the advice: no warning, and every reading within 0.1 % of the plan as constructed.
    followed = dataclasses.replace(measured, drawing=dataclasses.replace(scene.drawing, **{f"{kind}_pole": pole}))
    analysis = analyse(followed)
    assert not far_off(analysis)
    plan = next(p for p in analysis.plans if p.number == POSITION)
    constructed = {row.quantity: row.plan for row in plan.errors if row.source == "construction"}
    measured_rows = [row for row in plan.errors if row.source == "measured"]
    assert len(measured_rows) >= len(SEGMENTS)
    for row in measured_rows:
        assert abs(row.plan / constructed[row.quantity] - 1.0) < 1e-3, row


@pytest.mark.parametrize("pole", [120.0, 95.0, 180.0])
def test_the_velocity_plans_of_every_position_drawn_at_a_whole_pole_are_advised_that_pole(pole):
    """The same rounding advised velocity_plans_pole = 125 for a grid plan drawn at 120 mm."""
    scene = graphplan.load(FIXTURE)
    scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, velocity_plans=tuple(range(12))),
                                drawing=dataclasses.replace(scene.drawing, velocity_plans_pole=60.0))
    readings = readings_at(graphplan.solve(scene), "velocity", pole, index=3)
    measured = dataclasses.replace(scene, measured={3: {"velocity": readings}})
    (warning,) = far_off(analyse(measured))
    assert f"give `[drawing] velocity_plans_pole = {pole:g}`" in warning.detail, warning.detail
    followed = dataclasses.replace(measured, drawing=dataclasses.replace(scene.drawing, velocity_plans_pole=pole))
    analysis = analyse(followed)
    assert not far_off(analysis)
    rows = [row for row in analysis.errors if row.position == 3 and row.source == "measured"]
    assert rows and all(abs(row.percent) < 0.1 for row in rows)
