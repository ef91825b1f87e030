"""The note names the arms of Zhukovsky's lever as the force sheet's lever letters them.

The lever drawing letters each arm h1, h2, …, hb (hу in Russian), one name for the loads whose lines are one line,
and writes its ΣMp with those names (``−G3·h1 + (Mu4′ − M4′)·h7 + Fb·hb``); the note's table of the lever's moments
gave each load's arm under a bare "h, mm", so that a reader checking it against the sheet could not tell which arm
is which.  Read back from both as written, for every fixture with a lever and the starters that add the sliding and
class III groups and the shaper's friction, in every position: each load the sheet's ΣMp names an arm for stands in
the note's table with that arm, and no other load there carries a name (same names, same loads under each name).
The note's length of a named arm is the length of its perpendicular drawn on the sheet, measured from the SVG: the
note works the lever at the scale the sheet drew it at, whose drafting precision decides which lines are one.
"""

from __future__ import annotations

import pytest
from lever_arms import check_arms_agree
from note_scenes import SCENES, STARTERS, scene_path

import graphplan
from graphplan.run import run


# Without course sheets (sheet="none"): μl is then fitted to the plan of positions rather than chosen by laying every
# course sheet out, which was more than half of each run; the note works each lever at its force_N.svg's μV either
# way, and every scene here names the same arms with or without the sheets (diffed once); the sheets' own case is
# the last test's.
@pytest.mark.parametrize(("source", "name"), SCENES + STARTERS, ids=[name for _, name in SCENES + STARTERS])
def test_the_note_names_each_lever_arm_as_the_force_sheet_letters_it(tmp_path, source, name):
    scene = graphplan.load(scene_path(tmp_path, source, name))
    made = run(scene, tmp_path / "out", only=["forces", "lever", "note"], sheet="none")
    check_arms_agree(tmp_path / "out", made, scene.locale)


# hb is hу in Russian, and the loads' names localised (Fи3): the ratchet's own note is Russian, so it is read in the
# other two.
@pytest.mark.parametrize(("source", "name", "locale"),
                         [("fixture", "ratchet_crank_rocker", "en"), ("fixture", "ratchet_crank_rocker", "zh"),
                          ("fixture", "scotch_yoke", "ru"), ("starter", "triad", "ru"), ("starter", "triad", "zh"),
                          ("starter", "shaper", "ru")])
def test_the_lever_arms_agree_in_every_language(tmp_path, source, name, locale):
    made = run(graphplan.load(scene_path(tmp_path, source, name)), tmp_path / "out", only=["forces", "lever", "note"],
               locale=locale, sheet="none")
    check_arms_agree(tmp_path / "out", made, locale)


# A run with the sheets takes each force_N.svg the sheets hold as drawn alone from their panels, with the lever's μV
# they drew it at; on A4 the offset slider-crank's levers are kept larger on their parts.
@pytest.mark.parametrize(("source", "name", "sheet"), [("starter", "crank-rocker", None),
                                                       ("fixture", "offset_slider_crank", "A4")])
def test_the_lever_arms_agree_where_the_sheets_are_drawn_too(tmp_path, source, name, sheet):
    scene = graphplan.load(scene_path(tmp_path, source, name))
    made = run(scene, tmp_path / "out", sheet=sheet)
    check_arms_agree(tmp_path / "out", made, scene.locale)
