"""The exact analytic solution over all positions at once.

:func:`solve` runs the driver, then every group in structure order, each one
a closed-form position solution and two linear solves (velocities,
accelerations) vectorised over the positions; named points are placed on
their links as soon as those are known.  Assembly branches are chosen once,
at the first position (:func:`choose_branches`), and kept: the branch of a
group only changes where the group passes a toggle, which raises an error or
a warning, never silently.
"""

from __future__ import annotations

import contextlib
import math
import sys
from collections.abc import Callable, Collection, Mapping, Sequence
from dataclasses import dataclass, field, fields, replace
from types import MappingProxyType
from typing import Any

import numpy as np

from .errors import AssemblyError, PositionIndexError, SceneError, SingularPositionError, UnknownNameError
from .groups.base import Guide, GuideMotion
from .kinematics import (
    LinkMotion,
    PointMotion,
    SlideMotion,
    as_xy,
    at,
    point_fixed_on,
    read_only,
    unit,
)
from .lookalikes import lookalike_hint
from .mechanism import Mechanism, on_frame
from .memo import OwnedMemo
from .scene import PointSpec, Scene

# A group whose lines of action cross at less than this angle (degrees) has
# a transmission angle near 0° or 180°: it is solved, and it is warned of.
ILL_CONDITIONED_DEG = 1.0
# The sine of that angle, below which a group's conditioning is told.
ILL_CONDITIONED_SINE = math.sin(math.radians(ILL_CONDITIONED_DEG))

_STILL = 0j

# A slider this close to a named point's ``from`` along its slide (relative to their coordinates) is level with it:
# the coordinates' rounding, not a side to place the point toward.
_LEVEL = 1e-9

# A group found by continuation (a triad) is solved at least this often a turn of the crank (or along
# the slider's travel): Newton's method then starts within a degree of the next position.
CONTINUATION_STEPS = 360
# The longest walk a solve takes out to the values asked for: 100 turns, a minute's walk (a mistake, such as
# degrees given for radians or a time for an angle, beyond it).
_LONGEST_WALK = 100 * CONTINUATION_STEPS

# How a group's closest approach to a toggle between two samples of the dense sweep is found: each
# round solves this many points across the bracket round the least sine and keeps the two beside
# the least, so ten rounds narrow a 1° bracket to about 1e-9 rad.
_ZOOM_ROUNDS, _ZOOM_POINTS = 10, 17

# What the groups found by continuation found at each step of their walks, by scene and reference position.  By
# the scene, not the mechanism: every build of one scene is the same mechanism (its driver and groups are the
# scene's own), and graphplan.solve, the analysis, the reference solution and the dynamics each build their own, so
# that each walked the whole grid again (graphplan.solve at every call).  Not the built mechanism kept by scene
# instead: it holds its scene, so a memo of it would keep every scene alive.
_walks: OwnedMemo[dict[str, dict[int, Any]]] = OwnedMemo()


@dataclass(frozen=True)
class PositionWarning:
    """Something the user should know about one position (``position`` is its array index)."""

    position: int
    code: str
    detail: str


@dataclass(frozen=True)
class PointArrays:
    """A point's r, v, a as ``(N, 2)`` arrays, SI."""

    r: np.ndarray
    v: np.ndarray
    a: np.ndarray


@dataclass(frozen=True)
class LinkArrays:
    """A link's angle (rad), ω (rad/s), ε (rad/s²) as ``(N,)`` arrays, counter-clockwise positive.

    The angle is the direction of the link's reference line in (−π, π] (a driving crank's is the driver's
    coordinate, unwrapped): ``np.unwrap`` it along a sweep before plotting or differentiating it.
    """

    angle: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray


@dataclass(frozen=True)
class Motion:
    """The analytic motion of every point, link and sliding pair at every position.

    ``driver`` holds the driver's coordinate (crank angle in rad, or slider
    displacement in m) at each position.  Vectors are complex internally;
    :meth:`point` hands them out as ``(N, 2)`` float arrays.
    """

    mechanism: Mechanism
    driver: np.ndarray
    points: Mapping[str, PointMotion]
    links: Mapping[int, LinkMotion]
    slides: tuple[SlideMotion, ...]
    conditioning: Mapping[str, np.ndarray]
    warnings: tuple[PositionWarning, ...]
    singular: Mapping[int, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        # Handed out as it is (motion.driver): a view that cannot be written, as point() and link() hand theirs.
        object.__setattr__(self, "driver", read_only(np.asarray(self.driver).view()))
        # The motion's own arrays and tables are public fields: motion.points["B"].v[0] = … changed what point("B")
        # gave after, and a slide's s written left its slider's point where it was.
        for owner in (*self.points.values(), *self.links.values(), *self.slides):
            for field_ in fields(owner):
                read_only(getattr(owner, field_.name))
        for name in ("points", "links", "conditioning", "singular"):
            object.__setattr__(self, name, MappingProxyType(dict(getattr(self, name))))

    def __repr__(self) -> str:
        # The dataclass's own repr printed the scene and every array (8 600 characters for twelve positions).
        return (f"<Motion of {self.mechanism.scene.title!r} at {self.count} positions: points "
                f"{', '.join(self.points)}; links {', '.join(map(str, self.links))}>")

    def __reduce__(self):
        # Unpickled through the constructor, whose __post_init__ makes the arrays read-only again.
        return type(self), tuple(getattr(self, field_.name) for field_ in fields(self))

    @property
    def count(self) -> int:
        """The number of positions N."""
        return len(self.driver)

    def point(self, name: str) -> PointArrays:
        """Point ``name``'s r (m), v (m/s) and a (m/s²), each an ``(N, 2)`` array of x, y; read-only, since they are
        the motion's own (copy one to change it).  A name the motion does not have raises
        :class:`~graphplan.errors.UnknownNameError` (a ``KeyError`` too) that lists the points."""
        if not isinstance(name, str):
            raise TypeError(f"a point is named by its name, a string: point('B'), not point({name!r})")
        if name not in self.points:
            # A Cyrillic В among Latin names: the B it meant stood in the list, looking the same.
            raise UnknownNameError(f"no point {name!r}; points are {', '.join(self.points)}"
                                   f"{lookalike_hint(name, self.points)}")
        motion = self.points[name]
        return PointArrays(*(read_only(as_xy(value, self.count)) for value in (motion.r, motion.v, motion.a)))

    def link(self, number: int) -> LinkArrays:
        """Link ``number``'s angle (rad), ω (rad/s) and ε (rad/s²), each an ``(N,)`` array, counter-clockwise
        positive; read-only, as :meth:`point`'s.  A number the motion does not have raises
        :class:`~graphplan.errors.UnknownNameError`, as :meth:`point` does."""
        if isinstance(number, bool) or not isinstance(number, int | np.integer):
            raise TypeError(f"a link is named by its number, an integer: link(4), not link({number!r})")
        if number not in self.links:
            raise UnknownNameError(f"no link {number}; links are {', '.join(map(str, self.links))}")
        motion = self.links[number]
        shape = (self.count,)
        return LinkArrays(*(np.broadcast_to(np.asarray(value, dtype=float), shape)
                            for value in (motion.angle, motion.omega, motion.epsilon)))

    def guide(self, guide: Guide) -> GuideMotion:
        """``guide``'s line over the positions, as a group solved after these reads it."""
        return guide_motion(self.mechanism.scene, self.points, self.links, guide)

    def span(self, link: int | None = None, leaving_out: Collection[str] = (),
             slots: bool = True) -> tuple[float, str] | None:
        """The largest distance (m) between two points of ``link`` (the same at every position: the first's), or
        of the whole mechanism at the first position where ``link`` is None, with the two points (``"A–C"``); None
        for a link with one point (a slider's block).  What a link's mass, inertia or journal is weighed against;
        ``leaving_out`` names points not to measure (the scene's named points, for the span of a link's joints).

        With ``slots``, a moving link's body also reaches the ends of each slot or guide a block slides along on it,
        as far as the block's joint travels over the positions (``"D–A at one end of its guide"``): a Whitworth
        lever's slot runs on past its pivot away from the pin it drives, and its joints alone measured it a third as
        long."""
        if link is None:
            names = sorted(name for name in self.points if name not in leaving_out)
        else:
            names = sorted(name for name in self.mechanism.fixed_on.get(link, ())
                           if name in self.points and name not in leaving_out)
        where = {name: complex(*self.point(name).r[0]) for name in names}
        # The frame's guides are the machine's bed, which bounds no journal: a slider-crank's frame measured to the
        # piston's far end let a friction circle twice as wide as the crank is long pass at the crank's pivot.
        moving = link is not None and link != self.mechanism.scene.frame_link
        # Each slot end by its label, with the joint whose travel it ends: the two ends of one slot are named as one.
        end_of: dict[str, str] = {}
        for joint, ends in (self._slot_ends(link) if moving and slots else {}).items():
            for label, end in zip((f"{joint} at one end of its guide", f"{joint} at the other end of its guide"), ends,
                                  strict=True):
                where[label], end_of[label] = end, joint
        labels = list(where)

        def between(a: str, b: str) -> str:
            joint = end_of.get(a)
            return f"{joint}'s travel along its guide" if joint is not None and end_of.get(b) == joint else f"{a}–{b}"

        spans = [(abs(where[a] - where[b]), between(a, b)) for n, a in enumerate(labels) for b in labels[n + 1:]
                 if math.isfinite(abs(where[a] - where[b]))]
        return max(spans) if spans else None

    def _slot_ends(self, link: int) -> dict[str, tuple[complex, complex]]:
        """Where the joint of each block sliding on ``link`` stands at the two ends of its travel, in the link as it
        stands at the first position, by the joint's name; none where the block does not move along it."""
        ends: dict[str, tuple[complex, complex]] = {}
        for slide in self.slides:
            s = np.broadcast_to(slide.s, (self.count,))
            if slide.guide != link or slide.joint not in self.points or not np.all(np.isfinite(s)):
                continue
            start = complex(*self.point(slide.joint).r[0])
            u = complex(np.broadcast_to(slide.u, (self.count,))[0])
            lowest, highest = (start + (float(end) - float(s[0])) * u for end in (s.min(), s.max()))
            if abs(highest - lowest) > 0:
                ends[slide.joint] = lowest, highest
        return ends

    def at_positions(self, indices: Sequence[int]) -> Motion:
        """The motion at some of its positions only, in the order given (their warnings renumbered)."""
        chosen = np.asarray(indices)
        if chosen.ndim == 1 and not len(chosen):  # [] is read as floats: it was refused as no list of integers
            chosen = chosen.astype(int)
        if chosen.ndim != 1 or chosen.dtype.kind not in "iu":
            mask = "; a mask picks them as np.flatnonzero(mask)" if chosen.dtype.kind == "b" else ""
            raise TypeError(f"positions are picked by their indices, a list of integers (got {indices!r}){mask}")
        if len(chosen) and not (np.all(chosen < self.count) and np.all(chosen >= -self.count)):
            raise PositionIndexError(f"the motion has {self.count} positions, indices 0 to {self.count - 1} "
                                     f"(got {indices!r})")
        chosen = chosen % max(self.count, 1)
        renumbered = {int(old): new for new, old in enumerate(chosen)}
        points, links, slides, conditioning = _taken((self.points, self.links, self.slides, self.conditioning), chosen)
        warnings = tuple(replace(warning, position=renumbered[warning.position]) for warning in self.warnings
                         if warning.position in renumbered)
        singular = {renumbered[index]: reason for index, reason in self.singular.items() if index in renumbered}
        return Motion(mechanism=self.mechanism, driver=self.driver[chosen], points=points, links=links, slides=slides,
                      conditioning=conditioning, warnings=warnings, singular=singular)

    def slide(self, slider: int) -> SlideMotion:
        """The sliding pair in which link ``slider`` slides: its guide's unit direction ``u`` (complex, x + iy) and the
        slider's coordinate ``s`` along it (m), its relative ``velocity`` and ``acceleration`` along ``u`` (m/s,
        m/s²), each an ``(N,)`` array, read-only.  A link that slides in no pair raises
        :class:`~graphplan.errors.UnknownNameError`.

        ``s`` counts from the line's own origin: a guide's ``through`` point (the frame's point, or the named point
        of the link that carries the guide), from which a slider driver's values count too; in a slotted lever
        (``RPR``) the foot of the perpendicular from the lever's pivot to the slot (the pivot itself at
        ``offset = 0``); in an ``RPP``'s slot the point where the slot crosses the guide; in a triad's slotted leg
        the ternary link's inner joint."""
        if isinstance(slider, bool) or not isinstance(slider, int | np.integer):
            # slide('6') compared a string with the links' numbers and told of a link 6 that slides in no pair.
            raise TypeError(f"a sliding pair is named by its slider's number, an integer: slide(6), "
                            f"not slide({slider!r})")
        for slide in self.slides:
            if slide.slider == slider:
                # Views that cannot be written: a write would change the motion's own arrays.  A frame guide's u is
                # one number inside, handed out at every position as link() hands a link's constant ω.
                return replace(slide, **{name: np.broadcast_to(getattr(slide, name), (self.count,))
                                         for name in ("u", "s", "velocity", "acceleration")})
        pairs = ", ".join(f"link {slide.slider} on link {slide.guide}" for slide in self.slides)
        raise UnknownNameError(f"link {slider} slides in no pair; " + (f"the sliding pairs are {pairs}" if pairs
                                                                        else "the mechanism has no sliding pair"))


def guide_motion(scene: Scene, points: Mapping[str, PointMotion], links: Mapping[int, LinkMotion],
                 guide: Guide) -> GuideMotion:
    """``guide``'s line as ``points`` and ``links`` move it: a frame line by its name, a frame guide still, a guide on
    a moving link turning with it."""
    if guide.line is not None:
        guide = scene.frame_lines[guide.line]
    if on_frame(scene, guide):
        origin = points[guide.through] if isinstance(guide.through, str) else PointMotion(complex(*guide.through), _STILL, _STILL)
        return GuideMotion(scene.frame_link, origin, unit(guide.angle), 0.0, 0.0)
    assert guide.link is not None and isinstance(guide.through, str)
    link = links[guide.link]
    return GuideMotion(guide.link, points[guide.through], link.u * unit(guide.angle), link.omega, link.epsilon)


class _Context:
    """The motion found so far, as the groups ask for it while they solve."""

    def __init__(self, mechanism: Mechanism, values: np.ndarray, describe: Callable[[int], str],
                 tolerant: bool = False, start: int = 0, walked: dict[str, dict[int, Any]] | None = None,
                 steps: Sequence[int | None] | None = None) -> None:
        self.tolerant = tolerant
        self._walked = {} if walked is None else walked
        self._steps = [None] * len(values) if steps is None else steps
        self.singular: dict[int, str] = {}
        self.raised: dict[int, Exception] = {}
        self.count = len(values)
        self.start = start
        frame = list(mechanism.scene.frame_points.values())
        self.size = max([abs(r) for r in frame] + [abs(p - q) for p in frame for q in frame]
                        + [float(getattr(mechanism.driver, "length", 0.0) or 0.0)])
        scene = mechanism.scene
        self._scene = scene
        self._describe = describe
        self._driver = mechanism.driver
        self.points: dict[str, PointMotion] = {
            name: PointMotion(r, _STILL, _STILL) for name, r in scene.frame_points.items()
        }
        self.links: dict[int, LinkMotion] = {scene.frame_link: LinkMotion("", 1 + 0j, 0.0, 0.0, 0.0)}
        self.values = values

    def point(self, name: str) -> PointMotion:
        return self.points[name]

    def walk_memo(self, group: str) -> tuple[dict[int, Any], Sequence[int | None]]:
        return self._walked.setdefault(group, {}), self._steps

    def link(self, number: int) -> LinkMotion:
        return self.links[number]

    def guide(self, guide: Guide) -> GuideMotion:
        return guide_motion(self._scene, self.points, self.links, guide)

    def fail_where(self, bad: np.ndarray, error: Callable[[int, str], Exception]) -> None:
        if bad.any():
            index = int(np.argmax(bad))
            raise error(index, self._describe(index))

    def singular_where(self, bad: np.ndarray, error: Callable[[int, str], Exception]) -> None:
        if not self.tolerant:
            self.fail_where(bad, error)
            return
        for index in np.flatnonzero(bad):
            found = error(int(index), self._describe(int(index)))
            self.raised.setdefault(int(index), found)
            # The warning is told with its position's number: its text gives the driver's place alone.
            place = self._driver.describe(float(self.values[int(index)]))
            self.singular.setdefault(int(index), str(error(int(index), place)))


@dataclass(frozen=True)
class Reference:
    """What is fixed once, at one reference position, and kept for every solve.

    ``branches`` is the assembly branch of each group (a sign for a class-II
    group, a PRP's side and place, the pose found there for a triad); ``local`` the coordinates of
    each named point in its link's frame (link origin, link direction), so
    that the point rides rigidly with its link; ``value`` the driver's
    coordinate there; ``slides`` for each named point placed ``toward`` a slider,
    the slide's direction in the link's frame in the sense from ``from`` toward
    the slider there (see :func:`toward_slider`).
    """

    branches: tuple[object, ...]
    local: Mapping[str, complex]
    value: float = 0.0
    slides: Mapping[str, complex] = field(default_factory=dict)


def sides_value(mechanism: Mechanism) -> float:
    """The driver's coordinate where a point placed toward a slider takes its side: a turning crank's 0°, whatever
    the positions' ``start`` (a Scotch yoke's centre of mass jumped across its guide when the run started at 90°
    for 0°), a travel's or a swing's first end."""
    driver = mechanism.driver
    return float(driver.travel[0]) if not driver.cyclic else 0.0


def reference_at(mechanism: Mechanism, value: float, slides: Mapping[str, complex] | None = None) -> Reference:
    """Branches (from ``assembly`` or ``near``) and named points' local coordinates at driver coordinate ``value``.

    A point placed toward a slider takes its sense (``slides``) at :func:`sides_value`, whatever ``value`` is: a
    slider that crosses ``from`` (a sine mechanism's block) would otherwise put the point, and any group joined at it,
    on one side for one reference and on the other for the next.
    """
    if slides is None and any(spec.toward not in mechanism.fixed_on.get(spec.link, ()) for spec in mechanism.scene.points):
        first = sides_value(mechanism)
        if float(value) != first:
            with contextlib.suppress(AssemblyError, SingularPositionError):  # then taken here
                slides = reference_at(mechanism, first).slides
    values = np.array([float(value)])
    context = _Context(mechanism, values, lambda _: mechanism.driver.describe(float(value)))
    branches = []
    local: dict[str, complex] = {}
    given, slides = slides, {}
    for step, unit_ in enumerate(mechanism.units):
        if step == 0:
            found = mechanism.driver.solve(context, values)
        else:
            branch = unit_.solver.with_branch(context)  # type: ignore[union-attr]
            branches.append(branch)
            found = unit_.solver.solve(context, branch)  # type: ignore[union-attr]
        context.points.update(found.points)
        context.links.update(found.links)
        for spec in unit_.points:
            if spec.toward not in mechanism.fixed_on.get(spec.link, ()):
                slides[spec.name] = given[spec.name] if given is not None else toward_slider(
                    mechanism, spec, complex(at(context.point(spec.start).r, 0)),
                    complex(at(context.point(spec.toward).r, 0)), complex(at(context.link(spec.link).u, 0)))
            local[spec.name] = _local_coordinates(context, spec, mechanism, slides.get(spec.name))
            context.points[spec.name] = _place(context, spec, mechanism, local[spec.name])
    return Reference(tuple(branches), local, float(value), MappingProxyType(slides))


def _masked(values: object) -> bool:
    """Whether ``values`` is a masked array with something masked."""
    # Asked of numpy.ma only once something has imported it, as whoever made a masked array has: numpy imports it
    # lazily, and a run that never meets one would pay some 30 ms of its start-up for the question.
    masked_arrays = sys.modules.get("numpy.ma")
    return masked_arrays is not None and bool(masked_arrays.is_masked(values))


def solve(mechanism: Mechanism, values: Sequence[float] | np.ndarray, reference: Reference | None = None,
          numbers: Sequence[int] | None = None, tolerant: bool = False, indexed: bool = False) -> Motion:
    """The motion at every driver coordinate in ``values`` (rad for a crank, m for a slider).

    ``reference`` fixes the branches and named points (see
    :func:`reference_at`); without it they are fixed at ``values[0]``.
    ``numbers`` are the positions' numbers for error messages, or with ``indexed`` the values' indices
    (``driver[3]``: values a caller gave, where a crank's is told within the turn).  A position
    where a group's lines of action are parallel has no determined velocity:
    it raises :class:`SingularPositionError`, or, when ``tolerant``, is listed
    in ``Motion.singular`` with its reason (its velocities and accelerations
    are then not numbers and must not be read).
    """
    numbers_only = "must be an array of numbers (crank angles in rad, or slider positions in m)"
    if _masked(values):  # np.asarray keeps what the mask hides: the motion came out at those values
        hidden = ", ".join(f"driver[{index}]" for index in np.flatnonzero(np.ma.getmaskarray(values))[:3])
        raise SceneError("driver", f"has masked values ({hidden}), which the solve cannot leave out: give "
                                   f"driver.compressed(), the values the mask shows")
    try:
        given = np.asarray(values)
        if given.dtype.kind not in "iuf" and not (given.dtype.kind == "O" and all(
                isinstance(value, int | float | np.integer | np.floating) and not isinstance(value, bool | np.bool_)
                for value in given.ravel())):
            raise TypeError  # complex parts dropped, booleans and strings read as numbers: none is meant
        # A copy: the motion keeps its driver, whatever the caller does to the array afterwards.
        values = np.array(np.atleast_1d(given), dtype=float)
    except (TypeError, ValueError, OverflowError):  # OverflowError: a Python integer past float's range
        raise SceneError("driver", f"{numbers_only} (got {_shown(values)})") from None
    if values.ndim != 1:  # a grid of angles from np.meshgrid, say: which axis is the sweep only the caller knows
        raise SceneError("driver", f"must be a non-empty 1-D array of driver positions (got an array of shape "
                                   f"{values.shape}): give np.ravel(driver) for all its values")
    if len(values) == 0:
        raise SceneError("driver", "must be a non-empty 1-D array of driver positions (got an empty one)")
    if not np.all(np.isfinite(values)):
        # Among 36 000 angles the first bad one, by its index: "must be finite" alone left the caller to search.
        bad = np.flatnonzero(~np.isfinite(values))
        others = f"; {len(bad) - 1} more after it are not finite either" if len(bad) > 1 else ""
        raise SceneError(f"driver[{bad[0]}]", "must be a finite number, a driver position", float(values[bad[0]]),
                         hint=others)
    driver = mechanism.driver

    def describe(index: int) -> str:
        text = driver.describe(float(values[index]))
        if numbers is not None:
            return f"position {numbers[index]} ({text})"
        # Which of the caller's values: a crank's is told within the turn (−1e-9 rad as φ = 360°).
        return f"{text} (driver[{index}])" if indexed and len(values) > 1 else text

    if reference is None:
        try:
            reference = reference_at(mechanism, float(values[0]))
        except AssemblyError as error:  # the first value, where the branches are taken, named as the others are
            raise AssemblyError(error.joint, describe(0), error.group, error.reason) from None
        except SingularPositionError as error:
            raise SingularPositionError(describe(0), error.group, error.reason) from None

    solver = _solve_continued if any(group.continuation for group in mechanism.groups) else _solve
    if not tolerant:
        return solver(mechanism, values, reference, describe, tolerant)
    with np.errstate(divide="ignore", invalid="ignore"):
        return solver(mechanism, values, reference, describe, tolerant)


def _solve_continued(mechanism: Mechanism, values: np.ndarray, reference: Reference,
                     describe: Callable[[int], str], tolerant: bool) -> Motion:
    """The motion at ``values`` for a mechanism with a group found by continuation (a triad).

    Such a group follows one assembly from the reference position to its neighbours, so the
    positions are solved in driver order on a grid from the reference position out to every
    value asked for, :data:`CONTINUATION_STEPS` steps a turn (of the travel, for a slider) counted
    from the reference position, and the values asked for are taken out of it; the steps a solve
    walked are remembered for the next solve of the same scene (``walk_memo``).  A position between them where the
    mechanism does not assemble stops the walk with its error, as it stops the real mechanism; a
    singular one between them only matters when it is one of the values.
    """
    driver = mechanism.driver
    ends = np.append(values, reference.value)
    low, high = float(np.min(ends)), float(np.max(ends))
    if driver.cyclic:
        step = 2 * math.pi / CONTINUATION_STEPS
    else:
        step = abs(driver.travel[1] - driver.travel[0]) / CONTINUATION_STEPS or (high - low) / CONTINUATION_STEPS
    farthest = high if high - reference.value >= reference.value - low else low
    if abs(farthest - reference.value) / step > _LONGEST_WALK:
        unit, span = ("rad", "turns") if driver.cyclic else ("m", "travels")
        raise SceneError("driver", f"{farthest:g} {unit} is {abs(farthest - reference.value) / step / CONTINUATION_STEPS:.3g} "
                                   f"{span} from the reference position {reference.value:g} {unit}: a triad is "
                                   f"followed there a {CONTINUATION_STEPS}th of a {span[:-1]} at a time, which would "
                                   f"not end; give values within {_LONGEST_WALK // CONTINUATION_STEPS} {span} of it")
    # The grid is counted in steps from the reference position, the same for every solve: a group keeps what it
    # found at each step of it (while the scene lives) and walks on from there on the next solve.
    counted = np.arange(math.ceil((low - reference.value) / step), math.floor((high - reference.value) / step) + 1)
    grid = reference.value + counted * step
    on_grid = {float(value): int(k) for value, k in zip(grid, counted, strict=True) if low <= value <= high}
    walk, inverse = np.unique(np.concatenate([ends, list(on_grid)]), return_inverse=True)
    asked = inverse[:len(values)]
    start = int(inverse[len(values)])
    where_asked = {int(w): i for i, w in enumerate(asked)}
    walked = _walks.get(mechanism.scene, (reference.value, reference.branches), dict)

    def describe_walk(index: int) -> str:
        if index in where_asked:
            return describe(where_asked[index])
        return f"{driver.describe(float(walk[index]))}, on the way between the positions asked for"

    with np.errstate(divide="ignore", invalid="ignore"):
        context = _Context(mechanism, walk, describe_walk, tolerant=True, start=start, walked=walked,
                           steps=[on_grid.get(float(value)) for value in walk])
        found = _run(mechanism, context, walk, reference)
    points, links, slides, conditioning = _taken(found, asked)
    singular = {i: context.singular[int(w)] for i, w in enumerate(asked) if int(w) in context.singular}
    if singular and not tolerant:
        raise context.raised[int(asked[min(singular)])]
    warnings = tuple(PositionWarning(index, "singular", reason) for index, reason in sorted(singular.items()))
    conditioned = tuple(w for w in _conditioning_warnings(conditioning) if w.position not in singular)
    return Motion(mechanism=mechanism, driver=values, points=points, links=links, slides=slides,
                  conditioning=conditioning, warnings=tuple(sorted(warnings + conditioned, key=lambda w: w.position)),
                  singular=singular)


def _shown(values) -> str:
    text = repr(values)
    return text if len(text) <= 60 else f"{text[:57]}..."


def _taken(found, asked: np.ndarray):
    """The points, links, slides and conditioning of a walk at the positions asked for."""
    points, links, slides, conditioning = found

    def take(value):
        return value[asked] if isinstance(value, np.ndarray) and value.ndim else value

    return ({name: PointMotion(take(p.r), take(p.v), take(p.a)) for name, p in points.items()},
            {number: LinkMotion(link.origin, take(link.u), take(link.angle), take(link.omega), take(link.epsilon))
             for number, link in links.items()},
            tuple(SlideMotion(s.slider, s.guide, s.joint, take(s.u), take(s.s), take(s.velocity), take(s.acceleration))
                  for s in slides),
            {label: take(sine) for label, sine in conditioning.items()})


def _solve(mechanism: Mechanism, values: np.ndarray, reference: Reference,
           describe: Callable[[int], str], tolerant: bool) -> Motion:
    context = _Context(mechanism, values, describe, tolerant)
    _, _, slides, conditioning = _run(mechanism, context, values, reference)
    singular = tuple(PositionWarning(index, "singular", reason) for index, reason in sorted(context.singular.items()))
    conditioned = tuple(w for w in _conditioning_warnings(conditioning) if w.position not in context.singular)
    return Motion(mechanism=mechanism, driver=values, points=context.points, links=context.links,
                  slides=slides, conditioning=conditioning,
                  warnings=tuple(sorted(singular + conditioned, key=lambda w: w.position)),
                  singular=dict(context.singular))


def _run(mechanism: Mechanism, context: _Context, values: np.ndarray, reference: Reference):
    """Every unit in structure order on ``context``: the points, links, slides and conditioning found."""
    slides: list[SlideMotion] = []
    conditioning: dict[str, np.ndarray] = {}
    for step, unit_ in enumerate(mechanism.units):
        if step == 0:
            found = mechanism.driver.solve(context, values)
        else:
            found = unit_.solver.solve(context, reference.branches[step - 1])  # type: ignore[union-attr]
            conditioning[unit_.solver.label] = np.broadcast_to(np.abs(found.conditioning), values.shape)  # type: ignore[union-attr]
        context.points.update(found.points)
        context.links.update(found.links)
        slides.extend(found.slides)
        for spec in unit_.points:
            context.points[spec.name] = _place(context, spec, mechanism, reference.local[spec.name])
    return context.points, context.links, tuple(slides), conditioning


def toward_slider(mechanism: Mechanism, spec: PointSpec, start: complex, slider: complex, u: complex) -> complex:
    """The direction, in its link's frame, of a named point placed ``toward`` a slider on the link: along the slide
    line, in the sense from ``from`` toward where the slider is at the reference position (``start``, ``slider``
    the two points there, ``u`` the link's direction). A block may sit on either side of the point its slot is
    measured from (an RPP's block on the slot's negative side), so the slide's own sense is no answer to "toward".
    Where the slider is level with ``from`` there (a Scotch yoke's pin on the guide line at its extreme), no side
    is nearer: the slide's own sense is kept."""
    slide = complex(mechanism.sliding_on[spec.link][spec.toward])
    along = ((slider - start) * (u * slide).conjugate()).real
    level = _LEVEL * max(abs(start), abs(slider))
    return -slide if along < -level else slide


def _local_coordinates(context: _Context, spec: PointSpec, mechanism: Mechanism, slide: complex | None) -> complex:
    """Where a named point sits in its link's frame, from its definition at the reference position; ``slide`` the
    direction in the link's frame of a point placed toward a slider (:func:`toward_slider`)."""
    start = complex(at(context.point(spec.start).r, 0))
    link = context.link(spec.link)
    if slide is None:
        chord = complex(at(context.point(spec.toward).r, 0)) - start
        if chord == 0:
            raise SceneError(spec.where, f"from {spec.start!r} and toward {spec.toward!r} coincide, so they give no direction")
        direction = chord / abs(chord)
    else:
        direction = complex(at(link.u, 0)) * slide
    placed = start + (spec.at + 1j * spec.offset) * direction
    if spec.link == mechanism.scene.frame_link:
        return placed
    return (placed - complex(at(context.point(link.origin).r, 0))) / complex(at(link.u, 0))


def _place(context: _Context, spec: PointSpec, mechanism: Mechanism, local: complex) -> PointMotion:
    """A named point by the similarity of its link: its local coordinates carried by the link's pose."""
    if spec.link == mechanism.scene.frame_link:
        return PointMotion(local, _STILL, _STILL)
    link = context.link(spec.link)
    return point_fixed_on(context.point(link.origin), link, local)


def _conditioning_warnings(conditioning: Mapping[str, np.ndarray]) -> tuple[PositionWarning, ...]:
    limit = ILL_CONDITIONED_SINE
    warnings = []
    for label, sine in conditioning.items():
        if np.min(sine) >= limit:  # the usual case, told by one reduction (a NaN goes on)
            continue
        for index in np.flatnonzero(sine < limit):
            angle = math.degrees(math.asin(min(1.0, float(sine[index]))))
            warnings.append(PositionWarning(int(index), "ill-conditioned",
                                    f"lines of action at {angle:.3g}° in group {label} (condition number {1.0 / max(float(sine[index]), 1e-300):.3g})"))
    return tuple(sorted(warnings, key=lambda w: w.position))


def with_toggles_between(motion: Motion, reference: Reference, samples: int) -> Motion:
    """``motion`` (driver values in any order, as the Python interface takes them) with a warning at each toggle
    between two of its positions, found as :func:`toggles_between` finds them between a scene's positions.

    Each value is solved on its own, so positions either side of a toggle may be of two assemblies: the real
    mechanism, moving from one to the other, would change its assembly there, or not, as it happens.  The
    positions are taken in increasing driver coordinate (repeated values once), without a crank's wrap from
    the last back to the first, and swept over ``samples`` steps a turn (or over the values' span); a crank's
    values spanning more than a turn by their place in the turn, round it.
    """
    driver = motion.mechanism.driver
    distinct, first = np.unique(np.asarray(motion.driver, dtype=float), return_index=True)
    if len(distinct) < 2:
        return motion
    span = float(distinct[-1] - distinct[0])
    closed = driver.cyclic and span > 2 * math.pi
    if closed:
        # A crank's mechanism is the same every turn: values more than a turn apart are taken by their place in
        # the turn, one turn swept round. Swept turn by turn, [0, 1e5] rad took 5.7 million samples and 2.9 GB,
        # [0, 1e7] more than there is, and 99 turns warned of each toggle 198 times.
        places, in_turn = np.unique(distinct[0] + np.mod(distinct - distinct[0], 2 * math.pi), return_index=True)
        first = first[in_turn]
        sweep = places[0] + np.linspace(0.0, 2 * math.pi, samples + 1)
    else:
        steps = max(samples, math.ceil(samples * span / (2 * math.pi))) if driver.cyclic else samples
        sweep = np.linspace(distinct[0], distinct[-1], steps + 1)
    paths = solve(motion.mechanism, sweep, reference, tolerant=True)
    # Values already rising (a linspace, the usual sweep) need no reordered copy of a motion that may be large.
    ordered = motion if len(first) == motion.count and np.all(np.diff(first) > 0) else motion.at_positions(first)
    if closed:
        ordered = replace(ordered, driver=places)
    found = toggles_between(ordered, [int(index) for index in first], reference, paths, closed=closed)
    if not found:
        return motion
    stepped = tuple(replace(warning, position=int(first[warning.position])) for warning in found)
    return replace(motion, warnings=tuple(sorted(motion.warnings + stepped, key=lambda w: w.position)))


def toggles_between(analysed: Motion, numbers: Sequence[int], reference: Reference,
                    sweep: Motion, closed: bool | None = None) -> tuple[PositionWarning, ...]:
    """A warning at each analysed position after which a group passes a toggle before the next one.

    Between two regular positions a group's lines of action can come within ILL_CONDITIONED_DEG of
    parallel, unseen by either position.  There the real mechanism may go on in the other assembly
    (a change-point linkage turns from parallelogram to anti-parallelogram) while the solver keeps
    the branch it chose, so every later position would be of another mechanism.  ``sweep`` is the
    motion over the driver's whole range (the paths), solved with ``reference``, a crank's whole turn from
    the first position back to it unless not ``closed``; each local least
    sine in it is narrowed by a zoom to where the group comes closest to the toggle.  A toggle
    within a sample of an analysed position that is itself ill-conditioned is that position's,
    and already warned of.
    """
    mechanism, values = analysed.mechanism, analysed.driver
    limit = ILL_CONDITIONED_SINE
    x = sweep.driver
    span = float(x[-1] - x[0])
    cyclic = mechanism.driver.cyclic if closed is None else closed
    brackets, labels = [], []
    for label, sine in sweep.conditioning.items():
        sine = np.nan_to_num(sine, nan=0.0)
        # A crank's sweep closes on itself: its first and last samples are one position.
        inner = np.arange(0 if cyclic else 1, len(x) - 1)
        before = np.where(inner == 0, sine[-2], sine[inner - 1])  # sample 0's neighbour before it is the last but one
        after = sine[inner + 1]
        # Two equal samples either side of a minimum are one minimum: the first of them is its bracket.
        least = (sine[inner] < before) & (sine[inner] <= after)
        # Only a least sample that could hide a toggle is zoomed into. Between samples h apart the sine
        # dips below its least sample by at most the larger step to a neighbour: a smooth minimum
        # c + k·(x − x0)² by k·h²/4 against steps of at least k·h², a crossing of parallel (|m·(x − x0)|)
        # to 0 against a step of m·h. Twice that step is the margin.
        steep = np.maximum(np.abs(sine[inner] - before), np.abs(after - sine[inner]))
        for i in inner[least & (sine[inner] - 2 * steep < limit)]:
            low = x[i - 1] if i > 0 else x[0] - (x[1] - x[0])
            brackets.append((float(low), float(x[i + 1])))
            labels.append(label)
    if not brackets:
        return ()
    low, high = np.array(brackets).T
    for _ in range(_ZOOM_ROUNDS):
        grid = np.linspace(low, high, _ZOOM_POINTS, axis=1)
        found = solve(mechanism, grid.ravel(), reference, tolerant=True).conditioning
        sine = np.nan_to_num(np.array([found[label].reshape(grid.shape)[k] for k, label in enumerate(labels)]), nan=0.0)
        best = np.argmin(sine, axis=1)
        rows = np.arange(len(labels))
        low = grid[rows, np.maximum(best - 1, 0)]
        high = grid[rows, np.minimum(best + 1, _ZOOM_POINTS - 1)]
    closest = sine[rows, best]
    where = grid[rows, best]
    # Where the analysed positions lie along the sweep (0 at its start, 1 at its end).
    ends = (np.asarray(values, dtype=float) - x[0]) / span
    if cyclic:
        ends = np.append(ends, 1.0)
    sample = abs(float(x[1] - x[0]) / span)
    warnings = []
    for label, sine_, at_ in zip(labels, closest, where, strict=True):
        if sine_ >= limit:
            continue
        along = ((at_ - x[0]) / span) % 1.0 if cyclic else (at_ - x[0]) / span
        after = int(np.searchsorted(ends, along)) - 1
        if after < 0 or after >= len(values) - (0 if cyclic else 1):
            continue  # beyond the analysed positions: no position after it can be on the wrong branch
        following = (after + 1) % len(values)
        if following == after:
            continue  # a crank's one position: the turn comes back to it, and no position after it can change branch
        own = np.nan_to_num(analysed.conditioning[label], nan=0.0)
        if any(own[position] < limit and abs(ends[place] - along) <= sample
               for position, place in ((after, after), (following, after + 1))):
            continue
        angle = math.degrees(math.asin(min(1.0, float(sine_))))
        warnings.append(PositionWarning(after, "toggle-between",
                                        f"between positions {numbers[after]} and {numbers[following]} the lines of action "
                                        f"of group {label} come within {angle:.3g}° of parallel "
                                        f"({mechanism.driver.describe(float(at_))}): the real mechanism may change "
                                        f"assembly there, while the positions after it keep the assembly of the first"))
    return tuple(warnings)
