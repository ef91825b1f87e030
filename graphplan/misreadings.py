"""Hand readings (``[measured.N]``) far off the plan as constructed: a length misread, a segment taken for
another, a whole plan or force polygon drawn at another scale than the scene's, or an acceleration plan built with
its Coriolis parts laid off the wrong way.

A plan drawn with care keeps within a few per cent of the construction, and
a short segment within the drafting precision of its two ends; a reading
beyond both is a slip.  Where every reading of one drawing implies the same
scale (μV, μa; μF of a polygon, or of all of them), the slip is the drawing's
scale, not its lengths: the student laid off the driver's velocity (or
acceleration) at another pole distance, or drew the polygons at a μF of
their own (even where no reading is far off, every one in one ratio off 1 beyond the
drafting precision), and the warning gives the scene's key that sets that scale, at
the round value near it, with how close the readings come there.
"""

from __future__ import annotations

import itertools
import math
import statistics
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import TYPE_CHECKING

from .check import ErrorRow, exact_values_at, is_balancing, is_reaction, quantity_symbol, segment_millimetres
from .geometry import ParallelLinesError
from .locale import strings
from .motion import Motion, PositionWarning
from .plans import Plan, acceleration_plan
from .scales import nearest_standard_scale

if TYPE_CHECKING:
    from .analysis import VelocityPosition
    from .mechanism import Mechanism
    from .scene import Drawing

# Every reading of a plan in one ratio to the construction, to within the drafting precision, and the ratio off 1 by
# more than this (per cent): a plan laid off at another pole, though no reading is far off.
UNIFORM_SLIP_PERCENT = 5.0
# A hand reading this far (per cent) from the same quantity of the plan as constructed is a misread length or
# a segment taken for another, not a drawing's error ...
FAR_OFF_PERCENT = 15.0
# ... and this many drafting precisions off in millimetres, a short segment's reading being as good as its two ends.
FAR_OFF_PRECISIONS = 2.0
# A far-off reading within this share of the value it stands for (m/s, m/s², N) is that value typed: a student's
# own plan gives it to a few per cent.
VALUE_TYPED_SHARE = 0.05

_SCALES = {"velocity": ("μV", "(m/s)/mm"), "acceleration": ("μa", "(m/s²)/mm")}


@dataclass(frozen=True)
class Rescaled:
    """Every reading of one drawing in one ratio to its construction: the drawing laid off at another scale.

    ``kind`` is the plan read (``velocity``, ``acceleration``) or ``forces``; ``polygon`` the label of the one
    force polygon so read (None: a plan, or readings of several polygons); ``read_at`` each polygon's μF (by
    label) or the plan's scale (under its kind) the readings were read at; ``drawn_at`` the scale they agree
    best at (the median of the scales each implies).  ``key`` is the scene's key that sets that scale
    (``drawing.velocity_pole``, ``drawing.force_scale``), ``setting`` its value as the readings give it and
    ``rounded`` the round value near it a student would have drawn at; ``off`` the largest share by which a
    reading taken at ``rounded`` is off the construction: how close "agree" is.
    """

    kind: str
    polygon: str | None
    read_at: Mapping[str, float]
    drawn_at: float
    key: str
    setting: float
    rounded: float
    off: float
    # A plan's readings that agree at one unit a millimetre may be the values typed, or a plan truly drawn at
    # μ = 1: the scene's setting that draws it so (```[drawing] acceleration_scale = 1```), and the pole key it
    # stands in place of (a scene gives a plan's pole or its scale, not both), if any.
    unit_setting: str = ""
    replaces: str | None = None
    # The one reading (as the scene writes it) the others agree without: misread besides, as one of four or more.
    but: tuple[str, ...] = ()

    @property
    def ratio(self) -> float:
        """The readings over the construction, where every reading was read at one scale (else NaN)."""
        scales = set(self.read_at.values())
        return next(iter(scales)) / self.drawn_at if len(scales) == 1 else math.nan


@dataclass(frozen=True)
class Slips:
    """A position's hand readings far off its construction.

    ``rescaled``: each drawing (a plan, the force polygons, one polygon) whose readings stand in one ratio to
    the construction, drawn at another scale.  ``misread``: by the reading as the scene writes it
    (``pb = 25.9 mm``), the error rows it gives far off, each with the constructed value.
    """

    rescaled: tuple[Rescaled, ...]
    misread: Mapping[str, tuple[tuple[ErrorRow, float], ...]]
    # Far-off readings that are, to the drafting precision, other segments of the plans as constructed: by the reading
    # as the scene writes it, each segment it matches as (plan, segment, its length in mm), nearest first.  Those are
    # not in ``misread``.
    named: Mapping[str, tuple[Segment, ...]] = field(default_factory=lambda: MappingProxyType({}))
    # By the plan a table of readings was given for (``acceleration``), the other plan (``velocity``) whose segments of
    # the same names every one of them is, to the drafting precision: that plan's readings typed under the wrong table.
    other_plan: Mapping[str, tuple[str, tuple[str, ...]]] = field(default_factory=lambda: MappingProxyType({}))
    # Far-off readings a thousandth of their lengths as constructed, each with both lengths in mm: lengths typed in
    # metres (one alone, or readings of polygons each at its own μF, which no one scale joins).  Not in ``misread``.
    metres: Mapping[str, tuple[float, float]] = field(default_factory=lambda: MappingProxyType({}))
    # The same, a tenth of their lengths: lengths typed in centimetres.  Not in ``misread``.
    centimetres: Mapping[str, tuple[float, float]] = field(default_factory=lambda: MappingProxyType({}))
    # Far-off readings of a reaction that are, to the drafting precision, its length at another standard μF than its
    # polygon's: by the reading, (that μF, the length there in mm).  Not in ``misread``.
    force_scale: Mapping[str, tuple[float, float]] = field(default_factory=lambda: MappingProxyType({}))
    # Far-off readings that are the value they stand for (VE = 1.147 m/s typed as pe = 1.147), by the reading: the
    # quantity (a velocity, an acceleration, a reaction), the value typed and its length as constructed in mm.  Not
    # in ``misread``.
    values: Mapping[str, tuple[str, float, float]] = field(default_factory=lambda: MappingProxyType({}))
    # Reactions read off the course sheet, which draws the position's polygons larger than the record where it has
    # room: not in ``rescaled`` nor ``misread``.
    on_sheet: OnSheet | None = None
    # The readings of the acceleration plan, as the scene writes them, where every one fits the plan with its Coriolis
    # parts laid off the other way (:func:`coriolis_reversed`), and the Coriolis parts as the plan names them (aA4A3ᵏ).
    # Not in ``misread`` nor ``rescaled``.
    coriolis_reversed: tuple[str, ...] = ()
    coriolis_parts: tuple[str, ...] = ()


@dataclass(frozen=True)
class SheetPolygons:
    """A position's force sheet as a course sheet draws it, larger than the record (``forces_N.svg``, results.json's
    ``polygon_scales``) where the sheet has room: the sheet's number; by each group's label the μF there of each
    polygon drawn at another than the record's; whether it is the force sheet with friction
    (``forces_friction_N.svg``), whose reactions a hand that measured it read; and by each group's label the μF its
    group cut free draws its arrows at there, with the reactions drawn whole at their length: a hand reading a
    reaction off an arrow reads it as off its polygon, at another μF.  ``sheet`` None is the record itself
    (:func:`~graphplan.deliverables._record_drawings`): its groups cut free in ``forces_N.svg``, no polygon of its
    own drawn larger, its arrows at theirs; or, with ``friction``, its polygons with friction in
    ``forces_friction_N.svg``, at their μF, the record's own as a rule, and that sheet's groups cut free's arrows at
    theirs."""

    sheet: int | None
    scales: Mapping[str, float]
    friction: bool = False
    arrows: Mapping[str, tuple[float, tuple[str, ...]]] = field(default_factory=lambda: MappingProxyType({}))

    def drawings(self) -> Iterator[tuple[str, Mapping[str, float], Mapping[str, tuple[str, ...]] | None]]:
        """Each drawing of the sheet a reading may be measured on: its kind (``polygons``, ``arrows``), by group label
        its μF, and by the same the reactions it draws whole at their length (None: every reaction its polygon
        draws)."""
        yield "polygons", self.scales, None
        yield ("arrows", {label: scale for label, (scale, _) in self.arrows.items()},
               {label: whole for label, (_, whole) in self.arrows.items()})


# By position number, its force sheets drawn larger on the course sheets (without friction, with friction, or both).
SheetsDrawn = Mapping[int, tuple[SheetPolygons, ...]]


@dataclass(frozen=True)
class OnSheet:
    """Force readings that fit a drawing of the course sheet ``sheet`` rather than the record's polygons they are
    checked against: by polygon label, (its μF on the sheet, its μF in the record); ``every`` whether they are the
    readings of every polygon read; ``off`` the largest share by which a reading taken at the sheet's μF is off the
    construction.  ``drawing`` is what of the sheet they fit (``polygons``, or ``arrows``: the groups cut free),
    ``friction`` whether of the force sheet with friction, ``readings`` the readings that fit it.  ``sheet`` None:
    the record's own arrows, in ``forces_N.svg``, or with ``friction`` its polygons or arrows in
    ``forces_friction_N.svg``."""

    sheet: int | None
    polygons: Mapping[str, tuple[float, float]]
    every: bool
    off: float
    drawing: str = "polygons"
    friction: bool = False
    readings: frozenset[str] = frozenset()
    # Where a polygon's readings fit a drawing with friction only in part, the others the polygon without friction
    # they are checked against (one reaction measured on the wrong drawing): every reading that fits it, in the scene's
    # order, each named, as "every reading of the polygon" is not.  Empty where whole polygons fit.
    named: tuple[str, ...] = ()

    def scales(self, which: int, mark: str = ".") -> str:
        """The sheet's μF (``which`` 0) or the record's (1): ``4``, or ``II(3,4) 4, I(1,2) 10`` where they differ."""
        values = {label: scales[which] for label, scales in self.polygons.items()}
        if len(set(values.values())) == 1:
            return f"{next(iter(values.values())):g}".replace(".", mark)
        return ", ".join(f"{label} {value:g}".replace(".", mark) for label, value in values.items())

    def factor(self, mark: str = ".") -> str:
        """What turns a length on the sheet's polygon into the same on the record's: ``0.8``, or ``0.8 (II(3,4)), 0.5
        (I(1,2))`` where the polygons differ."""
        values = {label: sheet / record for label, (sheet, record) in self.polygons.items()}
        if len({f"{value:.4g}" for value in values.values()}) == 1:
            return f"{next(iter(values.values())):.4g}".replace(".", mark)
        return ", ".join(f"{value:.4g} ({label})".replace(".", mark) for label, value in values.items())

    @property
    def same_scales(self) -> bool:
        """Whether the drawing the readings fit is at the μF of the polygons they are checked against, polygon by
        polygon (a drawing with friction, the record's as a rule): those μF are then said once."""
        return self.scales(0) == self.scales(1)

    @property
    def kind(self) -> str:
        """The locale's key of what the readings fit (``sheet_drawn_arrows_friction``)."""
        return f"sheet_drawn_{self.drawing}" + ("_friction" if self.friction else "")


@dataclass(frozen=True)
class Segment:
    """A segment of a plan as constructed that a hand reading matches: its plan, its letters, its length (mm)."""

    plan: str
    name: str
    millimetres: float
    # On the other plan than the one the reading was given for: read off the wrong plan, not a segment swapped.
    other: bool = False


def slips(position: VelocityPosition, drawing: Drawing, joint: str,
          sheets: tuple[SheetPolygons, ...] = (), mechanism: Mechanism | None = None) -> Slips | None:
    """The hand readings of ``position`` far off its constructed plans and polygons, or None where all are near.

    ``drawing`` is the scene's (its precision and the keys a rescaled drawing is set by), ``joint`` the driver's
    point, whose vector on a plan is its pole distance; ``sheets`` the position's force sheets as the course sheets
    draw them larger (:class:`SheetPolygons`, one or several), where the run drew the sheets so.  Given the
    ``mechanism``, an acceleration plan whose readings fit it built with the Coriolis parts reversed is told so.
    """
    precision = drawing.drafting_precision
    constructed = {row.quantity: row.plan for row in position.errors if row.source == "construction"}
    # The balancing load found by hand is a value, not a length read off a drawing: its error is the table's alone.
    measured = [(row, constructed[row.quantity]) for row in position.errors
                if row.source == "measured" and row.quantity in constructed and not is_balancing(row.quantity)]
    far = [(row, plan) for row, plan in measured if _far_off(row, plan, precision)]
    # Polygons measured on the course sheet, drawn larger there: no scale of the scene's is off, the drawing read is.
    on_sheet = _on_sheet(position, measured, far, sheets, precision)
    if on_sheet is not None:
        measured = [(row, plan) for row, plan in measured if not _read_on_sheet(row, on_sheet)]
        far = [(row, plan) for row, plan in far if not _read_on_sheet(row, on_sheet)]
    reversed_parts = () if mechanism is None else coriolis_reversed(mechanism, position, measured, far, precision)
    reversed_readings = tuple(dict.fromkeys(row.reading for row, _ in measured if _plan_of(row) == "acceleration")) \
        if reversed_parts else ()
    measured = [(row, plan) for row, plan in measured if row.reading not in reversed_readings]
    far = [(row, plan) for row, plan in far if row.reading not in reversed_readings]
    # One rule for every drawing: the plans, then every force polygon together (the scene's one force_scale
    # sets them all, so a student who drew them all at one μF is told that one key), then each polygon alone.
    reactions = [(row, plan) for row, plan in measured if _plan_of(row) == "forces"]
    drawings = [(kind, None, [(row, plan) for row, plan in measured if _plan_of(row) == kind]) for kind in _SCALES]
    labels = dict.fromkeys(row.polygon for row, _ in reactions)
    drawings.append(("forces", next(iter(labels)) if len(labels) == 1 else None, reactions))
    drawings += [("forces", label, [(row, plan) for row, plan in reactions if row.polygon == label])
                 for label in labels if len(labels) > 1]
    rescaled = []
    for kind, polygon, rows in drawings:
        read = [(row, plan, _read_at(position, row)) for row, plan in rows]
        if not any(row is each for row, _ in rows for each, _ in far):
            # No reading far off, yet every reading of a plan in one ratio to it, off 1 beyond the readings' errors:
            # a plan laid off at another pole (pa = 110 mm for 100), not a drawing 10 % wrong everywhere.
            drawn_at = _uniform_scale(read, precision) if kind in _SCALES else None
            if drawn_at is not None:
                rescaled.append(_rescaled(kind, polygon, read, drawn_at, position, drawing, joint))
            continue
        drawn_at = _one_scale(read)
        if drawn_at is not None:
            rescaled.append(_rescaled(kind, polygon, read, drawn_at, position, drawing, joint))
            far = [(row, plan) for row, plan in far if not any(row is each for each, _ in rows)]
        elif kind in _SCALES and (odd := _one_scale_but_one(read)) is not None:
            # A plan drawn at another pole with one segment misread besides: the scale is told, and the one reading.
            drawn_at, left_out = odd
            kept = [(row, plan, scale) for row, plan, scale in read if row.reading != left_out]
            rescaled.append(replace(_rescaled(kind, polygon, kept, drawn_at, position, drawing, joint),
                                    but=(left_out,)))
            far = [(row, plan) for row, plan in far if not any(row is each for each, _, _ in kept)]
    if not rescaled and not far and on_sheet is None and not reversed_readings:
        return None
    misread: dict[str, list[tuple[ErrorRow, float]]] = {}
    for row, plan in far:
        misread.setdefault(row.reading, []).append((row, plan))
    # Readings far off that are other segments of the plans as constructed: a whole table read off the other plan, or
    # a segment taken for another (pb read where ab was), named rather than told "a length misread".
    other_plan = _other_plan(position, measured, misread, precision)
    for _, read in other_plan.values():
        for reading in read:
            misread.pop(reading, None)
    typed_in: dict[str, dict[str, tuple[float, float]]] = {unit: {} for unit, _, _ in _TYPED_UNITS}
    for reading, rows in list(misread.items()):
        row, plan = rows[0]
        constructed = abs(plan) / row.per_millimetre if row.per_millimetre else 0.0
        typed = typed_unit(_hand_millimetres(row) / constructed) if constructed > 0.0 else None
        if typed is not None:
            typed_in[typed[0]][reading] = (_hand_millimetres(row), constructed)
            del misread[reading]
    values = {}
    for reading, rows in list(misread.items()):
        millimetres = _hand_millimetres(rows[0][0])
        # One reading typed as its value, as a whole plan's are told (every reading the value it stands for): by
        # itself it was named another segment it happened to be near, or a length misread.
        # A segment's ω or ε is no value a segment stands for: its length gives the link's V or a first.
        quantity = next((row.quantity for row, plan in rows
                         if plan and not row.quantity.startswith(("omega", "epsilon"))
                         and abs(millimetres - abs(plan)) <= VALUE_TYPED_SHARE * abs(plan)), None)
        if quantity is not None:
            values[reading] = (quantity, millimetres, abs(rows[0][1]) / rows[0][0].per_millimetre)
            del misread[reading]
            continue
        # A tangential component gives its link's ε alone (n3b), and typed as its value in m/s² (ε3·lAB) it was
        # told a length misread, where aBA typed so was told the value it stands for.
        tangential = _tangential(position, rows[0][0])
        if tangential is not None and abs(millimetres - tangential[1]) <= VALUE_TYPED_SHARE * tangential[1]:
            values[reading] = (tangential[0], millimetres, tangential[2])
            del misread[reading]
    force_scale = {}
    for reading, rows in list(misread.items()):
        row, plan = rows[0]
        millimetres = _hand_millimetres(row)
        if _plan_of(row) != "forces" or not plan or not millimetres > 0.0:
            continue
        # One reaction read at another μF than its polygon's, the free-body arrows' that the force sheet draws beside
        # it at their own, say: the standard μF it is the reaction's length at.
        scale = nearest_standard_scale(abs(plan) / millimetres)
        # Within the precision and 2 % both: a short reading is near some standard μF's length by chance.
        there = abs(plan) / scale
        if not math.isclose(scale, row.per_millimetre) and abs(there - millimetres) <= min(precision, 0.02 * there):
            force_scale[reading] = (scale, abs(plan) / scale)
            del misread[reading]
    named = {}
    for reading, rows in list(misread.items()):
        matches = _matching_segments(position, rows[0][0], precision)
        if matches:
            named[reading] = matches
            del misread[reading]
    return Slips(tuple(rescaled), {reading: tuple(rows) for reading, rows in misread.items()},
                 MappingProxyType(named),
                 MappingProxyType({kind: (other, tuple(_name(reading) for reading in read))
                                   for kind, (other, read) in other_plan.items()}),
                 MappingProxyType(typed_in["metres"]), MappingProxyType(typed_in["centimetres"]),
                 MappingProxyType(force_scale), MappingProxyType(values), on_sheet, reversed_readings, reversed_parts)


def coriolis_reversed(mechanism: Mechanism, position: VelocityPosition, measured: list[tuple[ErrorRow, float]],
                      far: list[tuple[ErrorRow, float]], precision: float) -> tuple[str, ...]:
    """The Coriolis parts of ``position``'s acceleration plan (``aA4A3ᵏ``) that its hand readings, one at least far
    off the plan as constructed, find laid off against 2·ω × v_rel: every reading is its segment on the plan built
    so (:func:`_fits`), and two readings at least tell that plan from the one constructed (one may fit by chance;
    πa, the same on both, tells nothing).  The fewest parts that do so, each alone first; none where no such plan
    fits.

    Turning v_rel the wrong way is the slip the Coriolis part is known for: every segment from it on is off, and
    was told as so many lengths misread."""
    plan = position.plans.get("acceleration")
    if plan is None or not any(_plan_of(row) == "acceleration" for row, _ in far):
        return ()
    # By the letter of its end (k, k5), each part as the plan names it.
    parts = {vector.end: vector.meaning for step in plan.steps for vector in step.vectors if "ᵏ" in vector.meaning}
    rows = [row for row, _ in measured if _plan_of(row) == "acceleration"]
    if not parts or len({row.reading for row in rows}) < 2:
        return ()
    for count in range(1, len(parts) + 1):
        for reversed_ends in itertools.combinations(parts, count):
            try:
                reversed_plan = acceleration_plan(mechanism, position.positions, position.directions,
                                                  position.velocity, plan.scale, coriolis_reversed=reversed_ends)
            except ParallelLinesError:  # its lines cross nowhere: no plan a hand could have drawn
                continue
            telling = {row.reading for row in rows if not _same_length(row, plan, reversed_plan, position, precision)}
            if len(telling) >= 2 and all(_fits(row, reversed_plan, position, precision) for row in rows):
                return tuple(parts[end] for end in reversed_ends)
    return ()


def _same_length(row: ErrorRow, plan: Plan, other: Plan, position: VelocityPosition, precision: float) -> bool:
    """Whether a reading's segment is as long on ``plan`` and ``other``, to within what :func:`_fits` allows."""
    there = _length_on(other, row, position)
    return there is None or _within(segment_millimetres(plan, _segment_of(position, row)), there, precision)


def _within(read: float, there: float, precision: float) -> bool:
    """Whether a length ``read`` is ``there`` as closely as a careful drawing keeps to the construction: the drafting
    precision twice, or :data:`UNIFORM_SLIP_PERCENT`."""
    return abs(read - there) <= max(FAR_OFF_PRECISIONS * precision, UNIFORM_SLIP_PERCENT / 100.0 * there)


def _fits(row: ErrorRow, plan: Plan, position: VelocityPosition, precision: float) -> bool:
    """Whether a hand reading is its segment on ``plan`` (:func:`_within`)."""
    there = _length_on(plan, row, position)
    return there is not None and _within(_hand_millimetres(row), there, precision)


def _length_on(plan: Plan, row: ErrorRow, position: VelocityPosition) -> float | None:
    """The length (mm) on ``plan`` of the segment a measured row was read from; None where the plan has no such
    segment."""
    segment = _segment_of(position, row)
    if segment is None or not all(letter in plan.points for letter in segment):
        return None
    return segment_millimetres(plan, segment)


def _tangential(position: VelocityPosition, row: ErrorRow) -> tuple[str, float, float] | None:
    """For a reading of a tangential component (the segment that gives a link's ε), the component as the plan
    letters it (``aBAτ``), its value (m/s²) and its length as constructed (mm); None for another reading."""
    segment = _segment_of(position, row)
    plan = position.plans.get("acceleration")
    if not row.quantity.startswith("epsilon") or segment is None or plan is None:
        return None
    vector = next((vector for step in plan.steps for vector in step.vectors
                   if {vector.start, vector.end} == set(segment) and "τ" in vector.meaning), None)
    if vector is None:
        return None
    millimetres = segment_millimetres(plan, segment)
    return vector.meaning.replace("^τ", "τ"), millimetres * plan.scale, millimetres


def _read_on_sheet(row: ErrorRow, on_sheet: OnSheet) -> bool:
    """Whether a measured row is a reading found read off the course sheet."""
    return _plan_of(row) == "forces" and row.reading in on_sheet.readings


def _on_sheet(position: VelocityPosition, measured: list[tuple[ErrorRow, float]], far: list[tuple[ErrorRow, float]],
              sheets: tuple[SheetPolygons, ...], precision: float) -> OnSheet | None:
    """The readings that fit a drawing of the course ``sheets`` drawn larger there than the record (its polygons, or
    its groups cut free's arrows; of the force sheet, or of the force sheet with friction, taken at the reactions with
    friction), or the record's own groups cut free's arrows, where one reading of them at least is far off the
    record's polygons: a student who printed the course sheet, or the force sheet, measured it.  Of the drawings they
    fit, the one fitting the most readings, then the nearest, then the first (the course sheets come first).

    By polygon label, two readings or more fit as :func:`_one_scale` has readings fit one scale (each within
    :data:`FAR_OFF_PERCENT` of it, the scale they agree at within 5 % of the sheet's, as :func:`on_grid` has a
    small plan's); one alone as a reading at another standard μF is told (within the drafting ``precision`` and 2 %
    of the reaction's length on the sheet).  On a drawing with friction, a polygon's readings that fit it one by one
    where the polygon's others are near the polygon without friction fit it too, each named
    (:func:`_partly_with_friction`).  None where the run drew no sheet so or no readings fit it."""
    reactions = [(row, plan) for row, plan in measured if _plan_of(row) == "forces"]
    rubbing = getattr(position, "with_friction", None)
    best = None
    for sheet in sheets:
        if sheet.friction and rubbing is None:
            continue
        # Readings of the force sheet with friction measure its reactions, not those they are checked against.
        values = [(row, abs(rubbing.reactions[row.quantity].force) if sheet.friction else plan)
                  for row, plan in reactions if not sheet.friction or row.quantity in rubbing.reactions]
        plain = {row.reading: plan for row, plan in reactions}
        for drawing, scales, whole in sheet.drawings():
            by_polygon: dict[str, list[tuple[ErrorRow, float]]] = {}
            for row, value in values:
                if whole is None or _name(row.reading) in whole.get(row.polygon, ()):
                    by_polygon.setdefault(row.polygon, []).append((row, value))
            fitting, partly = {}, {}
            for label, rows in by_polygon.items():
                at, record = scales.get(label), rows[0][0].per_millimetre
                # The record's arrows at 1 N/mm are the forces' values in N: readings that fit them are told typed as
                # values, as they were before the record's arrows were known (a course sheet's stand on paper apart).
                if sheet.sheet is None and at is not None and in_units(at):
                    continue
                # The polygons with friction find other reactions: at the record's μF too they are another drawing.
                if at is None or not record or (not sheet.friction and math.isclose(at, record)):
                    continue
                if _fit_at(rows, at, record, precision, plain):
                    fitting[label] = (at, record)
                elif sheet.friction:
                    some = _partly_with_friction(rows, at, precision, far, reactions)
                    if some:
                        fitting[label], partly[label] = (at, record), some
            read = [(row, value) for label in fitting for row, value in partly.get(label, by_polygon[label])]
            if not any(row is each for row, _ in read for each, _ in far):
                continue
            off = max((abs(row.plan * fitting[row.polygon][0] / row.per_millimetre - value) / abs(value)
                       for row, value in read if value), default=0.0)
            found = OnSheet(sheet.sheet, MappingProxyType(fitting), len(read) == len(reactions), off, drawing,
                            sheet.friction, frozenset(row.reading for row, _ in read),
                            tuple(dict.fromkeys(row.reading for row, _ in read)) if partly else ())
            if best is None or (len(found.readings), -found.off) > (len(best.readings), -best.off):
                best = found
    return best


def _partly_with_friction(rows: list[tuple[ErrorRow, float]], at: float, precision: float,
                          far: list[tuple[ErrorRow, float]],
                          reactions: list[tuple[ErrorRow, float]]) -> list[tuple[ErrorRow, float]]:
    """Of one polygon's readings ``rows`` (each with its reaction with friction), those that fit a drawing with
    friction at ``at`` one by one (as one reading alone fits, :func:`_fit_at`), far off the polygon without friction,
    where every other reading of the polygon among ``reactions`` is near that polygon: one reaction measured on the
    drawing with friction, the others on the polygon they are checked against.  Empty where the readings are not so
    (some reading far off both), or where all fit it."""
    far_off = {row.reading for row, _ in far}
    fitting = [(row, value) for row, value in rows
               if row.reading in far_off and _fit_at([(row, value)], at, row.per_millimetre, precision, {})]
    named = {row.reading for row, _ in fitting}
    polygon = {row.reading for row, _ in reactions if row.polygon == rows[0][0].polygon}
    if not named or named == polygon or any(reading in far_off for reading in polygon - named):
        return []
    return fitting


def _fit_at(rows: list[tuple[ErrorRow, float]], at: float, record: float, precision: float,
            plain: Mapping[str, float]) -> bool:
    """Whether the readings ``rows`` of one polygon, read at its ``record`` μF, fit the polygon drawn at ``at``
    (its reactions each row's value) better than the record's, whose reactions are ``plain`` by reading: see
    :func:`_on_sheet`."""
    rows = [(row, plan) for row, plan in rows if plan]
    if not rows or any(row.plan / plan <= 0 for row, plan in rows):
        return False
    if len({row.reading for row, _ in rows}) == 1:
        row, plan = rows[0]
        there = abs(plan) / at
        return abs(there - _hand_millimetres(row)) <= min(precision, 0.02 * there)
    implied = [record * plan / row.plan for row, plan in rows]
    drawn_at = statistics.median(implied)
    # The record's polygons as the readings imply them: the same reactions, unless the drawing's are with friction.
    recorded_at = statistics.median(record * plain[row.reading] / row.plan for row, _ in rows)
    return (all(abs(each / at - 1.0) <= FAR_OFF_PERCENT / 100.0 for each in implied)
            and abs(drawn_at / at - 1.0) <= _ROUND_SHARE
            and abs(drawn_at / at - 1.0) < abs(recorded_at / record - 1.0))


def _name(reading: str) -> str:
    """A reading's segment as the scene writes it: ``pb`` of ``pb = 100.98 mm``."""
    return reading.split(" = ")[0]


def _hand_millimetres(row: ErrorRow) -> float:
    """The length a measured row was read as (mm)."""
    return abs(row.plan) / row.per_millimetre if row.per_millimetre else math.nan


def _segment_of(position: VelocityPosition, row: ErrorRow) -> tuple[str, str] | None:
    """The two plan letters of the segment a measured row of a plan was read from."""
    return next((reading.segment for reading in position.readings if reading.quantity == row.quantity), None)


def _other_plan(position: VelocityPosition, measured: list[tuple[ErrorRow, float]],
                misread: Mapping[str, list[tuple[ErrorRow, float]]],
                precision: float) -> dict[str, tuple[str, tuple[str, ...]]]:
    """By the plan a table of readings was given for, the other plan of the position and the readings (as the scene
    writes them) where every reading of that table is the other plan's segment of its name, to the drafting
    ``precision``, and one at least is far off its own plan: the other plan's readings typed under the wrong table."""
    found = {}
    for kind in _SCALES:
        other = next((each for each in _SCALES if each != kind), None)
        if kind not in position.plans or other not in position.plans:
            continue
        rows = {row.reading: row for row, _ in measured if _plan_of(row) == kind}
        if not rows or not any(reading in misread for reading in rows):
            continue
        if all(_same_named(position, position.plans[other], row, precision) for row in rows.values()):
            found[kind] = (other, tuple(rows))
    return found


def _same_named(position: VelocityPosition, other, row: ErrorRow, precision: float) -> bool:
    """Whether a reading is, to the drafting ``precision``, the segment of its letters on the ``other`` plan."""
    segment = _segment_of(position, row)
    if segment is None or not all(letter in other.points for letter in segment):
        return False
    return abs(_hand_millimetres(row) - segment_millimetres(other, segment)) <= precision


def _matching_segments(position: VelocityPosition, row: ErrorRow, precision: float) -> tuple[Segment, ...]:
    """The segments a student measures on the position's plans as constructed (those the error table reads), other
    than the one the reading names, that a far-off reading is to the drafting ``precision``, nearest first."""
    own = _segment_of(position, row)
    kind = _plan_of(row)
    millimetres = _hand_millimetres(row)
    seen: set[tuple[str, frozenset[str]]] = set()
    matches = []
    for plan in sorted(position.plans, key=lambda each: each != kind):  # its own plan's segments first
        for reading in position.readings:
            key = (plan, frozenset(reading.segment))
            if reading.plan != plan or key in seen or (plan == kind and set(reading.segment) == set(own or ())):
                continue
            seen.add(key)
            length = reading.millimetres(position.plans)
            # A segment no longer than the precision is a point on the drawing (ps4 of a centre on a fixed pivot):
            # any small reading is it, which tells nothing of the reading.
            if length > precision and abs(millimetres - length) <= precision:
                matches.append(Segment(plan, "".join(reading.segment), length, plan != kind))
        # A normal or Coriolis component is laid off, not read, so no reading names it; but a student who measured
        # it (ak, an3) and typed it under the segment beside it (ka4, n3b) is told which component it is.  Only on
        # the reading's own plan: a velocity plan has none beside its segments, and a velocity reading of the
        # length of an acceleration plan's component is chance (ab = 3.5 mm "is the acceleration plan's an3").
        for step in position.plans[plan].steps if plan == kind else ():
            for vector in step.vectors:
                key = (plan, frozenset((vector.start, vector.end)))
                if key in seen or not any(mark in vector.meaning for mark in ("ᵏ", "ⁿ")):
                    continue
                seen.add(key)
                length = abs(position.plans[plan].mm(vector.end) - position.plans[plan].mm(vector.start))
                if length > precision and abs(millimetres - length) <= precision:
                    matches.append(Segment(plan, f"{vector.start}{vector.end} ({vector.meaning})", length,
                                           plan != kind))
    return tuple(sorted(matches, key=lambda each: abs(millimetres - each.millimetres)))


def _read_at(position: VelocityPosition, row: ErrorRow) -> float:
    """The scale a measured row was read at: its plan's, or the μF of its force polygon."""
    kind = _plan_of(row)
    return row.per_millimetre if kind == "forces" else position.plans[kind].scale


def _one_scale(read: list[tuple[ErrorRow, float, float]]) -> float | None:
    """The one scale at which two readings or more agree with the construction where they were read at another:
    each reading implies the scale it was drawn at (read at μ as r, of a construction c: μ·c/r), and all those
    agree within :data:`FAR_OFF_PERCENT` of their median (a scale's slip, under the readings' own
    errors of a few per cent), which is far from a scale some were read at."""
    # A segment gives several quantities (pb: VB, ω4) in one ratio: two segments at least make a scale.
    implied = {}
    for row, plan, scale in read:
        if not plan:
            continue
        if row.plan / plan <= 0:
            return None
        implied[row.reading] = (scale * plan / row.plan, scale)
    if len(implied) < 2:
        return None
    drawn_at = statistics.median(each for each, _ in implied.values())
    tolerance = FAR_OFF_PERCENT / 100.0
    if not all(abs(each / drawn_at - 1.0) <= tolerance for each, _ in implied.values()):
        return None
    return drawn_at if any(abs(scale / drawn_at - 1.0) > tolerance for _, scale in implied.values()) else None


# The fewest readings of a plan that, all but one agreeing at one scale, tell the scale and the one misread.
_FEWEST_BUT_ONE = 4


def _one_scale_but_one(read: list[tuple[ErrorRow, float, float]]) -> tuple[float, str] | None:
    """The scale all readings of a plan but one agree at (:func:`_one_scale`), with that one reading as the scene
    writes it, where the plan has :data:`_FEWEST_BUT_ONE` readings or more and one alone leaves the rest agreeing,
    at a scale no unit explains (a plan typed in centimetres or in its values is told whole); None otherwise.  A
    plan drawn at pa = 120 mm with ps4 given pb's length was told four lengths misread, and no scale."""
    readings = list(dict.fromkeys(row.reading for row, _, _ in read))
    if len(readings) < _FEWEST_BUT_ONE:
        return None
    found = [(drawn_at, odd) for odd in readings
             if (drawn_at := _one_scale([each for each in read if each[0].reading != odd])) is not None]
    if len(found) != 1:
        return None
    drawn_at, odd = found[0]
    read_at = read[0][2]
    return None if typed_unit(read_at / drawn_at) is not None or in_units(drawn_at) else (drawn_at, odd)


def _uniform_scale(read: list[tuple[ErrorRow, float, float]], precision: float) -> float | None:
    """The scale a plan was drawn at whose readings, none far off, all stand in one ratio to the construction: each
    within the drafting ``precision`` (mm) of that ratio times its constructed length, the ratio off 1 by more than
    :data:`UNIFORM_SLIP_PERCENT` and some reading off its construction by more than twice the precision (a ratio
    the readings tell apart from 1).  None where they do not (a student's own errors scatter)."""
    implied = [(row, plan, scale) for row, plan, scale in read if plan and row.per_millimetre]
    if len({row.reading for row, _, _ in implied}) < 2 or any(row.plan / plan <= 0 for row, plan, _ in implied):
        return None
    ratio = statistics.median(row.plan / plan for row, plan, _ in implied)
    if abs(ratio - 1.0) <= UNIFORM_SLIP_PERCENT / 100.0:
        return None
    if any(abs(row.plan - ratio * plan) / row.per_millimetre > precision for row, plan, _ in implied):
        return None
    if all(abs(row.plan - plan) / row.per_millimetre <= FAR_OFF_PRECISIONS * precision for row, plan, _ in implied):
        return None
    drawn_at = statistics.median(scale * plan / row.plan for row, plan, scale in implied)
    # At one unit a millimetre read at about one, "values typed in their units" would be said of a plan's slip.
    return None if in_units(drawn_at) else drawn_at


def _rescaled(kind: str, polygon: str | None, read: list[tuple[ErrorRow, float, float]], drawn_at: float,
              position: VelocityPosition, drawing: Drawing, joint: str) -> Rescaled:
    """A drawing found at another scale, with the scene's key that sets it and how close the readings come."""
    read_at = ({row.polygon: scale for row, _, scale in read} if kind == "forces"
               else {kind: position.plans[kind].scale})
    driver = 0.0
    if kind == "forces":
        key = "drawing.force_scale"
    else:
        # A plan sheet's plans are set by the scene's pole distance or scale, the velocity plans of every
        # position (no acceleration plan beside them) by velocity_plans_pole; the driver's vector is the pole's.
        sheet = hasattr(position, "acceleration")
        given = getattr(drawing, f"{kind}_scale") if sheet else None
        plan = position.plans[kind]
        driver = abs(plan.value(joint)) if joint in plan.images else 0.0
        key = (f"drawing.{kind}_scale" if given is not None or not driver
               else f"drawing.{kind}_pole" if sheet else "drawing.velocity_plans_pole")
    # How far the readings' own scales stray from their fit: a round value within it they cannot tell from the fit.
    spread = max((abs(plan / row.plan * scale / drawn_at - 1.0) for row, plan, scale in read if plan and row.plan),
                 default=0.0)
    if key.endswith("_pole"):
        # pa = VA / μV: the pole distance the driver's vector is drawn at.
        setting = driver / drawn_at
        rounded = _round_pole(setting, spread)
        at = driver / rounded
    else:
        setting = drawn_at
        rounded = at = _round_scale(drawn_at, spread)
    off = max((abs(row.plan * at / scale - plan) / abs(plan) for row, plan, scale in read if plan), default=0.0)
    unit_setting, replaces = "`[drawing] force_scale = 1`", None
    if key == "drawing.velocity_plans_pole":
        # The plans of every position have no scale key: at μV = 1 the driver's vector is VA mm long.
        unit_setting = f"`[drawing] velocity_plans_pole = {driver:.4g}`"
    elif kind != "forces":
        unit_setting = f"`[drawing] {kind}_scale = 1`"
        replaces = f"{kind}_pole" if getattr(drawing, f"{kind}_pole") is not None else None
    return Rescaled(kind, polygon, read_at, drawn_at, key, setting, rounded, off, unit_setting, replaces)


def _round_scale(scale: float, spread: float) -> float:
    """The standard scale factor nearest ``scale`` where the readings cannot tell one from it (within their own
    ``spread``, a share of the fit, and within 5 %: a student draws at one), else ``scale`` to three digits."""
    near = nearest_standard_scale(scale)
    return near if abs(near / scale - 1.0) <= min(spread, _ROUND_SHARE) else float(f"{scale:.3g}")


def _round_pole(pole: float, spread: float) -> float:
    """The round pole distance (mm) a student laid off at ``pole``: the coarsest of 50, 25, 10, 5 mm steps the
    readings cannot tell from it (within their own ``spread``, a share of the fit, and within 5 %), else the whole
    millimetre nearest it (a tenth of one for a pole under 10 mm).  The coarsest step within 5 % alone took a plan
    drawn at 120 mm for one at 125 and put every reading 4 % off."""
    share = min(spread, _ROUND_SHARE)
    for step in (50.0, 25.0, 10.0, 5.0):
        value = round(pole / step) * step
        if value > 0 and abs(value / pole - 1.0) <= share:
            return value
    return float(round(pole)) if pole >= 10.0 else round(pole, 1)


# A round value this close to the scale the readings give is taken for the one the student drew at.
_ROUND_SHARE = 0.05


def sharing(rescaled: Rescaled, position: VelocityPosition, drawn: Iterable[VelocityPosition], drawing: Drawing,
            joint: str, sheets: SheetsDrawn | None = None) -> tuple[tuple[int, ...], dict[int, float]]:
    """The other positions whose drawings the key of ``rescaled`` sets too: those whose readings of them fit the
    present scale, and (by number) the value of the key those found drawn at another scale ask, where it is not this
    one's.  The key is the scene's, one for every position (every plan sheet's pole or scale, ``force_scale`` for
    every position's polygons, ``velocity_plans_pole`` for the plans of every position), so giving it as this
    position's readings ask would put the others' off."""
    sheet = hasattr(position, "acceleration")
    drawn = tuple(drawn)
    fitting, asking = [], {}
    for other in drawn:
        if other.number == position.number or hasattr(other, "acceleration") != sheet:
            continue
        if not any(row.source == "measured" and _plan_of(row) == rescaled.kind for row in other.errors):
            continue
        found = slips(other, drawing, joint, sheet_of(other, sheets or {}))
        if found is not None and found.on_sheet is not None and rescaled.kind == "forces":
            continue  # read off the course sheet's polygons: no scale of the key's either
        theirs = [each for each in (found.rescaled if found else ()) if each.key == rescaled.key]
        if any(on_grid(each, other, drawn) is not None for each in theirs):
            continue  # read off its small plan among the velocity plans of every position: no scale of the key's
        if not theirs:
            fitting.append(other.number)
        elif theirs[0].rounded != rescaled.rounded and not in_units(theirs[0].drawn_at):
            asking[other.number] = theirs[0].rounded
    return tuple(fitting), asking


@dataclass(frozen=True)
class OnGrid:
    """A plan sheet's velocity readings that fit the same position's small plan among the velocity plans of every
    position (``velocity_plans.svg``) instead: ``scale`` its μV, ``sheet`` the plan sheet's the readings are checked
    at, ``off`` the largest share by which a reading taken at ``scale`` is off the construction."""

    scale: float
    sheet: float
    off: float

    @property
    def factor(self) -> float:
        """What turns a length of the small plan into the same length on the plan sheet."""
        return self.scale / self.sheet


def on_grid(rescaled: Rescaled, position: VelocityPosition, drawn: Iterable[VelocityPosition]) -> OnGrid | None:
    """Where the velocity readings of a plan-sheet position, found drawn at another μV, fit the position's own plan
    among the velocity plans of every position (its μV within 5 % of the one they fit): the student measured that
    small plan, and the key to change is none.  None where the position has no such plan or they fit another μV."""
    if rescaled.kind != "velocity" or not hasattr(position, "acceleration") or in_units(rescaled.drawn_at):
        return None
    grid = next((each for each in drawn if each.number == position.number and not hasattr(each, "acceleration")), None)
    if grid is None:
        return None
    scale, sheet = grid.velocity.scale, position.velocity.scale
    if abs(rescaled.drawn_at / scale - 1.0) > _ROUND_SHARE:
        return None
    constructed = {row.quantity: row.plan for row in position.errors if row.source == "construction"}
    off = max((abs(row.plan * scale / sheet - constructed[row.quantity]) / abs(constructed[row.quantity])
               for row in position.errors if row.source == "measured" and _plan_of(row) == "velocity"
               and constructed.get(row.quantity)), default=0.0)
    return OnGrid(scale, sheet, off)


def factors(rescaled: Rescaled) -> dict[str, float]:
    """By the plan (or force polygon) read, the factor that turns readings of the drawing as the student drew it into
    lengths at the scale it was read at: the key then stays, for the other positions it sets."""
    at = rescaled.rounded if not rescaled.key.endswith("_pole") else rescaled.setting * rescaled.drawn_at / rescaled.rounded
    return {label: at / scale for label, scale in rescaled.read_at.items()}


def factor_text(rescaled: Rescaled, mark: str = ".") -> str:
    """:func:`factors` as a warning says it: ``0.5``, or ``0.5 (I(1,2)), 0.4 (II(3,4))`` for polygons read apart."""
    each = factors(rescaled)
    values = {f"{value:.4g}" for value in each.values()}
    if len(values) == 1:
        return values.pop().replace(".", mark)
    return ", ".join(f"{value:.4g} ({label})".replace(".", mark) for label, value in each.items())


def _shared_caveat(rescaled: Rescaled, position: VelocityPosition, drawn: tuple[VelocityPosition, ...],
                   drawing: Drawing, joint: str, sheets: SheetsDrawn | None = None) -> str:
    """Where the key of ``rescaled`` sets other positions whose readings fit it as it is, or ask it another value
    (:func:`sharing`): that said, with how to keep it; else nothing.  Asked only where the warning gives the key."""
    fitting, asking = sharing(rescaled, position, drawn, drawing, joint, sheets)
    if not (fitting or asking):
        return ""
    name = rescaled.key.removeprefix("drawing.")
    shared = fitting or tuple(asking)
    why = ("whose readings fit the present scale and would then be off" if fitting else
           "whose readings ask " + ", ".join(f"{name} = {value:g}" for value in asking.values())
           + " (no one value fits them all)")
    return (f"; but {name} sets the scale of position{'s' if len(shared) > 1 else ''} "
            f"{', '.join(map(str, shared))} too, {why}: rather keep it and give the readings of "
            f"position {position.number} times {factor_text(rescaled)}")


def misread(mechanism: Mechanism, drawn: Iterable[VelocityPosition], sheets: SheetsDrawn | None = None, *,
            motion: Motion | None = None, numbers: Sequence[int] = ()) -> tuple[PositionWarning, ...]:
    """A ``measured-far-off`` warning at each position with hand readings far off its constructed plans; ``sheets``
    the polygons the course sheets draw larger than the record, by position number, where the run drew them, and the
    record's own arrows of the groups cut free (:class:`SheetPolygons` with no sheet).  Given the ``motion`` of
    every position and their ``numbers``, readings far off that fit another position are told which."""
    drawing = mechanism.scene.drawing
    precision = drawing.drafting_precision
    joint = mechanism.driver.joint
    drawn = tuple(drawn)
    sheets = sheets or {}
    warnings = []
    for position in drawn:
        found = slips(position, drawing, joint, sheet_of(position, sheets), mechanism)
        if found is None:
            continue
        details = []
        if found.on_sheet is not None:
            details.append(on_sheet_detail(found.on_sheet, position.number))
        if found.coriolis_reversed:
            many = len(found.coriolis_parts) > 1
            details.append(f"every reading of the acceleration plan ({', '.join(map(_name, found.coriolis_reversed))}) "
                           f"fits the plan with the Coriolis component{'s' if many else ''} "
                           f"{' and '.join(found.coriolis_parts)} laid off the other way, not the plan as constructed "
                           f"(each to {FAR_OFF_PRECISIONS * precision:g} mm or {UNIFORM_SLIP_PERCENT:g} %): 2·ω × v_rel "
                           f"has the direction of v_rel turned by 90° in the sense of ω; "
                           f"{'were the Coriolis components' if many else 'was the Coriolis component'} laid off "
                           f"reversed?")
        for rescaled in found.rescaled:
            typed = typed_unit(rescaled.ratio)
            if typed is not None:
                unit, share, factor = typed
                what = (f"the force polygon {rescaled.polygon}" if rescaled.polygon else "the force polygons") \
                    if rescaled.kind == "forces" else f"the {rescaled.kind} plan"
                # A plan drawn at a tenth of its pole is a drawing one might make; at a thousandth, none.
                drawn_so = (f"; or, drawn at that scale, give {setting(rescaled)}"
                            f"{_shared_caveat(rescaled, position, drawn, drawing, joint, sheets)}"
                            if unit == "centimetres" else "")
                details.append(f"every reading of {what} is {rescaled.ratio:.4g} times its length as constructed, "
                               f"{share}: lengths typed in {unit}? give the millimetres measured (each reading "
                               f"times {factor}){drawn_so}")
                continue
            if rescaled.kind == "forces":
                caveat = "" if in_units(rescaled.drawn_at) else \
                    _shared_caveat(rescaled, position, drawn, drawing, joint, sheets)
                details.append(_polygons_detail(rescaled) + caveat)
                continue
            symbol, unit = _SCALES[rescaled.kind]
            drawn_at, kind = rescaled.drawn_at, rescaled.kind
            grid = on_grid(rescaled, position, drawn)
            if grid is not None:
                # The position's small plan among the velocity plans of every position, read for its plan sheet's:
                # no key is off, the plan measured is.
                details.append(
                    f"every reading of the velocity plan fits position {position.number}'s plan among the velocity "
                    f"plans of every position (velocity_plans.svg, at {symbol} = {grid.scale:.4g} {unit}; taken "
                    f"at it, every reading is within {grid.off * 100.0:.1f} % of the plan as constructed), not its "
                    f"plan sheet's (plan_{position.number}.svg, at {symbol} = {grid.sheet:.4g} {unit}), which they "
                    f"are checked against: readings of that small plan? measure the plan sheet's velocity plan, or "
                    f"give these readings times {grid.factor:.4g}")
                continue
            if in_units(drawn_at):
                quantity = unit.removeprefix("(").removesuffix(")/mm")
                # A plan may truly be drawn at one unit a millimetre: the readings cannot tell, so both are said.
                instead = f" (in place of {rescaled.replaces})" if rescaled.replaces else ""
                details.append(f"every reading of the {kind} plan is the value it stands for, in {quantity}, not "
                               f"its length on the plan: give the millimetres measured (the value / {symbol}), "
                               f"or, drawn at {symbol} = 1 {unit}, give {rescaled.unit_setting}{instead}")
                continue
            # The scale the readings fit best is the median's, not the one drawn at: the key to give is the round
            # value near it, with how close the readings come there (the student's own errors stay).
            fit = f", {rescaled.key.removeprefix('drawing.')} ≈ {rescaled.setting:.4g} mm" if rescaled.key.endswith(
                "_pole") else ""
            but = f" but {', '.join(map(_name, rescaled.but))}" if rescaled.but else ""
            details.append(f"every reading of the {kind} plan{but} is {rescaled.ratio:.4g} times the plan as "
                           f"constructed at {symbol} = {position.plans[kind].scale:.4g} {unit}: a plan drawn at {symbol} = "
                           f"{drawn_at:.4g} {unit}{fit}? give {setting(rescaled)} (taken at it, every reading{but} is "
                           f"within {rescaled.off * 100.0:.1f} % of the plan as constructed)"
                           f"{_shared_caveat(rescaled, position, drawn, drawing, joint, sheets)}")
        for (unit, share, factor), readings in ((_TYPED_UNITS[0], found.metres), (_TYPED_UNITS[1], found.centimetres)):
            if readings:
                lengths = "; ".join(f"{reading} against {constructed:.4g} mm as constructed"
                                    for reading, (_, constructed) in readings.items())
                details.append(f"readings {share} of their lengths on the drawings ({lengths}): lengths typed in "
                               f"{unit}? give the millimetres measured (each reading times {factor})")
        if found.values:
            typed = "; ".join(f"{reading} is {quantity_symbol(quantity)} = {value:.4g} "
                              f"{_VALUE_UNITS[value_kind(quantity)]} ({constructed:.4g} mm as constructed)"
                              for reading, (quantity, value, constructed) in found.values.items())
            details.append(f"readings that are the values they stand for, not their lengths on the drawings "
                           f"({typed}): give the millimetres measured (each value over its drawing's scale)")
        if found.force_scale:
            details.append("; ".join(
                f"{reading} is {row_name} at μF = {scale:g} N/mm ({length:.2f} mm there), not at its polygon's"
                for reading, (scale, length), row_name in ((reading, value, _name(reading))
                                                           for reading, value in found.force_scale.items()))
                + ": read off the free-body arrows, which the force sheet draws at a μF of their own, or off a "
                  "polygon drawn at that μF?")
        elsewhere = None if motion is None or not found.misread else \
            fitting_position(mechanism, motion, numbers, position, precision)
        if found.misread:
            # + 0.0 makes the −0.0 a reading of 0 mm gives a turning link's ω (signed as constructed) plain 0.
            readings = "; ".join(f"{reading} gives " + ", ".join(
                f"{quantity_symbol(row.quantity)} = {row.plan + 0.0:.4g} against {plan + 0.0:.4g}, "
                + (f"{abs(row.plan - plan) / abs(plan) * 100.0:.1f} % off" if plan else "where the plan has none")
                for row, plan in rows) for reading, rows in found.misread.items())
            question = "a length misread, or a segment taken for another?" if elsewhere is None else (
                f"every reading of the plans fits position {elsewhere} instead (none far off its exact values): "
                f"readings of position {elsewhere}'s plans, or of plans drawn with the positions counted or numbered "
                f"otherwise (positions.count, start, number_from)?")
            details.append(f"readings more than {FAR_OFF_PERCENT:g} % and {FAR_OFF_PRECISIONS * precision:g} mm off "
                           f"the plan as constructed ({readings}): {question}")
        for kind, (other, names) in found.other_plan.items():
            details.append(f"the readings given for the {kind} plan are the {other} plan's {', '.join(names)} (each to "
                           f"the drafting precision, {precision:g} mm): readings of the {other} plan typed under "
                           f"{kind}?")
        # Another position's readings explain every one: a far-off reading that is by chance another segment's
        # length here is no lead to follow.
        if found.named and elsewhere is None:
            named = "; ".join(f"{reading} is " + " or ".join(
                f"the {segment.plan} plan's {segment.name} ({segment.millimetres:.2f} mm as constructed)"
                for segment in segments) for reading, segments in found.named.items())
            question = ("a segment taken for another, or read off the other plan?" if off_the_other_plan(found.named)
                        else "segments taken for one another?")
            details.append(f"readings far off their own segments that are other segments of the plans as constructed, "
                           f"to the drafting precision ({precision:g} mm): {named}: {question}")
        warnings.append(PositionWarning(position.index, "measured-far-off",
                                        f"measured.{position.number}: " + "; ".join(details)))
    return tuple(warnings)


# The fewest readings of the plans that can tell one position from another: one speed is every position's where the
# output link passes it (twice a turn), three agreeing at one position alone are not chance.
_FEWEST_TELLING = 3


def fitting_position(mechanism: Mechanism, motion: Motion, numbers: Sequence[int], position: VelocityPosition,
                     precision: float) -> int | None:
    """The number of the one other position at whose exact motion none of ``position``'s hand readings of the plans
    is far off (:func:`_far_off`, by magnitude: a reading gives ω's sense as its own plan is drawn), where there are
    enough of them to tell (:data:`_FEWEST_TELLING`); None where none, or more than one, fits.  A student who drew
    the plans of twelve positions and then set 24, or numbered them from 1 where the scene numbers from 0, gave
    readings of one position under another's number."""
    rows = [row for row in position.errors if row.source == "measured" and _plan_of(row) != "forces"]
    # Readings, not rows: one segment gives several values (pb: VB, VBC, ω4), and one reading of 0 mm fitted the
    # position where the output link stands still.
    if len({row.reading for row in rows}) < _FEWEST_TELLING:
        return None
    table = list(position.readings)
    fitting = []
    for index in range(motion.count):
        if index == position.index:
            continue
        exact = exact_values_at(mechanism, motion, table, index)
        if all(not _far_off(replace(row, plan=abs(row.plan)), abs(exact[row.quantity]), precision) for row in rows):
            fitting.append(int(numbers[index]))
    return fitting[0] if len(fitting) == 1 else None


def reads_forces(position: VelocityPosition) -> bool:
    """Whether a hand read a reaction of ``position`` off a drawing (the balancing load is a value, not a length)."""
    return any(row.source == "measured" and _plan_of(row) == "forces" and not is_balancing(row.quantity)
               for row in position.errors)


def sheet_of(position: VelocityPosition, sheets: SheetsDrawn) -> tuple[SheetPolygons, ...]:
    """The course sheets' force drawings of a position of plans (a position among the velocity plans alone has
    none): its force sheet's and its sheet with friction's, where drawn larger."""
    return sheets.get(position.number, ()) if hasattr(position, "acceleration") else ()


def on_sheet_detail(found: OnSheet, number: int) -> str:
    """The warning's words for force readings that fit a drawing of the course sheet of position ``number``, drawn
    larger there than the record's polygons they are checked against."""
    what = ("the force polygons" if found.every and len(found.polygons) > 1
            else f"the force polygon{'s' if len(found.polygons) > 1 else ''} {', '.join(found.polygons)}")
    # The console's warnings are in English whatever the scene's locale, as are the others here.
    drawn_as = strings("en")[found.kind].format(number=number)
    if found.friction:
        # Readings of a drawing with friction measure the reactions with friction, others than those the tables
        # compare with: no factor turns them into the polygons without friction's, on a course sheet or off it.
        within = (f"taken at it, every reading is within {found.off * 100.0:.1f} % of the reactions with friction as "
                  f"constructed")
        english = strings("en")
        record_at = (english["record_at_same_scale"] if found.same_scales
                     else english["record_at_scale"].format(scale=found.scales(1)))
        checked = (f"{record_at}), whose reactions they are checked against: readings of the reactions with friction, "
                   f"off the")
        if found.named:
            # Some readings of a polygon off the drawing with friction, the others where they should be: those named.
            where = (f"on the course sheet (sheet_{found.sheet}.svg)" if found.sheet is not None
                     else f"in forces_friction_{number}.svg")
            readings = ", ".join(reading.split(" at μF")[0] for reading in found.named)
            return (f"readings of {what} that fit {drawn_as} {where} at μF = {found.scales(0)} N/mm (taken at it, each "
                    f"is within {found.off * 100.0:.1f} % of its reaction with friction as constructed), where the "
                    f"other readings fit the polygons without friction of forces_{number}.svg ({record_at}), which "
                    f"they are all checked against: {readings}; readings of the reactions with friction, off the "
                    f"drawing with friction? measure these on the polygons of forces_{number}.svg")
        if found.sheet is not None:
            return (f"every reading of {what} fits {drawn_as} on the course sheet (sheet_{found.sheet}.svg, at μF = "
                    f"{found.scales(0)} N/mm; {within}), which draws them larger where it has room, not the polygons "
                    f"without friction of its force sheet (forces_{number}.svg, {checked} course sheet? measure the "
                    f"polygons of forces_{number}.svg")
        arrows = found.drawing == "arrows"
        return (f"every reading of {what} fits {drawn_as} in forces_friction_{number}.svg at μF = {found.scales(0)} "
                f"N/mm ({within}){', drawn there at a μF of their own' if arrows else ''}, not the polygons "
                f"without friction of forces_{number}.svg ({checked} "
                f"{'arrows' if arrows else 'polygons with friction'}? measure the polygons of forces_{number}.svg")
    if found.sheet is None:
        # The record's own groups cut free: forces_N.svg draws their arrows beside its polygons, at a μF of their own.
        return (f"every reading of {what} fits {drawn_as} in forces_{number}.svg at μF = {found.scales(0)} N/mm "
                f"(taken at it, every reading is within {found.off * 100.0:.1f} % of the polygons as constructed), "
                f"drawn at a μF of their own, not its polygons (at μF = {found.scales(1)} N/mm), which they are "
                f"checked against: readings of the arrows? measure the polygons, or give these readings times "
                f"{found.factor()}")
    plain = found.kind == "sheet_drawn_polygons"
    return (f"every reading of {what} fits {drawn_as} on the course sheet "
            f"(sheet_{found.sheet}.svg, at μF = {found.scales(0)} N/mm; taken at it, every reading is within "
            f"{found.off * 100.0:.1f} % of the polygons as constructed), which draws them larger where it has room, "
            f"not {'those' if plain else 'the polygons'} of its force sheet (forces_{number}.svg, at μF = "
            f"{found.scales(1)} N/mm), which they are checked against: readings of the course sheet's "
            f"{'polygons' if plain else 'drawing'}? measure forces_{number}.svg, or give these readings times "
            f"{found.factor()}")


def off_the_other_plan(named: Mapping[str, tuple[Segment, ...]]) -> bool:
    """Whether the ``named`` readings may have been read off the other plan: one matches a segment of it, and no
    two are each the other's segment on their own plan (swapped, whatever else of the other plan either matches)."""
    return any(segment.other for segments in named.values() for segment in segments) and not _swapped(named)


def _swapped(named: Mapping[str, tuple[Segment, ...]]) -> bool:
    """Whether two of the ``named`` readings are each the other's segment on their own plan (pb = ab's length and
    ab = pb's): segments swapped, whatever else of the other plan either also matches."""
    def letters(name: str) -> str:
        return "".join(sorted(name.replace("π", "p")))

    own = {reading: {letters(segment.name) for segment in segments if not segment.other}
           for reading, segments in named.items()}
    return any(letters(_name(second)) in own[first] and letters(_name(first)) in own[second]
               for first in named for second in named if first < second)


def setting(rescaled: Rescaled) -> str:
    """The scene's setting that draws a rescaled drawing as the student did: ```[drawing] velocity_pole = 300```."""
    table, key = rescaled.key.split(".")
    return f"`[{table}] {key} = {rescaled.rounded:g}`"


def read_at(rescaled: Rescaled) -> str:
    """The μF the readings of force polygons were read at: ``10`` (one), ``I(1,2) 20, II(3,4) 10`` (each its own)."""
    scales = set(rescaled.read_at.values())
    if len(scales) == 1:
        return f"{next(iter(scales)):g}"
    return ", ".join(f"{label} {scale:g}" for label, scale in rescaled.read_at.items())


def _polygons_detail(rescaled: Rescaled) -> str:
    """The warning's words for force polygons drawn at another μF than they were read at, or readings in N."""
    what = f"the force polygon {rescaled.polygon}" if rescaled.polygon else "the force polygons"
    if in_units(rescaled.drawn_at):
        # A polygon may truly be drawn at 1 N/mm: the readings cannot tell, so both are said.
        return (f"every reading of {what} is the force it stands for, in N, not its length on the polygon: give the "
                f"millimetres measured (the force / μF), or, drawn at μF = 1 N/mm, give `[drawing] force_scale = 1`")
    return (f"every reading of {what} fits polygons drawn at μF = {rescaled.drawn_at:.4g} N/mm, not the μF they were "
            f"read at ({read_at(rescaled)} N/mm): give {setting(rescaled)} (taken at it, "
            f"every reading is within {rescaled.off * 100.0:.1f} % of the polygons as constructed)")


def in_metres(ratio: float) -> bool:
    """Whether readings ``ratio`` times their drawing's lengths are those lengths typed in metres for the millimetres
    asked: a thousandth, within the spread a uniform slip is told at (a plan drawn a thousand times smaller, its pole
    0.1 mm, is none a student draws or reads)."""
    return abs(ratio * 1000.0 - 1.0) <= FAR_OFF_PERCENT / 100.0


# The units other than millimetres that readings are typed in, each as the console names it: the unit, the share of
# a millimetre it reads as, and the factor that makes it millimetres.
_TYPED_UNITS = (("metres", "a thousandth", 1000), ("centimetres", "a tenth", 10))


def typed_unit(ratio: float) -> tuple[str, str, int] | None:
    """Of :data:`_TYPED_UNITS`, the unit in which readings ``ratio`` times their drawing's lengths were typed."""
    return _TYPED_UNITS[0] if in_metres(ratio) else _TYPED_UNITS[1] if in_centimetres(ratio) else None


def in_centimetres(ratio: float) -> bool:
    """Whether readings ``ratio`` times their drawing's lengths are those lengths typed in centimetres: a tenth, to
    within a uniform slip's spread (a ruler read in cm; a plan drawn at a tenth of its pole, pa = 8 mm, none draws)."""
    return abs(ratio * 10.0 - 1.0) <= UNIFORM_SLIP_PERCENT / 100.0


def in_units(drawn_at: float) -> bool:
    """Whether readings that agree at a plan scale of ``drawn_at`` (m/s or m/s² a millimetre) are the values
    themselves, typed in their units where a plan's millimetres were asked for: a scale of one unit a millimetre."""
    return abs(drawn_at - 1.0) <= FAR_OFF_PERCENT / 100.0


def _far_off(row: ErrorRow, plan: float, precision: float) -> bool:
    apart = abs(row.plan - plan)
    return apart > FAR_OFF_PERCENT / 100.0 * abs(plan) and apart > FAR_OFF_PRECISIONS * precision * row.per_millimetre


def _plan_of(row: ErrorRow) -> str:
    """The plan a row's quantity is read off: V… and ω off the velocity plan, a… and ε off the acceleration plan."""
    return value_kind(row.quantity)


def value_kind(quantity: str) -> str:
    """The drawing a quantity is read off: ``velocity``, ``acceleration`` or ``forces``."""
    if is_reaction(quantity):
        return "forces"
    return "velocity" if quantity.startswith(("V", "omega")) else "acceleration"


# The unit of the value a segment of each drawing stands for.
_VALUE_UNITS = {"velocity": "m/s", "acceleration": "m/s²", "forces": "N"}


__all__ = ["FAR_OFF_PERCENT", "FAR_OFF_PRECISIONS", "UNIFORM_SLIP_PERCENT", "OnGrid", "OnSheet",
           "Rescaled", "Segment", "SheetPolygons", "SheetsDrawn", "Slips", "factor_text", "in_centimetres", "in_metres",
           "in_units", "misread", "off_the_other_plan", "on_grid", "on_sheet_detail", "read_at", "reads_forces",
           "setting", "sharing", "sheet_of", "slips", "typed_unit", "value_kind"]
