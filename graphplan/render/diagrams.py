"""The kinematic diagrams of the output link: displacement, velocity and acceleration, stacked.

Drawn as the course project draws them: one φ axis of length L per diagram
(a t axis over a slider driver's travel) with the positions numbered at their
ticks, the displacement with its ordinates at the positions and the chords
between them, and under it the velocity and the acceleration got by the
chord method with the pole construction (the pole P at distance H left of
the origin, a ray parallel to each chord).  Each diagram also carries the
analytic curve and says how far the chord method strays from it.  The scales
are written as the textbook writes them: μs, μv = μs/(μt·H1),
μa = μv/(μt·H2), μφ = 2π/L (Δφ/L over a swing) and μt = μφ/ω (T/L over a
slider's travel).

The layout reads a :class:`~graphplan.kinematic_diagrams.KinematicDiagrams`
record and computes no mechanics.  Every word comes from ``text``, the ``kd_``
keys of a locale (:func:`graphplan.locale.strings`); English when none is given.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import shapely
from shapely.strtree import STRtree

from ..kinematic_diagrams import KinematicDiagrams
from ..locale import strings
from ..scales import format_scale
from . import lettering
from . import plans as plan_layout
from .labels import obstacles_of, text_box
from .numerals import scale_factor
from .primitives import (
    Arrow,
    Circle,
    Layer,
    Polyline,
    Primitive,
    Stroke,
    Text,
    bounds_of,
    dot_marker,
    moved_layers,
    text_width,
)
from .svg import to_svg
from .wrapping import fitted

KINDS = ("displacement", "velocity", "acceleration")
_LETTERS = {"displacement": "s", "velocity": "v", "acceleration": "a"}

_CURVE = Stroke(0.5)
_CHORD = Stroke(0.35, "#a83a1f", (2.0, 1.2))
_CHORD_COLOUR = "#a83a1f"
_AXIS = Stroke(0.35)
_THIN = Stroke(0.18, "#555555")
# The ring round a velocity read off a plan (mm).
PLAN_RING_MM = 1.1
_RAY = Stroke(0.15, "#7a7a7a")

# The heights of the lettering (mm, render/lettering.py): the drawing's title, each diagram's caption, the scales
# and the words under the diagrams, the axes' names, the positions' numbers, the pole distance's H.
TITLE_SIZE = lettering.TITLE
CAPTION_SIZE = lettering.CAPTION
SCALE_SIZE = lettering.SCALE
AXIS_LABEL_SIZE = lettering.AXIS_LABEL
NUMBER_SIZE = lettering.AXIS_NUMBER
POLE_DISTANCE_SIZE = lettering.DIMENSION
# A diagram's caption stands on its scale line with this much paper (mm) between the scale line's capitals and the
# caption's tails.
CAPTION_CLEARANCE_MM = 1.1
# The band the positions' numbers stand in, as a hand drawing keeps it: its top this far (mm) under the φ axis, its
# depth a number's box (``text_extent``: 0.3 of the size under the baseline, 1.15 over it).  Fixed by the font
# size alone, so that a diagram's extent is known before a number is placed (:func:`parts` ``lettered``).
NUMBER_CLEARANCE_MM = 0.8
NUMBER_HEIGHT_MM = 1.45 * NUMBER_SIZE
BAND_DEPTH_MM = NUMBER_CLEARANCE_MM + NUMBER_HEIGHT_MM
# Where the curve takes a number's spot in the band, the number steps along it by these (mm), no farther than its
# box's edge beyond its tick by NUMBER_REACH_MM (it reads as its tick's); failing that it stands at its tick right
# under the curves and the rings on them, LOW_ROW_CLEARANCE_MM under them, no lower than a second row under their
# lowest point; failing both it is left out, its tick kept.  The rows end within the 4 mm a diagram
# kept under its curves before it had them: deeper, they made every diagram taller, and a sheet that held the
# three beside the plans held them no more.  Never over the axis: a number there beside the curve read as
# lettering the curve.
NUMBER_STEP_MM = 0.25
NUMBER_REACH_MM = 1.0
LOW_ROW_CLEARANCE_MM = NUMBER_CLEARANCE_MM
# How many of H's spots are tried at once (:func:`_pole_distance`).
_H_SPOTS_AT_A_TIME = 256
# What a number keeps clear of the lines round it, and of its neighbour (mm).
NUMBER_MARGIN_MM = 0.2
NUMBER_SPACING_MM = 0.6
# How far an axis runs past the curves, and its arrowhead (mm).
AXIS_RUN_MM = 12.0
AXIS_HEAD_MM = 3.0
TICK_MM = 1.2
# Room above a diagram for its caption (two lines), and between one diagram and the next (mm).
CAPTION_ROOM_MM = 16.0
# Distance between the lines of a broken line of words, in cap heights.
LINE_SPACING = 1.5
GAP_MM = 12.0
# The most ordinates or pole rays a diagram draws: on its 240 mm axis, 5 mm apart.
MOST_CONSTRUCTION_LINES = 48


def diagrams_svg(record: KinematicDiagrams, text: Mapping[str, str] | None = None) -> str:
    """The SVG text of the kinematic diagrams (:func:`layout`)."""
    return to_svg(layout(record, text))


def layout(record: KinematicDiagrams, text: Mapping[str, str] | None = None) -> list[Layer]:
    """The three diagrams stacked, displacement on top, their φ axes one under another; paper mm, y up."""
    return stacked(parts(record, text))


def stacked(drawn: list[list[Layer]]) -> list[Layer]:
    """The diagrams of :func:`parts` one under another, :data:`GAP_MM` apart."""
    layers: list[Layer] = []
    top = 0.0
    for part in drawn:
        _, ymin, _, ymax = bounds_of(item for layer in part for item in layer.items)
        layers.extend(moved_layers(part, 0.0, top - ymax))
        top -= ymax - ymin + GAP_MM
    return layers


def parts(record: KinematicDiagrams, text: Mapping[str, str] | None = None,
          lettered: bool = True) -> list[list[Layer]]:
    """The displacement, velocity and acceleration diagrams apart, each round the origin of its own φ axis.

    The title stands over the first, the legend and the φ scale under the
    last, where they stand when the three are stacked (:func:`layout`).
    Not ``lettered``: without the positions' numbers and the pole distance's
    H, whose spots are the only ones sought among the lines; their band and
    spots lie inside what is drawn, so the extent is the lettered one's, for
    a sheet to choose the diagrams' size by before it letters the one chosen.
    """
    words = {**strings("en"), **(text or {})}
    drawn = [_panel(record, kind, words, lettered) for kind in KINDS]
    # Each diagram measured once, its curves of hundreds of points each: the last with its footer is its own extent
    # and the footer's together.
    extents = [_extent(part) for part in drawn]
    footer = _footer(record, words, extents[-1][1] - GAP_MM)
    drawn[-1] = [*drawn[-1], footer]
    extents[-1] = _together(extents[-1], _extent([footer]))
    left = min(extent[0] for extent in extents)
    title = words["kd_title"].format(link=record.link, point=record.point or "")
    # Broken to the diagrams' width: at 7 mm the Russian title ran 277 mm, wider than the diagrams on a small sheet.
    heading = title_texts(title, (left, extents[0][3]), max(extent[2] for extent in extents) - left)
    drawn[0] = [*drawn[0], Layer("sheet-title", heading)]
    return drawn


def title_texts(title: str, corner: tuple[float, float], room: float) -> tuple[Text, ...]:
    """``title`` in bold over a drawing whose top left corner is ``corner``, broken to ``room`` mm wide, each line
    over the next: the kinematic diagrams' title, and the "continued" one over a diagram on a sheet of its own."""
    left, top = corner
    return plan_layout.title_texts(fitted(title, room, TITLE_SIZE, "bold"), TITLE_SIZE, (left, top + 6.0), LINE_SPACING)


def _extent(layers: list[Layer]) -> tuple[float, float, float, float]:
    return bounds_of(item for layer in layers for item in layer.items)


def _together(first: tuple[float, float, float, float],
              second: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
    """The extent of what has the extents ``first`` and ``second``: :func:`bounds_of` of both's items."""
    return (min(first[0], second[0]), min(first[1], second[1]), max(first[2], second[2]), max(first[3], second[3]))


def _values(record: KinematicDiagrams, kind: str) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """A diagram's analytic values, the chord method's angles and values (SI), and its scale."""
    scales = record.scales
    if kind == "displacement":
        return record.s, record.nodes, record.s_nodes, scales.displacement
    if kind == "velocity":
        return record.v, record.midpoints, record.v_chord, scales.velocity
    return record.a, record.a_chord_nodes, record.a_chord, scales.acceleration


def _symbol(record: KinematicDiagrams, kind: str, words: Mapping[str, str]) -> tuple[str, str]:
    """The quantity's symbol (sB, ω4) and its unit."""
    how = "translating" if record.translating else "turning"
    letter = _LETTERS[kind]
    symbol = words[f"kd_symbol_{letter}_{how}"].format(link=record.link, point=record.point or "")
    return symbol, words[f"kd_unit_{letter}_{how}"]


def _panel(record: KinematicDiagrams, kind: str, words: Mapping[str, str], lettered: bool = True) -> list[Layer]:
    """One diagram with its origin at (0, 0): axes, pole and rays, curves, numbers, caption."""
    scales = record.scales
    along_mm = 1.0 / scales.along
    analytic, chord_x, chord_y, scale = _values(record, kind)
    curve = tuple(zip((record.along * along_mm).tolist(), (analytic / scale).tolist(), strict=True))
    points = tuple(zip((chord_x * along_mm).tolist(), (chord_y / scale).tolist(), strict=True))
    low = min(0.0, min(y for _, y in curve + points))
    high = max(0.0, max(y for _, y in curve + points))
    length = scales.axis_mm
    pole = None if kind == "displacement" else (
        scales.velocity_pole if kind == "velocity" else scales.acceleration_pole)
    left = -(pole + 6.0) if pole is not None else -4.0
    symbol, unit = _symbol(record, kind, words)

    # The numbers' rows: the band under the axis, and where the curves dip under it, one under their lowest point.
    rows = _number_rows(low)
    # The ordinate axis runs down past the numbers' rows too, which so lie within what is drawn.
    axes: list[Primitive] = [
        Arrow((left, 0.0), (length + AXIS_RUN_MM, 0.0), _AXIS, AXIS_HEAD_MM, key=f"{kind}-phi-axis"),
        Arrow((0.0, min(low - 4.0, rows[-1][0])), (0.0, high + AXIS_RUN_MM), _AXIS, AXIS_HEAD_MM,
              key=f"{kind}-ordinate-axis"),
    ]
    # Every position is numbered when the numbers fit between the ticks, else every second, third, … one.
    widest = max(text_width(str(number), NUMBER_SIZE) for number in record.numbers)
    every = max(1, math.ceil((widest + 1.0) / (record.step * along_mm)))
    # Of many positions (a degree apart) the ticks, dots and construction lines of each would run together
    # into a black comb and a grey field: those of one in every few numbered ones are drawn, as the plan of
    # positions draws its positions.
    shown = math.ceil(len(record.nodes) / MOST_CONSTRUCTION_LINES)
    if shown > 1:
        shown = every = every * math.ceil(shown / every)
    last = len(record.nodes) - 1

    def ticked(k: int) -> bool:
        """Whether node ``k`` gets its tick and number: the last one too (the end of the run), where it stands
        clear of the one before."""
        return k % every == 0 or (k == last and k % every >= every / 2)

    # Ticks above the axis only, so that a position's number stands right under its tick.
    axes.extend(Polyline(((x, 0.0), (x, TICK_MM)), _AXIS)
                for k, x in enumerate((record.nodes * along_mm).tolist()) if shown == 1 or ticked(k))

    rays: list[Primitive] = []
    if kind == "displacement":
        # The ordinates of the positions: the chords between their ends are what the velocity diagram lays off.
        rays.extend(Polyline(((x, 0.0), (x, y)), _THIN) for k, (x, y) in enumerate(points)
                    if abs(y) > 1e-9 and k % shown == 0)
    else:
        # The pole construction: a ray from P parallel to each chord of the diagram above cuts the
        # ordinate axis at H·tan(chord) = the derivative at this diagram's scale; one ray per chord
        # (a cycle's closing node repeats its first).
        closing = kind == "acceleration" and record.cyclic
        chords = points[:-1] if closing else points
        rays.extend(Polyline(((-pole, 0.0), (0.0, y)), _RAY) for k, (_, y) in enumerate(chords) if k % shown == 0)

    drawn: list[Primitive] = [Polyline(curve, _CURVE)]
    drawn.append(Polyline(points, _CHORD))
    # The values the velocity plans give, ringed: the third method beside the two.
    rings = [Circle((x * along_mm, value / scale), PLAN_RING_MM, _AXIS, None)
             for x, value in record.v_plans] if kind == "velocity" else []
    drawn.extend(rings)
    drawn.extend(dot_marker(p, 0.55, _CHORD_COLOUR) for k, p in enumerate(points) if k % shown == 0)
    if pole is not None:
        drawn.append(dot_marker((-pole, 0.0), 0.7))

    labels = [Text((-2.0, high + AXIS_RUN_MM - 1.0), words["kd_axis"].format(symbol=symbol, unit=unit),
                   AXIS_LABEL_SIZE, "end"),
              Text((length + AXIS_RUN_MM, -5.0), _abscissa(record, words), AXIS_LABEL_SIZE, "middle")]
    if pole is not None:
        # The pole's letter under the axis, left of the pole: the rays all run to its right, so nothing is there.
        labels.append(Text((-pole - 1.0, -0.8 - 1.15 * AXIS_LABEL_SIZE), words["kd_pole"], AXIS_LABEL_SIZE, "end"))
    placed: tuple[Text, ...] = ()
    if lettered:
        obstacles = obstacles_of(axes + rays + drawn + labels)
        ticks = [(x, str(number)) for k, (x, number)
                 in enumerate(zip((record.nodes * along_mm).tolist(), record.numbers, strict=True)) if ticked(k)]
        # A ring marks the curve's value at its tick, so a number steps under it as under the curve: a ring on the
        # axis (a velocity of nought, at an extreme position) takes the band's spot at its tick as the curve does.
        marks = [shapely.LineString(curve), shapely.LineString(points),
                 *(shapely.Point(ring.centre).buffer(ring.radius) for ring in rings)]
        placed = _numbers(ticks, obstacles, rows, marks)
        if pole is not None:
            numbers = [text_box(text) for text in placed]
            placed += (_pole_distance(words["kd_pole_distance"], pole, axes[1].start[1], high,
                                      obstacles + numbers),)

    strokes: list[Primitive] = []
    if kind == "displacement" and record.stroke_end is not None:
        strokes = _strokes(record, words, low - 9.0)

    # The words run no wider than the diagram, so that a small sheet's shorter axis makes it narrower.
    width = length + AXIS_RUN_MM - left
    title = words[f"kd_{kind}_title"].format(symbol=symbol, along=_abscissa(record, words))
    scale_lines = fitted(_scale_line(record, kind, words, unit), width - 8.0, SCALE_SIZE)
    # The caption's name broken as its scales are (at 5 mm a Russian name ran 176 mm, wider than a small sheet's
    # diagram), its last line on them.
    title_lines = fitted(title, width, CAPTION_SIZE, "bold")
    lowest = high + AXIS_RUN_MM + CAPTION_ROOM_MM - 10.5
    raised = (len(scale_lines) - 1) * LINE_SPACING * SCALE_SIZE
    named = lowest + raised + SCALE_SIZE + CAPTION_CLEARANCE_MM + 0.3 * CAPTION_SIZE
    caption = (*(Text((0.0, named + (len(title_lines) - 1 - k) * LINE_SPACING * CAPTION_SIZE), line, CAPTION_SIZE,
                      "start", weight="bold") for k, line in enumerate(title_lines)),
               *(Text((8.0, lowest + raised - k * LINE_SPACING * SCALE_SIZE), line, SCALE_SIZE, "start")
                 for k, line in enumerate(scale_lines)))
    # Under the numbers' band wherever they stand, so that the words under the diagram move with no label.
    bottom = min(low - 4.0, rows[-1][0] + 0.3 * NUMBER_SIZE, *(t.at[1] - 2.0 for t in labels[2:]), *(
        y for item in strokes if isinstance(item, Polyline) for _, y in item.points))
    notes: tuple[Text, ...] = ()
    if kind != "displacement":
        difference = _difference(record, kind, words)
        notes = tuple(Text((0.0, bottom - 6.0 - k * LINE_SPACING * SCALE_SIZE), line, SCALE_SIZE, "start",
                           _CHORD_COLOUR) for k, line in enumerate(fitted(difference, width, SCALE_SIZE)))
    key: tuple[Primitive, ...] = ()
    if kind == "velocity" and record.v_plans:
        # The rings' key stands with the one diagram that has them (the three may stand on sheets apart): after
        # its last line of words where the diagram's width leaves room, else under it.
        last = notes[-1]
        after = text_width(last.text, SCALE_SIZE) + 8.0
        room = after + 14.0 + text_width(words["kd_plans"], SCALE_SIZE) <= width
        x, ring_y = (after, last.at[1] + 1.2) if room else (0.0, last.at[1] - 6.0)
        key = (Circle((x + 6.0, ring_y), PLAN_RING_MM, _AXIS, None),
               Text((x + 14.0, ring_y - 1.2), words["kd_plans"], SCALE_SIZE, "start"))
    return [Layer(f"{kind}-axes", tuple(axes)), Layer(f"{kind}-rays", tuple(rays + strokes)),
            Layer(f"{kind}-curves", tuple(drawn)), Layer(f"{kind}-leaders", ()),
            Layer(f"{kind}-labels", tuple(labels) + placed + notes + key),
            Layer(f"{kind}-caption", caption)]


def _under_the_curves(curves: list, x0: float, x1: float) -> float:
    """The lowest point (mm, nought or under) of the ``curves`` (and rings, shapely geometries) between ``x0`` and
    ``x1``."""
    span = shapely.box(x0, -1e9, x1, 1e9)
    return min([0.0, *(piece.bounds[1] for piece in shapely.intersection(curves, span) if not piece.is_empty)])


def _number_rows(low: float) -> list[tuple[float, float]]:
    """The (bottom, top) mm of the rows a diagram's numbers stand in: the band under the φ axis, then, where the
    curves dip under the axis, the band under their lowest point (``low``, nought or less)."""
    rows = [(-BAND_DEPTH_MM, -NUMBER_CLEARANCE_MM)]
    if low < 0.0:
        top = low - LOW_ROW_CLEARANCE_MM
        rows.append((top - NUMBER_HEIGHT_MM, top))
    return rows


def _numbers(ticks: list[tuple[float, str]], obstacles: list, rows: list[tuple[float, float]],
             curves: list) -> tuple[Text, ...]:
    """The positions' numbers, each in the first row where a spot at its tick ``(x, number)``, or stepped a little
    along the row, covers none of the lines (``obstacles``) nor another number; one with no such spot is left out,
    its tick kept.  The rows are tried in turn: the band under the axis, then, where the ``curves`` (and the rings
    on them) cross the band within the number's reach of its tick, right under them there, no lower than the
    row under their lowest point (:func:`_number_rows`), which so is the row by the tick where the curves dip
    lowest there.  Nowhere else: a number in the row under the curves' lowest point far from where they pass its
    tick stood far under the tick with nothing between to say whose it is (the shaper's 5 of aE, 16 mm down; the
    shaper starter's 1 of vE, whose ring on the axis took the band, 80 mm down at the ordinate axis's foot).

    Every spot lies in the band or between it and the row under the curves' lowest point, within a number's reach
    of its tick: inside the diagram's extent, whatever the curves do, and under the axis.
    """
    tree = STRtree(obstacles)
    spots: list[tuple[int, float, float]] = []  # (tick, centre x, baseline) of every spot, in the order tried
    boxes = []
    band, *lower = rows
    # The extent keeps room down to the row under the curves' lowest point; a ring dips a little under that.
    floor = lower[-1][1] if lower else band[1]
    for index, (x, number) in enumerate(ticks):
        half = text_width(number, NUMBER_SIZE) / 2
        most = int((half + NUMBER_REACH_MM) / NUMBER_STEP_MM)
        steps = sorted(range(-most, most + 1), key=lambda k: (abs(k), -k))
        reach = most * NUMBER_STEP_MM + half
        under = max(_under_the_curves(curves, x - reach, x + reach) - LOW_ROW_CLEARANCE_MM, floor)
        by_the_tick = [(under - NUMBER_HEIGHT_MM, under)] if under < band[1] - 1e-9 else []
        for y0, y1 in [band, *by_the_tick]:
            for k in steps:
                centre = x + k * NUMBER_STEP_MM
                spots.append((index, centre, y0 + 0.3 * NUMBER_SIZE))
                boxes.append((centre - half, y0, centre + half, y1))
    grown = np.asarray(boxes, dtype=float) + np.array([-1.0, -1.0, 1.0, 1.0]) * NUMBER_MARGIN_MM
    hit, _ = tree.query(shapely.box(*grown.T), predicate="intersects") if obstacles else (np.array([], int), None)
    blocked = np.zeros(len(boxes), dtype=bool)
    blocked[hit] = True
    chosen: dict[int, int] = {}
    taken: list[tuple[float, float, float, float]] = []
    for spot, (index, _, _) in enumerate(spots):
        if index in chosen or blocked[spot]:
            continue
        x0, y0, x1, y1 = boxes[spot]
        if any(x0 < b1 + NUMBER_SPACING_MM and b0 < x1 + NUMBER_SPACING_MM and y0 < d1 and c0 < y1
               for b0, c0, b1, d1 in taken):
            continue
        chosen[index] = spot
        taken.append(boxes[spot])
    return tuple(Text((spots[spot][1], spots[spot][2]), ticks[index][1], NUMBER_SIZE, "middle")
                 for index, spot in sorted(chosen.items()))


def _pole_distance(word: str, pole: float, foot: float, high: float, obstacles: list) -> Text:
    """The pole distance's letter H between the pole and the ordinate axis, in the clear spot nearest the middle
    of the distance just over the axis (between the rays where they fan over and under it); where the rays leave
    none, the spot that covers fewest.  Every spot lies between the ordinate axis's ``foot`` and its top, and
    within the distance: inside the diagram's extent."""
    size = POLE_DISTANCE_SIZE
    half = text_width(word, size) / 2
    xs = np.arange(-pole + half + 1.5, -half - 1.0 + 1e-9, 0.5)
    if not len(xs):
        xs = np.array([-pole / 2])
    # Baselines from just over the axis (the box 0.8 mm clear of it) up to under the ordinate's top, and from just
    # under it down to the ordinate axis's foot.
    over = np.arange(0.8 + 0.3 * size, high + AXIS_RUN_MM - 6.0, 0.5)
    under = np.arange(-0.8 - 1.15 * size, foot + 0.3 * size - 1e-9, -0.5)
    baselines = np.concatenate((over, under))
    x, y = (grid.ravel() for grid in np.meshgrid(xs, baselines))
    distance = np.hypot(x + pole / 2, y - over[0])
    order = np.argsort(distance, kind="stable")
    x, y = x[order], y[order]
    # Tried nearest first, a few hundred at a time: the spot is mostly among the first.
    tree = STRtree(obstacles)
    fewest = (math.inf, 0)
    for start in range(0, len(x), _H_SPOTS_AT_A_TIME):
        near = slice(start, start + _H_SPOTS_AT_A_TIME)
        boxes = shapely.box(x[near] - half - 0.3, y[near] - 0.3 * size - 0.3, x[near] + half + 0.3,
                            y[near] + 1.15 * size + 0.3)
        hit, _ = tree.query(boxes, predicate="intersects")
        counts = np.bincount(hit, minlength=len(boxes))
        best = int(np.argmin(counts))  # the first, nearest, of the fewest covered
        fewest = min(fewest, (int(counts[best]), start + best))
        if fewest[0] == 0:
            break
    best = fewest[1]
    return Text((float(x[best]), float(y[best])), word, size, "middle")


def _strokes(record: KinematicDiagrams, words: Mapping[str, str], y: float) -> list[Primitive]:
    """Dimension lines under the φ axis: the working stroke from 0 to its end, the idle stroke after it."""
    end = record.stroke_end / record.scales.along
    length = record.scales.axis_mm
    items: list[Primitive] = []
    for x0, x1, key, angle in ((0.0, end, "kd_working_stroke", record.stroke_end),
                               (end, length, "kd_idle_stroke", 2.0 * math.pi - record.stroke_end)):
        items.append(Polyline(((x0, y), (x1, y)), _THIN))
        items.extend(Polyline(((x, y - 1.5), (x, y + 1.5)), _THIN) for x in (x0, x1))
        items.append(Text(((x0 + x1) / 2, y - 1.3 - SCALE_SIZE), words[key].format(angle=f"{math.degrees(angle):.1f}"),
                          SCALE_SIZE, "middle"))
    return items


def _difference(record: KinematicDiagrams, kind: str, words: Mapping[str, str]) -> str:
    """How far the chord method's velocity or acceleration (``kind``) comes from the analytic one: a share of the
    analytic peak, or where that is nought throughout (a crank's ε at constant ω), the value itself."""
    symbol, unit = _symbol(record, kind, words)
    peak = record.v_peak if kind == "velocity" else record.a_peak
    largest = record.largest_v_difference if kind == "velocity" else record.largest_a_difference
    analytic = record.v if kind == "velocity" else record.a
    if np.any(analytic):
        return words["kd_difference"].format(value=f"{largest:.2f}", symbol=symbol, peak=f"{peak:.4g}", unit=unit)
    scale = record.scales.velocity if kind == "velocity" else record.scales.acceleration
    read = round(largest / 100.0 * peak / scale, 2) * scale  # to a hundredth of a millimetre of paper
    return words["kd_difference_nought"].format(value=f"{read:.3g}", symbol=symbol, unit=unit)


def scales_and_differences(record: KinematicDiagrams,
                           words: Mapping[str, str]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The scales the diagrams are drawn at (the common abscissa's, then each diagram's with its pole distance) and
    how far the chord method's derivatives come from the analytic ones, each as the drawing writes it: for the note,
    which gives them beside the figure."""
    scales = (_abscissa_scale(record, words),
              *(_scale_line(record, kind, words, _symbol(record, kind, words)[1]) for kind in KINDS))
    return scales, tuple(_difference(record, kind, words) for kind in KINDS[1:])


def _scale_line(record: KinematicDiagrams, kind: str, words: Mapping[str, str], unit: str) -> str:
    scales = record.scales
    per_mm = words["kd_per_mm"].format(unit=f"({unit})" if "/" in unit else unit)
    # A turning output link's diagrams are of ψ, ω and ε, whose scales the textbooks (and the load diagram beside
    # them) write μψ, μω, με: a slider's μs, μv, μa over a unit in radians read as a misprint.
    turning = "" if record.translating else "_turning"
    if kind == "displacement":
        return words[f"kd_displacement_scale{turning}"].format(value=format_scale(scales.displacement), unit=per_mm)
    if kind == "velocity":
        return words[f"kd_velocity_scale{turning}"].format(value=scale_factor(scales.velocity), unit=per_mm,
                                                           pole=f"{scales.velocity_pole:g}")
    return words[f"kd_acceleration_scale{turning}"].format(value=scale_factor(scales.acceleration), unit=per_mm,
                                                           pole=f"{scales.acceleration_pole:g}")


def _footer(record: KinematicDiagrams, words: Mapping[str, str], top: float) -> Layer:
    """The legend (analytic, chord method) and the scales of the common φ axis, under the last diagram (the rings
    of the velocity plans have their key under the velocity diagram)."""
    scales = record.scales
    y = top + GAP_MM - 8.0
    # The second entry starts 60 mm in, or further when the first one's word is longer.
    second = max(60.0, 14.0 + text_width(words["kd_analytic"], SCALE_SIZE) + 8.0)
    items: list[Primitive] = [
        Polyline(((0.0, y), (12.0, y)), _CURVE),
        Text((14.0, y - 1.2), words["kd_analytic"], SCALE_SIZE, "start"),
        Polyline(((second, y), (second + 12.0, y)), _CHORD), dot_marker((second + 6.0, y), 0.55, _CHORD_COLOUR),
        Text((second + 14.0, y - 1.2), words["kd_chord"], SCALE_SIZE, "start", _CHORD_COLOUR),
    ]
    # As far as the diagrams reach right of their ordinate axes, where the lines start: counted with the poles' room
    # left of the axes, a line of the scales at 3.5 mm ran 8 mm past the φ axes' arrows and took the diagrams off
    # the sheet they had shared with a plan sheet.
    width = max(scales.axis_mm + AXIS_RUN_MM + 6.0, second + 40.0)
    conventions = list(_conventions(record, words))
    # What the diagrams count otherwise than results.json stands beside the legend where it fits there: a line
    # more under the diagrams took them off a sheet they had shared.
    beside = second + 14.0 + text_width(words["kd_chord"], SCALE_SIZE) + 10.0
    while conventions and beside + text_width(conventions[0], SCALE_SIZE) <= width:
        items.append(Text((beside, y - 1.2), conventions[0], SCALE_SIZE, "start"))
        beside += text_width(conventions.pop(0), SCALE_SIZE) + 10.0
    lines = [line for words_ in (_abscissa_scale(record, words), *conventions)
             for line in fitted(words_, width, SCALE_SIZE)]
    items += [Text((0.0, y - 8.0 - k * LINE_SPACING * SCALE_SIZE), line, SCALE_SIZE, "start")
              for k, line in enumerate(lines)]
    return Layer("legend", tuple(items))


def _conventions(record: KinematicDiagrams, words: Mapping[str, str]) -> tuple[str, ...]:
    """How the diagrams count what results.json counts otherwise: positive in a clockwise or backward working
    sense (results.json: counter-clockwise, along the link), and the driver moving uniformly, its ε (s̈) left out
    of the acceleration. Said only where it is so."""
    symbols = [_symbol(record, kind, words)[0] for kind in KINDS]
    said = [words["kd_positive"].format(symbols=words["enumeration"].join(symbols))] if record.reversed else []
    if record.driver_rate:
        key = "kd_uniform_crank" if record.driver == "crank" else "kd_uniform_slider"
        said.append(words[key].format(speed=f"{record.driver_speed:.4g}", rate=f"{record.driver_rate:.4g}",
                                      symbol=symbols[-1]))
    return tuple(said)


def _abscissa(record: KinematicDiagrams, words: Mapping[str, str]) -> str:
    """The common abscissa's letter: the crank's angle φ, or the time t of a slider's run."""
    return words["kd_angle_axis"] if record.driver == "crank" else words["kd_time_axis"]


def _abscissa_scale(record: KinematicDiagrams, words: Mapping[str, str]) -> str:
    """The scales of the common abscissa: μφ and μt over a crank's turn or swing, μt over a slider's travel."""
    scales = record.scales
    length, time = f"{scales.axis_mm:g}", scale_factor(scales.time)
    if record.driver == "slider":
        return words["kd_travel_scale"].format(time=time, length=length, travel=f"{record.span:.4g}",
                                               speed=f"{record.driver_speed:.4g}",
                                               duration=f"{record.span / record.driver_speed:.4g}")
    key = "kd_angle_scale" if record.cyclic else "kd_swing_scale"
    return words[key].format(value=scale_factor(scales.along), degrees=f"{math.degrees(scales.along):.4g}",
                             swing=f"{math.degrees(record.span):.4g}", length=length, time=time,
                             omega=f"{record.driver_speed:.4g}")
