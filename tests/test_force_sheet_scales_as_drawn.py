"""Every μF a course sheet's force sheet states is the scale its arrows are drawn at, measured.

A drawing review read the crank-rocker starter's heading "μl = 0.002 m/mm, μF = 20 N/mm, μV = …" as the scale of
the whole sheet, whose groups cut free draw their arrows at 100 and 200 N/mm and its lever at 200 N/mm: the 20 N/mm
was the polygons' alone (drawn finer than the record where the sheet has room), which the polygons' captions state
too, as the groups' and the lever's captions state their arrows' own.  A heading names μF only where the polygons
share it, and then it is theirs.

Each scale is measured, not read from the layout: an arrow's length on the sheet (from its shaft's tail to its
head's tip, in the SVG's millimetres) against the magnitude of its reaction in the linear system of every link's
equilibrium (:mod:`graphplan.statics`), which the plans and polygons never read.
"""

from __future__ import annotations

import math
import re
from collections import defaultdict
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest

import graphplan
from graphplan.render.force_marks import group_id
from graphplan.run import run
from graphplan.starters import starter

SVG = "{http://www.w3.org/2000/svg}"
NUMBER = re.compile(r"-?\d+(?:\.\d+)?")
# A force sheet's arrow of a reaction: ``forces-5-polygon-II-3-4-R23``, ``forces-3-2-polygon-II-3-4-1-R34`` (a
# second part, a group's second polygon), ``forces-5-body-I-1-2-R32``.
ARROW = re.compile(r"forces-(\d+)(?:-\d+)?-((?:polygon|body)-[IV]+(?:-\d+)+)-(R\d\d)$")
CAPTION = re.compile(r"forces-(\d+)(?:-\d+)?-((?:polygon|body)-[IV]+(?:-\d+)+|lever)-caption$")
HEADING = re.compile(r"forces-(\d+)(?:-\d+)?-sheet-title$")
FORCE_SCALE = re.compile(r"μF = ([\d.]+) N/mm")
# The sheet's coordinates are written to 0.001 mm; the plans close as the linear system does to rounding.
RELATIVE = 0.005
# The groups cut free draw no arrow shorter than this (mm), as their captions say: one so lengthened is at no scale.
LEAST_ARROW_MM = 10.0


def arrow_length(group: ElementTree.Element) -> float:
    """From the tail of the arrow's shaft to the tip of its head (the first point of each path)."""
    shaft, head = ([float(value) for value in NUMBER.findall(path.get("d"))[:2]]
                   for path in list(group.iter(f"{SVG}path"))[:2])
    return math.hypot(head[0] - shaft[0], head[1] - shaft[1])


def stated(group: ElementTree.Element) -> list[float]:
    return [float(value) for text in group.iter(f"{SVG}text") for value in FORCE_SCALE.findall("".join(text.itertext()))]


# The starter's two force sheets share one A1 with their rows apart, drawn at the record's scales: what is
# checked here is a sheet drawn larger where it has room.
pytestmark = pytest.mark.usefixtures("no_rows_apart")


@pytest.fixture(scope="module", params=["crank-rocker", "slider-crank"])
def sheets(request, tmp_path_factory):
    """The starter's analysis and its course sheets: the crank-rocker's draw its polygons finer than the record,
    the slider-crank's at the record's μF."""
    folder = tmp_path_factory.mktemp(request.param)
    path = folder / "scene.toml"
    path.write_text(starter(request.param, "en"), encoding="utf-8")
    made = run(graphplan.load(path), folder / "out", only=["sheets"])
    return made.analysis, sorted((folder / "out").glob("sheet_*.svg"))


def measured_and_stated(analysis, paths: list[Path]):
    """By sheet and force sheet (position number): each drawing's measured scales (N/mm, one per reaction arrow
    drawn at its length), each drawing's stated μF, and the heading's."""
    index = {plan.number: plan.index for plan in analysis.plans}
    reactions = {reaction.name: reaction.force for reaction in analysis.equilibrium.reactions}

    def magnitude(name: str, number: int) -> float | None:
        force = reactions.get(name, reactions.get(f"R{name[2]}{name[1]}"))
        return None if force is None else float(np.abs(force[index[number]]))

    measured: dict[tuple[str, int, str], list[float]] = defaultdict(list)
    captions: dict[tuple[str, int, str], list[float]] = {}
    headings: dict[tuple[str, int], list[float]] = {}
    for path in paths:
        for group in ElementTree.parse(path).getroot().iter(f"{SVG}g"):
            name = group.get("id", "")
            if found := ARROW.match(name):
                number, drawing, reaction = int(found.group(1)), found.group(2), found.group(3)
                force, length = magnitude(reaction, number), arrow_length(group)
                if force is None or (drawing.startswith("body-") and length < LEAST_ARROW_MM + 0.01):
                    continue
                # A group's second polygon (its block's) is captioned with its first.
                key = re.sub(r"^(polygon-[IV]+-\d+-\d+)-\d+$", r"\1", drawing)
                measured[path.name, number, key].append(force / length)
            elif found := CAPTION.match(name):
                captions[path.name, int(found.group(1)), found.group(2)] = stated(group)
            elif found := HEADING.match(name):
                headings[path.name, int(found.group(1))] = stated(group)
    return measured, captions, headings


def test_every_polygon_and_group_states_the_force_scale_its_arrows_are_drawn_at(sheets):
    analysis, paths = sheets
    measured, captions, _ = measured_and_stated(analysis, paths)
    polygons = [key for key in captions if key[2].startswith("polygon-")]
    assert polygons and all(measured[key] for key in polygons)
    for key, scales in measured.items():
        (given,) = captions[key]
        assert scales == pytest.approx([given] * len(scales), rel=RELATIVE), key
    if "crank-rocker" not in str(paths[0]):
        return
    # The case has what it is for: a polygon the sheet draws finer than the record does, so that a μF taken from
    # the record would be another than the one drawn.
    record = {(plan.number, f"polygon-{group_id(label)}"): scale for plan in analysis.plans
              if plan.forces is not None for label, scale in plan.forces.group_scales.items()}
    assert any(scales[0] < 0.9 * record[number, key] for (_, number, key), scales in measured.items()
               if key.startswith("polygon-"))

def test_a_heading_s_force_scale_is_the_one_every_polygon_under_it_is_drawn_at(sheets):
    """The heading names μF only where the sheet's polygons share it (the groups cut free and the lever state their
    arrows' own in their captions): each polygon under it is drawn at that μF, measured."""
    analysis, paths = sheets
    measured, _, headings = measured_and_stated(analysis, paths)
    for (sheet, number), named in headings.items():
        polygons = [scale for (page, position, key), scales in measured.items()
                    if (page, position) == (sheet, number) and key.startswith("polygon-") for scale in scales]
        for scale in named:
            assert polygons and all(value == pytest.approx(scale, rel=RELATIVE) for value in polygons), (
                sheet, number, named, polygons)
