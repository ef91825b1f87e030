"""The positions' numbers round the crank's circle on the plan of positions: clear of one another, outside the circle.

Read from the drawn texts: with many positions on a small crank the numbers ran together ("34" over "33"
read "3433") and the labeller put half of them inside the circle among the spokes.
"""

import itertools
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
