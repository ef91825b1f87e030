"""A length typed in millimetres that swells a drawing past any paper is refused at its own key, with what was
likely meant, not at the scale the drawing is drawn at.

The ratchet's E at 240 (0.24 m meant) put E 240 m off its coupler: the run refused `drawing.velocity_pole` and
the check `drawing.length_scale`, keys the student never changed, while the warning just before named E.  Each
scene here is a fixture with one value typed a thousand times too large (or too small: metres divided by 1000
again); the value the refusal offers is the one typed divided (or multiplied) by 1000, worked out here, not read off
the message, and with it the scene checks.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from console import without_progress

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.length_units import FARTHEST_POINT_SPANS, length_slip

ROOT = Path(__file__).resolve().parent.parent
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"
ENGINE = ROOT / "fixtures" / "engine_slider_crank.toml"
YOKE = ROOT / "fixtures" / "scotch_yoke.toml"
SLOTTED = ROOT / "fixtures" / "quick_return_slotted_lever.toml"
TANGENT = ROOT / "fixtures" / "tangent_mechanism_prp.toml"
SLIDER_DRIVEN = ROOT / "fixtures" / "slider_driven.toml"
OFFSET = ROOT / "fixtures" / "offset_slider_crank.toml"


def _written(value: float | list[float]) -> str:
    return "[" + ", ".join(f"{item:g}" for item in value) + "]" if isinstance(value, list) else f"{value:g}"


def _slipped(text: str, old: str, new: str) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def _case(fixture: Path, old: str, new: str, key: str, typed: float | list[float], *, id: str, short: bool = False):
    """(fixture, the line as written, the line with the slip, the key slipped, its value typed, whether it is a
    thousand times too short rather than too long)."""
    return pytest.param(fixture, old, new, key, typed, short, id=id)


CASES = [
    _case(RATCHET, "at = 0.24, offset = 0.125", "at = 240.0, offset = 0.125", "points.E.at", 240.0,
          id="coupler-point-at"),
    _case(RATCHET, "at = 0.24, offset = 0.125", "at = 0.24, offset = 125.0", "points.E.offset", 125.0,
          id="coupler-point-offset"),
    # A rod 190 m long beside a 0.05 m crank still assembles: its paths are what no paper holds.
    _case(ENGINE, "length   = 0.19", "length   = 190.0", "groups[0].length", 190.0, id="connecting-rod"),
    # The yoke's crank is its only link's length: its centre of mass, 25 mm out, is what it stands alone among.
    _case(YOKE, "length  = 0.075", "length  = 75.0", "driver.length", 75.0, id="scotch-yoke-crank"),
    _case(SLOTTED, "O = [0.0, 0.30]", "O = [0.0, 300.0]", "frame.points.O", [0.0, 300.0], id="frame-point"),
    # The ram's guide 550 m up: the PRP's sliders follow it there, and nothing had warned of it.
    _case(TANGENT, "through = [0.0, 0.55]", "through = [0.0, 550.0]", "frame.lines.ram.through",
          [0.0, 550.0], id="frame-guide"),
    # Under 20 m, but far off their links and beyond every other length: the crank's centre 6 m out on a 0.05 m
    # crank (120 of its spans), the rod's 5.5 m out on a 0.19 m rod, the lever's arm 12 m out beside a 0.15 m BC.
    _case(ENGINE, "at = 0.006 }", "at = 6.0 }", "points.S2.at", 6.0, id="crank-centre-at"),
    _case(ENGINE, "at = 0.055 }", "at = 5.5 }", "points.S3.at", 5.5, id="rod-centre-at"),
    _case(SLIDER_DRIVEN, "at = 0.0, offset = 0.12", "at = 0.0, offset = 12.0", "points.E.offset", 12.0,
          id="lever-arm-offset"),
    # A crank a thousand times too short, its centre hundreds of its lengths out: the yoke's among its points, the
    # ratchet's and the offset slider-crank's among links as well.
    _case(YOKE, "length  = 0.075", "length  = 7.5e-05", "driver.length", 7.5e-05, short=True,
          id="scotch-yoke-crank-short"),
    _case(RATCHET, "length  = 0.175 ", "length  = 0.000175 ", "driver.length", 0.000175, short=True,
          id="ratchet-crank-short"),
    _case(OFFSET, "length  = 0.08", "length  = 8e-05", "driver.length", 8e-05, short=True,
          id="offset-crank-short"),
]


@pytest.mark.parametrize("command", ["check", "run"])
@pytest.mark.parametrize(("fixture", "old", "new", "key", "typed", "short"), CASES)
def test_the_refusal_names_the_length_typed_in_millimetres(tmp_path, capsys, command, fixture, old, new, key, typed,
                                                           short):
    text = fixture.read_text(encoding="utf-8")
    scene = tmp_path / "slipped.toml"
    scene.write_text(_slipped(text, old, new), encoding="utf-8")
    out = tmp_path / "out"
    argv = [command, str(scene)] + (["--out", str(out)] if command == "run" else [])
    assert main(argv) == 2
    err = without_progress(capsys.readouterr().err)
    error = err.strip().splitlines()[-1]
    assert error.startswith(f"graphplan: error: {key}: "), error
    meant_value = [value / 1000 for value in typed] if isinstance(typed, list) else typed * 1000 if short \
        else typed / 1000
    assert f"{key} = {_written(meant_value)}" in error and f"(got {typed!r})" in error, error
    # Millimetres are asked of only where they are what was typed.
    assert ("millimetres typed for metres?" in error) is not short, error
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


def _slip(fixture: Path, old: str, new: str):
    return length_slip(analyse(graphplan.load_text(_slipped(fixture.read_text(encoding="utf-8"), old, new))).motion)


def test_a_point_is_far_off_its_link_only_beyond_the_bound():
    """The engine's crank is 0.05 m: its centre (FARTHEST_POINT_SPANS ± 1) crank lengths out is a slip only
    beyond the bound, and the value it names is the one typed."""
    within, beyond = ((FARTHEST_POINT_SPANS + sign) * 0.05 for sign in (-1, 1))
    assert _slip(ENGINE, "at = 0.006 }", f"at = {within!r} }}") is None
    slip = _slip(ENGINE, "at = 0.006 }", f"at = {beyond!r} }}")
    assert (slip.key, slip.value, slip.shorter) == ("points.S2.at", beyond, False)


def test_a_crank_and_its_centre_alone_tell_no_slip():
    """The yoke's crank 75 µm long with its centre 25 mm out, and no other length: either may be the slip, so
    neither is named (the yoke's other points taken off, the yoke's mass and load with them)."""
    text = _slipped(YOKE.read_text(encoding="utf-8"), "length  = 0.075", "length  = 7.5e-05")
    for line in ('S4 = { link = 4, from = "B", toward = "A", at = 0.0, offset = 0.16 }\n',
                 'P  = { link = 4, from = "B", toward = "A", at = 0.0, offset = 0.40 }'):
        text = _slipped(text, line, "")
    text = text[:text.index("[links.4]")] + text[text.index("[positions]"):]
    assert length_slip(analyse(graphplan.load_text(text)).motion) is None


@pytest.mark.parametrize("fixture", sorted((ROOT / "fixtures").glob("*.toml")), ids=lambda path: path.stem)
def test_no_fixture_has_a_length_slip(fixture):
    assert length_slip(analyse(graphplan.load(fixture)).motion) is None
