"""The velocity plans of every position on one drawing, all at one μV.

A course project draws the velocity plan of each of the twelve positions
(the equivalent model of the machine is read off them) in rows beside the
plan of positions.  Each plan is drawn as on a plan sheet
(:func:`graphplan.render.plans.plan_layers`) over its position's number;
this module only sets them out: in a grid read left to right and top to
bottom, each column as wide as its widest plan and each row as tall as its
tallest, its columns chosen so that the grid is about as wide against its
height as a sheet of the A series, under the drawing's title and its μV.  Each plan stands in a field of its own,
``position-N``, the title with the first.  Sheets too small for the whole
take it in runs (:func:`runs`), each as long as a sheet's room holds.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from ..mechanism import Mechanism
from ..plans import Plan
from .plans import (
    CAPTION_GAP_MM,
    CAPTION_LINE,
    CAPTION_SIZE,
    TITLE_SIZE,
    Arrangement,
    caption_texts,
    plan_layers,
    title_texts,
)
from .primitives import Layer, Text, bounds, moved_layers, prefixed, text_width

# Between two cells of the grid (mm): less than between a plan sheet's drawings, as the plans are one set.
CELL_GAP_MM = 15.0
# The line of μV stands this far (mm) over the plans' top.
HEADING_GAP_MM = 8.0
# The width against the height of a sheet of the A series, which the grid is shaped after.
SHEET_ASPECT = math.sqrt(2.0)


@dataclass(frozen=True)
class VelocityPlans:
    """What the drawing shows: each position's velocity plan (``number``, plan) at one μV, in order, with
    its caption (lines, the first its name), the drawing's title and the line of its scale."""

    mechanism: Mechanism
    plans: tuple[tuple[int, Plan], ...]
    captions: tuple[tuple[str, ...], ...]
    title: str
    scale_line: str
    pole: str = "p"

    def __post_init__(self) -> None:
        if not self.plans:
            raise ValueError("a drawing of the velocity plans needs at least one plan")
        if len(self.captions) != len(self.plans):
            raise ValueError(f"{len(self.plans)} plans but {len(self.captions)} captions")


def field_name(number: int) -> str:
    """The field (and the prefix of the layers and arrow ids) of position ``number``'s plan."""
    return f"position-{number}"


def layout(drawing: VelocityPlans) -> list[Layer]:
    """The layers of the drawing, in paper millimetres (y up)."""
    return arrange(drawing).layers


def arrange(drawing: VelocityPlans, columns: int | None = None) -> Arrangement:
    """The plans in a grid of ``columns`` (by default the count that shapes the grid most like a sheet): each
    column as wide as its widest plan or caption, each row as tall as its tallest plan, each plan in the
    middle of its cell with its caption under the row; the title and μV above the grid."""
    return arrangements(drawing, (columns,))[0]


def arrangements(drawing: VelocityPlans, column_counts: Sequence[int | None]) -> list[Arrangement]:
    """The grid of :func:`arrange` in each of ``column_counts``, the plans drawn once for all."""
    drawn = [prefixed(plan_layers(plan, "velocity", drawing.pole, drawing.mechanism), field_name(number))
             for number, plan in drawing.plans]
    return [_grid_arrangement(drawing, drawn, columns) for columns in column_counts]


def runs(drawing: VelocityPlans) -> Callable[[int, int, Sequence[int]], list[Arrangement]]:
    """The grids of the plans ``start`` to ``stop`` (a run of them, in order) in each of ``column_counts``, the
    plans drawn once for all: a sheet that holds no grid whole takes it run by run, as many plans as its room
    holds.  Only the run from the first plan carries the title and μV; a later one's heading is the sheet's."""
    drawn = [prefixed(plan_layers(plan, "velocity", drawing.pole, drawing.mechanism), field_name(number))
             for number, plan in drawing.plans]

    def arranged(start: int, stop: int, column_counts: Sequence[int]) -> list[Arrangement]:
        run = replace(drawing, plans=drawing.plans[start:stop], captions=drawing.captions[start:stop])
        return [_grid_arrangement(run, drawn[start:stop], columns, titled=start == 0) for columns in column_counts]

    return arranged


def _grid_arrangement(drawing: VelocityPlans, drawn: Sequence[Sequence[Layer]], columns: int | None,
                      titled: bool = True) -> Arrangement:
    extents = [bounds(layers) for layers in drawn]
    widths = [max(x1 - x0, *(text_width(line, CAPTION_SIZE, "bold") for line in caption))
              for (x0, _, x1, _), caption in zip(extents, drawing.captions, strict=True)]
    heights = [y1 - y0 for _, y0, _, y1 in extents]
    depths = [CAPTION_GAP_MM + len(caption) * CAPTION_LINE * CAPTION_SIZE for caption in drawing.captions]
    count = len(drawn)
    columns = columns or min(range(1, count + 1), key=lambda n: abs(math.log(_aspect(n, widths, heights, depths))))
    column_widths, row_heights, row_depths = _grid(columns, widths, heights, depths)
    lefts = [sum(column_widths[:c]) + CELL_GAP_MM * c for c in range(columns)]
    tops = [-(sum(row_heights[:r]) + sum(row_depths[:r]) + CELL_GAP_MM * r) for r in range(len(row_heights))]
    layers: list[Layer] = []
    fields: dict[str, tuple[float, float, float, float]] = {}
    for k, ((number, _), layers_of, (x0, y0, x1, y1), caption) in enumerate(
            zip(drawing.plans, drawn, extents, drawing.captions, strict=True)):
        row, column = divmod(k, columns)
        left, top, width, height = lefts[column], tops[row], column_widths[column], row_heights[row]
        fields[field_name(number)] = (left, top - height, left + width, top)
        layers.extend(moved_layers(layers_of, left + (width - x0 - x1) / 2, top - height / 2 - (y0 + y1) / 2))
        layers.append(Layer(f"{field_name(number)}-caption",
                            caption_texts(caption, (left + width / 2, top - height - CAPTION_GAP_MM))))
    if not titled:
        return Arrangement(layers, fields)
    left, _, _, top = bounds(layers)
    # The title goes with the first plan, over it: where a sheet takes the plans apart, μV stays in view.
    layers.append(Layer(f"{field_name(drawing.plans[0][0])}-title",
                        heading_texts((drawing.title,), drawing.scale_line, (left, top))))
    return Arrangement(layers, fields)


def heading_texts(title_lines: Sequence[str], scale_line: str, corner: tuple[float, float]) -> tuple[Text, ...]:
    """The title (its lines) and the line of μV over plans whose top left corner is ``corner``: over the whole
    grid, and over each part of it that goes on onto another sheet, where a grader measures by that μV too."""
    left, top = corner
    base = top + HEADING_GAP_MM
    return (*title_texts(title_lines, TITLE_SIZE, (left, base + CAPTION_LINE * CAPTION_SIZE)),
            Text((left, base), scale_line, CAPTION_SIZE, "start"))


def _grid(columns: int, widths: Sequence[float], heights: Sequence[float],
          depths: Sequence[float]) -> tuple[list[float], list[float], list[float]]:
    """The grid's column widths, row heights and the depth of each row's captions, the plans in order."""
    rows = math.ceil(len(widths) / columns)
    column_widths = [max(widths[c::columns]) for c in range(columns)]
    row_heights = [max(heights[r * columns:(r + 1) * columns]) for r in range(rows)]
    row_depths = [max(depths[r * columns:(r + 1) * columns]) for r in range(rows)]
    return column_widths, row_heights, row_depths


def _aspect(columns: int, widths: Sequence[float], heights: Sequence[float], depths: Sequence[float]) -> float:
    """How much wider against its height the grid of ``columns`` is than a sheet."""
    column_widths, row_heights, row_depths = _grid(columns, widths, heights, depths)
    width = sum(column_widths) + CELL_GAP_MM * (columns - 1)
    height = sum(row_heights) + sum(row_depths) + CELL_GAP_MM * (len(row_heights) - 1)
    return width / height / SHEET_ASPECT


__all__ = ["VelocityPlans", "arrange", "arrangements", "field_name", "heading_texts", "layout", "runs"]
