"""A teacher's review of the accuracy report (the error tables of the plans, the force polygons and the balancing
load): what it prints is checked against the scene's own readings and an independent reading of the plans."""

import dataclasses

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.report.note import note_markdown
from graphplan.report.tables import markdown

SHAPER = "fixtures/shaper_six_bar.toml"
POSITION = 3


def _shaper(measured, locale="en", **positions):
    scene = graphplan.load(SHAPER)
    scene = dataclasses.replace(scene, locale=locale, measured={POSITION: measured},
                                positions=dataclasses.replace(scene.positions, **positions))
    return analyse(scene)


def _pa4(analysis):
    """The length (mm) of pa4, the acceleration of the lever's point under the block, on the plan as constructed."""
    plan = next(p for p in analysis.plans if p.number == POSITION).plans["acceleration"]
    return abs(plan.mm("a4") - plan.mm("p"))


def test_a_reaction_read_as_another_segment_is_told_in_the_table_s_language_with_its_length_once():
    # R23 typed as the length of a segment of the acceleration plan: the table names the segment; the reading is
    # shown as the student gave it, its millimetres once and in the locale's words (it said "R23 = 40 mm at μF =
    # 50 N/mm мм", English inside the Russian sentence and the unit twice).
    typed = round(_pa4(_shaper({})), 1)
    for locale, millimetre, mark in (("en", "mm", "."), ("ru", "мм", ","), ("zh", "mm", ".")):
        table = markdown(_shaper({"forces": {"R23": typed}}, locale))
        line = next(line for line in table.splitlines() if f"R23 = {typed:g}".replace(".", mark) in line)
        assert f"R23 = {f'{typed:g}'.replace('.', mark)} {millimetre}" in line, line
        assert "N/mm" not in line and " at " not in line, line
        assert "pa4" in line, line


def _ram_at_rest_position(analysis):
    """The position whose ram stands still, found here from the motion's own points: E's speed against A's."""
    return min((p for p in analysis.velocity_plans),
               key=lambda p: abs(analysis.motion.points["E"].v[p.number - 1]) / abs(analysis.motion.points["A"].v[0]))


def test_a_reading_of_a_quantity_that_vanishes_gets_a_dash_and_the_reports_say_what_it_means():
    # At the extreme position the ram stands: VE = 0, and a hand reading pe = 1 mm has no relative error.  The
    # tables wrote δ — and no sentence of errors.md or the note said what the dash meant.
    every = tuple(range(1, 13))
    first = _shaper({}, velocity_plans=every)
    resting = _ram_at_rest_position(first)
    assert abs(first.motion.points["E"].v[resting.number - 1]) < 1e-9
    for locale in ("en", "ru", "zh"):
        scene = dataclasses.replace(graphplan.load(SHAPER), locale=locale,
                                    measured={resting.number: {"velocity": {"pe": 1.0}}})
        scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, velocity_plans=every))
        analysis = analyse(scene)
        (row,) = [row for position in analysis.velocity_plans for row in position.errors
                  if row.source == "measured" and row.quantity == "VE"]
        assert row.analytic == 0.0 and row.plan > 0.0
        table = markdown(analysis)
        assert any(line.startswith("| VE |") and line.rstrip(" |").endswith("—") for line in table.splitlines())
        explained = [line for line in table.splitlines() if "δ —" in line]
        assert explained and "|" not in explained[0], table[:600]
        note = note_markdown(analysis)
        assert "δ —" in note


def test_a_note_with_velocity_plans_of_every_position_alone_says_what_its_errors_are():
    # Without a plan sheet the note has no section on the plans' accuracy, yet its velocity plans of every position
    # give each position's largest δ by source: it never said how δ is formed nor what drafting means.
    for locale in ("en", "ru", "zh"):
        scene = dataclasses.replace(graphplan.load(SHAPER), locale=locale)
        scene = dataclasses.replace(scene, positions=dataclasses.replace(scene.positions, plans=(),
                                                                         velocity_plans=tuple(range(1, 13))))
        analysis = analyse(scene)
        assert not analysis.plans and analysis.velocity_plans
        text = strings(locale)
        note = note_markdown(analysis)
        assert text["errors_formula"] in note, locale
        precision = f"{scene.drawing.drafting_precision:g}".replace(".", text["decimal_mark"])
        assert text["note_errors_intro"].split("{precision}")[0].split("{formula}")[-1] in note
        assert f"{precision} " in note
