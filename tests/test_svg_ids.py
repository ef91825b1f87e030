"""Every id of every SVG a run writes is unique, whatever script the scene's point names are in.

Ids came from names with every character but ASCII letters and digits turned into ``_``: the Cyrillic points
А and В of a Russian scene both gave ``mechanism-v-_`` and ``velocity-p-_``.
"""

from __future__ import annotations

import collections
import re
from xml.etree import ElementTree

import pytest

from graphplan.cli import main
from graphplan.render.primitives import svg_id
from graphplan.starters import starter

CYRILLIC = {"O": "О", "A": "А", "B": "В", "C": "С"}


def crank_rocker_in_cyrillic() -> str:
    """The crank-rocker starter with its points O, A, B, C named by the Cyrillic letters that look the same."""
    text = starter("crank-rocker")
    text = re.sub(r'"([OABC])"', lambda found: f'"{CYRILLIC[found.group(1)]}"', text)
    text = text.replace("{ O = [", '{ "О" = [').replace(", C = [", ', "С" = [')
    assert '"О" = [' in text and '"С" = [' in text and 'joint   = "А"' in text
    return text


def test_names_in_any_script_give_ids_of_their_own():
    assert svg_id("velocity", "p", "b") == "velocity-p-b"  # ASCII letters as they were
    assert svg_id("polygon-II-3-4", "R23τ") == "polygon-II-3-4-R23tau"
    ids = {svg_id("velocity", "p", name) for name in ("а", "в", "a", "b", "с", "c")}
    assert len(ids) == 6 and "velocity-p-а" in ids
    assert svg_id("M", "a−b") != svg_id("M", "a+b")


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_every_id_of_every_svg_written_is_unique_with_cyrillic_point_names(locale, tmp_path):
    scene = tmp_path / "cyrillic.toml"
    scene.write_text(crank_rocker_in_cyrillic(), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--locale", locale]) == 0
    drawings = sorted(out.glob("*.svg"))
    assert {"plan_5.svg", "forces_5.svg", "sheet_1.svg"} <= {path.name for path in drawings}
    for path in drawings:
        ids = [element.get("id") for element in ElementTree.parse(path).getroot().iter() if element.get("id")]
        clashing = [found for found, count in collections.Counter(ids).items() if count > 1]
        assert not clashing, (path.name, clashing[:5])
