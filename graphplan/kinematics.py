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
from typing import Union

import numpy as np

Vector = Union[complex, np.ndarray]
Scalar = Union[float, np.ndarray]


def dot(a: Vector, b: Vector) -> Scalar:
    """a · b."""
    return (np.conj(a) * b).real


def cross(a: Vector, b: Vector) -> Scalar:
    """The z component of a × b: positive when b lies counter-clockwise of a."""
    return (np.conj(a) * b).imag


def norm2(a: Vector) -> Scalar:
    return a.real * a.real + a.imag * a.imag


def as_xy(vector: Vector, count: int) -> np.ndarray:
    """An ``(count, 2)`` float array of ``vector`` (a view when it already is an array)."""
    array = np.ascontiguousarray(np.broadcast_to(np.asarray(vector, dtype=complex), (count,)))
    return array.view(np.float64).reshape(count, 2)


def solve_pair(e1: Vector, e2: Vector, w: Vector, det: Scalar) -> tuple[Scalar, Scalar]:
    """x1, x2 of the vector equation ``x1·e1 + x2·e2 = w`` (Cramer's rule).

    This is the one equation every class-II group reduces to: two lines of
    action with known directions ``e1``, ``e2`` and unknown magnitudes closing
    the known vector ``w``.  ``det`` is ``cross(e1, e2)``, passed in because the
    caller has already checked it for singularity.
    """
    return cross(w, e2) / det, cross(e1, w) / det


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


def point_on_link(origin: PointMotion, link: LinkMotion, r: Vector) -> PointMotion:
    """Motion of the point at ``r`` fixed on ``link`` whose point ``origin`` is known.

    v = v_O + ω × OP,  a = a_O + ε × OP − ω²·OP.
    """
    arm = r - origin.r
    return PointMotion(
        r=r,
        v=origin.v + 1j * link.omega * arm,
        a=origin.a + (1j * link.epsilon - link.omega * link.omega) * arm,
    )


def unit(angle: float) -> complex:
    """The unit vector at ``angle`` radians from +x."""
    return complex(np.cos(angle), np.sin(angle))
