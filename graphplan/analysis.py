"""One run's analysis: everything the outputs read, computed once.

The command line and the Python interface both go through :func:`analyse`,
so that the numbers in ``results.json``, the drawings and a notebook agree.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType

import numpy as np

from .check import ErrorRow, Reading, balancing_error_rows, error_rows, exact_values_at, force_error_rows, readings
from .cycle_work import CycleWork, cycle_work
from .errors import SceneError
from .forces import ForcePlan, Load, force_plan
from .geometry import ParallelLinesError
from .joint_friction import (
    FrictionPair,
    check_journals,
    described,
    friction_loads,
    friction_pairs,
    rubbing_senses,
    unusual_coefficients,
)
from .kinematics import at
from .length_units import lengths_in_millimetres
from .lever import Lever, lever
from .load_strokes import diagrams_in_travel, resisting_forces_turning, strokes_of_other_links
from .loads import (
    activity,
    along_moving_points,
    has_loads,
    link_loads,
    motion_state,
    plan_state,
    refuse_lines_without_length,
    refuse_resisting_along_no_motion,
)
from .locale import strings
from .locking import LockedSpan, locked_between, pairs_that_lock, turned_round_between
from .mechanism import Mechanism, build
from .misreadings import SheetsDrawn, misread
from .motion import ILL_CONDITIONED_DEG, ILL_CONDITIONED_SINE, Motion, PositionWarning, solve, toggles_between
from .overlaps import overlaps
from .plans import SHALLOW_CROSSING_DEG, Plan, acceleration_plan, spread, velocity_plan
from .positions import PositionSet, make_positions
from .reach_advice import reach_hint
from .scales import standard_scale
from .scene import OTHER_SENSE, LoadSpec, Scene
from .statics import Equilibrium, balancing_scale, equilibrium, pairs, turned_round
from .unit_slips import (
    angles_in_radians,
    centres_as_shares,
    free_lengths_in_millimetres,
    inertia_too_large,
    loads_in_kilonewtons,
    masses_in_grams,
    speed_in_rpm,
    velocity_in_millimetres,
)
from .wording import balancing_symbol

# Driver positions per cycle for the paths drawn on the plan of positions.
PATH_SAMPLES = 360
# The field (mm) the largest of the velocity plans of every position fits at their μV, when the scene fixes
# none: smaller than a plan sheet's 150 mm, so that twelve stand in a grid on a sheet.
VELOCITY_PLANS_FIELD_MM = 120.0


@dataclass(frozen=True)
class VelocityPosition:
    """The velocity plan of one position listed in ``positions.velocity_plans``, its readings and errors."""

    number: int
    index: int
    positions: dict[str, complex]
    directions: dict[int, complex]
    velocity: Plan
    readings: tuple[Reading, ...]
    errors: tuple[ErrorRow, ...]

    @property
    def plans(self) -> dict[str, Plan]:
        return {"velocity": self.velocity}


@dataclass(frozen=True)
class PlanPosition(VelocityPosition):
    """The plans of one position listed in ``positions.plans``: the velocity plan with the acceleration plan,
    the readings and errors of both, and the force analysis where the scene has one."""

    acceleration: Plan
    loads: tuple[Load, ...] = ()
    forces: ForcePlan | None = None
    lever: Lever | None = None
    with_friction: ForcePlan | None = None
    lever_with_friction: Lever | None = None
    # The pairs' friction loads at the settled reactions (Mf23, Ff34, ...), as the lever with friction takes them.
    friction_loads: tuple[Load, ...] = ()

    @property
    def plans(self) -> dict[str, Plan]:
        return {"velocity": self.velocity, "acceleration": self.acceleration}


@dataclass(frozen=True)
class Strokes:
    """How far the crank turns in the working stroke and in the idle one (rad), between the extreme positions."""

    working: float
    idle: float

    @property
    def time_ratio(self) -> float:
        """K = φw/φi, the time ratio (advance-to-return; in Russian texts the coefficient of the change of the output
        link's mean speed)."""
        return self.working / self.idle


@dataclass(frozen=True)
class Analysis:
    scene: Scene
    mechanism: Mechanism
    positions: PositionSet
    motion: Motion
    emphasised: Motion
    paths: Motion
    plans: tuple[PlanPosition, ...] = ()
    warnings: tuple[PositionWarning, ...] = ()
    loads: tuple[Load, ...] = ()
    equilibrium: Equilibrium | None = None
    with_friction: Equilibrium | None = None
    friction: tuple[FrictionPair, ...] = ()
    velocity_plans: tuple[VelocityPosition, ...] = ()
    # Where the friction locks the mechanism between two analysed positions that move.
    locked_spans: tuple[LockedSpan, ...] = ()
    # The works over a crank's turn without and with the pairs' friction, and η over the cycle.
    cycle: CycleWork | None = None
    # Where, between two analysed positions, the friction holds loads that would drive the mechanism (η′ ≤ 0).
    turned_round_spans: tuple[LockedSpan, ...] = ()
    # By position number, the force sheets the course sheets draw larger than the record (without friction and with),
    # and the record's own arrows of the groups cut free where a reaction was read by hand, where the run drew them
    # (:func:`read_off_sheets`): the hand readings are checked against them too.
    sheet_polygons: SheetsDrawn = field(default_factory=lambda: MappingProxyType({}))

    def __repr__(self) -> str:
        # The dataclass's own repr ran to hundreds of thousands of characters.
        return (f"<Analysis of {self.scene.title!r}: {len(self.positions.numbers)} positions, plans of "
                f"{', '.join(str(plan.number) for plan in self.plans) or 'none'}, {len(self.warnings)} warnings>")

    @property
    def strokes(self) -> Strokes | None:
        """The crank's turn in the working and the idle stroke and their ratio K, as ``results.json``'s
        ``strokes``; None where the working link has no extreme positions (or the scene names none)."""
        turns = self.positions.stroke_turns(self.mechanism.driver.sense)
        return None if turns is None else Strokes(*turns)

    @functools.cached_property
    def balancing_scale(self) -> float:
        """The largest balancing load without friction over the positions: what its rounding noise (an extreme
        position's, where the loads take no power) is judged against for η (:func:`statics.efficiency`)."""
        return 0.0 if self.equilibrium is None else balancing_scale(self.equilibrium.balancing)

    @property
    def drawn_velocities(self) -> tuple[VelocityPosition, ...]:
        """Each position with a velocity plan, in order: its plan sheet's (drawn larger) where it has one, else
        its velocity plan of every position. What a reading of velocities alone takes, position by position."""
        drawn = {position.index: position for position in self.velocity_plans}
        drawn.update({plan.index: plan for plan in self.plans})
        return tuple(drawn[index] for index in sorted(drawn))

    @property
    def errors(self) -> tuple[ErrorRow, ...]:
        """Every error row of the run: the plan positions', then those of the velocity plans of the other
        positions (a plan position's velocities are read off its plan sheet's plan, drawn larger)."""
        planned = {plan.number for plan in self.plans}
        return (*(row for plan in self.plans for row in plan.errors),
                *(row for position in self.velocity_plans if position.number not in planned for row in position.errors))


def analyse(scene: Scene) -> Analysis:
    """Build the mechanism, place the positions and solve them, with the extremes and a dense sweep."""
    mechanism = build(scene)
    with reach_hint(mechanism):
        positions = make_positions(mechanism)
        motion = solve(mechanism, positions.values, positions.reference, positions.numbers, tolerant=True)
    # The positions drawn bold: the working link's two extremes, a slider's or a rocking crank's two ends, or
    # the first position.
    if positions.extremes is not None:
        bold = np.array(positions.extremes)
    elif not mechanism.driver.cyclic:
        bold = positions.values[[0, -1]]
    else:
        bold = positions.values[:1]
    emphasised = solve(mechanism, bold, positions.reference, tolerant=True)
    driver = mechanism.driver
    if driver.cyclic:
        sweep = positions.values[0] + driver.sense * np.linspace(0.0, 2.0 * np.pi, PATH_SAMPLES + 1)
    else:
        sweep = np.linspace(driver.travel[0], driver.travel[1], PATH_SAMPLES + 1)
    with reach_hint(mechanism):
        paths = solve(mechanism, sweep, positions.reference, tolerant=True)
    stepped_over = toggles_between(motion, positions.numbers, positions.reference, paths)
    # A force along a point that meets its own point has no line there: told at the position, else in the sweep.
    refuse_lines_without_length(mechanism, motion, positions.numbers)
    refuse_lines_without_length(mechanism, paths)
    refuse_resisting_along_no_motion(mechanism, motion)
    acting = activity(mechanism, positions, motion) if has_loads(mechanism) else None
    # Checked with no force analysis too, which leaves the friction out (check says why): a pair it names wrongly
    # is refused all the same, not only once masses are given.
    friction = friction_pairs(scene.friction, pairs(mechanism, motion.slides))
    check_journals(friction, mechanism, motion)
    unusual = unusual_coefficients(friction)
    if acting is None:
        friction = ()
    loads, balance, with_friction = (), None, None
    if acting is not None:
        # A singular position's velocities and accelerations are not numbers: its loads and reactions come
        # out as none (Equilibrium.singular), which its warning has told.
        with np.errstate(invalid="ignore"):
            loads = link_loads(mechanism, motion_state(motion), acting)
            balance = equilibrium(mechanism, motion, loads)
            if friction:
                with_friction = equilibrium(mechanism, motion, loads, friction)
    locked_spans = locked_between(mechanism, positions, friction, sweep, paths)
    # Only where the loads can drive it at all: a positive-work machine's friction never turns its flow round.
    held_spans = (turned_round_between(mechanism, positions, friction, sweep, paths)
                  if with_friction is not None else ())
    cycle = None
    if with_friction is not None:
        cycle = cycle_work(mechanism, positions, friction,
                           locked_elsewhere=bool(with_friction.locked.any()) or bool(locked_spans))
    every, unplanned = _velocity_plans(mechanism, motion)
    plans, warnings = _plans(mechanism, positions, motion, acting, friction, balance)
    warnings += misread(mechanism, (*plans, *every), motion=motion, numbers=positions.numbers)
    # A load judged against masses typed in grams, against inertia loads of a speed typed in rev/min or mm/s (some
    # hundred or a million times too large), or against weights' moments over lengths typed in mm (a thousand times
    # too long), would be told a slip of its own it is not, and its "fix" would make it a thousand times too large.
    mass_slips = masses_in_grams(mechanism, motion) + inertia_too_large(mechanism, motion)
    rpm_slip = speed_in_rpm(mechanism) + velocity_in_millimetres(mechanism)
    length_slips = lengths_in_millimetres(motion)
    in_order = tuple(sorted(length_slips + rpm_slip + angles_in_radians(mechanism)
                            + mass_slips + centres_as_shares(mechanism, motion)
                            + free_lengths_in_millimetres(mechanism, motion)
                            + (() if mass_slips or rpm_slip or length_slips
                               else loads_in_kilonewtons(mechanism, motion))
                            + motion.warnings + stepped_over
                            + _extra_reversals(mechanism, positions)
                            + _idle_throughout(mechanism, positions) + _working_throughout(mechanism, positions)
                            + _working_stroke_quicker(mechanism, positions) + _block_near_pivot(mechanism, paths)
                            + overlaps(mechanism, paths)
                            + strokes_of_other_links(mechanism, positions)
                            + diagrams_in_travel(mechanism, positions) + unusual
                            + resisting_forces_turning(mechanism, positions, motion)
                            + along_moving_points(mechanism)
                            + _self_locking(mechanism, positions, friction, with_friction)
                            + _turned_round(mechanism, balance, with_friction)
                            + _locked_between(mechanism, positions, friction, locked_spans)
                            + _turned_round_between(mechanism, positions, held_spans),
                            key=lambda warning: warning.position))
    return Analysis(scene, mechanism, positions, motion, emphasised, paths, plans,
                    in_order + warnings + tuple(unplanned),
                    loads, balance, with_friction, friction, every, locked_spans, cycle, held_spans)


def read_off_sheets(analysis: Analysis, sheets: SheetsDrawn) -> Analysis:
    """``analysis`` with the force drawings the run drew at a μF other than the record's polygons, ``sheets`` by
    position number, known to the check of the hand readings: the course sheets' polygons and groups cut free drawn
    larger, and the arrows of the groups cut free in forces_N.svg itself.  Readings measured on them are told so, not
    given a ``force_scale`` that would redraw every polygon.  Known only once the drawings are made, so told only by a
    run that draws them."""
    if not sheets:
        return analysis
    sheets = MappingProxyType(dict(sheets))
    told = iter(misread(analysis.mechanism, (*analysis.plans, *analysis.velocity_plans), sheets,
                        motion=analysis.motion, numbers=analysis.positions.numbers))
    # The polygons read off a sheet are found only among readings far off the record: the same positions are told,
    # in the same order.
    warnings = tuple(next(told) if warning.code == "measured-far-off" else warning for warning in analysis.warnings)
    # Readings that fit no course sheet are told as before: the analysis kept, with what the drawings remember of it.
    if warnings == analysis.warnings:
        return analysis
    return replace(analysis, warnings=warnings, sheet_polygons=sheets)


# Warnings about the scene as a whole, recorded at its first position (results.json's warnings are by position):
# the console gives them without one.
SCENE_WIDE_WARNINGS = frozenset({"lengths-in-mm", "idle-throughout", "working-throughout", "stroke-of-another-link",
                                 "diagram-in-travel", "high-friction", "speed-in-rpm", "masses-in-grams",
                                 "inertia-too-large", "centre-as-share", "resisting-turns-round",
                                 "along-moving-point", "working-stroke-quicker", "block-near-pivot",
                                 "joints-coincide", "blocks-pass-through", "angle-in-radians", "load-in-kn",
                                 "velocity-in-mm", "free-length-in-mm"})


def _self_locking(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
                  with_friction: Equilibrium | None) -> tuple[PositionWarning, ...]:
    """A warning at each position where the pairs' friction locks the mechanism: no driving load moves it
    (its balancing load and reactions are then null, and it has no force sheet with friction).  It names the
    pair whose friction locks it, the one to change."""
    if with_friction is None:
        return ()
    locked = np.flatnonzero(with_friction.locked)
    culprits = pairs_that_lock(mechanism, positions, friction, positions.values[locked])
    return tuple(PositionWarning(int(index), "self-locking", f"{_locking_friction(friction, alone)} locks the "
                                 "mechanism here: no driving load, however large, moves it")
                 for index, alone in zip(locked, culprits, strict=True))


def _locking_friction(friction: tuple[FrictionPair, ...], alone: tuple[FrictionPair, ...]) -> str:
    """Whose friction locks: the pairs that lock alone, or all of them together where none does."""
    if not alone:
        return f"the friction in the pairs together ({'; '.join(described(pair) for pair in friction)}; none alone)"
    return "the friction in " + " and in ".join(described(pair) for pair in alone) + (
        ", each alone," if len(alone) > 1 else "")


def _locked_between(mechanism: Mechanism, positions: PositionSet, friction: tuple[FrictionPair, ...],
                    spans: tuple[LockedSpan, ...]) -> tuple[PositionWarning, ...]:
    """A warning at the position before each stretch where the friction locks the mechanism between two positions
    that move: their plans and force polygons do not show it."""
    numbers, driver = positions.numbers, mechanism.driver
    return tuple(PositionWarning(span.after, "self-locking-between", (
        f"between positions {numbers[span.after]} and {numbers[(span.after + 1) % len(numbers)]} "
        f"{_locking_friction(friction, span.pairs)} locks the mechanism, from {driver.describe(span.start)} to "
        f"{driver.describe(span.end)}: no driving load, however large, moves it there, though it moves at both "
        "positions"))
        for span in spans)


def _turned_round_between(mechanism: Mechanism, positions: PositionSet,
                          spans: tuple[LockedSpan, ...]) -> tuple[PositionWarning, ...]:
    """A warning at the position before each stretch where the friction holds loads that would drive the
    mechanism between two positions: the positions' own η does not show it."""
    numbers, driver = positions.numbers, mechanism.driver
    return tuple(PositionWarning(span.after, "reverse-self-locking-between", (
        f"between positions {numbers[span.after]} and {numbers[(span.after + 1) % len(numbers)]}, from "
        f"{driver.describe(span.start)} to {driver.describe(span.end)}, the loads would drive the mechanism, but "
        "the friction in the pairs holds them, however large those that drive it there: the driver must drive it; "
        "the mechanism locks itself against its loads driving it (η′ ≤ 0)"))
        for span in spans)


def _turned_round(mechanism: Mechanism, ideal: Equilibrium | None,
                  with_friction: Equilibrium | None) -> tuple[PositionWarning, ...]:
    """A warning at each position where the loads would drive the mechanism but its friction holds them: the
    driver has to push it through, and η′ ≤ 0 (the efficiency of the flow backwards is not defined)."""
    if with_friction is None:
        return ()
    name, unit = balancing_symbol(mechanism, strings("en"))  # the warnings are in English
    moving = ~with_friction.locked
    return tuple(PositionWarning(int(index), "reverse-self-locking", (
        f"the loads would drive the mechanism here ({name}0 = {ideal.balancing[index]:.6g} {unit}), but the friction "
        f"in the pairs holds them: the driver must drive it ({name} = {with_friction.balancing[index]:.6g} {unit}); "
        "the mechanism locks itself against its loads driving it (η′ ≤ 0)"))
        for index in np.flatnonzero(moving & turned_round(mechanism, ideal.balancing, with_friction.balancing,
                                                          balancing_scale(ideal.balancing))))


def _idle_throughout(mechanism: Mechanism, positions: PositionSet) -> tuple[PositionWarning, ...]:
    """A warning where a slider's travel or a rocking crank's swing never moves the working link in its working
    sense: every position is then in the idle stroke, and a load of the working stroke is never applied."""
    working, driver = mechanism.scene.positions.working, mechanism.driver
    if driver.cyclic or positions.strokes is None or "working" in positions.strokes:
        return ()
    other = OTHER_SENSE[working.sense]
    unused = _never_applied(mechanism, "working")
    return (PositionWarning(0, "idle-throughout", (
        f"positions.working: link {working.link} never moves {working.sense} over driver.{driver.run_key}, so every "
        f"position is in the idle stroke{unused}; it moves {other}: is that its working sense?")),)


def _working_throughout(mechanism: Mechanism, positions: PositionSet) -> tuple[PositionWarning, ...]:
    """A warning where a run once over a travel or a swing keeps the working link in its working sense and a load
    is given to the idle stroke: that load is never applied.  A swing that is all working stroke is the usual case,
    so it is told only for the load it silently drops."""
    working, driver = mechanism.scene.positions.working, mechanism.driver
    if driver.cyclic or positions.strokes is None or "idle" in positions.strokes:
        return ()
    unused = _never_applied(mechanism, "idle")
    if not unused:
        return ()
    return (PositionWarning(0, "working-throughout", (
        f"positions.working: link {working.link} moves {working.sense} over the whole driver.{driver.run_key}, so "
        f"every position is in the working stroke{unused}: is that the stroke it acts in?")),)


# A quick-return mechanism does its work on its slow stroke, K = φw/φi some 1.25 to 2.5; the working sense typed the
# other way round gives 1/K, 0.4 to 0.8, the cutting load on the quick return.  Below this K the sense is asked
# about where a resisting load is given to the working stroke; a crank-rocker's K near 1 either way (the ratchet
# feed's 0.89) is not.
QUICKER_WORKING_K = 0.8


def _working_stroke_quicker(mechanism: Mechanism, positions: PositionSet) -> tuple[PositionWarning, ...]:
    """A warning where the working stroke is much the quicker (K below :data:`QUICKER_WORKING_K`) and a resisting
    load is given to it: the working sense is likely the other way round, and every such load acts in the wrong
    stroke."""
    working, driver = mechanism.scene.positions.working, mechanism.driver
    turns = positions.stroke_turns(driver.sense) if driver.cyclic else None
    if working is None or turns is None or not turns[0] < QUICKER_WORKING_K * turns[1]:
        return ()
    resisted = [load.where for load in _loads_of_stroke(mechanism, "working") if load.resisting]
    if not resisted:
        return ()
    working_deg, idle_deg = (math.degrees(turn) for turn in turns)
    return (PositionWarning(0, "working-stroke-quicker", (
        f"positions.working: link {working.link}'s working stroke ({working.sense}) is the quicker one, "
        f"K = φw/φi = {working_deg:.2f}°/{idle_deg:.2f}° = {turns[0] / turns[1]:.4f}, and {', '.join(resisted)} "
        f"{'resists' if len(resisted) == 1 else 'resist'} it: a quick-return mechanism works on its slow stroke, "
        f"which sense = \"{OTHER_SENSE[working.sense]}\" makes the working one (K = {turns[1] / turns[0]:.4f}); is "
        f"{working.sense} its working sense?")),)


# How many times its median speed over the turn a slotted lever turns by its pivot to be told whipping round: a
# Whitworth lever whose block passes sin 1° of its reach from the pivot turns there some 60 times its median (30 times
# the crank's speed), one whose block passes through the pivot steadily at its median.
LEVER_WHIP = 10.0


def _block_near_pivot(mechanism: Mechanism, paths: Motion) -> tuple[PositionWarning, ...]:
    """A warning where a slotted lever's block (an ``RPR`` with its slide through the pivot) passes nearer the pivot
    than sin 1° of the farthest it gets, the bound of lines of action told ill-conditioned, the lever turning there
    more than :data:`LEVER_WHIP` times its median speed over the turn.

    The lever turns as fast as the block crosses it over its distance from
    the pivot: a Whitworth crank 1 mm shorter than its pivots are apart
    whips the lever round at 79 times the crank's speed, its ε and inertia
    loads with it, and a hand plan magnifies every slip there.  The lines of
    action of its plans cross square wherever the block is, so the
    ill-conditioned positions never told it; at the pivot itself the lever
    has no direction (a singular position).
    """
    limit = ILL_CONDITIONED_SINE
    driver = mechanism.driver
    warnings = []
    for group in mechanism.groups:
        if group.kind != "RPR" or group.offset != 0.0:
            continue
        block, pivot = group.joints
        lever = group.links[1]
        distance = np.hypot(*(paths.point(block).r - paths.point(pivot).r).T)
        if not np.isfinite(distance).any():
            continue
        nearest = int(np.nanargmin(distance))
        farthest = float(np.nanmax(distance))
        if not distance[nearest] < limit * farthest:
            continue
        turning = np.abs(paths.link(lever).omega)
        omega = float(turning[nearest])
        # A crank exactly as long as the pivots are apart carries the block through the pivot, the lever turning
        # steadily at half its speed all the while (a singular position only at the pivot itself, told there).
        if not omega > LEVER_WHIP * float(np.nanmedian(turning)):
            continue
        times = f", {omega / abs(driver.omega):.3g} times as fast as the crank" if driver.kind == "crank" else ""
        warnings.append(PositionWarning(0, "block-near-pivot", (
            f"group {group.label}: {block} passes {distance[nearest] * 1000:.3g} mm from the pivot {pivot} of link "
            f"{lever} ({driver.describe(float(paths.driver[nearest]))}), under {limit * 100:.3g} % "
            f"(sin {ILL_CONDITIONED_DEG:g}°) of the farthest it gets, {farthest:.4g} m: link {lever} turns there at "
            f"{omega:.4g} rad/s{times}, its ε and inertia loads with it, and a plan drawn by hand magnifies every "
            f"slip; on the pivot itself the lever has no direction")))
    return tuple(warnings)


def _loads_of_stroke(mechanism: Mechanism, stroke: str) -> list[LoadSpec]:
    """The loads given to ``stroke`` (``working`` or ``idle``) of the working link's strokes: a window or a diagram is
    a share of the working stroke; a load with its own ``stroke`` moves with another link's and is not among them."""
    def stroke_of(during) -> str | None:
        return None if during == "always" else "idle" if during == "idle" else "working"

    return [load for load in mechanism.scene.loads if load.stroke is None and stroke_of(load.during) == stroke]


def _never_applied(mechanism: Mechanism, stroke: str) -> str:
    """The clause naming the loads of ``stroke`` (of the working link's strokes) that the run never applies; a load
    with its own ``stroke`` moves with another link's and is not among them."""
    dropped = [load.where for load in _loads_of_stroke(mechanism, stroke)]
    if not dropped:
        return ""
    return f"; {', '.join(dropped)} of the {stroke} stroke {'is' if len(dropped) == 1 else 'are'} never applied"


def _extra_reversals(mechanism: Mechanism, positions: PositionSet) -> tuple[PositionWarning, ...]:
    """A warning where the working link turns back more than twice a turn (a jaw that swings twice): its two
    extremes are then a choice, and its strokes, K and a load's window follow that choice.  Given at the
    position nearest a turn back that is not one of the extremes."""
    if len(positions.reversals) <= 2 or positions.extremes is None:
        return ()
    turn = 2.0 * math.pi

    def apart(one: float, other: float) -> float:
        return abs((one - other + math.pi) % turn - math.pi)

    # The extremes are two of the reversals, the same roots; the others lie at least a step of the sweep (half a
    # degree) from them, or the sweep would not have told them apart.
    others = [value for value in positions.reversals
              if min(apart(value, extreme) for extreme in positions.extremes) > math.radians(0.5)]
    if not others:
        return ()
    nearest = {index: min(apart(value, reversal) for reversal in others)
               for index, value in enumerate(positions.values)}
    where = min(nearest, key=nearest.get)
    working, driver = mechanism.scene.positions.working, mechanism.driver
    # As precise as the extremes beside them, and printed to the same hundredth of a degree.
    angles = ", ".join(f"{math.degrees(value) % 360.0:.2f}" for value in sorted(positions.reversals,
                                                                               key=lambda v: v % turn))
    start, end = (math.degrees(value) % 360.0 for value in positions.extremes)
    return (PositionWarning(where, "extra-reversals",
                            f"link {working.link} turns back {len(positions.reversals)} times a turn of link "
                            f"{driver.link} (at {angles}°), not twice: its working stroke is taken from "
                            f"{start:.2f}° to {end:.2f}°, the longest it makes in its working sense, and each "
                            f"position's stroke follows its sense of motion there; if it should swing once a "
                            f"turn, check the lengths"),)


def instant(motion: Motion, index: int) -> tuple[dict[str, complex], dict[int, complex]]:
    """The drawing of the mechanism at one position: where its points are, how its links lie."""
    return ({name: complex(at(point.r, index)) for name, point in motion.points.items()},
            {number: complex(at(link.u, index)) for number, link in motion.links.items()})


def _regular(motion: Motion, numbers: tuple[int, ...]) -> Iterator[tuple[int, int, dict[str, complex], dict[int, complex]]]:
    """(number, index, where the points are, how the links lie) of each position of ``numbers`` that is not
    singular (a singular one is already among the motion's warnings)."""
    number_from = motion.mechanism.scene.positions.number_from
    for number in numbers:
        index = int(number - number_from)
        if index not in motion.singular:
            yield (number, index, *instant(motion, index))


def _refuse_unplanned_readings(scene: Scene, motion: Motion, numbers: Iterable[int], what: str = "plan") -> None:
    """Refuse the hand readings of a position of ``numbers`` that the motion found singular: it has no plan
    (``what``) to check them against, and they are refused as a reading of a position without a plan is, not
    dropped without a word."""
    for number in numbers:
        reason = motion.singular.get(int(number - scene.positions.number_from))
        if reason is not None and scene.measured.get(number):
            _refuse_singular(number, reason, what)


def _refuse_singular(number: int, reason: object, what: str = "plan", kind: str = "") -> None:
    where = f"measured.{number}" + (f".{kind}" if kind else "")
    raise SceneError(where, f"cannot be checked: position {number} is singular and has no {what} to check the "
                     f"readings against ({reason}); measure a regular position instead")


def _velocity_plans(mechanism: Mechanism, motion: Motion) -> tuple[tuple[VelocityPosition, ...], list[PositionWarning]]:
    """The velocity plans of every position of ``positions.velocity_plans``, all at one μV.

    A course project draws them smaller than the plans of its plan sheets, at
    one scale: μV is fixed by ``drawing.velocity_plans_pole`` (the mm drawn
    for the driver's velocity), else the standard scale at which the largest
    plan fits :data:`VELOCITY_PLANS_FIELD_MM`.  A singular position gets no
    plan and, unless a plan position reports it, a warning.
    """
    scene = mechanism.scene
    found, warnings = [], []
    # A plan position's readings are of its plan sheet's plans, refused there if it has none.
    grid_only = [number for number in scene.positions.velocity_plans if number not in scene.positions.plans]
    _refuse_unplanned_readings(scene, motion, grid_only, "velocity plan")
    for number, index, where, directions in _regular(motion, scene.positions.velocity_plans):
        try:
            found.append((number, index, where, directions, velocity_plan(mechanism, where, directions)))
        except ParallelLinesError as error:
            if number not in scene.positions.plans:
                if scene.measured.get(number):
                    _refuse_singular(number, error, "velocity plan")
                warnings.append(PositionWarning(index, "singular", f"no velocity plan: {error}"))
    if not found:
        return (), warnings
    pole = scene.drawing.velocity_plans_pole
    if pole is not None:
        scale = max(abs(plan.value(mechanism.driver.joint)) for *_, plan in found) / pole
    else:
        scale = standard_scale(max(spread(plan) for *_, plan in found) / VELOCITY_PLANS_FIELD_MM)
    every = []
    for number, index, where, directions, velocity in found:
        velocity = replace(velocity, scale=scale)
        table = tuple(readings(mechanism, {"velocity": velocity}, where))
        # A plan position's hand readings are of its plan sheet's plan, drawn at another μV.
        measured = scene.measured.get(number) if number not in scene.positions.plans else None
        drawn = VelocityPosition(number, index, where, directions, velocity, table, ())
        every.append(replace(drawn, errors=_grid_rows(mechanism, motion, drawn, measured)))
    return tuple(every), warnings


def _grid_rows(mechanism: Mechanism, motion: Motion, position: VelocityPosition,
               measured: Mapping[str, Mapping[str, float]] | None) -> tuple[ErrorRow, ...]:
    """The error rows of a velocity plan among the plans of every position, with those of hand readings of it."""
    table = list(position.readings)
    return tuple(error_rows(position.number, exact_values_at(mechanism, motion, table, position.index), position.plans,
                            table, mechanism.scene.drawing.drafting_precision, measured))


def measured_on_velocity_plans(analysis: Analysis, number: int,
                               measured: Mapping[str, Mapping[str, float]]) -> tuple[ErrorRow, ...]:
    """The error rows of hand readings ``measured`` of position ``number``'s velocity plan among the plans of every
    position, read at their μV: a notebook that draws the position's plan sheet too (at another μV, which its other
    rows read) still checks a student's readings against the plan the student drew."""
    grid = next(position for position in analysis.velocity_plans if position.number == number)
    return tuple(row for row in _grid_rows(analysis.mechanism, analysis.motion, grid, measured)
                 if row.source == "measured")


def _plans(mechanism: Mechanism, positions: PositionSet, motion: Motion, acting: np.ndarray | None,
           friction: tuple[FrictionPair, ...], balance: Equilibrium | None):
    """Plans, readings, errors and forces for every position of ``positions.plans``; singular ones are reported.

    ``acting`` (which external load acts where) and ``balance`` (the
    reactions of the linear system, the force polygons' reference) are None
    when the scene has nothing for a force analysis.
    """
    scene = mechanism.scene
    found, warnings = [], []
    _refuse_unplanned_readings(scene, motion, scene.positions.plans)
    for number, index, where, directions in _regular(motion, scene.positions.plans):
        try:
            velocity = velocity_plan(mechanism, where, directions)
            acceleration = acceleration_plan(mechanism, where, directions, velocity)
        except ParallelLinesError as error:
            if scene.measured.get(number):
                _refuse_singular(number, error)
            warnings.append(PositionWarning(index, "singular", f"no plan: {error}"))
            continue
        plans = {"velocity": velocity, "acceleration": acceleration}
        table = readings(mechanism, plans, where)
        exact = exact_values_at(mechanism, motion, table, index)
        measured = dict(scene.measured.get(number, {}))
        measured_forces = measured.pop("forces", None)
        # The balancing load found by hand (a value, N·m or N), checked as the force readings are.
        measured_balancing = measured.pop("balancing", None)
        for key, given in (("forces", measured_forces), ("balancing", measured_balancing is not None)):
            if given and acting is None:
                raise SceneError(f"measured.{number}.{key}",
                                 "the scene has no force analysis: give the links' masses or loads")
        rows = error_rows(number, exact, plans, table, scene.drawing.drafting_precision, measured)
        warnings += _shallow_crossings(index, plans, scene.drawing.drafting_precision)
        loads, forces, on_lever, rubbing, rubbing_lever, rubbing_loads = (), None, None, None, None, ()
        if acting is not None:
            state = plan_state(mechanism, where, velocity, acceleration)
            loads = link_loads(mechanism, state, acting[:, index:index + 1])
            try:
                forces = force_plan(mechanism, where, directions, loads, scene.drawing.force_scale)
                if friction:
                    rubbing = force_plan(mechanism, where, directions, loads, forces.group_scales,
                                         functools.partial(friction_loads, friction, state,
                                                           senses=rubbing_senses(friction, state)))
            except ParallelLinesError as error:
                if measured_forces or measured_balancing is not None:
                    _refuse_singular(number, error, "force polygon", "forces" if measured_forces else "balancing")
                warnings.append(PositionWarning(index, "singular", f"no force plan: {error}"))
            if forces is not None and balance is not None and not balance.singular[index]:
                solved = {reaction.name: complex(reaction.force[index]) for reaction in balance.reactions}
                rows += force_error_rows(number, solved, forces, scene.drawing.drafting_precision, measured_forces)
                if measured_balancing is not None:
                    symbol, unit = balancing_symbol(mechanism, strings("en"))
                    rows += balancing_error_rows(number, float(balance.balancing[index]), forces, symbol, unit,
                                                 measured_balancing)
            on_lever = lever(mechanism, where, velocity, loads)
            if rubbing is not None and not rubbing.locked:
                settled = {name: found.force for name, found in rubbing.reactions.items()}
                rubbing_loads = friction_loads(friction, state, settled)
                rubbing_lever = lever(mechanism, where, velocity, loads + rubbing_loads)
        found.append(PlanPosition(number, index, where, directions, velocity, tuple(table), tuple(rows), acceleration,
                                  loads, forces, on_lever, rubbing, rubbing_lever, rubbing_loads))
    return tuple(found), tuple(warnings)


def _shallow_crossings(index: int, plans: dict[str, Plan], precision: float) -> list[PositionWarning]:
    """A warning for every crossing of lines of action at less than SHALLOW_CROSSING_DEG."""
    warnings = []
    for kind, plan in plans.items():
        for step in plan.steps:
            if step.crossing_deg is not None and step.crossing_deg < SHALLOW_CROSSING_DEG:
                bound = precision / math.sin(math.radians(max(step.crossing_deg, 1e-9)))
                warnings.append(PositionWarning(index, "ill-conditioned",
                                        f"lines of action cross at {step.crossing_deg:.3g}° in the {kind} plan "
                                        f"({step.equation}): a drafting error of {precision:g} mm moves the crossing "
                                        f"by up to {bound:.3g} mm"))
    return warnings
