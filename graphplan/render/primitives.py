"""Drawing primitives in paper millimetres, y up, and the symbols built from them.

A drawing is a list of :class:`Layer` objects, each a named list of
primitives.  Layouts (one module per drawing) compute primitives from
records; a backend (:mod:`graphplan.render.svg`) only translates them.
Symbols (pins, frame pivots, slider blocks, hatching, arrowheads) are drawn
once in a unit frame and placed by :func:`place`, so that their shape lives
in one place.
"""

from __future__ import annotations

import functools
import importlib.util
import math
import re
import unicodedata
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

Point = tuple[float, float]


@dataclass(frozen=True)
class Stroke:
    """Line style: width in mm, colour, dash pattern in mm (empty for solid)."""

    width: float = 0.35
    colour: str = "black"
    dash: tuple[float, ...] = ()


@dataclass(frozen=True)
class Polyline:
    points: tuple[Point, ...]
    stroke: Stroke = Stroke()
    closed: bool = False
    fill: str | None = None


@dataclass(frozen=True)
class Circle:
    centre: Point
    radius: float
    stroke: Stroke = Stroke()
    fill: str | None = "white"


@dataclass(frozen=True)
class Text:
    """Text at ``at``; ``anchor`` is start, middle or end; ``size`` is the cap height in mm; ``rotation`` the
    degrees it is turned counter-clockwise about ``at`` (ESKD's графа 26 is written upside down)."""

    at: Point
    text: str
    size: float = 3.5
    anchor: str = "middle"
    colour: str = "black"
    weight: str = "normal"
    rotation: float = 0.0
    # The text cut into its runs on the line, below it and above it (:mod:`graphplan.render.indices`), where it has
    # a symbol's index to set; empty where it is written as it is.  Joined, the runs are ``text``.
    runs: tuple[tuple[str, int], ...] = ()


@dataclass(frozen=True)
class Arrow:
    """A vector drawn from ``start`` to ``end``, its head's tip exactly at ``end``.

    ``head`` is the length of the arrowhead in mm; the head takes at most
    :data:`HEAD_SHARE` of the vector's length, so that a short vector still
    shows its shaft.  ``key`` names the vector for
    the backend (an svg id such as ``velocity-p-b``) and for tests.
    """

    start: Point
    end: Point
    stroke: Stroke = Stroke(0.5)
    head: float = 3.5
    key: str = ""

    @property
    def length(self) -> float:
        return math.dist(self.start, self.end)

    @property
    def angle(self) -> float:
        return math.atan2(self.end[1] - self.start[1], self.end[0] - self.start[0])

    @property
    def head_length(self) -> float:
        return min(self.head, HEAD_SHARE * self.length)

    def shaft(self) -> Polyline:
        """The line of the arrow, stopped inside the head so that its round cap cannot poke past the tip."""
        back = min(self.length, 0.7 * self.head_length)
        c, s = math.cos(self.angle), math.sin(self.angle)
        return Polyline((self.start, (self.end[0] - back * c, self.end[1] - back * s)), self.stroke)

    def tip(self) -> Polyline:
        return arrowhead(self.end, self.angle, self.head_length, self.stroke.colour)


Primitive = Polyline | Circle | Text | Arrow


@dataclass(frozen=True)
class Layer:
    """A named group of primitives (an svg ``<g id=...>``, a DXF layer)."""

    name: str
    items: tuple[Primitive, ...] = field(default_factory=tuple)


THIN = Stroke(0.25)
MAIN = Stroke(0.7)
BOLD = Stroke(1.0)


def place(points: Iterable[Point], at: Point, angle: float = 0.0, scale: float = 1.0) -> tuple[Point, ...]:
    """Points of a symbol drawn in its unit frame, turned by ``angle`` and moved to ``at``."""
    c, s = math.cos(angle), math.sin(angle)
    return tuple((at[0] + scale * (c * x - s * y), at[1] + scale * (s * x + c * y)) for x, y in points)


# The largest share of a vector's length its arrowhead may take.
HEAD_SHARE = 0.4
# An arrowhead in its unit frame: the tip at the origin, pointing along +x, one unit long.
_ARROWHEAD = ((0.0, 0.0), (-1.0, 0.17), (-0.82, 0.0), (-1.0, -0.17))


def arrowhead(tip: Point, angle: float, length: float = 3.5, colour: str = "black") -> Polyline:
    """A slender filled arrowhead with its tip at ``tip``, pointing along ``angle``."""
    return Polyline(place(_ARROWHEAD, tip, angle, length), Stroke(0.1, colour), closed=True, fill=colour)


def curved_arrow(centre: Point, radius: float, start: float, sweep: float, stroke: Stroke = Stroke(0.35),
                 head: float = 2.5) -> list[Primitive]:
    """An arc about ``centre`` from angle ``start`` through ``sweep`` (radians, ccw positive), headed at its end.

    The head points along the chord of its own length, so it sits on the arc
    rather than on the tangent's overshoot.
    """
    end_angle = start + sweep
    back = end_angle - math.copysign(min(head / radius, abs(sweep) / 2), sweep)
    tail, tip = _on_circle(centre, radius, back), _on_circle(centre, radius, end_angle)
    direction = math.atan2(tip[1] - tail[1], tip[0] - tail[0])
    # The shaft stops 0.7 of the head short of the tip, inside the head, as a straight arrow's does. It is cut
    # round the arc, not by the points' distance from the tip: an arc of more than half a turn comes back near
    # its tip, and would lose its beginning.
    hidden = 2 * math.asin(min(1.0, 0.35 * head / radius))
    drawn = math.copysign(max(0.0, abs(sweep) - hidden), sweep)
    shaft = arc_points(centre, radius, start, drawn) if drawn else (_on_circle(centre, radius, start),)
    return [Polyline(shaft, stroke), arrowhead(tip, direction, head, stroke.colour)]


def arc_points(centre: Point, radius: float, start: float, sweep: float) -> tuple[Point, ...]:
    """Points along the arc about ``centre`` from angle ``start`` through ``sweep`` (radians), its ends included, at
    most 5° apart and at least eight steps: the shaft :func:`curved_arrow` draws, and the line the drawings weigh
    such an arc by before they draw it."""
    steps = max(8, int(abs(sweep) / math.radians(5)))
    return tuple(_on_circle(centre, radius, start + sweep * k / steps) for k in range(steps + 1))


def _on_circle(centre: Point, radius: float, angle: float) -> Point:
    return centre[0] + radius * math.cos(angle), centre[1] + radius * math.sin(angle)


def hatching(start: Point, end: Point, side: float = -1.0, pitch: float = 2.0, depth: float = 2.0,
             stroke: Stroke = THIN) -> list[Polyline]:
    """The ground line from ``start`` to ``end`` with hatch strokes on one side (side −1: right of start→end)."""
    length = math.dist(start, end)
    if length == 0:
        return []
    angle = math.atan2(end[1] - start[1], end[0] - start[0])
    lines = [Polyline((start, end), stroke)]
    count = max(1, int(length / pitch))
    for k in range(count + 1):
        x = k * length / count
        lines.append(Polyline(place(((x, 0.0), (x - depth, side * depth)), start, angle), stroke))
    return lines


def frame_pivot(at: Point, size: float = 5.0) -> list[Primitive]:
    """A fixed revolute: the pin on a small triangle standing on hatched ground."""
    half = 0.7 * size
    left, right = (at[0] - half, at[1] - size), (at[0] + half, at[1] - size)
    items: list[Primitive] = [Polyline((at, left, right), MAIN, closed=True, fill="white")]
    items.extend(hatching((left[0] - 1.0, left[1]), (right[0] + 1.0, right[1]), side=-1.0, pitch=1.5, depth=1.5))
    items.append(pin(at))
    return items


# The radius of a revolute joint's circle (mm).
PIN_RADIUS_MM = 1.3


def pin(at: Point, radius: float = PIN_RADIUS_MM) -> Circle:
    """A revolute joint."""
    return Circle(at, radius, MAIN, "white")


# A slider block's length along its slide and its height across it (mm).
BLOCK_LENGTH_MM = 10.0
BLOCK_HEIGHT_MM = 5.0


def slider_block(at: Point, angle: float, length: float = BLOCK_LENGTH_MM, height: float = BLOCK_HEIGHT_MM,
                 stroke: Stroke = MAIN) -> Polyline:
    """A slider block centred at ``at`` with its long side along ``angle``."""
    half_l, half_h = length / 2, height / 2
    corners = ((-half_l, -half_h), (half_l, -half_h), (half_l, half_h), (-half_l, half_h))
    return Polyline(place(corners, at, angle), stroke, closed=True, fill="white")


# A spring's zig-zag: this many waves, each as long as the lettering beside it is high and as wide, whatever the
# spring's length, as a scheme draws the symbol: spread over a long spring they flatten into a wavy line.
SPRING_WAVES = 5
# The straight lead at each end of a spring and before a cylinder's barrel reaches this far past its pin (mm).
LEAD_PAST_PIN_MM = 1.0


def spring(start: Point, end: Point, letter: float, stroke: Stroke = THIN) -> Polyline:
    """A spring from ``start`` to ``end`` (paper mm): a straight lead at each end and between them a zig-zag of
    :data:`SPRING_WAVES` waves, each ``letter`` long and ``letter`` wide; squeezed to fit between leads clear of
    the pins where the spring is shorter, a straight line where there is no room for it at all."""
    length = math.dist(start, end)
    least_lead = PIN_RADIUS_MM + LEAD_PAST_PIN_MM
    body = min(SPRING_WAVES * letter, length - 2 * least_lead)
    if body <= 0.0:
        return Polyline((start, end), stroke)
    lead = (length - body) / 2
    angle = math.atan2(end[1] - start[1], end[0] - start[0])
    waves = zigzag(lead, body, 2 * SPRING_WAVES, letter)
    return Polyline(place(((0.0, 0.0), (lead, 0.0), *waves, (lead + body, 0.0), (length, 0.0)), start, angle), stroke)


def zigzag(lead: float, body: float, halves: int, width: float) -> list[Point]:
    """A spring's zig-zag in its unit frame: ``halves`` half waves ``width`` wide over ``body`` along +x from
    ``lead``, without the straight ends (a spring drawn whole, or a piece of one cut off a group cut free)."""
    return [(lead + (k + 0.5) * body / halves, (width / 2) * (1 if k % 2 == 0 else -1)) for k in range(halves)]


def cylinder(start: Point, end: Point, barrel: float, piston: float, letter: float, stroke: Stroke = MAIN
             ) -> list[Polyline]:
    """A hydraulic cylinder pinned at ``start`` with its rod pinned at ``end`` (paper mm), as a kinematic scheme
    draws one: a short lead from ``start`` to the barrel's closed end, the barrel a narrow rectangle ``barrel`` mm
    long and as wide as the lettering is high, the piston across it ``piston`` mm from ``start`` (kept inside the
    barrel), and the rod from the piston to ``end``."""
    length = math.dist(start, end)
    lead = PIN_RADIUS_MM + LEAD_PAST_PIN_MM
    barrel = min(barrel, length - lead - PIN_RADIUS_MM)
    if barrel <= 0.0:
        return [Polyline((start, end), stroke)]
    piston = min(max(piston, lead + 0.1 * barrel), lead + 0.9 * barrel)
    half = 0.5 * letter
    angle = math.atan2(end[1] - start[1], end[0] - start[0])
    return [Polyline(place(((0.0, 0.0), (lead, 0.0)), start, angle), stroke),
            Polyline(place(((lead, -half), (lead + barrel, -half), (lead + barrel, half), (lead, half)), start, angle),
                     stroke, closed=True),
            Polyline(place(((piston, -0.8 * half), (piston, 0.8 * half)), start, angle), stroke),
            Polyline(place(((piston, 0.0), (length, 0.0)), start, angle), stroke)]


def dot_marker(at: Point, radius: float = 0.6, colour: str = "black") -> Circle:
    return Circle(at, radius, Stroke(0.1, colour), colour)


# Font size over cap height (DejaVu Sans and Noto Sans CJK both have caps about 0.72 em high).
FONT_SIZE_PER_CAP = 1.0 / 0.72
# Advance widths in em of DejaVu Sans, by the few classes that matter for a box that must hold the
# text as rendered: narrow punctuation and letters, wide letters, and the rest by case.
_NARROW = frozenset(" ,.:;'!|ijlfrtIJ()/-′‘’")
_WIDE = frozenset("mwMWжшщюЖШЩЮЫ=+ω")
_BOLD_WIDENING = 1.1


def is_wide(character: str) -> bool:
    """Whether ``character`` is of East Asian width (an ideograph, kana, a full-width form), set in a CJK font."""
    return unicodedata.east_asian_width(character) in ("W", "F")


def has_wide(text: str) -> bool:
    """Whether ``text`` has a character of East Asian width: the rule every backend picks its fonts by."""
    # ASCII has no such character, and each other character is asked about once: the note's Markdown, asked about
    # whole, is tens of thousands of characters of a few dozen kinds.
    return not text.isascii() and any(map(is_wide, set(text)))


def character_width(character: str) -> float:
    """The advance width of ``character`` in em by its class: a CJK ideograph fills its em square."""
    if is_wide(character):
        return 1.0
    if character in _NARROW:
        return 0.36
    if character in _WIDE:
        return 0.95
    return 0.64 if character.islower() or character.isdigit() else 0.76


def text_width(text: str, size: float, weight: str = "normal") -> float:
    """How wide a box must be to hold ``text`` at cap height ``size`` (mm): :func:`em_width` at that size."""
    return size * FONT_SIZE_PER_CAP * em_width(text, weight)


@functools.lru_cache(maxsize=16384)
def em_width(text: str, weight: str = "normal") -> float:
    """How wide ``text`` is in em of its font, generously: as DejaVu Sans sets it, or by the characters' classes
    (:func:`character_width`) where that is wider.

    The classes alone fall short of letters DejaVu sets wide (ф, ы, м, Ф, №, r, t, W, a minus, an em dash): a
    Russian scale box's "4 м/мм" ran over its cell's lines, and a label's box, which keeps the labels off one another
    and the lines, must hold its text too.  The classes stay where they are wider: narrow letters and subscripts
    are measured generously.  Remembered: a sheet measures its labels at every spot it tries.
    """
    widths = [_character_widths(character, weight) for character in text]
    return max(sum(by_class for by_class, _ in widths), sum(as_set for _, as_set in widths))


def set_width_em(text: str, weight: str = "normal") -> float:
    """How wide DejaVu Sans sets ``text`` (em): where a run of a line starts that follows it.  A character the font
    has no glyph for counts by its class."""
    return sum(_character_widths(character, weight)[1] for character in text)


@functools.lru_cache(maxsize=4096)
def _character_widths(character: str, weight: str) -> tuple[float, float]:
    """:func:`em_width`'s two widths of ``character``: by its class, and as DejaVu Sans sets it.

    Found once a character: a run measures a thousand texts of the same few dozen characters.
    """
    widening = _BOLD_WIDENING if weight == "bold" else 1.0
    by_class = widening * character_width(character)
    # A character DejaVu has no glyph for (a CJK ideograph, set in Noto Sans CJK) counts by its class.
    return by_class, _dejavu_advances("bold" if weight == "bold" else "normal")(character) or by_class


@functools.cache
def _dejavu_advances(weight: str):
    """A character's advance (em) in the DejaVu Sans that matplotlib ships, or None where the font has no glyph
    for it: the drawings' own font, read from the same file on every machine, so that what fits is no machine's."""
    from fontTools.ttLib import TTFont

    # Found, not imported: importing matplotlib costs a run that draws no plot a second.
    matplotlib = Path(importlib.util.find_spec("matplotlib").submodule_search_locations[0])
    name = "DejaVuSans-Bold.ttf" if weight == "bold" else "DejaVuSans.ttf"
    font = TTFont(matplotlib / "mpl-data" / "fonts" / "ttf" / name, lazy=True)
    # The glyphs named by their numbers: the cmap and hmtx tables key them by name, which fontTools reads from the
    # 'post' table (six thousand names a font, a third of reading it) unless a glyph order is set; the advances,
    # found by glyph number, are the same.
    font.setGlyphOrder([f"glyph{number}" for number in range(font["maxp"].numGlyphs)])
    glyphs, metrics, units = font.getBestCmap(), font["hmtx"], font["head"].unitsPerEm

    def advance(character: str) -> float | None:
        glyph = None if is_wide(character) else glyphs.get(ord(character))
        return None if glyph is None else metrics[glyph][0] / units

    # The font kept with its advances: descent_em reads its outlines from the file read here, not read again.
    advance.font = font
    return advance


@functools.lru_cache(maxsize=1024)
def descent_em(text: str) -> float:
    """How far ``text``'s lowest glyph reaches under the baseline in DejaVu Sans (em; 0 for none that does): how low
    an index can be set and stay in its text's box."""
    advance = _dejavu_advances("normal")
    font = advance.font
    glyphs, outlines, units = font.getBestCmap(), font["glyf"], font["head"].unitsPerEm
    lowest = 0.0
    for character in set(text):
        glyph = None if is_wide(character) else glyphs.get(ord(character))
        if glyph is not None and getattr(outlines[glyph], "numberOfContours", 0):
            lowest = max(lowest, -outlines[glyph].yMin / units)
    return lowest


def text_extent(text: Text) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) of a text as rendered: its width estimated, descenders and accents included."""
    width = text_width(text.text, text.size, text.weight)
    x0 = text.at[0] + {"start": 0.0, "middle": -width / 2, "end": -width}[text.anchor]
    extent = (x0, text.at[1] - 0.3 * text.size, x0 + width, text.at[1] + 1.15 * text.size)
    if not text.rotation:
        return extent
    turn = complex(math.cos(math.radians(text.rotation)), math.sin(math.radians(text.rotation)))
    about = to_complex(text.at)
    corners = [about + (complex(x, y) - about) * turn for x in extent[0::2] for y in extent[1::2]]
    return (min(c.real for c in corners), min(c.imag for c in corners),
            max(c.real for c in corners), max(c.imag for c in corners))


def text_span(text: Text) -> float:
    """How wide a text's box is on the paper (mm)."""
    x0, _, x1, _ = text_extent(text)
    return x1 - x0


def to_complex(point: Point) -> complex:
    """A paper point (x, y) as x + iy, for arithmetic on it."""
    return complex(point[0], point[1])


def to_xy(value: complex) -> Point:
    """x + iy as the paper point (x, y)."""
    return (value.real, value.imag)


def bounds(layers: Sequence[Layer]) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) of every primitive, text by its estimated extent."""
    # Layer by layer, each layer's bounds remembered (:func:`_measured`): the least of the layers' least values is
    # the least of all, the first of equal ones as bounds_of would find it, and a sheet measures the same layers,
    # and the same layers moved, thousands of times while it packs.
    boxes = [box for layer in layers if (box := _measured(layer)[1]) is not None]
    if not boxes:
        return (0.0, 0.0, 1.0, 1.0)
    return (min(box[0] for box in boxes), min(box[1] for box in boxes),
            max(box[2] for box in boxes), max(box[3] for box in boxes))


Rect = tuple[float, float, float, float]
# The attribute a layer's measure is remembered in: a Layer is frozen, and its items (a tuple of frozen primitives)
# never change, so the measure of one layer object holds as long as the object does.
_MEASURE = "_measure"


def _measured(layer: Layer) -> tuple[Rect | None, Rect | None]:
    """The bounds of ``layer``'s polylines and arrows, and of all its items (None for none): the first shifts
    exactly with the layer (:func:`moved_layers`), since adding dx to every point keeps their order."""
    known = layer.__dict__.get(_MEASURE)
    if known is None:
        points = [item for item in layer.items if isinstance(item, (Polyline, Arrow))]
        known = (_bounds_or_none(points), _bounds_or_none(layer.items))
        # A list of items could change under the layer: only a tuple's measure is kept.
        if type(layer.items) is tuple:
            object.__setattr__(layer, _MEASURE, known)
    return known


def _remember(layer: Layer, points: Rect | None, others: Sequence[Primitive]) -> Layer:
    """``layer`` with its measure kept: ``points`` the bounds of its polylines and arrows, already known, and
    ``others`` its texts and circles, measured here."""
    rest = _bounds_or_none(others)
    if points is None or rest is None:
        whole = points or rest
    else:
        whole = (min(points[0], rest[0]), min(points[1], rest[1]), max(points[2], rest[2]), max(points[3], rest[3]))
    object.__setattr__(layer, _MEASURE, (points, whole))
    return layer


def renamed_layer(layer: Layer, name: str, items: Sequence[Primitive]) -> Layer:
    """``layer`` named ``name`` with ``items``, which are its own items renamed (an arrow's key), not moved: its
    measure, if known, is theirs too."""
    named = Layer(name, tuple(items))
    known = layer.__dict__.get(_MEASURE)
    if known is not None:
        object.__setattr__(named, _MEASURE, known)
    return named


def bounds_of(items: Iterable[Primitive]) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) of ``items``; a unit square for none."""
    return _bounds_or_none(items) or (0.0, 0.0, 1.0, 1.0)


def _bounds_or_none(items: Iterable[Primitive]) -> Rect | None:
    """(xmin, ymin, xmax, ymax) of ``items``; None where they have no point (no items, or empty polylines)."""
    # Every item's points and corners in one list, then their least and greatest: a sheet is measured often, and its
    # curves have hundreds of points each, whose bounds one at a time took a call of zip, min and max an item.
    corners: list[Point] = []
    for item in items:
        if isinstance(item, Polyline):
            corners += item.points
        elif isinstance(item, Arrow):
            corners += (item.start, item.end)
        elif isinstance(item, Circle):
            (x, y), radius = item.centre, item.radius
            corners += ((x - radius, y - radius), (x + radius, y + radius))
        else:
            x0, y0, x1, y1 = text_extent(item)
            corners += ((x0, y0), (x1, y1))
    if not corners:
        return None
    xs, ys = zip(*corners, strict=True)
    return (min(xs), min(ys), max(xs), max(ys))


def moved(item: Primitive, dx: float, dy: float) -> Primitive:
    """``item`` shifted by (dx, dy) mm."""
    def shift(p: Point) -> Point:
        return (p[0] + dx, p[1] + dy)

    # Made by their constructors, not dataclasses.replace, which takes several times as long: a sheet moves its
    # drawings' items hundreds of thousands of times while it packs them.
    if isinstance(item, Polyline):
        # Its points shifted in place, not through shift(): a diagram's curves have hundreds each.
        return Polyline(tuple([(x + dx, y + dy) for x, y in item.points]), item.stroke, item.closed, item.fill)
    if isinstance(item, Arrow):
        return Arrow(shift(item.start), shift(item.end), item.stroke, item.head, item.key)
    if isinstance(item, Circle):
        return Circle(shift(item.centre), item.radius, item.stroke, item.fill)
    return Text(shift(item.at), item.text, item.size, item.anchor, item.colour, item.weight, item.rotation, item.runs)


# A point between two digits is a decimal point: no other text of a drawing puts one there.
_DECIMAL_POINT = re.compile(r"(?<=\d)\.(?=\d)")
# The title block and ESKD's графа 26 hold what the user wrote (a designation ТММ.01.02, a date 21.11.2026): never
# changed.
USER_LAYERS = ("title-block", "sheet-designation")


def decimal_marked(text: str, mark: str) -> str:
    """``text`` with every number's decimal point written ``mark``: what a drawing's words become in its language, for
    the note that gives the same words beside it."""
    return _DECIMAL_POINT.sub(mark, text)


def with_decimal_mark(layers: Sequence[Layer], mark: str, kept: Iterable[str] = ()) -> list[Layer]:
    """``layers`` with every number's decimal point written ``mark`` (``","`` in Russian, as ESKD writes it).

    The title block and the strings ``kept`` (the scene's title, quoted in a
    drawing's heading) are the user's text and stay as written.
    """
    if mark == ".":
        return list(layers)
    kept = tuple(text for text in kept if text)

    def marked(text: str) -> str:
        for quoted in kept:
            if quoted in text:
                return quoted.join(marked(part) for part in text.split(quoted))
        return decimal_marked(text, mark)

    return [layer if layer.name in USER_LAYERS else
            Layer(layer.name, tuple(replace(item, text=marked(item.text)) if isinstance(item, Text) else item
                                    for item in layer.items))
            for layer in layers]


def in_language(layers: Sequence[Layer], locale: str, own_words: Iterable[str] = ()) -> list[Layer]:
    """``layers`` lettered as they are written: with the decimal mark of ``locale`` and their symbols' indices set
    (:mod:`graphplan.render.indices`); the scene's ``own_words`` (``Scene.own_words``) as the user wrote them."""
    from ..locale import strings
    from .indices import with_indices

    own_words = tuple(own_words)
    return with_indices(with_decimal_mark(layers, strings(locale)["decimal_mark"], own_words), own_words)


def moved_layers(layers: Sequence[Layer], dx: float, dy: float) -> list[Layer]:
    """``layers`` shifted by (dx, dy) mm."""
    return [_moved_layer(layer, dx, dy) for layer in layers]


def _moved_layer(layer: Layer, dx: float, dy: float) -> Layer:
    shifted = Layer(layer.name, tuple(moved(item, dx, dy) for item in layer.items))
    known = layer.__dict__.get(_MEASURE)
    if known is None:
        return shifted
    # The polylines' and arrows' bounds shifted, bit for bit those of their shifted points (rounding keeps the order
    # of sums with one dx); a text's and a circle's corners are sums of two terms besides, and are measured again.
    points = known[0] and (known[0][0] + dx, known[0][1] + dy, known[0][2] + dx, known[0][3] + dy)
    return _remember(shifted, points, [item for item in shifted.items if isinstance(item, (Text, Circle))])


# Characters of a name that an id spells out: the textbook's τ and primes, and the brackets and signs of a moment's
# name, as the force drawings' ids have always written them.
_SPELLED_IN_IDS = {"τ": "tau", "′": "-1", "″": "-2", "·": "-", "(": "-", ")": "", ",": "-"}
# Beyond ASCII, the code points XML 1.0 (fifth edition) allows in a name (NameStartChar and NameChar): an id keeps
# a letter of these as it is.
_XML_NAME_RANGES = ((0xC0, 0xD6), (0xD8, 0xF6), (0xF8, 0x37D), (0x37F, 0x1FFF), (0x200C, 0x200D), (0x203F, 0x2040),
                    (0x2070, 0x218F), (0x2C00, 0x2FEF), (0x3001, 0xD7FF), (0xF900, 0xFDCF), (0xFDF0, 0xFFFD),
                    (0x10000, 0xEFFFF))


def svg_id(*parts: str) -> str:
    """An SVG id from the names a drawing shows (points, plan letters, forces), joined by ``-``:
    ``velocity-p-b``, ``polygon-II-3-4-R23tau``.

    A letter or digit of any script stays as it is, since XML ids allow
    them: the Cyrillic А and В of two points' names give two ids, where
    both once came out ``_``.  τ and the primes are spelled out; any other
    character is written as its code point (``_2212_`` for a minus), so
    that two names never give one id.
    """
    return "-".join("".join(_id_characters(c) for c in part) for part in parts)


def _id_characters(c: str) -> str:
    if c in _SPELLED_IN_IDS:
        return _SPELLED_IN_IDS[c]
    if re.fullmatch(r"[A-Za-z0-9_.\-]", c) or c.isalnum() and any(low <= ord(c) <= high
                                                                for low, high in _XML_NAME_RANGES):
        return c
    return f"_{ord(c):x}_"


def prefixed(layers: Sequence[Layer], prefix: str) -> list[Layer]:
    """Layers and arrow keys named ``prefix-...``: the ids of two drawings in one SVG never clash."""
    def named(value: str) -> str:
        return f"{prefix}-{value}" if value else prefix

    return [renamed_layer(layer, named(layer.name), [replace(item, key=named(item.key))
                                                     if isinstance(item, Arrow) and item.key else item
                                                     for item in layer.items]) for layer in layers]
