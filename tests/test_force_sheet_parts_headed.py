"""Every sheet that holds a part of a force sheet says whose it is in a heading over its drawings.

The starter's crank-rocker with friction in its four turning pairs, in
Russian on A3: the force sheet with friction of position 5 stood in parts,
its group II(3,4) and its lever each on a sheet with no heading at all (the
title block alone said whose they were), the group's polygon beside it
under no heading either, though each stands under its heading on one A3
with its equations beside its drawing, as the same sheet's group of
position 11 does.
"""

from __future__ import annotations

import functools
import re

import pytest
from scene_texts import crank_rocker_working_its_quicker_stroke

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render.primitives import Text, text_extent
from graphplan.render.sheet import course_sheets
from graphplan.starters import starter

# A journal in every turning pair of the four-bar: the crank's O and A, the coupler's B, the rocker's C.
FRICTION = "".join(f'\n[[friction]]\njoint  = "{joint}"\nf      = 0.1\nradius = 0.02\n' for joint in "OABC")


@functools.cache
def sheets_of(locale: str, sheet: str):
    # The layouts the tests below were written for: the starter worked in its quicker stroke.
    text = crank_rocker_working_its_quicker_stroke(locale)
    scene = graphplan.load_text(text.replace("\n[positions]", FRICTION + "\n[positions]"))
    assert len(scene.friction) == 4
    return course_sheets(analyse(scene), sheet)


def force_sheet_of(layer_name: str) -> str | None:
    """The force sheet a layer is drawn for: ``forces-friction-5`` of ``forces-friction-5-2-polygon-II-3-4-lines``."""
    found = re.match(r"(forces(?:-friction)?-\d+)-", layer_name)
    return found.group(1) if found else None


@pytest.mark.parametrize("locale", ["ru", "en"])
def test_every_sheet_with_a_part_of_a_force_sheet_has_its_heading(locale):
    seen = force_sheets_headed(sheets_of(locale, "A3"), locale)
    assert seen == {"forces-5", "forces-friction-5", "forces-11", "forces-friction-11"}


@pytest.mark.parametrize("locale", ["zh", "en", "ru"])
def test_a_part_that_stands_whole_on_an_a4_across_is_not_cut_up_bare_to_stand_upright(locale):
    """The slider-crank starter on A4: every sheet upright stood its force sheets' driving links apart from their
    polygons, on a sheet of their own with no heading (the title block alone said whose they were), though each
    stands whole under its heading "continued" on an A4 across: in Chinese on as many sheets; in English the sheets
    upright where the drawing that opens them stands so, across where it does not, take one fewer than the other way
    round, across first, the only order tried for an ISO A4."""
    analysis = analyse(graphplan.load_text(starter("slider-crank", locale)))
    seen = force_sheets_headed(course_sheets(analysis, "A4"), locale)
    assert seen == {"forces-2", "forces-8"}


def force_sheets_headed(sheets, locale: str) -> set[str]:
    """The force sheets drawn on ``sheets``, each sheet with a part of one asserted to carry its heading (its title
    or its title "continued"), inside the frame and clear of every other drawing."""
    words = strings(locale)
    seen = set()
    for number, sheet in enumerate(sheets, 1):
        drawn = {force_sheet_of(layer.name) for layer in sheet.layers} - {None}
        seen |= drawn
        for whole in drawn:
            position = int(whole.rsplit("-", 1)[1])
            key = "tb_sheet_forces_friction_position" if "friction" in whole else "tb_sheet_forces_position"
            title = words[key].format(number=position)
            titles = {title, words["force_sheet_continued"].format(title=title)}
            headings = [layer for layer in sheet.layers
                        if force_sheet_of(layer.name) == whole and layer.name.endswith("-sheet-title")]
            assert headings, f"sheet {number}: {whole} drawn under no heading"
            # The title's lines, broken where the drawings are narrower than it, read as the title.
            texts = [item for layer in headings for item in layer.items if isinstance(item, Text)]
            lines = [text.text for text in texts if not text.text.startswith("μ")]
            assert " ".join(lines) in titles, (number, lines)
            # Inside the frame, clear of every drawing on the sheet.
            fx0, fy0, fx1, fy1 = sheet.frame
            for text in texts:
                x0, y0, x1, y1 = text_extent(text)
                assert fx0 < x0 and x1 < fx1 and fy0 < y0 and y1 < fy1, (number, text.text)
                for panel, (px0, py0, px1, py1) in sheet.panels.items():
                    if force_sheet_of(f"{panel}-") != whole:
                        assert not (x0 < px1 and px0 < x1 and y0 < py1 and py0 < y1), (number, text.text, panel)
    return seen


@pytest.mark.parametrize("locale", ["ru", "en"])
def test_the_force_sheets_of_a_run_on_a3_are_lettered_alike(locale):
    """The sheet with friction of position 5, its group under its heading only with its equations beside it, was
    first lettered at the usual size: in Russian in five parts, where lettered as the run's other force sheets it
    stands in four; in English in four either way, its group alone on a sheet, where lettered smaller it stands
    beside its polygon."""
    sizes = {}
    for sheet in sheets_of(locale, "A3"):
        for layer in sheet.layers:
            whole = force_sheet_of(layer.name)
            if whole and layer.name.endswith("-sheet-title"):
                sizes.setdefault(whole, set()).update(item.size for item in layer.items
                                                      if isinstance(item, Text) and item.weight == "bold")
    assert len(sizes) == 4 and len(set().union(*sizes.values())) == 1, sizes


def test_a_sheet_of_two_parts_of_one_force_sheet_is_named_after_it_in_the_title_block():
    """The Russian A3's group II(3,4) with friction of position 5, under its heading with its equations beside it,
    shares its sheet with its polygon, the next part, which goes on under that heading: the title block names the
    force sheet they are parts of, not the kind of drawing."""
    title = strings("ru")["tb_sheet_forces_friction_position"].format(number=5)
    shared = [sheet for sheet in sheets_of("ru", "A3") if sorted(sheet.panels) == ["forces-friction-5",
                                                                                   "forces-friction-5-2"]]
    assert len(shared) == 1
    (sheet,) = shared
    words = " ".join(item.text for layer in sheet.layers if layer.name == "title-block" for item in layer.items
                     if isinstance(item, Text))
    assert title in words or title.replace(" ", "") in words.replace(" ", ""), words
