"""The texts of a DXF as a CAD program reads them back: a TEXT's content, and an MTEXT's runs on its line, stacked
under it (an index) and over it (a component), read with ezdxf's own parser of MTEXT's inline codes."""

from __future__ import annotations

from graphplan.render.indices import ABOVE, BELOW, LINE


def mtext_runs(entity) -> tuple[tuple[str, int, float], ...]:
    """(text, place, height over the MTEXT's own) of each run of an MTEXT, runs at one place and height joined: a
    stack with nothing over it is an index (BELOW), one with nothing under it a component (ABOVE)."""
    from ezdxf.tools.text import MTextParser, TokenType

    found: list[tuple[str, int, float]] = []
    for token in MTextParser(entity.text):
        height = token.ctx.cap_height
        if token.type == TokenType.WORD:
            found.append((token.data, LINE, height))
        elif token.type in (TokenType.SPACE, TokenType.NBSP):
            found.append((" ", LINE, height))
        elif token.type == TokenType.STACK:
            over, under, kind = token.data
            assert kind == "^" and bool(over) != bool(under), token.data
            found.append((over, ABOVE, height) if over else (under, BELOW, height))
        else:
            raise AssertionError(f"an MTEXT of one line has no {token.type.name}")
    joined: list[tuple[str, int, float]] = []
    for text, place, height in found:
        if joined and joined[-1][1:] == (place, height):
            joined[-1] = (joined[-1][0] + text, place, height)
        else:
            joined.append((text, place, height))
    return tuple(joined)


def read_text(entity) -> str:
    """The characters a TEXT or an MTEXT reads as, an MTEXT's stacks in their place in the line."""
    if entity.dxftype() == "TEXT":
        return entity.plain_text()
    return "".join(text for text, _, _ in mtext_runs(entity))
