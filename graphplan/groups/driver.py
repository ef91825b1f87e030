"""Groups of class I: the input link and its prescribed motion.

``crank``: link turning about a frame pivot O, its joint A at OA·e^{iφ};
``ω`` and ``ε`` are those of the instant analysed at every position (the
plan method's data), so vA = ω × OA and aA = ε × OA − ω²·OA.  With a
``swing`` it rocks between two angles instead of turning round (an input
rocker, where the mechanism cannot let it make a whole turn): its positions
then run over the swing as a slider's run over its travel.

``slider``: link translating along a frame guide, its joint at G + s·u with
velocity ``ṡ`` and acceleration ``s̈`` along u.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import SceneError
from ..forces import ForceBoard, PolygonBuilder
from ..kinematics import (
    LinkMotion,
    PointMotion,
    SlideMotion,
    cross,
    point_fixed_on,
    unit_vectors,
)
from ..plans import Builder, LaidVector, Plan, Step
from ..reader import Table, radians_within_a_turn
from ..rounding import ANGLE_FLOOR_DEG
from ..table_keys import keys_of_other_tables
from .base import Context, GroupMotion, Guide, read_guide


@dataclass(frozen=True)
class Crank:
    kind = "crank"
    # The key of [driver] its positions run over when it does not turn round.
    run_key = "swing"
    where: str
    link: int
    pivot: str
    joint: str
    length: float
    omega: float
    epsilon: float
    swing: tuple[float, float] | None = None
    # The speed in rev/min where the scene gave it so (signed as omega), for the note to write n beside ω; None
    # where it gave omega.
    rpm: float | None = None

    @classmethod
    def read(cls, table: Table, link: int) -> Crank:
        pivot = table.string("pivot")
        joint = table.string("joint")
        length = table.number("length", positive=True)
        omega = table.speed(sense=", signed (counter-clockwise positive)")
        if omega == 0.0:
            raise SceneError(table.where("rpm" if table.has("rpm") else "omega"), "must not be zero: the driver must move")
        epsilon = table.number("epsilon", 0.0)
        swing = None
        if table.has("swing"):
            ends = table.numbers("swing", 2)
            if ends[0] == ends[1] or abs(ends[1] - ends[0]) >= 360.0:
                raise SceneError(table.where("swing"), "must span less than a turn: [from, to] in degrees with "
                                 "0 < |to − from| < 360 (leave swing out for a crank that turns round)", list(ends))
            # The span is kept as typed, a difference of two close floats (exact), from the first end's angle within
            # the turn.
            first = math.fmod(ends[0], 360.0)
            swing = (radians_within_a_turn(first), math.radians(first + (ends[1] - ends[0])))
        table.done(elsewhere=keys_of_other_tables("driver"))
        return cls(where=table.path, link=link, pivot=pivot, joint=joint, length=length, omega=omega,
                   epsilon=epsilon, swing=swing, rpm=float(table.raw("rpm")) if table.has("rpm") else None)

    def known_joints(self) -> tuple[str, ...]:
        return (self.pivot,)

    def new_joints(self) -> tuple[str, ...]:
        return (self.joint,)

    def guides(self) -> tuple[Guide, ...]:
        return ()

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        return {self.link: (self.pivot, self.joint)}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        return ((self.pivot, self.link, None),)

    def sliding_points(self) -> dict[int, dict[str, complex]]:
        return {}

    @property
    def sense(self) -> float:
        """+1 for a counter-clockwise crank, −1 for clockwise: the direction positions are counted in."""
        return math.copysign(1.0, self.omega)

    @property
    def cyclic(self) -> bool:
        """Whether the crank turns round, so that its positions and its motion repeat every turn."""
        return self.swing is None

    @property
    def coordinate_speed(self) -> float:
        """The rate of the driver's own coordinate, its angle φ: ω (rad/s)."""
        return self.omega

    @property
    def coordinate_acceleration(self) -> float:
        """The second derivative of the angle φ: ε (rad/s²)."""
        return self.epsilon

    @property
    def travel(self) -> tuple[float, float]:
        """The angles (rad) a rocking crank's positions run between."""
        if self.swing is None:
            raise AttributeError("a crank that turns round has no travel: its positions span the turn")
        return self.swing

    def describe(self, value: float) -> str:
        angle = math.degrees(value) % 360.0
        # An extreme found as a root lies 1e-18 rad off 0: rounding of a turn, written 0° as results.json does.
        if min(angle, 360.0 - angle) < ANGLE_FLOOR_DEG:
            angle = 0.0
        return f"φ = {angle:.6g}°"

    def solve(self, context: Context, values: np.ndarray) -> GroupMotion:
        u = unit_vectors(values)
        link = LinkMotion(self.pivot, u, values, self.omega, self.epsilon)
        joint = point_fixed_on(context.point(self.pivot), link, self.length)  # OA along the crank's reference line
        return GroupMotion(points={self.joint: joint}, links={self.link: link})

    def construct_velocity(self, board: Builder) -> None:
        """vA = ω × OA: pa perpendicular to OA, in the sense of ω."""
        pivot, joint = board.positions[self.pivot], board.positions[self.joint]
        a = board.fix(self.joint, 1j * self.omega * (joint - pivot))
        board.on_link(self.link, pivot, board.images[self.pivot])
        board.on_link(self.link, joint, a)
        board.step(Step(f"v{self.joint} = ω{self.link} × {self.pivot}{self.joint}",
                        (LaidVector("p", a, f"v{self.joint}"),), fixes=(a,)))

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aA = aAⁿ + aA^τ: ω²·OA toward O, and ε × OA only when ε ≠ 0."""
        pivot, joint = board.positions[self.pivot], board.positions[self.joint]
        arm = joint - pivot
        normal = -self.omega**2 * arm
        if self.epsilon == 0.0:
            a = board.fix(self.joint, normal)
            vectors: tuple[LaidVector, ...] = (LaidVector("p", a, f"a{self.joint}"),)
            equation = f"a{self.joint} = a{self.joint}ⁿ = ω{self.link}²·l{self.pivot}{self.joint}"
        else:
            end = board.mark(f"n{self.link}", normal)
            a = board.fix(self.joint, normal + 1j * self.epsilon * arm)
            vectors = (LaidVector("p", end, f"a{self.joint}ⁿ"), LaidVector(end, a, f"a{self.joint}^τ"),
                       LaidVector("p", a, f"a{self.joint}"))
            equation = f"a{self.joint} = a{self.joint}ⁿ + a{self.joint}^τ"
        board.on_link(self.link, pivot, board.images[self.pivot])
        board.on_link(self.link, joint, a)
        board.step(Step(equation, vectors, fixes=(a,)))

    def construct_forces(self, board: ForceBoard) -> None:
        """ΣMO of the crank gives the balancing moment; its polygon closes with the frame's reaction."""

        frame = board.mechanism.scene.frame_link
        balancing = board.couple(self.link, self.pivot, "Mb")
        polygon = PolygonBuilder(f"ΣF{self.link} + R{frame}{self.link} = 0")
        polygon.lay_all(board.loads_on(self.link))
        reaction = polygon.closing(f"R{frame}{self.link}")
        board.react(f"R{frame}{self.link}", self.pivot, frame, self.link, reaction)
        board.balancing = balancing
        board.finish_group(f"I({frame},{self.link})", (self.link,), polygon.record())


@dataclass(frozen=True)
class Slider:
    kind = "slider"
    # The key of [driver] its positions run over.
    run_key = "travel"
    where: str
    link: int
    joint: str
    guide: Guide
    velocity: float
    acceleration: float
    travel: tuple[float, float]

    @classmethod
    def read(cls, table: Table, link: int) -> Slider:
        joint = table.string("joint")
        guide = read_guide(table.raw("guide"), table.where("guide"))
        velocity = table.number("velocity")
        if velocity == 0.0:
            raise SceneError(table.where("velocity"), "must not be zero: the driver must move")
        acceleration = table.number("acceleration", 0.0)
        travel = table.numbers("travel", 2)
        if travel[0] == travel[1]:
            raise SceneError(table.where("travel"), "must span a stroke: [from, to] with from ≠ to", list(travel))
        table.done(elsewhere=keys_of_other_tables("driver"))
        return cls(where=table.path, link=link, joint=joint, guide=guide, velocity=velocity,
                   acceleration=acceleration, travel=travel)

    def known_joints(self) -> tuple[str, ...]:
        return ()

    def new_joints(self) -> tuple[str, ...]:
        return (self.joint,)

    def guides(self) -> tuple[Guide, ...]:
        return (self.guide,)

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        return {self.link: (self.joint,)}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        return ()

    def sliding_points(self) -> dict[int, dict[str, complex]]:
        return {}

    @property
    def sense(self) -> float:
        return math.copysign(1.0, self.velocity)

    @property
    def cyclic(self) -> bool:
        """A slider's positions run over its travel once: they do not repeat."""
        return False

    @property
    def coordinate_speed(self) -> float:
        """The rate of the driver's own coordinate, its travel s: ṡ (m/s)."""
        return self.velocity

    @property
    def coordinate_acceleration(self) -> float:
        """The second derivative of the travel s: s̈ (m/s²)."""
        return self.acceleration

    def describe(self, value: float) -> str:
        return f"s = {value:.6g} m"

    def solve(self, context: Context, values: np.ndarray) -> GroupMotion:
        guide = context.guide(self.guide)
        r = guide.origin.r + values * guide.u
        joint = PointMotion(r, self.velocity * guide.u + 0.0 * values, self.acceleration * guide.u + 0.0 * values)
        return GroupMotion(
            points={self.joint: joint},
            links={self.link: LinkMotion(self.joint, guide.u, np.angle(guide.u), 0.0, 0.0)},
            slides=(SlideMotion(self.link, guide.link, self.joint, guide.u, values, self.velocity,
                                self.acceleration),),
        )

    def construct_velocity(self, board: Builder) -> None:
        """vA = ṡ along the guide: the driver's given velocity, laid off from the pole."""
        a = board.fix(self.joint, self.velocity * board.guide_direction(self.guide))
        board.on_link(self.link, board.positions[self.joint], a)
        board.step(Step(f"v{self.joint} = ṡ", (LaidVector("p", a, f"v{self.joint}"),), fixes=(a,)))

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aA = s̈ along the guide."""
        a = board.fix(self.joint, self.acceleration * board.guide_direction(self.guide))
        board.on_link(self.link, board.positions[self.joint], a)
        board.step(Step(f"a{self.joint} = s̈", (LaidVector("p", a, f"a{self.joint}"),), fixes=(a,)))

    def construct_forces(self, board: ForceBoard) -> None:
        """The balancing force along the guide and the guide's normal reaction by crossing their lines;
        where the normal reaction acts from ΣM about the joint."""

        frame = board.mechanism.scene.frame_link
        _, u, carrier = board.guide_line(self.guide)
        name = f"R{carrier}{self.link}"
        polygon = PolygonBuilder(f"ΣF{self.link} + Fb + {name} = 0")
        polygon.lay_all(board.loads_on(self.link))
        balancing, normal = polygon.close("Fb", u, name, 1j * u)
        # The balancing force acts through the joint, so it adds nothing to ΣM about it.
        shift = board.couple(self.link, self.joint, f"{name}·x")
        offset = shift / cross(u, normal) if abs(normal) > 0 else 0.0
        board.react(name, self.joint, carrier, self.link, normal, offset)
        board.balancing = float((balancing * u.conjugate()).real)
        board.finish_group(f"I({frame},{self.link})", (self.link,), polygon.record())
