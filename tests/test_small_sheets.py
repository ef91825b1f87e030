"""A course project on A4: each sheet turned the way its drawings fit, the force drawings made smaller where
no A4 holds them at the mechanism's scales, and every caption broken to the sheet.

The ratchet at μl = 0.005 m/mm is the case: its plan of positions (116 × 195 mm) stands only upright, its
kinematic diagrams (255 mm wide) only across, and its group II(3,4) cut free is 160 mm tall at μl before its
caption. Scales are checked on the drawings themselves: the pins' distances against the scene's lengths, the
lever's rays against the velocities.
"""

import dataclasses
import functools
import itertools
import math
import re

import pytest
from hypothesis import given
from hypothesis import strategies as st
from test_sheets import (
    FIXTURES,
    STANDARD,
    analyses_of,
    force_drawings_on,
    held_under_its_heading,
    inside,
    layer,
    overlap,
    placed_bounds,
    texts,
    with_drawing,
)

import graphplan
from graphplan.analysis import analyse
from graphplan.errors import SceneError
from graphplan.kinematic_diagrams import of_analysis
from graphplan.locale import strings
from graphplan.render import forces as force_layout
from graphplan.render import plans as plan_layout
from graphplan.render.drawings import force_sheet, with_length_scale
from graphplan.render.force_rows import CAPTION_WIDTH_MM, HEADING_LAYER
from graphplan.render.formats import FORMATS, page_geometry
from graphplan.render.numerals import scale_factor, significant
from graphplan.render.primitives import Circle, Layer, Polyline, Text, bounds, text_extent, text_width
from graphplan.render.sheet import (
    _group_of_field,
    course_sheets,
    diagrams_panel,
    force_panels,
    forces_sheet,
    kinematics_panels,
    kinematics_sheet,
    split,
)
from graphplan.render.title_block import form_of, scale_text
from graphplan.render.wrapping import fitted
from graphplan.run import run
from graphplan.scales import format_scale, standard_scale

MECHANISM_SCALE = 0.005  # m/mm, the ratchet's scene gives 0.0025
CAPTION = plan_layout.CAPTION_SIZE


@functools.cache
def analysis_of(name):
    """One analysis of a fixture for the module (it is frozen, and the same file analyses alike): the ratchet's is
    read by its A4 and A1 sheets and its diagrams, the slotted lever's by its captions and its diagrams."""
    return analyses_of(name)


@pytest.fixture(scope="module")
def ratchet_a4():
    analysis = with_drawing(analysis_of("ratchet_crank_rocker"), length_scale=MECHANISM_SCALE, sheet="A4")
    return analysis, course_sheets(analysis, diagrams=(diagrams_panel(analysis, "A4"),))


def upright(sheet):
    return sheet.size[0] < sheet.size[1]


def test_every_drawing_of_the_ratchet_stands_on_an_a4_clear_of_the_others(ratchet_a4):
    _, sheets = ratchet_a4
    assert {tuple(sorted(sheet.size)) for sheet in sheets} == {tuple(sorted(FORMATS["A4"]))}
    for sheet in sheets:
        drawn = placed_bounds(sheet)
        block = bounds([layer(sheet, "title-block")])
        for panel, rect in drawn.items():
            assert inside(rect, sheet.frame), f"sheet {sheet.number}: {panel} leaves the frame"
            assert not overlap(rect, block), f"sheet {sheet.number}: {panel} covers the title block"
        for (first, a), (second, b) in itertools.combinations(drawn.items(), 2):
            assert not overlap(a, b), f"sheet {sheet.number}: {first} overlaps {second}"
        for text in texts(sheet.layers):
            assert inside(text_extent(text), sheet.frame), f"sheet {sheet.number}: {text.text!r} outside the frame"


def test_each_a4_is_turned_the_way_its_drawings_fit(ratchet_a4):
    _, sheets = ratchet_a4
    positions = next(sheet for sheet in sheets if "positions" in sheet.panels)
    diagrams = [sheet for sheet in sheets if any(name.startswith("diagrams") for name in sheet.panels)]
    assert upright(positions)
    assert diagrams and not any(upright(sheet) for sheet in diagrams)
    # The positions fit no A4 across, the diagrams none upright: one orientation for the set could not hold them.
    width, height = _size(positions, "positions")
    assert not page_geometry("A4", "eskd", portrait=False).holds(width, height)
    for sheet in diagrams:
        for name in sheet.panels:
            assert not page_geometry("A4", "eskd", portrait=True).holds(*_size(sheet, name))


def _size(sheet, name):
    x0, y0, x1, y1 = sheet.panels[name]
    return x1 - x0, y1 - y0


# Force drawings on A4.

def a4_force_sheets(length_scale, velocity_pole):
    """The ratchet's force sheets on A4 with the scene's μl and pole distance pv changed."""
    scene = graphplan.load("fixtures/ratchet_crank_rocker.toml")
    drawing = dataclasses.replace(scene.drawing, length_scale=length_scale, velocity_pole=velocity_pole, sheet="A4")
    analysis = analyse(dataclasses.replace(scene, drawing=drawing))
    return analysis, forces_sheet(force_panels(analysis), "A4", "ru", scale=length_scale)


@pytest.fixture(scope="module")
def drawn_smaller():
    """At the scene's μl = 0.0025 the group II(3,4) cut free is 320 mm tall, and at pv = 300 mm the lever
    300 mm wide: no A4 holds either at those scales."""
    return a4_force_sheets(0.0025, 300.0)


def caption_of(sheet, drawing):
    return " ".join(text.text for text in texts([layer(sheet, f"{drawing}-caption")]))


def drawing_on(sheets, position, drawing):
    """The sheet that holds ``drawing`` of ``position``'s force sheet and the drawing's name there, whichever
    part of the force sheet (``forces-5``, ``forces-5-2``) or piece of it (``forces-5-lever``) it stands in."""
    pattern = re.compile(rf"forces-{position.number}(-\d+)?-{drawing}")
    for sheet in sheets:
        for item in sheet.layers:
            found = pattern.match(item.name)
            if found and item.name == f"{found.group(0)}-caption":
                return sheet, found.group(0)
    raise AssertionError(f"no sheet holds {drawing} of position {position.number}")


def check_group_scale(analysis, sheets):
    """Each group II(3,4) cut free is drawn at the μl its caption and its sheet's scale box give: its pins stand
    the scene's lengths apart at that scale. Returns those scales."""
    group = next(group for group in analysis.scene.groups if group.kind == "RRR")
    scales = []
    for position in analysis.plans:
        sheet, name = drawing_on(sheets, position, "body-II-3-4")
        drawn_at = float(re.search(r"μl = ([\d.]+) м/мм", caption_of(sheet, name)).group(1))
        links = layer(sheet, f"{name}-links")
        pins = [item.centre for item in links.items if isinstance(item, Circle) and item.radius == pytest.approx(1.3)]
        distances = [math.dist(a, b) * drawn_at for a, b in itertools.combinations(pins, 2)]
        for length in group.lengths:  # AB and BC; AC is the third side of the triangle
            assert any(d == pytest.approx(length, rel=1e-9) for d in distances)
        assert scale_text(drawn_at, "eskd", "") in [text.text for text in texts([layer(sheet, "title-block")])]
        scales.append(drawn_at)
    return scales


def check_lever_scale(analysis, sheets):
    """Each lever is the velocity plan at the μV its caption gives: its rays are the velocities at that scale,
    and the balancing moment it finds is the lever's own. Returns those scales."""
    scales = []
    for position in analysis.plans:
        sheet, name = drawing_on(sheets, position, "lever")
        caption = caption_of(sheet, name)
        drawn_at = float(re.search(r"μV = ([\d.]+) ", caption).group(1))
        if drawn_at == pytest.approx(position.velocity.scale, rel=1e-3):
            drawn_at = position.velocity.scale  # the plan's own μV, written to four digits
        rays = [item for item in layer(sheet, f"{name}-plan").items
                if isinstance(item, Polyline) and len(item.points) == 2 and item.stroke.width == 0.25]
        drawn = sorted(math.dist(*ray.points) * drawn_at for ray in rays)
        images = {letter for letter in position.velocity.images.values() if letter != "p"}
        velocities = sorted(abs(position.velocity.points[letter]) for letter in images
                            if abs(position.velocity.points[letter]) / drawn_at >= plan_layout.ZERO_MM)
        assert drawn == pytest.approx(velocities, rel=1e-6)
        assert f"Mу = {significant(position.lever.balancing)} Н·м" in caption  # Russian: the textbook's Mу
        scales.append(drawn_at)
    return scales


def fits_a4(panel):
    x0, y0, x1, y1 = panel.extent
    return any(page_geometry("A4", "eskd", portrait).holds(x1 - x0, y1 - y0) for portrait in (False, True))


def test_on_a4_the_ratchet_forces_keep_their_scales_with_smaller_lettering(ratchet_a4):
    analysis, sheets = ratchet_a4
    # Position 5's group II(3,4) at 1:5 stands 214 mm tall under its heading, and the levers at their plans' μV
    # 209 and 212: they filled the 216 mm of an upright A4, of which GOST 2.104's графа 26 (14 mm in the frame's
    # top left corner) leaves 202 beside its 70 mm.  Position 11's group keeps its scale in smaller lettering.
    assert [position.number for position in analysis.plans] == [5, 11]
    assert check_group_scale(analysis, sheets) == [2 * MECHANISM_SCALE, MECHANISM_SCALE]
    # Each balancing load on one line of the caption (two lines, once four) leaves the levers room at 0.025 under
    # the line that says the plan is turned 90° clockwise, which a lever read without the note needs; at 0.02
    # both now stand too tall, 0.025 is a standard step smaller than position 11's plan's μV.
    assert check_lever_scale(analysis, sheets) == [0.025, 0.025]
    force_captions = [text for sheet in sheets for item in sheet.layers
                      if item.name.startswith("forces-") and item.name.endswith("-caption") for text in item.items]
    assert force_captions and {text.size for text in force_captions} == {force_layout.SMALL_CAPTION_SIZE}
    # The usual lettering would not do: some drawing of the force sheet then fits no A4.
    unframed = force_panels(analysis, "none")
    assert not all(fits_a4(piece) for panel in unframed for part in panel.parts for piece in part.parts or (part,))


def scale_box(sheet):
    """The ratios (1:10) written in the sheet's title block: its scale box's, the ESKD form giving μl as one."""
    return re.findall(r"\d+:\d+", " ".join(text.text for text in texts([layer(sheet, "title-block")])))


def test_a_sheet_of_a_lever_alone_leaves_the_scale_box_empty(ratchet_a4):
    """Zhukovsky's lever is the velocity plan turned through 90°, drawn at μV, to no length scale: the A4 that
    holds position 5's lever alone said 1:10 in its scale box (the group cut free's μl, on another sheet), and
    position 11's 1:5, as a sheet of velocity plans alone once did."""
    analysis, sheets = ratchet_a4
    levers_alone = [sheet for sheet in sheets if force_drawings_on(sheet) == {"lever"}]
    assert len(levers_alone) == len(analysis.plans) == 2
    for sheet in levers_alone:
        assert scale_box(sheet) == [], sheet.number
    # A sheet with a group cut free on it still gives the μl the group is drawn at.
    for sheet in sheets:
        if "body" in force_drawings_on(sheet):
            assert len(scale_box(sheet)) == 1, sheet.number


def test_a_sheet_of_force_polygons_alone_leaves_the_scale_box_empty(ratchet_a4):
    """A force polygon is drawn at μF, to no length scale: the A4s that hold a polygon of position 5 or 11 alone
    under the heading "(continued)" said 1:10 or 1:5 in their scale boxes, the μl of the group on the sheet
    before."""
    _, sheets = ratchet_a4
    polygons_alone = [sheet for sheet in sheets if force_drawings_on(sheet) == {"polygon"}]
    assert polygons_alone
    for sheet in polygons_alone:
        assert scale_box(sheet) == [], sheet.number


def heading_scales(panel):
    """The line of scales under a force sheet's (or a part's) heading, none where it stands without one."""
    return [item.text for part in panel.layers if part.name == HEADING_LAYER for item in part.items
            if isinstance(item, Text) and item.weight != "bold"]


def drawings_in(panel):
    return {part.name.removesuffix("-caption") for part in panel.layers if part.name.endswith("-caption")}


def test_a_part_of_a_force_sheet_names_only_the_scales_its_drawings_are_drawn_at():
    """The shaper's force sheets on A4 at one μF stand in parts, position 10's lever alone on its last, under
    "(continued)": that heading said μl = 0.004 m/mm, μF = 50 N/mm, μV = 0.02 (m/s)/mm, though the lever is the
    velocity plan turned, drawn at μV alone (its arrows at a μF its caption gives).  Each part's heading names
    the scales of the drawings that may stand under it: its own and the later parts' (a part that goes on on the
    sheet of the part before stands under that one's heading), the groups cut free μl, the polygons μF, the
    lever μV."""
    scene = graphplan.load("fixtures/shaper_six_bar.toml")
    analysis = analyse(dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, sheet="A4",
                                                                                force_scale=50.0)))
    words = strings(analysis.scene.locale)
    panels = force_panels(analysis, "A4")
    levers = [panel for panel in panels if drawings_in(panel) == {"lever"} and heading_scales(panel)]
    assert levers, [(panel.name, drawings_in(panel)) for panel in panels]
    for panel in levers:
        drawn_at = words["velocity_scale"].format(value=format_scale(panel.lever_scale))
        assert heading_scales(panel) == [drawn_at], panel.name
        # The μV the lever's caption gives: the scale it is drawn at.
        assert drawn_at in " ".join(item.text for part in panel.layers if part.name == "lever-caption"
                                    for item in part.items), panel.name
    for position in analysis.plans:
        parts = [panel for panel in panels if re.fullmatch(rf"forces-{position.number}(-\d+)?", panel.name)]
        assert len(parts) > 1, position.number
        for k, panel in enumerate(parts):
            if not heading_scales(panel):  # a drawing too big to stand under a heading
                continue
            later = {name.split("-")[0] for part in parts[k:] for name in drawings_in(part)}
            (line,) = heading_scales(panel)
            assert ("μl" in line, "μF" in line, "μV" in line) == ("body" in later, "polygon" in later,
                                                                  "lever" in later), (panel.name, line)


def test_force_drawings_no_a4_holds_are_drawn_at_the_next_standard_scales_that_fit(drawn_smaller):
    analysis, sheets = drawn_smaller
    group_scales = check_group_scale(analysis, sheets)
    lever_scales = check_lever_scale(analysis, sheets)
    scene = analysis.scene.drawing
    assert all(scale > scene.length_scale for scale in group_scales)
    assert all(scale > position.velocity.scale for scale, position in zip(lever_scales, analysis.plans, strict=True))
    for scale in (*group_scales, *lever_scales):
        assert scale in STANDARD
    # Each is the first standard scale that fits: one step back does not.
    for position, group_scale, lever_scale in zip(analysis.plans, group_scales, lever_scales, strict=True):
        back = max(value for value in STANDARD if value < group_scale - 1e-15)
        if back > scene.length_scale:
            sheet = with_scales(force_sheet(analysis, position), back, lever_scale)
            assert not fits_a4(part_named(sheet, position, "body-II-3-4"))
        back = max(value for value in STANDARD if value < lever_scale - 1e-15)
        if back > position.velocity.scale:
            sheet = with_scales(force_sheet(analysis, position), group_scale, back)
            assert not fits_a4(part_named(sheet, position, "lever"))
    for sheet in sheets:
        drawn = placed_bounds(sheet)
        for panel, rect in drawn.items():
            assert inside(rect, sheet.frame), f"sheet {sheet.number}: {panel} leaves the frame"


def with_scales(sheet, length_scale, lever_scale):
    return dataclasses.replace(sheet, length_scale=length_scale, lever_scale=lever_scale,
                               caption_size=force_layout.SMALL_CAPTION_SIZE)


def part_named(sheet, position, name):
    panel = split(force_layout.arrange(sheet), f"forces-{position.number}", "", _group_of_field)
    return next(piece for part in panel.parts for piece in part.parts or (part,)
                if piece.name == f"forces-{position.number}-{name}")


def test_on_a1_the_force_drawings_keep_the_mechanism_scale_or_a_finer_one_and_the_usual_lettering():
    """A1 has room: the groups cut free are drawn at the mechanism's μl or larger (a finer standard μl, where the
    sheet holds them so), never smaller, and lettered as usual."""
    analysis = analysis_of("ratchet_crank_rocker")
    sheets = course_sheets(analysis, "A1")
    captions = [text for sheet in sheets for item in sheet.layers
                if item.name.startswith("forces-") and item.name.endswith("caption") for text in texts([item])]
    joined = " ".join(text.text for text in captions)
    drawn = [float(value) for value in re.findall(r"μl = ([\d.]+) м/мм, стрелки сил", joined)]
    assert drawn and all(value <= analysis.scene.drawing.length_scale for value in drawn)
    assert all(standard_scale(value) == pytest.approx(value) for value in drawn)
    for position in analysis.plans:
        assert f"μV = {scale_factor(position.velocity.scale)} (м/с)/мм, стрелки сил" in joined
    assert {text.size for text in captions} == {plan_layout.CAPTION_SIZE}


def box(width, height):
    return [Layer("box", (Polyline(((0, 0), (width, 0), (width, height), (0, height)), closed=True),))]


def test_an_a4_set_turns_each_sheet_for_its_drawing_where_no_one_way_holds_them_all():
    upright_room, across_room = (max(page_geometry("A4", "iso", portrait).rooms()) for portrait in (True, False))
    tall = (upright_room[0] - 10, upright_room[1] - 10)
    wide = (across_room[0] - 10, min(across_room[1] - 10, tall[1] / 2))
    assert not page_geometry("A4", "iso", portrait=False).holds(*tall)
    assert not page_geometry("A4", "iso", portrait=True).holds(*wide)
    sheets = kinematics_sheet([box(*tall), box(*wide)], "A4", "en")
    assert [upright(sheet) for sheet in sheets] == [True, False]
    # One way holds both: the set is not turned about.
    sheets = kinematics_sheet([box(*tall), box(100, 100)], "A4", "en")
    assert all(upright(sheet) for sheet in sheets)


def test_a_drawing_too_big_for_any_a4_names_the_room_there_is():
    with pytest.raises(SceneError) as error:
        kinematics_sheet([box(300, 300)], "A4", "ru")
    message = str(error.value)
    for portrait in (False, True):
        for width, height in page_geometry("A4", "eskd", portrait).rooms():
            # A strip under 10 mm (the upright sheet's between графа 26 and the title block) is no room to offer.
            if min(width, height) >= 10.0:
                assert f"{width:.0f} × {height:.0f}" in message
            else:
                assert f"{width:.0f} × {height:.0f}" not in message
    # A3 lies only across, its room 374 × 221 mm: the format to name is A2.
    assert "choose A2 or a bigger sheet" in message


# Captions broken to the sheet.

SIGNED_TERMS = st.lists(st.tuples(st.sampled_from("+−"), st.from_regex(r"[A-Z][a-z]?[0-9]{1,2}·h[0-9]", fullmatch=True)),
                        min_size=1, max_size=30)


@given(SIGNED_TERMS, st.floats(60.0, 200.0))
def test_a_long_equation_breaks_before_its_signs_each_line_within_the_width(terms, width):
    line = "ΣMp: " + " ".join(f"{sign} {name}" for sign, name in terms) + " = 0"
    pieces = fitted(line, width, CAPTION)
    assert " ".join(pieces) == line
    assert all(piece == pieces[0] or piece[0] in "+−" for piece in pieces)
    if all(text_width(f"{sign} {name} = 0", CAPTION) <= width for sign, name in terms) and \
            text_width(f"ΣMp: {terms[0][0]} {terms[0][1]}", CAPTION) <= width:
        assert all(text_width(piece, CAPTION) <= width for piece in pieces)


def test_a_value_is_never_parted_from_its_name_or_its_unit():
    line = "уравновешивающий момент Mb = 49.02 Н·м (по планам сил)"
    for width in range(40, 240, 5):
        pieces = fitted(line, float(width), CAPTION)
        assert " ".join(pieces) == line
        assert any("Mb = 49.02 Н·м" in piece for piece in pieces), (width, pieces)


def test_every_caption_line_of_a_force_sheet_keeps_within_its_drawing_or_the_caption_width():
    analysis = analysis_of("quick_return_slotted_lever")
    for position in analysis.plans:
        arranged = force_layout.arrange(force_sheet(analysis, position))
        for name in arranged.fields:
            caption = next(item for item in arranged.layers if item.name == f"{name}-caption")
            drawing = [item for item in arranged.layers if item.name.startswith(f"{name}-") and item is not caption]
            x0, _, x1, _ = bounds(drawing)
            limit = max(x1 - x0, CAPTION_WIDTH_MM)
            for text in caption.items:
                assert isinstance(text, Text)
                assert text_width(text.text, text.size, text.weight) <= limit + 1e-9, text.text


# The kinematic diagrams on A4.

@pytest.mark.parametrize("name", FIXTURES)
def test_the_kinematic_diagrams_of_every_fixture_fit_a4_with_their_long_lines_broken(name):
    analysis = analysis_of(name)
    if analysis.scene.positions.working is None or analysis.scene.driver.kind != "crank":
        pytest.skip("no kinematic diagrams without a working stroke of a crank")
    panel = diagrams_panel(analysis, "A4")
    form = form_of(analysis.scene.locale)
    for part in panel.parts:
        assert held_under_its_heading(part, "A4", form), part.name
    # Every word is still there: the broken lines read as the whole ones.
    written = " ".join(text.text for text in texts(panel.layers))
    record = of_analysis(analysis)
    for value in (record.largest_v_difference, record.largest_a_difference):
        assert f"{value:.2f} %" in written
    assert re.search(r"μt = μφ/\|ω\| = [\d.]+ ", written)


def on_a4(name, **changes):
    """The fixture's course sheets on A4 at its automatic μl, with its drawing's keys changed."""
    scene = graphplan.load(f"fixtures/{name}.toml")
    drawing = dataclasses.replace(scene.drawing, length_scale=None, sheet="A4", **changes)
    # μl is left to the sheets to choose, as a run's are: they refuse what overflows before the choice, which lays
    # every sheet out at each μl it tries.  The diagrams draw no linkage: the same at any μl.
    analysis = analyse(dataclasses.replace(scene, drawing=drawing))
    return course_sheets(analysis, diagrams=(diagrams_panel(analysis, "A4"),))


def refusal_on_a4(name, **changes):
    with pytest.raises(SceneError) as error:
        on_a4(name, **changes)
    assert error.value.where == "drawing.sheet"
    return str(error.value)


def check_inside_frames(sheets):
    for sheet in sheets:
        for panel, rect in placed_bounds(sheet).items():
            assert inside(rect, sheet.frame), f"sheet {sheet.number}: {panel} leaves the frame"


def named_pole(message, kind):
    return int(re.search(rf"drawing\.{kind}_pole = (\d+) \(or less\)", message).group(1))


def test_a_plan_too_big_for_a4_names_the_largest_pole_distance_that_fits():
    """The shaper's acceleration plan at pa = 100 mm is 197 mm square: no room of an A4 holds it."""
    message = refusal_on_a4("shaper_six_bar")
    assert "'plan-10-acceleration' (197 × 195 mm) at drawing.acceleration_pole = 100 mm: no A4 sheet holds it" in message
    assert "velocity_pole" not in message and "choose A3 or a bigger sheet" in message
    fitting = named_pole(message, "acceleration")
    assert 50 < fitting < 100
    check_inside_frames(on_a4("shaper_six_bar", acceleration_pole=float(fitting)))
    one_more = refusal_on_a4("shaper_six_bar", acceleration_pole=fitting + 1.0)
    assert named_pole(one_more, "acceleration") == fitting


def test_a_refusal_only_weighed_leaves_out_the_values_it_would_offer_and_offers_them_after():
    """The reach advice tries swings only to see whether the run refuses them: there the shaper's plan on A4 is
    refused alike, with no pole distance worked out (a halving of laid-out plans, most of a trial's time), and so are
    a μl and a μF too small for A4 with no larger scale tried; outside that, the same refusals name them again."""
    from graphplan.errors import verdict_only

    quick_return = graphplan.load("fixtures/quick_return_slotted_lever.toml")   # at its μl = 0.002 m/mm
    quick_return = dataclasses.replace(quick_return, drawing=dataclasses.replace(quick_return.drawing, sheet="A4"))
    refusals = {"pole": lambda: on_a4("shaper_six_bar"), "μl": lambda: course_sheets(analyse(quick_return)),
                "μF": lambda: on_a4("ratchet_crank_rocker", force_scale=5.0)}
    for kind, refused in refusals.items():
        with verdict_only(), pytest.raises(SceneError) as weighed:
            refused()
        with pytest.raises(SceneError) as told:
            refused()
        assert weighed.value.where == told.value.where == "drawing.sheet", kind
        assert str(told.value).split(": no A4")[0] == str(weighed.value).split(": no A4")[0], kind
        assert "(or less)" not in str(weighed.value) and "(or more)" not in str(weighed.value), kind
        assert re.search(r"\((or less|or more)\)", str(told.value)), kind
    assert 50 < named_pole(refusal_on_a4("shaper_six_bar"), "acceleration") < 100


def test_a_plan_at_the_program_s_scale_too_big_for_a4_names_a_pole_distance_that_fits():
    """The triad's acceleration plan of position 1 at the μa the program chose is 166 mm wide, 2 mm more than an
    upright A4 holds: the error named no key to change (a student's A4 run), and now the pole distance that fits,
    which the next one refuses."""
    scene = graphplan.load("fixtures/triad_class_iii.toml")
    positions = dataclasses.replace(scene.positions, plans=(1,))
    drawing = dataclasses.replace(scene.drawing, sheet="A4", velocity_pole=None, acceleration_pole=None)

    def on_sheet(**changes):
        changed = dataclasses.replace(scene, positions=positions, drawing=dataclasses.replace(drawing, **changes))
        return course_sheets(analyse(changed))   # μl chosen by the sheets; the triad has no output link: no diagrams

    with pytest.raises(SceneError) as error:
        on_sheet()
    message = str(error.value)
    assert "'plan-1-acceleration'" in message and "acceleration scale μa = " in message and "(the program's)" in message
    fitting = named_pole(message, "acceleration")
    check_inside_frames(on_sheet(acceleration_pole=float(fitting)))
    with pytest.raises(SceneError) as error:
        on_sheet(acceleration_pole=fitting + 1.0)
    assert named_pole(str(error.value), "acceleration") == fitting


def test_a_pole_distance_too_long_for_the_sheet_is_refused_before_the_sheets_are_laid_out(monkeypatch, tmp_path):
    """The plans at the scene's pole distances are drawn at no μl, yet check chose μl first, laying every force
    sheet out at each μl it tried, and took 70 s to refuse a shaper's twelve plans on A4 (a student's check)."""
    from graphplan.render import sheet as sheet_module

    scene = graphplan.load("fixtures/shaper_six_bar.toml")
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, length_scale=None, sheet="A4"))
    # As the sheets laid out at the μl the program chooses refuse it (the choice lays them out at each μl tried).
    chosen = with_length_scale(analyse(scene))
    with pytest.raises(SceneError) as error:
        sheet_module._refuse_overflows(chosen, "A4", kinematics_panels(chosen))
    expected = named_pole(str(error.value), "acceleration")

    def laid_out(*_args, **_kwargs):
        raise AssertionError("the force sheets were laid out before the refusal")

    monkeypatch.setattr(sheet_module, "_force_sheets", laid_out)
    with pytest.raises(SceneError) as error:
        sheet_module.refuse_overflows(analyse(scene))
    assert "'plan-10-acceleration'" in str(error.value) and "drawing.acceleration_pole = 100 mm" in str(error.value)
    assert named_pole(str(error.value), "acceleration") == expected
    # The sheets themselves, and a run of them, refuse it so too: before μl is chosen or a force sheet laid out.
    monkeypatch.setattr(sheet_module, "fewest_sheets_length_scale", laid_out)
    assert refusal_on_a4("shaper_six_bar") == str(error.value)
    with pytest.raises(SceneError) as run_error:
        run(scene, tmp_path / "out", only=["sheets"])
    assert str(run_error.value) == str(error.value)


def test_plans_too_big_for_a4_are_named_together_with_a_pole_distance_for_each_kind():
    """The tangent mechanism's velocity and acceleration plans of position 10 both overflow A4 at the scene's
    pole distances; one error names both, and the two values it gives make the whole set fit."""
    message = refusal_on_a4("tangent_mechanism_prp")
    assert "'plan-10-velocity'" in message and "'plan-10-acceleration'" in message
    assert "drawing.velocity_pole = 100 mm, drawing.acceleration_pole = 100 mm: no A4 sheet holds them" in message
    velocity, acceleration = named_pole(message, "velocity"), named_pole(message, "acceleration")
    check_inside_frames(on_a4("tangent_mechanism_prp", velocity_pole=float(velocity),
                              acceleration_pole=float(acceleration)))


def test_a_plan_scale_given_in_the_scene_and_too_small_for_a4_is_answered_with_the_standard_scale_that_fits():
    """μa = 0.036 (m/s²)/mm is the shaper's scale at pa = 100 mm; at the standard 0.04 the plan is still
    about 177 mm square, at 0.05 about 142 mm, which an upright A4 holds."""
    message = refusal_on_a4("shaper_six_bar", acceleration_scale=0.036)
    assert "at drawing.acceleration_scale = 0.036: no A4 sheet holds it" in message
    fitting = float(re.search(r"drawing\.acceleration_scale = ([\d.]+) \(or more\)", message).group(1))
    assert fitting == 0.05
    assert "acceleration_scale = 0.05 (or more)" in refusal_on_a4("shaper_six_bar", acceleration_scale=0.04)
    check_inside_frames(on_a4("shaper_six_bar", acceleration_scale=fitting))


def test_a_force_scale_given_in_the_scene_and_too_small_for_a4_is_answered_with_the_standard_scale_that_fits():
    """At μF = 5 N/mm the ratchet's polygons of position 5 are over 200 mm tall; μF is the contract's
    polygon_scale, so the sheets refuse it with the smallest standard μF that fits instead of drawing smaller."""
    message = refusal_on_a4("ratchet_crank_rocker", force_scale=5.0)
    assert "'forces-5-polygon-I-1-2'" in message and "at drawing.force_scale = 5 N/mm: no A4 sheet holds them" in message
    fitting = float(re.search(r"drawing\.force_scale = ([\d.]+) \(or more\)", message).group(1))
    assert fitting == 10.0  # the standard factor after 5 (1, 2, 2.5, 4, 5 × 10ⁿ)
    sheets = on_a4("ratchet_crank_rocker", force_scale=fitting)
    check_inside_frames(sheets)
    assert any("μF = 10 Н/мм" in item.text for sheet in sheets for item in texts(sheet.layers))


def test_a_term_in_brackets_keeps_its_sign_and_a_title_breaks_after_its_colon():
    # "(mArA)II + (mБrБ)II + ((m·r)шкив)II +" ended a balancing caption's line on the sign: the break before a
    # bracket was taken after the sign of the bracketed term.
    equation = "(mArA)II + (mБrБ)II + ((m·r)шкив)II + ((m·r)муфта)II + mIIrII = 0"
    for width in range(60, 240, 5):
        pieces = fitted(equation, float(width), CAPTION)
        assert " ".join(pieces) == equation
        assert not any(piece.endswith(("+", "−")) for piece in pieces), (width, pieces)
    assert fitted(equation, 160.0, CAPTION) == ["(mArA)II + (mБrБ)II + ((m·r)шкив)II", "+ ((m·r)муфта)II + mIIrII = 0"]
    title = "Уравновешивание ротора: многоугольник дисбалансов"
    assert fitted(title, 180.0, 7.0, "bold") == ["Уравновешивание ротора:", "многоугольник дисбалансов"]
    assert fitted("转子平衡：质径积矢量多边形", 80.0, 7.0, "bold") == ["转子平衡：", "质径积矢量多边形"]


def test_a_chinese_caption_breaks_after_its_full_width_comma_and_before_its_bracket():
    line = "μV = 0.01983 (m/s)/mm，力：μF = 25 N/mm，最短 10 mm；平衡力矩 Mb = 49.02 N·m（茹可夫斯基杠杆）"
    pieces = fitted(line, 80.0, CAPTION)
    assert "".join(pieces).replace(" ", "") == line.replace(" ", "")
    assert all(text_width(piece, CAPTION) <= 80.0 for piece in pieces)
    assert "（茹可夫斯基杠杆）" in pieces
    assert any(piece.endswith("，") for piece in pieces)


def test_the_chosen_length_scale_fits_the_mechanism_of_every_plan_sheet_not_only_the_plan_of_positions():
    """The slider-driven mechanism on A4: at μl = 0.002 m/mm its plan of positions fits an A4, but the mechanism
    of its plan sheet (170 mm wide with its letters and senses) fits no room of one; μl = 0.0025 is chosen."""
    scene = graphplan.load("fixtures/slider_driven.toml")
    drawing = dataclasses.replace(scene.drawing, length_scale=None, sheet="A4")
    analysis = with_length_scale(analyse(dataclasses.replace(scene, drawing=drawing)))
    chosen = analysis.scene.drawing.length_scale
    smaller = STANDARD[STANDARD.index(chosen) - 1]
    positions, *plan_panels = kinematics_panels(with_drawing(analysis, length_scale=smaller))
    mechanisms = [part for panel in plan_panels for part in panel.parts if part.name.endswith("-mechanism")]
    assert len(mechanisms) == len(analysis.plans) > 0
    form = form_of(analysis.scene.locale)

    def fits(panel):
        x0, y0, x1, y1 = panel.extent
        return any(page_geometry("A4", form, portrait).holds(x1 - x0, y1 - y0) for portrait in (False, True))

    assert fits(positions)
    assert not all(fits(part) for part in mechanisms)
    for sheet in course_sheets(analysis):
        for panel, rect in placed_bounds(sheet).items():
            assert inside(rect, sheet.frame), f"sheet {sheet.number}: {panel} leaves the frame"


def test_a_plan_sheet_mechanism_too_big_at_the_scene_length_scale_names_the_length_scale_that_fits():
    scene = graphplan.load("fixtures/slider_driven.toml")

    def on_a4(length_scale):
        drawing = dataclasses.replace(scene.drawing, length_scale=length_scale, sheet="A4")
        return course_sheets(analyse(dataclasses.replace(scene, drawing=drawing)))

    with pytest.raises(SceneError) as error:
        on_a4(0.002)
    message = str(error.value)
    assert error.value.where == "drawing.sheet"
    assert re.search(r"the drawing 'plan-\d+-mechanism' is \d+ × \d+ mm at μl = 0\.002 m/mm", message)
    assert "choose A3 or a bigger sheet" in message
    fitting = float(re.search(r"length_scale = ([0-9.]+)", message).group(1))
    assert fitting == STANDARD[STANDARD.index(0.002) + 1]
    for sheet in on_a4(fitting):
        for panel, rect in placed_bounds(sheet).items():
            assert inside(rect, sheet.frame), f"sheet {sheet.number}: {panel} leaves the frame"


def test_every_drawing_the_scene_s_scales_make_too_big_is_named_in_one_error_whose_values_all_fit():
    """The quick-return on A4 at the scene's μl = 0.002 m/mm: its plan of positions and both plans of position
    11 overflow; one error gives μl and both pole distances, and with all three the set fits."""
    scene = graphplan.load("fixtures/quick_return_slotted_lever.toml")
    assert scene.drawing.length_scale == 0.002

    def on_a4(**changes):
        drawing = dataclasses.replace(scene.drawing, sheet="A4", **changes)
        return course_sheets(analyse(dataclasses.replace(scene, drawing=drawing)))

    with pytest.raises(SceneError) as error:
        on_a4()
    message = str(error.value)
    assert message.startswith("drawing.sheet: the plan of positions is ")
    assert "'plan-11-velocity'" in message and "'plan-11-acceleration'" in message
    assert message.count("no A4 sheet holds them") == 1
    length = float(re.search(r"drawing\.length_scale = ([\d.]+) \(or more\)", message).group(1))
    check_inside_frames(on_a4(length_scale=length, velocity_pole=float(named_pole(message, "velocity")),
                              acceleration_pole=float(named_pole(message, "acceleration"))))


def test_a_sign_is_never_left_alone_at_the_end_of_a_line():
    """Found by hypothesis: '+ Am00·h0 = 0' is a hair wider than 60 mm, and was broken after its '+'."""
    assert fitted("ΣMp: + A0·h0 + Am00·h0 = 0", 60.0, CAPTION) == ["ΣMp: + A0·h0", "+ Am00·h0 = 0"]


def test_a_factored_term_is_broken_inside_its_brackets_only_where_it_fits_no_line_alone():
    equation = "ΣMp: G3·h1 + Fu3·h2 − (Mu3′ − Mf23′ + Mf43′)·h3 + G4·h5 = 0"
    whole = text_width("− (Mu3′ − Mf23′ + Mf43′)·h3", CAPTION)
    # Room for the bracket and more on a line, not for the whole equation: it goes to a line of its own whole.
    for width in (whole + 1.0, 1.4 * whole, text_width(equation, CAPTION) - 10.0):
        pieces = fitted(equation, width, CAPTION)
        assert " ".join(pieces) == equation and all(piece.count("(") == piece.count(")") for piece in pieces), pieces
    # Narrower than the bracket alone, it is broken inside, between its names, never after a sign.
    narrow = fitted(equation, whole - 5.0, CAPTION)
    assert " ".join(narrow) == equation and not any(piece.endswith(("+", "−")) for piece in narrow), narrow
    assert any(piece.count("(") != piece.count(")") for piece in narrow), narrow
    # Words in brackets are no factored term: they still break after a comma inside.
    prose = "Mb = −166.7 N·m (iterations: 7, settled to 1e-9 of the load)"
    assert fitted(prose, text_width("Mb = −166.7 N·m (iterations: 7,", CAPTION) + 1.0, CAPTION) == [
        "Mb = −166.7 N·m (iterations: 7,", "settled to 1e-9 of the load)"]
