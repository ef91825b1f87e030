"""An independent 50-digit reference solution of a scene's kinematics (mpmath).

Nothing here calls graphplan's solver for the answer.  The closure equation of
every group is written afresh, generically from the mechanism's structure (the
scene's groups, guides and named points, in the order :func:`graphplan.mechanism.build`
checked), as one complex equation in a class-II group's two unknowns (two, one per loop, in a
triad's four):

========  =======================  =====================================================
kind      unknowns                 closure (G, u: a guide's point and direction)
========  =======================  =====================================================
RRR       θa, θb                   A + AB·e^{iθa} − C − CB·e^{iθb} = 0
RRP       θa, s                    A + AB·e^{iθa} − (G + s·u) = 0
RPR       θ (lever), s             A − C − (s + i·e)·e^{iθ} = 0
PRP       s1, s2                   G1 + (s1 + i·o1)·u1 − G2 − (s2 + i·o2)·u2 = 0
RPP       s_b, s_a                 A − G − s_b·u − s_a·u·e^{i·angle} = 0
triad     θa, θb, θc, ψ            A + AB·e^{iθa} + BD·e^{iψ} − C − CD·e^{iθb} = 0,
                                   A + AB·e^{iθa} + BF·e^{iψ}·e^{±iβ} − E − EF·e^{iθc} = 0
========  =======================  =====================================================

Every quantity is carried as a *jet* (value, first and second time derivative) so that
differentiating a closure equation is done by the arithmetic itself:

* positions: :func:`mpmath.findroot` (Newton, the Jacobian taken from the jets) on the
  value part, started from graphplan's double-precision answer, which only picks the
  branch;
* velocities: the first-derivative part of the closure is J·q̇ + b₁ = 0, solved with
  :func:`mpmath.lu_solve`;
* accelerations: the second-derivative part is J·q̈ + b₂(q̇) = 0, solved the same way.

Named points are placed by their definition (``from`` + (at + i·offset)·direction) at
every position, not carried from a reference position.  An RPR's lever point under
the block (``A4``) is a material point of the lever at the instant: its velocity and
acceleration are the lever's rigid motion from C.

``mp.dps`` is raised to 50 only inside :func:`solve_reference` (``mp.workdps``).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from mpmath import mp, mpc, mpf

from .mechanism import build
from .motion import reference_at, solve
from .positions import make_positions

DPS = 50


# --- jets: a quantity with its first and second time derivative -------------------------------

class Jet:
    """x, ẋ, ẍ of one real or complex quantity, with the product and chain rules built in."""

    __slots__ = ("d0", "d1", "d2")

    def __init__(self, d0, d1=0, d2=0) -> None:
        self.d0, self.d1, self.d2 = d0, d1, d2

    @staticmethod
    def of(value) -> Jet:
        return value if isinstance(value, Jet) else Jet(value)

    def __add__(self, other):
        other = Jet.of(other)
        return Jet(self.d0 + other.d0, self.d1 + other.d1, self.d2 + other.d2)

    __radd__ = __add__

    def __neg__(self):
        return Jet(-self.d0, -self.d1, -self.d2)

    def __sub__(self, other):
        return self + (-Jet.of(other))

    def __rsub__(self, other):
        return Jet.of(other) - self

    def __mul__(self, other):
        other = Jet.of(other)
        return Jet(self.d0 * other.d0,
                   self.d1 * other.d0 + self.d0 * other.d1,
                   self.d2 * other.d0 + 2 * self.d1 * other.d1 + self.d0 * other.d2)

    __rmul__ = __mul__

    def __truediv__(self, other):
        other = Jet.of(other)
        q0 = self.d0 / other.d0
        q1 = (self.d1 - q0 * other.d1) / other.d0
        q2 = (self.d2 - 2 * q1 * other.d1 - q0 * other.d2) / other.d0
        return Jet(q0, q1, q2)

    def conj(self) -> Jet:
        return Jet(mp.conj(self.d0), mp.conj(self.d1), mp.conj(self.d2))

    @property
    def real(self) -> Jet:
        return Jet(mp.re(self.d0), mp.re(self.d1), mp.re(self.d2))

    @property
    def imag(self) -> Jet:
        return Jet(mp.im(self.d0), mp.im(self.d1), mp.im(self.d2))


def expi(theta: Jet) -> Jet:
    """e^{iθ} of a real angle jet: (iθ̇)·e^{iθ}, then (iθ̈ − θ̇²)·e^{iθ}."""
    # cos + i·sin rather than mp.expj, which raises ComplexResult on a real angle in mpmath 1.4.
    e = mp.mpc(mp.cos(theta.d0), mp.sin(theta.d0))
    return Jet(e, 1j * theta.d1 * e, (1j * theta.d2 - theta.d1 ** 2) * e)


def sqrt(x: Jet) -> Jet:
    """√x of a positive real jet."""
    s0 = mp.sqrt(x.d0)
    s1 = x.d1 / (2 * s0)
    return Jet(s0, s1, (x.d2 - 2 * s1 * s1) / (2 * s0))


def magnitude(z: Jet) -> Jet:
    return sqrt((z * z.conj()).real)


def unit_of(z: Jet) -> Jet:
    return z / magnitude(z)


def cross(a: Jet, b: Jet) -> Jet:
    """a × b (z component) of complex jets."""
    return (a.conj() * b).imag


def dot(a: Jet, b: Jet) -> Jet:
    return (a.conj() * b).real


# --- the reference of one scene --------------------------------------------------------------

@dataclass(frozen=True)
class Instant:
    """The 50-digit solution at one driver position.

    ``points`` maps a point to (r, v, a) as mpc; ``links`` a link to (angle, ω, ε) as mpf;
    ``residuals`` the largest |closure| of each group for positions, velocities and
    accelerations (value, first and second derivative part).
    """

    driver: mpf
    points: Mapping[str, tuple[mpc, mpc, mpc]]
    links: Mapping[int, tuple[mpf, mpf, mpf]]
    residuals: Mapping[str, tuple[mpf, mpf, mpf]]


@dataclass(frozen=True)
class ReferenceMotion:
    """The reference at every position, with float arrays shaped as graphplan's ``Motion`` gives them."""

    instants: tuple[Instant, ...]

    @property
    def count(self) -> int:
        return len(self.instants)

    def point(self, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """r, v, a of ``name`` as ``(N,)`` complex arrays (rounded to double)."""
        rows = [instant.points[name] for instant in self.instants]
        return tuple(np.array([complex(row[k]) for row in rows]) for k in range(3))  # type: ignore[return-value]

    def link(self, number: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        rows = [instant.links[number] for instant in self.instants]
        return tuple(np.array([float(row[k]) for row in rows]) for k in range(3))  # type: ignore[return-value]

    @property
    def point_names(self) -> tuple[str, ...]:
        return tuple(self.instants[0].points)

    @property
    def link_numbers(self) -> tuple[int, ...]:
        return tuple(self.instants[0].links)


class ReferenceSolutionError(ArithmeticError):
    """A position where the 50-digit solution does not exist (no assembly) or is not unique (a toggle)."""


def _guide(scene, guide, points: Mapping[str, Jet], angles: Mapping[int, Jet]) -> tuple[Jet, Jet, Jet]:
    """A guide's point, unit direction and direction angle as jets."""
    if guide.line is not None:
        guide = scene.frame_lines[guide.line]
    if guide.link is None or guide.link == scene.frame_link:
        if isinstance(guide.through, str):
            origin = points[guide.through]
        else:
            origin = Jet(mpc(mpf(guide.through[0]), mpf(guide.through[1])))
        angle = Jet(mpf(guide.angle))
        return origin, expi(angle), angle
    angle = angles[guide.link] + mpf(guide.angle)
    return points[guide.through], expi(angle), angle


def _closure(group, scene, points, angles) -> tuple[Callable, Callable]:
    """The group's closure residual F(q1, q2) (a complex jet) and its outputs from q (points, link angles)."""
    kind = group.kind
    if kind == "RRR":
        a_name, b_name, c_name = group.joints
        ab, cb = (mpf(x) for x in group.lengths)

        def residual(q1, q2):
            return points[a_name] + ab * expi(q1) - points[c_name] - cb * expi(q2)

        def outputs(q1, q2):
            return {b_name: points[a_name] + ab * expi(q1)}, {group.links[0]: q1, group.links[1]: q2}
    elif kind == "RRP":
        a_name, b_name = group.joints
        length = mpf(group.length)

        def residual(q1, q2):
            origin, u, _ = _guide(scene, group.guide, points, angles)
            return points[a_name] + length * expi(q1) - origin - q2 * u

        def outputs(q1, q2):
            _, _, guide_angle = _guide(scene, group.guide, points, angles)
            return {b_name: points[a_name] + length * expi(q1)}, {group.links[0]: q1, group.links[1]: guide_angle}
    elif kind == "RPR":
        a_name, c_name = group.joints
        offset = mpf(group.offset)

        def residual(q1, q2):
            return points[a_name] - points[c_name] - (q2 + 1j * offset) * expi(q1)

        def outputs(q1, q2):
            return {}, {group.links[0]: q1, group.links[1]: q1}
    elif kind == "PRP":
        (b_name,) = group.joints
        o1, o2 = (mpf(x) for x in group.offsets)

        def residual(q1, q2):
            (g1, u1, _), (g2, u2, _) = (_guide(scene, g, points, angles) for g in group.guide_pair)
            return g1 + (q1 + 1j * o1) * u1 - g2 - (q2 + 1j * o2) * u2

        def outputs(q1, q2):
            (g1, u1, t1), (_, _, t2) = (_guide(scene, g, points, angles) for g in group.guide_pair)
            return {b_name: g1 + (q1 + 1j * o1) * u1}, {group.links[0]: t1, group.links[1]: t2}
    elif kind == "RPP":
        a_name, b_name = group.joints
        slot = mp.expj(mpf(group.angle))

        def residual(q1, q2):
            origin, u, _ = _guide(scene, group.guide, points, angles)
            return points[a_name] - origin - q1 * u - q2 * (u * slot)

        def outputs(q1, q2):
            origin, u, guide_angle = _guide(scene, group.guide, points, angles)
            return {b_name: origin + q1 * u}, {group.links[0]: guide_angle + mpf(group.angle), group.links[1]: guide_angle}
    elif kind == "triad":
        b_name, d_name, f_name = group.inner_joints
        bd = mpf(group.sides[0])
        corner_f = _corner_f(group, points)
        la, lb, lc, lt = group.links

        def inner(leg, q, psi):
            """The inner joint of a leg: its binary link at angle q, the slider s = q along its guide, or the corner
            s = q back along the slot from the block's pin."""
            if group.leg_guides[leg] is not None:
                origin, u, _ = _guide(scene, group.leg_guides[leg], points, angles)
                return origin + q * u
            if group.leg_slots[leg] is not None:
                return points[group.joints[2 * leg]] - q * expi(psi + mpf(group.leg_slots[leg]))
            return points[group.joints[2 * leg]] + mpf(group.lengths[leg]) * expi(q)

        def residual(qa, qb, qc, psi):
            b = inner(0, qa, psi)
            return b + bd * expi(psi) - inner(1, qb, psi), b + corner_f * expi(psi) - inner(2, qc, psi)

        def outputs(qa, qb, qc, psi):
            turned = {la: qa, lb: qb, lc: qc, lt: psi}
            for leg in group.sliding_legs:
                turned[group.links[leg]] = _guide(scene, group.leg_guides[leg], points, angles)[2]
            found = {b_name: inner(0, qa, psi), d_name: inner(1, qb, psi), f_name: inner(2, qc, psi)}
            for leg in group.slotted_legs:  # the block turns with the slot; the point under its pin is put after
                turned[group.links[leg]] = psi + mpf(group.leg_slots[leg])
                found[group.coincident(leg)] = points[group.joints[2 * leg]]
            return found, turned
    else:  # pragma: no cover - a new group kind needs its closure written here
        raise NotImplementedError(f"no reference closure for {kind} groups")
    return residual, outputs


def _corner_f(group, points) -> mpc:
    """F in the ternary link's own frame (B at the origin, D along +x), at 50 digits.

    Which side of BD it lies on is the side the sketch (``near``) puts it, as graphplan chooses.
    """
    bd, df, fb = (mpf(x) for x in group.sides)
    near = dict(group.near)
    b, d, f = (near[name] for name in group.inner_joints)
    turn = 1 if ((d - b).conjugate() * (f - b)).imag > 0 else -1
    cosine = (bd * bd + fb * fb - df * df) / (2 * bd * fb)
    return fb * mpc(cosine, turn * mp.sqrt(1 - cosine * cosine))


def _first_guess(group, scene, points, angles, near: Mapping[str, complex], near_angles: Mapping[int, float]):
    """The unknowns from graphplan's double-precision positions: they only pick the branch."""
    def value(name: str) -> mpc:
        return mpc(near[name])

    kind = group.kind
    if kind in ("RRR", "RRP"):
        a_name, b_name = group.joints[0], group.joints[1]
        theta_a = mp.arg(value(b_name) - value(a_name))
        if kind == "RRR":
            return theta_a, mp.arg(value(b_name) - value(group.joints[2]))
        origin, u, _ = _guide(scene, group.guide, points, angles)
        return theta_a, mp.re((value(b_name) - origin.d0) * mp.conj(u.d0))
    if kind == "RPR":
        a_name, c_name = group.joints
        theta = mpf(near_angles[group.links[1]])
        return theta, mp.re((points[a_name].d0 - points[c_name].d0) * mp.conj(mp.expj(theta)))
    if kind == "PRP":
        b = value(group.joints[0])
        return tuple(mp.re((b - g.d0) * mp.conj(u.d0))
                     for g, u, _ in (_guide(scene, guide, points, angles) for guide in group.guide_pair))
    if kind == "triad":
        a, b, c, d, e, f = (value(name) for name in group.joints)
        legs = [mp.arg(b - a), mp.arg(d - c), mp.arg(f - e)]
        for leg in group.sliding_legs:
            origin, u, _ = _guide(scene, group.leg_guides[leg], points, angles)
            legs[leg] = mp.re((value(group.inner_joints[leg]) - origin.d0) * mp.conj(u.d0))
        for leg in group.slotted_legs:  # how far the corner lies back along the slot from the block's pin
            slot = mp.expj(mp.arg(d - b) + mpf(group.leg_slots[leg]))
            legs[leg] = mp.re((points[group.joints[2 * leg]].d0 - value(group.inner_joints[leg])) * mp.conj(slot))
        return (*legs, mp.arg(d - b))
    a_name, b_name = group.joints
    origin, u, _ = _guide(scene, group.guide, points, angles)
    slot = u.d0 * mp.expj(mpf(group.angle))
    return (mp.re((value(b_name) - origin.d0) * mp.conj(u.d0)),
            mp.re((points[a_name].d0 - value(b_name)) * mp.conj(slot)))


def _values_only(jets: Mapping) -> dict:
    return {key: Jet(jet.d0) for key, jet in jets.items()}


def _solve_group(group, scene, points, angles, guess) -> tuple[tuple[Jet, ...], tuple[mpf, mpf, mpf]]:
    """The group's unknowns as jets: Newton for values, then two linear solves for rates.

    A class-II group has one complex closure in two unknowns; a triad two (one per loop) in four.
    """
    still_points, still_angles = _values_only(points), _values_only(angles)
    still, _ = _closure(group, scene, still_points, still_angles)
    moving, _ = _closure(group, scene, points, angles)
    count = len(guess)

    def loops(function, unknowns) -> tuple[Jet, ...]:
        found = function(*unknowns)
        return found if isinstance(found, tuple) else (found,)

    def parts(values) -> list:
        return [part for z in values for part in (mp.re(z), mp.im(z))]

    def f(*x):
        return parts(z.d0 for z in loops(still, [Jet(value) for value in x]))

    def jacobian(*x):
        columns = [parts(z.d1 for z in loops(still, [Jet(value, 1 if k == column else 0) for k, value in enumerate(x)]))
                   for column in range(count)]
        return mp.matrix([[column[row] for column in columns] for row in range(count)])

    try:
        # Near a toggle the root is nearly double and Newton slows to halving its error each step.
        root = mp.findroot(f, guess, solver="mdnewton", J=jacobian, maxsteps=400)
    except (ValueError, ZeroDivisionError) as error:
        raise ReferenceSolutionError(f"group {group.label}: no 50-digit position ({error})") from None
    q0 = [root[k] for k in range(count)]
    J = jacobian(*q0)
    if abs(mp.det(J)) < mp.mpf(10) ** (-(DPS - 10)):
        raise ReferenceSolutionError(f"group {group.label}: the closure's Jacobian is singular (a toggle)")
    first = parts(z.d1 for z in loops(moving, [Jet(value) for value in q0]))
    q1 = mp.lu_solve(J, -mp.matrix(first))
    second = parts(z.d2 for z in loops(moving, [Jet(value, q1[k]) for k, value in enumerate(q0)]))
    q2 = mp.lu_solve(J, -mp.matrix(second))
    unknowns = tuple(Jet(q0[k], q1[k], q2[k]) for k in range(count))
    closed = loops(moving, unknowns)
    return unknowns, tuple(max(abs(getattr(z, part)) for z in closed) for part in ("d0", "d1", "d2"))  # type: ignore[return-value]


def _place(spec, mechanism, points, angles, slides: Mapping[str, complex]) -> Jet:
    """A named point by its definition: from + (at + i·offset)·direction; toward a slider, the direction is the
    slide's, in the sense toward the slider at the reference position (``slides``, :func:`toward_slider`)."""
    start = points[spec.start]
    if spec.toward in mechanism.fixed_on.get(spec.link, ()):
        direction = unit_of(points[spec.toward] - start)
    else:
        direction = expi(angles[spec.link]) * mpc(slides[spec.name])
    return start + (mpf(spec.at) + 1j * mpf(spec.offset)) * direction


def _instant(mechanism, value: float, near: Mapping[str, complex], near_angles: Mapping[int, float],
             slides: Mapping[str, complex]) -> Instant:
    scene = mechanism.scene
    driver = mechanism.driver
    points: dict[str, Jet] = {name: Jet(mpc(z.real, z.imag)) for name, z in scene.frame_points.items()}
    angles: dict[int, Jet] = {scene.frame_link: Jet(mpf(0))}
    residuals: dict[str, tuple[mpf, mpf, mpf]] = {}
    if driver.kind == "crank":
        phi = Jet(mpf(value), mpf(driver.omega), mpf(driver.epsilon))
        points[driver.joint] = points[driver.pivot] + mpf(driver.length) * expi(phi)
        angles[driver.link] = phi
    else:
        origin, u, guide_angle = _guide(scene, driver.guide, points, angles)
        s = Jet(mpf(value), mpf(driver.velocity), mpf(driver.acceleration))
        points[driver.joint] = origin + s * u
        angles[driver.link] = guide_angle
    under_pins = []
    for step, unit in enumerate(mechanism.units):
        if step > 0:
            group = unit.solver
            guess = _first_guess(group, scene, points, angles, near, near_angles)
            unknowns, residuals[group.label] = _solve_group(group, scene, points, angles, guess)
            _, outputs = _closure(group, scene, points, angles)
            found, turned = outputs(*unknowns)
            points.update(found)
            angles.update(turned)
            under_pins += group.coincident_points()
        for spec in unit.points:
            points[spec.name] = _place(spec, mechanism, points, angles, slides)
    result = {name: (jet.d0, jet.d1, jet.d2) for name, jet in points.items()}
    for name, on, pivot, lever in under_pins:
        # The link's material point under the block: rigid with the link.
        arm = points[on].d0 - points[pivot].d0
        omega, epsilon = angles[lever].d1, angles[lever].d2
        result[name] = (points[on].d0, points[pivot].d1 + 1j * omega * arm,
                        points[pivot].d2 + (1j * epsilon - omega ** 2) * arm)
    links = {number: (mpf(jet.d0), mpf(jet.d1), mpf(jet.d2)) for number, jet in angles.items()
             if number != scene.frame_link}
    return Instant(mpf(value), result, links, residuals)


def solve_reference(scene, values: Sequence[float] | np.ndarray) -> ReferenceMotion:
    """The 50-digit motion of ``scene`` at each driver coordinate in ``values`` (rad, or m for a slider).

    graphplan's own double-precision positions (``graphplan.solve``, tolerant of singular
    positions) serve only as Newton's starting point and to pick each group's branch; the
    rates come from the reference's own linear solves.

    Raises
    ------
    ReferenceSolutionError
        at a position that does not assemble or whose Jacobian is singular.
    """
    mechanism = build(scene)
    values = np.atleast_1d(np.asarray(values, dtype=float))
    start = _start(mechanism)
    reference = reference_at(mechanism, start)
    with np.errstate(all="ignore"):
        guess = solve(mechanism, values, reference, tolerant=True)
    instants = []
    with mp.workdps(DPS):
        for index, value in enumerate(values):
            near = {name: complex(guess.point(name).r[index][0], guess.point(name).r[index][1]) for name in guess.points}
            near_angles = {number: float(guess.link(number).angle[index]) for number in guess.links}
            instants.append(_instant(mechanism, float(value), near, near_angles, reference.slides))
    return ReferenceMotion(tuple(instants))


def _start(mechanism) -> float:
    """Where the scene's branches are chosen: its first position (as ``[positions]`` places it)."""
    return float(make_positions(mechanism).values[0])


def scene_positions(scene) -> np.ndarray:
    """The scene's own driver positions."""
    return make_positions(build(scene)).values


def worst_residual(reference: ReferenceMotion) -> tuple[float, float, float]:
    """The largest closure residual of any group at any position: positions, velocities, accelerations."""
    worst = [0.0, 0.0, 0.0]
    for instant in reference.instants:
        for triple in instant.residuals.values():
            worst = [max(w, float(r)) for w, r in zip(worst, triple)]
    return tuple(worst)  # type: ignore[return-value]


def relative_difference(reference: ReferenceMotion, motion, names: Sequence[str] | None = None) -> dict[str, float]:
    """The largest difference of ``motion`` (graphplan's ``Motion``) from the reference, per kind,
    each divided by the largest magnitude of its kind over the positions (angles: absolute, rad)."""
    names = names or [n for n in reference.point_names if n in motion.points]
    out = {}
    for k, kind in enumerate(("r", "v", "a")):
        exact = np.array([reference.point(n)[k] for n in names])
        got = np.array([getattr(motion.point(n), kind)[:, 0] + 1j * getattr(motion.point(n), kind)[:, 1] for n in names])
        scale = float(np.max(np.abs(exact))) or 1.0
        out[kind] = float(np.max(np.abs(got - exact))) / scale
    for k, kind in enumerate(("angle", "omega", "epsilon")):
        numbers = [n for n in reference.link_numbers if n in motion.links]
        exact = np.array([reference.link(n)[k] for n in numbers])
        got = np.array([getattr(motion.link(n), kind) for n in numbers])
        if kind == "angle":
            out[kind] = float(np.max(np.abs(np.angle(np.exp(1j * (got - exact))))))
        else:
            scale = float(np.max(np.abs(exact))) or 1.0
            out[kind] = float(np.max(np.abs(got - exact))) / scale
    return out
