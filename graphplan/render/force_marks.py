"""What the force sheet's drawings share: the sheet's record, the strokes and sizes of its forces, its lettering.

The groups cut free (:mod:`graphplan.render.force_bodies`), their force
polygons (:mod:`graphplan.render.force_polygons`) and Zhukovsky's lever
(:mod:`graphplan.render.force_lever`) each read the :class:`ForceSheet`
and draw with what is here: forces as arrows at a standard scale that draws
the largest about a quarter of the drawing's size (:func:`arrow_scale`),
never shorter than :data:`LEAST_ARROW_MM`, a rounding error's not at all
(:func:`graphplan.forces.negligible`), two at one point on one line one beyond the other
(:func:`unstacked`), an arm as the perpendicular from its centre to the
force's line (:func:`arm_with_run_on`); names placed clear of the figure
(:func:`letters_placed`) and the tests of whether one reads as naming what it
should (:func:`label_on_a_line`, :func:`led_from`); the captions' values
listed a few to a line (:func:`wrapped`) and the balancing load's line
(:func:`balancing_line`).
"""

from __future__ import annotations

import math
import re
import unicodedata
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union

from ..forces import ForcePlan
from ..geometry import perpendicular_foot
from ..joint_friction import FrictionPair
from ..lever import Lever
from ..mechanism import Mechanism
from ..memo import RecentMemo
from ..motion import Motion
from ..plans import Plan
from ..scales import format_scale, standard_scale
from ..wording import balancing_symbol
from . import lettering
from .force_rows import RunOn
from .labels import (
    Anchor,
    Placement,
    ink_of,
    obstacles_and_shafts,
    place_labels,
    remembered,
    shapes_digest,
    text_box,
)
from .numerals import scale_factor, significant
from .plans import CAPTION_SIZE, ZERO_MM
from .primitives import Arrow, Polyline, Primitive, Stroke, Text, bounds_of, svg_id
from .primitives import to_complex as _c
from .primitives import to_xy as _xy

# The longest force arrow on a group cut free and on the lever (mm): the panel's force scale is the
# standard one that draws the largest force about a quarter of the drawing's size, within these bounds.
LONGEST_ARROW_MM = (25.0, 50.0)
ARROW_SHARE = 0.25
# No force arrow on a group or on the lever is drawn shorter than this (mm), so that its head and
# its direction read; the caption says so.
LEAST_ARROW_MM = 10.0
# A load whose arrow would run this far (mm), and this share of its length, within a bar of the drawn links
# either way from its point lies along its link (a long arrow leaving its link at a small angle reads well);
# it is drawn this far beside its line instead, tied to its point by a thin leader.
ALONG_BAR_MM = 4.5
ALONG_BAR_SHARE = 0.4
BESIDE_MM = 2.5
# How many values a caption line lists before it wraps.
PER_LINE = 4
# Between the values a caption line lists: a comma and two spaces, so that a value with a comma of its own (fE =
# 0.1, φ = …) reads as one.  A line of symbols and numbers alone takes it in every language.
VALUE_SEPARATOR = ",  "
# The heights of the letters of points, of the names of forces and of the arms' names (mm, render/lettering.py).
POINT_SIZE = lettering.LETTER
NAME_SIZE = lettering.NAME
ARM_NAME_SIZE = lettering.ARM_NAME

LOAD = Stroke(0.45)
BALANCING = Stroke(0.6, "#1f7a3a")
ACTION_RUN_ON = Stroke(0.25, "#333333", (2.5, 1.5))
ARM = Stroke(0.2, "#555555")
_ARM_RUN_ON = Stroke(0.2, "#555555", (1.5, 1.0))


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
    (:func:`~graphplan.render.force_lever.enlarged_lever_scale`), smaller where a small sheet needs it;
    ``caption_size`` the height of the captions' letters (mm), smaller on a small sheet.
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
        return self.text["velocity_scale"].format(value=written_lever_scale(self.lever_scale, self.velocity.scale))


def written_lever_scale(scale: float, plan_scale: float) -> str:
    """μV a lever drawn at ``scale`` is written at on its force sheet: its velocity plan's ``plan_scale`` as the plan
    writes it (0.07854), a standard scale of its own whole (0.04); the note writes a lever's μV as the sheet it
    tells of does."""
    return scale_factor(scale) if scale == plan_scale else format_scale(scale)


def draws_larger(scale: float, than: float) -> bool:
    """Whether the scale factor ``scale`` draws larger than ``than``, by more than rounding."""
    return scale < than * (1.0 - 1e-9)


# How many grown unions :func:`grown_union` keeps, the least recently asked given up first.
GROWN_KEPT = 512
_grown_unions: RecentMemo[BaseGeometry] = RecentMemo()


def grown_union(lines: Sequence[LineString], distance: float) -> BaseGeometry:
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


def points_onto(start: complex, end: complex, point: complex) -> bool:
    """Whether the arrow from ``start`` to ``end`` points onto ``point``, its head the nearer end."""
    return abs(end - point) < abs(start - point)


def unstacked(start: complex, end: complex, point: complex, arrows: Sequence[Primitive]) -> tuple[complex, complex]:
    """The arrow moved on along its own line, away from its point, until it covers no arrow drawn before.

    Two forces at one point in one direction (a weight and a load on a
    slider) would be drawn one over the other; moved along its line of
    action, the second stands beyond the first and keeps its line.
    """
    unit = (end - start) / abs(end - start)
    away = -unit if points_onto(start, end, point) else unit

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


def arm_with_run_on(centre: complex, start: complex, end: complex, unit: complex) -> list[Primitive]:
    """The arm from ``centre`` to the line of the arrow ``start``→``end``, and the line run on to its foot."""
    foot = perpendicular_foot(centre, start, unit)
    items: list[Primitive] = [Polyline((_xy(centre), _xy(foot)), ARM)]
    along = ((foot - start) * unit.conjugate()).real
    length = abs(end - start)
    if along < -ZERO_MM:
        items.append(Polyline((_xy(start), _xy(foot)), _ARM_RUN_ON))
    elif along > length + ZERO_MM:
        items.append(Polyline((_xy(end), _xy(foot)), _ARM_RUN_ON))
    return items


def short_run_on(values: Sequence[str], apart: Sequence[str], text: Mapping[str, str], after: int = 0) -> RunOn | None:
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


def whole_reaction(name: str) -> bool:
    """Whether ``name`` is a whole reaction's (R23, R43), which a student reads off the polygon, not a component's
    (R23n, R23τ) or a given load's (G3, Fu3), steps of the construction its caption may tell."""
    return re.fullmatch(r"R\d+", name) is not None


def letters_placed(anchors: Sequence[Anchor], figure: Sequence[Primitive],
              reach_farther: bool | Sequence[bool] = True, unnamed: Sequence[Anchor] = (),
              shafts_inked: bool = False, inked: Sequence[Primitive] = ()) -> Placement:
    """The labels of ``anchors`` placed clear of the figure and of every anchor's own spot, and of the spots of the
    ``unnamed`` (a lever's arrows whose names are given under it); ``shafts_inked``, clear of the arrows' shafts as
    wide as they are drawn, not their middles alone; clear of the items of the figure ``inked`` as wide as they are
    drawn too (:func:`graphplan.render.labels.ink_of`).

    A label covering another one's anchor (the tail of a moment's arc)
    would leave that one no room beside it, so the anchors count as points.
    """
    # The discs of shapely's Point.buffer (16 segments a quarter), made at once.  An arrow left unnamed keeps its head:
    # a name placed again over it (G2 on Fu3's head, the lift's friction lever of position 9) reads as its.
    centres = np.reshape([anchor.at for anchor in [*anchors, *unnamed]], (-1, 2))   # (0, 2) with no names
    spots = list(shapely.buffer(shapely.points(centres), 0.8, quad_segs=16))
    # A leader across an arrow reads as part of it, or as naming its load: the placer costs it as two leaders crossing.
    obstacles, shafts = obstacles_and_shafts(figure, shafts_inked)
    ink = ink_of(inked)
    return remembered(place_labels, anchors, obstacles + ink + spots, reach_farther=reach_farther,
                      shafts=shafts + [False] * len(ink))


def label_on_a_line(anchor: Anchor, text: Text, lines: Sequence[BaseGeometry], leaders: Sequence[Polyline],
               shafts: Sequence[BaseGeometry] = ()) -> bool:
    """Whether the placed label of ``anchor`` lies on one of the drawn ``lines`` or on another label's leader (its
    own starts by its point), or is led to across one of the ``shafts`` (the loads' arrows)."""
    box = text_box(text)
    # Asked of every label of a sheet, against every line and leader: the leaders' own ones found once, the lines met
    # in one call.
    along = None if anchor.along is None else LineString(anchor.along)
    its_own = [_led_from(leader, anchor.at, along) for leader in leaders]
    others = [LineString(leader.points) for leader, own in zip(leaders, its_own, strict=True) if not own]
    met = [*lines, *others]
    if met and shapely.intersects(box, np.array(met, dtype=object)).any():
        return True
    # Its own leader: from by its point to by its box (the placer stops it short of the box).  Across an arrow it
    # reads as part of that arrow, or as naming that load, as a name on a line reads as naming the line.
    own = [LineString(leader.points) for leader, mine in zip(leaders, its_own, strict=True) if mine
           and box.distance(ShapelyPoint(leader.points[-1])) < 0.5]
    return any(leader.intersects(shaft) for leader in own for shaft in shafts)


def led_from(leader: Polyline, anchor: Anchor) -> bool:
    """Whether ``leader`` is the one led from ``anchor``'s point: a placed leader starts by the point it names, or by
    another point of the line it names (its ``along``: a polygon's side's name led from a clear stretch of it)."""
    return _led_from(leader, anchor.at, None if anchor.along is None else LineString(anchor.along))


def _led_from(leader: Polyline, at: tuple[float, float], along: LineString | None) -> bool:
    """:func:`led_from`, the ``along`` line made by the caller."""
    start = leader.points[0]
    if math.dist(start, at) <= 1.0:
        return True
    return along is not None and along.distance(ShapelyPoint(start)) <= 1.0


def arrow_scale(forces: Sequence[complex], figure: Sequence[Primitive]) -> float:
    """The standard force scale (N/mm) that draws the largest of ``forces`` about a quarter of the figure's size."""
    largest = max((abs(force) for force in forces), default=0.0)
    x0, y0, x1, y1 = bounds_of(figure)
    longest = min(max(ARROW_SHARE * max(x1 - x0, y1 - y0), LONGEST_ARROW_MM[0]), LONGEST_ARROW_MM[1])
    return standard_scale(largest / longest) if largest > 0 else 1.0


def balancing_line(sheet: ForceSheet, value: float, how: str, named: bool = True) -> str:
    """The balancing load found ``how``, with its words (``balancing moment Mb = …``) or, not ``named``, its
    symbol alone."""
    text = sheet.text
    name, unit = balancing_symbol(sheet.mechanism, text)
    what = text["balancing_moment" if sheet.mechanism.driver.kind == "crank" else "balancing_force"] if named else ""
    return text[how].format(what=what, name=name, value=significant(value), unit=unit).strip()


def wrapped(items: Sequence[str], per_line: int = PER_LINE) -> list[str]:
    """Values listed ``per_line`` to a caption line, each line but the last ending in the comma between values.

    Without it the lever's fifth arm ran on from the fourth as one value: "h18 = 0.2587 mm" over "h19 = 21.21 mm",
    where a line the caption breaks keeps its comma ("R45 = 2141 N," over "R16 = 362.5 N")."""
    lines = [VALUE_SEPARATOR.join(items[k:k + per_line]) for k in range(0, len(items), per_line)]
    return [line + VALUE_SEPARATOR.rstrip() for line in lines[:-1]] + lines[-1:]


def sign_mark(value: float) -> str:
    return "−" if value < 0 else "+"


def direction_rad(value: complex) -> float:
    return math.atan2(value.imag, value.real)


def group_id(label: str) -> str:
    """The svg id of a group: ``II(3,4)`` → ``II-3-4``."""
    return svg_id(label).strip("-")
