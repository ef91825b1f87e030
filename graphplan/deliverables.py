"""What a run delivers: the pieces the scene has data for, in the formats asked for.

A *piece* is one part of a course project (the plan of positions, the
velocity plans, the force analysis, the error tables, the note, ...).  By
default a run delivers every piece the scene has data for and nothing else;
``[output] include`` or ``--only`` narrows that down, and asking for a piece
the scene cannot give is an error naming what is missing.  Every drawing is
written as SVG, and also as PNG, PDF or DXF when those formats are asked for.
"""

from __future__ import annotations

import dataclasses
import io
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from .analysis import Analysis
from .errors import SceneError
from .render.primitives import Layer

# Every piece a run can deliver, in the order a course project presents them.  The first seven are the
# scene contract's; ``figures`` are the report figures drawn with matplotlib.
PIECES = ("positions", "velocity", "acceleration", "forces", "lever", "errors", "note", "figures")
FORMATS = ("svg", "png", "pdf", "dxf")
# Pieces that cost more than they are worth by default: delivered only when asked for.
ON_REQUEST = ("figures",)


@dataclass(frozen=True)
class Drawing:
    """A drawing of the run: its file stem, its layers (paper mm, y up), and its page (mm) when it is a sheet."""

    stem: str
    layers: list[Layer]
    page: tuple[float, float] | None = None


def missing(analysis: Analysis, piece: str) -> str | None:
    """Why the scene cannot give ``piece``, or None when it can."""
    has_plans = bool(analysis.plans)
    has_forces = any(plan.forces is not None for plan in analysis.plans)
    if piece in ("velocity", "acceleration", "errors") and not has_plans:
        return "needs plan positions: positions.plans lists none"
    if piece in ("forces", "lever") and not has_plans:
        return "needs plan positions: positions.plans lists none"
    if piece in ("forces", "lever") and not has_forces:
        return "needs masses or loads: the scene has neither ([links.N] mass, [[loads]])"
    if piece == "figures" and analysis.equilibrium is None:
        return "needs masses or loads: the scene has neither ([links.N] mass, [[loads]])"
    return None


def chosen(analysis: Analysis, only: Iterable[str] | None = None, where: str = "--only") -> tuple[str, ...]:
    """The pieces to deliver: ``only`` (from ``--only``), else the scene's ``[output] include``, else every
    piece the scene has data for (those :data:`ON_REQUEST` excepted).

    A piece asked for that the scene cannot give is a :class:`SceneError`.
    """
    asked: list[str] | None = None
    if only is not None:
        asked = list(only)
        for k, piece in enumerate(asked):
            if piece not in PIECES:
                raise SceneError(f"{where}[{k}]", f"must be one of {', '.join(PIECES)}", piece)
    elif analysis.scene.include is not None:
        asked, where = list(analysis.scene.include), "output.include"
    if asked is None:
        return tuple(piece for piece in PIECES if piece not in ON_REQUEST and missing(analysis, piece) is None)
    for k, piece in enumerate(asked):
        reason = missing(analysis, piece)
        if reason is not None:
            raise SceneError(f"{where}[{k}]", f"{piece!r} {reason}")
    return tuple(piece for piece in PIECES if piece in asked)


def drawings(analysis: Analysis, pieces: tuple[str, ...]) -> list[Drawing]:
    """The drawings of ``pieces``: the plan of positions, a plan sheet and a force sheet per plan position."""
    from .render import drawings as draw
    from .render import forces as force_layout
    from .render import plans as plan_layout
    from .render import positions as positions_layout

    found: list[Drawing] = []
    if "positions" in pieces:
        found.append(Drawing("positions", positions_layout.layout(draw.positions_plan(analysis))))
    shown = tuple(name for name in ("velocity", "acceleration") if name in pieces)
    for plan in analysis.plans:
        if shown:
            sheet = dataclasses.replace(draw.plan_sheet(analysis, plan.index, plan.velocity, plan.acceleration),
                                        drawings=("mechanism", *shown))
            found.append(Drawing(f"plan_{plan.number}", plan_layout.layout(sheet)))
        if plan.forces is not None and ("forces" in pieces or "lever" in pieces):
            sheet = draw.force_sheet(analysis, plan)
            if "lever" not in pieces:
                sheet = dataclasses.replace(sheet, lever=None)
            found.append(Drawing(f"forces_{plan.number}", force_layout.layout(sheet)))
    return found


def tables(analysis: Analysis, pieces: tuple[str, ...]) -> dict[str, str]:
    """The text files of ``pieces``: the error tables, the force analysis, the note."""
    files: dict[str, str] = {}
    if "errors" in pieces:
        from .report.tables import csv_text, markdown

        files["errors.md"] = markdown(analysis)
        files["errors.csv"] = csv_text(analysis)
    if "forces" in pieces:
        from .report.forces import markdown as forces_markdown

        files["forces.md"] = forces_markdown(analysis)
    return files


def figures(analysis: Analysis, pieces: tuple[str, ...]) -> dict[str, str]:
    """The report figures drawn with matplotlib (imported only here)."""
    if "figures" not in pieces:
        return {}
    from .report.figures import balancing_diagram

    return {"balancing.svg": balancing_diagram(analysis)}


def encoded(drawing: Drawing, formats: Iterable[str]) -> dict[str, str | bytes]:
    """The files of one drawing in each of ``formats``."""
    from .render.svg import to_svg

    svg = to_svg(drawing.layers, page=drawing.page) if drawing.page else to_svg(drawing.layers)
    files: dict[str, str | bytes] = {}
    writers: dict[str, Callable[[], str | bytes]] = {
        "svg": lambda: svg,
        "png": lambda: _export("svg_to_png")(svg),
        "pdf": lambda: _export("svg_to_pdf")(svg),
        "dxf": lambda: _dxf(drawing),
    }
    for kind in formats:
        files[f"{drawing.stem}.{kind}"] = writers[kind]()
    return files


def _export(name: str):
    from .render import export

    return getattr(export, name)


def _dxf(drawing: Drawing) -> bytes:
    from .render.dxf import layers_to_dxf

    stream = io.StringIO()
    layers_to_dxf(drawing.layers, stream)
    return stream.getvalue().encode("utf-8")


def check_formats(formats: Iterable[str], where: str = "--format") -> tuple[str, ...]:
    """``formats`` checked against :data:`FORMATS`; SVG is always written."""
    asked = list(formats)
    for k, kind in enumerate(asked):
        if kind not in FORMATS:
            raise SceneError(f"{where}[{k}]", f"must be one of {', '.join(FORMATS)}", kind)
    return tuple(kind for kind in FORMATS if kind == "svg" or kind in asked)


def files(analysis: Analysis, pieces: tuple[str, ...], formats: tuple[str, ...] = ("svg",)) -> dict[str, str | bytes]:
    """Every file of the run: ``results.json``, the drawings in ``formats``, the tables and the figures."""
    from .report.results import dumps, results

    found: dict[str, str | bytes] = {"results.json": dumps(results(analysis))}
    for drawing in drawings(analysis, pieces):
        found.update(encoded(drawing, formats))
    found.update(tables(analysis, pieces))
    found.update(figures(analysis, pieces))
    return found


__all__ = ["FORMATS", "PIECES", "Drawing", "check_formats", "chosen", "drawings", "files", "missing"]
