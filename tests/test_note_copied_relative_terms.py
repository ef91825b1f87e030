"""An RPP on a turning guide: the note's table gives link b's reference point's relative terms as known.

Link 6 slides on the guide of link 4 without turning relative to it, so F moves relative to link 4 as E6 does:
VFF4 = VE6E4, aFF4ᵏ = aE6E4ᵏ = 2·ω4·VFF4, aFF4^r = aE6E4^r. The note once wrote "aFF4ᵏ | ? | — | —" (bug hunt 7,
F3). The expected moduli come from the closed-form positions of test_toward_a_slider, differenced in φ.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from test_toward_a_slider import EPSILON, LEVER_RPP, OMEGA, _e, _lever_rpp

import graphplan
from graphplan.analysis import analyse
from graphplan.report.note import note_markdown


def _relative(phi: float, step: float = 1e-4) -> tuple[float, float, float]:
    """ω4, and the speed and acceleration of F along link 4's guide (its coordinate from H), at ``phi``."""
    def coordinates(angle: float) -> tuple[float, float]:
        points, angles = _lever_rpp(angle)
        a = points["A"]
        h = (0.20 + 0.03j) * a / abs(a)
        return angles[4], float(((points["F"] - h) * np.conj(_e(angles[6]))).real)

    samples = [coordinates(phi + k * step) for k in (-1, 0, 1)]
    rates = []
    for part in range(2):
        before, here, after = (sample[part] for sample in samples)
        first, second = (after - before) / (2 * step), (after - 2 * here + before) / (step * step)
        rates.append((first * OMEGA, second * OMEGA ** 2 + first * EPSILON))
    (omega4, _), (speed, acceleration) = rates
    return omega4, speed, acceleration


def _modulus(row: str) -> float:
    cell = row.split(" | ")[1]
    return float(cell.rsplit(" = ", 1)[-1].split()[0].replace(",", ".").replace("−", "-"))


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_relative_terms_of_link_b_s_point_are_known_in_the_note(locale):
    scene = graphplan.load_text(LEVER_RPP)
    scene = dataclasses.replace(scene, locale=locale, positions=dataclasses.replace(scene.positions, plans=(2, 8)))
    rows = {}
    for line in note_markdown(analyse(scene)).splitlines():
        for name in ("VFF4", "aFF4ᵏ", "aFF4ʳ"):
            if line.startswith(f"| {name} |"):
                rows.setdefault(name, []).append(line)
    assert all(len(found) == 2 for found in rows.values()) and len(rows) == 3, rows
    for index, phi in enumerate((40.0, 220.0)):
        omega4, speed, acceleration = _relative(math.radians(phi))
        assert "?" not in rows["aFF4ᵏ"][index] and "?" not in rows["aFF4ʳ"][index]
        assert _modulus(rows["VFF4"][index]) == pytest.approx(abs(speed), rel=2e-4)
        assert _modulus(rows["aFF4ᵏ"][index]) == pytest.approx(2 * abs(omega4 * speed), rel=2e-4)
        assert _modulus(rows["aFF4ʳ"][index]) == pytest.approx(abs(acceleration), rel=2e-4)
