"""Hand readings (``[measured.N]``) far off the plan as constructed: a length misread, a segment taken for
another, or a whole plan drawn at another scale than the scene's.

A plan drawn with care keeps within a few per cent of the construction, and
a short segment within the drafting precision of its two ends; a reading
beyond both is a slip.  Where every reading of one plan stands in the same
ratio to the construction, the slip is the plan's scale, not its lengths:
the student laid off the driver's velocity (or acceleration) at another
pole distance, and the warning gives the scale that makes the readings agree.
"""

from __future__ import annotations

import statistics
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

from .check import ErrorRow, is_reaction
from .motion import PositionWarning

if TYPE_CHECKING:
    from .analysis import VelocityPosition
    from .scene import Scene

# A hand reading this far (per cent) from the same quantity of the plan as constructed is a misread length or
# a segment taken for another, not a drawing's error ...
FAR_OFF_PERCENT = 15.0
# ... and this many drafting precisions off in millimetres, a short segment's reading being as good as its two ends.
FAR_OFF_PRECISIONS = 2.0

_SCALES = {"velocity": ("μV", "(m/s)/mm"), "acceleration": ("μa", "(m/s²)/mm")}


@dataclass(frozen=True)
class Slips:
    """A position's hand readings far off its construction.

    ``rescaled``: by plan kind, the one ratio of every reading to the
    construction and the scale (μV, μa) at which the readings agree.
    ``misread``: by the reading as the scene writes it (``pb = 25.9 mm``),
    the error rows it gives far off, each with the constructed value.
    """

    rescaled: Mapping[str, tuple[float, float]]
    misread: Mapping[str, tuple[tuple[ErrorRow, float], ...]]


def slips(position: VelocityPosition, precision: float) -> Slips | None:
    """The hand readings of ``position`` far off its constructed plans, or None where all are near."""
    constructed = {row.quantity: row.plan for row in position.errors if row.source == "construction"}
    measured = [(row, constructed[row.quantity]) for row in position.errors
                if row.source == "measured" and row.quantity in constructed]
    far = [(row, plan) for row, plan in measured if _far_off(row, plan, precision)]
    if not far:
        return None
    rescaled = {}
    for kind in _SCALES:
        ratio = _one_ratio([(row, plan) for row, plan in measured if _plan_of(row) == kind])
        if ratio is not None and any(_plan_of(row) == kind for row, _ in far):
            rescaled[kind] = (ratio, position.plans[kind].scale / ratio)
            far = [(row, plan) for row, plan in far if _plan_of(row) != kind]
    misread: dict[str, list[tuple[ErrorRow, float]]] = {}
    for row, plan in far:
        misread.setdefault(row.reading, []).append((row, plan))
    return Slips(rescaled, {reading: tuple(rows) for reading, rows in misread.items()})


def misread(scene: Scene, drawn: Iterable[VelocityPosition]) -> tuple[PositionWarning, ...]:
    """A ``measured-far-off`` warning at each position with hand readings far off its constructed plans."""
    precision = scene.drawing.drafting_precision
    warnings = []
    for position in drawn:
        found = slips(position, precision)
        if found is None:
            continue
        details = []
        for kind, (ratio, drawn_at) in found.rescaled.items():
            symbol, unit = _SCALES[kind]
            if in_units(drawn_at):
                quantity = unit.removeprefix("(").removesuffix(")/mm")
                details.append(f"every reading of the {kind} plan is the value it stands for, in {quantity}, not "
                               f"its length on the plan: give the millimetres measured (the value / {symbol})")
                continue
            details.append(f"every reading of the {kind} plan is {ratio:.4g} times the plan as constructed at "
                           f"{symbol} = {position.plans[kind].scale:.4g} {unit}: a plan drawn at {symbol} = "
                           f"{drawn_at:.4g} {unit}? (set at that scale, the readings agree)")
        if found.misread:
            # + 0.0 makes the −0.0 a reading of 0 mm gives a turning link's ω (signed as constructed) plain 0.
            readings = "; ".join(f"{reading} gives " + ", ".join(
                f"{row.quantity} = {row.plan + 0.0:.4g} against {plan + 0.0:.4g}, "
                + (f"{abs(row.plan - plan) / abs(plan) * 100.0:.1f} % off" if plan else "where the plan has none")
                for row, plan in rows) for reading, rows in found.misread.items())
            details.append(f"readings more than {FAR_OFF_PERCENT:g} % and {FAR_OFF_PRECISIONS * precision:g} mm off "
                           f"the plan as constructed ({readings}): a length misread, or a segment taken for another?")
        warnings.append(PositionWarning(position.index, "measured-far-off",
                                        f"measured.{position.number}: " + "; ".join(details)))
    return tuple(warnings)


def in_units(drawn_at: float) -> bool:
    """Whether readings that agree at a plan scale of ``drawn_at`` (m/s or m/s² a millimetre) are the values
    themselves, typed in their units where a plan's millimetres were asked for: a scale of one unit a millimetre."""
    return abs(drawn_at - 1.0) <= FAR_OFF_PERCENT / 100.0


def _far_off(row: ErrorRow, plan: float, precision: float) -> bool:
    apart = abs(row.plan - plan)
    return apart > FAR_OFF_PERCENT / 100.0 * abs(plan) and apart > FAR_OFF_PRECISIONS * precision * row.per_millimetre


def _plan_of(row: ErrorRow) -> str:
    """The plan a row's quantity is read off: V… and ω off the velocity plan, a… and ε off the acceleration plan."""
    if is_reaction(row.quantity):
        return "forces"
    return "velocity" if row.quantity.startswith(("V", "omega")) else "acceleration"


def _one_ratio(rows: list[tuple[ErrorRow, float]]) -> float | None:
    """The ratio of two readings or more to the construction where one ratio, far from 1, accounts for them all:
    divided by it, none is far off (a scale's slip, under the readings' own errors of a few per cent)."""
    # A segment gives several quantities (pb: VB, ω4) in one ratio: two segments at least make a scale.
    ratios = list({row.reading: row.plan / plan for row, plan in rows if plan}.values())
    if len(ratios) < 2:
        return None
    ratio = statistics.median(ratios)
    if ratio <= 0 or abs(ratio - 1.0) <= FAR_OFF_PERCENT / 100.0:
        return None
    return ratio if all(abs(each / ratio - 1.0) <= FAR_OFF_PERCENT / 100.0 for each in ratios) else None


__all__ = ["FAR_OFF_PERCENT", "FAR_OFF_PRECISIONS", "Slips", "in_units", "misread", "slips"]
