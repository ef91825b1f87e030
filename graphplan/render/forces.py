"""The force sheet of one position: each group cut free with its loads, its force polygon, and Zhukovsky's lever.

Laid out as the second sheet of a course project.  For every group in the
order it was solved (the last group first, the driver last) a row: on the
left the group's links cut free at μl with its loads, moments and arms
(:mod:`graphplan.render.force_bodies`), on the right the group's force
polygon at μF (:mod:`graphplan.render.force_polygons`).  The last row is
Zhukovsky's lever (:mod:`graphplan.render.force_lever`).  What the three
share, the sheet's record (:class:`ForceSheet`) among it, is
:mod:`graphplan.render.force_marks`'.  A sheet too low for the rows in one
column takes them in two (:func:`arrangements`); how the rows stand on a
sheet too small for either is :mod:`graphplan.render.force_rows`'
(:func:`rows`).

The layout reads the records (:class:`graphplan.forces.ForcePlan`,
:class:`graphplan.lever.Lever`, the velocity plan, the positions): it puts
what they hold on paper and computes no mechanics.
"""

from __future__ import annotations

from collections.abc import MutableMapping, Sequence

from ..scales import format_scale
from . import lettering
from .force_bodies import body
from .force_lever import lever_drawing
from .force_marks import ForceSheet, group_id
from .force_polygons import polygons_drawing
from .force_rows import Drawing, Heading, Rows
from .plans import Arrangement
from .primitives import Layer

# The captions' lettering where the usual does not fit a small sheet: the next size down of GOST 2.304 and
# ISO 3098 (the usual is plans.CAPTION_SIZE, 5 mm).
SMALL_CAPTION_SIZE = lettering.SMALL_CAPTION


def layout(sheet: ForceSheet) -> list[Layer]:
    """The layers of the force sheet, in paper millimetres (y up)."""
    return arrange(sheet).layers


def arrange(sheet: ForceSheet) -> Arrangement:
    """One row per group (the group cut free, its polygon), then the lever; captions under, title above."""
    return arrangements(sheet, (1,))[0]


def arrangements(sheet: ForceSheet, columns: Sequence[int]) -> list[Arrangement]:
    """The sheet of :func:`arrange` with its rows down each number of ``columns`` in turn (1 or 2), in their
    order, split where the tallest column is least tall: the same drawings, made once, for a sheet too low
    for them in one column."""
    made = rows(sheet)
    return [made.arranged(made.in_columns(count)) for count in columns]


def rows(sheet: ForceSheet, bodies: MutableMapping[tuple[int, float], Drawing] | None = None) -> Rows:
    """The drawings of the sheet in their rows under its heading, to stand as a sheet's room lets them.

    ``bodies`` keeps the groups cut free, by group and μl, for the other versions of this one sheet (its lever at
    another scale, its lettering smaller), which draw them the same.
    """
    made = {} if bodies is None else bodies
    drawings: list[list[Drawing]] = []
    for number, group in enumerate(sheet.forces.groups):
        if (number, sheet.length_scale) not in made:
            made[number, sheet.length_scale] = body(sheet, group)
        drawings.append([made[number, sheet.length_scale], polygons_drawing(sheet, group)])
    if sheet.lever is not None:
        drawings.append([lever_drawing(sheet, sheet.lever)])
    text = sheet.text
    # μF heads the sheet when the polygons share it; else each polygon's caption gives its own.  μV is the lever's:
    # a sheet without it (forces asked without the lever) names none.
    scales = ((text["length_scale"].format(value=format_scale(sheet.length_scale)), "body-"),
              *([(text["force_scale"].format(value=format_scale(sheet.forces.scale)), "polygon-")]
                if sheet.forces.one_scale else []),
              *([(sheet.lever_scale_line, "lever")] if sheet.lever is not None else []))
    part_title = sheet.part_title or sheet.title
    return Rows(drawings, Heading(sheet.title, scales, sheet.caption_size, part_title,
                                  text["force_sheet_continued"].format(title=part_title), text["comma"]))


__all__ = ["Arrangement", "Drawing", "ForceSheet", "arrange", "arrangements", "group_id", "layout", "rows"]
