"""Rounding noise: the digits a computed value is trusted to, and the size below which a value of a quantity is
the noise its arithmetic leaves (a velocity that is zero by the geometry computed as 1e-18).

It knows nothing of linkages, so that the equilibrium's efficiency (``statics``) and ``results.json``
(``report/results``) judge noise by one rule.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

#: The significant digits a value is written to, and trusted to beside its quantity's largest.
SIGNIFICANT = 12
#: A value this small beside its quantity's largest is rounding noise.
RELATIVE_NOISE = 10.0 ** -SIGNIFICANT
# Angles are judged against the full turn and percentages against the whole,
# whatever the largest of them happens to be.
ANGLE_FLOOR_DEG = 360.0 * RELATIVE_NOISE
PERCENT_FLOOR = 100.0 * RELATIVE_NOISE
# A number this small (SI units, degrees, per cent) is what the arithmetic leaves of a nought: a dead centre's
# acceleration, a reaction no load calls for, the difference of two methods that agree, a direction of
# 1e−14°.  No quantity of a machine's analysis is this small, so the note writes it 0, as a student writes it, and
# the force sheets leave out no vector for it.
ROUNDING_NOISE = 1e-10


def written_as_nought(unit: str, worked_out: str = "") -> str:
    """Why a scene's value of no more than :data:`ROUNDING_NOISE` is refused, in the one wording every key's refusal
    gives: the note and the drawings write it 0 (``render/numerals.number``), beside the values given, as though
    it were not there.  ``unit`` is the value's; ``worked_out`` the quantity worked out of the key's values that is
    that small, where the key's own value is not (``its m·r = 1e-06·1e-05 = 1e-11 kg·m``), said first."""
    lead = f"{worked_out}, which " if worked_out else ""
    unit = f" {unit}" if unit else ""  # a ratio's has none
    return f"{lead}must be above {ROUNDING_NOISE:g}{unit}, the size the note and the drawings write as 0"


def largest_finite(values: Any) -> float:
    """The largest finite magnitude among ``values`` (real or complex), 0 where none is finite."""
    magnitudes = np.abs(np.asarray(values, dtype=complex if np.iscomplexobj(values) else float))
    finite = magnitudes[np.isfinite(magnitudes)]
    return float(finite.max()) if finite.size else 0.0


def noise_floor(values: Any) -> float:
    """The size below which a value of ``values``' quantity is rounding noise:
    :data:`SIGNIFICANT` digits of the largest finite one."""
    return largest_finite(values) * RELATIVE_NOISE


def digit_unit(value: float, digits: int) -> float:
    """The unit of the last of ``digits`` significant digits of ``value`` (> 0): 0.0001 for 0.7295 to four."""
    return 10.0 ** (math.floor(math.log10(value)) - digits + 1)


def rounded_up(value: float, digits: int = 2) -> float:
    """``value`` (> 0) to ``digits`` significant digits, rounded up: the least a refusal asks for, which rounded to
    the nearest could be a value the same refusal refuses."""
    unit = digit_unit(value, digits)
    return float(f"{math.ceil(value / unit) * unit:.{digits}g}")


# A bound that is a four-figure number to rounding (0.7 − 0.4 = 0.29999999999999993) is that number, not below it:
# in units of the fourth figure, this close to a whole one.
_FIGURES_ROUNDING = 1e-6


def figures_above(value: float) -> float:
    """The least number of four significant figures above ``value`` (> 0): a bound offered that clears the one it
    bounds, which met would still fail (a length that just closes a group stands its links in line)."""
    unit = digit_unit(value, 4)
    return (math.floor(value / unit + _FIGURES_ROUNDING) + 1) * unit


def figures_below(value: float) -> float:
    """The greatest number of four significant figures below ``value`` (> 0), as :func:`figures_above`."""
    unit = digit_unit(value, 4)
    return (math.ceil(value / unit - _FIGURES_ROUNDING) - 1) * unit


__all__ = ["ANGLE_FLOOR_DEG", "PERCENT_FLOOR", "RELATIVE_NOISE", "ROUNDING_NOISE", "SIGNIFICANT", "digit_unit",
           "figures_above", "figures_below", "largest_finite", "noise_floor", "rounded_up", "written_as_nought"]
