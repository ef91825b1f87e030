"""A drawing made smaller never takes a sheet more (graphplan.render.packing).

The slotted lever's force sheet of position 4 on an A3 stands in five parts on one sheet: the first part with its
equations beside its drawings, the second beside it at the top, the third and fourth under the first, the lever
at the right under the second.  Its crank's polygon of no area drawn at the μF of the other polygons made the
fourth part narrower (175 mm to 114 mm); each drawing placed where they stay most compact, the narrow one filled
the gap right of the third, under the second, where the lever stood, and the lever went on a sheet of its own.
The sizes here are those parts' (mm), each of its ways, the later ones without the headings they leave off under the
first one's.
"""

import pytest
from test_packing import box

from graphplan.render.packing import GAP_MM, Panel, pack

SHEET, FORM = "A3", "iso"


def drawing(name: str, *ways: tuple[float, float]) -> Panel:
    """A drawing standing in each of ``ways`` (width, height), the first as it is drawn."""
    first, *others = ways
    return Panel(name, (box("drawing", *first),),
                 alternatives=tuple(Panel(name, (box("drawing", *size),)) for size in others))


def parts(fourth: tuple[float, float]) -> list[Panel]:
    """Position 4's parts, the fourth with its equations beside it ``fourth`` in size."""
    return [drawing("forces-4", (140, 211), (158, 170)), drawing("forces-4-2", (148, 57), (217, 27)),
            drawing("forces-4-3", (117, 79), (192, 43)), drawing("forces-4-4", (122, 41), fourth),
            drawing("forces-4-5", (155, 199), (152, 141))]


def overlapping(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return a[0] < b[2] + GAP_MM - 1e-6 and b[0] < a[2] + GAP_MM - 1e-6 \
        and a[1] < b[3] + GAP_MM - 1e-6 and b[1] < a[3] + GAP_MM - 1e-6


@pytest.mark.parametrize("fourth", [(114, 17), (61, 17), (150, 10)])
def test_a_part_made_narrower_takes_no_more_sheets(fourth):
    wide = pack(parts((175, 17)), SHEET, FORM)
    narrow = pack(parts(fourth), SHEET, FORM)
    assert len(wide) == 1  # the reference: the fourth part as it was drawn before
    assert len(narrow) <= len(wide)
    # The layout found is a layout: every part inside the area, clear of the title block and a gap from the others.
    page = narrow[0]
    rects = [rect for _, rect, _ in page.placed]
    assert len(rects) == 5
    for k, rect in enumerate(rects):
        assert page.area[0] - 1e-6 <= rect[0] and rect[2] <= page.area[2] + 1e-6
        assert page.area[1] - 1e-6 <= rect[1] and rect[3] <= page.area[3] + 1e-6
        assert rect[2] <= page.block[0] or rect[1] >= page.block[3]
        assert not any(overlapping(rect, other) for other in rects[k + 1:])
