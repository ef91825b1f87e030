"""Naming a force polygon's vectors too short to draw costs the sheet no room it needs for a drawing.

Once the polygons' captions named their vectors under 0.25 mm at their μF with their values, the engine's Chinese
run drew 8 sheets where it drew 7: position 2's polygon of group II(3,4) took two more lines of lettering ("短于
0.25 mm、未画出的矢量：" over "G4 = 8.829 N"), and the driving link's group no longer stood on that sheet.  The
caption now runs the words and the values on after its μF where the field holds them on one line, so that the
vector is still named with its value on the sheet, in no more sheets than a caption that named nothing.

The vectors expected are found here from the polygons' forces and μF, and G4 from the scene's mass and g.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest
from sheet_texts import box, texts

import graphplan
import graphplan.render.forces as force_layout
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.locale import strings
from graphplan.render import force_polygons
from graphplan.render.drawings import force_sheet

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
ENGINE = FIXTURES / "engine_slider_crank.toml"
# The drawings leave out a polygon's vector shorter than this (mm) at its μF; a force this small (N) is a nought.
SHORTEST_DRAWN_MM = 0.25
NOUGHT_N = 1e-10


def sheets_of(folder: Path) -> list[Path]:
    return sorted(folder.glob("sheet_*.svg"))


@pytest.fixture(scope="module")
def engine_zh(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("named") / "engine"
    assert main(["run", str(ENGINE), "--only", "sheets", "--locale", "zh", "--out", str(out)]) == 0
    return out


@pytest.fixture(scope="module")
def engine_zh_naming_nothing(tmp_path_factory) -> Path:
    """The same run with no vector taken as too short to draw: captions that name none."""
    out = tmp_path_factory.mktemp("unnamed") / "engine"
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(force_polygons, "too_short_to_draw", lambda force, scale: False)
        assert main(["run", str(ENGINE), "--only", "sheets", "--locale", "zh", "--out", str(out)]) == 0
    return out


@pytest.fixture(scope="module")
def engine_analysis():
    return analyse(graphplan.load(ENGINE))


def too_short(position) -> dict[str, float]:
    """Each polygon vector of the position under 0.25 mm at its group's μF but no nought, with its force (N)."""
    return {vector.name: abs(vector.force) for group in position.forces.groups for vector in group.polygon.vectors
            if abs(vector.force) > NOUGHT_N and abs(vector.force) / group.scale < SHORTEST_DRAWN_MM}


def test_the_engine_s_chinese_sheets_take_no_more_sheets_for_naming_the_short_vectors(
        engine_zh, engine_zh_naming_nothing):
    assert len(sheets_of(engine_zh)) <= len(sheets_of(engine_zh_naming_nothing)), (
        [path.name for path in sheets_of(engine_zh)], [path.name for path in sheets_of(engine_zh_naming_nothing)])


def test_each_short_vector_is_named_with_its_value_on_a_sheet(engine_zh, engine_analysis):
    expected = {name: force for position in engine_analysis.plans if position.forces is not None
                for name, force in too_short(position).items()}
    # The scene's case: the piston's weight, m4·g, is under 0.25 mm at its polygon's μF = 40 N/mm.
    scene = tomllib.loads(ENGINE.read_text(encoding="utf-8"))
    assert expected["G4"] == pytest.approx(scene["links"]["4"]["mass"] * 9.81, rel=1e-12)
    words = strings("zh")["plan_too_short"].format(least=f"{SHORTEST_DRAWN_MM:g}")
    lines = [text for path in sheets_of(engine_zh) for *_, text in texts(path.read_text(encoding="utf-8"))]
    for name, force in expected.items():
        found = [(k, match) for k, line in enumerate(lines)
                 for match in re.finditer(rf"(?<![\w′″]){re.escape(name)} = ([\d.]+) N\b", line)]
        assert found, (name, [line for line in lines if name in line])
        for k, match in found:
            assert float(match[1]) == pytest.approx(force, rel=5e-4), (name, lines[k])
            # Said to be left out of the polygon, on its line or the line before it.
            assert words in lines[k] or lines[k - 1] == words, (name, lines[k - 1:k + 1])


def test_the_line_that_names_them_stands_within_the_frame_over_no_other_text_full_width(engine_zh):
    words = strings("zh")["plan_too_short"].format(least=f"{SHORTEST_DRAWN_MM:g}")
    seen = 0
    for path in sheets_of(engine_zh):
        source = path.read_text(encoding="utf-8")
        frame = re.search(r'<g id="sheet-frame"><path[^>]*/><path d="M([\d.]+),([\d.]+) L([\d.]+),[\d.]+ '
                          r'L[\d.]+,([\d.]+)', source)
        assert frame is not None, path.name
        left, bottom, right, top = (float(value) for value in frame.groups())
        found = texts(path.read_text(encoding="utf-8"))
        for k, item in enumerate(found):
            if words not in item[4]:
                continue
            seen += 1
            # A line with Chinese words in it separates its clauses full width (；), as every Chinese caption does.
            assert not re.search(r"[,;] ", item[4]), item[4]
            x0, y0, x1, y1 = box(*item)
            assert left <= x0 and x1 <= right and top <= y0 and y1 <= bottom, (path.name, item[4])
            for other in found[:k] + found[k + 1:]:
                u0, v0, u1, v1 = box(*other)
                assert u1 <= x0 or x1 <= u0 or v1 <= y0 or y1 <= v0, (path.name, item[4], other[4])
    assert seen


def test_a_stacked_polygon_naming_one_short_vector_takes_the_lines_of_one_naming_none(engine_analysis):
    """Under its group, the polygon's field is as wide as the group: the vector and its value go on after μF in the
    line that is there already, so the column is no taller for them."""
    import dataclasses

    from graphplan.render.force_rows import Drawing, Rows

    scene = dataclasses.replace(engine_analysis.scene, locale="zh")
    analysis = dataclasses.replace(engine_analysis, scene=scene)
    position = next(position for position in analysis.plans if position.number == 2)
    assert set(too_short(position)) == {"G4"}
    rows = force_layout.rows(force_sheet(analysis, position))
    body, polygon = rows.drawings[0]
    assert polygon.name.startswith("polygon-")
    scale_line = next(k for k, line in enumerate(polygon.caption) if line.startswith("μF ="))
    assert polygon.caption[scale_line + 1:]  # the words and the value
    naming_none = Drawing(polygon.name, polygon.layers, polygon.caption[:scale_line + 1])
    bare = Rows([[body, naming_none]], rows.heading)
    assert rows.stacked[0].height == pytest.approx(bare.stacked[0].height)
    assert rows.stacked[0].width == pytest.approx(bare.stacked[0].width)
