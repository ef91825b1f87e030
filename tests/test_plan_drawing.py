"""The plan sheet of one position, tested on its primitives: what is drawn, where, and how long.

The sheet is laid out from the plan records (graphplan.plans); these tests read the layers the
layout returns, find the vectors by their keys (``velocity-p-b``) and compare their lengths in
millimetres with the plan's values over its scale, check that every plan point is lettered once and
no two texts overlap, that a zero vector is left out, and that the SVG is the same byte for byte. On
every fixture's sheets: no label covers another, a leader, another point, an arrowhead or a block;
every word is the scene's locale's; each drawing stands in its own field.
"""

import dataclasses
import functools
import itertools
import math
import re
import warnings
from collections import Counter
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from shapely.geometry import LineString, Point
from shapely.geometry import Polygon as ShapelyPolygon

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.plans import PLAN_FIELD_MM, DrawnLine, LaidVector, LineMeaning, Step
from graphplan.render import labels, linkage, positions
from graphplan.render import plans as sheet_layout
from graphplan.render.drawings import (
    plan_sheet,
    plan_svg,
    positions_plan,
    positions_svg,
)
from graphplan.render.labels import text_box
from graphplan.render.primitives import (
    Arrow,
    Circle,
    Polyline,
    Stroke,
    Text,
    arrowhead,
    bounds_of,
    curved_arrow,
    place,
    text_width,
)
from graphplan.render.script_runs import script_runs, width_em
from graphplan.render.svg import FONT_FAMILY
from graphplan.scene import loads

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


def test_each_label_stands_beside_its_point_or_is_led_to_it(sheet):
    layers = layers_of(sheet)
    for plan, pole in ((sheet.velocity, sheet.velocity_pole), (sheet.acceleration, sheet.acceleration_pole)):
        where = on_paper(layers, plan)
        leaders = layers[f"{plan.kind}-leaders"]
        for text in layers[f"{plan.kind}-labels"]:
            letter = text.text.split(", ")[0]
            point = where("p" if letter == pole else letter)
            distance = text_box(text).distance(_point(point))
            beside = 1.2 + max(labels.BESIDE_SHARES) * text.size + 1e-6
            led = [line for line in leaders if abs(complex(*line.points[0]) - point) <= labels.LEADER_CLEARANCE + 1e-6
                   and text_box(text).distance(_point(complex(*line.points[-1]))) <= 0.5]
            assert distance <= beside or len(led) == 1, text.text
            # Within the outermost ring the labeller tries.
            assert distance <= 1.2 + max(labels.APART_SHARES) * text.size + 1e-6, text.text


def test_a_label_wider_than_its_rings_are_far_is_never_led_from_under_itself():
    """A long name set off obliquely on a ring led to its point reached back over the point: its leader had no
    length and no direction (0/0), and the NaN it drew made shapely fail on a joint named with 60 letters."""
    name = "B" + "x" * 80
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        placed = labels.place_labels([labels.Anchor((0.0, 0.0), name, prefer=math.pi / 32)], [])
    (text,) = placed.texts
    assert text.text == name and not text_box(text).intersects(Point(0.0, 0.0))
    assert all(np.isfinite(leader.points).all() for leader in placed.leaders)


def test_a_joint_with_a_long_name_is_lettered_on_its_sheet():
    long_name = "B" + "x" * 60
    text = Path(f"{FIXTURES}/ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    text = re.sub(r"^(velocity|acceleration) += .*$", "", text.replace('"B"', f'"{long_name}"'), flags=re.MULTILINE)
    sheet = plan_sheet(analyse(loads(text)), 5)
    written = [item.text for layer in sheet_layout.layout(sheet) for item in layer.items if isinstance(item, Text)]
    assert long_name in written and long_name.lower() in written


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
                lines=(DrawnLine("k", 1 + 0j, LineMeaning("guide")),), fixes=("k", "d"), crossing_deg=90.0)
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


@pytest.mark.parametrize("sweep_deg", [30.0, 170.0, 190.0, 270.0, 355.0, -30.0, -170.0, -190.0, -270.0, -355.0])
def test_a_curved_arrow_runs_its_whole_sweep_but_for_its_head(sweep_deg):
    centre, radius, start, head = (5.0, -3.0), 10.0, 0.4, 2.5
    shaft, tip = curved_arrow(centre, radius, start, math.radians(sweep_deg), Stroke(0.35), head)
    points = np.array(shaft.points) - centre
    assert np.hypot(points[:, 0], points[:, 1]) == pytest.approx(radius)
    # Each point's angle turned from the start in the arrow's sense, followed round without jumps.
    turned = math.copysign(1.0, sweep_deg) * (np.unwrap(np.arctan2(points[:, 1], points[:, 0])) - start)
    assert turned[0] == pytest.approx(0.0, abs=1e-12)
    assert np.all(np.diff(turned) > 0)
    # The shaft ends under the head: short of the tip by less than the head's length, and not past it.
    assert math.radians(abs(sweep_deg)) - head / radius < turned[-1] < math.radians(abs(sweep_deg))
    end = start + math.radians(sweep_deg)
    assert tip.points[0] == pytest.approx((centre[0] + radius * math.cos(end), centre[1] + radius * math.sin(end)))


def test_a_short_vector_gets_a_smaller_head():
    short = Arrow((0.0, 0.0), (3.0, 0.0), head=3.5)
    assert short.head_length == pytest.approx(0.4 * 3.0)
    assert short.shaft().points[-1][0] > 0.0


# Every fixture's sheets: legible, in the scene's language, each drawing in its field.

ALL_FIXTURES = sorted(path.stem for path in Path(FIXTURES).glob("*.toml"))
SIX_BARS = ("shaper_six_bar", "stephenson_six_bar")


@functools.cache
def analysed(name: str, automatic: bool = False):
    scene = graphplan.load(f"{FIXTURES}/{name}.toml")
    if automatic:  # the scales chosen to fit the plans' fields, not given by the scene
        drawing = dataclasses.replace(scene.drawing, velocity_pole=None, acceleration_pole=None,
                                      velocity_scale=None, acceleration_scale=None)
        scene = dataclasses.replace(scene, drawing=drawing)
    return analyse(scene)


def _checked_positions(name):
    """The plan positions of a fixture; every position of the crowded six-bars."""
    analysis = analysed(name)
    return range(analysis.motion.count) if name in SIX_BARS else [plan.index for plan in analysis.plans]


@pytest.mark.parametrize("name", ALL_FIXTURES)
def test_no_label_covers_another_label_a_leader_a_point_an_arrowhead_or_a_block(name):
    analysis = analysed(name)
    for index in _checked_positions(name):
        sheet = plan_sheet(analysis, index)
        layers = sheet_layout.layout(sheet)
        for drawing in ("mechanism", "velocity", "acceleration"):
            items = [item for layer in layers if layer.name.startswith(f"{drawing}-") for item in layer.items]
            texts = list(_named(layers)[f"{drawing}-labels"])
            boxes = [text_box(text) for text in texts]
            where = f"{name} position {sheet.number}, {drawing}"
            for (a, box_a), (b, box_b) in itertools.combinations(zip(texts, boxes), 2):
                assert not box_a.intersects(box_b), (where, a.text, b.text)
            for leader in _named(layers)[f"{drawing}-leaders"]:
                assert not any(box.intersects(LineString(leader.points)) for box in boxes), (where, leader)
            heads = [ShapelyPolygon(item.tip().points) for item in items if isinstance(item, Arrow)]
            heads += [ShapelyPolygon(item.points) for item in items
                      if isinstance(item, Polyline) and item.closed and item.fill and item.stroke.width <= 0.1]
            blocks = [ShapelyPolygon(item.points) for item in items
                      if isinstance(item, Polyline) and item.closed and item.fill == "white"]
            dots = [item for item in _named(layers)[f"{drawing}-points"] if isinstance(item, Circle)]
            if drawing != "mechanism":
                assert len(dots) == len(texts)  # a dot and a label for each place of the plan, in one order
            for k, (text, box) in enumerate(zip(texts, boxes)):
                assert not any(box.intersects(head) for head in heads), (where, text.text)
                assert not any(box.intersection(block).area > 0.5 for block in blocks), (where, text.text)
                # On the mechanism a named point's own dot is the one nearest its label.
                own = dots[k] if drawing != "mechanism" else min(
                    dots, key=lambda dot: box.distance(_point(complex(*dot.centre))), default=None)
                others = [dot for dot in dots if dot is not own]
                assert not any(box.intersects(_point(complex(*dot.centre)).buffer(dot.radius)) for dot in others), \
                    (where, text.text)


def _locale_patterns(locale):
    """Each string of ``locale`` as a pattern, its placeholders standing for numbers."""
    patterns = []
    for template in strings(locale).values():
        pattern = re.escape(template).replace(r"\{value\}", r"[0-9.]+").replace(r"\{number\}", r"[0-9]+")
        patterns.append(re.compile(pattern))
    return patterns


# The notation, the same in every language: points (B, S3, p′), plan letters (n3, k5), ω2, ε4, π, and
# the numbers of the positions (an extreme between two named after the one it follows, 5′).
NOTATION = re.compile(r"[0-9]+′?|(?:[A-Za-z][A-Za-z0-9]*′*|[ωε][0-9]+|π)(?:, (?:[A-Za-z][A-Za-z0-9]*′*|π))*")


def _words_of(layers):
    return [item.text for layer in layers for item in layer.items if isinstance(item, Text)]


def _localised(locale: str):
    text = (Path(FIXTURES) / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    scene, count = re.subn(r'(?m)^locale\s*=\s*"ru"', f'locale = "{locale}"', text)
    assert count == 1
    return analyse(loads(scene))


@pytest.mark.parametrize("locale", ["ru", "zh", "en"])
def test_every_word_on_the_sheets_comes_from_the_scenes_locale(locale):
    # The ratchet scene's title is English; its sheets must not show it in any language but English's own words.
    analysis = _localised(locale)
    own = _locale_patterns(locale)
    foreign = [p for other in ("en", "ru", "zh") if other != locale for p in _locale_patterns(other)
               if not any(p.pattern == q.pattern for q in own)]
    plan = analysis.plans[0]
    sheets = [sheet_layout.layout(plan_sheet(analysis, plan.index)), positions.layout(positions_plan(analysis))]
    for words in map(_words_of, sheets):
        for word in words:
            if not NOTATION.fullmatch(word):
                assert any(p.fullmatch(word) for p in own), (locale, word)
                assert not any(p.fullmatch(word) for p in foreign), (locale, word)
        assert analysis.scene.title not in words


def test_chinese_is_set_in_a_cjk_font_and_the_font_list_has_one_after_the_latin_fonts():
    families = [family.strip() for family in FONT_FAMILY.split(",")]
    assert families[0] == "DejaVu Sans" and "Noto Sans CJK SC" in families[1:]
    svg = plan_svg(_localised("zh"), _localised("zh").plans[0].index)
    root = ElementTree.fromstring(svg)
    # A line is one text in one font, or (mixing Chinese with symbols) its runs, each a tspan in its own font.
    runs = [element for element in root.iter() if element.tag.endswith("tspan")
            or element.tag.endswith("text") and element.text]
    if width_em(script_runs("速度 v"), "normal") is not None:  # the fonts to measure a mixed line by are here
        assert any(element.tag.endswith("tspan") for element in runs)
    # A symbol's index is a run in its line's font, which it takes from its text.
    line_font = {run: text.get("font-family") for text in root.iter() if text.tag.endswith("text") for run in text}
    for element in runs:
        chinese = any("\u4e00" <= character <= "\u9fff" for character in element.text)
        first = (element.get("font-family") or line_font[element]).split(",")[0]
        assert first == ("Noto Sans CJK SC" if chinese else "DejaVu Sans"), element.text


def test_text_boxes_hold_wide_letters_and_ideographs():
    # DejaVu Sans draws "m" 0.97 em wide and a digit 0.64 em; an ideograph fills its em square.
    em = 4.0 / 0.72
    assert text_width("m", 4.0) >= 0.95 * em and text_width("8", 4.0) >= 0.636 * em
    assert text_width("速度", 4.0) == pytest.approx(2 * em)
    assert text_width("Ab", 4.0, "bold") > text_width("Ab", 4.0)


@pytest.mark.parametrize("name", ALL_FIXTURES)
def test_each_drawing_stands_in_its_own_field_and_the_captions_on_one_line(name):
    analysis = analysed(name)
    for plan in analysis.plans:
        arrangement = sheet_layout.arrange(plan_sheet(analysis, plan.index))
        fields = arrangement.fields
        assert list(fields) == ["mechanism", "velocity", "acceleration"]
        for (_, _, right, _), (left, _, _, _) in itertools.pairwise(fields.values()):
            assert right < left
        baselines = set()
        for drawing, (x0, y0, x1, y1) in fields.items():
            drawn = [item for layer in arrangement.layers if layer.name.startswith(f"{drawing}-")
                     and layer.name != f"{drawing}-caption" for item in layer.items]
            bx0, by0, bx1, by1 = bounds_of(drawn)
            assert x0 - 1e-9 <= bx0 and bx1 <= x1 + 1e-9 and y0 - 1e-9 <= by0 and by1 <= y1 + 1e-9, drawing
            caption = _named(arrangement.layers)[f"{drawing}-caption"]
            baselines.add(round(caption[0].at[1], 9))
            assert x0 <= bounds_of(caption)[0] and bounds_of(caption)[2] <= x1
        assert len(baselines) == 1


def _drawing_layers(arrangement, drawing):
    return [layer for layer in arrangement.layers
            if layer.name.startswith(f"{drawing}-") and layer.name != f"{drawing}-caption"]


@pytest.mark.parametrize("name", ALL_FIXTURES)
@pytest.mark.parametrize("shape", ["stacked", "beside"])
def test_arranged_otherwise_the_drawings_are_the_row_s_moved_each_in_its_field_with_its_caption_clear(name, shape):
    """The mechanism above the plans, or beside them with the velocity plan over the acceleration plan: each
    drawing is the row's drawing moved whole, inside its field, its caption under it and clear of every other
    drawing and caption."""
    analysis = analysed(name)
    plan = analysis.plans[-1]
    sheet = plan_sheet(analysis, plan.index, plan.velocity, plan.acceleration)
    row, other = sheet_layout.arrange(sheet), sheet_layout.arrange(sheet, shape)
    assert list(other.fields) == list(row.fields)
    boxes = {}
    for drawing, (x0, y0, x1, y1) in other.fields.items():
        moved, first = _drawing_layers(other, drawing), _drawing_layers(row, drawing)
        assert [layer.name for layer in moved] == [layer.name for layer in first]
        shift = [a - b for a, b in zip(bounds_of(x for layer in moved for x in layer.items),
                                       bounds_of(x for layer in first for x in layer.items), strict=True)]
        for one, two in zip(moved, first, strict=True):
            if one.items:
                offset = [a - b for a, b in zip(bounds_of(one.items), bounds_of(two.items), strict=True)]
                assert offset == pytest.approx([shift[0], shift[1]] * 2, abs=1e-9), one.name
        drawn = bounds_of(x for layer in moved for x in layer.items)
        assert x0 - 1e-9 <= drawn[0] and drawn[2] <= x1 + 1e-9 and y0 - 1e-9 <= drawn[1] and drawn[3] <= y1 + 1e-9
        caption = bounds_of(_named(other.layers)[f"{drawing}-caption"])
        assert caption[3] < y0 and x0 - 1e-9 <= caption[0] and caption[2] <= x1 + 1e-9, drawing
        boxes[drawing], boxes[f"{drawing}-caption"] = drawn, caption
    boxes.update((f"{drawing}-field", field) for drawing, field in other.fields.items())
    for (one, a), (two, b) in itertools.combinations(boxes.items(), 2):
        if one.split("-")[0] != two.split("-")[0]:
            assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]), (one, two)
    mechanism, velocity, acceleration = (other.fields[k] for k in ("mechanism", "velocity", "acceleration"))
    # A caption stands as far from the drawing under it as two drawings stand apart.
    if shape == "stacked":
        assert boxes["mechanism-caption"][1] - max(velocity[3], acceleration[3]) >= sheet_layout.GAP_MM - 1e-9
        assert acceleration[0] - velocity[2] == pytest.approx(sheet_layout.GAP_MM)
    else:
        assert min(velocity[0], acceleration[0]) - mechanism[2] == pytest.approx(sheet_layout.GAP_MM)
        assert boxes["velocity-caption"][1] - acceleration[3] >= sheet_layout.GAP_MM - 1e-9


@pytest.mark.parametrize("name", ALL_FIXTURES)
def test_with_automatic_scales_each_plan_fills_its_field_and_the_two_plans_match(name):
    analysis = analysed(name, automatic=True)
    for plan in analysis.plans:
        arrangement = sheet_layout.arrange(plan_sheet(analysis, plan.index, plan.velocity, plan.acceleration))
        sizes = {}
        for kind in ("velocity", "acceleration"):
            x0, _, x1, _ = arrangement.fields[kind]
            assert x1 - x0 == pytest.approx(sheet_layout.plan_field_mm()), kind  # the field did not have to grow
            drawn = [item for layer in arrangement.layers if layer.name in (f"{kind}-vectors", f"{kind}-points")
                     for item in layer.items]
            bx0, by0, bx1, by1 = bounds_of(drawn)
            sizes[kind] = max(bx1 - bx0, by1 - by0)
            assert PLAN_FIELD_MM / 3 <= sizes[kind] <= PLAN_FIELD_MM + 1.0, (kind, plan.number, sizes[kind])
        assert max(sizes.values()) <= 3 * min(sizes.values()), sizes


def _linkage(name, number):
    """The mechanism of a fixture's plan position drawn bold at 1 mm per mm, and where its points are."""
    analysis = analysed(name)
    plan = next(p for p in analysis.plans if p.number == number)
    motion = analysis.motion
    items = linkage.links_at(motion, plan.index, linkage.outline_points(analysis.mechanism, motion),
                             lambda r: (1000 * r.real, 1000 * r.imag), Stroke(0.8), bold=True)
    return items, {name: 1000 * r for name, r in plan.positions.items()}


def test_every_joint_of_two_moving_links_has_its_pin():
    # D joins the shaper's lever and rod; E joins the Stephenson coupler and the output dyad: both are also
    # named points, and a named point that is a joint is still a pin.
    for name, number, joint in (("shaper_six_bar", 3, "D"), ("stephenson_six_bar", 3, "E")):
        items, at = _linkage(name, number)
        pins = [complex(*item.centre) for item in items if isinstance(item, Circle)]
        assert any(abs(pin - at[joint]) < 1e-9 for pin in pins), name


def test_a_levers_point_under_the_block_gets_no_arrow_of_its_own():
    analysis = analysed("quick_return_slotted_lever")
    drawn = arrows(layers_of(plan_sheet(analysis, analysis.plans[0].index)), "mechanism")
    assert "mechanism-v-A" in drawn and "mechanism-v-A4" not in drawn


@pytest.mark.parametrize("variant", ["ratchet+RRP-on-rocker", "ratchet+triad-slider-on-rocker"])
def test_a_moving_guide_s_point_under_the_slider_has_its_vector_from_the_pole(variant):
    """The guide link's point under the slider (k4), put on the plan by similarity, stood with no vector from
    the pole while the lever's point under a block (a4) had one: a student draws pk4 as vK4 and aK4 too."""
    from test_motion_against_finite_differences import VARIANTS

    analysis = analyse(VARIANTS[variant]())
    position = analysis.plans[0]
    layers = layers_of(plan_sheet(analysis, position.index))
    for plan in (position.velocity, position.acceleration):
        on_guides = [step.similarity.letter for step in plan.steps if step.similarity is not None
                     and step.similarity.letter not in plan.images.values()]
        assert on_guides, variant
        for letter in on_guides:
            assert f"{plan.kind}-p-{letter}" in arrows(layers, plan.kind), (plan.kind, letter)


def test_the_scotch_yoke_is_drawn_with_its_slot_across_and_its_rod():
    items, at = _linkage("scotch_yoke", 9)
    links = [item for item in items if isinstance(item, Polyline) and not item.fill]
    # No triangle A–B–P: the yoke is the rod B–P and the slot, which runs along the slot's line through B past A.
    assert not [item for item in links if item.closed]
    a, b = at["A"], at["B"]
    (slot,) = [item for item in links if _on_line(item, b, a - b)]
    along = sorted(((complex(*end) - b) / (a - b)).real for end in slot.points)
    assert along[0] < 0 and along[1] > 1, "the slot runs across the yoke, past B and past the block"
    assert [item for item in links if _on_line(item, b, at["P"] - b)], "the rod B–P"
    # B is where the slot crosses the guide, no joint: the block there slides, it has no pin.
    assert not [item for item in items if isinstance(item, Circle) and abs(complex(*item.centre) - b) < 1e-9]


def test_a_frame_guide_is_hatched_along_its_block_s_travel_away_from_the_links():
    # The engine's guide runs through the crank's pivot O: hatched along the whole line, its ground would be
    # crossed by the crank and the rod whenever they turn below it.  r = 0.05 m, l = 0.19 m, μl = 0.001 m/mm.
    analysis = analysed("engine_slider_crank")
    r, l = 50.0, 190.0  # mm
    sides = set()
    for plan in analysis.plans:
        layers = layers_of(plan_sheet(analysis, plan.index))
        thin = [item for item in layers["mechanism-frame"] if isinstance(item, Polyline) and len(item.points) == 2
                and abs(item.points[0][1] - item.points[1][1]) < 1e-9]
        (pivot,) = [item.centre for item in layers["mechanism-frame"] if isinstance(item, Circle)]
        pins = [item.centre for item in layers["mechanism-links"] if isinstance(item, Circle)]
        (crank_pin,) = [pin for pin in pins if math.dist(pin, pivot) == pytest.approx(r)]
        (piston_pin,) = [pin for pin in pins if pin != crank_pin]
        # The guide line runs through B; the ground line is the long one beside it, half a block's height off.
        y = piston_pin[1]
        ground = max((item for item in thin if abs(item.points[0][1] - y) > 1.0),
                     key=lambda item: abs(item.points[1][0] - item.points[0][0]))
        side = math.copysign(1.0, ground.points[0][1] - y)
        assert abs(ground.points[0][1] - y) == pytest.approx(2.5)
        assert side == -math.copysign(1.0, crank_pin[1] - y), f"position {plan.number}: the ground under the crank"
        sides.add(side)
        xs = sorted(point[0] - pivot[0] for point in ground.points)
        # From where the block's travel begins (l − r, less the 8 mm the block overhangs), past the block.
        assert r < xs[0] == pytest.approx(l - r - 8.0), f"position {plan.number}: the ground beyond the crank's reach"
        assert xs[1] > piston_pin[0] - pivot[0] + 5.0, f"position {plan.number}: the ground under the block"
    assert sides == {-1.0, 1.0}, "the crank turns above the guide in one plan position and below it in the other"



def test_a_scotch_yoke_s_guide_is_hatched_where_its_rod_always_runs_not_over_the_crank():
    # The yoke's guide runs through the crank's pivot O, and the block's travel (±r about O) over it: a ground
    # hatched along the travel crossed the crank circle.  The rod B–P (0.40 m) covers the guide's line from r
    # above O to 0.40 − r at every position; the ground stands there, 8 mm clear of the slot and the rod's end.
    # r = 0.075 m, μl = 0.002 m/mm: 37.5 mm and 200 mm on the paper.
    analysis = analysed("scotch_yoke")
    r, rod, block = 37.5, 200.0, 8.0
    for plan in analysis.plans:
        layers = layers_of(plan_sheet(analysis, plan.index))
        (pivot,) = [item.centre for item in layers["mechanism-frame"] if isinstance(item, Circle)]
        ground = [item for item in layers["mechanism-frame"] if isinstance(item, Polyline) and len(item.points) == 2
                  and all(abs(abs(x - pivot[0]) - 2.5) < 1e-6 for x, _ in item.points)]
        assert len(ground) == 1, f"position {plan.number}: one ground line beside the vertical guide"
        reach = sorted(abs(y - pivot[1]) for _, y in ground[0].points)
        assert reach[0] == pytest.approx(r + block), f"position {plan.number}: the ground clear of the crank circle"
        assert reach[1] == pytest.approx(rod - r - block), f"position {plan.number}: short of the rod's lowest end"
        signs = {math.copysign(1.0, y - pivot[1]) for _, y in ground[0].points}
        assert len(signs) == 1, f"position {plan.number}: the ground on one side of O, the rod's"

def _on_line(polyline, through, direction):
    return all(abs(((complex(*point) - through) / direction).imag) < 1e-6 for point in polyline.points)


def _named(layers):
    return {layer.name: layer.items for layer in layers}


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


def test_a_plan_of_positions_of_many_draws_one_in_every_few_and_each_plan_sheet_s_position():
    scene = graphplan.load(f"{FIXTURES}/ratchet_crank_rocker.toml")
    scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, count=360, plans=(5, 123)))
    analysis = analyse(scene)
    plan = positions_plan(analysis)
    # 360 positions, at most 36 drawn: every tenth (numbered from 0), and the plan sheets' 5 and 123.
    assert plan.numbers == tuple(sorted(set(range(0, 360, 10)) | {5, 123}))
    assert plan.caption.endswith(strings(scene.locale)["positions_thinned"].format(step=10, count=360))
    named = {layer.name: layer.items for layer in positions.layout(plan)}
    numbers = {text.text: text for text in named["labels"] if isinstance(text, Text) and text.text.isdigit()}
    assert sorted(map(int, numbers)) == list(plan.numbers)
    # Each number stands by the crank pin A of its own position, not of its neighbour in the drawing.
    mm_per_m = 1.0 / plan.length_scale
    pin = analysis.motion.point("A").r * mm_per_m
    for number, text in numbers.items():
        assert text_box(text).distance(Point(pin[int(number)])) < 12.0, number
    # The grey outlines pass through the crank pin at the drawn positions, and at no other of the 360.
    vertices = [point for item in named["positions"] if isinstance(item, Polyline) for point in item.points]
    through = {n for n in range(360) if any(math.dist(vertex, tuple(pin[n])) < 1e-6 for vertex in vertices)}
    assert through == set(plan.numbers)


def test_a_plan_of_positions_of_a_few_draws_them_all(ratchet):
    plan = positions_plan(ratchet)
    assert plan.numbers == tuple(range(12)) and ";" not in plan.caption


def test_a_coupler_whose_centre_carries_another_links_joint_is_drawn_as_the_plate_through_it():
    """Link 3's centre E is where rod 5 hangs from it: left out of the outline as a centre, E floated in empty
    space beside a bare bar AB.  It is a corner of the plate ABE, as the similarity theorem's triangle is."""
    from graphplan.scene import loads as scene_from_text

    text = """
[frame]
points = { O = [0.0, 0.0], C = [0.40, 0.05] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.10
omega = 12.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.35, 0.25]
assembly = "left"
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["E", "F"]
length = 0.20
guide = { link = 4, through = "C", angle = 20.0 }
assembly = "forward"
[points]
E = { link = 3, from = "A", toward = "B", at = 0.20, offset = -0.08 }
S4 = { link = 4, from = "C", toward = "B", at = 0.1 }
[links.3]
mass = 4.0
centre = "E"
[links.4]
mass = 3.0
centre = "S4"
[positions]
count = 12
plans = [2]
"""
    analysis = analyse(scene_from_text(text))
    outlines = linkage.outline_points(analysis.mechanism, analysis.motion)
    assert set(outlines[3]) == {"A", "B", "E"}
    assert "S4" not in outlines[4]  # a centre that carries no other link stays inside its plate
