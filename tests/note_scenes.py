"""The scenes the note's arm tests read back: every fixture, and the starters that add the sliding and class III
groups and the shaper's friction, each as a path a run loads."""

from __future__ import annotations

from pathlib import Path

from graphplan.starters import starter

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
SCENES = [("fixture", path.stem) for path in sorted(FIXTURES.glob("*.toml"))]
STARTERS = [("starter", kind) for kind in ("shaper", "slotted-lever", "triad")]


def scene_path(tmp_path: Path, source: str, name: str) -> Path:
    """The fixture's own file, or the starter written in English under ``tmp_path``."""
    if source == "fixture":
        return FIXTURES / f"{name}.toml"
    path = tmp_path / f"{name}.toml"
    path.write_text(starter(name, "en"), encoding="utf-8")
    return path
