"""A teacher's review of the force analysis with friction, each quantity recomputed here from scratch.

The mechanisms' positions and angular velocities are solved in closed form below, and their statics written as
every link's three equilibrium equations with the friction of each pair taken from the reactions and repeated
until they settle, as the textbook does (Artobolevsky, *Theory of Mechanisms and Machines*: the friction circle
ρ = f·r, the reaction tangent to it so that its moment about the journal opposes the relative rotation; in a
slide the reaction leaning by φ = arctan f against the relative sliding).  Nothing of graphplan's solvers is
used for the expected values.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from graphplan.analysis import analyse
from graphplan.report.forces import markdown as forces_markdown
from graphplan.report.note import note_markdown
from graphplan.report.results import results
from graphplan.scene import loads as scene_from_text

# Crank-rocker: crank OA = 0.175 m turning clockwise at 17 rad/s, coupler AB = 0.55 m, rocker CB = 0.325 m.
ROCKER_RHO = {"O": 0.1 * 0.03, "A": 0.12 * 0.02, "B": 0.15 * 0.025, "C": 0.1 * 0.03}
CRANK_ROCKER = """
[scene]
title = "Crank-rocker with friction in every journal"
locale = "{locale}"
gravity = 0.0
[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [0.0, 0.55] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.175
omega = -17.0
epsilon = 0.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.55, 0.325]
assembly = "left"
[[loads]]
kind = "moment"
link = 4
value = 1500.0
resisting = true
[[loads]]
kind = "force"
link = 3
point = "B"
value = 300.0
angle = 30.0
[[friction]]
joint = "O"
f = 0.1
radius = 0.03
[[friction]]
joint = "A"
f = 0.12
radius = 0.02
[[friction]]
joint = "B"
f = 0.15
radius = 0.025
[[friction]]
joint = "C"
f = 0.1
radius = 0.03
[positions]
count = 12
start = "extreme"
number_from = 0
working = {{ link = 4, sense = "ccw" }}
plans = [2, 8]
"""

# Offset slider-crank: crank 0.08 m at 10 rad/s counter-clockwise, rod 0.26 m, guide 0.03 m above O.
SLIDER_RHO = {"O": 0.1 * 0.02, "A": 0.1 * 0.015, "B": 0.12 * 0.012}
SLIDE_F = 0.15
SLIDER_CRANK = """
[scene]
title = "Slider-crank with friction"
gravity = 0.0
[frame]
link = 1
points = { O = [0.0, 0.0] }
lines = { g = { through = [0.0, 0.03], angle = 0.0 } }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.08
omega = 10.0
epsilon = 0.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.26
guide = "g"
assembly = "forward"
[[loads]]
kind = "force"
link = 4
point = "B"
value = 500.0
angle = 180.0
resisting = true
[[friction]]
joint = "O"
f = 0.1
radius = 0.02
[[friction]]
joint = "A"
f = 0.1
radius = 0.015
[[friction]]
joint = "B"
links = [3, 4]
f = 0.12
radius = 0.012
[[friction]]
joint = "B"
links = [1, 4]
f = 0.15
[positions]
count = 12
start = "extreme"
number_from = 1
working = { link = 4, sense = "forward" }
plans = [3, 9]
"""


def _cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


def _rocker_kinematics(phi: float) -> tuple[dict[str, complex], dict[int, float]]:
    points = {"O": 0j, "C": 0.55j, "A": 0.175 * complex(math.cos(phi), math.sin(phi))}
    a, c = points["A"], points["C"]
    span = abs(c - a)
    along = (0.55 ** 2 - 0.325 ** 2 + span ** 2) / (2 * span)
    unit = (c - a) / span
    points["B"] = b = a + along * unit + 1j * unit * math.sqrt(0.55 ** 2 - along ** 2)   # left of A→C
    speed_a = 1j * -17.0 * a
    matrix = np.array([[(1j * (b - a)).real, -(1j * (b - c)).real], [(1j * (b - a)).imag, -(1j * (b - c)).imag]])
    omega3, omega4 = np.linalg.solve(matrix, [-speed_a.real, -speed_a.imag])
    return points, {1: 0.0, 2: -17.0, 3: float(omega3), 4: float(omega4)}


def _journals(matrix: np.ndarray, known: np.ndarray, pairs, points: dict[str, complex],
              moments: dict[str, float]) -> None:
    """Into the equilibrium of links 2, 3, 4 (rows 3·(link − 2) … + 2: ΣFx, ΣFy, ΣM about the origin), each
    journal's reaction on its later link (columns 2k, 2k + 1) and its friction moment, the reverse on its earlier
    link; the frame, link 1, has no equations."""
    for column, (joint, i, j) in enumerate(pairs):
        for sign, link in ((1.0, j), (-1.0, i)):
            if link == 1:
                continue
            row = 3 * (link - 2)
            for k, unit in enumerate((1 + 0j, 1j)):
                matrix[row, 2 * column + k] += sign * unit.real
                matrix[row + 1, 2 * column + k] += sign * unit.imag
                matrix[row + 2, 2 * column + k] += sign * _cross(points[joint], unit)
            known[row + 2] -= sign * moments[joint]


def _rocker_statics(phi: float, friction: bool = True) -> tuple[float, dict[str, float]]:
    """Mb and each journal's friction moment on its later link (Mf12, Mf23, Mf34, Mf14), ccw positive."""
    points, omega = _rocker_kinematics(phi)
    pairs = [("O", 1, 2), ("A", 2, 3), ("B", 3, 4), ("C", 1, 4)]
    force = 300.0 * complex(math.cos(math.radians(30)), math.sin(math.radians(30)))
    resisting = -1500.0 * math.copysign(1.0, omega[4])
    reactions = {joint: 0j for joint, _, _ in pairs}
    moments: dict[str, float] = {}
    for _ in range(500):
        moments = {joint: -math.copysign(1.0, omega[j] - omega[i]) * ROCKER_RHO[joint] * abs(reactions[joint])
                   if friction else 0.0 for joint, i, j in pairs}
        matrix, known = np.zeros((9, 9)), np.zeros(9)
        _journals(matrix, known, pairs, points, moments)
        matrix[2, 8] = 1.0
        known[3:6] -= (force.real, force.imag, _cross(points["B"], force))
        known[8] -= resisting
        unknowns = np.linalg.solve(matrix, known)
        settled = {joint: complex(unknowns[2 * n], unknowns[2 * n + 1]) for n, (joint, _, _) in enumerate(pairs)}
        change = max(abs(settled[joint] - reactions[joint]) for joint in reactions)
        reactions = settled
        if change < 1e-10:
            break
    names = {"O": "Mf12", "A": "Mf23", "B": "Mf34", "C": "Mf14"}
    return float(unknowns[8]), {names[joint]: moment for joint, moment in moments.items()}


def _slider_kinematics(phi: float) -> tuple[dict[str, complex], dict[int, float], float]:
    a = 0.08 * complex(math.cos(phi), math.sin(phi))
    b = complex(a.real + math.sqrt(0.26 ** 2 - (0.03 - a.imag) ** 2), 0.03)
    speed_a = 1j * 10.0 * a
    omega3 = -speed_a.imag / (b - a).real
    return {"O": 0j, "A": a, "B": b}, {1: 0.0, 2: 10.0, 3: omega3, 4: 0.0}, (speed_a + 1j * omega3 * (b - a)).real


def _slider_statics(phi: float, friction: bool = True) -> tuple[float, dict[str, complex]]:
    """Mb and the friction loads on each pair's later link: Mf12, Mf23, Mf34 (ccw positive) and Ff14 (a vector)."""
    points, omega, speed = _slider_kinematics(phi)
    pairs = [("O", 1, 2), ("A", 2, 3), ("B", 3, 4)]
    resisting = -500.0 * math.copysign(1.0, speed)
    reactions = {"O": 0j, "A": 0j, "B": 0j, "N": 0j}
    moments: dict[str, float] = {}
    rubbing = 0.0
    for _ in range(500):
        moments = {joint: -math.copysign(1.0, omega[j] - omega[i]) * SLIDER_RHO[joint] * abs(reactions[joint])
                   if friction else 0.0 for joint, i, j in pairs}
        rubbing = -SLIDE_F * abs(reactions["N"]) * math.copysign(1.0, speed) if friction else 0.0
        matrix, known = np.zeros((9, 9)), np.zeros(9)
        _journals(matrix, known, pairs, points, moments)
        # The guide's normal force on the slider 4 at B, and the couple that places it along the guide.
        matrix[7, 6], matrix[8, 6], matrix[8, 7] = 1.0, points["B"].real, 1.0
        matrix[2, 8] = 1.0
        along = resisting + rubbing
        known[6:9] -= (along, 0.0, _cross(points["B"], complex(along, 0.0)))
        unknowns = np.linalg.solve(matrix, known)
        settled = {joint: complex(unknowns[2 * n], unknowns[2 * n + 1]) for n, (joint, _, _) in enumerate(pairs)}
        settled["N"] = complex(0.0, unknowns[6])
        change = max(abs(settled[key] - reactions[key]) for key in reactions)
        reactions = settled
        if change < 1e-10:
            break
    loads = {"Mf12": moments["O"], "Mf23": moments["A"], "Mf34": moments["B"], "Ff14": complex(rubbing, 0.0)}
    return float(unknowns[8]), loads


@pytest.fixture(scope="module")
def rocker():
    return analyse(scene_from_text(CRANK_ROCKER.format(locale="en")))


@pytest.fixture(scope="module")
def slider():
    return analyse(scene_from_text(SLIDER_CRANK))


def _plan_angles(analysis) -> dict[int, float]:
    document = results(analysis)
    numbers = {plan.number for plan in analysis.plans}
    return {entry["index"]: math.radians(entry["driver"]["angle_deg"]) for entry in document["positions"]
            if entry["index"] in numbers}


def test_the_crank_rockers_balancing_moment_and_efficiency_with_friction_in_every_journal_are_the_textbooks(rocker):
    document = results(rocker)
    for entry in document["positions"][1:]:   # the first is the rocker's dead centre, at rest in its pairs
        phi = math.radians(entry["driver"]["angle_deg"])
        ideal, _ = _rocker_statics(phi, friction=False)
        rubbing, moments = _rocker_statics(phi)
        friction = entry["equilibrium"]["friction"]
        assert friction["balancing_moment"] == pytest.approx(rubbing, rel=1e-8)
        assert friction["efficiency"] == pytest.approx(ideal / rubbing, rel=1e-8)
        for name, moment in moments.items():
            assert friction["loads"][name] == pytest.approx(moment, rel=1e-8)


def test_the_slider_cranks_cycle_efficiency_is_the_useful_work_over_the_driving_work(slider):
    # Midpoint rule over 3600 steps of the turn against the program's Simpson's rule with the jumps put in.
    steps = 3600
    phis = (np.arange(steps) + 0.5) * 2 * math.pi / steps
    useful = sum(_slider_statics(phi, friction=False)[0] for phi in phis) * 2 * math.pi / steps
    driving = sum(_slider_statics(phi)[0] for phi in phis) * 2 * math.pi / steps
    cycle = results(slider)["cycle_efficiency"]
    assert cycle["work_without_friction"] == pytest.approx(useful, rel=1e-5)
    assert cycle["work_with_friction"] == pytest.approx(driving, rel=1e-5)
    assert cycle["efficiency"] == pytest.approx(useful / driving, rel=1e-5)


def _section(note: str, number: int) -> str:
    """The note's section of plan position ``number`` (its heading "### 5.1. Position 3", in any language)."""
    heading = re.search(rf"^### [\d.]+ \S+ {number}$", note, re.MULTILINE)
    return note[heading.end():].split("\n### ", 1)[0]


def _journal_line(note: str, name: str) -> str:
    return next(line for line in note.splitlines() if line.startswith("- ρ") and f"; {name} = " in line)


@pytest.mark.parametrize("locale, clockwise, counter", [("en", "clockwise", "counter-clockwise"),
                                                        ("ru", "по часовой стрелке", "против часовой стрелки")])
def test_the_note_gives_each_friction_moment_the_sense_that_opposes_its_pairs_relative_rotation(locale, clockwise,
                                                                                             counter):
    analysis = analyse(scene_from_text(CRANK_ROCKER.format(locale=locale)))
    note = note_markdown(analysis)
    for number, phi in _plan_angles(analysis).items():
        section = _section(note, number)
        _, moments = _rocker_statics(phi)
        for name, moment in moments.items():
            line = _journal_line(section, name)
            # "… = 15.322 N·m, clockwise": the sense the moment turns the pair's later link in.
            assert line.endswith(f", {counter}" if moment > 0 else f", {clockwise}"), (number, name, line)
            assert not line.endswith(f", {counter}") or moment > 0


def test_forces_md_gives_each_friction_moment_its_sense_and_points_the_slides_friction_against_the_sliding(slider):
    table = forces_markdown(slider)
    for number, phi in _plan_angles(slider).items():
        section = table.split(f"## Position {number}\n", 1)[1].split("## Position", 1)[0]
        _, loads = _slider_statics(phi)
        for name in ("Mf12", "Mf23", "Mf34"):
            written = re.search(rf"\| {name} = ([\d.]+) N·m, (clockwise|counter-clockwise) \|", section)
            assert written, (number, name, section)
            assert float(written.group(1)) == pytest.approx(abs(loads[name]), rel=1e-4)
            assert written.group(2) == ("counter-clockwise" if loads[name] > 0 else "clockwise"), (number, name)
        written = re.search(r"\| Ff14 = ([\d.]+) ∠ (−?[\d.]+)° N \|", section)
        assert written, number
        assert float(written.group(1)) == pytest.approx(abs(loads["Ff14"]), rel=1e-4)
        # Against the slider's velocity along the guide: ∠ 180° while it moves to +x, ∠ 0° back.
        direction = math.degrees(math.atan2(loads["Ff14"].imag, loads["Ff14"].real))
        assert float(written.group(2).replace("−", "-")) == pytest.approx(direction, abs=1e-6)


def test_the_note_points_each_slides_friction_force_against_the_sliding(slider):
    note = note_markdown(slider)
    for number, phi in _plan_angles(slider).items():
        section = _section(note, number)
        line = next(line for line in section.splitlines() if line.startswith("- f14 = "))
        _, loads = _slider_statics(phi)
        direction = math.degrees(math.atan2(loads["Ff14"].imag, loads["Ff14"].real))
        assert f" ∠ {direction:g}° N; φ = arctan f14 = " in line, (number, line)   # the friction angle after it
