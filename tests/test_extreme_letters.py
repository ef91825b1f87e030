"""An extreme of the working link that falls on a numbered position keeps its number and is lettered as the other
extreme between two positions is, its points with a prime (A′, D′, E′): drawn bold with no letters, a reader could
not tell which bold outline was which end of the stroke."""

from __future__ import annotations

import cmath
import itertools
import math
import re

from scipy.optimize import brentq

from graphplan.cli import main
from tests.sheet_texts import box, texts

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
    scale = float(re.search(r"μl = ([\d.]+) m/mm", source).group(1))
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
