"""A student's friction exercises run as `graphplan run` runs them, each checked against the statics worked by hand.

The scenes are the course's textbook ones, massless and without weight so that the hand statics stays short: a
slider-crank with friction in the slide only (the reaction of the guide tilted by φ = arctan f against the piston's
velocity), the same with friction circles ρ = f·r in all three journals too, a crank-rocker with friction circles in
its four journals, a crank with a slotted lever and friction in the slot, and a wedge lift rubbing on its floor and
its incline.  The hand statics here takes every pair's friction as the textbook does (I. I. Artobolevsky, *Theory of
Mechanisms and Machines*, the force analysis with friction): a journal's reaction R tangent to its friction circle on
the side whose moment −ρ·|R| opposes the relative rotation of the link it acts on, a slide's friction f·|N| against
the relative velocity, and in a pair at relative rest (a dead centre) against the relative motion about to begin.
The kinematics is the closed forms of each mechanism with rates by central differences, the equilibrium solved by
the textbook's repetition (the reactions' sizes of the last solve in the friction): nothing of the package's own
solution is read.  The efficiency of a driven mechanism is η = Mb0/Mb at a position and
η = ∫Mb0 dφ / ∫Mb dφ over the cycle, as the results file defines it (`positions[].forces.friction.efficiency`,
`cycle_efficiency`).

Then the slips a student makes typing `[[friction]]`: each is told in one line naming the key path and what is
wrong, with no traceback and no output folder.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from scene_texts import central_slider_crank, wedge_lift
from scipy.integrate import trapezoid

from graphplan.cli import main

STEP = 1e-6  # rad of the crank, for the rates by central differences


def cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def sense(rate: Callable[[float], float], phi: float, omega: float) -> float:
    """The sign of a relative rate at φ; where it is zero (a dead centre), that of the motion about to begin."""
    now = rate(phi)
    if abs(now) > 1e-9:
        return math.copysign(1.0, now)
    return math.copysign(1.0, rate(phi + 1e-3 * math.copysign(1.0, omega)))


def rate_of(angle: Callable[[float], float], omega: float) -> Callable[[float], float]:
    """d(angle)/dt = d(angle)/dφ · ω, by central differences (the angle unwrapped over the step)."""
    def rate(phi: float) -> float:
        change = (angle(phi + STEP) - angle(phi - STEP) + math.pi) % (2 * math.pi) - math.pi
        return change / (2 * STEP) * omega
    return rate


def direction(points: Callable[[float], tuple], first: int, second: int) -> Callable[[float], float]:
    """The angle of the line from one of a mechanism's points to another, as the crank turns."""
    def angle(phi: float) -> float:
        start, end = points(phi)[first], points(phi)[second]
        return math.atan2(end[1] - start[1], end[0] - start[0])
    return angle


def solved(equations, sizes, unknowns: int) -> np.ndarray:
    """The textbook's repetition: the equations are linear once the reactions' sizes that the friction takes are
    fixed, so solve them with the last sizes until they settle; then the settled answer must hold exactly."""
    answer = np.zeros(unknowns)
    for _ in range(500):
        held = sizes(answer)
        at_zero = np.asarray(equations(np.zeros(unknowns), held))
        matrix = np.column_stack([np.asarray(equations(column, held)) - at_zero for column in np.eye(unknowns)])
        settled = np.linalg.solve(matrix, -at_zero)
        if np.allclose(settled, answer, rtol=1e-14, atol=1e-12):
            break
        answer = settled
    assert np.max(np.abs(equations(answer, sizes(answer)))) < 1e-8
    return answer


# ---------------------------------------------------------------- slider-crank: scenes 1 and 2

CRANK, ROD, PUSH, OMEGA = 0.1, 0.4, 1000.0, 10.0
SLIDER_CRANK = central_slider_crank(CRANK, ROD, OMEGA, locale="en") + f"""
[[loads]]
kind = "force"
link = 4
point = "B"
value = {PUSH}
angle = 180.0
resisting = true
during = "always"
[positions]
count = 12
start = 0.0
plans = [2, 5]
[drawing]
sheet = "none"
"""
SLIDE_ONLY = """
[[friction]]
joint = "B"
links = [4, 1]
f = 0.15
"""
EVERY_PAIR = """
[[friction]]
joint = "B"
links = [4, 1]
f = 0.15
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
f = 0.1
radius = 0.012
"""


def slider_crank_points(phi: float):
    a = np.array([CRANK * math.cos(phi), CRANK * math.sin(phi)])
    b = np.array([a[0] + math.sqrt(ROD ** 2 - a[1] ** 2), 0.0])
    return a, b


def slider_crank_mb(phi: float, f_slide: float, rho_o: float = 0.0, rho_a: float = 0.0, rho_b: float = 0.0) -> float:
    """Mb on the crank: the rod 3 carries F = R23 = R34 tangent to its circles at A and B; the piston 4 takes F, the
    resisting push and the guide's N with f·|N| against its motion; the crank takes −F at A and its circle at O."""
    a, b = slider_crank_points(phi)
    rod_angle = rate_of(direction(slider_crank_points, 0, 1), OMEGA)
    piston = lambda q: (slider_crank_points(q + STEP)[1][0] - slider_crank_points(q - STEP)[1][0]) / (2 * STEP) * OMEGA
    s_piston = sense(piston, phi, OMEGA)
    s_32 = sense(lambda q: rod_angle(q) - OMEGA, phi, OMEGA)   # link 3 turning relative to the crank 2
    s_34 = sense(rod_angle, phi, OMEGA)                         # link 3 relative to the piston 4, which does not turn
    s_21 = math.copysign(1.0, OMEGA)

    def equations(unknowns, sizes):
        fx, fy, normal = unknowns
        force = np.array([fx, fy])
        size, normal_size = sizes
        return [
            -cross(b - a, force) - rho_a * size * s_32 - rho_b * size * s_34,   # the rod about A
            fx - PUSH * s_piston - f_slide * normal_size * s_piston,            # the piston along the guide
            fy + normal,                                                        # the piston across it
        ]

    fx, fy, _ = solved(equations, lambda u: (math.hypot(u[0], u[1]), abs(u[2])), 3)
    force = np.array([fx, fy])
    return cross(a, force) - rho_a * math.hypot(fx, fy) * s_32 + rho_o * math.hypot(fx, fy) * s_21


# ---------------------------------------------------------------- crank-rocker: scene 3

RC_CRANK, RC_COUPLER, RC_ROCKER, RC_FRAME, RC_OMEGA, RC_MOMENT = 0.08, 0.30, 0.20, 0.28, -12.0, 50.0
RC_CIRCLES = {"O": (0.12, 0.015), "A": (0.1, 0.012), "B": (0.1, 0.01), "C": (0.12, 0.015)}
CRANK_ROCKER = f"""
[scene]
title = "Crank-rocker with friction circles"
locale = "ru"
gravity = 0.0
[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [{RC_FRAME}, 0.0] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {RC_CRANK}
omega = {RC_OMEGA}
epsilon = 0.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [{RC_COUPLER}, {RC_ROCKER}]
assembly = "left"
[[loads]]
kind = "moment"
link = 4
value = {RC_MOMENT}
resisting = true
during = "always"
[positions]
count = 12
start = 15.0
plans = [3]
[drawing]
sheet = "none"
""" + "".join(f'[[friction]]\njoint = "{joint}"\nf = {f}\nradius = {r}\n' for joint, (f, r) in RC_CIRCLES.items())


def crank_rocker_points(phi: float):
    a = np.array([RC_CRANK * math.cos(phi), RC_CRANK * math.sin(phi)])
    c = np.array([RC_FRAME, 0.0])
    chord = c - a
    d = float(np.hypot(*chord))
    along = (RC_COUPLER ** 2 - RC_ROCKER ** 2 + d ** 2) / (2 * d)
    across = math.sqrt(RC_COUPLER ** 2 - along ** 2)
    unit = chord / d
    left = np.array([-unit[1], unit[0]])   # "left" of the directed line A→C
    return a, a + along * unit + across * left, c


def crank_rocker_mb(phi: float, friction: bool) -> float:
    a, b, c = crank_rocker_points(phi)
    rho = {joint: (f * r if friction else 0.0) for joint, (f, r) in RC_CIRCLES.items()}

    omega3 = rate_of(direction(crank_rocker_points, 0, 1), RC_OMEGA)
    omega4 = rate_of(direction(crank_rocker_points, 2, 1), RC_OMEGA)
    s_32 = sense(lambda q: omega3(q) - RC_OMEGA, phi, RC_OMEGA)
    s_34 = sense(lambda q: omega3(q) - omega4(q), phi, RC_OMEGA)
    s_41 = sense(omega4, phi, RC_OMEGA)
    s_21 = math.copysign(1.0, RC_OMEGA)
    resisting = -RC_MOMENT * s_41

    def equations(force, size):
        return [
            -cross(b - a, force) - rho["A"] * size * s_32 - rho["B"] * size * s_34,     # the coupler about A
            cross(b - c, force) + resisting + rho["B"] * size * s_34 - rho["C"] * size * s_41,   # the rocker about C
        ]

    force = solved(equations, lambda u: math.hypot(*u), 2)
    size = math.hypot(*force)
    return cross(a, force) - rho["A"] * size * s_32 + rho["O"] * size * s_21


# ---------------------------------------------------------------- slotted lever: scene 4

SL_CRANK, SL_CENTRES, SL_OMEGA, SL_MOMENT, SL_F = 0.1, 0.25, 8.0, 100.0, 0.2
SLOTTED_LEVER = f"""
[scene]
title = "Slotted lever, friction in the slot"
locale = "en"
gravity = 0.0
[frame]
link = 1
points = {{ C = [0.0, 0.0], O = [0.0, {SL_CENTRES}] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {SL_CRANK}
omega = {SL_OMEGA}
epsilon = 0.0
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
offset = 0.0
[[loads]]
kind = "moment"
link = 4
value = {SL_MOMENT}
resisting = true
during = "always"
[[friction]]
joint = "A"
links = [3, 4]
f = {SL_F}
[positions]
count = 12
start = 10.0
plans = [4]
[drawing]
sheet = "none"
"""


def slotted_lever_mb(phi: float, f: float) -> float:
    """The block 3, massless on a pin without friction, takes the slot's N and f·|N| through A; the lever's moment
    about C holds the resisting moment with N alone (the friction lies along CA), so f changes only the crank's."""
    o = np.array([0.0, SL_CENTRES])
    place = lambda q: o + SL_CRANK * np.array([math.cos(q), math.sin(q)])
    a = place(phi)
    along = a / np.hypot(*a)
    across = np.array([-along[1], along[0]])
    lever = rate_of(lambda q: math.atan2(place(q)[1], place(q)[0]), SL_OMEGA)
    sliding = lambda q: (np.hypot(*place(q + STEP)) - np.hypot(*place(q - STEP))) / (2 * STEP) * SL_OMEGA
    resisting = -SL_MOMENT * sense(lever, phi, SL_OMEGA)
    # R34 = −(N·across + T·along) at A on the lever: the moment about C is −N·|CA|.
    normal = resisting / float(np.hypot(*a))
    friction = -f * abs(normal) * sense(sliding, phi, SL_OMEGA)
    on_crank = normal * across + friction * along   # R32 = R43, the slot's on the block, passed on through the pin
    return -cross(a - o, on_crank)


# ---------------------------------------------------------------- running the scenes as the student does

def run(tmp_path: Path, text: str, name: str) -> dict:
    scene = tmp_path / f"{name}.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / name
    assert main(["run", str(scene), "--out", str(out), "--only", "forces,note"]) == 0
    return json.loads((out / "results.json").read_text(encoding="utf-8"))


SCENES = {
    "slider-crank, slide only": (SLIDER_CRANK + SLIDE_ONLY, OMEGA,
                                 lambda q: slider_crank_mb(q, 0.0), lambda q: slider_crank_mb(q, 0.15)),
    "slider-crank, every pair": (SLIDER_CRANK + EVERY_PAIR, OMEGA, lambda q: slider_crank_mb(q, 0.0),
                                 lambda q: slider_crank_mb(q, 0.15, 0.1 * 0.02, 0.1 * 0.015, 0.1 * 0.012)),
    "crank-rocker, friction circles": (CRANK_ROCKER, RC_OMEGA,
                                       lambda q: crank_rocker_mb(q, False), lambda q: crank_rocker_mb(q, True)),
    "slotted lever, slot": (SLOTTED_LEVER, SL_OMEGA,
                            lambda q: slotted_lever_mb(q, 0.0), lambda q: slotted_lever_mb(q, SL_F)),
}


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("friction_scenes")
    return {name: run(folder, text, f"scene{i}") for i, (name, (text, *_)) in enumerate(SCENES.items())}


@pytest.mark.parametrize("name", SCENES)
def test_the_balancing_moment_and_efficiency_at_each_position_are_the_hand_statics(runs, name):
    _, _, without, with_friction = SCENES[name]
    for position in runs[name]["positions"]:
        phi = math.radians(position["driver"]["angle_deg"])
        equilibrium = position["equilibrium"]
        mb0, mb = without(phi), with_friction(phi)
        assert equilibrium["balancing_moment"] == pytest.approx(mb0, rel=1e-6, abs=1e-6), position["index"]
        assert equilibrium["friction"]["balancing_moment"] == pytest.approx(mb, rel=1e-6, abs=1e-6), position["index"]
        if abs(mb0) > 1e-6:
            assert equilibrium["friction"]["efficiency"] == pytest.approx(mb0 / mb, rel=1e-6), position["index"]
        if "forces" in position:   # the polygons with friction on the plan positions give the same
            assert position["forces"]["friction"]["balancing_moment"] == pytest.approx(mb, rel=1e-6)


@pytest.mark.parametrize("name", SCENES)
def test_the_cycle_efficiency_is_the_ratio_of_the_hand_works(runs, name):
    _, omega, without, with_friction = SCENES[name]
    # The works the driver gives over a turn, taken in the sense it turns (dφ = ω·dt), at every fifth of a degree:
    # the trapezoids then differ from those at every twentieth by under 1e-6 of the work for each scene, far inside
    # the 2e-4 asked of the run, in a quarter of the hand statics' time.
    angles = np.linspace(0.0, 2 * math.pi, 1801) * math.copysign(1.0, omega)
    work0 = trapezoid([without(q) for q in angles], angles)
    work = trapezoid([with_friction(q) for q in angles], angles)
    cycle = runs[name]["cycle_efficiency"]
    assert cycle["work_without_friction"] == pytest.approx(work0, rel=2e-4)
    assert cycle["work_with_friction"] == pytest.approx(work, rel=2e-4)
    assert cycle["efficiency"] == pytest.approx(work0 / work, rel=2e-4)
    assert 0 < cycle["efficiency"] < 1


# ---------------------------------------------------------------- the slips

def run_slip(tmp_path: Path, capsys, text: str) -> tuple[int, str, str, Path]:
    scene = tmp_path / "slip.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "slip"
    status = main(["run", str(scene), "--out", str(out), "--only", "forces"])
    told = capsys.readouterr()
    return status, told.out, told.err, out


SLIPS = {
    "a negative coefficient": (SLIDER_CRANK + SLIDE_ONLY.replace("f = 0.15", "f = -0.15"),
                               r"friction\[0\]\.f: must be >= 0 \(got -0\.15\)"),
    "a percentage written as text": (SLIDER_CRANK + SLIDE_ONLY.replace("f = 0.15", 'f = "15%"'),
                                     (r"friction\[0\]\.f: must be a number, not a string \(got '15%'\); .*no % sign.*"
                                     r"15 % is written 0\.15")),
    "a percentage that makes the friction circle wider than the links": (
        SLIDER_CRANK + EVERY_PAIR.replace("f = 0.1\nradius = 0.02", "f = 10\nradius = 0.02"),
        (r"friction\[1\]\.f: makes the friction circle at O ρ = f·r = 10 × 0\.02 m = 0\.2 m, larger than the links.*"
        r"not a percentage \(10 % is f = 0\.1\)")),
    "a joint with no pair": (SLIDER_CRANK + SLIDE_ONLY + '[[friction]]\njoint = "D"\nf = 0.1\nradius = 0.01\n',
                             (r"friction\[1\]\.joint: names no pair of the mechanism; its pairs are "
                              r"O \(1–2\), A \(2–3\), B \(3–4\), B \(1–4\) \(got 'D'\)")),
    "a joint typed as its plan's letter": (SLIDER_CRANK + SLIDE_ONLY.replace('joint = "B"', 'joint = "b"'),
                                           (r"friction\[0\]\.joint: names no pair of the mechanism; its pairs are "
                                            r".* \(got 'b'\); did you mean 'B'\?$")),
    "links that no pair at the joint joins": (SLIDER_CRANK + SLIDE_ONLY.replace("[4, 1]", "[3, 1]"),
                                              r"friction\[0\]\.links: joint B joins links 3–4 and 1–4, not these"),
    "a turning pair without its radius": (SLIDER_CRANK + SLIDE_ONLY + '[[friction]]\njoint = "O"\nf = 0.1\n',
                                          (r"friction\[1\]\.radius: the pair at O turns: give its journal radius \(m\) "
                                          r"for the friction circle")),
    "a radius on a slide": (SLIDER_CRANK + SLIDE_ONLY.replace("f = 0.15", "f = 0.15\nradius = 0.01"),
                            r"friction\[0\]\.radius: the pair at B slides: a radius is for a turning pair"),
    "a radius in millimetres": (SLIDER_CRANK + SLIDE_ONLY + '[[friction]]\njoint = "O"\nf = 0.1\nradius = 20\n',
                                (r"friction\[1\]\.radius: a journal of radius 20 m at O is larger than the links.*"
                                r"20 mm is 0\.02 m")),
    "mu for f": (SLIDER_CRANK + SLIDE_ONLY.replace("f = 0.15", "mu = 0.15"),
                 r"friction\[0\]\.mu: unknown key; the coefficient of friction is given as f: write f = 0\.15"),
}


@pytest.mark.parametrize("slip", SLIPS)
def test_a_slip_in_the_friction_is_told_in_one_line_with_its_key_and_no_folder(tmp_path, capsys, slip):
    text, told = SLIPS[slip]
    status, _, err, out = run_slip(tmp_path, capsys, text)
    assert status == 2
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert re.match(r"graphplan: error: " + told, lines[0]), lines[0]
    assert not out.exists()


def test_a_percentage_typed_for_a_slides_f_is_warned_of_and_its_locking_named(tmp_path, capsys):
    # f above 1 is taken (a few pairs reach it), so the run goes on; the warning names the key and the percentage.
    status, printed, err, _out = run_slip(tmp_path, capsys, SLIDER_CRANK + SLIDE_ONLY.replace("f = 0.15", "f = 15"))
    assert status == 0
    err = printed + err
    assert "warning: friction[0].f = 15 (at B): few pairs of materials rub with an f above 1" in err
    assert "(15 % is f = 0.15)" in err
    assert re.search(r"warning: positions [0-9–, ]+: the friction in the slide at B \(links 1–4, f = 15\) locks the "
                     r"mechanism here", err)
    assert "Traceback" not in err


# ---------------------------------------------------------------- the note's friction section

@pytest.mark.parametrize(("locale", "arctangent", "worked"), [
    ("en", "arctan", "fB = 0.15; Ff14 = fB·R14 = 0.15·"),
    ("ru", "arctg", "fB = 0,15; Ff14 = fB·R14 = 0,15·"),
])
def test_the_note_gives_each_slides_friction_angle_as_the_force_sheet_does(tmp_path, locale, arctangent, worked):
    text = (SLIDER_CRANK + SLIDE_ONLY).replace('locale = "en"', f'locale = "{locale}"')
    run(tmp_path, text, "note")
    note = (tmp_path / "note" / "note.md").read_text(encoding="utf-8")
    angle = f"{math.degrees(math.atan(0.15)):.4f}"   # φ = arctan f, 8.5308°
    if locale == "ru":
        angle = angle.replace(".", ",")
    lines = [line for line in note.splitlines() if worked in line]
    assert len(lines) == 2   # each plan position's friction loads
    for line in lines:
        assert line.endswith(f"; φ = {arctangent} fB = {angle}°"), line


# ---------------------------------------------------------------- a wedge lift: scene 5

WEDGE_ANGLE, WEDGE_LOAD, FLOOR_F, INCLINE_F = 20.0, 2000.0, 0.12, 0.15


def wedge_with_friction_on_both_faces(velocity: float) -> str:
    return wedge_lift(WEDGE_ANGLE, WEDGE_LOAD, velocity, count=5, title="Wedge lift with friction on both faces") + f"""
[[friction]]
joint = "A"
links = [1, 2]
f = {FLOOR_F}
[[friction]]
joint = "B"
links = [2, 3]
f = {INCLINE_F}
[drawing]
sheet = "none"
"""


@pytest.mark.parametrize(("velocity", "stroke"), [(-0.05, "raising"), (0.05, "lowering")])
def test_a_wedge_with_friction_on_both_faces_takes_the_textbooks_force_and_efficiency(tmp_path, velocity, stroke):
    """The incline's reaction leans by φ2 = arctan f2 against the sliding, so the load W on the post (frictionless)
    takes W·tan(α ± φ2) across; the floor's, by φ1 under the wedge's W: the push that raises the load is
    W·(tan(α + φ2) + tan φ1) at η = tan α / (tan(α + φ2) + tan φ1), the hold that lowers it W·(tan(α − φ2) − tan φ1)
    at η′ = (tan(α − φ2) − tan φ1) / tan α, which the results write as η where the load drives (Fb/Fb0)."""
    alpha, floor, incline = math.radians(WEDGE_ANGLE), math.atan(FLOOR_F), math.atan(INCLINE_F)
    if stroke == "raising":
        ideal = WEDGE_LOAD * math.tan(alpha)
        rubbing = WEDGE_LOAD * (math.tan(alpha + incline) + math.tan(floor))
        efficiency = ideal / rubbing
    else:
        ideal = WEDGE_LOAD * math.tan(alpha)
        rubbing = WEDGE_LOAD * (math.tan(alpha - incline) - math.tan(floor))
        efficiency = rubbing / ideal
    for position in run(tmp_path, wedge_with_friction_on_both_faces(velocity), stroke)["positions"]:
        equilibrium = position["equilibrium"]
        assert abs(equilibrium["balancing_force"]) == pytest.approx(ideal, rel=1e-9)
        assert abs(equilibrium["friction"]["balancing_force"]) == pytest.approx(rubbing, rel=1e-9)
        assert equilibrium["friction"]["efficiency"] == pytest.approx(efficiency, rel=1e-9)
