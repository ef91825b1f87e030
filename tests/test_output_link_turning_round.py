"""An output link that turns round: its kinematic diagrams, and what it cannot give (extremes, strokes, K).

The mechanism is an inverted slider-crank whose slider 4 runs on a guide of
the crank 2 and whose link 3 turns right round about C.  Its link 3 is solved
here afresh by loop closure: B on the crank's guide through A at 30° to OA,
|CB| = 0.35, ahead of the foot of C on the guide; the diagrams' ordinates are
checked against that angle, unwrapped, and its finite differences.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.kinematic_diagrams import closed_chord_derivative, kinematic_diagrams
from graphplan.mechanism import build
from graphplan.positions import make_positions
from graphplan.report.note import note_markdown
from graphplan.scene import loads

O, C = np.array([0.0, 0.0]), np.array([0.2, 0.05])
CRANK, ROD, GUIDE_DEG, OMEGA = 0.1, 0.35, 30.0, 10.0

SCENE = f"""
[scene]
title = "Inverted slider-crank, its link 3 turning round"
locale = "en"

[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [0.2, 0.05] }}

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {CRANK}
omega = {OMEGA}
epsilon = 5.0

[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["C", "B"]
length = {ROD}
guide = {{ link = 2, through = "A", angle = {GUIDE_DEG} }}
assembly = "forward"

[positions]
count = COUNT
start = START
working = {{ link = 3, sense = "SENSE" }}
"""

LOAD = '\n[[loads]]\nkind = "moment"\nlink = 3\nvalue = 10.0\nresisting = true\n'


def scene_text(start: str = "0.0", sense: str = "ccw", count: int = 12, extra: str = "") -> str:
    return SCENE.replace("COUNT", str(count)).replace("START", start).replace("SENSE", sense) + extra


def psi3(phi: np.ndarray) -> np.ndarray:
    """Link 3's angle C→B at crank angles ``phi``, unwrapped along ``phi``: B = A + t·g on the guide, |B − C| = l."""
    a = CRANK * np.stack((np.cos(phi), np.sin(phi)), axis=-1)
    g = np.stack((np.cos(phi + math.radians(GUIDE_DEG)), np.sin(phi + math.radians(GUIDE_DEG))), axis=-1)
    d = a - C
    along = np.sum(d * g, axis=-1)
    t = -along + np.sqrt(along**2 - np.sum(d * d, axis=-1) + ROD**2)  # ahead of C's foot along the guide
    b = a + t[:, None] * g
    return np.unwrap(np.arctan2(b[:, 1] - C[1], b[:, 0] - C[0]))


@pytest.mark.parametrize("start_deg", [0.0, 100.0])
def test_the_diagrams_of_a_link_that_turns_round_follow_its_loop_closure(start_deg):
    mechanism = build(loads(scene_text(start=str(start_deg))))
    positions = make_positions(mechanism)
    found = kinematic_diagrams(mechanism, positions)
    start, step = math.radians(start_deg), 2.0 * math.pi / 12
    dt = step / OMEGA
    # The displacement: the angle turned from the first position, unwrapped, a whole turn over the crank's.
    nodes = start + step * np.arange(13)
    turned = psi3(nodes) - psi3(nodes)[0]
    assert turned[-1] == pytest.approx(2.0 * math.pi, abs=1e-12)
    assert found.s_nodes == pytest.approx(turned, abs=1e-12)
    assert np.all(np.diff(found.s_nodes) > 0)
    dense = start + found.along
    assert found.s == pytest.approx(psi3(dense) - psi3(dense)[0], abs=1e-12)
    # The chord method as for a rocker: chords of ψ, then chords of those round the closed cycle.
    chords = np.diff(turned) / dt
    assert found.v_chord == pytest.approx(chords, rel=1e-10)
    assert found.a_chord == pytest.approx(closed_chord_derivative(chords, dt), rel=1e-8, abs=1e-9)
    # The analytic curves: central differences of the closure, h = 1e-5 rad of the crank (error ~ h²).
    h = 1e-5
    omega = (psi3(dense + h) - psi3(dense - h)) / (2 * h) * OMEGA
    epsilon = (psi3(dense + h) - 2 * psi3(dense) + psi3(dense - h)) / h**2 * OMEGA**2
    assert found.v == pytest.approx(omega, abs=1e-7 * found.v_peak)
    assert found.a == pytest.approx(epsilon, abs=1e-4 * found.a_peak)
    # No strokes to mark: no extremes, no end of a working stroke.
    assert positions.extremes is None and positions.strokes is None and found.stroke_end is None
    assert positions.working_link_turns == 1


def test_a_link_that_turns_against_its_working_sense_counts_its_turn_negative():
    mechanism = build(loads(scene_text(sense="cw")))
    positions = make_positions(mechanism)
    found = kinematic_diagrams(mechanism, positions)
    nodes = 2.0 * math.pi / 12 * np.arange(13)
    assert positions.working_link_turns == -1
    assert found.s_nodes == pytest.approx(-(psi3(nodes) - psi3(nodes)[0]), abs=1e-12)


TOLD = "link 3 turns round and never reverses its motion, so it has no extreme position"
START_TOLD = "start the positions at a crank angle in degrees (got 'extreme')"
STROKES_TOLD = f"needs the strokes of the output link, but {TOLD} for one to begin at"


@pytest.mark.parametrize(("start", "extra", "where", "problem"), [
    ('"extreme"', "", "positions.start",
     f"\"extreme\" needs the extreme positions of the output link, but {TOLD}: {START_TOLD}"),
    ("0.0", LOAD + 'during = "working"\n', "loads[0].during",
     f"a load of the working stroke {STROKES_TOLD}: use always (got 'working')"),
    ("0.0", LOAD + 'during = "idle"\n', "loads[0].during",
     f"a load of the idle stroke {STROKES_TOLD}: use always (got 'idle')"),
    ("0.0", LOAD + "during = { from = 0.2, to = 0.6 }\n", "loads[0].during",
     f"a window of the working stroke {STROKES_TOLD}: use always (got {{ from = 0.2, to = 0.6 }})"),
    ("0.0", '\n[[loads]]\nkind = "moment"\nlink = 3\nresisting = true\ndiagram = [[0.0, 5.0], [1.0, 10.0]]\n',
     "loads[0].diagram", f"a load diagram over the working stroke {STROKES_TOLD}: make the load a value that acts always"),
])
def test_what_needs_extremes_is_refused_with_the_key_that_asks_for_them(start, extra, where, problem):
    with pytest.raises(SceneError) as caught:
        analyse(loads(scene_text(start=start, extra=extra)))
    assert caught.value.where == where
    assert str(caught.value) == f"{where}: {problem}"


def test_a_load_that_always_acts_on_a_link_that_turns_round_is_balanced_by_the_power_it_takes():
    analysis = analyse(loads(scene_text(extra=LOAD + 'during = "always"\n')))
    assert analysis.positions.working_link_turns == 1
    # Massless links: Mb·ω2 balances the power 10 N·m·|ω3| the resisting moment takes.
    phi, h = analysis.positions.values, 1e-6
    omega3 = (psi3(phi + h) - psi3(phi - h)) / (2 * h) * OMEGA
    assert np.abs(analysis.equilibrium.balancing) == pytest.approx(10.0 * np.abs(omega3) / OMEGA, rel=1e-7)


def test_check_and_the_note_say_the_link_turns_round_and_has_no_k(tmp_path, capsys):
    path = tmp_path / "turning.toml"
    path.write_text(scene_text(), encoding="utf-8")
    assert main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert ("strokes: none: link 3 turns round once a turn of the crank (ccw) and never turns back, so it has no "
            "extreme positions and no K") in out.splitlines()
    assert "diagrams" in re.search(r"run writes: (.*)", out)[1]
    path.write_text(scene_text(sense="cw"), encoding="utf-8")
    assert main(["check", str(path)]) == 0
    assert "(ccw, against positions.working's cw)" in capsys.readouterr().out
    note = note_markdown(analyse(loads(scene_text())))
    assert ("The output link 3 turns round, 1 turn to a turn of the crank, and never turns back: it has no extreme "
            "positions, and so no working and idle strokes and no time ratio K.") in note
    assert "φw" not in note and "K = " not in note
