"""Whose strokes a load of one stroke acts in, and what its diagram's shares are of: the working link's stroke,
unless the load names its own.

A window or a diagram of a load is read along the working link's stroke (``positions.working``).  On a link whose
strokes turn back elsewhere, a second cylinder's piston, that reading is silently another cylinder's: the load
acts while the first piston compresses, and not while its own does.  The scene then names the load's own stroke
(``loads[].stroke``); where it does not, it is warned of.  A diagram whose shares end at the stroke's travel in
metres was typed in metres, not shares: warned of too.  So is a resisting force whose point, within its window,
moves both ways along the force's line: it turns round with the motion, which a weight typed resisting does not.
"""

from __future__ import annotations

import math

import numpy as np

from .kinematics import dot
from .loads import activity, external_names, motion_state, resisted_sense, stroke_travel
from .mechanism import Mechanism
from .motion import Motion, PositionWarning, solve
from .positions import PositionSet, link_extremes

# Strokes that turn back within this of each other (degrees of the crank) are one stroke, read alike.
SAME_STROKE_DEG = 1.0
# A diagram's last share within this share of the stroke's travel (m or rad) is the travel typed for shares.
TRAVEL_MATCH = 0.01


def strokes_of_other_links(mechanism: Mechanism, positions: PositionSet) -> tuple[PositionWarning, ...]:
    """A ``stroke-of-another-link`` warning for each load of one stroke on a link whose strokes turn back away from
    the working link's, read along the working link's for want of its own ``stroke``."""
    scene = mechanism.scene
    working = scene.positions.working
    if working is None or positions.extremes is None:
        return ()
    told = []
    for load in scene.loads:
        if load.during == "always" or load.stroke is not None or load.link == working.link:
            continue
        read = "diagram" if load.diagram is not None else "during"
        sense = '"forward" or "backward"' if load.link in mechanism.translating else '"ccw" or "cw"'
        give = f"give {load.where}.stroke = {{ link = {load.link}, sense = {sense} }}"
        own = link_extremes(mechanism, positions, load.link)
        if own is not None and not _same_ends(own, positions.extremes):
            told.append(PositionWarning(0, "stroke-of-another-link", (
                f"{load.where} acts on link {load.link}, which turns back at {_angles(own)}, not where link "
                f"{working.link} does ({_angles(positions.extremes)}): its {read} is read along link "
                f"{working.link}'s working stroke (positions.working); to read it along link {load.link}'s own, "
                f"{give}")))
        elif own is not None and load.link in mechanism.translating:
            # Turning back together, a second piston may still run the other way (an in-line twin's crank pins
            # half a turn apart): which of its strokes the load is of, only the scene can say.
            told.append(PositionWarning(0, "stroke-of-another-link", (
                f"{load.where} acts on link {load.link}, a slider other than the output link {working.link}: its "
                f"{read} is read along link {working.link}'s working stroke (positions.working), in which link "
                f"{load.link} moves {_sense_in_working_stroke(mechanism, positions, load.link)} along its guide; "
                f"if that is not the stroke the load is of, {give}")))
    return tuple(told)


def _sense_in_working_stroke(mechanism: Mechanism, positions: PositionSet, link: int) -> str:
    """Which way a slider moves along its guide halfway through the working link's working stroke."""
    start, end = positions.extremes
    sense = mechanism.driver.sense
    halfway = start + sense * ((sense * (end - start)) % (2.0 * math.pi)) / 2.0
    motion = solve(mechanism, np.array([halfway]), positions.reference)
    slider = motion.links[link]
    return "forward" if float(dot(slider.u, motion.points[slider.origin].v)[0]) > 0 else "backward"


def diagrams_in_travel(mechanism: Mechanism, positions: PositionSet) -> tuple[PositionWarning, ...]:
    """A ``diagram-in-travel`` warning for a load diagram whose shares end where the stroke's travel does (0.15 of a
    0.15 m stroke): the travel typed for shares of it, the load then acting over the stroke's first 15 % alone."""
    if positions.extremes is None:
        return ()
    told = []
    for load in mechanism.scene.loads:
        if load.diagram is None or (last := load.diagram[-1][0]) >= 1.0 - TRAVEL_MATCH:
            continue
        travel = stroke_travel(mechanism, positions, load.stroke)
        if abs(last - travel) <= TRAVEL_MATCH * travel:
            link = (load.stroke or mechanism.scene.positions.working).link
            unit = "m" if link in mechanism.translating else "rad"
            told.append(PositionWarning(0, "diagram-in-travel", (
                f"{load.where}.diagram's shares end at {last:g}, where link {link}'s stroke of {travel:.4g} {unit} "
                f"does: are they the travel in {unit}? They are shares of the stroke, 0 where it starts and 1 where "
                f"it ends: divide them by {travel:.4g}")))
    return tuple(told)


def _same_ends(one: tuple[float, float], other: tuple[float, float]) -> bool:
    """Whether two pairs of crank angles are the same two angles, in either order, within SAME_STROKE_DEG."""
    def apart(a: float, b: float) -> float:
        return abs(math.degrees(math.remainder(a - b, 2.0 * math.pi)))
    return all(min(apart(end, theirs) for theirs in other) <= SAME_STROKE_DEG for end in one)


def _angles(ends: tuple[float, float]) -> str:
    return " and ".join(f"φ = {round(math.degrees(end), 1) % 360.0:.1f}°" for end in ends)


def resisting_forces_turning(mechanism: Mechanism, positions: PositionSet,
                             motion: Motion) -> tuple[PositionWarning, ...]:
    """A ``resisting-turns-round`` warning for each resisting force whose point moves both ways along its line
    within its window of one stroke, at the analysed positions: it turns round with the motion there.  A lifted load
    typed ``resisting = true`` pushed a lever's end up once the end passed the top of its arc, with no word of it."""
    loads = mechanism.scene.loads
    # Acting always, a resistance turns round with a link that swings to and fro, as it should (a sieve's); in a
    # window of one stroke its point moving back along its line is the surprise.
    windowed = [row for row, load in enumerate(loads)
                if load.resisting and load.kind != "moment" and load.during != "always"]
    if not windowed:   # most scenes: no motion state nor activity worked out for nothing
        return ()
    told = []
    state = motion_state(motion)
    acting = activity(mechanism, positions, motion) > 0
    names = external_names(loads)
    for row in windowed:
        load, name = loads[row], names[row]
        sense = np.broadcast_to(np.nan_to_num(resisted_sense(load, state)), (motion.count,))
        senses = [(int(number), each) for number, acts, each in zip(positions.numbers, acting[row], sense, strict=True)
                  if acts]
        along = [number for number, each in senses if each < 0]
        against = [number for number, each in senses if each > 0]
        if along and against:
            if load.along is not None:
                # Its line turns: the sense is told as toward or away from the point it runs to.
                away, toward = f"away from {load.along}", f"toward {load.along}"
            else:
                away, toward = f"at {load.angle_deg:g}°", f"to {(load.angle_deg + 180.0) % 360.0:g}°"
            told.append(PositionWarning(0, "resisting-turns-round", (
                f"{load.where} ({name}) resists {load.point}'s motion along its line, and within its window "
                f"{load.point} moves both ways along it: {name} acts {away} at positions "
                f"{_numbers(along)} and turns round {toward} at positions {_numbers(against)}; a load of "
                f"one direction whatever the motion (a weight lifted) is resisting = false")))
    return tuple(told)


def _numbers(numbers: list[int]) -> str:
    """Position numbers as a list: 2, 3, 4, 7."""
    return ", ".join(map(str, numbers))

