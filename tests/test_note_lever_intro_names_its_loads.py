"""The note's intro to each worked Zhukovsky's lever tells how the loads the lever carries are put on it, and names no
load it does not carry: the inertia moments Mu as couples, the friction forces Ff at their points' images, the friction
moments Mf as couples, each where the lever's table of moments under the intro has rows of them.

The intros named them all whatever the scene had: "(the moments Mu are applied as couples of forces across their
links)" over a Scotch yoke's table with no inertia moment, and "each friction moment Mf as a couple of forces" over
a wedge's, whose slides have no journal to rub in.  Read back from the note as written, in each language: every
intro, and the rows of the table it leads.
"""

from __future__ import annotations

import re

import pytest
from lever_arms import note_arms
from note_scenes import scene_path
from test_note_friction_lever import CRANK_ROCKER, scene_text

import graphplan
from graphplan.locale import strings
from graphplan.run import run

# The crank-rocker's journals with its links' moments of inertia left out: friction moments and no inertia moment.
WITHOUT_INERTIA = re.sub(r"(?m)^inertia\s*=.*\n", "", CRANK_ROCKER)
# Each lever's intro and the caption of the table it leads.
LEVERS = (("note_lever_intro", "note_lever_table"), ("note_friction_lever_intro", "note_friction_lever_table"))


def symbols(locale: str) -> dict[str, str]:
    """Each kind of load the intros speak of, as the locale writes it (Mи in Russian)."""
    return {"Mu": strings(locale)["symbol_inertia_moment"], "Ff": "Ff", "Mf": "Mf"}


def rows_of(names: list[str], locale: str) -> set[str]:
    """The kinds of load among the rows of a lever's table: a couple's forces (Mu3′, Mu3″) and friction forces."""
    found = set()
    for kind, symbol in symbols(locale).items():
        couple = "" if kind == "Ff" else "[′″]"
        if any(re.fullmatch(rf"{re.escape(symbol)}\d+{couple}", name) for name in names):
            found.add(kind)
    return found


def named_in(intro: str, locale: str) -> set[str]:
    return {kind for kind, symbol in symbols(locale).items() if re.search(rf"(?<!\w){re.escape(symbol)}(?!\w)", intro)}


def intros(markdown: str, locale: str) -> list[tuple[str, int, str]]:
    """Each lever's intro as (its table's caption key, the position of its table, the intro): the paragraph that
    opens as the locale's intro does, paired with the next caption of its lever's table."""
    text = strings(locale)
    found, waiting = [], None
    for line in markdown.splitlines():
        for intro, table in LEVERS:
            if line.startswith(text[intro].split("{")[0]):
                waiting = (table, line)
            caption = re.search(re.escape(text[table]).replace(re.escape("{number}"), r"(\d+)") + "$", line)
            if caption and waiting is not None and waiting[0] == table:
                found.append((table, int(caption[1]), waiting[1]))
                waiting = None
    return found


@pytest.mark.parametrize(("source", "name", "locale"), [
    ("fixture", "scotch_yoke", "en"),  # no inertia moment
    ("fixture", "engine_slider_crank", "ru"),
    ("scene", "wedge", "en"), ("scene", "wedge", "ru"), ("scene", "wedge", "zh"),  # slides: Ff alone
    ("scene", "crank-rocker", "zh"),  # journals: Mf and Mu
    ("scene", "without inertia", "en"),  # journals: Mf alone
    ("scene", "shaper", "ru"),  # a slide and journals: Ff, Mf and Mu
])
def test_each_lever_intro_names_the_loads_its_table_has(tmp_path, source, name, locale):
    if source == "fixture":
        path = scene_path(tmp_path, source, name)
    else:
        path = tmp_path / "scene.toml"
        path.write_text(WITHOUT_INERTIA if name == "without inertia" else scene_text(name), encoding="utf-8")
    run(graphplan.load(path), tmp_path / "out", only=["note"], locale=locale)
    markdown = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    worked = intros(markdown, locale)
    tables = {table: note_arms(markdown, locale, table) for _, table in LEVERS}
    assert sorted((table, number) for table, number, _ in worked) == sorted(
        (table, number) for table, found in tables.items() for number in found), "a lever's table with no intro"
    for table, number, intro in worked:
        carried = rows_of([load for load, _, _ in tables[table][number]], locale)
        assert named_in(intro, locale) == carried, f"{table}, position {number}: {intro}"
