"""RRP: link a pivoted at a known A and at B to a slider (link b) moving along a guide.

The guide is a line through G with direction u, on the frame or on a moving
link g.  Closure: B = A + AB·e^{iθa} = G + s·u.  Differentiated:

    vB = vA + ωa × AB = vG + ωg × GB + ṡ·u
    aB = aA + εa × AB − ωa²·AB = aG + εg × GB − ωg²·GB + 2·ωg × ṡu + s̈·u

the last line with the Coriolis term of the slider on a rotating guide.

The plans solve the same equations by crossing lines of action (see
:meth:`RRP.construct_velocity`).  The helpers at the end of this module are
shared by the sliding kinds (RPR, PRP, RPP import them): the image of a guide
link's point under a slider by similarity, the Coriolis component, and the
crossing of two lines of action at the plan's own size.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError
from ..forces import ForceBoard, PolygonBuilder
from ..geometry import Line
from ..kinematics import (
    LinkMotion,
    PointMotion,
    SlideMotion,
    TwoLines,
    angle_of,
    cross,
    dot,
)
from ..plans import Builder, DrawnLine, LaidVector, LineMeaning, Plan, Step
from ..reader import Table
from .base import (
    Context,
    Group,
    GroupMotion,
    Guide,
    at_toggle,
    check_lines_cross,
    nearest_branch,
    read_branch,
    read_guide,
)
from .sliding import (
    coriolis,
    coriolis_letter,
    guide_link,
    guide_meaning,
    guide_point,
    turns,
)

# B ahead of (forward) or behind (backward) the foot of A on the guide,
# counted along the guide's direction.
_BRANCHES = {"forward": 1, "backward": -1}


@dataclass(frozen=True)
class RRP(Group):
    kind = "RRP"
    joint_roles = ("outer A (link a)", "inner B (slider, link b)")
    length: float = 0.0
    guide: Guide = Guide(where="")
    assembly: str | None = None
    near: tuple[float, float] | None = None

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> RRP:
        length = table.number("length", positive=True)
        guide = read_guide(table.raw("guide"), table.where("guide"))
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
            gap = abs(float(np.atleast_1d(height)[i]))
            a_name, b_name = self.joints
            return AssemblyError(b_name, at, self.label,
                                 f"{a_name} is {gap:.6g} m from the guide > {a_name}{b_name} = {self.length:.6g} m")

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

    def coriolis_sliders(self, mechanism) -> tuple[int, ...]:
        """The slider, when its guide turns (its acceleration then has a Coriolis component)."""
        return (self.links[1],) if turns(mechanism, guide_link(mechanism, self.guide)) else ()

    # The plans: the same equations, solved by crossing lines of action.

    def construct_velocity(self, board: Builder) -> None:
        """vB = vA + vBA (⊥ AB) = vBg + vBBg (∥ guide): lines through a and bg, crossed at b.

        bg is the image of the guide link g's point under B, by similarity from
        g's images already on the plan; on a frame guide it is the pole.
        """
        a_name, b_name = self.joints
        _, along_guide, carrier = board.guide_line(self.guide)
        a = board.images[a_name]
        bg = guide_point(board, carrier, b_name)
        b, angle, across_ab, on_guide = self._close(board, a, bg)
        g = f"{b_name}{carrier}"
        relative = () if bg == "p" else (LaidVector(bg, b, f"v{b_name}{g}"),)
        board.step(Step(
            equation=f"v{b_name} = v{a_name} + v{b_name}{a_name} = v{g} + v{b_name}{g}",
            vectors=(LaidVector(a, b, f"v{b_name}{a_name}"), *relative, LaidVector("p", b, f"v{b_name}")),
            lines=(DrawnLine(a, across_ab, LineMeaning("perpendicular", (a_name, b_name))),
                   DrawnLine(bg, along_guide, on_guide)),
            fixes=(b,), crossing_deg=angle))

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aB = aA + aBAⁿ + aBA^τ (⊥ AB) = aBg + aBBgᵏ + aBBg^r (∥ guide).

        The normal part ω²·AB points from B toward A; the Coriolis part
        2·ωg × vBBg (only on a turning guide) is vBBg, read off the velocity
        plan, turned 90° in the sense of ωg; the relative part runs along the
        guide.
        """
        a_name, b_name = self.joints
        rod, slider = self.links
        a_pos, b_pos = board.positions[a_name], board.positions[b_name]
        _, along_guide, carrier = board.guide_line(self.guide)
        a = board.images[a_name]
        omega = velocities.rates[rod]
        normal = board.mark(f"n{rod}", board.points[a] - omega**2 * (b_pos - a_pos))
        bg = guide_point(board, carrier, b_name)
        g = f"{b_name}{carrier}"
        laid = [LaidVector(a, normal, f"a{b_name}{a_name}ⁿ")]
        equation = f"a{b_name} = a{a_name} + a{b_name}{a_name}ⁿ + a{b_name}{a_name}^τ = a{g}"
        start = bg
        if self.coriolis_sliders(board.mechanism):
            v_rel = velocities.value(b_name) - velocities.points[bg]
            start = board.mark(coriolis_letter(board, slider),
                               board.points[bg] + coriolis(velocities.rates.get(carrier, 0.0), v_rel))
            laid.append(LaidVector(bg, start, f"a{b_name}{g}ᵏ"))
            equation += f" + a{b_name}{g}ᵏ"
        equation += f" + a{b_name}{g}^r"
        b, angle, across_ab, on_guide = self._close(board, normal, start)
        laid.append(LaidVector(normal, b, f"a{b_name}{a_name}^τ"))
        if start != "p":  # from the pole it would be aB itself
            laid.append(LaidVector(start, b, f"a{b_name}{g}^r"))
        laid.append(LaidVector("p", b, f"a{b_name}"))
        board.step(Step(
            equation=equation, vectors=tuple(laid),
            lines=(DrawnLine(normal, across_ab, LineMeaning("perpendicular", (a_name, b_name))),
                   DrawnLine(start, along_guide, on_guide)),
            fixes=(normal, *((start,) if start != bg else ()), b), crossing_deg=angle))

    def _close(self, board: Builder, on_rod: str, on_guide_line: str) -> tuple[str, float, complex, LineMeaning]:
        """The plan closed at b: the line square to AB through ``on_rod`` crossed with the line along the
        guide through ``on_guide_line``; b recorded on the rod and the slider, and the slider's sliding
        (b less the guide line's point).  Returns b, the crossing angle, the direction square to AB and
        what the guide's line means."""
        a_name, b_name = self.joints
        rod, slider = self.links
        a_pos, b_pos = board.positions[a_name], board.positions[b_name]
        _, along_guide, carrier = board.guide_line(self.guide)
        across_ab = 1j * (b_pos - a_pos)
        on_guide = guide_meaning(self.guide)
        value, angle = board.cross(Line(board.points[on_rod], across_ab, f"⊥{a_name}{b_name}"),
                                   Line(board.points[on_guide_line], along_guide, on_guide.text))
        b = board.fix(b_name, value)
        board.on_link(rod, a_pos, board.images[a_name])
        board.on_link(rod, b_pos, b)
        board.on_link(slider, b_pos, b)
        board.turns_with[slider] = carrier
        board.slides(slider, on_guide_line, b)
        return b, angle, across_ab, on_guide

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
