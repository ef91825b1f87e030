"""The plan sheet of one position: the mechanism, its velocity plan and its acceleration plan, side by side
(or the mechanism above or beside its plans, where a sheet of a set has room of that shape).

The mechanism is drawn at μl in the position, with the sense of each
point's velocity as a short arrow and the senses of ω and ε as curved arrows
on the links, all read off the plans.  Each plan is drawn from its record
(:class:`graphplan.plans.Plan`) as the student draws it: for every step the
lines of action, thin and dashed beyond their crossing, and the vectors laid
off, as arrows; then the absolute vectors of the points found by similarity
and the similar figures of the links; every point lettered once.  The layout
reads only what the step lists say, so a new group kind is drawn as soon as
it constructs its plans; it computes no mechanics.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, MultiPoint
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union

from ..kinematics import at
from ..mechanism import Mechanism
from ..memo import OwnedMemo
from ..motion import Motion
from ..plans import PLAN_FIELD_MM, Plan, image_name
from . import lettering
from .labels import (
    Anchor,
    breakable,
    broken_under,
    ink_of,
    obstacles_of,
    open_direction,
    place_breaking_thin_lines,
    place_labels,
    remembered,
    without,
)
from .linkage import (
    BLOCK_REACH_MM,
    GROUND_MARGIN_MM,
    Paper,
    along_loads,
    block_pins,
    frame_guide,
    frame_pivots,
    frame_points_along,
    ground_side,
    guide_bushing,
    link_outlines,
    links_at,
    loose_frame_points,
    outline_points,
)
from .primitives import (
    Arrow,
    Circle,
    Layer,
    Polyline,
    Primitive,
    Stroke,
    Text,
    arc_points,
    bounds_of,
    curved_arrow,
    dot_marker,
    moved_layers,
    svg_id,
)
from .primitives import text_span as _width
from .primitives import to_xy as _xy
from .wrapping import fitted

# A vector shorter than this on the paper (mm) is not drawn, and plan points closer than this share
# one label: half the usual drafting precision, below what a pencil resolves.
ZERO_MM = 0.25
# How far a line of action runs on, dashed, beyond the point where it crosses the other line (mm).
RUN_ON_MM = 12.0
# Length of the arrow that shows the sense of a point's velocity on the mechanism (mm).
SENSE_ARROW_MM = 12.0
# How far a fixed guide runs past its slider block (mm).
GUIDE_REACH_MM = 20.0
# Radius of the curved arrows of ω and ε on the links (mm).
TURN_RADIUS_MM = 7.0
# How near a curved arrow of ω or ε may come to the middle of a line of the frame or a pin's circle (the half width
# of the boldest, a pivot's 0.7 mm triangle or a pin, and the arrow's) (mm).
_FRAME_CLEARANCE_MM = 0.6
# The smaller radii a curved arrow is drawn at where the usual one finds no clear spot on a short link, down to the
# least that still reads as a turn headed by its 2.8 mm arrowhead (some 64° of its 100° shown as shaft) (mm).
_SHORT_TURN_RADII_MM = (6.0, 5.0, 4.5)
# The radii of a crank's ω drawn round its pivot, 5 mm first: close round the pin, yet clear of its triangle (mm).
_PIVOT_TURN_RADII_MM = (5.0, 4.5, 6.0, 7.0)
# How far a curved arrow's ink is kept from the ink of the other links, the points' dots and the other arrows (mm).
_ARC_GAP_MM = 0.3
# The curved arrows' stroke and head (mm).
_TURN_STROKE_MM = 0.45
_TURN_HEAD_MM = 2.8
# Space between the three drawings, and between a drawing and its caption (mm).
GAP_MM = 25.0
CAPTION_GAP_MM = 12.0
# Line spacing of captions and titles, in letter heights.
CAPTION_LINE = 1.6

# The heights of the lettering (mm, render/lettering.py): the points' letters, the captions, the sheet's title.
LETTER_SIZE = lettering.LETTER
CAPTION_SIZE = lettering.CAPTION
TITLE_SIZE = lettering.TITLE
# The layer of the sheet's title, over all its drawings: the heading its parts stand under apart.
TITLE_LAYER = "sheet-title"

_ABSOLUTE = Stroke(0.6)
_RELATIVE = Stroke(0.45)
_ACTION = Stroke(0.25, "#333333")
_ACTION_RUN_ON = Stroke(0.25, "#333333", (2.5, 1.5))
_FIGURE = Stroke(0.3)
_LINK = Stroke(0.8)
# A cylinder's barrel and rod: a little lighter than the links, its barrel only a letter wide.
_CYLINDER = Stroke(0.6)
_VELOCITY_COLOUR = "#1f5fa8"
_ACCELERATION_COLOUR = "#a83a1f"


@dataclass(frozen=True)
class PlanSheet:
    """What the plan sheet of one position shows.

    ``motion`` is the run's motion and ``index`` the position's index in it:
    the sheet reads only where the points are and how the links lie there;
    ``number`` is the position's number as the scene counts them.
    ``velocity`` and ``acceleration`` are the plans of that instant; the
    senses shown on the mechanism come from them.  ``length_scale`` is μl
    (m/mm); each caption is a tuple of lines (the drawing's name, its scale);
    ``velocity_pole`` and ``acceleration_pole`` letter the poles (``p``, ``π``).
    ``drawings`` are the drawings the sheet shows, of mechanism, velocity
    and acceleration: a run asked only for velocities draws no acceleration plan.
    """

    mechanism: Mechanism
    motion: Motion
    index: int
    number: int
    velocity: Plan
    acceleration: Plan
    length_scale: float
    title: str
    mechanism_caption: tuple[str, ...]
    velocity_caption: tuple[str, ...]
    acceleration_caption: tuple[str, ...]
    velocity_pole: str = "p"
    acceleration_pole: str = "π"
    drawings: tuple[str, ...] = ("mechanism", "velocity", "acceleration")


# Room around a plan's points in its field, for the run-on of its lines of action and its letters (mm).
FIELD_MARGIN_MM = RUN_ON_MM + 3.0


def plan_field_mm() -> float:
    """The width of a plan's field when the plan fits the field its scale was chosen for."""
    return PLAN_FIELD_MM + 2 * FIELD_MARGIN_MM


@dataclass(frozen=True)
class Arrangement:
    """The sheet laid out: its layers, and the field (xmin, ymin, xmax, ymax, mm) each drawing stands in."""

    layers: list[Layer]
    fields: dict[str, tuple[float, float, float, float]]


def layout(sheet: PlanSheet) -> list[Layer]:
    """The layers of the plan sheet, in paper millimetres (y up), the three drawings left to right."""
    return arrange(sheet).layers


# The ways the three drawings may stand, as rows of cells, each cell drawings one above the other: in one
# row; the mechanism above the two plans; the mechanism beside the plans. A sheet of a set takes the first
# that fits the room it has (a wide mechanism over its plans, a tall one beside them).
SHAPES: dict[str, tuple[tuple[tuple[str, ...], ...], ...]] = {
    "row": ((("mechanism",), ("velocity",), ("acceleration",)),),
    "stacked": ((("mechanism",),), (("velocity",), ("acceleration",))),
    "beside": ((("mechanism",), ("velocity", "acceleration")),),
}


def arrange(sheet: PlanSheet, shape: str = "row") -> Arrangement:
    """The drawings in fields as ``shape`` (of :data:`SHAPES`) sets them, each caption under its field, the title above.

    Each plan gets a field as wide as the field its scale is chosen for
    (:data:`~graphplan.plans.PLAN_FIELD_MM`) with room for its letters and
    run-on lines, or wider when the scene's scale makes the plan wider.  The
    fields of a row are as tall as its tallest cell and each drawing stands
    in the middle of its own, so that the drawings of a row are evenly
    spaced and the captions under them read as one line; in a cell of two
    drawings the lower one's field takes the height the upper one leaves.
    """
    return arrangements(sheet, (shape,))[0]


def arrangements(sheet: PlanSheet, shapes: Sequence[str]) -> list[Arrangement]:
    """The sheet of :func:`arrange` in each of ``shapes`` in turn: the same drawings, made once."""
    drawers = {
        "mechanism": lambda: _mechanism(sheet),
        "velocity": lambda: plan_layers(sheet.velocity, "velocity", sheet.velocity_pole, sheet.mechanism),
        "acceleration": lambda: plan_layers(sheet.acceleration, "acceleration", sheet.acceleration_pole, sheet.mechanism),
    }
    panels = {name: draw() for name, draw in drawers.items() if name in sheet.drawings}
    captions = {"mechanism": sheet.mechanism_caption, "velocity": sheet.velocity_caption,
                "acceleration": sheet.acceleration_caption}
    extents = {name: bounds_of(item for layer in drawing for item in layer.items) for name, drawing in panels.items()}
    least = {name: 0.0 if name == "mechanism" else plan_field_mm() for name in panels}
    widths = {name: max(x1 - x0, least[name], max(_width(text) for text in caption_texts(captions[name], (0.0, 0.0))))
              for name, (x0, _, x1, _) in extents.items()}
    heights = {name: y1 - y0 for name, (_, y0, _, y1) in extents.items()}
    depths = {name: _caption_depth(captions[name]) for name in panels}

    def arranged(shape: str) -> Arrangement:
        # Only the drawings the sheet shows: a run asked for velocities has no acceleration plan.
        rows = [row for row in ([cell for cell in (tuple(name for name in cell if name in panels) for cell in cells)
                                 if cell] for cells in SHAPES[shape]) if row]
        fields = _fields(rows, widths, heights, depths)
        layers: list[Layer] = []
        for name, drawing in panels.items():
            x0, y0, x1, y1 = extents[name]
            fx0, fy0, fx1, fy1 = fields[name]
            layers.extend(moved_layers(drawing, (fx0 + fx1 - x0 - x1) / 2, (fy0 + fy1 - y0 - y1) / 2))
        for name, (x0, y0, x1, _) in fields.items():
            layers.append(Layer(f"{name}-caption", caption_texts(captions[name], ((x0 + x1) / 2, y0 - CAPTION_GAP_MM))))
        left, _, _, top = bounds_of(item for layer in layers for item in layer.items)
        layers.append(Layer(TITLE_LAYER, title_texts((sheet.title,), TITLE_SIZE, (left, top + 8.0))))
        return Arrangement(layers, fields)

    return [arranged(shape) for shape in shapes]


def _fields(rows: list[list[tuple[str, ...]]], widths: dict[str, float], heights: dict[str, float],
            caption_depths: dict[str, float]) -> dict[str, tuple[float, float, float, float]]:
    """The field of each drawing: rows top to bottom (the first centred on y = 0), cells left to right from
    x = 0, the rows centred on one another."""
    fields: dict[str, tuple[float, float, float, float]] = {}
    row_widths = [sum(max(widths[name] for name in cell) for cell in cells) + GAP_MM * (len(cells) - 1)
                  for cells in rows]
    top = None
    for cells, row_width in zip(rows, row_widths, strict=True):
        # A cell's height down to its last drawing's field: the captions of a row's last drawings share a line.
        height = max(sum(heights[name] for name in cell)
                     + sum(caption_depths[name] + GAP_MM for name in cell[:-1]) for cell in cells)
        top = height / 2 if top is None else top
        left = (max(row_widths) - row_width) / 2
        for cell in cells:
            width = max(widths[name] for name in cell)
            y = top
            for name in cell[:-1]:
                fields[name] = (left, y - heights[name], left + width, y)
                y -= heights[name] + caption_depths[name] + GAP_MM
            fields[cell[-1]] = (left, top - height, left + width, y)
            left += width + GAP_MM
        top -= height + max(caption_depths[cell[-1]] for cell in cells) + GAP_MM
    return fields


def _caption_depth(lines: tuple[str, ...]) -> float:
    """How far a caption reaches below its field (mm), to its last line's descenders."""
    return CAPTION_GAP_MM + (len(lines) - 1) * CAPTION_LINE * CAPTION_SIZE + 0.3 * CAPTION_SIZE


# The mechanism in the position.

# The mechanism of a plan sheet, by what it is drawn from: a course sheet tries each plan sheet under a few captions
# (its plans' scales named on it or not), which leave the mechanism as it was, and its curved arrows' search for room
# took a tenth of the test suite drawing it again each time.  Kept with the velocity plan, as the plans are; the
# mechanism, the motion and the acceleration plan are kept with it, so that their ids in the key name no others.
_MECHANISMS: OwnedMemo[tuple[tuple[Mechanism, Motion, Plan], tuple[Layer, ...]]] = OwnedMemo()


def _mechanism(sheet: PlanSheet) -> list[Layer]:
    """The mechanism in the sheet's position, its senses and its letters, drawn once for what it is drawn from."""
    drawn_from = (sheet.mechanism, sheet.motion, sheet.acceleration)
    _, layers = _MECHANISMS.get(sheet.velocity, (*map(id, drawn_from), sheet.index, sheet.length_scale),
                                lambda: (drawn_from, tuple(_drawn_mechanism(sheet))))
    return list(layers)


def _drawn_mechanism(sheet: PlanSheet) -> list[Layer]:
    mechanism, motion, index = sheet.mechanism, sheet.motion, sheet.index
    mm_per_m = 1.0 / sheet.length_scale

    def paper(r: complex) -> tuple[float, float]:
        return (r.real * mm_per_m, r.imag * mm_per_m)

    def where(name: str) -> complex:
        return complex(at(motion.points[name].r, index))

    outlines = outline_points(mechanism, motion)
    links = links_at(motion, index, outlines, paper, _LINK, bold=True)
    loaded, load_pins = along_loads(motion, index, paper, LETTER_SIZE, _CYLINDER)
    links += load_pins
    frame: list[Primitive] = []
    for slide in motion.slides:
        if slide.guide == mechanism.scene.frame_link:
            u, r = complex(at(slide.u, index)), where(slide.joint)
            # The guide carries the block with room to spare, and runs to the frame points on its line.
            reach = GUIDE_REACH_MM * sheet.length_scale
            along = [0.0, *frame_points_along(mechanism, r, u)]
            first, last = min(along) - reach, max(along) + reach
            # The ground is hatched where the block travels, on the side clear of the links in this position: a
            # crank turning on the guide's line would otherwise cross it.
            travel = ((np.atleast_1d(motion.points[slide.joint].r) - r) * u.conjugate()).real
            margin = GROUND_MARGIN_MM * sheet.length_scale
            ground = (r + max(first, travel.min() - margin) * u, r + min(last, travel.max() + margin) * u)
            bushing = guide_bushing(mechanism, motion, slide.slider, slide.joint, u, sheet.length_scale)
            if bushing is not None:
                ground = bushing
                ends = [((end - r) * u.conjugate()).real for end in bushing]
                first, last = min(first, *ends), max(last, *ends)
            side = ground_side((where(name) for name in motion.points), r, u)
            frame.extend(frame_guide(r + first * u, r + last * u, u, sheet.length_scale, paper, ground, side))
    frame.extend(frame_pivots(mechanism, paper))
    # Named points, and frame points that are no pivot (the end of a guide), as dots.
    marks = [dot_marker(paper(where(spec.name))) for spec in mechanism.scene.points]
    marks += loose_frame_points(mechanism, paper)
    # The joints' pins and the blocks round them, which a curved arrow is kept off as the frame is.
    pins = [item for item in links if isinstance(item, Circle) or (isinstance(item, Polyline) and item.fill)]
    # Each link's lines alone, which the curved arrows of the other links keep clear of.
    link_lines = {number: link_outlines(motion, index, {number: names}, paper, _LINK)
                  for number, names in outlines.items()}
    # The links' lines, in the order they are given to the placer first among its obstacles, and which of them are each
    # link's: a letter led across a link reads as naming a point of it, unless that link is the point's own.
    lines_of_links = [(number, item) for number, items in link_lines.items() for item in items
                      if isinstance(item, Polyline) and not item.fill]
    own_lines = {number: tuple(k for k, (owner, _) in enumerate(lines_of_links) if owner == number)
                 for number in link_lines}
    senses, turn_anchors = _senses(sheet, outlines, where, paper, frame + loaded, pins, link_lines, marks, own_lines)
    special, special_at = _special_points(sheet.velocity, where, paper)
    marks += special
    drawn = loaded + links + frame + marks + senses
    # Points fixed on a link only: an RPR lever's point under the block would just repeat a label.
    names = [name for name in motion.points if any(name in on for on in mechanism.fixed_on.values())]
    blocked = block_pins(motion)
    anchors = [Anchor(paper(where(name)), name, LETTER_SIZE, open_direction(paper(where(name)), drawn),
                      symbol_mm=BLOCK_REACH_MM if name in blocked else 0.0,
                      own_lines=tuple(sorted(k for number, on in mechanism.fixed_on.items() if name in on
                                             for k in own_lines.get(number, ()))))
               for name in names]
    anchors += [Anchor(paper(r), name, LETTER_SIZE, open_direction(paper(r), drawn)) for name, r in special_at.items()]
    # As the plan of positions letters its bold extremes: clear of the ink of the links, the springs and cylinders,
    # the frame's pivots and the senses' arrows, as wide as each is drawn (kept off their middles alone, the slotted
    # levers' and the tangent mechanism's A stood with up to 0.3 mm² of its box on the outline of its 0.7 mm block,
    # and an ω on the arrow of a point's velocity), and where the thin lines (the ground's hatching, a guide's line,
    # the run-on lines to Assur's points) leave a letter no spot by its point, set there all the same with those
    # lines broken under it, not pushed out on a leader.
    # A letter is led across no other link's line where a spot near its point keeps it off them (the triad's O led up
    # over the coupler passing just above the crank's pivot read as naming a point of the coupler).
    thin = breakable(frame) + breakable(special)
    bold = without(drawn, thin + marks)
    crossable = [item for _, item in lines_of_links]
    ink = ink_of([item for item in bold if item not in crossable], shafts_inked=True)
    labels, breaking = place_breaking_thin_lines(anchors + turn_anchors, thin, drawn, bold, ink, [], [], [],
                                                 links=ink_of(crossable))
    frame = broken_under(frame, breaking, thin)
    marks = broken_under(marks, breaking, thin)
    # Under the frame and the links: their pins stand over the ends of the springs and cylinders.
    return [*([Layer("mechanism-load-links", tuple(loaded))] if loaded else []),
            Layer("mechanism-frame", tuple(frame)), Layer("mechanism-links", tuple(links)),
            Layer("mechanism-senses", tuple(senses)), Layer("mechanism-points", tuple(marks)),
            Layer("mechanism-leaders", labels.leaders), Layer("mechanism-labels", labels.texts)]


def _special_points(velocity: Plan, where: Callable[[str], complex],
                    paper: Paper) -> tuple[list[Primitive], dict[str, complex]]:
    """Assur's special points the plan was built through, each with the links' lines run on to it, dashed.

    The lines are those of the step that fixed the point's image (⊥ AB and ⊥ EF: Σ lies on AB and EF).
    """
    items: list[Primitive] = []
    for name, r in velocity.auxiliary.items():
        items.append(dot_marker(paper(r)))
        for step in velocity.steps:
            if image_name(name) not in step.fixes:
                continue
            for line in step.lines:
                nearer = min(line.along.points, key=lambda point: abs(where(point) - r))
                items.append(Polyline((paper(where(nearer)), paper(r)), _ACTION_RUN_ON))
    return items, dict(velocity.auxiliary)


def _senses(sheet: PlanSheet, outlines: dict[int, list[str]], where: Callable[[str], complex],
            paper: Paper, frame: list[Primitive], pins: list[Primitive], link_lines: Mapping[int, list[Primitive]],
            dots: list[Primitive], own_lines: Mapping[int, tuple[int, ...]]) -> tuple[list[Primitive], list[Anchor]]:
    """Short arrows along the velocities of the joints; curved arrows of ω and ε on each turning link.

    The senses are read off the plans: a point's velocity is along its
    vector pb, a link's ω and ε are those the plans give.  Centres of mass
    that are not joints get no arrow, to keep the links legible.  A link's
    curved arrows keep off the frame and the pins (``frame``, ``pins``), and
    where they can, off the other links' lines (``link_lines``, link by link),
    the points' ``dots`` and the arrows drawn before them.
    """
    velocity, acceleration = sheet.velocity, sheet.acceleration
    named = {spec.name for spec in sheet.mechanism.scene.points}
    centres = {spec.centre for spec in sheet.mechanism.scene.links.values()} & named
    items: list[Primitive] = []
    # A lever's point under a block (A4) stands where the block's pin is: its arrow would cross the pin's.
    on_links = {name for names in sheet.mechanism.fixed_on.values() for name in names}
    for name, letter in velocity.images.items():
        if letter == "p" or name in centres or name not in on_links or abs(velocity.mm(letter)) < ZERO_MM:
            continue
        sense = velocity.points[letter] / abs(velocity.points[letter])
        # From the rim of the pin, so that the pin does not hide the start.
        start = paper(where(name) + 1.6 * sheet.length_scale * sense)
        end = (start[0] + SENSE_ARROW_MM * sense.real, start[1] + SENSE_ARROW_MM * sense.imag)
        items.append(Arrow(start, end, Stroke(0.45, _VELOCITY_COLOUR), 3.0, svg_id("mechanism", "v", name)))
    points = MultiPoint([paper(where(name)) for name in sheet.motion.points])
    frame_shapes = obstacles_of(frame)
    # The ink an arc must keep off: the frame's symbols (a pivot's pin, triangle and hatching, a guide) and the
    # moving joints' pins and blocks, as wide as their lines and the arc's together.
    frame_and_pins = unary_union([shape.buffer(_FRAME_CLEARANCE_MM) for shape in frame_shapes + obstacles_of(pins)])
    frame_and_pins_ink = unary_union(ink_of(frame + pins))
    # Each link's outline and lines' ink, the dots' ink, and each arrow's ink and grown shape as it is drawn, made
    # once: every link's arrows are set clear of all the others'.  Made again link by link, and joined where no arrow
    # came near them, they took two fifths of the senses' time.
    link_outlines = {number: _outline(MultiPoint([paper(where(n)) for n in names]))
                     for number, names in outlines.items() if len(names) > 1}
    lines_ink = {number: ink_of(lines, shafts_inked=True) for number, lines in link_lines.items()}
    dots_ink = ink_of(dots, shafts_inked=True)
    arrows_ink = ink_of(items, shafts_inked=True)
    arrows_grown = [shape.buffer(_FRAME_CLEARANCE_MM) for shape in obstacles_of(items)]
    anchors: list[Anchor] = []
    for link in sheet.mechanism.moving_links:
        names = outlines.get(link, [])
        if len(names) < 2:
            continue
        other_links = [outline for number, outline in link_outlines.items() if number != link]
        others = unary_union([points, *frame_shapes] + other_links)
        first, second = max(((a, b) for i, a in enumerate(names) for b in names[i + 1:]),
                            key=lambda ab: abs(where(ab[0]) - where(ab[1])))
        start_mm, end_mm = paper(where(first)), paper(where(second))
        along = math.atan2(end_mm[1] - start_mm[1], end_mm[0] - start_mm[0])
        turns = []
        for symbol, rates, colour, side in (("ω", velocity.rates, _VELOCITY_COLOUR, 0.0),
                                            ("ε", acceleration.rates, _ACCELERATION_COLOUR, math.pi)):
            rate = rates.get(link, 0.0)
            if abs(rate) <= 1e-9 * max([1.0, *(abs(r) for r in rates.values())]):
                continue
            sweep = math.copysign(math.radians(100.0), rate)
            turns.append((symbol, colour, along + side - sweep / 2, sweep))
        if not turns:
            continue
        # The arrows drawn so far (the joints' velocities, the other links' ω and ε), joined only where a spot is
        # weighed by them.
        arcs = [(start, sweep) for _, _, start, sweep in turns]
        centre, turned = _clear_spot(start_mm, end_mm, others, frame_and_pins, lambda: unary_union(arrows_grown), arcs)
        placed = [(centre, TURN_RADIUS_MM, start + turned, sweep) for start, sweep in arcs]
        crossed = _Joined([shape for number, ink in lines_ink.items() if number != link for shape in ink]
                          + dots_ink + arrows_ink)
        # Drawn again where their ink lies on other ink, and then kept a gap clear of it; arrows merely near other ink
        # stay as they were.
        if _over(placed, frame_and_pins_ink, crossed) != (0.0, 0.0):
            crossed = crossed.union.buffer(_ARC_GAP_MM)
            pivots = [paper(where(name)) for name in names if name in sheet.mechanism.scene.frame_points]
            placed = _short_link_turns(placed, start_mm, end_mm, arcs, pivots[:1], frame_and_pins, crossed)
        for (symbol, colour, _, _), (centre, radius, start, sweep) in zip(turns, placed):
            arrow = curved_arrow(centre, radius, start, sweep, Stroke(_TURN_STROKE_MM, colour), _TURN_HEAD_MM)
            items.extend(arrow)
            arrows_ink.extend(ink_of(arrow, shafts_inked=True))
            arrows_grown.extend(shape.buffer(_FRAME_CLEARANCE_MM) for shape in obstacles_of(arrow))
            tail = (centre[0] + radius * math.cos(start), centre[1] + radius * math.sin(start))
            anchors.append(Anchor(tail, f"{symbol}{link}", lettering.NAME, start, colour,
                                  own_lines=own_lines.get(link, ())))
    return items, anchors


def _outline(points: MultiPoint) -> BaseGeometry:
    """The lines of a link drawn as the hull of its points: the segment, or the polygon's boundary."""
    hull = points.convex_hull
    return hull.boundary if hull.geom_type == "Polygon" else hull


def _clear_spot(start: tuple[float, float], end: tuple[float, float], others: BaseGeometry, frame: BaseGeometry,
                arrows: Callable[[], BaseGeometry],
                arcs: Sequence[tuple[float, float]]) -> tuple[tuple[float, float], float]:
    """The spot on the segment, among a few, about which the curved arrows ``arcs`` (each its start angle and sweep,
    of radius :data:`TURN_RADIUS_MM`) are drawn, and the half turn (0 or π) they are turned through there.

    The spot farthest from the mechanism's points and its other links, ``others``, where the arrows drawn about it
    keep off ``frame``, the ink of the frame's symbols and the pins; else the spot and half turn that run them least
    over that ink, then least over ``arrows`` (made when asked: the arrows drawn so far), then the farthest from
    ``others``.  Weighed by its centre alone, the spot a short crank's ω was turned about stood a few millimetres
    from its pivot (the slotted lever's, the shaper's, the triads'), and the arc, 7 mm round, ran over the pivot's
    triangle and hatching.  Turned through a half turn, ω bulges toward the link's other end (and ε, opposite it,
    toward this one): a crank too short for any of its spots to keep ω off its pivot keeps it toward its crankpin.
    """
    spots = _spots(start, end)

    def over(ink: BaseGeometry, spot: tuple[float, float], turned: float) -> float:
        return round(sum(_arc_line(spot, begin + turned, sweep).intersection(ink).length for begin, sweep in arcs), 3)

    def room(spot: tuple[float, float]) -> float:
        return round(others.distance(ShapelyPoint(spot)), 6)

    farthest = max(spots, key=room)
    if over(frame, farthest, 0.0) == 0:
        return farthest, 0.0
    drawn = arrows()
    return min(((spot, turned) for turned in (0.0, math.pi) for spot in spots),
               key=lambda choice: (over(frame, *choice), over(drawn, *choice), -room(choice[0])))


def _spots(start: tuple[float, float], end: tuple[float, float]) -> list[tuple[float, float]]:
    """The few spots of a link's segment its curved arrows may be turned about, the middle first."""
    return [(start[0] + t * (end[0] - start[0]), start[1] + t * (end[1] - start[1]))
            for t in (0.5, 0.65, 0.35, 0.75, 0.25)]


# A placed curved arrow: its centre, radius, start angle and sweep.
_Turn = tuple[tuple[float, float], float, float, float]


class _Joined:
    """Shapes to be joined into one only if something is found to lie on them: the ink of the other links, the dots
    and the arrows drawn so far, which a link's arrows mostly keep clear of by their bounds alone."""

    def __init__(self, shapes: list[BaseGeometry]) -> None:
        self.shapes = shapes
        self.bounds = shapely.bounds(np.array(shapes, dtype=object)).reshape(-1, 4)

    @functools.cached_property
    def union(self) -> BaseGeometry:
        return unary_union(self.shapes)

    def area_under(self, shape: BaseGeometry) -> float:
        """The area of ``shape`` lying on the shapes: nought, exactly as their union gives it, where no shape's bounds
        meet its bounds."""
        x0, y0, x1, y1 = shape.bounds
        near = ((self.bounds[:, 0] <= x1) & (self.bounds[:, 2] >= x0) & (self.bounds[:, 1] <= y1)
                & (self.bounds[:, 3] >= y0))
        return shape.intersection(self.union).area if near.any() else 0.0


def _over(placed: Sequence[_Turn], frame: BaseGeometry, crossed: BaseGeometry | _Joined) -> tuple[float, float]:
    """How much of the ink of the curved arrows ``placed``, heads and all, lies on ``frame`` (the frame's symbols
    and the pins) and on ``crossed`` (the other links, the dots, the arrows drawn so far) (mm²)."""
    shape = unary_union(ink_of([item for centre, radius, start, sweep in placed
                                for item in curved_arrow(centre, radius, start, sweep, Stroke(_TURN_STROKE_MM),
                                                         _TURN_HEAD_MM)], shafts_inked=True))
    on_crossed = crossed.area_under(shape) if isinstance(crossed, _Joined) else shape.intersection(crossed).area
    return round(shape.intersection(frame).area, 3), round(on_crossed, 3)


def _short_link_turns(placed: list[_Turn], start: tuple[float, float], end: tuple[float, float],
                      arcs: Sequence[tuple[float, float]], pivots: Sequence[tuple[float, float]],
                      frame: BaseGeometry, crossed: BaseGeometry) -> list[_Turn]:
    """The curved arrows ``arcs`` of a link (each its start angle, the link's own, and sweep) drawn as a drafter
    would where ``placed``, :func:`_clear_spot`'s, runs over other ink: about a spot of the link at a smaller radius,
    or, a crank's lone ω, about its pivot (``pivots``, the link's fixed point if any), on the side away from the
    ground first.  The first way clear of ``frame`` and ``crossed``: the usual radius on the link, then round the
    pivot, then the smaller radii on the link; ``placed`` where none is clear.

    A crank 12 to 17 mm long as drawn beside a rocker or a connecting rod at a narrow angle (the triads' at their
    eighth position, the slotted lever's and the shaper's) has no spot where a 7 mm arc clears the other link: ω ran
    over that link's line, over the point S2 on the crank, along the arrow of S2's velocity.
    """
    ways: list[list[_Turn]] = []
    # The spots nearest the one :func:`_clear_spot` chose first: the arrows move no farther than they must.
    spots = sorted(_spots(start, end), key=lambda spot: math.dist(spot, placed[0][0]))

    def on_the_link(radius: float) -> list[list[_Turn]]:
        return [[(spot, radius, begin + turned, sweep) for begin, sweep in arcs]
                for turned in (0.0, math.pi) for spot in spots]

    ways += on_the_link(TURN_RADIUS_MM)
    if len(arcs) == 1:
        # Close round the pivot, as a crank's ω1 is drawn round O, and away from its triangle and hatching (which
        # stand below it on the paper) first.
        for radius in _PIVOT_TURN_RADII_MM:
            ways += [[(pivot, radius, math.pi / 2 + side * math.radians(step) - sweep / 2, sweep)]
                     for pivot in pivots for step in range(0, 120, 15) for side in ((1,) if step == 0 else (1, -1))
                     for _, sweep in arcs]
    for radius in _SHORT_TURN_RADII_MM:
        ways += on_the_link(radius)
    return next((way for way in ways if _over(way, frame, crossed) == (0.0, 0.0)), placed)


def _arc_line(centre: tuple[float, float], start: float, sweep: float) -> LineString:
    """The arc of a curved arrow of radius :data:`TURN_RADIUS_MM`, head and all, as a line."""
    return LineString(arc_points(centre, TURN_RADIUS_MM, start, sweep))


# A plan.

# A plan is drawn at its own μV or μa, whatever μl the mechanism beside it is drawn at: the choice of μl lays the plan
# sheets and the velocity plans of every position out at each μl it tries (the latter twice, whole and in runs), and
# the plans' lettering was placed again each time.  The mechanism is kept with its plan's layers, so that its id in
# the key names no other mechanism while they are kept.
_PLANS: OwnedMemo[tuple[Mechanism, tuple[Layer, ...]]] = OwnedMemo()


def plan_layers(plan: Plan, kind: str, pole: str, mechanism: Mechanism) -> list[Layer]:
    """The plan's lines of action, similar figures, vectors, points and letters, drawn once for each plan, kind,
    pole and mechanism while the plan lives."""
    _, layers = _PLANS.get(plan, (kind, pole, id(mechanism)),
                           lambda: (mechanism, tuple(_plan_layers(plan, kind, pole, mechanism))))
    return list(layers)


def _plan_layers(plan: Plan, kind: str, pole: str, mechanism: Mechanism) -> list[Layer]:
    """The layers of :func:`plan_layers`."""
    actions = _lines_of_action(plan)
    figures = _similar_figures(plan, mechanism)
    vectors = _vectors(plan, kind)
    groups = _coincident(plan)
    dots = [dot_marker(_xy(plan.mm(group[0])), 0.7 if group[0] == "p" else 0.5) for group in groups]
    drawn = actions + figures + vectors + dots
    anchors = []
    for group in groups:
        at = _xy(plan.mm(group[0]))
        text = ", ".join(pole if letter == "p" else letter for letter in group)
        anchors.append(Anchor(at, text, LETTER_SIZE, open_direction(at, actions + figures + vectors)))
    # Clear of the vectors' and lines' ink, as wide as each is drawn: kept off their middles alone, a letter stood
    # with its box on a 0.6 mm vector's edge (the Stephenson six-bar's g along pa, s2 on pa of most plans).
    ink = ink_of(drawn, shafts_inked=True)
    labels = remembered(place_labels, anchors, ink)
    return [Layer(f"{kind}-lines", tuple(actions + figures)), Layer(f"{kind}-vectors", tuple(vectors)),
            Layer(f"{kind}-points", tuple(dots)), Layer(f"{kind}-leaders", labels.leaders),
            Layer(f"{kind}-labels", labels.texts)]


def _vectors(plan: Plan, kind: str) -> list[Primitive]:
    """Every vector the steps lay off, once, then the absolute vector of every point from the pole.

    A vector repeated by a later step (vBC = vB when C is at the pole) is drawn
    once; a vector shorter than :data:`ZERO_MM` is not drawn at all (see :func:`too_short`).
    """
    arrows: list[Primitive] = []
    for start, end, _ in _laid(plan, kind):
        if abs(plan.mm(end) - plan.mm(start)) >= ZERO_MM:
            stroke = _ABSOLUTE if start == "p" else _RELATIVE
            arrows.append(Arrow(_xy(plan.mm(start)), _xy(plan.mm(end)), stroke, key=svg_id(kind, start, end)))
    return arrows


def too_short_to_draw_mm(millimetres: float) -> bool:
    """Whether a plan's vector this long on the drawing (mm) is left out of it but is no nought (a point at the
    pole): the plan's caption names it and the note's equation tables say it is not drawn."""
    return 1e-9 < millimetres < ZERO_MM


def too_short(plan: Plan, kind: str) -> list[tuple[str, float]]:
    """The vectors of the plan too short to draw but not zero: each one's name and magnitude (SI).

    Where the vectors of one plan differ by 10⁴ in length the short ones vanish under the pencil;
    the sheet states them with their values instead.
    """
    found = []
    for start, end, name in _laid(plan, kind):
        length = abs(plan.mm(end) - plan.mm(start))
        if too_short_to_draw_mm(length):
            found.append((name, abs(plan.points[end] - plan.points[start])))
    return found


# Vectors named per caption line under a drawing, so that a long list does not widen the sheet.
SHORT_PER_LINE = 3


def too_short_lines(values: Sequence[str], text: Mapping[str, str], width: float | None = None,
                    words: str = "plan_too_short") -> list[str]:
    """Caption lines naming the vectors too short to draw (shorter than :data:`ZERO_MM`), each written with its value
    in ``values``: the words (the locale's ``words``: ``arms_too_short`` for a drawing's arms h) on a line of their
    own, then the values, :data:`SHORT_PER_LINE` a line, a line wider than ``width`` (mm; a plan's field by default)
    broken after a semicolon.  The plans, the balancing polygons and the force sheets all name theirs so."""
    if not values:
        return []
    reach = plan_field_mm() if width is None else width
    return [text[words].format(least=f"{ZERO_MM:g}"),
            *(piece for k in range(0, len(values), SHORT_PER_LINE)
              for piece in fitted("; ".join(values[k:k + SHORT_PER_LINE]), reach, CAPTION_SIZE))]


def _laid(plan: Plan, kind: str) -> list[tuple[str, str, str]]:
    """Every vector the plan lays off, once: (start letter, end letter, name), the steps' first, then the pole's."""
    laid: dict[tuple[str, str], str] = {}
    for step in plan.steps:
        for vector in step.vectors:
            if vector.start != vector.end:
                laid.setdefault((vector.start, vector.end), vector.meaning)
    symbol = "v" if kind == "velocity" else "a"
    for point, letter in plan.images.items():
        if letter != "p":
            laid.setdefault(("p", letter), f"{symbol}{point}")
    return [(start, end, name) for (start, end), name in laid.items()]


def _lines_of_action(plan: Plan) -> list[Primitive]:
    """Each line of action: thin from its point to where it crosses, dashed for a run beyond.

    The crossing is the point the step fixes on the line; a line whose
    crossing coincides with its own point (a zero vector) is drawn dashed
    both ways.  A step that fixes nothing only reads a vector off, along its line.
    """
    items: list[Primitive] = []
    for step in plan.steps:
        if not step.fixes:
            continue
        candidates = list(step.fixes) + [v.end for v in step.vectors]
        for line in step.lines:
            through = plan.mm(line.through)
            unit = line.direction / abs(line.direction)
            crossing = next((plan.mm(c) for c in candidates
                             if abs(_off_line(plan.mm(c), through, unit)) < 0.05 and abs(plan.mm(c) - through) >= ZERO_MM),
                            None)
            if crossing is None:
                items.append(Polyline((_xy(through - RUN_ON_MM * unit), _xy(through + RUN_ON_MM * unit)),
                                      _ACTION_RUN_ON))
                continue
            onward = (crossing - through) / abs(crossing - through)
            items.append(Polyline((_xy(through), _xy(crossing)), _ACTION))
            items.append(Polyline((_xy(crossing), _xy(crossing + RUN_ON_MM * onward)), _ACTION_RUN_ON))
    return items


def _similar_figures(plan: Plan, mechanism: Mechanism) -> list[Primitive]:
    """The figure of each link on the plan (abe ∼ ABE) when it is more than a segment."""
    items: list[Primitive] = []
    for link in mechanism.moving_links:
        letters = sorted({plan.images[name] for name in mechanism.fixed_on.get(link, ()) if name in plan.images})
        if len(letters) < 3:
            continue
        hull = MultiPoint([_xy(plan.mm(letter)) for letter in letters]).convex_hull
        corners = _corners(tuple(hull.exterior.coords)[:-1]) if hull.geom_type == "Polygon" else ()
        # Far out on a huge plan a hull of some area may still have all its corners in line: no figure.
        if len(corners) >= 3 and hull.area > ZERO_MM ** 2:
            items.append(Polyline(corners, _FIGURE, closed=True))
    return items


def _corners(ring: tuple[tuple[float, float], ...]) -> tuple[tuple[float, float], ...]:
    """The corners of a closed ring: a vertex on the line of its neighbours (s3 on ab) is none."""
    kept = []
    for k, (x, y) in enumerate(ring):
        (x0, y0), (x1, y1) = ring[k - 1], ring[(k + 1) % len(ring)]
        if abs((x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)) > 0.01 * math.hypot(x1 - x0, y1 - y0):
            kept.append((x, y))
    return tuple(kept)


def _coincident(plan: Plan) -> list[list[str]]:
    """The plan's letters grouped by where they stand: points closer than :data:`ZERO_MM` share a label."""
    groups: list[list[str]] = []
    for letter in sorted(plan.points, key=lambda name: name != "p"):
        for group in groups:
            if abs(plan.mm(letter) - plan.mm(group[0])) < ZERO_MM:
                group.append(letter)
                break
        else:
            groups.append([letter])
    return groups


def _off_line(point: complex, through: complex, unit: complex) -> float:
    """The signed distance of ``point`` from the line through ``through`` along ``unit``."""
    return ((point - through) * unit.conjugate()).imag


def title_texts(lines: Sequence[str], size: float, at: tuple[float, float],
                spacing: float = CAPTION_LINE) -> tuple[Text, ...]:
    """A drawing's title in bold at cap height ``size``, its ``lines`` (one, or the title broken) ``spacing`` sizes
    apart (a caption's line), from the left of ``at`` up, the last line's baseline at ``at``: the heading of a plan
    sheet, of the velocity plans, of a force sheet, of the kinematic diagrams, and each "continued"."""
    left, last = at
    return tuple(Text((left, last + spacing * size * (len(lines) - 1 - k)), line, size, "start", weight="bold")
                 for k, line in enumerate(lines))


def caption_texts(lines: Sequence[str], at: tuple[float, float]) -> tuple[Text, ...]:
    """A drawing's caption centred under ``at``: its name in bold, then its scale."""
    return tuple(Text((at[0], at[1] - k * CAPTION_LINE * CAPTION_SIZE), line, CAPTION_SIZE, "middle",
                      weight="bold" if k == 0 else "normal") for k, line in enumerate(lines))




__all__ = ["ZERO_MM", "PlanSheet", "caption_texts", "layout", "plan_layers", "title_texts", "too_short", "too_short_to_draw_mm"]
