"""How the explanatory note and forces.md write a number: as a student would, never as a float's repr.

At a dead centre, or where two methods agree, the arithmetic leaves 1e−15 of a nought: the Scotch yoke's
note wrote "aB = pb·μa = 0.00·0.13159 = 1.4503e−15 m/s²", a reaction of 3.6e−15 N with a direction, and
"−43.2 %" between two such noughts; products on the lever ran to "1.1586e+05". Those are 0 and 115860.
"""

import glob
import re

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.report import forces as force_report
from graphplan.report.forces import number, percent, polar
from graphplan.report.note import note_markdown


@pytest.mark.parametrize(("value", "digits", "written"), [
    (1.4503e-15, 5, "0"), (-6.4468e-14, 5, "0"), (1.49e-14, 3, "0"),
    (115860.2, 5, "115860"), (-868600.4, 5, "−868600"), (99999.6, 5, "100000"), (123456.7, 5, "123460"),
    (12.3456, 5, "12.346"), (-0.5, 3, "−0.5"), (0.00012345, 5, "0.00012345"),
    (3.63616e-5, 5, "0.000036362"), (-1.2e-7, 5, "−0.00000012"),
])
def test_noise_is_a_nought_and_a_large_or_small_number_is_written_without_an_exponent(value, digits, written):
    assert number(value, digits) == written
    # Written whole, a large number keeps its digits' worth: it reads back within half its last place.
    if abs(value) >= 1e5:
        assert abs(float(written.replace("−", "-")) - value) <= 0.5 * 10 ** (len(str(int(abs(value)))) - digits)


def test_a_force_of_noise_has_no_direction_and_two_noughts_differ_by_nought():
    assert polar(3.5716e-15 + 1e-20j) == "0"
    assert polar(-3.0 + 0j) == "3 ∠ 180°"
    assert percent(3.5716e-15, 6.291e-15) == "0"  # was −43.2
    assert percent(1.0, 6.291e-15) == "—"  # a value against a nought has no percentage
    assert percent(101.0, 100.0) == "1"


@pytest.mark.parametrize("path", sorted(glob.glob("fixtures/*.toml")))
def test_no_note_or_forces_md_of_a_fixture_writes_an_exponent(path):
    analysis = analyse(graphplan.load(path))
    for text in (note_markdown(analysis), force_report.markdown(analysis)):
        found = [match.group(0) for match in re.finditer(r".{30}\d[eE][+−-]?\d.{5}", text)]
        assert not found


def test_the_scotch_yokes_dead_centre_reads_nought_where_the_plan_has_nought():
    note = note_markdown(analyse(graphplan.load("fixtures/scotch_yoke.toml")))
    # Position 4 is the yoke's dead centre: the plan's segment pb is 0.00 mm, so aB is 0.
    assert "aB = pb·μa = 0.00·0.13159 = 0 m/s²" in note
    # The lever's difference with a negative balancing moment, subtrahend and divisor in brackets.
    assert re.search(r"= \(−2\.78633 − \(−2\.78633\)\)/\(−2\.78633\)·100 % = 0 %", note)
