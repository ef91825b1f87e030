"""Triad: the class-III group of the third order, three binary links round a ternary one.

The binary links a, b, c turn about known outer joints A, C, E; their inner joints B, D, F
are the corners of the ternary (base) link t:

    |B − A| = AB,   |D − C| = CD,   |F − E| = EF,   BDF a rigid triangle.

No closed form places it, so its pose q = (B, ψ), ψ the direction of BD, is found numerically.
At the reference position every assembly is found (B swept round its circle about A, D from
two circles, F from the triangle; each sign change of |F − E|² − EF² refined by Brent's method)
and the one nearest the scene's sketch (``near``) is taken.  Every other position is reached
from its neighbour by Newton's method, which is why the motion solves a mechanism with a triad
on a grid of driver positions fine enough to follow one assembly (``continuation``).  The
velocities and accelerations are the closure differentiated: one Jacobian, two linear solves.

The plans cannot cross two lines at B, D or F, each of which has three unknowns.  Assur's
special point Σ of the ternary link can be: it lies where the lines of two binary links (AB and
CD) cross, so that B's velocity relative to A and Σ's relative to B are both square to AB, and
Σ's relative to D and D's relative to C both square to CD.  Then F follows from Σ and E by
crossing two lines, and B and D by similarity.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError, SceneError, SingularPositionError
from ..forces import ForceBoard, PolygonBuilder, Term
from ..geometry import Line, cross_lines
from ..kinematics import LinkMotion, PointMotion, Scalar, Vector, cross
from ..plans import Builder, DrawnLine, LaidVector, LineMeaning, Plan, Step
from ..reader import Table, check_xy
from .base import SINGULAR_SINE, Context, Group, GroupMotion
from .rrr import crossed_from_two_pivots, velocity_from_two_pivots

# Samples of B's circle at the reference position: two assemblies closer than a 2048th of a
# turn of AB would be missed, and such a triad is at a singular position anyway.
_SWEEP = 2048
# Newton's step is trusted when it converges to this share of the group's size.
_CONVERGED = 1e-12


@dataclass(frozen=True)
class Pose:
    """Where the ternary link is: its corner B (m) and the direction ψ of BD (rad)."""

    b: complex
    psi: float


@dataclass(frozen=True)
class TriadBranch:
    """The assembly chosen at the reference position: the triangle's orientation and its pose there.

    ``turn`` is +1 when B, D, F run counter-clockwise round the ternary link, −1 when clockwise.
    """

    turn: int
    pose: Pose


@dataclass(frozen=True)
class Triad(Group):
    kind = "triad"
    link_count = 4
    klass = 3
    order = 3
    continuation = True
    joint_roles = ("outer A (link a)", "inner B (links a, t)", "outer C (link b)", "inner D (links b, t)",
                   "outer E (link c)", "inner F (links c, t)")
    lengths: tuple[float, float, float] = (0.0, 0.0, 0.0)
    sides: tuple[float, float, float] = (0.0, 0.0, 0.0)
    near: tuple[tuple[str, complex], ...] = ()

    @classmethod
    def read(cls, table: Table, links: tuple[int, ...], joints: tuple[str, ...]) -> Triad:
        lengths = table.numbers("lengths", 3, positive=True)
        sides = table.numbers("sides", 3, positive=True)
        bd, df, fb = sides
        longest = max(sides)
        if 2 * longest >= bd + df + fb:
            raise SceneError(table.where("sides"), f"the ternary link's sides BD, DF, FB must make a triangle: "
                                                   f"the longest, {longest:g} m, must be shorter than the other two together",
                             list(sides))
        near_table = table.table("near")
        inner = (joints[1], joints[3], joints[5])
        near = []
        for name in near_table.data:
            if name not in inner:
                raise SceneError(near_table.where(name), f"must name an inner joint of the triad: {', '.join(inner)}")
            x, y = check_xy(near_table.raw(name), near_table.where(name))
            near.append((name, complex(x, y)))
        missing = [name for name in inner if name not in dict(near)]
        if missing:
            raise SceneError(near_table.path, f"needs where each inner joint lies in the sketch, to choose among up to "
                                              f"six assemblies; missing {', '.join(missing)}")
        b, d, f = (dict(near)[name] for name in inner)
        if abs(((d - b).conjugate() * (f - b)).imag) <= 1e-9 * max(abs(d - b), abs(f - b)) ** 2:
            raise SceneError(near_table.path, f"the sketch's {', '.join(inner)} lie in a line; it must show which way "
                                              f"round the ternary link's corners run")
        table.done()
        return cls(where=table.path, links=links, joints=joints, lengths=lengths, sides=sides, near=tuple(near))

    @property
    def label(self) -> str:
        return f"III({','.join(map(str, self.links))})"

    @property
    def ternary(self) -> int:
        return self.links[3]

    def known_joints(self) -> tuple[str, ...]:
        return (self.joints[0], self.joints[2], self.joints[4])

    def new_joints(self) -> tuple[str, ...]:
        return (self.joints[1], self.joints[3], self.joints[5])

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, b, c, d, e, f = self.joints
        la, lb, lc, lt = self.links
        return {la: (a, b), lb: (c, d), lc: (e, f), lt: (b, d, f)}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        a, b, c, d, e, f = self.joints
        la, lb, lc, lt = self.links
        return ((a, la, None), (b, lt, la), (c, lb, None), (d, lt, lb), (e, lc, None), (f, lt, lc))

    def arms(self) -> tuple[tuple[str, str, int], ...]:
        """Each binary link as (outer joint, inner joint, link)."""
        a, b, c, d, e, f = self.joints
        la, lb, lc, _ = self.links
        return ((a, b, la), (c, d, lb), (e, f, lc))

    # The position: the pose of the ternary link.

    def corner_f(self, turn: int) -> complex:
        """F in the ternary link's own frame: B at the origin, D on the +x axis."""
        bd, df, fb = self.sides
        cosine = (bd * bd + fb * fb - df * df) / (2 * bd * fb)
        return fb * complex(cosine, turn * math.sqrt(max(0.0, 1 - cosine * cosine)))

    def corners(self, pose: Pose, turn: int) -> tuple[complex, complex, complex]:
        direction = complex(math.cos(pose.psi), math.sin(pose.psi))
        return pose.b, pose.b + self.sides[0] * direction, pose.b + self.corner_f(turn) * direction

    def assemblies(self, outer: tuple[complex, complex, complex], turn: int) -> list[Pose]:
        """Every pose of the ternary link that closes the triad on the outer joints A, C, E."""
        a, c, e = outer
        ab, cd, ef = self.lengths
        bd = self.sides[0]
        local_f = self.corner_f(turn)
        theta = np.linspace(0.0, 2 * math.pi, _SWEEP + 1)

        def closing(angle, sign):
            """|F − E|² − EF² with D on its two circles, and the direction of BD (NaN where D has none)."""
            b = a + ab * np.exp(1j * angle)
            towards = c - b
            span2 = np.abs(towards) ** 2
            with np.errstate(divide="ignore", invalid="ignore"):
                along = 0.5 + 0.5 * (bd * bd - cd * cd) / span2
                height2 = bd * bd / span2 - along * along
                d = b + towards * (along + 1j * sign * np.sqrt(height2))
            direction = (d - b) / bd
            return np.abs(b + local_f * direction - e) ** 2 - ef * ef, direction

        from scipy.optimize import brentq  # imported here, as in _settle: only a triad needs it

        poses = []
        for sign in (1, -1):
            values, _ = closing(theta, sign)
            crossing = np.flatnonzero(np.isfinite(values[:-1]) & np.isfinite(values[1:]) & (values[:-1] * values[1:] <= 0))
            for k in crossing:
                if values[k] == 0 and k > 0:
                    continue  # already the upper end of the bracket before
                angle = brentq(lambda t, sign=sign: float(closing(np.array([t]), sign)[0][0]), theta[k], theta[k + 1],
                               xtol=1e-15)
                direction = complex(closing(np.array([angle]), sign)[1][0])
                poses.append(Pose(a + ab * complex(math.cos(angle), math.sin(angle)), math.atan2(direction.imag, direction.real)))
        return poses

    def with_branch(self, context: Context) -> TriadBranch:
        """The assembly nearest the sketch, its triangle turning the way the sketch's does.

        The candidates are the assemblies the sweep finds and the one Newton's method reaches
        from the sketch itself (the sweep may miss a root where D's circles just touch).
        """
        outer = tuple(complex(np.atleast_1d(context.point(name).r)[0]) for name in self.known_joints())
        near = dict(self.near)
        sketch = [near[name] for name in self.new_joints()]
        turn = 1 if ((sketch[1] - sketch[0]).conjugate() * (sketch[2] - sketch[0])).imag > 0 else -1
        candidates = self.assemblies(outer, turn)
        from_sketch = self._settle(Pose(sketch[0], math.atan2(*reversed(_xy(sketch[1] - sketch[0])))), outer, turn)
        if from_sketch is not None:
            candidates.append(from_sketch)
        if not candidates:
            context.fail_where(np.array([True]), lambda i, at: AssemblyError(self.joints[1], at, self.label, self._why_not(outer)))
        best = min(candidates, key=lambda pose: sum(abs(p - q) ** 2 for p, q in zip(self.corners(pose, turn), sketch)))
        return TriadBranch(turn, best)

    def _settle(self, guess: Pose, outer: tuple[complex, complex, complex], turn: int) -> Pose | None:
        """Newton's method (scipy's hybrid Powell) from ``guess``; None when it does not close the triad."""
        # Imported here, not with the module: scipy.optimize takes a third of a cold run's time to import, and
        # only a scene with a triad needs it.
        from scipy.optimize import root

        size = sum(self.lengths) + sum(self.sides)
        found = root(self._residual, np.array([guess.b.real, guess.b.imag, guess.psi]), args=(outer, turn),
                     jac=True, method="hybr", options={"xtol": 1e-14})
        if not np.all(np.abs(self._residual(found.x, outer, turn)[0]) <= _CONVERGED * size * size):
            return None
        return Pose(complex(found.x[0], found.x[1]), float(found.x[2]))

    def _why_not(self, outer, walking: bool = False) -> str:
        a, c, e = outer
        names = self.known_joints()
        bars = ", ".join(f"{outer}{inner} = {length:g} m" for (outer, inner, _), length in zip(self.arms(), self.lengths))
        where = (f"({bars}; {names[0]}–{names[1]} = {abs(c - a):.6g} m, "
                 f"{names[1]}–{names[2]} = {abs(e - c):.6g} m, {names[0]}–{names[2]} = {abs(e - a):.6g} m)")
        if walking:
            return (f"the ternary link {self.ternary} cannot follow its assembly from the position before: "
                    f"the triad reaches a limit position on the way {where}")
        return (f"neither the sketch (near) nor a sweep of {self.joints[1]} round its circle finds a pose of the "
                f"ternary link {self.ternary} that closes on the circles about {', '.join(names)} {where}")

    def _residual(self, q: np.ndarray, outer: tuple[complex, complex, complex], turn: int):
        """The closure and its Jacobian in q = (Bx, By, ψ)."""
        b, d, f = self.corners(Pose(complex(q[0], q[1]), float(q[2])), turn)
        rows, values = [], []
        for (centre, length), point in zip(zip(outer, self.lengths), (b, d, f)):
            arm = point - centre
            swing = 1j * (point - b)  # dpoint/dψ
            values.append(abs(arm) ** 2 - length * length)
            rows.append([2 * arm.real, 2 * arm.imag, 2 * (arm.conjugate() * swing).real])
        return np.array(values), np.array(rows)

    def _poses(self, context: Context, branch: TriadBranch) -> list[Pose]:
        """The pose at every position, walked out from the reference position both ways."""
        outer_all = [np.broadcast_to(np.asarray(context.point(name).r, dtype=complex), (context.count,))
                     for name in self.known_joints()]
        poses: list[Pose | None] = [None] * context.count
        start = context.start

        def settle(index: int, guess: Pose) -> Pose | None:
            return self._settle(guess, tuple(complex(part[index]) for part in outer_all), branch.turn)

        poses[start] = settle(start, branch.pose)
        stops = [start] if poses[start] is None else []
        for order in (range(start + 1, context.count), range(start - 1, -1, -1)):
            previous = start
            for index in order:
                if poses[previous] is None:
                    break
                poses[index] = settle(index, poses[previous])
                if poses[index] is None:
                    stops.append(index)
                previous = index
        if stops:
            first = min(stops, key=lambda index: abs(index - start))
            outer = tuple(complex(part[first]) for part in outer_all)
            why = self._why_not(outer, walking=first != start)
            context.fail_where(np.arange(context.count) == first,
                               lambda i, at: AssemblyError(self.joints[1], at, self.label, why))
        return poses  # type: ignore[return-value]

    def solve(self, context: Context, branch: TriadBranch) -> GroupMotion:
        poses = self._poses(context, branch)
        count = context.count
        b = np.array([pose.b for pose in poses])
        toward_d = np.exp(1j * np.array([pose.psi for pose in poses]))
        d = b + self.sides[0] * toward_d
        f = b + self.corner_f(branch.turn) * toward_d
        outer = [context.point(name) for name in self.known_joints()]
        inner = (b, d, f)
        arms = [point - o.r for point, o in zip(inner, outer)]
        swings = [1j * (point - b) for point in inner]
        # J·(vB, ω) = rhs, row k: armₖ·vB + (armₖ·i(Pₖ − B))·ω = armₖ·v(outer k); the same J for aB, ε.
        jacobian = np.empty((count, 3, 3))
        for k, (arm, swing) in enumerate(zip(arms, swings)):
            jacobian[:, k, 0] = arm.real
            jacobian[:, k, 1] = arm.imag
            jacobian[:, k, 2] = (np.conj(arm) * swing).real
        scale = max(self.sides)
        normalised = jacobian * np.array([1.0, 1.0, 1.0 / scale])
        sine = np.linalg.det(normalised) / np.prod(np.linalg.norm(normalised, axis=2), axis=1)
        bad = np.abs(sine) < SINGULAR_SINE
        if bad.any():
            context.singular_where(bad, lambda i, at: SingularPositionError(
                at, self.label, f"the triad is at a singular position (the binary links' lines meet in one point "
                                f"or are parallel; normalised Jacobian {abs(float(sine[i])):.1e})"))
        safe = np.where(bad[:, None, None], np.eye(3), jacobian)

        def dot(p, q):
            return (np.conj(p) * q).real

        velocity_rhs = np.stack([np.broadcast_to(dot(arm, o.v), (count,)) for arm, o in zip(arms, outer)], axis=1)
        x = np.linalg.solve(safe, velocity_rhs[..., None])[..., 0]
        x[bad] = np.nan
        v_b, omega = x[:, 0] + 1j * x[:, 1], x[:, 2]
        v_inner = [v_b + 1j * omega * (point - b) for point in inner]
        # Differentiated again: armₖ·a(Pₖ) = armₖ·a(outer k) − |v(Pₖ) − v(outer k)|², with aPₖ = aB + (iε − ω²)(Pₖ − B).
        acceleration_rhs = np.stack([
            np.broadcast_to(dot(arm, o.a) - np.abs(vp - o.v) ** 2 + omega ** 2 * dot(arm, point - b), (count,))
            for arm, o, vp, point in zip(arms, outer, v_inner, inner)], axis=1)
        y = np.linalg.solve(safe, acceleration_rhs[..., None])[..., 0]
        y[bad] = np.nan
        a_b, epsilon = y[:, 0] + 1j * y[:, 1], y[:, 2]
        whirl = 1j * epsilon - omega ** 2
        a_inner = [a_b + whirl * (point - b) for point in inner]
        points = {name: PointMotion(r, v, a) for name, r, v, a in zip(self.new_joints(), inner, v_inner, a_inner)}
        links = {self.ternary: LinkMotion(self.joints[1], toward_d, np.angle(toward_d), omega, epsilon)}
        for (outer_name, _, link), o, arm, length, vp, ap in zip(self.arms(), outer, arms, self.lengths, v_inner, a_inner):
            u = arm * (1.0 / length)
            links[link] = LinkMotion(outer_name, u, np.angle(u), _turning(arm, vp - o.v), _turning(arm, ap - o.a))
        return GroupMotion(points=points, links=links, conditioning=sine)

    # The plans: Assur's special point Σ, then F, then B and D by similarity.

    def special_pair(self, positions) -> tuple[int, int, int]:
        """The two binary links whose lines cross at the widest angle (Σ is their crossing), and the third."""
        arms = self.arms()

        def sine(i: int, j: int) -> float:
            u = positions[arms[i][1]] - positions[arms[i][0]]
            w = positions[arms[j][1]] - positions[arms[j][0]]
            return abs((u.conjugate() * w).imag) / (abs(u) * abs(w))

        i, j = max(((0, 1), (0, 2), (1, 2)), key=lambda pair: sine(*pair))
        return i, j, 3 - i - j

    def special_point(self, positions, size: float) -> tuple[str, complex, tuple[int, int, int]]:
        """Σ's name, where it lies (m), and which binary links it is built from."""
        i, j, k = self.special_pair(positions)
        arms = self.arms()
        lines = [Line(positions[arms[n][0]], positions[arms[n][1]] - positions[arms[n][0]], f"{arms[n][0]}{arms[n][1]}")
                 for n in (i, j)]
        return f"Σ{self.ternary}", cross_lines(lines[0], lines[1], size), (i, j, k)

    def _special_point_on(self, board: Builder) -> tuple[str, complex, tuple[int, int, int]]:
        """Σ on the board: where it lies is recorded with the plan, for the drawing and the readings."""
        name, where, order = self.special_point(board.positions, board.size)
        board.auxiliary[name] = where
        return name, where, order

    def construct_velocity(self, board: Builder) -> None:
        """vΣ = vA + vΣA (⊥ AB) = vC + vΣC (⊥ CD); vF = vΣ + vFΣ (⊥ ΣF) = vE + vFE (⊥ EF); b, d by similarity;
        then vBA and vDC read off."""
        positions = board.positions
        sigma_name, sigma_pos, (i, j, k) = self._special_point_on(board)
        arms = self.arms()
        (oi, ni, _), (oj, nj, _), (ok, nk, _) = arms[i], arms[j], arms[k]
        across_i, across_j = 1j * (positions[ni] - positions[oi]), 1j * (positions[nj] - positions[oj])
        image_i, image_j = board.images[oi], board.images[oj]
        value, angle = board.cross(Line(board.points[image_i], across_i, f"⊥{oi}{ni}"),
                                   Line(board.points[image_j], across_j, f"⊥{oj}{nj}"))
        sigma = board.mark(sigma_name.lower(), value)
        board.step(Step(
            equation=f"v{sigma_name} = v{oi} + v{sigma_name}{oi} = v{oj} + v{sigma_name}{oj}",
            vectors=(LaidVector(image_i, sigma, f"v{sigma_name}{oi}"), LaidVector(image_j, sigma, f"v{sigma_name}{oj}")),
            lines=(DrawnLine(image_i, across_i, LineMeaning("perpendicular", (oi, ni))),
                   DrawnLine(image_j, across_j, LineMeaning("perpendicular", (oj, nj)))),
            fixes=(sigma,), crossing_deg=angle))
        velocity_from_two_pivots(board, nk, positions[nk], (sigma_name, sigma, sigma_pos), (ok, board.images[ok], positions[ok]))
        self._by_similarity(board, sigma_pos, sigma, (i, j, k))
        for n in (i, j):  # ωa and ωb are read off the relative velocities that end at b and d
            outer, inner, _ = arms[n]
            board.step(Step(equation=f"v{inner} = v{outer} + v{inner}{outer}",
                            vectors=(LaidVector(board.images[outer], board.images[inner], f"v{inner}{outer}"),)))

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aΣ = aA + aBAⁿ + aΣBⁿ + aΣA^τ (⊥ AB) = aC + aDCⁿ + aΣDⁿ + aΣC^τ (⊥ CD);
        aF = aΣ + aFΣⁿ + aFΣ^τ (⊥ ΣF) = aE + aFEⁿ + aFE^τ (⊥ EF); b, d by similarity."""
        positions = board.positions
        sigma_name, sigma_pos, (i, j, k) = self._special_point_on(board)
        arms, t = self.arms(), self.ternary
        whirl_t = velocities.rates[t] ** 2
        ends, vectors, lines = [], [], []
        for n, prime in ((i, ""), (j, "′")):
            outer, inner, link = arms[n]
            image = board.images[outer]
            whirl = velocities.rates[link] ** 2
            arm_end = board.mark(f"n{link}", board.points[image] - whirl * (positions[inner] - positions[outer]))
            end = board.mark(f"n{t}{prime}", board.points[arm_end] - whirl_t * (sigma_pos - positions[inner]))
            across = 1j * (positions[inner] - positions[outer])
            ends.append((end, across, f"⊥{outer}{inner}"))
            vectors += [LaidVector(image, arm_end, f"a{inner}{outer}ⁿ"), LaidVector(arm_end, end, f"a{sigma_name}{inner}ⁿ")]
            lines.append(DrawnLine(end, across, LineMeaning("perpendicular", (outer, inner))))
        value, angle = board.cross(*(Line(board.points[end], across, label) for end, across, label in ends))
        sigma = board.mark(sigma_name.lower(), value)
        (oi, ni, _), (oj, nj, _), (ok, nk, lk) = arms[i], arms[j], arms[k]
        vectors += [LaidVector(ends[0][0], sigma, f"a{sigma_name}{oi}^τ"), LaidVector(ends[1][0], sigma, f"a{sigma_name}{oj}^τ")]
        board.step(Step(
            equation=(f"a{sigma_name} = a{oi} + a{ni}{oi}ⁿ + a{sigma_name}{ni}ⁿ + a{sigma_name}{oi}^τ"
                      f" = a{oj} + a{nj}{oj}ⁿ + a{sigma_name}{nj}ⁿ + a{sigma_name}{oj}^τ"),
            vectors=tuple(vectors), lines=tuple(lines), fixes=(*(end for end, _, _ in ends), sigma), crossing_deg=angle))
        crossed_from_two_pivots(board, nk, positions[nk], (sigma_name, sigma, sigma_pos, velocities.rates[t], f"n{t}″"),
                                (ok, board.images[ok], positions[ok], velocities.rates[lk], f"n{lk}"))
        self._by_similarity(board, sigma_pos, sigma, (i, j, k))
        for n in (i, j):  # εa and εb are read off the tangential parts that end at b and d
            outer, inner, link = arms[n]
            board.step(Step(
                equation=f"a{inner} = a{outer} + a{inner}{outer}ⁿ + a{inner}{outer}^τ",
                vectors=(LaidVector(board.images[outer], f"n{link}", f"a{inner}{outer}ⁿ"),
                         LaidVector(f"n{link}", board.images[inner], f"a{inner}{outer}^τ"))))

    def _by_similarity(self, board: Builder, sigma_pos: complex, sigma: str, order: tuple[int, int, int]) -> None:
        """The ternary link's image from σ and the third inner joint; the other two inner joints by similarity."""
        i, j, k = order
        arms, t, positions = self.arms(), self.ternary, board.positions
        outer_k, inner_k, link_k = arms[k]
        board.on_link(t, sigma_pos, sigma)
        board.on_link(t, positions[inner_k], board.images[inner_k])
        board.on_link(link_k, positions[outer_k], board.images[outer_k])
        board.on_link(link_k, positions[inner_k], board.images[inner_k])
        for n in (i, j):
            outer, inner, link = arms[n]
            pair = board.widest(t)
            letter = board.fix(inner, board.image_on(t, positions[inner]))
            board.similarity_step(letter, t, inner, pair)
            board.on_link(t, positions[inner], letter)
            board.on_link(link, positions[outer], board.images[outer])
            board.on_link(link, positions[inner], letter)


    # The forces: the group cut free, moments about each inner joint and about Assur's point.

    def construct_forces(self, board: ForceBoard) -> None:
        """Each outer reaction split along and across its binary link: the across parts from ΣM of each
        binary link about its inner joint; the third link's along part from ΣM of the whole group about Σ,
        through which the other two along parts pass; those two by crossing their lines on the polygon.
        The inner reactions are read off the polygon."""
        positions, t = board.positions, self.ternary
        sigma_name, sigma_pos, (i, j, k) = self.special_point(positions, max(abs(p) for p in positions.values()))
        board.add_centre(sigma_name, sigma_pos)
        arms = self.arms()
        names, across, along, tau = {}, {}, {}, {}
        for n, (outer, inner, link) in enumerate(arms):
            source = board.source_of(outer, link)
            names[n] = (f"R{source}{link}", source)
            bar = positions[inner] - positions[outer]
            across[n], along[n] = 1j * bar / abs(bar), bar / abs(bar)
            tau[n] = board.solve_moment(link, inner, f"{names[n][0]}τ", across[n], positions[outer])
        terms = []
        for n, (outer, _, _) in enumerate(arms):
            moment = float(cross(positions[outer] - sigma_pos, tau[n] * across[n]))
            if tau[n] != 0 and moment != 0:
                terms.append(Term(f"{names[n][0]}τ", moment, abs(moment) / abs(tau[n])))
        normal_k = board.solve_moment_of(self.links, sigma_name, f"{names[k][0]}n", along[k], positions[arms[k][0]],
                                         tuple(terms))
        ri, rj, rk = (names[n][0] for n in (i, j, k))
        li, lj, lk = (arms[n][2] for n in (i, j, k))
        polygon = PolygonBuilder(f"{ri}n + {ri}τ + ΣF{li} + {rk}τ + {rk}n + ΣF{lk} + ΣF{t} + {rj}τ + ΣF{lj} + {rj}n = 0")
        polygon.lay(f"{ri}τ", tau[i] * across[i])
        end_i = polygon.lay_all(board.loads_on(li))
        polygon.lay(f"{rk}τ", tau[k] * across[k])
        polygon.lay(f"{rk}n", normal_k * along[k])
        end_k = polygon.lay_all(board.loads_on(lk))
        end_t = polygon.lay_all(board.loads_on(t))
        polygon.lay(f"{rj}τ", tau[j] * across[j])
        polygon.lay_all(board.loads_on(lj))
        rj_along, ri_along = polygon.close(f"{rj}n", along[j], f"{ri}n", along[i])
        vertex = polygon.start - ri_along
        # The ternary link's pull on each binary link, read between the polygon's vertices (see the equation).
        on_binary = {i: polygon.inner(f"R{t}{li}", end_i, vertex), k: polygon.inner(f"R{t}{lk}", end_k, end_i),
                     j: polygon.inner(f"R{t}{lj}", vertex, end_t)}
        outer_force = {i: tau[i] * across[i] + ri_along, j: tau[j] * across[j] + rj_along, k: tau[k] * across[k] + normal_k * along[k]}
        for n in (i, j, k):
            outer, inner, link = arms[n]
            name, source = names[n]
            board.hand_back(board.react(name, outer, source, link, outer_force[n]))
        for n in (i, j, k):
            outer, inner, link = arms[n]
            board.react(f"R{link}{t}", inner, link, t, -on_binary[n])
        board.finish_group(self.label, self.links, polygon.record())


def _xy(z: complex) -> tuple[float, float]:
    return z.real, z.imag


def _turning(arm: Vector, relative: Vector) -> Scalar:
    """ω (or ε) of a link from a point's velocity (or tangential acceleration) relative to its pivot: (arm × rel)/|arm|²."""
    return (np.conj(arm) * relative).imag / np.abs(arm) ** 2
