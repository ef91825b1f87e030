"""RPP: a block (link a) pivoted at a known A slides in a slot of link b; link b slides on a guide.

Link b's reference point B is where its slot crosses the guide line; the
slot makes ``angle`` with the guide (90° in a Scotch yoke).  With G a point
of the guide, u its direction and w = u·e^{i·angle} the slot's:

    A = G + s_b·u + s_a·w
    vA = vG + ωg × GA + ṡ_b·u + ṡ_a·w
    aA = aG + εg × GA − ωg²·GA + 2·ωg × (ṡ_b·u + ṡ_a·w) + s̈_b·u + s̈_a·w

Both links keep the guide's orientation (b) or the slot's (a), so they turn
with the guide's link.

On the plans the unknown is A_b (``A4``), link b's point under the block:
vA_b = vA + vA_bA (∥ slot) = vA_g + vA_bA_g (∥ guide), with A_g the guide
link's point under A; link b slides on the guide without turning relative to
it, so every point of it has the same motion relative to the guide link, and
B follows as vB = vB_g + vA_bA_g (on a frame guide link b translates: b = a_b).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import SceneError
from ..forces import ForceBoard, PolygonBuilder, Term
from ..geometry import Line
from ..kinematics import LinkMotion, PointMotion, SlideMotion, TwoLines, cross, unit
from ..plans import Builder, DrawnLine, LaidVector, LineMeaning, Plan, Step, image_name
from ..reader import Table, radians_within_a_turn
from .base import UNREAD_GUIDE, Context, Group, GroupMotion, Guide, read_guide, refuse_branch, turns
from .sliding import (
    coriolis_letter,
    free_letter,
    guide_link,
    guide_meaning,
    guide_point,
)

# Link b's images must be this far apart (a fraction of the mechanism's size) to carry its figure.
_SPAN = 1e-6


@dataclass(frozen=True)
class RPP(Group):
    kind = "RPP"
    joint_roles = ("outer A (block, link a)", "B (link b, where its slot crosses the guide)")
    guide: Guide = UNREAD_GUIDE
    angle: float = math.pi / 2

    @classmethod
    def read(cls, table: Table, links: tuple[int, int], joints: tuple[str, ...]) -> RPP:
        guide = read_guide(table.raw("guide"), table.where("guide"))
        angle_deg = table.number("angle", 90.0)
        if abs(math.sin(radians_within_a_turn(angle_deg))) < 1e-9:
            raise SceneError(table.where("angle"), "the slot must not be parallel to the guide", angle_deg)
        refuse_branch(table, "an RPP has one assembly: B is where link b's slot, through A at angle degrees to the "
                      "guide, crosses the guide")
        table.done()
        return cls(where=table.path, links=links, joints=joints, guide=guide, angle=radians_within_a_turn(angle_deg))

    def known_joints(self) -> tuple[str, ...]:
        return (self.joints[0],)

    def new_joints(self) -> tuple[str, ...]:
        return (self.joints[1],)

    def guides(self) -> tuple[Guide, ...]:
        return (self.guide,)

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, b = self.joints
        return {self.links[0]: (a,), self.links[1]: (b,)}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        return ((self.joints[0], self.links[0], None),)

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

    def sliding_pairs(self, mechanism) -> tuple[tuple[int, int, str], ...]:
        """The block in the slot of link b, and link b on its guide."""
        return ((self.links[0], self.links[1], self.joints[0]),
                (self.links[1], guide_link(mechanism, self.guide), self.joints[1]))

    def coriolis_sliders(self, mechanism) -> tuple[int, ...]:
        """Both links when the guide turns: the block in the turning slot, link b on the turning guide.

        Link b turns only with its guide, which the mechanism's translating links cannot tell where the guide's
        link itself translates; so the guide decides for both.
        """
        return self.links if turns(mechanism, guide_link(mechanism, self.guide)) else ()

    # The plans: the same equations, solved by crossing lines of action.

    def construct_velocity(self, board: Builder) -> None:
        """vA4 = vA3 + vA4A3 (∥ slot) = vAg + vA4Ag (∥ guide): lines through a and a_g, crossed at a4.

        A3 is the block's point A (image ``a``), A4 link b's point under it,
        Ag the guide link's point under it (the pole on a frame guide).
        """
        a_name, _ = self.joints
        block, slotted = self.links
        along_guide, along_slot, carrier = self._lines(board)
        on_slot, on_guide = self._meanings()
        a = board.images[a_name]
        ag = guide_point(board, carrier, a_name)
        value, angle = board.cross(Line(board.points[a], along_slot, on_slot.text),
                                   Line(board.points[ag], along_guide, on_guide.text))
        a4 = board.mark(self._coincident(board), value)
        board.slides(block, a4, a)
        board.slides(slotted, ag, a4)
        pin, point, g = f"{a_name}{block}", f"{a_name}{slotted}", f"{a_name}{carrier}"
        relative = () if ag == "p" else (LaidVector(ag, a4, f"v{point}{g}"),)
        board.step(Step(
            equation=f"v{point} = v{pin} + v{point}{pin} = v{g} + v{point}{g}",
            vectors=(LaidVector(a, a4, f"v{point}{pin}"), *relative, LaidVector("p", a4, f"v{point}")),
            lines=(DrawnLine(a, along_slot, on_slot), DrawnLine(ag, along_guide, on_guide)),
            fixes=(a4,), crossing_deg=angle))
        self._place_b(board, "v", carrier, ag, a4)

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aA4 = aA3 + aA4A3ᵏ + aA4A3^r (∥ slot) = aAg + aA4Agᵏ + aA4Ag^r (∥ guide).

        On a turning guide both Coriolis parts are laid: 2·ω4 × vA4A3 from a
        (link b turns with the guide, ω4 = ωg) and 2·ωg × vA4Ag from a_g, each
        the relative velocity read off the velocity plan turned 90° in the
        sense of ω; the lines along the slot and the guide go through their ends.
        """
        a_name, _ = self.joints
        block, slotted = self.links
        along_guide, along_slot, carrier = self._lines(board)
        on_slot, on_guide = self._meanings()
        a = board.images[a_name]
        ag = guide_point(board, carrier, a_name)
        coincident = self._coincident(board)
        pin, point, g = f"{a_name}{block}", f"{a_name}{slotted}", f"{a_name}{carrier}"
        k_slot, k_guide, laid = a, ag, []
        equation = [f"a{point} = a{pin}", f" = a{g}"]
        if self.coriolis_sliders(board.mechanism):
            v_slot = velocities.points[coincident] - velocities.value(a_name)
            v_guide = velocities.points[coincident] - velocities.points[ag]
            k_slot = board.lay_coriolis(coriolis_letter(board, block), a, velocities.rates[slotted], v_slot)
            k_guide = board.lay_coriolis(coriolis_letter(board, slotted), ag, velocities.rates.get(carrier, 0.0),
                                         v_guide)
            laid += [LaidVector(a, k_slot, f"a{point}{pin}ᵏ"), LaidVector(ag, k_guide, f"a{point}{g}ᵏ")]
            equation = [f"{equation[0]} + a{point}{pin}ᵏ", f"{equation[1]} + a{point}{g}ᵏ"]
        value, angle = board.cross(Line(board.points[k_slot], along_slot, on_slot.text),
                                   Line(board.points[k_guide], along_guide, on_guide.text))
        a4 = board.mark(coincident, value)
        board.slides(block, a4, k_slot)
        board.slides(slotted, k_guide, a4)
        laid.append(LaidVector(k_slot, a4, f"a{point}{pin}^r"))
        if k_guide != "p":  # from the pole it would be aA4 itself
            laid.append(LaidVector(k_guide, a4, f"a{point}{g}^r"))
        laid.append(LaidVector("p", a4, f"a{point}"))
        board.step(Step(
            equation=f"{equation[0]} + a{point}{pin}^r{equation[1]} + a{point}{g}^r",
            vectors=tuple(laid),
            lines=(DrawnLine(k_slot, along_slot, on_slot), DrawnLine(k_guide, along_guide, on_guide)),
            fixes=(*(m for m in (k_slot, k_guide) if m not in (a, ag)), a4), crossing_deg=angle))
        self._place_b(board, "a", carrier, ag, a4)

    def _lines(self, board: Builder) -> tuple[complex, complex, int]:
        """The guide's and the slot's directions, and the guide's link."""
        _, along_guide, carrier = board.guide_line(self.guide)
        return along_guide, along_guide * unit(self.angle), carrier

    def _meanings(self) -> tuple[LineMeaning, LineMeaning]:
        """What the two lines of action follow: the slot cut in link b, and the guide."""
        return LineMeaning("slot", link=self.links[1]), guide_meaning(self.guide)

    def _coincident(self, board: Builder) -> str:
        """The plan letter of link b's point under A (``a4``)."""
        return free_letter(board, f"{image_name(self.joints[0])}{self.links[1]}")

    def _place_b(self, board: Builder, symbol: str, carrier: int, ag: str, a4: str) -> None:
        """B, link b's reference point: its motion relative to the guide link is A4's (link b does not turn on it).

        Then link b's figure (A4, B) and the block's (A, turning with link b)
        are registered for the similarity of named points.
        """
        a_name, b_name = self.joints
        block, slotted = self.links
        a_pos, b_pos = board.positions[a_name], board.positions[b_name]
        point, g = f"{a_name}{slotted}", f"{b_name}{carrier}"
        if carrier == board.mechanism.scene.frame_link:
            b = board.fix(b_name, board.points[a4])
            step = Step(f"{symbol}{b_name} = {symbol}{point}", (LaidVector("p", b, f"{symbol}{b_name}"),), fixes=(b,),
                        translating=slotted)
        else:
            bg = guide_point(board, carrier, b_name)
            b = board.fix(b_name, board.points[bg] + board.points[a4] - board.points[ag])
            relative = f"{symbol}{b_name}{g}" if symbol == "v" else f"{symbol}{b_name}{g}ᵏ + {symbol}{b_name}{g}^r"
            same = (f"{symbol}{point}{a_name}{carrier}" if symbol == "v"
                    else f"{symbol}{point}{a_name}{carrier}ᵏ + {symbol}{point}{a_name}{carrier}^r")
            step = Step(f"{symbol}{b_name} = {symbol}{g} + {relative}, {relative} = {same}",
                        (LaidVector(bg, b, f"{symbol}{b_name}{g}"), LaidVector("p", b, f"{symbol}{b_name}")),
                        fixes=(b,))
        board.step(step)
        board.on_link(slotted, a_pos, a4)
        board.on_link(slotted, b_pos, b)
        if abs(a_pos - b_pos) < _SPAN * board.size:
            # The block sits on B: one more point of link b, along the guide, carries its figure.
            far = b_pos + board.guide_line(self.guide)[1] * board.size
            ratio = board.figure_ratio(carrier)
            letter = b if ratio == 0 else board.mark(free_letter(board, f"{b}′"),
                                                     board.points[b] + ratio * (far - b_pos))
            board.on_link(slotted, far, letter)
        board.on_link(block, a_pos, board.images[a_name])
        board.turns_with[slotted] = carrier
        board.turns_with[block] = slotted

    # The forces: the group cut free, as drawn.

    def construct_forces(self, board: ForceBoard) -> None:
        """ΣMA of the block places the slot's normal force on it; link b's polygon closes with the slot's
        and the guide's normal forces (their lines crossed); the block's polygon with the reaction at A;
        ΣMB of link b places the guide's force."""

        a_name, b_name = self.joints
        la, lb = self.links
        a, b = board.positions[a_name], board.positions[b_name]
        _, u, carrier = board.guide_line(self.guide)
        slot = u * complex(math.cos(self.angle), math.sin(self.angle))
        pa = board.source_of(a_name, la)
        on_block, on_slotted, guide_force = f"R{lb}{la}", f"R{la}{lb}", f"R{carrier}{lb}"
        shift = board.couple(la, a_name, f"{on_block}·x")
        polygon = PolygonBuilder(f"ΣF{lb} + {on_slotted} + {guide_force} = 0;  {on_block} + ΣF{la} + R{pa}{la} = 0")
        polygon.lay_all(board.loads_on(lb))
        slot_force, normal = polygon.close(on_slotted, 1j * slot, guide_force, 1j * u)
        block_force = -slot_force
        polygon.lay(on_block, block_force)
        polygon.lay_all(board.loads_on(la))
        r_a = polygon.closing(f"R{pa}{la}")
        block_offset = shift / cross(slot, block_force) if abs(block_force) > 0 else 0.0
        turning = Term(on_slotted, float(cross(a + block_offset * slot - b, slot_force)), 0.0)
        guide_shift = board.couple(lb, b_name, f"{guide_force}·x", extra=(turning,))
        offset = guide_shift / cross(u, normal) if abs(normal) > 0 else 0.0
        board.hand_back(board.react(f"R{pa}{la}", a_name, pa, la, r_a))
        board.react(on_block, a_name, lb, la, block_force, block_offset)
        board.hand_back(board.react(guide_force, b_name, carrier, lb, normal, offset), b + offset * u)
        board.finish_group(self.label, self.links, polygon.record())
