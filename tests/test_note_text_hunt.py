"""What a user writes is shown as written, and the command line refuses what it can before it analyses.

The note is written once as Markdown and every other format (HTML, the PDF typeset from it, LaTeX, Word) is read
from that Markdown's syntax tree: a title with Markdown in it (``Project #3 *draft*``) came out in italics, with
a link and a code span, in all of them.  Each format is read back here with a reader of its own: the HTML with
Python's parser, the PDF with PDFium, the Word document with python-docx.
"""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path

import pytest
from scene_texts import central_slider_crank

from graphplan import load_text
from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.mechanism import build

# Every character CommonMark reads as markup somewhere in a line, and the HTML's and LaTeX's own.
TITLE = r"Project #3 *draft* of `x` [a](b) <b>bold</b> & A|B __u__ \ 50% ~ $1 {c} ^2 !x"
AUTHOR = "J. *Doe* [student] | group_7"


def _toml_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _scene_text(title: str) -> str:
    """A small slider-crank titled ``title`` (a TOML string as written in the file), with one plan."""
    head = f'[scene]\ntitle = {title}\nlocale = "en"\ngravity = 0.0\n[project]\nauthor = {_toml_string(AUTHOR)}\n'
    return (central_slider_crank(0.1, 0.4, 10.0).replace("[scene]\ngravity = 0.0\n", head, 1)
            + "[positions]\ncount = 4\nplans = [1]\n")


def _run(tmp_path: Path, formats: str = "svg", title: str = _toml_string(TITLE)) -> Path:
    scene = tmp_path / "scene.toml"
    scene.write_text(_scene_text(title), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note,errors", "--format", formats]) == 0
    return out


AWKWARD = [TITLE, AUTHOR, "1. Faculty of machines", "2) group", "- a list?", "+ plus", "> quoted", "~~~ fence",
           "```", "=====", "---", "***", "#", "Title #", "R&D &amp; &copy;", "<http://x.org>", "a<b", "a^r and aBA^τ",
           "x_1_ _y_ __z__", "a\\*b\\", "    four spaces", "|", "cell | cell", "![x](y.svg)", "[a]: /url"]


@pytest.mark.parametrize("text", AWKWARD)
def test_literal_text_reads_back_as_written_in_a_heading_a_line_s_start_and_a_cell(text):
    """Read back by markdown-it's CommonMark with tables, as the note's writers read it, and through ``raised``,
    which the whole note goes through."""
    from markdown_it import MarkdownIt
    from markdown_it.tree import SyntaxTreeNode

    from graphplan.report.markdown import literal
    from graphplan.wording import raised

    def read(markdown: str) -> list[tuple[str, str]]:
        """Each block's type and its inline's text, made of nothing but text and breaks."""
        tree = SyntaxTreeNode(MarkdownIt("commonmark").enable("table").parse(raised(markdown)))
        found = []
        for node in tree.walk():
            if node.type == "inline":
                assert {child.type for child in node.children} <= {"text", "softbreak", "hardbreak"}, markdown
                found.append((node.parent.type, "".join(child.content or " " for child in node.children)))
        return found

    shown = " ".join(text.split())
    assert read(f"# Explanatory note: {literal(text)}") == [("heading", f"Explanatory note: {shown}")]
    # The project's lines, the organisation's alone on its own (a hard break ends the line before it).
    assert read(f"Author: A\\\n{literal(text)}\\\nDate: 1") == [("paragraph", f"Author: A {shown} Date: 1")]
    assert read(f"| a | b |\n|---|---|\n| {literal(text)} | c |") == [("th", "a"), ("th", "b"), ("td", shown),
                                                                     ("td", "c")]


class _Elements(HTMLParser):
    """The text of each element named in ``tags`` and the tags found inside it."""

    def __init__(self, tags: tuple[str, ...]) -> None:
        super().__init__()
        self.tags = tags
        self.texts: list[str] = []
        self.inner: list[list[str]] = []
        self._depth = 0

    def handle_starttag(self, tag, attrs):
        if tag in self.tags and not self._depth:
            self.texts.append("")
            self.inner.append([])
            self._depth = 1
        elif self._depth:
            self.inner[-1].append(tag)

    def handle_endtag(self, tag):
        if tag in self.tags:
            self._depth = 0

    def handle_data(self, data):
        if self._depth:
            self.texts[-1] += data


def test_the_title_and_project_markdown_is_shown_as_written_in_the_markdown_and_html_notes(tmp_path):
    out = _run(tmp_path)
    page = (out / "note.html").read_text(encoding="utf-8")
    heading = _Elements(("h1",))
    heading.feed(page)
    assert heading.texts == [f"Explanatory note: {TITLE}"]
    # No emphasis, code, link or strong made of the title's characters.
    assert heading.inner == [[]]
    paragraphs = _Elements(("p",))
    paragraphs.feed(page)
    assert f"Author: {AUTHOR}" in paragraphs.texts
    # The Markdown itself, read by a CommonMark reader, says the same.
    from markdown_it import MarkdownIt

    tokens = MarkdownIt("commonmark").enable("table").parse((out / "note.md").read_text(encoding="utf-8"))
    inline = tokens[1]
    assert tokens[0].tag == "h1" and [child.type for child in inline.children] == ["text"]
    assert inline.children[0].content == f"Explanatory note: {TITLE}"
    # The error tables' own heading too.
    errors = (out / "errors.md").read_text(encoding="utf-8").splitlines()[0]
    tokens = MarkdownIt("commonmark").parse(errors)
    assert [child.type for child in tokens[1].children] == ["text"] and TITLE in tokens[1].children[0].content


def test_the_title_is_shown_as_written_in_the_latex_note(tmp_path):
    tex = (_run(tmp_path) / "note.tex").read_text(encoding="utf-8")
    title_line = next(line for line in tex.splitlines() if "Explanatory note" in line and "bfseries" in line)
    # Nothing of the title set in italics, bold or typewriter; its characters each escaped as LaTeX wants.
    assert "\\textit" not in title_line and "\\texttt" not in title_line and "\\textbf" not in title_line
    assert "\\#3" in title_line and "\\&" in title_line and "\\%" in title_line and "\\$1" in title_line


def test_the_title_is_shown_as_written_in_the_word_and_pdf_notes(tmp_path):
    docx = pytest.importorskip("docx")
    pdfium = pytest.importorskip("pypdfium2")
    try:
        import weasyprint  # noqa: F401
    except (ImportError, OSError) as error:  # OSError: no Pango library
        pytest.skip(f"WeasyPrint cannot typeset here: {error}")
    out = _run(tmp_path, "pdf,docx")
    document = docx.Document(str(out / "note.docx"))
    first = next(paragraph for paragraph in document.paragraphs if paragraph.text.strip())
    assert first.text == f"Explanatory note: {TITLE}"
    assert not any(run.italic or run.font.name == "Courier New" for run in first.runs)
    pdf = pdfium.PdfDocument(str(out / "note.pdf"))
    text = pdf[0].get_textpage().get_text_range()
    squeezed = re.sub(r"\s+", "", text)
    assert re.sub(r"\s+", "", f"Explanatory note: {TITLE}") in squeezed


def test_a_title_on_several_lines_is_one_line_of_the_note(tmp_path):
    """A TOML multi-line string holds a long title as it is typed; the note's heading is one line (its second
    line was a paragraph of its own): the line breaks and the spaces round them read as one space."""
    multiline = '"""Crank-rocker\n   of a *ratchet*\r\n# feed"""'
    out = _run(tmp_path, title=multiline)
    heading = _Elements(("h1",))
    heading.feed((out / "note.html").read_text(encoding="utf-8"))
    assert heading.texts == ["Explanatory note: Crank-rocker of a *ratchet* # feed"]
    assert (out / "note.md").read_text(encoding="utf-8").startswith("# Explanatory note: Crank-rocker of a ")


def _analysis_refused(*args, **kwargs):
    raise AssertionError("the run analysed the scene before it refused its --out")


@pytest.mark.parametrize("inside", [False, True], ids=["a file", "a path through a file"])
def test_an_out_that_is_a_file_is_refused_before_the_analysis(tmp_path, monkeypatch, capsys, inside):
    import graphplan.analysis

    scene = tmp_path / "scene.toml"
    scene.write_text(_scene_text(_toml_string("Small")), encoding="utf-8")
    file = tmp_path / "report"
    file.write_text("the user's own", encoding="utf-8")
    out = file / "sub" if inside else file
    monkeypatch.setattr(graphplan.analysis, "analyse", _analysis_refused)
    assert main(["run", str(scene), "--out", str(out)]) == 2
    told = capsys.readouterr().err.strip().splitlines()
    assert told[-1] == (f"graphplan: error: {out}: {file} is not a folder, so the output cannot go in it; give --out "
                        "a folder elsewhere" if inside
                        else f"graphplan: error: {out}: exists and is not a folder; give --out a folder")
    # Nothing written beside it, the file as it was.
    assert sorted(path.name for path in tmp_path.iterdir()) == ["report", "scene.toml"]
    assert file.read_text(encoding="utf-8") == "the user's own"


def test_the_notebook_s_write_refuses_a_file_before_the_analysis_too(tmp_path, monkeypatch):
    import graphplan.analysis
    from graphplan.errors import OutputError
    from graphplan.scene import load

    scene = tmp_path / "scene.toml"
    scene.write_text(_scene_text(_toml_string("Small")), encoding="utf-8")
    file = tmp_path / "report"
    file.write_text("", encoding="utf-8")
    monkeypatch.setattr(graphplan.analysis, "analyse", _analysis_refused)
    with pytest.raises(OutputError, match="exists and is not a folder"):
        load(scene).write(file)


def test_a_repeated_format_or_only_adds_to_the_list_as_a_comma_would(tmp_path):
    """``--format`` and ``--only`` take comma-separated lists; given twice, the first list was dropped unsaid."""
    scene = tmp_path / "scene.toml"
    scene.write_text(_scene_text(_toml_string("Small")), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "positions", "--only", "note",
                 "--format", "png", "--format", "dxf"]) == 0
    written = {path.name for path in out.iterdir()}
    assert {"positions.svg", "positions.png", "positions.dxf", "note.md"} <= written


def test_a_rotor_s_mass_and_plane_names_are_shown_as_typed(tmp_path):
    """A rotor's masses and correction planes are named by the user: a mass named c|d split its table's row, and
    planes named _L_ and `R` were set in italics and as code in every sentence and formula that names them."""
    from graphplan.starters import starter

    text = starter("rotor", "en")
    text = text.replace("{ mass = 18.0,", '{ name = "a*b*", mass = 18.0,', 1)
    text = text.replace("{ mass = 14.0,", '{ name = "c|d", mass = 14.0,', 1)
    text = re.sub(r"(?m)^planes = \[0\.04, 0\.22\]", 'planes = [0.04, 0.22]\nplane_names = ["_L_", "`R`"]', text)
    assert text.count("a*b*") == text.count("c|d") == text.count("plane_names") == 1
    scene = tmp_path / "rotor.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "balancing,note"]) == 0
    page = (out / "note.html").read_text(encoding="utf-8")
    cells, paragraphs = _Elements(("td", "th")), _Elements(("p",))
    cells.feed(page)
    paragraphs.feed(page)
    assert {"a*b*", "c|d", "(m·r)a*b*", "(m·r)c|d", "share in _L_", "(m·r)`R`, kg·m"} <= set(cells.texts)
    # Every row of the masses' table as long as its header.
    rows = [row for row in (out / "note.md").read_text(encoding="utf-8").splitlines() if row.startswith("| ")]
    assert all(len(re.split(r"(?<!\\)\|", row)) == 8 for row in rows)
    assert any(line.startswith("Plane _L_: ((m·r)a*b*)_L_ + ((m·r)c|d)_L_ + (m3r3)_L_ + (m·r)_L_ = 0")
               for line in paragraphs.texts)
    assert any("correction mass is m`R` = " in line for line in paragraphs.texts)
    assert not any(tag in ("em", "code") for inner in cells.inner + paragraphs.inner for tag in inner)



def test_the_user_s_own_text_is_plain_where_it_holds_a_symbol_s_shape_and_the_note_s_symbols_are_not():
    from graphplan.report.symbols import Symbol, pieces

    said = "Press F1: the force F1 and M12"
    assert list(pieces(said, ["Press F1"])) == ["Press F1: the force ", Symbol("F", "1", ""), " and ",
                                                 Symbol("M", "12", "")]
    # A text is the user's where it stands whole: a title "M" is not the M of M12, nor of the word "Mass".
    assert list(pieces("M12 and M", ["M"])) == [Symbol("M", "12", ""), " and M"]
    assert list(pieces(said)) == ["Press ", Symbol("F", "1", ""), ": the force ", Symbol("F", "1", ""), " and ",
                                  Symbol("M", "12", "")]


def test_a_title_and_author_shaped_like_symbols_are_set_as_typed_in_html_latex_and_word(tmp_path):
    """A title "Press F1 of line M3" came out in the HTML, LaTeX and Word notes as a force F with an index 1 and a
    moment M with an index 3: the symbol pass read the user's text as the textbook's."""
    docx = pytest.importorskip("docx")
    title = "Press F1 of line M3"
    out = _run(tmp_path, "docx", title=_toml_string(title))
    page = (out / "note.html").read_text(encoding="utf-8")
    heading = _Elements(("h1",))
    heading.feed(page)
    assert heading.texts == [f"Explanatory note: {title}"] and heading.inner == [[]]
    # The note's own symbols are still set with their indices.
    assert "F<sub>" in page or "M<sub>" in page or "V<sub>" in page
    tex = (out / "note.tex").read_text(encoding="utf-8")
    title_line = next(line for line in tex.splitlines() if "Explanatory note" in line and "bfseries" in line)
    assert title in title_line and "textsubscript" not in title_line
    assert "\\textsubscript" in tex
    errors_tex = (out / "errors.tex").read_text(encoding="utf-8")
    assert title in errors_tex
    document = docx.Document(str(out / "note.docx"))
    first = next(paragraph for paragraph in document.paragraphs if paragraph.text.strip())
    assert first.text == f"Explanatory note: {title}"
    assert not any(run.font.subscript for run in first.runs)
    assert any(run.font.subscript for paragraph in document.paragraphs for run in paragraph.runs)


# matplotlib reads text between two dollars as mathtext: "$5 to $10" came out in italics, and "$\\frac$" (no
# numerator) stopped the run with a parser's traceback.
MATHTEXT_TITLE = r"Press $\frac$ costs $5 to $10"


def _drawn_by(monkeypatch, module, name: str) -> list:
    """The figures ``module.name`` returns while a run draws them."""
    drawn, drawing = [], getattr(module, name)
    monkeypatch.setattr(module, name, lambda *args, **kwargs: drawn.append(drawing(*args, **kwargs)) or drawn[-1])
    return drawn


def test_a_title_with_dollars_is_plain_text_in_the_motion_plot(tmp_path, monkeypatch):
    from graphplan.report import motion_plots
    from graphplan.starters import starter

    text = re.sub(r"(?m)^title\s*=.*$", lambda _: f"title = {_toml_string(MATHTEXT_TITLE)}", starter("flywheel", "en"),
                  count=1)
    scene = tmp_path / "flywheel.toml"
    scene.write_text(text, encoding="utf-8")
    drawn = _drawn_by(monkeypatch, motion_plots, "motion_plot")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    (figure,) = drawn
    assert MATHTEXT_TITLE in figure._suptitle.get_text() and not figure._suptitle.get_parse_math()


def test_a_title_with_dollars_is_plain_text_in_the_balancing_figure(tmp_path, monkeypatch):
    from graphplan.report import figures

    ratchet = (Path(__file__).parents[1] / "fixtures" / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    scene = tmp_path / "scene.toml"
    scene.write_text(re.sub(r"(?m)^title\s*=.*$", lambda _: f"title = {_toml_string(MATHTEXT_TITLE)}", ratchet,
                            count=1), encoding="utf-8")
    drawn = _drawn_by(monkeypatch, figures, "_balancing_figure")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "positions", "--figures"]) == 0
    (figure,) = drawn
    (title,) = {axes.title for axes in figure.axes if axes.get_title()}
    assert title.get_text() == MATHTEXT_TITLE and not title.get_parse_math()


def test_a_title_with_dollars_is_plain_text_in_the_accuracy_plot(tmp_path, monkeypatch):
    from graphplan.report import accuracy

    scene = tmp_path / "scene.toml"
    scene.write_text(_scene_text(_toml_string(MATHTEXT_TITLE)), encoding="utf-8")
    drawn = []
    monkeypatch.setattr(accuracy, "svg_text", lambda figure: drawn.append(figure) or "<svg/>")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "accuracy"]) == 0
    ((axes,),) = [figure.axes for figure in drawn]
    assert axes.title.get_text().startswith(MATHTEXT_TITLE + "\n") and not axes.title.get_parse_math()

@pytest.mark.parametrize(("name", "shown"), [("E*x*", "'*'"), ("S_2", "'_'"), ("a|b", "'|'"), ("E`1`", "'`'"),
                                             ("E 1", "a space"), ("E[1]", "'[', ']'")])
def test_a_point_name_the_note_would_read_as_markup_is_refused_at_its_key(name, shown):
    # A point's name is built into a hundred symbols and equations of the note (VE, lSE, ps2 = pa·lOS2/lOA): a
    # '*' there set the rest of the line in italics, a '|' split the table's row.  Refused where it is named.
    point = f'[points]\n"{name}" = {{ link = 3, from = "A", toward = "B", at = 0.5 }}\n'
    text = central_slider_crank(0.1, 0.4, 10.0) + point
    with pytest.raises(SceneError) as refused:
        build(load_text(text))
    assert refused.value.where in (f"points.{name}", f'points."{name}"')
    assert f"holds {shown}, which the note's equations and tables would read as markup" in str(refused.value)


def test_a_point_name_in_another_script_with_primes_is_kept():
    text = central_slider_crank(0.1, 0.4, 10.0) + '[points]\n"Е′1" = { link = 3, from = "A", toward = "B", at = 0.5 }\n'
    assert [spec.name for spec in build(load_text(text)).scene.points] == ["Е′1"]


def _slider_crank_on_a_frame_line(line_name: str) -> str:
    line = f'lines = {{ "{line_name}" = {{ through = "O", angle = 0.0 }} }}'
    on_a_line = central_slider_crank(0.1, 0.4, 10.0).replace("points = { O = [0.0, 0.0] }",
                                                              "points = { O = [0.0, 0.0] }\n" + line)
    return on_a_line.replace('guide = { through = "O", angle = 0.0 }', f'guide = "{line_name}"')


def test_a_frame_line_name_the_note_would_read_as_markup_is_refused_and_one_with_a_space_kept():
    # The note names a guide's line in its tables and lines of action ("∥ ram"): 'r*a*m' came out as r<em>a</em>m.
    with pytest.raises(SceneError) as refused:
        build(load_text(_slider_crank_on_a_frame_line("r*a*m")))
    assert refused.value.where.startswith("frame.lines.") and "holds '*'" in str(refused.value)
    assert "ram guide" in build(load_text(_slider_crank_on_a_frame_line("ram guide"))).scene.frame_lines
