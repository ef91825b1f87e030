"""A working sense typed the wrong way round: a quick-return mechanism's slotted lever given its quick stroke as the
working one puts the cutting load on the return.  The run goes on as given, and asks, naming K both ways; a
crank-rocker near K = 1 either way, a load that acts always, and every bundled scene are not asked about."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.scene import loads
from graphplan.starters import starter

# Scenes given their slips on purpose: scene.analyse() warns of each with a UserWarning, as the command line does,
# and these tests read the analysis's warnings themselves.
pytestmark = pytest.mark.filterwarnings(r"ignore:[a-z]+(-[a-z]+)+\b:UserWarning")

SLOW_STROKE = 'working     = { link = 4, sense = "ccw" }'
QUICK_STROKE = 'working     = { link = 4, sense = "cw" }'


def _slotted_lever(working: str, locale: str = "en") -> str:
    text = starter("slotted-lever", locale)
    assert SLOW_STROKE in text
    return text.replace(SLOW_STROKE, working)


def _quicker(text: str) -> list:
    analysis = loads(text).analyse()
    return [warning for warning in analysis.warnings if warning.code == "working-stroke-quicker"]


def test_the_quick_stroke_given_as_the_working_one_is_asked_about_with_k_both_ways() -> None:
    slow = loads(_slotted_lever(SLOW_STROKE)).analyse().positions
    working, idle = slow.stroke_turns(loads(_slotted_lever(SLOW_STROKE)).solve().mechanism.driver.sense)
    k = working / idle  # the starter's own time ratio, its slow stroke working
    assert k > 1.25
    (warning,) = _quicker(_slotted_lever(QUICK_STROKE))
    assert warning.position == 0
    assert f"K = φw/φi = {math.degrees(idle):.2f}°/{math.degrees(working):.2f}° = {1 / k:.4f}" in warning.detail
    assert f'which sense = "ccw" makes the working one (K = {k:.4f})' in warning.detail
    assert "loads[0] resists it" in warning.detail
    assert not _quicker(_slotted_lever(SLOW_STROKE))


def test_a_load_that_acts_always_is_no_sign_of_the_sense(tmp_path: Path) -> None:
    text = _slotted_lever(QUICK_STROKE).replace("during    = { from = 0.05, to = 0.95 }", 'during    = "always"')
    assert 'during    = "always"' in text
    assert not _quicker(text)


def test_the_run_writes_the_question_into_its_results_and_its_note(tmp_path: Path, capsys) -> None:
    scene = tmp_path / "scene.toml"
    scene.write_text(_slotted_lever(QUICK_STROKE, "ru"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "positions,note"]) == 0
    assert "warning: positions.working: link 4's working stroke (cw) is the quicker one" in capsys.readouterr().out
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    asked = [warning["position"] for warning in results["warnings"] if warning["code"] == "working-stroke-quicker"]
    assert asked == [results["positions"][0]["index"]]
    assert "рабочий ход выходного звена 4 — более быстрый (K < 1)" in (out / "note.md").read_text(encoding="utf-8")


BUNDLED = [*sorted(Path("fixtures").glob("*.toml")), *sorted(Path("tests/scenes").glob("*.toml"))]


@pytest.mark.parametrize("scene", BUNDLED, ids=lambda path: path.stem)
def test_no_bundled_scene_is_asked_about_its_working_sense_nor_told_of_a_block_by_its_pivot(scene: Path) -> None:
    warnings = loads(scene.read_text(encoding="utf-8")).analyse().warnings
    assert not [warning for warning in warnings if warning.code in ("working-stroke-quicker", "block-near-pivot")]
