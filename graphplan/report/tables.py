"""The error tables of the plans, as Markdown for the report and CSV for a spreadsheet.

One row per quantity, the analytic value beside the plan's from each source
(the plan as constructed, read to the drafting precision, measured by hand),
each with its error δ = (analytic − plan) / analytic · 100 %.
"""

from __future__ import annotations

import csv
import io
from collections import defaultdict

from ..analysis import Analysis
from ..check import SOURCES, ErrorRow

FORMULA = "δ = (analytic − plan) / analytic · 100 %"


def _grouped(analysis: Analysis):
    """For each plan position, its quantities in reading order with the error row of each source."""
    for plan in analysis.plans:
        table: dict[str, dict[str, ErrorRow]] = defaultdict(dict)
        for row in plan.errors:
            table[row.quantity][row.source] = row
        sources = [s for s in SOURCES if any(s in rows for rows in table.values())]
        yield plan.number, table, sources


def markdown(analysis: Analysis) -> str:
    lines = [f"# Errors of the plans: {analysis.scene.title}", "", f"{FORMULA}; drafting: every length read off the "
             f"plan rounded to {analysis.scene.drawing.drafting_precision:g} mm.", ""]
    for number, table, sources in _grouped(analysis):
        lines += [f"## Position {number}", ""]
        header = ["quantity", "analytic"] + [f"{s}" for s in sources] + [f"δ {s}, %" for s in sources]
        lines += ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
        for quantity, rows in table.items():
            exact = next(iter(rows.values())).analytic
            cells = [quantity, f"{exact:.5g}"]
            cells += [f"{rows[s].plan:.5g}" if s in rows else "" for s in sources]
            cells += [f"{round(rows[s].percent, 3) or 0.0:.3f}" if s in rows else "" for s in sources]
            lines.append("| " + " | ".join(cells) + " |")
        lines.append("")
    return "\n".join(lines)


def csv_text(analysis: Analysis) -> str:
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["position", "quantity", "analytic", "source", "plan", "percent"])
    for plan in analysis.plans:
        for row in plan.errors:
            writer.writerow([row.position, row.quantity, f"{row.analytic:.12g}", row.source, f"{row.plan:.12g}",
                             f"{row.percent:.6g}"])
    return out.getvalue()
