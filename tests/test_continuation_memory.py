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
    """The number of times Newton's method is started on the triad, counted from the fixture's start."""
    calls = []
    original = Triad._settle

    def counted(self, guess, tracks, turn):
        calls.append(1)
        return original(self, guess, tracks, turn)

    monkeypatch.setattr(Triad, "_settle", counted)
    return calls


def test_a_second_solve_finds_only_the_positions_between_the_steps_walked(settled):
    mechanism = graphplan.build(graphplan.load(FIXTURE))
    reference = reference_at(mechanism, 0.3)
    settled.clear()
    first = solve(mechanism, np.linspace(0.0, 2 * np.pi, 13), reference)
    walked = len(settled)
    assert walked >= 360  # a step a degree, a whole turn
    settled.clear()
    asked = np.array([0.1234, 1.5, 4.321, 6.0])
    again = solve(mechanism, asked, reference)
    assert len(settled) == len(asked)  # each off the steps, one Newton solve from the step before it
    settled.clear()
    repeated = solve(mechanism, np.linspace(0.0, 2 * np.pi, 13), reference)
    assert len(settled) == 13  # only the asked positions, all off the steps counted from 0.3 rad
    fresh_mechanism = graphplan.build(graphplan.load(FIXTURE))
    fresh = solve(fresh_mechanism, asked, reference_at(fresh_mechanism, 0.3))
    for name in ("B", "D", "F"):
        assert np.max(np.abs(again.point(name).r - fresh.point(name).r)) <= 1e-13
        assert np.max(np.abs(again.point(name).a - fresh.point(name).a)) <= 1e-9
        assert np.array_equal(first.point(name).r, repeated.point(name).r)


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
