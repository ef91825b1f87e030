"""Lengths typed in millimetres where the scene asks for metres: the warning where the mechanism still runs (every
length a thousand times too long, the results with them), and the hint where one typed so stops it assembling.
"""

from __future__ import annotations

from .mechanism import Mechanism
from .motion import PositionWarning
from .units import MIXED_RATIO, millimetres_question, motor_speed_in_rpm

# Lengths typed in millimetres where the scene asks for metres make a mechanism a thousand times too large, and
# every result follows it (a crank pin at 750 m/s, μl = 2.5 m/mm).  The linkages this method serves are a course
# project's 0.05–2 m, a press's or a pump jack's a few metres: a length over LONGEST_LINK_M is none a machine's
# linkage has, while one in millimetres (20 mm and up) reaches it ...
LONGEST_LINK_M = 20.0
# ... and where a small mechanism's millimetres stay under it, its crank pin gives them away: the fastest
# linkages' crank pins (an engine's at 6000 rev/min, a racing engine's) make some 20–40 m/s, so a crank pin over
# FASTEST_CRANK_PIN_M_S is a length a thousand times too long (or a speed not in rad/s).
FASTEST_CRANK_PIN_M_S = 100.0


def given_lengths(mechanism: Mechanism) -> list[tuple[str, float]]:
    """The links' lengths the scene gives, each with its key path: the crank's, the groups' links' and sides (a
    triad's ``lengths`` lists its turning legs only, its non-zero entries)."""
    found = [("driver.length", mechanism.driver.length)] if mechanism.driver.kind == "crank" else []
    for group in mechanism.groups:
        for key in ("lengths", "sides"):
            values = [value for value in getattr(group, key, ()) if value]
            found += [(f"{group.where}.{key}[{n}]", value) for n, value in enumerate(values)]
        if getattr(group, "length", 0.0):
            found.append((f"{group.where}.length", group.length))
    return found


def lengths_in_millimetres(mechanism: Mechanism) -> tuple[PositionWarning, ...]:
    """A ``lengths-in-mm`` warning, at the first position, where the scene's lengths are implausible as metres: a
    link or the frame larger than any machine's, or a crank turning its pin faster than any machine does."""
    told = []
    lengths = given_lengths(mechanism)
    key, longest = max(lengths, key=lambda item: item[1]) if lengths else ("", 0.0)
    some = False
    if longest > LONGEST_LINK_M:
        told.append(f"{key} = {longest:g} m is longer than any machine's link (over {LONGEST_LINK_M:g} m)")
    else:
        spread = _frame_spread(mechanism)
        far_point = _farthest_point(mechanism)
        if spread is not None and spread[3] > LONGEST_LINK_M:
            first, name, far, apart = spread
            told.append(f"frame.points.{name} = [{far.real:g}, {far.imag:g}] lies {apart:.4g} m from "
                        f"{first}, farther apart than any machine's pivots (over {LONGEST_LINK_M:g} m)")
        elif far_point is not None:
            # A named point's at or offset alone in millimetres moves no joint, so the mechanism runs; its drawings
            # are then refused at a scale or pole distance the student never gave, naming that key alone.
            told.append(far_point)
            some = True
    driver = mechanism.driver
    # An omega that reads as a motor's rpm explains a fast crank pin by itself, and is told so (``speed-in-rpm``):
    # asking of millimetres too would send the student to lengths that are right.
    rpm_typed = driver.kind == "crank" and driver.rpm is None and motor_speed_in_rpm(driver.omega)
    fast = driver.kind == "crank" and abs(driver.omega) * driver.length > FASTEST_CRANK_PIN_M_S and not rpm_typed
    if fast:
        told.append(f"driver.length = {driver.length:g} m at ω = {abs(driver.omega):.4g} rad/s moves the crank pin "
                    f"{driver.joint} at {abs(driver.omega) * driver.length:.4g} m/s, faster than any machine's (over "
                    f"{FASTEST_CRANK_PIN_M_S:g} m/s)")
    if not told:
        return ()
    unless = ", unless ω is too large: it is in rad/s, and rev/min are given as driver.rpm" if len(told) == 1 and fast \
        else ""
    return (PositionWarning(0, "lengths-in-mm", "; ".join(told) + f": {millimetres_question(some=some)}{unless}"),)


def _farthest_point(mechanism: Mechanism) -> str | None:
    """What to tell of the named point the scene places farthest from its link's joint, where that is farther
    than any machine's link reaches; None where every named point is within reach."""
    far = max(mechanism.scene.points, key=lambda spec: abs(complex(spec.at, spec.offset)), default=None)
    if far is None or abs(complex(far.at, far.offset)) <= LONGEST_LINK_M:
        return None
    key, value = ("at", far.at) if abs(far.at) >= abs(far.offset) else ("offset", far.offset)
    return (f"{far.where}.{key} = {value:g} m puts {far.name} {abs(complex(far.at, far.offset)):.4g} m from "
            f"{far.start}, farther than any machine's link reaches (over {LONGEST_LINK_M:g} m)")


def _frame_spread(mechanism: Mechanism) -> tuple[str, str, complex, float] | None:
    """The frame's first point, the point farthest from it with where it stands, and how far apart they are."""
    points = list(mechanism.scene.frame_points.items())
    if not points:
        return None
    first, origin = points[0]
    name, far = max(points, key=lambda item: abs(item[1] - origin))
    return first, name, far, abs(far - origin)


def mixed_units(mechanism: Mechanism) -> str | None:
    """What to tell a user whose mechanism does not assemble where a length looks typed in millimetres: one over
    :data:`LONGEST_LINK_M`, or :data:`MIXED_RATIO` times another (the frame's pivots' spread among them); None
    where the lengths are plausible together, and the geometry is to check."""
    lengths = [(f"{key} = {value:g} m", value) for key, value in given_lengths(mechanism) if value > 0]
    spread = _frame_spread(mechanism)
    if spread is not None and spread[3] > 0:
        first, name, _, apart = spread
        lengths.append((f"frame.points.{name} ({apart:g} m from {first})", apart))
    if len(lengths) < 2:
        return None
    # A joint placed or a guide put near its reference point is no link's length: only as the longest are they told.
    (long_one, longest), (short_one, shortest) = max(
        lengths + _placed_joints(mechanism) + _guide_spread(mechanism), key=lambda item: item[1]), min(
        lengths, key=lambda item: item[1])
    if longest <= LONGEST_LINK_M and longest < MIXED_RATIO * shortest:
        return None
    return f"{long_one} beside {short_one}: {millimetres_question(some=True)}"


def _placed_joints(mechanism: Mechanism) -> list[tuple[str, float]]:
    """The distances at which the scene places a named point that a group joins on to (a coupler point driving a
    rod): in millimetres it moves the group's joint as a link's length would."""
    joined = {joint for group in mechanism.groups for joint in group.known_joints()}
    found = []
    for spec in mechanism.scene.points:
        reach_m = abs(complex(spec.at, spec.offset))
        if spec.name in joined and reach_m > 0:
            key, value = ("at", spec.at) if abs(spec.at) >= abs(spec.offset) else ("offset", spec.offset)
            found.append((f"{spec.where}.{key} = {value:g} m (puts {spec.name} {reach_m:.4g} m from {spec.start})",
                          reach_m))
    return found


def _guide_spread(mechanism: Mechanism) -> list[tuple[str, float]]:
    """How far a frame guide's point given by its coordinates lies from the frame's first point: typed in
    millimetres, it puts the guide as far off as a frame point so typed puts a pivot."""
    points = list(mechanism.scene.frame_points.items())
    if not points:
        return []
    first, origin = points[0]
    solvers = [mechanism.driver, *mechanism.groups]
    guides = [*mechanism.scene.frame_lines.values(), *(guide for solver in solvers for guide in solver.guides())]
    found = []
    for guide in guides:
        if guide.on_frame and isinstance(guide.through, tuple):
            apart = abs(complex(*guide.through) - origin)
            if apart > 0:
                found.append((f"{guide.where}.through ({apart:g} m from {first})", apart))
    return found
