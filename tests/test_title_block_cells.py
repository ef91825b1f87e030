"""The title block as a teacher marks it: the scale written as the rest of the sheet writes its numbers, the
title and the drawing's name clear of their cell's sides, and ESKD's графа 26 at the top left of the frame.

Widths are measured with the fonts the sheets are rendered in (DejaVu Sans, Noto Sans CJK), not with the
estimate the block fits its texts by.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
from xml.etree import ElementTree

import pytest
from PIL import ImageFont

import graphplan
from graphplan.analysis import analyse
from graphplan.render.packing import Panel
from graphplan.render.primitives import FONT_SIZE_PER_CAP, Layer, Polyline, Text, has_wide
from graphplan.render.sheet import course_sheets, forces_sheet, kinematics_sheet
from graphplan.render.title_block import Details

DRAWING = [Layer("square", (Polyline(((0, 0), (100, 0), (100, 80), (0, 80)), closed=True),))]
FONTS = {("latin", "normal"): "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
         ("latin", "bold"): "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
         ("cjk", "normal"): "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc",
         ("cjk", "bold"): "/usr/share/fonts/opentype/noto/NotoSansCJK-Bold.ttc"}
# The cells (x0, y0, x1, y1 from the block's lower right corner, mm) of the title and the drawing's name:
# ESKD's 70 mm column, GB/T's 50 mm one, ISO's title and document type; and of the scale.
NAME_CELLS = {"ru": ((-120.0, 15.0, -50.0, 40.0),), "zh": ((-50.0, 20.0, 0.0, 38.0),),
              "en": ((-120.0, 10.0, 0.0, 30.0), (-100.0, 30.0, -40.0, 40.0))}
SCALE_CELLS = {"ru": (-18.0, 20.0, 0.0, 35.0), "zh": (-62.0, 7.0, -50.0, 21.0), "en": (-40.0, 30.0, 0.0, 40.0)}
# The fields' own names, printed in their cells.
FIELD_NAMES = {"Title", "Document type", "Scale"}
LEAST_MARGIN_MM = 1.5


@functools.cache
def _font(script: str, weight: str) -> ImageFont.FreeTypeFont:
    return ImageFont.truetype(FONTS[(script, weight)], 1000)


def printed_width(text: Text) -> float:
    """How wide ``text`` prints (mm), in the font the SVG names first for it."""
    font = _font("cjk" if has_wide(text.text) else "latin", text.weight)
    return font.getlength(text.text) / 1000 * text.size * FONT_SIZE_PER_CAP


def printed_span(text: Text) -> tuple[float, float]:
    width = printed_width(text)
    x0 = text.at[0] - {"start": 0.0, "middle": width / 2, "end": width}[text.anchor]
    return x0, x0 + width


def block_texts(sheet) -> list[Text]:
    block = next(layer for layer in sheet.layers if layer.name == "title-block")
    return [item for item in block.items if isinstance(item, Text)]


def in_cell(sheet, cell) -> list[Text]:
    """The texts of the title block that stand in ``cell`` (relative to the block's lower right corner), but for
    the field's name."""
    right, bottom = sheet.title_block[2], sheet.title_block[1]
    x0, y0, x1, y1 = cell
    return [text for text in block_texts(sheet) if text.text not in FIELD_NAMES
            and right + x0 < text.at[0] < right + x1 and bottom + y0 < text.at[1] < bottom + y1]


def scale_box(sheet, locale) -> str:
    return " ".join(text.text for text in in_cell(sheet, SCALE_CELLS[locale]))


@pytest.mark.parametrize("locale, expected", [("ru", "1:2,5"), ("zh", "1:2.5"), ("en", "1:2.5")])
def test_the_scale_box_writes_the_ratio_with_the_locale_s_decimal_mark(locale, expected):
    """ESKD writes 1:2,5 as the rest of a Russian sheet writes its numbers; ISO 7200's Scale field held
    μl = 0.0025 m/mm against its border where ESKD wrote 1:2.5 for the same μl."""
    sheet, = kinematics_sheet([DRAWING], "A3", locale, title="Crank", scale=0.0025)
    assert scale_box(sheet, locale) == expected


def test_a_scale_no_ratio_writes_is_written_out_with_the_locale_s_decimal_mark():
    # GOST 2.302 has no 1:3: the scale factor itself, with a decimal comma.
    sheet, = kinematics_sheet([DRAWING], "A3", "ru", title="Crank", scale=0.003)
    assert scale_box(sheet, "ru") == "μl = 0,003 м/мм"


@pytest.mark.parametrize("locale", ["ru", "zh", "en"])
@pytest.mark.parametrize("title, drawing", [
    ("Six-bar mechanism of a shaping machine", "Силовой анализ, положение 3"),
    ("Crank and slotted lever quick-return mechanism", "速度与加速度多边形，位置 11"),
    ("Ratchet crank-rocker with an output dyad (six-bar)", "Velocity and acceleration plans, position 12")])
def test_the_title_and_the_drawing_s_name_keep_clear_of_their_cell_s_sides(locale, title, drawing):
    # A page of one drawing is named after it, as a force sheet is named after its position.
    sheet, = forces_sheet([Panel("forces-3", tuple(DRAWING), label=drawing)], "A3", locale, title=title)
    right, bottom = sheet.title_block[2], sheet.title_block[1]
    named = [text for cell in NAME_CELLS[locale] for text in in_cell(sheet, cell)]
    assert sorted("".join(text.text for text in named).replace(" ", "")) == sorted((title + drawing).replace(" ", ""))
    for text in named:
        x0, x1 = printed_span(text)
        cell = next(cell for cell in NAME_CELLS[locale] if right + cell[0] < text.at[0] < right + cell[2]
                    and bottom + cell[1] < text.at[1] < bottom + cell[3])
        left_margin, right_margin = x0 - (right + cell[0]), right + cell[2] - x1
        assert min(left_margin, right_margin) >= LEAST_MARGIN_MM, (text.text, left_margin, right_margin)


@pytest.fixture(scope="module")
def ratchet_sheets():
    analysis = analyse(graphplan.load("fixtures/ratchet_crank_rocker.toml"))
    return {locale: course_sheets(analyse(dataclasses.replace(analysis.scene, locale=locale)), "A1",
                                  Details(designation="ТММ.01.02.000 Д1"))
            for locale in ("ru", "zh", "en")}


def test_every_eskd_sheet_writes_its_designation_upside_down_in_the_frame_s_top_left_corner(ratchet_sheets):
    """GOST 2.104 form 1, графа 26: a 70 × 14 mm box against the frame's top and left lines, the designation in it
    turned through 180°, clear of every drawing on the sheet."""
    for sheet in ratchet_sheets["ru"]:
        x0, _, _, y1 = sheet.frame
        box = (x0, y1 - 14.0, x0 + 70.0, y1)
        corner = next(layer for layer in sheet.layers if layer.name == "sheet-designation")
        lines = [item for item in corner.items if isinstance(item, Polyline)]
        points = {point for line in lines for point in line.points}
        # Its bottom and right side drawn; its top and left are the frame's.
        assert {(box[0], box[1]), (box[2], box[1]), (box[2], box[3])} <= {(round(x, 6), round(y, 6)) for x, y in points}
        designation = [item for item in corner.items if isinstance(item, Text)]
        assert [text.text for text in designation] == ["ТММ.01.02.000 Д1"]
        assert "ТММ.01.02.000 Д1" in [text.text for text in block_texts(sheet)]
        for text in designation:
            assert text.rotation == 180.0
            # Turned about its anchor, the text runs leftwards from it and hangs below its baseline.
            width = printed_width(text)
            left, right = text.at[0] - width / 2, text.at[0] + width / 2
            assert box[0] + 1.0 <= left and right <= box[2] - 1.0
            assert box[1] + 1.0 <= text.at[1] - text.size and text.at[1] + 0.3 * text.size <= box[3] - 1.0
        for name, placed in sheet.panels.items():
            assert not (placed[0] < box[2] and box[0] < placed[2] and placed[1] < box[3] and box[1] < placed[3]), name


@pytest.mark.parametrize("locale", ["zh", "en"])
def test_gb_and_iso_sheets_have_no_box_in_the_top_left_corner(ratchet_sheets, locale):
    for sheet in ratchet_sheets[locale]:
        assert "sheet-designation" not in [layer.name for layer in sheet.layers]


def test_the_upside_down_designation_is_turned_in_the_svg(ratchet_sheets):
    svg = ratchet_sheets["ru"][0].svg()
    root = ElementTree.fromstring(svg)
    group = next(element for element in root.iter() if element.get("id") == "sheet-designation")
    text, = [element for element in group.iter() if element.tag.endswith("text")]
    assert text.get("transform") == f"rotate(-180 {text.get('x')} {text.get('y')})"


def _ink_beside(items, text):
    """The inked edges (mm) of the nearest vertical lines left and right of ``text``, across its middle height."""
    y = text.at[1] + text.size / 2
    lines = []  # (x, stroke width) of each line across the text's height
    for item in items:
        if isinstance(item, Polyline):
            points = list(item.points) + ([item.points[0]] if item.closed else [])
            lines += [(xa, item.stroke.width) for (xa, ya), (xb, yb) in itertools.pairwise(points)
                      if xa == xb and min(ya, yb) <= y <= max(ya, yb)]
    left = max((x, width) for x, width in lines if x < text.at[0])
    right = min((x, width) for x, width in lines if x > text.at[0])
    return left[0] + left[1] / 2, right[0] - right[1] / 2


def _extent(text):
    """A text's left and right ends as the block fits it: ``text_width``, the renderer's measure of a text."""
    from graphplan.render.primitives import text_width

    width = text_width(text.text, text.size, text.weight)
    x0 = text.at[0] - {"start": 0.0, "middle": width / 2, "end": width}[text.anchor]
    return x0, x0 + width


@pytest.mark.parametrize("locale", ["zh", "en", "ru"])
def test_every_text_of_the_block_keeps_its_padding_from_the_ink_of_the_lines_beside_it(locale):
    """«Разраб.», «Т.контр.» and ISO's field names stood 0.15 mm from the block's thick lines: a text's padding was
    counted from a line's middle, and a thick line's half width, 0.35 mm, took most of a label's 0.5 mm.  The lines
    are read off the block as drawn.  A name its padding would set below the smallest lettering («Изм.» in its
    7 mm) gives up its padding instead, and stands at the smallest lettering clear of the ink."""
    from graphplan.render.title_block import (
        LABEL_PADDING,
        SMALLEST_LETTERING,
        TitleBlockFields,
        form_of,
        labels,
        title_block,
    )

    fields = TitleBlockFields(title="Crank and slotted lever quick-return mechanism", author="A. Student",
                              checked_by="Prof. B. Teacher", approved_by="C. Head", designation="TMM.CP.01.00.00",
                              organization="University, group 21", date="2026-12-01",
                              drawing="Силовой анализ, положение 11", scale="1:2.5", sheet=3, sheets=4,
                              language=locale)
    items = title_block(form_of(locale), fields, labels(locale), (200.0, 0.0))
    texts = [item for item in items if isinstance(item, Text)]
    assert len(texts) > 20
    for text in texts:
        left, right = _ink_beside(items, text)
        x0, x1 = _extent(text)
        # (A value too long for its box is set smaller, and warned of (``cramped``), but keeps its padding.)
        padding = 0.0 if text.size == SMALLEST_LETTERING else LABEL_PADDING
        assert left + padding - 1e-9 <= x0 and x1 <= right - padding + 1e-9, (text.text, left, x0, x1, right)


@pytest.mark.parametrize("locale", ["zh", "en", "ru"])
def test_the_gb_change_header_s_names_keep_a_value_s_padding_from_their_cell_s_lines(locale):
    """年、月、日 filled its 16 mm cell to 1 mm of the lines' middles, and of the block's thick line at 80 mm only
    0.7 mm of paper was left: each name of the row keeps the padding a value keeps, from its lines' inked edges."""
    from graphplan.render.title_block import PADDING, TitleBlockFields, labels, title_block

    fields = TitleBlockFields(title="", drawing="", scale="", sheet=1, sheets=1)
    items = title_block("gb", fields, labels(locale), (180.0, 0.0))
    words = labels(locale)
    header = [words[key] for key in ("gb_mark", "gb_places", "gb_zone", "gb_change_document", "gb_signature",
                                     "gb_date")]
    names = [item for item in items if isinstance(item, Text) and item.text in header and 28.0 < item.at[1] < 35.0]
    assert sorted(name.text for name in names) == sorted(header)
    for name in names:
        left, right = _ink_beside(items, name)
        x0, x1 = _extent(name)
        assert left + PADDING - 1e-9 <= x0 and x1 <= right - PADDING + 1e-9, (name.text, left, x0, x1, right)
        # And above and below: the row's lines at 28 mm (thick) and 35 mm.
        rows = [(ya, item.stroke.width) for item in items if isinstance(item, Polyline)
                for (xa, ya), (xb, yb) in itertools.pairwise(item.points)
                if ya == yb and min(xa, xb) < name.at[0] < max(xa, xb) and 27.0 < ya < 36.0]
        bottom, top = min(rows), max(rows)
        assert bottom[0] + bottom[1] / 2 + PADDING <= name.at[1] - 0.3 * name.size
        assert name.at[1] + 1.15 * name.size <= top[0] - top[1] / 2 - PADDING + 1e-9


@pytest.mark.parametrize("title", ["三级杆组六杆机构（带滑块）运动与力分析", "牛头刨床「六杆机构」的运动分析与力分析，第二方案",
                                   "曲柄摇杆机构（筛分机驱动）运动分析"])
def test_a_chinese_title_breaks_no_line_after_an_opening_bracket_or_before_a_closing_one_or_a_stop(title):
    """«三级杆组六杆机构（» over «带滑块）运动与力分析»: Chinese setting (禁则) ends no line on an opening bracket and
    starts none with a closing one or a stop; any ideograph else may end a line.  Every break is checked, at each
    number of lines a cell may give it."""
    from graphplan.render.title_block import wrapped

    for lines in (2, 3, 4):
        broken = wrapped(title, lines, 5.0, "bold")
        assert "".join(broken) == title
        for line in broken[:-1]:
            assert line[-1] not in "（「《", broken
        for line in broken[1:]:
            assert line[0] not in "）」》，。、；：", broken
