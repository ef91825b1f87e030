"""The legends of the machine's motion plot: the steady turn's under the plot, as the run's above it and the other
report plots' are, over no curve and with the plots no smaller; the stall's moments written as a textbook writes
them, M with its letter as a subscript (Mr, Md, Mt; Mс, Mд, Mт), the words around them in the figure's fonts."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from graphplan.locale import strings
from graphplan.report.motion_plots import motion_plot

pytest.importorskip("matplotlib")

LOCALES = ("en", "ru", "zh")
# The height the figure of a run and its steady turn is laid out at before the legends under its plots add their
# room (inches; 8.5 while the turn's legend stood on the plot, 8.0 since both legends stand under their plots).
FIGURE_HEIGHT_WITH_LEGEND_ON_THE_PLOT = 8.0


@pytest.fixture(scope="module")
def press():
    """The flywheel starter's punching press: Mr steps up over a third of the turn, and the flywheel's estimate of
    the speed runs beside the integrated one, the two curves across the whole plot."""
    from graphplan.machine_dynamics import MachineDynamics
    from graphplan.scene import load
    from graphplan.starters import starter

    dynamics = MachineDynamics(load(tomllib.loads(starter("flywheel", "en"))))
    assert dynamics.motion.steady is not None and dynamics.flywheel is not None
    return dynamics


def _steady_figure(press, locale: str):
    return motion_plot(press.motion, strings(locale), "press", (press.model.coordinate, press.flywheel.omega))


def _drawn(figure):
    """``figure`` drawn by Agg in the plots' own settings (fonts), and the renderer that knows its texts' extents."""
    import matplotlib
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from graphplan.report.plot_style import settings

    canvas = FigureCanvasAgg(figure)
    with matplotlib.rc_context(settings()):
        canvas.draw()
    return canvas.get_renderer()


def _display_points(line) -> np.ndarray:
    """The points of ``line`` on the figure (pixels), its segments filled in every tenth of their length: a straight
    stretch of the flywheel's estimate has its ends far outside a legend it crosses."""
    xy = np.column_stack(line.get_data()).astype(float)
    xy = xy[np.isfinite(xy).all(axis=1)]
    if len(xy) > 1:
        steps = np.linspace(0.0, 1.0, 11)[:, None, None]
        xy = (xy[:-1] + steps * (xy[1:] - xy[:-1])).reshape(-1, 2)
    return line.get_transform().transform(xy)


@pytest.mark.parametrize("locale", LOCALES)
def test_the_steady_turns_legend_lies_under_the_plot_inside_the_figure_over_no_line_or_word(press, locale):
    """loc="best" stood the legend in the corner it found freest of the two speeds over the turn, on the plot; the
    run's legend, the vibration's, the accuracy study's and the balancing load's stand under theirs."""
    from matplotlib import pyplot

    figure = _steady_figure(press, locale)
    try:
        renderer = _drawn(figure)
        run, turn = figure.axes
        legend = turn.get_legend().get_window_extent(renderer)
        plot = turn.get_window_extent(renderer)
        assert legend.y1 < plot.y0 and plot.x0 < legend.x0 and legend.x1 < plot.x1
        page = figure.bbox
        assert page.x0 <= legend.x0 and legend.x1 <= page.x1 and page.y0 <= legend.y0 and legend.y1 <= page.y1
        # Under the abscissa's numbers and its name, not on them.
        for text in [turn.xaxis.label, *turn.get_xticklabels()]:
            if text.get_text():
                assert not legend.overlaps(text.get_window_extent(renderer)), text.get_text()
        for axes in (run, turn):
            for line in axes.get_lines():
                points = _display_points(line)
                inside = ((points[:, 0] > legend.x0) & (points[:, 0] < legend.x1)
                          & (points[:, 1] > legend.y0) & (points[:, 1] < legend.y1))
                assert not inside.any(), f"the legend lies over {line.get_label()}"
        # Both curves are still named, with their δ.
        named = [text.get_text() for text in turn.get_legend().get_texts()]
        assert len(named) == 2 and all("δ" in words for words in named)
    finally:
        pyplot.close(figure)


def test_the_legend_under_the_steady_turn_leaves_both_plots_as_tall_as_they_were(press, locale="zh"):
    """The figure grows by the legend's room: laid out again at the height it had, with the legend taken off (where
    it stood on the plot it took no room of the figure's), neither plot is taller than it is now."""
    import matplotlib
    from matplotlib import pyplot

    from graphplan.report.plot_style import settings

    figure = _steady_figure(press, locale)
    try:
        def heights() -> list[float]:
            return [axes.get_position().height * figure.get_figheight() for axes in figure.axes]

        now = heights()
        assert figure.get_figheight() > FIGURE_HEIGHT_WITH_LEGEND_ON_THE_PLOT
        figure.axes[1].get_legend().remove()
        figure.set_figheight(FIGURE_HEIGHT_WITH_LEGEND_ON_THE_PLOT)
        with matplotlib.rc_context(settings()):
            figure.tight_layout()
        # To a point: tight_layout itself lays a figure out a few tenths of a point apart from where its plots stood.
        for was, is_now in zip(heights(), now, strict=True):
            assert is_now >= was - 1.0 / 72.0
    finally:
        pyplot.close(figure)
