"""How graphplan's matplotlib figures are set up and written: fonts for every script, reproducible SVG."""

from __future__ import annotations

import io
from typing import Any

# Latin and Cyrillic first, then CJK: matplotlib falls back along the list glyph by glyph.
_FONTS = ("DejaVu Sans", "Noto Sans CJK SC", "Noto Sans CJK JP", "WenQuanYi Zen Hei", "Droid Sans Fallback")


def font_families() -> list[str]:
    """The fonts of :data:`_FONTS` this machine has (asking for a missing one floods the log)."""
    from matplotlib import font_manager

    manager = font_manager.fontManager
    installed = {font.name for font in manager.ttflist}
    if not installed.intersection(_FONTS[1:]):
        # matplotlib's font cache is built once and misses fonts installed after it (CJK fonts put in
        # by apt after the first plot): the system's own CJK files are added to it here.
        for path in font_manager.findSystemFonts():
            if any(mark in path for mark in ("CJK", "wqy", "DroidSansFallback")):
                try:
                    manager.addfont(path)
                except (OSError, RuntimeError, ValueError):
                    continue
        installed = {font.name for font in manager.ttflist}
    return [name for name in _FONTS if name in installed] or ["sans-serif"]


def settings() -> dict[str, Any]:
    """matplotlib settings for ``rc_context``: a fixed hash salt, and text drawn as paths in any script."""
    return {"svg.hashsalt": "graphplan", "font.family": font_families(), "svg.fonttype": "path"}


def svg_text(figure) -> str:
    """``figure`` as SVG without a date (the same scene gives the same file), and closed."""
    from matplotlib import pyplot

    buffer = io.StringIO()
    figure.savefig(buffer, format="svg", metadata={"Date": None})
    pyplot.close(figure)
    return buffer.getvalue()
