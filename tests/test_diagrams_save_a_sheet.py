"""Kinematic diagrams that stand apart on a small sheet are drawn a little lower where that puts them on fewer sheets.

The Russian crank-rocker's three diagrams take three A3 sheets at the usual 50 mm fields, each a third full: their
words are wider than the English ones, and two diagrams one over the other miss the room above the title block by a
few millimetres.  Fields a few millimetres lower put two on one sheet.  Checked against the packing itself: the field
chosen is the highest at which the diagrams alone take fewer sheets, and no lower than a fifth below the usual.
"""

from __future__ import annotations

import functools
import re

from graphplan.analysis import analyse
from graphplan.kinematic_diagrams import AXIS_MM, FIELD_MM
from graphplan.locale import strings
from graphplan.render.packing import pack
from graphplan.render.primitives import Text
from graphplan.render.sheet import _apart, diagram_parts, diagrams_panel
from graphplan.render.title_block import form_of
from graphplan.scene import loads
from graphplan.starters import starter


@functools.cache
def crank_rocker_in_russian():
    return analyse(loads(starter("crank-rocker", locale="ru")))


def sheets_taken(analysis, field: float, sheet: str = "A3") -> int:
    """The sheets the diagrams drawn at ``field`` take on their own, as the packing lays them out."""
    title, drawn = diagram_parts(analysis, AXIS_MM, field, lettered=False)
    continued = strings(analysis.scene.locale)["force_sheet_continued"]
    return len(pack([_apart("diagrams", title, drawn, continued)], sheet, form_of(analysis.scene.locale)))


def test_the_diagrams_take_one_sheet_fewer_at_the_highest_field_that_saves_it():
    analysis = crank_rocker_in_russian()
    usual = sheets_taken(analysis, FIELD_MM)
    assert usual == 3
    saving = [field for field in range(int(FIELD_MM), int(0.8 * FIELD_MM) - 1, -1)
              if sheets_taken(analysis, field) < usual]
    assert saving, "no field a fifth lower saves a sheet"
    panel = diagrams_panel(analysis, "A3")
    assert len(pack([panel], "A3", form_of("ru"))) == usual - 1
    # Drawn at the highest of those fields: the displacement diagram's ψ scale is the one that field gives.
    _, highest = diagram_parts(analysis, AXIS_MM, float(saving[0]))
    _, at_usual = diagram_parts(analysis, AXIS_MM, FIELD_MM)
    assert displacement_scale(panel.parts[0].layers) == displacement_scale(highest[0])
    assert displacement_scale(highest[0]) != displacement_scale(at_usual[0])


def displacement_scale(layers) -> str:
    texts = [item.text for layer in layers for item in layer.items if isinstance(item, Text)]
    return next(match.group(0) for text in texts if (match := re.search(r"μψ = [\d.,]+", text)))


def test_diagrams_that_fit_their_sheets_keep_the_usual_field():
    """The English words are narrower: two diagrams stand one over the other at the usual field already."""
    analysis = analyse(loads(starter("crank-rocker")))
    assert sheets_taken(analysis, FIELD_MM) == 2
    panel = diagrams_panel(analysis, "A3")
    _, usual = diagram_parts(analysis, AXIS_MM, FIELD_MM)
    # Each diagram as drawn, those after the first under their title "continued" where they stand apart.
    assert [part.without_heading().layers if part.continues else part.layers
            for part in panel.parts] == [tuple(part) for part in usual]
