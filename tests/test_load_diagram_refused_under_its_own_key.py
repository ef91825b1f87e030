"""A load `diagram` that the mechanism cannot read is refused under `loads[N].diagram`, the key the scene wrote.

The diagram sets the load's window of the working stroke itself, (first share, last share). Where that window
was refused (a slider driver's travel or a rocking crank's swing is run once, with no working stroke to take
shares of; a scene without `positions.working`), the error named `loads[0].during`, which the scene never
wrote, and showed `{ from = 0.0, to = 1.0 }`, which it never typed. The way out each refusal gives is taken
here, and the scene then builds.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from graphplan.errors import SceneError
from graphplan.mechanism import build
from graphplan.scene import loads

ROOT = Path(__file__).resolve().parent.parent
SLIDER = ROOT / "fixtures" / "slider_driven.toml"
SWING = ROOT / "fixtures" / "double_rocker_swing.toml"
CRANK_ROCKER = ROOT / "graphplan" / "templates" / "crank-rocker.toml"
DIAGRAM = "diagram   = [[0.0, 100.0], [0.5, 300.0], [1.0, 100.0]]\n"


def _with_diagram(path: Path, value: str, during: str) -> str:
    text = path.read_text(encoding="utf-8")
    given = f"{value}resisting = true\n{during}"
    assert given in text
    return text.replace(given, f"resisting = true\n{DIAGRAM}")


def _refusal(text: str) -> SceneError:
    with pytest.raises(SceneError) as refused:
        build(loads(text))
    return refused.value


@pytest.mark.parametrize("path,value,during,run", [
    (SLIDER, "value     = 150.0        # N·m\n", 'during    = "working"\n', "driver.travel"),
    (SWING, "value     = 20.0            # N·m\n", 'during    = "always"\n', "driver.swing"),
], ids=["slider-travel", "rocking-crank-swing"])
def test_a_diagram_over_a_run_made_once_is_refused_as_a_diagram(path, value, during, run):
    text = _with_diagram(path, value, during)
    if path == SWING:   # a stroke to read the diagram along, so that only the swing is in the way
        text = text.replace("[positions]\n", '[positions]\nworking = { link = 4, sense = "ccw" }\n')
    refused = _refusal(text)
    assert refused.where == "loads[0].diagram"
    assert run in str(refused) and "during" in str(refused) and "{ from" not in str(refused)
    # The way out it gives: a value, in the working stroke.
    build(loads(text.replace(DIAGRAM, f'{value}during    = "working"\n')))


def test_a_diagram_without_a_working_stroke_is_refused_as_a_diagram():
    text = CRANK_ROCKER.read_text(encoding="utf-8")
    load_lines = [line for line in text.splitlines() if line.startswith(("value     = 1500", "during    ="))]
    assert len(load_lines) == 2
    text = text.replace(load_lines[0] + "\n", "").replace(load_lines[1], DIAGRAM.strip())
    working = [line for line in text.splitlines() if line.startswith("working ")]
    start = [line for line in text.splitlines() if line.startswith("start ")]
    unworked = text.replace(working[0], "").replace(start[0], "start = 0.0")
    refused = _refusal(unworked)
    assert refused.where == "loads[0].diagram"
    assert "positions.working" in str(refused) and "{ from" not in str(refused)
    build(loads(unworked.replace("[positions]\n", f"[positions]\n{working[0]}\n")))
