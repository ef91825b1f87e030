"""A group found by continuation (a triad) remembers the steps of its walk while the scene lives.

Each solve walks from the reference position to the positions asked for in steps of a degree; the
positions of a run are found by several solves (the sweep for the extremes, the roots, the positions,
the paths), and each walked the whole turn again.  What is checked here: a second solve takes the
steps already walked from memory and Newton's method only finds the positions between them, with the
same motion as a fresh mechanism's; every mechanism built from one scene shares the memory, and
``graphplan.solve`` finds the scene's positions once (it built the mechanism afresh at each call, and
walked the whole grid and found the extremes again each time); the memory goes with its scene; the
extremes are found in one round, the same assembly chosen again at the first position being
recognised as the same.
"""

from __future__ import annotations

import gc
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan import motion as motion_module
from graphplan import positions as positions_module
from graphplan.groups.triad import Triad
from graphplan.motion import reference_at, solve

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
FIXTURE = FIXTURES / "triad_class_iii.toml"


@pytest.fixture
def settled(monkeypatch):
    """Newton's method on the triad: each pose settled on its own (the walk's steps), and each batch of the
    positions asked for between the steps (their counts), counted from the fixture's start."""
    calls = {"alone": 0, "batches": []}
    alone, together = Triad._settle, Triad._settle_many

    def counted(self, guess, tracks, turn):
        calls["alone"] += 1
        return alone(self, guess, tracks, turn)

    def counted_many(self, guesses, tracks, turn):
        calls["batches"].append(len(guesses))
        return together(self, guesses, tracks, turn)

    monkeypatch.setattr(Triad, "_settle", counted)
    monkeypatch.setattr(Triad, "_settle_many", counted_many)
    return calls


@pytest.fixture
def only_new_objects_collected():
    """gc.collect() within the test looks only at the objects made since it began (gc.freeze): what the tests
    before it left in the worker, live or garbage, stands aside, as a full collection would leave it kept or
    gone.  Each full collection of a worker that has run other modules walked all they left: 18 s for the
    three of test_the_memory_goes_with_its_scene, which takes half a second alone."""
    gc.freeze()
    try:
        yield
    finally:
        gc.unfreeze()


def test_a_second_solve_finds_only_the_positions_between_the_steps_walked(settled):
    mechanism = graphplan.build(graphplan.load(FIXTURE))
    reference = reference_at(mechanism, 0.3)
    settled.update(alone=0, batches=[])
    first = solve(mechanism, np.linspace(0.0, 2 * np.pi, 13), reference)
    assert settled["alone"] >= 360  # a step a degree, a whole turn
    settled.update(alone=0, batches=[])
    asked = np.array([0.1234, 1.5, 4.321, 6.0])
    again = solve(mechanism, asked, reference)
    # Each off the steps, settled from the step before it, all in one batch; no step walked again.
    assert settled == {"alone": 0, "batches": [len(asked)]}
    settled.update(alone=0, batches=[])
    repeated = solve(mechanism, np.linspace(0.0, 2 * np.pi, 13), reference)
    assert settled == {"alone": 0, "batches": [13]}  # only the asked positions, all off the steps counted from 0.3 rad
    fresh_mechanism = graphplan.build(graphplan.load(FIXTURE))
    fresh = solve(fresh_mechanism, asked, reference_at(fresh_mechanism, 0.3))
    for name in ("B", "D", "F"):
        assert np.max(np.abs(again.point(name).r - fresh.point(name).r)) <= 1e-13
        assert np.max(np.abs(again.point(name).a - fresh.point(name).a)) <= 1e-9
        assert np.array_equal(first.point(name).r, repeated.point(name).r)


def test_dense_positions_are_settled_together_as_each_would_be_alone(settled):
    """36 000 positions a turn took a minute, each settled by scipy from the one before: the walk steps a
    degree alone, the positions between the steps are settled in one batch, each the pose its own solve
    from the step before it finds."""
    mechanism = graphplan.build(graphplan.load(FIXTURE))
    reference = reference_at(mechanism, 0.3)
    dense = 0.3 + np.linspace(-np.pi, np.pi, 36001)[:-1]
    settled.update(alone=0, batches=[])
    together = solve(mechanism, dense, reference)
    # The 360 steps of the turn and the reference alone; the rest (all but the few that fall on a step) together.
    assert settled["alone"] <= 361 and len(settled["batches"]) == 1 and settled["batches"][0] >= 36000 - 361
    sample = np.arange(17, 36000, 997)
    for index in sample:
        alone = solve(graphplan.build(graphplan.load(FIXTURE)), [dense[index]], reference)
        for name in ("B", "D", "F"):
            assert abs(together.point(name).r[index] - alone.point(name).r[0]) == pytest.approx(0.0, abs=1e-13)
            assert abs(together.point(name).a[index] - alone.point(name).a[0]) == pytest.approx(0.0, abs=1e-9)


@pytest.fixture
def rounds(monkeypatch):
    """One entry for each round of the search for the extremes (a sweep of the turn and the roots in it)."""
    found = []
    original = positions_module._find_extremes

    def counted(*args):
        found.append(1)
        return original(*args)

    monkeypatch.setattr(positions_module, "_find_extremes", counted)
    return found


def test_a_second_solve_of_the_same_scene_walks_no_step_and_finds_its_positions_once(settled, rounds):
    """graphplan.solve built the mechanism afresh at each call: a finite-difference stencil's eleven solves of one
    scene each walked the whole turn and found the extremes again (seconds a solve)."""
    path = FIXTURES / "triad_with_slider.toml"  # starts at an extreme: the positions are found by solves too
    scene = graphplan.load(path)
    asked = [0.1, 0.2, 3.0]
    settled.update(alone=0, batches=[])
    first = graphplan.solve(scene, driver=asked)
    assert settled["alone"] >= 360 and len(rounds) == 1  # the whole turn walked to find the extremes
    settled.update(alone=0, batches=[])
    again = graphplan.solve(scene, driver=asked)
    assert settled["alone"] == 0 and len(rounds) == 1  # no step walked, the extremes not sought again
    positions = graphplan.solve(scene)
    assert settled["alone"] == 0 and len(rounds) == 1
    settled.update(alone=0, batches=[])
    fresh_scene = graphplan.load(path)
    fresh = graphplan.solve(fresh_scene, driver=asked)
    assert settled["alone"] >= 360 and len(rounds) == 2  # another scene (the same file): its own walk
    fresh_positions = graphplan.solve(fresh_scene)
    for name in fresh.points:
        for kind in ("r", "v", "a"):
            assert np.array_equal(getattr(again.point(name), kind), getattr(fresh.point(name), kind)), (name, kind)
            assert np.array_equal(getattr(first.point(name), kind), getattr(fresh.point(name), kind)), (name, kind)
            assert np.array_equal(getattr(positions.point(name), kind), getattr(fresh_positions.point(name), kind))
    assert np.array_equal(positions.driver, fresh_positions.driver)


def test_the_memory_goes_with_its_scene(only_new_objects_collected):
    walks, position_sets = len(motion_module._walks), len(positions_module._position_sets)
    scene = graphplan.load(FIXTURE)
    mechanism = graphplan.build(scene)
    solve(mechanism, [0.5, 1.0], reference_at(mechanism, 0.3))
    positions_module.make_positions(mechanism)
    assert len(motion_module._walks) == walks + 1
    assert len(positions_module._position_sets) == position_sets + 1
    del mechanism
    gc.collect()
    # Another build of the scene is the same mechanism: it walks on from the first one's steps.
    other = graphplan.build(scene)
    solve(other, [0.5, 2.0], reference_at(other, 0.3))
    assert len(motion_module._walks) == walks + 1
    del other, scene
    gc.collect()
    assert len(motion_module._walks) == walks
    assert len(positions_module._position_sets) == position_sets


def test_positions_refused_are_refused_at_every_call_and_those_found_cannot_be_changed(
        only_new_objects_collected):
    """Only positions found are kept: a scene refused is refused again (not handed a set, nor another error); and
    the arrays every caller is handed are read-only, so that no caller changes another's positions."""
    import dataclasses

    from graphplan.errors import SceneError

    scene = graphplan.load(FIXTURES / "triad_with_slider.toml")
    # The crank as the working link: it turns round, so there is no extreme for the positions to start from.
    cranked = dataclasses.replace(scene, positions=dataclasses.replace(
        scene.positions, working=dataclasses.replace(scene.positions.working, link=2, sense="ccw")))
    gc.collect()
    kept = len(positions_module._position_sets)
    for _ in range(2):
        with pytest.raises(SceneError, match=r"^positions\.start: .*link 2 turns round"):
            graphplan.solve(cranked)
        assert len(positions_module._position_sets) == kept
    positions = positions_module.make_positions(graphplan.build(scene))
    for array in (positions.values, positions.numbers):
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 0
    with pytest.raises(TypeError):
        positions.load_strokes[(5, "forward")] = (0.0, 1.0)  # type: ignore[index]


def test_the_extremes_of_a_triad_are_found_in_one_round(rounds):
    found = graphplan.solve(graphplan.load(FIXTURES / "triad_with_slider.toml"))  # starts at an extreme
    assert len(rounds) == 1
    # The first position is the extreme: the working link is at rest there.
    working = found.mechanism.scene.positions.working
    assert abs(float(found.link(working.link).omega[0])) <= 1e-9 * float(np.max(np.abs(found.link(working.link).omega)))


def test_a_walk_that_would_not_end_is_refused_at_once():
    """Angles a hundred turns off, or 1e20 rad, were walked to a degree at a time (minutes, or numpy's "Maximum
    allowed size exceeded"); each is refused before the walk, naming the value and how far it is."""
    from graphplan.errors import SceneError

    scene = graphplan.load(FIXTURE)
    for far, turns in ((1e20, r"1\.59e\+19"), (2 * np.pi * 101, "101")):
        with pytest.raises(SceneError, match=rf"^driver: .* is {turns} turns from the reference position 0 rad: "):
            graphplan.solve(scene, driver=[0.0, far])
    within = graphplan.solve(scene, driver=[2 * np.pi * 3 + 1.0])  # three turns on: walked, and the turn's pose
    assert np.allclose(within.point("B").r, graphplan.solve(scene, driver=[1.0]).point("B").r, atol=1e-12)
