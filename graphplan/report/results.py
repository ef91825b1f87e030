"""``results.json``: the analysis as the public contract of ``scene-format.md`` spells it.

Values are SI, angles in degrees; numbers are rounded to 12 significant
digits so that the file reads cleanly and is byte-identical across runs.
A value is also rounded to 12 digits of its quantity's largest, so that a
coordinate or a velocity that is zero by the geometry (the crank along the
line of stroke) reads 0, not the 1e-18 that the trigonometry leaves.
"""

from __future__ import annotations

import json
import math
import platform
import sys
from typing import Any

import numpy as np

from .. import __version__
from ..analysis import Analysis, PlanPosition, VelocityPosition
from ..check import epsilon_of_another
from ..cycle_work import CycleWork
from ..forces import Load
from ..joint_friction import FrictionPair, friction_loads
from ..kinematics import as_xy, at
from ..loads import motion_state
from ..rounding import ANGLE_FLOOR_DEG, PERCENT_FLOOR, SIGNIFICANT, noise_floor
from ..statics import efficiency


def number(value: float, noise: float = 0.0) -> float | None:
    """``value`` rounded to :data:`SIGNIFICANT` digits, with −0 written as 0.

    A value smaller than ``noise`` is written as 0. A value that is not a
    number (a velocity at a singular position) is written as null, never as NaN.
    """
    if not math.isfinite(float(value)):
        return None
    if abs(float(value)) < noise:
        return 0.0
    rounded = float(f"{float(value):.{SIGNIFICANT}g}")
    return 0.0 if rounded == 0 else rounded


KEY_FLOORS = {"deg": ANGLE_FLOOR_DEG, "percent": PERCENT_FLOOR}


def _pair(xy: np.ndarray, noise: float = 0.0) -> list[float | None] | None:
    pair = [number(xy[0], noise), number(xy[1], noise)]
    return None if None in pair else pair


def results(analysis: Analysis) -> dict[str, Any]:
    """The results document of one analysis."""
    mechanism, motion, positions = analysis.mechanism, analysis.motion, analysis.positions
    count = motion.count
    driver = mechanism.driver
    points = {name: [as_xy(getattr(p, field), count) for field in ("r", "v", "a")] for name, p in motion.points.items()}
    links = {number_: motion.link(number_) for number_ in mechanism.moving_links}
    r_floor, v_floor, a_floor = (noise_floor([np.hypot(*xyz[k].T) for xyz in points.values()]) for k in range(3))
    omega_floor = noise_floor([link.omega for link in links.values()]) if links else 0.0
    epsilon_floor = noise_floor([link.epsilon for link in links.values()]) if links else 0.0
    slide_floors = (noise_floor([np.broadcast_to(s.velocity, count) for s in motion.slides]),
                    noise_floor([np.broadcast_to(s.acceleration, count) for s in motion.slides])
                    ) if motion.slides else (0.0, 0.0)
    balance, rubbing = analysis.equilibrium, analysis.with_friction
    balance_noise = _cycle_noise(balance) if balance is not None else {}
    rubbing_noise = _cycle_noise(rubbing) if balance is not None and rubbing is not None else {}
    if rubbing_noise:
        # Mb's scale is Mb0's, give or take the friction's share; where the friction locks every position but the
        # dead centres, Mb's own largest is their rounding noise, which only Mb0's scale tells for noise.
        rubbing_noise["balancing"] = max(rubbing_noise["balancing"], balance_noise["balancing"])
    rubbing_loads = _cycle_friction_loads(analysis) if balance is not None and rubbing is not None else {}
    planned = {plan.index: plan for plan in analysis.plans}
    velocity_planned = {position.index: position for position in analysis.velocity_plans}
    settled = {*analysis.scene.frame_points, driver.joint, driver.link}
    entries = []
    for i in range(count):
        if driver.kind == "crank":
            driver_entry = {"angle_deg": number(_turn_deg(positions.values[i]), ANGLE_FLOOR_DEG),
                            "omega": number(driver.omega), "epsilon": number(driver.epsilon)}
        else:
            driver_entry = {"displacement": number(positions.values[i]), "velocity": number(driver.velocity),
                            "acceleration": number(driver.acceleration)}
        entry: dict[str, Any] = {"index": int(positions.numbers[i]), "driver": driver_entry}
        if positions.strokes is not None:
            entry["stroke"] = positions.strokes[i]
        # At a singular position the velocities past the driver are not determined: they are null.
        known = (lambda name: True) if i not in motion.singular else (lambda name: name in settled)
        entry["points"] = {name: {"r": _pair(r[i], r_floor), "v": _pair(v[i], v_floor) if known(name) else None,
                                  "a": _pair(a[i], a_floor) if known(name) else None}
                           for name, (r, v, a) in points.items()}
        entry["links"] = {str(n): {"angle_deg": number(_half_turn_deg(float(link.angle[i])), ANGLE_FLOOR_DEG),
                                   "omega": number(link.omega[i], omega_floor) if known(n) else None,
                                   "epsilon": number(link.epsilon[i], epsilon_floor) if known(n) else None}
                          for n, link in links.items()}
        if motion.slides:
            entry["slides"] = [_slide(slide, i, slide_floors, i not in motion.singular) for slide in motion.slides]
        if i in velocity_planned:
            entry["velocity_plan"] = _plans(velocity_planned[i])["velocity"]
        if i in planned:
            entry["plans"] = _plans(planned[i])
            if planned[i].forces is not None:
                entry["forces"] = _forces(planned[i], mechanism, analysis.friction, analysis.balancing_scale)
        if balance is not None:
            entry["equilibrium"] = _equilibrium(balance, i, driver.kind, balance_noise)
            if rubbing is not None:
                entry["equilibrium"]["friction"] = {
                    **_equilibrium(rubbing, i, driver.kind, rubbing_noise, blank=bool(rubbing.locked[i])),
                    "loads": None if rubbing.locked[i] or rubbing.singular[i] else _friction_loads(
                        analysis.friction, rubbing_loads, rubbing_noise["reactions"], i),
                    "efficiency": None if rubbing.locked[i] else number(
                        efficiency(mechanism, balance.balancing[i], rubbing.balancing[i], analysis.balancing_scale)),
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
        document["extremes_deg"] = [number(_turn_deg(value), ANGLE_FLOOR_DEG) for value in positions.extremes]
        strokes = analysis.strokes
        document["strokes"] = {"working_deg": number(math.degrees(strokes.working)),
                               "idle_deg": number(math.degrees(strokes.idle)), "time_ratio": number(strokes.time_ratio)}
    if analysis.cycle is not None:
        document["cycle_efficiency"] = _cycle_efficiency(analysis.cycle)
    document["positions"] = entries
    # Always a list, as `warnings` is: a script reading the contract's `errors` of a scene with no plans finds none.
    document["errors"] = [{"position": row.position, "quantity": row.quantity, "analytic": number(row.analytic),
                           "plan": number(row.plan), "source": row.source, "percent": number(row.percent, PERCENT_FLOOR)}
                          for row in analysis.errors]
    document["warnings"] = [{"position": int(positions.numbers[w.position]), "code": w.code, "detail": w.detail}
                            for w in analysis.warnings]
    return document


def _cycle_efficiency(cycle: CycleWork) -> dict[str, Any]:
    """The driver's works over the cycle (J) and η over it; null with friction where the friction locks the
    mechanism on the way, and η null where the friction takes all that loads driving the driver give."""
    return {"work_without_friction": number(cycle.without_friction),
            "work_with_friction": number(cycle.with_friction), "friction_work": number(cycle.friction),
            "efficiency": number(cycle.efficiency), "loads_drive": cycle.loads_drive, "self_locking": cycle.locked,
            "samples": cycle.samples}


# The libraries whose arithmetic or geometry the numbers and drawings depend on.
DEPENDENCIES = ("numpy", "scipy", "shapely", "svgwrite")


def _turn_deg(angle: float) -> float:
    """``angle`` in degrees within [0, 360), a hair below 360 read as 0."""
    degrees = math.degrees(angle) % 360.0
    return 0.0 if 360.0 - degrees < ANGLE_FLOOR_DEG else degrees


def _half_turn_deg(angle: float) -> float:
    """A link's ``angle`` (rad, a crank's counted on round the turns) in degrees within (−180, 180]: a link along
    −x reads 180, whichever sign rounding left on the zero across it."""
    degrees = math.degrees(angle)
    if not -180.0 <= degrees <= 180.0:  # a crank's angle: brought into the half turns (the others are there)
        degrees = (degrees + 180.0) % 360.0 - 180.0
    return 180.0 if abs(degrees + 180.0) < ANGLE_FLOOR_DEG else degrees


def versions() -> dict[str, str]:
    """The versions of Python, graphplan and its main dependencies, so that a result can be reproduced."""
    found = {"python": platform.python_version(), "graphplan": __version__}
    for name in DEPENDENCIES:
        # A library the run has imported tells its version itself (numpy and shapely, always): importlib.metadata
        # would search the installed distributions for it.  One not imported (scipy, svgwrite before the drawings) is
        # asked of its distribution: importing it would cost a run that needs none of it.
        module = sys.modules.get(name)
        if module is not None and isinstance(getattr(module, "__version__", None), str):
            found[name] = module.__version__
            continue
        from importlib import metadata

        try:
            found[name] = metadata.version(name)
        except metadata.PackageNotFoundError:  # run from a source tree without the package installed
            found[name] = "unknown"
    return found


def rounded(value: Any, key: str = "") -> Any:
    """``value`` with every float in it rounded by :func:`number`, lists and dicts walked through.

    A list of numbers is one quantity (a value per sample of the cycle, a vector's components) and
    its rounding noise is judged against its largest member; a value under a key that ends in
    ``_deg`` or ``_percent`` is judged against the full turn or the whole.
    """
    if isinstance(value, dict):
        return {name: rounded(item, name) for name, item in value.items()}
    if isinstance(value, (list, tuple)):
        if value and all(_is_number(item) for item in value):
            noise = noise_floor(value)
            return [number(item, noise) if isinstance(item, float) else item for item in value]
        return [rounded(item) for item in value]
    if isinstance(value, float):
        return number(value, KEY_FLOORS.get(key.rsplit("_", 1)[-1], 0.0))
    return value


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def results_without_linkage(scene) -> dict[str, Any]:
    """The head of ``results.json`` for a scene with no mechanism (a rotor, a vibrating machine)."""
    return {"graphplan": __version__, "versions": versions(), "scene": scene.title}


def _plans(plan: VelocityPosition) -> dict[str, Any]:
    """``plans`` of one position: scale, the plan points in mm, the values read off the plan as constructed.

    A link that turns with another (an RPR's rod in its cylinder) has no tangential component of its own on the
    acceleration plan, yet a script reading its ε for the inertia loads looks for it under its own name: it is
    written with the other's value, and ``same_as`` says whose reading it is.
    """
    result = {}
    for kind, drawn in plan.plans.items():
        values = {reading.quantity: reading.value(plan.plans) for reading in plan.readings if reading.plan == kind}
        same_as = {f"epsilon{link}": f"epsilon{other}" for link, other in
                   sorted(epsilon_of_another(plan.plans, plan.readings).items())} if kind == "acceleration" else {}
        values.update({quantity: values[other] for quantity, other in same_as.items()})
        points_mm = {letter: drawn.mm(letter) for letter in drawn.points}
        points_floor, values_floor = noise_floor(list(points_mm.values())), noise_floor(list(values.values()))
        result[kind] = {"scale": number(drawn.scale),
                        "points_mm": {letter: _pair(np.array([mm.real, mm.imag]), points_floor)
                                      for letter, mm in points_mm.items()},
                        "values": {quantity: number(value, values_floor) for quantity, value in values.items()}}
        if same_as:
            result[kind]["same_as"] = same_as
    return result


def _balancing_key(driver_kind: str) -> str:
    return "balancing_moment" if driver_kind == "crank" else "balancing_force"


def _forces(plan: PlanPosition, mechanism, friction: tuple[FrictionPair, ...], scale: float) -> dict[str, Any]:
    """``forces`` of one plan position: the polygons' reactions and balancing load, the lever's, μF;
    with friction in the pairs the same with friction, the efficiency and the self-locking flag."""
    forces, lever = plan.forces, plan.lever
    key = _balancing_key(mechanism.driver.kind)
    reaction_floor = noise_floor([found.force for found in forces.reactions.values()])
    result: dict[str, Any] = {
        "reactions": {name: _pair(np.array([found.force.real, found.force.imag]), reaction_floor)
                      for name, found in forces.reactions.items()},
        key: number(forces.balancing),
        f"lever_{key}": number(lever.balancing),
        "lever_difference_percent": number(lever.difference_percent(forces.balancing), PERCENT_FLOOR),
        "polygon_scale": number(forces.scale),
        "polygon_scales": {label: number(scale) for label, scale in forces.group_scales.items()},
    }
    offsets = {name: _offset(found.force, found.offset, reaction_floor)
               for name, found in forces.reactions.items() if found.offset is not None}
    if offsets:
        result["offsets"] = offsets
    rubbing = plan.with_friction
    if rubbing is not None:
        acting = {load.name: load for load in plan.friction_loads}
        result["friction"] = {
            key: None if rubbing.locked else number(rubbing.balancing),
            "efficiency": None if rubbing.locked else number(
                efficiency(mechanism, forces.balancing, rubbing.balancing, scale)),
            "iterations": rubbing.iterations,
            "self_locking": rubbing.locked,
            "reactions": None if rubbing.locked else {
                name: _pair(np.array([found.force.real, found.force.imag]), reaction_floor)
                for name, found in rubbing.reactions.items()},
            "loads": None if rubbing.locked else _friction_loads(friction, acting, reaction_floor),
        }
        if plan.lever_with_friction is not None:
            result["friction"][f"lever_{key}"] = number(plan.lever_with_friction.balancing)
            result["friction"]["lever_difference_percent"] = number(
                plan.lever_with_friction.difference_percent(rubbing.balancing), PERCENT_FLOOR)
    return result


def _friction_loads(pairs: tuple[FrictionPair, ...], acting: dict[str, Load], reaction_floor: float,
                    i: int = 0) -> dict[str, Any]:
    """Each pair's friction load on its later link from its earlier (``Ff16`` on 6 from 1), as the tables name
    it: a slide's force [x, y] (N), a journal's moment (N·m, counter-clockwise positive); 0 in a pair at rest.

    ``acting`` holds the loads at one position or, as arrays, at every position (then ``i`` picks one)."""
    result: dict[str, Any] = {}
    for pair in pairs:
        name = pair.load_names[0]
        load = acting[name]
        if pair.sliding:
            force = complex(at(load.force, i))
            result[name] = _pair(np.array([force.real, force.imag]), reaction_floor * pair.coefficient)
        else:
            result[name] = number(float(at(load.moment, i)), reaction_floor * pair.radius)
    return result


def _cycle_friction_loads(analysis: Analysis) -> dict[str, Load]:
    """The pairs' friction loads at every position, from the reactions with friction settled there (the
    locked positions' are not numbers)."""
    settled = {reaction.name: reaction.force for reaction in analysis.with_friction.reactions}
    with np.errstate(invalid="ignore"):
        loads = friction_loads(analysis.friction, motion_state(analysis.motion), settled)
    return {load.name: load for load in loads}


def _cycle_noise(balance) -> dict[str, Any]:
    """The noise floors of the whole-mechanism system over the cycle: of its balancing load, of its
    reactions, and of each sliding pair's offset; judged by the positions that do not lock, whose
    reactions, grown without bound, would make every other one noise."""
    moving = ~np.asarray(balance.locked, dtype=bool)
    reactions = noise_floor([r.force[moving] for r in balance.reactions])
    return {"balancing": noise_floor(balance.balancing[moving]), "reactions": reactions,
            "offsets": {r.name: noise_floor(np.where(np.abs(r.force) < reactions, np.nan, r.offset)[moving])
                        for r in balance.reactions if r.sliding}}


def _equilibrium(balance, i: int, driver_kind: str, noise: dict[str, Any], blank: bool = False) -> dict[str, Any]:
    """The whole-mechanism linear system at one position: null where it is singular (or ``blank``).

    Rounding noise is judged against the whole cycle's (``noise``, from :func:`_cycle_noise`)."""
    if balance.singular[i] or blank:
        return {_balancing_key(driver_kind): None, "reactions": None}
    result: dict[str, Any] = {
        _balancing_key(driver_kind): number(balance.balancing[i], noise["balancing"]),
        "reactions": {r.name: _pair(np.array([r.force[i].real, r.force[i].imag]), noise["reactions"])
                      for r in balance.reactions},
    }
    offsets = {r.name: _offset(r.force[i], r.offset[i], noise["reactions"], noise["offsets"][r.name])
               for r in balance.reactions if r.sliding}
    if offsets:
        result["offsets"] = offsets
    return result


def _offset(force: complex, offset: float, force_floor: float, noise: float = 0.0) -> float | None:
    """Where along its slide a sliding pair's normal reaction acts; null where there is no normal reaction
    (below the reactions' noise): the guide then holds a couple alone, if anything, and the shift found by
    dividing by the rounding noise of the force would be a number of no meaning (10¹⁵ m in the scotch yoke)."""
    return None if abs(force) < force_floor else number(offset, noise)


def _slide(slide, i: int, floors: tuple[float, float], known: bool) -> dict[str, Any]:
    velocity_floor, acceleration_floor = floors
    return {"slider": slide.slider, "guide": slide.guide, "joint": slide.joint,
            "velocity": number(at(slide.velocity, i), velocity_floor) if known else None,
            "acceleration": number(at(slide.acceleration, i), acceleration_floor) if known else None}


def dumps(document: dict[str, Any]) -> str:
    return json.dumps(document, ensure_ascii=False, indent=1, allow_nan=False) + "\n"
