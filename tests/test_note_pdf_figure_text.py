"""The drawings' lettering as note.pdf sets it: WeasyPrint draws the SVG figures itself, and it laid a text's anchor
over runs that flow on from one another, so that every index stood over its letter (S₂ a struck-through S) and a
plan's μa = 0.50575 (m/s²)/mm came out as "a = 0.50575 μ".  Each run is now placed at its own x; here the figure is
typeset by WeasyPrint and its letters read back with PDFium, an independent reader, at the places they were set."""

from __future__ import annotations

import itertools

import pytest

from graphplan.render.indices import with_indices
from graphplan.render.primitives import Layer, Text, text_extent
from graphplan.render.svg import to_svg

pdfium = pytest.importorskip("pypdfium2")
try:
    import weasyprint
except (ImportError, OSError) as error:  # OSError: no Pango library
    pytest.skip(f"WeasyPrint cannot typeset here: {error}", allow_module_level=True)

PAGE_MM = (120.0, 60.0)
PT_PER_MM = 72 / 25.4
# Where WeasyPrint puts the figure on its page: at the page's corner, with no margin.
HTML = ("<html><head><style>@page {{ size: {w}mm {h}mm; margin: 0 }} body {{ margin: 0 }} "
        "img {{ display: block }}</style></head><body><img src='figure.svg'></body></html>")

TEXTS = [
    Text((60.0, 50.0), "μa = 0.50575 (m/s²)/mm", 3.5, "middle"),
    Text((20.0, 35.0), "S2", 3.5, "start"),
    Text((100.0, 35.0), "R14τ", 3.5, "end"),
    Text((60.0, 20.0), "杆组 II(3,4) 的力分析", 3.5, "middle"),
    Text((60.0, 8.0), "+ G3·h2 − Fu3·h3", 3.5, "middle"),
    # A lever's arms as its caption lists them, two spaces apart: a run set at its own x loses the spaces before its
    # first letter and sets two in a row as one, and placed by the spaces as typed stood a space off its letter.
    Text((60.0, 2.0), "h5 = 3.359 mm,  h6 = 9.334 mm", 3.5, "middle"),
]


def _typeset(tmp_path) -> list[list[tuple[str, tuple[float, float, float, float]]]]:
    """Each text's characters as PDFium reads them off the page, with their boxes in the drawing's mm (y up), in the
    order the texts were drawn."""
    layers = with_indices([Layer("labels", tuple(TEXTS))])
    (tmp_path / "figure.svg").write_text(to_svg(layers, page=PAGE_MM), encoding="utf-8")
    html = HTML.format(w=PAGE_MM[0], h=PAGE_MM[1])
    pdf_path = tmp_path / "figure.pdf"
    weasyprint.HTML(string=html, base_url=str(tmp_path)).write_pdf(pdf_path)
    page = pdfium.PdfDocument(str(pdf_path))[0]
    textpage = page.get_textpage()
    characters = []
    for index in range(textpage.count_chars()):
        character = textpage.get_text_range(index, 1)
        if character.strip():
            left, bottom, right, top = textpage.get_charbox(index)
            characters.append((character, tuple(value / PT_PER_MM for value in (left, bottom, right, top))))
    found = []
    for item in TEXTS:
        wanted = item.text.replace(" ", "")
        run = [characters.pop(0) for _ in range(len(wanted))]
        assert "".join(character for character, _ in run) == wanted
        found.append(run)
    return found


def test_a_figure_s_indexed_and_mixed_texts_stand_in_note_pdf_where_they_were_laid_out(tmp_path) -> None:
    for item, characters in zip(TEXTS, _typeset(tmp_path), strict=True):
        boxes = [box for _, box in characters]
        # Each letter after the one before it, none set over another (an index over its letter, the old S₂).
        for (_, before), (name, after) in itertools.pairwise(characters):
            assert after[0] >= before[2] - 0.15, (item.text, name, before, after)
        # The whole within the box the layouts measured the flat text in, and about its anchor as the anchor says.
        xmin, _, xmax, _ = text_extent(item)
        left, right = min(box[0] for box in boxes), max(box[2] for box in boxes)
        assert xmin - 0.5 <= left and right <= xmax + 0.5, (item.text, (left, right), (xmin, xmax))
        anchor = item.at[0]
        if item.anchor == "middle":
            assert abs((left + right) / 2 - anchor) < 0.6, item.text
        elif item.anchor == "start":
            assert abs(left - anchor) < 0.6, item.text
        else:
            assert abs(right - anchor) < 0.6, item.text


def test_an_index_stands_below_its_letter_and_a_component_above(tmp_path) -> None:
    """S₂'s 2 lower than its S; R₁₄ with its τ raised above the 14; each index right after its letter, as close as
    the letters of a word stand, after spaces before it and two in a row alike."""
    _, s2, r14, *_, arms = _typeset(tmp_path)
    # PDFium's boxes are the glyphs' ink: h₅ at the text's start and h₆ after two spaces stand their index as far
    # off, where a space's width more had parted the second.
    gaps = [box[0] - arms[k - 1][1][2] for k, (character, box) in enumerate(arms)
            if character.isdigit() and arms[k - 1][0] == "h"]
    assert len(gaps) == 2 and abs(gaps[1] - gaps[0]) < 0.1, gaps
    (_, s), (_, two) = s2
    assert two[1] < s[1] and two[3] < s[3]
    (_, r), (_, one), (_, four), (_, tau) = r14
    assert one[1] < r[1] and four[1] < r[1] and tau[1] > four[1]
