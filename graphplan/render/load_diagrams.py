"""The load diagrams: each load given over a stroke drawn against its link's travel, as the force sheet reads it.

As a course project draws the useful-resistance diagram of a press or a
shaper, or the indicator diagram of a compressor, on its kinetostatics
sheet: the value F (or M) at μF over the travel s (or ψ) at μs, the stroke
from its start on the left; every analysed position ticked on the travel
axis at its link's travel there and numbered under it, in a row for each
stroke, an arrow giving the row's sense of travel; each position's value
its ordinate, and the plan positions' values ringed and written, the very
values their force sheets take.  Both strokes of a piston stand in one
diagram, the other stroke's load dashed.

The layout reads :class:`graphplan.load_diagrams.LoadDiagram` records and
computes no mechanics; its axes, lettering and stacking are those of the
kinematic diagrams (:mod:`graphplan.render.diagrams`) and the dynamics
(:mod:`graphplan.render.dynamics`).  Every word comes from the ``ld_`` keys of
a locale (:func:`graphplan.locale.strings`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from ..load_diagrams import LoadDiagram
from ..locale import strings
from ..scales import fit_scale, format_scale
from .diagrams import (
    AXIS_HEAD_MM,
    AXIS_RUN_MM,
    CAPTION_SIZE,
    LINE_SPACING,
    MOST_CONSTRUCTION_LINES,
    NUMBER_SIZE,
    PLAN_RING_MM,
    SCALE_SIZE,
    TICK_MM,
    TITLE_SIZE,
    stacked,
)
from .dynamics import ordinate_axis
from .labels import broken_under
from .numerals import short
from .primitives import Arrow, Circle, Layer, Polyline, Primitive, Stroke, Text, bounds_of, dot_marker, text_width
from .svg import to_svg
from .wrapping import fitted

# The field of a stroke's travel and of the values (mm): the standard scales fill them to between 40 % and
# all of them, 75 to 150 mm of travel, as a sheet's stroke is drawn beside the plans.
TRAVEL_MM = 150.0
FIELD_MM = 60.0
# Smaller fields for a small sheet that holds no diagram at the usual ones: tried in turn, largest first.
SMALLER_FIELDS = ((120.0, 45.0), (100.0, 40.0), (80.0, 30.0))
# The rows of the positions' numbers under the diagram, and between them (mm).
ROW_GAP_MM = 5.0
# The arrow before each row, giving its sense of travel (mm from the ordinate): drawn as the axes are, long enough
# that its head is theirs (an arrow's head takes at most primitives.HEAD_SHARE of it), and clear of the first number.
ROW_ARROW_FROM_MM, ROW_ARROW_TO_MM = -12.0, -4.0
# The drawing's title, laid over its first diagram.
TITLE_LAYER = "title"

_AXIS = Stroke(0.35)
_THIN = Stroke(0.18, "#555555")
_GUIDE = Stroke(0.15, "#9a9a9a", (1.0, 1.0))
# The reference stroke's load solid, the other stroke's dashed (a piston's return), as the dynamics draws its
# two moments.
_STROKES = (Stroke(0.5), Stroke(0.5, "#1f5fa8", (3.0, 1.5)))
# The arrow before each stroke's row of position numbers, the reference stroke's pointing along the travel.
ROW_ARROWS = {True: "→", False: "←"}


def load_diagrams_svg(diagrams: Sequence[LoadDiagram], text: Mapping[str, str] | None = None) -> str:
    """The SVG text of the load diagrams (:func:`layout`)."""
    return to_svg(layout(diagrams, text))


def layout(diagrams: Sequence[LoadDiagram], text: Mapping[str, str] | None = None,
           field: tuple[float, float] = (TRAVEL_MM, FIELD_MM)) -> list[Layer]:
    """The diagrams one under another, the drawing's title over the first; paper mm, y up."""
    return stacked(parts(diagrams, text, field))


def parts(diagrams: Sequence[LoadDiagram], text: Mapping[str, str] | None = None,
          field: tuple[float, float] = (TRAVEL_MM, FIELD_MM)) -> list[list[Layer]]:
    """Each diagram round the origin of its own travel axis, the drawing's title over the first; ``field`` the mm
    the stroke and the values fill at their standard scales (a small sheet's smaller)."""
    words = {**strings("en"), **(text or {})}
    drawn = [_panel(diagram, words, field) for diagram in diagrams]
    left, _, _, top = bounds_of(item for layer in drawn[0] for item in layer.items)
    heading = Text((left, top + 6.0), words["ld_title"], TITLE_SIZE, "start", weight="bold")
    drawn[0] = [*drawn[0], Layer(TITLE_LAYER, (heading,))]
    return drawn


def scales_of(diagram: LoadDiagram, field: tuple[float, float] = (TRAVEL_MM, FIELD_MM)) -> tuple[float, float]:
    """(μs, μF): the standard scales at which the stroke fills ``field``'s first mm (:data:`TRAVEL_MM`) and the
    values its second (:data:`FIELD_MM`); μs in m/mm, or rad/mm at a round number of degrees per mm, μF in N/mm
    or N·m/mm."""
    travel_mm, values_mm = field
    if diagram.translating:
        along = fit_scale(diagram.travel, travel_mm)
    else:
        along = math.radians(fit_scale(math.degrees(diagram.travel), travel_mm))
    values = [value for load in diagram.loads for _, value in load.outline]
    span = max(max(values), 0.0) - min(min(values), 0.0)
    return along, fit_scale(span, values_mm)


def _panel(diagram: LoadDiagram, words: Mapping[str, str], field: tuple[float, float]) -> list[Layer]:
    """One diagram with the start of its reference stroke at (0, 0)."""
    along, scale = scales_of(diagram, field)
    xs = (diagram.coordinates / along).tolist()
    length = diagram.travel / along
    lows = [value / scale for load in diagram.loads for _, value in load.outline]
    low, high = min(0.0, *lows), max(0.0, *lows)
    unit = words["newton"] if diagram.kind == "force" else words["newton_metre"]
    letter = "F" if diagram.kind == "force" else "M"
    symbol = _travel_symbol(diagram, words)
    # The abscissa named with its unit, as the ordinate is ("F, N") and the note's table heads it: "sB" alone
    # left the reader to guess metres or millimetres of paper.
    travel_axis = words["ld_travel_axis_translating" if diagram.translating else "ld_travel_axis_turning"].format(
        symbol=symbol)

    axes: list[Primitive] = [
        Arrow((0.0, 0.0), (length + AXIS_RUN_MM, 0.0), _AXIS, AXIS_HEAD_MM, key=f"load-{diagram.link}-travel-axis"),
        *ordinate_axis(0.0, low, high, scale, 0.0, f"{letter}, {unit}"),
        Text((length + AXIS_RUN_MM + 1.5, -SCALE_SIZE / 2), travel_axis, SCALE_SIZE, "start"),
    ]
    count = len(xs)
    every = math.ceil(count / MOST_CONSTRUCTION_LINES)
    shown = [k for k in range(count) if k % every == 0 or k in diagram.plans]
    axes.extend(Polyline(((xs[k], 0.0), (xs[k], TICK_MM)), _AXIS) for k in shown)

    curves: list[Primitive] = []
    ordinates: list[Primitive] = []
    for load in diagram.loads:
        stroke = _STROKES[0 if load.with_reference else 1]
        curves.append(Polyline(tuple((x / along, value / scale) for x, value in load.outline), stroke))
        for k in shown:
            value = float(load.values[k]) / scale
            if value:
                ordinates.append(Polyline(((xs[k], 0.0), (xs[k], value)), _THIN))
                curves.append(dot_marker((xs[k], value), 0.55, stroke.colour))

    # The values the force sheets take, ringed at the plan positions and written over the diagram, each on a
    # dotted leader up its ordinate: set free beside their rings they stood on the curves they are read off.
    rings: list[Primitive] = []
    written: list[tuple[float, float, str]] = []
    for k in diagram.plans:
        acting = [load for load in diagram.loads if load.values[k]]
        for load in acting or diagram.loads[:1]:
            value = float(load.values[k])
            rings.append(Circle((xs[k], value / scale), PLAN_RING_MM, _AXIS, None))
            names = [load.name] if acting else [other.name for other in diagram.loads]
            # The position's number with it: a ring of the idle stroke stands over another number of the working
            # stroke's row, and a jaw crusher's "F6 = 0 N" read as position 6's, where the load acts.
            label = f"{' = '.join(names)} = {short(value)} {unit} ({diagram.numbers[k]})"
            written.append((xs[k], value / scale, label))
    values_top, values = _written_values(written, high + AXIS_RUN_MM + 3.0)
    # A value written on a higher line, over one whose words reach across its ordinate (two plan positions close on
    # the travel), or one by the ordinate axis, had its leader struck through the other's words or the axis's name.
    written_words = [item for item in values + axes if isinstance(item, Text)]
    values = broken_under(values, written_words, [item for item in values if isinstance(item, Polyline)])
    rows, guides = _numbers(diagram, xs, shown, low)
    bottom = min(item.at[1] for item in rows if isinstance(item, Text)) - 4.0
    legend = _legend(diagram, words, bottom)
    width = max(length + AXIS_RUN_MM + 4.0 + text_width(travel_axis, SCALE_SIZE),
                max((item.at[0] + text_width(item.text, SCALE_SIZE) / 2 for item in values if isinstance(item, Text)),
                    default=0.0))
    caption = _caption(diagram, words, symbol, along, scale, max(high, values_top - AXIS_RUN_MM), width)
    name = f"load-{diagram.link}"
    return [Layer(f"{name}-axes", tuple(axes + guides)), Layer(f"{name}-ordinates", tuple(ordinates)),
            Layer(f"{name}-curves", tuple(curves + rings)),
            Layer(f"{name}-leaders", tuple(item for item in values if not isinstance(item, Text))),
            Layer(f"{name}-labels", tuple(item for item in values if isinstance(item, Text)) + tuple(rows) + legend),
            Layer(f"{name}-caption", caption)]


def _written_values(written: list[tuple[float, float, str]], base: float) -> tuple[float, list[Primitive]]:
    """The plan positions' values written over the diagram from ``base`` up, each centred over its ring (a value that
    would touch the one before it a line higher) on a dotted leader down to the ring; and the top of the lines."""
    items: list[Primitive] = []
    ends: list[float] = []
    top = base
    for x, y, label in sorted(written):
        half = text_width(label, SCALE_SIZE) / 2
        centre = max(x, half)   # not left of the ordinate axis, whose numbers stand there
        line = next((n for n, end in enumerate(ends) if centre - half >= end + 2.0), len(ends))
        if line == len(ends):
            ends.append(-math.inf)
        ends[line] = centre + half
        at = base + line * (SCALE_SIZE + 2.0)
        items.append(Text((centre, at), label, SCALE_SIZE, "middle"))
        items.append(Polyline(((x, y + PLAN_RING_MM), (x, at - 1.0)), _GUIDE))
        top = max(top, at + SCALE_SIZE)
    return top, items


def _numbers(diagram: LoadDiagram, xs: list[float], shown: list[int], low: float) -> tuple[list[Primitive],
                                                                                             list[Primitive]]:
    """The positions' numbers in a row for each stroke under the diagram, each under its tick (a number that would
    touch the one before it a line lower), an arrow before each row in its sense of travel; and, where the values
    reach below the axis, dotted guides down from the ticks to the rows."""
    items: list[Primitive] = []
    top = min(low, 0.0) - ROW_GAP_MM
    for reference in (True, False):
        members = sorted((k for k in shown if bool(diagram.in_reference[k]) == reference), key=lambda k: xs[k])
        if not members:
            continue
        ends: list[float] = []   # the right end of the last number on each line of the row
        for k in members:
            label = str(diagram.numbers[k])
            half = text_width(label, NUMBER_SIZE) / 2
            line = next((n for n, end in enumerate(ends) if xs[k] - half >= end + 0.6), len(ends))
            if line == len(ends):
                ends.append(-math.inf)
            ends[line] = xs[k] + half
            items.append(Text((xs[k], top - NUMBER_SIZE - line * (NUMBER_SIZE + 1.2)), label, NUMBER_SIZE, "middle"))
        y = top - NUMBER_SIZE / 2
        tail, tip = (ROW_ARROW_FROM_MM, ROW_ARROW_TO_MM) if reference else (ROW_ARROW_TO_MM, ROW_ARROW_FROM_MM)
        items.append(Arrow((tail, y), (tip, y), _AXIS, AXIS_HEAD_MM))
        top -= len(ends) * (NUMBER_SIZE + 1.2) + ROW_GAP_MM - 1.2
    guides: list[Primitive] = []
    if low < 0:
        guides = [Polyline(((xs[k], 0.0), (xs[k], low - ROW_GAP_MM + 1.0)), _GUIDE) for k in shown]
    return items, guides


def _travel_symbol(diagram: LoadDiagram, words: Mapping[str, str]) -> str:
    """The abscissa's symbol: the travel sB of a translating link's point, or the angle ψ4 of a turning link."""
    if diagram.translating:
        return words["ld_travel_translating"].format(point=diagram.point or diagram.link)
    return words["ld_travel_turning"].format(link=diagram.link)


def _caption(diagram: LoadDiagram, words: Mapping[str, str], symbol: str, along: float, scale: float, high: float,
             width: float) -> tuple[Text, ...]:
    """The diagram's title and its scales above it, the words no wider than the diagram."""
    names = words["enumeration"].join(load.name for load in diagram.loads)
    title = words["ld_diagram"].format(names=names, symbol=symbol, link=diagram.link)
    values = words["ld_force_scale" if diagram.kind == "force" else "ld_moment_scale"].format(
        value=format_scale(scale))
    if diagram.translating:
        travel = words["ld_travel_scale"].format(value=format_scale(along), travel=short(diagram.travel),
                                                 length=short(diagram.travel / along))
    else:
        travel = words["ld_angle_scale"].format(value=short(along, 4), degrees=short(math.degrees(along)),
                                                travel=short(math.degrees(diagram.travel)),
                                                length=short(diagram.travel / along))
    # The locale's semicolon: the travel's words (行程) make the line Chinese, its separators full-width.
    lines = fitted(words["semicolon"].join((values, travel)), max(width, 80.0), SCALE_SIZE)
    lowest = high + AXIS_RUN_MM + 4.0
    items = [Text((0.0, lowest + (len(lines) - 1 - k) * LINE_SPACING * SCALE_SIZE), line, SCALE_SIZE, "start")
             for k, line in enumerate(lines)]
    titled = lowest + (len(lines) - 1) * LINE_SPACING * SCALE_SIZE + SCALE_SIZE + 3.0
    return (Text((0.0, titled), title, CAPTION_SIZE, "start", weight="bold"), *items)


def _legend(diagram: LoadDiagram, words: Mapping[str, str], top: float) -> tuple[Primitive, ...]:
    """Under the rows: each load's line with its name and stroke, and the ring of the plan positions' values."""
    items: list[Primitive] = []
    y = top - SCALE_SIZE
    for load in diagram.loads:
        stroke = _STROKES[0 if load.with_reference else 1]
        own = load.spec.stroke or diagram.reference
        # Working and idle, as the note's table beside it and the kinematic diagrams name the strokes: the
        # diagram's reference stroke is its link's working stroke (a compressor's suction load, given over the
        # piston's backward stroke, acts in the idle one).
        named = words["working_stroke" if load.with_reference else "idle_stroke"]
        items.append(Polyline(((0.0, y + SCALE_SIZE / 3), (10.0, y + SCALE_SIZE / 3)), stroke))
        # The stroke's row of numbers by its arrow: a "backward" stroke's positions may well run → along the
        # travel, which counts from that stroke's start, and the reader would otherwise look for them in the ← row.
        row = ROW_ARROWS[load.with_reference]
        items.append(Text((12.0, y), words["ld_legend"].format(name=load.name, stroke=named,
                                                              link=own.link, row=row), SCALE_SIZE, "start"))
        y -= LINE_SPACING * SCALE_SIZE + 1.0
    if diagram.plans:
        items.append(Circle((5.0, y + SCALE_SIZE / 3), PLAN_RING_MM, _AXIS, None))
        items.append(Text((12.0, y), words["ld_plans"], SCALE_SIZE, "start"))
        # The bracket's meaning on a line of its own: said after the ring's words, the legend ran 47 mm wider than
        # the diagram and took a sheet of its own beside the force sheets it had stood among.
        y -= LINE_SPACING * SCALE_SIZE + 1.0
        items.append(Text((5.0, y), "(k)", SCALE_SIZE, "middle"))
        items.append(Text((12.0, y), words["ld_plans_number"], SCALE_SIZE, "start"))
    return tuple(items)


__all__ = ["FIELD_MM", "SMALLER_FIELDS", "TITLE_LAYER", "TRAVEL_MM", "layout", "load_diagrams_svg", "parts", "scales_of"]
