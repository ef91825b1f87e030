"""Drawing sheets: formats, frames, title blocks of the three standards, and the drawings placed on them.

Every fixture's kinematics and force sheets are built on A1 and checked as a reader would: the SVG
parses and is the size of the format, every word stands inside the frame, no two drawings and no
drawing and the title block overlap (measured on the placed layers themselves, not on what the
packing recorded), the drawings keep their scales, the title block carries the title and the right
sheet numbers. The title block of each language is checked against its standard: the frame margins
and the block's size (GOST 2.104 and 2.301, GB/T 14689 and 10609.1, ISO 5457 and 7200), the ESKD
form's column lines, and the field labels each standard prints.
"""

import dataclasses
import functools
import itertools
import math
import re
from xml.etree import ElementTree

import cairosvg
import numpy as np
import pytest
from test_dynamics_without_linkage import PRESS

import graphplan
from graphplan.analysis import analyse
from graphplan.errors import SceneError
from graphplan.kinematic_diagrams import FIELD_MM, kinematic_diagrams, of_analysis
from graphplan.locale import strings
from graphplan.render import diagrams as diagrams_layout
from graphplan.render import drawings
from graphplan.render import forces as force_layout
from graphplan.render import plans as plan_layout
from graphplan.render.drawings import length_scale, mechanism_size, plan_sheet, positions_size
from graphplan.render.force_rows import has_heading
from graphplan.render.formats import holds
from graphplan.render.primitives import Arrow, Layer, Polyline, Text, bounds, bounds_of, text_extent
from graphplan.render.sheet import (
    Details,
    Panel,
    course_panels,
    course_sheets,
    diagrams_panel,
    forces_sheet,
    kinematics_panels,
    kinematics_sheet,
    sheet_svg,
)
from graphplan.render.title_block import form_of, labels, scale_text
from graphplan.scales import format_scale

FIXTURES = ["engine_slider_crank", "offset_slider_crank", "quick_return_slotted_lever", "ratchet_crank_rocker",
            "scotch_yoke", "shaper_six_bar", "slider_driven", "stephenson_six_bar", "tangent_mechanism_prp",
            "double_rocker_swing"]
SVG = "{http://www.w3.org/2000/svg}"
# Standard scale factors (m/mm) from 1e-4 to 1: mantissas 1, 2, 2.5, 4, 5 (graphplan.scales).
STANDARD = [mantissa * 10.0 ** power for power in range(-4, 1) for mantissa in (1.0, 2.0, 2.5, 4.0, 5.0)]
# Round-off allowed when a rectangle touches another (mm).
EPS = 1e-6


def analyses_of(name):
    return analyse(graphplan.load(f"fixtures/{name}.toml"))


@functools.cache
def on_a3(name):
    """The fixture's analysis and its sheets on A3, laid out once for the tests that read them (the triad's take
    some 15 s each time: its μl is chosen by laying every sheet out at each μl tried)."""
    analysis = analyses_of(name)
    return analysis, course_sheets(analysis, "A3")


@pytest.fixture(scope="module")
def analyses():
    """Every fixture analysed once for the module."""
    return {name: analyses_of(name) for name in FIXTURES}


def with_scene(analysis, **changes):
    """The analysis with its scene changed (locale, drawing): the sheets read nothing else of it."""
    return dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, **changes))


def with_drawing(analysis, **changes):
    return with_scene(analysis, drawing=dataclasses.replace(analysis.scene.drawing, **changes))


@pytest.fixture(scope="module")
def a1_sheets(analyses):
    """Each fixture's sheets on A1, in the scene's own language."""
    return {name: course_sheets(analysis, "A1", Details(author="A. Student"))
            for name, analysis in analyses.items()}


@pytest.fixture(scope="module")
def ratchet_sheets(analyses):
    """The ratchet's sheets in each language."""
    ratchet = analyses["ratchet_crank_rocker"]
    return {locale: course_sheets(with_scene(ratchet, locale=locale), "A1", Details(author="A. Student"))
            for locale in ("en", "ru", "zh")}


def texts(layers):
    return [item for layer in layers for item in layer.items if isinstance(item, Text)]


def layer(sheet, name):
    return next(layer for layer in sheet.layers if layer.name == name)


def force_drawings_on(sheet):
    """What a sheet's force drawings are: ``lever``, ``body`` (a group cut free), ``polygon``; the heading over
    them (``sheet-title``) is none."""
    found = (re.match(r"forces(?:-friction)?-\d+(?:-\d+)?-(lever|body|polygon)-", item.name) for item in sheet.layers)
    return {match.group(1) for match in found if match}


def forces_to_no_length_scale(sheet):
    """Whether a sheet's drawings are force drawings to no length scale: Zhukovsky's lever at μV, force polygons
    at μF, no group cut free at μl."""
    drawn = force_drawings_on(sheet)
    return bool(drawn) and "body" not in drawn


def held_under_its_heading(part, sheet: str, form: str) -> bool:
    """Whether ``sheet`` holds a diagram that stands apart in a way that keeps its heading: each after the first
    goes on under the title "continued", on one line where the sheet has the room, else broken (its last way bare)."""
    def held(way) -> bool:
        x0, y0, x1, y1 = way.extent
        return holds(sheet, form, x1 - x0, y1 - y0)

    return any(held(way) for way in part.ways if not way.continues or has_heading(way.layers))


def placed_bounds(sheet):
    """The bounds of each placed drawing, from the layers on the sheet that carry its name."""
    names = sorted(sheet.panels, key=len, reverse=True)
    members = {name: [] for name in names}
    for item in sheet.layers:
        owner = next((name for name in names if item.name.startswith(name + "-")), None)
        if owner is not None:
            members[owner].append(item)
    assert all(members.values()), "a placed drawing has no layers on the sheet"
    return {name: bounds(found) for name, found in members.items()}


def view_box(root):
    return [float(value) for value in re.split(r"[\s,]+", root.get("viewBox").strip())]


def overlap(a, b):
    return a[0] < b[2] - EPS and b[0] < a[2] - EPS and a[1] < b[3] - EPS and b[1] < a[3] - EPS


def inside(inner, outer):
    return (inner[0] >= outer[0] - EPS and inner[1] >= outer[1] - EPS and inner[2] <= outer[2] + EPS
            and inner[3] <= outer[3] + EPS)


# Every fixture on A1.

@pytest.mark.parametrize("name", FIXTURES)
def test_every_sheet_is_an_svg_of_the_format(a1_sheets, name):
    for sheet in a1_sheets[name]:
        root = ElementTree.fromstring(sheet.svg())
        assert root.tag == f"{SVG}svg"
        assert (root.get("width"), root.get("height")) == ("841mm", "594mm")
        assert view_box(root) == [0, 0, 841, 594]
        ids = [element.get("id") for element in root.iter() if element.get("id")]
        assert len(ids) == len(set(ids)), "two elements of one sheet share an id"


@pytest.mark.parametrize("name", FIXTURES)
def test_every_word_stands_inside_the_frame(a1_sheets, name):
    for sheet in a1_sheets[name]:
        for text in texts(sheet.layers):
            assert inside(text_extent(text), sheet.frame), f"sheet {sheet.number}: {text.text!r} outside the frame"


@pytest.mark.parametrize("name", FIXTURES)
def test_no_drawing_overlaps_another_or_the_title_block(a1_sheets, name):
    for sheet in a1_sheets[name]:
        drawn = placed_bounds(sheet)
        block = bounds([layer(sheet, "title-block")])
        assert inside(block, sheet.frame)
        for panel, rect in drawn.items():
            assert inside(rect, sheet.frame), f"sheet {sheet.number}: {panel} leaves the frame"
            assert not overlap(rect, block), f"sheet {sheet.number}: {panel} covers the title block"
        for (first, a), (second, b) in itertools.combinations(drawn.items(), 2):
            assert not overlap(a, b), f"sheet {sheet.number}: {first} overlaps {second}"


@pytest.mark.parametrize("name", FIXTURES)
def test_every_fixture_fits_the_sheet_it_names_with_its_diagrams(analyses, name):
    """What a plain run draws: the scene's own format (A1 or A2), the kinematic diagrams among the panels."""
    analysis = analyses[name]
    named = analysis.scene.drawing.sheet
    drawable = analysis.scene.positions.working is not None and analysis.scene.driver.kind == "crank"
    diagrams = (diagrams_panel(analysis, named),) if drawable else ()
    sheets = course_sheets(analysis, diagrams=diagrams)
    width, height = {"A1": (841.0, 594.0), "A2": (594.0, 420.0)}[named]
    for sheet in sheets:
        assert sheet.size == (width, height)
        for text in texts(sheet.layers):
            assert inside(text_extent(text), sheet.frame), f"sheet {sheet.number}: {text.text!r} outside the frame"
        drawn = placed_bounds(sheet)
        for (first, a), (second, b) in itertools.combinations(drawn.items(), 2):
            assert not overlap(a, b), f"sheet {sheet.number}: {first} overlaps {second}"
        assert not any(overlap(rect, sheet.title_block) for rect in drawn.values())


@pytest.mark.parametrize("name", FIXTURES)
def test_sheets_are_numbered_as_one_set_kinematics_first(a1_sheets, analyses, name):
    sheets = a1_sheets[name]
    assert [sheet.number for sheet in sheets] == list(range(1, len(sheets) + 1))
    assert {sheet.count for sheet in sheets} == {len(sheets)}
    kinds = ["forces" if all(panel.startswith("forces-") for panel in sheet.panels) else "kinematics"
             for sheet in sheets]
    assert kinds == sorted(kinds, key=lambda kind: kind == "forces")
    has_forces = any(position.forces is not None for position in analyses[name].plans)
    assert ("forces" in kinds) == has_forces
    # Every plan position's drawings are somewhere on the sheets.
    placed = {panel for sheet in sheets for panel in sheet.panels}
    for position in analyses[name].plans:
        assert any(panel == f"plan-{position.number}" or panel.startswith(f"plan-{position.number}-")
                   for panel in placed)


@pytest.mark.parametrize("name", FIXTURES)
def test_the_title_block_carries_the_title_and_the_sheet_numbers(a1_sheets, analyses, name):
    title_words = analyses[name].scene.title.split()
    for sheet in a1_sheets[name]:
        block = texts([layer(sheet, "title-block")])
        written = " ".join(text.text for text in block)
        assert all(word in written for word in title_words)
        # The fixtures are in English: ISO 7200's sheet field reads "n of N".
        if analyses[name].scene.locale == "en":
            assert f"{sheet.number} of {sheet.count}" in [text.text for text in block]
        assert "A. Student" in [text.text for text in block]


def test_drawings_keep_their_scale_on_the_sheet(analyses):
    """A vector of the velocity plan is as long on the sheet as in the plan sheet laid out alone."""
    analysis = analyses["ratchet_crank_rocker"]
    position = analysis.plans[0]
    alone = plan_layout.arrange(plan_sheet(analysis, position.index, position.velocity, position.acceleration))
    lengths = {item.key: item.length for layer in alone.layers for item in layer.items
               if isinstance(item, Arrow) and item.key}
    assert lengths
    sheets = course_sheets(analysis, "A1")
    on_sheet = {item.key: item.length for sheet in sheets for layer in sheet.layers for item in layer.items
                if isinstance(item, Arrow) and item.key.startswith(f"plan-{position.number}-")}
    for key, length in lengths.items():
        assert on_sheet[f"plan-{position.number}-{key}"] == pytest.approx(length, abs=1e-9)


# The three standards.

# Frame margins (left, bottom, right, top) on A1 and the title block's size, as the standards give them:
# GOST 2.104 (20 for binding, 5) with form 1 185 × 55; GB/T 14689 (a = 25, c = 10 on A1) with
# GB/T 10609.1's 180 × 56; ISO 5457 (20, 10) with an ISO 7200 block 180 mm wide.
STANDARD_FRAMES = {"ru": ((20, 5, 5, 5), (185, 55)), "zh": ((25, 10, 10, 10), (180, 56)),
                   "en": ((20, 10, 10, 10), (180, None))}
# The field labels each standard prints (GOST 2.104 form 1, GB/T 10609.1, ISO 7200).
STANDARD_LABELS = {
    "ru": ["Изм.", "Лист", "№ докум.", "Подп.", "Дата", "Разраб.", "Пров.", "Т.контр.", "Н.контр.", "Утв.", "Лит.",
           "Масса", "Масштаб", "Листов"],
    "zh": ["标记", "处数", "分区", "更改文件号", "签名", "年、月、日", "设计", "审核", "工艺", "批准", "标准化",
           "阶段标记", "重量", "比例"],
    "en": ["Title", "Identification number", "Sheet", "Scale", "Created by", "Approved by", "Document type",
           "Date of issue", "Legal owner"],
}


@pytest.mark.parametrize("locale", ["ru", "zh", "en"])
def test_frame_and_title_block_follow_the_standard(ratchet_sheets, locale):
    (left, bottom, right, top), (width, height) = STANDARD_FRAMES[locale]
    for sheet in ratchet_sheets[locale]:
        assert sheet.frame == pytest.approx((left, bottom, 841 - right, 594 - top))
        block = bounds([layer(sheet, "title-block")])
        # The block stands in the frame's lower right corner.
        assert block[2] == pytest.approx(sheet.frame[2]) and block[1] == pytest.approx(sheet.frame[1])
        assert block[2] - block[0] == pytest.approx(width)
        if height is not None:
            assert block[3] - block[1] == pytest.approx(height)
        else:  # ISO 7200 leaves the height free
            assert 20 <= block[3] - block[1] <= 60


@pytest.mark.parametrize("locale", ["zh", "en"])
def test_centring_marks_stand_on_the_sheet_s_axes_of_symmetry(ratchet_sheets, locale):
    """ISO 5457 and GB/T 14689 put the four centring marks at the ends of the trimmed sheet's axes of symmetry;
    they stood at the middle of the frame, 5 mm off on A1 (the frame's binding margin is wider), as a student
    measuring the sheets found."""
    for sheet in ratchet_sheets[locale]:
        width, height = sheet.size
        marks = [item for item in layer(sheet, "sheet-frame").items
                 if isinstance(item, Polyline) and len(item.points) == 2 and item.stroke.width == 0.7]
        assert len(marks) == 4
        vertical = [item for item in marks if item.points[0][0] == item.points[1][0]]
        horizontal = [item for item in marks if item.points[0][1] == item.points[1][1]]
        assert [item.points[0][0] for item in vertical] == pytest.approx([width / 2] * 2)
        assert [item.points[0][1] for item in horizontal] == pytest.approx([height / 2] * 2)
        # Each runs in from the sheet's edge across the margin to the frame.
        assert min(y for item in vertical for _, y in item.points) == 0.0
        assert min(x for item in horizontal for x, _ in item.points) == 0.0


@pytest.mark.parametrize("locale", ["ru", "zh", "en"])
def test_title_block_prints_the_labels_of_its_standard(ratchet_sheets, locale):
    for sheet in ratchet_sheets[locale]:
        written = [text.text for text in texts([layer(sheet, "title-block")])]
        missing = [label for label in STANDARD_LABELS[locale] if label not in written]
        assert not missing


def test_eskd_form_1_has_the_columns_of_the_standard(ratchet_sheets):
    """GOST 2.104 form 1: 7, 10, 23, 15, 10 | 70 | Лит. 3 × 5, Масса 17, Масштаб 18; Лист 20, Листов 30."""
    sheet = ratchet_sheets["ru"][0]
    block = layer(sheet, "title-block")
    left = bounds([block])[0]
    verticals = {round(item.points[0][0] - left, 3) for item in block.items
                 if isinstance(item, Polyline) and len(item.points) == 2 and item.points[0][0] == item.points[1][0]}
    assert {7, 17, 40, 55, 65, 135, 140, 145, 150, 155, 167} <= verticals


def test_sheet_numbers_in_the_eskd_and_gb_blocks(ratchet_sheets):
    for sheet in ratchet_sheets["zh"]:
        written = [text.text for text in texts([layer(sheet, "title-block")])]
        assert f"共 {sheet.count} 张  第 {sheet.number} 张" in written
    for sheet in ratchet_sheets["ru"]:
        block = texts([layer(sheet, "title-block")])
        label = next(text for text in block if text.text == "Лист" and text.anchor == "start")
        count_label = next(text for text in block if text.text == "Листов")

        assert right_of(block, label, count_label.at[0]) == [str(sheet.number)]
        assert right_of(block, count_label, math.inf) == [str(sheet.count)]


def right_of(block, anchor, limit):
    """The texts on ``anchor``'s line right of it and left of ``limit``."""
    return [text.text for text in block if abs(text.at[1] - anchor.at[1]) < 1.0
            and anchor.at[0] < text.at[0] < limit and text is not anchor]


@pytest.mark.parametrize("locale, drawing", [("en", "Kinematic analysis"), ("ru", "Кинематический анализ"),
                                             ("zh", "运动分析")])
def test_the_kind_of_drawing_is_named_in_the_language(ratchet_sheets, locale, drawing):
    written = [text.text for text in texts([layer(ratchet_sheets[locale][0], "title-block")])]
    assert drawing in written


def test_force_sheets_name_their_position(ratchet_sheets):
    numbers = [position.number for position in
               analyse(graphplan.load("fixtures/ratchet_crank_rocker.toml")).plans]
    force = [sheet for sheet in ratchet_sheets["ru"] if all(p.startswith("forces-") for p in sheet.panels)]
    assert len(force) == len(numbers)
    for sheet, number in zip(force, numbers, strict=True):
        written = " ".join(text.text for text in texts([layer(sheet, "title-block")]))
        assert f"Силовой анализ, положение {number}" in written


@pytest.mark.parametrize("length_scale, form, expected", [
    (0.0025, "eskd", "1:2.5"), (0.0025, "gb", "1:2.5"), (0.0025, "iso", "1:2.5"),
    (0.001, "iso", "1:1"), (0.002, "iso", "1:2"), (0.0005, "eskd", "2:1"), (0.04, "eskd", "1:40"),
    (0.003, "eskd", "μl = 0.003 m/mm"), (0.003, "gb", "1:3"), (0.003, "iso", "1:3"), (0.0004, "iso", "2.5:1"),
    (0.0026666, "iso", "μl = 0.0026666 m/mm")])
def test_scale_box_is_a_standard_ratio_or_the_scale_factor(length_scale, form, expected):
    """GOST 2.302 has 1:2.5 and 1:40 but not 1:3; GB/T 14690 has 1:2.5 and 1:3; ISO 5455 recommends neither
    but allows intermediate scales, so any ratio of a few digits is written as one."""
    assert scale_text(length_scale, form, "μl = {value} m/mm") == expected


def test_blank_fields_stay_drawn_and_a_long_title_stays_in_its_box():
    drawing = [Layer("square", (Polyline(((0, 0), (100, 0), (100, 80), (0, 80)), closed=True),))]
    # Eighty letters stay readable (1.8 mm is the smallest ESKD font); five hundred at least stay inside.
    for title, least in (("Crank-rocker of the ratchet feed of a planing machine with an output dyad", 1.8),
                         ("A very long title " * 30, 0.0)):
        for locale in ("en", "ru", "zh"):
            sheet, = kinematics_sheet([drawing], "A3", locale, title=title)
            block = layer(sheet, "title-block")
            box = bounds([block])
            lines = [item for item in block.items if isinstance(item, Polyline)]
            assert len(lines) >= 10  # the grid is drawn though nothing but the title is filled
            written = texts([block])
            assert " ".join(text.text for text in written if text.weight == "bold").split() == title.split()
            for text in written:
                assert inside(text_extent(text), box)
                assert text.size >= least


def test_a_plan_of_positions_too_big_names_the_length_scale_that_fits_and_that_scale_does():
    # At μl = 0.001 the Scotch yoke's plan of positions is 578 mm tall: more than any sheet holds.
    yoke = with_drawing(analyses_of("scotch_yoke"), length_scale=0.001)
    for sheet in ("A1", "A2"):
        with pytest.raises(SceneError) as error:
            course_sheets(yoke, sheet)
        assert error.value.where == "drawing.sheet"
        message = str(error.value)
        assert f"no {sheet} sheet" in message and '"none"' in message and "bigger sheet" not in message
        fitting = float(re.search(r"length_scale = ([0-9.]+)", message).group(1))
        assert fitting == 0.002  # a standard value, 578 / 2 = 289 mm tall
        fits = course_sheets(with_drawing(yoke, length_scale=fitting), sheet)
        assert max(rect[3] - rect[1] for rect in fits[0].panels.values()) <= fits[0].frame[3] - fits[0].frame[1]


def test_a_plan_too_big_for_a_small_sheet_names_the_bigger_sheet_that_holds_it(analyses):
    with pytest.raises(SceneError, match=r"choose A2 or a bigger sheet"):
        course_sheets(analyses["ratchet_crank_rocker"], "A3")
    with pytest.raises(SceneError, match=r"must be one of"):
        course_sheets(analyses["ratchet_crank_rocker"], "B2")


@pytest.mark.parametrize(("sheet", "field"), [("A4", 200.0), ("A4", 400.0), ("A3", 400.0), ("A1", 400.0)])
def test_without_a_length_scale_the_plan_of_positions_takes_the_least_standard_scale_that_fits(
        monkeypatch, sheet, field):
    """The first choice fits the paths into the field; where that plan (or a plan sheet's mechanism) overflows
    the sheet, the next standard values are tried, and the one that fits is the first at which both fit (the
    one taken may be larger still, for fewer sheets)."""
    monkeypatch.setattr(drawings, "POSITIONS_FIELD_MM", field)
    scene = graphplan.load("fixtures/ratchet_crank_rocker.toml")
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, length_scale=None, sheet=sheet))
    analysis = analyse(scene)
    tracks = np.concatenate([np.atleast_1d(path.r) for path in analysis.paths.points.values()])
    span = max(np.ptp(tracks.real), np.ptp(tracks.imag))
    first = min(value for value in STANDARD if value >= span / field - 1e-15)
    chosen = drawings.fitting_length_scale(analysis, sheet, first)
    assert length_scale(analysis) >= chosen
    form = form_of(scene.locale)
    assert chosen >= first
    assert holds(sheet, form, *positions_size(analysis, chosen))
    smaller = max(value for value in STANDARD if value < chosen - 1e-15)
    assert chosen == first or not (holds(sheet, form, *positions_size(analysis, smaller)) and all(
        holds(sheet, form, *mechanism_size(analysis, position, smaller)) for position in analysis.plans))
    if (sheet, field) == ("A4", 400.0):
        assert chosen > first  # 0.73 m at 0.0025 m/mm: 290 mm of paths, more than an A4 holds
    if sheet == "A1":
        assert chosen == first
    # The plan sheets may stand part by part, but each on the sheet; the force sheets are not asked here
    # (the ratchet's group II(3,4) cut free is 258 mm wide at its μF: no A4 holds it).
    sheets = kinematics_sheet(kinematics_panels(analysis), sheet, scene.locale)
    assert all(inside(rect, sheet_.frame) for sheet_ in sheets for rect in sheet_.panels.values())


@pytest.mark.parametrize("name, sheet", [("fixtures/shaper_six_bar", "A1"), ("fixtures/ratchet_crank_rocker", "A1"),
                                         ("fixtures/triad_class_iii", "A1"), ("fixtures/shaper_six_bar", "A2"),
                                         ("tests/scenes/long_coupler_crank_rocker", "A1"),
                                         ("tests/scenes/long_coupler_crank_rocker", "A3")])
def test_without_a_length_scale_a_drawing_a_step_smaller_saves_sheets(name, sheet):
    """Of the standard μl from the largest drawing that fits down to paths of the points 120 mm across, the
    one taken lays the set on the fewest sheets, and of those it draws largest: each μl is counted here
    by laying the whole set of sheets out at it.  The largest drawing starts at the μl that draws the paths
    within 200 mm, or the step finer where that one draws them under 120 mm (the long coupler's 103 mm at 1:10,
    a thumbnail in the corner of an A1 sheet)."""
    scene = graphplan.load(f"{name}.toml")
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, length_scale=None, sheet=sheet))
    analysis = analyse(scene)
    tracks = np.concatenate([np.atleast_1d(path.r) for path in analysis.paths.points.values()])
    span = max(np.ptp(tracks.real), np.ptp(tracks.imag))
    within = min(value for value in STANDARD if value >= span / 200)
    start = max(value for value in STANDARD if value < within) if span / within < 120 else within
    largest = drawings.fitting_length_scale(analysis, sheet, start)
    diagrams = (diagrams_panel(analysis, sheet),) if scene.positions.working is not None else ()

    def sheet_count(scale):
        return len(course_sheets(drawings.at_length_scale(analysis, scale), diagrams=diagrams))

    # The plan of positions' linework, the paths of the points, 120 mm across at least: its words, which do not
    # shrink with μl, are no part of it (measured with them, the README's 150 mm came out 124 mm of linework).
    tried = [value for value in STANDARD if value >= largest and (value == largest or span / value >= 120)]
    counts = {value: sheet_count(value) for value in tried}
    chosen = length_scale(analysis)
    assert chosen in tried
    assert counts[chosen] == min(counts.values())
    assert all(counts[value] > counts[chosen] for value in tried if value < chosen)
    assert chosen == largest or span / chosen >= 120


def test_a_run_without_a_length_scale_lays_the_sheets_out_once_at_each_scale_it_tries(monkeypatch, tmp_path):
    """Choosing μl lays the sheets out at each μl it tries; the run's sheets at the μl chosen are those layouts,
    not a layout made again (the same drawings, and a second or so saved on a course project)."""
    from graphplan.cli import main
    from graphplan.render import sheet as sheet_module

    laid_out = []
    original = sheet_module.kinematics_panels

    def counted(analysis):
        laid_out.append(analysis.scene.drawing.length_scale)
        return original(analysis)

    monkeypatch.setattr(sheet_module, "kinematics_panels", counted)
    with open("fixtures/shaper_six_bar.toml", encoding="utf-8") as file:
        text = file.read()
    scene = tmp_path / "shaper.toml"
    scene.write_text(re.sub(r"^length_scale\s*=.*$", "", text, flags=re.MULTILINE), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "sheets,positions"]) == 0
    assert len(laid_out) >= 2  # the choice tried more than one μl
    assert len(laid_out) == len(set(laid_out))


def box(name, width, height):
    """A drawing that is only its outline, ``width`` × ``height`` mm, named as a drawing of the set."""
    return Panel(name, (Layer("box", (Polyline(((0, 0), (width, 0), (width, height), (0, height)), closed=True),)),))


def test_panels_that_do_not_fit_one_sheet_spread_over_several():
    """Six 300 × 200 mm drawings need two A1 sheets: four fit beside the title block on one."""
    drawing = [Layer("box", (Polyline(((0, 0), (300, 0), (300, 200), (0, 200)), closed=True),))]
    sheets = kinematics_sheet([drawing] * 6, "A1", "en", title="Boxes", first=3, count=9)
    assert [sheet.number for sheet in sheets] == [3, 4]
    assert [len(sheet.panels) for sheet in sheets] == [4, 2]
    assert all(f"{sheet.number} of 9" in [t.text for t in texts(sheet.layers)] for sheet in sheets)


def test_a_drawing_fills_a_gap_on_an_earlier_sheet():
    """On an ESKD A1 (800 × 513 mm above the title block): a 600 × 400 drawing leaves 185 mm beside it, a
    780 × 400 one goes on a second sheet and leaves too little round it; a 180 × 180 drawing then goes beside
    the first, not on a third sheet."""
    sheets = kinematics_sheet([box("positions", 600, 400), box("plan-5", 780, 400), box("diagrams", 180, 180)],
                              "A1", "ru")
    assert [sorted(sheet.panels) for sheet in sheets] == [["diagrams", "positions"], ["plan-5"]]


def test_a_drawing_never_goes_back_before_an_earlier_drawing_of_its_kind():
    """Two 600 × 400 drawings on two A1 sheets, each with 185 mm beside it: the second position's small plans
    would fit beside the plan of positions but go beside the first position's, after them; the diagrams still
    fill the gap the plans left."""
    sheets = kinematics_sheet([box("positions", 600, 400), box("plan-5", 600, 400), box("plan-11", 180, 180),
                               box("diagrams", 180, 180)], "A1", "ru")
    assert [sorted(sheet.panels) for sheet in sheets] == [["diagrams", "positions"], ["plan-11", "plan-5"]]


def test_on_a_sheet_too_the_plans_of_a_later_position_read_after_an_earlier_one():
    """A tall narrow plan of positions and two 600 × 150 mm plan rows on an A1: the first row is most compact
    under the plan of positions, and the second would fit only beside it, above the first; the first stands
    its other way (400 × 250 mm) beside the plan of positions instead, and the second under both: the plans
    of position 11 are read after those of position 5, lower down or all to the right."""
    plan_5 = dataclasses.replace(box("plan-5", 600, 150), alternatives=(box("plan-5", 400, 250),))
    sheets = kinematics_sheet([box("positions", 90, 250), plan_5, box("plan-11", 600, 150)], "A1", "ru")
    assert len(sheets) == 1
    first, second = sheets[0].panels["plan-5"], sheets[0].panels["plan-11"]
    assert second[3] < first[3] or second[0] >= first[2]


def test_a_sheet_is_arranged_afresh_where_only_that_makes_room():
    """On an ESKD A1 (800 mm wide): a plan sheet as a 780 × 250 mm row leaves no room for 400 × 400 mm
    diagrams beside or under it, but with its mechanism above its plans (380 × 520 mm) it leaves 405 mm
    beside it: the two share the sheet, where without the other arrangement they took two."""
    plan = dataclasses.replace(box("plan-5", 780, 250), alternatives=(box("plan-5", 380, 520),))
    diagrams = box("diagrams", 400, 400)
    sheets = kinematics_sheet([plan, diagrams], "A1", "ru")
    assert [sorted(sheet.panels) for sheet in sheets] == [["diagrams", "plan-5"]]
    x0, y0, x1, y1 = sheets[0].panels["plan-5"]
    assert (x1 - x0, y1 - y0) == pytest.approx((380, 520))
    assert not overlap(sheets[0].panels["plan-5"], sheets[0].panels["diagrams"])
    rows_only = kinematics_sheet([dataclasses.replace(plan, alternatives=()), diagrams], "A1", "ru")
    assert [sorted(sheet.panels) for sheet in rows_only] == [["plan-5"], ["diagrams"]]


def test_a4_stands_upright_when_that_fits_better():
    tall = [Layer("tall", (Polyline(((0, 0), (150, 0), (150, 190), (0, 190)), closed=True),))]
    wide = [Layer("wide", (Polyline(((0, 0), (230, 0), (230, 100), (0, 100)), closed=True),))]
    assert kinematics_sheet([tall], "A4", "en")[0].size == (210.0, 297.0)
    assert kinematics_sheet([wide], "A4", "en")[0].size == (297.0, 210.0)
    # ESKD sets an A4 upright whenever the drawing fits that way.
    small = [Layer("small", (Polyline(((0, 0), (100, 0), (100, 100), (0, 100)), closed=True),))]
    assert kinematics_sheet([small], "A4", "ru")[0].size == (210.0, 297.0)


def test_a_panel_too_big_whole_goes_part_by_part_on_sheets_of_its_own(analyses):
    """A2 holds the quick-return mechanism's plan sheet of position 11 only as its three drawings apart."""
    analysis = analyses["quick_return_slotted_lever"]
    sheets = kinematics_sheet(kinematics_panels(analysis), "A2", "en", title=analysis.scene.title)
    own = [sheet for sheet in sheets if any(panel.startswith("plan-11-") for panel in sheet.panels)]
    assert own
    for sheet in own:
        assert all(panel.startswith("plan-11-") for panel in sheet.panels)
        written = [text.text for text in texts([layer(sheet, "title-block")])]
        assert "Velocity and acceleration plans, position 11" in written
    parts = {panel for sheet in own for panel in sheet.panels}
    # The parts and, over them, the plan sheet's heading.
    assert parts == {"plan-11-mechanism", "plan-11-velocity", "plan-11-acceleration", "plan-11-heading"}
    # A drawing set apart keeps its caption just under it.
    for sheet in own:
        for item in sheet.layers:
            if item.name.endswith("-caption"):
                owner = item.name[:-len("-caption")]
                drawing = bounds_of(x for other in sheet.layers if other.name.startswith(owner + "-")
                                    and other is not item for x in other.items)
                assert 0 < drawing[1] - item.items[0].at[1] <= plan_layout.CAPTION_GAP_MM + 1e-9


def test_a_force_sheet_too_tall_in_one_column_stands_whole_in_two_under_its_heading(analyses):
    """On A1 the shaper's force sheet of position 3 (three groups and the lever) is taller than the sheet in
    one column: it stands whole in two, its rows in their order (down the first column, then the second),
    under its title and scales, where it used to go part by part without them."""
    analysis = analyses["shaper_six_bar"]
    drawn = drawings.force_sheet(analysis, analysis.plans[0])
    one, two = force_layout.arrangements(drawn, (1, 2))
    form = form_of(analysis.scene.locale)
    assert not holds("A1", form, *size_of(one.layers)) and holds("A1", form, *size_of(two.layers))
    # The same drawings, each field the same size, only moved.
    assert one.fields.keys() == two.fields.keys()
    assert all(math.isclose(a[2] - a[0], b[2] - b[0]) and math.isclose(a[3] - a[1], b[3] - b[1])
               for a, b in zip(one.fields.values(), two.fields.values()))
    order = [name for name in one.fields if name.startswith(("body-", "lever"))]
    lefts = [two.fields[name][0] for name in order]
    columns = [sorted({left for left in lefts}).index(left) for left in lefts]
    assert columns == sorted(columns) and set(columns) == {0, 1}
    for column in (0, 1):
        tops = [two.fields[name][3] for name, c in zip(order, columns) if c == column]
        assert tops == sorted(tops, reverse=True)
    sheet = next(sheet for sheet in course_sheets(analysis, "A1")
                 if f"forces-{analysis.plans[0].number}" in sheet.panels)
    written = [text.text for text in texts(sheet.layers)]
    assert f"Force analysis, position {analysis.plans[0].number}" in written


def test_a_force_sheet_no_sheet_holds_whole_goes_in_parts_in_order_each_under_its_heading(analyses):
    """On A1 the Stephenson six-bar's force sheets are too big in any arrangement: each goes in parts, its
    groups in the order they were solved and the lever last, each part that opens a sheet whole under a heading,
    where they used to go drawing by drawing, jumbled, without one; a part on the sheet of the part before it goes
    on under that one's heading."""
    analysis = analyses["stephenson_six_bar"]
    sheets = course_sheets(analysis, "A1")
    force_sheets = [sheet for sheet in sheets if any(name.startswith("forces-") for name in sheet.panels)]
    assert all(re.fullmatch(r"forces-\d+(-\d+)?", name) for sheet in force_sheets for name in sheet.panels)
    rows = [f"body-{force_layout.group_id(group.label)}" for group in analysis.plans[0].forces.groups] + ["lever"]
    seen = []
    for position in analysis.plans:
        parts = [(sheet.number, name) for sheet in force_sheets for name in sheet.panels
                 if re.fullmatch(rf"forces-{position.number}(-\d+)?", name)]
        assert len(parts) >= 2
        seen += [number for number, _ in parts]
        order = []
        for k, (number, name) in enumerate(sorted(parts)):
            sheet = sheets[number - 1]
            assert name == (f"forces-{position.number}" if k == 0 else f"forces-{position.number}-{k + 1}")
            title = f"Force analysis, position {position.number}"
            if k and number == sorted(parts)[k - 1][0]:
                assert not any(item.name == f"{name}-sheet-title" for item in sheet.layers)
            else:
                heading = [text.text for text in texts([layer(sheet, f"{name}-sheet-title")])
                           if text.weight == "bold"]
                assert " ".join(heading) == (title if k == 0 else f"{title} (continued)")
            order += [row for row in rows if any(item.name == f"{name}-{row}-caption" for item in sheet.layers)]
        assert order == rows
    assert seen == sorted(seen)
    # The force sheet whole, as forces_N.svg has it, is still there for the drawing on its own.
    whole = course_panels(analysis).named(f"forces-{analysis.plans[0].number}")
    assert {f"{row}-caption" for row in rows} <= {item.name for item in whole.layers}


def test_a_sheet_of_parts_of_one_drawing_is_named_after_it_in_the_title_block(analyses):
    """On A3 each force sheet of the triad goes in parts: the title block of each sheet of its parts names the
    drawing they are parts of, not the kind of drawing.  (Its first two parts of position 2 or 8 shared a sheet
    while the first stood without a heading; under its heading, its equations beside it, it takes a sheet alone.  A
    sheet of two parts of one drawing: tests/test_force_sheet_parts_headed.py.)"""
    _, sheets = on_a3("triad_class_iii")
    for number in (2, 8):
        parts = [sheet for sheet in sheets
                 if sheet.panels and all(re.fullmatch(rf"forces-{number}(-\d+)?", name) for name in sheet.panels)]
        assert len(parts) > 1
        for sheet in parts:
            assert f"Force analysis, position {number}" in [text.text for text in texts([layer(sheet, "title-block")])]


def test_a_force_sheet_part_that_fits_under_its_heading_in_smaller_lettering_is_given_its_heading(analyses):
    """On A3 the engine's force sheet of position 2 stood in four parts, one with no heading at all, said whose it
    was by the title block alone (a student's reading of the sheets); lettered a size smaller, each of its parts
    stands under its heading, the first under the sheet's title, the others «continued», at the same scales.  A part
    that goes on under the one before it on the same sheet (the driving link's, its equations beside it, under the
    group of position 8) stands under that one's heading."""
    analysis = analyses["engine_slider_crank"]
    sheets = course_sheets(analysis, "A3")
    for position in analysis.plans:
        title = f"Force analysis, position {position.number}"
        parts = sorted((name, sheet) for sheet in sheets for name in sheet.panels
                       if re.fullmatch(rf"forces-{position.number}(-\d+)?", name))
        assert len(parts) >= 2
        for k, (name, sheet) in enumerate(parts):
            headings = [item for item in sheet.layers if item.name == f"{name}-sheet-title"]
            if k and parts[k - 1][1] is sheet:
                assert not headings, (sheet.number, name)
                continue
            heading = [text.text for text in texts(headings) if text.weight == "bold"]
            assert " ".join(heading) == (title if k == 0 else f"{title} (continued)"), (sheet.number, name)
    assert check_group_scale_is_the_mechanism_s(analysis, sheets)


def check_group_scale_is_the_mechanism_s(analysis, sheets) -> bool:
    """Whether every group cut free on the sheets is captioned at the mechanism's μl."""
    wanted = f"μl = {format_scale(length_scale(analysis))} m/mm"
    captions = [text.text for sheet in sheets for item in sheet.layers
                if re.fullmatch(r"forces-\d+(-\d+)?-body-.*-caption", item.name) for text in texts([item])]
    return bool(captions) and all(wanted in caption for caption in captions if caption.startswith("μl"))


def test_a_force_sheet_too_big_in_two_columns_stands_whole_with_each_polygon_under_its_group(analyses):
    """On A1 the shaper's force sheet of position 10 is too tall in two columns; with each group's polygon
    under it, the groups and the lever side by side, it stands whole on one sheet under its title."""
    analysis = analyses["shaper_six_bar"]
    position = analysis.plans[1]
    form = form_of(analysis.scene.locale)
    one, two = force_layout.arrangements(drawings.force_sheet(analysis, position), (1, 2))
    assert not holds("A1", form, *size_of(one.layers)) and not holds("A1", form, *size_of(two.layers))
    name = f"forces-{position.number}"
    (sheet,) = [sheet for sheet in course_sheets(analysis, "A1")
                if any(panel.startswith(name) for panel in sheet.panels)]
    assert [panel for panel in sheet.panels if panel.startswith(name)] == [name]
    assert f"Force analysis, position {position.number}" in [
        text.text for text in texts(sheet.layers)]
    captions = {item.name.removeprefix(name + "-").removesuffix("-caption"): item.items[0].at
                for item in sheet.layers if item.name.startswith(name + "-") and item.name.endswith("-caption")}
    for group in position.forces.groups:
        key = force_layout.group_id(group.label)
        body, polygon = captions[f"body-{key}"], captions[f"polygon-{key}"]
        assert polygon[0] == pytest.approx(body[0]) and polygon[1] < body[1]


def size_of(layers):
    x0, y0, x1, y1 = bounds(layers)
    return x1 - x0, y1 - y0


def arrangement_on(sheet, name):
    """How the plan sheet ``name`` stands on ``sheet``, read off its captions' first lines: "row" (one
    baseline), "stacked" (the mechanism's above the plans'), "beside" (the acceleration plan's level with the
    mechanism's, the velocity plan's above)."""
    baseline = {drawing: round(texts([layer(sheet, f"{name}-{drawing}-caption")])[0].at[1], 6)
                for drawing in ("mechanism", "velocity", "acceleration")}
    if len(set(baseline.values())) == 1:
        return "row"
    if baseline["velocity"] == baseline["acceleration"] < baseline["mechanism"]:
        return "stacked"
    assert baseline["mechanism"] == baseline["acceleration"] < baseline["velocity"], baseline
    return "beside"


def test_a_plan_sheet_too_wide_in_a_row_for_the_room_left_joins_the_sheet_rearranged(analyses):
    """On A2 the scotch yoke's plan sheet of position 4 stands beside the plan of positions only with its
    plans one above the other; in a row it would take a sheet of its own."""
    analysis = analyses["scotch_yoke"]
    panels = kinematics_panels(analysis)
    sheets = kinematics_sheet(panels, "A2", "en", title=analysis.scene.title)
    rows_only = kinematics_sheet([dataclasses.replace(panel, alternatives=()) for panel in panels], "A2", "en",
                                 title=analysis.scene.title)
    assert len(sheets) == len(rows_only) - 1
    first = sheets[0]
    assert set(first.panels) == {"positions", "plan-4"}
    assert arrangement_on(first, "plan-4") != "row"
    assert "Velocity and acceleration plans, position 4" in [text.text for text in texts(first.layers)]
    bounds_on_sheet = placed_bounds(first)
    assert not overlap(bounds_on_sheet["positions"], bounds_on_sheet["plan-4"])


def test_a_plan_sheet_no_sheet_holds_in_a_row_goes_whole_rearranged_rather_than_in_parts(analyses):
    """The engine's plan sheets are wider than an A2 in a row: each stands whole on its sheet, titled,
    the mechanism above its plans."""
    analysis = analyses["engine_slider_crank"]
    assert not any(holds("A2", "iso", _width, _height) for _width, _height in
                   [(p.extent[2] - p.extent[0], p.extent[3] - p.extent[1]) for p in kinematics_panels(analysis)[1:]])
    sheets = course_sheets(analysis, "A2")
    for position in analysis.plans:
        name = f"plan-{position.number}"
        holding = [sheet for sheet in sheets if any(panel.startswith(name) for panel in sheet.panels)]
        assert len(holding) == 1 and name in holding[0].panels
        assert arrangement_on(holding[0], name) == "stacked"
        written = [text.text for text in texts(holding[0].layers)]
        assert f"Velocity and acceleration plans, position {position.number}" in written


def test_a_plan_sheet_that_fits_in_a_row_stays_a_row(a1_sheets, analyses):
    for name in ("ratchet_crank_rocker", "quick_return_slotted_lever", "shaper_six_bar"):
        for position in analyses[name].plans:
            sheet = next(sheet for sheet in a1_sheets[name] if f"plan-{position.number}" in sheet.panels)
            assert arrangement_on(sheet, f"plan-{position.number}") == "row", (name, position.number)


def test_forces_sheet_and_extra_panels_as_layers(analyses):
    """Raw layers (a kinematic diagram, say) are panels too; forces_sheet places what it is given."""
    diagram = [Layer("curve", (Polyline(((0, 0), (120, 40), (240, 0))), Text((120, -8), "s(φ)")))]
    sheets = forces_sheet([diagram, diagram], "A3", "zh", title="图")
    assert len(sheets) == 1 and set(sheets[0].panels) == {"panel-1", "panel-2"}
    written = [text.text for text in texts([layer(sheets[0], "title-block")])]
    assert "力分析" in written and "共 1 张  第 1 张" in written
    panel = Panel("diagram", tuple(diagram))
    sheets = course_sheets(analyses["engine_slider_crank"], "A1", diagrams=[panel])
    assert any("diagram" in sheet.panels for sheet in sheets)


def test_no_sheet_gives_the_drawings_unframed(analyses):
    sheets = course_sheets(analyses["ratchet_crank_rocker"], "none")
    assert [next(iter(sheet.panels)) for sheet in sheets] == ["positions", "plan-5", "plan-11", "forces-5",
                                                              "forces-11"]
    for sheet in sheets:
        assert sheet.size is None and sheet.frame is None
        assert not any(item.name == "title-block" for item in sheet.layers)
        ElementTree.fromstring(sheet.svg())


def test_sheet_svg_pages_and_determinism(ratchet_sheets):
    layers = ratchet_sheets["en"][0].layers
    assert view_box(ElementTree.fromstring(sheet_svg(layers, "A3"))) == [0, 0, 420, 297]
    assert view_box(ElementTree.fromstring(sheet_svg(layers, (210.0, 297.0)))) == [0, 0, 210, 297]
    assert sheet_svg(layers, "A1") == ratchet_sheets["en"][0].svg()
    with pytest.raises(SceneError):
        sheet_svg(layers, "A0")


def test_a_sheet_renders(ratchet_sheets):
    png = cairosvg.svg2png(bytestring=ratchet_sheets["zh"][0].svg().encode(), output_width=400)
    assert png.startswith(b"\x89PNG")


def test_every_language_has_every_title_block_string():
    keys = {locale: {key for key in strings(locale) if key.startswith("tb_")} for locale in ("en", "ru", "zh")}
    assert keys["en"] and keys["ru"] == keys["en"] == keys["zh"]
    assert set(labels("ru")) == {key.removeprefix("tb_") for key in keys["en"]}
    with pytest.raises(ValueError, match="no title block strings for locale 'xx'"):
        labels("xx")


@pytest.mark.parametrize("sheet", ["A4", "A3", "A1"])
def test_the_kinematic_diagrams_fit_the_sheet_each_whole_or_shortened_by_whole_intervals(analyses, sheet):
    analysis = analyses["ratchet_crank_rocker"]
    count = analysis.scene.positions.count
    panel = diagrams_panel(analysis, sheet)
    assert len(panel.parts) == 3
    form = form_of(analysis.scene.locale)
    for part in panel.parts:
        assert held_under_its_heading(part, sheet, form), part.name
    # The φ axis is written under the last diagram: "L = 240 мм" for the usual axis.
    written = " ".join(text.text for text in texts(panel.layers))
    axis = float(re.search(r"\sL = ([0-9.]+)", written).group(1))
    assert axis % count == 0
    usual = diagrams_layout.layout(of_analysis(analysis), strings(analysis.scene.locale))
    if sheet == "A4":
        assert axis < 240.0  # 270 mm wide with its pole and words: wider than any room of an A4
        # As long as fits: one more interval would not.
        longer = diagrams_layout.parts(kinematic_diagrams(analysis.mechanism, analysis.positions,
                                                          axis_mm=axis + count, field_mm=FIELD_MM),
                                       strings(analysis.scene.locale))
        assert not all(holds(sheet, form, *(bounds(part)[2] - bounds(part)[0], bounds(part)[3] - bounds(part)[1]))
                       for part in longer)
    elif sheet == "A3":
        # The usual axis; the Russian words leave two usual diagrams a few millimetres too tall for one A3 with the
        # title block under them: drawn lower, they stand on two sheets, not three.
        assert axis == 240.0
        assert len(kinematics_sheet([panel], sheet, "ru")) == 2
        assert [layer.items for layer in panel.layers] != [layer.items for layer in usual]
    else:
        # A1 has room to spare: drawn larger, the usual diagrams its last way, for a sheet with little room left.
        assert axis >= 240.0
        assert [layer.items for layer in panel.ways[-1].layers] == [layer.items for layer in usual]


def test_diagrams_too_big_for_a_sheet_whole_stand_apart_on_it(analyses):
    """On A3 the three diagrams (some 300 mm stacked) exceed the 271 mm of the sheet: each stands whole on a sheet."""
    analysis = analyses["ratchet_crank_rocker"]
    sheets = kinematics_sheet([diagrams_panel(analysis, "A3")], "A3", "ru")
    placed = [name for sheet in sheets for name in sheet.panels]
    assert sorted(placed) == ["diagrams-1", "diagrams-2", "diagrams-3"]
    for sheet in sheets:
        for rect in placed_bounds(sheet).values():
            assert inside(rect, sheet.frame) and not overlap(rect, sheet.title_block)


def test_a_part_that_shares_its_sheet_with_the_part_it_goes_on_from_stands_without_a_continued_heading():
    """The crank-rocker starter's force sheets fit A2 and A3 only in parts: a part on the sheet of the part it goes
    on from reads as one drawing with it under one heading; a part that opens a sheet keeps its heading, which says
    it goes on from an earlier sheet.  (Both stand on A3; on A2, since the crank's polygon of no area is drawn at
    the others' μF, each force sheet's second part opens a sheet.)"""
    from importlib import resources

    scene = graphplan.scene.loads(resources.files("graphplan").joinpath("templates/crank-rocker.toml").read_text(
        encoding="utf-8"))
    marker = strings(scene.locale)["force_sheet_continued"].format(title="").strip()

    def heading(sheet, name):
        return [text.text for layer in sheet.layers if layer.name == f"{name}-sheet-title"
                for text in layer.items if isinstance(text, Text)]

    shared, alone = [], []
    for sheet_format in ("A2", "A3"):
        for sheet in course_sheets(analyse(scene), sheet_format):
            for name in sheet.panels:
                found = re.fullmatch(r"(forces-\d+)-(\d+)", name)
                if found is None:
                    continue
                before = found.group(1) if found.group(2) == "2" else f"{found.group(1)}-{int(found.group(2)) - 1}"
                (shared if before in sheet.panels else alone).append((sheet_format, sheet.number, name))
                texts_of_its_heading = heading(sheet, name)
                if before in sheet.panels:
                    assert not texts_of_its_heading, (sheet_format, sheet.number, name)
                else:
                    assert any(marker in text for text in texts_of_its_heading), (sheet_format, sheet.number, name)
    assert shared and alone, (shared, alone)


def test_a_sheet_of_the_kinematic_diagrams_alone_has_no_scale_in_its_title_block():
    # The diagrams are drawn to their μs, μv, μa, none of them a length scale: the sheet they stand on alone
    # said 1:2 (the mechanism's) in its scale box.
    analysis = drawings.with_length_scale(with_drawing(analyses_of("engine_slider_crank"), length_scale=None, sheet="A3"))
    sheets = course_sheets(analysis, "A3", diagrams=(diagrams_panel(analysis, "A3"),))
    ratio = scale_text(length_scale(analysis), form_of(analysis.scene.locale), "μl = {value} m/mm")
    alone = [sheet for sheet in sheets if all(name.startswith("diagrams") for name in sheet.panels)]
    assert alone
    for sheet in sheets:
        written = [text.text for text in texts([layer(sheet, "title-block")])]
        assert (ratio in written) == (sheet not in alone and not forces_to_no_length_scale(sheet)), \
            (sheet.number, sorted(sheet.panels))


def test_a_sheet_of_velocity_or_acceleration_plans_alone_has_no_scale_in_its_title_block(tmp_path):
    """The plans are drawn at μV and μa: the sheet of every position's velocity plans, or of one acceleration
    plan that stands apart from its mechanism, said 1:4 (the mechanism's) in its scale box.  A sheet with a
    mechanism on it still gives its μl."""
    scene = graphplan.load("fixtures/shaper_six_bar.toml")
    scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, velocity_plans=tuple(range(1, 13))))
    analysis = drawings.with_length_scale(with_drawing(analyse(scene), length_scale=None, sheet="A3"))
    sheets = course_sheets(analysis, "A3")
    ratio = scale_text(length_scale(analysis), form_of(analysis.scene.locale), "μl = {value} m/mm")
    plans_alone = [sheet for sheet in sheets
                   if all(name.startswith("velocity-plans") or name.endswith(("-velocity", "-acceleration", "-heading"))
                          for name in sheet.panels)]
    assert plans_alone
    for sheet in sheets:
        written = [text.text for text in texts([layer(sheet, "title-block")])]
        drawn_to_scale = sheet not in plans_alone and not all(name.startswith("diagrams") for name in sheet.panels) \
            and not forces_to_no_length_scale(sheet)
        assert (ratio in written) == drawn_to_scale, (sheet.number, sorted(sheet.panels))


# --- the rotor's balancing on a sheet ----------------------------------------------------------------------

_ROTOR_ALONE = """[scene]
title = "Rotor of a fan"
[balancing]
masses = [ { mass = 18.0, radius = 0.05, angle = 0.0, plane = 0.0 },
           { mass = 14.0, radius = 0.06, angle = -60.0, plane = 0.08 },
           { mass = 10.0, radius = 0.04, angle = 135.0, plane = 0.16 } ]
planes = [0.04, 0.22]
correction_radius = 0.05
[vibration]
mass = 100.0
unbalance = 0.02
stiffness = 1.0e5
damping_ratio = 0.1
rpm = 600.0
"""


def _texts(svg: str) -> list[str]:
    return ["".join(element.itertext()) for element in ElementTree.fromstring(svg).iter("{http://www.w3.org/2000/svg}text")]


@pytest.mark.parametrize(("how", "locale", "label"), [
    ("option", "en", "Balancing of the rotor"), ("scene", "en", "Balancing of the rotor"),
    ("option", "ru", "Уравновешивание ротора"), ("option", "zh", "转子平衡"),
])
def test_a_rotor_without_a_linkage_gets_a_balancing_sheet_with_its_polygons_at_their_scales(tmp_path, capsys, how,
                                                                                              locale, label):
    """--sheet A3 on a balancing-only scene wrote no sheet and said nothing, though --help promises the sheets."""
    from graphplan.cli import main

    scene = tmp_path / "rotor.toml"
    text = _ROTOR_ALONE.replace('title = "Rotor of a fan"', f'title = "Rotor of a fan"\nlocale = "{locale}"')
    scene.write_text(text + ('\n[drawing]\nsheet = "A3"\n' if how == "scene" else ""), encoding="utf-8")
    arguments = ["run", str(scene), "--out", str(tmp_path / "out")] + (["--sheet", "A3"] if how == "option" else [])
    assert main(arguments) == 0
    assert "warning" not in capsys.readouterr().out
    svg = (tmp_path / "out" / "sheet_1.svg").read_text(encoding="utf-8")
    root = ElementTree.fromstring(svg)
    assert (root.get("width"), root.get("height")) == ("420mm", "297mm")
    texts = _texts(svg)
    assert label in texts and "Rotor of a fan" in "".join(texts)
    # Each plane's correction drawn at the plane's μ: |mb·rb| of the equilibrium equations, over the μ captioned.
    products = [m * r * np.exp(1j * np.radians(angle)) for m, r, angle in [(18.0, 0.05, 0.0), (14.0, 0.06, -60.0),
                                                                          (10.0, 0.04, 135.0)]]
    zs = np.array([0.0, 0.08, 0.16])
    corrections = np.linalg.solve(np.array([[1.0, 1.0], [0.04, 0.22]], dtype=complex),
                                  -np.array([sum(products), sum(p * z for p, z in zip(products, zs, strict=True))]))
    scales = [float(found.replace(",", ".")) for found in re.findall(r"μ = ([\d.,]+) ", " ".join(texts))]
    assert len(scales) == 2
    for name, correction, scale in zip("LR", corrections, scales, strict=True):
        (arrow,) = [element for element in root.iter() if element.get("id") == f"balancing-plane-{name}-m{name}r{name}"]
        # The shaft's tail, and the head's tip (its first corner), which ends the vector.
        tail, tip = (complex(*map(float, path.get("d").split()[0][1:].split(","))) for path in list(arrow)[:2])
        assert abs(tip - tail) == pytest.approx(abs(correction) / scale, abs=0.01)


def test_a_linkages_sheets_end_with_the_rotors_balancing_where_the_scene_has_one(tmp_path):
    from graphplan.cli import main

    scene = tmp_path / "engine.toml"
    rotor = _ROTOR_ALONE.split("[balancing]")[1].split("[vibration]")[0]
    with open("fixtures/engine_slider_crank.toml", encoding="utf-8") as fixture:
        linkage = fixture.read()
    scene.write_text(linkage + "\n[balancing]" + rotor,
                     encoding="utf-8")
    assert main(["run", str(scene), "--only", "sheets", "--out", str(tmp_path / "out")]) == 0
    sheets = sorted((tmp_path / "out").glob("sheet_*.svg"), key=lambda path: int(path.stem.split("_")[1]))
    last = _texts(sheets[-1].read_text(encoding="utf-8"))
    assert "Balancing of the rotor" in last and f"{len(sheets)} of {len(sheets)}" in last
    assert not any("Balancing of the rotor" in _texts(path.read_text(encoding="utf-8")) for path in sheets[:-1])


def test_a_machine_without_a_linkage_gets_its_dynamics_on_sheets_then_its_rotors_balancing(tmp_path, capsys):
    """--sheet A3 on a scene of load diagrams drew no sheet ("only a [balancing] is drawn on a sheet"), though its
    work, energy and flywheel are a course project's dynamics sheet."""
    from graphplan.cli import main

    scene = tmp_path / "press.toml"
    # The power cycle of issue 7's worked example: JF = 80.473 kg·m² (its flywheel on a 1440 rpm shaft besides).
    scene.write_text(PRESS + "[balancing]" + _ROTOR_ALONE.split("[balancing]")[1].split("[vibration]")[0],
                     encoding="utf-8")
    assert main(["run", str(scene), "--sheet", "A3", "--out", str(tmp_path / "out")]) == 0
    assert "warning" not in capsys.readouterr().out
    sheets = sorted((tmp_path / "out").glob("sheet_*.svg"), key=lambda path: int(path.stem.split("_")[1]))
    texts = [_texts(path.read_text(encoding="utf-8")) for path in sheets]
    assert len(sheets) >= 2 and all(f"{k} of {len(sheets)}" in " ".join(own) for k, own in enumerate(texts, 1))
    # The flywheel as the power cycle gives it: ΔWmax = (3677 − 2573.9) W over two thirds of a turn at 100 rpm.
    mean_power = (367.7 + 2 * 3677) / 3
    surplus = (3677 - mean_power) * (2 / 3) * 60 / 100
    omega = 100 * 2 * np.pi / 60
    flywheel = surplus / (omega**2 * 0.05)
    drawn = " ".join(" ".join(own) for own in texts[:-1])
    assert "Dynamics of the machine" in drawn
    assert re.search(rf"JF = [^=]*= {flywheel:.3f} kg·m²", drawn), drawn
    assert "Balancing of the rotor" in " ".join(texts[-1]) and "Balancing of the rotor" not in drawn


def test_a_sheet_asked_for_a_scene_with_nothing_to_draw_on_one_is_said(tmp_path, capsys):
    from graphplan.cli import main

    scene = tmp_path / "mounts.toml"
    scene.write_text("[scene]\ntitle = \"mounts\"\n[vibration]" + _ROTOR_ALONE.split("[vibration]")[1],
                     encoding="utf-8")
    assert main(["run", str(scene), "--sheet", "A3", "--out", str(tmp_path / "out")]) == 0
    assert "warning: --sheet: no sheet is drawn: 'sheets' needs a mechanism" in capsys.readouterr().out
    assert not list((tmp_path / "out").glob("sheet_*"))


def test_a_refusal_offers_only_rooms_a_drawing_could_stand_in():
    """On an upright ESKD A4 the strip between графа 26 (70 mm wide, top left) and the title block (185 mm of the
    frame's 185 mm) is 1 mm wide: the refusal offered "1 × 184 mm" among the rooms of an empty sheet."""
    from graphplan.render.packing import rooms

    said = rooms("A4", "eskd", (False, True))
    sizes = [(float(w), float(h)) for w, h in re.findall(r"(\d+) × (\d+)", said)]
    assert sizes and all(min(size) >= 10.0 for size in sizes), said
    # The landscape sheet's room over its title block stays offered: the frame's 277 mm less the margins.
    assert any(width > 250.0 for width, _ in sizes), said


@pytest.mark.parametrize("name", ["triad_class_iii", "shaper_six_bar"])
def test_a_plan_sheet_in_parts_says_continued_over_its_parts_after_the_first(name):
    """On A3 the acceleration plan of the shaper's position 10 stood on a sheet of its own under the very heading
    of the sheet before, «position 10», read as a second plan sheet of that position (a hunt's sheets 5 and 6); the
    force sheets say «continued» there, and so do the plan sheets now."""
    analysis, sheets = on_a3(name)
    split_up = 0
    for position in analysis.plans:
        holding = [sheet for sheet in sheets if f"plan-{position.number}-heading" in sheet.panels]
        split_up += len(holding) > 1
        title = strings(analysis.scene.locale)["plan_sheet_title"].format(number=position.number)
        for k, sheet in enumerate(holding):
            heading = [text.text for text in texts([layer(sheet, f"plan-{position.number}-heading-sheet-title")])]
            assert " ".join(heading) == (title if k == 0 else f"{title} (continued)"), (sheet.number, heading)
    assert split_up



def test_a_sheet_of_plans_under_their_heading_leaves_the_scale_box_empty():
    """The heading of a plan sheet in parts took its sheet's scale box for a drawing at μl: a sheet holding the
    acceleration plan alone under it said 1:4 (a hunt's sheet 6), as if the plan were a drawing at μl."""
    _, sheets = on_a3("triad_class_iii")
    plans_alone = [sheet for sheet in sheets if sheet.panels and all(
        re.fullmatch(r"plan-\d+-(velocity|acceleration|heading)", name) for name in sheet.panels)]
    assert plans_alone
    for sheet in plans_alone:
        assert not re.search(r"\d:\d", " ".join(text.text for text in texts([layer(sheet, "title-block")]))), \
            sheet.number
