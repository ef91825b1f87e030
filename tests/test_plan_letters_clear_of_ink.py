"""The velocity and acceleration plans keep their points' letters off the lines' ink, as wide as each line is drawn.

Kept off the lines' middles alone, a letter could stand with its box on the edge of a vector drawn 0.6 mm wide (the
Stephenson six-bar's g along pa, s2 along pa of most plans).  The letters and lines are read back from the plan_N.svg
a run writes: a line is every unfilled stroked path of a plan's lines and vectors (lines of action, similar figures,
the vectors' shafts) widened by half its own stroke-width; a letter's box is as wide as the project's text_width
measures it at the SVG's font size and reaches from its descenders to its accents (0.3 and 1.15 cap heights below and
above the baseline).  Left out: the leaders (a label's own leader ends at its box), the arrowheads and the points'
dots, marks the placer keeps off by their outlines' middles (a 0.1 mm stroke).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely
from light_runs import plan_sheets_alone
from sheet_texts import layer_letter_boxes, set_off_a_line

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
KINDS = ("velocity", "acceleration")
# The SVG writes its numbers to 0.001 mm: a box standing exactly at a line's ink may read up to that much into it.
WRITTEN_PRECISION_MM = 0.002

# Crowded plans: the triad's star of vectors at its pole, the six-bar's fan, the tangent mechanism's letters between
# the lines of action, the slotted lever's short vectors.
FIXTURES = ["triad_class_iii", "stephenson_six_bar", "tangent_mechanism_prp", "quick_return_slotted_lever"]


def plan_lines(root: ET.Element, kind: str) -> list[tuple[str, shapely.Geometry]]:
    """(the group's id, the ink) of every unfilled stroked path of the plan ``kind``'s lines and vectors."""
    found = []
    for layer in root:
        name = layer.get("id") or ""
        if name not in (f"{kind}-lines", f"{kind}-vectors"):
            continue
        for group in layer.iter(f"{SVG}g"):
            for path in group.findall(f"{SVG}path"):
                if path.get("fill", "none") != "none" or path.get("stroke", "none") == "none":
                    continue
                numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", path.get("d"))]
                points = list(zip(numbers[0::2], numbers[1::2]))
                if path.get("d").rstrip().upper().endswith("Z"):
                    points.append(points[0])
                half = float(path.get("stroke-width")) / 2
                found.append((group.get("id"), shapely.LineString(points).buffer(half - WRITTEN_PRECISION_MM)))
    return found


def letter_boxes(root: ET.Element, kind: str) -> list[tuple[str, shapely.Geometry]]:
    """(text, box) of every letter of the plan ``kind``, in the SVG's y-down millimetres."""
    return layer_letter_boxes(root, f"{kind}-labels")


def letters_on_ink(root: ET.Element) -> list[str]:
    """Each letter whose box meets a line's ink, with the lines it meets."""
    found = []
    for kind in KINDS:
        lines = plan_lines(root, kind)
        for words, box in letter_boxes(root, kind):
            met = [name for name, ink in lines if ink.intersects(box)]
            if met:
                found.append(f"{kind} {words!r} on {', '.join(met)}")
    return found


@pytest.fixture(scope="module", params=FIXTURES)
def written_plans(request, tmp_path_factory) -> list[Path]:
    return plan_sheets_alone(ROOT / "fixtures" / f"{request.param}.toml", tmp_path_factory.mktemp(request.param) / "out")


def test_no_letter_stands_on_a_lines_ink(written_plans):
    for plan in written_plans:
        root = ET.parse(plan).getroot()
        assert all(letter_boxes(root, kind) for kind in KINDS), f"{plan.name}: no letters read"
        assert letters_on_ink(root) == [], plan.name


def test_a_letter_on_a_vectors_edge_is_on_its_ink_though_clear_of_its_middle(written_plans):
    # The check itself: a letter moved so that its box's nearest corner stands 0.1 mm off the middle of a vector of
    # the plan, within the half of its stroke that is ink, is found on that vector.
    root = ET.parse(written_plans[0]).getroot()
    vector = next(group for layer in root if layer.get("id") == "velocity-vectors" for group in layer.iter(f"{SVG}g")
                  if group.get("id") != "velocity-vectors")
    shaft = next(path for path in vector.findall(f"{SVG}path") if path.get("fill", "none") == "none")
    assert float(shaft.get("stroke-width")) / 2 > 0.1 + WRITTEN_PRECISION_MM
    numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", shaft.get("d"))]
    (x0, y0), (x1, y1) = numbers[:2], numbers[2:4]
    letter = next(text for layer in root if layer.get("id") == "velocity-labels" for text in layer.findall(f"{SVG}text"))
    words = "".join(letter.itertext())
    set_off_a_line(letter, (x0, y0), (x1, y1), 0.1)
    box = next(box for text, box in letter_boxes(root, "velocity") if text == words)
    assert box.distance(shapely.LineString([(x0, y0), (x1, y1)])) == pytest.approx(0.1, abs=1e-3)
    moved = [found for found in letters_on_ink(root) if found.startswith(f"velocity {words!r} on ")]
    assert len(moved) == 1 and vector.get("id") in moved[0].split(" on ")[1].split(", ")
