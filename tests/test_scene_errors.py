"""Every way a scene can be wrong, and the message each one gets.

Each case takes a valid base scene (a dict, written out as TOML by the small
writer below), changes one thing, and pins three facts about the error that
follows: its class, the stage that raises it (``load``: reading and checking
the file, ``build``: checking the names against each other, ``solve``: the
motion), and its whole message, key path first.

A case with ``gap=`` set is a strict xfail documenting a gap in the package: it
assert the behaviour wanted, and fail today.  When the gap is closed they
pass, and the strict marker turns that into a failure so the marker is removed.
"""

from __future__ import annotations

import codecs
import copy
import json
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import graphplan
from graphplan import AssemblyError, GraphplanError, SceneError, SingularPositionError
from graphplan import scene as scene_module
from graphplan.analysis import analyse
from graphplan.cli import main

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"


# --- a TOML writer small enough to trust -----------------------------------------------------
#
# Every table is written inline (``frame = { link = 1, ... }``), which TOML 1.0 allows at any
# depth; keys are always quoted, so ``"3"`` and ``"³"`` are keys like any other.


def _toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, list):
        return "[" + ", ".join(_toml_value(item) for item in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{json.dumps(k, ensure_ascii=False)} = {_toml_value(v)}" for k, v in value.items()) + " }"
    raise TypeError(f"cannot write {value!r} as TOML")


def to_toml(document: dict[str, Any]) -> str:
    return "".join(f"{json.dumps(key, ensure_ascii=False)} = {_toml_value(value)}\n" for key, value in document.items())


DELETE = object()


def variant(base: dict[str, Any], changes: dict[str, Any]) -> dict[str, Any]:
    """A deep copy of ``base`` with each dotted path set to its value (or removed, for DELETE).

    A path step into a list is its index: ``groups.0.lengths.1``; into a table, its key: ``links.3.mass``.
    """
    document = copy.deepcopy(base)
    for path, value in changes.items():
        *steps, last = path.split(".")
        node: Any = document
        for step in steps:
            node = node[int(step)] if isinstance(node, list) else node[step]
        key: Any = int(last) if isinstance(node, list) else last
        if value is DELETE:
            del node[key]
        else:
            node[key] = value
    return document


# --- valid base scenes -----------------------------------------------------------------------

# The bundled crank-rocker (fixtures/ratchet_crank_rocker.toml), plus [measured] and [output].
RATCHET: dict[str, Any] = {
    "scene": {"title": "Crank-rocker of a ratchet feed", "locale": "ru", "gravity": 9.81},
    "frame": {"link": 1, "points": {"O": [0.0, 0.0], "C": [0.0, 0.55]}},
    "driver": {"kind": "crank", "link": 2, "pivot": "O", "joint": "A", "length": 0.175,
               "omega": -17.0, "epsilon": 0.0},
    "groups": [{"kind": "RRR", "links": [3, 4], "joints": ["A", "B", "C"], "lengths": [0.55, 0.325],
                "assembly": "left"}],
    "points": {
        "S2": {"link": 2, "from": "O", "toward": "A", "at": 0.08},
        "S3": {"link": 3, "from": "A", "toward": "B", "at": 0.24},
        "E": {"link": 3, "from": "A", "toward": "B", "at": 0.24, "offset": 0.125},
        "S4": {"link": 4, "from": "C", "toward": "B", "at": 0.14},
    },
    "links": {
        "2": {"mass": 16.0, "centre": "S2"},
        "3": {"mass": 17.0, "centre": "S3", "inertia": 0.51},
        "4": {"mass": 17.0, "centre": "S4", "inertia": 0.18},
    },
    "loads": [{"kind": "moment", "link": 4, "value": 1500.0, "resisting": True,
               "during": {"from": 0.0, "to": 0.881}}],
    "positions": {"count": 12, "start": "extreme", "number_from": 0, "working": {"link": 4, "sense": "ccw"},
                  "plans": [5, 11]},
    "drawing": {"length_scale": 0.0025, "velocity_pole": 150.0, "acceleration_pole": 100.0,
                "drafting_precision": 0.5, "sheet": "A1"},
    "measured": {"5": {"velocity": {"pb": 39.0, "ab": 149.0}, "acceleration": {"pb": 65.0}}},
    "output": {"include": ["positions", "velocity", "acceleration"]},
}

# A four-bar that assembles everywhere: |AC| runs over [0.3, 0.7] m, AB + BC = 0.75, |AB − BC| = 0.05.
FOUR_BAR: dict[str, Any] = {
    "frame": {"points": {"O": [0.0, 0.0], "C": [0.5, 0.0]}},
    "driver": {"kind": "crank", "link": 2, "pivot": "O", "joint": "A", "length": 0.2, "omega": 10.0},
    "groups": [{"kind": "RRR", "links": [3, 4], "joints": ["A", "B", "C"], "lengths": [0.4, 0.35],
                "assembly": "left"}],
    "positions": {"count": 12, "start": 0.0},
}

# A central slider-crank: RRP on a frame guide along +x.
SLIDER_CRANK: dict[str, Any] = {
    "frame": {"points": {"O": [0.0, 0.0]}},
    "driver": {"kind": "crank", "link": 2, "pivot": "O", "joint": "A", "length": 0.1, "omega": 10.0},
    "groups": [{"kind": "RRP", "links": [3, 4], "joints": ["A", "B"], "length": 0.4,
                "guide": {"through": [0.0, 0.0], "angle": 0.0}, "assembly": "forward"}],
    "points": {"S3": {"link": 3, "from": "A", "toward": "B", "at": 0.2}},
    "positions": {"count": 12, "start": "extreme", "working": {"link": 4, "sense": "forward"}, "plans": [3]},
}

# A slider driver followed by an RRR.
SLIDER_DRIVEN: dict[str, Any] = {
    "frame": {"points": {"O": [0.0, 0.0], "C": [0.3, 0.2]}},
    "driver": {"kind": "slider", "link": 2, "joint": "A", "guide": {"through": [0.0, 0.0], "angle": 0.0},
               "velocity": 1.0, "travel": [0.0, 0.2]},
    "groups": [{"kind": "RRR", "links": [3, 4], "joints": ["A", "B", "C"], "lengths": [0.3, 0.3],
                "assembly": "left"}],
    "positions": {"count": 5},
}

# A crank-slotted lever: RPR, the block on A slides on lever 4 turning about C.
SLOTTED_LEVER: dict[str, Any] = {
    "frame": {"points": {"O": [0.0, 0.0], "C": [0.0, -0.3]}},
    "driver": {"kind": "crank", "link": 2, "pivot": "O", "joint": "A", "length": 0.1, "omega": 10.0},
    "groups": [{"kind": "RPR", "links": [3, 4], "joints": ["A", "C"]}],
    "positions": {"count": 12},
}

# PRP: a guide on the crank through A at 45° to it, crossing the frame's x axis at B (parallel to it only at
# φ = 135° and 315°, between the positions).
CROSSED_SLIDERS: dict[str, Any] = {
    "frame": {"points": {"O": [0.0, 0.0]}},
    # A guide on the crank runs parallel to the fixed one twice a turn (at 135° and 315°), where B is at infinity:
    # the crank rocks between the two.
    "driver": {"kind": "crank", "link": 2, "pivot": "O", "joint": "A", "length": 0.1, "omega": 10.0,
               "swing": [-40.0, 130.0]},
    "groups": [{"kind": "PRP", "links": [3, 4], "joints": ["B"],
                "guides": [{"link": 2, "through": "A", "angle": 45.0}, {"through": [0.0, 0.0], "angle": 0.0}]}],
    "positions": {"count": 12},
}

# A Scotch yoke: RPP, the block on A in the slot of link 4 that slides along +x.
SCOTCH_YOKE: dict[str, Any] = {
    "frame": {"points": {"O": [0.0, 0.0]}},
    "driver": {"kind": "crank", "link": 2, "pivot": "O", "joint": "A", "length": 0.1, "omega": 10.0},
    "groups": [{"kind": "RPP", "links": [3, 4], "joints": ["A", "B"], "guide": {"through": [0.0, 0.0], "angle": 0.0},
                "angle": 90.0}],
    "positions": {"count": 12},
}

BASES = {"RATCHET": RATCHET, "FOUR_BAR": FOUR_BAR, "SLIDER_CRANK": SLIDER_CRANK, "SLIDER_DRIVEN": SLIDER_DRIVEN,
         "SLOTTED_LEVER": SLOTTED_LEVER, "CROSSED_SLIDERS": CROSSED_SLIDERS, "SCOTCH_YOKE": SCOTCH_YOKE}


def first_error(text: str | bytes, driver: Any = None) -> tuple[str, GraphplanError]:
    """The stage (load, build, solve) whose GraphplanError stops ``text``, and that error.

    Any other exception propagates: on bad input the package raises only GraphplanError.
    """
    try:
        scene = scene_module.loads(text)
    except GraphplanError as error:
        return "load", error
    try:
        graphplan.build(scene)
    except GraphplanError as error:
        return "build", error
    try:
        graphplan.solve(scene, driver=driver)
    except GraphplanError as error:
        return "solve", error
    raise AssertionError("the scene was accepted: load, build and solve raised nothing")


@pytest.mark.parametrize("name", list(BASES))
def test_base_scene_is_valid(name: str) -> None:
    scene = scene_module.loads(to_toml(BASES[name]))
    motion = graphplan.solve(scene)
    assert motion.count == scene.positions.count


def test_writer_reproduces_the_bundled_fixture() -> None:
    ours = scene_module.loads(to_toml(variant(RATCHET, {"measured": DELETE, "output": DELETE})))
    theirs = graphplan.load(FIXTURE)
    assert ours.driver == theirs.driver and ours.groups == theirs.groups and ours.points == theirs.points
    assert ours.links == theirs.links and ours.loads == theirs.loads and ours.positions == theirs.positions


def test_error_classes_are_builtin_exceptions_too() -> None:
    assert issubclass(SceneError, GraphplanError) and issubclass(SceneError, ValueError)
    assert issubclass(AssemblyError, GraphplanError) and issubclass(AssemblyError, ValueError)
    assert issubclass(SingularPositionError, GraphplanError) and issubclass(SingularPositionError, ArithmeticError)
    error = SceneError("groups[0].lengths[1]", "must be > 0", -0.325)
    assert str(error) == "groups[0].lengths[1]: must be > 0 (got -0.325)"
    assert (error.where, error.problem, error.value) == ("groups[0].lengths[1]", "must be > 0", -0.325)
    assert str(SceneError("", "is empty")) == "is empty"


# --- the case table --------------------------------------------------------------------------


@dataclass(frozen=True)
class Case:
    """One malformed scene: ``changes`` applied to ``base``, the SceneError expected, and where it arises."""

    id: str
    changes: dict[str, Any]
    where: str
    problem: str
    stage: str = "load"
    base: str = "RATCHET"
    gap: str | None = None  # set when the package falls short: the case is then a strict xfail

    @property
    def message(self) -> str:
        return f"{self.where}: {self.problem}"


NAN, INF = float("nan"), float("inf")
UNKNOWN_AT_THIS_STAGE = ("is not known at this stage: it must be a frame point, a joint of the driver or "
                         "of an earlier group, or a named point of a link already found")

CASES: list[Case] = [
    # -- the document's own tables: missing, or of the wrong type
    Case("top-frame-missing", {"frame": DELETE}, "frame", "is required but missing: the fixed link's table: link = 1 "
         "and its points, points = { O = [x, y], … }"),
    Case("top-driver-missing", {"driver": DELETE}, "driver", "is required but missing: the input link's table: kind "
         "= \"crank\" or \"slider\", its link, joint and speed"),
    Case("top-frame-list", {"frame": [1, 2]}, "frame", "must be a table, not a list (got [1, 2])"),
    Case("top-driver-string", {"driver": "crank"}, "driver", "must be a table, not a string (got 'crank')"),
    Case("top-scene-string", {"scene": "ratchet"}, "scene", "must be a table, not a string (got 'ratchet')"),
    Case("top-groups-table", {"groups": {"kind": "RRR"}}, "groups",
         "must be a list, not a table (got { kind = \"RRR\" }); write [[groups]] (an array of tables), not [groups]"),
    Case("top-groups-item-number", {"groups": [1]}, "groups[0]", "must be a table, not an integer (got 1)"),
    Case("top-points-list", {"points": ["S2"]}, "points", "must be a table, not a list (got [\"S2\"])"),
    Case("top-links-list", {"links": [16.0]}, "links", "must be a table, not a list (got [16.0])"),
    Case("top-loads-table", {"loads": {"kind": "moment"}}, "loads",
         "must be a list, not a table (got { kind = \"moment\" }); write [[loads]] (an array of tables), not [loads]"),
    # A friction coefficient under another name, or an unknown key, is named before f is missed.
    Case("friction-mu-beside-f", {"friction": [{"joint": "O", "f": 0.1, "radius": 0.02, "mu": 0.2}]}, "friction[0].mu",
         "unknown key; the coefficient of friction is given as f, which this table has already: f = 0.1"),
    Case("friction-coefficient-for-f", {"friction": [{"joint": "O", "radius": 0.02, "coefficient": 0.1}]},
         "friction[0].coefficient", "unknown key; the coefficient of friction is given as f: write f = 0.1"),
    Case("friction-greek-mu-for-f", {"friction": [{"joint": "O", "radius": 0.02, "μ": 0.1}]},
         "friction[0].μ", "unknown key; the coefficient of friction is given as f: write f = 0.1"),
    Case("friction-unknown-key-before-f", {"friction": [{"joint": "O", "radius": 0.02, "fric": 0.1}]},
         "friction[0].fric", "unknown key"),
    Case("friction-f-missing", {"friction": [{"joint": "O", "radius": 0.02}]},
         "friction[0].f", "is required but missing: the coefficient of friction"),
    Case("friction-table", {"friction": {"joint": "O", "f": 0.1, "radius": 0.02}}, "friction",
         "must be a list, not a table (got { joint = \"O\", f = 0.1, radius = 0.02 }); write [[friction]] (an array "
         "of tables), not [friction]"),
    Case("top-loads-item-string", {"loads": ["moment"]}, "loads[0]", "must be a table, not a string (got 'moment')"),
    Case("top-positions-number", {"positions": 12}, "positions", "must be a table, not an integer (got 12)"),
    Case("top-drawing-bool", {"drawing": True}, "drawing", "must be a table, not a boolean (got True)"),
    Case("top-measured-list", {"measured": [5]}, "measured", "must be a table, not a list (got [5])"),
    Case("top-output-list", {"output": ["note"]}, "output", "must be a table, not a list (got [\"note\"])"),
    Case("top-unknown-key", {"pionts": {}}, "pionts", "unknown key; did you mean 'points'?"),
    Case("top-unknown-key-no-suggestion", {"colour": "red"}, "colour", "unknown key"),

    # -- [scene]
    Case("scene-title-number", {"scene.title": 3}, "scene.title", "must be a string, not an integer (got 3)"),
    Case("scene-title-empty", {"scene.title": "  "}, "scene.title", "must not be empty"),
    Case("scene-locale-unknown", {"scene.locale": "it"}, "scene.locale", "must be one of en, ru, zh (got 'it')"),
    Case("scene-locale-near-miss", {"scene.locale": "rus"}, "scene.locale",
         "must be one of en, ru, zh; did you mean 'ru'? (got 'rus')"),
    # China's country code and capitals, which a Chinese student tried: 'cn' was answered "did you mean 'en'?".
    Case("scene-locale-country", {"scene.locale": "cn"}, "scene.locale",
         "must be one of en, ru, zh; did you mean 'zh'? (got 'cn')"),
    Case("scene-locale-capitals", {"scene.locale": "ZH"}, "scene.locale",
         "must be one of en, ru, zh; did you mean 'zh'? (got 'ZH')"),
    Case("scene-locale-language-name", {"scene.locale": "中文"}, "scene.locale",
         "must be one of en, ru, zh; did you mean 'zh'? (got '中文')"),
    Case("scene-gravity-string", {"scene.gravity": "9.81"}, "scene.gravity",
         "must be a number, not a string (got '9.81'); TOML numbers take no quotes: write 9.81"),
    Case("scene-gravity-bool", {"scene.gravity": True}, "scene.gravity", "must be a number, not a boolean (got True)"),
    Case("scene-gravity-negative", {"scene.gravity": -9.81}, "scene.gravity", "must be >= 0 (got -9.81)"),
    Case("scene-gravity-nan", {"scene.gravity": NAN}, "scene.gravity", "must be a finite number (got nan)"),
    Case("scene-gravity-inf", {"scene.gravity": INF}, "scene.gravity", "must be a finite number (got inf)"),
    Case("scene-gravity-in-mm", {"scene.gravity": 9810.0}, "scene.gravity",
         "must be at most 30 m/s², more than any planet's (Jupiter's is 24.8) (got 9810.0); 9810.0 is Earth's g in "
         "mm/s²: the scene's is in m/s², write gravity = 9.81"),
    Case("scene-gravity-in-feet", {"scene.gravity": 32.174}, "scene.gravity",
         "must be at most 30 m/s², more than any planet's (Jupiter's is 24.8) (got 32.174); 32.174 is Earth's g in "
         "ft/s²: the scene's is in m/s², write gravity = 9.81"),
    Case("scene-gravity-no-planets", {"scene.gravity": 50.0}, "scene.gravity",
         "must be at most 30 m/s², more than any planet's (Jupiter's is 24.8) (got 50.0); Earth's is 9.81, 0 "
         "switches weight off"),
    Case("scene-unknown-key", {"scene.titel": "x"}, "scene.titel", "unknown key; did you mean 'title'?"),

    # -- [frame]
    Case("frame-link-zero", {"frame.link": 0}, "frame.link", "must be >= 1 (got 0)"),
    Case("frame-link-float", {"frame.link": 1.0}, "frame.link", "must be an integer, not a number (got 1.0)"),
    Case("frame-link-bool", {"frame.link": True}, "frame.link", "must be an integer, not a boolean (got True)"),
    Case("frame-points-list", {"frame.points": [[0.0, 0.0]]}, "frame.points",
         "must be a table, not a list (got [[0.0, 0.0]])"),
    Case("frame-point-one-coordinate", {"frame.points.O": [0.0]}, "frame.points.O", "must be a point [x, y] (got [0.0])"),
    Case("frame-point-table", {"frame.points.O": {"x": 0.0, "y": 0.0}}, "frame.points.O",
         "must be a point [x, y] (got { x = 0.0, y = 0.0 })"),
    Case("frame-point-string", {"frame.points.C": ["0", 0.55]}, "frame.points.C[0]",
         "must be a number, not a string (got '0'); TOML numbers take no quotes: write 0"),
    Case("frame-point-nan", {"frame.points.C": [0.0, NAN]}, "frame.points.C[1]", "must be a finite number (got nan)"),
    Case("frame-point-inf", {"frame.points.O": [-INF, 0.0]}, "frame.points.O[0]", "must be a finite number (got -inf)"),
    Case("frame-unknown-key", {"frame.pionts": {}}, "frame.pionts", "unknown key; did you mean 'points'?"),
    Case("frame-line-name", {"frame.lines": {"L": "M"}}, "frame.lines.L",
         "a frame line needs through and angle, on the frame"),
    Case("frame-line-on-moving-link", {"frame.lines": {"L": {"link": 2, "through": "A"}}}, "frame.lines.L",
         "a frame line needs through and angle, on the frame"),
    Case("frame-line-number", {"frame.lines": {"L": 0.0}}, "frame.lines.L", "must be a table, not a number (got 0.0)"),
    Case("frame-line-through-missing", {"frame.lines": {"L": {"angle": 0.0}}}, "frame.lines.L.through",
         "is required but missing: a point the line runs through: [x, y], or a point's name"),
    Case("frame-line-angle-nan", {"frame.lines": {"L": {"through": [0.0, 0.0], "angle": NAN}}}, "frame.lines.L.angle",
         "must be a finite number (got nan)"),
    Case("frame-line-unknown-key", {"frame.lines": {"L": {"through": [0.0, 0.0], "angel": 0.0}}},
         "frame.lines.L.angel", "unknown key; did you mean 'angle'?"),
    # A line read for a guide that names none of them: the slider runs on the inline guide, not the line meant.
    Case("frame-line-unused", {"frame.lines": {"ram": {"through": [0.0, 0.05], "angle": 0.0}}}, "frame.lines.ram",
         "no guide runs along this line: name it in the guide meant to run on it (guide = \"ram\"), or leave it out; "
         "groups[0].guide gives its line inline", stage="build", base="SLIDER_CRANK"),
    Case("frame-line-unused-beside-a-named-one",
         {"frame.lines": {"ram": {"through": [0.0, 0.0], "angle": 0.0}, "x–x": {"through": "O", "angle": 90.0}},
          "groups.0.guide": "ram"}, "frame.lines.x–x",
         "no guide runs along this line: name it in the guide meant to run on it (guide = \"x–x\"), or leave it out",
         stage="build", base="SLIDER_CRANK"),

    # -- [driver], a crank
    Case("crank-kind-missing", {"driver.kind": DELETE}, "driver.kind", "is required but missing: crank (the input "
         "link turns about a frame point) or slider (it moves along a guide)"),
    Case("crank-kind-unknown", {"driver.kind": "rocker"}, "driver.kind", "must be one of crank, slider (got 'rocker')"),
    Case("crank-kind-near-miss", {"driver.kind": "crnak"}, "driver.kind",
         "must be one of crank, slider; did you mean 'crank'? (got 'crnak')"),
    Case("crank-kind-number", {"driver.kind": 1}, "driver.kind", "must be a string, not an integer (got 1)"),
    Case("crank-link-missing", {"driver.link": DELETE}, "driver.link", "is required but missing: the number of the "
         "input link, as on the kinematic scheme"),
    Case("crank-link-zero", {"driver.link": 0}, "driver.link", "must be >= 1 (got 0)"),
    Case("crank-link-string", {"driver.link": "2"}, "driver.link",
         "must be an integer, not a string (got '2'); TOML numbers take no quotes: write 2"),
    Case("crank-link-is-frame", {"driver.link": 1}, "driver.link",
         "link 1 already belongs to the frame; a group's links are new", stage="build"),
    Case("crank-pivot-missing", {"driver.pivot": DELETE}, "driver.pivot", "is required but missing: the frame point "
         "the crank turns about"),
    Case("crank-pivot-number", {"driver.pivot": 0}, "driver.pivot", "must be a string, not an integer (got 0)"),
    Case("crank-pivot-unknown", {"driver.pivot": "Q"}, "driver.pivot",
         "must be a point of [frame] points: O, C (got 'Q')", stage="build"),
    Case("crank-joint-missing", {"driver.joint": DELETE}, "driver.joint", "is required but missing: the joint the "
         "input link moves, at its end, where the first group joins on"),
    Case("crank-joint-empty", {"driver.joint": ""}, "driver.joint", "must not be empty"),
    Case("crank-joint-is-frame-point", {"driver.joint": "C"}, "driver.joint",
         "'C' is already a frame point; the driver's joint is new", stage="build"),
    Case("crank-joint-is-pivot", {"driver.joint": "O"}, "driver.joint",
         "'O' is already a frame point; the driver's joint is new", stage="build"),
    Case("crank-length-missing", {"driver.length": DELETE}, "driver.length", "is required but missing: the crank's "
         "length from pivot to joint, m"),
    Case("crank-length-string", {"driver.length": "0.175"}, "driver.length",
         "must be a number, not a string (got '0.175'); TOML numbers take no quotes: write 0.175"),
    Case("crank-length-bool", {"driver.length": True}, "driver.length", "must be a number, not a boolean (got True)"),
    Case("crank-length-list", {"driver.length": [0.175]}, "driver.length", "must be a number, not a list (got [0.175])"),
    Case("crank-length-zero", {"driver.length": 0}, "driver.length", "must be > 0 (got 0)"),
    Case("crank-length-negative", {"driver.length": -0.175}, "driver.length", "must be > 0 (got -0.175)"),
    Case("crank-length-nan", {"driver.length": NAN}, "driver.length", "must be a finite number (got nan)"),
    Case("crank-length-inf", {"driver.length": INF}, "driver.length", "must be a finite number (got inf)"),
    Case("crank-omega-and-rpm", {"driver.rpm": -162.3}, "driver.rpm", "give either omega or rpm, not both"),
    Case("crank-omega-zero", {"driver.omega": 0.0}, "driver.omega", "must not be zero: the driver must move"),
    Case("crank-omega-integer-zero", {"driver.omega": 0}, "driver.omega", "must not be zero: the driver must move"),
    Case("crank-rpm-zero", {"driver.omega": DELETE, "driver.rpm": 0.0}, "driver.rpm",
         "must not be zero: the driver must move"),
    Case("crank-omega-missing", {"driver.omega": DELETE}, "driver.omega",
         "is required but missing: give omega (rad/s) or rpm (rev/min), signed (counter-clockwise positive)"),
    Case("crank-rpm-misspelt", {"driver.omega": DELETE, "driver.rpms": -162.3}, "driver.rpms",
         "unknown key; did you mean 'rpm'?"),
    Case("crank-omega-string", {"driver.omega": "-17"}, "driver.omega",
         "must be a number, not a string (got '-17'); TOML numbers take no quotes: write -17"),
    Case("crank-omega-nan", {"driver.omega": NAN}, "driver.omega", "must be a finite number (got nan)"),
    Case("crank-omega-minus-inf", {"driver.omega": -INF}, "driver.omega", "must be a finite number (got -inf)"),
    Case("crank-rpm-string", {"driver.omega": DELETE, "driver.rpm": "162"}, "driver.rpm",
         "must be a number, not a string (got '162'); TOML numbers take no quotes: write 162"),
    Case("crank-rpm-inf", {"driver.omega": DELETE, "driver.rpm": INF}, "driver.rpm", "must be a finite number (got inf)"),
    Case("crank-epsilon-nan", {"driver.epsilon": NAN}, "driver.epsilon", "must be a finite number (got nan)"),
    Case("crank-epsilon-bool", {"driver.epsilon": False}, "driver.epsilon",
         "must be a number, not a boolean (got False)"),
    Case("crank-unknown-key", {"driver.lenght": 0.2}, "driver.lenght", "unknown key; did you mean 'length'?"),
    Case("crank-unknown-key-omega", {"driver.omgea": 1.0}, "driver.omgea", "unknown key; did you mean 'omega'?"),
    Case("crank-slider-key", {"driver.travel": [0.0, 1.0]}, "driver.travel", "unknown key"),

    # -- [driver], a slider
    Case("slider-guide-missing", {"driver.guide": DELETE}, "driver.guide", "is required but missing: the line the "
         "slider moves along: a frame line's name, or { through = [x, y], angle = degrees }",
         base="SLIDER_DRIVEN"),
    Case("slider-guide-list", {"driver.guide": [0.0, 0.0]}, "driver.guide",
         "must be a table, not a list (got [0.0, 0.0])", base="SLIDER_DRIVEN"),
    Case("slider-guide-on-moving-link", {"driver.guide": {"link": 3, "through": "B"}}, "driver.guide",
         "a driving slider must slide on a frame guide", stage="build", base="SLIDER_DRIVEN"),
    Case("slider-guide-unknown-line", {"driver.guide": "rail"}, "driver.guide",
         "no frame line 'rail'; [frame] lines has none", stage="build", base="SLIDER_DRIVEN"),
    Case("slider-guide-unknown-point", {"driver.guide": {"through": "Z"}}, "driver.guide.through",
         "must be a point fixed on link 1: C, O (got 'Z')", stage="build", base="SLIDER_DRIVEN"),
    Case("slider-guide-unknown-key", {"driver.guide.angel": 0.0}, "driver.guide.angel",
         "unknown key; did you mean 'angle'?", base="SLIDER_DRIVEN"),
    Case("slider-velocity-missing", {"driver.velocity": DELETE}, "driver.velocity", "is required but missing: the "
         "slider's velocity along its guide, m/s",
         base="SLIDER_DRIVEN"),
    Case("slider-velocity-zero", {"driver.velocity": 0.0}, "driver.velocity",
         "must not be zero: the driver must move", base="SLIDER_DRIVEN"),
    Case("slider-velocity-nan", {"driver.velocity": NAN}, "driver.velocity", "must be a finite number (got nan)",
         base="SLIDER_DRIVEN"),
    Case("slider-acceleration-string", {"driver.acceleration": "0"}, "driver.acceleration",
         "must be a number, not a string (got '0'); TOML numbers take no quotes: write 0", base="SLIDER_DRIVEN"),
    Case("slider-travel-missing", {"driver.travel": DELETE}, "driver.travel", "is required but missing: [s0, s1], "
         "the stroke the positions run over, m along the guide from its through point",
         base="SLIDER_DRIVEN"),
    Case("slider-travel-empty-stroke", {"driver.travel": [0.2, 0.2]}, "driver.travel",
         "must span a stroke: [from, to] with from ≠ to (got [0.2, 0.2])", base="SLIDER_DRIVEN"),
    Case("slider-travel-three", {"driver.travel": [0.0, 0.1, 0.2]}, "driver.travel",
         "must have 2 entries, not 3 (got [0.0, 0.1, 0.2])", base="SLIDER_DRIVEN"),
    Case("slider-travel-number", {"driver.travel": 0.2}, "driver.travel", "must be a list, not a number (got 0.2)",
         base="SLIDER_DRIVEN"),
    Case("slider-travel-inf", {"driver.travel": [0.0, INF]}, "driver.travel[1]", "must be a finite number (got inf)",
         base="SLIDER_DRIVEN"),
    Case("slider-unknown-key", {"driver.omega": 1.0}, "driver.omega", "unknown key", base="SLIDER_DRIVEN"),
    Case("slider-positions-start", {"positions.start": 0.0}, "positions.start",
         "a slider driver's positions run over driver.travel: leave start out", base="SLIDER_DRIVEN"),

    # -- [[groups]]: what every kind shares
    Case("group-kind-missing", {"groups.0.kind": DELETE}, "groups[0].kind", "is required but missing: the group's "
         "kind: RRR, RRP, RPR, PRP, RPP or triad"),
    Case("group-kind-unknown", {"groups.0.kind": "cam"}, "groups[0].kind",
         "must be one of RRR, RRP, RPR, PRP, RPP, triad (got 'cam')"),
    Case("group-kind-near-miss", {"groups.0.kind": "RRRR"}, "groups[0].kind",
         "must be one of RRR, RRP, RPR, PRP, RPP, triad; did you mean 'RRR'? (got 'RRRR')"),
    Case("group-triad-with-two-links", {"groups.0.kind": "triad"}, "groups[0].links",
         "must have 4 entries, not 2 (got [3, 4])"),
    Case("group-links-missing", {"groups.0.links": DELETE}, "groups[0].links", "is required but missing: the numbers "
         "of the group's links, as on the kinematic scheme"),
    Case("group-links-string", {"groups.0.links": "3,4"}, "groups[0].links", "must be a list, not a string (got '3,4')"),
    Case("group-links-one", {"groups.0.links": [3]}, "groups[0].links", "must have 2 entries, not 1 (got [3])"),
    Case("group-links-item-string", {"groups.0.links": [3, "4"]}, "groups[0].links[1]",
         "must be an integer, not a string (got '4'); TOML numbers take no quotes: write 4"),
    Case("group-links-item-float", {"groups.0.links": [3.0, 4]}, "groups[0].links[0]",
         "must be an integer, not a number (got 3.0)"),
    Case("group-links-zero", {"groups.0.links": [0, 4]}, "groups[0].links[0]", "must be a link number >= 1 (got 0)"),
    Case("group-links-same", {"groups.0.links": [3, 3]}, "groups[0].links", "must name two different links (got [3, 3])"),
    Case("group-links-reuse-driver", {"groups.0.links": [2, 4]}, "groups[0].links",
         "link 2 already belongs to an earlier group; a group's links are new", stage="build"),
    Case("group-links-reuse-frame", {"groups.0.links": [3, 1]}, "groups[0].links",
         "link 1 already belongs to the frame; a group's links are new", stage="build"),
    Case("group-joints-missing", {"groups.0.joints": DELETE}, "groups[0].joints", "is required but missing: the "
         "names of the group's joints, its outer ones known from the driver or a group before it"),
    Case("group-joints-two", {"groups.0.joints": ["A", "B"]}, "groups[0].joints",
         "must have 3 entries, not 2 (got [\"A\", \"B\"])"),
    Case("group-joints-same", {"groups.0.joints": ["A", "A", "C"]}, "groups[0].joints",
         "must name different joints (got [\"A\", \"A\", \"C\"])"),
    Case("group-joints-number", {"groups.0.joints": [1, "B", "C"]}, "groups[0].joints[0]",
         "must be a string, not an integer (got 1)"),
    Case("group-joints-empty", {"groups.0.joints": ["A", "", "C"]}, "groups[0].joints[1]", "must not be empty"),
    Case("group-joint-unknown", {"groups.0.joints": ["A", "B", "X"]}, "groups[0].joints[2]",
         f"'X' {UNKNOWN_AT_THIS_STAGE}", stage="build"),
    Case("group-joint-unknown-near-miss", {"groups.0.joints": ["A", "B", "CC"]}, "groups[0].joints[2]",
         f"'CC' {UNKNOWN_AT_THIS_STAGE}; did you mean 'C'?", stage="build"),
    Case("group-new-joint-exists", {"groups.0.joints": ["A", "C", "O"]}, "groups[0].joints[1]",
         "'C' is already a known point; a group's inner joint is new", stage="build"),

    # -- RRR
    Case("rrr-lengths-missing", {"groups.0.lengths": DELETE}, "groups[0].lengths", "is required but missing: the "
         "lengths of the group's links between its joints, m, in the order its kind lists them"),
    Case("rrr-lengths-table", {"groups.0.lengths": {"AB": 0.55, "BC": 0.325}}, "groups[0].lengths",
         "must be a list, not a table (got { AB = 0.55, BC = 0.325 })"),
    Case("rrr-lengths-one", {"groups.0.lengths": [0.55]}, "groups[0].lengths", "must have 2 entries, not 1 (got [0.55])"),
    Case("rrr-lengths-negative", {"groups.0.lengths.1": -0.325}, "groups[0].lengths[1]", "must be > 0 (got -0.325)"),
    Case("rrr-lengths-zero", {"groups.0.lengths.0": 0}, "groups[0].lengths[0]", "must be > 0 (got 0)"),
    Case("rrr-lengths-nan", {"groups.0.lengths.1": NAN}, "groups[0].lengths[1]", "must be a finite number (got nan)"),
    Case("rrr-lengths-inf", {"groups.0.lengths.0": INF}, "groups[0].lengths[0]", "must be a finite number (got inf)"),
    Case("rrr-lengths-string", {"groups.0.lengths.0": "0.55"}, "groups[0].lengths[0]",
         "must be a number, not a string (got '0.55'); TOML numbers take no quotes: write 0.55"),
    Case("rrr-lengths-bool", {"groups.0.lengths.1": True}, "groups[0].lengths[1]",
         "must be a number, not a boolean (got True)"),
    Case("rrr-unknown-key-beside-lengths", {"groups.0.lenghts": [0.55, 0.325]}, "groups[0].lenghts",
         "unknown key; did you mean 'lengths'?"),
    Case("rrr-rrp-key", {"groups.0.length": 0.55}, "groups[0].length", "unknown key; did you mean 'lengths'?"),
    Case("rrr-assembly-unknown", {"groups.0.assembly": "up"}, "groups[0].assembly",
         "must be one of left, right (got 'up')"),
    Case("rrr-assembly-near-miss", {"groups.0.assembly": "lefft"}, "groups[0].assembly",
         "must be one of left, right; did you mean 'left'? (got 'lefft')"),
    Case("rrr-assembly-of-rrp", {"groups.0.assembly": "forward"}, "groups[0].assembly",
         "must be one of left, right (got 'forward')"),
    Case("rrr-assembly-and-near", {"groups.0.near": [0.3, 0.6]}, "groups[0].near",
         "give either assembly or near, not both"),
    Case("rrr-neither-assembly-nor-near", {"groups.0.assembly": DELETE}, "groups[0].assembly",
         "is required but missing: left or right chooses the branch the group assembles in (or near = [x, y], where "
         "its joint lies in a sketch)"),
    Case("rrr-near-short", {"groups.0.assembly": DELETE, "groups.0.near": [0.3]}, "groups[0].near",
         "must be a point [x, y] (got [0.3])"),
    Case("rrr-near-nan", {"groups.0.assembly": DELETE, "groups.0.near": [NAN, 0.6]}, "groups[0].near[0]",
         "must be a finite number (got nan)"),

    # -- RRP
    Case("rrp-length-missing", {"groups.0.length": DELETE}, "groups[0].length", "is required but missing: lAB, the "
         "length of link a from its outer joint A to the slider's joint B, m",
         base="SLIDER_CRANK"),
    Case("rrp-length-zero", {"groups.0.length": 0.0}, "groups[0].length", "must be > 0 (got 0.0)", base="SLIDER_CRANK"),
    Case("rrp-length-negative", {"groups.0.length": -0.4}, "groups[0].length", "must be > 0 (got -0.4)",
         base="SLIDER_CRANK"),
    Case("rrp-length-list", {"groups.0.length": [0.4]}, "groups[0].length",
         "must be a number, not a list (got [0.4])", base="SLIDER_CRANK"),
    Case("rrp-guide-missing", {"groups.0.guide": DELETE}, "groups[0].guide", "is required but missing: the line the "
         "slider moves along: a frame line's name, or { through = [x, y], angle = degrees }",
         base="SLIDER_CRANK"),
    Case("rrp-guide-number", {"groups.0.guide": 0.0}, "groups[0].guide", "must be a table, not a number (got 0.0)",
         base="SLIDER_CRANK"),
    Case("rrp-guide-through-missing", {"groups.0.guide.through": DELETE}, "groups[0].guide.through",
         "is required but missing: a point the line runs through: [x, y], or a point's name", base="SLIDER_CRANK"),
    Case("rrp-guide-through-short", {"groups.0.guide.through": [0.0]}, "groups[0].guide.through",
         "must be a point [x, y] (got [0.0])", base="SLIDER_CRANK"),
    Case("rrp-guide-angle-string", {"groups.0.guide.angle": "0"}, "groups[0].guide.angle",
         "must be a number, not a string (got '0'); TOML numbers take no quotes: write 0", base="SLIDER_CRANK"),
    Case("rrp-guide-angle-inf", {"groups.0.guide.angle": INF}, "groups[0].guide.angle",
         "must be a finite number (got inf)", base="SLIDER_CRANK"),
    Case("rrp-guide-link-zero", {"groups.0.guide": {"link": 0, "through": "O"}}, "groups[0].guide.link",
         "must be >= 1 (got 0)", base="SLIDER_CRANK"),
    Case("rrp-guide-unknown-key", {"groups.0.guide.angel": 0.0}, "groups[0].guide.angel",
         "unknown key; did you mean 'angle'?", base="SLIDER_CRANK"),
    Case("rrp-guide-coordinates-on-moving-link", {"groups.0.guide": {"link": 2, "through": [0.0, 0.0]}},
         "groups[0].guide.through", "on a moving link must name a point of link 2 (got [0.0, 0.0])",
         stage="build", base="SLIDER_CRANK"),
    Case("rrp-guide-unknown-line", {"groups.0.guide": "rail"}, "groups[0].guide",
         "no frame line 'rail'; [frame] lines has none", stage="build", base="SLIDER_CRANK"),
    Case("rrp-guide-unknown-line-with-lines",
         {"frame.lines": {"track": {"through": [0.0, 0.0]}}, "groups.0.guide": "rail"}, "groups[0].guide",
         "no frame line 'rail'; [frame] lines has track", stage="build", base="SLIDER_CRANK"),
    Case("rrp-guide-unknown-link", {"groups.0.guide": {"link": 9, "through": "A"}}, "groups[0].guide.link",
         "link 9 is not known before this group (got 9)", stage="build", base="SLIDER_CRANK"),
    Case("rrp-guide-on-own-link", {"groups.0.guide": {"link": 4, "through": "B"}}, "groups[0].guide.link",
         "link 4 is not known before this group (got 4)", stage="build", base="SLIDER_CRANK"),
    Case("rrp-guide-point-not-on-link", {"groups.0.guide": {"link": 2, "through": "Z"}}, "groups[0].guide.through",
         "must be a point fixed on link 2: A, O (got 'Z')", stage="build", base="SLIDER_CRANK"),
    Case("rrp-guide-point-not-on-frame", {"groups.0.guide": {"through": "A"}}, "groups[0].guide.through",
         "must be a point fixed on link 1: O (got 'A')", stage="build", base="SLIDER_CRANK"),
    Case("rrp-assembly-of-rrr", {"groups.0.assembly": "left"}, "groups[0].assembly",
         "must be one of forward, backward: an RRP's B stands ahead of the foot of A on the guide, along the guide's "
         "direction (forward), or behind it (backward); left and right are the sides of an RRR's line A→C (got 'left')",
         base="SLIDER_CRANK"),
    Case("rrp-neither-assembly-nor-near", {"groups.0.assembly": DELETE}, "groups[0].assembly",
         "is required but missing: forward or backward chooses the branch the group assembles in (or near = [x, y], "
         "where its joint lies in a sketch)", base="SLIDER_CRANK"),
    Case("rrp-unknown-key", {"groups.0.lenght": 0.4}, "groups[0].lenght", "unknown key; did you mean 'length'?",
         base="SLIDER_CRANK"),
    Case("rrp-joints-three", {"groups.0.joints": ["A", "B", "C"]}, "groups[0].joints",
         "must have 2 entries, not 3 (got [\"A\", \"B\", \"C\"])", base="SLIDER_CRANK"),

    # -- RPR
    Case("rpr-offset-string", {"groups.0.offset": "0.1"}, "groups[0].offset",
         "must be a number, not a string (got '0.1'); TOML numbers take no quotes: write 0.1", base="SLOTTED_LEVER"),
    Case("rpr-offset-nan", {"groups.0.offset": NAN}, "groups[0].offset", "must be a finite number (got nan)",
         base="SLOTTED_LEVER"),
    Case("rpr-unknown-key", {"groups.0.offest": 0.1}, "groups[0].offest", "unknown key; did you mean 'offset'?",
         base="SLOTTED_LEVER"),
    Case("rpr-joint-unknown", {"groups.0.joints": ["A", "D"]}, "groups[0].joints[1]",
         f"'D' {UNKNOWN_AT_THIS_STAGE}", stage="build", base="SLOTTED_LEVER"),

    # -- PRP
    Case("prp-guides-missing", {"groups.0.guides": DELETE}, "groups[0].guides", "is required but missing: [g1, g2], "
         "the lines the two sliders move along",
         base="CROSSED_SLIDERS"),
    Case("prp-guides-one", {"groups.0.guides": [{"through": [0.0, 0.0]}]}, "groups[0].guides",
         "must have 2 entries, not 1 (got [{ through = [0.0, 0.0] }])", base="CROSSED_SLIDERS"),
    Case("prp-guide-item-number", {"groups.0.guides.1": 90.0}, "groups[0].guides[1]",
         "must be a table, not a number (got 90.0)", base="CROSSED_SLIDERS"),
    Case("prp-guide-unknown-link", {"groups.0.guides.1": {"link": 9, "through": "A"}}, "groups[0].guides[1].link",
         "link 9 is not known before this group (got 9)", stage="build", base="CROSSED_SLIDERS"),
    Case("prp-guide-unknown-line", {"groups.0.guides.0": "rail"}, "groups[0].guides[0]",
         "no frame line 'rail'; [frame] lines has none", stage="build", base="CROSSED_SLIDERS"),
    Case("prp-offsets-string", {"groups.0.offsets": ["a", 0.0]}, "groups[0].offsets[0]",
         "must be a number, not a string (got 'a')", base="CROSSED_SLIDERS"),
    Case("prp-offsets-one", {"groups.0.offsets": [0.1]}, "groups[0].offsets",
         "must have 2 entries, not 1 (got [0.1])", base="CROSSED_SLIDERS"),
    Case("prp-unknown-key", {"groups.0.ofsets": [0.0, 0.0]}, "groups[0].ofsets",
         "unknown key; did you mean 'offsets'?", base="CROSSED_SLIDERS"),
    Case("prp-joint-exists", {"groups.0.joints": ["A"]}, "groups[0].joints[0]",
         "'A' is already a known point; a group's inner joint is new", stage="build", base="CROSSED_SLIDERS"),

    # -- RPP
    Case("rpp-slot-along-guide", {"groups.0.angle": 0.0}, "groups[0].angle",
         "the slot must not be parallel to the guide (got 0.0)", base="SCOTCH_YOKE"),
    Case("rpp-slot-against-guide", {"groups.0.angle": 180.0}, "groups[0].angle",
         "the slot must not be parallel to the guide (got 180.0)", base="SCOTCH_YOKE"),
    Case("rpp-angle-nan", {"groups.0.angle": NAN}, "groups[0].angle", "must be a finite number (got nan)",
         base="SCOTCH_YOKE"),
    Case("rpp-guide-missing", {"groups.0.guide": DELETE}, "groups[0].guide", "is required but missing: the line the "
         "slider moves along: a frame line's name, or { through = [x, y], angle = degrees }",
         base="SCOTCH_YOKE"),
    Case("rpp-guide-unknown-point", {"groups.0.guide": {"link": 2, "through": "B"}}, "groups[0].guide.through",
         "must be a point fixed on link 2: A, O (got 'B')", stage="build", base="SCOTCH_YOKE"),
    Case("rpp-unknown-key", {"groups.0.slot": 90.0}, "groups[0].slot", "unknown key", base="SCOTCH_YOKE"),

    # -- [points]
    Case("point-not-a-table", {"points.S2": 0.08}, "points.S2", "must be a table, not a number (got 0.08)"),
    Case("point-link-missing", {"points.S3.link": DELETE}, "points.S3.link", "is required but missing: the number of "
         "the link the point is fixed on"),
    Case("point-link-zero", {"points.S3.link": 0}, "points.S3.link", "must be >= 1 (got 0)"),
    Case("point-from-missing", {"points.S3.from": DELETE}, "points.S3.from", "is required but missing: the point it "
         "is placed from, at metres along from→toward"),
    Case("point-from-number", {"points.S3.from": 1}, "points.S3.from", "must be a string, not an integer (got 1)"),
    Case("point-toward-missing", {"points.S3.toward": DELETE}, "points.S3.toward", "is required but missing: the "
         "point that gives, from `from`, the direction the point is placed along"),
    Case("point-at-missing", {"points.S3.at": DELETE}, "points.S3.at", "is required but missing: how far the point "
         "lies from `from` toward `toward`, m"),
    Case("point-at-string", {"points.S3.at": "0.24"}, "points.S3.at",
         "must be a number, not a string (got '0.24'); TOML numbers take no quotes: write 0.24"),
    Case("point-at-nan", {"points.S3.at": NAN}, "points.S3.at", "must be a finite number (got nan)"),
    Case("point-offset-inf", {"points.E.offset": INF}, "points.E.offset", "must be a finite number (got inf)"),
    Case("point-unknown-key", {"points.S3.ofset": 0.1}, "points.S3.ofset", "unknown key; did you mean 'offset'?"),
    Case("point-named-like-joint", {"points.B": {"link": 3, "from": "A", "toward": "E", "at": 0.1}}, "points.B",
         "'B' is already the name of a joint groups[0] places (groups[0].joints[1]): name the point apart",
         stage="build"),
    Case("point-named-like-frame-point", {"points.C": {"link": 3, "from": "A", "toward": "B", "at": 0.1}}, "points.C",
         "'C' is already a frame point's name (frame.points.C): name the point apart", stage="build"),
    Case("point-on-unknown-link", {"points.S3.link": 9}, "points.S3.link",
         "no link 9 in the mechanism; links are 1, 2, 3, 4 (got 9)", stage="build"),
    Case("point-from-not-on-link", {"points.S3.from": "C"}, "points.S3.from",
         "'C' is not a point of link 3; its points are A, B, E; C is a point of the frame and of link 4",
         stage="build"),
    Case("point-toward-not-on-link", {"points.S4.toward": "A"}, "points.S4.toward",
         "'A' is not a point of link 4; its points are B, C; A is a point of link 2 and of link 3", stage="build"),
    Case("point-from-is-toward", {"points.S3.toward": "A"}, "points.S3.toward",
         "from and toward are both 'A'; they must be two points of link 3", stage="build"),
    Case("point-cycle", {"points.S": {"link": 3, "from": "T", "toward": "A", "at": 0.1},
                         "points.T": {"link": 3, "from": "S", "toward": "A", "at": 0.1}}, "points.S.from",
         "'T' refers back to 'S' through the named points S, T (a cyclic reference)", stage="build"),
    Case("point-refers-to-itself", {"points.S": {"link": 3, "from": "S", "toward": "A", "at": 0.1}}, "points.S.from",
         "'S' is the point itself; name two other points of link 3", stage="build"),
    Case("point-from-and-toward-coincide",
         {"frame.points.P": [0.0, 0.0], "points.Q": {"link": 1, "from": "O", "toward": "P", "at": 0.1}}, "points.Q",
         "from 'O' and toward 'P' coincide, so they give no direction", stage="solve"),

    # -- [links]
    Case("links-not-numbered", {"links.x": {"mass": 1.0}}, "links.x", "links are numbered: write [links.3]"),
    Case("links-zero", {"links.0": {"mass": 1.0}}, "links.0", "links are numbered: write [links.3]"),
    Case("links-entry-number", {"links.3": 17.0}, "links.3", "must be a table, not a number (got 17.0)"),
    Case("links-mass-negative", {"links.3.mass": -17.0}, "links.3.mass", "must be >= 0 (got -17.0)"),
    Case("links-mass-string", {"links.3.mass": "17"}, "links.3.mass",
         "must be a number, not a string (got '17'); TOML numbers take no quotes: write 17"),
    Case("links-mass-nan", {"links.3.mass": NAN}, "links.3.mass", "must be a finite number (got nan)"),
    Case("links-inertia-negative", {"links.4.inertia": -0.18}, "links.4.inertia", "must be >= 0 (got -0.18)"),
    Case("links-inertia-inf", {"links.4.inertia": INF}, "links.4.inertia", "must be a finite number (got inf)"),
    Case("links-centre-number", {"links.3.centre": 3}, "links.3.centre", "must be a string, not an integer (got 3)"),
    Case("links-unknown-key", {"links.3.center": "S3"}, "links.3.center", "unknown key; did you mean 'centre'?"),
    Case("links-mass-without-centre", {"links.3.centre": DELETE}, "links.3.centre",
         "a link with a mass needs its centre of mass: a point fixed on it"),
    Case("links-missing-link", {"links.9": {"mass": 1.0, "centre": "S3"}}, "links.9", "no link 9 in the mechanism; links are 1, 2, 3, 4",
         stage="build"),
    Case("links-centre-not-on-link", {"links.3.centre": "S4"}, "links.3.centre",
         "must be a point fixed on link 3: A, B, E, S3 (got 'S4')", stage="build"),
    Case("links-centre-unknown", {"links.2.centre": "S9"}, "links.2.centre",
         "must be a point fixed on link 2: A, O, S2 (got 'S9')", stage="build"),

    # -- [[loads]]
    Case("load-stroke-without-working", {"positions.working": DELETE, "positions.start": 0.0}, "loads[0].during",
         "a load that acts in one stroke needs positions.working (which motion of which link is the working stroke) "
         "(got { from = 0.0, to = 0.881 })", stage="build"),
    Case("load-kind-missing", {"loads.0.kind": DELETE}, "loads[0].kind", "is required but missing: moment (a couple "
         "on its link) or force (at a point of its link)"),
    Case("load-kind-unknown", {"loads.0.kind": "pressure"}, "loads[0].kind",
         "must be one of moment, force (got 'pressure')"),
    Case("load-kind-near-miss", {"loads.0.kind": "momnet"}, "loads[0].kind",
         "must be one of moment, force; did you mean 'moment'? (got 'momnet')"),
    Case("load-link-missing", {"loads.0.link": DELETE}, "loads[0].link", "is required but missing: the number of the "
         "link the load acts on"),
    Case("load-link-zero", {"loads.0.link": 0}, "loads[0].link", "must be >= 1 (got 0)"),
    Case("load-value-missing", {"loads.0.value": DELETE}, "loads[0].value", "is required but missing: the load's "
         "size, N·m for a moment, N for a force (or a diagram in its place)"),
    Case("load-value-string", {"loads.0.value": "1500"}, "loads[0].value",
         "must be a number, not a string (got '1500'); TOML numbers take no quotes: write 1500"),
    Case("load-value-nan", {"loads.0.value": NAN}, "loads[0].value", "must be a finite number (got nan)"),
    Case("load-resisting-negative", {"loads.0.value": -1500.0}, "loads[0].value",
         "a resisting load's value is its magnitude (resisting = true turns it against the motion): write 1500 "
         "(got -1500.0)"),
    Case("load-resisting-string", {"loads.0.resisting": "yes"}, "loads[0].resisting",
         "must be true or false, not a string (got 'yes')"),
    Case("load-resisting-number", {"loads.0.resisting": 1}, "loads[0].resisting",
         "must be true or false, not an integer (got 1)"),
    Case("load-during-unknown", {"loads.0.during": "sometimes"}, "loads[0].during",
         "must be one of working, idle, always (got 'sometimes')"),
    Case("load-during-near-miss", {"loads.0.during": "work"}, "loads[0].during",
         "must be one of working, idle, always; did you mean 'working'? (got 'work')"),
    Case("load-during-number", {"loads.0.during": 0.5}, "loads[0].during", "must be a string, not a number (got 0.5)"),
    Case("load-during-window-backwards", {"loads.0.during": {"from": 0.9, "to": 0.2}}, "loads[0].during",
         "must be a window 0 <= from < to <= 1 of the working stroke (got { from = 0.9, to = 0.2 })"),
    # Shown as the scene writes it, not as the tuple read from it ((0.0, 0.881), a teacher's variant).
    Case("load-during-window-with-a-swing", {"driver.swing": [300.0, 340.0], "positions.start": DELETE},
         "loads[0].during", "a window of the working stroke needs a crank that turns round; a crank driver's "
         "positions run over its swing, once: give the whole stroke, during = \"working\" or \"idle\", or "
         "\"always\" (got { from = 0.0, to = 0.881 })", stage="build"),
    Case("load-during-window-past-end", {"loads.0.during.to": 1.5}, "loads[0].during",
         "must be a window 0 <= from < to <= 1 of the working stroke (got { from = 0.0, to = 1.5 })"),
    Case("load-during-window-to-missing", {"loads.0.during.to": DELETE}, "loads[0].during.to",
         "is required but missing: the share of the working stroke (0 to 1) where the load stops acting"),
    Case("load-during-window-nan", {"loads.0.during.from": NAN}, "loads[0].during.from",
         "must be a finite number (got nan)"),
    Case("load-during-window-unknown-key", {"loads.0.during.too": 1.0}, "loads[0].during.too",
         "unknown key; did you mean 'to'?"),
    Case("load-force-without-point", {"loads.0.kind": "force"}, "loads[0].point",
         "is required but missing: a force needs point, where it acts: a point fixed on its link (a joint or one of "
         "[points])"),
    Case("load-force-without-angle", {"loads.0.kind": "force", "loads.0.point": "B"}, "loads[0].angle",
         "is required but missing: a force needs angle, its direction in degrees from +x (counter-clockwise), or "
         "along, the point whose line to its point it acts along"),
    Case("load-angle-string", {"loads.0.kind": "force", "loads.0.point": "B", "loads.0.angle": "90"},
         "loads[0].angle", "must be a number, not a string (got '90'); TOML numbers take no quotes: write 90"),
    Case("load-unknown-key", {"loads.0.resistant": True}, "loads[0].resistant",
         "unknown key; did you mean 'resisting'?"),
    Case("load-diagram-with-value", {"loads.0.diagram": [[0.0, 0.0], [1.0, 1500.0]]}, "loads[0].diagram",
         "a load diagram gives the values and the window itself: leave out value and during"),
    Case("load-diagram-one-point", {"loads.0.value": DELETE, "loads.0.during": DELETE, "loads.0.diagram": [[0.5, 1.0]]},
         "loads[0].diagram", "must have at least two points [share of the working stroke, value]"),
    Case("load-diagram-falling", {"loads.0.value": DELETE, "loads.0.during": DELETE,
                                  "loads.0.diagram": [[0.5, 1.0], [0.2, 2.0]]},
         "loads[0].diagram", ("shares of the working stroke must rise strictly within 0..1: 0 where the stroke starts, "
                              "1 where it ends (got [0.5, 0.2])")),
    Case("load-diagram-past-end", {"loads.0.value": DELETE, "loads.0.during": DELETE,
                                   "loads.0.diagram": [[0.5, 1.0], [1.2, 2.0]]},
         "loads[0].diagram", ("shares of the working stroke must rise strictly within 0..1 (shares, not crank angles "
                              "in degrees or the travel in metres or mm): 0 where the stroke starts, 1 where it ends "
                              "(got [0.5, 1.2])")),
    Case("load-diagram-all-zero", {"loads.0.value": DELETE, "loads.0.during": DELETE,
                                   "loads.0.diagram": [[0.0, 0.0], [1.0, 0.0]]},
         "loads[0].diagram", "must have a value other than zero"),
    Case("load-diagram-not-a-pair", {"loads.0.value": DELETE, "loads.0.during": DELETE,
                                     "loads.0.diagram": [[0.0, 0.0], 1.0]},
         "loads[0].diagram[1]", "must be a point [x, y] (got 1.0)"),
    Case("forces-inertia-unknown", {"forces": {"inertia": "resultant"}}, "forces.inertia",
         "must be one of couple, displaced (got 'resultant')"),
    Case("forces-unknown-key", {"forces": {"inertial": "displaced"}}, "forces.inertial",
         "unknown key; did you mean 'inertia'?"),
    Case("load-on-missing-link", {"loads.0.link": 9}, "loads[0].link", "no link 9 in the mechanism (got 9)",
         stage="build"),
    Case("load-point-not-on-link", {"loads.0.kind": "force", "loads.0.point": "A", "loads.0.angle": 90.0},
         "loads[0].point", "must be a point fixed on link 4: B, C, S4 (got 'A')", stage="build"),

    # -- [positions]
    Case("positions-count-zero", {"positions.count": 0}, "positions.count", "must be >= 1 (got 0)"),
    Case("positions-count-negative", {"positions.count": -12}, "positions.count", "must be >= 1 (got -12)"),
    Case("positions-count-too-many", {"positions.count": 20_001}, "positions.count",
         "must be <= 20000: a run takes about a minute for 20000, and minutes and gigabytes beyond (got 20001)"),
    Case("positions-count-float", {"positions.count": 12.0}, "positions.count",
         "must be an integer, not a number (got 12.0)"),
    Case("positions-count-string", {"positions.count": "12"}, "positions.count",
         "must be an integer, not a string (got '12'); TOML numbers take no quotes: write 12"),
    Case("positions-count-bool", {"positions.count": True}, "positions.count",
         "must be an integer, not a boolean (got True)"),
    Case("positions-start-unknown", {"positions.start": "middle"}, "positions.start",
         "must be \"extreme\" or a crank angle in degrees, a number: start = 30.0 (got 'middle')"),
    Case("positions-start-near-miss", {"positions.start": "extremes"}, "positions.start",
         "must be \"extreme\" or a crank angle in degrees, a number: start = 30.0 (got 'extremes'); did you mean "
         "'extreme'?"),
    # An angle is a number: one quoted with its degree sign was told that only "extreme" may be given.
    Case("positions-start-degrees-quoted", {"positions.start": "30°"}, "positions.start",
         "must be \"extreme\" or a crank angle in degrees, a number: start = 30 (got '30°')"),
    Case("positions-start-russian", {"positions.start": "крайнее"}, "positions.start",
         "must be \"extreme\" or a crank angle in degrees, a number: start = 30.0 (got 'крайнее'); did you mean "
         "'extreme'?"),
    Case("positions-start-bool", {"positions.start": True}, "positions.start",
         "must be a number, not a boolean (got True)"),
    Case("positions-start-nan", {"positions.start": NAN}, "positions.start", "must be a finite number (got nan)"),
    Case("positions-extreme-without-working", {"positions.working": DELETE}, "positions.working",
         "is required by start = \"extreme\": working = { link, sense } names the motion whose extreme the positions "
         "start at (or give start a crank angle in degrees)"),
    Case("positions-number-from-two", {"positions.number_from": 2}, "positions.number_from", "must be <= 1 (got 2)"),
    Case("positions-number-from-negative", {"positions.number_from": -1}, "positions.number_from",
         "must be >= 0 (got -1)"),
    Case("positions-working-string", {"positions.working": "4"}, "positions.working",
         "must be a table, not a string (got '4')"),
    Case("positions-working-link-missing", {"positions.working.link": DELETE}, "positions.working.link",
         "is required but missing: the number of the link whose motion makes the working stroke"),
    Case("positions-working-sense-missing", {"positions.working.sense": DELETE}, "positions.working.sense",
         "is required but missing: ccw or cw for a turning link, forward or backward (along its guide) for a sliding "
         "one: its motion in the stroke"),
    Case("positions-working-sense-unknown", {"positions.working.sense": "up"}, "positions.working.sense",
         "must be one of ccw, cw, forward, backward (got 'up'); a slider's sense is along its guide: forward the way "
         "the guide's angle points, backward against it, so up is forward along a guide at angle = 90 and backward "
         "along one at angle = -90 (a turning link's sense is ccw or cw)"),
    Case("positions-working-sense-near-miss", {"positions.working.sense": "cww"}, "positions.working.sense",
         "must be one of ccw, cw, forward, backward; did you mean 'cw'? (got 'cww')"),
    Case("positions-working-unknown-key", {"positions.working.sens": "cw"}, "positions.working.sens",
         "unknown key; did you mean 'sense'?"),
    Case("positions-working-missing-link", {"positions.working.link": 9}, "positions.working.link",
         "must be a moving link of the mechanism: 2, 3, 4 (got 9)", stage="build"),
    Case("positions-working-frame", {"positions.working.link": 1}, "positions.working.link",
         "must be a moving link of the mechanism: 2, 3, 4 (got 1)", stage="build"),
    Case("positions-working-translating-ccw", {"positions.working.sense": "ccw"}, "positions.working.sense",
         "link 4 translates: use forward or backward (along its guide) (got 'ccw')", stage="build",
         base="SLIDER_CRANK"),
    Case("positions-working-turning-forward", {"positions.working.link": 3}, "positions.working.sense",
         "link 3 turns: use ccw or cw (got 'forward')", stage="build", base="SLIDER_CRANK"),
    # The crank itself turns round: its diagrams may be drawn, but it has no extreme to start at, nor strokes.
    Case("positions-working-turns-round-start-extreme", {"positions.working.link": 2, "positions.working.sense": "cw"},
         "positions.start", '"extreme" needs the extreme positions of the output link, but link 2 turns round and '
         "never reverses its motion, so it has no extreme position: start the positions at a crank angle in degrees "
         "(got 'extreme')", stage="solve"),
    Case("positions-working-turns-round-load-window", {"positions.working.link": 2, "positions.working.sense": "cw",
                                                       "positions.start": 0.0},
         "loads[0].during", "a window of the working stroke needs the strokes of the output link, but link 2 turns "
         "round and never reverses its motion, so it has no extreme position for one to begin at: use always "
         "(got { from = 0.0, to = 0.881 })", stage="solve"),
    Case("positions-plans-past-end", {"positions.plans": [5, 12]}, "positions.plans[1]",
         "must be a position number from 0 to 11 (got 12)"),
    Case("positions-plans-negative", {"positions.plans": [-1]}, "positions.plans[0]",
         "must be a position number from 0 to 11 (got -1)"),
    Case("positions-plans-zero-numbered-from-one", {"positions.number_from": 1, "positions.plans": [0],
                                                   "measured": DELETE}, "positions.plans[0]",
         "must be a position number from 1 to 12 (got 0)"),
    Case("positions-plans-string", {"positions.plans": ["5"]}, "positions.plans[0]",
         "must be an integer, not a string (got '5'); TOML numbers take no quotes: write 5"),
    Case("positions-plans-float", {"positions.plans": [5.0]}, "positions.plans[0]",
         "must be an integer, not a number (got 5.0)"),
    Case("positions-plans-repeated", {"positions.plans": [5, 5, 11]}, "positions.plans[1]",
         "position 5 is already listed at positions.plans[0] (got 5)"),
    Case("positions-plans-number", {"positions.plans": 5}, "positions.plans", "must be a list, not an integer (got 5)"),
    Case("positions-unknown-key", {"positions.cuont": 12}, "positions.cuont", "unknown key; did you mean 'count'?"),

    # -- [drawing]
    Case("drawing-length-scale-zero", {"drawing.length_scale": 0}, "drawing.length_scale", "must be > 0 (got 0)"),
    Case("drawing-length-scale-negative", {"drawing.length_scale": -0.0025}, "drawing.length_scale",
         "must be > 0 (got -0.0025)"),
    Case("drawing-length-scale-nan", {"drawing.length_scale": NAN}, "drawing.length_scale",
         "must be a finite number (got nan)"),
    Case("drawing-velocity-pole-string", {"drawing.velocity_pole": "150"}, "drawing.velocity_pole",
         "must be a number, not a string (got '150'); TOML numbers take no quotes: write 150"),
    Case("drawing-acceleration-pole-inf", {"drawing.acceleration_pole": INF}, "drawing.acceleration_pole",
         "must be a finite number (got inf)"),
    Case("drawing-precision-zero", {"drawing.drafting_precision": 0.0}, "drawing.drafting_precision",
         "must be > 0 (got 0.0)"),
    Case("drawing-velocity-scale-negative", {"drawing.velocity_pole": DELETE, "drawing.velocity_scale": -0.02},
         "drawing.velocity_scale", "must be > 0 (got -0.02)"),
    Case("drawing-velocity-pole-and-scale", {"drawing.velocity_scale": 0.02},
         "drawing.velocity_scale", "give either velocity_pole or velocity_scale, not both"),
    Case("drawing-acceleration-pole-and-scale", {"drawing.acceleration_scale": 0.5},
         "drawing.acceleration_scale", "give either acceleration_pole or acceleration_scale, not both"),
    Case("drawing-sheet-unknown", {"drawing.sheet": "letter"}, "drawing.sheet",
         "must be one of A1, A2, A3, A4, none (got 'letter')"),
    Case("drawing-sheet-near-miss", {"drawing.sheet": "A3x"}, "drawing.sheet",
         "must be one of A1, A2, A3, A4, none; did you mean 'A3'? (got 'A3x')"),
    Case("drawing-sheet-smaller-size", {"drawing.sheet": "A5"}, "drawing.sheet",
         "is a paper size the sheets are not laid out on: A4 is the smallest of A1, A2, A3, A4 (or none for no course "
         "sheets) (got 'A5')"),
    Case("drawing-sheet-number", {"drawing.sheet": 1}, "drawing.sheet", "must be a string, not an integer (got 1)"),
    Case("drawing-unknown-key", {"drawing.sheets": "A1"}, "drawing.sheets", "unknown key; did you mean 'sheet'?"),
    Case("drawing-force-scale-zero", {"drawing.force_scale": 0.0}, "drawing.force_scale", "must be > 0 (got 0.0)"),
    Case("drawing-force-scale-string", {"drawing.force_scale": "20 N/mm"}, "drawing.force_scale",
         "must be a number, not a string (got '20 N/mm')"),

    # -- [measured]
    Case("measured-not-numbered", {"measured.five": {"velocity": {"pb": 39.0}}}, "measured.five",
         "must be a position number: write [measured.5]"),
    Case("measured-entry-number", {"measured.5": 39.0}, "measured.5", "must be a table, not a number (got 39.0)"),
    Case("measured-plan-number", {"measured.5.velocity": 39.0}, "measured.5.velocity",
         "must be a table, not a number (got 39.0)"),
    Case("measured-reading-string", {"measured.5.velocity.pb": "39"}, "measured.5.velocity.pb",
         "must be a number, not a string (got '39'); TOML numbers take no quotes: write 39"),
    Case("measured-reading-negative", {"measured.5.velocity.pb": -39.0}, "measured.5.velocity.pb",
         "must be >= 0: a reading is the segment's length, give 39; its sense is taken from the construction, as the "
         "ω and ε it gives take the plan's (got -39.0)"),
    Case("measured-reading-nan", {"measured.5.acceleration.pb": NAN}, "measured.5.acceleration.pb",
         "must be a finite number (got nan)"),
    Case("measured-force-negative", {"measured.5.forces": {"R23": -52.5}}, "measured.5.forces.R23",
         "must be >= 0: a reading is the segment's length, give 52.5; its sense is taken from the force analysis "
         "(got -52.5)"),
    Case("measured-forces-list", {"measured.5.forces": [52.5]}, "measured.5.forces",
         "must be a table, not a list (got [52.5])"),
    Case("measured-unknown-key", {"measured.5.velocty": {"pb": 39.0}}, "measured.5.velocty",
         "unknown key; did you mean 'velocity'?"),
    # A Russian word for the plan measured, and one that is no word for any.
    Case("measured-russian-word", {"measured.5.скорость": {"pb": 39.0}}, "measured.5.скорость",
         "unknown key; did you mean 'velocity'?"),
    Case("measured-unknown-key-listed", {"measured.5.замер": {"pb": 39.0}}, "measured.5.замер",
         "unknown key; the keys here are acceleration, balancing, forces, velocity"),
    Case("measured-not-in-plans", {"measured.7": {"velocity": {"pb": 39.0}}}, "measured.7",
         "position 7 is not in positions.plans [5, 11] nor in positions.velocity_plans", stage="build"),
    Case("measured-not-in-velocity-plans", {"positions.velocity_plans": [1, 2], "measured.7": {"velocity": {"pb": 39.0}}},
         "measured.7", "position 7 is not in positions.plans [5, 11] nor in positions.velocity_plans [1, 2]",
         stage="build"),
    # Past the last position, "all" velocity plans or not, the position is not there at all.
    Case("measured-no-such-position", {"positions.velocity_plans": "all", "measured.99": {"velocity": {"pb": 39.0}}},
         "measured.99", "no position 99; positions are 0..11", stage="build"),

    # -- [output]
    Case("output-include-string", {"output.include": "all"}, "output.include", "must be a list, not a string (got 'all')"),
    Case("output-include-unknown", {"output.include": ["positions", "plans"]}, "output.include[1]",
         "must be one of positions, velocity, acceleration, diagrams, load_diagrams, forces, lever, errors, accuracy, "
         "note, dynamics, balancing, vibration, sheets, figures (got 'plans')"),
    Case("output-include-near-miss", {"output.include": ["velocities"]}, "output.include[0]",
         "must be one of positions, velocity, acceleration, diagrams, load_diagrams, forces, lever, errors, accuracy, "
         "note, dynamics, balancing, vibration, sheets, figures; did you mean 'velocity'? (got 'velocities')"),
    Case("output-include-number", {"output.include": [1]}, "output.include[0]",
         "must be a string, not an integer (got 1)"),
    Case("output-unknown-key", {"output.include": DELETE, "output.includes": ["note"]}, "output.includes",
         "unknown key; did you mean 'include'?"),
]


def test_case_ids_are_unique() -> None:
    ids = [case.id for case in CASES]
    assert len(ids) == len(set(ids))


def _params(cases: list[Case]) -> list[Any]:
    return [pytest.param(case, id=case.id,
                         marks=[pytest.mark.xfail(strict=True, raises=AssertionError, reason=case.gap)] if case.gap else [])
            for case in cases]


@pytest.mark.parametrize("case", _params(CASES))
def test_scene_error(case: Case) -> None:
    stage, error = first_error(to_toml(variant(BASES[case.base], case.changes)))
    assert type(error) is SceneError, f"{type(error).__name__}: {error}"
    assert (stage, str(error)) == (case.stage, case.message)
    assert error.where == case.where
    assert isinstance(error, ValueError)


# --- groups that need a second group ---------------------------------------------------------


def two_groups(second: dict[str, Any], *, second_first: bool = False) -> str:
    """The ratchet scene with a second group after (or, wrongly, before) the first."""
    groups = [copy.deepcopy(RATCHET["groups"][0]), second]
    return to_toml(variant(RATCHET, {"groups": groups[::-1] if second_first else groups}))


def test_group_uses_a_joint_found_only_by_a_later_group() -> None:
    second = {"kind": "RRR", "links": [5, 6], "joints": ["B", "D", "C"], "lengths": [0.3, 0.4], "assembly": "left"}
    stage, error = first_error(two_groups(second, second_first=True))
    assert stage == "build" and type(error) is SceneError
    assert str(error) == f"groups[0].joints[0]: 'B' {UNKNOWN_AT_THIS_STAGE}"


def test_a_group_whose_joints_were_typed_in_each_others_places_is_told_them_in_their_places() -> None:
    """An RRP after the four-bar joined to a point E of the coupler, its joints typed ["F", "E"]: E, placed by
    [points], was refused only as "already a joint's name". The refusal names the group and gives its joints in their
    places, and the scene with them so builds."""
    second = {"kind": "RRP", "links": [5, 6], "joints": ["F", "E"], "length": 0.6,
              "guide": {"through": [0.0, -0.2], "angle": 0.0}, "assembly": "forward"}
    point = {"link": 3, "from": "A", "toward": "B", "at": 0.3, "offset": 0.1}
    scene = variant(RATCHET, {"groups": [copy.deepcopy(RATCHET["groups"][0]), second], "points.E": point})
    stage, error = first_error(to_toml(scene))
    assert stage == "build" and type(error) is SceneError
    assert str(error) == ("""points.E: 'E' is already the name of a joint groups[1] places (groups[1].joints[1]), """
                          """and 'F', which groups[1] joins to, is placed nowhere; its joints typed in each other's """
                          """places? groups[1].joints = ["E", "F"] joins it to E and places F; else name the point """
                          """apart""")
    second["joints"] = ["E", "F"]
    graphplan.build(scene_module.loads(to_toml(scene)))


@pytest.mark.parametrize("typed", [["B", "A", "C"], ["A", "C", "B"]])
def test_an_rrr_whose_joints_were_typed_in_each_others_places_is_told_them_in_their_places(typed) -> None:
    scene = variant(RATCHET, {"groups": [{**copy.deepcopy(RATCHET["groups"][0]), "joints": typed}]})
    stage, error = first_error(to_toml(scene))
    assert stage == "build" and type(error) is SceneError
    assert str(error) == (f"groups[0].joints[{typed.index('B')}]: 'B' {UNKNOWN_AT_THIS_STAGE}; its joints typed in "
                          """each other's places? groups[0].joints = ["A", "B", "C"] joins it to A and C and """
                          "places B")


def test_a_group_whose_links_were_typed_in_each_others_places_is_told_them_in_their_places() -> None:
    """The four-bar's links typed [4, 3]: the coupler's centre S3, placed from A toward B on link 3, was refused as
    "'A' is not a point of link 3" alone; the refusal now gives the links in their places, with which it builds."""
    group = {**copy.deepcopy(RATCHET["groups"][0]), "links": [4, 3]}
    stage, error = first_error(to_toml(variant(RATCHET, {"groups": [group]})))
    assert stage == "build" and type(error) is SceneError
    assert str(error) == ("points.S3.from: 'A' is not a point of link 3; its points are B, C; A is a point of link 2 "
                          "and of link 4; the links typed in each other's places? groups[0].links = [3, 4] fixes A "
                          "and B on link 3")
    group["links"] = [3, 4]
    graphplan.build(scene_module.loads(to_toml(variant(RATCHET, {"groups": [group]}))))


def test_second_group_reuses_a_link() -> None:
    second = {"kind": "RRR", "links": [4, 5], "joints": ["B", "D", "C"], "lengths": [0.3, 0.4], "assembly": "left"}
    stage, error = first_error(two_groups(second))
    assert stage == "build" and type(error) is SceneError
    assert str(error) == "groups[1].links: link 4 already belongs to an earlier group; a group's links are new"


def test_second_group_finds_a_joint_the_first_found() -> None:
    second = {"kind": "RRR", "links": [5, 6], "joints": ["A", "B", "C"], "lengths": [0.3, 0.4], "assembly": "left"}
    stage, error = first_error(two_groups(second))
    assert stage == "build" and type(error) is SceneError
    assert str(error) == "groups[1].joints[1]: 'B' is already a known point; a group's inner joint is new"


def test_second_group_guide_on_a_link_of_the_first() -> None:
    """A guide on a moving link names a point fixed on that link; here one that is not."""
    second = {"kind": "RRP", "links": [5, 6], "joints": ["B", "D"], "length": 0.3,
              "guide": {"link": 3, "through": "C"}, "assembly": "forward"}
    stage, error = first_error(two_groups(second))
    assert stage == "build" and type(error) is SceneError
    assert str(error) == "groups[1].guide.through: must be a point fixed on link 3: A, B, E, S3 (got 'C')"


# --- a group joined to the frame alone stands still ------------------------------------------------


@pytest.mark.parametrize(("second", "message"), [
    # O and C are the frame's points: a rigid triangle on the frame (a mistyped "A" for "O" does this).
    ({"kind": "RRR", "links": [5, 6], "joints": ["O", "D", "C"], "lengths": [0.3, 0.4], "assembly": "left"},
     "groups[1].joints: joins the frame alone (its outer joints O, C are frame points), so the group cannot move"),
    ({"kind": "RRP", "links": [5, 6], "joints": ["O", "D"], "length": 0.3, "guide": {"through": "C", "angle": 10.0},
      "assembly": "forward"},
     ("groups[1].joints: joins the frame alone (its outer joint O is a frame point and its guide is on the frame), "
      "so the group cannot move")),
    ({"kind": "PRP", "links": [5, 6], "joints": ["D"], "guides": [{"through": "O", "angle": 0.0},
                                                                 {"through": "C", "angle": 90.0}]},
     "groups[1].guides: joins the frame alone (its guides are on the frame), so the group cannot move"),
], ids=["RRR", "RRP", "PRP"])
def test_a_group_joined_to_the_frame_alone_is_refused(second, message) -> None:
    stage, error = first_error(two_groups(second))
    assert stage == "build" and type(error) is SceneError
    assert str(error).startswith(message), str(error)


def test_a_group_joined_to_a_moving_link_by_a_guide_alone_moves() -> None:
    """Both outer joints on the frame, but the guide on the rocker 4: the rocker moves the group."""
    second = {"kind": "RRP", "links": [5, 6], "joints": ["O", "D"], "length": 0.6,
              "guide": {"link": 4, "through": "C", "angle": 10.0}, "assembly": "forward"}
    mechanism = graphplan.build(scene_module.loads(two_groups(second)))
    assert mechanism.structure.endswith("II2(5,6)")


# --- the file itself: bytes, syntax, size, existence ----------------------------------------


def test_non_utf8_bytes() -> None:
    """The first byte that is not UTF-8 is told where an editor shows it, by line and column."""
    text = to_toml(RATCHET).replace("Crank-rocker", "Kurbelschwinge für")
    stage, error = first_error(text.encode("cp1252"))
    assert stage == "load" and type(error) is SceneError
    before = text[:text.index("ü")]
    line, column = before.count("\n") + 1, len(before) - before.rfind("\n")
    assert str(error) == f"<scene>: is not UTF-8 text (line {line}, column {column}: byte 0xFC); save it as UTF-8"
    assert error.where == "<scene>"


def test_non_utf8_file(tmp_path: Path) -> None:
    path = tmp_path / "cp1251.toml"
    # An editor's byte-order mark is not counted in the columns: 'К' is the tenth character of its line.
    path.write_bytes(codecs.BOM_UTF8 + '[scene]\ntitle = "Кривошип"\n'.encode("cp1251"))
    with pytest.raises(SceneError) as caught:
        graphplan.load(path)
    assert str(caught.value) == f"{path}: is not UTF-8 text (line 2, column 10: byte 0xCA); save it as UTF-8"
    assert caught.value.where == str(path)


@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-le", "utf-16-be"])
def test_a_utf16_file_is_told_to_be_saved_as_utf8(tmp_path: Path, encoding: str) -> None:
    """Windows editors save "Unicode" as UTF-16, with a byte-order mark or without: it was "not UTF-8 text (byte 0)",
    or a TOML error where the zero bytes between its letters were read as text."""
    path = tmp_path / "utf16.toml"
    path.write_bytes(to_toml(RATCHET).encode(encoding))
    with pytest.raises(SceneError) as caught:
        graphplan.load(path)
    assert str(caught.value) == f"{path}: is not UTF-8 text but UTF-16: save it as UTF-8"


@pytest.mark.parametrize("text, line", [
    ('[scene]\ntitle = "x"\n[frame\n', 3),                       # unclosed table header
    ('[scene]\ntitle = "x"\ngravity 9.81\n', 3),                 # no '='
    ('[scene]\ntitle = "x"\ntitle = "y"\n', 3),                  # a key given twice
    ('[driver]\nlength = 0.175.0\n', 2),                         # a malformed number
    ('[driver]\nomega = NaN\n', 2),                              # TOML spells it nan
], ids=["unclosed-header", "no-equals", "duplicate-key", "bad-number", "capital-nan"])
def test_invalid_toml(text: str, line: int) -> None:
    stage, error = first_error(text)
    assert stage == "load" and type(error) is SceneError
    assert str(error).startswith("<scene>: is not valid TOML: ")
    assert f"line {line}" in str(error)
    assert error.__cause__ is None and error.__suppress_context__


@pytest.mark.parametrize(("measured", "where", "problem"), [
    ({"velocity": {"рb": 38.82}}, "measured.5.velocity.рb",
     ("is not two letters of the plan (a, b, e, p, s2, s3, s4); 'рb' has the Cyrillic 'р' (U+0440) where 'pb' has "
      "the Latin 'p' (U+0070): type the Latin letter")),
    ({"velocity": {"PB": 38.82}}, "measured.5.velocity.PB",
     "is not two letters of the plan (a, b, e, p, s2, s3, s4); the plan's letters are small: write pb"),
    ({"velocity": {"πb": 38.82}}, "measured.5.velocity.πb",
     ("is not two letters of the plan (a, b, e, p, s2, s3, s4) (π is the acceleration plan's pole; the velocity "
      "plan's is p)")),
    ({"forces": {"Р32": 3.0}}, "measured.5.forces.Р32",
     ("the force polygons have no reaction Р32; they have R23, R14, R34, R12; it has the Cyrillic letter 'Р' "
      "(U+0420): type the Latin one")),
    ({"acceleration": {"p′b′": 58.5}}, "measured.5.acceleration.p′b′",
     ("is not two letters of the plan (a, b, e, n3, n4, p, s2, s3, s4) (its pole π is p); the plans' letters take "
      "no prime: write pb")),
    ({"velocity": {"ｐｂ": 38.82}}, "measured.5.velocity.ｐｂ",
     "is not two letters of the plan (a, b, e, p, s2, s3, s4); it has full-width letters: write pb"),
    # Capitals of a point the plan has not: "write ps5" was a fix refused in its turn.
    ({"velocity": {"pS5": 30.0}}, "measured.5.velocity.pS5",
     "is no segment of the plan: p is one of its letters, S5 is none (a, b, e, p, s2, s3, s4)"),
    # A point the plan has not after its pole: the pole was not the slip, nor were the letters "not two".
    ({"acceleration": {"ak": 3.0}}, "measured.5.acceleration.ak",
     "is no segment of the plan: a is one of its letters, k is none (a, b, e, n3, n4, p, s2, s3, s4)"),
    ({"velocity": {"px": 126.2}}, "measured.5.velocity.px",
     "is no segment of the plan: p is one of its letters, x is none (a, b, e, p, s2, s3, s4)"),
], ids=["cyrillic-letter", "capitals", "pi-on-the-velocity-plan", "cyrillic-reaction", "primed", "full-width",
        "capitals-of-no-point", "no-such-point-after-a-letter", "no-such-point-after-the-pole"])
def test_a_students_misnamed_reading_is_told_what_to_type(measured, where, problem) -> None:
    """A Russian student's slips: a Cyrillic р or Р that looks Latin, capitals, π on the velocity plan; a Chinese
    student's: 机械原理's primed letters of the acceleration plan (p′b′), an input method's full-width ｐｂ."""
    scene = scene_module.loads(to_toml(variant(RATCHET, {"measured.5": measured})))
    with pytest.raises(SceneError) as raised:
        analyse(scene)
    assert str(raised.value) == f"{where}: {problem}" and raised.value.where == where


@pytest.mark.parametrize("text, hint", [
    ("[measured.5]\nvelocity = { pb = 38,82 }\n", "; a decimal comma? TOML numbers take a point: write 38.82"),
    ("[scene]\ngravity = 9,81\n", "; a decimal comma? TOML numbers take a point: write 9.81"),
    ("[measured.5]\nvelocity = { рb = 38.82 }\n", ("; 'рb' has the Cyrillic 'р' (U+0440) where 'pb' has the Latin "
     "'p' (U+0070): type the Latin letter")),
    # A Russian word for the key: no letter of it looks Latin, the key is the English word.
    ('[[группы]]\nkind = "RRR"\n', "; a key is the English word, not the Russian 'группы': write [[groups]]"),
    ("[links.шатун]\nmass = 1.0\n", "; links are numbered: write [links.3]"),
    ("[foo]\nшатун = 1\n", ("; a key is an English word, not 'шатун': quote a name of your own in other letters "
                            '("шатун" = …)')),
    # What a value cannot hold: a degree sign, the typographic minus graphplan's own notes print, a non-breaking
    # space from Word or a PDF (no input method's full-width character).
    ("[positions]\nstart = 30°   # the first\n", ("; '°' (U+00B0) is a degree sign: an angle is a number, in "
     "degrees, so drop it: write start = 30")),
    ("[driver]\nomega = −17.0\n", ("; a minus sign '−' (U+2212) is a typographic sign (as the notes print a minus), "
     "which TOML does not read: type the ASCII '-'")),
    ("[driver]\nlength\u00a0= 0.175\n", ("; '\u00a0' (U+00A0) is a non-breaking space (copied from Word or a PDF): type "
     "an ordinary space, or delete it")),
    # A Chinese input method's full-width forms (a Chinese student's try): each was told to quote the key.
    ("[positions]\ncount ＝ 12\n", ("; '＝' (U+FF1D) is a full-width character (a Chinese or Japanese input "
     "method's): TOML reads the ASCII '=' where one belongs")),
    ("[positions]\nplans = [3，10]\n", ("; '，' (U+FF0C) is a full-width character (a Chinese or Japanese input "
     "method's): TOML reads the ASCII ',' where one belongs")),
    ("[positions]\ncount = １２\n", ("; '１' (U+FF11) is a full-width character (a Chinese or Japanese input "
     "method's): TOML reads the ASCII '1' where one belongs")),
    ("[scene]\ntitle = “牛头刨床”\n", ("; '“' (U+201C) is a typographic quote (a word processor's or an input "
     "method's): TOML reads the ASCII '\"' where one belongs")),
    ("[scene]\ngravity = 9.81。\n", ("; '。' (U+3002) is a Chinese or Japanese input method's punctuation: TOML "
     "reads the ASCII '.' where one belongs")),
    # A Russian scheme's point О, named so in quotes elsewhere: told to type the Latin O, the student renamed the
    # point here and had every "О" elsewhere refused.
    ('[frame]\nlink = 1\npoints = { О = [0.0, 0.0] }\n[driver]\npivot = "О"\n',
     ("; a bare TOML key takes ASCII letters, digits, '-' and '_' alone, and the scene names 'О' in quotes "
      'elsewhere: quote it here too, write points = { "О" = [0.0, 0.0] }')),
], ids=["decimal-comma-in-a-table", "decimal-comma", "cyrillic-key", "russian-table-name", "russian-link-name",
        "russian-key", "degree-sign", "typographic-minus", "non-breaking-space", "full-width-equals", "full-width-comma",
        "full-width-digits", "typographic-quote", "ideographic-full-stop", "point-named-in-cyrillic"])
def test_invalid_toml_with_a_students_slip_says_what_to_write(text: str, hint: str) -> None:
    stage, error = first_error(text)
    assert stage == "load" and str(error).startswith("<scene>: is not valid TOML: ") and str(error).endswith(hint)


@pytest.mark.parametrize("guide_line", [
    "lines = { x–x = { through = [0.0, 0.08], angle = 0.0 } }",
    "[frame.lines.x–x]",
], ids=["inline-table", "table-header"])
def test_a_dash_in_a_frame_line_s_name_is_told_to_quote_the_key_not_to_type_a_hyphen(guide_line: str) -> None:
    """A frame line named as the notes print it, x–x, typed as a bare key: TOML reads no en dash there, and the hint
    had said to type an ASCII '-', which renames the line, so that the guide naming it is refused in turn."""
    line = guide_line if guide_line.startswith("lines") else f"{guide_line}\nthrough = [0.0, 0.08]\nangle = 0.0"
    text = (FIXTURE.parent / "offset_slider_crank.toml").read_text(encoding="utf-8")
    text = text.replace('guide    = "saw"', 'guide    = "x–x"')
    text = re.sub(r"lines  = \{ saw = .*\n", line + "\n" if line.startswith("lines") else "", text)
    text += "" if line.startswith("lines") else "\n" + line + "\n"
    stage, error = first_error(text)
    assert stage == "load" and "an en dash '–' (U+2013) in the key x–x" in str(error), error
    assert "type the ASCII '-'" not in str(error)
    # The line the hint writes, put in place of the one TOML stumbled on, loads the line under its own name.
    written = str(error).split(": write ", 1)[1]
    assert written == guide_line.replace("x–x", '"x–x"')
    scene = scene_module.loads(text.replace(guide_line, written))
    assert np.allclose(graphplan.solve(scene).point("B").r[:, 1], 0.08)  # B runs along x–x, 80 mm above O


@pytest.mark.parametrize("way", ["up", "down", "向下"])
def test_a_working_sense_typed_as_a_way_on_the_drawing_is_told_which_sense_runs_that_way(way: str) -> None:
    """A press's ram works moving down: told only the four senses, a student took forward for down on a guide at
    90°, which runs up, and had the strokes the other way round without a word. The hint's sense for the guide's
    angle is the one whose working stroke moves the link that way."""
    text = (FIXTURE.parent / "scotch_yoke.toml").read_text(encoding="utf-8")
    guide_angle = re.search(r'guide  = \{ through = \[0\.0, 0\.0\], angle = (\S+) \}', text)[1]
    typed = text.replace('sense = "forward"', f'sense = "{way}"')
    stage, error = first_error(typed)
    assert stage == "load" and error.where == "positions.working.sense"
    told = re.findall(r"(forward|backward) along (?:a guide|one) at angle = (-?\d+)", str(error))
    sense = next(sense for sense, angle in told if float(angle) == float(guide_angle))
    analysis = scene_module.loads(typed.replace(f'sense = "{way}"', f'sense = "{sense}"')).analyse()
    working = np.array(analysis.positions.strokes) == "working"
    upward = analysis.motion.point("B").v[:, 1]
    moving = np.abs(upward) > 1e-9
    assert working.any() and moving[working].any()
    assert np.all(np.sign(upward[working & moving]) == (1 if way == "up" else -1))


@pytest.mark.parametrize(("changes", "message"), [
    ({"groups.0.lengths": [0, 55, 0, 325]},
     ("groups[0].lengths: must have 2 entries, not 4 (got [0, 55, 0, 325]); a decimal comma? TOML reads a comma in "
      "a list as the next entry: write [0.55, 0.325]")),
    ({"frame.points.C": [0, 0, 55]},
     ("frame.points.C: must be a point [x, y] (got [0, 0, 55]); a decimal comma? TOML reads a comma in a list as "
      "the next entry: write [0, 0.55] or [0.0, 55]")),
    ({"groups.0.near": [0, 2, 0, 5], "groups.0.assembly": DELETE},
     ("groups[0].near: must be a point [x, y] (got [0, 2, 0, 5]); a decimal comma? TOML reads a comma in a list "
      "as the next entry: write [0.2, 0.5]")),
    ({"driver.length": "0,175"},
     ("driver.length: must be a number, not a string (got '0,175'); a decimal comma? TOML numbers take a point "
      "and no quotes: write 0.175")),
    # Five entries for two are no slip of a comma: nothing is guessed.
    ({"groups.0.lengths": [1, 2, 3, 4, 5]}, "groups[0].lengths: must have 2 entries, not 5 (got [1, 2, 3, 4, 5])"),
], ids=["lengths", "point", "near", "string-with-a-comma", "too-many-to-be-commas"])
def test_a_decimal_comma_in_a_list_or_a_string_is_told_to_take_a_point(changes, message) -> None:
    """Inside brackets TOML reads a decimal comma as the next entry, so `[0,55, 0,325]` is four integers."""
    stage, error = first_error(to_toml(variant(RATCHET, changes)))
    assert (stage, str(error)) == ("load", message)


def test_invalid_toml_names_the_file(tmp_path: Path) -> None:
    path = tmp_path / "broken.toml"
    path.write_text("[frame\n", encoding="utf-8")
    with pytest.raises(SceneError, match=r"broken\.toml: is not valid TOML: .*line 1"):
        graphplan.load(path)


def test_file_over_the_size_limit(tmp_path: Path) -> None:
    limit = scene_module.MAX_SCENE_BYTES
    path = tmp_path / "huge.toml"
    text = to_toml(RATCHET)
    path.write_text(text + "#" * (limit + 1 - len(text.encode("utf-8")) - 1) + "\n", encoding="utf-8")
    assert path.stat().st_size == limit + 1
    with pytest.raises(SceneError) as caught:
        graphplan.load(path)
    assert str(caught.value) == f"{path}: is {limit + 1} bytes; a scene may have at most {limit}"


def test_file_at_the_size_limit_is_read(tmp_path: Path) -> None:
    limit = scene_module.MAX_SCENE_BYTES
    path = tmp_path / "big.toml"
    text = to_toml(RATCHET)
    path.write_text(text + "#" * (limit - len(text.encode("utf-8")) - 1) + "\n", encoding="utf-8")
    assert path.stat().st_size == limit
    assert graphplan.load(path).title == "Crank-rocker of a ratchet feed"


def test_bytes_over_the_size_limit() -> None:
    limit = scene_module.MAX_SCENE_BYTES
    with pytest.raises(SceneError) as caught:
        scene_module.loads(b"#" * (limit + 1))
    assert str(caught.value) == f"<scene>: is {limit + 1} bytes; a scene may have at most {limit}"


def test_missing_file(tmp_path: Path) -> None:
    path = tmp_path / "nowhere.toml"
    with pytest.raises(SceneError) as caught:
        graphplan.load(path)
    assert str(caught.value) == f"{path}: cannot be read: No such file or directory"
    assert caught.value.where == str(path)


def test_directory_instead_of_file(tmp_path: Path) -> None:
    with pytest.raises(SceneError) as caught:
        graphplan.load(tmp_path)
    assert str(caught.value) == f"{tmp_path}: is a folder, not a scene file: give the path of a .toml scene file"


def test_empty_document() -> None:
    stage, error = first_error("")
    assert stage == "load" and str(error).startswith("<scene>: is empty: a scene has a mechanism's tables")


# --- positions the mechanism cannot reach, or where it locks -------------------------------


def test_rrr_too_short_to_reach() -> None:
    """|AC| = √(0.29 − 0.2·cos φ) passes AB + BC = 0.6 m at φ ≈ 110.5°: position 5 (φ = 120°) is the first out."""
    text = to_toml(variant(FOUR_BAR, {"groups.0.lengths": [0.4, 0.2]}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is AssemblyError
    # The crank's reach told after it, as the Python interface tells it too: ±acos(−0.35) = ±110.4873°, inward.
    # Then the lengths that turn it round: A–C = 0.5 ∓ 0.2 m at φ = 0° and 180°, so BC > 0.7 − 0.4 and |0.4 − BC| <
    # 0.3; AB with BC = 0.2 would need AB > 0.5 and AB < 0.5, and is not named.  The scene writes start = 0.0, which
    # a swing refuses: the advice says to leave it out.
    assert str(error) == ("B cannot be assembled at position 5 (φ = 120°) in group II(3,4): "
                          "A–C = 0.6245 m > AB + BC = 0.6 m; the scene's keys that set it: groups[0].lengths = [0.4, "
                          "0.2], driver.length = 0.2, frame.points.O, frame.points.C; link 2 reaches only from "
                          "-110.48° to 110.48° (at each "
                          "end two links stand in line); since it cannot turn round, drive it as a rocker: "
                          "driver.swing = [from, to] in degrees, e.g. driver.swing = [-109, 109]; a rocking crank's "
                          "positions run once over its swing, so also leave positions.start out; or, if link 2 is "
                          "meant to turn round, check the lengths: over the turn A–C runs from 0.3 m (at φ = 0°) to "
                          "0.7 m (at φ = 180°), so the crank turns round only where AB + BC > 0.7 m and |AB − BC| < "
                          "0.3 m: groups[0].lengths[1] (BC) from 0.3001 m to 0.6999 m with AB as given")
    assert (error.joint, error.position, error.group) == ("B", "position 5 (φ = 120°)", "II(3,4)")
    assert error.keys == ("groups[0].lengths", "driver.length", "frame.points.O", "frame.points.C")
    assert error.reason.startswith("A–C = 0.6245 m > AB + BC = 0.6 m; the scene's keys that set it: ")
    assert isinstance(error, ValueError)


@pytest.mark.parametrize(("base", "key", "typed", "bounds", "meant"), [
    # The crank's 0.1 m is as far as A comes from the guide through O.
    ("SLIDER_CRANK", "groups.0.length", 0.04,
     ("over the turn A comes as far as 0.1 m from the guide (at φ = 90°), so the crank turns round only where AB > "
      "0.1 m: groups[0].length from 0.1001 m up"), "groups[0].length = 0.4, a digit off the 0.04 m given"),
    # A–C = 0.5 ∓ 0.2 m: AB > 0.7 − 0.35 and |AB − 0.35| < 0.3.
    ("FOUR_BAR", "groups.0.lengths", [0.04, 0.35],
     ("over the turn A–C runs from 0.3 m (at φ = 0°) to 0.7 m (at φ = 180°), so the crank turns round only where "
      "AB + BC > 0.7 m and |AB − BC| < 0.3 m: groups[0].lengths[0] (AB) from 0.3501 m to 0.6499 m with BC as given"),
     "groups[0].lengths[0] = 0.4, a digit off the 0.04 m given"),
])
def test_a_length_a_digit_off_is_named_beside_the_rocker_advised(base, key, typed, bounds, meant) -> None:
    """A student's DE = 0.05 for 0.5 was told only to rock the crank over the part of its turn it reaches: the
    bounds its lengths must keep to turn round are named, and the length that, a digit off, lets it, and the scene
    with it runs round."""
    scene = globals()[base]
    stage, error = first_error(to_toml(variant(scene, {key: typed})))
    assert stage == "solve" and type(error) is AssemblyError
    assert "drive it as a rocker" in str(error)
    assert str(error).endswith(f"; or, if link 2 is meant to turn round, check the lengths: {bounds}; {meant}, "
                               f"turns it round")
    # The length as meant: the mechanism turns round (it is the scene this file starts from).
    analyse(scene_module.loads(to_toml(scene)))


def test_rrr_too_short_position_numbers_follow_number_from() -> None:
    text = to_toml(variant(FOUR_BAR, {"groups.0.lengths": [0.4, 0.2], "positions.number_from": 0}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is AssemblyError
    assert error.position == "position 4 (φ = 120°)"


def test_rrr_too_short_for_an_explicit_driver_array() -> None:
    scene = scene_module.loads(to_toml(variant(FOUR_BAR, {"groups.0.lengths": [0.4, 0.2]})))
    with pytest.raises(AssemblyError) as caught:
        graphplan.solve(scene, driver=np.radians([0.0, 90.0, 150.0]))
    # Which of the values, by its index; the reach as for the scene's own positions.
    assert str(caught.value).startswith("B cannot be assembled at φ = 150° (driver[2]) in group II(3,4): "
                                        "A–C = 0.680592 m > AB + BC = 0.6 m; the scene's keys that set it: "
                                        "groups[0].lengths = [0.4, 0.2], driver.length = 0.2, frame.points.O, "
                                        "frame.points.C; link 2 reaches only from -110.48° to 110.48°")


def test_rrr_too_long_difference_at_the_first_position() -> None:
    """|AB − BC| = 0.4 m > |AC| = 0.3 m at φ = 0: the branch cannot even be chosen."""
    text = to_toml(variant(FOUR_BAR, {"groups.0.lengths": [0.5, 0.1]}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is AssemblyError
    assert str(error).startswith("B cannot be assembled at position 1 (φ = 0°) in group II(3,4): A–C = 0.3 m < |AB − BC| = 0.4 m; "
                                 "the scene's keys that set it: groups[0].lengths = [0.5, 0.1], driver.length = 0.2, "
                                 "frame.points.O, frame.points.C; link 2 reaches only from ")


def test_frame_points_at_one_place_are_named_where_the_mechanism_closes_nowhere() -> None:
    """C's coordinates copied from O: A–C is then the crank, 0.2 m, at every angle, short of |AB − BC| = 0.4 m
    (the same lengths with C at [0.5, 0] reach part of a turn, test_rrr_too_long_difference_at_the_first_position),
    so the mechanism closes nowhere and the slip is the place, not a length."""
    text = to_toml(variant(FOUR_BAR, {"frame.points.C": [0.0, 0.0], "groups.0.lengths": [0.5, 0.1]}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is AssemblyError
    assert str(error) == ("B cannot be assembled at position 1 (φ = 0°) in group II(3,4): A–C = 0.2 m < |AB − BC| = "
                          "0.4 m; the scene's keys that set it: groups[0].lengths = [0.5, 0.1], driver.length = 0.2, "
                          "frame.points.O, frame.points.C; frame points O and C stand at one place, [0, 0], so the "
                          "links pivoted at them turn about one axis: give C its own place (its coordinates copied "
                          "from O?), or check the lengths")


def test_frame_points_at_one_place_that_close_run() -> None:
    """A crank and a rocker about one axis are a mechanism where the lengths close it (|AB − BC| = 0.05 m ≤
    A–C = 0.2 m ≤ AB + BC): it runs, B a fixed corner of the triangle ABC that turns with the crank."""
    scene = scene_module.loads(to_toml(variant(FOUR_BAR, {"frame.points.C": [0.0, 0.0]})))
    solved = graphplan.solve(scene, driver=np.radians([0.0, 90.0]))
    a, b = (solved.points[name] for name in ("A", "B"))
    assert np.allclose(np.abs(b.r - a.r), 0.4) and np.allclose(np.abs(b.r), 0.35)
    # The triangle turns rigidly with the crank (ω = 10 rad/s about O): B's angle from A's is one at both
    # positions, and B moves as a point of the crank would, v = iω·r.
    assert np.isclose(np.angle(b.r[1] / a.r[1]), np.angle(b.r[0] / a.r[0]))
    assert np.allclose(b.v, 10j * b.r)


def test_a_diagram_scene_s_key_beside_a_slider_driver_names_no_crank() -> None:
    """A slider driver's loads and masses are reduced to the slider, not to a crank: the refusal of [dynamics]
    inertia (a key of a scene without a linkage) told a slider-driven scene they were reduced to the crank."""
    text = to_toml(variant(SLIDER_DRIVEN, {"dynamics": {"inertia": 2.0}}))
    stage, error = first_error(text)
    assert stage == "load" and str(error).startswith("dynamics.inertia: is for a scene without a linkage")
    assert "reduced to its driving link" in str(error) and "crank" not in str(error)


def test_rrr_too_short_with_near() -> None:
    text = to_toml(variant(FOUR_BAR, {"groups.0.lengths": [0.5, 0.1], "groups.0.assembly": DELETE,
                                      "groups.0.near": [0.3, 0.4]}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is AssemblyError
    assert str(error).startswith("B cannot be assembled at position 1 (φ = 0°) in group II(3,4): A–C = 0.3 m < |AB − BC| = 0.4 m; "
                                 "the scene's keys that set it: groups[0].lengths = [0.5, 0.1], driver.length = 0.2, "
                                 "frame.points.O, frame.points.C; link 2 reaches only from ")


def test_rrr_toggle_is_singular() -> None:
    """O–C = 1.25 m, OA = 0.25 m, AB = BC = 0.5 m: at φ = 0 the group is stretched straight."""
    text = to_toml(variant(FOUR_BAR, {"frame.points.C": [1.25, 0.0], "driver.length": 0.25,
                                      "groups.0.lengths": [0.5, 0.5]}))
    stage, error = first_error(text, driver=[0.0])
    assert stage == "solve" and type(error) is SingularPositionError
    # Exactly in line, the sine is nought and says nothing: -0.0e+00 was written.
    assert str(error) == ("singular position at φ = 0° in group II(3,4): links 3 and 4 lie in one line (a toggle): "
                          "the lines of action of the velocity plan are parallel")
    assert (error.position, error.group) == ("φ = 0°", "II(3,4)")
    assert isinstance(error, ArithmeticError)


def test_rrp_too_short_to_reach_the_guide() -> None:
    text = to_toml(variant(SLIDER_CRANK, {"groups.0.length": 0.05, "positions.start": 0.0,
                                          "positions.working": DELETE, "positions.plans": DELETE}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is AssemblyError
    assert str(error).startswith("B cannot be assembled at position 3 (φ = 60°) in group II(3,4): "
                                 "A is 0.0866025 m from the guide > AB = 0.05 m; the scene's keys that set it: "
                                 "groups[0].length = 0.05, groups[0].guide, driver.length = ")


def _rrp_toggle_scene() -> dict[str, Any]:
    """O 0.5 m above the guide, OA = 0.2 m, AB = 0.7 m: at φ = 90° AB stands square on the guide."""
    return variant(SLIDER_CRANK, {"frame.points.O": [0.0, 0.5], "driver.length": 0.2, "groups.0.length": 0.7,
                                  "positions.start": 0.0, "positions.working": DELETE, "positions.plans": DELETE})


def _rrp_toggle() -> str:
    return to_toml(_rrp_toggle_scene())


def test_rrp_toggle_is_singular() -> None:
    stage, error = first_error(_rrp_toggle(), driver=[math.pi / 2])
    assert stage == "solve" and type(error) is SingularPositionError
    assert str(error).startswith("singular position at φ = 90° in group II(3,4): ")
    assert error.reason.endswith("are parallel")


def test_a_singular_first_position_is_refused_as_the_first_with_what_moves_it() -> None:
    """The same toggle later in a run is a warning; the first position, where each group's assembly is chosen,
    was refused without saying which it was or why it, unlike the rest, cannot be passed."""
    text = to_toml(variant(_rrp_toggle_scene(), {"positions.start": 90.0}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is SingularPositionError
    assert str(error) == ("singular position at the first position, 1 (φ = 90°) in group II(3,4): link 3 stands "
                          "square to the guide (a dead point): the lines of action of the velocity plan are parallel; "
                          "the first position fixes each group's assembly and may not be singular: start the run elsewhere "
                          "(positions.start)")


def test_rpr_offset_wider_than_the_reach() -> None:
    text = to_toml(variant(SLOTTED_LEVER, {"groups.0.offset": 0.3}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is AssemblyError
    assert str(error).startswith("A cannot be assembled at position 8 (φ = 210°) in group II(3,4): "
                                 "the slide runs 0.3 m from C but A is only 0.264575 m from C, so "
                                 "the block at A cannot reach it; the scene's keys that set it: groups[0].offset = 0.3, "
                                 "driver.length = ")


def test_prp_guides_in_one_line_at_the_first_position_are_singular() -> None:
    """The guide on the crank along the crank itself lies along the fixed one at φ = 0: B anywhere on it."""
    text = to_toml(variant(CROSSED_SLIDERS, {"groups.0.guides.0.angle": 0.0, "driver.swing": [0.0, 130.0]}))
    stage, error = first_error(text)
    assert stage == "solve" and type(error) is SingularPositionError
    assert str(error) == ("singular position at the first position, 1 (φ = 0°) in group II(3,4): the two guides lie "
                          "in one line; the first position fixes each group's assembly and may not be singular: start "
                          "the run elsewhere (driver.swing)")


@pytest.mark.parametrize("swing, where", [([130.0, 140.0], "position 7 (φ = 135.455°)"), ([135.0, 140.0], "position 1 (φ = 135°)")])
def test_prp_guides_turning_parallel_take_b_off_to_infinity(swing, where) -> None:
    """The crank's guide at 45° to it is parallel to the fixed one at φ = 135° and −45°, 0.0707 m apart."""
    stage, error = first_error(to_toml(variant(CROSSED_SLIDERS, {"driver.swing": swing})))
    assert stage == "solve" and type(error) is AssemblyError
    assert str(error).startswith(f"B cannot be assembled at {where} in group II(3,4): its two guides ")
    assert "link 2 reaches only from -45.00° to 135.00°" in str(error)
    assert "(at each end its two guides run parallel)" in str(error)


@pytest.mark.parametrize("driver, message", [
    ([], "driver: must be a non-empty 1-D array of driver positions (got an empty one)"),
    ([[0.0, 1.0]], ("driver: must be a non-empty 1-D array of driver positions (got an array of shape (1, 2)): "
                    "give np.ravel(driver) for all its values")),
    ([0.0, float("nan")], "driver[1]: must be a finite number, a driver position (got nan)"),
    ([float("inf")], "driver[0]: must be a finite number, a driver position (got inf)"),
], ids=["empty", "two-dimensional", "nan", "inf"])
def test_solve_rejects_bad_driver_arrays(driver: list[Any], message: str) -> None:
    scene = scene_module.loads(to_toml(FOUR_BAR))
    with pytest.raises(SceneError) as caught:
        graphplan.solve(scene, driver=driver)
    assert str(caught.value) == message


def test_motion_lookups_name_what_exists() -> None:
    """The Python interface: asking a solved motion for a point, link or slide it does not have."""
    motion = graphplan.solve(graphplan.load(FIXTURE))
    with pytest.raises(KeyError) as caught:
        motion.point("Z")
    assert caught.value.args[0] == "no point 'Z'; points are O, C, A, S2, B, S3, E, S4"
    with pytest.raises(KeyError) as caught:
        motion.link(9)
    assert caught.value.args[0] == "no link 9; links are 1, 2, 3, 4"
    with pytest.raises(KeyError) as caught:
        motion.slide(3)
    assert caught.value.args[0] == "link 3 slides in no pair; the mechanism has no sliding pair"


def test_motion_lookups_by_the_wrong_kind_of_name_say_what_kind_it_takes() -> None:
    """motion.link("4") answered "no link 4; links are 1, 2, 3, 4" (the string is no key of the numbers), and
    scene.plan("5") raised numpy's own comparison error (a teacher's batch script)."""
    scene = graphplan.load(FIXTURE)
    motion = graphplan.solve(scene)
    with pytest.raises(TypeError, match=r"^a link is named by its number, an integer: link\(4\), not link\('4'\)$"):
        motion.link("4")
    with pytest.raises(TypeError, match=r"^a point is named by its name, a string"):
        motion.point(3)
    with pytest.raises(TypeError, match=r"^a position is named by its number, an integer: plan\(5\), not plan\('5'\)$"):
        scene.plan("5")
    assert motion.link(np.int64(4)).omega.shape == (motion.count,)


def test_toml_date_where_a_number_belongs() -> None:
    """TOML's own types (dates, times) reach the type check as Python objects."""
    stage, error = first_error('[scene]\ngravity = 2024-01-01\n')
    assert stage == "load" and type(error) is SceneError
    assert error.where == "scene.gravity" and str(error).startswith("scene.gravity: must be a number, not ")


# --- once gaps, now fixed: each test pins the better behaviour ----------------------------------


def test_misspelt_required_key_suggests_the_right_one() -> None:
    groups = [{k if k != "lengths" else "lenghts": v for k, v in RATCHET["groups"][0].items()}]
    stage, error = first_error(to_toml(variant(RATCHET, {"groups": groups})))
    assert stage == "load" and type(error) is SceneError
    assert "lenghts" in str(error) and "did you mean 'lengths'?" in str(error)


def test_misspelt_omega_suggests_omega() -> None:
    driver = {k if k != "omega" else "omgea": v for k, v in RATCHET["driver"].items()}
    stage, error = first_error(to_toml(variant(RATCHET, {"driver": driver})))
    assert stage == "load" and "omgea" in str(error)


@pytest.mark.parametrize("table", ["driver", "vibration", "dynamics"])
def test_a_speed_in_rev_per_min_is_read_in_rad_per_s(table: str) -> None:
    """One revolution a second: 60 rpm is 2π rad/s, wherever a speed is given either way."""
    from graphplan.reader import Table

    read = Table({"rpm": 60.0}, table).speed(positive=table != "driver")
    assert read == pytest.approx(2 * math.pi, rel=1e-15)
    assert Table({"omega": 3.5}, table).speed() == 3.5
    assert Table({}, table).speed(None) is None


@pytest.mark.parametrize(("key", "message"), [
    ("n", "driver.n: unknown key; a speed in rev/min is given as rpm: write rpm = -150"),
    ("RPM", "driver.RPM: unknown key; did you mean 'rpm'?"),
    ("Omega", "driver.Omega: unknown key; did you mean 'omega'?"),
    ("ω", "driver.ω: unknown key; a speed in rad/s is given as omega: write omega = -150"),
], ids=["russian-n", "capitals", "capital-omega", "greek-omega"])
def test_a_speed_under_another_key_is_named_before_the_speed_is_missed(key: str, message: str) -> None:
    """n, the speed in об/мин of a Russian textbook, was answered 'driver.omega: is required but missing'."""
    scene = variant(RATCHET, {"driver.omega": DELETE, f"driver.{key}": -150})
    stage, error = first_error(to_toml(scene))
    assert (stage, str(error)) == ("load", message)


@pytest.mark.parametrize(("kind", "hint"), [
    ("ВВВ", "; the Latin notation letters a turning pair (В) R and a sliding one (П) P"),
    ("ВВП", "; the Latin notation letters a turning pair (В) R and a sliding one (П) P"),
    ("РРР", "; the Latin notation letters a turning pair (В) R and a sliding one (П) P"),
    ("rrr", ""),
], ids=["russian-notation", "russian-slider", "cyrillic-er", "small-letters"])
def test_a_group_kind_in_russian_notation_or_small_letters_is_told_the_latin_one(kind: str, hint: str) -> None:
    """The ru note titles a group "ВВВ (RRR)", and a student copies it."""
    meant = kind.upper().translate(str.maketrans("ВПР", "RPR"))
    stage, error = first_error(to_toml(variant(RATCHET, {"groups.0.kind": kind})))
    told = f"groups[0].kind: must be one of RRR, RRP, RPR, PRP, RPP, triad; did you mean {meant!r}? (got {kind!r}){hint}"
    assert (stage, str(error)) == ("load", told)


def test_frame_line_through_unknown_point() -> None:
    text = to_toml(variant(SLIDER_CRANK, {"frame.lines": {"rail": {"through": "Z", "angle": 0.0}},
                                          "groups.0.guide": "rail"}))
    stage, error = first_error(text)
    assert stage in ("load", "build") and type(error) is SceneError
    assert "frame.lines.rail.through" in str(error) and "'Z'" in str(error)


def test_links_key_with_a_unicode_digit() -> None:
    stage, error = first_error(to_toml(variant(RATCHET, {"links.³": {"mass": 1.0}})))
    assert (stage, str(error)) == ("load", "links.³: links are numbered: write [links.3]")


def test_measured_key_with_a_unicode_digit() -> None:
    stage, error = first_error(to_toml(variant(RATCHET, {"measured.⁵": {"velocity": {"pb": 1.0}}})))
    assert (stage, str(error)) == ("load", "measured.⁵: must be a position number: write [measured.5]")


def test_point_depending_on_an_unplaceable_point_is_not_called_cyclic() -> None:
    text = to_toml(variant(RATCHET, {"points.T1": {"link": 3, "from": "T2", "toward": "A", "at": 0.1},
                                     "points.T2": {"link": 3, "from": "Z", "toward": "A", "at": 0.1}}))
    stage, error = first_error(text)
    assert stage == "build" and type(error) is SceneError
    assert "cyclic" not in str(error)
    assert str(error).startswith("points.T2")


def test_point_reference_errors_name_the_key() -> None:
    _stage, error = first_error(to_toml(variant(RATCHET, {"points.S3.from": "C"})))
    assert error.where == "points.S3.from"


def test_unknown_pivot_lists_the_frame_points() -> None:
    stage, error = first_error(to_toml(variant(RATCHET, {"driver.pivot": "Q"})))
    assert stage == "build"
    assert str(error) == "driver.pivot: must be a point of [frame] points: O, C (got 'Q')"


def test_rrp_toggle_message_describes_the_geometry() -> None:
    _stage, error = first_error(_rrp_toggle(), driver=[math.pi / 2])
    assert type(error) is SingularPositionError
    assert "are parallel" not in str(error) or "lines of action" in str(error)


def test_rpr_joint_on_the_lever_pivot() -> None:
    text = to_toml(variant(SLOTTED_LEVER, {"frame.points.C": [0.2, 0.0], "driver.length": 0.2}))
    stage, error = first_error(text, driver=[0.0])
    assert stage == "solve" and isinstance(error, GraphplanError)
    assert "is less than the slide's offset 0 m" not in str(error)


def test_rrr_outer_joints_coincide() -> None:
    text = to_toml(variant(FOUR_BAR, {"frame.points.C": [0.2, 0.0], "groups.0.lengths": [0.1, 0.1]}))
    stage, error = first_error(text, driver=[0.0])
    assert stage == "solve" and isinstance(error, GraphplanError)
    assert "0 m < |AB − BC| = 0 m" not in str(error)


def test_a_crank_stopped_at_one_angle_alone_is_told_its_reach_not_a_traceback(tmp_path, capsys) -> None:
    """A and C meet at φ = 0 only (the crank's circle through C): seeking the crank's reach bisected between
    two grid angles that both assemble and ended in scipy's traceback.  With the crank 0.2 m long,
    |AC| = 0.4·sin(|φ|/2) ≤ AB + BC = 0.2 m while |φ| ≤ 60°."""
    scene = tmp_path / "meeting.toml"
    scene.write_text(to_toml(variant(FOUR_BAR, {"frame.points.C": [0.2, 0.0], "groups.0.lengths": [0.1, 0.1]})),
                     encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert line.startswith("graphplan: error: B cannot be assembled at position 1 (φ = 0°) in group II(3,4): A and C coincide")
    assert "reaches only from -60.00° to 0.00° and from 0.00° to 60.00°" in line
    assert not (tmp_path / "out").exists()


def test_rpr_coincident_point_clash_is_explained() -> None:
    text = to_toml(variant(SLOTTED_LEVER, {"frame.points.A4": [1.0, 1.0]}))
    stage, error = first_error(text)
    assert stage == "build" and type(error) is SceneError
    assert "inner joint" not in str(error) and "A4" in str(error)


def test_slider_driver_on_explicit_frame_link() -> None:
    scene = scene_module.loads(to_toml(variant(SLIDER_DRIVEN, {"driver.guide": {"link": 1, "through": "O"}})))
    graphplan.build(scene)


def test_clockwise_is_not_suggested_as_ccw() -> None:
    _stage, error = first_error(to_toml(variant(RATCHET, {"positions.working.sense": "clockwise"})))
    assert type(error) is SceneError and "'ccw'" not in str(error)


def test_utf8_byte_order_mark() -> None:
    scene = scene_module.loads(b"\xef\xbb\xbf" + to_toml(RATCHET).encode("utf-8"))
    assert scene.title == "Crank-rocker of a ratchet feed"


def test_text_over_the_size_limit() -> None:
    limit = scene_module.MAX_SCENE_BYTES
    with pytest.raises(SceneError, match="a scene may have at most"):
        scene_module.loads(to_toml(RATCHET) + "#" * limit + "\n")


def test_toml_date_is_named_in_words() -> None:
    _stage, error = first_error('[scene]\ngravity = 2024-01-01\n')
    assert str(error) == "scene.gravity: must be a number, not a date (got 2024-01-01)"


def test_link_given_twice_under_two_spellings() -> None:
    text = to_toml(variant(RATCHET, {"links.03": {"mass": 99.0}}))
    stage, error = first_error(text)
    assert stage == "load" and type(error) is SceneError
    assert error.where == "links.03"


@pytest.mark.parametrize(("text", "where", "meant"), [
    ('[scene]\ntitle = "x"\n[vibrations]\nmass = 100.0\n', "vibrations", "vibration"),
    ('[scene]\ntitle = "x"\n[balancng]\nmasses = []\n', "balancng", "balancing"),
    ('[scene]\ntitle = "x"\n[vibration]\nmass = 100.0\nunbalance = 0.02\nstifness = 1.0e5\nrpm = 600.0\n',
     "vibration.stifness", "stiffness"),
])
def test_a_misspelt_table_or_key_of_a_scene_without_a_linkage_is_named_not_blamed_on_what_is_missing(
        text, where, meant) -> None:
    # "[vibrations]" was told "frame: is required but missing"; "stifness" "vibration.stiffness: is required".
    with pytest.raises(SceneError) as caught:
        scene_module.loads(text)
    assert str(caught.value) == f"{where}: unknown key; did you mean {meant!r}?"


@pytest.mark.parametrize(("gravity", "unit"), [(9810, "mm/s²"), (981, "cm/s²"), (32.2, "ft/s²")])
def test_gravity_in_another_unit_is_refused_before_anything_is_written(tmp_path, capsys, gravity, unit) -> None:
    """A g typed in mm/s², cm/s² or ft/s² ran without a word, every weight and with it every reaction and the
    balancing moment 1000, 100 or 3.3 times off; Earth's 9.81 m/s² is that many of each: 9.81 / 0.001 = 9810,
    9.81 / 0.01 = 981, 9.81 / 0.3048 = 32.2."""
    assert abs(gravity * {"mm/s²": 0.001, "cm/s²": 0.01, "ft/s²": 0.3048}[unit] - 9.81) < 0.02 * 9.81
    scene = tmp_path / "heavy.toml"
    scene.write_text(to_toml(variant(RATCHET, {"scene.gravity": gravity})), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert line.startswith("graphplan: error: scene.gravity: must be at most 30 m/s²"), line
    assert line.endswith(f"is Earth's g in {unit}: the scene's is in m/s², write gravity = 9.81"), line
    assert list(tmp_path.iterdir()) == [scene]


def test_the_heaviest_planet_gravity_still_runs() -> None:
    """Jupiter's 24.8 m/s² is a g a scene may give: the refusal starts above it."""
    loaded = scene_module.loads(to_toml(variant(FOUR_BAR, {"scene": {"gravity": 24.8}})))
    assert loaded.gravity == 24.8


@pytest.mark.parametrize("resisting", ["resisting_torque = [[0, 10.0], [360, 10.0]]",
                                       "resisting_power = [[0, 1000.0], [360, 1000.0]]"], ids=["torque", "power"])
def test_a_machine_of_no_inertia_whose_moments_balance_everywhere_is_refused_not_given_a_flywheel(
        tmp_path, capsys, resisting) -> None:
    """A constant resistance against the constant driving moment that balances it leaves ΔT = 0 at every angle; with
    the machine's Je = 0 its kinetic energy is 0 at any speed.  The torque ended in scipy's "The function value at
    x=-0.0 is NaN", under dynamics alone; the power (1000 W at 100 rpm: 95.5 N·m, whose work leaves ΔT ~ 1e-15 J of
    rounding) was given a flywheel of 1e-15 kg·m² and a speed that swung by δ = 0.05 on that rounding alone."""
    scene = tmp_path / "even.toml"
    scene.write_text(f'[scene]\ntitle = "even"\n[dynamics]\nrpm = 100\ndelta = 0.05\n{resisting}\n'
                     'driving = "constant"\ninertia = 0.0\n', encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    line = capsys.readouterr().err.strip().splitlines()[-1]
    assert line.startswith("graphplan: error: dynamics: the driving and resisting moments balance at every angle"), line
    assert "(dynamics.inertia without a linkage" in line and "NaN" not in line
    assert list(tmp_path.iterdir()) == [scene]
    # Any inertia of its own fixes its speed: no flywheel is needed, and the speed is the mean one throughout.
    scene.write_text(scene.read_text(encoding="utf-8").replace("inertia = 0.0", "inertia = 0.5"), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    dynamics = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["dynamics"]
    assert dynamics["flywheel_inertia"] == pytest.approx(0.0, abs=1e-12)
    assert dynamics["omega_max"] == pytest.approx(100 * math.pi / 30, rel=1e-9)
    assert dynamics["omega_min"] == pytest.approx(100 * math.pi / 30, rel=1e-9)


@pytest.mark.parametrize(("changes", "where", "home", "value"), [
    ({"drawing.sheet": DELETE, "scene.sheet": "A1"}, "scene.sheet", "drawing", "'A1'"),
    ({"drawing.velocity_pole": DELETE, "positions.velocity_pole": 150.0}, "positions.velocity_pole", "drawing",
     "150.0"),
    ({"scene.gravity": DELETE, "drawing.gravity": 9.81}, "drawing.gravity", "scene", "9.81"),
    ({"output.include": DELETE, "positions.include": ["note"]}, "positions.include", "output", '["note"]'),
    ({"positions.plans": DELETE, "frame.plans": [5, 11]}, "frame.plans", "positions", "[5, 11]"),
    # frame.pivot was asked "did you mean 'points'?", scene.planes "did you mean 'locale'?".
    ({"driver.pivot": DELETE, "frame.pivot": "O"}, "frame.pivot", "driver", "'O'"),
    ({"scene.planes": [0.0, 0.2]}, "scene.planes", "balancing", "[0.0, 0.2]"),
    ({"links.3.swing": [0, 90]}, "links.3.swing", "driver", "[0, 90]"),
], ids=["sheet-in-scene", "pole-in-positions", "gravity-in-drawing", "include-in-positions", "plans-in-frame",
        "pivot-in-frame", "planes-in-scene", "swing-in-a-link"])
def test_a_key_written_in_another_of_the_scenes_tables_is_told_where_it_goes(
        tmp_path, capsys, changes, where, home, value) -> None:
    """A key moved into the wrong table was told "unknown key", or sent astray by the nearest key of that table:
    sheet under [scene] "did you mean 'title'?", velocity_pole under [positions] "did you mean 'velocity_plans'?"."""
    table, _, key = where.rpartition(".")
    scene = tmp_path / "moved.toml"
    scene.write_text(to_toml(variant(RATCHET, changes)), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out")]) == 2
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert line == (f"graphplan: error: {where}: unknown key; {key} is a key of {home}, not of {table}: write it "
                    f"under [{home}]: {key} = {value}")
    assert list(tmp_path.iterdir()) == [scene]


def test_a_key_of_the_machines_tables_written_in_another_is_told_where_it_goes(tmp_path, capsys) -> None:
    """[balancing] and [vibration] were asked about their own nearest key: balancing.unbalance (the vibration's m·e)
    "did you mean 'planes'?"."""
    from graphplan.starters import starter

    rotor = starter("rotor", "en")
    assert "[balancing]\n" in rotor
    scene = tmp_path / "rotor.toml"
    scene.write_text(rotor.replace("[balancing]\n", "[balancing]\nunbalance = 0.01\n", 1), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    line = capsys.readouterr().err.strip().splitlines()[-1]
    assert line == ("graphplan: error: balancing.unbalance: unknown key; unbalance is a key of vibration, not of "
                    "balancing: write it under [vibration]: unbalance = 0.01")


@pytest.mark.parametrize(("key", "value", "homes"), [
    ("count", 12, "positions or dynamics"),
    ("start", 0, "positions or dynamics"),
    ("inertia", 0.5, "forces, dynamics or links.N"),
])
def test_a_key_of_several_tables_written_in_the_driver_is_sent_to_none_of_them(tmp_path, capsys, key, value,
                                                                                homes) -> None:
    """driver.count and driver.inertia were asked "did you mean 'joint'?", a key they are nothing like; a key that
    several tables take is told whose it is, and no one table is named to write it under."""
    scene = tmp_path / "driver.toml"
    scene.write_text(to_toml(variant(RATCHET, {f"driver.{key}": value})), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    line = capsys.readouterr().err.strip().splitlines()[-1]
    assert line == f"graphplan: error: driver.{key}: unknown key; {key} is a key of {homes}, not of driver"


def test_a_librarys_error_in_the_dynamics_is_told_as_the_step_it_stopped_and_the_keys_that_feed_it() -> None:
    """The [dynamics] wrapper passed any ValueError on as "dynamics: <its message>", a library's words ("f(a) and f(b)
    must have different signs") read as the project's and named no key; its own refusals it passes on as they are."""
    import scipy.optimize

    from graphplan.dynamics import equivalent_model_of
    from graphplan.machine_dynamics import _MOTION, _scene_values

    with pytest.raises(SceneError) as caught, _scene_values("dynamics", _MOTION):
        scipy.optimize.brentq(lambda x: x, 1.0, 2.0)
    message = str(caught.value)
    assert message.startswith("dynamics: integrating the machine's motion stopped in scipy (ValueError: \"f(a) and "
                              "f(b) must have different signs\")"), message
    assert "check dynamics's motor, brake, clutch, start, duration" in message
    with pytest.raises(SceneError) as caught, _scene_values("dynamics"):
        equivalent_model_of(None, 1)
    assert str(caught.value) == "dynamics: count must be an integer >= 2, not 1"


@pytest.mark.parametrize(("written", "meant"), [("torque", "moment"), ("couple", "moment"), ("момент", "moment"),
                                                ("сила", "force"), ("forse", "force")])
def test_a_load_s_kind_by_another_name_is_told_the_kind_it_names(written, meant):
    """"torque" was told "did you mean 'force'?", by its letters; a torque is a moment."""
    from graphplan.starters import starter

    text = starter("crank-rocker")
    assert text.count('kind      = "moment"') == 1
    with pytest.raises(graphplan.SceneError) as refused:
        graphplan.load_text(text.replace('kind      = "moment"', f'kind = "{written}"'))
    assert str(refused.value) == (f"loads[0].kind: must be one of moment, force; did you mean '{meant}'? "
                                  f"(got '{written}')")
