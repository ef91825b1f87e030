"""The texts of an SVG sheet as the drawings set them, and the box each takes, for the tests that check lettering
stands clear of other lettering and inside the frame."""

from __future__ import annotations

import re

from graphplan.render.primitives import FONT_SIZE_PER_CAP, text_width


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
