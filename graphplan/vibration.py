"""Vibration from rotating unbalance: steady response, transmissibility, critical speeds, isolation.

A machine of mass M on a mount of stiffness k and viscous damping c carries
an unbalance m·e turning at ω; its vertical motion obeys

    M·x'' + c·x' + k·x = m·e·ω²·sin ωt,

with ωn = √(k/M), ζ = c / (2·√(k·M)) and the frequency ratio r = ω/ωn.  The
steady response is x = X·sin(ωt − φ) with

    M·X / (m·e) = r² / √((1 − r²)² + (2ζr)²)        (the magnification factor)
    tan φ = 2ζr / (1 − r²),  0 ≤ φ ≤ π                (the lag behind the unbalance force)

and the force the mount passes to the base, k·x + c·x', has the amplitude
TR·m·e·ω² with the transmissibility

    TR = √(1 + (2ζr)²) / √((1 − r²)² + (2ζr)²),

which is also X/Y of a machine whose base moves as y = Y·sin ωt.  A disc on
a shaft whirls the same way, k being the shaft's bending stiffness at the
disc: its critical speed is ωc = √(k/m).

Conventions: SI units, angles in radians inside (``*_deg`` at the edges).
The dimensionless functions take numbers or numpy arrays, broadcast them
together and return a float for scalars and an array otherwise.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from .errors import SceneError
from .reader import Table, check_choice
from .render.numerals import number
from .rotor_lengths import (
    FASTEST_BASE_M_S,
    LARGEST_RADIUS_M,
    LARGEST_SECOND_MOMENT_M4,
    LONGEST_ROTOR_M,
    THICKEST_SHAFT_M,
    Implausible,
    LengthsInMillimetres,
    lightest_rotor,
)
from .rounding import ROUNDING_NOISE, digit_unit, written_as_nought
from .table_keys import keys_of_other_tables
from .units import RPM, STANDARD_GRAVITY, exponent_slip, motor_speed_in_rpm, percentage_question, rpm_question

Scalar = float | np.ndarray
#: Without damping, a speed this close to ωn (relative) is resonance: its amplitude is rounding's, not the machine's.
RESONANCE_TOLERANCE = 1e-6
#: Without damping, a speed this close to ωn (relative) is warned of: the amplitude grows without bound towards it.
NEAR_RESONANCE = 0.1
#: With damping, a speed that near ωn is warned of where the magnification M·X/(m·e) reaches this (ζ below about
#: 0.05 at resonance): a damping ratio of 1e-9 damps nothing, and had no warning where none had one.
LARGE_MAGNIFICATION = 10.0
# The most a machine's isolating mounts sag under its weight (m): steel springs reach some 50–100 mm, rubber less.
MOST_MOUNT_SAG = 0.1
Support = Literal["simply_supported", "cantilever"]
SUPPORTS = ("simply_supported", "cantilever")
# The speeds (rpm) a machine's rotor is taken to turn at: from a slow mixer's to past a turbocharger's (some 300 000)
# and a dental turbine's.  A speed of 10¹³ rpm (omega = 1e12) gave an exciting force of 10²² N without a word.
SLOWEST_RPM = 1.0
FASTEST_RPM = 1_000_000.0
# The moduli of elasticity (Pa) shafts are made of: from a polymer's some 3·10⁹ to a hard metal's 7·10¹¹ (diamond's
# 1.2·10¹²).  Steel's 2.1e5, typed in MPa (N/mm²), made a 50 mm shaft k = 3 N/m, sagging 317 m, without a word.
SOFTEST_SHAFT = 1e9
STIFFEST_SHAFT = 1.2e12


def _array(argument: str, value: ArrayLike, *, least: float | None = None, strict: bool = False) -> np.ndarray:
    array = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{argument}: must be finite (got {value!r})")
    if least is not None:
        bad = array <= least if strict else array < least
        if np.any(bad):
            relation = ">" if strict else ">="
            raise ValueError(f"{argument}: must be {relation} {least:g} (got {value!r})")
    return array


def _out(value: np.ndarray) -> Scalar:
    return float(value) if np.ndim(value) == 0 else value


def _ratio_and_damping(r: ArrayLike, zeta: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    return _array("r", r, least=0.0), _array("zeta", zeta, least=0.0)


def _denominator(r: np.ndarray, zeta: np.ndarray) -> np.ndarray:
    """√((1 − r²)² + (2ζr)²), the modulus of k − Mω² + icω over k."""
    return np.hypot(1.0 - r * r, 2.0 * zeta * r)


# --- the response as functions of r and ζ -----------------------------------------------------


def unbalance_magnification(r: ArrayLike, zeta: ArrayLike) -> Scalar:
    """The magnification factor M·X/(m·e) = r² / √((1 − r²)² + (2ζr)²) of a machine with rotating unbalance.

    0 at rest, 1/(2ζ) at resonance (r = 1), → 1 far above it: the machine
    then turns about the common centre of mass.  Infinite at r = 1 with ζ = 0.
    """
    ratio, damping = _ratio_and_damping(r, zeta)
    # At resonance with next to no damping the response is infinite, or too large for a float: inf either way.
    with np.errstate(divide="ignore", over="ignore"):
        return _out(ratio * ratio / _denominator(ratio, damping))


def force_magnification(r: ArrayLike, zeta: ArrayLike) -> Scalar:
    """X·k / F0 = 1 / √((1 − r²)² + (2ζr)²): the response to a force of constant amplitude F0 over its static one."""
    ratio, damping = _ratio_and_damping(r, zeta)
    with np.errstate(divide="ignore", over="ignore"):
        return _out(1.0 / _denominator(ratio, damping))


def _at_undamped_resonance(ratio: np.ndarray, damping: np.ndarray, lag: np.ndarray) -> np.ndarray:
    """``lag`` with π/2 where r = 1 and ζ = 0: every ζ > 0 lags by π/2 there, and so does the limit ζ → 0, where
    atan2(0, 0) = 0 would read as in phase."""
    return np.where((ratio == 1.0) & (damping == 0.0), np.pi / 2.0, lag)


def phase(r: ArrayLike, zeta: ArrayLike) -> Scalar:
    """φ = atan2(2ζr, 1 − r²) (rad), in [0, π]: how far the motion lags behind the exciting force (π/2 at r = 1
    for every ζ, the undamped limit included)."""
    ratio, damping = _ratio_and_damping(r, zeta)
    return _out(_at_undamped_resonance(ratio, damping, np.arctan2(2.0 * damping * ratio, 1.0 - ratio * ratio)))


def transmissibility(r: ArrayLike, zeta: ArrayLike) -> Scalar:
    """TR = √(1 + (2ζr)²) / √((1 − r²)² + (2ζr)²): the force passed to the base over the exciting force.

    1 at r = √2 for every ζ; below 1 (isolation) only above r = √2, where
    more damping passes more force.
    """
    ratio, damping = _ratio_and_damping(r, zeta)
    with np.errstate(divide="ignore"):
        return _out(np.hypot(1.0, 2.0 * damping * ratio) / _denominator(ratio, damping))


def displacement_transmissibility(r: ArrayLike, zeta: ArrayLike) -> Scalar:
    """X/Y of a mass on a spring and damper whose base moves as Y·sin ωt: the same expression as TR.

    The motion relative to the base, Z/Y, is :func:`unbalance_magnification`.
    """
    return transmissibility(r, zeta)


def displacement_transmissibility_phase(r: ArrayLike, zeta: ArrayLike) -> Scalar:
    """The lag (rad) of the mass's motion behind its base's: atan2(2ζr³, 1 − r² + (2ζr)²), in [0, π] (π/2 at r = 1
    and ζ = 0, the limit of atan2(2ζ, 4ζ²) as ζ → 0)."""
    ratio, damping = _ratio_and_damping(r, zeta)
    lag = np.arctan2(2.0 * damping * ratio ** 3, 1.0 - ratio * ratio + (2.0 * damping * ratio) ** 2)
    return _out(_at_undamped_resonance(ratio, damping, lag))


# --- the system's constants --------------------------------------------------------------------


def natural_frequency(stiffness: ArrayLike, mass: ArrayLike) -> Scalar:
    """ωn = √(k/m) (rad/s); for a disc of mass m on a shaft of stiffness k, its critical (whirling) speed."""
    return _out(np.sqrt(_array("stiffness", stiffness, least=0.0, strict=True)
                        / _array("mass", mass, least=0.0, strict=True)))


critical_speed = natural_frequency


def damping_ratio(damping: ArrayLike, stiffness: ArrayLike, mass: ArrayLike) -> Scalar:
    """ζ = c / (2·√(k·m)), c the viscous damping coefficient (N·s/m)."""
    c = _array("damping", damping, least=0.0)
    return _out(c / (2.0 * np.sqrt(_array("stiffness", stiffness, least=0.0, strict=True)
                                   * _array("mass", mass, least=0.0, strict=True))))


def circular_second_moment(diameter: ArrayLike) -> Scalar:
    """I = π·d⁴/64 (m⁴) of a solid round shaft of diameter d (m), about a diameter."""
    return _out(math.pi * _array("diameter", diameter, least=0.0, strict=True) ** 4 / 64.0)


def shaft_stiffness(modulus: float, second_moment: float, length: float, position: float | None = None,
                    support: Support = "simply_supported") -> float:
    """The bending stiffness k = F/δ (N/m) of a massless shaft at the disc it carries.

    ``simply_supported``: bearings at both ends of the span L, the disc at a
    from one of them (default L/2), k = 3·E·I·L / (a²·b²), b = L − a
    (48·E·I/L³ in the middle).  ``cantilever``: the shaft fixed at one end,
    the disc at a from it (default L, the free end), k = 3·E·I/a³.
    ``modulus`` is E (Pa), ``second_moment`` I (m⁴).
    """
    e = float(_array("modulus", modulus, least=0.0, strict=True))
    i = float(_array("second_moment", second_moment, least=0.0, strict=True))
    span = float(_array("length", length, least=0.0, strict=True))
    if support not in SUPPORTS:
        raise ValueError(f"support: must be one of {', '.join(SUPPORTS)} (got {support!r})")
    if support == "simply_supported":
        a = span / 2 if position is None else float(_array("position", position))
        if not 0 < a < span:
            raise ValueError(f"position: the disc must lie between the bearings, 0 < a < {span:g} (got {position!r})")
        b = span - a
        return 3.0 * e * i * span / (a * a * b * b)
    a = span if position is None else float(_array("position", position))
    if not 0 < a <= span:
        raise ValueError(f"position: the disc must lie on the shaft, 0 < a <= {span:g} (got {position!r})")
    return 3.0 * e * i / a ** 3


@dataclass(frozen=True)
class Shaft:
    """A massless shaft carrying the disc, as a scene gives it: E (Pa), I (m⁴) or the diameter d (m) it is
    worked out from, the span L (m), the disc's ``position`` a (m; None: the default of :func:`shaft_stiffness`)
    and the ``support``."""

    modulus: float
    second_moment: float
    length: float
    position: float | None = None
    support: Support = "simply_supported"
    diameter: float | None = None

    @property
    def disc_at(self) -> float:
        """a (m): from one bearing (simply supported; the middle by default) or from the fixed end (cantilever;
        the free end by default)."""
        if self.position is not None:
            return self.position
        return self.length / 2 if self.support == "simply_supported" else self.length

    @property
    def stiffness(self) -> float:
        """k (N/m) at the disc, :func:`shaft_stiffness`."""
        return shaft_stiffness(self.modulus, self.second_moment, self.length, self.position, self.support)


# --- design and identification -----------------------------------------------------------------


def isolation_frequency_ratio(wanted: ArrayLike, zeta: ArrayLike) -> Scalar:
    """The frequency ratio r > √2 at which the transmissibility is ``wanted`` (0 < TR < 1) with damping ζ.

    TR² = (1 + 4ζ²s) / ((1 − s)² + 4ζ²s) with s = r² is the quadratic
    TR²·s² − 2·(TR² + 2ζ²(1 − TR²))·s + TR² − 1 = 0; its root above 2 is
    the one on the isolating side (the other is negative).
    """
    t = _array("wanted", wanted)
    if np.any((t <= 0) | (t >= 1)):
        raise ValueError(f"wanted: a transmissibility that isolates must be in (0, 1) (got {wanted!r})")
    z = _array("zeta", zeta, least=0.0)
    t2 = t * t
    half_b = t2 + 2.0 * z * z * (1.0 - t2)
    s = (half_b + np.sqrt(half_b * half_b + t2 * (1.0 - t2))) / t2
    return _out(np.sqrt(s))


def isolation_stiffness(mass: ArrayLike, omega: ArrayLike, wanted: ArrayLike, zeta: ArrayLike) -> Scalar:
    """The mount stiffness k = M·(ω/r)² (N/m) that passes only ``wanted`` of the force at ω (rad/s)."""
    r = isolation_frequency_ratio(wanted, zeta)
    m = _array("mass", mass, least=0.0, strict=True)
    w = _array("omega", omega, least=0.0, strict=True)
    return _out(m * (w / r) ** 2)


def series_mount_stiffness(total: float, shaft: float) -> float | None:
    """The stiffness k_m (N/m, at the disc) of mounts under a shaft's bearings that, in series with the shaft's own
    k_s, give the support the ``total`` stiffness k: 1/k = 1/k_s + 1/k_m, so k_m = k·k_s/(k_s − k).

    None where k ≥ k_s: mounts in series only soften the shaft, so no mount gives a support stiffer than the shaft
    on rigid bearings (at k = k_s, rigid ones do).
    """
    k = float(_array("total", total, least=0.0, strict=True))
    k_s = float(_array("shaft", shaft, least=0.0, strict=True))
    return None if k >= k_s else k * k_s / (k_s - k)


def damping_from_resonance(resonant_amplitude: ArrayLike, high_speed_amplitude: ArrayLike, *,
                           at: Literal["resonance", "peak"] = "resonance") -> Scalar:
    """ζ of a machine with rotating unbalance from its amplitude at resonance and far above it.

    Far above resonance X∞ = m·e/M; at r = 1, X = (m·e/M)/(2ζ), so
    ζ = X∞ / (2·X_res) (``at="resonance"``, the textbooks' reading).  With
    ``at="peak"`` the first amplitude is the greatest one, reached at
    r = 1/√(1 − 2ζ²) where M·X/(m·e) = 1/(2ζ√(1 − ζ²)); then
    ζ² = (1 − √(1 − q⁻²))/2 with q = X_peak/X∞.
    """
    peak = _array("resonant_amplitude", resonant_amplitude, least=0.0, strict=True)
    far = _array("high_speed_amplitude", high_speed_amplitude, least=0.0, strict=True)
    if at == "resonance":
        return _out(far / (2.0 * peak))
    if at != "peak":
        raise ValueError(f"at: must be 'resonance' or 'peak' (got {at!r})")
    q = peak / far
    if np.any(q <= 1):
        raise ValueError("resonant_amplitude: the peak must exceed the amplitude far above resonance")
    return _out(np.sqrt((1.0 - np.sqrt(1.0 - 1.0 / (q * q))) / 2.0))


def damping_from_phase(r: ArrayLike, lag: ArrayLike) -> Scalar:
    """ζ from the lag φ (rad) of the motion behind the exciting force measured at the frequency ratio r.

    The inverse of :func:`phase`: tan φ = 2ζr/(1 − r²), so ζ = (1 − r²)·tan φ/(2r), for
    0 < φ < π (a lag of 0 or π is undamped; at r = 1 every ζ lags by π/2, which says nothing
    of ζ, and is refused).  Below resonance the lag is under π/2, above it over.
    """
    ratio = _array("r", r, least=0.0, strict=True)
    angle = _array("lag", lag, least=0.0, strict=True)
    if np.any(angle >= np.pi):
        raise ValueError("lag: must be less than π (a motion lags its force by 0 to π)")
    if np.any(np.isclose(ratio, 1.0, rtol=0.0, atol=1e-12)):
        raise ValueError("r: at resonance (r = 1) the lag is π/2 whatever the damping; measure off resonance")
    if np.any((ratio < 1.0) != (angle < np.pi / 2)):
        raise ValueError("lag: below resonance (r < 1) the lag is under π/2, above it (r > 1) over π/2")
    return _out((1.0 - ratio * ratio) * np.tan(angle) / (2.0 * ratio))


# --- a machine with rotating unbalance ------------------------------------------------------------


@dataclass(frozen=True)
class VibrationSpec:
    """A machine of ``mass`` M (kg, the unbalanced mass included) on a mount of ``stiffness`` k (N/m).

    ``unbalance`` is m·e (kg·m), ``damping_ratio`` ζ, ``omega`` the speed
    (rad/s); ``transmissibility`` a wanted TR to design an isolating mount
    for, or None; ``base_amplitude`` Y (m) where the base itself moves as
    y = Y·sin ωt (a floor shaken by the machines around), or None.
    """

    mass: float
    unbalance: float
    stiffness: float
    damping_ratio: float
    omega: float
    transmissibility: float | None = None
    base_amplitude: float | None = None
    # How the scene gave k and ζ, for the note to say: the shaft whose stiffness k is, the damping c (N·s/m); and
    # the eccentricity e (m) where it gave m·e as a mass and its eccentricity, for the lengths to be checked.
    shaft: Shaft | None = None
    damping: float | None = None
    eccentricity: float | None = None
    # Whether ω is the linkage's crank's, the table giving no speed of its own, for the note to say so.
    driver_speed: bool = False

    @property
    def on_shaft(self) -> bool:
        """Whether k is a shaft's bending stiffness at its disc (the rotor whirls), not its mounts'."""
        return self.shaft is not None

    def __post_init__(self) -> None:
        for name in ("mass", "stiffness", "omega"):
            _array(name, getattr(self, name), least=0.0, strict=True)
        _array("unbalance", self.unbalance, least=0.0)
        _array("damping_ratio", self.damping_ratio, least=0.0)
        if self.base_amplitude is not None:
            _array("base_amplitude", self.base_amplitude, least=0.0, strict=True)
        if self.transmissibility is not None and not 0 < self.transmissibility < 1:
            raise ValueError(f"transmissibility: a wanted transmissibility must be in (0, 1) "
                             f"(got {self.transmissibility!r})")
        if self.damping_ratio == 0 and at_resonance(self.omega, self.stiffness, self.mass):
            raise ValueError("omega: at resonance without damping the amplitude has no bound; give damping")


def at_resonance(omega: float, stiffness: float, mass: float) -> bool:
    """Whether ω is ωn = √(k/M) to within :data:`RESONANCE_TOLERANCE`: a speed typed as 31.6227766017 for
    √1000 is resonance, and without damping its amplitude (1e8 m) would be the rounding's."""
    return abs(omega / math.sqrt(stiffness / mass) - 1.0) < RESONANCE_TOLERANCE


@dataclass(frozen=True)
class NearResonance:
    """A machine run near its resonance with no damping or with next to none (:func:`near_resonance`).

    ``ratio`` r = ω/ωn, ``zeta`` ζ, ``magnification`` r²/√((1 − r²)² + (2ζr)²) and ``amplitude`` X (m) of the
    machine's motion (the unbalance's; where the ``base_moves``, the base's or the two added).  An ``instrument``
    (no unbalance, on a moving base) turns at no speed: the base shakes it, ``transmissibility`` X/Y times as far."""

    ratio: float
    zeta: float
    magnification: float
    amplitude: float
    base_moves: bool = False
    instrument: bool = False
    transmissibility: float = 0.0
    code = "near-resonance"

    @property
    def resonant_as_written(self) -> bool:
        """Whether r is 1 to the digits the note and the command line write it to (:func:`number`): r = 1.000003 is
        resonance to them, and "within 3e−06 of the natural frequency (r = 1)" said it in riddles."""
        return number(self.ratio) == "1"

    @property
    def percent_off(self) -> float:
        """How far ω lies from the natural frequency, in per cent of it: the command line and the note both give it
        so ("within 0.012" on the console beside the note's "within 1.2 %" read as two different distances)."""
        return abs(self.ratio - 1.0) * 100.0

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it), r written as the note writes it."""
        if self.instrument:
            return self._instrument_detail()
        off = number(self.percent_off, 2)
        # r = 1 to the digits written is resonance itself: "within 0 of the natural frequency" said it in riddles.
        at = self.resonant_as_written
        if self.zeta > 0:
            # On a moving base X is not the magnification times m·e/M: the base's motion is in it.
            times = (f", the magnification {number(self.magnification)}" if self.base_moves
                     else f" is {number(self.magnification)} times m·e/M")
            where = ("ω at the natural frequency (r = 1): the machine runs at resonance" if at
                     else f"ω within {off} % of the natural frequency (r = {number(self.ratio)})")
            return (f"{where} with little damping (ζ = {number(self.zeta)}): the amplitude X = "
                    f"{number(self.amplitude)} m{times}; run the machine {'away from' if at else 'farther from'} "
                    "resonance or damp it more")
        if at:
            return (f"no damping and ω at the natural frequency to five digits (r = 1): the machine runs at resonance, "
                    f"and the amplitude X = {number(self.amplitude)} m hangs on how near; give damping_ratio or "
                    "damping")
        return (f"no damping and ω within {off} % of the natural frequency "
                f"(r = {number(self.ratio)}): the amplitude X = {number(self.amplitude)} m grows without bound nearer "
                "it; give damping_ratio or damping")

    def _instrument_detail(self) -> str:
        """The warning of an instrument shaken near its resonance: the base's frequency, not a speed it runs at, is
        near ωn, and the way out is its mounts (another natural frequency) or their damping."""
        at = self.resonant_as_written
        where = ("the base's ω at the natural frequency" + (" to five digits" if self.zeta == 0 else "") + " (r = 1): "
                 "the instrument is shaken at resonance" if at else
                 f"the base's ω within {number(self.percent_off, 2)} % of the natural frequency "
                 f"(r = {number(self.ratio)})")
        if self.zeta > 0:
            return (f"{where} with little damping (ζ = {number(self.zeta)}): the instrument moves X = "
                    f"{number(self.amplitude)} m, {number(self.transmissibility)} times the base's Y; mount it with "
                    "its natural frequency farther from the base's (softer mounts) or damp the mounts more")
        grows = "hangs on how near" if at else "grows without bound nearer it"
        return (f"no damping and {where}: the instrument's amplitude X = {number(self.amplitude)} m {grows}; give "
                "damping_ratio or damping")


@dataclass(frozen=True)
class MountsSag:
    """Isolating mounts that would sag more than :data:`MOST_MOUNT_SAG` under the machine's weight
    (:func:`mounts_sag`), with what would bring them within it.

    ``stiffness`` k (N/m) and ``sag`` M·g/k (m) of the mounts designed; ``ratio`` the r they need for the
    ``wanted`` TR at ``zeta``, ``undamped_ratio`` the r undamped mounts would need.  Each way out is given only
    where it reaches the limit alone, rounded to its safe side: ``most_damping`` (ζ at most), ``least_transmissibility``
    (TR at least) and ``least_rpm`` (the speed at least; ``rpm`` the machine's).  ``undamped_sag`` (m) is given
    where even undamped mounts sag too much, ``root_two_sag`` (m) where even r = √2 does."""

    stiffness: float
    sag: float
    wanted: float
    ratio: float
    zeta: float
    undamped_ratio: float
    least_rpm: str
    rpm: float
    most_damping: str | None = None
    least_transmissibility: str | None = None
    undamped_sag: float | None = None
    root_two_sag: float | None = None
    # On a shaft, the shaft's own bending under the rotor's weight, M·g/k_s (m): the mounts under its bearings sag
    # the rest of g·r²/ω².  0 on mounts alone.
    shaft_sag: float = 0.0
    code = "mounts-sag"

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it)."""
        limit = f"{MOST_MOUNT_SAG * 1000:g} mm"
        if self.shaft_sag > 0:
            line = (f"the mounts under the shaft's bearings, k_m = {number(self.stiffness)} N/m at the disc, would sag "
                    f"by M·g/k_m = {number(self.sag, 3)} m under the rotor's weight, more than any spring mount "
                    f"({limit}); the sag is g·r²/ω² less the shaft's own bending M·g/k_s = {number(self.shaft_sag, 3)} "
                    "m, and ")
        else:
            line = (f"the isolating mounts, k = {number(self.stiffness)} N/m, would sag by M·g/k = "
                    f"{number(self.sag, 3)} m under the machine's weight, more than any spring mount ({limit}); the "
                    "sag is g·r²/ω², and ")
        if self.zeta > 0:
            line += (f"TR = {self.wanted:g} needs r = {number(self.ratio)} at the mounts' damping ratio ζ = "
                     f"{self.zeta:g} (more damping, a larger r; undamped, r = {number(self.undamped_ratio)})")
        else:
            line += f"TR = {self.wanted:g} needs r = {number(self.ratio)} without damping"
        ways = []
        if self.most_damping is not None:
            ways.append(f"damping ζ ≤ {self.most_damping}")
        if self.undamped_sag is not None:
            line += f"; even undamped mounts would sag {number(self.undamped_sag, 3)} m at this speed"
        if self.least_transmissibility is not None:
            ways.append(f"TR ≥ {self.least_transmissibility}" + (f" at ζ = {self.zeta:g}" if self.zeta > 0 else ""))
        if self.root_two_sag is not None:
            line += (f"; at this speed no mount isolates within {limit} (r = √2 already sags "
                     f"{number(self.root_two_sag, 3)} m)")
        ways.append(f"a speed of {self.least_rpm} rpm or more (now {number(self.rpm)} rpm)")
        return line + f"; within {limit}: " + ", or ".join(ways)


def near_resonance(spec: VibrationSpec) -> NearResonance | None:
    """The machine run near its resonance (within :data:`NEAR_RESONANCE`) without damping, or with so little
    that its magnification (an instrument's X/Y) reaches :data:`LARGE_MAGNIFICATION`; else None."""
    response = steady_state(spec)
    r = response.frequency_ratio
    if abs(r - 1.0) >= NEAR_RESONANCE:
        return None
    instrument = response.base is not None and spec.unbalance == 0
    # An instrument's growth is X/Y, the times its base's motion it makes: judged by M·X/(m·e), of an unbalance it
    # has not, one shaken 10.03 times as far as its floor (ζ = 0.05, r = 0.9935) went unwarned at 9.85.
    growth = response.transmissibility if instrument else response.magnification
    if spec.damping_ratio > 0 and growth < LARGE_MAGNIFICATION:
        return None
    # The motion the machine makes: a balanced machine on a moving base has no unbalance's amplitude to grow.
    amplitude = response.amplitude
    if response.combined is not None:
        amplitude = response.combined.amplitude
    elif instrument:
        amplitude = response.base.amplitude
    return NearResonance(ratio=r, zeta=spec.damping_ratio, magnification=response.magnification, amplitude=amplitude,
                         base_moves=response.base is not None, instrument=instrument,
                         transmissibility=response.transmissibility)


def mounts_sag(spec: VibrationSpec) -> MountsSag | None:
    """The isolating mounts the scene asks for where they would sag more than :data:`MOST_MOUNT_SAG` under the
    machine's weight (a low speed, a small transmissibility, much damping); else None.

    The sag M·g/k = g·r²/ω² is the mass's in nothing: r is the ratio that gives the wanted TR at the
    mounts' ζ, and grows with ζ (the damper passes force of its own), from √(1 + 1/TR) undamped.  So
    less damping, a larger TR or a higher speed each lower the sag; each is offered only where it
    reaches the limit alone, rounded to the side that keeps within it.  Mounts under a shaft's bearings
    sag M·g/k_m = g·r²/ω² − M·g/k_s: the shaft's own bending takes the rest.
    """
    wanted = spec.transmissibility
    if wanted is None:
        return None
    # A shaft soft enough by itself needs no mounts (None), and none can sag.
    stiffness = steady_state(spec).isolation_mount_stiffness
    if stiffness is None or not stiffness > 0:
        return None
    sag = spec.mass * STANDARD_GRAVITY / stiffness
    if sag <= MOST_MOUNT_SAG:
        return None
    # Mounts under a shaft's bearings are in series with it: the disc sinks g·r²/ω² in all, the shaft's own
    # bending M·g/k_s of it, and the mounts the rest.
    own = spec.mass * STANDARD_GRAVITY / spec.stiffness if spec.on_shaft else 0.0
    zeta, omega = spec.damping_ratio, spec.omega
    ratio = float(isolation_frequency_ratio(wanted, zeta))
    undamped = 1.0 + 1.0 / wanted  # r² that gives the wanted TR without damping
    # The largest r² a support whose mounts sag the most can have at this speed.
    reach = omega * omega * (MOST_MOUNT_SAG + own) / STANDARD_GRAVITY
    most_damping = undamped_sag = least = root_two_sag = None
    if zeta > 0 and undamped <= reach:
        # TR²·((1 − s)² + 4ζ²s) = 1 + 4ζ²s at s = reach, solved for ζ².
        most = math.sqrt((wanted * wanted * (1.0 - reach) ** 2 - 1.0) / (4.0 * reach * (1.0 - wanted * wanted)))
        most_damping = _rounded(most, down=True)
    elif zeta > 0:
        undamped_sag = STANDARD_GRAVITY * undamped / omega ** 2 - own
    if reach > 2.0:  # every ζ passes TR = 1 at r = √2: a larger TR reaches r = √reach
        rounded_up = _rounded(float(transmissibility(math.sqrt(reach), zeta)), down=False)
        if float(rounded_up) < 1.0:  # not rounded up to no isolation at all
            least = rounded_up
    else:
        root_two_sag = 2 * STANDARD_GRAVITY / omega ** 2 - own
    least_speed = ratio * math.sqrt(STANDARD_GRAVITY / (MOST_MOUNT_SAG + own)) / RPM
    return MountsSag(stiffness=stiffness, sag=sag, wanted=wanted, ratio=ratio, zeta=zeta,
                     undamped_ratio=math.sqrt(undamped), least_rpm=_rounded(least_speed, down=False),
                     rpm=omega / RPM, most_damping=most_damping, least_transmissibility=least,
                     undamped_sag=undamped_sag, root_two_sag=root_two_sag, shaft_sag=own)


def lengths_in_millimetres(spec: VibrationSpec) -> LengthsInMillimetres | None:
    """The machine's lengths that no machine has as metres, each with its key (``vibration.shaft.diameter``), as
    lengths typed in millimetres make them (an eccentricity too, where a rotor reaching so far would outweigh the
    whole machine); None where they are plausible (limits in :mod:`graphplan.rotor_lengths`)."""
    found = []
    if spec.eccentricity is not None and spec.eccentricity > LARGEST_RADIUS_M:
        found.append(Implausible("eccentricity", "vibration.eccentricity", spec.eccentricity, LARGEST_RADIUS_M))
    # m·e given whole needs e of at least m·e/M, the whole machine off its axis (unbalanced_mass may be no more than
    # mass): 1e6 kg·m on 100 kg went unwarned, and wrote an amplitude of 13 km, where the same e given apart is warned.
    if spec.eccentricity is None and spec.unbalance > LARGEST_RADIUS_M * spec.mass:
        found.append(Implausible("unbalance", "vibration.unbalance", spec.unbalance, LARGEST_RADIUS_M,
                                 other_key="vibration.mass", other=spec.mass))
    shaft = spec.shaft
    if shaft is not None:
        if shaft.diameter is not None and shaft.diameter > THICKEST_SHAFT_M:
            found.append(Implausible("diameter", "vibration.shaft.diameter", shaft.diameter, THICKEST_SHAFT_M))
        elif shaft.diameter is None and shaft.second_moment > LARGEST_SECOND_MOMENT_M4:
            found.append(Implausible("second_moment", "vibration.shaft.second_moment", shaft.second_moment,
                                     LARGEST_SECOND_MOMENT_M4))
        if shaft.length > LONGEST_ROTOR_M:
            found.append(Implausible("span", "vibration.shaft.length", shaft.length, LONGEST_ROTOR_M))
    base = spec.base_amplitude
    if base is not None and base * spec.omega > FASTEST_BASE_M_S:
        found.append(Implausible("base", "vibration.base_amplitude", base, FASTEST_BASE_M_S, other=spec.omega))
    eccentric = spec.eccentricity
    if eccentric is not None and eccentric <= LARGEST_RADIUS_M and lightest_rotor(eccentric) > spec.mass:
        found.append(Implausible("light_machine", "vibration.eccentricity", eccentric, lightest_rotor(eccentric),
                                 other_key="vibration.mass", other=spec.mass))
    return LengthsInMillimetres(tuple(found)) if found else None


@dataclass(frozen=True)
class SpeedInRpm:
    """The table's ``omega`` (rad/s, as typed) that reads as a motor's speed in rev/min."""

    omega: float
    code = "speed-in-rpm"

    @property
    def detail(self) -> str:
        """The warning in a line (English, as the command line prints it)."""
        return rpm_question("vibration.omega", self.omega, "vibration.rpm")


def speed_in_rpm(spec: VibrationSpec) -> SpeedInRpm | None:
    """The table's ``omega`` where it reads as a motor's speed in rev/min typed for rad/s
    (:func:`~graphplan.units.motor_speed_in_rpm`); None where it does not, or where the machine turns at the crank's
    speed (the driver's own key is warned of with the linkage)."""
    if spec.driver_speed or not motor_speed_in_rpm(spec.omega):
        return None
    return SpeedInRpm(spec.omega)


def cautions(spec: VibrationSpec) -> list[SpeedInRpm | LengthsInMillimetres | NearResonance | MountsSag]:
    """What the results hold that a reader should not take at face value: a speed that looks typed in rev/min,
    lengths that look typed in millimetres, a speed near resonance, isolating mounts no spring could be."""
    return [found for found in (speed_in_rpm(spec), lengths_in_millimetres(spec), near_resonance(spec),
                                mounts_sag(spec)) if found is not None]


def lengths_warning(spec: VibrationSpec) -> str | None:
    """The command line's line for :func:`lengths_in_millimetres`, or None."""
    found = lengths_in_millimetres(spec)
    return None if found is None else f"vibration: {found.detail}"


def speed_warning(spec: VibrationSpec) -> str | None:
    """The command line's line for :func:`speed_in_rpm`, or None."""
    found = speed_in_rpm(spec)
    return None if found is None else f"vibration: {found.detail}"


def resonance_warning(spec: VibrationSpec) -> str | None:
    """The command line's line for :func:`near_resonance`, or None."""
    found = near_resonance(spec)
    return None if found is None else f"vibration: {found.detail}"


def isolation_warning(spec: VibrationSpec) -> str | None:
    """The command line's line for :func:`mounts_sag`, or None."""
    found = mounts_sag(spec)
    return None if found is None else f"vibration: {found.detail}"


def unlikely_damping(spec: VibrationSpec) -> float | None:
    """The ``damping_ratio`` ζ where it is 1 or above, else None: critical or over-critical damping lets a mount creep
    back with no vibration at all, which no machine's mount does (they damp at a few hundredths to a few tenths), so
    such a ζ is rather a percentage typed for a fraction, as ``f`` and ``delta`` are told.  A damping c given in N·s/m
    is no ratio to mistype."""
    zeta = spec.damping_ratio
    return zeta if spec.damping is None and zeta >= 1 else None


def damping_words(zeta: float, text: Mapping[str, str], written: Callable[[float], str]) -> str:
    """What the command line and the note say of an :func:`unlikely_damping` ζ, in ``text``'s language, its numbers
    as ``written`` writes them: one source of the words for both."""
    # ζ = 1 exactly is critical damping, which a mount reaches only by design (an instrument's or a door closer's
    # dashpot, and those are tuned to some 0.6–0.7, the flattest response): typed as 1 it is far likelier 1 % than the
    # one ratio that marks the edge of vibrating at all, so it is asked as ζ = 2, 5, 10 are.  Below 1 nothing is told:
    # 0.7 is an instrument's design damping and 0.2–0.4 a viscous damper's.  Between 1 and 2 (1.5) the over-critical
    # line alone: 1.5 % is as likely a slip as an over-damped dashpot, and the line already says ζ is over 1.
    creeps = text["note_vib_damping_creeps"]
    question = text["percentage_question"].format(value=written(zeta), symbol="ζ", fraction=written(zeta / 100))
    if zeta == 1:
        return text["note_vib_damping_critical"].format(zeta=written(zeta), creeps=creeps, question=question)
    # From 100 up the percentage is no mount's ζ either: 1e6 "% is ζ = 10000" sent the student further astray.
    asked = text["semicolon"] + question if 2 <= zeta < 100 else ""
    return text["note_vib_damping_over_critical"].format(zeta=written(zeta), creeps=creeps, question=asked)


def damping_warning(spec: VibrationSpec) -> str | None:
    """The command line's line for an :func:`unlikely_damping` ζ, else None."""
    zeta = unlikely_damping(spec)
    if zeta is None:
        return None
    from .locale import strings

    return "vibration.damping_ratio: " + damping_words(zeta, strings("en"), lambda value: f"{value:g}")


def stiffness_warning(spec: VibrationSpec) -> str | None:
    """The command line's line for mounts given so soft for the machine that it would sink more than
    :data:`MOST_MOUNT_SAG` on them, M·g/k, as a stiffness typed in kN/m or N/mm, or a mass in grams, makes them;
    else None. A shaft's bending stiffness is left alone: a slender shaft does bend that far under its disc."""
    if spec.on_shaft:
        return None
    sag = spec.mass * STANDARD_GRAVITY / spec.stiffness
    if sag <= MOST_MOUNT_SAG:
        return None
    return (f"vibration.stiffness: k = {spec.stiffness:g} N/m would let the machine, vibration.mass = "
            f"{spec.mass:g} kg, sag M·g/k = {sag:.3g} m under its weight, more than any spring mount "
            f"({MOST_MOUNT_SAG * 1000:g} mm): a stiffness typed in kN/m or N/mm, or a mass in grams? "
            f"({spec.stiffness:g} kN/m is stiffness = {spec.stiffness * 1000:g}; {spec.mass:g} g is mass = "
            f"{spec.mass / 1000:g})")


def _rounded(value: float, *, down: bool, digits: int = 3) -> str:
    """``value`` to ``digits`` significant digits, rounded down or up (a bound offered must keep what it bounds), with
    no exponent."""
    step = digit_unit(value, digits)
    bound = (math.floor if down else math.ceil)(value / step) * step
    return np.format_float_positional(bound, precision=digits, unique=False, fractional=False, trim="-")


@dataclass(frozen=True)
class Response:
    """The steady vibration of a :class:`VibrationSpec` machine (SI, angles in radians)."""

    natural_frequency: float
    frequency_ratio: float
    magnification: float
    amplitude: float
    phase: float
    exciting_force: float
    transmissibility: float
    transmitted_force: float
    isolation_ratio: float | None
    isolation_stiffness: float | None
    base: BaseResponse | None = None
    combined: CombinedResponse | None = None
    # The mounts' own stiffness for the isolation: on mounts alone the support's, ``isolation_stiffness``; under a
    # shaft's bearings, in series with it, :func:`series_mount_stiffness` (None: the shaft alone is soft enough).
    isolation_mount_stiffness: float | None = None


@dataclass(frozen=True)
class BaseResponse:
    """The machine's steady motion where its base moves as y = Y·sin ωt (SI, the lag in radians).

    ``amplitude`` X = Y·TR, lagging the base by ``phase``; ``relative``
    Z = Y·r²/√((1 − r²)² + (2ζr)²), the mount's stroke; ``transmitted_force``
    the amplitude of the force the mounts pass, |(k + i·c·ω)·Z| = TR·M·ω²·Y (N).
    """

    base_amplitude: float
    amplitude: float
    phase: float
    relative: float
    transmitted_force: float = 0.0


@dataclass(frozen=True)
class CombinedResponse:
    """The machine's steady motion where the unbalance and the base both excite it (SI, the lag in radians).

    M·x″ + c·(x′ − y′) + k·(x − y) = m·e·ω²·sin ωt with y = Y·sin ωt is
    linear: its steady motion is the sum of the unbalance's and the base's,
    each with its own lag, the two taken in phase (a scene gives no angle
    between them).  As complex amplitudes over D = 1 − r² + i·2ζr,

        x = ((m·e/M)·r² + Y·(1 + i·2ζr)) / D,    x − y = (m·e/M + Y)·r² / D,

    so the mounts' strokes add in phase, and the force they pass,
    (k + i·cω)·(x − y), has the amplitude TR·ω²·(m·e + M·Y).
    ``amplitude`` X and its ``phase`` behind sin ωt; ``relative`` the
    mounts' stroke; ``transmitted_force`` (N).
    """

    amplitude: float
    phase: float
    relative: float
    transmitted_force: float


def steady_state(spec: VibrationSpec) -> Response:
    """Amplitude X = (m·e/M)·magnification, its lag φ, and the force m·e·ω²·TR passed to the base."""
    omega_n = natural_frequency(spec.stiffness, spec.mass)
    r = spec.omega / omega_n
    zeta = spec.damping_ratio
    magnification = unbalance_magnification(r, zeta)
    exciting = spec.unbalance * spec.omega ** 2
    tr = transmissibility(r, zeta)
    wanted = spec.transmissibility
    # The mounts pass k·Z + c·Z′ whatever moves them: |k + i·c·ω|·Z = k·√(1 + (2ζr)²)·Y·r²/√((1 − r²)² + (2ζr)²),
    # which is TR·M·ω²·Y since k·r² = M·ω².
    base = None if spec.base_amplitude is None else BaseResponse(
        base_amplitude=spec.base_amplitude, amplitude=spec.base_amplitude * displacement_transmissibility(r, zeta),
        phase=displacement_transmissibility_phase(r, zeta), relative=spec.base_amplitude * magnification,
        transmitted_force=tr * spec.mass * spec.omega ** 2 * spec.base_amplitude)
    combined = None if base is None or spec.unbalance == 0 else _combined(spec, r, zeta, tr)
    designed = None if wanted is None else isolation_stiffness(spec.mass, spec.omega, wanted, zeta)
    mounts = designed if designed is None or not spec.on_shaft else series_mount_stiffness(designed, spec.stiffness)
    return Response(
        natural_frequency=omega_n, frequency_ratio=r, magnification=magnification,
        amplitude=spec.unbalance / spec.mass * magnification, phase=phase(r, zeta), exciting_force=exciting,
        transmissibility=tr, transmitted_force=exciting * tr,
        isolation_ratio=None if wanted is None else isolation_frequency_ratio(wanted, zeta),
        isolation_stiffness=designed, base=base, combined=combined, isolation_mount_stiffness=mounts)


def _combined(spec: VibrationSpec, r: float, zeta: float, tr: float) -> CombinedResponse:
    """The unbalance's and the base's responses added as complex amplitudes (:class:`CombinedResponse`)."""
    assert spec.base_amplitude is not None
    denominator = complex(1.0 - r * r, 2.0 * zeta * r)
    own = spec.unbalance / spec.mass
    motion = (own * r * r + spec.base_amplitude * complex(1.0, 2.0 * zeta * r)) / denominator
    # Both parts lag by 0 to π, so their sum does too: −π (a zero imaginary part's sign) is π.
    lag = -math.atan2(motion.imag, motion.real)
    return CombinedResponse(amplitude=abs(motion), phase=lag + 2.0 * math.pi if lag < 0 else lag,
                            relative=(own + spec.base_amplitude) * r * r / abs(denominator),
                            transmitted_force=tr * spec.omega ** 2 * (spec.unbalance + spec.mass * spec.base_amplitude))


def vibration_results(spec: VibrationSpec) -> dict[str, Any]:
    """The steady vibration as the results file writes it: SI, angles in degrees, speeds also in rpm.

    ``amplitude`` (m), ``phase_deg`` and ``transmissibility`` are the
    contract's keys: the unbalance's response, ``phase_deg`` None where there
    is no unbalance (a zero amplitude has no lag); ``isolation`` appears when
    a transmissibility is wanted, ``base_excitation`` when the base moves, and
    ``combined`` when both the unbalance and the base excite the machine; ``warnings`` lists each
    :func:`cautions` as ``{code, detail}``.
    """
    response = steady_state(spec)
    document: dict[str, Any] = {
        "amplitude": response.amplitude,
        "phase_deg": math.degrees(response.phase) if spec.unbalance > 0 else None,
        "transmissibility": response.transmissibility,
        "magnification": response.magnification,
        "frequency_ratio": response.frequency_ratio,
        "damping_ratio": spec.damping_ratio,
        "natural_frequency": response.natural_frequency,
        "critical_speed": response.natural_frequency,
        "critical_speed_rpm": response.natural_frequency / RPM,
        "exciting_force": response.exciting_force,
        "transmitted_force": response.transmitted_force,
    }
    if spec.shaft is not None:
        document["stiffness"] = spec.stiffness
    if spec.transmissibility is not None:
        document["isolation"] = {"transmissibility": spec.transmissibility,
                                 "frequency_ratio": response.isolation_ratio,
                                 "stiffness": response.isolation_stiffness,
                                 "mount_stiffness": response.isolation_mount_stiffness}
    if response.base is not None:
        document["base_excitation"] = {"base_amplitude": response.base.base_amplitude,
                                       "amplitude": response.base.amplitude,
                                       "phase_deg": math.degrees(response.base.phase),
                                       "relative_amplitude": response.base.relative,
                                       "transmitted_force": response.base.transmitted_force}
    if response.combined is not None:
        document["combined"] = {"amplitude": response.combined.amplitude,
                                "phase_deg": math.degrees(response.combined.phase),
                                "relative_amplitude": response.combined.relative,
                                "transmitted_force": response.combined.transmitted_force}
    # Recorded beside the numbers they qualify: the command line's warning is gone once the run is over.
    document["warnings"] = [{"code": found.code, "detail": found.detail} for found in cautions(spec)]
    return document


# --- the scene table -------------------------------------------------------------------------------


# The symbols the textbooks write a machine's and its shaft's keys as (lower case, as ``Table.named_otherwise``
# compares them); the speed's (n, ω) are told by ``Table.speed``.
_MACHINE_SYMBOLS = (("stiffness", frozenset({"k"}), "the mounts' stiffness"),
                    ("unbalance", frozenset({"me", "m·e", "m*e", "m_e"}), "the unbalance m·e"),
                    ("eccentricity", frozenset({"e"}), "the eccentricity"),
                    ("damping_ratio", frozenset({"zeta", "ζ", "xi"}), "the damping ratio ζ"),
                    ("damping", frozenset({"c"}), "the damping coefficient c"),
                    ("transmissibility", frozenset({"tr"}), "the transmissibility wanted"),
                    ("base_amplitude", frozenset({"y"}), "the base's amplitude Y"))
_SHAFT_SYMBOLS = (("modulus", frozenset({"e"}), "the shaft's modulus of elasticity E"),
                  ("diameter", frozenset({"d"}), "the shaft's diameter"),
                  ("second_moment", frozenset({"i"}), "the shaft's second moment of area I"),
                  ("length", frozenset({"l"}), "the shaft's span"),
                  ("position", frozenset({"a"}), "the disc's place on the shaft"))


def read_vibration(table: Table, driver_speed: float | None = None) -> VibrationSpec:
    """The ``[vibration]`` table of a scene as a :class:`VibrationSpec`, each bad key named by its path.

    ``mass``; ``unbalance`` (m·e) or ``unbalanced_mass`` and ``eccentricity``;
    ``stiffness`` or ``shaft = {modulus, second_moment or diameter, length,
    position, support}``; ``damping_ratio`` or ``damping`` (c; neither: 0);
    ``omega`` or ``rpm`` (or neither where ``driver_speed``, a linkage's crank's
    |ω| in rad/s, is given: the machine turns at it); ``transmissibility``
    (wanted, optional); ``base_amplitude`` (m, optional: the base moving at ω too).
    """
    # A key written as the textbook's symbol is named with the one to write: "stiffness: is required (or shaft)" left
    # the k typed for it unmentioned.
    for key, symbols, what in _MACHINE_SYMBOLS:
        table.named_otherwise(key, symbols, what)
    mass = table.number("mass", positive=True)
    # The note writes a quantity below the rounding noise as 0, as no machine's is so small: a machine of 1e-14 kg
    # ended the run in ZeroDivisionError as the note worked out ωn = √(k/M) with M written 0.
    if mass <= ROUNDING_NOISE:
        raise SceneError(table.where("mass"), f"{written_as_nought('kg')}: no machine on mounts is so light (the mass "
                         "is in kg)", mass, hint="; a slip of the exponent?")
    unbalance, eccentricity = _unbalance(table, mass)
    shaft = _shaft(table)
    stiffness = table.number("stiffness", positive=True) if shaft is None else shaft.stiffness
    if stiffness <= ROUNDING_NOISE:
        # A shaft's k = 48·E·I/L³ (or its support's) of a modulus typed some powers of ten short comes out so small.
        key, typed = ("stiffness", stiffness) if shaft is None else ("shaft", table.data["shaft"])
        raise SceneError(table.where(key), f"{written_as_nought('N/m', f'gives a stiffness of {stiffness:.3g} N/m')}: "
                         "no mount or shaft is so soft (k is in N/m, a shaft's modulus in Pa)", typed,
                         hint="; a slip of the exponent?")
    given = table.has("omega") or table.has("rpm")
    omega = table.speed(positive=True) if driver_speed is None else table.speed(driver_speed, positive=True)
    if given:
        _refuse_speed(table, omega, unbalance)
    zeta = _damping(table, stiffness, mass)
    wanted = table.number("transmissibility", None, positive=True)
    base = table.number("base_amplitude", None, positive=True)
    if wanted is not None and not wanted < 1:
        # "Isolate to 10 %" typed as 10: a TR up to 100 may be a percentage, and is told so.
        percentage = f"; {percentage_question(wanted, 'TR')}" if wanted < 100 else ""
        raise SceneError(table.where("transmissibility"), "must be below 1: a mount isolates only where TR < 1",
                         wanted, hint=percentage)
    table.done(elsewhere=keys_of_other_tables("vibration"))
    if zeta == 0 and at_resonance(omega, stiffness, mass):
        if not given:
            raise SceneError(table.path, f"turns at the crank's speed, ω = {omega:.6g} rad/s, which is the natural "
                                         "frequency, and there is no damping: the amplitude has no bound; give "
                                         "damping, or another speed (omega or rpm)")
        raise SceneError(table.where("omega" if table.has("omega") else "rpm"),
                         "is the natural frequency and there is no damping: the amplitude has no bound")
    if unbalance == 0 and base is None:
        raise SceneError(table.where("unbalance" if table.has("unbalance") else "eccentricity"),
                         "is 0 and the base does not move (no base_amplitude): nothing excites the machine")
    return VibrationSpec(mass=mass, unbalance=unbalance, stiffness=stiffness, damping_ratio=zeta, omega=omega,
                         transmissibility=wanted, base_amplitude=base, shaft=shaft,
                         damping=table.number("damping") if table.has("damping") else None, eccentricity=eccentricity,
                         driver_speed=not given)


def _refuse_speed(table: Table, omega: float, unbalance: float) -> None:
    """Raise :class:`SceneError` at the table's ``omega`` or ``rpm`` for a speed (``omega`` rad/s, as read) outside
    :data:`SLOWEST_RPM`–:data:`FASTEST_RPM`, told in the unit it was typed in."""
    key = "omega" if table.has("omega") else "rpm"
    rpm = omega / RPM
    if SLOWEST_RPM <= rpm <= FASTEST_RPM:
        return
    fastest = f"{FASTEST_RPM:,.0f}".replace(",", " ")
    bounds = (f"{SLOWEST_RPM:g}–{fastest} rpm" if key == "rpm" else
              f"{SLOWEST_RPM * RPM:.4g}–{FASTEST_RPM * RPM:.6g} rad/s ({SLOWEST_RPM:g}–{fastest} rpm)")
    force = f": the exciting force m·e·ω² would be {unbalance * omega * omega:.3g} N" if unbalance else ""
    raise SceneError(table.where(key), f"must be within {bounds}, as a machine's rotor turns (a fan's some 1000 "
                     f"rpm, a turbocharger's up to some 300 000){force}", table.data[key],
                     hint=exponent_slip(rpm, SLOWEST_RPM, FASTEST_RPM))


def _one_of(table: Table, first: str, second: str, purpose: str) -> str:
    """Which of two alternative keys the table gives; exactly one of them must be there."""
    if table.has(first) and table.has(second):
        raise SceneError(table.where(second), f"give either {first} or {second}, not both")
    if not table.has(first) and not table.has(second):
        table.misspelt(first, second)
        raise SceneError(table.where(first), f"is required (or {second}): {purpose}")
    return first if table.has(first) else second


def _unbalance(table: Table, mass: float) -> tuple[float, float | None]:
    """m·e (kg·m), and e (m) where the table gives it apart."""
    whole = table.has("unbalance")
    parts = table.has("unbalanced_mass") or table.has("eccentricity")
    if whole and parts:
        raise SceneError(table.where("unbalance"), "give either unbalance (m·e) or unbalanced_mass and eccentricity, "
                                                   "not both")
    if not parts:
        if not whole:
            raise SceneError(table.where("unbalance"), "is required (m·e, kg·m), or unbalanced_mass and eccentricity")
        return table.number("unbalance", non_negative=True), None
    # One of the pair without the other is told with the pair's purpose and the whole m·e it stands for, not as a
    # key "required but missing" that the scene need not give at all.
    for key, other, what in (("unbalanced_mass", "eccentricity", "the unbalanced mass m, kg"),
                             ("eccentricity", "unbalanced_mass", "the unbalanced mass's distance e from the axis, m")):
        if not table.has(key):
            table.misspelt(key)
            raise SceneError(table.where(key), f"is required with {other}: {what}; or give unbalance (m·e, kg·m) "
                             f"alone in place of both")
    small = table.number("unbalanced_mass", positive=True)
    eccentricity = table.number("eccentricity", non_negative=True)
    if small > mass:
        raise SceneError(table.where("unbalanced_mass"), f"must not exceed mass ({mass:g} kg), which includes it",
                         small)
    return small * eccentricity, eccentricity


def _shaft(table: Table) -> Shaft | None:
    """The shaft whose stiffness the machine is on, or None where the table gives the mounts' stiffness."""
    if _one_of(table, "stiffness", "shaft", "the mounts' stiffness, N/m, or shaft = { modulus, diameter, length }, "
               "the shaft the machine turns on") == "stiffness":
        return None
    shaft = table.table("shaft")
    assert shaft is not None
    for key, symbols, what in _SHAFT_SYMBOLS:
        shaft.named_otherwise(key, symbols, what)
    modulus = shaft.number("modulus", positive=True)
    if not SOFTEST_SHAFT <= modulus <= STIFFEST_SHAFT:
        meant = next((f"; {unit} typed for Pa? {modulus:g} {unit} is modulus = {modulus * factor:g}"
                      for factor, unit in ((1e6, "MPa"), (1e9, "GPa")) if SOFTEST_SHAFT <= modulus * factor
                      <= STIFFEST_SHAFT), "")
        raise SceneError(shaft.where("modulus"), f"must be within {SOFTEST_SHAFT:g}–{STIFFEST_SHAFT:g} Pa, as shafts "
                         "are made (steel's 2.1e11, a polymer's some 3e9): E is in Pa", modulus, hint=meant)
    if shaft.has("second_moment") and shaft.has("diameter"):
        raise SceneError(shaft.where("diameter"), "give either second_moment or diameter, not both")
    if not shaft.has("diameter") and not shaft.has("second_moment"):
        # Either key names the section: a misspelling of either is told as one, not as the other one missing.
        shaft.misspelt("diameter", "second_moment")
        raise SceneError(shaft.where("diameter"), "is required (the shaft's diameter, m), or second_moment (I, m⁴): "
                                                  "give diameter or second_moment")
    diameter = shaft.number("diameter", positive=True) if shaft.has("diameter") else None
    second = circular_second_moment(diameter) if diameter is not None else shaft.number("second_moment", positive=True)
    length = shaft.number("length", positive=True)
    position = shaft.number("position", None, positive=True)
    support = check_choice(shaft.raw("support", "simply_supported"), shaft.where("support"), SUPPORTS)
    shaft.done()
    if position is not None and support == "simply_supported" and not position < length:
        raise SceneError(shaft.where("position"), f"the disc must lie between the bearings, below length ({length:g} m)",
                         position)
    if position is not None and support == "cantilever" and not position <= length:
        raise SceneError(shaft.where("position"), f"the disc must lie on the shaft, at most length ({length:g} m) "
                                                  "from its fixed end", position)
    return Shaft(modulus, float(second), length, position, support, diameter)


def _damping(table: Table, stiffness: float, mass: float) -> float:
    if table.has("damping_ratio") and table.has("damping"):
        raise SceneError(table.where("damping"), "give either damping_ratio or damping (c), not both")
    key = "damping" if table.has("damping") else "damping_ratio"
    zeta = float(damping_ratio(table.number("damping", non_negative=True), stiffness, mass)) if key == "damping" \
        else table.number("damping_ratio", 0.0, non_negative=True)
    # ζ = 1e-12 was warned of near resonance as "little damping (ζ = 0)": the note writes it 0, as none.
    if 0 < zeta <= ROUNDING_NOISE:
        worked = f"it gives ζ = c/(2·√(k·M)) = {zeta:.3g}" if key == "damping" else ""
        raise SceneError(table.where(key), f"{written_as_nought('', worked)}, or 0 for none (the "
                         "damping ratio ζ is a share of the critical damping)", table.data[key])
    return zeta


__all__ = [
    "NEAR_RESONANCE",
    "RESONANCE_TOLERANCE",
    "BaseResponse",
    "CombinedResponse",
    "MountsSag",
    "NearResonance",
    "Response",
    "Shaft",
    "SpeedInRpm",
    "VibrationSpec",
    "at_resonance",
    "cautions",
    "circular_second_moment",
    "critical_speed",
    "damping_from_phase",
    "damping_from_resonance",
    "damping_ratio",
    "damping_warning",
    "damping_words",
    "displacement_transmissibility",
    "displacement_transmissibility_phase",
    "force_magnification",
    "isolation_frequency_ratio",
    "isolation_stiffness",
    "isolation_warning",
    "lengths_in_millimetres",
    "lengths_warning",
    "mounts_sag",
    "natural_frequency",
    "near_resonance",
    "phase",
    "read_vibration",
    "resonance_warning",
    "series_mount_stiffness",
    "shaft_stiffness",
    "speed_in_rpm",
    "speed_warning",
    "steady_state",
    "stiffness_warning",
    "transmissibility",
    "unbalance_magnification",
    "unlikely_damping",
    "vibration_results",
]
