"""The positions' numbers round the crank's circle on the plan of positions: clear of one another, outside the circle.

Read from the drawn texts: with many positions on a small crank the numbers ran together ("34" over "33"
read "3433") and the labeller put half of them inside the circle among the spokes.
"""

import cmath
import itertools
import math
import re
from pathlib import Path

import pytest
from shapely.geometry import Point

from graphplan.analysis import analyse
from graphplan.render import positions
from graphplan.render.drawings import positions_plan
from graphplan.render.labels import obstacles_of, text_box
from graphplan.render.primitives import Text
from graphplan.scene import loads

RATCHET = Path("fixtures/ratchet_crank_rocker.toml").read_text()
NUMBER = re.compile(r"^\d+′?$")


def _ratchet(count: int, length_scale: float):
    text = RATCHET.replace("count       = 12", f"count       = {count}")
    text = text.replace("length_scale      = 0.0025", f"length_scale      = {length_scale}")
    return analyse(loads(text))


CASES = [(12, 0.0025), (12, 0.012), (36, 0.0025), (36, 0.008), (72, 0.008), (360, 0.008), (360, 0.0025)]


@pytest.mark.parametrize(("count", "length_scale"), CASES, ids=[f"{c}-at-{s}" for c, s in CASES])
def test_the_numbers_round_the_crank_stand_apart_and_outside_its_circle(count, length_scale):
    analysis = _ratchet(count, length_scale)
    plan = positions_plan(analysis)
    layers = {layer.name: layer.items for layer in positions.layout(plan)}
    numbers = [item for item in layers["labels"] if isinstance(item, Text) and NUMBER.match(item.text)]
    boxes = [text_box(item) for item in numbers]
    for (one, first), (other, second) in itertools.combinations(zip(numbers, boxes), 2):
        assert not first.intersects(second), (one.text, other.text)
    scene = analysis.scene
    pivot = Point(*(coordinate / length_scale for coordinate in
                    (scene.frame_points["O"].real, scene.frame_points["O"].imag)))
    radius = scene.driver.length / length_scale
    for item, box in zip(numbers, boxes):
        assert box.distance(pivot) > radius, item.text
    shown = {item.text for item in numbers}
    # The first position and the plan sheets' positions are always numbered; the rest one in every few, regularly.
    assert {str(plan.numbers[0]), "5", "11"} <= shown
    regular = sorted(int(text) for text in shown if text.isdigit() and text not in ("5", "11"))
    steps = {b - a for a, b in itertools.pairwise(regular)}
    assert len(regular) >= 6 and min(steps) > 0 and all(step % min(steps) == 0 for step in steps), regular


def test_twelve_positions_on_a_crank_drawn_large_are_all_numbered():
    plan = positions_plan(_ratchet(12, 0.0025))
    texts = {item.text for layer in positions.layout(plan) if layer.name == "labels" for item in layer.items
             if isinstance(item, Text)}
    assert {str(number) for number in range(12)} <= texts


CRANKS = [path.stem for path in sorted(Path("fixtures").glob("*.toml"))
          if loads(path.read_text(encoding="utf-8")).driver.kind == "crank"]


@pytest.mark.parametrize("name", CRANKS)
def test_no_number_round_the_crank_is_written_over_an_extreme_position(name):
    """The Scotch yoke's rod runs out along the radius of its top position: no spot along that line was clear of it,
    and "7" was written over the bold rod and its guide."""
    plan = positions_plan(analyse(loads(Path(f"fixtures/{name}.toml").read_text(encoding="utf-8"))))
    layers = {layer.name: layer.items for layer in positions.layout(plan)}
    bold = [item for item in layers["extremes"] if not isinstance(item, Text)]
    lines = obstacles_of(bold)
    for item in layers["labels"]:
        if isinstance(item, Text) and NUMBER.match(item.text):
            assert not any(text_box(item).intersects(line) for line in lines), item.text


V_TWIN = """
[scene]
title = "90-degree V-twin"
[frame]
link = 1
points = { O = [0.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.04
rpm = 3000.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.14
guide = { through = "O", angle = 45.0 }
assembly = "forward"
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["A", "D"]
length = 0.14
guide = { through = "O", angle = 135.0 }
assembly = "forward"
[points]
S3 = { link = 3, from = "A", toward = "B", at = 0.04 }
S5 = { link = 5, from = "A", toward = "D", at = 0.04 }
[positions]
count = 24
start = "extreme"
number_from = 0
working = { link = 4, sense = "backward" }
plans = [3, 15]
[drawing]
length_scale = 0.002
"""


def _number_order(plan, layers) -> list[tuple[str, float, float, float]]:
    """Each number round the crank's circle with the angles (about the pivot, radians) of its box's centre and of
    the pins of the positions before and after it."""
    driver = plan.mechanism.driver
    pivot = plan.mechanism.scene.frame_points[driver.pivot] / plan.length_scale
    pins = [complex(value) / plan.length_scale - pivot for value in plan.positions.points[driver.joint].r]
    ends = plan.mechanism.scene.driver.swing is not None
    found = []
    for item in layers["labels"]:
        if not (isinstance(item, Text) and item.text.isdigit()):
            continue
        index = plan.numbers.index(int(item.text))
        centre = complex(*text_box(item).centroid.coords[0]) - pivot
        own = pins[index]
        before = cmath.phase(pins[index - 1] / own) if index or not ends else None
        after = cmath.phase(pins[(index + 1) % len(pins)] / own) if index < len(pins) - 1 or not ends else None
        # A swing's end has a neighbour on one side only: the other way it may go as far as a half turn.
        before = -math.copysign(math.pi, after) if before is None else before
        after = -math.copysign(math.pi, before) if after is None else after
        found.append((item.text, cmath.phase(centre / own), before, after))
    return found


def test_a_number_set_aside_round_the_circle_is_not_carried_past_its_neighbours_pin():
    """Round a V-twin's crank drawn 20 mm long, the 14 ran into the 15 of a plan position, numbered first, and was set
    28° round the circle, beyond it: the numbers read 13, 15, 14.  A number set aside stays between the pins of the
    positions before and after it (going out on a leader instead)."""
    plan = positions_plan(analyse(loads(V_TWIN)))
    layers = {layer.name: layer.items for layer in positions.layout(plan)}
    found = _number_order(plan, layers)
    assert {text for text, *_ in found} >= {"13", "14", "15", "16"}
    for text, angle, before, after in found:
        assert before < angle < after, (text, angle, before, after)


@pytest.mark.parametrize("name", CRANKS)
def test_every_fixtures_numbers_read_in_order_round_the_crank(name):
    plan = positions_plan(analyse(loads(Path(f"fixtures/{name}.toml").read_text(encoding="utf-8"))))
    layers = {layer.name: layer.items for layer in positions.layout(plan)}
    for text, angle, before, after in _number_order(plan, layers):
        # A crank turning clockwise has the position before it on the counter-clockwise side.
        assert min(before, after) < angle < max(before, after), (text, angle, before, after)
