"""The rows of a force sheet on a sheet too small for them in one or two columns (graphplan.render.force_rows).

Drawings here are plain rectangles of known size, so that what fits where can be worked out by hand.
"""

from __future__ import annotations

import pytest

from graphplan.render.force_rows import Drawing, Heading, Rows
from graphplan.render.plans import CAPTION_GAP_MM, GAP_MM
from graphplan.render.primitives import Layer, Polyline, Text, bounds

HEADING = Heading("Crank-rocker: force analysis, position 3", (("μl = 0.0025 m/mm", "body-"),), 5.0,
                  "Force analysis, position 3", "Force analysis, position 3 (continued)")


def box(name: str, width: float, height: float) -> Drawing:
    """A drawing ``width`` × ``height`` mm with a one-line caption."""
    corners = ((0.0, 0.0), (width, 0.0), (width, height), (0.0, height))
    return Drawing(name, [Layer(f"{name}-lines", (Polyline(corners, closed=True),))], (name,))


def size(arrangement) -> tuple[float, float]:
    x0, y0, x1, y1 = bounds(arrangement.layers)
    return x1 - x0, y1 - y0


def within(width_limit: float, height_limit: float):
    return lambda width, height: width <= width_limit and height <= height_limit


def heading_of(arrangement) -> list[str]:
    return [item.text for layer in arrangement.layers if layer.name == "sheet-title" for item in layer.items
            if isinstance(item, Text) and item.weight == "bold"]


def reading_order(arrangement, names) -> list[str]:
    """The drawings down each column, the columns left to right (every drawing here stands in a column of
    its own rows, its left edge the column's)."""
    return sorted(names, key=lambda name: (round(arrangement.fields[name][0], 6), -arrangement.fields[name][3]))


def groups(count: int, body=(100.0, 200.0), polygon=(100.0, 50.0)) -> list[list[Drawing]]:
    return [[box(f"body-{k}", *body), box(f"polygon-{k}", *polygon)] for k in range(count)]


def test_rows_that_fit_neither_in_one_nor_two_columns_stand_whole_each_polygon_under_its_group():
    """Three groups (a 100 × 200 mm group over a 100 × 50 mm polygon): one column is over 700 mm tall, two
    side-by-side columns over 450 mm wide; stacked in three columns they are 350 mm wide and about 330 mm tall."""
    rows = Rows(groups(3), HEADING)
    fits = within(400.0, 360.0)
    assert not fits(*size(rows.arranged(rows.in_columns(1))))
    assert not fits(*size(rows.arranged(rows.in_columns(2))))
    parts = rows.parts(fits)
    assert parts is not None and len(parts) == 1
    (whole,) = parts
    assert fits(*size(whole))
    names = [drawing.name for row in rows.drawings for drawing in row]
    assert reading_order(whole, names) == names
    # Each polygon right under its group, in the group's column.
    for k in range(3):
        body, polygon = whole.fields[f"body-{k}"], whole.fields[f"polygon-{k}"]
        assert polygon[0] == pytest.approx(body[0]) and polygon[3] < body[1]
        assert body[1] - polygon[3] < 2 * CAPTION_GAP_MM + 2 * HEADING.size
    assert heading_of(whole) == [HEADING.title]


def test_rows_no_sheet_holds_together_go_in_parts_in_order_each_under_its_heading():
    """Four drawings of 150 × 280 mm, each a row of its own: two side by side are 325 mm wide, more than the
    300 mm a sheet has, and two in a column 585 mm tall: each part holds one."""
    rows = Rows([[box(f"lever-{k}", 150.0, 280.0)] for k in range(4)], HEADING)
    fits = within(300.0, 340.0)
    parts = rows.parts(fits)
    assert parts is not None and len(parts) == 4
    assert [list(part.fields) for part in parts] == [[f"lever-{k}"] for k in range(4)]
    assert all(fits(*size(part)) for part in parts)
    assert heading_of(parts[0]) == [HEADING.part_title]
    # A heading wider than the drawings stands on one line where the sheet has room for it: broken to the
    # caption's width, it took two lines though the sheet had room.
    for part in parts[1:]:
        assert heading_of(part) == [HEADING.continued]
        assert fits(*size(part))


def test_a_part_takes_as_many_rows_as_its_sheet_holds():
    """Four 100 × 100 mm drawings where a sheet holds two in a row but not three: two parts, not four."""
    rows = Rows([[box(f"drawing-{k}", 100.0, 100.0)] for k in range(4)], HEADING)
    fits = within(2 * 100.0 + GAP_MM + 40.0, 200.0)
    parts = rows.parts(fits)
    assert parts is not None
    assert [list(part.fields) for part in parts] == [["drawing-0", "drawing-1"], ["drawing-2", "drawing-3"]]


def test_of_as_many_parts_the_cuts_keep_most_groups_with_their_polygons():
    """Two groups each too wide beside its polygon (100 + 15 + 150 mm on a 200 mm sheet) stand drawing by
    drawing in three parts. The least paper cuts both groups from their polygons (group a | polygon a, group b |
    polygon b, lever); the first group and its polygon are too tall for one part, but the second stays whole
    with the first polygon, as many parts."""
    rows = Rows([[box("body-a", 100.0, 200.0), box("polygon-a", 150.0, 40.0)],
                 [box("body-b", 100.0, 40.0), box("polygon-b", 150.0, 40.0)], [box("lever", 150.0, 150.0)]], HEADING)
    fits = within(200.0, 300.0)
    parts = rows.parts(fits)
    assert parts is not None and all(fits(*size(part)) for part in parts)
    assert [list(part.fields) for part in parts] == [["body-a"], ["polygon-a", "body-b", "polygon-b"], ["lever"]]


def scales_of(arrangement) -> list[str]:
    return [item.text for layer in arrangement.layers if layer.name == "sheet-title" for item in layer.items
            if isinstance(item, Text) and item.weight != "bold"]


def test_each_part_names_the_scales_of_the_drawings_that_may_stand_under_it():
    """The sheet of the test above with μl, μF and μV in its heading: standing whole it names all three; in parts,
    the lever alone on the last is drawn at μV only, so its heading names μV, not the groups' μl and the
    polygons' μF it once named.  A part's heading names the later parts' scales too: a part that goes on on the
    sheet of the part before stands under that part's heading, without its own."""
    lines = {"body-": "μl = 0.0025 m/mm", "polygon-": "μF = 10 N/mm", "lever": "μV = 0.02 (m/s)/mm"}
    heading = Heading(HEADING.title, tuple((line, start) for start, line in lines.items()), HEADING.size,
                      HEADING.part_title, HEADING.continued)
    rows = Rows([[box("body-a", 100.0, 200.0), box("polygon-a", 150.0, 40.0)],
                 [box("body-b", 100.0, 40.0), box("polygon-b", 150.0, 40.0)], [box("lever", 150.0, 150.0)]], heading)
    every = ", ".join(lines.values())
    assert scales_of(rows.arranged(rows.in_columns(1))) == [every]
    # 220 mm wide: the line of all three scales is some 206 mm long at 5 mm, and every heading is measured with it.
    parts = rows.parts(within(220.0, 300.0))
    assert parts is not None
    assert [list(part.fields) for part in parts] == [["body-a"], ["polygon-a", "body-b", "polygon-b"], ["lever"]]
    assert scales_of(parts[-1]) == [lines["lever"]]
    for k, part in enumerate(parts):
        later = {name for after in parts[k:] for name in after.fields}
        assert scales_of(part) == [", ".join(line for start, line in lines.items()
                                             if any(name.startswith(start) for name in later))], list(part.fields)


def test_a_last_part_whose_drawings_have_none_of_the_sheet_s_scales_is_headed_by_its_title_alone():
    """A polygon at a μF of its own (its caption gives it) on the last part of a sheet without a lever: none of the
    heading's scales is one it is drawn at."""
    heading = Heading(HEADING.title, (("μl = 0.0025 m/mm", "body-"),), HEADING.size, HEADING.part_title,
                      HEADING.continued)
    rows = Rows([[box("body-a", 150.0, 250.0)], [box("polygon-a", 150.0, 250.0)]], heading)
    parts = rows.parts(within(200.0, 330.0))
    assert parts is not None and [list(part.fields) for part in parts] == [["body-a"], ["polygon-a"]]
    assert [scales_of(part) for part in parts] == [["μl = 0.0025 m/mm"], []]
    assert [" ".join(heading_of(part)) for part in parts] == [HEADING.part_title, HEADING.continued]


def test_a_row_too_wide_for_a_sheet_stands_drawing_by_drawing_and_a_drawing_too_tall_for_a_heading_alone():
    """A group 100 × 310 mm beside its polygon is too wide for a 180 mm sheet and, stacked, too tall; alone
    the group fits the 330 mm height only without the heading's 30 mm, its caption under it or beside it."""
    rows = Rows([[box("body", 100.0, 310.0), box("polygon", 150.0, 100.0)]], HEADING)
    fits = within(180.0, 330.0)
    parts = rows.parts(fits)
    assert parts is not None and [list(part.fields) for part in parts] == [["body"], ["polygon"]]
    # The first heading is the sheet's, though a part without one comes before it.
    assert heading_of(parts[0]) == [] and " ".join(heading_of(parts[1])) == HEADING.part_title
    assert all(fits(*size(part)) for part in parts)
    assert rows.unheld(fits) == {}


@pytest.mark.parametrize("height", [120.0, 140.0])
def test_only_a_drawing_with_no_room_for_a_heading_stands_without_one(height):
    """After a group too tall for a heading, the driver and its polygon fit on one sheet only without a heading:
    they stand under headings in more parts instead, and the first heading is the sheet's, the rest continued."""
    rows = Rows([[box("body", 100.0, 310.0), box("polygon", 150.0, 100.0)],
                 [box("driver", 100.0, height), box("driver-polygon", 100.0, height)]], HEADING)
    fits = within(180.0, 330.0)
    parts = rows.parts(fits)
    assert parts is not None and all(fits(*size(part)) for part in parts)
    assert [name for part in parts for name in part.fields] == ["body", "polygon", "driver", "driver-polygon"]
    headless = [list(part.fields) for part in parts if not heading_of(part)]
    assert headless == [["body"]]
    titles = [" ".join(heading_of(part)) for part in parts if heading_of(part)]
    assert titles[0] == HEADING.part_title and set(titles[1:]) == {HEADING.continued}


def test_a_drawing_too_tall_for_a_heading_over_its_caption_stands_under_one_with_its_caption_beside_it():
    """A group 100 × 300 mm misses the 330 mm under the heading with its caption under it (300 mm, the gap and
    a line of caption, the heading's 30 mm) but not with its caption beside it: it stands under the heading so,
    not on a part with none (the crank-rocker's group with friction on a Russian A3)."""
    rows = Rows([[box("body", 100.0, 300.0), box("polygon", 150.0, 100.0)]], HEADING)
    fits = within(180.0, 330.0)
    alone = Rows([[box("body", 100.0, 300.0)]], HEADING)
    title = HEADING.part_title
    assert not fits(*size(alone.arranged(alone.in_columns(1), title)))
    parts = rows.parts(fits)
    assert parts is not None and [list(part.fields) for part in parts] == [["body"], ["polygon"]]
    assert [" ".join(heading_of(part)) for part in parts] == [title, HEADING.continued]
    body = parts[0]
    # The way a sheet holds it: its caption level with the drawing, right of it, the heading over both.
    assert body.aside is not None and fits(*size(body.aside)) and not fits(*size(body))
    caption = next(item for layer in body.aside.layers if layer.name == "body-caption" for item in layer.items)
    drawing = bounds([layer for layer in body.aside.layers if layer.name == "body-lines"])
    assert caption.at[0] > drawing[2] and drawing[1] < caption.at[1] < drawing[3]
    assert bounds(body.aside.layers)[3] > drawing[3] + HEADING.size


def test_a_drawing_no_sheet_holds_even_alone_is_named_with_its_size():
    rows = Rows([[box("body", 100.0, 500.0), box("polygon", 50.0, 50.0)]], HEADING)
    fits = within(180.0, 330.0)
    assert rows.parts(fits) is None
    (unheld,) = rows.unheld(fits).items()
    name, (width, height) = unheld
    assert name == "body" and width == 100 and height > 500


@pytest.mark.parametrize(("caption_size", "title_size"), [(5.0, 7.0), (3.5, 5.0), (2.5, 3.5)])
def test_the_heading_title_is_lettered_one_size_above_the_captions(caption_size, title_size):
    """GOST 2.304 and ISO 3098 letter in a √2 series (2.5, 3.5, 5, 7 mm): a title one step above captions
    that a small sheet letters 3.5 mm is 5 mm, not the 7 mm over the usual 5 mm captions."""
    heading = Heading(HEADING.title, HEADING.scales, caption_size, HEADING.part_title, HEADING.continued)
    rows = Rows(groups(1), heading)
    arranged = rows.arranged(rows.in_columns(1), heading.title)
    titles = [item for layer in arranged.layers if layer.name == "sheet-title" for item in layer.items]
    assert {item.size for item in titles if item.weight == "bold"} == {title_size}
    assert {item.size for item in titles if item.weight != "bold"} == {caption_size}
