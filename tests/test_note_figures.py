"""The explanatory note shows the drawings and plots a run writes beside it, each in the section it illustrates.

The shaper starter has every kind of drawing of a linkage (plan of positions, plan sheets, the velocity plans of
every position, kinematic diagrams, force sheets with and without friction, the dynamics and the motion); the
rotor starter the balancing polygons and the vibration plots.  Each figure is checked against the files the
run wrote: in the Markdown as a picture and its numbered caption, in the HTML as a figure, in the PDF and the
LaTeX document as the drawing itself (its own lettering found on the page of the caption), in the Word
document as a picture of the drawing's proportions.
"""

from __future__ import annotations

import io
import re
import shutil
import subprocess
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main
from graphplan.render.export import svg_size_mm
from graphplan.starters import starter

pdfium = pytest.importorskip("pypdfium2")

# A figure in the note's Markdown: the picture alone in its paragraph, its caption the paragraph under it.
FIGURE = re.compile(r"^!\[([^\]]*)\]\(([^)]+)\)\n\n(.*)$", re.MULTILINE)
TEXT_WIDTH_MM = 170.0


def run(folder: Path, kind: str, *options: str) -> Path:
    scene = folder / f"{kind}.toml"
    scene.write_text(starter(kind), encoding="utf-8")
    out = folder / "out"
    assert main(["run", str(scene), "--out", str(out), *options]) == 0
    return out


@pytest.fixture(scope="module")
def shaper(tmp_path_factory) -> Path:
    return run(tmp_path_factory.mktemp("shaper"), "shaper", "--format", "pdf,docx")


def figures(note: str) -> list[tuple[str, str, str]]:
    return FIGURE.findall(note)


def heading_above(note: str, file: str, level: int) -> str:
    """The last heading of ``level`` before the figure of ``file``."""
    before = note[:note.index(f"]({file})")]
    return re.findall(rf"^{'#' * level} (.*)$", before, re.MULTILINE)[-1]


def pages_with(pdf_path: Path, words: str) -> list[str]:
    document = pdfium.PdfDocument(str(pdf_path))
    texts = [document[k].get_textpage().get_text_range() for k in range(len(document))]
    return [text for text in texts if words in text]


SVG = "{http://www.w3.org/2000/svg}"
PART = re.compile(r"^(.*)-(\d+)\.svg$")


def shown_as(file: str, folder: Path) -> str:
    """The picture the note shows for a drawing: itself, or the first of the parts it is cut into for the note."""
    first = f"{file.removesuffix('.svg')}-1.svg"
    return first if (folder / first).is_file() else file


def test_every_drawing_and_plot_written_is_a_numbered_figure_in_its_section(shaper):
    note = (shaper / "note.md").read_text(encoding="utf-8")
    found = figures(note)
    written = {path.name for path in shaper.glob("*.svg") if not path.name.startswith("sheet_")}
    # A drawing cut into parts for the note is shown part by part, not whole.
    parted = {f"{PART.match(name)[1]}.svg" for name in written if PART.match(name)}
    assert parted >= {"forces_3.svg", "forces_10.svg"}
    assert [file for _, file, _ in found] and {file for _, file, _ in found} == written - parted
    number = 0
    for alt, file, caption in found:
        part = PART.match(file)
        if part is None or part[2] == "1":   # the parts of one drawing are one figure
            number += 1
        assert caption == f"Figure {number}. {alt}"
        assert (shaper / file).is_file()
    for position in (3, 10):
        for file in (f"plan_{position}.svg", f"forces_{position}.svg", f"forces_friction_{position}.svg"):
            assert heading_above(note, shown_as(file, shaper), 3).split(": ")[0].endswith(f"Position {position}")
    assert heading_above(note, shown_as("forces_3.svg", shaper), 2).endswith("Force analysis")
    assert heading_above(note, shown_as("plan_3.svg", shaper), 2).endswith("Kinematic analysis by the plan method")
    assert heading_above(note, "positions.svg", 2).endswith("Initial data")
    assert heading_above(note, "diagrams.svg", 3).endswith("Kinematic diagrams of the output link 6")
    for file in ("dynamics.svg", "motion.svg"):
        assert heading_above(note, shown_as(file, shaper), 2).endswith("Dynamics of the machine")


def test_the_html_sets_each_figure_with_its_caption_and_links_it_to_its_drawing(shaper):
    page = (shaper / "note.html").read_text(encoding="utf-8")
    note = (shaper / "note.md").read_text(encoding="utf-8")
    # A caption's symbols are set in the HTML as the text's are (the dynamics part's "ΔT = A<sub>d</sub> − ..."),
    # read here as their letters.
    shown = [(link, picture, re.sub(r"<[^>]+>", "", caption)) for link, picture, caption in
             re.findall(r'<figure><a href="([^"]+)"><img src="([^"]+)" alt="[^"]*" /></a>'
                        r'<figcaption>(.*?)</figcaption></figure>', page)]
    assert shown == [(file, file, caption) for _, file, caption in figures(note)]
    assert all((shaper / file).is_file() for file, _, _ in shown)


def test_the_pdf_shows_each_drawing_on_the_page_of_its_caption(shaper):
    # Lettering of the drawings that the note's text never writes: their captions.
    # A plan sheet in a row too wide for a page is shown in parts, its mechanism in the first.
    for caption, lettering in (("Figure 2. Velocity and acceleration plans, position 3 (part 1 of",
                                "Mechanism in position 3"),
                               ("Figure 7. Force analysis, position 3 (part 1 of", "Force polygon"),
                               ("Figure 6. Load diagrams", "Load diagram F6(sE) of link 6")):
        pages = pages_with(shaper / "note.pdf", caption)
        assert len(pages) == 1 and lettering in pages[0]
    assert "Mechanism in position" not in (shaper / "note.md").read_text(encoding="utf-8")


def test_the_word_note_has_each_drawing_as_a_picture_of_its_proportions_over_its_caption(shaper):
    from docx import Document

    document = Document(io.BytesIO((shaper / "note.docx").read_bytes()))
    found = figures((shaper / "note.md").read_text(encoding="utf-8"))
    pictures = document.inline_shapes
    assert len(pictures) == len(found)
    for picture, (_, file, _) in zip(pictures, found, strict=True):
        width, height = svg_size_mm((shaper / file).read_text(encoding="utf-8"))
        assert picture.width.mm <= TEXT_WIDTH_MM + 0.1
        assert picture.width.mm <= width + 0.1   # never drawn larger than its own size
        assert picture.width / picture.height == pytest.approx(width / height, rel=0.01)
    captions = [k for k, paragraph in enumerate(document.paragraphs) if paragraph.text.startswith("Figure ")]
    assert len(captions) == len(found)
    for k in captions:
        assert document.paragraphs[k].alignment == 1   # centred
        assert document.paragraphs[k - 1].paragraph_format.keep_with_next


@pytest.mark.skipif(shutil.which("xelatex") is None, reason="XeLaTeX is not installed (Debian: texlive-xetex)")
def test_the_latex_note_takes_each_drawing_from_its_pdf_beside_it(shaper, tmp_path):
    folder = tmp_path / "tex"
    shutil.copytree(shaper, folder)
    (folder / "note.pdf").unlink()
    subprocess.run(["xelatex", "-interaction=nonstopmode", "-halt-on-error", "note.tex"], cwd=folder,
                   capture_output=True, timeout=300, check=True)
    pages = pages_with(folder / "note.pdf", "Figure 2. Velocity and acceleration plans, position 3 (part 1 of")
    assert len(pages) == 1 and "Mechanism in position 3" in pages[0]
    assert "not found" not in (folder / "note.log").read_text(encoding="utf-8", errors="replace")


def test_a_note_asked_for_alone_has_no_figures_to_show(tmp_path):
    # On no sheet: what the note shows does not hang on the sheet, whose scale is chosen by laying out every sheet
    # (the shaper's note on its own sheet is the module's fixture).
    out = run(tmp_path, "shaper", "--only", "note", "--sheet", "none")
    assert figures((out / "note.md").read_text(encoding="utf-8")) == []
    assert not list(out.glob("*.svg"))


def test_the_rotors_polygons_and_vibration_plots_are_figures_of_their_sections(tmp_path):
    out = run(tmp_path, "rotor")
    note = (out / "note.md").read_text(encoding="utf-8")
    assert [file for _, file, _ in figures(note)] == ["rotor_balancing.svg", "vibration_magnification.svg",
                                                     "vibration_transmissibility.svg"]
    assert heading_above(note, "rotor_balancing.svg", 2).endswith("Balancing of the rotor")
    assert heading_above(note, "vibration_magnification.svg", 2).endswith("Vibration from the rotating unbalance")


def test_the_plot_of_the_balancing_load_closes_the_section_on_it(tmp_path):
    scene = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "forces,figures,note", "--locale", "en"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    parts = {number: sorted((path.name for path in out.glob(f"forces_{number}-*.svg")),
                            key=lambda name: int(PART.match(name)[2])) for number in (5, 11)}
    assert all(parts.values())
    assert [file for _, file, _ in figures(note)] == [*parts[5], *parts[11], "balancing.svg"]
    assert heading_above(note, "balancing.svg", 3).endswith("Balancing moment over the cycle")


def test_a_title_with_a_bracket_and_a_backslash_keeps_its_figure_whole(tmp_path):
    # An unmatched "]" in the caption would close the picture's text early, and the figure would be lost.
    scene = tmp_path / "press.toml"
    scene.write_text(starter("flywheel").replace('title  = "Flywheel of a punching press"',
                                                 'title  = "Press v2] \\\\ draft"'), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    page = (out / "note.html").read_text(encoding="utf-8")
    assert ('<figure><a href="motion.svg"><img src="motion.svg" alt="Motion of the machine: Press v2] \\ draft" /></a>'
            "<figcaption>Figure 2. Motion of the machine: Press v2] \\ draft</figcaption></figure>") in page


def test_a_force_sheet_too_tall_for_a_page_is_shown_in_parts_that_print_readably(shaper):
    """The shaper's force sheet, 343 × 980 mm, went into the note's pages shrunk to a quarter, its letters 3 pt
    high (a Chinese student's PDF and Word notes).  Cut between its rows, each part prints at half size or more on
    a page; together the parts hold every layer of the whole, the heading over the first, in order down the sheet."""
    from graphplan.render.note_parts import LEAST_PRINT_SCALE, PAGE_FIGURE_MM

    whole = ElementTree.parse(shaper / "forces_3.svg").getroot()
    whole_ids = {group.get("id") for group in whole.findall(f"{SVG}g") if len(group)}
    parts = sorted(shaper.glob("forces_3-*.svg"), key=lambda path: int(PART.match(path.name)[2]))
    assert len(parts) >= 2
    seen: list[str] = []
    for k, path in enumerate(parts):
        root = ElementTree.parse(path).getroot()
        ids = [group.get("id") for group in root.findall(f"{SVG}g")]
        assert ("sheet-title" in ids) == (k == 0)
        seen += ids
        width, height = (float(root.get(side).removesuffix("mm")) for side in ("width", "height"))
        # Less its 8 mm margins, the part prints at half size or more within a page's figure (bar its width,
        # which no cut between rows changes).
        scale = min(PAGE_FIGURE_MM[0] / (width - 16.0), PAGE_FIGURE_MM[1] / (height - 16.0))
        assert scale >= LEAST_PRINT_SCALE or PAGE_FIGURE_MM[0] / (width - 16.0) < LEAST_PRINT_SCALE
        assert PAGE_FIGURE_MM[1] / (height - 16.0) >= LEAST_PRINT_SCALE
    assert sorted(seen) == sorted(whole_ids) and len(seen) == len(set(seen))
    # In the whole's order down the sheet: each part's layers stand below the last part's.
    order = [group.get("id") for group in whole.findall(f"{SVG}g") if len(group)]
    firsts = [order.index(next(g.get("id") for g in ElementTree.parse(path).getroot().findall(f"{SVG}g")
                                if g.get("id") != "sheet-title")) for path in parts]
    assert firsts == sorted(firsts)


def test_each_part_of_a_force_sheet_is_painted_in_the_whole_sheets_order(shaper):
    """A part was painted in its layers' order by height: the group's links (white slider blocks and pins) over
    its arrows and its names under everything, so a load pushing on the ram's block showed no head in the note.
    Each part paints its layers in the order the whole sheet does: links, then forces, then names."""
    whole = ElementTree.parse(shaper / "forces_3.svg").getroot()
    order = [group.get("id") for group in whole.findall(f"{SVG}g") if len(group)]
    for path in shaper.glob("forces_3-*.svg"):
        ids = [group.get("id") for group in ElementTree.parse(path).getroot().findall(f"{SVG}g")
               if len(group) and group.get("id") != "sheet-title"]  # the heading stands clear over the first part
        assert ids == sorted(ids, key=order.index)
        for links in (name for name in ids if name.startswith("body-") and name.endswith("-links")):
            group = links.removesuffix("-links")
            assert ids.index(links) < ids.index(f"{group}-forces") < ids.index(f"{group}-labels")
