"""The balancing polygons of a rotor, one per correction plane, side by side, each at its own scale.

Each correction plane's polygon is drawn from its record
(:class:`graphplan.rotor_balancing.CorrectionPlane`) as the student draws
it: from the pole, the masses' mass-radius products (their shares in the
plane) laid off head to tail, in the masses' order or, where that turns a
share back onto the one before it, in the first order that does not (a sum
is the same in any order; the caption's equation is written in the order
drawn), at the plane's μ (kg·m per mm, the standard
scale that draws it about as large as the others: a plane near the masses'
middle carries small shares and would shrink to a knot of labels at the
other plane's scale), each named beside its
middle; then the closing vector, the correction mb·rb, drawn thicker in
red from the last tip back to the pole, with its angle θ measured from a
dashed x-direction at its tail, or at its head to its line run on past the
pole where the tail leaves a side's name no room.  Under each polygon its caption: the plane,
its scale, its vector equation, any vector drawn beside the chain with what it would cover in its place, the
correction's product, angle and mass, and under the one plane of a static
balancing the couple Σ m·r·z it leaves.  The layout
reads the record and computes no mechanics.  Every word and unit comes from
``text``, the ``bal_`` keys of a locale (:func:`graphplan.locale.strings`);
English when none is given.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import replace
from functools import lru_cache

from shapely.geometry import LineString
from shapely.geometry import Point as ShapelyPoint

from ..locale import Count, strings
from ..rotor_balancing import POLYGON_FIELD_MM, BalancingResult, CorrectionPlane, PolygonVector, static_couple
from ..scales import format_scale, standard_scale
from . import lettering
from .force_rows import CAPTION_WIDTH_MM, caption_lines
from .labels import Anchor, Placement, obstacles_of, place_labels, remembered
from .numerals import angle_in_turn, significant
from .plans import CAPTION_GAP_MM, CAPTION_LINE, CAPTION_SIZE, TITLE_SIZE, ZERO_MM, too_short_lines
from .primitives import (
    Arrow,
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
    text_width,
)
from .primitives import to_complex as _c
from .primitives import to_xy as _xy
from .svg import to_svg
from .wrapping import fitted

# Space between the polygons of two planes (mm).
GAP_MM = 25.0
# The title's baseline stands this far over the drawing's top (mm), and takes at most this many lines at its size.
TITLE_GAP_MM = 8.0
MOST_TITLE_LINES = 2
# The dashed x-direction at the correction's tail, and the arc of its angle (mm).
REFERENCE_MM = 16.0
# The heights of the vectors' names and of the correction's angle θ (mm, render/lettering.py).
NAME_SIZE = lettering.NAME
ANGLE_NAME_SIZE = lettering.ARM_NAME
# A correction that would lie along a mass vector (one mass, masses at one angle, a couple: the polygon a straight
# line) would hide it: it is drawn this far beside the chain, parallel to where it closes the polygon, with thin
# leaders from the chain's ends, as a textbook draws the closing side of a flat polygon (mm).
BESIDE_MM = 6.0
# Closer than this to the correction's line, over a common stretch longer than this, a mass vector is hidden (mm).
ALONG_MM = 0.8
# A mass vector within this angle of the correction's line, half or more of whose length runs that close to it, is
# hidden too, though one end stands off it: a share leaving the pole a degree off the correction ran under it for
# three quarters of its length.
HIDDEN_DEG = 25.0
# A share that turns back along the one before it, within this angle of straight back, and ends within
# FOLDED_ONTO_MM of it (an arrowhead's length and width), runs over it from their common corner: its arrowhead sat on
# the other's and its name by the other's head.  It is drawn BESIDE_MM beside the chain, parallel to where it lies,
# with thin leaders from its true ends, as the correction along the masses is.  (A long share turning back at an
# acute corner stands clear of the other but near the corner, and stays where it is.)
FOLDED_BACK_DEG = 25.0
FOLDED_ONTO_MM = 2.5
# The orders of laying off the shares tried, at most, for one that draws none of them apart (a share folded back, a
# correction along the masses), and the partial orders the search may extend: each order weighed takes a few tenths
# of a millisecond, and twelve masses' orders, 2000 of them weighed, took 1.5 s.
MOST_ORDERS = 200
MOST_STEPS = 5000
# The radii tried for the correction's angle θ (mm), at its tail and then at its head, the first preferred: the one
# whose arc crosses the fewest sides, and of those the one that sends the fewest names out on leaders.
ANGLE_RADII_MM = (7.0, 5.5, 4.5, 9.0, 11.0)

# The layer of the drawing's title over its polygons: a sheet stands it as the drawing's heading.
TITLE_LAYER = "balancing-title"

_SHARE = Stroke(0.5)
_CORRECTION = Stroke(0.8, "#a83a1f")
_REFERENCE = Stroke(0.25, "#333333", (2.5, 1.5))
_ANGLE = Stroke(0.3, "#a83a1f")
_LEADER = Stroke(0.18, "#a83a1f", (1.0, 1.0))
_SHARE_LEADER = Stroke(0.18, "#333333", (1.0, 1.0))

# The fields (mm) the polygons are drawn larger to on a sheet with room (:func:`larger_layouts`), as a course project
# fills its sheet: at POLYGON_FIELD_MM the rotor starter's two planes took a twentieth of an A1, in its middle.
LARGER_FIELDS_MM = (120.0, 160.0, 200.0, 250.0, 320.0)


def layout(result: BalancingResult, text: Mapping[str, str] | None = None,
           field: float = POLYGON_FIELD_MM) -> list[Layer]:
    """The layers of the balancing drawing in paper millimetres (y up): the polygons left to right, each at the
    standard scale that draws it within ``field`` mm, captions under, the title over them broken to their width."""
    words = {**strings("en"), **(text or {})}
    layers: list[Layer] = []
    cursor = 0.0
    # A plane the scene places (two planes, or one at planes = [z]) is captioned with its z; a disc's is its masses'.
    placed = bool(result.spec.planes)
    # None but for a one-plane balancing, whose only plane says it under its caption.
    couple = static_couple(result)
    last = len(result.planes) - 1
    laid = [laid_off(plane, field) for plane in result.planes]
    panels = [_polygon(plane, _scale(plane, field), words, placed, couple if k == last else None)
              for k, plane in enumerate(laid)]
    height = max(y1 - y0 for _, _, (_, y0, _, y1), _ in panels)
    for key, drawing, (x0, y0, x1, y1), caption in panels:
        # Broken as a force polygon's caption is: a long equation of many named masses set no wider than the
        # polygon or a caption's least width, so that one line does not widen the drawing past its sheet.
        lines = caption_lines(caption, max(x1 - x0, CAPTION_WIDTH_MM), CAPTION_SIZE)
        width = max(x1 - x0, *(text_width(line, CAPTION_SIZE, weight) for line, weight in lines))
        layers.extend(moved_layers(drawing, cursor + (width - (x1 - x0)) / 2 - x0, -height / 2 - (y0 + y1) / 2))
        middle = cursor + width / 2
        layers.append(Layer(f"{key}-caption", tuple(
            Text((middle, -height - CAPTION_GAP_MM - k * CAPTION_LINE * CAPTION_SIZE), line, CAPTION_SIZE, "middle",
                 weight=weight)
            for k, (line, weight) in enumerate(lines))))
        cursor += width + GAP_MM
    left, _, _, top = bounds_of(item for layer in layers for item in layer.items)
    size, title = _title(words["bal_title"].format(count=Count(len(result.planes))), cursor - GAP_MM)
    layers.append(Layer(TITLE_LAYER, tuple(
        Text((left, top + TITLE_GAP_MM + (len(title) - 1 - k) * CAPTION_LINE * size), line, size, "start",
             weight="bold")
        for k, line in enumerate(title))))
    return layers


def _title(title: str, width: float) -> tuple[float, list[str]]:
    """The title's lettering size and its lines, broken to the polygons' width (to no less than a caption's): at
    the title's size where that takes at most :data:`MOST_TITLE_LINES` lines, else at the captions' size.

    One polygon is narrower than the title at a title's size; broken into three or four lines it stood over the
    polygon as a paragraph, and left whole it made the drawing two and a half times as wide as the polygon."""
    reach = max(width, CAPTION_WIDTH_MM)
    for size in (TITLE_SIZE, CAPTION_SIZE):
        lines = fitted(title, reach, size, "bold")
        if len(lines) <= MOST_TITLE_LINES:
            break
    return size, lines


def larger_layouts(result: BalancingResult, text: Mapping[str, str] | None = None) -> list[list[Layer]]:
    """:func:`layout` with the polygons drawn within each of :data:`LARGER_FIELDS_MM`, for a sheet with room."""
    return [layout(result, text, field) for field in LARGER_FIELDS_MM]


def balancing_svg(result: BalancingResult, text: Mapping[str, str] | None = None) -> str:
    """The balancing polygons of ``result`` as SVG text."""
    return to_svg(layout(result, text))


def plane_scale(plane: CorrectionPlane) -> float:
    """μ (kg·m/mm): the standard scale at which the plane's polygon, as it is laid off (:func:`laid_off`), fits
    :data:`POLYGON_FIELD_MM`."""
    return _scale(laid_off(plane))


def _scale(plane: CorrectionPlane, field: float = POLYGON_FIELD_MM) -> float:
    """μ (kg·m/mm) of ``plane``'s polygon in the order its vectors stand in, drawn within ``field`` mm."""
    extent = _extent(plane)
    return standard_scale(extent / field) if extent > 0 else 1.0


# Remembered: the sheets and the drawing's own file lay out the same planes, and the scale asks for them again.
@lru_cache(maxsize=64)
def laid_off(plane: CorrectionPlane, field: float = POLYGON_FIELD_MM) -> CorrectionPlane:
    """``plane`` with its shares in the order the drawing lays them off: the masses' order where that draws every
    vector in its place in the chain, else the first order (of :data:`MOST_ORDERS`) that draws fewest apart, and of
    those the one whose corners open widest; its equation written in that order.

    The rotor starter's plane L laid (m3r3)L, 6.7 mm long, back along (m2r2)L: drawn beside the chain with dashed
    leaders to keep its arrowhead off the other's, the polygon read as open.  Laid off before (m1r1)L it closes
    with every side in its place, as a student may lay the shares in any order.  ``field``: as the polygon is drawn
    (:func:`layout`), for what stands apart depends on the millimetres it is drawn in."""
    scale = _scale(plane, field)

    def mm(value: complex) -> complex:
        return value / scale

    masses = [k for k, vector in enumerate(plane.vectors) if vector.role == "mass"]
    if _drawn_apart(plane, mm) == 0:
        return plane
    best: tuple[tuple[int, float], CorrectionPlane] | None = None
    for order in _orders(plane, masses, mm):
        candidate = _reordered(plane, order)
        score = (_drawn_apart(candidate, mm), -_narrowest_corner(candidate, mm))
        if best is None or score < best[0]:
            best = (score, candidate)
    return plane if best is None else best[1]


def _orders(plane: CorrectionPlane, masses: Sequence[int], mm) -> Iterator[tuple[int, ...]]:
    """The orders of the shares (their indices among ``plane``'s vectors), the masses' own first, then as
    permutations go, leaving out every order with a share folded back onto the one before it (:func:`_folds`) but
    the masses' own, at most :data:`MOST_ORDERS` of them, found in :data:`MOST_STEPS` steps."""
    yield tuple(masses)
    drawn = {k: mm(plane.vectors[k].vector) for k in masses}
    count, steps = 1, 0

    def extend(order: list[int], before: complex | None) -> Iterator[tuple[int, ...]]:
        nonlocal count, steps
        if len(order) == len(masses):
            count += 1
            yield tuple(order)
            return
        for k in masses:
            steps += 1
            if count >= MOST_ORDERS or steps >= MOST_STEPS:
                return
            if k in order:
                continue
            side = drawn[k]
            shown = abs(side) >= ZERO_MM
            if shown and before is not None and _folds(before, side):
                continue
            order.append(k)
            yield from extend(order, side if shown else before)
            order.pop()

    for order in extend([], None):
        if order != tuple(masses):
            yield order


def _reordered(plane: CorrectionPlane, order: Sequence[int]) -> CorrectionPlane:
    """``plane`` with its shares laid off head to tail from its pole in ``order``, the correction closing them as
    before, and the equation written in that order (a mass with no share in the plane left out, as it is)."""
    tip = plane.vectors[0].start
    vectors = []
    for k in order:
        share = plane.vectors[k]
        vectors.append(PolygonVector(share.name, tip, tip + share.vector, share.role))
        tip += share.vector
    correction = plane.vectors[-1]
    terms = [plane.vectors[k].name for k in order if plane.factors[k] != 0.0]
    return replace(plane, vectors=(*vectors, correction), equation=" + ".join([*terms, correction.name]) + " = 0")


def _drawn_apart(plane: CorrectionPlane, mm) -> int:
    """How many of ``plane``'s vectors are drawn beside their places in the chain: shares folded back, and the
    correction where it lies along the masses."""
    folded = _folded_back(plane, mm)
    return len(folded) + bool(_beside(plane, mm, folded))


def _narrowest_corner(plane: CorrectionPlane, mm) -> float:
    """The smallest angle (rad) between two sides the polygon draws one after the other, the correction back to
    the first share included: 0 where a side runs back along the one before it."""
    sides = [mm(vector.vector) for vector in plane.vectors if abs(mm(vector.vector)) >= ZERO_MM]
    if len(sides) < 2:
        return math.pi
    return min(abs(math.atan2((after / -before).imag, (after / -before).real))
               for before, after in zip(sides, sides[1:] + sides[:1]))


def _extent(plane: CorrectionPlane) -> float:
    """The polygon's width or height, the larger (kg·m): 0 where every mass turns on the axis."""
    xs = [vertex.real for vertex in plane.vertices]
    ys = [vertex.imag for vertex in plane.vertices]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def _polygon(plane: CorrectionPlane, scale: float, text: Mapping[str, str], placed: bool, couple: float | None = None
             ) -> tuple[str, list[Layer], tuple[float, float, float, float], tuple[str, ...]]:
    """One plane's polygon at μ: its key, its layers, their bounds (mm) and its caption lines (with its z where the
    scene ``placed`` it, and last the ``couple`` Σ m·r·z a one-plane balancing leaves, kg·m², where given)."""
    key = f"plane-{plane.name}"

    def mm(value: complex) -> complex:
        return value / scale

    folded = _folded_back(plane, mm)
    beside = _beside(plane, mm, folded)
    # What stands apart from its place in the chain, and what it would cover there: the caption says why, or the
    # polygon, a vector joined to it by dashed lines, reads as open.
    apart = [(plane.vectors[index].name, [_drawn_before(plane, mm, index)]) for index in sorted(folded)]
    if beside:
        apart.append((plane.vectors[-1].name, [plane.vectors[k].name for k in _under_correction(plane, mm)]))
    arrows: list[Primitive] = []
    named: list[tuple[str, Arrow]] = []
    leaders: list[Primitive] = []
    for index, vector in enumerate(plane.vectors):
        if abs(mm(vector.vector)) < ZERO_MM:
            continue
        shift = beside if vector.role == "correction" else folded.get(index, 0j)
        stroke = _CORRECTION if vector.role == "correction" else _SHARE
        arrow = Arrow(_xy(mm(vector.start) + shift), _xy(mm(vector.end) + shift), stroke,
                      3.5 if vector.role == "correction" else 3.0, f"{key}-{_id(vector.name)}")
        arrows.append(arrow)
        named.append((vector.name, arrow))
        if shift:
            leaders += [Polyline((_xy(end), _xy(end + shift)), _LEADER if vector.role == "correction" else _SHARE_LEADER)
                        for end in (mm(vector.start), mm(vector.end))]
    # A polygon of nothing but its pole (every mass on the axis) is no drawing: a lone dot, at a scale of nothing.
    empty = _extent(plane) == 0
    pole = [] if empty else [dot_marker(_xy(mm(plane.vertices[0])), 0.7)]
    middle = sum((mm(vertex) for vertex in plane.vertices[:-1]), 0j) / max(len(plane.vertices) - 1, 1)
    anchors = []
    for name, arrow in named:
        centre = (_c(arrow.start) + _c(arrow.end)) / 2
        across = 1j * (_c(arrow.end) - _c(arrow.start))
        if ((centre - middle) * across.conjugate()).real < 0:
            across = -across
        anchors.append(Anchor(_xy(centre), name, NAME_SIZE, math.atan2(across.imag, across.real),
                              arrow.stroke.colour))
    ends = (mm(plane.vectors[-1].start) + beside, mm(plane.vectors[-1].end) + beside)
    radii = ANGLE_RADII_MM if plane.angle_deg is not None else ANGLE_RADII_MM[:1]
    angle_marks, labels = min((_marked(plane, ends, at, radius, anchors, arrows, leaders + pole)
                               for at in ends for radius in radii), key=lambda tried: tried[0])[1:]
    layers = [Layer(f"{key}-reference", tuple(angle_marks + leaders)), Layer(f"{key}-vectors", tuple(arrows + pole)),
              Layer(f"{key}-leaders", labels.leaders), Layer(f"{key}-labels", labels.texts)]
    extent = bounds_of(item for layer in layers for item in layer.items)
    return key, layers, extent, _caption(plane, None if empty else scale, text, placed, couple, apart)


def _drawn_before(plane: CorrectionPlane, mm, index: int) -> str:
    """The name of the share drawn last before the vector at ``index`` (too short ones are not drawn)."""
    return next(vector.name for vector in reversed(plane.vectors[:index]) if abs(mm(vector.vector)) >= ZERO_MM)


def _beside(plane: CorrectionPlane, mm, folded: dict[int, complex] | None = None) -> complex:
    """Where the correction is drawn from where it closes the polygon (mm): 0, or :data:`BESIDE_MM` across it, away
    from the chain's corners, where a mass vector lies along it."""
    tail, head = mm(plane.vectors[-1].start), mm(plane.vectors[-1].end)
    length = abs(head - tail)
    if length < ZERO_MM:
        return 0j
    along = (head - tail) / length

    def local(point: complex) -> complex:  # along the correction from its tail, and across it
        return (point - tail) / along

    if not _under_correction(plane, mm):
        return 0j
    # Away from the chain's corners that stand off the line; to the right of the correction where none does.
    offside = sum(local(mm(vertex)).imag for vertex in plane.vertices)
    side = along * 1j * (BESIDE_MM if offside < -ALONG_MM else -BESIDE_MM)
    # A share along the correction set beside the chain already (``folded``, :func:`_folded_back`) stands on that
    # side: the correction goes to the other, not onto it.
    for index, shift in (folded or {}).items():
        share = mm(plane.vectors[index].vector)
        if (shift / side).real > 0 and abs((share / along).imag) < abs(share) * math.sin(math.radians(HIDDEN_DEG)):
            return -side
    return side


def _under_correction(plane: CorrectionPlane, mm) -> list[int]:
    """The indices of the shares the correction would hide where it closes the polygon: those that run along it,
    within :data:`ALONG_MM` over a common stretch longer than that, or half or more of whose length runs that close
    (:func:`_hidden_share`)."""
    tail, head = mm(plane.vectors[-1].start), mm(plane.vectors[-1].end)
    length = abs(head - tail)
    if length < ZERO_MM:
        return []
    along = (head - tail) / length
    hidden = []
    for index, vector in enumerate(plane.vectors[:-1]):
        start, end = (mm(vector.start) - tail) / along, (mm(vector.end) - tail) / along
        common = min(max(start.real, end.real), length) - max(min(start.real, end.real), 0.0)
        if ((abs(start.imag) < ALONG_MM and abs(end.imag) < ALONG_MM and common > ALONG_MM)
                or _hidden_share(start, end, length) >= 0.5):
            hidden.append(index)
    return hidden


def _hidden_share(start: complex, end: complex, length: float) -> float:
    """The share of a mass vector's length (0 to 1) that runs within :data:`ALONG_MM` of a correction lying from 0 to
    ``length`` along the real axis, ``start`` and ``end`` its ends in that frame; 0 for one crossing it steeper than
    :data:`HIDDEN_DEG` or whose stretch there is no longer than :data:`ALONG_MM`."""
    side = end - start
    span = abs(side)
    if span == 0 or abs(side.imag) > span * math.sin(math.radians(HIDDEN_DEG)):
        return 0.0
    # The stretch of the vector, start + t·side with t in [0, 1], inside the band across and the correction along.
    low, high = 0.0, 1.0
    for offset, rate, bound in ((start.imag, side.imag, ALONG_MM), (start.real - length / 2, side.real, length / 2)):
        if rate == 0:
            if abs(offset) >= bound:
                return 0.0
            continue
        enter, leave = sorted(((-bound - offset) / rate, (bound - offset) / rate))
        low, high = max(low, enter), min(high, leave)
    share = max(0.0, high - low)
    return share if share * span > ALONG_MM else 0.0


def _folded_back(plane: CorrectionPlane, mm) -> dict[int, complex]:
    """Where each share that turns back onto the share before it (within :data:`FOLDED_BACK_DEG` of straight back,
    its end within :data:`FOLDED_ONTO_MM` of it) is drawn from where it lies (mm), by its index among the plane's
    vectors: :data:`BESIDE_MM` across the share before, to the side its own end already leans to (where it lies on
    that share's line, away from the chain's other corners)."""
    shifts: dict[int, complex] = {}
    before: complex | None = None
    corners = [mm(vertex) for vertex in plane.vertices]
    for index, vector in enumerate(plane.vectors):
        if vector.role != "mass" or abs(mm(vector.vector)) < ZERO_MM:
            continue
        side = mm(vector.vector)
        if before is not None and _folds(before, side):
            back = -before / abs(before)
            across = (side / back).imag
            if abs(across) < ALONG_MM:
                start = mm(vector.start)
                across = -sum(((corner - start) / back).imag for corner in corners)
            shifts[index] = back * 1j * math.copysign(BESIDE_MM, across if across else -1.0)
        before = side
    return shifts


def _folds(before: complex, side: complex) -> bool:
    """Whether a share ``side`` (mm) laid off after ``before`` turns back onto it: within :data:`FOLDED_BACK_DEG` of
    straight back, its end within :data:`FOLDED_ONTO_MM` of ``before``, or running back past ``before``'s start
    that close to it."""
    back = -before / abs(before)
    turned = side / back  # the share in the frame of the one before, turned back: 0° is straight back
    # How far its end stands from the share before, which runs from 0 to |before| along ``back`` here.
    reach = min(max(turned.real, 0.0), abs(before))
    onto = abs(turned - reach)
    # A longer one running back past the share before's start covers it whole: how far that start stands from it.
    along = min(max((abs(before) * turned.conjugate()).real / abs(turned) ** 2, 0.0), 1.0)
    over = abs(abs(before) - along * turned)
    return abs(math.degrees(math.atan2(turned.imag, turned.real))) < FOLDED_BACK_DEG and min(onto, over) < FOLDED_ONTO_MM


def _marked(plane: CorrectionPlane, ends: tuple[complex, complex], at: complex, radius: float,
            anchors: list[Anchor], arrows: list[Arrow], drawn: list[Primitive]
            ) -> tuple[tuple[int, int], list[Primitive], Placement]:
    """The correction's angle marked at ``at``, one of its ``ends`` (tail, head), at ``radius``, and the labels placed
    round it; first what that costs: the sides the arc crosses, then the names sent out on leaders.  Marked at the
    tail alone, the rotor starter's plane L's x-direction ran over the spot beside the short (m3r3)L ending there,
    whose name was led off under it, between the x-direction and (m1r1)L's arrowhead."""
    marks = _angle_marks(plane, ends, at, radius)
    named = list(anchors)
    if marks and plane.angle_deg is not None:
        half = math.radians(plane.angle_deg) / 2
        spot = at + (radius + 1.0) * complex(math.cos(half), math.sin(half))
        named.append(Anchor(_xy(spot), f"θ{plane.name}", ANGLE_NAME_SIZE, half, _ANGLE.colour))
    labels = _lettered(named, [*arrows, *drawn, *marks], [*marks, *arrows])
    # The arc ends on the correction at its tail, as it must: only elsewhere does the correction count as crossed.
    sides = [arrow for arrow in arrows if arrow.stroke != _CORRECTION or at != ends[0]]
    return (_crossings(plane, at, radius, sides + drawn), len(labels.leaders)), marks, labels


def _crossings(plane: CorrectionPlane, at: complex, radius: float, drawn: Sequence[Primitive]) -> int:
    """How many of the lines ``drawn`` the correction's angle arc about ``at`` at ``radius`` crosses: at 7 mm about
    the tail the arc ran through a share passing near it."""
    if plane.angle_deg is None:
        return 0
    arc = LineString(arc_points(_xy(at), radius, 0.0, math.radians(plane.angle_deg)))
    return sum(arc.intersects(line) for line in obstacles_of(drawn))


def _angle_marks(plane: CorrectionPlane, ends: tuple[complex, complex], at: complex, radius: float
                 ) -> list[Primitive]:
    """The dashed x-direction at ``at``, the correction's tail or head (its ``ends``), and the arc from it ccw to the
    correction, or at its head to the correction's line run on past it, dashed as the x-direction is: a line makes
    one angle with the x-direction at each of its points."""
    tail, head = ends
    if plane.angle_deg is None or abs(head - tail) < ZERO_MM:
        return []
    marks: list[Primitive] = [Polyline((_xy(at), _xy(at + REFERENCE_MM)), _REFERENCE)]
    if at != tail:
        along = (head - tail) / abs(head - tail)
        marks.append(Polyline((_xy(at), _xy(at + (radius + _RUN_ON_PAST_MM) * along)), _REFERENCE))
    sweep = math.radians(plane.angle_deg)
    if sweep > math.radians(2.0):
        marks.extend(curved_arrow(_xy(at), radius, 0.0, sweep, _ANGLE, head=2.0))
    return marks


# How far the correction's line, run on past its head to where its angle is marked, reaches past the arc (mm).
_RUN_ON_PAST_MM = 3.0


def _caption(plane: CorrectionPlane, scale: float | None, text: Mapping[str, str], placed: bool,
             couple: float | None = None, apart: Sequence[tuple[str, Sequence[str]]] = ()) -> tuple[str, ...]:
    """The plane's caption lines; ``scale`` None for a polygon with nothing drawn, which has none; for each vector
    drawn ``apart`` from its place, why, with what it would cover there; the ``couple`` a one-plane balancing leaves
    last, where given."""
    title = (text["bal_plane"].format(name=plane.name, position=_given(plane.position))
             if placed else text["bal_disc"].format(name=plane.name))
    lines = [title, *([] if scale is None else [text["bal_scale"].format(value=format_scale(scale))]), plane.equation,
             *_too_short(plane, scale, text),
             *(text["bal_drawn_apart"].format(vector=vector, covered=", ".join(covered), offset=_given(BESIDE_MM))
               for vector, covered in apart),
             text["bal_correction"].format(vector=plane.vectors[-1].name, name=plane.name,
                                           value=significant(plane.mass_radius), angle=_angle(plane.angle_deg))]
    if plane.mass is not None and plane.radius is not None:
        lines.append(text["bal_mass"].format(name=plane.name, mass=significant(plane.mass),
                                                   radius=_given(plane.radius)))
    if couple is not None:
        # One plane balances the masses' forces, not their moments about it: the couple left was told in a warning
        # and the note alone, and the drawing, its polygon closed, read as a rotor balanced.
        lines.append(text["bal_couple_left"].format(value=significant(couple)))
    return tuple(lines)


def _too_short(plane: CorrectionPlane, scale: float | None, text: Mapping[str, str]) -> list[str]:
    """A caption line naming the masses' shares too short to draw at the plane's μ, with their values, as a plan
    sheet names its short vectors: a mass far from this plane (m5 at z = 0.20 m, 0.02 m from plane R's 0.22 m, is
    all but nothing in plane L) stood in the polygon's equation and nowhere in the polygon."""
    if scale is None:
        return []
    short = [vector for vector in plane.vectors
             if vector.role == "mass" and 1e-9 < abs(vector.vector) / scale < ZERO_MM]
    return too_short_lines([text["bal_share_value"].format(vector=vector.name, value=significant(abs(vector.vector), 3))
                            for vector in short], text, CAPTION_WIDTH_MM)


def _lettered(anchors: Sequence[Anchor], figure: Sequence[Primitive], heavy: Sequence[Primitive]) -> Placement:
    """The labels placed clear of the figure and of every anchor's own spot.

    The ``heavy`` marks (the vectors, the correction's angle's arc and x-direction) count as areas, as heavy as a
    point: a polygon has few lines and room beside them, and a short vector's name by the correction's tail read as
    if it were written on them (plane L of the rotor starter).  Where no spot near a long name is clear of them, it
    stands farther out on a leader (``off_lines``) rather than on a line."""
    spots = [ShapelyPoint(anchor.at).buffer(0.8) for anchor in anchors]
    marks = [shape.buffer(0.4) for shape in obstacles_of(heavy)]
    return remembered(place_labels, anchors, obstacles_of(figure) + spots + marks, off_lines=True)


def _angle(angle_deg: float | None) -> str:
    """A correction's angle θ as the caption writes it: to a tenth of a degree, or "—" where there is no correction
    to have one."""
    return "—" if angle_deg is None else f"{angle_in_turn(angle_deg)}°"


def _given(value: float) -> str:
    """A value the scene gave, as short as it was written: 0.04, not 0.04000; a true minus sign."""
    return f"{value:.10g}".replace("-", "−")


def _id(name: str) -> str:
    """A vector's name as an svg id: a share (m1r1)L as m1r1L, other signs as _."""
    return "".join(c if c.isalnum() else "_" for c in name if c not in "()")



__all__ = ["balancing_svg", "layout", "plane_scale"]
