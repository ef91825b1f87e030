"""A teacher's reading of the explanatory note, each fault checked on the notes the fixtures' runs write.

- Every table of the note is numbered and captioned in one series, each referred to by its number before it: the
  vector equations' tables and the force polygons' were left bare among "Table 9. …" ones.
- A force polygon's vector too short to draw (shorter than the drawings' 0.25 mm) is told so beside its value in
  newtons, not written as a vector of "0.00 mm" laid off.
"""

from __future__ import annotations

import itertools
import json
import re
import tomllib
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.locale import load_symbol, strings

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
# The drawings leave out a vector shorter than this (render.plans.ZERO_MM), a length the sheets' captions state.
SHORTEST_DRAWN_MM = 0.25


def run_note(folder: Path, fixture: str, locale: str, *extra: str, scene: Path | None = None) -> str:
    """The note.md a run of ``fixture`` (or of ``scene``) writes in ``locale``, its results.json beside it."""
    out = folder / f"{fixture}-{locale}"
    source = scene if scene is not None else FIXTURES / f"{fixture}.toml"
    assert main(["run", str(source), "--out", str(out), "--only", "note", "--locale", locale, *extra]) == 0
    return (out / "note.md").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def notes(tmp_path_factory):
    """Notes of fixtures, each written once for the module: ``notes(fixture, locale)``."""
    folder = tmp_path_factory.mktemp("notes")
    written: dict[tuple[str, str], str] = {}

    def note(fixture: str, locale: str) -> str:
        if (fixture, locale) not in written:
            written[fixture, locale] = run_note(folder, fixture, locale)
        return written[fixture, locale]

    note.folder = folder
    return note


def number_pattern(template: str) -> re.Pattern:
    """A locale's sentence about a table (its caption, its continuation, a reference) as a pattern catching the
    number; the rest of it (a caption's words) anything."""
    escaped = re.escape(template).replace(r"\{number\}", r"(\d+)").replace(r"\{caption\}", ".*")
    return re.compile(escaped)


def table_starts(lines: list[str]) -> list[int]:
    return [k for k, line in enumerate(lines) if line.startswith("|") and (k == 0 or not lines[k - 1].startswith("|"))]


def check_tables(markdown: str, locale: str) -> int:
    """Every table under a caption or a continuation of the one before; the captions numbered 1, 2, … in order;
    every number the text refers to that of a table captioned after the reference, the next one captioned.
    The count of tables captioned."""
    text = strings(locale)
    caption = number_pattern(text["table_caption"])
    continued = number_pattern(text["table_continued"])
    lines = markdown.split("\n")
    captions: list[int] = []
    for k in table_starts(lines):
        above = next(line for line in reversed(lines[:k]) if line.strip())
        numbered = caption.fullmatch(above) or continued.fullmatch(above)
        assert numbered, f"a table with no number under {above!r}"
    # Each reference by number (the leads' words, any locale's key that names a table) is to the next table.
    references = [number_pattern(text[key]) for key in text if key.endswith("table_lead") or key == "note_groups_lead"]
    for line in lines:
        if match := caption.fullmatch(line):
            captions.append(int(match.group(1)))
            continue
        if continued.fullmatch(line):
            assert int(continued.fullmatch(line).group(1)) == captions[-1]
            continue
        for pattern in references:
            for match in pattern.finditer(line):
                assert int(match.group(1)) == len(captions) + 1, f"{line!r} after Table {len(captions)}"
    assert captions == list(range(1, len(captions) + 1))
    # No reference is left unmatched to a reference pattern: every "Table N" in the text is a caption's, a
    # continuation's or one of the leads checked above.
    word = {"en": r"Table", "ru": r"[Тт]аблиц\w*", "zh": r"表"}[locale]
    mentions = sum(len(re.findall(rf"{word}\s*\d+", line)) for line in lines)
    leads = sum(len(pattern.findall(line)) for line in lines for pattern in references)
    continuations = sum(1 for line in lines if continued.fullmatch(line))
    assert mentions == len(captions) + continuations + leads
    return len(captions)


def caption_of(locale: str, key: str) -> re.Pattern:
    """The pattern of a numbered caption whose words are the locale's ``key``, its fields anything."""
    text = strings(locale)
    words = re.sub(r"\\\{\w+\\\}", ".*", re.escape(text[key]))
    return re.compile(re.escape(text["table_caption"]).replace(r"\{number\}", r"\d+").replace(r"\{caption\}", words))


@pytest.mark.parametrize(("fixture", "locale"), [
    ("triad_class_iii", "en"), ("triad_with_slider", "ru"), ("slider_driven", "en"), ("engine_slider_crank", "ru"),
    ("ratchet_crank_rocker", "ru"), ("shaper_six_bar", "zh")])
def test_every_table_of_the_note_is_numbered_and_referred_to_before_it(notes, fixture, locale):
    markdown = notes(fixture, locale)
    check_tables(markdown, locale)
    # Each vector equation written with its terms' table, and each force polygon, has its own numbered caption.
    text = strings(locale)
    lines = markdown.split("\n")
    equation, polygon = text["note_vector_equation"].split("{")[0], text["note_polygon"].split("{")[0]
    tabled = [line for line in lines if line.startswith(equation) and "|" not in line
              and number_pattern(text["note_equation_table_lead"]).search(line)]
    polygons = [line for line in lines if line.startswith(polygon)]
    equation_captions = [line for line in lines if caption_of(locale, "note_equation_table").fullmatch(line)]
    polygon_captions = [line for line in lines if caption_of(locale, "note_polygon_table").fullmatch(line)
                        or caption_of(locale, "note_polygon_table_driver").fullmatch(line)]
    assert tabled and polygons
    assert len(equation_captions) == len(tabled) and len(polygon_captions) == len(polygons)


def polygon_rows(markdown: str, locale: str):
    """(μF, force's name, value in N, length cell, role cell) of every row of every force polygon's table: the
    table that follows the paragraph of its polygon's equation and μF."""
    polygon = strings(locale)["note_polygon"].split("{")[0]
    scale, inside = None, False
    for line in markdown.split("\n"):
        if line.startswith(polygon):
            scale = float(re.search(r"μF = ([\d.,]+) ", line).group(1).replace(",", "."))
            continue
        if line.startswith("|"):
            inside = True
            cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
            if scale is not None and re.match(r"−?\d", cells[1]):
                value = float(cells[1].split("∠")[0].replace(",", ".").replace("−", "-").strip())
                yield scale, cells[0], value, cells[2], cells[3]
        elif inside:
            scale, inside = None, False


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_a_polygon_vector_too_short_to_draw_is_told_so_with_its_value_not_as_a_nought_mm_vector(notes, locale):
    """The slider-driven four-bar's links 3 and 4 move so slowly that their inertia forces, hundredths of a newton,
    are under 0.25 mm at μF = 10 N/mm."""
    text = strings(locale)
    rows = list(polygon_rows(notes("slider_driven", locale), locale))
    short = [row for row in rows if 0 < abs(row[2]) / row[0] < SHORTEST_DRAWN_MM]
    assert {name for _, name, _, _, _ in short} >= {load_symbol("Fu3", text), load_symbol("Fu4", text)}
    least = text["note_role_short"].format(least=str(SHORTEST_DRAWN_MM).replace(".", text["decimal_mark"]))
    for scale, name, value, length, role in rows:
        if abs(value) / scale < SHORTEST_DRAWN_MM and value != 0:
            assert length == "—", (name, length)
            assert least.split(":")[-1].strip() in role and text["note_role_load"] not in role, (name, role)
        else:
            # A vector drawn: its length is its value over μF, as the drawing lays it.
            assert float(length.replace(",", ".")) == pytest.approx(abs(value) / scale, abs=0.006), name


@pytest.mark.parametrize("fixture", ["shaper_six_bar", "ratchet_crank_rocker"])
def test_k_is_the_time_ratio_in_english_and_keeps_its_russian_name(notes, fixture):
    """English textbooks call K = φw/φi the time ratio (advance-to-return); Russian ones «коэффициент изменения
    средней скорости выходного звена». Each note's K is its own φw over φi."""
    english, russian = notes(fixture, "en"), notes(fixture, "ru")
    working, idle, ratio = map(float, re.search(
        r"φw = ([\d.]+)° in the working stroke and φi = ([\d.]+)° in the idle stroke\. The time ratio "
        r"\(advance-to-return\) K = φw/φi = ([\d.]+)\.", english).groups())
    assert ratio == pytest.approx(working / idle, rel=1e-3)   # the angles written to a tenth of a degree
    assert "coefficient of the change" not in english and "mean speed" not in english
    assert re.search(r"Коэффициент изменения средней скорости выходного звена: K = φр\.х/φх\.х = ([\d,]+)\.",
                     russian)[1].replace(",", ".") == f"{ratio:g}"


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_load_diagram_table_names_the_strokes_working_and_idle_as_the_rest_of_the_note(notes, locale):
    """The engine's gas force acts in the working stroke, the piston moving toward the crank ("backward" along its
    guide): the table of the loads read off its diagram said "backward stroke" at position 2, whose heading says
    "working stroke". Each position's stroke is results.json's."""
    text = strings(locale)
    markdown = notes("engine_slider_crank", locale)
    results = json.loads((notes.folder / f"engine_slider_crank-{locale}" / "results.json").read_text())
    strokes = {position["index"]: position["stroke"] for position in results["positions"]}
    lines = markdown.split("\n")
    (at,) = [k for k, line in enumerate(lines) if caption_of(locale, "note_ld_table").fullmatch(line)]
    table = list(itertools.takewhile(lambda line: line.startswith("|"), lines[at + 2:]))[2:]
    rows = [[cell.strip() for cell in row.strip("|").split("|")] for row in table]
    assert [int(row[0]) for row in rows] == sorted(strokes)
    for row in rows:
        assert row[1] == text[f"{strokes[int(row[0])]}_stroke"], row
    # The headings of the plan positions name the same strokes.
    headings = re.findall(rf"{re.escape(text['position_heading'].format(number='@'))}".replace("@", r"(\d+)")
                          + rf"{re.escape(text['colon'])}[^\n]*{re.escape(text['comma'])}([^\n]+)$",
                          "\n".join(line for line in lines if line.startswith("### ")), flags=re.MULTILINE)
    assert len(headings) == 2
    for number, words in headings:
        assert words == text[f"{strokes[int(number)]}_stroke"]
        assert rows[int(number)][1] == words


FRICTION = '\n[[friction]]\njoint = "O"\nf = 0.1\nradius = 0.02\n'


def errors_intro(markdown: str, locale: str) -> str:
    """The paragraph under the note's heading of the plans' accuracy."""
    heading = next(line for line in markdown.split("\n") if line.startswith("## ") and strings(locale)["note_errors"]
                   in line)
    return markdown.split(heading, 1)[1].strip().split("\n\n", 1)[0]


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_with_friction_the_errors_intro_speaks_of_hand_measured_polygons_only_where_the_scene_gives_them(
        tmp_path, locale):
    """The ratchet's scene gives hand readings of its plans but none of its force polygons: with friction added, the
    note said the reactions measured on the hand-drawn polygons were checked against the polygons without friction.
    With a reaction measured ([measured.5] forces) it says so."""
    text = strings(locale)
    original = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    plain = tmp_path / "rubbing.toml"
    plain.write_text(original + FRICTION, encoding="utf-8")
    unmeasured = errors_intro(run_note(tmp_path, "rubbing", locale, scene=plain), locale)
    # The words of the hand-drawn polygons ("measured on the hand-drawn", «измеренные на планах сил»).
    hand_drawn = {"en": "hand-drawn polygons", "ru": "начерченных вручную"}[locale]
    assert hand_drawn not in unmeasured
    assert text["note_forces_without_friction_unmeasured"] in unmeasured
    measured = tmp_path / "measured.toml"
    measured.write_text(original.replace("[measured.5]\n", "[measured.5]\nforces = { R23 = 50.0 }\n") + FRICTION,
                        encoding="utf-8")
    told = errors_intro(run_note(tmp_path, "measured", locale, scene=measured), locale)
    assert text["note_forces_without_friction"] in told and hand_drawn in told


@pytest.mark.parametrize("locale", ["en", "ru"])
@pytest.mark.parametrize("fixture", ["triad_class_iii", "triad_with_slider"])
def test_the_triads_assur_point_of_the_forces_is_told_by_its_own_lines(notes, fixture, locale):
    """The force section's paragraph on Assur's point said, at the triad with a slider's position 8, "the part of
    an outer reaction along its binary link, or a guide's reaction on its slider": an either/or of every triad. It
    names the two unknowns' own lines, each as the scene's triad has it: a turning leg's along that leg (its joints
    as the scene lists them), a sliding leg's square to its guide at the slider's pin."""
    text = strings(locale)
    (group,) = tomllib.loads((FIXTURES / f"{fixture}.toml").read_text(encoding="utf-8"))["groups"]
    joints, links = group["joints"], group["links"]
    sliding = set(group.get("guides", {}))   # by the leg's inner joint
    legs = {links[n]: (joints[2 * n], joints[2 * n + 1]) for n in range(3)}
    lead = text["note_assur_forces"].split("{")[0]
    paragraphs = [line for line in notes(fixture, locale).split("\n") if line.startswith(lead)]
    assert len(paragraphs) == 2   # one a plan position
    for paragraph in paragraphs:
        point = re.match(re.escape(lead) + r"(Σ\d+)", paragraph)[1]
        closing = re.search(re.escape(text["note_assur_forces"].split("{closing}")[0].split("{unknown}")[1])
                            + r"(.+?)" + re.escape(text["note_assur_forces"].split("{closing}")[1]), paragraph)[1]
        names = closing.split(text["enumeration"])
        assert len(names) == 2
        for name in names:
            link = int(re.fullmatch(r"R\d(\d)n?", name)[1])
            outer, inner = legs[link]
            if inner in sliding:
                told = text["note_assur_force_guide"].format(name=name, link=link, pin=inner)
            else:
                told = text["note_assur_force_leg"].format(name=name, line=outer + inner)
            assert told in paragraph, (name, paragraph)
        assert point == f"Σ{links[3]}"
        # No either/or of kinds of legs the triad may not have.
        assert {"en": " or a guide's", "ru": " или реакция"}[locale] not in paragraph
