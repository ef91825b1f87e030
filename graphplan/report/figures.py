"""Report figures drawn with matplotlib: the balancing load over the cycle.

matplotlib is imported here and only here, when a figure is asked for: a
plain run stays fast (DESIGN principle 5).  The SVG is written without a
date and with a fixed hash salt, so that the same scene gives the same file.
"""

from __future__ import annotations

import math

import numpy as np

from ..analysis import Analysis
from ..loads import activity, link_loads, motion_state
from ..locale import strings
from ..statics import equilibrium
from .plot_style import (
    CRANK_TICK_DEG,
    PAGE_WIDTH_INCHES,
    legend_under,
    new_figure,
    settings,
    svg_text,
    with_decimal_mark,
)


def balancing_diagram(analysis: Analysis) -> str:
    """The balancing load over the driver's cycle (the linear system on the dense sweep), with friction
    when the scene has it; the analysed positions numbered, the force polygons' values marked."""
    import matplotlib

    # In a context, not in rcParams: a figure's settings must not leak into the user's own plots.
    with matplotlib.rc_context(settings()):
        return svg_text(_balancing_figure(analysis))


def _balancing_figure(analysis: Analysis):
    text = strings(analysis.scene.locale)
    mechanism, positions, sweep = analysis.mechanism, analysis.positions, analysis.paths
    loads = link_loads(mechanism, motion_state(sweep), activity(mechanism, positions, sweep))
    ideal = equilibrium(mechanism, sweep, loads)
    driver = mechanism.driver
    if driver.kind == "crank":
        along = np.degrees(np.abs(sweep.driver - positions.values[0]))
        marks = np.degrees(np.abs(positions.values - positions.values[0]))
        axis, unit = text["diagram_crank_angle"], text["newton_metre"]
        name = text["balancing_moment"]
    else:
        along, marks = sweep.driver, positions.values
        axis, unit = text["diagram_displacement"], text["newton"]
        name = text["balancing_force"]
    # Taller than the 3.6 in it was with the legend on the plot: the legend under it keeps the plot its height.
    figure = new_figure(figsize=(PAGE_WIDTH_INCHES, 4.1), dpi=100)
    plot = figure.subplots()
    plot.plot(along, ideal.balancing, color="#1f5fa8", linewidth=1.4, label=text["diagram_ideal"])
    if analysis.scene.friction and analysis.with_friction is not None:
        rubbing = equilibrium(mechanism, sweep, loads, _friction(analysis, sweep))
        shown = np.where(rubbing.locked, np.nan, rubbing.balancing)
        plot.plot(along, shown, color="#a83a1f", linewidth=1.1, linestyle="--", label=text["diagram_friction"])
        if rubbing.locked.any():
            _locked_stretches(plot, along, rubbing.locked, text["diagram_locked"])
            # Toward a lock the load with friction grows without bound (1e5 N·m beside 300): drawn to that, every
            # other value lay flat on the axis.  The axis stops at a few times the load without friction.
            _clipped(plot, ideal.balancing, shown)
    exact = analysis.equilibrium
    plot.plot(marks, exact.balancing, "o", color="#1f5fa8", markersize=3.5)
    ringed = {plan.index for plan in analysis.plans if plan.forces is not None}
    for k, (number, x, y) in enumerate(zip(positions.numbers, marks, exact.balancing, strict=True)):
        if math.isfinite(y):
            # Over a force polygon's square (7 pt across) the number stands higher: at 5 pt it sat on its top side.
            plot.annotate(str(number), (x, y), textcoords="offset points", xytext=(0, 7.5 if k in ringed else 5),
                          ha="center", fontsize=7)
    drawn = [(marks[plan.index], plan.forces.balancing) for plan in analysis.plans if plan.forces is not None]
    if drawn:
        plot.plot(*zip(*drawn, strict=True), "s", markerfacecolor="none", color="black", markersize=7,
                  label=text["diagram_polygons"])
    plot.axhline(0.0, color="black", linewidth=0.5)
    # The positions' numbers stand above their points: the highest ran into the frame at the top.
    low, high = plot.get_ylim()
    marked = exact.balancing[np.isfinite(exact.balancing)]
    if marked.size:
        plot.set_ylim(low, max(high, float(marked.max()) + NUMBER_ROOM * (high - low)))
    # A swing under three steps keeps matplotlib's own ticks.
    if driver.kind == "crank" and (turned := float(np.max(along))) >= CRANK_TICK_DEG * 3:
        plot.set_xticks(np.arange(0.0, turned + 1e-9, CRANK_TICK_DEG))
    plot.set_xlabel(axis)
    plot.set_ylabel(f"{name}{text['comma']}{unit}")  # a Chinese name takes a full-width comma
    plot.set_title(analysis.scene.title, fontsize=10, parse_math=False)  # the user's text, not mathtext
    plot.grid(True, linewidth=0.3)
    legend_under(figure, plot)
    with_decimal_mark(figure, text["decimal_mark"])
    return figure


# The room above the highest marked point for its number, as a share of the value axis (7 pt digits up to 7.5 pt over
# the point, on an axis some 200 pt tall).
NUMBER_ROOM = 0.1
# How far past the largest balancing load without friction the axis runs where a lock sends the one with it off.
LOCKED_REACH = 3.0


def _locked_stretches(plot, along: np.ndarray, locked: np.ndarray, label: str) -> None:
    """Each run of locked samples shaded, to halfway to the samples either side that move."""
    edges = np.flatnonzero(np.diff(np.concatenate([[0], locked.astype(int), [0]])))
    for number, (first, last) in enumerate(zip(edges[::2], edges[1::2] - 1, strict=True)):
        low = 0.5 * (along[max(first - 1, 0)] + along[first])
        high = 0.5 * (along[last] + along[min(last + 1, len(along) - 1)])
        plot.axvspan(low, high, color="#a83a1f", alpha=0.12, linewidth=0, label=label if number == 0 else None)


def _clipped(plot, ideal: np.ndarray, rubbing: np.ndarray) -> None:
    """The value axis over both curves as far as :data:`LOCKED_REACH` times the largest load without friction."""
    reach = LOCKED_REACH * float(np.nanmax(np.abs(ideal)))
    values = np.concatenate([ideal, rubbing])
    values = values[np.isfinite(values) & (np.abs(values) <= reach)]
    low, high = float(values.min()), float(values.max())
    margin = 0.08 * (high - low)
    plot.set_ylim(low - margin, high + margin)


def _friction(analysis: Analysis, sweep):
    from ..joint_friction import friction_pairs
    from ..statics import pairs

    return friction_pairs(analysis.scene.friction, pairs(analysis.mechanism, sweep.slides))
