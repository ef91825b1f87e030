"""RRR: two links jointed at B, each pivoted at a known outer joint (A on link a, C on link b).

Closure: B = A + AB·e^{iθa} = C + CB·e^{iθb}.  Differentiated once and twice:

    vB = vA + ωa × AB = vC + ωb × CB
    aB = aA + εa × AB − ωa²·AB = aC + εb × CB − ωb²·CB

Both are the two-line equation ``x1·(i·AB) − x2·(i·CB) = w``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError
from ..geometry import Line
from ..kinematics import LinkMotion, PointMotion, TwoLines, norm2
from ..plans import Builder, DrawnLine, LaidVector, Plan, Step
from ..reader import Table
from .base import Context, Group, GroupMotion, at_toggle, check_lines_cross, nearest_branch, read_branch

# B left of the directed line A→C is the counter-clockwise turn of A→C.
_BRANCHES = {"left": 1, "right": -1}


@dataclass(frozen=True)
class RRR(Group):
    kind = "RRR"
    joint_roles = ("outer A (link a)", "inner B", "outer C (link b)")
    lengths: tuple[float, float] = (0.0, 0.0)
    assembly: str | None = None
    near: tuple[float, float] | None = None

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> RRR:
        lengths = table.numbers("lengths", 2, positive=True)
        assembly, near = read_branch(table, tuple(_BRANCHES))
        table.done()
        return cls(where=table.path, links=links, joints=joints, lengths=lengths, assembly=assembly, near=near)

    def known_joints(self) -> tuple[str, ...]:
        return (self.joints[0], self.joints[2])

    def new_joints(self) -> tuple[str, ...]:
        return (self.joints[1],)

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, b, c = self.joints
        return {self.links[0]: (a, b), self.links[1]: (c, b)}

    def _candidates(self, context: Context, branch: int):
        a_name, b_name, c_name = self.joints
        ab, bc = self.lengths
        a, c = context.point(a_name), context.point(c_name)
        d = c.r - a.r
        d2 = norm2(d)
        # x: where the foot of B falls along A→C, h²: B's squared height over AC,
        # both as fractions of |AC| (law of cosines, no trigonometry needed).
        with np.errstate(divide="ignore", invalid="ignore"):
            x = (ab * ab - bc * bc + d2) / (2.0 * d2)
            h2 = at_toggle(ab * ab / d2 - x * x, 1.0)

        def reason(i: int, at: str) -> AssemblyError:
            span = float(np.sqrt(np.atleast_1d(d2)[i]))
            if span == 0:
                why = f"{a_name} and {c_name} coincide, so nothing fixes where {b_name} lies"
            elif span > ab + bc:
                why = f"{a_name}–{c_name} = {span:.6g} m > {a_name}{b_name} + {b_name}{c_name} = {ab + bc:.6g} m"
            else:
                why = f"{a_name}–{c_name} = {span:.6g} m < |{a_name}{b_name} − {b_name}{c_name}| = {abs(ab - bc):.6g} m"
            return AssemblyError(b_name, at, self.label, why)

        if not np.min(h2) >= 0:  # NaN fails too
            context.fail_where(np.atleast_1d(~(h2 >= 0)), reason)
        return a, c, a.r + d * (x + 1j * branch * np.sqrt(h2))

    def with_branch(self, context: Context) -> int:
        if self.assembly is not None:
            return _BRANCHES[self.assembly]
        assert self.near is not None
        return nearest_branch({s: self._candidates(context, s)[2] for s in (1, -1)}, self.near)

    def solve(self, context: Context, branch: int) -> GroupMotion:
        a, c, b_r = self._candidates(context, branch)
        ab_vec, cb_vec = b_r - a.r, b_r - c.r
        e1, e2 = 1j * ab_vec, -1j * cb_vec
        lines = TwoLines(e1, e2)
        sine = lines.det / (self.lengths[0] * self.lengths[1])
        check_lines_cross(context, self, sine, f"links {self.links[0]} and {self.links[1]} lie in one line (a toggle)")
        omega_a, omega_b = lines.solve(c.v - a.v)
        b_v = a.v + omega_a * e1
        w = c.a - a.a + omega_a * omega_a * ab_vec - omega_b * omega_b * cb_vec
        epsilon_a, epsilon_b = lines.solve(w)
        b_a = a.a + (1j * epsilon_a - omega_a * omega_a) * ab_vec
        u_a, u_b = ab_vec / self.lengths[0], cb_vec / self.lengths[1]
        a_name, b_name, c_name = self.joints
        return GroupMotion(
            points={b_name: PointMotion(b_r, b_v, b_a)},
            links={
                self.links[0]: LinkMotion(a_name, u_a, np.angle(u_a), omega_a, epsilon_a),
                self.links[1]: LinkMotion(c_name, u_b, np.angle(u_b), omega_b, epsilon_b),
            },
            conditioning=sine,
        )

    # The plans: the same equations, solved by crossing lines of action.

    def construct_velocity(self, board: Builder) -> None:
        """vB = vA + vBA (⊥ AB) = vC + vBC (⊥ CB): lines through a and c, crossed at b."""
        a_name, b_name, c_name = self.joints
        a_pos, b_pos, c_pos = (board.positions[n] for n in self.joints)
        a, c = board.images[a_name], board.images[c_name]
        along_ab, along_cb = 1j * (b_pos - a_pos), 1j * (b_pos - c_pos)
        b_value, angle = board.cross(Line(board.points[a], along_ab, f"⊥{a_name}{b_name}"),
                                     Line(board.points[c], along_cb, f"⊥{c_name}{b_name}"))
        b = board.fix(b_name, b_value)
        board.on_link(self.links[0], a_pos, a)
        board.on_link(self.links[0], b_pos, b)
        board.on_link(self.links[1], c_pos, c)
        board.on_link(self.links[1], b_pos, b)
        board.step(Step(
            equation=f"v{b_name} = v{a_name} + v{b_name}{a_name} = v{c_name} + v{b_name}{c_name}",
            vectors=(LaidVector(a, b, f"v{b_name}{a_name}"), LaidVector(c, b, f"v{b_name}{c_name}"),
                     LaidVector("p", b, f"v{b_name}")),
            lines=(DrawnLine(a, along_ab, f"⊥ {a_name}{b_name}"), DrawnLine(c, along_cb, f"⊥ {c_name}{b_name}")),
            fixes=(b,), crossing_deg=angle))

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aB = aA + aBA^n + aBA^τ = aC + aBC^n + aBC^τ, the normal parts ω²·l toward A and C."""
        a_name, b_name, c_name = self.joints
        a_pos, b_pos, c_pos = (board.positions[n] for n in self.joints)
        a, c = board.images[a_name], board.images[c_name]
        omega_a, omega_b = velocities.rates[self.links[0]], velocities.rates[self.links[1]]
        normal_a = board.mark(f"n{self.links[0]}", board.points[a] - omega_a**2 * (b_pos - a_pos))
        normal_b = board.mark(f"n{self.links[1]}", board.points[c] - omega_b**2 * (b_pos - c_pos))
        along_ab, along_cb = 1j * (b_pos - a_pos), 1j * (b_pos - c_pos)
        b_value, angle = board.cross(Line(board.points[normal_a], along_ab, f"⊥{a_name}{b_name}"),
                                     Line(board.points[normal_b], along_cb, f"⊥{c_name}{b_name}"))
        b = board.fix(b_name, b_value)
        for link, first, letter in ((self.links[0], a_pos, a), (self.links[1], c_pos, c)):
            board.on_link(link, first, letter)
            board.on_link(link, b_pos, b)
        board.step(Step(
            equation=(f"a{b_name} = a{a_name} + a{b_name}{a_name}ⁿ + a{b_name}{a_name}^τ"
                      f" = a{c_name} + a{b_name}{c_name}ⁿ + a{b_name}{c_name}^τ"),
            vectors=(LaidVector(a, normal_a, f"a{b_name}{a_name}ⁿ"), LaidVector(normal_a, b, f"a{b_name}{a_name}^τ"),
                     LaidVector(c, normal_b, f"a{b_name}{c_name}ⁿ"), LaidVector(normal_b, b, f"a{b_name}{c_name}^τ"),
                     LaidVector("p", b, f"a{b_name}")),
            lines=(DrawnLine(normal_a, along_ab, f"⊥ {a_name}{b_name}"),
                   DrawnLine(normal_b, along_cb, f"⊥ {c_name}{b_name}")),
            fixes=(normal_a, normal_b, b), crossing_deg=angle))
