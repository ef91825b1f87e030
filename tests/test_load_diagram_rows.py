"""A load diagram's legend points the reader at the row of position numbers its stroke's positions stand in.

The engine's gas force acts on the piston's "backward" stroke (toward the crank), which the diagram's travel
counts from top dead centre, so that stroke's positions run → along the abscissa: a legend saying only "backward
stroke" sent the reader to the ← row.  Which positions the piston travels toward the crank from is found here in
closed form, x = r·cos φ + √(l² − r²·sin² φ), apart from graphplan's own strokes.
"""

from __future__ import annotations

import functools
import math
import tomllib
from pathlib import Path

import pytest

import graphplan
from graphplan.load_diagrams import of_analysis
from graphplan.locale import strings
from graphplan.render import load_diagrams as layout
from graphplan.render.primitives import Arrow, Text

ENGINE = Path(__file__).parent.parent / "fixtures" / "engine_slider_crank.toml"


@functools.cache
def engine():
    return graphplan.load(ENGINE).analyse()


def _piston_x(phi: float) -> float:
    tables = tomllib.loads(ENGINE.read_text(encoding="utf-8"))
    r, l = tables["driver"]["length"], tables["groups"][0]["length"]
    return r * math.cos(phi) + math.sqrt(l**2 - (r * math.sin(phi)) ** 2)


def _rows(items) -> dict[str, set[int]]:
    """The position numbers of each row under the diagram, by the row's arrow (→ or ←)."""
    arrows = {item.start[1]: ("→" if item.end[0] > item.start[0] else "←")
              for item in items if isinstance(item, Arrow) and item.start[0] < 0}
    assert sorted(arrows.values()) == ["←", "→"]
    rows: dict[str, set[int]] = {"→": set(), "←": set()}
    for item in items:
        # Centred on their ticks: the ordinate's numbers, lettered as high, stand at its left.
        if isinstance(item, Text) and item.size == layout.NUMBER_SIZE and item.text.isdigit() and item.anchor == "middle":
            nearest = min(arrows, key=lambda y: abs(y - item.at[1]))
            rows[arrows[nearest]].add(int(item.text))
    return rows


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_legend_names_the_row_of_the_positions_the_gas_force_acts_in(locale):
    analysis = engine()
    (diagram,) = of_analysis(analysis)
    items = [item for layer in layout.layout([diagram], strings(locale)) for item in layer.items]
    (legend,) = [item.text for item in items if isinstance(item, Text) and item.text.startswith(("F4:", "F4："))]
    (arrow,) = [glyph for glyph in "→←" if glyph in legend]
    # The positions from which the crank's next small turn (it turns ccw) brings the piston nearer the crank:
    # at top dead centre the expansion stroke is about to begin, so position 0 is one of them.
    toward_crank = {int(number) for number, phi in zip(analysis.positions.numbers, analysis.positions.values)
                    if _piston_x(phi + 1e-6) < _piston_x(phi)}
    assert 0 in toward_crank and len(toward_crank) == 6
    assert _rows(items)[arrow] == toward_crank
