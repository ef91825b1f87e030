"""``forces.md``: the force analysis as the explanatory note tabulates it.

Per plan position: the initial data of the force analysis (m, aS, Fu, J, ε,
Mu, G of every link, read off the plans), the moment equations with their
arms, the reactions from the polygons against the linear system, the
balancing load four ways (polygons, lever, linear system, power), and with
friction its iterations and the efficiency.  Then the balancing load and the
efficiency over the whole cycle.
"""

from __future__ import annotations

import cmath
import math

import numpy as np

from ..analysis import Analysis, PlanPosition
from ..loads import motion_state
from ..statics import balancing_by_power, efficiency


# A rate this small against the plan's largest is the plan's rounding, not a value.
_ROUNDING = 1e-12


def _g(value: float, digits: int = 5) -> str:
    if not math.isfinite(value):
        return "—"
    text = f"{value:.{digits}g}"
    return "0" if text in ("-0", "0") else text.replace("-", "−")


def _polar(force: complex) -> str:
    return f"{_g(abs(force))} ∠ {_g(math.degrees(cmath.phase(force)) if force else 0.0, 4)}°"


def _percent(value: float, reference: float) -> str:
    return _g((value - reference) / reference * 100.0, 3) if reference else "—"


def markdown(analysis: Analysis) -> str:
    driver = analysis.mechanism.driver
    unit, name = ("N·m", "Mb") if driver.kind == "crank" else ("N", "Fb")
    lines = [f"# Force analysis: {analysis.scene.title}", "",
             f"Structure {analysis.mechanism.structure}; groups from the last to the driver. "
             f"Reactions R_ij: the force link i exerts on link j. {name} in {unit}, counter-clockwise "
             "(along the guide) positive.", ""]
    for plan in analysis.plans:
        if plan.forces is not None:
            lines += _position(analysis, plan, name, unit)
    if analysis.equilibrium is not None:
        lines += _cycle(analysis, name, unit)
    return "\n".join(lines) + "\n"


def _position(analysis: Analysis, plan: PlanPosition, name: str, unit: str) -> list[str]:
    forces, index = plan.forces, plan.index
    lines = [f"## Position {plan.number}", "", "### Initial data", "",
             "| link | m, kg | aS, m/s² | Fu, N | J, kg·m² | ε, rad/s² | Mu, N·m | G, N |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    scene = analysis.scene
    for number in analysis.mechanism.moving_links:
        spec = scene.links.get(number)
        if spec is None:
            continue
        a_s = abs(plan.acceleration.value(spec.centre)) if spec.centre else 0.0
        epsilon = plan.acceleration.rates.get(number, 0.0)
        if abs(epsilon) < _ROUNDING * max(abs(rate) for rate in plan.acceleration.rates.values()):
            epsilon = 0.0  # a driver at constant speed: what is left is the plan's rounding
        lines.append(f"| {number} | {_g(spec.mass)} | {_g(a_s)} | {_g(spec.mass * a_s)} | {_g(spec.inertia)} | "
                     f"{_g(epsilon)} | {_g(spec.inertia * abs(epsilon))} | {_g(spec.mass * scene.gravity)} |")
    lines.append("")
    external = [load for load in plan.loads if load.name[0] in "FM" and not load.name.startswith(("Fu", "Mu"))]
    for load in external:
        value = _polar(load.force) if load.is_force else f"{_g(load.moment)} N·m"
        acting = load.force != 0 if load.is_force else load.moment != 0
        lines.append(f"External load {load.name} on link {load.link}: {value if acting else 'not acting here'}.  ")
    lines += ["", "### Moment equations", ""]
    for group in forces.groups:
        for equation in group.moments:
            terms = ", ".join(f"{term.name}: {_g(term.moment)} N·m" + (f" (h = {_g(term.arm, 4)} m)"
                                                                        if term.arm else "")
                              for term in equation.terms)
            lines.append(f"- {group.label}: ΣM{equation.about}({equation.link}) = 0 → {equation.unknown} = "
                         f"{_g(equation.value)}" + (f"; {terms}" if terms else ""))
    exact = analysis.equilibrium
    lines += ["", "### Reactions", "", f"Force polygons at μF = {_g(forces.scale)} N/mm.", "",
              "| reaction | polygons, N ∠ | linear system, N ∠ | δ, % |", "|---|---:|---:|---:|"]
    for reaction in forces.reactions.values():
        solved = complex(exact.reaction(reaction.name).force[index]) if exact is not None else math.nan
        lines.append(f"| {reaction.name} | {_polar(reaction.force)} | {_polar(solved)} | "
                     f"{_percent(abs(reaction.force), abs(solved))} |")
    by_power = float(balancing_by_power(analysis.mechanism, motion_state(analysis.motion), analysis.loads)[index])
    lines += ["", f"### Balancing load {name}, {unit}", "", "| method | value | δ against the polygons, % |",
              "|---|---:|---:|",
              f"| force polygons | {_g(forces.balancing, 6)} | |",
              f"| Zhukovsky's lever | {_g(plan.lever.balancing, 6)} | {_percent(plan.lever.balancing, forces.balancing)} |",
              f"| linear system | {_g(float(exact.balancing[index]), 6)} | "
              f"{_percent(float(exact.balancing[index]), forces.balancing)} |",
              f"| power balance | {_g(by_power, 6)} | {_percent(by_power, forces.balancing)} |"]
    if plan.with_friction is not None:
        rubbing = plan.with_friction
        lines += ["", "### With friction in the pairs", ""]
        if rubbing.locked:
            lines.append(f"The reactions do not settle after {rubbing.iterations} repetitions: the mechanism locks "
                         "itself in this position.")
        else:
            lines.append(f"{name} = {_g(rubbing.balancing, 6)} {unit} after {rubbing.iterations} repetitions; "
                         f"without friction {_g(forces.balancing, 6)}: efficiency η = {name}0/{name} = "
                         f"{_g(efficiency(analysis.mechanism, forces.balancing, rubbing.balancing), 4)}.")
    return lines + [""]


def _cycle(analysis: Analysis, name: str, unit: str) -> list[str]:
    exact, rubbing = analysis.equilibrium, analysis.with_friction
    header = f"| position | {name}, {unit} |" + (f" {name} with friction, {unit} | η |" if rubbing is not None else "")
    lines = ["## The cycle", "", "From the linear system at every position.", "", header,
             "|---|---:|" + ("---:|---:|" if rubbing is not None else "")]
    for i, number in enumerate(analysis.positions.numbers):
        row = f"| {number} | {_g(float(exact.balancing[i]), 6)} |"
        if rubbing is not None:
            locked = bool(rubbing.locked[i])
            row += (" locked | — |" if locked else
                    f" {_g(float(rubbing.balancing[i]), 6)} | "
                    f"{_g(float(efficiency(analysis.mechanism, exact.balancing[i], rubbing.balancing[i])), 4)} |")
        lines.append(row)
    return lines + [""]
