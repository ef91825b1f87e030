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

Where such a crank lies beside another link at a narrow angle (CRAMPED), no spot of it let the 7 mm arc clear that
link too: ω crossed the connecting rod or the rocker, ran over the dot of S2 or along the arrow of S2's velocity.
There each curved arrow, arc and head, crosses the links' lines in one run at most (its own link, or none when drawn
round the crank's pivot) and lies on no point's dot (the circles of the points' layer) and no other arrow.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely
from drawn_lines import SVG, layer
from light_runs import plan_sheets_of

# The SVG writes its numbers to 0.001 mm: two inks that only touch may read up to that much into each other.
WRITTEN_PRECISION_MM = 0.002

# The triads' crank, and the starters' slotted lever and shaper, whose crank is short beside its rocker.
FIXTURES = ["triad_class_iii", "triad_with_slider"]
STARTERS = ["slotted-lever", "shaper", "triad"]
# The positions where that crank, 12 to 17 mm long as drawn, lies beside another link at a narrow angle: no spot of
# it lets a 7 mm arc clear that link, the point S2 on the crank or the arrow of S2's velocity.
CRAMPED = {"triad_with_slider": "plan_8.svg", "triad": "plan_8.svg", "slotted-lever": "plan_11.svg",
           "shaper": "plan_10.svg"}


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


def turns_with_heads(root: ET.Element) -> list[shapely.Geometry]:
    """The ink of each curved arrow, its arc and its head: the senses' own paths, an arc and then its head."""
    paths = layer(root, "mechanism-senses").findall(f"{SVG}path")
    return [shapely.union_all([_ink(arc), _ink(head)]) for arc, head in zip(paths[0::2], paths[1::2])]


def arrows_on_other_ink(plan: Path) -> list[str]:
    """Where a curved arrow crosses more than one run of the links' lines (its own link's, which it is drawn across),
    lies on a point's dot, or on another arrow (a joint's velocity, another link's ω or ε)."""
    root = ET.parse(plan).getroot()
    senses = layer(root, "mechanism-senses")
    turns = turns_with_heads(root)
    velocities = [shapely.union_all([_ink(path) for path in group.iter(f"{SVG}path")])
                  for group in senses.findall(f"{SVG}g")]
    lines = shapely.union_all([_ink(element) for element in layer(root, "mechanism-links").iter(f"{SVG}path")
                               if element.get("fill", "none") == "none"])
    dots = shapely.union_all([_ink(circle) for circle in layer(root, "mechanism-points").iter(f"{SVG}circle")])
    assert turns and velocities and not lines.is_empty and not dots.is_empty, f"{plan.name}: nothing read"
    found = []
    for k, turn in enumerate(turns):
        crossing = shapely.get_parts(turn.intersection(lines))
        if len(crossing) > 1:
            found.append(f"{plan.name}: curved arrow {k} crosses the links' lines in {len(crossing)} places")
        if turn.intersects(dots):
            found.append(f"{plan.name}: curved arrow {k} on {turn.intersection(dots).area:.3f} mm² of a dot")
        for other in turns[:k] + turns[k + 1:] + velocities:
            if turn.intersects(other):
                found.append(f"{plan.name}: curved arrow {k} on {turn.intersection(other).area:.3f} mm² of an arrow")
    return found


@pytest.fixture(scope="module", params=FIXTURES + STARTERS)
def written_plans(request, tmp_path_factory) -> list[Path]:
    return plan_sheets_of(request.param, tmp_path_factory.mktemp(request.param))


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


def test_a_short_cranks_curved_arrow_crosses_no_other_link_dot_or_arrow(written_plans, request):
    scene = request.node.callspec.params["written_plans"]
    if scene not in CRAMPED:
        pytest.skip("no cramped position drawn")
    plan = next(path for path in written_plans if path.name == CRAMPED[scene])
    assert arrows_on_other_ink(plan) == []


def test_an_arc_moved_onto_a_dot_is_found_there(written_plans):
    # The check itself: a curved arrow moved so that it passes through a point's dot is found on it.
    root = ET.parse(written_plans[0]).getroot()
    dot = next(layer(root, "mechanism-points").iter(f"{SVG}circle"))
    arc = layer(root, "mechanism-senses").findall(f"{SVG}path")[0]
    (x0, y0), *_ = _points(arc.get("d"))
    dx, dy = float(dot.get("cx")) - x0, float(dot.get("cy")) - y0
    arc.set("d", " ".join(f"{'M' if k == 0 else 'L'}{x + dx:.3f},{y + dy:.3f}"
                          for k, (x, y) in enumerate(_points(arc.get("d")))))
    dots = shapely.union_all([_ink(circle) for circle in layer(root, "mechanism-points").iter(f"{SVG}circle")])
    assert turns_with_heads(root)[0].intersects(dots)
