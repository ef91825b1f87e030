"""An A3 stands upright for a drawing no A3 across holds, as GOST 2.301, GB/T 14689 and ISO 5457 allow.

The slotted-lever starter on A3 was refused: its acceleration plan of position 11, 152 × 316 mm at the scene's
pole distance, is taller than an A3 across leaves clear of its title block (221 mm), though an A3 upright has
339 mm and more.  A set that fits across is laid out across as before.
"""

from __future__ import annotations

import dataclasses

import pytest
from test_small_sheets import box

import graphplan
from graphplan.analysis import analyse
from graphplan.errors import SceneError
from graphplan.render.formats import page_geometry
from graphplan.render.primitives import Polyline, Text
from graphplan.render.sheet import course_sheets, kinematics_sheet
from graphplan.render.title_block import CORNER_SIZES, SIZES, form_of
from graphplan.starters import starter

UPRIGHT_A3 = (297.0, 420.0)


def slotted_lever_on_a3(locale: str):
    scene = graphplan.load_text(starter("slotted-lever"))
    return dataclasses.replace(scene, locale=locale, drawing=dataclasses.replace(scene.drawing, sheet="A3"))


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_slotted_lever_s_tall_acceleration_plan_stands_on_an_upright_a3(locale):
    sheets = course_sheets(analyse(slotted_lever_on_a3(locale)))
    holding = [sheet for sheet in sheets if any(name.endswith("acceleration") and name.startswith("plan-11")
                                                   for name in sheet.panels)]
    assert holding and all(sheet.size == UPRIGHT_A3 for sheet in holding)
    assert {sheet.size for sheet in sheets} == {UPRIGHT_A3, (420.0, 297.0)}
    form = form_of(locale)
    for sheet in holding:
        x0, y0, x1, y1 = sheet.frame
        # The title block in the frame's lower right corner, as on every sheet.
        assert sheet.title_block == (x1 - SIZES[form][0], y0, x1, y0 + SIZES[form][1])
        # Every drawing stays inside the frame and clear of the title block.
        for bx0, by0, bx1, by1 in sheet.panels.values():
            assert x0 < bx0 and bx1 < x1 and y0 < by0 and by1 < y1
            tx0, _, _, ty1 = sheet.title_block
            assert bx1 < tx0 or by0 > ty1


def test_graph_26_runs_down_the_left_side_of_an_upright_eskd_a3_turned_through_90_degrees():
    """GOST 2.104: along the top, turned through 180°, on an A4 and a sheet with its title block along its long
    side; down the left side, turned through 90°, on a bigger sheet stood upright."""
    scene = slotted_lever_on_a3("ru")
    scene = dataclasses.replace(scene, project=dataclasses.replace(scene.project, designation="ТММ.КП.07.00.00"))
    sheets = course_sheets(analyse(scene))
    upright = next(sheet for sheet in sheets if sheet.size == UPRIGHT_A3)
    across = next(sheet for sheet in sheets if sheet.size != UPRIGHT_A3)
    long_side, short_side = CORNER_SIZES["eskd"]
    for sheet, (width, height), rotation in ((upright, (short_side, long_side), 90.0),
                                            (across, (long_side, short_side), 180.0)):
        x0, _, _, y1 = sheet.frame
        (corner,) = [layer for layer in sheet.layers if layer.name == "sheet-designation"]
        lines = [item for item in corner.items if isinstance(item, Polyline)]
        assert lines[0].points == ((x0, y1 - height), (x0 + width, y1 - height), (x0 + width, y1))
        (text,) = [item for item in corner.items if isinstance(item, Text)]
        assert text.text == "ТММ.КП.07.00.00" and text.rotation == rotation
        assert x0 < text.at[0] < x0 + width and y1 - height < text.at[1] < y1
    assert page_geometry("A3", "eskd", portrait=True).corner == (
        upright.frame[0], upright.frame[3] - long_side, upright.frame[0] + short_side, upright.frame[3])


def test_an_a3_set_that_fits_across_stays_across():
    across_room = max(page_geometry("A3", "iso").rooms())
    sheets = kinematics_sheet([box(across_room[0] - 10, across_room[1] - 10), box(100, 100)], "A3", "en")
    assert all(sheet.size == (420.0, 297.0) for sheet in sheets)


def test_a_drawing_no_a3_holds_either_way_names_the_upright_room_too():
    upright_rooms = page_geometry("A3", "eskd", portrait=True).rooms()
    with pytest.raises(SceneError) as error:
        kinematics_sheet([box(300, 400)], "A3", "ru")
    tallest = max(upright_rooms, key=lambda room: room[1] if min(room) >= 10 else 0)
    assert f"{tallest[0]:.0f} × {tallest[1]:.0f}" in str(error.value)
