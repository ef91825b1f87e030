"""What a student's first course projects, a jaw crusher's six-bar and a knee-lever press, showed on their sheets.

The kinematic diagrams of a rocker output are of its angle ψ, its ω and its ε: their scales are μψ, μω = μψ/(μt·H₁)
and με = μω/(μt·H₂), as the textbooks write them and as the load diagram beside them already writes μψ, not the
slider's μs, μv, μa with a unit in radians.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

import graphplan
from graphplan.kinematic_diagrams import kinematic_diagrams
from graphplan.locale import strings
from graphplan.mechanism import build
from graphplan.positions import make_positions
from graphplan.render import diagrams
from graphplan.scene import loads

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
NUMBER = r"([0-9]+(?:[.,][0-9]+)?)"


def _number(pattern: str, text: str) -> float:
    found = re.search(pattern, text)
    assert found is not None, pattern
    return float(found.group(1).replace(",", "."))


def _record(name: str):
    mechanism = build(loads((FIXTURES / f"{name}.toml").read_text(encoding="utf-8")))
    return kinematic_diagrams(mechanism, make_positions(mechanism))


def _rocker_diagrams(locale: str = "en"):
    record = _record("ratchet_crank_rocker")
    return record, diagrams.diagrams_svg(record, strings(locale))


def test_a_rocker_s_diagrams_state_the_scales_of_its_angle_omega_and_epsilon():
    record, svg = _rocker_diagrams()
    assert not record.translating
    assert "μs =" not in svg and "μv =" not in svg and "μa =" not in svg
    mu_psi = _number(r"μψ = " + NUMBER + r" rad/mm", svg)
    mu_omega = _number(r"μω = μψ/\(μt·H₁\) = " + NUMBER, svg)
    mu_eps = _number(r"με = μω/\(μt·H₂\) = " + NUMBER, svg)
    h1 = _number(r"H₁ = " + NUMBER + " mm", svg)
    h2 = _number(r"H₂ = " + NUMBER + " mm", svg)
    # μt from the φ axis the sheet states: a turn over L mm at the crank's |ω|, not the program's own μt.
    length = _number(r"L = " + NUMBER + " mm", svg)
    omega = abs(graphplan.load(FIXTURES / "ratchet_crank_rocker.toml").driver.omega)
    mu_t = 2.0 * math.pi / length / omega
    assert math.isclose(mu_omega, mu_psi / (mu_t * h1), rel_tol=5e-3)
    assert math.isclose(mu_eps, mu_omega / (mu_t * h2), rel_tol=5e-3)
    # The ψ ordinates are the rocker's swing at μψ: its unwrapped angle's span over the turn.
    motion = graphplan.solve(graphplan.load(FIXTURES / "ratchet_crank_rocker.toml"),
                             driver=np.radians(np.arange(0.0, 360.0, 0.1)))
    swing = np.ptp(np.unwrap(motion.link(4).angle))
    assert math.isclose(np.ptp(record.s), swing, rel_tol=1e-3)


def test_a_slider_s_diagrams_keep_mu_s_mu_v_mu_a():
    record = _record("engine_slider_crank")
    svg = diagrams.diagrams_svg(record)
    assert record.translating
    assert "μs = " in svg and "μv = μs/(μt·H₁)" in svg and "μa = μv/(μt·H₂)" in svg
    assert "μψ" not in svg


def test_the_russian_and_chinese_rocker_diagrams_write_mu_psi_too():
    for locale in ("ru", "zh"):
        _, svg = _rocker_diagrams(locale)
        assert "μψ = " in svg and "μω = μψ/(μt·H₁)" in svg and "με = μω/(μt·H₂)" in svg
