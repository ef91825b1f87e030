"""A force sheet's part whose equations under its drawing make it too tall for the room a sheet has left stands with
them beside the drawing, to its right, where that room is wide enough: on an A3, whose 216 mm above the title
block a group cut free or the lever with its equations under it misses by a few lines.

The saving is measured against the same parts packed with their equations under them only; the captions set
beside are checked on the sheets as drawn: to the right of their own drawing, clear of every other drawing, inside
the frame and off the title block.
"""

import dataclasses
import functools

import pytest
from scene_texts import journal_friction
from test_sheets import overlap

import graphplan
from graphplan.analysis import analyse
from graphplan.render.packing import pack
from graphplan.render.primitives import Text, bounds
from graphplan.render.sheet import course_sheets, force_panels
from graphplan.render.title_block import form_of
from graphplan.scene import loads
from graphplan.starters import starter

# The crank-rocker the starter writes, its four journals with friction (as the fresh-user friction scenes give them).
FRICTION = journal_friction({"O": 0.02, "A": 0.015, "B": 0.012, "C": 0.02})
CRANK_ROCKER_WITH_FRICTION = "crank-rocker with friction"
# Where the fixtures' force sheets have parts that the room left on a sheet holds only with their equations beside.
SAVING = [("engine_slider_crank", "A3"), ("quick_return_slotted_lever", "A3"), ("quick_return_slotted_lever", "A2")]


@functools.cache
def analysis_of(name: str):
    if name == CRANK_ROCKER_WITH_FRICTION:
        return analyse(loads(starter("crank-rocker") + FRICTION))
    return analyse(graphplan.load(f"fixtures/{name}.toml"))


@functools.cache
def sheets_of(name: str, sheet: str):
    return course_sheets(analysis_of(name), sheet)


def beside(layer) -> bool:
    """Whether ``layer`` is a caption set beside its drawing: its lines begin at its left, not about a middle."""
    return layer.name.endswith("-caption") and any(isinstance(item, Text) and item.anchor == "start"
                                                   for item in layer.items)


def forces_with_beside(panel):
    return any(beside(layer) for layer in panel.layers)


def under_only(panel):
    """``panel`` without the ways that set its equations beside its drawings: the parts as they stood before."""
    return dataclasses.replace(panel, alternatives=tuple(way for way in panel.alternatives
                                                          if not forces_with_beside(way)))


@pytest.mark.parametrize(("name", "sheet"), SAVING)
def test_equations_beside_a_drawing_save_a_sheet_where_the_room_left_is_too_low_for_them_under(name, sheet):
    analysis = analysis_of(name)
    parts = force_panels(analysis, sheet)
    form = form_of(analysis.scene.locale)
    assert any(forces_with_beside(way) for part in parts for way in part.alternatives)
    assert not any(forces_with_beside(part) for part in parts), "a part's first way keeps its equations under it"
    assert len(pack(parts, sheet, form)) < len(pack([under_only(part) for part in parts], sheet, form))


def test_the_crank_rocker_with_friction_on_a3_puts_several_force_parts_on_a_sheet():
    analysis = analysis_of(CRANK_ROCKER_WITH_FRICTION)
    parts = force_panels(analysis, "A3")
    force_sheets = [sheet for sheet in sheets_of(CRANK_ROCKER_WITH_FRICTION, "A3")
                    if any(name.startswith("forces") for name in sheet.panels)]
    # A part a sheet: as many sheets as parts.  Two of the four force sheets' parts share a sheet or more.
    assert len(force_sheets) <= len(parts) - 2
    assert any(sum(name.startswith("forces") for name in sheet.panels) > 1 for sheet in force_sheets)


@pytest.mark.parametrize(("name", "sheet"), [*SAVING, (CRANK_ROCKER_WITH_FRICTION, "A3")])
def test_equations_beside_a_drawing_stand_to_its_right_clear_of_every_drawing_the_frame_and_the_title_block(
        name, sheet):
    found = 0
    for drawn in sheets_of(name, sheet):
        captions = [layer for layer in drawn.layers if beside(layer)]
        for caption in captions:
            if not caption.name.startswith("forces"):
                continue  # the plan of positions' and the diagrams' captions stand from the left as drawn before
            found += 1
            box = bounds([caption])
            drawing = caption.name.removesuffix("-caption")
            own = [layer for layer in drawn.layers if layer.name.startswith(drawing + "-") and layer is not caption]
            assert own, caption.name
            assert box[0] >= bounds(own)[2], f"{caption.name} stands over its drawing"
            others = [layer for layer in drawn.layers if layer is not caption and layer.items
                      and layer.name.startswith(("forces", "load-diagrams"))]
            crossed = [layer.name for layer in others if overlap(box, bounds([layer]))]
            assert not crossed, f"{caption.name} on sheet {drawn.number} crosses {crossed}"
            frame, block = drawn.frame, drawn.title_block
            assert frame[0] <= box[0] and box[2] <= frame[2] and frame[1] <= box[1] and box[3] <= frame[3]
            assert not overlap(box, block), f"{caption.name} on sheet {drawn.number} runs into the title block"
            sizes = {item.size for item in caption.items if isinstance(item, Text)}
            assert min(sizes) >= 3.5, "lettering no smaller than GOST 2.304's 3.5 mm"
    assert found, f"no equations stand beside a drawing on {name}'s {sheet} sheets"
