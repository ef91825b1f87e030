"""Where a crank cannot go, what to tell the user: the ranges of its reach, a swing the run then takes, or a
triad sketched mirrored.

A scene's crank meets a position it cannot assemble at: the error says where it can go instead, as advice the user
can paste back (the swing advised is one the run itself accepts, found by analysing the scene rocking over it).
"""

from __future__ import annotations

import contextlib
import functools
import math
from collections.abc import Callable, Iterator
from dataclasses import replace

import numpy as np

from .errors import AssemblyError, GraphplanError, SingularPositionError, as_written, verdict_only, words_wanted
from .groups.base import Group
from .length_units import given_lengths, mixed_units
from .mechanism import Mechanism, build
from .motion import Motion, reference_at, solve
from .positions import FULL_TURN, first_value, reach, travel_reach, turns_round
from .rounding import noise_floor
from .scene import Scene
from .unit_slips import angles_in_radians


@contextlib.contextmanager
def reach_hint(mechanism: Mechanism, first: float | None = None) -> Iterator[None]:
    """Where a crank cannot go, say where it can: the ranges of its reach, and a swing inside one of them; or, for
    values a caller gave (``first`` the first of them, where the assemblies were taken), that they keep within one."""
    try:
        yield
    except AssemblyError as error:
        # Within _swing_that_runs's trials the words are dropped: the reach and advice are not worked out for them
        # (they took the crank's reach again, some 720 solves of a triad, for every swing tried).
        if not words_wanted():
            raise
        keys = keys_setting(mechanism, error.group)
        advised = _advised(mechanism, error, first, keys)
        raise advised from error


def _advised(mechanism: Mechanism, error: AssemblyError, first: float | None,
             keys: list[tuple[str, str]]) -> AssemblyError:
    """``error`` told with the scene's keys that set what does not close (the position it names says where) and
    the advice where there is one: a refusal that named only the joints' letters left the student to find which of
    the scene's keys give them."""
    # The keys right after the arithmetic they set, before any advice: what to change, then how.
    named = f"; the scene's keys that set it: {', '.join(told for _, told in keys)}" if keys else ""

    def told(advice: str = "") -> AssemblyError:
        return AssemblyError(error.joint, error.position, error.group,
                             f"{error.reason}{named}{f'; {advice}' if advice else ''}", tuple(key for key, _ in keys))

    # A length in millimetres among metres: the reach and the swing it allows would be advice about a typo.
    if (units := mixed_units(mechanism)) is not None:
        return told(units)
    # So would be a swing or a guide's angle typed in radians: [0.5236, 1.0472] rocks the crank where it cannot go.
    if slips := angles_in_radians(mechanism, loads=False):
        return told("; ".join(slip.detail for slip in slips))
    driver = mechanism.driver
    stopping = next((group.reach_ends for group in mechanism.groups if group.label == error.group),
                    Group.reach_ends)
    if driver.kind == "slider":
        advice = _travel_advice(mechanism, stopping)
        return told(advice or "")
    if driver.kind != "crank":
        return told()
    taken = None
    if first is not None:
        with contextlib.suppress(AssemblyError, SingularPositionError):
            taken = reference_at(mechanism, first)
    ranges = reach(mechanism, taken)
    if ranges == FULL_TURN:  # it turns round in the scene's assembly: the solve lost its branch
        return told()
    if not ranges and (copied := _frame_points_at_one_place(mechanism)) is not None:
        return told(copied)
    if not ranges and (turned_over := _mirrored_sketch(mechanism)) is not None:
        return told(turned_over)
    if not ranges and (stopped := _stopped_nowhere(mechanism, error.group)) is not None:
        return told(f"the mechanism assembles at no angle of link {driver.link}: {stopped}"
                    f"{_placed_by(mechanism, error.group)}")
    # The caller's own values are theirs to keep within the reach; a scene's crank may rock instead.
    if first is not None:
        advice = _reach_advice(driver.link, ranges, False, stopping, "the values")
    else:
        rocking, changes = _rocking_changes(mechanism.scene)
        advice = _reach_advice(driver.link, ranges, driver.cyclic, stopping,
                               runs=functools.partial(_swing_that_runs, rocking), also=changes)
        if driver.cyclic and ranges:
            checks = [told for told in (_turning_round(mechanism, error.group),
                                        _slipped_digit(mechanism, error.group)) if told is not None]
            if checks:
                advice += f"; or, if link {driver.link} is meant to turn round, check the lengths: {'; '.join(checks)}"
    if not ranges:
        advice += _placed_by(mechanism, error.group)
    return told(advice)


# The keys of a group's table that give its own lengths and offsets (a triad's lengths and sides too).
_GROUP_LENGTH_KEYS = ("length", "lengths", "sides", "offset", "offsets")


def keys_setting(mechanism: Mechanism, label: str) -> list[tuple[str, str]]:
    """The scene's keys that set what the group ``label`` closes, each with how it is told (a length with its value
    as typed): the group's own lengths and offsets and its guides, then what places each joint it joins on to (the
    crank's length and pivot, a frame point, a named point's entry, the earlier group that places it).  Empty where
    no group has that label (the driver's own refusal names its key itself)."""
    group = next((group for group in mechanism.groups if group.label == label), None)
    if group is None:
        return []
    found: dict[str, str] = {}
    for key in _GROUP_LENGTH_KEYS:
        value = getattr(group, key, None)
        if key == "lengths" and value is not None:  # as written: a triad's lists its turning legs only
            value = [length for length in value if length]
        # An offset left at nought is none the scene set; a length always is.
        if value is not None and (key not in ("offset", "offsets") or any(np.atleast_1d(value))):
            found[f"{group.where}.{key}"] = f"{group.where}.{key} = {as_written(value)}"
    for guide in group.guides():
        found.setdefault(guide.where, guide.where)
    scene, driver = mechanism.scene, mechanism.driver
    named = {spec.name: spec.where for spec in scene.points}
    for joint in group.known_joints():
        if joint in scene.frame_points:
            found.setdefault(f"frame.points.{joint}", f"frame.points.{joint}")
        elif joint in named:
            found.setdefault(named[joint], named[joint])
        elif driver.kind == "crank" and joint == driver.joint:
            found.setdefault(f"{driver.where}.length", f"{driver.where}.length = {as_written(driver.length)}")
            found.setdefault(f"frame.points.{driver.pivot}", f"frame.points.{driver.pivot}")
        elif driver.kind == "slider" and joint == driver.joint:
            found.setdefault(f"{driver.where}.travel", f"{driver.where}.travel = {as_written(list(driver.travel))}")
            found.setdefault(driver.guide.where, driver.guide.where)
        else:
            placing = next((other for other in mechanism.groups if joint in other.new_joints()), None)
            where = placing.where if placing is not None else driver.where
            found.setdefault(where, where)
    return list(found.items())


# A length typed a digit off, 0.05 for 0.5: each of the stopping group's lengths is tried this many times longer
# and shorter, alone.
_SLIPS = (10.0, 0.1)


def _slipped_digit(mechanism: Mechanism, label: str) -> str | None:
    """Which length of the group ``label``, a digit off (:data:`_SLIPS`), would let the crank turn round, in words;
    None where none alone would.  A student's DE = 0.05 for 0.5 was advised to rock the crank over the part of the
    turn it reaches, when the crank of a course's mechanism is meant to turn round."""
    scene = mechanism.scene
    found = []
    for n, group in enumerate(scene.groups):
        if group.label != label:
            continue
        for key, value, changed in _lengths_of(group):
            for slip in _SLIPS:
                other = replace(scene, groups=(*scene.groups[:n], changed(value * slip), *scene.groups[n + 1:]))
                try:
                    turns = turns_round(build(other))
                except GraphplanError:
                    continue
                if turns:
                    found.append(f"{key} = {value * slip:.6g}, a digit off the {value:.6g} m given, turns it round")
    return "; ".join(found) or None


def _lengths_of(group: Group) -> Iterator[tuple[str, float, Callable[[float], Group]]]:
    """Each length the group's table gives, with its key and a maker of the group with it changed: its ``length``,
    and its ``lengths`` (a triad's list its turning legs only, its sliding legs' 0 left out, as written)."""
    if getattr(group, "length", 0.0):
        yield f"{group.where}.length", group.length, lambda value: replace(group, length=value)
    lengths = getattr(group, "lengths", ())
    for k, n in enumerate(n for n, length in enumerate(lengths) if length):
        yield (f"{group.where}.lengths[{k}]", lengths[n],
               lambda value, n=n: replace(group, lengths=(*lengths[:n], value, *lengths[n + 1:])))


# A hundredth of a degree: the farthest or nearest a group reads off the sweep of the crank is then the true one to
# some 10⁻¹⁰ of its lengths.
_NOWHERE_SWEEP = 36000


def _placed_by(mechanism: Mechanism, label: str) -> str:
    """Where the group ``label`` joins a named point of an earlier link (a shaper's rod pinned at D, up the slotted
    lever), the key that places it, told after the lengths to check: no length of the group's is wrong where that
    point's ``at`` is, and nothing else names it.  Empty where the group joins only joints."""
    group = next((group for group in mechanism.groups if group.label == label), None)
    named = {spec.name: spec for spec in mechanism.scene.points}
    placed = [named[joint] for joint in (group.known_joints() if group is not None else ()) if joint in named]
    return "".join(f", and where {spec.where} places {spec.name}: at = {spec.at:g} m from {spec.start} toward "
                   f"{spec.toward}" + (f", offset = {spec.offset:g} m to its left" if spec.offset else "")
                   for spec in placed)


def _stopped_nowhere(mechanism: Mechanism, label: str) -> str | None:
    """Where a crank's mechanism assembles at no angle, what in the geometry of the group ``label`` stops it (its
    :meth:`~graphplan.groups.base.Group.nowhere`), read off the groups before it, in the assemblies the scene's
    first position gives them, over the turn or the parts of it where they assemble; None where the group has
    nothing to say, or those before it assemble nowhere either."""
    return _read_off_before(mechanism, label, lambda group, before: group.nowhere(before), whole_turn=False)


def _turning_round(mechanism: Mechanism, label: str) -> str | None:
    """Where a crank reaches only part of its turn, what the lengths of the group ``label`` that stops it must be
    for it to turn round (its :meth:`~graphplan.groups.base.Group.turning_round`), read off the groups before it
    over the whole turn; None where those do not turn round themselves, or the group has nothing to say.  A
    student told only where the first position failed lengthened the rod past that and was refused at the next."""
    return _read_off_before(mechanism, label, lambda group, before: group.turning_round(before), whole_turn=True)


def _read_off_before(mechanism: Mechanism, label: str, read: Callable[[Group, Motion], str | None],
                     whole_turn: bool) -> str | None:
    """What ``read`` says of the group ``label`` from the motion of the groups before it, in the assemblies the
    scene's first position gives them, over the turn (``whole_turn``: all of it, else the parts of it where they
    assemble); None where they assemble nowhere (or not all round, ``whole_turn``)."""
    step = next((n for n, unit in enumerate(mechanism.units) if n and unit.solver.label == label), None)
    if step is None:
        return None
    before = replace(mechanism, units=mechanism.units[:step])
    try:
        reference = reference_at(before, first_value(before))
        ranges = ((0.0, 2.0 * math.pi),) if whole_turn else reach(before, reference)
        if not ranges:
            return None
        values = np.concatenate([np.linspace(low, high, _NOWHERE_SWEEP + 1) for low, high in ranges])
        return read(mechanism.units[step].solver, solve(before, values, reference, tolerant=True))
    except GraphplanError:
        return None


def _travel_advice(mechanism: Mechanism, stopping: str = Group.reach_ends) -> str | None:
    """What part of a slider's typed travel the mechanism assembles over, and a travel within it that runs; None
    where it is all of it (the solve lost its assembly, and the lengths are no help); ``stopping`` says what stops
    it at the ends."""
    travel = mechanism.driver.travel
    ranges = travel_reach(mechanism)
    if ranges == (travel,):
        return None
    where = "along the travel typed the mechanism assembles only"
    if not ranges:
        # Past the travel typed: as far as the frame's points and the groups' lengths reach from the guide's point.
        bound = _farthest_reach(mechanism)
        ranges = travel_reach(mechanism, (-bound, bound))
        if not ranges:
            return "the mechanism assembles nowhere along driver.travel: check the lengths"
        where = "the mechanism assembles nowhere along the travel typed, only"
        ends = f"at each end {stopping}"
        middle = 0.5 * (travel[0] + travel[1])
        nearest = min(ranges, key=lambda span: abs(0.5 * (span[0] + span[1]) - middle))
    else:
        ends = f"an end inside the travel typed is a dead centre: {stopping}"
        nearest = max(ranges, key=lambda span: abs(span[1] - span[0]))
    quantum = 10.0 ** (math.floor(math.log10(abs(travel[1] - travel[0]))) - 5)
    spans = " and ".join(f"from s = {_inward_m(first, last, quantum)} m to s = {_inward_m(last, first, quantum)} m"
                         for first, last in ranges)
    # An end inside the typed travel is a dead centre: singular, and refused as the first position.
    first, last = nearest
    inset = 0.01 * (last - first)
    example = [end if end in travel else end + sign * inset for end, sign in ((first, 1.0), (last, -1.0))]
    quantum = 10.0 ** (math.floor(math.log10(abs(inset))) - 1)
    return (f"{where} {spans} ({ends}): keep driver.travel within {'it' if len(ranges) == 1 else 'one'}"
            f", e.g. driver.travel = [{_inward_m(example[0], example[1], quantum)}, "
            f"{_inward_m(example[1], example[0], quantum)}]")


def _farthest_reach(mechanism: Mechanism) -> float:
    """How far along its guide a slider driver can be from the guide's point and the mechanism still close: no
    farther than the frame's points and every length of its groups laid end to end, nor than the travel typed."""
    # Wherever the guide's point is among the frame's, twice their farthest from the origin covers the way to it.
    frame = 2.0 * max((abs(point) for point in mechanism.scene.frame_points.values()), default=0.0)
    lengths = sum(value for _, value in given_lengths(mechanism))
    return max(frame + lengths, *(abs(end) for end in mechanism.driver.travel))


def _frame_points_at_one_place(mechanism: Mechanism) -> str | None:
    """Where a mechanism assembles nowhere and two of its frame points stand at one place, that is the likelier slip
    than a length: a coordinate copied from the other point leaves no frame between them.  (Links meant to turn about
    one axis may share a place: such a mechanism runs where its lengths close it, so this is told only where they
    do not.)  None where every frame point has a place of its own."""
    points = mechanism.scene.frame_points
    noise = noise_floor([*(abs(point) for point in points.values()),
                         *(value for _, value in given_lengths(mechanism))])
    names = list(points)
    for n, first in enumerate(names):
        for second in names[n + 1:]:
            if abs(points[second] - points[first]) <= noise:
                place = points[first]
                return (f"frame points {first} and {second} stand at one place, [{place.real:.6g}, {place.imag:.6g}], "
                        f"so the links pivoted at them turn about one axis: give {second} its own place (its "
                        f"coordinates copied from {first}?), or check the lengths")
    return None


def _inward_m(end: float, other_end: float, quantum: float) -> str:
    """An end of a travel to ``quantum`` (m), rounded towards ``other_end`` past the bisection's last digits, so
    that a travel to it as written assembles."""
    rounding = math.ceil if other_end > end else math.floor
    return f"{rounding(round(end / quantum, 4)) * quantum + 0.0:.6g}"


def _mirrored_sketch(mechanism: Mechanism) -> str | None:
    """Where a mechanism assembles at no angle of its crank, but would with a group's sketched orientation turned
    over (a triad's corners sketched running the other way round): what to sketch instead.  None where that is
    not so, and the lengths are to check."""
    scene = mechanism.scene
    for n, group in enumerate(scene.groups):
        turned = group.mirrored()
        if turned is None:
            continue
        other = replace(scene, groups=(*scene.groups[:n], turned, *scene.groups[n + 1:]))
        try:
            ranges = reach(build(other))
        except GraphplanError:
            continue
        if not ranges:
            continue
        sketch, mirrored = dict(group.near), dict(turned.near)
        b, d, f = group.inner_joints
        running = "counter-clockwise" if ((sketch[d] - sketch[b]).conjugate() * (sketch[f] - sketch[b])).imag > 0 \
            else "clockwise"
        other_way = {"clockwise": "counter-clockwise", "counter-clockwise": "clockwise"}[running]
        where = mirrored[f]
        reaches = "" if ranges == FULL_TURN else " (" + "; ".join(
            f"link {mechanism.driver.link} then reaches from {_inward(low, math.ceil)}° to {_inward(high, math.floor)}°"
            for low, high in ranges) + ")"
        return (f"the mechanism assembles at no angle of link {mechanism.driver.link} as sketched: {group.where}.near "
                f"runs {b}, {d}, {f} {running} round the ternary link {group.ternary}, and its lengths close it only "
                f"the other way round, {other_way}: the lengths are right, the sketch is mirrored; sketch {f} on the "
                f"other side of {b}{d}, e.g. {f} = [{where.real:.4g}, {where.imag:.4g}] (its mirror image across "
                f"{b}{d}){reaches}")
    return None


def _inward(end: float, rounding) -> str:
    """An end of the reach in degrees to two places, rounded towards the inside (``math.ceil`` at a lower end)
    past the bisection's last digits, which would make -60° -59.99°."""
    return f"{rounding(round(math.degrees(end) * 100.0, 4)) / 100.0:.2f}"


def _reach_advice(link: int, ranges: tuple[tuple[float, float], ...], cyclic: bool,
                  stopping: str = Group.reach_ends, kept: str = "driver.swing",
                  runs: Callable[[float, float], tuple[int, int] | None] | None = None,
                  also: tuple[str, ...] = ()) -> str:
    """What a crank's reach allows, in degrees: the ranges and, for one meant to turn round, a swing to try (of
    ``runs``, the swing within a range that the run takes, where given) with what else the scene must change to
    rock (``also``); ``stopping`` says what stops it at the ends, ``kept`` what is to keep within them."""
    if not ranges:
        return f"the mechanism assembles at no angle of link {link}: check the lengths"
    # Rounded inward: a swing to an end as written is then inside the reach (70.49° of a reach to 70.4907° was
    # written 70.5° and refused).
    spans = " and ".join(f"from {_inward(low, math.ceil)}° to {_inward(high, math.floor)}°" for low, high in ranges)
    told = f"link {link} reaches only {spans} (at each end {stopping})"
    if not cyclic:
        return f"{told}: keep {kept} within one of these"
    low, high = max(ranges, key=lambda span: span[1] - span[0])
    if runs is not None:
        swing = runs(low, high)
    else:
        # A degree short of each end, where the velocities are determined.
        first, last = math.ceil(math.degrees(low) + 1.0), math.floor(math.degrees(high) - 1.0)
        swing = (first, last) if last > first else None
    example = f", e.g. driver.swing = [{swing[0]}, {swing[1]}]" if swing is not None else ""
    changes = f"; a rocking crank's positions run once over its swing, so also {', and '.join(also)}" if also else ""
    return (f"{told}; since it cannot turn round, drive it as a rocker: driver.swing = [from, to] in degrees{example}"
            f"{changes}")


def _rocking_changes(scene: Scene) -> tuple[Scene, tuple[str, ...]]:
    """The scene as it must change, besides its swing, for its crank to rock, and those changes in words: the
    start, a load's window or diagram of the working stroke, the flywheel and the equation of motion all need a
    turn (the swing alone was advised, and the scene that followed it was refused at the next of them)."""
    changes = []
    if scene.positions.start_given or scene.positions.start != 0.0:  # start = 0 written is refused beside a swing
        changes.append("leave positions.start out")
    loads = []
    for load in scene.loads:
        if load.diagram is not None:
            changes.append(f'give {load.where} a value in place of its diagram, with during = "working"')
            load = replace(load, diagram=None, value=max((value for _, value in load.diagram), key=abs),
                           during="working")
        elif isinstance(load.during, tuple):
            changes.append(f'give {load.where}.during = "working" (or "idle", "always") in place of its window')
            load = replace(load, during="working")
        loads.append(load)
    dynamics = scene.dynamics
    if dynamics is not None:
        turning = [key for key, value in (("delta", dynamics.delta), ("rpm or omega", dynamics.omega),
                                          ("flywheel_shaft_rpm", dynamics.flywheel_shaft_rpm),
                                          ("motor, brake, clutch and the motion's other keys", dynamics.motion))
                   if value is not None]
        if turning:
            changes.append(f"leave {', '.join(turning)} out of [dynamics]")
        dynamics = replace(dynamics, delta=None, omega=None, flywheel_shaft_rpm=None, motion=None)
    rocking = replace(scene, positions=replace(scene.positions, start=0.0, start_given=False), loads=tuple(loads),
                      dynamics=dynamics)
    return rocking, tuple(changes)


# How far (degrees) inside the ends of a crank's reach the swing it is advised to rock over keeps, tried in turn:
# a degree where the velocities are determined, and further in where the accelerations a toggle at an end drives up
# are more than the plans or the kinematic diagrams can draw (a swing a degree short of its ends was refused at once).
SWING_MARGINS_DEG = (1.0, 2.0, 3.0, 5.0, 8.0, 13.0, 21.0, 34.0)


def _swing_that_runs(scene: Scene, low: float, high: float) -> tuple[int, int] | None:
    """The swing (whole degrees) within the reach from ``low`` to ``high`` (rad), nearest its ends, that the run
    takes: the scene rocking over it is analysed and checked for everything a run would refuse, as ``check`` does;
    None where none of :data:`SWING_MARGINS_DEG` gives one."""
    # The analysis and the run's refusals are later stages: imported only on this path of a refusal.
    from .analysis import analyse
    from .deliverables import chosen, refuse_as_run_would

    driver = scene.driver
    for margin in SWING_MARGINS_DEG:
        first, last = math.ceil(math.degrees(low) + margin), math.floor(math.degrees(high) - margin)
        if last <= first:
            return None
        # The scene as the advice changes it (_rocking_changes), rocking over the swing.
        rocking = replace(scene, driver=replace(driver, swing=(math.radians(first), math.radians(last))))
        try:
            with verdict_only():  # a trial's refusal only says to try the next swing
                analysis = analyse(rocking)
                refuse_as_run_would(rocking, analysis, chosen(rocking, analysis))
        except GraphplanError:
            continue
        return first, last
    return None
