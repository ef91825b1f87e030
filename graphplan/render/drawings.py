"""Each drawing of a run, as SVG text: the layout of its record, written by the backend."""

from __future__ import annotations

import math

import numpy as np

from ..analysis import Analysis, instant
from ..locale import strings
from ..plans import Plan, acceleration_plan, velocity_plan
from ..scales import fit_scale, format_scale
from . import plans, positions
from .svg import to_svg

# The plan of positions is scaled to fit this field when the scene gives no μl.
POSITIONS_FIELD_MM = 200.0


def length_scale(analysis: Analysis) -> float:
    """μl from the scene, or the standard value that fits the paths of all points into the field."""
    given = analysis.scene.drawing.length_scale
    if given is not None:
        return given
    tracks = np.concatenate([np.atleast_1d(p.r) for p in analysis.paths.points.values()])
    extent = max(float(np.ptp(tracks.real)), float(np.ptp(tracks.imag)))
    return fit_scale(extent, POSITIONS_FIELD_MM)


def positions_svg(analysis: Analysis) -> str:
    text = strings(analysis.scene.locale)
    scale = length_scale(analysis)
    plan = positions.PositionsPlan(
        mechanism=analysis.mechanism, positions=analysis.motion,
        numbers=tuple(int(n) for n in analysis.positions.numbers),
        emphasised=analysis.emphasised,
        paths=analysis.paths, length_scale=scale, title=analysis.scene.title,
        caption=f"{text['positions_title']}, {text['length_scale'].format(value=format_scale(scale))}")
    return to_svg(positions.layout(plan))


def plan_svg(analysis: Analysis, index: int, velocity: Plan | None = None, acceleration: Plan | None = None) -> str:
    """The SVG text of the plan sheet of the position at ``index`` (:func:`plan_sheet`)."""
    return to_svg(plans.layout(plan_sheet(analysis, index, velocity, acceleration)))


def plan_sheet(analysis: Analysis, index: int, velocity: Plan | None = None,
               acceleration: Plan | None = None) -> plans.PlanSheet:
    """What the plan sheet of the position at ``index`` (an index into the analysed positions) shows.

    ``velocity`` and ``acceleration`` are the plans of that position; a plan
    not given is constructed here from the positions of the instant.
    """
    if not 0 <= index < analysis.motion.count:
        raise IndexError(f"no position at index {index}; there are {analysis.motion.count}")
    mechanism = analysis.mechanism
    if velocity is None or acceleration is None:
        where, directions = instant(analysis.motion, index)
        if velocity is None:
            velocity = velocity_plan(mechanism, where, directions)
        if acceleration is None:
            acceleration = acceleration_plan(mechanism, where, directions, velocity)
    text = strings(analysis.scene.locale)
    scale = length_scale(analysis)
    number = int(analysis.positions.numbers[index])
    return plans.PlanSheet(
        mechanism=mechanism, motion=analysis.motion, index=index, number=number,
        velocity=velocity, acceleration=acceleration, length_scale=scale,
        title=text["plan_sheet_title"].format(title=analysis.scene.title, number=number),
        mechanism_caption=(text["mechanism_title"].format(number=number),
                           text["length_scale"].format(value=format_scale(scale))),
        velocity_caption=(text["velocity_plan_title"],
                          text["velocity_scale"].format(value=plan_scale_text(velocity.scale))),
        acceleration_caption=(text["acceleration_plan_title"],
                              text["acceleration_scale"].format(value=plan_scale_text(acceleration.scale))),
        velocity_pole="p", acceleration_pole=text["acceleration_pole"])


def plan_scale_text(value: float) -> str:
    """A plan's scale factor as written on the sheet: four significant digits, five decimals at least.

    A standard value stays short (0.0004); a scale fixed by the pole
    distance is rounded (0.0198333… → 0.01983, 0.50575 stays).
    """
    decimals = max(5, 3 - math.floor(math.log10(abs(value)))) if value else 5
    text = f"{value:.{decimals}f}".rstrip("0").rstrip(".")
    return text or "0"
