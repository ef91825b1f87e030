"""An extreme of the working link that falls on a numbered position keeps its number and is lettered as the other
extreme between two positions is, its points with a prime (A′, D′, E′): drawn bold with no letters, a reader could
not tell which bold outline was which end of the stroke."""

from __future__ import annotations

import cmath
import itertools
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import shapely
from drawn_lines import stroked_shapes
from scipy.optimize import brentq
from sheet_texts import box, flat, texts

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"

# The Whitworth quick-return mechanism: crank OA, slotted lever turning about C with its tail D behind C, rod DE, ram
# E on a guide through C.  With 12 positions from the first extreme, the second falls on position 9.
RADIUS, PIVOT_DROP, TAIL, ROD = 0.1, 0.05, 0.12, 0.35
WHITWORTH = f"""
[scene]
title = "Whitworth quick-return mechanism"
locale = "en"
gravity = 9.81

[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [0.0, -{PIVOT_DROP}] }}

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {RADIUS}
omega = 10.0
epsilon = 0.0

[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]

[points]
D = {{ link = 4, from = "C", toward = "A", at = -{TAIL} }}

[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["D", "E"]
length = {ROD}
guide = {{ through = [0.0, -{PIVOT_DROP}], angle = 0.0 }}
assembly = "forward"

[positions]
count = 12
start = "extreme"
working = {{ link = 6, sense = "forward" }}
plans = [2, 8]
"""


def joints(phi: float) -> dict[str, complex]:
    """A, D and E at the crank angle ``phi``, from the triangle O-C-A, the lever through C and the rod DE closing
    on the guide (E ahead of D)."""
    a = RADIUS * cmath.exp(1j * phi)
    c = -1j * PIVOT_DROP
    along = (a - c) / abs(a - c)
    d = c - TAIL * along
    rise = d.imag - c.imag
    e = complex(d.real + math.sqrt(ROD**2 - rise**2), c.imag)
    return {"A": a, "D": d, "E": e}


def ram_speed(phi: float, step: float = 1e-6) -> float:
    """dxE/dφ by a central difference: zero at the ram's extremes."""
    return (joints(phi + step)["E"].real - joints(phi - step)["E"].real) / (2 * step)


def extremes() -> tuple[float, float]:
    """The crank angles of the ram's farthest back (where the forward stroke starts) and farthest forward."""
    # Off the whole degrees: this crank's extremes fall on them, where a bracket would end on a root.
    grid = [math.radians(0.5 + degrees) for degrees in range(0, 361, 5)]
    roots = [brentq(ram_speed, low, high, xtol=1e-12) for low, high in itertools.pairwise(grid)
             if ram_speed(low) * ram_speed(high) < 0]
    back = min(roots, key=lambda phi: joints(phi)["E"].real)
    ahead = max(roots, key=lambda phi: joints(phi)["E"].real)
    return back, ahead


def frame_origin(source: str, scale: float) -> tuple[float, float]:
    """Where the scene's origin O stands on the drawing (mm): the pivot circle with C's circle PIVOT_DROP below it."""
    circles = [(float(x), float(y)) for x, y in re.findall(r'<circle cx="([-\d.]+)" cy="([-\d.]+)"', source)]
    drop = PIVOT_DROP / scale
    found = {(x, y) for x, y in circles for u, v in circles if abs(u - x) < 0.01 and abs(v - y - drop) < 0.01}
    assert len(found) == 1, found
    return found.pop()


def test_an_extreme_on_a_numbered_position_is_lettered_with_primes_and_keeps_its_number(tmp_path):
    scene = tmp_path / "whitworth.toml"
    scene.write_text(WHITWORTH, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "positions"]) == 0
    source = (tmp_path / "out" / "positions.svg").read_text(encoding="utf-8")
    written = texts(source)
    scale = float(re.search(r"μl = ([\d.]+) m/mm", flat(source)).group(1))
    ox, oy = frame_origin(source, scale)

    def paper(r: complex) -> tuple[float, float]:
        return ox + r.real / scale, oy - r.imag / scale

    def centre(text: str) -> tuple[float, float]:
        (item,) = [entry for entry in written if entry[4] == text]
        x0, y0, x1, y1 = box(*item)
        return (x0 + x1) / 2, (y0 + y1) / 2

    assert {"A′", "D′", "E′"} <= {entry[4] for entry in written}
    first, second = extremes()
    # The second extreme is a numbered position: the crank has turned a whole number of the 12 steps from the first.
    steps = ((second - first) % (2 * math.pi)) / (2 * math.pi / 12)
    assert abs(steps - round(steps)) < 1e-6
    number = str(round(steps) + 1)
    at_first, at_second = joints(first), joints(second)
    for name in ("A", "D", "E"):
        # Beside the joint where it stands at the second extreme, nearer it than the unprimed letter's joint.
        there, here = paper(at_second[name]), paper(at_first[name])
        assert math.dist(centre(f"{name}′"), there) < 10.0, name
        assert math.dist(centre(f"{name}′"), there) < math.dist(centre(f"{name}′"), here), name
    # Its number still stands at the crank pin there.
    assert math.dist(centre(number), paper(at_second["A"])) < 8.0
    boxes = [(entry[4], box(*entry)) for entry in written]
    for (one, a), (other, b) in itertools.combinations(boxes, 2):
        assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]), (one, other)


# The Scotch yoke fixture: crank r = 75 mm from its first extreme at φ = 270°, 12 positions, so position 7 is φ = 90°,
# the yoke's top extreme.  There the crank pin A and B (the slot's centre line on the vertical guide through O, at
# (0, r sin φ)) are one point, r straight above O: the number 7 and the letters A′ and B′ all name it.
YOKE_CRANK = 0.075
YOKE_TOP = "7"


def _directions(corners: tuple[float, float, float, float], at: tuple[float, float]) -> tuple[float, float]:
    """The least and greatest direction (radians, y up) from ``at`` to the corners of a box beside it."""
    x0, y0, x1, y1 = corners
    middle = math.atan2(at[1] - (y0 + y1) / 2, (x0 + x1) / 2 - at[0])
    turns = [math.remainder(math.atan2(at[1] - y, x - at[0]) - middle, math.tau)
             for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
    return middle + min(turns), middle + max(turns)


def test_the_number_and_the_primed_letters_of_one_pin_stand_each_in_its_own_direction(tmp_path):
    """A number that cannot stand on its radius (the yoke's rod runs out along it) and two primed letters all name the
    Scotch yoke's top pin: each stands clear of the others and of the lines, near the pin, and in a direction of its
    own from it, so that the leader to one never runs past another (7 and B′ stood one behind the other up to the
    left of the pin, B′'s leader passing under the 7)."""
    assert main(["run", str(ROOT / "fixtures" / "scotch_yoke.toml"), "--out", str(tmp_path / "out"),
                 "--only", "positions"]) == 0
    source = (tmp_path / "out" / "positions.svg").read_text(encoding="utf-8")
    root = ET.fromstring(source)
    scale = float(re.search(r"μl = ([\d.]+) m/mm", flat(source)).group(1))
    # The pins and the pivot O, drawn as open circles: O the one with a pin r above it and r below.
    circles = {(round(float(item.get("cx")), 2), round(float(item.get("cy")), 2)) for item in root.iter(f"{SVG}circle")
               if item.get("fill") == "white"}
    reach = YOKE_CRANK / scale
    (pivot,) = [(x, y) for x, y in circles
                if any(abs(u - x) < 0.01 and abs(v - (y - reach)) < 0.01 for u, v in circles)
                and any(abs(u - x) < 0.01 and abs(v - (y + reach)) < 0.01 for u, v in circles)]
    pin = (pivot[0], pivot[1] - reach)  # φ = 90°: straight above O (the SVG's y runs down)
    written = {entry[4]: box(*entry) for entry in texts(source) if entry[4] in (YOKE_TOP, "A′", "B′")}
    assert set(written) == {YOKE_TOP, "A′", "B′"}
    letter = max(y1 - y0 for _, y0, _, y1 in written.values())
    lines = shapely.STRtree(stroked_shapes(root, ("leaders", "labels", "caption")))
    for name, corners in written.items():
        label = shapely.box(*corners)
        assert label.distance(shapely.Point(pin)) < 4 * letter, name
        assert not len(lines.query(label, predicate="intersects")), f"{name} stands on a drawn line"
    for (one, a), (other, b) in itertools.combinations(written.items(), 2):
        assert not shapely.box(*a).intersects(shapely.box(*b)), (one, other)
        # Seen from the pin, neither stands behind the other.
        (a0, a1), (b0, b1) = _directions(a, pin), _directions(b, pin)
        apart = math.remainder((b0 + b1) / 2 - (a0 + a1) / 2, math.tau)
        assert abs(apart) > (a1 - a0) / 2 + (b1 - b0) / 2, (one, other)
    # The line from the pin to each label, as its leader runs, keeps a letter's height from the other labels.
    for name, corners in written.items():
        near = shapely.shortest_line(shapely.Point(pin), shapely.box(*corners)).coords[1]
        sight = shapely.LineString([pin, near])
        for other, theirs in written.items():
            if other != name:
                assert sight.distance(shapely.box(*theirs)) >= letter, (name, other)
