"""Every plan length the note writes in millimetres says "not drawn" where the plan leaves that segment out.

The plans leave out a vector shorter than 0.25 mm (their captions name it), and the note's vector-equation tables
already said so beside its segment. The other places the note gives a plan's length did not: a slider-crank a tenth
of a degree from its dead centre has pb = 0.22 mm, read off as ``VB = pb·μV = 0.22·…`` and listed in the table of
velocities; at 90.1° its rod hardly turns, ab = 0.18 mm, and the rod's centre by similarity is ``as3 = … = 0.05 mm``
from a; a slider driver that hardly speeds up has its ``pa = aA/μa = … = 0.03 mm`` in the scale paragraph. A student
measuring the plan looked for those segments in vain. Each now carries the tables' words, in every locale and note
format, and a length the plan draws keeps its plain number.

Which segments are short is found from the plans' own points and scale and, for the scene built here, from the
analytic motion (``graphplan.solve``) at the plans' scale, not from the note.
"""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.locale import strings
from graphplan.report.note import note_markdown
from graphplan.report.tables import quantity_symbol
from graphplan.starters import starter
from graphplan.wording import raised

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
# The plans leave out a vector shorter than this (mm), as their captions state.
SHORTEST_DRAWN_MM = 0.25
# A segment this short is a point at the pole or on another point: nought, neither drawn nor "not drawn".
NOUGHT_MM = 1e-9
LOCALES = ("en", "ru", "zh")


def near_dead_centre(locale: str) -> dict:
    """The slider-crank starter analysed at φ = 0.1° (the slider a hair from its outer dead centre) and 90.1° (the
    rod at its greatest swing, hardly turning), both with plans."""
    tables = tomllib.loads(starter("slider-crank", locale))
    tables["positions"].update(count=4, start=0.1, number_from=0, plans=[0, 1])
    return tables


def hardly_speeding_slider(locale: str) -> dict:
    """The slider-driven four-bar whose cylinder speeds up by 10 μm/s², at the standard μa its plan fits at: the
    driver's own segment pa is shorter than the plan draws."""
    tables = tomllib.loads((FIXTURES / "slider_driven.toml").read_text(encoding="utf-8"))
    tables["scene"]["locale"] = locale
    tables["driver"]["acceleration"] = 1e-5
    del tables["drawing"]["acceleration_pole"]
    return tables


_analyses: dict[tuple[str, str], object] = {}


def analysis_of(kind: str, locale: str):
    if (kind, locale) not in _analyses:
        tables = near_dead_centre(locale) if kind == "slider-crank" else hardly_speeding_slider(locale)
        _analyses[kind, locale] = analyse(graphplan.load(tables))
    return _analyses[kind, locale]


def words(locale: str) -> str:
    text = strings(locale)
    return text["note_segment_short"].format(least=f"{SHORTEST_DRAWN_MM:g}".replace(".", text["decimal_mark"]))


def sections(note: str, locale: str) -> dict[tuple[int, str], list[str]]:
    """The lines of each position's velocity and acceleration plan subsections of the kinematic analysis."""
    text = strings(locale)
    heading = re.compile(re.escape(text["position_heading"]).replace(r"\{number\}", r"(\d+)")
                         + re.escape(text["colon"]))
    titles = {f"#### {text['velocity_plan_title']}": "velocity", f"#### {text['acceleration_plan_title']}": "acceleration"}
    found: dict[tuple[int, str], list[str]] = {}
    number = kind = None
    for line in note.splitlines():
        if line.startswith("## "):
            number = kind = None
        elif line.startswith("### "):
            match = heading.search(line)
            number, kind = (int(match.group(1)) if match else None), None
        elif line.startswith("#### "):
            kind = titles.get(line.strip())
        elif number is not None and kind is not None:
            found.setdefault((number, kind), []).append(line)
    return found


def letters(plan, locale: str, start: str, end: str) -> str:
    pole = strings(locale)["acceleration_pole"]
    return "".join(pole if plan.kind == "acceleration" and letter == "p" else letter for letter in (start, end))


def symbol(quantity: str) -> str:
    """A quantity as the note prints it: ω3, aBB1ʳ."""
    return raised(quantity_symbol(quantity))


def length_mm(plan, start: str, end: str) -> float:
    return abs(plan.points[end] - plan.points[start]) / plan.scale


def is_short(millimetres: float) -> bool:
    return NOUGHT_MM < millimetres < SHORTEST_DRAWN_MM


def written_mm(cell: str, locale: str) -> float:
    """The first number of a note's length, in the locale's decimal mark."""
    return float(re.match(r"[\d.,]+", cell).group(0).replace(strings(locale)["decimal_mark"], "."))


def test_the_scene_near_dead_centre_has_segments_too_short_to_draw_by_its_analytic_motion():
    """The analytic VB at 0.1° and VBA = ω3·lAB at 90.1° come out under 0.25 mm at the plans' μV, and VA does
    not: the scene tests what it is meant to, whatever the construction draws."""
    scene = graphplan.load(near_dead_centre("en"))
    motion = graphplan.solve(scene)
    analysis = analysis_of("slider-crank", "en")
    by_number = {position.number: position for position in analysis.plans}
    rod = math.dist(*(motion.point(name).r[1] for name in ("A", "B")))
    velocity_b = math.hypot(*motion.point("B").v[0])
    relative = abs(motion.link(3).omega[1]) * rod
    assert is_short(velocity_b / by_number[0].velocity.scale)
    assert is_short(relative / by_number[1].velocity.scale)
    assert math.hypot(*motion.point("A").v[0]) / by_number[0].velocity.scale > 50
    # The plan agrees with the analytic solution: the note's numbers come from it.
    assert length_mm(by_number[0].velocity, "p", "b") == pytest.approx(velocity_b / by_number[0].velocity.scale,
                                                                        rel=1e-6)


@pytest.mark.parametrize("locale", LOCALES)
def test_a_reading_off_a_segment_the_plan_leaves_out_says_it_is_not_drawn(locale):
    analysis = analysis_of("slider-crank", locale)
    text = strings(locale)
    blocks = sections(note_markdown(analysis), locale)
    marked = plain = 0
    for position in analysis.plans:
        for kind, plan in position.plans.items():
            lines = blocks[position.number, kind]
            for reading in position.readings:
                if reading.plan != kind:
                    continue
                segment = letters(plan, locale, *reading.segment)
                start = f"- {symbol(reading.quantity)} = "
                line = next(line for line in lines if line.startswith(start) and f"{segment}·μ" in line)
                millimetres = length_mm(plan, *reading.segment)
                # The length the line multiplies by μ is the plan's.
                assert written_mm(line.split(f"{segment}·μ")[1].split(" = ")[1], locale) == \
                    pytest.approx(millimetres, abs=0.006)
                if is_short(millimetres):
                    assert text["bracketed"].format(words=f"{segment} {words(locale)}") in line, line
                    marked += 1
                else:
                    assert words(locale) not in line, line
                    plain += 1
    # VB and VBB1 (pb) at 0°, ε3 (n3b) there; VBA and ω3 (ab) at 90.1°; the rest drawn.
    assert marked >= 5 and plain >= 10


@pytest.mark.parametrize("locale", LOCALES)
def test_a_point_by_similarity_closer_than_the_plan_draws_says_it_is_not_drawn(locale):
    analysis = analysis_of("slider-crank", locale)
    text = strings(locale)
    blocks = sections(note_markdown(analysis), locale)
    seen = set()
    for position in analysis.plans:
        for kind, plan in position.plans.items():
            letter = plan.images["S3"]
            line = next(line for line in blocks[position.number, kind] if line.startswith(f"- {letter}{text['colon']}"))
            segment = letters(plan, locale, plan.images["A"], letter)
            value = line.split(f"{segment} = ")[1].split(" = ")[-1]
            millimetres = length_mm(plan, plan.images["A"], letter)
            assert written_mm(value, locale) == pytest.approx(millimetres, abs=0.006)
            assert value.startswith(f"{millimetres:.2f}".replace(".", text["decimal_mark"]) + f" {text['millimetre']}")
            if is_short(millimetres):
                assert value.endswith(text["bracketed"].format(words=words(locale))), line
            else:
                assert words(locale) not in line, line
            seen.add(is_short(millimetres))
    assert seen == {True, False}


@pytest.mark.parametrize("locale", LOCALES)
def test_the_table_of_values_marks_a_length_the_plan_leaves_out(locale):
    analysis = analysis_of("slider-crank", locale)
    text = strings(locale)
    note = note_markdown(analysis)
    seen = set()
    for position in analysis.plans:
        for kind, plan in position.plans.items():
            caption = text[f"note_{kind}_table"].format(number=position.number)
            rows = note.split(caption, 1)[1].split("\n\n")[1].splitlines()[2:]
            cells = {row.strip("|").split("|")[0].strip(): [cell.strip() for cell in row.strip("|").split("|")]
                     for row in rows}
            for reading in position.readings:
                if reading.plan != kind:
                    continue
                row = cells[symbol(reading.quantity)]
                millimetres = length_mm(plan, *reading.segment)
                assert written_mm(row[2], locale) == pytest.approx(millimetres, abs=0.006)
                expected = f"{millimetres:.2f}".replace(".", text["decimal_mark"])
                if is_short(millimetres):
                    expected += text["semicolon"] + words(locale)
                assert row[2] == expected.strip(), row
                seen.add(is_short(millimetres))
    assert seen == {True, False}


@pytest.mark.parametrize("locale", LOCALES)
def test_the_driver_s_segment_in_the_scale_paragraph_says_not_drawn_where_it_is_short(locale):
    """pa = aA/μa of a slider speeding up by 10 μm/s² at a μa chosen for its plan's larger vectors, and so at a μa
    given as that number; the velocity plan's pa = 80 mm of the scene's pole stays a plain length."""
    text = strings(locale)
    for given in (False, True):
        tables = hardly_speeding_slider(locale)
        analysis = analysis_of("slider", locale)
        if given:
            tables["drawing"]["acceleration_scale"] = analysis.plans[0].acceleration.scale
            analysis = analyse(graphplan.load(tables))
        blocks = sections(note_markdown(analysis), locale)
        for position in analysis.plans:
            for kind, plan in position.plans.items():
                segment = letters(plan, locale, "p", plan.images["A"])
                millimetres = abs(plan.value("A")) / plan.scale
                lines = [line for line in blocks[position.number, kind] if f"{segment} = " in line
                         and text["millimetre"] in line and not line.startswith(("|", "- "))]
                assert len(lines) == 1, lines
                if kind == "acceleration":
                    assert is_short(millimetres)
                    length = lines[0].split(f"{segment} = ")[1].split(" = ")[-1]
                    assert written_mm(length, locale) == pytest.approx(millimetres, abs=0.006)
                    assert text["bracketed"].format(words=words(locale)) in length, lines[0]
                else:
                    assert millimetres == pytest.approx(80.0)
                    assert words(locale) not in lines[0]


def test_a_pole_shorter_than_the_plan_draws_says_so():
    """A plan pole typed as 0.1 mm (a slip for 100): the driver's vector is that segment, not drawn."""
    tables = hardly_speeding_slider("en")
    tables["drawing"]["acceleration_pole"] = 0.1
    analysis = analyse(graphplan.load(tables))
    lines = sections(note_markdown(analysis), "en")[analysis.plans[0].number, "acceleration"]
    assert any("pa = 0.1 mm" + strings("en")["bracketed"].format(words=words("en")) in line for line in lines)


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_every_note_format_says_not_drawn(tmp_path, locale):
    """note.md, note.html, note.tex and note.docx all carry the words beside as3 of position 1."""
    docx = pytest.importorskip("docx")
    scene = tmp_path / "scene.toml"
    scene.write_text(starter("slider-crank", locale).replace('start       = "extreme"', "start       = 0.1")
                     .replace("count       = 12", "count       = 4").replace("plans       = [2, 8]", "plans       = [0, 1]"),
                     encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note", "--format", "docx"]) == 0
    said = strings(locale)["bracketed"].format(words=words(locale))
    markdown = (out / "note.md").read_text(encoding="utf-8")
    assert markdown.count(said) >= 1
    assert words(locale) in (out / "note.html").read_text(encoding="utf-8")
    # LaTeX sets the Chinese words in their font between the Latin: \notecjk{；短于} 0.25 mm\notecjk{、未画出}.
    latex = re.sub(r"\\notecjk\{([^}]*)\}", r"\1", (out / "note.tex").read_text(encoding="utf-8"))
    assert words(locale) in latex
    document = docx.Document(str(out / "note.docx"))
    paragraphs = [paragraph.text for paragraph in document.paragraphs]
    cells = [cell.text for table in document.tables for row in table.rows for cell in row.cells]
    assert any(words(locale) in paragraph for paragraph in paragraphs)
    assert any(words(locale) in cell for cell in cells)


@pytest.mark.parametrize("locale", LOCALES)
def test_an_arm_on_zhukovsky_s_lever_too_short_to_draw_says_not_drawn(locale):
    """The lever is the velocity plan turned by 90°, and its sheet leaves out an arm shorter than 0.25 mm as the
    plans leave out a vector: at 0.1° the piston's image b stands 0.22 mm from the pole, so F4 and Fu4 at b have
    arms shorter than that. Each arm is worked out here from the velocity plan: the image turned clockwise, the
    perpendicular from the pole to the force's line through it, at the μV the note says the lever is drawn at."""
    from graphplan.render.force_lever import enlarged_lever_scale

    analysis = analysis_of("slider-crank", locale)
    text = strings(locale)
    note = note_markdown(analysis)
    position = next(position for position in analysis.plans if position.number == 0)
    velocity, lever = position.velocity, position.lever
    # The lever's own scale where it is drawn larger than the plan, as its note paragraph says.
    drawn_at = enlarged_lever_scale(velocity, lever) or velocity.scale
    caption = text["note_lever_table"].format(number=position.number)
    rows = note.split(caption, 1)[1].split("\n\n")[1].splitlines()[2:]
    cells = {row.strip("|").split("|")[0].strip(): [cell.strip() for cell in row.strip("|").split("|")]
             for row in rows}
    seen = set()
    for term in lever.terms:
        if not term.image or term.name not in cells or term.shift:
            continue
        place = velocity.points[term.image] * -1j
        direction = term.force / abs(term.force)
        millimetres = abs((place * direction.conjugate()).imag) / drawn_at
        cell = re.sub(r"^h\S* = ", "", cells[term.name][3])  # the length after the arm's name on the lever, h2 = …
        assert written_mm(cell, locale) == pytest.approx(millimetres, abs=0.006), (term.name, cell)
        expected = f"{millimetres:.2f}".replace(".", text["decimal_mark"])
        if is_short(millimetres):
            expected += text["semicolon"] + words(locale)
        assert cell == expected.strip(), (term.name, cell)
        seen.add(is_short(millimetres))
    assert seen == {True, False}
