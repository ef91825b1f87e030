"""The kinematic diagrams keep a fixed band under the φ axis for the positions' numbers, as a hand drawing does.

A diagram's extent so follows from its size alone: the sheet measures each size it may draw them at unlettered
and letters only the one it takes (the larger ways of a big sheet were each laid out with every label placed,
about a quarter of a cold run's time).  Checked here against the drawing itself: the SVG of the diagrams
lettered has the page of the SVG unlettered, every text and line of it inside; each number stands in the band
under the axis (or in its mirror over the ticks where the curve runs under the axis), within reach of its tick,
covering no line; and a sheet letters no size it does not draw.
"""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from shapely.geometry import LineString, Point, box

from graphplan.analysis import analyse
from graphplan.kinematic_diagrams import of_analysis
from graphplan.locale import strings
from graphplan.render import diagrams
from graphplan.render.packing import Panel
from graphplan.render.primitives import Arrow, Circle, Polyline, Text, bounds, text_extent, text_width
from graphplan.render.svg import to_svg
from graphplan.scene import load

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
# Every fixture with an output link, so with kinematic diagrams.
WITH_DIAGRAMS = sorted(path.stem for path in FIXTURES.glob("*.toml")
                       if re.search(r"(?m)^working\s*=\s*\{", path.read_text(encoding="utf-8")))
SVG = "{http://www.w3.org/2000/svg}"


@functools.cache
def analysis_of(name: str, locale: str | None = None):
    scene = load(FIXTURES / f"{name}.toml")
    if locale is not None:
        from dataclasses import replace
        scene = replace(scene, locale=locale)
    return analyse(scene)


@functools.cache
def drawn(name: str, locale: str | None = None, axis: float | None = None, field: float | None = None):
    """The record and its parts lettered and unlettered."""
    analysis = analysis_of(name, locale)
    sizes = {key: value for key, value in (("axis_mm", axis), ("field_mm", field)) if value is not None}
    record = of_analysis(analysis, **sizes)
    text = strings(analysis.scene.locale)
    return record, diagrams.parts(record, text), diagrams.parts(record, text, lettered=False)


def svg_page(svg: str) -> tuple[str, str, str]:
    root = ElementTree.fromstring(svg)
    return root.get("width"), root.get("height"), root.get("viewBox")


def test_every_fixture_with_an_output_link_is_checked():
    assert len(WITH_DIAGRAMS) >= 8 and {"ratchet_crank_rocker", "slider_driven", "shaper_six_bar"} <= set(
        WITH_DIAGRAMS)


@pytest.mark.parametrize("name", WITH_DIAGRAMS)
def test_the_extent_before_lettering_holds_every_label_read_back_from_the_svg(name):
    _, lettered, bare = drawn(name)
    full, unlettered = to_svg(diagrams.stacked(lettered)), to_svg(diagrams.stacked(bare))
    # The page round the drawing is its bounds and a margin: the same page, so nothing the lettering added reaches
    # past what the unlettered drawing measured.
    assert svg_page(full) == svg_page(unlettered)
    assert len(re.findall("<text", full)) > len(re.findall("<text", unlettered))
    root = ElementTree.fromstring(full)
    _, _, width, height = (float(value) for value in root.get("viewBox").split(","))
    margin = 8.0
    for element in root.iter(f"{SVG}text"):
        x, y, size = float(element.get("x")), float(element.get("y")), float(element.get("font-size"))
        words = "".join(element.itertext())
        wide = text_width(words, size / 1.3888889) if element.get("text-anchor") != "start" else 0.0
        assert margin - 0.01 <= x - wide / 2 and x + wide / 2 <= width - margin + 0.01, words
        assert margin - 0.01 <= y - size * 0.8 and y <= height - margin + 0.01, words
    for element in root.iter(f"{SVG}path"):
        numbers = [float(value) for value in re.findall(r"-?\d+(?:\.\d+)?", element.get("d"))]
        assert all(margin - 0.01 <= value for value in numbers)
        assert all(value <= width - margin + 0.01 for value in numbers[0::2])
        assert all(value <= height - margin + 0.01 for value in numbers[1::2])


@pytest.mark.parametrize("name", ["ratchet_crank_rocker", "shaper_six_bar", "slider_driven"])
@pytest.mark.parametrize("locale", ["ru", "zh", "en"])
def test_larger_sizes_keep_their_extent_lettered_in_every_language(name, locale):
    for axis, field in ((360.0, 96.0), (300.0, 48.0), (120.0, 20.0)):
        _, lettered, bare = drawn(name, locale, axis, field)
        for with_labels, without in zip(lettered, bare, strict=True):
            assert bounds(with_labels) == pytest.approx(bounds(without), abs=1e-9)


def numbers_and_lines(part: list, kind: str):
    layers = {layer.name: layer.items for layer in part}
    numbers = [item for item in layers[f"{kind}-labels"] if isinstance(item, Text) and item.text.isdigit()]
    lines = []
    for item in (*layers[f"{kind}-axes"], *layers[f"{kind}-rays"], *layers[f"{kind}-curves"]):
        if isinstance(item, Polyline) and len(item.points) > 1:
            lines.append(LineString(item.points))
        elif isinstance(item, Arrow):
            lines.append(LineString((item.start, item.end)))
        elif isinstance(item, Circle):
            lines.append(Point(item.centre).buffer(item.radius))
    return numbers, lines


def lowest_of_the_curves(part: list, kind: str) -> float:
    """The lowest point of a diagram's curves and chords, or the axis where they stay over it (mm)."""
    layers = {layer.name: layer.items for layer in part}
    return min(0.0, *(y for item in layers[f"{kind}-curves"] if isinstance(item, Polyline) for _, y in item.points))


def lowest_between(part: list, kind: str, x0: float, x1: float) -> float:
    """The lowest point of a diagram's curves and chords between x0 and x1, or the axis where they stay over it
    (mm): each a broken line along x, so its lowest point there is one of its corners or an end of the span."""
    layers = {layer.name: layer.items for layer in part}
    lowest = 0.0
    for item in layers[f"{kind}-curves"]:
        if isinstance(item, Polyline) and len(item.points) > 1:
            xs, ys = np.array(item.points).T
            at = np.concatenate(([x0, x1], xs[(xs > x0) & (xs < x1)]))
            at = at[(at >= xs.min()) & (at <= xs.max())]
            if len(at):
                lowest = min(lowest, float(np.interp(at, xs, ys).min()))
    return lowest


@pytest.mark.parametrize("name", WITH_DIAGRAMS)
def test_the_numbers_stand_in_the_band_by_their_ticks_off_every_line(name):
    """Each number in the band under the axis; where a curve takes that, right under the curves within the
    number's reach of its tick, or in the row under their lowest point; under its tick, on no line and no other
    number."""
    record, lettered, _ = drawn(name)
    along_mm = 1.0 / record.scales.along
    height = 1.45 * diagrams.NUMBER_SIZE
    for kind, part in zip(diagrams.KINDS, lettered, strict=True):
        numbers, lines = numbers_and_lines(part, kind)
        # Every second or third one where they would not fit between the ticks: at least half of those shown.
        assert len(numbers) >= len(record.numbers) / 6, kind
        low_row_top = lowest_of_the_curves(part, kind) - diagrams.LOW_ROW_CLEARANCE_MM
        seen = []
        for number in numbers:
            x0, y0, x1, y1 = text_extent(number)
            in_band = y1 <= -diagrams.NUMBER_CLEARANCE_MM + 1e-9 and y0 >= -diagrams.NUMBER_CLEARANCE_MM - height - 1e-9
            in_low_row = y1 <= low_row_top + 1e-9 and y0 >= low_row_top - height - 1e-9
            # Of a cycle the first and the last node bear one number: either tick is its own.
            tick = min((x for n, x in zip(record.numbers, (record.nodes * along_mm).tolist(), strict=True)
                        if str(n) == number.text), key=lambda x: abs(number.at[0] - x))
            nearest = abs(number.at[0] - tick)
            # As far as the number's box reaches, stepped along the row as far as it may go from its tick.
            half = (x1 - x0) / 2
            reach = half + diagrams.NUMBER_STEP_MM * math.floor((half + diagrams.NUMBER_REACH_MM) / diagrams.NUMBER_STEP_MM)
            under = lowest_between(part, kind, tick - reach, tick + reach) - diagrams.LOW_ROW_CLEARANCE_MM
            by_the_tick = abs(y1 - under) <= diagrams.NUMBER_STEP_MM and y1 < -diagrams.NUMBER_CLEARANCE_MM
            assert in_band or by_the_tick or in_low_row, (kind, number.text, y0, y1)
            assert nearest <= (x1 - x0) / 2 + diagrams.NUMBER_REACH_MM + 1e-9, (kind, number.text)
            assert not any(line.intersects(box(x0, y0, x1, y1)) for line in lines), (kind, number.text)
            assert not any(box(*other).intersects(box(x0, y0, x1, y1)) for other in seen), (kind, number.text)
            seen.append((x0, y0, x1, y1))


@pytest.mark.parametrize("name", WITH_DIAGRAMS)
def test_the_numbers_rows_make_no_diagram_deeper_than_the_room_it_keeps_under_its_curves(name):
    """The band and the row under the curves lie within the 4 mm every diagram keeps under its lowest point (and
    under the axis), so that the band costs no sheet any room: 2.3 mm deeper, the triad with a slider's three
    diagrams no longer stood on the sheet of its plans and took a fourth sheet of their own."""
    _, lettered, _ = drawn(name)
    for kind, part in zip(diagrams.KINDS, lettered, strict=True):
        numbers, _ = numbers_and_lines(part, kind)
        floor = lowest_of_the_curves(part, kind) - 4.0 - 0.3 * diagrams.NUMBER_SIZE
        assert all(text_extent(number)[1] >= floor - 1e-9 for number in numbers), kind
        layers = {layer.name: layer.items for layer in part}
        ordinate = next(item for item in layers[f"{kind}-axes"] if isinstance(item, Arrow) and item.start[0] == 0.0)
        assert ordinate.start[1] >= floor - 1e-9, kind


@pytest.mark.parametrize("name", ["ratchet_crank_rocker", "slider_driven", "shaper_six_bar"])
def test_most_numbers_stand_right_under_the_axis_and_none_over_it(name):
    """A number over the axis beside the curve read as lettering the curve: none stands there, and the row under
    the curves takes only those the curve leaves no room for under the axis."""
    _, lettered, _ = drawn(name)
    for kind, part in zip(diagrams.KINDS, lettered, strict=True):
        numbers, _ = numbers_and_lines(part, kind)
        assert all(text_extent(number)[3] < 0.0 for number in numbers), kind
        in_band = [number for number in numbers if text_extent(number)[1] >= -diagrams.BAND_DEPTH_MM - 1e-9]
        assert len(in_band) >= len(numbers) / 3, kind


@pytest.mark.parametrize("name", ["ratchet_crank_rocker", "slider_driven", "shaper_six_bar"])
def test_the_pole_and_its_distance_are_lettered_clear_of_the_rays(name):
    _, lettered, _ = drawn(name)
    for kind, part in zip(diagrams.KINDS[1:], lettered[1:], strict=True):
        layers = {layer.name: layer.items for layer in part}
        texts = {item.text: item for item in layers[f"{kind}-labels"] if isinstance(item, Text)}
        pole = next(item for item in layers[f"{kind}-curves"] if isinstance(item, Circle) and item.centre[0] < 0)
        rays = [LineString(item.points) for item in layers[f"{kind}-rays"] if isinstance(item, Polyline)]
        for letter in ("P", "H"):
            x0, y0, x1, y1 = text_extent(texts[letter])
            assert not any(ray.intersects(box(x0, y0, x1, y1)) for ray in rays), (kind, letter)
        # H between the pole and the ordinate axis, P beside the pole.
        assert pole.centre[0] < texts["H"].at[0] < 0.0
        assert math.dist(texts["P"].at, pole.centre) < 8.0


def test_a_sheet_letters_only_the_size_it_draws(monkeypatch):
    from graphplan.render import sheet

    analysis = analysis_of("ratchet_crank_rocker")
    lettered = []
    numbers = diagrams._numbers
    monkeypatch.setattr(diagrams, "_numbers", lambda *a: lettered.append(1) or numbers(*a))
    panel = sheet._diagrams_panel(analysis, "A1")
    # The usual size (diagrams.svg, and the parts where no larger way fits) alone: three diagrams.
    assert len(lettered) == 3
    assert len(panel.alternatives) >= 5
    for way in panel.ways:
        assert isinstance(way, Panel)
    # Each larger way, lettered when it is drawn, fills the extent it was measured by.
    first = panel.ways[0]
    assert first.lettered is not None
    assert bounds(first.drawn_layers()) == pytest.approx(first.extent, abs=1e-9)
    assert len(lettered) == 6
    assert any(item.text == "7" for layer in first.drawn_layers() for item in layer.items if isinstance(item, Text))


@pytest.mark.parametrize(("name", "kind", "texts"), [("shaper_six_bar", "acceleration", {"5"}),
                                                     ("slider_driven", "acceleration", {"2", "4", "6", "8"})])
def test_a_number_the_curve_keeps_out_of_the_band_stands_right_under_the_curve_by_its_tick(name, kind, texts):
    """The shaper's aE crosses its axis at position 5 and the lever's flat ε4 runs in the band: their numbers went
    to the row under the curves' lowest point, the shaper's 5 about 16 mm under its tick with nothing between to
    say whose it is.  They stand right under the curve at their tick now, as a draughtsman letters them."""
    record, lettered, _ = drawn(name)
    part = lettered[diagrams.KINDS.index(kind)]
    numbers, _ = numbers_and_lines(part, kind)
    along_mm = 1.0 / record.scales.along
    ticks = dict(zip((str(number) for number in record.numbers), (record.nodes * along_mm).tolist()))
    shown = {number.text: number for number in numbers}
    assert texts <= set(shown), (texts, set(shown))
    for text in texts:
        x0, _, x1, y1 = text_extent(shown[text])
        curve_there = lowest_between(part, kind, x0, x1)
        assert curve_there < -diagrams.NUMBER_CLEARANCE_MM, "the curve takes the band here"
        assert curve_there - y1 <= diagrams.LOW_ROW_CLEARANCE_MM + 1.5, (text, curve_there, y1)
        assert abs(shown[text].at[0] - ticks[text]) <= (x1 - x0) / 2 + diagrams.NUMBER_REACH_MM


@functools.cache
def starter_analysis(kind: str):
    from graphplan.scene import loads
    from graphplan.starters import starter

    return analyse(loads(starter(kind)))


def lowest_mark_between(part: list, kind: str, x0: float, x1: float) -> float:
    """The lowest point between x0 and x1 of a diagram's curves, chords and the rings of the plans' values on
    them, or the axis where they stay over it (mm): the rings cut by the span as the discs they are."""
    layers = {layer.name: layer.items for layer in part}
    span = box(x0, -1e9, x1, 1e9)
    rings = [Point(item.centre).buffer(item.radius).intersection(span) for item in layers[f"{kind}-curves"]
             if isinstance(item, Circle) and item.radius == diagrams.PLAN_RING_MM]
    return min([lowest_between(part, kind, x0, x1), *(ring.bounds[1] for ring in rings if not ring.is_empty)])


@pytest.mark.parametrize(("kind_of_scene", "name"), [("starter", "shaper"), ("starter", "crank-rocker"),
                                                     ("starter", "slotted-lever"), ("fixture", "shaper_six_bar"),
                                                     ("fixture", "stephenson_six_bar"), ("fixture", "slider_driven")])
@pytest.mark.parametrize(("axis", "field"), [(None, None), (360.0, 96.0)])
def test_every_number_stands_by_its_tick_with_only_the_curve_between(kind_of_scene, name, axis, field):
    """A number stands at its tick (stepped at most its reach aside) right under the axis, or right under the curve
    or ring that passes its tick: never farther down with nothing between to say whose it is.  The shaper
    starter's vE has a ring at nought at position 1 (the velocity plan there, at an extreme position), which took
    the band's spot by the tick: its 1 went to the row under the curve's lowest point, 80 mm down the ordinate
    axis of the sheet's diagram."""
    analysis = starter_analysis(name) if kind_of_scene == "starter" else analysis_of(name)
    sizes = {key: value for key, value in (("axis_mm", axis), ("field_mm", field)) if value is not None}
    record = of_analysis(analysis, **sizes)
    lettered = diagrams.parts(record, strings(analysis.scene.locale))
    along_mm = 1.0 / record.scales.along
    ticks = (record.nodes * along_mm).tolist()
    for kind, part in zip(diagrams.KINDS, lettered, strict=True):
        numbers, _ = numbers_and_lines(part, kind)
        assert numbers, kind
        for number in numbers:
            x0, _, x1, y1 = text_extent(number)
            half = (x1 - x0) / 2
            tick = min((x for n, x in zip(record.numbers, ticks, strict=True) if str(n) == number.text),
                       key=lambda x: abs(number.at[0] - x))
            reach = half + diagrams.NUMBER_STEP_MM * math.floor((half + diagrams.NUMBER_REACH_MM)
                                                                / diagrams.NUMBER_STEP_MM)
            assert abs(number.at[0] - tick) <= reach - half + 1e-9, (kind, number.text)
            # What stands over the number at its tick: the axis, or lower the curves and rings that cross there.
            over = min(0.0, lowest_mark_between(part, kind, tick - reach, tick + reach))
            assert y1 < 0.0, (kind, number.text)
            assert over - y1 <= diagrams.NUMBER_CLEARANCE_MM + 0.05, (kind, number.text, over, y1)
