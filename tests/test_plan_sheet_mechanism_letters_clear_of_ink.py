"""The mechanism drawn on a plan sheet keeps its points' letters and its ω, ε names off the bold lines' ink, as wide
as each line is drawn, as the plan of positions keeps its letters.

Kept off the lines' middles alone, the slotted lever's A stood on the 0.7 mm outline of its block (0.1-0.3 mm² of
its box), the pivots' C and O on their triangles', S2 and S4 on the 0.8 mm links, and the ω, ε names on the 0.45 mm
arrows of the points' velocities.  The letters and lines are read back from the plan_N.svg a run writes: a bold
line is every stroked path of the mechanism's links, springs and cylinders, frame and senses drawn 0.45 mm wide or
wider (a link, a block's or a pivot's outline, an arrow's shaft, a curved arrow), widened by half its own
stroke-width, a filled outline over the whole of what it fills; a letter's box is as wide as the project's
text_width measures it at the SVG's font size and reaches from its descenders to its accents (0.3 and 1.15 cap
heights below and above the baseline).  Left out: the thin lines (the ground's hatching, a guide's line, which the
letters may break), the leaders, the arrowheads, the points' dots and the pins' circles.
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
# The SVG writes its numbers to 0.001 mm: a box standing exactly at a line's ink may read up to that much into it.
WRITTEN_PRECISION_MM = 0.002
# The thinnest line counted bold: the arrows of the senses (0.45 mm); the hatching and guides are 0.25 mm.
BOLD_MM = 0.45
LINE_LAYERS = ("mechanism-links", "mechanism-load-links", "mechanism-frame", "mechanism-senses")

# Blocks round pins (the slotted levers, the tangent mechanism), a fan of links and arrows (the triad, the six-bar).
FIXTURES = ["quick_return_slotted_lever", "shaper_six_bar", "tangent_mechanism_prp", "triad_class_iii",
            "stephenson_six_bar", "engine_slider_crank"]


def _points(d: str) -> list[tuple[float, float]]:
    numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", d)]
    return list(zip(numbers[0::2], numbers[1::2]))


def bold_lines(root: ET.Element) -> list[tuple[str, shapely.Geometry]]:
    """(the layer's id, the ink) of every stroked path of the mechanism's bold lines."""
    found = []
    for layer in root:
        if layer.get("id") not in LINE_LAYERS:
            continue
        for path in layer.iter(f"{SVG}path"):
            width = float(path.get("stroke-width", "0"))
            if path.get("stroke", "none") == "none" or width < BOLD_MM:
                continue
            points = _points(path.get("d"))
            closed = path.get("d").rstrip().upper().endswith("Z")
            if closed and path.get("fill", "none") != "none":
                shape = shapely.Polygon(points)
            else:
                shape = shapely.LineString(points + (points[:1] if closed else []))
            found.append((layer.get("id"), shape.buffer(width / 2 - WRITTEN_PRECISION_MM)))
    return found


def letter_boxes(root: ET.Element) -> list[tuple[str, shapely.Geometry]]:
    """(text, box) of every letter and name of the mechanism, in the SVG's y-down millimetres."""
    return layer_letter_boxes(root, "mechanism-labels")


def letters_on_ink(root: ET.Element) -> list[str]:
    """Each letter whose box meets a bold line's ink, with the layers of the lines it meets."""
    lines = bold_lines(root)
    return [f"{words!r} on {', '.join(name for name, ink in lines if ink.intersects(box))}"
            for words, box in letter_boxes(root) if any(ink.intersects(box) for _, ink in lines)]


@pytest.fixture(scope="module", params=FIXTURES)
def written_plans(request, tmp_path_factory) -> list[Path]:
    return plan_sheets_alone(ROOT / "fixtures" / f"{request.param}.toml", tmp_path_factory.mktemp(request.param) / "out")


def test_no_mechanism_letter_stands_on_a_bold_lines_ink(written_plans):
    for plan in written_plans:
        root = ET.parse(plan).getroot()
        assert letter_boxes(root) and bold_lines(root), f"{plan.name}: no letters or lines read"
        assert letters_on_ink(root) == [], plan.name


def blocks(root: ET.Element) -> list[shapely.Geometry]:
    """The slider blocks round the mechanism's pins: each filled four-cornered outline of its links."""
    return [shapely.Polygon(_points(path.get("d"))) for layer in root if layer.get("id") == "mechanism-links"
            for path in layer.iter(f"{SVG}path")
            if path.get("fill", "none") != "none" and len(_points(path.get("d"))) == 4]


def test_a_block_pins_letter_stands_beside_the_block_not_led_out_of_it(written_plans):
    # Clear of the block's ink, the letter of the pin inside it stands beside the block, as a draughtsman letters it:
    # no leader starts within a block (the slotted levers' A, the shaper's E, the tangent mechanism's B stood on
    # leaders out of theirs), and every block has a letter within a letter's height of its outline.
    for plan in written_plans:
        root = ET.parse(plan).getroot()
        leaders = [shapely.Point(_points(path.get("d"))[0]) for layer in root if layer.get("id") == "mechanism-leaders"
                   for path in layer.iter(f"{SVG}path")]
        boxes = [box for _, box in letter_boxes(root)]
        for block in blocks(root):
            assert not [start for start in leaders if block.contains(start)], plan.name
            height = min(box.bounds[3] - box.bounds[1] for box in boxes) / 1.45
            assert min(block.exterior.distance(box) for box in boxes) < height, plan.name


def test_a_letter_on_a_links_edge_is_on_its_ink_though_clear_of_its_middle(written_plans):
    # The check itself: a letter moved so that its box's nearest corner stands 0.2 mm off the middle of a link's
    # line, within the half of its 0.8 mm stroke that is ink, is found on the links.
    root = ET.parse(written_plans[0]).getroot()
    link = next(path for layer in root if layer.get("id") == "mechanism-links" for path in layer.iter(f"{SVG}path")
                if path.get("fill", "none") == "none" and len(_points(path.get("d"))) == 2)
    assert float(link.get("stroke-width")) / 2 > 0.2 + WRITTEN_PRECISION_MM
    (x0, y0), (x1, y1) = _points(link.get("d"))
    letter = next(text for layer in root if layer.get("id") == "mechanism-labels" for text in layer.findall(f"{SVG}text"))
    words = "".join(letter.itertext())
    set_off_a_line(letter, (x0, y0), (x1, y1), 0.2)
    box = next(box for text, box in letter_boxes(root) if text == words)
    assert box.distance(shapely.LineString([(x0, y0), (x1, y1)])) == pytest.approx(0.2, abs=1e-3)
    assert any(found.startswith(f"{words!r} on ") and "mechanism-links" in found for found in letters_on_ink(root))
