"""The explanatory note is read by a teacher, who has the note and its figures, not the run's folder or the scene:
no sentence of it names a drawing's file (forces_N.svg) or a key of the scene ([measured] forces,
positions.working), in any language.  errors.md, read by the student who ran the program, may name them, but
after saying in words what they are."""

from __future__ import annotations

import functools
import re

import pytest
from scene_texts import crank_rocker_working_its_quicker_stroke

import graphplan
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown
from graphplan.report.tables import markdown as errors_markdown
from graphplan.starters import starter

LOCALES = ("en", "ru", "zh")
# A file the run writes, a table of the scene, or a key under one: what the note's reader cannot look up.
FILE_OR_KEY = re.compile(r"\w+\.(?:svg|md|csv|json|toml)\b|\[\w+\]|\b(?:positions|drawing|driver|measured)\.\w+")


def _sentences(note: str) -> str:
    """The note without its pictures' lines, whose targets are the files the figures show."""
    return "\n".join(line for line in note.splitlines() if not line.startswith("!["))


@functools.cache
def _r45_on_the_friction_polygon_mm() -> float:
    """R45 at the shaper's position 3 as its polygon with friction draws it, to 0.1 mm.  The starters of the three
    languages differ only in words (the title, the guide's name), not in a number: the polygon is read once."""
    return _r45_mm(analyse(graphplan.scene.loads(starter("shaper", "en"))))


def _r45_mm(analysis) -> float:
    plan = next(p for p in analysis.plans if p.number == 3)
    reaction = abs(complex(analysis.with_friction.reaction("R45").force[plan.index]))
    return round(reaction / plan.forces.scale_of("R45"), 1)


def _shaper_read_off_the_friction_polygon(locale: str):
    """The shaper's position 3 with R45 measured on its polygon with friction: the note then says which polygons the
    readings are checked against, and that they stand nearer the other ones."""
    millimetres = _r45_on_the_friction_polygon_mm()
    measured = analyse(graphplan.scene.loads(
        starter("shaper", locale) + f"\n[measured.3]\nforces = {{ R45 = {millimetres} }}\n"))
    assert _r45_mm(measured) == millimetres   # the reading is this scene's own polygon's
    return measured


@pytest.fixture(scope="module", params=LOCALES)
def shaper(request):
    return request.param, _shaper_read_off_the_friction_polygon(request.param)


def test_the_note_names_the_polygons_with_and_without_friction_in_words_alone(shaper):
    locale, analysis = shaper
    note = note_markdown(analysis, figures={"forces_3.svg", "forces_friction_3.svg"})
    words = {"en": ("these are the force polygons without friction", "stands nearer the polygons with friction (R45 = "),
             "ru": ("это планы сил без учёта трения", "ближе к планам сил с трением (R45 = "),
             "zh": ("此处为不计摩擦的力多边形", "更接近计摩擦的力多边形（R45 = ")}[locale]
    assert all(phrase in note for phrase in words), words
    assert FILE_OR_KEY.findall(_sentences(note)) == []


def test_errors_md_says_in_words_what_a_file_or_key_it_names_is(shaper):
    locale, analysis = shaper
    errors = errors_markdown(analysis)
    before = {"en": ("polygons without friction (forces_N.svg)", "the hand-drawn polygons ([measured] forces)",
                     "polygons with friction (forces_friction_3.svg: "),
              "ru": ("планы сил без учёта трения (forces_N.svg)", "начерченных вручную ([measured] forces)",
                     "планам сил с трением (forces_friction_3.svg: "),
              "zh": ("不计摩擦的力多边形（forces_N.svg）", "手绘力多边形上量取的反力（[measured] forces）",
                     "计摩擦的力多边形（forces_friction_3.svg：")}[locale]
    assert all(phrase in errors for phrase in before), before


@pytest.mark.parametrize("locale", LOCALES)
def test_a_quicker_working_stroke_is_told_without_the_scene_s_key(locale):
    analysis = analyse(graphplan.scene.loads(crank_rocker_working_its_quicker_stroke(locale)))
    note = note_markdown(analysis)
    assert "K = " in note and "K < 1" in note
    assert FILE_OR_KEY.findall(_sentences(note)) == []
