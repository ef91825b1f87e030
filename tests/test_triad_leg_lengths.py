"""A triad that stops a crank which should turn round is told, leg by leg, the lengths that close it at every angle of
the turn, the other legs as given, as a dyad is told its lengths (one that closes at no angle, those that close it at
some); a triad with a sliding leg has its digit-off lengths tried too, and its keys told as written.  The triad's
refusal gave the crank's reach and a swing, and nothing to make it turn round, where a dyad's said which lengths
would.  Each bound told is checked against the solver itself: at the bound the crank turns round (or reaches),
half a percent past it it does not."""

from __future__ import annotations

import functools
import math
import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from test_motion_against_finite_differences import _HUNG_ON_THE_RATCHET, _hung_on_the_ratchet

import graphplan
from graphplan.errors import AssemblyError
from graphplan.mechanism import build
from graphplan.positions import reach, turns_round
from graphplan.scene import Scene, loads

TRIAD = Path("fixtures/triad_class_iii.toml").read_text(encoding="utf-8")
WITH_SLIDER = Path("fixtures/triad_with_slider.toml").read_text(encoding="utf-8")


def _edited(text: str, old: str, new: str) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def _refusal(scene) -> str:
    with pytest.raises(AssemblyError) as refused:
        scene.analyse()
    return str(refused.value)


def _ranges(message: str) -> dict[int, tuple[float, float | None]]:
    """The told ranges by the index of ``lengths``: from, to (None: up)."""
    told = re.findall(r"lengths\[(\d)\] \(\w+\) from ([\d.]+) m (?:to ([\d.]+) m|up)", message)
    return {int(index): (float(low), float(high) if high else None) for index, low, high in told}


def _turns_round(scene, group: int, index: int, length: float) -> bool:
    """Whether the crank turns round with the ``index``-th length the triad's table writes set to ``length``."""
    triad = scene.groups[group]
    legs = [n for n, value in enumerate(triad.lengths) if value]  # as written: the turning legs' only
    lengths = list(triad.lengths)
    lengths[legs[index]] = length
    changed = replace(triad, lengths=tuple(lengths))
    return turns_round(build(replace(scene, groups=(*scene.groups[:group], changed, *scene.groups[group + 1:]))))


def _assert_bounds_hold(scene, group: int, told: dict[int, tuple[float, float | None]]) -> None:
    for index, (low, high) in told.items():
        assert _turns_round(scene, group, index, low) and not _turns_round(scene, group, index, low * 0.995), index
        if high is not None:
            assert _turns_round(scene, group, index, high), index
            assert not _turns_round(scene, group, index, high * 1.005), index


@functools.cache
def _short_ab() -> tuple[Scene, str]:
    """The fixture's triad with AB shortened to 0.08 m, and its refusal: the crank reaches 178° of its turn."""
    scene = loads(_edited(TRIAD, "lengths = [0.135, 0.108, 0.189]", "lengths = [0.08, 0.108, 0.189]"))
    return scene, _refusal(scene)


def test_each_leg_is_told_the_lengths_that_turn_the_crank_round():
    """AB shortened: AB and EF are each told a range; the solver turns the crank round at each end told, and not
    half a percent beyond it."""
    scene, message = _short_ab()
    assert "if link 2 is meant to turn round, check the lengths: the triad closes at every angle of the turn, the " \
           "other legs as given, only with groups[0].lengths[0] (AB) from" in message
    told = _ranges(message)
    assert sorted(told) == [0, 2]
    _assert_bounds_hold(scene, 0, told)


def test_a_leg_no_length_of_which_helps_is_told_where_the_others_cannot_close():
    """With AB at 0.08 m, no CD helps: at the angle told, B on its circle about A and F on its circle about E are
    never FB apart, whatever the ternary link's turn, which the circles' nearest and farthest points show."""
    _, message = _short_ab()
    (degrees,) = re.findall(r"no length of CD alone does: at φ = ([\d.]+)° AB and EF close at no turn of link 6",
                            message)
    a = complex(*graphplan.solve(loads(TRIAD), driver=[math.radians(float(degrees))]).point("A").r[0])
    e, ab, ef, fb = 0.10 + 0.35j, 0.08, 0.189, 0.108
    apart = abs(e - a)
    nearest = max(0.0, apart - ab - ef, abs(ab - ef) - apart)
    assert not nearest <= fb <= apart + ab + ef


def test_a_triad_that_closes_at_no_angle_is_told_each_leg_s_lengths_that_close_it_at_some():
    """AB at 0.02 m: the triad closes at no angle of the crank.  Each leg is told the lengths that close it at some
    angle, the other legs as given; the solver finds a reach at each end told, and none half a percent beyond."""
    scene = loads(_edited(TRIAD, "lengths = [0.135, 0.108, 0.189]", "lengths = [0.02, 0.108, 0.189]"))
    message = _refusal(scene)
    assert "the mechanism assembles at no angle of link 2: the triad closes at some angle, the other legs as given, " \
           "only with groups[0].lengths[0] (AB) from" in message
    told = _ranges(message)
    assert sorted(told) == [0, 1, 2]

    def reaches(length: float) -> bool:
        changed = replace(scene.groups[0], lengths=(length, 0.108, 0.189))
        return bool(reach(build(replace(scene, groups=(changed,)))))

    low, high = told[0]
    assert reaches(low) and reaches(high) and not reaches(low * 0.995) and not reaches(high * 1.005)


def test_lengths_that_close_at_every_angle_are_not_told_as_the_cause():
    """CD at 0.333 m closes the triad with a sliding leg at every angle, but the assembly the scene follows folds on
    the way: no length is told, for no one leg's is what stops it."""
    text = _edited(WITH_SLIDER, "lengths = [0.17, 0.14] ", "lengths = [0.17, 0.333]")
    message = _refusal(loads(text))
    assert "reaches only from" in message and "check the lengths" not in message
    assert "groups[0].lengths = [0.17, 0.333]," in message  # as written: the sliding leg has no length there


def test_a_triad_with_a_sliding_leg_is_tried_a_digit_off_its_lengths_as_written():
    scene = loads(_edited(WITH_SLIDER, "lengths = [0.17, 0.14] ", "lengths = [0.17, 0.014]"))
    message = _refusal(scene)
    assert "groups[0].lengths[1] = 0.14, a digit off the 0.014 m given, turns it round" in message
    assert _turns_round(scene, 0, 1, 0.14)
    told = _ranges(message)
    assert sorted(told) == [0, 1] and told[1][0] <= 0.14 <= told[1][1]


@pytest.mark.parametrize(("variant", "old", "new", "legs"), [
    ("ratchet+triad-slot", "lengths = [0.17, 0.18]", "lengths = [0.17, 0.12]", [0, 1]),
    ("ratchet+triad-slot-and-guide", "lengths = [0.17]", "lengths = [0.03]", [0]),
], ids=["slot", "slot-and-guide"])
def test_a_triad_with_a_slot_is_told_its_turning_legs_lengths(variant, old, new, legs):
    """The ratchet's triads with a leg in a slot of the ternary link: the slot turns with it, and the bounds still
    hold; with a guide besides, a leg may be as long as it likes (its corner runs off along the guide)."""
    scene = _hung_on_the_ratchet(_edited(_HUNG_ON_THE_RATCHET[variant], old, new))()
    told = _ranges(_refusal(scene))
    assert sorted(told) == legs
    _assert_bounds_hold(scene, 1, {legs[-1]: told[legs[-1]]})  # one leg's: each turn round takes a second
    if variant.endswith("guide"):
        assert told[0][1] is None and _turns_round(scene, 1, 0, 1.0)
    assert not np.isnan([bound for low_high in told.values() for bound in low_high if bound is not None]).any()


def test_a_leg_whose_corner_passes_over_its_outer_joint_is_told_a_length_under_its_farthest():
    """Where the corner comes onto the leg's outer joint at some angle, any length short of the farthest closes the
    triad there: told as under it, not from a length of 10⁻¹⁷ m."""
    from graphplan.groups.triad_legs import LegReach

    scene = loads(TRIAD)
    triad = scene.groups[0]
    told = triad._lengths_told((LegReach(0, 1e-17, 0.3), LegReach(1, None, None), LegReach(2, 0.25, None)),
                               None, "at some angle")
    assert told == ("the triad closes at some angle, the other legs as given, only with groups[0].lengths[0] (AB) "
                    "under 0.2999 m, or groups[0].lengths[2] (EF) from 0.2501 m up; no length of CD alone does")


def test_the_turn_asked_spread_out_gives_the_answer_asked_angle_by_angle_from_nought(monkeypatch):
    """turns_round asks the angles of the turn spread out (0°, 256°, 128°, …), where a range the crank does not
    reach is met in a few asks: the answer is the one the angles asked from 0° up give, on either side of each bound
    the refusal tells for the short AB's triad's legs (the crank turning round and not)."""
    from graphplan import positions

    scene, message = _short_ab()
    answers = []
    for order in (positions._SPREAD, np.arange(positions._REACH_GRID)):
        monkeypatch.setattr(positions, "_SPREAD", order)
        answers.append([_turns_round(scene, 0, index, length * factor)
                        for index, bounds in _ranges(message).items() for length in bounds if length is not None
                        for factor in (1.0, 0.995, 1.005)])
    assert answers[0] == answers[1] and True in answers[0] and False in answers[0]
