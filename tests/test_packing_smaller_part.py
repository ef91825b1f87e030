"""A drawing made smaller never takes a sheet more (graphplan.render.packing).

The slotted lever's force sheet of position 4 on an A3 stands in five parts on one sheet: the first part with its
equations beside its drawings, the second beside it at the top, the third and fourth under the first, the lever
at the right under the second.  Its crank's polygon of no area drawn at the μF of the other polygons made the
fourth part narrower (175 mm to 114 mm); each drawing placed where they stay most compact, the narrow one filled
the gap right of the third, under the second, where the lever stood, and the lever went on a sheet of its own.
The sizes here are those parts' (mm), each of its ways, the later ones without the headings they leave off under the
first one's.
"""

import dataclasses
from importlib import resources

import pytest
from test_packing import box

import graphplan
from graphplan import forces, load_diagrams
from graphplan.analysis import analyse
from graphplan.render.packing import GAP_MM, Panel, pack
from graphplan.render.sheet import course_panels, load_diagrams_panel
from graphplan.render.title_block import form_of

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


def _fitting_scales(groups):
    """μF of each polygon as drawn before a polygon of no area took the others' coarsest: each at its own field,
    a polygon of no length at the coarsest of all."""
    fitting = {group.label: forces._fitting_scale(group.polygon) for group in groups}
    coarsest = max((value for value in fitting.values() if value is not None), default=1.0)
    return {label: coarsest if value is None else value for label, value in fitting.items()}


def force_sheets_taken(scene) -> int:
    """How many sheets the run's force sheets, with the load diagrams after them, take."""
    analysis = analyse(scene)
    sheet = scene.drawing.sheet
    loads = (load_diagrams_panel(load_diagrams.of_analysis(analysis), scene.locale, sheet),)
    return len(pack(list(course_panels(analysis, sheet=sheet, loads=loads).forces), sheet, form_of(scene.locale)))


def test_the_slotted_lever_starter_takes_no_more_a3_sheets_with_its_crank_polygon_drawn_smaller(monkeypatch):
    """The starter's crank polygon of no area drawn at its own 150 mm field is the larger drawing: drawn at the
    other polygons' μF, its force sheets take no more A3 sheets than so."""
    text = resources.files("graphplan").joinpath("templates/slotted-lever.toml").read_text(encoding="utf-8")
    scene = graphplan.scene.loads(text)
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, sheet="A3"))
    smaller = force_sheets_taken(scene)
    with monkeypatch.context() as patched:
        patched.setattr(forces, "_chosen_scales", _fitting_scales)
        larger = force_sheets_taken(scene)
    assert smaller <= larger
