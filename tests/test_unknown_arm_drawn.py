"""An unknown reaction whose arm about the moment centre is no segment of the drawing (a class III triad's normal
reaction about Assur's point Σ) has its arm drawn as the knowns' are, lettered h: the caption gave ``h = 36.16 mm``
under ``R14n·h`` and the student found no h on the drawing to measure.  The arm drawn is checked against the
caption's length and against the unknown's arrow: square to its line, its foot on it."""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main

SVG = "{http://www.w3.org/2000/svg}"
PATH_POINT = re.compile(r"[ML](-?[\d.]+),(-?[\d.]+)")
ROOT = Path(__file__).resolve().parents[1]


def _paths(layer) -> list[list[complex]]:
    return [[complex(float(x), float(y)) for x, y in PATH_POINT.findall(path.get("d"))]
            for path in layer.iter(f"{SVG}path")]


def _arms_of_unknowns(svg: Path) -> list[tuple[str, float, list[list[complex]], list[list[complex]], set[str]]]:
    """For each group whose caption gives an unknown's arm h: the unknown, h (mm), its arrow's paths, the group's
    arm paths and the names lettered on the group."""
    root = ElementTree.parse(svg).getroot()
    layers = {layer.get("id"): layer for layer in root.iter(f"{SVG}g") if layer.get("id")}
    found = []
    for name, layer in layers.items():
        if not (name.startswith("body-") and name.endswith("-caption")):
            continue
        body = name.removesuffix("-caption")
        caption = " ".join("".join(text.itertext()) for text in layer.iter(f"{SVG}text"))
        given = re.search(r"h = ([\d.]+) mm", caption)
        if given is None:
            continue
        (unknown,) = set(re.findall(r"(R\d+[τn]?)·h\b", caption))
        arrow = layers[f"{body}-{unknown.replace('τ', 'tau')}"]
        lettered = {"".join(text.itertext()) for text in layers[f"{body}-labels"].iter(f"{SVG}text")}
        found.append((unknown, float(given[1]), _paths(arrow), _paths(layers[f"{body}-arms"]), lettered))
    return found


def _square_onto(arm: list[complex], start: complex, along: complex) -> bool:
    """Whether ``arm`` (centre to foot) ends on the line through ``start`` along the unit ``along``, square to it."""
    centre, foot = arm[0], arm[-1]
    off_line = abs(((foot - start) * along.conjugate()).imag)
    slant = abs(((foot - centre) / abs(foot - centre) * along.conjugate()).real)
    return off_line < 0.01 and slant < 1e-3


@pytest.mark.parametrize("fixture", ["triad_class_iii", "triad_with_slider"])
def test_the_unknown_s_arm_h_is_drawn_square_to_its_line_as_long_as_the_caption_gives_it(tmp_path, fixture):
    out = tmp_path / "out"
    assert main(["run", str(ROOT / "fixtures" / f"{fixture}.toml"), "--out", str(out), "--only", "forces",
                 "--sheet", "none"]) == 0
    checked = 0
    for svg in sorted(out.glob("forces_*.svg")):
        for unknown, h, arrow, arms, lettered in _arms_of_unknowns(svg):
            assert "h" in lettered, (svg.name, unknown)
            shaft = max(arrow, key=lambda path: abs(path[-1] - path[0]))   # along the unknown's line; its head beside
            start, end = shaft[0], shaft[-1]
            along = (end - start) / abs(end - start)

            drawn = [abs(arm[-1] - arm[0]) for arm in arms if len(arm) == 2 and _square_onto(arm, start, along)]
            assert any(abs(length - h) <= 5e-4 * h + 0.002 for length in drawn), (svg.name, unknown, h, drawn)
            checked += 1
    assert checked >= 2
