"""The explanatory note as a PDF: A4 pages that hold every heading and number of the note, in each language.

The PDF's text is read back with PDFium (pypdfium2), an independent reader: what it extracts is what
a reader of the PDF would copy, so a heading or a number lost in typesetting, or a glyph without its
font (CJK in a Latin font), fails here.
"""

from __future__ import annotations

import os
import re
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.errors import OutputError
from graphplan.report.note import note_html
from graphplan.report.pdf import note_pdf

pdfium = pytest.importorskip("pypdfium2")
try:
    import weasyprint
except (ImportError, OSError) as error:  # OSError: no Pango library
    pytest.skip(f"WeasyPrint cannot typeset here: {error}", allow_module_level=True)

A4_PT = (595.28, 841.89)


class _Headings(HTMLParser):
    """The text of each h1–h3 of an HTML document."""

    def __init__(self) -> None:
        super().__init__()
        self.found: list[str] = []
        self._inside = False

    def handle_starttag(self, tag, attrs):
        if tag in ("h1", "h2", "h3"):
            self._inside = True
            self.found.append("")

    def handle_endtag(self, tag):
        if tag in ("h1", "h2", "h3"):
            self._inside = False

    def handle_data(self, data):
        if self._inside:
            self.found[-1] += data


def squeezed(text: str) -> str:
    """Text without whitespace or soft hyphens: lines break differently in the PDF than in the HTML."""
    return re.sub(r"[\s\u00ad\ufffe]+", "", text)


@pytest.fixture(scope="module")
def ratchet():
    return analyse(graphplan.load("fixtures/ratchet_crank_rocker.toml"))


@pytest.fixture(scope="module")
def notes(ratchet):
    """The ratchet's note in each language: its HTML and its PDF."""
    found = {}
    for locale in ("en", "ru", "zh"):
        import dataclasses

        analysis = dataclasses.replace(ratchet, scene=dataclasses.replace(ratchet.scene, locale=locale))
        html = note_html(analysis)
        found[locale] = (html, note_pdf(html))
    return found


def pdf_text(data: bytes) -> tuple[list[tuple[float, float]], str]:
    document = pdfium.PdfDocument(data)
    sizes = [tuple(page.get_size()) for page in document]
    text = "".join(page.get_textpage().get_text_range() for page in document)
    return sizes, text


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_every_heading_of_the_note_is_in_its_pdf_on_a4_pages(notes, locale):
    html, data = notes[locale]
    sizes, text = pdf_text(data)
    assert len(sizes) > 5  # the ratchet's note runs over many pages
    assert all(abs(w - A4_PT[0]) < 1 and abs(h - A4_PT[1]) < 1 for w, h in sizes)
    parser = _Headings()
    parser.feed(html)
    assert len(parser.found) > 8
    flat = squeezed(text)
    for heading in parser.found:
        assert squeezed(heading) in flat, heading


def test_the_numbers_read_off_the_plan_are_in_the_pdf_with_the_languages_decimal_mark(notes):
    _, ru = notes["ru"]
    _, en = notes["en"]
    # μV = VA / pa = 2.975 / 150: the driver's velocity ω·lOA = 17 × 0.175 m/s, with the locale's decimal mark.
    assert "2,975" in pdf_text(ru)[1] and "2.975" in pdf_text(en)[1]


def test_a_unit_in_a_narrow_table_column_stays_on_one_line(notes):
    """The error table's unit column is narrow: рад/с² must not break after its slash."""
    _, data = notes["ru"]
    text = pdf_text(data)[1]
    assert text.count("рад/с²") >= 2 * 2  # ε3 and ε4 at both positions of the error tables
    assert not re.search(r"рад/\s+с", text)


def test_chinese_text_comes_out_as_chinese_not_as_missing_glyphs(notes):
    _, data = notes["zh"]
    text = pdf_text(data)[1]
    chinese = [c for c in text if "\u4e00" <= c <= "\u9fff"]
    assert len(chinese) > 500
    assert "\ufffd" not in text


@pytest.fixture(scope="module")
def ratchet_run_as_pdf(tmp_path_factory) -> Path:
    """``graphplan run`` of the ratchet's note as PDF: the folder it wrote."""
    out = tmp_path_factory.mktemp("ratchet") / "pdf"
    assert main(["run", "fixtures/ratchet_crank_rocker.toml", "--out", str(out), "--only", "note", "--format",
                 "pdf"]) == 0
    return out


def test_the_same_note_gives_the_same_pdf_bytes(notes, ratchet_run_as_pdf):
    """The ratchet's note is Russian: the run typesets the same HTML the fixture did, a second time, apart."""
    html, data = notes["ru"]
    assert (ratchet_run_as_pdf / "note.html").read_text(encoding="utf-8") == html
    assert (ratchet_run_as_pdf / "note.pdf").read_bytes() == data
    assert "SOURCE_DATE_EPOCH" not in os.environ


def test_the_command_line_writes_the_note_as_pdf_only_when_pdf_is_asked_for(tmp_path, ratchet_run_as_pdf):
    scene = "fixtures/ratchet_crank_rocker.toml"
    assert (ratchet_run_as_pdf / "note.pdf").read_bytes().startswith(b"%PDF")
    assert main(["run", scene, "--out", str(tmp_path / "plain"), "--only", "note"]) == 0
    assert not (tmp_path / "plain" / "note.pdf").exists()


def test_without_weasyprint_the_pdf_of_the_note_is_a_clear_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "weasyprint", None)  # import weasyprint now raises ImportError
    with pytest.raises(OutputError, match=r"note\.pdf: .*WeasyPrint.*--format"):
        note_pdf("<html><body><p>x</p></body></html>")


MM = 72 / 25.4
# The note's page margins (graphplan.report.html): 30 mm on the left for binding, 10 mm on the right.
LEFT_MM, RIGHT_MM = 30.0, 10.0
CAPTION = re.compile(r"^(Table \d+\.|Таблица \d+ —|表 \d+)")


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_every_character_of_the_pdf_stands_within_its_margins(notes, locale):
    """The widest table (the errors of a position: a value and an error for each of three sources) once ran
    off the right edge of the page; every glyph must lie between the margins, as PDFium places it."""
    _, data = notes[locale]
    for number, page in enumerate(pdfium.PdfDocument(data), 1):
        width, _ = page.get_size()
        text = page.get_textpage()
        boxes = [text.get_charbox(k) for k in range(text.count_chars())]
        boxes = [box for box in boxes if box[2] > box[0]]  # spaces and breaks have no extent
        assert min(box[0] for box in boxes) >= LEFT_MM * MM - 1, number
        assert max(box[2] for box in boxes) <= width - RIGHT_MM * MM + 1, number


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_no_page_ends_with_a_table_caption_parted_from_its_table(notes, locale):
    html, data = notes[locale]
    assert html.count('class="table-caption"') > 5
    for number, page in enumerate(pdfium.PdfDocument(data), 1):
        lines = [line.strip() for line in page.get_textpage().get_text_range().splitlines() if line.strip()]
        body = lines[:-1] if lines and lines[-1] == str(number) else lines  # the page number at the foot
        assert body and not CAPTION.match(body[-1]), (number, body[-1])


def test_a_table_longer_than_a_page_starts_under_its_caption_and_goes_on_over_the_page():
    """The shaper's error tables (36 rows) were kept whole and pushed to the next page, each leaving a page
    that held its caption alone (a user's report); a long table now starts where its caption is and its
    rows run over the page, the header repeated."""
    html = note_html(analyse(graphplan.load("fixtures/shaper_six_bar.toml")))
    long_tables = [table for table in re.findall(r"<table[^>]*>(.*?)</table>", html, re.DOTALL)
                   if table.count("<tr>") > 30]
    assert long_tables
    pages = [[line.strip() for line in page.get_textpage().get_text_range().splitlines() if line.strip()]
             for page in pdfium.PdfDocument(note_pdf(html))]
    for number, lines in enumerate(pages, 1):
        body = lines[:-1] if lines and lines[-1] == str(number) else lines
        assert body and not CAPTION.match(body[-1]), (number, body[-1])
        assert len(body) > 3, (number, body)  # no page of a caption or a heading alone


def test_the_page_numbers_are_set_in_the_body_s_font(notes):
    """The page's margin boxes inherit nothing from the body: the numbers came out in DejaVu Serif."""
    import ctypes

    from pypdfium2 import raw

    _, data = notes["en"]
    page = pdfium.PdfDocument(data)[1]
    text = page.get_textpage()
    name = ctypes.create_string_buffer(256)
    raw.FPDFText_GetFontInfo(text, text.count_chars() - 1, name, 256, ctypes.byref(ctypes.c_int()))
    assert text.get_text_range().rstrip().endswith("2")
    assert name.value.decode().split("+")[-1] == "DejaVu-Sans"


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_no_word_of_a_table_header_is_hyphenated(notes, locale):
    """The error tables' headers broke inside their words ("quant-ity", "construc-tion", "draft-ing") while
    their δ columns stood wide; a header wraps between its words only, a wide table set smaller to fit."""
    html, data = notes[locale]
    assert "<th" in html
    for number, page in enumerate(pdfium.PdfDocument(data), 1):
        text = page.get_textpage().get_text_range()
        # A break the typesetter hyphenated: a hyphen of its own (U+2010) or a soft one at the end of a line.
        assert not re.search(r"\w[\u2010\u00ad\ufffe]\s*\n", text), (number, text)
    # The ratchet's error tables of a position have nine columns in every language (with the measured values).
    assert max(len(re.findall(r"<th", row)) for row in re.findall(r"<tr>(.*?)</tr>", html, re.DOTALL)) == 9


def test_a_bold_paragraph_that_heads_what_follows_never_ends_a_page():
    """The note heads each group's equations with a bold paragraph ("Group II(5,6), kind RRP"); a student's
    PDF had three of them alone at the foot of a page.  Filled with more and more lines before it, the lead
    goes over to the next page with what it heads, wherever the page break falls."""
    from graphplan.report.html import to_html

    for filler in range(40, 56):
        markdown = "\n\n".join([f"Line {k} of the running text." for k in range(filler)]
                               + ["**Group II(5,6), kind RRP**", "Vector equation: VD = VC + VDC."])
        pages = [[line.strip() for line in page.get_textpage().get_text_range().splitlines() if line.strip()]
                 for page in pdfium.PdfDocument(note_pdf(to_html(markdown, "Lead", "en")))]
        for number, lines in enumerate(pages, 1):
            body = lines[:-1] if lines and lines[-1] == str(number) else lines
            assert body[-1] != "Group II(5,6), kind RRP", (filler, number)


def test_a_unit_is_never_broken_across_lines_of_the_pdf():
    """WeasyPrint broke a Chinese line of the note after a unit's slash: «（g = 9.81 m/» ended one line and «s²）»
    opened the next (a hunt's zh note.pdf, p. 21).  A paragraph set with its unit at every place along the line
    breaks before or after each unit, never inside it."""
    from weasyprint.formatting_structure import boxes

    from graphplan.report.html import to_html

    sentence = "重力 G = m·g（g = 9.81 m/s²），μV = 0.02 (m/s)/mm，平衡力矩 Mb = 49.02 N·m，ω = 12.5 rad/s。"
    page = to_html("\n\n".join("按" * shift + sentence for shift in range(60)), "units", "zh", symbols=True)
    lines = ["".join(text.text for text in line.descendants() if isinstance(text, boxes.TextBox))
             for laid in weasyprint.HTML(string=page).render().pages
             for line in laid._page_box.descendants() if isinstance(line, boxes.LineBox)]
    assert len(lines) > 60  # the sentence does break, somewhere
    assert [line for line in lines if line.rstrip().endswith(("/", "·"))] == []
