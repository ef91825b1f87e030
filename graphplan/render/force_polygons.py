"""The force polygons on the force sheet: each group's polygon at its own μF, to the right of the group cut free.

The known vectors head to tail, the two closing lines of action thin and
dashed beyond their crossing, the closing vectors, the inner reaction
dashed and each reaction found drawn whole.  A polygon that the record
closes twice (the lever and the block of an RPR group) is drawn as two
polygons side by side.  Two sides on one line are set side by side
(:func:`_side_by_side`); a side's name that finds no spot off the others is
set on a short leader out of the sliver of sides (:func:`_sliver_spot`), or
left to the caption, which tells the side by the one it starts from
(:func:`_unnamed_vector`).
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import replace

import numpy as np
import shapely
from shapely.geometry import LineString
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from ..forces import ForcePlan, GroupForces, PolygonVector
from ..geometry import Line
from ..locale import load_symbol, load_symbols_in
from ..memo import OwnedMemo
from ..rounding import ROUNDING_NOISE
from ..scales import finer_standard_scale, format_scale
from .force_marks import (
    ACTION_RUN_ON,
    NAME_SIZE,
    ForceSheet,
    direction_rad,
    group_id,
    label_on_a_line,
    led_from,
    letters_placed,
    short_run_on,
    whole_reaction,
    wrapped,
)
from .force_rows import CAPTION_WIDTH_MM, Drawing
from .labels import (
    LEADER_CLEARANCE,
    LEADER_GAP,
    LEADER_WIDTH,
    Anchor,
    Placement,
    obstacles_of,
    set_out,
    spaced_box,
    text_box,
)
from .numerals import significant
from .plans import CAPTION_SIZE, RUN_ON_MM, ZERO_MM, too_short_lines
from .primitives import (
    Arrow,
    Circle,
    Layer,
    Polyline,
    Primitive,
    Stroke,
    Text,
    bounds_of,
    dot_marker,
    moved_layers,
    svg_id,
    text_width,
)
from .primitives import to_complex as _c
from .primitives import to_xy as _xy

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

_KNOWN = Stroke(0.5)
_CLOSING = Stroke(0.55, "#a83a1f")
_INNER = Stroke(0.45, "#a83a1f", (3.0, 1.5))
_WHOLE = Stroke(0.35, "#1f5fa8")
_ACTION = Stroke(0.25, "#333333")

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


def polygons_drawing(sheet: ForceSheet, group: GroupForces) -> Drawing:
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
                                 _wholes(group, chain, scale), text)
        unnamed += [_unnamed_vector(vector, chain, scale, text) for vector in left]
        x0, _, x1, _ = bounds_of(item for layer in drawing for item in layer.items)
        layers.extend(moved_layers(drawing, cursor - x0, 0.0))
        cursor += x1 - x0 + POLYGON_GAP_MM
    short = [f"{load_symbol(vector.name, text)} = {significant(abs(vector.force))} {text['newton']}"
             for vector in group.polygon.vectors if too_short_to_draw(vector.force, scale)]
    apart = too_short_lines(short, text, CAPTION_WIDTH_MM)
    # One a line: broken where it runs over the polygon's width, a sum broke before its "+ R14n".
    told = wrapped(unnamed, per_line=1)
    under = [text["polygon_unnamed"].format(sides=told[0]), *told[1:]] if told else []
    caption = (text["force_polygon_title"], *(load_symbols_in(equation, text) for equation in group.polygon.equations),
               *_sums(group, text),
               text["force_scale"].format(value=format_scale(scale)), *apart, *under)
    return Drawing(f"polygon-{key}", layers, caption, run_on=short_run_on(short, apart, text, after=len(under)))


def _sums(group: GroupForces, text: Mapping[str, str]) -> list[str]:
    """``ΣF2 = R32``, ``ΣF4 = G4 + Fu4 + R54``: what each ΣF of the polygon's equations that holds a reaction lays
    off, as the note gives every ΣF after the same equations.  A ΣF sums the reactions later groups hand back to its
    link with the link's own loads: the crank-rocker's "ΣF2 + R12 = 0" alone named no R32, which its polygon draws
    beside R12.  A ΣF of the link's own loads alone (G3, Fu3, which the polygon names where it draws them) is read
    as the groups' equations have always been read: spelt out too, it took the double rocker's tight A2 force sheet
    a line more and a sheet more.

    As many sums a line as the equations' width holds at the usual lettering, so that a line breaks between sums,
    not inside one, and the sums widen no field: at the least caption width the Scotch yoke's group polygon widened
    its row, which an A2 no longer held across.  Symbols alone, they are set off by the Latin semicolon in every
    language, as a Chinese caption's lines without Chinese words are."""
    sums = []
    for link in dict.fromkeys(int(found) for found in re.findall(r"ΣF(\d+)", group.polygon.equation)):
        names = [load_symbol(load.name, text) for load in group.loads
                 if load.link == link and load.is_force and load.force != 0]
        # A reaction, R32 of link 3 on link 2, is the one force of a ΣF that comes from another link through a pair.
        if any(name.startswith("R") for name in names):
            sums.append(f"ΣF{link} = {' + '.join(names)}")
    if not sums:
        return []
    reach = min(max(text_width(load_symbols_in(equation, text), CAPTION_SIZE) for equation in group.polygon.equations),
                CAPTION_WIDTH_MM)
    lines: list[str] = []
    for item in sums:
        if lines and text_width(f"{lines[-1]}; {item}", CAPTION_SIZE) <= reach:
            lines[-1] += f"; {item}"
        else:
            lines.append(item)
    return [f"{line};" for line in lines[:-1]] + lines[-1:]


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
             wholes: Sequence[PolygonVector], text: Mapping[str, str]) -> tuple[list[Layer], list[PolygonVector]]:
    """One closed polygon: its lines of action, its vectors as arrows, each named beside its middle (as ``text``'s
    locale writes the name) but those left unnamed, which are handed back for the caption to say."""
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
            actions.append(Polyline((_xy(through - RUN_ON_MM * unit), _xy(through + RUN_ON_MM * unit)), ACTION_RUN_ON))
            continue
        onward = (crossing - through) / abs(crossing - through)
        actions.append(Polyline((_xy(through), _xy(crossing)), _ACTION))
        actions.append(Polyline((_xy(crossing), _xy(crossing + RUN_ON_MM * onward)), ACTION_RUN_ON))
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
        anchors.append(Anchor(_xy(centre), load_symbol(vector.name, text), NAME_SIZE, direction_rad(across),
                              arrow.stroke.colour,
                              along=(arrow.start, arrow.end)))
    # A name led across another vector's arrow reads as naming that one, as it does on the lever (or on a line, as
    # one lying there would): where the placer finds it no other spot (a sliver of sides side by side), the arrow is
    # left unnamed, one at a time, and the caption says which it is, as the lever's does (the placer still leads one
    # across an arrow where that is all that keeps it off a line, which is no better here).  A whole reaction, which
    # the student reads off the polygon, is never left unnamed: the components and given loads whose names crowd it
    # go first, and where none is left to go it keeps its leader (whole_reaction).  Before either, a name is set on a
    # short leader across the sides side by side with its own, where one reaches out of the sliver (_sliver_spot).
    drawn_lines = obstacles_of([item for item in figure if not isinstance(item, Circle)])
    drawn = obstacles_of(figure)
    shafts = [LineString((arrow.start, arrow.end)) for _, arrow in named]
    # By the name as lettered, which the anchors carry: a locale's symbol (Fи4 in Russian) is not the vector's Fi4.
    shaft_of = {anchor.text: shaft for anchor, shaft in zip(anchors, shafts)}
    vector_of = {id(anchor): vector for anchor, (vector, _) in zip(anchors, named)}
    unnamed: list[Anchor] = []
    kept: list[Anchor] = []
    # Names set on a short leader across the sides side by side with their own (_sliver_spot), which the others are
    # lettered round.
    set_by: list[tuple[Anchor, Text, Polyline]] = []
    while True:
        standing = [item for _, text, leader in set_by for item in (text, leader)]
        labels = letters_placed(anchors, [*figure, *standing], unnamed=[*unnamed, *(anchor for anchor, _, _ in set_by)])
        on_a_line = [anchor for anchor, placed in zip(anchors, labels.texts) if anchor not in kept
                     and label_on_a_line(anchor, placed, drawn_lines, labels.leaders,
                                    _crossed_apart(anchor, placed, labels.leaders, shafts))]
        # A whole reaction's name whose nearest arrow is another's reads as naming that one: it is set again where
        # a spot is found (_sliver_spot), but other names go for it only where it lies on a line.
        lying = on_a_line + [anchor for anchor, placed in zip(anchors, labels.texts)
                             if anchor not in kept and anchor not in on_a_line and whole_reaction(anchor.text)
                             and not _reads_as_own(anchor, placed, labels.leaders, shaft_of)]
        if not lying:
            break
        first = min(lying, key=lambda anchor: not whole_reaction(anchor.text))
        placed = labels.texts[anchors.index(first)]
        own = _own_leaders(first, placed, labels.leaders)
        spot = _sliver_spot(first, drawn, [text for anchor, text in zip(anchors, labels.texts) if anchor is not first]
                            + [text for _, text, _ in set_by],
                            [leader for leader in labels.leaders if leader not in own]
                            + [leader for _, _, leader in set_by], shaft_of)
        gone = first
        if spot is not None:
            set_by.append((first, *spot))
        elif not whole_reaction(first.text):
            unnamed.append(first)
        elif first not in on_a_line:
            kept.append(first)
            continue
        else:
            box = text_box(placed)
            crowding = sorted((anchor for anchor, text in zip(anchors, labels.texts)
                               if not whole_reaction(anchor.text) and text_box(text).distance(box) < CROWDING_MM),
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
        return f"{vector.name} = {parts[0].name} + {parts[1].name}"  # a reaction's, named alike in every locale
    sides = [side for side in chain if side.role != "inner" and side is not vector
             and not too_short_to_draw(side.force, scale)]
    before = min(sides, key=lambda side: abs(side.end - vector.start), default=None)
    name = load_symbol(vector.name, text)
    return name if before is None else text["polygon_side_from"].format(name=name,
                                                                         before=load_symbol(before.name, text))


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
            if led_from(leader, anchor) and box.distance(ShapelyPoint(leader.points[-1])) < 0.5]


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
    if not whole_reaction(anchor.text):
        # Where no short leader reaches out of a sliver, a leader that crosses nothing may be longer, and the name
        # may stand off the side obliquely or by its ends: the offset slider-crank's R23n at position 10, led 10 mm
        # across R23 and R14's line at b76b78f, stood so right of its head, beyond G3's name, at 3.2 mm (at 3.5 mm
        # the gap there is too narrow, and the caption tells it).
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
    # The three choices on a whole leader go through the same spots: worked out once, as the first asks for them.
    whole_leader_spots = itertools.tee(_sliver_spots(anchor, drawn, texts, leaders, WHOLE_LEADER_MM), 3)
    for spots, fits in ((_sliver_spots(anchor, drawn, texts, leaders, SLIVER_LEADER_MM),
                         lambda text, leader: _reads_as_own(anchor, text, [], shaft_of)),
                        (whole_leader_spots[0], lambda text, leader: nearest_box(text) in own
                         and _reads_as_own(anchor, text, [leader], shaft_of)),
                        (whole_leader_spots[1], lambda text, leader: _side_by_side_with(anchor, shaft_of[nearest_box(text)])
                         and _reads_as_own(anchor, text, [leader], shaft_of)),
                        (whole_leader_spots[2], lambda text, leader: _reads_as_own(anchor, text, [leader], shaft_of))):
        spot = next((spot for spot in spots if fits(*spot)), None)
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
    points, outs = [], []
    for share in shares:
        point = start + (end - start) * share
        for side in sides:
            points.append(point)
            outs.append(side * (end - start) / abs(end - start))
    point_x, point_y = np.array([point.real for point in points]), np.array([point.imag for point in points])
    reaches = np.arange(LEADER_CLEARANCE + LEADER_GAP + 0.2, longest + 2 * anchor.size, 0.2)[:, None]
    # Every spot at every reach (a row a reach), set out as the placer sets a box out from its point
    # (labels._candidates: its near edge ``reach`` off), its box as text_extent has it, and the nearest point of the
    # box to its point, all at once: the leader's length decides most spots, before any shape is made.
    x, y = set_out(point_x, point_y, np.array([out.real for out in outs]), np.array([out.imag for out in outs]),
                   reaches, width / 2, anchor.size)
    x0 = x + -width / 2
    extents = np.stack((x0, y - 0.3 * anchor.size, x0 + width, y + 1.15 * anchor.size), axis=-1)
    near_x = np.minimum(np.maximum(point_x, extents[..., 0]), extents[..., 2])
    near_y = np.minimum(np.maximum(point_y, extents[..., 1]), extents[..., 3])
    reaches_to_box = np.hypot(near_x - point_x, near_y - point_y)
    long_enough = ((LEADER_CLEARANCE + LEADER_GAP + SLIVER_LEADER_LEAST_MM <= reaches_to_box)
                   & (reaches_to_box <= longest + LEADER_CLEARANCE + LEADER_GAP + 1e-9))
    for row in range(len(reaches)):
        # The boxes of one reach asked of the tree at once.
        kept = np.flatnonzero(long_enough[row])
        if not len(kept):
            continue
        blocked = set(box_blockers.query(shapely.box(*extents[row, kept].T), predicate="intersects")[0].tolist())
        spots = [(points[k], (float(x[row, k]), float(y[row, k])), complex(near_x[row, k], near_y[row, k]),
                  float(reaches_to_box[row, k])) for index, k in enumerate(kept.tolist()) if index not in blocked]
        if not spots:
            continue
        # Each spot's leader, and the line from its point to its box, made and asked of the trees for the reach at once.
        towards = [(near - point) / reach_to_box for point, _, near, reach_to_box in spots]
        leaders = shapely.linestrings([(_xy(point + toward * LEADER_CLEARANCE), _xy(near - toward * LEADER_GAP))
                                       for (point, _, near, _), toward in zip(spots, towards)])
        # Run on to the box: an arrow in the gap between the leader's end and the letters reads as crossed.
        reaching = shapely.linestrings([(_xy(point), _xy(near)) for point, _, near, _ in spots])
        crossed = set(led.query(leaders, predicate="intersects")[0].tolist()) | set(
            uncrossable.query(reaching, predicate="intersects")[0].tolist())
        too_long = shapely.length(leaders) >= longest
        for index, ((point, at, near, _), toward, leader) in enumerate(zip(spots, towards, leaders)):
            if too_long[index] or index in crossed:
                continue
            # Off the side's own shapes (its shaft, head and line) the leader, run on to the box, meets nothing, and
            # it runs along no other line: its middle stands as far off them as two sides set side by side.
            if clear and (_meets(shape_tree, LineString((_xy(point + toward * LEADER_CLEARANCE), _xy(near))))
                          or (shapely.distance(leader.interpolate(0.5, normalized=True),
                                               shapes[shapely.distance(ShapelyPoint(_xy(point)), shapes) > ZERO_MM])
                              < SIDE_BY_SIDE_MM).any()):
                continue
            yield (Text(at, anchor.text, anchor.size, "middle", anchor.colour),
                   Polyline(tuple(leader.coords), Stroke(LEADER_WIDTH, anchor.colour)))


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
