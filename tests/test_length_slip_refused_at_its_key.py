"""A length typed in millimetres that swells a drawing past any paper is refused at its own key, with what was
likely meant, not at the scale the drawing is drawn at.

The ratchet's E at 240 (0.24 m meant) put E 240 m off its coupler: the run refused `drawing.velocity_pole` and
the check `drawing.length_scale`, keys the student never changed, while the warning just before named E.  Each
scene here is a fixture with one value typed a thousand times too large; the value the refusal offers is the one
typed divided by 1000 (worked out here, not read off the message), and with it the scene checks.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from console import without_progress

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"


def _slipped(text: str, old: str, new: str) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


# (fixture, the line as written, the line with the slip, the key slipped, its value typed, the drawing's own key)
CASES = [
    pytest.param(RATCHET, 'at = 0.24, offset = 0.125', 'at = 240.0, offset = 0.125', "points.E.at", 240.0,
                 ("drawing.velocity_pole", "drawing.length_scale"), id="coupler-point-at"),
    pytest.param(RATCHET, 'at = 0.24, offset = 0.125', 'at = 0.24, offset = 125.0', "points.E.offset", 125.0,
                 ("drawing.velocity_pole", "drawing.length_scale"), id="coupler-point-offset"),
]


@pytest.mark.parametrize("command", ["check", "run"])
@pytest.mark.parametrize(("fixture", "old", "new", "key", "typed", "drawing_keys"), CASES)
def test_the_refusal_names_the_length_typed_in_millimetres(tmp_path, capsys, command, fixture, old, new, key, typed,
                                                           drawing_keys):
    text = fixture.read_text(encoding="utf-8")
    scene = tmp_path / "slipped.toml"
    scene.write_text(_slipped(text, old, new), encoding="utf-8")
    out = tmp_path / "out"
    argv = [command, str(scene)] + (["--out", str(out)] if command == "run" else [])
    assert main(argv) == 2
    err = without_progress(capsys.readouterr().err)
    error = err.strip().splitlines()[-1]
    assert error.startswith(f"graphplan: error: {key}: "), error
    assert f"{key} = {typed / 1000:g}" in error and f"(got {typed!r})" in error, error
    # The drawing that showed the slip is still said, with the key it is drawn at.
    assert "more than any paper" in error and any(f"at {drawing} = " in error for drawing in drawing_keys), error
    assert not out.exists()
    # The warning named the same key before the refusal.
    assert err.index(f"warning: {key} = {typed:g} m") < err.index("graphplan: error: ")
    # What the refusal offers is what was meant: the scene as the fixture has it.
    meant = tmp_path / "meant.toml"
    meant.write_text(_slipped(text, old, new.replace(f"{typed!r}", f"{typed / 1000!r}")), encoding="utf-8")
    assert main(["check", str(meant)]) == 0, capsys.readouterr().err
