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
from collections.abc import Collection, Sequence
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
    Anchor,
    breakable,
    broken_under,
    ink_of,
    obstacles_of,
    place_breaking_thin_lines,
    spaced_box,
    text_box,
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
                                             every + loaded + bold + frame + paths + dimension, breakable(every))
        dimension += items
        swing_labels += labels_of
        swing_texts += [item for item in items if travel.swing and isinstance(item, Text)]
    drawn = every + loaded + bold + frame + paths + dimension
    # The bold lines the numbers and letters keep off by their ink: the extremes, the springs and cylinders; the
    # letters the frame's symbols' too.  The travel's dimension they keep farther off (dimensions.kept_clear): kept off
    # its ink alone, the Scotch yoke's 8 stood level on the stroke's extension line as if it were the line's number.
    bold_lines = loaded + bold + dimension
    bold_ink = ink_of(loaded + bold) + dimensions.kept_clear(dimension)
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
    # The points' paths are thin lines too, broken under a letter with no clear spot by its point as the positions'
    # outlines are: kept whole, the V-twin's O stood struck through by the 5 mm circle that S2 runs round the pivot,
    # and the triad's A was led off across the crank's circle to keep clear of its pin's path.
    labels, breaking = place_breaking_thin_lines(anchors + swing_labels, every + paths, drawn, bold_lines + frame,
                                                 bold_ink + ink_of(frame), number_leaders, numbers,
                                                 _crowded_pins(plan, paper))
    # A swing's ψ set by its arc breaks the thin lines under it too (ГОСТ 2.307: no line crosses a dimension's number),
    # and so does a position's number round the crank's circle, set clear of the bold lines alone: the Scotch yoke's
    # 10 and 4 stood struck through by the ends of its slot at those positions, and the crank-rocker's 5 on the dashed
    # path of B.
    under = breaking + swing_texts + numbers
    every = broken_under(every, under, breakable(every))
    paths = broken_under(paths, under, breakable(paths))
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
    solid = STRtree(obstacles_of(without(drawn, thin)))

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
    pins = [item.pin for item in every]
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
        text, leader = _set_aside(item, centre, boxes, bold, pins)
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
            text, leader = _set_aside(item, centre, boxes, bold, pins)
        spaced = spaced_box(text, LABEL_SPACING / 2)
        if any(spaced.intersects(other) for other in boxes):
            if step > drawing_step:
                continue  # numbered one in every few already: one more left out is not missed
            # Every position is numbered: this one is set aside on a leader rather than left out.
            text, leader = _set_aside(item, centre, boxes, bold, pins)
            spaced = spaced_box(text, LABEL_SPACING / 2)
            if any(spaced.intersects(other) for other in boxes):
                continue
        texts.append(text)
        boxes.append(spaced)
        if leader is not None:
            leaders.append(leader)
    return texts, leaders, crowded


def _set_aside(item: _Number, centre: complex, boxes: list[BaseGeometry],
               lines: list[BaseGeometry], pins: Sequence[complex] = ()) -> tuple[Text, Polyline | None]:
    """The number of ``item`` beside its pin, or where that runs into one of ``boxes`` or ``lines``, the nearest spot
    clear of them a few degrees round the circle, short of the next of the positions' ``pins`` each way, or farther
    out, with a leader from its pin; clear of the boxes alone where no spot near is clear of both."""
    back, ahead = _room_round(item, centre, pins)
    spots = [(out, turn) for out in (0.0, 2.0, 4.0, 6.0, 9.0, 12.0) for step in range(13)
             for turn in ((0.0,) if step == 0 else (step * _ROUND_STEP, -step * _ROUND_STEP)) if -back < turn < ahead]
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


def _room_round(item: _Number, centre: complex, pins: Sequence[complex]) -> tuple[float, float]:
    """How far round the circle (radians, clockwise and counter-clockwise) ``item``'s number may be set aside
    without passing the pin of another position: past it the numbers read out of order, as 13, 15, 14 did under a
    V-twin's crank, the 14 carried round beyond the 15 of a plan position."""
    own = item.pin - centre
    back = ahead = math.pi
    for pin in pins:
        if abs(pin - item.pin) < _SAME_PIN_MM or abs(own) < 1e-9 or abs(pin - centre) < 1e-9:
            continue
        turn = cmath.phase((pin - centre) / own)
        if turn > 0:
            ahead = min(ahead, turn)
        elif turn < 0:
            back = min(back, -turn)
    return back, ahead


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
    blocked = block_pins(motion)
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
            anchors.append(Anchor(paper(r), f"{name}′", _LETTER_SIZE, math.atan2(away.imag, away.real) if away else math.pi / 2,
                                  symbol_mm=BLOCK_REACH_MM if name in blocked else 0.0))
    return anchors


def _point_anchors(plan: PositionsPlan, paper: Paper) -> list[Anchor]:
    """Names of the joints and named points at the first emphasised position."""
    motion = plan.emphasised
    # Points fixed on a link only: an RPR lever's point under the block (A4) would just repeat A's label.
    drawn = {name for names in plan.mechanism.fixed_on.values() for name in names}
    names = [name for name in motion.points if name in drawn]
    centroid = sum(complex(at(motion.points[n].r, 0)) for n in names) / len(names)
    blocked = block_pins(motion)
    anchors = []
    for name in names:
        r = complex(at(motion.points[name].r, 0))
        away = r - centroid
        anchors.append(Anchor(paper(r), name, _LETTER_SIZE, math.atan2(away.imag, away.real) if away else math.pi / 2,
                              symbol_mm=BLOCK_REACH_MM if name in blocked else 0.0))
    return anchors


def _centre_marks(plan: PositionsPlan, paper: Paper) -> list[Primitive]:
    return [dot_marker(paper(complex(at(plan.emphasised.points[spec.name].r, 0)))) for spec in plan.mechanism.scene.points]
