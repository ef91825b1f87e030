"""RPP: a block (link a) pivoted at a known A slides in a slot of link b; link b slides on a guide.

Link b's reference point B is where its slot crosses the guide line; the
slot makes ``angle`` with the guide (90° in a Scotch yoke).  With G a point
of the guide, u its direction and w = u·e^{i·angle} the slot's:

    A = G + s_b·u + s_a·w
    vA = vG + ωg × GA + ṡ_b·u + ṡ_a·w
    aA = aG + εg × GA − ωg²·GA + 2·ωg × (ṡ_b·u + ṡ_a·w) + s̈_b·u + s̈_a·w

Both links keep the guide's orientation (b) or the slot's (a), so they turn
with the guide's link.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import SceneError
from ..kinematics import LinkMotion, PointMotion, SlideMotion, TwoLines, unit
from ..reader import Table
from .base import Context, Group, GroupMotion, Guide, read_guide


@dataclass(frozen=True)
class RPP(Group):
    kind = "RPP"
    joint_roles = ("outer A (block, link a)", "B (link b, where its slot crosses the guide)")
    guide: Guide = Guide(where="")
    angle: float = math.pi / 2

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> RPP:
        guide = read_guide(table.raw("guide"), table.where("guide"))
        angle_deg = table.number("angle", 90.0)
        if abs(math.sin(math.radians(angle_deg))) < 1e-9:
            raise SceneError(table.where("angle"), "the slot must not be parallel to the guide", angle_deg)
        table.done()
        return cls(where=table.path, links=links, joints=joints, guide=guide, angle=math.radians(angle_deg))

    def known_joints(self) -> tuple[str, ...]:
        return (self.joints[0],)

    def new_joints(self) -> tuple[str, ...]:
        return (self.joints[1],)

    def guides(self) -> tuple[Guide, ...]:
        return (self.guide,)

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, b = self.joints
        return {self.links[0]: (a,), self.links[1]: (b,)}

    def sliding_points(self) -> dict[int, dict[str, complex]]:
        return {self.links[1]: {self.joints[0]: unit(self.angle)}}

    def solve(self, context: Context, branch: int) -> GroupMotion:
        a_name, b_name = self.joints
        a = context.point(a_name)
        guide = context.guide(self.guide)
        u = guide.u
        w = u * unit(self.angle)
        lines = TwoLines(u, w)
        det = math.sin(self.angle)  # u × w, the same at every position
        s_b, s_a = lines.solve(a.r - guide.origin.r)
        b_r = guide.origin.r + s_b * u
        carried_v, carried_a = guide.carried(a.r)
        s_b_dot, s_a_dot = lines.solve(a.v - carried_v)
        coriolis = 2j * guide.omega * (s_b_dot * u + s_a_dot * w)
        s_b_ddot, s_a_ddot = lines.solve(a.a - carried_a - coriolis)
        b_carried_v, b_carried_a = guide.carried(b_r)
        b = PointMotion(b_r, b_carried_v + s_b_dot * u,
                        b_carried_a + 2j * guide.omega * s_b_dot * u + s_b_ddot * u)
        link_a, link_b = self.links
        return GroupMotion(
            points={b_name: b},
            links={
                link_a: LinkMotion(a_name, w, np.angle(w), guide.omega, guide.epsilon),
                link_b: LinkMotion(b_name, u, np.angle(u), guide.omega, guide.epsilon),
            },
            slides=(SlideMotion(link_a, link_b, a_name, w, s_a, s_a_dot, s_a_ddot),
                    SlideMotion(link_b, guide.link, b_name, u, s_b, s_b_dot, s_b_ddot)),
            conditioning=det,
        )
