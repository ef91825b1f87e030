"""The plan of positions: the mechanism at μl in all analysed positions, overlaid.

Thin grey outlines for every position, the extreme positions bold, each
position numbered at the driver's joint, the paths of the named points as
thin dashed curves, the frame pivots and guides drawn once.  The layout reads
solved motions and the mechanism's membership tables; it computes no
mechanics.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry.base import BaseGeometry

from ..kinematics import at
from ..mechanism import Mechanism
from ..motion import Motion
from .labels import Anchor, obstacles_of, place_labels
from .linkage import (
    GROUND_MARGIN_MM,
    Paper,
    frame_guide,
    frame_pivots,
    frame_points_along,
    ground_side,
    links_at,
    loose_frame_points,
    outline_points,
)
from .plans import CAPTION_LINE, CAPTION_SIZE, TITLE_SIZE
from .primitives import (
    BOLD,
    PIN_RADIUS_MM,
    Layer,
    Polyline,
    Primitive,
    Stroke,
    Text,
    bounds,
    dot_marker,
)

_POSITION_STROKE = Stroke(0.3, "#7a7a7a")
_PATH_STROKE = Stroke(0.25, "#1f5fa8", (2.0, 1.2))
_CRANK_CIRCLE_STROKE = Stroke(0.25, "#7a7a7a")
_LABEL = 3.0
# A point of the second extreme nearer than this to where it stands at the first (mm on the paper) is lettered there
# already: a frame point, a pin that hardly moves.
_SAME_POINT_MM = 2.0
# Room a label keeps round the driver's pin at a bold position (mm), past the pin's own radius.
_PIN_CLEARANCE_MM = 0.8


@dataclass(frozen=True)
class PositionsPlan:
    """What the plan of positions shows: the motions it reads and how to letter them.

    ``emphasised`` holds the positions drawn bold: the two extremes of the
    working link, or the first position when the scene names none.
    ``extremes`` names each of them that is no numbered position drawn, as
    Russian course projects mark an extreme: the number of the position it
    follows with a prime (8′), its points lettered with a prime (A′, D′);
    empty for one that is a numbered position.
    """

    mechanism: Mechanism
    positions: Motion
    numbers: tuple[int, ...]
    emphasised: Motion
    paths: Motion
    length_scale: float
    title: str
    caption: str
    extremes: tuple[str, ...] = ()


def layout(plan: PositionsPlan) -> list[Layer]:
    """The layers of the plan of positions, in paper millimetres (y up)."""
    mm_per_m = 1.0 / plan.length_scale

    def paper(r: complex) -> tuple[float, float]:
        return (r.real * mm_per_m, r.imag * mm_per_m)

    outlines = outline_points(plan.mechanism, plan.positions)
    every = _mechanism_at(plan.positions, outlines, paper, _POSITION_STROKE, bold=False)
    bold = _mechanism_at(plan.emphasised, outlines, paper, BOLD, bold=True)
    frame = _frame(plan, paper)
    paths = _paths(plan, paper)
    drawn = every + bold + frame + paths
    labels = place_labels(_position_anchors(plan, paper) + _point_anchors(plan, paper) + _extreme_anchors(plan, paper),
                          obstacles_of(drawn) + _crowded_pins(plan, paper))
    layers = [Layer("paths", tuple(paths)), Layer("positions", tuple(every)), Layer("extremes", tuple(bold)),
              Layer("frame", tuple(frame)), Layer("leaders", labels.leaders),
              Layer("labels", labels.texts + tuple(_centre_marks(plan, paper)))]
    xmin, _, _, ymax = bounds(layers)
    # Lettered as the plan sheets' headings beside it on the kinematics sheet: the title over its scale.
    scale_line = ymax + 5.0
    layers.append(Layer("caption", (Text((xmin, scale_line + CAPTION_LINE * CAPTION_SIZE), plan.title, TITLE_SIZE,
                                         "start", weight="bold"),
                                    Text((xmin, scale_line), plan.caption, CAPTION_SIZE, "start"))))
    return layers


def _mechanism_at(motion: Motion, outlines: dict[int, list[str]], paper: Paper, stroke: Stroke,
                  bold: bool) -> list[Primitive]:
    return [item for index in range(motion.count) for item in links_at(motion, index, outlines, paper, stroke, bold)]


def _frame(plan: PositionsPlan, paper: Paper) -> list[Primitive]:
    """Fixed pivots and frame guides, drawn once; a guide's ground spans its slider's whole travel, and its line
    runs on to the frame points on it (the point a triad's guide is named through)."""
    mechanism, motion = plan.mechanism, plan.paths
    frame = mechanism.scene.frame_link
    items: list[Primitive] = []
    for slide in motion.slides:
        if slide.guide != frame:
            continue
        track = np.atleast_1d(motion.points[slide.joint].r)
        u = complex(at(slide.u, 0))
        origin = complex(track[0])
        along = ((track - origin) * np.conj(u)).real
        margin = GROUND_MARGIN_MM * plan.length_scale
        travel = (float(along.min()) - margin, float(along.max()) + margin)
        reach = frame_points_along(mechanism, origin, u)
        first, last = min([travel[0], *reach]), max([travel[1], *reach])
        ground = (origin + travel[0] * u, origin + travel[1] * u)
        links = (complex(r) for point in motion.points.values() for r in np.atleast_1d(point.r))
        items.extend(frame_guide(origin + first * u, origin + last * u, u, plan.length_scale, paper, ground,
                                 side=ground_side(links, origin, u)))
    items.extend(frame_pivots(mechanism, paper))
    items.extend(loose_frame_points(mechanism, paper))
    return items


def _paths(plan: PositionsPlan, paper: Paper) -> list[Primitive]:
    driver = plan.mechanism.driver
    closed = driver.cyclic
    items: list[Primitive] = []
    named = {spec.name for spec in plan.mechanism.scene.points}
    if driver.kind == "crank" and driver.joint not in named:
        # The crank pin's circle (a rocking crank's arc), on which the positions are numbered: the first line
        # a student draws on the plan of positions.
        pin = np.atleast_1d(plan.paths.points[driver.joint].r)
        items.append(Polyline(tuple(paper(r) for r in pin), _CRANK_CIRCLE_STROKE, closed=closed))
    for spec in plan.mechanism.scene.points:
        track = np.atleast_1d(plan.paths.points[spec.name].r)
        if len(track) > 1 and np.ptp(track.real) + np.ptp(track.imag) > 0:
            items.append(Polyline(tuple(paper(r) for r in track), _PATH_STROKE, closed=closed))
    return items


def _position_anchors(plan: PositionsPlan, paper: Paper) -> list[Anchor]:
    """Each position's number at the driver's joint, on the side away from the driver's centre."""
    driver = plan.mechanism.driver
    joint = plan.positions.points[driver.joint].r
    centre = _driver_centre(plan)
    anchors = []
    for index, number in enumerate(plan.numbers):
        outward = complex(at(joint, index)) - centre
        anchors.append(Anchor(paper(complex(at(joint, index))), str(number), _LABEL, math.atan2(outward.imag, outward.real),
                              "#333333"))
    return anchors


def _crowded_pins(plan: PositionsPlan, paper: Paper) -> list[BaseGeometry]:
    """The driver's pin at each bold position, grown: its number and its letter both stand round it, and a
    label only clear of the pin itself read as run into it (position 0's "0" and "A" on the Stephenson six-bar)."""
    joint = plan.emphasised.points[plan.mechanism.driver.joint].r
    return [ShapelyPoint(paper(complex(at(joint, index)))).buffer(PIN_RADIUS_MM + _PIN_CLEARANCE_MM)
            for index in range(plan.emphasised.count)]


def _driver_centre(plan: PositionsPlan) -> complex:
    """Where the position numbers point away from: a crank's pivot, else the middle of the driver's run."""
    driver = plan.mechanism.driver
    if driver.kind == "crank":
        return plan.mechanism.scene.frame_points[driver.pivot]
    joint = plan.positions.points[driver.joint].r
    return complex(np.mean(np.atleast_1d(joint))) + 1j * complex(at(plan.positions.links[driver.link].u, 0))


def _extreme_anchors(plan: PositionsPlan, paper: Paper) -> list[Anchor]:
    """An extreme that is no numbered position: its name (8′) at the driver's joint, as the positions are
    numbered, and its points lettered with a prime; it stood bold with neither."""
    driver = plan.mechanism.driver
    motion = plan.emphasised
    centre = _driver_centre(plan)
    # The letters of the joints and points; a centre of mass that is no joint (S4) at the first extreme only.
    named = {spec.name for spec in plan.mechanism.scene.points}
    centres = {spec.centre for spec in plan.mechanism.scene.links.values()} & named
    drawn = {name for names in plan.mechanism.fixed_on.values() for name in names} - centres
    anchors = []
    for index, label in enumerate(plan.extremes):
        if not label or index >= motion.count:
            continue
        joint = complex(at(motion.points[driver.joint].r, index))
        outward = joint - centre
        anchors.append(Anchor(paper(joint), label, _LABEL, math.atan2(outward.imag, outward.real), "#333333"))
        moving = [name for name in motion.points if name in drawn
                  and abs(complex(at(motion.points[name].r, index)) - complex(at(motion.points[name].r, 0)))
                  > _SAME_POINT_MM * plan.length_scale]
        if not moving:
            continue
        middle = sum(complex(at(motion.points[name].r, index)) for name in moving) / len(moving)
        for name in moving:
            r = complex(at(motion.points[name].r, index))
            away = r - middle
            anchors.append(Anchor(paper(r), f"{name}′", _LABEL, math.atan2(away.imag, away.real) if away else math.pi / 2))
    return anchors


def _point_anchors(plan: PositionsPlan, paper: Paper) -> list[Anchor]:
    """Names of the joints and named points at the first emphasised position."""
    motion = plan.emphasised
    # Points fixed on a link only: an RPR lever's point under the block (A4) would just repeat A's label.
    drawn = {name for names in plan.mechanism.fixed_on.values() for name in names}
    names = [name for name in motion.points if name in drawn]
    centroid = sum(complex(at(motion.points[n].r, 0)) for n in names) / len(names)
    anchors = []
    for name in names:
        r = complex(at(motion.points[name].r, 0))
        away = r - centroid
        anchors.append(Anchor(paper(r), name, _LABEL, math.atan2(away.imag, away.real) if away else math.pi / 2))
    return anchors


def _centre_marks(plan: PositionsPlan, paper: Paper) -> list[Primitive]:
    return [dot_marker(paper(complex(at(plan.emphasised.points[spec.name].r, 0)))) for spec in plan.mechanism.scene.points]
