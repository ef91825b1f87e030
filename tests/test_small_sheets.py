"""A course project on A4: each sheet turned the way its drawings fit, the force drawings made smaller where
no A4 holds them at the mechanism's scales, and every caption broken to the sheet.

The ratchet at μl = 0.005 m/mm is the case: its plan of positions (116 × 195 mm) stands only upright, its
kinematic diagrams (255 mm wide) only across, and its group II(3,4) cut free is 160 mm tall at μl before its
caption. Scales are checked on the drawings themselves: the pins' distances against the scene's lengths, the
lever's rays against the velocities.
"""

import itertools
import math
import re

import pytest
from hypothesis import given
from hypothesis import strategies as st
from test_sheets import analyses_of, inside, layer, overlap, placed_bounds, texts, with_drawing

from graphplan.errors import SceneError
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, plan_scale_text
from graphplan.render.formats import FORMATS, page_geometry
from graphplan.render.primitives import Circle, Layer, Polyline, Text, bounds, text_extent
from graphplan.render.sheet import course_sheets, diagrams_panel, force_panels, kinematics_sheet
from graphplan.render.title_block import scale_text

MECHANISM_SCALE = 0.005  # m/mm, the ratchet's scene gives 0.0025


@pytest.fixture(scope="module")
def ratchet_a4():
    analysis = with_drawing(analyses_of("ratchet_crank_rocker"), length_scale=MECHANISM_SCALE, sheet="A4")
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


def test_a_group_cut_free_too_big_for_a4_is_drawn_at_a_larger_standard_scale_that_its_caption_and_block_name(
        ratchet_a4):
    analysis, sheets = ratchet_a4
    group = next(group for group in analysis.scene.groups if group.kind == "RRR")
    unframed = {panel.name: panel for panel in force_panels(analysis, "none")}
    bodies = [(sheet, item) for sheet in sheets for item in sheet.layers
              if re.fullmatch(r"forces-\d+-body-II-3-4-links", item.name)]
    assert len(bodies) == len(analysis.plans)
    smaller = 0
    for sheet, links in bodies:
        caption = " ".join(text.text for text in texts([layer(sheet, links.name.replace("-links", "-caption"))]))
        drawn_at = float(re.search(r"μl = ([\d.]+) м/мм", caption).group(1))
        pins = [item.centre for item in links.items if isinstance(item, Circle) and item.radius == pytest.approx(1.3)]
        distances = [math.dist(a, b) * drawn_at for a, b in itertools.combinations(pins, 2)]
        for length in group.lengths:  # AB and BC; AC is the third side of the triangle
            assert any(d == pytest.approx(length, rel=1e-9) for d in distances)
        block = [text.text for text in texts([layer(sheet, "title-block")])]
        assert scale_text(drawn_at, "eskd", "") in block
        # At the mechanism's own μl the group cut free fits no empty A4 exactly when it is drawn smaller.
        panel = unframed[links.name.split("-body-")[0]]
        alone = next(piece for part in panel.parts for piece in part.parts or (part,)
                     if piece.name.endswith("-body-II-3-4"))
        x0, y0, x1, y1 = alone.extent
        fits = any(page_geometry("A4", "eskd", portrait).holds(x1 - x0, y1 - y0) for portrait in (False, True))
        assert fits == (drawn_at == MECHANISM_SCALE)
        smaller += drawn_at > MECHANISM_SCALE
    assert smaller >= 1


def test_a_lever_too_big_for_a4_is_the_velocity_plan_at_a_larger_scale_that_its_caption_names(ratchet_a4):
    analysis, sheets = ratchet_a4
    for position in analysis.plans:
        sheet = next(sheet for sheet in sheets if f"forces-{position.number}-lever" in sheet.panels)
        caption = " ".join(text.text for text in texts([layer(sheet, f"forces-{position.number}-lever-caption")]))
        drawn_at = float(re.search(r"μV = ([\d.]+) ", caption).group(1))
        assert drawn_at > position.velocity.scale
        rays = [item for item in layer(sheet, f"forces-{position.number}-lever-plan").items
                if isinstance(item, Polyline) and len(item.points) == 2 and item.stroke.width == 0.25]
        drawn = sorted(math.dist(*ray.points) * drawn_at for ray in rays)
        images = {letter for letter in position.velocity.images.values() if letter != "p"}
        velocities = sorted(abs(position.velocity.points[letter]) for letter in images
                            if abs(position.velocity.points[letter]) / drawn_at >= force_layout.ZERO_MM)
        assert drawn == pytest.approx(velocities, rel=1e-9)
        # The balancing moment found on the lever does not depend on its scale.
        assert f"Mb = {force_layout._number(position.lever.balancing)} Н·м" in caption


def test_on_a1_the_force_drawings_keep_the_mechanism_scale():
    analysis = analyses_of("ratchet_crank_rocker")
    sheets = course_sheets(analysis, "A1")
    captions = " ".join(text.text for sheet in sheets for item in sheet.layers if item.name.endswith("caption")
                        for text in texts([item]))
    assert f"μl = {analysis.scene.drawing.length_scale:g} м/мм, силы" in captions
    for position in analysis.plans:
        assert f"μV = {plan_scale_text(position.velocity.scale)} (м/с)/мм, силы" in captions


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
            if width > 0:
                assert f"{width:.0f} × {height:.0f}" in message
    assert "choose A3" in message


# Captions broken to the sheet.

SIGNED_TERMS = st.lists(st.tuples(st.sampled_from("+−"), st.from_regex(r"[A-Z][a-z]?[0-9]{1,2}·h[0-9]", fullmatch=True)),
                        min_size=1, max_size=30)


@given(SIGNED_TERMS, st.floats(60.0, 200.0))
def test_a_long_equation_breaks_before_its_signs_each_line_within_the_width(terms, width):
    line = "ΣMp: " + " ".join(f"{sign} {name}" for sign, name in terms) + " = 0"
    pieces = force_layout._fitted(line, width)
    assert " ".join(pieces) == line
    assert all(piece == pieces[0] or piece[0] in "+−" for piece in pieces)
    if all(force_layout._span(f"{sign} {name} = 0", "normal") <= width for sign, name in terms) and \
            force_layout._span(f"ΣMp: {terms[0][0]} {terms[0][1]}", "normal") <= width:
        assert all(force_layout._span(piece, "normal") <= width for piece in pieces)


def test_a_value_is_never_parted_from_its_name_or_its_unit():
    line = "уравновешивающий момент Mb = 49.02 Н·м (по планам сил)"
    for width in range(40, 240, 5):
        pieces = force_layout._fitted(line, float(width))
        assert " ".join(pieces) == line
        assert any("Mb = 49.02 Н·м" in piece for piece in pieces), (width, pieces)


def test_every_caption_line_of_a_force_sheet_keeps_within_its_drawing_or_the_caption_width():
    analysis = analyses_of("quick_return_slotted_lever")
    for position in analysis.plans:
        arranged = force_layout.arrange(force_sheet(analysis, position))
        for name in arranged.fields:
            caption = next(item for item in arranged.layers if item.name == f"{name}-caption")
            drawing = [item for item in arranged.layers if item.name.startswith(f"{name}-") and item is not caption]
            x0, _, x1, _ = bounds(drawing)
            limit = max(x1 - x0, force_layout.CAPTION_WIDTH_MM)
            for text in caption.items:
                assert isinstance(text, Text)
                assert force_layout._span(text.text, text.weight) <= limit + 1e-9, text.text
