"""The note works Zhukovsky's lever with friction as the force sheet with friction draws it.

The sheet with friction draws its own lever, the pairs' friction loads (Ff16, the couples Mf12′, Mf12″) among its
loads, its arms lettered h1, h2, …, hb and its ΣMp written with them; the note gave that lever one sentence, its Mb
and how far it parts from the polygons, so that a student checking the note against the sheet found no worked lever
with friction.  Read back from both as written: every load ΣMp on forces_friction_N.svg names an arm for stands in
the note's table of the lever with friction with that arm and the length drawn on the sheet (the lever worked at the
μV the sheet drew it at), every friction load the note works out stands in it, and the balancing load its equation
gives is the lever's with friction, not the one without.
"""

from __future__ import annotations

import re

import pytest
from lever_arms import check_arms_agree, levers, note_arms
from scene_texts import journal_friction, wedge_lift

import graphplan
from graphplan.locale import load_symbol, strings
from graphplan.report import forces as force_report
from graphplan.run import run
from graphplan.starters import starter

CRANK_ROCKER = starter("crank-rocker") + journal_friction({"O": 0.02, "A": 0.015, "B": 0.015, "C": 0.02})
# Two slides, the floor's and the incline's: friction forces Ff12, Ff23 on the lever, not couples.
WEDGE = wedge_lift(20.0, 2000.0, -0.05, count=5) + """
[[friction]]
joint = "A"
links = [1, 2]
f = 0.12
[[friction]]
joint = "B"
links = [2, 3]
f = 0.15
"""


def scene_text(name: str) -> str:
    return {"crank-rocker": CRANK_ROCKER, "wedge": WEDGE}.get(name) or starter(name, "en")


def friction_loads_named(made, locale: str) -> dict[int, set[str]]:
    """By position, the friction loads the construction with friction applied, as the note names them: a couple's
    with the primes of its two forces on the lever."""
    text = strings(locale)
    found = {}
    for plan in made.analysis.plans:
        rubbing = plan.with_friction
        if rubbing is None or rubbing.locked:
            continue
        names = {load.name for group in rubbing.groups for load in group.loads
                 if re.fullmatch(r"[FM]f\d+", load.name) and abs(load.force if load.name[0] == "F" else load.moment)}
        found[plan.number] = {load_symbol(name, text) for name in names}
    return found


@pytest.mark.parametrize(("name", "locale"), [("shaper", "en"), ("shaper", "ru"), ("crank-rocker", "zh"),
                                              ("wedge", "en"), ("wedge", "ru")])
def test_the_note_works_the_lever_with_friction_as_the_sheet_with_friction_draws_it(tmp_path, name, locale):
    path = tmp_path / "scene.toml"
    path.write_text(scene_text(name), encoding="utf-8")
    # On no sheet: choosing μl by laying out course sheets this run does not write was most of the shaper's run, and
    # every file of each case here is the same bytes without it (diffed once); the sheets' own case is the next test.
    made = run(graphplan.load(path), tmp_path / "out", only=["forces", "lever", "note"], locale=locale, sheet="none")
    out = tmp_path / "out"
    check_arms_agree(out, made, locale, friction=True)
    markdown = (out / "note.md").read_text(encoding="utf-8")
    tables = note_arms(markdown, locale, "note_friction_lever_table")
    drawn = list(levers(made, friction=True))
    assert sorted(tables) == sorted(number for number, _, _ in drawn)
    text = strings(locale)
    for number, applied in friction_loads_named(made, locale).items():
        rows = {load.rstrip("′″") for load, _, _ in tables[number]}
        assert applied and applied <= rows, f"position {number}: {applied - rows} not on the note's lever"
    # Each lever's Fb gives its own balancing load, worked after its table: the one with friction, not without.
    mark = "," if locale == "ru" else "."
    caption = re.escape(text["note_friction_lever_table"]).replace(re.escape("{number}"), r"(\d+)")
    worked = dict(re.findall(caption + r"\n(.*?)\n!\[", markdown, re.DOTALL))
    plans = {plan.number: plan for plan in made.analysis.plans}
    for number, lever, _ in drawn:
        found = force_report.number(abs(lever.balancing), 6, mark)
        assert f"{found} " in worked[str(number)], f"position {number}: no {found} worked on the lever with friction"
        without = force_report.number(abs(plans[number].lever.balancing), 6, mark)
        assert without == found or without not in worked[str(number)]


# A run with the sheets draws each sheet with friction too, its lever at the μV the sheets drew it at.
def test_the_lever_with_friction_agrees_where_the_sheets_are_drawn_too(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_text(CRANK_ROCKER, encoding="utf-8")
    made = run(graphplan.load(path), tmp_path / "out", sheet="A3")
    check_arms_agree(tmp_path / "out", made, "en", friction=True)


def test_the_lever_with_friction_is_worked_at_the_scale_its_own_sheet_drew_it_at():
    """The sheets may draw a lever a step smaller than the plan's enlarged one, each sheet's at its own μV: the
    lever with friction is measured at forces_friction_N.svg's, not at the sheet without friction's.  Each arm the
    note writes is the lever's perpendicular (m/s on the plan) over the μV given for its sheet."""
    from graphplan.analysis import analyse
    from graphplan.report.note import note_markdown
    from graphplan.scene import loads as scene_from_text

    analysis = analyse(scene_from_text(CRANK_ROCKER))
    plan = next(plan for plan in analysis.plans if plan.lever_with_friction is not None)
    lever = plan.lever_with_friction
    plain_at, friction_at = plan.velocity.scale * 3, plan.velocity.scale * 2
    markdown = note_markdown(analysis, lever_scales={f"forces_{plan.number}.svg": plain_at,
                                                     f"forces_friction_{plan.number}.svg": friction_at})
    rows = note_arms(markdown, "en", "note_friction_lever_table")[plan.number]
    terms = {term.name: term for term in lever.terms}
    measured = [(name, length) for name, arm, length in rows if arm is not None]
    assert measured
    for name, length in measured:
        assert length == pytest.approx(terms[name].arm / friction_at, abs=0.006), name
