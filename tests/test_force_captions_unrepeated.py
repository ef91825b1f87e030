"""Force sheets as a teacher reads them: the crank's caption gives its balancing moment once (its moment equation
ends with it; a second line said it again "by the force polygons"), the lever's still gives it both ways, and a
heading stands on one line where the sheet has room for it (it broke to its drawings' width)."""

from __future__ import annotations

import dataclasses
import re

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render import drawings
from graphplan.render import forces as force_layout
from graphplan.render.primitives import Text, text_extent
from graphplan.render.sheet import course_sheets

# The balancing moment's name and value as a caption writes it: "Mb = 96.55 N·m", "Mу = −257.0 Н·м".
MB = re.compile(r"M[bу] = [−-]?[\d.]+ (?:N·m|Н·м)")  # the Russian textbook's Mу


def captions(layers, name):
    lines = [item.text for layer in layers if layer.name == f"{name}-caption" for item in layer.items
             if isinstance(item, Text)]
    # A line broken at its width is read whole again.
    return " ".join(lines)


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_the_crank_s_caption_gives_the_balancing_moment_once_and_the_lever_s_both_ways(locale):
    scene = dataclasses.replace(graphplan.load("fixtures/shaper_six_bar.toml"), locale=locale)
    analysis = analyse(scene)
    for position in analysis.plans:
        layers = force_layout.layout(drawings.force_sheet(analysis, position))
        crank = captions(layers, "body-I-1-2")
        lever = captions(layers, "lever")
        value = f"{abs(position.forces.balancing):.4g}".rstrip("0").rstrip(".")
        assert len(MB.findall(crank)) == 1, crank
        assert value in MB.findall(crank)[0].replace("−", "")
        # The lever compares its own value with the polygons': both stay.
        assert len(MB.findall(lever)) == 2, lever


def test_a_force_sheet_s_heading_stands_on_one_line_where_the_sheet_has_room():
    scene = graphplan.load("fixtures/shaper_six_bar.toml")
    scene = dataclasses.replace(scene, locale="ru", drawing=dataclasses.replace(scene.drawing, sheet="A2"))
    sheets = course_sheets(analyse(scene), "A2")
    headings = [(sheet, layer) for sheet in sheets for layer in sheet.layers
                if layer.name.startswith("forces-") and layer.name.endswith("sheet-title")]
    assert headings
    for sheet, layer in headings:
        bold = [item for item in layer.items if isinstance(item, Text) and item.weight == "bold"]
        assert len(bold) == 1, [item.text for item in bold]
        x0, _, x1, y1 = text_extent(bold[0])
        assert sheet.frame[0] < x0 and x1 < sheet.frame[2] and y1 < sheet.frame[3]
