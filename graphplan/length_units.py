"""Lengths typed in millimetres where the scene asks for metres: the warning where the mechanism still runs (every
length a thousand times too long, the results with them), and the hint where one typed so stops it assembling.
"""

from __future__ import annotations

from dataclasses import dataclass

from .errors import SceneError
from .mechanism import Mechanism
from .motion import Motion, PositionWarning
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
# A named point lies on its link's body: a centre of mass within the span of the link's joints, a coupler point or a
# lever's handle a few spans out (a hand lever's some 10).  One FARTHEST_POINT_SPANS times the span from its joint is
# a length typed in millimetres (a crank's centre 6 m out on a 0.05 m crank), or the link's own length typed a
# thousandth of itself (a 75 µm crank with its centre 25 mm out): the fixtures' named points lie within 1.1 spans.
FARTHEST_POINT_SPANS = 20.0


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


@dataclass(frozen=True)
class FarOff:
    """The named point far off its link that gives a length slip away: its name, the joint it is placed from, how
    far (m), the link's two joints that span it (``"O–A"``), how many times the slipped length, as typed, is off
    the length beside it that it is judged by (the link's span, for a point's; the mechanism's next shortest
    length, for a link's), and how far the point lies with the slip put right (its ``at`` or ``offset`` a
    thousandth, the other as typed; for a link's, as far as typed)."""

    point: str
    start: str
    reach: float
    joints: str
    times: float
    reach_meant: float


@dataclass(frozen=True)
class LengthSlip:
    """One length the scene gives that no machine's linkage has in metres: its key, its value as typed (a frame
    point's ``[x, y]``), what it does there (``puts E 240 m from A, …``), told after ``key = value m``, and whether
    it stands alone among lengths in metres (a named point's, or one :data:`MIXED_RATIO` times the shortest) or
    with them all in millimetres.  ``shorter``: typed a thousand times too short, metres divided by 1000 again (a
    crank of 7.5e-05 for 0.075), not millimetres typed for metres.  ``far_off``: the named point far off its link
    that gives the slip away, where one does."""

    key: str
    value: float | tuple[float, float]
    does: str
    alone: bool
    shorter: bool = False
    far_off: FarOff | None = None

    @property
    def meant_value(self) -> float | tuple[float, float]:
        """What was likely meant: the value a thousand times smaller (or, ``shorter``, larger)."""
        value = self.value
        if isinstance(value, tuple):
            return value[0] / 1000, value[1] / 1000
        return value * 1000 if self.shorter else value / 1000

    @property
    def typed(self) -> str:
        """``key = value m``, as the warning opens."""
        return f"{self.key} = {_written(self.value)}" + ("" if isinstance(self.value, tuple) else " m")

    @property
    def meant(self) -> str:
        """The question the refusal asks: the value read as millimetres (or as metres divided once too often), and
        the key with what was likely meant."""
        if self.shorter:
            return f"metres divided by 1000 again? {self.key} = {_written(self.meant_value)} was likely meant"
        return f"millimetres typed for metres? {_written(self.value)} mm is {self.key} = {_written(self.meant_value)}"


def _written(value: float | tuple[float, float]) -> str:
    return f"[{value[0]:g}, {value[1]:g}]" if isinstance(value, tuple) else f"{value:g}"


def length_slip(motion: Motion) -> LengthSlip | None:
    """The length :func:`lengths_in_millimetres` names as typed in another unit: beyond :data:`LONGEST_LINK_M`, the
    longest link's, else the frame point farthest from the first, else the frame guide's point farthest from it,
    else the named point placed farthest from its link's joint; where none is, a named point placed
    :data:`FARTHEST_POINT_SPANS` times its link's span from its joint (:func:`_point_off_its_link`); else None."""
    mechanism = motion.mechanism
    lengths = given_lengths(mechanism)
    key, longest = max(lengths, key=lambda item: item[1]) if lengths else ("", 0.0)
    # A named point's reach counts among the lengths a long one stands alone among: a Scotch yoke's crank is its
    # only link's length, and its centre of mass 25 mm out is in metres as well.
    reaches = [abs(complex(spec.at, spec.offset)) for spec in mechanism.scene.points]
    shortest = min((value for value in [*(value for _, value in lengths), *reaches] if value > 0), default=0.0)
    if longest > LONGEST_LINK_M:
        return LengthSlip(key, longest, f"is longer than any machine's link (over {LONGEST_LINK_M:g} m)",
                          longest >= MIXED_RATIO * shortest)
    spread = _frame_spread(mechanism)
    if spread is not None and spread[3] > LONGEST_LINK_M:
        first, name, far, apart = spread
        return LengthSlip(f"frame.points.{name}", (far.real, far.imag), f"lies {apart:.4g} m from {first}, farther "
                          f"apart than any machine's pivots (over {LONGEST_LINK_M:g} m)",
                          apart >= MIXED_RATIO * shortest)
    # A guide so far off that the mechanism still assembles along it (a PRP's, whose sliders follow it anywhere)
    # swells every drawing as a frame point would.
    guide = max(_frame_guides(mechanism), key=lambda found: found[2], default=None)
    if guide is not None and guide[2] > LONGEST_LINK_M:
        key, through, apart, first = guide
        return LengthSlip(key, through, f"lies {apart:.4g} m from {first}, farther than any machine's frame reaches "
                          f"(over {LONGEST_LINK_M:g} m)", apart >= MIXED_RATIO * shortest)
    # A slide set off its guide (a PRP's, whose sliders still meet however far off) carries its joint as far off:
    # it swells every drawing as a frame point would, and is the key to change where those are refused.
    offset = max(_slide_offsets(mechanism), key=lambda found: abs(found[1]), default=None)
    if offset is not None and abs(offset[1]) > LONGEST_LINK_M:
        key, value, joint = offset
        return LengthSlip(key, value, f"sets the slide at {joint} {abs(value):.4g} m off its guide, farther than any "
                          f"machine's slide is set off (over {LONGEST_LINK_M:g} m)",
                          abs(value) >= MIXED_RATIO * shortest)
    return _farthest_point(mechanism) or _point_off_its_link(motion)


def _slide_offsets(mechanism: Mechanism) -> list[tuple[str, float, str]]:
    """Each non-zero offset of a slide from its guide the groups give: its key, its value, and the joint it
    carries (a PRP's B, an RPR's block pin)."""
    found = []
    for group in mechanism.groups:
        offsets = getattr(group, "offsets", None)
        if offsets is not None:
            found += [(f"{group.where}.offsets[{n}]", value, group.joints[0]) for n, value in enumerate(offsets)
                      if value]
        elif getattr(group, "offset", 0.0):
            found.append((f"{group.where}.offset", group.offset, group.joints[0]))
    return found


def lengths_in_millimetres(motion: Motion) -> tuple[PositionWarning, ...]:
    """A ``lengths-in-mm`` warning, at the first position, where the scene's lengths are implausible as metres: a
    link or the frame larger than any machine's, a named point far off its link (or its link a thousandth of the
    rest), or a crank turning its pin faster than any machine does."""
    mechanism = motion.mechanism
    if (slip := length_slip(motion)) is not None and slip.shorter:
        # A length a thousandth of itself asks nothing of millimetres: dividing them by 1000 would shrink it further.
        return (PositionWarning(0, "lengths-in-mm", f"{slip.typed} {slip.does}: {slip.meant}"),)
    told = []
    # A named point's at or offset alone in millimetres moves no joint, so the mechanism runs: only that length is
    # in millimetres among metres, and the drawings it swells are refused at it (:func:`refused_at_slip`).
    some = slip is not None and slip.alone
    if slip is not None:
        told.append(f"{slip.typed} {slip.does}")
    driver = mechanism.driver
    if fast := crank_pin_too_fast(mechanism):
        told.append(f"driver.length = {driver.length:g} m at ω = {abs(driver.omega):.4g} rad/s moves the crank pin "
                    f"{driver.joint} at {abs(driver.omega) * driver.length:.4g} m/s, faster than any machine's (over "
                    f"{FASTEST_CRANK_PIN_M_S:g} m/s)")
    if not told:
        return ()
    unless = ", unless ω is too large: it is in rad/s, and rev/min are given as driver.rpm" if len(told) == 1 and fast \
        else ""
    return (PositionWarning(0, "lengths-in-mm", "; ".join(told) + f": {millimetres_question(some=some)}{unless}"),)


def crank_pin_too_fast(mechanism: Mechanism) -> bool:
    """Whether the crank turns its pin faster than :data:`FASTEST_CRANK_PIN_M_S`, its ω not a motor's rpm."""
    driver = mechanism.driver
    # An omega that reads as a motor's rpm explains a fast crank pin by itself, and is told so (``speed-in-rpm``):
    # asking of millimetres too would send the student to lengths that are right.
    rpm_typed = driver.kind == "crank" and driver.rpm is None and motor_speed_in_rpm(driver.omega)
    return bool(driver.kind == "crank" and abs(driver.omega) * driver.length > FASTEST_CRANK_PIN_M_S and not rpm_typed)


def refused_at_slip(motion: Motion, drawn: str, across_mm: float, largest_mm: float) -> SceneError | None:
    """The refusal of a drawing ``across_mm`` wide, more than ``largest_mm``, at the length typed in millimetres
    that swells it, where :func:`length_slip` finds one and the drawing would fit were it a thousand times smaller;
    None otherwise, the drawing's own scale then the key to change.

    ``drawn`` says what the drawing is and at which key's value (``draws the velocity plan of position 5 6.52e+04
    mm across at drawing.velocity_pole = 150``).  Refused at that key alone, the student was sent to a scale never
    changed, while the warning just before named the length."""
    slip = length_slip(motion)
    # Every length in millimetres is no one key's slip: the warning asks to divide them all, and a μl given for
    # them is refused at its own key.
    if slip is None or not slip.alone:
        return None
    value = list(slip.value) if isinstance(slip.value, tuple) else slip.value
    if across_mm / 1000 <= largest_mm:
        return SceneError(slip.key, f"{slip.does}, and {drawn}, more than any paper ({largest_mm:g} mm): "
                          f"{slip.meant}", value)
    # Larger than millimetres explain (a point typed a billion metres out): still the one length that stands alone
    # beyond the rest is the key to change, where the drawing's scale would be drawn at a size no plan is read at.
    return SceneError(slip.key, f"{slip.does}, and {drawn}, more than any paper ({largest_mm:g} mm), even were it "
                      "typed in millimetres: give it in metres, as the mechanism's other lengths are", value)


def _farthest_point(mechanism: Mechanism) -> LengthSlip | None:
    """The named point the scene places farthest from its link's joint, where that is farther than any machine's
    link reaches; None where every named point is within reach."""
    far = max(mechanism.scene.points, key=lambda spec: abs(complex(spec.at, spec.offset)), default=None)
    if far is None or abs(complex(far.at, far.offset)) <= LONGEST_LINK_M:
        return None
    key, value = ("at", far.at) if abs(far.at) >= abs(far.offset) else ("offset", far.offset)
    return LengthSlip(f"{far.where}.{key}", value, f"puts {far.name} {abs(complex(far.at, far.offset)):.4g} m from "
                      f"{far.start}, farther than any machine's link reaches (over {LONGEST_LINK_M:g} m)", True)


def _point_off_its_link(motion: Motion) -> LengthSlip | None:
    """A named point placed :data:`FARTHEST_POINT_SPANS` times its link's span (its joints', the named points left
    out) from its joint, told at the length of the two that stands alone beyond the mechanism's other lengths: the
    point's ``at`` or ``offset`` where it reaches beyond every one of them (millimetres typed for metres), the link's
    own length where it falls short of every one (metres divided by 1000 again); None where no point is so far
    off, or neither stands alone (nothing to tell which is the slip)."""
    mechanism = motion.mechanism
    named = {spec.name for spec in mechanism.scene.points}
    given = given_lengths(mechanism)
    for spec in sorted(mechanism.scene.points, key=lambda spec: -abs(complex(spec.at, spec.offset))):
        reach = abs(complex(spec.at, spec.offset))
        span = _joints_span(motion, spec.link, named, spec.start)
        if span is None or not reach >= FARTHEST_POINT_SPANS * span[0]:
            continue
        length = _length_of_link(mechanism, spec.link, span[0], given)
        # Told by the lengths that are neither: the point's reach beyond every one of them, or the link's length
        # short of every one.  A crank with only its centre to go by tells neither.
        rest = [abs(complex(other.at, other.offset)) for other in mechanism.scene.points if other is not spec]
        rest += [apart for _, _, apart, _ in _frame_guides(mechanism)]
        if (spread := _frame_spread(mechanism)) is not None:
            rest.append(spread[3])
        rest += [value for key, value in given if length is None or key != length[0]]
        rest = [value for value in rest if value > 0]
        if not rest:
            continue
        beyond, short_of = reach / max(rest), min(rest) / span[0]
        if beyond > 1 and beyond >= short_of:
            key, value = ("at", spec.at) if abs(spec.at) >= abs(spec.offset) else ("offset", spec.offset)
            meant = complex(spec.at / 1000, spec.offset) if key == "at" else complex(spec.at, spec.offset / 1000)
            return LengthSlip(f"{spec.where}.{key}", value, f"puts {spec.name} {reach:.4g} m from {spec.start}, "
                              f"{_times(reach / span[0])} times the {span[0]:.4g} m its link {spec.link} spans "
                              f"({span[1]}) and beyond every other length of the mechanism "
                              f"({max(*rest, span[0]):.4g} m at most)", True,
                              far_off=FarOff(spec.name, spec.start, reach, span[1], reach / span[0], abs(meant)))
        if length is not None and short_of > 1:
            shortest = min(*rest, reach)
            return LengthSlip(length[0], length[1], f"is {_times(shortest / span[0])} times shorter than every other "
                              f"length of the mechanism ({shortest:.4g} m and up; {spec.name} lies {reach:.4g} m from "
                              f"{spec.start} on link {spec.link})", True, shorter=True,
                              far_off=FarOff(spec.name, spec.start, reach, span[1], shortest / span[0], reach))
    return None


def _times(ratio: float) -> str:
    """A ratio as the warnings write how many times: whole from 10 on (2133, not 2.13e+03)."""
    return f"{ratio:.0f}" if ratio >= 10 else f"{ratio:.2g}"


def _joints_span(motion: Motion, link: int, named: set[str], start: str) -> tuple[float, str] | None:
    """The span (:meth:`~graphplan.motion.Motion.span`) of ``link``'s points that are no named points (its joints,
    a frame's pivots), with the two, ``start`` first where it is one (``"O–A"``); None for a link with one such point
    (a slider's block, a yoke), or whose such points stand at one place."""
    span = motion.span(link, leaving_out=named, slots=False)
    if span is None or not span[0] > 0:
        return None
    first, second = span[1].split("–")
    return span[0], f"{second}–{first}" if second == start else span[1]


def _length_of_link(mechanism: Mechanism, link: int, span: float,
                    given: list[tuple[str, float]]) -> tuple[str, float] | None:
    """The key and value of the length the scene gives that is ``link``'s span: the crank's, or the one given length
    of that value; None where none is (a span between joints no one length gives), or several are (which of them
    was typed is not to be told)."""
    # The span is measured on the solved positions: a class III group's by Newton's method, to some 1e-12.
    found = [(key, value) for key, value in given if abs(value - span) <= 1e-6 * span]
    driver = mechanism.driver
    if driver.kind == "crank" and driver.link == link and ("driver.length", driver.length) in found:
        return "driver.length", driver.length
    return found[0] if len(found) == 1 else None


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
    return [(f"{key} ({apart:g} m from {first})", apart) for key, _, apart, first in _frame_guides(mechanism)]


def frame_anchors(mechanism: Mechanism) -> list[tuple[str, complex]]:
    """Where the frame holds the mechanism: each frame point and each frame guide's point given by its
    coordinates, with its key (``frame.points.C``, ``groups[0].guide.through``)."""
    anchors = [(f"frame.points.{name}", point) for name, point in mechanism.scene.frame_points.items()]
    return anchors + [(f"{guide.where}.through", complex(*guide.through)) for guide in mechanism.scene.guides
                      if guide.on_frame and isinstance(guide.through, tuple)]


def _frame_guides(mechanism: Mechanism) -> list[tuple[str, tuple[float, float], float, str]]:
    """Each frame guide's point given by its coordinates: its key, the point, how far it lies from the frame's
    first point, and that point's name."""
    points = list(mechanism.scene.frame_points.items())
    if not points:
        return []
    first, origin = points[0]
    found = []
    for guide in mechanism.scene.guides:
        if guide.on_frame and isinstance(guide.through, tuple):
            apart = abs(complex(*guide.through) - origin)
            if apart > 0:
                found.append((f"{guide.where}.through", guide.through, apart, first))
    return found
