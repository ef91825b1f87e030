"""Each drawing of a run, as SVG text: the layout of its record, written by the backend."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping, Sequence

import numpy as np

from ..analysis import VELOCITY_PLANS_FIELD_MM, Analysis, PlanPosition, VelocityPosition, instant
from ..errors import SceneError
from ..forces import POLYGON_FIELD_MM, GroupForces, polygon_extent
from ..kinematics import at
from ..length_units import mixed_units, refused_at_slip
from ..locale import strings
from ..memo import OwnedMemo
from ..plans import PLAN_FIELD_MM, Plan, acceleration_plan, spread, velocity_plan
from ..positions import working_speed
from ..scales import (
    LARGEST_PAPER_MM,
    finer_standard_scale,
    fit_scale,
    format_scale,
    next_standard_scale,
    standard_scale,
)
from ..scene import Working
from ..statics import efficiency, rounded_zero
from ..unit_slips import velocity_slip_hint
from ..wording import raised
from . import force_lever, plans, positions, velocity_plans
from . import forces as force_layout
from .formats import holds
from .numerals import scale_factor
from .primitives import Layer, bounds, in_language
from .svg import to_svg
from .title_block import form_of

# The plan of positions is scaled to fit this field when the scene gives no μl.
POSITIONS_FIELD_MM = 200.0
# A plan of positions whose paths of the points (its linework, the longer side, mm) would come out shorter than
# this would run its outlines and position numbers together: μl is made no larger for fewer sheets, and where the
# standard μl that fits POSITIONS_FIELD_MM draws them shorter (its steps are twice apart at 1:5–1:10: a 1.03 m
# mechanism came out 103 mm at 1:10), the first μl is the step finer (207 mm at 1:5).
LEAST_POSITIONS_MM = 120.0
# A figure the scene's scale draws under this share of its usual field is told of: unreadable, but asked for.
READABLE_SHARE = 0.1
# Standard scale factors tried above the first choice before a sheet is given up (each step ×1.25 at least).
_LARGER_SCALES_TRIED = 40

# μl chosen for an analysis while it lives: the choice lays out every sheet at a few μl, and each drawing of an
# analysis whose μl is not fixed (:func:`with_length_scale`) asks for it again.
_chosen_scales: OwnedMemo[float] = OwnedMemo()
_largest_scales: OwnedMemo[float] = OwnedMemo()
# The μl of each plan position's force sheet whose groups cut free have no room at the run's (:func:`_groups_roomier`).
_roomier_scales: OwnedMemo[float] = OwnedMemo()


def paths_extent(analysis: Analysis) -> float:
    """How far across (m) the paths of all points run, the larger of their width and height: the linework of
    the plan of positions, without its words."""
    tracks = np.concatenate([np.atleast_1d(p.r) for p in analysis.paths.points.values()])
    return max(float(np.ptp(tracks.real)), float(np.ptp(tracks.imag)))


def length_scale(analysis: Analysis) -> float:
    """μl from the scene; or the standard value that fits the paths of all points into the field, and the
    plan of positions and each plan sheet's mechanism on an empty sheet of the scene's format (a larger
    standard value where 200 mm do not fit; the step finer where the one that fits draws them under 120 mm,
    :func:`positions_scale`), or a step or two larger where that lays the drawings on fewer
    sheets (:func:`graphplan.render.sheet.fewest_sheets_length_scale`).

    Choosing lays the sheets out at a few μl, once for each analysis; :func:`with_length_scale` fixes the
    choice in a copy of the analysis for the drawings of a run.
    """
    given = analysis.scene.drawing.length_scale
    extent = paths_extent(analysis)
    if given is not None:
        if extent / given > LARGEST_PAPER_MM:
            _refuse_at_length_slip(analysis, f"draws the paths of the points {extent / given:.3g} mm across at "
                                   f"drawing.length_scale = {format_scale(given)}", extent / given)
            usual = positions_scale(extent)
            raise SceneError("drawing.length_scale", f"draws the paths of the points {extent / given:.3g} mm across, "
                             f"more than any paper ({LARGEST_PAPER_MM:g} mm): give {format_scale(usual)} (a plan of "
                             f"positions {extent / usual:.0f} mm across), or leave it out for the program to choose",
                             given)
        return given
    sheet = analysis.scene.drawing.sheet
    if sheet == "none":
        return positions_scale(extent)
    # The sheets build on this module's drawings: imported here, where they are laid out at each μl tried.
    from .sheet import fewest_sheets_length_scale

    return _chosen_scales.get(analysis, sheet, lambda: fewest_sheets_length_scale(
        analysis, sheet, largest_length_scale(analysis, sheet)))


def positions_scale(extent: float) -> float:
    """The standard μl that draws the paths of the points, ``extent`` m across, into the plan of positions' field
    (:data:`POSITIONS_FIELD_MM`), or the step finer where that one draws them under :data:`LEAST_POSITIONS_MM`."""
    scale = fit_scale(extent, POSITIONS_FIELD_MM)
    return finer_standard_scale(scale) if extent / scale < LEAST_POSITIONS_MM else scale


def refuse_unfit_length_scale(analysis: Analysis) -> None:
    """Refuse the scene as :func:`length_scale` does, without choosing μl, for a run that draws nothing at μl: a μl
    given beyond any paper, or drawings that fit no sheet of the scene's format at any μl (the choice's other
    attempts are made only where the first one fits, and refuse nothing)."""
    sheet = analysis.scene.drawing.sheet
    if analysis.scene.drawing.length_scale is not None:
        length_scale(analysis)
    elif sheet != "none":
        largest_length_scale(analysis, sheet)


def largest_length_scale(analysis: Analysis, sheet: str) -> float:
    """The standard μl that draws the paths of the points into the plan of positions' field, or the smallest
    larger one at which the drawings at μl fit an empty ``sheet``: where the choice of μl starts."""
    # Found once: the sheets' refusal measures the drawings there before the choice starts from it.
    return _largest_scales.get(analysis, (sheet, POSITIONS_FIELD_MM), lambda: fitting_length_scale(
        analysis, sheet, positions_scale(paths_extent(analysis))))


def refuse_beyond_paper(analysis: Analysis) -> None:
    """Refuse a plan or force polygon that a scale the scene gives draws larger than any paper, naming the key
    and the value that draws it at its usual size: such a drawing is a slip of the unit, and written out it is
    an SVG metres wide that no viewer opens."""
    for position, kind, plan in _drawn_plans(analysis):
        across = spread(plan) / plan.scale
        if not across > LARGEST_PAPER_MM:  # NaN too: a singular position's plan is refused elsewhere
            continue
        # The velocity plans of every position are drawn at velocity_plans_pole, not at the plan sheets' pole.
        grid = _on_grid(position)
        field = VELOCITY_PLANS_FIELD_MM if grid else PLAN_FIELD_MM
        key, given, fix = _plan_scale(analysis, kind, plan, grid)
        at_key = f" at {key} = {given:g}" if given is not None else ""
        _refuse_at_length_slip(analysis, f"draws the {kind} plan of position {position.number} {across:.3g} mm "
                               f"across{at_key}", across)
        # A crank a thousand times shorter than its links draws pa, which the pole distance fixes, as a dot beside
        # the rest of the plan: the length is the key to change, which nothing else names.
        slips = [slip for slip in (mixed_units(analysis.mechanism), velocity_slip_hint(analysis.mechanism)) if slip]
        raise SceneError(key, f"draws the {kind} plan of position {position.number} {across:.3g} mm across, "
                         f"more than any paper ({LARGEST_PAPER_MM:g} mm): give {fix} (a {field:g} mm "
                         "plan), or leave it out for the program to choose", given,
                         hint="".join(f"; or {slip}" for slip in slips))
    polygons = _drawn_polygons(analysis)
    for position, group in polygons:
        across = polygon_extent(group.polygon) / group.scale
        if across > LARGEST_PAPER_MM:
            _refuse_at_length_slip(analysis, f"draws the force polygon of group {group.label} in position "
                                   f"{position.number} {across:.3g} mm across at drawing.force_scale = "
                                   f"{format_scale(group.scale)}", across)
            largest = max(polygon_extent(other.polygon) for _, other in polygons)
            raise SceneError("drawing.force_scale", f"draws the force polygon of group {group.label} in position "
                             f"{position.number} {across:.3g} mm across, more than any paper ({LARGEST_PAPER_MM:g} "
                             f"mm): give {format_scale(standard_scale(largest / POLYGON_FIELD_MM))} (the largest "
                             f"polygon {POLYGON_FIELD_MM:g} mm), or leave it out for the program to choose",
                             analysis.scene.drawing.force_scale)


def _refuse_at_length_slip(analysis: Analysis, drawn: str, across: float) -> None:
    """Refuse a drawing larger than any paper at the length typed in millimetres that swells it, where a length is
    (:func:`graphplan.length_units.refused_at_slip`): the scale the drawing is refused at is one the student never
    changed, and fits once the length is in metres."""
    refused = refused_at_slip(analysis.motion, drawn, across, LARGEST_PAPER_MM)
    if refused is not None:
        raise refused


def below_reading(analysis: Analysis) -> list[str]:
    """A line for each scale the scene gives that draws its figures under a tenth of their usual size, where a
    mechanism is a dot under its letters and a polygon's sides are a fraction of a millimetre (a slip of the
    unit, as a μl of 1e3 for 1e-3): drawn as asked, but told, with the value that draws it at its usual size."""
    drawing, told = analysis.scene.drawing, []
    if drawing.length_scale is not None:
        extent = paths_extent(analysis)
        if extent / drawing.length_scale < READABLE_SHARE * POSITIONS_FIELD_MM:
            usual = positions_scale(extent)
            told.append(f"drawing.length_scale: draws the paths of the points {extent / drawing.length_scale:.3g} mm "
                        f"across, too small to read; {format_scale(usual)} draws them {extent / usual:.0f} mm across")
    # The velocity plans of every position drawn at velocity_plans_pole are judged apart, each at that pole (a plan
    # sheet's position among them holds its sheet's larger plan): the plan sheets' plans would hide a slip of the
    # key's unit.  Without that pole they are drawn at the program's own μV, which fills their field, and
    # judged with the plan sheets' they would hide a plan sheet's pole drawn too small.
    pole, pin = drawing.velocity_plans_pole, analysis.mechanism.driver.joint
    for kind, grid in (("velocity", False), ("acceleration", False), ("velocity", True)):
        if grid and pole is None:
            continue
        drawn = [(spread(plan) * pole / abs(plan.value(pin)) if grid else spread(plan) / plan.scale, plan)
                 for position, plan_kind, plan in _drawn_plans(analysis)
                 if plan_kind == kind and spread(plan) > 0.0 and _on_grid(position) == grid]
        if not drawn:
            continue
        across, plan = max(drawn, key=lambda pair: pair[0])
        key, given, fix = _plan_scale(analysis, kind, plan, grid)
        field = VELOCITY_PLANS_FIELD_MM if grid else PLAN_FIELD_MM
        if across < READABLE_SHARE * field and given is not None:
            told.append(f"{key}: draws the largest {kind} plan {across:.3g} mm across, too small to read; {fix} draws "
                        f"it {field:g} mm")
    if drawing.force_scale is not None:
        largest = max((polygon_extent(group.polygon) for _, group in _drawn_polygons(analysis)), default=0.0)
        if 0.0 < largest / drawing.force_scale < READABLE_SHARE * POLYGON_FIELD_MM:
            told.append(f"drawing.force_scale: draws the largest force polygon {largest / drawing.force_scale:.3g} mm "
                        f"across, too small to read; {format_scale(standard_scale(largest / POLYGON_FIELD_MM))} draws it "
                        f"{POLYGON_FIELD_MM:g} mm")
    return told


def _drawn_plans(analysis: Analysis) -> list[tuple[VelocityPosition | PlanPosition, str, Plan]]:
    """(position, kind, plan) of every plan drawn: the velocity plans of every position, then the plan sheets'."""
    return [(position, kind, plan) for position in (*analysis.velocity_plans, *analysis.plans)
            for kind, plan in (position.plans if isinstance(position, PlanPosition)
                               else {"velocity": position.velocity}).items()]


def _on_grid(position: VelocityPosition | PlanPosition) -> bool:
    """Whether ``position``'s plan is one of the velocity plans of every position (``positions.velocity_plans``),
    not a plan sheet's: a plan sheet's position is a :class:`VelocityPosition` too, since it has a velocity plan,
    but its plans are drawn at the plan sheets' poles."""
    return not isinstance(position, PlanPosition)


def _drawn_polygons(analysis: Analysis) -> list[tuple[PlanPosition, GroupForces]]:
    """(position, group) of every force polygon drawn: each group's, without friction and with it where it moves."""
    return [(position, group) for position in analysis.plans
            for found in (position.forces, position.with_friction) if found is not None and not found.locked
            for group in found.groups]


def _plan_scale(analysis: Analysis, kind: str, plan: Plan, grid: bool = False) -> tuple[str, float | None, str]:
    """The key that sets ``kind``'s plans' scale (μ itself, or the pole distance), its value in the scene, and the
    value of it that draws ``plan`` as large as its field; ``grid`` for a velocity plan of every position drawn at
    ``velocity_plans_pole``."""
    drawing = analysis.scene.drawing
    if grid:  # one μV for them all: the largest of them fills the field
        every = [position.velocity for position in analysis.velocity_plans]
        pin = analysis.mechanism.driver.joint
        fitting = max(spread(each) for each in every) / VELOCITY_PLANS_FIELD_MM
        fix = _pole_that_fits(max(abs(each.value(pin)) for each in every) / fitting)
        return "drawing.velocity_plans_pole", drawing.velocity_plans_pole, fix
    fitting = spread(plan) / PLAN_FIELD_MM
    if getattr(drawing, f"{kind}_scale") is not None:
        return f"drawing.{kind}_scale", getattr(drawing, f"{kind}_scale"), format_scale(standard_scale(fitting))
    fix = _pole_that_fits(abs(plan.value(analysis.mechanism.driver.joint)) / fitting)
    return f"drawing.{kind}_pole", getattr(drawing, f"{kind}_pole"), fix


def _pole_that_fits(pole: float) -> str:
    """The pole distance (mm) that draws a plan as large as its field, ``pole`` at most, as the advice gives it: whole
    millimetres; under one, in two digits (a plan many times the driver's vector, which a whole millimetre of pole
    would still draw larger than any paper, is told the pole that fits, not 1)."""
    return f"{math.floor(pole):d}" if pole >= 1.0 else f"{pole:.2g}"


def with_length_scale(analysis: Analysis) -> Analysis:
    """The analysis with μl fixed in its scene as :func:`length_scale` chooses it, so that every drawing agrees."""
    if analysis.scene.drawing.length_scale is not None:
        return analysis
    return at_length_scale(analysis, length_scale(analysis))


def at_length_scale(analysis: Analysis, scale: float) -> Analysis:
    """The analysis with μl fixed at ``scale`` in its scene."""
    return dataclasses.replace(analysis, scene=dataclasses.replace(
        analysis.scene, drawing=dataclasses.replace(analysis.scene.drawing, length_scale=scale)))


def positions_size(analysis: Analysis, scale: float) -> tuple[float, float]:
    """The width and height (mm) of the plan of positions drawn at μl = ``scale``."""
    x0, y0, x1, y1 = bounds(positions.layout(positions_plan(analysis, scale)))
    return float(x1 - x0), float(y1 - y0)


def mechanism_size(analysis: Analysis, position: PlanPosition, scale: float) -> tuple[float, float]:
    """The width and height (mm) of the mechanism of a plan sheet, with its caption, drawn at μl = ``scale``:
    what stands on a sheet of the set when the plan sheet is cut into its drawings."""
    return _drawing_size(plan_sheet(at_length_scale(analysis, scale), position.index, position.velocity, position.acceleration), "mechanism")


def _drawing_size(sheet: plans.PlanSheet, drawing: str) -> tuple[float, float]:
    alone = dataclasses.replace(sheet, drawings=(drawing,))
    x0, y0, x1, y1 = bounds([layer for layer in plans.layout(alone) if layer.name != "sheet-title"])
    return float(x1 - x0), float(y1 - y0)


def fitting_length_scale(analysis: Analysis, sheet: str, least: float, either_way: bool = False) -> float:
    """The smallest standard μl ≥ ``least`` at which the drawings at μl fit on an empty ``sheet`` each:
    the plan of positions and the mechanism of every plan sheet; on a sheet as it is laid out, or ``either_way``
    it may stand (the μl a refusal offers).

    (The force sheets' drawings are drawn at a larger scale where they do
    not fit.)  Raises :class:`SceneError` when no μl does: the words and
    marks of a drawing alone take more than the sheet.
    """
    form = form_of(analysis.scene.locale)

    def fits(scale: float) -> bool:
        return (holds(sheet, form, *positions_size(analysis, scale), either_way)
                and all(holds(sheet, form, *mechanism_size(analysis, position, scale), either_way)
                        for position in analysis.plans))

    scale = standard_scale(least)
    for _ in range(_LARGER_SCALES_TRIED):
        if fits(scale):
            return scale
        scale = next_standard_scale(scale)
    raise SceneError("drawing.sheet", f"the plan of positions and the plan sheets' mechanisms fit no {sheet} sheet "
                     "at any μl", sheet)


def _svg(analysis: Analysis, layers: list[Layer]) -> str:
    """The SVG text of a drawing of the analysis, its numbers with the decimal mark of the scene's language."""
    return to_svg(in_language(layers, analysis.scene.locale, analysis.scene.own_words))


def positions_svg(analysis: Analysis) -> str:
    return _svg(analysis, positions.layout(positions_plan(analysis)))


# The most positions the plan of positions draws: beyond them the outlines run together into a grey
# sheet and their numbers cover each other (and placing them grows as the square of their count).
MOST_DRAWN_POSITIONS = 36


def drawn_positions(analysis: Analysis) -> list[int]:
    """The indices of the positions the plan of positions draws: all of them, or one in every few and
    each plan sheet's position when there are more than :data:`MOST_DRAWN_POSITIONS`."""
    count = analysis.motion.count
    step = math.ceil(count / MOST_DRAWN_POSITIONS)
    return sorted(set(range(0, count, step)) | {position.index for position in analysis.plans})


def positions_plan(analysis: Analysis, scale: float | None = None) -> positions.PositionsPlan:
    """What the plan of positions shows at μl = ``scale`` (:func:`length_scale` when None), in the scene's language."""
    text = strings(analysis.scene.locale)
    scale = length_scale(analysis) if scale is None else scale
    drawn = drawn_positions(analysis)
    caption = text["length_scale"].format(value=format_scale(scale))
    count = analysis.motion.count
    if len(drawn) < count:
        caption += "; " + text["positions_thinned"].format(step=math.ceil(count / MOST_DRAWN_POSITIONS), count=count)
    return positions.PositionsPlan(
        mechanism=analysis.mechanism, positions=analysis.motion.at_positions(drawn),
        numbers=tuple(int(analysis.positions.numbers[index]) for index in drawn),
        emphasised=analysis.emphasised,
        paths=analysis.paths, length_scale=scale, title=text["positions_title"], caption=caption,
        extremes=extreme_names(analysis, drawn),
        marked=tuple(sorted({int(analysis.positions.numbers[plan.index]) for plan in analysis.plans})),
        travels=dimensioned_travels(analysis, text), working_extremes=analysis.positions.extremes is not None)


def dimensioned_travels(analysis: Analysis, text: Mapping[str, str]) -> tuple[positions.Travel, ...]:
    """What the plan of positions dimensions between its bold positions: a slider driver's stroke (a cylinder's),
    and the working link's travel, its stroke H where it slides on a frame guide, its swing ψ where it rocks about a
    frame pivot, where the bold positions are its extremes (a crank's run) or the ends of a travel or a swing it
    moves one way over (a cylinder's lever); none where they are no two (a crank turning with no working link)."""
    mechanism, emphasised = analysis.mechanism, analysis.emphasised
    driver = mechanism.driver
    if emphasised.count < 2:
        return ()
    found = []
    if driver.kind == "slider":
        found.append(_stroke(emphasised, driver.joint, driver.link, text))
    working = analysis.scene.positions.working
    if working is None or working.link == driver.link:
        return tuple(found)
    if analysis.positions.extremes is None and (driver.cyclic or not _one_way(analysis, working)):
        return tuple(found)
    link, frame = working.link, mechanism.scene.frame_link
    if link in mechanism.translating:
        point = next((slide.joint for slide in emphasised.slides if slide.slider == link and slide.guide == frame), None)
        if point is not None:
            found.append(_stroke(emphasised, point, link, text))
        return tuple(found)
    pivot = next((joint for joint, first, second in mechanism.revolutes if {first, second} == {link, frame}), None)
    if pivot is not None:
        turned = emphasised.links[link].angle
        swing = abs(math.degrees(math.remainder(float(at(turned, 1)) - float(at(turned, 0)), 2 * math.pi)))
        found.append(positions.Travel(pivot, link, text["positions_swing"].format(value=f"{swing:.1f}"), swing=True))
    return tuple(found)


def _stroke(emphasised, point: str, link: int, text: Mapping[str, str]) -> positions.Travel:
    track = emphasised.points[point].r
    stroke = abs(complex(at(track, 1)) - complex(at(track, 0)))
    return positions.Travel(point, link, text["positions_stroke"].format(value=f"{stroke:.4g}"))


def _one_way(analysis: Analysis, working: Working) -> bool:
    """Whether the working link moves one way over the whole travel or swing (its speed of one sign where it moves,
    a singular position's left out): its travel between the run's ends is then its swing or its stroke."""
    speed, _ = working_speed(analysis.paths, working)
    finite = speed[np.isfinite(speed)]
    moving = finite[np.abs(finite) > 1e-9 * float(np.max(np.abs(finite), initial=0.0))]
    return bool(np.all(moving > 0) or np.all(moving < 0))


def extreme_names(analysis: Analysis, drawn: Sequence[int]) -> tuple[str, ...]:
    """What each bold position of the plan of positions is named by where it is no numbered position drawn: the
    number of the position it follows, turning the driver's way, with a prime (8′); empty for a numbered one."""
    driver = analysis.mechanism.driver
    values = analysis.positions.values
    numbers = [int(number) for number in analysis.positions.numbers]
    shown = {numbers[index] for index in drawn}
    names = []
    for value in np.atleast_1d(analysis.emphasised.driver):
        if driver.cyclic:
            turn = 2.0 * math.pi
            ahead = (driver.sense * (float(value) - values[0])) % turn
            steps = ahead / (turn / len(values))
        else:
            span = values[-1] - values[0]
            steps = (float(value) - values[0]) / span * (len(values) - 1) if span else 0.0
        nearest = round(steps) % len(values)
        if abs(steps - round(steps)) < 1e-6:
            names.append("" if numbers[nearest] in shown else str(numbers[nearest]))
        else:
            names.append(f"{numbers[math.floor(steps) % len(values)]}′")
    return tuple(names)


def plan_svg(analysis: Analysis, index: int, velocity: Plan | None = None, acceleration: Plan | None = None) -> str:
    """The SVG text of the plan sheet of the position at ``index`` (:func:`plan_sheet`)."""
    return _svg(analysis, plans.layout(plan_sheet(analysis, index, velocity, acceleration)))


def plan_alone_svg(analysis: Analysis, position: PlanPosition, kind: str) -> str:
    """The SVG text of ``position``'s velocity or acceleration plan (``kind``) alone, with its caption: a figure of a
    report, the plan sheet's drawing without the mechanism and the other plan."""
    return _svg(analysis, plans.layout(plan_sheet_showing(analysis, position, (kind,))))


def plan_sheet_showing(analysis: Analysis, position: PlanPosition, drawings: tuple[str, ...]) -> plans.PlanSheet:
    """``position``'s plan sheet (:func:`plan_sheet`) showing ``drawings`` alone (of mechanism, velocity and
    acceleration), titled by the plans among them (:func:`plan_sheet_title`)."""
    shown = tuple(name for name in drawings if name != "mechanism")
    return dataclasses.replace(plan_sheet(analysis, position.index, position.velocity, position.acceleration),
                               drawings=drawings, title=plan_sheet_title(strings(analysis.scene.locale), shown,
                                                                         position.number))


def plan_sheet_title(text: Mapping[str, str], shown: tuple[str, ...], number: int) -> str:
    """The title of a position's plan sheet holding the plans ``shown``: both, or the one drawn (under --only
    velocity, "Velocity and acceleration plans" stood over a sheet with no acceleration plan)."""
    key = "plan_sheet_title" if len(shown) == 2 else f"{shown[0]}_plan_caption"
    return text[key].format(number=number)


def plan_sheet(analysis: Analysis, index: int, velocity: Plan | None = None,
               acceleration: Plan | None = None) -> plans.PlanSheet:
    """What the plan sheet of the position at ``index`` (an index into the analysed positions) shows.

    ``velocity`` and ``acceleration`` are the plans of that position; a plan
    not given is constructed here from the positions of the instant.
    """
    if not 0 <= index < analysis.motion.count:
        raise IndexError(f"no position at index {index}; there are {analysis.motion.count}")
    mechanism = analysis.mechanism
    if velocity is None or acceleration is None:
        where, directions = instant(analysis.motion, index)
        if velocity is None:
            velocity = velocity_plan(mechanism, where, directions)
        if acceleration is None:
            acceleration = acceleration_plan(mechanism, where, directions, velocity)
    # Every word on a sheet is the locale's: the scene's title, written in any language, stays off it.
    text = strings(analysis.scene.locale)
    scale = length_scale(analysis)
    number = int(analysis.positions.numbers[index])
    return plans.PlanSheet(
        mechanism=mechanism, motion=analysis.motion, index=index, number=number,
        velocity=velocity, acceleration=acceleration, length_scale=scale,
        title=text["plan_sheet_title"].format(number=number),
        mechanism_caption=(text["mechanism_title"].format(number=number),
                           text["length_scale"].format(value=format_scale(scale))),
        velocity_caption=(text["velocity_plan_title"],
                          text["velocity_scale"].format(value=scale_factor(velocity.scale)),
                          *_too_short_lines(velocity, "velocity", text)),
        acceleration_caption=(text["acceleration_plan_title"],
                              text["acceleration_scale"].format(value=scale_factor(acceleration.scale)),
                              *_too_short_lines(acceleration, "acceleration", text)),
        velocity_pole="p", acceleration_pole=text["acceleration_pole"])


def velocity_plans_drawing(analysis: Analysis) -> velocity_plans.VelocityPlans:
    """What the drawing of the velocity plans of every position (``positions.velocity_plans``) shows."""
    text = strings(analysis.scene.locale)
    every = analysis.velocity_plans
    if not every:
        raise ValueError("the scene draws no velocity plans of every position: positions.velocity_plans lists none")
    return velocity_plans.VelocityPlans(
        mechanism=analysis.mechanism, plans=tuple((position.number, position.velocity) for position in every),
        captions=tuple((text["position_heading"].format(number=position.number),
                        *_too_short_lines(position.velocity, "velocity", text)) for position in every),
        title=text["velocity_plans_heading"],
        scale_line=text["velocity_scale"].format(value=scale_factor(every[0].velocity.scale)))


def _too_short_lines(plan: Plan, kind: str, text: Mapping[str, str]) -> list[str]:
    """Caption lines naming the plan's vectors too short to draw, with their values."""
    unit = text["unit_m_per_s" if kind == "velocity" else "unit_m_per_s2"]
    # Named as the note names them: aΣ6C^τ as aΣ6Cτ.
    values = [f"{raised(name)} = {value:.3g} {unit}" for name, value in plans.too_short(plan, kind)]
    return plans.too_short_lines(values, text)


def forces_svg(analysis: Analysis, plan_position: PlanPosition, with_friction: bool = False) -> str:
    """The SVG text of the force sheet of one plan position (:func:`force_sheet`)."""
    return _svg(analysis, force_layout.layout(force_sheet(analysis, plan_position, with_friction)))


def force_sheet(analysis: Analysis, plan_position: PlanPosition,
                with_friction: bool = False) -> force_layout.ForceSheet:
    """What the force sheet of a plan position shows: its groups cut free, their polygons, the lever.

    ``with_friction`` shows the force analysis with the pairs' friction, its
    friction circles and its lever, the driving link's caption giving the
    balancing load without friction and the efficiency; without it, the
    sheet of a position the friction locks says so under the driving link.  Raises :class:`ValueError` for a
    position without a force analysis (``plan_position.forces`` is None), or
    without one with friction that settled when it is asked for.
    """
    if plan_position.forces is None:
        raise ValueError(f"position {plan_position.number} has no force analysis")
    text = strings(analysis.scene.locale)
    velocity = plan_position.velocity
    forces, lever, title = plan_position.forces, plan_position.lever, "tb_sheet_forces_position"
    friction, ideal, eta = (), None, None
    locked = not with_friction and plan_position.with_friction is not None and plan_position.with_friction.locked
    if with_friction:
        rubbing = plan_position.with_friction
        if rubbing is None or rubbing.locked:
            raise ValueError(f"position {plan_position.number} has no settled force analysis with friction")
        forces, lever = rubbing, plan_position.lever_with_friction
        title = "tb_sheet_forces_friction_position"
        # Rounded here, so that the caption's Mb0 and η judge an extreme position's noise as the tables do.
        friction = analysis.friction
        ideal = float(rounded_zero(plan_position.forces.balancing, rubbing.balancing, analysis.balancing_scale))
        eta = float(efficiency(analysis.mechanism, ideal, rubbing.balancing))
    sheet = force_layout.ForceSheet(
        mechanism=analysis.mechanism, motion=analysis.motion, index=plan_position.index,
        number=plan_position.number, positions={**plan_position.positions, **forces.auxiliary}, forces=forces,
        lever=lever, velocity=velocity, length_scale=length_scale(analysis),
        # As on the plan sheets, every word is the locale's: the scene's title stays off the sheet.
        title=text[title].format(number=plan_position.number), text=text, friction=friction,
        without_friction=ideal, efficiency=eta, locked_with_friction=locked,
        lever_scale=force_lever.enlarged_lever_scale(velocity, lever),
        velocity_scale=text["velocity_scale"].format(value=scale_factor(velocity.scale)))
    # Chosen once for a position: the course sheets ask for its force sheet again, and the choice lays its groups out.
    key = (with_friction, analysis.scene.locale, analysis.scene.drawing, sheet.length_scale)
    roomier = _roomier_scales.get(plan_position, key, lambda: _groups_roomier(sheet).length_scale)
    return sheet if roomier == sheet.length_scale else dataclasses.replace(sheet, length_scale=roomier)


# How many standard steps larger than the run's μl a crowded group cut free may be drawn.
_ROOMIER_STEPS = 2


def _groups_roomier(sheet: force_layout.ForceSheet) -> force_layout.ForceSheet:
    """``sheet`` with its groups cut free drawn a standard step larger (a finer μl), or two, where at the run's μl
    the names of one find no room apart (a class III triad's seventeen arms from Σ6, its names left on its lines and
    on long leaders): a draughtsman draws a crowded group larger.  Left at the run's μl where no step clears them."""
    from . import force_bodies

    def crowded(drawn: force_layout.ForceSheet) -> bool:
        return any(force_bodies.labels_cover_one_another(force_bodies.body(drawn, group))
                   for group in drawn.forces.groups)

    if not crowded(sheet):
        return sheet
    for steps in range(1, _ROOMIER_STEPS + 1):
        larger = dataclasses.replace(sheet, length_scale=finer_standard_scale(sheet.length_scale, steps))
        if not crowded(larger):
            return larger
    return sheet
