"""Every letter on the course-project sheets stands at a height of the standard series (GOST 2.304, ISO 3098: 1.8,
2.5, 3.5, 5, 7, 10, 14, 20 mm of cap height), as a hand drawing made to the standard letters them.

The sheets are drawn as a user draws them, from the starters (`graphplan new`, `graphplan run --only sheets`): the
crank-rocker's (the plan of positions, the plan sheets, the kinematic diagrams, the force sheet with its lever, the
load diagrams) in English, Russian and Chinese, each under its language's title block; the shaper's (its force sheet
with friction, the machine's dynamics); the rotor's balancing polygons.  Each <text> and <tspan>'s font size is read
back to a cap height through the font's cap height (FONT_SIZE_PER_CAP) and the sheet's millimetres per unit (its
width in mm over its viewBox's)."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main
from graphplan.render import lettering
from graphplan.render.primitives import FONT_SIZE_PER_CAP

SVG = "{http://www.w3.org/2000/svg}"
# The SVG writes a font size to 0.001 of a unit: 3.5 mm comes back as 3.49992.
TOLERANCE_MM = 0.002
RUNS = (("crank-rocker", "en", "sheets"), ("crank-rocker", "ru", "sheets"), ("crank-rocker", "zh", "sheets"),
        ("shaper", "en", "sheets"), ("rotor", "en", "sheets,balancing"))


@pytest.fixture(scope="module")
def drawn(tmp_path_factory) -> dict[str, list[Path]]:
    """The SVG drawings of each run in :data:`RUNS`, by its name."""
    made = {}
    for kind, locale, pieces in RUNS:
        folder = tmp_path_factory.mktemp(f"{kind}-{locale}")
        scene = folder / f"{kind}.toml"
        assert main(["new", kind, "--out", str(scene), "--locale", locale]) == 0
        assert main(["run", str(scene), "--out", str(folder / "out"), "--only", pieces]) == 0
        made[f"{kind}-{locale}"] = sorted((folder / "out").glob("*.svg"))
    return made


def _millimetres_per_unit(root: ElementTree.Element) -> float:
    width = float(re.fullmatch(r"([0-9.]+)mm", root.get("width")).group(1))
    return width / float(re.split(r"[\s,]+", root.get("viewBox").strip())[2])


def heights(svg: Path) -> list[tuple[float, str]]:
    """The cap height (mm on the printed sheet) of every <text> and <tspan> of ``svg`` that sets a font size, with
    its text."""
    root = ElementTree.parse(svg).getroot()
    scale = _millimetres_per_unit(root)
    return [(float(element.get("font-size")) * scale / FONT_SIZE_PER_CAP, "".join(element.itertext()))
            for element in root.iter() if element.tag in (f"{SVG}text", f"{SVG}tspan") and element.get("font-size")]


def off_the_series(svg: Path) -> Counter:
    """The heights of ``svg``'s lettering that are no height of the series, each with a text set at it."""
    return Counter((round(height, 3), text) for height, text in heights(svg)
                   if min(abs(height - size) for size in lettering.SERIES) > TOLERANCE_MM)


def test_the_series_is_the_standards():
    assert lettering.SERIES == (1.8, 2.5, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0)
    assert [lettering.at_most(h) for h in (20.0, 6.9, 5.0, 3.4, 2.49, 1.8, 1.7)] == [20.0, 5.0, 5.0, 2.5, 1.8, 1.8, 1.7]
    assert lettering.larger(3.5) == 5.0 and lettering.larger(5.0) == 7.0


def test_the_roles_take_heights_of_the_series():
    roles = {name: value for name, value in vars(lettering).items()
             if name.isupper() and name not in ("SERIES", "SMALLEST")}
    assert roles and all(value in lettering.SERIES for value in roles.values()), roles


@pytest.mark.parametrize("run", [f"{kind}-{locale}" for kind, locale, _ in RUNS])
def test_every_letter_on_the_sheets_stands_at_a_height_of_the_series(drawn, run):
    svgs = drawn[run]
    assert any(svg.name.startswith("sheet_") for svg in svgs), svgs
    lettered = [svg for svg in svgs if heights(svg)]
    assert lettered
    off = {svg.name: dict(off_the_series(svg)) for svg in lettered}
    assert not any(off.values()), {name: found for name, found in off.items() if found}
