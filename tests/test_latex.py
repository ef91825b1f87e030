"""The note and the tables in LaTeX (note.tex, errors.tex, forces.tex).

Read back by other tools than the ones that wrote them: the LaTeX by pylatexenc, against the Markdown's
tables as markdown-it-py's HTML renderer gives them (the writer under test walks markdown-it's syntax tree
itself), the typeset PDF by pdfium.
Where XeLaTeX is installed the documents are typeset, twice as a user would, and must come out without a
missing glyph or a line running into the margin, in Latin, Cyrillic and CJK script.
"""

from __future__ import annotations

import dataclasses
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from markdown_it import MarkdownIt
from pylatexenc.latex2text import LatexNodes2Text

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.locale import strings
from graphplan.render.primitives import character_width, is_wide
from graphplan.report.forces import markdown as forces_markdown
from graphplan.report.latex import _COLUMN_GAP_PT, _LINE_PT, _layout, latex_document, latex_fragment
from graphplan.report.note import note_markdown
from graphplan.report.tables import markdown as errors_markdown

CASES = [("fixtures/shaper_six_bar.toml", "en"), ("fixtures/triad_class_iii.toml", "ru"),
         ("fixtures/engine_slider_crank.toml", "zh")]
XELATEX = shutil.which("xelatex")
needs_xelatex = pytest.mark.skipif(XELATEX is None, reason="XeLaTeX is not installed (Debian: texlive-xetex)")


_notes: dict[tuple[str, str], tuple] = {}


def note_of(path: str, locale: str) -> tuple:
    """The case's analysis and note.md, made once in a process: test_word reads the same notes as Word writes them,
    and shares them where it runs in the same worker."""
    if (path, locale) not in _notes:
        analysis = analyse(dataclasses.replace(graphplan.load(path), locale=locale))
        _notes[path, locale] = analysis, note_markdown(analysis)
    return _notes[path, locale]


@pytest.fixture(scope="module", params=CASES, ids=[f"{Path(path).stem}-{locale}" for path, locale in CASES])
def case(request):
    path, locale = request.param
    analysis, note = note_of(path, locale)
    return analysis, note, latex_document(note, analysis.scene.title, locale)


@pytest.fixture(scope="module")
def typeset_note(tmp_path_factory):
    """A note's LaTeX typeset once for the module (two XeLaTeX runs): the tests of one case read the same log and
    PDF, which the same source gives again."""
    done: dict[str, tuple[str, Path]] = {}

    def typeset_once(latex: str) -> tuple[str, Path]:
        if latex not in done:
            done[latex] = typeset(tmp_path_factory.mktemp("note"), "note", latex)
        return done[latex]

    return typeset_once


def plain(latex: str) -> str:
    """LaTeX back to its text, spaces collapsed; a caret comes back as the modifier letter pylatexenc uses; a line
    break as a space, as the Markdown's reads (pylatexenc drops ``\\newline`` and runs its lines together)."""
    return " ".join(LatexNodes2Text().latex_to_text(latex.replace("\\newline", " ")).replace("ˆ", "^").split())


def flat(text: str) -> str:
    """The note's text as it reads once its symbols are set: ``aBAτ`` is aBA with τ raised, ``aBAⁿ`` with n."""
    return text.replace("^", "").replace("ⁿ", "n").replace("ᵏ", "k").replace("ʳ", "r")


def markdown_tables(text: str) -> list[tuple[str | None, list[list[str]]]]:
    """Each table of the Markdown as (the paragraph right before it, or None; its rows, header first)."""
    tokens = MarkdownIt("commonmark").enable("table").parse(text)
    tables, rows, before = [], [], None
    for k, token in enumerate(tokens):
        if token.type == "table_open":
            previous = tokens[k - 2] if k >= 2 and tokens[k - 1].type == "paragraph_close" else None
            before, rows = (flat(" ".join(previous.content.split())) if previous is not None else None), []
        elif token.type == "tr_open":
            rows.append([])
        elif token.type == "inline" and tokens[k - 1].type in ("th_open", "td_open"):
            rows[-1].append(flat(" ".join(token.content.split())))
        elif token.type == "table_close":
            tables.append((before, rows))
    return tables


def latex_tables(latex: str) -> list[tuple[str | None, list[list[str]]]]:
    """Each longtable of the LaTeX as (its caption, or None; its rows, header first), read back to text."""
    found = []
    for table in re.findall(r"\\begin\{longtable\}.*?\\end\{longtable\}", latex, flags=re.DOTALL):
        caption = re.search(r"\\caption\*\{(.*)\}\\\\\n", table)
        head = table.split("\\endfirsthead")[0]
        header_line = re.search(r"\\toprule\n(.*) \\\\\n\\midrule", head)
        body = table.split("\\endlastfoot\n")[1].removesuffix("\\end{longtable}").strip().splitlines()
        lines = ([header_line[1]] if header_line else []) + [re.sub(r" \\\\\*?$", "", line) for line in body]
        rows = [[plain(_unstacked(cell)) for cell in re.split(r"(?<!\\)&", line)] for line in lines]
        found.append((plain(caption[1]) if caption else None, rows))
    return found


# Where a stacked header breaks its line. The break stands for a space or, in Chinese, for none: which one
# the LaTeX does not say, and a reader must accept either.
BREAK = "¦"


def _unstacked(cell: str) -> str:
    """A header cell's lines out of the one-column tabular that stacks them, joined by :data:`BREAK`."""
    stacked = re.fullmatch(r"\\begin\{tabular\}\[b\]\{@\{\}[lcr]@\{\}\}(.*)\\end\{tabular\}", cell.strip())
    return stacked[1].replace("\\\\", f" {BREAK} ") if stacked else cell


def same_tables(got, expected) -> bool:
    """Whether tables read back from the LaTeX are the Markdown's, a header's line break read as a space or none."""
    def same(cell: str, wanted: str) -> bool:
        pattern = " ?".join(re.escape(line.strip()) for line in cell.split(BREAK))
        return re.fullmatch(pattern, wanted) is not None

    return len(got) == len(expected) and all(
        caption == wanted_caption and len(rows) == len(wanted_rows)
        and all(len(row) == len(wanted_row) and all(map(same, row, wanted_row))
                for row, wanted_row in zip(rows, wanted_rows))
        for (caption, rows), (wanted_caption, wanted_rows) in zip(got, expected))


def test_every_table_of_the_note_comes_back_cell_for_cell_with_its_caption(case):
    _, note, latex = case
    expected, got = markdown_tables(note), latex_tables(latex)
    assert len(got) == len(expected) > 5
    for table, table_back in zip(expected, got):
        assert same_tables([table_back], [table]), (table_back, table)


def test_the_running_text_comes_back_word_for_word(case):
    _, note, latex = case
    # A line ending in a backslash breaks there (an equation's moments, a line each): the mark is no text.
    paragraphs = [line.removesuffix("\\") for line in note.splitlines() if line and not line.startswith(("|", "#", "- "))]
    body = plain(latex.split("\\begin{document}")[1])
    for paragraph in paragraphs:
        assert flat(" ".join(paragraph.replace("**", "").split())) in body


def test_special_characters_are_escaped_and_symbols_take_their_indices():
    text = r"Cost $5 & 10% of #3 {x} a_b ~ ^ \ and VBA = VA + aBA^τ, ω3, R23τ"
    latex = latex_fragment(text, "en")
    body = latex.split("\n", 3)[3]  # after the comment naming the packages
    assert plain(body) == "Cost $5 & 10% of #3 {x} a_b ~ ^ \\ and VBA = VA + aBAτ, ω3, R23τ"
    assert r"V\textsubscript{BA} = V\textsubscript{A} + a\textsubscript{BA}\textsuperscript{τ}" in body
    assert r"ω\textsubscript{3}" in body and r"R\textsubscript{23}\textsuperscript{τ}" in body
    # The friction's and the strokes' symbols, and the Russian dynamics' Cyrillic indices, after a comma too.
    russian = latex_fragment("f′E·R16, Mf12 = ρO·R12; φр.х; Jм = ΔTнб/(ωср²·δ) − Jп,ср", "ru").split("\n", 3)[3]
    for symbol in (r"f′\textsubscript{E}", r"M\textsubscript{f12}", r"ρ\textsubscript{O}", r"φ\textsubscript{р.х}",
                   r"J\textsubscript{м}", r"ΔT\textsubscript{нб}", r"ω\textsubscript{ср}", r"J\textsubscript{п,ср}"):
        assert symbol in russian, symbol
    # No character LaTeX would read as markup is left bare.
    assert not re.search(r"(?<!\\)[$&%#_{}~^]", body.replace(r"\textsubscript{", "").replace(r"\textsuperscript{", "")
                         .replace(r"\textbackslash{}", "").replace(r"\textasciitilde{}", "")
                         .replace(r"\textasciicircum{}", "").replace("}", ""))


def em(text: str) -> float:
    return sum(character_width(c) for c in text)


def line_used(layout) -> float:
    """The line a layout takes, pt: its columns at their type size, and their gaps."""
    return sum(layout.widths) * layout.points + 2 * _COLUMN_GAP_PT * len(layout.widths)


def test_every_table_keeps_room_for_its_bottom_rule_on_every_page(case):
    """A table whose last row filled its page left the bottom rule to the next page, under a repeated header
    and no row (the engine's note in Russian, pages 2 and 3): longtable keeps room on each page for a foot
    as tall as the last one."""
    _, _, latex = case
    tables = re.findall(r"\\begin\{longtable\}.*?\\end\{longtable\}", latex, flags=re.DOTALL)
    assert tables
    for table in tables:
        foot = table.split("\\endhead\n")[1].split("\\endlastfoot")[0]
        assert foot == "\\bottomrule\n\\endfoot\n\\bottomrule\n", foot


def test_a_table_that_fits_keeps_its_columns_and_size():
    layout = _layout(["quantity", "value"], [["lOA", "0.1 m"], ["ω2", "6 rad/s, clockwise"]], ("l", "l"))
    assert layout.specs == ("l", "l") and layout.size == "small"
    # Each column as wide as its widest text, the header in the first, a body cell in the second.
    assert layout.widths == pytest.approx((em("quantity"), em("6 rad/s, clockwise")))


def test_a_table_with_a_long_text_wraps_its_widest_columns_to_fit_the_line():
    long_text = "turned by 90° in the sense of ω3 (counter-clockwise) " * 2
    layout = _layout(["vector", "modulus", "on the plan, mm", "line of action, direction"],
                     [["aA", long_text, "pa = 100.00", "known"], ["aBA", "?", "ab", long_text]], ("l", "l", "r", "l"))
    assert layout.specs[0] == "l" and layout.specs[2] == "r" and layout.size == "small"
    assert "p{" in layout.specs[1] and "p{" in layout.specs[3]
    assert line_used(layout) == pytest.approx(_LINE_PT)


def test_a_table_of_many_columns_is_set_smaller_until_its_headers_fit():
    # The error table of a Russian note with measured values: nine columns, headers of long words.
    header = ["величина", "ед. изм.", "аналитически", "построение", "чертёж", "замер", "δ (построение), %",
              "δ (чертёж), %", "δ (замер), %"]
    layout = _layout(header, [["VB", "м/с", "0,70049", "0,70049", "0,70408", "0,76993", "0,000", "−0,513", "−9,913"]],
                     ("l", "l", "r", "r", "r", "r", "r", "r", "r"))
    assert layout.size != "small"
    assert line_used(layout) <= _LINE_PT


def test_the_fragments_carry_every_table_of_errors_md_and_forces_md(case):
    analysis, _, _ = case
    for markdown in (errors_markdown(analysis), forces_markdown(analysis)):
        fragment = latex_fragment(markdown, analysis.scene.locale)
        assert "\\documentclass" not in fragment and fragment.startswith("% ")
        assert same_tables(latex_tables(fragment), markdown_tables(markdown))


def test_the_command_line_writes_the_latex_beside_the_markdown(tmp_path):
    out = tmp_path / "out"
    # The pieces whose tables are read: the drawings would add none.
    assert main(["run", "fixtures/ratchet_crank_rocker.toml", "--out", str(out), "--only", "note,errors,forces"]) == 0
    for name in ("note", "errors", "forces"):
        markdown = (out / f"{name}.md").read_text(encoding="utf-8")
        latex = (out / f"{name}.tex").read_text(encoding="utf-8")
        assert same_tables(latex_tables(latex), markdown_tables(markdown))


def typeset(tmp_path: Path, name: str, latex: str) -> tuple[str, Path]:
    """``latex`` typeset by XeLaTeX twice (longtable settles its columns on the second): its log and PDF."""
    source = tmp_path / f"{name}.tex"
    source.write_text(latex, encoding="utf-8")
    for _ in range(2):
        done = subprocess.run([XELATEX, "-interaction=nonstopmode", "-halt-on-error", source.name], cwd=tmp_path,
                              capture_output=True, text=True, timeout=300, check=False)
        log = (tmp_path / f"{name}.log").read_text(encoding="utf-8", errors="replace")
        assert done.returncode == 0, log[-3000:]
    return log, tmp_path / f"{name}.pdf"


def pdf_pages(path: Path) -> list[str]:
    import pypdfium2

    document = pypdfium2.PdfDocument(path)
    try:
        return [page.get_textpage().get_text_range() for page in document]
    finally:
        document.close()


def pdf_text(path: Path) -> str:
    return "".join(pdf_pages(path))


@needs_xelatex
def test_the_note_typesets_with_every_glyph_inside_the_margins(case, typeset_note):
    _, note, latex = case
    log, pdf = typeset_note(latex)
    assert "Missing character" not in log
    assert "Overfull \\hbox" not in log
    assert "Table widths have changed" not in log
    # Every number of every table in the PDF, in the note's order.
    text = "".join(pdf_text(pdf).split())
    for _, rows in markdown_tables(note):
        numbers = [cell for row in rows[1:] for cell in row if re.fullmatch(r"[−\d.,]+", cell)]
        at = 0
        for number in numbers:
            at = text.find(number, at)
            assert at >= 0, number


@needs_xelatex
def test_a_table_running_onto_another_page_says_whose_continuation_it_is(case, typeset_note):
    """GOST 2.105 puts «Продолжение таблицы 3» over the header repeated on each page a table runs onto; a reader
    of page 9 otherwise had a header and numbers with no table to look up."""
    analysis, _, latex = case
    text = strings(analysis.scene.locale)
    _, pdf = typeset_note(latex)
    def pattern(template: str) -> re.Pattern:
        return re.compile(re.escape(template).replace(r"\{number\}", r"(\d+)").replace(r"\ ", r"\s*"))

    continued_line = pattern(text["table_continued"])
    caption_head = pattern(text["table_caption"].split("{caption}")[0])
    marks = []   # (page, "caption" or "continued", table number) in reading order
    for page, page_text in enumerate(pdf_pages(pdf)):
        for line in page_text.splitlines():
            if found := continued_line.fullmatch(line.strip()):
                marks.append((page, "table_continued", int(found[1])))
            elif found := caption_head.match(line.strip()):
                marks.append((page, "table_caption", int(found[1])))
    continued = [mark for mark in marks if mark[1] == "table_continued"]
    assert continued, "the note has no table long enough to run onto another page"
    for k, (page, kind, number) in enumerate(marks):
        if kind == "table_continued":
            last_caption = next(mark for mark in reversed(marks[:k]) if mark[1] == "table_caption")
            assert last_caption[2] == number and last_caption[0] < page, (last_caption, (page, number))


@needs_xelatex
def test_no_page_holds_one_row_of_a_table_alone_nor_a_heading_without_the_table_under_it(tmp_path):
    """The shaper's note left the first row of its table 17 alone at the foot of a page, under its caption and
    header.  Tables of 2 to 13 rows after paragraphs of 1 to 11 lines, some right under a heading, land at every
    height of a page; each page is read back for the rows it holds of each table."""
    blocks, under_heading = ["# Note"], []
    for t in range(1, 41):
        blocks.append(f"## Section {t}")
        if t % 3:
            blocks.append(" ".join(["filler"] * (12 * (t * 7 % 11 + 1))))
        else:
            under_heading.append(t)
        rows = t * 5 % 12 + 2
        blocks.append(f"Table {t}. Rows of table {t}")
        blocks.append("| row | value |\n|---|---:|\n" + "\n".join(f"| r{t}x{k} | {k} |" for k in range(rows)))
    _, pdf = typeset(tmp_path, "rows", latex_document("\n\n".join(blocks), "Note", "en"))
    pages = pdf_pages(pdf)
    held = {}   # table → how many of its rows each page holds
    for page, text in enumerate(pages):
        for t, _ in re.findall(r"\br(\d+)x(\d+)\b", text):
            held.setdefault(int(t), {}).setdefault(page, 0)
            held[int(t)][page] += 1
    assert len(held) == 40 and any(len(on_pages) > 1 for on_pages in held.values())
    for t, on_pages in held.items():
        assert 1 not in on_pages.values(), (t, on_pages)
    for t in under_heading:
        heading_page = next(page for page, text in enumerate(pages) if re.search(rf"Section {t}\b", text))
        assert heading_page == min(held[t]), t


@needs_xelatex
def test_a_fragment_typesets_in_a_document_of_the_user_s(case, tmp_path):
    analysis, _, _ = case
    font = "Noto Sans CJK SC" if analysis.scene.locale == "zh" else "DejaVu Sans"
    fragment = latex_fragment(errors_markdown(analysis), analysis.scene.locale)
    (tmp_path / "errors.tex").write_text(fragment, encoding="utf-8")
    wrapper = ("\\documentclass{article}\n\\usepackage{fontspec}\n\\setmainfont{" + font + "}\n"
               "\\usepackage{array,longtable,booktabs,caption}\n\\begin{document}\n\\input{errors.tex}\n\\end{document}\n")
    log, pdf = typeset(tmp_path, "report", wrapper)
    assert "Missing character" not in log
    assert analysis.scene.title.split()[0] in pdf_text(pdf)


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_a_note_with_a_cjk_name_in_it_is_set_in_the_cjk_font_whatever_its_language(locale, tmp_path):
    scene = graphplan.load("fixtures/ratchet_crank_rocker.toml")
    analysis = analyse(dataclasses.replace(scene, locale=locale, title="棘轮机构: crank-rocker"))
    latex = latex_document(note_markdown(analysis), analysis.scene.title, locale)
    assert "\\newfontfamily{\\notecjkfont}{Noto Sans CJK SC}" in latex and "XeTeXlinebreaklocale" in latex
    assert "\\notecjk{棘轮机构}" in latex
    # Without the ideographs the same note keeps the drawings' Latin and Cyrillic font.
    plain_analysis = analyse(dataclasses.replace(scene, locale=locale))
    assert "\\setmainfont{DejaVu Sans}" in latex_document(note_markdown(plain_analysis), scene.title, locale)
    if XELATEX is None:
        pytest.skip("XeLaTeX is not installed (Debian: texlive-xetex)")
    log, pdf = typeset(tmp_path, "note", latex)
    assert "Missing character" not in log
    assert "棘轮机构" in pdf_text(pdf)


@needs_xelatex
def test_a_russian_note_breaks_its_words_at_syllables_where_tex_has_the_patterns(case, tmp_path, typeset_note):
    analysis, note, latex = case
    if analysis.scene.locale != "ru":
        pytest.skip("Russian only")
    # Whether this TeX has the patterns at all, asked of babel apart from the note's preamble.
    probe = ("\\documentclass{article}\n\\usepackage{fontspec}\n\\setmainfont{DejaVu Sans}\n\\usepackage{babel}\n"
             "\\babelprovide[import,main]{russian}\n\\begin{document}\n\\showhyphens{механизма}\n\\end{document}\n")
    log, _ = typeset(tmp_path, "probe", probe)
    if "ме-ха-низ-ма" not in log:
        pytest.skip("this TeX has no Russian hyphenation patterns (Debian: texlive-lang-cyrillic)")
    _, pdf = typeset_note(latex)
    # PDFium marks a hyphen TeX put at a line's end with U+FFFE; the word joined again is one of the note's.
    broken = re.findall(r"([а-яё]+)\ufffe\s*([а-яё]+)", pdf_text(pdf))
    assert broken
    words = set(re.findall(r"[а-яё]+", note))
    assert all(head + tail in words for head, tail in broken), broken


def characters_fonts(pdf: Path) -> dict[str, set[str]]:
    """Each character of the typeset PDF and the names of the fonts it is set in, read by pdfium (a test
    dependency, as the other PDF checks here)."""
    import ctypes

    import pypdfium2
    import pypdfium2.raw as pdfium_c

    fonts: dict[str, set[str]] = {}
    document = pypdfium2.PdfDocument(pdf)
    try:
        for page in document:
            text = page.get_textpage()
            for index in range(text.count_chars()):
                character = chr(pdfium_c.FPDFText_GetUnicode(text.raw, index))
                size = pdfium_c.FPDFText_GetFontInfo(text.raw, index, None, 0, None)
                name = ctypes.create_string_buffer(size)
                pdfium_c.FPDFText_GetFontInfo(text.raw, index, name, size, None)
                fonts.setdefault(character, set()).add(name.value.decode("utf-8", "replace"))
    finally:
        document.close()
    return fonts


def test_a_chinese_note_sets_only_its_cjk_runs_in_the_cjk_font(tmp_path):
    """Noto Sans CJK SC as the main font set · and × full-width (the quick-return note in Chinese: «ω2 · lOA =
    8 × 0.12») and had no ⁿ: the Latin font is the main one, each run of ideographs and full-width punctuation
    set apart in the CJK font."""
    scene = graphplan.load("fixtures/quick_return_slotted_lever.toml")
    analysis = analyse(dataclasses.replace(scene, locale="zh"))
    note = note_markdown(analysis)
    latex = latex_document(note, analysis.scene.title, "zh")
    assert "\\setmainfont{DejaVu Sans}" in latex and "\\setmainfont{Noto Sans CJK SC}" not in latex
    body = latex.split("\\begin{document}")[1]
    runs = re.findall(r"\\notecjk\{([^{}]*)\}", body)
    assert runs and all(all(is_wide(c) for c in run) for run in runs)
    outside = re.sub(r"\\notecjk\{[^{}]*\}", "", body)
    assert not any(map(is_wide, outside))
    assert "·" in outside and "×" in outside and "→" in outside
    if XELATEX is None:
        pytest.skip("XeLaTeX is not installed (Debian: texlive-xetex)")
    log, pdf = typeset(tmp_path, "note", latex)
    assert "Missing character" not in log
    fonts = characters_fonts(pdf)
    for character in "·×→⊥ωφ":
        assert fonts[character] and all("DejaVu" in font for font in fonts[character]), (character, fonts[character])
    assert all("CJK" in font for font in fonts["机"] | fonts["，"])
