"""The explanatory note as a student hands it in and a teacher reads it: note.html, note.tex, note.docx and
note.pdf say what note.md says, in English, Russian and Chinese.

The notes are those of the starters a course project begins from (`graphplan new shaper`: friction in two pairs,
the machine's dynamics with a motor; `new flywheel`, `new rotor`: no linkage) and of a fixture, written as
`graphplan run` writes them.  Each format is read back by a reader of its own, none of them the writer's: the
HTML by html.parser, the LaTeX by pylatexenc (and, where XeLaTeX is installed, typeset and read by PDFium), the
Word document by python-docx, the PDF by PDFium; note.md by markdown-it's token stream.
"""

from __future__ import annotations

import io
import itertools
import json
import re
import zipfile
from html.parser import HTMLParser
from pathlib import Path

import docx
import pytest
from markdown_it import MarkdownIt
from test_latex import (
    flat,
    latex_tables,
    markdown_tables,
    needs_xelatex,
    pdf_text,
    plain,
    same_tables,
    typeset,
)
from test_word import body_blocks, word_tables

import graphplan
from graphplan import deliverables
from graphplan.analysis import analyse
from graphplan.starters import starter

# (what the note is of, its locale, the pieces written beside it): the shaper's note with the drawings it shows in
# one language, and without them in the others.
CASES = [("shaper", "zh", ("note", "positions", "velocity", "acceleration", "diagrams", "dynamics")),
         ("shaper", "en", ("note",)), ("shaper", "ru", ("note",)),
         ("flywheel", "ru", ("note", "dynamics")), ("rotor", "en", ("note", "balancing", "vibration")),
         ("fixtures/ratchet_crank_rocker.toml", "ru", ("note",))]
IDS = [f"{Path(kind).stem}-{locale}-{'figures' if len(pieces) > 1 else 'text'}" for kind, locale, pieces in CASES]

_written: dict[tuple, dict] = {}


def scene_of(kind: str, locale: str):
    if kind.endswith(".toml"):
        import dataclasses

        return dataclasses.replace(graphplan.load(kind), locale=locale)
    return graphplan.load_text(starter(kind, locale))


def written(kind: str, locale: str, pieces: tuple[str, ...], formats=("svg", "docx")) -> dict:
    """The files `graphplan run` writes of the case, made once for the module."""
    key = (kind, locale, pieces, formats)
    if key not in _written:
        scene = scene_of(kind, locale)
        analysis = analyse(scene) if scene.has_linkage else None
        _written[key] = deliverables.files(scene, analysis, pieces, formats)
    return _written[key]


@pytest.fixture(scope="module", params=CASES, ids=IDS)
def case(request):
    kind, locale, pieces = request.param
    return kind, written(kind, locale, pieces)


# ---- each format read back as blocks: ("h", level, text), ("p", text), ("t", rows), ("figure", file) ----

def markdown_blocks(note: str) -> list[tuple]:
    tokens = MarkdownIt("commonmark").enable("table").parse(note)
    blocks, depth = [], 0
    for k, token in enumerate(tokens):
        depth += {"table_open": 1, "table_close": -1}.get(token.type, 0)
        if token.type == "heading_open":
            blocks.append(("h", int(token.tag[1:]), squashed(flat(tokens[k + 1].content))))
        elif token.type == "inline" and depth == 0 and tokens[k - 1].type == "paragraph_open":
            images = [child for child in token.children or () if child.type == "image"]
            blocks.append(("figure", images[0].attrs["src"]) if images else ("p", squashed(flat(text_of(token)))))
    return blocks


def text_of(token) -> str:
    return "".join(child.content if child.type in ("text", "code_inline") else " " if "break" in child.type else ""
                   for child in token.children or ())


def squashed(text: str) -> str:
    return " ".join(text.split())


class _HtmlBlocks(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.blocks: list[tuple] = []
        self.text: str | None = None
        self.rows: list[list[str]] | None = None

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.blocks.append(("figure", dict(attrs)["src"]))
        elif tag == "table":
            self.rows = []
        elif tag == "tr":
            self.rows.append([])
        elif re.fullmatch(r"h\d|p|li|figcaption|td|th", tag):
            self.text = ""

    def handle_endtag(self, tag):
        if tag == "table":
            self.blocks.append(("t", self.rows))
        if self.text is None or not re.fullmatch(r"h\d|p|li|figcaption|td|th", tag):
            return
        text, self.text = squashed(self.text), None
        if tag in ("td", "th"):
            self.rows[-1].append(text)
        elif re.fullmatch(r"h\d", tag):
            self.blocks.append(("h", int(tag[1:]), text))
        elif text:
            self.blocks.append(("p", text))

    def handle_data(self, data):
        if self.text is not None:
            self.text += data


def html_blocks(page: str) -> list[tuple]:
    reader = _HtmlBlocks()
    reader.feed(page)
    return reader.blocks


def html_tables(page: str) -> list[list[list[str]]]:
    tables = re.findall(r"<table[^>]*>(.*?)</table>", page, flags=re.DOTALL)
    return [[[squashed(plain_html(cell)) for cell in re.findall(r"<t[hd][^>]*>(.*?)</t[hd]>", row, flags=re.DOTALL)]
             for row in re.findall(r"<tr>(.*?)</tr>", table, flags=re.DOTALL)] for table in tables]


def plain_html(fragment: str) -> str:
    from html import unescape

    return unescape(re.sub(r"<[^>]+>", "", fragment))


WORD_LEVELS = {"Title": 1, "Heading 1": 2, "Heading 2": 3, "Heading 3": 4}


def word_headings(document) -> list[tuple[int, str]]:
    return [(WORD_LEVELS[p.style.name], squashed(p.text)) for p in document.paragraphs if p.style.name in WORD_LEVELS]


def word_marked(document) -> str:
    """The Word document's paragraphs' text with each run set below the line written _{so}."""
    return "\n".join("".join(f"_{{{run.text}}}" if run.font.subscript else run.text for run in p.runs)
                     for kind, p in body_blocks(document) if kind == "p")


def latex_headings(latex: str) -> list[tuple[int, str]]:
    body = latex.split("\\begin{document}")[1]
    found = []
    for line in body.splitlines():
        if title := re.fullmatch(r"\{\\centering\\Large\\bfseries (.*)\\par\}", line):
            found.append((1, plain(title[1])))
        elif section := re.fullmatch(r"\\((?:sub)*)section\*\{(.*)\}", line):
            found.append((2 + len(section[1]) // 3, plain(section[2])))
    return found


# ---- the same note in every format ----

def test_every_format_has_note_md_s_headings_in_its_order(case):
    _, files = case
    expected = [(level, text) for kind, level, text in
                (block for block in markdown_blocks(files["note.md"]) if block[0] == "h")]
    assert len(expected) >= 2
    html = [(level, text) for kind, level, text in
            (block for block in html_blocks(files["note.html"]) if block[0] == "h")]
    assert html == expected
    assert latex_headings(files["note.tex"]) == [(min(level, 4), text) for level, text in expected]
    document = docx.Document(io.BytesIO(files["note.docx"]))
    assert word_headings(document) == [(min(level, 4), text) for level, text in expected]


def test_every_table_has_the_same_cells_and_numbers_in_every_format(case):
    """Cell for cell: a number that differed in one format (rounded otherwise, a sign lost) would show here."""
    kind, files = case
    expected = markdown_tables(files["note.md"])
    assert len(expected) >= (0 if kind == "flywheel" else 2)   # the flywheel's note tables nothing
    assert [rows for _, rows in expected] == html_tables(files["note.html"])
    assert same_tables(latex_tables(files["note.tex"]), expected)
    assert word_tables(docx.Document(io.BytesIO(files["note.docx"]))) == expected


def test_every_paragraph_reads_the_same_in_every_format(case):
    _, files = case
    expected = [block[1] for block in markdown_blocks(files["note.md"]) if block[0] == "p"]
    html = [block[1] for block in html_blocks(files["note.html"]) if block[0] == "p"]
    assert html == expected
    word = [squashed(p.text) for kind, p in body_blocks(docx.Document(io.BytesIO(files["note.docx"])))
            if kind == "p" and p.text.strip() and p.style.name not in WORD_LEVELS]
    assert word == expected
    latex = plain(files["note.tex"].split("\\begin{document}")[1])
    for paragraph in expected:
        assert paragraph in latex


def test_every_figure_the_note_names_is_written_and_shown_in_every_format(case):
    _, files = case
    figures = [block[1] for block in markdown_blocks(files["note.md"]) if block[0] == "figure"]
    assert all(name in files for name in figures)
    assert [block[1] for block in html_blocks(files["note.html"]) if block[0] == "figure"] == figures
    assert re.findall(r"\\notefigure\{([^}]*)\.pdf\}", files["note.tex"]) == [name[:-4] for name in figures]
    with zipfile.ZipFile(io.BytesIO(files["note.docx"])) as package:
        document = package.read("word/document.xml").decode("utf-8")
        pictures = [name for name in package.namelist() if name.startswith("word/media/")]
    assert document.count("<a:blip ") == len(figures)
    assert len(pictures) == len(figures)


def test_no_section_is_empty_and_no_placeholder_or_markup_is_left(case):
    _, files = case
    blocks = markdown_blocks(files["note.md"])
    for k, block in enumerate(blocks):
        if block[0] == "h":
            after = blocks[k + 1] if k + 1 < len(blocks) else None
            assert after is not None and not (after[0] == "h" and after[1] <= block[1]), block
    text = " ".join(block[-1] for block in html_blocks(files["note.html"]) if block[0] in ("h", "p"))
    text += json.dumps(html_tables(files["note.html"]), ensure_ascii=False)
    for leftover in (r"\{[a-z_]+\}", r"\bNone\b", r"\bnan\b", r"\*\*", r"\^", r"\\", r"\ufffd", r"Ã|Ð[^\w]|â€"):
        assert not re.search(leftover, text), leftover


# ---- the formulas ----

def subscripted_everywhere(files: dict, base: str, index: str, after: str = "") -> None:
    """``base`` with ``index`` set below the line (followed by ``after``) in the HTML, the LaTeX and the Word note."""
    assert f"{base}<sub>{index}</sub>{after}" in files["note.html"]
    assert f"{base}\\textsubscript{{{index}}}{after}" in files["note.tex"]
    assert f"{base}_{{{index}}}{after}" in word_marked(docx.Document(io.BytesIO(files["note.docx"])))


def test_the_structure_formula_sets_each_group_s_order_as_its_class_s_index():
    """«II2(3,4)» read as a class «II2»: the textbooks write a group's order under its class, II₂(3,4)."""
    files = written("shaper", "en", ("note",))
    assert "I(1,2) → II2(3,4) → II2(5,6)" in files["note.md"]
    subscripted_everywhere(files, "II", "2", "(3,4)")


def test_the_lever_s_moments_about_its_pole_and_a_travel_along_a_guide_take_their_index():
    files = written("shaper", "ru", ("note",))
    assert "ΣMp" in files["note.md"] and "| sE, м |" in files["note.md"]
    subscripted_everywhere(files, "ΣM", "p")
    subscripted_everywhere(files, "s", "E")


@pytest.mark.parametrize("locale, speeds", [("en", ("s", "N")), ("ru", ("0", "н"))])
def test_the_initial_data_s_journal_radius_and_motor_speeds_take_their_index(locale, speeds):
    """The initial data's table wrote rO beside fO subscripted, and the motor's ns, nN (n0, nн) flat."""
    files = written("shaper", locale, ("note",))
    assert "| rO |" in files["note.md"]
    cells = "\n".join("".join(f"_{{{run.text}}}" if run.font.subscript else run.text
                               for paragraph in cell.paragraphs for run in paragraph.runs)
                       for table in docx.Document(io.BytesIO(files["note.docx"])).tables
                       for row in table.rows for cell in row.cells)
    for base, index, after in [("r", "O", ""), *(("n", index, " = ") for index in speeds)]:
        assert f"{base}{index}{after}" in files["note.md"]
        assert f"{base}<sub>{index}</sub>{after}" in files["note.html"]
        assert f"{base}\\textsubscript{{{index}}}{after}" in files["note.tex"]
        assert f"{base}_{{{index}}}{after}" in cells


def test_a_rocker_s_angle_takes_its_link_s_index():
    files = written("fixtures/ratchet_crank_rocker.toml", "ru", ("note",))
    assert "ψ4" in files["note.md"]
    subscripted_everywhere(files, "ψ", "4")


def test_the_natural_frequency_of_a_machine_on_its_mounts_takes_its_index():
    files = written("rotor", "en", ("note", "balancing", "vibration"))
    assert "ωn = √(k/M)" in files["note.md"] and "sin ωt" in files["note.md"]
    subscripted_everywhere(files, "ω", "n", " = √")
    assert "ω<sub>t</sub>" not in files["note.html"] and " ωt" in plain_html(files["note.html"])   # ω times t


# ---- PDF ----

def pdf_reads(pdf: Path | bytes, note: str) -> list[str]:
    """The headings, paragraphs and table cells of ``note`` the PDF's text does not hold (whitespace, soft hyphens
    and hyphens at line ends aside; the page numbers dropped)."""
    import pypdfium2

    document = pypdfium2.PdfDocument(pdf)
    try:
        pages = [page.get_textpage().get_text_range() for page in document]
    finally:
        document.close()
    # List items' bullets are read after their page's text, and a word broken at a hyphen has lost it.
    squeeze = lambda text: re.sub(r"[\s\u00ad\ufffe•-]+", "", text)
    pages = [squeeze(re.sub(r"\d+\s*$", "", page)) for page in pages]
    text = "".join(pages)

    def read_across_a_page_break(piece: str) -> bool:
        # A figure's words are read after the text of its page, so a paragraph going on over the next page is read
        # with the figure's words between its two parts: its head must end a page's text flow before them, and its
        # tail begin the next page.
        for page, after in itertools.pairwise(pages):
            for cut in range(1, len(piece)):
                if after.startswith(piece[cut:]):
                    if piece[:cut] in page:
                        return True
                    break
        return False

    wanted = [block[-1] for block in markdown_blocks(note) if block[0] in ("h", "p")]
    wanted += [cell for _, rows in markdown_tables(note) for row in rows for cell in row]
    return [piece for piece in wanted if squeeze(piece) not in text and not read_across_a_page_break(squeeze(piece))]


def embedded_fonts(pdf: bytes) -> set[str]:
    import ctypes

    import pypdfium2
    from pypdfium2 import raw

    names = set()
    document = pypdfium2.PdfDocument(pdf)
    for page in document:
        for item in page.get_objects(max_depth=5):
            if item.type == raw.FPDF_PAGEOBJ_TEXT:
                font = raw.FPDFTextObj_GetFont(item.raw)
                size = raw.FPDFFont_GetBaseFontName(font, None, 0)
                name = ctypes.create_string_buffer(size)
                raw.FPDFFont_GetBaseFontName(font, name, size)
                names.add(name.value.decode())
    document.close()
    return names


@pytest.mark.parametrize("kind, locale, pieces, script", [
    ("shaper", "zh", ("note",), "CJK"), ("flywheel", "ru", ("note", "dynamics"), "DejaVu")])
def test_the_pdf_holds_every_heading_paragraph_and_cell_in_a_font_of_its_script(kind, locale, pieces, script):
    pytest.importorskip("pypdfium2")
    try:
        import weasyprint  # noqa: F401
    except (ImportError, OSError) as error:
        pytest.skip(f"WeasyPrint cannot typeset here: {error}")
    files = written(kind, locale, pieces)
    note = note_pdf_of(files)
    assert pdf_reads(note, files["note.md"]) == []
    assert any(script.replace(" ", "") in name.replace("-", "") for name in embedded_fonts(note))


def note_pdf_of(files: dict) -> bytes:
    """note.pdf as `--format svg,pdf` writes it: deliverables.files typesets note.html with the SVGs beside it.  The
    run's own files are shared with the other tests (the note made once), and the PDF of every drawing and plot,
    which no test here reads, is not made; for both cases above this was diffed once against
    ``files(..., ("svg", "pdf"))["note.pdf"]``: the same bytes."""
    from graphplan.report.pdf import note_pdf

    return note_pdf(str(files["note.html"]), {name: str(text) for name, text in files.items() if name.endswith(".svg")})


@needs_xelatex
@pytest.mark.parametrize("kind, locale, pieces", [("shaper", "en", ("note",)), ("shaper", "zh", ("note",)),
                                                  ("rotor", "ru", ("note", "balancing", "vibration"))])
def test_the_latex_typesets_to_the_words_of_note_md_with_its_figures(kind, locale, pieces, tmp_path):
    """Typeset, the LaTeX reads as note.md does: every glyph in a font that has it, every figure's drawing from its
    PDF beside the note (no frame with a file's name in its place), and the text as written: TeX's ligatures
    had set the note's apostrophes as ’."""
    from graphplan.render.export import svg_to_pdf

    files = written(kind, locale, pieces)
    for name, content in files.items():
        if name.endswith(".svg"):   # as --format pdf writes each drawing beside its SVG
            (tmp_path / f"{name[:-4]}.pdf").write_bytes(svg_to_pdf(str(content)))
    log, pdf = typeset(tmp_path, "note", files["note.tex"])
    assert "Missing character" not in log
    assert pdf_reads(pdf, files["note.md"]) == []
    assert ".svg" not in pdf_text(pdf)


@needs_xelatex
def test_a_title_is_typeset_as_typed_without_tex_s_ligatures(tmp_path):
    """The title is shown as typed in every format (docs/scene-format-extensions.md): XeLaTeX's TeX ligatures had
    set its ` as ‘, -- as –, `` and '' as “ ”, << >> as « », ,, as „ in note.tex alone."""
    title = "Press `A` -- ``B'' <<C>> ,,D & 50% {y} ~z #3"
    scene_text = re.sub(r'^title\s*=\s*"[^"]*"', "title = " + json.dumps(title), starter("rotor", "en"), count=1,
                        flags=re.MULTILINE)
    files = deliverables.files(graphplan.load_text(scene_text), None, ("note",), ("svg", "docx"))
    heading = f"Explanatory note: {title}"
    assert ("h", 1, heading) in html_blocks(files["note.html"])
    assert word_headings(docx.Document(io.BytesIO(files["note.docx"])))[0] == (1, heading)
    _, pdf = typeset(tmp_path, "note", files["note.tex"])
    assert squashed(pdf_text(pdf)).startswith(f"{heading} 1. Balancing of the rotor")

