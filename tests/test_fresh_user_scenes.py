"""Scenes a student writes from the docs alone for mechanisms the fixtures lack (a Whitworth quick-return, a
four-bar whose coupler point drives a slider, a slotted lever driving a rocker), run as written and with the
student's usual slips: each slip told where and what, no folder left behind, and the numbers checked against a
hand calculation of the geometry."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main

# After Khurmi & Gupta, Theory of Machines, the Whitworth quick-return example: OQ = 100 mm, OP = 200 mm,
# QR = 150 mm, RS = 500 mm, the crank at 120 rpm clockwise.  The lever turns round about Q; R on its tail.
WHITWORTH = """
[scene]
title = "Whitworth quick-return mechanism"
[frame]
link = 1
points = { O = [0.0, 0.0], Q = [0.0, -0.1] }
lines = { ram = { through = "Q", angle = 0.0 } }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "P"
length = 0.2
rpm = -120.0
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["P", "Q"]
[points]
R = { link = 4, from = "Q", toward = "P", at = -0.15 }
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["R", "S"]
length = 0.5
guide = "ram"
assembly = "forward"
[positions]
count = 12
start = 0.0
working = { link = 6, sense = "backward" }
"""

# A crank-rocker O-A-B-C whose coupler point E drives the slider F by the rod EF (my own dimensions of the
# textbook kind: lOA = 100, lAB = 350, lBC = 250, lOC = 300, E 150 along AB and 120 to its left, lEF = 400 mm).
SIX_BAR = """
[scene]
title = "Six-bar with a coupler-point slider"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.3, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
rpm = 150.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.35, 0.25]
assembly = "left"
[points]
E = { link = 3, from = "A", toward = "B", at = 0.15, offset = 0.12 }
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["E", "F"]
length = 0.4
guide = { through = [0.0, 0.45], angle = 0.0 }
assembly = "forward"
[positions]
count = 6
start = 0.0
"""


def _refused(tmp_path, capsys, text: str) -> str:
    """The one line ``run`` refuses ``text`` with, after checking that it left no folder and no traceback."""
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    lines = [line for line in err.splitlines() if line.startswith("graphplan: error: ")]
    assert len(lines) == 1 and "Traceback" not in err, err
    assert not out.exists()
    return lines[0]


def _whitworth_ram(phi: np.ndarray, rod: float = 0.5) -> np.ndarray:
    """The ram's x by the geometry: R = Q − QR·(P − Q)/|P − Q|, S on the guide through Q ahead of R."""
    p = 0.2 * np.exp(1j * phi)
    q = -0.1j
    r = q - 0.15 * (p - q) / np.abs(p - q)
    return r.real + np.sqrt(rod ** 2 - (r.imag - q.imag) ** 2)


def test_the_whitworth_ram_moves_as_the_geometry_says():
    motion = analyse(graphplan.load_text(WHITWORTH)).motion
    phi = np.asarray(motion.driver)
    omega = -4.0 * math.pi
    step = 1e-6
    np.testing.assert_allclose(motion.point("S").r[:, 0], _whitworth_ram(phi), atol=1e-12)
    central = (_whitworth_ram(phi + step) - _whitworth_ram(phi - step)) / (2 * step) * omega
    np.testing.assert_allclose(motion.point("S").v[:, 0], central, atol=1e-6)


def test_a_ram_rod_as_long_as_the_levers_tail_is_told_its_whole_dwell(tmp_path, capsys):
    """RS = QR = 0.15 m folds the rod back along the lever's tail and rests the ram at Q while P is right of O
    (x_S = 0.15·(|ux| − ux)), the crank from 90° clockwise round to 270°: half a turn.  The sweep that finds the
    dwell starts at the crank's 0°, inside it, and told only the part after that start (0.25° to 270.25°)."""
    told = _refused(tmp_path, capsys, WHITWORTH.replace("length = 0.5", "length = 0.15"))
    assert told.startswith("graphplan: error: positions.working: link 6 stands still from φ = "), told
    start, end = (float(value) for value in
                  told.split("stands still from φ = ")[1].split(" (")[0].replace("°", "").split(" to φ = "))
    # The samples half a degree apart: the first and last still ones lie within a step inside the dwell.
    assert 89.5 <= start <= 90.0 and 270.0 <= end <= 270.5, told


@pytest.mark.parametrize(("typed", "key"), [
    ("at = 150.0, offset = 120.0", "points.E.at = 150 m"),
    ("at = 0.15, offset = 120.0", "points.E.offset = 120 m"),
])
def test_a_coupler_point_placed_in_millimetres_is_named_where_it_stops_the_rod(tmp_path, capsys, typed, key):
    """E typed in millimetres puts the rod's joint some 190 m off, so F cannot reach the guide at any angle; the
    refusal said 'check the lengths' of a scene whose every link length was right."""
    told = _refused(tmp_path, capsys, SIX_BAR.replace("at = 0.15, offset = 0.12", typed))
    assert "F cannot be assembled" in told and key in told and "driver.length = 0.1 m" in told, told
    assert "millimetres" in told, told


def test_a_guide_put_in_millimetres_is_named_where_it_stops_the_rod(tmp_path, capsys):
    told = _refused(tmp_path, capsys, SIX_BAR.replace("through = [0.0, 0.45]", "through = [0.0, 450.0]"))
    assert "groups[1].guide.through (450 m from O)" in told and "millimetres" in told, told


def test_a_short_coupler_point_is_not_taken_for_a_millimetre_slip(tmp_path, capsys):
    """A joint placed a millimetre from its reference point is no link's length: a rod too short to reach the
    guide is still told to check the lengths or to swing, not asked about millimetres."""
    told = _refused(tmp_path, capsys, SIX_BAR.replace("at = 0.15, offset = 0.12", "at = 0.0005, offset = 0.0")
                    .replace("length = 0.4", "length = 0.1"))
    assert "F cannot be assembled" in told and "millimetres" not in told, told


def test_a_point_at_below_zero_lies_behind_from_and_its_offset_to_the_left():
    """The docs' row for a negative `at`: R 0.15 m behind Q from P, then `offset` to the left of Q→P."""
    text = WHITWORTH.replace('at = -0.15 }', 'at = -0.15 }\nT = { link = 4, from = "Q", toward = "P", at = -0.15, '
                                              'offset = 0.02 }')
    motion = analyse(graphplan.load_text(text)).motion
    p = 0.2 * np.exp(1j * np.asarray(motion.driver))
    along = (p + 0.1j) / np.abs(p + 0.1j)
    expected = -0.1j - 0.15 * along + 0.02 * 1j * along
    found = motion.point("T").r
    np.testing.assert_allclose(found[:, 0] + 1j * found[:, 1], expected, atol=1e-12)


WITH_MASSES = WHITWORTH + """
[points.S5]
link = 5
from = "R"
toward = "S"
at = 0.25
[links.5]
centre = "S5"
inertia = 0.17
[links.6]
mass = 30.0
centre = "S"
[[loads]]
kind = "force"
link = 6
point = "S"
angle = 0.0
value = 2500.0
resisting = true
during = "working"
"""


def test_a_link_given_its_inertia_and_centre_but_not_its_mass_is_warned_of(tmp_path, capsys):
    """No body has J > 0 and m = 0: the rod's mass was forgotten, and its weight and inertia force were left out of
    the force analysis without a word."""
    scene = tmp_path / "scene.toml"
    scene.write_text(WITH_MASSES, encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    said = capsys.readouterr()
    told = [line for line in (said.out + said.err).splitlines() if line.startswith("warning: links.5")]
    assert len(told) == 1 and "no mass" in told[0] and "Fu5" in told[0], told
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "positions"]) == 0
    said = capsys.readouterr()
    assert any(line.startswith("warning: links.5") for line in (said.out + said.err).splitlines())
    # With the mass given, or with the inertia alone (a crank's with its flywheel), nothing is said.
    for meant in (WITH_MASSES.replace('centre = "S5"', 'mass = 8.0\ncentre = "S5"'),
                  WITH_MASSES.replace('centre = "S5"\n', '')):
        scene.write_text(meant, encoding="utf-8")
        assert main(["check", str(scene)]) == 0
        said = capsys.readouterr()
        assert "warning: links.5" not in said.out + said.err


def test_a_lever_point_with_a_misspelt_from_is_told_at_its_own_key(tmp_path, capsys):
    """R's `from` typed "q" for Q left R unplaced, and the refusal blamed the rod's group for joining an unknown R."""
    told = _refused(tmp_path, capsys, WHITWORTH.replace('from = "Q", toward = "P", at = -0.15',
                                                        'from = "q", toward = "P", at = -0.15'))
    assert told.startswith("graphplan: error: points.R.from: 'q' is not a point of link 4"), told
    assert "Q" in told.split("its points are ")[1], told


@pytest.mark.parametrize(("typed", "where", "meant"), [
    ('joints = ["r", "S"]', "groups[1].joints[0]", "R"),
    ('joints = ["P", "q"]', "groups[0].joints[1]", "Q"),
])
def test_a_joint_typed_in_the_other_case_is_told_the_name_meant(tmp_path, capsys, typed, where, meant):
    """A one-letter name is no close match of another to difflib: 'r' for R was told no name to write."""
    original = 'joints = ["R", "S"]' if meant == "R" else 'joints = ["P", "Q"]'
    told = _refused(tmp_path, capsys, WHITWORTH.replace(original, typed))
    assert told.startswith(f"graphplan: error: {where}: ") and told.endswith(f"did you mean {meant!r}?"), told


# The six-bar with masses and a resisting moment on the rocker in its own working stroke (its turning back is not
# the slider's).  The rocker's AB = 0.25, BC = 0.12 make the crank stop short of a turn.
SIX_BAR_LOADED = SIX_BAR.replace('start = 0.0\n', 'start = "extreme"\nworking = { link = 6, sense = "backward" }\n'
                                 'plans = [2]\n') + """
[points.S3]
link = 3
from = "A"
toward = "B"
at = 0.175
[links.3]
mass = 4.0
centre = "S3"
inertia = 0.05
[[loads]]
kind = "moment"
link = 4
value = 40.0
resisting = true
during = "working"
stroke = { link = 4, sense = "ccw" }
"""


def test_a_crank_that_cannot_turn_round_under_a_load_of_the_rockers_stroke_is_advised_a_swing(tmp_path, capsys):
    """The advice tries the swing it names by analysing the scene rocking over it; a load of another link's stroke
    then looked up that stroke's extremes, which a swing has not, and the run ended in a KeyError traceback."""
    stuck = SIX_BAR_LOADED.replace("lengths = [0.35, 0.25]", "lengths = [0.25, 0.12]")
    told = _refused(tmp_path, capsys, stuck)
    assert "B cannot be assembled" in told and "driver.swing = [" in told, told
    # Rocking over the swing advised, as the advice says the scene then runs, the load acts while the rocker
    # turns counter-clockwise, its sense of motion alone deciding, as the working link's does over a swing.
    swing = told.rsplit("driver.swing = [", 1)[1].split("]")[0]
    rocking = stuck.replace("rpm = 150.0", f"rpm = 150.0\nswing = [{swing}]").replace('start = "extreme"\n', "")
    analysis = graphplan.load_text(rocking).analyse()
    omega4 = analysis.motion.link(4).omega
    moment = next(load for load in analysis.loads if load.name == "M4").moment
    assert np.all(np.asarray(omega4) != 0.0)
    np.testing.assert_array_equal(np.abs(moment) == 40.0, np.asarray(omega4) > 0)
    np.testing.assert_array_equal(np.abs(moment) == 0.0, np.asarray(omega4) < 0)


def test_a_change_point_four_bar_started_at_the_extreme_is_told_why_it_stood_at_0_degrees(tmp_path, capsys):
    """C moved to 0.2 m makes AB − BC = OC − OA: at the crank's 0° the coupler and the rocker fold into one line.
    The scene asked for no 0°: start = "extreme" chooses the assemblies there, and the refusal named a toggle at a
    position the student never gave, with nothing to change."""
    folding = SIX_BAR_LOADED.replace("C = [0.3, 0.0]", "C = [0.2, 0.0]")
    told = _refused(tmp_path, capsys, folding)
    assert told.startswith("graphplan: error: singular position at φ = 0° in group II(3,4)"), told
    assert 'positions.start = "extreme"' in told and "leave positions.working out" in told, told
    angle = float(told.rsplit("positions.start = ", 1)[1].rstrip(")"))
    # The angle advised is off the toggle: there, A (on the crank) and B stand off the line O–C.
    assert 0.0 < angle < 360.0 / 6
    advised = (folding.replace('start = "extreme"', f"start = {angle}")
               .replace('working = { link = 6, sense = "backward" }\n', "")
               .replace('during = "working"\nstroke = { link = 4, sense = "ccw" }', 'during = "always"'))
    assert graphplan.load_text(advised).analyse().motion.count == 6


# The Whitworth with what its force analysis needs and one plan position, 3 (the crank at 150°).
WHITWORTH_PLANNED = WITH_MASSES.replace("[links.5]\n", "[links.5]\nmass = 8.0\n").replace(
    "start = 0.0", "start = 210.0\nplans = [3]") + """
[drawing]
velocity_pole = 100.0
acceleration_pole = 100.0
"""


def _far_off_detail(tmp_path, capsys, text: str) -> str:
    """The `measured.3` warning `check` gives of ``text``."""
    scene = tmp_path / "measured.toml"
    scene.write_text(text, encoding="utf-8")
    capsys.readouterr()
    assert main(["check", str(scene)]) == 0
    said = capsys.readouterr()
    told = [line for line in (said.out + said.err).splitlines() if line.startswith("warning: position 3: measured.3")]
    assert len(told) == 1, said
    return told[0]


def test_plan_readings_typed_in_metres_are_told_so_not_a_pole_of_a_tenth_of_a_millimetre(tmp_path, capsys):
    """ps and pr measured in metres (0.049 for 49 mm): the warning advised `velocity_pole = 0.1`, a plan a tenth
    of a millimetre long that the run then calls too small to read."""
    phi = math.radians(150.0)  # position 3: the crank from 210° two steps of 30° clockwise
    step = 1e-6
    ram_speed = abs(_whitworth_ram(np.array([phi + step])) - _whitworth_ram(np.array([phi - step])))[0] / (2 * step)
    scale = 4.0 * math.pi * 0.2 / 100.0  # μV = ω2·lOP / pp′
    ps = ram_speed * 4.0 * math.pi / scale
    detail = _far_off_detail(tmp_path, capsys, WHITWORTH_PLANNED + f"[measured.3]\nvelocity = {{ ps = "
                             f"{ps / 1000:.6f} }}\n")
    assert "typed in metres" in detail and "times 1000" in detail and "velocity_pole" not in detail, detail


def test_force_readings_typed_in_metres_are_told_so_not_taken_for_a_point_on_the_plans(tmp_path, capsys):
    """R12 and R43 in metres (each polygon at its own μF, so no one scale joins them): each reading, a tenth of a
    millimetre or less, was told to be the plans' ps4, 0 mm long (S4 on the fixed pivot Q).  The crank is given a
    weight: without one its polygon, R32 and R12 on one line, would be drawn at group II(3,4)'s μF."""
    text = WHITWORTH_PLANNED.replace('[points.S5]', '[points.S4]\nlink = 4\nfrom = "Q"\ntoward = "P"\nat = 0.0\n'
                                     '[links.4]\nmass = 12.0\ncentre = "S4"\ninertia = 0.15\n'
                                     '[points.S2]\nlink = 2\nfrom = "O"\ntoward = "P"\nat = 0.1\n'
                                     '[links.2]\nmass = 5.0\ncentre = "S2"\n[points.S5]')
    out = tmp_path / "out"
    done = graphplan.load_text(text).write(out, only=["forces"])
    assert done.files
    forces = json.loads((out / "results.json").read_text(encoding="utf-8"))["positions"][2]["forces"]
    lengths = {name: abs(complex(*forces["reactions"][name])) / forces["polygon_scales"][label]
               for name, label in (("R12", "I(1,2)"), ("R43", "II(3,4)"))}
    assert forces["polygon_scales"]["I(1,2)"] != forces["polygon_scales"]["II(3,4)"]
    readings = ", ".join(f"{name} = {length / 1000:.6f}" for name, length in lengths.items())
    detail = _far_off_detail(tmp_path, capsys, text + f"[measured.3]\nforces = {{ {readings} }}\n")
    assert "ps4" not in detail and "typed in metres" in detail and "times 1000" in detail, detail


# A crank, its block sliding in an oscillating lever (RPR, the slide 30 mm to the left of the pivot C), and a rocker
# driven from the lever's end D (RRR): my own dimensions of the textbook kind, lOC = 300, lOA = 100, lCD = 500,
# lDE = 350, lEF = 300 mm, n = 90 rpm.
SLOTTED_LEVER_ROCKER = """
[scene]
title = "Slotted lever driving a rocker"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.0, -0.3], F = [0.45, 0.25] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
rpm = 90.0
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
offset = 0.03
[points]
D = { link = 4, from = "C", toward = "A", at = 0.5 }
[[groups]]
kind = "RRR"
links = [5, 6]
joints = ["D", "E", "F"]
lengths = [0.35, 0.3]
assembly = "right"
[positions]
count = 8
start = 0.0
"""


def _lever_and_rocker(phi: float) -> tuple[float, complex]:
    """The lever's slide direction and E, by the geometry: A = C + s·u + e·(left of u), |DE| = 0.35, |EF| = 0.3,
    E to the right of D→F."""
    a, c, f = 0.1 * np.exp(1j * phi), -0.3j, 0.45 + 0.25j
    theta = np.angle(a - c) - math.asin(0.03 / abs(a - c))
    d = c + 0.5 * np.exp(1j * theta)
    apart = abs(f - d)
    along = (0.35 ** 2 - 0.3 ** 2 + apart ** 2) / (2 * apart)
    across = math.sqrt(0.35 ** 2 - along ** 2)
    return theta, d + (f - d) / apart * (along - 1j * across)


def test_an_offset_slotted_lever_driving_a_rocker_moves_as_the_geometry_says():
    """The lever's point D is placed toward the block: from C in the slide line's direction, not along C–A."""
    motion = analyse(graphplan.load_text(SLOTTED_LEVER_ROCKER)).motion
    omega, step = 3.0 * math.pi, 1e-6
    for index, phi in enumerate(np.asarray(motion.driver)):
        theta, e = _lever_and_rocker(phi)
        (ahead, e_ahead), (behind, e_behind) = _lever_and_rocker(phi + step), _lever_and_rocker(phi - step)
        assert abs(np.angle(np.exp(1j * (motion.link(4).angle[index] - theta)))) < 1e-9
        assert motion.link(4).omega[index] == pytest.approx((ahead - behind) / (2 * step) * omega, abs=1e-6)
        found = motion.point("E")
        assert complex(*found.r[index]) == pytest.approx(e, abs=1e-12)
        assert complex(*found.v[index]) == pytest.approx((e_ahead - e_behind) / (2 * step) * omega, abs=1e-6)
