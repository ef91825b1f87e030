"""The load diagrams of a run: each load given over a stroke, against the travel of its stroke's link.

A press's or a shaper's useful resistance F(s), a compressor's gas force over
its strokes (an indicator diagram: one load per stroke), a cutting force over
its window: the course project draws each against the working link's travel,
the positions marked on the travel axis, and reads off it the value the force
analysis takes at each position.  This module gathers what that drawing and
the note show; it draws nothing (:mod:`graphplan.render.load_diagrams`).

The loads of one link and one kind (forces or moments) share a diagram: the
two strokes of a piston make one closed figure.  Its abscissa is the link's
travel from where the reference stroke starts (the scene's working stroke
where the link is the working link, else the first load's own), in that
stroke's sense: metres along a guide, radians turning.  A diagram's shares
map onto it linearly, a load of the other stroke's from the other end.  The
values at the positions are :func:`graphplan.loads.activity`'s, the very ones
the force analysis and the equilibrium take.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from .analysis import Analysis
from .loads import activity, external_names, stroke_ends, stroke_share
from .positions import in_working_stroke, stroke_extremes
from .scene import OTHER_SENSE, LoadSpec, Working


@dataclass(frozen=True)
class DrawnLoad:
    """One load on a load diagram: its outline over the travel and the value it takes at each position."""

    name: str
    spec: LoadSpec
    # (travel from the diagram's origin, value) of its diagram, or of the rectangle over its window or stroke;
    # closed to the axis where it starts or ends at a value.
    outline: tuple[tuple[float, float], ...]
    # The value the force analysis takes at each analysed position: N or N·m, as the diagram writes it (a
    # resisting load's magnitude, another's signed along its angle); 0 where it does not act.
    values: np.ndarray
    # Whether its stroke is the diagram's reference stroke (else the other one, travelled back).
    with_reference: bool


@dataclass(frozen=True)
class LoadDiagram:
    """The loads of one link and kind over its strokes, and the analysed positions on its travel."""

    link: int
    kind: str                 # "force" or "moment": the ordinate's unit
    translating: bool         # the abscissa in metres; else in radians
    point: str | None         # the translating link's point whose travel the abscissa is (its symbol sB)
    reference: Working        # the stroke the abscissa runs along, from its start
    travel: float             # the reference stroke's length: m or rad
    numbers: tuple[int, ...]
    # Each position's travel from the reference stroke's start, and whether it lies in that stroke (at an
    # extreme: the stroke about to begin).
    coordinates: np.ndarray
    in_reference: np.ndarray
    plans: tuple[int, ...]    # the indices of the plan positions, whose values the force sheets use
    loads: tuple[DrawnLoad, ...]

    def stroke_at(self, index: int) -> tuple[str, float]:
        """The sense of the stroke position ``index`` is in and its share of that stroke, as a diagram of that
        stroke counts it (the other stroke runs back from the reference's end)."""
        share = float(self.coordinates[index] / self.travel)
        if self.in_reference[index]:
            return self.reference.sense, share
        return OTHER_SENSE[self.reference.sense], 1.0 - share


def drawn(spec: LoadSpec) -> bool:
    """Whether a load has a diagram to draw: one given over a stroke (a diagram, a window, a stroke's length)."""
    return spec.during != "always"


def unavailable(analysis: Analysis) -> str | None:
    """Why the run has no load diagram to draw, or None where it has one."""
    scene = analysis.scene
    if not any(drawn(spec) for spec in scene.loads):
        # A spring acts always, by its length: it has no stroke to draw a diagram over.
        springs = [spec.where for spec in scene.loads if spec.spring]
        besides = f" ({', '.join(springs)}: a spring acts always, its force set by its length)" if springs else ""
        return f"needs a load given over a stroke: a [[loads]] diagram, during window or stroke{besides}"
    if not _drawn_rows(analysis):
        return ("needs the extremes of the loads' strokes: the output link turns round, or the positions run once "
                "over a slider's travel or a rocking crank's swing")
    return None


def _drawn_rows(analysis: Analysis) -> list[int]:
    """The scene's loads that have a diagram to draw and a stroke with extremes to draw it over."""
    scene, positions = analysis.scene, analysis.positions
    return [row for row, spec in enumerate(scene.loads)
            if drawn(spec) and (spec.stroke or scene.positions.working) is not None
            and stroke_extremes(positions, spec.stroke) is not None]


def of_analysis(analysis: Analysis) -> tuple[LoadDiagram, ...]:
    """The load diagrams of ``analysis``: one for each link and kind with a load over a stroke, in the scene's
    order of their first loads; none where the scene has none, or the stroke has no extremes."""
    mechanism, positions, motion = analysis.mechanism, analysis.positions, analysis.motion
    scene = analysis.scene
    names = external_names(scene.loads)
    rows = _drawn_rows(analysis)
    if not rows:
        return ()
    acting = activity(mechanism, positions, motion)
    groups: dict[tuple[int, str], list[int]] = {}
    for row in rows:
        spec = scene.loads[row]
        stroke = spec.stroke or scene.positions.working
        groups.setdefault((stroke.link, spec.kind), []).append(row)
    plans = tuple(plan.index for plan in analysis.plans)
    found = []
    for (link, kind), members in groups.items():
        working = scene.positions.working
        # A stroke is named None where it is the working link's: positions.load_strokes keeps the others'.
        named = None if working is not None and working.link == link else scene.loads[members[0]].stroke
        reference = named or working
        start, end = stroke_ends(mechanism, positions, named)
        translating = link in mechanism.translating
        travel = abs(end - start)
        coordinates = stroke_share(mechanism, positions, motion, named) * travel
        loads = []
        for row in members:
            spec = scene.loads[row]
            own = spec.stroke or working
            # The load's shares run along its own stroke: from the reference's start, or back from its end.
            own_start, own_end = stroke_ends(mechanism, positions, spec.stroke)
            along = functools.partial(_travel_at, own=(own_start, own_end), origin=start,
                                      sense=1.0 if end > start else -1.0, turning=not translating)
            values = acting[row] * spec.value
            if spec.resisting:  # as the force analysis takes it: against the motion, its magnitude
                values = np.abs(values)
            # A load of the idle stroke acts in the stroke the other way.
            same = own.link == reference.link and own.sense == reference.sense
            loads.append(DrawnLoad(names[row], spec, _outline(spec, along), values, same != (spec.during == "idle")))
        found.append(LoadDiagram(link, kind, translating, _origin(analysis, link), reference, travel, tuple(positions.numbers),
                                 coordinates, in_working_stroke(motion, named), plans, tuple(loads)))
    return tuple(found)


def _travel_at(share: float, own: tuple[float, float], origin: float, sense: float, turning: bool) -> float:
    """The abscissa of a share of a load's own stroke (``own``: its start and end coordinates): the travel from
    the reference stroke's start ``origin`` in its ``sense``; an angle within half a turn of it."""
    offset = own[0] + share * (own[1] - own[0]) - origin
    if turning:
        offset = math.remainder(offset, 2.0 * math.pi)
    return sense * offset + 0.0


def _origin(analysis: Analysis, link: int) -> str | None:
    """The point whose travel a translating link's abscissa is (its symbol sB); none for a turning link."""
    if link not in analysis.mechanism.translating:
        return None
    return analysis.motion.links[link].origin


def _outline(spec: LoadSpec, along) -> tuple[tuple[float, float], ...]:
    """The load's diagram (or its window's or stroke's rectangle) as (travel, value), closed to the axis."""
    if spec.diagram is not None:
        corners = [(along(share), value) for share, value in spec.diagram]
    else:
        start, end = (0.0, 1.0) if isinstance(spec.during, str) else spec.during
        corners = [(along(start), spec.value), (along(end), spec.value)]
    if spec.resisting:
        corners = [(x, abs(value)) for x, value in corners]
    first, last = corners[0], corners[-1]
    return ((first[0], 0.0), *corners, (last[0], 0.0))


__all__ = ["DrawnLoad", "LoadDiagram", "drawn", "of_analysis", "unavailable"]
