"""A group cut free on a force sheet letters the pin of a slider block beside the block, not on its outline, as the
plan sheets and the plan of positions letter it.

Placed about the pin as any point is, the shaper's A stood on its block's corner and the engine's B on its edge.  The
letters and the blocks are read back from the forces_N.svg a run writes: a block is a closed path of four corners in
a group's links layer, its ink its rectangle grown by half its stroke; a letter's box is as wide as the project's
text_width measures it, from its descenders to its accents.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely
from sheet_texts import layer_letter_boxes

import graphplan
from graphplan.run import run

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
# The SVG writes its numbers to 0.001 mm: a box standing exactly at a line's ink may read up to that much into it.
WRITTEN_PRECISION_MM = 0.002
# A slider's block on the slotted levers, the shaper's ram and the engine's piston.
FIXTURES = ["quick_return_slotted_lever", "shaper_six_bar", "engine_slider_crank"]


def blocks(root: ET.Element, group: str) -> list[shapely.Geometry]:
    """The ink of every block drawn in ``group``'s links layer (a closed path of four corners)."""
    found = []
    for layer in root:
        if layer.get("id") != f"{group}-links":
            continue
        for path in layer.iter(f"{SVG}path"):
            d = path.get("d")
            numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", d)]
            corners = list(zip(numbers[0::2], numbers[1::2]))
            if d.rstrip().upper().endswith("Z") and len(corners) == 4:
                width = float(path.get("stroke-width", "0"))
                found.append(shapely.Polygon(corners).buffer(width / 2 - WRITTEN_PRECISION_MM))
    return found


def letters_on_blocks(svg: Path) -> list[str]:
    """Each point's letter of a group cut free whose box meets its group's block."""
    root = ET.parse(svg).getroot()
    groups = {layer.get("id").removesuffix("-labels") for layer in root
              if re.fullmatch(r"(?:forces-\d+-)?body-.*-labels", layer.get("id", ""))}
    found = []
    for group in sorted(groups):
        inks = blocks(root, group)
        for words, box in layer_letter_boxes(root, f"{group}-labels"):
            if re.fullmatch(r"[A-Z][0-9′]*", words) and any(ink.intersects(box) for ink in inks):
                found.append(f"{svg.name} {group}: {words!r}")
    return found


@pytest.fixture(scope="module", params=FIXTURES)
def force_sheets(request, tmp_path_factory) -> list[Path]:
    folder = tmp_path_factory.mktemp(request.param)
    run(graphplan.load(ROOT / "fixtures" / f"{request.param}.toml"), folder, only=["forces"])
    written = sorted(folder.glob("forces_*.svg"))
    assert written, f"{request.param}: the run wrote no force sheet"
    return written


def test_a_block_s_pin_is_lettered_clear_of_its_block(force_sheets):
    checked = 0
    for svg in force_sheets:
        root = ET.parse(svg).getroot()
        checked += sum(len(blocks(root, layer.get("id").removesuffix("-links"))) for layer in root
                       if layer.get("id", "").endswith("-links") and "body-" in layer.get("id", ""))
        assert letters_on_blocks(svg) == []
    assert checked, "no block was read: the reader would let any letter pass"
