"""The Python interface for notebooks: scene.solve(), scene.plan(n), drawings that show themselves."""

from __future__ import annotations

import dataclasses
from types import MappingProxyType
from xml.etree import ElementTree

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse

RATCHET = "fixtures/ratchet_crank_rocker.toml"


@pytest.fixture(scope="module")
def scene():
    return graphplan.load(RATCHET)


def test_solve_is_the_module_solve(scene):
    here, there = scene.solve(), graphplan.solve(scene)
    np.testing.assert_array_equal(here.link(4).omega, there.link(4).omega)
    dense = scene.solve(driver=np.radians([10.0, 20.0]))
    assert dense.point("B").r.shape == (2, 2)


def test_a_listed_position_gives_the_plans_of_the_run(scene):
    """Position 5 is listed in the scene: its notebook plans read what the run's plans read."""
    five = scene.plan(5)
    run = next(plan for plan in analyse(scene).plans if plan.number == 5)
    assert five.number == 5
    assert five.velocity.scale == run.velocity.scale
    for reading in run.readings:
        assert five.values[reading.quantity] == pytest.approx(reading.value(run.plans), rel=1e-12)
    # The values read off the plans are the motion's: VB against the analytic speed of B.
    assert five.values["VB"] == pytest.approx(float(np.hypot(*scene.solve().point("B").v[5])), rel=1e-9)


def test_an_unlisted_position_is_planned_too(scene):
    three = scene.plan(3)
    assert three.values["VB"] == pytest.approx(float(np.hypot(*scene.solve().point("B").v[3])), rel=1e-9)
    assert three.forces is not None


def test_a_position_shows_itself_as_its_plan_sheet(scene, tmp_path):
    three = scene.plan(3)
    svg = three._repr_svg_()
    root = ElementTree.fromstring(svg)
    assert root.tag.endswith("svg")
    assert any((element.get("id") or "").startswith("velocity") for element in root.iter())
    assert three.forces_drawing._repr_svg_().startswith("<?xml") or "<svg" in three.forces_drawing.svg
    saved = three.drawing.save(tmp_path / "three.svg")
    assert saved.read_text(encoding="utf-8") == svg


def test_no_such_position(scene):
    # A GraphplanError, as the README promises of bad input (a plain ValueError escaped `except GraphplanError`).
    with pytest.raises(graphplan.GraphplanError, match="^positions: no position 12: the scene numbers its positions "
                                                      "0 to 11$"):
        scene.plan(12)


def test_a_position_with_friction_shows_its_sheet_with_friction(scene):
    import dataclasses

    from graphplan.notebook import plan
    from graphplan.scene import FrictionSpec

    assert scene.plan(3).forces_with_friction_drawing is None  # the scene has no [[friction]]
    rubbing = dataclasses.replace(scene, friction=(FrictionSpec("friction[0]", "O", None, 0.1, 0.02, None),))
    svg = plan(rubbing, 3).forces_with_friction_drawing.svg
    root = ElementTree.fromstring(svg)
    assert any((element.get("id") or "").endswith("-friction") for element in root.iter())


def test_hand_readings_of_a_position_drawn_only_among_the_velocity_plans_are_read_at_their_scale(scene):
    """A student who drew a position only among the velocity plans of every position measured it there, at their
    μV; scene.plan(n) draws a plan sheet at another μV and read the readings at that one (40 % off where the
    run's error table said 0.7 %)."""
    first, count = scene.positions.number_from, scene.positions.count
    speeds = np.hypot(*scene.solve().point("B").v.T)
    # A position between the extremes (at an extreme B stands still and a percentage of it means nothing).
    number = next(n for n in range(first, first + count) if n not in scene.positions.plans and speeds[n - first] > 0.1)
    grid_scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions,
                                                                          velocity_plans=tuple(range(first, first + count))))
    grid = next(position for position in analyse(grid_scene).velocity_plans if position.number == number)
    exact = float(speeds[number - first])
    drawn = 1.02 * exact / grid.velocity.scale  # a reading 2 % long, on the plan drawn at the grid's μV
    measured = dataclasses.replace(grid_scene, measured=MappingProxyType(
        {number: MappingProxyType({"velocity": MappingProxyType({"pb": drawn})})}))
    planned = measured.plan(number)
    assert planned.velocity.scale != pytest.approx(grid.velocity.scale)  # the plan sheet is at another μV
    [row] = [row for row in planned.errors if row.source == "measured" and row.quantity == "VB"]
    assert row.plan == pytest.approx(1.02 * exact, rel=1e-9)
    assert row.percent == pytest.approx(-2.0, rel=1e-6)


def test_a_position_s_plan_sheet_is_the_run_s_at_the_mu_l_the_run_chooses(tmp_path):
    """The Russian shaper leaves μl to the program, which takes the one that lays the run's drawings (positions 3
    and 10) on the fewest sheets, 0.004 m/mm; the notebook chose it for position 3 alone and drew 0.005."""
    from graphplan.cli import main
    from graphplan.starters import starter

    path = tmp_path / "shaper.toml"
    path.write_text(starter("shaper", "ru"), encoding="utf-8")
    assert main(["run", str(path), "--out", str(tmp_path / "run"), "--only", "velocity,acceleration"]) == 0
    written = (tmp_path / "run" / "plan_3.svg").read_text(encoding="utf-8")
    assert "μl = 0,004 м/мм" in written
    assert graphplan.load(path).plan(3).drawing.svg == written
