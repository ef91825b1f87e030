"""The load diagrams, read after the force sheets whose values they give, stand on the last force sheet's sheet or
after it wherever another cut of the force sheets packs them so on as many sheets: the packing puts them on an
earlier sheet only where that alone has room for them, and the force sheets' cuts decide which has.  The order is
never bought with a sheet, nor with a force sheet's drawings set apart (a group away from its polygon) that the count
does not need.

The drawings of the first tests are rectangles of known size on an ISO A3, whose area is 374 by 261 mm, the title
block grown by its padding taking its lower right corner from x = 222 mm and up to y = 58 mm: what fits where is a
fact of their sizes, the gaps kept between them and the title block.
"""

from __future__ import annotations

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
from graphplan.render.title_block import form_of

# Each force sheet's two rows, the width of each such that two stand side by side in the area, but a force sheet
# whole (its rows down one column under its heading) leaves beside it less than the load diagrams' width.
ROW_MM = (179.0, 95.0)
LOADS_MM = (200.0, 80.0)


def whole(name: str, width: float = ROW_MM[0], height: float = ROW_MM[1]) -> Panel:
    """A force sheet whole: two rows ``width`` × ``height`` down one column under its heading."""
    return Panel(name, (box(HEADING_LAYER, width, HEADING_MM, HEADING_MM), box("row", width, height),
                        box("row-2", width, height, -height - GAP_MM)))


def apart(name: str, width: float = ROW_MM[0], height: float = ROW_MM[1]) -> list[Panel]:
    """The same force sheet with its drawings apart: each row a part, the second going on from the first."""
    return [part(name, width, height), part(f"{name}-2", width, height, continues=name)]


def loads() -> Panel:
    return Panel("load-diagrams", (box("loads", *LOADS_MM),), to_scale=False, reads_after="forces")


def placed(pages) -> list[list[str]]:
    return [[panel.name for panel, _, _ in page.placed] for page in pages]


def loads_after_every_force_sheet(pages) -> bool:
    names = placed(pages)
    at = next(k for k, page in enumerate(names) if "load-diagrams" in page)
    return all(at >= k for k, page in enumerate(names) for name in page if name.startswith("forces"))


def test_the_sizes_make_the_order_at_the_same_count_a_fact():
    """Whole, a force sheet leaves the load diagrams no room on its sheet; its drawings apart, side by side, leave
    them the room under them.  So with one force sheet apart the set takes two sheets, and the load diagrams stand
    beside whichever sheet stands apart: the first's, as the choice that saves the sheet finds first, or the
    last's."""
    geometry = page_geometry(SHEET, FORM)
    ax0, ay0, ax1, ay1 = geometry.area
    bx0, _, _, by1 = geometry.block
    (row_width, row_height), (loads_width, loads_height) = ROW_MM, LOADS_MM
    whole_height = HEADING_MM + row_height + GAP_MM + row_height
    # Whole: the area holds it upright, in the column left of the title block, and the room right of that column is
    # narrower than the load diagrams, and none is left under it, nor is it under the load diagrams above the block.
    assert whole_height <= ay1 - ay0 and row_width <= bx0 - PADDING_MM - ax0
    assert ax1 - (ax0 + row_width + GAP_MM) < loads_width
    assert whole_height + GAP_MM + loads_height > ay1 - ay0
    # Apart: two rows side by side under one heading, and the load diagrams under them above the title block.
    assert 2 * row_width + GAP_MM <= ax1 - ax0
    assert HEADING_MM + row_height + GAP_MM + loads_height <= ay1 - (by1 + PADDING_MM)
    # As the packing finds them: three sheets whole; two with either apart, the load diagrams beside that one.
    assert len(pack([whole("forces-2"), whole("forces-8"), loads()], SHEET, FORM)) == 3
    first_apart = pack([*apart("forces-2"), whole("forces-8"), loads()], SHEET, FORM)
    assert placed(first_apart) == [["forces-2", "forces-2-2", "load-diagrams"], ["forces-8"]]
    last_apart = pack([whole("forces-2"), *apart("forces-8"), loads()], SHEET, FORM)
    assert len(last_apart) == 2 and loads_after_every_force_sheet(last_apart)


def test_the_load_diagrams_stand_after_the_force_sheets_where_another_cut_keeps_the_count():
    """The choice that saves a sheet sets the first force sheet's drawings apart, and the load diagrams stood on its
    sheet, before the second force sheet's; set apart instead, the second's leaves them room after it, on as many
    sheets, with as many force sheets apart."""
    cuts = [[[whole("forces-2")], apart("forces-2")], [[whole("forces-8")], apart("forces-8")]]
    chosen = fewest_sheets_cuts(cuts, [loads()], SHEET, FORM)
    pages = pack([*chosen, loads()], SHEET, FORM)
    fewest = min(len(pack([*first, *last, loads()], SHEET, FORM)) for first in cuts[0] for last in cuts[1])
    assert len(pages) == fewest == 2
    assert loads_after_every_force_sheet(pages)
    assert [panel.name for panel in chosen] == ["forces-2", "forces-8", "forces-8-2"]


def test_the_order_takes_no_force_sheet_apart_that_the_count_does_not_need():
    """A first force sheet low enough to leave the load diagrams room under it, and a second whole that leaves them
    none: after it they would stand only beside its drawings apart, which save no sheet, and they stay on the
    first's sheet."""
    low = [part("forces-2", 300.0, 100.0)]
    cuts = [[low], [[whole("forces-8", ROW_MM[0], 100.0)], apart("forces-8", ROW_MM[0], 100.0)]]
    as_they_stand = pack([*low, whole("forces-8", ROW_MM[0], 100.0), loads()], SHEET, FORM)
    assert placed(as_they_stand) == [["forces-2", "load-diagrams"], ["forces-8"]]
    second_apart = pack([*low, *apart("forces-8", ROW_MM[0], 100.0), loads()], SHEET, FORM)
    assert len(second_apart) == 2 and loads_after_every_force_sheet(second_apart)
    assert [panel.name for panel in fewest_sheets_cuts(cuts, [loads()], SHEET, FORM)] == ["forces-2", "forces-8"]


def test_the_load_diagrams_and_nothing_read_after_keep_every_cut_as_chosen():
    """Without a drawing read after them, the force sheets' cuts are the ones that save the sheet, first found."""
    cuts = [[[whole("forces-2")], apart("forces-2")], [[whole("forces-8")], apart("forces-8")]]
    plain = Panel("diagram", (box("diagram", *LOADS_MM),), to_scale=False)
    assert [panel.name for panel in fewest_sheets_cuts(cuts, [plain], SHEET, FORM)] == \
        ["forces-2", "forces-2-2", "forces-8"]


@pytest.mark.parametrize("fixture", ["scotch_yoke"])
def test_a_fixture_reads_its_load_diagrams_after_its_force_sheets_on_the_fewest_sheets(fixture):
    """The scotch yoke on its A2: its load diagrams stood on the sheet of position 4's force sheet, before position 9's.
    Its force sheets and load diagrams cover more than one A2's room (:func:`area_allows` refuses one sheet), so the
    two sheets they take are the fewest any packing could: the order took no sheet."""
    analysis = with_length_scale(analyse(graphplan.load(f"fixtures/{fixture}.toml")))
    panels = deliverables._course_panels(analysis)
    sheets = course_sheets(analysis, panels=panels)
    forces = [sheet.number for sheet in sheets for name in sheet.panels if name.startswith("forces-")]
    (loads_at,) = [sheet.number for sheet in sheets if "load-diagrams" in sheet.panels]
    assert loads_at >= max(forces)
    taken = {*forces, loads_at}
    sheet = analysis.scene.drawing.sheet
    form = form_of(analysis.scene.locale)
    least = next(n for n in range(1, len(taken) + 1) if area_allows(panels.forces, n, sheet, form))
    assert len(taken) <= least == 2
