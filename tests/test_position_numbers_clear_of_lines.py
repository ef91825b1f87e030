"""A position's number round the crank's circle on the plan of positions stands on no line: the thin ones (the other
positions' outlines, the points' paths) are broken under it, as a draftsman breaks a thin line under a number (ГОСТ
2.307), and the bold ones it is set clear of by their ink, not their middles.

The numbers were set clear of the bold lines' middles alone, among the thin ones: the Scotch yoke's 10 and 4 stood
struck through by the ends of its slot at those positions, the crank-rocker's 5 and 7 on the dashed path of B and
the outlines of the rocker, and the shaper's 12 on the ink of its 1 mm crank.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest
import shapely
from drawn_lines import stroked_shapes
from positions_runs import positions_plan
from sheet_texts import box, texts


@pytest.mark.parametrize("scene", ["scotch_yoke", "new:crank-rocker", "ratchet_crank_rocker", "tangent_mechanism_prp",
                                   "new:shaper", "shaper_six_bar"])
def test_no_position_number_stands_on_a_line(tmp_path, scene) -> None:
    source = positions_plan(tmp_path, scene)
    ink = shapely.STRtree(stroked_shapes(ET.fromstring(source), ("leaders", "labels", "caption")))
    numbers = [entry for entry in texts(source) if re.fullmatch(r"\d+", entry[4])]
    assert len(numbers) >= 12, "the plan numbers its positions round the crank's circle"
    struck = [entry[4] for entry in numbers if len(ink.query(shapely.box(*box(*entry)), predicate="intersects"))]
    assert struck == []


@pytest.mark.parametrize("scene", ["v_twin_engine", "engine_slider_crank", "ratchet_crank_rocker"])
def test_no_letter_stands_on_a_points_path(tmp_path, scene) -> None:
    """A letter with no clear spot by its point breaks the thin lines under it, the points' paths among them: the
    V-twin's O, beside its pivot inside the 5 mm circle that S2 runs round it, stood struck through by that circle."""
    source = positions_plan(tmp_path, scene)
    root = ET.fromstring(source)
    drawn = stroked_shapes(root, tuple(layer.get("id") for layer in root if layer.get("id") != "paths"))
    assert drawn, "the plan draws the paths of its points"
    paths = shapely.STRtree(drawn)
    letters = [entry for entry in texts(source) if not re.fullmatch(r"\d+", entry[4])]
    struck = [entry[4] for entry in letters if len(paths.query(shapely.box(*box(*entry)), predicate="intersects"))]
    assert struck == []
