"""A drawing's line that mixes Chinese with Latin symbols: each script in its own font, the line where its anchor says.

Set wholly in Noto Sans CJK, «平衡力矩 Mb = 49.02 N·m（力多边形）» drew a full-width middle dot (N・m); set run by
run, a centred line's runs were drawn over one another by cairosvg, which anchors every run on its own.
"""

from __future__ import annotations

import io
from xml.etree import ElementTree

import numpy as np
import pytest
from PIL import Image, ImageFont

from graphplan.render.primitives import FONT_SIZE_PER_CAP, Layer, Polyline, Stroke, Text
from graphplan.render.script_runs import CJK_FONT, LATIN_FONT, _font_file, script_runs, width_em
from graphplan.render.svg import to_svg

LINE = "平衡力矩 Mb = 49.02 N·m"
SVG = "{http://www.w3.org/2000/svg}"
DPI = 600
PAGE = (120.0, 30.0)

pytestmark = pytest.mark.skipif(width_em(script_runs("力 N"), "normal") is None,
                                reason="fontconfig with DejaVu Sans and Noto Sans CJK is needed to measure mixed lines")


def test_each_run_names_its_own_script_s_font_first():
    svg = to_svg([Layer("line", (Text((60.0, 15.0), LINE, 3.5, "middle"),))])
    text = next(ElementTree.fromstring(svg).iter(f"{SVG}text"))
    runs = [(span.text, span.get("font-family").split(",")[0]) for span in text.iter(f"{SVG}tspan")]
    # The space between the scripts hung on the end of the run before it: set at its own x, a run loses the spaces
    # it starts with.
    assert runs == [("平衡力矩 ", CJK_FONT), ("Mb = 49.02 N·m", LATIN_FONT)]
    assert "".join(text.itertext()) == LINE


@pytest.mark.parametrize("weight", ["normal", "bold"])
def test_the_width_is_the_fonts_own_as_freetype_measures_it(weight):
    measured = 0.0
    for run, wide in script_runs(LINE):
        path, index = _font_file(CJK_FONT if wide else LATIN_FONT, weight)
        font = ImageFont.truetype(path, 1000, index=index, layout_engine=ImageFont.Layout.BASIC)
        measured += sum(font.getlength(character) for character in run) / 1000
    # FreeType rounds each advance to a whole pixel of its 1000-pixel em.
    assert width_em(script_runs(LINE), weight) == pytest.approx(measured, abs=0.5e-3 * len(LINE))


def test_the_cjk_widths_are_read_and_the_font_file_closed():
    """The font was left to the collector with its file open: a ResourceWarning wherever warnings show (a notebook
    run with ``-W always``), found by a probe.  The widths, read out, are the font's still (the test above)."""
    import gc
    import warnings

    from graphplan.render.script_runs import _advances

    path, _ = _font_file(CJK_FONT, "normal")
    _advances.cache_clear()
    gc.collect()  # what earlier tests left to the collector (matplotlib's own fonts) is told before, not here
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ResourceWarning)
        advance = _advances(CJK_FONT, "normal")
        gc.collect()
    assert advance("力") == pytest.approx(1.0) and 0.2 < advance("N") < 1.0
    assert not [str(each.message) for each in caught
                if issubclass(each.category, ResourceWarning) and path in str(each.message)]


def _ink_columns_mm(layers) -> tuple[float, float]:
    """The leftmost and rightmost inked columns of the rendered page (mm from its left), the page's own frame aside."""
    import cairosvg

    png = cairosvg.svg2png(bytestring=to_svg(layers, page=PAGE).encode(), dpi=DPI)
    ink = np.asarray(Image.open(io.BytesIO(png)).convert("L")) < 128
    columns = np.flatnonzero(ink.any(axis=0))
    per_mm = ink.shape[1] / PAGE[0]
    return columns[0] / per_mm, (columns[-1] + 1) / per_mm


@pytest.mark.parametrize("anchor", ["middle", "end"])
def test_a_mixed_line_stands_where_its_anchor_says(anchor):
    """The ink of a centred line is centred on its anchor, a right-aligned one ends at it (within a side bearing)."""
    pytest.importorskip("cairosvg")
    size = 3.5
    left, right = _ink_columns_mm([Layer("line", (Text((60.0, 15.0), LINE, size, anchor),))])
    width = width_em(script_runs(LINE), "normal") * size * FONT_SIZE_PER_CAP
    bearing = 0.12 * size * FONT_SIZE_PER_CAP
    if anchor == "middle":
        assert (left + right) / 2 == pytest.approx(60.0, abs=bearing)
    else:
        assert right == pytest.approx(60.0, abs=bearing)
    assert right - left == pytest.approx(width, abs=2 * bearing)


def test_a_mixed_line_turned_about_its_anchor_keeps_its_centre_there():
    pytest.importorskip("cairosvg")
    turned = Text((60.0, 15.0), LINE, 3.5, "middle", rotation=180.0)
    left, right = _ink_columns_mm([Layer("line", (turned,))])
    assert (left + right) / 2 == pytest.approx(60.0, abs=0.6)


def test_a_line_in_one_script_is_one_text_in_its_font():
    svg = to_svg([Layer("line", (Text((60.0, 15.0), "平衡力矩", 3.5, "middle"),
                                 Polyline(((0.0, 0.0), (1.0, 1.0)), Stroke(0.35))))])
    text = next(ElementTree.fromstring(svg).iter(f"{SVG}text"))
    assert text.text == "平衡力矩" and text.get("text-anchor") == "middle"
    assert not list(text.iter(f"{SVG}tspan"))
