"""The loads of the force analysis: weights, d'Alembert's inertia loads, the scene's external loads.

Loads are computed from a *state*: where the points are, how fast they and
the links move.  The analytic :class:`~graphplan.motion.Motion` is one state
(arrays over all positions); the plans of one instant are another
(:func:`plan_state`), so that the force polygons, built from the plans, never
read the analytic accelerations (DESIGN principle 1).

Sign conventions: forces are complex numbers (x + iy, N), moments are
counter-clockwise positive (N·m).  The inertia force ``Fu = −m·aS`` acts at
the centre of mass, the inertia moment ``Mu = −J·ε`` on the link; weight is
``G = m·g`` along −y.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from .errors import SceneError
from .forces import Load
from .kinematics import PointMotion, Scalar, Vector, at, dot, unit
from .mechanism import Mechanism
from .motion import Motion, PositionWarning, solve
from .plans import Plan
from .positions import PositionSet, in_working_stroke, stroke_extremes
from .reader import radians_within_a_turn
from .rounding import largest_finite
from .scene import LoadSpec, Working

# A speed this small against the cycle's largest is rest: a resisting load then opposes
# the motion about to begin (the sense of the acceleration).
_AT_REST = 1e-9
# Where the loads switch (a window opens or closes, a resisting load's motion turns back), the bisection stops at
# this share of the sweep's step: the sliver it leaves holds no work.
SWITCH_TOLERANCE = 1e-12
_MAX_BISECTIONS = 80


class Turning(Protocol):
    omega: Scalar
    epsilon: Scalar


@dataclass(frozen=True)
class State:
    """Where the points are and how they and the links move: arrays over positions, or one instant."""

    points: Mapping[str, PointMotion]
    links: Mapping[int, Turning]
    # Each slider's velocity and acceleration relative to its guide, as vectors along the slide.
    sliding: Mapping[int, Vector] = field(default_factory=dict)
    sliding_acceleration: Mapping[int, Vector] = field(default_factory=dict)

    # The scales are of the finite speeds alone: a singular position's are infinite (a swing that ends at a toggle),
    # and beside them every other position's was rest, its resisting loads turned the wrong way.
    @functools.cached_property
    def turning_scale(self) -> float:
        """The largest finite |ω| of the state: an angular speed far below it is rest (once a state: each load and
        pair asks it)."""
        return max((largest_finite(link.omega) for link in self.links.values()), default=0.0)

    @functools.cached_property
    def moving_scale(self) -> float:
        """The largest finite speed of a point of the state: a speed far below it is rest."""
        return max((largest_finite(point.v) for point in self.points.values()), default=0.0)

    # The rates' scales are at least what the speeds make (ω², v·ω): where every ε of one instant is nought but for
    # rounding (a crank at constant speed, a parallelogram's coupler), the largest would be that rounding itself.
    @functools.cached_property
    def turning_rate_scale(self) -> float:
        """The scale of the state's ε: one far below it at rest is rounding, no turning about to begin."""
        largest = max((largest_finite(link.epsilon) for link in self.links.values()), default=0.0)
        return max(largest, self.turning_scale ** 2)

    @functools.cached_property
    def moving_rate_scale(self) -> float:
        """The scale of the state's accelerations: one far below it at rest is rounding, no motion about to
        begin."""
        largest = max((largest_finite(point.a) for point in self.points.values()), default=0.0)
        return max(largest, self.moving_scale * self.turning_scale)


@dataclass(frozen=True)
class Rates:
    omega: float
    epsilon: float


def motion_state(motion: Motion) -> State:
    return State(motion.points, motion.links, {slide.slider: slide.velocity * slide.u for slide in motion.slides},
                 {slide.slider: slide.acceleration * slide.u for slide in motion.slides})


def plan_state(mechanism: Mechanism, positions: Mapping[str, complex], velocity: Plan,
               acceleration: Plan | None) -> State:
    """The state of one instant as read off its plans: velocities, accelerations, ω and ε of the plans.

    Without an acceleration plan (a velocity plan of every position) no
    acceleration is known: they stand as zero, so that the state serves the
    powers of the loads and the kinetic energy (the equivalent model), never
    an inertia load.
    """
    def accelerated(name: str) -> complex:
        return 0j if acceleration is None else acceleration.value(name)

    def epsilon(number: int) -> float:
        return 0.0 if acceleration is None else acceleration.rates.get(number, 0.0)

    points = {name: PointMotion(position, velocity.value(name), accelerated(name))
              for name, position in positions.items()
              if name in velocity.images and (acceleration is None or name in acceleration.images)}
    links: dict[int, Turning] = {number: Rates(velocity.rates.get(number, 0.0), epsilon(number))
                                 for number in mechanism.moving_links}
    links[mechanism.scene.frame_link] = Rates(0.0, 0.0)
    sliding = dict(velocity.sliding)
    sliding_acceleration = {} if acceleration is None else dict(acceleration.sliding)
    driver = mechanism.driver
    if driver.kind == "slider":  # on its frame guide, its own velocity is the sliding one
        sliding[driver.link] = velocity.value(driver.joint)
        sliding_acceleration[driver.link] = accelerated(driver.joint)
    return State(points, links, sliding, sliding_acceleration)


def has_loads(mechanism: Mechanism) -> bool:
    """Whether the scene gives the force analysis anything to work with (no masses, no loads: no forces)."""
    scene = mechanism.scene
    return bool(scene.loads) or any(spec.mass > 0 or spec.inertia > 0 for spec in scene.links.values())


def activity(mechanism: Mechanism, positions: PositionSet, motion: Motion) -> np.ndarray:
    """How much of each external load acts at each position of ``motion``: a ``(loads, N)`` array.

    ``motion`` may be any solution of the mechanism with the positions'
    reference (the analysed positions, a dense sweep for a diagram).  A
    load acts fully (1) or not at all (0), except one with a diagram, which
    acts by the diagram's share of its largest value.

    A window ``during = {from, to}`` is a share of the working stroke of the
    working link, measured by its travel (angle or displacement) from the
    extreme where the working stroke starts; of the load's own ``stroke``
    where it names one (a second cylinder's piston).
    """
    scene = mechanism.scene
    count = motion.count
    acting = np.ones((len(scene.loads), count))
    if not scene.loads:
        return acting
    # Each stroke once: several loads of one stroke (a shaper's cutting force and its window's edges) share it.
    in_stroke = functools.cache(lambda stroke: in_working_stroke(motion, stroke))
    progress = functools.cache(lambda stroke: stroke_share(mechanism, positions, motion, stroke))
    for row, load in enumerate(scene.loads):
        if load.during == "always":
            continue
        working = in_stroke(load.stroke)
        if load.during == "working":
            acting[row] = working
        elif load.during == "idle":
            acting[row] = ~working
        else:
            inside, share = _in_window(working, progress(load.stroke), load.during)
            if load.diagram is None:
                acting[row] = inside
            else:
                shares, values = np.array(load.diagram).T
                acting[row] = np.where(inside, np.interp(share, shares, values) / load.value, 0.0)
    return acting


def _in_window(working: np.ndarray, progress: np.ndarray, window: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Where a load given over ``window`` (shares of its stroke) acts, in the working stroke between the window's
    ends, and the share of the stroke travelled it is read at there, ``progress`` to 12 digits: equal ends then,
    so that a window that ends where a position lies includes it."""
    start, end = window
    share = np.round(progress, 12)
    return working & (share >= start) & (share <= end), share


def activity_at(mechanism: Mechanism, positions: PositionSet, values: np.ndarray, *,
                tolerant: bool = False) -> np.ndarray:
    """:func:`activity` at driver coordinates ``values``, read the same wherever they lie (``tolerant``: a
    singular one among them is not refused; its loads act as a working link at rest there decides).

    A window of the working stroke is measured by the working link's angle, which ``activity``
    unwraps about the first position of the motion it is given; that position is here always
    the start of the working stroke, so that a few positions far from it (a bisection's) are
    measured as the cycle's own are.
    """
    return _read_at(activity, mechanism, positions, values, tolerant)


def diagram_segments(mechanism: Mechanism, positions: PositionSet, motion: Motion) -> np.ndarray:
    """Which segment of its diagram each load with a ``diagram`` is on at each position of ``motion``: a
    ``(loads, N)`` array of integers, the count of the diagram's shares at or below the share of the stroke
    travelled (−1 where the load does not act; 0 for a load without a diagram).  Where it changes, the load's
    value has a corner (a vertex of the diagram): the reduced moment kinks there."""
    scene = mechanism.scene
    segments = np.zeros((len(scene.loads), motion.count), dtype=int)
    in_stroke = functools.cache(lambda stroke: in_working_stroke(motion, stroke))
    progress = functools.cache(lambda stroke: stroke_share(mechanism, positions, motion, stroke))
    for row, load in enumerate(scene.loads):
        if load.diagram is None:
            continue
        # Read as activity reads it, so that a segment is found wherever the load acts.
        inside, share = _in_window(in_stroke(load.stroke), progress(load.stroke), load.during)
        shares = np.array([vertex for vertex, _ in load.diagram])
        segments[row] = np.where(inside, np.searchsorted(shares, share, side="right"), -1)
    return segments


def load_corners(mechanism: Mechanism, positions: PositionSet, motion: Motion) -> np.ndarray:
    """What sets each load's value at a position apart from its neighbours', at each position of ``motion``: a
    ``(loads, N)`` array of codes, one row a load, that change where its :func:`diagram_segments` does (where it
    has a diagram; else where it starts or stops acting, :func:`activity`) and, for a resisting load where it
    acts, where the sense of the motion it opposes does (:func:`resisted_sense`: its link turns back).  Where a
    row changes between two positions, the load's reduced moment jumps there or turns a corner."""
    scene = mechanism.scene
    acting = activity(mechanism, positions, motion) > 0
    drawn = np.array([[load.diagram is not None] for load in scene.loads], dtype=bool)
    shares = np.where(drawn, diagram_segments(mechanism, positions, motion), acting) if drawn.size else acting
    state = motion_state(motion)
    with np.errstate(invalid="ignore"):
        senses = np.array([np.where(on, np.nan_to_num(np.broadcast_to(resisted_sense(load, state), (motion.count,))),
                                    0.0) if load.resisting else np.zeros(motion.count)
                           for load, on in zip(scene.loads, acting, strict=True)]).reshape(shares.shape)
    # One code a load (the sense −1, 0 or 1 beside the segment), so that a place where both change is found once.
    return 3 * shares.astype(int) + senses.astype(int) + 1


def load_corners_at(mechanism: Mechanism, positions: PositionSet, values: np.ndarray) -> np.ndarray:
    """:func:`load_corners` at driver coordinates ``values``, read as :func:`activity_at` reads them."""
    return _read_at(load_corners, mechanism, positions, values, False)


def _read_at(read: Callable[[Mechanism, PositionSet, Motion], np.ndarray], mechanism: Mechanism,
             positions: PositionSet, values: np.ndarray, tolerant: bool) -> np.ndarray:
    """``read`` of a motion solved at ``values``, with the start of the working stroke put first (see
    :func:`activity_at`)."""
    if positions.extremes is None:
        return read(mechanism, positions, solve(mechanism, values, positions.reference, tolerant=tolerant))
    padded = np.concatenate([[positions.extremes[0]], values])
    return read(mechanism, positions, solve(mechanism, padded, positions.reference, tolerant=tolerant))[:, 1:]


def with_switches(sweep: np.ndarray, state: Callable[[np.ndarray], np.ndarray]) -> np.ndarray:
    """``sweep`` with the two sides of every place where ``state`` (an array of rows over driver coordinates)
    changes between two samples put in, each found by bisection to :data:`SWITCH_TOLERANCE` of the step."""
    now = state(sweep)
    rows, steps = np.nonzero(now[:, :-1] != now[:, 1:])
    if len(rows) == 0:
        return sweep
    low, high = sweep[steps].copy(), sweep[steps + 1].copy()
    before = now[rows, steps]
    tolerance = SWITCH_TOLERANCE * float(np.max(np.abs(np.diff(sweep))))
    for _ in range(_MAX_BISECTIONS):
        if np.all(np.abs(high - low) <= tolerance):
            break
        middle = 0.5 * (low + high)
        # Rest is judged against the largest speed of the positions judged together: the middles beside the
        # sweep, as the sweep with them in is judged after, not among a few positions all near rest.
        same = state(np.concatenate([sweep, middle]))[rows, len(sweep) + np.arange(len(rows))] == before
        low = np.where(same, middle, low)
        high = np.where(same, high, middle)
    # A side that falls on a sample is that sample (the same position, the same loads): kept once.
    found = np.unique(np.concatenate([sweep, low, high]))
    return found if sweep[-1] > sweep[0] else found[::-1]


def stroke_share(mechanism: Mechanism, positions: PositionSet, motion: Motion,
                 stroke: Working | None = None) -> np.ndarray:
    """The share of the working stroke (of ``stroke``, a load's own, or the working link's) travelled at each
    position (0 at its start)."""
    start, end = stroke_ends(mechanism, positions, stroke)
    here = _output_coordinate(mechanism, motion, stroke, about=start)
    return (here - start) / (end - start)


def stroke_travel(mechanism: Mechanism, positions: PositionSet, stroke: Working | None = None) -> float:
    """How far the working link (or ``stroke``'s) travels in its working stroke: m along a guide, rad turning."""
    start, end = stroke_ends(mechanism, positions, stroke)
    return abs(end - start)


def stroke_ends(mechanism: Mechanism, positions: PositionSet, stroke: Working | None) -> tuple[float, float]:
    """The working link's (or ``stroke``'s) coordinate where its working stroke starts and where it ends."""
    extremes = stroke_extremes(positions, stroke)
    assert extremes is not None, "mechanism.build requires a crank driver for a window of the stroke"
    ends = solve(mechanism, np.array(extremes), positions.reference)
    start, end = _output_coordinate(mechanism, ends, stroke)
    return float(start), float(end)


def _output_coordinate(mechanism: Mechanism, motion: Motion, stroke: Working | None = None,
                       about: float | None = None) -> np.ndarray:
    """The working link's (or ``stroke``'s link's) angle, within half a turn of ``about`` (default: its first
    angle in ``motion``), or its displacement along its direction.

    A window of the stroke is measured from the stroke's start: unwrapped
    about any other angle, a swing across ±180° would be cut in two.
    """
    working = stroke or mechanism.scene.positions.working
    assert working is not None
    link = motion.links[working.link]
    if working.link in mechanism.translating:
        return np.broadcast_to(dot(link.u, motion.points[link.origin].r), motion.driver.shape)
    angle = np.broadcast_to(np.asarray(link.angle, dtype=float), motion.driver.shape)
    reference = float(angle[0]) if about is None else about
    return reference + np.angle(np.exp(1j * (angle - reference)))


def link_loads(mechanism: Mechanism, state: State, acting: np.ndarray | None = None) -> tuple[Load, ...]:
    """Every load on every moving link in the order the textbook's table lists them.

    ``acting`` is :func:`activity` for the positions of ``state`` (one
    column for one instant); None lets every external load act.
    """
    scene = mechanism.scene
    found: list[Load] = []
    for number in mechanism.moving_links:
        spec = scene.links.get(number)
        if spec is None:
            continue
        centre = spec.centre
        if spec.mass > 0 and scene.gravity != 0:
            found.append(Load(f"G{number}", number, centre, -1j * spec.mass * scene.gravity, 0.0))
        inertia_force = -spec.mass * state.points[centre].a if spec.mass > 0 else None
        inertia_moment = -spec.inertia * state.links[number].epsilon if spec.inertia > 0 else None
        if scene.inertia == "displaced" and inertia_force is not None and inertia_moment is not None:
            found.extend(_displaced(number, centre, inertia_force, inertia_moment))
            continue
        if inertia_force is not None:
            found.append(Load(f"Fu{number}", number, centre, inertia_force, 0.0))
        if inertia_moment is not None:
            found.append(Load(f"Mu{number}", number, None, 0j, inertia_moment))
    found.extend(_external(mechanism, state, acting))
    return tuple(found)


def _displaced(number: int, centre: str, force: Vector, moment: Scalar) -> list[Load]:
    """The inertia force and moment of a link as one resultant Fu displaced by h = Mu/Fu from the centre.

    Where Fu vanishes (a centre at rest) there is no resultant to displace,
    and Mu stays a couple at those positions.
    """
    force_array, moment_array = np.broadcast_arrays(np.asarray(force, dtype=complex), np.asarray(moment, dtype=float))
    size = np.abs(force_array)
    movable = size > _AT_REST * max(float(np.max(size)), 1e-300)
    square = np.where(movable, size * size, 1.0)
    # cross(offset, Fu) = Mu for the offset across Fu: offset = −i·Fu·Mu/|Fu|².
    offset = np.where(movable, -1j * force_array * moment_array / square, 0j)
    left = np.where(movable, 0.0, moment_array)
    if np.ndim(force) == 0 and np.ndim(moment) == 0:
        offset, left = complex(offset), float(left)
    loads = [Load(f"Fu{number}", number, centre, force, 0.0, offset)]
    if np.any(left != 0):
        loads.append(Load(f"Mu{number}", number, None, 0j, left))
    return loads


def external_names(loads: tuple[LoadSpec, ...]) -> tuple[str, ...]:
    """The name of each of the scene's loads as the force analysis gives it: F4, M3, and F4.1, F4.2 where a
    link has several (the force sheets, the note and the load diagrams name them alike)."""
    per_link: dict[int, int] = {}
    for load in loads:
        per_link[load.link] = per_link.get(load.link, 0) + 1
    seen: dict[int, int] = {}
    names = []
    for load in loads:
        seen[load.link] = seen.get(load.link, 0) + 1
        suffix = f".{seen[load.link]}" if per_link[load.link] > 1 else ""
        names.append(f"{'M' if load.kind == 'moment' else 'F'}{load.link}{suffix}")
    return tuple(names)


def _external(mechanism: Mechanism, state: State, acting: np.ndarray | None) -> list[Load]:
    scene = mechanism.scene
    found = []
    for row, (load, name) in enumerate(zip(scene.loads, external_names(scene.loads), strict=True)):
        on = 1.0 if acting is None else acting[row].astype(float)
        if np.ndim(on) and len(on) == 1:
            on = float(on[0])
        if load.resisting:
            # A resisting load opposes the motion whatever the sign its diagram is drawn with.
            on = np.abs(on)
        value = given_value(load, state)
        if load.kind == "moment":
            value = -abs(value) * resisted_sense(load, state) if load.resisting else value
            found.append(Load(name, load.link, None, 0j, on * value))
        else:
            direction = line_of_action(load, state)
            force = -abs(value) * direction * resisted_sense(load, state) if load.resisting else value * direction
            found.append(Load(name, load.link, load.point, on * force, 0.0))
    return found


def given_value(load: LoadSpec, state: State) -> Scalar:
    """A load's value at the positions of ``state``, before its window and a resisting load's sense: a spring's its
    length's (:func:`spring_value`), which the scene gives no value for; any other's as the scene gives it (a
    diagram's largest magnitude, which its shares scale)."""
    return spring_value(load, state) if load.spring else load.value


def spring_length(load: LoadSpec, state: State) -> Scalar:
    """A spring's length L: how far its ``point`` is from the point it is ``along``, m."""
    length = np.abs(state.points[load.point].r - state.points[load.along].r)
    return float(length) if np.ndim(length) == 0 else length


def spring_value(load: LoadSpec, state: State) -> Scalar:
    """A spring's force along its line from ``along`` to its point, N: −k·(L − L0), so that stretched past its free
    length it pulls its point toward ``along`` (negative, as a force's value pulling there is) and squeezed short of
    it pushes its point away."""
    return -load.stiffness * (spring_length(load, state) - load.free_length)


def resisted_sense(load, state: State) -> Scalar:
    """The sense of the motion a resisting load opposes (:func:`sense_of_motion`): its link's turning for a
    moment, its point's motion along the load's line for a force."""
    # A point that never moves along the load's line (a force square to a slider's guide), a link that never turns
    # (a parallelogram's coupler): its speed and its rate there are rounding, whose signs turned the load to and fro.
    if load.kind == "moment":
        turning = state.links[load.link]
        return sense_of_motion(turning.omega, turning.epsilon, state.turning_scale, state.turning_rate_scale)
    direction, point = line_of_action(load, state), state.points[load.point]
    rate = dot(direction, point.a)
    if load.along is not None:
        # The line turns: d(v·e)/dt = a·e + v·ė, ė = (ḋ − e·(e·ḋ))/|d| with d from the far end to the point.
        far = state.points[load.along]
        reach, closing = point.r - far.r, point.v - far.v
        length = np.abs(reach)
        turning = (closing - direction * dot(direction, closing)) / np.where(length > 0, length, 1.0)
        rate = rate + dot(point.v, turning)
    return sense_of_motion(dot(direction, point.v), rate, state.moving_scale, state.moving_rate_scale)


def line_of_action(load: LoadSpec, state: State) -> Vector:
    """The unit vector of a force's line in its positive sense: at its fixed angle, or (``along``) from the point
    it acts along to its own point, a line that turns as the mechanism moves (a cylinder or a spring pinned there).

    Where the two points meet there is no line, and no force: an analysed position where they do is refused
    (:func:`refuse_lines_without_length`), but a sweep between positions may pass one.
    """
    if load.along is None:
        return unit(radians_within_a_turn(load.angle_deg))
    reach = state.points[load.point].r - state.points[load.along].r
    length = np.abs(reach)
    direction = np.where(length > 0, reach / np.where(length > 0, length, 1.0), 0j)
    return complex(direction) if np.ndim(direction) == 0 else direction


# Two points this near (against the farthest they come apart) meet: the line between them has no direction.
_MEET = 1e-9


def refuse_lines_without_length(mechanism: Mechanism, motion: Motion, numbers: np.ndarray | None = None) -> None:
    """Refuse a force ``along`` a point that meets its own point somewhere in ``motion``: the line it acts along is
    then no line.  ``numbers`` names ``motion``'s positions; without them (a sweep) the driver's value is named."""
    for load in mechanism.scene.loads:
        if load.along is None:
            continue
        reach = np.abs(np.asarray(motion.points[load.point].r - motion.points[load.along].r))
        apart = reach[np.isfinite(reach)]
        if not apart.size:
            continue
        met = np.flatnonzero(reach <= _MEET * max(float(np.max(apart)), 1e-300))
        if not met.size:
            continue
        index = int(met[0])
        if numbers is not None:
            at = f"at position {int(numbers[index])}"
        elif mechanism.driver.cyclic:
            at = f"at the crank's {math.degrees(float(motion.driver[index])) % 360.0:.4g}°"
        else:
            at = f"at the slider's {float(motion.driver[index]):.6g} m"
        where = complex(np.ravel(motion.points[load.point].r)[index])
        raise SceneError(f"{load.where}.along", f"{load.along} meets {load.point} {at}, at ({where.real:.6g}, "
                         f"{where.imag:.6g}) m, where there is no line between them for the force to act along: "
                         f"name a point that stays clear of {load.point}, or give the force an angle", load.along)


def along_moving_points(mechanism: Mechanism) -> tuple[PositionWarning, ...]:
    """An ``along-moving-point`` warning for each force ``along`` a point of a moving link: a spring or a cylinder
    pinned there pushes that link back, which the scene gives no load for (a cylinder between two moving links is
    two loads, one at each end along the other's point), or, where the point is on the load's own link, pushes the
    link on itself and moves nothing: the force is taken as one from outside, turning with the line."""
    scene = mechanism.scene
    told = []
    for load in scene.loads:
        if load.kind != "force" or load.along is None or load.along in scene.frame_points:
            continue
        carriers = sorted(link for link in mechanism.moving_links if load.along in mechanism.fixed_on.get(link, ()))
        what = "spring" if load.spring else "cylinder"
        if load.link in carriers:
            told.append(PositionWarning(0, "along-moving-point", (
                f"{load.where} acts along {load.along}, a point of link {load.link}, the link it acts on: a {what} "
                f"between two points of one link pushes it on itself and moves nothing; the force is taken as one "
                f"from outside along {load.along}→{load.point}, turning with link {load.link}")))
            continue
        # The load at the cylinder's other end, on the link that carries the point this one is along.
        if not carriers or any(other.kind == "force" and other.ends == load.ends and other.point == load.along
                               and other.link in carriers for other in scene.loads):
            continue
        given = "stiffness and free_length" if load.spring else "value"
        told.append(PositionWarning(0, "along-moving-point", (
            f"{load.where} acts along {load.along}, a point of moving link {carriers[0]}: a {what} pinned there "
            f"pushes link {carriers[0]} back at {load.along}, which no load of the scene does; give it as "
            f"[[loads]] kind = \"force\", link = {carriers[0]}, point = \"{load.along}\", along = \"{load.point}\" "
            f"with the same {given}, or pin the {what} at a frame point")))
    return tuple(told)


def refuse_resisting_along_no_motion(mechanism: Mechanism, motion: Motion) -> None:
    """Refuse a resisting force ``along`` a point whose own point never moves along the line between them, nor is
    about to, at any position of ``motion`` (a point of a link that turns about the point it is along): the force
    acted nowhere, without a word, as one square to its point's only guide would (which the mechanism refuses)."""
    state = None
    for load in mechanism.scene.loads:
        if load.kind != "force" or load.along is None or not load.resisting:
            continue
        state = state or motion_state(motion)
        if np.any(np.nan_to_num(np.asarray(resisted_sense(load, state), dtype=float)) != 0):
            continue
        raise SceneError(f"{load.where}.resisting", f"{load.point} never moves along the line from {load.along} at "
                         f"any position (it moves square to it, as a point of a link turning about {load.along} "
                         "does), so a force along that line has no motion to resist: name another point for it to "
                         "act along, or give it a set sense (resisting = false)")


def sense_of_motion(speed: Scalar, rate: Scalar, scale: float, rate_scale: float = 0.0) -> Scalar:
    """+1 or −1: the sense of motion, or at rest (against the mechanism's ``scale`` of speeds)
    the sense of the motion about to begin; 0 at rest with nothing about to begin (a ``rate`` that is
    rounding against ``rate_scale``, where one is given)."""
    speed_array, rate_array = np.asarray(speed, dtype=float), np.asarray(rate, dtype=float)
    about = np.where(at_rest(rate_array, rate_scale), 0.0, np.sign(rate_array)) if rate_scale > 0.0 \
        else np.sign(rate_array)
    return np.where(at_rest(speed_array, scale), about, np.sign(speed_array))


def at_rest(speed: Scalar | Vector, scale: float) -> Scalar:
    """Whether ``speed`` (or a velocity's size) is rest against the mechanism's ``scale`` of speeds: at an
    extreme position it is zero but for rounding, and its sign says nothing."""
    return np.abs(speed) <= _AT_REST * max(scale, 1e-300)


def load_at(load: Load, index: int) -> Load:
    """The load at position ``index`` of an array state."""
    return Load(load.name, load.link, load.point, complex(at(load.force, index)), float(at(load.moment, index)),
                complex(at(load.offset, index)))


def power(loads: tuple[Load, ...], state: State) -> Scalar:
    """Σ(F·v + M·ω) of the loads: the power they deliver to the mechanism (not a number at a singular
    position of an array state, whose velocities are not)."""
    total: Scalar = 0.0
    with np.errstate(invalid="ignore"):
        for load in loads:
            if load.is_force:
                # A displaced force's point moves with its link: v + ω × offset.
                velocity = state.points[load.point].v
                if np.any(load.offset != 0):
                    velocity = velocity + 1j * state.links[load.link].omega * load.offset
                total = total + dot(load.force, velocity)
            else:
                total = total + load.moment * state.links[load.link].omega
    return total


__all__ = ["SWITCH_TOLERANCE", "Load", "Rates", "State", "activity", "activity_at", "at_rest", "external_names",
           "has_loads", "line_of_action", "link_loads", "load_at", "motion_state", "plan_state", "power",
           "refuse_lines_without_length", "refuse_resisting_along_no_motion",
           "resisted_sense", "sense_of_motion", "spring_length", "spring_value", "stroke_ends", "stroke_share",
           "stroke_travel", "with_switches"]
