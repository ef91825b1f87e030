"""The rows of a force sheet on paper: how its drawings stand, under its heading, on one sheet or several.

A force sheet is a sequence of rows in reading order (each group cut free
with its force polygon, then Zhukovsky's lever).  A row stands with its
drawings side by side, or stacked, the polygon under the group; the rows go
down one column or down several, in order.  A sheet too small for all the
rows takes them in parts, in order, each part under the heading, the first
part's title as given and the others' marked as continued: the reading
order and the scales stay in view, as on a drawing of several sheets.

This module puts drawings already made (:class:`Drawing`) on paper; what
the drawings show is :mod:`graphplan.render.forces`'.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable, Collection, Iterator, Sequence
from dataclasses import dataclass, replace

from . import lettering
from .plans import CAPTION_GAP_MM, CAPTION_LINE, GAP_MM, TITLE_LAYER, Arrangement, title_texts
from .primitives import Layer, Text, bounds, bounds_of, moved_layers, text_width
from .wrapping import NAME_BEFORE, fitted

# The least width a caption is broken to (mm), so that a narrow drawing's equations are not set a word a line.
CAPTION_WIDTH_MM = 160.0
# A width no title reaches: a heading broken to it stands on one line.
_ONE_LINE_MM = 100_000
# The heading's scales line stands this far (mm) above the drawings' top.
HEADING_GAP_MM = 8.0
# The estimate of a way's size errs by a few mm (a caption's last line is counted whole): a way estimated
# this much too big is still drawn and measured.
ESTIMATE_SLACK_MM = 10.0
# Beyond this many rows, rows are not tried stacked: the ways to stand grow as 4 to the rows.
MOST_ROWS_TRIED_STACKED = 6
# A caption set beside its drawing (:func:`_captions_beside`) is broken to the narrowest of these widths (mm) that
# keeps it no taller than the drawing, so that it widens the row least; the widest where none does.
CAPTION_BESIDE_WIDTHS_MM = (70.0, 85.0, 100.0, 120.0, 140.0, CAPTION_WIDTH_MM)
# The cuts of a force sheet into as many parts that the sheets try packing (:meth:`Rows.cuts`), least paper first.
# Measured, bench/results/sheet_cuts.md: over every fixture and starter in en, ru and zh, on its own sheet, A3 and
# A4, no force sheet had more than 4 such cuts however many were offered, so the bound only keeps a sheet of many
# rows from trying all.
MOST_CUTS = 4


Fits = Callable[[float, float], bool]
# The layer of a force sheet's (or a part's) heading: its title and the line of its scales; the plan sheet's
# title layer, as every heading's, by which the packing knows a heading to leave off a part that goes on.
HEADING_LAYER = TITLE_LAYER
# The title of a part that stands with no heading at all: a drawing that a sheet holds only so.  A heading's
# own titles are never empty.
HEADLESS = ""
# How the rows stand: columns left to right, each the rows down it as (row index, stacked).
Shape = tuple[tuple[tuple[int, bool], ...], ...]


def has_heading(layers: Sequence[Layer]) -> bool:
    """Whether a force sheet's drawing (or a part of it) stands under its heading."""
    return any(layer.name == HEADING_LAYER for layer in layers)


@dataclass(frozen=True)
class RunOn:
    """How ``lines`` lines of a drawing's caption, the last but ``after`` (a force polygon's vectors too short to
    draw, or the lever's arms: the words, then the values), may take fewer (:func:`caption_lines`): ``alone``, the
    words and the values on one line, going on after ``joint`` at the end of the line before them where the
    caption's field has the room, else on a line of its own where it fits so, else the words on their line and
    ``values`` filling the lines after where that takes fewer lines than ``lines``' own.

    Apart, they took two lines of lettering under the engine's polygon of
    position 2, and its Chinese sheet then had no room beside the polygon for
    the driving link's group, which went on to a sheet of its own.  The lever's
    short arms stand before its balancing loads, which ``after`` counts.
    """

    lines: int
    alone: str
    joint: str
    after: int = 0
    # The values the lines name, each whole: broken to the room where they do not go on.
    values: tuple[str, ...] = ()


@dataclass(frozen=True)
class Drawing:
    """One drawing of the sheet: its layers (paper mm, anywhere) and the lines of its caption, the first its title."""

    name: str
    layers: list[Layer]
    caption: tuple[str, ...]
    # The drawing under the head of its caption, and the rest of its caption (a group's equations) as a drawing of
    # its own to go on from it: for a sheet that holds the drawing only without them at a scale its labels stand
    # apart at (:meth:`Rows.parted`).  None where the caption stays whole under its drawing.
    parted: tuple[Drawing, Drawing] | None = None
    # The caption's last lines as they may stand in fewer where its field has the room.
    run_on: RunOn | None = None
    # Whether its labels found no room apart (:attr:`graphplan.render.labels.Placement.crowded`).
    labels_crowded: bool = False


@dataclass(frozen=True)
class Heading:
    """The sheet's title and the line of its scales, lettered at ``size`` (the captions' height);
    the title one size of lettering above.

    ``scales`` are the scales the drawings are drawn at, in the order the
    line names them, each with the start of the names of the drawings drawn
    at it (``("μl = 0.0025 m/mm", "body-")``).  Where the sheet stands in
    parts, the first part is headed ``part_title`` (the title without the
    mechanism's name, which the title block gives) and the others
    ``continued``; each part's heading is drawn naming the scales of the
    drawings that may stand under it, its own and the later parts' (a part
    that goes on on the sheet of the part before stands under that part's
    heading), and once the parts are packed names those that do
    (:func:`with_scales_line`): the lever alone names μV, not the groups' μl,
    and a group alone on its sheet not the μF of polygons on the next.
    Where the parts stand is found with every heading measured at all of
    ``scales`` (:attr:`whole_scales`), so that which of them a part names
    moves no drawing: measured at its own, a lever under a shorter heading
    fitted at the usual lettering in more parts, and the engine's force
    sheets on A3 took a sheet more.
    """

    title: str
    scales: tuple[tuple[str, str], ...]
    size: float
    part_title: str
    continued: str
    # What sets the scales apart: the locale's comma, a full-width one in Chinese as its captions have it.
    comma: str = ", "

    def __post_init__(self) -> None:
        if HEADLESS in (self.title, self.part_title, self.continued):
            raise ValueError(f"a heading's titles are not empty: {self!r}")

    def scales_of(self, names: Sequence[str]) -> str:
        """The line of the scales the drawings ``names`` are drawn at (:func:`scales_line`)."""
        return scales_line(self.scales, names, self.comma)

    @property
    def whole_scales(self) -> str:
        """The line of all the sheet's scales, which every heading is measured with."""
        return self.comma.join(line for line, _ in self.scales)

    @property
    def title_size(self) -> float:
        """The next size of GOST 2.304 / ISO 3098 above the captions': 7 mm over 5, 5 mm over 3.5."""
        return lettering.larger(self.size)


def scales_line(scales: Sequence[tuple[str, str]], names: Sequence[str], comma: str = ", ") -> str:
    """The line of those of ``scales`` (:attr:`Heading.scales`) that the drawings ``names`` (or their layers) are
    drawn at; empty where none has one of the sheet's (force polygons each at its own μF, which their captions
    give)."""
    return comma.join(line for line, start in scales if any(name.startswith(start) for name in names))


def with_scales_line(heading: Layer, line: str) -> Layer:
    """A heading's layer (:meth:`Rows._heading_layer`) with its line of scales saying ``line``, none where that is
    empty.  Only the heading changes, so that a heading narrowed to the drawings a sheet holds under it moves none
    of them; with no scales left, its title comes down onto their line, which would stand empty between it and
    the drawings under it."""
    titles = tuple(item for item in heading.items if not _is_scales_line(item))
    scales = tuple(item for item in heading.items if _is_scales_line(item))
    if line or not scales:
        return Layer(heading.name, (*titles, *(replace(item, text=line) for item in scales)))
    below = scales[0].at[1]
    nearest = min((item.at[1] for item in titles if isinstance(item, Text)), key=lambda y: abs(y - below),
                  default=below)
    return Layer(heading.name, tuple(replace(item, at=(item.at[0], item.at[1] + below - nearest))
                                     if isinstance(item, Text) else item for item in titles))


def _is_scales_line(item: object) -> bool:
    """Whether ``item`` of a heading's layer is its line of scales, the one text not in bold (the title's lines
    are, :func:`~graphplan.render.plans.title_texts`)."""
    return isinstance(item, Text) and item.weight != "bold"


@dataclass(frozen=True)
class _Block:
    """A row laid out from its top left corner (0, 0), its captions under its drawings."""

    layers: list[Layer]
    fields: dict[str, tuple[float, float, float, float]]
    width: float
    height: float


@dataclass(frozen=True)
class Part(Arrangement):
    """A part of a force sheet as arranged, its captions under its drawings, and ``aside``: the same part with the
    long captions (a group's equations, the lever's) beside their drawings, for a sheet whose room left is too low
    for it so (None where that is no lower); the packing takes it where only that makes room.

    On an A3 a drawing with its equations under it often misses the 216 mm
    above the title block by a few lines: the engine's force sheet of
    position 8 took two A3, its groups and polygons with their equations
    beside them stand on one.
    """

    aside: Arrangement | None = None


class Rows:
    """The rows of one force sheet, each laid out once side by side, once stacked and once with its long captions
    beside their drawings."""

    def __init__(self, rows: Sequence[Sequence[Drawing]], heading: Heading, origins: Sequence[int] = ()) -> None:
        self.drawings = [tuple(row) for row in rows]
        self.heading = heading
        # The row of the sheet each row was cut from (:meth:`_apart`), so that a cut keeps them together where
        # it can: a group cut free and its polygon on one sheet.
        self.origins = tuple(origins) or tuple(range(len(self.drawings)))
        self._heading_sizes: dict[tuple[str, float], tuple[float, float]] = {}
        self.beside = [_side_by_side(row, heading.size) for row in rows]
        # Each row stacked, laid out when a shape first stacks it (:meth:`_stacked_block`): a sheet that stands
        # whole in one or two columns of rows side by side (and each of its versions drawn larger) never does.
        self._stacked_blocks: dict[int, _Block | None] = {}
        # Each row with its long captions beside their drawings, where that makes it lower (:class:`Part`), laid
        # out when a part is first arranged so: most rows tried for a cut never are.
        self._aside: dict[int, _Block | None] = {}

    def __len__(self) -> int:
        return len(self.beside)

    @property
    def stacked(self) -> list[_Block | None]:
        """Each row with its drawings one under another; None for a row of one drawing (the lever), which stands
        the same either way."""
        return [self._stacked_block(index) for index in range(len(self.drawings))]

    def _stacked_block(self, index: int) -> _Block | None:
        if index not in self._stacked_blocks:
            row = self.drawings[index]
            self._stacked_blocks[index] = _stacked(row, self.heading.size) if len(row) > 1 else None
        return self._stacked_blocks[index]

    def block(self, index: int, stacked: bool, aside: bool = False) -> _Block:
        block = self._stacked_block(index) if stacked else None
        if block is None and aside:
            if index not in self._aside:
                self._aside[index] = _captions_beside(self.drawings[index], self.heading.size,
                                                      self.beside[index].height)
            block = self._aside[index]
        return block if block is not None else self.beside[index]

    def arranged(self, shape: Shape, title: str | None = None, one_line: bool = False,
                 part: bool = False, aside: bool = False) -> Arrangement:
        """The rows as ``shape`` has them, under the heading: the sheet's title on one line, or ``title`` (a
        part's) on one line too where ``one_line``, else broken to the drawings' width where it is wider than
        they are; over the line of all the sheet's scales, or where ``part`` (a part as it is drawn, once
        chosen), of those of the drawings that may stand under it; the rows side by side with their long
        captions beside their drawings where ``aside``."""
        layers: list[Layer] = []
        fields: dict[str, tuple[float, float, float, float]] = {}
        left = 0.0
        for column in shape:
            top = 0.0
            for index, stacked in column:
                block = self.block(index, stacked, aside)
                layers.extend(moved_layers(block.layers, left, top))
                fields.update({name: (x0 + left, y0 + top, x1 + left, y1 + top)
                               for name, (x0, y0, x1, y1) in block.fields.items()})
                top -= block.height + GAP_MM
            left += max(self.block(index, stacked, aside).width for index, stacked in column) + GAP_MM
        left, _, right, upper = bounds(layers)
        if title != HEADLESS:
            width = math.inf if title is None or one_line else right - left
            scales = self._scales(shape) if part else self.heading.whole_scales
            layers.append(self._heading_layer(left, upper + HEADING_GAP_MM, title or self.heading.title, scales,
                                              width))
        return Arrangement(layers, fields)

    def _scales(self, shape: Shape) -> str:
        """The line of the scales of the drawings that may stand under the heading of ``shape``: those it holds
        and those of the rows after it, which may go on under its heading on its sheet (once packed, the heading
        names those that do: :func:`with_scales_line`)."""
        first = min(index for column in shape for index, _ in column)
        return self.heading.scales_of([drawing.name for row in self.drawings[first:] for drawing in row])

    def in_columns(self, count: int) -> Shape:
        """All the rows side by side, in ``count`` columns (fewer where there are fewer rows), in order, split
        where the tallest column is least tall."""
        heights = [block.height for block in self.beside]
        if count <= 1 or len(heights) <= 1:
            return (tuple((k, False) for k in range(len(heights))),)
        if count > 2:
            raise ValueError(f"a force sheet's rows are split in one or two columns, not {count}")
        cut = min(range(1, len(heights)), key=lambda k: max(sum(heights[:k]), sum(heights[k:])))
        return (tuple((k, False) for k in range(cut)), tuple((k, False) for k in range(cut, len(heights))))

    def parts(self, fits: Fits, headless: bool = True) -> list[Part] | None:
        """The rows in the fewest parts in order, each standing the way that ``fits`` and takes least paper
        (of as many parts, those that cut fewest rows apart); the first part under the heading's title, the
        others under its ``continued``.  Where a row fits in no way, every drawing stands as a row of its own
        (a polygon may then stand apart from its group, where no cut of as many parts keeps them together),
        and a drawing too big to stand under a heading stands alone without one where ``headless`` allows it;
        None where a drawing does not fit even so (:meth:`unheld`)."""
        found = self.cuts(fits, headless)
        return found[0] if found else None

    def cuts(self, fits: Fits, headless: bool = True) -> list[list[Part]]:
        """:meth:`parts` first, then the other cuts into as many parts that cut as few rows apart, by the paper
        they take, :data:`MOST_CUTS` in all, and last, where there are several parts, every drawing a part of its
        own (a group cut free apart from its polygon), which the sheets take only where it saves one; none where
        a drawing does not fit.

        The least paper of the parts alone does not tell the fewest sheets:
        the engine's force sheet of position 2 in Russian took group II on a
        part and group I with the lever on the next, a tenth less paper than
        both groups on one and the lever alone (its part as wide as its long
        heading "(продолжение)"), and the lever's part with group I left no
        room beside it for position 8's sheet, which took a sheet more; the
        sheets choose among these by packing them
        (:func:`graphplan.render.sheet.fewest_sheets_cuts`)."""
        found = self._parts(fits)
        apart = self._apart()
        if not found:
            if any(len(row) > 1 for row in self.drawings):
                found = apart._parts(fits)
            found = found if found or not headless else apart._parts(fits, headless=True)
        # Last, every drawing a part of its own, each put where a sheet has room for it: the crank-rocker's group I
        # with friction beside its polygon, a part too wide for the room any sheet had left on an A3, stood alone on
        # one, a fifth of it drawn on; apart, group I stands under group II's polygon and its own polygon beside the
        # lever, and the Russian A3 sheets went from 18 to 15.
        each = apart._each_apart(fits) if found and len(found[0]) > 1 else []
        return [*found, each] if each and len(each) > len(found[0]) else found

    def rows_apart(self, fits: Fits) -> list[Part]:
        """For a sheet that stands whole: every row a part of its own under its heading (a group cut free beside
        its polygon, the lever), in order, which the sheets take only where it saves one; none for a sheet of one
        row, or where a row fits under no heading.

        Whole, the shaper six-bar's force sheet of position 10 took an A1,
        and its load diagrams another, a twentieth of it drawn on; apart, its
        rows stand round its lever with the load diagrams beside them.
        """
        return self._each_apart(fits) if len(self) > 1 else []

    def _each_apart(self, fits: Fits) -> list[Part]:
        """Every row a part of its own under its heading (where it stands in parts, the rows are each a drawing:
        :meth:`_apart`); none where a row fits under no heading."""
        ways = []
        for start in range(len(self)):
            title = self._title_of(start)
            least = self._least(start, start + 1, fits, title)
            if least is None:
                return []
            ways.append((least[1], title, least[2]))
        return self._arranged_parts(ways)

    def parted(self, names: Collection[str]) -> Rows:
        """The rows with each drawing of ``names`` that may be parted (:attr:`Drawing.parted`) ending its row
        under the head of its caption, the rest of its caption beginning the next row, with the drawings after it:
        a group cut free on a part of its own, its equations going on with its polygon."""
        rows: list[list[Drawing]] = []
        origins: list[int] = []
        for origin, row in zip(self.origins, self.drawings, strict=True):
            current: list[Drawing] = []
            for drawing in row:
                if drawing.name in names and drawing.parted is not None:
                    head, rest = drawing.parted
                    rows.append([*current, head])
                    origins.append(origin)
                    current = [rest]
                else:
                    current.append(drawing)
            rows.append(current)
            origins.append(origin)
        return Rows(rows, self.heading, origins)

    def unheld(self, fits: Fits, headed: bool = False) -> dict[str, tuple[float, float]]:
        """The drawings that do not fit even alone with no heading (``headed``: under the heading), with their
        (width, height)."""
        alone = self._apart()
        sizes = {}
        for k, (drawing,) in enumerate(alone.drawings):
            title = self.heading.part_title if headed else HEADLESS
            x0, y0, x1, y1 = bounds(alone.arranged((((k, False),),), title).layers)
            if not fits(x1 - x0, y1 - y0):
                sizes[drawing.name] = (round(x1 - x0), round(y1 - y0))
        return sizes

    def _apart(self) -> Rows:
        """Every drawing a row of its own."""
        return Rows([[drawing] for row in self.drawings for drawing in row], self.heading,
                    [origin for origin, row in zip(self.origins, self.drawings, strict=True) for _ in row])

    def _parts(self, fits: Fits, headless: bool = False) -> list[list[Part]]:
        """:meth:`cuts` with the rows as they are; where ``headless``, a row that fits under no heading stands
        under one with its long captions beside its drawings (:class:`Part`'s other way, which the packing takes
        where the usual one fits no sheet), else alone without one (rows that fit only so together stand apart
        under their headings instead: a part without a heading is for a drawing that has no room for one, not a
        way to save a sheet)."""
        heading = self.heading
        count = len(self)
        for title in (heading.title, heading.part_title):
            whole = self._least(0, count, fits, title)
            if whole is not None:
                return [[self._part(whole[1], title, whole[2])]]
        best_of: dict[tuple[int, int], tuple[float, Shape, bool, str] | None] = {}

        def best(start: int, stop: int) -> tuple[float, Shape, bool, str] | None:
            if (start, stop) not in best_of:
                title = self._title_of(start)
                # A group cut free with friction, its equations under it, missed an A3 under its heading by 4 mm
                # and stood on a sheet with no heading at all, where beside it they leave the heading room.
                ways = ((title, False), (title, True), (HEADLESS, False)) if headless and stop == start + 1 \
                    else ((title, False),)
                best_of[start, stop] = next(((*found, title) for title, aside in ways
                                             for found in [self._least(start, stop, fits, title, aside)] if found),
                                            None)
            return best_of[start, stop]

        for pieces in range(2, count + 1):
            found: list[tuple[tuple[int, float], list[tuple[Shape, str, bool]]]] = []
            for cuts in itertools.combinations(range(1, count), pieces - 1):
                chosen = [best(a, b) for a, b in itertools.pairwise((0, *cuts, count))]
                if any(choice is None for choice in chosen):
                    continue
                # Of as many parts, the fewest that cut a row of the sheet apart, then the least paper.
                cost = (sum(self.origins[cut - 1] == self.origins[cut] for cut in cuts),
                        sum(choice[0] for choice in chosen if choice is not None))
                found.append((cost, [(choice[1], choice[3], choice[2]) for choice in chosen if choice is not None]))
            if found:
                fewest_apart = min(cost[0] for cost, _ in found)
                kept = sorted((item for item in found if item[0][0] == fewest_apart), key=lambda item: item[0])
                return [self._arranged_parts(ways) for _, ways in kept[:MOST_CUTS]]
        return []

    def _arranged_parts(self, ways: Sequence[tuple[Shape, str, bool]]) -> list[Part]:
        """The parts of one cut, each (shape, title, one_line), arranged under their headings, each with the same
        part with its long captions beside their drawings where that is lower."""
        # After parts with no heading, the first heading is the sheet's, not "continued" (no longer).
        headed = next((k for k, (_, title, _) in enumerate(ways) if title != HEADLESS), None)
        return [self._part(shape, self.heading.part_title if k == headed else title, one_line)
                for k, (shape, title, one_line) in enumerate(ways)]

    def _part(self, shape: Shape, title: str, one_line: bool) -> Part:
        """A part as ``shape`` has it under ``title``, and as it stands with its long captions beside its drawings
        where that is lower."""
        usual = self.arranged(shape, title, one_line, part=True)
        aside = self.arranged(shape, title, one_line, part=True, aside=True)
        return Part(usual.layers, usual.fields, aside if _height(aside) < _height(usual) - 1e-6 else None)

    def _title_of(self, start: int) -> str:
        """The heading of the part of several that begins with row ``start``."""
        return self.heading.part_title if start == 0 else self.heading.continued

    def _least(self, start: int, stop: int, fits: Fits, title: str, aside: bool = False
               ) -> tuple[float, Shape, bool] | None:
        """Of the ways rows ``start``..``stop`` may stand under ``title`` (``aside``: with their long captions
        beside their drawings), the one taking least paper that ``fits`` once drawn (the estimate of its size may
        be a little off), with its area and whether its title stands on one line; None when none does.

        The title stands on one line where that fits: broken to drawings
        narrower than it, it went onto two lines though the sheet had room.
        """
        sized = [(self._size(shape, title, aside=aside), shape) for shape in self._shapes(start, stop)]
        for _, shape in sorted(sized, key=lambda item: item[0][0] * item[0][1]):
            for one_line in (True, False):
                width, height = self._size(shape, title, one_line, aside)
                if not fits(width - ESTIMATE_SLACK_MM, height - ESTIMATE_SLACK_MM):
                    continue
                x0, y0, x1, y1 = bounds(self.arranged(shape, title, one_line, aside=aside).layers)
                if fits(x1 - x0, y1 - y0):
                    return (x1 - x0) * (y1 - y0), shape, one_line
        return None

    def _shapes(self, start: int, stop: int) -> Iterator[Shape]:
        """Every way rows ``start``..``stop`` may stand: each column a run of them, each row side by side or
        stacked; all side by side in one column first."""
        indices = range(start, stop)
        stackable = [k for k in indices if len(self.drawings[k]) > 1]
        if len(indices) > MOST_ROWS_TRIED_STACKED:
            stackable = []
        for stacks in itertools.chain.from_iterable(itertools.combinations(stackable, n)
                                                    for n in range(len(stackable) + 1)):
            for cuts in itertools.chain.from_iterable(itertools.combinations(indices[1:], n)
                                                      for n in range(len(indices))):
                bounds = (start, *cuts, stop)
                yield tuple(tuple((k, k in stacks) for k in range(a, b)) for a, b in itertools.pairwise(bounds))

    def _size(self, shape: Shape, title: str, one_line: bool = False, aside: bool = False) -> tuple[float, float]:
        """The size ``shape`` takes under ``title`` (``aside``: its long captions beside its drawings), estimated
        from the rows' sizes without drawing it."""
        widths = [max(self.block(k, stacked, aside).width for k, stacked in column) for column in shape]
        heights = [sum(self.block(k, stacked, aside).height for k, stacked in column) + GAP_MM * (len(column) - 1)
                   for column in shape]
        width = sum(widths) + GAP_MM * (len(shape) - 1)
        if title == HEADLESS:
            return width, max(heights)
        heading_width, heading_height = self._heading_size(title, _ONE_LINE_MM if one_line else round(width))
        return max(width, heading_width), max(heights) + HEADING_GAP_MM + heading_height

    def _heading_size(self, title: str, width: float) -> tuple[float, float]:
        """The heading's (width, height) over drawings ``width`` mm wide, measured with the line of all the sheet's
        scales (:class:`Heading`: which of them a part names moves no drawing; remembered: every way asks)."""
        if (title, width) not in self._heading_sizes:
            x0, y0, x1, y1 = bounds_of(self._heading_layer(0.0, 0.0, title, self.heading.whole_scales, width).items)
            self._heading_sizes[title, width] = (x1 - x0, y1 - y0)
        return self._heading_sizes[title, width]

    def _heading_layer(self, left: float, scales_line: float, title: str, scales: str, width: float) -> Layer:
        """``title`` broken to ``width`` mm (to no less than a caption's width) over the line of the scales
        ``scales``, where the drawings under it have any."""
        size = self.heading.title_size
        lines = fitted(title, max(width, CAPTION_WIDTH_MM), size, "bold")
        scale_texts = (Text((left, scales_line), scales, self.heading.size, "start"),) if scales else ()
        return Layer(HEADING_LAYER, (*title_texts(lines, size, (left, scales_line + CAPTION_LINE * size)),
                                     *scale_texts))


def _extent(drawing: Drawing) -> tuple[float, float, float, float]:
    """The bounds of ``drawing``'s lines and words; a caption with no drawing (a group's equations set apart) has
    none, its field no height."""
    return bounds(drawing.layers) if any(layer.items for layer in drawing.layers) else (0.0, 0.0, 0.0, 0.0)


def _captions_under(row: Sequence[Drawing], extents: Sequence[tuple[float, float, float, float]],
                    size: float) -> list[list[tuple[str, str]]]:
    """Each drawing's caption of ``row`` broken to stand under it: as wide as the drawing, at least
    :data:`CAPTION_WIDTH_MM`."""
    return [caption_lines(drawing.caption, max(x1 - x0, CAPTION_WIDTH_MM), size, drawing.run_on)
            for drawing, (x0, _, x1, _) in zip(row, extents, strict=True)]


def _side_by_side(row: Sequence[Drawing], size: float) -> _Block:
    """The drawings of ``row`` side by side, each in the middle of a field as tall as the tallest."""
    extents = [_extent(drawing) for drawing in row]
    height = max(y1 - y0 for _, y0, _, y1 in extents)
    captions = _captions_under(row, extents, size)
    layers: list[Layer] = []
    fields: dict[str, tuple[float, float, float, float]] = {}
    cursor = 0.0
    for drawing, (x0, y0, x1, y1), caption in zip(row, extents, captions, strict=True):
        width = max(x1 - x0, *(text_width(line, size, weight) for line, weight in caption))
        fields[drawing.name] = (cursor, -height, cursor + width, 0.0)
        layers.extend(moved_layers(drawing.layers, cursor + (width - (x1 - x0)) / 2 - x0, -height / 2 - (y0 + y1) / 2))
        layers.append(_caption_layer(drawing.name, cursor + width / 2, -height, caption, size))
        cursor += width + GAP_MM
    lines = max(len(caption) for caption in captions)
    return _Block(layers, fields, cursor - GAP_MM, height + CAPTION_GAP_MM + lines * CAPTION_LINE * size)


def _stacked(row: Sequence[Drawing], size: float) -> _Block:
    """The drawings of ``row`` one under another (the polygon under its group), each with its caption, in
    the middle of a field as wide as the widest."""
    extents = [_extent(drawing) for drawing in row]
    captions = _captions_under(row, extents, size)
    width = max(max(x1 - x0, *(text_width(line, size, weight) for line, weight in caption))
                for (x0, _, x1, _), caption in zip(extents, captions, strict=True))
    # A caption's end that runs on (:class:`RunOn`) may take the whole width the group above the polygon has
    # already made the field: the line costs no paper there, and a line saved is a line less of the column.
    captions = [caption_lines(drawing.caption, max(x1 - x0, CAPTION_WIDTH_MM), size, drawing.run_on, width)
                for drawing, (x0, _, x1, _) in zip(row, extents, strict=True)]
    layers: list[Layer] = []
    fields: dict[str, tuple[float, float, float, float]] = {}
    top = 0.0
    for drawing, (x0, y0, x1, y1), caption in zip(row, extents, captions, strict=True):
        height = y1 - y0
        fields[drawing.name] = (0.0, top - height, width, top)
        layers.extend(moved_layers(drawing.layers, (width - (x1 - x0)) / 2 - x0, top - height / 2 - (y0 + y1) / 2))
        layers.append(_caption_layer(drawing.name, width / 2, top - height, caption, size))
        # A drawing's caption and the next drawing stand as close as a drawing and its caption: one group.
        top -= height + CAPTION_GAP_MM + len(caption) * CAPTION_LINE * size + CAPTION_GAP_MM
    return _Block(layers, fields, width, -top - CAPTION_GAP_MM)


def _height(arrangement: Arrangement) -> float:
    _, y0, _, y1 = bounds(arrangement.layers)
    return y1 - y0


def _captions_beside(row: Sequence[Drawing], size: float, under_height: float) -> _Block | None:
    """The drawings of ``row`` side by side, each caption that makes its drawing taller than the row needs be
    (a group's equations, the lever's) set beside the drawing, on its right, the others under theirs; None where
    that makes the row no lower than ``under_height``, its height with every caption under its drawing
    (:func:`_side_by_side`).

    A caption beside its drawing is broken to the narrowest width of
    :data:`CAPTION_BESIDE_WIDTHS_MM` that keeps it no taller than the
    drawing, and set from the left, level with the drawing's middle; the
    row is as tall as the tallest drawing or caption beside one, and a
    caption under its drawing stays there wherever the two are no taller.
    """
    extents = [_extent(drawing) for drawing in row]
    under = _captions_under(row, extents, size)
    beside = [_caption_beside(drawing, y1 - y0, size) for drawing, (_, y0, _, y1) in zip(row, extents, strict=True)]
    height = max(max(y1 - y0, _lines_height(caption, size))
                 for (_, y0, _, y1), caption in zip(extents, beside, strict=True))
    moved = [y1 - y0 + CAPTION_GAP_MM + _lines_height(caption, size) > height + 1e-9
             for (_, y0, _, y1), caption in zip(extents, under, strict=True)]
    if not any(moved) or height >= under_height - 1e-9:
        return None
    # The drawings that keep their captions under them stand over one line of captions, as side by side.
    kept_lines = max((len(caption) for caption, aside in zip(under, moved, strict=True) if not aside), default=0)
    kept_height = height - (CAPTION_GAP_MM + kept_lines * CAPTION_LINE * size if kept_lines else 0.0)
    layers: list[Layer] = []
    fields: dict[str, tuple[float, float, float, float]] = {}
    cursor = 0.0
    for drawing, (x0, y0, x1, y1), below, aside, caption in zip(row, extents, under, moved, beside, strict=True):
        if aside:
            text_left = cursor + x1 - x0 + CAPTION_GAP_MM
            width = text_left - cursor + max(text_width(line, size, weight) for line, weight in caption)
            layers.extend(moved_layers(drawing.layers, cursor - x0, -height / 2 - (y0 + y1) / 2))
            # The first line's capitals stand a letter under the top of the caption's lines (:func:`_lines_height`).
            top = -height / 2 + _lines_height(caption, size) / 2 - size
            layers.append(Layer(f"{drawing.name}-caption", tuple(
                Text((text_left, top - k * CAPTION_LINE * size), line, size, "start", weight=weight)
                for k, (line, weight) in enumerate(caption))))
        else:
            width = max(x1 - x0, *(text_width(line, size, weight) for line, weight in below))
            layers.extend(moved_layers(drawing.layers, cursor + (width - (x1 - x0)) / 2 - x0,
                                       -kept_height / 2 - (y0 + y1) / 2))
            layers.append(_caption_layer(drawing.name, cursor + width / 2, -kept_height, below, size))
        fields[drawing.name] = (cursor, -height, cursor + width, 0.0)
        cursor += width + GAP_MM
    return _Block(layers, fields, cursor - GAP_MM, height)


def _caption_beside(drawing: Drawing, height: float, size: float) -> list[tuple[str, str]]:
    """``drawing``'s caption broken to the narrowest width that keeps it no taller than ``height`` mm, the
    drawing's, and to the widest where none does."""
    # Broken width by width, the narrowest first, as far as the first that fits: breaking every caption of a sheet's
    # rows six ways was an eighth of an A3 set's sheets.  Not so narrow that a line ends on a name's colon, what it
    # names on the next: at 70 mm the lever's "arrows: μF = 40 N/mm (no arrow shorter than 10 mm)" left "arrows:"
    # alone, though the phrase is no place for a break where the width holds it (:data:`wrapping.NAME_BEFORE`).
    for width in CAPTION_BESIDE_WIDTHS_MM:
        lines = caption_lines(drawing.caption, width, size, drawing.run_on)
        if _lines_height(lines, size) <= height and not any(NAME_BEFORE.search(line) for line, _ in lines):
            break
    return lines


def _lines_height(lines: Sequence[tuple[str, str]], size: float) -> float:
    """The height a caption's lines take, a line of lettering each (as under a drawing, :func:`_side_by_side`)."""
    return len(lines) * CAPTION_LINE * size


def _caption_layer(name: str, middle: float, under: float, caption: Sequence[tuple[str, str]], size: float) -> Layer:
    return Layer(f"{name}-caption", tuple(
        Text((middle, under - CAPTION_GAP_MM - k * CAPTION_LINE * size), line, size, "middle", weight=weight)
        for k, (line, weight) in enumerate(caption)))


def caption_lines(caption: Sequence[str], width: float, size: float, run_on: RunOn | None = None,
                  room: float | None = None) -> list[tuple[str, str]]:
    """A drawing's caption as (line, weight) pairs, its title bold, each line broken to ``width`` mm; a line
    that only says again what an equation above it found is left out.  The lines ``run_on`` stands for go on
    at the end of the line before them where ``room`` mm (``width`` by default) holds the two, else stand as its
    one line where that fits, else as the words and the values filling each line of ``room`` where that takes fewer
    lines than they do, else as they are."""
    end = len(caption) - (run_on.after if run_on is not None else 0)
    start = end - (run_on.lines if run_on is not None else 0)
    tail = caption[start:end]
    # Whether a line repeats a value depends only on the lines above it: the head's kept lines begin the whole's.
    kept_head = _unrepeated(caption[:start])
    kept_rest = _unrepeated([*caption[:start], *caption[end:]])[len(kept_head):]

    def broken(texts: Sequence[str], first: int) -> list[tuple[str, str]]:
        return [(piece, "bold" if first + k == 0 else "normal") for k, line in enumerate(texts)
                for piece in fitted(line, width, size, "bold" if first + k == 0 else "normal")]

    lines = broken(kept_head, 0)
    rest = broken(kept_rest, len(kept_head) + len(tail))
    if run_on is None or not tail or not lines:
        return lines + [(piece, "normal") for line in tail for piece in fitted(line, width, size)] + rest
    reach = max(width, room or 0.0)
    before, weight = lines[-1]
    if text_width(before + run_on.joint + run_on.alone, size, weight) <= reach:
        return [*lines[:-1], (before + run_on.joint + run_on.alone, weight), *rest]
    if text_width(run_on.alone, size) <= reach:
        return [*lines, (run_on.alone, "normal"), *rest]
    apart = [piece for line in tail for piece in fitted(line, width, size)]
    # The values filling each line of the room where that takes fewer lines: the lever's four short arms took a line
    # of words and three of values (three a line, the third broken off), two of values so.  A line of values alone
    # keeps the Latin semicolon, as in Chinese a line with no Chinese words in it does.
    filled = [*fitted(tail[0], width, size), *fitted("; ".join(run_on.values), reach, size)]
    return [*lines, *((piece, "normal") for piece in (filled if run_on.values and len(filled) < len(apart) else apart)),
            *rest]


# What an equation's line finds, at its end: "ΣMO(2): Mb − G2·h1 − R32·h2 = 0,  Mb = 96.55 N·m".
_FOUND = re.compile(r"= 0,\s+(\S+ = \S+(?: \S+)?)$")


def _unrepeated(caption: Sequence[str]) -> list[str]:
    """``caption`` without the lines that give nothing but a value an equation above already found: the
    crank's "balancing moment Mb = 96.55 N·m (force polygons)" under its ΣMO(2) that ends "Mb = 96.55 N·m".
    A line that goes on with a number of its own is kept: the sheet with friction's "Mb = −2.00 N·m after 10
    passes; without friction 6.48 N·m: …" gives the load without friction, though no "=" is left in it."""
    found: list[str] = []
    kept = []
    for line in caption:
        rest = line
        for value in found:
            rest = rest.replace(value, "")
        if rest != line and "=" not in rest and not any(character.isdigit() for character in rest):
            continue
        kept.append(line)
        if (match := _FOUND.search(line)) is not None:
            found.append(match.group(1))
    return kept
