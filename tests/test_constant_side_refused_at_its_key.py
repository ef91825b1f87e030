"""`[dynamics] constant` naming a side the scene gives loads on is refused at `dynamics.constant`, offering only
the ways out that work.

A slider-driven lever with the cylinder's push (driving) and the lever's 150 N·m (resisting) given, and
`constant = "driving"`, was told `dynamics: constant='driving' replaces the driving moment …; take
constant='resisting' or 'none'`: the key was `dynamics`, the side a moment where the slider's is a force, the
spelling Python's, and `constant = "resisting"` was refused in its turn, the scene giving resisting loads too.
Each way out offered is tried here, and so is each withheld.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.machine_dynamics import MachineDynamics
from graphplan.scene import loads

ROOT = Path(__file__).resolve().parent.parent
SLIDER = ROOT / "fixtures" / "slider_driven.toml"
ENGINE = ROOT / "fixtures" / "engine_slider_crank.toml"
PUSH = '\n[[loads]]\nkind = "force"\nlink = 2\npoint = "A"\nvalue = 900.0\nangle = 0.0\nduring = "always"\n'
CHOICES = ("driving", "resisting", "none")


def _text(path: Path, constant: str, extra: str = "") -> str:
    return path.read_text(encoding="utf-8") + extra + f'\n[dynamics]\ncount = 12\nconstant = "{constant}"\n'


def _refusal(text: str) -> SceneError | None:
    try:
        MachineDynamics(analyse(loads(text)))
    except SceneError as refused:
        return refused
    return None


def _offered(message: str) -> set[str]:
    return set(re.findall(r'constant = "(\w+)"', message))


@pytest.mark.parametrize("path,extra,constant,noun,named", [
    (SLIDER, PUSH, "driving", "driving force", "loads[1]"),      # both sides given: only "none" works
    (SLIDER, PUSH, "resisting", "resisting force", "loads[0]"),
    (SLIDER, "", "resisting", "resisting force", "loads[0]"),     # no driving load: "driving" works too
    (ENGINE, "", "driving", "driving moment", "loads[0]"),        # the gas force drives; nothing is marked resisting
], ids=["slider-both-sides-driving", "slider-both-sides-resisting", "slider-resisting-only", "engine-driving"])
def test_the_refusal_names_its_key_and_offers_only_what_works(path, extra, constant, noun, named):
    refused = _refusal(_text(path, constant, extra))
    assert refused is not None
    assert refused.where == "dynamics.constant"
    message = str(refused)
    assert noun in message and f"({named})" in message and "constant='" not in message
    offered = _offered(message)
    assert offered and constant not in offered
    for choice in CHOICES:
        works = _refusal(_text(path, choice, extra)) is None
        assert works == (choice in offered or choice == "auto"), choice


def test_check_and_run_refuse_it_alike_and_write_nothing(tmp_path, capsys):
    scene = tmp_path / "lever.toml"
    scene.write_text(_text(SLIDER, "driving", PUSH), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    checked = capsys.readouterr().err
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    assert capsys.readouterr().err.strip().splitlines()[-1] == checked.strip().splitlines()[-1]
    assert "dynamics.constant:" in checked and not out.exists()
