"""A slotted link is as long as its slot: a Whitworth quick-return's lever carries its pivot C and the pin D that
drives the ram, 0.1 m apart, and a slot on the other side of C along which the crank pin A runs out to 0.22 m.  The
checks that weigh a link's mass against a steel bar of its length (masses typed in grams) measured it by C and D
alone and told a student that an ordinary 8 kg lever had its mass in grams.

The same lever driven by a crank nearly as long as its pivots are apart passes its block by its pivot, where it whips
round many times as fast as the crank: no position was told ill-conditioned (its plans' lines cross square)."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.scene import loads

# Scenes given their slips on purpose: scene.analyse() warns of each with a UserWarning, as the command line does,
# and these tests read the analysis's warnings themselves.
pytestmark = pytest.mark.filterwarnings(r"ignore:[a-z]+(-[a-z]+)+\b:UserWarning")

WHITWORTH = """
[scene]
title = "Whitworth quick-return mechanism"

[frame]
link = 1
points = { C = [0.0, 0.0], O = [0.0, 0.08] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.14
omega = 10.0

[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
offset = 0.0

[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["D", "E"]
length = 0.30
guide = { through = [0.0, -0.05], angle = 0.0 }
assembly = "forward"

[points]
S2 = { link = 2, from = "O", toward = "A", at = 0.07 }
D = { link = 4, from = "C", toward = "A", at = -0.10 }
S5 = { link = 5, from = "D", toward = "E", at = 0.15 }

[links.2]
mass = 4.0
centre = "S2"
inertia = 0.01
[links.3]
mass = 1.0
centre = "A"
[links.4]
mass = LEVER_MASS
centre = "C"
inertia = 0.12
[links.5]
mass = 3.0
centre = "S5"
inertia = 0.03
[links.6]
mass = 20.0
centre = "E"

[positions]
count = 12
start = 0.0
"""


def _scene(lever_mass: float) -> str:
    return WHITWORTH.replace("LEVER_MASS", repr(lever_mass))


def test_a_slotted_lever_spans_from_its_far_pin_to_where_the_block_runs_out_along_its_slot() -> None:
    motion = loads(_scene(8.0)).solve()
    a, c = motion.point("A").r, motion.point("C").r
    # D stands 0.1 m from C on the far side of the slot, on one line with it (offset 0): the lever reaches from D
    # to the farthest A gets from C.
    farthest = float(np.max(np.hypot(*(a - c).T)))
    length, between = motion.span(4)
    assert math.isclose(length, 0.10 + farthest, rel_tol=1e-12)
    # Independently: the twelve positions from φ = 0 include φ = 90°, where A stands straight above O, the crank's
    # 0.14 m and the pivots' 0.08 m in line, so the slot reaches 0.22 m from C and the lever 0.32 m from D.
    assert math.isclose(farthest, 0.14 + 0.08, rel_tol=1e-12) and math.isclose(length, 0.32, rel_tol=1e-12)
    assert between.startswith("D–A at ") and between.endswith(" end of its guide")
    # Its joints alone, as the check of lengths typed in millimetres compares them with the lengths given.
    joints, named = motion.span(4, slots=False)
    assert math.isclose(joints, 0.10, rel_tol=1e-12) and named == "C–D"


def test_an_ordinary_whitworth_lever_is_not_told_its_mass_is_in_grams(tmp_path: Path, capsys) -> None:
    scene = tmp_path / "whitworth.toml"
    scene.write_text(_scene(8.0), encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    told = capsys.readouterr()
    assert "masses-in-grams" not in told.out + told.err and "grams typed for kg" not in told.out + told.err


def test_the_same_lever_in_grams_is_still_told_with_the_length_its_slot_gives_it(tmp_path: Path, capsys) -> None:
    scene = tmp_path / "whitworth.toml"
    scene.write_text(_scene(8000.0), encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    told = capsys.readouterr().out
    assert "links.4.mass = 8000 kg on a link 0.3" in told
    assert "(D–A at " in told and "8000 g is links.4.mass = 8" in told


def _crank(length: float) -> str:
    return _scene(8.0).replace("length = 0.14\n", f"length = {length!r}\n", 1)


def test_a_crank_a_millimetre_short_of_the_pivots_distance_is_told_the_lever_whips_round() -> None:
    d, r, omega = 0.08, 0.079, 10.0  # O above C, the crank, its speed (rad/s)
    (warning,) = [w for w in loads(_crank(r)).analyse().warnings if w.code == "block-near-pivot"]
    found = re.search(r"A passes ([\d.]+) mm from the pivot C of link 4 \(φ = ([\d.]+)°\).* turns there at "
                      r"([\d.]+) rad/s, ([\d.]+) times as fast as the crank", warning.detail)
    assert found, warning.detail
    distance, phi, turning, times = (float(value) for value in found.groups())
    # A = O + r·(cos φ, sin φ) from C: |CA|² = r² + d² + 2·r·d·sin φ, and the lever's angle atan2(d + r·sin φ,
    # r·cos φ) turns (r² + r·d·sin φ)/|CA|² times as fast as the crank; nearest d − r = 1 mm at φ = 270°.
    sine = math.sin(math.radians(phi))
    ca2 = r * r + d * d + 2 * r * d * sine
    assert math.isclose(distance / 1000, math.sqrt(ca2), rel_tol=2e-3)
    assert d - r - 1e-12 <= math.sqrt(ca2) <= 1.25 * (d - r)  # the sweep's sample nearest the pivot, a degree apart
    assert math.isclose(times, abs(r * r + r * d * sine) / ca2, rel_tol=2e-3)
    assert math.isclose(turning, times * omega, rel_tol=2e-3)


def test_a_crank_well_short_of_the_pivots_distance_is_not_told() -> None:
    assert not [w for w in loads(_crank(0.07)).analyse().warnings if w.code == "block-near-pivot"]
    assert not [w for w in loads(_scene(8.0)).analyse().warnings if w.code == "block-near-pivot"]


def test_the_note_hands_in_the_caution_under_its_initial_data(tmp_path: Path, capsys) -> None:
    scene = tmp_path / "whitworth.toml"
    scene.write_text(_crank(0.0775), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "positions,note"]) == 0
    assert "warning: group II(3,4): A passes 2.5 mm from the pivot C of link 4" in capsys.readouterr().out
    assert "the block of a slotted lever passes close to the lever's pivot" in (out / "note.md").read_text("utf-8")
