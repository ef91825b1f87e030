"""Panels packed onto pages (graphplan.render.packing), with drawings of known size.

A part of a force sheet that goes on from a part already on the page stands under that part's heading:
it is placed, and takes room, without its own ("continued"), so that two parts that fit together only
without the second heading share a sheet.
"""

from graphplan.memo import RecentMemo
from graphplan.render import packing
from graphplan.render.force_rows import HEADING_LAYER
from graphplan.render.formats import page_geometry
from graphplan.render.packing import GAP_MM, Panel, pack
from graphplan.render.primitives import MAIN, Layer, Polyline

SHEET, FORM = "A3", "iso"
HEADING_MM = 20.0


def box(name: str, width: float, height: float, top: float = 0.0) -> Layer:
    """A rectangle ``width`` × ``height`` mm whose top edge is at ``top``."""
    corners = ((0.0, top - height), (width, top - height), (width, top), (0.0, top))
    return Layer(name, (Polyline(corners, MAIN, closed=True),))


def part(name: str, width: float, height: float, continues: str = "") -> Panel:
    """A force sheet's part: its drawing ``height`` mm tall under a heading :data:`HEADING_MM` tall."""
    return Panel(name, (box(HEADING_LAYER, width, HEADING_MM, HEADING_MM), box("drawing", width, height)),
                 continues=continues)


def room_above_the_title_block() -> tuple[float, float]:
    (width, height), _ = page_geometry(SHEET, FORM).rooms()
    return width, height


def two_parts(continues: bool) -> list:
    """Two parts as wide as the room above the title block (too wide to stand beside it), as tall together
    as that room holds once the second has no heading, and too tall with it."""
    width, height = room_above_the_title_block()
    first_height = height - HEADING_MM - GAP_MM - 60.0
    second_height = 58.0
    first = part("forces-5", width - 1.0, first_height)
    second = part("forces-5-2" if continues else "forces-6", width - 1.0, second_height,
                  continues="forces-5" if continues else "")
    return pack([first, second], SHEET, FORM)


def test_a_part_goes_on_under_the_heading_of_the_part_before_on_its_sheet():
    pages = two_parts(continues=True)
    assert len(pages) == 1
    (first, first_rect, _), (second, second_rect, _) = pages[0].placed
    assert [layer.name for layer in first.layers] == [HEADING_LAYER, "drawing"]
    assert [layer.name for layer in second.layers] == ["drawing"]
    assert second_rect[3] - second_rect[1] == 58.0
    # Under the first part, a gap apart, as the rest of a drawing that reads on.
    assert first_rect[1] - second_rect[3] >= GAP_MM - 1e-9


def test_a_drawing_that_goes_on_from_none_keeps_its_heading_and_its_room():
    """The same sizes without the link: the second needs its heading's room, which the sheet has not."""
    pages = two_parts(continues=False)
    assert len(pages) == 2
    (alone, rect, _), = pages[1].placed
    assert [layer.name for layer in alone.layers] == [HEADING_LAYER, "drawing"]
    assert rect[3] - rect[1] == HEADING_MM + 58.0


def test_a_part_on_a_sheet_of_its_own_keeps_its_heading():
    """Where the part it goes on from fills its sheet, the heading says on the next one that it goes on."""
    width, height = room_above_the_title_block()
    pages = pack([part("forces-5", width - 1.0, height - HEADING_MM),
                  part("forces-5-2", width - 1.0, 58.0, continues="forces-5")], SHEET, FORM)
    assert len(pages) == 2
    (second, _, _), = pages[1].placed
    assert [layer.name for layer in second.layers] == [HEADING_LAYER, "drawing"]


def drawing(name: str, width: float, height: float, *others: tuple[float, float]) -> Panel:
    """A drawing ``width`` × ``height`` mm, with other ways of arranging it of the sizes ``others``."""
    return Panel(name, (box("drawing", width, height),),
                 alternatives=tuple(Panel(name, (box("drawing", *size),)) for size in others))


def test_a_page_laid_out_afresh_grows_down_a_column_where_a_block_leaves_no_room_for_the_next_drawing():
    """A1 (ESKD) with the sizes of a V-twin's kinematics: the plan of positions, a plan sheet (a row 538 mm
    long, or its mechanism above its plans) and the kinematic diagrams. Grown as a block the plan sheet stands
    beside the plan of positions and leaves 800 − 814 mm for the diagrams; with the plan sheet under the plan
    of positions all three share the sheet, as a course project's first sheet has them."""
    panels = [drawing("positions", 163, 123), drawing("plan-3", 538, 170, (315, 313)),
              drawing("diagrams", 306, 312)]
    pages = pack(panels, "A1", "eskd")
    assert len(pages) == 1
    rects = {panel.name: rect for panel, rect, _ in pages[0].placed}
    positions, plan, diagrams = rects["positions"], rects["plan-3"], rects["diagrams"]
    assert plan[3] - plan[1] == 313 and plan[3] <= positions[1] - GAP_MM + 1e-9  # under the plan of positions
    assert diagrams[0] >= max(positions[2], plan[2]) + GAP_MM - 1e-9  # beside both
    # Each stands clear of the others and of the title block, inside the area drawings may take.
    area, block = pages[0].area, pages[0].block
    for name, rect in rects.items():
        assert area[0] <= rect[0] and rect[2] <= area[2] and area[1] <= rect[1] and rect[3] <= area[3], name
        assert rect[2] <= block[0] or rect[1] >= block[3], name


def test_a_page_grows_as_a_block_where_that_leaves_room():
    """Where the next drawing fits beside a block, the page keeps its first growth (the sheets of every
    fixture are laid out as before)."""
    panels = [drawing("positions", 163, 123), drawing("plan-3", 538, 170, (315, 313)),
              drawing("diagrams", 200, 312)]
    pages = pack(panels, "A1", "eskd")
    assert len(pages) == 1 and pages[0].growth == "block"


def test_a_part_without_a_heading_shares_no_sheet_with_another_drawing():
    """Position 2's Zhukovsky lever, too big to stand under a heading, stood on a sheet beside position 7's
    force sheet and under its heading, where it read as position 7's.  It now has a sheet of its own, whose
    title block names it; another drawing goes neither beside it nor after it."""
    lever = Panel("forces-2-5", (box("drawing", 120.0, 150.0),), continues="forces-2-4", label="position 2")
    seven = Panel("forces-7", (box(HEADING_LAYER, 100.0, HEADING_MM, HEADING_MM), box("drawing", 100.0, 60.0)),
                  label="position 7")
    eight = Panel("forces-8", (box(HEADING_LAYER, 100.0, HEADING_MM, HEADING_MM), box("drawing", 100.0, 60.0)),
                  label="position 8")
    for order in ([lever, seven, eight], [seven, lever, eight]):
        pages = pack(order, SHEET, FORM)
        for page in pages:
            names = [drawing.name for drawing in page.drawings]
            assert "forces-2-5" not in names or names == ["forces-2-5"], names
        assert sum(len(page.drawings) for page in pages) == 3


def test_the_first_part_of_a_force_sheet_without_a_heading_shares_no_sheet_with_another_drawing():
    """The English crank-rocker with friction on A3: its sheet with friction of position 5 began with group II(3,4)
    too tall for a heading, which stood beside position 5's lever under "Force analysis, position 5 (continued)",
    read as the analysis without friction.  A first part goes on from no part, but it has a heading to name the
    scales of (:attr:`Panel.heading_scales`) and stands without it."""
    scales = (("μl = 0.005 m/mm", "body-"),)
    group = Panel("forces-friction-5", (box("drawing", 120.0, 150.0),), heading_scales=scales, label="friction, 5")
    lever = Panel("forces-5-4", (box(HEADING_LAYER, 100.0, HEADING_MM, HEADING_MM), box("drawing", 100.0, 60.0)),
                  continues="forces-5-3", heading_scales=(("μV = 0.01983 (m/s)/mm", "lever"),), label="position 5")
    for order in ([lever, group], [group, lever]):
        pages = pack(order, SHEET, FORM)
        assert [[drawing.name for drawing in page.drawings] for page in pages] == [[panel.name] for panel in order]


def test_no_drawings_take_no_sheets_on_every_format():
    # An A4, which chooses between its turns by its first sheet, failed on none: a scene without forces on A4.
    for sheet in ("A4", "A3", "A1"):
        for form in ("iso", "eskd", "gb"):
            assert pack([], sheet, form) == [], (sheet, form)


def test_a_force_sheet_with_friction_goes_on_no_sheet_before_the_last_part_of_the_sheet_without():
    """The sheet with friction is read after its position's sheet without it: it fills no room left on a sheet
    before that sheet's last part, though the room there holds it (in Chinese on A3 the crank-rocker's sheet of
    position 11 began on a sheet before the one with friction of position 5 went on)."""
    width, height = room_above_the_title_block()
    first_height = height - HEADING_MM - 100.0  # leaves 100 mm under it, a gap and 85 mm of room
    second_height = 120.0  # too tall for that room even under the first's heading: a sheet of its own
    friction_height = 20.0
    assert HEADING_MM + friction_height <= 100.0 - GAP_MM
    assert HEADING_MM + friction_height <= height - (HEADING_MM + second_height) - GAP_MM
    pages = pack([part("forces-5", width - 1.0, first_height),
                  part("forces-5-2", width - 1.0, second_height, continues="forces-5"),
                  part("forces-friction-5", width - 1.0, friction_height)], SHEET, FORM)
    assert [[panel.name for panel, _, _ in page.placed] for page in pages] == \
        [["forces-5"], ["forces-5-2", "forces-friction-5"]]
    (_, second_rect, _), (_, friction_rect, _) = pages[1].placed
    assert friction_rect[3] <= second_rect[1] - GAP_MM + 1e-9


def test_a_page_laid_out_afresh_is_remembered_as_laid_out_and_handed_out_as_a_page_of_its_own(monkeypatch):
    """The V-twin's first sheet: the plan of positions and a plan sheet on a page that leaves no room for the
    kinematic diagrams until it is laid out afresh (the first test of a page grown down a column).  The layout is
    remembered (the force sheets' combinations of ways ask again for most of theirs); each asker gets a page of its
    own to go on filling."""
    monkeypatch.setattr(packing, "_LAID_OUT_AFRESH", RecentMemo())
    positions, plan, diagrams = (drawing("positions", 163, 123), drawing("plan-3", 538, 170, (315, 313)),
                                 drawing("diagrams", 306, 312))
    page = packing._empty_page("A1", "eskd", False)
    assert page.place(positions) and page.place(plan) and not page.place(diagrams)
    fresh = packing._laid_out_afresh(page, diagrams, packing._MOST_MOVES)
    assert fresh is not None
    first = packing._rearranged(page, diagrams)
    assert first.placed == fresh.placed and first.drawings == fresh.drawings and first.growth == fresh.growth
    first.place(drawing("note", 20, 20))
    first.label = "filled"
    again = packing._rearranged(page, diagrams)
    assert again.placed == fresh.placed and again.drawings == fresh.drawings and again.label == ""
    assert len(packing._LAID_OUT_AFRESH) == 1
    # Another drawing of another size, though named alike, is laid out for itself.
    taller = drawing("diagrams", 306, 900)
    assert packing._laid_out_afresh(page, taller, packing._MOST_MOVES) is None
    assert packing._rearranged(page, taller) is None
    assert len(packing._LAID_OUT_AFRESH) == 2
