"""What a student finds opening the deliverables of a run in other formats: the note's figures, the drawings.

The note shows each drawing the run writes beside it.  A plan sheet stands in one row, the mechanism, the
velocity plan and the acceleration plan side by side: 650 mm wide for the shaper's position 10, it went into the
note's PDF and Word pages shrunk to a quarter, its letters under 1 mm high.  Like a force sheet too tall for a
page, it is shown in the note in parts that a page prints at half size or more.
"""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
SVG = "{http://www.w3.org/2000/svg}"
# A figure in the note's Markdown: the picture alone in its paragraph.
PICTURE = re.compile(r"^!\[[^\]]*\]\(([^)]+)\)$", re.MULTILINE)
# The room a note's page gives a figure (mm) and the least scale it may print at there, as the note's own
# module for force sheets sets them (A4 less its margins, 3.5 mm letters printed no smaller than 1.75 mm).
PAGE_FIGURE_MM = (170.0, 200.0)
LEAST_PRINT_SCALE = 0.5
SVG_MARGIN_MM = 8.0


def print_scale(path: Path) -> float:
    """The scale ``path`` prints at on a note's page: its drawing (the page less its margins) fitted to the room."""
    root = ElementTree.parse(path).getroot()
    width, height = (float(root.get(side).removesuffix("mm")) - 2 * SVG_MARGIN_MM for side in ("width", "height"))
    return min(1.0, PAGE_FIGURE_MM[0] / width, PAGE_FIGURE_MM[1] / height)


def group_ids(path: Path) -> list[str]:
    return [group.get("id") for group in ElementTree.parse(path).getroot().findall(f"{SVG}g") if len(group)]


@pytest.fixture(scope="module")
def shaper_plans(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("shaper") / "out"
    assert main(["run", str(FIXTURES / "shaper_six_bar.toml"), "--out", str(out), "--locale", "ru",
                 "--only", "velocity,acceleration,note"]) == 0
    return out


def test_a_plan_sheet_too_wide_for_a_page_is_shown_in_the_note_in_parts_that_print_readably(shaper_plans):
    note = (shaper_plans / "note.md").read_text(encoding="utf-8")
    shown = PICTURE.findall(note)
    wide = [path for path in sorted(shaper_plans.glob("plan_*.svg")) if "-" not in path.stem]
    assert wide and all(print_scale(path) < LEAST_PRINT_SCALE for path in wide)   # the case this test is about
    for whole in wide:
        parts = sorted(shaper_plans.glob(f"{whole.stem}-*.svg"), key=lambda path: int(path.stem.rsplit("-", 1)[1]))
        assert len(parts) >= 2, whole.name
        # The note shows the parts in order, not the whole, each at half size or more.
        assert [name for name in shown if name.startswith(f"{whole.stem}-") or name == whole.name] == \
            [part.name for part in parts]
        for part in parts:
            assert print_scale(part) >= LEAST_PRINT_SCALE, (part.name, print_scale(part))
        # Together the parts draw every drawing of the whole sheet, each once, in the sheet's order, and its
        # title over the first alone.  (Leaders go where each part's labels are placed afresh.)
        def drawing_layers(path: Path) -> list[str]:
            return [name for name in group_ids(path) if name != "sheet-title" and not name.endswith("-leaders")]

        drawn = [name for part in parts for name in drawing_layers(part)]
        assert sorted(drawn) == sorted(drawing_layers(whole)) and len(drawn) == len(set(drawn))
        kinds = [name.split("-")[0] for name in drawn if not name.endswith("-caption")]
        assert kinds == sorted(kinds, key=["mechanism", "velocity", "acceleration"].index)
        assert ["sheet-title" in group_ids(part) for part in parts] == [True] + [False] * (len(parts) - 1)


def test_a_plan_sheet_drawn_in_a_way_a_page_holds_is_not_cut_for_the_note():
    """On a course-project run plan_N.svg is the sheet's own arrangement (the mechanism above or beside its plans),
    which may print on a page whole though the three drawings in a row would not: it is then shown whole."""
    from graphplan.render.note_parts import note_parts_of_drawings
    from graphplan.render.primitives import Layer, Polyline

    def box(name: str, x: float, y: float, width: float, height: float) -> Layer:
        return Layer(name, (Polyline(((x, y), (x + width, y), (x + width, y + height), (x, y + height)), closed=True),))

    def in_a_row(names: tuple[str, ...]) -> list[Layer]:   # each drawing 200 × 100 mm, side by side
        return [box(name, 210.0 * k, 0.0, 200.0, 100.0) for k, name in enumerate(names)]

    drawings = ("mechanism", "velocity", "acceleration")
    # 620 mm in a row prints at 170/620 < 0.5, two of them (410 mm) at 170/410 < 0.5; one alone at 170/200.
    assert [[layer.name for layer in part] for part in note_parts_of_drawings(drawings, in_a_row, "title")] == \
        [["mechanism"], ["velocity"], ["acceleration"]]
    # The same drawings one above the other on 200 × 320 mm print at 200/320 > 0.5: whole.
    stacked = [box(name, 0.0, 110.0 * k, 200.0, 100.0) for k, name in enumerate(drawings)]
    assert note_parts_of_drawings(drawings, in_a_row, "title", whole=stacked) is None
