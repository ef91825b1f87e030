"""Triad: the class-III group of the third order, three binary links round a ternary one.

The binary links a, b, c turn about known outer joints A, C, E; their inner joints B, D, F
are the corners of the ternary (base) link t:

    |B − A| = AB,   |D − C| = CD,   |F − E| = EF,   BDF a rigid triangle.

Any leg may slide instead of turning: such a binary link is a slider pivoted on the ternary link
at its inner joint (F) and moving along a guide through its outer joint (E), on the frame or on
an earlier link; its closure is F on that line.  Each inner joint so moves on a track
at every instant, a circle about its outer joint or the guide's line.  Or a leg's block, pinned at
its outer joint (A), slides in a slot of the ternary link through its inner joint (B): the slot
turns with the link, and its closure is A on the slot's line.

No closed form places the triad, so its pose q = (B, ψ), ψ the direction of BD, is found
numerically.  At the reference position every assembly is found (the inner joint of a turning leg
swept round its circle, the next leg's where its track meets the circle of the ternary link's side
about it, the third corner from the triangle, or, where all three legs slide, the ternary link
turned round; each sign change of the third leg's closure refined by Brent's method) and the one
nearest the scene's sketch (``near``) is taken.  Every other position is reached from its
neighbour by Newton's method, which is why the motion solves a mechanism with a triad on a grid
of driver positions fine enough to follow one assembly (``continuation``).  The velocities and
accelerations are the closure differentiated: one Jacobian, two linear solves.

The plans cannot cross two lines at B, D or F, each of which has three unknowns.  Assur's
special point Σ of the ternary link can be: it lies where two legs' lines cross, so that B's
velocity relative to A and Σ's relative to B are both square to AB where the leg AB turns, and
D's velocity relative to the guide and Σ's relative to D both along the guide where the leg CD
slides and Σ is on the guide's normal at D, or relative to the pin A along the slot where Σ is on the
slot's normal at A.  Then F follows from Σ and E by crossing two lines (square to EF, or along the
guide where that leg slides; where it is slotted, the link's point under its pin), and B and D by
similarity.  The force analysis takes the whole group's moments about Σ likewise.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np

from ..errors import AssemblyError, SceneError, SingularPositionError, as_written, listed
from ..forces import ForceBoard, PolygonBuilder, Term
from ..geometry import Line, cross_lines
from ..kinematics import LinkMotion, PointMotion, Scalar, SlideMotion, Vector, cross
from ..plans import Builder, DrawnLine, LaidVector, LineMeaning, Plan, Step
from ..reader import Table, check_xy, radians_within_a_turn
from ..rounding import ROUNDING_NOISE, figures_above, figures_below
from .base import SINGULAR_SINE, Context, Group, GroupMotion, Guide
from .rrr import crossed_from_two_pivots, velocity_from_two_pivots
from .sliding import (
    acceleration_on_guide,
    coriolis_end,
    guide_link,
    guide_meaning,
    guide_point,
    record_slide,
    velocity_on_guide,
)
from .triad_legs import leg_reaches

# Samples of a turning leg's circle at the reference position: two assemblies closer than a 2048th of a
# turn would be missed, and such a triad is at a singular position anyway.
_SWEEP = 2048
# The sweep's angles and the turns e^{iθ} at them, the same for every sweep: made once (a crank's reach sweeps at
# each of its 720 angles), read-only.
_SWEEP_ANGLES = np.linspace(0.0, 2 * math.pi, _SWEEP + 1)
_SWEEP_ANGLES.flags.writeable = False
_SWEEP_TURNS = np.exp(1j * _SWEEP_ANGLES)
_SWEEP_TURNS.flags.writeable = False
# Newton's step is trusted when it converges to this share of the group's size.
_CONVERGED = 1e-12
# Plain Newton steps for the positions between the walk's steps, each started within a step of its root:
# quadratic convergence takes a residual of 1e-3 below 1e-12 of the size in three or four.
_BATCH_NEWTON_STEPS = 6


@dataclass(frozen=True)
class Pose:
    """Where the ternary link is: its corner B (m) and the direction ψ of BD (rad)."""

    b: complex
    psi: float


@dataclass(frozen=True)
class TriadBranch:
    """The assembly chosen at the reference position: the triangle's orientation and its pose there.

    ``turn`` is +1 when B, D, F run counter-clockwise round the ternary link, −1 when clockwise.
    """

    turn: int
    pose: Pose


@dataclass(frozen=True)
class Track:
    """Where a leg's inner joint may be at one instant: on the circle of ``radius`` about ``centre`` (the leg's
    outer joint), or, for a leg that slides, on the guide's line through ``centre`` along unit ``u``.  For a
    slotted leg the slot's line, which turns with the ternary link (``slot`` its direction in the link's own
    frame), must run through ``centre``, the block's pin."""

    centre: complex
    radius: float = 0.0
    u: complex | None = None
    slot: complex | None = None

    def along(self, rotation):
        """The line's direction with the ternary link turned by ``rotation`` (e^{iψ}); None for a circle."""
        return self.u if self.slot is None else self.slot * rotation

    def closure(self, point, size: float, rotation=1.0):
        """Zero where ``point`` is on the track: |P − O|² − r², or size·(u × (P − O)); both in m²."""
        u = self.along(rotation)
        if u is None:
            return np.abs(point - self.centre) ** 2 - self.radius * self.radius
        return size * (np.conj(u) * (point - self.centre)).imag

    def gradient(self, point, size: float, rotation=1.0) -> complex:
        """The closure's gradient in ``point``, as a vector."""
        u = self.along(rotation)
        return 2 * (point - self.centre) if u is None else size * 1j * u

    def turning(self, point, size: float, rotation=1.0) -> float:
        """The closure's derivative in ψ with ``point`` held: a slot turns with the ternary link."""
        if self.slot is None:
            return 0.0
        return -size * (np.conj(self.slot * rotation) * (point - self.centre)).real

    def taken(self, which) -> Track:
        """The track at the positions ``which`` of one whose fields hold every position: at an index array, its
        fields arrays; at one index, plain numbers (scipy's root calls the closure with them, a scalar at a time)."""
        def at(value):
            if value is None or np.ndim(value) == 0:
                return value
            return value[which] if np.ndim(which) else complex(value[which])

        return replace(self, centre=at(self.centre), u=at(self.u))


def _taken(tracks: tuple[Track, Track, Track], which) -> tuple[Track, Track, Track]:
    return tuple(track.taken(which) for track in tracks)  # type: ignore[return-value]


@dataclass(frozen=True)
class Triad(Group):
    kind = "triad"
    # A triad folds where the ternary link can turn about one point that all three legs allow (a sliding leg's line
    # the normal to its guide or slot at its pin): no two of its links need stand in line there.
    reach_ends = "the lines of its three legs meet in one point"
    link_count = 4
    klass = 3
    order = 3
    continuation = True
    joint_roles = ("outer A (link a)", "inner B (links a, t)", "outer C (link b)", "inner D (links b, t)",
                   "outer E (link c)", "inner F (links c, t)")
    # AB, CD, EF; 0 for a leg that slides.
    lengths: tuple[float, float, float] = (0.0, 0.0, 0.0)
    sides: tuple[float, float, float] = (0.0, 0.0, 0.0)
    near: tuple[tuple[str, complex], ...] = ()
    # Each leg's guide through its outer joint where that leg slides (a, b, c in order), None where it turns.
    leg_guides: tuple[Guide | None, Guide | None, Guide | None] = (None, None, None)
    # Where a leg's block, pinned at its outer joint, slides in a slot of the ternary link instead: the slot's
    # angle (rad) from BD, the slot running through that leg's inner joint; None where it does not.
    leg_slots: tuple[float | None, float | None, float | None] = (None, None, None)

    @classmethod
    def read(cls, table: Table, links: tuple[int, ...], joints: tuple[str, ...]) -> Triad:
        inner = (joints[1], joints[3], joints[5])
        leg_guides = _read_sliding_legs(table, joints)
        leg_slots = _read_slotted_legs(table, joints, leg_guides)
        turning = [n for n in range(3) if leg_guides[n] is None and leg_slots[n] is None]
        bars = ", ".join(f"l{joints[2 * n]}{joints[2 * n + 1]}" for n in turning)
        raw_lengths = table.raw("lengths", None)
        if isinstance(raw_lengths, list) and len(raw_lengths) != len(turning):
            sliding = [f"{joints[2 * n]}{joints[2 * n + 1]}" for n in range(3) if n not in turning]
            if not turning:
                raise SceneError(table.where("lengths"), f"must be left out: the legs {listed(sliding)} all slide",
                                 raw_lengths)
            why = "" if not sliding else f" (the leg {sliding[0]} slides)" if len(sliding) == 1 else \
                f" (the legs {listed(sliding)} slide)"
            raise SceneError(table.where("lengths"), f"must have {len(turning)} entr{'y' if len(turning) == 1 else 'ies'}, {bars}{why}, not "
                                                     f"{len(raw_lengths)}", raw_lengths)
        lengths = [0.0, 0.0, 0.0]
        # Where every leg slides there is no length to give: the key may be left out.
        given = table.numbers("lengths", len(turning), positive=True) if turning else table.numbers("lengths", 0, ())
        for n, length in zip(turning, given):
            lengths[n] = length
        sides = table.numbers("sides", 3, positive=True)
        bd, df, fb = sides
        longest = max(sides)
        if 2 * longest >= bd + df + fb:
            raise SceneError(table.where("sides"), f"the ternary link's sides BD, DF, FB must make a triangle: "
                                                   f"the longest, {longest:g} m, must be shorter than the other two together",
                             list(sides))
        # The contract chooses a group's branch by assembly or near; of a triad's up to six assemblies no left or right
        # names one, and a bare "unknown key" sent the student looking for another name.
        if table.has("assembly"):
            sketch = ", ".join(f"{name} = [x, y]" for name in inner)
            raise SceneError(table.where("assembly"), f"unknown key: a triad has up to six assemblies, chosen by "
                             f"near = {{ {sketch} }}, where its inner joints lie in a sketch")
        near_table = table.table("near")
        near = []
        for name in near_table.data:
            if name not in inner:
                raise SceneError(near_table.where(name), f"must name an inner joint of the triad: {', '.join(inner)}"
                                 f"{_inner_swapped(table.where('joints'), joints, list(near_table.data))}")
            x, y = check_xy(near_table.raw(name), near_table.where(name))
            near.append((name, complex(x, y)))
        missing = [name for name in inner if name not in dict(near)]
        if missing:
            raise SceneError(near_table.where(missing[0]), f"is required but missing: where {missing[0]} lies in the "
                             f"sketch, [x, y]; the sketch of every inner joint ({', '.join(inner)}) chooses among up "
                             "to six assemblies")
        b, d, f = (dict(near)[name] for name in inner)
        if abs(((d - b).conjugate() * (f - b)).imag) <= 1e-9 * max(abs(d - b), abs(f - b)) ** 2:
            raise SceneError(near_table.path, f"the sketch's {', '.join(inner)} lie in a line; it must show which way "
                                              f"round the ternary link's corners run")
        table.done()
        return cls(where=table.path, links=links, joints=joints, lengths=tuple(lengths), sides=sides, near=tuple(near),
                   leg_guides=leg_guides, leg_slots=leg_slots)

    @property
    def label(self) -> str:
        return f"III({','.join(map(str, self.links))})"

    @property
    def ternary(self) -> int:
        return self.links[3]

    @property
    def turning_legs(self) -> tuple[int, ...]:
        return tuple(n for n in range(3) if self.leg_guides[n] is None and self.leg_slots[n] is None)

    @property
    def sliding_legs(self) -> tuple[int, ...]:
        """The legs that slide on a guide through their outer joints."""
        return tuple(n for n in range(3) if self.leg_guides[n] is not None)

    @property
    def slotted_legs(self) -> tuple[int, ...]:
        """The legs whose blocks, pinned at their outer joints, slide in slots of the ternary link."""
        return tuple(n for n in range(3) if self.leg_slots[n] is not None)

    def known_joints(self) -> tuple[str, ...]:
        return (self.joints[0], self.joints[2], self.joints[4])

    @property
    def inner_joints(self) -> tuple[str, str, str]:
        """B, D, F: the ternary link's corners."""
        return (self.joints[1], self.joints[3], self.joints[5])

    def new_joints(self) -> tuple[str, ...]:
        return self.inner_joints + tuple(self.coincident(n) for n in self.slotted_legs)

    def coincident(self, leg: int) -> str:
        """The ternary link's point under a slotted leg's pin (``E8`` under E on link 8), as textbooks name it."""
        return f"{self.joints[2 * leg]}{self.ternary}"

    def coincident_points(self) -> tuple[tuple[str, str, str, int], ...]:
        return tuple((self.coincident(n), self.joints[2 * n], self.joints[2 * n + 1], self.ternary) for n in self.slotted_legs)

    def slot(self, leg: int) -> Guide:
        """A slotted leg's slot: a guide on the ternary link through the leg's inner joint."""
        return Guide(where=f"{self.where}.slots.{self.joints[2 * leg + 1]}", link=self.ternary,
                     through=self.joints[2 * leg + 1], angle=self.leg_slots[leg])  # type: ignore[arg-type]

    def guides(self) -> tuple[Guide, ...]:
        return tuple(guide for guide in self.leg_guides if guide is not None)

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, b, c, d, e, f = self.joints
        la, lb, lc, lt = self.links
        fixed = {la: (a, b), lb: (c, d), lc: (e, f), lt: (b, d, f)}
        for n in self.sliding_legs:  # a slider carries its pin only: its outer joint is on the guide's link
            _, inner, link = self.arms()[n]
            fixed[link] = (inner,)
        for n in self.slotted_legs:  # a block carries its pin only: its inner joint is the slot's, on the ternary link
            outer, _, link = self.arms()[n]
            fixed[link] = (outer,)
        return fixed

    def sliding_points(self) -> dict[int, dict[str, complex]]:
        slots = {self.joints[2 * n]: self.slot_direction(n) for n in self.slotted_legs}
        return {self.ternary: slots} if slots else {}

    def slot_direction(self, leg: int) -> complex:
        """A slotted leg's slot's direction in the ternary link's own frame (BD along +x)."""
        angle = self.leg_slots[leg]
        assert angle is not None, f"the leg {leg} has no slot"
        return complex(math.cos(angle), math.sin(angle))

    def turning_round(self, before) -> str | None:
        """Each turning leg's lengths that close the triad at every angle of the turn ``before`` it, the other legs as
        given (:func:`~graphplan.groups.triad_legs.leg_reaches`); None where the lengths given do: then it is the
        assembly followed that folds, which no one leg's length explains."""
        return self._lengths_told(leg_reaches(self, before), before, "at every angle of the turn")

    def nowhere(self, before) -> str | None:
        """Where the crank assembles at no angle: each turning leg's lengths that close the triad at some angle of
        the turn ``before`` it (over the angles the groups before it assemble at), the other legs as given."""
        return self._lengths_told(leg_reaches(self, before, somewhere=True), before, "at some angle")

    def _lengths_told(self, reaches, before, where: str) -> str | None:
        """The legs' :class:`~graphplan.groups.triad_legs.LegReach` in words: each leg's range with its key, or that no
        length of it alone does; None where the lengths given are within them all."""
        if all(reach.nearest is not None and reach.nearest <= self.lengths[reach.leg] <= (reach.farthest or math.inf)
               for reach in reaches):
            return None
        ranges, none = [], []
        for reach in reaches:
            outer, inner, _ = self.arms()[reach.leg]
            key = f"{self.where}.lengths[{self.turning_legs.index(reach.leg)}] ({outer}{inner})"
            if reach.nearest is not None:
                # A corner that passes over its outer joint at some angle closes with a leg as short as any.
                low = figures_above(reach.nearest) if reach.nearest > ROUNDING_NOISE * self.size else None
                if reach.farthest is None:
                    ranges.append(f"{key} from {low:.6g} m up" if low is not None else f"{key} of any length")
                    continue
                if low is None:
                    ranges.append(f"{key} under {figures_below(reach.farthest):.6g} m")
                    continue
                if low < (high := figures_below(reach.farthest)):
                    ranges.append(f"{key} from {low:.6g} m to {high:.6g} m")
                    continue
            if reach.shut_at is not None:
                others = " and ".join(f"{o}{i}" for n, (o, i, _) in enumerate(self.arms()) if n != reach.leg)
                none.append(f"no length of {outer}{inner} alone does: at "
                            f"{before.mechanism.driver.describe(reach.shut_at)} {others} close at no turn of link "
                            f"{self.ternary}")
            else:
                none.append(f"no length of {outer}{inner} alone does")
        only = f"the triad closes {where}, the other legs as given, only with {', or '.join(ranges)}"
        return "; ".join(([only] if ranges else []) + none)

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        a, b, c, d, e, f = self.joints
        la, lb, lc, lt = self.links
        pairs = [(a, la, None), (b, lt, la), (c, lb, None), (d, lt, lb), (e, lc, None), (f, lt, lc)]
        for n in reversed(range(3)):
            if n in self.sliding_legs:
                del pairs[2 * n]  # its outer pair slides
            elif n in self.slotted_legs:
                del pairs[2 * n + 1]  # its inner pair slides
        return tuple(pairs)

    def arms(self) -> tuple[tuple[str, str, int], ...]:
        """Each binary link as (outer joint, inner joint, link)."""
        a, b, c, d, e, f = self.joints
        la, lb, lc, _ = self.links
        return ((a, b, la), (c, d, lb), (e, f, lc))

    def sliders(self) -> tuple[tuple[int, Guide], ...]:
        """Each sliding leg's slider link and its guide."""
        return tuple((self.arms()[n][2], self.leg_guides[n]) for n in self.sliding_legs)  # type: ignore[misc]

    def sliding_pairs(self, mechanism) -> tuple[tuple[int, int, str], ...]:
        """Each sliding leg's slider on its guide, each slotted leg's block in its slot, in the order of the legs."""
        pairs = []
        for n, (outer, inner, link) in enumerate(self.arms()):
            if n in self.sliding_legs:
                pairs.append((link, guide_link(mechanism, self.leg_guides[n]), inner))  # type: ignore[arg-type]
            elif n in self.slotted_legs:
                pairs.append((link, self.ternary, outer))
        return tuple(pairs)

    # The position: the pose of the ternary link.

    def corner_f(self, turn: int) -> complex:
        """F in the ternary link's own frame: B at the origin, D on the +x axis."""
        bd, df, fb = self.sides
        cosine = (bd * bd + fb * fb - df * df) / (2 * bd * fb)
        return fb * complex(cosine, turn * math.sqrt(max(0.0, 1 - cosine * cosine)))

    def local_corners(self, turn: int) -> tuple[complex, complex, complex]:
        """B, D, F in the ternary link's own frame."""
        known = self._local_corners_by_turn.get(turn)
        return known if known is not None else (0j, complex(self.sides[0]), self.corner_f(turn))

    @functools.cached_property
    def _local_corners_by_turn(self) -> dict[int, tuple[complex, complex, complex]]:
        # Worked out once: Newton's method asks for them at every step, thousands of times along a crank's reach.
        return {turn: (0j, complex(self.sides[0]), self.corner_f(turn)) for turn in (1, -1)}

    def corners(self, pose: Pose, turn: int) -> tuple[complex, complex, complex]:
        direction = complex(math.cos(pose.psi), math.sin(pose.psi))
        return tuple(pose.b + corner * direction for corner in self.local_corners(turn))  # type: ignore[return-value]

    @functools.cached_property
    def size(self) -> float:
        """The group's size (m): the scale of its closure's residuals (worked out once: every closure asks)."""
        return sum(self.lengths) + sum(self.sides)

    @property
    def _turns_round(self) -> bool:
        """Whether the assemblies are found by turning the ternary link round rather than sweeping a leg's circle:
        where no leg turns, or a slot, which turns with the link, makes no fixed track."""
        return not self.turning_legs or bool(self.slotted_legs)

    def assemblies(self, tracks: tuple[Track, Track, Track], turn: int) -> list[Pose]:
        """Every pose of the ternary link that puts each inner joint on its track.

        The first turning leg's inner joint is swept round its circle, the next leg's found on its
        track at its distance from the first, the third corner follows from the triangle; the
        roots of the third leg's closure are the assemblies.  Where all three legs slide, or one
        slides in a slot of the ternary link, the ternary link is turned round instead: at each
        turn each leg keeps B on a circle or a line (its track carried back by B's side to its
        corner), and B is where the first two meet.
        """
        first, second, third = self.turning_legs + self.sliding_legs + self.slotted_legs
        local = self.local_corners(turn)
        theta = _SWEEP_ANGLES

        def turns(angle):
            """e^{i·angle}: the sweep's made once."""
            return _SWEEP_TURNS if angle is theta else np.exp(1j * angle)

        def around(angle, sign):
            """The first pin, on its circle at ``angle``, and the ternary link's turn e^{iψ} with the second pin at
            either meeting of its track with the circle of the side between them (NaN where they do not meet)."""
            p = tracks[first].centre + tracks[first].radius * turns(angle)
            q = _at_distance(tracks[second], p, abs(local[second] - local[first]), sign)
            return p, (q - p) / (local[second] - local[first])

        def turned(angle, sign):
            """The ternary link turned to e^{iψ} = e^{i·angle}, and the first pin where B's two tracks by the first two
            legs meet, carried back to the first corner (NaN where they do not meet)."""
            rotation = turns(angle)
            one, other = (_carried_back(tracks[n], local[n] * rotation, rotation) for n in (first, second))
            return _meet(one, other, sign) + local[first] * rotation, rotation

        if self._turns_round:
            circles = sum(tracks[n].radius > 0 for n in (first, second))
            placed, signs = turned, ((1, -1) if circles else (1,))
        else:
            placed, signs = around, (1, -1)

        def closing(angle, sign):
            """The third leg's closure, with B and the ternary link's turn e^{iψ}."""
            p, rotation = placed(angle, sign)
            corner = p + (local[third] - local[first]) * rotation
            return tracks[third].closure(corner, self.size, rotation), p - local[first] * rotation, rotation

        from scipy.optimize import brentq  # imported here, as in _settle: only a triad needs it

        poses = []
        for sign in signs:
            values = closing(theta, sign)[0]
            crossing = np.flatnonzero(np.isfinite(values[:-1]) & np.isfinite(values[1:]) & (values[:-1] * values[1:] <= 0))
            for k in crossing:
                if values[k] == 0 and k > 0:
                    continue  # already the upper end of the bracket before
                angle = brentq(lambda t, sign=sign: float(closing(np.array([t]), sign)[0][0]), theta[k], theta[k + 1],
                               xtol=1e-15)
                _, b, rotation = closing(np.array([angle]), sign)
                poses.append(Pose(complex(b[0]), float(np.angle(rotation[0]))))
        return poses

    def mirrored(self) -> Triad:
        """The triad with its sketch's third inner joint mirrored across the line of the first two: its ternary
        link's corners then run the other way round."""
        near = dict(self.near)
        b, d, _ = (near[name] for name in self.inner_joints)
        return replace(self, near=tuple((name, b + (d - b) * ((point - b) / (d - b)).conjugate())
                                        if name == self.inner_joints[2] else (name, point)
                                        for name, point in self.near))

    @property
    def sketched_turn(self) -> int:
        """Which way the ternary link's corners B, D, F run in the scene's sketch: 1 counter-clockwise, −1 not.  A
        rigid triangle keeps its way round at every position."""
        near = dict(self.near)
        b, d, f = (near[name] for name in self.inner_joints)
        return 1 if ((d - b).conjugate() * (f - b)).imag > 0 else -1

    def with_branch(self, context: Context) -> TriadBranch:
        """The assembly nearest the sketch, its triangle turning the way the sketch's does.

        The candidates are the assemblies the sweep finds and the one Newton's method reaches
        from the sketch itself (the sweep may miss a root where D's circles just touch).
        """
        tracks = self._tracks_at(context, 0)
        near = dict(self.near)
        sketch = [near[name] for name in self.inner_joints]
        turn = self.sketched_turn
        candidates = self.assemblies(tracks, turn)
        from_sketch = self._settle(Pose(sketch[0], math.atan2(*reversed(_xy(sketch[1] - sketch[0])))), tracks, turn)
        if from_sketch is not None:
            candidates.append(from_sketch)
        if not candidates:
            context.fail_where(np.array([True]), lambda i, at: AssemblyError(self.joints[1], at, self.label, self._why_not(tracks)))
        best = min(candidates, key=lambda pose: sum(abs(p - q) ** 2 for p, q in zip(self.corners(pose, turn), sketch)))
        return TriadBranch(turn, best)

    def _settle(self, guess: Pose, tracks: tuple[Track, Track, Track], turn: int) -> Pose | None:
        """Newton's method (scipy's hybrid Powell) from ``guess``; None when it does not close the triad."""
        # Imported here, not with the module: scipy.optimize takes a third of a cold run's time to import, and
        # only a scene with a triad needs it.
        from scipy.optimize import root

        found = root(self._residual, np.array([guess.b.real, guess.b.imag, guess.psi]), args=(tracks, turn),
                     jac=True, method="hybr", options={"xtol": 1e-14})
        if not np.all(np.abs(self._residual(found.x, tracks, turn)[0]) <= _CONVERGED * self.size * self.size):
            return None
        return Pose(complex(found.x[0], found.x[1]), float(found.x[2]))

    def _why_not(self, tracks: tuple[Track, Track, Track], walking: bool = False) -> str:
        names = self.known_joints()
        legs = []
        b, d = self.inner_joints[:2]
        for (outer, inner, _), track in zip(self.arms(), tracks):
            if track.slot is not None:
                legs.append(f"{outer} slides in the slot through {inner} at "
                            f"{math.degrees(math.atan2(track.slot.imag, track.slot.real)):.6g}° to {b}{d}")
                continue
            legs.append(f"{outer}{inner} = {track.radius:g} m" if track.u is None else
                        f"{inner} slides on the guide through {outer} at "
                        f"{math.degrees(math.atan2(track.u.imag, track.u.real)):.6g}°")
        a, c, e = (track.centre for track in tracks)
        where = (f"({', '.join(legs)}; {names[0]}–{names[1]} = {abs(c - a):.6g} m, "
                 f"{names[1]}–{names[2]} = {abs(e - c):.6g} m, {names[0]}–{names[2]} = {abs(e - a):.6g} m)")
        if walking:
            return (f"the ternary link {self.ternary} cannot follow its assembly from the position before: "
                    f"the triad reaches a limit position on the way {where}")
        sweep = f"a turn of the ternary link {self.ternary}" if self._turns_round else \
            f"a sweep of {self.arms()[self.turning_legs[0]][1]} round its circle"
        return (f"neither the sketch (near) nor {sweep} finds a pose of the ternary "
                f"link {self.ternary} that closes on the tracks of {', '.join(self.inner_joints)} {where}")

    def _residual(self, q: np.ndarray, tracks: tuple[Track, Track, Track], turn: int):
        """The closure and its Jacobian in q = (Bx, By, ψ)."""
        legs = self._legs(complex(q[0], q[1]), complex(math.cos(q[2]), math.sin(q[2])), tracks, turn)
        return np.array([leg[0] for leg in legs]), np.array([leg[1:] for leg in legs])

    def _legs(self, b, rotation, tracks: tuple[Track, Track, Track], turn: int):
        """Each leg's closure at the poses (B, e^{iψ}), plain numbers or arrays of many poses, and its derivatives
        in Bx, By and ψ."""
        legs = []
        for track, corner in zip(tracks, self.local_corners(turn)):
            point = b + corner * rotation
            gradient = track.gradient(point, self.size, rotation)
            legs.append((track.closure(point, self.size, rotation), gradient.real, gradient.imag,
                         (gradient.conjugate() * 1j * (point - b)).real + track.turning(point, self.size, rotation)))
        return legs

    def _settle_many(self, guesses: list[Pose], tracks: tuple[Track, Track, Track],
                     turn: int) -> list[Pose | None]:
        """Newton's method from many guesses at once, each near its root (a neighbour on the walk's grid);
        None where it does not close the triad in a few steps.

        scipy's root solves one system at a time, a millisecond each: tens of thousands of positions asked
        for between the walk's steps took a minute. These start within a step of their roots, where plain
        Newton converges quadratically, so one batched solve of the 3 × 3 systems does them all; the ones
        it does not settle go to scipy one by one.
        """
        b = np.array([guess.b for guess in guesses])
        psi = np.array([guess.psi for guess in guesses])
        tolerance = _CONVERGED * self.size * self.size
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            for _ in range(_BATCH_NEWTON_STEPS):
                legs = self._legs(b, np.exp(1j * psi), tracks, turn)
                values = np.stack([leg[0] for leg in legs], axis=-1)
                jacobian = np.stack([np.stack(np.broadcast_arrays(*leg[1:]), axis=-1) for leg in legs], axis=-2)
                invertible = np.abs(np.linalg.det(jacobian)) > 0
                step = np.linalg.solve(np.where(invertible[:, None, None], jacobian, np.eye(3)), -values[..., None])
                step = np.where(invertible[:, None], step[..., 0], np.nan)
                b = b + step[:, 0] + 1j * step[:, 1]
                psi = psi + step[:, 2]
            values = np.stack([leg[0] for leg in self._legs(b, np.exp(1j * psi), tracks, turn)], axis=-1)
        settled = np.all(np.abs(values) <= tolerance, axis=-1)
        return [Pose(complex(b[k]), float(psi[k])) if settled[k] else None for k in range(len(guesses))]

    def _tracks(self, context: Context) -> tuple[Track, Track, Track]:
        """Each leg's track, its centre (and a guide's direction) an array over every position."""
        return self.tracks_over(lambda name: context.point(name).r, context.guide, context.count)

    def tracks_over(self, place, guide_motion, count: int) -> tuple[Track, Track, Track]:
        """Each leg's track at ``count`` positions: its outer joint where ``place`` (a joint's name) puts it, complex,
        and a sliding leg's guide as ``guide_motion`` moves it.  A solve's context gives both, and so does the motion
        of the groups before the triad, which :mod:`.triad_legs` reads its legs' bounds off."""
        tracks = []
        for n, (outer, _, _) in enumerate(self.arms()):
            centre = np.broadcast_to(np.asarray(place(outer), dtype=complex), (count,))
            if n in self.turning_legs:
                tracks.append(Track(centre, self.lengths[n]))
            elif self.leg_slots[n] is not None:
                tracks.append(Track(centre, slot=self.slot_direction(n)))
            else:
                guide = guide_motion(self.leg_guides[n])
                tracks.append(Track(centre, u=np.broadcast_to(np.asarray(guide.u, dtype=complex), (count,))))
        return tuple(tracks)  # type: ignore[return-value]

    def _tracks_at(self, context: Context, index: int) -> tuple[Track, Track, Track]:
        return _taken(self._tracks(context), index)

    def _poses(self, context: Context, branch: TriadBranch) -> list[Pose]:
        """The pose at every position: walked out from the reference position both ways along the steps of
        the walk's grid, then each position asked for between two steps settled from the step before it."""
        tracks = self._tracks(context)
        poses: list[Pose | None] = [None] * context.count
        start = context.start
        walked, steps = context.walk_memo(self.label)

        def settle(index: int, guess: Pose) -> Pose | None:
            step = steps[index]
            if step in walked:  # an earlier solve walked past this step of the same assembly
                return walked[step]
            pose = self._settle(guess, _taken(tracks, index), branch.turn)
            if step is not None and pose is not None:
                walked[step] = pose
            return pose

        poses[start] = settle(start, branch.pose)
        stops = [start] if poses[start] is None else []
        between: list[tuple[int, int]] = []  # (a position off the grid, the walk's position before it)
        for order in (range(start + 1, context.count), range(start - 1, -1, -1)):
            previous = start
            for index in order:
                if poses[previous] is None:
                    break
                if steps[index] is None:
                    between.append((index, previous))
                    continue
                poses[index] = settle(index, poses[previous])
                if poses[index] is None:
                    stops.append(index)
                previous = index
        if between:
            off, before = (np.array(column) for column in zip(*between))
            batched = self._settle_many([poses[k] for k in before],  # type: ignore[misc]
                                        _taken(tracks, off), branch.turn)
            for index, guess, pose in zip(off, before, batched):
                poses[index] = pose if pose is not None else settle(int(index), poses[guess])  # type: ignore[arg-type]
                if poses[index] is None:
                    stops.append(int(index))
        if stops:
            first = min(stops, key=lambda index: abs(index - start))
            why = self._why_not(_taken(tracks, first), walking=first != start)
            context.fail_where(np.arange(context.count) == first,
                               lambda i, at: AssemblyError(self.joints[1], at, self.label, why))
        return poses  # type: ignore[return-value]

    def solve(self, context: Context, branch: TriadBranch) -> GroupMotion:
        poses = self._poses(context, branch)
        count = context.count
        b = np.array([pose.b for pose in poses])
        toward_d = np.exp(1j * np.array([pose.psi for pose in poses]))
        inner = tuple(b + corner * toward_d for corner in self.local_corners(branch.turn))
        guides = [None if guide is None else context.guide(guide) for guide in self.leg_guides]
        slots = [toward_d * self.slot_direction(n) if n in self.slotted_legs else None for n in range(3)]
        # Each leg's closure differentiated, row k: nₖ·vB + (nₖ·i(Pₖ − B))·ω = nₖ·v₀ₖ with nₖ the arm Pₖ − Oₖ of a
        # turning leg (v₀ its outer joint's velocity), or the guide's normal iu of a sliding leg (v₀ the velocity
        # of the guide's point under its slider); the same rows for aB, ε.  A slotted leg's row is the slot's
        # normal iu at the ternary link's point Pₖ under the block's pin, v₀ the pin's velocity: the block
        # moves along the slot only.
        outers = [context.point(outer_name) for outer_name, _, _ in self.arms()]
        contacts = [np.broadcast_to(outer.r, (count,)) if slot is not None else point
                    for outer, point, slot in zip(outers, inner, slots)]
        normals, base_v, base_a = [], [], []
        for outer, point, guide, slot in zip(outers, inner, guides, slots):
            if slot is not None:
                normals.append(1j * slot)
                base_v.append(np.broadcast_to(outer.v, (count,)))
                base_a.append(np.broadcast_to(outer.a, (count,)))
            elif guide is None:
                normals.append(np.broadcast_to(point - outer.r, (count,)))
                base_v.append(np.broadcast_to(outer.v, (count,)))
                base_a.append(np.broadcast_to(outer.a, (count,)))
            else:
                carried_v, carried_a = guide.carried(point)
                normals.append(np.broadcast_to(1j * guide.u, (count,)))
                base_v.append(np.broadcast_to(carried_v, (count,)))
                base_a.append(np.broadcast_to(carried_a, (count,)))
        swings = [1j * (contact - b) for contact in contacts]
        jacobian = np.empty((count, 3, 3))
        for k, (normal, swing) in enumerate(zip(normals, swings)):
            jacobian[:, k, 0] = normal.real
            jacobian[:, k, 1] = normal.imag
            jacobian[:, k, 2] = (np.conj(normal) * swing).real
        scale = max(self.sides)
        normalised = jacobian * np.array([1.0, 1.0, 1.0 / scale])
        sine = np.linalg.det(normalised) / np.prod(np.linalg.norm(normalised, axis=2), axis=1)
        bad = np.abs(sine) < SINGULAR_SINE
        if bad.any():
            lines = self._lines_of_action()
            context.singular_where(bad, lambda i, at: SingularPositionError(
                at, self.label, f"the triad is at a singular position ({lines} meet in one point "
                                f"or are parallel; normalised Jacobian {abs(float(sine[i])):.1e})"))
        safe = np.where(bad[:, None, None], np.eye(3), jacobian)

        def dot(p, q):
            return (np.conj(p) * q).real

        velocity_rhs = np.stack([dot(normal, v) for normal, v in zip(normals, base_v)], axis=1)
        x = np.linalg.solve(safe, velocity_rhs[..., None])[..., 0]
        x[bad] = np.nan
        v_b, omega = x[:, 0] + 1j * x[:, 1], x[:, 2]
        v_contact = [v_b + 1j * omega * (contact - b) for contact in contacts]
        # Differentiated again, with aPₖ = aB + (iε − ω²)(Pₖ − B): a turning leg's row is armₖ·aPₖ = armₖ·a₀ₖ −
        # |vPₖ − v₀ₖ|²; a sliding leg's iu·aPₖ = iu·(a₀ₖ + 2ωg × v_rel), its relative acceleration along u; a
        # slotted leg's the same with the ternary link's ω, the slot's own link.
        rhs = []
        for n, (normal, v0, a0, vp, contact) in enumerate(zip(normals, base_v, base_a, v_contact, contacts)):
            if n in self.turning_legs:
                known = dot(normal, a0) - np.abs(vp - v0) ** 2
            else:
                carrier_omega = omega if slots[n] is not None else guides[n].omega  # type: ignore[union-attr]
                known = dot(normal, a0 + 2j * carrier_omega * (vp - v0))
            rhs.append(known + omega ** 2 * dot(normal, contact - b))
        y = np.linalg.solve(safe, np.stack(rhs, axis=1)[..., None])[..., 0]
        y[bad] = np.nan
        a_b, epsilon = y[:, 0] + 1j * y[:, 1], y[:, 2]
        whirl = 1j * epsilon - omega ** 2
        v_inner = [v_b + 1j * omega * (point - b) for point in inner]
        a_inner = [a_b + whirl * (point - b) for point in inner]
        points = {name: PointMotion(r, v, a) for name, r, v, a in zip(self.inner_joints, inner, v_inner, a_inner)}
        links = {self.ternary: LinkMotion(self.joints[1], toward_d, np.angle(toward_d), omega, epsilon)}
        slides = []
        for n, ((outer_name, inner_name, link), vp, ap, point, guide, outer) in enumerate(
                zip(self.arms(), v_inner, a_inner, inner, guides, outers)):
            if n in self.slotted_legs:
                # The block turns with the ternary link; relative to it the pin slides along the slot from B.
                u = slots[n]
                under = PointMotion(contacts[n], v_contact[n], a_b + whirl * (contacts[n] - b))
                points[self.coincident(n)] = under
                relative_v = outer.v - under.v
                relative_a = outer.a - under.a - 2j * omega * relative_v
                links[link] = LinkMotion(outer_name, u, np.angle(u), omega, epsilon)
                slides.append(SlideMotion(link, self.ternary, outer_name, u, dot(u, contacts[n] - point),
                                          dot(u, relative_v), dot(u, relative_a)))
                continue
            if guide is None:
                arm = point - outer.r
                u = arm * (1.0 / self.lengths[n])
                links[link] = LinkMotion(outer_name, u, np.angle(u), _turning(arm, vp - outer.v), _turning(arm, ap - outer.a))
                continue
            u = np.broadcast_to(guide.u, (count,))
            relative_v = vp - base_v[n]
            relative_a = ap - base_a[n] - 2j * guide.omega * relative_v
            links[link] = LinkMotion(inner_name, u, np.angle(u), guide.omega, guide.epsilon)
            slides.append(SlideMotion(link, guide.link, inner_name, u, dot(u, point - guide.origin.r), dot(u, relative_v),
                                      dot(u, relative_a)))
        return GroupMotion(points=points, links=links, slides=tuple(slides), conditioning=sine)

    def _lines_of_action(self) -> str:
        """The lines that meet in one point at a singular position: "the lines AB and CD and the normal to the guide at F"."""
        arms = self.arms()
        bars = [f"{arms[n][0]}{arms[n][1]}" for n in self.turning_legs]
        pins = [arms[n][1] for n in self.sliding_legs]
        blocks = [arms[n][0] for n in self.slotted_legs]
        parts = [("the line " if len(bars) == 1 else "the lines ") + listed(bars)] if bars else []
        if pins:
            parts.append(("the normal to the guide at " if len(pins) == 1 else "the normals to the guides at ") + listed(pins))
        if blocks:
            parts.append(("the normal to the slot at " if len(blocks) == 1 else "the normals to the slots at ") + listed(blocks))
        return " and ".join(parts)

    # The plans: Assur's special point Σ, then F, then B and D by similarity.

    def lines_through_sigma(self, board: Builder | ForceBoard) -> tuple[Line, Line, Line]:
        """Each leg's line on which Σ may lie: a turning leg's own line (AB), a sliding leg's guide's normal at its
        pin, a slotted leg's slot's normal at the block's pin."""
        lines = []
        for n, ((outer, inner, _), guide) in enumerate(zip(self.arms(), self.leg_guides)):
            at = board.positions[inner]
            if n in self.slotted_legs:
                lines.append(Line(board.positions[outer], 1j * board.guide_line(self.slot(n))[1], f"⊥ slot at {outer}"))
            elif guide is None:
                lines.append(Line(at, at - board.positions[outer], f"{outer}{inner}"))
            else:
                lines.append(Line(at, 1j * board.guide_line(guide)[1], f"⊥ guide at {inner}"))
        return tuple(lines)  # type: ignore[return-value]

    def special_point(self, board: Builder | ForceBoard, size: float) -> tuple[str, complex, tuple[int, int, int]]:
        """Σ's name, where it lies (m), and the legs: the two whose lines cross at the widest angle (Σ is their
        crossing), then the third.  ``size`` is the figure's extent."""
        lines = self.lines_through_sigma(board)
        i, j = max(((0, 1), (0, 2), (1, 2)), key=lambda pair: abs((lines[pair[0]].unit.conjugate() * lines[pair[1]].unit).imag))
        return f"Σ{self.ternary}", cross_lines(lines[i], lines[j], size), (i, j, 3 - i - j)

    def _special_point_on(self, board: Builder) -> tuple[str, complex, tuple[int, int, int]]:
        """Σ on the board: where it lies is recorded with the plan, for the drawing and the readings."""
        name, where, order = self.special_point(board, board.size)
        board.auxiliary[name] = where
        return name, where, order

    def _on_guide(self, board: Builder, n: int) -> tuple[str, str]:
        """The plan letter of the guide link's point under sliding leg ``n``'s pin, and that point's name (F1)."""
        _, inner, _ = self.arms()[n]
        carrier = board.guide_line(self.leg_guides[n])[2]
        return guide_point(board, carrier, inner), f"{inner}{carrier}"

    def _plan_line_to_sigma(self, board: Builder, n: int, start: str, sigma_name: str) -> tuple[DrawnLine, str]:
        """The line of action through ``start`` on which σ lies by leg ``n`` (⊥ AB, or ∥ its guide), and the name of
        Σ's motion along it."""
        outer, inner, _ = self.arms()[n]
        guide = self.leg_guides[n]
        if n in self.slotted_legs:  # the slot's line carries the block's sliding: it names the pin, on Σ's normal
            return DrawnLine(start, board.guide_line(self.slot(n))[1],
                             LineMeaning("slot", points=(outer,), link=self.ternary)), f"{sigma_name}{outer}"
        if guide is None:
            return DrawnLine(start, 1j * (board.positions[inner] - board.positions[outer]),
                             LineMeaning("perpendicular", (outer, inner))), f"{sigma_name}{outer}"
        # The guide's line carries the pin's sliding: it names the pin, whose normal Σ lies on.
        _, u, carrier = board.guide_line(guide)
        return DrawnLine(start, u, replace(guide_meaning(guide), points=(inner,))), f"{sigma_name}{inner}{carrier}"

    def _block_slides(self, board: Builder, n: int, under: str, end: str) -> None:
        """Put slotted leg ``n``'s block on the plan by its pin: it turns with the ternary link, and slides relative to
        it as the vector from ``under`` (the image of the link's point under the pin) to ``end``."""
        outer, _, block = self.arms()[n]
        board.on_link(block, board.positions[outer], board.images[outer])
        board.turns_with[block] = self.ternary
        board.slides(block, under, end)

    def _slot_velocity(self, board: Builder, n: int, pivot: tuple[str, str, complex]) -> None:
        """vE8 = vΣ + vE8Σ (⊥ ΣE) = vE + vE8E (∥ slot): the ternary link's point under slotted leg ``n``'s pin."""
        outer = self.arms()[n][0]
        under, (pivot_name, pivot_letter, pivot_position) = self.coincident(n), pivot
        where = board.positions[outer]
        across = 1j * (where - pivot_position)
        u = board.guide_line(self.slot(n))[1]
        pin = board.images[outer]
        value, angle = board.cross(Line(board.points[pivot_letter], across, f"⊥{pivot_name}{outer}"),
                                   Line(board.points[pin], u, f"∥ slot {self.ternary}"))
        fixed = board.fix(under, value)
        self._block_slides(board, n, fixed, pin)
        board.step(Step(
            equation=f"v{under} = v{pivot_name} + v{under}{pivot_name} = v{outer} + v{under}{outer}",
            vectors=(LaidVector(pivot_letter, fixed, f"v{under}{pivot_name}"), LaidVector(pin, fixed, f"v{under}{outer}"),
                     LaidVector("p", fixed, f"v{under}")),
            lines=(DrawnLine(pivot_letter, across, LineMeaning("perpendicular", (pivot_name, under))),
                   DrawnLine(pin, u, LineMeaning("slot", link=self.ternary))),
            fixes=(fixed,), crossing_deg=angle))

    def _slot_acceleration(self, board: Builder, velocities: Plan, n: int, pivot: tuple[str, str, complex, float, str],
                           turning: bool) -> None:
        """aE8 = aΣ + aE8Σⁿ + aE8Σ^τ (⊥ ΣE) = aE + aE8Eᵏ + aE8E^r (∥ slot): the ternary link's point under slotted
        leg ``n``'s pin, the Coriolis part 2ω × vE8E (the block turns with the link) only where the link is
        ``turning``."""
        outer, _, block = self.arms()[n]
        under, (pivot_name, pivot_letter, pivot_position, omega, normal_letter) = self.coincident(n), pivot
        where = board.positions[outer]
        across = 1j * (where - pivot_position)
        u = board.guide_line(self.slot(n))[1]
        pin = board.images[outer]
        normal = board.mark(normal_letter, board.points[pivot_letter] - omega ** 2 * (where - pivot_position))
        kink = coriolis_end(board, velocities, under, block, self.ternary, pin) if turning else pin
        value, angle = board.cross(Line(board.points[normal], across, f"⊥{pivot_name}{outer}"),
                                   Line(board.points[kink], u, f"∥ slot {self.ternary}"))
        fixed = board.fix(under, value)
        self._block_slides(board, n, fixed, kink)
        laid = [LaidVector(pivot_letter, normal, f"a{under}{pivot_name}ⁿ"), LaidVector(normal, fixed, f"a{under}{pivot_name}^τ")]
        coriolis_term = ""
        if turning:
            laid.append(LaidVector(pin, kink, f"a{under}{outer}ᵏ"))
            coriolis_term = f" + a{under}{outer}ᵏ"
        laid += [LaidVector(kink, fixed, f"a{under}{outer}^r"), LaidVector("p", fixed, f"a{under}")]
        board.step(Step(
            equation=f"a{under} = a{pivot_name} + a{under}{pivot_name}ⁿ + a{under}{pivot_name}^τ = a{outer}{coriolis_term} + "
                     f"a{under}{outer}^r",
            vectors=tuple(laid),
            lines=(DrawnLine(normal, across, LineMeaning("perpendicular", (pivot_name, under))),
                   DrawnLine(kink, u, LineMeaning("slot", link=self.ternary))),
            fixes=(normal, *((kink,) if turning else ()), fixed), crossing_deg=angle))

    def construct_velocity(self, board: Builder) -> None:
        """vΣ = vA + vΣA (⊥ AB) = vC + vΣC (⊥ CD), or vD4 + vΣD4 (∥ guide) where D slides; vF = vΣ + vFΣ (⊥ ΣF) =
        vE + vFE (⊥ EF), or vF1 + vFF1 (∥ guide) where F slides; b, d by similarity; then vBA and vDD4 read off."""
        positions = board.positions
        sigma_name, sigma_pos, (i, j, k) = self._special_point_on(board)
        arms = self.arms()
        on_guide = {n: self._on_guide(board, n) for n in (i, j) if self.leg_guides[n] is not None}
        drawn, terms = [], []
        for n in (i, j):
            outer = arms[n][0]
            start = board.images[outer] if n not in on_guide else on_guide[n][0]
            line, relative = self._plan_line_to_sigma(board, n, start, sigma_name)
            drawn.append(line)
            terms.append((outer if n not in on_guide else on_guide[n][1], relative))
        value, angle = board.cross(*(Line(board.points[line.through], line.direction, line.meaning) for line in drawn))
        sigma = board.mark(sigma_name.lower(), value)
        board.step(Step(
            equation=f"v{sigma_name} = " + " = ".join(f"v{known} + v{relative}" for known, relative in terms),
            vectors=tuple(LaidVector(line.through, sigma, f"v{relative}") for line, (_, relative) in zip(drawn, terms)),
            lines=tuple(drawn), fixes=(sigma,), crossing_deg=angle))
        ok, nk, lk = arms[k]
        if k in self.slotted_legs:
            self._slot_velocity(board, k, (sigma_name, sigma, sigma_pos))
        elif self.leg_guides[k] is not None:
            velocity_on_guide(board, nk, (sigma_name, sigma, sigma_pos), self.leg_guides[k], lk)
        else:
            velocity_from_two_pivots(board, nk, positions[nk], (sigma_name, sigma, sigma_pos),
                                     (ok, board.images[ok], positions[ok]))
        self._by_similarity(board, sigma_pos, sigma, (i, j, k))
        for n in (i, j):  # ωa and ωb are read off the relative velocities that end at b and d; a slider's sliding too
            outer, inner, link = arms[n]
            if n in self.slotted_legs:
                under, u = self.coincident(n), board.guide_line(self.slot(n))[1]
                start, end = board.images[outer], board.images[under]
                self._block_slides(board, n, end, start)
                board.step(Step(equation=f"v{under} = v{outer} + v{under}{outer}",
                                vectors=(LaidVector(start, end, f"v{under}{outer}"),),
                                lines=(DrawnLine(start, u, LineMeaning("slot", link=self.ternary)),)))
                continue
            if n in on_guide:
                start, under = on_guide[n]
                end = board.images[inner]
                _, u, carrier = board.guide_line(self.leg_guides[n])
                record_slide(board, link, inner, carrier, start, end)
                # The line along the guide says which way the sliding is read; the step fixes nothing.
                board.step(Step(equation=f"v{inner} = v{under} + v{inner}{under}",
                                vectors=(LaidVector(start, end, f"v{inner}" if start == "p" else f"v{inner}{under}"),),
                                lines=(DrawnLine(start, u, guide_meaning(self.leg_guides[n])),)))
                continue
            board.step(Step(equation=f"v{inner} = v{outer} + v{inner}{outer}",
                            vectors=(LaidVector(board.images[outer], board.images[inner], f"v{inner}{outer}"),)))

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aΣ = aA + aBAⁿ + aΣBⁿ + aΣA^τ (⊥ AB) = aC + aDCⁿ + aΣDⁿ + aΣC^τ (⊥ CD), or aD4 + aDD4ᵏ + aΣDⁿ + aΣD4^τ
        (∥ guide) where D slides; aF = aΣ + aFΣⁿ + aFΣ^τ (⊥ ΣF) = aE + aFEⁿ + aFE^τ (⊥ EF), or aF1 + aFF1ᵏ + aFF1^r
        (∥ guide) where F slides; b, d by similarity."""
        positions = board.positions
        sigma_name, sigma_pos, (i, j, k) = self._special_point_on(board)
        arms, t = self.arms(), self.ternary
        whirl_t = velocities.rates[t] ** 2
        coriolis_sliders = self.coriolis_sliders(board.mechanism)
        on_guide = {n: self._on_guide(board, n) for n in (i, j) if self.leg_guides[n] is not None}
        kinks: dict[int, str] = {}  # where a sliding leg's Coriolis part ends
        ends, vectors, lines, terms = [], [], [], []
        for n, prime in ((i, ""), (j, "′")):
            outer, inner, link = arms[n]
            contact, contact_name = positions[inner], inner
            if n in self.slotted_legs:  # aΣ = aE + aE8Eᵏ + aΣE8ⁿ + (∥ slot): E8 slides along the slot relative to E
                contact, contact_name = positions[outer], self.coincident(n)
                arm_end, known = board.images[outer], f"a{outer}"
                if link in coriolis_sliders:
                    arm_end = coriolis_end(board, velocities, contact_name, link, t, board.images[outer])
                    vectors.append(LaidVector(board.images[outer], arm_end, f"a{contact_name}{outer}ᵏ"))
                    known += f" + a{contact_name}{outer}ᵏ"
                    kinks[n] = arm_end
            elif n in on_guide:
                start, under = on_guide[n]
                arm_end, known = start, f"a{under}"
                if link in coriolis_sliders:
                    carrier = board.guide_line(self.leg_guides[n])[2]
                    arm_end = coriolis_end(board, velocities, inner, link, carrier, start)
                    vectors.append(LaidVector(start, arm_end, f"a{inner}{under}ᵏ"))
                    known += f" + a{inner}{under}ᵏ"
                    kinks[n] = arm_end
            else:
                image = board.images[outer]
                whirl = velocities.rates[link] ** 2
                arm_end = board.mark(f"n{link}", board.points[image] - whirl * (positions[inner] - positions[outer]))
                vectors.append(LaidVector(image, arm_end, f"a{inner}{outer}ⁿ"))
                known = f"a{outer} + a{inner}{outer}ⁿ"
            end = board.mark(f"n{t}{prime}", board.points[arm_end] - whirl_t * (sigma_pos - contact))
            line, relative = self._plan_line_to_sigma(board, n, end, sigma_name)
            vectors.append(LaidVector(arm_end, end, f"a{sigma_name}{contact_name}ⁿ"))
            ends.append(end)
            lines.append(line)
            terms.append((f"{known} + a{sigma_name}{contact_name}ⁿ", f"a{relative}^τ"))
        value, angle = board.cross(*(Line(board.points[line.through], line.direction, line.meaning) for line in lines))
        sigma = board.mark(sigma_name.lower(), value)
        vectors += [LaidVector(end, sigma, tangential) for end, (_, tangential) in zip(ends, terms)]
        board.step(Step(
            equation=f"a{sigma_name} = {' + '.join(terms[0])} = {' + '.join(terms[1])}",
            vectors=tuple(vectors), lines=tuple(lines), fixes=(*kinks.values(), *ends, sigma), crossing_deg=angle))
        ok, nk, lk = arms[k]
        if k in self.slotted_legs:
            self._slot_acceleration(board, velocities, k, (sigma_name, sigma, sigma_pos, velocities.rates[t], f"n{t}″"),
                                    lk in coriolis_sliders)
        elif self.leg_guides[k] is not None:
            acceleration_on_guide(board, velocities, nk, (sigma_name, sigma, sigma_pos, velocities.rates[t], f"n{t}″"),
                                  self.leg_guides[k], lk, lk in coriolis_sliders)
        else:
            crossed_from_two_pivots(board, nk, positions[nk], (sigma_name, sigma, sigma_pos, velocities.rates[t], f"n{t}″"),
                                    (ok, board.images[ok], positions[ok], velocities.rates[lk], f"n{lk}"))
        self._by_similarity(board, sigma_pos, sigma, (i, j, k))
        for n in (i, j):  # εa and εb are read off the tangential parts that end at b and d; a slider's sliding too
            outer, inner, link = arms[n]
            if n in self.slotted_legs:
                under, pin = self.coincident(n), board.images[outer]
                kink, end = kinks.get(n, pin), board.images[under]
                self._block_slides(board, n, end, kink)
                laid = [LaidVector(pin, kink, f"a{under}{outer}ᵏ")] if n in kinks else []
                laid.append(LaidVector(kink, end, f"a{under}{outer}^r"))
                coriolis_term = f" + a{under}{outer}ᵏ" if n in kinks else ""
                board.step(Step(equation=f"a{under} = a{outer}{coriolis_term} + a{under}{outer}^r", vectors=tuple(laid),
                                lines=(DrawnLine(kink, board.guide_line(self.slot(n))[1],
                                                 LineMeaning("slot", link=t)),)))
                continue
            if n in on_guide:
                start, under = on_guide[n]
                kink = kinks.get(n, start)
                end = board.images[inner]
                record_slide(board, link, inner, board.guide_line(self.leg_guides[n])[2], kink, end)
                laid = [LaidVector(start, kink, f"a{inner}{under}ᵏ")] if n in kinks else []
                laid.append(LaidVector(kink, end, f"a{inner}" if kink == "p" else f"a{inner}{under}^r"))
                coriolis_term = f" + a{inner}{under}ᵏ" if n in kinks else ""
                board.step(Step(equation=f"a{inner} = a{under}{coriolis_term} + a{inner}{under}^r", vectors=tuple(laid),
                                lines=(DrawnLine(kink, board.guide_line(self.leg_guides[n])[1],
                                                 guide_meaning(self.leg_guides[n])),)))
                continue
            board.step(Step(
                equation=f"a{inner} = a{outer} + a{inner}{outer}ⁿ + a{inner}{outer}^τ",
                vectors=(LaidVector(board.images[outer], f"n{link}", f"a{inner}{outer}ⁿ"),
                         LaidVector(f"n{link}", board.images[inner], f"a{inner}{outer}^τ"))))

    def _by_similarity(self, board: Builder, sigma_pos: complex, sigma: str, order: tuple[int, int, int]) -> None:
        """The ternary link's image from σ and the point the third leg crossed (its inner joint, or the link's point
        under a slotted leg's pin); the link's other named points by similarity."""
        i, j, k = order
        arms, t, positions = self.arms(), self.ternary, board.positions
        outer_k, inner_k, link_k = arms[k]
        board.on_link(t, sigma_pos, sigma)
        if k in self.slotted_legs:
            board.on_link(t, positions[outer_k], board.images[self.coincident(k)])
        else:
            board.on_link(t, positions[inner_k], board.images[inner_k])
        if k in self.turning_legs:  # a slider was put on the plan as its pin's image was crossed
            board.on_link(link_k, positions[outer_k], board.images[outer_k])
            board.on_link(link_k, positions[inner_k], board.images[inner_k])
        for n in (i, j):
            outer, inner, link = arms[n]
            self._similar_on_ternary(board, inner, positions[inner])
            if n in self.turning_legs:  # a slider is put on the plan with its sliding, read off after
                board.on_link(link, positions[outer], board.images[outer])
                board.on_link(link, positions[inner], board.images[inner])
        # The slot's own corner, and the link's points under the blocks' pins whose sliding is read off after.
        rest = [(inner_k, positions[inner_k])] if k in self.slotted_legs else []
        rest += [(self.coincident(n), positions[arms[n][0]]) for n in (i, j) if n in self.slotted_legs]
        for name, where in rest:
            self._similar_on_ternary(board, name, where)

    def _similar_on_ternary(self, board: Builder, name: str, where: complex) -> None:
        t = self.ternary
        pair = board.widest(t)
        letter = board.fix(name, board.image_on(t, where))
        board.similarity_step(letter, t, name, pair)
        board.on_link(t, where, letter)

    # The forces: the group cut free, moments about each inner joint and about Assur's point.

    def construct_forces(self, board: ForceBoard) -> None:
        """Each outer reaction of a turning leg split along and across its binary link, the across part from ΣM
        of the binary link about its inner joint; a sliding leg's guide reaction square to the guide, through
        its pin shifted along the guide by ΣM of the slider about the pin.  Σ is where two of the unknown
        lines (along a turning leg, or a sliding leg's normal at its pin) cross: ΣM of the whole group about Σ
        gives the third leg's unknown, and the polygon closes on those two lines.  The inner reactions are
        read off the polygon."""
        positions, t = board.positions, self.ternary
        sigma_name, sigma_pos, (i, j, k) = self.special_point(board, max(abs(p) for p in positions.values()))
        board.add_centre(sigma_name, sigma_pos)
        arms = self.arms()
        names, across, along, tau, unknown, acts_at = {}, {}, {}, {}, {}, {}
        for n, (outer, inner, link) in enumerate(arms):
            guide = self.leg_guides[n]
            if n in self.slotted_legs:
                source = board.source_of(outer, link)
                names[n] = (f"R{source}{link}", source)
                u = board.guide_line(self.slot(n))[1]
                # The slot takes no force along it: along the slot the pin's reaction balances the block's loads.
                across[n], along[n] = u, 1j * u
                tau[n] = board.solve_projection(link, f"{names[n][0]}τ", u)
                unknown[n], acts_at[n] = f"{names[n][0]}n", positions[outer]
                continue
            if guide is not None:
                _, u, carrier = board.guide_line(guide)
                names[n] = (f"R{carrier}{link}", carrier)
                # The unknown's direction (`along`) is the guide's normal, the reaction having no part along the
                # guide (`across`, where it shifts instead): the friction in the pair comes in as loads.
                across[n], along[n], tau[n] = u, 1j * u, 0.0
                unknown[n], acts_at[n] = names[n][0], positions[inner]
                continue
            source = board.source_of(outer, link)
            names[n] = (f"R{source}{link}", source)
            bar = positions[inner] - positions[outer]
            across[n], along[n] = 1j * bar / abs(bar), bar / abs(bar)
            tau[n] = board.solve_moment(link, inner, f"{names[n][0]}τ", across[n], positions[outer])
            unknown[n], acts_at[n] = f"{names[n][0]}n", positions[outer]
        terms = []
        for n, (outer, _, _) in enumerate(arms):
            moment = float(cross(positions[outer] - sigma_pos, tau[n] * across[n]))
            if tau[n] != 0 and moment != 0:
                terms.append(Term(f"{names[n][0]}τ", moment, abs(moment) / abs(tau[n])))
        # A guide's reaction acts x along the guide from the pin: R·x is what turns the slider about its pin, and
        # its moment about Σ where Σ is on the pin's normal.
        shifts = {}
        for n in self.sliding_legs:
            _, inner, link = arms[n]
            shifts[n] = board.couple(link, inner, f"{names[n][0]}·x")
            if shifts[n]:
                terms.append(Term(f"{names[n][0]}·x", shifts[n], 0.0))
        ri, rj, rk = (names[n][0] for n in (i, j, k))
        li, lj, lk = (arms[n][2] for n in (i, j, k))
        normal_k = board.solve_moment_of(self.links, sigma_name, unknown[k], along[k], acts_at[k], tuple(terms))

        def whole(n: int) -> str:
            return names[n][0] if self.leg_guides[n] is not None else f"{names[n][0]}τ + {names[n][0]}n"

        first = f"{ri}n + {ri}τ" if self.leg_guides[i] is None else ri
        last = f"{rj}τ + ΣF{lj} + {rj}n" if self.leg_guides[j] is None else f"ΣF{lj} + {rj}"
        polygon = PolygonBuilder(f"{first} + ΣF{li} + {whole(k)} + ΣF{lk} + ΣF{t} + {last} = 0")
        if self.leg_guides[i] is None:
            polygon.lay(f"{ri}τ", tau[i] * across[i])
        end_i = polygon.lay_all(board.loads_on(li))
        if self.leg_guides[k] is None:
            polygon.lay(f"{rk}τ", tau[k] * across[k])
        polygon.lay(unknown[k], normal_k * along[k])
        end_k = polygon.lay_all(board.loads_on(lk))
        end_t = polygon.lay_all(board.loads_on(t))
        if self.leg_guides[j] is None:
            polygon.lay(f"{rj}τ", tau[j] * across[j])
        polygon.lay_all(board.loads_on(lj))
        rj_along, ri_along = polygon.close(unknown[j], along[j], unknown[i], along[i])
        vertex = polygon.start - ri_along
        # The ternary link's pull on each binary link, read between the polygon's vertices (see the equation).
        on_binary = {i: polygon.inner(f"R{t}{li}", end_i, vertex), k: polygon.inner(f"R{t}{lk}", end_k, end_i),
                     j: polygon.inner(f"R{t}{lj}", vertex, end_t)}
        outer_force = {i: tau[i] * across[i] + ri_along, j: tau[j] * across[j] + rj_along, k: tau[k] * across[k] + normal_k * along[k]}
        for n in (i, j, k):
            outer, inner, link = arms[n]
            name, source = names[n]
            if n in shifts:
                normal = outer_force[n]
                offset = shifts[n] / cross(across[n], normal) if abs(normal) > 0 else 0.0
                board.hand_back(board.react(name, inner, source, link, normal, offset),
                                positions[inner] + offset * across[n])
            else:
                board.hand_back(board.react(name, outer, source, link, outer_force[n]))
        for n in (i, j, k):
            outer, inner, link = arms[n]
            if n in self.slotted_legs:
                # The slot's reaction on the block, square to the slot, acts x along it from the pin: R·x balances
                # the block's loads' moment about the pin.
                couple = board.couple(link, outer, f"R{t}{link}·x")
                offset = couple / cross(across[n], on_binary[n]) if abs(on_binary[n]) > 0 else 0.0
                board.react(f"R{t}{link}", outer, t, link, on_binary[n], offset)
                continue
            board.react(f"R{link}{t}", inner, link, t, -on_binary[n])
        board.finish_group(self.label, self.links, polygon.record())


def _inner_swapped(where: str, joints: tuple[str, ...], sketched: list[str]) -> str:
    """Where the sketch names the inner joints but for one, an outer joint in its place, as ``joints`` typed with the
    two in each other's places name them (["B", "A", "C", "D", "E", "F"]), the joints in their places."""
    inner = (joints[1], joints[3], joints[5])
    stray = [name for name in sketched if name in joints and name not in inner]
    left = [name for name in inner if name not in sketched]
    if len(sketched) != 3 or len(stray) != 1 or len(left) != 1:
        return ""
    swapped = [stray[0] if name == left[0] else left[0] if name == stray[0] else name for name in joints]
    return (f"; the joints typed in each other's places? {where} = {as_written(swapped)} makes "
            f"{listed(swapped[1::2])} the inner joints")


def _legs_in(table: Table, key: str, joints: tuple[str, ...], what: str) -> list[tuple[int, str, Table]]:
    """The legs a table under ``key`` names by their inner joints (``{ F = { … } }``), each as (leg, inner joint,
    its table); none where the key is left out.  ``what`` says what the named legs do, for the message."""
    legs = table.table(key, None)
    if legs is None:
        return []
    inner = (joints[1], joints[3], joints[5])
    names = list(legs.data)
    if not names:
        raise SceneError(legs.path, f"must name the legs {what} by their inner joints ({', '.join(inner)})", names)
    for name in names:
        if name not in inner:
            raise SceneError(legs.where(name), f"must name an inner joint of the triad: {', '.join(inner)}")
    return [(inner.index(name), name, legs.table(name)) for name in names]


def _read_sliding_legs(table: Table, joints: tuple[str, ...]) -> tuple[Guide | None, Guide | None, Guide | None]:
    """Each leg's guide, through that leg's outer joint, where it slides (``guides = { F = { angle = 0 } }``, by
    its inner joint); None where it turns."""
    legs: list[Guide | None] = [None, None, None]
    for leg, name, spec in _legs_in(table, "guides", joints, "that slide"):
        outer = joints[2 * leg]
        if spec.has("through"):
            raise SceneError(spec.where("through"), f"the guide of the sliding leg {outer}{name} runs through its "
                                                    f"outer joint {outer}: place {outer} where the guide should pass")
        link = spec.integer("link", None, minimum=1)
        angle = radians_within_a_turn(spec.number("angle", 0.0))
        spec.done()
        legs[leg] = Guide(where=spec.path, link=link, through=outer, angle=angle, angle_given=spec.has("angle"),
                          through_given=False)
    return legs[0], legs[1], legs[2]


def _read_slotted_legs(table: Table, joints: tuple[str, ...], leg_guides) -> tuple[float | None, float | None, float | None]:
    """Each leg whose block, pinned at its outer joint, slides in a slot of the ternary link (``slots = { B = {
    angle = 30.0 } }``, by its inner joint, through which the slot runs): the slot's angle from BD (rad)."""
    legs: list[float | None] = [None, None, None]
    for leg, name, spec in _legs_in(table, "slots", joints, "whose blocks slide in slots of the ternary link"):
        if leg_guides[leg] is not None:
            raise SceneError(spec.path, f"the leg {joints[2 * leg]}{name} already slides on a guide through "
                                        f"{joints[2 * leg]} (guides.{name}); a leg slides either on a guide or in "
                                        f"a slot of the ternary link, not both")
        legs[leg] = radians_within_a_turn(spec.number("angle", 0.0))
        spec.done()
    return legs[0], legs[1], legs[2]


def _at_distance(track: Track, point, distance: float, sign: int):
    """Where ``track`` meets the circle of ``distance`` about ``point`` (an array): one of its two meetings by
    ``sign``, NaN where they do not meet."""
    with np.errstate(divide="ignore", invalid="ignore"):
        if track.u is None:
            towards = track.centre - point
            span2 = np.abs(towards) ** 2
            along = 0.5 + 0.5 * (distance * distance - track.radius ** 2) / span2
            height2 = distance * distance / span2 - along * along
            return point + towards * (along + 1j * sign * np.sqrt(height2))
        # centre + t·u at the distance: t² + 2βt + |centre − point|² − distance² = 0, β = u·(centre − point).
        offset = track.centre - point
        beta = (np.conj(track.u) * offset).real
        return track.centre + (-beta + sign * np.sqrt(beta * beta - np.abs(offset) ** 2 + distance * distance)) * track.u


def _carried_back(track: Track, offset, rotation) -> Track:
    """Where B must be for the corner ``offset`` from it (B's side to the corner, turned) to be on ``track``."""
    return Track(track.centre - offset, track.radius, track.along(rotation))


def _meet(one: Track, other: Track, sign: int):
    """Where two tracks (circles or lines, arrays of them) meet: one of a circle's two meetings by ``sign``, NaN
    where they do not meet."""
    if one.u is None:
        return _at_distance(other, one.centre, one.radius, sign)
    if other.u is None:
        return _at_distance(one, other.centre, other.radius, sign)
    with np.errstate(divide="ignore", invalid="ignore"):
        along = (np.conj(other.centre - one.centre) * other.u).imag / (np.conj(one.u) * other.u).imag
    return one.centre + along * one.u


def _xy(z: complex) -> tuple[float, float]:
    return z.real, z.imag


def _turning(arm: Vector, relative: Vector) -> Scalar:
    """ω (or ε) of a link from a point's velocity (or tangential acceleration) relative to its pivot: (arm × rel)/|arm|²."""
    return (np.conj(arm) * relative).imag / np.abs(arm) ** 2
