"""Golden drawings: the plan sheets of two fixtures, compared after normalisation.

Normalisation keeps what a reader sees (element kinds, ids, texts, styles) and
rounds every number to 0.1 mm, so that a change in the last digits of the
arithmetic does not fail the test but a moved arrow or a lost label does.
After a deliberate change to the drawings, regenerate the golden files with
``GRAPHPLAN_REGENERATE_GOLDEN=1 python -m pytest tests/test_golden_drawings.py``
and look at the new PNGs before committing them.
"""

import os
import re
from pathlib import Path
from xml.etree import ElementTree

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render.drawings import plan_svg, positions_svg

GOLDEN = Path(__file__).parent / "golden"
NUMBER = re.compile(r"-?\d+\.\d+|-?\d+")

CASES = [("ratchet_crank_rocker", 5), ("engine_slider_crank", None)]


def normalised(svg: str) -> list[str]:
    root = ElementTree.fromstring(svg)
    lines = []
    for element in root.iter():
        tag = element.tag.split("}")[-1]
        attributes = " ".join(f"{key}={_round(value)}" for key, value in sorted(element.attrib.items()))
        text = (element.text or "").strip()
        lines.append(f"{tag} {attributes} {text}".strip())
    return lines


def _round(value: str) -> str:
    return NUMBER.sub(lambda m: f"{round(float(m.group()), 1) + 0.0:.1f}", value)


def drawings(name: str, number: int | None) -> dict[str, str]:
    analysis = analyse(graphplan.load(f"fixtures/{name}.toml"))
    plan = next(p for p in analysis.plans if number is None or p.number == number)
    return {f"{name}_positions.svg": positions_svg(analysis),
            f"{name}_plan_{plan.number}.svg": plan_svg(analysis, plan.index, plan.velocity, plan.acceleration)}


@pytest.mark.parametrize("name, number", CASES)
def test_drawings_match_their_golden_copies(name, number):
    for file, svg in drawings(name, number).items():
        golden = GOLDEN / file
        if os.environ.get("GRAPHPLAN_REGENERATE_GOLDEN"):
            golden.write_text(svg, encoding="utf-8")
        assert golden.exists(), f"no golden copy {golden}; regenerate it (see this module's docstring)"
        assert normalised(svg) == normalised(golden.read_text(encoding="utf-8")), file
