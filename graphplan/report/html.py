"""Markdown → a standalone HTML page (the explanatory note for a browser or for printing).

markdown-it-py renders CommonMark with tables; the page carries its own
small style sheet and names fonts that have Cyrillic and CJK glyphs (DejaVu
Sans, Noto Sans CJK), so that it reads the same on any machine.  Raw HTML in
the Markdown is escaped, not passed through: the note's text is data.

With ``symbols=True`` the textbook's symbols in the text get their indices
as the textbooks set them: ``VBA`` → V<sub>BA</sub>, ``aBA^τ`` →
a<sub>BA</sub><sup>τ</sup>, ``ω3`` → ω<sub>3</sub>, ``μV`` → μ<sub>V</sub>; Assur's special
point is an index like a letter (``VDΣ6`` → V<sub>DΣ6</sub>).
Only a closed list of shapes is recognised (:data:`_SYMBOL`), none of which
is a word of the note's languages.
"""

from __future__ import annotations

import html
import re

_STYLE = """\
body { font-family: "DejaVu Sans", "Noto Sans", "Noto Sans CJK SC", "Noto Sans CJK JP", "Noto Sans SC",
       "Microsoft YaHei", "PingFang SC", sans-serif;
       max-width: 60em; margin: 2em auto; padding: 0 1em; line-height: 1.45; color: #111; }
h1 { font-size: 1.6em; } h2 { font-size: 1.35em; margin-top: 1.6em; } h3 { font-size: 1.15em; }
h4 { font-size: 1em; }
table { border-collapse: collapse; margin: 0.6em 0 1.2em; font-size: 0.92em; }
th, td { border: 1px solid #999; padding: 0.2em 0.55em; vertical-align: top; }
th { background: #eee; }
td { font-variant-numeric: tabular-nums; }
td.word { white-space: nowrap; }
@page { size: A4; margin: 20mm 10mm 20mm 30mm; @bottom-center { content: counter(page); font-size: 9pt; } }
p.table-caption { margin-bottom: 0.3em; }
th { hyphens: auto; }
@media print { body { max-width: none; margin: 0; } h2, h3, p.table-caption { break-after: avoid; }
               table { break-inside: avoid; font-size: 0.8em; } th, td { padding: 0.2em 0.4em; } }
"""

# A paragraph right before a table is its caption (the note numbers its tables above them, as GOST 2.105
# asks): marked so that a page break never parts it from its table.
_CAPTION = re.compile(r"<p>((?:(?!</p>).)*)</p>\n(?=<table>)", re.DOTALL)


# A cell of one word (a number, a unit, a symbol): a narrow column must not break it after a slash (рад/с²).
_ONE_WORD_CELL = re.compile(r"<td((?: [^>]*)?)>((?:(?!</td>)[^\s])+)</td>")

# base, index, component: the symbols of the plan method and of the force analysis.
_SYMBOL = re.compile(
    r"(?<![A-Za-z_])(?:"
    r"(?P<base>[Va]|l)(?P<index>[A-ZΣ][A-Z0-9Σ]*)(?P<component>ⁿ|ᵏ|\^τ|\^r)?"
    r"|(?P<base12>a)(?P<component12>\^τ)"
    r"|(?P<base2>[ωε])(?P<index2>\d+)"
    r"|(?P<base3>μ)(?P<index3>[VaFl])"
    r"|(?P<base4>R)(?P<index4>\d+)(?P<component4>τ|n)?"
    r"|(?P<base5>[FM])(?P<index5>u\d*|b\d*|\d+)"
    r"|(?P<base6>F)(?P<index6>y)"
    r"|(?P<base7>[GJ])(?P<index7>\d+|S)|(?P<base11>m)(?P<index11>\d+)"
    r"|(?<=Σ)(?P<base8>M)(?P<index8>[A-ZΣ][A-Z0-9Σ]*)"
    r"|(?P<base9>p)(?P<index9>[45])"
    r"|(?P<base10>P)(?P<index10>[LH])"
    r")(?![A-Za-z0-9_])")


def _indexed(match: re.Match[str]) -> str:
    groups = {key: value for key, value in match.groupdict().items() if value is not None}
    base = next(value for key, value in groups.items() if key.startswith("base"))
    index = next((value for key, value in groups.items() if key.startswith("index")), "")
    component = next((value for key, value in groups.items() if key.startswith("component")), "")
    if component in ("ⁿ", "ᵏ"):
        component = {"ⁿ": "n", "ᵏ": "k"}[component]
    component = component.removeprefix("^")
    return base + (f"<sub>{index}</sub>" if index else "") + (f"<sup>{component}</sup>" if component else "")


def symbols_html(text: str) -> str:
    """Escape ``text`` for HTML and set the indices of its symbols as subscripts and superscripts."""
    return _SYMBOL.sub(_indexed, html.escape(text, quote=False))


def to_html(markdown_text: str, title: str, lang: str, symbols: bool = False) -> str:
    """A complete HTML5 page of ``markdown_text`` with ``title`` in its head, in language ``lang``.

    ``symbols`` sets the indices of the textbook's symbols (``VBA``, ``ω3``) as subscripts.
    """
    from markdown_it import MarkdownIt

    renderer = MarkdownIt("commonmark", {"html": False}).enable("table")
    if symbols:
        renderer.add_render_rule("text", lambda self, tokens, idx, options, env: symbols_html(tokens[idx].content))
    body = _CAPTION.sub(r'<p class="table-caption">\1</p>\n', renderer.render(markdown_text))
    body = _ONE_WORD_CELL.sub(r'<td class="word"\1>\2</td>', body)
    return (f'<!DOCTYPE html>\n<html lang="{html.escape(lang, quote=True)}">\n<head>\n<meta charset="utf-8">\n'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">\n'
            f"<title>{html.escape(title, quote=False)}</title>\n<style>\n{_STYLE}</style>\n</head>\n<body>\n"
            f"{body}</body>\n</html>\n")


__all__ = ["symbols_html", "to_html"]
