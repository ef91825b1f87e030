"""μF of a force polygon of no area, all its vectors on one line: the coarsest of the position's other polygons'.

A crank with no weight of its own balances R32 with R12 alone: its polygon ΣF2 + R12 = 0 is two opposite vectors
on one line, which shows no more at the 150 mm field than at the μF of the polygon whose reaction it carries, and
at the field takes a sheet's room as one thin diagonal.  Each polygon's span and the standard μF that fits it are
worked out here from its vectors, apart from the program's own choice.
"""

from __future__ import annotations

import math
from functools import cache
from itertools import pairwise
from pathlib import Path

import pytest
from scene_texts import crank_rocker_working_its_quicker_stroke, journal_friction

import graphplan
from graphplan.analysis import analyse
from graphplan.forces import POLYGON_FIELD_MM, Polygon, PolygonVector, _chosen_scales
from graphplan.scales import STANDARD_MANTISSAS
from graphplan.starters import starter

FIXTURES = Path(__file__).parent.parent / "fixtures"
DRIVER = "I(1,2)"
# The crank-rocker starter's pairs with friction circles, as a course project gives them.
FRICTION = journal_friction({"O": 0.02, "A": 0.015, "B": 0.015, "C": 0.02})


@cache
def _analysis(text: str):
    return analyse(graphplan.load_text(text))


def _crank_rocker(extra: str = ""):
    return _analysis(starter("crank-rocker") + extra)


def _crank_rocker_working_its_quicker_stroke():
    return _analysis(crank_rocker_working_its_quicker_stroke())


def _fixture(name: str):
    return _analysis((FIXTURES / f"{name}.toml").read_text(encoding="utf-8"))


def _vertices(polygon) -> list[complex]:
    return [point for vector in polygon.vectors for point in (vector.start, vector.end)]


def _span(polygon) -> float:
    """The largest distance between two of the polygon's vertices, N."""
    vertices = _vertices(polygon)
    return max(abs(one - other) for one in vertices for other in vertices)


def _width(polygon) -> float:
    """How far the polygon's vertices stand off the line through its first vector, N (by the cross product)."""
    vertices = _vertices(polygon)
    base = next(vector for vector in polygon.vectors if abs(vector.force) > 0)
    along = base.force / abs(base.force)
    return max(abs((along.conjugate() * (vertex - base.start)).imag) for vertex in vertices)


def _fitting(span: float) -> float:
    """The least of the standard μF 1, 2, 2.5, 4, 5 × 10ᵏ N/mm at which ``span`` N is at most 150 mm long."""
    least = span / 150.0
    exponent = math.floor(math.log10(least))
    candidates = [mantissa * 10.0 ** power for power in range(exponent - 1, exponent + 2)
                  for mantissa in (1, 2, 2.5, 4, 5)]
    return min(value for value in candidates if value >= least * (1 - 1e-12))


def test_the_standard_mantissas_are_the_ones_counted_here():
    assert STANDARD_MANTISSAS == (1.0, 2.0, 2.5, 4.0, 5.0)
    assert POLYGON_FIELD_MM == 150.0


@pytest.mark.parametrize("number", [5, 11])
def test_a_weightless_cranks_polygon_lies_on_one_line_and_takes_the_coarsest_of_the_others(number):
    # Worked in its slower stroke, the crank's own field's μF is the coarsest at both positions.
    plan = next(plan for plan in _crank_rocker_working_its_quicker_stroke().plans if plan.number == number)
    groups = {group.label: group for group in plan.forces.groups}
    driver = groups.pop(DRIVER)
    span = _span(driver.polygon)
    assert span > 0
    assert _width(driver.polygon) <= 1e-9 * span  # R32 and R12: opposite, on one line
    others = [_fitting(_span(group.polygon)) for group in groups.values()]
    assert [group.scale for group in groups.values()] == others  # the others keep their own field's μF
    assert driver.scale == max(others)
    # Its own field's μF is finer: the rule changes it here, and draws it shorter than its field.
    assert _fitting(span) < driver.scale
    for vector in driver.polygon.vectors:
        assert abs(vector.force) / driver.scale <= POLYGON_FIELD_MM
    assert span / driver.scale <= POLYGON_FIELD_MM
    # The position's μF, at which every polygon fits its field, is still the coarsest.
    assert plan.forces.scale == max(others)


@pytest.mark.parametrize("name, number", [("ratchet_crank_rocker", 5), ("ratchet_crank_rocker", 11),
                                          ("shaper_six_bar", 3), ("shaper_six_bar", 10)])
def test_a_polygon_with_an_area_keeps_its_own_fields_scale(name, number):
    """The ratchet's crank has a weight, G2, which stands off R12's line; the shaper's crank polygon is a thin
    triangle, 2 % of its span across at position 3, and its own μF finer than group II(3,4)'s."""
    plan = next(plan for plan in _fixture(name).plans if plan.number == number)
    driver = next(group for group in plan.forces.groups if group.label == DRIVER)
    assert _width(driver.polygon) > 1e-3 * _span(driver.polygon)
    for group in plan.forces.groups:
        assert group.scale == _fitting(_span(group.polygon)), group.label
    if (name, number) == ("shaper_six_bar", 3):
        assert driver.scale < max(group.scale for group in plan.forces.groups)


def test_the_polygons_with_friction_keep_the_scales_without_it():
    """With friction the crank's polygon is still R32 and R12 on one line (the friction circles add moments, no
    force): it keeps the μF of the one without friction, the others' coarsest, as every polygon keeps its own."""
    analysis = _crank_rocker(FRICTION)
    for plan in analysis.plans:
        ideal, rubbing = plan.forces, plan.with_friction
        assert rubbing is not None and not rubbing.locked
        driver = next(group for group in rubbing.groups if group.label == DRIVER)
        assert _width(driver.polygon) <= 1e-9 * _span(driver.polygon)
        assert rubbing.group_scales == ideal.group_scales
        assert driver.scale == max(scale for label, scale in ideal.group_scales.items() if label != DRIVER)
        assert _span(driver.polygon) / driver.scale <= POLYGON_FIELD_MM


def test_a_scale_the_scene_sets_draws_every_polygon_at_it():
    text = starter("crank-rocker").replace("[drawing]\n", "[drawing]\nforce_scale = 20.0\n", 1)
    analysis = _analysis(text + FRICTION)
    assert analysis.scene.drawing.force_scale == 20.0
    for plan in analysis.plans:
        for forces in (plan.forces, plan.with_friction):
            assert forces.scale == 20.0
            assert set(forces.group_scales.values()) == {20.0}


def _polygon(*points: complex) -> Polygon:
    """A polygon through ``points`` in turn, closed back to the first."""
    ends = (*points, points[0])
    return Polygon("", tuple(PolygonVector(f"F{index}", start, end, "load")
                             for index, (start, end) in enumerate(pairwise(ends))))


class _Group:
    def __init__(self, label: str, polygon: Polygon):
        self.label, self.polygon = label, polygon


def test_a_polygon_on_one_line_is_never_drawn_larger_than_its_field():
    """Where its own field's μF is the coarser (its span the largest), the polygon on one line keeps it: the rule
    only ever draws it smaller.  A polygon of no length takes the coarsest of all."""
    line = _polygon(0j, 3000 + 4000j)  # 5000 N: 40 N/mm at 150 mm
    triangle = _polygon(0j, 600 + 0j, 600j)  # 849 N across: 10 N/mm
    nothing = _polygon(0j, 0j)
    scales = _chosen_scales((_Group("II", triangle), _Group("I", line), _Group("III", nothing)))
    assert scales == {"II": _fitting(600 * math.sqrt(2)), "I": _fitting(5000.0), "III": _fitting(5000.0)}
    assert (scales["II"], scales["I"]) == (10.0, 40.0)
    smaller = _polygon(0j, 300 + 400j, 150 + 200j)  # on one line, 500 N: 4 N/mm at its field
    assert _chosen_scales((_Group("II", triangle), _Group("I", smaller))) == {"II": 10.0, "I": 10.0}
    # Only on one line to the arithmetic's rounding: a vertex 1 N off a 500 N line gives the polygon an area.
    bent = _polygon(0j, 300 + 400j, 150 + 200j + 0.8 - 0.6j)
    assert _width(bent) > 0.9
    assert _chosen_scales((_Group("II", triangle), _Group("I", bent))) == {"II": 10.0, "I": 4.0}
