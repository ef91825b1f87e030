"""Lines of a drawing as tests read them: a line broken under the words it crosses (a tangent under a Je number, as
a draftsman breaks it) is drawn in pieces, which are one line to the reader."""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Collection, Iterable

import shapely
from shapely.geometry import LineString
from sheet_texts import flat

SVG = "{http://www.w3.org/2000/svg}"


def layer(root: ET.Element, name: str) -> ET.Element:
    """The group of an SVG's root with the id ``name`` (a drawing's layer: ``mechanism-senses``)."""
    return next(group for group in root if group.get("id") == name)


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


def stroked_shapes(root: ET.Element, skipped: Collection[str] = ("leaders",)) -> list[shapely.Geometry]:
    """Every stroked path and circle of an SVG drawing outside the groups whose ids are ``skipped`` (the leaders: a
    label's own leader ends at it), each widened by half its stroke, as the ink a label must keep clear of."""
    shapes = []
    for group in root.iter(f"{SVG}g"):
        if group.get("id") in skipped:
            continue
        for item in group:
            width = float(item.get("stroke-width", "0"))
            if item.get("stroke", "none") == "none":
                continue
            if item.tag == f"{SVG}path":
                if len(path_points(item)) >= 2:
                    shapes.append(stroked_path(item))
            elif item.tag == f"{SVG}circle":
                centre = shapely.Point(float(item.get("cx")), float(item.get("cy")))
                shapes.append(centre.buffer(float(item.get("r"))).exterior.buffer(width / 2))
    return shapes


def path_points(item: ET.Element) -> list[tuple[float, float]]:
    """The points an SVG path runs through, its first again at the end where it closes (``Z``)."""
    numbers = [float(value) for value in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", item.get("d"))]
    points = list(zip(numbers[0::2], numbers[1::2]))
    if item.get("d").rstrip().upper().endswith("Z"):
        points.append(points[0])
    return points


def stroked_path(item: ET.Element) -> shapely.Geometry:
    """An SVG path's ink: its line widened by half its stroke."""
    return shapely.LineString(path_points(item)).buffer(float(item.get("stroke-width", "0")) / 2)


def caption_text(svg: str, element: str) -> str:
    """The words of the caption of the drawing's group ``element`` (``II(3,4)-caption``), its lines joined by spaces,
    each line whole (a symbol's index is set as a run of its own)."""
    return " ".join(re.findall(r">([^<]*)</text>", re.search(f'id="{element}-caption">(.*?)</g>', flat(svg)).group(1)))


def arrow_length(svg: str, element: str) -> float:
    """The length (mm) of the arrow drawn as the SVG's group ``element``, from its tail to its head's tip, as a ruler
    measures it off the paper."""
    group = re.search(f'<g id="{element}">(.*?)</g>', svg).group(1)
    (tail, *_), head = (re.findall(r"[ML]([-0-9.]+),([-0-9.]+)", path) for path in re.findall(r'd="([^"]+)"', group))
    return math.dist(tuple(map(float, tail)), tuple(map(float, head[0])))
