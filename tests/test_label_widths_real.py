"""A label's box holds its text as DejaVu Sans, the drawings' font, sets it.

The box (what the label placer keeps off the lines and off the other labels, what a drawing's extent and the
sheets' packing take) was measured by letter classes, which fall short of letters DejaVu sets wide: м, ф, ы, №,
r, t, W, a minus.  The widths here are DejaVu's advances read with fontTools from the file matplotlib ships and
summed in the test (cairo sets a line without kerning), and the glyphs' ink by matplotlib's TextPath.
"""

import sys
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from fontTools.ttLib import TTFont
from matplotlib.font_manager import FontProperties
from matplotlib.textpath import TextPath
from shapely.geometry import LineString, box

import graphplan
from graphplan.render import labels
from graphplan.render.labels import Anchor, place_labels, text_box
from graphplan.render.primitives import FONT_SIZE_PER_CAP, Text, text_extent
from graphplan.run import run

FONTS = Path(matplotlib.get_data_path()) / "fonts" / "ttf"
FILES = {"normal": FONTS / "DejaVuSans.ttf", "bold": FONTS / "DejaVuSans-Bold.ttf"}
# Labels as the drawings write them (a Russian unit, an inertia force's name, a speed's), and letters the classes
# measured short.
TYPICAL = ["ωд", "мм/с", "Fи₃", "W", "rtm", "ф", "Фы", "№ 5", "Юд", "−ω₃", "M₁₂", "Σ′", "ε₄ − ω₄"]
SIZES = [3.0, 3.5, 5.0]


def set_width(text: str, size: float, weight: str = "normal") -> float:
    """How wide DejaVu Sans sets ``text`` at cap height ``size`` (mm): its glyphs' advances summed."""
    font = _font(weight)
    glyphs, metrics, unit = font.getBestCmap(), font["hmtx"], font["head"].unitsPerEm
    return size * FONT_SIZE_PER_CAP * sum(metrics[glyphs[ord(character)]][0] / unit for character in text)


def ink_right(text: str, size: float, weight: str = "normal") -> float:
    """How far right of its start the ink of ``text`` reaches at cap height ``size`` (mm)."""
    path = TextPath((0.0, 0.0), text, size=size * FONT_SIZE_PER_CAP, prop=FontProperties(fname=FILES[weight]))
    return path.get_extents().x1


_FONTS: dict[str, TTFont] = {}


def _font(weight: str) -> TTFont:
    return _FONTS.setdefault(weight, TTFont(FILES[weight]))


def set_box(text: Text) -> tuple[float, float]:
    """(left, right) of ``text`` on the paper as DejaVu Sans sets it from its anchor."""
    width = set_width(text.text, text.size, text.weight)
    left = text.at[0] - {"start": 0.0, "middle": width / 2, "end": width}[text.anchor]
    return left, left + width


@pytest.mark.parametrize("size", SIZES)
@pytest.mark.parametrize("label", TYPICAL)
def test_a_placed_label_s_box_holds_its_text_as_set(label, size):
    placed = place_labels([Anchor((0.0, 0.0), label, size)], []).texts[0]
    x0, _, x1, _ = text_box(placed).bounds
    left, right = set_box(placed)
    assert x0 <= left + 1e-9 and right <= x1 + 1e-9, (label, (x0, x1), (left, right))
    assert left + ink_right(label, size) <= x1 + 1e-9, label


@pytest.mark.parametrize("weight", ["normal", "bold"])
@pytest.mark.parametrize("anchor", ["start", "middle", "end"])
@pytest.mark.parametrize("label", TYPICAL)
def test_a_text_s_extent_holds_it_as_set(label, anchor, weight):
    text = Text((10.0, 5.0), label, 3.5, anchor, weight=weight)
    x0, _, x1, _ = text_extent(text)
    left, right = set_box(text)
    assert x0 <= left + 1e-9 and right <= x1 + 1e-9, (label, anchor, weight, (x0, x1), (left, right))


@pytest.mark.parametrize("label", TYPICAL)
def test_a_label_keeps_off_a_line_beside_it_wherever_the_line_stands(label):
    """An upright line a little way right of the point, swept across the first spot tried: wherever it stands, the
    text as set is not written over it (a box the classes measured short left the line under the text's end)."""
    gap, size = 1.2, 3.5
    crossed = []
    for line_x in np.arange(gap, gap + set_width(label, size) + 1.0, 0.02):
        line = LineString([(line_x, -30.0), (line_x, 30.0)])
        placed = place_labels([Anchor((0.0, 0.0), label, size, prefer=0.0)], [line], gap=gap).texts[0]
        _, y0, _, y1 = text_extent(placed)
        left, right = set_box(placed)
        # Touching the line to the last digit is not writing over it.
        if box(left + 1e-9, y0, right - 1e-9, y1).intersects(line):
            crossed.append(round(float(line_x), 2))
    assert crossed == [], label


@pytest.fixture(scope="module")
def russian_placements(tmp_path_factory):
    """Every label placement of a Russian run of the ratchet's drawings: the anchors and the texts placed."""
    recorded = []
    original = labels.place_labels

    def recording(anchors, obstacles, *args, **kwargs):
        placement = original(anchors, obstacles, *args, **kwargs)
        recorded.append((tuple(anchors), placement, tuple(kwargs.get("standing", ()))))
        return placement

    patched = [module for name, module in sys.modules.items()
               if name.startswith("graphplan.render.") and getattr(module, "place_labels", None) is original]
    with pytest.MonkeyPatch.context() as patch:
        for module in patched:
            patch.setattr(module, "place_labels", recording)
        run(graphplan.load("fixtures/ratchet_crank_rocker.toml"), tmp_path_factory.mktemp("ru") / "out",
            only=["positions", "velocity", "acceleration", "forces", "diagrams", "sheets"], locale="ru")
    assert recorded, "no labels were placed"
    return recorded


def test_the_russian_run_s_labels_hold_their_texts_as_set(russian_placements):
    short = []
    for _, placement, _ in russian_placements:
        for text in placement.texts:
            x0, _, x1, _ = text_extent(text)
            left, right = set_box(text)
            if left < x0 - 1e-9 or right > x1 + 1e-9:
                short.append((text.text, text.size, round(x1 - x0, 3), round(right - left, 3)))
    assert short == []


def test_no_two_of_the_russian_run_s_labels_overlap_as_set(russian_placements):
    overlapping = []
    for _, placement, standing in russian_placements:
        texts = [*placement.texts, *standing]
        boxes = []
        for text in texts:
            _, y0, _, y1 = text_extent(text)
            left, right = set_box(text)
            boxes.append(box(left, y0, right, y1))
        overlapping += [(texts[k].text, texts[j].text) for k in range(len(texts)) for j in range(k + 1, len(texts))
                        if boxes[k].intersects(boxes[j])]
    assert overlapping == []
