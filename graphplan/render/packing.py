"""Panels packed onto pages: where each drawing of a set of sheets stands.

The drawings come as :class:`Panel` s, each at its own scale factors: a
panel is never scaled, since μl, μV, μa and μF are written beside it and a
shrunken drawing would falsify them.  Panels are placed in the order given,
each where the drawings of the sheet stay most compact (then as high and
as far left as can be), never nearer than :data:`GAP_MM` to another (the
plan sheets of two positions :data:`BETWEEN_POSITIONS_MM`, so that each reads as one block) or
than :data:`PADDING_MM` to the frame, the title block and ESKD's графа 26; the drawings of
a sheet are then moved together towards its middle.  A panel goes on the
first sheet of the set with room for it, else on a new sheet of the same
format, but never on a sheet before one with a drawing of its kind (the
plans of position 11 never come before those of position 5), nor on its
sheet as high as one of its kind unless all to the right of it, and under a
heading of its own beside another position's drawing of its kind only with
their tops level.  A plan sheet
of one position stands as a row (mechanism, velocity plan, acceleration
plan) wherever that fits, else with its mechanism above its plans or
beside them, so that it may join a sheet with room of another shape, and
the drawings already on a sheet are arranged afresh in their other ways,
or grown down a column or along a row instead of as a block, where only
that makes room for the next (fewest changed first), and then with a drawing
moved off its most compact spot, where that left no room for one after it; a force sheet stands
in one column of rows, else in two, and a part of it that goes on from a
part on the same sheet stands under that part's heading, without its own, and each heading then names the
scales of the drawings under it on its sheet.  A panel too big for
an empty sheet every way it may stand is placed part by part (a plan sheet
of one position as its mechanism, velocity plan and acceleration plan; a
force sheet as its groups, each beside its polygon, and the lever), on
sheets of its own whose title block names it.
"""

from __future__ import annotations

import contextlib
import functools
import heapq
import itertools
import re
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field, replace

from ..errors import SceneError
from ..memo import RecentMemo
from .force_rows import HEADING_LAYER, has_heading, scales_line, with_scales_line
from .formats import BIGGER, PADDING_MM, PageGeometry, Rect, check_sheet, holds, orientations, page_geometry
from .primitives import Layer, bounds

# Space between two drawings (mm).
GAP_MM = 15.0
# Space between the plan sheets of two positions (mm): wider than between the drawings of one
# (:data:`graphplan.render.plans.GAP_MM`, 25 mm), so that each position's mechanism and plans read as one block.  At
# 15 mm, the plans of position 4 stood nearer to the mechanism of position 11 beside them than to their own.
BETWEEN_POSITIONS_MM = 35.0
# A free strip of an empty sheet narrower than this (mm) is no room a refusal offers.
_LEAST_ROOM_MM = 10.0
# A drawing may reach this far (mm) past the area's edge or into the room kept round another: rounding, not overlap.
_EDGE = 1e-6
# How a page's drawings grow as each is placed (:meth:`Page.place`): as a block of the sheet's shape, which
# fills a page, or down a column or along a row, which a page is laid out afresh in where a block leaves no room
# for the next drawing.
GROWTHS = ("block", "column", "row")


@dataclass(frozen=True)
class Panel:
    """A drawing to place on a sheet, at its own scales.

    ``layers`` is the drawing whole (paper mm, anywhere); ``parts`` the same
    drawing cut into pieces that may stand apart, used when the whole does
    not fit a sheet; ``label`` says what the drawing is, for the title block
    of a sheet that holds only its parts.  ``name`` prefixes the ids of its
    layers and arrows on the sheet, so that two panels' ids never clash.
    ``length_scale`` is μl where the drawing is drawn at another μl than
    the set's (a force sheet made smaller for a small sheet), for the title
    block's scale box.  ``alternatives`` are the same drawing whole, its
    parts arranged otherwise (a plan sheet's mechanism above or beside its
    plans): the packing takes the first way that fits a sheet's room.
    """

    name: str
    layers: tuple[Layer, ...]
    parts: tuple[Panel, ...] = ()
    label: str = ""
    length_scale: float | None = None
    alternatives: tuple[Panel, ...] = ()
    # The part of the same drawing this one goes on from (a force sheet's "continued" part): where both stand
    # on one sheet, this one's heading is left off, and the two read as one drawing.
    continues: str = ""
    # False for a drawing to no length scale (a kinematic diagram, a plot of the dynamics): a sheet of such alone
    # leaves its title block's scale box empty.
    to_scale: bool = True
    # μV of the Zhukovsky's lever on a force sheet as it is drawn here (a small sheet draws it smaller than the
    # plan's enlarged lever); the note works the lever at forces_N.svg's scale, the drawing laid out alone.
    lever_scale: float | None = None
    # True where the parts are a sequence read in its order (the velocity plans of positions 1, 2, 3, … by rows):
    # they are never put tallest or largest first to save a sheet.
    in_order: bool = False
    # The drawing's heading, in no part of it (a plan sheet's "Velocity and acceleration plans, position 11"): put
    # over its parts where they stand on sheets of their own and that costs no sheet; they stood headless, the
    # heading only in the title block, the top drawing against the frame's margin.
    heading: tuple[Layer, ...] = ()
    # The heading over the parts on the sheets after the first (the title "continued"), as the force sheets' parts
    # have it: the same title repeated read as another drawing.  Its ways (on one line, broken), the first a sheet
    # holds taken; none given: ``heading`` on every sheet.
    continued_heading: tuple[tuple[Layer, ...], ...] = ()
    # ``heading`` broken onto lines, for a sheet too narrow for it on one: its ways, each narrower than the one before,
    # the first a sheet holds taken; none given: never broken.
    broken_heading: tuple[tuple[Layer, ...], ...] = ()
    # The scales a force sheet's part's heading may name, each with the start of the names of the drawings drawn at
    # it (:attr:`force_rows.Heading.scales`): drawn naming those of every drawing that may stand under it, once
    # packed it names those of the drawings that do (:func:`_headings_named`).  None given: the heading as drawn.
    heading_scales: tuple[tuple[str, str], ...] = ()
    heading_comma: str = ", "  # what sets those scales apart (:attr:`force_rows.Heading.comma`)
    # A force sheet drawn larger for a course sheet with room (:func:`force_sheet_choice.larger_where_room`): the μF
    # of each of its polygons drawn at another than the record's, by its group's label, for the check of readings
    # measured on it.
    polygon_scales: tuple[tuple[str, float], ...] = ()
    # Of the same, the μF each group cut free (drawn larger too, or as the record) draws its arrows at, by its label,
    # with the reactions drawn whole at their length (:func:`force_bodies.free_body_arrows`): readings measured on
    # them too.
    body_arrows: tuple[tuple[str, float, tuple[str, ...]], ...] = ()
    # True where ``layers`` are the drawing as the run writes it in a file of its own (a force sheet at its own
    # scales and lettering, the load diagrams at their usual fields), which the run then takes from here instead of
    # laying it out twice; a drawing the sheets altered to fit (a lever stepped back, smaller lettering, a larger
    # scale) is laid out again for its file, which no sheet format may change.
    drawn_alone: bool = False
    # The drawing as it goes on the sheet, where ``layers`` leaves out labels that only room was kept for: the
    # same extent, its labels placed only for the way the packing takes (each larger size of the kinematic
    # diagrams, measured by its unlettered layers).  None: ``layers`` as they are.
    lettered: Callable[[], tuple[Layer, ...]] | None = field(default=None, repr=False, compare=False)
    # A sequence no sheet holds whole that a sheet's room takes run by run (the velocity plans of every position):
    # ``runs(start, stop)`` draws its items start to stop - 1 as one drawing in each of its ways, the first under
    # the title, a later one under its own heading; ``run_count`` is how many items there are.  Cut into fixed
    # parts instead (a grid's rows), a sheet with room for a row and a half took one row, and the grid went one
    # row to a sheet.
    runs: Callable[[int, int], Panel] | None = field(default=None, repr=False, compare=False)
    run_count: int = 0
    # True for such a run as placed: it stands below every run of its drawing before it on the sheet, so that the
    # sheet reads as one grid, row after row.
    in_rows: bool = False
    # The kind of drawing this one is read after (the load diagrams after the force sheets, whose values they give):
    # it goes on no sheet before the last of that kind unless only a sheet before it has room for it, which saves
    # the sheet it would open.  The slider-crank's load diagrams stood on A3 sheet 7, in room the second part of
    # position 2's force sheet had left there, before the force sheet of position 8 on sheets 8 and 9.
    reads_after: str = ""
    extent: Rect = field(init=False, repr=False, compare=False)
    # The drawing with its heading left off, made once (:meth:`without_heading`): a part that goes on from another
    # is asked for so at every sheet it is tried on, and measured anew each time.
    _headless_way: Panel | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        # Computed once: the packing asks for it at every spot it tries.
        object.__setattr__(self, "extent", _extent(self.layers))

    @property
    def ways(self) -> tuple[Panel, ...]:
        """The drawing whole as arranged, then as each alternative arranges it."""
        return (self, *self.alternatives)

    def without_heading(self) -> Panel:
        """The drawing with its heading left off, as it stands on the sheet of the part it goes on from."""
        if self._headless_way is None:
            lettered = self.lettered
            object.__setattr__(self, "_headless_way", replace(
                self, layers=_headless_layers(self.layers),
                alternatives=tuple(way.without_heading() for way in self.alternatives),
                lettered=None if lettered is None else lambda: _headless_layers(lettered())))
        return self._headless_way

    def drawn_layers(self) -> tuple[Layer, ...]:
        """The layers the sheet draws: lettered (:attr:`lettered`) where the labels wait for the way taken."""
        return self.layers if self.lettered is None else self.lettered()


def _headless_layers(layers: tuple[Layer, ...]) -> tuple[Layer, ...]:
    return tuple(layer for layer in layers if layer.name != HEADING_LAYER)


# The extents of the layers of the panels made lately, by the layers' identity: a panel replaced in another field
# alone (its alternatives left off, its heading named, its parts moved) keeps its layers, which were measured with
# the panel it came from, and a sheet set replaces its panels a hundred times and more.
_EXTENTS: dict[int, tuple[tuple[Layer, ...], Rect]] = {}
_EXTENTS_KEPT = 256


def _extent(layers: tuple[Layer, ...]) -> Rect:
    known = _EXTENTS.get(id(layers))
    if known is not None and known[0] is layers:
        return known[1]
    extent = tuple(float(value) for value in bounds(layers))
    # Kept only where nothing in it can change: a tuple of layers whose items are tuples (of frozen primitives).
    if type(layers) is tuple and all(type(layer.items) is tuple for layer in layers):
        if len(_EXTENTS) >= _EXTENTS_KEPT:
            del _EXTENTS[next(iter(_EXTENTS))]
        _EXTENTS[id(layers)] = (layers, extent)
    return extent


def _headless(panel: Panel) -> bool:
    """Whether ``panel`` is a part that goes on from another, or a force sheet's first part (one with a heading's
    scales to name), with no heading of its own."""
    # The first part of the crank-rocker's sheet with friction of position 5, going on from none, stood headless
    # beside the lever of the sheet without friction on an English A3, under that one's heading.
    return bool(panel.continues or panel.heading_scales) and not has_heading(panel.layers)


def _whole_of(panel: Panel) -> str:
    """The drawing a part is of: ``forces-2`` of ``forces-2-5``; a drawing that is no part, its own name."""
    return re.sub(r"-\d+$", "", panel.name) if panel.continues else panel.name


def smallest_drawings(parts: Sequence[Panel]) -> list[Panel]:
    """``parts`` cut into their smallest drawings: each part's own parts, or the part where it has none."""
    return [piece for part in parts for piece in (part.parts or (part,))]


@dataclass
class Page:
    """A sheet being filled: its size, the area panels may take, the title block, what is placed."""

    size: tuple[float, float]
    frame: Rect
    block: Rect
    area: Rect
    placed: list[tuple[Panel, Rect, tuple[float, float]]] = field(default_factory=list)
    label: str = ""
    # The drawings placed, each with every way it may stand, for the page to be laid out afresh.
    drawings: list[Panel] = field(default_factory=list)
    growth: str = "block"
    # The box in the frame's top left corner that drawings keep clear of as of the title block (ESKD's графа 26).
    corner: Rect | None = None
    # Whether a drawing goes under the corner box rather than beside it where both are as compact.
    tuck: bool = True
    # Whether the page holds parts of a drawing that stands under a heading, with none of it over them: only the
    # title block says whose they are (:func:`_bare`).
    bare: bool = False

    def obstacles(self) -> list[Rect]:
        """The title block and the corner box, each grown by the room a drawing keeps from it."""
        return [_grown(box, PADDING_MM) for box in (self.block, self.corner) if box is not None]

    def place(self, panel: Panel) -> bool:
        """Put ``panel``, arranged in the first of its ways that fits, where the drawings stay most compact,
        then as high and as far left as can be.

        Compact is measured by the share of the area's width and of its
        height that the drawings' common bounds take: as a ``block`` the
        larger share, so the drawings grow together as a block of the
        sheet's shape; as a ``column`` the share of the width, then of the
        height; as a ``row`` the other way round (:data:`GROWTHS`).  False
        when the panel does not fit.
        """
        found = self._candidates(panel, 1)
        if not found:
            return False
        self._put(*found[0])
        return True

    def _candidates(self, panel: Panel, most: int) -> list[tuple[Panel, Panel, Rect]]:
        """Where ``panel`` may go, the best first, at most ``most`` spots: each as (the drawing as the page keeps
        it, the way it stands in, the spot), in the first of its ways that fits."""
        # A part too big to stand under its heading says whose it is only by its sheet's title block: beside
        # another drawing it read as that one's (position 2's lever under "position 7"), so the two never share.
        others = [drawing for drawing in self.drawings if _whole_of(drawing) != _whole_of(panel)]
        spots_of = {placed.name: rect for placed, rect, _ in self.placed}

        def unowned(drawing: Panel) -> bool:
            # A part headless only because it stands under the part it goes on from (a run of a grid, a force sheet's
            # rows) reads as that one's: no ambiguity.  Kept apart, the offset slider-crank's load diagrams found no
            # room on the sheet of a force sheet's rows, though the room was there.
            return _headless(drawing) and drawing.continues not in spots_of

        def stray(drawing: Panel) -> bool:
            # Headless away from the part it goes on from, it reads as the drawing's it stands by: position 11's
            # driving link stood under position 4's, the slotted lever's English A1.  Only a drawing of the same kind
            # is mistaken for its whole (a lever by load diagrams under their own heading is no load diagram).
            return _headless(drawing) and drawing.continues in spots_of and \
                not _goes_on_from(spots_of[drawing.name], spots_of[drawing.continues])

        if others and (unowned(panel) or any(map(unowned, others))):
            return []
        rivals = [drawing for drawing in others if _kind(drawing) == _kind(panel)]
        if any(map(stray, rivals)):
            return []
        if panel.continues and panel.continues in spots_of:
            # Under the heading of the part it goes on from, which it would only repeat as "continued": by another
            # whole of its kind only next to that part, else with its heading.
            earlier = spots_of[panel.continues]
            found = self._spots_in_first_way(panel.without_heading(), most,
                                             (lambda rect: _goes_on_from(rect, earlier)) if rivals else None)
            if found or not rivals:
                return found
        return self._spots_in_first_way(panel, most)

    def _spots_in_first_way(self, panel: Panel, most: int,
                            allowed: Callable[[Rect], bool] | None = None) -> list[tuple[Panel, Panel, Rect]]:
        """``panel``'s ``most`` best spots (of those ``allowed``) in the first of its ways that has any, as
        :meth:`_candidates` gives them; none where no way fits."""
        for way in panel.ways:
            spots = self._spots(way, most, allowed)
            if spots:
                return [(panel, way, rect) for rect in spots]
        return []

    def place_all(self, panels: Sequence[Panel], moves: int = 0) -> bool:
        """Put ``panels`` in order, each as :meth:`place` puts it; where one finds no room, a drawing before it
        at its next best spot and those after it placed afresh, at most ``moves`` times in all.  False, the page
        as it was, where they do not all fit."""
        left = [moves]

        def put_from(k: int) -> bool:
            if k == len(panels):
                return True
            for found in self._candidates(panels[k], _SPOTS_TRIED if moves else 1):
                self._put(*found)
                if put_from(k + 1):
                    return True
                self._unput()
                if left[0] <= 0:
                    return False
                left[0] -= 1
            return False

        return put_from(0)

    def _put(self, panel: Panel, way: Panel, rect: Rect) -> None:
        x0, _, _, y1 = way.extent
        self.placed.append((way, rect, (rect[0] - x0, rect[3] - y1)))
        self.drawings.append(panel)

    def _unput(self) -> None:
        self.placed.pop()
        self.drawings.pop()

    def _spots(self, panel: Panel, most: int, allowed: Callable[[Rect], bool] | None = None) -> list[Rect]:
        """The ``most`` spots where ``panel`` as arranged keeps the drawings most compact, the best first, of those
        ``allowed`` where given; none where it fits nowhere."""
        x0, y0, x1, y1 = panel.extent
        width, height = x1 - x0, y1 - y0
        rects = [rect for _, rect, _ in self.placed]
        kind = _kind(panel)
        same_kind = [rect for placed, rect, _ in self.placed if _kind(placed) == kind]
        level_with = _headed_rivals(panel, self.placed)
        gaps = [_gap_between(panel, placed) for placed, _, _ in self.placed]
        # Against the area's edges, beside or under another drawing, level with one, or just above the block.
        xs = {self.area[0], self.area[2] - width, *(r[2] + gap for r, gap in zip(rects, gaps, strict=True)),
              *(r[0] - gap - width for r, gap in zip(rects, gaps, strict=True)), *(r[0] for r in rects)}
        tops = {self.area[3], self.block[3] + PADDING_MM + height,
                *(r[1] - gap for r, gap in zip(rects, gaps, strict=True)), *(r[3] for r in rects)}
        if self.corner is not None:
            # Beside the corner box, or under it.
            xs.add(self.corner[2] + PADDING_MM)
            tops.add(self.corner[1] - PADDING_MM)
        area_width, area_height = self.area[2] - self.area[0], self.area[3] - self.area[1]
        # Under a corner box is as high as beside it: a drawing put beside it, as high as can be, left the box's
        # width unused under it (the diagrams then found no room beside a plan sheet).
        highest = self.area[3] if self.corner is None or not self.tuck else self.corner[1] - PADDING_MM
        # What a drawing keeps clear of, and the drawings' common bounds so far: found once, not at every spot tried
        # (a sheet tries some twenty thousand).
        blocked = [*self.obstacles(), *(_grown(other, gap - _EDGE) for other, gap in zip(rects, gaps, strict=True))]
        common = [min(r[0] for r in rects), min(r[1] for r in rects), max(r[2] for r in rects),
                  max(r[3] for r in rects)] if rects else None
        ax0, ay0, ax1, ay1 = self.area
        # A spot is within the area and clear of every box blocked (the title block and the corner box, the drawings
        # placed, each grown by the room kept from it): a left and a top are each held to the area once, and a row
        # of spots tried only against the boxes level with it.  A sheet tries some twenty thousand spots.
        lefts = [left for left in xs if left >= ax0 - _EDGE and left + width <= ax1 + _EDGE]
        found: list[tuple[tuple[float, ...], Rect]] = []
        for top in tops:
            bottom = top - height
            if bottom < ay0 - _EDGE or top > ay1 + _EDGE:
                continue
            level = [box for box in blocked if bottom < box[3] and box[1] < top]
            for left in lefts:
                rect = (left, bottom, left + width, top)
                if any(left < box[2] and box[0] < rect[2] for box in level) \
                        or not all(_reads_after(rect, earlier) for earlier in same_kind):
                    continue
                if panel.in_rows and not all(rect[3] <= earlier[1] + 1e-6 for earlier in same_kind):
                    continue
                if not all(_level_or_apart(rect, other) for other in level_with):
                    continue
                if allowed is not None and not allowed(rect):
                    continue
                union = rect if common is None else (min(common[0], rect[0]), min(common[1], rect[1]),
                                                     max(common[2], rect[2]), max(common[3], rect[3]))
                key = self._compactness((union[2] - union[0]) / area_width, (union[3] - union[1]) / area_height)
                # Of two as high, the one level with the line under the corner box: drawings beside one another
                # keep one top.
                key += (-min(top, highest), left, top)
                found.append((key, rect))
        return [rect for _, rect in heapq.nsmallest(most, found)]

    def _compactness(self, width_share: float, height_share: float) -> tuple[float, ...]:
        """How compact drawings are whose common bounds take these shares of the area, as the page grows
        (the smaller the more compact)."""
        if self.growth == "column":
            return round(width_share, 3), round(height_share, 3)
        if self.growth == "row":
            return round(height_share, 3), round(width_share, 3)
        return (round(max(width_share, height_share), 3),)

    def fits_empty(self, panel: Panel) -> bool:
        geometry = PageGeometry(self.size, self.frame, self.block, self.area, self.corner)
        return any(geometry.holds(width(way), height(way)) for way in panel.ways)


def _gap_between(panel: Panel, other: Panel) -> float:
    """The least space between ``panel`` and ``other`` on a sheet: :data:`BETWEEN_POSITIONS_MM` between the plan
    sheets of two positions, each drawn whole, else :data:`GAP_MM`."""
    if _kind(panel) == _kind(other) == "plan" and panel.parts and other.parts:
        return BETWEEN_POSITIONS_MM
    return GAP_MM


def _headed_rivals(panel: Panel, placed: Sequence[tuple[Panel, Rect, tuple[float, float]]]) -> list[Rect]:
    """Where the drawings placed stand that ``panel`` may stand beside only with their tops level: other wholes of
    its kind, each under a heading of its own, as ``panel`` is.

    Beside one another at different heights, a heading stood level with the
    other's drawings, and a reader scanning the band under it met those
    first: on the V-twin's Russian A1, "положение 8" stood level with
    position 2's plans.  Not held so: a drawing's own parts; a part that goes
    on from another, whose heading says "continued" (held so, the double
    rocker's force sheets took a Russian A1 more); a drawing with no heading,
    which a reader pairs by its captions.
    """
    def headed_whole(drawing: Panel) -> bool:
        return not drawing.continues and has_heading(drawing.layers)

    if not headed_whole(panel):
        return []
    return [rect for other, rect, _ in placed if _kind(other) == _kind(panel)
            and _whole_of(other) != _whole_of(panel) and headed_whole(other)]


def _level_or_apart(rect: Rect, other: Rect) -> bool:
    """Whether a drawing at ``rect`` keeps its top level with one at ``other``, or stands clear of its height."""
    return abs(rect[3] - other[3]) <= 1e-6 or rect[1] >= other[3] - 1e-6 or rect[3] <= other[1] + 1e-6


def _reads_after(rect: Rect, earlier: Rect) -> bool:
    """Whether a drawing at ``rect`` is read after one at ``earlier``: its top lower, or all of it to the right
    (the next in a row, or the top of the next column).

    The plans of position 11 stand after those of position 5 on a sheet
    too, as the sheets keep them in order.
    """
    return rect[0] >= earlier[2] - 1e-6 or rect[3] < earlier[3] - 1e-6


def _goes_on_from(rect: Rect, earlier: Rect) -> bool:
    """Whether a part at ``rect`` stands next to the part at ``earlier`` it goes on from, so that it reads as going
    on under that one's heading: under it, across some of its width, with no room for another drawing between; or
    beside it, level with its top, as the next in its row."""
    near = 2.0 * GAP_MM
    under = rect[0] < earlier[2] and earlier[0] < rect[2] and earlier[1] - near <= rect[3] <= earlier[1] + _EDGE
    beside = earlier[2] - _EDGE <= rect[0] <= earlier[2] + near and abs(rect[3] - earlier[3]) <= _EDGE
    return under or beside


def overlap(a: Rect, b: Rect) -> bool:
    """Whether rectangles ``a`` and ``b`` (xmin, ymin, xmax, ymax) share some area."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _grown(rect: Rect, by: float) -> Rect:
    return (rect[0] - by, rect[1] - by, rect[2] + by, rect[3] + by)


def _empty_page(sheet: str, form: str, portrait: bool) -> Page:
    geometry = page_geometry(sheet, form, portrait)
    return Page(geometry.size, geometry.frame, geometry.block, geometry.area, corner=geometry.corner)


def pack(panels: Sequence[Panel], sheet: str, form: str) -> list[Page]:
    """The panels on as few sheets as this simple packing needs.

    An A4 stands upright or across, all sheets one way when that needs no
    more of them and leaves no more parts of a drawing bare (:attr:`Page.bare`),
    else each sheet the way its drawings fit (a tall plan of positions
    upright, wide diagrams across), as a set of A4 drawings may.
    A bigger sheet stands across, as a course project's do, and a sheet of
    it upright only where it opens with a drawing too tall for it across.
    """
    check_sheet(sheet)
    if not panels:
        # No sheets, as every format gives: an A4's choice between its turns asked the first sheet of none (a scene
        # without forces, whose force sheets are none, failed `run --sheet A4`).
        return []
    if not any(panel.runs is not None for panel in panels):
        return _packed(panels, sheet, form)
    # A sequence taken in runs fills each sheet, but each run that opens a sheet stands under its heading, which
    # on a narrow sheet (an upright A4) takes the room of a plan: where its plans apart, bare, as they stood before,
    # need fewer sheets, they stand so.
    apart = [replace(panel, runs=None) for panel in panels]
    try:
        flowed = _packed(panels, sheet, form)
    except SceneError:
        return _packed(apart, sheet, form)
    with contextlib.suppress(SceneError):
        fewer = _packed(apart, sheet, form)
        if len(fewer) < len(flowed):
            return fewer
    return flowed


def _packed(panels: Sequence[Panel], sheet: str, form: str) -> list[Page]:
    turns = orientations(sheet)
    if len(turns) == 1:
        return _pack_on(panels, sheet, form, turns)
    if sheet != "A4":
        with contextlib.suppress(SceneError):  # a drawing too tall across: its sheet stands upright
            return _pack_on(panels, sheet, form, (False,))
        return _pack_on(panels, sheet, form, turns)
    # ESKD puts an A4 upright; the other standards turn it as the drawing needs.
    upright_first = form == "eskd"
    packed = [_pack_on(panels, sheet, form, (upright_first, not upright_first))]
    # Each sheet turned as the drawing that opens it needs, the other way first too: an English slider-crank's
    # force sheets took a sheet fewer turned upright first than across first, and all upright left two bare.
    for ways in ((not upright_first, upright_first), *((portrait,) for portrait in turns)):
        try:
            packed.append(_pack_on(panels, sheet, form, ways))
        except SceneError:
            continue
    # One way only where that leaves no more drawings bare: all upright, a Chinese slider-crank's force sheet of
    # position 2 stood its driving link and polygon apart with no heading, where across it stood whole under it.
    return min(packed, key=lambda pages: (len(pages), sum(page.bare for page in pages),
                                          len({_upright(page) for page in pages}), _upright(pages[0]) != upright_first))


def _upright(page: Page) -> bool:
    return page.size[0] < page.size[1]


def _pack_on(panels: Sequence[Panel], sheet: str, form: str, turns: Sequence[bool]) -> list[Page]:
    """The panels packed in order, each on the first sheet with room for it that keeps the drawings of its
    kind in order; a new sheet is turned the first of ``turns`` (True: upright) that holds the panel that
    opens it."""
    pages: list[Page] = []
    # A small drawing fills a gap left sheets back, but the plans of position 11 never come before those
    # of position 5: a drawing goes no further back than the last sheet of a drawing of its kind.
    last_of_kind: dict[str, int] = {}
    for panel in panels:
        kind = _kind(panel)
        earliest = last_of_kind.get(kind, 0)
        # Read after the drawings of another kind: on their last sheet or after, before it only where that saves one.
        reads_from = max(earliest, last_of_kind.get(panel.reads_after, 0)) if panel.reads_after else earliest
        room = None
        for start, stop in ((reads_from, len(pages)), (earliest, reads_from)):
            room = next((k for k in range(start, stop) if not pages[k].label and pages[k].place(panel)), None)
            if room is None:
                room = _room_by_rearranging(pages, start, panel, stop)
            if room is not None:
                break
        if room is not None:
            last_of_kind[kind] = room
            continue
        page = _empty_page(sheet, form, _turn_holding(panel, sheet, form, turns))
        if page.place(panel):
            pages.append(page)
        elif panel.runs is not None:
            last_of_kind[kind] = _flowed(pages, earliest, panel, sheet, form, turns)
            continue
        elif not panel.parts:
            raise _too_big(panel, sheet, form, turns)
        else:
            # Parts go on sheets of their own, whose title block says whose parts they are.
            pages += _bare(panel, _parts_on(panel, sheet, form, turns))
        last_of_kind[kind] = len(pages) - 1
    for page in pages:
        _centre(page)
        _headings_named(page)
    return pages


def _bare(panel: Panel, pages: list[Page]) -> list[Page]:
    """``pages`` of ``panel``'s parts, each marked :attr:`Page.bare` where ``panel`` stands under a heading and no
    drawing on the page has one (of the panel's heading, a part's own, or its "continued")."""
    if has_heading(panel.layers):
        for page in pages:
            page.bare = not any(has_heading(drawing.layers) for drawing, _, _ in page.placed)
    return pages


def reads_in_order(pages: Sequence[Page]) -> bool:
    """Whether every drawing read after another kind (:attr:`Panel.reads_after`) stands on the last sheet of that
    kind or after it: :func:`pack` puts it before only where an earlier sheet alone has room for it, which the
    choice of the force sheets' cuts may still avoid (:func:`graphplan.render.force_sheet_choice.fewest_sheets_cuts`)."""
    last_of_kind: dict[str, int] = {}
    for k, page in enumerate(pages):
        for panel, _, _ in page.placed:
            last_of_kind[_kind(panel)] = k
    return all(k >= last_of_kind.get(panel.reads_after, -1) for k, page in enumerate(pages)
               for panel, _, _ in page.placed if panel.reads_after)


def _flowed(pages: list[Page], earliest: int, panel: Panel, sheet: str, form: str, turns: Sequence[bool]) -> int:
    """``panel``'s items (:attr:`Panel.runs`) placed in order as a draftsman fills sheets: on each sheet from
    ``earliest`` on, beside the drawings already there, as long a run as its room holds, the next run below it
    (narrower, beside the title block) or on the next sheet; the index of the last page taken."""
    assert panel.runs is not None
    start, at, previous = 0, earliest, ""
    while start < panel.run_count:
        for k in range(at, len(pages) + 1):
            if k == len(pages):
                first = panel.runs(start, start + 1)
                page = _empty_page(sheet, form, _turn_holding(first, sheet, form, turns))
            elif pages[k].label:
                continue
            else:
                page = pages[k]
            found = _longest_run(page, panel, start, previous)
            if found is not None:
                break
            if k == len(pages):
                raise _too_big(first, sheet, form, turns, panel.label)
        stop, page = found
        if k == len(pages):
            pages.append(page)
        else:
            pages[k] = page
        previous, start, at = page.placed[-1][0].name, stop, k
    return at


def _longest_run(page: Page, panel: Panel, start: int, previous: str) -> tuple[int, Page] | None:
    """Where the longest run of ``panel``'s items from ``start`` that ``page`` holds ends, going on from the run
    named ``previous``, and the page with it placed: ``page`` itself, or where only that makes room for the run,
    ``page`` laid out afresh (:func:`_rearranged`); None where not even one item fits either way."""
    assert panel.runs is not None
    # The longest run an empty sheet holds, counted up from one: a long sequence (48 plans) is not drawn whole to
    # find that a sheet holds ten.
    runs = {start + 1: panel.runs(start, start + 1)}
    longest = start + 1
    while longest < panel.run_count:
        runs[longest + 1] = panel.runs(start, longest + 1)
        if not page.fits_empty(runs[longest + 1]):
            break
        longest += 1
    for stop in range(longest, start, -1):
        ways = tuple(replace(way, in_rows=True, alternatives=(), continues=previous) for way in runs[stop].ways)
        run = replace(ways[0], alternatives=ways[1:])
        if page.place(run):
            return stop, page
        # The drawings already there set otherwise: an ESKD sheet's plan of positions put under графа 26 left a
        # run of the grid, its heading wider in Russian, no room under it or beside the title block, where beside
        # графа 26 it left a row of three plans under it.  Not the runs before it: set afresh they stood beside the
        # plan of positions, the next one under it, out of the order of the rows.  Nor a drawing moved off its
        # most compact spot: a shorter run goes on on the next sheet, and for a plan more the shaper's plan of
        # positions stood right of the grid on an A3, read after it.
        fresh = _rearranged(page, run, moves=0) if page.drawings and not any(
            _kind(drawing) == _kind(run) for drawing in page.drawings) else None
        if fresh is not None:
            return stop, fresh
    return None


def _headings_named(page: Page) -> None:
    """Each heading on ``page`` naming the scales of the drawings that stand under it there: its part's own and
    those of the parts that go on from it without their headings (:attr:`Panel.heading_scales`).

    A part is drawn with a heading that names the scales of every later
    part too, any of which may go on under it; where they went to other
    sheets, a group cut free alone under it named the μF of polygons and
    the μV of a lever on other sheets, two μF on one sheet with its own
    caption's.  Only the words change: every drawing stays where it was
    placed.
    """
    placed = {panel.name: panel for panel, _, _ in page.placed}

    def heading_over(panel: Panel) -> Panel:
        while _headless(panel) and panel.continues in placed:
            panel = placed[panel.continues]
        return panel

    under: dict[str, list[str]] = {}
    for panel, _, _ in page.placed:
        under.setdefault(heading_over(panel).name, []).extend(layer.name for layer in panel.layers)
    page.placed = [(_with_scales_of(panel, under[panel.name]) if panel.heading_scales and panel.name in under
                    else panel, rect, offset) for panel, rect, offset in page.placed]


def _with_scales_of(panel: Panel, names: Sequence[str]) -> Panel:
    """``panel`` with its heading's line of scales naming those the drawings (or layers) ``names`` are drawn at."""
    line = scales_line(panel.heading_scales, names, panel.heading_comma)
    return replace(panel, layers=tuple(with_scales_line(layer, line) if layer.name == HEADING_LAYER else layer
                                       for layer in panel.layers))


# The most arrangements of a page's drawings tried to make room for one more, fewest changed first: each
# drawing may stand in any of its ways (a plan sheet's three), 3^k arrangements for k drawings; 81 try every
# arrangement of four plan sheets.
_MOST_REARRANGEMENTS = 81
# Where a page's drawings laid out afresh leave no room for the last, the most times a drawing is moved to a later
# spot of the :data:`_SPOTS_TRIED` where it is most compact, for those after it to fit.
_MOST_MOVES = 4
_SPOTS_TRIED = 8


def _room_by_rearranging(pages: list[Page], earliest: int, panel: Panel, stop: int | None = None) -> int | None:
    """The first page from ``earliest`` on (before ``stop``) that holds ``panel`` once its drawings are laid out
    afresh, replaced in ``pages`` by its new layout; None when none does."""
    for k in range(earliest, len(pages) if stop is None else stop):
        fresh = None if pages[k].label else _rearranged(pages[k], panel)
        if fresh is not None:
            pages[k] = fresh
            return k
    return None


# Pages laid out afresh, by the page and the drawing added: each combination of the force sheets' ways is packed
# anew, and asks again for most of the layouts the one before it found (62 of 106 in the Stephenson six-bar's Russian
# A1, some 13 % of that run).  Drawings are known by their ids, which each entry keeps from being reused by holding
# the drawings themselves; the last few hundred are kept.
_LAID_OUT_AFRESH: RecentMemo[tuple[tuple[Panel, ...], Page | None]] = RecentMemo()
_MOST_LAYOUTS_KEPT = 256


def _rearranged(page: Page, panel: Panel, moves: int = _MOST_MOVES) -> Page | None:
    """:func:`_laid_out_afresh`, remembered: a page of its own each time, which the packing goes on filling."""
    key = (page.size, page.frame, page.block, page.area, page.growth, page.corner, page.tuck,
           tuple(map(id, page.drawings)), id(panel), moves)
    _, fresh = _LAID_OUT_AFRESH.get(key, lambda: ((*page.drawings, panel), _laid_out_afresh(page, panel, moves)),
                                    _MOST_LAYOUTS_KEPT)
    return None if fresh is None else replace(fresh, placed=list(fresh.placed), drawings=list(fresh.drawings))


def _laid_out_afresh(page: Page, panel: Panel, moves: int) -> Page | None:
    """``page`` laid out afresh with ``panel`` added, its drawings in other ways (a plan sheet with its
    mechanism above its plans, say) or grown otherwise (down a column where a block leaves no room beside the
    last drawing, say) where only that makes room, then with a drawing moved off the spot where it keeps them most
    compact, at most ``moves`` times in each arrangement (:meth:`Page.place_all`); None when nothing does.

    The arrangements that change fewest drawings are tried first, so that
    drawings keep the way they were placed in where that costs no sheet,
    and the page's own growth before the others.
    """
    drawings = [*page.drawings, panel]
    choices = [[replace(way, alternatives=()) for way in drawing.ways] for drawing in drawings]
    counts = [len(ways) for ways in choices]
    # With a corner box, the drawings also beside it as high as can be: under it, the first left a plan of
    # positions' height too little for the plan sheet under it.
    tucks = (page.tuck,) if page.corner is None else (page.tuck, not page.tuck)
    layouts = [(tuck, growth, picked) for tuck in tucks
               for growth in sorted(GROWTHS, key=lambda growth: growth != page.growth)
               # Every drawing in its first way was tried in the page's own growth as the page was filled.
               for picked in itertools.islice(
                   _arrangements(counts) if growth == page.growth and tuck == page.tuck else
                   itertools.chain([(0,) * len(counts)], _arrangements(counts)), _MOST_REARRANGEMENTS)]
    # Each drawing where it keeps them most compact; then, where that leaves no room for one, the one before it
    # elsewhere: a narrow part of a force sheet filled the gap right of the part before it, where the lever after
    # it stood only so, and the sheet took a sheet more for a drawing made smaller.  So in the page's own growth
    # only: in every growth, the slotted lever's run on A3 took 1.6 times as long for no sheet fewer.
    own = [layout for layout in layouts if layout[:2] == (page.tuck, page.growth)]
    for most, tried in [(0, layouts), *([(moves, own)] if moves else [])]:
        for tuck, growth, picked in tried:
            fresh = Page(page.size, page.frame, page.block, page.area, growth=growth, corner=page.corner, tuck=tuck)
            if fresh.place_all([ways[k] for ways, k in zip(choices, picked, strict=True)], most):
                fresh.drawings = drawings
                return fresh
    return None


def _arrangements(ways: Sequence[int]) -> Iterator[tuple[int, ...]]:
    """Which way each drawing stands in (an index below its count in ``ways``), one drawing changed from its
    first way, then two, and so on: the arrangement of all first ways, tried as the page was filled, is left out."""
    for changed in range(1, len(ways) + 1):
        for which in itertools.combinations(range(len(ways)), changed):
            for others in itertools.product(*(range(1, ways[k]) for k in which)):
                picked = [0] * len(ways)
                for k, way in zip(which, others, strict=True):
                    picked[k] = way
                yield tuple(picked)


def _kind(panel: Panel) -> str:
    """What ``panel`` draws, whichever position it is of: ``plan`` of ``plan-11``, ``forces`` of ``forces-5``
    and of its second part ``forces-5-2``."""
    return _kind_of(panel.name)


# Remembered: every spot a drawing is put at asks the kind of each drawing placed on the page.
@functools.lru_cache(maxsize=1024)
def _kind_of(name: str) -> str:
    # A force sheet with friction is read after the one without of its position, before the next position's.
    kind = re.sub(r"(?<=.)(-\d+)+$", "", name)
    return "forces" if kind == "forces-friction" else kind


def _turn_holding(panel: Panel, sheet: str, form: str, turns: Sequence[bool]) -> bool:
    """The first of ``turns`` whose empty sheet holds ``panel``; the first of all when none does."""
    return next((portrait for portrait in turns if _empty_page(sheet, form, portrait).fits_empty(panel)), turns[0])


def _parts_on(panel: Panel, sheet: str, form: str, turns: Sequence[bool]) -> list[Page]:
    """The parts of ``panel`` on pages of their own, arranged to need the fewest pages.

    Tried in turn: the parts as given, then each part that holds several
    drawings (a group and its polygon) cut into them, each in the given
    order and, unless the panel's parts are a sequence read in order
    (``in_order``), tallest, largest and widest first; of two arrangements on as many pages the first tried is
    kept, so that a drawing stays with its neighbours and in reading order
    where that costs no sheet; the pages are then put in the order of the
    first drawing each holds.
    """
    def held(part: Panel) -> bool:
        return any(_empty_page(sheet, form, portrait).fits_empty(part) for portrait in turns)

    if panel.in_order:
        # Of its ways, the one of fewest groups that a sheet holds each of (the grid of velocity plans in as many
        # columns as a sheet is wide): a group no sheet holds would stand apart drawing by drawing, out of order.
        whole = [way for way in panel.ways if way.parts and all(held(part) for part in way.parts)]
        if whole:
            panel = min(whole, key=lambda way: len(way.parts))
    # A part too big for a sheet stands apart in its own parts.
    grouped = [piece for part in panel.parts
               for piece in (part.parts if part.parts and not held(part) else (part,))]
    single = smallest_drawings(grouped)
    best: list[Page] | None = None
    best_parts: list[Panel] = grouped
    # A sequence read in order keeps its groups (the grid's rows): its drawings one by one, each where it fits
    # best, read 2, 7, 15, 34, 1, 10, … over the sheet.
    for parts in (grouped,) if panel.in_order else (grouped, single):
        orders = [parts]
        if not panel.in_order:
            orders += [sorted(parts, key=lambda part: -height(part)), sorted(parts, key=lambda part: -_area(part)),
                       sorted(parts, key=lambda part: -width(part))]
        for order in orders:
            pages: list[Page] = []
            for part in order:
                if pages and pages[-1].place(part):
                    continue
                if not held(part):
                    raise _too_big(part, sheet, form, turns, panel.label)
                pages.append(_empty_page(sheet, form, _turn_holding(part, sheet, form, turns)))
                pages[-1].place(part)
            if best is None or len(pages) < len(best):
                best, best_parts = pages, parts
    assert best is not None
    # Packed tallest or largest first, the pages still read in the drawings' order: the slotted lever's acceleration
    # plan of position 11, alone on an upright A3, came before the sheet of its mechanism and velocity plan.
    reading = {part.name: k for k, part in enumerate(best_parts)}
    best.sort(key=lambda page: min(reading[drawing.name] for drawing in page.drawings))
    if panel.heading:
        best = _headed(panel, best, sheet, form, turns) or best
    for page in best:
        page.label = panel.label or panel.name
    return best


# The most orders a page's drawings are tried in under a heading that takes the sheet's corner: every order of a plan
# sheet's three.
_MOST_HEADED_ORDERS = 6


def _headed(panel: Panel, pages: list[Page], sheet: str, form: str, turns: Sequence[bool]) -> list[Page] | None:
    """``pages`` of ``panel``'s parts laid out again under its heading (the sheets after the first under its
    continued heading, the first of its ways that the sheet holds), each page's drawings that much lower, on no
    more pages; a page whose drawings leave no room for a heading stays as it was, bare.  None where no page takes
    the heading.  All or none, the slider-crank's plan sheets on an A4 (the mechanism alone, then both plans, as
    tall as the sheet) stood bare, the first of them with half the sheet empty.  A second sheet is headed "continued"
    whether or not the first had room for the heading: a boxer twin's plans of position 3 on a Russian A4 began bare
    (its mechanism and velocity plan filling the sheet), and the sheet after it, headed with the plain title, read as
    where they began."""
    # As far over the drawings as the whole sets its heading over its fields.
    parts_top = bounds([layer for layer in panel.layers if layer not in panel.heading])[3]
    gap = bounds(panel.heading)[1] - parts_top
    headed: list[Page] = []
    any_headed = False
    for number, page in enumerate(pages):
        ways = panel.continued_heading if number and panel.continued_heading else (panel.heading,
                                                                                   *panel.broken_heading)
        # Lettering, at no length scale: a sheet of plans under it leaves its scale box empty.
        fresh = next((found for way in ways
                      for found in [_under_heading(Panel(f"{panel.name}-heading", way, to_scale=False), page, gap,
                                                   sheet, form)]
                      if found is not None), None)
        any_headed = any_headed or fresh is not None
        headed.append(page if fresh is None else fresh)
    return headed if any_headed else None


def _under_heading(heading: Panel, page: Page, gap: float, sheet: str, form: str) -> Page | None:
    """``page``'s drawings laid out afresh under ``heading``, ``gap`` mm under it; None where the sheet does
    not hold them so."""
    drawings = [drawing for drawing, _, _ in page.placed]
    fresh = _empty_page(sheet, form, _upright(page))
    # From the top of the area, or, where the heading runs into the corner box there and is too wide to stand right
    # of it, from under the box: the Russian slider-crank's plan headings on an upright ESKD A4.
    corner = _grown(fresh.corner, PADDING_MM) if fresh.corner is not None else None
    ceilings = [fresh.area[3], *([corner[1] - 1e-6] if corner is not None and corner[1] < fresh.area[3] else [])]
    for k, ceiling in enumerate(ceilings):
        # A page of its own each time: a page's copy shares the list of what is placed on it.
        lowered = replace(_empty_page(sheet, form, _upright(page)),
                          area=(*fresh.area[:3], ceiling - height(heading) - gap))
        if lowered.area[3] <= lowered.area[1] or not all(lowered.place(drawing) for drawing in drawings):
            # Lower down they fit no better.
            return _heading_cornered(heading, drawings, page, sheet, form) if k == 0 else None
        rects = [rect for _, rect, _ in lowered.placed]
        left, top = min(rect[0] for rect in rects), max(rect[3] for rect in rects)
        # Over the drawings' left edge, or right of a corner box it would run into.
        spots = [(x, top + gap, x + width(heading), top + gap + height(heading))
                 for x in (left, *([lowered.corner[2] + PADDING_MM] if lowered.corner else []))]
        rect = next((spot for spot in spots if spot[2] <= fresh.area[2] + 1e-6
                     and not any(overlap(spot, box) for box in lowered.obstacles())), None)
        if rect is not None:
            x0, y0, _, _ = heading.extent
            lowered.placed.append((heading, rect, (rect[0] - x0, rect[1] - y0)))
            lowered.area = fresh.area
            return lowered
    return None


def _heading_cornered(heading: Panel, drawings: Sequence[Panel], page: Page, sheet: str, form: str) -> Page | None:
    """A drawing as tall as the sheet: the heading takes its corner first, the drawings the room left, in the order
    they stood in or, where that leaves none, in another; else the first drawing first (a mechanism as tall as the
    sheet down its left side) and the heading at the top of the room it leaves, over the rest, where nothing stands
    higher than the heading: the scotch yoke's Russian plan sheet on A3 had none, room for it over its plans.  None
    where no order fits."""
    orders = list(itertools.islice(itertools.permutations(drawings), _MOST_HEADED_ORDERS))
    for order in orders:
        cornered = _empty_page(sheet, form, _upright(page))
        if cornered.place(heading) and all(cornered.place(drawing) for drawing in order):
            return cornered
    for first, *rest in orders if len(drawings) > 1 else ():
        beside = _empty_page(sheet, form, _upright(page))
        if not (beside.place(first) and beside.place(heading) and all(beside.place(drawing) for drawing in rest)):
            continue
        top = {panel.name: rect[3] for panel, rect, _ in beside.placed}
        if top[heading.name] >= max(top.values()) - 1e-6:
            return beside
    return None


def area_allows(panels: Sequence[Panel], count: int, sheet: str, form: str) -> bool:
    """Whether ``panels`` might stand on ``count`` sheets for all their area: False where even their least area
    exceeds the room of that many, so that no way of packing them does (never True because they fit).

    Each drawing is counted at its least area (its smallest way; a part
    that goes on from another without its heading; a drawing too big for a
    sheet in its smallest drawings) with half the gap kept round it, which
    no other's takes, against an empty sheet's area grown by as much, less
    its title block and corner box.  A packing costs a tenth of a second and
    more: the cuts of the force sheets that cannot save a sheet are not
    packed (:func:`graphplan.render.force_sheet_choice.fewest_sheets_cuts`).
    """
    check_sheet(sheet)
    room = max(_room_area(page_geometry(sheet, form, portrait)) for portrait in orientations(sheet))
    return sum(map(least_area, panels)) <= count * room + 1e-6


def _room_area(geometry: PageGeometry) -> float:
    """The area of an empty sheet a drawing grown by half the gap round it may take (:func:`area_allows`)."""
    ax0, ay0, ax1, ay1 = _grown(geometry.area, GAP_MM / 2)
    area = (ax1 - ax0) * (ay1 - ay0)
    for box in (geometry.block, geometry.corner):
        if box is not None:
            # The boxes themselves: a drawing keeps PADDING_MM off them, more than the half gap it is grown by.
            area -= max(0.0, min(ax1, box[2]) - max(ax0, box[0])) * max(0.0, min(ay1, box[3]) - max(ay0, box[1]))
    return area


def least_area(panel: Panel) -> float:
    """The least area ``panel`` takes on sheets, grown by half the gap round it (:func:`area_allows`)."""
    if panel.runs is not None:
        return 0.0  # taken run by run, each under a heading of its own: no less than nothing
    ways = [*panel.ways, *(panel.without_heading().ways if panel.continues else ())]
    if panel.parts:
        ways.append(None)

    def grown(way: Panel | None) -> float:
        if way is None:
            return sum(grown(part) for part in smallest_drawings(panel.parts))
        return (width(way) + GAP_MM) * (height(way) + GAP_MM)

    return min(map(grown, ways))


def width(panel: Panel) -> float:
    x0, _, x1, _ = panel.extent
    return x1 - x0


def height(panel: Panel) -> float:
    _, y0, _, y1 = panel.extent
    return y1 - y0


def _area(panel: Panel) -> float:
    return width(panel) * height(panel)


def _centre(page: Page) -> None:
    """Move the drawings of a page together towards the middle of its area, as far as the title block (and the
    corner box) lets them."""
    rects = [rect for _, rect, _ in page.placed]
    ux0, uy0 = min(r[0] for r in rects), min(r[1] for r in rects)
    ux1, uy1 = max(r[2] for r in rects), max(r[3] for r in rects)
    ax0, ay0, ax1, ay1 = page.area
    towards = ((ax0 + ax1 - ux0 - ux1) / 2, (ay0 + ay1 - uy0 - uy1) / 2)
    boxes = page.obstacles()
    steps = 20
    for k in range(steps, 0, -1):
        dx, dy = towards[0] * k / steps, towards[1] * k / steps
        if not any(overlap((r[0] + dx, r[1] + dy, r[2] + dx, r[3] + dy), box) for r in rects for box in boxes):
            page.placed = [(panel, (r[0] + dx, r[1] + dy, r[2] + dx, r[3] + dy), (ox + dx, oy + dy))
                           for panel, r, (ox, oy) in page.placed]
            return


def _too_big(panel: Panel, sheet: str, form: str, turns: Sequence[bool], whose: str = "") -> SceneError:
    """The error for a drawing no empty sheet holds (one whose scale the scene sets is refused before the
    packing, by :mod:`graphplan.render.sheet`, with the value that fits)."""
    x0, y0, x1, y1 = panel.extent
    if whose and panel.label not in ("", whose):
        what = panel.label  # a part that names itself: a balancing plane's polygon
    else:
        what = f"{whose}: {panel.name}" if whose else (panel.label or panel.name)
    bigger = bigger_holding(sheet, form, [panel])
    # The largest format graphplan draws is told alone: "choose A1 or a bigger sheet" offered sheets it has not.
    ways = [f"choose {bigger}{' or a bigger sheet' if bigger in BIGGER else ''}"] if bigger else []
    # Only a drawing at μl shrinks with a larger μl: the dynamics and the diagrams are at scales the program fits.
    ways += ["a larger μl (drawing.length_scale)"] if not bigger and panel.to_scale else []
    ways.append('sheet = "none"')
    return SceneError("drawing.sheet",
                      f"the drawing {what!r} ({x1 - x0:.0f} × {y1 - y0:.0f} mm at its scales) does not fit on {sheet} "
                      f"({rooms(sheet, form, turns)}); {', or '.join(ways)}", sheet)


def rooms(sheet: str, form: str, turns: Sequence[bool]) -> str:
    """The rooms an empty ``sheet`` has clear of its title block, in words: those a drawing could stand in (an
    upright A4's strip between ESKD's графа 26 and the title block, 1 mm wide, is none)."""
    rooms = dict.fromkeys(f"{width:.0f} × {height:.0f}" for portrait in turns
                          for width, height in page_geometry(sheet, form, portrait).rooms()
                          if min(width, height) >= _LEAST_ROOM_MM)
    return f"an empty one has room for {' or '.join(rooms)} mm clear of its title block"


def bigger_holding(sheet: str, form: str, panels: Sequence[Panel]) -> str | None:
    """The smallest format bigger than ``sheet`` whose empty sheet holds each of ``panels``, if any."""
    bigger = BIGGER.get(sheet)
    while bigger is not None and not all(holds(bigger, form, width(panel), height(panel)) for panel in panels):
        bigger = BIGGER.get(bigger)
    return bigger
