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
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError
from ..kinematics import LinkMotion, PointMotion, SlideMotion, TwoLines, norm2
from ..reader import Table
from .base import Context, Group, GroupMotion, check_lines_cross


@dataclass(frozen=True)
class RPR(Group):
    kind = "RPR"
    joint_roles = ("outer A (slider block, link a)", "outer C (lever, link b)")
    offset: float = 0.0

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> RPR:
        offset = table.number("offset", 0.0)
        table.done()
        return cls(where=table.path, links=links, joints=joints, offset=offset)

    @property
    def coincident(self) -> str:
        """The lever's point that coincides with A (``A4`` on lever 4), as textbooks name it."""
        return f"{self.joints[0]}{self.links[1]}"

    def known_joints(self) -> tuple[str, ...]:
        return self.joints

    def new_joints(self) -> tuple[str, ...]:
        return (self.coincident,)

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, c = self.joints
        return {self.links[0]: (a,), self.links[1]: (c,)}

    def sliding_points(self) -> dict[int, dict[str, complex]]:
        return {self.links[1]: {self.joints[0]: 1.0 + 0j}}

    def solve(self, context: Context, branch: int) -> GroupMotion:
        a_name, c_name = self.joints
        a, c = context.point(a_name), context.point(c_name)
        ca = a.r - c.r
        ca2 = norm2(ca)
        e = self.offset
        s2 = ca2 - e * e

        def reason(i: int, at: str) -> AssemblyError:
            gap = float(np.sqrt(np.atleast_1d(ca2)[i]))
            if gap == 0:
                why = f"{a_name} lies on {c_name}, so nothing fixes the direction of link {self.links[1]}"
            else:
                why = f"{a_name}–{c_name} = {gap:.6g} m is not more than the slide's offset {abs(e):.6g} m"
            return AssemblyError(a_name, at, self.label, why)

        if not np.min(s2) > 0:
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
        angle = np.angle(u)
        lever = LinkMotion(c_name, u, angle, omega, epsilon)
        block = LinkMotion(a_name, u, angle, omega, epsilon)
        coincident = PointMotion(a.r, c.v + omega * e1, c.a + (1j * epsilon - omega * omega) * ca)
        return GroupMotion(
            points={self.coincident: coincident},
            links={self.links[0]: block, self.links[1]: lever},
            slides=(SlideMotion(self.links[0], self.links[1], a_name, u, s, s_dot, s_ddot),),
            conditioning=sine,
        )
