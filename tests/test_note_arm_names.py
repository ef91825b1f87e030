"""The note names each moment's arm as the force sheet letters it.

The force sheet writes a group's moment equations under its drawing with each load's arm lettered h1, h2, … on
through the group's equations (``ΣMB(3): −R23τ·AB − G3·h1 − Fu3·h2``); the note wrote the same terms with a bare h
(``M(G3) = −G3·h = −166.77·0.09161``), so a student could not tell which arm on the drawing each number is.  Read back
from both as written, for every fixture and the starters that add the sliding and class III groups, in every
position with forces (and with friction where a scene has it): each load the sheet letters an arm for stands in
the note with that same arm, in the same order, and a load the note writes with a bare h has no arm on the sheet.
The sheet's equations are broken over lines, and its indices set in runs (R₂₃ is ``R<tspan>23</tspan>``): a text is
read whole, and a group's lines are read together.
"""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
from note_lines import items_on_one_line
from note_scenes import SCENES, STARTERS, scene_path

import graphplan
from graphplan.locale import strings
from graphplan.render.force_marks import group_id
from graphplan.run import run

SVG = "{http://www.w3.org/2000/svg}"
# A group's caption on a force sheet: its drawing's, or its equations' parted from it onto a row of their own.
CAPTION = re.compile(r"^(?:body|equations)-(.+)-caption$")
# A load's name with its arm lettered on the sheet: ``G3·h1``, ``Fи3·h2``, ``R23τ·h15``; the unknown's arm (``·AB``,
# a bare ``·h``) and a length written out (``h2 = 0.1 mm``) are no lettered arm of a load.
SHEET_ARM = re.compile(r"(?:^|(?<=[\s:(]))([^\s·:=(),]+)·(h\d+)(?![\w])")
# A term of the note: ``M(G3) = −G3·h1 = …``, its arm numbered or, for a load the sheet draws no arrow for, bare.
NOTE_ARM = re.compile(r"M\((?P<name>[^()]+)\) = −?(?P=name)·(?P<arm>h\d*)(?![\w])")



def sheet_arms(folder: Path, labels: dict[str, str]) -> dict[tuple[int, bool, str], list[tuple[str, str]]]:
    """By (position, with friction, group label), the loads the force sheet letters an arm for, with the arm, in the
    order its equations write them."""
    found: dict[tuple[int, bool, str], list[tuple[str, str]]] = {}
    for sheet in folder.glob("forces_*.svg"):
        number = re.fullmatch(r"forces_(friction_)?(\d+)", sheet.stem)
        if number is None:  # a part of a sheet cut for the note's pages: the whole sheet is read instead
            continue
        for layer in ElementTree.parse(sheet).getroot().iter(f"{SVG}g"):
            caption = CAPTION.match(layer.get("id", ""))
            if caption is None or caption.group(1) not in labels:
                continue
            key = (int(number.group(2)), number.group(1) is not None, labels[caption.group(1)])
            for text in layer.findall(f"{SVG}text"):
                found.setdefault(key, []).extend(SHEET_ARM.findall("".join(text.itertext())))
    return found


def note_arms(markdown: str, locale: str, labels: list[str]
              ) -> dict[tuple[int, bool, str], list[tuple[str, str]]]:
    """By (position, with friction, group label), the loads the note writes as F·h, with the arm as written."""
    text = strings(locale)
    position = re.compile(re.escape(text["position_heading"]).replace(re.escape("{number}"), r"(\d+)") + r"(?!\d)")
    headings = {f"**{text[key + kind].format(group=label)}**": (bool(kind), label)
                for label in labels for key in ("note_group_forces", "note_driver_forces")
                for kind in ("", "_friction")}
    found: dict[tuple[int, bool, str], list[tuple[str, str]]] = {}
    number, group = None, None
    for line in items_on_one_line(markdown):
        if line.startswith("#"):
            heading = position.search(line)
            number, group = (int(heading.group(1)) if heading else None), None
        elif line.startswith("**"):
            group = headings.get(line.strip())
        elif number is not None and group is not None:
            for term in NOTE_ARM.finditer(line):
                found.setdefault((number, *group), []).append((term["name"], term["arm"]))
    return found


def check_arms_agree(folder: Path, made, locale: str) -> None:
    analysis = made.analysis
    labels = {group_id(group.label): group.label for plan in analysis.plans if plan.forces is not None
              for group in plan.forces.groups}
    sheet = sheet_arms(folder, labels)
    note = note_arms((folder / "note.md").read_text(encoding="utf-8"), locale, list(labels.values()))
    assert sum(len(pairs) for pairs in sheet.values()) > 0, "the force sheets letter no arm"
    assert set(note) <= set(sheet) | {key for key, pairs in note.items() if all(arm == "h" for _, arm in pairs)}
    for key, lettered in sheet.items():
        written = note.get(key, [])
        numbered = [(name, arm) for name, arm in written if arm != "h"]
        assert numbered == lettered, (f"position {key[0]}{' with friction' if key[1] else ''}, group {key[2]}: "
                                      f"the sheet letters {lettered}, the note writes {written}")
        bare = {name for name, arm in written if arm == "h"}
        assert not bare & {name for name, _ in lettered}, f"{key}: {bare} lettered on the sheet, bare in the note"


# Without course sheets (sheet="none"): μl is then fitted to the plan of positions rather than chosen by laying every
# course sheet out, which was more than half of each run; each force_N.svg and the note are drawn and written at the
# one μl either way, and every scene here letters the same arms with or without the sheets (diffed once).
@pytest.mark.parametrize(("source", "name"), SCENES + STARTERS, ids=[name for _, name in SCENES + STARTERS])
def test_the_note_names_each_arm_as_the_force_sheet_letters_it(tmp_path, source, name):
    scene = graphplan.load(scene_path(tmp_path, source, name))
    made = run(scene, tmp_path / "out", only=["forces", "note"], sheet="none")
    check_arms_agree(tmp_path / "out", made, scene.locale)


# Load names are localised (Fи3 for Fu3 in Russian): the ratchet's own note is Russian, so it is read in the other two.
@pytest.mark.parametrize(("source", "name", "locale"),
                         [("fixture", "ratchet_crank_rocker", "en"), ("fixture", "ratchet_crank_rocker", "zh"),
                          ("starter", "triad", "ru"), ("starter", "triad", "zh"), ("starter", "shaper", "ru")])
def test_the_arms_agree_in_every_language(tmp_path, source, name, locale):
    made = run(graphplan.load(scene_path(tmp_path, source, name)), tmp_path / "out", only=["forces", "note"],
               locale=locale, sheet="none")
    check_arms_agree(tmp_path / "out", made, locale)
