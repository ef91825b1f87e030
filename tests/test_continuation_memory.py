"""A group found by continuation (a triad) remembers the steps of its walk while the mechanism lives.

Each solve walks from the reference position to the positions asked for in steps of a degree; the
positions of a run are found by several solves (the sweep for the extremes, the roots, the positions,
the paths), and each walked the whole turn again.  What is checked here: a second solve takes the
steps already walked from memory and Newton's method only finds the positions between them, with the
same motion as a fresh mechanism's; the memory goes with its mechanism; the extremes are found in
one round, the same assembly chosen again at the first position being recognised as the same.
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


def test_the_memory_goes_with_its_mechanism():
    gc.collect()
    before = len(motion_module._walks)
    mechanism = graphplan.build(graphplan.load(FIXTURE))
    solve(mechanism, [0.5, 1.0], reference_at(mechanism, 0.3))
    assert len(motion_module._walks) == before + 1
    del mechanism
    gc.collect()
    assert len(motion_module._walks) == before


def test_the_extremes_of_a_triad_are_found_in_one_round(monkeypatch):
    rounds = []
    original = positions_module._find_extremes

    def counted(*args):
        rounds.append(1)
        return original(*args)

    monkeypatch.setattr(positions_module, "_find_extremes", counted)
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
