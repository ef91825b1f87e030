"""A line that mixes Chinese with Latin, Greek or Cyrillic, set in two fonts: its runs of each and its width.

Set wholly in Noto Sans CJK, such a line drew its middle dot, times sign and
parallel sign full-width (``N・m``).  It is set run by run instead: the wide
characters in Noto Sans CJK, the rest in DejaVu Sans, as every other line of
a drawing.  cairosvg anchors each run of a line on its own (a centred line's
runs were drawn over one another), so a mixed line is placed from its start
by its width: its Chinese measured in the font fontconfig gives cairo (fontTools
reads its advance widths, which cairo's text API sets without kerning), the rest
in the DejaVu Sans every text of the drawings is measured in.  Without
fontconfig or the CJK font the width is unknown and the line is set in one font.
"""

from __future__ import annotations

import functools
import itertools
import shutil

from .primitives import is_wide, set_width_em

LATIN_FONT = "DejaVu Sans"
CJK_FONT = "Noto Sans CJK SC"


def script_runs(text: str) -> tuple[tuple[str, bool], ...]:
    """``text`` cut into its runs of wide (CJK) characters and of the rest, each with whether it is wide."""
    return tuple(("".join(run), wide) for wide, run in itertools.groupby(text, key=is_wide))


def is_mixed(runs: tuple[tuple[str, bool], ...]) -> bool:
    """Whether the runs hold both CJK and some other character that is not a space."""
    return any(wide for _, wide in runs) and any(not wide and run.strip() for run, wide in runs)


def width_em(runs: tuple[tuple[str, bool], ...], weight: str) -> float | None:
    """How wide the runs are set, each in its font, in em; None when the CJK font cannot be found or read.  The
    other runs are measured as every text of the drawings is, in the DejaVu Sans matplotlib ships
    (:func:`~graphplan.render.primitives.set_width_em`): no subprocess asked for a line without Chinese."""
    total = 0.0
    for run, wide in runs:
        if not wide:
            total += set_width_em(run, weight)
            continue
        advances = _advances(CJK_FONT, weight)
        if advances is None:
            return None
        total += sum(advances(character) for character in run)
    return total


@functools.cache
def _advances(family: str, weight: str):
    """A character's advance width (em) in the font fontconfig matches to ``family`` at ``weight``, or None."""
    found = _font_file(family, weight)
    if found is None:
        return None
    path, index = found
    try:
        from fontTools.ttLib import TTFont

        # The widths read out and the file closed: the font left to the collector left its file open, a
        # ResourceWarning in a notebook or a test run that shows them.
        with TTFont(path, fontNumber=index, lazy=True) as font:
            glyphs, units = font.getBestCmap(), font["head"].unitsPerEm
            widths = {glyph: width for glyph, (width, _) in font["hmtx"].metrics.items()}
            notdef = widths[font.getGlyphOrder()[0]]
    except Exception:  # noqa: BLE001 - any unreadable font leaves the line in one font, as before
        return None

    def advance(character: str) -> float:
        glyph = glyphs.get(ord(character))
        return (widths[glyph] if glyph is not None else notdef) / units

    return advance


def _font_file(family: str, weight: str) -> tuple[str, int] | None:
    """The file and face index fontconfig gives for ``family`` at ``weight``, if it is that family."""
    if shutil.which("fc-match") is None:
        return None
    # Imported here: only a text that mixes Chinese with Latin letters asks fontconfig, and a run of none loads no
    # subprocess machinery.
    import subprocess

    try:
        found = subprocess.run(["fc-match", "-f", "%{family}\t%{file}\t%{index}", f"{family}:{weight}"],
                               capture_output=True, text=True, timeout=10, check=True).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    families, path, index = (found.split("\t") + ["", "", ""])[:3]
    # fontconfig answers with its nearest font when the family is missing: its widths would not be the line's.
    if family not in (name.strip() for name in families.split(",")) or not path:
        return None
    return path, int(index or 0)
