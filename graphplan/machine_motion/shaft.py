"""The machine reduced to its driving shaft: ``Je(φ)``, ``dJe/dφ`` and ``Mr(φ, ω)`` as functions of the angle."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike
from scipy.interpolate import BSpline, make_interp_spline

from .moment import PiecewiseMoment

TWO_PI = 2.0 * math.pi
# The degree of the periodic spline through samples over a turn (see periodic_spline).
SPLINE_DEGREE = 5


def periodic_spline(samples: ArrayLike, name: str = "samples") -> BSpline:
    """A periodic quintic spline through samples taken at ``φ = 2π·i/n``, ``i = 0 … n−1``.

    The spline repeats with period 2π; its ``derivative()`` is the slope over φ.  Quintic, not
    cubic: the equation of motion carries ``dJe/dφ``, and a cubic spline's slope is only once
    continuously differentiable, so the high-order solvers lose their order at every knot (in
    the energy test of ``tests/test_machine_motion.py`` a cubic spline through 72 samples let
    ``½·Je·ω²`` drift by 4e-7 at rtol 1e-10, the quintic one by 3e-10, as the exact function).
    """
    values = np.asarray(samples, dtype=float)
    if values.ndim != 1 or values.size < SPLINE_DEGREE + 1:
        raise ValueError(f"{name}: needs at least {SPLINE_DEGREE + 1} samples over one turn, equally spaced on "
                         f"[0, 2π) (got shape {values.shape})")
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        raise ValueError(f"{name}: must be finite, at index {bad[0]} (got {values[bad[0]]!r})")
    grid = np.linspace(0.0, TWO_PI, values.size + 1)
    spline = make_interp_spline(grid, np.append(values, values[0]), k=SPLINE_DEGREE, bc_type="periodic")
    spline.extrapolate = "periodic"
    return spline


def _angle_function(value: Any, name: str) -> tuple[Callable[[float], float], BSpline | None]:
    """A number, samples over one turn or a callable of φ, as a callable (and the spline, if any)."""
    if callable(value):
        return value, None
    array = np.asarray(value, dtype=float) if not isinstance(value, (str, bytes)) else None
    if array is None or array.dtype.kind not in "iuf":
        raise ValueError(f"{name}: must be a number, samples over one turn or a function of φ (got {value!r})")
    if array.ndim == 0:
        constant = float(array)
        if not math.isfinite(constant):
            raise ValueError(f"{name}: must be finite (got {constant!r})")
        return (lambda phi: constant), None
    spline = periodic_spline(array, name)
    return spline, spline


@dataclass(frozen=True, eq=False)
class Machine:
    """The machine reduced to its driving shaft.

    Parameters
    ----------
    inertia
        ``Je(φ)``, kg·m²: a number, samples over one turn ``[0, 2π)`` equally spaced, or a
        callable of φ.
    resisting
        ``Mr``, N·m, positive when it resists forward motion: a number, samples of ``Mr(φ)``
        over one turn, a :class:`~graphplan.machine_motion.moment.PiecewiseMoment` (samples with
        jumps: the integrator stops at each jump and goes on with the next piece), or a callable
        ``Mr(φ, ω)``.  A callable should be smooth: a jump in φ is stepped over by the solvers'
        error control (RK45 let a machine with a step in Mr and a constant drive run off to three
        times its speed at rtol 1e-7); samples are splined smooth, and ring round a jump.
    inertia_slope
        ``dJe/dφ``, kg·m²/rad: samples or a callable of φ.  Taken from the spline when
        ``inertia`` is samples, zero when it is a number; required when it is a callable.
    reversible
        Whether ``Mr`` is the moment of forces that act whichever way the shaft turns (the weights alone, which
        give back on the way down what they took on the way up), not of passive resistances that only resist the
        motion.  Run down with the motor off, such a machine turns back from rest where Mr outpulls the brake
        (which holds it at most with its torque) and swings until the brake holds it.  Otherwise a machine at
        rest is held wherever its moments do not drive it forward.
    """

    inertia: Any
    resisting: Any = 0.0
    inertia_slope: Any = None
    reversible: bool = False
    _je: Callable[[float], float] = field(init=False, repr=False)
    _je_slope: Callable[[float], float] = field(init=False, repr=False)
    _mr: Callable[[float, float], float] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        je, spline = _angle_function(self.inertia, "inertia")
        if self.inertia_slope is not None:
            slope, _ = _angle_function(self.inertia_slope, "inertia_slope")
        elif spline is not None:
            slope = spline.derivative()
        elif not callable(self.inertia):
            slope = lambda phi: 0.0  # a constant Je has no slope
        else:
            raise ValueError("inertia_slope: is required when inertia is a function of φ "
                             "(give dJe/dφ as a function or as samples over one turn)")
        if isinstance(self.resisting, PiecewiseMoment):
            moment = self.resisting
            resisting = lambda phi, omega: moment(phi)
        elif callable(self.resisting):
            resisting = self.resisting
        else:
            of_angle, _ = _angle_function(self.resisting, "resisting")
            resisting = lambda phi, omega: of_angle(phi)
        object.__setattr__(self, "_je", je)
        object.__setattr__(self, "_je_slope", slope)
        object.__setattr__(self, "_mr", resisting)
        angles = np.linspace(0.0, TWO_PI, 721)
        values = np.array([float(je(a)) for a in angles])
        if not np.all(np.isfinite(values)) or values.min() <= 0:
            where = int(np.argmin(np.where(np.isfinite(values), values, -np.inf)))
            raise ValueError(f"inertia: must be > 0 over the whole turn (Je = {float(values[where]):g} kg·m² "
                             f"at φ = {math.degrees(angles[where]):.1f}°: the links have no mass that moves there)")

    def je(self, phi: float) -> float:
        """The reduced moment of inertia Je(φ), kg·m²."""
        return float(self._je(phi))

    def je_slope(self, phi: float) -> float:
        """dJe/dφ, kg·m²/rad."""
        return float(self._je_slope(phi))

    def mr(self, phi: float, omega: float) -> float:
        """The reduced moment of the resisting forces Mr(φ, ω), N·m."""
        return float(self._mr(phi, omega))

    @property
    def moment(self) -> PiecewiseMoment | None:
        """Mr as pieces between its jumps, where it was given so (the integrator steps from jump to jump)."""
        return self.resisting if isinstance(self.resisting, PiecewiseMoment) else None

    @property
    def resists_by_angle_alone(self) -> bool:
        """Whether Mr depends on the angle alone (pieces, samples over the turn, a constant), not on the speed."""
        return self.moment is not None or not callable(self.resisting)
