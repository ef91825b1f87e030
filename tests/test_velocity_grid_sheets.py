"""The velocity plans of every position fill the course-project sheets as a draftsman fills them.

A user's Watt II six-bar on A3 took eight sheets: the grid went one row of
four plans to a sheet, two-thirds of each blank, and the plan of positions
stood alone and small on the first.  The grid's rows now go on each sheet
as long as its room holds, beside the drawings already there.  What fits is
worked out here from the sheet as drawn (its frame, its title block, the
plans' boxes read from the SVG), not from the packing.

In Russian the first sheet again held the plan of positions alone: set under
ESKD's графа 26 in the frame's top left corner, it left no room under it for
the grid's first run, whose heading is wider in Russian than the strip beside
the title block; beside графа 26 it leaves a row of plans, as in English.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from itertools import combinations, pairwise

import pytest
from scene_texts import watt_ii
from sheet_texts import box as text_box
from sheet_texts import texts

from graphplan.analysis import analyse
from graphplan.render.formats import PADDING_MM
from graphplan.render.packing import GAP_MM
from graphplan.render.sheet import course_sheets
from graphplan.scene import loads

WATT_II = watt_ii(every_velocity_plan=True, sheet="A3")
TITLE_LINE = 'title = "Watt II six-bar linkage"\n'

SVG = "{http://www.w3.org/2000/svg}"
Box = tuple[float, float, float, float]  # x0, y0, x1, y1 in the SVG's millimetres, y down


def _union(boxes: list[Box]) -> Box:
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes))


def _overlap(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _group_box(group: ET.Element) -> Box | None:
    """The box of what a group draws: its paths' points, its circles, its texts (as wide as they are set)."""
    boxes: list[Box] = []
    for path in group.iter(f"{SVG}path"):
        numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", path.get("d", ""))]
        xs, ys = numbers[0::2], numbers[1::2]
        boxes.append((min(xs), min(ys), max(xs), max(ys)))
    for circle in group.iter(f"{SVG}circle"):
        x, y, r = (float(circle.get(key)) for key in ("cx", "cy", "r"))
        boxes.append((x - r, y - r, x + r, y + r))
    source = ET.tostring(group, encoding="unicode").replace("ns0:", "")
    boxes += [text_box(*found) for found in texts(source)]
    return _union(boxes) if boxes else None


def _drawing_of(name: str) -> str:
    """The drawing a group of the sheet belongs to: a plan of the grid by its position, the grid's heading, a plan
    sheet's drawing, or the panel its name begins with."""
    found = re.search(r"position-(\d+)-", name)
    if name.startswith("velocity-plans") and found and not name.endswith("-title"):  # the title goes with plan 1
        return f"plan {found.group(1)}"
    if name.startswith("velocity-plans"):
        return f"heading {name}"
    # A plan sheet's mechanism, velocity and acceleration plans are drawings of their own, set as an L at times.
    return "-".join(name.split("-")[:3]) if name.startswith("plan-") else name.split("-")[0]


class _Sheet:
    """A sheet's frame, title block and the box of each drawing on it, read from its SVG."""

    def __init__(self, svg: str) -> None:
        root = ET.fromstring(svg)
        groups = {group.get("id"): group for group in root.iter(f"{SVG}g")}
        frame = next(_group_box_of_path(path) for path in groups["sheet-frame"].iter(f"{SVG}path")
                     if path.get("stroke") == "black" and path.get("d", "").endswith("Z"))
        self.frame = frame
        self.block = _group_box(groups["title-block"])
        # ESKD's графа 26, which drawings keep clear of as of the title block.
        self.corner = _group_box(groups["sheet-designation"]) if "sheet-designation" in groups else None
        self.area = (frame[0] + PADDING_MM, frame[1] + PADDING_MM, frame[2] - PADDING_MM, frame[3] - PADDING_MM)
        drawings: dict[str, list[Box]] = {}
        for name, group in groups.items():
            if name in ("sheet-frame", "title-block", "sheet-designation"):
                continue
            found = _group_box(group)
            if found is not None:
                drawings.setdefault(_drawing_of(name), []).append(found)
        self.drawings = {name: _union(boxes) for name, boxes in drawings.items()}
        self.plans = {int(name.split()[1]): b for name, b in self.drawings.items() if name.startswith("plan ")}
        self.texts = [(text, text_box(x, y, size, anchor, text)) for x, y, size, anchor, text in texts(svg)
                      if not _in(text_box(x, y, size, anchor, text), self.block)]


def _group_box_of_path(path: ET.Element) -> Box:
    numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", path.get("d", ""))]
    return min(numbers[0::2]), min(numbers[1::2]), max(numbers[0::2]), max(numbers[1::2])


def _in(inner: Box, outer: Box, slack: float = 1e-6) -> bool:
    return (inner[0] >= outer[0] - slack and inner[1] >= outer[1] - slack and inner[2] <= outer[2] + slack
            and inner[3] <= outer[3] + slack)


def _room_for(sheet: _Sheet, size: tuple[float, float]) -> str | None:
    """Where a plan of ``size`` (width, height with its caption) would still go on ``sheet`` after the grid's last
    plan there: as a new row under all the sheet's drawings, or at the end of the last row; None where nowhere.

    The drawings are taken up to the area's top left corner first (the sheet sets them in its middle), no higher
    than the room kept under a corner box (графа 26) lets those under it go."""
    ax0, ay0, _, _ = sheet.area
    content = _union(list(sheet.drawings.values()))
    dx, dy = ax0 - content[0], ay0 - content[1]
    corner = None if sheet.corner is None else _grown(sheet.corner, PADDING_MM)
    if corner is not None:
        dy = max([dy, *(corner[3] - b[1] for b in sheet.drawings.values() if b[0] + dx < corner[2])])
    boxes = {name: (b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy) for name, b in sheet.drawings.items()}
    block_top, block_left = sheet.block[1] - PADDING_MM, sheet.block[0] - PADDING_MM
    width, height = size

    def clear(rect: Box) -> bool:
        if not _in(rect, sheet.area) or (rect[3] > block_top and rect[2] > block_left):
            return False
        if corner is not None and _overlap(rect, corner):
            return False
        return not any(_overlap(rect, (b[0] - GAP_MM, b[1] - GAP_MM, b[2] + GAP_MM, b[3] + GAP_MM))
                       for b in boxes.values())

    top = max(b[3] for b in boxes.values()) + GAP_MM
    if clear((ax0, top, ax0 + width, top + height)):
        return "a row under the drawings"
    last = max(sheet.plans)
    row = [b for number, b in sheet.plans.items() if _overlap((-1e9, b[1], 1e9, b[3]), sheet.plans[last])]
    left, row_top = max(b[2] for b in row) + dx + GAP_MM, min(b[1] for b in row) + dy
    if clear((left, row_top, left + width, row_top + height)):
        return "the end of the last row"
    return None


def _grown(b: Box, by: float) -> Box:
    return b[0] - by, b[1] - by, b[2] + by, b[3] + by


# Russian sheets (ESKD) have графа 26 in the frame's corner and a taller title block; Chinese ones (GB/T) are ISO's
# shape with other margins.
@pytest.fixture(scope="module", params=["en", "ru", "zh"])
def sheets(request) -> list[_Sheet]:
    scene = WATT_II.replace(TITLE_LINE, f'{TITLE_LINE}locale = "{request.param}"\n', 1)
    assert f'locale = "{request.param}"' in scene
    return [_Sheet(page.svg()) for page in course_sheets(analyse(loads(scene)), "A3")]


def test_each_sheet_of_the_grid_holds_as_many_plans_as_its_room_does(sheets):
    grid = [sheet for sheet in sheets if sheet.plans]
    numbers = [number for sheet in grid for number in sorted(sheet.plans)]
    assert numbers == list(range(1, 13))  # every plan once, in order, sheet after sheet
    for sheet, following in pairwise(grid):
        first = following.plans[min(following.plans)]
        size = (first[2] - first[0], first[3] - first[1])
        assert _room_for(sheet, size) is None, (min(following.plans), _room_for(sheet, size))
    # The plan of positions shares its sheet with plans of the grid: the first sheet has room beside it.
    assert "positions" in grid[0].drawings


def test_no_two_drawings_overlap_and_no_text_leaves_the_frame_or_runs_over_the_title_block(sheets):
    for k, sheet in enumerate(sheets):
        for (one, a), (other, b) in combinations(sheet.drawings.items(), 2):
            assert not _overlap(a, b), (k + 1, one, other)
        for name, b in sheet.drawings.items():
            assert _in(b, sheet.frame) and not _overlap(b, sheet.block), (k + 1, name)
            assert sheet.corner is None or not _overlap(b, sheet.corner), (k + 1, name)
        for text, b in sheet.texts:
            assert _in(b, sheet.frame) and not _overlap(b, sheet.block), (k + 1, text)
            assert sheet.corner is None or not _overlap(b, sheet.corner), (k + 1, text)
