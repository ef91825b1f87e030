"""The console names a quantity as errors.md does: a hand reading far off its plan is told as giving ω4, ε3 or
aA4A3ʳ, the textbook's symbols the error tables, the note and the drawings write, not results.json's keys
(``omega4``, ``epsilon3``, ``aA4A3^r``), which a student reading the console beside errors.md would not find there.

The values the warning gives are worked out here from the scene's scales: μV = ω·lOA/pa, μa = ω²·lOA/πa, then
ω4 = pb·μV/lBC, |ε3| = n3b·μa/lAB and the relative acceleration ka4·μa.
"""

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _scene(tmp_path, fixture, measured):
    """The fixture with the student's ``measured`` table in place of its own."""
    text = (ROOT / "fixtures" / fixture).read_text(encoding="utf-8")
    text = re.sub(r"\[measured\.\d+\]\n(?:(?:velocity|acceleration)\s*=.*\n)*", "", text)
    scene = tmp_path / "scene.toml"
    scene.write_text(text + "\n" + measured + "\n", encoding="utf-8")
    return scene


def _console(scene, command="run"):
    out = scene.parent / "out"
    extra = ["--out", str(out), "--only", "errors"] if command == "run" else []
    done = subprocess.run([sys.executable, "-m", "graphplan", command, str(scene), *extra], cwd=ROOT,
                          capture_output=True, text=True, encoding="utf-8", timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    return done.stdout + done.stderr, out


def _ratchet(tmp_path):
    # The ratchet's crank-rocker at position 5, pb and n3b misread: pb = 30 mm, n3b = 12 mm.
    measured = "[measured.5]\nvelocity = { pb = 30.0, ab = 148.99 }\nacceleration = { pb = 64.99, n3b = 12.0 }"
    return _scene(tmp_path, "ratchet_crank_rocker.toml", measured)


def test_a_misread_rocker_reading_is_told_as_omega4_and_epsilon3_as_errors_md_writes_them(tmp_path):
    omega, crank, l_ab, l_bc = 17.0, 0.175, 0.55, 0.325
    mu_v, mu_a = omega * crank / 150.0, omega ** 2 * crank / 100.0
    console, out = _console(_ratchet(tmp_path))
    (warning,) = [line for line in console.splitlines() if "measured.5:" in line]
    assert f"pb = 30 mm gives VB = {30.0 * mu_v:.4g} against " in warning
    assert f"ω4 = {30.0 * mu_v / l_bc:.4g} against " in warning
    # The rocker and the rod turn clockwise here, so the construction signs ε3 negative.
    assert f"n3b = 12 mm gives ε3 = {-12.0 * mu_a / l_ab:.4g} against " in warning
    assert "omega" not in warning and "epsilon" not in warning
    table = (out / "errors.md").read_text(encoding="utf-8")
    assert "| ω4 |" in table and "| ε3 |" in table and "omega4" not in table


def test_graphplan_check_tells_the_same_symbols(tmp_path):
    console, _ = _console(_ratchet(tmp_path), command="check")
    (warning,) = [line for line in console.splitlines() if "measured.5:" in line]
    assert "ω4 = " in warning and "ε3 = " in warning
    assert "omega4" not in warning and "epsilon3" not in warning


def test_a_misread_relative_acceleration_is_told_with_its_superscript_r(tmp_path):
    # The shaper's six-bar at position 3: ka4, the slider's acceleration along the lever, read as 5 mm.
    mu_a = 6.0 ** 2 * 0.10 / 100.0
    scene = _scene(tmp_path, "shaper_six_bar.toml", "[measured.3]\nacceleration = { ka4 = 5.0 }")
    console, out = _console(scene)
    (warning,) = [line for line in console.splitlines() if "measured.3:" in line]
    assert f"ka4 = 5 mm gives aA4A3ʳ = {5.0 * mu_a:.4g} against " in warning
    assert "^r" not in warning
    assert "| aA4A3ʳ |" in (out / "errors.md").read_text(encoding="utf-8")
