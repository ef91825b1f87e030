"""The knee-lever press of the student probe: its Zhukovsky lever at the knee's dead centre, where the points of the
lever crowd round the pole, and its note's two signed moments, Mb and the plans' Mr, each with its sign convention."""

from __future__ import annotations

import json
import math
import re
import tomllib
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import shapely
from sheet_texts import box, flat
from test_student_probe_2 import KNEE_PRESS

import graphplan
from graphplan.locale import load_symbol, strings

SVG = "{http://www.w3.org/2000/svg}"
NUMBERS = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"
# A head or shaft this near another point's dot (mm, centre to shaft) reads as a load at that point: a dot is 1 mm
# across, an arrowhead 1 mm wide.
NEAR_ANOTHER_POINT_MM = 1.5


def _path_points(item: ET.Element) -> list[tuple[float, float]]:
    numbers = [float(value) for value in re.findall(NUMBERS, item.get("d"))]
    return list(zip(numbers[0::2], numbers[1::2]))


def _lever(source: str) -> tuple[dict[str, tuple[tuple[float, float], tuple[float, float], shapely.Geometry]],
                                 list[tuple[float, float]], list[tuple[str, shapely.Geometry]]]:
    """The lever's load arrows by name (tail, tip, their ink), its points' dots, and its labels' boxes."""
    groups = {group.get("id"): group for group in ET.fromstring(source).iter(f"{SVG}g")}
    arrows = {}
    for group in groups["lever-forces"]:
        if group.tag != f"{SVG}g":
            continue   # a thin leader tying an arrow set beside its line to its point
        shaft, head = (_path_points(item) for item in group)
        tip = max(head, key=lambda corner: math.dist(corner, shaft[0]))
        ink = shapely.union_all([shapely.LineString(shaft).buffer(0.225), shapely.Polygon(head)])
        arrows[group.get("id").removeprefix("lever-")] = (shaft[0], tip, ink)
    dots = [(float(dot.get("cx")), float(dot.get("cy"))) for dot in groups["lever-points"]]
    labels = []
    for text in groups["lever-labels"]:
        words = "".join(text.itertext())
        labels.append((words, shapely.box(*box(float(text.get("x")), float(text.get("y")),
                                               float(text.get("font-size")), text.get("text-anchor", "start"), words))))
    return arrows, dots, labels


@pytest.fixture(scope="module")
def levers(tmp_path_factory) -> dict[str, str]:
    out = tmp_path_factory.mktemp("press")
    graphplan.load_text(KNEE_PRESS).write(out / "run", only=["lever"])
    return {path.name: path.read_text(encoding="utf-8") for path in (out / "run").glob("forces_*.svg")
            if not re.search(r"-\d+\.svg$", path.name)}


def test_no_load_arrow_on_the_press_lever_passes_over_another_point(levers):
    """At position 6 Fu4, drawn from s4 toward s5 8.6 mm away, ended with its head 1.1 mm from s5's dot and on G5's
    tail: a reader took it for a load at s5.  Every arrow now passes the other points well clear, pushing onto its
    own point where pulling from it would reach another; and no two labels of the lever cover one another or
    another load's arrow."""
    assert {"forces_5.svg", "forces_6.svg", "forces_friction_5.svg", "forces_friction_6.svg"} <= set(levers)
    for name, source in levers.items():
        arrows, dots, labels = _lever(source)
        for load, (tail, tip, _) in arrows.items():
            own = min(dots, key=lambda dot: min(math.dist(dot, tail), math.dist(dot, tip)))
            shaft = shapely.LineString([tail, tip])
            for dot in dots:
                if dot != own:
                    assert shaft.distance(shapely.Point(dot)) >= NEAR_ANOTHER_POINT_MM, (name, load, dot)
        for k, (words, taken) in enumerate(labels):
            assert not any(taken.intersects(other) for _, other in labels[k + 1:]), (name, words)
            for load, (_, _, ink) in arrows.items():
                # A couple's two forces (Mu3-1, Mu3-2) are named Mu3′ and Mu3″.
                if load.split("-")[0] != words.rstrip("′″"):
                    assert not taken.intersects(ink), (name, words, load)



# A name standing this much (mm) nearer another load's free end than its own reads as that load's; led to its
# arrow by a leader, it does where that free end stands by the name, this near.
NEARER_MM = 0.5
BY_THE_NAME_MM = 2.5


def _own_load(words: str, arrows: dict) -> str | None:
    """The arrow a load's name names (a couple's two forces Mu3-1, Mu3-2 named Mu3′ and Mu3″); None for a point's
    letter or an arm's name."""
    own = [load for load in arrows if load.split("-")[0] == words.rstrip("′″")
           and (words[-1] not in "′″" or load.endswith("-1" if words[-1] == "′" else "-2"))]
    return own[0] if len(own) == 1 else None


def _leaders(source: str) -> list[list[tuple[float, float]]]:
    groups = {group.get("id"): group for group in ET.fromstring(source).iter(f"{SVG}g")}
    return [_path_points(item) for item in groups["lever-leaders"].iter() if item.tag == f"{SVG}path"]


def test_every_load_name_on_the_press_lever_stands_nearest_its_own_arrow_led_or_not(levers):
    """On the lever with friction of position 5 Fu6's name, led by a short leader from its tail, stood 1.9 mm from
    Ff16's head and 6.9 mm from its own tail, and its leader ran to that head: it read as Ff16's name (and Mu5′ at
    position 6, 1.6 mm from G2's head).  A name stands no nearer another load's free end than its own (less a hair), a
    leader from its arrow excusing that only where the other free end is not by the name; or it is given under the
    lever."""
    for name, source in levers.items():
        arrows, dots, labels = _lever(source)
        leaders = _leaders(source)
        # An arrow's ends that stand off the lever's points: a free end, or both ends of one drawn beside its point.
        free_ends = {load: [end for end in (tail, tip) if min(math.dist(end, dot) for dot in dots) > 1.0]
                     for load, (tail, tip, _) in arrows.items()}
        for words, taken in labels:
            load = _own_load(words, arrows)
            if load is None or load == "Fb":
                continue  # a point's letter or an arm's name; Fb is drawn and named in its own colour
            tail, tip, _ = arrows[load]
            mine = min(taken.distance(shapely.Point(end)) for end in (tail, tip))
            led = any(min(math.dist(points[0], end) for end in (tail, tip)) <= 1.0
                      and taken.distance(shapely.LineString(points)) < 3.0 for points in leaders)
            for other, ends in free_ends.items():
                for end in ends if other not in (load, "Fb") else ():
                    apart = taken.distance(shapely.Point(end))
                    assert apart >= mine - NEARER_MM or (led and apart >= BY_THE_NAME_MM), (name, words, other)
    # Fu6's arrow is named all the same: on the lever, or under it as the arrow at d left unnamed ("d 处的 Fu6").
    _, _, labels = _lever(levers["forces_friction_5.svg"])
    assert ("Fu6" in [words for words, _ in labels]
            or re.search(r"d\s*(?:<[^>]*>\s*)*处的\s*(?:<[^>]*>\s*)*Fu6", flat(levers["forces_friction_5.svg"])))


# The convention stated beside Mb, and beside the plans' Mr, in each language (as the textbooks of each put it).
MB_CONVENTION = {"en": "(Mb counter-clockwise positive)",
                 "ru": "(Mу: положительное направление — против часовой стрелки)", "zh": "（Mb 以逆时针为正）"}
MR_CONVENTION = {"en": "positive where they drive, negative where they resist",
                 "ru": "положителен там, где силы движущие, и отрицателен там, где они сопротивляются",
                 "zh": "载荷起驱动作用处为正，起阻力作用处为负"}
# The column is the loads' moment signed as their power: Mr, the resisting moment of the equation of motion
# (Md − Mr, positive where the loads resist), with its sign turned.
MR_SYMBOL = {"en": "−Mr", "ru": "−Mс", "zh": "−Mr"}
MR_RESISTING = {"en": "Mr itself", "ru": "Сам момент сопротивления Mс", "zh": "等效阻力矩 Mr 本身"}


def _number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def _powers(results: dict, scene: dict, number: int, press: float) -> tuple[float, float, float]:
    """At position ``number``: the driver's ω, the power of the loads and the weights, and that of the inertia loads
    (W), from the motion results.json gives, the scene's masses and the press force ``press`` (N, up, at D)."""
    position = next(item for item in results["positions"] if item["index"] == number)
    points, links = position["points"], position["links"]
    gravity = scene["scene"]["gravity"]
    loads = inertia = 0.0
    for link, data in scene["links"].items():
        v, a = np.array(points[data["centre"]]["v"]), np.array(points[data["centre"]]["a"])
        loads += data["mass"] * -gravity * v[1]
        turning = links[link]["epsilon"] * links[link]["omega"]
        inertia += -data["mass"] * float(a @ v) - data.get("inertia", 0.0) * turning
    loads += press * points["D"]["v"][1]
    return position["driver"]["omega"], loads, inertia


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_press_note_gives_mb_and_mr_each_with_its_sign_convention(tmp_path, locale):
    """Mb = −353.5 N·m and the plans' Mr = −358.1 N·m at position 5 were written alike: one is counter-clockwise
    positive, the other signed by the loads' power, and the crank turns clockwise, so that the one drives and the
    other resists.  The note says which where it gives each, and the values keep what it says: Mb·ω1 + ΣP = 0 with
    every load's power (the inertia loads' too), Mr·|ω1| the power of the loads and the weights."""
    text = re.sub(r'locale = "zh"', f'locale = "{locale}"', KNEE_PRESS)
    text = text.replace("[drawing]\n", "[drawing]\nlength_scale = 0.005\n") + "[dynamics]\ndelta = 0.05\n"
    graphplan.load_text(text).write(tmp_path / "run", only=["note"])
    note = (tmp_path / "run" / "note.md").read_text(encoding="utf-8")
    results = json.loads((tmp_path / "run" / "results.json").read_text(encoding="utf-8"))
    scene = tomllib.loads(text)
    # The press force at the plan positions 5 and 6, from the ram's share of its down-stroke on the scene's diagram.
    motion = graphplan.solve(graphplan.load_text(text), driver=np.radians(np.arange(0.0, 360.0, 0.01)))
    top, bottom = motion.point("D").r[:, 1].max(), motion.point("D").r[:, 1].min()
    mark = r"(−?[\d.,]+)"
    lines = note.splitlines()
    header = next(at for at, line in enumerate(lines) if line.startswith("| ") and f"{MR_SYMBOL[locale]}, " in line)
    for number in (5, 6):
        position = next(item for item in results["positions"] if item["index"] == number)
        share = (top - position["points"]["D"]["r"][1]) / (top - bottom)
        press = float(np.interp(share, *zip(*scene["loads"][0]["diagram"])))
        omega, loads, inertia = _powers(results, scene, number, press)
        mb = position["equilibrium"]["balancing_moment"]
        assert omega < 0   # the crank turns clockwise
        assert math.isclose(mb * omega + loads + inertia, 0.0, abs_tol=1e-6 * abs(loads))
        # Counter-clockwise positive: the press resists, and the moment that drives the clockwise crank is negative.
        assert loads < 0 and mb < 0
        written = [line for line in lines if MB_CONVENTION[locale] in line]
        symbol = load_symbol("Mb", strings(locale))  # the Russian note's Mу
        assert any(math.isclose(_number(found), mb, rel_tol=1e-5)
                   for line in written for found in re.findall(symbol + " = " + mark, line)), number
        # Signed by the loads' power: negative where they resist, whichever way the crank turns.
        row = next(line for line in lines[header:] if line.startswith(f"| {number} |"))
        mr = _number(row.split("|")[6].strip())
        assert math.isclose(mr, loads / abs(omega), rel_tol=1e-4) and mr < 0
    paragraph = "\n".join(lines[header:]).split("\n\n")[1]
    assert paragraph.startswith(MR_SYMBOL[locale]) and MR_CONVENTION[locale] in paragraph
    assert MR_RESISTING[locale] in paragraph  # and says which way Mr itself is positive
    # And the table of Mb at every position says it too.
    assert any(line.startswith(("Table", "Таблица", "表")) and MB_CONVENTION[locale].strip("()（）") in line
               for line in lines)
