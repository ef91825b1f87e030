"""The plan of positions' hardest labels read clear of every line drawn: the crank pivot's letter "O" that all the
crank positions' lines leave, the swing's ψ across the rocker's positions, the centre of mass S6 among the triad's
thin outlines.

The labels and lines are read back from the positions.svg a run writes.  A letter's ink is measured independently
of graphplan's own width rule, with matplotlib's DejaVu Sans outlines (the font the SVG names first) at the SVG's
font size; a line is its path widened by half its stroke width.  The leaders' layer is left out: a label's own
leader ends at it.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely
from drawn_lines import stroked_shapes
from matplotlib.font_manager import FontProperties
from matplotlib.textpath import TextPath, TextToPath

from graphplan import cli

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
FONT = FontProperties(family="DejaVu Sans")

# (fixture, locale, the labels that must stand clear of every line: a text, or "ψ" for every swing's ψ).
CASES = [
    ("ratchet_crank_rocker", "en", ("O", "ψ")),
    ("ratchet_crank_rocker", "ru", ("O", "ψ")),
    ("triad_class_iii", "en", ("O",)),
    ("shaper_six_bar", "en", ("O",)),
    ("scotch_yoke", "en", ("O",)),
    ("triad_with_slider", "en", ("O", "S6")),
    ("slider_driven", "en", ("ψ",)),
    ("stephenson_six_bar", "en", ("ψ",)),
    ("double_rocker_swing", "en", ("O",)),
]


def _advance(text: str, size: float) -> float:
    return TextToPath().get_text_width_height_descent(text, FontProperties(family="DejaVu Sans", size=size),
                                                      ismath=False)[0]


def _ink(element: ET.Element) -> shapely.Polygon:
    """The box round a text element's glyphs as drawn, in the SVG's coordinates (y down).  A text whose indices are
    set as runs is measured run by run: an index is smaller and lower than the flat text it was laid out as, so its
    ink is not that text's."""
    size = float(element.get("font-size"))
    x, y = float(element.get("x")), float(element.get("y"))
    spans = element.findall(f"{SVG}tspan")
    if spans:
        assert not (element.text or "").strip(), "words before a text's first run have no place of their own"
        # The first run is placed at the text's start; each next one where the run before it left the pen.
        start = float(spans[0].get("x"))
        runs = [(span.text or "", float(span.get("font-size", size)), float(span.get("dy", 0.0))) for span in spans]
    else:
        text = element.text or ""
        advance = _advance(text, size)
        start = x - {"start": 0.0, "middle": advance / 2, "end": advance}[element.get("text-anchor", "start")]
        runs = [(text, size, 0.0)]
    boxes = []
    for text, run_size, lowered in runs:
        y += lowered
        extent = TextPath((0, 0), text, size=run_size, prop=FONT).get_extents()
        # The glyphs' y grows upward from the baseline; the SVG's downward.
        boxes.append(shapely.box(start + extent.x0, y - extent.y1, start + extent.x1, y - extent.y0))
        start += _advance(text, run_size)
    return shapely.union_all(boxes).envelope


def _words(element: ET.Element) -> str:
    """A text's words whole, its runs (a symbol's index) read on."""
    return "".join(element.itertext())


@pytest.mark.parametrize(("fixture", "locale", "names"), CASES, ids=[f"{case[0]}-{case[1]}" for case in CASES])
def test_named_labels_meet_no_drawn_line(fixture: str, locale: str, names: tuple[str, ...], tmp_path: Path) -> None:
    out = tmp_path / "out"
    assert cli.main(["run", str(ROOT / "fixtures" / f"{fixture}.toml"), "--out", str(out), "--locale", locale,
                     "--sheet", "none"]) == 0
    root = ET.parse(out / "positions.svg").getroot()
    texts = [element for element in root.iter(f"{SVG}text")]
    lines = stroked_shapes(root)
    tree = shapely.STRtree(lines)
    checked = []
    for name in names:
        found = [element for element in texts
                 if _words(element).startswith("ψ" if name == "ψ" else "\0") or _words(element) == name]
        assert found, f"{fixture} ({locale}): no label {name!r} on the plan of positions"
        for element in found:
            ink = _ink(element)
            met = tree.query(ink, predicate="intersects")
            assert not len(met), (f"{fixture} ({locale}): {_words(element)!r} at ({element.get('x')}, {element.get('y')}) "
                                  f"meets {len(met)} drawn line(s)")
            checked.append(_words(element))
    assert checked
