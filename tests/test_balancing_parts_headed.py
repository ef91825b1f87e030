"""A rotor's balancing polygons that stand a plane to a sheet say what they are: the drawing's title, "continued".

On an upright Russian A4 the rotor starter's two planes stood one to a sheet under their captions alone, the title
block all that said they were the balancing of a rotor.  Each now stands under the drawing's title, the second under
the title "continued", as the kinematic diagrams' parts do; where the two stand on one sheet (in English, one under
the other) the title of the first alone would take the second off it, and the sheet stays as it was.
"""

from __future__ import annotations

import re
from xml.etree import ElementTree

from graphplan.cli import main
from graphplan.locale import Count, strings
from graphplan.starters import starter

SVG = "{http://www.w3.org/2000/svg}"


def _sheets(tmp_path, locale: str) -> list[ElementTree.Element]:
    scene = tmp_path / "rotor.toml"
    scene.write_text(starter("rotor"), encoding="utf-8")
    out = tmp_path / locale
    assert main(["run", str(scene), "--out", str(out), "--sheet", "A4", "--locale", locale]) == 0
    paths = sorted(out.glob("sheet_*.svg"), key=lambda path: int(re.search(r"(\d+)\.svg$", path.name).group(1)))
    return [ElementTree.parse(path).getroot() for path in paths]


def _planes_and_headings(root: ElementTree.Element) -> tuple[list[str], list[str]]:
    """The correction planes whose captions a sheet holds, and the headings over the balancing on it."""
    planes, headings = [], []
    for group in root.iter(f"{SVG}g"):
        name = group.get("id", "")
        if found := re.fullmatch(r"balancing-(?:\d+-)?plane-(\w+)-caption", name):
            planes.append(found.group(1))
        if re.fullmatch(r"balancing-(?:\d+-)?sheet-title", name):
            headings.append(" ".join("".join(text.itertext()) for text in group.iter(f"{SVG}text")))
    return planes, headings


def test_each_plane_on_a_sheet_of_its_own_stands_under_the_title_the_second_continued(tmp_path):
    locale = "ru"
    text = strings(locale)
    title = text["bal_title"].format(count=Count(2))
    sheets = [_planes_and_headings(root) for root in _sheets(tmp_path, locale)]
    assert [planes for planes, _ in sheets] == [["L"], ["R"]]
    # Broken onto lines to the polygon's width: the words, not the breaks, are read.
    assert [[heading.split() for heading in headings] for _, headings in sheets] == \
        [[title.split()], [text["force_sheet_continued"].format(title=title).split()]]


def test_two_planes_on_one_sheet_stay_there_without_a_title_that_would_take_one_off(tmp_path):
    (root,) = _sheets(tmp_path, "en")
    planes, _ = _planes_and_headings(root)
    assert planes == ["L", "R"]
