"""A sheet that holds two kinds of drawing is named by both where the title block's cell holds the longer name
legibly, and by the shorter names after it where it does not.

The Russian crank-rocker with friction's last A3 sheet held the rest of position 11's force analysis with friction
beside the load diagrams, and its block named only the force analysis.  The drawing's cell is small (ESKD's 70 × 8
mm under the title, ISO 7200's 60 mm Document type of one line): the name is measured as the block sets it, and
one it would set below ISO 3098's smallest lettering gives way to the next.
"""

from __future__ import annotations

import re

import pytest
from test_title_block_cells import printed_span

from graphplan.locale import strings
from graphplan.render.primitives import Text, text_width
from graphplan.render.title_block import (
    NAME_MARGIN,
    SMALLEST_LETTERING,
    TitleBlockFields,
    fitting_name,
    form_of,
    labels,
    title_block,
)

# The drawing's cell (x0, y0, x1, y1 from the block's lower left corner, mm) of each locale's form: ESKD's name
# cell below the title (GOST 2.104's 25 mm high column, the lower 0.32 of it), GB/T 10609.1's likewise, ISO 7200's
# Document type under its field's name.
DRAWING_CELLS = {"ru": (65.0, 15.0, 135.0, 23.0), "zh": (130.0, 20.0, 180.0, 25.76), "en": (80.0, 30.0, 140.0, 40.0)}


def drawn_name(locale: str, name: str) -> list[Text]:
    """The lines the block of ``locale``'s form draws for the drawing's name ``name``, its lower left corner at 0."""
    form = form_of(locale)
    words = labels(locale)
    width = {"eskd": 185.0, "gb": 180.0, "iso": 180.0}[form]

    def texts(drawing: str) -> set[Text]:
        fields = TitleBlockFields(title="", drawing=drawing, scale="", sheet=1, sheets=1)
        return {item for item in title_block(form, fields, words, (width, 0.0)) if isinstance(item, Text)}

    return sorted(texts(name) - texts(""), key=lambda text: -text.at[1])


def candidates(locale: str, number: int) -> list[str]:
    """The names :func:`graphplan.render.sheet._drawing_name` offers a sheet of a position's force analysis with
    friction beside the load diagrams: both, the force analysis alone, the kind's word and the load diagrams."""
    text = strings(locale)
    shared = text["tb_sheet_with_load_diagrams"]
    position = text["tb_sheet_forces_friction_position"].format(number=number)
    return [shared.format(name=position), position, shared.format(name=text["tb_sheet_forces"])]


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_name_chosen_is_legible_and_inside_its_cell(locale):
    names = candidates(locale, 11)
    chosen = fitting_name(form_of(locale), names, labels(locale))
    assert chosen in names
    lines = drawn_name(locale, chosen)
    # Every word of the name is drawn, none below the smallest lettering, and clear of the cell's sides as printed.
    assert " ".join(line.text for line in lines).split() == chosen.split()
    assert min(line.size for line in lines) >= SMALLEST_LETTERING
    x0, y0, x1, y1 = DRAWING_CELLS[locale]
    for line in lines:
        left, right = printed_span(line)
        assert x0 < left and right < x1, line
        assert y0 < line.at[1] < y1, line
    # A name passed over is one the block would set smaller than that.
    for passed in names[:names.index(chosen)]:
        assert min(line.size for line in drawn_name(locale, passed)) < SMALLEST_LETTERING


def test_the_longer_name_is_taken_where_it_fits():
    # ESKD's cell holds the Russian name in two lines at 2.1 mm (8 mm less 0.8 mm above and below, over the three
    # cap heights two lines take: 6.4 / 3); ISO's one line of 56 mm does not hold the English one at 1.8 mm
    # (56 characters, some 0.6 cap height wide each), but holds the force analysis's name alone, which keeps the
    # friction and the position that tell the sheet from the others.
    assert fitting_name("eskd", candidates("ru", 11), labels("ru")) == candidates("ru", 11)[0]
    assert fitting_name("iso", candidates("en", 11), labels("en")) == candidates("en", 11)[1]


def test_of_names_none_holds_legibly_the_largest_set_is_taken():
    words = labels("en")
    long = "Force analysis with friction, position 11, and everything else this sheet holds besides it"
    longer = long + " and more"
    # Each tried in full and with its position's word shortened: the shorter wording of the shorter name is set
    # largest.
    assert fitting_name("iso", [longer, long], words) == long.replace("position 11", "pos. 11")


def _position_names(locale: str, number: int) -> list[list[str]]:
    """The names a force sheet's block is offered (:func:`graphplan.render.sheet._drawing_name`): a position's force
    analysis, without and with friction, alone and beside the load diagrams, each followed by the kind's word."""
    text = strings(locale)
    shared = text["tb_sheet_with_load_diagrams"]
    offered = []
    for key in ("tb_sheet_forces_position", "tb_sheet_forces_friction_position"):
        position = text[key].format(number=number)
        offered.append([position, text["tb_sheet_forces"]])
        offered.append([shared.format(name=position), position, shared.format(name=text["tb_sheet_forces"])])
    return offered


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_position_is_named_on_one_line_with_its_number_inside_the_cell(locale):
    """The Russian crank-rocker's last sheet broke «Силовой анализ, положение / 11; диаграммы нагрузок», and the
    English one of the same page dropped the position: "Force analysis; load diagrams"."""
    words = labels(locale)
    word, short = words["position_word"], words["position_short"]
    x0, _, x1, _ = DRAWING_CELLS[locale]
    for names in _position_names(locale, 11):
        chosen = fitting_name(form_of(locale), names, words)
        lines = drawn_name(locale, chosen)
        for line in lines:
            # The line's extent as the block fits it (the renderer's measure of text), inside the cell by the
            # margin the drawing's name keeps from its sides.
            half = text_width(line.text, line.size) / 2
            assert x0 + NAME_MARGIN - 1e-9 <= line.at[0] - half and line.at[0] + half <= x1 - NAME_MARGIN + 1e-9
        if "11" in chosen:
            # The number stands on the line of the word it counts, right after it.
            (numbered,) = [line.text for line in lines if "11" in line.text]
            assert re.search(rf"(?:{re.escape(word)}|{re.escape(short)}) 11", numbered), lines
    # The position is named in every locale, alone and beside the load diagrams, with friction too (ISO 7200's one
    # line of Document type set the English name in full at 1.77 mm, and with friction at 1.46 mm even with the
    # position's word shortened).
    for names in _position_names(locale, 11):
        assert "11" in fitting_name(form_of(locale), names, words)
