"""The Python interface as a notebook uses it: what it hands out, and how it says it was misused.

A researcher's review (solving every fixture from scripts against a loop-closure solver of her own)
found the numbers right and these faults: a change-point linkage changing its assembly between two
angles with no warning where the command line warned; arrays that were views of the motion's own,
so that ``B -= B[0]`` changed the motion; misuse passed on to numpy's errors or taken silently.
"""

from __future__ import annotations

import dataclasses
import math
import re
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.errors import SceneError

RATCHET = "fixtures/ratchet_crank_rocker.toml"

# A change-point four-bar (Grashof's equality: 0.5 + 1 = 1 + 0.5): a parallelogram from φ = 0° to 180°, where
# the coupler and the rocker come in line with the frame, and the closed form's "left" assembly an
# anti-parallelogram beyond.
CHANGE_POINT = """
[scene]
title = "change-point four-bar"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [1.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.5
omega = 10.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [1.0, 0.5]
assembly = "left"
"""


@pytest.fixture(scope="module")
def change_point():
    return graphplan.scene.loads(CHANGE_POINT, source="change-point")


def coupler(motion, index: int) -> np.ndarray:
    return motion.point("B").r[index] - motion.point("A").r[index]


def test_a_toggle_between_two_angles_asked_for_is_warned_of_as_the_command_line_does(change_point):
    angles = np.radians([30.0, 120.0, 210.0, 300.0])
    motion = graphplan.solve(change_point, driver=angles)
    # The positions themselves show the change: the coupler parallel to the frame (a parallelogram) at 120°, not
    # at 210°, where a parallelogram would have it parallel again.
    assert coupler(motion, 1) == pytest.approx([1.0, 0.0], abs=1e-12)
    assert abs(coupler(motion, 2)[1]) > 0.1
    stepped = [w for w in motion.warnings if w.code == "toggle-between"]
    assert [(w.position, "φ = 180°" in w.detail) for w in stepped] == [(1, True)]
    # In any order: the warning stays with the position before the toggle in driver order.
    shuffled = graphplan.solve(change_point, driver=angles[[3, 0, 2, 1]])
    assert [w.position for w in shuffled.warnings if w.code == "toggle-between"] == [3]
    # Both angles on one side of the toggles: nothing to warn of.
    assert not graphplan.solve(change_point, driver=np.radians([30.0, 60.0])).warnings


def test_a_crank_s_values_many_turns_apart_are_taken_by_their_place_in_the_turn(change_point):
    """[0.5, 0.5 + 1e7] rad were swept turn by turn for the toggles between them, 360 samples a turn: 1e5 rad took
    2.9 GB and 1e7 rad raised numpy's MemoryError. The change point's toggles are at 0° and 180° every turn."""
    values = np.array([0.5, 0.5 + 1e7, 2.0 + 2 * np.pi * 300])
    motion = graphplan.solve(change_point, driver=values)
    places = np.mod(values, 2 * np.pi)
    order = np.argsort(places)
    expected = set()
    for here, following in zip(order, np.roll(order, -1), strict=True):
        low, high = places[here], places[following] + (2 * np.pi if places[following] <= places[here] else 0.0)
        if any(low < toggle < high for toggle in (np.pi, 2 * np.pi, 3 * np.pi)):
            expected.add(int(here))
    assert expected  # the check can fail
    assert {w.position for w in motion.warnings if w.code == "toggle-between"} == expected
    # 99 turns apart: each toggle of the turn once (it was warned of at every turn passed, 198 times).
    stepped = [w for w in graphplan.solve(change_point, driver=[0.5, 0.5 + 2 * np.pi * 99]).warnings
               if w.code == "toggle-between"]
    assert len(stepped) == len({w.detail for w in stepped}) <= 2


def test_the_arrays_handed_out_are_read_only_and_the_driver_a_copy():
    scene = graphplan.load(RATCHET)
    angles = np.radians([0.0, 10.0, 20.0])
    motion = graphplan.solve(scene, driver=angles)
    before = motion.point("B").r.copy()
    b = motion.point("B").r
    with pytest.raises(ValueError, match="read-only"):
        b -= b[0]
    with pytest.raises(ValueError, match="read-only"):
        motion.link(4).omega[0] = 0.0
    angles[0] = 5.0
    assert motion.driver[0] == 0.0
    assert np.array_equal(motion.point("B").r, before)
    moved = motion.point("B").r.copy()
    moved -= moved[0]  # a copy is the caller's own
    assert np.array_equal(motion.point("B").r, before)


def test_the_motion_s_own_tables_and_the_scene_s_readings_cannot_be_written_through():
    """motion.points["B"].v[0] = … changed what point("B") gave after; a slide's s written left its slider where
    it was; scene.measured[5]["velocity"]["pb"] = … changed what plan(5) read."""
    motion = graphplan.solve(graphplan.load(Path(RATCHET).with_name("engine_slider_crank.toml")))
    with pytest.raises(ValueError, match="read-only"):
        motion.points["B"].v[0] = 123.0
    with pytest.raises(ValueError, match="read-only"):
        motion.slides[0].s[0] = 99.0
    with pytest.raises(TypeError):
        motion.points["Z"] = motion.points["B"]
    with pytest.raises(ValueError, match="read-only"):
        motion.at_positions([0, 1]).links[3].omega[0] = 0.0
    measured = graphplan.load_text(Path(RATCHET).read_text(encoding="utf-8")
                                   + "\n[measured.11]\nvelocity = { pb = 42.0 }\n").measured
    with pytest.raises(TypeError):
        measured[11]["velocity"]["pb"] = 1.0


def test_scenes_and_motions_survive_pickle_and_deepcopy_as_they_were():
    """A process pool's parameter sweep sends its scenes to the workers: pickle refused their read-only tables."""
    import copy
    import pickle

    scene = graphplan.load_text(Path(RATCHET).read_text(encoding="utf-8") + "\n[measured.11]\nvelocity = { pb = 42.0 }\n")
    motion = graphplan.solve(scene)
    for clone in (pickle.loads(pickle.dumps(scene)), copy.deepcopy(scene)):
        assert clone == scene and clone is not scene
        np.testing.assert_array_equal(graphplan.solve(clone).point("B").a, motion.point("B").a)
    for clone in (pickle.loads(pickle.dumps(motion)), copy.deepcopy(motion)):
        np.testing.assert_array_equal(clone.link(4).epsilon, motion.link(4).epsilon)
        with pytest.raises(ValueError, match="read-only"):
            clone.points["B"].v[0] = 0.0


def test_a_value_the_mechanism_cannot_reach_is_named_by_its_index_with_the_crank_s_reach():
    """−1e-9 rad was told as «φ = 360°», a value the caller never gave, without the reach the run tells."""
    scene = graphplan.load(Path(RATCHET).with_name("double_rocker_swing.toml"))
    with pytest.raises(graphplan.AssemblyError) as raised:
        graphplan.solve(scene, driver=[0.5, 0.6, -1e-9])
    message = str(raised.value)
    assert "(driver[2])" in message
    # The crank OA = 0.25 about O, C 0.3 m away: A–C runs from |AB − BC| = 0.08 m up, reached where
    # 0.25² + 0.3² − 2·0.25·0.3·cos φ = 0.08².
    lowest = math.degrees(math.acos((0.25 ** 2 + 0.3 ** 2 - 0.08 ** 2) / (2 * 0.25 * 0.3)))
    ends = [float(value) for value in re.findall(r"from (\d+\.\d+)° to (\d+\.\d+)°", message)[0]]
    assert ends[0] == pytest.approx(lowest, abs=0.01)


def test_a_table_of_readings_with_none_in_it_is_refused():
    with pytest.raises(SceneError, match=r"^measured\.11\.velocity: has no readings"):
        graphplan.load_text(Path(RATCHET).read_text(encoding="utf-8") + "\n[measured.11]\nvelocity = { }\n")


@pytest.mark.parametrize("driver", [[1 + 1j], ["1", "2"], [True, False], np.array([0.1, "x"], dtype=object)])
def test_a_driver_that_is_not_plain_numbers_is_refused(driver):
    with pytest.raises(SceneError, match=r"^driver: must be an array of numbers .* \(got "):
        graphplan.solve(graphplan.load(RATCHET), driver=driver)


def test_solve_given_a_path_says_it_takes_a_scene():
    with pytest.raises(TypeError, match=r"solve takes a scene, as graphplan.load\(path\) reads it \(got 'fix"):
        graphplan.solve(RATCHET, driver=[0.0])
    with pytest.raises(TypeError, match=rf"; read it first: graphplan\.load\('{RATCHET}'\)$"):
        graphplan.solve(RATCHET, driver=[0.0])


VERBS = ["solve", "analyse", "machine_dynamics", "balance", "vibration_response", "results", "drawings"]


@pytest.mark.parametrize("verb", VERBS)
def test_a_scenes_method_called_on_its_path_says_to_read_the_scene_first(verb):
    # Scene.analyse("x.toml") was told that a string has no has_linkage.
    with pytest.raises(TypeError) as raised:
        getattr(graphplan.Scene, verb)(RATCHET)
    assert str(raised.value) == (f"Scene.{verb} takes a scene, as graphplan.load(path) reads it (got {RATCHET!r}); "
                                 f"read it first: graphplan.load({RATCHET!r})")


def test_a_scenes_method_with_arguments_called_on_no_scene_says_so():
    with pytest.raises(TypeError, match=r"^Scene\.plan takes a scene, .*; read it first: graphplan\.load\('fixtures/"):
        graphplan.Scene.plan(Path(RATCHET), 3)
    with pytest.raises(TypeError, match=r"^Scene\.write takes a scene, as graphplan\.load\(path\) reads it \(got 3\)$"):
        graphplan.Scene.write(3, "out")


def test_positions_picked_by_index_must_be_indices_of_the_motion():
    motion = graphplan.solve(graphplan.load(RATCHET), driver=np.radians([0.0, 10.0, 20.0]))
    with pytest.raises(TypeError, match="list of integers"):
        motion.at_positions([0.5])
    with pytest.raises(IndexError, match="has 3 positions, indices 0 to 2"):
        motion.at_positions([5])
    assert motion.at_positions([-1]).driver == pytest.approx([np.radians(20.0)])


def test_a_plan_is_named_by_numpy_s_integers_too_and_prints_in_a_line():
    scene = graphplan.load(RATCHET)
    five = scene.plan(np.int64(5))
    assert five.number == 5
    assert repr(five) == "<PositionPlans of position 5 of 'Crank-rocker of a ratchet feed'>"


def test_a_scene_given_as_text_is_read_by_load_text_and_load_says_so_instead_of_quoting_it_as_a_path():
    text = Path(RATCHET).read_text(encoding="utf-8")
    for wrong in (text, text.encode()):
        with pytest.raises(SceneError) as raised:
            graphplan.load(wrong)
        assert str(raised.value) == ("load takes the path of a scene file; for a scene given as TOML text use "
                                     "graphplan.load_text(text)")
    from_text, from_file = graphplan.load_text(text), graphplan.load(RATCHET)
    assert (from_text.title, from_text.driver, from_text.groups) == (from_file.title, from_file.driver, from_file.groups)


def test_the_driver_and_a_slides_arrays_cannot_be_written_either():
    """point() and link() hand out read-only views; motion.driver and slide(n)'s arrays could be written, and the
    write changed the motion's own data."""
    motion = graphplan.solve(graphplan.load("fixtures/shaper_six_bar.toml"), driver=[0.1, 0.2])
    slide = motion.slide(motion.slides[0].slider)
    for array in (motion.driver, slide.s, slide.velocity, slide.acceleration):
        with pytest.raises(ValueError, match="read-only"):
            array[...] = 0.0
    assert motion.driver.tolist() == [0.1, 0.2]


def test_a_coupler_short_of_its_reach_by_a_hair_is_told_with_the_digits_that_show_it():
    """With the crank pointing away from C, A–C = OC + OA = 0.725 m; BC 0.1 µm short of closing the gap was
    told "A–C = 0.725 m > AB + BC = 0.725 m"."""
    scene = graphplan.load(RATCHET)
    ab, _ = scene.groups[0].lengths
    short = dataclasses.replace(scene, groups=(dataclasses.replace(scene.groups[0], lengths=(ab, 0.725 - ab - 1e-7)),))
    with pytest.raises(graphplan.AssemblyError) as raised:
        graphplan.solve(short, driver=[-math.pi / 2])   # A straight below O, C straight above it
    far, reach = re.search(r"A–C = ([\d.]+) m > AB \+ BC = ([\d.]+) m", str(raised.value)).groups()
    assert float(far) == pytest.approx(0.725, abs=1e-12) and float(reach) < float(far)


def test_what_a_notebook_prints_of_a_motion_an_analysis_or_a_drawing_is_a_line():
    """Their reprs ran to 8 600, 386 000 and 25 000 characters (the scene, every array, the whole SVG)."""
    scene = graphplan.load(RATCHET)
    motion, analysis, drawing = scene.solve(), scene.analyse(), scene.plan(5).drawing
    for shown in (repr(motion), repr(analysis), repr(drawing)):
        assert len(shown) < 200 and "\n" not in shown, shown
    assert scene.title in repr(motion) and f"at {motion.count} positions" in repr(motion)
    assert f"{len(drawing.svg)} characters of SVG" in repr(drawing)


def test_load_text_says_what_it_takes():
    with pytest.raises(TypeError, match=r"its TOML text, a str \(got NoneType\)"):
        graphplan.load_text(None)
    with pytest.raises(SceneError, match=r"looks like a file's name: graphplan\.load\(path\) reads a scene file"):
        graphplan.load_text(RATCHET)
    assert graphplan.load_text.__name__ == "load_text" and "TOML text" in graphplan.load_text.__doc__


# --- a parameter study, the strokes, the dynamics and the drawings from Python ---------------------------------


def test_a_scene_given_as_its_tables_is_checked_as_its_file_is():
    """A parameter study changes the tables tomllib reads of a scene: dataclasses.replace on a Scene skips every
    check (a negative rod came out as a mirrored mechanism), so load takes the tables and checks them."""
    import tomllib

    tables = tomllib.loads(Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8"))
    tables["groups"][0]["length"] = -0.26
    with pytest.raises(SceneError, match=r"^groups\[0\]\.length: must be > 0 \(got -0\.26\)$"):
        graphplan.load(tables)
    tables["groups"][0]["length"] = np.float64(0.26)  # numpy's numbers, as a sweep's np.linspace gives them
    tables["positions"]["count"] = np.int64(12)
    scene = graphplan.load(tables)
    assert scene.groups[0].length == 0.26 and scene.positions.count == 12
    tables["groups"][0]["guide"]["angle"] = {0.0}
    with pytest.raises(SceneError, match=r"^groups\[0\]\.guide\.angle: is a set, which a scene file cannot hold"):
        graphplan.load(tables)
    with pytest.raises(TypeError, match=r"graphplan\.load\(tables\) reads a scene given as its tables"):
        graphplan.load_text(tables)


def test_the_strokes_and_k_of_a_slotted_lever_are_the_closed_form_s():
    """The crank-and-slotted-lever: the lever's extremes are where the crank stands square to it, so the crank
    turns π ± 2·asin(r/d) in the two strokes (r the crank, d the pivots' distance)."""
    scene = graphplan.load("fixtures/quick_return_slotted_lever.toml")
    r = scene.driver.length
    d = abs(scene.frame_points["C"] - scene.frame_points[scene.driver.pivot])
    strokes = scene.analyse().strokes
    assert strokes.working == pytest.approx(math.pi + 2 * math.asin(r / d), abs=1e-9)
    assert strokes.idle == pytest.approx(math.pi - 2 * math.asin(r / d), abs=1e-9)
    assert strokes.time_ratio == pytest.approx(strokes.working / strokes.idle)
    assert graphplan.load("fixtures/slider_driven.toml").analyse().strokes is None


def test_the_dynamics_of_a_scene_are_worked_out_from_python_with_a_short_repr():
    """The flywheel starter is the punching press of the issue's worked example (power 367.7 W for a third of the
    turn and 3677 W for two thirds at 100 rpm, δ = 0.05): JF = ΔWmax/(ωm²·δ) = 441.24/((100·π/30)²·0.05)."""
    from graphplan.starters import starter

    dynamics = graphplan.load_text(starter("flywheel")).machine_dynamics()
    omega = 100 * math.pi / 30
    assert dynamics.flywheel.inertia == pytest.approx(441.24 / (omega**2 * 0.05), rel=1e-4)
    assert len(repr(dynamics)) < 200 and "JF = 80.47" in repr(dynamics)
    with pytest.raises(SceneError, match=r"^dynamics: the scene has no \[dynamics\] table"):
        graphplan.load(RATCHET).machine_dynamics()


def test_a_drawing_is_saved_as_its_name_s_suffix_says(tmp_path):
    """save("plan.png") wrote SVG text into a file named .png."""
    drawing = graphplan.load(RATCHET).plan(5).drawing
    png, pdf, svg = (drawing.save(tmp_path / f"plan.{kind}") for kind in ("png", "pdf", "svg"))
    assert png.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    assert pdf.read_bytes().startswith(b"%PDF-")
    assert svg.read_text(encoding="utf-8") == drawing.svg
    with pytest.raises(ValueError, match=r"\.svg, \.png or \.pdf"):
        drawing.save(tmp_path / "plan.jpg")
    assert not (tmp_path / "plan.jpg").exists()


def test_drawing_the_report_figures_leaves_a_notebook_s_matplotlib_as_it_was(tmp_path):
    """The figures chose matplotlib's Agg backend for the whole process (a notebook's inline plots stopped
    showing after a run) and kept their figures open in pyplot."""
    matplotlib = pytest.importorskip("matplotlib")
    from matplotlib import pyplot

    from graphplan.cli import main
    from graphplan.starters import starter

    before = matplotlib.get_backend()
    pyplot.switch_backend("svg")  # a backend no figure of graphplan's asks for
    try:
        # Each of the three kinds of plot: a linkage's balancing, a machine's motion (the flywheel starter's, drawn by
        # the same motion_figure as the shaper's, without the shaper's nine seconds of dynamics), a rotor's vibration.
        for kind, pieces, drawn in (("shaper", "figures", {"balancing.svg"}), ("flywheel", "dynamics", {"motion.svg"}),
                                    ("rotor", "vibration", {"vibration_magnification.svg"})):
            scene = tmp_path / f"{kind}.toml"
            scene.write_text(starter(kind), encoding="utf-8")
            assert main(["run", str(scene), "--only", pieces, "--out", str(tmp_path / kind)]) == 0
            assert {path.name for path in (tmp_path / kind).glob("*.svg")} >= drawn
        assert matplotlib.get_backend() == "svg"
        assert pyplot.get_fignums() == []
    finally:
        pyplot.switch_backend(before)


def test_a_slide_an_equilibrium_a_force_plan_and_a_plan_print_in_a_line_that_names_them():
    """Their reprs ran to 28 500, 3 900, 7 800 and 3 500 characters on the shaper (every array, every step)."""
    scene = graphplan.load("fixtures/shaper_six_bar.toml")
    analysis, three = scene.analyse(), scene.plan(3)
    slide, equilibrium, forces = analysis.motion.slides[0], analysis.equilibrium, three.forces
    shown = [repr(item) for item in (slide, equilibrium, forces, three.velocity, three.acceleration)]
    assert all(len(line) < 200 and "\n" not in line for line in shown), shown
    assert f"link {slide.slider} on link {slide.guide}" in shown[0] and f"{len(analysis.positions.numbers)} positions" in shown[0]
    assert all(reaction.name in shown[1] for reaction in equilibrium.reactions)
    assert f"balancing {forces.balancing:.5g}" in shown[2]
    assert all(letter in shown[3] for letter in three.velocity.points) and "(acceleration)" in shown[4]
