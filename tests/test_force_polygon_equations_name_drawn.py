"""A force polygon's caption names every force its polygon lays off.

The crank-rocker starter's driving link was captioned "ΣF2 + R12 = 0" over a polygon of R32 and R12: its ΣF2
summed the reaction group II(3,4) hands back, R32, which the caption named nowhere (the note says "Here ΣF2 =
R32").  The caption now gives what a ΣF that holds a reaction sums, as the note does, under the equations: every
reaction laid off is named, and every given load (G3, Fu3) by its name or by the ΣF of its link.

Read back from the course sheets as written: the arrows each polygon draws (their ids), against the lines of its
caption between its title and its μF (the equations, broken to the polygon's width, and what each ΣF sums).  The
vectors read off the polygon once it is closed (a whole reaction drawn as the sum of its components, an inner one
such as R43) are found by it, not laid off in its equation.
"""

from __future__ import annotations

import re
from xml.etree import ElementTree

import pytest

import graphplan
from graphplan.render.force_marks import group_id
from graphplan.render.primitives import svg_id
from graphplan.run import run
from graphplan.starters import starter

SVG = "{http://www.w3.org/2000/svg}"
# A polygon's layer of a force sheet: ``forces-5-polygon-I-1-2-R32``, ``forces-friction-3-2-polygon-II-3-4-1-R34``
# (a part of the sheet, the group's second polygon).
LAYER = re.compile(r"forces-(friction-)?(\d+)(?:-\d+)?-polygon-(.+)-([^-]+)$")
CAPTION = re.compile(r"forces-(friction-)?(\d+)(?:-\d+)?-polygon-([IV]+(?:-\d+)+)-caption$")
NOT_ARROWS = {"lines", "vectors", "leaders", "labels"}


def named_in(name: str, text: str) -> bool:
    """Whether ``name`` stands in ``text`` as a name of its own: R23 is not named by R23τ or R234."""
    return re.search(rf"(?<!\w){re.escape(name)}(?![\w′″])", text) is not None


@pytest.mark.parametrize("kind", ["crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad"])
def test_every_force_a_polygon_lays_off_is_named_by_its_caption(tmp_path, kind):
    path = tmp_path / "scene.toml"
    path.write_text(starter(kind, "en"), encoding="utf-8")
    made = run(graphplan.load(path), tmp_path / "out", only=["sheets"])
    plans = {plan.number: plan for plan in made.analysis.plans if plan.forces is not None}
    drawn: dict[tuple[bool, int, str], set[str]] = {}
    equations: dict[tuple[bool, int, str], str] = {}
    for sheet in sorted((tmp_path / "out").glob("sheet_*.svg")):
        for group in ElementTree.parse(sheet).getroot().iter(f"{SVG}g"):
            name = group.get("id", "")
            if found := CAPTION.match(name):
                lines = ["".join(text.itertext()) for text in group.iter(f"{SVG}text")
                         if text.get("font-weight") != "bold"]
                scale = next(k for k, line in enumerate(lines) if "μF" in line)
                key = (bool(found.group(1)), int(found.group(2)), found.group(3))
                equations[key] = " ".join(lines[:scale])
            elif (found := LAYER.match(name)) and found.group(4) not in NOT_ARROWS and list(group.iter(f"{SVG}path")):
                number, key = int(found.group(2)), found.group(3)
                if key not in {group_id(forces.label) for forces in plans[number].forces.groups}:
                    key = key.rsplit("-", 1)[0]  # the group's second polygon
                drawn.setdefault((bool(found.group(1)), number, key), set()).add(found.group(4))
    assert drawn and set(drawn) <= set(equations)
    checked = 0
    for (friction, number, key), names in drawn.items():
        record = plans[number].with_friction if friction else plans[number].forces
        (group,) = [group for group in record.groups if group_id(group.label) == key]
        laid_off = {vector.name for vector in group.polygon.vectors if vector.role in ("load", "closing")}
        # The ids spell τ out (R23tau): the record's names as the layers name them.
        by_id = {svg_id(name): name for name in laid_off}
        links = {load.name: load.link for load in group.loads}
        for name in names & set(by_id):
            checked += 1
            force, caption = by_id[name], equations[friction, number, key]
            assert named_in(force, caption) or (not force.startswith("R") and force in links and named_in(
                f"ΣF{links[force]}", caption)), (kind, number, key, force, caption)
    assert checked
