"""The note's tables and figures as GOST 2.105 and 7.32 want them found: each referred to by its number in the text
before it, and a table split into parts naming every part after the first as the first's continuation; and its
symbols' components raised without a caret.

Each format is read back by its own means: the Markdown by markdown-it-py's tokens, the HTML by its elements,
the LaTeX by its longtables, the Word document by python-docx, in the order of its body.
"""

from __future__ import annotations

import dataclasses
import io
import re
from html import unescape

import pytest
from docx import Document
from docx.text.paragraph import Paragraph
from markdown_it import MarkdownIt
from pylatexenc.latex2text import LatexNodes2Text

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.report.latex import latex_document
from graphplan.report.note import note_html, note_markdown
from graphplan.report.word import note_docx

LOCALES = ("en", "ru", "zh")


def template(text: str) -> re.Pattern:
    """A locale's caption template as a pattern, its number caught."""
    return re.compile(re.escape(text).replace(r"\ ", r"\s*").replace(r"\{number\}", r"(\d+)").replace(r"\{caption\}", ".*")
                      .replace(r"\{part\}", r"\d+").replace(r"\{count\}", r"\d+"))


@pytest.fixture(scope="module", params=LOCALES)
def every_velocity_plan(request):
    """The shaper with the velocity plans of all twelve positions: their table in two parts of six."""
    scene = graphplan.load("fixtures/shaper_six_bar.toml")
    positions = dataclasses.replace(scene.positions, velocity_plans=tuple(range(1, 13)))
    analysis = analyse(dataclasses.replace(scene, locale=request.param, positions=positions))
    return analysis, note_markdown(analysis)


def markdown_tables(note: str) -> list[str | None]:
    """The paragraph right before each table of the Markdown (None where there is none), in order."""
    tokens = MarkdownIt("commonmark").enable("table").parse(note)
    return [tokens[k - 2].content if tokens[k - 1].type == "paragraph_close" else None
            for k, token in enumerate(tokens) if token.type == "table_open"]


def docx_tables(document: bytes) -> list[str | None]:
    """The paragraph right before each table of the Word document, in the order of its body."""
    document = Document(io.BytesIO(document))
    before, found = None, []
    for element in document.element.body.iterchildren():
        tag = element.tag.rsplit("}", 1)[-1]
        if tag == "tbl":
            found.append(before)
        before = Paragraph(element, document).text if tag == "p" else None
    return found


def test_a_table_split_into_parts_names_each_part_after_the_first_its_continuation(every_velocity_plan):
    analysis, note = every_velocity_plan
    text = strings(analysis.scene.locale)
    caption, continued = template(text["table_caption"]), template(text["table_continued"])
    befores = markdown_tables(note)
    # The tables' numbers counted here: each paragraph over a table that is a caption is the next number.
    numbers, count = [], 0
    for before in befores:
        if before is not None and caption.fullmatch(before):
            count += 1
            assert int(caption.fullmatch(before)[1]) == count
        numbers.append(count)
    heading = text["table_caption"].format(number=r"(\d+)", caption=text["velocity_plans_heading"])
    first = next(k for k, before in enumerate(befores) if before and re.fullmatch(heading, before))
    number = numbers[first]
    # The twelve positions in two parts: the second under «Продолжение таблицы N», no caption of its own.
    assert befores[first + 1] == text["table_continued"].format(number=number)
    assert continued.fullmatch(befores[first + 1]) and numbers[first + 1] == number
    assert not any(before and continued.fullmatch(before) for k, before in enumerate(befores) if k != first + 1)
    wanted = text["table_continued"].format(number=number)

    html = note_html(analysis, markdown=note)
    assert re.search(rf'<p class="table-caption">{re.escape(wanted)}</p>\s*<table', html)

    latex = latex_document(note, analysis.scene.title, analysis.scene.locale)
    captions = re.findall(r"\\begin\{longtable\}[^\n]*\n\\caption\*\{(.*)\}\\\\\n", latex)
    assert captions.count(_latex(wanted)) == 1
    # Over the rows it runs onto another page, the continued part is said to be table N's.
    part = latex.split(f"\\caption*{{{_latex(wanted)}}}")[1].split("\\end{longtable}")[0]
    assert f"{{{_latex(wanted)}}}\\\\\n\\toprule" in part

    def captions_only(befores: list[str | None]) -> list[str | None]:   # a symbol's index is no text in Word
        return [before if before and (caption.fullmatch(before) or continued.fullmatch(before)) else None
                for before in befores]

    docx = docx_tables(note_docx(note, analysis.scene.title, analysis.scene.locale))
    assert captions_only(docx) == captions_only(befores)


def _latex(words: str) -> str:
    """Words as the LaTeX note writes them: each run of CJK characters marked for its font."""
    return re.sub(r"([\u3000-\u9fff\uff00-\uffef]+)", r"\\notecjk{\1}", words)


@pytest.mark.parametrize("locale", LOCALES)
def test_the_markdown_raises_its_components_with_no_caret_and_the_other_formats_still_raise_them(locale):
    """note.md wrote «aEDⁿ + aED^τ», «aBB1^r», «ε = a^τ/l»: a Markdown viewer shows the caret.  The components are
    counted here in the Markdown (r as ʳ, τ after an index or an a, as R23τ; R23n's n too), and each is a superscript in the
    HTML, the LaTeX and the Word document."""
    scene = graphplan.load("fixtures/shaper_six_bar.toml")   # two sliding pairs: relative and Coriolis terms
    analysis = analyse(dataclasses.replace(scene, locale=locale))
    note = note_markdown(analysis)
    assert "^" not in note
    assert "ʳ" in note and "ⁿ" in note and "ᵏ" in note and re.search(r"aτ/l", note)
    counts = {"r": note.count("ʳ"), "n": note.count("ⁿ") + len(re.findall(r"(?<![A-Za-z])R\d+n(?![A-Za-z0-9])", note)),
              "k": note.count("ᵏ"),
              "τ": len(re.findall(r"(?:[A-Z0-9Σ]|(?<![A-Za-z])a)τ(?![A-Za-z0-9])", note))}
    assert counts["r"] > 5 and counts["τ"] > 5

    html = note_html(analysis, markdown=note)
    assert {letter: html.count(f"<sup>{letter}</sup>") for letter in counts} == counts
    latex = latex_document(note, analysis.scene.title, locale)
    assert {letter: latex.count(f"\\textsuperscript{{{letter}}}") for letter in counts} == counts
    document = Document(io.BytesIO(note_docx(note, analysis.scene.title, locale)))
    raised = [run.text for paragraph in document.paragraphs for run in paragraph.runs if run.font.superscript]
    raised += [run.text for table in document.tables for row in table.rows for cell in row.cells
               for paragraph in cell.paragraphs for run in paragraph.runs if run.font.superscript]
    assert {letter: raised.count(letter) for letter in counts} == counts


# Drawings the run would write beside the note, each a blank sheet: the note shows them as figures.
DRAWINGS = ("positions.svg", "plan_3.svg", "plan_10.svg", "diagrams.svg", "forces_3.svg", "forces_10.svg",
            "balancing.svg")
BLANK = ('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="60mm" viewBox="0 0 100 60">'
         '<rect x="1" y="1" width="98" height="58" fill="none" stroke="black"/></svg>')


def sequence(lines: list[str], text) -> list[tuple[str, str, int]]:
    """What each line is, in order: ("caption" or "lead", "table" or "figure", number); other lines left out."""
    leads = {kind: [template(text[key]) for key in keys] for kind, keys in
             (("table", ("table_lead", "note_groups_lead", "note_data_masses_table_lead", "note_data_table_lead")), ("figure", ("figure_lead", "plot_lead")))}
    # A vector equation's and a force polygon's paragraph ends with the sentence that refers to its table.
    leads["table"] += [re.compile(".*" + template(text[key]).pattern)
                       for key in ("note_equation_table_lead", "note_polygon_table_lead")]
    captions = {kind: re.compile(template(text[f"{kind}_caption"]).pattern.removesuffix(".*"))
                for kind in ("table", "figure")}
    found = []
    for line in lines:
        line = " ".join(line.split())
        for kind in ("table", "figure"):
            if caption := captions[kind].match(line):
                found.append(("caption", kind, int(caption[1])))
            elif lead := next((match for pattern in leads[kind] if (match := pattern.fullmatch(line))), None):
                found.append(("lead", kind, int(lead[1])))
    return found


@pytest.mark.parametrize("locale", LOCALES)
def test_every_table_and_figure_is_referred_to_by_its_number_before_it_in_every_format(locale):
    """GOST 2.105 and 7.32: each table and figure is referred to in the text before it.  The shaper's note had
    12 figures and 31 tables and not one «рисунок 2» or «таблица 3»."""
    scene = graphplan.load("fixtures/shaper_six_bar.toml")
    analysis = analyse(dataclasses.replace(scene, locale=locale))
    note = note_markdown(analysis, figures=DRAWINGS)
    text = strings(locale)
    blocks = [block for block in note.split("\n\n") if not block.startswith(("|", "#", "!["))]
    order = sequence(blocks, text)
    # Counted here: the captions number the tables and the figures 1, 2, 3, ... each (a figure in parts under one).
    for kind in ("table", "figure"):
        numbers = list(dict.fromkeys(number for what, k, number in order if what == "caption" and k == kind))
        assert numbers == list(range(1, len(numbers) + 1)) and len(numbers) >= (10 if kind == "table" else 5)
        if kind == "table":   # a numbered table is a table of the Markdown, its parts one
            assert len(numbers) <= len(re.findall(r"^\|---", note, flags=re.MULTILINE))
        else:
            assert len(numbers) == len(DRAWINGS)
    # Each caption's number referred to before it, by a sentence that is no caption.
    referred = set()
    for what, kind, number in order:
        if what == "lead":
            referred.add((kind, number))
        else:
            assert (kind, number) in referred, (kind, number)

    html = note_html(analysis, markdown=note)
    html_lines = [unescape(re.sub(r"<[^>]+>", "", found[1]))
                  for found in re.finditer(r"<(?:p|figcaption)[^>]*>(.*?)</(?:p|figcaption)>", html, re.DOTALL)]
    assert sequence(html_lines, text) == order
    # A page break never parts a reference from what it refers to (nor the heading over it from either).
    refers = [unescape(re.sub(r"<[^>]+>", "", found)) for found in re.findall(r'<p class="refers">(.*?)</p>', html)]
    assert sequence(refers, text) == [item for item in order if item[0] == "lead"]

    latex = latex_document(note, analysis.scene.title, locale).split("\\begin{document}")[1]
    to_text = LatexNodes2Text()
    latex_lines = [to_text.latex_to_text(line.removeprefix("\\caption*{").removesuffix("}\\\\"))
                   for line in latex.splitlines()]
    assert sequence(latex_lines, text) == order

    document = Document(io.BytesIO(note_docx(note, analysis.scene.title, locale, {name: BLANK for name in DRAWINGS})))
    assert sequence([paragraph.text for paragraph in document.paragraphs], text) == order
    leads = [paragraph for paragraph in document.paragraphs if sequence([paragraph.text], text)[:1]
             and sequence([paragraph.text], text)[0][0] == "lead"]
    assert len(leads) == sum(item[0] == "lead" for item in order)
    assert all(paragraph.paragraph_format.keep_with_next for paragraph in leads)
