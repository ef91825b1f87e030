"""What a run of the bundled scene imports: the README's first command is the one every new user times.

A sheet's import of the dynamics drawing's layer names pulled in the flywheel and with it scipy.integrate (and
scipy.special, sparse, linalg under it): a third of a cold run of a scene that asks for no dynamics
(bench/cold_run.py).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _imported_by_a_run(scene: Path, out: Path) -> set[str]:
    code = ("import sys; from graphplan.cli import main; "
            f"code = main(['run', {str(scene)!r}, '--out', {str(out)!r}]); "
            "print(code, *sorted(m for m in sys.modules if m.split('.')[0] in ('scipy', 'matplotlib')))")
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    code, *modules = found.stdout.splitlines()[-1].split()
    assert code == "0", found.stderr
    return set(modules)


def test_the_bundled_scene_runs_without_importing_scipy(tmp_path):
    modules = _imported_by_a_run(ROOT / "fixtures" / "ratchet_crank_rocker.toml", tmp_path / "ratchet")
    assert not modules, f"a run without dynamics imported {sorted(modules)[:5]}"
    assert (tmp_path / "ratchet" / "sheet_1.svg").is_file()


def test_a_scene_with_a_flywheel_still_finds_its_integrators(tmp_path):
    """The check above can see an import: the flywheel's scene needs scipy.integrate, and gets it."""
    scene = tmp_path / "flywheel.toml"
    subprocess.run([sys.executable, "-m", "graphplan", "new", "flywheel", "--out", str(scene)], check=True,
                   capture_output=True, cwd=ROOT)
    assert "scipy.integrate" in _imported_by_a_run(scene, tmp_path / "flywheel")
