"""A teacher's close look at the dynamics drawings, read back off the SVG files a run writes.

- The load diagram's abscissa carries its unit as its ordinate does ("sB, m" beside "F, N"), in every language,
  in the words the note's table heads the same travel with.
"""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
COMPRESSOR = ROOT / "tests" / "scenes" / "compressor_indicator_diagram.toml"
SVG = "{http://www.w3.org/2000/svg}"


def _scene(locale: str, source: Path = COMPRESSOR) -> str:
    text = source.read_text(encoding="utf-8")
    return re.sub(r'(?m)^locale(\s*)=\s*"en"', f'locale\\1= "{locale}"', text, count=1)


def _run(tmp_path: Path, scene_text: str, pieces: str) -> Path:
    tmp_path.mkdir(parents=True, exist_ok=True)
    scene = tmp_path / "scene.toml"
    scene.write_text(scene_text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", pieces, "--sheet", "none"]) == 0
    return out


def _group(svg: Path, name: str) -> ElementTree.Element:
    root = ElementTree.parse(svg).getroot()
    found = next((group for group in root.iter(f"{SVG}g") if group.get("id") == name), None)
    assert found is not None, f"{svg.name} has no group {name}"
    return found


def _texts(group: ElementTree.Element) -> list[ElementTree.Element]:
    return list(group.iter(f"{SVG}text"))


@pytest.mark.parametrize(("locale", "metre"), [("en", "m"), ("ru", "м"), ("zh", "m")])
def test_the_load_diagrams_travel_axis_names_its_unit(tmp_path, locale, metre):
    out = _run(tmp_path, _scene(locale), "load_diagrams,note")
    labels = ["".join(text.itertext()) for text in _texts(_group(out / "load_diagrams.svg", "load-4-axes"))]
    # The ordinate as "F, N"; the abscissa, the piston's travel sB, likewise with its unit.
    assert any(re.fullmatch(r"F, [NН]", label) for label in labels), labels
    assert f"sB, {metre}" in labels, labels
    assert "sB" not in labels
    # The note's table heads the same travel in the same words.
    assert f"sB, {metre}" in (out / "note.md").read_text(encoding="utf-8")
