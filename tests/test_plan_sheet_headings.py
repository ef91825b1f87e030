"""Every plan sheet keeps its heading on the sheets, also where its mechanism, velocity plan and acceleration plan
stand apart on a sheet of their own (a small sheet): the heading stood in the title block only, and the top
drawing took its place against the frame's margin."""

from __future__ import annotations

import dataclasses
import itertools
import re
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render.primitives import Text, text_extent
from graphplan.render.sheet import course_sheets
from graphplan.starters import starter

ROOT = Path(__file__).resolve().parent.parent

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


def _sheet_headings(tmp_path, kind: str, sheet: str, locale: str = "en"
                    ) -> dict[int, list[list[tuple[str, float, float]]]]:
    """Each plan position's headings as the run draws them on its ``sheet`` course sheets, sheet by sheet: each
    heading's lines' (text, x, y)."""
    from xml.etree import ElementTree

    from graphplan.cli import main

    if kind.endswith(".toml"):   # a fixture, drawn in ``locale``
        scene, language = Path(kind), ["--locale", locale]
    else:
        scene, language = tmp_path / f"{kind}.toml", []
        scene.write_text(starter(kind, locale), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "sheets", "--sheet", sheet, *language]) == 0
    found: dict[int, list[list[tuple[str, float, float]]]] = {}
    for path in sorted(out.glob("sheet_*.svg"), key=lambda path: int(path.stem.split("_")[1])):
        groups = {g.get("id"): g for g in ElementTree.parse(path).getroot().iter(f"{SVG}g") if g.get("id")}
        for name, group in groups.items():
            if (number := re.fullmatch(r"plan-(\d+)-heading-sheet-title", name)) is None:
                continue
            # Over the position's own drawings, on a sheet that holds at least one of them.
            assert any(other.startswith(f"plan-{number.group(1)}-") and other != name for other in groups), path
            found.setdefault(int(number.group(1)), []).append(
                [("".join(t.itertext()), float(t.get("x")), float(t.get("y"))) for t in group.iter(f"{SVG}text")])
    return found


def _read(lines: list[tuple[str, float, float]], locale: str = "en") -> str:
    """A heading's lines read as one, flush left and one under another."""
    assert all(x == pytest.approx(lines[0][1]) for _, x, _ in lines)
    assert all(b[2] > a[2] for a, b in itertools.pairwise(lines))
    return ("" if locale == "zh" else " ").join(text for text, _, _ in lines)


def test_plan_sheets_too_tall_for_one_a4_keep_their_heading_where_a_page_has_room(tmp_path):
    """On A4 the slider-crank's plan sheets stand on two sheets a position (the mechanism, then both plans, or the
    mechanism with the velocity plan, then the acceleration plan).  A page whose drawings fill the sheet's height
    leaves no room for the heading; the packing took the heading all or nothing, so no plan sheet had one, the
    mechanism of position 2 alone on half an empty sheet under none.  Now each heading stands over the first of its
    pages that holds it, and "continued" over those after it that have room."""
    headings = _sheet_headings(tmp_path, "slider-crank", "A4")
    positions = [plan.number for plan in analyse(graphplan.load_text(starter("slider-crank", "en"))).plans]
    assert sorted(headings) == sorted(positions)
    for number, pages in headings.items():
        title = HEADINGS["en"].format(number=number)
        assert [_read(lines) for lines in pages] == [title] + [f"{title} (continued)"] * (len(pages) - 1)


def test_a_heading_wider_than_the_sheet_is_broken_at_its_phrases(tmp_path):
    """On an A4, "Velocity and acceleration plans, position 11", lettered 7 mm high and bold, is 251.5 mm wide: wider
    than an A4 across holds between its margins (251 mm; position 5's fitted), and even broken after its comma
    (184 mm) than an upright one.  Each of the crank-rocker's plan pages (each drawing as tall as an upright A4) had
    none: now the heading is broken at its phrases to the room the page leaves, its lines flush left."""
    headings = _sheet_headings(tmp_path, "crank-rocker", "A4")
    for number in (5, 11):
        first, *after = headings[number]
        title = HEADINGS["en"].format(number=number)
        assert len(first) >= 2 and _read(first) == title
        assert all(_read(lines) == f"{title} (continued)" for lines in after)


def test_an_eskd_a4s_heading_stands_under_its_corner_box(tmp_path):
    """An upright ESKD A4 has the box of the document's designation in its top left corner (ГОСТ 2.104's графа 26,
    70 × 14 mm, its foot 19 mm from the sheet's top).  The Russian heading, broken to fit beside the drawings' left
    edge, ran into it there and was too wide to stand right of it: no Russian plan sheet on A4 had its heading.  It
    stands under the box now, every line of it."""
    headings = _sheet_headings(tmp_path, "slider-crank", "A4", "ru")
    positions = [plan.number for plan in analyse(graphplan.load_text(starter("slider-crank", "ru"))).plans]
    assert sorted(headings) == sorted(positions)
    for number, pages in headings.items():
        title = HEADINGS["ru"].format(number=number)
        assert _read(pages[0], "ru") == title
        # Each line's letters (7 mm capitals over the baseline) below the box's foot.
        assert all(y - 7.0 > 19.0 for lines in pages for _, _, y in lines)


def test_a_heading_stands_over_the_plans_beside_a_mechanism_as_tall_as_the_sheet(tmp_path):
    """The scotch yoke's plunger is drawn down the whole height of a Russian A3, under its ESKD corner box: no
    heading stood over it nor over the page's drawings lowered, and the plan sheet of position 4 had none, with room
    over its velocity and acceleration plans right of the mechanism.  The heading stands there now, the highest
    thing on the sheet, clear of the mechanism's column."""
    from xml.etree import ElementTree

    headings = _sheet_headings(tmp_path, str(ROOT / "fixtures" / "scotch_yoke.toml"), "A3", "ru")
    assert _read(headings[4][0], "ru") == HEADINGS["ru"].format(number=4)
    for path in (tmp_path / "out").glob("sheet_*.svg"):
        groups = {g.get("id"): g for g in ElementTree.parse(path).getroot().iter(f"{SVG}g") if g.get("id")}
        if "plan-4-heading-sheet-title" not in groups:
            continue
        heading = groups["plan-4-heading-sheet-title"]
        lines = [(float(t.get("x")), float(t.get("y"))) for t in heading.iter(f"{SVG}text")]
        # SVG's y runs down: the heading's first baseline above every text of the position's drawings.
        drawn = [float(t.get("y")) for name, group in groups.items() if name.startswith("plan-4-")
                 and not name.startswith("plan-4-heading") for t in group.iter(f"{SVG}text")]
        assert lines[0][1] < min(drawn)
        # Starting right of the mechanism's letters (P, S4, O, A, B: its column down the sheet's left side).
        letters = [float(t.get("x")) for t in groups["plan-4-mechanism-labels"].iter(f"{SVG}text")]
        assert lines[0][0] > max(letters)


BOXER = """
[scene]
title = "Opposed twin"
locale = "ru"
[frame]
link = 1
points = { O = [0.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.04
rpm = 3000.0
[points]
C = { link = 2, from = "O", toward = "A", at = -0.04 }
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.14
guide = { through = "O", angle = 0.0 }
assembly = "forward"
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["C", "D"]
length = 0.14
guide = { through = "O", angle = 180.0 }
assembly = "forward"
[positions]
count = 12
start = "extreme"
working = { link = 4, sense = "backward" }
plans = [3, 8]
[drawing]
length_scale = 0.0025
sheet = "A4"
"""


def test_only_the_first_sheet_of_a_plan_sheet_has_its_plain_title_the_others_are_continued():
    """A boxer twin's plans of position 3 on a Russian A4 began bare (its mechanism and velocity plan fill the first
    sheet) and the sheet after it, the acceleration plan's, was headed with the plain title, so that it read as
    where position 3 began; it is headed "continued"."""
    from graphplan.render.sheet import kinematics_panels, kinematics_sheet

    analysis = analyse(graphplan.load_text(BOXER))
    sheets = kinematics_sheet(kinematics_panels(analysis), "A4", "ru")
    for position in analysis.plans:
        own = [sheet for sheet in sheets if any(re.fullmatch(rf"plan-{position.number}(-.+)?", name)
                                                for name in sheet.panels)]
        assert len(own) >= 2
        # Each sheet after the first that carries the heading carries it "continued" (outside the title block).
        for sheet in own[1:]:
            written = " ".join(item.text for layer in sheet.layers if layer.name != "title-block"
                               for item in layer.items if isinstance(item, Text))
            assert "(продолжение)" in written, (position.number, sheet.number, written)


def test_a_continued_heading_is_broken_at_its_phrase_where_that_fits(tmp_path):
    """The Russian slotted lever's plans of position 11 on an A4 (poles of 80 and 60 mm) go on onto a sheet across
    with the velocity plan alone.  Its heading "continued" is too wide for one line there and too wide broken to the
    title's width, so it was broken to three fifths of it: four lines, where two, broken after the comma as the title
    itself is broken, stood right of the corner box."""
    text = starter("slotted-lever", "ru")
    for key, value in (("velocity_pole", 80.0), ("acceleration_pole", 60.0)):
        text, count = re.subn(rf"(?m)^{key}\s*=.*$", f"{key} = {value}", text)
        assert count == 1, key
    scene = tmp_path / "slotted_lever.toml"
    scene.write_text(text, encoding="utf-8")
    title = HEADINGS["ru"].format(number=11)
    continued = [lines for lines in _sheet_headings(tmp_path, str(scene), "A4", "ru")[11]
                 if _read(lines, "ru") == f"{title} (продолжение)"]
    assert continued
    assert all([line for line, _, _ in lines] == ["Планы скоростей и ускорений,", "положение 11 (продолжение)"]
               for lines in continued)


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_positions_sheets_read_in_the_order_of_its_drawings(locale):
    """The slotted lever's plans of position 11 take two A3 sheets.  Packed tallest first, the acceleration plan
    alone on an upright sheet came before the sheet of the mechanism and the velocity plan, and the heading went on
    the acceleration plan's sheet.  The sheets now read in the order of the first drawing each holds."""
    scene = dataclasses.replace(scenes()["slotted-lever"], locale=locale)
    analysis = analyse(scene)
    sheets = course_sheets(analysis, "A3")
    reading = ("mechanism", "velocity", "acceleration")
    split = 0
    for position in analysis.plans:
        firsts = []
        for sheet in sheets:
            held = [reading.index(kind.group(1)) for name in sheet.panels
                    if (kind := re.fullmatch(rf"plan-{position.number}-({'|'.join(reading)})", name))]
            if held:
                firsts.append(min(held))
        if len(firsts) > 1:
            split += 1
            assert firsts == sorted(firsts) and firsts[0] == 0, (position.number, firsts)
    assert split, "no position's plans stand on more than one sheet"
