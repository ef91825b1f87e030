"""Drawing sheets of a course project: the format, the frame, the title block, and the drawings placed on it.

A sheet is an A1, A2, A3 or A4 format (A4 turned upright when that needs
fewer sheets, each A4 of a set turned its own way when no one way holds
all the drawings) with the frame and title block of the locale's drafting
standard: ESKD for ``ru`` (GOST 2.301 formats, GOST 2.104 frame: 20 mm
for binding on the left, 5 mm elsewhere), GB/T 14689 for ``zh`` (a = 25 mm
for binding, c = 10 mm on A1 and A2, 5 mm on A3 and A4, centring marks),
ISO 5457 for ``en`` (20 mm on the left, 10 mm elsewhere, centring marks).

The drawings come as :class:`~graphplan.render.packing.Panel` s, each at
its own scale factors, and :mod:`graphplan.render.packing` places them on
the sheets of a set.  A drawing at a scale the scene sets that no empty
sheet holds (the plan of positions or a mechanism at μl, a plan at its pole
distance, a force polygon at the scene's μF) is refused before anything is
placed, with the room there is, the scene's key and the value of it that
fits, and a bigger format that holds it.  A force sheet with a drawing that
no empty sheet holds is first lettered a size smaller, then its group cut
free or lever is drawn at the next larger standard scale (its caption and
the title block's scale box say which), since a small sheet is no reason
to give up a drawing that would fit a step smaller.
``sheet = "none"`` gives each panel unframed on a page of its own, as the
drawings were before sheets.
"""

from __future__ import annotations

import contextlib
import functools
import math
import re
from collections.abc import Callable, Collection, Iterator, Mapping, Sequence
from dataclasses import asdict, dataclass, replace

import shapely

from ..analysis import Analysis, PlanPosition
from ..errors import SceneError, words_wanted
from ..load_diagrams import LoadDiagram
from ..locale import Count, strings
from ..memo import OwnedMemo
from ..misreadings import SheetPolygons
from ..scales import finer_standard_scale, format_scale, next_standard_scale, standard_scale
from . import force_bodies, force_marks, force_polygons, force_rows
from . import forces as force_layout
from . import plans as plan_layout
from . import positions as positions_layout
from . import velocity_plans as velocity_plans_layout
from .drawings import (
    LEAST_POSITIONS_MM,
    at_length_scale,
    fitting_length_scale,
    force_sheet,
    largest_length_scale,
    length_scale,
    paths_extent,
    plan_sheet,
    positions_plan,
    velocity_plans_drawing,
    with_length_scale,
)
from .dynamics import TITLE_LAYER, Redrawings
from .dynamics import headings as dynamics_headings
from .force_lever import LEVER_FIELD
from .force_rows import HEADING_LAYER, has_heading
from .force_sheet_choice import (
    CutChoice,
    ForceSheetWays,
    fewest_sheets_cuts,
    larger_ways,
    larger_where_room,
    loads_saving_a_sheet,
    read_after_forces,
)
from .formats import (
    BIGGER,
    FORMATS,
    Rect,
    check_sheet,
    holds,
    orientations,
    page_geometry,
    usual_orientations,
)
from .labels import obstacles_of
from .numerals import scale_factor
from .packing import (
    Page,
    Panel,
    bigger_holding,
    height,
    overlap,
    pack,
    reads_in_order,
    rooms,
    smallest_drawings,
    width,
)
from .plans import CAPTION_GAP_MM, Arrangement
from .primitives import (
    MAIN,
    Arrow,
    Layer,
    Polyline,
    Primitive,
    Stroke,
    Text,
    bounds,
    bounds_of,
    moved,
    moved_layers,
    prefixed,
    renamed_layer,
    text_extent,
    text_width,
)
from .svg import to_svg
from .title_block import (
    Details,
    TitleBlockFields,
    corner_box,
    details_of,
    fitting_name,
    form_of,
    labels,
    scale_text,
    title_block,
)
from .wrapping import fitted, joined

# How far a centring mark reaches into the drawing area past the frame (ISO 5457, GB/T 14689).
CENTRING_REACH_MM = 5.0
# The kinematic diagrams are shortened for a small sheet in at most this many rounds, to no less of a field.
_SHORTENING_ROUNDS = 8
_LEAST_FIELD_MM = 10
# Where the kinematic diagrams stand apart, their fields are lowered to this share of their height at most to put
# them on fewer sheets: a fifth lower still reads as the same diagram, a sheet less is a sheet less to draw.
_FIELD_GIVEN_FOR_A_SHEET = 0.8
# A force sheet's drawing is drawn at most this many standard scales smaller to fit a small sheet.
_LARGER_SCALES_TRIED = 12
# A "none" page has this margin round its drawing, as the drawings before sheets had.
UNFRAMED_MARGIN_MM = 8.0
# A title too wide for a sheet is broken to narrower than these shares of its width, in turn: at its last phrase
# (the English and Russian plan sheet's titles after their comma), then into three lines or so (the Russian title's
# first line, 181 mm, was still too wide for an upright A4 beside its ESKD corner box).
HEADING_SHARES = (1.0, 0.6)
# How much narrower than that share a broken title must be, so that the whole title is broken at a phrase or a word.
NARROWER_BY_MM = 0.5

_EDGE = Stroke(0.2, "#555555")
_CENTRING = Stroke(0.7)


@dataclass(frozen=True)
class Sheet:
    """One laid out sheet.

    ``size`` is the format (width, height mm) or None for an unframed page;
    ``layers`` are in sheet millimetres from the lower left corner (y up);
    ``frame`` the inner frame and ``title_block`` the block (xmin, ymin,
    xmax, ymax), None on an unframed page; ``panels`` the bounds of each
    drawing placed, by panel name; ``number`` and ``count`` as in the title
    block.
    """

    format: str
    size: tuple[float, float] | None
    layers: list[Layer]
    frame: Rect | None
    title_block: Rect | None
    panels: dict[str, Rect]
    number: int
    count: int

    def svg(self) -> str:
        return sheet_svg(self.layers, self.size)


# Panels of an analysis.

def panel_of(drawing: Panel | Sequence[Layer], name: str) -> Panel:
    """``drawing`` as a panel: a panel as it is, a list of layers as a whole panel named ``name``."""
    if isinstance(drawing, Panel):
        return drawing
    layers = tuple(drawing)
    if not all(isinstance(layer, Layer) for layer in layers):
        raise ValueError(f"panel {name!r}: expected a Panel or a list of Layer, got {drawing!r:.80}")
    return Panel(name, layers)


def split(arrangement: Arrangement, name: str, label: str,
          together: Callable[[str], str] | None = None) -> Panel:
    """A laid out sheet (:func:`graphplan.render.plans.arrange`, :func:`graphplan.render.forces.arrange`) as a panel.

    Its parts are its fields, each with the layers named after it (the
    field ``velocity``: ``velocity-lines``, ``velocity-caption``, ...); a
    layer of no field (the sheet's title) stays with the whole only.
    ``together`` maps a field to the name of the part it goes in: fields
    of one part (a group cut free and its force polygon) stay side by side
    as laid out, and stand apart only when the part does not fit a sheet.
    """
    fields = sorted(arrangement.fields, key=len, reverse=True)
    members: dict[str, list[Layer]] = {key: [] for key in arrangement.fields}
    for layer in arrangement.layers:
        owner = next((key for key in fields if layer.name == key or layer.name.startswith(key + "-")), None)
        if owner is not None:
            members[owner].append(layer)
    alone = {key: Panel(f"{name}-{key}", tuple(_renamed(_captioned(layers, key), key)))
             for key, layers in members.items() if layers}
    groups: dict[str, list[str]] = {}
    for key in alone:
        groups.setdefault(together(key) if together else key, []).append(key)
    parts = []
    for group, keys in groups.items():
        if len(keys) == 1:
            parts.append(alone[keys[0]])
        else:
            parts.append(Panel(f"{name}-{group}", tuple(layer for key in keys for layer in members[key]),
                               tuple(alone[key] for key in keys)))
    return Panel(name, tuple(arrangement.layers), tuple(parts), label)


def _headed(panel: Panel, continued: str) -> Panel:
    """A plan sheet as a panel with its title as the heading its parts stand under on sheets of their own, the
    sheets after the first under the title "continued" (``continued``, a format of ``{title}``)."""
    heading = tuple(layer for layer in panel.layers if layer.name == plan_layout.TITLE_LAYER)
    ways = tuple(tuple(_continued(layer, continued, broken, share) for layer in heading)
                 for broken, share in ((False, None), (True, None), *((True, share) for share in HEADING_SHARES)))
    narrower = (tuple(_continued(layer, "{title}", True, share) for layer in heading) for share in HEADING_SHARES)
    return replace(panel, heading=heading, continued_heading=tuple(dict.fromkeys(ways)),
                   broken_heading=tuple(way for way in dict.fromkeys(narrower) if way != heading),
                   alternatives=tuple(_headed(way, continued) for way in panel.alternatives))


def _continued(title: Layer, continued: str, broken: bool, share: float | None = None) -> Layer:
    """``title``'s layer with its title "continued" (``continued``, a format of ``{title}``), on one line or
    ``broken`` to no wider than the title (which a sheet holds), or, given a ``share``, to narrower than that share
    of the title (the title itself too wide for a sheet: an A4 across held "Velocity and acceleration plans,
    position 5" and not, by half a millimetre, position 11's), its last line where the title stands and the others
    above."""
    first = next(item for item in title.items if isinstance(item, Text))
    line = continued.format(title=first.text)
    room = text_width(first.text, first.size, first.weight)
    if share is not None:
        room = share * room - NARROWER_BY_MM
    lines = fitted(line, room, first.size, first.weight) if broken else [line]
    return Layer(title.name, plan_layout.title_texts(lines, first.size, first.at))


def _group_of_field(field_name: str) -> str:
    """The part a field of the force sheet goes in: a group cut free with its equations and polygons, the lever
    alone."""
    for kind in ("body-", "equations-", "polygon-"):
        if field_name.startswith(kind):
            return "group-" + field_name[len(kind):]
    return field_name


def _captioned(layers: Sequence[Layer], field_name: str) -> list[Layer]:
    """A field's layers with its caption moved up under its drawing.

    A sheet's fields are as tall as its tallest drawing, and each caption
    stands under its field: a drawing set apart keeps its caption at
    :data:`~graphplan.render.plans.CAPTION_GAP_MM` under itself instead.
    """
    caption_name = f"{field_name}-caption"
    captions = [layer for layer in layers if layer.name == caption_name and layer.items]
    # A title over the field (the velocity plans', over the first of them) is wider than its drawing: the
    # caption goes under the drawing alone.
    drawing = [layer for layer in layers if layer.name not in (caption_name, f"{field_name}-title")]
    if not captions or not any(layer.items for layer in drawing):
        return list(layers)
    x0, y0, x1, _ = bounds(drawing)
    first = captions[0].items[0]
    if not isinstance(first, Text):
        return list(layers)
    dx, dy = (x0 + x1) / 2 - first.at[0], y0 - CAPTION_GAP_MM - first.at[1]
    return [moved_layers([layer], dx, dy)[0] if layer.name == caption_name else layer for layer in layers]


def _renamed(layers: Sequence[Layer], field_name: str) -> list[Layer]:
    """Layers of a field named without the field's name, which their panel's name will carry."""
    def short(value: str) -> str:
        return value[len(field_name) + 1:] if value.startswith(field_name + "-") else value

    return [renamed_layer(layer, short(layer.name), [replace(item, key=short(item.key))
                                                     if isinstance(item, Arrow) and item.key else item
                                                     for item in layer.items]) for layer in layers]


def kinematics_panels(analysis: Analysis) -> list[Panel]:
    """The plan of positions, then the plan sheet (mechanism, velocity and acceleration plans) of each plan position."""
    text = strings(analysis.scene.locale)
    panels = [Panel("positions", tuple(positions_layout.layout(positions_plan(analysis))))]
    if analysis.velocity_plans:
        panels.append(velocity_plans_panel(analysis))
    for position in analysis.plans:
        sheet = plan_sheet(analysis, position.index, position.velocity, position.acceleration)
        row, *others = _plan_sheet_ways(sheet, text)
        # In the force sheets' words: one "continued" for every drawing that goes on onto another sheet.
        panels.append(_headed(replace(row, alternatives=tuple(others)), text["force_sheet_continued"]))
    return panels


def _plan_sheet_ways(sheet: plan_layout.PlanSheet, text: Mapping[str, str],
                     shapes: Sequence[str] = tuple(plan_layout.SHAPES)) -> list[Panel]:
    """The plan sheet as a panel in each of ``shapes``, its captions naming its position, its plans standing apart
    each in the ways its caption may read (:func:`_plans_captioned_apart`)."""
    label = text["plan_sheet_title"].format(number=sheet.number)
    return [_plans_at_no_length_scale(_plans_captioned_apart(
        split(_on_their_captions(arrangement), f"plan-{sheet.number}", label), sheet, text))
        for arrangement in _arranged_naming_position(sheet, text, shapes)]


def _plans_captioned_apart(panel: Panel, sheet: plan_layout.PlanSheet, text: Mapping[str, str]) -> Panel:
    """``panel`` with each plan among its parts in the ways its caption naming its position may read: broken to
    the width the plan took with its unnamed caption where one line is wider, then on one line.

    A part apart takes its caption's width: the Russian class III triad's
    velocity plan, 98 mm wide, took 127 under «План скоростей, положение 8»,
    and its plan sheet, three parts on one A3, went over two.
    """
    parts = []
    for part in panel.parts:
        field = part.name.rsplit("-", 1)[-1]
        caption = next((layer for layer in part.layers if layer.name == "caption" and layer.items), None)
        if field not in _NAMED_CAPTIONS or caption is None or not isinstance(caption.items[0], Text):
            parts.append(part)
            continue
        attribute, key = _NAMED_CAPTIONS[field]
        name, rest = text[key].format(number=sheet.number), getattr(sheet, attribute)[1:]
        x0, _, x1, _ = bounds([layer for layer in part.layers if layer.name != "caption"])
        room = max(x1 - x0, *(text_width(line, plan_layout.CAPTION_SIZE, "bold" if k == 0 else "normal")
                              for k, line in enumerate(getattr(sheet, attribute))))

        def captioned(lines: Sequence[str], part: Panel = part, at: tuple[float, float] = caption.items[0].at,
                      rest: Sequence[str] = rest) -> Panel:
            texts = _name_in_bold(plan_layout.caption_texts((*lines, *rest), at), len(lines))
            return replace(part, layers=tuple(Layer("caption", texts) if layer.name == "caption" else layer
                                              for layer in part.layers))

        ways = [captioned((name,))]
        if text_width(name, plan_layout.CAPTION_SIZE, "bold") > room + 1e-6:
            # Broken first: a part is placed in the first of its ways a sheet holds, and on one line it left no room
            # for the part after it.  On one line where only that fits, a line lower.
            ways.insert(0, captioned(_name_lines(name, room)))
        parts.append(replace(ways[0], alternatives=tuple(ways[1:])))
    return replace(panel, parts=tuple(parts))


# The plans' captions, by field, and the words that name their position on a course sheet.
_NAMED_CAPTIONS = {"velocity": ("velocity_caption", "velocity_plan_caption"),
                   "acceleration": ("acceleration_caption", "acceleration_plan_caption")}


def _arranged_naming_position(sheet: plan_layout.PlanSheet, text: Mapping[str, str],
                              shapes: Sequence[str] = tuple(plan_layout.SHAPES)) -> list[Arrangement]:
    """``sheet`` in each of its shapes (:data:`~graphplan.render.plans.SHAPES`), its plans' captions naming its
    position, as its mechanism's does.

    On a course sheet another position's drawings stand beside these, and
    the plan sheet's heading is over its first drawing only: the plans of
    position 4 at the foot of the slotted lever's sheet stood level with the
    caption of position 11's mechanism and read as that position's.  A
    caption that would reach past the drawing's edge, where the shorter one
    did not, is broken to the room the shorter one left: the Russian
    crank-rocker's row, 15 mm wider for «План ускорений, положение 11», no
    longer fitted an A3 and took two sheets a position.
    """
    bare = plan_layout.arrangements(sheet, shapes)
    named_lines = {field: text[key].format(number=sheet.number) for field, (_, key) in _NAMED_CAPTIONS.items()}
    arranged = []
    for shape, unnamed in zip(shapes, bare, strict=True):
        left, _, right, _ = bounds(unnamed.layers)
        captions, broken = {}, {}
        for field, (attribute, _) in _NAMED_CAPTIONS.items():
            if field not in unnamed.fields:
                continue
            x0, _, x1, _ = unnamed.fields[field]
            # As wide as the caption may be, centred under its field, within the drawing's bounds as they were.
            room = 2 * min((x0 + x1) / 2 - left, right - (x0 + x1) / 2)
            lines = _name_lines(named_lines[field], room)
            captions[attribute] = (*lines, *getattr(sheet, attribute)[1:])
            broken[f"{field}-caption"] = len(lines)
        laid = plan_layout.arrangements(replace(sheet, **captions), (shape,))[0]
        # A caption sets its first line in bold, the drawing's name: the name's every line, where it is broken.
        arranged.append(replace(laid, layers=[
            replace(layer, items=_name_in_bold(layer.items, broken[layer.name]))
            if broken.get(layer.name, 1) > 1 else layer for layer in laid.layers]))
    return arranged


def _name_lines(name: str, room: float) -> tuple[str, ...]:
    """A plan's caption's name on one line, or broken to ``room`` (mm) where one line is wider."""
    if text_width(name, plan_layout.CAPTION_SIZE, "bold") > room + 1e-6:
        return tuple(fitted(name, room, plan_layout.CAPTION_SIZE, "bold"))
    return (name,)


def _name_in_bold(texts: Sequence[Primitive], lines: int) -> tuple[Primitive, ...]:
    """A caption's ``texts`` with its first ``lines``, the drawing's name, in bold: a caption sets its first line
    so, and a name broken over lines is every line of it."""
    return tuple(replace(item, weight="bold") if k < lines else item for k, item in enumerate(texts))


def _on_their_captions(arrangement: Arrangement) -> Arrangement:
    """``arrangement`` with each drawing lowered to the foot of its field, just over its caption.

    A field is as tall as the tallest drawing of its row (the mechanism's
    beside both plans, as tall as the two): the drawing stood in its middle
    and its caption under the field, 130 mm under the slotted lever's
    mechanism, level with the plans of another position beside it.  At the
    foot, the captions of a row still share a line.
    """
    keys = sorted(arrangement.fields, key=len, reverse=True)

    def owner(layer: Layer) -> str | None:
        return next((key for key in keys if layer.name == key or layer.name.startswith(key + "-")), None)

    drops: dict[str, float] = {}
    for key, (_, field_bottom, _, _) in arrangement.fields.items():
        drawing = [layer for layer in arrangement.layers
                   if owner(layer) == key and layer.name != f"{key}-caption" and layer.items]
        if drawing:
            drops[key] = field_bottom - bounds(drawing)[1]
    layers = [moved_layers([layer], 0.0, drops[key])[0]
              if (key := owner(layer)) in drops and layer.name != f"{key}-caption" else layer
              for layer in arrangement.layers]
    return replace(arrangement, layers=layers)


def _plans_at_no_length_scale(panel: Panel) -> Panel:
    """A plan sheet whose velocity and acceleration plans, standing apart from its mechanism on a sheet, are
    drawn at μV and μa, no length scale: a sheet of them alone leaves its scale box empty."""
    return replace(panel, parts=tuple(part if part.name.endswith("-mechanism") else _to_no_length_scale(part)
                                      for part in panel.parts))


# The grid of the velocity plans of every position is tried in up to this many columns, to fit a sheet's room.
_MOST_VELOCITY_PLAN_COLUMNS = 6


def velocity_plans_panel(analysis: Analysis) -> Panel:
    """The velocity plans of every position as a panel: in the grid shaped like a sheet, or in another count of
    columns where that fits the room, or each plan apart where no sheet holds the grid."""
    drawing = velocity_plans_drawing(analysis)
    text = strings(analysis.scene.locale)
    label = text["velocity_plans_heading"]
    # The force sheets' "(continued)": one wording for every drawing that goes on onto another sheet.
    continued = text["force_sheet_continued"].format(title=drawing.title)
    counts = (None, *range(1, min(len(drawing.plans), _MOST_VELOCITY_PLAN_COLUMNS) + 1))
    first, *others = (_rows_continued(replace(split(arrangement, "velocity-plans", label, _row_of(arrangement)),
                                              in_order=True), drawing, continued)
                      for arrangement in velocity_plans_layout.arrangements(drawing, counts))
    others = [way for way in others if _size(way.layers) != _size(first.layers)]
    # Plans drawn at μV, no length: a sheet of them alone leaves its title block's scale box empty.
    return _to_no_length_scale(replace(first, alternatives=tuple(others), runs=_grid_runs(drawing, label, continued),
                                       run_count=len(drawing.plans)))


def _grid_runs(drawing: velocity_plans_layout.VelocityPlans, label: str, continued: str) -> Callable[[int, int], Panel]:
    """The grid's plans ``start`` to ``stop`` - 1 as one drawing, for a sheet that holds as many as its room does
    (:attr:`Panel.runs`): in as many columns as they are, up to the most tried, and in each fewer; a run after the
    first under the title "continued" with μV, as a grader measures each sheet's plans by the μV on it."""
    arranged = velocity_plans_layout.runs(drawing)
    # Broken to no narrower than the title, which a sheet holds, nor than the run's plans.
    least = text_width(drawing.title, plan_layout.TITLE_SIZE, "bold")

    def run(start: int, stop: int) -> Panel:
        ways = []
        name = f"velocity-plans-from-{start + 1}"
        for arrangement in arranged(start, stop, range(min(stop - start, _MOST_VELOCITY_PLAN_COLUMNS), 0, -1)):
            way = split(arrangement, name, label)
            if not start:
                ways.append(_to_no_length_scale(way))
                continue
            x0, _, x1, top = way.extent
            # On one line where the sheet has the room, else broken to the title's width, or narrower down to the
            # plans' (an upright A4 is narrower than the title), the fewest lines the sheet holds.
            rooms = sorted({max(least * share, x1 - x0) for share in (1.0, 0.75, 0.5, 0.0)}, reverse=True)
            for lines in dict.fromkeys((continued,) if room is None
                                       else tuple(fitted(continued, room, plan_layout.TITLE_SIZE, "bold"))
                                       for room in (None, *rooms)):
                heading = Layer(HEADING_LAYER,
                                velocity_plans_layout.heading_texts(lines, drawing.scale_line, (x0, top)))
                ways.append(_to_no_length_scale(replace(way, layers=(*way.layers, heading))))
            if stop - start == 1:
                # Last of all a plan bare, as the plans stood apart before: on a sheet that holds it under no heading
                # (a Russian A4's) it shares that sheet with nothing, whose title block names it.
                ways.append(_to_no_length_scale(way))
        return replace(ways[0], alternatives=tuple(ways[1:]))

    return run


def _rows_continued(panel: Panel, drawing: velocity_plans_layout.VelocityPlans, continued: str) -> Panel:
    """The grid's rows after the first each under a "continued" heading with μV, going on from the row before.

    The title and μV stand over the first row only: a row that the packing
    puts on a sheet of its own stood bare, and its plans could not be
    measured.  A row on the sheet of the row before loses the heading there
    (:attr:`Panel.continues`), so the grid on one sheet reads as one drawing.
    """
    # Broken to no narrower than the first row's title, which a sheet holds, nor than the row's plans.
    least = text_width(drawing.title, plan_layout.TITLE_SIZE, "bold")
    rows = []
    for k, part in enumerate(panel.parts):
        if k:
            x0, _, x1, top = part.extent
            lines = fitted(continued, max(least, x1 - x0), plan_layout.TITLE_SIZE, "bold")
            heading = Layer(HEADING_LAYER, velocity_plans_layout.heading_texts(lines, drawing.scale_line, (x0, top)))
            part = replace(part, layers=(*part.layers, heading), continues=panel.parts[k - 1].name)
        rows.append(part)
    return replace(panel, parts=tuple(rows))


def _to_no_length_scale(panel: Panel) -> Panel:
    """``panel``, its parts and its other ways marked as drawn to no length scale."""
    return replace(panel, to_scale=False, parts=tuple(_to_no_length_scale(part) for part in panel.parts),
                   alternatives=tuple(_to_no_length_scale(way) for way in panel.alternatives))


def _row_of(arrangement: Arrangement) -> Callable[[str], str]:
    """The part a plan of the grid goes in where no sheet holds the grid whole: its row, so that the rows stand
    on the sheets in order and each reads left to right (the plans one by one, placed where each fits best,
    read 1, 5, 2, 3, 4, 6, …); a row no sheet holds stands apart plan by plan."""
    tops = sorted({round(top, 6) for _, _, _, top in arrangement.fields.values()}, reverse=True)
    return lambda field: f"row-{tops.index(round(arrangement.fields[field][3], 6)) + 1}"


def force_panels(analysis: Analysis, sheet: str | None = None) -> list[Panel]:
    """The force sheet (groups cut free, force polygons, Zhukovsky's lever) of each plan position that has one,
    each followed by the force sheet with friction where the scene has friction and the reactions settle.

    Where a drawing of a force sheet fits no empty ``sheet`` (the scene's
    format by default), the force sheet's captions are lettered a size
    smaller; where that is not enough, a group cut free or the lever is
    drawn at the next larger standard scale, and so on until it fits: its
    caption says the scale it is drawn at.  A force sheet that no empty
    ``sheet`` holds whole in any arrangement of its rows stands in parts, in
    order, each whole under its heading: ``forces-5``, ``forces-5-2``, ...
    """
    chosen = analysis.scene.drawing.sheet if sheet is None else sheet
    forces = _force_sheets(analysis, chosen)
    return fewest_sheets_cuts([cuts for _, cuts, _, _ in forces], (), chosen, form_of(analysis.scene.locale),
                              [apart for _, _, apart, _ in forces])


def _force_sheets(analysis: Analysis, sheet: str | None = None) -> list[ForceSheetWays]:
    """Each force sheet of :func:`force_panels` whole (its rows down one column), the ways it may stand on
    sheets and its rows apart (:func:`fewest_sheets_cuts` chooses), and the same sheet drawn larger where an empty
    sheet holds it so whole (:func:`_larger_force_sheet`)."""
    chosen = analysis.scene.drawing.sheet if sheet is None else sheet
    found = []
    for position in analysis.plans:
        if position.forces is None:
            continue
        found.append(_force_panels(analysis, position, chosen))
        if position.with_friction is not None and not position.with_friction.locked:
            found.append(_force_panels(analysis, position, chosen, with_friction=True))
    return found


def _headless(part: Arrangement) -> bool:
    """Whether a part of a force sheet stands without a heading (a drawing too big to stand under one)."""
    return not has_heading(part.layers)


def _no_more_parts_or_headings_missing(parts: Sequence[Arrangement], kept: Sequence[Arrangement]) -> bool:
    """Whether the cut ``parts`` takes no more parts than ``kept`` and leaves no more of them without a heading."""
    return len(parts) <= len(kept) and sum(map(_headless, parts)) <= sum(map(_headless, kept))


def _force_panels(analysis: Analysis, position: PlanPosition, sheet: str,
                  with_friction: bool = False) -> ForceSheetWays:
    """The force sheet of ``position`` whole, and the ways it may stand on sheets: whole, or its parts in order
    where no empty ``sheet`` holds it whole in any way (each part whole under its heading, continued), cut as
    :meth:`force_rows.Rows.cuts` has them; its rows apart (:func:`_rows_apart`); and, where it stands whole as
    first drawn, the same sheet drawn larger (:func:`_larger_force_sheet`)."""
    words = labels(analysis.scene.locale)
    form = form_of(analysis.scene.locale)
    drawn = force_sheet(analysis, position, with_friction)
    name, label = ("forces-friction", "sheet_forces_friction_position") if with_friction else \
        ("forces", "sheet_forces_position")

    def fits(width: float, height: float) -> bool:
        return holds(sheet, form, width, height)

    enlarged = drawn if drawn.lever_enlarged else None
    first = drawn
    # The groups cut free, drawn once for all the versions of the sheet tried (:func:`force_layout.rows`).
    groups_cut_free: dict[tuple[int, float], force_layout.Drawing] = {}
    # The groups cut free that stand on a part of their own, their equations going on after them: drawn smaller
    # with their equations under them, their labels would cover one another.
    parted: set[str] = set()

    def laid(rows: force_rows.Rows) -> force_rows.Rows:
        return rows.parted(parted) if parted else rows

    def cut(drawn: force_layout.ForceSheet, one: Panel, cuts: list[list[force_rows.Part]], rows: force_rows.Rows
            ) -> tuple[force_layout.ForceSheet, Panel, list[list[Panel]], force_rows.Rows]:
        """Each cut's parts as panels (:func:`_part_panels`), the lever drawn larger where the sheet holds it so on
        its part without adding a part; the rows they are cut from."""
        parts = cuts[0]
        for larger in _larger_levers(enlarged, drawn) if enlarged is not None else ():
            larger_rows = force_layout.rows(larger, groups_cut_free)
            larger_cuts = laid(larger_rows).cuts(fits, headless=any(_headless(part) for part in parts))
            if larger_cuts and len(larger_cuts[0]) == len(parts):
                drawn, cuts, rows = larger, larger_cuts, larger_rows
                one = split(larger_rows.arranged(larger_rows.in_columns(1)), one.name, one.label, _group_of_field)
                break
        return drawn, one, [_part_panels(parts, one, rows.heading) for parts in cuts], rows

    before: dict[str, tuple[float, float]] = {}
    # The first way in parts with a drawing that stands under its heading only with its equations beside it, or
    # under none: taken only where no smaller lettering gives every part its heading over its equations under its
    # drawings (a part with none says whose it is by its title block alone).
    headless: tuple[force_layout.ForceSheet, Panel, list[list[force_rows.Part]], force_rows.Rows] | None = None
    for _ in range(_LARGER_SCALES_TRIED + _steps_to_plan_size(drawn)):
        rows = force_layout.rows(drawn, groups_cut_free)
        one, two = (split(rows.arranged(rows.in_columns(count)), f"{name}-{position.number}",
                          words[label].format(number=position.number), _group_of_field) for count in (1, 2))
        if sheet == "none":
            return replace(one, drawn_alone=True), [[one]], [], lambda steps: None
        # Its rows in two columns where a sheet is too low for them in one.
        cuts = [[replace(one, alternatives=(two,) if two.extent != one.extent else ())]]
        if any(fits(width(way), height(way)) for way in cuts[0][0].ways):
            headless = None
            break
        # A lever drawn larger than its plan gives the room back, a step at a time, before the sheet is cut up.
        if drawn.lever_enlarged:
            drawn = replace(drawn, lever_scale=_smaller_lever(drawn))
            continue
        # Else stacked, in more columns, or in parts on several sheets, each part under the heading.
        placed = laid(rows)  # the groups parted so far set apart from their equations, laid out once for the step
        found = placed.cuts(fits, headless=False)
        if found:
            drawn, one, cuts, rows = cut(drawn, one, found, rows)
            headless = None
            break
        # Lettered smaller, a part that stands under its heading only with its equations beside it may share a
        # part again, or a sheet: the crank-rocker's sheet with friction on a Russian A3 took five parts at the usual
        # lettering, four at the smaller one that the run's other force sheets are lettered at, and on an English A3
        # four at either, its group alone on a sheet at the usual lettering and beside its polygon at the smaller.
        found = placed.cuts(fits) if headless is None or drawn.caption_size < headless[0].caption_size else []
        if found and (headless is None or _no_more_parts_or_headings_missing(found[0], headless[2][0])):
            headless = (drawn, one, found, rows)
        # A drawing too big for a sheet: smaller lettering, then a larger scale.  One too big for a sheet under
        # its heading only: smaller lettering, but not a smaller drawing (1:2 made 1:4 for a heading).
        unheld = placed.unheld(fits)
        if not unheld and drawn.caption_size > force_layout.SMALL_CAPTION_SIZE:
            unheld = placed.unheld(fits, headed=True)
        if unheld == before or not unheld:
            break  # the packing cuts the panel up, or names the drawing that no sheet holds
        before = unheld
        lever = "lever" in unheld
        newly_parted = _parted_for_legibility(rows, drawn, groups_cut_free, unheld, fits) \
            if drawn.caption_size <= force_layout.SMALL_CAPTION_SIZE else set()
        parted |= newly_parted
        bodies = any(drawing.startswith("body-") and drawing not in newly_parted for drawing in unheld)
        if drawn.caption_size > force_layout.SMALL_CAPTION_SIZE:  # the next size of lettering first
            drawn = replace(drawn, caption_size=force_layout.SMALL_CAPTION_SIZE)
        elif newly_parted and not bodies and not lever:
            continue  # the same drawings, those groups parted from their equations
        elif bodies or lever:
            drawn = replace(
                drawn,
                length_scale=next_standard_scale(drawn.length_scale) if bodies else drawn.length_scale,
                lever_scale=next_standard_scale(drawn.lever_drawn_scale) if lever else drawn.lever_scale)
        else:
            break
    if headless is not None:
        drawn, one, cuts, rows = cut(*headless)
    apart = _rows_apart(cuts, laid(rows), one, fits)
    whole, ways = _finished(analysis, drawn, one, [*cuts, apart] if apart else cuts, rows.heading)
    ways, apart = (ways[:-1], ways[-1]) if apart else (ways, [])
    # Only a sheet an empty sheet held whole as first drawn, at its lettering and scales, has room to spare.
    roomy = drawn == first and not parted and len(ways) == 1 and len(ways[0]) == 1

    fixed_polygons = analysis.scene.drawing.force_scale is not None

    @functools.cache
    def larger(steps: tuple[int, int]) -> Panel | None:
        bodies, polygons = steps
        # The polygons at the μF the scene sets are left at it, as the drawing a hand fixed.
        bigger = _larger_force_sheet(drawn, bodies, 0 if fixed_polygons else polygons) if roomy else None
        if bigger is None:
            return None
        rows = force_layout.rows(bigger, groups_cut_free)
        arranged = [rows.arranged(rows.in_columns(count)) for count in (1, 2)]
        # Measured as a panel of its layers would be, before it is cut into its parts: most ways tried stand on no
        # empty sheet, in one column or in two, and are thrown away.
        if not any(fits(x1 - x0, y1 - y0) for x0, y0, x1, y1 in
                   (tuple(float(value) for value in bounds(arrangement.layers)) for arrangement in arranged)):
            return None
        way, other = (split(arrangement, one.name, one.label, _group_of_field) for arrangement in arranged)
        panel = replace(way, alternatives=(other,) if other.extent != way.extent else ())
        record = drawn.forces.group_scales
        return replace(_finished(analysis, bigger, panel, [[panel]], rows.heading)[1][0][0],
                       polygon_scales=tuple((label, scale) for label, scale in bigger.forces.group_scales.items()
                                            if scale != record.get(label)),
                       body_arrows=tuple((label, scale, whole) for label, (scale, whole)
                                         in force_bodies.free_body_arrows(bigger).items() if whole))

    # The whole as the run writes it on its own only where nothing was changed to fit the sheet: its parts stand as
    # cut, but a lever stepped back, smaller lettering or a group at a larger μl would change the file with the format.
    return replace(whole, drawn_alone=drawn == first), ways, apart, larger


def _rows_apart(cuts: list[list[Panel]], rows: force_rows.Rows, whole: Panel,
                fits: Callable[[float, float], bool]) -> list[Panel]:
    """The force sheet ``whole``'s ``rows`` apart (:meth:`force_rows.Rows.rows_apart`) as panels, where that is
    another way than its ``cuts``, in more parts than its first: a cut the sheets take only where it saves one
    (:func:`fewest_sheets_cuts`), so that a sheet that stands whole may still give the room in its block to the
    drawings after it, and one in parts keeps each group beside its polygon where its drawings apart would not."""
    apart = rows.rows_apart(fits)
    # A cut of as many parts is the rows apart already: every drawing apart, each row one drawing.
    if len(apart) <= len(cuts[0]) or any(len(cut) == len(apart) for cut in cuts):
        return []
    return _part_panels(apart, whole, rows.heading)


def _part_panels(parts: Sequence[force_rows.Part], whole: Panel, heading: force_rows.Heading) -> list[Panel]:
    """The parts of one cut of the force sheet ``whole`` as panels, each going on from the one before, their
    headings to name the scales of the drawings the packing puts under them (``heading``'s), each with its long
    captions beside its drawings as its other way (:class:`force_rows.Part`)."""
    names = [whole.name, *(f"{whole.name}-{k + 1}" for k in range(1, len(parts)))]

    def panel(k: int, part: force_rows.Part) -> Panel:
        ways = [replace(split(way, names[k], whole.label, _group_of_field), continues=names[k - 1] if k else "",
                        heading_scales=heading.scales, heading_comma=heading.comma)
                for way in (part, part.aside) if way is not None]
        return replace(ways[0], alternatives=tuple(ways[1:]))

    return [panel(k, part) for k, part in enumerate(parts)]


def _finished(analysis: Analysis, drawn: force_layout.ForceSheet, one: Panel, cuts: list[list[Panel]],
              heading: force_rows.Heading) -> tuple[Panel, list[list[Panel]]]:
    """The force sheet ``one`` whole and its ways ``cuts`` as drawn by ``drawn``: the lever's μV and the groups' μl
    they stand at, the polygons and the lever to no length scale, the heading's scales named."""
    lever = drawn.lever_drawn_scale if drawn.lever is not None else None
    # The whole names its heading's scales for the note, which shows it in parts (:func:`note_parts.note_parts`).
    one, cuts = (replace(_at_no_length_scale(one), lever_scale=lever, heading_scales=heading.scales,
                         heading_comma=heading.comma),
                 [[replace(_at_no_length_scale(part), lever_scale=lever) for part in panels] for panels in cuts])
    if drawn.length_scale == length_scale(analysis):
        return one, cuts
    return _drawn_at(one, drawn.length_scale), [[_drawn_at(part, drawn.length_scale) for part in panels]
                                                for panels in cuts]


def _larger_force_sheet(drawn: force_layout.ForceSheet, bodies: int,
                        polygons: int) -> force_layout.ForceSheet | None:
    """``drawn`` with its groups cut free ``bodies`` standard steps larger (finer μl) and its polygons ``polygons``
    steps larger (finer μF); None for no step at all."""
    if not bodies and not polygons:
        return None
    return replace(drawn, length_scale=finer_standard_scale(drawn.length_scale, bodies),
                   forces=force_polygons.with_finer_polygons(drawn.forces, polygons))


def _parted_for_legibility(rows: force_rows.Rows, drawn: force_layout.ForceSheet,
                           groups_cut_free: dict[tuple[int, float], force_layout.Drawing],
                           unheld: Collection[str], fits: Callable[[float, float], bool]) -> set[str]:
    """The groups cut free among ``unheld`` to stand on a part of their own, their equations going on after
    them, rather than be drawn at the next larger μl: those that a sheet holds so and whose labels would cover
    one another drawn smaller, as a draughtsman goes on to the next sheet before letters run together."""
    bodies = [drawing for row in rows.drawings for drawing in row
              if drawing.name in unheld and drawing.name.startswith("body-") and drawing.parted is not None]
    if not bodies:
        return set()
    # Both the group and its equations on a sheet of their own: equations longer than a sheet stay under it.
    still_unheld = rows.parted([body.name for body in bodies]).unheld(fits)
    held = {body.name for body in bodies if not any(piece.name in still_unheld for piece in body.parted or ())}
    smaller = force_layout.rows(replace(drawn, length_scale=next_standard_scale(drawn.length_scale)), groups_cut_free)
    return {drawing.name for row in smaller.drawings for drawing in row
            if drawing.name in held and force_bodies.labels_cover_one_another(drawing)}


def _at_no_length_scale(panel: Panel) -> Panel:
    """A force sheet, or a part of one, whose lever (the velocity plan turned, at μV) and force polygons (at μF)
    are drawn to no length scale: a sheet of them alone leaves its title block's scale box empty, as one of plans
    alone; only a group cut free is drawn at μl."""
    parts = tuple(_to_no_length_scale(part) if _drawn_to_no_length_scale(part.name)
                  else _at_no_length_scale(part) for part in panel.parts)
    return replace(panel, parts=parts, to_scale=any(part.to_scale for part in parts) if parts else panel.to_scale,
                   alternatives=tuple(_at_no_length_scale(way) for way in panel.alternatives))


def _drawn_to_no_length_scale(name: str) -> bool:
    """Whether the part ``name`` of a force sheet is its lever or a force polygon (``forces-5-polygon-II-3-4``),
    or a group's equations set apart from it, which draw nothing."""
    return name.endswith("-lever") or "-polygon-" in name or "-equations-" in name


def _smaller_lever(drawn: force_layout.ForceSheet) -> float | None:
    """The lever's μV a standard step smaller than ``drawn``'s enlarged one; None back at the plan's own."""
    smaller = next_standard_scale(drawn.lever_drawn_scale)
    return smaller if force_marks.draws_larger(smaller, drawn.velocity.scale) else None


def _larger_levers(enlarged: force_layout.ForceSheet, drawn: force_layout.ForceSheet) -> Iterator[force_layout.ForceSheet]:
    """``drawn`` with its lever at ``enlarged``'s μV, then at each standard step down to just above the plan's."""
    candidate = replace(drawn, lever_scale=enlarged.lever_scale)
    while candidate.lever_scale is not None:
        yield candidate
        candidate = replace(candidate, lever_scale=_smaller_lever(candidate))


def _steps_to_plan_size(drawn: force_layout.ForceSheet) -> int:
    """How many standard steps ``drawn``'s lever is drawn larger than its velocity plan."""
    steps = 0
    while drawn.lever_enlarged:
        drawn, steps = replace(drawn, lever_scale=_smaller_lever(drawn)), steps + 1
    return steps


def _drawn_at(panel: Panel, scale: float) -> Panel:
    """``panel``, its parts and its other arrangements marked as drawn at μl = ``scale``."""
    return replace(panel, parts=tuple(_drawn_at(part, scale) for part in panel.parts), length_scale=scale,
                   alternatives=tuple(_drawn_at(way, scale) for way in panel.alternatives))


def fewest_sheets_length_scale(analysis: Analysis, sheet: str, largest: float) -> float:
    """The standard μl, from ``largest`` (the largest drawing that fits) to a plan of positions
    :data:`LEAST_POSITIONS_MM` across, that lays the kinematics and the force sheets on the fewest ``sheet`` s;
    of those, the largest drawing.

    A course project has its kinematics on one sheet and its force analysis
    on the next where they fit: a drawing a step smaller is worth a sheet.
    """
    from ..kinematic_diagrams import unavailable

    # The paths of the points, its linework, at least so far across: measured with its words, which do not shrink
    # with μl, the plan of positions came out 124 mm across on A2.
    extent = paths_extent(analysis)
    candidates = [largest]
    while extent / next_standard_scale(candidates[-1]) >= LEAST_POSITIONS_MM:
        candidates.append(next_standard_scale(candidates[-1]))
    if len(candidates) == 1:
        return largest
    form = form_of(analysis.scene.locale)
    diagrams: tuple[Panel, ...] = ()
    if unavailable(analysis.scene, analysis) is None:
        with contextlib.suppress(SceneError):  # the run that draws them says why they fit no sheet
            diagrams = (diagrams_panel(analysis, sheet),)
    fewest: tuple[int, float] | None = None
    for scale in candidates:
        try:
            panels = course_panels(at_length_scale(analysis, scale), diagrams, sheet, larger=False)
            count = sum(len(pack(drawings, sheet, form)) for drawings in (panels.kinematics, panels.forces)
                        if drawings)
        except SceneError:  # at this μl; the run at the μl chosen says why where none will do
            continue
        if fewest is None or count < fewest[0]:
            fewest = (count, scale)
        if fewest[0] == 1 + bool(panels.forces):
            break  # no μl does better than one sheet of each kind
    return largest if fewest is None else fewest[1]


# The kinematic diagrams' panels, by what they depend on: they stand to no length scale, so the μl choice and the
# run at the μl chosen share one (its layout, with the larger ways tried, took a tenth of a shaper's run each time).
_diagrams_panels: OwnedMemo[Panel] = OwnedMemo()


def diagrams_panel(analysis: Analysis, sheet: str) -> Panel:
    """The kinematic diagrams of the output link as a panel whose three diagrams may stand apart
    (:func:`_diagrams_panel`), laid out once for the analysis at any μl."""
    scene = analysis.scene
    unscaled = (replace(scene.drawing, length_scale=None), scene.locale, sheet)
    return _diagrams_panels.get(analysis.motion, unscaled, lambda: _diagrams_panel(analysis, sheet))


def _diagrams_panel(analysis: Analysis, sheet: str) -> Panel:
    """The kinematic diagrams of the output link as a panel whose three diagrams may stand apart.

    On a sheet too small for the usual φ axis and fields, both are
    shortened until each diagram fits beside or above the title block:
    the φ axis by whole intervals, so that the positions stay at whole
    millimetres, the fields by whole millimetres; the scales follow
    from them as they always do.  On a sheet that holds them whole with
    room to spare they are drawn larger as well (:func:`_larger_diagram_sizes`):
    the panel's ways, largest first and the usual last, of which the
    packing takes the largest that the room left on a sheet holds.
    """
    from ..kinematic_diagrams import AXIS_MM, FIELD_MM, interval_count
    from . import diagrams as diagrams_layout

    def drawn_at(axis: float, field: float) -> tuple[str, list[list[Layer]]]:
        # Measured unlettered: the numbers' rows and H's spots lie within what is drawn, so the extent is the same;
        # but the usual size, which diagrams.svg draws lettered anyway.
        return diagram_parts(analysis, axis, field, lettered=(axis, field) == (AXIS_MM, FIELD_MM))

    form = form_of(analysis.scene.locale)
    continued = strings(analysis.scene.locale)["force_sheet_continued"]
    intervals = interval_count(analysis.mechanism.driver.cyclic, analysis.scene.positions.count)
    axis, field = AXIS_MM, FIELD_MM
    title, drawn = drawn_at(axis, field)
    # The pole distances, and with them the room left of each axis, change with the field: a few rounds.
    for _ in range(_SHORTENING_ROUNDS):
        if sheet == "none" or all(holds(sheet, form, *_size(part)) for part in drawn):
            break
        axis, field = _shortened(drawn, sheet, form, intervals, (axis, field))
        title, drawn = drawn_at(axis, field)
    else:
        raise SceneError("drawing.sheet", _no_sheet_holds(sheet), sheet)
    # The shortening is cautious where the words break narrower as the axis shortens: lengthen back while
    # the diagrams still fit.
    for grown in ((intervals, 0.0), (0.0, 1.0)):
        while sheet != "none" and axis + grown[0] <= AXIS_MM and field + grown[1] <= FIELD_MM:
            longer = drawn_at(axis + grown[0], field + grown[1])
            if not all(holds(sheet, form, *_size(part)) for part in longer[1]):
                break
            axis, field = axis + grown[0], field + grown[1]
            title, drawn = longer
    # The size chosen lettered: its parts stand apart where no sheet holds a larger way.
    title, drawn = diagram_parts(analysis, axis, field)
    usual = _apart("diagrams", title, drawn, continued)
    if sheet != "none" and not holds(sheet, form, *_size(usual.layers)):
        lower = _field_saving_a_sheet(drawn_at, sheet, form, axis, field, continued)
        if lower != field:
            field = lower
            usual = _apart("diagrams", *diagram_parts(analysis, axis, field), continued)
    if sheet == "none" or (axis, field) != (AXIS_MM, FIELD_MM) or not holds(sheet, form, *_size(usual.layers)):
        return usual
    # A sheet that holds them with room to spare has them drawn larger, as a course project fills its sheet: each
    # larger way that an empty sheet holds, largest first, for the packing to take the largest the room left holds.
    # Each is measured unlettered and lettered only where the packing takes it (:attr:`Panel.lettered`).
    def way_at(axis: float, field: float, pole: float | None = None) -> Panel:
        title, drawn = diagram_parts(analysis, axis, field, lettered=False, greatest_pole=pole)
        return Panel("diagrams", tuple(diagrams_layout.stacked(drawn)), usual.parts, title, to_scale=False,
                     lettered=_lettered_diagrams(analysis, axis, field, pole))

    sizes = _larger_diagram_sizes(intervals)
    larger = [way for way in (way_at(axis, field) for axis, field in sizes) if holds(sheet, form, width(way), height(way))]
    if _poles_held(analysis):
        # The diagrams with longer poles as one way more, the largest an empty sheet holds: a way more of every size
        # took the slider-driven lever's diagrams off the sheet of its plans, a page's rearranging trying only so
        # many of its drawings' ways (packing._MOST_REARRANGEMENTS) and no longer reaching the one that fitted.
        longer = (way_at(axis, field, pole) for axis, field in sizes for pole in _longer_poles(axis))
        largest = max((way for way in longer if holds(sheet, form, width(way), height(way))),
                      key=lambda way: width(way) * height(way), default=None)
        larger += [largest] if largest is not None else []
    if not larger:
        return usual
    # The parts are the usual diagrams': where no sheet holds a way whole, they stand apart at the usual size.
    first, *others = sorted(larger, key=lambda way: -width(way) * height(way))
    return replace(first, alternatives=(*others, usual))


def _field_saving_a_sheet(drawn_at: Callable[[float, float], tuple[str, list[list[Layer]]]], sheet: str, form: str,
                         axis: float, field: float, continued: str) -> float:
    """``field`` (mm), or the largest field down to :data:`_FIELD_GIVEN_FOR_A_SHEET` of it at which the kinematic
    diagrams stand on fewer sheets of their own: on A3 the Russian crank-rocker's three stood one to a sheet, each a
    third full, where fields 3 mm lower put two on one sheet.  ``drawn_at(axis, field)`` draws them unlettered,
    ``continued`` is the title "continued" over a diagram that stands apart (:func:`_apart`)."""
    def sheets_taken(at: float) -> float:
        title, drawn = drawn_at(axis, at)
        # A lower field draws the chords' pole farther left (the pole distance follows the field): a part may
        # come out wider than the sheet.
        if not all(holds(sheet, form, *_size(part)) for part in drawn):
            return math.inf
        return len(pack([_apart("diagrams", title, drawn, continued)], sheet, form))

    taken = sheets_taken(field)
    if taken == 1:
        return field
    lowest = max(_LEAST_FIELD_MM, math.ceil(_FIELD_GIVEN_FOR_A_SHEET * field))
    return next((float(lower) for lower in range(math.ceil(field) - 1, lowest - 1, -1) if sheets_taken(lower) < taken),
                field)


def _apart(name: str, label: str, drawn: Sequence[Sequence[Layer]], continued: str,
           drawn_alone: bool = False) -> Panel:
    """Diagrams ``drawn`` one under another as the panel ``name`` (``label``, their title, says what it is), each
    a part that may stand apart where there are several: the kinematic diagrams, the load diagrams.

    The title stands over the first only.  Each part after it goes on from
    the one before (:attr:`Panel.continues`) under the title "continued"
    (``continued``, a format of ``{title}``), which it loses on the sheet of
    that one: on an A3 the shaper's acceleration diagram stood on a sheet of
    its own under its caption alone, and read as a drawing of its own.  The
    title is on one line where the sheet has the room, else broken to the
    part's width; last of its ways the part stands bare, which a sheet holds
    alone.
    """
    from .diagrams import stacked

    parts: list[Panel] = []
    for k, part in enumerate(drawn if len(drawn) > 1 else ()):
        bare = Panel(f"{name}-{k + 1}", tuple(part), to_scale=False)
        parts.append(_headed_part(bare, continued.format(title=label), parts[-1].name) if k else bare)
    return Panel(name, tuple(stacked(drawn)), tuple(parts), label, to_scale=False, drawn_alone=drawn_alone)


def _headed_part(bare: Panel, title: str, continues: str = "") -> Panel:
    """The part ``bare`` under ``title``, going on from the part ``continues`` (none for a first part): the title on
    one line where the sheet has the room, else broken to the part's width; last of its ways the part bare, which a
    sheet holds alone."""
    from .diagrams import title_texts

    x0, _, x1, top = bare.extent
    headings = dict.fromkeys(title_texts(title, (x0, top), room) for room in (math.inf, x1 - x0))
    first, *others = (replace(bare, layers=(*bare.layers, Layer(force_rows.HEADING_LAYER, heading)))
                      for heading in headings)
    return replace(first, alternatives=(*others, bare), continues=continues)


def _lettered_diagrams(analysis: Analysis, axis: float, field: float,
                       pole: float | None = None) -> Callable[[], tuple[Layer, ...]]:
    """The kinematic diagrams drawn at ``axis`` and ``field`` (their pole distances up to ``pole``, when given)
    stacked with their labels, laid out when asked."""
    from . import diagrams as diagrams_layout

    return lambda: tuple(diagrams_layout.stacked(diagram_parts(analysis, axis, field, greatest_pole=pole)[1]))


# The kinematic diagrams' parts by the φ axis and field they are drawn at, lettered or not, for an analysis: the
# run's own drawing (diagrams.svg) is the sheet's usual way, which the sheet laid out already.
_diagram_parts: OwnedMemo[tuple[str, list[list[Layer]]]] = OwnedMemo()


def diagram_parts(analysis: Analysis, axis: float, field: float, lettered: bool = True,
                  greatest_pole: float | None = None) -> tuple[str, list[list[Layer]]]:
    """The title and the parts (:func:`graphplan.render.diagrams.parts`) of the kinematic diagrams of ``analysis``
    drawn on a φ axis of ``axis`` mm and fields ``field`` mm tall, laid out once; not ``lettered``, without the
    labels whose room alone is kept (the extent is the same); their pole distances up to ``greatest_pole`` mm
    where it is given (:func:`_longer_poles`), else up to the axis's usual greatest."""
    from ..kinematic_diagrams import of_analysis
    from . import diagrams as diagrams_layout

    def drawn() -> tuple[str, list[list[Layer]]]:
        text = strings(analysis.scene.locale)
        record = of_analysis(analysis, axis_mm=axis, field_mm=field, greatest_pole_mm=greatest_pole)
        return (text["kd_title"].format(link=record.link, point=record.point or ""),
                diagrams_layout.parts(record, text, lettered))

    return _diagram_parts.get(analysis, (axis, field, lettered, greatest_pole), drawn)


# A derivative whose pole distance stops at its greatest stands lower than its field: the more so the more nearly
# uniform the motion (the slider-driven lever's ε4 stood 12 mm tall in a field of 96, its ψ4 nearly a straight
# line over the rod's steady travel).  A sheet with the room beside them has them drawn with poles longer by these
# multiples of the greatest, up to as long as the φ axis (:func:`_diagrams_panel`).
_POLE_GROWTHS = (3.0, 2.0)


def _poles_held(analysis: Analysis) -> bool:
    """Whether a pole distance of the usual diagrams of ``analysis`` stopped at its greatest."""
    from ..kinematic_diagrams import AXIS_MM, FIELD_MM, greatest_pole, of_analysis

    scales = of_analysis(analysis, axis_mm=AXIS_MM, field_mm=FIELD_MM).scales
    return max(scales.velocity_pole, scales.acceleration_pole) >= greatest_pole(AXIS_MM)


def _longer_poles(axis: float) -> tuple[float, ...]:
    """The greatest pole distances (mm), longer than the usual greatest, that the larger ways of diagrams on a φ
    axis ``axis`` mm long are tried with where the usual's stopped there (:data:`_POLE_GROWTHS`)."""
    from ..kinematic_diagrams import greatest_pole

    return tuple(float(math.floor(min(greatest_pole(axis) * growth, axis))) for growth in _POLE_GROWTHS)


# Diagrams drawn larger on a sheet with room are tried at these multiples of the usual φ axis and of the usual
# field, each kept within GREATEST_AXIS_MM and GREATEST_FIELD_MM: longer and taller, or only taller (as long as
# the usual, they fit the room beside a plan sheet), for the packing to take the largest the room left holds.
_AXIS_GROWTHS = (1.5, 1.25, 1.0)
_FIELD_GROWTHS = (2.4, 2.0, 1.6, 1.3, 1.0)


def _larger_diagram_sizes(intervals: int) -> list[tuple[float, float]]:
    """The (φ axis, field) mm of diagrams drawn larger than the usual: the axis a whole number of millimetres
    per interval, up to :data:`~graphplan.kinematic_diagrams.GREATEST_AXIS_MM`, the field whole millimetres up
    to :data:`~graphplan.kinematic_diagrams.GREATEST_FIELD_MM`."""
    from ..kinematic_diagrams import AXIS_MM, FIELD_MM, GREATEST_AXIS_MM, GREATEST_FIELD_MM

    sizes: list[tuple[float, float]] = []
    for along in _AXIS_GROWTHS:
        # The usual axis as it is (240 mm, however many intervals), a longer one by whole millimetres per interval.
        axis = AXIS_MM if along == 1.0 else \
            float(intervals * math.floor(min(AXIS_MM * along, GREATEST_AXIS_MM) / intervals))
        for up in _FIELD_GROWTHS:
            field = float(math.floor(min(FIELD_MM * up, GREATEST_FIELD_MM)))
            if axis >= AXIS_MM and (axis, field) not in sizes and (axis, field) != (AXIS_MM, FIELD_MM):
                sizes.append((axis, field))
    return sizes


def _size(layers: Sequence[Layer]) -> tuple[float, float]:
    x0, y0, x1, y1 = bounds(layers)
    return float(x1 - x0), float(y1 - y0)


def _shortened(drawn: Sequence[Sequence[Layer]], sheet: str, form: str, intervals: int,
               now: tuple[float, float]) -> tuple[float, float]:
    """A shorter φ axis and field (mm) than ``now``, at which the diagrams ``drawn`` at ``now`` would fit the
    room of a ``sheet`` that leaves them largest; the words and arrows round them keep their size."""
    axis, field = now
    sizes = [_size(part) for part in drawn]
    around_width = max(width for width, _ in sizes) - axis
    around_height = max(height for _, height in sizes) - field
    rooms = [room for portrait in usual_orientations(sheet) for room in page_geometry(sheet, form, portrait).rooms()]
    room = max(rooms, key=lambda r: min((r[0] - around_width) / axis, (r[1] - around_height) / field))
    fitting_axis = min(axis, math.floor((room[0] - around_width) / intervals) * intervals)
    fitting_field = min(field, math.floor(room[1] - around_height))
    if (fitting_axis, fitting_field) == (axis, field):
        # Fits by the estimate, not in fact: the wider side gives way by one step.
        if around_width + axis > room[0]:
            fitting_axis -= intervals
        else:
            fitting_field -= 1
    if fitting_axis < intervals or fitting_field < _LEAST_FIELD_MM:
        raise SceneError("drawing.sheet", _no_sheet_holds(sheet), sheet)
    return float(fitting_axis), float(fitting_field)


def _no_sheet_holds(sheet: str) -> str:
    bigger = f'choose a bigger one ({BIGGER[sheet]}) or sheet = "none"' if sheet in BIGGER else 'use sheet = "none"'
    return f"the kinematic diagrams fit on no {sheet} sheet; {bigger}"


# Sheets.

def kinematics_sheet(panels: Sequence[Panel | Sequence[Layer]], sheet: str = "A1", locale: str = "en",
                     title: str = "", scale: float | None = None, details: Details | None = None,
                     first: int = 1, count: int | None = None) -> list[Sheet]:
    """The kinematics sheets: the plan of positions, the plans of each position, any further panels (diagrams).

    ``scale`` is μl (m/mm) for the title block's scale box; ``first`` the
    number of the first sheet and ``count`` how many sheets the set has
    (these sheets only, when not given).  Returns one :class:`Sheet` per
    sheet needed: several when the panels do not fit on one.
    """
    return _sheets(panels, sheet, locale, "sheet_kinematics", title, scale, details, first, count)


def forces_sheet(panels: Sequence[Panel | Sequence[Layer]], sheet: str = "A1", locale: str = "en",
                 title: str = "", scale: float | None = None, details: Details | None = None,
                 first: int = 1, count: int | None = None) -> list[Sheet]:
    """The force sheets: each position's groups cut free, force polygons and lever (:func:`kinematics_sheet`)."""
    return _sheets(panels, sheet, locale, "sheet_forces", title, scale, details, first, count)


def dynamics_sheet(panels: Sequence[Panel | Sequence[Layer]], sheet: str = "A1", locale: str = "en",
                   title: str = "", details: Details | None = None, first: int = 1,
                   count: int | None = None) -> list[Sheet]:
    """The sheets of the machine's dynamics (:func:`dynamics_panel`; :func:`kinematics_sheet`), with no μl."""
    return _sheets(panels, sheet, locale, "sheet_dynamics", title, None, details, first, count)


def balancing_panel(layers: Sequence[Layer], locale: str, sheet: str | None = None,
                    larger: Callable[[], Sequence[Sequence[Layer]]] | None = None) -> Panel:
    """The balancing drawing (:func:`graphplan.render.balancing.layout`) as a panel to no length scale.

    Where no sheet holds it whole (two planes side by side on an A4), each plane's polygon with its caption
    stands apart, the title block naming what they are; a part no sheet holds is named by its plane, as its caption
    names it ("Balancing of the rotor: Correction plane II"), not by its panel's id.  ``larger()`` lays out the
    same drawing with its polygons drawn larger (:func:`graphplan.render.balancing.larger_layouts`): those an empty
    ``sheet`` holds are the panel's ways, largest first, as the dynamics' are (:func:`dynamics_panel`), their parts
    the usual drawing's."""
    usual = _balancing_drawn(layers, locale, sheet)
    form = form_of(locale)
    if larger is None or sheet is None or sheet == "none" or not holds(sheet, form, width(usual), height(usual)):
        return usual
    # Fields a step of the standard scales apart draw a polygon at one scale: each drawing once.
    ways = {(round(width(usual), 3), round(height(usual), 3)): usual}
    for drawn in larger():
        way = replace(usual, layers=_title_as_heading(drawn))
        ways.setdefault((round(width(way), 3), round(height(way), 3)), way)
    return _larger_first(usual, [way for way in ways.values() if way is not usual], sheet, form)


def _balancing_drawn(layers: Sequence[Layer], locale: str, sheet: str | None = None) -> Panel:
    """The balancing drawing ``layers`` as a panel whose parts are its planes' polygons, where it has two.

    Each plane that stands apart does so under the drawing's title, the
    second "continued", as the diagrams' parts do: on an upright A4 the two
    polygons stood with their captions alone, the title block all that said
    what they were.  Where the first plane's title alone keeps the second
    off its ``sheet`` (the English rotor starter's two planes, one under the
    other on an upright A4), the first stands bare: a sheet more for a
    heading is no saving.
    """
    planes: dict[str, list[Layer]] = {}
    for layer in layers:
        stem, _, part = layer.name.rpartition("-")
        if layer.name.startswith("plane-") and part in ("reference", "vectors", "leaders", "labels", "caption"):
            planes.setdefault(stem, []).append(layer)
    label = labels(locale)["sheet_balancing"]
    text = strings(locale)
    title = text["bal_title"].format(count=Count(len(planes)))
    parts: list[Panel] = []
    for k, (stem, own) in enumerate(planes.items() if len(planes) > 1 else ()):
        bare = Panel(f"balancing-{k + 1}", tuple(own),
                     label=f"{label}: {text['bal_disc'].format(name=stem.removeprefix('plane-'))}", to_scale=False)
        heading = text["force_sheet_continued"].format(title=title) if k else title
        parts.append(_headed_part(bare, heading, parts[-1].name if k else ""))
    panel = Panel("balancing", _title_as_heading(layers), tuple(parts), label=label, to_scale=False)
    if not parts or sheet is None or sheet == "none":
        return panel
    first_bare = replace(panel, parts=(parts[0].ways[-1], *parts[1:]))
    form = form_of(locale)
    with contextlib.suppress(SceneError):
        if len(pack([first_bare], sheet, form)) < len(pack([panel], sheet, form)):
            return first_bare
    return panel


def _title_as_heading(layers: Sequence[Layer]) -> tuple[Layer, ...]:
    """The balancing drawing's ``layers`` with its title as the heading of a drawing on a sheet, by which the packing
    tells a page of its parts that stands without one (:attr:`~graphplan.render.packing.Page.bare`)."""
    from .balancing import TITLE_LAYER as BALANCING_TITLE

    return tuple(Layer(force_rows.HEADING_LAYER, layer.items) if layer.name == BALANCING_TITLE else layer
                 for layer in layers)


@dataclass(frozen=True)
class CoursePanels:
    """The drawings of a course project's sheets, laid out once: the plan of positions first among the
    kinematics panels (then the plan sheets, the diagrams), a force sheet per position among the forces."""

    kinematics: tuple[Panel, ...]
    forces: tuple[Panel, ...]
    # The force sheets whole, laid out for the sheets as those that stand whole among ``forces`` are.
    whole_forces: tuple[Panel, ...] = ()
    # The dynamics of the machine (:func:`dynamics_panel`), where the run has them.
    dynamics: tuple[Panel, ...] = ()
    # The rotor's balancing polygons (:func:`balancing_panel`), where the scene has a [balancing] table.
    balancing: tuple[Panel, ...] = ()

    def named(self, name: str) -> Panel | None:
        """The drawing ``name`` whole (a force sheet that stands in parts on the sheets too)."""
        return next((panel for panel in (*self.kinematics, *self.whole_forces, *self.forces) if panel.name == name),
                    None)


def course_panels(analysis: Analysis, diagrams: Sequence[Panel | Sequence[Layer]] = (),
                  sheet: str | None = None, dynamics: Sequence[Panel] = (),
                  balancing: Sequence[Panel] = (), loads: Sequence[Panel] = (),
                  smaller_loads: Callable[[], Iterator[Sequence[Panel]]] | None = None,
                  larger: bool = True) -> CoursePanels:
    """The panels of :func:`course_sheets`, for a caller that also writes the drawings on their own; ``loads``, the
    load diagrams (:func:`load_diagrams_panel`), stand among the force sheets, whose values they give;
    ``smaller_loads`` the same drawn smaller, largest first, the first of which that saves a sheet is taken;
    ``larger`` draws a force sheet larger where the sheets have the room (:func:`larger_where_room`): the choice
    of μl, which counts sheets alone, leaves it out."""
    chosen = analysis.scene.drawing.sheet if sheet is None else sheet
    linkage, forces = _laid_out(analysis, chosen)
    kinematics = [*linkage, *(panel_of(d, f"diagram-{k + 1}") for k, d in enumerate(diagrams))]
    # Placed after the force sheets, the load diagrams take the first room left beside one (the first sheet of
    # forces that has it); placed first, one took an A1 alone where the force sheet after it needed a whole sheet.
    form = form_of(analysis.scene.locale)
    cuts = [cuts for _, cuts, _, _ in forces]
    if loads and smaller_loads is not None and chosen != "none":
        # Drawn smaller where at their size they would take a sheet of their own beside the force sheets as cut, as
        # they were before any force sheet's rows stood apart: a knee press's load diagram stands beside a whole
        # force sheet at 120 by 45 mm, not at its usual size beside its rows apart.  Only the count is asked: the
        # cuts that save sheets, none chosen again for the order.
        without_apart = CutChoice(cuts, loads, chosen, form)
        parts = without_apart.parts_of(without_apart.fewest())
        if parts:
            loads = loads_saving_a_sheet(parts, loads, smaller_loads, chosen, form)
    choice = CutChoice(cuts, loads, chosen, form, [apart for _, _, apart, _ in forces])
    picked = choice.fewest(combined=True)
    parts = choice.parts_of(picked)
    if larger and chosen != "none":
        parts, pages = larger_where_room(parts, loads, larger_ways(forces, parts), chosen, form,
                                          packed=choice.pages(picked))
        if pages is not None and not reads_in_order(pages):
            parts = read_after_forces(choice, picked, parts, len(pages), forces, length_scale(analysis))
    return CoursePanels(tuple(kinematics), (*parts, *loads), tuple(whole for whole, _, _, _ in forces), tuple(dynamics),
                        tuple(balancing))


def load_diagrams_panel(diagrams: Sequence[LoadDiagram], locale: str, sheet: str | None = None,
                        field: tuple[float, float] | None = None) -> Panel:
    """The load diagrams (:func:`graphplan.render.load_diagrams.parts`) as a panel to no length scale, each
    diagram a part of its own where no sheet holds them together; on a ``sheet`` too small for a diagram at the
    usual fields, at the first of the smaller ones that it holds (the scales stated follow); at ``field`` where
    that is given."""
    from . import load_diagrams as load_layout

    text = strings(locale)
    form = form_of(locale)
    usual = field is None
    if field is not None:
        drawn = load_layout.parts(diagrams, text, field)
    else:
        drawn = load_layout.parts(diagrams, text)
        for smaller in load_layout.SMALLER_FIELDS:
            if sheet is None or sheet == "none" or all(holds(sheet, form, *_size(part)) for part in drawn):
                break
            drawn, usual = load_layout.parts(diagrams, text, smaller), False
    # At the usual fields, the drawing load_diagrams.svg is (:func:`graphplan.render.load_diagrams.layout`).  Read
    # after the force sheets, whose values they give, where that costs no sheet.
    return replace(_apart("load-diagrams", text["ld_title"], drawn, text["force_sheet_continued"], drawn_alone=usual),
                   reads_after="forces")


# The linkage's panels laid out for an analysis, by all they depend on: a μl choice lays out the sheets at a
# few μl (:func:`fewest_sheets_length_scale`) and the run lays out those of the μl chosen once more.  An
# analysis fixed at a μl (:func:`~graphplan.render.drawings.at_length_scale`) shares its motion with the
# analysis it is made from: the panels are kept by that motion while it lives.
# The kinematics panels are kept apart from the force sheets: the refusal of drawings no sheet holds reads them
# alone, before any force sheet is laid out, and the sheets then take them as laid out for it.
_LaidOut = tuple[list[Panel], list[tuple[Panel, list[list[Panel]]]]]
_laid_out_panels: OwnedMemo[_LaidOut] = OwnedMemo()
_laid_out_kinematics: OwnedMemo[list[Panel]] = OwnedMemo()


def _laid_out(analysis: Analysis, sheet: str) -> _LaidOut:
    """:func:`kinematics_panels` and :func:`_force_sheets` of ``analysis`` on ``sheet``, each laid out once."""
    return _laid_out_panels.get(analysis.motion, (analysis.scene.drawing, analysis.scene.locale, sheet),
                                lambda: (_kinematics_laid_out(analysis), _force_sheets(analysis, sheet)))


def _kinematics_laid_out(analysis: Analysis) -> list[Panel]:
    """:func:`kinematics_panels` of ``analysis``, laid out once."""
    return _laid_out_kinematics.get(analysis.motion, (analysis.scene.drawing, analysis.scene.locale),
                                    lambda: kinematics_panels(analysis))


def dynamics_panel(layers: Sequence[Layer], locale: str, redrawn: Redrawings | None = None,
                   sheet: str | None = None, filled: bool = True) -> Panel:
    """The dynamics drawing (:func:`graphplan.render.dynamics.layout`) as a panel.

    Where no sheet holds it whole, its diagrams stand apart: the energy–mass
    diagram with Je(φ) under it while a sheet holds the two together, for
    they share the axis of Je.  ``redrawn`` lays out the same drawing at
    other scales.  Where an empty ``sheet`` holds the usual one whole, those
    drawn larger that it holds too are the panel's ways, largest first, so
    that the drawing fills the sheet as a course project's does; their parts
    stay the usual drawing's.  Where it holds the usual one not even diagram
    by diagram, the panel is the largest drawn smaller that it holds so, its
    scales the program's to choose as the usual ones are.  Not ``filled``,
    the larger ones are not laid out: `check` asks only whether a sheet
    holds the drawing.
    """
    form = form_of(locale)
    usual = _dynamics_drawn(layers, locale, sheet, form)
    if sheet is None or sheet == "none" or redrawn is None:
        return usual
    if not holds(sheet, form, width(usual), height(usual)):
        if _held_by_parts(usual, sheet, form):
            return usual
        smaller = (_dynamics_drawn(drawn, locale, sheet, form) for drawn in redrawn.smaller())
        held = [way for way in smaller if _held_by_parts(way, sheet, form)]
        # Where none is held, the usual one is refused as it stands, in the words `check` uses.
        return max(held, key=lambda way: width(way) * height(way)) if held else usual
    if not filled:
        return usual
    return _larger_first(usual, [replace(usual, layers=tuple(drawn)) for drawn in redrawn.larger()], sheet, form)


def _larger_first(usual: Panel, larger: Sequence[Panel], sheet: str, form: str) -> Panel:
    """``usual`` with the ways of ``larger`` that an empty ``sheet`` holds as its own, largest first, itself last:
    for the packing to take the largest the room left holds."""
    ways = sorted((way for way in larger if holds(sheet, form, width(way), height(way))),
                  key=lambda way: -width(way) * height(way))
    return replace(ways[0], alternatives=(*ways[1:], usual)) if ways else usual


def _dynamics_drawn(layers: Sequence[Layer], locale: str, sheet: str | None, form: str) -> Panel:
    """The dynamics drawing ``layers`` as a panel whose parts are its diagrams, on ``sheet``."""
    # Its diagrams are at scales fitted to the machine, none a length's: no μl in a title block, nor in advice.
    # Each is labelled by its heading, which a refusal names it by: "dynamics-moments" told a reader nothing.
    alone = {layer.name: Panel(f"dynamics-{layer.name}", (layer,), label="; ".join(dynamics_headings((layer,))),
                               to_scale=False) for layer in layers if layer.name != TITLE_LAYER}
    parts: list[Panel] = []
    for name, part in alone.items():
        if name == "inertia" and "energy-mass" in alone:
            continue
        if name == "energy-mass" and "inertia" in alone:
            together = (part, alone["inertia"])
            part = Panel("dynamics-flywheel", tuple(layer for piece in together for layer in piece.layers), together,
                         "; ".join(piece.label for piece in together), to_scale=False)
        parts.append(part)
    if sheet is not None and sheet != "none":
        # A diagram no sheet holds only for its heading (the Russian flywheel's moments, 259 mm wide for the words
        # over a 200 mm diagram, on an A4's 256 mm) stands with its heading broken; one that fits keeps it whole.
        parts = [_fitting(part, sheet, form) for part in parts]
    return Panel("dynamics", tuple(layers), tuple(parts), labels(locale)["sheet_dynamics"], to_scale=False)


def _held_by_parts(panel: Panel, sheet: str, form: str) -> bool:
    """Whether an empty ``sheet`` holds ``panel`` whole, or else each of its parts so, as the packing sets them."""
    return holds(sheet, form, width(panel), height(panel)) or \
        bool(panel.parts) and all(_held_by_parts(part, sheet, form) for part in panel.parts)


def _fitting(part: Panel, sheet: str, form: str) -> Panel:
    """``part``, or where no empty ``sheet`` holds it and one holds it with its headings broken, that."""
    if holds(sheet, form, width(part), height(part)):
        return part
    broken = _heading_broken(part)
    return broken if holds(sheet, form, width(broken), height(broken)) else part


def _heading_broken(part: Panel) -> Panel:
    """``part`` with the heading of each of its diagrams (its largest bold text) broken at its phrases to no wider
    than the rest of that diagram, its last line where it stood and the others above, where the heading is the
    wider; the parts within it likewise."""
    def broken(layer: Layer) -> Layer:
        texts = [item for item in layer.items if isinstance(item, Text) and item.weight == "bold"]
        if not texts:
            return layer
        heading = max(texts, key=lambda text: text.size)
        rest = [item for item in layer.items if item is not heading]
        if not rest:
            return layer
        _, _, x1, _ = bounds_of(rest)
        room = x1 - heading.at[0]
        if text_width(heading.text, heading.size, heading.weight) <= room:
            return layer
        lines = fitted(heading.text, room, heading.size, heading.weight)
        return replace(layer, items=(*rest, *plan_layout.title_texts(lines, heading.size, heading.at)))

    return replace(part, layers=tuple(broken(layer) for layer in part.layers),
                   parts=tuple(_heading_broken(piece) for piece in part.parts))


def course_sheets(analysis: Analysis, sheet: str | None = None, details: Details | None = None,
                  diagrams: Sequence[Panel | Sequence[Layer]] = (), panels: CoursePanels | None = None) -> list[Sheet]:
    """Every sheet of the analysis, numbered as one set: kinematics first, then forces, then dynamics, then the
    rotor's balancing.

    ``sheet`` defaults to the scene's ``drawing.sheet``; ``diagrams`` are
    further kinematics panels (the diagrams of the output link); ``panels``
    the drawings already laid out (:func:`course_panels` of the analysis
    with its μl fixed, :func:`~graphplan.render.drawings.with_length_scale`),
    which then stand for ``diagrams`` too.
    """
    chosen = analysis.scene.drawing.sheet if sheet is None else sheet
    check_sheet(chosen)
    # On the scene's own sheet, what it refuses is found before the drawings are: before μl is chosen, whose
    # choice lays every sheet out at each μl it tries, and before the force sheets (a shaper's plans refused on A4
    # after 15 s of it).  On another sheet μl is still chosen for the scene's, and only the sheets laid out tell.
    refused_first = chosen != "none" and chosen == analysis.scene.drawing.sheet
    if refused_first:
        refuse_overflows(analysis)
    analysis = with_length_scale(analysis)
    scene = analysis.scene
    panels = panels or course_panels(analysis, diagrams, chosen)
    if chosen != "none" and not refused_first:
        _refuse_overflows(analysis, chosen, panels.kinematics)
    form = form_of(scene.locale)
    details = details or details_of(scene.project, scene.title, form)
    if not details.title:
        details = replace(details, title=scene.title)
    scale = length_scale(analysis)
    kinds = (("sheet_kinematics", panels.kinematics, scale), ("sheet_forces", panels.forces, scale),
             ("sheet_dynamics", panels.dynamics, None),  # no μl: the dynamics draws no linkage
             ("sheet_balancing", panels.balancing, None))
    return _numbered_set(kinds, chosen, scene.locale, details)


def larger_polygons(panels: CoursePanels, sheets: Sequence[Sheet]) -> dict[int, tuple[SheetPolygons, ...]]:
    """By position number, the force drawings the course ``sheets`` draw larger than the record (the sheet each
    stands on, the μF there of its polygons and of its groups' arrows), for the check of readings measured on them
    (:func:`~graphplan.analysis.read_off_sheets`): the force sheet's and, with friction, the force sheet with
    friction's, whose reactions a hand that measured it read."""
    drawn = {panel.name: panel for panel in panels.forces if panel.polygon_scales or panel.body_arrows}
    found: dict[int, list[SheetPolygons]] = {}
    for sheet in sheets:
        for name in sheet.panels:
            friction = name.startswith("forces-friction-")
            number = name.removeprefix("forces-friction-" if friction else "forces-")
            if name in drawn and number.isdigit():
                found.setdefault(int(number), []).append(SheetPolygons(
                    sheet.number, dict(drawn[name].polygon_scales), friction,
                    {label: (scale, whole) for label, scale, whole in drawn[name].body_arrows}))
    return {number: tuple(each) for number, each in found.items()}


@dataclass(frozen=True)
class SheetLever:
    """A force sheet's Zhukovsky's lever as a course sheet draws it: the force sheet (``forces-2``,
    ``forces-friction-2``), the number of the sheet that holds the lever and the μV it is drawn at there, which a
    small sheet makes coarser than the force sheet's own (:attr:`~graphplan.render.packing.Panel.lever_scale`)."""

    drawing: str
    sheet: int
    scale: float


def sheet_levers(panels: CoursePanels, sheets: Sequence[Sheet]) -> list[SheetLever]:
    """Each lever the course ``sheets`` draw, read off the packing that laid them out: the panel placed on a sheet
    that holds the lever's layers (the force sheet whole, one of its parts, or a part's drawing standing apart), and
    the μV its force sheet's panel draws the lever at."""
    wholes = [whole.name for whole in panels.whole_forces]
    placed: dict[str, tuple[Panel, Panel]] = {}

    def index(drawn: Panel, part: Panel) -> None:
        placed[part.name] = (drawn, part)
        for inner in part.parts:
            index(drawn, inner)

    for drawn in panels.forces:
        if drawn.lever_scale is not None:
            index(drawn, drawn)
    found = []
    for sheet in sheets:
        for name in sheet.panels:
            if name not in placed:
                continue
            drawn, part = placed[name]
            if not any(layer.name == LEVER_FIELD or layer.name.startswith(LEVER_FIELD + "-") for layer in part.layers):
                continue
            # A force sheet's parts are named after it (forces-2-3), and so are their drawings (forces-2-3-lever).
            whole = max((whole for whole in wholes if drawn.name == whole or drawn.name.startswith(whole + "-")),
                        key=len)
            found.append(SheetLever(whole, sheet.number, drawn.lever_scale))
    return found


def machine_sheets(dynamics: Sequence[Panel], balancing: Sequence[Panel], sheet: str, locale: str,
                   details: Details) -> list[Sheet]:
    """The sheets of a machine without a linkage, numbered as one set: its dynamics from load diagrams
    (:func:`dynamics_panel`), then its rotor's balancing (:func:`balancing_panel`); no μl, neither draws a linkage."""
    check_sheet(sheet)
    return _numbered_set((("sheet_dynamics", dynamics, None), ("sheet_balancing", balancing, None)), sheet, locale,
                         details)


def _numbered_set(kinds: Sequence[tuple[str, Sequence[Panel], float | None]], sheet: str, locale: str,
                  details: Details) -> list[Sheet]:
    """Sheets of each kind in turn, (kind, its panels, μl for the title block), numbered as one set."""
    if sheet == "none":
        pages = [panel for _, drawings, _ in kinds for panel in drawings]
        return [_unframed(panel, k + 1, len(pages)) for k, panel in enumerate(pages)]
    form = form_of(locale)
    packed = [(kind, pack(list(drawings), sheet, form) if drawings else [], at) for kind, drawings, at in kinds]
    total = sum(len(pages) for _, pages, _ in packed)
    sheets: list[Sheet] = []
    for kind, pages, at in packed:
        sheets += _drawn(pages, sheet, locale, kind, at, details, len(sheets) + 1, total)
    return sheets


@dataclass(frozen=True)
class _Overflow:
    """Drawings at a scale the scene sets that no empty sheet holds, and the settings that would fit them."""

    what: str
    fixes: tuple[str, ...]
    panels: tuple[Panel, ...]


def refuse_overflows(analysis: Analysis) -> None:
    """What the scene's sheets would refuse (:func:`_refuse_overflows`), found by laying out the drawings at a
    scale the scene sets alone, not the sheets: ``check``'s word before a run."""
    sheet = analysis.scene.drawing.sheet
    if sheet == "none":
        return
    # Where μl is the program's, the drawings at μl fit at the largest it starts its choice from, and the plans
    # at the scene's pole distances and the polygons at its μF are drawn at no μl: all measured there, not at the
    # μl chosen, whose choice lays every sheet out at each μl it tries (70 s for a shaper's twelve plans on A4).
    given = analysis.scene.drawing.length_scale
    analysis = with_length_scale(analysis) if given is not None else \
        at_length_scale(analysis, largest_length_scale(analysis, sheet))
    _refuse_overflows(analysis, sheet, _kinematics_laid_out(analysis))


def _refuse_overflows(analysis: Analysis, sheet: str, kinematics: Sequence[Panel]) -> None:
    """One clear error naming every drawing at a scale the scene sets (μl, a pole distance) that fits no empty
    ``sheet``, with the value of each key that fits and the format that would do, before anything is placed."""
    overflows = [found for found in (_length_scale_overflow(analysis, sheet, kinematics),
                                     _plans_overflow(analysis, sheet, kinematics),
                                     _polygons_overflow(analysis, sheet)) if found is not None]
    if not overflows:
        return
    form = form_of(analysis.scene.locale)
    panels = [panel for found in overflows for panel in found.panels]
    fixes = [fix for found in overflows for fix in found.fixes]
    ways = ["give " + " and ".join(fixes)] if fixes else []
    bigger = bigger_holding(sheet, form, panels)
    if bigger is not None:
        # The largest format graphplan draws is told alone: "or a bigger sheet" offered sheets it has not.
        ways.append(f"choose {bigger}{' or a bigger sheet' if bigger in BIGGER else ''}")
    ways.append('sheet = "none"')
    raise SceneError("drawing.sheet",
                     f"{'; '.join(found.what for found in overflows)}: no {sheet} sheet holds "
                     f"{'it' if len(panels) == 1 else 'them'} ({rooms(sheet, form, orientations(sheet))}); "
                     f"{', or '.join(ways)}", sheet)


def _length_scale_overflow(analysis: Analysis, sheet: str, kinematics: Sequence[Panel]) -> _Overflow | None:
    """The first drawing at μl (the plan of positions, the mechanism of a plan sheet) no empty ``sheet`` holds."""
    form = form_of(analysis.scene.locale)
    at_scale = [kinematics[0]] + [part for panel in kinematics[1:] for part in panel.parts
                                  if part.name.endswith("-mechanism")]
    too_big = next((panel for panel in at_scale if not holds(sheet, form, width(panel), height(panel), True)), None)
    if too_big is None:
        return None
    scale = length_scale(analysis)
    what = "the plan of positions" if too_big is kinematics[0] else f"the drawing {too_big.name!r}"
    fix = (f"drawing.length_scale = {format_scale(fitting_length_scale(analysis, sheet, scale, True))} (or more)",) \
        if words_wanted() else ()  # no fix tried where none is read
    return _Overflow(f"{what} is {width(too_big):.0f} × {height(too_big):.0f} mm at μl = {format_scale(scale)} m/mm",
                     fix, (too_big,))


def _plans_overflow(analysis: Analysis, sheet: str, kinematics: Sequence[Panel]) -> _Overflow | None:
    """The velocity and acceleration plans, drawn as the scene sets them, that no empty ``sheet`` holds: every
    one, since one pole distance serves all positions."""
    form = form_of(analysis.scene.locale)
    plan_panels = {panel.name: panel for panel in kinematics}
    too_big = [(position, kind, part) for position in analysis.plans
               for part in getattr(plan_panels.get(f"plan-{position.number}"), "parts", ())
               for kind in [part.name.rsplit("-", 1)[-1]]
               if kind in ("velocity", "acceleration")
               and not any(holds(sheet, form, width(way), height(way), True) for way in part.ways)]
    if not too_big:
        return None
    settings, fixes = [], []
    for kind in ("velocity", "acceleration"):
        positions = [position for position, of_kind, _ in too_big if of_kind == kind]
        if positions:
            setting, fitting = _plan_setting(analysis, sheet, kind, positions)
            settings.append(setting)
            fixes += [fitting] if fitting else []
    parts = tuple(part for _, _, part in too_big)
    named = ", ".join(f"{part.name!r} ({width(part):.0f} × {height(part):.0f} mm)" for part in parts)
    return _Overflow(f"the drawing{'s' if len(parts) > 1 else ''} {named} at {', '.join(settings)}", tuple(fixes),
                     parts)


def _polygons_overflow(analysis: Analysis, sheet: str) -> _Overflow | None:
    """The force polygons, drawn at the μF the scene gives, that no empty ``sheet`` holds, and the smallest
    standard μF that fits them all (μF is the contract's ``polygon_scale``: never changed behind the scene's back).
    """
    given = analysis.scene.drawing.force_scale
    if given is None:  # chosen to fill a field that every sheet holds
        return None
    form = form_of(analysis.scene.locale)

    def unheld(scale: float) -> list[Panel]:
        return [piece for piece in _polygon_pieces(analysis, scale)
                if not holds(sheet, form, width(piece), height(piece), True)]

    too_big = unheld(given)
    if not too_big:
        return None
    fix: tuple[str, ...] = ()
    scale = standard_scale(given)
    for _ in range(_LARGER_SCALES_TRIED if words_wanted() else 0):  # no fix tried where none is read
        if scale > given and not unheld(scale):
            fix = (f"drawing.force_scale = {format_scale(scale)} (or more)",)
            break
        scale = next_standard_scale(scale)
    named = ", ".join(f"{piece.name!r} ({width(piece):.0f} × {height(piece):.0f} mm)" for piece in too_big)
    return _Overflow(f"the force polygon{'s' if len(too_big) > 1 else ''} {named} at drawing.force_scale = "
                     f"{format_scale(given)} N/mm", fix, tuple(too_big))


def _polygon_pieces(analysis: Analysis, scale: float) -> list[Panel]:
    """Every force polygon of the analysis (with friction too) drawn at μF = ``scale``, as the force sheets cut
    them out, lettered at the smaller caption size that a force sheet falls back to."""
    pieces = []
    for position in analysis.plans:
        for with_friction in (False, True):
            forces = position.with_friction if with_friction else position.forces
            if forces is None or forces.locked:
                continue
            drawn = force_sheet(analysis, position, with_friction)
            drawn = replace(drawn, forces=drawn.forces.at_scale(scale),
                            caption_size=force_layout.SMALL_CAPTION_SIZE)
            name = f"{'forces-friction' if with_friction else 'forces'}-{position.number}"
            panel = split(force_layout.arrange(drawn), name, "", _group_of_field)
            pieces += [piece for piece in smallest_drawings(panel.parts) if "-polygon-" in piece.name]
    return pieces


def _plan_setting(analysis: Analysis, sheet: str, kind: str,
                  positions: Sequence[PlanPosition]) -> tuple[str, str | None]:
    """How the scene sizes its ``kind`` plans, and the value that makes the plans of ``positions`` fit
    ``sheet`` (None when the scene leaves the scale to the program, or no value does)."""
    form = form_of(analysis.scene.locale)
    drawing = analysis.scene.drawing
    pole, given_scale = getattr(drawing, f"{kind}_pole"), getattr(drawing, f"{kind}_scale")

    def fits(position: PlanPosition, scale: float) -> bool:
        return any(holds(sheet, form, *size, True) for size in _plan_part_sizes(analysis, position, kind, scale))

    if given_scale is not None:
        scale = standard_scale(given_scale)
        for _ in range(_LARGER_SCALES_TRIED if words_wanted() else 0):  # no fix tried where none is read
            if all(fits(position, scale) for position in positions):
                return (f"drawing.{kind}_scale = {format_scale(given_scale)}",
                        f"drawing.{kind}_scale = {format_scale(scale)} (or more)")
            scale = next_standard_scale(scale)
        return f"drawing.{kind}_scale = {format_scale(given_scale)}", None
    driven = [abs(getattr(position, kind).value(analysis.mechanism.driver.joint)) for position in positions]
    # The program's scale as the plan's caption writes it (the errors are in English).
    setting = f"drawing.{kind}_pole = {pole:g} mm" if pole is not None else \
        f"{kind} scale " + strings("en")[f"{kind}_scale"].format(
            value=scale_factor(getattr(positions[0], kind).scale)) + " (the program's)"
    if not all(pa > 0 for pa in driven) or not words_wanted():  # no fix to find, or none read
        return setting, None
    # A plan grows with its pole distance: for each position the largest whole millimetre that fits, by halving,
    # from the scene's pole distance or the one the program's scale draws (a small sheet's fix the error named
    # no key for).
    drawn = max(pa / getattr(position, kind).scale for position, pa in zip(positions, driven, strict=True))
    too_long = math.ceil(pole if pole is not None else drawn)
    for position, pa in zip(positions, driven, strict=True):
        if not fits(position, pa / 1.0):
            return setting, None
        fitting = 1
        while too_long - fitting > 1:
            middle = (fitting + too_long) // 2
            fitting, too_long = (middle, too_long) if fits(position, pa / middle) else (fitting, middle)
        too_long = fitting + 1
    return setting, f"drawing.{kind}_pole = {too_long - 1} (or less)"


def _plan_part_sizes(analysis: Analysis, position: PlanPosition, kind: str,
                     scale: float) -> list[tuple[float, float]]:
    """The width and height (mm) of the velocity or acceleration plan (``kind``) of a plan sheet standing apart on
    a course sheet, in each way it may stand, drawn at the plan scale ``scale`` instead of its own: with its
    caption as the sheet sets it, naming its position (:func:`_plans_captioned_apart`).  Measured with the plan
    sheet's own caption, the pole distance a refusal offered the quick-return's acceleration plan on an A4 left it
    6 mm too tall there."""
    plans_at = {"velocity": position.velocity, "acceleration": position.acceleration}
    plans_at[kind] = replace(plans_at[kind], scale=scale)
    sheet = plan_sheet(analysis, position.index, **plans_at)
    row = _plan_sheet_ways(sheet, strings(analysis.scene.locale), ("row",))[0]
    part = next(part for part in row.parts if part.name.endswith(f"-{kind}"))
    return [(width(way), height(way)) for way in part.ways]


def _sheets(drawings: Sequence[Panel | Sequence[Layer]], sheet: str, locale: str, kind: str, title: str,
            scale: float | None, details: Details | None, first: int, count: int | None) -> list[Sheet]:
    check_sheet(sheet)
    panels = [panel_of(drawing, f"panel-{k + 1}") for k, drawing in enumerate(drawings)]
    details = replace(details or Details(), title=title or (details.title if details else ""))
    if sheet == "none":
        return [_unframed(panel, first + k, count or len(panels)) for k, panel in enumerate(panels)]
    pages = pack(panels, sheet, form_of(locale))
    return _drawn(pages, sheet, locale, kind, scale, details, first, count or first - 1 + len(pages))


def sheet_svg(layers: Sequence[Layer], sheet: str | tuple[float, float] | None) -> str:
    """The SVG text of a sheet's ``layers``: a page of the sheet's size (a format name or (width, height) mm).

    ``"none"`` or None gives a page round the drawing, as the drawings before sheets.
    """
    if sheet is None or sheet == "none":
        return to_svg(layers, UNFRAMED_MARGIN_MM)
    if isinstance(sheet, str):
        check_sheet(sheet)
        sheet = FORMATS[sheet]
    return to_svg(layers, page=(float(sheet[0]), float(sheet[1])))


# Drawing the sheets.

def _drawn(pages: Sequence[Page], sheet: str, locale: str, kind: str, scale: float | None, details: Details,
           first: int, count: int) -> list[Sheet]:
    form = form_of(locale)
    words = labels(locale)
    text = strings(locale)
    sheets = []
    for k, page in enumerate(pages):
        own = {panel.length_scale for panel, _, _ in page.placed if panel.length_scale is not None}
        page_scale = own.pop() if len(own) == 1 else scale
        if not any(panel.to_scale for panel, _, _ in page.placed):
            page_scale = None
        scale_box = scale_text(page_scale, form, text["length_scale"], text["decimal_mark"]) if page_scale is not None else ""
        fields = TitleBlockFields(**asdict(details), drawing=_drawing_name(page, kind, form, words) or words[kind],
                                  scale=scale_box, sheet=first + k, sheets=count, language=locale)
        layers: list[Layer] = []
        placed: dict[str, Rect] = {}
        for panel, rect, (dx, dy) in page.placed:
            layers.extend(prefixed(moved_layers(panel.drawn_layers(), dx, dy), panel.name))
            placed[panel.name] = rect
        layers = _plan_names_on_one_line(layers, page, placed)
        layers.append(Layer("sheet-frame", tuple(_frame(page, form))))
        layers.append(Layer("title-block", tuple(title_block(form, fields, words, (page.frame[2], page.frame[1])))))
        if page.corner is not None:
            layers.append(Layer("sheet-designation", tuple(corner_box(form, fields.designation, page.corner))))
        sheets.append(Sheet(sheet, page.size, layers, page.frame, page.block, placed, first + k, count))
    return sheets


# A plan's caption on a sheet, by its layer's name there (a plan sheet's whole or its plan standing apart).
_PLAN_CAPTION = re.compile(r"^plan-\d+-(?:velocity|acceleration)-caption$")
# How far (mm) a plan's name set on one line keeps from the ink round it: beside it two cap heights, so that two
# captions on one line read as two; above and below one, less than its own drawing stands over it.
_ONE_LINE_CLEARANCE_MM = (2 * plan_layout.CAPTION_SIZE, plan_layout.CAPTION_SIZE)


def _plan_names_on_one_line(layers: Sequence[Layer], page: Page, placed: Mapping[str, Rect]) -> list[Layer]:
    """A packed page's ``layers`` with each plan's caption whose name is broken over lines (``_name_lines``) set
    with its name on one line, the lines under it raised, where they keep :data:`_ONE_LINE_CLEARANCE_MM` from every
    other ink of the page, stay in the room the page gives its drawings and widen their drawing's bounds (``placed``,
    by its name, as the packing placed it) into no other's.  A caption may reach into the room the packing keeps
    round a drawing, where no ink is: the slotted lever's "Acceleration plan, position 4" stands 20 mm short of the
    bounds of position 11's plan sheet, placed 35 mm off, but 80 mm under them.

    The name is broken to the room its drawing or the plan sheet's row gives it before the drawings are placed, and
    the packing keeps the broken form, which leaves the most room: the slotted lever's A1 set "Acceleration plan, /
    position 4" on two lines with nothing beside it for 200 mm.  Only once placed is the room round it known.
    """
    out = list(layers)
    inked = dict(placed)
    for k, layer in enumerate(out):
        if not _PLAN_CAPTION.match(layer.name) or not all(isinstance(item, Text) for item in layer.items):
            continue
        texts: list[Text] = list(layer.items)  # type: ignore[arg-type]
        broken = next((n for n, item in enumerate(texts) if item.weight != "bold"), len(texts))
        own = max((name for name in inked if layer.name.startswith(name + "-")), key=len, default=None)
        if broken < 2 or own is None:
            continue
        rise = texts[0].at[1] - texts[1].at[1]
        one_line = (replace(texts[0], text=joined([item.text for item in texts[:broken]])),
                    *(moved(item, 0.0, (broken - 1) * rise) for item in texts[broken:]))
        # The drawings' bounds stay apart: the ratchet's Russian acceleration plan on one line, 40 mm under the
        # kinematic diagrams' bounds, widened its plan sheet's, as tall as the diagrams', into theirs.
        widened = _union_of((inked[own], *map(text_extent, one_line)))
        if not any(overlap(widened, rect) for name, rect in inked.items() if name != own) \
                and _clear_of_ink(one_line, out[:k] + out[k + 1:], page):
            inked[own] = widened
            out[k] = Layer(layer.name, one_line)
    return out


def _union_of(boxes: Sequence[Sequence[float]]) -> Rect:
    return (min(box[0] for box in boxes), min(box[1] for box in boxes),
            max(box[2] for box in boxes), max(box[3] for box in boxes))


def _clear_of_ink(texts: Sequence[Text], others: Sequence[Layer], page: Page) -> bool:
    """Whether ``texts`` stand in ``page``'s area, clear of its title block (and графа 26), and each at least
    :data:`_ONE_LINE_CLEARANCE_MM` from every item of ``others``, measured to its lines, not their bounds."""
    boxes = [text_extent(item) for item in texts]
    ax0, ay0, ax1, ay1 = page.area
    if any(x0 < ax0 or y0 < ay0 or x1 > ax1 or y1 > ay1 for x0, y0, x1, y1 in boxes):
        return False
    if any(overlap(box, obstacle) for box in boxes for obstacle in page.obstacles()):
        return False
    across, up = _ONE_LINE_CLEARANCE_MM
    grown = [(x0 - across, y0 - up, x1 + across, y1 + up) for x0, y0, x1, y1 in boxes]
    kept = shapely.union_all([shapely.box(*box) for box in grown])
    reach = kept.bounds
    for layer in others:
        if not layer.items or not overlap(bounds([layer]), reach):
            continue
        near = [item for item in layer.items if overlap(bounds_of([item]), reach)]
        if near and any(kept.intersects(shape) for shape in obstacles_of(near)):
            return False
    return True


# The panels that are a sheet kind's own drawings, by their names' start: beside them a page may hold drawings of
# another kind that have a heading of their own (the load diagrams in the room a force sheet leaves).
_OWN_PANELS = {"sheet_forces": "forces"}
# The drawings of another kind a sheet kind's page may hold, by their names' start, with the title block's name of
# the page that holds them too (its ``{name}``, the page's own drawings').
_SHARING_PANELS = {"sheet_forces": ("load-diagrams", "sheet_with_load_diagrams")}


def _drawing_name(page: Page, kind: str = "", form: str = "", words: Mapping[str, str] | None = None) -> str:
    """What a page shows, when it is one drawing's: the parts of one (on pages of their own, or parts that
    share a page), or one whole alone; or one force analysis beside drawings of another kind, named with them in
    ``form``'s title block's ``words`` where its cell holds that (:func:`~graphplan.render.title_block.fitting_name`).

    A page with the force analysis of position 8 and the load diagrams was named only "Force analysis", where the
    page of position 2 alone was named "Force analysis, position 2"; a page of two positions' force analyses
    names neither (the kind's word), which two names in the title block's two lines would not hold.  A page of
    the rest of a force analysis and the load diagrams was named by the force analysis alone."""
    if page.label:
        return page.label
    names = {panel.label for panel, _, _ in page.placed}
    if len(names) == 1:
        return names.pop()
    own = _OWN_PANELS.get(kind)
    labels = {panel.label for panel, _, _ in page.placed if own is not None and panel.name.startswith(own)}
    named = labels.pop() if len(labels) == 1 else ""
    sharing, shared_name = _SHARING_PANELS.get(kind, ("", ""))
    if words is None or not sharing or not any(panel.name.startswith(sharing) for panel, _, _ in page.placed):
        return named
    # Named by both where the cell holds that legibly, else by the force analysis alone, else by the kind's word and
    # the other drawings: ISO's one line set "Force analysis with friction, pos. 11; load diagrams" at 1.46 mm, and
    # the sheet named by the kind's word lost both the friction and the position that tell it from the others.
    ways = [words[shared_name].format(name=named), named] if named else []
    ways.append(words[shared_name].format(name=words[kind]))
    return fitting_name(form, ways, words)


def _unframed(panel: Panel, number: int, count: int) -> Sheet:
    layers = prefixed(list(panel.drawn_layers()), panel.name)
    return Sheet("none", None, layers, None, None, {panel.name: panel.extent}, number, count)


def _frame(page: Page, form: str) -> list[Primitive]:
    """The sheet's edge (thin), the frame (a main line) and, but for ESKD, the centring marks."""
    width, height = page.size
    x0, y0, x1, y1 = page.frame
    items: list[Primitive] = [
        Polyline(((0.0, 0.0), (width, 0.0), (width, height), (0.0, height)), _EDGE, closed=True),
        Polyline(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), MAIN, closed=True)]
    if form != "eskd":
        # On the trimmed sheet's axes of symmetry (ISO 5457, GB/T 14689), not the frame's, which the wider
        # binding margin moves 5 mm or more to the right.
        middle_x, middle_y = width / 2, height / 2
        reach = CENTRING_REACH_MM
        # A mark that would run into the title block stops at the frame (GB/T 14689).
        bottom = y0 if page.block[0] <= middle_x <= page.block[2] else y0 + reach
        items += [Polyline(((middle_x, 0.0), (middle_x, bottom)), _CENTRING),
                  Polyline(((middle_x, height), (middle_x, y1 - reach)), _CENTRING),
                  Polyline(((0.0, middle_y), (x0 + reach, middle_y)), _CENTRING),
                  Polyline(((width, middle_y), (x1 - reach, middle_y)), _CENTRING)]
    return items
