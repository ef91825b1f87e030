"""The letters and numbers of the plan of positions keep clear of the travel's dimension (a stroke's H, a swing's ψ):
farther off its extension and dimension lines and its text than the dimension's own text stands off its line.  Nearer,
a label reads as that line's number: kept off the dimension's ink alone, the Scotch yoke's 8 stood level just over the
stroke's upper extension line, and its 12 hung just under the lower one."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest
import shapely
from drawn_lines import SVG, stroked_path
from positions_runs import positions_plan
from sheet_texts import layer_letter_boxes


def _dimension_lines(root: ET.Element) -> list[shapely.Geometry]:
    """The dimension's stroked lines and arrowheads as drawn, each as wide as its stroke."""
    (group,) = [group for group in root.iter(f"{SVG}g") if group.get("id") == "dimensions"]
    return [stroked_path(item) for item in group.findall(f"{SVG}path")]


@pytest.mark.parametrize("scene", ["scotch_yoke", "offset_slider_crank", "engine_slider_crank", "new:slider-crank",
                                   "new:shaper"])
def test_no_label_stands_nearer_the_stroke_s_lines_than_its_own_text(tmp_path, scene) -> None:
    root = ET.fromstring(positions_plan(tmp_path, scene))
    lines = _dimension_lines(root)
    (written,) = [box for text, box in layer_letter_boxes(root, "dimensions") if text.startswith("H")]
    # How far the dimension's own text stands off its lines: the distance that reads as belonging to them.
    own_gap = min(written.distance(line) for line in lines)
    assert 0 < own_gap < 3
    near = [(text, round(min(box.distance(shape) for shape in [*lines, written]), 2))
            for text, box in layer_letter_boxes(root, "labels")]
    assert near, "the plan letters its points and numbers its positions"
    assert [(text, gap) for text, gap in near if gap <= own_gap] == []
