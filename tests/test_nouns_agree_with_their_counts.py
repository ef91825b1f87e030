"""A noun after a count takes the form the number asks for: «1 точка», «2 точки», «5 точек», «21 точка»; the flywheel
note said «362 точек»."""

from __future__ import annotations

import dataclasses
import math
import re

import pytest
from test_joint_friction import RADIUS, ROD, slider_crank
from test_machine_note import PRESS, note_of

from graphplan.analysis import analyse
from graphplan.locale import Count, strings
from graphplan.report.forces import cycle_notes
from graphplan.report.note import note_markdown

# The forms as a Russian grammar gives them, number by number.
POINTS = {0: "точек", 1: "точка", 2: "точки", 4: "точки", 5: "точек", 11: "точек", 12: "точек", 14: "точек",
          20: "точек", 21: "точка", 22: "точки", 25: "точек", 101: "точка", 111: "точек", 112: "точек", 362: "точки"}


@pytest.mark.parametrize("count", sorted(POINTS))
def test_a_russian_noun_takes_the_form_of_its_number(count):
    assert f"{Count(count)} {Count(count):точка|точки|точек}" == f"{count} {POINTS[count]}"


@pytest.mark.parametrize(("count", "noun"), [(1, "sample"), (2, "samples"), (11, "samples"), (21, "samples")])
def test_an_english_noun_is_singular_for_one_alone(count, noun):
    assert f"{Count(count):sample|samples}" == noun


def test_a_count_without_forms_is_its_number():
    assert f"{Count(362)}" == "362" and f"{Count(7):>3}" == "  7"


def test_a_noun_with_four_forms_is_refused():
    with pytest.raises(ValueError, match="two or three forms, not 4"):
        format(Count(3), "a|b|c|d")


@pytest.mark.parametrize(("count", "expected"), [(1, "время расчёта 1 положения, с"), (2, "время расчёта 2 положений, с"),
                                                 (5, "время расчёта 5 положений, с"), (11, "время расчёта 11 положений, с"),
                                                 (21, "время расчёта 21 положения, с"), (22, "время расчёта 22 положений, с")])
def test_the_accuracy_plots_axis_agrees_with_its_count_of_positions(count, expected):
    assert strings("ru")["accuracy_axis_time"].format(count=Count(count)) == expected.replace(
        ", с", " (диаграммы — N узлов), с")


@pytest.mark.parametrize(("count", "positions"), [(1, "в 1 положении"), (5, "в 5 положениях"), (11, "в 11 положениях"),
                                                  (21, "в 21 положении"), (22, "в 22 положениях")])
def test_the_accuracy_report_agrees_with_its_count_of_positions(count, positions):
    assert positions in strings("ru")["accuracy_explained"].format(count=Count(count))


def test_the_flywheel_note_counts_the_points_of_its_diagrams_in_agreement(tmp_path):
    _, note = note_of(tmp_path, PRESS, "ru")
    count, noun = re.search(r"в виде диаграмм \((\d+) (\w+)\)", note).groups()
    last, last_two = int(count) % 10, int(count) % 100
    agreeing = "точка" if last == 1 and last_two != 11 else "точки" if 2 <= last <= 4 and not 12 <= last_two <= 14 \
        else "точек"
    assert noun == agreeing


# The sentences that name positions: "At position 8", «В положении 6» for one, the plural for more (a teacher
# found "At positions 8" and «В положениях 6»).  The slider-crank of test_joint_friction with friction in its
# crank's journal alone: Mb = Mb0 + sign(ω)·ρ·P/cos β, Mb0 = −P·r·sin(φ + β)/cos β, so where the piston drives
# the crank, 0 < r·sin(φ + β) < ρ, the friction turns the flow round.
SINGULAR_PLURAL = {"en": ("At position ", "At positions "), "ru": ("В положении ", "В положениях "),
                   "zh": ("在位置 ", "在位置 ")}


def _turned_round(rho: float) -> list[int]:
    """The positions (numbered from 1) where the friction turns the power flow round, by the closed form."""
    found = []
    for k in range(24):
        phi = math.radians(7.5 + 15.0 * k)
        beta = math.asin(RADIUS * math.sin(phi) / ROD)
        if 0.0 < RADIUS * math.sin(phi + beta) < rho:
            found.append(k + 1)
    return found


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
@pytest.mark.parametrize("rho", [0.012, 0.02])
def test_the_positions_where_friction_turns_the_flow_round_are_one_or_several(locale, rho):
    where = _turned_round(rho)
    assert len(where) == (1 if rho == 0.012 else 2)
    scene = slider_crank(f'[[friction]]\njoint = "O"\nf = 0.4\nradius = {rho / 0.4}')
    notes = cycle_notes(analyse(dataclasses.replace(scene, locale=locale)))
    enumeration = strings(locale)["enumeration"]
    one, several = SINGULAR_PLURAL[locale]
    lead = (one if len(where) == 1 else several) + enumeration.join(map(str, where))
    assert any(note.startswith(lead) and not note.startswith(lead + enumeration) for note in notes), notes


@pytest.mark.parametrize(("locale", "one", "several"), [
    ("en", "constructed for position 5 from", "constructed for positions 1, 5 from"),
    ("ru", "построены для положения 5 по", "построены для положений 1, 5 по"),
    ("zh", "作位置 5 的", "作位置 1、5 的")])
def test_the_note_constructs_its_plans_for_one_position_or_several(locale, one, several):
    scene = slider_crank("")
    for plans, expected in (((5,), one), ((1, 5), several)):
        only = dataclasses.replace(scene, locale=locale,
                                   positions=dataclasses.replace(scene.positions, plans=plans))
        assert expected in note_markdown(analyse(only))
