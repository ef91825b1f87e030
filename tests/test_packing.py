"""Panels packed onto pages (graphplan.render.packing), with drawings of known size.

A part of a force sheet that goes on from a part already on the page stands under that part's heading:
it is placed, and takes room, without its own ("continued"), so that two parts that fit together only
without the second heading share a sheet.
"""

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
