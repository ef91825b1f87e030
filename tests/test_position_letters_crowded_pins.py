"""The plan of positions' letters round its crowded pins, read back from the positions.svg a run writes: the Scotch
yoke's A′ stands near its top pin, the engine's O clear of its pivot's hatching, and the slider driven mechanism's
leaders not beside the hatching of its guide.

A text's box is as wide as the drawings measure it and a cap height tall (``sheet_texts.box``); a line's ink is its
path widened by half its stroke (``drawn_lines.stroked_shapes``).  The pins are found from the scene's own
geometry, not from the labels' anchors.
"""

from __future__ import annotations

import itertools
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import shapely
from drawn_lines import stroked_shapes
from sheet_texts import box, flat, texts

from graphplan.cli import main
from graphplan.render.linkage import BLOCK_REACH_MM

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
# ISO 128-20: the least space between parallel lines, hatching included (mm).
LEAST_SPACE = 0.7
# A leader within this angle of a line, and nearer it than the least space for more than a millimetre, runs beside it.
NEARLY_ALONG = math.radians(20.0)


def _drawn(fixture: str, tmp_path: Path) -> tuple[str, ET.Element]:
    assert main(["run", str(ROOT / "fixtures" / f"{fixture}.toml"), "--out", str(tmp_path / fixture),
                 "--only", "positions"]) == 0
    source = (tmp_path / fixture / "positions.svg").read_text(encoding="utf-8")
    return source, ET.fromstring(source)


def _boxes(source: str, name: str) -> list[shapely.Polygon]:
    return [shapely.box(*box(*entry)) for entry in texts(source) if entry[4] == name]


def _segments(root: ET.Element, groups: set[str]) -> list[tuple[shapely.LineString, float]]:
    """Each straight piece of the paths in the SVG groups ``groups``, with its stroke's width."""
    found = []
    for group in root.iter(f"{SVG}g"):
        if group.get("id") not in groups:
            continue
        for item in group:
            if item.tag != f"{SVG}path" or item.get("stroke", "none") == "none":
                continue
            numbers = [float(value) for value in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", item.get("d"))]
            points = list(zip(numbers[0::2], numbers[1::2]))
            found += [(shapely.LineString(pair), float(item.get("stroke-width", "0")))
                      for pair in itertools.pairwise(points) if pair[0] != pair[1]]
    return found


def test_the_scotch_yokes_a_prime_stands_near_its_top_pin_clear_of_the_ink(tmp_path):
    """At the yoke's top extreme (φ = 90°, r = 75 mm straight above O) the crank pin carries the number 7 and the
    letters A′ and B′, inside the slider blocks drawn round it.  A′ stands above the pin, within three of its
    letters' heights of the blocks' edge (where a block's pin's spots begin, ``linkage.BLOCK_REACH_MM`` from it), on
    the ink of no line (it stood on a 7 mm leader 8.5 mm off, down across the blocks, after reaching out from a clear
    spot near the pin to a dearer one)."""
    source, root = _drawn("scotch_yoke", tmp_path)
    scale = float(re.search(r"μl = ([\d.]+) m/mm", flat(source)).group(1))
    reach = 0.075 / scale
    circles = {(round(float(item.get("cx")), 2), round(float(item.get("cy")), 2)) for item in root.iter(f"{SVG}circle")
               if item.get("fill") == "white"}
    # O: the open circle with a pin r above it and r below (the extremes at 90° and 270°); the SVG's y runs down.
    (pivot,) = [(x, y) for x, y in circles
                if any(abs(u - x) < 0.01 and abs(v - (y - reach)) < 0.01 for u, v in circles)
                and any(abs(u - x) < 0.01 and abs(v - (y + reach)) < 0.01 for u, v in circles)]
    pin = shapely.Point(pivot[0], pivot[1] - reach)
    (label,) = _boxes(source, "A′")
    letter = label.bounds[3] - label.bounds[1]
    assert label.distance(pin) < BLOCK_REACH_MM + 3 * letter, f"A′ stands {label.distance(pin):.2f} mm from its pin"
    assert label.centroid.y < pin.y, "A′ stands below its pin, across the blocks"
    ink = shapely.STRtree(stroked_shapes(root, ("leaders", "labels", "caption")))
    assert not len(ink.query(label, predicate="intersects")), "A′ stands on a line's ink"


def test_the_engines_o_stands_clear_of_its_pivots_hatching(tmp_path):
    """The crank's pivot O keeps off the ink of every line, the thin hatching of its pivot's ground too (its box
    stood 0.02 mm into the ink of a hatch stroke, kept clear of that stroke's middle alone)."""
    source, root = _drawn("engine_slider_crank", tmp_path)
    (label,) = _boxes(source, "O")
    lines = stroked_shapes(root, ("leaders", "labels", "caption"))
    nearest = min(line.distance(label) for line in lines)
    assert nearest > 0.0, "O stands on a line's ink"


def test_no_leader_of_the_slider_driven_mechanism_runs_beside_a_line_of_its_frame(tmp_path):
    """A leader nearly along a hatch stroke and nearer it than ISO 128-20's least space between parallel lines
    reads as one more stroke: the letter G's ran down 0.45 mm beside one for 1.8 mm.  No leader runs so beside any
    line of the frame (the guides, their hatching, the pivots)."""
    _, root = _drawn("slider_driven", tmp_path)
    frame = _segments(root, {"frame"})
    leaders = _segments(root, {"leaders"})
    assert leaders
    for leader, leader_width in leaders:
        (x0, y0), (x1, y1) = leader.coords
        for line, width in frame:
            (u0, v0), (u1, v1) = line.coords
            if abs(math.sin(math.atan2(y1 - y0, x1 - x0) - math.atan2(v1 - v0, u1 - u0))) >= math.sin(NEARLY_ALONG):
                continue
            beside = leader.intersection(line.buffer(LEAST_SPACE + (width + leader_width) / 2, cap_style="flat"))
            assert beside.length <= 1.0, (f"the leader from {leader.coords[0]} runs {beside.length:.2f} mm beside "
                                          f"the frame's line {list(line.coords)}")
