"""A position where a group's lines of action are parallel is reported, not guessed, and the rest is drawn."""

import json

import pytest

import graphplan
from graphplan.cli import main
from graphplan.errors import SingularPositionError

# A four-bar whose coupler and rocker lie in one line at φ = 180° (|AC| = 0.2 + 1.0 = AB + BC = 1.2):
# at that position the velocity equations of group II(3,4) have no unique solution.
TOGGLE = """
[scene]
title = "Four-bar through a toggle"
[frame]
points = { O = [0.0, 0.0], C = [1.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.2
omega = 10.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.5, 0.7]
assembly = "left"
[positions]
count = 12
plans = [2, 7]
"""


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("toggle")
    scene = folder / "toggle.toml"
    scene.write_text(TOGGLE, encoding="utf-8")
    status = main(["run", str(scene), "--out", str(folder / "out")])
    return status, folder / "out"


def test_the_run_succeeds_and_draws_the_other_plan(run):
    status, out = run
    assert status == 0
    assert (out / "plan_2.svg").exists()
    assert not (out / "plan_7.svg").exists()


def test_the_singular_position_is_reported_with_its_reason(run):
    _, out = run
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))
    singular = [w for w in document["warnings"] if w["code"] == "singular"]
    assert [w["position"] for w in singular] == [7]
    assert "links 3 and 4 lie in one line (a toggle)" in singular[0]["detail"]
    assert "φ = 180°" in singular[0]["detail"]


def test_nothing_undetermined_is_written_as_a_number(run):
    _, out = run
    text = (out / "results.json").read_text(encoding="utf-8")
    assert "NaN" not in text and "Infinity" not in text
    seventh = json.loads(text)["positions"][6]
    assert seventh["index"] == 7
    assert seventh["points"]["B"]["v"] is None and seventh["links"]["4"]["omega"] is None
    # The position itself is determined: B lies on the line A–C, 0.5 m from A.
    assert seventh["points"]["B"]["r"] == pytest.approx([0.3, 0.0], abs=1e-12)
    # The driver's own motion is known everywhere.
    assert seventh["links"]["2"]["omega"] == 10.0
    assert json.loads(text)["positions"][1]["points"]["B"]["v"] is not None


def test_the_python_interface_still_refuses_to_guess():
    scene = graphplan.scene.loads(TOGGLE)
    with pytest.raises(SingularPositionError, match="position 7"):
        graphplan.solve(scene)
