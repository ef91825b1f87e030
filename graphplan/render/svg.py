"""The svgwrite backend: layers of primitives in, an SVG document out.

Paper coordinates are millimetres with y up; the flip to SVG's y-down happens
here and nowhere else.  Numbers are written by one formatter at a fixed
precision and every group has an explicit id, so that the same drawing gives
the same bytes every time.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from .indices import ABOVE, BELOW, LINE
from .lettering import index_height
from .primitives import (
    FONT_SIZE_PER_CAP,
    Arrow,
    Circle,
    Layer,
    Polyline,
    Stroke,
    Text,
    bounds,
    descent_em,
    has_wide,
)
from .script_runs import is_mixed, script_runs, width_em

# Latin, Greek and Cyrillic from DejaVu Sans; a viewer that falls back glyph by glyph takes
# Chinese from Noto Sans CJK.
FONT_FAMILY = "DejaVu Sans, Noto Sans CJK SC, Noto Sans CJK JP, Noto Sans, sans-serif"
# A text with Chinese in it names the CJK font first: some renderers (cairosvg) take only the first
# family of the list, and Noto Sans CJK has the Latin letters and digits such a text mixes in.
CJK_FONT_FAMILY = "Noto Sans CJK SC, Noto Sans CJK JP, DejaVu Sans, Noto Sans, sans-serif"


def font_family(text: str) -> str:
    """The font-family list for ``text``: CJK first when it has a character of East Asian width."""
    return CJK_FONT_FAMILY if has_wide(text) else FONT_FAMILY


# An index and a component are lettered a height of the series smaller than their symbol (lettering.index_height),
# this far (em of the line) under and over its baseline, inside the box the flat text was laid out in (its
# descenders' depth under the baseline, its accents' height over it): an index that descends (Mу, ΣMp) is lowered
# less.
_LOWERED = {LINE: 0.0, BELOW: 0.2, ABOVE: -0.36}
_BOX_DESCENT_EM = 0.3 / FONT_SIZE_PER_CAP


def _scale(place: int, size: float) -> float:
    """A run's lettering over its line's, for a line lettered at cap height ``size``."""
    return 1.0 if place == LINE else index_height(size) / size


def _lowered(run: str, place: int, size: float) -> float:
    """How far under the line's baseline a run is set (em of the line; negative over it)."""
    if place != BELOW:
        return _LOWERED[place]
    return min(_LOWERED[BELOW], _BOX_DESCENT_EM - _scale(place, size) * descent_em(run))


def _segments(item: Text) -> tuple[tuple[str, bool, int], ...]:
    """The runs a text is set in, each in one font and at one place (text, wide, place); empty where it is set whole,
    in one font on the line."""
    if not item.runs:
        scripts = script_runs(item.text)
        return tuple((run, wide, LINE) for run, wide in scripts) if is_mixed(scripts) else ()
    return tuple((run, wide, place) for text, place in item.runs for run, wide in script_runs(text))


# Spaces in a row, which a renderer sets as one.
_ONE_SPACE = re.compile(" {2,}")


def _set_runs(item: Text, segments: tuple[tuple[str, bool, int], ...]
              ) -> tuple[list[tuple[str, float, bool, int, str]], float] | None:
    """Each run of ``segments`` as written, where it starts (em of the line's font from the text's start), its font
    and place and the run it was cut as, and the width the runs take (em), as cairosvg and WeasyPrint set runs each
    at its own x: there a run's spaces before its first letter are dropped and spaces in a row set as one, so those
    are hung on the end of the run before it (the text reads as written) and one space of them left between the two
    (runs placed by their spaces as typed read "h ₁₄" after "mm,  h").  None where the text is set whole, or a CJK
    font's widths cannot be read."""
    if not segments:
        return None
    placed: list[list] = []
    pen, after_space = 0.0, False
    for run, wide, place in segments:
        scale = _scale(place, item.size)
        letters = run.lstrip(" ") if placed else run
        if len(letters) < len(run):
            placed[-1][0] += run[:len(run) - len(letters)]
            space = width_em(((" ", wide),), item.weight)
            if space is None:
                return None
            if not after_space:
                pen += space * scale
                after_space = True
        if not letters:
            continue
        shown = _ONE_SPACE.sub(" ", letters)
        advance = width_em(((shown, wide),), item.weight)
        if advance is None:
            return None
        placed.append([letters, pen, wide, place, run])
        pen += advance * scale
        after_space = shown.endswith(" ")
    return [tuple(run) for run in placed], pen


def _n(value: float) -> str:
    text = f"{value:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _stroke_attributes(stroke: Stroke) -> dict[str, str]:
    attributes = {"stroke": stroke.colour, "stroke-width": _n(stroke.width),
                  "stroke-linecap": "round", "stroke-linejoin": "round"}
    if stroke.dash:
        attributes["stroke-dasharray"] = " ".join(_n(d) for d in stroke.dash)
    return attributes


def to_svg(layers: Sequence[Layer], margin: float = 8.0, page: tuple[float, float] | None = None) -> str:
    """The SVG text of ``layers``; the page is the drawing's bounds plus ``margin`` unless given (mm)."""
    if page is None:
        # Measured only here: a sheet's page is given, and its drawings' bounds, a walk over all their points, unused.
        xmin, ymin, xmax, ymax = bounds(layers)
        left, top = xmin - margin, ymax + margin
        width, height = xmax - xmin + 2 * margin, ymax - ymin + 2 * margin
    else:
        left, top = 0.0, page[1]
        width, height = page

    def xy(point: tuple[float, float]) -> tuple[str, str]:
        return _n(point[0] - left), _n(top - point[1])

    # Imported here, not with the module: the layouts that import to_svg are also measured by check and the sheet
    # packing, which write no SVG, and svgwrite (its validator's grammar built on import) is a good part of a start.
    from xml.etree import ElementTree

    import svgwrite

    document = svgwrite.Drawing(size=(f"{_n(width)}mm", f"{_n(height)}mm"), profile="full", debug=False)
    document.viewbox(0, 0, float(_n(width)), float(_n(height)))
    document.add(document.rect(insert=(0, 0), size=(_n(width), _n(height)), fill="white", id="background"))
    # The elements' attributes are put in their attribs dict at once: their names are written as SVG spells them, and
    # the document is not validated (debug=False), all svgwrite's update() would do to each, some twenty thousand.
    def polyline(item: Polyline):
        # A path with our own number formatting: svgwrite's polyline formats points itself.
        # Each point written in place, not through xy(): the drawings have some ten thousand.
        path = "M" + " L".join(f"{_n(x - left)},{_n(top - y)}" for x, y in item.points) + (" Z" if item.closed else "")
        element = document.path(d=path)
        element.attribs.update({"fill": item.fill or "none", **_stroke_attributes(item.stroke)})
        return element

    def text(item: Text):
        x, y = xy(item.at)
        size = item.size * FONT_SIZE_PER_CAP
        runs = _set_runs(item, _segments(item))
        # The attributes gathered in the order they are written and set at once: svgwrite sets each in a call.
        if runs is None:
            element = document.text(item.text, insert=(x, y))
            attributes = {"font-family": font_family(item.text), "text-anchor": item.anchor}
        else:
            # Set run by run, each at its own x and y: a run that flows on from the one before is anchored on its own
            # by cairosvg, and set by WeasyPrint (note.pdf) with the text's anchor laid over the runs, every index
            # over its letter (S₂ a struck-through S) and μa's scale after its number.  The text keeps its anchor,
            # where a reader of the SVG finds it, as for a text set whole.
            placed, width = runs
            start = float(x) + {"start": 0.0, "middle": -width / 2, "end": -width}[item.anchor] * size
            element = document.text("", insert=(x, y))
            mixed = has_wide(item.text)
            attributes = {"font-family": CJK_FONT_FAMILY if mixed else FONT_FAMILY, "text-anchor": item.anchor}
            for written, offset, wide, place, run in placed:
                span = document.tspan(written)
                span.attribs.update({"text-anchor": "start", "x": _n(start + offset * size),
                                     "y": _n(float(y) + _lowered(run, place, item.size) * size)})
                if mixed:
                    span.attribs["font-family"] = CJK_FONT_FAMILY if wide else FONT_FAMILY
                if place != LINE:
                    span.attribs["font-size"] = _n(size * _scale(place, item.size))
                element.add(span)
        attributes.update({"font-size": _n(size), "fill": item.colour})
        if item.weight != "normal":
            attributes["font-weight"] = item.weight
        if item.rotation:
            # Counter-clockwise on the paper is clockwise once y points down; about the anchor, not the start.
            attributes["transform"] = f"rotate({_n(-item.rotation)} {x} {y})"
        element.attribs.update(attributes)
        return element

    for layer in layers:
        group = document.g(id=layer.name)
        for item in layer.items:
            if isinstance(item, Polyline):
                element = polyline(item)
            elif isinstance(item, Arrow):
                element = document.g(id=item.key) if item.key else document.g()
                element.add(polyline(item.shaft()))
                element.add(polyline(item.tip()))
            elif isinstance(item, Circle):
                cx, cy = xy(item.centre)
                element = document.circle(center=(cx, cy), r=_n(item.radius))
                element.attribs.update({"fill": item.fill or "none", **_stroke_attributes(item.stroke)})
            elif isinstance(item, Text):
                element = text(item)
            else:  # pragma: no cover - the Primitive union is closed
                raise TypeError(f"unknown primitive {item!r}")
            group.add(element)
        document.add(group)
    # svgwrite's tostring() serializes to UTF-8 bytes through a codec writer, a call for each of the document's
    # pieces, and decodes them again: ElementTree writes the same text straight to a string (as svgwrite's own note
    # on tostring() says Python 3 may), with no XML declaration either way.
    return ElementTree.tostring(document.get_xml(), encoding="unicode")
