"""The report plots' lettering as a student pastes them into a report: ωₙ with its n set as a subscript, a log axis
numbered within its decades (at 2 and 5, as a printed chart is) in the language's decimal mark, the balancing plot's
legend under the plot (not on a curve, a number or a square), and the plots' PNG at a print's 300 dpi while the
drawings' stays at the export's 150.

The plots are made as a user makes them, from the starters (`graphplan new`), in English, Russian and Chinese."""

from __future__ import annotations

import io
import math
import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.locale import strings

pytest.importorskip("matplotlib")

LOCALES = ("en", "ru", "zh")


def _starter(tmp_path: Path, kind: str, locale: str) -> Path:
    scene = tmp_path / f"{kind}-{locale}.toml"
    assert main(["new", kind, "--out", str(scene), "--locale", locale]) == 0
    return scene


def _made(monkeypatch, draw) -> list:
    """The matplotlib figures ``draw()`` saves, laid out by the Agg renderer as saved, with their renderer."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    made = []
    original = Figure.savefig

    def keep(self, *arguments, **options):
        made.append(self)
        return original(self, *arguments, **options)

    monkeypatch.setattr(Figure, "savefig", keep)
    draw()
    drawn = []
    for figure in made:
        canvas = FigureCanvasAgg(figure)
        canvas.draw()
        drawn.append((figure, canvas.get_renderer()))
    return drawn


def _vibration(tmp_path, monkeypatch, locale: str) -> list:
    """The rotor starter's magnification and transmissibility plots in ``locale``."""
    from graphplan.deliverables import vibration_figures
    from graphplan.scene import load

    return _made(monkeypatch, lambda: vibration_figures(load(_starter(tmp_path, "rotor", locale))))


# --- ωₙ -------------------------------------------------------------------------------------------------------------


def _font_has(text, character: str) -> bool:
    """Whether a font of ``text``'s family list, as matplotlib finds it, has ``character`` (fontTools' reading)."""
    from fontTools.ttLib import TTCollection, TTFont
    from matplotlib import font_manager

    for family in text.get_fontproperties().get_family():
        prop = text.get_fontproperties().copy()
        prop.set_family(family)
        try:
            path = font_manager.findfont(prop, fallback_to_default=False)
        except ValueError:
            continue
        faces = TTCollection(path).fonts if path.lower().endswith((".ttc", ".otc")) else [TTFont(path)]
        if any(ord(character) in face.getBestCmap() for face in faces):
            return True
    return False


@pytest.mark.parametrize("locale", LOCALES)
def test_the_natural_frequency_on_the_plots_axis_has_its_n_as_a_subscript(tmp_path, monkeypatch, locale):
    """"r = ω/ωn" printed the n as a letter of the line, as if ω times n; ωₙ (U+2099, in DejaVu Sans, which
    matplotlib ships) or mathtext's ω_n set it small and low."""
    pytest.importorskip("fontTools")
    for figure, _ in _vibration(tmp_path, monkeypatch, locale):
        (axes,) = figure.axes
        label = axes.xaxis.label
        words = label.get_text()
        assert "ω" in words and "ωn" not in words, words
        if "$" in words:  # mathtext
            assert re.search(r"\\omega_\{?n", words), words
        else:
            assert "ωₙ" in words and _font_has(label, "ₙ"), words


# --- the log axis numbered within its decades ----------------------------------------------------------------------


def _numbered(axis) -> list[tuple[float, str]]:
    """(value, label) of ``axis``'s numbered major ticks within its view."""
    low, high = sorted(axis.get_view_interval())
    pairs = zip(axis.get_majorticklocs(), axis.get_majorticklabels(), strict=False)
    return [(float(value), text.get_text()) for value, text in pairs
            if low * (1 - 1e-9) <= value <= high * (1 + 1e-9) and text.get_text().strip()]


def _one_two_five(low: float, high: float) -> list[float]:
    """1, 2 and 5 of every decade from ``low`` to ``high``."""
    return [mark * 10.0**power for power in range(math.floor(math.log10(low)) - 1, math.ceil(math.log10(high)) + 1)
            for mark in (1.0, 2.0, 5.0) if low * (1 - 1e-9) <= mark * 10.0**power <= high * (1 + 1e-9)]


def _read(label: str, mark: str) -> float:
    """A tick label's number: the locale's decimal mark, a true minus, no exponent."""
    assert re.fullmatch(r"−?\d+(" + re.escape(mark) + r"\d+)?", label), f"{label!r}: not a number written with {mark}"
    return float(label.replace(mark, ".").replace("−", "-"))


def _crowded(axis, renderer) -> list[str]:
    """Labels of ``axis`` whose drawn boxes overlap a neighbour's."""
    boxes = [(text.get_text(), text.get_window_extent(renderer)) for text in axis.get_majorticklabels()
             if text.get_visible() and text.get_text().strip()]
    return [f"{one} / {other}" for k, (one, box) in enumerate(boxes) for other, box2 in boxes[k + 1:]
            if box.overlaps(box2)]


@pytest.mark.parametrize("locale", LOCALES)
def test_the_transmissibility_axis_is_numbered_at_2_and_5_within_each_decade_in_the_languages_decimal_mark(
        tmp_path, monkeypatch, locale):
    """Numbered at 10⁻², 10⁻¹, 1 and 10 alone, TR = 0.05 was read by counting the grid's unnumbered lines."""
    mark = strings(locale)["decimal_mark"]
    figures = _vibration(tmp_path, monkeypatch, locale)
    (transmissibility,) = [(figure, renderer) for figure, renderer in figures if figure.axes[0].get_yscale() == "log"]
    figure, renderer = transmissibility
    axis = figure.axes[0].yaxis
    numbered = _numbered(axis)
    low, high = sorted(axis.get_view_interval())
    assert high / low > 100, "the starter's transmissibility runs over decades"
    assert [value for value, _ in numbered] == pytest.approx(_one_two_five(low, high), rel=1e-9)
    for value, label in numbered:
        assert _read(label, mark) == pytest.approx(value, rel=1e-9)
    assert not _crowded(axis, renderer)


def test_a_log_axis_over_many_decades_is_numbered_within_them_only_where_the_numbers_have_room(monkeypatch):
    """A working point at r = 60 and mounts designed for TR = 0.0005 at r = 150: the abscissa, three decades over the
    page's width, has room for 2 and 5; the ordinate, five decades over the plot's height, numbered so would set
    each number against the next; there every decade is numbered and nothing overlaps."""
    from graphplan.report.vibration_plots import transmissibility_figure

    ((figure, renderer),) = _made(monkeypatch, lambda: transmissibility_figure(
        io.StringIO(), operating=(60.0, 0.05), design=(150.0, 0.0005), text=strings("ru")))
    (axes,) = figure.axes
    assert axes.get_xscale() == "log" and axes.get_yscale() == "log"
    x_low, x_high = sorted(axes.xaxis.get_view_interval())
    assert [value for value, _ in _numbered(axes.xaxis)] == pytest.approx(_one_two_five(x_low, x_high), rel=1e-9)
    y_low, y_high = sorted(axes.yaxis.get_view_interval())
    decades = [10.0**power for power in range(math.ceil(math.log10(y_low)), math.floor(math.log10(y_high)) + 1)]
    numbered = [value for value, _ in _numbered(axes.yaxis)]
    assert all(any(math.isclose(value, decade, rel_tol=1e-9) for value in numbered) for decade in decades), numbered
    for axis in (axes.xaxis, axes.yaxis):
        assert not _crowded(axis, renderer)
        for value, label in _numbered(axis):
            assert _read(label, ",") == pytest.approx(value, rel=1e-9)


# --- the balancing plot's legend -------------------------------------------------------------------------------------


def _legend_clear(figure, renderer) -> list[str]:
    """What the legend of ``figure``'s one axes covers: a curve's or a marker's point, a text; and whether it lies
    under the axes and the abscissa's numbers and name, inside the image."""
    (axes,) = figure.axes
    legend = axes.get_legend().get_window_extent(renderer)
    faults = []
    under = axes.xaxis.get_tightbbox(renderer)
    if not legend.y1 <= min(axes.get_window_extent(renderer).y0, under.y0):
        faults.append("not under the plot and its abscissa")
    page = figure.bbox
    if not (page.x0 <= legend.x0 and legend.x1 <= page.x1 and page.y0 <= legend.y0 and legend.y1 <= page.y1):
        faults.append("cut off by the image's edge")
    for text in [*axes.texts, axes.xaxis.label, axes.yaxis.label, *axes.get_xticklabels(), *axes.get_yticklabels()]:
        if text.get_visible() and text.get_text().strip() and legend.overlaps(text.get_window_extent(renderer)):
            faults.append(f"covers the text {text.get_text()}")
    for line in axes.get_lines():
        points = axes.transData.transform(np.column_stack(line.get_data()).astype(float))
        points = points[np.isfinite(points).all(axis=1)]
        if ((points[:, 0] > legend.x0) & (points[:, 0] < legend.x1)
                & (points[:, 1] > legend.y0) & (points[:, 1] < legend.y1)).any():
            faults.append(f"covers {line.get_label()}")
    return faults


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("kind", ["crank-rocker", "shaper"])
def test_the_balancing_plots_legend_lies_under_it_as_the_other_plots_do(tmp_path, monkeypatch, kind, locale):
    """"best" put it in a corner the curve left free, a different one scene by scene (and none is free where a curve
    fills the plot); under the plot, as the vibration and accuracy plots have theirs, it is over nothing on any.
    The shaper's has friction, three lines to place."""
    import matplotlib

    from graphplan.analysis import analyse
    from graphplan.report.figures import _balancing_figure
    from graphplan.report.plot_style import settings
    from graphplan.scene import load

    analysis = analyse(load(_starter(tmp_path, kind, locale)))
    with matplotlib.rc_context(settings()):
        ((figure, renderer),) = _made(monkeypatch, lambda: _balancing_figure(analysis).savefig(io.BytesIO(), format="svg"))
        assert not _legend_clear(figure, renderer)


# --- the PNG's resolution ------------------------------------------------------------------------------------------


def _png(data: bytes) -> tuple[tuple[int, int], float]:
    """The PNG's size in pixels and the dpi its pHYs chunk says."""
    from PIL import Image

    image = Image.open(io.BytesIO(data))
    return image.size, float(image.info["dpi"][0])


def _svg_inches(svg: str) -> tuple[float, float]:
    """The SVG's width and height in inches, read from its own attributes (matplotlib's in pt, the drawings' in mm)."""
    from xml.etree import ElementTree

    root = ElementTree.fromstring(svg)
    per_inch = {"pt": 72.0, "mm": 25.4}
    sizes = [re.fullmatch(r"([\d.]+)(pt|mm)", root.get(side)) for side in ("width", "height")]
    return tuple(float(size.group(1)) / per_inch[size.group(2)] for size in sizes)


def test_the_plots_png_is_printed_at_300_dpi_and_the_drawings_at_150(tmp_path):
    """A report prints its figures at 300 dpi; the plots' PNG shared the drawings' export's 150.  The rotor's
    balancing drawing keeps 150 (a sheet at 300 is four times the pixels)."""
    pytest.importorskip("cairosvg")
    scene = _starter(tmp_path, "rotor", "en")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--format", "png"]) == 0
    expected = {"vibration_magnification": 300.0, "vibration_transmissibility": 300.0, "rotor_balancing": 150.0}
    for stem, dpi in expected.items():
        (width, height), written = _png((out / f"{stem}.png").read_bytes())
        inches = _svg_inches((out / f"{stem}.svg").read_text(encoding="utf-8"))
        assert written == pytest.approx(dpi, abs=0.5), stem
        assert (width, height) == pytest.approx((inches[0] * dpi, inches[1] * dpi), abs=1.5), stem
    # The notebook saves the plot as the run writes it.
    from graphplan.scene import load

    saved = load(scene).vibration_response().transmissibility_plot.save(tmp_path / "plot.png")
    assert _png(saved.read_bytes())[1] == pytest.approx(300.0, abs=0.5)
