"""The note works out each group's equilibrium with friction as it does without: the moment equations with their
numbers, the friction loads among their terms, the polygon's equation with the friction forces in its sums.

Each moment equation written after "With friction in the pairs" is read back from the note's text alone: its terms
and the value found must sum to nought, the value must be the reaction (or Mb, or the couple R·x and the shift x)
of the analysis with friction, and each friction load among the terms must be f·|R| or ρ·|R| of its pair's reaction
with friction, worked out here from the scene's f and r.  The Russian and Chinese notes must carry the same
equations.
"""

from __future__ import annotations

import dataclasses
import math
import re
from functools import cache

import pytest
from note_lines import items_on_one_line
from test_press_with_friction import PRESS, shaper_text

from graphplan import load_text
from graphplan.analysis import analyse
from graphplan.locale import load_symbol, strings
from graphplan.report.note import note_markdown

SCENES = {"shaper": shaper_text, "press": lambda: PRESS}
NUMBER = r"−?\d+(?:[.,]\d+)?"
EQUATION = re.compile(rf"ΣM(?P<about>\S+?)\((?P<bodies>[\d,]+)\) = (?P<sign>−?)(?P<unknown>[^\s·]+(?:·x)?)"
                      rf"(?:·(?P<arm>{NUMBER}))?(?P<terms>(?: [+−] {NUMBER})*) = 0 ⇒ (?P<rest>.*)")
MOMENT_PART = re.compile(rf"M\((?P<name>[^)]+)\) = (?:[^;]*? = )?(?P<value>{NUMBER}) (?:N·m|Н·м)")


def value_of(text: str) -> float:
    return float(text.replace(",", ".").replace("−", "-").replace(" ", ""))


@cache
def analysis_of(name: str, locale: str):
    scene = load_text(SCENES[name]())
    return analyse(dataclasses.replace(scene, locale=locale))


@cache
def friction_blocks(name: str, locale: str) -> tuple[str, ...]:
    """The text of each plan position's force analysis with friction, from its bold lead to the position's end."""
    analysis = analysis_of(name, locale)
    text = strings(locale)
    note = "\n".join(items_on_one_line(note_markdown(analysis), text["semicolon"]))
    lead = f"**{text['forces_friction']}{text['full_stop']}**"
    blocks = []
    for part in note.split(lead)[1:]:
        blocks.append(re.split(r"\n#{2,3} ", part)[0])
    assert len(blocks) == sum(plan.forces is not None for plan in analysis.plans), "a position's friction is unwritten"
    return tuple(blocks)


def equations(block: str) -> list[tuple[re.Match, str]]:
    """Each moment equation of a block with the clauses before it on its line (the terms' moments worked out)."""
    found = []
    for line in block.splitlines():
        if line.startswith("- ") and "ΣM" in line and " ⇒ " in line:
            head, _, equation = line[2:].rpartition("ΣM")
            match = EQUATION.match("ΣM" + equation)
            assert match, line
            found.append((match, head))
    return found


CASES = [(name, k) for name in SCENES for k in (0, 1)]


@pytest.mark.parametrize(("name", "k"), CASES)
def test_each_moment_equation_with_friction_balances_with_the_value_the_analysis_found(name, k):
    analysis = analysis_of(name, "en")
    plan = analysis.plans[k]
    rubbing = plan.with_friction
    assert rubbing is not None and not rubbing.locked
    block = friction_blocks(name, "en")[k]
    # How the friction loads were found: the passes the analysis with friction records, each from the last one's.
    assert rubbing.iterations > 1
    assert f"settled after {rubbing.iterations} passes" in block
    written = equations(block)
    # Every equation of every group of the last pass with friction is written, in the order solved.
    records = [equation for group in rubbing.groups for equation in group.moments]
    assert [match["unknown"] for match, _ in written] == [equation.unknown for equation in records]
    vectors = {vector.name: vector.force for group in rubbing.groups for vector in group.polygon.vectors}
    shifted = 0
    for match, _ in written:
        terms = [value_of(term) for term in re.findall(rf"[+−] {NUMBER}", match["terms"])]
        total, largest = sum(terms), max([abs(term) for term in terms], default=0.0)
        unknown, rest = match["unknown"], match["rest"]
        sign = -1.0 if match["sign"] else 1.0
        if unknown.endswith("·x") and rest.startswith("x = 0"):
            assert not terms  # the reaction's line through the joint: nothing else has a moment about it
            assert abs(rubbing.reactions[unknown[:-2]].offset or 0.0) < 1e-9
            continue
        value = value_of(re.search(rf"= ({NUMBER}) (?:N|Н)", rest).group(1))
        if unknown == "Mb":
            assert value == pytest.approx(rubbing.balancing, rel=1e-4)
            assert value + total == pytest.approx(0.0, abs=1e-4 * largest)
        elif unknown.endswith("·x"):
            # R·x signed by its moment, x a length: |R|·x balances the rest.
            reaction = rubbing.reactions[unknown[:-2]]
            shift = re.search(rf"x = ({NUMBER})/({NUMBER}) = ({NUMBER}) m = ({NUMBER}) mm", rest)
            assert shift, rest
            assert value > 0 and value_of(shift[1]) == value
            assert value_of(shift[2]) == pytest.approx(abs(reaction.force), rel=1e-4)
            assert value_of(shift[4]) == pytest.approx(1000.0 * abs(reaction.offset), rel=1e-4)
            assert value_of(shift[3]) * value_of(shift[2]) == pytest.approx(value, rel=2e-4)
            assert sign * value + total == pytest.approx(0.0, abs=1e-4 * largest)
            shifted += 1
        else:
            arm = value_of(match["arm"])
            assert abs(value) == pytest.approx(abs(vectors[unknown]), rel=1e-4)
            assert sign * value * arm + total == pytest.approx(0.0, abs=2e-4 * largest)
    assert shifted == 1  # the ram's guide holds the pin's friction moment by shifting R16 along it


@pytest.mark.parametrize(("name", "k"), CASES)
def test_the_friction_loads_in_the_equations_are_f_and_rho_times_the_reactions_with_friction(name, k):
    """Each Mf among a moment equation's terms is ρ·|R| of its pair, ρ = f·r from the scene's table; each Ff in a
    polygon's sums and table is f·|R|: the friction of the reactions the note's equations find."""
    analysis = analysis_of(name, "en")
    rubbing = analysis.plans[k].with_friction
    block = friction_blocks(name, "en")[k]
    pairs = {pair.load_names[0]: pair for pair in analysis.friction}
    seen = set()
    for _, head in equations(block):
        for part in MOMENT_PART.finditer(head):
            name_, value = part["name"], value_of(part["value"])
            load = name_ if name_ in pairs else f"Mf{name_[3]}{name_[2]}" if name_.startswith("Mf") else None
            if load is None or not load.startswith("Mf"):
                continue
            pair = pairs[load]
            reaction = abs(rubbing.reactions[pair.reaction].force)
            assert abs(value) == pytest.approx(pair.spec.f * pair.spec.radius * reaction, rel=1e-4), part[0]
            seen.add(load)
    assert {name_ for name_, pair in pairs.items() if not pair.sliding} <= seen
    slide = next(pair for pair in analysis.friction if pair.sliding)
    assert re.search(rf"ΣF6 = [^.;]*\bFf{slide.source}{slide.target}\b", block)
    row = re.search(rf"\| Ff{slide.source}{slide.target} \| ({NUMBER}) ∠", block)
    assert value_of(row[1]) == pytest.approx(slide.spec.f * abs(rubbing.reactions[slide.reaction].force), rel=1e-4)


@pytest.mark.parametrize("name", SCENES)
@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_the_russian_and_chinese_notes_carry_the_same_equations_with_friction(name, locale):
    def written(language: str) -> list[tuple[str, ...]]:
        rows = []
        for block in friction_blocks(name, language):
            for match, _ in equations(block):
                numbers = tuple(re.findall(NUMBER, match["rest"].replace(",", ".")))
                rows.append((match["about"], match["bodies"], match["sign"], match["unknown"], (match["arm"] or "").replace(",", "."),
                             match["terms"].replace(",", "."), numbers[:4]))
        return rows

    # The unknowns as each locale writes them: the Russian Mу of the driver's Mb.
    english = [(*row[:3], load_symbol(row[3], strings(locale)), *row[4:]) for row in written("en")]
    other = written(locale)
    assert english and other == english
    text = strings(locale)
    note = "".join(friction_blocks(name, locale))
    assert text["note_group_forces_friction"].format(group="II(5,6)") in note
    assert math.isfinite(analysis_of(name, locale).plans[0].with_friction.balancing)


@pytest.mark.parametrize(("name", "k"), CASES)
def test_the_ram_s_couple_is_signed_and_its_x_measured_as_the_force_sheet_with_friction_writes_them(name, k):
    """ΣME(6) = R16·x − 7.3395 = 0 in the note beside ΣME(6): R16·x − Mf56 = 0, x = 3.301 mm on the sheet: the same
    sign before R16·x, the same length x."""
    from test_press_with_friction import analysis_of as drawn_analysis_of
    from test_press_with_friction import ram_equation

    drawn = drawn_analysis_of(name)
    sheet = re.match(r"ΣME\(6\): (−?)R16·x [+−] Mf56 = 0,\s+x = ([\d.]+) mm", ram_equation(drawn, drawn.plans[k]))
    assert sheet
    note = next(match for match, _ in equations(friction_blocks(name, "en")[k]) if match["unknown"] == "R16·x")
    assert note["sign"] == sheet[1]
    x = re.search(rf"= ({NUMBER}) mm", note["rest"])
    assert value_of(x[1]) == pytest.approx(float(sheet[2]), rel=1e-3)
