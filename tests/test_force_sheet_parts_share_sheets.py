"""A force sheet's parts fill the A3 sheets they stand on, in reading order.

The starter's crank-rocker with friction in its four turning pairs on A3:
each force sheet stands in parts (group II, its polygon, group I beside its
polygon, the lever), and group I with its long thin polygon, a part too wide
for the room any sheet had left, stood alone on an A3, a fifth of it drawn
on, once for each force sheet.  Cut drawing by drawing where that saves a
sheet, group I stands under group II's polygon and its polygon beside the
lever.  The sheets keep the reading order: each position's force sheet, its
parts "continued", then the same position's sheet with friction, before the
next position's; in Chinese the sheet of position 11 began on a sheet before
the one with friction of position 5 went on.
"""

from __future__ import annotations

import functools
import itertools
import re

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render.primitives import bounds
from graphplan.render.sheet import course_sheets
from graphplan.starters import starter

FRICTION = "".join(f'\n[[friction]]\njoint  = "{joint}"\nf      = 0.1\nradius = 0.02\n' for joint in "OABC")
LOCALES = ("ru", "zh", "en")


@functools.cache
def sheets_of(locale: str):
    scene = graphplan.load_text(starter("crank-rocker", locale).replace("\n[positions]", FRICTION + "\n[positions]"))
    assert len(scene.friction) == 4
    return course_sheets(analyse(scene), "A3")


def force_parts(sheet) -> list[str]:
    return [name for name in sheet.panels if name.startswith("forces-")]


@pytest.mark.parametrize("locale", LOCALES)
def test_the_force_sheets_take_fewer_sheets_than_their_parts(locale):
    sheets = [sheet for sheet in sheets_of(locale) if force_parts(sheet)]
    parts = [name for sheet in sheets for name in force_parts(sheet)]
    assert len(parts) == len(set(parts))
    assert len(sheets) < len(parts)


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_group_one_stands_beside_group_two_where_the_sheet_has_room(locale):
    """Group I of position 5 (cut free, without friction) on the sheet of group II, not alone with its polygon."""
    def groups_on(sheet) -> set[str]:
        return {found.group(1) for layer in sheet.layers
                for found in [re.match(r"forces-5(?:-\d+)?-body-(I+)-", layer.name)] if found}

    assert any(groups_on(sheet) == {"I", "II"} for sheet in sheets_of(locale))


def drawings_on(sheet) -> dict[str, tuple[float, float, float, float]]:
    """The bounds of each drawing on ``sheet`` measured from its layers (a layer is its panel's by its name)."""
    names = sorted(sheet.panels, key=len, reverse=True)
    layers: dict[str, list] = {}
    for layer in sheet.layers:
        owner = next((name for name in names if layer.name.startswith(f"{name}-")), None)
        if owner is not None:
            layers.setdefault(owner, []).append(layer)
    return {name: tuple(float(value) for value in bounds(found)) for name, found in layers.items()}


def overlap(a, b) -> bool:
    return a[0] < b[2] - 1e-6 and b[0] < a[2] - 1e-6 and a[1] < b[3] - 1e-6 and b[1] < a[3] - 1e-6


@pytest.mark.parametrize("locale", LOCALES)
def test_no_drawing_covers_another_or_the_title_block(locale):
    for sheet in sheets_of(locale):
        drawn = drawings_on(sheet)
        assert set(drawn) == set(sheet.panels)
        for name, box in drawn.items():
            assert not overlap(box, sheet.title_block), (sheet.number, name)
            fx0, fy0, fx1, fy1 = sheet.frame
            assert fx0 <= box[0] and box[2] <= fx1 and fy0 <= box[1] and box[3] <= fy1, (sheet.number, name)
        for first, second in ((a, b) for a in drawn for b in drawn if a < b):
            assert not overlap(drawn[first], drawn[second]), (sheet.number, first, second)


def headings(svg: str) -> list[tuple[str, str, float, float]]:
    """The force sheets' headings in the order the SVG draws them: (the part's id, its title, x, y of its first
    line, y down the page)."""
    found = []
    for group in re.finditer(r'<g id="(forces-[^"]*?)-sheet-title">(.*?)</g>', svg, re.DOTALL):
        # A line mixing scripts is set in runs (<tspan>), each in its script's font: its words are their texts.
        texts = [(x, y, re.sub(r"<[^>]+>", "", inner)) for x, y, inner in
                 re.findall(r'<text [^>]*x="([-\d.]+)" y="([-\d.]+)"[^>]*>(.*?)</text>', group.group(2), re.DOTALL)]
        title_lines = [text for _, _, text in texts if not re.search(r"μ[lFV]", text)]
        x, y = float(texts[0][0]), float(texts[0][1])
        found.append((group.group(1), " ".join(title_lines), x, y))
    return found


@pytest.mark.parametrize("locale", LOCALES)
def test_the_headings_read_in_order(locale):
    words = strings(locale)

    def titles(number: int) -> list[str]:
        return [words[key].format(number=number) for key in ("tb_sheet_forces_position",
                                                              "tb_sheet_forces_friction_position")]

    expected = [title for number in (5, 11) for title in titles(number)]
    read: list[str] = []
    for sheet in sheets_of(locale):
        on_sheet = headings(sheet.svg())
        drawn = drawings_on(sheet)
        for (before, _, _, y0), (part, _, x1, y1) in itertools.pairwise(on_sheet):
            # The next heading stands lower, or right of the drawing before it (the top of the next column).
            assert y1 > y0 + 1e-6 or x1 >= drawn[before][2] - 1e-6, (sheet.number, part)
        read += [title for _, title, _, _ in on_sheet]
    # A heading that is no whole sheet's title is its title "continued", the title of the heading before it.
    wholes = []
    for title in read:
        plain = next((whole for whole in expected if title.replace(" ", "") == whole.replace(" ", "")), None)
        if plain is not None:
            wholes.append(plain)
        else:
            assert wholes and title.replace(" ", "") == words["force_sheet_continued"].format(
                title=wholes[-1]).replace(" ", ""), title
    assert wholes == expected

