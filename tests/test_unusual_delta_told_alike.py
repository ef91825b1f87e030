"""A δ above the 0.2 machines are built to run with is told by the command line and cautioned in the note alike:
both give the speed's swing over the turn, ωmax/ωmin = (2 + δ)/(2 − δ), from one function.

With ωm the mean of ωmax and ωmin and δ = (ωmax − ωmin)/ωm, ωmax = ωm·(1 + δ/2) and ωmin = ωm·(1 − δ/2): their
ratio is (2 + δ)/(2 − δ), 2.5/1.5 = 5/3 for δ = 0.5.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.flywheel import LARGEST_USUAL_DELTA, delta_warning, unusual_speed_swing
from graphplan.starters import starter


def test_the_swing_is_given_only_for_an_unusual_delta():
    assert unusual_speed_swing(None) is None
    assert unusual_speed_swing(LARGEST_USUAL_DELTA) is None
    assert unusual_speed_swing(0.05) is None
    assert unusual_speed_swing(0.5) == pytest.approx(5.0 / 3.0, rel=1e-15)


def run(tmp_path: Path, delta: float, capsys) -> tuple[str, str]:
    text = starter("flywheel")
    text, changed = re.subn(r"^delta = 0\.05", f"delta = {delta}", text, flags=re.MULTILINE)
    assert changed == 1
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "note"]) == 0
    return capsys.readouterr().out, (tmp_path / "out" / "note.md").read_text(encoding="utf-8")


def test_the_warning_and_the_note_give_the_same_swing(tmp_path, capsys):
    told, note = run(tmp_path, 0.5, capsys)
    assert "dynamics.delta: 0.5 is above the 0.2" in told and "(2 + δ)/(2 − δ) = 1.67 over the turn" in told
    assert "Caution: δ = 0.5 is above 0.2" in note and "ωmax/ωmin = (2 + δ)/(2 − δ) = 1.67 over the cycle" in note


def test_a_usual_delta_is_neither_told_nor_cautioned(tmp_path, capsys):
    told, note = run(tmp_path, 0.05, capsys)
    assert "(2 + δ)/(2 − δ)" not in told and "(2 + δ)/(2 − δ)" not in note


def test_the_warning_needs_a_delta():
    class Spec:
        delta = None
        where = "dynamics"

    assert delta_warning(Spec()) is None
