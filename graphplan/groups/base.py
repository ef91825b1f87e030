"""What every group kind shares: guides, the solving context, the group record.

A group kind is one module holding one :class:`Group` subclass that reads
its own keys from the scene, names the joints it needs and the joints it
finds, and solves its position, velocity and acceleration over all positions
at once.  The registry in ``groups/__init__.py`` maps ``kind`` to the class.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, ClassVar, Protocol

import numpy as np

from ..errors import SceneError, SingularPositionError
from ..kinematics import LinkMotion, PointMotion, Scalar, SlideMotion, Vector
from ..reader import Table, check_str, check_xy, radians_within_a_turn

# Below this sine of the angle between two lines of action a position is
# treated as exactly singular: the velocities are not determined by the
# driver any more, and a number would be a guess.
SINGULAR_SINE = 1e-12
# A squared height this small (relative to the squares it is the difference
# of) is rounding at a toggle: the joint lies on the line, and is placed there.
# Either side of zero: a travel typed to end at a dead centre (0.3 − 0.1 falls
# short of 0.2 in binary) left a height of 1e-8 above it, and a "position"
# whose velocities were rounding divided by rounding (ω 1e8 rad/s, Fb 1e29 N).
TOGGLE_ROUNDING = 1e-12


def at_toggle(square: np.ndarray | float, scale: np.ndarray | float) -> np.ndarray | float:
    """``square`` with rounding either side of zero at a toggle set to zero; a real shortfall stays negative."""
    return np.where(np.abs(square) < TOGGLE_ROUNDING * scale, 0.0, square)


@dataclass(frozen=True)
class Guide:
    """A straight line along which a slider moves.

    ``link`` carries the line (the frame's number for a fixed guide);
    ``through`` is a named point of that link or fixed coordinates on the
    frame; ``angle`` is in radians, measured from the carrying link's
    reference line (from +x on the frame).  ``line`` names a frame line of
    ``[frame] lines`` instead, resolved when the mechanism is built.
    """

    where: str
    link: int | None = None
    through: str | tuple[float, float] | None = None
    angle: float = 0.0
    line: str | None = None
    # Whether the scene wrote the angle: the contract always does, so one left out is told (it runs along +x).
    angle_given: bool = field(default=True, compare=False, repr=False)
    # Whether the scene wrote ``through``: a triad's sliding leg takes its outer joint, and a problem with that point
    # is told on the key the user wrote (the guide's link), not on one they cannot write.
    through_given: bool = field(default=True, compare=False, repr=False)

    @property
    def on_frame(self) -> bool:
        return self.link is None


# The guide a group's dataclass starts with before ``read`` puts the scene's in its place; frozen, so one serves all.
UNREAD_GUIDE = Guide(where="")


def read_guide(value: object, where: str) -> Guide:
    """A guide as the scene writes it: a frame line's name or a table."""
    if isinstance(value, str):
        return Guide(where=where, line=check_str(value, where))
    table = Table(value, where)
    link = table.integer("link", None, minimum=1)
    through_raw = table.raw("through")
    if isinstance(through_raw, str):
        through: str | tuple[float, float] = check_str(through_raw, table.where("through"))
    else:
        through = check_xy(through_raw, table.where("through"))
    angle = radians_within_a_turn(table.number("angle", 0.0))
    table.done()
    return Guide(where=where, link=link, through=through, angle=angle, angle_given=table.has("angle"))


@dataclass(frozen=True)
class GuideMotion:
    """A guide in motion: a point of the line, its direction, its link's rotation."""

    link: int
    origin: PointMotion
    u: Vector
    omega: Scalar
    epsilon: Scalar

    def carried(self, r: Vector) -> tuple[Vector, Vector]:
        """Velocity and acceleration of the guide's link at ``r``: the point under a slider."""
        arm = r - self.origin.r
        return (self.origin.v + 1j * self.omega * arm,
                self.origin.a + (1j * self.epsilon - self.omega * self.omega) * arm)


class Context(Protocol):
    """What a group may ask while it solves: the motion found so far.

    ``count`` is the number of positions; ``start`` the index of the position
    where the branches were chosen, from which a group solved by
    continuation walks out to its neighbours on either side (the positions
    are in driver order then).
    """

    count: int
    start: int
    # The mechanism's size (m), the same at every position: its frame points' largest coordinate or distance apart,
    # or its driver's length.  A scale for the rounding of the coordinates where the positions asked for leave
    # none (one position, with the joints at the origin).
    size: float

    def point(self, name: str) -> PointMotion: ...

    def link(self, number: int) -> LinkMotion: ...

    def guide(self, guide: Guide) -> GuideMotion: ...

    def walk_memo(self, group: str) -> tuple[dict[int, Any], Sequence[int | None]]:
        """For a group found by continuation: what it found before at the steps of the walk (by step, counted
        from the reference position; kept while the scene lives), and each position's step, or None for a
        position off the steps (one asked for between them)."""
        ...

    def fail_where(self, bad: np.ndarray, error: Callable[[int, str], Exception]) -> None:
        """Raise ``error(i, position_text)`` for the first position where ``bad`` holds."""
        ...

    def singular_where(self, bad: np.ndarray, error: Callable[[int, str], Exception]) -> None:
        """Positions where the velocities are undetermined: an error, or noted when the solve tolerates them."""
        ...


@dataclass(frozen=True)
class GroupMotion:
    """What a group found: its new points, its links' motion, its sliding pairs.

    ``conditioning`` is the sine of the angle between the two lines of action
    of the group's velocity equation at every position (1 is best, 0 is a
    toggle): the group's transmission quality and the error amplification of
    the plan construction alike.
    """

    points: dict[str, PointMotion]
    links: dict[int, LinkMotion]
    slides: tuple[SlideMotion, ...] = ()
    conditioning: Scalar = 1.0


@dataclass(frozen=True)
class Group:
    """An Assur group: by default of class II, two links and three kinematic pairs.

    Subclasses set ``kind`` and ``joint_roles`` and implement :meth:`read`,
    :meth:`solve` and the membership queries.  A group of a higher class
    sets its ``link_count``, ``klass`` and ``order`` (its pairs are
    ``3·link_count/2``, W = 0).  ``continuation`` says that its position has
    no closed form and is followed from a neighbouring position
    (``Context.start``), so the motion must ask for positions close enough.
    """

    kind: ClassVar[str]
    joint_roles: ClassVar[tuple[str, ...]]
    link_count: ClassVar[int] = 2
    klass: ClassVar[int] = 2
    order: ClassVar[int] = 2
    continuation: ClassVar[bool] = False
    # What stops the group at an end of a crank's reach, in the refusal's words.
    reach_ends: ClassVar[str] = "two links stand in line"
    where: str
    links: tuple[int, ...]
    joints: tuple[str, ...]

    @property
    def label(self) -> str:
        """The group's name on the sheets, in the tables and as results.json's key: its class and links, ``II(3,4)``
        (the structure formula adds its order, ``II2(3,4)``)."""
        return f"II({self.links[0]},{self.links[1]})"

    @property
    def pair_count(self) -> int:
        """Its lower pairs: 3n/2 for an Assur group of n links (W = 3n − 2·p5 = 0)."""
        return 3 * self.link_count // 2

    def mirrored(self) -> Group | None:
        """The group with the orientation its sketch fixes turned over (a triad's ``near``: which way round its
        ternary link's corners run), for the advice where it assembles nowhere; None where no sketch fixes one."""
        return None

    def nowhere(self, before) -> str | None:
        """Where the mechanism assembles nowhere and this group stops it, what in its own geometry does, read off
        ``before``, the motion of the groups before it over the driver's reach (an RPR's slide farther from the
        lever's pivot than the block ever comes); None where the lengths are to check."""
        return None

    def turning_round(self, before) -> str | None:
        """Where the crank reaches only part of its turn and this group stops it, what its own lengths must be for
        the crank to turn round, read off ``before``, the motion of the groups before it over the whole turn (an
        RRR's A–C from its nearest to its farthest); None where they are not what stops it, or the group has
        nothing to say."""
        return None

    # Membership, used to check the structure and to place named points.
    def known_joints(self) -> tuple[str, ...]:
        """Joints that must be known before this group is solved."""
        raise NotImplementedError

    def new_joints(self) -> tuple[str, ...]:
        """Joints this group finds."""
        raise NotImplementedError

    def guides(self) -> tuple[Guide, ...]:
        return ()

    def sliding_pairs(self, mechanism) -> tuple[tuple[int, int, str], ...]:
        """Each sliding pair the group constructs as (slider, the link it slides on, its joint): the pairs of
        ``Motion.slides``, in the same order."""
        return ()

    def coriolis_sliders(self, mechanism) -> tuple[int, ...]:
        """The sliders whose guide turns: their acceleration has a Coriolis component."""
        return tuple(slider for slider, guide, _ in self.sliding_pairs(mechanism) if turns(mechanism, guide))

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        """For each of the group's links, the joints fixed on it."""
        raise NotImplementedError

    def coincident_points(self) -> tuple[tuple[str, str, str, int], ...]:
        """The points the group names after a link under another link's pin (``A4``), each as (name, the pin, a
        point of that link, the link): such a point has no path of its own, it moves rigidly with its link."""
        return ()

    def sliding_points(self) -> dict[int, dict[str, complex]]:
        """For each link carrying a slide, the sliding joint and the slide's
        direction in the link's own frame (a unit complex)."""
        return {}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        """The group's turning pairs as (joint, link of the group, the other link).

        The other link is None for an outer joint: it is the earlier link
        that carries the joint, which the mechanism knows and the group does
        not.  Sliding pairs need no list: every one is a ``SlideMotion``.
        """
        raise NotImplementedError

    def with_branch(self, context: Context) -> object:
        """The branch fixed at the first position: a sign for a kind with two solutions, 1 for one with one (a
        PRP's side its guides cross from and B's place along the first, a triad's pose)."""
        return 1

    def solve(self, context: Context, branch: object) -> GroupMotion:
        raise NotImplementedError

    # The plans (graphplan.plans): the same vector equations, solved by crossing lines of action
    # on a Builder from the positions of the instant alone.
    def construct_velocity(self, board) -> None:
        raise NotImplementedError(f"the velocity plan of a {self.kind} group is not constructed yet")

    def construct_acceleration(self, board, velocities) -> None:
        raise NotImplementedError(f"the acceleration plan of a {self.kind} group is not constructed yet")


def turns(mechanism, link: int) -> bool:
    """Whether ``link`` can turn: neither the frame nor a link translating on a frame guide."""
    return link != mechanism.scene.frame_link and link not in mechanism.translating


def check_lines_cross(context: Context, group: Group, sine: Scalar, what: str) -> None:
    """Report a position where the two lines of action are parallel."""
    if np.min(np.abs(sine)) >= SINGULAR_SINE:
        return
    context.singular_where(
        np.atleast_1d(np.abs(sine) < SINGULAR_SINE),
        lambda i, at: SingularPositionError(at, group.label, f"{what}: the lines of action of the velocity plan "
                                                             f"are parallel{_sine(sine, i)}"),
    )


def told_apart(larger: float, smaller: float) -> tuple[str, str]:
    """Two lengths written to six significant digits, or as many more as keep them apart: a group that fails to
    assemble by 1e-7 m was told "A–C = 0.55 m > AB + BC = 0.55 m"."""
    for digits in range(6, 18):
        written = f"{larger:.{digits}g}", f"{smaller:.{digits}g}"
        if written[0] != written[1]:
            return written
    return f"{larger!r}", f"{smaller!r}"


def _sine(sine: Scalar, index: int) -> str:
    """The sine of the lines' angle where it is not exactly nought (then it says nothing, and -0.0e+00 is noise)."""
    value = abs(float(np.atleast_1d(sine)[index] if np.ndim(sine) else sine))
    return f" (sine {value:.1e})" if value > 0 else ""


def read_branch(table: Table, choices: tuple[str, ...]) -> tuple[str | None, tuple[float, float] | None]:
    """``assembly`` or ``near``, exactly one of them."""
    assembly = table.choice("assembly", choices, None)
    near = table.xy("near", None)
    if assembly is None and near is None:
        table.misspelt("assembly", "near")
        raise SceneError(table.where("assembly"), f"is required but missing: {' or '.join(choices)} chooses the "
                         "branch the group assembles in (or near = [x, y], where its joint lies in a sketch)")
    if assembly is not None and near is not None:
        # Told at a key, as a speed given both ways is: the path alone named no key to take out.
        raise SceneError(table.where("near"), "give either assembly or near, not both")
    return assembly, near


def refuse_branch(table: Table, why: str) -> None:
    """``assembly`` and ``near`` refused in a group of one assembly, saying ``why``: the contract gives every group one
    of them, so a bare "unknown key" sent the student looking for another name."""
    for key in ("assembly", "near"):
        if table.has(key):
            raise SceneError(table.where(key), f"unknown key: {why}")


def nearest_branch(candidates: dict[int, Vector], near: tuple[float, float]) -> int:
    """The branch whose joint lies nearest ``near`` at the first position."""
    target = complex(*near)
    return min(candidates, key=lambda sign: abs(complex(np.atleast_1d(candidates[sign])[0]) - target))
