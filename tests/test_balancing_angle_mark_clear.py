"""A balancing polygon's correction angle θ is marked where it keeps clear of the sides' names: each name stands by
its side without a leader and more than its letters' height off the x-direction, the arc and any line run on, and the
arc still measures the caption's θ from the x-direction to the correction's line.

Marked at the correction's tail alone, the rotor starter's plane L's x-direction ran over the spot beside the short
(m3r3)L ending there: its name was led off under the x-direction, 2.4 mm from it, between it and (m1r1)L's arrowhead."""

from __future__ import annotations

import json
import math
import re
import xml.etree.ElementTree as ET

import pytest
import shapely
from drawn_lines import SVG
from sheet_texts import layer_letter_boxes

from graphplan.cli import main
from graphplan.render.primitives import FONT_SIZE_PER_CAP

_ANGLE_COLOUR = "#a83a1f"


@pytest.fixture(scope="module")
def rotor(tmp_path_factory) -> tuple[ET.Element, dict]:
    folder = tmp_path_factory.mktemp("rotor")
    assert main(["new", "rotor", "--out", str(folder / "rotor.toml")]) == 0
    assert main(["run", str(folder / "rotor.toml"), "--out", str(folder / "out")]) == 0
    svg = ET.fromstring((folder / "out" / "rotor_balancing.svg").read_text(encoding="utf-8"))
    return svg, json.loads((folder / "out" / "results.json").read_text(encoding="utf-8"))


def _paths(root: ET.Element, group_id: str) -> list[ET.Element]:
    (group,) = [group for group in root.iter(f"{SVG}g") if group.get("id") == group_id]
    return list(group.iter(f"{SVG}path"))


def _points(path: ET.Element) -> list[tuple[float, float]]:
    numbers = [float(value) for value in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", path.get("d"))]
    return list(zip(numbers[0::2], numbers[1::2]))


@pytest.mark.parametrize("plane", ["L", "R"])
def test_the_sides_names_stand_clear_of_the_correction_s_angle(rotor, plane) -> None:
    root, _ = rotor
    marks = [shapely.LineString(_points(path)).buffer(float(path.get("stroke-width")) / 2)
             for path in _paths(root, f"plane-{plane}-reference") if path.get("fill") == "none"]
    assert marks
    (labels,) = [group for group in root.iter(f"{SVG}g") if group.get("id") == f"plane-{plane}-labels"]
    names = [(text, box) for text, box in layer_letter_boxes(root, f"plane-{plane}-labels") if not text.startswith("θ")]
    assert len(names) == 4  # three masses' shares and the correction
    # The sides' names' letter height, as the sheet sets it.
    height = max(float(text.get("font-size")) for text in labels.iter(f"{SVG}text")) / FONT_SIZE_PER_CAP
    assert [(text, round(min(box.distance(mark) for mark in marks), 2)) for text, box in names
            if min(box.distance(mark) for mark in marks) <= height] == []
    assert _paths(root, f"plane-{plane}-leaders") == []


@pytest.mark.parametrize("plane", ["L", "R"])
def test_the_arc_measures_theta_from_the_x_direction_to_the_correction_s_line(rotor, plane) -> None:
    root, results = rotor
    theta = next(entry["angle_deg"] for entry in results["balancing"]["planes"] if entry["plane"] == plane)
    reference = _paths(root, f"plane-{plane}-reference")
    (arc,) = [path for path in reference if path.get("stroke") == _ANGLE_COLOUR and path.get("fill") == "none"]
    (head,) = [path for path in reference if path.get("fill") == _ANGLE_COLOUR]
    x_direction = _points(next(path for path in reference if path.get("stroke-dasharray")))
    (centre, toward) = x_direction
    assert toward[1] == pytest.approx(centre[1]) and toward[0] > centre[0]  # the x-direction, level to the right
    # From the x-direction to the tip of the arc's arrowhead, its first point (the arc stops short of it); paper y runs
    # down in SVG: an angle turned counter-clockwise on the sheet is a negative one in its coordinates.
    angles = [math.degrees(-math.atan2(y - centre[1], x - centre[0])) % 360 for x, y in (_points(arc)[0],
                                                                                      _points(head)[0])]
    assert min(angles[0], 360 - angles[0]) < 0.5
    assert angles[1] == pytest.approx(theta, abs=0.5)
    # The arc's centre lies on the correction's line (at its tail or its head).
    (correction,) = [path for path in _paths(root, f"plane-{plane}-vectors")
                     if path.get("stroke") == _ANGLE_COLOUR and path.get("fill") == "none"]
    line = shapely.LineString(_points(correction))
    (x0, y0), (x1, y1) = line.coords
    across = abs((x1 - x0) * (centre[1] - y0) - (y1 - y0) * (centre[0] - x0)) / line.length
    assert across < 0.05
