"""The accuracy report of one scene: each method's error against its run time, as a table, CSV and a plot.

The numbers come from :func:`graphplan.accuracy.study`; this module only
presents them, in the scene's language.  Its run times are measured, so
unlike every other output this report differs from run to run.
"""

from __future__ import annotations

import csv
import io
import math
import statistics
from collections.abc import Iterable, Mapping

from ..accuracy import Row, Study, draw_study
from ..locale import Count, strings
from .markdown import literal
from .plot_style import PAGE_WIDTH_INCHES, legend_under, new_figure, settings, svg_text, with_decimal_mark

FAMILIES = ("velocity", "acceleration")


def method_name(row: Row, text: Mapping[str, str]) -> str:
    """A row's method as a reader calls it: "plans read to 0.5 mm", "plans read to 0.3 mm (as in the initial data)",
    "kinematic diagrams, N = 48"."""
    if row.method == "drafting":
        precision = row.parameter.removesuffix(" mm").replace(".", text["decimal_mark"])
        return text["accuracy_drafting_own" if row.own else "accuracy_drafting"].format(precision=precision)
    if row.method == "diagram":
        return text["accuracy_diagram"].format(count=row.positions)
    return text.get(f"accuracy_{row.method}", row.method)


def table_lines(rows: Iterable[Row], text: Mapping[str, str]) -> list[str]:
    """The Markdown table: method, positions, time, largest and median error of velocities and accelerations."""
    header = [text["accuracy_method"], text["accuracy_positions"], text["accuracy_time"],
              text["accuracy_velocity_largest"], text["accuracy_median"],
              text["accuracy_acceleration_largest"], text["accuracy_median"]]
    lines = ["| " + " | ".join(header) + " |", "|---|---:|---:|---:|---:|---:|---:|"]
    for row in rows:
        numbers = [f"{row.seconds:.2e}", *(f"{row.stat(family, how):.1e}" for family in FAMILIES
                                          for how in (max, statistics.median))]
        cells = [method_name(row, text), str(row.positions), *(n.replace(".", text["decimal_mark"]) for n in numbers)]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def order_sentence(orders: Mapping[str, float], text: Mapping[str, str]) -> str:
    mark = text["decimal_mark"]
    return text["accuracy_order"].format(velocity=f"{orders.get('velocity', math.nan):.2f}".replace(".", mark),
                                         acceleration=f"{orders.get('acceleration', math.nan):.2f}".replace(".", mark))


def markdown(study: Study, locale: str, title: str) -> str:
    """``accuracy.md``: what was compared with what, the table, and the diagrams' order of convergence."""
    text = strings(locale)
    lines = [f"# {text['accuracy_title'].format(title=literal(title))}", "",
             text["accuracy_explained"].format(count=Count(len(study.case.compared))), "",
             *([text["accuracy_left_out"].format(positions="; ".join(study.case.left_out.values()),
                                                 count=Count(len(study.case.left_out))), ""]
               if study.case.left_out else []),
             *table_lines(study.rows, text), "", order_sentence(study.orders, text), "",
             text["accuracy_measured"], ""]
    return "\n".join(lines)


def csv_text(rows: Iterable[Row]) -> str:
    """The rows for a spreadsheet, with the contract's identifiers (``fixture`` is the scene's name).

    The last column, ``scene_precision``, is ``true`` on the drafting row read to the scene's own
    ``drafting_precision``.
    """
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["fixture", "method", "parameter", "positions", "seconds",
                     *(f"{family}_{stat}" for family in FAMILIES for stat in ("max", "median")), "scene_precision"])
    for row in rows:
        writer.writerow([row.fixture, row.method, row.parameter, row.positions, f"{row.seconds:.4e}",
                         *(f"{row.stat(family, how):.4e}" for family in FAMILIES for how in (max, statistics.median)),
                         "true" if row.own else "false"])
    return out.getvalue()


def figure(study: Study, locale: str, title: str) -> str:
    """``accuracy.svg``: largest error against run time on log-log axes (filled: accelerations; ringed: the plans
    read to the scene's own drafting precision)."""
    import matplotlib

    text = strings(locale)
    with matplotlib.rc_context(settings()):
        drawn = new_figure(figsize=(PAGE_WIDTH_INCHES, 5.0), dpi=100)
        axes = drawn.subplots()
        names = {key.removeprefix("accuracy_legend_"): word for key, word in text.items()
                 if key.startswith("accuracy_legend_")}
        draw_study(axes, study.rows, text["millimetre"], names, text["accuracy_tag_own"])
        axes.set_xlabel(text["accuracy_axis_time"].format(count=Count(len(study.case.compared))), fontsize=9)
        axes.set_ylabel(text["accuracy_axis_error"], fontsize=9)
        axes.set_title(f"{title}\n{text['accuracy_plot_note']}", fontsize=9, parse_math=False)  # the user's title
        # Under the plot, not on it: "best" shuns the markers but not their labels (1 mm, 3600), and the run times
        # that place them change from run to run; the legend sat on a label as often as not.
        legend_under(drawn, axes, ncol=4)
        with_decimal_mark(drawn, text["decimal_mark"])
        return svg_text(drawn)
