"""Parts of a mechanism standing on one another: a twin's second cylinder given the first one's guide and rod solved
without a word, its joints on the first's at every position and every sheet drawing the two as one; two pistons on
one cylinder line whose pins are half a turn apart pass through each other, which the run did not tell either."""

from __future__ import annotations

import json
import re

import pytest
from scene_texts import central_slider_crank, second_cylinder

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.scene import loads

# Scenes given their slips on purpose: scene.analyse() warns of each with a UserWarning, as the command line does,
# and these tests read the analysis's warnings themselves.
pytestmark = pytest.mark.filterwarnings(r"ignore:[a-z]+(-[a-z]+)+\b:UserWarning")

RADIUS, ROD = 0.05, 0.19


def _second_piston(pin: str, assembly: str = "forward", angle: float = 0.0, rod: float = ROD) -> str:
    """The central slider-crank with a second rod (link 5) from ``pin`` (A, or D half a turn from it) to a second
    piston C (link 6) on a guide through O at ``angle``."""
    return central_slider_crank(RADIUS, ROD, 10.0) + second_cylinder(RADIUS, rod, pin == "D", angle, assembly, "D")


def _codes(text: str) -> list[str]:
    return [warning.code for warning in loads(text).analyse().warnings]


def test_a_group_given_twice_is_told_once_naming_both_joints_and_groups():
    (warning,) = [w for w in loads(_second_piston("A")).analyse().warnings if w.code == "joints-coincide"]
    assert warning.position == 0
    assert re.match(r"joints B and C \(groups II\(3,4\) and II\(5,6\)\) stand at one place at every position", warning.detail)
    assert "blocks-pass-through" not in _codes(_second_piston("A"))


@pytest.mark.parametrize("changed", [{"angle": 90.0}, {"assembly": "backward"}, {"rod": 0.2}],
                         ids=["V-twin", "boxer", "longer rod"])
def test_a_second_piston_of_its_own_is_not_told(changed):
    """At its own angle, on the other side of the pin, or on a longer rod (always 10 mm farther out than the first,
    both on one pin), the second piston stands nowhere the first does."""
    codes = _codes(_second_piston("A", **changed))
    assert "joints-coincide" not in codes and "blocks-pass-through" not in codes


def test_two_pistons_on_one_line_whose_pins_are_half_a_turn_apart_are_told_where_they_meet(tmp_path, capsys):
    """Pins A and D opposite on the crank, equal rods, both pistons on the +x side of their pins: xB − xC = 2r·cos φ,
    which changes sign where the pins are level with O, at φ = 90° first over the turn from φ = 0."""
    text = _second_piston("D")
    (warning,) = [w for w in loads(text).analyse().warnings if w.code == "blocks-pass-through"]
    assert warning.detail.startswith("the blocks at B (link 4) and C (link 6) slide on one line of the frame and pass "
                                     "through each other (φ = 90°)")
    assert "joints-coincide" not in _codes(text)
    # Told about the scene as a whole: by check, and in results.json at the first position.
    scene = tmp_path / "cross.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    assert "warning: the blocks at B (link 4) and C (link 6)" in capsys.readouterr().out
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "note", "--sheet", "none"]) == 0
    told = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["warnings"]
    assert [w["code"] for w in told if w["code"] == "blocks-pass-through"] == ["blocks-pass-through"]
    # The note handed in says so under its initial data: the console's line is gone by then.
    assert strings("en")["note_warning_blocks_pass_through"] in (tmp_path / "out" / "note.md").read_text("utf-8")


def test_a_slider_on_another_line_of_the_same_direction_is_not_told():
    """A guide parallel to the first but 0.1 m above it: the blocks' places along x cross, but on two lines."""
    text = _second_piston("D").replace('joints = ["D", "C"]\nlength = 0.19\nguide = { through = "O", angle = 0.0 }',
                                       'joints = ["D", "C"]\nlength = 0.19\nguide = { through = [0.0, 0.1], angle = 0.0 }')
    assert "through = [0.0, 0.1]" in text
    assert "blocks-pass-through" not in _codes(text)
