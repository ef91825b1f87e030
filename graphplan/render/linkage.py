"""The mechanism drawn at one instant: link outlines, pins, slider blocks, frame pivots and guides, and the springs
and cylinders of the forces along a turning line.

Shared by the drawings that show the linkage itself: the plan of positions
overlays every position (:mod:`graphplan.render.positions`), the plan sheet
shows the one position its plans belong to (:mod:`graphplan.render.plans`).
The functions read solved positions and the mechanism's membership tables;
they compute no mechanics.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable

import numpy as np
from shapely.geometry import MultiPoint, Point, Polygon

from ..kinematics import at
from ..mechanism import Mechanism
from ..motion import Motion
from .primitives import (
    BLOCK_HEIGHT_MM,
    LEAD_PAST_PIN_MM,
    MAIN,
    PIN_RADIUS_MM,
    THIN,
    Polyline,
    Primitive,
    Stroke,
    cylinder,
    dot_marker,
    frame_pivot,
    hatching,
    pin,
    slider_block,
    spring,
)

Paper = Callable[[complex], tuple[float, float]]


def outline_points(mechanism: Mechanism, motion: Motion) -> dict[int, list[str]]:
    """For every moving link, the points whose convex hull is its outline.

    A link's own centre of mass lies inside it and is left out, unless it
    is a joint or the link has no other point but one; the line a slider runs on is drawn long enough to carry the
    slider, so sliding joints count.
    """
    named = {spec.name for spec in mechanism.scene.points}

    def inside(link: int, name: str) -> bool:
        spec = mechanism.scene.links.get(link)
        # A centre another link is jointed at (a coupler's E carrying a rod) is a corner of the plate.
        jointed = any(name in points for other, points in mechanism.fixed_on.items() if other != link)
        return spec is not None and spec.centre == name and name in named and not jointed

    outlines = {}
    for link in mechanism.moving_links:
        names = sorted(mechanism.fixed_on.get(link, ()))
        kept = [name for name in names if not inside(link, name)]
        # A link of one joint whose centre stands off it (a piston rod pinned at A, centred along the rod) is drawn
        # out to its centre: else its loads there stood on the force sheet joined to nothing.
        outlines[link] = kept if len(kept) > 1 else names
    for slide in motion.slides:
        if slide.guide in outlines and slide.joint not in outlines[slide.guide]:
            outlines[slide.guide].append(slide.joint)
    return outlines


# How far a bold slider block reaches from its pin across its slide (mm), its outline's ink included: a letter of the
# pin stands beyond it (labels.Anchor's symbol_mm).
BLOCK_REACH_MM = BLOCK_HEIGHT_MM / 2 + MAIN.width / 2


def block_pins(motion: Motion) -> set[str]:
    """The points a slider block is drawn round (:func:`links_at`): each slide's joint."""
    return {slide.joint for slide in motion.slides}


def links_at(motion: Motion, index: int, outlines: dict[int, list[str]], paper: Paper, stroke: Stroke,
             bold: bool) -> list[Primitive]:
    """The links of ``motion`` at position ``index``: outlines and slots (:func:`link_outlines`), slider blocks
    and, when ``bold``, the pins, drawn where two moving links are jointed."""
    items = link_outlines(motion, index, outlines, paper, stroke)
    for slide in motion.slides:
        joint = complex(at(motion.points[slide.joint].r, index))
        items.append(slider_block(paper(joint), float(np.angle(complex(at(slide.u, index)))),
                                  stroke=MAIN if bold else stroke))
    if bold:
        items.extend(pin(paper(complex(at(motion.points[name].r, index)))) for name in joints(motion.mechanism))
    return items


def link_outlines(motion: Motion, index: int, outlines: dict[int, list[str]], paper: Paper,
                  stroke: Stroke) -> list[Primitive]:
    """The outlines of the links in ``outlines`` at position ``index``, each with the slots it carries.

    A link is drawn as the hull of the points fixed on it, with bars to a
    joint that stands inside the hull (:func:`_bars_to_inner_joints`); a slot or slide
    it carries is drawn as a line of its own along the slide, from where it
    leaves the link to past the slider's block, so that a Scotch yoke shows
    its slot and its rod rather than a triangle.
    """
    mechanism = motion.mechanism
    jointed = _jointed(mechanism)
    items: list[Primitive] = []

    def where(name: str) -> complex:
        return complex(at(motion.points[name].r, index))

    for link, names in outlines.items():
        fixed = [name for name in names if name in mechanism.fixed_on.get(link, ())]
        corners = [where(name) for name in fixed]
        for slide in motion.slides:
            if slide.guide != link or not fixed:
                continue
            u, joint = complex(at(slide.u, index)), where(slide.joint)
            off_line = [abs(((r - joint) * u.conjugate()).imag) for r in corners]
            # Where the slide leaves the link: the foot on the slide line of the link's point nearest to it.
            nearest = corners[off_line.index(min(off_line))]
            foot = joint + ((nearest - joint) * u.conjugate()).real * u
            corners.append(foot)
            # A lever's slot ends at its pivot; a yoke's slot runs across the link, past its middle.
            across = max(off_line) > 1e-9  # m: a point of the link stands off the slide line
            items.append(_slot(paper(foot), paper(joint), u, stroke, across))
        outline = _outline([paper(r) for r in corners], stroke)
        if outline is not None:
            items.append(outline)
            pivots = [paper(where(name)) for name in fixed if name in jointed.get(link, ())]
            items.extend(_bars_to_inner_joints(outline, pivots, stroke))
    return items


def _jointed(mechanism: Mechanism) -> dict[int, set[str]]:
    """For every link, the points at which it turns on another link or on the frame."""
    found: dict[int, set[str]] = {}
    for name, first, second in mechanism.revolutes:
        found.setdefault(first, set()).add(name)
        found.setdefault(second, set()).add(name)
    return found


def _bars_to_inner_joints(outline: Polyline, pivots: list[tuple[float, float]], stroke: Stroke) -> list[Polyline]:
    """Bars that tie to the plate ``outline`` each of its joints at ``pivots`` (paper mm) that stands inside it.

    A ternary link with a point beyond one of its joints (K past D) has that
    joint inside the hull of its points, where no line of the hull reaches
    it: the pin would be drawn free of its link. A draughtsman ties it to
    the link's other joints on the outline (the triangle of its pins drawn
    within the plate), or to the nearest corner where no other joint is on it.
    """
    if not outline.closed:
        return []
    plate = Polygon(outline.points)
    # A joint within a hundredth of a millimetre of the outline is on it.
    inner = [pivot for pivot in pivots if plate.boundary.distance(Point(pivot)) > 0.01 and plate.contains(Point(pivot))]
    corners = [pivot for pivot in pivots if pivot not in inner]
    bars: list[Polyline] = []
    for joint in inner:
        ends = corners or [min(outline.points, key=lambda corner: math.dist(corner, joint))]
        bars.extend(Polyline((joint, end), stroke) for end in ends)
    return bars


def _outline(corners: list[tuple[float, float]], stroke: Stroke) -> Polyline | None:
    """The hull of a link's points: a closed outline, or the segment between the farthest two when they lie in a line."""
    if len(corners) < 2:
        return None
    far = max(((a, b) for i, a in enumerate(corners) for b in corners[i + 1:]), key=lambda ab: math.dist(*ab))
    hull = MultiPoint(corners).convex_hull
    # Points in a line up to rounding (a foot computed on the link's own line) make a sliver, not a plate.
    if hull.geom_type == "Polygon" and hull.area > 1e-6 * math.dist(*far) ** 2:
        return Polyline(tuple(hull.exterior.coords)[:-1], stroke, closed=True)
    return Polyline(far, stroke) if math.dist(*far) > 0 else None


# How far a slot runs past the middle of its slider block (mm): half the block and a little more.
SLOT_REACH_MM = 8.0


def _slot(foot: tuple[float, float], joint: tuple[float, float], u: complex, stroke: Stroke,
          across: bool) -> Polyline:
    """The slide line of a link from ``foot`` to ``joint`` (paper mm), run on past the joint by :data:`SLOT_REACH_MM`,
    and as far past the foot when the slot runs ``across`` the link."""
    dx, dy = joint[0] - foot[0], joint[1] - foot[1]
    length = math.hypot(dx, dy)
    ex, ey = (dx / length, dy / length) if length > 1e-9 else (u.real, u.imag)
    back = SLOT_REACH_MM if across or length <= 1e-9 else 0.0
    return Polyline(((foot[0] - back * ex, foot[1] - back * ey),
                     (joint[0] + SLOT_REACH_MM * ex, joint[1] + SLOT_REACH_MM * ey)), stroke)


def joints(mechanism: Mechanism) -> list[str]:
    """The moving revolute joints: points fixed on two moving links at once (a crank pin, a rod's end)."""
    frame = set(mechanism.scene.frame_points)
    count: dict[str, int] = {}
    for link in mechanism.moving_links:
        for name in mechanism.fixed_on.get(link, ()):
            count[name] = count.get(name, 0) + 1
    return sorted(name for name, links in count.items() if links >= 2 and name not in frame)


# The hatched ground of a guide runs this far (mm) past its block's travel: past the block's own half-length.
GROUND_MARGIN_MM = 8.0


def frame_guide(start: complex, end: complex, u: complex, length_scale: float, paper: Paper,
                ground: tuple[complex, complex] | None = None, side: float = -1.0) -> list[Primitive]:
    """A fixed guide from ``start`` to ``end`` (m) along ``u``, with hatched ground from ``ground``'s first end to
    its second (the whole guide by default) on ``side`` of it (−1: right of ``u``, +1: left)."""
    # The ground lies beside the block, half the block's height off the line.
    off = side * 2.5 * length_scale * 1j * u
    first, last = ground or (start, end)
    return [*hatching(paper(first + off), paper(last + off), side=side), Polyline((paper(start), paper(end)), THIN)]


def guide_bushing(mechanism: Mechanism, motion: Motion, slider: int, joint: str, u: complex,
                  length_scale: float) -> tuple[complex, complex] | None:
    """Where a frame guide's ground is hatched (m) when its slider's travel runs over a frame pivot that a link
    turns about (a Scotch yoke's vertical guide through the crank's pivot O): over the stretch of the guide's
    line that the sliding link, a rod, covers at every position, clear of its travel by the ground's margin,
    where a bushing can hold it.  None where no pivot stands in the travel, or the link is no rod long enough:
    the ground spans the travel, as under a block."""
    track = np.atleast_1d(motion.points[joint].r)
    origin = complex(track[0])
    travel = ((track - origin) * np.conj(u)).real
    block = GROUND_MARGIN_MM * length_scale
    pivots = {name: r for name, r in mechanism.scene.frame_points.items() if name in _pivots(mechanism)}
    crossed = [name for name, r in pivots.items()
               if abs(((r - origin) * np.conj(u)).imag) < block
               and travel.min() < ((r - origin) * np.conj(u)).real < travel.max()]
    if not crossed:
        return None
    # The stretch covered at every position: from the highest of the rod's lowest ends to the lowest of its highest.
    on_line = []
    for name in sorted(mechanism.fixed_on.get(slider, ())):
        if name not in motion.points:
            continue
        offsets = (np.atleast_1d(motion.points[name].r) - origin) * np.conj(u)
        if np.all(np.abs(offsets.imag) < 1e-9 * max(float(np.abs(offsets).max()), 1.0)):
            on_line.append(offsets.real * np.ones_like(travel))
    if len(on_line) < 2:
        return None
    low, high = float(np.max(np.min(on_line, axis=0))), float(np.min(np.max(on_line, axis=0)))
    # Beyond the travel on either side, by the margin the slot or block at the joint takes, and short of the rod's
    # end by as much: the longer stretch.
    stretches = [(max(low, travel.max() + block), high - block), (low + block, min(high, travel.min() - block))]
    low, high = max(stretches, key=lambda stretch: stretch[1] - stretch[0])
    if high - low < 2.0 * block:
        return None
    return origin + low * u, origin + high * u


def frame_points_along(mechanism: Mechanism, through: complex, u: complex) -> list[float]:
    """How far along the line through ``through`` along ``u`` (m) each frame point on it lies: a guide is drawn
    on to them, so that the point its scene names stands on it."""
    return [((q - through) * u.conjugate()).real for q in mechanism.scene.frame_points.values()
            if abs(((q - through) * u.conjugate()).imag) < 1e-9 * max(abs(q - through), 1.0)]


def loose_frame_points(mechanism: Mechanism, paper: Paper) -> list[Primitive]:
    """Frame points that no link turns about (a guide's end), as dots: their labels mark something drawn."""
    pivots = _pivots(mechanism)
    return [dot_marker(paper(r)) for name, r in mechanism.scene.frame_points.items() if name not in pivots]


def ground_side(points: Iterable[complex], through: complex, u: complex) -> float:
    """The side of the guide through ``through`` along ``u`` its ground is hatched on: away from the links at
    ``points``, so that they do not cross it (−1, right of ``u``, where they stand evenly on both sides)."""
    offsets = [((point - through) * u.conjugate()).imag for point in points]
    lean = sum(offsets)
    return 1.0 if lean < -1e-6 * sum(abs(offset) for offset in offsets) else -1.0


def frame_pivots(mechanism: Mechanism, paper: Paper) -> list[Primitive]:
    """The fixed revolutes: frame points that a moving link turns about, or a spring or a cylinder is pinned at."""
    pivots = _pivots(mechanism)
    items: list[Primitive] = []
    for name, r in mechanism.scene.frame_points.items():
        if name in pivots:
            items.extend(frame_pivot(paper(r)))
    return items


def _pivots(mechanism: Mechanism) -> set[str]:
    """The points a moving link turns about, and those a spring or a cylinder (:func:`along_loads`) is pinned at."""
    turned_about = {name for link in mechanism.moving_links for name in mechanism.fixed_on.get(link, ())}
    return turned_about | {name for far, near, _ in _along(mechanism) for name in (far, near)}


def _along(mechanism: Mechanism) -> list[tuple[str, str, bool]]:
    """The forces along a turning line (``[[loads]]`` with ``along``), one of each spring or cylinder, as the point
    it is along, its own point and whether it is a spring: a cylinder between two moving links is two loads, one at
    each end along the other's point, and is drawn once."""
    found: dict[tuple[frozenset[str], bool], tuple[str, str, bool]] = {}
    for load in mechanism.scene.loads:
        if load.kind == "force" and load.ends is not None:
            found.setdefault((load.ends, load.spring), (load.along, load.point, load.spring))
    return list(found.values())


def along_loads(motion: Motion, index: int, paper: Paper, letter: float, stroke: Stroke,
                span: Motion | None = None) -> tuple[list[Primitive], list[Primitive]]:
    """The springs and cylinders of the forces along a turning line at position ``index`` of ``motion``, each
    between the point it is along and its own point, and the pins at their ends that no link's pin or frame pivot
    (:func:`frame_pivots`) marks already (a centre of mass a spring pulls), to draw over the links.

    A spring is a thin zig-zag (:func:`~graphplan.render.primitives.spring`), sized to the drawing's ``letter``.
    A cylinder (a force of a set value along the line) is drawn in ``stroke``, its barrel pinned at the point it
    is along and its rod at its own point; the barrel and the rod keep their lengths over the positions of
    ``span`` (``motion`` by default): the barrel a little longer than the stroke between its shortest and longest
    there (and no shorter than near half the shortest, nor longer than the shortest leaves room for), the rod so
    that the piston stands near the barrel's open end at the longest and near its closed end at the shortest, as a
    cylinder that carries the mechanism through them would.
    """
    mechanism = motion.mechanism
    pinned = set(joints(mechanism)) | set(mechanism.scene.frame_points)
    span = span or motion
    lines: list[Primitive] = []
    pins: list[Primitive] = []
    for along, point, is_spring in _along(mechanism):
        far, near = complex(at(motion.points[along].r, index)), complex(at(motion.points[point].r, index))
        start, end = paper(far), paper(near)
        length = math.dist(start, end)
        if length == 0.0:
            continue
        if is_spring:
            lines.append(spring(start, end, letter))
        else:
            mm_per_m = length / abs(near - far)
            reach = np.abs(np.atleast_1d(span.points[point].r - span.points[along].r)) * mm_per_m
            shortest, longest = float(reach.min()), float(reach.max())
            lead = LEAD_PAST_PIN_MM + PIN_RADIUS_MM
            # Room for the piston's stroke between a tenth of the barrel from either end, within the shortest.
            barrel = min(max(0.45 * shortest, 1.25 * (longest - shortest)), shortest - lead - PIN_RADIUS_MM)
            rod = longest - lead - 0.9 * barrel
            lines.extend(cylinder(start, end, barrel, length - rod, letter, stroke))
        pins.extend(pin(where) for name, where in ((along, start), (point, end)) if name not in pinned)
    return lines, pins
