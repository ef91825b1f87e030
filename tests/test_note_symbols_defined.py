"""A symbol the note uses is said what it is where it is first used, as a textbook does: a link's point under
another link's pin or on a guide (A3, A4, E1), a length to such a point (lCA4), the reactions Rij and their
components, and the sign of a load's moment F·h on Zhukovsky's lever.

Each symbol is found in the note itself (the points with a link's number in the vector equations, the lengths to
them in the similarity lines), each definition by its locale key's sentence; the first use may not come before it.
"""

from __future__ import annotations

import dataclasses
import re
import tomllib
from functools import cache
from importlib import resources
from pathlib import Path

import pytest

import graphplan
from graphplan import starters
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown
from graphplan.run import as_asked

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
SCENES = ("quick_return_slotted_lever", "tangent_mechanism_prp", "shaper_six_bar", "slotted-lever", "shaper")
LOCALES = ("en", "ru", "zh")


@cache
def words(locale: str) -> dict[str, str]:
    return tomllib.loads(resources.files("graphplan").joinpath("locales", f"{locale}.toml").read_text("utf-8"))


@cache
def note_of(name: str, locale: str) -> str:
    if name in starters.KINDS:
        scene = graphplan.scene.load(tomllib.loads(starters.starter(name)))
    else:
        scene = graphplan.load(FIXTURES / f"{name}.toml")
    return note_markdown(analyse(as_asked(dataclasses.replace(scene, locale=locale), sheet="none")))


def template(text: str, **known: str) -> re.Pattern[str]:
    """The locale's sentence as a pattern: the fields given filled in, every other field any words."""
    parts = re.split(r"(\{\w+\})", text)
    return re.compile("".join(re.escape(known[part[1:-1]]) if part[1:-1] in known else ".+?"
                              if part.startswith("{") and part.endswith("}") else re.escape(part) for part in parts))


def first_use(note: str, symbol: str) -> int:
    match = re.search(rf"{re.escape(symbol)}(?!\d)", note)
    assert match, f"{symbol} not in the note"
    return match.start()


def coincident_points(note: str, locale: str) -> set[str]:
    """The points the vector equations name with a link's number after the point's letter (VA4A3, VE1)."""
    lead = words(locale)["note_vector_equation"].split("{")[0]
    equations = [line for line in note.splitlines() if line.startswith(lead)]
    return {token for line in equations for token in re.findall(r"[A-Z]\d+", line)}


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("name", SCENES)
def test_points_of_links_under_a_pin_defined_before_first_use(name, locale):
    note = note_of(name, locale)
    points = coincident_points(note, locale)
    assert points, "a sliding pair's equations name the coincident points"
    lengths = {length for point in points for length in re.findall(rf"l[A-Z]{point}(?!\d)", note)}
    assert lengths or name == "tangent_mechanism_prp"
    for symbol in points:
        definitions = [template(words(locale)[key], name=symbol).search(note)
                       for key in ("note_coincident_point", "note_coincident_frame_point")]
        found = [match.start() for match in definitions if match]
        assert found, f"{symbol} is never said what it is"
        assert min(found) <= first_use(note, symbol), f"{symbol} is used before it is said what it is"
    for symbol in lengths:
        definition = template(words(locale)["note_length_to_coincident"], length=symbol).search(note)
        assert definition, f"{symbol} is never said what it is"
        assert definition.start() <= first_use(note, symbol)


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("name", ("shaper_six_bar", "slotted-lever"))
def test_reactions_and_lever_moments_defined_before_first_use(name, locale):
    note = note_of(name, locale)
    reaction = re.search(r"R\d\d", note)
    assert reaction
    assert note.count(words(locale)["note_reactions_named"]) == 1
    assert note.index(words(locale)["note_reactions_named"]) <= reaction.start()
    sign = words(locale)["note_lever_sign"]
    assert sign in note
    assert note.index(sign) <= note.index("F·h")
