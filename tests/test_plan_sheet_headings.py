"""Every plan sheet keeps its heading on the sheets, also where its mechanism, velocity plan and acceleration plan
stand apart on a sheet of their own (a small sheet): the heading stood in the title block only, and the top
drawing took its place against the frame's margin."""

from __future__ import annotations

import dataclasses
import re

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


SVG = "{http://www.w3.org/2000/svg}"


def _sheet_headings(tmp_path, kind: str, sheet: str) -> dict[int, list[tuple[str, float, float]]]:
    """Each plan position's heading as the run draws it on its ``sheet`` course sheets: its lines' (text, x, y)."""
    from xml.etree import ElementTree

    from graphplan.cli import main

    scene = tmp_path / f"{kind}.toml"
    scene.write_text(starter(kind, "en"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "sheets", "--sheet", sheet]) == 0
    found: dict[int, list[tuple[str, float, float]]] = {}
    for path in sorted(out.glob("sheet_*.svg")):
        groups = {g.get("id"): g for g in ElementTree.parse(path).getroot().iter(f"{SVG}g") if g.get("id")}
        for name, group in groups.items():
            if (number := re.fullmatch(r"plan-(\d+)-heading-sheet-title", name)) is None:
                continue
            # Over the position's own drawings, on a sheet that holds at least one of them.
            assert any(other.startswith(f"plan-{number.group(1)}-") and other != name for other in groups), path
            found[int(number.group(1))] = [("".join(t.itertext()), float(t.get("x")), float(t.get("y")))
                                           for t in group.iter(f"{SVG}text")]
    return found


def test_plan_sheets_too_tall_for_one_a4_keep_their_heading_where_a_page_has_room(tmp_path):
    """On A4 the slider-crank's plan sheets stand on two sheets a position (the mechanism, then both plans, or the
    mechanism with the velocity plan, then the acceleration plan).  A page whose drawings fill the sheet's height
    leaves no room for the heading; the packing took the heading all or nothing, so no plan sheet had one, the
    mechanism of position 2 alone on half an empty sheet under none.  Now each heading stands over the first of its
    pages that holds it."""
    headings = _sheet_headings(tmp_path, "slider-crank", "A4")
    positions = [plan.number for plan in analyse(graphplan.load_text(starter("slider-crank", "en"))).plans]
    assert sorted(headings) == sorted(positions)
    for number, lines in headings.items():
        assert " ".join(text for text, _, _ in lines) == HEADINGS["en"].format(number=number)


def test_a_heading_wider_than_the_sheet_is_broken_at_its_phrase(tmp_path):
    """On an A4 across, 251 mm clear between the frame's margins, "Velocity and acceleration plans, position 11",
    lettered 7 mm high and bold, is 251.5 mm wide (position 5's fitted): broken after its comma, its two lines flush
    left, one over the other, it stands over the acceleration plan of position 11, which leaves room for it."""
    headings = _sheet_headings(tmp_path, "crank-rocker", "A4")
    lines = headings[11]
    assert [text for text, _, _ in lines] == ["Velocity and acceleration plans,", "position 11"]
    (_, x0, y0), (_, x1, y1) = lines
    assert x0 == pytest.approx(x1) and y1 > y0
