"""The title block of a sheet, in the form its language's drafting standard prescribes.

Three forms, chosen by the scene's locale:

* ``ru``: ESKD, GOST 2.104-2006 form 1, 185 × 55 mm: the change and
  signature columns on the left (Изм., Лист, № докум., Подп., Дата;
  Разраб., Пров., Т.контр., Н.контр., Утв.), the designation across the top
  right, the name of the drawing, the material, Лит./Масса/Масштаб,
  Лист/Листов and the organisation.  Column widths and row heights follow the
  standard's drawing (7, 10, 23, 15, 10 | 70 | 50; rows of 5 mm).
* ``zh``: GB/T 10609.1-2008, 180 × 56 mm in rows of 7 mm: 更改区 (标记, 处数,
  分区, 更改文件号, 签名, 年、月、日), 签字区 (设计, 标准化, 审核, 工艺, 批准),
  其他区 (阶段标记, 重量, 比例, 共 张 第 张) and 名称及代号区.
* ``en``: ISO 7200:2004, 180 × 40 mm: Created by, Approved by, Document
  type, Scale; Legal owner, Title; Identification number, Rev., Date of
  issue, Lang., Sheet.  Each field's label stands small in its top left
  corner, as ISO 7200 shows it.

A block is drawn in paper millimetres (y up) with its lower right corner at
a given point: the lower right corner of the frame.  What graphplan does not
know (a signature, a date, a mass) is left blank but its box is drawn.
Every value is wrapped and, if it must, set smaller so that it stays inside
its box.
"""

from __future__ import annotations

import datetime
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from functools import cache, lru_cache
from importlib import resources

from ..locale import strings
from ..scales import format_scale
from . import lettering
from .primitives import MAIN, Polyline, Primitive, Stroke, Text, has_wide, is_wide, text_width

# The strings of the three forms and of what graphplan writes into them are the locale files' ``tb_`` keys;
# every locale has every key, so that any form can be drawn in any language.
PREFIX = "tb_"

# The form each locale's drafting standard prescribes.
FORMS = {"ru": "eskd", "zh": "gb", "en": "iso"}
# Width and height of each form (mm).
SIZES = {"eskd": (185.0, 55.0), "gb": (180.0, 56.0), "iso": (180.0, 40.0)}
# The box a form adds in the frame's top left corner (mm): GOST 2.104's графа 26, 70 × 14 mm along the top with the
# designation turned through 180° on an A4 and on a larger sheet with the title block along its long side; down
# the left side, turned through 90°, on a larger sheet stood upright (:func:`graphplan.render.formats.page_geometry`).
CORNER_SIZES = {"eskd": (70.0, 14.0)}

# Standard scales as ``real`` per ``paper`` (mm of the object per mm of the drawing): reductions above
# 1, enlargements below.  GOST 2.302-68; GB/T 14690-1993 (first and second choice); ISO 5455:1979.
STANDARD_RATIOS = {
    "eskd": (1, 2, 2.5, 4, 5, 10, 15, 20, 25, 40, 50, 75, 100, 200, 400, 500, 800, 1000,
             1 / 2, 1 / 2.5, 1 / 4, 1 / 5, 1 / 10, 1 / 20, 1 / 40, 1 / 50, 1 / 100),
    "gb": (1, 1.5, 2, 2.5, 3, 4, 5, 6, 10, 15, 20, 25, 30, 40, 50, 60, 100, 150, 200, 250, 300, 400, 500, 600, 1000,
           1 / 2, 1 / 2.5, 1 / 4, 1 / 5, 1 / 10, 1 / 20, 1 / 25, 1 / 40, 1 / 50, 1 / 100),
    "iso": (1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 1 / 2, 1 / 5, 1 / 10, 1 / 20, 1 / 50),
}

THIN = Stroke(0.25)
# ISO 3098-0's smallest lettering (mm): a field set smaller to fit its box is hard to read printed.
SMALLEST_LETTERING = lettering.SMALLEST
# The heights of the block's lettering (mm), from the standard series (render/lettering.py): a field's printed
# name, ISO 7200's small in its field's corner, what the fields say, the drawing's name and designation, the kind
# of drawing (and ISO 7200's fields' values).  A text its box does not hold steps down the series (:func:`fitted`).
LABEL_SIZE = lettering.BLOCK_LABEL
CORNER_LABEL_SIZE = lettering.BLOCK_CORNER_LABEL
VALUE_SIZE = lettering.BLOCK_VALUE
NAME_SIZE = lettering.BLOCK_NAME
DESIGNATION_SIZE = lettering.BLOCK_DESIGNATION
KIND_SIZE = lettering.BLOCK_KIND
# Room between a text and the lines of its box (mm): a value, a printed label.
PADDING = 0.8
LABEL_PADDING = 0.5
# Room beside the title and the drawing's name, the block's largest lettering (mm): with a value's padding they ran
# to their cell's sides as printed.  Two millimetres by the generous estimate keep 1.5 mm or more of paper.
NAME_MARGIN = 2.0
# Room an ISO 7200 field's name takes at the top of its field (mm).
CORNER_LABEL_ROOM = LABEL_PADDING + 1.45 * CORNER_LABEL_SIZE
# How each form writes a signature's date: ESKD's narrow date column as dd.mm.yy, GB/T 10609.1's 年、月、日
# in that order, ISO 7200's date of issue as ISO 8601.
DATE_FORMATS = {"eskd": "{date:%d.%m.%y}", "gb": "{date:%Y.%m.%d}", "iso": "{date:%Y-%m-%d}"}
# A date typed as text the way Russian forms write it in full, dd.mm.yyyy: ESKD's 10 mm column sets it at about
# 1 mm, so the block reads it as the date it is and writes it as it writes a TOML date.
_FULL_DOTTED_DATE = re.compile(r"(\d{1,2})\.(\d{1,2})\.(\d{4})")
# Line pitch over cap height.
LINE_PITCH = 1.55
# The lines a scale box may break a μl written out into (no ratio of the form's: μl = 0,00004 м/мм): on two, ESKD's
# 18 × 15 mm box set that at 1.7 mm, GB/T's 12 × 14 mm box μl = 0.000004 m/mm at 1.0 mm; "μl =", the number and the
# unit each on its line stand 1.6 times as large.
SCALE_LINES = 3


@dataclass(frozen=True)
class Details:
    """What the title block says beyond the drawings: the scene's title and what only the student knows."""

    title: str = ""
    author: str = ""
    designation: str = ""
    organization: str = ""
    checked_by: str = ""
    approved_by: str = ""
    date: str = ""


def details_of(project: object, title: str, form: str) -> Details:
    """The :class:`Details` a scene's ``[project]`` (:class:`graphplan.scene.Project`) gives, its date written as
    ``form`` writes dates."""
    fields = {name: getattr(project, name) for name in Details.__dataclass_fields__ if hasattr(project, name)}
    date = fields.get("date", "")
    if isinstance(date, str) and form == "eskd":
        date = _dotted_date(date) or date
    if isinstance(date, datetime.date):
        fields["date"] = DATE_FORMATS[form].format(date=date)
    return Details(**{**fields, "title": title})


def _dotted_date(text: str) -> datetime.date | None:
    """The day ``text`` names as dd.mm.yyyy, if it does (not a day of the calendar, such as 31.02.2025: None)."""
    found = _FULL_DOTTED_DATE.fullmatch(text.strip())
    if found is None:
        return None
    day, month, year = (int(part) for part in found.groups())
    try:
        return datetime.date(year, month, day)
    except ValueError:
        return None


def cramped(details: Details, form: str, text: Mapping[str, str]) -> dict[str, float]:
    """The fields of ``details`` (``title``, ``author``, …) that ``form``'s boxes set below :data:`SMALLEST_LETTERING`
    to fit them in, with the size (mm) they get."""
    fields = TitleBlockFields(**{name: getattr(details, name) for name in Details.__dataclass_fields__},
                              drawing="", scale="", sheet=1, sheets=1)

    def texts(of: TitleBlockFields) -> set[Text]:
        return {item for item in title_block(form, of, text, (0.0, 0.0)) if isinstance(item, Text)}

    drawn = texts(fields)
    found = {}
    for name in ("title", "author", "checked_by", "approved_by", "organization", "designation", "date"):
        # A field left empty draws no line of its own: the block without it is the block already drawn, and laying
        # it out again (six of the eight layouts of a scene with no [project]) finds nothing.
        if not getattr(fields, name):
            continue
        # A field's lines are what the block draws with it and not without it.
        sizes = [item.size for item in drawn - texts(replace(fields, **{name: ""}))]
        if sizes and min(sizes) < SMALLEST_LETTERING:
            found[name] = min(sizes)
    return found


def drawing_size(form: str, drawing: str, text: Mapping[str, str]) -> float:
    """The size (mm) ``form``'s block sets ``drawing``, the kind of drawing, at: the smallest of its lines, below the
    usual where its cell holds it only smaller."""
    fields = TitleBlockFields(title="", drawing=drawing, scale="", sheet=1, sheets=1)

    def texts(of: TitleBlockFields) -> set[Text]:
        return {item for item in title_block(form, of, text, (0.0, 0.0)) if isinstance(item, Text)}

    return min((item.size for item in texts(fields) - texts(replace(fields, drawing=""))), default=0.0)


def fitting_name(form: str, names: Sequence[str], text: Mapping[str, str]) -> str:
    """The first of ``names`` that ``form``'s block sets at :data:`SMALLEST_LETTERING` or more; where none fits so,
    the one it sets largest.

    A sheet that holds two kinds of drawing is named by both where its cell
    holds the longer name legibly, else by the shorter names after it; each
    name is tried with its position's word shortened before the next.
    """
    # Each name in full, then with the position's word shortened (pos. 11, пол. 11), before the next name: ISO 7200's
    # one line of Document type set "Force analysis, position 11; load diagrams" at 1.77 mm, and the sheet was named
    # by the kind's word alone, its position dropped.
    tried = list(dict.fromkeys(way for name in names for way in (name, _shortened(name, text))))
    sizes = {name: drawing_size(form, name, text) for name in tried}
    return next((name for name in tried if sizes[name] >= SMALLEST_LETTERING), max(tried, key=sizes.__getitem__))


def _shortened(name: str, text: Mapping[str, str]) -> str:
    """``name`` with the locale's word for a position shortened where a number follows it ("position 11" →
    "pos. 11")."""
    word, short = text.get("position_word", ""), text.get("position_short", "")
    if not word or not short:
        return name
    return re.sub(rf"(?<!\w){re.escape(word)}(?= \d)", lambda _: short, name)


@dataclass(frozen=True, kw_only=True)
class TitleBlockFields(Details):
    """What the title block says: the :class:`Details`, and what the sheet itself gives.

    ``title`` is the scene's title, ``drawing`` the kind of drawing
    (Kinematic analysis), ``scale`` the text of the scale box, ``sheet`` and
    ``sheets`` the sheet's number and how many sheets the set has.  The rest
    is what only the student knows; empty fields are drawn blank.
    """

    # Required here, though a student's Details may leave it empty until the sheets give the scene's.
    title: str = field()
    drawing: str
    scale: str
    sheet: int
    sheets: int
    language: str = ""


def form_of(locale: str) -> str:
    """The title block form of ``locale``'s drafting standard."""
    if locale not in FORMS:
        raise ValueError(f"no title block form for locale {locale!r}; known: {', '.join(sorted(FORMS))}")
    return FORMS[locale]


def labels(locale: str) -> Mapping[str, str]:
    """The title block strings of ``locale`` (its ``tb_`` keys, without the prefix), English where it has none."""
    known = locales()
    if locale not in known:
        raise ValueError(f"no title block strings for locale {locale!r}; known: {', '.join(known)}")
    return {key.removeprefix(PREFIX): value for key, value in strings(locale).items() if key.startswith(PREFIX)}


@cache
def locales() -> tuple[str, ...]:
    """The locales that have a locale file, sorted."""
    folder = resources.files("graphplan").joinpath("locales")
    return tuple(sorted(entry.name.removesuffix(".toml") for entry in folder.iterdir() if entry.name.endswith(".toml")))


def scale_text(length_scale: float, form: str, length_caption: str, decimal_mark: str = ".") -> str:
    """The scale box's text: a ratio (1:2.5) where the form allows μl's, else μl written out; its numbers with
    ``decimal_mark`` (ESKD writes 1:2,5, as the rest of a Russian sheet writes its numbers).

    ``length_caption`` is the locale's line for μl with a ``{value}``
    field (``μl = {value} m/mm``).  GOST 2.302 and GB/T 14690 allow only
    their standard ratios; ISO 5455 allows intermediate scales where its
    recommended ones do not serve, so any ratio written in a few digits is
    written as one there (μl written out did not fit ISO 7200's Scale field).
    """
    real_per_paper = length_scale * 1000.0
    ratios = [*STANDARD_RATIOS[form]]
    if form == "iso":
        ratios.append(real_per_paper)
    for ratio in ratios:
        if abs(real_per_paper - ratio) <= 1e-9 * ratio and _ratio_number(max(ratio, 1 / ratio)) is not None:
            text = f"1:{_ratio_number(ratio)}" if ratio >= 1 else f"{_ratio_number(1 / ratio)}:1"
            break
    else:
        text = length_caption.format(value=format_scale(length_scale))
    return _DECIMAL_POINT.sub(decimal_mark, text)


# A point between two digits: the decimal point of the scale box's numbers.
_DECIMAL_POINT = re.compile(r"(?<=\d)\.(?=\d)")
# A ratio is written when its number has at most this many significant digits: 1:2.5, 1:3, not 1:2.66667.
_RATIO_DIGITS = 4


def _ratio_number(value: float) -> str | None:
    """``value`` (≥ 1) written in at most :data:`_RATIO_DIGITS` significant digits, exactly; None when it takes
    more."""
    text = f"{value:.3f}".rstrip("0").rstrip(".")
    if abs(float(text) - value) > 1e-9 * value or len(text.replace(".", "").lstrip("0")) > _RATIO_DIGITS:
        return None
    return text


def title_block(form: str, fields: TitleBlockFields, text: Mapping[str, str],
                corner: tuple[float, float]) -> list[Primitive]:
    """The title block of ``form`` with its lower right corner at ``corner`` (mm, y up), in the words ``text``.

    ``text`` is :func:`labels` of a locale: any form can be drawn in any language.
    """
    draw = {"eskd": _eskd, "gb": _gb, "iso": _iso}
    if form not in draw:
        raise ValueError(f"unknown title block form {form!r}; known: {', '.join(draw)}")
    width, _ = SIZES[form]
    block = _Block(corner[0] - width, corner[1])
    draw[form](block, fields, text)
    # A row (or column) of printed names is lettered at one height, as a draftsman letters it: the largest of the
    # series that each of its boxes holds (ESKD's «Изм.» holds 1.8 mm, «№ докум.» beside it 2.5 mm).
    least = {row: max(lettering.at_most(size), SMALLEST_LETTERING) for row, size in block.label_sizes.items()
             if size < LABEL_SIZE}
    if least:
        block = _Block(corner[0] - width, corner[1], least)
        draw[form](block, fields, text)
    return block.items


def corner_box(form: str, designation: str, corner: tuple[float, float, float, float]) -> list[Primitive]:
    """The box ``form`` adds at ``corner`` (x0, y0, x1, y1, in the frame's top left corner; none but ESKD's):
    графа 26, the designation as the title block writes it, turned through 180° in a box along the frame's top
    and through 90° in one down its left side, so that it reads from the sheet's edge when the set is filed."""
    if form not in CORNER_SIZES:
        return []
    x0, y0, x1, y1 = corner
    items: list[Primitive] = [Polyline(((x0, y0), (x1, y0), (x1, y1)), MAIN)]
    # Fitted as the title block's designation (5 mm in its 15 mm row) in the box laid along it, then turned
    # about the box's middle.
    middle = complex((x0 + x1) / 2, (y0 + y1) / 2)
    length, depth = max(x1 - x0, y1 - y0), min(x1 - x0, y1 - y0)
    rotation, turn = (180.0, -1 + 0j) if x1 - x0 >= y1 - y0 else (90.0, 1j)
    along = (middle.real - length / 2, middle.imag - depth / 2, middle.real + length / 2, middle.imag + depth / 2)
    for text in fitted(designation, along, DESIGNATION_SIZE):
        turned = middle + (complex(*text.at) - middle) * turn
        items.append(replace(text, at=(turned.real, turned.imag), rotation=rotation))
    return items


class _Block:
    """A title block under construction, in coordinates from its lower left corner.

    Its lines are drawn before its texts, and each text keeps its padding from the inked edge of the lines beside
    its box (:meth:`inner`), not from their middles: a thick line's half width, 0.35 mm, ate a label's 0.5 mm
    padding, and «Изм.», «Разраб.», 年、月、日 stood against the block's thick lines.  (Above and below, a line of
    text has its descenders' room to spare: a sheet's number kept its size.)"""

    def __init__(self, x: float, y: float, row_sizes: Mapping[str, float] | None = None) -> None:
        self.x, self.y = x, y
        self.items: list[Primitive] = []
        # The height each row of printed names is lettered at (LABEL_SIZE where none is given), and the least that
        # each row's labels were set at, by the row's name.
        self.row_sizes = dict(row_sizes or {})
        self.label_sizes: dict[str, float] = {}
        # Each line drawn, (x0, y0, x1, y1, stroke width) from the block's corner: what a text's box is inside of.
        self.lines: list[tuple[float, float, float, float, float]] = []

    def line(self, x0: float, y0: float, x1: float, y1: float, stroke: Stroke = MAIN) -> None:
        self.items.append(Polyline(((self.x + x0, self.y + y0), (self.x + x1, self.y + y1)), stroke))
        self.lines.append((x0, y0, x1, y1, stroke.width))

    def inner(self, box: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
        """``box`` less half the width of the widest line drawn along its left side and along its right."""
        x0, y0, x1, y1 = box

        def half(at: float) -> float:
            widths = [width for ax, ay, bx, by, width in self.lines
                      if abs(ax - at) < 1e-9 and abs(bx - at) < 1e-9 and min(ay, by) < y1 and max(ay, by) > y0]
            return max(widths, default=0.0) / 2

        return x0 + half(x0), y0, x1 - half(x1), y1

    def rows(self, x0: float, x1: float, ys: Sequence[float], stroke: Stroke = THIN) -> None:
        for y in ys:
            self.line(x0, y, x1, y, stroke)

    def outline(self, width: float, height: float) -> None:
        self.items.append(Polyline(((self.x, self.y), (self.x + width, self.y), (self.x + width, self.y + height),
                                    (self.x, self.y + height)), MAIN, closed=True))
        self.lines += [(0.0, 0.0, width, 0.0, MAIN.width), (width, 0.0, width, height, MAIN.width),
                       (0.0, height, width, height, MAIN.width), (0.0, 0.0, 0.0, height, MAIN.width)]

    def text(self, value: str, box: tuple[float, float, float, float], size: float = VALUE_SIZE,
             anchor: str = "middle", weight: str = "normal", lines: int = 1, margin: float | None = None,
             padding: float = PADDING) -> None:
        """``value`` fitted into ``box`` (x0, y0, x1, y1 from the block's corner), ``margin`` mm from its sides (whose
        2 mm, counted from the lines' middles, leave the paper :data:`NAME_MARGIN` says), else ``padding`` from the
        lines' ink."""
        x0, y0, x1, y1 = self.inner(box) if margin is None else box
        self.items.extend(fitted(value, (self.x + x0, self.y + y0, self.x + x1, self.y + y1), size, anchor,
                                 weight, lines, padding=padding, margin=margin))

    def label(self, value: str, box: tuple[float, float, float, float], anchor: str = "middle",
              padding: float = LABEL_PADDING, row: str | None = None) -> None:
        """A printed name (or a short value set as one) fitted into ``box``; one of a ``row`` of names lettered
        at the row's height."""
        x0, y0, x1, y1 = self.inner(box)
        at = (self.x + x0, self.y + y0, self.x + x1, self.y + y1)
        size = self.row_sizes.get(row, LABEL_SIZE) if row is not None else LABEL_SIZE
        texts = fitted(value, at, size, anchor, padding=padding)
        if texts and min(text.size for text in texts) < SMALLEST_LETTERING:
            # A name its padding would set below the smallest lettering gives up its padding first, as far as it
            # must and the ink allows: ESKD's «Изм.» in its 7 mm between two thick lines.
            room = (x1 - x0 - text_width(value, SMALLEST_LETTERING)) / 2 - 1e-6
            if room >= 0:
                texts = fitted(value, at, size, anchor, padding=min(padding, room))
        if texts and row is not None:
            self.label_sizes[row] = min(self.label_sizes.get(row, size), *(text.size for text in texts))
        self.items.extend(texts)

    def corner_label(self, value: str, box: tuple[float, float, float, float]) -> None:
        """An ISO 7200 field's name, small in the top left corner of its field."""
        x0, _, x1, y1 = self.inner(box)
        size = min(CORNER_LABEL_SIZE, CORNER_LABEL_SIZE * (x1 - x0 - 2 * LABEL_PADDING)
                   / text_width(value, CORNER_LABEL_SIZE))
        self.items.append(Text((self.x + x0 + LABEL_PADDING, self.y + y1 - LABEL_PADDING - 1.15 * size), value,
                               math.floor(size * 1000) / 1000, "start"))


# GOST 2.104-2006, form 1: rows of 5 mm from the bottom; x from the block's left edge.
def _eskd(block: _Block, fields: TitleBlockFields, text: Mapping[str, str]) -> None:
    block.outline(185.0, 55.0)
    # The left part: changes (rows 35..55), their header (30..35), the signatures (0..30).
    for x in (17.0, 40.0, 55.0, 65.0):
        block.line(x, 0.0, x, 55.0)
    block.line(7.0, 30.0, 7.0, 55.0)
    block.rows(0.0, 65.0, (35.0, 30.0), MAIN)
    block.rows(0.0, 65.0, (50.0, 45.0, 40.0, 25.0, 20.0, 15.0, 10.0, 5.0))
    # The right part: designation (40..55), name (15..40) and material (0..15) in a 70 mm column,
    # Лит./Масса/Масштаб, Лист/Листов and the organisation in a 50 mm column.
    block.line(65.0, 40.0, 185.0, 40.0)
    block.line(65.0, 15.0, 185.0, 15.0)
    block.line(135.0, 0.0, 135.0, 40.0)
    block.line(135.0, 35.0, 185.0, 35.0)
    block.line(135.0, 20.0, 185.0, 20.0)
    block.line(150.0, 20.0, 150.0, 40.0)
    block.line(167.0, 20.0, 167.0, 40.0)
    block.line(155.0, 15.0, 155.0, 20.0)
    for x in (140.0, 145.0):
        block.line(x, 20.0, x, 35.0, THIN)
    header = 30.0
    for key, (x0, x1) in (("eskd_change", (0.0, 7.0)), ("eskd_sheet", (7.0, 17.0)), ("eskd_document", (17.0, 40.0)),
                          ("eskd_signature", (40.0, 55.0)), ("eskd_date", (55.0, 65.0))):
        block.label(text[key], (x0, header, x1, header + 5.0), row="changes")
    people = (("eskd_designed", 25.0, fields.author), ("eskd_checked", 20.0, fields.checked_by),
              ("eskd_technical_control", 15.0, ""), ("eskd_standards_control", 5.0, ""),
              ("eskd_approved", 0.0, fields.approved_by))
    for key, y, name in people:
        block.label(text[key], (0.0, y, 17.0, y + 5.0), "start", row="signatures")
        # A name in its 5 mm row with a label's padding: a value's set it under 2.5 mm, the series' next down 1.8.
        block.text(name, (17.0, y, 40.0, y + 5.0), LABEL_SIZE, "start", padding=LABEL_PADDING)
    if fields.date:
        block.label(fields.date, (55.0, 25.0, 65.0, 30.0))  # a label's padding: 10 mm hold dd.mm.yy
    block.text(fields.designation, (65.0, 40.0, 185.0, 55.0), DESIGNATION_SIZE)
    _name(block, fields, (65.0, 15.0, 135.0, 40.0))
    block.label(text["eskd_letter"], (135.0, 35.0, 150.0, 40.0), row="others")
    block.label(text["eskd_mass"], (150.0, 35.0, 167.0, 40.0), row="others")
    block.label(text["eskd_scale"], (167.0, 35.0, 185.0, 40.0), row="others")
    block.text(fields.scale, (167.0, 20.0, 185.0, 35.0), VALUE_SIZE, lines=SCALE_LINES)
    block.label(text["eskd_sheet"], (135.0, 15.0, 145.0, 20.0), "start", row="sheets")
    block.text(str(fields.sheet), (145.0, 15.0, 155.0, 20.0), LABEL_SIZE, padding=LABEL_PADDING)
    block.label(text["eskd_sheets"], (155.0, 15.0, 170.0, 20.0), "start", row="sheets")
    block.text(str(fields.sheets), (170.0, 15.0, 185.0, 20.0), LABEL_SIZE, padding=LABEL_PADDING)
    block.text(fields.organization, (135.0, 0.0, 185.0, 15.0), VALUE_SIZE, lines=2)


# GB/T 10609.1-2008: rows of 7 mm from the bottom.  The widths (10, 10, 16, 16, 12, 16 over the changes,
# 12, 12, 16, 12, 12, 16 under them; 4 × 6.5, 12, 12; 50) follow the standard's figure; the heights of the
# cells right of the signatures (material 28, names 7, values 14, sheets 7; unit 18, name 18, code 10,
# projection 10) are this module's reading of it.
def _gb(block: _Block, fields: TitleBlockFields, text: Mapping[str, str]) -> None:
    block.outline(180.0, 56.0)
    # 更改区 (rows 28..56: three blank rows and the header) over 签字区 (0..28).
    block.line(0.0, 28.0, 80.0, 28.0)
    block.rows(0.0, 80.0, (49.0, 42.0, 35.0))
    block.rows(0.0, 80.0, (21.0, 14.0, 7.0))
    for x in (10.0, 20.0, 36.0):
        block.line(x, 28.0, x, 56.0, THIN)
    for x in (12.0, 24.0, 40.0):
        block.line(x, 0.0, x, 28.0, THIN)
    for x in (52.0, 64.0):
        block.line(x, 0.0, x, 56.0, THIN)
    block.line(80.0, 0.0, 80.0, 56.0)
    # 其他区: material mark (28..56), 阶段标记 | 重量 | 比例 (21..28 their names, 7..21 their values),
    # 共 张 第 张 (0..7); 名称及代号区: unit (38..56), drawing name (20..38), code (10..20), projection (0..10).
    block.line(80.0, 28.0, 130.0, 28.0)
    block.line(80.0, 21.0, 130.0, 21.0, THIN)
    block.line(80.0, 7.0, 130.0, 7.0)
    for k in range(1, 4):
        block.line(80.0 + 6.5 * k, 7.0, 80.0 + 6.5 * k, 21.0, THIN)
    for x in (106.0, 118.0):
        block.line(x, 7.0, x, 28.0, THIN)
    block.line(130.0, 0.0, 130.0, 56.0)
    block.rows(130.0, 180.0, (38.0, 20.0, 10.0), MAIN)
    header = 28.0
    # The row's names fill their cells (年、月、日 and 更改文件号 take 14 of 16 mm): each keeps a value's padding from
    # its cell's lines, as the values do, or 年、月、日 ran against the thick line at 80 mm.
    for key, (x0, x1) in (("gb_mark", (0.0, 10.0)), ("gb_places", (10.0, 20.0)), ("gb_zone", (20.0, 36.0)),
                          ("gb_change_document", (36.0, 52.0)), ("gb_signature", (52.0, 64.0)),
                          ("gb_date", (64.0, 80.0))):
        block.label(text[key], (x0, header, x1, header + 7.0), padding=PADDING, row="changes")
    signatures = (("gb_designed", 21.0, 0.0, fields.author), ("gb_standardized", 21.0, 40.0, ""),
                  ("gb_checked", 7.0, 0.0, fields.checked_by), ("gb_process", 0.0, 0.0, ""),
                  ("gb_approved", 0.0, 40.0, fields.approved_by))
    for key, y, x, name in signatures:
        block.label(text[key], (x, y, x + 12.0, y + 7.0), row="signatures")
        block.text(name, (x + 12.0, y, x + 24.0, y + 7.0), LABEL_SIZE)
    if fields.date:
        block.text(fields.date, (24.0, 21.0, 40.0, 28.0), LABEL_SIZE)
    block.label(text["gb_stage"], (80.0, 21.0, 106.0, 28.0), row="others")
    block.label(text["gb_weight"], (106.0, 21.0, 118.0, 28.0), row="others")
    block.label(text["gb_scale"], (118.0, 21.0, 130.0, 28.0), row="others")
    block.text(fields.scale, (118.0, 7.0, 130.0, 21.0), VALUE_SIZE, lines=SCALE_LINES)
    block.label(text["gb_sheets"].format(number=fields.sheet, count=fields.sheets), (80.0, 0.0, 130.0, 7.0))
    block.text(fields.organization, (130.0, 38.0, 180.0, 56.0), VALUE_SIZE, lines=2)
    _name(block, fields, (130.0, 20.0, 180.0, 38.0))
    block.text(fields.designation, (130.0, 10.0, 180.0, 20.0), VALUE_SIZE)


# ISO 7200:2004: the fields in rows of 10 mm, each with its name in the top left corner.
def _iso(block: _Block, fields: TitleBlockFields, text: Mapping[str, str]) -> None:
    block.outline(180.0, 40.0)
    block.line(0.0, 30.0, 180.0, 30.0)
    block.line(60.0, 10.0, 180.0, 10.0)
    block.line(60.0, 0.0, 60.0, 30.0)
    for x in (40.0, 80.0, 140.0):
        block.line(x, 30.0, x, 40.0, THIN)
    for x in (110.0, 120.0, 150.0, 160.0):
        block.line(x, 0.0, x, 10.0, THIN)
    cells = (
        ("iso_created_by", (0.0, 30.0, 40.0, 40.0), fields.author),
        ("iso_approved_by", (40.0, 30.0, 80.0, 40.0), fields.approved_by),
        ("iso_document_type", (80.0, 30.0, 140.0, 40.0), fields.drawing),
        ("iso_scale", (140.0, 30.0, 180.0, 40.0), fields.scale),
        ("iso_identification", (60.0, 0.0, 110.0, 10.0), fields.designation),
        ("iso_revision", (110.0, 0.0, 120.0, 10.0), ""),
        ("iso_date_of_issue", (120.0, 0.0, 150.0, 10.0), fields.date),
        ("iso_language", (150.0, 0.0, 160.0, 10.0), fields.language),
        ("iso_sheet", (160.0, 0.0, 180.0, 10.0), text["sheet_of"].format(number=fields.sheet, count=fields.sheets)),
    )
    for key, (x0, y0, x1, y1), value in cells:
        block.corner_label(text[key], (x0, y0, x1, y1))
        block.text(value, (x0, y0, x1, y1 - CORNER_LABEL_ROOM), KIND_SIZE,
                   margin=NAME_MARGIN if key == "iso_document_type" else None)
    block.corner_label(text["iso_legal_owner"], (0.0, 0.0, 60.0, 30.0))
    block.text(fields.organization, (0.0, 0.0, 60.0, 30.0 - CORNER_LABEL_ROOM), VALUE_SIZE, lines=3)
    block.corner_label(text["iso_title"], (60.0, 10.0, 180.0, 30.0))
    block.text(fields.title, (60.0, 10.0, 180.0, 30.0 - CORNER_LABEL_ROOM), NAME_SIZE, weight="bold", lines=3,
               margin=NAME_MARGIN)


def _name(block: _Block, fields: TitleBlockFields, box: tuple[float, float, float, float]) -> None:
    """The drawing's name: the scene's title over the kind of drawing, each fitted into its share of ``box``."""
    x0, y0, x1, y1 = box
    split = y0 + 0.32 * (y1 - y0)
    block.text(fields.title, (x0, split, x1, y1), NAME_SIZE, weight="bold", lines=4, margin=NAME_MARGIN)
    block.text(fields.drawing, (x0, y0, x1, split), KIND_SIZE, lines=2, margin=NAME_MARGIN)


# Fitting a text into a box.

_SPACES = re.compile(r"\s+")


def _tokens(value: str, at_spaces: bool = False) -> list[tuple[str, bool]]:
    """Words and ideographs of ``value`` (words alone ``at_spaces``), each with whether a space stands before it; a
    number after a word kept with it (:func:`_numbers_kept`), a bracket or a stop with what it holds on to
    (:func:`_punctuation_held`)."""
    return _punctuation_held(_numbers_kept(_split(value, at_spaces)))


# Chinese (and Japanese) setting's rule of lines (禁则): no line ends on an opening bracket, none starts with a
# closing one or a stop.  A title broke «三级杆组六杆机构（» over «带滑块）运动与力分析».
_OPENING = frozenset("（「『《〈【〔“‘")
_CLOSING = frozenset("）」』》〉】〕”’，。、；：！？")


def _punctuation_held(tokens: list[tuple[str, bool]]) -> list[tuple[str, bool]]:
    """``tokens`` with a wide opening bracket joined to the token after it and a wide closing bracket or stop to the
    token before it (where no space stands between them), so that no line breaks at either."""
    held: list[tuple[str, bool]] = []
    for token, spaced in tokens:
        if held and not spaced and (token[0] in _CLOSING or held[-1][0][-1] in _OPENING):
            held[-1] = (held[-1][0] + token, held[-1][1])
        else:
            held.append((token, spaced))
    return held


def _numbers_kept(tokens: list[tuple[str, bool]]) -> list[tuple[str, bool]]:
    """``tokens`` with a number that follows a word after a space joined to that word: a line that ends
    «Силовой анализ, положение» names no position, and the next that starts «11;» no more."""
    kept: list[tuple[str, bool]] = []
    for token, spaced in tokens:
        if kept and spaced and token[0].isdigit() and kept[-1][0][-1].isalpha():
            kept[-1] = (f"{kept[-1][0]} {token}", kept[-1][1])
        else:
            kept.append((token, spaced))
    return kept


def _split(value: str, at_spaces: bool) -> list[tuple[str, bool]]:
    if at_spaces:
        return [(word, k > 0) for k, word in enumerate(_SPACES.split(value.strip())) if word]
    tokens: list[tuple[str, bool]] = []
    for k, word in enumerate(_SPACES.split(value.strip())):
        if not word:
            continue
        piece = ""
        first = True
        for character in word:
            # A line may break before or after any ideograph, as Chinese is set.
            if is_wide(character):
                if piece:
                    tokens.append((piece, k > 0 and first))
                    first = False
                    piece = ""
                tokens.append((character, k > 0 and first))
                first = False
            else:
                piece += character
        if piece:
            tokens.append((piece, k > 0 and first))
    return tokens


def _joined(tokens: Sequence[tuple[str, bool]]) -> str:
    return "".join((" " if space and k else "") + token for k, (token, space) in enumerate(tokens))


def wrapped(value: str, lines: int, size: float, weight: str = "normal", at_spaces: bool = False) -> list[str]:
    """``value`` broken into at most ``lines`` lines so that the widest is as narrow as can be.

    The narrowest width that greedy filling still gets into ``lines`` lines
    is found by bisection: a line's width is the sum of its letters' widths.
    A line breaks before or after any ideograph, or ``at_spaces`` only.
    """
    return list(_wrapped(value, lines, size, weight, at_spaces))


# Remembered: a run draws the same title block on every sheet, and check and run measure it with each field left
# out in turn (cramped), each field's bisection done afresh every time.
@lru_cache(maxsize=4096)
def _wrapped(value: str, lines: int, size: float, weight: str, at_spaces: bool) -> tuple[str, ...]:
    tokens = _tokens(value, at_spaces)
    if not tokens:
        return ()
    if lines <= 1 or len(tokens) == 1:
        return (value.strip(),)
    word = [text_width(token, size, weight) for token, _ in tokens]
    space = text_width(" ", size, weight)
    # The space a token is joined to the token before it by, where the two share a line.
    joint = [space if spaced else 0.0 for _, spaced in tokens]

    low, high = max(word), sum(word) + space * len(word)
    for _ in range(40):
        middle = (low + high) / 2
        if len(_filled(tokens, word, joint, middle)) <= lines:
            high = middle
        else:
            low = middle
    rows = _filled(tokens, word, joint, high)
    if not at_spaces and has_wide(value):
        # Of the breaks as narrow, Chinese takes the one with the shorter lines first (GB/T 9704 sets a title
        # broken over lines as a trapezoid, short over long): «单缸内燃机 / 曲柄滑块机构», where filling the first
        # line cut 曲柄 in two.  The same lines filled from the end, as many and no wider: the tokens last first,
        # each joined to the one after it (now before it) by that one's space.
        from_end = _filled(tokens[::-1], word[::-1], [*joint[1:], 0.0][::-1], high)
        if len(from_end) == len(rows):
            rows = [row[::-1] for row in from_end[::-1]]
    return tuple(_joined(row) for row in rows)


def _filled(tokens: Sequence[tuple[str, bool]], word: Sequence[float], joint: Sequence[float],
            limit: float) -> list[list[tuple[str, bool]]]:
    """``tokens`` (each ``word`` mm wide, ``joint`` mm from the token before it on a line) filled greedily into
    lines no wider than ``limit`` where they can be."""
    rows: list[list[tuple[str, bool]]] = [[]]
    width = 0.0
    for token, token_width, before in zip(tokens, word, joint, strict=True):
        extra = token_width + (before if rows[-1] else 0.0)
        if rows[-1] and width + extra > limit:
            rows.append([])
            width, extra = 0.0, token_width
        rows[-1].append(token)
        width += extra
    return rows


def fitted(value: str, box: tuple[float, float, float, float], size: float, anchor: str = "middle",
           weight: str = "normal", lines: int = 1, padding: float = PADDING, margin: float | None = None) -> list[Text]:
    """``value`` in at most ``lines`` lines, centred in ``box`` (x0, y0, x1, y1), set smaller when it must: at the
    largest height of the standard series (:func:`graphplan.render.lettering.at_most`) up to ``size`` that it fits
    at, in as few lines as take that height; under the series' smallest, as large as it fits.  ``padding`` mm from
    the box's lines, ``margin`` (if given) from its sides."""
    if not value.strip():
        return []
    x0, y0, x1, y1 = box
    side = padding if margin is None else margin
    width, height = x1 - x0 - 2 * side, y1 - y0 - 2 * padding
    best: tuple[float, list[str]] | None = None
    for count in range(1, lines + 1):
        # Broken at its spaces where that sets it as large as breaking between ideographs does: «清华大学 机械系»
        # is not cut inside a word.
        for parts in (wrapped(value, count, size, weight, at_spaces=True), wrapped(value, count, size, weight)):
            widest = max(text_width(part, size, weight) for part in parts)
            # The block of n lines is (n - 1) pitches plus one line's extent (1.45 cap heights) high.
            tall = ((len(parts) - 1) * LINE_PITCH + 1.45) * size
            # Set smaller, it steps down the standard series, as a draftsman letters a field too small for it.
            fit = lettering.at_most(min(size, size * width / widest, size * height / tall))
            if best is None or fit > best[0] + 1e-9:
                best = (fit, parts)
        if best[0] >= size:
            break
    assert best is not None
    fit, parts = best
    pitch = LINE_PITCH * fit
    tall = (len(parts) - 1) * pitch + 1.45 * fit
    top = (y0 + y1) / 2 + tall / 2 - 1.15 * fit
    x = {"start": x0 + side, "middle": (x0 + x1) / 2, "end": x1 - side}[anchor]
    return [Text((x, top - k * pitch), part, math.floor(fit * 1000) / 1000, anchor, weight=weight) for k, part in enumerate(parts)]
