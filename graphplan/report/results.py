"""``results.json``: the analysis as the public contract of ``scene-format.md`` spells it.

Values are SI, angles in degrees; numbers are rounded to 12 significant
digits so that the file reads cleanly and is byte-identical across runs.
"""

from __future__ import annotations

import json
import math
import platform
from importlib import metadata
from typing import Any

import numpy as np

from .. import __version__
from ..analysis import Analysis, PlanPosition
from ..kinematics import as_xy, at
from ..statics import efficiency

SIGNIFICANT = 12


def number(value: float) -> float | None:
    """``value`` rounded to :data:`SIGNIFICANT` digits, with −0 written as 0.

    A value that is not a number (a velocity at a singular position) is
    written as null, never as NaN.
    """
    if not math.isfinite(float(value)):
        return None
    rounded = float(f"{float(value):.{SIGNIFICANT}g}")
    return 0.0 if rounded == 0 else rounded


def _pair(xy: np.ndarray) -> list[float | None] | None:
    pair = [number(xy[0]), number(xy[1])]
    return None if None in pair else pair


def results(analysis: Analysis) -> dict[str, Any]:
    """The results document of one analysis."""
    mechanism, motion, positions = analysis.mechanism, analysis.motion, analysis.positions
    count = motion.count
    driver = mechanism.driver
    points = {name: [as_xy(getattr(p, field), count) for field in ("r", "v", "a")] for name, p in motion.points.items()}
    links = {number_: motion.link(number_) for number_ in mechanism.moving_links}
    planned = {plan.index: plan for plan in analysis.plans}
    settled = {*analysis.scene.frame_points, driver.joint, driver.link}
    entries = []
    for i in range(count):
        if driver.kind == "crank":
            driver_entry = {"angle_deg": number(math.degrees(positions.values[i]) % 360.0),
                            "omega": number(driver.omega), "epsilon": number(driver.epsilon)}
        else:
            driver_entry = {"displacement": number(positions.values[i]), "velocity": number(driver.velocity),
                            "acceleration": number(driver.acceleration)}
        entry: dict[str, Any] = {"index": int(positions.numbers[i]), "driver": driver_entry}
        if positions.strokes is not None:
            entry["stroke"] = positions.strokes[i]
        # At a singular position the velocities past the driver are not determined: they are null.
        known = (lambda name: True) if i not in motion.singular else (lambda name: name in settled)
        entry["points"] = {name: {"r": _pair(r[i]), "v": _pair(v[i]) if known(name) else None,
                                  "a": _pair(a[i]) if known(name) else None}
                           for name, (r, v, a) in points.items()}
        entry["links"] = {str(n): {"angle_deg": number(math.degrees(float(link.angle[i]))),
                                   "omega": number(link.omega[i]) if known(n) else None,
                                   "epsilon": number(link.epsilon[i]) if known(n) else None}
                          for n, link in links.items()}
        slides = [_slide(slide, i) for slide in motion.slides] if i not in motion.singular else []
        if slides:
            entry["slides"] = slides
        if i in planned:
            entry["plans"] = _plans(planned[i])
            if planned[i].forces is not None:
                entry["forces"] = _forces(planned[i], mechanism)
        if analysis.equilibrium is not None:
            entry["equilibrium"] = _equilibrium(analysis.equilibrium, i, driver.kind)
            if analysis.with_friction is not None:
                rubbing = analysis.with_friction
                entry["equilibrium"]["friction"] = {
                    **_equilibrium(rubbing, i, driver.kind, blank=bool(rubbing.locked[i])),
                    "efficiency": None if rubbing.locked[i] else number(
                        efficiency(mechanism, analysis.equilibrium.balancing[i], rubbing.balancing[i])),
                    "iterations": int(rubbing.iterations[i]),
                    "self_locking": bool(rubbing.locked[i]),
                }
        entries.append(entry)
    n, p5, w = mechanism.degrees_of_freedom
    document: dict[str, Any] = {
        "graphplan": __version__,
        "versions": versions(),
        "scene": analysis.scene.title,
        "structure": mechanism.structure,
        "degrees_of_freedom": {"moving_links": n, "lower_pairs": p5, "W": w},
        "groups": [{"label": g.label, "kind": g.kind, "links": list(g.links), "joints": list(g.joints)}
                   for g in mechanism.groups],
    }
    if positions.extremes is not None:
        document["extremes_deg"] = [number(math.degrees(value) % 360.0) for value in positions.extremes]
        working, idle = positions.stroke_turns(mechanism.driver.sense)
        document["strokes"] = {"working_deg": number(math.degrees(working)), "idle_deg": number(math.degrees(idle)),
                               "time_ratio": number(working / idle)}
    document["positions"] = entries
    errors = [row for plan in analysis.plans for row in plan.errors]
    if errors:
        document["errors"] = [{"position": row.position, "quantity": row.quantity, "analytic": number(row.analytic),
                               "plan": number(row.plan), "source": row.source, "percent": number(row.percent)}
                              for row in errors]
    document["warnings"] = [{"position": int(positions.numbers[w.position]), "code": w.code, "detail": w.detail}
                            for w in analysis.warnings]
    return document


# The libraries whose arithmetic or geometry the numbers and drawings depend on.
DEPENDENCIES = ("numpy", "scipy", "shapely", "svgwrite")


def versions() -> dict[str, str]:
    """The versions of Python, graphplan and its main dependencies, so that a result can be reproduced."""
    found = {"python": platform.python_version(), "graphplan": __version__}
    for name in DEPENDENCIES:
        try:
            found[name] = metadata.version(name)
        except metadata.PackageNotFoundError:  # run from a source tree without the package installed
            found[name] = "unknown"
    return found


def rounded(value: Any) -> Any:
    """``value`` with every float in it rounded by :func:`number` (lists and dicts walked through)."""
    if isinstance(value, dict):
        return {key: rounded(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [rounded(item) for item in value]
    if isinstance(value, float):
        return number(value)
    return value


def results_without_linkage(scene) -> dict[str, Any]:
    """The head of ``results.json`` for a scene with no mechanism (a rotor, a vibrating machine)."""
    return {"graphplan": __version__, "versions": versions(), "scene": scene.title}


def _plans(plan: PlanPosition) -> dict[str, Any]:
    """``plans`` of one position: scale, the plan points in mm, the values read off the plan as constructed."""
    result = {}
    for kind, drawn in plan.plans.items():
        values = {reading.quantity: number(reading.value(plan.plans)) for reading in plan.readings if reading.plan == kind}
        result[kind] = {"scale": number(drawn.scale),
                        "points_mm": {letter: _pair(np.array([drawn.mm(letter).real, drawn.mm(letter).imag]))
                                      for letter in drawn.points},
                        "values": values}
    return result


def _balancing_key(driver_kind: str) -> str:
    return "balancing_moment" if driver_kind == "crank" else "balancing_force"


def _forces(plan: PlanPosition, mechanism) -> dict[str, Any]:
    """``forces`` of one plan position: the polygons' reactions and balancing load, the lever's, μF;
    with friction in the pairs the same with friction, the efficiency and the self-locking flag."""
    forces, lever = plan.forces, plan.lever
    key = _balancing_key(mechanism.driver.kind)
    result: dict[str, Any] = {
        "reactions": {name: _pair(np.array([found.force.real, found.force.imag]))
                      for name, found in forces.reactions.items()},
        key: number(forces.balancing),
        f"lever_{key}": number(lever.balancing),
        "lever_difference_percent": number(lever.difference_percent(forces.balancing)),
        "polygon_scale": number(forces.scale),
        "polygon_scales": {label: number(scale) for label, scale in forces.group_scales.items()},
    }
    offsets = {name: number(found.offset) for name, found in forces.reactions.items() if found.offset is not None}
    if offsets:
        result["offsets"] = offsets
    rubbing = plan.with_friction
    if rubbing is not None:
        result["friction"] = {
            key: None if rubbing.locked else number(rubbing.balancing),
            "efficiency": None if rubbing.locked else number(efficiency(mechanism, forces.balancing, rubbing.balancing)),
            "iterations": rubbing.iterations,
            "self_locking": rubbing.locked,
            "reactions": None if rubbing.locked else {
                name: _pair(np.array([found.force.real, found.force.imag])) for name, found in rubbing.reactions.items()},
        }
        if plan.lever_with_friction is not None:
            result["friction"][f"lever_{key}"] = number(plan.lever_with_friction.balancing)
            result["friction"]["lever_difference_percent"] = number(
                plan.lever_with_friction.difference_percent(rubbing.balancing))
    return result


def _equilibrium(balance, i: int, driver_kind: str, blank: bool = False) -> dict[str, Any]:
    """The whole-mechanism linear system at one position: null where it is singular (or ``blank``)."""
    if balance.singular[i] or blank:
        return {_balancing_key(driver_kind): None, "reactions": None}
    result: dict[str, Any] = {
        _balancing_key(driver_kind): number(balance.balancing[i]),
        "reactions": {r.name: _pair(np.array([r.force[i].real, r.force[i].imag])) for r in balance.reactions},
    }
    offsets = {r.name: number(r.offset[i]) for r in balance.reactions if r.sliding}
    if offsets:
        result["offsets"] = offsets
    return result


def _slide(slide, i: int) -> dict[str, Any]:
    return {"slider": slide.slider, "guide": slide.guide, "joint": slide.joint,
            "velocity": number(at(slide.velocity, i)), "acceleration": number(at(slide.acceleration, i))}


def dumps(document: dict[str, Any]) -> str:
    return json.dumps(document, ensure_ascii=False, indent=1, allow_nan=False) + "\n"
