"""Each drawing of a run, as SVG text: the layout of its record, written by the backend."""

from __future__ import annotations

import numpy as np

from ..analysis import Analysis
from ..locale import strings
from ..scales import fit_scale, format_scale
from . import positions
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
