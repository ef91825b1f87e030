"""The groups cut free on the force sheet: each group's links at μl with every force at its point.

On the left of each row of the force sheet the group's links cut free at
μl, every force an arrow at its point (proportional at the panel's own
force scale, never shorter than
:data:`~graphplan.render.force_marks.LEAST_ARROW_MM`), every moment a
curved arrow with its sense, the arms ``h`` of the moment equations as thin
perpendiculars from the moment centre to the forces' lines; a force along a
turning line (a cylinder's or a spring's) with its line to the point it is
along (:func:`_along_lines`).  Under it the group's moment and projection
equations, with the reactions they find.

The sheet of the force analysis with friction is the same sheet of the
plan with friction, with the textbook's construction at every journal with
friction: its friction circle ρ = f·r, the friction moments turning about
the journal, and the whole reaction of the pair on the circle's tangent,
on the side whose moment about the joint is the friction moment.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

from shapely.geometry import LineString, Polygon
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union

from ..forces import NEGLIGIBLE, BodyForce, GroupForces, MomentEquation, ProjectionEquation
from ..geometry import perpendicular_foot
from ..joint_friction import FrictionPair, pair_name
from ..kinematics import at
from ..loads import external_names
from ..locale import load_symbol
from ..scales import format_scale
from ..wording import friction_summary
from .force_marks import (
    ACTION_RUN_ON,
    ALONG_BAR_MM,
    ALONG_BAR_SHARE,
    ARM,
    ARM_NAME_SIZE,
    BALANCING,
    BESIDE_MM,
    LEAST_ARROW_MM,
    LOAD,
    NAME_SIZE,
    PER_LINE,
    POINT_SIZE,
    VALUE_SEPARATOR,
    ForceSheet,
    arm_with_run_on,
    arrow_scale,
    balancing_line,
    direction_rad,
    group_id,
    grown_union,
    letters_placed,
    points_onto,
    sign_mark,
    unstacked,
    whole_reaction,
    wrapped,
)
from .force_rows import CAPTION_WIDTH_MM, Drawing
from .labels import LEADER_WIDTH, Anchor, cover_one_another, open_direction
from .linkage import BLOCK_REACH_MM, link_outlines, outline_points
from .numerals import short, significant
from .plans import ZERO_MM, too_short_lines
from .primitives import (
    LEAD_PAST_PIN_MM,
    MAIN,
    PIN_RADIUS_MM,
    Arrow,
    Circle,
    Layer,
    Point,
    Polyline,
    Primitive,
    Stroke,
    Text,
    curved_arrow,
    dot_marker,
    pin,
    place,
    slider_block,
    svg_id,
    zigzag,
)
from .primitives import to_complex as _c
from .primitives import to_xy as _xy

# Radii of the curved arrows of moments on the links (mm).
MOMENT_RADIUS_MM = 6.0
BALANCING_RADIUS_MM = 9.0
# A friction circle is drawn at least this large (mm), clear of the pin drawn over its joint; the caption
# says when it is enlarged.
LEAST_FRICTION_CIRCLE_MM = 3.0
# The whole reaction on the friction circle's tangent runs this far past the circle each way (mm).
TANGENT_RUN_MM = 9.0

_LINK = Stroke(0.7)
_REACTION = Stroke(0.5, "#a83a1f")
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
_MOMENT = Stroke(0.4)
_FRICTION_CIRCLE = Stroke(0.3, "#a83a1f")
_ON_TANGENT = Stroke(0.3, "#a83a1f", (6.0, 1.5, 1.0, 1.5))


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


@dataclass(frozen=True)
class _Force:
    """A force drawn on a group cut free: its name, its point (m), its value (N), its style."""

    name: str
    point: complex
    force: complex
    stroke: Stroke


def body(sheet: ForceSheet, group: GroupForces) -> Drawing:
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
    bars = grown_union([LineString(item.points + item.points[:1] if item.closed else item.points) for item in links
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
    for force in sorted(shown, key=lambda force: not points_onto(*beside[force.name][:2], _c(paper(force.point)))):
        start, end, shift = beside[force.name]
        start, end = unstacked(start, end, _c(paper(force.point)) + shift, list(stacked.values()))
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
            leaders.append(Polyline((_xy(point), _xy(near)), Stroke(LEADER_WIDTH, force.stroke.colour)))
        drawn[force.name] = (start - shift, end - shift, unit)
        # Named at the arrow's free end: its head, or its tail when it points onto its joint; beside its shaft, or led
        # from it, it names the arrow as well.
        free, outward = (start, -unit) if points_onto(start, end, point + shift) else (end, unit)
        anchors.append(Anchor(_xy(free), load_symbol(force.name, text), NAME_SIZE, direction_rad(outward),
                              force.stroke.colour, along=(arrow.start, arrow.end)))
    turning, turning_anchors, turned_about = _moments(sheet, group, paper, is_driver, links + arrows)
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
    # of action run on to its arm, every leader from its head to a clear spot crossing another name); so does the
    # name of a point a moment's arc turns about, on a leader from its dot, which the arc rings (the triad with a
    # slider's S6 at position 8 lay on Mu6's arc, the arm h of its class III group through the arc's open quarter).
    # Another point's, a moment's or an arm's name keeps its place: led far out from a thin arm in the star of arms
    # at Σ6 (the class III triad's h3 and h8 on its A3 sheet of position 8), it reads as naming another.
    # A pin a slider block is drawn round is lettered beside the block, as on the plan sheets, not on its outline.
    blocked = {slide.joint for slide in sheet.motion.slides if slide.slider in group.links}
    points = [Anchor(where, name, POINT_SIZE, open_direction(where, figure),
                     symbol_mm=BLOCK_REACH_MM if name in blocked else 0.0)
              for name in _named_points(sheet, group) + special_names for where in [paper(sheet.positions[name])]]
    points += [Anchor(where, name, POINT_SIZE, open_direction(where, figure))
               for name, where in along_names if name not in {anchor.text for anchor in points}]
    # The moments', friction circles' and arms' names, which keep their place (above).
    placed_near = turning_anchors + circle_anchors + arm_anchors
    # Clear of the filled outlines' ink (a slider's block), as wide as it is drawn: kept off its middle alone, the
    # shaper's A stood on the 0.7 mm outline of its block.
    filled = [item for item in links if isinstance(item, Polyline) and item.closed and item.fill]
    reach_farther = [True] * len(anchors) + [point.at in turned_about for point in points]
    labels = letters_placed(anchors + points + placed_near, figure, inked=filled,
                            reach_farther=reach_farther + [False] * len(placed_near))
    caption = [text["driver_forces_title" if is_driver else "group_forces_title"].format(group=group.label),
               text["comma"].join((text["length_scale"].format(value=format_scale(sheet.length_scale)),
                                   text["body_force_scale"].format(value=format_scale(scale),
                                                                   least=f"{LEAST_ARROW_MM:g}")))]
    caption += [line for equation in group.projections if (line := _projection(sheet, equation))]
    caption += equations
    caption += circle_caption
    caption += _slide_friction(sheet, group)
    if is_driver:
        caption.append(balancing_line(sheet, sheet.forces.balancing, "balancing_by_polygons"))
        # Under the load it balances, so that a sheet set part by part keeps it.
        caption += _friction_summary(sheet)
    caption += wrapped([f"{found.name} = {significant(abs(found.force))} {text['newton']}" for found in group.found
                         if abs(found.force) / group.scale >= ZERO_MM])
    friction = [Layer(f"body-{key}-friction", tuple(circles))] if circles else []
    # Under the links, whose pins cover its lines' ends; named for lines, as a CAD file's construction lines.
    under = [Layer(f"body-{key}-along-lines", tuple(along))] if along else []
    layers = [*under, Layer(f"body-{key}-links", tuple(links)), Layer(f"body-{key}-arms", tuple(arms)),
              Layer(f"body-{key}-moments", tuple(turning)), *friction, Layer(f"body-{key}-forces", tuple(arrows)),
              Layer(f"body-{key}-leaders", labels.leaders), Layer(f"body-{key}-labels", labels.texts)]
    # Its title and scales stay with the group; its equations, under its title again, may go on after it.
    parted = (Drawing(f"body-{key}", layers, tuple(caption[:2]), labels_crowded=labels.crowded),
              Drawing(f"equations-{key}", [], (caption[0], *caption[2:]))) if len(caption) > 2 else None
    return Drawing(f"body-{key}", layers, tuple(caption), parted, labels_crowded=labels.crowded)


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
        if spec.ends in done:
            continue
        done.add(spec.ends)
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
    are drawn (a rounding error's is not, :attr:`GroupForces.shown_forces`) and the μF their arrows are drawn at, which the links'
    extent sets."""
    links = _links(sheet, group, paper)
    special, special_names = _special_points(sheet, group, paper)
    links += special
    shown = [_drawn(sheet, force) for force in group.shown_forces]
    return links, special_names, shown, arrow_scale([force.force for force in group.body_forces], links)


def free_body_arrows(sheet: ForceSheet) -> dict[str, tuple[float, tuple[str, ...]]]:
    """By each group's label, the μF (N/mm) its group cut free draws its forces' arrows at, and the reactions drawn
    whole there at their length at it (a component, R23τ, is no whole reaction; an arrow lengthened to
    :data:`LEAST_ARROW_MM` is at no scale): what a hand reading of a reaction off the arrows measures."""
    paper = _paper(sheet.length_scale)
    found = {}
    for group in sheet.forces.groups:
        _, _, shown, scale = _body_frame(sheet, group, paper)
        whole = tuple(force.name for force in shown if whole_reaction(force.name)
                      and abs(force.force) / scale >= LEAST_ARROW_MM)
        found[group.label] = (scale, whole)
    return found


def labels_cover_one_another(drawing: Drawing) -> bool:
    """Whether the labels of a group cut free find no room apart: drawn so small that the names of its points,
    loads and arms cover one another, or one was left on another till the placer's last pass moved it onto lines or
    a leader (:attr:`~graphplan.render.labels.Placement.crowded`)."""
    return drawing.labels_crowded or cover_one_another([item for layer in drawing.layers
                                                        if layer.name == f"{drawing.name}-labels"
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
            back = min([-14.0, *(shift - 6.0 for shift in shifts)])
            ahead = max([14.0, *(shift + 6.0 for shift in shifts)])
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
            items.append(Polyline((paper(nearer), paper(where)), ACTION_RUN_ON))
        for slide in sheet.motion.slides:
            if slide.slider not in group.links:
                continue
            pin = sheet.positions[slide.joint]
            u = complex(at(slide.u, sheet.index))
            if abs(((where - pin) * u.conjugate()).real) <= 1e-9 * max(abs(where - pin), 1.0):
                items.append(Polyline((paper(pin), paper(where)), ACTION_RUN_ON))
    return items, names


def _named_points(sheet: ForceSheet, group: GroupForces) -> list[str]:
    """The points of the group's links lettered on the drawing, and the points its loads act at."""
    names = {name for link in group.links for name in sheet.mechanism.fixed_on.get(link, ())}
    names |= {load.point for load in group.loads if load.point is not None}
    return sorted(name for name in names if name in sheet.positions)


def _drawn(sheet: ForceSheet, force: BodyForce) -> _Force:
    """A force on the group cut free (:attr:`GroupForces.body_forces`) at its point, in its style: a load at its
    point, its line moved by its offset; a reaction at its joint, or off it along its slide; Fb at the driver's
    joint."""
    if force.load is not None:
        return _Force(force.name, _load_point(sheet, force.load.point) + force.load.offset, force.force, LOAD)
    if force.reaction is not None:
        found = force.reaction
        return _Force(force.name, _along_slide(sheet, found.joint, found.source, found.target, found.offset),
                      force.force, _REACTION)
    return _Force(force.name, sheet.positions[sheet.mechanism.driver.joint], force.force, BALANCING)


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
             drawn: Sequence[Primitive]) -> tuple[list[Primitive], list[Anchor], set[Point]]:
    """A curved arrow for every moment on the group, with its sense; the driver's balancing moment; and the points
    (paper mm) the arcs turn about.

    Each arc leaves open the quarter where the point it turns about is
    lettered (the widest gap between the lines ``drawn`` from it).
    """
    items: list[Primitive] = []
    anchors: list[Anchor] = []
    largest = max((abs(load.moment) for load in group.loads), default=0.0)
    journals = _friction_moment_joints(sheet)
    rings: dict[str, int] = {}
    centres: set[Point] = set()
    for load in group.loads:
        if load.is_force or abs(load.moment) <= 1e-9 * max(largest, 1.0):
            continue
        # A friction moment turns about its journal, the other moments about the link's centre.
        about = journals.get(load.name, f"link {load.link}")
        ring = rings.get(about, 0)
        rings[about] = ring + 1
        where = sheet.positions[journals[load.name]] if load.name in journals else _link_centre(sheet, load.link)
        centre = _c(paper(where))
        items_, anchor = _turn(centre, MOMENT_RADIUS_MM + 3.5 * ring, load.moment, load_symbol(load.name, sheet.text),
                               _MOMENT,
                               open_direction(_xy(centre), drawn))
        items += items_
        anchors.append(anchor)
        centres.add(_xy(centre))
    driver = sheet.mechanism.driver
    if is_driver and driver.kind == "crank" and sheet.forces.balancing != 0:
        centre = _c(paper(sheet.positions[driver.pivot]))
        items_, anchor = _turn(centre, BALANCING_RADIUS_MM, sheet.forces.balancing, load_symbol("Mb", sheet.text),
                               Stroke(0.5, BALANCING.colour), open_direction(_xy(centre), drawn))
        items += items_
        anchors.append(anchor)
        centres.add(_xy(centre))
    return items, anchors, centres


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
            anchors.append(Anchor(_xy(touch + run * unit), found.name, NAME_SIZE, direction_rad(unit),
                                  _ON_TANGENT.colour))
    text = sheet.text
    values = [f"ρ{_pair_name(sheet, pair)} = {significant(1000.0 * pair.radius)} {text['millimetre']}"
              for pair in sorted(journals, key=lambda pair: (pair.joint, pair.source, pair.target))]
    caption = wrapped([text["friction_circles"].format(values=values[0]), *values[1:]])
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
    return [first, *wrapped([", ".join(value) for value in values[PER_LINE:]])]


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
        items.append(Polyline((_xy(centre), _xy(shifted)), ARM))
        anchors.append(Anchor(_xy((centre + shifted) / 2), load_symbol(f"hu{load.link}", sheet.text), ARM_NAME_SIZE,
                              direction_rad(1j * (shifted - centre)), ARM.colour))
    return items, anchors


def _arms(sheet: ForceSheet, group: GroupForces, drawn: Mapping[str, tuple[complex, complex, complex]],
          paper) -> tuple[list[Primitive], list[Anchor], list[str]]:
    """The arm of every term of the group's moment equations, h1, h2, …, and the equations written with them.

    The arms are named as the note names them (:attr:`GroupForces.arm_names`):
    each force drawn here (``drawn``, the group's shown forces) that stands
    in an equation.

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

    def draw_arm(name: str, centre: complex, start: complex, end: complex, unit: complex) -> None:
        """The arm ``name`` from ``centre`` square to the line of the arrow from ``start`` to ``end`` (along
        ``unit``), run on to its foot, and its name."""
        items.extend(arm_with_run_on(centre, start, end, unit))
        foot = perpendicular_foot(centre, start, unit)
        anchors.append(Anchor(_xy((centre + foot) / 2), name, ARM_NAME_SIZE, direction_rad(1j * (foot - centre)),
                              ARM.colour, along=(_xy(centre), _xy(foot))))

    for equation, names in zip(group.moments, group.arm_names, strict=True):
        centre = _c(paper(sheet.positions[equation.about]))
        parts: list[str] = []
        undrawn: list[str] = []
        for term, name in zip(equation.standing_terms, names, strict=True):
            if name is not None:
                start, end, unit = drawn[term.name]
                parts.append(f"{sign_mark(term.moment)} {load_symbol(term.name, sheet.text)}·{name}")
                if term.arm / sheet.length_scale < ZERO_MM:
                    undrawn.append(f"{name} = {significant(term.arm / sheet.length_scale)} {sheet.text['millimetre']}")
                    continue
                draw_arm(name, centre, start, end, unit)
            else:
                # A couple stands as itself; a force not drawn (or a term the group adds) by its moment.
                couple = any(load.name == term.name and not load.is_force for load in group.loads)
                symbol = load_symbol(term.name, sheet.text)
                parts.append(f"{sign_mark(term.moment)} {symbol if couple else f'M({symbol})'}")
        unknown_arm = _unknown_arm(sheet, group, equation)
        line = _equation(sheet, group, equation, parts, unknown_arm)
        # An unknown force's arm h drawn as the knowns' arms are (a couple, Mb or R14·x, is no arrow drawn): given
        # by its length alone, the student had no line to measure it on.
        if line and equation.unknown in drawn and unknown_arm == "h" and equation.arm / sheet.length_scale >= ZERO_MM:
            draw_arm("h", centre, *drawn[equation.unknown])
        if line:
            lines.append(line)
            # Said to be too short, as the lever says it of its arms: a bare h2 = 0.1088 mm sent the reader looking
            # for an arm on the drawing.
            lines += too_short_lines(undrawn, sheet.text, CAPTION_WIDTH_MM, words="arms_too_short")
    return items, anchors, lines


def _one_letter(point: str) -> bool:
    """Whether a point's name is a letter, with its link's number or a prime (B, B4, C′): two of them run together
    name their segment (AB); two words (CRANKPIN, KNEE) run together are read as none, and the arm is an h."""
    return re.fullmatch(r"[^\W\d_]\d*[′″]*", point) is not None


def _equation(sheet: ForceSheet, group: GroupForces, equation: MomentEquation, parts: list[str], arm: str) -> str:
    """The moment equation as the note writes it: ``ΣMB(3): R23τ·AB − G3·h1 + Fu3·h2 + Mu3 = 0,  R23τ = 26.13 N``.

    The unknown's arm ``arm`` (:func:`_unknown_arm`) is named by its segment (its joint and the centre) where
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
        balancing = load_symbol(unknown, text)
        return (f"{about} {' '.join([balancing, *parts])} = 0,  {balancing} = {significant(equation.value)} "
                f"{text['newton_metre']}")
    # The unknown's sense as first assumed: its moment balances the others'.
    sign = "" if equation.value == 0 or -total / equation.value >= 0 else "−"
    # An arm h is no segment of the drawing: drawn as the others are (:func:`_arms`), its length is also given, as
    # the note gives it, the unknown's value following from it.
    length = f",  h = {significant(equation.arm / sheet.length_scale)} {text['millimetre']}" if arm == "h" else ""
    return (f"{about} {sign}{unknown}·{arm} {terms} = 0,  {unknown} = {significant(equation.value)} {text['newton']}"
            f"{length}")


def _unknown_arm(sheet: ForceSheet, group: GroupForces, equation: MomentEquation) -> str:
    """The name of the arm of an unknown force in ``equation``: the segment from the centre to its joint where it is
    that segment (a τ part square to its link), else ``h`` (a guide's normal reaction about Assur's point, at an
    angle to the segment)."""
    unknown = equation.unknown
    joint = next((found.joint for found in group.found
                  if unknown.rstrip("τn") in (f"R{found.source}{found.target}", f"R{found.target}{found.source}")),
                 None)
    if joint is not None and joint != equation.about and all(map(_one_letter, (joint, equation.about))):
        segment = abs(sheet.positions[joint] - sheet.positions[equation.about])
        if abs(segment - equation.arm) <= 1e-9 * segment:
            return "".join(sorted((joint, equation.about)))
    return "h"


def _projection(sheet: ForceSheet, equation: ProjectionEquation) -> str:
    """``ΣFτ(5): R35τ + G5τ − Fu5τ = 0,  R35τ = 8.7 N``: a block's loads along its slot, each by its part along it;
    left out where the block has none."""
    largest = max((abs(value) for _, value in equation.components), default=0.0)
    parts = [f"{sign_mark(value)} {load_symbol(name, sheet.text)}τ" for name, value in equation.components
             if abs(value) > NEGLIGIBLE * largest]
    if not parts:
        return ""
    return (f"ΣFτ({equation.link}): {equation.unknown} {' '.join(parts)} = 0,  {equation.unknown} = "
            f"{significant(equation.value)} {sheet.text['newton']}")


def _paper(length_scale: float) -> Callable[[complex], tuple[float, float]]:
    def paper(r: complex) -> tuple[float, float]:
        return (r.real / length_scale, r.imag / length_scale)

    return paper
