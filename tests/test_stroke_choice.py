"""Which reversals of the working link are its extremes, when it turns back more than twice a turn or passes
a singular position; and what the run says about it."""

from __future__ import annotations

import json
import math
import re
import warnings

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.motion import solve
from graphplan.positions import working_speed

# A jaw crusher's six-bar (a teacher's scene): the jaw 6 swings twice while the eccentric shaft turns once,
# C, D and E coming into line at both of its inner extremes.
CRUSHER = """
[scene]
title = "Jaw crusher"
locale = "en"

[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.5, 0.4], F = [-0.50, 1.20] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.09
rpm = 250.0

[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.55, 0.35]
assembly = "left"

[[groups]]
kind = "RRR"
links = [5, 6]
joints = ["D", "E", "F"]
lengths = [0.45, 0.60]
assembly = "left"

[points]
D = { link = 4, from = "C", toward = "B", at = 0.55, offset = 0.03 }

[positions]
count = 12
start = START
working = { link = 6, sense = "ccw" }
"""


def crusher(tmp_path, start):
    path = tmp_path / f"crusher_{start}.toml".replace('"', "")
    path.write_text(CRUSHER.replace("START", start), encoding="utf-8")
    return path


def test_a_link_that_swings_twice_a_turn_has_the_same_strokes_wherever_the_positions_start(tmp_path):
    found = []
    for start in ('"extreme"', "0.0", "300.0", "100.0"):
        positions = analyse(graphplan.load(crusher(tmp_path, start))).positions
        found.append((sorted(math.degrees(value) % 360.0 for value in positions.extremes),
                      positions.stroke_turns(1)))
    for extremes, turns in found[1:]:
        assert extremes == pytest.approx(found[0][0], abs=1e-9)
        assert turns == pytest.approx(found[0][1], abs=1e-9)


def test_its_working_stroke_is_the_longest_it_makes_in_its_working_sense(tmp_path):
    analysis = analyse(graphplan.load(crusher(tmp_path, '"extreme"')))
    # Independently: ω6 on a grid of 0.01° round the turn, the runs of the working sense between its zeros.
    grid = np.radians(np.arange(0.0, 360.0, 0.01))
    speed, _ = working_speed(solve(analysis.mechanism, grid, analysis.positions.reference))
    rising = np.flatnonzero((speed <= 0) & (np.roll(speed, -1) > 0))
    falling = np.flatnonzero((speed >= 0) & (np.roll(speed, -1) < 0))
    assert len(rising) == len(falling) == 2  # it turns back four times
    runs = [((falling[falling > r][0] if np.any(falling > r) else falling[0] + len(grid)) - r, r) for r in rising]
    length, begins = max(runs)
    start, end = analysis.positions.extremes
    assert math.degrees(start) % 360.0 == pytest.approx(math.degrees(grid[begins]), abs=0.02)
    assert math.degrees(end) % 360.0 == pytest.approx((begins + length) * 0.01 % 360.0, abs=0.02)
    assert math.degrees(analysis.positions.stroke_turns(1)[0]) == pytest.approx(length * 0.01, abs=0.02)


def test_the_run_warns_that_the_extremes_are_a_choice(tmp_path):
    out = tmp_path / "out"
    assert main(["run", str(crusher(tmp_path, '"extreme"')), "--out", str(out), "--only", "positions"]) == 0
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))
    (warning,) = [w for w in document["warnings"] if w["code"] == "extra-reversals"]
    assert "link 6 turns back 4 times a turn of link 2" in warning["detail"]
    start, end = document["extremes_deg"]
    assert f"from {start:.2f}° to {end:.2f}°" in warning["detail"]


def test_a_link_that_turns_back_twice_has_no_such_warning():
    analysis = analyse(graphplan.load("fixtures/stephenson_six_bar.toml"))
    assert len(analysis.positions.reversals) == 2
    assert not [w for w in analysis.warnings if w.code == "extra-reversals"]


# A sine mechanism driving a rocker through a link (a teacher's scene) whose links 5 and 6 come into line at
# position 7 (φ = 345°): there ω6 is not determined. P is placed from B toward A, which is on the slot's negative side
# at φ = 0°: its offset is to the right of B→A.
TOGGLE = """
[scene]
title = "Sine mechanism with a rocker"
locale = "en"

[frame]
link = 1
points = { O = [0.0, 0.0], G = [-0.30, 0.32] }
lines = { slide = { through = "O", angle = 10.0 } }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.06
omega = 15.0

[[groups]]
kind = "RPP"
links = [3, 4]
joints = ["A", "B"]
guide = "slide"
angle = 65.0

[[groups]]
kind = "RRR"
links = [5, 6]
joints = ["P", "E", "G"]
lengths = [0.15, 0.123392747509]
assembly = "right"

[points]
P = { link = 4, from = "B", toward = "A", at = 0.0, offset = -0.25 }
S6 = { link = 6, from = "G", toward = "E", at = 0.07 }

[links.6]
mass = 1.5
centre = "S6"
inertia = 0.005

[[loads]]
kind = "moment"
link = 6
value = 60.0
resisting = true
during = "working"

[positions]
count = 12
start = "extreme"
working = { link = 6, sense = "ccw" }
plans = [2, 8]
"""


@pytest.fixture
def toggle(tmp_path):
    path = tmp_path / "toggle.toml"
    path.write_text(TOGGLE, encoding="utf-8")
    return path


def test_a_singular_position_leaves_the_other_positions_strokes_to_their_sense_of_motion(toggle):
    analysis = analyse(graphplan.load(toggle))
    singular = set(analysis.motion.singular)
    assert singular == {6}
    omega = analysis.motion.links[6].omega
    for index, stroke in enumerate(analysis.positions.strokes):
        if index not in singular and abs(omega[index]) > 1e-9:
            assert stroke == ("working" if omega[index] > 0 else "idle"), index


def test_a_run_past_a_singular_position_prints_its_warning_once_and_no_arithmetic_noise(toggle, tmp_path, capsys):
    # Every piece the scene has data for but the kinematic diagrams, which the chord method draws through every
    # position: left out, with the reason.
    assert main(["check", str(toggle)]) == 0
    assert "left out: diagrams (needs every position regular: position 7 is singular)" in capsys.readouterr().out
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        assert main(["run", str(toggle), "--out", str(tmp_path / "out")]) == 0
    printed = capsys.readouterr()
    (line,) = [line for line in printed.out.splitlines() + printed.err.splitlines() if "singular position" in line]
    assert line.startswith("warning: position 7: singular position at φ = 345° in group II(5,6): ")
    assert line.count("position 7") == 1


SLOTTED_BY_A_SLIDER = """
[frame]
points = { G = [0.0, 0.0], C = [0.05, 0.2] }
[driver]
kind = "slider"
link = 2
joint = "A"
guide = { through = "G", angle = 0.0 }
travel = [-0.1, 0.12]
velocity = 0.5
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
offset = 0.03
[points]
D = { link = 4, from = "C", toward = "A", at = -0.15 }
[links.4]
mass = 4.0
centre = "C"
[[loads]]
kind = "force"
link = 4
point = "D"
value = 200.0
angle = 90.0
resisting = true
during = "working"
[positions]
count = 8
working = { link = 4, sense = "SENSE" }
plans = [2]
"""


def test_a_working_sense_the_travel_never_gives_is_warned_of_with_the_load_it_drops():
    """The slider pushes the slotted link 4 counter-clockwise over its whole travel: with working sense cw every
    position was idle and the 200 N load of the working stroke silently never applied."""
    from graphplan.scene import loads as scene_from_text

    analysis = analyse(scene_from_text(SLOTTED_BY_A_SLIDER.replace("SENSE", "cw")))
    omega4 = analysis.motion.link(4).omega
    assert np.all(np.asarray(omega4) > 0) and set(analysis.positions.strokes) == {"idle"}
    (warning,) = [w for w in analysis.warnings if w.code == "idle-throughout"]
    assert warning.detail == ("positions.working: link 4 never moves cw over driver.travel, so every position is in "
                              "the idle stroke; loads[0] of the working stroke is never applied; it moves ccw: is "
                              "that its working sense?")
    assert all(np.all(load.force == 0) for load in analysis.loads if load.name.startswith("F4"))
    right = analyse(scene_from_text(SLOTTED_BY_A_SLIDER.replace("SENSE", "ccw")))
    assert set(right.positions.strokes) == {"working"} and not [w for w in right.warnings if w.code == "idle-throughout"]


def test_a_load_of_the_idle_stroke_a_travel_never_reaches_is_warned_of():
    """The mirror case: the working sense is the one the travel gives throughout, and a load is given to the idle
    stroke, which the run never reaches (its link turns ccw at every position): the load was silently dropped."""
    from graphplan.scene import loads as scene_from_text

    idle_load = SLOTTED_BY_A_SLIDER.replace("SENSE", "ccw").replace('during = "working"', 'during = "idle"')
    analysis = analyse(scene_from_text(idle_load))
    assert np.all(np.asarray(analysis.motion.link(4).omega) > 0)
    assert all(np.all(load.force == 0) for load in analysis.loads if load.name.startswith("F4"))
    (warning,) = [w for w in analysis.warnings if w.code == "working-throughout"]
    assert warning.detail == ("positions.working: link 4 moves ccw over the whole driver.travel, so every position "
                              "is in the working stroke; loads[0] of the idle stroke is never applied: is that the "
                              "stroke it acts in?")
    # A travel all in the working stroke with its loads in it is the usual case: nothing to tell.
    usual = analyse(scene_from_text(SLOTTED_BY_A_SLIDER.replace("SENSE", "ccw")))
    assert not [w for w in usual.warnings if w.code.endswith("-throughout")]


def test_a_load_with_its_own_stroke_is_not_named_among_those_the_working_link_drops():
    """A load given its own stroke (here link 4's other sense) acts by that link's motion, not by the working
    link's: the idle-throughout warning named it among the loads never applied although it acts everywhere."""
    from graphplan.scene import loads as scene_from_text

    own = SLOTTED_BY_A_SLIDER.replace("SENSE", "cw").replace(
        'during = "working"', 'during = "working"\nstroke = { link = 4, sense = "ccw" }')
    analysis = analyse(scene_from_text(own))
    (warning,) = [w for w in analysis.warnings if w.code == "idle-throughout"]
    assert "never applied" not in warning.detail
    assert all(np.all(load.force != 0) for load in analysis.loads if load.name.startswith("F4"))


# The tester's scene: a crank-rocker whose ternary rocker CBD drives a slotted lever 6 about F through a block at D.
TERNARY_ROCKER = """
[scene]
title = "Crank-rocker with a ternary rocker driving a slotted lever"

[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.3, 0.05], F = [0.45, 0.3] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.08
omega = 10.0

[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.28, 0.2]
assembly = "left"

[[groups]]
kind = "RPR"
links = [5, 6]
joints = ["D", "F"]

[points]
D = { link = 4, from = "C", toward = "B", at = 0.15, offset = -0.07 }

[positions]
count = 12
start = "extreme"
working = { link = 6, sense = "ccw" }
"""


def test_the_warning_gives_each_turn_back_as_precisely_as_the_extremes():
    """It printed 'at about 43.0, 169.0, 230.0, 292.0°' in the sentence that gives the extremes as 292.24° and
    43.20°: the middles of the sweep's half-degree brackets, rounded.  Each is now the root of the lever's speed,
    checked here against the roots of dθ6/dφ of the linkage closed afresh: the circles about A and C crossed at B,
    D set off CB, θ6 the direction FD."""
    from scipy.optimize import brentq

    analysis = analyse(graphplan.scene.loads(TERNARY_ROCKER))
    o, c, f = 0j, 0.3 + 0.05j, 0.45 + 0.3j
    first_b = complex(np.ravel(analysis.motion.points["B"].r)[0])
    first_angle = float(analysis.positions.values[0])

    def b_of(phi: float, side: float) -> complex:
        a = o + 0.08 * np.exp(1j * phi)
        ac = c - a
        along = (0.28**2 - 0.2**2 + abs(ac) ** 2) / (2 * abs(ac))
        return a + ac / abs(ac) * complex(along, side * math.sqrt(0.28**2 - along**2))

    # The assembly the scene chose, told by where B stands at the first position.
    side = min((1.0, -1.0), key=lambda s: abs(b_of(first_angle, s) - first_b))

    def theta6(phi: float) -> float:
        b = b_of(phi, side)
        along = (b - c) / abs(b - c)
        return float(np.angle(c + (0.15 - 0.07j) * along - f))

    def rate(phi: float, h: float = 1e-6) -> float:
        return (theta6(phi + h) - theta6(phi - h)) / (2 * h)

    grid = np.radians(np.arange(0.0, 361.0, 1.0))
    rates = np.array([rate(phi) for phi in grid])
    roots = sorted(math.degrees(brentq(rate, grid[i], grid[i + 1], xtol=1e-13)) % 360.0
                   for i in np.flatnonzero(np.sign(rates[:-1]) != np.sign(rates[1:])))
    assert len(roots) == 4
    (warning,) = [w for w in analysis.warnings if w.code == "extra-reversals"]
    printed = re.search(r"turns back 4 times a turn of link 2 \(at ([\d., ]+)°\)", warning.detail)[1].split(", ")
    assert printed == [f"{root:.2f}" for root in roots]
    found = sorted(math.degrees(value) % 360.0 for value in analysis.positions.reversals)
    assert found == pytest.approx(roots, abs=1e-6)
