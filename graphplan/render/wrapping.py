"""Long lines of a drawing's text broken to a width on the paper, where a reader expects the break.

First after a comma, semicolon or colon (not one that ends a name of a word or
two, which would end a line on it), before the sign of a term, before a
bracket, none of them inside a factored term's brackets; a piece still too
wide is then broken between words, into pieces as even as can be, never inside
``name = value unit`` nor after the sign of a term.  Widths are the generous estimate of
:func:`~graphplan.render.primitives.text_width`.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

import numpy as np

from .primitives import text_width

# Where a line may break first: after a comma, semicolon or colon, before the sign of a term, before a bracket (but
# one after a sign, which would end the line on the sign);
# in Chinese, which puts no space there, after its full-width comma, semicolon and colon and before its bracket.
PHRASE_BREAK = re.compile(r"(?<=[,;:])\s+|\s+(?=[+−] )|(?<![+−=])\s+(?=\()|(?<=[，；、：])(?=\S)|(?<=\S)(?=（)")
# A colon that ends a name of a word or two, no number in it ("arrows: μF = 100 N/mm", "стрелки сил: μF = …",
# "ΣMp: G2·h1 + …"), is no place for a break: the line would end on the name, what it names on the next.
NAME_BEFORE = re.compile(r"(?:^|[,;]\s+)[^\s\d,;:]+(?: [^\s\d,;:]+)?:$")
# Where a piece still too wide breaks: between words, but not round "=", nor between a number and its unit,
# nor between a sign and its term.
WORD_BREAK = re.compile(r"(?<![\d=+−])\s+(?![=\d])")
# The pieces of a line broken between words are evened out in steps of this width (mm).
EVENING_STEP_MM = 2.0


def fitted(line: str, width: float, size: float, weight: str = "normal") -> list[str]:
    """``line`` at cap height ``size`` (mm) broken into pieces no wider than ``width`` mm where it can be;
    the pieces give the line back, joined with the spaces they were cut at (none in Chinese)."""
    def span(text: str) -> float:
        return text_width(text, size, weight)

    phrase_cuts = [cut for cut in PHRASE_BREAK.finditer(line)
                   if not NAME_BEFORE.search(line, 0, cut.start()) and not _in_factored_term(line, cut.start())]
    pieces = _broken(line, phrase_cuts, width, span)
    return [word_piece for piece in pieces
            for word_piece in (_evened(piece, WORD_BREAK, width, span) if span(piece) > width else [piece])]


def joined(pieces: Sequence[str]) -> str:
    """The line :func:`fitted` broke into ``pieces``, given back: joined with the space each was cut at, but none
    after Chinese's full-width punctuation or before its bracket, where it cuts at none."""
    line = ""
    for piece in pieces:
        spaced = line and not _CUT_AT_NO_SPACE_BEFORE.search(line) and not piece.startswith("（")
        line += (" " if spaced else "") + piece
    return line


# The ends of a piece after which :data:`PHRASE_BREAK` cut at no space: Chinese's full-width comma, semicolon, colon.
_CUT_AT_NO_SPACE_BEFORE = re.compile(r"[，；、：]$")


def _in_factored_term(line: str, at: int) -> bool:
    """Whether ``at`` stands inside the brackets of a term with a factor taken out, ``(Mu3″ − Mf23″ + Mf43″)·h4``: a
    break there (``− (Mu3″`` ending a line of ΣMp, the rest on the next) parts a term a reader takes in as one.
    Words in brackets break after their commas as anywhere else."""
    opened = line.rfind("(", 0, at)
    if opened < 0 or line.find(")", opened, at) >= 0:
        return False
    closed = line.find(")", at)
    return closed >= 0 and line.startswith("·", closed + 1)


def _evened(line: str, breaks: re.Pattern[str], width: float, span: Callable[[str], float]) -> list[str]:
    """``line`` cut at ``breaks`` into as few pieces as keep within ``width`` mm, the pieces as even as can be."""
    pieces = _broken(line, list(breaks.finditer(line)), width, span)
    narrowest = max(span(line) / len(pieces), *(span(piece) for piece in pieces[1:-1]), 0.0)
    for narrower in np.arange(narrowest, width, EVENING_STEP_MM):
        even = _broken(line, list(breaks.finditer(line)), float(narrower), span)
        if len(even) == len(pieces):
            return even
    return pieces


def _broken(line: str, cuts: list[re.Match[str]], width: float, span: Callable[[str], float]) -> list[str]:
    """``line`` cut greedily at ``cuts``: each piece as long as keeps within ``width`` mm, if it can."""
    starts = [0, *(cut.end() for cut in cuts)]
    ends = [*(cut.start() for cut in cuts), len(line)]
    pieces: list[str] = []
    current = line[starts[0]:ends[0]]
    for k in range(1, len(starts)):
        joined = current + line[ends[k - 1]:starts[k]] + line[starts[k]:ends[k]]
        if span(joined) > width:
            pieces.append(current)
            current = line[starts[k]:ends[k]]
        else:
            current = joined
    pieces.append(current)
    return pieces
