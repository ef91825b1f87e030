"""The dynamics drawing counts its abscissa from the position where the model's run starts.

A swing or a travel is run once, the way the driver moves: a lever lowered (ω < 0 over `swing = [20, 65]`) or a
rod drawn in (v < 0 over `travel = [0, 0.2]`) starts at the far end, the last position. The drawing read
"φ, ° from position 1" there, so that the plans' rings at 0° stood for position 1 where they were the last
position's; a slider's abscissa, its travel from the first sample, read "s, m" as if it were the displacement the
note's table gives. Which position the run starts at is found here from results.json alone: the position whose
driver coordinate is the dynamics' first sample.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
SWING = ROOT / "fixtures" / "double_rocker_swing.toml"
SLIDER = ROOT / "fixtures" / "slider_driven.toml"


def _run(tmp_path: Path, text: str) -> tuple[dict, str]:
    tmp_path.mkdir(exist_ok=True)
    scene = tmp_path / "scene.toml"
    scene.write_text(text + "\n[dynamics]\ncount = 30\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return results, (out / "dynamics.svg").read_text(encoding="utf-8")


def _starting_position(results: dict, key: str, coordinate: str) -> int:
    """The number of the position whose driver coordinate is the dynamics' first sample."""
    first = results["dynamics"][key][0]
    (number,) = [p["index"] for p in results["positions"] if p["driver"][coordinate] == pytest.approx(first, abs=1e-9)]
    return number


def _axis_names(drawing: str, symbol: str) -> set[str]:
    """The drawing's texts that name an axis of ``symbol`` (a text in two scripts is set in spans, one a font)."""
    texts = (re.sub(r"<[^>]+>", "", body) for body in re.findall(r"<text[^>]*>(.*?)</text>", drawing))
    return {text for text in texts if text.startswith(f"{symbol}, ")}


@pytest.mark.parametrize("omega,far_end", [("4.0", False), ("-4.0", True)])
def test_a_swing_s_angle_is_counted_from_the_position_the_lever_starts_at(tmp_path, omega, far_end):
    text = SWING.read_text(encoding="utf-8").replace("omega   = 4.0 ", f"omega   = {omega} ")
    results, drawing = _run(tmp_path, text)
    start = _starting_position(results, "angle_deg", "angle_deg")
    assert start == (len(results["positions"]) if far_end else 1)
    assert _axis_names(drawing, "φ") == {f"φ, ° from position {start}"}


@pytest.mark.parametrize("velocity,far_end", [("0.08", False), ("-0.08", True)])
def test_a_slider_s_travel_is_counted_from_the_position_the_rod_starts_at(tmp_path, velocity, far_end):
    text = SLIDER.read_text(encoding="utf-8").replace("velocity     = 0.08 ", f"velocity     = {velocity} ")
    if far_end:   # the lever then turns clockwise: its working stroke too
        text = text.replace('sense = "ccw"', 'sense = "cw"')
    results, drawing = _run(tmp_path, text)
    start = _starting_position(results, "displacement", "displacement")
    assert start == (12 if far_end else 1)
    assert _axis_names(drawing, "s") == {f"s, m from position {start}"}


def test_the_words_are_the_scene_s_language(tmp_path):
    text = SWING.read_text(encoding="utf-8").replace("omega   = 4.0 ", "omega   = -4.0 ")
    _, drawing = _run(tmp_path, text.replace('locale  = "en"', 'locale  = "ru"'))
    assert _axis_names(drawing, "φ") == {"φ, ° от положения 7"}
    slider = SLIDER.read_text(encoding="utf-8").replace('locale  = "en"', 'locale  = "zh"')
    _, drawing = _run(tmp_path / "zh", slider)
    assert _axis_names(drawing, "s") == {"s, m（自位置 1 起）"}
