"""A force sheet that a sheet holds whole may still stand with its rows apart where that saves a sheet: whole, its
block kept the room beside its lever from the load diagrams after it, which took a sheet of their own (the shaper's
six-bar on A1: its load diagrams alone on a fifth sheet, a twentieth of it drawn on).  A part standing under the part
it goes on from, without its heading, shares its sheet with other drawings; the load diagrams stand on the last
force sheet's sheet or after it unless only a sheet before it has room for them.

The drawings here are rectangles of known size on an ISO A3, whose room above the title block is 374 by 221 mm:
what fits where is a fact of their sizes, the gaps kept between them and the title block.
"""

from __future__ import annotations

import itertools

import pytest
from test_packing import FORM, HEADING_MM, SHEET, box, part

import graphplan
from graphplan import deliverables
from graphplan.analysis import analyse
from graphplan.render.drawings import with_length_scale
from graphplan.render.force_rows import HEADING_LAYER
from graphplan.render.force_sheet_choice import fewest_sheets_cuts
from graphplan.render.formats import PADDING_MM, page_geometry
from graphplan.render.packing import GAP_MM, Panel, area_allows, pack
from graphplan.render.sheet import course_sheets

# A force sheet of two rows, a group with its polygon over the lever, and the load diagrams after it.
ROW_MM, LEVER_MM, LOADS_MM = (300.0, 90.0), (150.0, 80.0), (200.0, 90.0)


def whole() -> Panel:
    """The force sheet whole: its two rows down one column under its heading."""
    (row_width, row_height), (lever_width, lever_height) = ROW_MM, LEVER_MM
    return Panel("forces-5", (box(HEADING_LAYER, row_width, HEADING_MM, HEADING_MM),
                              box("row", row_width, row_height),
                              box("lever", lever_width, lever_height, -row_height - GAP_MM)))


def rows_apart() -> list[Panel]:
    return [part("forces-5", *ROW_MM), part("forces-5-2", *LEVER_MM, continues="forces-5")]


def loads(width: float = LOADS_MM[0], height: float = LOADS_MM[1]) -> Panel:
    return Panel("load-diagrams", (box("loads", width, height),), to_scale=False, reads_after="forces")


def room() -> tuple[float, float, float, float]:
    """The area of the sheet and the box drawings keep out of (the title block grown by its padding)."""
    geometry = page_geometry(SHEET, FORM)
    x0, y0, x1, y1 = geometry.block
    return geometry.area, (x0 - PADDING_MM, y0 - PADDING_MM, x1 + PADDING_MM, y1 + PADDING_MM)


def test_the_sizes_make_the_saving_a_fact():
    """Whole, the sheet leaves the load diagrams no room beside it or under it on its A3; apart, its lever and the
    load diagrams stand side by side under its first row, clear of the title block."""
    (ax0, ay0, ax1, ay1), (bx0, _, _, by1) = room()
    whole_width, whole_height = ROW_MM[0], HEADING_MM + ROW_MM[1] + GAP_MM + LEVER_MM[1]
    # Whole: only the room above the title block is as wide as it, and neither beside it nor under it there is
    # room for the load diagrams, nor left of the title block under it.
    assert whole_width > bx0 - ax0 and whole_height <= ay1 - by1
    assert whole_width + GAP_MM + LOADS_MM[0] > ax1 - ax0
    assert whole_height + GAP_MM + LOADS_MM[1] > ay1 - ay0
    # Apart: the lever without its heading and the load diagrams side by side under the first row.
    assert LEVER_MM[0] + GAP_MM + LOADS_MM[0] <= ax1 - ax0
    assert HEADING_MM + ROW_MM[1] + GAP_MM + max(LEVER_MM[1], LOADS_MM[1]) <= ay1 - by1
    # As the packing finds them: two sheets whole, one apart.
    assert len(pack([whole(), loads()], SHEET, FORM)) == 2
    assert len(pack([*rows_apart(), loads()], SHEET, FORM)) == 1


def test_a_sheet_that_stands_whole_stands_with_its_rows_apart_where_that_saves_a_sheet():
    chosen = fewest_sheets_cuts([[[whole()]]], [loads()], SHEET, FORM, [rows_apart()])
    assert [panel.name for panel in chosen] == ["forces-5", "forces-5-2"]
    (page,) = pack([*chosen, loads()], SHEET, FORM)
    placed = {panel.name: (panel, rect) for panel, rect, _ in page.placed}
    # The lever goes on under the first row's heading, read after it: lower on the sheet.
    lever, lever_rect = placed["forces-5-2"]
    assert [layer.name for layer in lever.layers] == ["drawing"]
    assert lever_rect[3] <= placed["forces-5"][1][1] - GAP_MM + 1e-9
    for (_, a), (_, b) in itertools.combinations(placed.values(), 2):
        assert a[2] + GAP_MM <= b[0] + 1e-9 or b[2] + GAP_MM <= a[0] + 1e-9 or \
            a[3] + GAP_MM <= b[1] + 1e-9 or b[3] + GAP_MM <= a[1] + 1e-9


def test_a_sheet_keeps_standing_whole_where_its_rows_apart_save_nothing():
    """Load diagrams small enough to stand beside the whole: the sheet stays whole, one block under its heading."""
    small = loads(50.0, 40.0)
    assert len(pack([whole(), small], SHEET, FORM)) == 1
    assert [panel.name for panel in fewest_sheets_cuts([[[whole()]]], [small], SHEET, FORM, [rows_apart()])] == \
        ["forces-5"]


def test_a_part_under_the_part_it_goes_on_from_shares_its_sheet():
    """Standing without its heading under its first part, the lever read as that part's: the load diagrams, which
    fit beside it, were kept off the sheet, and took one of their own."""
    pages = pack([*rows_apart(), loads()], SHEET, FORM)
    assert [[panel.name for panel, _, _ in page.placed] for page in pages] == [
        ["forces-5", "forces-5-2", "load-diagrams"]]


def test_the_load_diagrams_stand_after_the_force_sheets_unless_only_an_earlier_sheet_has_room():
    (ax0, _, ax1, ay1), (_, _, _, by1) = room()
    # Two force sheets as wide as the sheet, each on a sheet of its own: under each there is room left for the load
    # diagrams above the title block.
    short = ay1 - by1 - HEADING_MM - GAP_MM - LOADS_MM[1]
    first = part("forces-2", ax1 - ax0, short)
    second = part("forces-8", ax1 - ax0, short)
    pages = pack([first, second, loads()], SHEET, FORM)
    assert [[panel.name for panel, _, _ in page.placed] for page in pages] == [
        ["forces-2"], ["forces-8", "load-diagrams"]]
    # The second fills the room above the title block: the first's sheet takes them, which saves the sheet they
    # would open.
    tall = part("forces-8", ax1 - ax0, ay1 - by1 - HEADING_MM)
    pages = pack([first, tall, loads()], SHEET, FORM)
    assert [[panel.name for panel, _, _ in page.placed] for page in pages] == [
        ["forces-2", "load-diagrams"], ["forces-8"]]


def test_the_area_bound_never_refuses_a_packing_that_exists():
    """:func:`area_allows` rules a count of sheets out only where the drawings' area exceeds it: it allows every
    packing the sheets find, and refuses one sheet for drawings each as big as most of it."""
    for drawings in ([whole(), loads()], [*rows_apart(), loads()], [whole(), loads(50.0, 40.0)]):
        assert area_allows(drawings, len(pack(drawings, SHEET, FORM)), SHEET, FORM)
    (ax0, ay0, ax1, ay1), _ = room()
    big = [Panel(f"plan-{k}", (box("plan", 0.6 * (ax1 - ax0), 0.6 * (ay1 - ay0)),)) for k in (1, 2, 3)]
    assert not area_allows(big, 1, SHEET, FORM)


@pytest.mark.parametrize("fixture", ["shaper_six_bar"])
def test_no_sheet_of_the_forces_is_left_nearly_empty_and_the_load_diagrams_come_last(fixture):
    """The shaper's six-bar on A1: its force sheets each took a sheet, and its load diagrams a third, a twentieth of
    it drawn on.  Now no sheet of the forces is left nearly empty, and the load diagrams stand on the last of them,
    after the force sheets whose values they give."""
    analysis = with_length_scale(analyse(graphplan.load(f"fixtures/{fixture}.toml")))
    panels = deliverables._course_panels(analysis)
    sheets = [sheet for sheet in course_sheets(analysis, panels=panels)
              if any(name.startswith(("forces-", "load-diagrams")) for name in sheet.panels)]
    for sheet in sheets:
        x0, y0, x1, y1 = sheet.frame
        drawn = sum((r[2] - r[0]) * (r[3] - r[1]) for r in sheet.panels.values())
        assert drawn >= 0.2 * (x1 - x0) * (y1 - y0), (sheet.number, sheet.panels)
    assert "load-diagrams" in sheets[-1].panels
