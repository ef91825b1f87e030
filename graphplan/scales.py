"""Scale factors as the textbooks choose them: round standard values.

A scale factor μ says how many units of a quantity one millimetre of the
drawing stands for (m/mm, (m/s)/mm, ...).  When the scene does not fix one,
the smallest standard value is taken that still fits the drawing into its
field, so that the drawing is as large as the field allows and every length
read off it is a round multiple.
"""

from __future__ import annotations

import math

# How the drawings write a number too large or too small to read whole: a leaf of no imports of its own.
from .render.numerals import POWER_OF_TEN, power_of_ten

# No paper is longer (mm; a roll plotter's): a μl that draws the mechanism larger is a slip, refused before
# anything is drawn, since the hatching along a guide alone would take all the memory there is.
LARGEST_PAPER_MM = 5000.0

# Mantissas of the standard scale factors, as in drafting scales 1:1, 1:2, 1:2.5, 1:4, 1:5.
STANDARD_MANTISSAS = (1.0, 2.0, 2.5, 4.0, 5.0)


def standard_scale(least: float) -> float:
    """The smallest standard scale factor ≥ ``least`` (which must be > 0)."""
    if not least > 0 or not math.isfinite(least):
        raise ValueError(f"a scale factor must be positive and finite, not {least!r}")
    exponent = math.floor(math.log10(least))
    for power in (exponent, exponent + 1):
        for mantissa in STANDARD_MANTISSAS:
            value = float(f"{mantissa}e{power}")
            if value >= least * (1 - 1e-12):
                return value
    raise AssertionError("unreachable: 10^(exponent+1) ≥ least")


def nearest_standard_scale(value: float) -> float:
    """The standard scale factor nearest ``value`` (which must be > 0) by ratio: the one a drawing found at
    ``value`` was most likely drawn at."""
    exponent = math.floor(math.log10(value))
    near = [float(f"{mantissa}e{power}") for power in (exponent - 1, exponent, exponent + 1)
            for mantissa in STANDARD_MANTISSAS]
    return min(near, key=lambda candidate: abs(math.log(candidate / value)))


def next_standard_scale(scale: float) -> float:
    """The standard scale factor just above ``scale``: the drawing a step smaller."""
    return standard_scale(scale * (1.0 + 1e-9))


def finer_standard_scale(scale: float, steps: int = 1) -> float:
    """The standard scale factor ``steps`` standard steps below ``scale``: the drawing that many steps larger
    (0.004 → 0.0025 → 0.002, 5 → 4)."""
    for _ in range(steps):
        exponent = math.floor(math.log10(scale))
        below = [float(f"{mantissa}e{power}") for power in (exponent - 1, exponent) for mantissa in STANDARD_MANTISSAS]
        scale = max(value for value in below if value < scale * (1.0 - 1e-9))
    return scale


def fit_scale(extent: float, field_mm: float) -> float:
    """The standard scale at which ``extent`` (SI units) fits in ``field_mm`` millimetres."""
    return standard_scale(max(extent, 1e-300) / field_mm)


# Below this, as from the drawings' POWER_OF_TEN on, a scale factor is written as a power of ten (2.5·10⁻¹²,
# 1·10⁹): whole, its noughts are not read.
_SMALLEST_WHOLE_SCALE = 1e-10


def format_scale(value: float) -> str:
    """A scale factor as written on a drawing: 0.0025, not 2.5e-03; 10000000, not 1e+07 (a 450 MN press's μF
    was written "1e+07 Н/мм" on its force sheet, the only exponent of the drawings)."""
    if value and not _SMALLEST_WHOLE_SCALE <= abs(value) < POWER_OF_TEN:
        return power_of_ten(value, 7)
    return f"{value:.10f}".rstrip("0").rstrip(".")
