"""On a plan sheet's mechanism no point's letter is led across another link's line where a spot near it keeps off.

The triad's crank at position 8 lies under its coupler, which passes just above the crank's pivot O: O's letter
stood above the coupler on a short leader across it, its box clear of every line, and read as naming a point of the
coupler.  The placer weighed a leader across a link as across any line (the ω arc beside the pivot, the pivot's own
pin, which every leader from O starts inside), and a label whose box covered nothing was never looked at again.  A
link's line is now weighed as an arrow's shaft is (``place_labels``' ``shafts``): crossed only where nothing nearer
is clear (its own link's lines as any line); O stands below its pivot's hatching.

The leaders and the links' lines are read back from the plan_N.svg a run writes: the points' leaders are the black
paths of the mechanism's leaders layer (an ω's or ε's is in its colour), the links' lines the unfilled paths of its
links layer, as wide as each is drawn.  A leader may cross the lines of its point's own link (the point on the line,
or inside the link's closed outline: the triad with a slider's S6 inside its triangular link, lettered outside it):
it still names a point of that link.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely
from drawn_lines import SVG, layer, path_points, stroked_path
from light_runs import plan_sheets_of

# The triads, whose crank lies under the coupler at position 8, and starters whose letters stood clear of the links.
FIXTURES = ["triad_class_iii", "triad_with_slider"]
STARTERS = ["triad", "crank-rocker", "slider-crank"]


# A leader starts this far from its point (labels.py's LEADER_CLEARANCE), on the line to its label.
LEADER_CLEARANCE_MM = 0.9
# A point lies on a link's line when within this (mm) of its ink: the SVG writes its numbers to 0.001 mm.
ON_THE_LINE_MM = 0.01


def point_leaders(root: ET.Element) -> list[tuple[tuple[float, float], shapely.LineString]]:
    """The points' letters' leaders (the black ones: an ω's or ε's is in its colour), each with the point it leads
    from: back along it by the clearance it starts off its point."""
    found = []
    for path in layer(root, "mechanism-leaders").iter(f"{SVG}path"):
        if path.get("stroke") != "black":
            continue
        (x0, y0), (x1, y1) = path_points(path)[:2]
        length = max(((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5, 1e-9)
        point = (x0 - (x1 - x0) / length * LEADER_CLEARANCE_MM, y0 - (y1 - y0) / length * LEADER_CLEARANCE_MM)
        found.append((point, shapely.LineString([(x0, y0), (x1, y1)])))
    return found


def links(root: ET.Element) -> list[tuple[shapely.Geometry, shapely.Geometry]]:
    """Each link's lines as inked (the unfilled paths of the links' layer: their pins are circles, blocks filled), and
    what of the paper is the link's: its ink and, outlined closed, the inside of its outline."""
    found = []
    for path in layer(root, "mechanism-links").iter(f"{SVG}path"):
        points = path_points(path)
        if path.get("fill", "none") != "none" or len(points) < 2:
            continue
        ink = stroked_path(path)
        inside = shapely.Polygon(points) if len(points) > 3 and points[0] == points[-1] else shapely.Polygon()
        found.append((ink, shapely.union(ink.buffer(ON_THE_LINE_MM), inside)))
    return found


def leaders_across_links(plan: Path) -> list[str]:
    """Where a point's letter is led across the line of a link the point is not on (nor inside the outline of): a
    leader across its own link's line still names a point of that link (a centre of mass inside a triangular link)."""
    root = ET.parse(plan).getroot()
    drawn = links(root)
    assert drawn, f"{plan.name}: no link's line read"
    return [f"{plan.name}: the leader from the point at {point} crosses a link's line"
            for point, leader in point_leaders(root)
            if any(leader.intersects(ink) and not own.contains(shapely.Point(point)) for ink, own in drawn)]


@pytest.fixture(scope="module", params=FIXTURES + STARTERS)
def written_plans(request, tmp_path_factory) -> list[Path]:
    return plan_sheets_of(request.param, tmp_path_factory.mktemp(request.param))


def test_no_letter_on_a_mechanism_is_led_across_a_links_line(written_plans):
    assert [found for plan in written_plans for found in leaders_across_links(plan)] == []


def test_a_leader_laid_across_a_link_is_found(written_plans):
    # The check itself: a point's leader moved to run across the middle of a link's line, from a point off every link,
    # is found crossing it.
    plan = written_plans[0]
    root = ET.parse(plan).getroot()
    link = next(path for path in layer(root, "mechanism-links").iter(f"{SVG}path")
                if path.get("fill", "none") == "none" and len(path_points(path)) == 2)  # a bar: no inside
    (x0, y0), (x1, y1) = path_points(link)[:2]
    middle, length = ((x0 + x1) / 2, (y0 + y1) / 2), ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5
    across = ((y0 - y1) / length, (x1 - x0) / length)
    start, end = ((middle[0] + k * across[0], middle[1] + k * across[1]) for k in (-2.0, 2.0))
    leader = ET.SubElement(layer(root, "mechanism-leaders"), f"{SVG}path", stroke="black")
    leader.set("d", f"M{start[0]:.3f},{start[1]:.3f} L{end[0]:.3f},{end[1]:.3f}")
    plan = plan.with_name("laid_" + plan.name)
    ET.ElementTree(root).write(plan)
    assert leaders_across_links(plan)
