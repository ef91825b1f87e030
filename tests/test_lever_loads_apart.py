"""The lever of a student's lift (a slider-driven four-bar with friction in three pairs): its loads at one point on one
line kept apart, each name by its own arrow, and the lever drawn larger by the rule the fixtures' levers follow.

On the lever with friction of position 3 the two couples on link 4 that come from friction, Mf14 and Mf34, each put
a force at b and at e square to be, parallel to the couple Mu4's: the third of them at b was drawn 2.5 mm beside
the first, the two arrows read as one, and their names stood one above the other by either head.  G3's name stood
0.8 mm from Mu4″'s head and 2.4 mm from its own, and Mu4″'s name under G3's head.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest
import shapely
from sheet_texts import box
from test_lever_drawn_larger import crowded, drawn_scale, expected_scale

import graphplan
from graphplan.analysis import analyse
from graphplan.render import force_lever, force_marks
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet

LIFT = """
[scene]
title   = "Рычажный механизм подъёма с гидроприводом"
locale  = "ru"
gravity = 9.81

[frame]
link   = 1
points = { G = [0.0, 0.0], C = [0.45, 0.30] }
lines  = { "ось цилиндра" = { through = "G", angle = 30.0 } }

[driver]
kind         = "slider"
link         = 2
joint        = "A"
guide        = "ось цилиндра"
travel       = [0.05, 0.30]
velocity     = 0.10
acceleration = 0.0

[[groups]]
kind     = "RRR"
links    = [3, 4]
joints   = ["A", "B", "C"]
lengths  = [0.30, 0.20]
assembly = "right"

[points]
S3 = { link = 3, from = "A", toward = "B", at = 0.15 }
S4 = { link = 4, from = "C", toward = "B", at = 0.10 }
E  = { link = 4, from = "C", toward = "B", at = -0.35 }

[links.2]
mass   = 8.0
centre = "A"
[links.3]
mass    = 4.5
centre  = "S3"
inertia = 0.034
[links.4]
mass    = 16.0
centre  = "S4"
inertia = 0.35

[[loads]]
kind      = "force"
link      = 4
point     = "E"
value     = 900.0
angle     = -90.0
resisting = true
during    = "working"

[[friction]]
joint = "A"
links = [2, 1]
f     = 0.12

[[friction]]
joint  = "C"
f      = 0.1
radius = 0.02

[[friction]]
joint  = "B"
f      = 0.1
radius = 0.012

[positions]
count       = 12
number_from = 1
working     = { link = 4, sense = "ccw" }
plans       = [3, 9]
"""

SVG = "{http://www.w3.org/2000/svg}"
NUMBERS = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"
# A name 3.2 mm high stands in a box some 4.6 mm high: two parallel arrows whose heads stand level need at least
# this much between their lines (mm) for each to have its name beside its head.
PARALLEL_APART_MM = 5.0
# A name standing this much (mm) nearer another load's free end than its own reads as that load's.
NEARER_MM = 0.5


def _points(item: ET.Element) -> list[tuple[float, float]]:
    numbers = [float(value) for value in re.findall(NUMBERS, item.get("d") or item.get("points") or "")]
    return list(zip(numbers[0::2], numbers[1::2]))


def _lever(source: str):
    """The lever's load arrows by name (tail, tip), its dots, its names' boxes and its leaders' ends."""
    groups = {group.get("id"): group for group in ET.fromstring(source).iter(f"{SVG}g")}
    arrows = {}
    for group in groups["lever-forces"]:
        if group.tag == f"{SVG}g":
            shaft, head = (_points(item) for item in group)
            tip = max(head, key=lambda corner: math.dist(corner, shaft[0]))
            arrows[group.get("id").removeprefix("lever-")] = (shaft[0], tip)
    dots = [(float(dot.get("cx")), float(dot.get("cy"))) for dot in groups["lever-points"]]
    names = [("".join(text.itertext()), shapely.box(*box(float(text.get("x")), float(text.get("y")),
                                                         float(text.get("font-size")),
                                                         text.get("text-anchor", "start"), "".join(text.itertext()))))
             for text in groups["lever-labels"]]
    leaders = [_points(item) for item in groups["lever-leaders"].iter() if item.tag in (f"{SVG}path", f"{SVG}polyline")]
    return arrows, dots, names, [points for points in leaders if len(points) >= 2]


@pytest.fixture(scope="module")
def levers(tmp_path_factory) -> dict[str, str]:
    out = tmp_path_factory.mktemp("lift")
    graphplan.load_text(LIFT).write(out / "run", only=["lever"])
    return {path.name: path.read_text(encoding="utf-8") for path in (out / "run").glob("forces_*.svg")
            if not re.search(r"-\d+\.svg$", path.name)}


def _line_distance(one, other) -> float:
    """The distance between the lines of two parallel arrows (tail, tip)."""
    (x0, y0), (x1, y1) = one
    ux, uy = (x1 - x0) / math.dist(one[0], one[1]), (y1 - y0) / math.dist(one[0], one[1])
    return abs((other[0][0] - x0) * uy - (other[0][1] - y0) * ux)


def _direction(arrow) -> complex:
    (x0, y0), (x1, y1) = arrow
    return complex(x1 - x0, y1 - y0) / math.dist(arrow[0], arrow[1])


def test_the_friction_couples_forces_at_one_point_stand_apart(levers):
    arrows, _, _, _ = _lever(levers["forces_friction_3.svg"])
    for first, second in (("Mf14-1", "Mf34-1"), ("Mf14-2", "Mf34-2")):
        one, other = arrows[first], arrows[second]
        # Both couples on link 4, across the same two points: their forces at a point are parallel, of one sense.
        assert abs(_direction(one) - _direction(other)) < 1e-3
        assert _line_distance(one, other) >= PARALLEL_APART_MM, (first, second)


def test_each_load_named_beside_its_arrow_stands_nearest_its_own_free_end(levers):
    assert {"forces_3.svg", "forces_9.svg", "forces_friction_3.svg", "forces_friction_9.svg"} <= set(levers)
    for sheet, source in levers.items():
        arrows, dots, names, leaders = _lever(source)
        free_ends = {}
        for load, (tail, tip) in arrows.items():
            point = min(dots, key=lambda dot: min(math.dist(dot, tail), math.dist(dot, tip)))
            free_ends[load] = tip if math.dist(point, tip) > math.dist(point, tail) else tail
        for words, taken in names:
            own = [load for load in arrows if load.split("-")[0] == words.rstrip("′″")
                   and (words[-1] not in "′″" or load.endswith("-1" if words[-1] == "′" else "-2"))]
            if not own or own == ["Fb"]:
                continue  # a point's letter or an arm's name; Fb is drawn and named in its own colour
            if any(taken.distance(shapely.Point(points[-1])) < 1.0 for points in leaders):
                continue  # led to its arrow by a leader
            (load,) = own
            mine = taken.distance(shapely.Point(free_ends[load]))
            for other, end in free_ends.items():
                if other not in (load, "Fb"):
                    assert taken.distance(shapely.Point(end)) >= mine - NEARER_MM, (sheet, words, other)


def test_the_lift_levers_are_drawn_larger_by_the_fixtures_rule():
    # Position 3's plan: its nearest points (a, b and s3) 19.2 mm apart, no closer than 15 mm: drawn at the plan's
    # μV without friction, with 3 + 2 loads at a and s3; with friction, 5 + 2 there want 21 mm and it is drawn larger.
    # Position 9's: a and s3 6.9 mm apart: drawn at the standard μV whose longest ray is at most 250 mm.
    analysis = analyse(graphplan.load_text(LIFT))
    found = {}
    for position in analysis.plans:
        for friction in (False, True):
            lever = position.lever_with_friction if friction else position.lever
            scale, _ = drawn_scale(force_layout.layout(force_sheet(analysis, position, friction)), position.velocity)
            assert scale == pytest.approx(expected_scale(position.velocity, lever), rel=1e-12)
            found[position.number, friction] = (crowded(position.velocity), crowded(position.velocity, lever),
                                                scale < position.velocity.scale)
    assert found == {(3, False): (False, False, False), (3, True): (False, True, True),
                     (9, False): (True, True, True), (9, True): (True, True, True)}


# Two points of the lever need this much room between them (mm) for each load arrow drawn at either.
ROOM_PER_LOAD_MM = 3.0


def test_the_friction_lever_whose_points_crowd_with_loads_is_drawn_larger_than_the_15_mm_rule_gives(levers):
    """Position 3's lever with friction: 18 loads at points no closer than 19.2 mm on the plan, which the 15 mm rule
    alone left at the plan's size, the arrows and names at a, b and s3 running together.  Read off the drawing: its
    points stand farther apart than the plan's, and every two of them as far as 3 mm for each arrow drawn at either."""
    analysis = analyse(graphplan.load_text(LIFT))
    position = next(position for position in analysis.plans if position.number == 3)
    velocity = position.velocity
    on_plan = [value / velocity.scale for value in velocity.points.values()]
    closest_on_plan = min(abs(a - b) for i, a in enumerate(on_plan) for b in on_plan[i + 1:] if abs(a - b) > 0.25)
    assert closest_on_plan >= 15.0
    arrows, dots, _, _ = _lever(levers["forces_friction_3.svg"])
    at = [0] * len(dots)
    for tail, tip in arrows.values():
        at[min(range(len(dots)), key=lambda k: min(math.dist(dots[k], tail), math.dist(dots[k], tip)))] += 1
    assert sum(at) >= 18
    apart = [(math.dist(dots[i], dots[j]), at[i] + at[j]) for i in range(len(dots)) for j in range(i + 1, len(dots))]
    nearest = min(distance for distance, _ in apart)
    assert nearest > closest_on_plan * 1.5
    for distance, count in apart:
        assert distance >= ROOM_PER_LOAD_MM * count, (distance, count)


def test_a_load_set_beside_stands_nearer_where_the_wider_side_is_taken():
    """Beside a load drawn before along its line, a load stands LEVER_BESIDE_MM off where that is clear, else
    BESIDE_MM off on the same side, rather than beyond the first on its line."""
    from shapely.geometry import LineString

    from graphplan.render.primitives import Arrow

    image, load = complex(-1.0, 5.0), complex(0.0, -10.0)
    first = [Arrow((-1.0, 5.0), (-1.0, -5.0))]  # drawn before from the same image down the same line
    taken = LineString(((-1.0, 5.0), (-1.0, 20.0))).buffer(0.8)  # the line's other side, an arm there
    _, _, shift = force_lever._pushing_or_pulling(image, load, first, lambda: taken)
    assert shift == pytest.approx(-force_lever.LEVER_BESIDE_MM)  # on the pole's side of its line, x < −1
    # A load drawn before 6 mm off on that side too: the second stands between them, 2.5 mm off.
    wider = [*first, Arrow((-1.0 - force_lever.LEVER_BESIDE_MM, 5.0), (-1.0 - force_lever.LEVER_BESIDE_MM, -5.0))]
    start, end, shift = force_lever._pushing_or_pulling(image, load, wider, lambda: taken)
    assert shift == pytest.approx(-force_marks.BESIDE_MM)
    assert (start, end) == (pytest.approx(image + shift), pytest.approx(image + load + shift))
