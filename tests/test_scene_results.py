"""scene.results(): results.json as a dict, nothing written.

A notebook that wanted the run's numbers (a linkage's positions, its forces, a flywheel's JF) had to write a folder
and read the file back.  Each dict here is checked against the results.json that scene.write writes for the same
options, read back with json: the file is the contract, and the dict must be it, key for key and number for number.
"""

import json
import os
import tomllib
import warnings
from pathlib import Path

import pytest

import graphplan

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
    scene = graphplan.load_text(graphplan.starter("shaper"))
    assert "dynamics" in scene.results()
    assert "dynamics" not in scene.results(only=["positions"])


@pytest.mark.parametrize(("options", "error", "told"), [
    ({"only": "positions"}, TypeError, r"only is a list of names: only=\['positions'\], not only='positions'"),
    ({"only": []}, graphplan.SceneError, r"^only: names nothing: give one or more pieces"),
    ({"only": ["results"]}, graphplan.SceneError, r"^only\[0\]: results\.json is written by every run"),
    ({"only": ["velocty"]}, graphplan.SceneError, r"^only\[0\]: .*did you mean 'velocity'"),
    ({"only": ["balancing"]}, graphplan.SceneError, r"^only\[0\]: 'balancing' "),
    ({"locale": "de"}, graphplan.SceneError, r"^locale: "),
    ({"sheet": "A9"}, graphplan.SceneError, r"^sheet")])
def test_what_a_run_refuses_is_refused_alike_and_named_as_python_names_it(options, error, told):
    with pytest.raises(error, match=told):
        graphplan.load(RATCHET).results(**options)


def test_a_scene_mistyped_in_its_units_is_warned_of_at_the_callers_line():
    tables = tomllib.loads(RATCHET.read_text(encoding="utf-8"))
    tables["driver"]["omega"] = -1450.0
    with pytest.warns(UserWarning, match=r"^speed-in-rpm: driver\.omega = -1450 rad/s") as told:
        graphplan.load(tables).results(only=["positions"])
    assert Path(told[0].filename).name == Path(__file__).name
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        graphplan.load(RATCHET).results(only=["positions"])
