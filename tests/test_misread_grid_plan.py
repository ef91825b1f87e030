"""A plan-sheet position drawn among the velocity plans of every position too: readings taken off its small plan there
(velocity_plans.svg) were told that the plan sheets were drawn at another μV and advised a velocity_pole that would
redraw every plan sheet; they are now told which plan they fit.

The readings are lengths of the program's own small plan, read in the test off its plan points.
"""

import dataclasses

import graphplan
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown
from graphplan.report.tables import markdown

FIXTURE = "fixtures/ratchet_crank_rocker.toml"
POSITION = 5  # a plan-sheet position of the fixture
SEGMENTS = ("pb", "ab", "pe", "ps3")


def _scene():
    scene = graphplan.load(FIXTURE)
    return dataclasses.replace(scene, measured={}, locale="en",
                               positions=dataclasses.replace(scene.positions, velocity_plans=tuple(range(12))))


def _far_off(analysis):
    return [w for w in analysis.warnings if w.code == "measured-far-off"]


def test_readings_of_the_small_plan_of_a_plan_sheet_position_are_told_so():
    """Lengths of the position's small plan typed for its plan sheet are told so, with the factor to the sheet's, in
    the warning, errors.md and the note (en, ru, zh); readings that fit neither plan are still advised the pole."""
    scene = _scene()
    bare = analyse(scene)
    small = next(p for p in bare.velocity_plans if p.number == POSITION).velocity
    sheet = next(p for p in bare.plans if p.number == POSITION).velocity
    assert abs(small.scale / sheet.scale - 1.0) > 0.15  # the two plans are told apart by their readings
    readings = {name: round(abs(small.mm(name[1:]) - small.mm(name[0])), 2) for name in SEGMENTS}
    analysis = analyse(dataclasses.replace(scene, measured={POSITION: {"velocity": readings}}))
    (warning,) = _far_off(analysis)
    factor = small.scale / sheet.scale
    assert (f"every reading of the velocity plan fits position {POSITION}'s plan among the velocity plans of every "
            f"position (velocity_plans.svg, at μV = {small.scale:.4g} (m/s)/mm") in warning.detail, warning.detail
    assert f"measure the plan sheet's velocity plan, or give these readings times {factor:.4g}" in warning.detail
    assert "velocity_pole" not in warning.detail
    assert f"plan of position {POSITION} among the velocity plans of every position (velocity_plans.svg" in markdown(
        analysis)
    russian = dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, locale="ru"))
    assert f"согласуются с планом положения {POSITION} среди планов скоростей всех положений" in markdown(russian)
    # The note's reader has no run folder: the plans are named in words alone.
    (said,) = [line for line in note_markdown(russian).splitlines() if "сняты с этого малого плана" in line]
    assert ".svg" not in said
    chinese = dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, locale="zh"))
    assert f"第 {POSITION} 位置的小图相符" in markdown(chinese)
    # Following it: the readings times the factor are lengths on the plan sheet, and nothing is said.
    followed = {name: mm * factor for name, mm in readings.items()}
    assert not _far_off(analyse(dataclasses.replace(scene, measured={POSITION: {"velocity": followed}})))
    # Readings that fit neither the plan sheet nor the small plan: a plan sheet drawn at another pole, advised as before.
    pole = 120.0
    given = scene.drawing.velocity_pole
    readings = {name: round(abs(sheet.mm(name[1:]) - sheet.mm(name[0])) * pole / given, 2) for name in SEGMENTS}
    (warning,) = _far_off(analyse(dataclasses.replace(scene, measured={POSITION: {"velocity": readings}})))
    assert "give `[drawing] velocity_pole = 120`" in warning.detail and "among the velocity plans" not in warning.detail
