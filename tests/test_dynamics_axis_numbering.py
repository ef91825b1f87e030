"""The numbers of the dynamics sheet's axes: a Je axis shows at least two, each where its tick's value puts it, and
the bands ωmax and ωmin keep out of are those of the numbers the axes wrote, not of any text of figures alone."""

from __future__ import annotations

import itertools
import math
import re
from pathlib import Path
from types import SimpleNamespace
from xml.etree import ElementTree

import numpy as np
import pytest
from shapely.geometry import box

from graphplan.cli import main
from graphplan.render import dynamics
from graphplan.render.primitives import (
    FONT_SIZE_PER_CAP,
    Polyline,
    Text,
    text_extent,
    text_width,
)

ROOT = Path(__file__).resolve().parents[1]
COMPRESSOR = ROOT / "tests" / "scenes" / "compressor_indicator_diagram.toml"
SVG = "{http://www.w3.org/2000/svg}"
FIGURES = re.compile(r"\d+(?:[.,]\d+)?")
SCALE = re.compile(r"μJ = (\d+(?:[.,]\d+)?) ")
LOCALES = ("en", "ru", "zh")


@pytest.fixture(scope="module")
def compressor_drawings(tmp_path_factory) -> dict[str, Path]:
    """The compressor's dynamics.svg as `graphplan run` writes it in each locale."""
    drawings = {}
    for locale in LOCALES:
        out = tmp_path_factory.mktemp("compressor") / locale
        assert main(["run", str(COMPRESSOR), "--out", str(out), "--only", "dynamics", "--locale", locale]) == 0
        drawings[locale] = out / "dynamics.svg"
    return drawings


def _number(words: str) -> float:
    return float(words.replace(",", "."))


def _segments(group: ElementTree.Element) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The straight strokes of a group: (start, end) of each path of two points."""
    found = []
    for path in group.iter(f"{SVG}path"):
        if path.get("fill") not in (None, "none"):
            continue
        points = re.findall(r"(-?[\d.]+),(-?[\d.]+)", path.get("d"))
        if len(points) == 2:
            (x0, y0), (x1, y1) = points
            found.append(((float(x0), float(y0)), (float(x1), float(y1))))
    return found


def _at_number_height(text: ElementTree.Element) -> bool:
    return abs(float(text.get("font-size")) - dynamics.NUMBER * FONT_SIZE_PER_CAP) < 0.002


def _je_axis(group: ElementTree.Element) -> tuple[float, float, list[float], list[tuple[float, float]], float]:
    """The Je axis of a group read off the paper: its origin's x and its y, its ticks' x, its numbers as (value, the x
    of the tick each stands by) and μJ as the group's scale line writes it."""
    segments = _segments(group)
    (x0, axis_y), (x1, _) = max((s for s in segments if abs(s[0][1] - s[1][1]) < 1e-6),
                                key=lambda s: abs(s[1][0] - s[0][0]))
    origin = min(x0, x1)
    ticks = sorted(start[0] for start, end in segments if abs(start[0] - end[0]) < 1e-6
                   and min(start[1], end[1]) < axis_y < max(start[1], end[1]) and abs(end[1] - start[1]) < 3
                   and start[0] > origin + 0.1)
    texts = list(group.iter(f"{SVG}text"))
    words = ["".join(t.itertext()) for t in texts]
    numbers = []
    for text, said in zip(texts, words, strict=True):
        # The axes' numbers are lettered at their own height (lettering.AXIS_NUMBER), under the axis's name.
        if not FIGURES.fullmatch(said) or _number(said) <= 0 or not _at_number_height(text):
            continue
        if abs(float(text.get("y")) - axis_y) > 8:
            continue
        x = float(text.get("x"))
        tick = min(ticks, key=lambda at: abs(at - x))
        assert abs(tick - x) <= 0.6, f"{said} at x = {x} stands by no tick of {ticks}"
        numbers.append((_number(said), tick))
    scale = _number(SCALE.search(" ".join(words))[1])
    return origin, axis_y, ticks, sorted(numbers), scale


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("diagram", ["energy-mass", "inertia"])
def test_the_compressors_je_axes_carry_two_numbers_each_at_its_ticks_value(compressor_drawings, locale, diagram):
    """At μJ = 0.002 kg·m²/mm the compressor's Je axes were ticked at 0.025, 0.05 and 0.075 and, the numbers too
    crowded at 12.5 mm, numbered at 0.05 alone: no two numbers to read the axis's scale off.  Each axis shows two
    numbers or more, each the value its tick stands for at the μJ the drawing writes, counted from the origin."""
    root = ElementTree.parse(compressor_drawings[locale]).getroot()
    group = next(g for g in root.iter(f"{SVG}g") if g.get("id") == diagram)
    origin, _, ticks, numbers, scale = _je_axis(group)
    assert len(numbers) >= 2, numbers
    assert len({tick for _, tick in numbers}) == len(numbers)
    for value, tick in numbers:
        assert value == pytest.approx((tick - origin) * scale, rel=1e-6), (value, tick, origin, scale)
    # The axis's own scale, read off two of its numbers and their ticks, is the μJ it states, and its ticks stand at
    # equal steps from the origin: value a linear map of the position along the axis.
    (v1, x1), (v2, x2) = numbers[0], numbers[-1]
    assert (v2 - v1) / (x2 - x1) == pytest.approx(scale, rel=1e-6)
    spacing = ticks[0] - origin
    assert ticks == pytest.approx([origin + k * spacing for k in range(1, len(ticks) + 1)], abs=1e-3)


@pytest.mark.parametrize("locale", LOCALES)
def test_the_compressors_je_axes_are_numbered_alike_and_run_past_their_last_tick(compressor_drawings, locale):
    """The energy–mass diagram and Je(φ) under it share their Je axis: one set of numbers, at one place each; the
    axis's arrow runs on past the last tick (0.1, past the curve's largest Je of 0.091), its name past the arrow."""
    root = ElementTree.parse(compressor_drawings[locale]).getroot()
    groups = {g.get("id"): g for g in root.iter(f"{SVG}g") if g.get("id")}
    axes = [_je_axis(groups[name]) for name in ("energy-mass", "inertia")]
    # Nested pairs (value, x): compared as an array, which pytest.approx takes at any shape from pytest 9 on.
    assert np.array(axes[0][3]) == pytest.approx(np.array(axes[1][3]))
    for name, (origin, axis_y, ticks, _, _) in zip(("energy-mass", "inertia"), axes, strict=True):
        group = groups[name]
        (x0, _), (x1, _) = max((s for s in _segments(group) if abs(s[0][1] - axis_y) < 1e-6
                                and abs(s[1][1] - axis_y) < 1e-6), key=lambda s: abs(s[1][0] - s[0][0]))
        assert max(x0, x1) - ticks[-1] >= dynamics.AXIS_RUN_MM, name


def _fake_model(largest: float) -> SimpleNamespace:
    """What the Je ticks read of a model: its reduced moments of inertia, up to ``largest``."""
    return SimpleNamespace(inertia=np.linspace(0.6 * largest, largest, 7))


def _one_two_five(step: float) -> bool:
    mantissa = step / 10.0 ** math.floor(math.log10(step) + 1e-9)
    return any(math.isclose(mantissa, m, rel_tol=1e-9) for m in (1.0, 2.0, 2.5, 5.0, 10.0))


@pytest.mark.parametrize("scale", [0.0005, 0.001, 0.002, 0.004, 0.01, 0.05, 0.2])
def test_every_je_axis_shows_two_numbers_a_letter_apart_at_round_values(scale):
    """Over a sweep of largest Je and μJ: at least two numbers, each centred on its tick and a letter's width from the
    next; the ticks at equal round steps from nought, carried past the largest Je only as far as the axis runs past
    the curve, or to a second tick."""
    gap = text_width("0", dynamics.NUMBER)
    for largest in np.geomspace(0.01, 400.0, 97):
        largest = float(largest)
        ticks = dynamics._inertia_ticks(_fake_model(largest), SimpleNamespace(inertia=scale))
        numbered = [(value, at) for value, at, shown in ticks if shown]
        assert len(numbered) >= 2, (largest, scale, ticks)
        step = ticks[0][0]
        assert _one_two_five(step), (largest, scale, step)
        for k, (value, at, _) in enumerate(ticks, start=1):
            assert value == pytest.approx(k * step, rel=1e-9)
            assert at == pytest.approx(value / scale, rel=1e-9)
        beyond = [value for value, _, _ in ticks if value > largest * (1 + 1e-9)]
        within_run = all(value <= largest + dynamics.AXIS_RUN_MM * scale * (1 + 1e-9) for value in beyond)
        assert within_run or len(ticks) == 2, (largest, scale, ticks)
        # The axis is ticked as far as it runs past the curve: no round value is left bare there.
        assert ticks[-1][0] + step > largest + dynamics.AXIS_RUN_MM * scale * (1 - 1e-9), (largest, scale, ticks)
        boxes = [box(*_centred(value, at)) for value, at in numbered]
        for a, b in itertools.pairwise(boxes):
            assert a.distance(b) >= gap - 1e-6, (largest, scale, numbered)


def _centred(value: float, at: float) -> tuple[float, float, float, float]:
    return text_extent(Text((at, 0.0), dynamics.short(value), dynamics.NUMBER, "middle"))


def test_an_axis_already_numbered_twice_or_more_keeps_its_ticks():
    """Where the Je axis shows two numbers or more at its usual step (the compressor's at μJ = 0.001, 25 mm a step
    of 0.025), the ticks stay at that step, about four to the largest Je, each numbered."""
    largest = 0.09103727616462795
    ticks = dynamics._inertia_ticks(_fake_model(largest), SimpleNamespace(inertia=0.001))
    assert [round(value, 9) for value, _, _ in ticks] == [0.025, 0.05, 0.075]
    assert all(shown for _, _, shown in ticks)


def test_a_je_past_its_last_tick_is_read_against_the_next_where_the_axis_runs_on_to_it():
    """The Whitworth mechanism's Je peaks at 1.45 kg·m², drawn at μJ = 0.02 kg·m²/mm: 72.5 mm along an axis ticked
    every 0.5 that runs 8 mm past the curve.  The tick at 1.5, 2.5 mm past the peak, is drawn and numbered, so the
    peak stands between two numbers; the compressor's 0.091 at μJ = 0.001 keeps 0.075 last (0.1 is 9 mm out)."""
    ticks = dynamics._inertia_ticks(_fake_model(1.45), SimpleNamespace(inertia=0.02))
    assert [(round(value, 9), shown) for value, _, shown in ticks] == [(0.5, True), (1.0, True), (1.5, True)]
    assert ticks[-1][1] == pytest.approx(75.0)


def test_a_diagrams_numberings_are_its_axes_numbers_and_not_a_legend_of_figures():
    """The bands ωmax and ωmin keep out of were cut round every text of figures alone, whatever wrote it: a legend
    naming its curves "1" and "2" made a band along the scale line.  They are cut round the numbers the axes wrote."""
    x = np.linspace(0.0, 180.0, 37)
    model = SimpleNamespace(turning=True, cyclic=True, coordinate=np.radians(np.linspace(0.0, 360.0, 37)))
    scales = dynamics.Scales(angle=2.0 * math.pi / 180.0, moment=10.0, work=10.0, energy=5.0, inertia=0.002)
    words = {**dynamics.strings("en")}
    values = 300.0 * np.sin(np.linspace(0.0, 2.0 * math.pi, 37))
    drawn = dynamics._diagram(x, [(values, dynamics._DRIVING, "1"), (-values / 2, dynamics._RESISTING, "2")], 10.0,
                              model, "M, N·m", "μM = 10 N·m/mm", "Me", scales, words)
    legend = [item for item in drawn.items if isinstance(item, Text) and item.text in ("1", "2")]
    assert len(legend) == 2
    numbers = [number for axis in drawn.numberings for number in axis]
    assert not any(number is item for number in numbers for item in legend)
    # The φ axis's numbers are its ticks' degrees, 0 to 360 at 30°, each under its tick; the ordinate's, round values.
    across, up = drawn.numberings
    assert [number.text for number in across] == [str(degrees) for degrees in range(0, 361, 30)]
    ticks = {round(item.points[0][0], 6) for item in drawn.items
             if isinstance(item, Polyline) and len(item.points) == 2 and item.points[0][0] == item.points[1][0]}
    assert all(round(number.at[0], 6) in ticks for number in across)
    assert all(FIGURES.fullmatch(number.text.lstrip("−")) for number in up) and len(up) >= 3
    bands = dynamics._numbering(drawn.numberings)
    assert len(bands) == 2
    assert not any(band.intersects(box(*text_extent(item))) for band in bands for item in legend)
