"""The curved arrows of ω and ε on the mechanism of a plan sheet keep off the frame's symbols (a pivot's triangle,
its ground line and hatching, a guide) and the moving joints' pins and slider blocks.

Each arrow was turned about the spot of its link farthest from the other links and points, weighed by that spot
alone: on a short crank beside a rocker (the slotted lever's, the shaper's, the triads') the spot stood a few
millimetres from the crank's pivot, and the arc, 7 mm round it, ran over the pivot's triangle and hatching; moved
off the frame alone, the arc of the triad's crank, 12 mm long, ran over its crankpin, and the shaper's over the top
of its slider block.  The arrows, the frame, the pins and blocks are read back from the plan_N.svg a run writes: an
arrow is each path of more than four points drawn straight in the layer of the senses (the joints' velocities are
arrows of their own groups), the frame every stroked path and pin of its layer, the pins and blocks the circles and
filled outlines of the links' layer, each as wide as its stroke draws it.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely
from light_runs import plan_sheets_alone

from graphplan.starters import starter

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
# The SVG writes its numbers to 0.001 mm: two inks that only touch may read up to that much into each other.
WRITTEN_PRECISION_MM = 0.002

# The triads' crank, and the starters' slotted lever and shaper, whose crank is short beside its rocker.
FIXTURES = ["triad_class_iii", "triad_with_slider"]
STARTERS = ["slotted-lever", "shaper"]


def _points(d: str) -> list[tuple[float, float]]:
    numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", d)]
    return list(zip(numbers[0::2], numbers[1::2]))


def _ink(element: ET.Element) -> shapely.Geometry:
    """The element's stroke (and a filled outline's inside), as wide as it is drawn."""
    half = float(element.get("stroke-width", "0")) / 2 - WRITTEN_PRECISION_MM
    if element.tag == f"{SVG}circle":
        centre = shapely.Point(float(element.get("cx")), float(element.get("cy")))
        return centre.buffer(float(element.get("r")) + half)
    points = _points(element.get("d"))
    if element.get("d").rstrip().upper().endswith("Z") and len(points) > 2:
        return shapely.Polygon(points).buffer(half)
    return shapely.LineString(points).buffer(half)


def layer(root: ET.Element, name: str) -> ET.Element:
    return next(group for group in root if group.get("id") == name)


def turn_arrows(root: ET.Element) -> list[shapely.Geometry]:
    """The ink of each curved arrow's arc: the senses' paths of more than two points (a head has four, closed)."""
    return [_ink(path) for path in layer(root, "mechanism-senses").findall(f"{SVG}path")
            if len(_points(path.get("d"))) > 4]


def frame_ink(root: ET.Element) -> shapely.Geometry:
    frame = layer(root, "mechanism-frame")
    return shapely.union_all([_ink(element) for element in frame.iter()
                              if element.tag in (f"{SVG}path", f"{SVG}circle")])


def pins_ink(root: ET.Element) -> shapely.Geometry:
    """The moving joints' pins and the slider blocks round them: the circles and filled outlines of the links."""
    links = layer(root, "mechanism-links")
    return shapely.union_all([_ink(element) for element in links.iter()
                              if element.tag == f"{SVG}circle"
                              or (element.tag == f"{SVG}path" and element.get("fill", "none") != "none")])


def arrows_on_the_frame(plan: Path) -> list[str]:
    root = ET.parse(plan).getroot()
    frame, pins, arrows = frame_ink(root), pins_ink(root), turn_arrows(root)
    assert arrows and not frame.is_empty and not pins.is_empty, f"{plan.name}: no curved arrows, frame or pins read"
    return [f"{plan.name}: an arc of ω or ε over {arc.intersection(ink).area:.2f} mm² of the {what}"
            for arc in arrows for what, ink in (("frame", frame), ("pins and blocks", pins)) if arc.intersects(ink)]


@pytest.fixture(scope="module", params=FIXTURES + STARTERS)
def written_plans(request, tmp_path_factory) -> list[Path]:
    folder = tmp_path_factory.mktemp(request.param)
    if request.param in STARTERS:
        scene = folder / f"{request.param}.toml"
        scene.write_text(starter(request.param), encoding="utf-8")
    else:
        scene = ROOT / "fixtures" / f"{request.param}.toml"
    return plan_sheets_alone(scene, folder / "out")


def test_no_curved_arrow_of_a_link_runs_over_the_frame_a_pin_or_a_block(written_plans):
    assert [found for plan in written_plans for found in arrows_on_the_frame(plan)] == []


def test_an_arc_drawn_over_a_pivot_is_found_on_the_frame(written_plans):
    # The check itself: an arc moved so that it passes through a pivot's pin is found there.
    root = ET.parse(written_plans[0]).getroot()
    pin = next(layer(root, "mechanism-frame").iter(f"{SVG}circle"))
    arc = next(path for path in layer(root, "mechanism-senses").findall(f"{SVG}path")
               if len(_points(path.get("d"))) > 4)
    (x0, y0), *_ = _points(arc.get("d"))
    dx, dy = float(pin.get("cx")) - x0, float(pin.get("cy")) - y0
    arc.set("d", " ".join(f"{'M' if k == 0 else 'L'}{x + dx:.3f},{y + dy:.3f}"
                          for k, (x, y) in enumerate(_points(arc.get("d")))))
    frame = frame_ink(root)
    assert any(ink.intersects(frame) for ink in turn_arrows(root))
