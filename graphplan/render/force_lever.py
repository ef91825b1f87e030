"""Zhukovsky's lever on the force sheet: the velocity plan turned 90° clockwise, the loads at their points' images.

The last row of the force sheet: the velocity plan turned about its pole,
the loads at the images of their points with their arms from the pole, the
balancing force at the driver's image, and the equation of moments about
the pole that finds it.  Where the plan's points crowd round the pole the
lever is drawn larger than the plan (:func:`enlarged_lever_scale`): a
similar figure at any scale gives the same balancing load.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence

from shapely.geometry import LineString, MultiPoint
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry.base import BaseGeometry

from ..forces import negligible
from ..geometry import perpendicular_foot
from ..lever import BALANCING_ARM, BALANCING_FORCE, Lever, LeverTerm, turned
from ..locale import load_symbol
from ..memo import OwnedMemo
from ..plans import Plan
from ..scales import fit_scale, format_scale
from .force_marks import (
    ALONG_BAR_MM,
    ARM,
    ARM_NAME_SIZE,
    BALANCING,
    BESIDE_MM,
    LEAST_ARROW_MM,
    LOAD,
    NAME_SIZE,
    POINT_SIZE,
    ForceSheet,
    arm_with_run_on,
    arrow_scale,
    balancing_line,
    direction_rad,
    draws_larger,
    grown_union,
    label_on_a_line,
    led_from,
    letters_placed,
    points_onto,
    short_run_on,
    sign_mark,
    unstacked,
    wrapped,
)
from .force_rows import CAPTION_WIDTH_MM, Drawing
from .labels import LABEL_GAP_MM, LEADER_WIDTH, LED_SHARES, Anchor, obstacles_of, open_direction, text_box
from .numerals import significant
from .plans import ZERO_MM, too_short_lines
from .plans import _coincident as coincident_letters
from .primitives import Arrow, Circle, Layer, Polyline, Primitive, Stroke, Text, dot_marker, svg_id
from .primitives import to_xy as _xy

# On the lever a load set beside stands by another load's arrow parallel to it at the same point (two couples' forces
# at one end of their link: Mf14″ and Mf34″ at b), their heads level: this far apart (mm) each head has its name
# beside it (a name's box is 4.6 mm high, kept 0.8 mm off another's), where at BESIDE_MM the two arrows read as one
# and one name stood by the other's head.
LEVER_BESIDE_MM = 6.0
# How far ahead along its line (mm) a load set beside on a slant stands (:func:`_pushing_or_pulling`): its leader,
# LEVER_BESIDE_MM long, leaves the point some 30° ahead of square to the line, and the arrow stands 5.2 mm beside
# its line, as far apart as a name by each of two heads needs.
SLANT_AHEAD_MM = 3.0
# The lever's field on a force sheet, which its layers are named after (lever-plan, lever-arm-G3): a course sheet
# tells the part that holds the lever by them.
LEVER_FIELD = "lever"
# A load's arrow on the lever passes no other point's dot nearer than this (mm) where another way of drawing it
# passes none: a head by another point reads as a load at that point.
POINT_CLEAR_MM = 2.5
# An arm on the lever whose name would stand nearer the pole than this (mm) is not lettered.
POLE_CLEAR_MM = 10.0

_LEVER = Stroke(0.6)
_RAY = Stroke(0.25, "#555555")


def _pushing_or_pulling(at: complex, vector: complex, arrows: Sequence[Primitive],
                        lines: Callable[[], BaseGeometry],
                        others: Sequence[complex] = (),
                        senses: Sequence[complex] = ()) -> tuple[complex, complex, complex]:
    """The arrow of a load on the lever at its point ``at``: from it, or onto it where a load drawn before
    already lies along that line from it and the other side of the point is clear of ``lines()``, or else
    :data:`LEVER_BESIDE_MM` beside that line (:data:`BESIDE_MM` where only that is clear); with the shift that sets
    it beside (0 on its line).

    Two loads at one point on one line (F6 and Fu6 at e, a couple's forces
    M4′ and Mu4′ at d) drawn one after another read as one arrow broken
    by a head; one pulling from the point and one pushing onto it read as
    two, and both at their point, as a hand drawing shows them.  Where the
    other side is taken (the arms run from the pole, another load comes
    in), the second stands beside the first, tied to the point by a leader
    that lies along no line and no arrow of the lever, drawn or to come from
    the point along its load's line (``senses``), else a little ahead on a
    slanting leader; where that too is taken, it runs on beyond the first
    (:func:`unstacked`).  Set beside, it keeps to its line's side of the pole
    where either side is clear.

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
        return (unstacked(start, end, at, arrows) == (start, end)
                and LineString((_xy(start), _xy(end))).intersection(lines()).length < along)

    def crosses_pole(shift: complex) -> bool:  # the lever's moments are about the pole, at 0
        return (at * unit.conjugate()).imag * ((at + shift) * unit.conjugate()).imag < 0

    @functools.cache
    def ink() -> tuple[BaseGeometry, ...]:
        """The lever's lines and the arrows drawn so far, each shaft grown to a band: measured once, asked of every
        way tried."""
        shafts = (LineString((item.start, item.end)).buffer(0.8) for item in arrows
                  if isinstance(item, Arrow) and item.length > 0)
        return (lines(), *shafts)

    def tied(shift: complex) -> bool:
        """Whether the leader from the point to an arrow ``shift`` beside it lies along no line and no other arrow,
        drawn or still to be drawn from the point along its load's line (``senses``): one along the lever's line
        e–s5 or along Mu5′'s shaft is not seen, and the arrow reads as a load at another point (the Russian shaper's
        G6 and F6 at e)."""
        if any(abs((shift * sense.conjugate()).imag) < math.sin(math.radians(10.0)) * abs(shift) for sense in senses):
            return False
        tie = LineString((_xy(at), _xy(at + shift)))
        return all(tie.intersection(line).length < abs(shift) / 2 for line in ink())

    away, onto = (at, at + vector), (at - vector, at)
    # A side is taken where it is clear at BESIDE_MM, and drawn there LEVER_BESIDE_MM off where that is clear too: a
    # side clear only that far off (the knee press's F6 at d, past Fu6 and G6 on its line) left the next load along
    # the line (Ff16) no side, and it stood beyond another on its line, the two reading as one arrow broken by a head.
    sides = [(shift * LEVER_BESIDE_MM / BESIDE_MM, shift)
             for shift in sorted((1j * unit * BESIDE_MM, -1j * unit * BESIDE_MM), key=crosses_pole)]
    # Where a line or an arrow lies along each side's leader, the arrow stands beside and SLANT_AHEAD_MM ahead along
    # its own line, on a leader as long, slanting off the line along the side.
    slants = [side / abs(side) * math.sqrt(LEVER_BESIDE_MM ** 2 - SLANT_AHEAD_MM ** 2) + unit * SLANT_AHEAD_MM
              for side, _ in sides]

    def first_way(keep_off: bool, along: float = 1.0) -> tuple[complex, complex, complex] | None:
        def fits(start: complex, end: complex, ok: Callable[[complex, complex], bool]) -> bool:
            return ok(start, end) and (not keep_off or off_points(start, end))

        if fits(*away, lambda start, end: unstacked(start, end, at, arrows) == (start, end)):
            return (*away, 0j)
        if fits(*onto, lambda start, end: clear(start, end, along)):
            return (*onto, 0j)
        for wide, shift in sides:
            if fits(away[0] + shift, away[1] + shift, lambda start, end: clear(start, end, along)) and tied(shift):
                if fits(away[0] + wide, away[1] + wide, lambda start, end: clear(start, end, along)) and tied(wide):
                    shift = wide
                return (away[0] + shift, away[1] + shift, shift)
        for slant in slants:
            if fits(away[0] + slant, away[1] + slant, lambda start, end: clear(start, end, along)) and tied(slant):
                return (away[0] + slant, away[1] + slant, slant)
        return None

    chosen = first_way(False) or (*unstacked(*away, at, arrows), 0j)
    if off_points(*chosen[:2]):
        return chosen
    # Kept off the other points where no way is clear of the lines, an arrow may cross the lever's thin lines as long
    # as it lies along none (ALONG_BAR_MM, as on a group cut free): s4's Fu4 pushes onto s4 across the rays there.
    return first_way(True) or first_way(True, ALONG_BAR_MM) or chosen


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
        if image in spot_of and not negligible(force, [other for _, other in drawn]):
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


# The lever is drawn at μV, whatever μl the groups are drawn at: choosing μl lays each force sheet out at
# every μl it tries, and the lever's lettering was placed again each time (three quarters of a triad's run).
_LEVERS: OwnedMemo[Drawing] = OwnedMemo()


def lever_drawing(sheet: ForceSheet, lever: Lever) -> Drawing:
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

    def shown(name: str) -> str:
        return load_symbol(name, text)

    balancing_name = shown(BALANCING_FORCE)  # as its arrow is named: Fу in Russian

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
    named = [(term.name, term.image, term.force, LOAD, turned(term.shift) / drawn_at)
             for term in lever.terms if term.image and term.force != 0]
    named.append((BALANCING_FORCE, lever.balancing_image, lever.balancing_force, BALANCING, 0j))
    scale = arrow_scale([force for _, _, force, _, _ in named], frame)
    arrows: list[Primitive] = []
    leaders: list[Primitive] = []
    anchors: list[Anchor] = []
    arm_layers: list[Layer] = []
    arm_anchors: list[Anchor] = []
    arm_lengths: dict[str, float] = {}  # on the drawing, mm
    by_arm: dict[str, list[tuple[str, str]]] = {}  # each arm's loads in ΣMp, as (sign, name), in the order drawn
    moments = {term.name: term.moment for term in lever.terms}
    standing = lever.standing(velocity) | {BALANCING_FORCE}

    def stands(term: LeverTerm) -> bool:
        return term.name in standing

    # One numbering of the arms, the note's too: at the scale drawn at, whose drafting precision decides which are one.
    arm_of = {name: load_symbol(arm, text) for name, arm in
              lever.arm_names(velocity, drawn_at, sheet.mechanism.scene.drawing.drafting_precision,
                              standing=standing).items()}
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
        return grown_union([LineString(item.points + item.points[:1] if item.closed else item.points)
                       for item in frame if isinstance(item, Polyline)]
                      + [LineString(((0.0, 0.0), _xy(foot))) for foot in feet if abs(foot) >= ZERO_MM], 0.8)

    for name, image, force, stroke, shift in named:
        if negligible(force, [other for _, _, other, _, _ in named]):
            continue
        length = abs(force) / scale
        unit = force / abs(force)
        at = mm(image) + shift
        others = [spot for spot in spots if abs(spot - mm(image)) >= ZERO_MM]
        senses = [other / abs(other) for _, other_image, other, _, other_shift in named
                  if other != 0 and abs(mm(other_image) + other_shift - at) < ZERO_MM]
        start, end, beside = _pushing_or_pulling(at, max(length, LEAST_ARROW_MM) * unit, arrows, lines, others,
                                                 senses)
        arrows.append(Arrow(_xy(start), _xy(end), stroke, 3.0, svg_id("lever", name)))
        if beside:
            leaders.append(Polyline((_xy(at), _xy(start)), Stroke(LEADER_WIDTH, stroke.colour)))
        # Named at its free end: its head, or its tail where it pushes onto its point.
        free, outward = (start, -unit) if points_onto(start, end, at + beside) else (end, unit)
        anchors.append(Anchor(_xy(free), shown(name), NAME_SIZE, direction_rad(outward), stroke.colour))
        load_points[shown(name)] = image
        # The arm runs to the force's line, through its point, beside which the arrow may stand.
        start, end = start - beside, end - beside
        foot = perpendicular_foot(0j, start, unit)
        if name not in standing:
            continue
        arm = arm_of[name]
        if name != BALANCING_FORCE:
            by_arm.setdefault(arm, []).append((sign_mark(moments[name]), shown(name)))
        if arm in arm_lengths:
            # Its arm is drawn and named with the first load on its line: only the line is run on to its foot.
            if run_on := arm_with_run_on(0j, start, end, unit)[1:]:
                arm_layers.append(Layer(svg_id("lever-arm", name), tuple(run_on)))
            continue
        arm_lengths[arm] = abs(foot)
        if abs(foot) < ZERO_MM:
            # Too short to draw (a point's image by the pole, near a dead centre), its moment is still in Mb.
            undrawn.append(arm)
            continue
        arm_layers.append(Layer(svg_id("lever-arm", name), tuple(arm_with_run_on(0j, start, end, unit))))
        # Named out of the pole's reach where the room round it allows; a name left within it is dropped (below).
        arm_anchors.append(Anchor(_xy(0.8 * foot), arm, ARM_NAME_SIZE, direction_rad(1j * foot), ARM.colour,
                                  along=((0.0, 0.0), _xy(foot)), keep_off=((0.0, 0.0), POLE_CLEAR_MM)))
    # M·ω is a power (W); the lever's terms F·h are N·mm at μV: a block's moment enters as M·ω/μV.
    parts = [_factored(terms, arm) for arm, terms in by_arm.items()]
    parts += [f"{sign_mark(term.moment)} {shown(term.name)}·ω{term.link}/μV" for term in lever.terms
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
    # arrow at s6 without a name is G6's.  Last, so is a load's at a point whose letter lies on a line.
    drawn_lines = obstacles_of([item for item in figure if not isinstance(item, Circle)])
    shafts = [LineString((item.start, item.end)) for item in arrows if isinstance(item, Arrow)]
    crowded: list[Anchor] = []
    lettered = list(arm_anchors)
    loads, points = anchors[:len(load_points)], anchors[len(load_points):]
    unnamed: list[Anchor] = []
    # The free ends that a name, whose point keeps an arrow unnamed already, stood by: every name is kept
    # LED_NAME_HEAD_CLEAR_MM off them when placed again (the knee press's Mf14″ by G6's head, beside Fu6 tied to d).
    kept_off: list[Circle] = []
    while True:
        # Clear of the loads' arrows' ink: a letter touching one reads as naming that load (the knee press's d, by its
        # dot, on the 0.45 mm line of F6 pulling from it, its box 0.17 mm off the arrow's middle).
        labels = letters_placed(loads + points + lettered, figure, reach_farther=False, unnamed=unnamed,
                                shafts_inked=True, inked=kept_off)
        if near := [anchor for anchor, placed in zip(lettered, labels.texts[len(loads) + len(points):])
                    if text_box(placed).distance(ShapelyPoint(0.0, 0.0)) < POLE_CLEAR_MM
                    or label_on_a_line(anchor, placed, drawn_lines, labels.leaders, shafts)]:
            crowded += near
            lettered = [anchor for anchor in lettered if anchor not in near]
            continue
        taken = {load_points[anchor.text] for anchor in unnamed}
        # Fb's head is left out: drawn and named in its own colour, it is not taken for a load's.  An arrow left unnamed
        # keeps its head on the drawing, by which another's name reads as its.
        heads = [anchor.at for anchor in anchors[:len(load_points)] if anchor.text != balancing_name]
        lying = [anchor for anchor, placed in zip(loads, labels.texts) if anchor.text != balancing_name
                 and load_points[anchor.text] not in taken
                 and (label_on_a_line(anchor, placed, drawn_lines, labels.leaders, shafts)
                      or _by_another_head(anchor, placed, heads, labels.leaders))]
        by_heads = {head for anchor, placed in zip(loads, labels.texts) if anchor.text != balancing_name
                    and load_points[anchor.text] in taken
                    for head in _other_heads_by(anchor, placed, heads, labels.leaders)}
        if not lying and (new_heads := by_heads - {circle.centre for circle in kept_off}):
            kept_off += [Circle(head, LED_NAME_HEAD_CLEAR_MM) for head in sorted(new_heads)]
            continue
        if not lying:
            # A point whose letter the names round it left only a spot on a line (the class III triad's s4 and s5
            # among the loads at 3.5 mm) has one of its loads given under the lever, as a name lying on a line is.
            pressed = [group for group, anchor, placed in zip(groups, points, labels.texts[len(loads):], strict=False)
                       if label_on_a_line(anchor, placed, drawn_lines, labels.leaders, shafts)]
            free = [anchor for anchor in loads
                    if anchor.text != balancing_name and load_points[anchor.text] not in taken]
            lying = [anchor for anchor in free if any(load_points[anchor.text] in group for group in pressed)][:1]
            if pressed and not lying:
                # Its own arrows already keep one unnamed: the name standing by its dot, in the room its letter needs,
                # is given under the lever instead (G6 by s5 on the class III triad's lever of position 8, where s5's
                # letter, Fu5 under the lever, was led across G4's arrow).
                lying = _crowding_names([ShapelyPoint(_xy(mm(group[0]))) for group in pressed],
                                        [(anchor, placed) for anchor, placed in zip(loads, labels.texts)
                                         if anchor in free])[:1]
        if not lying:
            break
        unnamed.append(lying[0])
        loads = [anchor for anchor in loads if anchor is not lying[0]]
    given = sorted([anchor.text for anchor in crowded], key=list(arm_lengths).index)
    # An arm too short to draw is said to be so, as the plans and the polygons say it of their vectors: given among
    # the arms drawn but left unlettered, h5 = 0.2205 mm read as an arm the reader should find on the lever.
    short = [f"{arm} = {significant(arm_lengths[arm])} {text['millimetre']}" for arm in undrawn]
    apart = too_short_lines(short, text, CAPTION_WIDTH_MM, words="arms_too_short")
    unnamed_at = wrapped([text["lever_load_at"].format(name=anchor.text, point=load_points[anchor.text])
                           for anchor in unnamed])
    parts.append(f"{sign_mark(-sum(moments[name] for name in standing - {BALANCING_FORCE}))} "
                 f"{balancing_name}·{shown(BALANCING_ARM)}")
    equation = _leading(" ".join(parts))
    # Drawn turned as every lever is: a reader laying the velocity plan beside it must know which way.
    caption = [text["lever_title"], text["lever_turned"],
               text["comma"].join((sheet.lever_scale_line,
                                   text["body_force_scale"].format(value=format_scale(scale),
                                                                   least=f"{LEAST_ARROW_MM:g}"))),
               f"ΣMp: {equation} = 0",
               *wrapped([f"{arm} = {significant(arm_lengths[arm])} {text['millimetre']}" for arm in given]),
               *apart]
    under = [*([text["lever_unnamed"].format(loads=unnamed_at[0]), *unnamed_at[1:]] if unnamed_at else []),
             # The symbol alone: "balancing moment" said twice broke each line in two under a narrow lever (the
             # lever's title and its ΣMp say what Mb is).
             balancing_line(sheet, balancing, "balancing_by_lever", named=False),
             balancing_line(sheet, sheet.forces.balancing, "balancing_by_polygons", named=False),
             text["lever_difference"].format(value=_percent(lever.difference_percent(sheet.forces.balancing)))]
    return Drawing(LEVER_FIELD, [Layer("lever-plan", tuple(frame)), *arm_layers, Layer("lever-forces", tuple(arrows)),
                             Layer("lever-points", tuple(dots)), Layer("lever-leaders", labels.leaders),
                             Layer("lever-labels", labels.texts)], (*caption, *under),
                   run_on=short_run_on(short, apart, text, after=len(under)))


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
    return bool(_other_heads_by(anchor, text, heads, leaders))


def _other_heads_by(anchor: Anchor, text: Text, heads: Sequence[tuple[float, float]],
                    leaders: Sequence[Polyline]) -> list[tuple[float, float]]:
    """The other loads' free ends of ``heads`` that the placed name of ``anchor`` stands nearer than its own
    (:func:`_by_another_head`)."""
    led = any(led_from(leader, anchor) for leader in leaders)
    box = text_box(text)
    own = box.distance(ShapelyPoint(anchor.at))
    return [head for head in heads if math.dist(head, anchor.at) > 1e-6
            and (apart := box.distance(ShapelyPoint(head))) < own - OTHER_HEAD_MARGIN_MM
            and (not led or apart < LED_NAME_HEAD_CLEAR_MM)]


# A name whose box stands this near a point's dot (mm) takes the room of that point's letter: the letter stands beside
# its dot or on a short leader, its box within the placer's led rings of it.
LETTER_ROOM_MM = LABEL_GAP_MM + LED_SHARES[-1] * POINT_SIZE


def _crowding_names(dots: Sequence[ShapelyPoint], names: Sequence[tuple[Anchor, Text]]) -> list[Anchor]:
    """The anchors of the placed load ``names`` that stand in the room of a point's letter at one of ``dots``, the
    nearest first."""
    apart = [(min(text_box(placed).distance(dot) for dot in dots), index) for index, (_, placed) in enumerate(names)]
    return [names[index][0] for distance, index in sorted(apart) if distance < LETTER_ROOM_MM]


def _percent(value: float) -> str:
    """A percentage to two decimals, a true minus sign, no minus on a nought."""
    text = f"{value:.2f}"
    return "0.00" if text in ("-0.00", "0.00") else text.replace("-", "−")


def _factored(terms: Sequence[tuple[str, str]], arm: str) -> str:
    """The ``(sign, name)`` loads whose forces share ``arm`` as one term of ΣMp, the arm taken out of brackets as a
    hand calculation does: ``+ (Mu4′ − M4′ − Mf34′)·h7``, not three terms each times h7."""
    (sign, name), *others = terms
    if not others:
        return f"{sign} {name}·{arm}"
    inside = " ".join(f"{'+' if other_sign == sign else '−'} {other}" for other_sign, other in others)
    return f"{sign} ({name} {inside})·{arm}"


def _leading(terms: str) -> str:
    """A sum of terms without the sign of a leading plus, and a leading minus set close: ``−Fu3·h1 + …``."""
    if terms.startswith("+ "):
        return terms[2:]
    return "−" + terms[2:] if terms.startswith("− ") else terms
