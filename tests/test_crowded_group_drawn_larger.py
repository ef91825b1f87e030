"""A group cut free whose names find no room apart at the run's μl is drawn a standard step larger.

A probe's class III triad (tests/scenes/triad_crowded_star_zh.toml) draws, on the force sheet of position 2, seventeen
arms from Σ6 beside F.  At the run's μl its names stood on the group's lines and on long leaders: no spot round the
star was free.  A draughtsman draws such a group larger; the force sheet now does, at the first finer standard μl that
leaves its names room apart, and its heading and the group's caption say that μl.  Sheets whose groups have room stay
at the run's μl.
"""

import dataclasses
import re
from pathlib import Path

import graphplan
from graphplan.analysis import analyse
from graphplan.render import force_bodies
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, length_scale
from graphplan.render.primitives import Text
from graphplan.scales import finer_standard_scale

ROOT = Path(__file__).resolve().parents[1]
CROWDED_STAR = ROOT / "tests" / "scenes" / "triad_crowded_star_zh.toml"


def _crowded(sheet: force_layout.ForceSheet) -> list[str]:
    """The groups whose names find no room apart, by the predicate the sheets' parting uses."""
    return [group.label for group in sheet.forces.groups
            if force_bodies.labels_cover_one_another(force_bodies.body(sheet, group))]


def _written_length_scales(layers) -> list[str]:
    """Each μl the sheet writes, in its heading and its groups' captions."""
    texts = [item.text for layer in layers for item in layer.items if isinstance(item, Text)]
    return [found for text in texts for found in re.findall(r"μl = ([0-9.]+)", text)]


def test_the_crowded_triad_is_drawn_a_step_larger_and_says_so():
    analysis = analyse(graphplan.load(CROWDED_STAR))
    [position] = [plan for plan in analysis.plans if plan.number == 2]
    run_scale = length_scale(analysis)
    sheet = force_sheet(analysis, position)
    # At the run's μl the triad's names find no room apart.
    assert _crowded(dataclasses.replace(sheet, length_scale=run_scale)) == ["III(3,4,5,6)"]
    assert sheet.length_scale == finer_standard_scale(run_scale)
    assert not _crowded(sheet)
    written = _written_length_scales(force_layout.layout(sheet))
    assert written and set(written) == {f"{sheet.length_scale:g}"}


def test_the_sheets_whose_groups_have_room_stay_at_the_runs_scale():
    analysis = analyse(graphplan.load(ROOT / "fixtures" / "triad_class_iii.toml"))
    run_scale = length_scale(analysis)
    sheets = [force_sheet(analysis, position) for position in analysis.plans if position.forces is not None]
    assert sheets and {sheet.length_scale for sheet in sheets} == {run_scale}
