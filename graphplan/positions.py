"""The positions to analyse: equally spaced driver positions from a start.

``start = "extreme"`` puts the first position where the working stroke
begins: the output link's velocity changes sign there, from the idle sense
to the working sense, as the driver advances.  That zero is bracketed on a
fine sweep and then found to machine precision as the root of the speed's
Chebyshev interpolant on the bracket (numpy), by Brent's method where that
fails.

:func:`reach` tells where a crank that cannot turn round can go at all, so
that a scene can be given a swing inside it.
"""

from __future__ import annotations

import contextlib
import math
import statistics
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np
from numpy.polynomial import Chebyshev

from .errors import AssemblyError, SceneError, SingularPositionError
from .kinematics import dot
from .length_units import LONGEST_LINK_M, frame_anchors, mixed_units
from .mechanism import Mechanism
from .memo import OwnedMemo
from .motion import Motion, Reference, reference_at, solve
from .reader import radians_within_a_turn
from .rounding import rounded_up
from .scales import LARGEST_PAPER_MM
from .scene import Working

# Driver positions per cycle of the sweep that brackets the extremes.
_BRACKET_SWEEP = 720
# The degree of the speed's interpolant on a bracket: the speed is analytic in the driver's coordinate, so on
# half a degree this is exact to rounding (the root agrees with Brent's method to a few ulps on every fixture).
_INTERPOLANT_DEGREE = 12
# Crank angles per turn on which the ends of a crank's reach are bracketed: half a degree apart.
_REACH_GRID = 720
# Narrower than this (rad), a range of the reach is one angle where it happens to assemble, which no run reaches.
_REACH_POINT = 1e-6


@dataclass(frozen=True)
class PositionSet:
    """The analysed positions: driver coordinates, their numbers, stroke, and the reference.

    ``reference`` holds the branches and named points fixed at the first
    position; every later solve of this mechanism should use it.

    ``extremes`` are the driver coordinates where the working stroke starts
    and where it ends (the idle stroke starts), when the scene names the
    working link.  ``reversals`` are the driver coordinates, as precise as
    the extremes, of every turn back of the working link over the crank's
    turn: the two extremes, and more where the link swings to and fro more
    than once a turn.  ``working_link_turns`` is how many times a working link
    that never turns back goes round in a turn of the crank, positive in its
    working sense; it has then no extremes and no strokes (0 for one that
    swings to and fro, or without a working link).  ``load_strokes`` holds the
    extremes of the strokes loads name as their own (``loads[].stroke``, a
    second cylinder's piston), by link and sense.
    """

    values: np.ndarray
    numbers: np.ndarray
    strokes: tuple[str, ...] | None
    reference: Reference
    extremes: tuple[float, float] | None
    reversals: tuple[float, ...] = ()
    working_link_turns: int = 0
    load_strokes: Mapping[tuple[int, str], tuple[float, float]] = field(default_factory=dict)

    def stroke_turns(self, sense: int) -> tuple[float, float] | None:
        """How far the crank turns (rad) in the working stroke and in the idle one, turning the way ``sense``
        says (+1 ccw); None without extremes.  Their ratio is the coefficient K of the output link's mean
        speed change."""
        if self.extremes is None:
            return None
        start, end = self.extremes
        working = (sense * (end - start)) % (2.0 * math.pi)
        return working, 2.0 * math.pi - working


# The positions of each scene while it lives: finding a crank's extremes solves the mechanism a few dozen times (the
# sweep, the roots, the assemblies chosen again at the first position), and graphplan.solve, the analysis, the
# reference solution, the accuracy study and the dynamics each ask for them; graphplan.solve at every call.
_position_sets: OwnedMemo[PositionSet] = OwnedMemo()


def make_positions(mechanism: Mechanism) -> PositionSet:
    """The positions of the scene's ``[positions]`` table, found once while the scene lives (a scene that has
    none is refused each time it is asked)."""
    return _position_sets.get(mechanism.scene, "positions", lambda: _found_positions(mechanism))


def _found_positions(mechanism: Mechanism) -> PositionSet:
    scene = mechanism.scene
    spec = scene.positions
    driver = mechanism.driver
    numbers = np.arange(spec.number_from, spec.number_from + spec.count)
    if not driver.cyclic:  # a slider's travel, a rocking crank's swing: from one end to the other
        values = np.linspace(driver.travel[0], driver.travel[1], spec.count)
        reference = _first_reference(mechanism, float(values[0]), int(numbers[0]), f"driver.{driver.run_key}")
        if driver.kind == "slider":
            _refuse_travel_below_drawing(mechanism, values, reference, numbers)
        extremes, reversals, turns = None, (), 0
    else:
        start = first_value(mechanism)
        # With start = "extreme" the first position is found later; the branches are chosen at 0° first.
        reference = _extreme_reference(mechanism, start) if spec.start == "extreme" else \
            _first_reference(mechanism, start, int(numbers[0]), "positions.start")
        extremes, reversals, turns = None, (), 0
        if spec.working is not None:
            extremes, reversals, turns, reference = _settle_extremes(mechanism, start, reference)
            if spec.start == "extreme":
                start = extremes[0]
                reference = reference_at(mechanism, start)
        values = start + driver.sense * 2.0 * math.pi * np.arange(spec.count) / spec.count
    load_strokes = _load_strokes(mechanism, start, reference) if driver.cyclic else {}
    strokes = None
    # A link that turns round is in no stroke: every position of it would be "working", or "idle" against its sense.
    if spec.working is not None and not turns:
        motion = solve(mechanism, values, reference, numbers, tolerant=True)
        if not driver.cyclic:   # a crank's turn was swept for its extremes already
            require_moving(motion)
        strokes = tuple("working" if working else "idle" for working in in_working_stroke(motion))
    # Read-only: every caller is handed the same set.
    values.flags.writeable = numbers.flags.writeable = False
    return PositionSet(values=values, numbers=numbers, strokes=strokes, reference=reference, extremes=extremes,
                       reversals=reversals, working_link_turns=turns, load_strokes=MappingProxyType(load_strokes))


def _extreme_reference(mechanism: Mechanism, start: float) -> Reference:
    """The reference at the crank's 0°, where ``start = "extreme"`` chooses the assemblies: a toggle there (a
    change-point four-bar folding) is told with why the run stood there, which the scene did not say, and what
    runs instead: the extremes are sought over the turn, which passes it, so no stroke can be cut at it."""
    try:
        return reference_at(mechanism, start)
    except SingularPositionError as error:
        apart = 180.0 / mechanism.scene.positions.count
        raise SingularPositionError(error.position, error.group, f'{error.reason}; positions.start = "extreme" '
                                    "chooses the assemblies here and seeks the output link's extreme positions over "
                                    "the crank's turn, which passes it, and a stroke cannot begin or end where the "
                                    f"mechanism may fold either way: leave {mechanism.scene.positions.working.where} "
                                    f"out and start the positions at an angle off it (positions.start = {apart:g})"
                                    ) from None


def _load_strokes(mechanism: Mechanism, start: float, reference: Reference) -> dict[tuple[int, str], tuple[float, float]]:
    """The extremes of each stroke a load of one stroke names as its own, by link and sense; a link that turns
    round has no strokes for a load to act in, and is refused."""
    found: dict[tuple[int, str], tuple[float, float]] = {}
    for load in mechanism.scene.loads:
        stroke = load.stroke
        if stroke is None or load.during == "always" or (stroke.link, stroke.sense) in found:
            continue
        ends, _, _ = _find_extremes(mechanism, start, reference, stroke)
        if ends is None:
            raise SceneError(f"{stroke.where}.link", f"link {stroke.link} turns round and never reverses its motion, "
                             "so it has no strokes for the load to act in: name a link that swings or slides to and "
                             "fro, or leave stroke out", stroke.link)
        found[(stroke.link, stroke.sense)] = ends
    return found


def link_extremes(mechanism: Mechanism, positions: PositionSet, link: int) -> tuple[float, float] | None:
    """The crank angles where ``link`` turns back (its strokes' ends, in either sense); None for a link that
    turns round or stands still."""
    sense = "forward" if link in mechanism.translating else "ccw"
    try:
        ends, _, _ = _find_extremes(mechanism, float(positions.values[0]), positions.reference,
                                    Working(link=link, sense=sense, where=f"links.{link}"))
    except SceneError:  # it stands still, or dwells: it has no strokes to compare
        return None
    return ends


def stroke_extremes(positions: PositionSet, stroke: Working | None) -> tuple[float, float] | None:
    """The driver coordinates where ``stroke`` (a load's own, or None: the working link's) starts and ends; None
    where the positions run once over a swing or a travel, which have no extremes (a load's stroke then goes by
    its link's sense of motion alone, as the working link's does)."""
    return positions.extremes if stroke is None else positions.load_strokes.get((stroke.link, stroke.sense))


def _refuse_travel_below_drawing(mechanism: Mechanism, values: np.ndarray, reference: Reference,
                                 numbers: np.ndarray) -> None:
    """Refuse a slider driver's travel too short for its positions to be drawn apart (`travel = [0, 1e-15]` was
    refused as a working link at rest, or drew its 12 positions as one): at ``driver.travel``, with the least travel
    that draws them apart, as a rocking crank's swing is refused at ``driver.swing``."""
    driver, scene = mechanism.driver, mechanism.scene
    steps = len(values) - 1
    if steps < 1:
        return
    # The plan of positions draws the paths of every point, and no μl may draw them wider or taller than the
    # largest paper (LARGEST_PAPER_MM, render/drawings.length_scale): so μl ≥ across/LARGEST_PAPER_MM, where across
    # is at least the joints' spread in the first position, which lies on those paths.  A step moves the slider
    # travel/steps, drawn travel/steps/μl ≤ travel/steps·LARGEST_PAPER_MM/across; a drawing tells lines apart only
    # to its drafting precision, so under that on the largest paper no drawing tells the positions apart.  Weighed
    # against the mechanism's own size, never refusing a stroke the paper draws: a 0.2 m cylinder's on a 0.3 m
    # lever drive clears it some 700 times.
    named = {spec.name for spec in scene.points}
    first = solve(mechanism, values[:1], reference, numbers[:1], tolerant=True)
    joints = np.concatenate([np.ravel(point.r) for name, point in first.points.items() if name not in named])
    across = max(float(np.ptp(joints.real)), float(np.ptp(joints.imag)))
    travel = abs(float(values[-1] - values[0]))
    precision = scene.drawing.drafting_precision
    if not across > 0 or travel / steps * LARGEST_PAPER_MM / across >= precision:
        return
    least = rounded_up(precision * across / LARGEST_PAPER_MM * steps)
    raise SceneError(f"{driver.where}.travel", f"spans {travel:.3g} m, too little for its {len(values)} positions "
                     f"(positions.count) to be drawn apart: the mechanism, {across:.3g} m across at position "
                     f"{numbers[0]}, drawn as large as the largest paper ({LARGEST_PAPER_MM:g} mm) moves the slider "
                     f"{travel / steps * LARGEST_PAPER_MM / across:.3g} mm a step, under the drafting precision of "
                     f"{precision:g} mm (drawing.drafting_precision); give a travel of at least {least:g} m",
                     list(driver.travel))


def _first_reference(mechanism: Mechanism, value: float, number: int, moved_by: str) -> Reference:
    """The reference at the first position, where each group's assembly is chosen: one that cannot be assembled is
    named by its number, as a later position is; a singular one is refused as such, with what moves it (a position
    later in the run is only warned of)."""
    try:
        return reference_at(mechanism, value)
    except AssemblyError as error:
        where = f"position {number} ({mechanism.driver.describe(value)})"
        raise AssemblyError(error.joint, where, error.group, error.reason) from None
    except SingularPositionError as error:
        driver = mechanism.driver
        elsewhere = value + (2.0 * math.pi / 3.0 if driver.cyclic else 0.5 * (driver.travel[1] - driver.travel[0]))
        try:
            reference_at(mechanism, elsewhere)
        except (SingularPositionError, AssemblyError):
            raise error from None  # no better elsewhere (parallel guides): another start is no advice
        raise SingularPositionError(f"the first position, {number} ({mechanism.driver.describe(value)})", error.group,
                                    f"{error.reason}; the first position fixes each group's assembly and may not be "
                                    f"singular: start the run elsewhere ({moved_by})") from None


def first_value(mechanism: Mechanism) -> float:
    """The driver's coordinate where the scene's positions start and its assemblies are chosen: a travel's or a
    swing's first end, a turning crank's ``start`` (0° for "extreme", whose position is found later)."""
    driver, start = mechanism.driver, mechanism.scene.positions.start
    if not driver.cyclic:
        return float(driver.travel[0])
    return 0.0 if start == "extreme" else radians_within_a_turn(float(start))


def _first_assembly(mechanism: Mechanism) -> Reference | None:
    """The assemblies the scene's first position fixes, where it can be assembled; None where it cannot, or where a
    group is followed by continuation (a walk to every angle of the grid would be long): each angle's own then."""
    if any(group.continuation for group in mechanism.groups):
        return None
    try:
        return reference_at(mechanism, first_value(mechanism))
    except (AssemblyError, SingularPositionError):
        return None


def working_speed(motion: Motion, working: Working | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The output link's velocity and acceleration, signed so that positive is the working sense; of ``working``'s
    link and sense where given (a load's own stroke), else of the scene's ``positions.working``.

    A turning link gives ω and ε, a translating one its velocity and
    acceleration along its own direction.
    """
    mechanism = motion.mechanism
    working = working or mechanism.scene.positions.working
    assert working is not None
    link = motion.links[working.link]
    if working.link in mechanism.translating:
        origin = motion.points[link.origin]
        speed, rate = dot(link.u, origin.v), dot(link.u, origin.a)
    else:
        speed, rate = link.omega, link.epsilon
    sign = 1.0 if working.sense in ("ccw", "forward") else -1.0
    shape = motion.driver.shape
    return np.broadcast_to(sign * speed, shape), np.broadcast_to(sign * rate, shape)


def require_moving(motion: Motion, working: Working | None = None) -> None:
    """Refuse a working link (``working``'s, or the scene's) that stays where it is over ``motion`` (a sweep of the
    driver's run): it has no strokes, and its diagrams would be drawn at an endless scale.  A slip of the scene,
    such as a slider's guide through the pivot of the slotted link, or a crank too short to move anything."""
    mechanism = motion.mechanism
    working = working or mechanism.scene.positions.working
    assert working is not None
    link = motion.links[working.link]
    shape = motion.driver.shape
    if working.link in mechanism.translating:
        along = np.broadcast_to(dot(link.u, motion.points[link.origin].r), shape)
        # Measured by the joints alone: a named point (a centre of mass) placed far off its link moves nothing, and
        # would otherwise make a real stroke read as rest.
        named = {spec.name for spec in mechanism.scene.points}
        size = max(float(np.max(np.abs(point.r))) for name, point in motion.points.items() if name not in named)
        travel, rest, unit = float(np.ptp(along)), 1e-9 * max(size, 1e-300), "m"
        _refuse_far_from_the_origin(motion, named, working.link, travel, rest)
    else:
        angle = np.broadcast_to(np.asarray(link.angle, dtype=float), shape)
        travel, rest, unit = float(np.ptp(np.angle(np.exp(1j * (angle - angle[0]))))), 1e-9, "rad"
    if travel <= rest:
        run = "the crank's turn" if mechanism.driver.cyclic else f"driver.{mechanism.driver.run_key}"
        _refuse_frame_far_apart(motion, working.link, f"{travel:.3g} {unit} over {run}, no more than rest "
                                f"({rest:.3g} {unit})")
        raise SceneError(working.where, f"link {working.link} does not move over {run}: its travel is "
                         f"{travel:.3g} {unit}, so it has no strokes and its kinematic diagrams nothing to draw; "
                         "name a link the mechanism moves, or check the lengths and guides that should move it",
                         working.link)


def _refuse_far_from_the_origin(motion: Motion, named: set[str], link: int, travel: float, rest: float) -> None:
    """Refuse a frame placed so far from the origin that a stroke which moves against the mechanism's own size is
    within what a position there is told from rest by (the rest weighed against the joints' distance from the
    origin): told at the frame point that stands farthest, not as a link at rest with its travel beside it."""
    joints = np.concatenate([np.ravel(point.r) for name, point in motion.points.items() if name not in named])
    across = max(float(np.ptp(joints.real)), float(np.ptp(joints.imag)))
    frame = motion.mechanism.scene.frame_points
    if not (1e-9 * across < travel <= rest) or not frame:
        return
    name = max(frame, key=lambda each: abs(frame[each]))
    raise SceneError(f"frame.points.{name}", f"stands {abs(frame[name]):.3g} m from the origin, where a position is "
                     f"told from rest only to {rest:.3g} m, more than link {link}'s travel of {travel:.3g} m on a "
                     f"mechanism {across:.3g} m across: place the frame points near the origin",
                     [frame[name].real, frame[name].imag])


def _refuse_frame_far_apart(motion: Motion, link: int, moves: str) -> None:
    """Refuse a working link at rest where the frame holds the mechanism at places farther apart than any machine's
    pivots (:data:`~graphplan.length_units.LONGEST_LINK_M`): a rocker's pivot 1e15 m from the crank's is turned
    through some 1e-16 rad, and a slider that far from its guide's point moves within what a position there is told
    from rest by.  Told at the place that stands farthest from the origin, which the scene moved off (its
    neighbours stay near the origin), with how far it stands from the nearest other and what the link then does:
    named as a link at rest, the student was sent to the links' lengths and guides, which are right."""
    anchors = frame_anchors(motion.mechanism)
    if len(anchors) < 2:
        return
    key, far = max(anchors, key=lambda anchor: abs(anchor[1]))
    nearest_key, nearest = min(((other_key, other) for other_key, other in anchors if other_key != key),
                               key=lambda anchor: abs(anchor[1] - far))
    apart = abs(far - nearest)
    if not apart > LONGEST_LINK_M:
        return
    nearest_name = (nearest_key.removeprefix("frame.points.") if nearest_key.startswith("frame.points.")
                    else f"the guide's point {nearest_key}")
    raise SceneError(key, f"stands {apart:.3g} m from {nearest_name}, farther apart than any machine's pivots (over "
                     f"{LONGEST_LINK_M:g} m): link {link} moves {moves} at that size, so it has no strokes; place "
                     "the frame points and guides as near one another as the mechanism's pivots stand",
                     [far.real, far.imag])


def in_working_stroke(motion: Motion, working: Working | None = None) -> np.ndarray:
    """Whether each position of ``motion`` belongs to the working stroke of ``working`` (a load's own stroke), or
    of the scene's working link."""
    speed, rate = working_speed(motion, working)
    # Of the finite speeds: a singular position's is not (it would make every other position one at rest).
    finite = np.abs(speed[np.isfinite(speed)])
    scale = float(np.max(finite)) if finite.size else 0.0
    at_rest = np.abs(speed) <= 1e-9 * (scale or 1.0)
    # At an extreme the link is at rest; it belongs to the stroke it is about to begin.
    return np.where(at_rest, rate > 0, speed > 0)


def _settle_extremes(mechanism: Mechanism, start: float, reference: Reference):
    """The extremes, every reversal and the working link's turns (:attr:`PositionSet.working_link_turns`), with
    branches chosen at the first position (a ``near`` branch may depend on it)."""
    for _ in range(3):
        extremes, reversals, turns = _find_extremes(mechanism, start, reference)
        if extremes is None:  # a link that turns round: the positions start where the scene says
            return None, (), turns, reference
        first = extremes[0] if mechanism.scene.positions.start == "extreme" else start
        settled = reference_at(mechanism, first)
        if settled.branches == reference.branches:
            return extremes, reversals, 0, reference
        # A triad's branch holds its pose where it was chosen: chosen again at the first position, the same
        # assembly is another branch, whose extremes are those just found.
        if _same_assembly(mechanism, first, reference, settled):
            return extremes, reversals, 0, settled
        reference = settled
    return extremes, reversals, 0, reference


def _same_assembly(mechanism: Mechanism, value: float, one: Reference, other: Reference) -> bool:
    """Whether the mechanism stands the same at driver ``value`` from either reference position."""
    first, second = (solve(mechanism, [value], reference) for reference in (one, other))
    size = max(float(np.max(np.abs(point.r))) for point in first.points.values()) or 1.0
    return all(float(np.max(np.abs(point.r - second.points[name].r))) <= 1e-9 * size
               for name, point in first.points.items())


def _find_extremes(mechanism: Mechanism, start: float, reference: Reference, working: Working | None = None
                   ) -> tuple[tuple[float, float] | None, tuple[float, ...], int]:
    """Driver angles where the working stroke starts and ends, and where the working link turns back at all (in
    the driver's order from ``start``), each to machine precision; for a link that turns round and never turns
    back, no extremes but its turns in the crank's (:attr:`PositionSet.working_link_turns`), where the scene asks
    for nothing that needs extremes.  Of ``working``'s link and sense where given (a load's own stroke), whose
    link turning round is its caller's to refuse."""
    own = working is None
    working = working or mechanism.scene.positions.working
    try:
        return _extremes_over_turn(mechanism, start, reference, working, own)
    except SingularPositionError as error:
        # Met between the scene's positions, or at an extreme itself (a change-point linkage folds there): the
        # positions alone would pass it with a warning, the strokes cannot be cut at it.
        leave_out = f"leave {working.where} out"
        if own and mechanism.scene.positions.start == "extreme":
            leave_out += ", and number the positions from an angle (positions.start = 0.0)"
        raise SingularPositionError(error.position, error.group, f"{error.reason}; {working.where}: link "
                                    f"{working.link}'s extreme positions are sought over the crank's turn, which "
                                    f"passes it, and a stroke cannot begin or end where the mechanism may fold either "
                                    f"way: {leave_out}") from None


def _median(values: np.ndarray) -> float:
    """The median of a 1-D array of finite numbers (nan for none), by the standard library: np.median asks numpy.ma
    whether its answer is masked, and importing that costs a cold run some 30 ms."""
    return float(statistics.median(values.tolist())) if len(values) else math.nan


def _extremes_over_turn(mechanism: Mechanism, start: float, reference: Reference, working: Working, own: bool
                        ) -> tuple[tuple[float, float] | None, tuple[float, ...], int]:
    driver = mechanism.driver
    # Half a step off the start, so that an extreme exactly at the start falls inside a bracket.
    steps = start + driver.sense * 2.0 * math.pi * (np.arange(_BRACKET_SWEEP + 1) - 0.5) / _BRACKET_SWEEP
    sweep = solve(mechanism, steps, reference)
    require_moving(sweep, working)
    speed, _ = working_speed(sweep, working)
    _refuse_dwell(mechanism, steps, speed, working)

    def speeds_at(angles: Sequence[float]) -> np.ndarray:
        return working_speed(solve(mechanism, np.asarray(angles, dtype=float), reference), working)[0]

    def zero_in(index: int) -> float:
        lo, hi = steps[index], steps[index + 1]
        return float(lo) if speed[index] == 0 else _zero_between(speeds_at, float(lo), float(hi))

    found, roots = {}, {}
    before, after = speed[:-1], speed[1:]
    # A sign change is a turn back where the speed passes through zero, not through a singular position (a
    # toggle of a later group, where it runs off to infinity and back from the other side).
    through_zero = np.minimum(np.abs(before), np.abs(after)) < _median(np.abs(speed[np.isfinite(speed)]))
    rises = through_zero & (before <= 0) & (after > 0)
    falls = through_zero & (before >= 0) & (after < 0)
    turns = 0 if (rises | falls).any() else _turns_round(mechanism, sweep, working)
    if turns:
        if own:
            _refuse_needing_extremes(mechanism)
        return None, (), turns
    for name, rising, crossing in (("working", True, rises), ("idle", False, falls)):
        candidates = np.flatnonzero(crossing)
        if len(candidates) == 0:
            raise SceneError(working.where, f"link {working.link} never reverses its motion, so it has no extreme "
                             f"position{_half_turned(mechanism, sweep, working)}")
        # Several reversals (a dwell, a six-bar): take the one that begins the longest stroke.
        index = max(candidates, key=lambda i: _stroke_length(speed[:-1], i, rising))
        found[name] = roots[index] = zero_in(index)
    # Each turn back found as closely as the extremes: where there are more than two, a warning prints them all
    # in the sentence that gives the extremes.
    reversals = tuple(roots[i] if i in roots else zero_in(i) for i in np.flatnonzero(rises | falls))
    return (found["working"], found["idle"]), reversals, 0


def _turns_round(mechanism: Mechanism, sweep: Motion, working: Working) -> int:
    """How many times the working link goes round over ``sweep`` (a crank's turn), positive in its working
    sense: 0 for a translating link, or for a turning one that comes back to its angle without going round."""
    if working.link in mechanism.translating:
        return 0
    turned = float(np.sum(_turning_steps(sweep, working.link)))
    sign = 1 if working.sense == "ccw" else -1
    return sign * round(turned / (2.0 * math.pi))


def _turning_steps(sweep: Motion, link: int) -> np.ndarray:
    """The angle (rad) ``link`` turns through at each step of ``sweep``, within ±π: a half-degree step of the crank
    turns it through less than half a turn, away from a toggle."""
    angle = np.broadcast_to(np.asarray(sweep.links[link].angle, dtype=float), sweep.driver.shape)
    return np.angle(np.exp(1j * np.diff(angle)))


def _half_turned(mechanism: Mechanism, sweep: Motion, working: Working) -> str:
    """Why the working link never reverses, where its angle, or that of a link it is driven through, flips over by
    half a turn between two neighbouring steps of the sweep: the mechanism passes a singular position each cycle,
    and the motion after it has no extreme to find.  A Whitworth slider driven off a lever whose block passes over
    its pivot was refused without a cause: the flip is the lever's, not the slider's."""
    # A half-degree step turns a link through far less than a quarter turn, away from a singular position: the
    # steps where each turning link flips.
    flips = {number: np.flatnonzero(np.abs(_turning_steps(sweep, number)) > 0.75 * math.pi)
             for number in sorted(sweep.links) if number not in mechanism.translating}
    flipped = [number for number, steps in flips.items() if steps.size]
    # A block turns with the lever it slides in: the lever is the link to name.
    carried = {slide.slider for slide in sweep.slides if slide.guide in flipped}
    named = [number for number in flipped if number not in carried]
    if not named:
        return ""
    if working.link in flipped:
        whose = "its angle flips"
    elif len(named) == 1:
        whose = f"the angle of link {named[0]}, which drives it, flips"
    else:
        whose = f"the angles of links {', '.join(map(str, named[:-1]))} and {named[-1]}, which drive it, flip"
    at = int(flips[working.link if working.link in flipped else named[0]][0])
    crank = np.asarray(sweep.driver, dtype=float)
    near = math.degrees((crank[at] + crank[at + 1]) / 2.0) % 360.0
    return (f": {whose} over by half a turn once a cycle (near φ = {near:.0f}°), at a singular position where "
            "nothing fixes that direction (the block of a slotted lever passing over the lever's pivot, where the "
            "crank is as long as the distance between the pivots); make those lengths differ")


def _refuse_needing_extremes(mechanism: Mechanism) -> None:
    """Refuse what needs the extremes of a working link that turns round, naming the key that asks for them: a
    start at the extreme, a load of one stroke (or of a window of the working stroke, or along a diagram of it)."""
    scene = mechanism.scene
    working = scene.positions.working
    assert working is not None
    told = f"link {working.link} turns round and never reverses its motion, so it has no extreme position"
    # A length in millimetres among metres turns a rocker round (a slotted lever's crank longer than the distance
    # between the pivots): refused here, before the warning that would name it, the key to change is that length.
    units = mixed_units(mechanism)
    slip = f"; link {working.link} may turn round only because {units}" if units is not None else ""
    if scene.positions.start == "extreme":
        raise SceneError("positions.start", f'"extreme" needs the extreme positions of the output link, but '
                         f"{told}: start the positions at a crank angle in degrees", "extreme", hint=slip)
    for load in scene.loads:
        if load.diagram is not None:
            raise SceneError(f"{load.where}.diagram", "a load diagram over the working stroke needs the strokes "
                             f"of the output link, but {told} for one to begin at: make the load a value that "
                             f"acts always{slip}")
        if load.during != "always":
            what = f"a load of the {load.during} stroke" if isinstance(load.during, str) else \
                "a window of the working stroke"
            written = load.during if isinstance(load.during, str) else dict(zip(("from", "to"), load.during))
            raise SceneError(f"{load.where}.during", f"{what} needs the strokes of the output link, but {told} "
                             "for one to begin at: use always", written, hint=slip)


# A working link's speed this small beside its largest is rounding's: the link stands still.
_STILL = 1e-9


def _refuse_dwell(mechanism: Mechanism, steps: np.ndarray, speed: np.ndarray, working: Working) -> None:
    """Refuse a working link that stands still over a stretch of the turn (a rod as long as its crank rests its
    slider at the crank's pivot for half a turn): its speed there is rounding's, whose every change of sign was
    a turn back (136 a turn), and its extremes and K were noise."""
    finite = np.isfinite(speed)
    scale = float(np.max(np.abs(speed[finite]), initial=0.0))
    still = finite & (np.abs(speed) <= _STILL * scale)
    if scale == 0.0 or not still.any():
        return
    # The sweep's last step is its first a turn on: a dwell across the sweep's start is one stretch, not two
    # that would each name a part of it (a quarter of the half turn a Whitworth ram rests in).
    turn = len(still) - 1
    shift = int(np.argmin(still[:turn])) if still[0] and still[turn - 1] and not still[:turn].all() else 0
    around = np.roll(still[:turn], -shift) if shift else still
    runs = np.flatnonzero(np.diff(np.concatenate([[0], around.astype(int), [0]])))
    first, last = max(zip(runs[::2], runs[1::2] - 1), key=lambda run: run[1] - run[0])
    if last - first < 2:
        return
    first, last = (first + shift) % turn if shift else first, (last + shift) % turn if shift else last
    driver = mechanism.driver
    raise SceneError(working.where,
                     f"link {working.link} stands still from {driver.describe(float(steps[first]))} "
                     f"to {driver.describe(float(steps[last]))} (its speed there is rounding's): an output link that "
                     "dwells has no one extreme position for its stroke to start at; two links lie along each other "
                     "there (a rod as long as its crank?): change the lengths, or leave positions.working out")


def _zero_between(speeds_at: Callable[[Sequence[float]], np.ndarray], lo: float, hi: float) -> float:
    """The zero of the speed between ``lo`` and ``hi``, where its sign changes, to machine precision.

    One vectorised solve at the interpolant's Chebyshev points and numpy's roots of it, where the scalar
    root finders solve the mechanism once per step; Brent's method, which needs only the sign change,
    where the interpolant does not give exactly one root inside at which the speed itself vanishes (a
    speed that is not smooth there, which a mechanism's is away from a toggle).
    """
    low, high = min(lo, hi), max(lo, hi)
    series = Chebyshev.interpolate(speeds_at, _INTERPOLANT_DEGREE, domain=[low, high])
    roots = series.roots()
    inside = roots[(np.abs(roots.imag) <= 1e-12 * (high - low)) & (roots.real >= low) & (roots.real <= high)].real
    if len(inside) == 1:
        at_low, at_high, at_root = speeds_at([low, high, inside[0]])
        # Half a degree off, the speed is its slope times the bracket: this asks for the root to ~1e-11 rad.
        if abs(at_root) <= 1e-9 * max(abs(at_low), abs(at_high)):
            return float(inside[0])
    from scipy.optimize import brentq  # imported here: its import costs a third of a cold run

    return float(brentq(lambda angle: float(speeds_at([angle])[0]), lo, hi, xtol=1e-15,
                        rtol=4 * np.finfo(float).eps, maxiter=200))


def _stroke_length(turn: np.ndarray, index: int, rising: bool) -> int:
    """How many samples of the speed over a turn (``turn``, periodic) follow sample ``index`` in the sense that
    the reversal after it begins.  Counted round the end of the samples: a stroke the sweep's start cuts in two
    is one stroke, so that which reversal begins the longest does not depend on where the positions start."""
    following = np.roll(turn, -(index + 1))
    following = following > 0 if rising else following < 0
    stops = np.flatnonzero(~following)
    return int(stops[0]) if len(stops) else len(following)


# The reach of a crank that turns round: one range, the whole turn.
FULL_TURN = ((0.0, 2.0 * math.pi),)


def reach(mechanism: Mechanism, reference: Reference | None = None) -> tuple[tuple[float, float], ...]:
    """The ranges of crank angle (rad, lower end first) in which the mechanism assembles.

    An angle belongs to the reach when every group assembles there in the
    scene's assembly, as its first position fixes it where it can be assembled
    (a PRP's guides crossing from one side).  The ranges are bracketed on a grid of half a degree
    and their ends, where two links stand in line, found by bisection to a
    nanoradian; a range narrower than the grid may be missed.  A range
    through 0 starts at a negative angle.  A crank that turns round has the
    one range (0, 2π); one that assembles nowhere has none.  ``reference``: the assemblies a solve took
    elsewhere (from the first of the values a caller gave).
    """
    found = _assembled_ranges(_assembles(mechanism, reference), _turn_grid(), wraps=True, tolerance=1e-9)
    if found is None:
        return FULL_TURN
    ranges = []
    for lower, upper in found:
        if lower >= math.pi and upper > 2.0 * math.pi:  # through 0: from a negative angle
            lower, upper = lower - 2.0 * math.pi, upper - 2.0 * math.pi
        if upper - lower > _REACH_POINT:  # not one angle alone, where it happens to assemble
            ranges.append((lower, upper))
    return tuple(sorted(ranges))


def turns_round(mechanism: Mechanism) -> bool:
    """Whether a crank's mechanism assembles at every angle of :func:`reach`'s grid, as :func:`reach` then finds
    :data:`FULL_TURN`: asked angle by angle up to the first that fails, with no range's ends bisected, for the
    advice that tries lengths a digit off, most of which stop the crank (a triad's check took 7 s of its 9 there)."""
    # One walk round the grid from the first position's assembly settles a mechanism that turns round: a triad's
    # walk takes a twentieth of the time its angles take asked one by one, each assembled afresh (0.07 s to 1.2 s).
    # Where the walk stops, the angles are asked alone, as reach asks them: another assembly may close there.
    with contextlib.suppress(AssemblyError, SingularPositionError):
        solve(mechanism, _turn_grid(), reference_at(mechanism, first_value(mechanism)), tolerant=True)
        return True
    # Asked spread over the turn, halving the gaps (0°, 256°, 128°, …), not from 0° up: an angle it does not reach
    # lies in a range of them, which the spread meets within a few asks where the climb took hundreds (a second of
    # the advice's each length a digit off).  Each angle's answer is its own, walked to from the first position's
    # assembly whatever was asked before, so the order changes no answer.
    assembles = _assembles(mechanism, None)
    return all(assembles(float(value)) for value in _turn_grid()[_SPREAD])


def _turn_grid() -> np.ndarray:
    """The crank angles (rad) :func:`reach` and :func:`turns_round` ask, round the turn from 0."""
    return 2.0 * math.pi * np.arange(_REACH_GRID) / _REACH_GRID


def _spread_order(count: int) -> np.ndarray:
    """``range(count)`` ordered by its indices' bits read backwards: each next index halves a gap the ones before
    it leave (0, 512, 256, 128, 640, … of 720)."""
    bits = max(1, (count - 1).bit_length())
    return np.array(sorted(range(count), key=lambda index: int(f"{index:0{bits}b}"[::-1], 2)))


_SPREAD = _spread_order(_REACH_GRID)


def travel_reach(mechanism: Mechanism, over: tuple[float, float] | None = None) -> tuple[tuple[float, float], ...]:
    """The ranges of a slider driver's typed travel (or of the coordinates ``over``; m, in the travel's own order)
    in which the mechanism assembles, found as :func:`reach` finds a crank's, on a grid of their 720th parts."""
    low, high = sorted(mechanism.driver.travel if over is None else over)
    grid = np.linspace(low, high, _REACH_GRID + 1)
    found = _assembled_ranges(_assembles(mechanism, None), grid, wraps=False, tolerance=1e-9 * (high - low))
    ranges = ((low, high),) if found is None else \
        tuple((lower, upper) for lower, upper in found if upper - lower > 1e-6 * (high - low))
    return ranges if mechanism.driver.travel[0] <= mechanism.driver.travel[1] else \
        tuple((upper, lower) for lower, upper in reversed(ranges))


def _assembles(mechanism: Mechanism, reference: Reference | None) -> Callable[[float], bool]:
    """Whether every group assembles at a driver's value in the scene's assembly (taken at the first position
    where it can be, or ``reference``'s); a toggle counts as assembled."""
    reference = reference or _first_assembly(mechanism)

    def assembles(value: float) -> bool:
        try:
            if reference is None:
                reference_at(mechanism, value)
            else:
                solve(mechanism, np.array([value]), reference)
        except AssemblyError:
            return False
        except SingularPositionError:  # assembled, at a toggle
            return True
        return True

    return assembles


def _assembled_ranges(assembles: Callable[[float], bool], grid: np.ndarray, wraps: bool,
                      tolerance: float) -> list[tuple[float, float]] | None:
    """The ranges of the driver's value where ``assembles``, None where it assembles all over ``grid``: bracketed
    on ``grid`` (evenly spaced; ``wraps`` round its end to its start for a crank's turn), each end found by
    bisection to ``tolerance``."""
    inside = np.array([assembles(float(value)) for value in grid])
    step = grid[1] - grid[0]
    if inside.all():
        return None

    from scipy.optimize import bisect  # imported here: only a driver that cannot go everywhere needs it

    def end(inner: float, outer: float) -> float:
        """The end of a range between a grid value inside it and the next one outside it."""
        if assembles(outer):  # it fails at that one value alone (its outer joints meet), not a rounding off it
            return outer
        return bisect(lambda value: 1.0 if assembles(value) else -1.0, min(inner, outer), max(inner, outer),
                      xtol=tolerance)

    if wraps:
        firsts = np.flatnonzero(inside & ~np.roll(inside, 1))
        counts = [int(np.argmin(np.roll(inside, -first))) for first in firsts]  # up to the first outside
    else:
        edges = np.diff(np.concatenate([[0], inside.astype(int), [0]]))
        firsts = np.flatnonzero(edges == 1)
        counts = list(np.flatnonzero(edges == -1) - firsts)
    ranges = []
    for first, count in zip(firsts, counts, strict=True):
        last = float(grid[first] + (count - 1) * step)
        # A travel's own ends bound it: what lies past them was not asked for.
        lower = float(grid[0]) if not wraps and first == 0 else end(float(grid[first]), float(grid[first] - step))
        upper = float(grid[-1]) if not wraps and first + count == len(grid) else end(last, last + step)
        ranges.append((lower, upper))
    return ranges
