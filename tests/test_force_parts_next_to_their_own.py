"""A part of a force sheet that stands headless on a course sheet stands next to the part it goes on from wherever
another position's force sheet shares the sheet: under it, or beside it level with its top.

On the quick-return mechanism's A1 sheet 3, position 11's driving link stood at the foot of position 4's column and
its lever under the load diagrams, neither under a heading of its own: a student read them as position 4's, the Mb
they give (−14.35 N·m against position 4's 36.58) the only clue.  The crank-rocker starter's position 11 went on
beside position 5's lever.  A part that finds no room next to the one before it now stands under its own heading,
"Force analysis, position 11 (continued)", or on a sheet of its own.

The sheets are read as drawn: each placed drawing's bounds from the layers that carry its name, its heading the
layer ``forces-11-2-sheet-title``.
"""

from __future__ import annotations

import functools
import re

import pytest

import graphplan
from graphplan import deliverables
from graphplan.analysis import analyse
from graphplan.render.packing import GAP_MM
from graphplan.render.primitives import bounds
from graphplan.starters import starter

# A layer of a force sheet's part: the part's name (forces-11, forces-11-2, forces-friction-5-3), then the layer's.
PART_LAYER = re.compile(r"^(forces(?:-friction)?-\d+(?:-\d+)?)-(?!\d)")
# A part's name: its position's whole (forces-11) and its number after the first (2, 3).
PART = re.compile(r"^(forces(?:-friction)?-\d+)(?:-(\d+))?$")
# Two drawings' sides level with each other, to the round-off of the sheet's numbers (mm).
LEVEL_MM = 1e-3
SCENES = {
    "quick_return_slotted_lever": lambda: graphplan.load("fixtures/quick_return_slotted_lever.toml"),
    "crank-rocker": lambda: graphplan.load_text(starter("crank-rocker")),
    "slotted-lever": lambda: graphplan.load_text(starter("slotted-lever")),
}


@functools.cache
def sheets_of(name: str) -> list[tuple[str, dict[str, tuple], set[str]]]:
    """The course sheets a run of the scene ``name`` draws: each sheet's name, its force sheets' parts with their
    bounds (the sheet's y up, as the packing lays out), and the parts that stand under a heading of their own."""
    scene = SCENES[name]()
    found = []
    for drawing in deliverables.drawings(scene, analyse(scene), ("sheets",)):
        layers: dict[str, list] = {}
        for layer in drawing.layers:
            if (part := PART_LAYER.match(layer.name)) is not None:
                layers.setdefault(part[1], []).append(layer)
        headed = {name for name, own in layers.items() if any(layer.name == f"{name}-sheet-title" for layer in own)}
        found.append((drawing.stem, {part: bounds(own) for part, own in layers.items()}, headed))
    return found


@pytest.fixture(params=list(SCENES))
def sheets(request) -> list[tuple[str, dict[str, tuple], set[str]]]:
    return sheets_of(request.param)


def next_to(rect, earlier) -> bool:
    """Whether a drawing at ``rect`` goes on from one at ``earlier``: under it across some of its width, no room for a
    drawing between; or beside it, level with its top."""
    near = 2.0 * GAP_MM
    under = rect[0] < earlier[2] and earlier[0] < rect[2] and earlier[1] - near <= rect[3] <= earlier[1] + LEVEL_MM
    beside = earlier[2] - LEVEL_MM <= rect[0] <= earlier[2] + near and abs(rect[3] - earlier[3]) <= LEVEL_MM
    return under or beside


def _before(name: str) -> str:
    part = PART.match(name)
    return part[1] if part[2] == "2" else f"{part[1]}-{int(part[2]) - 1}"


def _headless_parts(parts: dict[str, tuple], headed: set[str]) -> list[str]:
    return [name for name in parts if PART.match(name)[2] is not None and name not in headed]


def strays(sheet: str, parts: dict[str, tuple], headed: set[str]) -> list[str]:
    """The headless parts on a sheet away from the part they go on from, where another position's force sheet is on
    it too."""
    if len({PART.match(name)[1] for name in parts}) < 2:
        return []
    return [f"{sheet}: {name} stands headless away from {_before(name)}" for name in _headless_parts(parts, headed)
            if _before(name) not in parts or not next_to(parts[name], parts[_before(name)])]


def test_a_headless_part_stands_next_to_the_part_it_goes_on_from(sheets):
    assert [stray for sheet in sheets for stray in strays(*sheet)] == []


def test_the_crank_rocker_shares_a_sheet_between_two_positions_with_a_part_under_its_own_heading():
    """The check is not idle: the starter's second sheet holds positions 5 and 11, and position 11's driving link,
    with no room next to its group, goes on under "Force analysis, position 11 (continued)"."""
    (second,) = [(parts, headed) for sheet, parts, headed in sheets_of("crank-rocker") if sheet == "sheet_2"]
    assert {PART.match(name)[1] for name in second[0]} == {"forces-5", "forces-11"}
    assert {"forces-5", "forces-11", "forces-11-2"} <= second[1]


def test_a_part_moved_away_from_the_one_before_it_is_found():
    """The check itself: position 5's headless driving link, next to its group on the crank-rocker's second sheet,
    moved to the far side of the group."""
    (parts, headed), = [(parts, headed) for sheet, parts, headed in sheets_of("crank-rocker") if sheet == "sheet_2"]
    assert "forces-5-2" in _headless_parts(parts, headed)
    assert strays("sheet_2", parts, headed) == []
    earlier, width = parts["forces-5"], parts["forces-5-2"][2] - parts["forces-5-2"][0]
    moved = dict(parts, **{"forces-5-2": (earlier[0] - 3 * GAP_MM - width, earlier[1] - 200.0,
                                           earlier[0] - 3 * GAP_MM, earlier[1] - 150.0)})
    # The lever under it goes with it, away from its group too.
    assert strays("sheet_2", moved, headed)[:1] == ["sheet_2: forces-5-2 stands headless away from forces-5"]
