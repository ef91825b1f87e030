"""``results.json``: the analysis as the public contract of ``scene-format.md`` spells it.

Values are SI, angles in degrees; numbers are rounded to 12 significant
digits so that the file reads cleanly and is byte-identical across runs.
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from .. import __version__
from ..analysis import Analysis, PlanPosition
from ..kinematics import as_xy, at

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
        entries.append(entry)
    n, p5, w = mechanism.degrees_of_freedom
    document: dict[str, Any] = {
        "graphplan": __version__,
        "scene": analysis.scene.title,
        "structure": mechanism.structure,
        "degrees_of_freedom": {"moving_links": n, "lower_pairs": p5, "W": w},
        "groups": [{"label": g.label, "kind": g.kind, "links": list(g.links), "joints": list(g.joints)}
                   for g in mechanism.groups],
    }
    if positions.extremes is not None:
        document["extremes_deg"] = [number(math.degrees(value) % 360.0) for value in positions.extremes]
    document["positions"] = entries
    errors = [row for plan in analysis.plans for row in plan.errors]
    if errors:
        document["errors"] = [{"position": row.position, "quantity": row.quantity, "analytic": number(row.analytic),
                               "plan": number(row.plan), "source": row.source, "percent": number(row.percent)}
                              for row in errors]
    document["warnings"] = [{"position": int(positions.numbers[w.position]), "code": w.code, "detail": w.detail}
                            for w in analysis.warnings]
    return document


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


def _slide(slide, i: int) -> dict[str, Any]:
    return {"slider": slide.slider, "guide": slide.guide, "joint": slide.joint,
            "velocity": number(at(slide.velocity, i)), "acceleration": number(at(slide.acceleration, i))}


def dumps(document: dict[str, Any]) -> str:
    return json.dumps(document, ensure_ascii=False, indent=1, allow_nan=False) + "\n"
