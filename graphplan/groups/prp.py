"""PRP: two sliders, link a on guide 1 and link b on guide 2, jointed at B.

B runs along each guide at its ``offset`` (to the left of the guide's
direction).  Closure: B = G1 + (s1 + i·o1)·u1 = G2 + (s2 + i·o2)·u2.
Differentiated, with B_k the point of guide k's link under B:

    vB = vB_1 + ṡ1·u1 = vB_2 + ṡ2·u2
    aB = aB_1 + 2·ω1 × ṡ1u1 + s̈1·u1 = aB_2 + 2·ω2 × ṡ2u2 + s̈2·u2

Each slider turns with its guide.  On the plans B_k is the image of guide
k's point under B, by similarity from its link's images (the pole on the
frame), and each line of action runs along its guide through B_k, or through
the end k of the Coriolis component when that guide turns.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError, SingularPositionError
from ..forces import ForceBoard, PolygonBuilder
from ..geometry import Line
from ..kinematics import LinkMotion, PointMotion, SlideMotion, TwoLines, angle_of, cross
from ..plans import Builder, DrawnLine, LaidVector, Plan, Step
from ..reader import Table
from .base import SINGULAR_SINE, UNREAD_GUIDE, Context, Group, GroupMotion, Guide, read_guide, refuse_branch
from .sliding import (
    coriolis_letter,
    guide_link,
    guide_meaning,
    guide_point,
)

# Relative to the lengths about, what counts as nought: parallel guides this near one line lie in it.
_TOLERANCE = 1e-9


@dataclass(frozen=True)
class PRP(Group):
    kind = "PRP"
    reach_ends = "its two guides run parallel"
    joint_roles = ("inner B",)
    guide_pair: tuple[Guide, Guide] = (UNREAD_GUIDE, UNREAD_GUIDE)
    offsets: tuple[float, float] = (0.0, 0.0)

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> PRP:
        pairs = table.items("guides", length=2)
        assert pairs is not None
        guide_pair = (read_guide(pairs[0][1], pairs[0][0]), read_guide(pairs[1][1], pairs[1][0]))
        offsets = table.numbers("offsets", 2, (0.0, 0.0))
        refuse_branch(table, "a PRP has one assembly: B is where its two sliders' lines cross, each guide moved its "
                      "offset to its left (a negative offset, to its right)")
        table.done()
        return cls(where=table.path, links=links, joints=joints, guide_pair=guide_pair, offsets=offsets)

    def known_joints(self) -> tuple[str, ...]:
        return ()

    def new_joints(self) -> tuple[str, ...]:
        return self.joints

    def guides(self) -> tuple[Guide, ...]:
        return self.guide_pair

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        return {self.links[0]: self.joints, self.links[1]: self.joints}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        return ((self.joints[0], self.links[1], self.links[0]),)

    def with_branch(self, context: Context) -> tuple[int, float]:
        """The side the second guide crosses the first from at the first position, and how far along the first B
        stands there. Turning through parallel takes B off to infinity and back from the other end, unless B is a
        point of both guides' links that stays on both (the two guides pivot about it)."""
        g1, g2 = (context.guide(g) for g in self.guide_pair)
        lines, gap = TwoLines(g1.u, -g2.u), self._gap(g1, g2)
        det = np.atleast_1d(lines.det)
        self._refuse_parallel(context, g1.u, gap, det)
        along, _ = lines.solve(gap)
        return (1 if det[0] > 0 else -1), float(np.atleast_1d(along)[0])

    def _gap(self, g1, g2):
        o1, o2 = self.offsets
        return g2.origin.r - g1.origin.r + 1j * (o2 * g2.u - o1 * g1.u)

    def _refuse_parallel(self, context: Context, u1, gap, det) -> None:
        """Parallel guides, the first along ``u1``, ``gap`` apart (:meth:`_gap`): B at infinity where they lie
        apart; undetermined where they lie in one line."""
        parallel = np.abs(det) < SINGULAR_SINE
        if not parallel.any():
            return
        apart = np.atleast_1d(np.abs(cross(u1, gap)) > _TOLERANCE * (1.0 + np.abs(gap)))
        context.fail_where(parallel & apart, lambda i, at: AssemblyError(
            self.joints[0], at, self.label, "its two guides run parallel: B would be at infinity"))
        context.fail_where(parallel & ~apart, lambda i, at: SingularPositionError(
            at, self.label, "the two guides lie in one line"))

    def solve(self, context: Context, branch: tuple[int, float]) -> GroupMotion:
        g1, g2 = (context.guide(g) for g in self.guide_pair)
        o1, o2 = self.offsets
        u1, u2 = g1.u, g2.u
        lines, gap = TwoLines(u1, -u2), self._gap(g1, g2)
        det = lines.det
        self._refuse_parallel(context, u1, gap, np.atleast_1d(det))
        # Position: s1·u1 − s2·u2 = G2 − G1 + i·(o2·u2 − o1·u1).
        s1, s2 = lines.solve(gap)
        b_r = g1.origin.r + (s1 + 1j * o1) * u1
        v1, a1 = g1.carried(b_r)
        v2, a2 = g2.carried(b_r)
        s1_dot, s2_dot = lines.solve(v2 - v1)
        # The guides crossing from the other side: on the way from the first position they ran parallel, and B off
        # to infinity (a tangent mechanism's crank at 0° and 180°); the mechanism does not get there. Unless the
        # guides pivot about B: the first position's B, carried on the first guide, lies on the second still and
        # slides along neither.
        side, along = branch
        carried = g1.origin.r + (along + 1j * o1) * u1
        pivoting = ((np.abs(cross(u2, carried - g2.origin.r) - o2) <= _TOLERANCE * (1.0 + np.abs(carried)))
                    & (np.abs(s1_dot) + np.abs(s2_dot) <= _TOLERANCE * (1.0 + np.abs(v1) + np.abs(v2))))
        context.fail_where(np.atleast_1d((det * side < 0) & ~pivoting), lambda i, at: AssemblyError(
            self.joints[0], at, self.label, "its two guides cross from the other side than at the first position: "
                                            "between the two they run parallel and B goes off to infinity"))
        coriolis1 = 2j * g1.omega * s1_dot * u1
        coriolis2 = 2j * g2.omega * s2_dot * u2
        s1_ddot, s2_ddot = lines.solve(a2 + coriolis2 - a1 - coriolis1)
        b_name = self.joints[0]
        b = PointMotion(b_r, v1 + s1_dot * u1, a1 + coriolis1 + s1_ddot * u1)
        link_a, link_b = self.links
        return GroupMotion(
            points={b_name: b},
            links={
                link_a: LinkMotion(b_name, u1, angle_of(u1), g1.omega, g1.epsilon),
                link_b: LinkMotion(b_name, u2, angle_of(u2), g2.omega, g2.epsilon),
            },
            slides=(SlideMotion(link_a, g1.link, b_name, u1, s1, s1_dot, s1_ddot),
                    SlideMotion(link_b, g2.link, b_name, u2, s2, s2_dot, s2_ddot)),
            conditioning=det,
        )

    def sliding_pairs(self, mechanism) -> tuple[tuple[int, int, str], ...]:
        """Each slider on its guide."""
        return tuple((link, guide_link(mechanism, guide), self.joints[0]) for link, guide in zip(self.links, self.guide_pair))

    # The plans: the same equations, solved by crossing lines of action.

    def construct_velocity(self, board: Builder) -> None:
        """vB = vB_1 + vBB_1 (∥ guide 1) = vB_2 + vBB_2 (∥ guide 2): lines through b_1 and b_2, crossed at b."""
        b_name = self.joints[0]
        b_pos = board.positions[b_name]
        sides = []
        for slider, guide in zip(self.links, self.guide_pair):
            _, along, carrier = board.guide_line(guide)
            sides.append((slider, guide, along, carrier, guide_point(board, carrier, b_name)))
        (_, g1, u1, _, b1), (_, g2, u2, _, b2) = sides
        along1, along2 = guide_meaning(g1), guide_meaning(g2)
        value, angle = board.cross(Line(board.points[b1], u1, along1.text), Line(board.points[b2], u2, along2.text))
        b = board.fix(b_name, value)
        laid, terms = [], []
        for slider, guide, along, carrier, under in sides:
            board.on_link(slider, b_pos, b)
            board.turns_with[slider] = carrier
            board.slides(slider, under, b)
            g = f"{b_name}{carrier}"
            terms.append(f"v{g} + v{b_name}{g}")
            if under != "p":
                laid.append(LaidVector(under, b, f"v{b_name}{g}"))
        board.step(Step(
            equation=f"v{b_name} = {terms[0]} = {terms[1]}",
            vectors=(*laid, LaidVector("p", b, f"v{b_name}")),
            lines=(DrawnLine(b1, u1, along1), DrawnLine(b2, u2, along2)),
            fixes=(b,), crossing_deg=angle))

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aB = aB_1 + aBB_1ᵏ + aBB_1^r (∥ guide 1) = aB_2 + aBB_2ᵏ + aBB_2^r (∥ guide 2).

        On a turning guide k the Coriolis part 2·ωk × vBB_k, its relative
        velocity read off the velocity plan and turned 90° in the sense of ωk,
        is laid from b_k; the line along the guide goes through its end.
        """
        b_name = self.joints[0]
        b_pos = board.positions[b_name]
        turning = self.coriolis_sliders(board.mechanism)
        sides, laid, terms, marks = [], [], [], []
        for slider, guide in zip(self.links, self.guide_pair):
            _, along, carrier = board.guide_line(guide)
            under = guide_point(board, carrier, b_name)
            g = f"{b_name}{carrier}"
            term = f"a{g}"
            start = under
            if slider in turning:
                v_rel = velocities.value(b_name) - velocities.points[under]
                start = board.lay_coriolis(coriolis_letter(board, slider), under, velocities.rates.get(carrier, 0.0),
                                           v_rel)
                laid.append(LaidVector(under, start, f"a{b_name}{g}ᵏ"))
                marks.append(start)
                term += f" + a{b_name}{g}ᵏ"
            terms.append(f"{term} + a{b_name}{g}^r")
            sides.append((slider, guide, along, carrier, start, g))
        (_, g1, u1, _, k1, _), (_, g2, u2, _, k2, _) = sides
        along1, along2 = guide_meaning(g1), guide_meaning(g2)
        value, angle = board.cross(Line(board.points[k1], u1, along1.text), Line(board.points[k2], u2, along2.text))
        b = board.fix(b_name, value)
        for slider, guide, along, carrier, start, g in sides:
            board.on_link(slider, b_pos, b)
            board.turns_with[slider] = carrier
            board.slides(slider, start, b)
            if start != "p":  # from the pole it would be aB itself
                laid.append(LaidVector(start, b, f"a{b_name}{g}^r"))
        board.step(Step(
            equation=f"a{b_name} = {terms[0]} = {terms[1]}",
            vectors=(*laid, LaidVector("p", b, f"a{b_name}")),
            lines=(DrawnLine(k1, u1, along1), DrawnLine(k2, u2, along2)),
            fixes=(*marks, b), crossing_deg=angle))

    # The forces: the group cut free, as drawn.

    def construct_forces(self, board: ForceBoard) -> None:
        """Both guides' normal reactions by crossing their lines on the group's polygon; the joint's
        reaction read off it; where each normal reaction acts from ΣMB of its slider."""

        (b_name,) = self.joints
        la, lb = self.links
        b = board.positions[b_name]
        (_, u1, g1), (_, u2, g2) = (board.guide_line(guide) for guide in self.guide_pair)
        r1, r2, inner = f"R{g1}{la}", f"R{g2}{lb}", f"R{lb}{la}"
        polygon = PolygonBuilder(f"ΣF{la} + ΣF{lb} + {r2} + {r1} = 0")
        end_of_a = polygon.lay_all(board.loads_on(la))
        polygon.lay_all(board.loads_on(lb))
        n2, n1 = polygon.close(r2, 1j * u2, r1, 1j * u1)
        vertex = polygon.start - n1
        r_ba = polygon.inner(inner, end_of_a, vertex)
        shifts = (board.couple(la, b_name, f"{r1}·x"), board.couple(lb, b_name, f"{r2}·x"))
        offsets = [shift / cross(u, n) if abs(n) > 0 else 0.0 for shift, u, n in zip(shifts, (u1, u2), (n1, n2))]
        board.hand_back(board.react(r1, b_name, g1, la, n1, offsets[0]), b + offsets[0] * u1)
        board.hand_back(board.react(r2, b_name, g2, lb, n2, offsets[1]), b + offsets[1] * u2)
        board.react(f"R{la}{lb}", b_name, la, lb, -r_ba)
        board.finish_group(self.label, self.links, polygon.record())
