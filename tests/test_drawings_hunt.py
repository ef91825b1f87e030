"""A hostile user's scenes against the drawings: a crank drawn a few millimetres long, texts measured against the
fonts they are set in, and the like.  Each asserts what a reader of the sheet sees, measured with the drawings' own
geometry (:mod:`graphplan.render.labels`, :mod:`graphplan.render.primitives`)."""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import matplotlib
import pytest
from fontTools.ttLib import TTFont

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render import positions
from graphplan.render.drawings import forces_svg, positions_plan
from graphplan.render.labels import obstacles_of, text_box
from graphplan.render.linkage import frame_pivots
from graphplan.render.primitives import FONT_SIZE_PER_CAP, Polyline, Text, is_wide, text_width
from graphplan.render.title_block import SIZES, SMALLEST_LETTERING, TitleBlockFields, labels, scale_text, title_block
from graphplan.scales import format_scale
from graphplan.scene import loads

RATCHET = Path("fixtures/ratchet_crank_rocker.toml").read_text(encoding="utf-8")
POSITION_NUMBER = re.compile(r"^\d+′?$")


def test_a_crank_drawn_a_millimetre_long_keeps_its_position_numbers_off_its_pivot() -> None:
    # The crank 1:200 of the coupler, at the ratchet's μl: its circle is 1.4 mm across, smaller than the pivot's
    # triangle, and the numbers set just outside the circle stood on the triangle and its hatching.
    text = RATCHET.replace("length  = 0.175 ", "length  = 0.00275").replace(
        'S2 = { link = 2, from = "O", toward = "A", at = 0.08 }', 'S2 = { link = 2, from = "O", toward = "A", at = 0.001 }')
    text = text[:text.index("[measured.5]")] + text[text.index("[drawing]"):]
    analysis = analyse(loads(text))
    plan = positions_plan(analysis)
    layers = {layer.name: layer.items for layer in positions.layout(plan)}
    numbers = [item for item in layers["labels"] if isinstance(item, Text) and POSITION_NUMBER.match(item.text)]
    assert len(numbers) >= 3  # the first, the plan sheets' and the second extreme at least
    paper = 1.0 / plan.length_scale
    pivot = obstacles_of(frame_pivots(plan.mechanism, lambda r: (r.real * paper, r.imag * paper)))
    on_pivot = [number.text for number in numbers if any(text_box(number).intersects(shape) for shape in pivot)]
    assert on_pivot == []


def _dejavu(weight: str) -> TTFont:
    """DejaVu Sans as matplotlib ships it: the font the drawings name first, wherever they are measured."""
    name = "DejaVuSans-Bold.ttf" if weight == "bold" else "DejaVuSans.ttf"
    return TTFont(Path(matplotlib.get_data_path()) / "fonts" / "ttf" / name)


def _advance(font: TTFont, text: str) -> float:
    """How wide ``text`` is set in ``font``, in em: the sum of its glyphs' advances."""
    glyphs, metrics, unit = font.getBestCmap(), font["hmtx"], font["head"].unitsPerEm
    return sum(metrics[glyphs[ord(character)]][0] / unit for character in text if ord(character) in glyphs)


def _letters() -> list[str]:
    """Every character that the locales write, ASCII's, the Russian alphabet and the Greek letters, the signs of
    the drawings' equations and units, and what else a title or a name may hold."""
    locales = Path(graphplan.__file__).parent / "locales"
    written = set().union(*(set(path.read_text(encoding="utf-8")) for path in locales.glob("*.toml")))
    more = {chr(code) for code in [*range(0x21, 0x7F), *range(0xA1, 0x180), *range(0x391, 0x3CA), *range(0x400, 0x460)]}
    return sorted(character for character in written | more | set("′″–—…№−±×÷≈≤≥·°→")
                  if character.isprintable() and not character.isspace() and not is_wide(character))


@pytest.mark.parametrize("weight", ["normal", "bold"])
def test_no_letter_is_boxed_narrower_than_dejavu_sans_sets_it(weight: str) -> None:
    font = _dejavu(weight)
    em = 1.0 / FONT_SIZE_PER_CAP  # the cap height at which a text's width in mm is its width in em
    narrower = {character: round(_advance(font, character), 3) for character in _letters()
                if _advance(font, character) > text_width(character, em, weight) + 1e-9}
    assert narrower == {}


def _between_its_lines(items: list, font_of) -> list[str]:
    """The texts of a title block that, as DejaVu Sans sets them, reach within 0.5 mm of the lines on either side
    of them (a line up to 0.7 mm wide stands half inside a cell): each with the room it has and takes."""
    walls = [(p[0], min(p[1], q[1]), max(p[1], q[1])) for item in items if isinstance(item, Polyline)
             for p, q in zip(item.points, item.points[1:] + ((item.points[0],) if item.closed else ()))
             if abs(p[0] - q[0]) < 1e-9]
    crowded = []
    for item in items:
        if not isinstance(item, Text) or not item.text.strip() or item.rotation:
            continue
        width = _advance(font_of(item.weight), item.text) * item.size * FONT_SIZE_PER_CAP
        left = item.at[0] - {"start": 0.0, "middle": width / 2, "end": width}[item.anchor]
        middle = item.at[1] + 0.4 * item.size
        beside = [x for x, y0, y1 in walls if y0 <= middle <= y1]
        room = (max(x for x in beside if x <= item.at[0] + 1e-9), min(x for x in beside if x >= item.at[0] - 1e-9))
        if left < room[0] + 0.5 or left + width > room[1] - 0.5:
            crowded.append(f"{item.text!r} {left:.2f}..{left + width:.2f} in {room[0]:.2f}..{room[1]:.2f}")
    return crowded


HOSTILE_PROJECT = {"author": "Шмидт-Щербакова Ю. М.", "checked_by": "Жмышенко Ш. Щ.", "approved_by": "Мышкин Ф. Ы.",
                   "organization": "МГТУ им. Н. Э. Баумана, каф. РК-2 «Теория механизмов и машин» — №5…",
                   "designation": "ТММ.КП.МФ.02.00.00.000 ПЗ", "date": "01.12.26"}


@pytest.mark.parametrize("locale", ["ru", "zh", "en"])
def test_a_title_block_s_texts_stay_between_their_cell_s_lines_as_dejavu_sans_sets_them(locale: str) -> None:
    # μl = 4 m/mm, no ratio GOST 2.302 allows: written out in ESKD's 18 mm scale cell, "4 м/мм" ran over its
    # lines; so did the Russian names above in their cells, measured as Latin letters of their case.
    words = strings(locale)
    form = {"ru": "eskd", "zh": "gb", "en": "iso"}[locale]
    scale = scale_text(4.0, form, words["length_scale"], words["decimal_mark"])
    fields = TitleBlockFields(title="Кривошипно-шатунный механизм ДВС «Жук-Ш»", drawing=words["tb_sheet_kinematics"],
                              scale=scale, sheet=1, sheets=12, **HOSTILE_PROJECT)
    crowded = _between_its_lines(title_block(form, fields, labels(locale), (185.0, 0.0)), _dejavu)
    assert crowded == []


@pytest.mark.parametrize("length_scale", [0.00004, 0.000004])
def test_a_length_scale_no_ratio_of_the_form_writes_is_written_out_no_smaller_than_the_least_lettering(
        length_scale: float) -> None:
    # 25:1 and 250:1 are no ratios of GOST 2.302's: μl is written out in the 18 × 15 mm scale box, on two lines at
    # 1.7 and 1.6 mm, where three give it 2.8 and 2.4 mm.
    locale, form, cell = "ru", "eskd", (167.0, 20.0, 185.0, 35.0)
    words = strings(locale)
    scale = scale_text(length_scale, form, words["length_scale"], words["decimal_mark"])
    assert scale.startswith("μl = ")
    fields = TitleBlockFields(title="Механизм", drawing=words["tb_sheet_kinematics"], scale=scale, sheet=1, sheets=1)
    x0, y0, x1, y1 = cell  # from the block's lower left corner, as the form's drawing gives it
    block = title_block(form, fields, labels(locale), (SIZES[form][0], 0.0))
    written = [item for item in block if isinstance(item, Text) and x0 <= item.at[0] <= x1 and y0 <= item.at[1] <= y1]
    assert " ".join(item.text for item in written) == scale
    assert min(item.size for item in written) >= SMALLEST_LETTERING


EXPONENT = re.compile(r"\de[+-]?\d")


def test_the_force_sheet_of_a_450_mn_press_writes_its_force_scales_without_an_exponent() -> None:
    # The engine's gas force times 10⁵: μF came out 1·10⁷ N/mm, written "μF = 1e+07 N/mm" in the captions.
    engine = Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8")
    analysis = analyse(loads(engine.replace("value     = 4500.0", "value     = 450000000.0")))
    position = next(plan for plan in analysis.plans if plan.forces is not None)
    texts = ["".join(element.itertext()) for element in ElementTree.fromstring(forces_svg(analysis, position)).iter()
             if element.tag.endswith("}text")]
    scales = [text for text in texts if "μF = " in text]
    assert scales and not [text for text in texts if EXPONENT.search(text)]
    assert any("μF = 10000000 N/mm" in text for text in scales)


def test_a_press_s_force_polygon_is_one_polygon_however_short_its_small_vectors() -> None:
    # Beside the 450 MN load the weights, inertia forces and R23τ are under 0.01 mm at μF: R23τ + ΣF3 "closed" to
    # 0.01 mm and the polygon was cut into three, two of them a lone dot beside the third.
    engine = Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8")
    analysis = analyse(loads(engine.replace("value     = 4500.0", "value     = 450000000.0")))
    for position in (plan for plan in analysis.plans if plan.forces is not None):
        groups = {element.get("id"): element for element in
                  ElementTree.fromstring(forces_svg(analysis, position)).iter("{http://www.w3.org/2000/svg}g")}
        polygons = [name for name in groups if name and name.startswith("polygon-") and name.endswith("-vectors")]
        assert polygons
        # Each polygon drawn has an arrow (a group of its own, shaft and head) besides its starting dot.
        assert [name for name in polygons if not groups[name].findall("{http://www.w3.org/2000/svg}g")] == []
        # One polygon a group: its vectors under the group's own name, not numbered apart (polygon-II-3-4-1).
        captions = [name.removesuffix("-caption") for name in groups if name and name.startswith("polygon-")
                    and name.endswith("-caption")]
        assert sorted(polygons) == sorted(f"{caption}-vectors" for caption in captions), position.number


def test_a_scale_factor_beyond_a_thousand_millionth_is_a_power_of_ten_not_nought() -> None:
    # Ten decimals wrote an acceleration scale of a crank turning once a day, 2.5·10⁻¹² (m/s²)/mm, as "0".
    assert [format_scale(value) for value in (2.5e-12, 1e-10, 4e8, 2e9)] == [
        "2.5·10⁻¹²", "0.0000000001", "400000000", "2·10⁹"]
