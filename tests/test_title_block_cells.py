"""The title block as a teacher marks it: the scale written as the rest of the sheet writes its numbers, the
title and the drawing's name clear of their cell's sides, and ESKD's графа 26 at the top left of the frame.

Widths are measured with the fonts the sheets are rendered in (DejaVu Sans, Noto Sans CJK), not with the
estimate the block fits its texts by.
"""

from __future__ import annotations

import functools

import pytest
from PIL import ImageFont

from graphplan.render.packing import Panel
from graphplan.render.primitives import FONT_SIZE_PER_CAP, Layer, Polyline, Text, has_wide
from graphplan.render.sheet import forces_sheet, kinematics_sheet

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
