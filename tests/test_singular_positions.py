"""A position where a group's lines of action are parallel is reported, not guessed, and the rest is drawn."""

import json
import math
import re

import pytest
from scene_texts import four_bar_through_a_toggle

import graphplan
from graphplan.cli import main
from graphplan.errors import SingularPositionError

# A four-bar whose coupler and rocker lie in one line at φ = 180° (|AC| = 0.2 + 1.0 = AB + BC = 1.2):
# at that position the velocity equations of group II(3,4) have no unique solution.
TOGGLE = four_bar_through_a_toggle() + """
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
    # The plans of that position too, with the error solve() raises (it was a SceneError naming positions).
    with pytest.raises(SingularPositionError, match=r"^singular position at position 7 \("):
        scene.plan(7)


# A slotted lever whose crank's circle runs through the lever's pivot C (OA = OC): at φ = 90° the block A lies
# on C and the group leaves the lever's direction free. Elsewhere CA is a chord of the crank's circle, so by
# the inscribed angle the lever turns at half the crank's speed, and the block slides at
# ṡ = d|CA|/dt = d(2·r·sin(θ/2))/dt with θ = φ − 90° measured from C: ṡ = r·ω·cos(θ/2)·sign(θ).
THROUGH_PIVOT = """
[scene]
title = "Slotted lever whose block passes over the lever's pivot"
[frame]
points = { O = [0.0, 0.0], C = [0.0, 0.1] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
[positions]
count = 12
start = 0.0
plans = [2]
"""


def test_a_block_over_the_lever_s_pivot_is_singular_not_a_lever_spinning_at_1e17(tmp_path):
    """Found by a user's own solver: A a rounding (6e-18 m) off C made the lever's direction noise, and results.json
    said ω4 = 10 and ε4 = 9e17 at position 4 with no warning."""
    scene = tmp_path / "lever.toml"
    scene.write_text(THROUGH_PIVOT, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "velocity"]) == 0
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    assert [(w["position"], w["code"]) for w in document["warnings"]] == [(4, "singular")]
    assert "A passes over C" in document["warnings"][0]["detail"]
    for position in document["positions"]:
        lever, slide = position["links"]["4"], position["slides"][0]
        if position["index"] == 4:
            assert lever["omega"] is None and lever["epsilon"] is None and slide["velocity"] is None
            continue
        theta = math.radians(position["driver"]["angle_deg"] - 90.0)
        theta = (theta + math.pi) % (2 * math.pi) - math.pi
        assert lever["omega"] == pytest.approx(5.0, rel=1e-12) and lever["epsilon"] == pytest.approx(0.0, abs=1e-9)
        expected = 0.1 * 10.0 * math.cos(theta / 2) * (1 if theta > 0 else -1)
        assert abs(slide["velocity"]) == pytest.approx(abs(expected), rel=1e-12)


def test_a_block_on_the_lever_s_pivot_at_the_first_position_is_refused_in_one_line(tmp_path, capsys):
    """At φ = 0 the block lay exactly on C; asking where the crank can reach then bisected an interval whose
    ends both assemble, and the run ended in scipy's traceback."""
    scene = tmp_path / "lever.toml"
    scene.write_text(THROUGH_PIVOT.replace("C = [0.0, 0.1]", "C = [0.1, 0.0]"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    error = capsys.readouterr().err.strip().splitlines()
    assert error == [("graphplan: error: singular position at the first position, 1 (φ = 0°) in group II(3,4): A "
                      "passes over C, so nothing fixes the direction of link 4; the first position fixes each group's "
                      "assembly and may not be singular: start the run elsewhere (positions.start)")]
    assert not (tmp_path / "out").exists()


# A piston A on the x axis drives crank CB through rod AB: at s = AC = AB − BC = 0.2 rod and crank lie in one line,
# the crank's dead centre, which a push along the line cannot turn it through. In binary 0.3 − 0.1 falls short of 0.2,
# so the triangle's squared height came out as rounding above zero.
PISTON_TO_DEAD_CENTRE = """
[frame]
points = { G = [0.0, 0.0], C = [0.4, 0.0] }
[driver]
kind = "slider"
link = 2
joint = "A"
guide = { through = "G", angle = 0.0 }
travel = [0.02, 0.2]
velocity = 0.5
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.3, 0.1]
assembly = "left"
[links.2]
mass = 0.0
[[loads]]
kind = "moment"
link = 4
value = 10.0
resisting = true
during = "always"
[positions]
count = 9
plans = [1]
"""


def _crank_speed(s: float, h: float = 1e-6) -> float:
    """ω4 = dθ/dt of crank CB by a central difference of its law-of-cosines angle, with ds/dt = 0.5 m/s."""
    def angle(x: float) -> float:
        span = 0.4 - x  # A = (x, 0), C = (0.4, 0)
        at_c = math.acos((0.1 ** 2 + span ** 2 - 0.3 ** 2) / (2 * 0.1 * span))
        return math.pi - at_c  # "left": B above the line A→C, CB measured from +x
    return 0.5 * (angle(s + h) - angle(s - h)) / (2 * h)


def test_a_travel_typed_to_end_at_the_crank_s_dead_centre_is_singular_there_and_nowhere_else(tmp_path):
    """The last position was solved from rounding: ω4 = −1.3e8 rad/s and Fb = 8e29 N in results.json, beside which
    every other position's whole-mechanism equilibrium was written as 0 (noise)."""
    scene = tmp_path / "piston.toml"
    scene.write_text(PISTON_TO_DEAD_CENTRE, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "forces"]) == 0
    document = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    assert [(w["position"], w["code"]) for w in document["warnings"]] == [(9, "singular")]
    *regular, last = document["positions"]
    assert last["links"]["4"]["omega"] is None and last["equilibrium"]["balancing_force"] is None
    for position in regular:
        s = position["driver"]["displacement"]
        omega = _crank_speed(s)
        assert position["links"]["4"]["omega"] == pytest.approx(omega, rel=1e-6)
        # Massless links: the piston's push does the moment's work, Fb·v = M·|ω4|.
        assert position["equilibrium"]["balancing_force"] == pytest.approx(10.0 * abs(omega) / 0.5, rel=1e-6)


@pytest.mark.parametrize(("travel", "ends"), [([-0.05, 0.2], (0.0, 0.2)), ([0.05, 0.35], (0.05, 0.2)),
                                             ([0.35, 0.05], (0.2, 0.05))])
def test_a_travel_past_the_reach_is_told_the_part_of_it_that_assembles(tmp_path, capsys, travel, ends):
    """The piston's rod AB = 0.3 and crank BC = 0.1 close on C = (0.4, 0) for 0.2 ≤ |A–C| ≤ 0.4, s = 0.4 − |A–C|:
    from s = 0 (stretched) to s = 0.2 (folded). The refusal named neither, where a swing's names its reach."""
    scene = tmp_path / "piston.toml"
    scene.write_text(PISTON_TO_DEAD_CENTRE.replace("travel = [0.02, 0.2]", f"travel = {travel}"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    told = capsys.readouterr().err
    first, last = (float(x) for x in re.search(r"assembles only from s = (-?[\d.]+) m to s = (-?[\d.]+) m", told).groups())
    assert (first, last) == pytest.approx(ends, abs=1e-6)
    assert not (tmp_path / "out").exists()
    # The travel it gives for an example runs: within those ends, short of a dead centre at its first end.
    example = re.search(r"e\.g\. driver\.travel = (\[[-\d., ]+\])", told).group(1)
    begin, end = json.loads(example)
    assert min(first, last) <= min(begin, end) < max(begin, end) <= max(first, last)
    assert (begin - end) * (travel[0] - travel[1]) > 0
    scene.write_text(PISTON_TO_DEAD_CENTRE.replace("travel = [0.02, 0.2]", f"travel = {example}"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "velocity"]) == 0


def test_a_travel_wholly_past_the_reach_is_told_where_the_mechanism_does_assemble(tmp_path, capsys):
    """Past C = (0.4, 0) the piston closes the triangle again for 0.2 ≤ |A–C| ≤ 0.4: s from 0.6 to 0.8 m. A travel
    typed from 1.0 to 1.2 m was told to check the lengths, which were right."""
    scene = tmp_path / "piston.toml"
    scene.write_text(PISTON_TO_DEAD_CENTRE.replace("travel = [0.02, 0.2]", "travel = [1.0, 1.2]"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    told = capsys.readouterr().err
    assert "nowhere along the travel typed" in told and "check the lengths" not in told
    begin, end = json.loads(re.search(r"e\.g\. driver\.travel = (\[[-\d., ]+\])", told).group(1))
    assert 0.6 < begin < end < 0.8
    scene.write_text(PISTON_TO_DEAD_CENTRE.replace("travel = [0.02, 0.2]", f"travel = [{begin}, {end}]"),
                     encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "velocity"]) == 0


def test_a_toggle_on_the_way_to_the_working_link_s_extremes_says_the_search_for_them_met_it(tmp_path, capsys):
    """A change-point four-bar (here the crank and frame as long as coupler and rocker together) given a working
    stroke was refused as "singular position at φ = 180°" alone, though the scene numbers its positions from 0°: the
    toggle was met seeking the rocker's extremes, and the message said neither that nor what to change."""
    scene = tmp_path / "toggle.toml"
    scene.write_text(four_bar_through_a_toggle() + """
[positions]
count = 12
start = 0.0
working = { link = 4, sense = "ccw" }
""", encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "singular position at φ = 180° in group II(3,4): links 3 and 4 lie in one line (a toggle)" in err
    assert "positions.working: link 4's extreme positions are sought over the crank's turn, which passes it" in err
    assert "leave positions.working out" in err
    without = scene.read_text(encoding="utf-8").replace('working = { link = 4, sense = "ccw" }\n', "")
    scene.write_text(without, encoding="utf-8")
    assert main(["check", str(scene)]) == 0  # the positions themselves pass the toggle with a warning
