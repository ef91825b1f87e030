"""On the kinematic sheets every caption of a plan sheet's drawing names its position and stands under its own
drawing, nearer to it than to any other drawing of the sheet.

A drawing review found position 4's plans at the foot of the slotted lever's sheet beside "Mechanism in position
11", whose caption stood 130 mm under its mechanism (a field as tall as the two plans beside it), and the Russian
crank-rocker's position 11 plans in position 5's row: the plans' captions named no position, and a reader paired
them with the mechanism beside them.
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render.drawings import with_length_scale
from graphplan.render.plans import CAPTION_GAP_MM, GAP_MM
from graphplan.render.primitives import Text, bounds
from graphplan.render.sheet import kinematics_panels, kinematics_sheet
from graphplan.starters import starter

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
CAPTION = re.compile(r"^plan-(\d+)-(mechanism|velocity|acceleration)-caption$")
# The words each drawing's caption opens with, by field.
CAPTION_KEYS = {"mechanism": "mechanism_title", "velocity": "velocity_plan_caption",
                "acceleration": "acceleration_plan_caption"}

CASES = [*((f"new:{kind}", "en", None) for kind in ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad")),
         ("new:crank-rocker", "ru", None), ("new:slotted-lever", "zh", None),
         *((path.name, "en", None) for path in sorted(FIXTURES.glob("*.toml"))),
         ("quick_return_slotted_lever.toml", "en", "A3"),
         ("quick_return_slotted_lever.toml", "ru", "A3")]


def scene_of(name: str, locale: str):
    scene = graphplan.load_text(starter(name[4:])) if name.startswith("new:") else graphplan.load(FIXTURES / name)
    return dataclasses.replace(scene, locale=locale)


def drawings_and_captions(sheet):
    """The bounds of each drawing on ``sheet`` (its layers but its caption and the plan sheet's heading), by its
    layers' common start, and each plan sheet's caption: (position, field, first line, bounds)."""
    groups: dict[str, list] = {}
    captions = []
    for layer in sheet.layers:
        if not layer.items or layer.name in ("sheet-frame", "title-block", "sheet-designation"):
            continue
        found = CAPTION.match(layer.name)
        if found:
            # Its lines as one, without the spaces they were broken at: a caption broken to its drawing's width.
            words = "".join(item.text for item in layer.items if isinstance(item, Text)).replace(" ", "")
            captions.append((int(found[1]), found[2], words, bounds([layer])))
            continue
        if layer.name.endswith("-sheet-title") or layer.name.endswith("-caption"):
            continue
        drawing = re.match(r"^(plan-\d+-(?:mechanism|velocity|acceleration))-", layer.name)
        groups.setdefault(drawing[1] if drawing else layer.name.split("-")[0], []).append(layer)
    return {name: bounds(layers) for name, layers in groups.items()}, captions


def distance(a, b) -> float:
    """The shortest distance between two boxes (0 where they meet)."""
    dx = max(a[0] - b[2], b[0] - a[2], 0.0)
    dy = max(a[1] - b[3], b[1] - a[3], 0.0)
    return (dx * dx + dy * dy) ** 0.5


@pytest.mark.parametrize(("name", "locale", "sheet_format"), CASES)
def test_each_caption_names_its_position_under_its_own_drawing(name, locale, sheet_format):
    analysis = with_length_scale(analyse(scene_of(name, locale)))
    if not analysis.plans:
        pytest.skip("no plan positions")
    chosen = sheet_format or analysis.scene.drawing.sheet
    sheets = kinematics_sheet(kinematics_panels(analysis), chosen, locale)
    text = strings(locale)
    seen = set()
    for sheet in sheets:
        drawings, captions = drawings_and_captions(sheet)
        for number, field, line, box in captions:
            seen.add((number, field))
            assert line.startswith(text[CAPTION_KEYS[field]].format(number=number).replace(" ", "")), line
            own = drawings[f"plan-{number}-{field}"]
            # Under its drawing, as far as a caption is set under a drawing, and centred within its width.
            assert own[1] - CAPTION_GAP_MM - 1.0 <= box[3] <= own[1] + 1e-6, (sheet.number, line, own, box)
            assert own[0] - 1e-6 <= (box[0] + box[2]) / 2 <= own[2] + 1e-6, (sheet.number, line)
            # Nearer to its own drawing than to any other: the drawing a reader pairs it with.
            nearest = min(drawings, key=lambda other: distance(drawings[other], box))
            assert nearest == f"plan-{number}-{field}", (sheet.number, line, nearest)
    # Every drawing of every plan position is captioned somewhere in the set.
    assert seen == {(position.number, field) for position in analysis.plans
                    for field in ("mechanism", "velocity", "acceleration")}


@pytest.mark.parametrize(("name", "locale"), [("new:slotted-lever", "zh"), ("new:crank-rocker", "ru"),
                                              ("new:crank-rocker", "en"), ("new:triad", "en")])
def test_two_positions_plan_sheets_stand_further_apart_than_the_drawings_of_one(name, locale):
    """Each position's mechanism and plans read as one block: two positions' plan sheets on one sheet are further
    apart than the drawings inside one (at 15 mm, against their 25, position 4's plans read as position 11's).

    The slotted lever in Chinese: in English its two positions no longer share a sheet, as position 11's stood
    beside position 4's only with its heading level with position 4's plans (tests/test_headed_drawings_level.py).
    """
    analysis = with_length_scale(analyse(scene_of(name, locale)))
    sheets = kinematics_sheet(kinematics_panels(analysis), analysis.scene.drawing.sheet, locale)
    pairs = 0
    for sheet in sheets:
        blocks = [rect for panel, rect in sheet.panels.items() if re.fullmatch(r"plan-\d+", panel)]
        for k, first in enumerate(blocks):
            for second in blocks[k + 1:]:
                pairs += 1
                assert distance(first, second) > GAP_MM, (sheet.number, first, second)
    assert pairs, "no sheet holds two positions' plan sheets: the test tests nothing"
