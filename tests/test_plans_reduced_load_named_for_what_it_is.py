"""The reduced load read off the velocity plans is named for what it is, in the note and its docs.

A plan gives the power of the scene's loads and of the weights, never a side taken constant.  The note headed
that column Me and the docs called it the resisting moment; for an engine, whose gas force drives and whose
consumer is taken constant, it is the gas force's and the weights' reduced moment, which is neither (224.81 N·m
at 30°, where Me is 184.07 and Mr −41.30).  Checked against the slider-crank's closed form: the gas force by
its indicator diagram at the stroke's share, times the piston's speed ratio, and the weights' −m·g·dyS/dφ.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scene_texts import engine

from graphplan.cli import main

CRANK, ROD = 0.05, 0.19
CENTRE_2, CENTRE_3, MASS_2, MASS_3 = 0.006, 0.055, 4.5, 1.1
G = 9.81
EXPANSION = ([0.0, 0.1, 0.3, 0.6, 1.0], [9000.0, 7000.0, 4000.0, 2000.0, 800.0])
COMPRESSION = ([0.0, 0.5, 0.8, 1.0], [200.0, 500.0, 1200.0, 2500.0])


def engine_scene(locale: str) -> str:
    """The engine with a velocity plan at each of its 12 positions, its note in ``locale``."""
    return engine(locale) + """
[positions]
count = 12
start = "extreme"
working = { link = 4, sense = "backward" }
velocity_plans = "all"

[dynamics]
delta = 0.02
"""


def loads_moment(phi: float) -> float:
    """The gas force's and the weights' reduced moment at the crank angle φ (the crank turns ccw from 0°, the
    top dead centre: the piston goes back toward the crank, expanding, over the first half turn)."""
    def piston(angle):
        return CRANK * math.cos(angle) + math.sqrt(ROD ** 2 - (CRANK * math.sin(angle)) ** 2)

    def heights(angle):
        a = CRANK * math.sin(angle)
        return CENTRE_2 * math.sin(angle), a + CENTRE_3 * (0.0 - a) / ROD

    h = 1e-6
    speed = (piston(phi + h) - piston(phi - h)) / (2 * h)
    expanding = math.sin(phi) > 0
    share = (piston(0.0) - piston(phi)) / (2 * CRANK) if expanding else (piston(phi) - piston(math.pi)) / (2 * CRANK)
    force = np.interp(share, *(EXPANSION if expanding else COMPRESSION))
    ahead, behind = heights(phi + h), heights(phi - h)
    weights = -G * (MASS_2 * (ahead[0] - behind[0]) + MASS_3 * (ahead[1] - behind[1])) / (2 * h)
    return -force * speed + weights   # the force along −x: its power −F·vB


def note_of(tmp_path, locale: str) -> str:
    scene = tmp_path / f"engine_{locale}.toml"
    scene.write_text(engine_scene(locale), encoding="utf-8")
    out = tmp_path / locale
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    return (out / "note.md").read_text(encoding="utf-8")


@pytest.mark.parametrize(("locale", "symbol"), [("en", "Md + MG"), ("ru", "Mд + MG"), ("zh", "Md + MG")])
def test_an_engines_plans_give_the_gas_forces_and_the_weights_reduced_moment_and_the_note_says_so(tmp_path, locale,
                                                                                                   symbol):
    note = note_of(tmp_path, locale)
    # The dynamics' table of the plan positions: the initial data's table of masses, with its JS in kg·m², stands
    # before it.
    header = next(line for line in note.splitlines() if line.startswith("| ") and ("kg·m²" in line or "кг·м²" in line)
                  and f"| {symbol}, " in line)
    columns = [cell.strip() for cell in header.strip("|").split("|")]
    # Chinese sets its bracket full width beside its words, "Md + MG（解析值）".
    bracket = "（" if locale == "zh" else " ("
    assert columns[5].startswith(f"{symbol}, ") and columns[6].startswith(f"{symbol}{bracket}")
    assert "Me" not in header and "Mп" not in header
    # The sentence under the table says what the column is.
    assert note.split(header)[1].split("\n\n")[1].startswith(f"{symbol} ")
    rows = [line for line in note.split(header)[1].splitlines()[2:] if line.startswith("| ")]
    assert len(rows) == 12
    for row in rows:
        cells = [cell.strip() for cell in row.strip("|").split("|")]
        phi = math.radians(float(cells[1].replace(",", ".")))
        analytic = float(cells[6].replace("−", "-").replace(",", "."))
        assert analytic == pytest.approx(loads_moment(phi), rel=5e-5, abs=1e-3), cells[0]


def test_the_docs_say_what_the_plans_reduced_moment_is():
    from pathlib import Path

    docs = (Path(__file__).resolve().parent.parent / "docs" / "scene-format-extensions.md").read_text(encoding="utf-8")
    row = next(line for line in docs.splitlines() if line.startswith("| `dynamics` |"))
    assert "the position's `resisting_moment`, since the driving moment is not read off a plan" not in row
    assert re.search(r"where it is `\"resisting\"` \(an engine's gas force driving\) the driving loads' and the "
                     r"weights'", row)
