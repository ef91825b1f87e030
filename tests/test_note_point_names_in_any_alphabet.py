"""Points named in Cyrillic or Greek letters (a Russian scheme's О, А, В, С) are set in the note as Latin names
are: their symbols' indices below the line in every format, no caret of the plans' aBA^τ left in any.

The same starter is run with its points named in Latin letters and renamed letter for letter; the English note of
a renamed scene, its letters mapped back, must be the Latin scene's note character for character in Markdown,
LaTeX and Word (the English note writes no Cyrillic or Greek of its own in these letters).
"""

from __future__ import annotations

import io
import re
import tomllib
import zipfile

import docx
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.report.latex import latex_document
from graphplan.report.note import note_html, note_markdown
from graphplan.report.word import note_docx
from graphplan.starters import starter

# The starters' point names, renamed: a Russian student's letters (О, А, В, С look Latin, Д does not), and
# Greek capitals whose small letters the English note never writes.
ALPHABETS = {"cyrillic": {"O": "О", "A": "А", "B": "В", "C": "С", "D": "Д", "S4": "Ц4"},
             "greek": {"O": "Ξ", "A": "Γ", "B": "Χ", "C": "Κ", "D": "Ι", "S4": "Ζ4"}}
# The crank-rocker's tangential components, and the slotted lever's block and lever (A3, A4: aA4A3ᵏ, aA4A3ʳ).
STARTERS = ("crank-rocker", "slotted-lever")


def _renamed(value, names: dict[str, str]):
    """The scene's tables with every point named anew, as a key and as a string."""
    if isinstance(value, dict):
        return {names.get(key, key): _renamed(item, names) for key, item in value.items()}
    if isinstance(value, list):
        return [_renamed(item, names) for item in value]
    return names.get(value, value) if isinstance(value, str) else value


def _outputs(kind: str, locale: str, names: dict[str, str]) -> dict[str, str]:
    tables = _renamed(tomllib.loads(starter(kind, locale)), names)
    analysis = analyse(graphplan.load(tables))
    note = note_markdown(analysis)
    word = note_docx(note, analysis.scene.title, locale)
    document = docx.Document(io.BytesIO(word))
    # Each run of the Word document with how it is set, so that a flat VА and a subscripted А differ.
    runs = "\n".join(f"{run.font.subscript}|{run.font.superscript}|{run.text}"
                     for paragraph in document.paragraphs for run in paragraph.runs)
    with zipfile.ZipFile(io.BytesIO(word)) as package:
        xml = package.read("word/document.xml").decode()
    return {"md": note, "html": note_html(analysis, markdown=note),
            "tex": latex_document(note, analysis.scene.title, locale), "docx": runs, "docx-xml": xml}


def _letters_back(names: dict[str, str]) -> dict[int, str]:
    """The renamed letters, capital and small (the plans' letters), mapped back to the Latin ones."""
    back = {}
    for latin, renamed in names.items():
        for got, wanted in zip(renamed, latin):
            back[ord(got)] = wanted
            back[ord(got.lower())] = wanted.lower()
    return back


@pytest.fixture(scope="module", params=STARTERS)
def latin(request):
    return request.param, _outputs(request.param, "en", {})


@pytest.mark.parametrize("alphabet", ALPHABETS)
def test_a_note_of_renamed_points_is_the_latin_note_letter_for_letter_in_every_format(latin, alphabet):
    kind, wanted = latin
    names = ALPHABETS[alphabet]
    got = _outputs(kind, "en", names)
    back = _letters_back(names)
    for form in ("md", "tex", "docx"):
        assert got[form].translate(back) == wanted[form], form


@pytest.mark.parametrize("kind", STARTERS)
def test_a_russian_note_of_cyrillic_points_sets_their_indices_and_writes_no_caret(kind):
    got = _outputs(kind, "ru", ALPHABETS["cyrillic"])
    for form in ("md", "html", "tex", "docx-xml"):
        assert "^" not in got[form], form
    assert "textasciicircum" not in got["tex"]
    tex = got["tex"]
    assert r"V\textsubscript{А} = ω\textsubscript{2}·l\textsubscript{ОА}" in tex
    # No symbol of a point named in Cyrillic is left flat: a V, a or l before a capital is set with an index.
    assert re.findall(r"(?<![A-Za-z\\])[Val][А-Я]", tex) == []
    if kind == "crank-rocker":
        assert r"a\textsubscript{ВА}\textsuperscript{τ}" in tex
        assert "True|False|ВА\nFalse|True|τ" in got["docx"]
    else:
        assert r"a\textsubscript{А4А3}\textsuperscript{k}" in tex and r"a\textsubscript{А4А3}\textsuperscript{r}" in tex
