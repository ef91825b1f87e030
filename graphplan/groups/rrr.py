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
from ..kinematics import LinkMotion, PointMotion, TwoLines, norm2
from ..reader import Table
from .base import Context, Group, GroupMotion, check_lines_cross, nearest_branch, read_branch

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
            h2 = ab * ab / d2 - x * x

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
