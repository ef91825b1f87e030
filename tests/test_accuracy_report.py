"""The accuracy study of one scene (graphplan.accuracy) and the report ``include = ["accuracy"]`` delivers.

The reference is the 50-digit mpmath solution of graphplan.reference, written apart from the solver.
What the errors must be comes from outside the code: the analytic solver and the exact construction
agree with the reference to a few units of double precision; a plan read with a ruler to d mm is off by
at most d/2 on every segment; chords through two neighbours converge as N⁻² (their leading error term
is h²/6 of the third derivative).
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import math
import statistics
import tomllib
from pathlib import Path

import pytest
from test_motion_against_finite_differences import CASES
from test_scene_errors import to_toml

import graphplan
from graphplan.accuracy import (
    DIAGRAM_REFINEMENTS,
    Row,
    diagram_refinements,
    drafting_precisions,
    draw_study,
    prepare,
    study,
)
from graphplan.analysis import analyse, instant
from graphplan.check import drafted, readings
from graphplan.cli import main
from graphplan.deliverables import chosen
from graphplan.output import WRITTEN
from graphplan.plans import acceleration_plan, velocity_plan

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"


# The slotted lever and the triad with a slot name a link's point under a block (A4, E8): it moves with its link,
# which the reference and the diagrams must know.
@pytest.fixture(scope="module", params=["ratchet_crank_rocker", "quick_return_slotted_lever", "slider_driven",
                                        "ratchet+triad-slot"])
def found(request):
    return study(CASES[request.param](), request.param)


def rows_of(found, method):
    return [row for row in found.rows if row.method == method]


def test_the_exact_methods_agree_with_the_50_digit_reference(found):
    for method in ("analytic", "construction"):
        (row,) = rows_of(found, method)
        for family in ("velocity", "acceleration"):
            assert row.stat(family, max) < 1e-12, (found.name, method, family)


def test_a_plan_read_to_d_mm_is_off_by_no_more_than_the_ruler_allows(found):
    """Each reading is off by at most d/2 on its segment; a quantity's error is divided by its largest length."""
    case = found.case
    longest: dict[str, float] = {}
    for plans, table in zip(case.plans, case.tables, strict=True):
        for reading in table:
            longest[reading.quantity] = max(longest.get(reading.quantity, 0.0), abs(reading.millimetres(plans)))
    drafting = {row.parameter: row for row in rows_of(found, "drafting")}
    assert set(drafting) == {"1 mm", "0.5 mm", "0.25 mm", "0.1 mm"}
    shortest_peak = min(length for length in longest.values() if length > 0)
    for parameter, row in drafting.items():
        precision = float(parameter.removesuffix(" mm"))
        # A sliding velocity or ω is read off one segment, a relative acceleration off two (normal and tangential).
        bound = 2 * (precision / 2) / shortest_peak
        assert 0 < row.stat("velocity", max) <= bound and row.stat("acceleration", max) <= bound, (parameter, row.errors)
    assert drafted(12.34, 0.5) == 12.5  # the ruler the rows were read with


def test_the_kinematic_diagrams_converge_as_n_to_the_minus_two(found):
    assert 1.8 < found.orders["velocity"] < 2.2
    assert 1.8 < found.orders["acceleration"] < 2.2
    diagrams = rows_of(found, "diagram")
    errors = [row.stat("acceleration", max) for row in diagrams]
    assert errors == sorted(errors, reverse=True)
    assert [row.positions for row in diagrams][:2] in ([12, 24], [12, 23])


def test_a_rocking_crank_s_diagrams_show_their_order_between_their_finest_grids():
    """The double rocker over its swing: a fit over all but the coarsest grid wrote the acceleration's order 1.74 beside
    «order 2»; between the finest two grids the error falls as N⁻², as chords through two neighbours do."""
    result = study(graphplan.load(FIXTURES / "double_rocker_swing.toml"), "double_rocker_swing")
    diagrams = sorted(rows_of(result, "diagram"), key=lambda row: row.positions)
    coarse, fine = diagrams[-2:]
    for family in ("velocity", "acceleration"):
        expected = math.log(coarse.stat(family, max) / fine.stat(family, max)) / math.log(fine.positions / coarse.positions)
        assert result.orders[family] == pytest.approx(expected, rel=1e-12)
        assert 1.9 < result.orders[family] < 2.1


def test_the_diagrams_put_a_node_on_every_position_whatever_their_count(tmp_path):
    """Nine positions a cycle: the grid is refined by whole nodes per interval, so each position is read exactly."""
    document = tomllib.loads((FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8"))
    document["positions"]["count"] = 9
    document["positions"]["plans"] = [2]
    document.pop("measured", None)
    scene = graphplan.scene.loads(to_toml(document))
    case = prepare(scene, "nine")
    assert diagram_refinements(case) == DIAGRAM_REFINEMENTS  # 9 × 300 = 2700 nodes at most
    result = study(scene, "nine")
    assert 1.8 < result.orders["acceleration"] < 2.2
    assert [row.positions for row in rows_of(result, "diagram")] == [9 * m for m in DIAGRAM_REFINEMENTS]


def test_accuracy_is_delivered_on_request_only(tmp_path):
    scene = graphplan.load(FIXTURES / "ratchet_crank_rocker.toml")
    assert "accuracy" not in chosen(scene, analyse(scene))
    out = tmp_path / "out"
    assert main(["run", str(FIXTURES / "ratchet_crank_rocker.toml"), "--out", str(out), "--only", "accuracy"]) == 0
    assert {p.name for p in out.iterdir()} - {WRITTEN} == {"results.json", "accuracy.md", "accuracy.tex", "accuracy.csv",
                                               "accuracy.svg"}
    table = list(csv.DictReader(io.StringIO((out / "accuracy.csv").read_text(encoding="utf-8"))))
    assert [row["method"] for row in table][:2] == ["analytic", "construction"]
    assert all(float(row["velocity_max"]) < 1e-12 for row in table[:2])
    # The scene reads its plans to 0.5 mm, one of the standard precisions: that row is marked as its own, not repeated.
    assert [(row["parameter"], row["scene_precision"]) for row in table if row["method"] == "drafting"] == [
        ("1 mm", "false"), ("0.5 mm", "true"), ("0.25 mm", "false"), ("0.1 mm", "false")]
    note = (out / "accuracy.md").read_text(encoding="utf-8")
    assert note.startswith("# Точность методов") and "чертёжной точностью 0,5 мм (как в исходных данных) |" in note  # ru
    latex = (out / "accuracy.tex").read_text(encoding="utf-8")
    rows = latex.split("\\endlastfoot\n")[1].split("\\end{longtable}")[0].strip().splitlines()
    assert len(rows) == len(table)
    for row, line in zip(table, rows):
        assert f"{float(row['acceleration_max']):.1e}".replace(".", ",") in note
        assert f"{float(row['acceleration_max']):.1e}".replace(".", ",") in line.split("&")[5]
    assert "<svg" in (out / "accuracy.svg").read_text(encoding="utf-8")


def test_include_accuracy_in_the_scene(tmp_path):
    document = tomllib.loads((FIXTURES / "slider_driven.toml").read_text(encoding="utf-8"))
    document["output"] = {"include": ["errors", "accuracy"]}
    path = tmp_path / "scene.toml"
    path.write_text(to_toml(document), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out)]) == 0
    assert {"accuracy.md", "accuracy.csv", "accuracy.svg", "errors.md"} <= {p.name for p in out.iterdir()}
    assert "plans read to 0.5 mm" in (out / "accuracy.md").read_text(encoding="utf-8")


def test_a_position_without_a_plan_is_left_out_and_named(tmp_path):
    """0.005° past the change point the analytic solution exists, but the plan's lines cross off the board."""
    text = (ROOT / "bench" / "extreme" / "change_point_at_toggle.toml").read_text(encoding="utf-8")
    path = tmp_path / "near_change_point.toml"
    path.write_text(text.replace("start = 30.0", "start = 0.005"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--only", "accuracy"]) == 0
    text = (out / "accuracy.md").read_text(encoding="utf-8")
    # Two positions left out: "positions", not the "position" it wrote for any number of them.
    assert "Left out" in text and "positions 1 (φ = 0.005°)" in text
    table = list(csv.DictReader(io.StringIO((out / "accuracy.csv").read_text(encoding="utf-8"))))
    assert all(math.isfinite(float(row["velocity_max"])) for row in table)
    # The methods are compared at the positions less those left out, and the report counts those (it said
    # "at the 12 positions" and gave 12 in each row while comparing at 10).
    # The parallelogram's links stand nearly in line at φ = 0.005° and 180.005°: those positions have no plan.
    values = analyse(graphplan.load(path)).positions.values
    in_line = sum(1 for value in values if abs(math.sin(float(value))) < 1e-3)
    assert in_line == next(line for line in text.splitlines() if line.startswith("Left out")).count("(φ =") == 2
    compared = len(values) - in_line
    assert f"at the {compared} positions" in text
    assert {row["positions"] for row in table if row["method"] != "diagram"} == {str(compared)}


def test_a_singular_position_has_no_accuracy_and_says_so(tmp_path, capsys):
    path = ROOT / "bench" / "extreme" / "dead_centre_slider.toml"
    scene = graphplan.load(path)
    singular = analyse(scene).motion.singular
    assert singular  # the slider-driven dyad passes its dead centre exactly at a position
    number = analyse(scene).positions.numbers[min(singular)]
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--only", "accuracy"]) == 2
    # After the scene's warnings (the singular position's among them), the error.
    error = capsys.readouterr().err.strip().splitlines()[-1]
    assert error.startswith("graphplan: error: --only[0]: 'accuracy' needs every position regular")
    assert f"position {number} is singular" in error
    assert not out.exists()


def test_the_english_report_reads_the_study(tmp_path):
    from graphplan.report.accuracy import markdown

    result = study(graphplan.load(FIXTURES / "slider_driven.toml"), "slider_driven")
    text = markdown(result, "en", "Lever")
    assert text.startswith("# ")
    assert f"{result.orders['acceleration']:.2f}" in text
    assert math.isfinite(result.orders["velocity"])


def test_the_scene_s_own_drafting_precision_has_its_row(tmp_path):
    """A scene read to 0.3 mm was shown the plans read to 1, 0.5, 0.25 and 0.1 mm only, never its own.

    Its row stands between 0.5 and 0.25 mm, marked as the scene's, and its errors are worked out here apart from
    the study: every segment of the plans constructed at the positions rounded to 0.3 mm, turned into its quantity by
    the plan's scale (and the link's length), against the analytic values results.json gives, each divided by the
    largest magnitude of its quantity over the positions.
    """
    document = tomllib.loads((FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8"))
    document["drawing"]["drafting_precision"] = 0.3
    document["scene"]["locale"] = "en"
    path = tmp_path / "scene.toml"
    path.write_text(to_toml(document), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--only", "accuracy"]) == 0
    table = list(csv.DictReader(io.StringIO((out / "accuracy.csv").read_text(encoding="utf-8"))))
    assert [(row["parameter"], row["scene_precision"]) for row in table if row["method"] == "drafting"] == [
        ("1 mm", "false"), ("0.5 mm", "false"), ("0.3 mm", "true"), ("0.25 mm", "false"), ("0.1 mm", "false")]
    assert all(row["scene_precision"] == "false" for row in table if row["method"] != "drafting")
    (own,) = [row for row in table if row["scene_precision"] == "true"]
    note = (out / "accuracy.md").read_text(encoding="utf-8")
    assert [line.split(" | ")[0] for line in note.splitlines() if "(as in the initial data)" in line] == [
        "| plans read to 0.3 mm (as in the initial data)"]

    scene = graphplan.load(path)
    motion = analyse(scene).motion
    mechanism = motion.mechanism
    exact = json.loads((out / "results.json").read_text(encoding="utf-8"))["positions"]
    assert len(exact) == int(own["positions"]) == 12  # no position is left out

    def analytic(reading, at):
        name, kind = reading.quantity, "v" if reading.plan == "velocity" else "a"
        assert reading.slide is None  # a four-bar: no sliding pair
        if name.startswith(("omega", "epsilon")):
            return at["links"][name.removeprefix("omega").removeprefix("epsilon")]["omega" if kind == "v" else "epsilon"]
        first, second = reading.points or (name[1:], None)
        vector = complex(*at["points"][first][kind]) - (complex(*at["points"][second][kind]) if second else 0)
        return abs(vector)

    pairs = []  # (quantity, drafted value, analytic value) at every position
    for index, at in enumerate(exact):
        where, directions = instant(motion, index)
        velocity = velocity_plan(mechanism, where, directions)
        plans = {"velocity": velocity, "acceleration": acceleration_plan(mechanism, where, directions, velocity)}
        for reading in readings(mechanism, plans, where):
            plan = plans[reading.plan]
            millimetres = abs(plan.mm(reading.segment[1]) - plan.mm(reading.segment[0]))
            ruled = round(millimetres / 0.3) * 0.3
            pairs.append((reading.quantity, reading.sign * ruled * plan.scale / reading.length, analytic(reading, at)))
    peak: dict[str, float] = {}
    for quantity, _, value in pairs:
        peak[quantity] = max(peak.get(quantity, 0.0), abs(value))
    assert min(peak.values()) > 0  # no quantity vanishes at every position
    errors: dict[str, list[float]] = {"velocity": [], "acceleration": []}
    for quantity, ruled, value in pairs:
        family = "velocity" if quantity.startswith(("V", "omega")) else "acceleration"
        errors[family].append(abs(ruled - value) / peak[quantity])
    for family in ("velocity", "acceleration"):
        assert float(own[f"{family}_max"]) == pytest.approx(max(errors[family]), rel=2e-4)
        assert float(own[f"{family}_median"]) == pytest.approx(statistics.median(errors[family]), rel=2e-4)
    # Between the standard precisions' errors: coarser than 0.25 mm, finer than 0.5 mm.
    largest = {row["parameter"]: float(row["acceleration_max"]) for row in table if row["method"] == "drafting"}
    assert largest["0.5 mm"] > largest["0.3 mm"] > largest["0.25 mm"]


@pytest.mark.parametrize("precision, expected", [
    (2.0, [(2.0, True), (1.0, False), (0.5, False), (0.25, False), (0.1, False)]),
    (0.25, [(1.0, False), (0.5, False), (0.25, True), (0.1, False)]),
    (0.05, [(1.0, False), (0.5, False), (0.25, False), (0.1, False), (0.05, True)]),
])
def test_the_scene_s_precision_takes_its_place_among_the_standard_ones_once(precision, expected):
    scene = graphplan.load(FIXTURES / "slider_driven.toml")
    scene = dataclasses.replace(scene, drawing=dataclasses.replace(scene.drawing, drafting_precision=precision))
    assert list(drafting_precisions(scene)) == expected


@pytest.mark.parametrize("own, tags", [
    ("0.3 mm", {"1 mm", "0.3 mm (initial data)", "0.1 mm"}),
    ("1 mm", {"1 mm (initial data)", "0.1 mm"}),  # a standard precision tagged already: one tag, the initial data's
])
def test_the_plot_rings_and_tags_the_scene_s_precision(own, tags):
    from matplotlib.figure import Figure

    parameters = ["1 mm", "0.5 mm", "0.3 mm", "0.1 mm"] if own == "0.3 mm" else ["1 mm", "0.5 mm", "0.1 mm"]
    rows = [Row("scene", "drafting", parameter, 12, 4e-3, {"velocity": [k * 1e-4], "acceleration": [k * 2e-4]},
                own=parameter == own) for k, parameter in enumerate(parameters, start=1)]
    axes = Figure().subplots()
    draw_study(axes, rows)
    assert {text.get_text() for text in axes.texts} == tags
    (tag,) = [text for text in axes.texts if "(initial data)" in text.get_text()]
    (mine,) = [row for row in rows if row.own]
    assert tag.xy == (4e-3, mine.stat("acceleration", max))
    (ring,) = [line for line in axes.lines if line.get_gid() == "own-precision"]
    assert (list(ring.get_xdata()), list(ring.get_ydata())) == ([4e-3], [mine.stat("acceleration", max)])
