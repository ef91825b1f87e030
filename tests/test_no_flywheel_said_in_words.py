"""Where the machine's own inertia does without a flywheel, the drawing and the note say so in words.

The energy–mass diagram read "ab = -107.9 mm" (with a hyphen for a minus) where its tangents cut the ΔT axis in
the other order, and the note printed a negative approximate flywheel with no word on it.  The compressor of
``test_compressor_motion_at_its_dead_centres`` is worked out here afresh: Je and Mr by its closed form, ΔT by
the trapezoid on 72 000 steps, the flywheel by the tangents of slopes ωm²·(1 ± δ/2)²/2.
"""

from __future__ import annotations

import functools
import math
import re
from xml.etree import ElementTree

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid
from test_compressor_motion_at_its_dead_centres import SCENE, inertia, resistance

from graphplan.cli import main

SVG = "{http://www.w3.org/2000/svg}"
DELTA = 0.2
HEAVY_CRANK = 0.5   # kg·m²: the crank's own inertia, for 0.02


def run(tmp_path, locale: str, rpm: float, crank: float = 0.02) -> tuple[ElementTree.Element, str, dict]:
    import json

    crank_link = '[links.2]\nmass = 5.0\ncentre = "O"\ninertia = '
    text = SCENE.replace("[scene]\n", f'[scene]\nlocale = "{locale}"\n', 1).replace(crank_link + "0.02",
                                                                                   crank_link + str(crank))
    assert f"inertia = {crank}" in text
    scene = tmp_path / f"compressor_{locale}_{rpm:g}.toml"
    scene.write_text(text + f"\n[dynamics]\ndelta = {DELTA}\nrpm = {rpm}\n", encoding="utf-8")
    out = tmp_path / f"out_{locale}_{rpm:g}"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]
    return ElementTree.parse(out / "dynamics.svg").getroot(), (out / "note.md").read_text(encoding="utf-8"), results


@pytest.fixture(scope="module")
def compressor(tmp_path_factory):
    """:func:`run`, each (locale, rpm, crank) run once for the module: the compressor's own at 500 rpm is read by
    three tests in each language, and was run by each."""

    @functools.cache
    def made(locale: str, rpm: float, crank: float = 0.02) -> tuple[ElementTree.Element, str, dict]:
        return run(tmp_path_factory.mktemp(f"compressor_{locale}"), locale, rpm, crank)

    return made


def texts_of(drawing: ElementTree.Element, layer: str) -> list[str]:
    group = next(g for g in drawing.iter(f"{SVG}g") if g.get("id") == layer)
    return ["".join(t.itertext()) for t in group.iter(f"{SVG}text")]


@functools.cache   # the same for every language: worked out once for each speed and crank
def flywheels(rpm: float, crank: float = 0.02) -> tuple[float, float, np.ndarray]:
    """The tangents' JF and the approximate ΔWmax/(ωm²·δ) − Je,mean, and Je over the turn."""
    travel = np.linspace(0.0, 2 * math.pi, 72_001)
    shaft = np.array([inertia(psi) for psi in travel]) + (crank - 0.02)
    resisting = np.array([resistance(psi) for psi in travel])
    energy = cumulative_trapezoid(np.mean(resisting[:-1]) - resisting, travel, initial=0.0)
    energy -= travel * energy[-1] / travel[-1]     # the constant driving moment balances the turn's work
    omega = rpm * math.pi / 30
    fastest, slowest = 0.5 * (omega * (1 + DELTA / 2)) ** 2, 0.5 * (omega * (1 - DELTA / 2)) ** 2
    tangents = (np.max(energy - fastest * shaft) - np.min(energy - slowest * shaft)) / (fastest - slowest)
    mean = float(np.trapezoid(shaft, travel)) / (2 * math.pi)
    return tangents, float(np.ptp(energy)) / (omega ** 2 * DELTA) - mean, shaft


@pytest.mark.parametrize(("locale", "axis"), [("en", "Je, kg·m²"), ("ru", "Jп, кг·м²"), ("zh", "Je, kg·m²")])
def test_the_energy_mass_diagrams_inertia_axis_carries_its_unit(compressor, locale, axis):
    drawing, _, _ = compressor(locale, 500.0)
    assert axis in texts_of(drawing, "energy-mass")


@pytest.mark.parametrize(("locale", "told"), [("en", "ab ≤ 0: no flywheel is needed"),
                                              ("ru", "ab ≤ 0: маховик не нужен"), ("zh", "ab ≤ 0：无需飞轮")])
def test_a_crank_heavy_enough_to_keep_delta_is_told_no_flywheel_is_needed_not_a_negative_ab(compressor, locale, told):
    drawing, _, results = compressor(locale, 500.0, HEAVY_CRANK)
    tangents, _, _ = flywheels(500.0, HEAVY_CRANK)
    assert tangents < 0 and results["flywheel_inertia_required"] == pytest.approx(tangents, rel=1e-4)
    words = texts_of(drawing, "energy-mass")
    assert told in words
    assert not [word for word in words if word.startswith("ab =")]
    # The compressor's own crank: a flywheel, ab a length.
    drawing, _, results = compressor(locale, 500.0)
    assert results["flywheel_inertia"] > 0
    assert [word for word in texts_of(drawing, "energy-mass") if re.fullmatch(r"ab = [\d.,]+ (mm|мм)", word)]


@pytest.mark.parametrize(("locale", "told"), [("en", "The approximate value is below nought"),
                                              ("ru", "Приближённое значение меньше нуля"), ("zh", "近似值小于零")])
def test_a_negative_approximate_flywheel_is_told_to_give_way_to_the_energy_mass_diagrams(compressor, locale, told):
    # At 1500 rpm the links' own inertia swings the energy more than the loads do: the approximate method, which
    # takes Je at its mean, asks for a negative flywheel; the tangents, with Je as it varies, for a positive one.
    _, note, results = compressor(locale, 1500.0)
    tangents, approximate, shaft = flywheels(1500.0)
    assert approximate < 0 < tangents
    assert results["flywheel_inertia_approximate"] == pytest.approx(approximate, rel=1e-3)
    assert results["flywheel_inertia"] == pytest.approx(tangents, rel=1e-3)
    paragraph = next(line for line in note.splitlines() if line.startswith(told))
    low, high, exact = (float(found.replace(",", ".")) for found in re.findall(r"\d+[.,]\d+", paragraph))
    # Je's extremes as the model's 1° samples reach them, and the tangents' flywheel.
    assert low == pytest.approx(float(np.min(shaft)), rel=1e-4)
    assert high == pytest.approx(float(np.max(shaft)), rel=1e-4)
    assert exact == pytest.approx(tangents, rel=1e-3)
    # The compressor's own speed, 500 rpm: the approximate flywheel is positive, and nothing is said.
    _, note, _ = compressor(locale, 500.0)
    assert told not in note
