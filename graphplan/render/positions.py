"""The plan of positions: the mechanism at μl in all analysed positions, overlaid.

Thin grey outlines for every position, the extreme positions bold, each
position numbered at the driver's joint, the paths of the named points as
thin dashed curves, the frame pivots and guides drawn once.  The layout reads
solved motions and the mechanism's membership tables; it computes no
mechanics.
"""

from __future__ import annotations

import cmath
import itertools
import math
from collections.abc import Collection
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry import Polygon as ShapelyPolygon
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from ..kinematics import at
from ..mechanism import Mechanism
from ..motion import Motion
from . import dimensions, lettering
from .labels import (
    LABEL_GAP_MM,
    LABEL_SPACING,
    LEADER_GAP,
    Anchor,
    Placement,
    broken_under,
    ink_of,
    obstacles_of,
    place_labels,
    remembered,
    spaced_box,
    text_box,
)
from .linkage import (
    GROUND_MARGIN_MM,
    Paper,
    along_loads,
    frame_guide,
    frame_pivots,
    frame_points_along,
    ground_side,
    guide_bushing,
    links_at,
    loose_frame_points,
    outline_points,
)
from .plans import CAPTION_LINE, CAPTION_SIZE, TITLE_SIZE
from .primitives import (
    BOLD,
    MAIN,
    PIN_RADIUS_MM,
    Layer,
    Polyline,
    Primitive,
    Stroke,
    Text,
    bounds,
    dot_marker,
    slider_block,
    text_extent,
    text_width,
    to_complex,
    to_xy,
)

_POSITION_STROKE = Stroke(0.3, "#7a7a7a")
_PATH_STROKE = Stroke(0.25, "#1f5fa8", (2.0, 1.2))
_CRANK_CIRCLE_STROKE = Stroke(0.25, "#7a7a7a")
# The heights of the lettering (mm, render/lettering.py): the points' letters, the positions' numbers, a travel's
# dimension (H, ψ).
_LETTER_SIZE = lettering.POSITIONS_LETTER
_NUMBER_SIZE = lettering.POSITION_NUMBER
_DIMENSION_SIZE = lettering.DIMENSION
# A point of the second extreme nearer than this to where it stands at the first (mm on the paper) is lettered there
# already: a frame point, a pin that hardly moves.
_SAME_POINT_MM = 2.0
# Room a label keeps round the driver's pin at a bold position (mm), past the pin's own radius.
_PIN_CLEARANCE_MM = 0.8


@dataclass(frozen=True)
class PositionsPlan:
    """What the plan of positions shows: the motions it reads and how to letter them.

    ``emphasised`` holds the positions drawn bold: the two extremes of the
    working link, or the first position when the scene names none.
    ``extremes`` names each of them that is no numbered position drawn, as
    Russian course projects mark an extreme: the number of the position it
    follows with a prime (8′), its points lettered with a prime (A′, D′);
    empty for one that is a numbered position.  ``working_extremes`` says
    the bold positions are the working link's extremes: the second's points
    are then lettered with a prime where it is a numbered position too.
    ``marked`` holds the numbers always lettered however the numbers are
    thinned: the plan sheets' positions.
    """

    mechanism: Mechanism
    positions: Motion
    numbers: tuple[int, ...]
    emphasised: Motion
    paths: Motion
    length_scale: float
    title: str
    caption: str
    extremes: tuple[str, ...] = ()
    marked: tuple[int, ...] = ()
    travels: tuple[Travel, ...] = ()
    working_extremes: bool = False


@dataclass(frozen=True)
class Travel:
    """The travel between the two bold positions that the plan of positions dimensions, as a course drawing marks
    it: a slider's stroke H, where ``point`` slides along a frame guide, or a rocker's swing ψ, ``link`` rocking
    about the frame pivot ``point``; ``text`` is what is written (H = 0.2 m)."""

    point: str
    link: int
    text: str
    swing: bool = False


def layout(plan: PositionsPlan) -> list[Layer]:
    """The layers of the plan of positions, in paper millimetres (y up)."""
    mm_per_m = 1.0 / plan.length_scale

    def paper(r: complex) -> tuple[float, float]:
        return (r.real * mm_per_m, r.imag * mm_per_m)

    outlines = outline_points(plan.mechanism, plan.positions)
    every = _mechanism_at(plan.positions, outlines, paper, _POSITION_STROKE, bold=False)
    bold = _mechanism_at(plan.emphasised, outlines, paper, BOLD, bold=True)
    # The springs and cylinders at the first bold position alone: drawn at every position they would hide the links.
    loaded, load_pins = along_loads(plan.emphasised, 0, paper, _LETTER_SIZE, MAIN, span=plan.paths)
    bold += load_pins
    frame = _frame(plan, paper)
    paths = _paths(plan, paper)
    dimension: list[Primitive] = []
    swing_labels: list[Anchor] = []
    swing_texts: list[Text] = []
    for travel in plan.travels:  # each kept clear of those before it
        items, labels_of = _travel_dimension(plan, travel, paper, outlines,
                                             every + loaded + bold + frame + paths + dimension, _breakable(every))
        dimension += items
        swing_labels += labels_of
        swing_texts += [item for item in items if travel.swing and isinstance(item, Text)]
    drawn = every + loaded + bold + frame + paths + dimension
    # The bold lines the numbers and letters keep off by their ink: the extremes, the springs and cylinders, the
    # travel's dimension; the letters the frame's symbols' too.
    bold_lines = loaded + bold + dimension
    bold_ink = ink_of(bold_lines)
    if plan.mechanism.driver.kind == "crank":
        # Round the crank pin's circle: set outside it, one in every few where they would run together. Clear of
        # the frame's pivots' ink too, as the letters are: round a crank drawn a few millimetres long they fell on its
        # pivot's triangle.
        primed = _extreme_anchors(plan, paper, names=False)
        numbers, number_leaders, crowded = _numbers_round_the_circle(
            plan, paper, bold_ink + ink_of(frame_pivots(plan.mechanism, paper)),
            [anchor.at for anchor in primed])
        # A number that cannot stand on its radius at a pin lettered with primes is lettered with those letters, round
        # the pin: set aside first on its own, it took the nearest spot beside the pin and left its letters the spots
        # behind it (the Scotch yoke's 7 and B′, up to the left of its top pin, B′'s leader run under the 7).  Given
        # first among them, it takes the spot nearest its radius, and the letters stand round it.
        anchors = crowded + _point_anchors(plan, paper) + primed
    else:
        numbers, number_leaders = [], []
        anchors = _position_anchors(plan, paper) + _point_anchors(plan, paper) + _extreme_anchors(plan, paper)
    labels, breaking = _place_breaking_thin_lines(anchors + swing_labels, every, drawn, bold_lines + frame,
                                                  bold_ink + ink_of(frame), number_leaders, numbers,
                                                  _crowded_pins(plan, paper))
    # A swing's ψ set by its arc breaks the thin lines under it too (ГОСТ 2.307: no line crosses a dimension's number),
    # and so does a position's number round the crank's circle, set clear of the bold lines alone: the Scotch yoke's
    # 10 and 4 stood struck through by the ends of its slot at those positions.
    every = broken_under(every, breaking + swing_texts + numbers, _breakable(every))
    # A point's path too: the crank-rocker's 5 stood on the dashed path of B.
    paths = broken_under(paths, numbers, _breakable(paths))
    # Under the bold links and the frame: the pins they draw stand over the ends of the springs and cylinders.
    layers = [Layer("paths", tuple(paths)), Layer("positions", tuple(every)),
              *([Layer("load-links", tuple(loaded))] if loaded else []), Layer("extremes", tuple(bold)),
              Layer("frame", tuple(frame)), Layer("dimensions", tuple(dimension)),
              Layer("leaders", tuple(number_leaders) + labels.leaders),
              Layer("labels", tuple(numbers) + labels.texts + tuple(_centre_marks(plan, paper)))]
    xmin, _, _, ymax = bounds(layers)
    # Lettered as the plan sheets' headings beside it on the kinematics sheet: the title over its scale.
    scale_line = ymax + 5.0
    layers.append(Layer("caption", (Text((xmin, scale_line + CAPTION_LINE * CAPTION_SIZE), plan.title, TITLE_SIZE,
                                         "start", weight="bold"),
                                    Text((xmin, scale_line), plan.caption, CAPTION_SIZE, "start"))))
    return layers


def _place_breaking_thin_lines(anchors: list[Anchor], every: list[Primitive], drawn: list[Primitive],
                               inked: list[Primitive], ink: list[BaseGeometry], number_leaders: list[Polyline],
                               numbers: list[Text], pins: list[BaseGeometry]) -> tuple[Placement, list[Text]]:
    """The labels placed clear of the drawn lines, and those of them that the thin lines of the other positions
    break under (:func:`~graphplan.render.labels.broken_under`).

    The ``inked`` lines among ``drawn`` (the extremes, the springs and cylinders, the travel's dimension, and the
    frame's symbols, whose thin hatching is never broken under a label either) are kept clear of as wide as their
    strokes draw them (``ink``, :func:`~graphplan.render.labels.ink_of`), as the numbers round the crank's circle are: clear of
    their middles alone, the Scotch yoke's A′ stood 0.2 mm into the ink of the 0.7 mm block round its top pin, S4 half
    a millimetre into its 1 mm rod, and the engine's O on its pivot's hatching.  A leader is kept from running beside
    a line, nearly along it (``place_labels``' ``leaders_apart``): the slider driven mechanism's G was led down
    beside a stroke of its guide's hatching, reading as one more, and a crank's pivot O led off along the thin lines
    of the crank's positions.  The labels of one point (a crowded crank pin's number and its primed letters) then
    stand each in a direction of its own from it (:func:`_each_in_its_own_direction`).

    Where the thin lines leave no clear spot near a point (the crank's pivot, that every crank position's line
    leaves; a swing's ψ on its arc, across the rocker's positions; a centre of mass among the links' thin
    outlines), a draughtsman letters it beside its point all the same, clear of the bold lines and the frame's
    symbols, and breaks the thin lines under the letters, as ГОСТ 2.307 breaks thin lines under a dimension's
    number: set farther out on a leader it was read as naming something else.  Those labels are placed again
    without the thin lines, then the rest round them; their leaders, which the thin lines are not broken under, kept
    from running beside those lines all the same (the Scotch yoke's O was led out along the thin line of a position
    of its rod)."""
    obstacles = obstacles_of(_without(drawn, inked) + number_leaders) + ink + pins
    first = _each_in_its_own_direction(
        remembered(place_labels, anchors, obstacles, standing=numbers, reach_farther=False, leaders_apart=True),
        anchors, obstacles, numbers)
    lines = [shape for shape in obstacles_of(drawn + number_leaders + list(first.leaders))
             if shape.geom_type == "LineString"]
    tree = STRtree(lines)
    breaking = [index for index, text in enumerate(first.texts)
                if len(tree.query(text_box(text), predicate="intersects"))]
    if not breaking:
        return first, []
    over = remembered(place_labels, [anchors[index] for index in breaking],
                      obstacles_of(_without(drawn, _breakable(every) + inked) + number_leaders) + ink + pins,
                      standing=numbers, leaders_apart=obstacles_of(_breakable(every)))
    rest = [index for index in range(len(anchors)) if index not in breaking]
    others = remembered(place_labels, [anchors[index] for index in rest],
                        obstacles + obstacles_of(list(over.leaders)), standing=[*numbers, *over.texts],
                        leaders_apart=True)
    texts = dict(zip(breaking, over.texts)) | dict(zip(rest, others.texts))
    return Placement(tuple(texts[index] for index in range(len(anchors))), over.leaders + others.leaders), \
        list(over.texts)


# Two labels of one point stand apart, seen from it, by this many of their letters' heights: the line from the point
# to one (its leader, or where a leader would run) keeps this far from the other.
_SIGHT_CLEARANCE = 1.0
# How far out the shadow of a label reaches from its point (mm), seen from which another label would stand behind it.
_SHADOW_MM = 60.0


def _each_in_its_own_direction(placement: Placement, anchors: list[Anchor], obstacles: list[BaseGeometry],
                               standing: list[Text]) -> Placement:
    """``placement`` with each label that stands, seen from its point, behind or in front of another label of the same
    point (their directions from it overlapping, or the line from the point to one running within a letter's height
    of the other) placed again alone, out of the others' shadows, where a spot clear of everything is: the leader to
    one would run past the other, reading as leading to it (the Scotch yoke's top pin, its number 7 and its letters
    A′ and B′, the 7 and B′ one behind the other up to the left of it, B′'s leader passing under the 7).  The placer
    costs what a label covers, and two labels of one point stand a label's width apart there all the same."""
    texts, leaders = list(placement.texts), list(placement.leaders)
    by_point: dict[tuple[float, float], list[int]] = {}
    for index, anchor in enumerate(anchors):
        by_point.setdefault((round(anchor.at[0], 6), round(anchor.at[1], 6)), []).append(index)
    for point, group in by_point.items():
        for index in group[1:]:
            others = [k for k in group if k != index]
            clearance = _SIGHT_CLEARANCE * anchors[index].size
            if not any(_one_behind_another(text_box(texts[index]), text_box(texts[k]), point, clearance)
                       for k in others):
                continue
            own_leader = _leader_of(leaders, texts[index])
            around = [leader for leader in leaders if leader is not own_leader]
            shadows = [_shadow(text_box(texts[k]), point, clearance) for k in others]
            kept_off = [*obstacles, *obstacles_of(around), *shadows]
            again = remembered(place_labels, [anchors[index]], kept_off,
                               standing=[*standing, *(text for k, text in enumerate(texts) if k != index)],
                               reach_farther=False, leaders_apart=True)
            (moved,) = again.texts
            box = text_box(moved)
            if (any(box.intersects(shape) for shape in kept_off)
                    or any(box.intersects(spaced_box(text)) for k, text in enumerate(texts) if k != index)
                    or any(leader.intersects(spaced_box(text)) for leader in obstacles_of(list(again.leaders))
                           for k, text in enumerate(texts) if k != index)):
                continue  # nowhere clear: left where the placer set it
            texts[index] = moved
            leaders = around + list(again.leaders)
    return Placement(tuple(texts), tuple(leaders))


def _one_behind_another(one: BaseGeometry, other: BaseGeometry, point: tuple[float, float], clearance: float) -> bool:
    """Whether the boxes ``one`` and ``other`` stand one behind the other seen from ``point``: their spans of
    direction from it overlapping, or the line from the point to the nearest side of either running within
    ``clearance`` of the other."""
    (a0, a1), (b0, b1) = _span(one, point), _span(other, point)
    apart = math.remainder((b0 + b1) / 2 - (a0 + a1) / 2, math.tau)
    if abs(apart) <= (a1 - a0) / 2 + (b1 - b0) / 2:
        return True
    seen = ShapelyPoint(point)
    return any(shapely.shortest_line(seen, box).distance(far) < clearance for box, far in ((one, other), (other, one)))


def _span(box: BaseGeometry, point: tuple[float, float]) -> tuple[float, float]:
    """The least and greatest direction (radians) from ``point`` to the corners of ``box``, which stands beside it."""
    x0, y0, x1, y1 = box.bounds
    middle = math.atan2((y0 + y1) / 2 - point[1], (x0 + x1) / 2 - point[0])
    turns = [math.remainder(math.atan2(y - point[1], x - point[0]) - middle, math.tau)
             for x in (x0, x1) for y in (y0, y1)]
    return middle + min(turns), middle + max(turns)


def _shadow(box: BaseGeometry, point: tuple[float, float], clearance: float) -> BaseGeometry:
    """Where, seen from ``point``, a label would stand behind or in front of the label of ``box``: the wedge from the
    point through the box's corners, out to :data:`_SHADOW_MM`, and the box grown by ``clearance`` (the line to a
    label there would run past it)."""
    x0, y0, x1, y1 = box.bounds
    corners = [(x, y) for x in (x0, x1) for y in (y0, y1)]
    reach = [(point[0] + (x - point[0]) * _SHADOW_MM / math.dist((x, y), point),
              point[1] + (y - point[1]) * _SHADOW_MM / math.dist((x, y), point)) for x, y in corners]
    return shapely.union(shapely.MultiPoint([point, *corners, *reach]).convex_hull, box.buffer(clearance))


def _leader_of(leaders: list[Polyline], text: Text) -> Polyline | None:
    """The leader of ``leaders`` that ends at the label ``text`` (:data:`~graphplan.render.labels.LEADER_GAP` short
    of its box), if any."""
    box = text_box(text)
    ends = [leader for leader in leaders if ShapelyPoint(leader.points[-1]).distance(box) < 2 * LEADER_GAP]
    return ends[0] if ends else None


def _without(items: list[Primitive], left_out: list[Primitive]) -> list[Primitive]:
    """``items`` but those of ``left_out`` (the same objects): the drawing's solid lines without its thin ones."""
    out = {id(item) for item in left_out}
    return [item for item in items if id(item) not in out]


def _breakable(items: list[Primitive]) -> list[Polyline]:
    """The lines of ``items`` that a label may break: open or unfilled outlines (not a slider's block)."""
    return [item for item in items if isinstance(item, Polyline) and not item.fill and len(item.points) >= 2]


def _mechanism_at(motion: Motion, outlines: dict[int, list[str]], paper: Paper, stroke: Stroke,
                  bold: bool) -> list[Primitive]:
    return [item for index in range(motion.count) for item in links_at(motion, index, outlines, paper, stroke, bold)]


def _frame(plan: PositionsPlan, paper: Paper) -> list[Primitive]:
    """Fixed pivots and frame guides, drawn once; a guide's ground spans its slider's whole travel, and its line
    runs on to the frame points on it (the point a triad's guide is named through)."""
    mechanism, motion = plan.mechanism, plan.paths
    frame = mechanism.scene.frame_link
    items: list[Primitive] = []
    for slide in motion.slides:
        if slide.guide != frame:
            continue
        track = np.atleast_1d(motion.points[slide.joint].r)
        u = complex(at(slide.u, 0))
        origin = complex(track[0])
        along = ((track - origin) * np.conj(u)).real
        margin = GROUND_MARGIN_MM * plan.length_scale
        travel = (float(along.min()) - margin, float(along.max()) + margin)
        reach = frame_points_along(mechanism, origin, u)
        first, last = min([travel[0], *reach]), max([travel[1], *reach])
        ground = (guide_bushing(mechanism, motion, slide.slider, slide.joint, u, plan.length_scale)
                  or (origin + travel[0] * u, origin + travel[1] * u))
        ends = [((end - origin) * u.conjugate()).real for end in ground]
        first, last = min(first, *ends), max(last, *ends)
        links = (complex(r) for point in motion.points.values() for r in np.atleast_1d(point.r))
        items.extend(frame_guide(origin + first * u, origin + last * u, u, plan.length_scale, paper, ground,
                                 side=ground_side(links, origin, u)))
    items.extend(frame_pivots(mechanism, paper))
    items.extend(loose_frame_points(mechanism, paper))
    return items


# How far a stroke's dimension line is tried off the slider's joint: past the block and the guide's hatching (mm).
_STROKE_OFFSETS_MM = (10.0, 14.0, 18.0, 24.0, 30.0, 40.0, 50.0)
# The radii a swing's arc is tried at, as shares of the rocker's length on the paper (the middle one preferred),
# and the least radius it is drawn at (mm).
_SWING_SHARES = (0.55, 0.5, 0.6, 0.45, 0.65, 0.4, 0.7, 0.35, 0.75, 0.8, 0.85)
_SWING_LEAST_MM = 8.0
# How near a solid line runs alongside a swing's arc (mm).
_ALONGSIDE_MM = 3.0


def _travel_dimension(plan: PositionsPlan, travel: Travel, paper: Paper, outlines: dict[int, list[str]],
                      drawn: list[Primitive], thin: list[Primitive]) -> tuple[list[Primitive], list[Anchor]]:
    """The stroke H or the swing ψ between the two bold positions, dimensioned, and a swing's label to place at
    its arc's middle; nothing where there are not two.  A swing's arc is drawn at the radius where it crosses the
    fewest of the ``drawn`` lines (through the crank's circle, the quick-return lever's ran over the crank), a
    stroke's on the side and at the offset where its lines and text cross fewest.  A swing's arc goes first where
    its ψ, beside the arc's middle, meets none of the ``drawn`` lines but the ``thin`` ones, which break under it
    (:func:`~graphplan.render.labels.broken_under`): across a rocker's extremes a long ψ inside a narrow angle lay on them."""
    bold = plan.emphasised
    if bold.count < 2:
        return [], []
    track = [to_complex(paper(complex(at(bold.points[travel.point].r, i)))) for i in (0, 1)]
    shapes = STRtree(obstacles_of(drawn))

    def crossed(items: list[Primitive]) -> int:
        """What ``items`` run over; a text over a line three times a line over a line (it hides, a line crosses)."""
        return sum((3 if isinstance(item, Text) else 1) * len(shapes.query(shape, predicate="intersects"))
                   for item in items for shape in obstacles_of([item]))

    if not travel.swing:
        # Out from the mechanism's middle, where the guide's hatching is, unless the other side is clearer (a
        # Scotch yoke's middle lies on its stroke's line: its H landed on the crank's circle).
        middle = np.mean([to_complex(paper(complex(r))) for point in plan.paths.points.values()
                          for r in np.atleast_1d(point.r)])
        away = (track[0] + track[1]) / 2 - middle
        tried = [dimensions.linear(to_xy(track[0]), to_xy(track[1]), side * away, offset, travel.text, _DIMENSION_SIZE)
                 for offset in _STROKE_OFFSETS_MM for side in (1.0, -1.0)]
        return min(tried, key=crossed), []  # the first of the clearest: the nearest, away from the middle
    pivot = track[0]
    far = max((name for name in outlines.get(travel.link, ()) if name != travel.point),
              key=lambda name: abs(complex(at(bold.points[name].r, 0)) - complex(at(bold.points[travel.point].r, 0))),
              default=None)
    if far is None:
        return [], []
    ends = [to_complex(paper(complex(at(bold.points[far].r, i)))) - pivot for i in (0, 1)]
    start = cmath.phase(ends[0])
    sweep = cmath.phase(ends[1] / ends[0])

    middle = start + sweep / 2
    solid = STRtree(obstacles_of(_without(drawn, thin)))

    def tried(share: float) -> tuple[tuple[bool, int, int], float, list[Primitive], tuple[int, float]]:
        """A swing's arc at ``share`` of the lever's drawn length: its cost, its radius, the arc, and the fewest
        solid lines its ψ meets beside the arc's middle (outside the arc or inside it) with the side it stands."""
        radius = max(share * min(abs(end) for end in ends), _SWING_LEAST_MM)
        arc = dimensions.angular(to_xy(pivot), radius, start, sweep)
        own = obstacles_of(arc)
        sides = []
        for side in (middle, middle + math.pi):
            box = text_box(_beside_arc(pivot + cmath.rect(radius, middle), cmath.rect(1.0, side), travel.text))
            sides.append((len(solid.query(box, predicate="intersects")) + sum(box.intersects(shape) for shape in own),
                          side))
        label = min(sides)
        # A solid line alongside the arc (a point's path at about its radius) reads as one with it.
        alongside = len(solid.query(own[0].buffer(_ALONGSIDE_MM), predicate="intersects"))
        return (label[0] > 0, alongside, crossed(arc[:1])), radius, arc, label

    # The first of the fewest: the nearest the middle share.
    _, radius, arc, (hits, side) = min((tried(share) for share in _SWING_SHARES), key=lambda option: option[0])
    if not hits:
        # Written as a dimension's number is, by its arc's middle: left to the placer, it took a leader, the spot
        # beside the arc too tight for its spaced box.
        return [*arc, _beside_arc(pivot + cmath.rect(radius, middle), cmath.rect(1.0, side), travel.text)], []
    return arc, [Anchor(to_xy(pivot + cmath.rect(radius, middle)), travel.text, _DIMENSION_SIZE, prefer=middle)]


def _beside_arc(at: complex, outward: complex, text: str) -> Text:
    """``text`` set level with its box's near side the placer's gap clear of ``at`` along ``outward``."""
    left, bottom, right, top = text_extent(Text((0.0, 0.0), text, _DIMENSION_SIZE, "middle"))
    reach = abs(outward.real) * (right - left) / 2 + abs(outward.imag) * (top - bottom) / 2 + LABEL_GAP_MM
    centre = at + outward * reach
    return Text((centre.real, centre.imag - (top + bottom) / 2), text, _DIMENSION_SIZE, "middle")


def _paths(plan: PositionsPlan, paper: Paper) -> list[Primitive]:
    driver = plan.mechanism.driver
    closed = driver.cyclic
    items: list[Primitive] = []
    named = {spec.name for spec in plan.mechanism.scene.points}
    if driver.kind == "crank" and driver.joint not in named:
        # The crank pin's circle (a rocking crank's arc), on which the positions are numbered: the first line
        # a student draws on the plan of positions.
        pin = np.atleast_1d(plan.paths.points[driver.joint].r)
        items.append(Polyline(tuple(paper(r) for r in pin), _CRANK_CIRCLE_STROKE, closed=closed))
    for spec in plan.mechanism.scene.points:
        track = np.atleast_1d(plan.paths.points[spec.name].r)
        if len(track) > 1 and np.ptp(track.real) + np.ptp(track.imag) > 0:
            items.append(Polyline(tuple(paper(r) for r in track), _PATH_STROKE, closed=closed))
    return items


def _position_anchors(plan: PositionsPlan, paper: Paper) -> list[Anchor]:
    """Each position's number at the driver's joint, on the side away from the driver's centre."""
    driver = plan.mechanism.driver
    joint = plan.positions.points[driver.joint].r
    centre = _driver_centre(plan)
    anchors = []
    for index, number in enumerate(plan.numbers):
        outward = complex(at(joint, index)) - centre
        anchors.append(Anchor(paper(complex(at(joint, index))), str(number), _NUMBER_SIZE, math.atan2(outward.imag, outward.real),
                              "#333333"))
    return anchors


@dataclass(frozen=True)
class _Number:
    """A number (or an extreme's name, 8′) to set beside the crank pin at ``pin`` (paper mm), along ``outward``,
    clear of the slider ``block`` drawn on the pin (a slotted lever's)."""

    text: str
    pin: complex
    outward: complex
    block: BaseGeometry | None = None


def _numbers_round_the_circle(plan: PositionsPlan, paper: Paper, bold: list[BaseGeometry],
                              lettered: Collection[tuple[float, float]] = ()
                              ) -> tuple[list[Text], list[Polyline], list[Anchor]]:
    """The positions' numbers round the crank pin's circle (or a rocking crank's arc), each just outside it on the
    line from the pivot through its pin, as a draughtsman numbers them, and the leaders of those set aside.

    The first position, the plan sheets' positions (``PositionsPlan.marked``) and the extremes named 8′ are always
    numbered; one that would run into another, or into the ``bold`` lines of the extreme positions (the rod leaving
    its pin outward) or the travel's dimension, is set a little round the circle or farther out, on a leader. Of the
    rest, one in every few is numbered, the fewest skipped that keep every number clear of its neighbours
    (36 positions on a small crank are numbered 1, 3, 5, …); where they are thinned so, one that would run into a
    number always given is left out, and where every position is numbered, it is set aside as those are.

    A number (or an extreme's name) that would be set aside at a pin where letters with primes stand (``lettered``,
    the points of :func:`_extreme_anchors`' anchors) is given back as an anchor instead, to be placed with them.
    """
    driver = plan.mechanism.driver
    centre = complex(*paper(plan.mechanism.scene.frame_points[driver.pivot]))

    def number(name: str, motion: Motion, index: int) -> _Number:
        pin = complex(*paper(complex(at(motion.points[driver.joint].r, index))))
        outward = pin - centre
        blocks = [ShapelyPolygon(slider_block((pin.real, pin.imag), float(np.angle(complex(at(slide.u, index))))).points)
                  for slide in motion.slides if slide.joint == driver.joint]
        return _Number(name, pin, outward / abs(outward) if abs(outward) > 1e-9 else 1j, blocks[0] if blocks else None)

    every = [number(str(value), plan.positions, index) for index, value in enumerate(plan.numbers)]
    always = [every[0], *(item for index, item in enumerate(every) if index and plan.numbers[index] in plan.marked)]
    always += [number(name, plan.emphasised, index)
               for index, name in enumerate(plan.extremes) if name and index < plan.emphasised.count]
    texts: list[Text] = []
    leaders: list[Polyline] = []
    boxes: list[BaseGeometry] = []
    crowded: list[Anchor] = []

    def with_its_letters(item: _Number) -> bool:
        """Whether ``item``, whose number stands off its radius, is left to be placed with the letters of its pin."""
        pin = next((point for point in lettered if abs(complex(*point) - item.pin) < _SAME_PIN_MM), None)
        if pin is None:
            return False
        crowded.append(Anchor(pin, item.text, _NUMBER_SIZE,
                              math.atan2(item.outward.imag, item.outward.real), _NUMBER_COLOUR))
        return True

    for item in always:
        text, leader = _set_aside(item, centre, boxes, bold)
        if leader is not None and with_its_letters(item):
            continue
        texts.append(text)
        boxes.append(spaced_box(text, LABEL_SPACING / 2))
        if leader is not None:
            leaders.append(leader)
    # The positions drawn one in every few (more than 36 of them) are numbered on that grid, the plan sheets' positions
    # drawn besides them off it.
    first = plan.numbers[0]
    drawing_step = math.gcd(*(value - first for value in plan.numbers if value not in plan.marked)) or 1
    step = next(step for step in itertools.count(drawing_step, drawing_step)
                if _clear([item for item, value in zip(every, plan.numbers) if (value - first) % step == 0]))
    for item, value in zip(every[1:], plan.numbers[1:]):
        if (value - first) % step or value in plan.marked:
            continue
        # A little farther out along its line where a bold line runs through it, if that clears it; else round the
        # circle on a leader (the Scotch yoke's rod runs out along the line of its top position's number).
        text = next((text for text in (_number_text(item, out) for out in (0.0, 1.0, 2.0, 3.0))
                     if not any(text_box(text).intersects(line) for line in bold)), None)
        leader = None
        if text is None:
            # Numbered one in every few, one that cannot stand on its radius is left out sooner than set aside on a
            # leader into the room the others need: round a crank drawn a millimetre long the 9, set below the
            # pivot off a link's ink, left the 5′ no spot but the pivot's triangle.
            if step > drawing_step or with_its_letters(item):
                continue
            text, leader = _set_aside(item, centre, boxes, bold)
        spaced = spaced_box(text, LABEL_SPACING / 2)
        if any(spaced.intersects(other) for other in boxes):
            if step > drawing_step:
                continue  # numbered one in every few already: one more left out is not missed
            # Every position is numbered: this one is set aside on a leader rather than left out.
            text, leader = _set_aside(item, centre, boxes, bold)
            spaced = spaced_box(text, LABEL_SPACING / 2)
            if any(spaced.intersects(other) for other in boxes):
                continue
        texts.append(text)
        boxes.append(spaced)
        if leader is not None:
            leaders.append(leader)
    return texts, leaders, crowded


def _set_aside(item: _Number, centre: complex, boxes: list[BaseGeometry],
               lines: list[BaseGeometry]) -> tuple[Text, Polyline | None]:
    """The number of ``item`` beside its pin, or where that runs into one of ``boxes`` or ``lines``, the nearest spot
    clear of them a few degrees round the circle or farther out, with a leader from its pin; clear of the boxes
    alone where no spot near is clear of both."""
    spots = [(out, turn) for out in (0.0, 2.0, 4.0, 6.0, 9.0, 12.0) for step in range(13)
             for turn in ((0.0,) if step == 0 else (step * _ROUND_STEP, -step * _ROUND_STEP))]
    for avoided in (lines, []):
        for out, turn in spots:
            turned = cmath.exp(1j * turn)
            text = _number_text(_Number(item.text, centre + (item.pin - centre) * turned, item.outward * turned,
                                        item.block), out)
            spaced = spaced_box(text, LABEL_SPACING / 2)
            if any(spaced.intersects(other) for other in boxes) or any(text_box(text).intersects(line)
                                                                     for line in avoided):
                continue
            if not out and not turn:
                return text, None
            # The leader from the pin's rim to the near side of the box.
            near = shapely.shortest_line(ShapelyPoint(item.pin.real, item.pin.imag), text_box(text)).coords[1]
            along = complex(*near) - item.pin
            start = item.pin + along / abs(along) * _NUMBER_GAP_MM
            return text, Polyline(((start.real, start.imag), near), Stroke(0.18, _NUMBER_COLOUR))
    return _number_text(item, 0.0), None  # nowhere near is clear: beside its pin after all


# A crank pin nearer than this (mm) to a point lettered with a prime is that point.
_SAME_PIN_MM = 1e-6
# How far round the circle a number set aside is tried at a time (radians).
_ROUND_STEP = math.radians(4.0)


# How far a number stands off its crank pin (mm): clear of the pin drawn at a bold position.
_NUMBER_GAP_MM = PIN_RADIUS_MM + _PIN_CLEARANCE_MM
_NUMBER_COLOUR = "#333333"


def _number_text(item: _Number, out: float) -> Text:
    """The number of ``item`` set with the nearest side of its box ``out`` mm past :data:`_NUMBER_GAP_MM` off its
    pin, along the line from the pivot (and past the block on it): the box then stands wholly outside the crank's
    circle."""
    width, height = text_width(item.text, _NUMBER_SIZE), 1.45 * _NUMBER_SIZE
    # The half-extent of the box along the outward line, and its middle above the text's baseline.
    reach = abs(item.outward.real) * width / 2 + abs(item.outward.imag) * height / 2

    def text(off: float) -> Text:
        middle = item.pin + item.outward * (_NUMBER_GAP_MM + off + reach)
        return Text((middle.real, middle.imag - 0.425 * _NUMBER_SIZE), item.text, _NUMBER_SIZE, "middle", _NUMBER_COLOUR)

    past = 0.0
    while item.block is not None and past < 10.0 and spaced_box(text(past), LABEL_SPACING / 2).intersects(item.block):
        past += 0.5
    return text(past + out)


def _clear(items: list[_Number]) -> bool:
    """Whether the numbers of ``items``, each set beside its pin, all stand apart from one another."""
    boxes = [spaced_box(_number_text(item, 0.0), LABEL_SPACING / 2) for item in items]
    tree = STRtree(boxes)
    first, second = tree.query(boxes, predicate="intersects")
    return bool(np.all(first == second))


def _crowded_pins(plan: PositionsPlan, paper: Paper) -> list[BaseGeometry]:
    """The driver's pin at each bold position, grown: its number and its letter both stand round it, and a
    label only clear of the pin itself read as run into it (position 0's "0" and "A" on the Stephenson six-bar)."""
    joint = plan.emphasised.points[plan.mechanism.driver.joint].r
    return [ShapelyPoint(paper(complex(at(joint, index)))).buffer(PIN_RADIUS_MM + _PIN_CLEARANCE_MM)
            for index in range(plan.emphasised.count)]


def _driver_centre(plan: PositionsPlan) -> complex:
    """Where the position numbers point away from: a crank's pivot, else the middle of the driver's run."""
    driver = plan.mechanism.driver
    if driver.kind == "crank":
        return plan.mechanism.scene.frame_points[driver.pivot]
    joint = plan.positions.points[driver.joint].r
    return complex(np.mean(np.atleast_1d(joint))) + 1j * complex(at(plan.positions.links[driver.link].u, 0))


def _extreme_anchors(plan: PositionsPlan, paper: Paper, names: bool = True) -> list[Anchor]:
    """An extreme that is no numbered position: its name (8′) at the driver's joint, as the positions are
    numbered (unless ``names`` is false: round a crank's circle they are set with the numbers), and its points
    lettered with a prime; it stood bold with neither.  An extreme that is a numbered position keeps its number
    and is lettered with a prime too (``PositionsPlan.working_extremes``): lettered with neither, as it was, a
    reader could not tell which bold outline was which end of the stroke."""
    driver = plan.mechanism.driver
    motion = plan.emphasised
    centre = _driver_centre(plan)
    # The letters of the joints and points; a centre of mass that is no joint (S4) at the first extreme only.
    named = {spec.name for spec in plan.mechanism.scene.points}
    centres = {spec.centre for spec in plan.mechanism.scene.links.values()} & named
    drawn = {name for names in plan.mechanism.fixed_on.values() for name in names} - centres
    anchors = []
    for index, label in enumerate(plan.extremes):
        if index >= motion.count or not (label or plan.working_extremes):
            continue
        joint = complex(at(motion.points[driver.joint].r, index))
        outward = joint - centre
        if names and label:
            anchors.append(Anchor(paper(joint), label, _NUMBER_SIZE, math.atan2(outward.imag, outward.real), "#333333"))
        moving = [name for name in motion.points if name in drawn
                  and abs(complex(at(motion.points[name].r, index)) - complex(at(motion.points[name].r, 0)))
                  > _SAME_POINT_MM * plan.length_scale]
        if not moving:
            continue
        middle = sum(complex(at(motion.points[name].r, index)) for name in moving) / len(moving)
        for name in moving:
            r = complex(at(motion.points[name].r, index))
            away = r - middle
            anchors.append(Anchor(paper(r), f"{name}′", _LETTER_SIZE, math.atan2(away.imag, away.real) if away else math.pi / 2))
    return anchors


def _point_anchors(plan: PositionsPlan, paper: Paper) -> list[Anchor]:
    """Names of the joints and named points at the first emphasised position."""
    motion = plan.emphasised
    # Points fixed on a link only: an RPR lever's point under the block (A4) would just repeat A's label.
    drawn = {name for names in plan.mechanism.fixed_on.values() for name in names}
    names = [name for name in motion.points if name in drawn]
    centroid = sum(complex(at(motion.points[n].r, 0)) for n in names) / len(names)
    anchors = []
    for name in names:
        r = complex(at(motion.points[name].r, 0))
        away = r - centroid
        anchors.append(Anchor(paper(r), name, _LETTER_SIZE, math.atan2(away.imag, away.real) if away else math.pi / 2))
    return anchors


def _centre_marks(plan: PositionsPlan, paper: Paper) -> list[Primitive]:
    return [dot_marker(paper(complex(at(plan.emphasised.points[spec.name].r, 0)))) for spec in plan.mechanism.scene.points]
