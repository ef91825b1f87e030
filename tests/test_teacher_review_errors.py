"""A teacher's review of the accuracy report (the error tables of the plans, the force polygons and the balancing
load): what it prints is checked against the scene's own readings and an independent reading of the plans."""

import dataclasses

import graphplan
from graphplan.analysis import analyse
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
