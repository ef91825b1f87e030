"""A load's name on a group cut free that finds no clear spot near its arrow's head is led out from the arrow's shaft.

On the triad with a slider's force sheets of positions 3 and 8 the name Fu6 (the inertia load of link 6) lay on a
drawn line: at 3 on Fu6's own line of action run on to its arm, at 8 on Mu6's arc, and every leader from the
arrow's head to a clear spot crossed another name (Mu6, h6, S6 crowd it).  The groups cut free kept such a name where
it lay (``reach_farther=False``); they now reach farther like the plans, and a name reaching farther that names a
line (a load's arrow, ``Anchor.along``) may be led from any point of it, as a draughtsman names a crowded arrow by a
leader from its shaft.

Read here as a reader meets it: the SVG the run writes, its paths and circles the lines, a text's box from its
place, size and anchor; and over every fixture, the bench's own count of labels on lines (``bench/label_clutter.py``).
"""

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
import shapely
from label_bench import label_clutter
from shapely.geometry import LineString, Point, Polygon

from graphplan import cli
from graphplan.render import labels
from graphplan.render.primitives import text_width
from graphplan.render.svg import FONT_SIZE_PER_CAP

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = sorted(path.stem for path in (ROOT / "fixtures").glob("*.toml"))
SVG = "{http://www.w3.org/2000/svg}"
# A circle smaller than this (radius, mm) is a point's dot or a pin, not a line a label lies on (the bench's rule).
DOT_RADIUS = 1.5
# A leader ends 0.3 mm short of its own label's box (labels.py draws it so).
OWN_LEADER_MM = 0.35
GROUP = "III-3-4-5-6"


def svg_lines(root, only: str | None = None) -> list[tuple[str, object]]:
    """Every drawn line of an SVG (y down), or of one of its groups (``only``: the group's own lines, named so), with
    the id of its layer: each path (a closed one, a filled arrowhead or block, as its outline) and each circle's
    outline but a point's dot."""
    lines = []
    for layer in [root] if only else root.iter(f"{SVG}g"):
        for element in layer:
            items = [element] if element.tag != f"{SVG}g" else list(element)  # an arrow: its shaft and its head
            for item in items:
                if item.tag == f"{SVG}path":
                    points = [tuple(map(float, pair.split(","))) for pair in re.findall(r"-?[\d.]+,-?[\d.]+",
                                                                                        item.get("d"))]
                    if len(points) < 2:
                        continue
                    closed = item.get("d").rstrip().endswith("Z")
                    lines.append((only or layer.get("id"), Polygon(points).boundary if closed and len(points) > 2
                                  else LineString(points)))
                elif item.tag == f"{SVG}circle" and float(item.get("r")) >= DOT_RADIUS:
                    centre = Point(float(item.get("cx")), float(item.get("cy")))
                    lines.append((only or layer.get("id"), centre.buffer(float(item.get("r"))).boundary))
    return lines


def svg_text_boxes(root, text: str) -> list[object]:
    """The boxes (y down) of the texts ``text`` in an SVG, as graphplan sets a text: its width measured, from 0.3
    letter heights below its baseline to 1.15 above."""
    boxes = []
    for element in root.iter(f"{SVG}text"):
        if "".join(element.itertext()) != text:
            continue
        size = float(element.get("font-size")) / FONT_SIZE_PER_CAP
        width = text_width(text, size)
        x, y = float(element.get("x")), float(element.get("y"))
        x0 = x + {"start": 0.0, "middle": -width / 2, "end": -width}[element.get("text-anchor", "start")]
        boxes.append(shapely.box(x0, y - 1.15 * size, x0 + width, y + 0.3 * size))
    return boxes


@pytest.fixture(scope="module")
def force_sheets(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("triad_with_slider") / "out"
    code = cli.main(["run", str(ROOT / "fixtures" / "triad_with_slider.toml"), "--out", str(out),
                     "--only", "forces", "--sheet", "none"])
    assert code == 0
    return out


@pytest.mark.parametrize("position", [3, 8])
def test_fu6_on_the_triad_with_a_slider_s_force_sheet_lies_on_no_drawn_line(force_sheets, position):
    root = ElementTree.parse(force_sheets / f"forces_{position}.svg").getroot()
    (box,) = svg_text_boxes(layer_of(root, f"body-{GROUP}-labels"), "Fu6")
    lines = svg_lines(root)
    # Its own leader, if any, ends by its box; every other line, leaders of other labels among them, is a line.
    crossing = [layer for layer, line in lines if box.intersects(line)
                and not (layer.endswith("-leaders") and box.distance(Point(line.coords[-1])) <= OWN_LEADER_MM)]
    assert crossing == []
    # Still tied to its arrow: beside it, or on a leader that starts by it (at its head or on its shaft).
    arrow = shapely.union_all([line for _, line in svg_lines(layer_of(root, f"body-{GROUP}-Fu6"), "arrow")])
    leaders = [line for layer, line in lines if layer.endswith("-leaders")
               and box.distance(Point(line.coords[-1])) <= OWN_LEADER_MM]
    beside = box.distance(arrow) <= labels.LABEL_GAP_MM + max(labels.BESIDE_SHARES) * 3.2 + 0.5
    led = any(Point(leader.coords[0]).distance(arrow) <= labels.LEADER_CLEARANCE + 1e-3 for leader in leaders)
    assert beside or led


@pytest.mark.parametrize("position", [3, 8])
def test_s6_within_mu6_s_arc_lies_on_no_drawn_line_and_is_tied_to_its_dot(force_sheets, position):
    """S6, the centre of mass Mu6's arc turns about, lay on that arc at position 8 once the class III group's arm h
    was drawn through the arc's open quarter, where S6 had stood: a point's name kept its place.  The name of a point
    an arc rings now reaches farther, on a leader from its dot."""
    root = ElementTree.parse(force_sheets / f"forces_{position}.svg").getroot()
    (box,) = svg_text_boxes(layer_of(root, f"body-{GROUP}-labels"), "S6")
    lines = svg_lines(root)
    own = [line for layer, line in lines if layer.endswith("-leaders")
           and box.distance(Point(line.coords[-1])) <= OWN_LEADER_MM]
    crossing = [layer for layer, line in lines if box.intersects(line) and line not in own]
    assert crossing == []
    # S6's dot: the centre of Mu6's arc (of the group's arcs, the one Mu6's name stands by).
    (mu6,) = svg_text_boxes(layer_of(root, f"body-{GROUP}-labels"), "Mu6")
    arcs = [line for _, line in svg_lines(layer_of(root, f"body-{GROUP}-moments"), "moments")
            if not line.is_closed]
    dot = _centre_of(min(arcs, key=mu6.distance))
    beside = box.distance(dot) <= labels.LABEL_GAP_MM + 4.0
    led = any(Point(leader.coords[0]).distance(dot) <= labels.LEADER_CLEARANCE + 1.0 for leader in own)
    assert beside or led, (box.bounds, dot)


def _centre_of(arc) -> Point:
    """The centre of the circle through the first, middle and last points of ``arc`` (its points in order)."""
    (ax, ay), (bx, by), (cx, cy) = (arc.coords[0], arc.coords[len(arc.coords) // 2], arc.coords[-1])
    d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    return Point(ux, uy)


def layer_of(root, name: str):
    """The group of the SVG with the id ``name``."""
    (found,) = [element for element in root.iter(f"{SVG}g") if element.get("id") == name]
    return found


@pytest.mark.parametrize("fixture", FIXTURES)
def test_no_label_of_any_fixture_lies_on_a_line_by_the_bench_s_count(tmp_path, fixture):
    # The bench's own count (every placement a run draws, English, no sheets): at the start Fu6 alone lay on lines,
    # twice; now no placement of any fixture leaves one there, nor one label on another.
    bench = label_clutter()
    clutter = bench.run_fixture(ROOT / "fixtures" / f"{fixture}.toml", "en", labels.place_labels, tmp_path / "out")
    assert (clutter.on_line, clutter.overlapping) == (0, 0)
