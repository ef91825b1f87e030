"""The note as a Word document (note.docx), read back by python-docx against the Markdown it was written from.

The Markdown side is read with markdown-it's flat token stream (as the LaTeX's tests read it), not with the
syntax tree the writer walks: every table cell for cell with its caption, every heading with its level, the
running text word for word, and each symbol's index and component as the sub- and superscript runs that
:mod:`graphplan.report.symbols` tells apart.
"""

from __future__ import annotations

import functools
import io
import zipfile
from pathlib import Path
from xml.etree import ElementTree

import docx
import pytest
from docx.oxml.ns import qn
from markdown_it import MarkdownIt
from test_latex import CASES, flat, markdown_tables, note_of

from graphplan.cli import main
from graphplan.report.symbols import Symbol, pieces
from graphplan.report.word import note_docx
from graphplan.starters import starter


@pytest.fixture(scope="module", params=CASES, ids=[f"{Path(path).stem}-{locale}" for path, locale in CASES])
def case(request):
    path, locale = request.param
    analysis, note = note_of(path, locale)
    written = note_docx(note, analysis.scene.title, locale)
    return locale, note, written, docx.Document(io.BytesIO(written))


def body_blocks(document):
    """The document's paragraphs and tables in order, as ("p", paragraph) and ("table", table)."""
    paragraphs = {p._p: p for p in document.paragraphs}
    tables = {t._tbl: t for t in document.tables}
    for element in document.element.body.iterchildren():
        if element.tag == qn("w:p"):
            yield "p", paragraphs[element]
        elif element.tag == qn("w:tbl"):
            yield "table", tables[element]


def word_tables(document) -> list[tuple[str | None, list[list[str]]]]:
    """Each table as (the paragraph right before it, when it has text; its rows, header first)."""
    found, before = [], None
    for kind, block in body_blocks(document):
        if kind == "p":
            before = " ".join(block.text.split()) or None
        else:
            rows = [[" ".join(cell.text.split()) for cell in row.cells] for row in block.rows]
            found.append((before, rows))
            before = None
    return found


def markdown_inline(note: str, inside_tables: bool):
    """The inline tokens of the Markdown, those in its tables or those outside them."""
    tokens = MarkdownIt("commonmark").enable("table").parse(note)
    depth = 0
    for token in tokens:
        depth += {"table_open": 1, "table_close": -1}.get(token.type, 0)
        if token.type == "inline" and (depth > 0) == inside_tables:
            yield token


def test_every_table_of_the_note_comes_back_cell_for_cell_with_its_caption(case):
    _, note, _, document = case
    expected, got = markdown_tables(note), word_tables(document)
    assert len(got) == len(expected) > 5
    assert got == expected


def test_every_heading_comes_back_with_its_level(case):
    _, note, _, document = case
    tokens = MarkdownIt("commonmark").enable("table").parse(note)
    expected = [(int(token.tag[1:]), flat(tokens[k + 1].content))
                for k, token in enumerate(tokens) if token.type == "heading_open"]
    levels = {"Title": 1, "Heading 1": 2, "Heading 2": 3, "Heading 3": 4}
    got = [(levels[p.style.name], p.text) for p in document.paragraphs if p.style.name in levels]
    # The note's fourth level (a plan) and below share Word's third heading.
    assert got == [(min(level, 4), text) for level, text in expected]
    assert document.paragraphs[0].style.name == "Title"


def test_the_running_text_comes_back_word_for_word(case):
    _, note, _, document = case
    expected = " ".join(flat(" ".join(child.content for child in token.children or () if child.type == "text"))
                        for token in markdown_inline(note, inside_tables=False)).split()
    got = " ".join(p.text for kind, p in body_blocks(document) if kind == "p").split()
    assert got == expected


def test_symbols_have_their_index_below_the_line_and_their_component_above(case):
    _, note, _, document = case
    expected = [(symbol.index, symbol.component) for token in markdown_inline(note, inside_tables=False)
                for child in token.children or () if child.type == "text"
                for symbol in pieces(child.content) if isinstance(symbol, Symbol)]
    runs = [run for kind, p in body_blocks(document) if kind == "p" for run in p.runs]
    got, k = [], 0
    while k < len(runs):
        if runs[k].font.subscript:
            above = runs[k + 1].text if k + 1 < len(runs) and runs[k + 1].font.superscript else ""
            got.append((runs[k].text, above))
            k += 2 if above else 1
        else:
            k += 1
    assert got == [(index, component) for index, component in expected if index]
    assert len(got) > 50


def test_a_table_s_header_row_is_bold_and_repeats_on_every_page(case):
    _, _, _, document = case
    for table in document.tables:
        header = table.rows[0]
        assert header._tr.trPr.find(qn("w:tblHeader")) is not None
        assert all(run.bold for cell in header.cells for run in cell.paragraphs[0].runs)
        assert not any(run.bold for row in table.rows[1:] for cell in row.cells
                       for run in cell.paragraphs[0].runs if run.text.strip() and not run.text.startswith("Σ"))


def test_a_short_table_keeps_to_one_page_and_a_long_one_keeps_its_header_with_its_first_row(case):
    """Word keeps a table on one page when every row but the last keeps with the next; no row parts its lines."""
    _, _, _, document = case
    kept = lambda row: {p.paragraph_format.keep_with_next for cell in row.cells for p in cell.paragraphs}
    assert any(len(table.rows) <= 20 for table in document.tables)
    for table in document.tables:
        rows = table.rows
        assert all(row._tr.trPr.find(qn("w:cantSplit")) is not None for row in rows)
        assert kept(rows[-1]) == {False}
        if len(rows) <= 20:
            assert all(kept(row) == {True} for row in rows[:-1])
        else:
            assert kept(rows[0]) == {True} and all(kept(row) == {False} for row in rows[1:])


def test_a_table_of_more_rows_than_a_third_of_a_page_runs_on():
    rows = "\n".join(f"| {k} | {k * k} |" for k in range(30))
    document = docx.Document(io.BytesIO(note_docx(f"# Note\n\n| k | k² |\n|---|---|\n{rows}\n\n| a |\n|---|\n| 1 |\n",
                                                  "Note", "en")))
    long, short = document.tables
    assert [row.cells[0].paragraphs[0].paragraph_format.keep_with_next for row in long.rows] == [True] + [False] * 30
    assert [row.cells[0].paragraphs[0].paragraph_format.keep_with_next for row in short.rows] == [True, False]


def test_a_long_table_is_written_without_listing_all_its_cells_for_each_cell(monkeypatch):
    """python-docx finds a cell by its row and column (``table.cell``, a column's cells) by listing every cell of the
    table: the writer asked so for each cell, and the shaper's note of 31 tables took 14 s to write.  Counted here:
    how often the whole table's cells are listed, against the tables written."""
    listing = docx.table.Table._cells
    listed = []
    monkeypatch.setattr(docx.table.Table, "_cells", property(lambda table: listed.append(1) or listing.fget(table)))
    rows = "\n".join(f"| {k} | {k * k} | {k ** 3} |" for k in range(40))
    written = note_docx(f"# Note\n\n| k | k² | k³ |\n|---|---|---|\n{rows}\n\n| a |\n|---|\n| 1 |\n", "Note", "en")
    # At most once a row (python-docx 1.1 lists them for a row's cells, 1.2 not at all), where once a cell and once
    # a column listed them 129 times for these 43 rows.
    assert len(listed) <= 41 + 2
    monkeypatch.undo()
    long, short = docx.Document(io.BytesIO(written)).tables
    assert [[cell.text for cell in row.cells] for row in long.rows] == [["k", "k²", "k³"]] + [
        [str(k), str(k * k), str(k ** 3)] for k in range(40)]
    assert [[cell.text for cell in row.cells] for row in short.rows] == [["a"], ["1"]]


def test_the_title_is_black_on_no_rule(case):
    _, _, _, document = case
    title = document.styles["Title"]
    assert title.element.find(f"{qn('w:pPr')}/{qn('w:pBdr')}") is None
    assert title.font.color.rgb is None
    assert document.paragraphs[0].style.name == "Title"


def test_the_page_the_fonts_and_the_language_are_the_note_s(case):
    locale, _, _, document = case
    section = document.sections[0]
    # Word keeps lengths in twentieths of a point: a mm comes back to within one of them.
    lengths = (section.page_width, section.page_height, section.left_margin, section.right_margin,
               section.top_margin, section.bottom_margin)
    assert [length.mm for length in lengths] == pytest.approx([210, 297, 30, 10, 20, 20], abs=0.02)
    normal = document.styles["Normal"].element.rPr
    fonts = normal.find(qn("w:rFonts"))
    assert fonts.get(qn("w:ascii")) == "Times New Roman" and fonts.get(qn("w:eastAsia")) == "SimSun"
    language = normal.find(qn("w:lang"))
    assert language.get(qn("w:val")) == {"en": "en-GB", "ru": "ru-RU", "zh": "zh-CN"}[locale]
    assert language.get(qn("w:eastAsia")) == ("zh-CN" if locale == "zh" else language.get(qn("w:val")))


WORD = "{http://schemas.openxmlformats.org/wordprocessingml/2006/main}"
RELATIONSHIPS = "{http://schemas.openxmlformats.org/officeDocument/2006/relationships}"


def package_parts(written: bytes) -> dict[str, ElementTree.Element]:
    """The .docx's XML parts by their names in the package, parsed as they are stored."""
    with zipfile.ZipFile(io.BytesIO(written)) as package:
        return {name: ElementTree.fromstring(package.read(name)) for name in package.namelist()
                if name.endswith((".xml", ".rels"))}


# Kept by the document's bytes: each case's test reads the two wide notes twice, and the package parsed once will do.
@functools.cache
def tables_and_line(written: bytes) -> tuple[list[list[int]], int]:
    """Each table's grid column widths and the width of the text between the margins, twips, from the XML."""
    body = package_parts(written)["word/document.xml"].find(f"{WORD}body")
    section = body.find(f"{WORD}sectPr")
    page, margins = section.find(f"{WORD}pgSz"), section.find(f"{WORD}pgMar")
    line = int(page.get(f"{WORD}w")) - int(margins.get(f"{WORD}left")) - int(margins.get(f"{WORD}right"))
    return [[int(column.get(f"{WORD}w")) for column in table.iter(f"{WORD}gridCol")]
            for table in body.iter(f"{WORD}tbl")], line


@pytest.fixture(scope="module")
def ratchet_for_word(tmp_path_factory) -> Path:
    """``graphplan run`` of the ratchet's note for Word, as a user asks for it: the folder it wrote.  One run serves
    the tests that read it (its tables' widths, its title and author, the files beside it)."""
    out = tmp_path_factory.mktemp("ratchet") / "out"
    assert main(["run", "fixtures/ratchet_crank_rocker.toml", "--out", str(out), "--only", "note",
                 "--format", "docx"]) == 0
    return out


@pytest.fixture(scope="module")
def wide_notes(tmp_path_factory, ratchet_for_word):
    """The notes whose tables outran the line before their columns were narrowed to it: the ratchet's error
    table of nine columns, and the Russian shaper's reduced moments by plan and exact, of eight."""
    folder = tmp_path_factory.mktemp("wide")
    scene = folder / "shaper.toml"
    scene.write_text(starter("shaper", "ru"), encoding="utf-8")
    out = folder / "shaper"
    assert main(["run", str(scene), "--out", str(out), "--only", "note", "--format", "docx"]) == 0
    return [(ratchet_for_word / "note.docx").read_bytes(), (out / "note.docx").read_bytes()]


def test_every_table_fits_between_the_margins(case, wide_notes):
    for written in (case[2], *wide_notes):
        tables, line = tables_and_line(written)
        assert line == round((210 - 30 - 10) / 25.4 * 1440)
        assert tables and all(sum(columns) <= line for columns in tables)
    # The two notes have a table too wide for the line at the sizes a table is set at first.
    assert max(len(columns) for written in wide_notes for columns in tables_and_line(written)[0]) == 9


def test_a_table_too_wide_even_set_small_is_narrowed_to_the_line():
    header = " | ".join(f"abcdefghijklmnopqrstuvwxyz{k}" for k in range(8))
    note = f"# Note\n\n| {header} |\n|{'---|' * 8}\n| {' | '.join(['1.5'] * 8)} |\n"
    (columns,), line = tables_and_line(note_docx(note, "Note", "en"))
    assert len(columns) == 8 and line - 8 <= sum(columns) <= line
    assert max(columns) - min(columns) <= 1   # all as wide: their words are


def test_every_page_is_numbered_at_its_foot_in_the_centre(case):
    parts = package_parts(case[2])
    section = parts["word/document.xml"].find(f"{WORD}body/{WORD}sectPr")
    (reference,) = section.findall(f"{WORD}footerReference")
    assert reference.get(f"{WORD}type") == "default"
    targets = {relation.get("Id"): relation.get("Target") for relation in parts["word/_rels/document.xml.rels"]}
    footer = parts["word/" + targets[reference.get(f"{RELATIONSHIPS}id")]]
    (paragraph,) = footer.findall(f"{WORD}p")
    assert paragraph.find(f"{WORD}pPr/{WORD}jc").get(f"{WORD}val") == "center"
    fields = [field.get(f"{WORD}instr").split() for field in paragraph.iter(f"{WORD}fldSimple")]
    instructions = "".join(text.text for text in paragraph.iter(f"{WORD}instrText"))
    assert fields + ([instructions.split()] if instructions else []) == [["PAGE"]]


def test_the_same_note_gives_the_same_file_with_no_date(case):
    locale, note, written, document = case
    assert note_docx(note, document.core_properties.title, locale) == written
    with zipfile.ZipFile(io.BytesIO(written)) as package:
        assert {info.date_time for info in package.infolist()} == {(1980, 1, 1, 0, 0, 0)}
        core = package.read("docProps/core.xml").decode("utf-8")
    assert "dcterms:created" not in core and "dcterms:modified" not in core
    assert document.core_properties.created is None


def test_a_title_longer_than_a_document_property_holds_is_shortened_there_and_kept_whole_in_the_heading():
    """Word's document properties hold at most 255 characters: a 300-character title crashed python-docx."""
    title = " ".join(["Crank-rocker of a ratchet feed"] * 10)
    assert len(title) == 309
    document = docx.Document(io.BytesIO(note_docx(f"# Note: {title}\n\nText.\n", title, "en")))
    shortened = document.core_properties.title
    assert len(shortened) == 255 and shortened.endswith("…")
    assert title.startswith(shortened.removesuffix("…"))
    assert document.paragraphs[0].text == f"Note: {title}"


def test_the_project_s_author_is_the_word_and_pdf_note_s_author(tmp_path, ratchet_for_word):
    """A note handed in from Word gave its author as "graphplan" though the scene's [project] names the student
    (the title block and the note's head carry it); the PDF gave none.  Both give the student now, and the program
    where the scene names no one."""
    text = starter("crank-rocker", "ru").replace('# [project]\n# author       = "Иванов И. И."',
                                                 '[project]\nauthor       = "Иванов И. И."')
    assert '\nauthor       = "Иванов И. И."' in text
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    formats = "svg,docx,pdf" if _weasyprint() else "svg,docx"
    assert main(["run", str(scene), "--out", str(out), "--only", "note", "--format", formats]) == 0
    assert docx.Document(out / "note.docx").core_properties.author == "Иванов И. И."
    assert '<meta name="author" content="Иванов И. И.">' in (out / "note.html").read_text(encoding="utf-8")
    if _weasyprint():
        import pypdfium2

        assert pypdfium2.PdfDocument(str(out / "note.pdf")).get_metadata_dict()["Author"] == "Иванов И. И."
    # The ratchet's scene names no one.
    assert docx.Document(ratchet_for_word / "note.docx").core_properties.author == "graphplan"


def _weasyprint() -> bool:
    try:
        import pypdfium2  # noqa: F401
        import weasyprint  # noqa: F401
    except (ImportError, OSError):
        return False
    return True


def test_the_command_line_writes_the_note_for_word_when_asked(tmp_path, ratchet_for_word):
    out = ratchet_for_word
    document = docx.Document(out / "note.docx")
    assert document.core_properties.title == "Crank-rocker of a ratchet feed"
    assert document.paragraphs[0].text.startswith("Пояснительная записка")
    assert not (out / "note.svg").exists()   # docx is the note's format, not the drawings'
    plain = tmp_path / "plain"
    assert main(["run", "fixtures/ratchet_crank_rocker.toml", "--out", str(plain), "--only", "note"]) == 0
    assert not (plain / "note.docx").exists()
