"""``forces.md``: the force analysis as the explanatory note tabulates it.

Per plan position: the initial data of the force analysis (m, aS, Fu, J, ε,
Mu, G of every link, read off the plans), the moment equations with their
arms, the reactions from the polygons against the linear system, the
balancing load four ways (polygons, lever, linear system, power), and with
friction its iterations and the efficiency, the reactions with friction (the polygons against the linear
system) and each pair's friction load (Mf = ρ·|R|, Ff = f′·|R|).  Then the balancing load and the
efficiency at every position of the cycle, and over the whole cycle: the driver's works with and without
friction and their ratio.

The rows are computed once here (:func:`initial_data`, :func:`reaction_rows`,
:func:`balancing_rows`, :func:`cycle_rows`) and written by the ``*_lines``
functions in the scene's language, so that ``forces.md`` and the explanatory
note (:mod:`graphplan.report.note`) print the same numbers.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from .. import wording
from ..analysis import Analysis, PlanPosition
from ..forces import ForcePlan
from ..joint_friction import FrictionPair, pair_name
from ..loads import external_names, motion_state, spring_length, spring_value
from ..locale import Count, load_symbol, strings
from ..mechanism import Mechanism
from ..render.numerals import number
from ..rounding import ROUNDING_NOISE
from ..statics import balancing_by_power, delivers_power, efficiency, rounded_zero, turned_round
from .markdown import literal

# A rate or a load this small against the largest of its kind is the plan's rounding, not a value.
ROUNDING = 1e-12


def polar(force: complex, mark: str = ".") -> str:
    """A force as magnitude ∠ direction in degrees; a force of rounding noise as 0, which has no direction."""
    if not (math.isfinite(force.real) and math.isfinite(force.imag)):
        return "—"
    if abs(force) < ROUNDING_NOISE:
        return "0"
    return f"{number(abs(force), mark=mark)} {direction(force, mark)}"


def direction(force: complex, mark: str = ".") -> str:
    """``∠ 180°``: which way ``force`` acts, in degrees from the x axis, as :func:`polar` writes it."""
    return f"∠ {number(math.degrees(cmath.phase(force)), 4, mark)}°"


def percent(value: float, reference: float, mark: str = ".") -> str:
    """(value − reference)/reference · 100; 0 where both are noughts, a dash where only the reference is."""
    if abs(reference) < ROUNDING_NOISE:
        return "0" if abs(value) < ROUNDING_NOISE else "—"
    return number((value - reference) / reference * 100.0, 3, mark)


def error_percent(exact: float, found: float, mark: str = ".") -> str:
    """The error of ``found``, (exact − found)/exact · 100, signed as the error tables sign it; 0 where both are
    noughts, a dash where only the exact value is."""
    if abs(exact) < ROUNDING_NOISE:
        return "0" if abs(found) < ROUNDING_NOISE else "—"
    return number((exact - found) / exact * 100.0, 3, mark)


@dataclass(frozen=True)
class Shift:
    """What a slide's moment equation ``ΣM = R·x + … = 0`` finds: the couple R·x (N·m, signed by its moment) of the
    normal reaction ``reaction``, of size ``force`` (N), shifted x along the slide from the joint the moments are
    taken about.  A couple of nought puts the reaction's line through that joint: x = 0."""

    reaction: str
    moment: float
    force: float

    @property
    def through(self) -> bool:
        return self.moment == 0.0

    @property
    def x(self) -> float:
        """The shift, m: the couple's size over the reaction's."""
        return abs(self.moment) / self.force if self.force else 0.0


def shift(group, equation) -> Shift | None:
    """The shift x an equation solved for a slide's couple R·x finds, as forces.md and the note both write it, or
    None: an equation for a force or Mb, or a couple its guide holds alone (R = 0, no line and no x)."""
    if not equation.unknown.endswith("·x") or group.held_as_couple_alone(equation):
        return None
    name = equation.unknown.removesuffix("·x")
    size = max([abs(term.moment) for term in equation.terms] + [abs(equation.value * equation.arm)])
    if abs(equation.value) <= ROUNDING * max(size, 1.0):
        return Shift(name, 0.0, 0.0)
    found = next((item for item in group.found if item.name == name), None)
    return Shift(name, equation.value, abs(found.force)) if found is not None and abs(found.force) > 0 else None


@dataclass(frozen=True)
class LinkData:
    """One row of the initial data of the force analysis: a link's mass and inertia, and its motion from the plans.

    ``epsilon`` is signed (ccw positive) as the acceleration plan gives it.
    """

    link: int
    centre: str | None
    mass: float
    inertia: float
    centre_acceleration: float
    epsilon: float
    gravity: float

    @property
    def inertia_force(self) -> float:
        """Fu = m·aS, N."""
        return self.mass * self.centre_acceleration

    @property
    def inertia_moment(self) -> float:
        """Mu = J·|ε|, N·m."""
        return self.inertia * abs(self.epsilon)

    @property
    def inertia_moment_signed(self) -> float:
        """Mu = −J·ε, N·m, counter-clockwise positive as ε is: beside the signed ε, its modulus would read as turning
        with ε where it turns against it."""
        return -self.inertia * self.epsilon + 0.0

    @property
    def weight(self) -> float:
        """G = m·g, N."""
        return self.mass * self.gravity


def initial_data(analysis: Analysis, plan: PlanPosition) -> list[LinkData]:
    """The initial data of the force analysis at a plan position, link by link in the order of the structure."""
    scene = analysis.scene
    rows = []
    largest = max(abs(rate) for rate in plan.acceleration.rates.values())
    for link in analysis.mechanism.moving_links:
        spec = scene.links.get(link)
        if spec is None:
            continue
        a_s = abs(plan.acceleration.value(spec.centre)) if spec.centre else 0.0
        epsilon = plan.acceleration.rates.get(link, 0.0)
        if abs(epsilon) < ROUNDING * largest:
            epsilon = 0.0  # a driver at constant speed: what is left is the plan's rounding
        rows.append(LinkData(link, spec.centre, spec.mass, spec.inertia, a_s, epsilon, scene.gravity))
    return rows


def external_loads(plan: PlanPosition):
    """The scene's own loads at the position (not the weights and the inertia loads)."""
    return [load for load in plan.loads if load.name[0] in "FM" and not load.name.startswith(("Fu", "Mu"))]


def reaction_rows(analysis: Analysis, plan: PlanPosition) -> list[tuple[str, complex, complex]]:
    """Every reaction as (name, from the polygons, from the linear system); NaN without the linear system."""
    exact = analysis.equilibrium
    rows = []
    for reaction in plan.forces.reactions.values():
        solved = complex(exact.reaction(reaction.name).force[plan.index]) if exact is not None else complex(math.nan)
        rows.append((reaction.name, reaction.force, solved))
    return rows


# The four ways to the balancing load, in the order the tables list them.
METHODS = ("polygons", "lever", "linear", "power")


def balancing_rows(analysis: Analysis, plan: PlanPosition) -> list[tuple[str, float]]:
    """The balancing load at a plan position four ways, as (method, value) in the order of :data:`METHODS`."""
    index = plan.index
    by_power = float(balancing_by_power(analysis.mechanism, motion_state(analysis.motion), analysis.loads)[index])
    exact = analysis.equilibrium
    return [("polygons", plan.forces.balancing),
            ("lever", plan.lever.balancing if plan.lever is not None else math.nan),
            ("linear", float(exact.balancing[index]) if exact is not None else math.nan),
            ("power", by_power)]


def cycle_rows(analysis: Analysis) -> list[tuple[int, float, float | None, float | None, bool]]:
    """(position, Mb, Mb with friction, η, locked) at every position, from the linear system."""
    exact, rubbing = analysis.equilibrium, analysis.with_friction
    rows = []
    for i, position in enumerate(analysis.positions.numbers):
        ideal = float(exact.balancing[i])
        if rubbing is None:
            rows.append((int(position), ideal, None, None, False))
            continue
        locked = bool(rubbing.locked[i])
        rubbed = float(rubbing.balancing[i])
        eta = float(efficiency(analysis.mechanism, exact.balancing[i], rubbing.balancing[i], analysis.balancing_scale))
        rows.append((int(position), ideal, None if locked else rubbed, None if locked else eta, locked))
    return rows


def balancing_symbol(analysis: Analysis) -> tuple[str, str]:
    """The balancing load's symbol and its unit in the locale: (Mb, N·m) for a crank, (Fb, N) for a slider."""
    return wording.balancing_symbol(analysis.mechanism, strings(analysis.scene.locale))


def sense_of_balancing(mechanism: Mechanism, text: Mapping[str, str]) -> str:
    """The balancing load's sign convention: a moment counter-clockwise positive, a force along the driving slider's
    guide (told by the driver, not by the symbol, which the locale spells)."""
    return text["forces_sense_moment" if mechanism.driver.kind == "crank" else "forces_sense_force"]


# Tables shared with the explanatory note: each returns Markdown lines in the scene's language.

def initial_data_lines(analysis: Analysis, plan: PlanPosition, mark: str = ".") -> list[str]:
    """The table of the links' masses, inertias and inertia loads; none where no link has any (a scene of loads
    alone), whose table was its header over no row."""
    rows = initial_data(analysis, plan)
    if not rows:
        return []
    text = strings(analysis.scene.locale)
    header = (f"| {text['column_link']} | m, {text['unit_kg']} | aS, {text['unit_m_per_s2']} | "
              f"{load_symbol('Fu', text)}, {text['newton']} | J, {text['unit_kg_m2']} | ε, {text['unit_rad_per_s2']} | "
              f"{load_symbol('Mu', text)}, {text['newton_metre']} | "
              f"G, {text['newton']} |")
    lines = [header, "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for row in rows:
        cells = (row.mass, row.centre_acceleration, row.inertia_force, row.inertia, row.epsilon,
                 row.inertia_moment_signed, row.weight)
        lines.append(f"| {row.link} | " + " | ".join(number(value, mark=mark) for value in cells) + " |")
    return lines


def external_load_lines(analysis: Analysis, plan: PlanPosition, mark: str = ".") -> list[str]:
    text = strings(analysis.scene.locale)
    specs = dict(zip(external_names(analysis.scene.loads), analysis.scene.loads, strict=True))
    lines = []
    for load in external_loads(plan):
        acting = load.force != 0 if load.is_force else load.moment != 0
        if not acting:
            value = text["forces_not_acting"]
        elif load.is_force:
            value = f"{polar(load.force, mark)} {text['newton']}"
        else:
            value = f"{number(load.moment, mark=mark)} {text['newton_metre']}"
        spec = specs.get(load.name)
        if spec is not None and spec.spring:
            # Its value is its length's here: k·(L − L0) written out, that the force can be checked by hand.
            state_at = motion_state(analysis.motion)
            length = float(np.ravel(spring_length(spec, state_at))[plan.index])
            # The force spring_value gives along DB, pushing B away, is the tension's opposite.
            tension = -float(np.ravel(spring_value(spec, state_at))[plan.index])
            state = "pulls" if tension > 0 else "pushes" if tension < 0 else "free"
            sense = text[f"forces_spring_{state}"].format(point=spec.point, along=spec.along)
            lines.append(text["forces_external_spring"].format(
                name=load.name, link=load.link, line=f"{spec.along}{spec.point}",
                stiffness=number(spec.stiffness, mark=mark), length=number(length, mark=mark),
                free_length=number(spec.free_length, mark=mark),
                tension=number(tension, mark=mark), sense=sense, value=value) + "  ")
        elif spec is not None and spec.along is not None:
            # Its angle is this position's alone: the line it keeps is the one to the point it acts along.
            lines.append(text["forces_external_along"].format(name=load.name, link=load.link,
                                                             line=f"{spec.along}{spec.point}", value=value) + "  ")
        else:
            lines.append(text["forces_external"].format(name=load.name, link=load.link, value=value) + "  ")
    return lines


def reaction_lines(analysis: Analysis, plan: PlanPosition, mark: str = ".") -> list[str]:
    return _reaction_table(analysis, reaction_rows(analysis, plan), mark)


def _reaction_table(analysis: Analysis, rows: list[tuple[str, complex, complex]], mark: str) -> list[str]:
    text = strings(analysis.scene.locale)
    header = (f"| {text['column_reaction']} | {text['column_polygons']}{text['comma']}{text['newton']} ∠ | "
              f"{text['column_linear']}{text['comma']}{text['newton']} ∠ | δ, % |")
    lines = [header, "|---|---:|---:|---:|"]
    for name, drawn, solved in rows:
        lines.append(f"| {name} | {polar(drawn, mark)} | {polar(solved, mark)} | "
                     f"{error_percent(abs(solved), abs(drawn), mark) if math.isfinite(abs(solved)) else '—'} |")
    return lines


def balancing_lines(analysis: Analysis, plan: PlanPosition, mark: str = ".") -> list[str]:
    text = strings(analysis.scene.locale)
    lines = [f"| {text['column_method']} | {text['column_value']} | {text['column_delta_polygons']} |",
             "|---|---:|---:|"]
    rows = balancing_rows(analysis, plan)
    polygons = rows[0][1]
    for method, value in rows:
        delta = "" if method == "polygons" else percent(value, polygons, mark) if math.isfinite(value) else "—"
        lines.append(f"| {text['method_' + method]} | {number(value, 6, mark)} | {delta} |")
    return lines


def friction_lines(analysis: Analysis, plan: PlanPosition, mark: str = ".") -> list[str]:
    text = strings(analysis.scene.locale)
    rubbing = plan.with_friction
    if rubbing.locked:
        return [text["forces_locked"]]
    scale = analysis.balancing_scale
    eta = efficiency(analysis.mechanism, plan.forces.balancing, rubbing.balancing, scale)
    return [wording.friction_summary(
        analysis.mechanism, text, plan.forces.balancing, rubbing.balancing, scale=scale,
        write=lambda value: number(value, 6, mark), iterations=rubbing.iterations,
        written_efficiency=number(float(eta), 4, mark))]


@dataclass(frozen=True)
class FrictionLoad:
    """A pair's friction load at the settled reactions: ``Mf23 = ρ·|R23|`` of a journal, ``Ff16 = f′·|R16|`` of a
    slide, against the pair's relative motion.

    ``where`` names the pair in ρ and f (f′ in a V-guide) as the drawings do (:func:`pair_name`): its joint (ρO,
    fE), or its links where two pairs with friction share the joint (ρ23 and f43 at a block's pin in its slot);
    ``reaction`` is |R| of the pair (N); ``moving`` is
    false where the pair's links do not move relative to each other, and its load is then 0.  ``acting`` is the
    load as it acts on the pair's later link: a journal's moment signed counter-clockwise positive, a slide's force
    as a vector, whose sense against the relative motion the reader checks the drawing by.
    """

    pair: FrictionPair
    where: str
    name: str
    reaction: float
    moving: bool = True
    acting: complex = 0j

    @property
    def factor(self) -> float:
        """ρ of a journal (m), f′ of a slide."""
        return self.pair.coefficient if self.pair.sliding else self.pair.radius

    @property
    def value(self) -> float:
        """Mf (N·m) or Ff (N): ρ·|R| or f′·|R|, 0 where the pair does not move."""
        return self.factor * self.reaction if self.moving else 0.0


def friction_load_rows(analysis: Analysis, plan: PlanPosition) -> list[FrictionLoad]:
    """Each pair's friction load at the settled reactions of a plan position, in the scene's order of the pairs;
    none where the position locks."""
    rubbing = plan.with_friction
    if rubbing is None or rubbing.locked:
        return []
    acting = {load.name: load for load in plan.friction_loads}
    rows = []
    for pair in analysis.friction:
        where = pair_name(pair, analysis.friction)
        name = pair.load_names[0]
        load = acting.get(name)
        moving = load is None or bool(np.any(load.force if pair.sliding else load.moment))
        signed = 0j if load is None else complex(np.asarray(load.force if pair.sliding else load.moment).item())
        rows.append(FrictionLoad(pair, where, name, abs(rubbing.reactions[pair.reaction].force), moving, signed))
    return rows


def friction_reaction_rows(analysis: Analysis, plan: PlanPosition) -> list[tuple[str, complex, complex]]:
    """Every reaction with friction as (name, from the polygons with friction, from the linear system with
    friction); none where the position locks."""
    rubbing, exact = plan.with_friction, analysis.with_friction
    if rubbing is None or rubbing.locked:
        return []
    return [(reaction.name, reaction.force,
             complex(exact.reaction(reaction.name).force[plan.index]) if exact is not None else complex(math.nan))
            for reaction in rubbing.reactions.values()]


def friction_reaction_lines(analysis: Analysis, plan: PlanPosition, mark: str = ".") -> list[str]:
    """The reactions with friction, as :func:`reaction_lines` tabulates those without."""
    return _reaction_table(analysis, friction_reaction_rows(analysis, plan), mark)


def friction_load_lines(analysis: Analysis, plan: PlanPosition, mark: str = ".") -> list[str]:
    """The friction loads of :func:`friction_load_rows` as a table: the pair, its ρ or f′, its reaction, the load."""
    text = strings(analysis.scene.locale)
    lines = [(f"| {text['column_pair']} | {text['column_friction_factor']} | {text['column_reaction']}"
              f"{text['comma']}{text['newton']} | {text['column_friction_load']} |"), "|---|---:|---:|---:|"]
    for row in friction_load_rows(analysis, plan):
        pair = row.pair
        # With its sense, as the note writes it: a moment's size ρ·|R| and the way it turns the later link, a force
        # ∠ its direction; a size alone left the reader to guess which way each pair rubs.
        if pair.sliding:
            factor = f"{'f′' if pair.in_vee else 'f'}{row.where} = {number(row.factor, mark=mark)}"
            load = f"{polar(row.acting if row.moving else 0j, mark)} {text['newton']}"
        else:
            factor = f"ρ{row.where} = {number(row.factor, mark=mark)} {text['unit_m']}"
            load = f"{number(row.value, mark=mark)} {text['newton_metre']}{_turning(text, row, mark)}"
        lines.append(f"| {pair.joint} ({pair.source}–{pair.target}) | {factor} | "
                     f"{pair.reaction} = {number(row.reaction, mark=mark)} | {row.name} = {load} |")
    return lines


def _turning(text: Mapping[str, str], row: FrictionLoad, mark: str) -> str:
    """``, clockwise`` after a friction moment's size: the sense it turns the pair's later link in; nothing after
    one written 0."""
    if not row.moving or number(row.acting.real, mark=mark) == "0":
        return ""
    return text["comma"] + text["sense_ccw" if row.acting.real > 0 else "sense_cw"]


def friction_lever_lines(analysis: Analysis, plan: PlanPosition, mark: str = ".") -> list[str]:
    """Zhukovsky's lever with the pairs' friction loads against the polygons with friction; none where they lock."""
    lever = plan.lever_with_friction
    if lever is None or plan.with_friction is None:
        return []
    name, unit = balancing_symbol(analysis)
    return [strings(analysis.scene.locale)["forces_friction_lever"].format(
        name=name, value=number(lever.balancing, 6, mark), unit=unit,
        difference=percent(lever.balancing, plan.with_friction.balancing, mark))]


def cycle_lines(analysis: Analysis, mark: str = ".") -> list[str]:
    text = strings(analysis.scene.locale)
    name, unit = balancing_symbol(analysis)
    rubbing = analysis.with_friction is not None
    header = f"| {text['column_position']} | {name}, {unit} |"
    if rubbing:
        header += f" {text['column_with_friction'].format(name=name, unit=unit)} | η |"
    lines = [header, "|---|---:|" + ("---:|---:|" if rubbing else "")]
    for position, ideal, rubbed, eta, locked in cycle_rows(analysis):
        row = f"| {position} | {number(ideal, 6, mark)} |"
        if rubbing:
            row += (f" {text['forces_locked_short']} | — |" if locked else
                    f" {number(rubbed, 6, mark)} | {number(eta, 4, mark)} |")
        lines.append(row)
    return lines


def cycle_notes(analysis: Analysis) -> list[str]:
    """What the cycle table's η column means where it is not Mb0/Mb: the positions where the loads drive the
    driver (η = Mb/Mb0), and those where the friction turns that flow round (η′ ≤ 0, written —)."""
    exact, rubbing = analysis.equilibrium, analysis.with_friction
    if exact is None or rubbing is None:
        return []
    text = strings(analysis.scene.locale)
    name, _ = balancing_symbol(analysis)
    ideal = rounded_zero(exact.balancing, rubbing.balancing, analysis.balancing_scale)
    with np.errstate(invalid="ignore"):
        moving = ~rubbing.locked & np.isfinite(ideal) & np.isfinite(rubbing.balancing)
        held = moving & turned_round(analysis.mechanism, ideal, rubbing.balancing, analysis.balancing_scale)
        driven = moving & ~held & ~delivers_power(analysis.mechanism, ideal)
    numbers = analysis.positions.numbers
    notes = []
    for key, where in (("forces_cycle_reverse_ratio", driven), ("forces_cycle_turned_round", held)):
        if where.any():
            indices = np.flatnonzero(where)
            positions = text["enumeration"].join(str(numbers[index]) for index in indices)
            notes.append(text[key].format(positions=positions, count=Count(len(indices)), name=name))
    return notes


def cycle_efficiency_lines(analysis: Analysis, mark: str = ".") -> list[str]:
    """The driver's works over the cycle without and with friction and η over the cycle
    (:mod:`graphplan.cycle_work`); where the friction locks the mechanism on the way, that there is none."""
    cycle = analysis.cycle
    if cycle is None:
        return []
    text = strings(analysis.scene.locale)
    name, _ = balancing_symbol(analysis)
    sign = -1.0 if cycle.loads_drive else 1.0   # what the loads give the driver, where they drive it

    def write(value: float) -> str:
        return number(sign * value, 6, mark)

    values = {"name": name, "useful": write(cycle.without_friction), "driving": write(cycle.with_friction),
              "friction": number(cycle.friction, 6, mark), "efficiency": number(cycle.efficiency, 4, mark)}
    if cycle.locked:
        key = "forces_cycle_efficiency_locked"
        values["useful"] = number(cycle.without_friction, 6, mark)
    elif cycle.without_friction == 0:
        key = "forces_cycle_efficiency_idle"
    elif not cycle.loads_drive:
        key = "forces_cycle_efficiency"
    elif math.isfinite(cycle.efficiency):
        key = "forces_cycle_efficiency_reverse"
    else:
        key = "forces_cycle_efficiency_turned_round"
        values["driving"] = number(cycle.with_friction, 6, mark)
    return [text[key].format(**values)]


def locked_between_lines(analysis: Analysis, mark: str = ".") -> list[str]:
    """A paragraph for each stretch between two positions where the friction locks the mechanism, then for each
    where it holds the loads that would drive it."""
    text = strings(analysis.scene.locale)
    numbers = analysis.positions.numbers

    def write(value: float) -> str:
        return number(value, 5, mark)

    return [*(wording.locked_between(analysis.mechanism, text, numbers, span, write)
              for span in analysis.locked_spans),
            *(wording.locked_between(analysis.mechanism, text, numbers, span, write, "forces_turned_round_between")
              for span in analysis.turned_round_spans)]


def markdown(analysis: Analysis) -> str:
    text = strings(analysis.scene.locale)
    mark = text["decimal_mark"]
    name, unit = balancing_symbol(analysis)
    lines = [f"# {text['forces_title'].format(title=literal(analysis.scene.title))}", "",
             text["forces_intro"].format(structure=analysis.mechanism.structure, name=name, unit=unit,
                                         sense=sense_of_balancing(analysis.mechanism, text)),
             ""]
    for plan in analysis.plans:
        if plan.forces is not None:
            lines += _position(analysis, plan, text)
    if analysis.equilibrium is not None:
        lines += [f"## {text['forces_cycle']}", "", text["forces_cycle_intro"], "", *cycle_lines(analysis, mark), ""]
        sentences = [*cycle_notes(analysis), *locked_between_lines(analysis, mark), *cycle_efficiency_lines(analysis, mark)]
        lines += [line for sentence in sentences for line in (sentence, "")]
    return "\n".join(lines) + "\n"


def _position(analysis: Analysis, plan: PlanPosition, text: Mapping[str, str]) -> list[str]:
    name, unit = balancing_symbol(analysis)
    forces, mark = plan.forces, text["decimal_mark"]
    balancing = text["forces_balancing"].format(load=wording.balancing_load(analysis.mechanism, text), name=name,
                                                unit=unit)
    lines = [f"## {text['position_heading'].format(number=plan.number)}", "",
             f"### {text['forces_initial_data']}", ""]
    if table := initial_data_lines(analysis, plan, mark):
        lines += [*table, ""]
    lines += external_load_lines(analysis, plan, mark)
    # A block's pin reaction along its slot, found from the block's forces before the moments.
    projections = [f"- {group.label}: ΣFτ({projection.link}) = 0 → {projection.unknown} = "
                   f"{number(projection.value, mark=mark)} {text['newton']}"
                   + "".join(f"; {name}: {number(value, mark=mark)} {text['newton']}"
                             for name, value in projection.components)
                   for group in forces.groups for projection in group.projections]
    if projections:
        lines += ["", f"### {text['forces_projections']}", "", *projections]
    lines += ["", f"### {text['forces_moment_equations']}", ""]
    metre, newton_metre = text["unit_m"], text["newton_metre"]
    for group in forces.groups:
        for equation in group.moments:
            # The moments the unknown balances, as the note writes them: a term of the plan's rounding (a block's
            # couple R34·x about C where its line passes through A) balances nothing and is left out.
            terms = ", ".join(f"{load_symbol(term.name, text)}: {number(term.moment, mark=mark)} {newton_metre}"
                              + (f" (h = {number(term.arm, 4, mark)} {metre})" if term.arm else "")
                              for term in equation.standing_terms)
            unit = newton_metre if equation.couple else text["newton"]
            found = shift(group, equation)
            if found is None:
                solved = f"{load_symbol(equation.unknown, text)} = {number(equation.value, mark=mark)} {unit}"
            elif found.through:
                solved = text["note_couple_through"].format(name=found.reaction, point=equation.about)
            else:
                # A slide's reaction off its joint: the equation gives its shift, the couple over the reaction.
                solved = (f"x = |{equation.unknown}|/{found.reaction} = {number(abs(found.moment), mark=mark)}/"
                          f"{number(found.force, mark=mark)} = {number(found.x, mark=mark)} {metre}")
            line = (f"- {group.label}: ΣM{equation.about}({equation.bodies}) = 0 → {solved}"
                    + (f"; {terms}" if terms else ""))
            if reaction := group.held_as_couple_alone(equation):
                line += text["semicolon"] + text["note_couple_alone"].format(name=reaction)
            lines.append(line)
    lines += ["", f"### {text['forces_reactions']}", "",
              _polygon_scales(forces, text, mark), "", *reaction_lines(analysis, plan, mark),
              "", f"### {balancing}", "", *balancing_lines(analysis, plan, mark)]
    if plan.with_friction is not None:
        lines += ["", f"### {text['forces_friction']}", "", *friction_lines(analysis, plan, mark)]
        if not plan.with_friction.locked:
            lines += ["", text["forces_friction_reactions"], "", *friction_reaction_lines(analysis, plan, mark),
                      "", text["note_friction_loads"], "", *friction_load_lines(analysis, plan, mark)]
        lever = friction_lever_lines(analysis, plan, mark)
        lines += ["", *lever] if lever else []
    return lines + [""]


def _polygon_scales(forces: ForcePlan, text: Mapping[str, str], mark: str) -> str:
    """The line of μF: one for all the polygons, or each group's where the program drew each at its own."""
    if forces.one_scale:
        return text["forces_polygon_scale"].format(value=number(forces.scale, mark=mark))
    return text["forces_polygon_scales"].format(
        values=text["separator"].join(f"{label}: {number(scale, mark=mark)}" for label, scale in forces.group_scales.items()))


__all__ = [
    "METHODS",
    "FrictionLoad",
    "LinkData",
    "balancing_lines",
    "balancing_rows",
    "balancing_symbol",
    "cycle_efficiency_lines",
    "cycle_lines",
    "cycle_notes",
    "cycle_rows",
    "external_load_lines",
    "external_loads",
    "friction_lever_lines",
    "friction_lines",
    "friction_load_lines",
    "friction_load_rows",
    "friction_reaction_lines",
    "friction_reaction_rows",
    "initial_data",
    "initial_data_lines",
    "markdown",
    "number",
    "percent",
    "polar",
    "reaction_lines",
    "reaction_rows",
    "shift",
]
