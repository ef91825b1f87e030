"""forces.md (and forces.tex, made from it) gives with friction what the note and results.json give: the reactions
with friction, and each pair's friction load at them.  It gave the balancing load and η alone.

The slider-crank of ``test_joint_friction`` with friction in the crank's journal (ρ = f·r) and its piston in a
V-guide (f′ = f/sin θ): each table row is read back and checked against results.json's reactions with
friction, the loads worked out here afresh, Mf12 = f·r·|R12| and Ff14 = f/sin θ·|R14|.
"""

import dataclasses
import json
import math
import re

import pytest
from test_joint_friction import slider_crank, slider_crank_text

from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.locale import strings
from graphplan.report.forces import markdown

F_JOURNAL, R_JOURNAL, F_GUIDE, THETA = 0.1, 0.03, 0.1, 30.0
FRICTION = (f'[[friction]]\njoint = "O"\nf = {F_JOURNAL}\nradius = {R_JOURNAL}\n'
            f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {F_GUIDE}\ngroove_half_angle = {THETA}')
NUMBER = r"(−?[\d.]+)"


def value(text: str) -> float:
    return float(text.replace("−", "-"))


def friction_part(markdown_text: str, number: int, heading: str) -> str:
    """The part of ``number``'s section under its heading with friction."""
    section = next(part for part in re.split(r"^## ", markdown_text, flags=re.MULTILINE) if part.split("\n")[0].endswith(
        f" {number}"))
    return section[section.index(f"### {heading}"):]


def test_forces_md_tables_the_reactions_and_the_friction_loads_with_friction(tmp_path):
    scene = tmp_path / "rubbing.toml"
    scene.write_text(slider_crank_text(FRICTION))
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "forces"]) == 0
    written = (tmp_path / "out" / "forces.md").read_text(encoding="utf-8")
    results = json.loads((tmp_path / "out" / "results.json").read_text())
    planned = [p for p in results["positions"] if p.get("forces")]
    assert len(planned) == 4
    for position in planned:
        friction = position["forces"]["friction"]
        part = friction_part(written, position["index"], strings("en")["forces_friction"])
        reactions = {name: complex(*xy) for name, xy in friction["reactions"].items()}
        tabled = dict(re.findall(rf"^\| (R\d\d) \| {NUMBER} ∠", part, flags=re.MULTILINE))
        assert set(tabled) == set(reactions)
        for name, magnitude in tabled.items():
            assert value(magnitude) == pytest.approx(abs(reactions[name]), rel=1e-4)
        loads = {name: (value(reaction), value(load)) for name, reaction, name_, load in re.findall(
            rf"\| (R\d\d) = {NUMBER} \| (Ff|Mf)\d\d = {NUMBER} ", part)}
        assert set(loads) == {"R12", "R14"}
        journal = F_JOURNAL * R_JOURNAL * abs(reactions["R12"])
        guide = F_GUIDE / math.sin(math.radians(THETA)) * abs(reactions["R14"])
        assert loads["R12"] == pytest.approx((abs(reactions["R12"]), journal), rel=1e-4)
        assert loads["R14"] == pytest.approx((abs(reactions["R14"]), guide), rel=1e-4)
    tex = (tmp_path / "out" / "forces.tex").read_text(encoding="utf-8")
    assert tex.count(r"F\textsubscript{f14} = ") == tex.count(r"M\textsubscript{f12} = ") == len(planned)


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_the_tables_with_friction_are_in_the_scene_s_language(locale):
    analysis = analyse(dataclasses.replace(slider_crank(FRICTION), locale=locale))
    text = strings(locale)
    written = markdown(analysis)
    settled = [p for p in analysis.plans if not p.with_friction.locked]
    assert written.count(text["forces_friction_reactions"]) == len(settled)
    assert written.count(f"| {text['column_pair']} | {text['column_friction_factor']} |") == len(settled)
    # The friction force with its direction along the guide, as every load is written.
    load = r"\| Ff14 = [\d,]+ ∠ −?[\d,]+° Н \|" if locale == "ru" else r"\| Ff14 = [\d.]+ ∠ −?[\d.]+° N \|"
    assert len(re.findall(load, written)) == len(settled)
