"""The mechanism drawn at one instant: link outlines, pins, slider blocks, frame pivots and guides.

Shared by the drawings that show the linkage itself: the plan of positions
overlays every position (:mod:`graphplan.render.positions`), the plan sheet
shows the one position its plans belong to (:mod:`graphplan.render.plans`).
The functions read solved positions and the mechanism's membership tables;
they compute no mechanics.
"""

from __future__ import annotations

from typing import Callable

import numpy as np
from shapely.geometry import MultiPoint

from ..kinematics import at
from ..mechanism import Mechanism
from ..motion import Motion
from .primitives import MAIN, THIN, Polyline, Primitive, Stroke, frame_pivot, hatching, pin, slider_block

Paper = Callable[[complex], tuple[float, float]]


def outline_points(mechanism: Mechanism, motion: Motion) -> dict[int, list[str]]:
    """For every moving link, the points whose convex hull is its outline.

    A link's own centre of mass lies inside it and is left out, unless it
    is a joint; the line a slider runs on is drawn long enough to carry the
    slider, so sliding joints count.
    """
    named = {spec.name for spec in mechanism.scene.points}

    def inside(link: int, name: str) -> bool:
        spec = mechanism.scene.links.get(link)
        return spec is not None and spec.centre == name and name in named

    outlines = {link: [name for name in sorted(mechanism.fixed_on.get(link, ())) if not inside(link, name)]
                for link in mechanism.moving_links}
    for slide in motion.slides:
        if slide.guide in outlines and slide.joint not in outlines[slide.guide]:
            outlines[slide.guide].append(slide.joint)
    return outlines


def links_at(motion: Motion, index: int, outlines: dict[int, list[str]], paper: Paper, stroke: Stroke,
             bold: bool) -> list[Primitive]:
    """The links of ``motion`` at position ``index``: hulls, slider blocks and, when ``bold``, the moving pins."""
    items: list[Primitive] = []
    frame_points = set(motion.mechanism.scene.frame_points)
    named = {spec.name for spec in motion.mechanism.scene.points}
    for names in outlines.values():
        points = [paper(complex(at(motion.points[name].r, index))) for name in names]
        if len(points) < 2:
            continue
        hull = MultiPoint(points).convex_hull
        if hull.geom_type == "Polygon":
            items.append(Polyline(tuple(hull.exterior.coords)[:-1], stroke, closed=True))
        elif hull.geom_type == "LineString":
            items.append(Polyline(tuple(hull.coords), stroke))
    for slide in motion.slides:
        items.append(slider_block(paper(complex(at(motion.points[slide.joint].r, index))),
                                  float(np.angle(complex(at(slide.u, index)))), stroke=MAIN if bold else stroke))
    if bold:
        joints = {n for names in outlines.values() for n in names} - frame_points - named
        items.extend(pin(paper(complex(at(motion.points[name].r, index)))) for name in sorted(joints))
    return items


def frame_guide(start: complex, end: complex, u: complex, length_scale: float, paper: Paper) -> list[Primitive]:
    """A fixed guide from ``start`` to ``end`` (m) along ``u``, hatched ground under its slider block."""
    # The ground lies under the block, half the block's height off the line.
    below = -2.5 * length_scale * 1j * u
    return [*hatching(paper(start + below), paper(end + below), side=-1.0), Polyline((paper(start), paper(end)), THIN)]


def frame_pivots(mechanism: Mechanism, paper: Paper) -> list[Primitive]:
    """The fixed revolutes: frame points that a moving link turns about."""
    pivots = {name for link in mechanism.moving_links for name in mechanism.fixed_on.get(link, ())}
    items: list[Primitive] = []
    for name, r in mechanism.scene.frame_points.items():
        if name in pivots:
            items.extend(frame_pivot(paper(r)))
    return items

