"""A crank that only rocks (``driver.swing``): a double rocker driven by its input lever.

The lever OA cannot turn round (Grashof: the coupler is the shortest link), so its positions run over
its swing from one end to the other, as a slider's run over its travel.  Checked against
calculations that do not go through graphplan's solver: the four-bar's joint B by crossing two
circles, its ω3 and ω4 from the two scalar velocity equations written out by hand; the plans and
the force polygons against the analytic solution and the statics (the error table's construction
column); and every way the swing can be given wrongly.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.errors import AssemblyError, SceneError
from graphplan.kinematic_diagrams import of_analysis
from graphplan.mechanism import build
from graphplan.positions import FULL_TURN, reach, turns_round
from graphplan.scene import loads

FIXTURE = "fixtures/double_rocker_swing.toml"
O, C = 0.0, 0.3 + 0.0j
OA, AB, CB = 0.25, 0.12, 0.2
OMEGA = 4.0


@pytest.fixture(scope="module")
def text():
    with open(FIXTURE, encoding="utf-8") as handle:
        return handle.read()


@pytest.fixture(scope="module")
def analysis():
    return analyse(graphplan.load(FIXTURE))


def changed(text: str, old: str, new: str) -> str:
    assert re.search(old, text, flags=re.MULTILINE), old
    return re.sub(old, new, text, count=1, flags=re.MULTILINE)


def by_hand(phi: float) -> tuple[complex, float, float]:
    """B by crossing the circles about A (radius AB) and C (radius CB), on the right of A→C; ω3, ω4 from
    ω2·OA⊥ + ω3·AB⊥ = ω4·CB⊥ split into x and y (Cramer's rule)."""
    a = OA * complex(math.cos(phi), math.sin(phi))
    d = abs(C - a)
    along = (d * d + AB * AB - CB * CB) / (2 * d)
    across = math.sqrt(AB * AB - along * along)
    u = (C - a) / d
    b = a + along * u - 1j * across * u  # right of the directed line A→C
    ab, cb = b - a, b - C
    # i·ω2·OA + i·ω3·AB − i·ω4·CB = 0  →  ω3·AB − ω4·CB = −ω2·OA (as complex numbers)
    rhs = -OMEGA * a
    det = (ab.real * -cb.imag) - (-cb.real * ab.imag)
    omega3 = (rhs.real * -cb.imag - (-cb.real) * rhs.imag) / det
    omega4 = (ab.real * rhs.imag - rhs.real * ab.imag) / det
    return b, omega3, omega4


def test_the_positions_run_over_the_swing_end_to_end(analysis):
    angles = np.asarray(analysis.positions.values)
    assert angles == pytest.approx(np.radians(np.linspace(20.0, 65.0, 7)), abs=1e-15)
    # The two ends are the positions drawn bold on the plan of positions.
    assert np.asarray(analysis.emphasised.driver) == pytest.approx(np.radians([20.0, 65.0]), abs=1e-15)
    # The paths run over the swing only, from one end to the other.
    track = np.asarray(analysis.paths.links[2].angle)
    assert (track.min(), track.max()) == pytest.approx(np.radians((20.0, 65.0)), abs=1e-12)


def test_the_motion_agrees_with_the_four_bar_worked_by_hand(analysis):
    motion = analysis.motion
    for index, phi in enumerate(analysis.positions.values):
        b, omega3, omega4 = by_hand(float(phi))
        assert complex(motion.points["B"].r[index]) == pytest.approx(b, abs=1e-12)
        assert float(motion.links[3].omega[index]) == pytest.approx(omega3, rel=1e-10)
        assert float(motion.links[4].omega[index]) == pytest.approx(omega4, rel=1e-10)


def test_plans_and_force_polygons_agree_with_the_analytic_solution_and_the_statics(analysis):
    assert [plan.number for plan in analysis.plans] == [2, 5]
    for plan in analysis.plans:
        built = [row for row in plan.errors if row.source == "construction"]
        assert {"VB", "omega4", "aB", "epsilon4", "R12", "R34"} <= {row.quantity for row in built}
        assert all(abs(row.percent) < 1e-9 for row in built), [r for r in built if abs(r.percent) >= 1e-9]
        # Zhukovsky's lever gives the balancing moment of the polygons.
        assert plan.lever.balancing == pytest.approx(plan.forces.balancing, rel=1e-9)


@pytest.mark.parametrize("locale, word, crank", [("en", "rocker", "crank"), ("ru", "коромысло", "кривошип"),
                                                  ("zh", "摇杆", "曲柄")])
def test_the_note_names_a_swinging_driver_a_rocker(locale, word, crank):
    """A hand lever over 45° was a «кривошип» (曲柄) in the structure table (a Chinese student's reading)."""
    import dataclasses

    from graphplan.render.drawings import POSITIONS_FIELD_MM, paths_extent
    from graphplan.report.note import note_markdown
    from graphplan.scales import fit_scale

    scene = dataclasses.replace(graphplan.load(FIXTURE), locale=locale)
    # The structure table names the driver alike at any μl: fixed at the one that draws the paths into the plan of
    # positions' field, not chosen by laying the sheets out at a few μl (seconds a note, none of its words).
    length_scale = fit_scale(paths_extent(analyse(scene)), POSITIONS_FIELD_MM)
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, length_scale=length_scale))
    note = note_markdown(analyse(scene))
    driver_row = next(line for line in note.splitlines() if line.startswith("| I(1,2) |"))
    assert driver_row.split("|")[-2].strip() == word and crank not in driver_row


def test_the_command_line_writes_the_run_with_the_driver_s_angles_over_the_swing(tmp_path):
    out = tmp_path / "out"
    assert main(["run", FIXTURE, "--out", str(out)]) == 0
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    angles = [position["driver"]["angle_deg"] for position in results["positions"]]
    assert angles == pytest.approx(list(np.linspace(20.0, 65.0, 7)), abs=1e-9)
    assert {"plan_2.svg", "forces_5.svg", "sheet_1.svg", "note.md"} <= {path.name for path in out.iterdir()}
    assert not (out / "diagrams.svg").exists()  # the fixture names no output link (positions.working)
    assert "| φ2 | 20° … 65° |" in (out / "note.md").read_text(encoding="utf-8")


WORKING = (r"^count = 7$", 'count = 7\nworking = { link = 4, sense = "cw" }')


@pytest.mark.parametrize(("edits", "where", "words"), [
    ([(r"^swing .*$", "swing = [20.0, 20.0]")], "driver.swing", "less than a turn"),
    ([(r"^swing .*$", "swing = [0.0, 360.0]")], "driver.swing", "less than a turn"),
    ([(r"^swing .*$", "swing = [20.0]")], "driver.swing", ""),
    ([(r"^count = 7$", "count = 7\nstart = 20.0")], "positions.start", "driver.swing"),
    ([WORKING, (r'^during    = "always"$', "during = { from = 0.0, to = 0.5 }")], "loads[0].during", "swing"),
    ([(r"^\[drawing\]$", "[dynamics]\ndelta = 0.05\n\n[drawing]")], "dynamics", "driver.swing"),
])
def test_a_swing_given_wrongly_is_named_with_what_to_change(text, edits, where, words):
    for old, new in edits:
        text = changed(text, old, new)
    with pytest.raises(SceneError) as raised:
        analyse(loads(text))
    assert raised.value.where.startswith(where)
    assert words in str(raised.value)


def test_a_swing_beyond_the_lever_s_reach_names_the_position_it_cannot_reach(text):
    with pytest.raises(AssemblyError) as raised:
        analyse(loads(changed(text, r"^swing .*$", "swing = [20.0, 80.0]")))
    # 80° lies beyond 70.5°, where A–C exceeds AB + BC: the last position (φ = 80°) fails.
    assert "φ = 80°" in str(raised.value) and "AB + BC" in str(raised.value)


def test_a_crank_that_cannot_turn_round_is_told_to_swing(text):
    with pytest.raises(AssemblyError) as raised:
        analyse(loads(changed(text, r"^swing .*$", "")))
    assert "driver.swing" in str(raised.value)
    # Positions inside the reach, but the paths over the turn leave it: the same advice.
    single = changed(changed(text, r"^swing .*$", ""), r"^count = 7$", "count = 1\nstart = 30.0")
    with pytest.raises(AssemblyError) as raised:
        analyse(loads(changed(single, r"^plans = \[2, 5\]$", "plans = [1]")))
    assert "driver.swing" in str(raised.value)


def lever_reach_by_hand(turned_deg: float = 0.0) -> list[tuple[float, float]]:
    """The lever's reach in degrees: A–C runs from |AB − BC| to AB + BC, so by the law of cosines in
    triangle OAC the lever stands at ±arccos((OA² + OC² − AC²) / (2·OA·OC)) from the frame line O→C at each
    end; ``turned_deg`` turns the frame line."""
    frame = abs(C - O)

    def apart(ac: float) -> float:
        return math.degrees(math.acos((OA * OA + frame * frame - ac * ac) / (2 * OA * frame)))

    near, far = apart(abs(AB - CB)), apart(AB + CB)
    return [(turned_deg + near, turned_deg + far), (turned_deg + 360.0 - far, turned_deg + 360.0 - near)]


def turned_frame(text: str, degrees: float) -> str:
    at = abs(C) * complex(math.cos(math.radians(degrees)), math.sin(math.radians(degrees)))
    return changed(text, r"^points = \{ O = \[0\.0, 0\.0\], C = \[0\.3, 0\.0\] \}$",
                   f"points = {{ O = [0.0, 0.0], C = [{at.real!r}, {at.imag!r}] }}")


def test_the_lever_s_reach_is_where_the_law_of_cosines_puts_it(analysis):
    found = np.degrees(reach(analysis.mechanism))
    assert found == pytest.approx(np.array(lever_reach_by_hand()), abs=1e-6)


def test_a_reach_through_zero_starts_at_a_negative_angle(text):
    # The frame line turned 40° clockwise: the upper range runs from −26.9° to 30.5°.
    mechanism = analyse(loads(changed(turned_frame(text, -40.0), r"^swing .*$", "swing = [-20.0, 25.0]"))).mechanism
    found = np.degrees(reach(mechanism))
    above, below = lever_reach_by_hand(-40.0)
    assert above[0] < 0.0 < above[1]
    assert found == pytest.approx(np.array([above, below]), abs=1e-6)


def test_a_crank_that_turns_round_reaches_the_whole_turn():
    mechanism = analyse(graphplan.load("fixtures/engine_slider_crank.toml")).mechanism
    assert reach(mechanism) == ((0.0, 2.0 * math.pi),)


@pytest.mark.parametrize("crank", [0.01, 0.015, 0.05, 0.25, 0.35])
def test_a_crank_turns_round_where_its_reach_is_the_whole_turn_and_the_four_bar_closes_all_round(text, crank):
    """turns_round, which the advice of a length a digit off asks without finding a reach's ends, answers as reach
    does, and as the four-bar's lengths do: A–C runs from |OC − OA| to OC + OA over the turn, and B closes all
    round where that stays within |AB − CB| … AB + CB (here for OA up to 0.02 m)."""
    mechanism = build(loads(changed(changed(text, r"^swing .*$", ""), r"^length *= 0\.25\b.*$",
                                    f"length = {crank}")))
    closes = abs(C) + crank <= AB + CB and abs(abs(C) - crank) >= abs(AB - CB)
    assert turns_round(mechanism) is (reach(mechanism) == FULL_TURN) is closes


def test_the_advice_gives_the_reach_and_a_swing_that_runs(text):
    with pytest.raises(AssemblyError) as raised:
        analyse(loads(changed(text, r"^swing .*$", "")))
    message = str(raised.value)
    for low, high in lever_reach_by_hand():
        assert f"from {math.ceil(low * 100) / 100:.2f}° to {math.floor(high * 100) / 100:.2f}°" in message
    suggested = re.search(r"driver\.swing = \[(\d+), (\d+)\]", message)
    assert suggested, message
    first, last = int(suggested[1]), int(suggested[2])
    near, far = lever_reach_by_hand()[0]
    assert near < first < last < far
    ran = analyse(loads(changed(text, r"^swing .*$", f"swing = [{first}.0, {last}.0]")))
    assert math.degrees(ran.positions.values[-1]) == pytest.approx(last)


def test_a_swing_beyond_the_reach_is_told_the_reach_and_a_swing_to_its_end_as_told_runs(text):
    """The reach was written to a tenth rounded to nearest: 70.5° for 70.486°, and a swing to 70.49° was
    refused by the message that allowed it (a user's try)."""
    with pytest.raises(AssemblyError) as raised:
        analyse(loads(changed(text, r"^swing .*$", "swing = [20.0, 80.0]")))
    (low, high), _ = lever_reach_by_hand()
    told = re.search(r"reaches only from ([\d.]+)° to ([\d.]+)°", str(raised.value))
    assert low <= float(told[1]) < low + 0.01 and high - 0.01 < float(told[2]) <= high
    assert "keep driver.swing within" in str(raised.value)
    ran = analyse(loads(changed(text, r"^swing .*$", f"swing = [20.0, {told[2]}]")))
    assert math.degrees(ran.positions.values[-1]) == pytest.approx(float(told[2]))


def test_a_mechanism_that_assembles_nowhere_is_told_to_check_its_lengths(text):
    """AB + BC = 0.04 m, shorter than the least A–C there is, OC − OA = 0.05 m (its most OC + OA = 0.55 m): with BC
    at 0.02 m, AB closes B at some angle from 0.05 − 0.02 to 0.55 + 0.02 m, told rounded inward."""
    short = changed(text, r"^lengths  = \[0\.12, 0\.2\] .*$", "lengths  = [0.02, 0.02]")
    with pytest.raises(AssemblyError) as raised:
        analyse(loads(short))
    assert ("assembles at no angle of link 2: A–C runs from 0.05 m (at φ = 0°) to 0.55 m (at φ = 180°), so B closes "
            "at some angle only where AB + BC ≥ 0.05 m and |AB − BC| ≤ 0.55 m: groups[0].lengths[0] (AB) from "
            "0.03001 m to 0.5699 m with BC as given") in str(raised.value)


def test_the_kinematic_diagrams_run_over_the_swing_as_worked_by_hand(text):
    found = of_analysis(analyse(loads(changed(text, *WORKING))))
    assert not found.cyclic and found.driver == "crank"
    assert found.span == pytest.approx(math.radians(45.0), abs=1e-15)
    assert found.numbers == tuple(range(1, 8)) and found.intervals == 6
    phis = np.radians(np.linspace(20.0, 65.0, 7))
    rocker = [by_hand(float(phi)) for phi in phis]
    angles = np.unwrap([math.atan2((b - C).imag, (b - C).real) for b, _, _ in rocker])
    # The working sense is clockwise: the diagrams count the rocker's turn and speed that way.
    assert found.s_nodes == pytest.approx(-(angles - angles[0]), abs=1e-12)
    assert found.v_nodes == pytest.approx([-omega4 for _, _, omega4 in rocker], rel=1e-10)
    # The time axis: 45° at 4 rad/s over the axis of L mm.
    assert found.scales.time * found.scales.axis_mm == pytest.approx(math.radians(45.0) / OMEGA, rel=1e-12)
    # The same swing given from its other end is met backwards: the lever still rises at ω > 0.
    backward = of_analysis(analyse(loads(changed(changed(text, *WORKING), r"^swing .*$", "swing = [65.0, 20.0]"))))
    assert backward.numbers == tuple(range(7, 0, -1))
    assert backward.s == pytest.approx(found.s, abs=1e-12)


# A class III six-bar whose crank is too long to turn round (a student's, 0.075 m): its reach ends where the triad
# stands in a limit position, and a degree inside it the acceleration of link 5 still runs to −162 452 rad/s².
TRIAD_TOO_LONG_A_CRANK = """
[scene]
title = "Six-bar with a class III triad"
locale = "en"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.30, -0.04], E = [0.02, 0.42] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.075
omega = -15.0
epsilon = 5.0
[[groups]]
kind = "triad"
links = [3, 4, 5, 6]
joints = ["A", "B", "C", "D", "E", "F"]
lengths = [0.163, 0.18, 0.248]
sides = [0.141, 0.149, 0.136]
near = { B = [0.16, 0.12], D = [0.30, 0.14], F = [0.20, 0.25] }
[positions]
count = 12
start = "extreme"
number_from = 1
working = { link = 5, sense = "ccw" }
plans = [3, 9]
[drawing]
velocity_pole = 100.0
acceleration_pole = 100.0
"""


def test_the_swing_advised_is_one_the_next_check_takes(tmp_path, capsys):
    """The advice gave driver.swing = [85, 392], a degree inside the reach, and the next check refused it: the
    kinematic diagram of link 5 would be 2667 mm tall near its first position.  The swing advised is now one the
    program takes when it is fed back (with positions.start left out, as a rocking crank has none)."""
    scene = tmp_path / "too_long_a_crank.toml"
    scene.write_text(TRIAD_TOO_LONG_A_CRANK, encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    told = capsys.readouterr().err
    assert "link 2 reaches only from 83.86° to 393.46°" in told
    first, last = map(int, re.search(r"e\.g\. driver\.swing = \[(-?\d+), (-?\d+)\]", told).groups())
    assert 83.86 < first < last < 393.46
    rocking = TRIAD_TOO_LONG_A_CRANK.replace('start = "extreme"\n', "").replace(
        "epsilon = 5.0\n", f"epsilon = 5.0\nswing = [{first}, {last}]\n")
    scene.write_text(rocking, encoding="utf-8")
    assert main(["check", str(scene)]) == 0, capsys.readouterr().err


def test_a_swing_that_ends_at_its_toggle_leaves_every_other_position_s_resisting_load_turned_right(text):
    """The swing up to the very end of the lever's reach: the last position is a toggle, its ω infinite.  Beside an
    infinite ω every other position's ω4 counted as rest, and the resisting moment was turned against ε4 instead
    of against ω4: the linear system's Mb at position 2 came out 1.912 N·m where the force polygons (and the power
    balance) give 5.424, and the note called the student's right polygons 65 % off."""
    (_, toggle), _ = lever_reach_by_hand()  # A–C = AB + BC: the coupler and the rocker in line
    at_toggle = loads(text.replace("swing   = [20.0, 65.0]", f"swing   = [20.0, {toggle!r}]"))
    analysis = analyse(at_toggle)
    assert analysis.motion.singular and max(analysis.motion.singular) == analysis.motion.count - 1
    for plan in analysis.plans:
        assert analysis.equilibrium.balancing[plan.index] == pytest.approx(plan.forces.balancing, rel=1e-9)
