"""RRP: link a pivoted at a known A and at B to a slider (link b) moving along a guide.

The guide is a line through G with direction u, on the frame or on a moving
link g.  Closure: B = A + AB·e^{iθa} = G + s·u.  Differentiated:

    vB = vA + ωa × AB = vG + ωg × GB + ṡ·u
    aB = aA + εa × AB − ωa²·AB = aG + εg × GB − ωg²·GB + 2·ωg × ṡu + s̈·u

the last line with the Coriolis term of the slider on a rotating guide.

The plans solve the same equations by crossing lines of action, with the
step a triad's sliding leg takes too (``sliding.velocity_on_guide``,
``sliding.acceleration_on_guide``): B's image is crossed from a's square to AB
with the guide's line through the image of the guide link's point under B.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError, SceneError
from ..forces import ForceBoard, PolygonBuilder
from ..kinematics import (
    LinkMotion,
    PointMotion,
    SlideMotion,
    TwoLines,
    angle_of,
    cross,
    dot,
)
from ..plans import Builder, Plan
from ..reader import Table
from ..rounding import figures_above
from .base import (
    UNREAD_GUIDE,
    Context,
    Group,
    GroupMotion,
    Guide,
    at_toggle,
    check_lines_cross,
    nearest_branch,
    read_branch,
    read_guide,
    told_apart,
)
from .sliding import acceleration_on_guide, guide_link, velocity_on_guide

# B ahead of (forward) or behind (backward) the foot of A on the guide,
# counted along the guide's direction.
_BRANCHES = {"forward": 1, "backward": -1}


@dataclass(frozen=True)
class RRP(Group):
    kind = "RRP"
    # Past where A's distance from the guide is AB, B is A's foot on it: no two links stand in line there.
    reach_ends = "the rod stands square to the guide"
    joint_roles = ("outer A (link a)", "inner B (slider, link b)")
    length: float = 0.0
    guide: Guide = UNREAD_GUIDE
    assembly: str | None = None
    near: tuple[float, float] | None = None

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> RRP:
        length = table.number("length", positive=True)
        guide = read_guide(table.raw("guide"), table.where("guide"))
        # The contract names a group's branches left and right, which an RRR's line A→C has sides for; an RRP's are
        # along its guide, and "must be one of forward, backward" did not say what those are.
        if table.data.get("assembly") in ("left", "right"):
            raise SceneError(table.where("assembly"), "must be one of forward, backward: an RRP's B stands ahead of "
                             "the foot of A on the guide, along the guide's direction (forward), or behind it "
                             "(backward); left and right are the sides of an RRR's line A→C", table.data["assembly"])
        assembly, near = read_branch(table, tuple(_BRANCHES))
        table.done()
        return cls(where=table.path, links=links, joints=joints, length=length, guide=guide,
                   assembly=assembly, near=near)

    def known_joints(self) -> tuple[str, ...]:
        return (self.joints[0],)

    def new_joints(self) -> tuple[str, ...]:
        return (self.joints[1],)

    def guides(self) -> tuple[Guide, ...]:
        return (self.guide,)

    def turning_round(self, before) -> str | None:
        """A's farthest from the guide over the turn ``before`` the group: B closes where AB reaches that far."""
        a, b = self.joints
        heights = self._heights(before)
        farthest = int(np.argmax(heights))
        most = float(heights[farthest])
        if self.length >= most:
            return None
        place = before.mechanism.driver.describe(float(before.driver[farthest]))
        return (f"over the turn {a} comes as far as {most:.6g} m from the guide (at {place}), so the crank turns round "
                f"only where {a}{b} > {most:.6g} m: {self.where}.length from {figures_above(most):.6g} m up")

    def nowhere(self, before) -> str | None:
        """Where the crank assembles at no angle: A's nearest to the guide over the angles ``before`` the group
        assembles at, where AB falls short of it."""
        a, b = self.joints
        heights = self._heights(before)
        nearest = int(np.argmin(heights))
        least = float(heights[nearest])
        if self.length >= least:
            return None
        place = before.mechanism.driver.describe(float(before.driver[nearest]))
        return (f"{a} comes no nearer the guide than {least:.6g} m (at {place}), farther than {a}{b} = "
                f"{self.length:.6g} m: {self.where}.length from {figures_above(least):.6g} m up, or the guide "
                f"nearer {a}")

    def _heights(self, before) -> np.ndarray:
        """A's distance from the guide at each of ``before``'s driver values."""
        guide = before.guide(self.guide)
        return np.abs(cross(guide.u, before.points[self.joints[0]].r - guide.origin.r))

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, b = self.joints
        return {self.links[0]: (a, b), self.links[1]: (b,)}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        a, b = self.joints
        return ((a, self.links[0], None), (b, self.links[1], self.links[0]))

    def _candidates(self, context: Context, branch: int):
        a = context.point(self.joints[0])
        guide = context.guide(self.guide)
        ga = a.r - guide.origin.r
        foot = dot(ga, guide.u)
        height = cross(guide.u, ga)
        reach2 = at_toggle(self.length * self.length - height * height, self.length * self.length)

        def reason(i: int, at: str) -> AssemblyError:
            gap, length = told_apart(abs(float(np.atleast_1d(height)[i])), self.length)
            a_name, b_name = self.joints
            return AssemblyError(b_name, at, self.label, f"{a_name} is {gap} m from the guide > {a_name}{b_name} = {length} m")

        if not np.min(reach2) >= 0:
            context.fail_where(np.atleast_1d(~(reach2 >= 0)), reason)
        s = foot + branch * np.sqrt(reach2)
        return a, guide, s, guide.origin.r + s * guide.u

    def with_branch(self, context: Context) -> int:
        if self.assembly is not None:
            return _BRANCHES[self.assembly]
        assert self.near is not None
        return nearest_branch({s: self._candidates(context, s)[3] for s in (1, -1)}, self.near)

    def solve(self, context: Context, branch: int) -> GroupMotion:
        a, guide, s, b_r = self._candidates(context, branch)
        ab_vec = b_r - a.r
        e1, e2 = 1j * ab_vec, -guide.u
        lines = TwoLines(e1, e2)
        sine = lines.det / self.length
        check_lines_cross(context, self, sine, f"link {self.links[0]} stands square to the guide (a dead point)")
        omega_g, epsilon_g = guide.omega, guide.epsilon
        guide_point_v, guide_point_a = guide.carried(b_r)
        omega_a, s_dot = lines.solve(guide_point_v - a.v)
        coriolis = 2j * omega_g * s_dot * guide.u
        w = guide_point_a + coriolis - a.a + omega_a * omega_a * ab_vec
        epsilon_a, s_ddot = lines.solve(w)
        b_v = a.v + omega_a * e1
        b_a = a.a + (1j * epsilon_a - omega_a * omega_a) * ab_vec
        a_name, b_name = self.joints
        u_a = ab_vec * (1.0 / self.length)  # a complex array divided by a real number is a complex division
        return GroupMotion(
            points={b_name: PointMotion(b_r, b_v, b_a)},
            links={
                self.links[0]: LinkMotion(a_name, u_a, angle_of(u_a), omega_a, epsilon_a),
                self.links[1]: LinkMotion(b_name, guide.u, angle_of(guide.u), omega_g, epsilon_g),
            },
            slides=(SlideMotion(self.links[1], guide.link, b_name, guide.u, s, s_dot, s_ddot),),
            conditioning=sine,
        )

    def sliding_pairs(self, mechanism) -> tuple[tuple[int, int, str], ...]:
        """The slider on its guide."""
        return ((self.links[1], guide_link(mechanism, self.guide), self.joints[1]),)

    # The plans: the same equations, solved by crossing lines of action.

    def construct_velocity(self, board: Builder) -> None:
        """vB = vA + vBA (⊥ AB) = vBg + vBBg (∥ guide): lines through a and bg, crossed at b.

        bg is the image of the guide link g's point under B, by similarity from
        g's images already on the plan; on a frame guide it is the pole.
        """
        a_name, b_name = self.joints
        b = velocity_on_guide(board, b_name, (a_name, board.images[a_name], board.positions[a_name]), self.guide,
                              self.links[1])
        self._on_rod(board, b)

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aB = aA + aBAⁿ + aBA^τ (⊥ AB) = aBg + aBBgᵏ + aBBg^r (∥ guide).

        The normal part ω²·AB points from B toward A; the Coriolis part
        2·ωg × vBBg (only on a turning guide) is vBBg, read off the velocity
        plan, turned 90° in the sense of ωg; the relative part runs along the
        guide.
        """
        a_name, b_name = self.joints
        rod, slider = self.links
        pivot = (a_name, board.images[a_name], board.positions[a_name], velocities.rates[rod], f"n{rod}")
        b = acceleration_on_guide(board, velocities, b_name, pivot, self.guide, slider,
                                  bool(self.coriolis_sliders(board.mechanism)))
        self._on_rod(board, b)

    def _on_rod(self, board: Builder, b: str) -> None:
        """A and B's images recorded on the rod, for the similarity of its other points."""
        a_name, b_name = self.joints
        board.on_link(self.links[0], board.positions[a_name], board.images[a_name])
        board.on_link(self.links[0], board.positions[b_name], b)

    # The forces: the group cut free, as drawn.

    def construct_forces(self, board: ForceBoard) -> None:
        """The rod's reaction at A split along and across AB (across from ΣMB of the rod); the guide's
        normal reaction and the along part by crossing their lines on the polygon; where the normal
        reaction acts from ΣMB of the slider."""

        a_name, b_name = self.joints
        la, lb = self.links
        a, b = board.positions[a_name], board.positions[b_name]
        _, u, carrier = board.guide_line(self.guide)
        pa = board.source_of(a_name, la)
        across_a = 1j * (b - a) / abs(b - a)
        ra, rn, inner = f"R{pa}{la}", f"R{carrier}{lb}", f"R{lb}{la}"
        ta = board.solve_moment(la, b_name, f"{ra}τ", across_a, a)
        polygon = PolygonBuilder(f"{ra}τ + ΣF{la} + ΣF{lb} + {rn} + {ra}n = 0")
        polygon.lay(f"{ra}τ", ta * across_a)
        end_of_a = polygon.lay_all(board.loads_on(la))
        polygon.lay_all(board.loads_on(lb))
        normal, ra_along = polygon.close(rn, 1j * u, f"{ra}n", b - a)
        vertex = polygon.start - ra_along
        r_ba = polygon.inner(inner, end_of_a, vertex)
        shift = board.couple(lb, b_name, f"{rn}·x")
        offset = shift / cross(u, normal) if abs(normal) > 0 else 0.0
        board.hand_back(board.react(ra, a_name, pa, la, ta * across_a + ra_along))
        board.react(f"R{la}{lb}", b_name, la, lb, -r_ba)
        board.hand_back(board.react(rn, b_name, carrier, lb, normal, offset), b + offset * u)
        board.finish_group(self.label, self.links, polygon.record())
