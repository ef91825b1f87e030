"""scene.results() and scene.drawings(): a run's results.json and its SVG files, nothing written.

A notebook that wanted the run's numbers (a linkage's positions, its forces, a flywheel's JF) or a drawing other than
a position's plans (the kinematic diagrams, a sheet, the motion's plot) had to write a folder and read the files back.
Each is checked against what scene.write writes for the same options: the results.json read back with json (the file
is the contract, and the dict must be it, key for key and number for number), and each SVG byte for byte.
"""

import json
import os
import tomllib
import warnings
from pathlib import Path

import pytest

import graphplan
from graphplan.report.plot_style import PLOT_DPI

ROOT = Path(__file__).resolve().parents[1]
RATCHET = ROOT / "fixtures" / "ratchet_crank_rocker.toml"


def _written(scene: graphplan.Scene, folder: Path, **options) -> dict:
    scene.write(folder, **options)
    return json.loads((folder / "results.json").read_text(encoding="utf-8"))


@pytest.mark.parametrize(("scene", "options"), [
    (lambda: graphplan.load(RATCHET), {}),
    (lambda: graphplan.load_text(graphplan.starter("shaper")), {"only": ["positions", "dynamics"], "locale": "ru"}),
    (lambda: graphplan.load_text(graphplan.starter("rotor")), {}),
    (lambda: graphplan.load_text(graphplan.starter("flywheel", "zh")), {})],
    ids=["ratchet", "shaper-dynamics-ru", "rotor-alone", "flywheel-alone-zh"])
def test_the_dict_is_the_file_the_run_writes(scene, options, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    found = scene().results(**options)
    assert os.listdir(tmp_path) == []  # nothing written, not even a folder
    assert found == _written(scene(), tmp_path / "out", **options)
    assert {"dynamics", "balancing", "vibration", "positions"} & set(found)


def test_the_pieces_asked_for_decide_the_parts_given():
    scene = graphplan.load_text(graphplan.starter("rotor"))
    assert {"balancing", "vibration"} <= set(scene.results())
    assert "balancing" not in scene.results(only=["vibration"])


@pytest.mark.parametrize(("options", "error", "told"), [
    ({"only": "positions"}, TypeError, r"only is a list of names: only=\['positions'\], not only='positions'"),
    ({"only": []}, graphplan.SceneError, r"^only: names nothing: give one or more pieces"),
    ({"only": ["results"]}, graphplan.SceneError, r"^only\[0\]: results\.json is written by every run"),
    ({"only": ["velocty"]}, graphplan.SceneError, r"^only\[0\]: .*did you mean 'velocity'"),
    ({"only": ["balancing"]}, graphplan.SceneError, r"^only\[0\]: 'balancing' "),
    ({"locale": "de"}, graphplan.SceneError, r"^locale: "),
    ({"sheet": "A9"}, graphplan.SceneError, r"^sheet"),
    # The ratchet's plan of positions, on no A4 sheet: refused though results.json draws nothing.
    ({"sheet": "A4"}, graphplan.SceneError, r"^sheet \(in place of drawing\.sheet\): the plan of positions .* no A4")])
def test_what_a_run_refuses_is_refused_alike_and_named_as_python_names_it(options, error, told, tmp_path):
    with pytest.raises(error, match=told):
        graphplan.load(RATCHET).results(**options)
    if error is graphplan.SceneError:
        with pytest.raises(error, match=told):
            graphplan.load(RATCHET).write(tmp_path / "out", **options)


def test_a_scene_mistyped_in_its_units_is_warned_of_at_the_callers_line():
    tables = tomllib.loads(RATCHET.read_text(encoding="utf-8"))
    tables["driver"]["omega"] = -1450.0
    with pytest.warns(UserWarning, match=r"^speed-in-rpm: driver\.omega = -1450 rad/s") as told:
        graphplan.load(tables).results(only=["positions"])
    assert Path(told[0].filename).name == Path(__file__).name
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        graphplan.load(RATCHET).results(only=["positions"])


@pytest.mark.parametrize(("scene", "options", "plots"), [
    (lambda: graphplan.load(RATCHET), {"figures": True, "locale": "zh"}, {"balancing.svg"}),
    (lambda: graphplan.load_text(graphplan.starter("rotor")), {},
     {"vibration_magnification.svg", "vibration_transmissibility.svg"})],
    ids=["ratchet-figures-zh", "rotor-alone"])
def test_each_drawing_is_the_svg_file_the_run_writes(scene, options, plots, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    found = scene().drawings(**options)
    assert os.listdir(tmp_path) == []
    scene().write(tmp_path / "out", **options)
    written = {path.name: path.read_text(encoding="utf-8") for path in (tmp_path / "out").glob("*.svg")}
    assert {name: drawing.svg for name, drawing in found.items()} == written
    # The plots print at a report's resolution, the drawings at the export's, as the run's PNG are made.
    assert {name for name, drawing in found.items() if drawing.png_dpi == PLOT_DPI} == plots


def test_the_kinematic_diagrams_are_a_drawing_of_their_own():
    found = graphplan.load(RATCHET).drawings(only=["diagrams"], locale="en")
    assert list(found) == ["diagrams.svg"]
    assert "Kinematic diagrams of the output link" in found["diagrams.svg"]._repr_svg_()


@pytest.mark.parametrize(("options", "error", "told"), [
    ({"only": "diagrams"}, TypeError, r"only is a list of names: only=\['diagrams'\]"),
    ({"figures": "no"}, TypeError, r"figures is True or False \(got 'no'\)"),
    ({"only": ["diagram"]}, graphplan.SceneError, r"^only\[0\]: .*did you mean 'diagrams'"),
    ({"sheet": "B2"}, graphplan.SceneError, r"^sheet")])
def test_drawings_asked_for_wrongly_are_refused_as_a_run_refuses_them(options, error, told):
    with pytest.raises(error, match=told):
        graphplan.load(RATCHET).drawings(**options)


@pytest.mark.parametrize("verb", ["results", "drawings"])
def test_a_refusal_notes_the_warnings_that_may_name_its_cause(verb):
    """A run's refusal carries the scene's warnings as notes (the command line prints them before it): a centre of
    mass typed in millimetres draws the plan of positions larger than any paper, and the warning names the key."""
    text = (ROOT / "fixtures" / "engine_slider_crank.toml").read_text(encoding="utf-8")
    slipped = graphplan.load_text(text.replace("at = 0.055 }", "at = 5.5 }"))
    with pytest.warns(UserWarning, match=r"^lengths-in-mm: points\.S3\.at = 5\.5 m"), \
            pytest.raises(graphplan.SceneError, match=r"^points\.S3\.at: ") as refused:
        getattr(slipped, verb)(only=["positions"])
    assert [note for note in refused.value.__notes__ if note.startswith("warning: points.S3.at = 5.5 m")]


@pytest.mark.parametrize("verb", ["results", "drawings"])
def test_what_the_run_warns_of_is_warned_of_at_the_callers_line(verb, tmp_path):
    """A rotor's machine of 100 t on the starter's springs would sag metres: scene.write gives the warning in its
    .warnings, the command line prints it; results() and drawings() warn of it, a scene without a linkage too."""
    tables = tomllib.loads(graphplan.starter("rotor"))
    tables["vibration"]["mass"] = 100000.0
    heavy = graphplan.load(tables)
    written = heavy.write(tmp_path / "out").warnings
    with pytest.warns(UserWarning) as told:
        getattr(heavy, verb)()
    assert [str(warning.message) for warning in told] == list(written)
    assert [line for line in written if line.startswith("vibration.stiffness: ")]
    assert {Path(warning.filename).name for warning in told} == {Path(__file__).name}
