"""The force sheets say where the friction locks the mechanism, as forces.md and the note do.

Two ways, both on the massless central slider-crank of ``test_joint_friction`` and checked against its closed
forms (a force P on the piston, rod angle β with sin β = r·sin φ / l):

* friction in the crank's journal alone (friction circle ρ): the rod force P/cos β does not change and
  Mb = Mb0 + sign(ω)·ρ·P/cos β with Mb0 = −P·r·sin(φ + β)/cos β.  At φ = 7.5° the piston pushes the crank
  round (Mb0 against ω), and a ρ of 0.02 m turns Mb round: the mechanism locks itself against its loads
  driving it (η′ ≤ 0).  The sheet with friction lost that line: the caption filter took it for a repeat of
  the crank's moment equation, which found the same Mb, since nothing but words was left of it beside Mb.
* friction f = 5 in the guide: where the crank pushes the piston, f·tan β > 1 jams it (position 17).  That
  position has no sheet with friction, and no sheet said so: its sheet without friction says it now, under
  the driving link, in the words of forces.md, and so does the course sheet that holds it.
"""

import dataclasses
import math
import re

import pytest
from test_joint_friction import OMEGA, PUSH, RADIUS, ROD, slider_crank

from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, with_length_scale
from graphplan.render.primitives import Text
from graphplan.render.sheet import course_sheets
from graphplan.report.forces import friction_lines

LOCALES = ("en", "ru", "zh")


def written(value: float) -> str:
    """Four significant digits, as a drawing writes a number, with a true minus sign."""
    decimals = max(0, 3 - math.floor(math.log10(abs(value))))
    return f"{value:.{decimals}f}".replace("-", "−")


def in_locale(friction: str, locale: str):
    return with_length_scale(analyse(dataclasses.replace(slider_crank(friction), locale=locale)))


def driver_caption(analysis, position, with_friction: bool) -> str:
    forces = position.with_friction if with_friction else position.forces
    key = force_layout.group_id(forces.groups[-1].label)
    layers = {layer.name: layer.items for layer in force_layout.layout(force_sheet(analysis, position, with_friction))}
    return "".join(item.text for item in layers[f"body-{key}-caption"])


def bare(text: str) -> str:
    """Without the breaks and spaces a caption's wrapping puts in or takes out."""
    return re.sub(r"\s+", "", text)


@pytest.mark.parametrize("locale", LOCALES)
def test_a_position_locked_against_its_loads_driving_it_says_so_under_the_driving_link(locale):
    rho = 0.02
    analysis = in_locale(f'[[friction]]\njoint = "O"\nf = 0.4\nradius = {rho / 0.4}', locale)
    position = analysis.plans[0]
    phi = analysis.motion.driver[position.index]
    beta = math.asin(RADIUS * math.sin(phi) / ROD)
    ideal = -PUSH * RADIUS * math.sin(phi + beta) / math.cos(beta)
    rubbing = ideal + math.copysign(rho * PUSH / math.cos(beta), OMEGA)
    assert ideal * OMEGA < 0 < rubbing * OMEGA  # the loads would drive; with friction the crank must
    assert position.forces.balancing == pytest.approx(ideal, rel=1e-9)
    assert position.with_friction.balancing == pytest.approx(rubbing, rel=1e-9)
    caption = bare(driver_caption(analysis, position, True))
    said = caption[caption.rindex(bare(f"= {written(rubbing)}")):]
    assert bare(written(ideal)) in said and "η′≤0" in said
    # The sentence is forces.md's, but for its numbers' digits.
    sentence = friction_lines(analysis, position)[0]
    words = [bare(piece) for piece in re.split(r"−?[\d.]+", sentence) if bare(piece)]
    assert all(piece in caption for piece in words)


@pytest.mark.parametrize("locale", LOCALES)
def test_a_position_the_friction_locks_says_so_on_its_force_sheet_and_on_the_course_sheet(locale):
    f = 5.0
    analysis = in_locale(f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}', locale)
    locked = [p for p in analysis.plans if p.with_friction.locked]
    for position in analysis.plans:
        phi = analysis.motion.driver[position.index]
        beta = math.asin(RADIUS * math.sin(phi) / ROD)
        pushes_the_piston = analysis.motion.point("B").v[position.index, 0] > 0
        assert (position in locked) == (pushes_the_piston and f * abs(math.tan(beta)) > 1.0)
    assert [p.number for p in locked] == [17]
    position = locked[0]
    sentence = bare(friction_lines(analysis, position)[0])
    assert sentence == bare(strings(locale)["forces_locked"])
    # The solves that found the lock are the program's count, not a step of the student's construction.
    assert str(position.with_friction.iterations) not in sentence
    assert sentence in bare(driver_caption(analysis, position, False))
    # The sheets of the positions that move say nothing of it.
    for moving in analysis.plans:
        if moving is not position:
            assert sentence not in bare(driver_caption(analysis, moving, False))
    sheet = next(sheet for sheet in course_sheets(analysis, "A1") if f"forces-{position.number}" in sheet.panels)
    drawn = "".join(item.text for layer in sheet.layers if layer.name.startswith(f"forces-{position.number}-")
                    for item in layer.items if isinstance(item, Text))
    assert sentence in bare(drawn)
