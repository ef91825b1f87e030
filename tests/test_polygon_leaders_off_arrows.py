"""A force polygon's name led out to a clear spot crosses no other vector's arrow, nor stops short of one.

A leader stops 0.3 mm short of its label's box, and the placer tested only the leader as drawn against the arrows: an
arrow passing through that gap, between the leader's end and the letters, went unseen, and to a reader the leader
runs across it.  On the ratchet crank-rocker's polygon of position 11 Fu3 was so led across R23n's arrow, and on the
triad with a slider's of position 8 R15 across R65's.  The placer now tests a leader run on to its box against the
arrows' shafts; a name led out from another stretch of its side is also tried on the short leaders there, not only
on the long ones.

Read here as a reader meets it: the SVG the run writes, each leader of a polygon's ``-leaders`` group, run on to its
label's box, against the shaft and head of every vector's arrow in its ``-vectors`` group but its own label's.
"""

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
import shapely
from shapely.geometry import LineString, Point, Polygon
from shapely.ops import substring

import graphplan
from graphplan import cli
from graphplan.locale import load_symbol, strings
from graphplan.render.primitives import svg_id, text_width
from graphplan.render.svg import FONT_SIZE_PER_CAP

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
# Names led across another vector's arrow at the commit this work started from.  (In a sliver of sides side by side,
# the slider driven mechanism's polygon of position 3, a side's name between two others has no spot that is not.)
NAMES = [("ratchet_crank_rocker", 11, "polygon-II-3-4", "Fu3"), ("triad_with_slider", 8, "polygon-III-3-4-5-6", "R15")]
# A leader starts 0.9 mm off its point, and an arrow met within this of its start is where it begins (its own side,
# or the corner its side starts at), not crossed.  It stops 0.3 mm short of its label's box.
END_MM = 0.3
GAP_MM = 0.3


def group(root, name: str):
    (found,) = [element for element in root.iter(f"{SVG}g") if element.get("id") == name]
    return found


def shapes(element) -> list:
    """The paths under ``element`` (y down): a closed one (an arrowhead) as its polygon, any other as its line."""
    found = []
    for path in element.iter(f"{SVG}path"):
        d = path.get("d")
        points = [tuple(map(float, pair.split(","))) for pair in re.findall(r"-?[\d.]+,-?[\d.]+", d)]
        if len(points) >= 3 and d.rstrip().endswith("Z"):
            found.append(Polygon(points))
        elif len(points) >= 2:
            found.append(LineString(points))
    return found


def text_boxes(element) -> list[tuple[str, object]]:
    """Each text under ``element`` and its box, as graphplan sets a text: its width measured, from 0.3 letter heights
    below its baseline to 1.15 above."""
    boxes = []
    for text in element.iter(f"{SVG}text"):
        words = "".join(text.itertext())
        size = float(text.get("font-size")) / FONT_SIZE_PER_CAP
        width = text_width(words, size)
        x, y = float(text.get("x")), float(text.get("y"))
        x0 = x + {"start": 0.0, "middle": -width / 2, "end": -width}[text.get("text-anchor", "start")]
        boxes.append((words, shapely.box(x0, y - 1.15 * size, x0 + width, y + 0.3 * size)))
    return boxes


def crossings(root, prefix: str, text=None) -> list[tuple[str, str]]:
    """(a label, the arrow's id) for each leader of the drawing ``prefix`` that crosses another vector's arrow; a label
    as the locale ``text`` writes a load's name (the Russian Fи3), its arrow's id by the name inside (Fu3)."""
    text = text or strings("en")
    arrows = {element.get("id"): shapely.union_all(shapes(element))
              for element in group(root, f"{prefix}-vectors") if element.tag == f"{SVG}g"}
    labels = text_boxes(group(root, f"{prefix}-labels"))
    found = []
    for leader in shapes(group(root, f"{prefix}-leaders")):
        # Its label: the one whose box its far end stops by.
        name, _ = min(labels, key=lambda label: label[1].distance(Point(leader.coords[-1])))
        if leader.length <= END_MM:
            continue
        # From past its start to its label's box, over the gap it stops short by.
        (x0, y0), (x1, y1) = leader.coords[0], leader.coords[-1]
        inner = LineString((substring(leader, END_MM, leader.length).coords[0],
                            (x1 + (x1 - x0) / leader.length * GAP_MM, y1 + (y1 - y0) / leader.length * GAP_MM)))
        found += [(name, key) for key, arrow in arrows.items()
                  if load_symbol(key.removeprefix(f"{prefix}-"), text) != name and key != f"{prefix}-{svg_id(name)}"
                  and inner.intersects(arrow)]
    return found


@pytest.mark.parametrize("leader_end", [11.0, 4.8])
def test_the_check_sees_a_leader_across_another_arrow_and_not_one_from_its_own(leader_end):
    # R1's leader runs down from its shaft past R2's (11.0), or stops 0.2 mm short of it, R2's arrow passing between
    # the leader's end and R1's letters (4.8).
    top = leader_end + GAP_MM + 1.15 * 4.444 / FONT_SIZE_PER_CAP
    drawing = f"""<svg xmlns="http://www.w3.org/2000/svg">
    <g id="p-vectors"><g id="p-R1"><path d="M0,0 L20,0" /><path d="M20,0 L17,0.5 L17.4,0 L17,-0.5 Z" /></g>
    <g id="p-R2"><path d="M0,5 L20,5" /><path d="M20,5 L17,5.5 L17.4,5 L17,4.5 Z" /></g></g>
    <g id="p-leaders"><path d="M9,5.9 L6,9" /><path d="M12,0.9 L12,{leader_end}" /></g>
    <g id="p-labels"><text font-size="4.444" text-anchor="middle" x="4" y="13.5">R2</text>
    <text font-size="4.444" text-anchor="middle" x="14" y="{top}">R1</text></g></svg>"""
    root = ElementTree.fromstring(drawing)
    # R2's leader leaves its own arrow and meets nothing; R1's crosses R2's.
    assert crossings(root, "p") == [("R1", "p-R2")]


@pytest.mark.parametrize(("fixture", "number", "prefix", "name"), NAMES)
def test_the_name_s_leader_crosses_no_other_vector_s_arrow(tmp_path, fixture, number, prefix, name):
    out = tmp_path / fixture
    assert cli.main(["run", str(ROOT / "fixtures" / f"{fixture}.toml"), "--out", str(out),
                     "--only", "forces", "--sheet", "none"]) == 0
    root = ElementTree.parse(out / f"forces_{number}.svg").getroot()
    text = strings(graphplan.load(ROOT / "fixtures" / f"{fixture}.toml").locale)
    arrow = shapely.union_all(shapes(group(root, f"{prefix}-{svg_id(name)}")))
    name = load_symbol(name, text)  # drawn as the locale writes it: the Russian ratchet's Fи3
    # Still by its own arrow: beside it, or on a leader that starts by it.
    (box,) = [box for words, box in text_boxes(group(root, f"{prefix}-labels")) if words == name]
    led = [leader for leader in shapes(group(root, f"{prefix}-leaders"))
           if box.distance(Point(leader.coords[-1])) <= GAP_MM + 0.05]
    assert (all(Point(leader.coords[0]).distance(arrow) <= 0.9 + 1e-3 for leader in led) if led
            else box.distance(arrow) <= 2.5)
    assert [found for found in crossings(root, prefix, text) if found[0] == name] == []
