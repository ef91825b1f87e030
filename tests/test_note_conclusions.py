"""The note ends with its conclusions, as a course project's explanatory note does, and every number they give is
the one the section that found it wrote: the structure formula, K, the plans' largest errors (the largest in magnitude
of the error tables' δ, velocities and accelerations apart), the balancing load by the polygons and by the lever with
their difference, the efficiency over the cycle, the flywheel's JF (against results.json).

The numbers are parsed out of the conclusions and looked up in the note's own sentences and tables (each found by its
locale key's words), never compared with the code's record of them.
"""

from __future__ import annotations

import json
import re
import tomllib
from functools import cache
from importlib import resources
from pathlib import Path

import pytest

from graphplan.cli import main

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
LOCALES = ("en", "ru", "zh")


@cache
def words(locale: str) -> dict[str, str]:
    return tomllib.loads(resources.files("graphplan").joinpath("locales", f"{locale}.toml").read_text("utf-8"))


# The fields that hold a number, matched whole: "K = 1.452." has a full stop after it that a number's mark is not.
NUMBERS = {"exact", "ratio", "working", "idle", "efficiency", "lever", "polygons", "delta", "percent", "inertia", "number"}
NUMBER = r"\(?[−-]?\d+(?:[.,]\d+)?\)?"


def pattern(text: str) -> str:
    """The locale's sentence as a pattern, each field a named group (a field repeated, the same words again)."""
    seen: set[str] = set()
    out = []
    for part in re.split(r"(\{\w+\})", text):
        field = part[1:-1] if part.startswith("{") and part.endswith("}") else None
        if field is None:
            # set_close takes the spaces the joined words left beside Chinese full-width punctuation
            out.append(re.escape(part).replace("\\ ", " ?"))
        elif field in seen:
            out.append(f"(?P={field})")
        else:
            seen.add(field)
            out.append(f"(?P<{field}>{NUMBER if field in NUMBERS else '.+?'})")
    return "".join(out)


def number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """note.md and results.json of the shaper's starter (friction, dynamics) and of a fixture, in each language."""
    @cache
    def made(name: str, locale: str) -> tuple[str, dict]:
        folder = tmp_path_factory.mktemp(f"{name}-{locale}")
        scene = folder / "scene.toml"
        if name == "shaper":
            assert main(["new", "shaper", "--out", str(scene)]) == 0
        else:
            scene.write_text((FIXTURES / f"{name}.toml").read_text(encoding="utf-8"), encoding="utf-8")
        pieces = "note,dynamics" if name == "shaper" else "note"
        assert main(["run", str(scene), "--out", str(folder), "--locale", locale, "--only", pieces,
                     "--sheet", "none"]) == 0
        return ((folder / "note.md").read_text(encoding="utf-8"),
                json.loads((folder / "results.json").read_text(encoding="utf-8")))
    return made


def conclusions(note: str, locale: str) -> tuple[str, list[str]]:
    """The note before its conclusions, and the conclusions' list items; the conclusions the note's last section."""
    headings = [match for match in re.finditer(r"^## (.+)$", note, re.MULTILINE)]
    assert headings[-1].group(1).endswith(words(locale)["note_conclusion"])
    body = note[headings[-1].end():]
    items = [line[2:] for line in body.splitlines() if line.startswith("- ")]
    assert items
    return note[:headings[-1].start()], items


def item(items: list[str], locale: str, key: str) -> list[re.Match]:
    found = [re.fullmatch(pattern(words(locale)[key]) + r"[;；.。]", line) for line in items]
    return [match for match in found if match]


def error_tables(before: str, locale: str) -> dict[int, list[dict[str, str]]]:
    """Each plan position's error table as rows of header → cell."""
    caption = pattern(words(locale)["table_caption"]).replace("(?P<caption>.+?)", "(?P<caption>.+)") + "$"
    title = pattern(words(locale)["note_errors_table"])
    tables, lines = {}, before.splitlines()
    for k, line in enumerate(lines):
        match = re.fullmatch(caption, line)
        if not (match and (position := re.fullmatch(title, match.group("caption")))):
            continue
        rows = [row.strip("|").split("|") for row in table_lines(lines[k + 2:])]
        header = [cell.strip() for cell in rows[0]]
        tables[int(position.group("number"))] = [dict(zip(header, (c.strip() for c in row), strict=True))
                                                 for row in rows[2:]]
    return tables


def grid_largest(before: str, locale: str, source: str) -> list[tuple[str, int]]:
    """The table of every position's velocity plans: each position's largest δ of ``source``, as written, with the
    position's number (its column's head)."""
    text = words(locale)
    name = text["velocity_plans_largest"].format(source=text[f"source_{source}"])
    found, heads = [], []
    for line in before.splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if cells[:2] == [text["errors_quantity"], text["column_unit"]]:
            # The grid's head numbers its positions; an error table's names its columns.
            heads = [int(cell) for cell in cells[2:]] if all(cell.isdigit() for cell in cells[2:]) else []
        elif cells[0] == name and heads:
            found += [(cell, number) for cell, number in zip(cells[2:], heads, strict=True) if cell]
    return found


def table_lines(lines: list[str]) -> list[str]:
    """The Markdown table's lines at the head of ``lines``."""
    out = []
    for line in lines:
        if not line.startswith("|"):
            break
        out.append(line)
    return out


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("name", ("shaper", "quick_return_slotted_lever"))
def test_conclusions_repeat_what_the_note_found(run, name, locale):
    note, results = run(name, locale)
    before, items = conclusions(note, locale)
    text = words(locale)

    (structure,) = item(items, locale, "note_conclusion_structure")
    formula = re.search(pattern(text["note_structure_formula"]), before)
    assert (structure.group("formula"), structure.group("klass")) == (formula.group("formula"), formula.group("klass"))
    # The degrees of freedom under the symbol the note's formula gives them (the Chinese F, not W).
    symbol = text["dof_formula"].split("=")[0].strip()
    assert re.search(rf"(?<!\w){symbol} = {structure.group('w')}(?!\d)", structure.group(0)), structure.group(0)

    (ratio,) = item(items, locale, "note_conclusion_ratio")
    strokes = re.search(pattern(text["note_strokes"]), before)
    assert ratio.group("ratio") == strokes.group("ratio")
    assert number(ratio.group("ratio")) == pytest.approx(number(strokes.group("working")) / number(strokes.group("idle")),
                                                         rel=1e-3)

    tables = error_tables(before, locale)
    assert tables
    for key, units in (("note_conclusion_velocity_errors", (text["unit_m_per_s"], text["unit_rad_per_s"])),
                       ("note_conclusion_acceleration_errors", (text["unit_m_per_s2"], text["unit_rad_per_s2"]))):
        (errors,) = item(items, locale, key)
        # Each source's largest, split at the commas outside the brackets that name its quantity and position.
        for part in re.split(r"(?:, |，)(?![^(（]*[)）])", errors.group("errors")):
            source = next(source for source in ("construction", "drafting", "measured")
                          if part.startswith(text[f"source_{source}"]))
            column = text["errors_delta"].format(source=text[f"source_{source}"])
            deltas = [(abs(number(row[column])), row[column], row[text["errors_quantity"]], position)
                      for position, rows in tables.items() for row in rows
                      if row[text["column_unit"]] in units and row.get(column, "—") not in ("", "—")]
            # The velocities' over the velocity plans of every position too, whose table names no quantity.
            grid = grid_largest(before, locale, source) if key == "note_conclusion_velocity_errors" else []
            largest = max([*deltas, *((abs(number(written)), written, None, position) for written, position in grid)],
                          key=lambda delta: delta[0])
            named = re.fullmatch(pattern(text["note_conclusion_error_of"]), part)
            if named:
                assert (named.group("percent"), named.group("quantity"), int(named.group("number"))) in {
                    (written, quantity, position) for size, written, quantity, position in deltas} or (
                    named.group("percent"), int(named.group("number"))) in set(grid)
                assert abs(number(named.group("percent"))) == largest[0]
            else:
                plain = re.fullmatch(pattern(text["note_conclusion_error"]), part)
                assert plain and largest[0] == 0 == number(plain.group("percent"))

    differences = [match.groupdict() for match in re.finditer(pattern(text["note_lever_difference"]), before)]
    balancing = item(items, locale, "note_conclusion_balancing")
    assert len(balancing) == len(differences) > 0
    for concluded, found in zip(balancing, differences, strict=True):
        assert concluded.group("lever") == found["lever"]
        assert concluded.group("polygons") in (found["polygons"], found["polygons"].strip("()"))
        assert concluded.group("delta") == found["delta"]

    efficiency = item(items, locale, "note_conclusion_efficiency")
    flywheel = item(items, locale, "note_conclusion_flywheel")
    if name == "shaper":
        (efficiency,) = efficiency
        cycle = re.search(pattern(text["forces_cycle_efficiency"]), before)
        assert efficiency.group("efficiency") == cycle.group("efficiency")
        (flywheel,) = flywheel
        assert number(flywheel.group("inertia")) == pytest.approx(results["dynamics"]["flywheel_inertia"], rel=1e-4)
        taken = re.search(pattern(text["note_dyn_flywheel_taken"]), before)
        assert flywheel.group("inertia") == taken.group("exact")
    else:
        assert not efficiency and not flywheel
