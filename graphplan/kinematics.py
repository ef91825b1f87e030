"""Planar kinematics over many positions at once, in complex numbers.

A vector (x, y) is the complex number x + iy, so that the textbook's
operations read as they are written: ``ω × r`` is ``1j * omega * r``, turning
by θ is multiplying by ``exp(1j*θ)``.  Every quantity is either a scalar (the
same at every position, such as a frame point) or a 1-D numpy array over the
positions; numpy broadcasting mixes them freely.  A complex array is also a
zero-copy ``(N, 2)`` array of floats (:func:`as_xy`), which is how the public
interface hands vectors out.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

Vector = complex | np.ndarray
Scalar = float | np.ndarray


def dot(a: Vector, b: Vector) -> Scalar:
    """a · b."""
    return (np.conj(a) * b).real


def cross(a: Vector, b: Vector) -> Scalar:
    """The z component of a × b: positive when b lies counter-clockwise of a."""
    return (np.conj(a) * b).imag


def at(value: Vector | Scalar, index: int):
    """The value at position ``index``: a scalar is the same at every position."""
    return np.atleast_1d(value)[index if np.ndim(value) else 0]


def read_only(value):
    """``value`` made read-only where it is an array, and handed back (a number, a constant field, as it is): what
    a motion, an equilibrium or a machine's model hands out is theirs, and a write through it changed what was read
    of them after."""
    if isinstance(value, np.ndarray):
        value.flags.writeable = False
    return value


def norm2(a: Vector) -> Scalar:
    total = a.real * a.real
    total += a.imag * a.imag
    return total


def complex_from(real: Scalar, imag: Scalar) -> Vector:
    """real + i·imag, its parts written in place: ``real + 1j * imag`` would pass over the positions twice more."""
    if np.ndim(real) == 0 and np.ndim(imag) == 0:
        return complex(real, imag)
    out = np.empty(np.broadcast(real, imag).shape, dtype=complex)
    out.real = real
    out.imag = imag
    return out


def unit_vectors(angles: np.ndarray) -> np.ndarray:
    """exp(i·angles) over all positions, by the half-angle substitution t = tan(θ/2).

    cos θ = (1 − t²)/(1 + t²) and sin θ = 2t/(1 + t²): numpy's float64 tan
    runs a SIMD loop, its cos and sin scalar libm ones about ten times slower.
    Both ways agree to a few units in the last place of the unit vector.
    """
    t = np.tan(0.5 * angles)
    t2 = t * t
    # 1/(1 + t²), 2t and 1 − t², each made in place of its operand.
    inverse = 1.0 + t2
    np.reciprocal(inverse, out=inverse)
    t += t
    np.subtract(1.0, t2, out=t2)
    u = np.empty(angles.shape, dtype=complex)
    np.multiply(t2, inverse, out=u.real)
    np.multiply(t, inverse, out=u.imag)
    return u


def angle_of(vector: Vector) -> Scalar:
    """The angle of ``vector`` from +x, as ``np.angle`` gives it.

    From contiguous copies of the parts: over the strided parts of a complex
    array arctan2 misses numpy's SIMD loop and takes about three times as long.
    """
    if np.ndim(vector) == 0:
        return float(np.angle(vector))
    return np.arctan2(np.ascontiguousarray(vector.imag), np.ascontiguousarray(vector.real))


def as_xy(vector: Vector, count: int) -> np.ndarray:
    """An ``(count, 2)`` float array of ``vector`` (a view when it already is an array)."""
    if isinstance(vector, np.ndarray) and vector.shape == (count,) and vector.dtype == complex and vector.flags.c_contiguous:
        return vector.view(np.float64).reshape(count, 2)  # the usual case, without the general path's five calls
    array = np.ascontiguousarray(np.broadcast_to(np.asarray(vector, dtype=complex), (count,)))
    return array.view(np.float64).reshape(count, 2)


class TwoLines:
    """The vector equation ``x1·e1 + x2·e2 = w`` that every class-II group reduces to.

    Two lines of action with known directions ``e1``, ``e2`` and unknown
    magnitudes close a known vector ``w``; a group solves it twice with the
    same lines (velocities, then accelerations), so Cramer's rule is set up
    once: ``det = e1 × e2``, then ``x1 = (w × e2)/det``, ``x2 = (e1 × w)/det``.
    """

    __slots__ = ("_e1_conj", "_e2_conj", "_inverse", "_negated_inverse", "det")

    def __init__(self, e1: Vector, e2: Vector) -> None:
        self._e1_conj = np.conj(e1)
        self._e2_conj = np.conj(e2)
        self.det = (self._e1_conj * e2).imag
        with np.errstate(divide="ignore"):
            self._inverse = 1.0 / self.det
        # Negated once here rather than at each solve (see below).
        self._negated_inverse = -self._inverse

    def solve(self, w: Vector) -> tuple[Scalar, Scalar]:
        """x1, x2 for the known vector ``w``."""
        # w × e2 = −Im(w·conj(e2)),  e1 × w = Im(conj(e1)·w)
        return (w * self._e2_conj).imag * self._negated_inverse, (self._e1_conj * w).imag * self._inverse


@dataclass(frozen=True)
class PointMotion:
    """Position, velocity and acceleration of a point, SI, as complex numbers."""

    r: Vector
    v: Vector
    a: Vector


@dataclass(frozen=True)
class LinkMotion:
    """Orientation and angular motion of a link.

    ``origin`` names a point fixed on the link and ``u`` is the unit vector of
    the link's reference line (``exp(1j*angle)``); together they fix the
    link's pose, so that any point fixed on it follows from its local
    coordinates.  ``omega`` and ``epsilon`` are counter-clockwise positive.
    """

    origin: str
    u: Vector
    angle: Scalar
    omega: Scalar
    epsilon: Scalar

    @cached_property
    def turning(self) -> tuple[Vector, Vector]:
        """The factors that turn an arm r of the link into ω × r and into ε × r − ω²·r.

        Computed once per link, they serve every point the link carries.
        """
        omega, epsilon = self.omega, self.epsilon
        if np.ndim(omega) == 0 and np.ndim(epsilon) == 0:
            return 1j * omega, 1j * epsilon - omega * omega
        # Part by part, ω and ε being real: −ω² + iε from ω + iε, squared and negated in place.
        whirl = complex_from(omega, epsilon)
        whirl.real *= omega
        np.negative(whirl.real, out=whirl.real)
        return complex_from(0.0, omega), whirl


@dataclass(frozen=True)
class SlideMotion:
    """Relative motion in a sliding pair: ``slider`` moves along a line fixed in ``guide``.

    ``u`` is the unit direction of the line, ``s`` the slider's coordinate on it,
    ``velocity`` and ``acceleration`` the relative ṡ and s̈ along ``u``.  The
    Coriolis acceleration of the slider is ``2j * ω_guide * velocity * u``.
    """

    slider: int
    guide: int
    joint: str
    u: Vector
    s: Scalar
    velocity: Scalar
    acceleration: Scalar

    def __repr__(self) -> str:
        # The dataclass's own repr printed every array: 28 000 characters at 360 positions.
        return (f"<SlideMotion of link {self.slider} on link {self.guide} at {self.joint}: "
                f"{np.size(self.s)} positions>")


def point_on_link(origin: PointMotion, link: LinkMotion, arm: Vector) -> PointMotion:
    """Motion of the point P fixed on ``link`` at ``arm`` = OP from its known point O.

    v = v_O + ω × OP,  a = a_O + ε × OP − ω²·OP.
    """
    return PointMotion(origin.r + arm, *carried(origin, link, arm))


def carried(origin: PointMotion, link: LinkMotion, arm: Vector) -> tuple[Vector, Vector]:
    """v and a of :func:`point_on_link`, for a point whose r is known already."""
    spin, whirl = link.turning
    return _plus(origin.v, spin * arm), _plus(origin.a, whirl * arm)


def point_fixed_on(origin: PointMotion, link: LinkMotion, local: complex) -> PointMotion:
    """:func:`point_on_link` for the point at ``local`` in the link's own frame (arm = u·local)."""
    arm = np.multiply(link.u, local)
    v, a = carried(origin, link, arm)
    return PointMotion(_plus(origin.r, arm), v, a)  # the arm, no longer needed, takes r in place


def _plus(base: Vector, term: Vector) -> Vector:
    """base + term for a ``term`` just computed: into ``term`` when it has the sum's shape already."""
    if _still(base):
        return term
    if isinstance(term, np.ndarray) and getattr(base, "shape", ()) in ((), term.shape):
        term += base
        return term
    return base + term


def _still(value: Vector) -> bool:
    """The scalar zero of a point at rest: adding it would only be a pass over the positions."""
    return not isinstance(value, np.ndarray) and value == 0


def unit(angle: float) -> complex:
    """The unit vector at ``angle`` radians from +x."""
    return complex(np.cos(angle), np.sin(angle))
