"""A drawing too tall for a page of the note, cut between its rows into parts a page holds at a readable size.

A force sheet stands in one column of rows (each group beside its polygon, then Zhukovsky's lever): 330 mm wide
and near a metre tall for a six-bar, it went into the note's PDF and Word pages shrunk to a quarter, its letters
3 pt high.  The note shows it part by part instead, each part a whole number of rows, the sheet's heading over
the first; the drawing itself, forces_N.svg, stays whole.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from .force_rows import HEADING_LAYER, scales_line, with_scales_line
from .primitives import Layer, bounds

# A note's page holds a figure this wide and tall (mm): A4's line, and the height that leaves room for its caption
# (report/word.py and report/latex.py set their pictures within these).
PAGE_FIGURE_MM = (170.0, 200.0)
# A figure printed smaller than this (its letters 3.5 mm high come out under 1.75 mm, some 7 pt) is cut into parts.
LEAST_PRINT_SCALE = 0.5


def note_parts(layers: Sequence[Layer], scales: Sequence[tuple[str, str]] = (),
               comma: str = ", ") -> list[list[Layer]] | None:
    """``layers`` cut between their rows into parts that each print on a page at :data:`LEAST_PRINT_SCALE` or
    larger, the heading with the first; None where the drawing prints so whole, or no cut between rows helps.

    Where ``scales`` gives the scales its heading names with the drawings
    drawn at each (:attr:`~graphplan.render.force_rows.Heading.scales`), the
    heading names those of the first part's drawings alone: over the
    groups of the first part it named the μV of a lever on the next.
    """
    drawn = [layer for layer in layers if layer.items]
    if not drawn or _prints(drawn):
        return None
    tallest = PAGE_FIGURE_MM[1] / LEAST_PRINT_SCALE
    heading = [layer for layer in drawn if layer.name == HEADING_LAYER]
    parts: list[list[Layer]] = []
    current: list[Layer] = list(heading)
    holds_a_row = False   # the heading alone is no part: the first row goes under it, however tall
    for row in _rows([layer for layer in drawn if layer.name != HEADING_LAYER]):
        if holds_a_row and _size([*current, *row])[1] > tallest:
            parts.append(current)
            current = []
        current += row
        holds_a_row = True
    parts.append(current)
    if len(parts) < 2:
        return None
    if scales:
        line = scales_line(scales, [layer.name for layer in parts[0]], comma)
        parts[0] = [with_scales_line(layer, line) if layer.name == HEADING_LAYER else layer for layer in parts[0]]
    return parts


def note_parts_in_order(layers: Sequence[Layer], heading: str) -> list[list[Layer]] | None:
    """``layers`` of a drawing in columns (the dynamics: the diagrams over φ down one side, the energy–mass diagram
    over Je(φ) down the other) gathered in their own order into parts that each print on a page at
    :data:`LEAST_PRINT_SCALE` or larger, the layer ``heading`` over the first; None where the drawing prints so
    whole.  Cut into rows, each row still spanned both columns and printed as small as the whole."""
    drawn = [layer for layer in layers if layer.items]
    if not drawn or _prints(drawn):
        return None
    parts: list[list[Layer]] = []
    current = [layer for layer in drawn if layer.name == heading]
    for layer in (layer for layer in drawn if layer.name != heading):
        if current and any(item.name != heading for item in current) and not _prints([*current, layer]):
            parts.append(current)
            current = []
        current.append(layer)
    parts.append(current)
    return parts if len(parts) > 1 else None


def note_parts_of_drawings(drawings: Sequence[str], laid_out: Callable[[tuple[str, ...]], list[Layer]],
                           title: str, whole: Sequence[Layer] | None = None) -> list[list[Layer]] | None:
    """A sheet of ``drawings`` side by side (a plan sheet: the mechanism, the velocity plan, the acceleration plan)
    too wide for a page of the note, gathered in their order into parts that each print on a page at
    :data:`LEAST_PRINT_SCALE` or larger; None where the sheet prints so whole, or no part holds two drawings.

    ``laid_out`` gives the layers of the drawings it is given, each under its caption, the layer ``title`` over
    them (the deliverables take them out of the sheet as drawn); the title is kept over the first part alone.
    ``whole`` is the sheet as drawn, where it is not ``laid_out`` of all the drawings (a plan sheet arranged for a
    course-project sheet)."""
    if not drawings or _prints(whole if whole is not None else laid_out(tuple(drawings))):
        return None
    groups: list[tuple[str, ...]] = []
    for name in drawings:
        if groups and _prints(laid_out((*groups[-1], name))):
            groups[-1] = (*groups[-1], name)
        else:
            groups.append((name,))
    if len(groups) < 2:
        return None
    parts = [[layer for layer in laid_out(group) if layer.items] for group in groups]
    return [parts[0]] + [[layer for layer in part if layer.name != title] for part in parts[1:]]


def _prints(layers: Sequence[Layer]) -> bool:
    """Whether ``layers`` print on a note's page at :data:`LEAST_PRINT_SCALE` or larger."""
    width, height = _size(layers)
    return min(PAGE_FIGURE_MM[0] / width, PAGE_FIGURE_MM[1] / height) >= LEAST_PRINT_SCALE


def _rows(layers: Sequence[Layer]) -> list[list[Layer]]:
    """The layers grouped into bands that overlap in height, top down: a sheet's rows (a group cut free beside its
    polygon); a band of captions alone goes with the drawings over it, whose captions they are."""
    ordered = sorted(layers, key=lambda layer: -bounds([layer])[3])
    rows: list[list[Layer]] = []
    low = None
    for layer in ordered:
        _, bottom, _, top = bounds([layer])
        if rows and low is not None and top >= low:
            rows[-1].append(layer)
            low = min(low, bottom)
        else:
            rows.append([layer])
            low = bottom
    joined: list[list[Layer]] = []
    for row in rows:
        if joined and all(layer.name.endswith("-caption") for layer in row):
            joined[-1] += row
        else:
            joined.append(row)
    # Each part is painted in the drawing's own order: taken by height, a group's white slider blocks and pins
    # were laid over its arrows (a load pushing on a block lost its head) and its names under everything.
    painting = {id(layer): index for index, layer in enumerate(layers)}
    return [sorted(row, key=lambda layer: painting[id(layer)]) for row in joined]


def _size(layers: Sequence[Layer]) -> tuple[float, float]:
    x0, y0, x1, y1 = bounds(list(layers))
    return x1 - x0, y1 - y0
