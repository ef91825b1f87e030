"""The heights of the drawings' lettering: the standard series of GOST 2.304 and ISO 3098, and the height each kind
of lettering on a sheet takes from it.

A height is the lettering's cap height on the printed sheet (mm), what a
:class:`~graphplan.render.primitives.Text` and a label's
:class:`~graphplan.render.labels.Anchor` are given; the SVG writes it as a
font size :data:`~graphplan.render.primitives.FONT_SIZE_PER_CAP` times as
large.  Every drawing letters from here, as a draftsman letters a sheet
from the one series: a sheet's letters, names, numbers and captions stand
at the few heights it has, each kind at one of them throughout.  Lettering
set smaller to fit its box (a title block's field) steps down the series
(:func:`at_most`); only under its smallest height, which nothing is set
below but a field too long for its box, does it shrink in between.
"""

from __future__ import annotations

# GOST 2.304-81 and ISO 3098-0: each height √2 times the one before.
SERIES = (1.8, 2.5, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0)
# Printed smaller than this, lettering is hard to read.
SMALLEST = SERIES[0]

# On the drawings.
# A point's letter: on the mechanism and its plans, the groups cut free, the lever.
LETTER = 3.5
# A load's or a vector's name (R23, Fu3, mu2·ru2) and a link's ω and ε on the mechanism.
NAME = 3.5
# An arm's name (h3, hu2) and a correction's angle θ: the next height down from the names they go with.
ARM_NAME = 2.5
# A point's letter on the plan of positions, among the outlines of all its positions: a size under the plans'.
POSITIONS_LETTER = 2.5
# A position's number round the crank's circle on the plan of positions (36 of them where it draws many): a size
# under the plans' letters, as the diagrams' numbers are.
POSITION_NUMBER = 2.5
# A dimension's value or letter (GOST 2.307): a stroke's H, a swing's ψ, a diagram's pole distance H.
DIMENSION = 3.5
# A drawing's caption (its name, in bold, and its scale), and a diagram's heading.
CAPTION = 5.0
# The captions where the usual do not fit a small sheet: the next height down.
SMALL_CAPTION = 3.5
# A sheet's or a drawing's title, over its drawings.
TITLE = 7.0
# A diagram's scales, its legend and the lines of words under it.
SCALE = 3.5
# The name of a diagram's axis (φ, s, mm), and a diagram's words beside its curves (ψmax = …, a level's value).
AXIS_LABEL = 3.5
# The numbers along a diagram's axes and under its positions' ticks, and the ticks of ωmax and ωmin named.
AXIS_NUMBER = 2.5
# A position's number by its point on a diagram's curve (the energy–mass diagram's loop): a size under the axes'
# numbers, so that it reads as naming its point and not as an axis's numbering.
CURVE_NUMBER = 1.8

# In the title block (the sizes it sets a field at where the field holds it; smaller, down the series, where not).
# A field's printed name (Изм., Разраб., 比例); 1.8 mm where its box holds no more, a row of them at one height.
BLOCK_LABEL = 2.5
# ISO 7200's field names, small in their fields' top left corners.
BLOCK_CORNER_LABEL = SMALLEST
# What the block says: the scale, the organisation, a name, the sheet's number.
BLOCK_VALUE = 3.5
# The drawing's name and designation: the block's largest lettering.
BLOCK_NAME = 5.0
BLOCK_DESIGNATION = 5.0
# The kind of drawing under its name (Kinematic analysis), and ISO 7200's fields' values.
BLOCK_KIND = 3.5


def at_most(height: float) -> float:
    """The largest height of the series not above ``height``: what lettering set smaller to fit is set at.  Under
    the smallest, ``height`` itself (what is set there is told as too small where it matters)."""
    return max((size for size in SERIES if size <= height + 1e-9), default=height)


def index_height(height: float) -> float:
    """The height a symbol's index (R₁₂'s 12) is lettered at beside a symbol lettered at ``height``: the next height
    of the series down, as GOST 2.304 letters indices; at the smallest height, that height (none is smaller)."""
    return max((size for size in SERIES if size < height - 1e-9), default=height)


def larger(height: float) -> float:
    """The next height of the series above ``height``; past the largest, √2 times it."""
    return next((size for size in SERIES if size > height + 1e-9), height * 2 ** 0.5)


__all__ = [
    "ARM_NAME",
    "AXIS_LABEL",
    "AXIS_NUMBER",
    "BLOCK_CORNER_LABEL",
    "BLOCK_DESIGNATION",
    "BLOCK_KIND",
    "BLOCK_LABEL",
    "BLOCK_NAME",
    "BLOCK_VALUE",
    "CAPTION",
    "CURVE_NUMBER",
    "DIMENSION",
    "LETTER",
    "NAME",
    "POSITIONS_LETTER",
    "POSITION_NUMBER",
    "SCALE",
    "SERIES",
    "SMALLEST",
    "SMALL_CAPTION",
    "TITLE",
    "at_most",
    "index_height",
    "larger",
]
