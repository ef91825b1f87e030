"""A vector too short to draw (under 0.25 mm, render.plans.ZERO_MM) is named wherever a drawing leaves it out.

- A force polygon's caption names each of its vectors shorter than 0.25 mm at its μF with its value, in the words a
  plan's caption uses: the slider-driven four-bar's inertia forces Fu3, Fu4 (hundredths of a newton at μF = 10 N/mm)
  were dropped from the polygon with no word, and a student measuring it found two sides missing.
- The note's tables of the vector equations say "not drawn" beside a segment the plan leaves out (n5n6′ = 0.13 mm),
  as its polygon tables do, rather than give a length the reader looks for on the plan in vain.

The vectors expected are those of the analysis whose length over the drawing's scale is under 0.25 mm, found here
from the plans' and polygons' own points, not from a caption or a table.
"""

from __future__ import annotations

import json
import math
import re
import tomllib
from pathlib import Path

import pytest
from sheet_texts import flat

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.locale import load_symbol, strings

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
# The drawings leave out a vector shorter than this (mm), as their captions state.
SHORTEST_DRAWN_MM = 0.25
# A force or a plan vector this small is a nought the arithmetic left, neither drawn nor named.
NOUGHT_N = 1e-10
NOUGHT_MM = 1e-9

_analyses: dict[str, object] = {}
_runs: dict[tuple[str, str], Path] = {}


def analysis_of(fixture: str):
    if fixture not in _analyses:
        _analyses[fixture] = analyse(graphplan.load(FIXTURES / f"{fixture}.toml"))
    return _analyses[fixture]


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """The folder of a run of ``fixture`` in ``locale`` (its force drawings and note), each made once."""
    folder = tmp_path_factory.mktemp("short")

    def made(fixture: str, locale: str) -> Path:
        if (fixture, locale) not in _runs:
            out = folder / f"{fixture}-{locale}"
            assert main(["run", str(FIXTURES / f"{fixture}.toml"), "--out", str(out), "--only", "forces,note",
                         "--locale", locale]) == 0
            _runs[fixture, locale] = out
        return _runs[fixture, locale]
    return made


def svg_texts(path: Path) -> list[tuple[float, float, str]]:
    """(x, y, text) of every text of an SVG drawing, in the order it is written, its runs read on as one."""
    source = flat(path.read_text(encoding="utf-8"))
    return [(float(x), float(y), text.replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">"))
            for x, y, text in re.findall(r'<text[^>]*?x="([-\d.]+)" y="([-\d.]+)">([^<]*)</text>', source)]


def named_short(path: Path, locale: str) -> dict[str, float]:
    """The vectors the drawing's captions name as too short to draw, with the values written: the lines under
    each "not drawn, shorter than 0.25 mm:" line, in the same column, one caption line apart."""
    text = strings(locale)
    # The drawings write the locale's decimal mark: 0,25 мм.
    heading = text["plan_too_short"].format(least=f"{SHORTEST_DRAWN_MM:g}".replace(".", text["decimal_mark"]))
    item = re.compile(rf"(\S+) = ([\d.,]+) {re.escape(text['newton'])}")
    texts = svg_texts(path)
    named: dict[str, float] = {}
    for k, (x, y, line) in enumerate(texts):
        if line != heading:
            continue
        above = y
        for x_next, y_next, following in texts[k + 1:]:
            items = following.split("; ")
            if x_next != x or not 0 < y_next - above < 12 or not all(item.fullmatch(piece) for piece in items):
                break
            for piece in items:
                name, value = item.fullmatch(piece).groups()
                assert name not in named, (path.name, name)
                named[name] = float(value.replace(",", "."))
            above = y_next
    return named


def too_short_forces(position) -> dict[str, float]:
    """Each polygon vector of the position whose length at its group's μF is under 0.25 mm but no nought."""
    return {vector.name: abs(vector.force) for group in position.forces.groups
            for vector in group.polygon.vectors
            if abs(vector.force) > NOUGHT_N and abs(vector.force) / group.scale < SHORTEST_DRAWN_MM}


@pytest.mark.parametrize("locale", ["en", "ru"])
@pytest.mark.parametrize("fixture", ["slider_driven", "tangent_mechanism_prp", "offset_slider_crank"])
def test_a_force_polygon_names_exactly_its_vectors_too_short_to_draw(run, fixture, locale):
    analysis = analysis_of(fixture)
    folder = run(fixture, locale)
    positions = [position for position in analysis.plans if position.forces is not None]
    assert positions
    for position in positions:
        # Named as the locale writes them: the Russian Fи3 of Fu3.
        expected = {load_symbol(name, strings(locale)): value for name, value in too_short_forces(position).items()}
        named = named_short(folder / f"forces_{position.number}.svg", locale)
        assert set(named) == set(expected), (position.number, named, expected)
        for name, value in named.items():
            # Written to four significant figures.
            assert value == pytest.approx(expected[name], rel=5e-4), (position.number, name)
    if fixture == "slider_driven":
        assert all({"Fu3", "Fu4"} <= set(too_short_forces(position)) for position in positions)
    if fixture == "offset_slider_crank":
        # A scene whose polygons draw every vector: no such line at all.
        assert not any(too_short_forces(position) for position in positions)


def test_the_inertia_forces_named_are_the_links_masses_times_their_centres_accelerations(run):
    """Fu3 = m3·aS3 of the slider-driven four-bar, from results.json's accelerations and the scene's masses: the
    value the caption gives for the vector left out is the force, not a length."""
    folder = run("slider_driven", "en")
    results = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    scene = tomllib.loads((FIXTURES / "slider_driven.toml").read_text(encoding="utf-8"))
    for position in results["positions"]:
        path = folder / f"forces_{position['index']}.svg"
        if not path.exists():
            continue
        named = named_short(path, "en")
        for link in (3, 4):
            centre = scene["links"][str(link)]["centre"]
            expected = scene["links"][str(link)]["mass"] * math.hypot(*position["points"][centre]["a"])
            assert named[f"Fu{link}"] == pytest.approx(expected, rel=5e-4)


def equation_rows(note: str, locale: str):
    """(position, kind, segment cell) of every row of the note's vector-equation tables."""
    text = strings(locale)
    caption = re.compile(re.escape(text["note_equation_table"]).replace(r"\{vector\}", r"(\S+)")
                         .replace(r"\{number\}", r"(\d+)"))
    current = None
    for line in note.splitlines():
        found = caption.search(line)
        if found and not line.startswith("|"):
            current = (int(found.group(2)), "velocity" if found.group(1).startswith("V") else "acceleration")
            continue
        if line.startswith("|") and current is not None:
            cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
            if len(cells) == 4 and not set(cells[0]) <= set("-: "):
                yield (*current, cells[2])
        elif line.strip() and current is not None and not line.startswith(("Table", "Таблица")):
            # Past its table: the next paragraph belongs to no equation's table.
            current = None


def short_segments(analysis, locale: str) -> dict[tuple[int, str], set[str]]:
    """For each position and plan, the segments (their two letters, as the note writes them) of the vectors the
    plan lays off that are shorter than 0.25 mm at its scale: the steps' vectors and the pole's."""
    pole = strings(locale)["acceleration_pole"]
    short: dict[tuple[int, str], set[str]] = {}
    for position in analysis.plans:
        for kind, plan in position.plans.items():
            ends = {(vector.start, vector.end) for step in plan.steps for vector in step.vectors}
            ends |= {("p", letter) for letter in plan.images.values() if letter != "p"}
            found = set()
            for start, end in ends:
                if NOUGHT_MM < abs(plan.points[end] - plan.points[start]) / plan.scale < SHORTEST_DRAWN_MM:
                    found.add("".join(pole if kind == "acceleration" and letter == "p" else letter
                                      for letter in (start, end)))
            short[position.number, kind] = found
    return short


@pytest.mark.parametrize("locale", ["en", "ru"])
@pytest.mark.parametrize("fixture", ["triad_class_iii", "stephenson_six_bar", "offset_slider_crank"])
def test_the_note_says_a_plan_segment_too_short_to_draw_is_not_drawn(run, fixture, locale):
    text = strings(locale)
    note = (run(fixture, locale) / "note.md").read_text(encoding="utf-8")
    short = short_segments(analysis_of(fixture), locale)
    words = text["note_segment_short"].format(least=str(SHORTEST_DRAWN_MM).replace(".", text["decimal_mark"]))
    rows = list(equation_rows(note, locale))
    assert rows
    marked = 0
    for number, kind, cell in rows:
        segment = cell.split(" = ")[0]
        if segment in short[number, kind] and " = " in cell:
            assert cell.endswith(text["semicolon"] + words), (number, kind, cell)
            length = float(cell.split(" = ")[1].split(text["semicolon"].strip())[0].replace(",", "."))
            assert length < SHORTEST_DRAWN_MM
            marked += 1
        else:
            assert words not in cell, (number, kind, cell)
    if fixture == "offset_slider_crank":
        assert marked == 0
    else:
        # n5n6′ = 0.13 of the triad's acceleration plan, en5 = 0.08 of the Stephenson six-bar’s.
        assert marked >= 1
