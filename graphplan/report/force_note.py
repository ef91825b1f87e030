"""The note's section on the force analysis: for each plan position the loads worked out (weights, d'Alembert's
inertia forces and moments), each group's moment equations and force polygon, the reactions, the balancing
load by the polygons and on Zhukovsky's lever, and the friction loads; then the balancing load over the cycle
and, with friction, the efficiency over it.

It is written by the note's own writer (:mod:`graphplan.report.note`), whose numbering, tables, language and
plan letters it shares; the tables are those ``forces.md`` prints (:mod:`graphplan.report.forces`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from typing import Protocol

import numpy as np

from .. import load_diagrams, settling
from ..analysis import Analysis, PlanPosition
from ..locale import Count
from ..mechanism import Mechanism
from ..plans import Plan
from ..render.force_lever import enlarged_lever_scale
from ..render.force_polygons import too_short_to_draw
from ..render.numerals import power_of_ten
from ..render.plans import ZERO_MM
from ..scales import format_scale
from ..wording import balancing_load
from . import forces as force_report
from .forces import ROUNDING
from .machine_note import Writer as SectionWriter


class Writer(SectionWriter, Protocol):
    """What the force section needs of the note besides a section's words and numbers."""

    analysis: Analysis
    mechanism: Mechanism
    lever_scales: Mapping[str, float]

    def captioned(self, caption: str, table_lines: list[str]) -> None: ...
    def product(self, *factors: str) -> str: ...
    def with_sense(self, value: float) -> str: ...
    def mm(self, value: float) -> str: ...
    def on_plan(self, millimetres: float) -> str: ...
    def enclosed(self, number: str) -> str: ...
    def letter(self, plan: Plan, letter: str) -> str: ...
    def segment(self, plan: Plan, start: str, end: str) -> str: ...


def forces_section(note: Writer, section: int) -> None:
    """Each plan position's force analysis, then the balancing load over the cycle where the scene asks for it."""
    note.heading(2, note.t("note_forces"), section)
    note.para(note.t("note_forces_intro", gravity=note.n(note.analysis.scene.gravity)))
    _load_diagrams(note)
    number = 0
    for plan in note.analysis.plans:
        if plan.forces is None:
            continue
        number += 1
        _forces_position(note, f"{section}.{number}", plan)
    if note.analysis.equilibrium is not None:
        number += 1
        name, _ = force_report.balancing_symbol(note.analysis)
        load = balancing_load(note.mechanism, note.text)
        note.heading(3, note.t("note_cycle", load=load), f"{section}.{number}")
        note.captioned(note.t("note_cycle_table", load=load, name=name, convention=_convention(note, name)),
                       force_report.cycle_lines(note.analysis, note.mark))
        for sentence in [*force_report.cycle_notes(note.analysis),
                         *force_report.locked_between_lines(note.analysis, note.mark),
                         *force_report.cycle_efficiency_lines(note.analysis, note.mark)]:
            note.para(sentence)
        note.figure("balancing.svg", note.t("note_cycle", load=load), lead="plot_lead")


def _load_diagrams(note: Writer) -> None:
    """The loads given over a stroke: each position's value read off its load diagram, which the force analysis
    takes there (the plan positions' on their force sheets), and the diagrams' figure."""
    if load_diagrams.unavailable(note.analysis) is not None:
        return
    text = note.text
    numbers = [str(plan.number) for plan in note.analysis.plans if plan.forces is not None]
    plans = text["enumeration"].join(numbers)
    for diagram in load_diagrams.of_analysis(note.analysis):
        names = text["enumeration"].join(load.name for load in diagram.loads)
        if diagram.translating:
            symbol = note.t("ld_travel_translating", point=diagram.point or diagram.link)
            travel = note.t("ld_travel_axis_translating", symbol=symbol)
            coordinates = diagram.coordinates
        else:
            symbol = note.t("ld_travel_turning", link=diagram.link)
            travel = note.t("ld_travel_axis_turning", symbol=symbol)
            coordinates = np.degrees(diagram.coordinates)
        unit = text["newton"] if diagram.kind == "force" else text["newton_metre"]
        given = text["semicolon"].join(_given(note, load, unit) for load in diagram.loads)
        note.para(note.t("note_ld_intro", link=diagram.link, given=given, symbol=symbol, plans=plans or "—",
                         count=Count(len(numbers))))
        header = [text["column_position"], text["note_ld_stroke"], travel, text["note_ld_share"],
                  *(f"{load.name}, {unit}" for load in diagram.loads)]
        rows = []
        # The strokes named as the positions' headings, the strokes paragraph and the kinematic diagrams name
        # them, working and idle, not by the link's sense of motion (a piston's "backward" working stroke); those
        # of a link other than the working link named with it.
        working = note.analysis.scene.positions.working
        own = working is not None and working.link == diagram.link
        for k, number in enumerate(diagram.numbers):
            _, share = diagram.stroke_at(k)
            stroke = text["working_stroke" if diagram.in_reference[k] else "idle_stroke"]
            if not own:
                stroke = note.t("ld_stroke_of_link", stroke=stroke, link=diagram.link)
            rows.append([str(number), stroke, note.n(float(coordinates[k]), 4),
                         note.n(share, 4), *(note.n(float(load.values[k])) for load in diagram.loads)])
        note.table(note.t("note_ld_table", names=names, link=diagram.link), header, rows, "llrr" + "r" * len(diagram.loads))
    note.figure("load_diagrams.svg", text["ld_title"], lead="plot_lead")


def _given(note: Writer, load: load_diagrams.DrawnLoad, unit: str) -> str:
    """How the scene gives a load of a load diagram: by a diagram of its own, or as one value over a stroke or a
    window of it, which the diagram draws as a rectangle; the note called every one a diagram the scene gave."""
    spec = load.spec
    if spec.diagram is not None:
        return note.t("note_ld_given_diagram", name=load.name)
    value = note.n(abs(spec.value) if spec.resisting else spec.value)
    if isinstance(spec.during, str):
        return note.t(f"note_ld_given_{spec.during}", name=load.name, value=value, unit=unit)
    start, end = spec.during
    return note.t("note_ld_given_window", name=load.name, value=value, unit=unit, start=note.n(start),
                  end=note.n(end))


def _forces_position(note: Writer, section: str, plan: PlanPosition) -> None:
    text, analysis = note.text, note.analysis
    note.heading(3, note.t("position_heading", number=plan.number), section)
    if table := force_report.initial_data_lines(analysis, plan, note.mark):
        note.para(note.text["note_loads_formulas"])
        note.captioned(note.t("note_loads_table", number=plan.number), table)
    details = []
    for row in force_report.initial_data(analysis, plan):
        parts = []
        if row.mass > 0:
            parts.append(f"G{row.link} = m{row.link}·g = {note.product(note.n(row.mass), note.n(row.gravity))} = "
                         f"{note.n(row.weight)} {text['newton']}")
            parts.append(f"Fu{row.link} = m{row.link}·aS{row.link} = "
                         f"{note.product(note.n(row.mass), note.n(row.centre_acceleration))} = "
                         f"{note.n(row.inertia_force)} {text['newton']}")
        if row.inertia > 0 and row.epsilon != 0:
            moment = (f"Mu{row.link} = J{row.link}·ε{row.link} = "
                      f"{note.product(note.n(row.inertia), note.n(abs(row.epsilon)))} = "
                      f"{note.n(row.inertia_moment)} {text['newton_metre']}")
            moment += note.with_sense(-row.epsilon)
            parts.append(moment)
        # [forces] inertia = "displaced": Fu's line is off the centre, which the arms of the moment equations and the
        # lever's point of Fu measure from; a reader told "Fu at the centre of mass" would measure them from S.
        displaced = next((load for load in plan.loads if load.name == f"Fu{row.link}" and load.offset != 0), None)
        if displaced is not None:
            parts.append(note.t("note_inertia_displaced", link=row.link, centre=row.centre,
                                moment=note.n(row.inertia_moment), force=note.n(row.inertia_force),
                                shift=note.n(abs(complex(displaced.offset)))))
        if parts:
            details.append(f"- {note.t('note_link', link=row.link)}{note.text['colon']}"
                           + note.text["semicolon"].join(parts))
    if details:
        note.para(*details)
    external = force_report.external_load_lines(analysis, plan, note.mark)
    if external:
        note.para(*external)
    for group in plan.forces.groups:
        _force_group(note, plan, group)
    note.captioned(note.t("note_reactions_table", number=plan.number),
                   force_report.reaction_lines(analysis, plan, note.mark))
    _balancing(note, plan)
    note.figure(f"forces_{plan.number}.svg", note.t("tb_sheet_forces_position", number=plan.number))
    if plan.with_friction is not None:
        lines = force_report.friction_lines(analysis, plan, note.mark)
        note.para(f"**{text['forces_friction']}{text['full_stop']}** " + " ".join(lines))
        if not plan.with_friction.locked:
            _friction_loads(note, plan)
            # The same writer as without friction, given the records of the last construction with friction: each
            # group's moment equations and polygon with the pairs' friction loads among its loads.
            for group in plan.with_friction.groups:
                _force_group(note, plan, group, friction=True)
            # Checked as the polygons without friction are: against every equilibrium equation with friction at once.
            if analysis.with_friction is not None:
                note.captioned(note.t("note_friction_reactions_table", number=plan.number),
                               force_report.friction_reaction_lines(analysis, plan, note.mark))
            _friction_lever(note, plan)
            note.figure(f"forces_friction_{plan.number}.svg",
                        note.t("tb_sheet_forces_friction_position", number=plan.number))


def _friction_loads(note: Writer, plan: PlanPosition) -> None:
    """How the friction loads were found (the construction repeated until the reactions settle), and each pair's
    friction load worked out at the settled reactions."""
    text, rubbing = note.text, plan.with_friction
    note.para(_settling(note, rubbing.iterations))
    lines = []
    for row in force_report.friction_load_rows(note.analysis, plan):
        pair, where, name = row.pair, row.where, row.name
        if not row.moving:
            moved = "note_friction_not_sliding" if pair.sliding else "note_friction_not_turning"
            lines.append(f"- {note.t(moved, name=name, first=pair.source, second=pair.target)}")
            continue
        if pair.sliding:
            # f of a flat guide as given; f′ = f/sin θ of a V-guide, the coefficient reduced
            symbol, reduced = "f", ""
            if pair.in_vee:
                symbol = "f′"
                reduced = f" = f/sin θ = {note.n(pair.spec.f)}/sin {note.n(math.degrees(pair.spec.groove_half_angle))}°"
            # The friction angle, as the force sheet gives it: the normal reaction and Ff lean together by φ.
            angle = f"φ = {text['arctangent']} {symbol}{where} = {note.n(math.degrees(math.atan(row.factor)))}°"
            lines.append(f"- {symbol}{where}{reduced} = {note.n(row.factor)}{text['semicolon']}{name} = "
                         f"{symbol}{where}·{pair.reaction} = {note.product(note.n(row.factor), note.n(row.reaction))}"
                         f" = {note.n(row.value)}{_direction(note, row.acting)} {text['newton']}{text['semicolon']}"
                         f"{angle}")
        else:
            lines.append(f"- ρ{where} = f·r = {note.product(note.n(pair.spec.f), note.n(pair.spec.radius))} = "
                         f"{note.n(row.factor)} {text['unit_m']}{text['semicolon']}{name} = "
                         f"ρ{where}·{pair.reaction} = {note.product(note.n(row.factor), note.n(row.reaction))} = "
                         f"{note.n(row.value)} {text['newton_metre']}{note.with_sense(row.acting.real)}")
    note.para(note.t("note_friction_loads"), *lines)
    if both := _both_links(note, plan):
        note.para(both)


def _settling(note: Writer, solves: int) -> str:
    """What settling.settle did: the construction repeated, each time with the friction loads of the reactions the
    last one found, from those without friction; or, where that had not settled after its most repetitions, the
    friction brought in by shares with Newton's method."""
    if solves <= settling.MAX_ITERATIONS:
        return note.t("note_friction_passes", passes=Count(solves), tolerance=power_of_ten(settling.CONVERGED, 1))
    return note.t("note_friction_shares", most=settling.MAX_ITERATIONS, shares=settling.SHARE_STEPS, solves=Count(solves))


def _both_links(note: Writer, plan: PlanPosition) -> str:
    """That a pair's friction load acts back on its other link, named with the links swapped (Mf65 = −Mf56), as the
    groups' equations take it on the link each group holds; said with the first pair whose load back is in them."""
    acting = {load.name for group in plan.with_friction.groups for load in group.loads}
    for pair in note.analysis.friction:
        on_target, on_source = pair.load_names
        if on_source in acting:
            return note.t("note_friction_both_links", load=on_target, back=on_source, link=pair.source)
    return ""


def _friction_lever(note: Writer, plan: PlanPosition) -> None:
    """Zhukovsky's lever with the friction loads, against the polygons with friction."""
    rubbing = plan.with_friction
    lever = plan.lever_with_friction
    name, unit = force_report.balancing_symbol(note.analysis)
    note.para(note.t("note_friction_lever", name=name, value=note.n(lever.balancing), unit=unit,
                     difference=force_report.percent(lever.balancing, rubbing.balancing, note.mark)))


def _direction(note: Writer, force: complex) -> str:
    """`` ∠ 180°`` after a friction force's size: which way it acts along the slide, against the sliding, as the
    note writes the external loads' directions; nothing for a force of rounding noise, which has none."""
    if not abs(force) > force_report.ROUNDING_NOISE:
        return ""
    return f" {force_report.direction(force, note.mark)}"


def _force_group(note: Writer, plan: PlanPosition, group, friction: bool = False) -> None:
    """A group's moment equations, polygon and reactions, of the analysis without friction or (``friction``) of the
    last construction with it, whose loads hold the pairs' friction loads."""
    text = note.text
    driver = group.label.startswith("I(")
    # With friction the headings and captions say so: the same group is worked out twice in a position.
    kind = "_friction" if friction else ""
    key = "note_driver_forces" if driver else "note_group_forces"
    note.para(f"**{note.t(key + kind, group=group.label)}**")
    whole = next((equation for equation in group.moments if equation.links), None)
    if whole is not None:  # a triad: about Assur's point, through which two unknown lines pass
        note.para(_assur_point(note, group, whole))
    if group.projections:
        note.para(note.t("note_slot_projections"), *(f"- {_projection(note, equation)}" for equation in group.projections))
    loads = {load.name: load for load in group.loads}
    lines = []
    for equation in group.moments:
        line = f"- {_moment_equation(note, equation, loads, group)}"
        if reaction := group.held_as_couple_alone(equation):
            line += note.text["semicolon"] + note.t("note_couple_alone", name=reaction)
        lines.append(line)
    if lines:
        note.para(note.t("note_moment_equations"), *lines)
    polygon = group.polygon
    scale = group.scale
    # Two unknowns of known lines are found where those lines cross; a single unknown, the polygon's last side,
    # closes it from its end back to its start, with no line of action drawn for it.
    crossed = {line.label for line in polygon.lines}
    rows = []
    for vector in polygon.vectors:
        force = vector.force
        role = "closes" if vector.role == "closing" and vector.name not in crossed else vector.role
        length, words = note.mm(abs(force) / scale), note.text[f"note_role_{role}"]
        # The drawing leaves out a vector shorter than ZERO_MM (a link's inertia force of a hundredth of a newton
        # at μF = 10 N/mm): the table says so beside its value in newtons, not "0.00 mm, laid off".
        if too_short_to_draw(force, scale):
            least = note.n(ZERO_MM)
            length = "—"
            words = note.t("note_role_load_short", least=least) if role == "load" else \
                words + text["semicolon"] + note.t("note_role_short", least=least)
        rows.append([vector.name, force_report.polar(force, note.mark), length, words])
    sums = _polygon_sums(note, group)
    note.para(note.t("note_polygon", equation=text["separator"].join(polygon.equations), scale=note.n(scale),
                     unit=text["unit_force_scale"])
              + (" " + note.t("note_polygon_sums", sums=sums) if sums else "")
              + " " + note.t("note_polygon_table_lead", number=note.next_table))
    header = [note.t("column_force"), f"{note.t('column_value')}{text['comma']}{text['newton']} ∠",
              f"{note.t('column_length')}{text['comma']}{text['millimetre']}", note.t("column_role")]
    caption = note.t(("note_polygon_table_driver" if driver else "note_polygon_table") + kind, group=group.label,
                     number=plan.number)
    note.table(caption, header, rows, "lrrl", lead=None)
    if group.found:
        found = note.text["semicolon"].join(f"{item.name} = {force_report.polar(item.force, note.mark)} {text['newton']}"
                          for item in group.found)
        note.para(note.t("note_found", reactions=found))


def _assur_point(note: Writer, group, whole) -> str:
    """Which point the whole triad's moment equation is taken about and how it is found: where the lines of the two
    unknowns the polygon closes on cross, each named with its own line (a turning leg's part along the leg, R34n
    along CD; a sliding leg's guide reaction square to its guide at the slider's pin; a slotted leg's part of its
    block's reaction square to the slot); a guide reaction's shift along its guide, where it has one, with it."""
    triad = next(unit.solver for unit in note.mechanism.units if getattr(unit.solver, "label", None) == group.label)
    closing = [vector.name for vector in group.polygon.vectors if vector.role == "closing"]
    found = {reaction.name: reaction for reaction in group.found}

    def line_of(name: str) -> str:
        # A turning or slotted leg's unknown is a part of its reaction (R34n), a sliding leg's the whole (R15).
        reaction = found.get(name) or found[name.removesuffix("n")]
        leg = next(n for n, (_, _, link) in enumerate(triad.arms()) if link == reaction.target)
        outer, inner, link = triad.arms()[leg]
        if triad.leg_guides[leg] is not None:
            return note.t("note_assur_force_guide", name=name, link=link, pin=inner)
        if leg in triad.slotted_legs:
            return note.t("note_assur_force_slot", name=name, pin=outer, link=triad.ternary)
        return note.t("note_assur_force_leg", name=name, line=f"{outer}{inner}")

    sentence = note.t("note_assur_forces", point=whole.about, unknown=whole.unknown, first=line_of(closing[0]),
                      second=line_of(closing[1]), closing=note.text["enumeration"].join(closing))
    for term in whole.terms:
        # A guide's reaction off its slider's pin (R·x ≠ 0): its moment about Σ, known, is in the equation.
        if term.name.endswith("·x"):
            name = term.name.removesuffix("·x")
            reaction = found[name]
            sentence += " " + note.t("note_assur_force_shift", name=name, pin=reaction.joint, link=reaction.target,
                                     point=whole.about)
    return sentence


def _projection(note: Writer, equation) -> str:
    """ΣFτ(5) = R35τ + G5τ + Fu5τ = R35τ − 11.77 + 3.1 = 0 ⇒ R35τ = 8.67 N."""
    names = "".join(f" + {name}τ" for name, _ in equation.components)
    values = "".join(f" {'−' if value < 0 else '+'} {note.n(abs(value))}" for _, value in equation.components)
    return (f"ΣFτ({equation.link}) = {equation.unknown}{names} = {equation.unknown}{values} = 0 ⇒ "
            f"{equation.unknown} = {note.n(equation.value)} {note.text['newton']}")


def _polygon_sums(note: Writer, group) -> str:
    """``ΣF5 = G5 + Fu5; ΣF6 = G6 + Fu6 + F6 + Ff16``: the forces each ΣF of the polygon's equations lays off, the
    reactions handed back and the pairs' friction forces among them, as the polygon's table lists them."""
    sums = []
    for link in dict.fromkeys(int(found) for found in re.findall(r"ΣF(\d+)", group.polygon.equation)):
        names = [load.name for load in group.loads if load.link == link and load.is_force and load.force != 0]
        if names:
            sums.append(f"ΣF{link} = {' + '.join(names)}")
    return note.text["semicolon"].join(sums)


def _moment_equation(note: Writer, equation, loads: Mapping[str, object], group=None) -> str:
    """ΣMB(3) = −R23τ·0.55 − 34.254 + 39.287 + 9.34 = 0 ⇒ R23τ = … with every load's moment F·h."""
    text = note.text
    total = sum(term.moment for term in equation.terms)
    couple = equation.unknown.startswith("M") or "·" in equation.unknown
    unit = text["newton_metre"] if couple else text["newton"]
    # A moment of the plan's rounding (an inertia moment of a crank at constant speed) is not written.
    size = max([abs(term.moment) for term in equation.terms] + [abs(equation.value * equation.arm)])
    shown = [term for term in equation.terms if abs(term.moment) > ROUNDING * size]
    parts = []
    for term in shown:
        load = loads.get(term.name)
        force = getattr(load, "force", 0j) if load is not None and getattr(load, "is_force", False) else None
        if force is not None and term.arm:
            parts.append(f"M({term.name}) = {_sign(term.moment)}{term.name}·h = "
                         f"{_sign(term.moment)}{note.product(note.n(abs(force)), note.n(term.arm, 4))} = "
                         f"{note.n(term.moment)} {text['newton_metre']}")
        else:
            parts.append(f"M({term.name}) = {note.n(term.moment)} {text['newton_metre']}")
    terms = "".join(f" {'−' if term.moment < 0 else '+'} {note.n(abs(term.moment))}" for term in shown)
    sum_text = note.n(total)
    # forces.md asks the same: both write a slide's equation as the shift x it finds.
    shift = force_report.shift(group, equation) if group is not None else None
    if shift is not None and shift.through:
        # A slide's normal reaction with no couple to carry: it passes through the moment centre, its joint.
        line = (f"ΣM{equation.about}({equation.bodies}) = {equation.unknown}{terms} = 0 ⇒ "
                + note.t("note_couple_through", name=shift.reaction, point=equation.about))
    elif shift is not None:
        # A slide's normal reaction off its joint by x, a length, as on the force sheet: R·x signed by its moment,
        # which balances the rest (a pin's friction moment Mf56 on the ram), and x its size over |R|.
        size, force = abs(shift.moment), shift.force
        line = (f"ΣM{equation.about}({equation.bodies}) = {_sign(equation.value)}{equation.unknown}{terms} = 0 ⇒ "
                f"{equation.unknown} = {note.n(size)} {unit}{text['comma']}x = {note.n(size)}/{note.n(force)} = "
                f"{note.n(shift.x)} {text['unit_m']} = {note.n(1000.0 * shift.x)} {text['millimetre']}")
    elif couple:
        line = (f"ΣM{equation.about}({equation.bodies}) = {equation.unknown}{terms} = 0 ⇒ "
                f"{equation.unknown} = {note.n(equation.value)} {unit}")
    else:
        lever = -total / equation.value if equation.value else equation.arm
        sign = "−" if lever < 0 else ""
        solved = f"{sum_text}/{note.n(equation.arm, 4)}" if lever < 0 else f"−({sum_text})/{note.n(equation.arm, 4)}"
        line = (f"ΣM{equation.about}({equation.bodies}) = {sign}{equation.unknown}·{note.n(equation.arm, 4)}{terms} = 0"
                f" ⇒ {equation.unknown} = {solved} = {note.n(equation.value)} {unit}")
        if equation.value < 0:
            line += " " + note.t("note_sense_reversed", name=equation.unknown)
    return note.text["semicolon"].join([*parts, line])


def _sign(value: float) -> str:
    return "−" if value < 0 else ""


def _convention(note: Writer, name: str) -> str:
    """The balancing load's sign convention, as forces.md states it: Mb counter-clockwise positive, Fb along the
    driving slider's guide."""
    return note.text["forces_sense_moment" if name == "Mb" else "forces_sense_force"]


def _balancing(note: Writer, plan: PlanPosition) -> None:
    text, analysis = note.text, note.analysis
    name, unit = force_report.balancing_symbol(analysis)
    driver = note.mechanism.driver
    polygons = plan.forces.balancing
    # The sign convention with the value: the dynamics' reduced moments, signed by their power, stand beside Mb.
    note.para(note.t("note_balancing_polygons", name=name, value=note.n(polygons, 6), unit=unit,
                     convention=_convention(note, name),
                     sense=note.with_sense(polygons) if driver.kind == "crank" else ""))
    lever = plan.lever
    if lever is not None:
        velocity = plan.velocity
        # As the force sheet beside the note draws it: a small sheet may draw it smaller than enlarged.
        drawn_at = (note.lever_scales.get(f"forces_{plan.number}.svg") or enlarged_lever_scale(velocity, lever)
                    or velocity.scale)
        rows = []
        total = 0.0
        largest = max((abs(term.moment) for term in lever.terms), default=0.0)
        strongest = max((abs(term.force) for term in lever.terms), default=0.0)
        for term in lever.terms:
            if abs(term.force) <= ROUNDING * strongest and abs(term.moment) <= ROUNDING * largest:
                continue  # a load of the plan's rounding: no load
            # a load whose line passes through the pole has no moment, whatever rounding says
            moment_mm = term.moment / drawn_at if abs(term.moment) > ROUNDING * largest else 0.0
            total += moment_mm
            point = note.letter(velocity, term.image) if term.image else "—"
            if term.image and term.shift:  # a displaced Fu acts at the image of its own point, off its link's
                link = term.name.removeprefix("Fu")
                point += f" + ω{link}·hu{link}"
            # The lever's sheet leaves out an arm shorter than a plan draws, as the plans leave out a vector.
            arm = note.on_plan(term.arm / drawn_at) if term.image else "—"
            force = note.n(abs(term.force)) if term.image else "—"
            rows.append([term.name, point, force, arm, note.n(moment_mm)])
        note.para(note.text["note_lever_intro"])
        for term in lever.terms:
            if not term.image and term.moment != 0:  # a block's moment: no two points of its own to put a couple on
                note.para(note.t("note_lever_block", name=term.name, link=term.link))
        if drawn_at != velocity.scale:
            scale = text["velocity_scale"].format(value=format_scale(drawn_at).replace(".", note.mark))
            note.para(note.t("note_lever_scale", scale=scale))
        header = [note.t("column_force"), note.t("column_point"), f"F, {text['newton']}",
                  f"h, {text['millimetre']}", f"F·h, {text['newton']}·{text['millimetre']}"]
        note.table(note.t("note_lever_table", number=plan.number), header, rows, "llrrr")
        pa = abs(velocity.value(driver.joint)) / drawn_at
        segment = note.segment(velocity, "p", velocity.images[driver.joint])
        force = abs(total) / pa if pa else math.nan
        # Fb as the lever drawings name it; the product of two magnitudes gives |Mb|, its sense after it.
        equation = (f"Fb = |Σ(F·h)|/{segment} = {note.n(abs(total))}/{note.mm(pa)} = {note.n(force)} "
                    f"{text['newton']}")
        if driver.kind == "crank":
            length = f"l{driver.pivot}{driver.joint}"
            equation += (f"{text['separator']}|{name}| = Fb·{length} = {note.product(note.n(force), note.n(driver.length))} = "
                         f"{note.n(abs(lever.balancing), 6)} {unit}{note.with_sense(lever.balancing)}")
            note.para(note.t("note_lever_result", load=balancing_load(note.mechanism, text, lower=True),
                             equation=equation))
        else:  # a slider's balancing load is the lever's force itself, signed: not named twice as if another load
            equation += f"{text['separator']}{name} = {note.n(lever.balancing, 6)} {unit}"
            note.para(note.t("note_lever_result_force", equation=equation))
        difference = lever.difference_percent(polygons)
        note.para(note.t("note_lever_difference", name=name, lever=note.n(lever.balancing, 6),
                         polygons=note.enclosed(note.n(polygons, 6)), delta=note.n(difference, 3)))
    note.captioned(note.t("note_balancing_table", load=balancing_load(note.mechanism, text), name=name,
                          number=plan.number),
                   force_report.balancing_lines(analysis, plan, note.mark))
