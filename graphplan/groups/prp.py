"""PRP: two sliders, link a on guide 1 and link b on guide 2, jointed at B.

B runs along each guide at its ``offset`` (to the left of the guide's
direction).  Closure: B = G1 + (s1 + i·o1)·u1 = G2 + (s2 + i·o2)·u2.
Differentiated, with B_k the point of guide k's link under B:

    vB = vB_1 + ṡ1·u1 = vB_2 + ṡ2·u2
    aB = aB_1 + 2·ω1 × ṡ1u1 + s̈1·u1 = aB_2 + 2·ω2 × ṡ2u2 + s̈2·u2

Each slider turns with its guide.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import SingularPositionError
from ..kinematics import LinkMotion, PointMotion, SlideMotion, TwoLines
from ..reader import Table
from .base import SINGULAR_SINE, Context, Group, GroupMotion, Guide, read_guide


@dataclass(frozen=True)
class PRP(Group):
    kind = "PRP"
    joint_roles = ("inner B",)
    guide_pair: tuple[Guide, Guide] = (Guide(where=""), Guide(where=""))
    offsets: tuple[float, float] = (0.0, 0.0)

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> PRP:
        pairs = table.items("guides", length=2)
        assert pairs is not None
        guide_pair = (read_guide(pairs[0][1], pairs[0][0]), read_guide(pairs[1][1], pairs[1][0]))
        offsets = table.numbers("offsets", 2, (0.0, 0.0))
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

    def solve(self, context: Context, branch: int) -> GroupMotion:
        g1, g2 = (context.guide(g) for g in self.guide_pair)
        o1, o2 = self.offsets
        u1, u2 = g1.u, g2.u
        lines = TwoLines(u1, -u2)
        det = lines.det
        context.fail_where(
            np.atleast_1d(np.abs(det) < SINGULAR_SINE),
            lambda i, at: SingularPositionError(at, self.label, "the two guides are parallel"),
        )
        # Position: s1·u1 − s2·u2 = G2 − G1 + i·(o2·u2 − o1·u1).
        gap = g2.origin.r - g1.origin.r + 1j * (o2 * u2 - o1 * u1)
        s1, s2 = lines.solve(gap)
        b_r = g1.origin.r + (s1 + 1j * o1) * u1
        v1, a1 = g1.carried(b_r)
        v2, a2 = g2.carried(b_r)
        s1_dot, s2_dot = lines.solve(v2 - v1)
        coriolis1 = 2j * g1.omega * s1_dot * u1
        coriolis2 = 2j * g2.omega * s2_dot * u2
        s1_ddot, s2_ddot = lines.solve(a2 + coriolis2 - a1 - coriolis1)
        b_name = self.joints[0]
        b = PointMotion(b_r, v1 + s1_dot * u1, a1 + coriolis1 + s1_ddot * u1)
        link_a, link_b = self.links
        return GroupMotion(
            points={b_name: b},
            links={
                link_a: LinkMotion(b_name, u1, np.angle(u1), g1.omega, g1.epsilon),
                link_b: LinkMotion(b_name, u2, np.angle(u2), g2.omega, g2.epsilon),
            },
            slides=(SlideMotion(link_a, g1.link, b_name, u1, s1, s1_dot, s1_ddot),
                    SlideMotion(link_b, g2.link, b_name, u2, s2, s2_dot, s2_ddot)),
            conditioning=det,
        )
