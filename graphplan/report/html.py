"""Markdown → a standalone HTML page (the explanatory note for a browser or for printing).

markdown-it-py renders CommonMark with tables; the page carries its own
small style sheet and names fonts that have Cyrillic and CJK glyphs (DejaVu
Sans, Noto Sans CJK), so that it reads the same on any machine.  Raw HTML in
the Markdown is escaped, not passed through: the note's text is data.

With ``symbols=True`` the textbook's symbols in the text get their indices
as the textbooks set them: ``VBA`` → V<sub>BA</sub>, ``aBA^τ`` →
a<sub>BA</sub><sup>τ</sup>, ``ω3`` → ω<sub>3</sub>, ``μV`` → μ<sub>V</sub>; Assur's special
point is an index like a letter (``VDΣ6`` → V<sub>DΣ6</sub>); the symbols
are told apart by :mod:`graphplan.report.symbols`.
"""

from __future__ import annotations

import html
import re
from collections.abc import Collection

from .symbols import Symbol, pieces

_FONTS = ('"DejaVu Sans", "Noto Sans", "Noto Sans CJK SC", "Noto Sans CJK JP", "Noto Sans SC", "Microsoft YaHei", '
          '"PingFang SC", sans-serif')
# The page's margin boxes (its number) inherit nothing from the body: they name the body's fonts themselves.
# A table's header wraps between its words only: hyphenated, the error table's read «quant-ity», «draft-ing».
_STYLE = """\
body { font-family: FONTS;
       max-width: 60em; margin: 2em auto; padding: 0 1em; line-height: 1.45; color: #111; }
h1 { font-size: 1.6em; } h2 { font-size: 1.35em; margin-top: 1.6em; } h3 { font-size: 1.15em; }
h4 { font-size: 1em; }
table { border-collapse: collapse; margin: 0.6em 0 1.2em; font-size: 0.92em; }
th, td { border: 1px solid #999; padding: 0.2em 0.55em; vertical-align: top; }
th { background: #eee; }
td { font-variant-numeric: tabular-nums; }
td.word { white-space: nowrap; }
span.unit { white-space: nowrap; }
@page { size: A4; margin: 20mm 10mm 20mm 30mm;
        @bottom-center { content: counter(page); font-family: FONTS; font-size: 9pt; } }
p.table-caption { margin-bottom: 0.3em; }
figure { margin: 1em 0 1.2em; text-align: center; break-inside: avoid; }
figure img { max-width: 100%; max-height: 230mm; height: auto; }
figcaption { margin-top: 0.4em; }
th { hyphens: manual; }
@media print { body { max-width: none; margin: 0; } h2, h3, h4, p.table-caption, p.lead, p.refers { break-after: avoid; }
               table { font-size: 0.8em; } table.whole, tr { break-inside: avoid; }
               th, td { padding: 0.2em 0.4em; }
               table.wide { font-size: 0.67em; } table.wide th, table.wide td { padding: 0.2em 0.3em; } }
"""

_STYLE = _STYLE.replace("FONTS", _FONTS)

# A table of at most this many rows stays on one page; a longer one goes on from where it starts (a page
# break between its rows, its header repeated), not to the next page whole, which left its caption alone.
_WHOLE_ROWS = 20
_TABLE = re.compile(r"<table>(.*?)</table>", re.DOTALL)
# A table of more columns than this is printed a size smaller: its headers wrap only between words, and the
# longest of them (the error table's «аналитически», «(построение),») must fit the line side by side.
_WIDE_COLUMNS = 7

# A paragraph right before a table is its caption (the note numbers its tables above them, as GOST 2.105
# asks): marked so that a page break never parts it from its table.
_CAPTION = re.compile(r"<p>((?:(?!</p>).)*)</p>\n(?=<table>)", re.DOTALL)


# A picture alone in its paragraph and the paragraph under it, its caption (the note's "Figure 2. ..."): one
# figure, which a page break never parts.  The picture links to its file: a plan sheet drawn at 530 mm shows
# at the page's width, and its full size is a click away.
_FIGURE = re.compile(r'<p>(<img src="([^"]*)"[^>]*>)</p>\n<p>((?:(?!</p>).)*)</p>\n', re.DOTALL)

# The sentence right before a table's caption or a figure refers to it by its number: marked so that a page break
# never leaves it behind, and the heading over it, at the foot of a page.
_REFERS = re.compile(r"<p>((?:(?!</p>).)*)</p>\n(?=<p class=\"table-caption\">|<figure>)", re.DOTALL)

# A paragraph of bold text alone heads what follows (the note's "Group II(5,6), kind RRP" over a group's vector
# equation): marked so that a page break never leaves it at the foot of a page.
_LEAD = re.compile(r"<p>(<strong>(?:(?!</strong>).)*</strong>)</p>\n", re.DOTALL)

# A cell of one word (a number, a unit, a symbol): a narrow column must not break it after a slash (рад/с²).
_ONE_WORD_CELL = re.compile(r"<td((?: [^>]*)?)>((?:(?!</td>)[^\s])+)</td>")

# A unit of measure (m/s², (m/s)/mm, N·m, кг·м²) or a quotient of letters (Mb0/Mb): never broken across lines.
# In a Chinese line WeasyPrint broke one after its slash, «（g = 9.81 m/» ending a line and «s²）» opening the next.
_UNIT_CHARACTER = r"[A-Za-zА-Яа-яЁёΑ-Ωα-ω0-9()²³⁻¹′°.,]"
_UNIT = re.compile(rf"{_UNIT_CHARACTER}+(?:[/·]{_UNIT_CHARACTER}+)+")
_TAG = re.compile(r"(<[^>]*>)")


def _units_unbroken(body: str) -> str:
    """``body`` with each unit in its text (not in its tags) set in a span that is not broken across lines; a
    product that runs on into or out of a symbol's index (λ·M<sub>N</sub>, J<sub>rot</sub>·u²) is a formula, left
    as it is."""
    pieces = _TAG.split(body)

    def spanned(k: int) -> str:
        piece = pieces[k]
        indexed_after = k + 1 < len(pieces) and pieces[k + 1] in ("<sub>", "<sup>")
        indexed_before = k > 0 and pieces[k - 1] in ("</sub>", "</sup>")

        def unit(match: re.Match) -> str:
            if (indexed_after and not piece[match.end():].strip("/·")) or \
                    (indexed_before and not piece[:match.start()].strip("/·")):
                return match[0]
            return f'<span class="unit">{match[0]}</span>'

        return _UNIT.sub(unit, piece)

    return "".join(piece if piece.startswith("<") else spanned(k) for k, piece in enumerate(pieces))


def symbols_html(text: str, verbatim: Collection[str] = ()) -> str:
    """Escape ``text`` for HTML and set the indices of its symbols as subscripts and superscripts (none in the
    user's own texts ``verbatim``)."""
    return "".join(html.escape(piece, quote=False) if isinstance(piece, str) else _symbol_html(piece)
                   for piece in pieces(text, verbatim))


def _symbol_html(symbol: Symbol) -> str:
    base, index, component = (html.escape(part, quote=False) for part in symbol)
    return base + (f"<sub>{index}</sub>" if index else "") + (f"<sup>{component}</sup>" if component else "")


def _classed_table(table: re.Match) -> str:
    """The table marked ``whole`` if short enough to keep to one page and ``wide`` if of many columns."""
    columns = table[1].split("</tr>", 1)[0].count("<th")
    classes = [name for name, marked in (("whole", table[1].count("<tr>") <= _WHOLE_ROWS),
                                         ("wide", columns > _WIDE_COLUMNS)) if marked]
    return table[0].replace("<table>", f'<table class="{" ".join(classes)}">', 1) if classes else table[0]


def to_html(markdown_text: str, title: str, lang: str, symbols: bool = False, author: str = "",
            verbatim: Collection[str] = ()) -> str:
    """A complete HTML5 page of ``markdown_text`` with ``title`` (and ``author``, where given) in its head, in
    language ``lang``; a PDF made of it takes them as its own.

    ``symbols`` sets the indices of the textbook's symbols (``VBA``, ``ω3``) as subscripts, except in the user's
    own texts ``verbatim`` (:func:`graphplan.report.markdown.user_texts`).
    """
    from .markdown import parser, tokens

    markdown = parser()
    if symbols:
        markdown.add_render_rule("text", lambda self, tokens, idx, options, env: symbols_html(tokens[idx].content, verbatim))
    rendered = markdown.renderer.render(list(tokens(markdown_text)), markdown.options, {})
    body = _CAPTION.sub(r'<p class="table-caption">\1</p>\n', rendered)
    body = _FIGURE.sub(r'<figure><a href="\2">\1</a><figcaption>\3</figcaption></figure>\n', body)
    body = _REFERS.sub(r'<p class="refers">\1</p>\n', body)
    body = _LEAD.sub(r'<p class="lead">\1</p>\n', body)
    body = _ONE_WORD_CELL.sub(r'<td class="word"\1>\2</td>', body)
    body = _TABLE.sub(_classed_table, body)
    body = _units_unbroken(body)
    return (f'<!DOCTYPE html>\n<html lang="{html.escape(lang, quote=True)}">\n<head>\n<meta charset="utf-8">\n'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">\n'
            f"<title>{html.escape(title, quote=False)}</title>\n"
            + (f'<meta name="author" content="{html.escape(author, quote=True)}">\n' if author else "")
            + f"<style>\n{_STYLE}</style>\n</head>\n<body>\n"
            f"{body}</body>\n</html>\n")


__all__ = ["symbols_html", "to_html"]
