"""A plan's caption on the course sheets names its plan and position on one line wherever that line fits the room
round it on the sheet, and on two only where it does not.

The slotted lever's A1 set "Acceleration plan, / position 4" on two lines with nothing beside it for 200 mm: the
name was broken to the room the drawing gave it before the drawings were placed, and never joined again once the
room round it was known.

The room is measured here apart from the sheet's own check: every other ink of the sheet sampled as points along its
lines (a text and a pin as their boxes), against the caption's lines as the sheet's text-width function measures
them, grown by the clearance a caption set on one line keeps; and the bounds of the other drawings placed, which a
caption's drawing's bounds widened by it must not meet.
"""

from __future__ import annotations

import dataclasses
import itertools
import re
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render.drawings import with_length_scale
from graphplan.render.formats import PADDING_MM
from graphplan.render.plans import CAPTION_SIZE
from graphplan.render.primitives import Arrow, Circle, Polyline, Text, text_extent, text_width
from graphplan.render.sheet import course_sheets
from graphplan.starters import starter

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
CAPTION = re.compile(r"^plan-(\d+)-(velocity|acceleration)-caption$")
CAPTION_KEYS = {"velocity": "velocity_plan_caption", "acceleration": "acceleration_plan_caption"}
# Beside the caption two cap heights, above and below one: what a caption set on one line keeps from other ink.
CLEARANCE = (2 * CAPTION_SIZE, CAPTION_SIZE)
# Points along a line this far apart (mm): finer than any caption's box is tall.
STEP_MM = 0.25

CASES = [*((f"new:{kind}", "en", None) for kind in ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad")),
         ("new:crank-rocker", "ru", None), ("new:crank-rocker", "zh", None), ("new:slotted-lever", "ru", "A3"),
         ("quick_return_slotted_lever.toml", "en", "A2"), ("stephenson_six_bar.toml", "en", None),
         ("triad_class_iii.toml", "ru", None), ("ratchet_crank_rocker.toml", "ru", None)]


def scene_of(name: str, locale: str):
    scene = graphplan.load_text(starter(name[4:])) if name.startswith("new:") else graphplan.load(FIXTURES / name)
    return dataclasses.replace(scene, locale=locale)


def ink_of(layers) -> tuple[np.ndarray, np.ndarray]:
    """Every item of ``layers`` as points along its lines, and as boxes (a text's, a circle's)."""
    points, boxes = [np.empty((0, 2))], [np.empty((0, 4))]
    for layer in layers:
        for item in layer.items:
            if isinstance(item, Text):
                boxes.append(np.array([text_extent(item)]))
            elif isinstance(item, Circle):
                (x, y), r = item.centre, item.radius
                boxes.append(np.array([[x - r, y - r, x + r, y + r]]))
            else:
                ends = (item.start, item.end) if isinstance(item, Arrow) else item.points
                if isinstance(item, Polyline) and item.closed:
                    ends = (*ends, ends[0])
                ends = np.asarray(ends, dtype=float)
                points.append(ends)
                for a, b in itertools.pairwise(ends):
                    count = int(np.hypot(*(b - a)) / STEP_MM) + 1
                    points.append(a + np.linspace(0.0, 1.0, count + 1)[:, None] * (b - a))
    return np.concatenate(points), np.concatenate(boxes)


def meets(box, points: np.ndarray, boxes: np.ndarray) -> bool:
    x0, y0, x1, y1 = box
    inside = (points[:, 0] > x0) & (points[:, 0] < x1) & (points[:, 1] > y0) & (points[:, 1] < y1)
    crossing = (boxes[:, 0] < x1) & (boxes[:, 2] > x0) & (boxes[:, 1] < y1) & (boxes[:, 3] > y0)
    return bool(inside.any() or crossing.any())


def fits(texts, sheet, own, drawings, points, boxes, clearance) -> bool:
    """Whether ``texts`` stand in the sheet's field (its frame less the padding kept from it), off the title block,
    widen the bounds of their drawing ``own`` as placed into none of the other ``drawings``', and keep ``clearance``
    (across, up) from every other ink."""
    fx0, fy0, fx1, fy1 = sheet.frame
    bx0, by0, bx1, by1 = sheet.title_block
    extents = np.array([own, *(text_extent(item) for item in texts)])
    wx0, wy0 = extents[:, :2].min(axis=0)
    wx1, wy1 = extents[:, 2:].max(axis=0)
    for x0, y0, x1, y1 in drawings:
        if wx0 < x1 and x0 < wx1 and wy0 < y1 and y0 < wy1:
            return False
    for item in texts:
        x0, y0, x1, y1 = text_extent(item)
        if x0 < fx0 + PADDING_MM or y0 < fy0 + PADDING_MM or x1 > fx1 - PADDING_MM or y1 > fy1 - PADDING_MM:
            return False
        if x0 < bx1 + PADDING_MM and x1 > bx0 - PADDING_MM and y0 < by1 + PADDING_MM and y1 > by0 - PADDING_MM:
            return False
        across, up = clearance
        if meets((x0 - across, y0 - up, x1 + across, y1 + up), points, boxes):
            return False
    return True


def captions_of(name, locale, sheet_format):
    """Each plan caption of the kinematics sheets: (sheet, its texts, the name on one line, the bounds of its drawing
    as the sheet gives them, those of the other drawings placed, the other ink)."""
    analysis = with_length_scale(analyse(scene_of(name, locale)))
    text = strings(locale)
    found = []
    for sheet in course_sheets(analysis, sheet_format):
        captions = [(k, layer) for k, layer in enumerate(sheet.layers) if CAPTION.match(layer.name)]
        for k, layer in captions:
            number, field = CAPTION.match(layer.name).groups()
            others = [other for j, other in enumerate(sheet.layers)
                      if j != k and other.name not in ("sheet-frame", "title-block")]
            own = max((panel for panel in sheet.panels if layer.name.startswith(panel + "-")), key=len)
            drawings = [rect for panel, rect in sheet.panels.items() if panel != own]
            found.append((sheet, layer.items, text[CAPTION_KEYS[field]].format(number=number),
                          sheet.panels[own], drawings, ink_of(others)))
    return found


@pytest.mark.parametrize(("name", "locale", "sheet_format"), CASES)
def test_a_plan_name_on_two_lines_only_where_one_would_not_fit(name, locale, sheet_format):
    captions = captions_of(name, locale, sheet_format)
    assert captions, "no plan captions on the sheets: the test tests nothing"
    for sheet, texts, one_line, own, drawings, (points, boxes) in captions:
        named = [item for item in texts if item.weight == "bold"]
        # The name as set: its lines are the locale's words for it, broken or not.
        assert "".join(item.text for item in named).replace(" ", "") == one_line.replace(" ", "")
        if len(named) == 1:
            # On one line: it meets no other ink, stands in the field off the title block, and widens its
            # drawing's bounds into no other's.
            assert fits(texts, sheet, own, drawings, points, boxes, (0.0, 0.0)), (sheet.number, one_line)
            continue
        # On two lines: the name on one line, its scale under it a line higher, would leave the field or come
        # nearer other ink than the clearance.
        assert text_width(one_line, named[0].size, "bold") > max(
            text_width(item.text, item.size, "bold") for item in named)
        rise = texts[0].at[1] - texts[1].at[1]
        joined = [dataclasses.replace(texts[0], text=one_line),
                  *(dataclasses.replace(item, at=(item.at[0], item.at[1] + (len(named) - 1) * rise))
                    for item in texts[len(named):])]
        assert not fits(joined, sheet, own, drawings, points, boxes, CLEARANCE), (sheet.number, one_line)


def test_the_slotted_lever_names_position_4s_acceleration_plan_on_one_line():
    """The sheet the fault was seen on: 200 mm of room beside a name broken over two lines."""
    captions = captions_of("new:slotted-lever", "en", None)
    named = {one_line: [item.text for item in texts if item.weight == "bold"] for _, texts, one_line, _, _, _ in captions}
    assert named["Acceleration plan, position 4"] == ["Acceleration plan, position 4"]
