"""What a cold run of the bundled scene no longer loads, and that a scene that needs it still loads it.

Each run is a fresh interpreter, as a user starts it (bench/cold_run.py times it), asked which modules it imported.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "fixtures" / "ratchet_crank_rocker.toml"


def _imported_by_a_run(out: Path, scene: Path = SCENE, written: str = "sheet_1.svg") -> set[str]:
    code = ("import sys; from graphplan.cli import main; "
            f"code = main(['run', {str(scene)!r}, '--out', {str(out)!r}]); "
            "print(code, *sorted(sys.modules))")
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    code, *modules = found.stdout.splitlines()[-1].split()
    assert code == "0", found.stderr
    assert (out / written).is_file()
    return set(modules)


def test_a_linkage_run_does_not_import_the_rotor_or_the_vibration(tmp_path):
    """The scene reads [balancing] and [vibration], and the note writes their sections, with modules a scene without
    those tables never needs."""
    modules = _imported_by_a_run(tmp_path / "ratchet")
    loaded = {"graphplan.rotor_balancing", "graphplan.vibration", "graphplan.report.vibration_plots"} & modules
    assert not loaded, sorted(loaded)


def test_a_rotor_on_mounts_still_finds_its_modules(tmp_path):
    """The check above can see those imports: a rotor's scene with [vibration] loads them, and its note has both."""
    scene = tmp_path / "rotor.toml"
    subprocess.run([sys.executable, "-m", "graphplan", "new", "rotor", "--out", str(scene)], check=True,
                   capture_output=True, cwd=ROOT)
    text = scene.read_text(encoding="utf-8")
    if "[vibration]" not in text:
        text += "\n[vibration]\nmass = 20.0\nunbalance = 0.002\nstiffness = 2.0e4\ndamping_ratio = 0.05\nrpm = 1200\n"
        scene.write_text(text, encoding="utf-8")
    modules = _imported_by_a_run(tmp_path / "rotor", scene, "note.md")
    assert {"graphplan.rotor_balancing", "graphplan.vibration", "graphplan.report.vibration_plots"} <= modules
    note = (tmp_path / "rotor" / "note.md").read_text(encoding="utf-8")
    assert "balanc" in note.lower() and "vibration" in note.lower()
