"""A drawing's symbols with their indices set as the textbooks set them: R₁₂, ω₂, Fᵤ₂, R₁₄ with its τ above.

The drawings letter and measure their symbols flat, as plain text allows (``R12``, ``Mu4′``, ``R14τ``, ``h7``); as
the last step before a drawing is written, :func:`with_indices` cuts each of its texts into runs on the line, below it
(an index) and above it (a component), and the SVG sets the runs below and above a size smaller.  The flat text stays
what is measured: a run set smaller is narrower than the box it was laid out in, never wider.

A symbol is what the note calls one (:mod:`graphplan.report.symbols`, shared so that a drawing and the note beside it
index the same symbols) and the few shapes only the drawings letter: an arm (h7, hb), a numbered point of a plan or a
mechanism (s2, n3, S2, σ6), a rocker's swing (ψmax), a plane's angle (θL) and a velocity
along a diagram's axis (vB).  The title block and the scene's own words (its title, the loads it names) are the user's
text and stay as written, but for a word that is one symbol whole (a load named F6, indexed F₆ as the drawing's own
Fᵤ₆ beside it).
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Collection, Iterable, Sequence

from ..report.symbols import CAPITALS, Symbol, occurrences, pieces
from .primitives import USER_LAYERS, Layer, Text

#: A run's place: on the line, below it (an index) or above it (a component).
LINE, BELOW, ABOVE = 0, -1, 1

# The shapes the drawings letter and the note does not, each standing whole (no letter or digit either side).
_DRAWING_SYMBOL = re.compile(
    r"(?<![\w′″])(?:"
    r"(?P<arm>h)(?P<arm_index>\d+|[bу]|[uи]\d+)"
    r"|(?P<point>[A-Za-zσΣ])(?P<number>\d+)"
    r"|(?P<swing>ψ)(?P<extreme>max|min)"
    r"|(?P<angle>θ)(?P<plane>[A-Z])"
    # A point's name in any script, as the scene names it (vB, vБ, vSLIDEPIN), as s and a beside it are indexed.
    rf"|(?P<speed>v)(?P<of>[{CAPITALS}][{CAPITALS}0-9]*)"
    r")(?![\w])")

Run = tuple[str, int]

# The components a text may write as superscript letters of their own.
_RAISED = frozenset("ⁿᵏʳ")


def runs(text: str, verbatim: Collection[str] = ()) -> tuple[Run, ...]:
    """``text`` as its runs (text, place); empty where it has no index to set, so that it is written as it is.

    ``verbatim``: the user's texts, kept flat wherever they stand whole in ``text``.
    """
    found: list[Run] = []
    at = 0
    for piece in pieces(text, tuple(verbatim)):
        if isinstance(piece, Symbol):
            found += [(piece.base, LINE), (piece.index, BELOW)]
            at += len(piece.base) + len(piece.index)
            if piece.component:
                # A component written raised already (aGEⁿ) stays as written; one written flat (R14τ) is raised.
                written = text[at:at + 1]
                found.append((written, LINE) if written in _RAISED else (piece.component, ABOVE))
                at += 2 if written == "^" else 1
        else:
            found += _drawing_runs(piece, verbatim)
            at += len(piece)
    joined = _joined(run for run in found if run[0])
    return joined if any(place != LINE for _, place in joined) else ()


def _drawing_runs(plain: str, verbatim: Collection[str]) -> list[Run]:
    """The runs of a text the note's symbols left plain: the drawings' own shapes in it indexed."""
    kept = [found.span() for found in occurrences(tuple(verbatim)).finditer(plain)] if verbatim else []
    found: list[Run] = []
    done = 0
    for match in _DRAWING_SYMBOL.finditer(plain):
        if any(start < match.end() and match.start() < end for start, end in kept):
            continue
        base, index = (value for value in match.groups() if value is not None)
        found += [(plain[done:match.start()], LINE), (base, LINE), (index, BELOW)]
        done = match.end()
    return found + [(plain[done:], LINE)]


def _joined(found: Iterable[Run]) -> tuple[Run, ...]:
    """Neighbouring runs of one place made one."""
    joined: list[Run] = []
    for text, place in found:
        if joined and joined[-1][1] == place:
            joined[-1] = (joined[-1][0] + text, place)
        else:
            joined.append((text, place))
    return tuple(joined)


def _one_symbol(word: str) -> bool:
    """Whether ``word`` is a single symbol: a base on the line and nothing after its index and component."""
    found = runs(word)
    return len(found) >= 2 and found[1][1] == BELOW and all(place != LINE for _, place in found[1:])


def with_indices(layers: Sequence[Layer], verbatim: Iterable[str] = ()) -> list[Layer]:
    """``layers`` with each text's symbols' indices set (:attr:`Text.runs`); the title block and the texts
    ``verbatim`` (the scene's own words) as written."""
    # A word of the user's that is one symbol whole (a load named F6) is indexed as one; any other (F4.2, a title
    # "Press F1") is kept as typed.
    verbatim = tuple(typed for typed in verbatim if typed and not _one_symbol(typed))

    def indexed(item):
        if not isinstance(item, Text):
            return item
        found = runs(item.text, verbatim)
        return dataclasses.replace(item, runs=found) if found else item

    return [layer if layer.name in USER_LAYERS else Layer(layer.name, tuple(map(indexed, layer.items)))
            for layer in layers]


__all__ = ["ABOVE", "BELOW", "LINE", "Run", "runs", "with_indices"]
