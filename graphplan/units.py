"""Units a scene may give that are not SI, as factors to SI; and lengths typed in millimetres where metres are
asked for: how far apart two lengths of one machine stand before one is taken for millimetres, and the question
the warnings then ask; and the question asked of a fraction typed as its percentage."""

from __future__ import annotations

import math

#: rad/s in one revolution per minute.
RPM = math.pi / 30.0

#: A length this many times another of the same machine is one typed in millimetres among metres: a linkage's
#: lengths stand within some 1:50 of each other (a shaper's 0.1 m crank beside its 0.6 m rocker is 1:6), and a
#: rotor's masses turn within as much of the radius their corrections are fixed at.
MIXED_RATIO = 200.0


def percentage_question(value: float, symbol: str) -> str:
    """The question a refusal or a warning asks of a fraction typed as its percentage (δ = 5 for 5 %), with the
    fraction that percentage is."""
    return f"a percentage typed for a fraction? ({value:g} % is {symbol} = {value / 100:g})"


def millimetres_question(*, some: bool = False, second_moment: bool = False) -> str:
    """The question a warning about lengths in millimetres ends with, and the fix: every length divided by 1000
    (and a second moment of area, mm⁴, by 10¹²), or, where only ``some`` are in millimetres among metres, those
    alone (dividing every length would spoil the ones in metres)."""
    if some:
        return "are some lengths in millimetres? The scene's lengths are all in metres (divide millimetres by 1000)"
    also = ", a second moment of area by 10¹²" if second_moment else ""
    return f"are the lengths in millimetres? The scene's lengths are in metres (divide them by 1000{also})"
