"""The plan of positions marks both extreme positions: one that is no numbered position is named after the position
it follows with a prime (8′) and its points lettered with a prime (A′, D′), as Russian course projects mark them;
every label clear of the others and of the driver's pin it names."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render import drawings, positions
from graphplan.render.primitives import Circle, Text, text_extent


def plan_of(name):
    analysis = drawings.with_length_scale(analyse(graphplan.load(f"fixtures/{name}.toml")))
    return analysis, positions.layout(drawings.positions_plan(analysis))


def labels(layers):
    return [item for layer in layers if layer.name == "labels" for item in layer.items if isinstance(item, Text)]


def overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def follows(analysis, value):
    """The number of the position the driver passes last before ``value``, turning its way, found from the
    positions' crank angles."""
    driver = analysis.mechanism.driver
    offsets = [(driver.sense * (v - value)) % (2 * math.pi) for v in analysis.positions.values]
    # The one it is furthest ahead of going back: the least turn from it to the extreme, the driver's way.
    behind = [(2 * math.pi - offset) % (2 * math.pi) for offset in offsets]
    return int(analysis.positions.numbers[int(np.argmin(behind))])


@pytest.mark.parametrize("name, expected", [("quick_return_slotted_lever", "8′"), ("stephenson_six_bar", "6′")])
def test_the_extreme_between_two_positions_is_named_after_the_one_it_follows(name, expected):
    analysis, layers = plan_of(name)
    _, second = analysis.positions.extremes
    assert f"{follows(analysis, second)}′" == expected
    written = {text.text: text for text in labels(layers)}
    assert expected in written
    # At the driver's pin in that extreme, as the positions' numbers stand at theirs.
    pin = complex(analysis.emphasised.points[analysis.mechanism.driver.joint].r[1]) / drawings.length_scale(analysis)
    x0, y0, x1, y1 = text_extent(written[expected])
    assert math.dist(((x0 + x1) / 2, (y0 + y1) / 2), (pin.real, pin.imag)) < 8.0


@pytest.mark.parametrize("name, letters", [("quick_return_slotted_lever", {"A′", "D′"}),
                                           ("stephenson_six_bar", {"A′", "B′", "E′", "G′"})])
def test_the_second_extreme_s_points_are_lettered_with_a_prime(name, letters):
    analysis, layers = plan_of(name)
    written = {text.text: text for text in labels(layers)}
    assert letters <= set(written)
    scale = drawings.length_scale(analysis)
    for letter in letters:
        point = complex(analysis.emphasised.points[letter.rstrip("′")].r[1]) / scale
        x0, y0, x1, y1 = text_extent(written[letter])
        assert math.dist(((x0 + x1) / 2, (y0 + y1) / 2), (point.real, point.imag)) < 12.0, letter  # by a leader


@pytest.mark.parametrize("name", ["quick_return_slotted_lever", "stephenson_six_bar"])
def test_no_label_of_the_plan_of_positions_covers_another_or_the_driver_s_pin_at_an_extreme(name):
    analysis, layers = plan_of(name)
    texts = labels(layers)
    for one, other in itertools.combinations(texts, 2):
        assert not overlap(text_extent(one), text_extent(other)), (one.text, other.text)
    scale = drawings.length_scale(analysis)
    joint = analysis.emphasised.points[analysis.mechanism.driver.joint].r
    pins = [item for layer in layers if layer.name == "extremes" for item in layer.items if isinstance(item, Circle)]
    for index in range(analysis.emphasised.count):
        at = complex(joint[index]) / scale
        pin = next(item for item in pins if math.dist(item.centre, (at.real, at.imag)) < 1e-6)
        for text in texts:
            x0, y0, x1, y1 = text_extent(text)
            # The nearest point of the label's box to the pin's centre stands half a millimetre clear of the pin.
            nearest = (min(max(at.real, x0), x1), min(max(at.imag, y0), y1))
            assert math.dist(nearest, (at.real, at.imag)) >= pin.radius + 0.5, (text.text, index)
