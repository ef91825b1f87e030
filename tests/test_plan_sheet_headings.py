"""Every plan sheet keeps its heading on the sheets, also where its mechanism, velocity plan and acceleration plan
stand apart on a sheet of their own (a small sheet): the heading stood in the title block only, and the top
drawing took its place against the frame's margin."""

from __future__ import annotations

import dataclasses

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render.primitives import Text, text_extent
from graphplan.render.sheet import course_sheets
from graphplan.starters import starter

# The heading of a plan sheet, as each locale words it.
HEADINGS = {"en": "Velocity and acceleration plans, position {number}",
            "ru": "Планы скоростей и ускорений, положение {number}",
            "zh": "速度与加速度多边形，位置 {number}"}


def scenes():
    quick_return = graphplan.load("fixtures/quick_return_slotted_lever.toml")
    slotted_lever = graphplan.load_text(starter("slotted-lever", "zh"))
    return {"quick-return": quick_return, "slotted-lever": slotted_lever}


@pytest.mark.parametrize("name", ["quick-return", "slotted-lever"])
@pytest.mark.parametrize("locale", ["zh", "en"])
def test_every_plan_sheet_has_its_heading_over_its_drawings_on_a2(name, locale):
    scene = dataclasses.replace(scenes()[name], locale=locale)
    analysis = analyse(scene)
    sheets = course_sheets(analysis, "A2")
    drawn = [(sheet, item) for sheet in sheets for layer in sheet.layers if layer.name != "title-block"
             for item in layer.items if isinstance(item, Text)]
    for position in analysis.plans:
        heading = HEADINGS[locale].format(number=position.number)
        found = [(sheet, text) for sheet, text in drawn if text.text == heading]
        assert found, heading
        sheet, text = found[0]
        x0, y0, x1, y1 = text_extent(text)
        # Inside the frame's margin, over every drawing of its position on that sheet and clear of them.
        fx0, _, fx1, fy1 = sheet.frame
        assert fx0 + 8.0 - 1e-6 <= x0 and x1 <= fx1 - 8.0 + 1e-6 and y1 <= fy1 - 8.0 + 1e-6
        for panel, (px0, py0, px1, py1) in sheet.panels.items():
            if panel.startswith(f"plan-{position.number}-") and not panel.endswith("-heading"):
                assert not (x0 < px1 and px0 < x1 and y0 < py1 and py0 < y1), panel
