"""Zhukovsky's lever with the friction loads: the balancing load with friction by a second method.

The lever is the power balance drawn, so with the pairs' friction loads on it
(the friction moments of the journals, the friction forces of the slides, at
the settled reactions) it must give the balancing load of the polygons with
friction and of the linear system with friction.  A friction force on a guide
acts at the guide's own point under the slider (``a4``): applied at the
slider's image it would cancel its partner and lose the slide's power loss.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
from pathlib import Path

import pytest
from sheet_texts import flat
from test_joint_friction import OMEGA, PUSH, RADIUS, ROD, ratchet_with_friction, slider_crank, slider_crank_text

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.locale import strings
from graphplan.report import forces as force_report
from graphplan.report.note import note_markdown
from graphplan.report.results import results
from graphplan.scene import FrictionSpec

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


def slotted_lever_with_friction():
    """The quick-return mechanism with friction in the slot (block 3 on the rocker 4) and in two journals."""
    scene = graphplan.load(FIXTURES / "quick_return_slotted_lever.toml")
    specs = (FrictionSpec("friction[0]", "A", (3, 4), 0.15, None, None),
             FrictionSpec("friction[1]", "C", None, 0.1, 0.02, None),
             FrictionSpec("friction[2]", "A", (2, 3), 0.1, 0.01, None))
    return analyse(dataclasses.replace(scene, friction=specs))


def triad_slider_with_friction():
    """The triad whose third leg slides, with friction on the slider's guide and in two journals of the triad."""
    scene = graphplan.load(FIXTURES / "triad_with_slider.toml")
    specs = (FrictionSpec("friction[0]", "F", (1, 5), 0.12, None, None),
             FrictionSpec("friction[1]", "B", (3, 6), 0.1, 0.01, None),
             FrictionSpec("friction[2]", "D", (4, 6), 0.1, 0.01, None))
    return analyse(dataclasses.replace(scene, friction=specs))


def tangent_slot_with_friction():
    """The tangent mechanism with friction in the lever's upper slot (block 5 on lever 4), whose point under the
    block, b4, the velocity plan does not construct."""
    scene = graphplan.load(FIXTURES / "tangent_mechanism_prp.toml")
    return analyse(dataclasses.replace(scene, friction=(FrictionSpec("friction[0]", "B", (4, 5), 0.15, None, None),)))


CASES = {
    "journals of the ratchet": lambda: ratchet_with_friction(0.12),
    "guide and journals of a triad's sliding leg": triad_slider_with_friction,
    "slot and journals of the slotted lever": slotted_lever_with_friction,
    "slot on a moving lever with no image under the block": tangent_slot_with_friction,
    "guide of the slider-crank, on the frame": lambda: analyse(slider_crank(
        '[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 0.15\n[[friction]]\njoint = "A"\nf = 0.1\nradius = 0.02')),
}


@pytest.mark.parametrize("case", CASES)
def test_the_lever_with_friction_gives_the_polygons_and_the_linear_system_with_friction(case):
    analysis = CASES[case]()
    exact = analysis.with_friction
    checked = 0
    for position in analysis.plans:
        if position.with_friction.locked:
            assert position.lever_with_friction is None
            continue
        rubbing, lever = position.with_friction, position.lever_with_friction
        assert lever.balancing == pytest.approx(rubbing.balancing, rel=1e-9)
        assert lever.balancing == pytest.approx(exact.balancing[position.index], rel=1e-9)
        # The friction is on the lever: it parts from the frictionless lever as the polygons do.
        assert lever.balancing != pytest.approx(position.lever.balancing, rel=1e-3)
        checked += 1
    assert checked >= 2


def test_a_friction_force_on_the_guide_acts_at_the_guides_own_point():
    analysis = slotted_lever_with_friction()
    position = analysis.plans[0]
    images = {term.name: term.image for term in position.lever_with_friction.terms}
    assert images["Ff43"] == "a" and images["Ff34"] == "a4"
    velocity = position.velocity
    assert abs(velocity.points["a"] - velocity.points["a4"]) > 1e-3 * abs(velocity.points["a"])


def test_a_friction_force_on_a_guide_without_its_own_image_there_acts_where_similarity_puts_it():
    analysis = tangent_slot_with_friction()
    position = analysis.plans[0]
    velocity = position.velocity
    assert "B4" not in velocity.images
    terms = {term.name: term for term in position.lever_with_friction.terms}
    on_block, on_lever = terms["Ff45"], terms["Ff54"]
    assert on_block.image == "b" and on_block.shift == 0
    # b4 by hand: the lever turns about its fixed pivot C, so vB4 = ω4 × CB.
    where = position.positions
    b4 = 1j * velocity.rates[4] * (where["B"] - where["C"])
    assert velocity.points[on_lever.image] + on_lever.shift == pytest.approx(b4, abs=1e-12)
    assert abs(b4 - velocity.points["b"]) > 1e-3 * abs(b4)


def test_results_carry_the_lever_with_friction():
    analysis = slotted_lever_with_friction()
    written = json.loads(json.dumps(results(analysis)))
    by_number = {entry["index"]: entry for entry in written["positions"]}
    for position in analysis.plans:
        friction = by_number[position.number]["forces"]["friction"]
        assert friction["lever_balancing_moment"] == pytest.approx(position.lever_with_friction.balancing, rel=1e-10)
        assert friction["lever_balancing_moment"] == pytest.approx(friction["balancing_moment"], rel=1e-9)
        assert abs(friction["lever_difference_percent"]) < 1e-7


def test_forces_md_gives_the_lever_with_friction_once_per_settled_position_and_the_note_once_too():
    analysis = slotted_lever_with_friction()
    written = force_report.markdown(analysis)
    note = note_markdown(analysis)
    for position in analysis.plans:
        lever, polygons = position.lever_with_friction.balancing, position.with_friction.balancing
        difference = (lever - polygons) / polygons * 100.0
        line = next(line for line in written.splitlines()
                    if line.startswith("Zhukovsky's lever with the pairs' friction loads")
                    and f"Mb = {force_report.number(lever, 6)} N·m" in line)
        assert float(line.split(", ")[-1].split(" %")[0].replace("−", "-")) == pytest.approx(difference, abs=1e-3)
        assert abs(difference) < 1e-6
    assert written.count("Zhukovsky's lever with the pairs' friction loads") == len(analysis.plans)
    # The note works the loads out and gives the lever in its own words, not twice.
    assert "Zhukovsky's lever with the pairs' friction loads" not in note
    assert note.count(strings("en")["note_friction_lever_table"].format(number="")) == len(analysis.plans)


@pytest.mark.parametrize(("only", "lever"), [("lever", True), ("forces", False), ("forces,lever", True)])
def test_the_lever_piece_brings_the_lever_with_friction_and_forces_alone_the_sheets_without_a_lever(tmp_path, only,
                                                                                                    lever):
    """`--only lever` wrote forces_N.svg with the plain lever and no sheet with friction at all; the sheet with
    friction comes with the force sheet it repeats, its lever with friction on it where the lever is asked.
    Friction in the crank's journal alone: Mb = Mb0 + sign(ω)·ρ·P/cos β, Mb0 = −P·r·sin(φ + β)/cos β."""
    f, journal = 0.1, 0.03
    scene = tmp_path / "journal.toml"
    scene.write_text(slider_crank_text(f'[[friction]]\njoint = "O"\nf = {f}\nradius = {journal}'))
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", only]) == 0
    for number in (1, 5, 9, 17):
        plain = (tmp_path / "out" / f"forces_{number}.svg").read_text(encoding="utf-8")
        rubbing = (tmp_path / "out" / f"forces_friction_{number}.svg").read_text(encoding="utf-8")
        assert ('id="lever-caption"' in plain) == lever and ('id="lever-caption"' in rubbing) == lever
        if not lever:
            continue
        phi = math.radians(7.5 + 15.0 * (number - 1))
        beta = math.asin(RADIUS * math.sin(phi) / ROD)
        expected = -PUSH * RADIUS * math.sin(phi + beta) / math.cos(beta) + math.copysign(
            f * journal * PUSH / math.cos(beta), OMEGA)
        caption = flat(re.search(r'<g id="lever-caption">(.*?)</g>', rubbing).group(1))
        on_lever = re.search(r"Mb = (−?[\d.]+) N·m \(Zhukovsky's lever\)", caption)
        assert float(on_lever.group(1).replace("−", "-")) == pytest.approx(expected, rel=2e-3)
        # Its loads are the friction's too: the journal's friction moment, as a couple of forces on the lever.
        assert 'id="lever-Mf12-1"' in rubbing and 'id="lever-Mf12' not in plain
