"""A teacher's reading of the force sheets, in each language the drawings are lettered in.

A force sheet names μF three ways: the polygons' (its heading, each polygon's caption), the arrows on a group cut
free, drawn at a μF of their own so that none is shorter than 10 mm, and the arrows on Zhukovsky's lever.  The
engine's sheet of position 2 read "μl = 0.001 m/mm, μF = 40 N/mm" over a group captioned "forces: μF = 100 N/mm"
and a driver captioned "forces: μF = 200 N/mm": each true, but a reader measuring a polygon could not tell which
to take.  The arrows' μF now says it is the arrows'; the heading's is the polygons', which each polygon's caption
gives again under its title.  (Naming the polygons in the heading too widened it past a narrow part's drawings:
the engine's and the shaper's sheets in Chinese took one sheet more, so the heading is left as it was.)

The sheets are read back from the SVG the command line writes.
"""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main

SVG = "{http://www.w3.org/2000/svg}"
FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
LOCALE_LINE = re.compile(r'^locale\s*=\s*"[a-z]+"\s*$', re.MULTILINE)

# The words a reader of each language looks for beside a μF: the drawing it belongs to.
POLYGON = {"en": "Force polygon", "ru": "План сил", "zh": "力多边形"}
ARROWS = {"en": "arrows", "ru": "стрелки", "zh": "箭头"}
# The clause a scale stands in: from the comma before it (Latin or full-width) to the next; the drawing's name
# stands before the μF, as the reader comes to it.
CLAUSE = re.compile(r"[^,，；;]*μF = [^,，；;]*")
SCALE = re.compile(r"μF = ([\d.,]+)")
# The caption's lines as read back, kept apart.
LINE = "\n"
WHOLE = re.compile(r"(forces(?:-friction)?-\d+)")


def in_locale(fixture: str, locale: str, folder: Path) -> Path:
    """A copy of the fixture whose drawings are lettered in ``locale`` (the scene's own key, not --locale)."""
    text = (FIXTURES / f"{fixture}.toml").read_text(encoding="utf-8")
    line = f'locale = "{locale}"'
    text = LOCALE_LINE.sub(line, text, count=1) if LOCALE_LINE.search(text) else text.replace(
        "[scene]\n", f"[scene]\n{line}\n", 1)
    scene = folder / f"{fixture}_{locale}.toml"
    scene.write_text(text, encoding="utf-8")
    return scene


def sheets(fixture: str, locale: str, folder: Path) -> list[Path]:
    scene = in_locale(fixture, locale, folder)
    out = folder / f"{fixture}_{locale}"
    assert main(["run", str(scene), "--only", "sheets", "--format", "svg", "--out", str(out)]) == 0
    return sorted(out.glob("sheet_*.svg"), key=lambda path: int(path.stem.split("_")[1]))


def captions(paths: list[Path]) -> list[tuple[str, str, str]]:
    """(the force sheet, the kind of drawing, the caption's or heading's lines, one a line) of every force sheet's
    caption and heading: the sheet ``forces-2`` (its parts too), the kind ``body``, ``polygon``, ``lever`` or
    ``heading``."""
    found = []
    for path in paths:
        for group in ElementTree.parse(path).getroot().iter(f"{SVG}g"):
            name = group.get("id", "")
            if not name.startswith("forces"):
                continue
            kind = ("heading" if name.endswith("sheet-title") else
                    next((kind for kind in ("body", "polygon", "lever") if f"-{kind}-" in f"{name}-"
                          and name.endswith("-caption")), None))
            if kind is not None:
                found.append((WHOLE.match(name).group(1), kind, LINE.join("".join(text.itertext()) for text in group.iter(f"{SVG}text"))))
    return found


@pytest.mark.parametrize("fixture", ["engine_slider_crank", "shaper_six_bar"])
@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_every_force_scale_on_a_force_sheet_says_which_drawing_it_is_for(tmp_path, fixture, locale):
    words = {"polygon": POLYGON[locale], "body": ARROWS[locale], "lever": ARROWS[locale]}
    read = captions(sheets(fixture, locale, tmp_path))
    kinds = {kind for _, kind, text in read if "μF" in text}
    assert kinds >= {"polygon", "body", "lever"}, read
    for _, kind, text in read:
        if kind == "heading":
            continue
        # A polygon's caption is named by its title, right over its μF: the words again widened the driver's
        # narrow polygon and sent its group onto a sheet of its own.  The arrows' name stands on the line of their
        # μF: "μV = 0.004 (m/s)/mm, forces:" ended a lever's line, its μF under it.
        for clause in CLAUSE.findall(text) if kind == "polygon" else [
                clause for line in text.split(LINE) for clause in CLAUSE.findall(line)]:
            before = text.split("μF")[0] if kind == "polygon" else clause.split("μF")[0]
            assert words[kind] in before, (kind, clause)
    # The heading's μF, unnamed, is the one every polygon is drawn at, and no arrow's; polygons each at their own
    # leave the heading none.
    for whole in {whole for whole, _, _ in read}:
        polygons = {value for at, kind, text in read if at == whole and kind == "polygon"
                    for value in SCALE.findall(text)}
        headings = {value for at, kind, text in read if at == whole and kind == "heading"
                    for value in SCALE.findall(text)}
        assert not headings or (len(polygons) == 1 and headings == polygons), (whole, polygons, headings)


# An arm as an equation names it: «R23τ·AB» (a segment, drawn as the link) is not one; «G3·h7» and «R14n·h» are.
ARM = re.compile(r"·(h\d*)(?![\w′″])")


def drawn_and_given(path: Path) -> dict[str, tuple[set[str], set[str], str]]:
    """For each drawing of a force sheet's SVG with equations (a group cut free, the lever): the names lettered on
    it, the arms whose length its caption gives (``h1 = 11.78 mm``), and its caption's text."""
    found: dict[str, tuple[set[str], set[str], str]] = {}
    for group in ElementTree.parse(path).getroot().iter(f"{SVG}g"):
        name = group.get("id", "")
        drawing = re.match(r"(body-[\w-]+?|lever)-(labels|caption)$", name)
        if drawing is None:
            continue
        texts = ["".join(text.itertext()) for text in group.iter(f"{SVG}text")]
        labels, given, caption = found.get(drawing.group(1), (set(), set(), ""))
        if drawing.group(2) == "labels":
            labels |= set(texts)
        else:
            caption = " ".join(texts)
            given |= set(re.findall(r"\b(h\d*) = [\d.,]+ (?:mm|мм)", caption))
        found[drawing.group(1)] = (labels, given, caption)
    return found


@pytest.mark.parametrize("fixture", ["triad_class_iii", "triad_with_slider"])
def test_every_arm_an_equation_names_is_drawn_and_lettered_or_given_its_length(tmp_path, fixture):
    """The triad's moment equation about Assur's point Σ6 wrote its unknown's arm «R14n·h», an h neither drawn
    nor given: a reader could not check the equation.  Every arm an equation names is lettered on its drawing or
    its length stands under it."""
    out = tmp_path / fixture
    assert main(["run", str(FIXTURES / f"{fixture}.toml"), "--only", "forces,lever", "--format", "svg",
                 "--out", str(out)]) == 0
    checked = 0
    for path in sorted(out.glob("forces_*.svg")):
        for drawing, (labels, given, caption) in drawn_and_given(path).items():
            for arm in ARM.findall(caption):
                checked += 1
                assert arm in labels or arm in given, (path.name, drawing, arm, caption)
    assert checked


@pytest.mark.parametrize("fixture", ["engine_slider_crank", "quick_return_slotted_lever"])
def test_a_chinese_force_sheets_heading_sets_its_scales_off_as_its_captions_do(tmp_path, fixture):
    """Under «力分析，位置 2» the heading read «μl = 0.001 m/mm, μF = 40 N/mm» with a Latin comma, where every
    caption under it sets its scales off with 「，」: the heading's line of scales now does too, on every part."""
    headings = [text for _, kind, text in captions(sheets(fixture, "zh", tmp_path)) if kind == "heading"]
    lines = [line for text in headings for line in text.split(LINE) if "μ" in line]
    assert lines and any(line.count("μ") > 1 for line in lines), headings
    for line in lines:
        assert ", " not in line and line.count("，") == line.count("μ") - 1, line


def test_a_caption_beside_its_drawing_is_set_no_narrower_than_its_names_and_what_they_name():
    """The lever's caption beside it on the slider-crank's A2, broken to 70 mm, no taller than the lever there, ended
    a line on "arrows:", its μF alone on the next: "arrows: μF = 40 N/mm" is wider than 70 mm at the lettering, and a
    piece too wide for its width breaks between words.  It is set at the next width, which holds the two on a line,
    and still no taller than the drawing."""
    from graphplan.render.force_rows import CAPTION_BESIDE_WIDTHS_MM, Drawing, _caption_beside, _lines_height
    from graphplan.render.primitives import text_width

    size = 5.0
    caption = ("Zhukovsky's lever", "the velocity plan turned 90° clockwise",
               "μV = 0.04 (m/s)/mm, arrows: μF = 40 N/mm (no arrow shorter than 10 mm)", "ΣMp: G3·h1 − Fu3·h2 = 0")
    assert text_width("arrows: μF = 40 N/mm", size) > CAPTION_BESIDE_WIDTHS_MM[0]  # the narrowest breaks it
    height = 200.0
    lines = _caption_beside(Drawing("lever", [], caption), height, size)
    assert any(line.startswith("arrows: μF = 40 N/mm") or ", arrows: μF = 40 N/mm" in line for line, _ in lines)
    assert not any(line.endswith(":") for line, _ in lines)
    assert _lines_height(lines, size) <= height


def test_a_line_is_not_broken_after_a_short_name_and_its_colon():
    """«μV = 0.004 (m/s)/mm, arrows:» ended a lever's caption line, its μF on the next; a colon after a clause of
    several words is still a place to break."""
    from graphplan.render.primitives import text_width
    from graphplan.render.wrapping import fitted

    line = "μV = 0.004 (m/s)/mm, arrows: μF = 2 N/mm (no arrow shorter than 10 mm)"
    width = text_width("μV = 0.004 (m/s)/mm, arrows:", 2.5) + 1.0
    assert fitted(line, width, 2.5)[:2] == ["μV = 0.004 (m/s)/mm,", "arrows: μF = 2 N/mm"]
    russian = "μV = 0,01983 (м/с)/мм, стрелки сил: μF = 2 Н/мм"
    assert fitted(russian, text_width("μV = 0,01983 (м/с)/мм, стрелки сил:", 2.5) + 1.0, 2.5) == [
        "μV = 0,01983 (м/с)/мм,", "стрелки сил: μF = 2 Н/мм"]
    clause = "without friction 6.48 N·m: the rest"
    assert fitted(clause, text_width("without friction 6.48 N·m:", 2.5) + 1.0, 2.5) == [
        "without friction 6.48 N·m:", "the rest"]


def test_an_unknowns_arm_between_points_named_in_words_is_an_h_with_its_length(tmp_path):
    """Points named in words ran together into one: «−R45τ·ROCKERENDSLIDEPIN».  Two one-letter names name their
    segment (R23τ·AB); a name of more letters makes the arm an h, its length given under the equation."""
    from graphplan.starters import starter

    def equations(text: str, folder: Path) -> list[str]:
        folder.mkdir()
        scene = folder / "scene.toml"
        scene.write_text(text, encoding="utf-8")
        assert main(["run", str(scene), "--only", "forces", "--sheet", "none", "--out", str(folder / "out")]) == 0
        return [equation for path in sorted((folder / "out").glob("forces_*.svg"))
                for _, _, caption in drawn_and_given(path).values()
                for equation in re.findall(r"ΣM\w+\(3\): .*?R23τ = \S+ N(?:,\s+h = [\d.]+ mm)?", caption)]

    text = starter("crank-rocker", "en")
    lettered = equations(text, tmp_path / "letters")
    assert lettered and all("R23τ·AB " in equation and "h = " not in equation for equation in lettered), lettered
    worded = equations(text.replace('"B"', '"KNEE"'), tmp_path / "words")
    assert len(worded) == len(lettered), worded
    assert all("ΣMKNEE(3): " in equation and "R23τ·h " in equation and re.search(r",\s+h = [\d.]+ mm$", equation)
               and "AKNEE" not in equation for equation in worded), worded
