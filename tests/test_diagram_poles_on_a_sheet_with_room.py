"""A derivative whose pole distance stops at its greatest is drawn with a longer pole where the sheet has the room.

The slider-driven lever turns nearly uniformly over the rod's steady travel: the pole distances that would fill the
fields are about as long as the t axis, four times the greatest the usual diagrams allow, and on the A1 sheet where
the diagrams stand alone its ε4(t) stood 12 mm tall under a ψ4(t) of 94 mm.  Checked against the sheet as drawn:
each derivative's height, its pole distance as the rays show it and its scale as written agree with the textbook's
μ′ = μ/(μt·H) and with the record's values in SI; and the longer poles cost no sheet where the diagrams share one.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from pathlib import Path

import pytest

from graphplan.analysis import analyse
from graphplan.kinematic_diagrams import of_analysis
from graphplan.render.primitives import Polyline, Text
from graphplan.render.sheet import course_sheets, diagrams_panel, kinematics_sheet
from graphplan.scene import load

SLIDER_DRIVEN = Path(__file__).resolve().parent.parent / "fixtures" / "slider_driven.toml"


@functools.cache
def slider_driven(length_scale_given: bool = True):
    scene = load(SLIDER_DRIVEN)
    if not length_scale_given:
        scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, length_scale=None))
    return analyse(scene)


def _layer(sheet, name):
    return next(layer for layer in sheet.layers if layer.name == name)


def _written(sheet):
    return " ".join(item.text for layer in sheet.layers if layer.name.startswith("diagrams-")
                    for item in layer.items if isinstance(item, Text))


def _number(pattern, text):
    return float(re.search(pattern, text).group(1))


def _height(sheet, kind):
    """The drawn height (mm) of a diagram's analytic curve, measured from the axis as the field counts it."""
    ys = [y for _, y in _layer(sheet, f"diagrams-{kind}-curves").items[0].points]
    axis = _layer(sheet, f"diagrams-{kind}-axes").items[0]
    return max(max(ys), axis.start[1]) - min(min(ys), axis.start[1])


def _pole(sheet, kind):
    """The pole distance (mm) as the rays draw it: from the pole to the ordinate axis they all run to."""
    rays = [item for item in _layer(sheet, f"diagrams-{kind}-rays").items if isinstance(item, Polyline)]
    return min(ray.points[1][0] for ray in rays) - min(ray.points[0][0] for ray in rays)


def test_a_nearly_uniform_output_s_derivatives_fill_their_fields_on_a_sheet_with_room():
    analysis = slider_driven()
    record = of_analysis(analysis)
    (alone,) = kinematics_sheet([diagrams_panel(analysis, "A1")], "A1")
    written = _written(alone)
    displacement = _height(alone, "displacement")
    # Each derivative nearly as tall as the displacement over it, not an eighth of it.
    for kind in ("velocity", "acceleration"):
        assert _height(alone, kind) >= 0.75 * displacement, kind
    # The scales as written, the poles as drawn and the heights agree: μω = μψ/(μt·H1), με = μω/(μt·H2).
    mu_t = _number(r"μt = T/L = ([0-9.]+) s/mm", written)
    mu_psi = _number(r"μψ = ([0-9.]+) rad/mm", written)
    h1, h2 = _number(r"H₁ = ([0-9.]+) mm", written), _number(r"H₂ = ([0-9.]+) mm", written)
    assert _pole(alone, "velocity") == pytest.approx(h1, abs=1e-6)
    assert _pole(alone, "acceleration") == pytest.approx(h2, abs=1e-6)
    mu_omega = _number(r"μω = μψ/\(μt·H₁\) = ([0-9.]+)", written)
    mu_epsilon = _number(r"με = μω/\(μt·H₂\) = ([0-9.]+)", written)
    assert mu_omega == pytest.approx(mu_psi / (mu_t * h1), rel=5e-4)
    assert mu_epsilon == pytest.approx(mu_omega / (mu_t * h2), rel=5e-4)
    for kind, values, mu in (("velocity", record.v, mu_omega), ("acceleration", record.a, mu_epsilon)):
        reach = max(values.max(), 0.0) - min(values.min(), 0.0)
        assert _height(alone, kind) * mu == pytest.approx(reach, rel=5e-4), kind
    # No pole longer than the t axis the diagrams are drawn along.
    assert max(h1, h2) <= _number(r"L = ([0-9.]+) mm", written)


def test_the_longer_poles_cost_no_sheet_where_the_diagrams_share_one_with_the_plans():
    """Without the scene's μl the A1 sheet of the plans holds the diagrams beside them at the usual poles: the
    longer poles, one way more of the panel, leave them there."""
    analysis = slider_driven(length_scale_given=False)
    sheets = course_sheets(analysis, "A1", diagrams=(diagrams_panel(analysis, "A1"),))
    (shared,) = [sheet for sheet in sheets if "diagrams" in sheet.panels]
    assert any(name.startswith("plan") for name in shared.panels), sorted(shared.panels)
