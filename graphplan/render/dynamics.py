"""The dynamics sheet: the diagrams of the equivalent model and the energy–mass diagram of the flywheel.

Laid out as the dynamics sheet of a course project, each diagram at round scales written beside
it.  On the left, over the driver's cycle at μφ: the reduced moments Md(φ) and Mr(φ) at μM; the
works Ad(φ) and Ar(φ) at μA; the change of kinetic energy ΔT(φ) = Ad − Ar at μT.  To the right of
ΔT(φ), sharing its ordinate, Wittenbauer's energy–mass diagram ΔT(Je) at μJ with its two tangents
at ψmax and ψmin (tan ψ = (μJ/μT)·ω²/2) that cut the segment ab off the ΔT axis; below it the
reduced moment of inertia Je(φ) turned through 90°, its abscissa that of the energy–mass diagram,
as the textbook transfers it point by point.  The results of the flywheel are written under the
diagrams.

The layout reads :class:`graphplan.dynamics.EquivalentModel` and :class:`graphplan.flywheel.Flywheel`
and puts what they hold on paper; it computes no mechanics.  Every word, symbol and unit comes from
``text``, the ``dyn_`` keys of a locale (:func:`graphplan.locale.strings`); English when none is given.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import shapely
from shapely.geometry import box
from shapely.geometry.base import BaseGeometry

from ..locale import strings
from ..scales import fit_scale, format_scale
from ..units import RPM
from . import lettering
from .labels import Anchor, broken_under, obstacles_of, place_labels, remembered
from .numerals import number as note_number
from .numerals import short, worked_out
from .primitives import (
    THIN,
    Arrow,
    Circle,
    Layer,
    Polyline,
    Primitive,
    Stroke,
    Text,
    bounds,
    bounds_of,
    dot_marker,
    moved,
    text_extent,
    text_width,
)
from .svg import to_svg

if TYPE_CHECKING:
    # Read, never made here: the dynamics and the flywheel import scipy.integrate, a third of a cold run that
    # every sheet's import of this module's layer names would pay.
    from ..dynamics import EquivalentModel
    from ..flywheel import Flywheel

# The abscissa of a whole cycle (mm): 2°/mm, as the textbook draws it.
ABSCISSA_MM = 180.0
# Heights of the diagrams over the cycle (mm), and the width of the energy–mass diagram.
MOMENTS_MM = 60.0
WORKS_MM = 60.0
ENERGY_MM = 55.0
ENERGY_MASS_MM = 80.0
# Space between the diagrams (mm).
GAP_MM = 24.0
# The heights of the lettering (mm, render/lettering.py): the axes' numbers; the axes' names, the scales, the
# legends and the words on and under the diagrams; each diagram's heading; the drawing's title.
NUMBER = lettering.AXIS_NUMBER
LABEL = lettering.AXIS_LABEL
HEADING = lettering.CAPTION
TITLE = lettering.TITLE
# The drawing's title, laid over the first of the parts a note shows it in.
TITLE_LAYER = "title"
# How far an axis runs past its last tick, to its arrowhead (mm).
AXIS_RUN_MM = 8.0
TICK_MM = 1.2
# The ring round a value read off a velocity plan on the curve of the exact one (mm).
PLAN_RING_MM = 1.2
# An ordinate that starts far from nought (a reduced mass of 6.5 kg and more) is broken as a draftsman breaks it:
# its abscissa stands at nought, a zig-zag crosses the ordinate this high over it, and the values resume above;
# an axis cut off at 6.5 with no mark reads as one that starts at nought, and the curve's swing as a large one.
BREAK_LIFT_MM = 9.0
BREAK_HALF_WIDTH_MM = 1.5
# A tangent of the energy–mass diagram is drawn to the ΔT axis unless its intercept lies further
# than this many heights of the ΔT diagram from its abscissa; then it is cut short of the axis.
INTERCEPT_REACH = 3.0
# A tangent cut short of the axis runs this far (mm) past the curve's band at either end, enough to read its
# angle by: cut at the reach both ways, a steep one (ψ near 90°, a machine whose own Je far outweighs its ΔT)
# stood 8 heights of ΔT tall, a 685 mm drawing no A1 sheet held.
CUT_TANGENT_RUN_MM = 10.0

_DRIVING = Stroke(0.5, "#1f5fa8", (3.0, 1.5))
_RESISTING = Stroke(0.5, "black")
_CURVE = Stroke(0.5, "black")
_TANGENT = Stroke(0.35, "#b22222")
_GRID = Stroke(0.15, "#9a9a9a", (1.0, 1.0))
# The angles of ωmax and ωmin on ΔT(φ), in the colour of the tangents at ψmax and ψmin that the two speeds set.
_SPEED_EXTREME = Stroke(0.35, _TANGENT.colour)
_SPEED_ORDINATE = Stroke(0.2, _TANGENT.colour)
SPEED_TICK_MM = 2.0
# A plan position's point on the energy–mass diagram and the size of its number.
POSITION_DOT_MM = 0.5
POSITION_NUMBER = lettering.CURVE_NUMBER
# How far a letter's tail (ψ, the g of "kg") hangs under its baseline, in cap heights, and the gap kept between a
# tangent's ψ and the Je axis with its name (mm), which the Je axis's numbers keep off the energy–mass diagram's lines
# and ωmax and ωmin off ΔT(φ)'s: the curve's stroke, half a millimetre wide, and paper beyond it.
DESCENT = 0.3
AXIS_WORDS_GAP_MM = 0.6
# How far a diagram's heading stands over its scale's line (mm): the scale's capitals, and paper between them and the
# heading's tails.
HEADING_OVER_SCALE_MM = LABEL + 1.4 + DESCENT * HEADING
# A letter's width (mm): the least gap between two numbers of one axis, and how far a label keeps off an axis's
# numbers.  Nearer, two numbers ran together into one ("0.05 0.075" read as one figure), and a label read as one of
# the numbers (ωmin at φ = 0, hung left of the ΔT axis beside its "0", as the axis's numbering).
NUMBER_GAP_MM = text_width("0", NUMBER)
# How far the field runs past a level line at its edge (mm): ended at the line, the grid's and the
# ordinate's ends made it read as the plot's frame (the engine's Mr = 206.25 N·m along the bottom of its diagram).
LEVEL_MARGIN_MM = 3.0
# The strip beyond a level line at the edge that holds its value under (over) it, where the field inside has no room
# for it: a slider's Fr of 100 N, 5 mm under the abscissa, was led past the travel's numbers to a spot below them.
LEVEL_ROOM_FOR_WORDS_MM = LABEL + 3.0
# A curve runs along an edge when it does so this far (mm): one that only touches it at a peak leaves no line there.
LEVEL_RUN_MM = 10.0


class _Diagram(NamedTuple):
    """A diagram's primitives, and among them the numbers of each of its axes, an axis's apart: told by the axis that
    writes them, not guessed afterwards from the look of a text (figures alone) and its anchor, which any other text of
    figures would pass."""

    items: list[Primitive]
    numberings: list[list[Text]]


@dataclass(frozen=True)
class Scales:
    """Scale factors of the sheet: units per millimetre of paper."""

    angle: float      # μφ, rad/mm (a slider: μs, m/mm)
    moment: float     # μM, N·m/mm (N/mm)
    work: float       # μA, J/mm
    energy: float     # μT, J/mm: the ΔT diagram and the energy–mass diagram
    inertia: float    # μJ, kg·m²/mm (kg/mm)
    # μm, kg/mm, of the reduced mass over a slider's travel (a driver that turns has none); 0: fitted to WORKS_MM.
    mass: float = 0.0
    # μφ, rad/mm, of Je(φ) turned under the energy–mass diagram, which shares its axis of Je with that diagram and
    # nothing with the φ axes beside it: on a big sheet it may run shorter than they do, and let their fields grow
    # (it hung the whole column's height on the cycle's length); 0: the abscissa's μφ.
    turned: float = 0.0

    @property
    def turned_angle(self) -> float:
        """μφ of Je(φ) turned, rad/mm."""
        return self.turned or self.angle


# Drawn larger to fill a big sheet (:func:`larger_layouts`): the abscissa of a cycle at 1.5°/mm and 1°/mm besides
# the usual 2°/mm, and the fields this many times their usual height; Je(φ) turned as long as the abscissa, or as
# long as one of the shorter ones (at 3°/mm the shortest).
LARGER_ABSCISSAE_MM = (360.0, 240.0, ABSCISSA_MM)
LARGER_FIELDS = (2.0, 1.6, 1.3, 1.0)
TURNED_MM = (*LARGER_ABSCISSAE_MM[1:], 120.0)


def scales_for(model: EquivalentModel, abscissa_mm: float = ABSCISSA_MM, fields: float = 1.0,
               turned_mm: float | None = None) -> Scales:
    """Round scales at which each diagram fills its field: the cycle ``abscissa_mm`` long, each field ``fields``
    times its usual height (:data:`MOMENTS_MM`, ...; the energy–mass diagram as many times its width), and Je(φ)
    turned ``turned_mm`` long (as long as the abscissa where not given, or where the drawing has no Je(φ))."""
    angle = _angle_per_mm(model, abscissa_mm)
    turned = 0.0
    if turned_mm is not None and model.turning and not model.inertia_is_constant:
        turned = _angle_per_mm(model, turned_mm)
        turned = 0.0 if turned == angle else turned
    moments = np.concatenate([model.driving, model.resisting])
    works = np.concatenate([model.driving_work, model.resisting_work])
    mass = 0.0 if model.turning else \
        fit_scale(float(np.ptp(model.inertia)) or float(np.max(model.inertia)), WORKS_MM * fields)
    return Scales(angle=angle, moment=fit_scale(_span(moments), MOMENTS_MM * fields),
                  work=fit_scale(_span(works), WORKS_MM * fields), energy=fit_scale(_span(model.energy), ENERGY_MM * fields),
                  inertia=fit_scale(float(np.max(model.inertia)), ENERGY_MASS_MM * fields), mass=mass, turned=turned)


def _angle_per_mm(model: EquivalentModel, length_mm: float) -> float:
    """μφ (rad/mm; a slider's μs, m/mm) at which the cycle, the swing or the travel is about ``length_mm`` long:
    exactly, for a cycle; a round number of degrees (or metres) per millimetre otherwise."""
    if model.turning and model.cyclic:
        return 2.0 * math.pi / length_mm
    if model.turning:
        return math.radians(fit_scale(math.degrees(float(model.coordinate[-1])), length_mm))
    return fit_scale(float(model.coordinate[-1]), length_mm)


def larger_layouts(model: EquivalentModel, flywheel: Flywheel | None = None,
                   text: Mapping[str, str] | None = None) -> list[list[Layer]]:
    """The dynamics sheet (:func:`layout`) drawn larger, for a big sheet with room: on each of
    :data:`LARGER_ABSCISSAE_MM` with the fields each of :data:`LARGER_FIELDS` times as high, but the usual
    size; at round scales, each its own."""
    found: list[list[Layer]] = []
    seen = {scales_for(model)}
    for abscissa in LARGER_ABSCISSAE_MM:
        for fields in LARGER_FIELDS:
            for turned in (abscissa, *(length for length in TURNED_MM if length < abscissa)):
                scales = scales_for(model, abscissa, fields, turned)
                if scales not in seen:
                    seen.add(scales)
                    found.append(layout(model, flywheel, text, scales))
    return found


# Drawn smaller where no sheet of the scene's format holds the usual drawing even diagram by diagram (a V-twin's
# moments, 252 mm wide with their axis's words, on an A4's 251 mm): the cycle at 2.5°, 3° and 4°/mm besides the
# usual 2°/mm, and the fields as high as usual or this many times it.
SMALLER_ABSCISSAE_MM = (ABSCISSA_MM, 144.0, 120.0, 90.0)
SMALLER_FIELDS = (1.0, 0.8, 0.6)


def smaller_layouts(model: EquivalentModel, flywheel: Flywheel | None = None,
                    text: Mapping[str, str] | None = None) -> list[list[Layer]]:
    """The dynamics sheet (:func:`layout`) drawn smaller, for a small sheet that holds no diagram of the usual
    one: on each of :data:`SMALLER_ABSCISSAE_MM` with the fields each of :data:`SMALLER_FIELDS` times as high, but
    the usual size; at round scales, each its own."""
    found: list[list[Layer]] = []
    seen = {scales_for(model)}
    for abscissa in SMALLER_ABSCISSAE_MM:
        for fields in SMALLER_FIELDS:
            scales = scales_for(model, abscissa, fields)
            if scales not in seen:
                seen.add(scales)
                found.append(layout(model, flywheel, text, scales))
    return found


@dataclass(frozen=True)
class Redrawings:
    """The dynamics drawing at scales other than its usual ones, for a sheet: each laid out only when a sheet
    asks, for the usual drawing fills a course sheet of its format and most runs ask for neither."""

    model: EquivalentModel
    flywheel: Flywheel | None = None
    text: Mapping[str, str] | None = None

    def larger(self) -> list[list[Layer]]:
        """:func:`larger_layouts`: for a big sheet with room."""
        return larger_layouts(self.model, self.flywheel, self.text)

    def smaller(self) -> list[list[Layer]]:
        """:func:`smaller_layouts`: for a small sheet that holds none of the usual diagrams."""
        return smaller_layouts(self.model, self.flywheel, self.text)


def dynamics_svg(model: EquivalentModel, flywheel: Flywheel | None = None,
                 text: Mapping[str, str] | None = None) -> str:
    """The SVG text of the dynamics sheet (:func:`layout`)."""
    return to_svg(layout(model, flywheel, text))


def layout(model: EquivalentModel, flywheel: Flywheel | None = None, text: Mapping[str, str] | None = None,
           scales: Scales | None = None) -> list[Layer]:
    """The layers of the dynamics sheet, in paper millimetres (y up)."""
    words = {**strings("en"), **(text or {})}
    scales = scales or scales_for(model)
    x = model.coordinate / scales.angle
    # A slider driver has reduced forces (N) where a crank has reduced moments (N·m).
    moment = ("moment", "moments") if model.turning else ("force", "forces")
    moments = _diagram(x, [(model.driving, _DRIVING, words[f"dyn_driving_{moment[0]}"]),
                           (model.resisting, _RESISTING, words[f"dyn_resisting_{moment[0]}"])],
                       scales.moment, model, words[f"dyn_{moment[0]}_axis"],
                       words[f"dyn_{moment[0]}_scale"].format(value=format_scale(scales.moment)),
                       words[f"dyn_{moment[1]}"], scales, words,
                       levels=[constant_level(model, side, words) for side in ("driving", "resisting")])
    works = _diagram(x, [(model.driving_work, _DRIVING, words["dyn_driving_work"]),
                         (model.resisting_work, _RESISTING, words["dyn_resisting_work"])],
                     scales.work, model, words["dyn_work_axis"],
                     words["dyn_work_scale"].format(value=format_scale(scales.work)), words["dyn_works"], scales, words)
    energy = _diagram(x, [(model.energy, _CURVE, "")], scales.energy, model, words["dyn_energy_axis"],
                      words["dyn_energy_scale"].format(value=format_scale(scales.energy)), words["dyn_energy"], scales,
                      words)
    if flywheel is not None:
        energy.items.extend(_speed_extremes(model, flywheel, scales, energy))
    layers: list[Layer] = []
    bottom = GAP_MM
    for name, items in (("moments", moments.items), ("works", works.items), ("energy", energy.items)):
        dy = bottom - GAP_MM - bounds_of(items)[3]
        layers.append(_layer(name, items, 0.0, dy))
        bottom = bounds_of(layers[-1].items)[1]
    energy_dy = dy
    left_bottom = bottom
    # A constant Je (a flywheel sized from a load diagram alone) makes the energy–mass diagram a
    # vertical segment and Je(φ) a straight line: the ΔT diagram then says all they would.
    if model.turning and not model.inertia_is_constant:
        energy_mass = _energy_mass(model, flywheel, scales, words)
        # Clear of the left column's axis names ("φ, ° from position 1") by a gap, its own numbers included.
        left_column = max(bounds_of(layer.items)[2] for layer in layers)
        right = max(max(ABSCISSA_MM, float(x[-1])) + AXIS_RUN_MM + GAP_MM + 12.0, left_column + GAP_MM - bounds_of(energy_mass)[0])
        layers.append(_layer("energy-mass", energy_mass, right, energy_dy))
        turned = _inertia_turned(model, scales, words)
        low = min(bottom, bounds_of(layers[-1].items)[1])
        layers.append(_layer("inertia", turned, right, low - GAP_MM - bounds_of(turned)[3]))
    elif not model.turning:
        mass_scale = scales.mass or fit_scale(float(np.ptp(model.inertia)) or float(np.max(model.inertia)), WORKS_MM)
        # me read off each velocity plan ringed on the curve of the exact me, as Je is on Je(φ): the note tables both.
        rings = [(_travel(model, plan.driver) / scales.angle, plan.inertia) for plan in model.plans]
        mass = _diagram(x, [(model.inertia, _CURVE, "")], mass_scale, model, words["dyn_mass_axis"],
                        words["dyn_mass_scale"].format(value=format_scale(mass_scale)), words["dyn_mass"], scales,
                        words, floor=True, rings=rings, rings_legend=words["dyn_mass_plans"]).items
        layers.append(_layer("inertia", mass, 0.0, bottom - GAP_MM - bounds_of(mass)[3]))
        left_bottom = bounds_of(layers[-1].items)[1]
    results = _results(model, flywheel, words)
    if results:
        layers.append(_layer("results", results, 0.0, left_bottom - GAP_MM - bounds_of(results)[3]))
    xmin, _, _, ymax = bounds(layers)
    title = words["dyn_title"] if flywheel is not None else words["dyn_title_model"]
    layers.append(Layer(TITLE_LAYER, (Text((xmin, ymax + 8.0), title, TITLE, "start", weight="bold"),)))
    return layers


def headings(layers: Iterable[Layer]) -> tuple[str, ...]:
    """The headings of the diagrams ``layers`` draw, the drawing's title aside: what names a diagram to a reader,
    where its layer's name is an id."""
    return tuple(item.text for layer in layers if layer.name != TITLE_LAYER for item in layer.items
                 if isinstance(item, Text) and item.weight == "bold" and item.size == HEADING)


def _layer(name: str, items: Sequence[Primitive], dx: float, dy: float) -> Layer:
    return Layer(name, tuple(moved(item, dx, dy) for item in items))


def _span(values: np.ndarray) -> float:
    """The height the values need with the abscissa among them."""
    return max(float(np.max(values)), 0.0) - min(float(np.min(values)), 0.0) or 1.0


def constant_level(model: EquivalentModel, side: str, words: Mapping[str, str]) -> str:
    """The words written beside the ``side``'s ("driving" or "resisting") reduced moment (force) where it is the same
    all the run ("Mr = 206.25 N·m", its size as the note gives it, to five digits), else "".  A level line between the
    ticks of a round step (0, 500 on the engine's axis, 0, −1000, −2000 on the press's) has no value to read it by."""
    values = model.driving if side == "driving" else model.resisting
    largest = float(np.max(np.abs(values), initial=0.0))
    if not largest or float(np.ptp(values)) > 1e-9 * largest:
        return ""
    size = model.mean_over_run(values if side == "driving" else -values)
    kind = "moment" if model.turning else "force"
    return words[f"dyn_constant_{side}_{kind}"].format(value=note_number(size))


def _diagram(x: np.ndarray, curves, scale: float, model: EquivalentModel, axis: str, scale_text: str,
             heading: str, scales: Scales, words: Mapping[str, str], floor: bool = False,
             rings: Sequence[tuple[float, float]] = (), rings_legend: str = "", levels: Sequence[str] = (),
             level_room: float = LEVEL_MARGIN_MM) -> _Diagram:
    """A diagram over the cycle with its abscissa at y = 0: curves, axes, ticks, a legend, heading and scale.

    ``floor`` starts the ordinate at a round value under the smallest rather than at zero (a reduced mass far from
    zero), over a break of :data:`BREAK_LIFT_MM` above the abscissa, which stands at nought.
    ``rings`` are (abscissa in mm, value) of values read off the velocity plans, ringed on the curve and named in the
    legend by ``rings_legend``.
    ``levels`` are the words written beside each curve that is a level line ("" for the others): its value, which the
    axis's round ticks seldom give; the field then runs ``level_room`` past such a line at its edge, and further where
    its words find no spot near it.
    """
    values = np.concatenate([c[0] for c in curves])
    base = 0.0
    if floor:  # from a round value under the smallest, so that the abscissa is a tick
        step = nice_step(float(np.ptp(values)) / 4)
        base = math.floor(float(np.min(values)) / step + 1e-9) * step
    lift = BREAK_LIFT_MM if base > 0 else 0.0
    top_mm = (max(float(np.max(values)), base) - base) / scale
    bottom_mm = min(float(np.min(values)) - base, 0.0) / scale
    # The ordinate runs on to the tick under the lowest value where that lies over half a step under the lowest
    # tick, so that every value is read within half a step of a tick: a constant Mr of −71.6 N·m under ticks 0, 100,
    # 200 alone read as a second abscissa.  A dip just under a tick (ΔT of −9 J at steps of 100 J) is read against
    # it, and leaves no strip of empty paper.
    step = _ordinate_step(values, base)
    lowest_tick = math.ceil(bottom_mm * scale / step - 1e-9) * step
    if bottom_mm * scale < lowest_tick - step / 2:
        bottom_mm = (lowest_tick - step) / scale
    # A curve that runs level along the field's edge (a constant moment, the press's Ar once the stroke's work is
    # done) is given a strip beyond it, so that it does not read as the frame the grid's ends draw there.
    for (data, _, _), said in itertools.zip_longest(curves, levels, fillvalue=""):
        y = (np.asarray(data) - base) / scale
        room = level_room if said else LEVEL_MARGIN_MM
        if bottom_mm < 0.0 and _length_along(x, y, bottom_mm) >= LEVEL_RUN_MM:
            bottom_mm -= room
        if top_mm > 0.0 and _length_along(x, y, top_mm) >= LEVEL_RUN_MM:
            top_mm += room
    level_lines = [((float(curve[0][0]) - base) / scale, curve, words_of)
                   for curve, words_of in zip(curves, levels) if words_of]
    width = float(x[-1])
    items, across = _abscissa(model, scales, width, bottom_mm, top_mm + lift, words)
    ordinate, up = _ordinate_axis(0.0, bottom_mm, top_mm, scale, base, axis, step, broken_mm=lift)
    items += ordinate
    for data, stroke, _ in curves:
        y = lift + (np.asarray(data) - base) / scale
        items.append(Polyline(tuple(zip(x.tolist(), y.tolist())), stroke))
    scale_y = top_mm + lift + AXIS_RUN_MM + 3.0
    items.append(Text((0.0, scale_y + HEADING_OVER_SCALE_MM), heading, HEADING, "start", weight="bold"))
    scale_line = f"{scale_text}, {_angle_scale(model, scales.angle, words)}"
    items.append(Text((0.0, scale_y), scale_line, LABEL, "start"))
    # The legend runs on along the scale's line, each curve's stroke before its name.
    cursor = text_width(scale_line, LABEL) + 8.0
    for _, stroke, name in curves:
        if not name:
            continue
        items.append(Polyline(((cursor, scale_y + LABEL / 3), (cursor + 10.0, scale_y + LABEL / 3)), stroke))
        items.append(Text((cursor + 12.0, scale_y), name, LABEL, "start", stroke.colour))
        cursor += 12.0 + text_width(name, LABEL) + 6.0
    if rings:
        items += [Circle((at, lift + (value - base) / scale), PLAN_RING_MM, THIN, None) for at, value in rings]
        items.append(Circle((cursor + PLAN_RING_MM, scale_y + LABEL / 3), PLAN_RING_MM, THIN, None))
        items.append(Text((cursor + 2 * PLAN_RING_MM + 2.0, scale_y), rings_legend, LABEL, "start"))
    if level_lines:
        drawn = [lift + (np.asarray(data) - base) / scale for data, _, _ in curves]
        items, led = _levels_written(items, [(lift + at, curve[1].colour, said) for at, curve, said in level_lines],
                                     x, drawn, [across, up])
        if led and level_room < LEVEL_ROOM_FOR_WORDS_MM:
            return _diagram(x, curves, scale, model, axis, scale_text, heading, scales, words, floor, rings,
                            rings_legend, levels, LEVEL_ROOM_FOR_WORDS_MM)
    return _Diagram(items, [across, up])


def _length_along(x: np.ndarray, y: np.ndarray, edge: float) -> float:
    """How far (mm of abscissa) the polyline through ``x``, ``y`` runs along the level ``edge``."""
    on = np.abs(y - edge) < 1e-6 * max(abs(edge), 1.0)
    return float(np.sum(np.diff(x)[on[:-1] & on[1:]]))


def _levels_written(items: list[Primitive], levels: Sequence[tuple[float, str, str]], x: np.ndarray,
                    curves: Sequence[np.ndarray], numberings: Sequence[Sequence[Text]]) -> tuple[list[Primitive], bool]:
    """``items`` with each level line's words (its height in mm, colour, words) written beside it, anywhere along it,
    clear of the curves, the axes and their numbers, the legend and each other; the grid, a dotted guide to the
    eye, is broken under them rather than kept clear of, which no spot a line's value is long between its lines was.
    And whether any of them had to be led to a spot away from its line.  Each is first tried over the stretch of
    its line the other ``curves`` (their heights at ``x``) keep farthest from: set in the middle of the run, the
    engine's Mr stood wedged under the corner of Md's dip at 180°, with the open half of the run beside it."""
    width = float(x[-1])
    grid = [item for item in items if isinstance(item, Polyline) and item.stroke == _GRID]
    solid = [item for item in items if not any(item is line for line in grid)]
    # The axes kept off by the gap ωmax and ωmin keep: a value hugging the ordinate reads as one of its numbers.
    axes = [shapely.buffer(shapely.linestrings(item.points if isinstance(item, Polyline) else (item.start, item.end)),
                           AXIS_WORDS_GAP_MM)
            for item in solid if isinstance(item, (Arrow, Polyline)) and item.stroke == THIN]
    anchors = [Anchor((_most_open(x, curves, at, text_width(said, LABEL)), at), said, LABEL, math.pi / 2, colour,
                      along=((0.0, at), (width, at))) for at, colour, said in levels]
    placed = remembered(place_labels, anchors, obstacles_of(solid) + _numbering(numberings) + axes)
    drawn = broken_under(items, list(placed.texts), grid) + list(placed.leaders) + list(placed.texts)
    return drawn, bool(placed.leaders)


def _most_open(x: np.ndarray, curves: Sequence[np.ndarray], level: float, length: float) -> float:
    """The abscissa (mm) of the middle of the stretch ``length`` long, within the run, over which the ``curves`` other
    than the level line at ``level`` come least near it; of stretches alike, the one nearest the run's middle."""
    width = float(x[-1])
    others = [y for y in curves if not np.allclose(y, level)]
    half = min(length / 2 + 2.0, width / 2)
    middles = np.linspace(half, width - half, max(2, int(width - 2 * half) + 1))
    if not others:
        return width / 2
    # Each curve's distance from the level at every millimetre, then the nearest within each stretch.
    grid = np.linspace(0.0, width, int(width) + 1)
    distance = np.min([np.abs(np.interp(grid, x, y) - level) for y in others], axis=0)
    clearance = np.array([np.min(distance[(grid >= middle - half) & (grid <= middle + half)]) for middle in middles])
    best = np.flatnonzero(clearance >= np.max(clearance) - 0.5)
    return float(middles[best[np.argmin(np.abs(middles[best] - width / 2))]])


def _ordinate_step(values: np.ndarray, base: float = 0.0) -> float:
    """The round step of a diagram's ordinate numbers: about a quarter of the span from ``base`` (nought, or a reduced
    mass's round floor) to the values, that base among them."""
    top = max(float(np.max(values)), base) - base
    bottom = min(float(np.min(values)) - base, 0.0)
    return nice_step((top - bottom) / 4)


def _abscissa(model: EquivalentModel, scales: Scales, width: float, bottom_mm: float, top_mm: float,
              words: Mapping[str, str]) -> tuple[list[Primitive], list[Text]]:
    """The φ axis at y = 0 (its arrow past the cycle), with a thin grid and the ticks' values under the diagram; and
    those values' texts apart."""
    items: list[Primitive] = [Arrow((0.0, 0.0), (width + AXIS_RUN_MM, 0.0), THIN, head=2.5)]
    numbers: list[Text] = []
    if model.turning:
        ticks = [(psi / scales.angle, label) for psi, label in _angle_ticks(model)]
        name = words["dyn_angle_axis"]
    else:
        travel = float(model.coordinate[-1])
        step = nice_step(travel / 5)
        ticks = [(v / scales.angle, short(v)) for v in np.arange(0.0, travel * (1 + 1e-9), step)]
        name = words["dyn_travel_axis"]
    for at, label in ticks:
        if at > 0:
            items.append(Polyline(((at, bottom_mm), (at, top_mm)), _GRID))
        items.append(Polyline(((at, -TICK_MM), (at, TICK_MM)), THIN))
        numbers.append(Text((at, bottom_mm - NUMBER - 2.5), label, NUMBER, "middle"))
        items.append(numbers[-1])
    items.append(Text((width + AXIS_RUN_MM + 1.5, -LABEL / 2), name, LABEL, "start"))
    return items, numbers


def _speed_extremes(model: EquivalentModel, flywheel: Flywheel, scales: Scales, diagram: _Diagram) -> list[Primitive]:
    """The crank angles of ωmax and ωmin on ΔT(φ): a tick across the φ axis, named, and a thin ordinate from it to
    the curve, as a course project marks them.  With Je varying they need not lie at the extremes of ΔT."""
    drawn = diagram.items
    items: list[Primitive] = []
    anchors: list[Anchor] = []
    for name, index in (("ωmax", flywheel.index_max), ("ωmin", flywheel.index_min)):
        x = float(model.coordinate[index]) / scales.angle
        y = float(model.energy[index]) / scales.energy
        items.append(Polyline(((x, 0.0), (x, y)), _SPEED_ORDINATE))
        items.append(Polyline(((x, -SPEED_TICK_MM), (x, SPEED_TICK_MM)), _SPEED_EXTREME))
        items.append(dot_marker((x, y), 0.6, _SPEED_EXTREME.colour))
        # Named on the side of the axis away from the curve there, where its ordinate does not run; lettered as the
        # axis's numbers are, a tick of which it names.
        anchors.append(Anchor((x, 0.0), name, NUMBER, -math.pi / 3 if y > 0 else math.pi / 3, _SPEED_EXTREME.colour))
    # Kept off the axes too, by the gap a tangent's ψ keeps off the Je axis: hugging the φ axis among its ticks, the
    # shaper's ωmin stood 0.16 mm from the 210° tick and the compressor's 0.15 mm from the 180° grid line.
    axes = [shapely.buffer(shapely.linestrings((item.start, item.end)), AXIS_WORDS_GAP_MM)
            for item in drawn if isinstance(item, Arrow)]
    # And off every line by as much, the axes' ticks, the grid and their own ticks and ordinates: lettered 2.5 mm
    # high, ωmin found the compressor's spot over its tick too tight and hugged its ordinate under the axis 0.1 mm
    # off it.
    marks = [shapely.buffer(shapely.linestrings(item.points), AXIS_WORDS_GAP_MM)
             for item in [*drawn, *items] if isinstance(item, Polyline)]
    placed = remembered(place_labels, anchors,
                        obstacles_of([*drawn, *items]) + _numbering(diagram.numberings) + axes + marks)
    return items + list(placed.leaders) + list(placed.texts)


def _numbering(numberings: Sequence[Sequence[Text]]) -> list[BaseGeometry]:
    """The bands the axes' numbers stand in, one an axis, each a letter's width wider every way: an ordinate's column
    of numbers from the lowest to the highest, an abscissa's row from the first to the last.  A label anywhere in such
    a band, between two numbers too, reads as one of them."""
    bands = []
    for numbers in numberings:
        if not numbers:
            continue
        x0s, y0s, x1s, y1s = zip(*(text_extent(number) for number in numbers))
        bands.append(shapely.box(min(x0s) - NUMBER_GAP_MM, min(y0s) - NUMBER_GAP_MM,
                                 max(x1s) + NUMBER_GAP_MM, max(y1s) + NUMBER_GAP_MM))
    return bands


def ordinate_axis(x: float, bottom_mm: float, top_mm: float, scale: float, base: float, name: str,
                  step: float | None = None, broken_mm: float = 0.0) -> list[Primitive]:
    """A vertical axis at ``x`` from the lowest value to past the highest, ticked at round values (``step``, by
    default about a quarter of the range).  ``base`` stands at ``broken_mm`` over the abscissa (``bottom_mm`` and
    ``top_mm`` are counted from it); where that is above it, the abscissa is nought, ticked so, and the axis is
    broken between them by a zig-zag."""
    return _ordinate_axis(x, bottom_mm, top_mm, scale, base, name, step, broken_mm)[0]


def _ordinate_axis(x: float, bottom_mm: float, top_mm: float, scale: float, base: float, name: str,
                   step: float | None = None, broken_mm: float = 0.0) -> tuple[list[Primitive], list[Text]]:
    """:func:`ordinate_axis`, and its numbers' texts apart."""
    items: list[Primitive] = [Polyline(((x, bottom_mm + broken_mm), (x, broken_mm)), THIN),
                              Arrow((x, broken_mm), (x, top_mm + broken_mm + AXIS_RUN_MM), THIN, head=2.5)]
    numbers: list[Text] = []
    if broken_mm > 0:
        lines, nought = _break_mark(x, broken_mm)
        items += [*lines, nought]
        numbers.append(nought)
    low, high = base + bottom_mm * scale, base + top_mm * scale
    step = step or nice_step((high - low) / 4)
    first = math.ceil(low / step - 1e-9) * step
    for value in np.arange(first, high + step * 1e-9, step):
        at = broken_mm + (value - base) / scale
        items.append(Polyline(((x - TICK_MM, at), (x, at)), THIN))
        numbers.append(Text((x - TICK_MM - 1.0, at - NUMBER / 2), short(value), NUMBER, "end"))
        items.append(numbers[-1])
    items.append(Text((x + 2.0, top_mm + broken_mm + AXIS_RUN_MM - LABEL), name, LABEL, "start"))
    return items, numbers


def _break_mark(x: float, lift: float) -> tuple[list[Primitive], Text]:
    """The axis from nought at the abscissa up to ``lift``, where its values resume, with a zig-zag halfway across
    it: the values between are left out, as a draftsman marks it; nought ticked, and its number apart."""
    middle = lift / 2
    w = BREAK_HALF_WIDTH_MM
    zigzag = ((x, middle - w), (x - w, middle - w / 2), (x + w, middle + w / 2), (x, middle + w))
    lines: list[Primitive] = [Polyline(((x, 0.0), zigzag[0]), THIN), Polyline(zigzag, THIN),
                              Polyline((zigzag[-1], (x, lift)), THIN), Polyline(((x - TICK_MM, 0.0), (x, 0.0)), THIN)]
    return lines, Text((x - TICK_MM - 1.0, -NUMBER / 2), short(0.0), NUMBER, "end")


def _energy_mass(model: EquivalentModel, flywheel: Flywheel | None, scales: Scales,
                 words: Mapping[str, str]) -> list[Primitive]:
    """ΔT over Je (origin at Je = 0, ΔT = 0), the tangents at ψmax, ψmin and the segment ab they cut off."""
    xs = model.inertia / scales.inertia
    ys = model.energy / scales.energy
    # A cycle closes on itself; a swing or a travel run once ends elsewhere, and a chord back would be a false arc.
    curve_line = Polyline(tuple(zip(xs.tolist(), ys.tolist())), _CURVE, closed=model.cyclic)
    items: list[Primitive] = [curve_line]
    tangents: list[Polyline] = []
    top_mm, bottom_mm = float(np.max(ys)), float(np.min(ys))
    curve = (bottom_mm - CUT_TANGENT_RUN_MM, top_mm + CUT_TANGENT_RUN_MM)
    width = float(np.max(xs))
    if flywheel is not None:
        reach = INTERCEPT_REACH * max(top_mm - bottom_mm, 1.0)
        written: list[float] = []   # the baselines of the ψ written so far
        for tangent, letter, name in ((flywheel.upper, "a", "ψmax"), (flywheel.lower, "b", "ψmin")):
            slope = tangent.slope * scales.inertia / scales.energy   # tan ψ on the paper
            touch = (float(xs[tangent.touch]), float(ys[tangent.touch]))
            intercept = tangent.intercept / scales.energy
            # A steep tangent (a fast machine: tan ψ grows as ωm²) whose intercept lies beyond the reach is drawn
            # only across the band of the curve and a little beyond; run to the axis it was metres long.
            band = reach + max(abs(top_mm), abs(bottom_mm))
            low, high = (-band, band) if abs(intercept) <= band else curve
            start_x, end_x = 0.0, width + 4.0
            if slope:
                ends = sorted(((low - intercept) / slope, (high - intercept) / slope))
                start_x, end_x = max(start_x, ends[0]), min(end_x, ends[1])
            line = ((start_x, intercept + slope * start_x), (end_x, intercept + slope * end_x))
            tangents.append(Polyline(line, _TANGENT))
            items.append(tangents[-1])
            items.append(dot_marker(touch, 0.7, _TANGENT.colour))
            angle = math.degrees(math.atan(slope))
            baseline = _off_the_inertia_axis(line[1][1], written)
            written.append(baseline)
            items.append(Text((end_x + 1.0, baseline), f"{name} = {angle:.2f}°", LABEL, "start", _TANGENT.colour))
            if start_x == 0.0:
                items.append(dot_marker((0.0, intercept), 0.7, _TANGENT.colour))
                # Above a's tangent and below b's over the letter's whole width: set off the intercept alone, a
                # steep tangent (ψ of 30° and more, a fast machine's) ran through the letter it names.
                # Only as far as the tangent is drawn: past its end there is no line to clear, and a tangent all
                # but upright (a machine's own Je far beyond the flywheel's) set the letter kilometres up.
                rise = slope * min(1.2 + text_width(letter, LABEL), end_x)
                letter_y = intercept + max(rise, 0.0) + 1.2 if letter == "a" else intercept + min(rise, 0.0) - LABEL - 1.2
                items.append(Text((1.2, letter_y), letter, LABEL, "start", _TANGENT.colour))
            top_mm, bottom_mm = max(top_mm, line[0][1], line[1][1]), min(bottom_mm, line[0][1], line[1][1])
        ab = (flywheel.upper.intercept - flywheel.lower.intercept) / scales.energy
        # ab ≤ 0 is a flywheel of negative inertia, which the machine's own spares: said so, not as a length.
        told = words["dyn_segment"].format(value=f"{ab:.1f}") if flywheel.inertia > 0 else words["dyn_segment_none"]
        items.append(Text((width / 2, bottom_mm - 2 * LABEL - 2.0), told, LABEL, "middle", _TANGENT.colour))
    # Je graduated as on Je(φ) under it; lettered on the side of the axis where fewer of the diagram's lines and
    # words run through its numbers, and of two alike the side the curve comes less near.  A number struck through
    # there stands clear on the other side, or beside its tick, where it can.  Where no spot by its tick is clear (a
    # steep tangent, a fast machine's, crossing the axis at the tick itself), it keeps a spot only a tangent runs
    # through, and the tangent is broken under it, as ГОСТ 2.307 breaks a line under a dimension's number; the curve
    # too, last of all.  Left out, as it was, the axis read 0.025, ·, 0.075 under a scale that says nothing of a gap.
    # Each item's shapes kept with it (an arrow has two), so that the lines a number may stand over are left out
    # of what was drawn by the items they come of.
    shaped = [(item, obstacles_of([item])) for item in items]

    def shapes_but(left_out: Sequence[Primitive]) -> list[BaseGeometry]:
        return [shape for item, shapes in shaped if not any(item is line for line in left_out) for shape in shapes]

    drawn = shapes_but(())
    beside_the_tangents = shapes_but(tangents)
    beside_the_lines = shapes_but([*tangents, curve_line])
    near = NUMBER + TICK_MM + 2.0
    every_tick = _inertia_ticks(model, scales)
    ticks = [(value, at) for value, at, numbered in every_tick if numbered]

    def struck(number: Text, shapes: Sequence[BaseGeometry]) -> bool:
        # The lines are their middles: a number clear of the curve's middle alone had its half-millimetre stroke
        # through the foot of its first figure (the triad's 0.02, 0.24 mm off, lettered 2.5 mm high).
        ink = _ink(number).buffer(AXIS_WORDS_GAP_MM, join_style="mitre")
        return any(ink.intersects(shape) for shape in shapes)

    sides = []
    for letter_y, crowd in ((TICK_MM + 1.0, (ys > 0) & (ys < near)), (-TICK_MM - 1.0 - NUMBER, (ys < 0) & (ys > -near))):
        struck_here = sum(struck(Text((at, letter_y), short(value), NUMBER, "middle"), drawn) for value, at in ticks)
        sides.append((struck_here, int(np.count_nonzero(crowd)), letter_y))
    (_, _, letter_y), (_, _, other_y) = sorted(sides)
    items += ordinate_axis(0.0, min(bottom_mm, 0.0), max(top_mm, 0.0), scales.energy, 0.0, words["dyn_energy_axis"],
                           _ordinate_step(model.energy))
    # Past the curve and past its last tick, which a coarser step may carry beyond the curve.
    axis_to = max(width, every_tick[-1][1])
    items.append(Arrow((0.0, 0.0), (axis_to + AXIS_RUN_MM + 12.0, 0.0), THIN, head=2.5))
    numbers: list[Text] = []
    over_tangents: list[Text] = []
    over_lines: list[Text] = []
    for k, (value, at) in enumerate(ticks):
        spots = [(at, letter_y, "middle"), (at, other_y, "middle"), (at - 0.5, letter_y, "end"),
                 (at + 0.5, letter_y, "start"), (at - 0.5, other_y, "end"), (at + 0.5, other_y, "start")]
        # Clear of the lines, and a letter's width clear of the numbers set already and of the next one's usual spot.
        others = [_ink(number).buffer(NUMBER_GAP_MM, join_style="mitre") for number in numbers]
        if k + 1 < len(ticks):
            others.append(_ink(Text((ticks[k + 1][1], letter_y), short(ticks[k + 1][0]), NUMBER, "middle"))
                          .buffer(NUMBER_GAP_MM, join_style="mitre"))
        candidates = [Text((x, y), short(value), NUMBER, anchor) for x, y, anchor in spots]
        number = None
        for shapes, breaking in ((drawn, None), (beside_the_tangents, over_tangents), (beside_the_lines, over_lines)):
            number = next((text for text in candidates if not struck(text, shapes)
                           and not any(_ink(text).intersects(shape) for shape in others)), None)
            if number is not None:
                if breaking is not None:
                    breaking.append(number)
                break
        if number is None:   # a spot every way crowded by words: its usual one, the lines broken under it
            number = candidates[0]
            over_lines.append(number)
        numbers.append(number)
    items = broken_under(items, over_tangents + over_lines, tangents)
    items = broken_under(items, over_lines, [item for item in items if item is curve_line])
    items += [Polyline(((at, -TICK_MM), (at, TICK_MM)), THIN) for _, at, _ in every_tick]
    items += numbers
    items.append(Text((axis_to + AXIS_RUN_MM + 13.5, -LABEL / 2), words["dyn_inertia_axis"], LABEL, "start"))
    scale_y = max(top_mm, 0.0) + AXIS_RUN_MM + 3.0
    items.append(Text((0.0, scale_y + HEADING_OVER_SCALE_MM), words["dyn_energy_mass"], HEADING, "start", weight="bold"))
    items.append(Text((0.0, scale_y), f"{words['dyn_inertia_scale'].format(value=format_scale(scales.inertia))}, "
                                      f"{words['dyn_energy_scale'].format(value=format_scale(scales.energy))}",
                      LABEL, "start"))
    return items + _numbered_positions(model, scales, items)


def _off_the_inertia_axis(end_y: float, written: Sequence[float] = ()) -> float:
    """The baseline of a tangent's ψ, written level with the tangent's end unless that puts it on the Je axis, which
    runs on under it to its arrowhead and name: a tangent ending near ΔT = 0 (a small intercept, a shallow slope) had
    its "ψmax = 1.88°" struck through by the axis and run into "Je, kg·m²"; there it stands just above the axis, or
    just below it where the tangent ends under it, or where the other ψ, at ``written``, stands above it already."""
    baseline = end_y - LABEL / 2
    descent = DESCENT * LABEL    # ψ's tail under its baseline, as the g of "kg" hangs under the axis's name
    above = LABEL / 2 + AXIS_WORDS_GAP_MM
    below = -LABEL / 2 - descent - AXIS_WORDS_GAP_MM
    if baseline - descent >= above or baseline + LABEL <= below:
        return baseline
    over, under = above + descent, below - LABEL
    taken = any(abs(other - over) < LABEL + descent + AXIS_WORDS_GAP_MM for other in written)
    return over if end_y >= 0.0 and not taken else under


def _numbered_positions(model: EquivalentModel, scales: Scales, drawn: Sequence[Primitive]) -> list[Primitive]:
    """The plan positions' points on the energy–mass diagram, each a dot numbered as the position is: (Je, ΔT) of
    the exact curve at the position's angle, so that the diagram is read against the plans as ΔT(φ) and Je(φ) are."""
    plans = {plan.number: plan for plan in model.plans}
    if not plans:
        return []
    points = []
    for number, plan in sorted(plans.items()):
        energy = float(np.interp(_travel(model, plan.driver), model.coordinate, model.energy))
        points.append((number, (plan.inertia_exact / scales.inertia, energy / scales.energy)))
    dots: list[Primitive] = [dot_marker(at, POSITION_DOT_MM) for _, at in points]
    # Each number away from the middle of the loop, where the tangents' letters and the other numbers crowd.
    middle = np.mean([at for _, at in points], axis=0)
    anchors = [Anchor(at, str(number), POSITION_NUMBER, math.atan2(at[1] - middle[1], at[0] - middle[0]))
               for number, at in points]
    placed = remembered(place_labels, anchors, obstacles_of([*drawn, *dots]))
    return dots + list(placed.leaders) + list(placed.texts)


def _inertia_turned(model: EquivalentModel, scales: Scales, words: Mapping[str, str]) -> list[Primitive]:
    """Je(φ) with Je across (the energy–mass diagram's abscissa) and φ running down from y = 0."""
    xs = model.inertia / scales.inertia
    angle = scales.turned_angle
    ys = -model.coordinate / angle
    width = float(np.max(xs))
    items: list[Primitive] = [Polyline(tuple(zip(xs.tolist(), ys.tolist())), _CURVE)]
    length = float(-ys[-1])
    items.append(Arrow((0.0, 0.0), (0.0, -length - AXIS_RUN_MM), THIN, head=2.5))
    items.append(Text((1.5, -length - AXIS_RUN_MM - LABEL), words["dyn_angle_axis"], LABEL, "start"))
    for psi, label in _angle_ticks(model):
        at = -psi / angle
        items.append(Polyline(((-TICK_MM, at), (TICK_MM, at)), THIN))
        items.append(Text((-TICK_MM - 1.0, at - NUMBER / 2), label, NUMBER, "end"))
    ticks = _inertia_ticks(model, scales)
    # Past the curve and past its last tick, which a coarser step may carry beyond the curve.
    axis_to = max(width, ticks[-1][1])
    items.append(Arrow((0.0, 0.0), (axis_to + AXIS_RUN_MM + 12.0, 0.0), THIN, head=2.5))
    for value, at, numbered in ticks:
        items.append(Polyline(((at, -TICK_MM), (at, TICK_MM)), THIN))
        if numbered:
            items.append(Text((at, TICK_MM + 1.0), short(value), NUMBER, "middle"))
    items.append(Text((axis_to + AXIS_RUN_MM + 13.5, -LABEL / 2), words["dyn_inertia_axis"], LABEL, "start"))
    # Headed above its Je axis's lettering, as the other diagrams are above theirs.
    scale_y = TICK_MM + 1.0 + NUMBER + 2.5
    if model.plans:
        # Je read off each position's velocity plan, ringed on the curve of the exact Je: the two methods side
        # by side; the legend on a line of its own under the scale, so that the diagram grows no wider.
        items += [Circle((plan.inertia / scales.inertia, -_travel(model, plan.driver) / angle), PLAN_RING_MM,
                         THIN, None) for plan in model.plans]
        items.append(Circle((PLAN_RING_MM, scale_y + LABEL / 3), PLAN_RING_MM, THIN, None))
        items.append(Text((2 * PLAN_RING_MM + 2.0, scale_y), words["dyn_inertia_plans"], LABEL, "start"))
        scale_y += LABEL + 2.0
    items.append(Text((0.0, scale_y + HEADING_OVER_SCALE_MM), words["dyn_inertia"], HEADING, "start", weight="bold"))
    items.append(Text((0.0, scale_y), f"{words['dyn_inertia_scale'].format(value=format_scale(scales.inertia))}, "
                                      f"{_angle_scale(model, angle, words)}", LABEL, "start"))
    return items


def _travel(model: EquivalentModel, driver: float) -> float:
    """ψ of a driver position: its travel from the model's first sample in the driver's sense (within a turn)."""
    travel = model.sense * (driver - float(model.driver[0]))
    return travel % (2.0 * math.pi) if model.cyclic else travel


def _ink(number: Text):
    """The box a number's figures cover: from its baseline to its cap height (figures have neither descenders nor
    accents, which :func:`~graphplan.render.labels.text_box` allows for), as wide as it is written."""
    x0, _, x1, _ = text_extent(number)
    return box(x0, number.at[1], x1, number.at[1] + number.size)


def _inertia_ticks(model: EquivalentModel, scales: Scales) -> list[tuple[float, float, bool]]:
    """(Je, its abscissa in mm, whether it is numbered) of the ticks of Je: round steps, about four to the largest
    Je, on along the axis as far as it runs past the curve (:data:`AXIS_RUN_MM`): the Whitworth mechanism's Je of
    1.45 kg·m² ran 22 mm past its last tick, 1, under an axis drawn bare to 2.3.  Every one numbered where the
    numbers stand a letter's width apart (:data:`NUMBER_GAP_MM`) at that step, else every second (third, ...) one,
    at the multiples of that many steps, as the kinematic diagrams number their positions: 0.05 and 0.075 twelve
    millimetres apart at μJ = 0.002 ran together.

    Where that leaves fewer than two numbers, the ticks go to the coarsest step of the 1-2-5 series that needs no
    thinning, every one numbered, carried past the largest Je to a second tick where the curve stops short of it: one
    number alone (0.05 between bare ticks at 0.025 and 0.075, the compressor's) gives no scale to read the axis by."""
    largest = float(np.max(model.inertia))
    step = nice_step(largest / 4)
    axis_run = largest + AXIS_RUN_MM * scales.inertia
    values = [float(value) for value in np.arange(step, axis_run + step * 1e-9, step)]
    every = _numbered_every(values, step, scales.inertia)
    ticks = [(value, value / scales.inertia, round(value / step) % every == 0) for value in values]
    if sum(numbered for _, _, numbered in ticks) >= 2:
        return ticks
    while True:
        step = _coarser(step)
        count = max(2, math.floor(largest / step + 1e-9))
        values = [k * step for k in range(1, count + 1)]
        if _numbered_every(values, step, scales.inertia) == 1:
            return [(value, value / scales.inertia, True) for value in values]


def _numbered_every(values: Sequence[float], step: float, scale: float) -> int:
    """How many ticks at ``step`` apart (``scale`` a unit per mm) each number of ``values`` written centred on its
    tick takes so as to stand a letter's width (:data:`NUMBER_GAP_MM`) from its neighbour's: 1, or 2 for every other
    tick, ..."""
    halves = [text_width(short(value), NUMBER) / 2 for value in values]
    # Two neighbours' numbers, each centred on its tick, need half of each one's width and the gap between the ticks.
    needed = max((sum(pair) + NUMBER_GAP_MM for pair in itertools.pairwise(halves)), default=0.0)
    return max(1, math.ceil(needed / (step / scale) - 1e-9))


def _coarser(step: float) -> float:
    """The next step of the 1-2-5 series above ``step``: 0.05 after 0.025 or 0.02, 0.1 after 0.05."""
    power = 10.0 ** math.floor(math.log10(step) + 1e-9)
    return next(mantissa * power for mantissa in (1.0, 2.0, 5.0, 10.0) if mantissa * power > step * (1 + 1e-9))


def _angle_ticks(model: EquivalentModel) -> list[tuple[float, str]]:
    """(ψ in rad, its label in degrees) of the angle's ticks: every 30° of a turn, round steps over a swing."""
    if model.cyclic:
        return [(math.radians(degrees), f"{degrees}") for degrees in range(0, 361, 30)]
    span = math.degrees(float(model.coordinate[-1]))
    return [(math.radians(degrees), short(degrees))
            for degrees in np.arange(0.0, span * (1 + 1e-9), nice_step(span / 6))]


def _angle_scale(model: EquivalentModel, angle: float, words: Mapping[str, str]) -> str:
    """The scale line of a φ axis drawn at ``angle`` (rad/mm; a slider's travel, m/mm)."""
    if model.turning:
        return words["dyn_angle_scale"].format(degrees=short(math.degrees(angle), 4), radians=short(angle, 4))
    return words["dyn_travel_scale"].format(value=format_scale(angle))


class FlywheelNumbers(NamedTuple):
    """The flywheel's numbers as the drawing's results and the note both write them, with a decimal point.

    Written once, here, so that a reader who compares the two finds the same digits: the drawing wrote JF′ to
    four (0.3881) beside the note's five (0.38808).  A result worked out keeps its trailing noughts
    (:func:`~graphplan.render.numerals.worked_out`: ωmin = 10.210 beside ωmax = 10.734); a value the scene gives
    (δ, ωm and its rpm, the other shaft's n′) and an angle of the cycle are written short, as typed (δ = 0.05).
    """

    delta: str
    omega_mean: str
    rpm: str
    delta_w_max: str
    required: str
    approximate: str
    mertsalov: str
    omega_max: str
    omega_min: str
    angle_max: str
    angle_min: str
    # None where the scene names no other shaft.
    shaft_rpm: str | None
    moved: str | None


def flywheel_numbers(model: EquivalentModel, flywheel: Flywheel) -> FlywheelNumbers:
    """The numbers of ``flywheel`` the dynamics drawing's results and the note's flywheel both write."""
    def angle(index: int) -> str:
        return short(math.degrees(model.driver[index]) % 360.0, 4)

    other_shaft = flywheel.moved is not None and flywheel.shaft_rpm is not None
    return FlywheelNumbers(
        delta=short(flywheel.delta, 5), omega_mean=short(flywheel.omega_mean, 5),
        rpm=short(flywheel.omega_mean / RPM, 5), delta_w_max=worked_out(flywheel.delta_w_max),
        required=worked_out(flywheel.required), approximate=worked_out(flywheel.approximate),
        mertsalov=worked_out(flywheel.mertsalov), omega_max=worked_out(flywheel.omega[flywheel.index_max]),
        omega_min=worked_out(flywheel.omega[flywheel.index_min]), angle_max=angle(flywheel.index_max),
        angle_min=angle(flywheel.index_min),
        # The speed as the scene gives it: 1462.5 rpm, which four digits drew as 1462 beside the note's 1462.5.
        shaft_rpm=short(flywheel.shaft_rpm, 6) if other_shaft else None,
        moved=worked_out(flywheel.moved) if other_shaft else None)


def _results(model: EquivalentModel, flywheel: Flywheel | None, words: Mapping[str, str]) -> list[Primitive]:
    if flywheel is None:
        return []
    numbers = flywheel_numbers(model, flywheel)
    lines = [
        words["dyn_delta"].format(delta=numbers.delta, omega=numbers.omega_mean, rpm=numbers.rpm),
        words["dyn_delta_w_max"].format(value=numbers.delta_w_max),
    ]
    if model.inertia_is_constant:
        constant = "dyn_exact_no_inertia" if model.inertia_is_nought else "dyn_exact_constant"
        lines.append(words[constant].format(value=numbers.required))
    else:
        lines += [words["dyn_exact"].format(value=numbers.required),
                  words["dyn_approximate"].format(value=numbers.approximate),
                  words["dyn_mertsalov"].format(value=numbers.mertsalov,
                                                constant=short(flywheel.constant_inertia, 4))]
    if numbers.moved is not None:
        lines.append(words["dyn_moved"].format(rpm=numbers.shaft_rpm, value=numbers.moved))
    for key, index, value, angle in (("dyn_omega_max", flywheel.index_max, numbers.omega_max, numbers.angle_max),
                                     ("dyn_omega_min", flywheel.index_min, numbers.omega_min, numbers.angle_min)):
        travel = short(math.degrees(model.coordinate[index]), 4)
        # A cycle that starts at 0° (a load diagram's, a crank's from 0°) has the two angles alike: said once.
        into = words["dyn_into_cycle"].format(travel=travel) if travel != angle else ""
        lines.append(words[key].format(value=value, angle=angle, into=into))
    if flywheel.inertia <= 0:
        lines.append(words["dyn_no_flywheel"])
    items: list[Primitive] = [Text((0.0, 0.0), words["dyn_results"], HEADING, "start", weight="bold")]
    for k, line in enumerate(lines, start=1):
        items.append(Text((0.0, -k * 1.7 * LABEL - 2.0), line, LABEL, "start"))
    return items


def nice_step(rough: float) -> float:
    """A round step (1, 2, 2.5, 5 × 10ⁿ) at least ``rough``."""
    if not rough > 0:
        return 1.0
    power = 10.0 ** math.floor(math.log10(rough))
    for mantissa in (1.0, 2.0, 2.5, 5.0, 10.0):
        if mantissa * power >= rough * (1 - 1e-9):
            return mantissa * power
    return 10.0 * power


__all__ = ["FlywheelNumbers", "Redrawings", "Scales", "dynamics_svg", "flywheel_numbers", "larger_layouts", "layout",
           "nice_step", "ordinate_axis", "scales_for", "smaller_layouts"]
