"""table_keys.py lists every scene table's keys a second time, beside the readers that take them, so that a key written
in the wrong table is told where it goes.  Nothing ties the two together: a key added to a reader and forgotten there
is asked "did you mean …?" about the nearest key of whatever table it stands in, and a key a reader no longer takes
sends the user to a table that refuses it.

The keys each reader takes are found here without table_keys.py: many scenes are read while every
:class:`~graphplan.reader.Table` made is kept, and each table's taken keys (every key its reader asked for, given or
not) are gathered by the table's path.  The scenes are the fixtures, the starters of ``graphplan new``, the TOML texts
the other tests read, and a few written here for the keys only one kind or mode of a table takes (a slider driver, a
load diagram, each kind of motor, a brake, a clutch, a start, a flywheel from load diagrams, a machine on a shaft).
"""

from __future__ import annotations

import ast
import re
import tomllib
from pathlib import Path

import pytest
import scene_texts

from graphplan import reader, scene, starters
from graphplan.errors import GraphplanError
from graphplan.flywheel import _MOTOR_KEYS, _NESTED_KEYS, _OWN_KEYS
from graphplan.table_keys import NUMBERED_TABLE_KEYS, TABLE_KEYS

ROOT = Path(__file__).resolve().parent.parent

# The numbered tables' paths as the readers write them, each with its name in NUMBERED_TABLE_KEYS.  A point's name
# with a dot in it is quoted, as TOML quotes it (reader.join_path).
_NUMBERED_PATHS = (
    (re.compile(r"links\.\d+"), "links.N"),
    (re.compile(r"groups\[\d+\]"), "[[groups]]"),
    (re.compile(r"loads\[\d+\]"), "[[loads]]"),
    (re.compile(r"friction\[\d+\]"), "[[friction]]"),
    (re.compile(r'points\.(?:"[^"]*"|[^."\[]+)'), "points.NAME"),
    (re.compile(r"measured\.\d+"), "measured.N"),
)
# The scene's own top-level keys for the numbered tables above: [links.N], [[groups]], …
_NUMBERED_TOPS = {"links", "groups", "loads", "friction", "points", "measured"}

def _crank_slider(tail: str, speed: str = "rpm = 120.0") -> str:
    scene = scene_texts.slider_crank_with_masses("Keys", 0.1, 0.4, 120.0, (0.05, 0.15), (1.0, 2.0, 3.0), (0.01, 0.03))
    return scene.replace("rpm = 120.0", speed) + tail


_RESISTING_FORCE = """
[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
value = 500.0
resisting = true
during = "working"
[positions]
working = { link = 4, sense = "backward" }
"""

# Scenes for the keys one kind or mode of a table takes and no fixture or starter gives.  Each must load (checked
# below): a scene refused half-way would leave the keys after the refusal unasked.
MODE_SCENES = {
    "project": _crank_slider("""
[project]
author = "A. Student"
checked_by = "B. Teacher"
approved_by = "C. Head"
organization = "A university"
designation = "TMM.01.00"
date = 2026-12-01
[output]
include = ["positions", "velocity"]
"""),
    "load diagram": _crank_slider("""
[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
resisting = true
diagram = [[0.0, 100.0], [0.5, 400.0], [1.0, 100.0]]
stroke = { link = 4, sense = "backward" }
"""),
    "constant motor, brake, start at speed": _crank_slider(_RESISTING_FORCE + """
[dynamics]
delta = 0.05
motor = { kind = "constant", torque = 60.0, gear_ratio = 2.0, rotor_inertia = 0.01, off_at = 5.0 }
brake = { torque = 10.0, damping = 0.1, at = 4.0 }
start = { rpm = 100.0, angle_deg = 30.0 }
duration = 10.0
method = "auto"
rtol = 1e-8
steady_tolerance = 1e-4
"""),
    "linear motor through two points, clutch": _crank_slider(_RESISTING_FORCE + """
[dynamics]
omega = 12.0
delta = 0.05
constant = "driving"
count = 360
motor = { kind = "linear", points = [[0.0, 200.0], [1500.0, 0.0]], gear_ratio = 12.0 }
clutch = { torque = 150.0, engage_at = 0.5, inertia = 0.05 }
start = { omega = 0.0, driving_omega = 100.0 }
"""),
    "linear motor by its stall torque, clutch started in rpm": _crank_slider(_RESISTING_FORCE + """
[dynamics]
delta = 0.05
motor = { kind = "linear", stall_torque = 200.0, no_load_rpm = 1500.0, gear_ratio = 12.0, rotor_inertia = 0.01 }
clutch = { torque = 150.0 }
start = { rpm = 0.0, driving_rpm = 1000.0 }
"""),
    "Kloss motor by its rated slip": _crank_slider(_RESISTING_FORCE + """
[dynamics]
delta = 0.05
[dynamics.motor]
kind = "kloss"
power = 1500.0
overload = 2.2
synchronous_rpm = 1500.0
rated_slip = 0.04
gear_ratio = 12.5
"""),
    "slider driver": """
[frame]
points = { O = [0.0, 0.0] }
[driver]
kind = "slider"
link = 2
joint = "A"
guide = { through = [0.0, 0.0], angle = 0.0 }
velocity = 0.5
acceleration = 0.1
travel = [0.0, 0.2]
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "O"]
lengths = [0.3, 0.25]
assembly = "left"
""",
    "rocking crank": _crank_slider("", speed="omega = 5.0\nepsilon = 1.0\nswing = [0.0, 90.0]"),
    "driving torque diagram": """
[dynamics]
rpm = 300.0
delta = 0.02
count = 720
driving_torque = [[0.0, 0.0], [180.0, 400.0], [360.0, 0.0]]
resisting = "constant"
inertia = 0.5
flywheel_shaft_rpm = 1500.0
""",
    "resisting torque diagram with a motor": """
[dynamics]
omega = 30.0
delta = 0.05
resisting_torque = [[0.0, 100.0], [180.0, 300.0], [360.0, 100.0]]
driving = "constant"
motor = { kind = "kloss", power = 8000.0, overload = 2.5, rated_rpm = 1440.0, rated_slip = 0.04, gear_ratio = 5.0 }
""",
    "driving power diagram": """
[dynamics]
omega = 30.0
driving_power = [[0.0, 3000.0], [360.0, 3000.0]]
""",
    "machine on a shaft": """
[vibration]
mass = 50.0
unbalanced_mass = 0.2
eccentricity = 0.01
shaft = { modulus = 2.1e11, diameter = 0.05, length = 1.0, position = 0.5, support = "simply_supported" }
damping = 20.0
rpm = 1450.0
transmissibility = 0.2
""",
    "machine on a shaft given its second moment": """
[vibration]
mass = 50.0
unbalance = 0.002
shaft = { modulus = 2.1e11, second_moment = 3e-7, length = 0.5, support = "cantilever" }
damping_ratio = 0.05
omega = 100.0
base_amplitude = 0.001
""",
}


def _scene_texts_of_the_tests() -> list[str]:
    """The TOML texts the tests' modules hold as plain string constants (f-strings left out) that read as tables."""
    texts = []
    for path in sorted((ROOT / "tests").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Constant) and isinstance(node.value, str) and "=" in node.value:
                try:
                    document = tomllib.loads(node.value)
                except tomllib.TOMLDecodeError:
                    continue
                if set(document) & {*TABLE_KEYS, *_NUMBERED_TOPS}:
                    texts.append(node.value)
    return texts


def _helper_scene_texts() -> list[str]:
    """tests/scene_texts.py's scenes, each called with the numbers of a plain machine."""
    return [
        scene_texts.central_slider_crank(0.1, 0.4, 10.0),
        scene_texts.central_slider_crank(0.1, 0.4, 10.0, named_guide=True, locale="ru"),
        scene_texts.slider_crank_with_masses("Engine", 0.05, 0.2, 1500.0, (0.0, 0.07), (1.0, 2.0, 1.5), (0.01, 0.02)),
        scene_texts.piston_compressor(),
        scene_texts.engine(),
        scene_texts.four_bar_through_a_toggle(),
        scene_texts.offset_slotted_lever(0.05),
        scene_texts.slider_crank_with_a_resisting_force("Press"),
        scene_texts.wedge_lift(30.0, 1000.0, 0.1, 12),
        scene_texts.watt_ii(every_velocity_plan=True, sheet="A2"),
        scene_texts.oscillating_cylinder(0.05),
    ]


def _read_recording(texts: list[str]) -> tuple[dict[str, set[str]], list[str]]:
    """Each table path's taken keys over the scenes ``texts`` read, and the refusals of those that did not load.

    A scene refused part of the way still counts: each key a reader asked for before the refusal is a key it takes
    (its own argument, whatever the scene gave)."""
    made: list[reader.Table] = []
    original = reader.Table.__init__

    def recording(self, data, path):
        original(self, data, path)
        made.append(self)

    refusals = []
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(reader.Table, "__init__", recording)
        for text in texts:
            try:
                scene.loads(text)
            except GraphplanError as error:
                refusals.append(str(error))
    taken: dict[str, set[str]] = {}
    for table in made:
        taken.setdefault(table.path, set()).update(table._taken)
    return taken, refusals


def _listed_table(path: str) -> str | None:
    """The entry of TABLE_KEYS or NUMBERED_TABLE_KEYS the table at ``path`` is, or None for a table nested in one."""
    if path in TABLE_KEYS:
        return path
    return next((name for pattern, name in _NUMBERED_PATHS if pattern.fullmatch(path)), None)


@pytest.fixture(scope="module")
def mode_keys() -> dict[str, set[str]]:
    texts = [path.read_text(encoding="utf-8") for path in sorted((ROOT / "fixtures").glob("*.toml"))]
    texts += [starters.starter(kind) for kind in starters.KINDS]
    texts += _helper_scene_texts() + list(MODE_SCENES.values())
    taken, refusals = _read_recording(texts)
    assert not refusals, refusals
    return taken


@pytest.fixture(scope="module")
def every_key(mode_keys) -> dict[str, set[str]]:
    """mode_keys with those of the tests' own scenes, bad ones among them, read as well."""
    taken, _ = _read_recording(_scene_texts_of_the_tests())
    for path, keys in mode_keys.items():
        taken.setdefault(path, set()).update(keys)
    return taken


def _by_table(taken: dict[str, set[str]]) -> dict[str, set[str]]:
    gathered: dict[str, set[str]] = {}
    for path, keys in taken.items():
        name = _listed_table(path)
        if name is not None:
            gathered.setdefault(name, set()).update(keys)
    return gathered


def test_every_scene_written_here_loads():
    """The scenes for one mode's keys are scenes that load: one refused half-way would ask only some of its keys, and
    a key it no longer reaches would pass for one no reader takes."""
    for name, text in MODE_SCENES.items():
        try:
            scene.loads(text)
        except GraphplanError as error:
            pytest.fail(f"{name}: {error}")


def test_every_key_a_reader_takes_is_listed(every_key):
    listed = {**TABLE_KEYS, **NUMBERED_TABLE_KEYS}
    unlisted = {name: sorted(keys - set(listed[name])) for name, keys in _by_table(every_key).items()}
    assert {name: keys for name, keys in unlisted.items() if keys} == {}


def test_every_listed_key_is_taken_by_a_reader(mode_keys):
    gathered = _by_table(mode_keys)
    stale = {name: sorted(set(keys) - gathered.get(name, set()))
             for name, keys in {**TABLE_KEYS, **NUMBERED_TABLE_KEYS}.items()}
    assert {name: keys for name, keys in stale.items() if keys} == {}


def test_every_table_of_the_scene_is_listed(every_key):
    """A table the scene's reader takes at the top that table_keys.py has not heard of would tell none of its keys
    where they go, nor be told of a key written in it that belongs elsewhere."""
    assert every_key[""] - {*TABLE_KEYS, *_NUMBERED_TOPS} == set()
    assert {*TABLE_KEYS, *_NUMBERED_TOPS} - every_key[""] == set()


def test_the_motions_misplaced_keys_are_their_tables(mode_keys):
    """flywheel.py lists the keys of [dynamics]' motor, brake, clutch and start once more, to tell one written in the
    wrong one of them where it goes: each must be a key of the table it names."""
    assert set(_MOTOR_KEYS) - mode_keys["dynamics.motor"] == set()
    for table, keys in _NESTED_KEYS.items():
        assert set(keys) - mode_keys[f"dynamics.{table}"] == set(), table
    assert set(_OWN_KEYS) - mode_keys["dynamics"] == set()


def test_a_machines_damping_written_in_another_table_is_sent_to_vibration():
    """[vibration] takes damping (c, N·s/m) beside damping_ratio; table_keys.py had left it out, so a damping written
    under [scene] was asked about the nearest key there instead of being sent to [vibration]."""
    text = (ROOT / "fixtures" / "scotch_yoke.toml").read_text(encoding="utf-8")
    text = text.replace("[scene]", "[scene]\ndamping = 20.0", 1)
    with pytest.raises(GraphplanError) as refused:
        scene.loads(text)
    assert str(refused.value).startswith("scene.damping: unknown key; damping is a key of vibration")
    assert "write it under [vibration]: damping = 20.0" in str(refused.value)


def test_a_key_read_that_table_keys_does_not_list_fails_as_the_table_is_done(monkeypatch):
    """A key added to a reader and forgotten in table_keys.py fails the first test that reads its table, not only
    this file's survey of the scenes."""
    monkeypatch.setitem(TABLE_KEYS, "scene", tuple(key for key in TABLE_KEYS["scene"] if key != "gravity"))
    with pytest.raises(RuntimeError, match=r"^\[scene\] was read for gravity, which graphplan/table_keys\.py's "
                                           r"TABLE_KEYS\['scene'\] does not list: add it there$"):
        scene.loads(starters.starter("crank-rocker"))
    monkeypatch.undo()
    assert scene.loads(starters.starter("crank-rocker")).gravity is not None
