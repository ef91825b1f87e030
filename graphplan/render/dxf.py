"""The DXF backend: the same layers of primitives the SVG backend draws, written with ezdxf.

Paper millimetres with y up are the DXF's own model space (``$INSUNITS`` =
mm), so points are written as they are.  Each graphplan layer (each primitive
of a dynamics diagram) goes to one of a few DXF layers by :func:`dxf_layer`;
each primitive becomes:

* a :class:`~.primitives.Polyline`: an LWPOLYLINE, and a solid HATCH when it is filled;
* a :class:`~.primitives.Circle`: a CIRCLE, and a solid HATCH when it is filled;
* an :class:`~.primitives.Arrow`: its shaft as an LWPOLYLINE from its start to its tip and its head as a
  solid HATCH;
* a :class:`~.primitives.Text` without indices: a TEXT on its baseline, aligned left, centre or right,
  in a TrueType style that has its glyphs (DejaVu Sans, or Noto Sans CJK for Chinese);
* a :class:`~.primitives.Text` with indices to set (its ``runs``, R₁₂, R₁₄ with τ over it): an
  MTEXT in the same style, height, colour and turn, its runs on the line as written, each index
  a stack with nothing over it (``\\S^ 12;``) and each component one with nothing under it
  (``\\Sτ^ ;``), lettered a height of the series smaller (:func:`~.lettering.index_height`) as
  the SVG letters them; attached by the bottom of its line, its baseline (a stack makes a line
  taller, which moves its top and its middle), at the left, the centre or the right, in a
  column as wide as its flat text (of no width, a reader that estimates one wrapped it).
  How far under and over the line a stack stands is the CAD program's to choose (ezdxf's own
  renderer sets an index on the line, a component over the cap height).

A white fill only hides what lies under a pin or a block on white paper; a
model space is often dark, so white fills are left out.  Stroke widths go to
the nearest DXF lineweight, dash patterns to linetypes of their own, colours
other than black to true colours (black stays BYLAYER, colour 7, which a CAD
program shows black on white and white on black).

ezdxf stamps the time and random GUIDs into a new document and again when
it writes one; they are fixed while it does (its option
``write_fixed_meta_data_for_testing``, set and restored around the calls,
so not safe across threads) so that the same layers give the same bytes.
"""

from __future__ import annotations

import io
import os
import re
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import IO

from .export import tool_for
from .indices import ABOVE, LINE
from .lettering import index_height
from .primitives import THIN, Arrow, Circle, Layer, Polyline, Primitive, Stroke, Text, bounds, has_wide, text_width

# The DXF layers and the words of a graphplan layer's name that send it there.
LINKS, CONSTRUCTION, VECTORS, TEXT, CURVES, AXES, SHEET = (
    "LINKS", "CONSTRUCTION", "VECTORS", "TEXT", "CURVES", "AXES", "SHEET")
LAYER_WORDS: dict[str, str] = {
    # the mechanism: links, blocks, pins, frame pivots; the lever's outline
    "links": LINKS, "positions": LINKS, "extremes": LINKS, "frame": LINKS, "plan": LINKS,
    # thin lines: lines of action, arms, leaders, paths of points, pole rays and ordinates; a balancing polygon's
    # angle marks and the extension line they are measured from
    "lines": CONSTRUCTION, "arms": CONSTRUCTION, "arm": CONSTRUCTION, "leaders": CONSTRUCTION,
    "paths": CONSTRUCTION, "rays": CONSTRUCTION, "friction": CONSTRUCTION, "reference": CONSTRUCTION,
    # a load diagram's ordinates from its axis up to the load at each position, thin as the rays beside them
    "ordinates": CONSTRUCTION,
    # a stroke's or a swing's dimension on the plan of positions
    "dimensions": CONSTRUCTION,
    # vectors and what marks them: plan vectors, forces, moments, senses of motion, plan points
    "vectors": VECTORS, "forces": VECTORS, "moments": VECTORS, "senses": VECTORS, "points": VECTORS,
    # lettering; the dynamics' results written under its diagrams
    "labels": TEXT, "caption": TEXT, "title": TEXT, "results": TEXT,
    # diagrams over the cycle
    "curves": CURVES, "legend": CURVES, "axes": AXES,
}
# The layers of the dynamics drawing (render/dynamics.py) as dynamics.dxf names them: each holds a whole diagram,
# axes, curves and lettering together.  On a sheet they are named dynamics-….
WHOLE_DIAGRAMS = frozenset({"moments", "works", "energy", "energy-mass", "inertia"})
# Lineweight (1/100 mm), in the order the layers are created.
LAYER_LINEWEIGHTS = {LINKS: 70, CONSTRUCTION: 25, VECTORS: 50, TEXT: 25, CURVES: 50, AXES: 35, SHEET: 50}

# Text styles: a TrueType font for Latin, Greek and Cyrillic, and one for Chinese (which also has Latin
# letters and digits, for a text that mixes them); bold variants for titles.
TEXT_STYLES = {
    ("latin", "normal"): ("GP-SANS", "DejaVuSans.ttf", "DejaVu Sans"),
    ("latin", "bold"): ("GP-SANS-BOLD", "DejaVuSans-Bold.ttf", "DejaVu Sans"),
    ("cjk", "normal"): ("GP-CJK", "NotoSansCJK-Regular.ttc", "Noto Sans CJK SC"),
    ("cjk", "bold"): ("GP-CJK-BOLD", "NotoSansCJK-Bold.ttc", "Noto Sans CJK SC"),
}

_NAMED_COLOURS = {"black": (0, 0, 0), "white": (255, 255, 255), "gray": (128, 128, 128), "grey": (128, 128, 128),
                  "red": (255, 0, 0), "green": (0, 128, 0), "blue": (0, 0, 255)}
_HEX = re.compile(r"#([0-9a-fA-F]{3}|[0-9a-fA-F]{6})")
# ACI 7: black on a white background, white on a dark one.
_FOREGROUND = 7
_BYLAYER = 256
# LWPOLYLINE flag: the dash pattern runs on across the vertices instead of restarting at each.
_PLINEGEN = 128
# Characters a DXF layer name may not hold.
_BAD_NAME = re.compile(r"[<>/\\\":;?*|=`,\s]")
# What a CAD program reads in a TEXT as a code, not as the characters written: two percent signs open a special
# character (%%d is °, %%c ⌀), a caret a control character (^J a line feed), \U+xxxx and \M+nxxxx a character by
# its number.
_PERCENTS = re.compile(r"%{2,}")
_CARET_OR_CONTROL = re.compile(r"[\x00-\x1f^]")
_CHARACTER_CODE = re.compile(r"\\(?=[UuMm]\+)")
# What an MTEXT reads as a code besides: a backslash opens a formatting code (\P a paragraph, \S a stack, \U+ a
# character), braces a group; inside a stack a semicolon closes it and a caret, a slash or a hash splits it.
_MTEXT_CODE = re.compile(r"[\\{}]")
_STACK_CODE = re.compile(r"[\\{};/#]")


def dxf_layer(name: str, item: Primitive | None = None) -> str:
    """The DXF layer of a primitive in the graphplan layer ``name``.

    The sheet's own layers, ``sheet-…`` (its title and frame) and ``title-block``,
    go whole to SHEET; any other text goes to TEXT.  A diagram of the dynamics
    drawing (:data:`WHOLE_DIAGRAMS`, ``dynamics-…`` on a sheet) is taken apart
    as the kinematic diagrams are drawn: its arrows and thin lines (axes, ticks,
    grid) to AXES, the rest (curves, their legend, the points marked on them,
    the energy–mass diagram's tangents) to CURVES.  The rest goes where the last word of ``name`` that
    :data:`LAYER_WORDS` knows sends it (``body-II-3-4-links`` → LINKS,
    ``lever-arm-Fu3`` → CONSTRUCTION).  A name with no known word keeps its own
    name, upper-cased, so nothing is lost.
    """
    words = name.lower().split("-")
    if words[0] == "sheet" or name == "title-block":
        return SHEET
    if isinstance(item, Text):
        return TEXT
    if words[0] == "dynamics" or name in WHOLE_DIAGRAMS:
        # Before the words: "moments" also names a force sheet's curved arrows, which are VECTORS.
        thin = isinstance(item, Polyline) and item.stroke.width <= THIN.width
        return AXES if isinstance(item, Arrow) or thin else CURVES
    for word in reversed(words):
        if word in LAYER_WORDS:
            return LAYER_WORDS[word]
    return _BAD_NAME.sub("_", name.upper()) or "0"


def to_dxf_document(layers: Sequence[Layer]):
    """An ezdxf document (R2013, mm, y up) holding ``layers``."""
    ezdxf = tool_for("dxf", "ezdxf")
    from ezdxf import units

    with _fixed_metadata():
        document = ezdxf.new("R2013", setup=False, units=units.MM)
    document.header["$MEASUREMENT"] = 1
    document.header["$LWDISPLAY"] = 1
    for name, weight in LAYER_LINEWEIGHTS.items():
        document.layers.add(name, color=_FOREGROUND, lineweight=weight)
    for style, font, family in TEXT_STYLES.values():
        entry = document.styles.add(style, font=font)
        entry.set_extended_font_data(family, bold=style.endswith("BOLD"))
    space = document.modelspace()
    writer = _Writer(document, space)
    for layer in layers:
        for item in layer.items:
            writer.add(dxf_layer(layer.name, item), item)
    xmin, ymin, xmax, ymax = bounds(layers)
    space.dxf.extmin = (xmin, ymin, 0.0)
    space.dxf.extmax = (xmax, ymax, 0.0)
    # The header's extents and limits, by which a CAD program zooms and plots: they were unset and the template's
    # 420 × 297 on an A1 sheet.  ezdxf writes $LIMMIN/$LIMMAX from the model space's limits.
    document.header["$EXTMIN"] = (xmin, ymin, 0.0)
    document.header["$EXTMAX"] = (xmax, ymax, 0.0)
    space.dxf.limmin = (xmin, ymin)
    space.dxf.limmax = (xmax, ymax)
    document.set_modelspace_vport(height=1.1 * (ymax - ymin), center=((xmin + xmax) / 2, (ymin + ymax) / 2))
    _register_classes_in_a_fixed_order(document)
    return document


def _register_classes_in_a_fixed_order(document) -> None:
    """The CLASS records of the entity types ``document`` uses, registered in the order of their names.

    ezdxf registers them as it writes, in the order of a set of the names, which string hashing changes from
    process to process (``PYTHONHASHSEED``): two runs of one scene wrote two DXF files.  A class registered
    already is kept where it stands, so ezdxf's own pass adds none."""
    for name in sorted(document.entitydb.dxf_types_in_use()):
        document.classes.add_class(name)


def layers_to_dxf(layers: Sequence[Layer], target: str | os.PathLike[str] | IO) -> None:
    """Write ``layers`` as a DXF file (UTF-8) to a path or to an open text or binary stream."""
    document = to_dxf_document(layers)
    with _fixed_metadata():
        if isinstance(target, (str, os.PathLike)):
            document.saveas(target, encoding="utf-8")
            return
        text = io.StringIO()
        document.write(text)
    data = text.getvalue()
    if isinstance(target, io.TextIOBase):
        target.write(data)
    else:
        target.write(data.encode("utf-8"))


@contextmanager
def _fixed_metadata() -> Iterator[None]:
    """ezdxf writes a fixed date and GUIDs instead of now and random ones, for the duration."""
    ezdxf = tool_for("dxf", "ezdxf")

    before = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        yield
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = before


class _Writer:
    """Adds primitives to a model space, creating a linetype for each dash pattern it meets."""

    def __init__(self, document, space) -> None:
        self._document = document
        self._space = space

    def add(self, layer: str, item: Primitive) -> None:
        if layer not in self._document.layers:
            self._document.layers.add(layer, color=_FOREGROUND)
        if isinstance(item, Polyline):
            self._polyline(layer, item.points, item.stroke, item.closed)
            if _filled(item.fill):
                self._hatch(layer, item.fill).paths.add_polyline_path(item.points, is_closed=True)
        elif isinstance(item, Circle):
            self._space.add_circle(item.centre, item.radius, dxfattribs=self._attributes(layer, item.stroke))
            if _filled(item.fill):
                self._hatch(layer, item.fill).paths.add_edge_path().add_arc(item.centre, item.radius, 0.0, 360.0)
        elif isinstance(item, Arrow):
            # The shaft runs to the tip, under the head: measured in CAD, a vector is as long as it is drawn
            # (pa = 100 mm), where the SVG stops it short so that its round cap cannot poke past the tip.
            self._polyline(layer, (item.start, item.end), item.stroke, False)
            self._hatch(layer, item.stroke.colour).paths.add_polyline_path(item.tip().points, is_closed=True)
        elif isinstance(item, Text):
            self._text(layer, item)
        else:  # pragma: no cover - the Primitive union is closed
            raise TypeError(f"unknown primitive {item!r}")

    def _attributes(self, layer: str, stroke: Stroke) -> dict:
        attributes: dict = {"layer": layer, "lineweight": _lineweight(stroke.width)}
        attributes.update(_colour_attributes(stroke.colour))
        if stroke.dash:
            attributes["linetype"] = self._linetype(stroke.dash)
        return attributes

    def _polyline(self, layer: str, points, stroke: Stroke, closed: bool) -> None:
        entity = self._space.add_lwpolyline(points, format="xy", close=closed,
                                            dxfattribs=self._attributes(layer, stroke))
        if stroke.dash:
            entity.dxf.flags |= _PLINEGEN

    def _hatch(self, layer: str, colour: str):
        rgb = _rgb(colour)
        hatch = self._space.add_hatch(color=_FOREGROUND, dxfattribs={"layer": layer})
        hatch.set_solid_fill(color=_FOREGROUND, rgb=None if rgb == (0, 0, 0) else rgb)
        return hatch

    def _text(self, layer: str, item: Text) -> None:
        from ezdxf.enums import TextEntityAlignment

        if item.runs:
            self._mtext(layer, item)
            return
        attributes = {"layer": layer, "style": _style(item), **_colour_attributes(item.colour)}
        if item.rotation:
            attributes["rotation"] = item.rotation
        align = {"start": TextEntityAlignment.LEFT, "middle": TextEntityAlignment.CENTER,
                 "end": TextEntityAlignment.RIGHT}[item.anchor]
        self._space.add_text(_escaped(item.text), height=item.size,
                             dxfattribs=attributes).set_placement(item.at, align=align)

    def _mtext(self, layer: str, item: Text) -> None:
        """A text with indices: an MTEXT that stacks each index under its line and each component over it, a height
        of the series smaller, as the SVG sets them (a TEXT has no codes to move or shrink a part of it)."""
        from ezdxf.enums import MTextEntityAlignment
        from ezdxf.math import Vec3

        # The column is the box the layouts keep for the label, as wide as its flat text (its smaller indices only
        # narrow it): of no width, an MTEXT is wrapped by a reader that estimates one (ezdxf's renderer set the "(φ)"
        # of "Displacement diagram sE(φ)" on a line of its own).
        attributes = {"layer": layer, "style": _style(item), "char_height": item.size,
                      "width": text_width(item.text, item.size, item.weight), **_colour_attributes(item.colour)}
        if item.rotation:
            # Its baseline's direction rather than its rotation, whose unit readers disagree on (radians by the
            # DXF reference, degrees as AutoCAD writes it).
            attributes["text_direction"] = Vec3.from_deg_angle(item.rotation)
        # Bottom: a line's baseline, whatever hangs under it or stands over it (a stack makes the line taller,
        # which moves its top and its middle); left, centre or right as the TEXT is aligned on its baseline.
        attach = {"start": MTextEntityAlignment.BOTTOM_LEFT, "middle": MTextEntityAlignment.BOTTOM_CENTER,
                  "end": MTextEntityAlignment.BOTTOM_RIGHT}[item.anchor]
        entity = self._space.add_mtext(_mtext_content(item), dxfattribs=attributes)
        entity.set_location(item.at, attachment_point=attach.value)

    def _linetype(self, dash: tuple[float, ...]) -> str:
        name = "GP-DASH-" + "-".join(f"{d:g}" for d in dash)
        if name not in self._document.linetypes:
            # DXF alternates dashes (positive) and gaps (negative); an odd SVG pattern repeats to even.
            pattern = list(dash) * (2 if len(dash) % 2 else 1)
            elements = [d if k % 2 == 0 else -d for k, d in enumerate(pattern)]
            self._document.linetypes.add(name, pattern=[sum(pattern), *elements],
                                         description="graphplan " + " ".join(f"{d:g}" for d in dash))
        return name


def _style(item: Text) -> str:
    """The text style of ``item``: a TrueType font that has its glyphs, bold or not."""
    script = "cjk" if has_wide(item.text) else "latin"
    return TEXT_STYLES[(script, "bold" if item.weight == "bold" else "normal")][0]


def _mtext_content(item: Text) -> str:
    """The MTEXT content of a text with indices: its runs on the line as they are written, each index a stack
    with nothing over it (\\S^ 12;) and each component one with nothing under it (\\Sτ^ ;), in a group lettered
    :func:`~.lettering.index_height` high, as the SVG letters them."""
    from ezdxf.tools.text import MTextEditor

    smaller = index_height(item.size) / item.size
    content = MTextEditor()
    for text, place in item.runs:
        if place == LINE:
            content.append(_mtext_escaped(text))
            continue
        stacked = _mtext_escaped(text, stacked=True)
        over, under = (stacked, "") if place == ABOVE else ("", stacked)
        content.group(str(MTextEditor().scale_height(smaller).stack(over, under)))
    return str(content)


def _mtext_escaped(text: str, stacked: bool = False) -> str:
    """``text`` as an MTEXT's content (``stacked``: a part of a stack) that a CAD program reads as ``text``.

    A backslash and a brace (and in a stack a semicolon, a slash and a hash) after a
    backslash, a caret in a stack as a backslash, a caret and a space; percent signs and
    control characters as in a TEXT (:func:`_escaped`), which an MTEXT reads alike.
    """
    text = (_STACK_CODE if stacked else _MTEXT_CODE).sub(lambda code: "\\" + code.group(), text)
    return _percents_and_carets(text, "\\^ " if stacked else "^ ")


def _escaped(text: str) -> str:
    """``text`` as a TEXT's content that a CAD program reads as ``text`` (a title ``50%%d`` read as 50°).

    As the DXF reference writes them: a percent sign as %%% wherever two or more
    stand together (one alone is read as itself, and stays readable to a program
    that knows no codes), a caret as a caret and a space, a control character as
    a caret and its letter (a tab ^I); a backslash before U+ or M+ as its own
    code, \\U+005C.
    """
    return _CHARACTER_CODE.sub(r"\\U+005C", _percents_and_carets(text, "^ "))


def _percents_and_carets(text: str, caret: str) -> str:
    """Percent signs as %%% where two or more stand together, a caret as ``caret``, a control character as a
    caret and its letter."""
    text = _PERCENTS.sub(lambda run: "%%%" * len(run.group()), text)
    return _CARET_OR_CONTROL.sub(lambda c: caret if c.group() == "^" else "^" + chr(ord(c.group()) + 64), text)


def _filled(fill: str | None) -> bool:
    return fill is not None and fill != "none" and _rgb(fill) != (255, 255, 255)


def _colour_attributes(colour: str) -> dict:
    rgb = _rgb(colour)
    if rgb == (0, 0, 0):
        return {"color": _BYLAYER}
    from ezdxf.colors import rgb2int

    return {"true_color": rgb2int(rgb)}


def _rgb(colour: str) -> tuple[int, int, int]:
    """A colour of the primitives (#rrggbb, #rgb or a few names) as (r, g, b)."""
    key = colour.strip().lower()
    if key in _NAMED_COLOURS:
        return _NAMED_COLOURS[key]
    if _HEX.fullmatch(key):
        digits = key[1:] if len(key) == 7 else "".join(2 * c for c in key[1:])
        return (int(digits[0:2], 16), int(digits[2:4], 16), int(digits[4:6], 16))
    raise ValueError(f"colour {colour!r} is not #rrggbb, #rgb or one of {', '.join(_NAMED_COLOURS)}")


def _lineweight(width: float) -> int:
    """The DXF lineweight (1/100 mm) nearest to a stroke width in mm."""
    from ezdxf.lldxf.const import VALID_DXF_LINEWEIGHTS

    return min(VALID_DXF_LINEWEIGHTS, key=lambda weight: abs(weight - 100.0 * width))

