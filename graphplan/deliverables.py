"""What a run delivers: the pieces the scene has data for, in the formats asked for.

A *piece* is one part of a course project (the plan of positions, the
velocity plans, the force analysis, the error tables, the note, ...).  By
default a run delivers every piece the scene has data for and nothing else;
``[output] include`` or ``--only`` narrows that down, and asking for a piece
the scene cannot give is an error naming what is missing.  Every drawing is
written as SVG, and also as PNG, PDF or DXF when those formats are asked for.

A scene without a linkage (a rotor to balance, a machine on its springs)
has no analysis: only its own pieces and ``results.json``.
"""

from __future__ import annotations

import dataclasses
import io
import json
import math
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .choices import OUTPUT_PIECES
from .errors import SceneError
from .locale import strings
from .machine_dynamics import MachineDynamics
from .reader import check_choice, check_choices
from .render.primitives import Layer, in_language

# The scene, the analysis and what reads them are imported where they are used: the command line's parser takes
# PIECES and FORMATS from here, and `graphplan --help` need not load them to list the pieces.
if TYPE_CHECKING:
    from .analysis import Analysis
    from .misreadings import SheetPolygons
    from .render.dynamics import Redrawings
    from .render.export import Rendering
    from .render.sheet import SheetLever
    from .scene import Scene

# ``figures`` are the report figures of the force analysis (matplotlib).
PIECES = OUTPUT_PIECES
DRAWING_FORMATS = ("svg", "png", "pdf", "dxf")
# Formats of the note alone: docx is the note as a Word document to edit (pdf typesets it too).
FORMATS = (*DRAWING_FORMATS, "docx")
# Pieces delivered only when asked for: the figures cost matplotlib's second; the accuracy report
# times the methods, so it is the one output that differs from run to run.  The sheets repeat the
# drawings in a frame: they come unasked only when the scene names its sheet ([drawing] sheet).
ON_REQUEST = ("figures", "accuracy")
_NO_LINKAGE = "needs a mechanism: the scene has no [frame] and [driver]"
_NO_LOADS = "needs masses or loads: the scene has neither ([links.N] mass, [[loads]])"
_NO_PLANS = "needs plan positions: positions.plans lists none"
_NO_VELOCITY_PLANS = "needs plan positions: positions.plans and positions.velocity_plans list none"


@dataclass(frozen=True)
class Drawing:
    """A drawing of the run: its file stem and its layers (paper mm, y up)."""

    stem: str
    layers: list[Layer]
    page: tuple[float, float] | None = None
    # μV a force sheet's lever is drawn at (a small sheet may draw it smaller than the plan's enlarged one): the
    # note works the lever, and names its arms, at the scale of the sheet beside it.
    lever_scale: float | None = None
    # The headings of the diagrams a part of a drawing cut for the note shows, which its caption names: "Figure 6
    # (part 2 of 3)" alone left the reader to find which of the dynamics' diagrams each part holds.
    shows: tuple[str, ...] = ()
    # A course sheet's force drawings drawn larger than the record, by position number (:func:`larger_polygons`): a
    # position's force sheet and its sheet with friction each give one; a force sheet's own arrows of the groups cut
    # free, and the sheet with friction's polygons and arrows, where a reaction was read by hand
    # (:func:`_record_drawings`).
    larger_polygons: tuple[tuple[int, SheetPolygons], ...] = ()
    # The levers a course sheet draws (:func:`~graphplan.render.sheet.sheet_levers`), each at the μV it stands at
    # there, which a small sheet makes coarser than its force sheet's: the note tells a reader measuring them.
    levers: tuple[SheetLever, ...] = ()


def missing(scene: Scene, analysis: Analysis | None, piece: str, sheet_key: str = "drawing.sheet") -> str | None:
    """Why the scene cannot give ``piece``, or None when it can; ``sheet_key`` names what set the sheet format
    (``--sheet`` given on the command line)."""
    if piece == "balancing":
        return None if scene.balancing is not None else "needs a [balancing] table"
    if piece == "vibration":
        return None if scene.vibration is not None else "needs a [vibration] table"
    if piece == "dynamics" and _diagrams_alone_do(scene):
        return None
    if piece == "dynamics" and scene.dynamics is None:
        # Asked first: a rotor's scene told it "needs a mechanism" where a load diagram alone would do.
        return "needs a [dynamics] table"
    if piece == "note" and analysis is None and (
            scene.balancing is not None or scene.vibration is not None or _diagrams_alone_do(scene)):
        return None  # the note on the machine's flywheel, rotor or vibration alone
    # A rotor's balancing and a machine's load diagrams have sheets of their own: a scene of them alone asked for
    # sheets on "none" was told it "needs a mechanism", which it does not, and not the sheet format that stops them.
    drawn_on_sheets = analysis is not None or scene.balancing is not None or _diagrams_alone_do(scene)
    if piece == "sheets" and drawn_on_sheets:
        return f'needs a sheet format: {sheet_key} is "none"' if scene.drawing.sheet == "none" else None
    if analysis is None:
        return _NO_LINKAGE
    from . import kinematic_diagrams, load_diagrams

    if piece == "diagrams" and (reason := kinematic_diagrams.unavailable(scene, analysis)) is not None:
        return reason
    if piece == "load_diagrams" and (reason := load_diagrams.unavailable(analysis)) is not None:
        return reason
    if piece == "accuracy" and analysis.motion.singular:
        index = min(analysis.motion.singular)
        return (f"needs every position regular: position {analysis.positions.numbers[index]} is singular "
                "and has no reference solution")
    has_plans = bool(analysis.plans)
    if piece in ("velocity", "errors") and not has_plans and not analysis.velocity_plans:
        return _NO_VELOCITY_PLANS
    if piece in ("acceleration", "forces", "lever") and not has_plans:
        return _NO_PLANS
    if piece in ("forces", "lever") and not any(plan.forces is not None for plan in analysis.plans):
        # Friction acts through the reactions the loads cause: without them the scene's [[friction]] does nothing.
        return _NO_LOADS + ("; its [[friction]] has no reactions to act through" if scene.friction else "")
    if piece == "figures" and analysis.equilibrium is None:
        return _NO_LOADS
    return None


def _diagrams_alone_do(scene: Scene) -> bool:
    """Whether ``[dynamics]`` gives load diagrams, which need no mechanism."""
    return scene.dynamics is not None and bool(scene.dynamics.diagrams)


def chosen(scene: Scene, analysis: Analysis | None, only: Iterable[str] | None = None,
           where: str = "--only", sheet_key: str = "drawing.sheet") -> tuple[str, ...]:
    """The pieces to deliver: ``only`` (from ``--only``), else the scene's ``[output] include``, else every
    piece the scene has data for (those :data:`ON_REQUEST` excepted).

    A piece asked for that the scene cannot give is a :class:`SceneError`.
    """
    if only is None and scene.include is None:
        return tuple(piece for piece in PIECES if _by_default(scene, piece) and missing(scene, analysis, piece) is None)
    if scene.include is not None:
        # Refused under --only too, as check refuses it: the scene is wrong whichever pieces this run writes.  Under
        # --only its sheets are not judged by the --sheet this run gives (none, for pieces drawn without them).
        _refuse_missing(scene, analysis, list(scene.include), "output.include", sheet_key,
                        not_judged=() if only is None else ("sheets",))
    if only is None:
        return tuple(piece for piece in PIECES if piece in scene.include)
    # Checked as the scene's [output] include is, with the piece a misspelling was meant to be.
    asked = [check_choice(piece, f"{where}[{k}]", PIECES) for k, piece in enumerate(only)]
    _refuse_missing(scene, analysis, asked, where, sheet_key)
    return tuple(piece for piece in PIECES if piece in asked)


def _refuse_missing(scene: Scene, analysis: Analysis | None, asked: list[str], where: str, sheet_key: str,
                    not_judged: tuple[str, ...] = ()) -> None:
    """A :class:`SceneError` at ``where[k]`` for the first of ``asked`` (but those ``not_judged``) that the scene
    cannot give."""
    for k, piece in enumerate(asked):
        reason = None if piece in not_judged else missing(scene, analysis, piece, sheet_key)
        if reason is not None:
            raise SceneError(f"{where}[{k}]", f"{piece!r} {reason}")


def refuse_as_run_would(scene: Scene, analysis: Analysis | None,
                        pieces: tuple[str, ...]) -> MachineDynamics | None:
    """Raise the :class:`SceneError` a run of ``pieces`` would meet only once it draws or integrates: a plan or
    polygon larger than any paper, a drawing no sheet holds at the scale the scene gives, a motor that outpulls
    the resistance at every speed.  For ``check``, so that its "ok" means the run goes through.

    Returns the machine's dynamics where it worked them out, for the warnings of their outcomes to read: worked out
    again, the machine's motion was integrated once more for each (three times over in all)."""
    drawn = {"positions", "velocity", "acceleration", "forces", "lever", "sheets"} & set(pieces)
    if analysis is not None and drawn:
        from .render import drawings as draw

        if scene.drawing.length_scale is not None:
            # Every drawing of the mechanism reads μl, which refuses one that draws it larger than any paper: with
            # no sheet to fit (sheet = "none"), check said ok to a scene the run then refused.
            draw.length_scale(analysis)
        if drawn - {"positions"}:
            draw.refuse_beyond_paper(analysis)
    if analysis is not None and "sheets" in pieces:
        from .render.sheet import refuse_overflows

        refuse_overflows(analysis)
    if analysis is not None and {"diagrams", "sheets"} & set(pieces) and scene.positions.working is not None:
        from .kinematic_diagrams import of_analysis

        of_analysis(analysis)  # a derivative out of the pole method's reach near a toggle
    dynamics = None
    if "dynamics" in pieces and scene.dynamics is not None:
        dynamics = _dynamics_of(scene, analysis, None)
        dynamics.refuse()
    if "sheets" in pieces and scene.drawing.sheet != "none" and missing(scene, analysis, "dynamics") is None:
        dynamics = _dynamics_of(scene, analysis, dynamics)
        _refuse_dynamics_overflow(scene, analysis, dynamics)
    return dynamics


def _refuse_dynamics_overflow(scene: Scene, analysis: Analysis | None, dynamics: MachineDynamics) -> None:
    """The refusal the sheets meet where no sheet holds the dynamics drawing, even part by part: its scales are the
    program's, fitted to the machine, so only packing it shows whether it fits."""
    from .render.packing import pack
    from .render.sheet import dynamics_panel
    from .render.title_block import form_of

    machine, redrawn = _machine_layouts(dynamics, _dynamics_words(scene, analysis, dynamics))
    pack([dynamics_panel(machine, scene.locale, redrawn, scene.drawing.sheet, filled=False)], scene.drawing.sheet,
         form_of(scene.locale))


def _by_default(scene: Scene, piece: str) -> bool:
    if piece == "sheets":
        return scene.drawing.sheet_given
    return piece not in ON_REQUEST


def _silent(stage: str) -> None:
    """A stage nobody is told of."""


def drawings(scene: Scene, analysis: Analysis | None, pieces: tuple[str, ...],
             dynamics: MachineDynamics | None = None, say: Callable[[str], None] = _silent) -> list[Drawing]:
    """The drawings of ``pieces``, each laid out once for every format it is written in; ``say`` is told of each
    kind of drawing as its laying out begins."""
    found: list[Drawing] = []
    if analysis is not None:
        found += _linkage_drawings(analysis, pieces, dynamics, say)
    elif {"dynamics", "balancing", "sheets"} & set(pieces):
        say("drawing the machine")
    sheets = analysis is None and "sheets" in pieces
    # Each laid out once for its own drawing and the sheets of a machine without a linkage.
    machine: list[Layer] = []
    redrawn = None
    if analysis is None and ("dynamics" in pieces or sheets and missing(scene, None, "dynamics") is None):
        machine, redrawn = _machine_layouts(_dynamics_of(scene, analysis, dynamics), strings(scene.locale))
    if "dynamics" in pieces and analysis is None:
        found += _dynamics_drawings(machine, pieces)
    rotor = _balancing_layers(scene) if "balancing" in pieces or sheets and scene.balancing is not None else []
    if "balancing" in pieces:
        found.append(Drawing("rotor_balancing", rotor))
    if sheets:
        found += _machine_sheets(scene, machine, rotor, redrawn)
    return [dataclasses.replace(drawing, layers=in_language(drawing.layers, scene.locale, scene.own_words))
            for drawing in found]


def _machine_layouts(dynamics: MachineDynamics, words: Mapping[str, str]) -> tuple[list[Layer], Redrawings]:
    """The dynamics drawing, and the same at other scales for a sheet that asks (larger for one with room, smaller
    for one that holds none of its diagrams)."""
    from .render import dynamics as dynamics_layout

    return (dynamics_layout.layout(dynamics.model, dynamics.flywheel, words),
            dynamics_layout.Redrawings(dynamics.model, dynamics.flywheel, words))


def _machine_sheets(scene: Scene, machine: list[Layer], rotor: list[Layer],
                    redrawn: Redrawings | None = None) -> list[Drawing]:
    """The sheets of a machine without a linkage: its dynamics drawing ``machine`` (``redrawn`` at other scales
    where the sheet asks) and its rotor's balancing."""
    from .render.sheet import balancing_panel, dynamics_panel, machine_sheets
    from .render.title_block import details_of, form_of

    details = details_of(scene.project, scene.title, form_of(scene.locale))
    details = dataclasses.replace(details, title=details.title or scene.title)
    dynamics = [dynamics_panel(machine, scene.locale, redrawn, scene.drawing.sheet)] if machine else []
    balancing = [balancing_panel(rotor, scene.locale, scene.drawing.sheet, lambda: _larger_balancing(scene))] \
        if rotor else []
    return [Drawing(f"sheet_{sheet.number}", sheet.layers, sheet.size)
            for sheet in machine_sheets(dynamics, balancing, scene.drawing.sheet, scene.locale, details)]


def _balancing_layers(scene: Scene) -> list[Layer]:
    from .render import balancing as balancing_layout
    from .rotor_balancing import balance

    assert scene.balancing is not None
    return balancing_layout.layout(balance(scene.balancing), strings(scene.locale))


def _larger_balancing(scene: Scene) -> list[list[Layer]]:
    """The balancing drawing with its polygons drawn larger, for a sheet with room."""
    from .render import balancing as balancing_layout
    from .rotor_balancing import balance

    assert scene.balancing is not None
    return balancing_layout.larger_layouts(balance(scene.balancing), strings(scene.locale))


def _dynamics_words(scene: Scene, analysis: Analysis | None, dynamics: MachineDynamics) -> dict[str, str]:
    """The locale's strings for the dynamics' drawings and plots: of a linkage, their angle (a slider's travel) is
    counted from the position where the model's run starts (the note's φ of ωmax and ωmin is the crank's own
    angle, and its table's s the slider's own displacement)."""
    text = strings(scene.locale)
    if analysis is None:
        return text
    # A cycle starts at the first position; a swing or a travel that the driver runs from its far end (a lever
    # lowered, a rod drawn in) starts at the last, and its drawing read "from position 1" there.
    first = float(dynamics.model.driver[0])
    _, start = min(zip(analysis.positions.values.tolist(), analysis.positions.numbers.tolist(), strict=True),
                   key=lambda position: abs(position[0] - first))
    angle = text["angle_axis_from_position"].format(number=start)
    travel = text["travel_axis_from_position"].format(number=start)
    return {**text, "dyn_angle_axis": angle, "motion_angle_axis": angle, "dyn_travel_axis": travel}


# The pieces of a linkage drawn at μl, or on its sheets, or to scales that follow it (the diagrams' μs).
_DRAWN_AT_LENGTH_SCALE = frozenset({"positions", "velocity", "acceleration", "forces", "lever", "diagrams",
                                    "load_diagrams", "sheets"})


def _linkage_drawings(analysis: Analysis, pieces: tuple[str, ...], dynamics: MachineDynamics | None,
                      tell: Callable[[str], None] = _silent) -> list[Drawing]:
    from .render import drawings as draw
    from .render import plans as plan_layout
    from .render import positions as positions_layout
    from .render import velocity_plans as velocity_plans_layout

    found: list[Drawing] = []
    # Refused as check refuses, before μl is chosen: the choice lays every sheet out at each μl it tries, and
    # a plan no sheet holds at the scene's pole distance was refused only after it.
    draw.refuse_beyond_paper(analysis)
    if "sheets" in pieces:
        from .render.sheet import refuse_overflows

        refuse_overflows(analysis)
    if set(pieces) & _DRAWN_AT_LENGTH_SCALE:
        if analysis.scene.drawing.length_scale is None:
            tell("choosing the length scale")
        analysis = draw.with_length_scale(analysis)
    else:
        # The dynamics alone are drawn at scales of their own: choosing μl would lay every sheet out at a few μl
        # (the shaper's seconds) for nothing drawn.  The scene is still refused where the choice refuses it.
        draw.refuse_unfit_length_scale(analysis)
    machine, redrawn = None, None
    # The sheets hold the dynamics wherever the scene has them, as they hold the plans and forces unasked.
    if "dynamics" in pieces or ("sheets" in pieces and missing(analysis.scene, analysis, "dynamics") is None):
        tell("drawing the dynamics")
        dynamics = _dynamics_of(analysis.scene, analysis, dynamics)
        machine, redrawn = _machine_layouts(dynamics, _dynamics_words(analysis.scene, analysis, dynamics))
    # The sheets hold the drawings that are also written on their own: each is laid out once, where the sheets hold
    # it as it is on its own (:func:`_drawn_alone`).
    if "sheets" in pieces:
        tell("laying out the sheets")
    panels = _course_panels(analysis, machine, redrawn) if "sheets" in pieces else None
    if "positions" in pieces:
        tell("drawing the plan of positions")
        layers = list(panels.kinematics[0].layers) if panels else positions_layout.layout(draw.positions_plan(analysis))
        found.append(Drawing("positions", layers))
    if "dynamics" in pieces:
        found += _dynamics_drawings(machine, pieces)
    if "diagrams" in pieces:
        tell("drawing the kinematic diagrams")
        from .kinematic_diagrams import AXIS_MM, FIELD_MM
        from .render import diagrams as diagrams_layout
        from .render.sheet import diagram_parts

        # At the usual size, as the sheet's usual way draws them: laid out once for both.
        found.append(Drawing("diagrams", diagrams_layout.stacked(diagram_parts(analysis, AXIS_MM, FIELD_MM)[1])))
    if "load_diagrams" in pieces:
        tell("drawing the load diagrams")
        laid_out = _drawn_alone(panels, "load-diagrams")
        layers = list(laid_out.layers) if laid_out else _load_diagram_layers(analysis)
        found.append(Drawing("load_diagrams", layers))
    if panels is not None:
        from .render.sheet import course_sheets, larger_polygons, sheet_levers

        tell("drawing the sheets")
        sheets = course_sheets(analysis, panels=panels)
        larger = larger_polygons(panels, sheets)
        levers = sheet_levers(panels, sheets)
        for sheet in sheets:
            found.append(Drawing(f"sheet_{sheet.number}", sheet.layers, sheet.size, larger_polygons=tuple(
                (number, polygons) for number, drawn in larger.items() for polygons in drawn
                if polygons.sheet == sheet.number), levers=tuple(lever for lever in levers
                                                                  if lever.sheet == sheet.number)))
    if "velocity" in pieces and analysis.velocity_plans:
        tell("drawing the velocity plans of the positions")
        laid_out = panels.named("velocity-plans") if panels else None
        layers = list(laid_out.layers) if laid_out else velocity_plans_layout.layout(draw.velocity_plans_drawing(analysis))
        found.append(Drawing("velocity_plans", layers))
    shown = tuple(name for name in ("velocity", "acceleration") if name in pieces)
    if analysis.plans and (shown or {"forces", "lever"} & set(pieces)):
        tell("drawing the plans and the force sheets")
    for plan in analysis.plans:
        if shown:
            # The sheets' panel only where it is drawn as alone: on the sheets each plan's caption names its position
            # and each drawing stands at its field's foot, which took the sheets' plan sheet for plan_N.svg.
            laid_out = _drawn_alone(panels, f"plan-{plan.number}") if len(shown) == 2 else None
            if laid_out is None:
                layers = plan_layout.layout(draw.plan_sheet_showing(analysis, plan, ("mechanism", *shown)))
            else:
                layers = list(laid_out.layers)
            found.append(Drawing(f"plan_{plan.number}", layers))
            found += _plan_note_parts(plan, shown, pieces, layers)
        if plan.forces is not None and ("forces" in pieces or "lever" in pieces):
            laid_out = _drawn_alone(panels, f"forces-{plan.number}") if "lever" in pieces else None
            layers, scales, lever_scale = (list(laid_out.layers), _scales_of(laid_out), laid_out.lever_scale) \
                if laid_out else _force_sheet_layers(analysis, plan, pieces)
            found.append(Drawing(f"forces_{plan.number}", layers, lever_scale=lever_scale,
                                 larger_polygons=_record_drawings(analysis, plan)))
            found += _note_parts(f"forces_{plan.number}", layers, pieces, scales)
            rubbing = plan.with_friction
            # The sheet with friction comes with the sheet it repeats: with `lever` its lever with friction on it.
            if rubbing is not None and not rubbing.locked:
                laid_out = _drawn_alone(panels, f"forces-friction-{plan.number}") if "lever" in pieces else None
                layers, scales, lever_scale = \
                    (list(laid_out.layers), _scales_of(laid_out), laid_out.lever_scale) if laid_out \
                    else _force_sheet_layers(analysis, plan, pieces, True)
                found.append(Drawing(f"forces_friction_{plan.number}", layers, lever_scale=lever_scale,
                                     larger_polygons=_record_drawings(analysis, plan, True)))
                found += _note_parts(f"forces_friction_{plan.number}", layers, pieces, scales)
    return found


def _drawn_alone(panels, name: str):
    """The sheets' drawing ``name`` where it is the drawing as written in its own file, else None: the sheets may
    alter a force sheet or the load diagrams to fit their format (a lever a step smaller, smaller lettering, smaller
    fields), and the file on its own is the same whatever the sheets' format, or without them."""
    laid_out = panels.named(name) if panels is not None else None
    return laid_out if laid_out is not None and laid_out.drawn_alone else None


def _file_alone(panel: str) -> str:
    """The file a force sheet's panel (``forces-friction-2``) is written in on its own (``forces_friction_2.svg``)."""
    return f"{panel.replace('-', '_')}.svg"


def _load_diagram_layers(analysis: Analysis) -> list[Layer]:
    from . import load_diagrams
    from .render import load_diagrams as load_diagrams_layout

    return load_diagrams_layout.layout(load_diagrams.of_analysis(analysis), strings(analysis.scene.locale))


def _dynamics_drawings(machine: list[Layer], pieces: tuple[str, ...]) -> list[Drawing]:
    """The dynamics drawing, and where the run writes the note, the parts it shows it in (``dynamics-1.svg``, ...):
    whole, 400 mm wide, it printed on the note's page with letters 1 mm high."""
    from .render.dynamics import TITLE_LAYER, headings
    from .render.note_parts import note_parts_in_order

    parts = note_parts_in_order(machine, TITLE_LAYER) if "note" in pieces else None
    return [Drawing("dynamics", machine),
            *(Drawing(f"dynamics-{k}", part, shows=headings(part)) for k, part in enumerate(parts or (), 1))]


def _scales_of(panel) -> tuple[tuple[tuple[str, str], ...], str]:
    """The scales a force sheet's panel's heading names, with the comma that sets them apart."""
    return panel.heading_scales, panel.heading_comma


def _note_parts(stem: str, layers: list, pieces: tuple[str, ...],
                scales: tuple[tuple[tuple[str, str], ...], str]) -> list[Drawing]:
    """A force sheet too tall for a page of the note, cut between its rows for the note to show part by part
    (``forces_3-1.svg``, ...), where the run writes the note; the heading over the first naming the ``scales`` of
    its drawings alone (with the comma that sets them apart)."""
    from .render.note_parts import note_parts

    parts = note_parts(layers, *scales) if "note" in pieces else None
    return [Drawing(f"{stem}-{k}", part) for k, part in enumerate(parts or (), start=1)]


def _plan_note_parts(plan, shown: tuple[str, ...], pieces: tuple[str, ...], whole: list) -> list[Drawing]:
    """The plan sheet ``whole`` where it is too wide for a page of the note (its three drawings in a row, 650 mm for
    a six-bar), in parts for the note to show (``plan_3-1.svg``, ...), where the run writes the note; the drawing
    itself stays whole."""
    if "note" not in pieces:
        return []
    from .render import plans as plan_layout
    from .render.note_parts import note_parts_of_drawings
    from .render.primitives import bounds, moved_layers

    drawings = ("mechanism", *shown)
    own = {name: [layer for layer in whole if layer.name.startswith(f"{name}-")] for name in drawings}
    # Each caption raised to its drawing: in a row they all stand under the tallest, which a part may not hold.
    drawn = {name: bounds([layer for layer in layers if layer.name != f"{name}-caption" and layer.items])
             for name, layers in own.items()}
    captions = {name: bounds(caption) for name, layers in own.items()
                if (caption := [layer for layer in layers if layer.name == f"{name}-caption" and layer.items])}
    gap = min((drawn[name][1] - captions[name][3] for name in captions), default=0.0)
    for name, layers in own.items():
        rise = drawn[name][1] - captions[name][3] - gap if name in captions else 0.0
        own[name] = [moved_layers([layer], 0.0, rise)[0] if layer.name == f"{name}-caption" else layer
                     for layer in layers]

    def laid_out(names: tuple[str, ...]) -> list:
        # The drawings' own layers, each named after its drawing (velocity-lines, velocity-caption), taken out of
        # the sheet as it is drawn: laid out afresh, the plans' labels were placed a second time, a tenth of a run.
        # The title stands over the first drawing, and goes with it.
        title = [layer for layer in whole if layer.name == plan_layout.TITLE_LAYER and drawings[0] in names]
        return [layer for name in drawings if name in names for layer in own[name]] + title

    parts = note_parts_of_drawings(drawings, laid_out, plan_layout.TITLE_LAYER, whole)
    return [Drawing(f"plan_{plan.number}-{k}", part) for k, part in enumerate(parts or (), start=1)]


def _record_drawings(analysis: Analysis, plan, with_friction: bool = False) -> tuple[tuple[int, SheetPolygons], ...]:
    """What hand readings of ``plan``'s reactions may have been measured on besides the polygons they are checked
    against, where a reaction was read by hand: the arrows of the groups cut free that ``forces_N.svg`` draws
    beside its polygons at a μF of their own (:func:`~graphplan.render.force_bodies.free_body_arrows`), told so (a
    :class:`SheetPolygons` of no sheet) after the course sheets' drawings, drawn before them; ``with_friction``,
    the polygons with friction of ``forces_friction_N.svg`` (at the record's μF where they fit two fields there) and
    its own arrows, whose readings are the reactions with friction, not those the tables compare with, told so with
    no ``force_scale`` nor a factor."""
    from .misreadings import SheetPolygons, reads_forces

    if not reads_forces(plan):
        return ()
    from .render import drawings as draw
    from .render import force_bodies

    arrows = force_bodies.free_body_arrows(draw.force_sheet(analysis, plan, with_friction))
    drawn = {label: (scale, whole) for label, (scale, whole) in arrows.items() if whole}
    if with_friction:
        return ((plan.number, SheetPolygons(None, dict(plan.with_friction.group_scales), friction=True,
                                            arrows=drawn)),)
    return ((plan.number, SheetPolygons(None, {}, arrows=drawn)),) if drawn else ()


def _force_sheet_layers(analysis: Analysis, plan, pieces: tuple[str, ...], with_friction: bool = False
                        ) -> tuple[list, tuple[tuple[tuple[str, str], ...], str], float | None]:
    """The force sheet of a plan position, its lever left off unless the run asks for it, with the scales its
    heading names (:attr:`~graphplan.render.force_rows.Heading.scales`) and the comma that sets them apart, and μV
    its lever is drawn at (None without one): the note works the lever, and names its arms, at the sheet's scale."""
    from .render import drawings as draw
    from .render import forces as force_layout

    sheet = draw.force_sheet(analysis, plan, with_friction)
    if "lever" not in pieces:
        sheet = dataclasses.replace(sheet, lever=None)
    rows = force_layout.rows(sheet)
    return (rows.arranged(rows.in_columns(1)).layers, (rows.heading.scales, rows.heading.comma),
            sheet.lever_drawn_scale if sheet.lever is not None else None)


def _course_panels(analysis: Analysis, machine: list | None = None, redrawn: Redrawings | None = None):
    """The drawings of the sheets (:func:`graphplan.render.sheet.course_panels`), the diagrams fitted to the sheet,
    the dynamics drawing ``machine`` where the run draws one (``redrawn`` at other scales where the sheet asks), and
    the rotor's balancing where the scene has it."""
    from . import load_diagrams
    from .render.sheet import balancing_panel, course_panels, diagrams_panel, dynamics_panel, load_diagrams_panel

    scene = analysis.scene
    diagrams = ()
    if missing(scene, analysis, "diagrams") is None:
        diagrams = (diagrams_panel(analysis, scene.drawing.sheet),)
    # The load diagrams stand on the force sheets wherever the scene has them, as the kinematic diagrams do on theirs.
    loads = ()
    smaller_loads = None
    if missing(scene, analysis, "load_diagrams") is None:
        drawn = load_diagrams.of_analysis(analysis)
        loads = (load_diagrams_panel(drawn, scene.locale, scene.drawing.sheet),)

        def smaller_loads():
            # Smaller only where that saves a sheet: at the usual size they took an A1 alone beside the forces.
            from .render.load_diagrams import SMALLER_FIELDS

            return ((load_diagrams_panel(drawn, scene.locale, field=field),) for field in SMALLER_FIELDS)
    dynamics = (dynamics_panel(machine, scene.locale, redrawn, scene.drawing.sheet),) if machine is not None else ()
    # The sheets hold the rotor's balancing wherever the scene has it, as they hold the dynamics.
    balancing = (balancing_panel(_balancing_layers(scene), scene.locale, scene.drawing.sheet,
                                 lambda: _larger_balancing(scene)),) if scene.balancing is not None else ()
    return course_panels(analysis, diagrams, dynamics=dynamics, balancing=balancing, loads=loads,
                         smaller_loads=smaller_loads)


def _dynamics_of(scene: Scene, analysis: Analysis | None, dynamics: MachineDynamics | None) -> MachineDynamics:
    """The run's dynamics: the one given, or worked out now."""
    return dynamics if dynamics is not None else MachineDynamics(analysis if analysis is not None else scene)


def tells_diagrams(scene: Scene, analysis: Analysis | None, pieces: Iterable[str] = ()) -> bool:
    """Whether the note tells the kinematic diagrams, their method and scales: where the run draws them (``pieces``)
    or a run of the scene would, as it tells the plans whatever it is asked with (``--only note``)."""
    return analysis is not None and "diagrams" in (*pieces, *chosen(scene, analysis))


def tables(scene: Scene, analysis: Analysis | None, pieces: tuple[str, ...],
           dynamics: MachineDynamics | None = None, pictures: tuple[str, ...] = (),
           lever_scales: Mapping[str, float] | None = None,
           shown_in_parts: Mapping[str, tuple[str, ...]] | None = None,
           sheet_levers: Mapping[str, tuple[int, float]] | None = None) -> dict[str, str]:
    """The text files of ``pieces``: the error tables, the force analysis, the explanatory note (with its sections
    on the machine's ``dynamics``, its rotor's balancing and its vibration when the run has them, and the
    drawings and plots written beside it that ``pictures`` names, each force sheet's lever worked at the μV it is
    drawn at, ``lever_scales``, and the course sheet and μV each is drawn at there, ``sheet_levers``; the diagrams
    each part of a drawing cut for it shows, ``shown_in_parts``), each in Markdown and LaTeX (the note also in
    HTML).  A scene without a linkage has only the note."""
    files: dict[str, str] = {}
    if not {"note", "errors", "forces"} & set(pieces):
        return files  # no text asked for: the LaTeX writer and its Markdown parser stay unloaded
    from .report.latex import latex_document, latex_fragment
    from .report.markdown import user_texts

    locale = scene.locale
    verbatim = user_texts(scene)
    if "note" in pieces:
        from .report.note import note_html, note_markdown

        shown = tuple(name for name in ("velocity", "acceleration") if name in pieces)
        files["note.md"] = note_markdown(analysis, dynamics, scene, pictures, lever_scales, shown_in_parts,
                                         sheet_levers, tells_diagrams(scene, analysis, pieces),
                                         plans_shown=shown or ("velocity", "acceleration"))
        files["note.html"] = note_html(analysis, markdown=files["note.md"], scene=scene)
        files["note.tex"] = latex_document(files["note.md"], scene.title, locale, verbatim)
    if analysis is None:
        return files
    if "errors" in pieces:
        from .report.tables import csv_text, markdown

        files["errors.md"] = markdown(analysis)
        files["errors.csv"] = csv_text(analysis)
        files["errors.tex"] = latex_fragment(files["errors.md"], locale, verbatim)
    if "forces" in pieces:
        from .report.forces import markdown as forces_markdown

        files["forces.md"] = forces_markdown(analysis)
        files["forces.tex"] = latex_fragment(files["forces.md"], locale, verbatim)
    return files


def figures(scene: Scene, analysis: Analysis | None, pieces: tuple[str, ...],
            dynamics: MachineDynamics | None = None, say: Callable[[str], None] = _silent) -> dict[str, str]:
    """The plots drawn with matplotlib, which is imported only here; ``say`` is told of each as it begins."""
    found: dict[str, str] = {}
    if "dynamics" in pieces and scene.dynamics.motion is not None:
        from .report.motion_plots import motion_figure

        say("plotting the motion of the machine")
        dynamics = _dynamics_of(scene, analysis, dynamics)
        # A flywheel is sized only for a turning driver, the one the equation of motion is for.
        flywheel = dynamics.flywheel
        estimate = (dynamics.model.coordinate, flywheel.omega) if flywheel is not None else None
        found["motion.svg"] = motion_figure(dynamics.motion, _dynamics_words(scene, analysis, dynamics), scene.title,
                                            estimate, dynamics.resisting, stall_angle_deg=dynamics.rest_angle_deg())
    if "figures" in pieces and analysis is not None:
        from .report.figures import balancing_diagram

        say("plotting the balancing load")
        found["balancing.svg"] = balancing_diagram(analysis)
    if "vibration" in pieces:
        say("plotting the vibration")
        found.update(vibration_figures(scene))
    return found


def vibration_figures(scene: Scene) -> dict[str, str]:
    """The scene's vibration plotted (matplotlib's SVG): the magnification and the transmissibility, each against
    the frequency ratio, the machine's working point on them (and the isolation's design point)."""
    from .report.vibration_plots import magnification_figure, transmissibility_figure, words_for
    from .vibration import steady_state

    spec = scene.vibration
    assert spec is not None
    response = steady_state(spec)
    operating = (response.frequency_ratio, spec.damping_ratio)
    text = words_for(spec, strings(scene.locale))
    design = None if response.isolation_ratio is None or spec.transmissibility is None \
        else (response.isolation_ratio, spec.transmissibility)
    found = {}
    stream = io.StringIO()
    magnification_figure(stream, operating=operating, text=text)
    found["vibration_magnification.svg"] = stream.getvalue()
    stream = io.StringIO()
    transmissibility_figure(stream, operating=operating, design=design, text=text)
    found["vibration_transmissibility.svg"] = stream.getvalue()
    return found


def encoded(drawing: Drawing, formats: Iterable[str]) -> dict[str, str | bytes]:
    """The files of one drawing in each of ``formats``."""
    from .render.export import Rendering, rendered_all

    files = _encodings(drawing, formats)
    rendered = rendered_all({name: content for name, content in files.items() if isinstance(content, Rendering)})
    return {name: rendered.get(name, content) for name, content in files.items()}


def _encodings(drawing: Drawing, formats: Iterable[str]) -> dict[str, str | bytes | Rendering]:
    """The files of one drawing in each of ``formats``, its PNG and PDF still to render: a run renders all its
    drawings' and plots' at once (:func:`~graphplan.render.export.rendered_all`)."""
    from .render.export import Rendering
    from .render.svg import to_svg

    svg = to_svg(drawing.layers, page=drawing.page) if drawing.page else to_svg(drawing.layers)
    writers: dict[str, Callable[[], str | bytes | Rendering]] = {
        "svg": lambda: svg,
        "png": lambda: Rendering(svg, "png"),
        "pdf": lambda: Rendering(svg, "pdf"),
        "dxf": lambda: _dxf(drawing),
    }
    return {f"{drawing.stem}.{kind}": writers[kind]() for kind in formats}


def _dxf(drawing: Drawing) -> bytes:
    from .render.dxf import layers_to_dxf

    stream = io.BytesIO()
    layers_to_dxf(drawing.layers, stream)
    return stream.getvalue()


def check_formats(formats: Iterable[str], where: str = "--format") -> tuple[str, ...]:
    """``formats`` checked against :data:`FORMATS`; SVG is always written."""
    asked = check_choices(formats, where, FORMATS, "format")
    return tuple(kind for kind in FORMATS if kind == "svg" or kind in asked)


def document(scene: Scene, analysis: Analysis | None, pieces: tuple[str, ...],
             dynamics: MachineDynamics | None = None) -> dict[str, Any]:
    """``results.json``: the analysis of the contract, and the rotor's and the vibration's results."""
    from .report.results import results, results_without_linkage, rounded

    found = results(analysis) if analysis is not None else results_without_linkage(scene)
    if "dynamics" in pieces:
        from .flywheel import dynamics_results

        dynamics = _dynamics_of(scene, analysis, dynamics)
        found["dynamics"] = rounded(dynamics_results(dynamics.model, dynamics.flywheel))
        if dynamics.motion is not None:
            found["dynamics"]["motion"] = rounded(dynamics.motion_results())
    if "balancing" in pieces:
        found["balancing"] = balancing_document(scene)
    if "vibration" in pieces:
        found["vibration"] = vibration_document(scene)
    return found


def results_document(scene: Scene, analysis: Analysis | None, pieces: tuple[str, ...],
                     warn: Callable[[str], None] | None = None) -> dict[str, Any]:
    """``results.json`` as :func:`files` writes it for ``pieces``, ``warn`` told of the same outcomes: its drawings
    laid out, not written, so that what a run refuses is refused here too and readings measured on polygons drawn
    larger than the record are told so."""
    from .report.results import dumps

    analysis, _, dynamics = _laid_out(scene, analysis, pieces, warn)
    # Through the file's own text: its numbers as a reader of the file gets them (a tuple a list, a key a string).
    return json.loads(dumps(document(scene, analysis, pieces, dynamics)))


def svg_files(scene: Scene, analysis: Analysis | None, pieces: tuple[str, ...],
              warn: Callable[[str], None] | None = None) -> dict[str, tuple[str, bool]]:
    """Every SVG file :func:`files` writes for ``pieces``, by name, and whether it is a plot (matplotlib's, printed
    at the plots' resolution) or a drawing, ``warn`` told of the same outcomes: nothing rendered, no table or note
    made."""
    analysis, made, dynamics = _laid_out(scene, analysis, pieces, warn)
    found = {name: (str(svg), False) for drawing in made for name, svg in _encodings(drawing, ("svg",)).items()}
    plots = figures(scene, analysis, pieces, dynamics)
    if "accuracy" in pieces and analysis is not None:
        plots.update(accuracy_report(analysis))
    return found | {name: (str(svg), True) for name, svg in plots.items() if name.endswith(".svg")}


def _laid_out(scene: Scene, analysis: Analysis | None, pieces: tuple[str, ...], warn: Callable[[str], None] | None,
              say: Callable[[str], None] = _silent
              ) -> tuple[Analysis | None, list[Drawing], MachineDynamics | None]:
    """The drawings of ``pieces`` laid out, ``warn`` told first of each outcome a user should not miss (a machine
    that stalls, a drawing too small to read); with the analysis as they tell it (:func:`_as_drawn`) and the
    machine's dynamics, which the results, the plots and the note take."""
    # The model, the flywheel and the integrated motion serve the results, the drawing, the plot and the note,
    # which tells all the scene has whichever drawings are asked for.
    explained = "note" in pieces and missing(scene, analysis, "dynamics") is None
    dynamics = _dynamics_of(scene, analysis, None) if "dynamics" in pieces or explained else None
    if warn is not None:
        for told in outcome_warnings(scene, pieces, dynamics) + scale_warnings(analysis, pieces):
            warn(told)
    made = drawings(scene, analysis, pieces, dynamics, say=say)
    return _as_drawn(analysis, made), made, dynamics


def _as_drawn(analysis: Analysis | None, made: list[Drawing]) -> Analysis | None:
    """``analysis`` with the readings measured on the polygons ``made`` draws larger than the record, or on the
    arrows of its groups cut free, told for what they are: known only once those are drawn."""
    larger: dict[int, tuple[SheetPolygons, ...]] = {}
    for drawing in made:
        for number, polygons in drawing.larger_polygons:
            larger[number] = (*larger.get(number, ()), polygons)
    if analysis is None or not larger:
        return analysis
    from .analysis import read_off_sheets

    return read_off_sheets(analysis, larger)


def balancing_document(scene: Scene) -> dict[str, Any]:
    """``results.json``'s ``balancing``: each correction plane's mass-radius product and angle (its mass where the
    scene gives the radius), the unbalance before and after, rounded as the results file rounds every number."""
    from .report.results import rounded
    from .rotor_balancing import balance, balancing_results

    assert scene.balancing is not None
    return rounded(balancing_results(balance(scene.balancing)))


def vibration_document(scene: Scene) -> dict[str, Any]:
    """``results.json``'s ``vibration``: the amplitude, phase, transmissibility and what follows from them, rounded
    as the results file rounds every number."""
    from .report.results import rounded
    from .vibration import vibration_results

    assert scene.vibration is not None
    return rounded(vibration_results(scene.vibration))


def scale_warnings(analysis: Analysis | None, pieces: tuple[str, ...]) -> list[str]:
    """A line for each scale the scene gives that draws one of the drawings of ``pieces`` too small to read."""
    if analysis is None or not {"positions", "velocity", "acceleration", "forces", "lever", "sheets"} & set(pieces):
        return []
    from .render.drawings import below_reading

    return below_reading(analysis)


# The lengths a ruler reads a plan to, in mm: a precision outside them is a slip of the unit (5 for 0.5) that spoils the
# drafting column and, through the measured-far-off threshold (twice it), hides misread lengths.
SENSIBLE_DRAFTING_PRECISION = (0.05, 2.0)


def drafting_precision_warnings(scene: Scene) -> list[str]:
    """A line where the scene's ``drafting_precision`` is outside what a ruler reads, as a force_scale that draws a
    polygon too small to read is told: drawn as asked, but said."""
    from .misreadings import FAR_OFF_PRECISIONS

    precision = scene.drawing.drafting_precision
    least, most = SENSIBLE_DRAFTING_PRECISION
    if least <= precision <= most:
        return []
    effect = (f"every length read off a plan is rounded to {precision:g} mm and a hand reading is far off only "
              f"beyond {FAR_OFF_PRECISIONS * precision:g} mm" if precision > most
              else "finer than a ruler reads, the drafting column shows next to no error")
    return [(f"drawing.drafting_precision: {precision:g} mm is outside what a ruler reads ({least:g} to {most:g} mm): "
             f"{effect}; give 0.5 (a ruler read to half a millimetre)")]


def outcome_warnings(scene: Scene, pieces: tuple[str, ...], dynamics: MachineDynamics | None) -> list[str]:
    """A line for each outcome of ``pieces`` that the files record but a user should not miss: a machine that
    stalls or never settles, a rotor left a couple, a speed near resonance; ``check`` tells them as ``run`` does."""
    from .scene import guides_without_angle, links_without_mass

    told = guides_without_angle(scene) + links_without_mass(scene)
    if scene.dynamics is not None and ("dynamics" in pieces or "note" in pieces):
        from .flywheel import (
            crank_omega,
            delta_warning,
            gear_warning,
            rotor_inertia_warning,
            speed_unit_warning,
            speed_warnings,
            synchronous_warning,
        )

        crank = crank_omega(scene.driver)
        told += [line for line in (delta_warning(scene.dynamics), speed_unit_warning(scene.dynamics, crank),
                                   synchronous_warning(scene.dynamics), gear_warning(scene.dynamics, crank),
                                   rotor_inertia_warning(scene.dynamics,
                                                         dynamics is not None and dynamics.asks_kilowatts(), crank))
                 if line is not None] + speed_warnings(scene.dynamics)
    if dynamics is not None:
        told += [line for line in (dynamics.stall_warning(), dynamics.slipping_warning(),
                                   dynamics.unsettled_warning(), dynamics.off_design_warning()) if line is not None]
    if "balancing" in pieces:
        from .rotor_balancing import balance, cautions

        assert scene.balancing is not None
        told += [f"balancing: {found.detail}" for found in cautions(balance(scene.balancing))]
    if "sheets" in pieces:
        from .render.title_block import SMALLEST_LETTERING, cramped, details_of, form_of, labels

        form = form_of(scene.locale)
        shorter = {"author": " to a surname and initials", "checked_by": " to a surname and initials",
                   "approved_by": " to a surname and initials",
                   "date": " (a TOML date, 2026-12-01, is written as the title block writes dates)"}
        # The title is the scene's; the rest is the project's.
        table_of = {"title": "scene"}
        # A date the block writes as the form writes dates (a TOML date; in ESKD's 10 mm column dd.mm.yy, also of a
        # dd.mm.yyyy typed as text) is not the user's to shorten.
        details = details_of(scene.project, scene.title, form)
        # Written down to the hundredth: 1.797 mm written "1.8 mm" beside "no smaller than 1.8 mm" read as no slip.
        told += [f"{table_of.get(name, 'project')}.{name}: the title block's box sets it at "
                 f"{math.floor(size * 100.0) / 100.0:g} mm to fit it "
                 f"in (printed letters are no smaller than {SMALLEST_LETTERING:g} mm); shorten it{shorter.get(name, '')}"
                 for name, size in cramped(details, form, labels(scene.locale)).items()
                 if name != "date" or details.date == scene.project.date]
    if "errors" in pieces or "note" in pieces:
        told += drafting_precision_warnings(scene)
    if "vibration" in pieces:
        from .vibration import (
            damping_warning,
            isolation_warning,
            lengths_warning,
            resonance_warning,
            speed_warning,
            stiffness_warning,
        )

        assert scene.vibration is not None
        told += [line for line in (damping_warning(scene.vibration), stiffness_warning(scene.vibration),
                                   speed_warning(scene.vibration),
                                   lengths_warning(scene.vibration),
                                   resonance_warning(scene.vibration), isolation_warning(scene.vibration))
                 if line is not None]
    return told


def files(scene: Scene, analysis: Analysis | None, pieces: tuple[str, ...],
          formats: tuple[str, ...] = ("svg",), warn: Callable[[str], None] | None = None,
          say: Callable[[str], None] = _silent,
          checked: Callable[[Analysis], None] | None = None) -> dict[str, str | bytes]:
    """Every file of the run: ``results.json``, the drawings in ``formats``, the tables and the plots.

    ``warn`` is told, in a line, of an outcome the files record but a user should not miss (a machine
    that stalls); ``say`` of each stage as it begins, so that a long run's progress line names the piece
    it is making (a note of 20 000 positions takes a minute), not the first of them; ``checked`` of the
    analysis as the files tell it, where the course sheets drawn change what it says of the hand readings
    (:func:`~graphplan.analysis.read_off_sheets`)."""
    from .report.plot_style import PLOT_DPI
    from .report.results import dumps

    found: dict[str, str | bytes] = {"results.json": ""}  # written first, once the sheets have said what they drew
    lever_scales: dict[str, float] = {}
    told, made, dynamics = _laid_out(scene, analysis, pieces, warn, say)
    if told is not analysis:
        analysis = told
        if checked is not None:
            checked(analysis)
    say("writing the results")
    found["results.json"] = dumps(document(scene, analysis, pieces, dynamics))
    shown_in_parts = {f"{drawing.stem}.svg": drawing.shows for drawing in made if drawing.shows}
    if made:
        say("writing the drawings")
    # By the force sheet's file, whether it is written or not: the note works its lever at that file's μV.
    sheet_levers = {_file_alone(lever.drawing): (lever.sheet, lever.scale) for drawing in made
                    for lever in drawing.levers}
    from .render.export import Rendering, rendered_all

    renderings: dict[str, Rendering] = {}
    for drawing in made:
        for name, content in _encodings(drawing, [kind for kind in formats if kind in DRAWING_FORMATS]).items():
            if isinstance(content, Rendering):
                renderings[name] = content
            else:
                found[name] = content
        if drawing.lever_scale is not None:
            lever_scales[f"{drawing.stem}.svg"] = drawing.lever_scale
    plots = figures(scene, analysis, pieces, dynamics, say=say)
    if "accuracy" in pieces and analysis is not None:
        say("studying the accuracy")
        plots.update(accuracy_report(analysis))
    found.update(plots)
    # A report takes its plots as PNG or PDF as it takes the drawings; DXF, a drafting format, is for the drawings.
    # Their PNG at a print's 300 dpi (a plot some 0.2 MB, a few tenths of a second more than at 150); the sheets keep
    # the export's 150, an A1 sheet at 300 dpi being 70 million pixels.
    for name, svg in plots.items():
        if name.endswith(".svg"):
            renderings.update({f"{name[:-4]}.{kind}": Rendering(svg, kind, PLOT_DPI if kind == "png" else None)
                            for kind in formats if kind in ("png", "pdf")})
    if renderings:
        say("rendering the drawings and plots as " + " and ".join(kind for kind in formats if kind in ("png", "pdf")))
        found.update(rendered_all(renderings))
    # The note shows the drawings and plots written beside it, each in the section it illustrates.
    pictures = {name: str(text) for name, text in found.items() if name.endswith(".svg")}
    if {"note", "errors", "forces"} & set(pieces):
        say("writing the note and the tables" if "note" in pieces else "writing the tables")
    found.update(tables(scene, analysis, pieces, dynamics, pictures=tuple(pictures), lever_scales=lever_scales,
                        shown_in_parts=shown_in_parts, sheet_levers=sheet_levers))
    if "pdf" in formats and "note.html" in found:
        from .report.pdf import note_pdf

        say("typesetting the note as pdf")
        found["note.pdf"] = note_pdf(str(found["note.html"]), pictures)
    if "docx" in formats and "note.md" in found:
        from .render.export import CAIRO, tool_for

        tool_for("docx", "docx")
        if pictures:  # the figures go into the document as PNG
            tool_for("docx", CAIRO)
        from .report.markdown import user_texts
        from .report.word import note_docx

        say("writing the note as docx")
        found["note.docx"] = note_docx(str(found["note.md"]), scene.title, scene.locale, pictures,
                                       author=scene.project.author, verbatim=user_texts(scene))
    return found


def accuracy_report(analysis: Analysis) -> dict[str, str]:
    """Each method's error against the 50-digit reference and its run time: table (Markdown, LaTeX), CSV and plot."""
    from pathlib import PurePath

    from .accuracy import study
    from .report import accuracy
    from .report.latex import latex_fragment
    from .report.markdown import user_texts

    scene = analysis.scene
    found = study(scene, PurePath(scene.source).stem)
    text = accuracy.markdown(found, scene.locale, scene.title)
    return {"accuracy.md": text, "accuracy.tex": latex_fragment(text, scene.locale, user_texts(scene)),
            "accuracy.csv": accuracy.csv_text(found.rows),
            "accuracy.svg": accuracy.figure(found, scene.locale, scene.title)}


__all__ = ["DRAWING_FORMATS", "FORMATS", "PIECES", "Drawing", "balancing_document", "check_formats", "chosen",
           "document", "drawings", "files", "missing", "results_document", "svg_files", "tells_diagrams",
           "vibration_document", "vibration_figures"]
