"""Malformed and hostile scenes: `graphplan run` exits 2 with one clear line, no traceback, and writes nothing.

A property test mutates a valid scene (the ratchet fixture) in one of the ways a scene goes wrong:
a value of the wrong type, a required key deleted, an unknown key added, a negative or zero
length, NaN or infinity, a huge count, a name that refers to nothing, a cyclic reference,
geometry that does not assemble, bytes that are not UTF-8, text that is not TOML.  Each mutation
is invalid by construction; the command line (``graphplan.cli.main``, in process) must answer it
with exit status 2, one line on stderr that starts ``graphplan: error:`` and names the key (for a
key's mistake), no traceback, and no output folder (not even a half-written one beside it).
Explicit cases cover each category once more, the 10 MB file, and an output path that is a file.
A second property test changes any one number of any fixture (and of a scene with [dynamics], and
of a rotor's): the run either goes through or is refused in one such line, never with a traceback.

The faults found while writing this file are checked by the tests at the end.
"""

from __future__ import annotations

import contextlib
import copy
import json
import math
import os
import re
import shutil
import tempfile
import tomllib
import warnings
from pathlib import Path

import pytest
from console import PROGRESS, without_progress
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st
from test_scene_errors import to_toml

from graphplan.cli import main
from graphplan.starters import starter

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"
BASE = tomllib.loads(FIXTURE.read_text(encoding="utf-8"))


# --- key paths as graphplan writes them -------------------------------------------------------------

def _join(path: str, key) -> str:
    return f"{path}[{key}]" if isinstance(key, int) else (f"{path}.{key}" if path else key)


def leaves(node, path="", keys=()):
    """(graphplan's key path, the keys to reach it, the value) of every scalar in the scene."""
    items = node.items() if isinstance(node, dict) else enumerate(node)
    for key, value in items:
        where, reach = _join(path, key), (*keys, key)
        if isinstance(value, (dict, list)):
            yield from leaves(value, where, reach)
        else:
            yield where, reach, value


def tables(node, path="", keys=()):
    if isinstance(node, dict):
        yield path, keys
    items = node.items() if isinstance(node, dict) else enumerate(node)
    for key, value in items:
        if isinstance(value, (dict, list)):
            yield from tables(value, _join(path, key), (*keys, key))


def _set(document, keys, value):
    node = document
    for key in keys[:-1]:
        node = node[key]
    node[keys[-1]] = value


def _delete(document, keys):
    node = document
    for key in keys[:-1]:
        node = node[key]
    del node[keys[-1]]


LEAVES = list(leaves(BASE))
NUMBERS = [leaf for leaf in LEAVES if isinstance(leaf[2], (int, float)) and not isinstance(leaf[2], bool)]
STRINGS = [leaf for leaf in LEAVES if isinstance(leaf[2], str)]
TABLES = [t for t in tables(BASE) if t[0]]
# Keys whose value must be > 0 (or, for the mass and the inertia, >= 0).
POSITIVE = ["driver.length", "groups[0].lengths[0]", "groups[0].lengths[1]", "drawing.length_scale",
            "drawing.velocity_pole", "drawing.acceleration_pole", "drawing.drafting_precision", "positions.count"]
NON_NEGATIVE = ["links.2.mass", "links.3.inertia", "links.4.mass", "scene.gravity"]
REQUIRED = {"driver.kind": "driver.kind", "driver.link": "driver.link", "driver.pivot": "driver.pivot",
            "driver.joint": "driver.joint", "driver.length": "driver.length", "driver.omega": "driver.omega",
            "groups[0].kind": "groups[0].kind", "groups[0].links": "groups[0].links",
            "groups[0].joints": "groups[0].joints", "groups[0].lengths": "groups[0].lengths",
            "groups[0].assembly": "groups[0]", "points.S3.link": "points.S3.link", "points.S3.from": "points.S3.from",
            "points.S3.at": "points.S3.at", "loads[0].kind": "loads[0].kind", "loads[0].value": "loads[0].value",
            "links.3.centre": "links.3.centre", "frame": "frame", "driver": "driver",
            "positions.working": "positions.working"}
BY_PATH = {where: keys for where, keys, _ in LEAVES} | {where: keys for where, keys in TABLES}
BY_PATH |= {"frame": ("frame",), "driver": ("driver",), "groups[0].links": ("groups", 0, "links"),
            "groups[0].joints": ("groups", 0, "joints"), "groups[0].lengths": ("groups", 0, "lengths")}


# --- running the command line -------------------------------------------------------------------------

def run(capsys, text: str | bytes, extra: tuple[str, ...] = ()) -> tuple[int, str, Path]:
    """Run ``graphplan run`` on ``text`` in a fresh folder; the status, stderr, and the folder."""
    folder = Path(tempfile.mkdtemp(prefix="hostile-"))
    scene = folder / "scene.toml"
    scene.write_bytes(text if isinstance(text, bytes) else text.encode("utf-8"))
    capsys.readouterr()
    try:
        status = main(["run", str(scene), "--out", str(folder / "out"), *extra])
    except BaseException:
        shutil.rmtree(folder)
        raise
    return status, capsys.readouterr().err, folder


def assert_refused(capsys, text: str | bytes, names: str | None = None) -> str:
    """Exit 2, one error line (naming ``names`` when given), no traceback, nothing written."""
    status, err, folder = run(capsys, text)
    try:
        assert "Traceback" not in err
        # The scene's warnings, which may name the cause, come before the error (test_command_line).
        lines = [line for line in err.splitlines() if not PROGRESS.match(line)]
        errors = [line for line in lines if not line.startswith("warning: ")]
        assert status == 2, err
        assert len(errors) == 1 and errors[0].startswith("graphplan: error: ") and lines[-1] == errors[0], err
        if names is not None:
            assert names in errors[0], errors[0]
        assert sorted(p.name for p in folder.iterdir()) == ["scene.toml"], "an output folder was left behind"
        return errors[0]
    finally:
        shutil.rmtree(folder)


# --- the mutations ----------------------------------------------------------------------------------

WRONG_FOR_NUMBER = st.sampled_from([True, "x", [1.0], {"a": 1}])
WRONG_FOR_STRING = st.sampled_from([True, [True], {"a": True}])
NON_FINITE = st.sampled_from([math.nan, math.inf, -math.inf])


@st.composite
def hostile(draw):
    """A mutated scene (TOML text or bytes) and the key path its error must name (None: any clear line)."""
    document = copy.deepcopy(BASE)
    kind = draw(st.sampled_from(["type", "missing", "unknown", "negative", "non-finite", "huge", "dangling",
                                 "cyclic", "unassemblable", "bytes", "not-toml", "table-type"]))
    if kind == "type":
        where, keys, value = draw(st.sampled_from(NUMBERS + STRINGS))
        _set(document, keys, draw(WRONG_FOR_NUMBER if not isinstance(value, str) else WRONG_FOR_STRING))
        return to_toml(document), where
    if kind == "missing":
        where = draw(st.sampled_from(sorted(REQUIRED)))
        _delete(document, BY_PATH[where])
        return to_toml(document), REQUIRED[where]
    if kind == "unknown":
        where, keys = draw(st.sampled_from(TABLES))
        name = draw(st.sampled_from(["colour", "lenght", "omgea", "x"]))
        node = document
        for key in keys:
            node = node[key]
        node[name] = draw(st.sampled_from([1.0, "y", True]))
        return to_toml(document), _join(where, name)
    if kind == "negative":
        where = draw(st.sampled_from(POSITIVE + NON_NEGATIVE))
        value = draw(st.sampled_from([-1.0, -1e-300, -1e300]) if where in NON_NEGATIVE else st.sampled_from([0, 0.0, -1.0, -1e-300]))
        if where == "positions.count":
            value = draw(st.integers(max_value=0))
        _set(document, BY_PATH[where], value)
        return to_toml(document), where
    if kind == "non-finite":
        where, keys, value = draw(st.sampled_from([leaf for leaf in NUMBERS if isinstance(leaf[2], float)]))
        _set(document, keys, draw(NON_FINITE))
        return to_toml(document), where
    if kind == "huge":
        _set(document, ("positions", "count"), draw(st.integers(min_value=100_001, max_value=10**40)))
        return to_toml(document), "positions.count"
    if kind == "dangling":
        where = draw(st.sampled_from(["driver.pivot", "groups[0].joints[0]", "groups[0].joints[2]", "points.S3.from",
                                      "points.E.toward", "links.3.centre", "loads[0].link", "positions.working.link"]))
        _set(document, BY_PATH[where], 99 if where.endswith("link") else "Zz")
        return to_toml(document), where
    if kind == "cyclic":
        document["points"]["P1"] = {"link": 3, "from": "P2", "toward": "B", "at": 0.1}
        document["points"]["P2"] = {"link": 3, "from": "P1", "toward": "A", "at": 0.1}
        return to_toml(document), "cyclic reference"
    if kind == "unassemblable":
        shrink = draw(st.floats(min_value=0.01, max_value=0.3))
        document["groups"][0]["lengths"] = [0.55 * shrink, 0.325 * shrink]
        return to_toml(document), "cannot be assembled"
    if kind == "bytes":
        text = to_toml(document).encode("utf-8")
        at = draw(st.integers(min_value=0, max_value=len(text)))
        bad = draw(st.binary(min_size=1, max_size=8).map(lambda b: bytes([0xFF]) + b))
        return text[:at] + bad + text[at:], "is not UTF-8 text"
    if kind == "not-toml":
        text = to_toml(document)
        at = draw(st.integers(min_value=0, max_value=len(text)))
        return text[:at] + draw(st.sampled_from(["= =", "[[", "x = [1, ", '"', "]]]\n"])) + "\n" + text[at:], None
    section = draw(st.sampled_from(["frame", "driver", "positions", "drawing", "scene", "groups", "points"]))
    document[section] = draw(st.sampled_from([1, "x", [1, 2]] if section != "groups" else [1, "x", {"a": 1}, [1]]))
    return to_toml(document), section


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(case=hostile())
def test_a_hostile_scene_is_refused_in_one_clear_line(capsys, case):
    text, names = case
    assert_refused(capsys, text, names)


@pytest.mark.parametrize("where", sorted(REQUIRED))
def test_a_missing_key_is_told_where_it_belongs(capsys, where):
    """Each required key, removed, is told at its path: the property test above draws one now and then, and a
    message moved to another path (positions.working's, from the start that needs it) failed it only on the draw."""
    document = copy.deepcopy(BASE)
    _delete(document, BY_PATH[where])
    assert_refused(capsys, to_toml(document), REQUIRED[where])


# --- one explicit case per category ------------------------------------------------------------------

def _with(path: str, value) -> str:
    document = copy.deepcopy(BASE)
    _set(document, BY_PATH[path], value)
    return to_toml(document)


def _without(path: str) -> str:
    document = copy.deepcopy(BASE)
    _delete(document, BY_PATH[path])
    return to_toml(document)


@pytest.mark.parametrize(("text", "message"), [
    (_with("groups[0].lengths[1]", "long"), "groups[0].lengths[1]: must be a number, not a string"),
    (_with("driver.pivot", 7), "driver.pivot: must be a string, not an integer"),
    (_without("driver.length"), "driver.length: is required but missing"),
    (_with("points.S3.at", math.nan), "points.S3.at: must be a finite number"),
    (_with("driver.length", -0.175), "driver.length: must be > 0 (got -0.175)"),
    (_with("groups[0].lengths[0]", 0.0), "groups[0].lengths[0]: must be > 0"),
    (_with("scene.gravity", -math.inf), "scene.gravity: must be a finite number"),
    (_with("positions.count", 10**12), "positions.count: must be <= 20000"),
    (_with("driver.pivot", "Q"), "driver.pivot: must be a point of [frame] points"),
    (_with("links.3.centre", "Nowhere"), "links.3.centre: must be a point fixed on link 3"),
    (_with("groups[0].lengths[0]", 0.1), "B cannot be assembled at φ = "),
], ids=["wrong-type", "wrong-type-name", "missing", "nan", "negative", "zero", "infinity", "huge-count",
        "dangling-pivot", "dangling-centre", "unassemblable"])
def test_each_category_names_its_key(capsys, text, message):
    assert_refused(capsys, text, message)


def test_an_unknown_key_is_named_with_a_suggestion(capsys):
    document = copy.deepcopy(BASE)
    document["driver"]["lenght"] = document["driver"].pop("length")
    assert_refused(capsys, to_toml(document), "driver.lenght: unknown key; did you mean 'length'?")


def test_a_cyclic_reference_between_named_points_is_named(capsys):
    document = copy.deepcopy(BASE)
    document["points"]["P1"] = {"link": 3, "from": "P2", "toward": "B", "at": 0.1}
    document["points"]["P2"] = {"link": 3, "from": "P1", "toward": "A", "at": 0.1}
    assert_refused(capsys, to_toml(document), "(a cyclic reference)")


def test_bytes_that_are_not_utf8(capsys):
    text = FIXTURE.read_bytes().replace(b"Crank-rocker", b"Crank\xc0\xafrocker")
    assert_refused(capsys, text, "is not UTF-8 text")


def test_text_that_is_not_toml(capsys):
    assert_refused(capsys, "[scene\ntitle = 'x'\n", "is not valid TOML")


def test_an_empty_file(capsys):
    assert_refused(capsys, "", "scene.toml: is empty")


def test_a_10_mb_file_is_refused_before_it_is_read(capsys):
    text = FIXTURE.read_text(encoding="utf-8") + "#" + "x" * (10 * 1024 * 1024) + "\n"
    assert_refused(capsys, text, "a scene may have at most 1000000")


def test_a_missing_scene_file(capsys, tmp_path):
    status = main(["run", str(tmp_path / "nowhere.toml"), "--out", str(tmp_path / "out")])
    err = capsys.readouterr().err
    assert status == 2 and err.count("\n") == 1 and "nowhere.toml: cannot be read" in err
    assert not (tmp_path / "out").exists()


def test_an_output_path_that_is_a_file_is_left_alone(capsys, tmp_path):
    target = tmp_path / "out"
    target.write_text("keep me", encoding="utf-8")
    status = main(["run", str(FIXTURE), "--out", str(target), "--only", "positions"])
    err = capsys.readouterr().err
    assert status == 2 and "exists and is not a folder" in err and "Traceback" not in err
    assert target.read_text(encoding="utf-8") == "keep me"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"], "a staging folder was left behind"


@pytest.mark.parametrize("under", ["sub", "sub/deeper"])
def test_an_output_path_under_a_file_names_the_file(capsys, tmp_path, under):
    """It said "cannot write the output (File exists)", naming neither the file nor what was wrong with it."""
    blocking = tmp_path / "afile"
    blocking.write_text("keep me", encoding="utf-8")
    status = main(["run", str(FIXTURE), "--out", str(blocking / under), "--only", "positions"])
    err = without_progress(capsys.readouterr().err)
    assert status == 2 and err == f"graphplan: error: {blocking / under}: {blocking} is not a folder, so the output " \
                                  "cannot go in it; give --out a folder elsewhere\n"
    assert blocking.read_text(encoding="utf-8") == "keep me"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]


def test_a_bad_scene_leaves_an_earlier_output_folder_untouched(capsys, tmp_path):
    target = tmp_path / "out"
    target.mkdir()
    (target / "results.json").write_text("{}", encoding="utf-8")
    scene = tmp_path / "scene.toml"
    scene.write_text(_with("driver.length", -1.0), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(target)]) == 2
    assert [p.name for p in target.iterdir()] == ["results.json"]
    assert (target / "results.json").read_text(encoding="utf-8") == "{}"


# --- faults found here, fixed: magnitudes a float cannot carry are refused by the reader -------------

def test_an_integer_too_large_for_a_float(capsys):
    assert_refused(capsys, _with("driver.length", 10**400), "driver.length")


def test_a_vanishing_length(capsys):
    """A crank of 1e-300 m would underflow its square in the force analysis: refused where it is given."""
    error = assert_refused(capsys, _with("driver.length", 1e-300), "driver.length")
    # Not "must be 0 or …": a length must be > 0, and 0 is refused as such.
    assert "driver.length: must be > 0, of a magnitude from 1e-15 to 1e+15 (got 1e-300)" in error
    assert_refused(capsys, _with("driver.length", 0.0), "driver.length")


def test_a_vanishing_value_of_a_key_that_may_be_0_is_offered_0(capsys):
    error = assert_refused(capsys, _with("frame.points.O[0]", 1e-300), "frame.points.O[0]")
    assert "frame.points.O[0]: must be 0 or of a magnitude from 1e-15 to 1e+15 (got 1e-300)" in error


@pytest.mark.parametrize("path,value", [("drawing.length_scale", 1e-300), ("drawing.velocity_pole", 1e300),
                                        ("points.S3.at", 1e300), ("driver.omega", 1e200)])
def test_magnitudes_near_the_float_range(capsys, path, value):
    """Coordinates, scales and speeds a float cannot square are refused, naming the key."""
    assert_refused(capsys, _with(path, value), path)


def test_an_overflowing_speed_is_an_error_or_warned_everywhere(capsys):
    status, _, folder = run(capsys, _with("driver.omega", 1e200), ("--only", "positions"))
    if status == 2:
        shutil.rmtree(folder)
        return
    document = json.loads((folder / "out" / "results.json").read_text(encoding="utf-8"))
    shutil.rmtree(folder)
    warned = {w["position"] for w in document["warnings"]}
    blank = {p["index"] for p in document["positions"] if any(point["a"] is None for point in p["points"].values())}
    assert blank <= warned, f"positions {sorted(blank - warned)} hold null accelerations without a warning"


# --- faults found by mutating the other fixtures, fixed --------------------------------------------

def test_a_pole_distance_no_sheet_holds_is_refused_not_drawn(capsys):
    """At pa = 1e9 mm the plan's points lie so far out that a link's collinear points (p, s4, b) round to a
    hull of some area, whose corners were then all dropped as in line; the plan is refused instead."""
    error = assert_refused(capsys, _with("drawing.acceleration_pole", 1e9), "drawing.acceleration_pole")
    assert "more than any paper" in error


def _refused_without_sheets(capsys, text: str, key: str) -> str:
    """The value the error line offers for ``key`` once a run without sheets refuses ``text``."""
    status, err, folder = run(capsys, text, ("--only", "velocity,acceleration,forces"))
    shutil.rmtree(folder)
    assert status == 2 and f"graphplan: error: {key}: " in err and "more than any paper" in err, err
    (error,) = [line for line in err.splitlines() if line.startswith("graphplan: error: ")]
    return re.search(r"give (\S+) ", error).group(1)


@pytest.mark.parametrize("key, slip", [("velocity_pole", 1e5), ("acceleration_pole", 1e5),
                                       ("velocity_scale", 1e-7), ("force_scale", 1e-3)])
def test_a_scale_that_draws_a_plan_or_polygon_larger_than_any_paper_is_refused_without_sheets_too(capsys, key, slip):
    """A pole distance in micrometres or μF in the wrong unit wrote an SVG hundreds of metres wide when no sheet
    was asked for (the sheets refused it); now every run refuses it, and the value it offers draws the
    largest plan or polygon at its usual size."""
    def scene(value: float) -> str:
        document = copy.deepcopy(BASE)
        document["drawing"][key] = value
        if key == "velocity_scale":  # given instead of the pole distance, never with it
            del document["drawing"]["velocity_pole"]
        return to_toml(document)

    offered = float(_refused_without_sheets(capsys, scene(slip), f"drawing.{key}"))
    status, err, folder = run(capsys, scene(offered), ("--only", "velocity,acceleration,forces"))
    try:
        assert status == 0, err
        drawings = sorted((folder / "out").glob("*.svg"))
        assert drawings
        for drawing in drawings:
            width_mm = float(re.search(r'<svg[^>]* width="([0-9.]+)mm"', drawing.read_text(encoding="utf-8"))[1])
            assert width_mm < 600, (drawing.name, width_mm)
    finally:
        shutil.rmtree(folder)


@pytest.mark.parametrize("key, slip", [("length_scale", 1e3), ("velocity_pole", 1e-6), ("acceleration_pole", 1e-6),
                                       ("velocity_scale", 1e5), ("force_scale", 1e12)])
def test_a_scale_that_draws_a_figure_too_small_to_read_is_told_by_check_and_run(capsys, tmp_path, key, slip):
    """μl = 1e3 for 1e-3 drew the mechanism as a dot under a pile of letters, μF = 1e12 polygons of 0.00 mm sides,
    with no word from check or run (a scale drawing larger than any paper is refused).  Both tell it, naming the
    key; the size they tell agrees with the positions' own extent over the scale, and the value they offer draws
    the figure readably and is not told of."""
    def scene(value: float) -> str:
        document = copy.deepcopy(BASE)
        document["drawing"][key] = value
        if key == "velocity_scale":  # given instead of the pole distance, never with it
            del document["drawing"]["velocity_pole"]
        return to_toml(document)

    path = tmp_path / "scene.toml"
    path.write_text(scene(slip), encoding="utf-8")
    capsys.readouterr()
    assert main(["check", str(path)]) == 0
    told = [line for line in capsys.readouterr().out.splitlines() if line.startswith(f"warning: drawing.{key}: ")]
    assert len(told) == 1 and "too small to read" in told[0], told
    only = ("--only", "positions,velocity,acceleration,forces")
    assert main(["run", str(path), "--out", str(tmp_path / "slip"), *only]) == 0
    assert told[0] in capsys.readouterr().out.splitlines()
    across = float(re.search(r"draws the [a-z ]+ ([0-9.e+-]+) mm across", told[0])[1])
    offered = float(re.search(r"; (\S+) draws", told[0])[1])
    path.write_text(scene(offered), encoding="utf-8")
    assert main(["run", str(path), "--out", str(tmp_path / "offered"), *only]) == 0
    assert "too small to read" not in capsys.readouterr().out
    if key == "length_scale":
        # The positions' own extent at μl, from results.json: no more than the paths' told (the paths run
        # between the positions), and readable at the value offered.
        def extent(folder: str, value: float) -> float:
            positions = json.loads((tmp_path / folder / "results.json").read_text(encoding="utf-8"))["positions"]
            points = [complex(*point["r"]) for position in positions for point in position["points"].values()]
            return max(max(p.real for p in points) - min(p.real for p in points),
                       max(p.imag for p in points) - min(p.imag for p in points)) / value
        assert extent("slip", slip) <= across * (1 + 1e-6)
        assert extent("offered", offered) > 0.1 * 200.0
    elif key.endswith("_pole"):
        # The pole's own vector (pa) is that many millimetres long, and a plan holds it.
        assert slip <= across * (1 + 1e-6) and offered > 0.1 * 150.0


def test_a_length_scale_that_would_draw_the_mechanism_kilometres_large_is_refused_before_drawing(capsys):
    """At μl = 1e-9 m/mm the hydraulic lever's guide would be 2e8 mm long, and its hatching, a stroke every
    2 mm, filled all the memory there was (found by the property test below); refused with the μl to give."""
    document = tomllib.loads((FIXTURE.parent / "slider_driven.toml").read_text(encoding="utf-8"))
    document["drawing"]["length_scale"] = 1e-9
    error = assert_refused(capsys, to_toml(document), "drawing.length_scale")
    assert "more than any paper" in error and "give 0.002" in error


# --- any number of any fixture, changed: a run or one clear line, never a traceback -------------------

FIXTURES = sorted(FIXTURE.parent.glob("*.toml"))
# Scenes with the tables the fixtures lack: the ratchet's dynamics with a flywheel, the shaper starter's
# friction and induction motor, a rotor without a linkage.
EXTRA_SCENES = {
    "ratchet-dynamics": FIXTURE.read_text(encoding="utf-8") + "\n[dynamics]\ndelta = 0.05\nflywheel_shaft_rpm = 1440\n",
    "shaper-starter": starter("shaper"),
    "rotor": ('[scene]\ntitle = "Rotor"\n[balancing]\nmasses = [ { mass = 18.0, radius = 0.05, angle = 0.0, plane = 0.0 },'
              ' { mass = 14.0, radius = 0.06, angle = -60.0, plane = 0.08 } ]\nplanes = [0.04, 0.22]\n'
              "correction_radius = 0.05\n[vibration]\nmass = 100.0\nunbalance = 0.02\nstiffness = 1.0e5\n"
              "damping_ratio = 0.1\nrpm = 600.0\n"),
}
SCENES = {path.stem: path.read_text(encoding="utf-8") for path in FIXTURES} | EXTRA_SCENES
NUMBER_LEAVES = {name: [leaf for leaf in leaves(tomllib.loads(text))
                        if isinstance(leaf[2], (int, float)) and not isinstance(leaf[2], bool)]
                 for name, text in SCENES.items()}


@st.composite
def changed_number(draw):
    """A scene with one of its numbers scaled, negated, zeroed or made huge, tiny or not finite."""
    name = draw(st.sampled_from(sorted(SCENES)))
    document = tomllib.loads(SCENES[name])
    where, keys, value = draw(st.sampled_from(NUMBER_LEAVES[name]))
    new = draw(st.sampled_from([0, -1, 2, 1e-6, 1e6, 1e9, -1e9, math.nan, math.inf]))
    changed = new if new in (0, -1) or not math.isfinite(new) or abs(new) >= 1e9 else value * new
    _set(document, keys, float(changed) if isinstance(value, float) or not math.isfinite(new) else int(changed))
    return name, where, to_toml(document)


# What one run may take beyond the tests' own address space: a run that needs more is a fault to find here,
# not a machine to bring down (a guide's hatching at μl = 1e-9 took 23 GB before it was refused).
RUN_MEMORY_BYTES = 6 * 2**30


@contextlib.contextmanager
def memory_ceiling(extra: int):
    """The process's address space held to what it has now and ``extra`` bytes more (Linux; else no ceiling)."""
    try:
        import resource

        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        pages, _ = Path("/proc/self/statm").read_text().split(maxsplit=1)
        now = int(pages) * os.sysconf("SC_PAGE_SIZE")
    except (ImportError, OSError, ValueError):
        yield
        return
    ceiling = now + extra if hard == resource.RLIM_INFINITY else min(now + extra, hard)
    resource.setrlimit(resource.RLIMIT_AS, (ceiling, hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


# Each example is a whole run (1.5 s): 25 a run of the suite, new ones each time, keep the search going; 40 took a
# minute of a CI worker's twenty.
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(case=changed_number())
def test_any_number_of_any_scene_changed_runs_or_is_refused_in_one_line(capsys, case):
    name, where, text = case
    with memory_ceiling(RUN_MEMORY_BYTES):
        status, err, folder = run(capsys, text)
    event("ran" if status == 0 else "refused")
    try:
        # A run the scene's own pieces make (not an --only its tables lack) and that got past the reader.
        assert status == 0 or not err.startswith("graphplan: error: --only"), err
        assert "Traceback" not in err, (name, where)
        errors = [line for line in err.splitlines() if not PROGRESS.match(line) and not line.startswith("warning: ")]
        if status == 2:
            assert len(errors) == 1 and errors[0].startswith("graphplan: error: "), (name, where, err)
            assert sorted(p.name for p in folder.iterdir()) == ["scene.toml"], (name, where)
        else:
            assert status == 0, (name, where, err)
            json.loads((folder / "out" / "results.json").read_text(encoding="utf-8"))
    finally:
        shutil.rmtree(folder)


# --- found by fuzzing the command line: refusals of the dynamics and the reader that ended in a traceback ---


def test_a_scene_nested_past_the_reader_s_recursion_is_refused(capsys):
    assert_refused(capsys, "a = " + "[" * 5000 + "]" * 5000 + "\n", "nests arrays or tables too deeply")


def test_a_resisting_constant_beside_the_scene_s_own_resisting_loads_is_refused(capsys):
    # The ratchet's loads resist: Mr cannot also be the constant that balances the cycle's work.
    line = assert_refused(capsys, to_toml({**BASE, "dynamics": {"constant": "resisting"}}), "dynamics.constant: ")
    # Nothing drives: the driving side may be the constant one.
    assert "(got 'resisting')" in line and "loads[0]" in line and 'constant = "driving"' in line


def test_a_motor_on_links_without_mass_is_refused(capsys):
    # No masses and no loads: Je = 0, and the equation of motion has nothing to accelerate.
    scene = {key: value for key, value in BASE.items() if key not in ("links", "loads")}
    scene["dynamics"] = {"motor": {"kind": "constant", "torque": 1.0}}
    line = assert_refused(capsys, to_toml(scene), "dynamics: inertia: must be > 0 over the whole turn")
    assert "Je = 0 kg·m²" in line


def test_a_duration_of_more_turns_than_a_run_integrates_is_refused_at_once(capsys):
    # A slip of the unit (a million seconds for a minute's start-up) would hold the run for hours.
    scene = {"dynamics": {"rpm": 100.0, "inertia": 1.0, "duration": 1e6,
                          "resisting_torque": [[0.0, 10.0], [360.0, 10.0]],
                          "motor": {"kind": "linear", "stall_torque": 200.0, "no_load_rpm": 120.0}}}
    line = assert_refused(capsys, to_toml(scene), "dynamics.duration: 1e+06 s")
    assert "at most 100000 turns" in line


def test_a_start_far_above_the_running_speed_is_refused_at_once(capsys):
    # rpm = 1e12 under a motor that runs at 120 rpm: slowing down would take some 1e13 turns, each
    # integrated step by step, and the run hung.  It is beyond any shaft's speed, and told so as it is read.
    scene = {"dynamics": {"rpm": 100.0, "inertia": 1.0, "start": {"rpm": 1e12},
                          "resisting_torque": [[0.0, 10.0], [360.0, 10.0]],
                          "motor": {"kind": "linear", "stall_torque": 200.0, "no_load_rpm": 120.0}}}
    line = assert_refused(capsys, to_toml(scene), "dynamics.start.rpm: must be at most 100000 rpm")
    assert line.endswith("(got 1000000000000.0); a slip of the exponent?")


def test_an_output_link_that_does_not_move_is_refused_as_such_not_as_a_sheet_too_small(capsys):
    # The tangent mechanism's ram guide turned upright through the slotted link's pivot C: the block then
    # stays at C, and the diagrams' scale came out endless, refused as "fit on no A1 sheet".
    scene = tomllib.loads((FIXTURE.parent / "tangent_mechanism_prp.toml").read_text(encoding="utf-8"))
    scene["frame"]["lines"]["ram"]["angle"] = 90.0
    scene["loads"][0]["angle"] = 270.0  # turned with the guide: square to it, it would be refused as resisting nothing
    line = assert_refused(capsys, to_toml(scene), "positions.working: link 6 does not move over the crank's turn")
    assert "drawing.sheet" not in line


def test_a_travel_ending_next_to_a_toggle_is_refused_by_check_and_run_alike_naming_the_diagram_and_position(capsys):
    """0.68° from the toggle ε4 reaches −157737 rad/s² (mpmath agrees): its chord diagram would stand 113 m tall
    at the shortest pole distance.  The run said "fit on no A1 sheet; choose a bigger one" (A1 is the largest),
    check said ok, and with no sheet the run wrote an SVG 113 m tall."""
    from graphplan.cli import main

    scene = tomllib.loads((FIXTURE.parent / "slider_driven.toml").read_text(encoding="utf-8"))
    scene["driver"]["travel"] = [0.2, 0.4295]
    scene.pop("measured", None)
    line = assert_refused(capsys, to_toml(scene), "positions: the acceleration diagram of link 4 cannot be drawn: its "
                                                  "acceleration reaches -157737 rad/s² near position 12")
    assert "Keep the driver's run clear of the toggle" in line and "drawing.sheet" not in line
    folder = Path(tempfile.mkdtemp())
    try:
        (folder / "near.toml").write_text(to_toml(scene), encoding="utf-8")
        assert main(["check", str(folder / "near.toml")]) == 2
        assert "the acceleration diagram of link 4 cannot be drawn" in capsys.readouterr().err
    finally:
        shutil.rmtree(folder)


def test_a_crank_too_short_to_move_the_output_is_refused_as_such(capsys):
    # A femtometre crank rocks the rocker by some 1e-14 rad: refused through drawing.sheet before.
    scene = {**BASE, "driver": {**BASE["driver"], "length": 1e-15}}
    line = assert_refused(capsys, to_toml(scene), "positions.working: link 4 does not move over the crank's turn")
    assert "lengths" in line


def test_friction_on_links_a_joint_does_not_join_names_the_links(capsys):
    scene = {**BASE, "friction": [{"joint": "B", "links": [2, 3], "f": 0.1, "radius": 0.01}]}
    line = assert_refused(capsys, to_toml(scene), "friction[0].links: joint B joins links 3–4, not these")
    assert "friction[0].joint" not in line


def test_two_frictions_for_one_pair_are_refused(capsys):
    # Accepted before: both coefficients went into the force analysis of the one pair.
    scene = {**BASE, "friction": [{"joint": "B", "f": 0.1, "radius": 0.01}, {"joint": "B", "f": 0.2, "radius": 0.01}]}
    assert_refused(capsys, to_toml(scene), "friction[1]: the pair at B (3–4) has its friction in friction[0] already")


# --- accepted silently before, found by fuzzing: each is a slip of the scene that the run went past ---


def test_an_empty_point_name_is_refused(capsys):
    scene = {**BASE, "points": {**BASE["points"], "": BASE["points"]["S2"]}}
    assert_refused(capsys, to_toml(scene), 'points."": must not be empty')


@pytest.mark.parametrize("what", ["mass", "inertia"])
def test_a_mass_on_the_frame_is_refused(capsys, what):
    scene = {**BASE, "links": {**BASE["links"], "1": {"mass": 5.0, "centre": "O"} if what == "mass" else {"inertia": 1.0}}}
    assert_refused(capsys, to_toml(scene), "links.1: link 1 is the frame, which does not move")


def test_a_load_on_the_frame_is_refused(capsys):
    load = {"kind": "force", "link": 1, "point": "O", "value": 100.0, "angle": 0.0}
    assert_refused(capsys, to_toml({**BASE, "loads": [*BASE["loads"], load]}),
                   "loads[1].link: link 1 is the frame, which does not move")


@pytest.mark.parametrize("key, value", [("point", "B"), ("angle", 30.0)])
def test_a_moment_given_a_point_or_a_direction_is_refused(capsys, key, value):
    load = {"kind": "moment", "link": 4, "value": 10.0, key: value}
    assert_refused(capsys, to_toml({**BASE, "loads": [*BASE["loads"], load]}),
                   f"loads[1].{key}: a moment acts on its whole link")


def test_a_frame_line_named_as_a_frame_point_is_refused(capsys):
    scene = {**BASE, "frame": {**BASE["frame"], "lines": {"C": {"through": [0.0, 0.0], "angle": 0.0}}}}
    assert_refused(capsys, to_toml(scene), "frame.lines.C: C names a point of [frame] points already")


@pytest.mark.parametrize("option", ["--format", "--only"])
def test_an_option_that_lists_nothing_is_refused(capsys, option):
    with pytest.raises(SystemExit) as stopped:
        run(capsys, to_toml(BASE), (option, " , "))
    assert stopped.value.code == 2
    assert f"argument {option}: names nothing" in capsys.readouterr().err


# --- runs that succeeded with numpy's, scipy's or matplotlib's warnings on the terminal ---


def run_quietly(capsys, text: str) -> tuple[str, dict]:
    """Run ``text`` with every warning an error; the stderr and the results of a run that must succeed."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        status, err, folder = run(capsys, text)
    try:
        assert status == 0, err
        return err, json.loads((folder / "out" / "results.json").read_text(encoding="utf-8"))
    finally:
        shutil.rmtree(folder)


def test_friction_that_locks_the_mechanism_runs_without_numpy_s_overflow_warnings(capsys):
    # f = 50 (ρ = 0.5 m, just inside the 0.55 m rod: a wider circle is refused) locks 8 positions of 12: the
    # iteration's reactions grow to inf, which is how locking is found.
    scene = {**BASE, "friction": [{"joint": "B", "f": 50.0, "radius": 0.01}]}
    err, _ = run_quietly(capsys, to_toml(scene))
    assert "Warning" not in err


def test_a_motor_exactly_equal_to_the_resistance_holds_the_machine_at_rest(capsys):
    # Equal but for the last bits of turning the diagram into torque: it crept off and "stalled" 15 s later,
    # and the stall plot's empty turn warned from matplotlib.
    scene = {"dynamics": {"rpm": 100.0, "inertia": 1.0, "resisting_torque": [[0.0, 10.0], [360.0, 10.0]],
                          "motor": {"kind": "constant", "torque": 10.0}}}
    err, results = run_quietly(capsys, to_toml(scene))
    assert "Warning" not in err
    assert results["dynamics"]["motion"]["stalled_at"] == 0.0


def test_a_tolerance_below_the_solvers_least_is_refused(capsys):
    scene = {"dynamics": {"rpm": 100.0, "inertia": 1.0, "resisting_torque": [[0.0, 10.0], [360.0, 10.0]],
                          "rtol": 1e-15, "motor": {"kind": "linear", "stall_torque": 200.0, "no_load_rpm": 120.0}}}
    assert_refused(capsys, to_toml(scene), "dynamics.rtol: must be at least 2.22e-14")


def test_check_refuses_an_output_link_that_does_not_move_as_the_run_does(capsys, tmp_path):
    # check said "ok" and printed strokes of the resting link's rounding noise (φw = 223°).
    scene = tomllib.loads((FIXTURE.parent / "tangent_mechanism_prp.toml").read_text(encoding="utf-8"))
    scene["frame"]["lines"]["ram"]["angle"] = 90.0
    scene["loads"][0]["angle"] = 270.0  # turned with the guide: square to it, it would be refused as resisting nothing
    path = tmp_path / "scene.toml"
    path.write_text(to_toml(scene), encoding="utf-8")
    capsys.readouterr()
    assert main(["check", str(path)]) == 2
    captured = capsys.readouterr()
    assert "strokes" not in captured.out
    assert captured.err.startswith("graphplan: error: positions.working: link 6 does not move")


def test_a_swing_too_small_to_move_the_output_is_refused_at_the_swing(capsys):
    # Refused at the swing that is too small, before the working link it leaves at rest is looked at: the swing is
    # the key to change (tests/test_fuzzed_scene_keys.py holds the bound).
    scene = tomllib.loads((FIXTURE.parent / "double_rocker_swing.toml").read_text(encoding="utf-8"))
    scene["driver"]["swing"] = [20.0, 20.0 + 1e-12]
    scene["positions"]["working"] = {"link": 4, "sense": "ccw"}
    assert_refused(capsys, to_toml(scene), "driver.swing: spans ")
