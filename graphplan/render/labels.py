"""Placing labels where they cover nothing: the cheapest spot around each anchor.

A label is tried at sixteen spots on each of a few rings around its point,
nearest first in the preferred direction; a spot costs for what the label's
box would cover (the drawn lines, the boxes of labels already placed) and
for standing nearer another point than its own.  Where nothing beside the
point is free the label is set apart on a thin leader line.  A label left
on a line once all stand tries finer spots, and a neighbour's; one still on
it reaches farther, for a spot clear of everything, moving a few neighbours
if it must, and farther out on its leader where that fails.  Shapely does
the intersection tests.
"""

from __future__ import annotations

import functools
import hashlib
import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from ..memo import RecentMemo
from . import lettering
from .primitives import (
    Arrow,
    Circle,
    Polyline,
    Primitive,
    Stroke,
    Text,
    text_extent,
    text_width,
)

# The least space between two labels (mm).
LABEL_SPACING = 0.8


@dataclass(frozen=True)
class Anchor:
    """A label to place: its text, the point it names, the direction it prefers (radians)."""

    at: tuple[float, float]
    text: str
    size: float = lettering.LETTER
    prefer: float = math.pi / 4
    colour: str = "black"
    # The ends of the line the label names (an arm), beside any point of which it reads as naming it: a label left
    # on a line beside ``at`` may slide along it to a clear stretch.  None: the label names the point ``at``.
    along: tuple[tuple[float, float], tuple[float, float]] | None = None
    # A point and a distance (mm) the label's box keeps beyond wherever that costs less than lines covered
    # (``KEPT_OFF``): a lever's pole, in whose reach an arm's name is read among the loads' names there.  None: none.
    keep_off: tuple[tuple[float, float], float] | None = None
    # Which of ``place_labels``' shafts (their indices among its obstacles) are lines of the link the point lies on: a
    # leader across one still names a point of that link, crossing it as an ordinary line (a centre of mass inside a
    # triangular link, lettered outside it).
    own_lines: tuple[int, ...] = ()
    # How far the symbol drawn round the point reaches from it across its narrower side (mm): a slider block's half
    # height and half its outline's stroke.  Its spots stand that much farther out, a label beside them read as
    # naming the point without a leader, as a draughtsman letters a block's pin beside the block: the rings from the
    # pin itself left it no spot clear of the block's ink but on a leader out of the block.
    symbol_mm: float = 0.0


def text_box(text: Text) -> BaseGeometry:
    """The box a text covers on the paper (:func:`~graphplan.render.primitives.text_extent`)."""
    # shapely.box, the same polygon as shapely.geometry.box's, made in C: a sheet makes a box for every text and
    # label placed, and the Python-level polygon took six times as long.
    return shapely.box(*text_extent(text))


def obstacles_of(items: Sequence[Primitive]) -> list[BaseGeometry]:
    """The shapes of drawn primitives that a label must not cover."""
    return obstacles_and_shafts(items)[0]


def ink_of(items: Sequence[Primitive], shafts_inked: bool = False) -> list[BaseGeometry]:
    """:func:`obstacles_of`'s shapes with each line as wide as its stroke draws it, and a filled shape grown by half its
    outline's stroke: for what is set clear of a few bold lines (a position's number round the crank's circle, the
    plan of positions' letters), where their middles alone let a number touch a 1 mm link's ink, and the outline of
    a 0.7 mm slider block drawn round a pin left a letter beside the pin 0.15 mm into its ink.  ``shafts_inked``: the
    arrows' shafts too (:func:`obstacles_and_shafts`), for the plans' vectors and the senses' arrows."""
    return obstacles_and_shafts(items, shafts_inked, lines_inked=True)[0]


def obstacles_and_shafts(items: Sequence[Primitive], shafts_inked: bool = False,
                         lines_inked: bool = False) -> tuple[list[BaseGeometry], list[bool]]:
    """:func:`obstacles_of`'s shapes of ``items`` and, shape by shape, whether it is an arrow's shaft (``place_labels``'
    ``shafts``): one pass, so that the two lists keep one order.  ``shafts_inked``: each arrow's shaft as wide as its
    stroke draws it, not its middle alone; ``lines_inked``: each line and filled shape so (:func:`ink_of`)."""
    # Made by shapely's functions, the same shapes as its classes make, in C, and each kind of shape for all the items
    # in one call: a sheet's drawings have a thousand, and a call an item took longer than the shapes' making.
    kinds: list[tuple[str, int]] = []  # each shape's kind and its number among the shapes of that kind
    made: dict[str, list] = {"line": [], "polygon": [], "circle": [], "box": []}
    shafts: list[bool] = []
    # Each shape's stroke, halved, where it is grown to its ink: nought for any other shape.
    half_widths: list[float] = []

    def add(kind: str, what, shaft: bool = False, inked_width: float = 0.0) -> None:
        kinds.append((kind, len(made[kind])))
        made[kind].append(what)
        shafts.append(shaft)
        half_widths.append(inked_width / 2)

    for item in items:
        line_width = item.stroke.width if lines_inked and isinstance(item, Polyline) else 0.0
        if isinstance(item, Polyline) and item.closed and item.fill and len(item.points) >= 3:
            # A filled shape (a slider block, a pivot's triangle) hides what is written inside it.
            add("polygon", item.points, inked_width=line_width)
        elif isinstance(item, Polyline) and len(item.points) >= 2:
            add("line", item.points + ((item.points[0],) if item.closed else ()), inked_width=line_width)
        elif isinstance(item, Arrow):
            add("line", (item.start, item.end), shaft=True, inked_width=item.stroke.width if shafts_inked else 0.0)
            add("polygon", item.tip().points)
        elif isinstance(item, Circle):
            add("circle", item)
        elif isinstance(item, Text):
            add("box", text_extent(item))
    shapes = {kind: _shapes(kind, given) for kind, given in made.items() if given}
    found = [shapes[kind][number] for kind, number in kinds]
    if wide := [index for index, half in enumerate(half_widths) if half > 0]:
        grown = shapely.buffer(np.array([found[index] for index in wide], dtype=object),
                               [half_widths[index] for index in wide])
        for index, shape in zip(wide, grown, strict=True):
            found[index] = shape
    return found, shafts


def _shapes(kind: str, given: list) -> np.ndarray:
    """:func:`obstacles_of`'s shapes of one ``kind``, each of its ``given`` (points, a circle, a text's extent)."""
    if kind == "circle":
        # Sixteen segments a quarter, as the geometry's buffer method draws it (the function's default is 8).
        return shapely.buffer(shapely.points([circle.centre for circle in given]),
                              [circle.radius for circle in given], quad_segs=16)
    if kind == "box":
        return shapely.box(*np.array(given, dtype=float).T)
    # A line or a ring of each item's points, told apart by their indices.
    points = np.array([point for each in given for point in each], dtype=float)
    indices = np.repeat(np.arange(len(given)), [len(each) for each in given])
    if kind == "line":
        return shapely.linestrings(points, indices=indices)
    return shapely.polygons(shapely.linearrings(points, indices=indices))


@dataclass(frozen=True)
class Placement:
    """Placed labels: a text for each anchor, in the anchors' order, and the leader lines of those set apart."""

    texts: tuple[Text, ...]
    leaders: tuple[Polyline, ...] = ()
    # Whether some label found no spot clear of the others round its point after every mend, and was moved off the
    # one it covered onto lines or a leader at the last: the drawing is too small for its names to stand apart.
    crowded: bool = False


class _Spots(NamedTuple):
    """The spots tried for one label (:func:`place_labels`' ``costed``): each spot's box, whether it stands beside
    its point, the indices of those led to it and their leaders, what each costs, what it covers of the drawing,
    and the part of its cost that is for covering another label or leader."""

    boxes: np.ndarray
    beside: np.ndarray
    led: np.ndarray
    leaders: np.ndarray
    cost: np.ndarray
    covering: np.ndarray
    clashing: np.ndarray


# What a spot costs: each drawn line it covers, HEAVY times as much for a point, an arrowhead or a
# text; each other labelled point it stands about as near to as to its own; each ring farther out.
COVER = 10.0
HEAVY = 3.0
# A thin leader crossing a drawn line hides less than a letter on it.
LEADER_CROSSING = 4.0
# A leader across a load's arrow (``place_labels``' ``shafts``) counts as crossing this many thin lines, costing as
# much as two leaders crossing (LEADERS_CROSSING, below): it reads as part of the arrow, or as pointing at that load,
# where it crosses a thin line plainly.  (As the head's three lines, four more lever names of the bench went under.)
SHAFT_CROSSED = 15.0
MISLEADING = 8.0
# "About as near": a label this much farther (mm) from another point than from its own still misleads.
MISLEADING_MARGIN = 0.8
RING = 2.5
# A label set well apart costs this much more, so that it goes there only when no nearer spot is clear.
SET_APART = 12.0
# Anchors with more neighbours within CROWD letter heights of them are lettered first.
CROWD = 4.0
LEADER_WIDTH = 0.18
# The rings of spots around a point, beyond the gap, in letter heights: beside it; near it, led to it
# by a leader line; and set apart, led to it.
BESIDE_SHARES = (0.0, 0.5)
LED_SHARES = (1.1, 1.8)
APART_SHARES = (3.2, 4.8)
# Farther still, tried only where every spot on those rings covers another label or a leader.
FAR_SHARES = (6.6, 8.6, 11.0)
# The rings whose spots a label is costed on first: those beside the point.  The spots farther out, a spot on ring r
# costing RING × r and more, are costed only when none of these costs less (nought: all are costed at once).
FIRST_RINGS = len(BESIDE_SHARES)
# Whether the first rings of all the labels of a drawing are costed on the drawing together, before any is placed: the
# same numbers as each label's own costing gives, in a few array operations and one query of the tree for them all,
# where each label took some thirty operations of its own (a run places a few hundred labels).
FIRST_RINGS_TOGETHER = True
# What covering another label or leader costs: more than any spot that covers only drawn lines.
OVERLAP = 1000.0
LEADERS_CROSSING = 60.0
# How many times the labels that cover another are placed again among all the rest.
REPAIR_ROUNDS = 2
# What covering a drawn line costs where the labels keep off the lines (``off_lines``): more than any clear spot,
# less than covering another label.
LINE_COVERED = OVERLAP / 2
# The rings of the finer spots tried for a label left on a line (in twice the directions): a ring between the two
# beside the point, and those beside it and led to it.
FINE_SHARES = (0.0, 0.25, 0.5, 1.1, 1.8)
# A leader with more than this of its length (mm) within ALONG_WIDTH of a drawn line runs along it, reading as part
# of it: a neighbour is not moved to such a spot.
ALONG = 1.0
ALONG_WIDTH = 0.25
# A leader running beside a drawn line, nearly along it, reads as part of it too (a hatch stroke's twin, the slider
# driven mechanism's G led down beside its guide's hatching): where the caller asks (``place_labels``' leaders_apart),
# one with more than ALONG of its length nearer than ISO 128-20's least space between parallel lines, 0.7 mm, to a
# line's ink (an inked obstacle's edge, else a line's middle), within BESIDE_ANGLE of its direction, counts as a
# line covered.
BESIDE_SPACE = 0.7
BESIDE_ANGLE = math.radians(20.0)
# How many cheaper spots a label left on a line looks at, and how many of those it tries, each by moving the one
# neighbour that stands there (a spot two labels stand on is passed over).
SPOTS_LOOKED_AT = 12
MOVES_TRIED = 2
# A leader starts this far from its point (mm), clear of the point's dot.
LEADER_CLEARANCE = 0.9
# And stops this far short of its label's box (mm), a gap before the letters.
LEADER_GAP = 0.3
# What standing within an anchor's ``keep_off`` costs: as much as covering three lines, so that a label steps out of
# it onto a line sooner (to reach out from there, below) and stands there only where that is crowded, not set well
# apart among the labels round it (a lever's arms, so set, left the loads' names round the pole no room).
KEPT_OFF = 3 * COVER
# A label still on a line once all stand reaches out to a spot whose box covers nothing, if one is within reach: on a
# short leader from its point, at these rings (letter heights beyond the gap, the last as far as the nearer ring set
# apart), in twice the directions; or, naming a line (``Anchor.along``), beside another point of it, these points
# SLIDE_STEP letter heights apart, as far as SLIDE either way.  Beside its line it reads as naming it without a
# leader: a step along it costs SLIDE_COST.
REACH_SHARES = (1.1, 1.8, 2.5, 3.2)
# A label on a line even so, every clear spot within that reach held by neighbours that cannot all stand clear
# elsewhere (n6″ where a triad's plan crowds n3, n6 and σ6 at the end of its rays), reaches out farther on its leader,
# ring by ring, as far as the farthest ring tried for a label that covers another (``place_labels``' reach_farther); a
# label naming a line led from any point of it beside which it may stand (a load's name from its arrow's shaft).
FARTHER_SHARES = (4.0, 4.8, 5.7, 6.6, 8.6, 11.0)
# Led from another point of its line, a label is tried on the short leaders first, as from its own point: the slider
# driven mechanism's sliver of a polygon at position 3 had R43 clear on a 2 mm leader from a stretch of its side
# farther along, and, never tried there, led it across R14's and R14τ's arrows.
FROM_LINE_SHARES = (*REACH_SHARES, *FARTHER_SHARES)
SLIDE_STEP = 1.5
SLIDE = 9.0
SLIDE_COST = 1.5
# How many neighbours a label left on a line may move to stand clear (``make_room``), and at how many of its
# cheapest spots it tries.
ROOM_MADE = 3
ROOM_TRIES = 4
# How many of the cheapest clear spots are tried for one whose leader runs along no line (and, of those one neighbour
# stands on, for one the neighbour gives up).
REACH_TRIES = 8


# The clearance (mm) between a label's box and its point where nothing else asks for another.
LABEL_GAP_MM = 1.2


def place_labels(anchors: Sequence[Anchor], obstacles: Sequence[BaseGeometry], gap: float = LABEL_GAP_MM,
                 standing: Sequence[Text] = (), off_lines: bool = False,
                 reach_farther: bool | Sequence[bool] = True, shafts: Sequence[bool] = (),
                 leaders_apart: bool | Sequence[BaseGeometry] = False) -> Placement:
    """Texts for ``anchors``, each at the cheapest spot around its point, and the leader lines of those led to it.

    Another label or leader is never covered when any spot avoids it.  A
    spot costs for every drawn shape it covers (a point, an arrowhead or a
    text three times a line), for every other labelled point it stands
    about as near to as to its own, and for its distance from the point.
    Beyond the spots beside the point a thin leader line joins the label to
    its point, as a draughtsman letters a crowded corner of a plan: a clear
    spot a little way off is then taken before a letter is written over a
    line, and one set well apart only when nothing nearer is clear.  The
    most crowded points are lettered first, while there is still room
    around them; ties go to the preferred direction.  Where every spot
    near a point covers another label, rings farther out are tried; and a
    label that still had to cover another is placed again once all stand,
    after the one it covers, which may now find a clear spot elsewhere.
    Then each label left covering a line (or a point, or a text) looks
    for a spot that covers less at a lower cost: among finer spots round
    its point (between two directions, where lines meeting at the point
    leave room), or where a single neighbour stands that can move without
    covering more or taking a leader it had not.  A label still covering
    a line, or another label, then takes the cheapest spot within reach that
    covers nothing at all, where the costs above had let it lie on one line
    sooner than lead it across two: beside another point of the arm it names
    (``Anchor.along``), on a short leader (twice the directions, as far as a
    spot set apart), or where a single neighbour stands that can itself
    stand as clear elsewhere.  One on a line even so, whose clear spots
    within reach a few neighbours hold (a crowd of names round a lever's
    pole, none of which can move alone), takes one and the neighbours are
    placed again round it, when fewer of them all then lie on lines.  One
    on a line after all that (every clear spot within reach held by
    neighbours that cannot all stand clear elsewhere) reaches farther out
    on its leader (``reach_farther``), as far as the rings tried for a
    label that would cover another, and one naming a line (a load's
    arrow) from any point of it, as a draughtsman leads a crowded
    arrow's name from its shaft: on a line its letters are misread, a
    leader across a few lines still leads to it.  A label keeps out of
    its anchor's ``keep_off`` wherever that costs less than three lines
    covered.

    ``standing`` are labels set already (the numbers round a crank's
    circle): the anchors' labels keep clear of them as of one another.

    ``reach_farther`` False leaves a label on a line where the caller has a
    way of its own for it: the plan of positions letters it beside its
    point and breaks the thin lines under it, and the lever names its
    arrow under the drawing.  Given anchor by anchor, it lets only some
    reach farther: a group cut free leads a load's name out from its
    arrow's shaft, but leaves an arm's name where it lies (led far out from
    a thin arm among the star of arms at a point it reads as naming
    another).

    ``shafts`` says which of the ``obstacles`` (the first ones, in their
    order; :func:`obstacles_and_shafts`) are arrows' shafts: a leader across one
    costs as much as two leaders crossing (:data:`SHAFT_CROSSED` lines),
    for a name led across a load's arrow reads as naming that load; such
    a spot counts as a line covered, and is reached out to only by a label
    whose name would lie on a line otherwise.  A mechanism's links are
    given so too (:func:`place_breaking_thin_lines`' ``links``): a letter
    led across a link reads as naming a point of it.

    ``leaders_apart`` counts a leader that runs beside a drawn line's ink,
    nearly along it, as a line covered (:data:`BESIDE_SPACE`): beside a
    hatch stroke it reads as one more (the plan of positions).  Given as
    shapes, beside those lines too, which the labels may cover (thin lines
    broken under them, but not under their leaders).

    ``off_lines`` keeps the labels off the drawn lines wherever any spot,
    farther out too, does, for a drawing of few lines with room round them
    (a balancing polygon): a long name on the middle of a side inside the
    polygon has no clear spot near it, and read crossed by its own vector;
    on a longer leader it stands clear.

    The spots of one anchor are costed at once by shapely's array
    functions: a sheet has a few hundred labels and ninety-six spots each.
    Those beside the point are costed first, and the rest only when one
    of them could cost less (:data:`FIRST_RINGS`): most labels stand beside
    their points.
    """
    fixed = list(obstacles)
    weights = np.array([HEAVY if shape.geom_type in ("Polygon", "MultiPolygon") else 1.0 for shape in fixed])
    # What each obstacle weighs crossed by a leader: as covered by a box, but an arrow's shaft SHAFT_CROSSED lines.
    shafts_met = np.flatnonzero(np.asarray(shafts, dtype=bool)[:len(fixed)])
    fixed_shafts = np.array([fixed[k] for k in shafts_met], dtype=object)
    crossed_weights = weights.copy()
    crossed_weights[shafts_met] = SHAFT_CROSSED
    pieces, owners = _pieces(fixed)
    tree = STRtree(pieces) if fixed else None
    edges, edge_directions = _edges([] if leaders_apart is False
                                    else [*fixed, *(() if leaders_apart is True else leaders_apart)])
    # Each edge's bounds, grown as far as a leader's middle runs beside it: those a leader's meet are measured.
    edge_reach = shapely.bounds(edges) + (BESIDE_SPACE + LEADER_WIDTH / 2) * np.array([-1.0, -1.0, 1.0, 1.0])
    edge_tree = STRtree(shapely.box(*edge_reach.T)) if len(edges) else None
    edge_ends = shapely.get_coordinates(edges).reshape(-1, 2, 2)
    shaft_tree = STRtree(fixed_shafts) if len(fixed_shafts) else None
    at = np.array([anchor.at for anchor in anchors], dtype=float).reshape(-1, 2)
    # Each placed label's box (kept apart by a little more than touching) and leader, by its anchor's index.
    placed_boxes: dict[int, BaseGeometry] = {}
    leader_lines: dict[int, BaseGeometry] = {}
    texts: dict[int, Text] = {}
    paid: dict[int, float] = {}
    # The labels standing already, under indices no anchor has.
    for number, text in enumerate(standing):
        placed_boxes[-1 - number] = spaced_box(text)

    def met(shapes: np.ndarray) -> np.ndarray:
        """Which drawn shapes each of ``shapes`` meets, as a table (a shape by an obstacle)."""
        table = np.zeros((len(shapes), len(fixed)), dtype=bool)
        if tree is None:
            return table
        # A shape covers a line once however many of its segments it covers: which shape meets which obstacle, as a
        # table (a few hundred spots by a few hundred obstacles), costs less than sorting the pairs to drop the
        # repeated ones.
        hit, piece = tree.query(shapes, predicate="intersects")
        table[hit, owners[piece]] = True
        return table

    def across_gap(table: np.ndarray, lines: np.ndarray, leaders_from: int) -> None:
        """Mark in ``table`` (:func:`met`'s, the leaders ``lines`` from row ``leaders_from``) the arrows' shafts each
        leader meets run on to its box (:func:`_to_the_box`), as well as those it meets as drawn."""
        if shaft_tree is None or not len(lines):
            return
        hit, shaft = shaft_tree.query(_to_the_box(lines), predicate="intersects")
        table[leaders_from + hit, shafts_met[shaft]] = True

    def others_shafts(index: int) -> np.ndarray:
        """Which of the shafts (``shafts_met``) a leader from the point of ``index`` reads as naming: all but the lines
        of its own link (``Anchor.own_lines``)."""
        # A mask of the obstacles, not np.isin, which imports numpy.ma to ask whether they are masked.
        own = np.zeros(len(fixed), dtype=bool)
        own[np.asarray(anchors[index].own_lines, dtype=int)] = True
        return ~own[shafts_met]

    def covered(table: np.ndarray, leaders_from: int, index: int) -> np.ndarray:
        """What the drawn shapes each shape of ``table`` (:func:`met`'s) meets weigh together: those before
        ``leaders_from`` covering them, the leaders after it (from the point of ``index``) crossing them
        (``crossed_weights``, but its own link's lines as ordinary ones).  The weights are whole numbers, so their
        sums are exact in any order."""
        crossed = crossed_weights
        if anchors[index].own_lines:
            crossed = crossed_weights.copy()
            own = shafts_met[~others_shafts(index)]
            crossed[own] = weights[own]
        return np.concatenate((table[:leaders_from] @ weights, table[leaders_from:] @ crossed))

    def others_than(placed: dict[int, BaseGeometry], own: int) -> tuple[np.ndarray, np.ndarray]:
        """The shapes of ``placed`` but ``own``'s, and their bounds: found once for the boxes and the leaders of all
        the spots a label tries."""
        others = np.array([shape for index, shape in placed.items() if index != own], dtype=object)
        return others, shapely.bounds(others)

    def crossing(shapes: np.ndarray, bounds: np.ndarray, others: tuple[np.ndarray, np.ndarray],
                 weights: np.ndarray | None = None) -> np.ndarray:
        """How many of ``others`` (:func:`others_than`'s) each of ``shapes`` (whose ``bounds`` are given) meets; with
        ``weights`` (one an other), what those it meets weigh together."""
        others, their_bounds = others
        # Only the pairs whose boxes meet are tested: of a few hundred labels placed, a spot is near a few.
        mine, theirs = np.nonzero(_boxes_meet(bounds[:, None], their_bounds))
        hit = shapely.intersects(shapes[mine], others[theirs])
        return np.bincount(mine[hit], None if weights is None else weights[theirs[hit]], minlength=len(shapes))

    def crossing_placed(shapes: np.ndarray, placed: dict[int, BaseGeometry], own: int) -> np.ndarray:
        """How many of the shapes ``placed`` but ``own``'s each of ``shapes`` meets."""
        return crossing(shapes, shapely.bounds(shapes), others_than(placed, own))

    led_from = len(BESIDE_SHARES)
    apart_from = led_from + len(LED_SHARES)

    # What a label's spots cost for the drawing alone, which stays as it is while the labels move: found once for
    # each anchor and kind of spot (a label is placed again in the repairs, and its neighbours with it).
    drawn_costs: dict[tuple, tuple] = {}

    def costed(index: int, shares: tuple[float, ...], rings: np.ndarray, directions: int = 16, first: int = 0):
        """The spots on the rings at ``shares`` round the anchor, numbered ``rings`` (a ring between two of the
        standard rings costs between them): their boxes, their rings, the leaders of those led, and what each
        costs.  With ``first``, only the spots of the first rings when one of them costs less than any spot farther
        out can (:data:`FIRST_RINGS`); the spots are numbered ring by ring, so theirs keep their numbers."""
        if first and (index, shares, directions) not in drawn_costs:
            spot = with_labels(index, on_drawing(index, shares[:first], rings[:first], directions))
            # Most labels stand beside their points: the spots farther out, and their leaders, are then never
            # costed, nor what they cover of the drawing asked of the tree.
            if spot.cost.min() < RING * rings[first]:
                return spot
        return with_labels(index, on_drawing(index, shares, rings, directions))

    def on_drawing(index: int, shares: tuple[float, ...], rings: np.ndarray, directions: int) -> tuple:
        """:func:`costed_on_drawing`'s, found once."""
        key = (index, shares, directions)
        if key not in drawn_costs:
            drawn_costs[key] = costed_on_drawing(index, shares, rings, directions)
        return drawn_costs[key]

    def with_labels(index: int, drawn: tuple) -> _Spots:
        """:func:`costed`'s spots with what they cost on the drawing (``drawn``, :func:`costed_on_drawing`'s) and what
        covering the labels and the leaders placed (but the label of ``index``) adds."""
        candidates, beside, led, lines, line_bounds, shapes, covering, drawn_cost = drawn
        # A spot's box is its candidate's bounds.
        labels, leaders = others_than(placed_boxes, index), others_than(leader_lines, index)
        # The labels and the leaders asked of together, once for the boxes and once for the leaders of the spots (a
        # label is costed some three hundred times a run, and each ask is a dozen array operations).
        placed = (np.concatenate((labels[0], leaders[0])), np.concatenate((labels[1], leaders[1])))
        clashing = OVERLAP * crossing(shapes, candidates, placed)
        # Two thin leaders crossing each other still lead each to its own label: less amiss than a leader
        # through a label, yet more than any drawn line covered.  The weights are whole numbers: their sums are exact.
        weights = np.repeat((OVERLAP, LEADERS_CROSSING), (len(labels[0]), len(leaders[0])))
        clashing[led] += crossing(lines, line_bounds, placed, weights)
        return _Spots(candidates, beside, led, lines, drawn_cost + clashing, covering, clashing)

    def costed_on_drawing(index: int, shares: tuple[float, ...], rings: np.ndarray, directions: int):
        """:func:`costed`'s spots and what they cost but for the labels and leaders placed."""
        anchor = anchors[index]
        ring, order, candidates = _candidates(anchor, gap, shares, directions)
        ring = np.asarray(rings, dtype=float)[ring]
        shapes = shapely.box(*candidates.T)
        # A label nearer another labelled point than its own would name the wrong one.  A box reaching
        # at most `reach` from its point is at least `away - reach` from a point `away` off, and at most
        # `reach` from its own: only points nearer than twice the reach (and the margin) can mislead.
        away = np.hypot(*(at - at[index]).T)
        off = np.abs(candidates - np.tile(at[index], 2))
        reach = np.hypot(off[:, [0, 2]].max(axis=1), off[:, [1, 3]].max(axis=1)).max()
        neighbours = at[(away > 1e-9) & (away < 2 * reach + MISLEADING_MARGIN + 1e-9)]
        misleading = _misleading(candidates, at[index], neighbours)
        beside = ring < led_from
        led = np.flatnonzero(~beside)
        lines = _leaders(anchor.at, candidates[led])
        # What the boxes and the leaders cover, in one query of the tree.
        table = met(np.concatenate((shapes, lines)))
        across_gap(table, lines, len(shapes))
        covers = covered(table, len(shapes), index)
        cost = COVER * covers[:len(shapes)] + RING * ring + order * 0.01
        # The leader says which point the label names: standing near a neighbour misleads less.
        cost[beside] += MISLEADING * misleading[beside]
        cost[led] += LEADER_CROSSING * covers[len(shapes):] + MISLEADING / 2 * misleading[led]
        cost[ring >= apart_from] += SET_APART
        # A box as wide as a long name, set off obliquely, reaches back over its own point even on the rings led to
        # it: beside the point already, it has no leader to draw.
        cost[led[_box_distances(candidates[led], at[index:index + 1])[:, 0] == 0.0]] += OVERLAP
        cost += KEPT_OFF * _kept_off(anchor, candidates, ~beside)
        covering = covers[:len(shapes)].copy()
        # A leader across a load's arrow counts as a line covered, as its name on the arrow would: the label is moved
        # off it, or reaches out, as one lying on a line is (``letter``).
        covering[led] += table[len(shapes):, shafts_met[others_shafts(index)]].sum(axis=1)
        # One run beside a line (where the caller asks) as one on it.
        beside_a_line = runs_beside(lines)
        cost[led[beside_a_line]] += COVER
        covering[led[beside_a_line]] += 1
        if off_lines:
            cost[covering > 0] += LINE_COVERED
        line_bounds = shapely.bounds(lines)
        for array in (candidates, beside, led, lines, line_bounds, shapes, covering, cost):
            array.flags.writeable = False
        return candidates, beside, led, lines, line_bounds, shapes, covering, cost

    near_shares = (*BESIDE_SHARES, *LED_SHARES, *APART_SHARES)

    def first_rings_on_drawing() -> None:
        """:func:`costed_on_drawing`'s of the spots on the first rings (:data:`FIRST_RINGS`) of every anchor, which
        every label is costed on first, found for all of them at once, each number by the same arithmetic."""
        shares = near_shares[:FIRST_RINGS]
        sizes = np.array([anchor.size for anchor in anchors], dtype=float)[:, None]
        half_widths = np.array([text_width(anchor.text, anchor.size) for anchor in anchors], dtype=float)[:, None] / 2
        prefer = np.array([anchor.prefer for anchor in anchors], dtype=float)[:, None]
        # _candidates', for every anchor: a row each.
        symbols = np.array([anchor.symbol_mm for anchor in anchors], dtype=float)[:, None]
        radii = gap + symbols + np.array(shares)[None, :] * sizes
        ring, order = _rings_and_orders(len(shares), 16)
        direction = prefer + _turns(16)[order] * math.pi / 8
        x, y = set_out(at[:, :1], at[:, 1:], np.cos(direction), np.sin(direction), radii[:, ring], half_widths, sizes)
        boxes = np.stack((x - half_widths, y - 0.3 * sizes, x + half_widths, y + 1.15 * sizes), axis=-1)
        spots_each = boxes.shape[1]
        shapes = shapely.box(*boxes.reshape(-1, 4).T)
        # The labelled points each spot stands about as near to as to its own (_misleading's), among those within
        # reach of its label's spots.
        away = np.hypot(*(at[None, :, :] - at[:, None, :]).transpose(2, 0, 1))
        off = np.abs(boxes - np.concatenate((at, at), axis=1)[:, None, :])
        reach = np.hypot(off[:, :, [0, 2]].max(axis=2), off[:, :, [1, 3]].max(axis=2)).max(axis=1)
        neighbours = (away > 1e-9) & (away < (2 * reach + MISLEADING_MARGIN + 1e-9)[:, None])
        own = _box_distance(boxes, at[:, None, :])
        misleading = np.zeros(own.shape, dtype=np.int64)
        block = max(1, 250_000 // (spots_each * len(anchors)))  # a few megabytes of distances at a time
        for first in range(0, len(anchors), block):
            rows = slice(first, first + block)
            near = _box_distance(boxes[rows, :, None, :], at[None, None, :, :]) < own[rows, :, None] + MISLEADING_MARGIN
            misleading[rows] = (near & neighbours[rows, None, :]).sum(axis=2)
        if tree is None:
            covers = np.zeros(len(shapes))
        else:
            # covered()'s, its table of which spot meets which obstacle as the pairs sorted without repeats: a table
            # for every spot of a drawing would take megabytes.  The weights are whole numbers: the sums are exact.
            hit, piece = tree.query(shapes, predicate="intersects")
            pairs = np.sort(hit * len(fixed) + owners[piece])
            unrepeated = np.ones(len(pairs), dtype=bool)  # none where no spot meets an obstacle
            unrepeated[1:] = pairs[1:] != pairs[:-1]
            pairs = pairs[unrepeated]  # not np.unique, which imports numpy.ma (a cold run's import time)
            covers = np.bincount(pairs // len(fixed), weights=weights[pairs % len(fixed)], minlength=len(shapes))
        covering = covers.reshape(boxes.shape[:2])
        cost = COVER * covering + RING * np.asarray(ring, dtype=float) + order * 0.01
        cost += MISLEADING * misleading  # every spot stands beside its point: none is led
        beside = np.ones(spots_each, dtype=bool)
        for index, anchor in enumerate(anchors):
            if anchor.keep_off is not None:  # added where costed_on_drawing adds it (nought elsewhere)
                cost[index] += KEPT_OFF * _kept_off(anchor, boxes[index], ~beside)
        if off_lines:
            cost[covering > 0] += LINE_COVERED
        led = np.flatnonzero(~beside)
        lines = _leaders(anchors[0].at, boxes[0][led])
        line_bounds = shapely.bounds(lines)
        for array in (beside, led, lines, line_bounds):
            array.flags.writeable = False
        for index in range(len(anchors)):
            own_shapes = shapes[index * spots_each:(index + 1) * spots_each]
            drawn = (boxes[index], beside, led, lines, line_bounds, own_shapes, covering[index], cost[index])
            for array in drawn:
                array.flags.writeable = False
            drawn_costs[(index, shares, 16)] = drawn

    fine_rings = np.interp(FINE_SHARES, (*BESIDE_SHARES, *LED_SHARES), np.arange(apart_from))
    kinds = {"near": (near_shares, np.arange(len(near_shares)), 16),
             "far": (FAR_SHARES, np.arange(len(FAR_SHARES)) + len(near_shares), 16),
             "fine": (FINE_SHARES, fine_rings, 2 * 16)}

    # Each standard spot short of those set apart, as the finer spot at the same place: its direction's turn doubled.
    standard_turns, fine_turns = _turns(16), list(_turns(2 * 16))
    as_fine = np.array([FINE_SHARES.index(share) * len(fine_turns) + fine_turns.index(2 * turn)
                        for share in (*BESIDE_SHARES, *LED_SHARES) for turn in standard_turns])

    def spots(index: int, kind: str = "near"):
        return costed(index, *kinds[kind], first=FIRST_RINGS if kind == "near" else 0)

    def put(index: int, spot: _Spots, best: int, kind: str) -> None:
        """Set the label of ``index`` at spot ``best`` of ``spot`` (what :func:`costed` gave)."""
        anchor = anchors[index]
        candidates, beside, led, lines, cost = spot.boxes, spot.beside, spot.led, spot.leaders, spot.cost
        x0, y0, x1, _ = candidates[best]
        texts[index] = Text(((x0 + x1) / 2, y0 + 0.3 * anchor.size), anchor.text, anchor.size, "middle",
                            anchor.colour)
        placed_boxes[index] = spaced_box(texts[index])
        leader_lines.pop(index, None)
        if not beside[best]:
            leader_lines[index] = lines[best - led[0]]
        paid[index] = float(cost[best])
        # What it covers, its leader crossing loads' arrows counted as lines covered (:func:`costed_on_drawing`), and
        # what its box covers alone.
        across = 0.0
        if index in leader_lines and len(shafts_met):
            across = float(shapely.intersects(_to_the_box(np.array([leader_lines[index]]))[0],
                                              fixed_shafts[others_shafts(index)]).sum())
        # And whether it stands within its anchor's ``keep_off``: what, with a line covered, sends it reaching out.
        kept_off = bool(_kept_off(anchor, candidates[best:best + 1], ~beside[best:best + 1])[0])
        where[index] = (kind, best, float(spot.covering[best]), float(spot.covering[best]) - across, kept_off)

    def place(index: int) -> None:
        """Put the label of ``index`` at its cheapest spot among the labels placed so far (but itself)."""
        spot = spots(index)
        cost, covering = spot.cost, spot.covering
        best, kind = int(np.argmin(cost)), "near"
        if cost[best] >= OVERLAP or (off_lines and covering[best] > 0):
            # Every spot near the point covers a label or a leader (the pole of a crowded lever), or a drawn line
            # where the drawing has room to keep off its lines: farther out, on a longer leader, before writing one
            # label over another.
            farther = spots(index, "far")
            if farther.cost.min() < cost[best]:
                spot, best, kind = farther, int(np.argmin(farther.cost)), "far"
        put(index, spot, best, kind)

    def off_other_labels(index: int) -> None:
        """Set the label of ``index``, left on another label after every mend, at the cheapest spot near or far whose
        box covers no other label, where one does: a box on a thin leader still reads, one on another box neither
        (two arms' names in the star of arms at a triad's Σ6, where every spot covered a leader, stood one on the
        other, as costly as it)."""
        others = others_than(placed_boxes, index)
        if not crossing(np.array([placed_boxes[index]]), np.array([placed_boxes[index].bounds]), others)[0]:
            return
        best = None
        for kind in ("near", "far"):
            spot = spots(index, kind)
            on_labels = crossing(shapely.box(*spot.boxes.T), spot.boxes, others)
            cost = np.where(on_labels > 0, np.inf, spot.cost)
            cheapest = int(np.argmin(cost))
            if np.isfinite(cost[cheapest]) and (best is None or cost[cheapest] < best[0]):
                best = (cost[cheapest], spot, cheapest, kind)
        crowded.append(index)
        if best is not None:
            put(index, *best[1:])

    def saved(*indices: int) -> list:
        return [(k, texts[k], placed_boxes[k], leader_lines.get(k), paid[k], where[k]) for k in indices]

    def restore(state: list) -> None:
        for k, text, spaced, leader, cost, spot in state:
            texts[k], placed_boxes[k], paid[k], where[k] = text, spaced, cost, spot
            leader_lines.pop(k, None)
            if leader is not None:
                leader_lines[k] = leader

    straight = shapely.get_type_id(pieces) == shapely.GeometryType.LINESTRING if fixed else np.zeros(0, dtype=bool)

    def runs_beside(leaders: np.ndarray) -> np.ndarray:
        """Whether each of ``leaders`` runs beside a drawn line's ink, nearly along it (:data:`BESIDE_SPACE`), where
        the caller asks (``leaders_apart``): all False else."""
        found = np.zeros(len(leaders), dtype=bool)
        if edge_tree is None or not len(leaders):
            return found
        # How far a leader runs within each band is measured exactly below.
        hit, edge = edge_tree.query(leaders)
        ends = shapely.get_coordinates(leaders).reshape(-1, 2, 2)
        along = ends[:, 1] - ends[:, 0]
        along /= np.maximum(np.hypot(*along.T), 1e-12)[:, None]
        # Nearly along the edge: only those pairs are measured.
        near = np.abs(along[hit, 0] * edge_directions[edge, 1] - along[hit, 1] * edge_directions[edge, 0]) \
            < math.sin(BESIDE_ANGLE)
        hit, edge = hit[near], edge[near]
        found[hit[_run_within(ends[hit], edge_ends[edge], BESIDE_SPACE + LEADER_WIDTH / 2) > ALONG]] = True
        return found

    def runs_along(leader: BaseGeometry) -> bool:
        """Whether ``leader`` runs along a drawn line (more than ALONG of it on the line), reading as part of it; or,
        where the caller asks, beside one (:func:`runs_beside`)."""
        if tree is None:
            return False
        if runs_beside(np.array([leader]))[0]:
            return True
        # Within a stroke's width of the line, not only on it: a point a hair off its line leads along it too.
        near = tree.query(leader, predicate="dwithin", distance=ALONG_WIDTH)
        near = near[straight[near]]
        strokes = shapely.buffer(pieces[near], ALONG_WIDTH, quad_segs=1)
        return bool(shapely.length(shapely.intersection(leader, strokes)).max(initial=0.0) > ALONG)

    def off_the_line(index: int) -> None:
        """Move the label of ``index``, which covers a drawn line, where it covers less and costs less: to the
        cheapest of finer spots round its point (twice the directions, a ring between the two beside it, no farther
        out than those led to it), and else to one of those that a single neighbouring label stands on, when that
        neighbour finds another spot covering no more, and the two cost less together."""
        kind, best, covers, *_ = where[index]
        # Between lines meeting at a point a clear spot often lies between two of the standard ones.
        spot = spots(index, "fine")
        cost, covering, clashing = spot.cost, spot.covering, spot.clashing
        # Only spots that cover less: a move trades no line for another, nor for a point or a text.
        less = covering < covers - 1e-9
        # The standard spots beside the point and led to it are among the finer ones (but for the order's tie-break).
        same = best if kind == "fine" else as_fine[best] if kind == "near" and best < len(as_fine) else None
        before = float(cost[same] if same is not None else spots(index, kind).cost[best])
        if before >= OVERLAP:
            return  # left covering another label's leader: the repair rounds' business, not this one's
        finest = int(np.argmin(np.where(less, cost, np.inf)))
        if less[finest] and cost[finest] < before - 1e-9:
            put(index, spot, finest, "fine")
            if not covering[finest]:
                return
            before, less = float(cost[finest]), covering < covering[finest] - 1e-9
        # Spots that would be cheaper but for one neighbour's label or leader, cheapest first.
        free = cost - clashing
        hopeful = [k for k in np.argsort(free, kind="stable")
                   if less[k] and free[k] < before - 1e-9 and clashing[k] > 0]
        owners = np.array([k for k in placed_boxes if k != index] + [k for k in leader_lines if k != index])
        shapes = np.array([placed_boxes[k] for k in placed_boxes if k != index]
                          + [leader_lines[k] for k in leader_lines if k != index], dtype=object)
        tried: set[int] = set()
        for candidate in hopeful[:SPOTS_LOOKED_AT]:
            if len(tried) == MOVES_TRIED:
                break
            mine = [shapely.box(*spot.boxes[candidate])]
            if not spot.beside[candidate]:
                mine.append(spot.leaders[candidate - spot.led[0]])
            hit = np.zeros(len(shapes), dtype=bool)
            for shape in mine:
                hit |= shapely.intersects(shape, shapes)
            neighbours = set(owners[hit].tolist())
            # One neighbour that is an anchor's (not a label standing already), and not tried yet.
            if len(neighbours) != 1 or min(neighbours) < 0 or neighbours <= tried:
                continue
            (neighbour,) = neighbours
            tried.add(neighbour)
            state = saved(index, neighbour)
            # What the neighbour paid where it stands: at most what it costs now, which labels lettered after it
            # can only have raised; a move judged against it is never worse.
            together, its_covers, its_leader = before + paid[neighbour], where[neighbour][2], neighbour in leader_lines
            put(index, spot, int(candidate), "fine")
            place(neighbour)
            # The spot costs what it would but for the neighbour, and what it pays for the neighbour where it went.
            theirs = [placed_boxes[neighbour], *([leader_lines[neighbour]] if neighbour in leader_lines else [])]
            moved = float(free[candidate]) + sum(
                LEADERS_CROSSING if (one, other) == (1, 1) else OVERLAP  # two leaders crossing, else a label hit
                for one, mine_shape in enumerate(mine) for other, their in enumerate(theirs)
                if mine_shape.intersects(their))
            # The neighbour covers no more than it did, and stays beside its point if it stood there: a label off a
            # line never puts another on one, nor sends it off on a leader (one run along a line reads as the line).
            if (moved < OVERLAP and paid[neighbour] < OVERLAP and moved + paid[neighbour] < together - 1e-9
                    and where[neighbour][2] <= its_covers + 1e-9 and (its_leader or neighbour not in leader_lines)
                    and not (neighbour in leader_lines and runs_along(leader_lines[neighbour]))):
                paid[index] = moved
                return
            restore(state)

    # Every standard ring, near and far: those a label reaches to are numbered as the ones they fall between.
    all_shares = (*near_shares, *FAR_SHARES)

    reachable_on_drawing: dict[tuple[int, bool, tuple[float, ...], bool], tuple] = {}

    def reachable(index: int, leading: bool = True, shares: tuple[float, ...] = REACH_SHARES,
                  from_line: bool = False, across_shafts: bool = False):
        """The spots within reach of the label of ``index`` (:func:`reach_out`'s): their costs (as :class:`_Spots`),
        their boxes as shapes, which are led, and which may hold it as far as the drawing goes: the box covering
        nothing, and standing where the anchor lets it (none within its ``keep_off``, no leader where not
        ``leading``, no long name led from a spot that reaches back over its own point); led from its point alone, or
        (``from_line``) from any point of the line it names beside which it may stand too; its leader crossing no
        load's arrow (``shafts``) but ``across_shafts``."""
        key = (index, leading, shares, from_line)
        if key not in reachable_on_drawing:
            reachable_on_drawing[key] = reachable_drawn(*key)
        spot, shapes, is_led, usable, across = reachable_on_drawing[key]
        if not across_shafts:
            usable = usable & ~across
        crossings = LEADERS_CROSSING * crossing_placed(spot.leaders, leader_lines, index)
        cost = spot.cost.copy()
        cost[spot.led] += crossings
        return spot._replace(cost=cost), shapes, is_led, usable

    def reachable_drawn(index: int, leading: bool, shares: tuple[float, ...], from_line: bool):
        """:func:`reachable` but for the leaders placed."""
        anchor = anchors[index]
        slid = _slide_points(anchor)
        ring, turn, offsets = _candidates(anchor, gap, BESIDE_SHARES, 16, at=(0.0, 0.0))
        beside_boxes = (offsets[None, :, :] + np.tile(slid, 2)[:, None, :]).reshape(-1, 4)
        beside_points = np.repeat(slid, len(offsets), axis=0)
        beside_cost = (RING * np.tile(ring, len(slid)) + 0.01 * np.tile(turn, len(slid))
                       + SLIDE_COST * np.repeat(np.hypot(*(slid - anchor.at).T), len(offsets))
                       / (SLIDE_STEP * anchor.size))
        # Led from its point or, from_line, from another point of the line it names too, as a draughtsman names an
        # arrow whose head is crowded by a leader from its shaft.
        starts = slid if from_line else slid[:1]
        led_ring, led_turn, led_offsets = _candidates(anchor, gap, shares, 2 * 16, at=(0.0, 0.0))
        led_boxes = (led_offsets[None, :, :] + np.tile(starts, 2)[:, None, :]).reshape(-1, 4)
        led_points = np.repeat(starts, len(led_offsets), axis=0)
        led_ring, led_turn = np.tile(led_ring, len(starts)), np.tile(led_turn, len(starts))
        led_slid = np.repeat(np.hypot(*(starts - anchor.at).T), len(led_offsets)) / (SLIDE_STEP * anchor.size)
        # The rings reached, numbered as the standard ones they fall between.
        reach_rings = np.interp(shares, all_shares, np.arange(len(all_shares)))
        candidates = np.concatenate((beside_boxes, led_boxes))
        points = np.concatenate((beside_points, led_points))
        is_led = np.arange(len(candidates)) >= len(beside_boxes)
        led = np.flatnonzero(is_led)
        lines = np.concatenate([_leaders(tuple(point), led_boxes[k * len(led_offsets):(k + 1) * len(led_offsets)])
                                for k, point in enumerate(starts)])
        shapes = shapely.box(*candidates.T)
        table = met(np.concatenate((shapes, lines)))
        across_gap(table, lines, len(shapes))
        covers = covered(table, len(shapes), index)
        usable = covers[:len(shapes)] == 0
        # Which spots' leaders cross a load's arrow, reading as part of it or as naming its load: not clear either
        # unless nothing else is (:func:`reachable`).
        across = np.zeros(len(candidates), dtype=bool)
        across[led] = table[len(shapes):, shafts_met[others_shafts(index)]].any(axis=1)
        # A long name set off obliquely reaches back over its own point: beside it already, with no leader to draw.
        usable[led] &= _box_distance(led_boxes, led_points) > 0.0
        usable &= ~_kept_off(anchor, candidates, is_led)
        if not leading:
            usable &= ~is_led
        # Standing about as near another labelled point as its own (the point of its line beside which it stands)
        # would name the wrong one.
        misleading = _misleading(candidates, points, np.delete(at, index, axis=0))
        cost = np.concatenate((beside_cost + MISLEADING * misleading[:len(beside_boxes)],
                               RING * reach_rings[led_ring] + 0.01 * led_turn + SLIDE_COST * led_slid
                               + SET_APART * (reach_rings[led_ring] >= apart_from)
                               + LEADER_CROSSING * covers[len(shapes):]
                               + MISLEADING / 2 * misleading[led]))
        # A usable spot's box covers nothing: it covers what its leader crosses of the loads' arrows, as the spots
        # costed_on_drawing costs.
        spot = _Spots(candidates, ~is_led, led, lines, cost, across.astype(float), np.zeros(len(candidates)))
        return spot, shapes, is_led, usable, across

    def tried(spot: _Spots, is_led: np.ndarray, usable: np.ndarray, tries: int = REACH_TRIES):
        """The cheapest of the ``usable`` spots whose leader, if any, runs along no line (it would read as part of
        it, not as leading to the label), as far as ``tries``."""
        for best in np.argsort(np.where(usable, spot.cost, np.inf), kind="stable")[:tries]:
            if not usable[best]:
                return
            if not (is_led[best] and runs_along(spot.leaders[best - spot.led[0]])):
                yield int(best)

    def reach_out(index: int, moving: bool = True, leading: bool = True,
                  shares: tuple[float, ...] = REACH_SHARES, from_line: bool = False, across_shafts: bool = False,
                  cheaper: bool = False) -> bool:
        """Move the label of ``index``, left on a line (or another label) once all stand, to the cheapest spot within
        reach (its leader as long as the rings at ``shares`` letter heights) whose box covers nothing and whose leader
        crosses no label and runs along no line: beside another point of the line it names, or (``leading``) on a short
        leader from its point; else (``moving``) to such a spot one neighbouring label stands on, when that neighbour
        reaches such a spot too, beside its point if it stood there; ``from_line``, also on a leader from another
        point of the line it names (:func:`reachable`); ``across_shafts``, led across a load's arrow too.  Such a spot
        costs more than the line it leaves by
        the rules of :func:`costed`, which let a letter lie on one line sooner than lead it off across two.
        ``cheaper``: the label covers nothing where it stands, and only a spot that costs less than it paid there will
        do, no neighbour moved for it.  Whether the label moved."""
        spot, shapes, is_led, usable = reachable(index, leading, shares, from_line, across_shafts)
        # Clear of the drawing, of every leader, and where it may stand; then clear of the labels too, or of one.
        open_ = usable & (crossing_placed(shapes, leader_lines, index) == 0)
        if cheaper:
            open_ &= spot.cost < paid[index] - 1e-9
            moving = False
        open_[spot.led] &= crossing_placed(spot.leaders, placed_boxes, index) == 0
        if not open_.any():
            return False
        labels_hit = crossing_placed(shapes, placed_boxes, index)
        for best in tried(spot, is_led, open_ & (labels_hit == 0)):
            put(index, spot, best, "reach")
            return True
        if not moving:
            return False
        for best in tried(spot, is_led, open_ & (labels_hit == 1)):
            (neighbour,) = [k for k, other in placed_boxes.items() if k != index and other.intersects(shapes[best])]
            if neighbour < 0:
                continue  # a label standing already does not move
            state = saved(index, neighbour)
            put(index, spot, best, "reach")
            if reach_out(neighbour, moving=False, leading=neighbour in leader_lines):
                return True
            restore(state)
        return False

    def astray(index: int) -> bool:
        """Whether the label of ``index`` stands where it must not: on a line, on another label, or within its anchor's
        ``keep_off``.  One that paid as much as that for its leader's way alone stands clear, and moves only where it
        pays less: sent reaching out, the Scotch yoke's A′, clear on a short leader up to the right of its top pin, went
        to a dearer spot 9 mm to the left behind the pin's number, and, set again out of the number's shadow, stood
        8 mm down across the blocks."""
        return where[index][2] > 0 or where[index][4] or paid[index] >= OVERLAP

    # The farthest a label reaches from its point (letter heights beyond the gap): a neighbour it moves to make room
    # is led no farther than that, or than it was.
    reach_share = max(REACH_SHARES)

    def make_room(index: int, across_shafts: bool = False) -> bool:
        """Move the label of ``index``, still on a line after :func:`reach_out`, to a spot within reach whose box
        covers nothing of the drawing but the labels or leaders of up to ROOM_MADE neighbours, placing those again
        round it (each where :func:`place` puts it, reaching out from a line there), when fewer of them all then lie
        on lines and none covers another label, takes a leader along a line, or a longer one than it had beyond
        the reach.  In a crowd of names round a lever's pole each spot off the lines near a label is taken by a
        neighbour that could stand as well elsewhere, but not by one alone: moved one at a time, none moves.
        ``across_shafts``: its own leader may cross a load's arrow.  Whether the label moved."""
        spot, shapes, is_led, usable = reachable(index, across_shafts=across_shafts)
        # Whose label or leader each spot's box or leader meets.
        owners = [k for k in placed_boxes if k != index] + [k for k in leader_lines if k != index]
        others = np.array([placed_boxes[k] for k in placed_boxes if k != index]
                          + [leader_lines[k] for k in leader_lines if k != index], dtype=object)
        if not len(others):
            return False
        mine = np.concatenate((shapes, spot.leaders))
        hit, other = STRtree(others).query(mine, predicate="intersects")
        # A leader's spot is the box's index, whether its box or its leader meets the neighbour.
        hit = np.where(hit >= len(shapes), spot.led[np.clip(hit - len(shapes), 0, len(spot.led) - 1)], hit)
        met: list[set[int]] = [set() for _ in range(len(shapes))]
        for one, theirs in zip(hit.tolist(), other.tolist()):
            met[one].add(owners[theirs])
        crowded = np.array([0 < len(them) <= ROOM_MADE and min(them) >= 0 for them in met])
        for best in tried(spot, is_led, usable & crowded, ROOM_TRIES):
            neighbours = sorted(met[best], key=order.index)
            state = saved(index, *neighbours)
            lying = [where[k][2] > 0 for k in (index, *neighbours)]
            covering = sum(where[k][2] for k in (index, *neighbours))
            reaches = {k: max(leader_lines[k].length if k in leader_lines else 0.0,
                              gap + anchors[k].symbol_mm + reach_share * anchors[k].size) for k in neighbours}
            put(index, spot, best, "room")
            for k in neighbours:
                place(k)
                if where[k][2] > 0 or paid[k] >= KEPT_OFF:
                    reach_out(k, moving=False, cheaper=not astray(k))
            if (sum(where[k][2] > 0 for k in neighbours) < sum(lying)
                    and sum(where[k][2] for k in neighbours) <= covering + 1e-9
                    and all(paid[k] < OVERLAP for k in neighbours)
                    and all(k not in leader_lines or (leader_lines[k].length <= reaches[k] + 1e-9
                                                      and not runs_along(leader_lines[k])) for k in neighbours)):
                return True
            restore(state)
        return False

    def letter() -> None:
        """Place every label in ``order`` among those placed before it, and mend what that left."""
        if FIRST_RINGS and FIRST_RINGS_TOGETHER and anchors:
            first_rings_on_drawing()
        for index in order:
            place(index)
        # Lettered one by one, a label can take the only clear spot of a later one.  Each label that had to cover
        # another is placed again among all the others, now that they all stand: it, or the one it covers, moves.
        for _ in range(REPAIR_ROUNDS):
            clashing = [index for index in order if paid[index] >= OVERLAP]
            if not clashing:
                break
            covered_ones = [other for other in order if other not in clashing
                            and any(_clash(index, other, placed_boxes, leader_lines) for index in clashing)]
            for index in covered_ones + clashing:
                place(index)
        # Lettered one by one, a label can also be left on a line beside its point where a neighbour lettered before
        # it took the clear spot, which the neighbour did not need: the two change places when that costs less.
        for index in order:
            if where[index][2] > 0 and paid[index] < OVERLAP:
                off_the_line(index)
        # Those still on a line, or on another label, reach farther for a spot clear of everything.
        for index in order:
            if where[index][2] > 0 or paid[index] >= KEPT_OFF:
                reach_out(index, cheaper=not astray(index))
        # Those on a line still, where a clear spot within reach is held by a few neighbours, move them.
        for index in order:
            if where[index][2] > 0 and paid[index] < OVERLAP:
                make_room(index)
        # Those on a line even so, every clear spot within reach held by neighbours that cannot all stand clear
        # elsewhere, reach farther out on their leaders, where the caller gives them no other way.
        for index in order:
            if farther[index] and where[index][2] > 0 and paid[index] < OVERLAP:
                reach_out(index, shares=FROM_LINE_SHARES, from_line=True)
        # Those whose names lie on a line even so, every clear spot within reach led across a load's arrow, take the
        # cheapest of those: the leader still leads to the name, which on the line is misread.
        for index in order:
            if len(shafts_met) and where[index][3] > 0 and paid[index] < OVERLAP:
                reach_out(index, across_shafts=True)
        # Those on another label even so take a spot on a leader, or on lines, rather.
        for index in order:
            if paid[index] >= OVERLAP:
                off_other_labels(index)

    farther = np.broadcast_to(np.asarray(reach_farther, dtype=bool), len(anchors))

    order = _most_crowded_first(anchors, at)
    where: dict[int, tuple[str, int, float, float, bool]] = {}
    crowded: list[int] = []
    letter()
    leaders = tuple(Polyline(_from_its_line(leader_lines[k], anchors[k]), Stroke(LEADER_WIDTH, anchors[k].colour))
                    for k in order if k in leader_lines)
    return Placement(tuple(texts[k] for k in range(len(anchors))), leaders, bool(crowded))


def _from_its_line(leader: BaseGeometry, anchor: Anchor) -> tuple[tuple[float, float], ...]:
    """``leader``'s points, run back onto the line its anchor names where it starts from a point along that line
    (:func:`_slide_points`): started :data:`LEADER_CLEARANCE` off it, as off a point's dot, a load's name led from
    its arrow's shaft stood a millimetre from the arrow, its leader touching nothing."""
    points = tuple(leader.coords)
    if anchor.along is None:
        return points
    line = shapely.LineString(anchor.along)
    start = shapely.Point(points[0])
    # From the anchor's own point (a joint's dot, a load's tail) the leader keeps clear of it.
    if start.distance(shapely.Point(anchor.at)) <= LEADER_CLEARANCE + 1e-6 or \
            start.distance(line) > LEADER_CLEARANCE + 1e-6:
        return points
    foot = line.interpolate(line.project(start))
    return ((foot.x, foot.y), *points[1:])


# How many placements :func:`remembered` keeps, the least recently asked given up first: a test module draws the same
# scenes some hundreds of times, a few dozen placements each.
PLACEMENTS_KEPT = 4096
_placements: RecentMemo[Placement] = RecentMemo()
# The placer as this module defines it: one a test puts in its place (to record or count its calls) is asked every time.
_PLACER = place_labels


def remembered(placer: Callable[..., Placement], anchors: Sequence[Anchor], obstacles: Sequence[BaseGeometry],
               *arguments, **keywords) -> Placement:
    """``placer(anchors, obstacles, *arguments, **keywords)``, the same placement given again where
    :func:`place_labels` was asked it before with the very same arguments.

    The placer is a function of its arguments alone, and the drawings ask it
    the same again and again: the tests draw each scene many times in one
    process (two thirds of the placements of the force sheets' tests were
    ones made before, 21 s of 32), and a run letters a sheet's plans again
    for each format it tries.  The key is every argument as it is written (a
    float's repr is exact, an array's bytes, the shapes by
    :func:`shapes_digest`), and the tuning of this module, which the tests
    change to compare placements made other ways.  A placer other than
    :func:`place_labels` (a recorder of the calls, a test's, also one set in
    its place in this module) is asked every time, as is one whose tree a
    test has replaced (to count its queries).
    """
    if placer is not _PLACER or place_labels is not _PLACER or STRtree is not shapely.STRtree or PLACEMENTS_KEPT <= 0:
        return placer(anchors, obstacles, *arguments, **keywords)
    head = repr((_as_written(tuple(anchors)), _as_written(arguments),
                 sorted((name, _as_written(value)) for name, value in keywords.items()),
                 [(name, value) for name, value in globals().items() if name.isupper()]))
    return _placements.get(shapes_digest(obstacles, head), lambda: placer(anchors, obstacles, *arguments, **keywords),
                           PLACEMENTS_KEPT)


def shapes_digest(shapes: Sequence[BaseGeometry], head: str) -> bytes:
    """A key for ``shapes`` as they are, after ``head``: each shape's type (WKB writes a ring's as a line's) and its
    WKB, its coordinates' exact bytes."""
    given = np.array(list(shapes), dtype=object)
    written = shapely.to_wkb(given).tolist() if len(given) else []
    key = hashlib.sha256(head.encode())
    key.update(np.asarray(shapely.get_type_id(given) if len(given) else [], dtype=np.int64).tobytes())
    key.update(np.array([len(each) for each in written], dtype=np.int64).tobytes())
    key.update(b"".join(written))
    return key.digest()


def _as_written(value: object) -> object:
    """``value`` for :func:`remembered`'s key: an array by its type, shape and bytes (its repr elides a long one's
    middle), a shape by its WKB (so does its repr), a sequence item by item."""
    if isinstance(value, np.ndarray):
        return ("array", value.dtype.str, value.shape, value.tobytes())
    if isinstance(value, (list, tuple)):
        return (type(value).__name__, *(_as_written(item) for item in value))
    if isinstance(value, BaseGeometry):
        return ("shape", shapely.to_wkb(value))
    return value


def spaced_box(text: Text, spacing: float = LABEL_SPACING) -> BaseGeometry:
    """The box of ``text`` kept apart by a little more than touching, so that two letters never read as one (s5g):
    the upright box grown by ``spacing`` on every side (a mitred buffer, without shapely's general buffer's cost)."""
    x0, y0, x1, y1 = text_extent(text)
    return shapely.box(x0 - spacing, y0 - spacing, x1 + spacing, y1 + spacing)


# How far a thin line broken under a label stops short of its letters' box (mm).
BREAK_MM = 0.4


def broken_under(items: Sequence[Primitive], texts: Sequence[Text], breakable: Sequence[Polyline]) -> list[Primitive]:
    """``items`` with those of them in ``breakable`` (thin lines) broken where they run under one of ``texts``, as
    ГОСТ 2.307 breaks a line under a dimension's number and a draftsman any thin line under a label."""
    if not texts:
        return list(items)
    gaps = shapely.union_all([spaced_box(text, BREAK_MM) for text in texts])
    breaking = {id(item) for item in breakable}
    kept: list[Primitive] = []
    for item in items:
        if id(item) not in breaking:
            kept.append(item)
            continue
        line = shapely.LineString(item.points + ((item.points[0],) if item.closed else ()))
        if not line.intersects(gaps):
            kept.append(item)
            continue
        left = line.difference(gaps)
        for piece in getattr(left, "geoms", [left]):
            if piece.geom_type == "LineString" and not piece.is_empty:
                kept.append(Polyline(tuple(piece.coords), item.stroke))
    return kept


def _clash(one: int, other: int, boxes: dict[int, BaseGeometry], leaders: dict[int, BaseGeometry]) -> bool:
    """Whether the label of ``one`` (its box or leader) covers the box or the leader of ``other``'s."""
    mine = [boxes[one], *([leaders[one]] if one in leaders else [])]
    theirs = [boxes[other], *([leaders[other]] if other in leaders else [])]
    return any(a.intersects(b) for a in mine for b in theirs)


def _most_crowded_first(anchors: Sequence[Anchor], at: np.ndarray) -> list[int]:
    """The anchors' indices, those with the most neighbours near them first (stable otherwise)."""
    distance = np.hypot(*(at[:, None, :] - at[None, :, :]).transpose(2, 0, 1))
    reach = np.array([CROWD * anchor.size for anchor in anchors])
    neighbours = (distance < reach[:, None]).sum(axis=1) - 1
    return sorted(range(len(anchors)), key=lambda index: -neighbours[index])


def _leaders(at: tuple[float, float], boxes: np.ndarray) -> np.ndarray:
    """The leader lines from just outside the point ``at`` to the nearest edge of each label's box
    ((xmin, ymin, xmax, ymax) rows).

    A box over the point itself gets a leader of no length (:func:`place_labels` takes such a spot last)."""
    near = np.clip(np.asarray(at), boxes[:, :2], boxes[:, 2:])
    along = near - np.asarray(at)
    length = np.hypot(*along.T)[:, None]
    unit = np.divide(along, length, out=np.zeros_like(along), where=length > 0)
    start = np.asarray(at) + unit * LEADER_CLEARANCE
    return shapely.linestrings(np.stack((start, near - unit * LEADER_GAP), axis=1))


def _to_the_box(leaders: np.ndarray) -> np.ndarray:
    """``leaders`` (:func:`_leaders`' lines) run on to their labels' boxes over the gap they stop short by: an arrow
    passing through that gap, between a leader's end and its letters, reads as crossed by the leader."""
    ends = shapely.get_coordinates(leaders).reshape(-1, 2, 2)
    along = ends[:, 1] - ends[:, 0]
    length = np.hypot(*along.T)[:, None]
    unit = np.divide(along, length, out=np.zeros_like(along), where=length > 0)
    return shapely.linestrings(np.stack((ends[:, 0], ends[:, 1] + unit * LEADER_GAP), axis=1))


def _pieces(shapes: Sequence[BaseGeometry]) -> tuple[np.ndarray, np.ndarray]:
    """The obstacles as the tree holds them, and the index of the obstacle each piece is of: a line by its segments,
    whose boxes the tree tells apart (a curve of a diagram spans it, and every label's spot was tested against
    all its vertices), any other shape whole."""
    whole = np.array(shapes, dtype=object)
    kinds = shapely.get_type_id(whole)
    lines = np.flatnonzero((kinds == shapely.GeometryType.LINESTRING) | (kinds == shapely.GeometryType.LINEARRING))
    segments, of_line, _ = _segments(whole[lines])
    owners = lines[of_line]
    # A line that is one point, like any other shape, stays whole.  Found by a mask: np.setdiff1d asks numpy.ma
    # whether the indices are masked, and importing it costs a cold run some 30 ms.
    cut = np.zeros(len(whole), dtype=bool)
    cut[owners] = True
    kept = np.flatnonzero(~cut)
    return np.concatenate((segments, whole[kept])), np.concatenate((owners, kept))


def _edges(shapes: Sequence[BaseGeometry]) -> tuple[np.ndarray, np.ndarray]:
    """The straight edges of the obstacles' ink as segments, and each one's direction (a unit vector): a line's
    segments (its middle: a thin line), and the segments of a shape's outline (an inked line's edges, a block's
    sides), beside which a leader runs."""
    whole = np.array(shapes, dtype=object)
    if not len(whole):
        return np.zeros(0, dtype=object), np.zeros((0, 2))
    kinds = shapely.get_type_id(whole)
    areas = (kinds == shapely.GeometryType.POLYGON) | (kinds == shapely.GeometryType.MULTIPOLYGON)
    outlines = np.concatenate((whole[~areas], shapely.boundary(whole[areas])))
    parts = shapely.get_parts(outlines)
    parts = parts[shapely.get_type_id(parts) != shapely.GeometryType.POINT]
    segments, _, along = _segments(parts)
    return segments, along / np.hypot(*along.T)[:, None]


def _segments(lines: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The straight segments of ``lines``, each vertex to the next of the same line (one of no length is a vertex of
    its neighbours): the segments, the index in ``lines`` of the line each is of, and each one's run (end − start)."""
    ends, of_line = shapely.get_coordinates(lines, return_index=True)
    segment = (of_line[:-1] == of_line[1:]) & np.any(ends[:-1] != ends[1:], axis=1)
    starts, stops = ends[:-1][segment], ends[1:][segment]
    return shapely.linestrings(np.stack((starts, stops), axis=1)), of_line[:-1][segment], stops - starts


def _run_within(lines: np.ndarray, edges: np.ndarray, width: float) -> np.ndarray:
    """How much of each segment of ``lines`` (its two ends, in the last two axes) runs within ``width`` of the segment
    of ``edges`` beside it, between the perpendiculars at its ends: its band as a flat-capped buffer draws it.  Both
    ends' offsets from the edge's line and places along it change linearly along the segment, so the part within is
    where the intervals of both meet."""
    start, stop = edges[:, 0], edges[:, 1]
    length = np.maximum(np.hypot(*(stop - start).T), 1e-12)
    unit = (stop - start) / length[:, None]

    def placed(point: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        offset = point - start
        return (offset[:, 0] * unit[:, 0] + offset[:, 1] * unit[:, 1],
                offset[:, 1] * unit[:, 0] - offset[:, 0] * unit[:, 1])

    (along0, off0), (along1, off1) = placed(lines[:, 0]), placed(lines[:, 1])
    low, high = np.zeros(len(lines)), np.ones(len(lines))
    for first, last, least, most in ((off0, off1, -width, width), (along0, along1, 0.0, length)):
        change = last - first
        steady = np.abs(change) < 1e-12
        with np.errstate(divide="ignore", invalid="ignore"):
            enter, leave = (least - first) / change, (most - first) / change
        enter, leave = np.minimum(enter, leave), np.maximum(enter, leave)
        inside = (first >= least) & (first <= most)
        low = np.maximum(low, np.where(steady, np.where(inside, 0.0, 1.0), enter))
        high = np.minimum(high, np.where(steady, np.where(inside, 1.0, 0.0), leave))
    return np.maximum(high - low, 0.0) * np.hypot(*(lines[:, 1] - lines[:, 0]).T)


def cover_one_another(texts: Sequence[Text]) -> bool:
    """Whether two of ``texts`` cover one another on the paper (their boxes meet)."""
    boxes = np.array([text_box(text).bounds for text in texts], dtype=float).reshape(-1, 4)
    return bool(_boxes_meet(boxes[:, None], boxes[None, :])[np.triu_indices(len(boxes), 1)].any())


def _boxes_meet(one: np.ndarray, other: np.ndarray) -> np.ndarray:
    """Whether upright boxes ((xmin, ymin, xmax, ymax) in the last axis, broadcast) meet, edges included."""
    return ((one[..., 0] <= other[..., 2]) & (other[..., 0] <= one[..., 2])
            & (one[..., 1] <= other[..., 3]) & (other[..., 1] <= one[..., 3]))


def _box_distances(boxes: np.ndarray, points: np.ndarray) -> np.ndarray:
    """The distance of each upright box ((xmin, ymin, xmax, ymax) rows) from each point: nought inside it."""
    return _box_distance(boxes[:, None, :], points[None, :, :])


def _box_distance(boxes: np.ndarray, points: np.ndarray) -> np.ndarray:
    """The distance of upright boxes ((xmin, ymin, xmax, ymax) in the last axis) from points ((x, y) in the last
    axis), broadcast against each other: nought inside."""
    x, y = points[..., 0], points[..., 1]
    dx = np.maximum(np.maximum(boxes[..., 0] - x, x - boxes[..., 2]), 0.0)
    dy = np.maximum(np.maximum(boxes[..., 1] - y, y - boxes[..., 3]), 0.0)
    return np.hypot(dx, dy)


def _misleading(boxes: np.ndarray, own: np.ndarray, others: np.ndarray) -> np.ndarray:
    """For each box, how many of the points ``others`` it stands about as near as its own point ``own`` (one for all
    the boxes, or one a box): a label there would read as naming the wrong one."""
    return (_box_distances(boxes, others) < _box_distance(boxes, own)[:, None] + MISLEADING_MARGIN).sum(axis=1)


def set_out(x: Any, y: Any, cos: Any, sin: Any, radius: Any, half_width: Any, size: Any) -> tuple[Any, Any]:
    """Where a label's text (its anchor point, as :class:`Text` takes it) stands set out from the point (``x``,
    ``y``) along the direction (``cos``, ``sin``), its box's near edge ``radius`` off: scalars or numpy arrays alike,
    for every spot the placer tries and for a spot chosen outside it (a polygon's name out of a sliver)."""
    return x + cos * (radius + half_width), y + sin * (radius + 0.55 * size) - 0.45 * size


def _candidates(anchor: Anchor, gap: float, shares: tuple[float, ...], directions: int = 16,
                at: tuple[float, float] | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(ring, order, box) of every spot round ``at`` (the anchor's point unless given): sixteen directions (or
    ``directions``) on each ring, the preferred direction first.

    The rings of :data:`BESIDE_SHARES` stand beside the point; a label on
    those of :data:`LED_SHARES` and :data:`APART_SHARES` gets a leader line.
    A box is (xmin, ymin, xmax, ymax) as :func:`text_extent` gives it.
    """
    width = text_width(anchor.text, anchor.size)
    radii = np.array([gap + anchor.symbol_mm + share * anchor.size for share in shares])
    half = directions // 2
    turns = _turns(directions)
    ring, order = _rings_and_orders(len(radii), directions)
    direction = anchor.prefer + turns[order] * math.pi / half
    # Push the box's near edge, not its centre, out to the radius.
    at = anchor.at if at is None else at
    x, y = set_out(at[0], at[1], np.cos(direction), np.sin(direction), radii[ring], width / 2, anchor.size)
    boxes = np.stack((x - width / 2, y - 0.3 * anchor.size, x + width / 2, y + 1.15 * anchor.size), axis=1)
    return ring, order, boxes


def _slide_points(anchor: Anchor) -> np.ndarray:
    """The points of the line an anchor names (:attr:`Anchor.along`) beside which its label may stand, its own point
    first: every SLIDE_STEP letter heights either way, as far as SLIDE, short of the line's ends by a letter height
    (where the line meets the lines it runs between).  Its own point alone where it names a point."""
    if anchor.along is None:
        return np.array([anchor.at], dtype=float)
    start, end = np.asarray(anchor.along, dtype=float)
    length = math.hypot(*(end - start))
    if length <= 2 * anchor.size:
        return np.array([anchor.at], dtype=float)
    unit = (end - start) / length
    here = float(np.dot(np.asarray(anchor.at) - start, unit))
    steps = np.arange(1, int(SLIDE / SLIDE_STEP) + 1) * SLIDE_STEP * anchor.size
    along = np.ravel(np.column_stack((here + steps, here - steps)))
    along = along[(along >= anchor.size) & (along <= length - anchor.size)]
    return np.concatenate(([anchor.at], start + along[:, None] * unit))


def _kept_off(anchor: Anchor, boxes: np.ndarray, led: np.ndarray) -> np.ndarray:
    """Whether each spot ((xmin, ymin, xmax, ymax) rows; ``led``: those on a leader from the anchor's point) stands in
    the reach of the anchor's ``keep_off`` point: its box nearer than the distance, or its leader starting there (a
    name led out of the reach from a point within it still reads among the names there)."""
    if anchor.keep_off is None:
        return np.zeros(len(boxes), dtype=bool)
    point, distance = anchor.keep_off
    within = _box_distances(boxes, np.array([point], dtype=float))[:, 0] < distance
    return within | (led & (math.dist(anchor.at, point) < distance))


# The two below are the same for every label of every drawing: remembered, read-only, for the thousand labels a run
# places.
@functools.cache
def _turns(directions: int) -> np.ndarray:
    """The steps of a full turn / ``directions`` from the preferred direction, in the order the spots are tried:
    nearest first, each way."""
    half = directions // 2
    turns = np.array([0, *(turn for step in range(1, half) for turn in (step, -step)), half])
    turns.flags.writeable = False
    return turns


@functools.cache
def _rings_and_orders(rings: int, directions: int) -> tuple[np.ndarray, np.ndarray]:
    """The ring and the place in :func:`_turns`' order of each of the ``rings`` × ``directions`` spots, ring by ring."""
    ring, order = np.divmod(np.arange(rings * directions), directions)
    ring.flags.writeable = False
    order.flags.writeable = False
    return ring, order


def open_direction(at: tuple[float, float], items: Sequence[Primitive], default: float = math.pi / 4,
                   reach: float = 0.3) -> float:
    """The direction (radians) from ``at`` into the widest gap between the lines drawn from it.

    Every segment of a polyline or arrow that ends at ``at`` (within
    ``reach`` mm) leaves it in one direction; one that passes through it
    leaves in two.  A label put in the middle of the widest gap sits clear
    of them all, as a draughtsman puts a letter in the open angle.
    """
    directions: list[float] = []
    x, y = at
    for item in items:
        if isinstance(item, Arrow):
            segments = [(item.start, item.end)]
        elif isinstance(item, Polyline):
            points = item.points + ((item.points[0],) if item.closed else ())
            segments = list(itertools.pairwise(points))
        else:
            continue
        for (x0, y0), (x1, y1) in segments:
            dx, dy = x1 - x0, y1 - y0
            length2 = dx * dx + dy * dy
            if length2 <= reach * reach:
                continue
            t = ((x - x0) * dx + (y - y0) * dy) / length2
            t = min(1.0, max(0.0, t))
            if math.hypot(x0 + t * dx - x, y0 + t * dy - y) > reach:
                continue
            if math.hypot(x1 - x, y1 - y) > reach:
                directions.append(math.atan2(y1 - y, x1 - x))
            if math.hypot(x0 - x, y0 - y) > reach:
                directions.append(math.atan2(y0 - y, x0 - x))
    if not directions:
        return default
    directions.sort()
    gaps = [(directions[(k + 1) % len(directions)] - d) % (2 * math.pi) or 2 * math.pi
            for k, d in enumerate(directions)]
    widest = max(range(len(gaps)), key=lambda k: (round(gaps[k], 9), -k))
    return directions[widest] + gaps[widest] / 2


def place_breaking_thin_lines(anchors: list[Anchor], every: list[Primitive], drawn: list[Primitive],
                              inked: list[Primitive], ink: list[BaseGeometry], number_leaders: list[Polyline],
                              numbers: list[Text], pins: list[BaseGeometry],
                              links: Sequence[BaseGeometry] = ()) -> tuple[Placement, list[Text]]:
    """The labels placed clear of the drawn lines, and those of them that the thin lines ``every`` break under
    (:func:`broken_under`): the plan of positions' letters and numbers (``every``: the other positions' thin
    outlines and the points' paths) and the plan sheet's mechanism's (the frame's hatching and guides, the run-on
    lines to Assur's points).

    The ``inked`` lines among ``drawn`` (the extremes or the links, the springs and cylinders, the travel's dimension,
    and the frame's symbols, whose thin hatching is never broken under a label either) are kept clear of as wide as
    their strokes draw them (``ink``, :func:`ink_of`), as the numbers round the crank's circle are: clear of their
    middles alone, the Scotch yoke's A′ stood 0.2 mm into the ink of the 0.7 mm block round its top pin, S4 half a
    millimetre into its 1 mm rod, the engine's O on its pivot's hatching, and the slotted lever's A on its block's
    outline.  A leader is kept from running beside a line, nearly along it (``place_labels``' ``leaders_apart``): the
    slider driven mechanism's G was led down beside a stroke of its guide's hatching, reading as one more, and a
    crank's pivot O led off along the thin lines of the crank's positions.  The labels of one point (a crowded crank
    pin's number and its primed letters) then stand each in a direction of its own from it
    (:func:`_each_in_its_own_direction`); ``numbers`` stand already, ``number_leaders`` and ``pins`` (grown) are kept
    clear of.

    Where the thin lines leave no clear spot near a point (the crank's pivot, that every crank position's line
    leaves; a swing's ψ on its arc, across the rocker's positions; a centre of mass among the links' thin
    outlines), a draughtsman letters it beside its point all the same, clear of the bold lines and the frame's
    symbols, and breaks the thin lines under the letters, as ГОСТ 2.307 breaks thin lines under a dimension's
    number: set farther out on a leader it was read as naming something else.  Those labels are placed again
    without the thin lines, then the rest round them; their leaders, which the thin lines are not broken under, kept
    from running beside those lines all the same (the Scotch yoke's O was led out along the thin line of a position
    of its rod).

    ``links`` are the links' lines as inked (not among ``ink``), which a leader crosses only where no spot near its
    point lets it keep off them (``place_labels``' ``shafts``): a letter led across a link reads as naming a point of
    that link, as the triad's O, led up over the coupler that passes just above the crank's pivot, did.  They stand
    first among the obstacles, numbered so for the anchors' ``own_lines``: those of the point's own link it crosses as
    any line."""
    links = list(links)
    crossed = [True] * len(links)
    obstacles = links + obstacles_of(without(drawn, inked) + number_leaders) + ink + pins
    first = _each_in_its_own_direction(
        remembered(place_labels, anchors, obstacles, standing=numbers, reach_farther=False, leaders_apart=True,
                   shafts=crossed),
        anchors, obstacles, numbers, crossed)
    lines = [shape for shape in obstacles_of(drawn + number_leaders + list(first.leaders))
             if shape.geom_type == "LineString"]
    tree = STRtree(lines)
    breaking = [index for index, text in enumerate(first.texts)
                if len(tree.query(text_box(text), predicate="intersects"))]
    if not breaking:
        return first, []
    over = remembered(place_labels, [anchors[index] for index in breaking],
                      links + obstacles_of(without(drawn, breakable(every) + inked) + number_leaders) + ink + pins,
                      standing=numbers, leaders_apart=obstacles_of(breakable(every)), shafts=crossed)
    rest = [index for index in range(len(anchors)) if index not in breaking]
    others = remembered(place_labels, [anchors[index] for index in rest],
                        obstacles + obstacles_of(list(over.leaders)), standing=[*numbers, *over.texts],
                        leaders_apart=True, shafts=crossed)
    texts = dict(zip(breaking, over.texts)) | dict(zip(rest, others.texts))
    return Placement(tuple(texts[index] for index in range(len(anchors))), over.leaders + others.leaders), \
        list(over.texts)


# Two labels of one point stand apart, seen from it, by this many of their letters' heights: the line from the point
# to one (its leader, or where a leader would run) keeps this far from the other.
_SIGHT_CLEARANCE = 1.0
# How far out the shadow of a label reaches from its point (mm), seen from which another label would stand behind it.
_SHADOW_MM = 60.0


def _each_in_its_own_direction(placement: Placement, anchors: list[Anchor], obstacles: list[BaseGeometry],
                               standing: list[Text], shafts: Sequence[bool] = ()) -> Placement:
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
                               reach_farther=False, leaders_apart=True, shafts=shafts)
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
    seen = shapely.Point(point)
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
    ends = [leader for leader in leaders if shapely.Point(leader.points[-1]).distance(box) < 2 * LEADER_GAP]
    return ends[0] if ends else None


def without(items: list[Primitive], left_out: list[Primitive]) -> list[Primitive]:
    """``items`` but those of ``left_out`` (the same objects): the drawing's solid lines without its thin ones."""
    out = {id(item) for item in left_out}
    return [item for item in items if id(item) not in out]


def breakable(items: list[Primitive]) -> list[Polyline]:
    """The lines of ``items`` that a label may break: open or unfilled outlines (not a slider's block)."""
    return [item for item in items if isinstance(item, Polyline) and not item.fill and len(item.points) >= 2]
