"""The load diagrams: each load given over a stroke drawn against its link's travel, its values those the force
analysis takes.

The values are checked against the force analysis's own loads (``analysis.loads``, from which the equilibrium
is solved) and against an independent reading of the diagram: the centric slider-crank's piston travel in closed
form, x = r·cos φ + √(l² − r²·sin² φ), its share of each stroke from the dead centres x = l ± r, and the diagram
interpolated there with numpy.  The drawing is checked on its primitives (rings, ticks, numbers at μs and μF), the
sheets and the note on what they hold.
"""

from __future__ import annotations

import functools
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.deliverables import chosen, drawings
from graphplan.errors import SceneError
from graphplan.load_diagrams import of_analysis
from graphplan.locale import strings
from graphplan.render import load_diagrams as layout
from graphplan.render.primitives import Arrow, Circle, Polyline, Text, text_extent
from graphplan.report.note import note_markdown
from graphplan.scales import STANDARD_MANTISSAS
from graphplan.starters import starter

SCENES = Path(__file__).parent / "scenes"
COMPRESSOR = SCENES / "compressor_indicator_diagram.toml"


@functools.cache
def compressor():
    return graphplan.load(COMPRESSOR).analyse()


@functools.cache
def shaper():
    return graphplan.load_text(starter("shaper")).analyse()


def _standard(value: float) -> bool:
    mantissa = value / 10.0 ** math.floor(math.log10(value) + 1e-12)
    return any(math.isclose(mantissa, standard) for standard in STANDARD_MANTISSAS)


def test_the_compressor_s_values_are_its_indicator_diagram_read_at_the_closed_form_piston_travel():
    tables = tomllib.loads(COMPRESSOR.read_text(encoding="utf-8"))
    r, l = tables["driver"]["length"], tables["groups"][0]["length"]
    forward, backward = (np.array(load["diagram"]).T for load in tables["loads"])
    analysis = compressor()
    # Twelve positions from the dead centre nearest the crank (φ = 180°, where the forward stroke starts), ccw.
    phi = np.radians(180.0 + 30.0 * np.arange(12))
    assert np.allclose(np.cos(analysis.positions.values), np.cos(phi), atol=1e-9)
    x = r * np.cos(phi) + np.sqrt(l**2 - (r * np.sin(phi)) ** 2)
    going = np.sin(phi) < -1e-9    # dx/dφ = −r·sin φ·(…) > 0: the piston moves toward the head, +x
    going[0] = True                # at the bottom dead centre it is about to go forward; at the top, back
    share_forward = (x - (l - r)) / (2 * r)
    share_backward = ((l + r) - x) / (2 * r)
    expected_forward = np.where(going, np.interp(share_forward, *forward), 0.0)
    expected_backward = np.where(going, 0.0, np.interp(share_backward, *backward))

    (diagram,) = of_analysis(analysis)
    first, second = diagram.loads
    assert (first.name, second.name) == ("F4.1", "F4.2")
    assert np.allclose(first.values, expected_forward, atol=1e-6)
    assert np.allclose(second.values, expected_backward, atol=1e-6)
    assert np.allclose(diagram.coordinates, x - (l - r), atol=1e-9)
    assert np.isclose(diagram.travel, 2 * r)
    assert list(diagram.in_reference) == list(going)
    # Position 7, the top dead centre, takes the backward stroke's first value: the discharge pressure's.
    assert second.values[6] == pytest.approx(5300.0)


def test_the_values_drawn_are_those_the_force_analysis_and_its_plans_take():
    for analysis in (compressor(), shaper()):
        external = {load.name: load for load in analysis.loads}
        for diagram in of_analysis(analysis):
            for load in diagram.loads:
                direction = complex(math.cos(math.radians(load.spec.angle_deg)),
                                    math.sin(math.radians(load.spec.angle_deg)))
                along = (np.asarray(external[load.name].force) * direction.conjugate()).real
                taken = np.abs(along) if load.spec.resisting else along
                assert np.allclose(load.values, taken, atol=1e-9)
                for plan in analysis.plans:
                    (on_sheet,) = [item for item in plan.loads if item.name == load.name]
                    value = (on_sheet.force * direction.conjugate()).real
                    assert load.values[plan.index] == pytest.approx(abs(value) if load.spec.resisting else value)


def test_the_shaper_s_cutting_window_is_a_rectangle_over_its_shares_of_the_ram_s_stroke():
    (diagram,) = of_analysis(shaper())
    (load,) = diagram.loads
    travel = diagram.travel
    corners = ((0.05 * travel, 0.0), (0.05 * travel, 2000.0), (0.95 * travel, 2000.0), (0.95 * travel, 0.0))
    assert np.allclose(load.outline, corners)
    shares = diagram.coordinates / travel
    inside = diagram.in_reference & (np.round(shares, 12) >= 0.05) & (np.round(shares, 12) <= 0.95)
    assert np.array_equal(load.values, np.where(inside, 2000.0, 0.0))


def test_the_drawing_rings_and_writes_each_plan_position_s_value_at_its_travel_and_value_at_the_scales():
    (diagram,) = of_analysis(compressor())
    along, scale = layout.scales_of(diagram)
    assert _standard(along) and _standard(scale)
    assert along == 0.001 and scale == 100.0   # a 0.15 m stroke in 150 mm; 5450 N of values in 60 mm
    layers = layout.parts([diagram], strings("en"))[0]   # round the start of the stroke, as the scales measure
    items = [item for layer in layers for item in layer.items]
    rings = {(round(item.centre[0], 6), round(item.centre[1], 6)) for layer in layers if layer.name == "load-4-curves"
             for item in layer.items if isinstance(item, Circle) and item.radius == layout.PLAN_RING_MM}
    expected = set()
    for plan in compressor().plans:
        load = next(load for load in diagram.loads if load.values[plan.index])
        expected.add((round(diagram.coordinates[plan.index] / along, 6),
                      round(load.values[plan.index] / scale, 6)))
    assert rings == expected
    texts = [item.text for item in items if isinstance(item, Text)]
    assert any(re.fullmatch(r"F4\.1 = 407\.7 N \(\d+\)", text) for text in texts)
    assert any(re.fullmatch(r"F4\.2 = −150 N \(\d+\)", text) for text in texts)
    # Every position numbered under its tick (centred on it: the ordinate's numbers, lettered as high, stand at its
    # left), each stroke in its own row.
    numbers = {item.text: item.at for item in items if isinstance(item, Text) and item.text.isdigit()
               and item.size == layout.NUMBER_SIZE and item.anchor == "middle"}
    assert sorted(map(int, numbers)) == list(range(1, 13))
    for k, number in enumerate(diagram.numbers):
        assert numbers[str(number)][0] == pytest.approx(diagram.coordinates[k] / along)
    rows = {bool(diagram.in_reference[k]): numbers[str(number)][1] for k, number in enumerate(diagram.numbers)}
    assert rows[True] > rows[False]
    ticks = [item for item in items if isinstance(item, Polyline) and len(item.points) == 2
             and item.points[0][1] == 0.0 and item.points[1][1] == layout.TICK_MM]
    assert len(ticks) == 12
    assert any("μF = 100 N/mm" in text and "μs = 0.001 m/mm" in text for text in texts)


def test_each_row_s_sense_arrow_is_headed_as_the_axes_are_and_clear_of_its_numbers():
    """The arrows before the rows of numbers had 1.8 mm heads in thin grey, beside 2.5 mm numbers and the axes'
    3 mm heads: they are drawn as the axes are, each at its row's height, pointing the row's way, and stand off
    every number by a millimetre or more."""
    (diagram,) = of_analysis(compressor())
    layers = layout.parts([diagram], strings("en"))[0]
    items = [item for layer in layers for item in layer.items]
    (axis,) = [item for item in items if isinstance(item, Arrow) and item.key == "load-4-travel-axis"]
    rows = [item for item in items if isinstance(item, Arrow) and item.start[1] == item.end[1] < 0]
    assert len(rows) == 2   # the forward stroke's and the return's
    numbers = [item for item in items if isinstance(item, Text) and item.text.isdigit()
               and item.size == layout.NUMBER_SIZE]
    for arrow in rows:
        assert arrow.head_length == axis.head_length and arrow.stroke == axis.stroke
        # At the middle of its row's first line of numbers, to the left of all of them.
        assert any(abs(number.at[1] + layout.NUMBER_SIZE / 2 - arrow.start[1]) < 1e-9 for number in numbers)
        for number in numbers:
            x0, y0, _, y1 = text_extent(number)
            assert max(arrow.start[0], arrow.end[0]) + 1.0 <= x0 or not y0 - 1.0 <= arrow.start[1] <= y1 + 1.0
    senses = sorted(arrow.end[0] - arrow.start[0] > 0 for arrow in rows)
    assert senses == [False, True]


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_every_word_of_the_drawing_is_the_locale_s(locale):
    words = strings(locale)
    texts = " ".join(item.text for layer in layout.layout(of_analysis(compressor()), words)
                     for item in layer.items if isinstance(item, Text))
    assert words["ld_title"] in texts
    assert words["working_stroke"] in texts and words["idle_stroke"] in texts
    assert "{" not in texts


def test_the_piece_comes_where_a_load_is_given_over_a_stroke_and_is_refused_elsewhere():
    assert "load_diagrams" in chosen(compressor().scene, compressor())
    tables = tomllib.loads(starter("crank-rocker"))
    assert tables["loads"][0]["during"] == "working"
    tables["loads"][0]["during"] = "always"
    plain = graphplan.load(tables)
    analysis = plain.analyse()
    assert "load_diagrams" not in chosen(plain, analysis)
    with pytest.raises(SceneError, match="'load_diagrams' needs a load given over a stroke"):
        chosen(plain, analysis, ["load_diagrams"])


def test_the_load_diagrams_stand_on_a_force_sheet_and_are_written_alone():
    analysis = compressor()
    made = drawings(analysis.scene, analysis, chosen(analysis.scene, analysis, ["forces", "lever", "load_diagrams",
                                                                                "sheets"]))
    sheets = [drawing for drawing in made if drawing.stem.startswith("sheet_")]

    def holds(drawing, name: str) -> bool:
        return any(name in layer.name for layer in drawing.layers)

    (holding,) = [sheet for sheet in sheets if holds(sheet, "load-4-curves")]
    assert holds(holding, "forces-")
    (alone,) = [drawing for drawing in made if drawing.stem == "load_diagrams"]
    assert any(layer.name == "load-4-curves" for layer in alone.layers)


def test_a_russian_drawing_writes_its_numbers_with_a_comma_and_the_loads_names_as_named():
    """F4.1 and F4.2 are the first and second loads on link 4 (as the note and the force sheets call them): the
    decimal-comma pass wrote them F4,1 and F4,2 on a Russian drawing."""
    def values_written(text: str) -> list[str]:
        analysis = graphplan.load_text(text).analyse()
        made = drawings(analysis.scene, analysis, chosen(analysis.scene, analysis, ["load_diagrams"]))
        (drawing,) = [drawing for drawing in made if drawing.stem == "load_diagrams"]
        return [item.text for layer in drawing.layers for item in layer.items
                if isinstance(item, Text) and item.text.startswith("F4.") and " = " in item.text]

    english = COMPRESSOR.read_text(encoding="utf-8")
    russian = english.replace('locale  = "en"', 'locale  = "ru"')
    assert russian != english
    in_english = values_written(english)
    assert {line.split(" = ")[0] for line in in_english} == {"F4.1", "F4.2"}
    # The same lines, the value's point a comma and N the Russian Н: the load's name as it was.
    expected = [f"{name} = {value.replace('.', ',').replace(' N (', ' Н (')}"
                for name, value in (line.split(" = ") for line in in_english)]
    assert values_written(russian) == expected


def test_the_note_tables_each_position_s_value_and_shows_the_figure():
    analysis = compressor()
    note = note_markdown(analysis, figures={"load_diagrams.svg"})
    assert "![Load diagrams](load_diagrams.svg)" in note
    table = re.search(r"\| position \| stroke \| sB, m \|.*?\n\n", note, re.DOTALL)
    assert table is not None
    rows = [line.strip("| ").split(" | ") for line in table.group(0).splitlines()[2:] if line]
    assert len(rows) == 12
    assert rows[2][-2:] == ["407.69", "0"] and rows[9][1] == "idle stroke"
