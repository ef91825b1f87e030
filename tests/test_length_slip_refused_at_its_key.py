"""A length typed in millimetres that swells a drawing past any paper is refused at its own key, with what was
likely meant, not at the scale the drawing is drawn at.

The ratchet's E at 240 (0.24 m meant) put E 240 m off its coupler: the run refused `drawing.velocity_pole` and
the check `drawing.length_scale`, keys the student never changed, while the warning just before named E.  Each
scene here is a fixture with one value typed a thousand times too large; the value the refusal offers is the one
typed divided by 1000 (worked out here, not read off the message), and with it the scene checks.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from console import without_progress

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"
ENGINE = ROOT / "fixtures" / "engine_slider_crank.toml"
YOKE = ROOT / "fixtures" / "scotch_yoke.toml"
SLOTTED = ROOT / "fixtures" / "quick_return_slotted_lever.toml"
TANGENT = ROOT / "fixtures" / "tangent_mechanism_prp.toml"


def _written(value: float | list[float]) -> str:
    return "[" + ", ".join(f"{item:g}" for item in value) + "]" if isinstance(value, list) else f"{value:g}"


def _slipped(text: str, old: str, new: str) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


# (fixture, the line as written, the line with the slip, the key slipped, its value typed)
CASES = [
    pytest.param(RATCHET, "at = 0.24, offset = 0.125", "at = 240.0, offset = 0.125", "points.E.at", 240.0,
                 id="coupler-point-at"),
    pytest.param(RATCHET, "at = 0.24, offset = 0.125", "at = 0.24, offset = 125.0", "points.E.offset", 125.0,
                 id="coupler-point-offset"),
    # A rod 190 m long beside a 0.05 m crank still assembles: its paths are what no paper holds.
    pytest.param(ENGINE, "length   = 0.19", "length   = 190.0", "groups[0].length", 190.0, id="connecting-rod"),
    # The yoke's crank is its only link's length: its centre of mass, 25 mm out, is what it stands alone among.
    pytest.param(YOKE, "length  = 0.075", "length  = 75.0", "driver.length", 75.0, id="scotch-yoke-crank"),
    pytest.param(SLOTTED, "O = [0.0, 0.30]", "O = [0.0, 300.0]", "frame.points.O", [0.0, 300.0], id="frame-point"),
    # The ram's guide 550 m up: the PRP's sliders follow it there, and nothing had warned of it.
    pytest.param(TANGENT, "through = [0.0, 0.55]", "through = [0.0, 550.0]", "frame.lines.ram.through",
                 [0.0, 550.0], id="frame-guide"),
]


@pytest.mark.parametrize("command", ["check", "run"])
@pytest.mark.parametrize(("fixture", "old", "new", "key", "typed"), CASES)
def test_the_refusal_names_the_length_typed_in_millimetres(tmp_path, capsys, command, fixture, old, new, key, typed):
    text = fixture.read_text(encoding="utf-8")
    scene = tmp_path / "slipped.toml"
    scene.write_text(_slipped(text, old, new), encoding="utf-8")
    out = tmp_path / "out"
    argv = [command, str(scene)] + (["--out", str(out)] if command == "run" else [])
    assert main(argv) == 2
    err = without_progress(capsys.readouterr().err)
    error = err.strip().splitlines()[-1]
    assert error.startswith(f"graphplan: error: {key}: "), error
    meant_value = [value / 1000 for value in typed] if isinstance(typed, list) else typed / 1000
    assert f"{key} = {_written(meant_value)}" in error and f"(got {typed!r})" in error, error
    # The drawing that showed the slip is still said, with the key it is drawn at.
    assert "more than any paper" in error and re.search(r" at drawing\.\w+ = ", error), error
    assert not out.exists()
    # The warning named the same key before the refusal.
    assert err.index(f"warning: {key} = {_written(typed)}") < err.index("graphplan: error: ")
    # What the refusal offers is what was meant: the scene as the fixture has it.
    meant = tmp_path / "meant.toml"
    meant.write_text(_slipped(text, old, new.replace(repr(typed), repr(meant_value))), encoding="utf-8")
    assert main(["check", str(meant)]) == 0, capsys.readouterr().err


@pytest.mark.parametrize(("old", "new", "said"), [
    ("length  = 0.12\n", "length  = 120.0\n", "driver.length = 120 m beside frame.points.O (0.3 m from C)"),
    ("O = [0.0, 0.30]", "O = [0.0, 0.0003]", "frame.points.O (0.0003 m from C)"),
], ids=["crank-in-millimetres", "pivots-a-thousandth-apart"])
def test_a_lever_turned_round_by_a_slipped_length_says_which(tmp_path, capsys, old, new, said):
    """The Whitworth lever's crank at 120 m (or its pivots 0.3 mm apart) turns the lever round, and
    `start = "extreme"` was refused for a lever with no extremes, before any warning named the length."""
    scene = tmp_path / "slipped.toml"
    scene.write_text(_slipped(SLOTTED.read_text(encoding="utf-8"), old, new), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    error = without_progress(capsys.readouterr().err).strip().splitlines()[-1]
    assert error.startswith("graphplan: error: positions.start: "), error
    assert "link 4 turns round" in error and said in error and "millimetres" in error, error


def test_a_crank_a_thousand_times_too_short_is_named_beside_the_pole_distance(tmp_path, capsys):
    """A crank of 0.175 mm draws pa, which velocity_pole fixes at 150 mm, beside links 3000 times as long: the plan
    was refused at the pole distance alone, and nothing named the crank."""
    scene = tmp_path / "slipped.toml"
    scene.write_text(_slipped(RATCHET.read_text(encoding="utf-8"), "length  = 0.175 ", "length  = 0.000175 "),
                     encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    error = without_progress(capsys.readouterr().err).strip().splitlines()[-1]
    assert error.startswith("graphplan: error: drawing.velocity_pole: "), error
    assert "driver.length = 0.000175 m" in error, error
