"""The error tables of the plans, as Markdown for the report and CSV for a spreadsheet.

One row per quantity with its unit, the analytic value beside the plan's from each source
(the plan as constructed, read to the drafting precision, measured by hand),
each with its error δ = (analytic − plan) / analytic · 100 %.  The Markdown is
in the scene's language (:mod:`graphplan.locale`) and its table of a position
(:func:`error_table_lines`) is the one the explanatory note prints; the CSV
keeps the contract's identifiers for machines.
"""

from __future__ import annotations

import csv
import io
import math
from collections import defaultdict
from collections.abc import Mapping

from ..analysis import Analysis, PlanPosition, VelocityPosition
from ..check import SOURCES, ErrorRow, epsilon_of_another, is_balancing, is_reaction, quantity_symbol
from ..locale import strings
from ..misreadings import (
    FAR_OFF_PERCENT,
    FAR_OFF_PRECISIONS,
    UNIFORM_SLIP_PERCENT,
    OnSheet,
    Rescaled,
    factor_text,
    fitting_position,
    in_units,
    off_the_other_plan,
    on_grid,
    read_at,
    setting,
    sharing,
    sheet_of,
    slips,
    typed_unit,
    value_kind,
)
from ..render.numerals import number, scale_factor
from ..wording import balancing_load
from .markdown import literal, set_close
from .results import PERCENT_FLOOR

FORMULA = "δ = (analytic − plan) / analytic · 100 %"

def unit_of(quantity: str, text: dict[str, str]) -> str:
    """The unit of an error table's quantity in the locale ``text``: rad/s for ω, N for a reaction, ..."""
    if quantity.startswith("omega"):
        return text["unit_rad_per_s"]
    if quantity.startswith("epsilon"):
        return text["unit_rad_per_s2"]
    if is_reaction(quantity) or quantity == "Fb":
        return text["newton"]
    if quantity == "Mb":
        return text["newton_metre"]
    return text["unit_m_per_s" if quantity.startswith("V") else "unit_m_per_s2"]


def _grouped(plan: VelocityPosition) -> tuple[dict[str, dict[str, ErrorRow]], list[str]]:
    """A position's quantities in reading order with the error row of each source, and the sources present."""
    table: dict[str, dict[str, ErrorRow]] = defaultdict(dict)
    for row in plan.errors:
        table[row.quantity][row.source] = row
    return table, [s for s in SOURCES if any(s in rows for rows in table.values())]


def error_table_lines(analysis: Analysis, plan: PlanPosition | VelocityPosition, mark: str = ".") -> list[str]:
    """The error table of one plan position (or of a velocity plan measured by hand) as Markdown lines; ``mark``
    is the decimal mark of its numbers."""
    text = strings(analysis.scene.locale)
    table, sources = _grouped(plan)
    names = [text[f"source_{s}"] for s in sources]
    header = [text["errors_quantity"], text["column_unit"], text["errors_analytic"], *names,
              *(text["errors_delta"].format(source=name) for name in names)]
    lines = ["| " + " | ".join(header) + " |", "|---|---|" + "---:|" * (len(header) - 2)]
    for quantity, rows in table.items():
        exact = next(iter(rows.values())).analytic
        cells = [number(exact, mark=mark)]
        cells += [number(rows[s].plan, mark=mark) if s in rows else "" for s in sources]
        cells += [_percent(rows[s].percent, mark) if s in rows else "" for s in sources]
        lines.append("| " + " | ".join([quantity_symbol(quantity, text), unit_of(quantity, text), *cells]) + " |")
    # A teacher looks for the worst reading first: under each δ column its largest, signed, and whose it is.
    worst = [_worst(table, source, mark, text) for source in sources]
    lines.append("| " + " | ".join([text["errors_largest"], "%", "", *([""] * len(sources)), *worst]) + " |")
    return lines


def largest_errors(analysis: Analysis, accelerations: bool, mark: str = ".") -> list[tuple[str, str, str, int]]:
    """For each source of the plan positions' error tables, the largest error in magnitude of the velocities (or of
    the ``accelerations``) over every position, as its table writes it: (source, δ, the quantity's symbol, the
    position), for the note's conclusions; no symbol where it rounds to 0.000, as :func:`_worst` names none.  The
    velocities' are over the velocity plans of every position too: a conclusion of 0.538 % stood under their
    table's 13.843 %."""
    found: dict[str, tuple[float, str, str, int]] = {}
    for plan in analysis.plans if accelerations else (*analysis.plans, *analysis.velocity_plans):
        for row in plan.errors:
            if is_reaction(row.quantity) or is_balancing(row.quantity) or not math.isfinite(row.percent):
                continue
            if not row.quantity.startswith(("a", "epsilon") if accelerations else ("V", "omega")):
                continue
            if row.source not in found or abs(row.percent) > abs(found[row.source][0]):
                found[row.source] = (row.percent, _percent(row.percent, mark), quantity_symbol(row.quantity),
                                     plan.number)
    return [(source, written, quantity if round(percent, 3) != 0 else "", number)
            for source in SOURCES if source in found for percent, written, quantity, number in [found[source]]]


def _worst(table: dict[str, dict[str, ErrorRow]], source: str, mark: str, text: Mapping[str, str]) -> str:
    """The error of ``source`` largest in magnitude, signed as its row writes it, with its quantity's symbol
    (``−11.820 (ε3)``); none named where it rounds to 0.000 (the construction's), since any row would do."""
    errors = {quantity: rows[source].percent for quantity, rows in table.items()
              if source in rows and math.isfinite(rows[source].percent)}
    if not errors:
        return ""
    quantity = max(errors, key=lambda name: abs(errors[name]))
    written = _percent(errors[quantity], mark)
    return written if round(errors[quantity], 3) == 0 else f"{written} ({quantity_symbol(quantity, text)})"


def slip_lines(analysis: Analysis, plan: VelocityPosition, mark: str = ".", in_note: bool = False) -> list[str]:
    """The hand readings of a position far off its construction (:mod:`graphplan.misreadings`), said under its
    error table in the scene's language: a plan drawn at another scale, or each misread length.  ``in_note``:
    for the explanatory note's reader, who knows the sheets by their captions, not by the files they are in."""
    found = slips(plan, analysis.scene.drawing, analysis.mechanism.driver.joint,
                  sheet_of(plan, analysis.sheet_polygons), analysis.mechanism)
    nearer = _nearer_with_friction(analysis, plan, mark, in_note)
    if found is None:
        return nearer
    text = strings(analysis.scene.locale)
    # Readings found on a drawing with friction (the record's or a course sheet's) are told that once, with the
    # drawing and its μF: "nearer the polygons with friction" would say it again.
    on_friction = found.on_sheet is not None and found.on_sheet.friction
    lines = [] if on_friction else nearer
    drawn = (*analysis.plans, *analysis.velocity_plans)
    if found.on_sheet is not None:
        lines.append(_on_sheet_line(found.on_sheet, plan.number, text, mark, in_note))
    if found.coriolis_reversed:
        lines.append(text["errors_coriolis_reversed_many" if len(found.coriolis_parts) > 1
                          else "errors_coriolis_reversed"].format(
            readings=text["enumeration"].join(reading.split(" = ")[0] for reading in found.coriolis_reversed),
            parts=text["enumeration"].join(found.coriolis_parts), percent=f"{UNIFORM_SLIP_PERCENT:g}",
            millimetres=f"{FAR_OFF_PRECISIONS * analysis.scene.drawing.drafting_precision:g}".replace(".", mark)))
    for rescaled in found.rescaled:
        typed = typed_unit(rescaled.ratio)
        if typed is not None:
            # Lengths typed in another unit than mm, not a drawing at a pole of 0.1 or 8 mm: said as the console
            # says it.
            what = (text["errors_what_polygon"].format(label=rescaled.polygon) if rescaled.polygon
                    else text["errors_what_polygons"]) if rescaled.kind == "forces" \
                else text["errors_what_plan"].format(plan=text[f"{rescaled.kind}_plan_title"].lower())
            # The key a drawing at a tenth is set by may set other positions' too, as for any scale it gives.
            caveat = _shared_caveat(analysis, plan, drawn, rescaled, text, mark) if typed[0] == "centimetres" else ""
            lines.append(text[f"errors_typed_{typed[0]}"].format(what=what, ratio=number(rescaled.ratio, 4, mark),
                                                              setting=setting(rescaled)) + caveat)
            continue
        if rescaled.kind == "forces":
            caveat = "" if in_units(rescaled.drawn_at) else _shared_caveat(analysis, plan, drawn, rescaled, text, mark)
            lines.append(_polygons_line(rescaled, text, mark) + caveat)
            continue
        kind, drawn_at = rescaled.kind, rescaled.drawn_at
        symbol, unit = ("μV", text["unit_velocity_scale"]) if kind == "velocity" else ("μa", text["unit_acceleration_scale"])
        grid = on_grid(rescaled, plan, drawn)
        if grid is not None:
            # The position's small plan among the velocity plans of every position, read for its plan sheet's.
            lines.append(text["note_on_grid" if in_note else "errors_on_grid"].format(
                number=plan.number, grid=scale_factor(grid.scale).replace(".", mark),
                sheet=scale_factor(grid.sheet).replace(".", mark), unit=unit,
                off=f"{grid.off * 100.0:.1f}".replace(".", mark), factor=number(grid.factor, 4, mark),
                grid_file="velocity_plans.svg", sheet_file=f"plan_{plan.number}.svg"))
            continue
        if in_units(drawn_at):
            instead = text["errors_in_place"].format(key=rescaled.replaces) if rescaled.replaces else ""
            lines.append(text["errors_in_units"].format(plan=text[f"{kind}_plan_title"].lower(), symbol=symbol,
                                                        unit=unit, setting=rescaled.unit_setting + instead))
            continue
        but = text["errors_rescaled_but"].format(names=text["enumeration"].join(
            reading.split(" = ")[0] for reading in rescaled.but)) if rescaled.but else ""
        lines.append(text["errors_rescaled"].format(
            plan=text[f"{kind}_plan_title"].lower(), ratio=number(rescaled.ratio, 4, mark), symbol=symbol, but=but,
            scale=scale_factor(plan.plans[kind].scale).replace(".", mark), unit=unit,
            drawn=scale_factor(drawn_at).replace(".", mark), setting=setting(rescaled),
            off=f"{rescaled.off * 100.0:.1f}".replace(".", mark),
            fit=text["errors_pole_fit"].format(key=rescaled.key.removeprefix("drawing."),
                                               fit=number(rescaled.setting, 4, mark))
            if rescaled.key.endswith("_pole") else "") + _shared_caveat(analysis, plan, drawn, rescaled, text, mark))
    elsewhere = None
    if found.misread:
        # A segment's name may be on both plans (pb): the quantities it gives say which.
        readings = ", ".join(f"{_reading(rows[0][0], text, mark)} ({', '.join(quantity_symbol(row.quantity, text) for row, _ in rows)})"
                             for rows in found.misread.values())
        elsewhere = fitting_position(analysis.mechanism, analysis.motion, analysis.positions.numbers, plan,
                                     analysis.scene.drawing.drafting_precision)
        lines.append(text["errors_misread" if elsewhere is None else "errors_misread_elsewhere"].format(
            percent=f"{FAR_OFF_PERCENT:g}", readings=readings, elsewhere=elsewhere,
            millimetres=f"{FAR_OFF_PRECISIONS * analysis.scene.drawing.drafting_precision:g}".replace(".", mark)))
    for typed, readings in (("metres", found.metres), ("centimetres", found.centimetres)):
        if readings:
            lines.append(text[f"errors_readings_{typed}"].format(readings=text["semicolon"].join(
                text["errors_reading_against"].format(reading=_written(reading, text, mark),
                                                      millimetres=f"{constructed:.4g}".replace(".", mark))
                for reading, (_, constructed) in readings.items())))
    if found.values:
        units = {"velocity": text["unit_m_per_s"], "acceleration": text["unit_m_per_s2"], "forces": text["newton"]}
        lines.append(text["errors_readings_values"].format(readings=text["semicolon"].join(
            text["errors_reading_value"].format(
                reading=_written(reading, text, mark), symbol=quantity_symbol(quantity, text),
                value=f"{value:.4g}".replace(".", mark), unit=units[value_kind(quantity)],
                millimetres=f"{constructed:.4g}".replace(".", mark))
            for reading, (quantity, value, constructed) in found.values.items())))
    if found.force_scale:
        lines.append(text["errors_force_scale"].format(readings=text["semicolon"].join(
            text["errors_force_scale_item"].format(
                reading=_written(reading, text, mark), name=reading.split(" = ")[0],
                scale=f"{scale:g}".replace(".", mark), millimetres=f"{length:.2f}".replace(".", mark))
            for reading, (scale, length) in found.force_scale.items())))
    precision = f"{analysis.scene.drawing.drafting_precision:g}".replace(".", mark)
    for other, names in found.other_plan.values():
        # Readings of the other plan typed under this one's table: named, with the other plan's segments they are.
        lines.append(text[f"errors_other_plan_{other}"].format(segments=", ".join(names), precision=precision))
    if found.named and elsewhere is None:  # as the console: another position's readings explain every one
        items = text["semicolon"].join(text["errors_or"].join(
            text[f"errors_segment_{segment.plan}"].format(
                reading=_written(reading, text, mark), segment=segment.name,
                millimetres=f"{segment.millimetres:.2f}".replace(".", mark))
            for segment in segments) for reading, segments in found.named.items())
        other = off_the_other_plan(found.named)
        lines.append(text["errors_named"].format(
            precision=precision, readings=items,
            question=text["errors_named_other" if other else "errors_named_swapped"]))
    # Chinese sets its sentences close: a caveat joined on with a Latin space stood as «）。 但».
    return [set_close(line) for line in lines] if analysis.scene.locale == "zh" else lines


def _shared_caveat(analysis: Analysis, plan: VelocityPosition, drawn: tuple[VelocityPosition, ...],
                   rescaled: Rescaled, text: dict[str, str], mark: str) -> str:
    """Where the key of ``rescaled`` sets other positions whose readings fit it as it is, or ask it another value
    (:func:`~graphplan.misreadings.sharing`): that said, with how to keep it; else nothing.  Asked only where the
    line gives the key."""
    fitting, asking = sharing(rescaled, plan, drawn, analysis.scene.drawing, analysis.mechanism.driver.joint,
                              analysis.sheet_polygons)
    shared = fitting or tuple(asking)
    if not shared:
        return ""
    key = rescaled.key.removeprefix("drawing.")
    return " " + text["errors_shared" if fitting else "errors_shared_other"].format(
        key=key, factor=factor_text(rescaled, mark), number=plan.number,
        values=", ".join(f"{key} = {value:g}".replace(".", mark) for value in asking.values()),
        positions=text["errors_shared_positions" if len(shared) > 1 else "errors_shared_position"].format(
            numbers=", ".join(map(str, shared))))


def _on_sheet_line(found: OnSheet, number: int, text: dict[str, str], mark: str, in_note: bool) -> str:
    """Force readings that fit a drawing of the course sheet (its polygons, its groups cut free's arrows, of the force
    sheet or of the one with friction), drawn larger there than the record's polygons, the arrows the record's
    force sheet draws at a μF of their own, or the record's polygons with friction, in the locale's words;
    ``in_note`` names the drawings by what they are, not by their files."""
    labels = ", ".join(found.polygons)
    polygons = (text["errors_polygons"] if found.every and len(found.polygons) > 1
                else text["errors_polygons_named" if len(found.polygons) > 1 else "errors_polygon"].format(
                    label=labels, labels=labels))
    # The record's own arrows (no course sheet): forces_N.svg draws them beside its polygons at a μF of their own.
    # A drawing with friction (forces_friction_N.svg's polygons or arrows, or the course sheet's) draws reactions no
    # factor turns into those compared with: told to measure the polygons without friction, with none.
    which = "sheet" if found.sheet is not None else "record"
    if found.friction:
        which += "_friction" + ("_arrows" if found.sheet is None and found.drawing == "arrows" else "")
    # A drawing with friction at the μF of the polygons the readings are checked against (the record's, as a rule)
    # has its μF said once.
    record_at = (text["record_at_same_scale"] if found.same_scales
                 else text["record_at_scale"].format(scale=found.scales(1, mark)))
    prefix = "note" if in_note else "errors"
    if found.named:
        # Some readings of a polygon off the drawing with friction, the others where they should be: those named.
        where = text[f"{prefix}_where_{'sheet' if found.sheet is not None else 'record_friction'}"].format(
            sheet=found.sheet, sheet_file=f"sheet_{found.sheet}.svg", friction_file=f"forces_friction_{number}.svg")
        return text[f"{prefix}_on_friction_some"].format(
            polygons=polygons, drawn_as=text[found.kind].format(number=number), where=where,
            drawn=found.scales(0, mark), off=f"{found.off * 100.0:.1f}".replace(".", mark), record_at=record_at,
            forces_file=f"forces_{number}.svg",
            readings=text["comma"].join(_written(each, text, mark) for each in found.named))
    return text[f"{prefix}_on_{which}"].format(
        polygons=polygons, drawn_as=text[found.kind].format(number=number), sheet=found.sheet,
        drawn=found.scales(0, mark), record_at=record_at,
        record=found.scales(1, mark), off=f"{found.off * 100.0:.1f}".replace(".", mark), factor=found.factor(mark),
        sheet_file=f"sheet_{found.sheet}.svg", forces_file=f"forces_{number}.svg",
        friction_file=f"forces_friction_{number}.svg")


def _written(reading: str, text: dict[str, str], mark: str) -> str:
    """A reading as the scene gives it (``pb = 100.98 mm``) in the locale's words: ``pb = 100,98 мм``.  A reaction's
    reading names its polygon's μF in English (``R23 = 40 mm at μF = 50 N/mm``, for the warnings): only the
    length is kept, the one the sentence compares with the other segment's."""
    name, value = reading.split(" = ", 1)
    millimetres = value.split(" ", 1)[0]
    return f"{name} = {millimetres.replace('.', mark)} {text['millimetre']}"


def _polygons_line(rescaled: Rescaled, text: dict[str, str], mark: str) -> str:
    """Force polygons drawn at another μF than they were read at, or readings typed in N, in the locale's words."""
    polygons = (text["errors_polygon"].format(label=rescaled.polygon) if rescaled.polygon
                else text["errors_polygons"])
    if in_units(rescaled.drawn_at):
        return text["errors_forces_in_units"].format(polygons=polygons, setting="`[drawing] force_scale = 1`")
    return text["errors_forces_rescaled"].format(
        polygons=polygons, drawn=number(rescaled.drawn_at, 4, mark), read=read_at(rescaled).replace(".", mark),
        setting=setting(rescaled), off=f"{rescaled.off * 100.0:.1f}".replace(".", mark))


def _reading(row: ErrorRow, text: dict[str, str], mark: str) -> str:
    """A hand reading as the scene gives it, ``pb = 25,88 мм``, in the locale's words."""
    name = row.reading.split(" = ")[0]
    millimetres = abs(row.plan) / row.per_millimetre if row.per_millimetre else 0.0
    return f"{name} = {f'{millimetres:.6g}'.replace('.', mark)} {text['millimetre']}"


def _percent(value: float, mark: str) -> str:
    """An error to the thousandth of a per cent, with a true minus sign (none on a zero); a dash where a reading
    is of a quantity that vanishes, whose error has no finite value."""
    if not math.isfinite(value):
        return "—"
    text = f"{round(value, 3) or 0.0:.3f}"
    return text.replace("-", "−").replace(".", mark)


def measured_bound(analysis: Analysis, mark: str = ".") -> str:
    """Where the tables have hand readings, the one bound the program sets on them (a reading told as misread),
    so that a teacher does not take the absence of a verdict on a δ of 12 % for one; else nothing."""
    positions = (*analysis.plans, *measured_velocity_plans(analysis))
    if not any(row.source == "measured" for position in positions for row in position.errors):
        return ""
    millimetres = FAR_OFF_PRECISIONS * analysis.scene.drawing.drafting_precision
    return strings(analysis.scene.locale)["errors_measured_bound"].format(
        percent=f"{FAR_OFF_PERCENT:g}", millimetres=f"{millimetres:g}".replace(".", mark))


def undefined_errors(analysis: Analysis, positions: tuple[VelocityPosition, ...]) -> str:
    """What a δ written — means, where the tables of ``positions`` write one: a hand reading of a quantity that
    is zero at its position has no relative error (its δ would divide by that zero); else nothing."""
    if any(not math.isfinite(row.percent) for position in positions for row in position.errors):
        return strings(analysis.scene.locale)["errors_undefined"]
    return ""


def epsilons_of_others(analysis: Analysis) -> str:
    """Why a turning link has an ω row and no ε row, where one has: it turns with another link (a point of an RPR's
    rod), whose ε is its own and the only one the acceleration plan lays off; else nothing."""
    pairs = {pair for plan in analysis.plans for pair in epsilon_of_another(plan.plans, plan.readings).items()}
    text = strings(analysis.scene.locale)
    return " ".join(text["errors_epsilon_of_another"].format(link=link, other=other) for link, other in sorted(pairs))


def has_reactions(analysis: Analysis) -> bool:
    """Whether the error tables compare the force polygons' reactions too."""
    return any(is_reaction(row.quantity) for plan in analysis.plans for row in plan.errors)


def reactions_intro(analysis: Analysis, in_note: bool = False) -> str:
    """What the reaction rows compare, in the scene's language; with friction in the pairs, which polygons: those
    without friction, the linear system's reference, so a student who drew the friction polygons knows.  The
    student who ran the program is told the files and the scene's key too; the note's reader (``in_note``), who
    has neither, the polygons in words alone."""
    text = strings(analysis.scene.locale)
    # Only reactions the scene gives as measured are checked against these polygons: neither reader, with no
    # hand-drawn polygon to look for, is told of one where none was given.
    measured = any(row.source == "measured" and is_reaction(row.quantity)
                   for plan in analysis.plans for row in plan.errors)
    if in_note:
        without = text["note_forces_without_friction" if measured else "note_forces_without_friction_unmeasured"]
    else:
        # The file names and the key are written as they are in every language: placeholders keep them out of
        # the words.
        key = "errors_forces_without_friction" if measured else "errors_forces_without_friction_unmeasured"
        without = text[key].format(
            plain="forces_N.svg", with_friction="forces_friction_N.svg", measured="[measured] forces",
            forces="forces.md")
    # The balancing load found by hand, checked beside the reactions: what its rows compare, and its sense's source.
    balancing = next((row.quantity for plan in analysis.plans for row in plan.errors
                      if row.source == "measured" and is_balancing(row.quantity)), None)
    found = ""
    if balancing is not None:
        found = " " + text["note_balancing_measured" if in_note else "errors_balancing_measured"].format(
            symbol=quantity_symbol(balancing, text), unit=unit_of(balancing, text),
            load=balancing_load(analysis.mechanism, text, lower=True),
            key="[measured] balancing")
    return text["errors_forces"] + (f" {without}" if analysis.friction else "") + found


def _nearer_with_friction(analysis: Analysis, plan: VelocityPosition, mark: str, in_note: bool) -> list[str]:
    """Hand readings of reactions that every one stands nearer the polygons with friction than those without,
    which the table checks them against: said, with each reaction as the friction polygon gives it."""
    rubbing = getattr(plan, "with_friction", None)
    if rubbing is None:
        return []
    ideal = {row.quantity: row.plan for row in plan.errors if row.source == "construction"}
    read = [row for row in plan.errors if row.source == "measured" and is_reaction(row.quantity)
            and row.quantity in rubbing.reactions]
    with_friction = {row.quantity: abs(rubbing.reactions[row.quantity].force) for row in read}
    # Nearer by more than the drafting precision on the paper: polygons alike within it cannot be told apart.
    slack = analysis.scene.drawing.drafting_precision
    if not read or not all(abs(row.plan - with_friction[row.quantity]) + slack * row.per_millimetre
                           < abs(row.plan - ideal[row.quantity]) for row in read):
        return []
    text = strings(analysis.scene.locale)
    values = ", ".join(f"{row.quantity} = {number(with_friction[row.quantity], mark=mark)} {text['newton']}"
                       for row in read)
    if in_note:
        return [text["note_nearer_friction"].format(values=values)]
    return [text["errors_nearer_friction"].format(values=values, plain=f"forces_{plan.number}.svg",
                                                  with_friction=f"forces_friction_{plan.number}.svg")]


def markdown(analysis: Analysis) -> str:
    text = strings(analysis.scene.locale)
    mark = text["decimal_mark"]
    precision = f"{analysis.scene.drawing.drafting_precision:g}".replace(".", mark)
    undefined = undefined_errors(analysis, (*analysis.plans, *measured_velocity_plans(analysis)))
    bound = measured_bound(analysis, mark)
    others = epsilons_of_others(analysis)
    lines = [f"# {text['errors_title'].format(title=literal(analysis.scene.title))}", "",
             f"{text['errors_formula']}{text['semicolon']}{text['errors_drafting'].format(precision=precision)}"
             + (f" {undefined}" if undefined else "") + (f" {others}" if others else "")
             + (f" {bound}" if bound else ""), ""]
    if has_reactions(analysis):
        lines += [reactions_intro(analysis), ""]
    if analysis.scene.locale == "zh":  # its sentences, joined with a Latin space, set close as the note's are
        lines = [line if line.startswith("|") else set_close(line) for line in lines]
    for plan in analysis.plans:
        lines += [f"## {text['position_heading'].format(number=plan.number)}", "",
                  *error_table_lines(analysis, plan, mark), ""]
        slipped = slip_lines(analysis, plan, mark)
        lines += [*slipped, ""] if slipped else []
    if analysis.velocity_plans:
        lines += [f"## {text['velocity_plans_heading']}", "", velocity_plans_intro(analysis, mark), "",
                  *velocity_plans_lines(analysis, mark), ""]
        for position in measured_velocity_plans(analysis):
            lines += [f"### {text['velocity_plan_errors'].format(number=position.number)}", "",
                      *error_table_lines(analysis, position, mark), ""]
            slipped = slip_lines(analysis, position, mark)
            lines += [*slipped, ""] if slipped else []
    return "\n".join(lines)


def measured_velocity_plans(analysis: Analysis) -> tuple[VelocityPosition, ...]:
    """The velocity plans of positions without a plan sheet that ``[measured]`` reads: the table of every
    position gives only their largest error, and a student checks a drawing quantity by quantity."""
    planned = {plan.number for plan in analysis.plans}
    return tuple(position for position in analysis.velocity_plans if position.number not in planned
                 and any(row.source == "measured" for row in position.errors))


def velocity_plans_intro(analysis: Analysis, mark: str = ".") -> str:
    """The sentence before the tables of :func:`velocity_plans_lines`: what they give, at which μV."""
    scale = scale_factor(analysis.velocity_plans[0].velocity.scale).replace(".", mark)
    return strings(analysis.scene.locale)["velocity_plans_intro"].format(scale=scale)


# The positions side by side in one table of the velocity plans of every position: six fit a page of the note.
POSITIONS_PER_TABLE = 6


def velocity_plans_lines(analysis: Analysis, mark: str = ".") -> list[str]:
    """The values read off the velocity plans of every position (as constructed) as Markdown lines: a column a
    position (headed by its number), a row a quantity, then each source's largest error of the position in
    magnitude; in tables of :data:`POSITIONS_PER_TABLE` positions.  ``mark`` is the decimal mark of the numbers."""
    text = strings(analysis.scene.locale)
    every = analysis.velocity_plans
    quantities = list(dict.fromkeys(row.quantity for position in every for row in position.errors))
    sources = [s for s in SOURCES if any(row.source == s for position in every for row in position.errors)]
    lines = []
    for start in range(0, len(every), POSITIONS_PER_TABLE):
        chunk = every[start:start + POSITIONS_PER_TABLE]
        tables = [_grouped(position)[0] for position in chunk]
        header = [text["errors_quantity"], text["column_unit"],
                  *(str(position.number) for position in chunk)]
        lines += ["| " + " | ".join(header) + " |", "|---|---|" + "---:|" * len(chunk)]
        for quantity in quantities:
            cells = [number(table[quantity]["construction"].plan, mark=mark) if quantity in table else ""
                     for table in tables]
            lines.append("| " + " | ".join([quantity_symbol(quantity, text), unit_of(quantity, text), *cells]) + " |")
        for source in sources:
            cells = [_largest(table, source, mark, text) for table in tables]
            if not any(cells):
                continue
            name = text["velocity_plans_largest"].format(source=text[f"source_{source}"])
            lines.append("| " + " | ".join([name, "%", *cells]) + " |")
        lines.append("")
    return lines[:-1]


def _largest(table: dict[str, dict[str, ErrorRow]], source: str, mark: str, text: Mapping[str, str]) -> str:
    """A position's largest error of ``source`` in magnitude, signed, of those that have a value; a reading of a quantity
    that vanishes there has none (its δ is written —) and is named beside it, so that it hides no finite
    error (``0.268 (VE: —)``).  A position not measured by hand has no measured error: empty, not 0."""
    errors = {quantity: rows[source].percent for quantity, rows in table.items() if source in rows}
    finite = [value for value in errors.values() if math.isfinite(value)]
    undefined = [quantity_symbol(quantity, text) for quantity, value in errors.items() if not math.isfinite(value)]
    if not finite:
        return _percent(math.inf, mark) if undefined else ""
    # Signed, as the position's own table writes its largest (−3.446 there, 3.446 here read as another value).
    return _percent(max(finite, key=abs), mark) + (f" ({', '.join(undefined)}: —)" if undefined else "")


def csv_text(analysis: Analysis) -> str:
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["position", "quantity", "analytic", "source", "plan", "percent"])
    for row in analysis.errors:
        # An error of rounding (1e-14 %) is none, as results.json writes it.
        percent = 0.0 if abs(row.percent) < PERCENT_FLOOR else row.percent
        writer.writerow([row.position, row.quantity, _cell(row.analytic, 12), row.source, _cell(row.plan, 12),
                         _cell(percent, 6)])
    return out.getvalue()


def _cell(value: float, digits: int) -> str:
    """A number of the CSV: empty where it has none (the error of a reading of what stands still, which
    results.json writes null and the tables —), and a rounding's −0 as 0."""
    return f"{value + 0.0:.{digits}g}" if math.isfinite(value) else ""
