"""The linkage's and the rotor's warnings about lengths in millimetres judge by one ratio and ask one question.

A length 200 times another of the same machine is one in millimetres among metres, whether a link beside a crank
or a mass's radius beside its correction's; the warning then asks whether some lengths are millimetres (divide
those alone), else whether all are (divide them by 1000, a second moment of area, mm⁴ = 10⁻¹² m⁴, by 10¹²).
"""

from __future__ import annotations

from graphplan import length_units, rotor_lengths, units
from graphplan.rotor_lengths import Implausible, LengthsInMillimetres

ALL = "are the lengths in millimetres? The scene's lengths are in metres (divide them by 1000)"
SOME = "are some lengths in millimetres? The scene's lengths are all in metres (divide millimetres by 1000)"


def test_one_ratio_tells_millimetres_among_metres():
    assert length_units.MIXED_RATIO == rotor_lengths.MIXED_RATIO == units.MIXED_RATIO == 200.0


def test_the_question_for_all_lengths_and_for_some():
    assert units.millimetres_question() == ALL
    assert units.millimetres_question(some=True) == SOME
    assert units.millimetres_question(second_moment=True) == (
        "are the lengths in millimetres? The scene's lengths are in metres (divide them by 1000, a second moment of "
        "area by 10¹²)")
    # Only some in millimetres: the second moment is one of them or not, and is named by the lengths told.
    assert units.millimetres_question(some=True, second_moment=True) == SOME


def test_the_rotor_warning_ends_with_the_question():
    diameter = Implausible("diameter", "vibration.shaft.diameter", 30.0, rotor_lengths.THICKEST_SHAFT_M)
    assert LengthsInMillimetres((diameter,)).detail == (
        "vibration.shaft.diameter = 30 m is thicker than any shaft (over 5 m): " + ALL)
    mixed = Implausible("mixed", "balancing.masses[0].radius", 80.0, 200.0, other_key="balancing.planes[0].radius",
                        other=0.2)
    assert LengthsInMillimetres((mixed, diameter)).detail.endswith(": " + SOME)
