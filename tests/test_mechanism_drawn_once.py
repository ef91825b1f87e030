"""A plan sheet's mechanism is drawn once for what it is drawn from (plans._MECHANISMS): the course sheets try each
plan sheet under a few captions, which leave the mechanism as it was.  What the memo gives is what drawing it anew
gives: every sheet of a run is the same to the byte with the memo as without it."""
from collections import Counter

import pytest
from light_runs import FIXTURES_FOLDER

import graphplan
from graphplan.analysis import analyse
from graphplan.memo import OwnedMemo
from graphplan.render import plans
from graphplan.run import run


class _Forgetful(OwnedMemo):
    """A memo that keeps nothing: every mechanism drawn anew."""

    def get(self, owner, key, make):
        return make()


def _drawn(folder, monkeypatch, memo):
    """The sheets a run of the shaper's fixture writes with ``memo`` for the mechanisms, and how often each plan
    sheet's mechanism (its position and μl) was drawn."""
    counts: Counter = Counter()
    drawn_mechanism = plans._drawn_mechanism

    def counted(sheet):
        counts[sheet.index, sheet.length_scale] += 1
        return drawn_mechanism(sheet)

    with monkeypatch.context() as patch:
        patch.setattr(plans, "_MECHANISMS", memo)
        patch.setattr(plans, "_drawn_mechanism", counted)
        run(graphplan.load(FIXTURES_FOLDER / "shaper_six_bar.toml"), folder)
    return {path.name: path.read_bytes() for path in folder.glob("*.svg")}, counts


def test_a_plan_sheets_mechanism_is_drawn_once_and_as_it_is_drawn_anew(tmp_path, monkeypatch):
    remembered, once = _drawn(tmp_path / "remembered", monkeypatch, OwnedMemo())
    anew, each_time = _drawn(tmp_path / "anew", monkeypatch, _Forgetful())
    assert once and set(once.values()) == {1}
    # Without the memo the course sheets drew each mechanism again, caption by caption: the memo has work to save.
    assert set(each_time) == set(once) and all(count > 1 for count in each_time.values())
    assert any(name.startswith("sheet_") for name in remembered)
    assert remembered.keys() == anew.keys()
    for name, written in remembered.items():
        assert written == anew[name], name


@pytest.mark.parametrize("changed", ["index", "length_scale"])
def test_another_position_or_length_scale_is_drawn_for_itself(changed, monkeypatch):
    """The position and μl are in the key: a sheet that differs in either is not given another's mechanism."""
    from dataclasses import replace

    from graphplan.render.drawings import at_length_scale, plan_sheet

    monkeypatch.setattr(plans, "_MECHANISMS", OwnedMemo())
    analysis = analyse(graphplan.load(FIXTURES_FOLDER / "shaper_six_bar.toml"))
    position = analysis.plans[0]
    sheet = plan_sheet(analysis, position.index, position.velocity, position.acceleration)
    other = replace(sheet, index=sheet.index + 1) if changed == "index" else \
        plan_sheet(at_length_scale(analysis, 2 * sheet.length_scale), position.index, position.velocity,
                   position.acceleration)
    assert plans._mechanism(other) == plans._drawn_mechanism(other) != plans._mechanism(sheet)
