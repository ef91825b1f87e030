"""How a number is written on a drawing: short, with no exponent, and a true minus sign.

The SVG writer puts in the locale's decimal mark; these functions write the point.  A number too large to
read written out whole (a steel's E, a reaction near a lock) is written as a power of ten, 2.1·10¹¹.
"""

from __future__ import annotations

import math

from ..rounding import ROUNDING_NOISE

# From this magnitude on a number is written as a power of ten (a steel's E = 2.1·10¹¹ Pa): whole, it would run to
# more digits than are read.
POWER_OF_TEN = 1e9
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def power_of_ten(value: float, digits: int) -> str:
    """``value`` as ``m·10ⁿ`` with ``digits`` significant digits in m (trailing noughts dropped) and a true minus."""
    mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
    mantissa = mantissa.rstrip("0").rstrip(".") if "." in mantissa else mantissa
    return f"{mantissa}·10{str(int(exponent)).translate(_SUPERSCRIPT)}".replace("-", "−")


def significant(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant digits, no exponent, a true minus sign, no minus on a nought."""
    value = float(value)
    if value == 0 or not math.isfinite(value):
        return "0"
    if abs(float(f"{value:.{digits}g}")) >= POWER_OF_TEN:
        return power_of_ten(value, digits)
    # The digits counted from the value as rounded: 0.99999999 rounds to 1.000, whose first digit stands a place
    # higher than its own, and counted from it gave one digit more (1.0000).
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(float(f"{value:.{digits}g}")))))
    text = f"{value:.{decimals}f}"
    return text.replace("-", "−") if text.strip("-0.") else "0"


def number(value: float, digits: int = 5, mark: str = ".") -> str:
    """``value`` to ``digits`` significant digits with a true minus sign and the locale's decimal mark.

    A value of :data:`ROUNDING_NOISE` or less is 0; others are written without an exponent: one of
    ``digits`` places before the point or more whole (868600, not 8.686e+05), a small one in decimals
    (0.000036362, not 3.6362e−05), one of 10⁹ or more as a power of ten (2.1·10¹¹).  The note's numbers, and the
    command line's where a warning writes a quantity the note writes too: a reader sees one number in both.
    """
    if not math.isfinite(value):
        return "—"
    if abs(value) < ROUNDING_NOISE:
        return "0"
    text = f"{value:.{digits}g}"
    if abs(float(text)) >= POWER_OF_TEN:
        return power_of_ten(value, digits).replace(".", mark)
    if "e+" in text:
        text = f"{float(text):.0f}"
    elif "e-" in text:
        text = f"{float(text):.{digits - 1 - math.floor(math.log10(abs(float(text))))}f}".rstrip("0")
    text = "0" if text in ("-0", "0") else text.replace("-", "−")
    return text.replace(".", mark)


def worked_out(value: float, digits: int = 5) -> str:
    """A result worked out to ``digits`` significant digits, its trailing noughts kept; rounding noise
    (:data:`~graphplan.rounding.ROUNDING_NOISE`) is 0 and a value that is not a number a dash, as the note writes them.

    ωmin = 10.210 beside ωmax = 10.734: written 10.21, it reads as a value known to a digit less than the other,
    and the drawing and the note that write it so say the same number to different digits.
    """
    value = float(value)
    if not math.isfinite(value):
        return "—"
    return "0" if abs(value) < ROUNDING_NOISE else significant(value, digits)


def steady_delta(delta: float) -> str:
    """The δ = (ωmax − ωmin)/ωm of an integrated steady run as the note, the motion plot and the command line write
    it: four significant digits, the simulation's, noughts kept (0.02350, where 0.0235 reads as known to a digit
    less)."""
    return worked_out(delta, 4)


def angle_in_turn(angle_deg: float) -> str:
    """An angle of [0°, 360°) to a tenth of a degree, its nought kept (211.0, not 211); one that rounds to a whole
    turn is 0.0."""
    return f"{round(float(angle_deg), 1) % 360.0:.1f}"


def short(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant digits with the trailing noughts dropped: 0.05, not 0.05000.

    For tick labels and quantities worked out where a trailing nought would claim a digit nobody
    measured; a value that is not a number is written as it is (nan, inf).
    """
    value = float(value)
    if not math.isfinite(value):
        return str(value)
    text = significant(value, digits)
    return text.rstrip("0").rstrip(".") if "." in text else text


def scale_factor(value: float) -> str:
    """A scale factor fixed by a pole distance: four significant digits, five decimals at least.

    A standard value stays short (0.0004); the rest is rounded (0.0198333… → 0.01983, 0.50575 stays).
    """
    decimals = max(5, 3 - math.floor(math.log10(abs(value)))) if value else 5
    text = f"{value:.{decimals}f}".rstrip("0").rstrip(".")
    return text or "0"
