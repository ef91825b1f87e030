"""A force sheet's title block names the position whose force analysis it holds, whatever else shares the page.

A conveyor's A1 set named sheet 2, position 2's force analysis alone, «Силовой анализ, положение 2», and sheet 3,
position 8's beside the load diagrams, only «Силовой анализ»: the load diagrams' own heading made two drawings on
the page, and a page of two drawings fell back to the kind's word.  A page of two positions' force analyses still
names neither (both would not hold in the block's two lines).  A page that holds the load diagrams names them
too, after the force analysis where the block's cell holds both legibly, else after the kind's word: the Russian
crank-rocker with friction's last A3 sheet, the rest of position 11's force analysis with friction beside the load
diagrams, named only «Силовой анализ с учётом трения, положение 11».
"""

from __future__ import annotations

import re
from pathlib import Path
from types import SimpleNamespace
from xml.etree import ElementTree

import pytest
from test_force_sheet_parts_headed import FRICTION

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.render.packing import Panel
from graphplan.render.primitives import FONT_SIZE_PER_CAP
from graphplan.render.sheet import _drawing_name
from graphplan.render.title_block import SMALLEST_LETTERING, form_of, labels
from graphplan.starters import starter

SVG = "{http://www.w3.org/2000/svg}"
FIXTURES = Path(__file__).parent.parent / "fixtures"


def title_block_texts(path: Path) -> list[str]:
    root = ElementTree.parse(path).getroot()
    (block,) = [group for group in root.iter(f"{SVG}g") if group.get("id") == "title-block"]
    # A line of Chinese with Latin letters or digits is set in spans of each script's font.
    return ["".join(text.itertext()) for text in block.iter(f"{SVG}text")]


def test_the_sheet_of_a_position_beside_the_load_diagrams_names_that_position(tmp_path):
    out = tmp_path / "out"
    # The engine's load diagrams stood beside position 2's force analysis until its two force sheets shared one A1.
    assert main(["run", str(FIXTURES / "offset_slider_crank.toml"), "--sheet", "A1", "--locale", "ru",
                 "--only", "sheets,load_diagrams,forces", "--out", str(out)]) == 0
    text = strings("ru")
    shared = 0
    for sheet in sorted(out.glob("sheet_*.svg")):
        svg = sheet.read_text(encoding="utf-8")
        positions = sorted(set(re.findall(r'id="forces-(\d+)-', svg)))
        if len(positions) != 1:
            continue
        named = text["tb_sheet_forces_position"].format(number=positions[0])
        shared_page = text["ld_title"] in svg
        if shared_page:
            named = text["tb_sheet_with_load_diagrams"].format(name=named)
        # The name's lines, broken where the cell is narrower than it, read as the name.
        assert named in " ".join(title_block_texts(sheet)), sheet.name
        shared += shared_page
    assert shared == 1  # the offset slider-crank's load diagrams stand beside position 10's force analysis


def test_a_page_of_two_positions_names_neither():
    text = strings("en")

    def page(*panels: tuple[str, str]) -> SimpleNamespace:
        return SimpleNamespace(label="", placed=[(Panel(name, (), label=label), None, None) for name, label in panels])

    second = ("forces-2", text["tb_sheet_forces_position"].format(number=2))
    eighth = ("forces-8", text["tb_sheet_forces_position"].format(number=8))
    loads = ("load-diagrams", text["ld_title"])
    words = labels("en")
    both = text["tb_sheet_with_load_diagrams"]
    assert _drawing_name(page(eighth, loads), "sheet_forces", "iso", words) == both.format(name=eighth[1])
    assert _drawing_name(page(second, eighth), "sheet_forces", "iso", words) == ""
    assert _drawing_name(page(second, eighth, loads), "sheet_forces", "iso", words) == both.format(
        name=text["tb_sheet_forces"])
    # Another kind's page of two drawings is named by its kind, as before.
    assert _drawing_name(page(("plan-2", "a"), ("plan-8", "b")), "sheet_kinematics") == ""


@pytest.mark.parametrize("locale", ["ru", "en", "zh"])
def test_a_sheet_of_a_force_analysis_and_the_load_diagrams_names_both(tmp_path, locale):
    scene = tmp_path / "crank_rocker.toml"
    scene.write_text(starter("crank-rocker", locale).replace("\n[positions]", FRICTION + "\n[positions]"),
                     encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--sheet", "A3", "--only", "sheets", "--out", str(out)]) == 0
    text = strings(locale)
    (shared,) = [sheet for sheet in out.glob("sheet_*.svg") if 'id="load-diagrams-' in (svg := sheet.read_text(
        encoding="utf-8")) and 'id="forces-' in svg]
    (whole,) = set(re.findall(r'id="(forces(?:-friction)?-\d+)-', shared.read_text(encoding="utf-8")))
    key = "tb_sheet_forces_friction_position" if "friction" in whole else "tb_sheet_forces_position"
    position = text[key].format(number=whole.rsplit("-", 1)[1])
    full, short = (text["tb_sheet_with_load_diagrams"].format(name=name) for name in (position, text["tb_sheet_forces"]))
    # ESKD's name cell holds the Russian name with the position in two lines, GB/T's the Chinese in one; ISO's one
    # line of Document type holds the English one only below the smallest lettering, so the force analysis's name
    # stands alone, keeping the position (and the friction) that the kind's word with the load diagrams dropped.
    named = position if form_of(locale) == "iso" else full
    assert short not in " ".join(title_block_texts(shared))
    assert named in " ".join(title_block_texts(shared))
    root = ElementTree.parse(shared).getroot()
    (block,) = [group for group in root.iter(f"{SVG}g") if group.get("id") == "title-block"]
    sizes = [float(line.get("font-size")) / FONT_SIZE_PER_CAP for line in block.iter(f"{SVG}text")
             if len(words := "".join(line.itertext())) > 3 and words in named]
    assert sizes and min(sizes) >= SMALLEST_LETTERING
