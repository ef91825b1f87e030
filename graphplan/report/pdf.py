"""The explanatory note as a PDF: its HTML typeset by WeasyPrint.

WeasyPrint lays out HTML and CSS (tables, sub- and superscripts, page
breaks) and embeds the fonts the note's stylesheet names, found by
fontconfig: DejaVu Sans for Latin, Greek and Cyrillic, Noto Sans CJK for
Chinese, as for the drawings' PNG and PDF.  It needs the Pango library
(Debian: ``libpango-1.0-0``); it is imported only when a PDF is asked for.

Determinism: the fonts are embedded as subsets, and fontTools stamps a
subset with the time it was made unless ``SOURCE_DATE_EPOCH`` says
otherwise; unless the caller has set it, the note fixes it to 0 while it
is typeset, so that the same HTML gives the same PDF bytes.
"""

from __future__ import annotations

import base64
import contextlib
import os
import re
from collections.abc import Iterator, Mapping

from ..errors import OutputError

# A figure's picture, named by its file beside the note.
_PICTURE = re.compile(r'<img src="([^"]+)"')


def note_pdf(html: str, pictures: Mapping[str, str] | None = None) -> bytes:
    """The PDF of the note's HTML (:func:`graphplan.report.note.note_html`), pages A4 as its stylesheet sets,
    with the drawings its figures name (``plan_2.svg``) taken from ``pictures`` (file name → SVG text)."""
    try:
        import weasyprint
    except (ImportError, OSError) as error:  # OSError: the Pango library is missing
        raise OutputError(f"note.pdf: the PDF of the note needs WeasyPrint and the Pango library ({error}); "
                          "install them (pip install weasyprint; Debian: apt install libpango-1.0-0) "
                          "or leave pdf out of --format") from error
    pictures = pictures or {}

    # The pictures go in as data: the folder they are written to is written after the PDF.
    def inlined(found: re.Match) -> str:
        svg = pictures.get(found.group(1))
        if svg is None:
            return found.group(0)
        return f'<img src="data:image/svg+xml;base64,{base64.b64encode(svg.encode("utf-8")).decode("ascii")}"'

    with _fixed_font_dates():
        return weasyprint.HTML(string=_PICTURE.sub(inlined, html)).write_pdf()


@contextlib.contextmanager
def _fixed_font_dates() -> Iterator[None]:
    if "SOURCE_DATE_EPOCH" in os.environ:
        yield
        return
    os.environ["SOURCE_DATE_EPOCH"] = "0"
    try:
        yield
    finally:
        del os.environ["SOURCE_DATE_EPOCH"]
