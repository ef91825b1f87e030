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
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from .. import load_diagrams, settling
from ..analysis import Analysis, PlanPosition
from ..lever import BALANCING_FORCE, Lever, LeverTerm
from ..locale import Count, load_symbol, load_symbols_in
from ..mechanism import Mechanism
from ..plans import Plan
from ..render.force_lever import enlarged_lever_scale
from ..render.force_marks import written_lever_scale
from ..render.force_polygons import too_short_to_draw
from ..render.numerals import power_of_ten
from ..render.plans import ZERO_MM
from ..wording import balancing_load
from . import forces as force_report
from .forces import ROUNDING
from .machine_note import Writer as SectionWriter


class Writer(SectionWriter, Protocol):
    """What the force section needs of the note besides a section's words and numbers."""

    analysis: Analysis
    mechanism: Mechanism
    lever_scales: Mapping[str, float]
    sheet_levers: Mapping[str, tuple[int, float]]

    def captioned(self, caption: str, table_lines: list[str]) -> None: ...
    def product(self, *factors: str) -> str: ...
    def with_sense(self, value: float) -> str: ...
    def mm(self, value: float) -> str: ...
    def on_plan(self, millimetres: float) -> str: ...
    def enclosed(self, number: str) -> str: ...
    def letter(self, plan: Plan, letter: str) -> str: ...
    def segment(self, plan: Plan, start: str, end: str) -> str: ...
    def reactions_named(self) -> str: ...
    found: dict[str, object]


@dataclass(frozen=True)
class LeverWords:
    """The locale's keys a worked Zhukovsky's lever is introduced, captioned and set against its polygons by."""

    intro: str
    table: str
    difference: str


# The lever without friction, and the one with the pairs' friction loads, which the sheet with friction draws: one
# worked table and equation each, in words that tell them apart.
PLAIN_LEVER = LeverWords("note_lever_intro", "note_lever_table", "note_lever_difference")
FRICTION_LEVER = LeverWords("note_friction_lever_intro", "note_friction_lever_table", "note_friction_lever_difference")

# How a worked lever's intro says its loads are put on it: a clause for each kind of load its table has a row of, in
# this order, so that a lever with no inertia moment, or with the friction of slides alone, names no Mu or Mf.  A
# couple's forces (Mu3′, Mu3″) stand at images; a block's moment, which has none, is told apart (note_lever_block).
LOADS_APPLIED = (("Mu", "note_lever_applied_inertia_moments"), ("Ff", "note_lever_applied_friction_forces"),
                 ("Mf", "note_lever_applied_friction_moments"))
_APPLIED_LOAD = re.compile(r"(Mu|Ff|Mf)\d+[′″]?")


def forces_section(note: Writer, section: int) -> None:
    """Each plan position's force analysis, then the balancing load over the cycle where the scene asks for it."""
    note.heading(2, note.t("note_forces"), section)
    intro = note.t("note_forces_intro", gravity=note.n(note.analysis.scene.gravity))
    named = note.reactions_named()
    note.para(f"{intro} {named}" if named else intro)
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
        note.captioned(note.t("note_cycle_table", load=load, name=name, convention=_convention(note)),
                       force_report.cycle_lines(note.analysis, note.mark))
        cycle = note.analysis.cycle
        if cycle is not None and not cycle.locked and cycle.without_friction != 0 and not cycle.loads_drive:
            # As the sentence on the cycle's works below writes η.
            note.found["efficiency"] = force_report.number(cycle.efficiency, 4, note.mark)
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
            weight, inertia_force = note.n(row.weight), note.n(row.inertia_force)
            parts.append(f"G{row.link} = m{row.link}·g = {worked_product(note, [row.mass, row.gravity], weight)} = "
                         f"{weight} {text['newton']}")
            parts.append(f"{load_symbol(f'Fu{row.link}', text)} = m{row.link}·aS{row.link} = "
                         f"{worked_product(note, [row.mass, row.centre_acceleration], inertia_force)} = "
                         f"{inertia_force} {text['newton']}")
        if row.inertia > 0 and row.epsilon != 0:
            inertia_moment = note.n(row.inertia_moment)
            moment = (f"{load_symbol(f'Mu{row.link}', text)} = J{row.link}·ε{row.link} = "
                      f"{worked_product(note, [row.inertia, abs(row.epsilon)], inertia_moment)} = "
                      f"{inertia_moment} {text['newton_metre']}")
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
                         f"{symbol}{where}·{pair.reaction} = "
                         f"{worked_product(note, [row.factor, row.reaction], note.n(row.value))}"
                         f" = {note.n(row.value)}{_direction(note, row.acting)} {text['newton']}{text['semicolon']}"
                         f"{angle}")
        else:
            lines.append(f"- ρ{where} = f·r = {worked_product(note, [pair.spec.f, pair.spec.radius], note.n(row.factor))} = "
                         f"{note.n(row.factor)} {text['unit_m']}{text['semicolon']}{name} = "
                         f"ρ{where}·{pair.reaction} = {worked_product(note, [row.factor, row.reaction], note.n(row.value))} = "
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
    """Zhukovsky's lever with the friction loads worked as the force sheet with friction draws it, against the
    polygons with friction."""
    _worked_lever(note, plan, plan.lever_with_friction, f"forces_friction_{plan.number}.svg",
                  plan.with_friction.balancing, FRICTION_LEVER)


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
    for equation, arms in zip(group.moments, group.arm_names, strict=True):
        line = f"- {_moment_equation(note, equation, loads, group, arms)}"
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
        rows.append([load_symbol(vector.name, text), force_report.polar(force, note.mark), length, words])
    sums = _polygon_sums(note, group)
    equations = text["separator"].join(load_symbols_in(equation, text) for equation in polygon.equations)
    note.para(note.t("note_polygon", equation=equations, scale=note.n(scale),
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
    names = "".join(f" + {load_symbol(name, note.text)}τ" for name, _ in equation.components)
    result = note.n(equation.value)
    values = _summed(note, [value for _, value in equation.components], result, lambda total: -total)
    return (f"ΣFτ({equation.link}) = {equation.unknown}{names} = {equation.unknown}{values} = 0 ⇒ "
            f"{equation.unknown} = {result} {note.text['newton']}")


# The most significant digits a number of a worked-out formula is written to: one more would be beyond the double's.
MOST_DIGITS = 15


def _read(note: Writer, written: str) -> float:
    return float(written.replace("−", "-").replace(note.mark, "."))


def reproducing(note: Writer, values: list[float], least: list[int], result: str, digits: int,
                combine) -> list[str]:
    """``values`` written for a formula whose printed arithmetic, ``combine`` of them as written, must give the result
    as written (``result``, to ``digits`` significant digits): each to its ``least`` significant digits, then a digit
    more at a time, each to the value whose digit brings the printed arithmetic nearest the exact one, until it does
    (1356.4/0.425 printed = 3191.5, not the −3191.7 found: 1356.35/0.42496).  Lengthening every value at once gave
    each the digits only one needed, and a formula worked from one so written more again (220.673322·0.56133356 where
    220.673·0.561334 reads 123.871)."""
    counts = list(least)
    written = [note.n(value, count) for value, count in zip(values, counts, strict=True)]
    try:
        exact = combine(*values)
        while note.n(combine(*(_read(note, text) for text in written)), digits) != result:
            lengthened = []
            for index, value in enumerate(values):
                # A digit that writes the value as before (0.003 to six digits) is no digit: the next that changes it.
                count = next((count for count in range(counts[index] + 1, MOST_DIGITS + 1)
                              if note.n(value, count) != written[index]), None)
                if count is not None:
                    trial = [*written[:index], note.n(value, count), *written[index + 1:]]
                    error = abs(combine(*(_read(note, text) for text in trial)) - exact)
                    lengthened.append((error, index, count, trial))
            if not lengthened:
                return written
            _, index, counts[index], written = min(lengthened, key=lambda option: option[:2])
    except (ValueError, ZeroDivisionError):  # a power of ten (2.1·10¹¹) or a nought: written as it is
        return written
    return written


def _summed(note: Writer, moments: list[float], result: str, solve, digits: int = 5) -> str:
    """`` − 34.254 + 39.287 + 9.34``: the terms of a sum, each signed, written to as many digits as make ``solve`` of
    their printed sum read ``result`` (to ``digits``)."""
    if not moments:
        return ""
    signs = [-1.0 if moment < 0 else 1.0 for moment in moments]
    sizes = [abs(moment) for moment in moments]
    # A sum is as exact as its terms' last decimal place, not their digits: the digit that brings it nearest goes to
    # the largest term, a smaller one's only once the largest reaches its place (1.303545 + 0.0024154).
    written = reproducing(note, sizes, [5] * len(sizes), result, digits,
                          lambda *printed: solve(sum(sign * size for sign, size in zip(signs, printed, strict=True))))
    return "".join(f" {'−' if sign < 0 else '+'} {size}" for sign, size in zip(signs, written, strict=True))


def _polygon_sums(note: Writer, group) -> str:
    """``ΣF5 = G5 + Fu5; ΣF6 = G6 + Fu6 + F6 + Ff16``: the forces each ΣF of the polygon's equations lays off, the
    reactions handed back and the pairs' friction forces among them, as the polygon's table lists them."""
    sums = []
    for link in dict.fromkeys(int(found) for found in re.findall(r"ΣF(\d+)", group.polygon.equation)):
        names = [load_symbol(load.name, note.text) for load in group.loads
                 if load.link == link and load.is_force and load.force != 0]
        if names:
            sums.append(f"ΣF{link} = {' + '.join(names)}")
    return note.text["semicolon"].join(sums)


def _moment_equation(note: Writer, equation, loads: Mapping[str, object], group,
                     arms: tuple[str | None, ...]) -> str:
    """ΣMB(3) = −R23τ·0.55 − 34.254 + 39.287 + 9.34 = 0 ⇒ R23τ = … with every load's moment F·h1, its arm named as
    the force sheet names it (``arms``, the group's :attr:`~graphplan.forces.GroupForces.arm_names` of the equation).

    Each number is written to as many digits as make the arithmetic as printed give the number printed after it:
    the reader who checks the note with a calculator finds its results.  So the result is written first, and the
    numbers it is worked out from after it, each as long as it needs."""
    text = note.text
    total = sum(term.moment for term in equation.terms)
    couple = equation.unknown.startswith("M") or "·" in equation.unknown
    unknown = load_symbol(equation.unknown, text)  # the driver's balancing moment Mb, as the locale writes it
    unit = text["newton_metre"] if couple else text["newton"]
    # A moment of the plan's rounding (an inertia moment of a crank at constant speed) is not written: the terms the
    # force sheet writes, whose arms it names.
    shown = list(equation.standing_terms)
    # A force the sheet names the arm of but no load of the group (the reactions' τ parts a triad's equation about
    # Assur's point adds) is written as F·h too, its size the one the sheet draws.
    named = {force.name: force.force for force in group.shown_forces}
    moments = [term.moment for term in shown]
    # forces.md asks the same: both write a slide's equation as the shift x it finds.
    shift = force_report.shift(group, equation)
    head = f"ΣM{equation.about}({equation.bodies})"
    if shift is not None and shift.through:
        # A slide's normal reaction with no couple to carry: it passes through the moment centre, its joint.
        terms = "".join(f" {'−' if moment < 0 else '+'} {note.n(abs(moment))}" for moment in moments)
        line = (f"{head} = {unknown}{terms} = 0 ⇒ "
                + note.t("note_couple_through", name=shift.reaction, point=equation.about))
    elif shift is not None:
        # A slide's normal reaction off its joint by x, a length, as on the force sheet: R·x signed by its moment,
        # which balances the rest (a pin's friction moment Mf56 on the ram), and x its size over |R|.
        x = note.n(shift.x)
        couple_text, force = reproducing(note, [abs(shift.moment), shift.force], [5, 5], x, 5,
                                         lambda moment, force: moment / force)
        digits = _digits(couple_text)
        terms = _summed(note, moments, couple_text, lambda total: abs(total), digits)
        line = (f"{head} = {_sign(equation.value)}{unknown}{terms} = 0 ⇒ "
                f"{unknown} = {couple_text} {unit}{text['comma']}x = {couple_text}/{force} = "
                f"{x} {text['unit_m']} = {note.n(1000.0 * shift.x)} {text['millimetre']}")
        moments_written = _written_terms(terms)
        return _one_a_line([*_moment_parts(note, shown, loads, moments_written, arms, named), line])
    elif couple:
        value = note.n(equation.value)
        terms = _summed(note, moments, value, lambda total: -total)
        line = f"{head} = {unknown}{terms} = 0 ⇒ {unknown} = {value} {unit}"
    else:
        value = note.n(equation.value)
        # sign·R·arm + Σ = 0: R = −Σ/(sign·arm), the arm written as the equation and the solution both write it.
        lever = -total / equation.value if equation.value else equation.arm
        sign = -1.0 if lever < 0 else 1.0
        sum_text, arm = reproducing(note, [abs(total), equation.arm], [5, 4], value, 5,
                                    lambda size, arm: -math.copysign(size, total) / (sign * arm))
        terms = _summed(note, moments, sum_text, lambda found: abs(found), _digits(sum_text))
        written_sum = f"−{sum_text}" if total < 0 else sum_text
        # −Σ/arm, or Σ/arm where the unknown stands with a minus: a negative Σ after a minus in brackets.
        solved = f"{written_sum}/{arm}" if sign < 0 else f"−{note.enclosed(written_sum)}/{arm}"
        line = (f"{head} = {'−' if sign < 0 else ''}{unknown}·{arm}{terms} = 0"
                f" ⇒ {unknown} = {solved} = {value} {unit}")
        if equation.value < 0:
            line += " " + note.t("note_sense_reversed", name=unknown)
    return _one_a_line([*_moment_parts(note, shown, loads, _written_terms(terms), arms, named), line])


def _one_a_line(parts: list[str]) -> str:
    """An equation's moments each on a line of its own within its item, the equation last: run on as one
    paragraph, a dozen M(·) = F·h = … broke mid-formula wherever the page's line ended."""
    return "\\\n  ".join(parts)


def worked_product(note: Writer, factors: list[float], result: str) -> str:
    """``6·1.1844``: the factors of a product the note writes as ``result``, each to as many digits as make their
    printed product read it (6·1.18440, not 6·1.1844 = 7.1061)."""
    written = reproducing(note, factors, [5] * len(factors), result, _digits(result),
                          lambda *printed: math.copysign(math.prod(printed), _read(note, result)))
    return note.product(*written)


def _digits(written: str) -> int:
    """The significant digits a number the note writes to five or more was written to: ``258.065``, six."""
    mantissa = written.split("·10")[0]
    figures = re.sub(r"\D", "", mantissa).lstrip("0")
    # A whole number's noughts at its end hold places, not digits: 405370 to five digits.
    return max(5, len(figures if "." in mantissa or "," in mantissa else figures.rstrip("0")))


def _written_terms(terms: str) -> list[str]:
    """The sizes of `` − 34.254 + 39.287`` as written: each term's moment is written so in its own M(·) too."""
    return terms.split()[1::2]


def _moment_parts(note: Writer, shown, loads: Mapping[str, object], written: list[str],
                  arms: tuple[str | None, ...], named: Mapping[str, complex]) -> list[str]:
    """``M(G3) = −G3·h1 = −166.77·0.2054 = −34.254 N·m``: each term's moment, written as the equation writes it, with
    its force and arm to as many digits as make their product read it, the arm by the name the force sheet letters
    it (``arms``, one for each term of ``shown``)."""
    parts = []
    for term, size, arm_name in zip(shown, written, arms, strict=True):
        moment = f"{_sign(term.moment)}{size}"
        symbol = load_symbol(term.name, note.text)
        load = loads.get(term.name)
        force = getattr(load, "force", 0j) if load is not None and getattr(load, "is_force", False) else None
        if force is None and arm_name is not None:
            force = named[term.name]
        if force is not None and term.arm:
            digits = _digits(size)
            magnitude, arm = reproducing(note, [abs(force), term.arm], [5, 4], size, digits,
                                         lambda force, arm: abs(force * arm))
            # A force the sheet draws no arrow for (a rounding error's beside the others) has no arm lettered there:
            # its arm stays a bare h, as the sheet writes its term M(F).
            parts.append(f"M({symbol}) = {_sign(term.moment)}{symbol}·{arm_name or 'h'} = "
                         f"{_sign(term.moment)}{note.product(magnitude, arm)} = {moment} {note.text['newton_metre']}")
        else:
            parts.append(f"M({symbol}) = {moment} {note.text['newton_metre']}")
    return parts


def _sign(value: float) -> str:
    return "−" if value < 0 else ""


def _convention(note: Writer) -> str:
    """The balancing load's sign convention, as forces.md states it: Mb counter-clockwise positive, Fb along the
    driving slider's guide."""
    return force_report.sense_of_balancing(note.mechanism, note.text)


def _balancing(note: Writer, plan: PlanPosition) -> None:
    text, analysis = note.text, note.analysis
    name, unit = force_report.balancing_symbol(analysis)
    driver = note.mechanism.driver
    polygons = plan.forces.balancing
    found = {"number": plan.number, "name": name, "unit": unit, "polygons": note.n(polygons, 6)}
    note.found.setdefault("balancing", []).append(found)
    # The sign convention with the value: the dynamics' reduced moments, signed by their power, stand beside Mb.
    note.para(note.t("note_balancing_polygons", name=name, value=note.n(polygons, 6), unit=unit,
                     convention=_convention(note),
                     sense=note.with_sense(polygons) if driver.kind == "crank" else ""))
    lever = plan.lever
    if lever is not None:
        difference = _worked_lever(note, plan, lever, f"forces_{plan.number}.svg", polygons, PLAIN_LEVER)
        found["lever"], found["delta"] = note.n(lever.balancing, 6), note.n(difference, 3)
    note.captioned(note.t("note_balancing_table", load=balancing_load(note.mechanism, text), name=name,
                          number=plan.number),
                   force_report.balancing_lines(analysis, plan, note.mark))


def _loads_applied(note: Writer, tabled: list[LeverTerm]) -> str:
    """What a lever's intro says of how the loads of its table's rows (``tabled``) are put on it: a clause for each
    kind of :data:`LOADS_APPLIED` among them at an image, nothing where there is none."""
    kinds = {found[1] for term in tabled if term.image and (found := _APPLIED_LOAD.fullmatch(term.name))}
    clauses = [note.t(key) for kind, key in LOADS_APPLIED if kind in kinds]
    return note.t("note_lever_applied", loads=note.text["semicolon"].join(clauses)) if clauses else ""


def _on_course_sheet(note: Writer, drawing: str, drawn_at: float, plan_scale: float) -> None:
    """Where a course sheet draws the lever of the force sheet ``drawing`` at another μV than ``drawn_at``, the one
    the note works it at (a small sheet draws it coarser to fit), which sheet, its μV there, and the factor that
    turns the table's arms into those a reader measures on that sheet."""
    found = note.sheet_levers.get(drawing)
    if found is None:
        return
    sheet, scale = found
    if math.isclose(scale, drawn_at, rel_tol=1e-9):
        return
    # Both μV as the drawings write them, so that the ratio reads off the two captions.
    worked, there = (written_lever_scale(value, plan_scale).replace(".", note.mark) for value in (drawn_at, scale))
    note.para(note.t("note_lever_on_sheet", sheet=sheet, scale=note.text["velocity_scale"].format(value=there),
                     ratio=f"{worked}/{there}", factor=note.n(drawn_at / scale, 4)))


def _worked_lever(note: Writer, plan: PlanPosition, lever: Lever, drawing: str, polygons: float,
                  words: LeverWords) -> float:
    """Zhukovsky's ``lever`` of ``plan`` worked as the force sheet ``drawing`` draws it: the table of its loads'
    moments, each arm named as the sheet letters it, Fb and the balancing load from them, and how far they part from
    the balancing load by the ``polygons``, which is returned (%)."""
    text = note.text
    name, unit = force_report.balancing_symbol(note.analysis)
    driver = note.mechanism.driver
    velocity = plan.velocity
    # As forces_N.svg, the figure the note shows, draws it: laid out alone whatever the sheet format (7da53bfe), so
    # that --sheet leaves the table as it is; a small course sheet may draw its own copy smaller, which the sentence
    # after the table tells (:func:`_on_course_sheet`).
    drawn_at = note.lever_scales.get(drawing) or enlarged_lever_scale(velocity, lever) or velocity.scale
    # Each arm by the name the sheet's lever letters it (h1, h2, hb), a shared arm's in each of its loads' rows; a
    # load the lever names no arm for (one with no moment, at the pole) keeps its length alone.
    arm_names = lever.arm_names(velocity, drawn_at, note.mechanism.scene.drawing.drafting_precision)
    rows = []
    tabled = []
    total = 0.0
    largest = max((abs(term.moment) for term in lever.terms), default=0.0)
    strongest = max((abs(term.force) for term in lever.terms), default=0.0)
    for term in lever.terms:
        if abs(term.force) <= ROUNDING * strongest and abs(term.moment) <= ROUNDING * largest:
            continue  # a load of the plan's rounding: no load
        tabled.append(term)
        # a load whose line passes through the pole has no moment, whatever rounding says
        moment_mm = term.moment / drawn_at if abs(term.moment) > ROUNDING * largest else 0.0
        total += moment_mm
        point = note.letter(velocity, term.image) if term.image else "—"
        if term.image and term.shift:  # a displaced Fu acts at the image of its own point, off its link's
            link = term.name.removeprefix("Fu")
            point += f" + ω{link}·{load_symbol(f'hu{link}', text)}"
        # The lever's sheet leaves out an arm shorter than a plan draws, as the plans leave out a vector.
        arm = note.on_plan(term.arm / drawn_at) if term.image else "—"
        if term.name in arm_names:
            arm = f"{load_symbol(arm_names[term.name], text)} = {arm}"
        force = note.n(abs(term.force)) if term.image else "—"
        rows.append([load_symbol(term.name, text), point, force, arm, note.n(moment_mm)])
    note.para(note.t(words.intro, sign=note.text["note_lever_sign"], applied=_loads_applied(note, tabled)))
    for term in lever.terms:
        if not term.image and term.moment != 0:  # a block's moment: no two points of its own to put a couple on
            note.para(note.t("note_lever_block", name=load_symbol(term.name, text), link=term.link))
    if drawn_at != velocity.scale:
        scale = text["velocity_scale"].format(value=written_lever_scale(drawn_at, velocity.scale).replace(".", note.mark))
        note.para(note.t("note_lever_scale", scale=scale))
    header = [note.t("column_force"), note.t("column_point"), f"F, {text['newton']}",
              f"h, {text['millimetre']}", f"F·h, {text['newton']}·{text['millimetre']}"]
    note.table(note.t(words.table, number=plan.number), header, rows, "llrrr")
    _on_course_sheet(note, drawing, drawn_at, velocity.scale)
    pa = abs(velocity.value(driver.joint)) / drawn_at
    segment = note.segment(velocity, "p", velocity.images[driver.joint])
    force = abs(total) / pa if pa else math.nan
    # Fb as long as |Mb| = Fb·l, written to six digits, needs it to read so; then |Σ(F·h)| and pa as long as Fb needs.
    moment = note.n(abs(lever.balancing), 6)
    if driver.kind == "crank":
        written_force, arm = reproducing(note, [force, driver.length], [5, 5], moment, 6,
                                         lambda force, arm: force * arm)
    else:
        written_force = note.n(force)
    moments, pole = reproducing(note, [abs(total), pa], [5, 5], written_force,
                                _digits(written_force), lambda moments, pole: moments / pole)
    # Fb as the lever drawings name it; the product of two magnitudes gives |Mb|, its sense after it.
    lever_force = load_symbol(BALANCING_FORCE, text)
    equation = f"{lever_force} = |Σ(F·h)|/{segment} = {moments}/{pole} = {written_force} {text['newton']}"
    if driver.kind == "crank":
        length = f"l{driver.pivot}{driver.joint}"
        equation += (f"{text['separator']}|{name}| = {lever_force}·{length} = {note.product(written_force, arm)} = "
                     f"{moment} {unit}{note.with_sense(lever.balancing)}")
        note.para(note.t("note_lever_result", load=balancing_load(note.mechanism, text, lower=True),
                         equation=equation))
    else:  # a slider's balancing load is the lever's force itself, signed: not named twice as if another load
        equation += f"{text['separator']}{name} = {note.n(lever.balancing, 6)} {unit}"
        note.para(note.t("note_lever_result_force", equation=equation))
    difference = lever.difference_percent(polygons)
    note.para(note.t(words.difference, name=name, lever=note.n(lever.balancing, 6),
                     polygons=note.enclosed(note.n(polygons, 6)), delta=note.n(difference, 3)))
    return difference
