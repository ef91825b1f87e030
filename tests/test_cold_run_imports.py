"""What a run of the bundled scene imports: the README's first command is the one every new user times.

A sheet's import of the dynamics drawing's layer names pulled in the flywheel and with it scipy.integrate (and
scipy.special, sparse, linalg under it): a third of a cold run of a scene that asks for no dynamics
(bench/cold_run.py).  The scene's readers and the note's sections of a rotor and of a machine on its mounts cost
a linkage's run 35 ms more.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


ROTOR_AND_VIBRATION = {"graphplan.rotor_balancing", "graphplan.vibration", "graphplan.report.vibration_plots"}


def _imported_by_a_run(scene: Path, out: Path) -> set[str]:
    """Every module a fresh interpreter has imported once ``graphplan run`` of ``scene`` has written ``out``."""
    code = ("import sys; from graphplan.cli import main; "
            f"code = main(['run', {str(scene)!r}, '--out', {str(out)!r}]); "
            "print(code, *sorted(sys.modules))")
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    code, *modules = found.stdout.splitlines()[-1].split()
    assert code == "0", found.stderr
    return set(modules)


def test_the_bundled_scene_runs_without_importing_scipy(tmp_path):
    modules = {module for module in _imported_by_a_run(ROOT / "fixtures" / "ratchet_crank_rocker.toml",
                                                       tmp_path / "ratchet")
               if module.split(".")[0] in ("scipy", "matplotlib")}
    assert not modules, f"a run without dynamics imported {sorted(modules)[:5]}"
    assert (tmp_path / "ratchet" / "sheet_1.svg").is_file()


def test_a_scene_with_a_flywheel_still_finds_its_integrators(tmp_path):
    """The check above can see an import: the flywheel's scene needs scipy.integrate, and gets it."""
    scene = tmp_path / "flywheel.toml"
    subprocess.run([sys.executable, "-m", "graphplan", "new", "flywheel", "--out", str(scene)], check=True,
                   capture_output=True, cwd=ROOT)
    assert "scipy.integrate" in _imported_by_a_run(scene, tmp_path / "flywheel")


def test_a_linkage_run_does_not_import_the_rotor_or_the_vibration(tmp_path):
    """The scene reads [balancing] and [vibration], and the note writes their sections, with modules a scene without
    those tables never needs."""
    modules = _imported_by_a_run(ROOT / "fixtures" / "ratchet_crank_rocker.toml", tmp_path / "ratchet")
    assert (tmp_path / "ratchet" / "sheet_1.svg").is_file()
    loaded = ROTOR_AND_VIBRATION & modules
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
    modules = _imported_by_a_run(scene, tmp_path / "rotor")
    assert (tmp_path / "rotor" / "note.md").is_file()
    assert ROTOR_AND_VIBRATION <= modules
    note = (tmp_path / "rotor" / "note.md").read_text(encoding="utf-8")
    assert "balanc" in note.lower() and "vibration" in note.lower()


def test_the_classic_friction_formulas_load_only_for_a_scene_with_friction(tmp_path):
    """The bundled scene has no [[friction]]: its run never loads friction.py (inclines, threads, clutches); a scene
    with a journal's friction does, and the pair's friction circle is ρ = f·r."""
    assert "graphplan.friction" not in _imported_by_a_run(ROOT / "fixtures" / "ratchet_crank_rocker.toml",
                                                          tmp_path / "ratchet")
    text = (ROOT / "fixtures" / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    scene = tmp_path / "with_friction.toml"
    scene.write_text(text.replace("[positions]", '[[friction]]\njoint = "O"\nf = 0.2\nradius = 0.05\n\n[positions]', 1),
                     encoding="utf-8")
    code = ("import json, sys\nfrom graphplan.analysis import analyse\nfrom graphplan.scene import load\n"
            "before = 'graphplan.friction' in sys.modules\n"
            f"analysis = analyse(load({str(scene)!r}))\n"
            "print(json.dumps([before, 'graphplan.friction' in sys.modules, [p.radius for p in analysis.friction]]))")
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    before, after, radii = json.loads(found.stdout.splitlines()[-1])
    assert not before and after
    assert radii == [pytest.approx(0.2 * 0.05)]
