"""The plan sheet of one position, tested on its primitives: what is drawn, where, and how long.

The sheet is laid out from the plan records (graphplan.plans); these tests read the layers the
layout returns, find the vectors by their keys (``velocity-p-b``) and compare their lengths in
millimetres with the plan's values over its scale, check that every plan point is lettered once and
no two texts overlap, that a zero vector is left out, and that the SVG is the same byte for byte.
"""

import dataclasses
import itertools
import math
import re
from collections import Counter

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.plans import DrawnLine, LaidVector, Step
from graphplan.render import plans as sheet_layout
from graphplan.render.drawings import plan_scale_text, plan_sheet, plan_svg, positions_svg
from graphplan.render.labels import text_box
from graphplan.render.primitives import Arrow, Polyline, Text, arrowhead, bounds_of, place

FIXTURES = "fixtures"


@pytest.fixture(scope="module")
def ratchet():
    return analyse(graphplan.load(f"{FIXTURES}/ratchet_crank_rocker.toml"))


@pytest.fixture(scope="module")
def six_bar():
    return analyse(graphplan.load(f"{FIXTURES}/stephenson_six_bar.toml"))


@pytest.fixture(scope="module")
def slider_driven():
    return analyse(graphplan.load(f"{FIXTURES}/slider_driven.toml"))


def layers_of(sheet):
    return {layer.name: layer.items for layer in sheet_layout.layout(sheet)}


def arrows(layers, prefix):
    return {item.key: item for name, items in layers.items() if name.startswith(prefix)
            for item in items if isinstance(item, Arrow)}


def pole_on_paper(layers, kind):
    """Where the pole of a plan stands on the sheet: the start of its first vector from p."""
    vector = next(a for key, a in arrows(layers, kind).items() if key.startswith(f"{kind}-p-"))
    return complex(*vector.start)


def on_paper(layers, plan):
    origin = pole_on_paper(layers, plan.kind)
    return lambda letter: origin + plan.mm(letter)


CASES = [("ratchet", 5), ("ratchet", 11), ("six_bar", 3), ("six_bar", 9), ("slider_driven", 2), ("slider_driven", 8)]


@pytest.fixture(params=CASES, ids=[f"{name}-{index}" for name, index in CASES])
def sheet(request):
    name, index = request.param
    return plan_sheet(request.getfixturevalue(name), index)


def test_the_vector_pb_is_as_long_as_vb_over_the_velocity_scale(ratchet):
    sheet = plan_sheet(ratchet, 5)
    vector = arrows(layers_of(sheet), "velocity")["velocity-p-b"]
    assert vector.length == pytest.approx(abs(sheet.velocity.value("B")) / sheet.velocity.scale, abs=0.01)
    # 0.7005 m/s (the worked example's exact value) at μV = 0.01983 (m/s)/mm is 35.3 mm.
    assert vector.length == pytest.approx(0.7005 / (2.975 / 150), abs=0.01)


def test_every_vector_of_both_plans_has_its_length_over_the_scale(sheet):
    layers = layers_of(sheet)
    for plan in (sheet.velocity, sheet.acceleration):
        drawn = arrows(layers, plan.kind)
        for key, arrow in drawn.items():
            _, start, end = key.split("-")
            assert arrow.length == pytest.approx(abs(plan.mm(end) - plan.mm(start)), abs=0.01)
            assert complex(*arrow.end) - complex(*arrow.start) == pytest.approx(plan.mm(end) - plan.mm(start), abs=1e-9)


def test_every_vector_the_steps_lay_off_is_drawn_once_unless_zero(sheet):
    layers = layers_of(sheet)
    for plan in (sheet.velocity, sheet.acceleration):
        drawn = arrows(layers, plan.kind)
        laid = {(v.start, v.end) for step in plan.steps for v in step.vectors}
        absolute = {("p", letter) for letter in plan.images.values() if letter != "p"}
        for start, end in laid | absolute:
            long_enough = abs(plan.mm(end) - plan.mm(start)) >= sheet_layout.ZERO_MM
            assert (f"{plan.kind}-{start}-{end}" in drawn) == long_enough, (start, end)
        keys = [item.key for items in layers.values() for item in items if isinstance(item, Arrow)]
        assert len(keys) == len(set(keys))


def test_a_zero_vector_is_left_out_and_its_ends_share_a_label(slider_driven):
    # The rod moves at a steady speed: aA = 0, so a stands at the pole of the acceleration plan.
    sheet = plan_sheet(slider_driven, 2)
    assert abs(sheet.acceleration.mm("a")) < sheet_layout.ZERO_MM
    layers = layers_of(sheet)
    assert "acceleration-p-a" not in arrows(layers, "acceleration")
    assert all(a.length >= sheet_layout.ZERO_MM for a in arrows(layers, "").values())
    assert "p, a" in [t.text for t in layers["acceleration-labels"]]


def test_vbc_equal_to_vb_is_drawn_once(ratchet):
    # C is a frame point, so vBC is laid off from p to b: the same vector as vB.
    sheet = plan_sheet(ratchet, 5)
    laid = [(v.start, v.end) for step in sheet.velocity.steps for v in step.vectors]
    assert laid.count(("p", "b")) == 2
    shafts = [a for a in arrows(layers_of(sheet), "velocity").values()
              if a.length == pytest.approx(abs(sheet.velocity.mm("b")), abs=1e-9)]
    assert len(shafts) == 1


def test_every_plan_letter_is_labelled_exactly_once(sheet):
    layers = layers_of(sheet)
    for plan, pole in ((sheet.velocity, sheet.velocity_pole), (sheet.acceleration, sheet.acceleration_pole)):
        written = Counter(letter for text in layers[f"{plan.kind}-labels"] for letter in text.text.split(", "))
        expected = Counter(pole if letter == "p" else letter for letter in plan.points)
        assert written == expected


@pytest.mark.parametrize("name", ["ratchet", "six_bar", "slider_driven"])
def test_every_position_is_lettered_once_with_no_texts_overlapping(name, request):
    analysis = request.getfixturevalue(name)
    for index in range(analysis.motion.count):
        sheet = plan_sheet(analysis, index)
        layers = sheet_layout.layout(sheet)
        named = {layer.name: layer.items for layer in layers}
        for plan, pole in ((sheet.velocity, sheet.velocity_pole), (sheet.acceleration, sheet.acceleration_pole)):
            written = Counter(letter for text in named[f"{plan.kind}-labels"] for letter in text.text.split(", "))
            assert written == Counter(pole if letter == "p" else letter for letter in plan.points), index
        boxes = [text_box(item) for layer in layers for item in layer.items if isinstance(item, Text)]
        assert all(a.intersection(b).area == 0.0 for a, b in itertools.combinations(boxes, 2)), index


def test_each_label_stands_near_its_point(sheet):
    layers = layers_of(sheet)
    for plan, pole in ((sheet.velocity, sheet.velocity_pole), (sheet.acceleration, sheet.acceleration_pole)):
        where = on_paper(layers, plan)
        for text in layers[f"{plan.kind}-labels"]:
            letter = text.text.split(", ")[0]
            point = where("p" if letter == pole else letter)
            # Within the outermost ring the labeller tries: the letter's gap plus 2.5 letter heights.
            assert text_box(text).distance(_point(point)) <= 1.2 + 2.5 * text.size + 1e-6, text.text


def test_no_two_texts_on_the_sheet_overlap(sheet):
    texts = [item for layer in sheet_layout.layout(sheet) for item in layer.items if isinstance(item, Text)]
    boxes = [text_box(t) for t in texts]
    for (a, box_a), (b, box_b) in itertools.combinations(zip(texts, boxes), 2):
        assert box_a.intersection(box_b).area == 0.0, (a.text, b.text)


def test_the_three_drawings_stand_side_by_side_without_overlap(sheet):
    layers = sheet_layout.layout(sheet)
    spans = []
    for prefix in ("mechanism-", "velocity-", "acceleration-"):
        xmin, _, xmax, _ = bounds_of(item for layer in layers if layer.name.startswith(prefix) for item in layer.items)
        spans.append((xmin, xmax))
    assert spans[0][1] < spans[1][0] and spans[1][1] < spans[2][0]


def test_each_line_of_action_runs_thin_to_its_crossing_and_dashed_beyond(ratchet):
    sheet = plan_sheet(ratchet, 5)
    layers = layers_of(sheet)
    for plan in (sheet.velocity, sheet.acceleration):
        where = on_paper(layers, plan)
        lines = [item for item in layers[f"{plan.kind}-lines"] if isinstance(item, Polyline)]
        for step in plan.steps:
            for line in step.lines:
                crossing = where("b")
                solid = [p for p in lines if not p.stroke.dash and not p.closed and _ends(p) == pytest.approx((where(line.through), crossing), abs=1e-9)]
                dashed = [p for p in lines if p.stroke.dash and complex(*p.points[0]) == pytest.approx(crossing, abs=1e-9)
                          and _direction(p) == pytest.approx(_unit(crossing - where(line.through)), abs=1e-9)]
                assert len(solid) == 1 and len(dashed) == 1, line.meaning
                assert max(p.stroke.width for p in solid + dashed) < 0.35


def test_the_similar_figure_of_the_coupler_is_drawn(ratchet):
    # abe ∼ ABE: the coupler's triangle on both plans.
    sheet = plan_sheet(ratchet, 5)
    layers = layers_of(sheet)
    for plan in (sheet.velocity, sheet.acceleration):
        where = on_paper(layers, plan)
        corners = {complex(round(where(letter).real, 6), round(where(letter).imag, 6)) for letter in "abe"}
        figures = [{complex(round(x, 6), round(y, 6)) for x, y in item.points}
                   for item in layers[f"{plan.kind}-lines"] if isinstance(item, Polyline) and item.closed]
        assert corners in figures


def test_the_scales_are_written_under_their_drawings(ratchet, six_bar):
    texts = [t.text for layer in sheet_layout.layout(plan_sheet(ratchet, 5)) for t in layer.items if isinstance(t, Text)]
    assert {"μV = 0.01983 (м/с)/мм", "μa = 0.50575 (м/с²)/мм", "μl = 0.0025 м/мм"} <= set(texts)
    texts = [t.text for layer in sheet_layout.layout(plan_sheet(six_bar, 3)) for t in layer.items if isinstance(t, Text)]
    assert {"μV = 0.01983 (m/s)/mm", "μa = 0.50575 (m/s²)/mm", "μl = 0.0025 m/mm"} <= set(texts)


@pytest.mark.parametrize("value, text", [(2.975 / 150, "0.01983"), (0.50575, "0.50575"), (0.0004, "0.0004"),
                                         (0.001, "0.001"), (1.234e-6, "0.000001234"), (250.0, "250")])
def test_plan_scales_are_written_to_four_significant_digits_or_five_decimals(value, text):
    assert plan_scale_text(value) == text


def test_the_acceleration_pole_is_lettered_as_the_locale_prefers(ratchet, six_bar):
    assert plan_sheet(ratchet, 5).acceleration_pole == "π"   # ru
    assert plan_sheet(six_bar, 3).acceleration_pole == "p"   # en
    labels = layers_of(plan_sheet(ratchet, 5))["acceleration-labels"]
    assert "π" in [t.text.split(", ")[0] for t in labels]


def test_the_mechanism_shows_the_velocity_senses_read_off_the_plan(ratchet):
    sheet = plan_sheet(ratchet, 5)
    drawn = arrows(layers_of(sheet), "mechanism")
    for point in ("A", "B", "E"):
        arrow = drawn[f"mechanism-v-{point}"]
        assert arrow.length == pytest.approx(sheet_layout.SENSE_ARROW_MM)
        assert complex(*arrow.end) - complex(*arrow.start) == pytest.approx(
            sheet_layout.SENSE_ARROW_MM * _unit(sheet.velocity.value(point)), abs=1e-9)
    # Centres of mass get no arrow.
    assert not any(key.startswith("mechanism-v-S") for key in drawn)


def test_the_turning_senses_are_named_on_the_links(ratchet):
    # ω2 is given and ε2 = 0: the crank has a curved arrow for ω only.
    labels = {t.text for t in layers_of(plan_sheet(ratchet, 5))["mechanism-labels"]}
    assert {"ω2", "ω3", "ω4", "ε3", "ε4"} <= labels
    assert "ε2" not in labels


def test_a_step_of_a_new_kind_is_drawn_from_its_record_alone(ratchet):
    # A Coriolis-like step, as the sliding kinds will write it: b → k → d, d found on a line through k.
    sheet = plan_sheet(ratchet, 5)
    plan = sheet.acceleration
    b = plan.points["b"]
    k, d = b + 10.0 * plan.scale * 1j, b + (10.0j + 25.0) * plan.scale
    step = Step("aD = aB + aDBᵏ + aDBʳ", (LaidVector("b", "k", "aDBᵏ"), LaidVector("k", "d", "aDBʳ"),
                                         LaidVector("p", "d", "aD")),
                lines=(DrawnLine("k", 1 + 0j, "∥ guide"),), fixes=("k", "d"), crossing_deg=90.0)
    extended = dataclasses.replace(plan, points={**plan.points, "k": k, "d": d}, steps=plan.steps + (step,),
                                   images={**plan.images, "D": "d"})
    layers = layers_of(dataclasses.replace(sheet, acceleration=extended))
    drawn = arrows(layers, "acceleration")
    assert drawn["acceleration-b-k"].length == pytest.approx(10.0, abs=1e-9)
    assert drawn["acceleration-k-d"].length == pytest.approx(25.0, abs=1e-9)
    assert "acceleration-p-d" in drawn
    written = [letter for t in layers["acceleration-labels"] for letter in t.text.split(", ")]
    assert written.count("k") == 1 and written.count("d") == 1
    where = on_paper(layers, extended)
    assert any(p.stroke.dash and complex(*p.points[0]) == pytest.approx(where("d"), abs=1e-9)
               for p in layers["acceleration-lines"] if isinstance(p, Polyline))


def test_the_svg_is_the_same_byte_for_byte_and_its_ids_are_unique(ratchet):
    first, second = plan_svg(ratchet, 5), plan_svg(ratchet, 5)
    assert first == second
    ids = re.findall(r' id="([^"]+)"', first)
    assert len(ids) == len(set(ids))
    assert {"velocity-p-b", "acceleration-p-b", "velocity-vectors", "acceleration-labels"} <= set(ids)


def test_given_plans_are_drawn_as_given(ratchet):
    sheet = plan_sheet(ratchet, 11)
    assert plan_svg(ratchet, 11, sheet.velocity, sheet.acceleration) == plan_svg(ratchet, 11)


def test_a_position_out_of_range_is_refused(ratchet):
    with pytest.raises(IndexError, match="no position at index 12"):
        plan_sheet(ratchet, 12)


def test_the_plan_of_positions_still_draws(ratchet):
    assert positions_svg(ratchet).startswith("<svg")


def test_an_arrowhead_is_the_unit_symbol_placed_with_its_tip_at_the_end():
    arrow = Arrow((0.0, 0.0), (30.0, 40.0), head=3.5)
    assert arrow.length == 50.0
    assert arrow.tip().points == place(((0.0, 0.0), (-1.0, 0.17), (-0.82, 0.0), (-1.0, -0.17)), (30.0, 40.0),
                                       math.atan2(40.0, 30.0), 3.5)
    assert arrow.tip().points[0] == (30.0, 40.0)
    # The shaft stops inside the head, so its round cap cannot show past the tip.
    assert math.dist(arrow.shaft().points[-1], arrow.end) == pytest.approx(0.7 * 3.5)
    assert arrowhead((1.0, 2.0), 0.0, 2.0).points[0] == (1.0, 2.0)


def test_a_short_vector_gets_a_smaller_head():
    short = Arrow((0.0, 0.0), (3.0, 0.0), head=3.5)
    assert short.head_length == pytest.approx(0.4 * 3.0)
    assert short.shaft().points[-1][0] > 0.0


def _ends(polyline):
    return complex(*polyline.points[0]), complex(*polyline.points[-1])


def _direction(polyline):
    start, end = _ends(polyline)
    return _unit(end - start)


def _unit(value):
    return value / abs(value)


def _point(value):
    from shapely.geometry import Point
    return Point(value.real, value.imag)
