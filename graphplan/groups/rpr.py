"""RPR: a slider block (link a) pivoted at a known A slides on a lever (link b) turning about a known C.

The slide line of the lever runs at ``offset`` e to the left of C along the
lever's direction u.  Closure: A = C + (s + i·e)·u.  Differentiated, with
the lever's point A_b that coincides with A:

    vA = vC + ωb × CA + ṡ·u                           (vA = vA_b + vA A_b)
    aA = aC + εb × CA − ωb²·CA + 2·ωb × ṡu + s̈·u       (Coriolis 2·ωb × v_rel)

The block turns with the lever: ωa = ωb, εa = εb.  The lever's direction u
points from C's foot on the slide line toward A, so s > 0 everywhere; the
block cannot pass that foot without the lever turning through a singular
position.

The plans lay the same equations off as the textbook writes them, with the
lever's point A_b (``A4``) as the unknown (see :meth:`RPR.construct_velocity`
and :meth:`RPR.construct_acceleration`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..errors import AssemblyError, SingularPositionError
from ..forces import ForceBoard, PolygonBuilder, Term
from ..geometry import Line
from ..kinematics import LinkMotion, PointMotion, SlideMotion, TwoLines, angle_of, norm2
from ..plans import Builder, DrawnLine, LaidVector, LineMeaning, Plan, Step
from ..reader import Table
from ..rounding import figures_below
from .base import SINGULAR_SINE, Context, Group, GroupMotion, check_lines_cross, refuse_branch
from .sliding import coriolis_letter

if TYPE_CHECKING:
    from ..motion import Motion


@dataclass(frozen=True)
class RPR(Group):
    kind = "RPR"
    # |CA| comes down to the slide's offset: CA is then square to the slide (only an offset slide stops a crank).
    reach_ends = "the block stands at the foot of the perpendicular from the lever's pivot to the slide"
    joint_roles = ("outer A (slider block, link a)", "outer C (lever, link b)")
    offset: float = 0.0

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> RPR:
        offset = table.number("offset", 0.0)
        # The RRR and RRP pick one of two assemblies; a lever through its block has one, and only an offset slide
        # has a side to choose, which offset's sign gives.
        refuse_branch(table, "an RPR has one assembly, its lever laid through the block; an offset slide's side is "
                      "the sign of offset (m: the slide runs that far to the left of C, looking along the lever "
                      "toward the block; negative, to its right)")
        table.done()
        return cls(where=table.path, links=links, joints=joints, offset=offset)

    def _out_of_reach(self, gap: float) -> str:
        """Why the block pivoted at A, ``gap`` m from C, cannot reach the slide: it runs farther from C than that.
        The offset's key is left to the list of the scene's keys that set it, which the refusal ends with
        (:func:`graphplan.reach_advice.keys_setting`): named here too, it was named twice."""
        a_name, c_name = self.joints
        return (f"the slide runs {abs(self.offset):.6g} m from {c_name} but {a_name} is only "
                f"{gap:.6g} m from {c_name}, so the block at {a_name} cannot reach it")

    def nowhere(self, before: Motion) -> str | None:
        """Where the mechanism assembles nowhere: A's farthest from C over the driver's values ``before`` the group
        is solved, where that falls short of the slide's offset, with the size of offset under it that reaches."""
        a_name, c_name = self.joints
        gaps = np.abs(before.points[a_name].r - before.points[c_name].r)
        farthest = int(np.argmax(gaps))
        reach = float(gaps[farthest])
        if reach > abs(self.offset) or reach == 0.0:
            return None
        # To four figures below the reach, as turning_round and the other groups' bounds are offered: an offset of
        # the size written reaches at the farthest, not only touches there.
        return (f"{a_name} comes no farther than {reach:.6g} m from {c_name} "
                f"(at {before.mechanism.driver.describe(float(before.driver[farthest]))}), short of the slide's "
                f"{abs(self.offset):.6g} m: give {self.where}.offset a size up to {figures_below(reach):.6g} m")

    def turning_round(self, before: Motion) -> str | None:
        """A's nearest to C over the turn ``before`` the group, where that falls inside the slide's offset: the
        block reaches the slide wherever A is no nearer C than the offset."""
        a_name, c_name = self.joints
        gaps = np.abs(before.points[a_name].r - before.points[c_name].r)
        nearest = int(np.argmin(gaps))
        least = float(gaps[nearest])
        if least >= abs(self.offset) or least == 0.0:
            return None
        place = before.mechanism.driver.describe(float(before.driver[nearest]))
        return (f"over the turn {a_name} comes as near as {least:.6g} m to {c_name} (at {place}), inside the slide's "
                f"{abs(self.offset):.6g} m, so the crank turns round only with {self.where}.offset of a size up to "
                f"{figures_below(least):.6g} m")

    @property
    def coincident(self) -> str:
        """The lever's point that coincides with A (``A4`` on lever 4), as textbooks name it."""
        return f"{self.joints[0]}{self.links[1]}"

    def known_joints(self) -> tuple[str, ...]:
        return self.joints

    def coincident_points(self) -> tuple[tuple[str, str, str, int], ...]:
        return ((self.coincident, self.joints[0], self.joints[1], self.links[1]),)

    def new_joints(self) -> tuple[str, ...]:
        return (self.coincident,)

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, c = self.joints
        return {self.links[0]: (a,), self.links[1]: (c,)}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        a, c = self.joints
        return ((a, self.links[0], None), (c, self.links[1], None))

    def sliding_points(self) -> dict[int, dict[str, complex]]:
        # The block turns with the lever, so the slide's line is fixed in the block too: a point of the block (the
        # piston rod of an oscillating cylinder, whose one joint is A) is placed along it toward the lever's pivot.
        return {self.links[1]: {self.joints[0]: 1.0 + 0j}, self.links[0]: {self.joints[1]: 1.0 + 0j}}

    def solve(self, context: Context, branch: int) -> GroupMotion:
        a_name, c_name = self.joints
        a, c = context.point(a_name), context.point(c_name)
        ca = a.r - c.r
        ca2 = norm2(ca)
        e = self.offset
        s2 = ca2 - e * e

        def reason(i: int, at: str) -> AssemblyError:
            return AssemblyError(a_name, at, self.label, self._out_of_reach(float(np.sqrt(np.atleast_1d(ca2)[i]))))

        if e == 0.0:
            # A block on the lever's own pivot assembles at every direction of the lever: the group leaves ω
            # to 0/0. Within rounding of the coordinates (A a hair off C) the direction is noise as well.
            size = max(float(np.max(np.abs(a.r))), float(np.max(np.abs(c.r))), float(np.max(np.sqrt(ca2))),
                       context.size)
            over = np.atleast_1d(ca2 <= (SINGULAR_SINE * size) ** 2)
            if over.any():
                def over_pivot(i: int, at: str) -> SingularPositionError:
                    return SingularPositionError(at, self.label, f"{a_name} passes over {c_name}, so nothing "
                                                                 f"fixes the direction of link {self.links[1]}")

                # Exactly on it the lever has no direction even to draw; a hair off it, one of rounding noise.
                context.fail_where(np.atleast_1d(ca2 == 0), over_pivot)
                context.singular_where(over, over_pivot)
        elif not np.min(s2) > 0:
            context.fail_where(np.atleast_1d(~(s2 > 0)), reason)
        s = np.sqrt(s2)
        u = ca * (s - 1j * e) / ca2
        # Unknowns ωb and ṡ: ωb·(i·CA) + ṡ·u = vA − vC.
        e1, e2 = 1j * ca, u
        lines = TwoLines(e1, e2)
        sine = lines.det / np.sqrt(ca2)
        check_lines_cross(context, self, sine, f"the slide on link {self.links[1]} and its normal")
        omega, s_dot = lines.solve(a.v - c.v)
        coriolis = 2j * omega * s_dot * u
        w = a.a - c.a + omega * omega * ca - coriolis
        epsilon, s_ddot = lines.solve(w)
        angle = angle_of(u)
        lever = LinkMotion(c_name, u, angle, omega, epsilon)
        block = LinkMotion(a_name, u, angle, omega, epsilon)
        coincident = PointMotion(a.r, c.v + omega * e1, c.a + (1j * epsilon - omega * omega) * ca)
        return GroupMotion(
            points={self.coincident: coincident},
            links={self.links[0]: block, self.links[1]: lever},
            slides=(SlideMotion(self.links[0], self.links[1], a_name, u, s, s_dot, s_ddot),),
            conditioning=sine,
        )

    def sliding_pairs(self, mechanism) -> tuple[tuple[int, int, str], ...]:
        """The block on the lever."""
        return ((self.links[0], self.links[1], self.joints[0]),)

    # The plans: the same equations, solved by crossing lines of action.

    def _slide(self, board: Builder) -> tuple[complex, complex, complex, LineMeaning]:
        """A's and C's positions, the slide's direction (the lever's line) and what its line of action follows."""
        a_name, c_name = self.joints
        a_pos, c_pos = board.positions[a_name], board.positions[c_name]
        along = board.directions[self.links[1]]
        slide = (LineMeaning("parallel", (c_name, a_name)) if self.offset == 0.0
                 else LineMeaning("slide", link=self.links[1]))
        return a_pos, c_pos, along, slide

    def construct_velocity(self, board: Builder) -> None:
        """vA4 = vA3 + vA4A3 (∥ slide) = vC + vA4C (⊥ CA): lines through a3 and c, crossed at a4.

        A3 is the block's point A (its image ``a`` is known), A4 the lever's
        point under it.  vA3A4 = a − a4 is the block's sliding velocity; the
        block turns with the lever.
        """
        a_name, c_name = self.joints
        block, _ = self.links
        a, c = board.images[a_name], board.images[c_name]
        a4, angle, along, slide, across_ca = self._close(board, a, c)
        pin, point = f"{a_name}{block}", self.coincident
        board.step(Step(
            equation=f"v{point} = v{pin} + v{point}{pin} = v{c_name} + v{point}{c_name}",
            vectors=(LaidVector(a, a4, f"v{point}{pin}"), LaidVector(c, a4, f"v{point}{c_name}"),
                     LaidVector("p", a4, f"v{point}")),
            lines=(DrawnLine(a, along, slide), DrawnLine(c, across_ca, LineMeaning("perpendicular", (c_name, a_name)))),
            fixes=(a4,), crossing_deg=angle))

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aA4 = aA3 + aA4A3ᵏ + aA4A3^r (∥ slide) = aC + aA4Cⁿ + aA4C^τ (⊥ CA).

        The Coriolis part 2·ω3 × vA4A3 (ω3 = ω4, read off the velocity plan,
        as is vA4A3 = a4 − a there) is laid from a3 and ends at k; the normal
        part ω4²·CA points from A toward C and ends at n4; the lines through
        k along the slide and through n4 square to CA cross at a4.  The
        block's relative acceleration is then aA3A4^r = k − a4.
        """
        a_name, c_name = self.joints
        block, lever = self.links
        a_pos, c_pos = board.positions[a_name], board.positions[c_name]
        a, c = board.images[a_name], board.images[c_name]
        omega = velocities.rates[lever]
        v_rel = velocities.value(self.coincident) - velocities.value(a_name)
        k = board.lay_coriolis(coriolis_letter(board, block), a, omega, v_rel)
        normal = board.mark(f"n{lever}", board.points[c] - omega**2 * (a_pos - c_pos))
        a4, angle, along, slide, across_ca = self._close(board, k, normal)
        pin, point = f"{a_name}{block}", self.coincident
        board.step(Step(
            equation=(f"a{point} = a{pin} + a{point}{pin}ᵏ + a{point}{pin}^r"
                      f" = a{c_name} + a{point}{c_name}ⁿ + a{point}{c_name}^τ"),
            vectors=(LaidVector(a, k, f"a{point}{pin}ᵏ"), LaidVector(k, a4, f"a{point}{pin}^r"),
                     LaidVector(c, normal, f"a{point}{c_name}ⁿ"), LaidVector(normal, a4, f"a{point}{c_name}^τ"),
                     LaidVector("p", a4, f"a{point}")),
            lines=(DrawnLine(k, along, slide),
                   DrawnLine(normal, across_ca, LineMeaning("perpendicular", (c_name, a_name)))),
            fixes=(k, normal, a4), crossing_deg=angle))

    def _close(self, board: Builder, on_slide: str,
               on_lever_line: str) -> tuple[str, float, complex, LineMeaning, complex]:
        """The plan closed at a4: the line along the slide through ``on_slide`` crossed with the line square
        to CA through ``on_lever_line``; a4 recorded on the lever, the block turning with it, and the block's
        sliding (``on_slide`` less a4).  Returns a4, the crossing angle, the slide's direction and meaning,
        and the direction square to CA."""
        a_name, c_name = self.joints
        block, lever = self.links
        a_pos, c_pos, along, slide = self._slide(board)
        across_ca = 1j * (a_pos - c_pos)
        value, angle = board.cross(Line(board.points[on_slide], along, slide.text),
                                   Line(board.points[on_lever_line], across_ca, f"⊥{c_name}{a_name}"))
        a4 = board.fix(self.coincident, value)
        board.on_link(lever, c_pos, board.images[c_name])
        board.on_link(lever, a_pos, a4)
        board.on_link(block, a_pos, board.images[a_name])
        board.turns_with[block] = lever
        board.slides(block, a4, on_slide)
        return a4, angle, along, slide, across_ca

    # The forces: the group cut free, as drawn.

    def construct_forces(self, board: ForceBoard) -> None:
        """ΣMA of the block places the lever's normal force on it; ΣMC of the lever gives that force;
        the two polygons (lever, block) close with the reactions at C and A."""

        a_name, c_name = self.joints
        la, lb = self.links
        a = board.positions[a_name]
        u = board.directions[lb]
        normal = 1j * u
        pa, pc = board.source_of(a_name, la), board.source_of(c_name, lb)
        on_block, on_lever = f"R{lb}{la}", f"R{la}{lb}"
        # The lever's force on the block, N·normal, acts x along the slide from A: its couple x·N.
        shift = board.couple(la, a_name, f"{on_block}·x")
        value = board.solve_moment(lb, c_name, on_lever, normal, a, extra=(Term(f"{on_lever}·x", -shift, 0.0),))
        block_force = -value * normal
        offset = shift / -value if value != 0 else 0.0
        polygon = PolygonBuilder(f"{on_lever} + ΣF{lb} + R{pc}{lb} = 0;  {on_block} + ΣF{la} + R{pa}{la} = 0")
        polygon.lay(on_lever, -block_force)
        polygon.lay_all(board.loads_on(lb))
        r_c = polygon.closing(f"R{pc}{lb}")
        polygon.lay(on_block, block_force)
        polygon.lay_all(board.loads_on(la))
        r_a = polygon.closing(f"R{pa}{la}")
        board.hand_back(board.react(f"R{pa}{la}", a_name, pa, la, r_a))
        board.hand_back(board.react(f"R{pc}{lb}", c_name, pc, lb, r_c))
        board.react(on_block, a_name, lb, la, block_force, offset)
        board.finish_group(self.label, self.links, polygon.record())
