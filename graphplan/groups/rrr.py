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
from ..forces import ForceBoard, PolygonBuilder
from ..geometry import Line
from ..kinematics import LinkMotion, PointMotion, Scalar, carried, norm2
from ..plans import Builder, DrawnLine, LaidVector, LineMeaning, Plan, Step
from ..reader import Table
from ..rounding import figures_above, figures_below
from .base import (
    Context,
    Group,
    GroupMotion,
    at_toggle,
    check_lines_cross,
    nearest_branch,
    read_branch,
    told_apart,
)

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

    def turning_round(self, before) -> str | None:
        """A–C's nearest and farthest over the turn ``before`` the group: B closes where |AB − BC| ≤ A–C ≤ AB + BC,
        so the crank turns round where both hold at those two, and each length's range for that, the other as
        given."""
        least, most, near, far = self._span_of_ac(before)
        ab, bc = self.lengths
        if ab + bc >= most and abs(ab - bc) <= least:
            return None
        a, b, c = self.joints
        told = (f"over the turn {a}–{c} runs from {least:.6g} m (at {near}) to {most:.6g} m (at {far}), so the crank "
                f"turns round only where {a}{b} + {b}{c} > {most:.6g} m and |{a}{b} − {b}{c}| < {least:.6g} m")
        return self._ranges_told(told, lambda other: (max(most - other, other - least), other + least))

    def nowhere(self, before) -> str | None:
        """Where the crank assembles at no angle: A–C's nearest and farthest over the angles ``before`` the group
        assembles at; B closes at some angle where [|AB − BC|, AB + BC] reaches into them, and each length's range
        for that, the other as given."""
        least, most, near, far = self._span_of_ac(before)
        ab, bc = self.lengths
        if ab + bc >= least and abs(ab - bc) <= most:
            return None
        a, b, c = self.joints
        told = (f"{a}–{c} runs from {least:.6g} m (at {near}) to {most:.6g} m (at {far}), so B closes at some angle "
                f"only where {a}{b} + {b}{c} ≥ {least:.6g} m and |{a}{b} − {b}{c}| ≤ {most:.6g} m")
        return self._ranges_told(told, lambda other: (max(least - other, other - most), most + other))

    def _span_of_ac(self, before) -> tuple[float, float, str, str]:
        """A–C's nearest and farthest over ``before``, and the driver's values where they are, in words."""
        a, _, c = self.joints
        spans = np.abs(before.points[a].r - before.points[c].r)
        nearest, farthest = int(np.argmin(spans)), int(np.argmax(spans))
        near, far = (before.mechanism.driver.describe(float(before.driver[index])) for index in (nearest, farthest))
        return float(spans[nearest]), float(spans[farthest]), near, far

    def _ranges_told(self, told: str, bounds) -> str:
        """``told`` with each length's range, the other as given: from ``bounds(other)``'s first to its second,
        each rounded to four figures inward (under the second where the first is none)."""
        a, b, c = self.joints
        ab, bc = self.lengths
        ranges = []
        for k, (name, other, other_name) in enumerate(((f"{a}{b}", bc, f"{b}{c}"), (f"{b}{c}", ab, f"{a}{b}"))):
            bound, high = bounds(other)
            high = figures_below(high)
            # Where A–C never varies from the other length, any length short of twice it closes.
            span = f"under {high:.6g} m" if bound <= 0 else f"from {figures_above(bound):.6g} m to {high:.6g} m"
            if bound <= 0 or figures_above(bound) < high:
                ranges.append(f"{self.where}.lengths[{k}] ({name}) {span} with {other_name} as given")
        return f"{told}: {', or '.join(ranges)}" if ranges else told

    def fixed_points(self) -> dict[int, tuple[str, ...]]:
        a, b, c = self.joints
        return {self.links[0]: (a, b), self.links[1]: (c, b)}

    def revolutes(self) -> tuple[tuple[str, int, int | None], ...]:
        a, b, c = self.joints
        return ((a, self.links[0], None), (b, self.links[1], self.links[0]), (c, self.links[1], None))

    def _candidates(self, context: Context, branch: int):
        """A, C, then B, AB and AB × CB on ``branch``."""
        a_name, b_name, c_name = self.joints
        ab, bc = self.lengths
        a, c = context.point(a_name), context.point(c_name)
        d = np.asarray(c.r - a.r)
        d2 = norm2(d)
        # x: where the foot of B falls along A→C, h²: B's squared height over AC,
        # both as fractions of |AC| (law of cosines, no trigonometry needed).
        with np.errstate(divide="ignore", invalid="ignore"):
            inverse = 1.0 / d2
            x = 0.5 * (ab * ab - bc * bc) * inverse
            x += 0.5
            h2 = ab * ab * inverse
            h2 -= x * x

        def reason(i: int, at: str) -> AssemblyError:
            span = float(np.sqrt(np.atleast_1d(d2)[i]))
            if span == 0:
                why = f"{a_name} and {c_name} coincide, so nothing fixes where {b_name} lies"
            elif span > ab + bc:
                far, reach = told_apart(span, ab + bc)
                why = f"{a_name}–{c_name} = {far} m > {a_name}{b_name} + {b_name}{c_name} = {reach} m"
            else:
                reach, near = told_apart(abs(ab - bc), span)
                why = f"{a_name}–{c_name} = {near} m < |{a_name}{b_name} − {b_name}{c_name}| = {reach} m"
            return AssemblyError(b_name, at, self.label, why)

        # x's rounding is of its 0.5, x²'s then of x: the scale is 1, or the squares where AB outreaches AC.
        with np.errstate(invalid="ignore"):  # A on C: inf − inf, refused below
            h2 = at_toggle(h2, np.maximum(1.0, ab * ab * inverse))
        if not np.min(h2) >= 0:  # NaN fails too
            context.fail_where(np.atleast_1d(~(h2 >= 0)), reason)
        # AB = AC·(x + ih), built in place: h straight into its imaginary part, then turned and scaled by AC.
        arm = np.empty(d.shape, dtype=complex)
        arm.real = x
        np.sqrt(h2, out=arm.imag)
        if branch < 0:
            np.negative(arm.imag, out=arm.imag)
        det = d2 * arm.imag  # AB × CB = |AC|²·h, for CB = AB − AC = AC·(x − 1 + ih)
        arm *= d
        return a, c, a.r + arm, arm, det

    def with_branch(self, context: Context) -> int:
        if self.assembly is not None:
            return _BRANCHES[self.assembly]
        assert self.near is not None
        return nearest_branch({s: self._candidates(context, s)[2] for s in (1, -1)}, self.near)

    def solve(self, context: Context, branch: int) -> GroupMotion:
        a, c, b_r, ab_vec, det = self._candidates(context, branch)
        cb_vec = b_r - c.r
        ab_length, cb_length = self.lengths
        # In contiguous real parts from here: a real array times a complex one costs a complex product.
        abx, aby, cbx, cby = (np.asarray(part, order="C") for part in (ab_vec.real, ab_vec.imag, cb_vec.real, cb_vec.imag))
        sine = det * (1.0 / (ab_length * cb_length))
        check_lines_cross(context, self, sine, f"links {self.links[0]} and {self.links[1]} lie in one line (a toggle)")
        with np.errstate(divide="ignore"):
            inverse = 1.0 / det
        w = c.v - a.v
        omega_a, omega_b = _two_lines(w.real, w.imag, abx, aby, cbx, cby, inverse)
        whirl_a, whirl_b = omega_a * omega_a, omega_b * omega_b
        # w = aC − aA + ωa²·AB − ωb²·CB, in parts, each summed in place
        wx = whirl_a * abx
        wx -= whirl_b * cbx
        wx += c.a.real
        wx -= a.a.real
        wy = whirl_a * aby
        wy -= whirl_b * cby
        wy += c.a.imag
        wy -= a.a.imag
        epsilon_a, epsilon_b = _two_lines(wx, wy, abx, aby, cbx, cby, inverse)
        a_name, b_name, c_name = self.joints
        # Scaled by reciprocals: dividing a complex array by a real number is a complex division.
        link_a = LinkMotion(a_name, ab_vec * (1.0 / ab_length), np.arctan2(aby, abx), omega_a, epsilon_a)
        link_b = LinkMotion(c_name, cb_vec * (1.0 / cb_length), np.arctan2(cby, cbx), omega_b, epsilon_b)
        # B rides on link a at AB from A (link a's turning factors then serve its named points too).
        return GroupMotion(points={b_name: PointMotion(b_r, *carried(a, link_a, ab_vec))},
                           links={self.links[0]: link_a, self.links[1]: link_b}, conditioning=sine)

    # The plans: the same equations, solved by crossing lines of action.

    def construct_velocity(self, board: Builder) -> None:
        """vB = vA + vBA (⊥ AB) = vC + vBC (⊥ CB): lines through a and c, crossed at b."""
        a_name, b_name, c_name = self.joints
        a_pos, b_pos, c_pos = (board.positions[n] for n in self.joints)
        a, c = board.images[a_name], board.images[c_name]
        b = velocity_from_two_pivots(board, b_name, b_pos, (a_name, a, a_pos), (c_name, c, c_pos))
        board.on_link(self.links[0], a_pos, a)
        board.on_link(self.links[0], b_pos, b)
        board.on_link(self.links[1], c_pos, c)
        board.on_link(self.links[1], b_pos, b)

    def construct_acceleration(self, board: Builder, velocities: Plan) -> None:
        """aB = aA + aBA^n + aBA^τ = aC + aBC^n + aBC^τ, the normal parts ω²·l toward A and C."""
        a_name, b_name, c_name = self.joints
        a_pos, b_pos, c_pos = (board.positions[n] for n in self.joints)
        a, c = board.images[a_name], board.images[c_name]
        omega_a, omega_b = velocities.rates[self.links[0]], velocities.rates[self.links[1]]
        b = crossed_from_two_pivots(board, b_name, b_pos, (a_name, a, a_pos, omega_a, f"n{self.links[0]}"),
                                    (c_name, c, c_pos, omega_b, f"n{self.links[1]}"))
        for link, first, letter in ((self.links[0], a_pos, a), (self.links[1], c_pos, c)):
            board.on_link(link, first, letter)
            board.on_link(link, b_pos, b)

    # The forces: the group cut free, as drawn.

    def construct_forces(self, board: ForceBoard) -> None:
        """Outer reactions split along and across their links: the across parts from ΣMB of each link,
        the along parts by crossing their lines on the group's polygon, the inner reaction read off it."""

        a_name, b_name, c_name = self.joints
        la, lb = self.links
        a, b, c = (board.positions[name] for name in self.joints)
        pa, pc = board.source_of(a_name, la), board.source_of(c_name, lb)
        across_a, across_c = 1j * (b - a) / abs(b - a), 1j * (b - c) / abs(b - c)
        ra, rc, inner = f"R{pa}{la}", f"R{pc}{lb}", f"R{lb}{la}"
        ta = board.solve_moment(la, b_name, f"{ra}τ", across_a, a)
        tc = board.solve_moment(lb, b_name, f"{rc}τ", across_c, c)
        polygon = PolygonBuilder(f"{ra}τ + ΣF{la} + ΣF{lb} + {rc}τ + {rc}n + {ra}n = 0")
        polygon.lay(f"{ra}τ", ta * across_a)
        end_of_a = polygon.lay_all(board.loads_on(la))
        polygon.lay_all(board.loads_on(lb))
        polygon.lay(f"{rc}τ", tc * across_c)
        rc_along, ra_along = polygon.close(f"{rc}n", b - c, f"{ra}n", b - a)
        vertex = polygon.start - ra_along
        r_ba = polygon.inner(inner, end_of_a, vertex)
        board.hand_back(board.react(ra, a_name, pa, la, ta * across_a + ra_along))
        board.hand_back(board.react(rc, c_name, pc, lb, tc * across_c + rc_along))
        board.react(f"R{la}{lb}", b_name, la, lb, -r_ba)
        board.finish_group(self.label, self.links, polygon.record())


def velocity_from_two_pivots(board: Builder, point: str, where: complex,
                             first: tuple[str, str, complex], second: tuple[str, str, complex]) -> str:
    """vP = vA + vPA (⊥ AP) = vC + vPC (⊥ CP) on the velocity plan: P's image, fixed and returned.

    Each pivot is (name, plan letter, position).
    """
    lines = [Line(board.points[image], 1j * (where - position), f"⊥{name}{point}") for name, image, position in (first, second)]
    value, angle = board.cross(*lines)
    fixed = board.fix(point, value)
    (a_name, a, _), (c_name, c, _) = first, second
    board.step(Step(
        equation=f"v{point} = v{a_name} + v{point}{a_name} = v{c_name} + v{point}{c_name}",
        vectors=(LaidVector(a, fixed, f"v{point}{a_name}"), LaidVector(c, fixed, f"v{point}{c_name}"),
                 LaidVector("p", fixed, f"v{point}")),
        lines=tuple(DrawnLine(image, line.direction, LineMeaning("perpendicular", (name, point)))
                    for line, (name, image, _) in zip(lines, (first, second))),
        fixes=(fixed,), crossing_deg=angle))
    return fixed


def crossed_from_two_pivots(board: Builder, point: str, where: complex,
                            first: tuple[str, str, complex, float, str], second: tuple[str, str, complex, float, str]) -> str:
    """aP = aA + aPAⁿ + aPA^τ = aC + aPCⁿ + aPC^τ on the acceleration plan: P's image, fixed and returned.

    Each pivot is (name, plan letter, position, ω of the arm to P, letter of the normal part's end);
    the normal parts ω²·l point from P to the pivots, the tangential lines are square to the arms.
    """
    normals, lines = [], []
    for name, image, position, omega, letter in (first, second):
        normal = board.mark(letter, board.points[image] - omega**2 * (where - position))
        normals.append(normal)
        lines.append(Line(board.points[normal], 1j * (where - position), f"⊥{name}{point}"))
    value, angle = board.cross(*lines)
    fixed = board.fix(point, value)
    (a_name, a, _, _, _), (c_name, c, _, _, _) = first, second
    normal_a, normal_c = normals
    board.step(Step(
        equation=(f"a{point} = a{a_name} + a{point}{a_name}ⁿ + a{point}{a_name}^τ"
                  f" = a{c_name} + a{point}{c_name}ⁿ + a{point}{c_name}^τ"),
        vectors=(LaidVector(a, normal_a, f"a{point}{a_name}ⁿ"), LaidVector(normal_a, fixed, f"a{point}{a_name}^τ"),
                 LaidVector(c, normal_c, f"a{point}{c_name}ⁿ"), LaidVector(normal_c, fixed, f"a{point}{c_name}^τ"),
                 LaidVector("p", fixed, f"a{point}")),
        lines=tuple(DrawnLine(normal, line.direction, LineMeaning("perpendicular", (name, point)))
                    for normal, line, (name, *_) in zip(normals, lines, (first, second))),
        fixes=(normal_a, normal_c, fixed), crossing_deg=angle))
    return fixed


def _two_lines(wx: Scalar, wy: Scalar, abx: Scalar, aby: Scalar, cbx: Scalar, cby: Scalar,
               inverse: Scalar) -> tuple[Scalar, Scalar]:
    """x1, x2 of ``x1·(i·AB) − x2·(i·CB) = w``, given ``inverse`` = 1/(AB × CB).

    Dotted with CB the x2 term drops out, dotted with AB the x1 term:
    x1 = w·CB/(AB × CB), x2 = w·AB/(AB × CB) (the two-line equation of the
    module docstring, solved in real parts).
    """
    x1 = wx * cbx
    x1 += wy * cby
    x1 *= inverse
    x2 = wx * abx
    x2 += wy * aby
    x2 *= inverse
    return x1, x2
