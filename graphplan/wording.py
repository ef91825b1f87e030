"""Phrases that the report and the drawings both write, composed once so that they never disagree.

The numbers come in written: the report writes more digits and its own
decimal mark, a drawing four digits that the SVG writer localises.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping

from .locale import Count, load_symbol
from .mechanism import Mechanism
from .statics import delivers_power, rounded_zero, turned_round

# A component written with a caret (the plans' aBA^τ, aBB4^r), which a reader would see as a caret beside
# aBAⁿ and aBA4ᵏ: r raised as its modifier letter, τ, which has none, on the line as in R23τ.  After a point's
# name in any alphabet (aВА^τ of a Russian scheme's points), before no letter.
_CARET_COMPONENT = re.compile(r"(?<=[^\W_])\^([τr])(?![^\W\d_])")
_RAISED = {"τ": "τ", "r": "ʳ"}


def raised(text: str) -> str:
    """Symbols with no caret, as the note and the drawings write them: aBA^τ as aBAτ, aBB4^r as aBB4ʳ (the note's
    HTML, LaTeX and Word documents set both as superscripts, :mod:`graphplan.report.symbols`)."""
    return _CARET_COMPONENT.sub(lambda found: _RAISED[found[1]], text)


def balancing_symbol(mechanism: Mechanism, text: Mapping[str, str]) -> tuple[str, str]:
    """The balancing load's symbol and its unit in ``text``'s locale: (Mb, N·m) for a crank, (Fb, N) for a slider;
    in Russian (Mу, Н·м) and (Fу, Н).  The symbol is for the reader: what the load is, ask the driver's kind."""
    if mechanism.driver.kind == "crank":
        return load_symbol("Mb", text), text["newton_metre"]
    return load_symbol("Fb", text), text["newton"]


def balancing_load(mechanism: Mechanism, text: Mapping[str, str], lower: bool = False) -> str:
    """The balancing load by its name in ``text``'s locale: the balancing moment of a crank, the force of a slider
    (a Russian note says «уравновешивающий момент», not the generic «нагрузка»)."""
    words = text["balancing_moment_words" if mechanism.driver.kind == "crank" else "balancing_force_words"]
    return words[:1].lower() + words[1:] if lower else words


def driver_at(mechanism: Mechanism, text: Mapping[str, str], value: float, write: Callable[[float], str]) -> str:
    """Where the driver is, its coordinate written by ``write``: "φ = 325.05°" for a crank, "s = 0.12 m" for a
    slider."""
    if mechanism.driver.kind == "crank":
        return f"φ = {write(math.degrees(value) % 360.0)}°"
    return f"s = {write(value)} {text['unit_m']}"


def locked_between(mechanism: Mechanism, text: Mapping[str, str], numbers, span,
                   write: Callable[[float], str], key: str = "forces_locked_between") -> str:
    """The sentence on a stretch between two positions where the friction locks the mechanism
    (:class:`graphplan.locking.LockedSpan`), or with ``key`` ``forces_turned_round_between`` where it holds
    the loads that would drive it."""
    return text[key].format(
        after=numbers[span.after], next=numbers[(span.after + 1) % len(numbers)],
        start=driver_at(mechanism, text, span.start, write), end=driver_at(mechanism, text, span.end, write))


def friction_summary(mechanism: Mechanism, text: Mapping[str, str], ideal: float, load: float, *,
                     write: Callable[[float], str], iterations: int, written_efficiency: str,
                     scale: float = 0.0) -> str:
    """The balancing load with friction (``load``) after its repetitions, the one without (``ideal``), and η,
    each number written by ``write``; ``ideal`` is rounding of a zero beside ``scale`` as
    :func:`graphplan.statics.efficiency` takes it.

    η is named by the ratio it is: Mb0/Mb where the driver delivers power,
    Mb/Mb0 where the loads drive it back.  Where friction turns that flow
    round, the sentence says so instead of giving an η.
    """
    name, unit = balancing_symbol(mechanism, text)
    ideal = float(rounded_zero(ideal, load, scale))
    values = {"name": name, "value": write(load), "unit": unit, "iterations": Count(iterations), "ideal": write(ideal)}
    if turned_round(mechanism, ideal, load, scale):
        return text["forces_turned_round"].format(**values)
    ratio = f"{name}0/{name}" if delivers_power(mechanism, ideal) else f"{name}/{name}0"
    return text["forces_with_friction"].format(**values, ratio=ratio, efficiency=written_efficiency)
