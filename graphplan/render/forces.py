"""The force sheet of one position: each group cut free with its loads, its force polygon, and Zhukovsky's lever.

Laid out as the second sheet of a course project.  For every group in the
order it was solved (the last group first, the driver last) a row: on the
left the group's links cut free at μl, every force an arrow at its point
(proportional at the panel's own force scale, never shorter than
:data:`LEAST_ARROW_MM`), every moment a curved arrow with its sense, the
arms ``h`` of the moment equations as thin perpendiculars from the moment
centre to the forces' lines; on the right the group's force polygon at μF,
the known vectors head to tail, the two closing lines of action thin and
dashed beyond their crossing, the closing vectors, the inner reaction
dashed and each reaction found drawn whole.  A polygon that the record
closes twice (the lever and the block of an RPR group) is drawn as two
polygons side by side.  The last row is Zhukovsky's lever: the velocity
plan turned 90° clockwise, the loads at the images of their points with
their arms from the pole, the balancing force at the driver's image.  A
sheet too low for the rows in one column takes them in two
(:func:`arrangements`); how the rows stand on a sheet too small for
either is :mod:`graphplan.render.force_rows`' (:func:`rows`).

The sheet of the force analysis with friction is the same sheet of the
plan with friction, with the textbook's construction at every journal with
friction: its friction circle ρ = f·r, the friction moments turning about
the journal, and the whole reaction of the pair on the circle's tangent,
on the side whose moment about the joint is the friction moment.

The layout reads the records (:class:`graphplan.forces.ForcePlan`,
:class:`graphplan.lever.Lever`, the velocity plan, the positions): it puts
what they hold on paper and computes no mechanics.
"""

from __future__ import annotations

import functools
import math
import re
import unicodedata
from collections.abc import Callable, Iterator, Mapping, MutableMapping, Sequence
from dataclasses import dataclass, replace

import numpy as np
import shapely
from shapely.geometry import LineString, MultiPoint, Polygon
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union
from shapely.strtree import STRtree

from ..forces import TERM_ROUNDING, ForcePlan, GroupForces, MomentEquation, PolygonVector, ProjectionEquation
from ..geometry import Line, perpendicular_foot
from ..joint_friction import FrictionPair, pair_name
from ..kinematics import at
from ..lever import Lever, LeverTerm, shared_arms, turned
from ..loads import external_names
from ..mechanism import Mechanism
from ..memo import OwnedMemo, RecentMemo
from ..motion import Motion
from ..plans import Plan
from ..rounding import ROUNDING_NOISE
from ..scales import finer_standard_scale, fit_scale, format_scale, standard_scale
from ..wording import balancing_symbol, friction_summary
from .force_rows import CAPTION_WIDTH_MM, Drawing, Heading, Rows, RunOn
from .labels import (
    LEADER_CLEARANCE,
    LEADER_GAP,
    LEADER_WIDTH,
    Anchor,
    Placement,
    cover_one_another,
    obstacles_and_shafts,
    obstacles_of,
    open_direction,
    place_labels,
    remembered,
    set_out,
    shapes_digest,
    spaced_box,
    text_box,
)
from .linkage import link_outlines, outline_points
from .numerals import short, significant
from .plans import CAPTION_SIZE, RUN_ON_MM, ZERO_MM, Arrangement, too_short_lines
from .plans import _coincident as coincident_letters
from .primitives import (
    LEAD_PAST_PIN_MM,
    MAIN,
    PIN_RADIUS_MM,
    Arrow,
    Circle,
    Layer,
    Polyline,
    Primitive,
    Stroke,
    Text,
    bounds_of,
    curved_arrow,
    dot_marker,
    moved_layers,
    pin,
    place,
    slider_block,
    svg_id,
    text_extent,
    text_width,
    zigzag,
)
from .primitives import to_complex as _c
from .primitives import to_xy as _xy

# The longest force arrow on a group cut free and on the lever (mm): the panel's force scale is the
# standard one that draws the largest force about a quarter of the drawing's size, within these bounds.
LONGEST_ARROW_MM = (25.0, 50.0)
ARROW_SHARE = 0.25
# No force arrow on a group or on the lever is drawn shorter than this (mm), so that its head and
# its direction read; the caption says so.
LEAST_ARROW_MM = 10.0
# A force less than this share of the largest beside it is a rounding error and is not drawn.
NEGLIGIBLE = 1e-9
# A load whose arrow would run this far (mm), and this share of its length, within a bar of the drawn links
# either way from its point lies along its link (a long arrow leaving its link at a small angle reads well);
# it is drawn this far beside its line instead, tied to its point by a thin leader.
ALONG_BAR_MM = 4.5
ALONG_BAR_SHARE = 0.4
BESIDE_MM = 2.5
# On the lever a load set beside stands by another load's arrow parallel to it at the same point (two couples' forces
# at one end of their link: Mf14″ and Mf34″ at b), their heads level: this far apart (mm) each head has its name
# beside it (a name's box is 4.6 mm high, kept 0.8 mm off another's), where at BESIDE_MM the two arrows read as one
# and one name stood by the other's head.
LEVER_BESIDE_MM = 6.0
_LEADER_WIDTH = 0.18
# Radii of the curved arrows of moments on the links (mm).
MOMENT_RADIUS_MM = 6.0
BALANCING_RADIUS_MM = 9.0
# A friction circle is drawn at least this large (mm), clear of the pin drawn over its joint; the caption
# says when it is enlarged.
LEAST_FRICTION_CIRCLE_MM = 3.0
# The whole reaction on the friction circle's tangent runs this far past the circle each way (mm).
TANGENT_RUN_MM = 9.0
# A load's arrow on the lever passes no other point's dot nearer than this (mm) where another way of drawing it
# passes none: a head by another point reads as a load at that point.
POINT_CLEAR_MM = 2.5
# An arm on the lever whose name would stand nearer the pole than this (mm) is not lettered.
POLE_CLEAR_MM = 10.0
# Two sides of a force polygon on one line in opposite senses are drawn this far apart (mm), side by side.
SIDE_BY_SIDE_MM = 1.5
# A polygon's name on a leader shorter than this (mm) across arrows within SLIVER_DEG of its own line, side by side
# with it in a sliver, reads as naming its own: the crank-rocker starter's R23n at position 5, 1.6 mm across R43.
# Longer, it reads as naming one it crosses (the class III triad's R14 at position 2, 15 mm across Fu3 and R64).
SLIVER_LEADER_MM = 3.0
SLIVER_DEG = 5.0
# A whole reaction's name, which the eye reads as naming the nearest line, may instead stand on a leader up to this
# long (mm) across sides side by side with its own, ending on its own line: the crank-rocker starter's R23 at position
# 5, on a 0.8 mm leader across R14 just above R14's own name, read as naming R14; led 7 mm across R23n and R43, as at
# b76b78f, it was followed to its own line without doubt.  Shorter than SLIVER_LEADER_MM a leader is not followed.
WHOLE_LEADER_MM = 8.0
# A name no more than this (mm) farther from its own arrow than from the nearest reads as its own: the eye tells no
# nearer of two lines this close, and the name has its own arrow's colour (the crank-rocker starter's R14 at position
# 5, 0.4 mm from R14 and 0.05 mm from R14τ, between the two, as at b76b78f).
TIE_MM = 0.5
# So set, a name stands off the lines it is led across, its leader at least this long (mm): beside them without one
# it reads as naming the nearest.
SLIVER_LEADER_LEAST_MM = 0.8
# The names of components and given loads standing within this (mm) of a whole reaction's name that lies on a line
# or across an arrow crowd it: they are left unnamed, nearest first, till it finds a clear spot.
CROWDING_MM = 8.0
# A component's or load's name on a leader that crosses nothing stands square out from its side or turned this much
# (degrees) toward either end, where G3's name, say, stands square to the side (the offset slider-crank's R23n at
# position 10).
CLEAR_TURNS_DEG = (0.0, 30.0, -30.0, 60.0, -60.0)
# Space between two polygons of one group (mm).
POLYGON_GAP_MM = 15.0
# How many values a caption line lists before it wraps.
PER_LINE = 4
# Between the values a caption line lists: a comma and two spaces, so that a value with a comma of its own (fE =
# 0.1, φ = …) reads as one.  A line of symbols and numbers alone takes it in every language.
VALUE_SEPARATOR = ",  "
# The captions' lettering where the usual does not fit a small sheet: the next size down of GOST 2.304 and
# ISO 3098 (the usual is plans.CAPTION_SIZE, 5 mm).
SMALL_CAPTION_SIZE = 3.5
# Size of the letters of points and of the names of forces (cap height, mm).
POINT_SIZE = 3.5
NAME_SIZE = 3.2

_LINK = Stroke(0.7)
_LOAD = Stroke(0.45)
_REACTION = Stroke(0.5, "#a83a1f")
_BALANCING = Stroke(0.6, "#1f7a3a")
_KNOWN = Stroke(0.5)
_CLOSING = Stroke(0.55, "#a83a1f")
_INNER = Stroke(0.45, "#a83a1f", (3.0, 1.5))
_WHOLE = Stroke(0.35, "#1f5fa8")
_ACTION = Stroke(0.25, "#333333")
_ACTION_RUN_ON = Stroke(0.25, "#333333", (2.5, 1.5))
_ARM = Stroke(0.2, "#555555")
_ARM_RUN_ON = Stroke(0.2, "#555555", (1.5, 1.0))
_AXIS = Stroke(0.2, "#333333", (6.0, 1.5, 1.0, 1.5))
# A force along a turning line (a cylinder's or a spring's) has its line drawn on its group cut free, thin dash-dot,
# from its point to the point it is along: the cylinder or spring is cut away with the frame or the other link, all but
# a piece at its point.
_ALONG_LINE = Stroke(0.25, "#333333", (6.0, 1.5, 1.0, 1.5))
# Of a cylinder or spring cut away from a group, the length of its rod drawn from its point (at most), a spring's wave
# (as long as it is wide), and the short slanted cut across where it ends (mm): what a hand drawing keeps of it.
CUT_OFF_MM = 7.0
CUT_SPRING_WAVE_MM = 2.5
CUT_MARK_MM = 2.5
_ALONG_ROD = Stroke(0.5)
_ALONG_SPRING = Stroke(0.25)
_ALONG_CUT = Stroke(0.25)
# The line is run to the point it is along where that lies within this many times the group's size of it; farther,
# it stops at that length, where the drawing would grow mostly to show one line.
ALONG_REACH = 1.5
_LEVER = Stroke(0.6)
_RAY = Stroke(0.25, "#555555")
_MOMENT = Stroke(0.4)
_FRICTION_CIRCLE = Stroke(0.3, "#a83a1f")
_ON_TANGENT = Stroke(0.3, "#a83a1f", (6.0, 1.5, 1.0, 1.5))


@dataclass(frozen=True)
class ForceSheet:
    """What the force sheet of one position shows.

    ``positions`` are the mechanism's points at the instant (m) and ``index``
    the position's index in ``motion`` (whose slides give the directions of
    the sliding pairs there); ``forces`` and ``lever`` the records of the
    force analysis; ``velocity`` the velocity plan the lever is turned from;
    ``length_scale`` is μl (m/mm); ``text`` the locale's strings;
    ``velocity_scale`` the line of μV as the plan sheet writes it;
    ``part_title`` heads the first part of the sheet where it stands in
    parts on several sheets (the title without the mechanism's name).
    ``friction`` holds the pairs with friction when ``forces`` is the plan
    with friction; ``without_friction`` is then the balancing load without
    it and ``efficiency`` η (NaN where friction turns the power flow round).
    ``locked_with_friction`` marks the sheet without friction of a position
    the pairs' friction locks: the driving link's caption says so, as the
    tables do (that position has no sheet with friction).
    ``lever_scale`` is μV of the lever when it is drawn at another scale
    than the velocity plan (a similar figure at any scale gives the same
    balancing load): larger where the plan's points crowd
    (:func:`enlarged_lever_scale`), smaller where a small sheet needs it; ``caption_size`` the height of the
    captions' letters (mm), smaller on a small sheet.
    """

    mechanism: Mechanism
    motion: Motion
    index: int
    number: int
    positions: Mapping[str, complex]
    forces: ForcePlan
    lever: Lever | None
    velocity: Plan
    length_scale: float
    title: str
    text: Mapping[str, str]
    velocity_scale: str
    part_title: str = ""
    friction: tuple[FrictionPair, ...] = ()
    without_friction: float | None = None
    efficiency: float | None = None
    locked_with_friction: bool = False
    lever_scale: float | None = None
    caption_size: float = CAPTION_SIZE

    @property
    def lever_drawn_scale(self) -> float:
        """μV the lever is drawn at: its own where it has one, else the velocity plan's."""
        return self.velocity.scale if self.lever_scale is None else self.lever_scale

    @property
    def lever_enlarged(self) -> bool:
        """Whether the lever is drawn larger than its velocity plan."""
        return draws_larger(self.lever_drawn_scale, self.velocity.scale)

    @property
    def lever_scale_line(self) -> str:
        """The line of μV the lever is drawn at."""
        if self.lever_scale is None:
            return self.velocity_scale
        return self.text["velocity_scale"].format(value=format_scale(self.lever_scale))


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
            made[number, sheet.length_scale] = _body(sheet, group)
        drawings.append([made[number, sheet.length_scale], _polygons_drawing(sheet, group)])
    if sheet.lever is not None:
        drawings.append([_lever_drawing(sheet, sheet.lever)])
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


def _friction_summary(sheet: ForceSheet) -> list[str]:
    """The line of the sheet with friction under the driving link: the balancing load with and without it, η;
    on the sheet without friction of a position the friction locks, that it locks."""
    if sheet.locked_with_friction:
        return [sheet.text["forces_locked"]]
    if sheet.without_friction is None:
        return []
    eta = "—" if sheet.efficiency is None or not math.isfinite(sheet.efficiency) else significant(sheet.efficiency)
    return [friction_summary(sheet.mechanism, sheet.text, sheet.without_friction, sheet.forces.balancing,
                             write=significant, iterations=sheet.forces.iterations, written_efficiency=eta)]


# A group cut free.

@dataclass(frozen=True)
class _Force:
    """A force drawn on a group cut free: its name, its point (m), its value (N), its style."""

    name: str
    point: complex
    force: complex
    stroke: Stroke


def _body(sheet: ForceSheet, group: GroupForces) -> Drawing:
    """The group's links at μl with every force at its point, the moments, the arms of the moment equations."""
    text = sheet.text
    key = group_id(group.label)
    paper = _paper(sheet.length_scale)
    is_driver = group is sheet.forces.groups[-1]
    links, special_names, shown, scale = _body_frame(sheet, group, paper)
    arrows: list[Primitive] = []
    drawn: dict[str, tuple[complex, complex, complex]] = {}  # name → (arrow start, arrow end, unit), mm
    anchors: list[Anchor] = []
    # Only the links' heavy lines hide an arrow laid over them: a slide's thin axis is the line a slider's
    # loads act along, and the textbooks draw them on it; a slider's block is crossed every way from its pin.
    bars = _grown([LineString(item.points + item.points[:1] if item.closed else item.points) for item in links
                   if isinstance(item, Polyline) and len(item.points) > 1 and item.stroke.width >= _LINK.width
                   and item.fill is None], 1.0)
    blocks = unary_union([Polygon(item.points) for item in links
                          if isinstance(item, Polyline) and item.closed and item.fill is not None])
    # The points the equations take each force's moment about: an arrow set beside its line stays on its line's
    # side of them, so that it turns about each as its term in the equation is signed.
    centres: dict[str, list[complex]] = {}
    for equation in group.moments:
        for term in equation.standing_terms:
            centres.setdefault(term.name, []).append(_c(paper(sheet.positions[equation.about])))
    beside = {force.name: _beside(_c(paper(force.point)), max(abs(force.force) / scale, LEAST_ARROW_MM)
                                  * force.force / abs(force.force), bars, blocks, centres.get(force.name, ()))
              for force in shown}
    # Arrows pointing onto their joint are set first, so that where several share a line the others run on
    # beyond their tails, not head against head.
    stacked: dict[str, Arrow] = {}
    for force in sorted(shown, key=lambda force: not _points_onto(*beside[force.name][:2], _c(paper(force.point)))):
        start, end, shift = beside[force.name]
        start, end = _unstacked(start, end, _c(paper(force.point)) + shift, list(stacked.values()))
        stacked[force.name] = Arrow(_xy(start), _xy(end), force.stroke, 3.0, svg_id("body", key, force.name))
    leaders: list[Primitive] = []
    for force in shown:
        arrow = stacked[force.name]
        arrows.append(arrow)
        start, end = _c(arrow.start), _c(arrow.end)
        unit = force.force / abs(force.force)
        shift = beside[force.name][2]
        point = _c(paper(force.point))
        if shift:
            # Set beside its link, the arrow is tied to its point; its arm is still taken to its true line.
            near = min((start, end), key=lambda end_: abs(end_ - point))
            leaders.append(Polyline((_xy(point), _xy(near)), Stroke(_LEADER_WIDTH, force.stroke.colour)))
        drawn[force.name] = (start - shift, end - shift, unit)
        # Named at the arrow's free end: its head, or its tail when it points onto its joint; beside its shaft, or led
        # from it, it names the arrow as well.
        free, outward = (start, -unit) if _points_onto(start, end, point + shift) else (end, unit)
        anchors.append(Anchor(_xy(free), force.name, NAME_SIZE, _angle(outward), force.stroke.colour,
                              along=(arrow.start, arrow.end)))
    turning, turning_anchors = _moments(sheet, group, paper, is_driver, links + arrows)
    circles, circle_anchors, circle_caption = _friction_circles(sheet, group, paper)
    arms, arm_anchors, equations = _arms(sheet, group, drawn, paper)
    displaced, displaced_anchors = _displacements(sheet, group, paper)
    arms += displaced
    arm_anchors += displaced_anchors
    arrows += leaders
    along, along_names = _along_lines(sheet, group, paper, stacked)
    figure = links + arrows + turning + circles + arms + along
    # Left on a line, a load's name reaches farther out on a leader from its arrow's shaft (its anchor's ``along``),
    # which ties it to its arrow among the group's arms and arcs (the triad with a slider's Fu6 lay on its own line
    # of action run on to its arm, every leader from its head to a clear spot crossing another name); a point's,
    # a moment's or an arm's name keeps its place: led far out from a thin arm in the star of arms at Σ6 (the class
    # III triad's h3 and h8 on its A3 sheet of position 8), it reads as naming another.
    points = [Anchor(where, name, POINT_SIZE, open_direction(where, figure))
              for name in _named_points(sheet, group) + special_names for where in [paper(sheet.positions[name])]]
    points += [Anchor(where, name, POINT_SIZE, open_direction(where, figure))
               for name, where in along_names if name not in {anchor.text for anchor in points}]
    others = points + turning_anchors + circle_anchors + arm_anchors
    labels = _lettered(anchors + others, figure, reach_farther=[True] * len(anchors) + [False] * len(others))
    caption = [text["driver_forces_title" if is_driver else "group_forces_title"].format(group=group.label),
               text["comma"].join((text["length_scale"].format(value=format_scale(sheet.length_scale)),
                                   text["body_force_scale"].format(value=format_scale(scale),
                                                                   least=f"{LEAST_ARROW_MM:g}")))]
    caption += [line for equation in group.projections if (line := _projection(sheet, equation))]
    caption += equations
    caption += circle_caption
    caption += _slide_friction(sheet, group)
    if is_driver:
        caption.append(_balancing_line(sheet, sheet.forces.balancing, "balancing_by_polygons"))
        # Under the load it balances, so that a sheet set part by part keeps it.
        caption += _friction_summary(sheet)
    caption += _wrapped([f"{found.name} = {significant(abs(found.force))} {text['newton']}" for found in group.found
                         if abs(found.force) / group.scale >= ZERO_MM])
    friction = [Layer(f"body-{key}-friction", tuple(circles))] if circles else []
    # Under the links, whose pins cover its lines' ends; named for lines, as a CAD file's construction lines.
    under = [Layer(f"body-{key}-along-lines", tuple(along))] if along else []
    layers = [*under, Layer(f"body-{key}-links", tuple(links)), Layer(f"body-{key}-arms", tuple(arms)),
              Layer(f"body-{key}-moments", tuple(turning)), *friction, Layer(f"body-{key}-forces", tuple(arrows)),
              Layer(f"body-{key}-leaders", labels.leaders), Layer(f"body-{key}-labels", labels.texts)]
    # Its title and scales stay with the group; its equations, under its title again, may go on after it.
    parted = (Drawing(f"body-{key}", layers, tuple(caption[:2])),
              Drawing(f"equations-{key}", [], (caption[0], *caption[2:]))) if len(caption) > 2 else None
    return Drawing(f"body-{key}", layers, tuple(caption), parted)


def _along_lines(sheet: ForceSheet, group: GroupForces, paper: Callable[[complex], tuple[float, float]],
                 arrows: Mapping[str, Arrow]) -> tuple[list[Primitive], list[tuple[str, tuple[float, float]]]]:
    """The line of each force along a turning line (``[[loads]]`` with ``along``) on the group, from its point to
    the point it is along, and that point's name and place on the paper where the group's drawing does not show it.

    Cut free, the group keeps no frame and no more of the cylinder or spring than a piece at its point: the line to
    D is what shows that the force acts along DB, as the hand drawing shows it.  A cylinder between two links of the
    group (two loads, one at each end) is one line.  A point farther off than :data:`ALONG_REACH` times the group's
    size is not reached: its line stops there, unnamed, its direction still DB's.

    Where the force's arrow (in ``arrows``, by name) leaves the side of its point toward D free, the spring or
    cylinder is drawn cut off at its point, as the group is cut free of it (:func:`_cut_off`); where the arrow runs
    toward D (a pull) the piece would lie under it, and the line alone shows it.
    """
    specs = dict(zip(external_names(sheet.mechanism.scene.loads), sheet.mechanism.scene.loads, strict=True))
    drawn_points = set(_named_points(sheet, group))
    reach = ALONG_REACH * max(_group_size_mm(sheet, group), 1.0)
    lines: list[Primitive] = []
    names: list[tuple[str, tuple[float, float]]] = []
    done: set[frozenset[str]] = set()
    for load in group.loads:
        spec = specs.get(load.name)
        if spec is None or spec.along is None or load.point is None or not load.is_force or load.force == 0:
            continue
        if frozenset((spec.along, load.point)) in done:
            continue
        done.add(frozenset((spec.along, load.point)))
        near = _c(paper(_load_point(sheet, load.point)))
        far = _c(paper(_position(sheet, spec.along)))
        if abs(far - near) == 0.0:
            continue
        if abs(far - near) > reach:
            far = near + reach * (far - near) / abs(far - near)
        elif spec.along not in drawn_points:
            names.append((spec.along, _xy(far)))
            lines.append(dot_marker(_xy(far)))
        lines.append(Polyline((_xy(near), _xy(far)), _ALONG_LINE))
        unit = (far - near) / abs(far - near)
        arrow = arrows.get(load.name)
        if arrow is not None and max(((_c(end) - near) * unit.conjugate()).real
                                     for end in (arrow.start, arrow.end)) < ZERO_MM:
            lines.extend(_cut_off(near, unit, spec.spring, min(CUT_OFF_MM, 0.4 * abs(far - near))))
    return lines, names


def _cut_off(point: complex, unit: complex, is_spring: bool, length: float) -> list[Primitive]:
    """A cylinder's rod or a spring from its ``point`` (mm) along ``unit`` toward the point it is along, ``length``
    mm of it, ending in a short slanted cut: the part of it a hand drawing keeps to show what the group was cut
    free of.  A spring keeps a lead past its pin and a wave and a half of its zig-zag."""
    lead = PIN_RADIUS_MM + LEAD_PAST_PIN_MM
    if is_spring:
        wave = CUT_SPRING_WAVE_MM
        end = lead + 1.5 * wave
        shape = [(0.0, 0.0), (lead, 0.0), *zigzag(lead, 1.5 * wave, 3, wave), (end, 0.0)]
        stroke = _ALONG_SPRING
    else:
        end = max(length, lead + 1.0)
        shape = [(0.0, 0.0), (end, 0.0)]
        stroke = _ALONG_ROD
    angle = math.atan2(unit.imag, unit.real)
    half = CUT_MARK_MM / 2
    cut = ((end - 0.5 * half, -half), (end + 0.5 * half, half))
    return [Polyline(place(shape, _xy(point), angle), stroke), Polyline(place(cut, _xy(point), angle), _ALONG_CUT)]


def _position(sheet: ForceSheet, name: str) -> complex:
    """A point of the mechanism at the sheet's instant (m), whether or not the sheet's positions list it."""
    if name in sheet.positions:
        return sheet.positions[name]
    return complex(at(sheet.motion.points[name].r, sheet.index))


def _group_size_mm(sheet: ForceSheet, group: GroupForces) -> float:
    """The larger side of the box round the group's points on the paper (mm)."""
    points = [sheet.positions[name] for name in _named_points(sheet, group)]
    if not points:
        return 0.0
    xs, ys = [point.real for point in points], [point.imag for point in points]
    return max(max(xs) - min(xs), max(ys) - min(ys)) / sheet.length_scale


def _body_frame(sheet: ForceSheet, group: GroupForces, paper: Callable[[complex], tuple[float, float]]
                ) -> tuple[list[Primitive], list[str], list[_Force], float]:
    """The group cut free's links (and its special points) on the paper, those points' names, the forces on it that
    are drawn (a rounding error's is not, :func:`_negligible`) and the μF their arrows are drawn at, which the links'
    extent sets."""
    links = _links(sheet, group, paper)
    special, special_names = _special_points(sheet, group, paper)
    links += special
    forces = _forces_on(sheet, group)
    shown = [force for force in forces if not _negligible(force.force, [other.force for other in forces])]
    return links, special_names, shown, _arrow_scale([force.force for force in forces], links)


def free_body_arrows(sheet: ForceSheet) -> dict[str, tuple[float, tuple[str, ...]]]:
    """By each group's label, the μF (N/mm) its group cut free draws its forces' arrows at, and the reactions drawn
    whole there at their length at it (a component, R23τ, is no whole reaction; an arrow lengthened to
    :data:`LEAST_ARROW_MM` is at no scale): what a hand reading of a reaction off the arrows measures."""
    paper = _paper(sheet.length_scale)
    found = {}
    for group in sheet.forces.groups:
        _, _, shown, scale = _body_frame(sheet, group, paper)
        whole = tuple(force.name for force in shown if _whole_reaction(force.name)
                      and abs(force.force) / scale >= LEAST_ARROW_MM)
        found[group.label] = (scale, whole)
    return found


def labels_cover_one_another(drawing: Drawing) -> bool:
    """Whether two of the labels of a group cut free cover one another: drawn so small that the names of its
    points, loads and arms find no room apart (:func:`~graphplan.render.labels.place_labels` lets a label cover
    another only where no spot round its point is clear)."""
    return cover_one_another([item for layer in drawing.layers if layer.name == f"{drawing.name}-labels"
                              for item in layer.items if isinstance(item, Text)])


def _beside(point: complex, vector: complex, bars: BaseGeometry,
            blocks: BaseGeometry, centres: Sequence[complex] = ()) -> tuple[complex, complex, complex]:
    """The arrow of a force at ``point``: from it, or onto it where that keeps it off the links' bars, or
    beside the bar it runs along; with the shift that sets it beside (0 where it stands on its point).

    A reaction pushing along a link (R23n) drawn from its joint would lie on
    the link; drawn onto the joint it stands clear, as the textbooks draw it.
    Onto a slider's joint it pushes on the block's side: its head at the pin
    would be lost inside the block.  A load at a point inside its link (a
    crank's Fu2 at S2, a weight along an upright link) lies on the bar
    either way: it is drawn parallel to its line, :data:`BESIDE_MM` off it
    on the side the bars leave clearer (else away from them), tied to its point.
    Set beside, it never crosses a moment centre of ``centres`` its line
    passes within :data:`BESIDE_MM` of: the crank's G2 with its line 0.5 mm
    left of O, drawn 2.5 mm to its right, turned clockwise about O on the
    drawing while its equation and arm h1 took it counter-clockwise.
    """
    def covered(start: complex, end: complex) -> float:
        return LineString((_xy(start), _xy(end))).intersection(bars).length

    unit = vector / abs(vector)
    shy = 0.0
    if ShapelyPoint(_xy(point)).within(blocks):
        shy = LineString((_xy(point), _xy(point - (abs(vector) + 100.0) * unit))).intersection(blocks).length
    away, onto = (point, point + vector), (point - vector - shy * unit, point - shy * unit)
    chosen = onto if covered(*onto) < covered(*away) - 0.5 else away
    hidden = covered(*chosen)
    # A block's loads along its slot stand as they do: set off, they would run along the block's own edge.
    if hidden < max(ALONG_BAR_MM, ALONG_BAR_SHARE * abs(vector)) or shy:
        return (*chosen, 0j)
    def across(where: complex) -> float:
        return (where * unit.conjugate()).imag

    def crossed(shift: complex) -> int:
        return sum(across(point - centre) * across(point + shift - centre) < 0 for centre in centres)

    sides = [(start + shift, end + shift, shift) for start, end in (away, onto)
             for shift in (1j * unit * BESIDE_MM, -1j * unit * BESIDE_MM)]
    sides = [side for side in sides if covered(side[0], side[1]) < hidden - 0.5 * ALONG_BAR_MM]
    if not sides:
        return (*chosen, 0j)
    # Of the sides that clear it, one that crosses no moment centre; of those as clear, the one away from the
    # drawn links, where the loads stand round the group.
    middle = _c(bars.centroid.coords[0]) if not bars.is_empty else point
    return min(sides, key=lambda side: (crossed(side[2]), round(covered(side[0], side[1]), 6),
                                        ((middle - point) * side[2].conjugate()).real > 0))


# How many grown unions :func:`_grown` keeps, the least recently asked given up first.
GROWN_KEPT = 512
_grown_unions: RecentMemo[BaseGeometry] = RecentMemo()


def _grown(lines: Sequence[LineString], distance: float) -> BaseGeometry:
    """The union of ``lines`` grown by ``distance`` (mm): the same shape given again for the very same lines.

    Growing the union of a lever's lines takes a tenth of a second and more (its rays and bars overlap), and the
    same lever is drawn again and again: for each force sheet tried, each locale, each test of a module.  Keyed by
    the lines as they are (:func:`~graphplan.render.labels.shapes_digest`) and the distance's exact repr; GEOS grows
    the same lines the same.
    """
    if GROWN_KEPT <= 0:
        return unary_union(list(lines)).buffer(distance)
    return _grown_unions.get(shapes_digest(lines, repr(distance)), lambda: unary_union(list(lines)).buffer(distance),
                             GROWN_KEPT)


def _points_onto(start: complex, end: complex, point: complex) -> bool:
    """Whether the arrow from ``start`` to ``end`` points onto ``point``, its head the nearer end."""
    return abs(end - point) < abs(start - point)


def _unstacked(start: complex, end: complex, point: complex, arrows: Sequence[Primitive]) -> tuple[complex, complex]:
    """The arrow moved on along its own line, away from its point, until it covers no arrow drawn before.

    Two forces at one point in one direction (a weight and a load on a
    slider) would be drawn one over the other; moved along its line of
    action, the second stands beyond the first and keeps its line.
    """
    unit = (end - start) / abs(end - start)
    away = -unit if _points_onto(start, end, point) else unit

    def along(item: Arrow) -> bool:  # an arrow crossing this one hides nothing of it
        other = (_c(item.end) - _c(item.start)) / max(item.length, 1e-12)
        return abs((unit.conjugate() * other).imag) < math.sin(math.radians(10.0))

    others = [LineString((item.start, item.end)).buffer(0.8) for item in arrows
              if isinstance(item, Arrow) and item.length > 0 and along(item)]
    for _ in range(8):
        overlap = max((LineString((_xy(start), _xy(end))).intersection(other).length for other in others), default=0.0)
        if overlap < 1.0:
            break
        start, end = start + (overlap + 1.5) * away, end + (overlap + 1.5) * away
    return start, end


def _pushing_or_pulling(at: complex, vector: complex, arrows: Sequence[Primitive],
                        lines: Callable[[], BaseGeometry],
                        others: Sequence[complex] = ()) -> tuple[complex, complex, complex]:
    """The arrow of a load on the lever at its point ``at``: from it, or onto it where a load drawn before
    already lies along that line from it and the other side of the point is clear of ``lines()``, or else
    :data:`LEVER_BESIDE_MM` beside that line (:data:`BESIDE_MM` where only that is clear); with the shift that sets
    it beside (0 on its line).

    Two loads at one point on one line (F6 and Fu6 at e, a couple's forces
    M4′ and Mu4′ at d) drawn one after another read as one arrow broken
    by a head; one pulling from the point and one pushing onto it read as
    two, and both at their point, as a hand drawing shows them.  Where the
    other side is taken (the arms run from the pole, another load comes
    in), the second stands beside the first, tied to the point; where that
    too is taken, it runs on beyond the first (:func:`_unstacked`).  Set
    beside, it keeps to its line's side of the pole where either side is clear.

    An arrow so drawn that passes another point of the lever, ``others``,
    within :data:`POINT_CLEAR_MM` is drawn the first of these ways that
    passes none, or else one that passes none and crosses lines without
    lying along one: the knee press's Fu4, drawn from s4 toward s5, ended
    with its head on s5's dot and on G5's tail, and read as a load at s5.
    """
    unit = vector / abs(vector)

    def off_points(start: complex, end: complex) -> bool:
        shaft = LineString((_xy(start), _xy(end)))
        return all(shaft.distance(ShapelyPoint(_xy(point))) >= POINT_CLEAR_MM for point in others)

    def clear(start: complex, end: complex, along: float = 1.0) -> bool:
        return (_unstacked(start, end, at, arrows) == (start, end)
                and LineString((_xy(start), _xy(end))).intersection(lines()).length < along)

    def crosses_pole(shift: complex) -> bool:  # the lever's moments are about the pole, at 0
        return (at * unit.conjugate()).imag * ((at + shift) * unit.conjugate()).imag < 0

    away, onto = (at, at + vector), (at - vector, at)
    # A side is taken where it is clear at BESIDE_MM, and drawn there LEVER_BESIDE_MM off where that is clear too: a
    # side clear only that far off (the knee press's F6 at d, past Fu6 and G6 on its line) left the next load along
    # the line (Ff16) no side, and it stood beyond another on its line, the two reading as one arrow broken by a head.
    sides = [(shift * LEVER_BESIDE_MM / BESIDE_MM, shift)
             for shift in sorted((1j * unit * BESIDE_MM, -1j * unit * BESIDE_MM), key=crosses_pole)]

    def first_way(keep_off: bool, along: float = 1.0) -> tuple[complex, complex, complex] | None:
        def fits(start: complex, end: complex, ok: Callable[[complex, complex], bool]) -> bool:
            return ok(start, end) and (not keep_off or off_points(start, end))

        if fits(*away, lambda start, end: _unstacked(start, end, at, arrows) == (start, end)):
            return (*away, 0j)
        if fits(*onto, lambda start, end: clear(start, end, along)):
            return (*onto, 0j)
        for wide, shift in sides:
            if fits(away[0] + shift, away[1] + shift, lambda start, end: clear(start, end, along)):
                if fits(away[0] + wide, away[1] + wide, lambda start, end: clear(start, end, along)):
                    shift = wide
                return (away[0] + shift, away[1] + shift, shift)
        return None

    chosen = first_way(False) or (*_unstacked(*away, at, arrows), 0j)
    if off_points(*chosen[:2]):
        return chosen
    # Kept off the other points where no way is clear of the lines, an arrow may cross the lever's thin lines as long
    # as it lies along none (ALONG_BAR_MM, as on a group cut free): s4's Fu4 pushes onto s4 across the rays there.
    return first_way(True) or first_way(True, ALONG_BAR_MM) or chosen


def _links(sheet: ForceSheet, group: GroupForces, paper: Callable[[complex], tuple[float, float]]) -> list[Primitive]:
    """The group's links alone: their outlines, slider blocks with the axes of their slides, pins, centres."""
    mechanism, positions = sheet.mechanism, sheet.positions
    outlines = outline_points(mechanism, sheet.motion)
    # Drawn as the plan sheet draws them, so that a yoke is its slot and its rod, not a triangle.
    items = link_outlines(sheet.motion, sheet.index, {link: outlines[link] for link in group.links if link in outlines},
                          paper, _LINK)
    for slide in sheet.motion.slides:
        if slide.slider not in group.links:
            continue
        u = complex(at(slide.u, sheet.index))
        centre = _c(paper(positions[slide.joint]))
        if slide.guide not in group.links:  # the slide's axis, where the guide itself is cut away
            # Run on to where the guide's reaction acts off the joint (R14 at x = −190 mm): it stands on the axis.
            shifts = [found.offset / sheet.length_scale for found in group.found
                      if found.offset and found.joint == slide.joint
                      and {found.source, found.target} == {slide.guide, slide.slider}
                      and abs(found.force) / sheet.forces.scale_of(found.name) >= ZERO_MM]
            back, ahead = min([-14.0, *(shift - 6.0 for shift in shifts)]), max([14.0, *(shift + 6.0 for shift in shifts)])
            items.append(Polyline((_xy(centre + back * u), _xy(centre + ahead * u)), _AXIS))
        items.append(slider_block(_xy(centre), math.atan2(u.imag, u.real), stroke=MAIN))
    joints = {name for name, first, second in mechanism.revolutes if first in group.links or second in group.links}
    items.extend(pin(paper(positions[name])) for name in sorted(joints))
    named = {spec.name for spec in mechanism.scene.points} - joints
    for link in group.links:
        for name in sorted(mechanism.fixed_on.get(link, ())):
            if name in named:
                items.append(dot_marker(paper(positions[name])))
    return items


def _special_points(sheet: ForceSheet, group: GroupForces, paper) -> tuple[list[Primitive], list[str]]:
    """Assur's special points the group's moment equations are taken about, each marked.

    The lines of the binary links that cross there, and the normal of a slider's guide at its pin where it
    runs through it, run on to it, dashed, as on the plan sheet: the reader sees why the unknowns along them
    have no arm.
    """
    outlines = outline_points(sheet.mechanism, sheet.motion)
    items: list[Primitive] = []
    names: list[str] = []
    for name in dict.fromkeys(equation.about for equation in group.moments):
        if name not in sheet.forces.auxiliary:
            continue
        where = sheet.positions[name]
        items.append(dot_marker(paper(where)))
        names.append(name)
        for link in group.links:
            ends = [sheet.positions[joint] for joint in outlines.get(link, ())]
            if len(ends) != 2 or abs(ends[1] - ends[0]) == 0.0:
                continue
            unit = (ends[1] - ends[0]) / abs(ends[1] - ends[0])
            if abs(((where - ends[0]) * unit.conjugate()).imag) > 1e-9 * max(abs(where - ends[0]), 1.0):
                continue
            nearer = min(ends, key=lambda end: abs(end - where))
            items.append(Polyline((paper(nearer), paper(where)), _ACTION_RUN_ON))
        for slide in sheet.motion.slides:
            if slide.slider not in group.links:
                continue
            pin = sheet.positions[slide.joint]
            u = complex(at(slide.u, sheet.index))
            if abs(((where - pin) * u.conjugate()).real) <= 1e-9 * max(abs(where - pin), 1.0):
                items.append(Polyline((paper(pin), paper(where)), _ACTION_RUN_ON))
    return items, names


def _named_points(sheet: ForceSheet, group: GroupForces) -> list[str]:
    """The points of the group's links lettered on the drawing, and the points its loads act at."""
    names = {name for link in group.links for name in sheet.mechanism.fixed_on.get(link, ())}
    names |= {load.point for load in group.loads if load.point is not None}
    return sorted(name for name in names if name in sheet.positions)


def _forces_on(sheet: ForceSheet, group: GroupForces) -> list[_Force]:
    """Every force on the group cut free: its loads, the reactions found on it, a slider driver's Fb.

    A reaction is split as the group's polygon splits it (R23τ, R23n);
    reactions between the group's own links are inner and not drawn here.
    """
    forces = [_Force(load.name, _load_point(sheet, load.point) + load.offset, load.force, _LOAD)
              for load in group.loads if load.is_force and load.force != 0]
    polygon = {vector.name: vector for vector in group.polygon.vectors if vector.role != "inner"}
    for found in group.found:
        if found.source in group.links:
            continue
        point = _along_slide(sheet, found.joint, found.source, found.target, found.offset)
        parts = [polygon[name] for name in (f"{found.name}τ", f"{found.name}n") if name in polygon]
        if parts:
            forces.extend(_Force(part.name, point, part.force, _REACTION) for part in parts)
        else:
            forces.append(_Force(found.name, point, found.force, _REACTION))
    if "Fb" in polygon:
        forces.append(_Force("Fb", sheet.positions[sheet.mechanism.driver.joint], polygon["Fb"].force, _BALANCING))
    return forces


def _load_point(sheet: ForceSheet, point: str | None) -> complex:
    """Where a load acts: a named point, or a reaction handed back off its joint (``B(R14)``)."""
    assert point is not None
    if point in sheet.positions:
        return sheet.positions[point]
    shifted = re.fullmatch(r"(.+)\((.+)\)", point)
    if shifted is None or shifted.group(2) not in sheet.forces.reactions:
        raise KeyError(f"no position for the point {point!r} of a load")
    found = sheet.forces.reactions[shifted.group(2)]
    return _along_slide(sheet, found.joint, found.source, found.target, found.offset)


def _along_slide(sheet: ForceSheet, joint: str, guide: int, slider: int, offset: float | None) -> complex:
    """The joint, moved ``offset`` along its slide when the reaction acts off it (a normal force's shift)."""
    where = sheet.positions[joint]
    if not offset:
        return where
    for slide in sheet.motion.slides:
        if slide.joint == joint and {slide.guide, slide.slider} == {guide, slider}:
            return where + offset * complex(at(slide.u, sheet.index))
    return where


def _moments(sheet: ForceSheet, group: GroupForces, paper, is_driver: bool,
             drawn: Sequence[Primitive]) -> tuple[list[Primitive], list[Anchor]]:
    """A curved arrow for every moment on the group, with its sense; the driver's balancing moment.

    Each arc leaves open the quarter where the point it turns about is
    lettered (the widest gap between the lines ``drawn`` from it).
    """
    items: list[Primitive] = []
    anchors: list[Anchor] = []
    largest = max((abs(load.moment) for load in group.loads), default=0.0)
    journals = _friction_moment_joints(sheet)
    rings: dict[str, int] = {}
    for load in group.loads:
        if load.is_force or abs(load.moment) <= 1e-9 * max(largest, 1.0):
            continue
        # A friction moment turns about its journal, the other moments about the link's centre.
        about = journals.get(load.name, f"link {load.link}")
        ring = rings.get(about, 0)
        rings[about] = ring + 1
        where = sheet.positions[journals[load.name]] if load.name in journals else _link_centre(sheet, load.link)
        centre = _c(paper(where))
        items_, anchor = _turn(centre, MOMENT_RADIUS_MM + 3.5 * ring, load.moment, load.name, _MOMENT,
                               open_direction(_xy(centre), drawn))
        items += items_
        anchors.append(anchor)
    driver = sheet.mechanism.driver
    if is_driver and driver.kind == "crank" and sheet.forces.balancing != 0:
        centre = _c(paper(sheet.positions[driver.pivot]))
        items_, anchor = _turn(centre, BALANCING_RADIUS_MM, sheet.forces.balancing, "Mb",
                               Stroke(0.5, _BALANCING.colour), open_direction(_xy(centre), drawn))
        items += items_
        anchors.append(anchor)
    return items, anchors


def _turn(centre: complex, radius: float, moment: float, name: str, stroke: Stroke,
          gap: float) -> tuple[list[Primitive], Anchor]:
    """A curved arrow of 270° about ``centre`` in the sense of ``moment`` (ccw positive), open towards ``gap``.

    Its name stands outside the middle of the arc, across from the gap.
    """
    sweep = math.copysign(math.radians(270.0), moment)
    start = gap + math.copysign(math.radians(45.0), moment)
    items = curved_arrow(_xy(centre), radius, start, sweep, stroke, 2.5)
    middle = start + sweep / 2
    at = centre + radius * complex(math.cos(middle), math.sin(middle))
    return items, Anchor(_xy(at), name, NAME_SIZE, middle, stroke.colour)


def _friction_moment_joints(sheet: ForceSheet) -> dict[str, str]:
    """The journal each friction moment turns about: ``Mf23`` and ``Mf32`` about the joint of 2 and 3."""
    return {name: pair.joint for pair in sheet.friction if not pair.sliding
            for name in pair.load_names}


def _friction_circles(sheet: ForceSheet, group: GroupForces, paper) -> tuple[list[Primitive], list[Anchor], list[str]]:
    """The friction circle of every journal of the group with friction, and the whole reaction of each outer
    pair on the circle's tangent, on the side whose moment about the joint is the friction moment on the group:
    those the group finds, and those later groups found that act back on it (``R32``, with ``Mf32``).

    The reaction ``R23`` through the joint with the moment ``Mf23`` is one force
    ``R23`` shifted ρ across its line: ``cross(−i·û·ρ·sign Mf, R) = ρ·|R|·sign Mf``.
    """
    items: list[Primitive] = []
    anchors: list[Anchor] = []
    journals = [pair for pair in sheet.friction if not pair.sliding
                and (pair.source in group.links or pair.target in group.links)]
    if not journals:
        return items, anchors, []
    # Two journals at one joint (three links pinned together) have a circle each.
    drawn = {frozenset((pair.source, pair.target)): max(pair.radius / sheet.length_scale, LEAST_FRICTION_CIRCLE_MM)
             for pair in journals}
    for pair in sorted(journals, key=lambda pair: (pair.joint, pair.source, pair.target)):
        items.append(Circle(paper(sheet.positions[pair.joint]), drawn[frozenset((pair.source, pair.target))],
                            _FRICTION_CIRCLE, fill=None))
    moments = {load.name: load.moment for load in group.loads if not load.is_force}
    split = {vector.name for vector in group.polygon.vectors}
    # The outer pairs only (an inner reaction is not drawn on the group): the reactions the group finds, and those a
    # later group found, which act back on the group's links on the same line (R32 = −R23, on R23's tangent).
    outer = [found for found in group.found if found.source not in group.links]
    outer += [found.back for found in sheet.forces.reactions.values()
              if found.source in group.links and found.target not in group.links]
    for found in outer:
        moment = moments.get(f"Mf{found.source}{found.target}", 0.0)
        if moment == 0 or found.force == 0:
            continue  # a reaction without friction has no tangent to lie on
        unit = found.force / abs(found.force)
        radius = drawn[frozenset((found.source, found.target))]
        touch = _c(paper(sheet.positions[found.joint])) - 1j * unit * math.copysign(radius, moment)
        run = radius + TANGENT_RUN_MM
        items.append(Polyline((_xy(touch - run * unit), _xy(touch + run * unit)), _ON_TANGENT))
        if f"{found.name}n" in split:  # split into τ and n on the drawing, the whole reaction is named only here
            anchors.append(Anchor(_xy(touch + run * unit), found.name, NAME_SIZE, _angle(unit), _ON_TANGENT.colour))
    text = sheet.text
    values = [f"ρ{_pair_name(sheet, pair)} = {significant(1000.0 * pair.radius)} {text['millimetre']}"
              for pair in sorted(journals, key=lambda pair: (pair.joint, pair.source, pair.target))]
    caption = _wrapped([text["friction_circles"].format(values=values[0]), *values[1:]])
    if any(pair.radius / sheet.length_scale < LEAST_FRICTION_CIRCLE_MM for pair in journals):
        caption.append(text["friction_circles_enlarged"].format(least=f"{LEAST_FRICTION_CIRCLE_MM:g}"))
    return items, anchors, caption


def _slide_friction(sheet: ForceSheet, group: GroupForces) -> list[str]:
    """The caption of the group's slides with friction: each one's coefficient f (f′ = f/sin θ in a V-guide), the
    friction angle φ = arctan f by which its reaction and friction force lean together, and its friction force
    Ff at the settled reactions, the load the drawing shows as an arrow of its own."""
    text = sheet.text
    values: list[tuple[str, ...]] = []  # each value as its clauses: f and φ, or Ff
    for pair in sorted((pair for pair in sheet.friction if pair.sliding
                        and (pair.source in group.links or pair.target in group.links)),
                       key=lambda pair: (pair.joint, pair.source, pair.target)):
        where = _pair_name(sheet, pair)
        theta = pair.spec.groove_half_angle
        if not pair.in_vee:
            coefficient, angle = f"f{where} = {short(pair.coefficient)}", f"φ = {text['arctangent']} f"
        else:
            # f′ = f/sin θ, written with the numbers alone: a break inside "sin θ" would part it
            coefficient = (f"f′{where} = {short(pair.spec.f)}/sin {short(math.degrees(theta))}° = "
                           f"{short(pair.coefficient)}")
            angle = f"φ = {text['arctangent']} f′"
        values.append((coefficient, f"{angle} = {significant(math.degrees(math.atan(pair.coefficient)))}°"))
        load = next((load for load in group.loads if load.name in pair.load_names), None)
        force = abs(load.force) if load is not None else pair.coefficient * abs(
            sheet.forces.reactions[pair.reaction].force)
        values.append((f"{pair.load_names[0]} = {significant(force)} {text['newton']}",))
    if not values:
        return []
    # The line after the locale's words takes the locale's separators (full-width after Chinese: "滑动摩擦：fE = 0.1，
    # φ = …" read with ASCII commas after a full-width colon); the lines of symbols and numbers alone after it
    # Latin ones, as every such line of the sheet.
    comma = text["comma"]
    spaced = VALUE_SEPARATOR if comma == ", " else comma
    first = text["sliding_friction"].format(values=spaced.join(comma.join(value) for value in values[:PER_LINE]))
    return [first, *_wrapped([", ".join(value) for value in values[PER_LINE:]])]


def _pair_name(sheet: ForceSheet, pair: FrictionPair) -> str:
    """How a pair with friction is named in its ρ or f, as the note names it (:func:`pair_name`)."""
    return pair_name(pair, sheet.friction)


def _link_centre(sheet: ForceSheet, link: int) -> complex:
    """Where a moment on the link is drawn: its centre of mass, or the middle of its points."""
    spec = sheet.mechanism.scene.links.get(link)
    if spec is not None and spec.centre in sheet.positions:
        return sheet.positions[spec.centre]
    names = [name for name in sheet.mechanism.fixed_on.get(link, ()) if name in sheet.positions]
    return sum((sheet.positions[name] for name in names), 0j) / max(len(names), 1)


def _displacements(sheet: ForceSheet, group: GroupForces, paper) -> tuple[list[Primitive], list[Anchor]]:
    """The shift hu = Mu/Fu of each displaced inertia force, from its link's centre across to its line."""
    items: list[Primitive] = []
    anchors: list[Anchor] = []
    for load in group.loads:
        if not load.is_force or not load.offset or abs(load.offset) / sheet.length_scale < ZERO_MM:
            continue
        centre = _c(paper(sheet.positions[load.point]))
        shifted = _c(paper(sheet.positions[load.point] + load.offset))
        items.append(Polyline((_xy(centre), _xy(shifted)), _ARM))
        anchors.append(Anchor(_xy((centre + shifted) / 2), f"hu{load.link}", NAME_SIZE - 0.4,
                              _angle(1j * (shifted - centre)), _ARM.colour))
    return items, anchors


def _arms(sheet: ForceSheet, group: GroupForces, drawn: Mapping[str, tuple[complex, complex, complex]],
          paper) -> tuple[list[Primitive], list[Anchor], list[str]]:
    """The arm of every term of the group's moment equations, h1, h2, …, and the equations written with them.

    An arm is the perpendicular from the moment centre to the force's line;
    the line runs on, dashed, from the arrow to the foot when the foot lies
    off the arrow.  A force whose line passes through the centre has no arm
    and no term.  Every term whose moment is in the value stands in the
    equation (:attr:`MomentEquation.standing_terms`), as in the note: an arm
    too short to draw (a crank near a dead centre) is given by its length
    under the equation instead.
    """
    items: list[Primitive] = []
    anchors: list[Anchor] = []
    lines: list[str] = []
    count = 0
    for equation in group.moments:
        centre = _c(paper(sheet.positions[equation.about]))
        parts: list[str] = []
        undrawn: list[str] = []
        for term in equation.standing_terms:
            if term.name in drawn:
                start, end, unit = drawn[term.name]
                count += 1
                name = f"h{count}"
                parts.append(f"{_sign(term.moment)} {term.name}·{name}")
                if term.arm / sheet.length_scale < ZERO_MM:
                    undrawn.append(f"{name} = {significant(term.arm / sheet.length_scale)} {sheet.text['millimetre']}")
                    continue
                items += _perpendicular(centre, start, end, unit)
                foot = perpendicular_foot(centre, start, unit)
                anchors.append(Anchor(_xy((centre + foot) / 2), name, NAME_SIZE - 0.4,
                                      _angle(1j * (foot - centre)), _ARM.colour, along=(_xy(centre), _xy(foot))))
            else:
                # A couple stands as itself; a force not drawn (or a term the group adds) by its moment.
                couple = any(load.name == term.name and not load.is_force for load in group.loads)
                parts.append(f"{_sign(term.moment)} {term.name if couple else f'M({term.name})'}")
        line = _equation(sheet, group, equation, parts)
        if line:
            lines.append(line)
            # Said to be too short, as the lever says it of its arms: a bare h2 = 0.1088 mm sent the reader looking
            # for an arm on the drawing.
            lines += too_short_lines(undrawn, sheet.text, CAPTION_WIDTH_MM, words="arms_too_short")
    return items, anchors, lines


def _equation(sheet: ForceSheet, group: GroupForces, equation: MomentEquation, parts: list[str]) -> str:
    """The moment equation as the note writes it: ``ΣMB(3): R23τ·AB − G3·h1 + Fu3·h2 + Mu3 = 0,  R23τ = 26.13 N``.

    The unknown's arm is named by its segment (its joint and the centre) where
    it is square to that segment, else ``h``, whose length follows the unknown's value;
    where the unknown is a couple (the balancing moment, the shift ``x`` of a
    normal reaction along its slide), the couple stands alone.  An equation
    with nothing in it (a load through the joint) is left out.
    """
    text = sheet.text
    unknown, about = equation.unknown, f"ΣM{equation.about}({equation.bodies}):"
    terms = " ".join(parts)
    total = sum(term.moment for term in equation.terms)
    if unknown.endswith("·x"):
        if equation.value == 0 and total == 0:
            return ""
        if (reaction := group.held_as_couple_alone(equation)) is not None:
            # The reaction is nought and the guide holds a couple alone, with no line and no x: R14·x stands for
            # that couple, signed, and its value is the answer, as the note writes it (R14·x = −95.518 N·m).  Bare,
            # the equation gave the Scotch yoke's sheet no value and no word of why R14 is missing.
            return (f"{about} {unknown} {terms} = 0{VALUE_SEPARATOR}{unknown} = {significant(equation.value)} "
                    f"{text['newton_metre']}{VALUE_SEPARATOR}{text['sheet_couple_alone'].format(name=reaction)}")
        found = sheet.forces.reactions.get(unknown[:-2])
        shift = ""
        if found is not None and found.offset and abs(found.force) > 0:
            # x is an arm, as every h is: a length, its term signed by the moment it gives, as the others are.  The
            # offset along the guide written here put x = −3.301 mm under a +R16·x on a press's downward guide,
            # which read with R16 = 2224 N doubled the friction moment Mf56 where it should balance it.  Written
            # wherever the note writes it, the reaction drawn or too short to draw.
            shift = f",  x = {significant(1000.0 * abs(found.offset))} {text['millimetre']}"
        sign = "−" if shift and equation.value < 0 else ""
        return f"{about} {sign}{unknown} {terms} = 0{shift}"
    if unknown == "Mb":
        return f"{about} {' '.join(['Mb', *parts])} = 0,  Mb = {significant(equation.value)} {text['newton_metre']}"
    # The unknown's sense as first assumed: its moment balances the others'.
    sign = "" if equation.value == 0 or -total / equation.value >= 0 else "−"
    joint = next((found.joint for found in group.found
                  if unknown.rstrip("τn") in (f"R{found.source}{found.target}", f"R{found.target}{found.source}")),
                 None)
    # The arm is named by the segment from the centre to the joint only where it is that segment (a τ part square
    # to its link); an unknown at an angle to it (a guide's normal reaction about Assur's point) has an arm h.
    arm = "h"
    if joint is not None and joint != equation.about:
        segment = abs(sheet.positions[joint] - sheet.positions[equation.about])
        if abs(segment - equation.arm) <= 1e-9 * segment:
            arm = "".join(sorted((joint, equation.about)))
    # An arm h is no segment of the drawing: its length is given, or the equation names an h found nowhere.  Drawn,
    # it crowded the arms round Assur's point until two names on the triad's A4 sheet ran together.
    length = f",  h = {significant(equation.arm / sheet.length_scale)} {text['millimetre']}" if arm == "h" else ""
    return (f"{about} {sign}{unknown}·{arm} {terms} = 0,  {unknown} = {significant(equation.value)} {text['newton']}"
            f"{length}")


def _projection(sheet: ForceSheet, equation: ProjectionEquation) -> str:
    """``ΣFτ(5): R35τ + G5τ − Fu5τ = 0,  R35τ = 8.7 N``: a block's loads along its slot, each by its part along it;
    left out where the block has none."""
    largest = max((abs(value) for _, value in equation.components), default=0.0)
    parts = [f"{_sign(value)} {name}τ" for name, value in equation.components if abs(value) > NEGLIGIBLE * largest]
    if not parts:
        return ""
    return (f"ΣFτ({equation.link}): {equation.unknown} {' '.join(parts)} = 0,  {equation.unknown} = "
            f"{significant(equation.value)} {sheet.text['newton']}")


def _perpendicular(centre: complex, start: complex, end: complex, unit: complex) -> list[Primitive]:
    """The arm from ``centre`` to the line of the arrow ``start``→``end``, and the line run on to its foot."""
    foot = perpendicular_foot(centre, start, unit)
    items: list[Primitive] = [Polyline((_xy(centre), _xy(foot)), _ARM)]
    along = ((foot - start) * unit.conjugate()).real
    length = abs(end - start)
    if along < -ZERO_MM:
        items.append(Polyline((_xy(start), _xy(foot)), _ARM_RUN_ON))
    elif along > length + ZERO_MM:
        items.append(Polyline((_xy(end), _xy(foot)), _ARM_RUN_ON))
    return items


# The force polygon of a group.

# A group's polygons are drawn at its μF, whatever μl its body is drawn at: the choice of μl lays each force sheet
# out at every μl it tries, and the polygons' lettering was placed again each time.
_POLYGONS: OwnedMemo[Drawing] = OwnedMemo()


# The polygons drawn finer on a sheet with room for them, by the record and the steps: the same groups each time, so
# that each group's polygon is lettered once at its finer μF (:data:`_POLYGONS` keeps it by the group).
_FINER: OwnedMemo[ForcePlan] = OwnedMemo()


def with_finer_polygons(forces: ForcePlan, steps: int) -> ForcePlan:
    """``forces`` with every group's polygon drawn ``steps`` standard steps larger (μF 5 → 4 → 2.5 → 2 N/mm): a
    polygon at any μF closes alike and gives the same reactions; the sheet's captions then name the μF drawn."""
    def made() -> ForcePlan:
        return replace(forces, groups=tuple(replace(group, scale=finer_standard_scale(group.scale, steps))
                                            for group in forces.groups),
                       scale=finer_standard_scale(forces.scale, steps))

    return forces if steps <= 0 else _FINER.get(forces, steps, made)


def _polygons_drawing(sheet: ForceSheet, group: GroupForces) -> Drawing:
    """The polygons of :func:`_polygons`, made once for each group and language while the group lives."""
    return _POLYGONS.get(group, tuple(sheet.text.items()), lambda: _polygons(sheet, group))


def _polygons(sheet: ForceSheet, group: GroupForces) -> Drawing:
    """The group's polygon at μF; a record closed twice gives two polygons side by side."""
    text = sheet.text
    key = group_id(group.label)
    scale = group.scale
    layers: list[Layer] = []
    cursor = 0.0
    chains = _chains(group.polygon.vectors, scale)
    unnamed: list[str] = []
    for number, chain in enumerate(chains):
        drawing, left = _polygon(chain, [line for line in group.polygon.lines
                                         if any(v.name == line.label for v in chain)], scale,
                                 f"polygon-{key}" + (f"-{number + 1}" if len(chains) > 1 else ""),
                                 _wholes(group, chain, scale))
        unnamed += [_unnamed_vector(vector, chain, scale, text) for vector in left]
        x0, _, x1, _ = bounds_of(item for layer in drawing for item in layer.items)
        layers.extend(moved_layers(drawing, cursor - x0, 0.0))
        cursor += x1 - x0 + POLYGON_GAP_MM
    short = [f"{vector.name} = {significant(abs(vector.force))} {text['newton']}"
             for vector in group.polygon.vectors if too_short_to_draw(vector.force, scale)]
    apart = too_short_lines(short, text, CAPTION_WIDTH_MM)
    # One a line: broken where it runs over the polygon's width, a sum broke before its "+ R14n".
    told = _wrapped(unnamed, per_line=1)
    under = [text["polygon_unnamed"].format(sides=told[0]), *told[1:]] if told else []
    caption = (text["force_polygon_title"], *group.polygon.equations,
               text["force_scale"].format(value=format_scale(scale)), *apart, *under)
    return Drawing(f"polygon-{key}", layers, caption, run_on=_short_run_on(short, apart, text, after=len(under)))


def _short_run_on(values: Sequence[str], apart: Sequence[str], text: Mapping[str, str], after: int = 0) -> RunOn | None:
    """The polygon's vectors too short to draw (``values``, each named with its value; ``apart``, the caption's
    lines of them, ``after`` lines under them) going on after its μF where the field has the room: they are too short
    at that μF; the lever's arms so after its equation.  The words and the values on one line take the locale's
    semicolon between values, as a line with Chinese words in it does (；), where the values alone on theirs take a
    Latin one."""
    if not values:
        return None
    words = apart[0]
    # A full-width colon ends the Chinese words with its own space.
    space = "" if unicodedata.east_asian_width(words[-1]) in ("F", "W") else " "
    return RunOn(len(apart), words + space + text["semicolon"].join(values), text["semicolon"], after, tuple(values))


def too_short_to_draw(force: complex, scale: float) -> bool:
    """Whether a polygon's vector of ``force`` (N) at μF ``scale`` (N/mm) is left out of the drawing but is no
    nought: the polygon's caption names it with its value, and the note's polygon table says it is not drawn, so
    that a student measuring the polygon knows why a side is missing."""
    return abs(force) > ROUNDING_NOISE and abs(force) / scale < ZERO_MM


def _chains(vectors: Sequence[PolygonVector], scale: float) -> list[list[PolygonVector]]:
    """The polygon's vectors as closed chains: a chain ends where it returns to its start, having gone somewhere.

    An inner vector goes with the chain whose vertices it joins.  Vectors too
    short to draw close no chain of their own: a press's weights and inertia
    forces beside its 450 MN load (R23τ + ΣF3 = 0 to 0.01 mm) stood apart as
    polygons of a lone dot each.
    """
    def drawn(chain: list[PolygonVector]) -> bool:
        return any(abs(vector.force) / scale >= 0.01 for vector in chain)

    chains: list[list[PolygonVector]] = []
    current: list[PolygonVector] = []
    for vector in vectors:
        if vector.role == "inner":
            continue
        current.append(vector)
        if abs(vector.end - current[0].start) / scale < 0.01 and len(current) > 1 and drawn(current):
            chains.append(current)
            current = []
    if current:
        if chains and not drawn(current):
            chains[-1].extend(current)
        else:
            chains.append(current)
    for vector in vectors:
        if vector.role == "inner":
            vertices = [{v.start for v in chain} | {v.end for v in chain} for chain in chains]
            home = next((k for k, corner in enumerate(vertices)
                         if any(abs(vector.start - c) / scale < 0.01 for c in corner)
                         and any(abs(vector.end - c) / scale < 0.01 for c in corner)), 0)
            chains[home].append(vector)
    return chains or [[]]


def _wholes(group: GroupForces, chain: Sequence[PolygonVector], scale: float) -> list[PolygonVector]:
    """Each reaction the polygon gives in two components (R23τ, R23n) drawn whole: R23 = R23τ + R23n.

    Where one component is too short to draw, the whole is the other one
    and is not drawn over it (the caption gives its value).
    """
    by_name = {vector.name: vector for vector in chain if vector.role != "inner"}
    wholes = []
    for found in group.found:
        tangent, normal = by_name.get(f"{found.name}τ"), by_name.get(f"{found.name}n")
        if tangent is None or normal is None or min(abs(tangent.force), abs(normal.force)) / scale < ZERO_MM:
            continue
        if normal.end == tangent.start:
            wholes.append(PolygonVector(found.name, normal.start, tangent.end, "whole"))
        elif tangent.end == normal.start:
            wholes.append(PolygonVector(found.name, tangent.start, normal.end, "whole"))
    return wholes


def _polygon(chain: Sequence[PolygonVector], lines: Sequence[Line], scale: float, name: str,
             wholes: Sequence[PolygonVector]) -> tuple[list[Layer], list[PolygonVector]]:
    """One closed polygon: its lines of action, its vectors as arrows, each named beside its middle but those left
    unnamed, which are handed back for the caption to say."""
    def mm(value: complex) -> complex:
        return value / scale

    actions: list[Primitive] = []
    closing = {vector.name: vector for vector in chain if vector.role == "closing"}
    for line in lines:
        through = mm(line.through)
        unit = line.unit
        # The crossing is the far end of the closing vector the line carries.
        vector = closing.get(line.label)
        ends = [mm(vector.start), mm(vector.end)] if vector is not None else []
        crossing = max(ends, key=lambda end: abs(end - through), default=None)
        if crossing is not None and abs(crossing - through) < ZERO_MM:
            crossing = None
        if crossing is None:
            actions.append(Polyline((_xy(through - RUN_ON_MM * unit), _xy(through + RUN_ON_MM * unit)), _ACTION_RUN_ON))
            continue
        onward = (crossing - through) / abs(crossing - through)
        actions.append(Polyline((_xy(through), _xy(crossing)), _ACTION))
        actions.append(Polyline((_xy(crossing), _xy(crossing + RUN_ON_MM * onward)), _ACTION_RUN_ON))
    styles = {"load": _KNOWN, "closing": _CLOSING, "inner": _INNER, "whole": _WHOLE}
    arrows: list[Primitive] = []
    named: list[tuple[PolygonVector, Arrow]] = []
    corners = [mm(v.start) for v in chain]
    middle = sum(corners, 0j) / max(len(corners), 1)
    for vector in [*chain, *wholes]:
        if abs(mm(vector.force)) < ZERO_MM:
            continue
        start, end = mm(vector.start), mm(vector.end)
        start, end = _side_by_side(start, end, [arrow for arrow in arrows if isinstance(arrow, Arrow)], middle)
        arrow = Arrow(_xy(start), _xy(end), styles[vector.role], 3.0, svg_id(name, vector.name))
        arrows.append(arrow)
        named.append((vector, arrow))
    dots = [dot_marker(_xy(mm(chain[0].start)), 0.6)] if chain else []
    figure = actions + arrows + dots
    anchors = []
    for vector, arrow in named:
        centre = (_c(arrow.start) + _c(arrow.end)) / 2
        across = 1j * (_c(arrow.end) - _c(arrow.start))
        if ((centre - middle) * across.conjugate()).real < 0:
            across = -across
        # Beside any stretch of its side the name reads as naming it: where sides crowd at the middle (a sliver
        # of a polygon, R23n between R23 and R43), it slides along to a clear stretch rather than lie on one.
        anchors.append(Anchor(_xy(centre), vector.name, NAME_SIZE, _angle(across), arrow.stroke.colour,
                              along=(arrow.start, arrow.end)))
    # A name led across another vector's arrow reads as naming that one, as it does on the lever (or on a line, as
    # one lying there would): where the placer finds it no other spot (a sliver of sides side by side), the arrow is
    # left unnamed, one at a time, and the caption says which it is, as the lever's does (the placer still leads one
    # across an arrow where that is all that keeps it off a line, which is no better here).  A whole reaction, which
    # the student reads off the polygon, is never left unnamed: the components and given loads whose names crowd it
    # go first, and where none is left to go it keeps its leader (_whole_reaction).  Before either, a name is set on a
    # short leader across the sides side by side with its own, where one reaches out of the sliver (_sliver_spot).
    drawn_lines = obstacles_of([item for item in figure if not isinstance(item, Circle)])
    drawn = obstacles_of(figure)
    shafts = [LineString((arrow.start, arrow.end)) for _, arrow in named]
    shaft_of = {vector.name: shaft for (vector, _), shaft in zip(named, shafts)}
    vector_of = {id(anchor): vector for anchor, (vector, _) in zip(anchors, named)}
    unnamed: list[Anchor] = []
    kept: list[Anchor] = []
    # Names set on a short leader across the sides side by side with their own (_sliver_spot), which the others are
    # lettered round.
    set_by: list[tuple[Anchor, Text, Polyline]] = []
    while True:
        standing = [item for _, text, leader in set_by for item in (text, leader)]
        labels = _lettered(anchors, [*figure, *standing], unnamed=[*unnamed, *(anchor for anchor, _, _ in set_by)])
        on_a_line = [anchor for anchor, placed in zip(anchors, labels.texts) if anchor not in kept
                     and _on_a_line(anchor, placed, drawn_lines, labels.leaders,
                                    _crossed_apart(anchor, placed, labels.leaders, shafts))]
        # A whole reaction's name whose nearest arrow is another's reads as naming that one: it is set again where
        # a spot is found (_sliver_spot), but other names go for it only where it lies on a line.
        lying = on_a_line + [anchor for anchor, placed in zip(anchors, labels.texts)
                             if anchor not in kept and anchor not in on_a_line and _whole_reaction(anchor.text)
                             and not _reads_as_own(anchor, placed, labels.leaders, shaft_of)]
        if not lying:
            break
        first = min(lying, key=lambda anchor: not _whole_reaction(anchor.text))
        placed = labels.texts[anchors.index(first)]
        own = _own_leaders(first, placed, labels.leaders)
        spot = _sliver_spot(first, drawn, [text for anchor, text in zip(anchors, labels.texts) if anchor is not first]
                            + [text for _, text, _ in set_by],
                            [leader for leader in labels.leaders if leader not in own]
                            + [leader for _, _, leader in set_by], shaft_of)
        gone = first
        if spot is not None:
            set_by.append((first, *spot))
        elif not _whole_reaction(first.text):
            unnamed.append(first)
        elif first not in on_a_line:
            kept.append(first)
            continue
        else:
            box = text_box(placed)
            crowding = sorted((anchor for anchor, text in zip(anchors, labels.texts)
                               if not _whole_reaction(anchor.text) and text_box(text).distance(box) < CROWDING_MM),
                              key=lambda anchor: text_box(labels.texts[anchors.index(anchor)]).distance(box))
            if not crowding:
                kept.append(first)
                continue
            gone = crowding[0]
            unnamed.append(gone)
        anchors = [anchor for anchor in anchors if anchor is not gone]
    labels = Placement((*labels.texts, *(text for _, text, _ in set_by)),
                       (*labels.leaders, *(leader for _, _, leader in set_by)))
    return [Layer(f"{name}-lines", tuple(actions)), Layer(f"{name}-vectors", tuple(arrows + dots)),
            Layer(f"{name}-leaders", labels.leaders), Layer(f"{name}-labels", labels.texts)], [
        vector_of[id(anchor)] for anchor in unnamed]


def _unnamed_vector(vector: PolygonVector, chain: Sequence[PolygonVector], scale: float, text: Mapping[str, str]
                    ) -> str:
    """Which arrow of the polygon ``chain`` (at μF ``scale``) the vector left unnamed is, for its caption: a reaction
    drawn whole as the sum of its components (R23 = R23τ + R23n, drawn from the first one's tail to the other's head),
    any other by the side drawn whose head it starts from (the sides run head to tail in the equation's order; one
    too short to draw, the slider driven mechanism's Fu3 at position 3, is no side to find it by)."""
    parts = sorted((side for side in chain if side.name in (f"{vector.name}τ", f"{vector.name}n")),
                   key=lambda side: abs(side.start - vector.start))
    if vector.role == "whole" and len(parts) == 2:
        return f"{vector.name} = {parts[0].name} + {parts[1].name}"
    sides = [side for side in chain if side.role != "inner" and side is not vector
             and not too_short_to_draw(side.force, scale)]
    before = min(sides, key=lambda side: abs(side.end - vector.start), default=None)
    return vector.name if before is None else text["polygon_side_from"].format(name=vector.name, before=before.name)


def _whole_reaction(name: str) -> bool:
    """Whether ``name`` is a whole reaction's (R23, R43), which a student reads off the polygon, not a component's
    (R23n, R23τ) or a given load's (G3, Fu3), steps of the construction its caption may tell."""
    return re.fullmatch(r"R\d+", name) is not None


def _crossed_apart(anchor: Anchor, text: Text, leaders: Sequence[Polyline], shafts: Sequence[LineString]
                   ) -> list[LineString]:
    """The arrows' ``shafts`` that ``anchor``'s leader, led to its placed ``text``, would be misread across: all, but
    where the leader is shorter than :data:`SLIVER_LEADER_MM` those side by side with the line the name names (within
    :data:`SLIVER_DEG` of it)."""
    own = _own_leaders(anchor, text, leaders)
    if anchor.along is None or not own or max(LineString(leader.points).length for leader in own) >= SLIVER_LEADER_MM:
        return list(shafts)
    return [shaft for shaft in shafts if not _side_by_side_with(anchor, shaft)]


def _own_leaders(anchor: Anchor, text: Text, leaders: Sequence[Polyline]) -> list[Polyline]:
    """The leader led from ``anchor``'s point or line to its placed ``text`` (none where it stands beside it): one
    that starts by its line and stops short of its box (another side's by the line in a sliver stops elsewhere)."""
    box = text_box(text)
    return [leader for leader in leaders
            if _led_from(leader, anchor) and box.distance(ShapelyPoint(leader.points[-1])) < 0.5]


def _sliver_spot(anchor: Anchor, drawn: Sequence[BaseGeometry], texts: Sequence[Text], leaders: Sequence[Polyline],
                 shaft_of: Mapping[str, LineString]) -> tuple[Text, Polyline] | None:
    """A spot for the name of a polygon's side ``anchor`` that the placer left on a line or led across an arrow: its
    text and leader, the leader shorter than :data:`SLIVER_LEADER_MM` and across no ``drawn`` shape but lines side by
    side with the side it names, the text clear of every drawn shape and of the other ``texts`` and ``leaders``, or,
    where there is none, on a leader up to :data:`WHOLE_LEADER_MM` across nothing where the name reads as naming its
    own arrow; None where there is neither.  A whole reaction's name is set only where it reads as naming its own
    arrow of those in ``shaft_of`` (_reads_as_own), on a leader up to :data:`WHOLE_LEADER_MM` where a short one finds
    no such spot.

    In a sliver of sides the placer, costing a leader across an arrow as two leaders crossing, led a name the long way
    round (the crank-rocker starter's R23 at position 5, 7 mm across R23n and R43) where a hand drawing leads it a
    little way across the sides side by side with its own, out of the sliver."""
    if anchor.along is None:
        return None
    if not _whole_reaction(anchor.text):
        # Where no short leader reaches out of a sliver, a leader that crosses nothing may be longer, and the name
        # may stand off the side obliquely or by its ends: the offset slider-crank's R23n at position 10, led 10 mm
        # across R23 and R14's line at b76b78f, stands right of its head, beyond G3's name, which stands square to
        # the side (left to the caption, it made that force sheet too tall to share an A1 sheet with its lever).
        short_leader = next(_sliver_spots(anchor, drawn, texts, leaders, SLIVER_LEADER_MM), None)
        if short_leader is not None:
            return short_leader
        return next((spot for spot in _sliver_spots(anchor, drawn, texts, leaders, WHOLE_LEADER_MM, clear=True)
                     if _reads_as_own(anchor, spot[0], [spot[1]], shaft_of)), None)

    def nearest_box(text: Text) -> str:
        box = text_box(text)
        return min(shaft_of, key=lambda name: shaft_of[name].distance(box))

    # A whole reaction's name stands beside its own arrow where it can; else on a leader that is followed to its own
    # line, beside one of its own components, or beside an arrow side by side with its own, the leader across the
    # sliver (the crank-rocker starter's R23 at position 5 beyond R23n and R43, as at b76b78f), sooner than beside any
    # other arrow (beyond R14, by R14τ and just above R14's own name, it read as naming R14).
    own = {anchor.text, f"{anchor.text}n", f"{anchor.text}τ"}
    for longest, fits in ((SLIVER_LEADER_MM, lambda text, leader: _reads_as_own(anchor, text, [], shaft_of)),
                          (WHOLE_LEADER_MM, lambda text, leader: nearest_box(text) in own
                           and _reads_as_own(anchor, text, [leader], shaft_of)),
                          (WHOLE_LEADER_MM, lambda text, leader: _side_by_side_with(anchor, shaft_of[nearest_box(text)])
                           and _reads_as_own(anchor, text, [leader], shaft_of)),
                          (WHOLE_LEADER_MM, lambda text, leader: _reads_as_own(anchor, text, [leader], shaft_of))):
        spot = next((spot for spot in _sliver_spots(anchor, drawn, texts, leaders, longest) if fits(*spot)), None)
        if spot is not None:
            return spot
    return None


def _sliver_spots(anchor: Anchor, drawn: Sequence[BaseGeometry], texts: Sequence[Text], leaders: Sequence[Polyline],
                  longest: float, clear: bool = False) -> Iterator[tuple[Text, Polyline]]:
    """The spots _sliver_spot chooses from, nearest the side first, their leaders shorter than ``longest`` (mm); with
    ``clear``, leaders that cross no drawn shape at all, their boxes set out square to the side or turned toward
    either end of it, from more points along it."""
    start, end = _c(anchor.along[0]), _c(anchor.along[1])
    width = text_width(anchor.text, anchor.size)
    shapes = np.array(drawn, dtype=object)
    # Thousands of candidate spots are each tested against every shape: trees answer by the shapes near them.
    shape_tree = STRtree(shapes)
    leader_lines = [LineString(leader.points) for leader in leaders]
    box_blockers = STRtree([*drawn, *(spaced_box(text) for text in texts), *leader_lines])
    led = STRtree(leader_lines)
    # What a leader may cross: the sides side by side with the one it names (and the lines of action along them).
    uncrossable = STRtree([shape for shape in drawn
                           if not (shape.geom_type == "LineString" and _side_by_side_with(anchor, shape))])
    # Nearest the side first (a box set out square to a slanting side comes nearer it by a corner: the leader's
    # length, not the reach, decides how far out it may stand); along it from its middle outwards, either side of it.
    shares = (0.5, 0.625, 0.375, 0.75, 0.25, 0.875, 0.125) + ((0.9375, 0.0625) if clear else ())
    sides = [1j, -1j] if not clear else [side * np.exp(1j * math.radians(turn)) for side in (1j, -1j)
                                         for turn in CLEAR_TURNS_DEG]
    for reach in np.arange(LEADER_CLEARANCE + LEADER_GAP + 0.2, longest + 2 * anchor.size, 0.2):
        # The leader's length first, from the box's corners alone: most spots fail it, before any shape is made; the
        # boxes of one reach then asked of the tree at once.
        spots = []
        for share in shares:
            point = start + (end - start) * share
            for side in sides:
                out = side * (end - start) / abs(end - start)
                # As the placer sets a box out from its point (labels._candidates): its near edge ``reach`` off.
                x, y = set_out(point.real, point.imag, out.real, out.imag, reach, width / 2, anchor.size)
                text = Text((x, y), anchor.text, anchor.size, "middle", anchor.colour)
                extent = text_extent(text)
                near = complex(min(max(point.real, extent[0]), extent[2]), min(max(point.imag, extent[1]), extent[3]))
                reach_to_box = abs(near - point)
                if (LEADER_CLEARANCE + LEADER_GAP + SLIVER_LEADER_LEAST_MM <= reach_to_box
                        <= longest + LEADER_CLEARANCE + LEADER_GAP + 1e-9):
                    spots.append((point, text, extent, near, reach_to_box))
        if not spots:
            continue
        blocked = set(box_blockers.query(shapely.box(*np.array([spot[2] for spot in spots]).T),
                                         predicate="intersects")[0].tolist())
        for index, (point, text, extent, near, reach_to_box) in enumerate(spots):
            if index in blocked:
                continue
            toward = (near - point) / reach_to_box
            leader = LineString((_xy(point + toward * LEADER_CLEARANCE), _xy(near - toward * LEADER_GAP)))
            # Run on to the box: an arrow in the gap between the leader's end and the letters reads as crossed.
            reaching = LineString((_xy(point), _xy(near)))
            if leader.length >= longest or _meets(led, leader) or _meets(uncrossable, reaching):
                continue
            # Off the side's own shapes (its shaft, head and line) the leader, run on to the box, meets nothing, and
            # it runs along no other line: its middle stands as far off them as two sides set side by side.
            if clear and (_meets(shape_tree, LineString((_xy(point + toward * LEADER_CLEARANCE), _xy(near))))
                          or (shapely.distance(leader.interpolate(0.5, normalized=True),
                                               shapes[shapely.distance(ShapelyPoint(_xy(point)), shapes) > ZERO_MM])
                              < SIDE_BY_SIDE_MM).any()):
                continue
            yield text, Polyline(tuple(leader.coords), Stroke(LEADER_WIDTH, anchor.colour))


def _meets(tree: STRtree, geometry: BaseGeometry) -> bool:
    return tree.query(geometry, predicate="intersects").size > 0


def _reads_as_own(anchor: Anchor, text: Text, leaders: Sequence[Polyline], shaft_of: Mapping[str, LineString]
                  ) -> bool:
    """Whether ``anchor``'s placed ``text`` reads as naming its own of the polygon's arrows (``shaft_of``, by name):
    the eye takes the arrow nearest the name (its own, no more than :data:`TIE_MM` farther), or, on a leader long
    enough to be followed (:data:`SLIVER_LEADER_MM`), the first one the leader, run on past its end by the line, meets
    (its own components apart)."""
    followed = [leader for leader in _own_leaders(anchor, text, leaders)
                if LineString(leader.points).length >= SLIVER_LEADER_MM]
    if followed:
        start, end = _c(followed[0].points[0]), _c(followed[0].points[-1])
        run_on = LineString((_xy(start), _xy(start + (start - end) / abs(start - end) * 3 * LEADER_CLEARANCE)))
        # Its own components, drawn from its tail or to its head, may run between it and the leader's end.
        parts = (f"{anchor.text}n", f"{anchor.text}τ")
        met = [(ShapelyPoint(_xy(start)).distance(shaft.intersection(run_on)), name)
               for name, shaft in shaft_of.items() if name not in parts and shaft.intersects(run_on)]
        return bool(met) and min(met)[1] == anchor.text
    box = text_box(text)
    return shaft_of[anchor.text].distance(box) <= min(shaft.distance(box) for shaft in shaft_of.values()) + TIE_MM


def _side_by_side_with(anchor: Anchor, line: LineString) -> bool:
    """Whether ``line`` runs within :data:`SLIVER_DEG` of the line ``anchor`` names (its ``along``)."""
    (x0, y0), (x1, y1) = line.coords[0], line.coords[-1]
    turn = complex(x1 - x0, y1 - y0) * (_c(anchor.along[1]) - _c(anchor.along[0])).conjugate()
    apart = abs(math.degrees(math.atan2(turn.imag, turn.real)))
    return min(apart, 180.0 - apart) < SLIVER_DEG


def _side_by_side(start: complex, end: complex, arrows: Sequence[Arrow], middle: complex) -> tuple[complex, complex]:
    """The vector ``start``→``end`` of a polygon, moved square to itself by :data:`SIDE_BY_SIDE_MM` (or twice
    that, where another side stands there) where it runs back along a side drawn before (a polygon that closes
    on a straight line: R43 + ΣF3 + R23 = 0).

    Drawn over each other, the two sides hide each other's heads; side by
    side, as a hand drawing sets them, both read.  It moves away from the
    polygon's ``middle`` first, or to its left where the polygon is flat.
    """
    length = abs(end - start)
    unit = (end - start) / length

    def along(first: complex, last: complex, arrow: Arrow, back: bool) -> bool:
        """Whether ``first``→``last`` runs along ``arrow`` (back along it, if ``back``) for more than 1 mm."""
        other = _c(arrow.end) - _c(arrow.start)
        if arrow.length < ZERO_MM or ((unit.conjugate() * other).real < 0) != back:
            return False
        if abs((unit.conjugate() * other).imag) / arrow.length > math.sin(math.radians(3.0)):
            return False
        return LineString((_xy(first), _xy(last))).intersection(
            LineString((arrow.start, arrow.end)).buffer(0.8)).length >= 1.0

    if not any(along(start, end, arrow, True) for arrow in arrows):
        return start, end
    aside = 1j * unit
    if ((middle - start) * aside.conjugate()).real > 0.5:
        aside = -aside
    for shift in (SIDE_BY_SIDE_MM * aside, -SIDE_BY_SIDE_MM * aside, 2 * SIDE_BY_SIDE_MM * aside,
                  -2 * SIDE_BY_SIDE_MM * aside):
        if not any(along(start + shift, end + shift, arrow, back) for arrow in arrows for back in (True, False)):
            return start + shift, end + shift
    return start + SIDE_BY_SIDE_MM * aside, end + SIDE_BY_SIDE_MM * aside


# Zhukovsky's lever.

# A velocity plan whose points crowd round the pole (two of them closer than this, mm) is drawn larger as
# the lever, its longest ray this long (mm): a similar figure at any scale gives the same balancing load,
# and at the plan's own size the loads, their arms and their names at the crowded points run together.
LEVER_CROWDED_MM = 15.0
LEVER_LONGEST_RAY_MM = 250.0
# Two points of the lever need this much room between them (mm) for each load drawn at either, where that is more
# than LEVER_CROWDED_MM: about a name's height, each load's name standing by its arrow's free end, so that the 15 mm
# is the room of the usual five (a centre of mass's weight and inertia force, a link's end with a couple's force, and
# one more).  With friction a couple of friction at each end of a link puts a force at each: the lift's friction lever
# of position 3, 18 loads at points 19.2 mm apart, kept at its plan's size by the 15 mm alone, ran its arrows and
# names together.
LEVER_ROOM_PER_LOAD_MM = 3.0


def lever_loads_at(velocity: Plan, lever: Lever | None) -> dict[str, int]:
    """How many load arrows the lever draws at each point of the plan, by the point's first letter (its spot's,
    :func:`coincident_letters`): its loads' and the balancing force's, none too small beside the others to be
    drawn."""
    if lever is None:
        return {}
    spot_of = {letter: group[0] for group in coincident_letters(velocity) for letter in group}
    drawn = [(term.image, term.force) for term in lever.terms if term.image and term.force != 0]
    drawn.append((lever.balancing_image, lever.balancing_force))
    counts: dict[str, int] = {}
    for image, force in drawn:
        if image in spot_of and not _negligible(force, [other for _, other in drawn]):
            counts[spot_of[image]] = counts.get(spot_of[image], 0) + 1
    return counts


def enlarged_lever_scale(velocity: Plan, lever: Lever | None = None) -> float | None:
    """The standard μV that draws the lever of ``velocity`` larger than the plan, where its points crowd.

    Two points crowd where they stand closer than :data:`LEVER_CROWDED_MM`, or than the room the loads ``lever``
    draws at both take (:data:`LEVER_ROOM_PER_LOAD_MM` each).  None where the plan is drawn clear enough or already
    as large.
    """
    spots = [group[0] for group in coincident_letters(velocity)]
    loads = lever_loads_at(velocity, lever)

    def room(one: str, other: str) -> float:
        return max(LEVER_CROWDED_MM, LEVER_ROOM_PER_LOAD_MM * (loads.get(one, 0) + loads.get(other, 0)))

    if not any(abs(velocity.mm(a) - velocity.mm(b)) < room(a, b) for i, a in enumerate(spots) for b in spots[i + 1:]):
        return None
    larger = fit_scale(max(abs(value) for value in velocity.points.values()), LEVER_LONGEST_RAY_MM)
    return larger if draws_larger(larger, velocity.scale) else None


def draws_larger(scale: float, than: float) -> bool:
    """Whether the scale factor ``scale`` draws larger than ``than``, by more than rounding."""
    return scale < than * (1.0 - 1e-9)


# The lever is drawn at μV, whatever μl the groups are drawn at: choosing μl lays each force sheet out at
# every μl it tries, and the lever's lettering was placed again each time (three quarters of a triad's run).
_LEVERS: OwnedMemo[Drawing] = OwnedMemo()


def _lever_drawing(sheet: ForceSheet, lever: Lever) -> Drawing:
    """The lever of :func:`_lever`, made once for each lever, plan and scale while the lever lives."""
    # What _lever reads of the sheet besides the lever (a lever's plan position holds its velocity plan).
    key = (id(sheet.velocity), sheet.lever_drawn_scale, sheet.lever_scale_line, sheet.forces.balancing,
           sheet.mechanism.scene.frame_link, sheet.mechanism.scene.drawing.drafting_precision,
           tuple(sheet.text.items()))
    return _LEVERS.get(lever, key, lambda: _lever(sheet, lever))


def _lever(sheet: ForceSheet, lever: Lever) -> Drawing:
    """The velocity plan turned 90° clockwise about the pole p, the loads at the images of their points."""
    text = sheet.text
    velocity = sheet.velocity
    drawn_at = sheet.lever_drawn_scale

    def mm(letter: str) -> complex:
        return turned(velocity.points[letter]) / drawn_at

    # The rays from the pole thin, each link's figure (its points' hull) as a bar of the lever.
    frame: list[Primitive] = []
    for letter in sorted(set(velocity.images.values())):
        if letter != "p" and abs(mm(letter)) >= ZERO_MM:
            frame.append(Polyline(((0.0, 0.0), _xy(mm(letter))), _RAY))
    for link in sorted(velocity.members):
        if link == sheet.mechanism.scene.frame_link:
            continue
        letters = sorted({letter for _, letter in velocity.members[link]})
        hull = MultiPoint([_xy(mm(letter)) for letter in letters]).convex_hull
        if hull.geom_type == "Polygon" and hull.area > ZERO_MM ** 2:
            frame.append(Polyline(tuple(hull.exterior.coords)[:-1], _LEVER, closed=True))
        elif hull.geom_type == "LineString" and hull.length >= ZERO_MM:
            frame.append(Polyline(tuple(hull.coords), _LEVER))
    named = [(term.name, term.image, term.force, _LOAD, turned(term.shift) / drawn_at)
             for term in lever.terms if term.image and term.force != 0]
    named.append(("Fb", lever.balancing_image, lever.balancing_force, _BALANCING, 0j))
    scale = _arrow_scale([force for _, _, force, _, _ in named], frame)
    arrows: list[Primitive] = []
    leaders: list[Primitive] = []
    anchors: list[Anchor] = []
    arm_layers: list[Layer] = []
    arm_anchors: list[Anchor] = []
    arm_lengths: dict[str, float] = {}  # on the drawing, mm
    parts: list[str] = []
    moments = {term.name: term.moment for term in lever.terms}
    # Beside the loads' powers at the plan's fastest point, a term's is rounding where its point stands still or moves
    # square to it: at a Scotch yoke's dead centre every one is, and the lever wrote h1 = 0.000000000000006661 mm
    # and Mb = −0.00000000000001040 N·m where the polygons find Mb = 0.
    reach = (max((abs(value) for value in velocity.points.values()), default=0.0)
             * max((abs(term.force) for term in lever.terms), default=0.0))

    def stands(term: LeverTerm) -> bool:
        return lever.stands(term) and abs(term.moment) > TERM_ROUNDING * reach

    standing = {term.name for term in lever.terms if stands(term)} | {"Fb"}
    arm_of = _arm_names(sheet, lever, [(name, image, force) for name, image, force, _, _ in named if name in standing
                                       and not _negligible(force, [other for _, _, other, _, _ in named])])
    balancing = lever.balancing if len(standing) > 1 else 0.0
    undrawn: list[str] = []  # arms in the equation too short to draw, given under it
    load_points: dict[str, str] = {}  # each named load's point on the lever, where its arrow stands
    # The lever's bars and rays, and every arm (from the pole square to its force's line wherever the arrow
    # stands on it), which an arrow pushing onto its point must not lie along.
    feet = [perpendicular_foot(0j, mm(image) + shift, force / abs(force))
            for _, image, force, _, shift in named if force != 0]

    # The points of the lever, one for each spot its letters stand at, which another point's load keeps clear of.
    spots = [mm(group[0]) for group in coincident_letters(velocity)]

    @functools.cache
    def lines() -> BaseGeometry:
        # Made only for a load drawn onto its point or beside, which few are: grown from the union of all the
        # lever's lines, it took a quarter of a second a lever.
        return _grown([LineString(item.points + item.points[:1] if item.closed else item.points)
                       for item in frame if isinstance(item, Polyline)]
                      + [LineString(((0.0, 0.0), _xy(foot))) for foot in feet if abs(foot) >= ZERO_MM], 0.8)

    for name, image, force, stroke, shift in named:
        if _negligible(force, [other for _, _, other, _, _ in named]):
            continue
        length = abs(force) / scale
        unit = force / abs(force)
        at = mm(image) + shift
        others = [spot for spot in spots if abs(spot - mm(image)) >= ZERO_MM]
        start, end, beside = _pushing_or_pulling(at, max(length, LEAST_ARROW_MM) * unit, arrows, lines, others)
        arrows.append(Arrow(_xy(start), _xy(end), stroke, 3.0, svg_id("lever", name)))
        if beside:
            leaders.append(Polyline((_xy(at), _xy(start)), Stroke(_LEADER_WIDTH, stroke.colour)))
        # Named at its free end: its head, or its tail where it pushes onto its point.
        free, outward = (start, -unit) if _points_onto(start, end, at + beside) else (end, unit)
        anchors.append(Anchor(_xy(free), name, NAME_SIZE, _angle(outward), stroke.colour))
        load_points[name] = image
        # The arm runs to the force's line, through its point, beside which the arrow may stand.
        start, end = start - beside, end - beside
        foot = perpendicular_foot(0j, start, unit)
        if name not in standing:
            continue
        arm = arm_of[name]
        if name != "Fb":
            parts.append(f"{_sign(moments[name])} {name}·{arm}")
        if arm in arm_lengths:
            # Its arm is drawn and named with the first load on its line: only the line is run on to its foot.
            if run_on := _perpendicular(0j, start, end, unit)[1:]:
                arm_layers.append(Layer(svg_id("lever-arm", name), tuple(run_on)))
            continue
        arm_lengths[arm] = abs(foot)
        if abs(foot) < ZERO_MM:
            # Too short to draw (a point's image by the pole, near a dead centre), its moment is still in Mb.
            undrawn.append(arm)
            continue
        arm_layers.append(Layer(svg_id("lever-arm", name), tuple(_perpendicular(0j, start, end, unit))))
        # Named out of the pole's reach where the room round it allows; a name left within it is dropped (below).
        arm_anchors.append(Anchor(_xy(0.8 * foot), arm, NAME_SIZE - 0.4, _angle(1j * foot), _ARM.colour,
                                  along=((0.0, 0.0), _xy(foot)), keep_off=((0.0, 0.0), POLE_CLEAR_MM)))
    # M·ω is a power (W); the lever's terms F·h are N·mm at μV: a block's moment enters as M·ω/μV.
    parts += [f"{_sign(term.moment)} {term.name}·ω{term.link}/μV" for term in lever.terms
              if not term.image and stands(term)]
    arrows += leaders
    groups = coincident_letters(velocity)  # a turn keeps distances: the plan's own grouping
    dots = [dot_marker(_xy(mm(group[0])), 0.7 if group[0] == "p" else 0.5) for group in groups]
    figure = frame + arrows + dots + [item for layer in arm_layers for item in layer.items]
    for group in groups:
        where = _xy(mm(group[0]))
        anchors.append(Anchor(where, ", ".join(group), POINT_SIZE, open_direction(where, frame + arrows)))
    # An arm lettered within reach of the pole (a short one, or one whose name found no room farther out) names
    # no arm there, among the names of the loads at p and every other arm's start: it is left unlettered and
    # its length stands under the drawing, beside the equation that names its force.  So is one whose name found no
    # spot beside its arm off the other lines (the arms and loads crowding round the pole of a triad's lever): a
    # grey name lying on another line reads as naming that one.
    # Placed again without them, another arm's name may take the room they left: until none stands there.
    # Then a load's name that lies on a line even so (the crowd of a triad's lever round d, f and s6, where no spot
    # within reach of its arrow is off the lines), or that stands nearer another load's free end than its own, led to
    # it or not (G3 by Mu4″'s head on the lift's lever, Fu6 by Ff16's on the knee press's), is given under the lever
    # too, by the point its arrow stands at, one at a time, each point keeping one arrow unnamed at most: the only
    # arrow at s6 without a name is G6's.
    drawn_lines = obstacles_of([item for item in figure if not isinstance(item, Circle)])
    shafts = [LineString((item.start, item.end)) for item in arrows if isinstance(item, Arrow)]
    crowded: list[Anchor] = []
    lettered = list(arm_anchors)
    loads, points = anchors[:len(load_points)], anchors[len(load_points):]
    unnamed: list[Anchor] = []
    while True:
        labels = _lettered(loads + points + lettered, figure, reach_farther=False, unnamed=unnamed)
        if near := [anchor for anchor, placed in zip(lettered, labels.texts[len(loads) + len(points):])
                    if text_box(placed).distance(ShapelyPoint(0.0, 0.0)) < POLE_CLEAR_MM
                    or _on_a_line(anchor, placed, drawn_lines, labels.leaders, shafts)]:
            crowded += near
            lettered = [anchor for anchor in lettered if anchor not in near]
            continue
        taken = {load_points[anchor.text] for anchor in unnamed}
        # Fb's head is left out: drawn and named in its own colour, it is not taken for a load's.  An arrow left unnamed
        # keeps its head on the drawing, by which another's name reads as its.
        heads = [anchor.at for anchor in anchors[:len(load_points)] if anchor.text != "Fb"]
        lying = [anchor for anchor, placed in zip(loads, labels.texts) if anchor.text != "Fb"
                 and load_points[anchor.text] not in taken
                 and (_on_a_line(anchor, placed, drawn_lines, labels.leaders, shafts)
                      or _by_another_head(anchor, placed, heads, labels.leaders))]
        if not lying:
            break
        unnamed.append(lying[0])
        loads = [anchor for anchor in loads if anchor is not lying[0]]
    given = sorted([anchor.text for anchor in crowded], key=list(arm_lengths).index)
    # An arm too short to draw is said to be so, as the plans and the polygons say it of their vectors: given among
    # the arms drawn but left unlettered, h5 = 0.2205 mm read as an arm the reader should find on the lever.
    short = [f"{arm} = {significant(arm_lengths[arm])} {text['millimetre']}" for arm in undrawn]
    apart = too_short_lines(short, text, CAPTION_WIDTH_MM, words="arms_too_short")
    unnamed_at = _wrapped([text["lever_load_at"].format(name=anchor.text, point=load_points[anchor.text])
                           for anchor in unnamed])
    parts.append(f"{_sign(-sum(moments[name] for name in standing - {'Fb'}))} Fb·hb")
    equation = _leading(" ".join(parts))
    # Drawn turned as every lever is: a reader laying the velocity plan beside it must know which way.
    caption = [text["lever_title"], text["lever_turned"],
               text["comma"].join((sheet.lever_scale_line,
                                   text["body_force_scale"].format(value=format_scale(scale),
                                                                   least=f"{LEAST_ARROW_MM:g}"))),
               f"ΣMp: {equation} = 0",
               *_wrapped([f"{arm} = {significant(arm_lengths[arm])} {text['millimetre']}" for arm in given]),
               *apart]
    under = [*([text["lever_unnamed"].format(loads=unnamed_at[0]), *unnamed_at[1:]] if unnamed_at else []),
             # The symbol alone: "balancing moment" said twice broke each line in two under a narrow lever (the
             # lever's title and its ΣMp say what Mb is).
             _balancing_line(sheet, balancing, "balancing_by_lever", named=False),
             _balancing_line(sheet, sheet.forces.balancing, "balancing_by_polygons", named=False),
             text["lever_difference"].format(value=_percent(lever.difference_percent(sheet.forces.balancing)))]
    return Drawing("lever", [Layer("lever-plan", tuple(frame)), *arm_layers, Layer("lever-forces", tuple(arrows)),
                             Layer("lever-points", tuple(dots)), Layer("lever-leaders", labels.leaders),
                             Layer("lever-labels", labels.texts)], (*caption, *under),
                   run_on=_short_run_on(short, apart, text, after=len(under)))


def _arm_names(sheet: ForceSheet, lever: Lever, loads: Sequence[tuple[str, str, complex]]) -> dict[str, str]:
    """The name of each standing load's arm on the lever (``loads``: name, image, force, in the order they are drawn,
    the balancing force Fb last): h1, h2, … in order, hb the balancing force's, one name for the loads whose lines
    are one line within the drafting precision (:func:`~graphplan.lever.shared_arms`), hb where Fb is among them."""
    shifts = {term.name: term.shift for term in lever.terms}
    tolerance = sheet.mechanism.scene.drawing.drafting_precision * sheet.lever_drawn_scale
    names: dict[str, str] = {}
    count = 0
    for gathered in shared_arms(sheet.velocity, [(name, image, force, shifts.get(name, 0j))
                                                 for name, image, force in loads], tolerance):
        if "Fb" in gathered:
            arm = "hb"
        else:
            count += 1
            arm = f"h{count}"
        names.update(dict.fromkeys(gathered, arm))
    return names


def _lettered(anchors: Sequence[Anchor], figure: Sequence[Primitive],
              reach_farther: bool | Sequence[bool] = True, unnamed: Sequence[Anchor] = ()) -> Placement:
    """The labels of ``anchors`` placed clear of the figure and of every anchor's own spot, and of the spots of the
    ``unnamed`` (a lever's arrows whose names are given under it).

    A label covering another one's anchor (the tail of a moment's arc)
    would leave that one no room beside it, so the anchors count as points.
    """
    # The discs of shapely's Point.buffer (16 segments a quarter), made at once.  An arrow left unnamed keeps its head:
    # a name placed again over it (G2 on Fu3's head, the lift's friction lever of position 9) reads as its.
    centres = np.reshape([anchor.at for anchor in [*anchors, *unnamed]], (-1, 2))   # (0, 2) with no names
    spots = list(shapely.buffer(shapely.points(centres), 0.8, quad_segs=16))
    # A leader across an arrow reads as part of it, or as naming its load: the placer costs it as two leaders crossing.
    obstacles, shafts = obstacles_and_shafts(figure)
    return remembered(place_labels, anchors, obstacles + spots, reach_farther=reach_farther, shafts=shafts)


def _on_a_line(anchor: Anchor, text: Text, lines: Sequence[BaseGeometry], leaders: Sequence[Polyline],
               shafts: Sequence[BaseGeometry] = ()) -> bool:
    """Whether the placed label of ``anchor`` lies on one of the drawn ``lines`` or on another label's leader (its
    own starts by its point), or is led to across one of the ``shafts`` (the loads' arrows)."""
    box = text_box(text)
    others = [LineString(leader.points) for leader in leaders if not _led_from(leader, anchor)]
    if any(box.intersects(line) for line in [*lines, *others]):
        return True
    # Its own leader: from by its point to by its box (the placer stops it short of the box).  Across an arrow it
    # reads as part of that arrow, or as naming that load, as a name on a line reads as naming the line.
    own = [LineString(leader.points) for leader in leaders if _led_from(leader, anchor)
           and box.distance(ShapelyPoint(leader.points[-1])) < 0.5]
    return any(leader.intersects(shaft) for leader in own for shaft in shafts)


def _led_from(leader: Polyline, anchor: Anchor) -> bool:
    """Whether ``leader`` is the one led from ``anchor``'s point: a placed leader starts by the point it names, or by
    another point of the line it names (its ``along``: a polygon's side's name led from a clear stretch of it)."""
    start = leader.points[0]
    if math.dist(start, anchor.at) <= 1.0:
        return True
    return anchor.along is not None and LineString(anchor.along).distance(ShapelyPoint(start)) <= 1.0


# A load's name standing this much (mm) nearer another load's free end than its own names that load: the friction
# lever of the lift's position 3 had G3 by Mu4″'s head, 0.8 mm from it and 2.4 mm from G3's own.
OTHER_HEAD_MARGIN_MM = 0.5
# A leader ties a name to its own arrow, but not against another load's free end this near the name (mm): on the knee
# press's friction lever of position 5 Fu6's name stood 1.9 mm from Ff16's head and 6.9 mm from its own tail, its
# leader running from its tail to that head, and it read as Ff16's; on its lever of position 6 Mu5′ stood 1.6 mm
# from G2's head.  Farther off, the leader says whose the name is (a triad's Mu4″, 5.6 mm from Mu5″'s head).
LED_NAME_HEAD_CLEAR_MM = 2.5


def _by_another_head(anchor: Anchor, text: Text, heads: Sequence[tuple[float, float]],
                     leaders: Sequence[Polyline]) -> bool:
    """Whether the placed name of ``anchor`` stands nearer another of the loads' free ends ``heads`` than its own: a
    reader takes it for that load's name, where it stands by that head even on a leader of its own."""
    led = any(_led_from(leader, anchor) for leader in leaders)
    box = text_box(text)
    own = box.distance(ShapelyPoint(anchor.at))
    for head in heads:
        if math.dist(head, anchor.at) <= 1e-6:
            continue
        apart = box.distance(ShapelyPoint(head))
        if apart < own - OTHER_HEAD_MARGIN_MM and (not led or apart < LED_NAME_HEAD_CLEAR_MM):
            return True
    return False


def _negligible(force: complex, forces: Sequence[complex]) -> bool:
    """Whether a force is nought beside the others (a rounding error): it is not drawn.

    A small force that is there (a link's weight beside the inertia loads)
    is drawn, at least :data:`LEAST_ARROW_MM` long.
    """
    return abs(force) <= NEGLIGIBLE * max((abs(other) for other in forces), default=0.0)


def _arrow_scale(forces: Sequence[complex], figure: Sequence[Primitive]) -> float:
    """The standard force scale (N/mm) that draws the largest of ``forces`` about a quarter of the figure's size."""
    largest = max((abs(force) for force in forces), default=0.0)
    x0, y0, x1, y1 = bounds_of(figure)
    longest = min(max(ARROW_SHARE * max(x1 - x0, y1 - y0), LONGEST_ARROW_MM[0]), LONGEST_ARROW_MM[1])
    return standard_scale(largest / longest) if largest > 0 else 1.0


# Text.

def _balancing_line(sheet: ForceSheet, value: float, how: str, named: bool = True) -> str:
    """The balancing load found ``how``, with its words (``balancing moment Mb = …``) or, not ``named``, its
    symbol alone."""
    text = sheet.text
    name, unit = balancing_symbol(sheet.mechanism, text)
    what = text["balancing_moment" if name == "Mb" else "balancing_force"] if named else ""
    return text[how].format(what=what, name=name, value=significant(value), unit=unit).strip()


def _wrapped(items: Sequence[str], per_line: int = PER_LINE) -> list[str]:
    """Values listed ``per_line`` to a caption line, each line but the last ending in the comma between values.

    Without it the lever's fifth arm ran on from the fourth as one value: "h18 = 0.2587 mm" over "h19 = 21.21 mm",
    where a line the caption breaks keeps its comma ("R45 = 2141 N," over "R16 = 362.5 N")."""
    lines = [VALUE_SEPARATOR.join(items[k:k + per_line]) for k in range(0, len(items), per_line)]
    return [line + VALUE_SEPARATOR.rstrip() for line in lines[:-1]] + lines[-1:]


def _percent(value: float) -> str:
    """A percentage to two decimals, a true minus sign, no minus on a nought."""
    text = f"{value:.2f}"
    return "0.00" if text in ("-0.00", "0.00") else text.replace("-", "−")


def _leading(terms: str) -> str:
    """A sum of terms without the sign of a leading plus, and a leading minus set close: ``−Fu3·h1 + …``."""
    if terms.startswith("+ "):
        return terms[2:]
    return "−" + terms[2:] if terms.startswith("− ") else terms


def _sign(value: float) -> str:
    return "−" if value < 0 else "+"


# Paper.

def _paper(length_scale: float) -> Callable[[complex], tuple[float, float]]:
    def paper(r: complex) -> tuple[float, float]:
        return (r.real / length_scale, r.imag / length_scale)

    return paper





def _angle(value: complex) -> float:
    return math.atan2(value.imag, value.real)


def group_id(label: str) -> str:
    """The svg id of a group: ``II(3,4)`` → ``II-3-4``."""
    return svg_id(label).strip("-")


__all__ = ["Arrangement", "Drawing", "ForceSheet", "arrange", "arrangements", "draws_larger", "enlarged_lever_scale",
           "free_body_arrows", "group_id", "layout", "lever_loads_at", "rows", "svg_id", "too_short_to_draw",
           "with_finer_polygons"]
