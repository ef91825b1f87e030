"""Lines of a drawing as tests read them: a line broken under the words it crosses (a tangent under a Je number, as
a draftsman breaks it) is drawn in pieces, which are one line to the reader."""

from __future__ import annotations

from collections.abc import Iterable

from shapely.geometry import LineString


def whole_lines(pieces: Iterable[LineString]) -> list[LineString]:
    """``pieces`` (two-point segments) joined where they lie on one line, each line from its first end to its last."""
    whole: list[LineString] = []
    for piece in pieces:
        k = next((k for k, line in enumerate(whole) if _collinear(line, piece)), None)
        if k is None:
            whole.append(piece)
        else:
            ends = sorted([*whole[k].coords, *piece.coords])
            whole[k] = LineString([ends[0], ends[-1]])
    return whole


def _collinear(one: LineString, other: LineString) -> bool:
    (x0, y0), (x1, y1) = one.coords
    return all(abs((x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)) < 1e-3 * one.length for x, y in other.coords)
