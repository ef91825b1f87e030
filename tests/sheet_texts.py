"""The texts of an SVG sheet as the drawings set them, and the box each takes, for the tests that check lettering
stands clear of other lettering and inside the frame."""

from __future__ import annotations

import re

from graphplan.render.primitives import FONT_SIZE_PER_CAP, text_width

_RUN_TAG = re.compile(r"</?tspan[^>]*>")


def flat(source: str) -> str:
    """An SVG's ``source`` with each text's runs joined, as a reader reads its words: a symbol's index (R₁₂, written
    ``R<tspan ...>12</tspan>``) and a mixed line's scripts run on, ``<text ...>R12</text>``."""
    return _RUN_TAG.sub("", source)


def texts(source: str) -> list[tuple[float, float, float, str, str]]:
    """(x, y, font size, anchor, text) of each text of an SVG's ``source``, its runs in a script's font joined."""
    found = []
    for attributes, body in re.findall(r"<text([^>]*)>(.*?)</text>", source):
        values = dict(re.findall(r'([\w-]+)="([^"]*)"', attributes))
        text = re.sub(r"<[^>]+>", "", body).replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">")
        found.append((float(values["x"]), float(values["y"]), float(values["font-size"]),
                      values.get("text-anchor", "start"), text))
    return found


def box(x: float, y: float, font_size: float, anchor: str, text: str) -> tuple[float, float, float, float]:
    """The box a text takes on the sheet (mm), as wide as the drawings measure a text, a cap height tall."""
    cap = font_size / FONT_SIZE_PER_CAP
    width = text_width(text, cap)
    left = {"start": x, "middle": x - width / 2, "end": x - width}[anchor]
    return left, y - cap, left + width, y


def layer_letter_boxes(root, layer_id: str, svg: str = "{http://www.w3.org/2000/svg}") -> list[tuple[str, object]]:
    """(text, box) of every text of the SVG layer ``layer_id`` (an ElementTree group), in the SVG's y-down
    millimetres: as wide as the drawings measure it at its font size and weight, from its descenders to its accents
    (0.3 and 1.15 cap heights about its baseline), for the tests that keep letters off a line's ink."""
    import shapely

    boxes = []
    for layer in root:
        if layer.get("id") != layer_id:
            continue
        for text in layer.findall(f"{svg}text"):
            words = "".join(text.itertext())
            cap = float(text.get("font-size")) / FONT_SIZE_PER_CAP
            width = text_width(words, cap, text.get("font-weight", "normal"))
            x, baseline = float(text.get("x")), float(text.get("y"))
            left = x - {"start": 0.0, "middle": width / 2, "end": width}[text.get("text-anchor", "start")]
            boxes.append((words, shapely.box(left, baseline - 1.15 * cap, left + width, baseline + 0.3 * cap)))
    return boxes


def set_off_a_line(letter, start: tuple[float, float], end: tuple[float, float], off_mm: float) -> None:
    """Move the SVG text element ``letter`` so that the nearest corner of its box (:func:`layer_letter_boxes`') stands
    ``off_mm`` off the middle of the line from ``start`` to ``end``, square to it, the box reaching away from the line:
    for the tests that check their own check of a letter on a line's ink."""
    (x0, y0), (x1, y1) = start, end
    length = ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5
    normal = ((y0 - y1) / length, (x1 - x0) / length)
    corner = ((x0 + x1) / 2 + off_mm * normal[0], (y0 + y1) / 2 + off_mm * normal[1])
    cap = float(letter.get("font-size")) / FONT_SIZE_PER_CAP
    width = text_width("".join(letter.itertext()), cap, letter.get("font-weight", "normal"))
    letter.set("text-anchor", "start")
    letter.set("x", f"{corner[0] if normal[0] >= 0 else corner[0] - width:.4f}")
    letter.set("y", f"{corner[1] + 1.15 * cap if normal[1] >= 0 else corner[1] - 0.3 * cap:.4f}")
