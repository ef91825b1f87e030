"""Sheet formats and where a drawing may stand on them: the frame, the title block and the drawing area.

The geometry only, so that a drawing can ask whether it fits a sheet (the
plan of positions choosing its μl, the diagrams their axis) before the
sheets are packed (:mod:`graphplan.render.packing`).  Formats are those of
ISO 216, GOST 2.301 and GB/T 14689; the frame's margins are those of the
locale's standard, the title block stands in the frame's lower right corner.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import SceneError
from .title_block import CORNER_SIZES, SIZES

Rect = tuple[float, float, float, float]

# Sheet formats, landscape (mm): ISO 216, GOST 2.301, GB/T 14689.
FORMATS: dict[str, tuple[float, float]] = {"A1": (841.0, 594.0), "A2": (594.0, 420.0), "A3": (420.0, 297.0),
                                           "A4": (297.0, 210.0)}
SHEET_NAMES = (*FORMATS, "none")
BIGGER = {"A4": "A3", "A3": "A2", "A2": "A1"}
# The formats a sheet of the set may stand upright on.
UPRIGHT_FORMATS = ("A4", "A3")
# Space between a drawing and the frame or the title block (mm).
PADDING_MM = 8.0


def check_sheet(sheet: str) -> None:
    """Refuse a sheet format that is none of :data:`SHEET_NAMES`, naming the scene's key."""
    if sheet not in SHEET_NAMES:
        raise SceneError("drawing.sheet", f"must be one of {', '.join(SHEET_NAMES)}", sheet)


@dataclass(frozen=True)
class PageGeometry:
    """An empty sheet: its size, the inner frame, the title block and the area drawings may take (mm, y up);
    ``corner`` the box in the frame's top left corner that no drawing may take either (ESKD's графа 26)."""

    size: tuple[float, float]
    frame: Rect
    block: Rect
    area: Rect
    corner: Rect | None = None

    def rooms(self) -> tuple[tuple[float, float], ...]:
        """The largest free rectangles (width, height): above the title block, and left of it; with a corner
        box, each of those below it or right of it."""
        ax0, ay0, ax1, ay1 = self.area
        below_top = ay1 if self.corner is None else self.corner[1] - PADDING_MM
        if self.corner is None:
            return (ax1 - ax0, ay1 - (self.block[3] + PADDING_MM)), (self.block[0] - PADDING_MM - ax0, ay1 - ay0)
        right_of = self.corner[2] + PADDING_MM
        return ((ax1 - ax0, below_top - (self.block[3] + PADDING_MM)),
                (ax1 - right_of, ay1 - (self.block[3] + PADDING_MM)),
                (self.block[0] - PADDING_MM - ax0, below_top - ay0),
                (self.block[0] - PADDING_MM - right_of, ay1 - ay0))

    def holds(self, width: float, height: float) -> bool:
        """Whether a drawing of this size fits on the empty sheet, clear of the title block."""
        eps = 1e-6
        return any(width <= room_width + eps and height <= room_height + eps
                   for room_width, room_height in self.rooms())


def margins(form: str, sheet: str) -> tuple[float, float, float, float]:
    """The frame's distance from the sheet's edges (left, bottom, right, top, mm) in ``form``'s standard."""
    if form == "eskd":  # GOST 2.104: 20 mm for binding, 5 mm elsewhere
        return (20.0, 5.0, 5.0, 5.0)
    if form == "gb":  # GB/T 14689, with binding: a = 25; c = 10 on A0..A2, 5 on A3, A4
        c = 10.0 if sheet in ("A1", "A2") else 5.0
        return (25.0, c, c, c)
    return (20.0, 10.0, 10.0, 10.0)  # ISO 5457


def page_geometry(sheet: str, form: str, portrait: bool = False) -> PageGeometry:
    """The empty ``sheet`` (a format name) in ``form``'s standard, turned upright when ``portrait``."""
    width, height = FORMATS[sheet]
    if portrait:
        width, height = height, width
    left, bottom, right, top = margins(form, sheet)
    frame = (left, bottom, width - right, height - top)
    block_width, block_height = SIZES[form]
    block = (frame[2] - block_width, frame[1], frame[2], frame[1] + block_height)
    area = (frame[0] + PADDING_MM, frame[1] + PADDING_MM, frame[2] - PADDING_MM, frame[3] - PADDING_MM)
    corner = None
    if form in CORNER_SIZES:
        corner_width, corner_height = CORNER_SIZES[form]
        if portrait and sheet != "A4":
            # GOST 2.104: a sheet bigger than A4 stood upright has its title block along its short side, and
            # графа 26 down the frame's left side instead of along its top.
            corner_width, corner_height = corner_height, corner_width
        corner = (frame[0], frame[3] - corner_height, frame[0] + corner_width, frame[3])
    return PageGeometry((width, height), frame, block, area, corner)


def orientations(sheet: str) -> tuple[bool, ...]:
    """The ways the format may stand (``portrait`` values), across first: GOST 2.301, GB/T 14689 and ISO 5457
    allow every format either way round; an A4 is turned as its drawings need, an A3 stood upright only for a
    drawing that no A3 across holds (:func:`graphplan.render.packing.pack`)."""
    return (False, True) if sheet in UPRIGHT_FORMATS else (False,)


def usual_orientations(sheet: str) -> tuple[bool, ...]:
    """The ways the drawings are laid out for (their size, a force sheet's parts, the diagrams' length): an A4 either
    way, a bigger sheet across; it stands upright only for a drawing at the scene's scale that it holds no other
    way, so that a set that fits across is laid out as it always was."""
    return orientations(sheet) if sheet == "A4" else (False,)


def holds(sheet: str, form: str, width: float, height: float, either_way: bool = False) -> bool:
    """Whether a drawing of ``width`` × ``height`` mm fits on an empty ``sheet`` the ways it is laid out for, or
    ``either_way`` it may stand (whether the scene's scale is refused)."""
    turns = orientations(sheet) if either_way else usual_orientations(sheet)
    return any(page_geometry(sheet, form, portrait).holds(width, height) for portrait in turns)
