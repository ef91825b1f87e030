"""A force sheet's title block names the position whose force analysis it holds, whatever else shares the page.

A conveyor's A1 set named sheet 2, position 2's force analysis alone, «Силовой анализ, положение 2», and sheet 3,
position 8's beside the load diagrams, only «Силовой анализ»: the load diagrams' own heading made two drawings on
the page, and a page of two drawings fell back to the kind's word.  A page of two positions' force analyses still
names neither (both would not hold in the block's two lines).
"""

from __future__ import annotations

import re
from pathlib import Path
from types import SimpleNamespace
from xml.etree import ElementTree

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.render.packing import Panel
from graphplan.render.sheet import _drawing_name

SVG = "{http://www.w3.org/2000/svg}"
FIXTURES = Path(__file__).parent.parent / "fixtures"


def title_block_texts(path: Path) -> list[str]:
    root = ElementTree.parse(path).getroot()
    (block,) = [group for group in root.iter(f"{SVG}g") if group.get("id") == "title-block"]
    return [text.text or "" for text in block.iter(f"{SVG}text")]


def test_the_sheet_of_a_position_beside_the_load_diagrams_names_that_position(tmp_path):
    out = tmp_path / "out"
    assert main(["run", str(FIXTURES / "engine_slider_crank.toml"), "--sheet", "A1", "--locale", "ru",
                 "--only", "sheets,load_diagrams,forces", "--out", str(out)]) == 0
    text = strings("ru")
    shared = 0
    for sheet in sorted(out.glob("sheet_*.svg")):
        svg = sheet.read_text(encoding="utf-8")
        positions = sorted(set(re.findall(r'id="forces-(\d+)-', svg)))
        if len(positions) != 1:
            continue
        named = text["tb_sheet_forces_position"].format(number=positions[0])
        assert named in title_block_texts(sheet), sheet.name
        shared += text["ld_title"] in svg
    assert shared == 1  # the engine's load diagrams stand beside position 2's force analysis


def test_a_page_of_two_positions_names_neither():
    text = strings("en")

    def page(*panels: tuple[str, str]) -> SimpleNamespace:
        return SimpleNamespace(label="", placed=[(Panel(name, (), label=label), None, None) for name, label in panels])

    second = ("forces-2", text["tb_sheet_forces_position"].format(number=2))
    eighth = ("forces-8", text["tb_sheet_forces_position"].format(number=8))
    loads = ("load-diagrams", text["ld_title"])
    assert _drawing_name(page(eighth, loads), "sheet_forces") == eighth[1]
    assert _drawing_name(page(second, eighth), "sheet_forces") == ""
    assert _drawing_name(page(second, eighth, loads), "sheet_forces") == ""
    # Another kind's page of two drawings is named by its kind, as before.
    assert _drawing_name(page(("plan-2", "a"), ("plan-8", "b")), "sheet_kinematics") == ""
