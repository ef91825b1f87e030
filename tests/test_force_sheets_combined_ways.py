"""The force sheets a run draws take the fewest sheets that any combination of their ways (each sheet's cuts and its
rows apart) packs them on, where those combinations are few.

The choice changes one force sheet's way at a time and keeps a change that saves a sheet; where only two changed
together save one, it saved none: the engine's force sheets on its own A2 stood on three sheets (its run on seven),
where a cut of each together puts them, with the load diagrams, on two (bench/sheet_cuts.py).  Here every
combination is packed by the packer itself and the run's choice is held to the fewest.
"""

from __future__ import annotations

import dataclasses
import itertools
import math

import pytest

import graphplan
from graphplan import deliverables
from graphplan.analysis import analyse
from graphplan.errors import SceneError
from graphplan.render import sheet as sheet_module
from graphplan.render.drawings import with_length_scale
from graphplan.render.force_sheet_choice import MOST_COMBINATIONS, CutChoice
from graphplan.render.packing import pack


def sheets_taken(choice: CutChoice, picks) -> float:
    """The sheets the force sheets' ways ``picks`` take with the drawings after them, packed afresh."""
    try:
        return len(pack([*choice.parts_of(list(picks)), *choice.after], choice.sheet, choice.form))
    except SceneError:
        return math.inf


@pytest.fixture
def final_choice(monkeypatch):
    """The choice of ways behind the sheets a run draws: the last one :func:`sheet.course_panels` makes."""
    made: list[CutChoice] = []

    class Recorded(CutChoice):
        def __init__(self, *args, **options) -> None:
            super().__init__(*args, **options)
            made.append(self)

    monkeypatch.setattr(sheet_module, "CutChoice", Recorded)

    def run(fixture: str, locale: str) -> CutChoice:
        scene = dataclasses.replace(graphplan.load(f"fixtures/{fixture}.toml"), locale=locale)
        analysis = with_length_scale(analyse(scene))
        deliverables._course_panels(analysis)
        return made[-1]

    return run


# The engine on its A2; the Stephenson six-bar's two force sheets, five ways each, on its A1 in Russian, where its
# English and Chinese sheets take as few without the search.
@pytest.mark.parametrize(("fixture", "locale"), [("engine_slider_crank", "en"), ("stephenson_six_bar", "ru")])
def test_the_force_sheets_take_the_fewest_sheets_any_combination_of_their_ways_gives(final_choice, fixture, locale):
    choice = final_choice(fixture, locale)
    combinations = list(itertools.product(*(range(len(ways)) for ways in choice.ways_of)))
    assert 1 < len(combinations) <= MOST_COMBINATIONS
    fewest = min(sheets_taken(choice, picks) for picks in combinations)
    assert sheets_taken(choice, choice.fewest(combined=True)) == fewest
    # The case the search is for: changed one sheet at a time, the ways take a sheet more.
    assert sheets_taken(choice, choice.fewest()) == fewest + 1
