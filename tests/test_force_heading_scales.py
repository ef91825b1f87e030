"""The heading over a force sheet's part names the scales of the drawings that stand under it on its sheet.

A force sheet too big for one sheet stands in parts, each under its heading, a part that goes on on the sheet of
the part before under that part's heading.  Each heading was drawn naming the scales of its own drawings and of
every later part's, as any of them might go on under it; where they went to other sheets, the triad's group
III(3,4,5,6) alone on an A4 (its caption "forces: μF = 4 N/mm") stood under "μl = 0.0025 m/mm, μF = 1 N/mm, μV =
0.004 (m/s)/mm": the polygons' μF and the lever's μV, both on other sheets, and two μF on one sheet.

The sheets are read as written: which drawings stand on a sheet from their ids (``forces-2-3-polygon-…``, a part's
name, then its drawing's), the scale each is drawn at from its own caption.
"""

from __future__ import annotations

import re
from collections import defaultdict
from pathlib import Path
from xml.etree import ElementTree

import pytest

from graphplan.cli import main

SVG = "{http://www.w3.org/2000/svg}"
# A force sheet's part (``forces-2``, ``forces-2-3``, ``forces-friction-8-2``), then the drawing a layer is of.
PART = re.compile(r"(forces(?:-friction)?-\d+)(?:-(\d+))?-(body-|polygon-|equations-|lever|sheet-title)")
# The scales a caption or a heading names: "μl = 0.0025 m/mm", "μF = 1 N/mm", "μV = 0.004 (m/s)/mm".
SCALE = re.compile(r"μ([lFV]) = ([^,]+)")


def written(scene: Path, sheet: str, out: Path) -> list[Path]:
    assert main(["run", str(scene), "--only", "sheets", "--format", "svg", "--sheet", sheet, "--out", str(out)]) == 0
    return sorted(out.glob("sheet_*.svg"), key=lambda path: int(path.stem.split("_")[1]))


def lines_of(group: ElementTree.Element) -> list[str]:
    """The lines of a caption or heading that are not in bold: a drawing's scales, a heading's line of scales."""
    return ["".join(text.itertext()) for text in group.iter(f"{SVG}text") if text.get("font-weight") != "bold"]


def scales_in(lines: list[str], symbol: str) -> list[str]:
    return [f"μ{found} = {value.strip()}" for line in lines for found, value in SCALE.findall(line)
            if found == symbol]


def force_sheet_parts(paths: list[Path]) -> list[dict]:
    """Each part of a force sheet as it stands on the sheets: the index of its sheet, the force sheet it is a part
    of (``forces-2``), its number there, its heading's lines not in bold, its line of scales (None: it stands
    without a heading) and the lines of each of its drawings' captions not in bold, by drawing."""
    parts: dict[tuple[int, str, int], dict] = {}
    for page, path in enumerate(paths):
        for group in ElementTree.parse(path).getroot().iter(f"{SVG}g"):
            found = PART.match(group.get("id", ""))
            if found is None:
                continue
            whole, number, kind = found.group(1), int(found.group(2) or 1), found.group(3)
            part = parts.setdefault((page, whole, number), {"page": page, "whole": whole, "number": number,
                                                            "heading": None, "drawings": {}})
            rest = group.get("id")[found.start(3):]
            if kind == "sheet-title":
                part["heading"] = lines_of(group)
            elif rest.endswith("-caption"):
                part["drawings"][rest.removesuffix("-caption")] = lines_of(group)
    return list(parts.values())


def heading_faults(paths: list[Path]) -> list[str]:
    """Where a heading names a scale no drawing under it on its sheet is drawn at, or leaves out one that is.

    A part without a heading stands under that of the part it goes on from where that stands on its sheet.
    The groups cut free are drawn at μl, the lever at μV, the polygons at μF, which the heading names where they
    share one (on every sheet their captions give the same)."""
    parts = force_sheet_parts(paths)
    by_key = {(part["page"], part["whole"], part["number"]): part for part in parts}
    polygon_scales: dict[str, set[str]] = defaultdict(set)
    for part in parts:
        for drawing, lines in part["drawings"].items():
            if drawing.startswith("polygon-"):
                polygon_scales[part["whole"]].update(scales_in(lines, "F"))
    under: dict[tuple[int, str, int], set[str]] = defaultdict(set)
    for part in parts:
        head = part
        while head["heading"] is None and (head["page"], head["whole"], head["number"] - 1) in by_key:
            head = by_key[head["page"], head["whole"], head["number"] - 1]
        if head["heading"] is None:
            continue  # a drawing too big to stand under a heading
        key = (head["page"], head["whole"], head["number"])
        for drawing, lines in part["drawings"].items():
            if drawing.startswith("body-"):
                under[key].update(scales_in(lines, "l"))
            elif drawing == "lever":
                under[key].update(scales_in(lines, "V"))
            elif drawing.startswith("polygon-") and len(polygon_scales[part["whole"]]) == 1:
                under[key].update(polygon_scales[part["whole"]])
    faults = []
    for part in parts:
        if part["heading"] is None:
            continue
        key = (part["page"], part["whole"], part["number"])
        named = [scale for symbol in "lFV" for scale in scales_in(part["heading"], symbol)]
        if len(part["heading"]) > 1 or sorted(named) != sorted(under[key]):
            faults.append(f"{paths[part['page']].name}: {part['whole']} part {part['number']} heading "
                          f"{part['heading']}, drawings under it at {sorted(under[key])}")
    return faults


# Scenes whose force sheets stand in parts on several sheets: the triad on A4, the offset slider-crank on A3
# (position 3's group II under its heading, the driving link and the lever on the next sheet under "continued"), the
# Scotch yoke on A3 (a heading whose part goes on on the next sheet).  The Stephenson six-bar on its own A1 was one
# until each of its sheets stood with its rows apart on one sheet, the parts under the first's heading.
CASES = [("triad_class_iii", "A4"), ("offset_slider_crank", "A3"), ("scotch_yoke", "A3")]


@pytest.fixture(scope="module")
def sheets_of(tmp_path_factory):
    made: dict[tuple[str, str], list[Path]] = {}

    def sheets(name: str, sheet: str) -> list[Path]:
        if (name, sheet) not in made:
            out = tmp_path_factory.mktemp(f"{name}-{sheet}")
            made[name, sheet] = written(Path(f"fixtures/{name}.toml"), sheet, out)
        return made[name, sheet]

    return sheets


def test_the_triads_group_alone_on_an_a4_is_headed_with_its_own_scale_alone(sheets_of):
    # Since the lettering took the standard heights (names 3.5 mm, arms' 2.5), the group stands with its equations
    # under it at 1:4, its labels clear of one another, on a sheet of its own with no room for the heading, which
    # saves an A4 (16, not 17): a heading over it, where one is drawn, names its scale alone.
    parts = force_sheet_parts(sheets_of("triad_class_iii", "A4"))
    (alone,) = [part for part in parts if part["whole"] == "forces-2" and part["number"] == 1]
    assert list(alone["drawings"]) == ["body-III-3-4-5-6"]
    (body_scale,) = scales_in(alone["drawings"]["body-III-3-4-5-6"], "l")
    assert alone["heading"] in (None, [body_scale])
    # The polygon that goes on from it on the next sheet: its "continued" names its μF alone, not the group's μl.
    (polygon,) = [part for part in parts if part["whole"] == "forces-2" and part["number"] == 2]
    assert [drawing.split("-")[0] for drawing in polygon["drawings"]] == ["polygon"]
    (polygon_scale,) = {scale for drawing in polygon["drawings"].values() for scale in scales_in(drawing, "F")}
    assert polygon["heading"] == [polygon_scale]


@pytest.mark.parametrize(("name", "sheet"), CASES)
def test_every_heading_of_a_force_sheet_in_parts_names_the_scales_of_the_drawings_under_it(sheets_of, name, sheet):
    paths = sheets_of(name, sheet)
    parts = force_sheet_parts(paths)
    pages = {(part["whole"], part["number"]): part["page"] for part in parts}
    # The case has what it is for: a heading whose part the next goes on from on another sheet.
    assert any(part["heading"] is not None and pages.get((part["whole"], part["number"] + 1), part["page"])
               != part["page"] for part in parts)
    assert heading_faults(paths) == []


def test_a_lever_going_on_under_the_heading_of_the_part_before_is_named_in_it(sheets_of):
    # The Scotch yoke on its own A2: a lever going on under the heading of the part before, on its sheet (on A3 it
    # did until the force sheets' drawings could each go where a sheet has room, and its lever opens a sheet there).
    parts = force_sheet_parts(sheets_of("scotch_yoke", "A2"))
    levers = [part for part in parts if "lever" in part["drawings"] and part["heading"] is None]
    assert levers
    by_key = {(part["page"], part["whole"], part["number"]): part for part in parts}
    for lever in levers:
        # Under the heading of the first part before it that has one, the parts between going on on its sheet too
        # (the driver's polygon, its caption widened by what ΣF2 sums, stands apart from its group on the A2).
        over = lever
        while over["heading"] is None:
            over = by_key[over["page"], over["whole"], over["number"] - 1]
        (drawn_at,) = scales_in(lever["drawings"]["lever"], "V")
        assert drawn_at in over["heading"][0]


def note_heading_faults(folder: Path) -> list[str]:
    """Where the heading over the first of the parts the note shows a force sheet in (``forces_2-1.svg``) names
    another scale than those of the drawings in that part: the whole sheet's polygons share a μF where every
    polygon caption of it gives the same."""
    faults = []
    wholes = [path for path in folder.glob("forces_*.svg") if not re.search(r"-\d+$", path.stem)]
    assert wholes
    for whole in wholes:
        parts = sorted(folder.glob(f"{whole.stem}-*.svg"), key=lambda path: int(path.stem.rsplit("-", 1)[1]))
        groups = {path: {group.get("id"): group for group in ElementTree.parse(path).getroot().iter(f"{SVG}g")}
                  for path in (whole, *parts)}
        polygons = {scale for name, group in groups[whole].items() if name.startswith("polygon-")
                    and name.endswith("-caption") for scale in scales_in(lines_of(group), "F")}
        for part in parts:
            if "sheet-title" not in groups[part]:
                continue
            drawn_at = set()
            for name, group in groups[part].items():
                if name.startswith("body-") and name.endswith("-caption"):
                    drawn_at.update(scales_in(lines_of(group), "l"))
                elif name == "lever-caption":
                    drawn_at.update(scales_in(lines_of(group), "V"))
                elif name.startswith("polygon-") and name.endswith("-caption") and len(polygons) == 1:
                    drawn_at.update(polygons)
            heading = lines_of(groups[part]["sheet-title"])
            named = [scale for symbol in "lFV" for scale in scales_in(heading, symbol)]
            if len(heading) > 1 or sorted(named) != sorted(drawn_at):
                faults.append(f"{part.name}: heading {heading}, drawings in it at {sorted(drawn_at)}")
    return faults


@pytest.mark.parametrize("only", [[], ["--only", "forces,lever,note", "--format", "svg"]])
def test_the_heading_over_the_first_part_the_note_shows_a_force_sheet_in_names_its_drawings_scales(tmp_path, only):
    """The note shows a force sheet too tall for its page in parts, the heading over the first: that heading named
    every scale of the whole sheet, the lever's μV over the triad's groups, its lever in the next part.  Written
    with the sheets, the note's force sheet is the sheets' own (laid out for them) where they draw it as it is
    alone (the triad's A1 draws its lever a step smaller, and the note's is drawn for itself); without, drawn for
    itself."""
    out = tmp_path / "out"
    assert main(["run", "fixtures/triad_class_iii.toml", *only, "--out", str(out)]) == 0
    assert list(out.glob("forces_*-1.svg")), "the case: the note shows the force sheets in parts"
    assert note_heading_faults(out) == []


def heading_gaps(path: Path) -> list[tuple[str, float]]:
    """Each heading on a sheet: whether it names scales ("scales", "none") and how far its lowest line's baseline
    stands above the top of the part's drawings under it (mm, read as drawn: a text's top is its baseline less
    its font size, a path's its highest vertex)."""
    tops: dict[str, float] = defaultdict(lambda: float("inf"))
    headings: dict[str, tuple[str, float]] = {}
    for group in ElementTree.parse(path).getroot().iter(f"{SVG}g"):
        found = PART.match(group.get("id", ""))
        if found is None:
            continue
        key = f"{found.group(1)}-{found.group(2) or 1}"
        texts = list(group.iter(f"{SVG}text"))
        if found.group(3) == "sheet-title":
            named = [text for text in texts if text.get("font-weight") != "bold"]
            headings[key] = ("scales" if named else "none", max(float(text.get("y")) for text in texts))
            continue
        for text in texts:
            tops[key] = min(tops[key], float(text.get("y")) - float(text.get("font-size")))
        for element in group.iter(f"{SVG}path"):
            ys = [float(y) for y in re.findall(r"[ML]\s*-?[\d.]+,(-?[\d.]+)", element.get("d", ""))]
            tops[key] = min([tops[key], *ys])
    return [(kind, tops[key] - baseline) for key, (kind, baseline) in headings.items() if tops[key] < float("inf")]


def test_a_heading_left_with_no_scale_stands_as_close_over_its_drawings_as_a_line_of_scales_does(sheets_of):
    """The triad's equations that go on alone on an A4 are drawn at no scale: their heading named none but kept
    the line's room, a line's gap between the title and the equations."""
    gaps = [gap for path in sheets_of("triad_class_iii", "A4") for gap in heading_gaps(path)]
    bare = [gap for kind, gap in gaps if kind == "none"]
    named = [gap for kind, gap in gaps if kind == "scales"]
    assert bare and named
    assert max(bare) <= max(named) + 0.5, (bare, named)
