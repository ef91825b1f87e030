"""The report plots read as a student pastes them into a report and a teacher reads them: each as wide as the note's
line at most (its type then prints at the sizes it was set in), nothing cut off at the figure's edge, its legend over
no curve, marker or label, every axis named, and every character drawn from a font that has it, also on a machine
whose only CJK font is Windows' or a Mac's.

The plots are made as a user makes them (`graphplan new`, `graphplan run`) in English, Russian and Chinese."""

from __future__ import annotations

import dataclasses
import functools
import io
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.locale import strings

pytest.importorskip("matplotlib")
fontTools = pytest.importorskip("fontTools")

LOCALES = ("en", "ru", "zh")
# Each starter with the pieces that make its matplotlib plots, and the plots' files.
PLOTS = {"crank-rocker": ("figures", ("balancing.svg",)), "flywheel": ("dynamics", ("motion.svg",)),
         "rotor": ("vibration", ("vibration_magnification.svg", "vibration_transmissibility.svg")),
         "shaper": ("accuracy", ("accuracy.svg",))}
# The note's line in Word (report/word.py: an A4 page less its 30 mm and 10 mm margins).
LINE_MM = 210.0 - 30.0 - 10.0


@pytest.fixture(scope="module")
def plots(tmp_path_factory) -> dict[tuple[str, str, str], Path]:
    """{(starter, locale, file): the plot's SVG} for every starter in every locale."""
    root = tmp_path_factory.mktemp("plots")
    found = {}
    for locale in LOCALES:
        for kind, (pieces, names) in PLOTS.items():
            scene = root / f"{kind}-{locale}.toml"
            assert main(["new", kind, "--out", str(scene), "--locale", locale]) == 0
            out = root / f"{kind}-{locale}"
            assert main(["run", str(scene), "--out", str(out), "--only", pieces]) == 0
            for name in names:
                found[kind, locale, name] = out / name
    return found


def _svg_mm(path: Path) -> tuple[float, float]:
    """The SVG's width and height in mm, read from its own attributes (matplotlib writes them in pt)."""
    from xml.etree import ElementTree

    root = ElementTree.fromstring(path.read_text(encoding="utf-8"))
    return tuple(float(root.get(side).removesuffix("pt")) * 25.4 / 72.0 for side in ("width", "height"))


def test_every_plot_fits_the_notes_line_so_its_type_prints_at_its_own_size(plots):
    wider = {f"{kind}/{locale}/{name}": round(_svg_mm(path)[0], 1) for (kind, locale, name), path in plots.items()
             if _svg_mm(path)[0] > LINE_MM}
    assert not wider, f"wider than the note's {LINE_MM} mm line (mm): {wider}"


def test_nothing_a_plot_draws_is_cut_off_at_the_edge_of_its_image(plots):
    """The saved image's outermost pixels are the background: a word or a curve cut by the edge leaves ink there."""
    import cairosvg
    from PIL import Image

    touching = []
    for key, path in plots.items():
        png = cairosvg.svg2png(bytestring=path.read_bytes(), dpi=150)
        pixels = np.asarray(Image.open(io.BytesIO(png)).convert("L"), dtype=float)
        edge = np.concatenate([pixels[:2].ravel(), pixels[-2:].ravel(), pixels[:, :2].ravel(), pixels[:, -2:].ravel()])
        if edge.min() < 230:
            touching.append("/".join(key))
    assert not touching


# --- the figures themselves, as matplotlib drew them ---------------------------------------------------------------


def _drawn(figure):
    """``figure`` laid out by the Agg renderer as it is saved (the text's extents are known once drawn)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    return canvas.get_renderer()


def _vibration_figures(locale: str) -> list:
    """The rotor starter's two vibration plots in ``locale`` as matplotlib figures."""
    from matplotlib.figure import Figure

    from graphplan.deliverables import vibration_figures
    from graphplan.scene import load

    made = []
    original = Figure.savefig

    def keep(self, *arguments, **options):
        made.append(self)
        return original(self, *arguments, **options)

    Figure.savefig = keep
    try:
        vibration_figures(load(_starter("rotor", locale)))
    finally:
        Figure.savefig = original
    return made


def _starter(kind: str, locale: str) -> Path:
    import tempfile

    scene = Path(tempfile.mkdtemp()) / f"{kind}-{locale}.toml"
    assert main(["new", kind, "--out", str(scene), "--locale", locale]) == 0
    return scene


@pytest.mark.parametrize("locale", LOCALES)
def test_each_vibration_plots_axes_are_named_and_its_legend_lies_over_no_curve(locale):
    for figure in _vibration_figures(locale):
        renderer = _drawn(figure)
        (axes,) = figure.axes
        assert axes.get_xlabel().strip() and axes.get_ylabel().strip()
        legend = axes.get_legend().get_window_extent(renderer)
        inside = axes.get_window_extent(renderer)
        for line in axes.get_lines():
            points = axes.transData.transform(np.column_stack(line.get_data()).astype(float))
            points = points[np.isfinite(points).all(axis=1)]
            points = points[(points[:, 0] >= inside.x0) & (points[:, 0] <= inside.x1)
                            & (points[:, 1] >= inside.y0) & (points[:, 1] <= inside.y1)]
            covered = ((points[:, 0] > legend.x0) & (points[:, 0] < legend.x1)
                       & (points[:, 1] > legend.y0) & (points[:, 1] < legend.y1))
            assert not covered.any(), f"the legend covers {line.get_label()}"


@pytest.fixture(scope="module")
def study():
    from graphplan.accuracy import study as accuracy_study
    from graphplan.scene import load

    return accuracy_study(load(_starter("shaper", "ru")), "shaper")


def _accuracy_figure(found, locale: str, monkeypatch):
    from graphplan.report import accuracy

    made = []
    monkeypatch.setattr(accuracy, "svg_text", lambda figure: made.append(figure) or "")
    accuracy.figure(found, locale, "Shaping machine")
    return made[0]


# Run times as a slow machine measures them, the drafting rows the slowest (as in a Russian run that put the legend on
# the label "1 мм"): the places of the markers and their labels change from run to run, the legend must not.
_SECONDS = {"analytic": 3e-4, "construction": 9.5e-3, "drafting": 9.5e-3, "diagram": 1.2e-3}


@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("slowest", ["drafting", "diagram", "construction"])
def test_the_accuracy_plots_legend_covers_no_marker_and_no_label_however_long_the_methods_ran(
        study, locale, slowest, monkeypatch):
    seconds = {**_SECONDS, slowest: 4e-2}
    rows = tuple(dataclasses.replace(row, seconds=seconds[row.method] * (1.0 + 0.1 * row.positions / 3600))
                 for row in study.rows)
    figure = _accuracy_figure(dataclasses.replace(study, rows=rows), locale, monkeypatch)
    renderer = _drawn(figure)
    (axes,) = figure.axes
    legend = axes.get_legend().get_window_extent(renderer)
    labels = [text for text in axes.texts if text.get_text().strip()]
    assert labels, "the drafting rows and the diagrams are labelled"
    for text in labels:
        assert not legend.overlaps(text.get_window_extent(renderer)), f"the legend covers the label {text.get_text()}"
    for line in axes.get_lines():
        points = axes.transData.transform(np.column_stack(line.get_data()).astype(float))
        for x, y in points[np.isfinite(points).all(axis=1)]:
            assert not (legend.x0 < x < legend.x1 and legend.y0 < y < legend.y1), \
                f"the legend covers a marker of {line.get_label()}"


# --- every character in a font that has it --------------------------------------------------------------------------


# Read once a file: a CJK collection's cmaps took some forty seconds a text, minutes a plot.
@functools.cache
def _cmap(path: str) -> frozenset[int]:
    """The characters of every face of the font file at ``path``."""
    from fontTools.ttLib import TTCollection, TTFont

    faces = TTCollection(path).fonts if path.lower().endswith((".ttc", ".otc")) else [TTFont(path)]
    return frozenset(code for face in faces for code in face.getBestCmap())


def _missing_glyphs(figure) -> dict[str, str]:
    """{a text of ``figure``: its characters that no font of its family list (matplotlib's fallback) has}."""
    from matplotlib import font_manager
    from matplotlib.text import Text

    missing = {}
    for text in figure.findobj(Text):
        words = text.get_text()
        if not words.strip() or text.get_parse_math() and "$" in words:
            continue
        known: set[int] = set()
        for family in text.get_fontproperties().get_family():
            prop = text.get_fontproperties().copy()
            prop.set_family(family)
            try:
                known |= _cmap(font_manager.findfont(prop, fallback_to_default=False))
            except ValueError:
                continue
        absent = "".join(sorted({c for c in words if not c.isspace() and ord(c) not in known}))
        if absent:
            missing[words] = absent
    return missing


@pytest.fixture
def only_windows_cjk_font(tmp_path, monkeypatch):
    """matplotlib's fonts as on a Windows machine: its CJK font Microsoft YaHei (here Noto Sans CJK SC's glyphs for
    the Chinese plot words, under that name), and none of Linux's CJK fonts."""
    from fontTools import subset
    from fontTools.ttLib import TTCollection
    from matplotlib import font_manager

    manager = font_manager.fontManager
    noto = next((entry.fname for entry in manager.ttflist if entry.name.startswith("Noto Sans CJK")), None)
    if noto is None:
        pytest.skip("no Noto Sans CJK to stand in for Microsoft YaHei")
    words = "".join(word for word in strings("zh").values() if isinstance(word, str))
    face = next(face for face in TTCollection(noto).fonts if "SC" in face["name"].getDebugName(1))
    options = subset.Options()
    options.name_IDs = ["*"]
    subsetter = subset.Subsetter(options)
    subsetter.populate(text=words)
    subsetter.subset(face)
    for record in face["name"].names:
        if record.nameID in (1, 4, 16):
            record.string = "Microsoft YaHei"
        elif record.nameID == 6:
            record.string = "MicrosoftYaHei"
    yahei = tmp_path / "msyh.otf"
    face.save(str(yahei))
    linux_cjk = ("CJK", "WenQuanYi", "Droid Sans Fallback", "Source Han", "Noto Sans SC")
    monkeypatch.setattr(manager, "ttflist", [entry for entry in manager.ttflist
                                             if not any(mark in entry.name for mark in linux_cjk)])
    manager.addfont(str(yahei))
    # The system's own font files, as matplotlib lists them for a rescan: Windows' msyh, no Noto.
    monkeypatch.setattr(font_manager, "findSystemFonts", lambda *arguments, **options: [str(yahei)])
    yield
    manager._findfont_cached.cache_clear()


def test_a_chinese_plot_on_a_machine_whose_only_cjk_font_is_windows_draws_every_character(only_windows_cjk_font):
    from graphplan.report.plot_style import font_families

    assert "Microsoft YaHei" in font_families()
    missing = {}
    for figure in _vibration_figures("zh"):
        _drawn(figure)
        missing.update(_missing_glyphs(figure))
    assert not missing, f"drawn as empty boxes: {missing}"


@pytest.mark.parametrize("locale", LOCALES)
def test_every_word_of_the_vibration_plots_is_in_a_font_matplotlib_chose_for_it(locale):
    for figure in _vibration_figures(locale):
        _drawn(figure)
        assert not _missing_glyphs(figure)
