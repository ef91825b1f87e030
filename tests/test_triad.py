"""The class III triad: what the fixture-wide tests cannot show.

Every fixture, the triad's included, is already checked against its closure equations, finite
differences, the 50-digit reference, the plans and the linear system of statics.  Here: which
assembly the sketch picks and that it is kept whatever positions are asked for, Assur's special
point against its definition, the structure formula, and every kind of bad input.
"""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path

import numpy as np
import pytest
from sheet_texts import flat

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.errors import AssemblyError, SceneError
from graphplan.mechanism import build
from graphplan.positions import reach
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, length_scale
from graphplan.render.primitives import Circle, Polyline
from graphplan.report.note import note_html, note_markdown
from graphplan.scene import loads

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "triad_class_iii.toml"


@functools.cache
def fixture_analysis():
    """The fixture's analysis, one for the module's tests: an analysis is a frozen record that they only read (its
    note, drawings and tables are made from it afresh by each)."""
    return analyse(graphplan.load(FIXTURE))
TEXT = FIXTURE.read_text(encoding="utf-8")
SKETCH = 'near    = { B = [0.14, 0.10], D = [0.26, 0.10], F = [0.20, 0.19] }'
assert SKETCH in TEXT


def _scene(old: str = "", new: str = ""):
    assert old in TEXT
    return loads(TEXT.replace(old, new))


def _xy(motion, name: str) -> np.ndarray:
    r = motion.point(name).r
    return r[:, 0] + 1j * r[:, 1]


def test_the_structure_formula_names_a_class_iii_group_of_the_third_order():
    mechanism = graphplan.build(graphplan.load(FIXTURE))
    assert mechanism.structure == "I(1,2) → III3(3,4,5,6)"
    # W = 3n − 2p5 with n = 5 moving links and p5 = 1 + 6 pairs
    assert mechanism.degrees_of_freedom == (5, 7, 1)


def test_another_sketch_picks_another_assembly_that_closes_as_well():
    # The second assembly of the triad at φ = 0, found by hand from the same lengths.
    other = _scene(SKETCH, 'near = { B = [0.036, 0.134], D = [0.129, 0.058], F = [0.140, 0.165] }')
    first = graphplan.solve(graphplan.load(FIXTURE), driver=[0.0])
    second = graphplan.solve(other, driver=[0.0])
    assert abs(_xy(first, "B")[0] - (0.14 + 0.10j)) < 0.005
    assert abs(_xy(second, "B")[0] - (0.036 + 0.134j)) < 0.005
    a, c, e = 0.05 + 0j, 0.22 + 0j, 0.10 + 0.35j
    b, d, f = (_xy(second, name)[0] for name in "BDF")
    for closing, expected in ((abs(b - a), 0.135), (abs(d - c), 0.108), (abs(f - e), 0.189),
                              (abs(d - b), 0.12), (abs(f - d), 0.108), (abs(b - f), 0.108)):
        assert closing == pytest.approx(expected, abs=1e-12)


def test_the_assembly_is_the_same_whatever_positions_are_asked_for():
    scene = graphplan.load(FIXTURE)
    every = graphplan.solve(scene)
    values = every.driver
    for index in (3, 7, 10):
        alone = graphplan.solve(scene, driver=[values[index]])
        for name in "BDF":
            assert abs(_xy(alone, name)[0] - _xy(every, name)[index]) < 1e-12
        assert alone.link(6).omega[0] == pytest.approx(every.link(6).omega[index], rel=1e-10)
    backwards = graphplan.solve(scene, driver=values[::-1])
    assert np.allclose(_xy(backwards, "F"), _xy(every, "F")[::-1], atol=1e-12)


def test_assurs_point_lies_on_two_binary_links_and_moves_with_the_ternary_link():
    analysis = fixture_analysis()
    for plan_position in analysis.plans:
        velocity = plan_position.velocity
        positions = plan_position.positions
        (name, sigma), = velocity.auxiliary.items()
        assert name == "Σ6"
        on_lines = [pair for pair in (("A", "B"), ("C", "D"), ("E", "F"))
                    if abs(((positions[pair[1]] - positions[pair[0]]).conjugate() * (sigma - positions[pair[0]])).imag)
                    <= 1e-9 * abs(sigma - positions[pair[0]]) * abs(positions[pair[1]] - positions[pair[0]])]
        assert len(on_lines) >= 2, "Σ is where the lines of two binary links cross"
        # The analytic velocity of the ternary link's point at Σ: vB + ω6 × BΣ.
        index = plan_position.index
        b = _xy(analysis.motion, "B")[index]
        v_b = analysis.motion.point("B").v[index]
        omega = analysis.motion.link(6).omega[index]
        expected = complex(*v_b) + 1j * omega * (sigma - b)
        assert abs(velocity.points["σ6"] - expected) <= 1e-9 * abs(expected)


@pytest.mark.parametrize(("old", "new", "where", "message"), [
    ("sides   = [0.12, 0.108, 0.108]", "sides = [0.12, 0.05, 0.05]", "groups[0].sides", "must make a triangle"),
    (SKETCH, 'near = { B = [0.14, 0.10], D = [0.26, 0.10] }', "groups[0].near.F", "where F lies in the sketch"),
    (SKETCH, 'near = { B = [0.14, 0.10], D = [0.26, 0.10], F = [0.20, 0.19], A = [0, 0] }', "groups[0].near.A",
     "must name an inner joint"),
    (SKETCH, 'near = { B = [0.1, 0.1], D = [0.2, 0.2], F = [0.3, 0.3] }', "groups[0].near", "lie in a line"),
    ("links   = [3, 4, 5, 6]", "links = [3, 4, 5]", "groups[0].links", "must have 4 entries"),
    ("links   = [3, 4, 5, 6]", "links = [3, 4, 5, 5]", "groups[0].links", "must name four different links"),
    ("lengths = [0.135, 0.108, 0.189]", "lengths = [0.135, 0.108, -0.189]", "groups[0].lengths[2]", "must be > 0"),
])
def test_a_bad_triad_is_refused_with_its_key(old, new, where, message):
    with pytest.raises(SceneError) as caught:
        _scene(old, new)
    assert caught.value.where == where and message in str(caught.value)


@pytest.mark.parametrize("swap", [(0, 1), (1, 2), (0, 5)])
def test_a_triad_whose_joints_were_typed_in_each_others_places_is_told_them_in_their_places(swap):
    """The sketch names B, D and F; the joints typed with an outer and an inner one swapped make another inner joint
    in place of one it names. The refusal gives the joints in their places."""
    joints = ["A", "B", "C", "D", "E", "F"]
    typed = list(joints)
    typed[swap[0]], typed[swap[1]] = typed[swap[1]], typed[swap[0]]
    with pytest.raises(SceneError) as caught:
        _scene('joints  = ["A", "B", "C", "D", "E", "F"]', "joints = [" + ", ".join(f'"{j}"' for j in typed) + "]")
    stray = next(name for name in typed if name in "BDF" and typed.index(name) % 2 == 0)
    assert caught.value.where == f"groups[0].near.{stray}"
    assert str(caught.value).endswith("""; the joints typed in each other's places? groups[0].joints = """
                                      """["A", "B", "C", "D", "E", "F"] makes B, D and F the inner joints""")


def test_a_triad_on_the_frame_alone_is_refused_and_nothing_is_written(tmp_path, capsys):
    # A mistyped joint: the leg AB pinned at the crank's pivot O makes the triad a truss on the frame.
    scene = tmp_path / "truss.toml"
    text = TEXT.replace('joints  = ["A", "B", "C", "D", "E", "F"]', 'joints  = ["O", "B", "C", "D", "E", "F"]')
    scene.write_text(text.replace('from = "A"', 'from = "O"'), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert "groups[0].joints: joins the frame alone (its outer joints O, C, E are frame points)" in error
    assert not out.exists()


def test_a_triad_that_cannot_close_says_so_and_writes_nothing(tmp_path, capsys):
    scene = tmp_path / "short.toml"
    scene.write_text(TEXT.replace("lengths = [0.135, 0.108, 0.189]", "lengths = [0.135, 0.108, 0.02]"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert "B cannot be assembled" in error and "III(3,4,5,6)" in error and "EF = 0.02" in error
    assert not out.exists()


def test_a_triad_that_reaches_a_limit_position_stops_there():
    # A longer crank drags the triad to a limit position before 200°: the walk stops there, naming it.
    scene = _scene("length = 0.05 ", "length = 0.08 ")
    with pytest.raises(AssemblyError) as caught:
        graphplan.solve(scene)
    error = caught.value
    assert error.group == "III(3,4,5,6)" and "limit position" in error.reason
    angle = float(error.position.split("φ = ")[1].split("°")[0])
    assert 90 < angle < 200
    # Just before it the triad still closes; the positions asked for before it are solved.
    assert graphplan.solve(scene, driver=[math.radians(angle - 2)]).count == 1


def test_the_plan_sheet_marks_assurs_point_on_the_mechanism(tmp_path):
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "velocity"]) == 0
    drawing = flat((out / "plan_2.svg").read_text(encoding="utf-8"))
    assert ">Σ6<" in drawing, "the special point is lettered on the mechanism"
    assert ">σ6<" in drawing, "and its image on the velocity plan"


def test_the_force_sheet_marks_assurs_point_where_the_group_moment_is_taken():
    analysis = fixture_analysis()
    plan_position = analysis.plans[0]
    (name, sigma), = plan_position.forces.auxiliary.items()
    assert any(equation.about == name for group in plan_position.forces.groups for equation in group.moments)
    layers = {layer.name: layer for layer in force_layout.layout(force_sheet(analysis, plan_position))}
    key = force_layout.group_id("III(3,4,5,6)")
    assert name in {item.text for item in layers[f"body-{key}-labels"].items}
    mm = 1.0 / length_scale(analysis)
    positions = plan_position.positions
    paper = {joint: positions[joint] * mm for joint in "ABCDEF"}
    links = layers[f"body-{key}-links"].items
    run_ons = [item for item in links if isinstance(item, Polyline) and item.stroke.dash]
    markers = [complex(*item.centre) for item in links if isinstance(item, Circle) and item.radius < 1.0]
    # The panel is moved as a whole: find the marker whose shift puts the run-on lines on the binary links.
    for marker in markers:
        shift = marker - sigma * mm
        starts = {joint for item in run_ons for joint, at in paper.items()
                  if abs(complex(*item.points[0]) - (at + shift)) < 1e-6
                  and abs(complex(*item.points[-1]) - marker) < 1e-6}
        if len(starts) >= 2:
            break
    else:
        pytest.fail("no marker at Σ with the binary links' lines run on to it")
    binary = {"A": "B", "B": "A", "C": "D", "D": "C", "E": "F", "F": "E"}
    for joint in starts:
        arm, other = positions[joint] - sigma, positions[binary[joint]] - sigma
        assert abs((arm.conjugate() * other).imag) <= 1e-9 * abs(arm) * abs(other), f"Σ on the line of {joint}"


def test_the_note_names_the_length_each_omega_and_epsilon_is_read_over():
    analysis = fixture_analysis()
    text = note_markdown(analysis)
    places = [{**pp.positions, **pp.velocity.auxiliary} for pp in analysis.plans]
    names = sorted(set().union(*places), key=len, reverse=True)
    readings = [line for line in text.splitlines() if re.match(r"- [ωε][3-6] = ", line)]
    assert len(readings) == 4 * 2 * len(analysis.plans)
    for line in readings:
        found = re.search(r"/l(\S+) = [^=]*/([\d.]+) = ", line)
        assert found, f"no named length in {line!r}"
        pair, printed = found.group(1), float(found.group(2))
        first = next(name for name in names if pair.startswith(name) and pair[len(name):] in names)
        second = pair[len(first):]
        assert any(math.isclose(abs(where[first] - where[second]), printed, rel_tol=1e-4) for where in places), line
    for line in readings:
        if re.match(r"- ω[345] = ", line):
            assert re.match(r"- ω\d = V([BDF])([ACE])/l\2\1 = ", line), f"a binary link's ω is VBA/lAB: {line}"
    assert "vΣ" not in text, "velocities are written V, Σ's too"
    page = note_html(analysis, markdown=text)
    assert "^τ" not in page, "every tangential part is set as a superscript"
    assert "V<sub>DΣ6</sub>" in page and "a<sub>Σ6A</sub><sup>τ</sup>" in page, "Σ6 is set in the index"


def test_the_error_tables_hold_each_binary_links_relative_velocity():
    analysis = fixture_analysis()
    arms = {3: ("A", "B"), 4: ("C", "D"), 5: ("E", "F")}
    for pp in analysis.plans:
        rows = {row.quantity: row for row in pp.errors if row.source == "construction"}
        relative = {f"V{inner}{outer}": link for link, (outer, inner) in arms.items() if f"V{inner}{outer}" in rows}
        assert len(relative) >= 2, sorted(rows)
        for quantity, link in relative.items():
            outer, inner = arms[link]
            v = analysis.motion.point(inner).v[pp.index] - analysis.motion.point(outer).v[pp.index]
            assert rows[quantity].analytic == pytest.approx(float(np.hypot(*v)), rel=1e-12)
            assert rows[quantity].plan == pytest.approx(rows[quantity].analytic, rel=1e-9)


def test_the_note_reads_each_binary_links_tangential_part_off_the_plan():
    analysis = fixture_analysis()
    text = note_markdown(analysis)
    rows = re.findall(r"\| a([BDF])([ACE])τ \| ([\d.]+) m/s² \| n(\d)[bdf] = [\d.]+ \| ⊥ \2\1 \|", text)
    assert len(rows) == 2 * len(analysis.plans)
    expected = set()
    for pp in analysis.plans:
        for link, (outer, inner) in {3: ("A", "B"), 4: ("C", "D"), 5: ("E", "F")}.items():
            arm = abs(pp.positions[inner] - pp.positions[outer])
            expected.add((inner, outer, abs(analysis.motion.link(link).epsilon[pp.index]) * arm))
    for inner, outer, value, _ in rows:
        assert any(i == inner and o == outer and math.isclose(float(value), v, rel_tol=1e-4) for i, o, v in expected)


# A student's class III six-bar (its crank 0.05 m turns round), with F sketched on the other side of BD: the sketch
# runs B, D, F clockwise round link 6, and these lengths close the ternary link only counter-clockwise.
MIRRORED_SKETCH = """
[scene]
title = "Six-bar with a class III triad, sketched mirrored"
locale = "en"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.30, -0.04], E = [0.02, 0.42] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.05
omega = -15.0
[[groups]]
kind = "triad"
links = [3, 4, 5, 6]
joints = ["A", "B", "C", "D", "E", "F"]
lengths = [0.163, 0.18, 0.248]
sides = [0.141, 0.149, 0.136]
near = { B = [0.16, 0.12], D = [0.30, 0.14], F = [0.24, 0.03] }
[positions]
count = 12
"""


def test_a_mirrored_sketch_is_told_so_not_to_check_the_lengths(tmp_path, capsys):
    """The lengths are right, and the advice was "check the lengths": it is the sketch that runs the other way."""
    with pytest.raises(AssemblyError) as raised:
        analyse(loads(MIRRORED_SKETCH))
    message = str(raised.value)
    assert "check the lengths" not in message
    assert ("the mechanism assembles at no angle of link 2 as sketched: groups[0].near runs B, D, F clockwise round "
            "the ternary link 6, and its lengths close it only the other way round, counter-clockwise: the lengths are "
            "right, the sketch is mirrored; sketch F on the other side of BD, e.g. F = [") in message
    x, y = map(float, re.search(r"e\.g\. F = \[([-\d.]+), ([-\d.]+)\]", message).groups())
    scene = tmp_path / "sketched_again.toml"
    scene.write_text(MIRRORED_SKETCH.replace("F = [0.24, 0.03]", f"F = [{x}, {y}]"), encoding="utf-8")
    assert main(["check", str(scene)]) == 0, capsys.readouterr().err


def test_lengths_that_close_the_triad_neither_way_are_still_to_check():
    """Not a mirrored sketch: told which leg's lengths close the triad at some angle, the others as given; EF from
    the length told on, the crank reaches part of its turn, as the solver finds."""
    short = MIRRORED_SKETCH.replace("lengths = [0.163, 0.18, 0.248]", "lengths = [0.063, 0.08, 0.048]")
    with pytest.raises(AssemblyError) as raised:
        analyse(loads(short))
    message = str(raised.value)
    assert "sketch is mirrored" not in message
    (low,) = re.findall(r"the mechanism assembles at no angle of link 2: the triad closes at some angle, the other "
                        r"legs as given, only with groups\[0\]\.lengths\[2\] \(EF\) from ([\d.]+) m to", message)
    assert reach(build(loads(short.replace("lengths = [0.063, 0.08, 0.048]", f"lengths = [0.063, 0.08, {low}]"))))
