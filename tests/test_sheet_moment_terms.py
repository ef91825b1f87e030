"""The moment equations on a force sheet keep every term whose moment is in the value they give.

Near a dead centre an arm can be shorter than the sheet draws (0.24 mm for the crank's R32 at a compressor's
top dead centre).  The sheet dropped such a term and wrote ``ΣMO(2): Mb = 0,  Mb = 1.471 N·m``, while
forces.md kept it; the lever dropped the piston's inertia force beside it.  These tests read the equations the
sheet writes, name by name, against the force records.
"""

import re

import pytest
from lever_equation import unfactored
from scene_texts import piston_compressor

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet
from graphplan.render.plans import ZERO_MM
from graphplan.report.forces import markdown as forces_markdown

FIXTURES = "fixtures"

# A horizontal compressor whose 12 positions start at the piston's dead centre: position 7 is the other one.
COMPRESSOR = piston_compressor() + """
[positions]
count = 12
start = START
working = { link = 4, sense = "forward" }
plans = [1, 7]
[drawing]
length_scale = 0.0025
velocity_pole = 100.0
acceleration_pole = 100.0
"""


def _compressor(tmp_path, start='"extreme"'):
    path = tmp_path / "compressor.toml"
    path.write_text(COMPRESSOR.replace("START", start), encoding="utf-8")
    return analyse(graphplan.load(path))


def _drawings(analysis, position):
    return {drawing.name: drawing for row in force_layout.rows(force_sheet(analysis, position)).drawings
            for drawing in row}


def _written(line, head, unknown=True):
    """The names an equation ``head: unknown ± A·h1 ± M(B) ± C = 0, …`` writes (beside its unknown)."""
    body = unfactored(line[len(head):].split(" = 0")[0])
    terms = [term for term in re.split(r"\s*[+−]\s*", body.strip()) if term][1 if unknown else 0:]
    return [re.sub(r"^M\((.*)\)$", r"\1", term.split("·")[0]) for term in terms]


def _equations(analysis, position):
    """(equation record, the line the sheet writes for it or None) of every group of the position."""
    lines = [line for drawing in _drawings(analysis, position).values() for line in drawing.caption
             if line.startswith("ΣM")]
    for group in position.forces.groups:
        for equation in group.moments:
            head = f"ΣM{equation.about}({equation.bodies}):"
            yield equation, head, next((line for line in lines if line.startswith(head)), None)


def test_the_crank_s_equation_at_a_dead_centre_keeps_the_reaction_whose_arm_is_too_short_to_draw(tmp_path):
    analysis = _compressor(tmp_path)
    position = next(p for p in analysis.plans if p.number == 7)
    crank = position.forces.groups[-1]
    (equation,) = crank.moments
    (term,) = equation.terms
    assert term.name == "R32" and term.arm / analysis.scene.drawing.length_scale < ZERO_MM
    caption = _drawings(analysis, position)[f"body-{force_layout.group_id(crank.label)}"].caption
    line = next(line for line in caption if line.startswith("ΣMO(2):"))
    assert line.startswith("ΣMO(2): Mb − R32·h1 = 0,")
    # Not drawn, the arm is given under the equation, under the words that say why, at its length on the drawing.
    words, given = caption[caption.index(line) + 1:caption.index(line) + 3]
    assert words == strings(analysis.scene.locale)["arms_too_short"].format(least=f"{ZERO_MM:g}")
    assert re.fullmatch(r"h1 = [\d.]+ mm", given)
    assert float(given.split()[2]) == pytest.approx(term.arm / analysis.scene.drawing.length_scale, rel=1e-3)
    # forces.md writes the same terms as the sheet in every equation: those it gives a moment other than 0.
    sections = re.split(r"^## Position (\d+)$", forces_markdown(analysis), flags=re.MULTILINE)
    for number, section in zip(sections[1::2], sections[2::2]):
        for equation, head, line in _equations(analysis, next(p for p in analysis.plans if p.number == int(number))):
            row = next(row for row in section.splitlines() if f"ΣM{equation.about}({equation.bodies}) = 0" in row)
            acting = re.findall(r"(?:;|,) (\S+): (−?[\d.]+) N·m", row)
            assert sorted(_written(line, head) if line else []) == sorted(name for name, value in acting
                                                                          if value != "0"), (number, row, line)


def test_the_lever_near_a_dead_centre_keeps_the_piston_s_loads_whose_arms_are_too_short_to_draw(tmp_path):
    analysis = _compressor(tmp_path, start="180.1")
    position = next(p for p in analysis.plans if p.number == 7)
    lever = _drawings(analysis, position)["lever"]
    line = next(line for line in lever.caption if line.startswith("ΣMp:"))
    scale = force_sheet(analysis, position).lever_drawn_scale
    short = [term.name for term in position.lever.terms
             if term.image and term.force and abs(term.moment) / abs(term.force) / scale < ZERO_MM
             and position.lever.stands(term)]
    assert "Fu4" in short
    assert set(short) <= set(_written(line, "ΣMp:", unknown=False))


def _scenes():
    return [f"{FIXTURES}/{name}.toml" for name in
            ("engine_slider_crank", "offset_slider_crank", "quick_return_slotted_lever", "shaper_six_bar",
             "tangent_mechanism_prp", "scotch_yoke", "slider_driven", "stephenson_six_bar", "triad_with_slider")]


@pytest.mark.parametrize("start", ['"extreme"', "180.1"])
def test_the_compressor_s_sheet_writes_terms_that_sum_to_the_value(tmp_path, start):
    _check_every_equation(_compressor(tmp_path, start))


@pytest.mark.parametrize("path", _scenes())
def test_every_sheet_writes_terms_that_sum_to_the_value(path):
    _check_every_equation(analyse(graphplan.load(path)))


def _check_every_equation(analysis):
    """Every moment equation (each group's and the lever's) writes the terms the record keeps, and what it leaves
    out sums to nothing beside the value: the terms written give the value."""
    checked = 0
    for position in analysis.plans:
        if position.forces is None:
            continue
        for equation, head, line in _equations(analysis, position):
            left_out = [term for term in equation.terms if term not in equation.standing_terms]
            size = max([abs(term.moment) for term in equation.terms] + [abs(equation.value * equation.arm)])
            assert abs(sum(term.moment for term in left_out)) <= 1e-9 * size, (position.number, head)
            if line is None:  # an equation with nothing in it (a reaction through its joint)
                assert not equation.standing_terms and abs(equation.value * equation.arm) <= 1e-9 * max(size, 1.0)
                continue
            assert sorted(_written(line, head)) == sorted(term.name for term in equation.standing_terms), line
            checked += 1
        lever = position.lever
        line = next(line for line in _drawings(analysis, position)["lever"].caption if line.startswith("ΣMp:"))
        written = _written(line, "ΣMp:", unknown=False)
        assert written[-1] == "Fb"
        moments = {term.name: term.moment for term in lever.terms}
        total = sum(moments.values())
        assert abs(sum(moments[name] for name in written[:-1]) - total) <= 1e-9 * max(map(abs, moments.values())), line
        checked += 1
    assert checked >= 2
