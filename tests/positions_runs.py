"""The plan of positions as a run writes it, for the tests that read its lettering back from positions.svg."""

from __future__ import annotations

from pathlib import Path

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent


def positions_plan(tmp_path: Path, scene: str) -> str:
    """The positions.svg text of ``scene``: a fixture's name, or ``new:KIND`` for a starter written under
    ``tmp_path``."""
    if scene.startswith("new:"):
        path = tmp_path / "scene.toml"
        assert main(["new", scene.removeprefix("new:"), "--out", str(path)]) == 0
    else:
        path = ROOT / "fixtures" / f"{scene}.toml"
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--only", "positions"]) == 0
    return (tmp_path / "out" / "positions.svg").read_text(encoding="utf-8")
