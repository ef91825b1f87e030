"""Balancing rotating masses by polygons, against published answers and an independent linear system.

Static balancing is checked against two published worked examples (sources
at each test and in docs/sources/rotor-balancing.md).  Dynamic balancing,
which splits each mass-radius product between the two correction planes by
moments and closes a polygon in each, is checked against the four
equilibrium equations of the corrected rotor (ΣFx, ΣFy, ΣMx, ΣMy = 0)
solved as one 4×4 linear system with numpy, on published problems' data;
and, with hypothesis, for any rotor: the corrected rotor has neither
resultant force nor resultant moment, about any point.  The drawing is
tested on its primitives and rendered once with cairosvg.
"""

from __future__ import annotations

import cmath
import itertools
import json
import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString
from shapely.geometry import Point as ShapelyPoint
from sheet_texts import flat

from graphplan.errors import SceneError
from graphplan.reader import Table
from graphplan.render import balancing as drawing
from graphplan.render.labels import text_box
from graphplan.render.primitives import Arrow, Text
from graphplan.rotor_balancing import (
    BalancingSpec,
    RotatingMass,
    balance,
    balancing_results,
    cautions,
    read_balancing,
)

RESIDUAL = 1e-12


def resultant_about(result, origin=0.0):
    """(force, moment) of the corrected rotor summed afresh from its masses and its corrections (kg·m, kg·m²)."""
    force = sum((mass.unbalance for mass in result.spec.masses), 0j)
    moment = sum((mass.unbalance * (mass.plane - origin) for mass in result.spec.masses), 0j)
    for plane in result.planes:
        force += plane.correction
        moment += plane.correction * (plane.position - origin)
    return force, moment


def corrections_by_linear_system(masses, left, right):
    """The two corrections (kg·m) from ΣF = 0 and ΣM = 0 about z = 0, four real equations in four unknowns."""
    force = sum(m.unbalance for m in masses)
    moment = sum(m.unbalance * m.plane for m in masses)
    # Unknowns: Lx, Ly, Rx, Ry.  Rows: ΣFx, ΣFy, ΣMx (of the vector Σ u·z), ΣMy.
    matrix = np.array([[1, 0, 1, 0], [0, 1, 0, 1], [left, 0, right, 0], [0, left, 0, right]], dtype=float)
    rhs = -np.array([force.real, force.imag, moment.real, moment.imag])
    lx, ly, rx, ry = np.linalg.solve(matrix, rhs)
    return complex(lx, ly), complex(rx, ry)


# --- static balancing: published examples ---------------------------------------------------------


def test_four_masses_in_one_plane_khurmi_example_21_1():
    # R.S. Khurmi & J.K. Gupta, "A Textbook of Theory of Machines", S. Chand, Ch. 21 (Balancing of
    # rotating masses), Example 21.1: 200, 300, 240, 260 kg at 0.2, 0.15, 0.25, 0.3 m, the angles
    # between successive masses 45°, 75°, 135°; the balance mass at 0.2 m.  Answer: 116 kg at
    # 201.48° from m1 (the book rounds ΣV to 8.5 kg·m, which moves the angle by 0.17°).
    angles = np.cumsum([0, 45, 75, 135])
    masses = [RotatingMass(m, r, a) for m, r, a in zip((200, 300, 240, 260), (0.2, 0.15, 0.25, 0.3), angles)]
    result = balance(BalancingSpec(masses, correction_radius=0.2))
    (plane,) = result.planes
    assert plane.mass == pytest.approx(116, abs=0.5)
    assert plane.angle_deg == pytest.approx(201.48, abs=0.25)
    force, moment = resultant_about(result)
    assert abs(force) < RESIDUAL and abs(moment) < RESIDUAL


def test_three_weights_in_one_plane_graphical_answer():
    # mechdiploma.com, "Three masses m1, m2 and m3 are of 100 N, 200 N and 150 N ..." (a diploma
    # examination question): radii 0.3, 0.15, 0.25 m, 45° from m1 to m2, 75° from m2 to m3; the
    # balance at 0.2 m.  Graphical answer: m·r = 63 (N·m), m = 315 N; read off a drawing, so to 1 %.
    masses = [RotatingMass(100, 0.3, 0), RotatingMass(200, 0.15, 45), RotatingMass(150, 0.25, 120)]
    (plane,) = balance(BalancingSpec(masses, correction_radius=0.2)).planes
    assert plane.mass_radius == pytest.approx(63, rel=0.01)
    assert plane.mass == pytest.approx(315, rel=0.01)


def test_the_static_correction_closes_the_polygon_of_the_masses():
    masses = [RotatingMass(2.0, 0.1, 30), RotatingMass(1.0, 0.3, 200)]
    (plane,) = balance(BalancingSpec(masses)).planes
    assert plane.vertices[0] == 0 and plane.vertices[-1] == 0
    assert [v.role for v in plane.vectors] == ["mass", "mass", "correction"]
    assert plane.vectors[-1].start == plane.vectors[1].end
    assert plane.correction == pytest.approx(-(masses[0].unbalance + masses[1].unbalance), abs=1e-15)
    assert plane.equation == "m1r1 + m2r2 + mbrb = 0"
    assert plane.mass is None


# --- dynamic balancing ------------------------------------------------------------------------------


# Data of "A rotating shaft carries four unbalanced masses 18 kg, 14 kg, 16 kg and 12 kg at radii 50,
# 60, 70, 60 mm ... planes 80, 160, 280 mm from the first ... 60°, 135°, 270° clockwise ... balanced
# by two masses at 50 mm in planes midway between the 1st and 2nd and the 3rd and 4th" (an examination
# problem, the statement as found on westonci.ca; its published answer was not found, see the sources).
SHAFT_OF_FOUR = [RotatingMass(18, 0.05, 0, 0.0), RotatingMass(14, 0.06, -60, 0.08),
                 RotatingMass(16, 0.07, -135, 0.16), RotatingMass(12, 0.06, -270, 0.28)]
# Data of "A shaft with 3 m span between two bearings carries two weights of 100 N and 200 N ... arms
# 0.45 m and 0.60 m ... planes 1.2 and 2.4 m from the left bearing ... 60° apart ... counterweights at
# 0.3 m radius, 0.3 m from each bearing" (holooly.com, Fig. 12.58): weights, so the products are N·m.
TWO_WEIGHTS = [RotatingMass(100, 0.45, 0, 1.2), RotatingMass(200, 0.60, 60, 2.4)]


@pytest.mark.parametrize(("masses", "planes", "radius"), [
    (SHAFT_OF_FOUR, (0.04, 0.22), 0.05),
    (TWO_WEIGHTS, (0.3, 2.7), 0.3),
], ids=["shaft-of-four", "two-weights"])
def test_dynamic_corrections_agree_with_the_equilibrium_equations(masses, planes, radius):
    result = balance(BalancingSpec(masses, planes=planes, correction_radius=radius))
    expected = corrections_by_linear_system(masses, *planes)
    for plane, correction in zip(result.planes, expected, strict=True):
        assert abs(plane.correction - correction) < 1e-12 * (1 + abs(correction))
        assert plane.mass == pytest.approx(abs(correction) / radius, rel=1e-12)
        assert plane.angle_deg == pytest.approx(math.degrees(cmath.phase(correction)) % 360, abs=1e-9)
    assert abs(result.residual_force) < RESIDUAL and abs(result.residual_moment) < RESIDUAL


def test_shaft_of_four_corrections_by_hand():
    # Moments about the plane R (z = 0.22 m) by hand, components to four places:
    # plane L takes (0.22 − z)/0.18 of each m·r: 1.2222, 0.7778, 0.3333, −0.3333.
    (left, right) = balance(BalancingSpec(SHAFT_OF_FOUR, planes=(0.04, 0.22), correction_radius=0.05)).planes
    assert left.factors == pytest.approx((0.22 / 0.18, 0.14 / 0.18, 0.06 / 0.18, -0.06 / 0.18), rel=1e-12)
    assert right.factors == pytest.approx((-0.04 / 0.18, 0.04 / 0.18, 0.12 / 0.18, 0.24 / 0.18), rel=1e-12)
    # Σ share·cos, Σ share·sin in L: 0.9·1.2222 + 0.84·0.7778·cos(−60°) + 1.12·0.3333·cos(−135°)
    # − 0.72·0.3333·cos(−270°) = 1.1000 + 0.3267 − 0.2640 − 0 = 1.1627;
    # 0 − 0.5658 − 0.2640 − 0.2400 = −1.0698; the correction is minus that: |·| = 1.5800 at 137.38°.
    assert left.mass_radius == pytest.approx(1.5800, abs=5e-4)
    assert left.angle_deg == pytest.approx(137.38, abs=0.01)
    assert left.mass == pytest.approx(31.60, abs=0.01)


def test_a_mass_in_a_correction_plane_loads_only_that_plane():
    masses = [RotatingMass(1.0, 0.1, 90, 0.0), RotatingMass(2.0, 0.1, 0, 1.0)]
    left, right = balance(BalancingSpec(masses, planes=(0.0, 1.0))).planes
    assert left.correction == pytest.approx(-masses[0].unbalance, abs=1e-15)
    assert right.correction == pytest.approx(-masses[1].unbalance, abs=1e-15)


def test_a_plane_equation_leaves_out_the_mass_that_turns_in_the_other_correction_plane():
    # Its share there is nothing, and the polygon draws no side for it: the equation says what the drawing draws.
    masses = [RotatingMass(1.0, 0.1, 90, 0.0), RotatingMass(2.0, 0.1, 0, 0.5), RotatingMass(1.5, 0.1, 200, 1.0)]
    result = balance(BalancingSpec(masses, planes=(0.0, 1.0)))
    left, right = result.planes
    assert left.equation == "(m1r1)L + (m2r2)L + mLrL = 0"
    assert right.equation == "(m2r2)R + (m3r3)R + mRrR = 0"
    drawn = {text.text for layer in drawing.layout(result) for text in layer.items if isinstance(text, Text)}
    assert {"(m1r1)L", "(m2r2)L", "(m2r2)R", "(m3r3)R"} <= drawn and not drawn & {"(m3r3)L", "(m1r1)R"}


def test_an_overhung_mass_pulls_the_far_plane_against_its_sense():
    # A mass beyond plane R: plane L takes a share opposite to it, plane R more than all of it.
    masses = [RotatingMass(1.0, 0.2, 0, 1.5)]
    left, right = balance(BalancingSpec(masses, planes=(0.0, 1.0))).planes
    assert left.factors[0] == pytest.approx(-0.5) and right.factors[0] == pytest.approx(1.5)
    assert left.angle_deg == pytest.approx(0.0) and right.angle_deg == pytest.approx(180.0)
    assert right.mass_radius == pytest.approx(3 * left.mass_radius)


def test_a_couple_alone_needs_equal_and_opposite_corrections():
    masses = [RotatingMass(1.0, 0.1, 0, 0.2), RotatingMass(1.0, 0.1, 180, 0.8)]
    result = balance(BalancingSpec(masses, planes=(0.0, 1.0)))
    left, right = result.planes
    assert abs(result.unbalance) < 1e-15 and abs(result.unbalance_moment) == pytest.approx(0.06)
    assert left.correction == pytest.approx(-right.correction, abs=1e-15)
    assert left.mass_radius == pytest.approx(0.06)


def test_one_plane_for_masses_in_several_leaves_the_couple():
    masses = [RotatingMass(1.0, 0.1, 0, 0.0), RotatingMass(1.0, 0.1, 90, 1.0)]
    result = balance(BalancingSpec(masses, planes=(0.5,)))
    assert abs(result.residual_force) < RESIDUAL
    assert abs(result.residual_moment) == pytest.approx(abs(-0.1 * 0.5 + 0.1j * 0.5), rel=1e-12)


rotors = st.lists(
    st.tuples(st.floats(0.01, 100.0), st.floats(0.0, 1.0), st.floats(-720.0, 720.0), st.floats(-2.0, 2.0)),
    min_size=1, max_size=6)


@settings(max_examples=60, deadline=None)
@given(rotors, st.floats(-2.0, 2.0), st.floats(0.05, 3.0), st.floats(-5.0, 5.0))
def test_the_corrected_rotor_has_no_resultant_force_or_moment(data, left, span, origin):
    masses = [RotatingMass(m, r, a, z) for m, r, a, z in data]
    result = balance(BalancingSpec(masses, planes=(left, left + span)))
    scale = 1 + sum(abs(mass.unbalance) for mass in masses) * (1 + abs(origin) + 2 + 3 / span)
    force, moment = resultant_about(result, origin)
    assert abs(force) < RESIDUAL * scale
    assert abs(moment) < RESIDUAL * scale
    # Each polygon closes: its vectors add up to nothing.
    for plane in result.planes:
        assert abs(sum((v.vector for v in plane.vectors), 0j)) < RESIDUAL * scale


@settings(max_examples=40, deadline=None)
@given(rotors, st.floats(-180.0, 180.0))
def test_turning_the_masses_turns_the_static_correction(data, turn):
    masses = [RotatingMass(m, r, a) for m, r, a, _ in data]
    turned = [RotatingMass(m.mass, m.radius, m.angle_deg + turn) for m in masses]
    (plane,) = balance(BalancingSpec(masses)).planes
    (other,) = balance(BalancingSpec(turned)).planes
    expected = plane.correction * cmath.exp(1j * math.radians(turn))
    assert abs(other.correction - expected) < 1e-12 * (1 + sum(abs(m.unbalance) for m in masses))


@pytest.mark.parametrize("turns", [0, 1, -3, 277_777_777_777])
def test_a_mass_given_whole_turns_past_its_angle_is_balanced_as_at_that_angle(turns):
    # 277 777 777 777 turns and 280° make 1e14°, which as radians keeps only about a thousandth of a degree.
    (plane,) = balance(BalancingSpec([RotatingMass(1.0, 0.2, 360.0 * turns + 280.0)])).planes
    assert plane.angle_deg == pytest.approx(100.0, abs=1e-9)
    assert plane.correction == pytest.approx(-0.2 * complex(math.cos(math.radians(280)), math.sin(math.radians(280))),
                                             abs=1e-15)


# --- the specification --------------------------------------------------------------------------------


def test_unnamed_masses_are_numbered_and_names_must_differ():
    spec = BalancingSpec([RotatingMass(1, 0.1, 0, name="A"), RotatingMass(1, 0.1, 90)])
    assert [m.name for m in spec.masses] == ["A", "2"]
    with pytest.raises(ValueError, match=r"masses\[1\]\.name: repeats"):
        BalancingSpec([RotatingMass(1, 0.1, 0, name="A"), RotatingMass(1, 0.1, 90, name="A")])


@pytest.mark.parametrize(("arguments", "message"), [
    ({"masses": []}, "at least one"),
    ({"masses": [RotatingMass(1, 0.1, 0, 0.0), RotatingMass(1, 0.1, 0, 1.0)]}, "different planes"),
    ({"masses": [RotatingMass(1, 0.1, 0)], "planes": (0.2, 0.2)}, "must differ"),
    ({"masses": [RotatingMass(1, 0.1, 0)], "planes": (0.0, 0.1, 0.2)}, "one or two"),
    ({"masses": [RotatingMass(1, 0.1, 0)], "planes": (0.0, 0.1), "correction_radius": (0.1,)}, "one per"),
    ({"masses": [RotatingMass(1, 0.1, 0)], "correction_radius": -0.1}, r"correction_radius\[0\]: must be > 0"),
    ({"masses": [RotatingMass(1, 0.1, 0)], "plane_names": ("L", "R")}, "plane_names"),
])
def test_a_bad_specification_says_what_is_wrong(arguments, message):
    with pytest.raises(ValueError, match=message):
        BalancingSpec(**arguments)


@pytest.mark.parametrize(("arguments", "message"), [
    ((0.0, 0.1, 0.0), r"mass: must be > 0 \(got 0.0\)"),
    ((1.0, -0.1, 0.0), "radius: must be >= 0"),
    ((1.0, 0.1, math.nan), "angle_deg: must be a finite number"),
])
def test_a_bad_mass_says_what_is_wrong(arguments, message):
    with pytest.raises(ValueError, match=message):
        RotatingMass(*arguments)


# --- the scene table ----------------------------------------------------------------------------------


def read(data):
    return read_balancing(Table(data, "balancing"))


def test_a_dynamic_table_is_read():
    spec = read({"masses": [{"mass": 18, "radius": 0.05, "angle": 0, "plane": 0.0, "name": "A"},
                            {"mass": 14, "radius": 0.06, "angle": -60, "plane": 0.08}],
                 "planes": [0.04, 0.22], "correction_radius": [0.05, 0.06], "plane_names": ["X", "Y"]})
    assert spec.dynamic and spec.planes == (0.04, 0.22) and spec.correction_radius == (0.05, 0.06)
    assert spec.plane_names == ("X", "Y")
    assert spec.masses[0] == RotatingMass(18, 0.05, 0, 0.0, "A") and spec.masses[1].name == "2"


def test_a_disc_table_is_read_without_planes():
    spec = read({"masses": [{"mass": 1, "radius": 0.1, "angle": 10}], "correction_radius": 0.2})
    assert not spec.dynamic and spec.correction_planes == (0.0,) and spec.correction_radius == (0.2,)


@pytest.mark.parametrize(("data", "message"), [
    ({}, "balancing.masses: is required but missing"),
    ({"masses": []}, "balancing.masses: must list at least one rotating mass"),
    ({"masses": [{"mass": -1, "radius": 0.1, "angle": 0}]}, r"balancing.masses\[0\].mass: must be > 0 \(got -1\)"),
    ({"masses": [{"mass": 1, "radius": 0.1}]}, r"balancing.masses\[0\].angle: is required but missing"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angel": 0}]}, r"balancing.masses\[0\].angel: unknown key; did you mean 'angle'"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0}], "planes": [0, 1]},
     r"balancing.masses\[0\].plane: is required when \[balancing\] has two correction planes"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0, "plane": 0},
                 {"mass": 1, "radius": 0.1, "angle": 0, "plane": 1}]}, "balancing.planes: is required when the masses"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0}], "planes": [0, 1, 2]},
     "balancing.planes: must list one correction plane"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0, "plane": 0}], "planes": [0.5, 0.5]},
     "balancing.planes: the two correction planes must be apart"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0}], "correction_radius": 0},
     r"balancing.correction_radius: must be > 0 \(got 0.0\)"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0, "plane": 0}], "planes": [0, 1],
      "correction_radius": [0.1, -2]}, r"balancing.correction_radius\[1\]: must be > 0"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0, "plane": 0}], "planes": [0, 1],
      "correction_radius": [0.1]}, "balancing.correction_radius: must be one radius or one per correction plane"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0, "name": "A"},
                 {"mass": 1, "radius": 0.1, "angle": 9, "name": "A"}]},
     r"balancing.masses\[1\].name: repeats the name of balancing.masses\[0\]"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0}], "plane_names": ["L", "R"]},
     "balancing.plane_names: must have 1 entries"),
    ({"masses": [{"mass": 1, "radius": 0.1, "angle": 0}], "correction_radis": 0.1},
     "balancing.correction_radis: unknown key; did you mean 'correction_radius'"),
])
def test_a_bad_table_names_the_key(data, message):
    with pytest.raises(SceneError, match=message):
        read(data)


def test_two_planes_listed_right_first_are_refused_unless_named():
    """planes = [0.22, 0.04] ran with the plane lettered L at z = 0.22, to the right of R at 0.04."""
    masses = [{"mass": 1, "radius": 0.1, "angle": 0, "plane": 0.1}, {"mass": 2, "radius": 0.1, "angle": 90,
                                                                    "plane": 0.15}]
    with pytest.raises(SceneError) as refused:
        read({"masses": masses, "planes": [0.22, 0.04]})
    assert str(refused.value) == ("balancing.planes: must list the left plane L first, then the right R, along z: write "
                                  "[0.04, 0.22], or name the planes as you list them (plane_names) (got [0.22, 0.04])")
    # As advised, or named in the order listed: the same correction in each plane, at its own z.
    named = balance(read({"masses": masses, "planes": [0.22, 0.04], "plane_names": ["A", "B"]}))
    advised = balance(read({"masses": masses, "planes": [0.04, 0.22]}))
    assert [(plane.name, plane.position) for plane in named.planes] == [("A", 0.22), ("B", 0.04)]
    assert [(plane.name, plane.position) for plane in advised.planes] == [("L", 0.04), ("R", 0.22)]
    assert named.planes[0].correction == pytest.approx(advised.planes[1].correction, abs=1e-15)
    assert named.planes[1].correction == pytest.approx(advised.planes[0].correction, abs=1e-15)


@pytest.mark.parametrize(("entry", "message"), [
    # "radius: is required but missing" of a mass whose radius was there, under the textbook's r.
    ({"mass": 1, "r": 0.1, "angle": 0}, r"^balancing.masses\[0\].r: unknown key; .* radius: write radius = 0.1$"),
    ({"mass": 1, "radius": 0.1, "theta": 30}, r"^balancing.masses\[0\].theta: unknown key; .* angle: write angle = 30$"),
    ({"mass": 1, "radius": 0.1, "φ": 30}, r"^balancing.masses\[0\].φ: unknown key; .* angle: write angle = 30$"),
    # "z: unknown key", with no word of plane.
    ({"mass": 1, "radius": 0.1, "angle": 0, "z": 0.2},
     r"^balancing.masses\[0\].z: unknown key; .* plane: write plane = 0.2$"),
])
def test_a_mass_given_by_the_textbooks_symbols_is_told_the_key_to_write(entry, message):
    with pytest.raises(SceneError, match=message):
        read({"masses": [entry], "planes": [0, 1]})


# --- results --------------------------------------------------------------------------------------------


def test_results_give_each_plane_its_product_angle_and_mass():
    result = balance(BalancingSpec(SHAFT_OF_FOUR, planes=(0.04, 0.22), correction_radius=0.05))
    document = balancing_results(result)
    assert document["kind"] == "dynamic"
    assert [entry["plane"] for entry in document["planes"]] == ["L", "R"]
    for entry, plane in zip(document["planes"], result.planes, strict=True):
        assert entry["mass_radius"] == plane.mass_radius and entry["angle_deg"] == plane.angle_deg
        assert entry["mass"] == pytest.approx(entry["mass_radius"] / 0.05) and entry["radius"] == 0.05
        assert entry["position"] == plane.position
    assert document["residual"]["force"] < RESIDUAL and document["residual"]["moment"] < RESIDUAL
    assert document["unbalance"]["mass_radius"] == pytest.approx(abs(sum(m.unbalance for m in SHAFT_OF_FOUR)))
    static = balancing_results(balance(BalancingSpec([RotatingMass(1, 0.1, 0)])))
    assert static["kind"] == "static" and "mass" not in static["planes"][0]


# --- the drawing ----------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def shaft_result():
    return balance(BalancingSpec(SHAFT_OF_FOUR, planes=(0.04, 0.22), correction_radius=0.05))


def test_each_polygon_is_drawn_to_scale_and_closes(shaft_result):
    layers = {layer.name: layer.items for layer in drawing.layout(shaft_result)}
    for plane in shaft_result.planes:
        scale = drawing.plane_scale(plane)
        arrows = {item.key: item for item in layers[f"plane-{plane.name}-vectors"] if isinstance(item, Arrow)}
        correction = arrows[f"plane-{plane.name}-m{plane.name}r{plane.name}"]
        drawn = [a for key, a in arrows.items() if key != correction.key]
        assert len(drawn) == sum(abs(s) / scale >= 0.25 for s in plane.shares)
        for arrow in drawn:
            name = arrow.key.rsplit("-", 1)[1]
            share = next(v for v in plane.vectors if drawing._id(v.name) == name)
            assert arrow.length == pytest.approx(abs(share.vector) / scale, rel=1e-9)
        # Head to tail: each vector starts where one ends or at the pole; the correction ends at the pole.
        pole = (plane.vertices[0].real / scale, plane.vertices[0].imag / scale)
        ends = [a.end for a in drawn] + [correction.end]
        assert all(any(math.dist(a.start, e) < 1e-9 for e in ends) or math.dist(a.start, pole) < 1e-9
                   for a in drawn)
        assert math.dist(correction.end, pole) < 1e-9 or math.dist(correction.end, drawn[0].start) < 1e-9
        assert correction.length == pytest.approx(plane.mass_radius / scale, rel=1e-9)
        assert correction.stroke.colour != drawn[0].stroke.colour and correction.stroke.width > drawn[0].stroke.width


def test_each_plane_is_drawn_at_the_standard_scale_that_makes_it_about_as_large_as_the_others():
    # Three masses between planes L (0.04) and R (0.22): R carries small shares (its polygon some 0.4 kg·m
    # across, L's 1.6), and at L's scale it shrank to a knot of its labels.
    masses = [(18.0, 0.05, 0.0, 0.0), (14.0, 0.06, -60.0, 0.08), (10.0, 0.04, 135.0, 0.16)]
    result = balance(BalancingSpec([RotatingMass(*mass) for mass in masses], planes=(0.04, 0.22),
                                   correction_radius=0.05))
    standard = [mantissa * 10.0 ** power for power in range(-5, 3) for mantissa in (1, 2, 2.5, 4, 5)]
    scales = []
    for plane, share_of in zip(result.planes, (lambda z: (0.22 - z) / 0.18, lambda z: (z - 0.04) / 0.18),
                               strict=True):
        tips = np.cumsum([0j] + [m * r * cmath.exp(1j * math.radians(angle)) * share_of(z) for m, r, angle, z in masses])
        extent = max(np.ptp(tips.real), np.ptp(tips.imag))
        expected = min(value for value in standard if extent / value <= drawing.POLYGON_FIELD_MM * (1 + 1e-12))
        assert drawing.plane_scale(plane) == pytest.approx(expected, rel=1e-12)
        scales.append(expected)
    assert scales[1] < scales[0] / 2  # R drawn finer: its polygon as large on the paper as L's within a step
    written = [item.text for layer in drawing.layout(result) for item in layer.items if isinstance(item, Text)]
    assert [f"μ = {scale:g} kg·m/mm" in written for scale in scales] == [True, True]


def test_the_drawing_writes_its_scale_and_labels_that_do_not_overlap(shaft_result):
    layers = drawing.layout(shaft_result)
    texts = [item for layer in layers for item in layer.items if isinstance(item, Text)]
    written = [t.text for t in texts]
    for plane in shaft_result.planes:
        assert f"μ = {drawing.plane_scale(plane):g} kg·m/mm" in written
    assert "mLrL = 1.580 kg·m, θL = 137.4°" in written and "mR = 13.80 kg at rR = 0.05 m" in written
    for name in ("(m1r1)L", "(m2r2)L", "(m3r3)L", "(m4r4)L", "(m1r1)R", "(m4r4)R", "mLrL", "mRrR", "θL", "θR"):
        assert name in written
    for a, b in itertools.combinations(texts, 2):
        assert not text_box(a).intersects(text_box(b)), (a.text, b.text)


def test_a_correction_just_short_of_a_whole_turn_is_written_at_0_degrees():
    # The mass at 179.97° wants its correction at 359.97°, which to a tenth of a degree is 0.0°, not 360.0°.
    result = balance(BalancingSpec([RotatingMass(1, 0.1, 179.97)], correction_radius=0.1))
    written = [item.text for layer in drawing.layout(result) for item in layer.items if isinstance(item, Text)]
    assert "mbrb = 0.1000 kg·m, θb = 0.0°" in written


def test_an_unbalance_along_x_is_written_at_0_degrees_not_a_whole_turn():
    """The results' angles lie in [0°, 360°): 2·0.1 kg·m at 0° and 1·0.1 kg·m at −180° leave Σ m·r = 0.2 − 0.1 =
    0.1 kg·m along +x, at 0°, its correction at 180°.  e^(−iπ) has the imaginary part −1.2e-16, so the phase of the sum
    came out a hair below 0 and the unbalance was written at 360.0°."""
    result = balance(BalancingSpec([RotatingMass(2.0, 0.1, 0.0), RotatingMass(1.0, 0.1, -180.0)],
                                   correction_radius=0.1))
    written = balancing_results(result)
    assert written["unbalance"]["mass_radius"] == pytest.approx(0.1, rel=1e-12)
    assert written["unbalance"]["angle_deg"] == pytest.approx(0.0, abs=1e-9)
    assert written["planes"][0]["angle_deg"] == pytest.approx(180.0, abs=1e-9)


def test_a_locale_replaces_the_strings():
    result = balance(BalancingSpec([RotatingMass(1, 0.1, 30)], correction_radius=0.1))
    texts = [item.text for layer in drawing.layout(result, {"bal_disc": "Плоскость коррекции {name}"})
             for item in layer.items if isinstance(item, Text)]
    assert "Плоскость коррекции b" in texts


def test_the_svg_renders_and_is_deterministic(shaft_result):
    cairosvg = pytest.importorskip("cairosvg")
    svg = drawing.balancing_svg(shaft_result)
    assert svg == drawing.balancing_svg(shaft_result)
    assert 'id="plane-L-mLrL"' in svg
    png = cairosvg.svg2png(bytestring=svg.encode())
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_balanced_rotor_needs_no_correction_and_its_angle_is_not_rounding_noise():
    masses = [RotatingMass(1.0, 0.1, 0, 0.0), RotatingMass(1.0, 0.1, 180, 0.0)]
    document = balancing_results(balance(BalancingSpec(masses, planes=(0.0, 1.0))))
    assert all(entry["mass_radius"] < 1e-15 and entry["angle_deg"] is None for entry in document["planes"])
    assert document["unbalance"]["angle_deg"] is None  # no unbalance points anywhere (0.0 read as along x)


def test_the_residual_left_by_rounding_is_written_as_none_and_a_real_one_as_it_is():
    # The teacher's rotor whose corrections left 1.4e-17 kg·m in results.json: written as 0 below 1e-12 of the
    # rotor's unbalance, as every quantity's rounding is.
    masses = [RotatingMass(2.5, 0.02, 0.0, 0.05), RotatingMass(0.8, 0.06, 0.0, 0.05),
              RotatingMass(1.5, 0.04, 120.0, 0.15)]
    result = balance(BalancingSpec(masses, planes=(0.0, 0.2), correction_radius=0.08))
    assert 0 < abs(result.residual_force) < 1e-12 * sum(abs(mass.unbalance) for mass in masses)
    assert balancing_results(result)["residual"] == {"force": 0.0, "moment": 0.0}
    from graphplan.rotor_balancing import _above_noise

    assert _above_noise(2e-12, 1.0) == 2e-12


@pytest.mark.parametrize(("name", "label"), [("m1", "m1r1"), ("mA", "mArA"), ("1", "m1r1"), ("L", "mLrL"),
                                             ("m12", "m12r12"), ("mass", "(m·r)mass"), ("m", "mmrm")])
def test_a_mass_named_as_a_mass_is_lettered_by_its_index(name, label):
    # "m1" made "mm1rm1" on the polygons and in the note's table.
    assert RotatingMass(1.0, 0.1, 0.0, name=name).label == label


def test_one_correction_plane_for_masses_in_other_planes_names_the_couple_it_leaves(tmp_path, capsys):
    # Balanced statically at z = 0.2, masses at 0.1 and 0.3 leave Σ m·r·(z − 0.2), a couple one plane cannot
    # take: the note said "a disc ... balanced", and no one was told.
    from graphplan.cli import main
    from graphplan.rotor_balancing import static_couple

    masses = [RotatingMass(1.0, 0.1, 0.0, 0.1), RotatingMass(2.0, 0.1, 90.0, 0.3)]
    result = balance(BalancingSpec(masses, planes=(0.2,)))
    expected = abs(sum(mass.unbalance * (mass.plane - 0.2) for mass in masses))
    assert static_couple(result) == pytest.approx(expected, rel=1e-12)
    disc = [RotatingMass(1.0, 0.1, 0.0, 0.2), RotatingMass(2.0, 0.1, 90.0, 0.2)]
    assert static_couple(balance(BalancingSpec(disc, planes=(0.2,)))) is None
    assert static_couple(balance(BalancingSpec(masses, planes=(0.0, 0.4)))) is None  # dynamic: none left
    scene = tmp_path / "rotor.toml"
    scene.write_text('[scene]\ntitle = "Rotor"\nlocale = "en"\n[balancing]\nmasses = [{ mass = 1.0, radius = 0.1, '
                     'angle = 0.0, plane = 0.1 }, { mass = 2.0, radius = 0.1, angle = 90.0, plane = 0.3 }]\n'
                     'planes = [0.2]\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    assert f"couple Σ m·r·z = {expected:.4g} kg·m²" in capsys.readouterr().out
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert "is a disc" not in note and f"Σ m·r·z = {expected:.5g} kg·m² remains" in note


# --- corrections that cannot be worked out to rounding -------------------------------------------------

# The teacher's rotor: planes 1e-14 m apart, a mass 1e14 m away.  Each share grew as 1e28 and cancelled to less than its
# rounding: the corrections left 0.96 of 1.39 kg·m, yet results.json wrote the moment 0 and the note "balanced".
FAR_FROM_CLOSE_PLANES = ('[balancing]\nmasses = [ { mass = 10.0, radius = 0.1, angle = 0.0, plane = 0.2 }, '
                         '{ mass = 12.0, radius = 0.08, angle = 90.0, plane = 1e14 } ]\nplanes = [0.0, 1e-14]\n'
                         'correction_radius = 0.1\n')


def test_planes_too_close_for_the_masses_distance_are_refused_naming_the_planes(tmp_path, capsys):
    import tomllib

    from graphplan.cli import main

    data = tomllib.loads(FAR_FROM_CLOSE_PLANES)["balancing"]
    masses = [RotatingMass(m["mass"], m["radius"], m["angle"], m["plane"]) for m in data["masses"]]
    result = balance(BalancingSpec(masses, planes=tuple(data["planes"])))
    # What the corrections leave, summed exactly (as fractions: a float sum in another order loses the 0.96 kg·m
    # against the 1e28 of the corrections and reads 0): m2·r2 = 0.96 kg·m along y, 49 % of Σ |mi·ri| = 1.96.
    from fractions import Fraction

    left, right = (plane.correction for plane in result.planes)
    force_y = Fraction(left.imag) + Fraction(right.imag) + Fraction(12) * Fraction(0.08)
    assert float(force_y) == pytest.approx(0.96, rel=1e-12)
    assert not result.balanced and result.residual[0] == pytest.approx(0.96, rel=1e-12)
    with pytest.raises(SceneError, match=r"^balancing\.planes: are 1e-14 m apart, too close for a mass 1e\+14 m from "
                                         r"them \(1e\+28 times their spacing\): the corrections cannot be worked out"):
        read(data)
    scene = tmp_path / "rotor.toml"
    scene.write_text('[scene]\ntitle = "Rotor"\n' + FAR_FROM_CLOSE_PLANES, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    error = capsys.readouterr().err
    assert error.count("\n") == 1 and "balancing.planes: are 1e-14 m apart" in error
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("ratio", [10.0, 300.0])
def test_planes_close_but_not_too_close_are_balanced(ratio):
    # A mass `ratio` spacings beyond plane R: its shares are ratio and 1 + ratio times it, which rounding keeps.
    masses = [RotatingMass(2.0, 0.1, 30.0, 0.0), RotatingMass(3.0, 0.1, 100.0, 0.01 * (1 + ratio))]
    spec = read({"masses": [{"mass": m.mass, "radius": m.radius, "angle": m.angle_deg, "plane": m.plane}
                            for m in masses], "planes": [0.0, 0.01]})
    result = balance(spec)
    assert result.balanced and result.residual == (0.0, 0.0)
    expected = corrections_by_linear_system(masses, 0.0, 0.01)
    for plane, correction in zip(result.planes, expected, strict=True):
        assert abs(plane.correction - correction) < 1e-9 * abs(correction)


def test_the_notes_residual_is_the_results_and_measured_against_the_rotors_own_unbalance(tmp_path):
    # A rotor whose axial origin is 10 000 km away: its moments about z = 0 are 1e7 times its products, and their
    # rounding (1e-10 kg·m², above the note's absolute noise) was printed in the note beside a 0 in results.json.
    import json

    from graphplan.cli import main

    offset = 1e7
    masses = [RotatingMass(2.5, 0.02, 0.0, offset + 0.05), RotatingMass(0.8, 0.06, 10.0, offset + 0.05),
              RotatingMass(1.5, 0.04, 120.0, offset + 0.15)]
    result = balance(BalancingSpec(masses, planes=(offset, offset + 0.2)))
    _, moment = resultant_about(result)
    own = sum(m.mass * m.radius for m in masses)
    # Summed either way, rounding of 1e-12 of Σ |mi·ri|·z at most, yet as the corrections' sum leaves it, above the
    # note's absolute noise (1e-10).
    assert abs(moment) < 1e-12 * own * (offset + 0.2) and abs(result.residual_moment) > 1e-10
    lines = ", ".join(f"{{ mass = {m.mass}, radius = {m.radius}, angle = {m.angle_deg}, plane = {m.plane!r} }}"
                      for m in masses)
    scene = tmp_path / "rotor.toml"
    scene.write_text(f'[scene]\ntitle = "Rotor"\n[balancing]\nmasses = [{lines}]\nplanes = [{offset!r}, '
                     f'{offset + 0.2!r}]\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    assert document["balancing"]["residual"] == {"force": 0.0, "moment": 0.0}
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert "Σ m·r = 0 kg·m and Σ m·r·z = 0 kg·m²: the rotor is balanced." in note


# --- a polygon that is a straight line ---------------------------------------------------------------------


def _distance_to_line(point, start, end):
    p, a, b = (np.asarray(xy, dtype=float) for xy in (point, start, end))
    d = b - a
    return abs(d[0] * (p - a)[1] - d[1] * (p - a)[0]) / np.hypot(*d)


@pytest.mark.parametrize("masses", [
    [RotatingMass(4.0, 0.25, 70.0, 0.3)],  # one mass
    [RotatingMass(10.0, 0.1, 45.0, 0.2), RotatingMass(5.0, 0.2, 45.0, 0.6), RotatingMass(3.0, 0.1, 45.0, 0.9)],
    [RotatingMass(5.0, 0.1, 0.0, 0.2), RotatingMass(5.0, 0.1, 180.0, 0.8)],  # a couple alone
], ids=["one-mass", "one-angle", "couple"])
def test_a_correction_along_the_masses_is_drawn_beside_them_with_leaders_to_the_chains_ends(masses):
    # The teacher's scenes: the correction was drawn exactly over the mass vectors, which vanished under it.
    result = balance(BalancingSpec(masses, planes=(0.0, 1.0), correction_radius=0.1))
    layers = {layer.name: layer.items for layer in drawing.layout(result)}
    for plane in result.planes:
        scale = drawing.plane_scale(plane)
        arrows = [item for item in layers[f"plane-{plane.name}-vectors"] if isinstance(item, Arrow)]
        correction = next(a for a in arrows if a.key.endswith(f"m{plane.name}r{plane.name}"))
        shares = [a for a in arrows if a is not correction]
        # Its tail and head where the polygon puts them (the chain's last tip, the pole), moved across by BESIDE_MM.
        # The panel is moved into place on the sheet: the first share's tail is the polygon's start.
        shift = complex(*shares[0].start) - plane.vectors[0].start / scale
        tip, pole = plane.vectors[-1].start / scale + shift, plane.vectors[-1].end / scale + shift
        across = 1j * (pole - tip) / abs(pole - tip)
        moved = [complex(*correction.start) - tip, complex(*correction.end) - pole]
        assert moved[0] == pytest.approx(moved[1], abs=1e-9)
        assert abs(moved[0]) == pytest.approx(drawing.BESIDE_MM, rel=1e-9)
        assert abs((moved[0] / across).imag) < 1e-9  # straight across, the correction parallel to itself
        # A share on the chain stands BESIDE_MM from the correction; one folded back over the share before it (the
        # couple's second) is set beside the chain on the other side, twice that.
        apart = [min(_distance_to_line(end, correction.start, correction.end) for end in (share.start, share.end))
                 for share in shares]
        assert min(apart) == pytest.approx(drawing.BESIDE_MM, abs=1e-6)
        assert all(value == pytest.approx(drawing.BESIDE_MM, abs=1e-6)
                   or value == pytest.approx(2 * drawing.BESIDE_MM, abs=1e-6) for value in apart)
        leaders = [item for item in layers[f"plane-{plane.name}-reference"] if item.stroke == drawing._LEADER]
        joined = {(round(x, 6), round(y, 6)) for leader in leaders for x, y in leader.points}
        for point in (tip, pole, complex(*correction.start), complex(*correction.end)):
            assert (round(point.real, 6), round(point.imag, 6)) in joined


def test_a_correction_that_hides_no_mass_vector_closes_the_polygon_where_it_is(shaft_result):
    for plane in shaft_result.planes:
        layers = {layer.name: layer.items for layer in drawing.layout(shaft_result)}
        assert not [item for item in layers[f"plane-{plane.name}-reference"] if getattr(item, "stroke", None)
                    == drawing._LEADER]


# --- a rotor balanced already ------------------------------------------------------------------------------

BALANCED_ALREADY = {  # the teacher's: each plane's shares close by themselves but for 1e-16 kg·m of rounding
    "dynamic": ('[balancing]\nmasses = [{ mass = 10.0, radius = 0.1, angle = 0.0, plane = 0.2 }, '
                '{ mass = 10.0, radius = 0.1, angle = 180.0, plane = 0.2 }, '
                '{ mass = 5.0, radius = 0.2, angle = 90.0, plane = 0.5 }, '
                '{ mass = 5.0, radius = 0.2, angle = 270.0, plane = 0.5 }]\nplanes = [0.0, 1.0]\n'
                'correction_radius = 0.1\n'),
    "static": ('[balancing]\nmasses = [{ mass = 3.0, radius = 0.1, angle = 0.0 }, '
               '{ mass = 3.0, radius = 0.1, angle = 120.0 }, { mass = 3.0, radius = 0.1, angle = 240.0 }]\n'
               'correction_radius = 0.05\n'),
}


@pytest.mark.parametrize("kind", sorted(BALANCED_ALREADY))
def test_a_rotor_balanced_already_writes_its_corrections_0_and_no_angle_in_the_results_drawing_and_note(kind, tmp_path):
    import json
    import tomllib

    from graphplan.cli import main

    data = tomllib.loads(BALANCED_ALREADY[kind])["balancing"]
    products = [m["mass"] * m["radius"] * np.exp(1j * np.radians(m["angle"])) for m in data["masses"]]
    own = sum(abs(p) for p in products)
    # numpy's own sums: not 0 in floating point, yet under 1e-12 of the masses' Σ |m·r|.
    assert 0 < abs(np.sum(products)) < 1e-12 * own
    scene = tmp_path / "rotor.toml"
    scene.write_text('[scene]\ntitle = "Rotor"\n' + BALANCED_ALREADY[kind], encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["balancing"]
    assert document["unbalance"] == {"mass_radius": 0.0, "angle_deg": None, "moment": 0.0}
    for entry in document["planes"]:
        # A vector of no length has no direction: "θL = 0.0°" and angle_deg 0.0 read as a correction set along x.
        assert entry["mass_radius"] == 0.0 and entry["mass"] == 0.0 and entry["angle_deg"] is None
    assert '"angle_deg": null' in (tmp_path / "out" / "results.json").read_text(encoding="utf-8")
    svg = flat((tmp_path / "out" / "rotor_balancing.svg").read_text(encoding="utf-8"))
    name = "L" if kind == "dynamic" else "b"
    assert f"m{name}r{name} = 0 kg·m, θ{name} = —" in svg and "0000000" not in svg and "θL = 0.0°" not in svg
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert f"Plane {name}: the masses' products close by themselves" in note and "e-1" not in note
    assert f"m{name}r{name} = 0 kg·m, its angle θ undefined (—)" in note


def test_two_planes_name_each_side_the_masss_share_carried_to_the_plane(shaft_result):
    # The sides were lettered m1r1 and the caption said "m1r1 + m2r2 + m3r3 + m4r4 + mLrL = 0", which is false: each
    # side is (mi·ri)·(zR − zi)/(zR − zL) in L and (mi·ri)·(zi − zL)/(zR − zL) in R.
    left_z, right_z = 0.04, 0.22
    layers = drawing.layout(shaft_result)
    for plane, share_of in zip(shaft_result.planes, (lambda z: (right_z - z) / (right_z - left_z),
                                                     lambda z: (z - left_z) / (right_z - left_z)), strict=True):
        name = plane.name
        # The equation is broken before a sign where it is wider than a caption: its lines joined give it back.
        caption = " ".join(item.text for layer in layers if layer.name == f"plane-{name}-caption" for item in layer.items)
        assert f"(m1r1){name} + (m2r2){name} + (m3r3){name} + (m4r4){name} + m{name}r{name} = 0" in caption
        for k, mass in enumerate(SHAFT_OF_FOUR, start=1):
            side = next(v for v in plane.vectors if v.name == f"(m{k}r{k}){name}")
            assert abs(side.vector - mass.unbalance * share_of(mass.plane)) < 1e-12
        # The sides and the correction close: Σ (mi·ri)plane + mb·rb = 0, as the caption now says.
        assert abs(sum(v.vector for v in plane.vectors)) < 1e-12
    disc = balance(BalancingSpec([RotatingMass(1.0, 0.1, 0.0), RotatingMass(2.0, 0.1, 90.0)]))
    assert disc.planes[0].equation == "m1r1 + m2r2 + mbrb = 0"  # one plane takes the whole m·r: no share


def test_the_rotor_starters_labels_stand_clear_of_the_vectors_and_the_angles():
    # Plane L's short m3r3 was lettered over the θL arc and x-direction; (m2r2)L over the correction.
    import tomllib
    from importlib import resources

    from shapely.geometry import LineString

    from graphplan.render.primitives import Polyline

    data = tomllib.loads(resources.files("graphplan").joinpath("templates/rotor.toml").read_text(encoding="utf-8"))
    result = balance(read(data["balancing"]))
    layers = drawing.layout(result)
    for plane in result.planes:
        named = {layer.name: layer.items for layer in layers}
        lines = [LineString((item.start, item.end)) for item in named[f"plane-{plane.name}-vectors"]
                 if isinstance(item, Arrow)]
        lines += [LineString(item.points) for item in named[f"plane-{plane.name}-reference"]
                  if isinstance(item, Polyline)]
        for text in named[f"plane-{plane.name}-labels"]:
            assert not any(text_box(text).intersects(line) for line in lines), (plane.name, text.text)


def test_the_couple_one_plane_leaves_is_recorded_in_the_results(tmp_path, capsys):
    """The single plane's leftover couple was in the note and on the console, not in results.json."""
    from graphplan.cli import main

    scene = tmp_path / "one.toml"
    scene.write_text('[scene]\ntitle = "one"\n[balancing]\n'
                     'masses = [ { mass = 18.0, radius = 0.05, angle = 0.0, plane = 0.0 },\n'
                     '           { mass = 14.0, radius = 0.06, angle = -60.0, plane = 0.08 } ]\n'
                     'planes = [0.3]\ncorrection_radius = 0.05\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    # The correction −Σ m·r at z = 0.3 leaves Σ m·r·(z − 0.3).
    couple = abs(sum(m * r * cmath.exp(1j * math.radians(angle)) * (z - 0.3)
                     for m, r, angle, z in [(18.0, 0.05, 0.0, 0.0), (14.0, 0.06, -60.0, 0.08)]))
    assert f"couple Σ m·r·z = {couple:.4g} kg·m²" in capsys.readouterr().out
    results = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    (found,) = results["balancing"]["warnings"]
    assert found["code"] == "couple-left" and f"Σ m·r·z = {couple:.4g} kg·m²" in found["detail"]
    scene.write_text(scene.read_text(encoding="utf-8").replace("planes = [0.3]", "planes = [0.0, 0.3]"),
                     encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "two")]) == 0
    assert json.loads((tmp_path / "two" / "results.json").read_text(encoding="utf-8"))["balancing"]["warnings"] == []


@pytest.mark.parametrize(("table", "key", "label"), [
    # Masses a and b balanced in one plane, named b by default: "mara + mbrb + mbrb = 0".
    (('masses = [ { mass = 2.0, radius = 0.1, angle = 30.0, name = "a" }, '
     '{ mass = 1.0, radius = 0.1, angle = 100.0, name = "b" } ]\ncorrection_radius = 0.1\n'),
     r"balancing\.masses\[1\]\.name", "mbrb"),
    # Planes named as the masses: "(mArA)A + … + mArA = 0", and "mA = 1.204 kg" of mass A's 2 kg.
    (('masses = [ { mass = 2.0, radius = 0.1, angle = 30.0, plane = 0.3, name = "A" }, '
     '{ mass = 1.0, radius = 0.1, angle = 200.0, plane = 0.8, name = "B" } ]\nplanes = [0, 1]\n'
     'plane_names = ["A", "B"]\ncorrection_radius = 0.1\n'), r"balancing\.plane_names", "mArA"),
    # m1 is lettered by its index, as 1 is.
    (('masses = [ { mass = 2.0, radius = 0.1, angle = 30.0, name = "m1" }, '
     '{ mass = 1.0, radius = 0.1, angle = 100.0, name = "1" } ]\n'), r"balancing\.masses\[1\]\.name", "m1r1"),
    # An unnamed second mass is numbered 2: a traceback, from the specification's own check.
    ('masses = [ { mass = 2.0, radius = 0.1, angle = 30.0, name = "2" }, { mass = 1.0, radius = 0.1, angle = 100.0 } ]\n',
     r"balancing\.masses\[0\]\.name", "m2r2"),
    (('masses = [ { mass = 2.0, radius = 0.1, angle = 30.0, plane = 0.1, name = "L" }, '
     '{ mass = 1.0, radius = 0.1, angle = 100.0, plane = 0.2 } ]\nplanes = [0, 1]\n'), r"balancing\.masses\[0\]\.name",
     "mLrL"),
])
def test_names_whose_products_would_read_alike_are_refused_naming_the_key_and_the_label(tmp_path, capsys, table, key,
                                                                                        label):
    from graphplan.cli import main

    scene = tmp_path / "rotor.toml"
    scene.write_text('[scene]\ntitle = "rotor"\n[balancing]\n' + table, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    error = capsys.readouterr().err
    assert re.search(rf"^graphplan: error: {key}: .*would both read {label}\b", error), error
    assert not (tmp_path / "out").exists()


def test_the_specification_refuses_products_that_read_alike_too():
    with pytest.raises(ValueError, match=r"masses\[1\]\.name: the products of mass '1' and mass 'm1' would both read "
                                         r"m1r1"):
        BalancingSpec([RotatingMass(1, 0.1, 0, name="m1"), RotatingMass(1, 0.1, 90, name="1")])
    with pytest.raises(ValueError, match=r"masses\[0\]\.name: .* would both read mbrb"):
        BalancingSpec([RotatingMass(1, 0.1, 0, name="b")])
    assert BalancingSpec([RotatingMass(1, 0.1, 0, name="b")], plane_names=("c",)).plane_names == ("c",)


@pytest.mark.parametrize(("locale", "placed", "disc"), [
    ("en", "Correction plane b, z = 0.3 m", "Correction plane b"),
    ("ru", "Плоскость коррекции b, z = 0.3 м", "Плоскость коррекции b"),
    ("zh", "校正平面 b，z = 0.3 m", "校正平面 b"),
])
def test_one_correction_plane_the_scene_places_is_captioned_with_its_z(locale, placed, disc):
    """The two planes' captions gave z, the one plane at planes = [0.3] did not ("Correction plane b"); a disc's
    plane is its masses' own and keeps the caption without it."""
    from graphplan.locale import strings

    def captions(spec):
        return [item.text for layer in drawing.layout(balance(spec), strings(locale)) if layer.name.endswith("-caption")
                for item in layer.items]

    masses = [RotatingMass(18.0, 0.05, 0.0, 0.0), RotatingMass(14.0, 0.06, -60.0, 0.08)]
    assert captions(BalancingSpec(masses, planes=(0.3,), correction_radius=0.05))[0] == placed
    flat = [RotatingMass(18.0, 0.05, 0.0), RotatingMass(14.0, 0.06, -60.0)]
    assert captions(BalancingSpec(flat, correction_radius=0.05))[0] == disc


def test_a_chinese_caption_line_with_a_middle_dot_is_set_in_the_latin_font():
    """A full-width comma in "mLrL = 1.413 kg·m，θL = 160.5°" made the whole line CJK, whose middle dot is as wide as
    an ideograph ("kg ・ m"); a line of symbols and numbers takes a Latin comma."""
    import unicodedata

    from graphplan.locale import strings

    masses = [RotatingMass(18.0, 0.05, 0.0, 0.0), RotatingMass(14.0, 0.06, -60.0, 0.08)]
    layers = drawing.layout(balance(BalancingSpec(masses, planes=(0.04, 0.22), correction_radius=0.05)),
                            strings("zh"))
    lines = [item.text for layer in layers if layer.name.endswith("-caption") for item in layer.items]
    dotted = [line for line in lines if "·" in line]
    assert len(dotted) == 4  # μ and the correction of each plane
    assert not [line for line in dotted if any(unicodedata.east_asian_width(c) in "WF" for c in line)]


# --- the drawing's width follows its polygons --------------------------------------------------------------------

DISC = [RotatingMass(3.0, 0.1, 30.0, 0.0), RotatingMass(2.0, 0.08, 150.0, 0.0)]
NAMED = [RotatingMass(18.0, 0.05, 0.0, 0.0, name="А"), RotatingMass(14.0, 0.06, -60.0, 0.08, name="Б"),
         RotatingMass(10.0, 0.04, 135.0, 0.16, name="шкив"), RotatingMass(2.0, 0.10, 270.0, 0.30, name="муфта")]
SPECS = {"disc": BalancingSpec(DISC, correction_radius=0.1),
         "named": BalancingSpec(NAMED, planes=(0.04, 0.22), plane_names=("I", "II"), correction_radius=(0.05, 0.08))}


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
@pytest.mark.parametrize("kind", sorted(SPECS))
def test_the_title_and_captions_are_broken_to_the_polygons_width(locale, kind):
    """The title at 9.7 mm on one line made a disc's drawing 366 mm wide about a polygon of 60 mm, and one equation
    of four named masses made plane II's 242 mm: neither went on an A4."""
    from graphplan.locale import strings
    from graphplan.render.force_rows import CAPTION_WIDTH_MM
    from graphplan.render.primitives import bounds, text_width

    layers = drawing.layout(balance(SPECS[kind]), strings(locale))
    body = [layer for layer in layers if layer.name != "balancing-title"]
    x0, _, x1, _ = bounds(body)
    whole_x0, _, whole_x1, _ = bounds(layers)
    assert whole_x1 - whole_x0 <= max(x1 - x0, CAPTION_WIDTH_MM) + 1e-9
    for plane in SPECS[kind].plane_names:
        polygon = [layer for layer in layers if layer.name.startswith(f"plane-{plane}-")
                   and not layer.name.endswith("-caption")]
        px0, _, px1, _ = bounds(polygon)
        (caption,) = [layer for layer in layers if layer.name == f"plane-{plane}-caption"]
        for text in caption.items:
            assert text_width(text.text, text.size, text.weight) <= max(px1 - px0, CAPTION_WIDTH_MM) + 1e-9, text.text


@pytest.mark.parametrize(("locale", "one", "two"), [
    ("en", "Balancing of rotating masses: polygon of mass-radius products",
     "Balancing of rotating masses: polygons of mass-radius products"),
    ("ru", "Уравновешивание ротора: многоугольник дисбалансов", "Уравновешивание ротора: многоугольники дисбалансов"),
    ("zh", "转子平衡：质径积矢量多边形", "转子平衡：质径积矢量多边形"),
])
def test_the_title_names_one_polygon_or_several(locale, one, two):
    from graphplan.locale import strings

    def title(spec):
        (layer,) = [layer for layer in drawing.layout(balance(spec), strings(locale)) if layer.name == "balancing-title"]
        return ("" if locale == "zh" else " ").join(item.text for item in layer.items)

    assert title(SPECS["disc"]) == one
    assert title(BalancingSpec(NAMED, planes=(0.05,), correction_radius=0.1)) == one
    assert title(SPECS["named"]) == two


ROTOR_SCENES = {
    "disc": ('masses = [ { mass = 3.0, radius = 0.1, angle = 30.0, plane = 0.0 },\n'
             '           { mass = 2.0, radius = 0.08, angle = 150.0, plane = 0.0 } ]\ncorrection_radius = 0.1\n'),
    "one plane": ('masses = [ { mass = 3.0, radius = 0.1, angle = 30.0, plane = 0.0 },\n'
                  '           { mass = 2.0, radius = 0.08, angle = 150.0, plane = 0.05 },\n'
                  '           { mass = 1.0, radius = 0.12, angle = 250.0, plane = 0.1 } ]\n'
                  'planes = [0.05]\ncorrection_radius = 0.1\n'),
    "named": ('masses = [ { mass = 18.0, radius = 0.05, angle = 0.0, plane = 0.0, name = "А" },\n'
              '           { mass = 14.0, radius = 0.06, angle = -60.0, plane = 0.08, name = "Б" },\n'
              '           { mass = 10.0, radius = 0.04, angle = 135.0, plane = 0.16, name = "шкив" },\n'
              '           { mass = 2.0, radius = 0.10, angle = 270.0, plane = 0.30, name = "муфта" } ]\n'
              'planes = [0.04, 0.22]\nplane_names = ["I", "II"]\ncorrection_radius = [0.05, 0.08]\n'),
}


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
@pytest.mark.parametrize("kind", sorted(ROTOR_SCENES))
def test_a_rotors_balancing_goes_on_an_a4(tmp_path, capsys, locale, kind):
    from graphplan.cli import main

    scene = tmp_path / "rotor.toml"
    scene.write_text(f'[scene]\ntitle = "Rotor"\nlocale = "{locale}"\n[balancing]\n' + ROTOR_SCENES[kind],
                     encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--sheet", "A4"]) == 0, capsys.readouterr().err
    assert (tmp_path / "out" / "sheet_1.svg").exists()


@pytest.mark.parametrize(("locale", "names"), [("ru", ("А", "Б", "шкив", "муфта")),
                                               ("zh", ("叶轮", "齿轮", "带轮", "联轴器"))])
def test_long_names_of_masses_stand_clear_of_every_vector_and_of_one_another(locale, names):
    """Plane II's "((m·r)шкив)II" stood inside the polygon with the шкив vector through its "II", and "(m齿轮r齿轮)II"
    on the correction: no spot beside the middle of a long side inside the polygon is clear of the lines."""
    from shapely.geometry import LineString

    from graphplan.locale import strings
    from graphplan.render.primitives import Polyline

    masses = [RotatingMass(mass.mass, mass.radius, mass.angle_deg, mass.plane, name=name)
              for mass, name in zip(NAMED, names, strict=True)]
    result = balance(BalancingSpec(masses, planes=(0.04, 0.22), plane_names=("I", "II"), correction_radius=(0.05, 0.08)))
    named = {layer.name: layer.items for layer in drawing.layout(result, strings(locale))}
    for plane in result.planes:
        lines = [LineString((item.start, item.end)) for item in named[f"plane-{plane.name}-vectors"]
                 if isinstance(item, Arrow)]
        lines += [LineString(item.points) for item in named[f"plane-{plane.name}-reference"]
                  if isinstance(item, Polyline)]
        texts = named[f"plane-{plane.name}-labels"]
        assert len(texts) == len(masses) + 2  # each share, the correction and its angle
        for text in texts:
            assert not any(text_box(text).intersects(line) for line in lines), (plane.name, text.text)
        for a, b in itertools.combinations(texts, 2):
            assert not text_box(a).intersects(text_box(b)), (a.text, b.text)


# --- the note words the rotor by its masses' planes ---------------------------------------------------------------

IN_ONE_PLANE = ('[balancing]\nmasses = [ { mass = 2.0, radius = 0.1, angle = 0.0, plane = 0.1 },\n'
                '           { mass = 4.0, radius = 0.05, angle = 180.0, plane = 0.1 } ]\n'
                'planes = [0.0, 0.2]\ncorrection_radius = 0.1\n')


@pytest.mark.parametrize(("locale", "together", "apart", "undefined"), [
    ("en", "The rotor's masses all turn in one plane, z = 0.1 m, and a correction mass", "The rotor is long",
     "its angle θ undefined (—)"),
    ("ru", "Все массы ротора вращаются в одной плоскости, z = 0,1 м, и его уравновешивают", "Ротор длинный",
     "угол θ не определён (—)"),
    ("zh", "转子各质量均在同一平面（z = 0.1 m）内回转，在平面 L", "转子为长转子", "方位角 θ 无定义（—）"),
])
def test_masses_in_one_plane_balanced_in_two_are_not_called_a_long_rotor(tmp_path, locale, together, apart,
                                                                         undefined):
    from graphplan.cli import main

    scene = tmp_path / "rotor.toml"
    scene.write_text(f'[scene]\ntitle = "Rotor"\nlocale = "{locale}"\n' + IN_ONE_PLANE, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "one")]) == 0
    note = (tmp_path / "one" / "note.md").read_text(encoding="utf-8")
    assert together in note and apart not in note
    # Both planes' shares close by themselves: 2·0.1 = 4·0.05 kg·m at 0° and 180°, at z = 0.1 between them.
    assert note.count(undefined) == 2
    scene.write_text(scene.read_text(encoding="utf-8").replace("plane = 0.1 },\n", "plane = 0.15 },\n", 1),
                     encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "two")]) == 0
    note = (tmp_path / "two" / "note.md").read_text(encoding="utf-8")
    assert apart in note and together not in note and undefined not in note


def test_one_correction_plane_for_masses_whose_moments_cancel_is_no_disc(tmp_path):
    from graphplan.cli import main

    # Equal products at one angle, at z = 0 and z = 0.2, corrected at z = 0.1: Σ m·r·(z − 0.1) = 0, no couple left,
    # yet the masses turn in two planes.
    scene = tmp_path / "rotor.toml"
    scene.write_text('[scene]\ntitle = "Rotor"\n[balancing]\n'
                     'masses = [ { mass = 1.0, radius = 0.1, angle = 30.0, plane = 0.0 },\n'
                     '           { mass = 2.0, radius = 0.05, angle = 30.0, plane = 0.2 } ]\n'
                     'planes = [0.1]\ncorrection_radius = 0.1\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert "a disc" not in note and "in one plane" not in note
    assert "Its masses turn at z = 0 … 0.2 m and the correction at z = 0.1 m; their moments" in note


@pytest.mark.parametrize(("locale", "where", "span"), [
    ("en", "Its masses turn at z = 0.1 m and the correction at z = 0.3 m, and one plane", "z = 0.1 … 0.1 m"),
    ("ru", "Его массы вращаются при z = 0,1 м, корректирующая — при z = 0,3 м, и одна плоскость", "z = 0,1 … 0,1 м"),
    ("zh", "各质量位于 z = 0.1 m，校正质量位于 z = 0.3 m，一个平面", "z = 0.1 … 0.1 m"),
], ids=["en", "ru", "zh"])
def test_masses_in_one_plane_corrected_in_another_are_placed_at_their_z_not_a_range_of_it(tmp_path, locale, where,
                                                                                           span):
    """A disc at z = 0.1 corrected at planes = [0.3] (a pulley corrected on its hub's face) was said to turn at
    "z = 0.1 … 0.1 m", a span of one plane."""
    from graphplan.cli import main

    scene = tmp_path / "rotor.toml"
    scene.write_text(f'[scene]\ntitle = "Rotor"\nlocale = "{locale}"\n[balancing]\n'
                     'masses = [ { mass = 2.0, radius = 0.1, angle = 0.0, plane = 0.1 },\n'
                     '           { mass = 1.0, radius = 0.1, angle = 90.0, plane = 0.1 } ]\n'
                     'planes = [0.3]\ncorrection_radius = 0.1\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert where in note and span not in note
    # Σ m·r = 0.2 + 0.1i kg·m at z = 0.1 and its correction −Σ m·r at z = 0.3 leave (0.1 − 0.3)·(0.2 + 0.1i):
    # |−0.04 − 0.02i| = 0.02·√5 = 0.044721 kg·m², the couple the sentence goes on to name.
    couple = f"{0.02 * math.sqrt(5):.5g}".replace(".", "," if locale == "ru" else ".")
    assert f"Σ m·r·z = {couple} " in note


@pytest.mark.parametrize(("locale", "plane"), [("en", "Balancing of the rotor: Correction plane"),
                                               ("ru", "Уравновешивание ротора: Плоскость коррекции"),
                                               ("zh", "转子平衡: 校正平面")])
def test_a_plane_no_sheet_holds_is_named_as_its_caption_names_it(locale, plane):
    """The refusal named the part's id: "the drawing 'Уравновешивание ротора: balancing-2'".  A scene's names are
    held to what letters a polygon (rotor_balancing.LONGEST_NAME), so a plane no sheet holds is made in Python, where
    a name is taken as given."""
    from graphplan.locale import strings
    from graphplan.render.sheet import balancing_panel, machine_sheets
    from graphplan.render.title_block import details_of, form_of

    # A name with no space to break at: its share's label and the caption's equation wider than an A4 holds.
    long = "high_pressure_feed_pump_drive_pulley_hub_with_its_key_and_its_locking_collar"
    spec = BalancingSpec(masses=(RotatingMass(18.0, 0.05, 0.0, 0.0, "A"), RotatingMass(14.0, 0.06, -60.0, 0.08, long)),
                         planes=(0.04, 0.22), plane_names=("I", "II"))
    panel = balancing_panel(drawing.layout(balance(spec), strings(locale)), locale)
    with pytest.raises(SceneError) as refused:
        machine_sheets([], [panel], "A4", locale, details_of(None, "Rotor", form_of(locale)))
    error = str(refused.value)
    assert re.search(rf"the drawing '{plane} II?' \(", error) and "balancing-" not in error, error


# --- correction planes close together ---------------------------------------------------------------------------

# The hunter's B14: 6 kg of masses up to 0.8 m along the rotor, corrected in planes 1 mm apart.
_CLOSE = [(2.0, 0.1, 0.0, 0.0), (3.0, 0.1, 100.0, 0.3), (1.0, 0.2, 250.0, 0.8)]


def _corrections_by_moments(masses, left, right):
    """mL·rL and mR·rR from Σ m·r + corrections = 0 and Σ m·r·z + z·corrections = 0, solved as one system."""
    products = [m * r * cmath.exp(1j * math.radians(angle)) for m, r, angle, _ in masses]
    system = np.array([[1.0, 1.0], [left, right]], dtype=complex)
    return np.linalg.solve(system, -np.array([sum(products), sum(p * z for p, (*_, z) in zip(products, masses,
                                                                                            strict=True))]))


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_correction_planes_close_together_are_cautioned_against(tmp_path, capsys, locale):
    """mL = 1464 kg and mR = 1463 kg for a 6 kg rotor, worked out right and said nothing of."""
    from graphplan.cli import main

    scene = tmp_path / "rotor.toml"
    masses = ",\n".join(f"{{ mass = {m}, radius = {r}, angle = {a}, plane = {z} }}" for m, r, a, z in _CLOSE)
    scene.write_text(f'[scene]\ntitle = "Rotor"\nlocale = "{locale}"\n[balancing]\nmasses = [{masses}]\n'
                     "planes = [0.4, 0.401]\ncorrection_radius = 0.1\n", encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    told = capsys.readouterr().out
    corrections = sum(abs(c) for c in _corrections_by_moments(_CLOSE, 0.4, 0.401))
    own = sum(m * r for m, r, _, _ in _CLOSE)
    ratio = corrections / own
    assert ratio > 10
    line = f"the corrections' Σ |m·r| = {corrections:.4g} kg·m is {ratio:.3g} times the masses' ({own:.4g} kg·m)"
    assert f"warning: balancing: {line}" in told and "set the planes farther apart" in told
    (found,) = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["balancing"]["warnings"]
    assert found["code"] == "planes-close" and found["detail"].startswith(line)
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    mark = "," if locale == "ru" else "."
    written = f"{ratio:.3g}".replace(".", mark)
    caution = {"en": f"Caution: the corrections' Σ |m·r| = {corrections:.5g} kg·m is {written} times",
               "ru": f"Внимание: сумма |m·r| корректирующих масс, {corrections:.5g} кг·м, более чем в десять раз",
               "zh": f"注意：校正质量的 Σ |m·r| = {corrections:.5g} kg·m，是各质量本身"}[locale]
    assert caution.replace(".", mark) in note and f"{written}" in note


def test_planes_a_rotor_length_apart_are_not_cautioned_against():
    """The same masses corrected at the rotor's ends, 0 and 0.8 m: the corrections are the size of the masses."""
    result = balance(BalancingSpec([RotatingMass(m, r, a, z) for m, r, a, z in _CLOSE], planes=(0.0, 0.8)))
    corrections = sum(abs(c) for c in _corrections_by_moments(_CLOSE, 0.0, 0.8))
    assert corrections < 10 * sum(m * r for m, r, _, _ in _CLOSE)
    assert [found.code for found in cautions(result)] == []


# --- a share folded back over the one before it, and the correction's angle ------------------------------------


def _segment_distance(point, start, end):
    return LineString((start, end)).distance(ShapelyPoint(point))


def _starter_result():
    import tomllib
    from importlib import resources

    data = tomllib.loads(resources.files("graphplan").joinpath("templates/rotor.toml").read_text(encoding="utf-8"))
    return balance(read(data["balancing"]))


# The hunter's B13: in plane L (m3r3)L runs straight back down (m2r2)L, over it, laid off in the masses' order.
B13 = [RotatingMass(20, 1, 0, 0), RotatingMass(30, 2, 90, 2), RotatingMass(10, 3, -270, 5)]
# Two masses nearly opposite: whichever is laid off second turns back onto the first (4° off straight back), in
# either order.
FOLDED_EITHER_WAY = [RotatingMass(1.0, 1.0, 0.0), RotatingMass(0.3, 1.0, 176.0)]


def _drawn_chain(layers, name):
    """The plane's arrows walked head to tail from its pole (the dot), as drawn: the arrows in the order walked,
    the arrows no walk reaches, and how far the last head stands from the pole (mm)."""
    items = layers[f"plane-{name}-vectors"]
    arrows = [item for item in items if isinstance(item, Arrow)]
    (pole,) = [complex(*item.centre) for item in items if not isinstance(item, Arrow)]
    walked, at = [], pole
    left = list(arrows)
    while left:
        following = [arrow for arrow in left if abs(complex(*arrow.start) - at) < 0.01]
        if len(following) != 1:
            break
        walked.append(following[0])
        left.remove(following[0])
        at = complex(*following[0].end)
    return walked, left, abs(at - pole)


def _caption_scale(layers, name):
    """μ (kg·m/mm) as the plane's caption writes it."""
    (value,) = [float(re.fullmatch(r"μ = ([\d.e+-]+) kg·m/mm", item.text).group(1))
                for item in layers[f"plane-{name}-caption"] if item.text.startswith("μ = ")]
    return value


@pytest.mark.parametrize(("masses", "planes"), [("starter", None), (B13, (1, 4)), (SHAFT_OF_FOUR, (0.04, 0.22))],
                         ids=["starter", "B13", "shaft-of-four"])
def test_each_plane_s_polygon_is_drawn_as_a_closed_chain_of_its_shares(masses, planes):
    """The rotor starter's plane L drew (m3r3)L, folded back onto (m2r2)L, beside the chain on dashed leaders, and
    the polygon read as open: the shares are laid off in an order that turns none back onto the one before."""
    result = _starter_result() if masses == "starter" else balance(BalancingSpec(masses, planes=planes,
                                                                                  correction_radius=0.05))
    layers = {layer.name: layer.items for layer in drawing.layout(result)}
    left_plane, right_plane = result.spec.planes
    for plane in result.planes:
        name = plane.name
        walked, stray, gap = _drawn_chain(layers, name)
        # Every arrow on the walk from the pole, head to tail, the correction last and back on the pole.
        assert stray == [] and gap < 0.01
        assert walked[-1].key.endswith(f"m{name}r{name}")
        # The shares walked are the masses' m·r carried to the plane by moments, worked out here afresh, each drawn
        # once at the caption's μ; the correction is their sum turned back.
        scale = _caption_scale(layers, name)
        other = right_plane if plane.position == left_plane else left_plane
        shares = [mass.unbalance * (other - mass.plane) / (other - plane.position) / scale
                  for mass in result.spec.masses]
        drawn = [complex(*arrow.end) - complex(*arrow.start) for arrow in walked[:-1]]
        assert len(drawn) == sum(abs(share) >= drawing.ZERO_MM for share in shares)
        for vector in drawn:
            assert min(abs(vector - share) for share in shares) < 1e-6
        correction = complex(*walked[-1].end) - complex(*walked[-1].start)
        assert abs(correction + sum(shares)) < 0.01
        # Nothing is drawn beside the chain, so nothing needs saying: no leaders, no caption line about it.
        assert not [item for item in layers[f"plane-{name}-reference"]
                    if getattr(item, "stroke", None) in (drawing._LEADER, drawing._SHARE_LEADER)]
        assert not [item for item in layers[f"plane-{name}-caption"] if "aside" in item.text]
        # The caption's equation is the order drawn: its terms are the walked arrows' names, one by one.
        caption = " ".join(item.text for item in layers[f"plane-{name}-caption"])  # a long equation is broken
        (equation,) = re.findall(r"((?:\S+ \+ )+\S+) = 0", caption)
        assert [drawing._id(term) for term in equation.split(" + ")] == [
            arrow.key.removeprefix(f"plane-{name}-") for arrow in walked]


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
@pytest.mark.parametrize(("masses", "planes"), [
    (FOLDED_EITHER_WAY, ()),
    ([RotatingMass(5.0, 0.1, 0.0, 0.2), RotatingMass(5.0, 0.1, 180.0, 0.8)], (0.0, 1.0)),  # a couple alone
    ([RotatingMass(4.0, 0.25, 70.0, 0.3)], (0.0, 1.0)),  # one mass
], ids=["folded-either-way", "couple", "one-mass"])
def test_a_vector_drawn_beside_the_chain_is_named_in_the_caption_with_what_it_would_cover(masses, planes, locale):
    """Where no order of the shares keeps every side in its place (a share folded back whichever goes first, a
    correction along the masses), the caption says which vector stands aside and why: unexplained, the dashed
    leaders read as a polygon left open."""
    from graphplan.locale import strings

    text = strings(locale)
    result = balance(BalancingSpec(masses, planes=planes, correction_radius=0.1))
    layers = {layer.name: layer.items for layer in drawing.layout(result, text)}
    names = {drawing._id(vector.name): vector.name for plane in result.planes for vector in plane.vectors}

    def squeezed(value: str) -> str:  # a caption broken over lines, Chinese at any ideograph, read whole
        return "".join(value.split())

    template = squeezed(text["bal_drawn_apart"])
    tail = template[template.index("{covered}") + len("{covered}"):]
    for plane in result.planes:
        walked, stray, _ = _drawn_chain(layers, plane.name)
        assert stray  # the walk from the pole stops at the first arrow drawn apart
        drawn = {arrow.key.removeprefix(f"plane-{plane.name}-") for arrow in walked + stray}
        caption = squeezed("".join(item.text for item in layers[f"plane-{plane.name}-caption"]))
        # One line for each arrow off the chain, and none for another.
        assert caption.count(tail) == len(stray)
        for arrow in stray:
            key = arrow.key.removeprefix(f"plane-{plane.name}-")
            vector = names[key]
            pattern = (re.escape(template).replace(re.escape("{vector}"), re.escape(vector))
                       .replace(re.escape("{covered}"), "(?P<covered>.+?)")
                       .replace(re.escape("{offset}"), "(?P<offset>[\\d.,]+)"))
            (found,) = [match.groupdict() for match in re.finditer(pattern, caption)]
            assert float(found["offset"].replace(",", ".")) == drawing.BESIDE_MM
            # What it would cover is a share of the plane that is drawn.
            assert {drawing._id(covered) for covered in found["covered"].split(",")} <= drawn - {key}


@pytest.mark.parametrize(("masses", "planes", "plane_index", "folded"), [
    (FOLDED_EITHER_WAY, (), 0, "m2r2"),
], ids=["folded-either-way"])
def test_a_share_folded_back_over_the_one_before_is_drawn_beside_it_with_leaders(masses, planes, plane_index, folded):
    result = balance(BalancingSpec(masses, planes=planes, correction_radius=2))
    plane = result.planes[plane_index]
    scale = drawing.plane_scale(plane)
    layers = {layer.name: layer.items for layer in drawing.layout(result)}
    arrows = {item.key: item for item in layers[f"plane-{plane.name}-vectors"] if isinstance(item, Arrow)}
    index = next(k for k, vector in enumerate(plane.vectors) if vector.name == folded)
    share, before = plane.vectors[index], plane.vectors[index - 1]
    # The share turns back within 25° of the one before it, and its true end lies within 2.5 mm of it.
    turn = math.degrees(abs(cmath.phase(share.vector / -before.vector)))
    assert turn < 25
    first = arrows[f"plane-{plane.name}-{drawing._id(plane.vectors[0].name)}"]
    origin = complex(*first.start) - plane.vectors[0].start / scale  # where the panel was moved to
    true_start, true_end = share.start / scale + origin, share.end / scale + origin
    prior = [before.start / scale + origin, before.end / scale + origin]
    assert _segment_distance((true_end.real, true_end.imag), *((p.real, p.imag) for p in prior)) < 2.5
    drawn = arrows[f"plane-{plane.name}-{drawing._id(folded)}"]
    moved = [complex(*drawn.start) - true_start, complex(*drawn.end) - true_end]
    # Drawn parallel to itself, its own length, BESIDE_MM across the share before it.
    assert moved[0] == pytest.approx(moved[1], abs=1e-9) and abs(moved[0]) == pytest.approx(drawing.BESIDE_MM)
    assert abs((moved[0] / (before.vector / abs(before.vector))).real) < 1e-9
    assert drawn.length == pytest.approx(abs(share.vector) / scale, rel=1e-9)
    # Its arrowhead clear of the share before it, and thin leaders from its true ends to the drawn ones.
    assert _segment_distance(drawn.end, *((p.real, p.imag) for p in prior)) > 2.5
    joined = {(round(x, 6), round(y, 6)) for item in layers[f"plane-{plane.name}-reference"]
              if getattr(item, "stroke", None) == drawing._SHARE_LEADER for x, y in item.points}
    for point in (true_start, true_end, complex(*drawn.start), complex(*drawn.end)):
        assert (round(point.real, 6), round(point.imag, 6)) in joined
    # Its name nearer its own arrow than any other side.
    (label,) = [text for text in layers[f"plane-{plane.name}-labels"] if text.text == folded]
    box = text_box(label)
    own = box.distance(LineString((drawn.start, drawn.end)))
    assert all(own < box.distance(LineString((arrow.start, arrow.end))) for key, arrow in arrows.items()
               if arrow is not drawn)


def test_the_correction_angle_is_drawn_at_the_radius_crossing_fewest_sides():
    """The hunter's B9, plane L: θL's arc at 7 mm ran over (m1r1)L as well as the (m2r2)L it cannot miss."""
    from graphplan.render.primitives import Polyline

    result = balance(BalancingSpec([RotatingMass(2.0, 0.1, 10.0, 0.1), RotatingMass(1.0, 0.1, 200.0, 0.1)],
                                   planes=(0.1, 0.5), correction_radius=0.1))
    plane = result.planes[0]
    layers = {layer.name: layer.items for layer in drawing.layout(result)}
    sides = [LineString((item.start, item.end)) for item in layers["plane-L-vectors"] if isinstance(item, Arrow)
             and item.stroke != drawing._CORRECTION]
    arc = next(item for item in layers["plane-L-reference"] if isinstance(item, Polyline)
               and item.stroke == drawing._ANGLE)
    correction = next(item for item in layers["plane-L-vectors"] if isinstance(item, Arrow)
                      and item.stroke == drawing._CORRECTION)
    tail = complex(*correction.start)

    def crossed(radius):  # the arc from the x-direction to θ about the correction's tail, as a polyline
        sweep = math.radians(plane.angle_deg)
        points = [tail + radius * cmath.exp(1j * sweep * k / 90) for k in range(91)]
        return sum(LineString([(p.real, p.imag) for p in points]).intersects(side) for side in sides)

    radius = abs(complex(*arc.points[0]) - tail)
    assert crossed(radius) == min(crossed(r) for r in drawing.ANGLE_RADII_MM) < crossed(7.0)
