"""forces.md wrote a slide's moment equation as a product equal to nought ("ΣME(6) = 0 → R16·x = 0 N·m") and listed
the couple of a block's reaction through its pin as a term ("R34·x: 0 N·m") of the equation that finds R34: neither
says what the equation gives.  It gives the shift x of the slide's normal reaction along the slide from its joint, as
the note writes it; here each shift forces.md states is held against the linear system's (statics), which finds the
same reaction's shift from all the equilibrium equations at once."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.scene import load

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
LINE = re.compile(r"^- (?P<group>\S+): ΣM(?P<about>\S+?)\((?P<bodies>[\d,]+)\) = 0 → (?P<rest>.*)$", re.MULTILINE)
THROUGH = re.compile(r"^x = 0: the line of (?P<reaction>R\d+) passes through (?P<point>\S+?)(?:;|$)")
SHIFTED = re.compile(r"^x = \|(?P<reaction>R\d+)·x\|/R\d+ = (?P<couple>[\d.]+)/(?P<force>[\d.]+) = (?P<x>[\d.]+) m")


def _scene(tmp_path: Path, source: str) -> Path:
    if source.endswith(".toml"):
        return FIXTURES / source
    path = tmp_path / f"{source}.toml"
    assert main(["new", source, "--out", str(path)]) == 0
    return path


def _statics_shift(equilibrium, name: str, index: int) -> tuple[float, float]:
    """The linear system's shift of the slide's reaction ``name`` (m, along the slide) and its size (N)."""
    found = {reaction.name: reaction for reaction in equilibrium.reactions}
    reaction = found.get(name) or found[f"R{name[2]}{name[1]}"]
    assert reaction.offset is not None, f"{name} is no slide's reaction"
    return float(np.asarray(reaction.offset)[index]), abs(complex(np.asarray(reaction.force)[index]))


@pytest.mark.parametrize("source", ["shaper", "slotted-lever", "scotch_yoke.toml", "tangent_mechanism_prp.toml",
                                    "triad_with_slider.toml"])
def test_forces_md_writes_a_slide_s_moment_equation_as_the_shift_it_finds(tmp_path, capsys, source):
    path = _scene(tmp_path, source)
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--only", "forces,note", "--locale", "en"]) == 0
    capsys.readouterr()
    forces = (out / "forces.md").read_text(encoding="utf-8")
    note = (out / "note.md").read_text(encoding="utf-8")
    # A product written equal to nought, or listed as a term of nought, says nothing of what the equation gives.
    assert not re.search(r"·x = 0 N·m|·x: 0 N·m", forces), forces
    analysis = analyse(load(path))
    stated = 0
    for heading, block in zip(re.findall(r"^## Position (\d+)$", forces, re.MULTILINE),
                              re.split(r"^## Position \d+$", forces, flags=re.MULTILINE)[1:], strict=True):
        plan = next(plan for plan in analysis.plans if plan.number == int(heading))
        for line in LINE.finditer(block):
            rest = line["rest"]
            if through := THROUGH.match(rest):
                offset, force = _statics_shift(analysis.equilibrium, through["reaction"], plan.index)
                # The line passes through the joint only where the reaction has a line: a reaction of some size.
                assert force > 1e-6 and abs(offset) <= 1e-9, (line[0], offset, force)
                # The note writes the same equation to the same end.
                assert (f"ΣM{line['about']}({line['bodies']}) = {through['reaction']}·x = 0 ⇒ x = 0: the line of "
                        f"{through['reaction']} passes through {through['point']}") in note, line[0]
                stated += 1
            elif shifted := SHIFTED.match(rest):
                offset, force = _statics_shift(analysis.equilibrium, shifted["reaction"], plan.index)
                assert float(shifted["x"]) == pytest.approx(abs(offset), rel=1e-4), (line[0], offset)
                stated += 1
            else:
                assert "·x" not in rest.split(";")[0] or "holds this moment as a couple alone" in rest, line[0]
    assert stated, forces
