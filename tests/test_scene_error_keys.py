"""A scene's refusals name the key to write, and their advice, followed as written, gives a scene that runs.

A force without its `point` was told at `loads[0]`, leaving the student to find which of two keys was meant; a
required key was told "is required but missing" and nothing of what to write there. Every required key of the
fixtures and the starters is taken out in turn here, and must be told at its own path with what it is for.
The advice of the refusals a student meets first (a crank that cannot turn round, lengths that cannot assemble, a
load on an unknown point, ...) is followed literally, and the scene it gives must then run.
"""

from __future__ import annotations

import copy
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from graphplan.errors import GraphplanError, SceneError
from graphplan.reader import join_path
from graphplan.scene import load

ROOT = Path(__file__).resolve().parent.parent
SCENES = sorted((ROOT / "fixtures").glob("*.toml")) + sorted((ROOT / "graphplan" / "templates").glob("*.toml"))


def _cli(scene: str, tmp_path: Path, name: str = "scene") -> tuple[int, str, Path]:
    """Run ``graphplan run`` on the TOML text ``scene``: its exit code, its standard error and the output folder."""
    path = tmp_path / f"{name}.toml"
    path.write_text(scene, encoding="utf-8")
    out = tmp_path / f"out_{name}"
    done = subprocess.run([sys.executable, "-m", "graphplan", "run", str(path), "--out", str(out)],
                          capture_output=True, text=True, cwd=ROOT, timeout=300, check=False)
    return done.returncode, done.stderr, out


def _refused(scene: str, tmp_path: Path) -> str:
    """The one error line a refused scene prints, checked to be a refusal: exit 2, no traceback, no folder."""
    code, err, out = _cli(scene, tmp_path)
    assert code == 2, err
    assert "Traceback" not in err, err
    assert not out.exists()
    lines = [line for line in err.splitlines() if line.startswith("graphplan: error: ")]
    assert len(lines) == 1, err
    return lines[0].removeprefix("graphplan: error: ")


def _runs(scene: str, tmp_path: Path, name: str) -> None:
    code, err, out = _cli(scene, tmp_path, name)
    assert code == 0, err
    assert (out / "results.json").is_file()


def _paths(value, path=()):
    """Every key path in a parsed scene, as tuples of keys and indices."""
    if isinstance(value, dict):
        for key, item in value.items():
            yield (*path, key)
            yield from _paths(item, (*path, key))
    elif isinstance(value, list):
        for index, item in enumerate(value):
            yield from _paths(item, (*path, index))


def _written(path: tuple) -> str:
    text = ""
    for key in path:
        text = join_path(text, key)
    return text


# Keys that may be given as one of two or more (omega or rpm, stiffness or shaft, two of a motor's three speeds, a
# flywheel's delta asked for by flywheel_shaft_rpm, a diagram or a value, a triad's guides that change which
# lengths it takes): taking one out is told at the other, or at the table that chooses among them.
_ALTERNATIVES = re.compile(r"\.(rpm|omega|stiffness|synchronous_rpm|rated_rpm|delta|diagram|guides|guides\.\w+|"
                           r"resisting_power|resisting_torque)$|^dynamics$")


def _required_keys_taken_out():
    for scene in SCENES:
        data = tomllib.loads(scene.read_text(encoding="utf-8"))
        for path in _paths(data):
            if _ALTERNATIVES.search(_written(path)):
                continue
            changed = copy.deepcopy(data)
            table = changed
            for key in path[:-1]:
                table = table[key]
            del table[path[-1]]
            try:
                load(changed)
            except SceneError as error:
                if "required" in error.problem or "missing" in error.problem:
                    yield scene.name, _written(path), error
            except GraphplanError:
                pass


def test_every_required_key_is_told_at_its_own_path_with_what_it_is_for() -> None:
    """Each key of the fixtures and starters whose absence stops the scene is named by its own key path (not its
    table's), and the message says what the key is for, not only that it is missing."""
    told = list(_required_keys_taken_out())
    assert len(told) > 50
    wrong = [f"{scene}: {path} told as {error}" for scene, path, error in told if error.where != path]
    assert not wrong, "\n".join(wrong)
    bare = [f"{scene}: {error}" for scene, _, error in told
            if re.search(r"is required( but missing)?$", error.problem) or error.problem.endswith("missing")]
    assert not bare, "\n".join(bare)


_FORCE_SCENE = """
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.4, 0.0] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0

[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.4, 0.3]
assembly = "left"

[[loads]]
kind = "force"
link = 4
value = 100.0
{force}

[positions]
count = 6
"""


@pytest.mark.parametrize(("given", "where", "what"), [
    ("angle = 90.0", "loads[0].point", "where it acts"),
    ('point = "B"', "loads[0].angle", "direction"),
], ids=["point", "angle"])
def test_a_force_without_its_point_or_angle_is_told_at_that_key(tmp_path, given, where, what) -> None:
    """Both were told at loads[0], "a force needs point and angle", whichever of the two was there."""
    told = _refused(_FORCE_SCENE.replace("{force}", given), tmp_path)
    assert told.startswith(f"{where}: is required but missing: "), told
    assert what in told


@pytest.mark.parametrize(("change", "where", "what"), [
    (('assembly = "left"', ""), "groups[0].assembly", "left or right"),
    (("[positions]\ncount = 6", '[positions]\ncount = 6\nstart = "extreme"'), "positions.working",
     "working = { link, sense }"),
], ids=["assembly", "working"])
def test_a_key_another_key_needs_is_told_at_its_own_path(tmp_path, change, where, what) -> None:
    """A group with neither assembly nor near was told at groups[0]; start = "extreme" without working was told at
    positions.start, which was there, and not at the key to add."""
    scene = _FORCE_SCENE.replace("{force}", 'point = "B"\nangle = 90.0').replace(*change)
    told = _refused(scene, tmp_path)
    assert told.startswith(f"{where}: is required"), told
    assert what in told


def test_a_triad_sketch_without_a_joint_is_told_at_that_joint() -> None:
    data = tomllib.loads((ROOT / "fixtures" / "triad_class_iii.toml").read_text(encoding="utf-8"))
    triad = next(group for group in data["groups"] if group["kind"] == "triad")
    index = data["groups"].index(triad)
    missing = triad["joints"][3]
    del triad["near"][missing]
    with pytest.raises(SceneError) as caught:
        load(data)
    assert caught.value.where == f"groups[{index}].near.{missing}"
    assert "[x, y]" in caught.value.problem


_DOUBLE_ROCKER = """
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.3, 0.0] }

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.25
omega = 4.0

[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.12, 0.2]
assembly = "right"

[points]
S4 = { link = 4, from = "C", toward = "B", at = 0.1 }

[links.4]
mass = 3.0
centre = "S4"
inertia = 0.01

[[loads]]
kind = "moment"
link = 4
resisting = true
{load}

[positions]
count = 7
start = 30.0
working = { link = 4, sense = "ccw" }
"""


@pytest.mark.parametrize("load", [
    "value = 20.0\nduring = { from = 0.1, to = 0.6 }",
    "diagram = [[0.0, 20.0], [1.0, 10.0]]",
], ids=["window", "diagram"])
def test_a_crank_advised_to_rock_runs_once_the_advice_is_followed(tmp_path, load) -> None:
    """A double rocker's crank cannot turn round, and was advised driver.swing alone, with no swing to try (none ran
    with the load's window of the working stroke or its diagram, which a swing refuses); a student who added a
    swing was then refused at positions.start, and again at the load."""
    scene = _DOUBLE_ROCKER.replace("{load}", load)
    told = _refused(scene, tmp_path)
    swing = re.search(r"e\.g\. driver\.swing = (\[-?\d+, -?\d+\])", told)
    assert swing is not None, told
    assert "leave positions.start out" in told
    followed = scene.replace('joint = "A"\n', f'joint = "A"\nswing = {swing.group(1)}\n', 1)
    followed = followed.replace("start = 30.0\n", "")
    if "diagram" in load:
        assert 'give loads[0] a value in place of its diagram, with during = "working"' in told
        followed = followed.replace(load, 'value = 20.0\nduring = "working"')
    else:
        assert 'give loads[0].during = "working"' in told
        followed = followed.replace("during = { from = 0.1, to = 0.6 }", 'during = "working"')
    _runs(followed, tmp_path, "followed")


def test_a_crank_advised_to_rock_is_told_to_leave_out_a_start_written_as_zero(tmp_path) -> None:
    """A start of 0 written out is refused beside a swing as any other start is, but the advice took it for a start
    left out and did not say to drop it: the scene that followed the advice was refused at positions.start."""
    scene = _DOUBLE_ROCKER.replace("{load}", 'value = 20.0\nduring = "working"').replace("start = 30.0", "start = 0.0")
    told = _refused(scene, tmp_path)
    swing = re.search(r"e\.g\. driver\.swing = (\[-?\d+, -?\d+\])", told)
    assert swing is not None, told
    assert "leave positions.start out" in told
    followed = scene.replace('joint = "A"\n', f'joint = "A"\nswing = {swing.group(1)}\n', 1)
    _runs(followed.replace("start = 0.0\n", ""), tmp_path, "followed")


@pytest.mark.parametrize(("key", "given"), [
    ("force_scale", "0.001"),
    ("length_scale", "0.00001"),
    ("velocity_pole", "5000.0"),
], ids=["force_scale", "length_scale", "velocity_pole"])
def test_a_scale_too_large_for_any_paper_runs_at_the_value_advised(tmp_path, key, given) -> None:
    """A scale a student mistypes is refused with a value to give: that value, written in, must run."""
    scene = _FORCE_SCENE.replace("{force}", 'point = "B"\nangle = 90.0').replace(
        "[positions]\ncount = 6", f'[positions]\ncount = 6\nplans = [1]\n\n[drawing]\nsheet = "A3"\n{key} = {given}')
    told = _refused(scene, tmp_path)
    advised = re.search(rf"^drawing\.{key}: .*: give ([\d.]+) \(", told)
    assert advised is not None, told
    _runs(scene.replace(f"{key} = {given}", f"{key} = {advised.group(1)}"), tmp_path, "followed")


def test_a_force_on_a_point_off_its_link_names_the_points_it_may_act_at(tmp_path) -> None:
    """It said "must be a point fixed on link 4" and no more; a point it names, written in, runs."""
    told = _refused(_FORCE_SCENE.replace("{force}", 'point = "X"\nangle = 90.0'), tmp_path)
    listed = re.search(r"^loads\[0\]\.point: must be a point fixed on link 4: (.+) \(got 'X'\)$", told)
    assert listed is not None, told
    names = listed.group(1).split(", ")
    assert "B" in names and "C" in names and "A" not in names
    _runs(_FORCE_SCENE.replace("{force}", f'point = "{names[0]}"\nangle = 90.0'), tmp_path, "followed")
