"""The note tells a link's rotation accelerated or decelerated only where its ε is a value, not rounding.

The quick-return's lever passes the vertical at φ = 90° (A straight above O, on the line CO) at its greatest ω:
with a uniform crank its ε is nought there by the symmetry of the two sides. The plan leaves ε4 a residue of
1e-16, which the note writes 0 rad/s²; it once went on "the rotation of link 4 is accelerated (ω4 and ε4 in the
same sense)" (bug hunt 7, F2). As for ω4 = 0, nothing is said of a nought. At φ = 120° the lever is slowing
(ω4 > 0 past its greatest), and the note says so.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.report.note import note_markdown

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


def _lever_rates(phi: float, step: float = 1e-4) -> tuple[float, float]:
    """ω4 and ε4 of the quick-return's lever (O 0.30 m above C, crank 0.12 m, ω2 = 8 rad/s, ε2 = 0) by differences of
    its angle ψ = atan2(yA, xA)."""
    def psi(angle: float) -> float:
        return math.atan2(0.30 + 0.12 * math.sin(angle), 0.12 * math.cos(angle))

    first = (psi(phi + step) - psi(phi - step)) / (2 * step)
    second = (psi(phi + step) - 2 * psi(phi) + psi(phi - step)) / (step * step)
    return first * 8.0, second * 64.0


def _epsilon_lines(locale: str) -> list[str]:
    scene = graphplan.load(FIXTURES / "quick_return_slotted_lever.toml")
    scene = dataclasses.replace(scene, locale=locale, positions=dataclasses.replace(
        scene.positions, start=90.0, plans=(1, 2)))
    note = note_markdown(analyse(scene))
    unit = strings(locale)["unit_rad_per_s2"]
    return [line for line in note.splitlines() if line.startswith("- ε4 = ") and unit in line]


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_nought_epsilon_is_neither_accelerated_nor_decelerated(locale):
    text = strings(locale)
    accelerated, decelerated = (text[key].format(link=4) for key in ("note_accelerated", "note_decelerated"))
    at_90, at_120 = _epsilon_lines(locale)
    omega, epsilon = _lever_rates(math.radians(90.0))
    assert abs(epsilon) < 1e-6 * omega * omega  # nought in theory
    assert accelerated not in at_90 and decelerated not in at_90
    omega, epsilon = _lever_rates(math.radians(120.0))
    assert omega > 0 > epsilon
    assert decelerated in at_120
