"""The plan of positions dimensions the working link's travel between its two bold extremes, as a course drawing
marks it: a slider's stroke H, a rocker's swing ψ; a cylinder's stroke too.  Checked against the closed forms."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

import graphplan
from graphplan.render import positions
from graphplan.render.drawings import positions_plan
from graphplan.render.primitives import Polyline, Text

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


def _plan(path: Path, **replacements: str):
    text = path.read_text(encoding="utf-8")
    for old, new in replacements.items():
        assert old in text
        text = text.replace(old, new)
    plan = positions_plan(graphplan.load_text(text).analyse())
    return plan, positions.layout(plan)


def _texts(layers) -> list[str]:
    return [item.text for layer in layers for item in layer.items if isinstance(item, Text)]


def test_the_offset_slider_crank_s_stroke_is_dimensioned_at_its_length():
    """H = √((l + r)² − e²) − √((l − r)² − e²), r = 0.08, l = 0.26, e = 0.08 m (the hacksaw's guide)."""
    r, rod, e = 0.08, 0.26, 0.08
    stroke = math.sqrt((rod + r) ** 2 - e ** 2) - math.sqrt((rod - r) ** 2 - e ** 2)
    plan, layers = _plan(FIXTURES / "offset_slider_crank.toml")
    (travel,) = [layer for layer in layers if layer.name == "dimensions"]
    (written,) = [item.text for item in travel.items if isinstance(item, Text)]
    assert float(re.fullmatch(r"H = ([\d.]+) m", written).group(1)) == pytest.approx(stroke, rel=1e-4)
    # The dimension line between the arrowheads is the stroke at μl, parallel to the guide (level here).
    lines = [item for item in travel.items if isinstance(item, Polyline) and not item.fill]
    dimension_line = max(lines, key=lambda item: math.dist(*item.points))
    (x0, y0), (x1, y1) = dimension_line.points
    assert abs(x1 - x0) == pytest.approx(stroke / plan.length_scale, rel=1e-9) and y1 == pytest.approx(y0)


def test_the_crank_rocker_s_swing_is_dimensioned_by_its_angle():
    """The rocker CB's extremes are where crank OA and coupler AB stand in line, |OB| = AB ± OA: the angle OCB by
    the law of cosines at each, ψ their difference (lOC = 0.55, lOA = 0.175, lAB = 0.55, lBC = 0.325 m)."""
    oc, oa, ab, bc = 0.55, 0.175, 0.55, 0.325

    def at_c(ob: float) -> float:
        return math.degrees(math.acos((oc ** 2 + bc ** 2 - ob ** 2) / (2 * oc * bc)))

    swing = at_c(ab + oa) - at_c(ab - oa)
    _, layers = _plan(FIXTURES / "ratchet_crank_rocker.toml", **{'locale  = "ru"': 'locale  = "en"'})
    (written,) = [text for text in _texts(layers) if text.startswith("ψ = ")]
    assert float(re.fullmatch(r"ψ = ([\d.]+)°", written).group(1)) == pytest.approx(swing, abs=0.05)
    assert [layer for layer in layers if layer.name == "dimensions" and layer.items]


def _lever_angle(s: float) -> float:
    """The angle of CB (rad) with A = (s, 0), C = (0.15, 0.25), AB = 0.225, BC = 0.15, B right of A→C."""
    a, c = complex(s, 0.0), complex(0.15, 0.25)
    span = abs(c - a)
    along = (0.225 ** 2 - 0.15 ** 2 + span ** 2) / (2 * span)
    height = math.sqrt(0.225 ** 2 - along ** 2)
    unit = (c - a) / span
    b = a + unit * complex(along, -height)  # right of A→C: turned clockwise
    return math.atan2((b - c).imag, (b - c).real)


def test_a_cylinder_s_stroke_is_its_travel_and_its_lever_s_swing_is_dimensioned_too():
    """The hydraulic lever: the rod's travel H, and the lever's swing ψ between the travel's ends (it turns one way
    over the whole travel)."""
    _, layers = _plan(FIXTURES / "slider_driven.toml")
    scene = graphplan.load(FIXTURES / "slider_driven.toml")
    low, high = scene.driver.travel
    (stroke,) = [text for text in _texts(layers) if text.startswith("H = ")]
    assert float(stroke.split()[2]) == pytest.approx(abs(high - low), rel=1e-4)
    swing = abs(math.degrees(math.remainder(_lever_angle(high) - _lever_angle(low), 2 * math.pi)))
    (written,) = [text for text in _texts(layers) if text.startswith("ψ = ")]
    assert float(re.fullmatch(r"ψ = ([\d.]+)°", written).group(1)) == pytest.approx(swing, abs=0.05)


def test_a_turning_crank_with_no_working_link_has_no_dimension():
    plan = positions_plan(graphplan.load_text(TURNING).analyse())
    assert plan.travels == ()
    assert not [t for t in _texts(positions.layout(plan)) if t.startswith(("H = ", "ψ = "))]


# A crank-rocker with no working link named: its bold position is the first, no extreme to measure from.
TURNING = """
[frame]
points = { O = [0.0, 0.0], C = [0.55, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.175
omega = 10.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.55, 0.325]
assembly = "left"
[positions]
count = 12
"""


def test_a_stroke_s_text_is_set_clear_of_the_lines_and_numbers():
    """The Scotch yoke's guide runs through the crank's pivot, so the mechanism's middle lies on the stroke's own line:
    its H was set inside the crank's circle, over position 10's crank and block and against its number."""
    from graphplan.render.labels import obstacles_of, text_box

    _, layers = _plan(FIXTURES / "scotch_yoke.toml")
    (dimension,) = [layer for layer in layers if layer.name == "dimensions"]
    (written,) = [item for item in dimension.items if isinstance(item, Text)]
    others = [item for layer in layers if layer.name not in ("dimensions", "caption") for item in layer.items]
    assert others
    assert not [shape for shape in obstacles_of(others) if shape.intersects(text_box(written))]
