"""Which way each force sheet stands on the course sheets: whole or cut into parts, its rows apart, drawn larger where
the sheets have room, on the fewest sheets, with the drawings read after the force sheets (the load diagrams) after
them all where as few sheets allow it.

:mod:`graphplan.render.sheet` lays each force sheet out in its ways (:data:`ForceSheetWays`) and hands them here;
what comes back is the panels it packs.  Every choice is judged by packing it
(:func:`graphplan.render.packing.pack`): the sheets it takes, the order it keeps.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterator, Sequence

from ..errors import SceneError
from .packing import Page, Panel, area_allows, least_area, pack, reads_in_order

# A force sheet whole, the ways it may stand on sheets, its rows apart (:func:`~graphplan.render.sheet._rows_apart`:
# none where that is no other way), and the same sheet drawn larger by given standard steps of μl and μF (made when
# first asked for, None where no empty sheet holds it so: :func:`larger_where_room` asks).
ForceSheetWays = tuple[Panel, list[list[Panel]], list[Panel], Callable[[tuple[int, int]], Panel | None]]


# The standard steps finer the groups cut free (μl) and their polygons (μF) a sheet with room for them may draw them
# at, largest first: a student's A1 draws them about twice the mechanism's μl (0.004 → 0.002 m/mm, 5 → 2 N/mm).
LARGER_FORCE_STEPS = ((3, 3), (3, 2), (2, 3), (2, 2), (2, 1), (1, 2), (1, 1), (1, 0), (0, 1))
# The way tried first (:func:`first_fitting`).  Each way is a force sheet laid out afresh, its labels placed: trying
# all nine, largest first, made a run's sheets a third slower.
PROBE_STEPS = (1, 1)
# The most combinations of the force sheets' ways packed each in turn where the greedy choice may have missed a
# saving (:meth:`CutChoice._combined`), each a packing of some 30 to 110 ms: the engine's 16 on its A2 save a sheet,
# the Stephenson six-bar's 25 an A1 sheet in Russian (3 → 2), for 2.5 s of processor time more (2.3 s → 4.8 s): a
# course project's sheet is worth the seconds.  At 16, that was the one run of 171 whose force sheets some
# combination packed on fewer sheets than the run (bench/results/sheet_cuts.md).
MOST_COMBINATIONS = 25


def fewest_sheets_cuts(cuts: Sequence[Sequence[Sequence[Panel]]], after: Sequence[Panel], sheet: str,
                       form: str, rows_apart: Sequence[Sequence[Panel]] = ()) -> list[Panel]:
    """The force sheets' parts, each sheet cut the way of its ``cuts`` (:meth:`~graphplan.render.force_rows.Rows.cuts`,
    least paper first) or its rows apart (``rows_apart``, each sheet's: :func:`~graphplan.render.sheet._rows_apart`)
    that packs them, with the drawings ``after`` them, on the fewest ``sheet`` s: each in turn takes the first of its
    ways that saves a sheet on those chosen so far, and last the rows of several sheets apart at once where that saves
    one.  Where a drawing ``after`` them that is read after the force sheets (the load diagrams) then stands before
    one of them, the first other way (:meth:`CutChoice.in_order`) that packs as few sheets with it after all of them.

    The least paper of a sheet's parts alone does not tell: the engine's
    force sheet of position 2 in Russian took a part with group I and the
    lever 351 mm wide, which left no room beside it on its A2 for the sheet
    of position 8, and the force sheets took four A2 where the cut with the
    lever on a part of its own packs them on three.  One pack per cut tried,
    a sheet after another, not one per combination of cuts, and none for a
    cut whose drawings' area leaves no room for a sheet fewer
    (:func:`~graphplan.render.packing.area_allows`).
    """
    choice = CutChoice(cuts, after, sheet, form, rows_apart)
    picked = choice.fewest()
    if not choice.reads_in_order(picked):
        picked = next(choice.in_order(picked), picked)
    return choice.parts_of(picked)


class CutChoice:
    """The ways each force sheet may stand on ``sheet`` s (its ``cuts``, then its rows apart), the drawings ``after``
    them, and the sheets each choice of ways packs them on (each choice packed once)."""

    def __init__(self, cuts: Sequence[Sequence[Sequence[Panel]]], after: Sequence[Panel], sheet: str, form: str,
                 rows_apart: Sequence[Sequence[Panel]] = ()) -> None:
        self.cuts, self.after, self.sheet, self.form = cuts, after, sheet, form
        self.ways_of = [[*ways, *([apart] if apart else [])]
                        for ways, apart in itertools.zip_longest(cuts, rows_apart, fillvalue=())]
        # Each sheet's rows apart, by its index among its ways: None where it has none.
        self.apart_at = [len(ways) - 1 if len(ways) > len(own) else None
                         for ways, own in zip(self.ways_of, cuts, strict=True)]
        self._packed: dict[tuple[int, ...], list[Page] | None] = {}

    def parts_of(self, picks: Sequence[int]) -> list[Panel]:
        return [part for ways, way in zip(self.ways_of, picks, strict=True) for part in ways[way]]

    def pages(self, picks: Sequence[int], fewer_than: float = math.inf) -> list[Page] | None:
        """The sheets the ways ``picks`` take, with the drawings after them; None where no sheet holds a drawing,
        or, not packed, where their area alone leaves no room for fewer than ``fewer_than`` sheets
        (:func:`~graphplan.render.packing.area_allows`)."""
        key = tuple(picks)
        if key in self._packed:
            return self._packed[key]
        drawings = [*self.parts_of(picks), *self.after]
        if fewer_than < math.inf and not area_allows(drawings, int(fewer_than) - 1, self.sheet, self.form):
            return None
        try:
            found = pack(drawings, self.sheet, self.form)
        except SceneError:  # packed with the cut least paper first, the run says why no sheet holds a drawing
            found = None
        self._packed[key] = found
        return found

    def sheets_taken(self, picks: Sequence[int], fewer_than: float = math.inf) -> float:
        """How many sheets :meth:`pages` takes; infinite where it gives none."""
        found = self.pages(picks, fewer_than)
        return math.inf if found is None else len(found)

    def reads_in_order(self, picks: Sequence[int]) -> bool:
        """Whether the drawings after the force sheets that are read after them stand after them all, as ``picks``
        packs them (:func:`~graphplan.render.packing.reads_in_order`); true where nothing is read after them."""
        if not any(panel.reads_after for panel in self.after) or self.sheet == "none":
            return True
        found = self.pages(picks)
        return found is None or reads_in_order(found)

    def fewest(self, combined: bool = False) -> list[int]:
        """The way of each sheet, by its index among its ways, that the greedy choice takes: the fewest sheets; with
        ``combined``, every combination of few ways searched after it too (:meth:`_combined`), for the sheets a run
        draws, not for the counts that choose a scale."""
        picked = [0] * len(self.cuts)  # the way each sheet takes, by its index among its ways
        if self.sheet == "none" or all(len(ways) == 1 for ways in self.ways_of):
            return picked
        fewest = self.sheets_taken(picked)

        def saving(k: int, way: int) -> None:
            nonlocal picked, fewest
            tried = [*picked[:k], way, *picked[k + 1:]]
            taken = self.sheets_taken(tried, fewest)
            if taken < fewest:
                picked, fewest = tried, taken

        # The cuts into more parts than a sheet's first only once every sheet has tried its others, so that they
        # are taken only where nothing else saves the sheet: tried in turn with the others, the Stephenson six-bar's
        # sheet of position 3 stood in seven parts on an A1 where its second cut and position 9's take as few.  Its
        # rows apart first, the last sheet's first: the rows of the sheet next to the load diagrams after them leave
        # those their place after the force sheets, where an earlier sheet's took room before the later ones.  Every
        # drawing apart (a group away from its polygon) last: the offset slider-crank's driving link stood in the
        # middle of its A1, its polygon under another group's, where its rows apart save the sheet too.
        for k, way in self._preferred(fewer_parts=True):
            saving(k, way)
        for k in reversed(range(len(self.cuts))):
            if self.apart_at[k] is not None:
                saving(k, self.apart_at[k])
        for k, way in self._preferred(fewer_parts=False):
            saving(k, way)
        # Where no sheet's rows apart save one alone, several may together: the Stephenson six-bar's force sheets on
        # A1 each left room on the other's sheets that only their rows apart could take, on three sheets with either
        # apart and on two with both.  Every sheet's rows apart at once, then each sheet put back as it was, the
        # first first, where the set keeps its count without it, so that only the sheets the saving needs stand
        # apart, the later ones (as the rows apart of one sheet are tried) where either would do.
        together = [way if at is None else at for way, at in zip(picked, self.apart_at, strict=True)]
        changed = [k for k, way in enumerate(together) if way != picked[k]]
        if len(changed) > 1:
            taken = self.sheets_taken(together, fewest)
            if taken < fewest:
                for k in changed:
                    tried = [*together[:k], picked[k], *together[k + 1:]]
                    if self.sheets_taken(tried, taken + 1) <= taken:
                        together = tried
                picked, fewest = together, taken
        return self._combined(picked, fewest) if combined else picked

    def _combined(self, picked: list[int], fewest: float) -> list[int]:
        """``picked``, or where the sheets' ways are few enough to pack every combination of them
        (:data:`MOST_COMBINATIONS`), the one that packs on the fewest sheets, fewer than ``picked``'s ``fewest``: of
        those as few, the one with fewest sheets standing every drawing apart, then the ways :meth:`fewest` prefers.

        A way changed one sheet at a time saves nothing where only two
        changed together do: the engine's force sheets on its own A2 stood
        on three sheets where a cut of each together puts them on two, the
        triad with a slider's and the double rocker's likewise on A3
        (bench/results/sheet_cuts.md: the greedy choice alone takes a sheet
        more than every combination of the ways in nine runs of 171).
        """
        varied = [k for k, ways in enumerate(self.ways_of) if len(ways) > 1]
        if math.prod(len(self.ways_of[k]) for k in varied) > MOST_COMBINATIONS:
            return picked
        # The fewest sheets any combination might take for its area, each sheet's way of least area counted: none is
        # packed where that is no fewer than the choice's, and the search ends at a combination that takes it.
        smallest = [part for ways in self.ways_of for part in min(ways, key=lambda way: sum(map(least_area, way)))]
        bound = next(count for count in itertools.count(1)
                     if area_allows([*smallest, *self.after], count, self.sheet, self.form))
        best: tuple[tuple[float, int], list[int]] | None = None
        if bound >= fewest:
            return picked
        for combination in itertools.product(*(self._ranked(k) for k in varied)):
            tried = list(picked)
            for k, way in zip(varied, combination, strict=True):
                tried[k] = way
            # Packed only where the drawings' area leaves room for as few sheets as the best so far.
            taken = self.sheets_taken(tried, fewest if best is None else best[0][0] + 1)
            if taken < fewest and (best is None or (taken, self.drawings_apart(tried)) < best[0]):
                best = ((taken, self.drawings_apart(tried)), tried)
                if taken <= bound and not best[0][1]:
                    break
        return picked if best is None else best[1]

    def _preferred(self, fewer_parts: bool) -> Iterator[tuple[int, int]]:
        """Each sheet's cuts after its first (sheet, way), those into no more parts than its first, or those into
        more (every drawing apart: a group away from its polygon)."""
        for k, ways in enumerate(self.cuts):
            for way in range(1, len(ways)):
                if (len(ways[way]) <= len(ways[0])) == fewer_parts:
                    yield k, way

    def _ranked(self, k: int, apart: bool = True) -> list[int]:
        """Sheet ``k``'s ways as :meth:`fewest` prefers them: its cuts into no more parts than its first (the first
        first), its rows apart, and (with ``apart``) its cuts into more, every drawing apart."""
        ways = self.cuts[k]
        fewer = [way for way in range(len(ways)) if len(ways[way]) <= len(ways[0])]
        more = [way for way in range(1, len(ways)) if len(ways[way]) > len(ways[0])] if apart else []
        rows = [] if self.apart_at[k] is None else [self.apart_at[k]]
        return [*fewer, *rows, *more]

    def drawings_apart(self, picks: Sequence[int]) -> int:
        """How many force sheets ``picks`` stands with every drawing apart (a group away from its polygon)."""
        return sum(way < len(self.cuts[k]) and len(self.cuts[k][way]) > len(self.cuts[k][0])
                   for k, way in enumerate(picks))

    def in_order(self, picked: Sequence[int]) -> Iterator[list[int]]:
        """Other ways than ``picked`` that pack on as few sheets with the drawings read after the force sheets (the
        load diagrams) after them all, and stand no more force sheets with every drawing apart: one sheet's way
        changed, the last sheet's first (the sheets next to the load diagrams leave them their room after the force
        sheets), each sheet's ways as :meth:`fewest` prefers them; then each other sheet standing otherwise than its
        first way given the first of its ways, drawings apart left out, that keeps the count and the order.

        The scotch yoke's load diagrams stood on its A2 of position 4's
        force sheet, its drawings apart, before position 9's, its rows
        apart, on the last A2: with position 4's rows apart and position 9's
        drawings apart, they stand after both on as many sheets.  The
        offset slider-crank's, beside position 3's rows apart, stand there
        still: after position 10's they would stand only beside its drawings
        apart, its driving link's polygon under its other group's, which
        takes a sheet with its drawings apart that the count does not need.
        One sheet's way changed at a time, and each other sheet's once: each
        way tried is a packing.
        """
        count = self.sheets_taken(picked)
        if count == math.inf:
            return
        most_apart = self.drawings_apart(picked)

        def kept(tried: Sequence[int]) -> bool:
            return self.sheets_taken(tried, count + 1) <= count and self.reads_in_order(tried)

        seen: set[tuple[int, ...]] = set()
        for k in reversed(range(len(self.ways_of))):
            for way in self._ranked(k):
                tried = [*picked[:k], way, *picked[k + 1:]]
                if way == picked[k] or not kept(tried):
                    continue
                for other in range(len(tried)):
                    if other == k or tried[other] == 0:
                        continue
                    tried = next((back for back in ([*tried[:other], own, *tried[other + 1:]]
                                                    for own in self._ranked(other, apart=False)
                                                    if own != tried[other]) if kept(back)), tried)
                if self.drawings_apart(tried) <= most_apart and tuple(tried) not in seen:
                    seen.add(tuple(tried))
                    yield tried


def larger_ways(forces: Sequence[ForceSheetWays], parts: Sequence[Panel]
                 ) -> list[Callable[[tuple[int, int]], Panel | None]]:
    """The larger ways of each force sheet that stands whole among ``parts``: one cut into its rows apart saved a
    sheet."""
    cut_up = {part.continues for part in parts}
    return [ways for whole, _, _, ways in forces if whole.name not in cut_up]


def larger_where_room(parts: Sequence[Panel], after: Sequence[Panel],
                       larger: Sequence[Callable[[tuple[int, int]], Panel | None]],
                       sheet: str, form: str, packed: list[Page] | None = None, keep_order: bool = False
                       ) -> tuple[list[Panel], list[Page] | None]:
    """``parts``, each force sheet that stands whole among them drawn larger (its groups cut free at a finer μl,
    its polygons at a finer μF) where the sheets hold it so: of its ``larger`` ways, the first of
    :data:`LARGER_FORCE_STEPS` (:func:`first_fitting`) that packs with the drawings ``after`` them on no more
    sheets, keeps the drawings in order (with ``keep_order``, those read after the force sheets after them too:
    :func:`~graphplan.render.packing.reads_in_order`), and puts no two μl on one sheet, whose title block gives one
    scale; with the sheets they pack on (``packed``, where given, those of ``parts``), None where none holds them.  A
    force sheet with room to spare on its A1 drew its groups and polygons a third of the way across it, as small as
    the mechanism's own μl and the polygons' 150 mm fields make them."""
    chosen = list(parts)

    def packing(tried: Sequence[Panel]) -> list[Page] | None:
        try:
            return pack([*tried, *after], sheet, form)
        except SceneError:
            return None

    pages = packed if packed is not None else packing(chosen)
    if pages is None or not LARGER_FORCE_STEPS:
        return chosen, pages
    count = len(pages)
    # The sheets of the last way taken: the way :func:`first_fitting` gives.
    taken_pages: list[list[Page]] = []
    for way_at in larger:
        def taken(steps: tuple[int, int], way_at=way_at, current=chosen) -> list[Panel] | None:
            way = way_at(steps)
            at = None if way is None else next((k for k, part in enumerate(current) if part.name == way.name), None)
            if at is None:
                return None
            tried = [*current[:at], way, *current[at + 1:]]
            found = packing(tried)
            fitting = found is not None and len(found) <= count and \
                _in_order(found, [part.name for part in tried]) and all(_one_length_scale(page) for page in found) \
                and (not keep_order or reads_in_order(found))
            if fitting:
                taken_pages.append(found)
            return tried if fitting else None

        taken_pages.clear()
        larger_way = first_fitting(LARGER_FORCE_STEPS, taken)
        if larger_way is not None:
            chosen, pages = larger_way, taken_pages[-1]
    return chosen, pages


def read_after_forces(choice: CutChoice, picked: Sequence[int], parts: Sequence[Panel], count: int,
                       forces: Sequence[ForceSheetWays], scale: float) -> list[Panel]:
    """``parts`` (the force sheets cut as ``picked``, drawn larger where room, on ``count`` sheets, a drawing read
    after them standing before one), or the first of their other ways (the same cut drawn larger no further than
    keeps the order, then :meth:`CutChoice.in_order`) that packs on as few sheets with every drawing read after the
    force sheets after them all, and draws no group cut free, no polygon and no arrow smaller than ``parts`` do
    (:func:`_drawn_no_smaller`): the order is not bought with a sheet, nor with a smaller drawing."""
    for tried in itertools.chain((list(picked),), choice.in_order(picked)):
        if not choice.reads_in_order(tried):
            continue
        cut = choice.parts_of(tried)
        drawn, pages = larger_where_room(cut, choice.after, larger_ways(forces, cut), choice.sheet, choice.form,
                                          packed=choice.pages(tried), keep_order=True)
        if pages is not None and len(pages) <= count and reads_in_order(pages) and \
                _drawn_no_smaller(drawn, parts, scale):
            return drawn
    return list(parts)


def _drawn_no_smaller(drawn: Sequence[Panel], before: Sequence[Panel], scale: float) -> bool:
    """Whether ``drawn`` draws every force sheet that ``before`` draws larger than its record at least as large: its
    groups cut free at no coarser μl (``scale``, the analysis's, where a panel gives none), each polygon at no coarser
    μF, each group's arrows likewise."""
    by_name = {panel.name: panel for panel in drawn}
    for old in before:
        if not (old.polygon_scales or old.body_arrows):
            continue
        new = by_name.get(old.name)
        if new is None or (new.length_scale or scale) > (old.length_scale or scale) + 1e-12:
            return False
        polygons, arrows = dict(new.polygon_scales), {label: at for label, at, _ in new.body_arrows}
        if any(polygons.get(label, math.inf) > at + 1e-12 for label, at in old.polygon_scales) or \
                any(arrows.get(label, math.inf) > at + 1e-12 for label, at, _ in old.body_arrows):
            return False
    return True


def first_fitting(ways: Sequence[tuple[int, int]], taken: Callable[[tuple[int, int]], list[Panel] | None]
                   ) -> list[Panel] | None:
    """What ``taken`` gives for the first of ``ways`` (the preferred first) that it takes, None where it takes none.

    Tried from :data:`PROBE_STEPS`, then the way in the middle of those
    left: a way not taken is taken to mean that no way at least as many
    steps larger in both does either (a larger drawing needs more room), and
    one taken leaves only the ways before it.  Where only the probe packs,
    four ways are laid out of the nine, not seven.
    """
    left = list(ways)
    found = None
    way = PROBE_STEPS if PROBE_STEPS in left else left[len(left) // 2]
    while left:
        tried = taken(way)
        if tried is not None:
            found, left = tried, left[:left.index(way)]
        else:
            left = [other for other in left if not (other[0] >= way[0] and other[1] >= way[1])]
        way = left[len(left) // 2] if left else None
    return found


def _in_order(pages: Sequence[Page], names: Sequence[str]) -> bool:
    """Whether the drawings ``names`` stand on ``pages`` in their order: a force sheet drawn larger that moves on to
    a later sheet leaves its sheet with friction on the sheet before it."""
    page_of = {panel.name: k for k, page in enumerate(pages) for panel, _, _ in page.placed}
    standing = [page_of[name] for name in names if name in page_of]
    return standing == sorted(standing)


def _one_length_scale(page: Page) -> bool:
    """Whether the drawings to scale on ``page`` share one μl (those of no μl of their own at the analysis's)."""
    return len({panel.length_scale for panel, _, _ in page.placed if panel.to_scale}) <= 1


def loads_saving_a_sheet(parts: Sequence[Panel], loads: Sequence[Panel],
                          smaller: Callable[[], Iterator[Sequence[Panel]]], sheet: str, form: str) -> Sequence[Panel]:
    """``loads``, or the first of ``smaller`` that stands in the room the force sheets leave where ``loads`` would
    take a sheet of their own: a knee press's load diagram, 199 by 156 mm, took a fifth A1 alone beside four force
    sheets whose room holds it at 120 by 45 mm."""
    count = len(pack([*parts, *loads], sheet, form))
    if count <= len(pack(parts, sheet, form)):
        return loads
    for drawn in smaller():
        try:
            if len(pack([*parts, *drawn], sheet, form)) < count:
                return drawn
        except SceneError:  # a size no sheet holds saves none
            continue
    return loads
