"""How graphplan's matplotlib figures are set up and written: fonts for every script, reproducible SVG."""

from __future__ import annotations

import io
import re
from typing import Any

# Latin and Cyrillic first, then CJK: matplotlib falls back along the list glyph by glyph.  The CJK fonts are those
# Linux, Windows and macOS ship (the note's HTML names the same): with Linux's alone, a Chinese plot made on Windows
# or a Mac found no CJK font and drew every character as an empty box.
_FONTS = ("DejaVu Sans", "Noto Sans CJK SC", "Noto Sans CJK JP", "Noto Sans SC", "Source Han Sans SC",
          "WenQuanYi Zen Hei", "Droid Sans Fallback", "Microsoft YaHei", "SimHei", "PingFang SC", "Hiragino Sans GB",
          "Heiti SC", "Arial Unicode MS")
# Parts of the CJK fonts' file names, by which fonts installed after matplotlib's cache was built are found.
_CJK_FILES = ("CJK", "wqy", "DroidSansFallback", "SourceHanSans", "NotoSansSC", "msyh", "simhei", "PingFang",
              "Hiragino Sans GB", "STHeiti", "Arial Unicode")

#: The widest a figure is drawn (inches): the note's line, 170 mm (report/word), less a little, so that a figure
#: pasted into a report keeps its type at the sizes it was set in (8.4 inches wide, its 8 pt legend printed at 6 pt).
PAGE_WIDTH_INCHES = 6.6
#: The step of a crank angle's ticks (degrees), as the kinematic and dynamics diagrams grid a turn and its twelve
#: positions stand: matplotlib's own 0, 50, 100, … put position 3's 60° between two ticks.
CRANK_TICK_DEG = 30.0


def font_families() -> list[str]:
    """The fonts of :data:`_FONTS` this machine has (asking for a missing one floods the log)."""
    from matplotlib import font_manager

    manager = font_manager.fontManager
    installed = {font.name for font in manager.ttflist}
    if not installed.intersection(_FONTS[1:]):
        # matplotlib's font cache is built once and misses fonts installed after it (CJK fonts put in
        # by apt after the first plot): the system's own CJK files are added to it here.
        for path in font_manager.findSystemFonts():
            if any(mark.lower() in path.lower() for mark in _CJK_FILES):
                try:
                    manager.addfont(path)
                except (OSError, RuntimeError, ValueError):
                    continue
        installed = {font.name for font in manager.ttflist}
    return [name for name in _FONTS if name in installed] or ["sans-serif"]


def settings() -> dict[str, Any]:
    """matplotlib settings for ``rc_context``: a fixed hash salt, text drawn as paths in any script, and tick labels
    that say their values (no offset: a steady turn of δ = 3e-6 read −0.0002…0.0008 "+2.69307e2" in a corner)."""
    return {"svg.hashsalt": "graphplan", "font.family": font_families(), "svg.fonttype": "path",
            "axes.formatter.useoffset": False}


# A point between two digits is a decimal point (the same rule as the drawings', render.primitives).
_DECIMAL_POINT = re.compile(r"(?<=\d)\.(?=\d)")


def with_decimal_mark(figure, mark: str) -> None:
    """Write the numbers of ``figure`` with ``mark`` (a comma in Russian): tick labels, legends, annotations; and a
    linear axis's factor as a textbook writes it, ×10⁶, not matplotlib's 1e6 (in any language).

    The axes' titles are left as they are: they quote the scene's title, which is the user's text.
    """
    from matplotlib.text import Text
    from matplotlib.ticker import ScalarFormatter

    if mark != ".":
        titles = {id(axes.title) for axes in figure.axes}
        for text in figure.findobj(Text):
            if id(text) not in titles:
                text.set_text(_DECIMAL_POINT.sub(mark, text.get_text()))
    for axes in figure.axes:
        for axis in (axes.xaxis, axes.yaxis):
            for inner, put in ((axis.get_major_formatter(), axis.set_major_formatter),
                               (axis.get_minor_formatter(), axis.set_minor_formatter)):
                if mark != "." or isinstance(inner, ScalarFormatter):
                    put(_marked_formatter(inner, mark))


# matplotlib's factor of a linear axis (its offset text without mathtext): 1e6, 1e−5.
_FACTOR = re.compile(r"1e([-−+]?\d+)")
_SUPERSCRIPT = str.maketrans("0123456789-−+", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁻⁺")


def _factor(offset: str) -> str:
    """matplotlib's factor ``1e6`` as ×10⁶ (mathtext would do it, but sets a decimal comma in the ticks as a list's)."""
    found = _FACTOR.fullmatch(offset)
    return f"×10{found.group(1).lstrip('+').translate(_SUPERSCRIPT)}" if found else offset


def _marked_formatter(inner, mark: str):
    """``inner`` (a matplotlib tick formatter) with its decimal points written ``mark``."""
    from matplotlib.ticker import Formatter

    class Marked(Formatter):
        def set_locs(self, locs):
            inner.set_locs(locs)

        def __call__(self, x, pos=None):
            return _DECIMAL_POINT.sub(mark, inner(x, pos))

        def get_offset(self):
            return _DECIMAL_POINT.sub(mark, _factor(inner.get_offset()))

    return Marked()


#: The plots' PNG resolution: a report prints its figures at 300 dpi.  The drawings keep the export's own
#: (render.export.DEFAULT_DPI): an A1 sheet at 300 dpi is 70 million pixels.
PLOT_DPI = 300.0
# Within a decade a log axis is numbered at 1, 2 and 5, as a printed chart is; where that crowds, at 1 alone.
_ONE_TWO_FIVE = (1.0, 2.0, 5.0)
# The least room between two numbers along a log axis, in the tick labels' font size: on the value axis their
# height and a gap; along the abscissa each number's width (a digit some 0.6 em) and a gap of one em.
_ROOM_ACROSS = 1.8
_DIGIT_WIDTH = 0.6


def number_log_axis(axis, length_points: float) -> None:
    """Number the log ``axis`` (a matplotlib ``XAxis`` or ``YAxis`` of ``length_points``, as laid out) at 1, 2 and 5
    of each decade where the numbers have room, else at each decade; the numbers written as numbers, 0.02 … 20, not
    10⁻² … 10¹ (the decimal mark is put in by :func:`with_decimal_mark`).  Only decades numbered, a reader had to
    count the grid's unlabelled lines to read TR = 0.05."""
    import math

    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    from ..render.numerals import short

    low, high = sorted(axis.get_view_interval())
    decades = math.log10(high / low)
    size = axis.get_major_ticks()[0].label1.get_size()
    shown = [mark * 10.0**power for power in range(math.floor(math.log10(low)), math.ceil(math.log10(high)) + 1)
             for mark in _ONE_TWO_FIVE if low <= mark * 10.0**power <= high]
    if axis.axis_name == "y":
        needed = _ROOM_ACROSS * size
    else:
        needed = (max(len(short(value, 3)) for value in shown) * _DIGIT_WIDTH + 1.0) * size
    # The closest numbers, 1 and 2 or 5 and 10, are log10(2) of a decade apart.
    roomy = decades > 0 and math.log10(2.0) / decades * length_points >= needed
    axis.set_major_locator(LogLocator(base=10.0, subs=_ONE_TWO_FIVE if roomy else (1.0,), numticks=1000))
    axis.set_major_formatter(FuncFormatter(lambda value, _: short(value, 3)))
    # Under a decade matplotlib would number the minor ticks too, over the ones above.
    axis.set_minor_formatter(NullFormatter())


def number_log_axes(figure) -> None:
    """Every log axis of ``figure`` (laid out) numbered by :func:`number_log_axis`."""
    for axes in figure.axes:
        box = axes.get_position()
        width, height = figure.get_size_inches() * 72.0
        for axis, length in ((axes.xaxis, box.width * width), (axes.yaxis, box.height * height)):
            if axis.get_scale() == "log":
                number_log_axis(axis, length)


# The gap between an abscissa's name and the legend under it (pt).
LEGEND_GAP = 4.0


def legend_under(figure, plot, *, fontsize: float = 8.0, ncol: int = 2, keep_heights: bool = False,
                 laid_out: bool = False):
    """The legend of ``plot`` under it, below the abscissa's numbers and name, ``figure`` laid out round it; returned.

    Not "best": that looks for a corner free of the curves scene by scene, and a plot with no such corner has its
    legend on one.  Its drop is measured in points from the laid-out axis, not as a share of the plot's height, which
    under a short plot would put it on the axis's name.  ``keep_heights`` grows the figure by the room the legend
    takes, so that its plots keep the heights they had without it (the figure is laid out as it stands: its
    suptitle, if any, already set).  ``laid_out`` says the caller has laid the figure out as it stands: the legend's
    drop is in points from the axis, the same wherever the layout puts the plot, so laying it out again to measure
    would change nothing (a sixth of a plot's time)."""
    from matplotlib.transforms import ScaledTranslation

    if not laid_out:
        figure.tight_layout()
    before = _plot_heights(figure)
    drop = (plot.get_window_extent().y0 - plot.xaxis.get_tightbbox().y0) / figure.dpi + LEGEND_GAP / 72.0
    legend = plot.legend(fontsize=fontsize, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=ncol, frameon=False,
                         bbox_transform=plot.transAxes + ScaledTranslation(0.0, -drop, figure.dpi_scale_trans))
    figure.tight_layout()
    # tight_layout's margins and the gaps between plots do not grow with the figure in step: a few rounds make up
    # what is short to within a hundredth of a point.
    for _ in range(4 if keep_heights else 0):
        short = sum(was - now for was, now in zip(before, _plot_heights(figure), strict=True))
        if short < 0.01 / 72.0:
            break
        figure.set_figheight(figure.get_figheight() + short)
        figure.tight_layout()
    return legend


def _plot_heights(figure) -> list[float]:
    """The heights of ``figure``'s plots (inches)."""
    return [axes.get_position().height * figure.get_figheight() for axes in figure.axes]


def new_figure(**options):
    """A matplotlib ``Figure`` (made with ``options``) on an Agg canvas of its own.

    A bare ``Figure`` has no renderer to measure with: each measure of its layout (``tight_layout``, the legend's drop,
    a label's extent) made a new one, and matplotlib keeps its text metrics a renderer, so every label was measured
    afresh each time, 9 s of the motion plot's 16.  The canvas keeps one renderer while the figure's size stands; it is
    the Agg renderer the measuring made each time, so the layout and the files written are the same to the byte."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(**options)
    FigureCanvasAgg(figure)
    return figure


def svg_text(figure) -> str:
    """``figure`` as SVG without a date (the same scene gives the same file).

    The figures are matplotlib ``Figure`` objects made without pyplot: pyplot would keep them open, and choosing
    its backend to draw them would change the backend of a notebook the run is called from."""
    buffer = io.StringIO()
    write_svg(figure, buffer)
    return buffer.getvalue()


def write_svg(figure, target) -> None:
    """``figure`` written as SVG without a date to ``target``, a path or a stream.

    ``tight_layout`` leaves the figure a placeholder layout engine, for which ``savefig`` draws the whole figure once
    unseen before it draws it into the file: a draw for a layout made already, a sixth of a plot's time.  Without
    the engine the file is the same to the byte."""
    figure.set_layout_engine(None)
    figure.savefig(target, format="svg", metadata={"Date": None})
