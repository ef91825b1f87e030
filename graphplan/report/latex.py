r"""Markdown → LaTeX: the explanatory note as a document for XeLaTeX, and the tables as fragments to ``\input``.

markdown-it-py parses the Markdown the note is written in (CommonMark with
tables, :mod:`graphplan.report.markdown`), and its syntax tree is written out:

- headings unnumbered, since the note numbers its own;
- a figure (a picture alone in its paragraph and the caption under it) as
  its drawing's PDF beside the note, centred over its caption, the two
  unbroken by a page (``\notefigure``: the drawing's name in a frame until
  ``--format pdf`` has written the PDFs);
- a table as a longtable with booktabs rules, its header repeated on every
  page it runs onto under the locale's "continued" line (GOST 2.105's
  «Продолжение таблицы 3»), and the paragraph right before it (the note's
  "Table 3. ...") as its caption, so that a page break never parts them;
  no page holding a single row of a table, and a heading right over a
  table taken to the next page with it where its first rows do not fit;
  a wide table set smaller, and its columns still too wide for the line
  wrapped (:func:`_layout`);
- the textbook's symbols with their indices as sub- and superscripts, read
  as the HTML reads them (:mod:`graphplan.report.symbols`);
- every other character as text: LaTeX's special characters escaped, the
  rest left Unicode (Greek, Cyrillic, CJK, −, ⊥, ²).

The text being Unicode, the document is for XeLaTeX with fontspec, set in
the fonts of the drawings: DejaVu Sans, and each run of CJK characters in
Noto Sans CJK SC with XeTeX's line breaks between them (in Chinese, and in
a note of another language with a CJK character in it: a scene's title or
names), and hyphenated by babel in Russian.  It uses only packages of TeX Live's base and recommended
collections (Debian: texlive-xetex, texlive-latex-recommended); Russian
words break at their syllables where TeX Live's Cyrillic patterns are
installed too (texlive-lang-cyrillic).  A fragment has no preamble: a
comment at its head names what the including document needs.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping
from dataclasses import dataclass
from itertools import groupby

import numpy as np
from markdown_it.tree import SyntaxTreeNode

from ..locale import strings
from ..render.primitives import FONT_SIZE_PER_CAP, em_width, has_wide, is_wide
from ..render.wrapping import fitted
from .markdown import picture_source, plain, table_parts, tree
from .symbols import Symbol, pieces

_SPECIAL = str.maketrans({"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
                          "%": r"\%", "_": r"\_", "^": r"\textasciicircum{}", "~": r"\textasciitilde{}"})

# The note's heading levels below its title (a fragment's from its first): its sections, a position, a plan.
_HEADINGS = ("section", "subsection", "subsubsection")

# A table is measured against the note's line, A4 less its margins of 30 mm and 10 mm, in pt.
_LINE_PT = 483.7
# What each column keeps clear on either side (\tabcolsep), pt.
_COLUMN_GAP_PT = 4.0
# A table's type sizes of the 11 pt class, largest first: a wide table takes the first its headers fit at.
_SIZES = (("small", 10.0), ("footnotesize", 9.0), ("scriptsize", 8.0))
# A wrapping column keeps the side its Markdown aligns it to.
_RAGGED = {"l": "\\raggedright", "c": "\\centering", "r": "\\raggedleft"}
# A header no wider than this (em) stays on one line where the table has room.
_HEADER_LINE_EM = 7.0
# The room a heading needs for the table right under it (the sentence that refers to it, its caption of up to
# two lines, a header of three and the two rows it starts with), and its own.
_ROOM_UNDER_HEADING = "11\\baselineskip"
# The drawings' line breaker measures in mm at a cap height: at this one a mm is an em.
_EM_CAP = 1.0 / FONT_SIZE_PER_CAP

# XeTeX takes every glyph from the one font in force, and DejaVu Sans has no ideographs: each run of them
# is set in Noto Sans CJK SC (``\notecjk``), the rest in DejaVu Sans.  Noto Sans CJK SC as the main font
# set ·, ×, →, ⊥ full-width (GB 18030 gives them an ideograph's square) and has no ⁿ or ᵏ; xeCJK, which
# would switch by itself, is in no collection the note may count on (texlive-lang-chinese).
_FONT = "DejaVu Sans"
_CJK_FONT = "Noto Sans CJK SC"

_PREAMBLE = r"""\documentclass[11pt,a4paper]{article}
\usepackage[top=20mm,bottom=20mm,left=30mm,right=10mm]{geometry}
\usepackage{fontspec}
%% No TeX ligatures: the note's text is Unicode as written, and a title's `, -- or << would be set as ‘, – or «.
\setmainfont{%(font)s}[Ligatures=TeXOff]
%(cjk_font)s\usepackage{array,longtable,booktabs}
\usepackage[font=normalsize,justification=raggedright,singlelinecheck=false,skip=3pt]{caption}
%% Tables flush left under their captions, which span the line (its width is geometry's once the document begins).
\setlength{\LTleft}{0pt}
\setlength{\LTright}{\fill}
\AtBeginDocument{\setlength{\LTcapwidth}{\textwidth}}
%% A heading with a table right under it goes to the next page unless the table's first rows fit under it too:
%% longtable breaks the page where it starts when they do not, which left the heading alone at the foot of a page.
\newdimen\noteroomleft
\newcommand{\noteneedroom}[1]{\par\noteroomleft=\pagegoal\advance\noteroomleft-\pagetotal
\ifdim#1>\noteroomleft\vfil\break\fi}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5em}
%% Lines may stretch rather than run over: a formula is a long run without a break.
\sloppy
%% A figure's drawing from its PDF beside the note (graphplan run --format pdf writes them), at its size or smaller
%% to fit the line and most of the page; without the PDF, the name of the drawing in a frame.
\usepackage{graphicx}
\newsavebox{\notepicture}
\newcommand{\notefigure}[2]{\IfFileExists{#1}{\sbox{\notepicture}{\includegraphics{#1}}%%
\ifdim\wd\notepicture>\linewidth\sbox{\notepicture}{\resizebox{\linewidth}{!}{\usebox{\notepicture}}}\fi
\ifdim\ht\notepicture>0.8\textheight\sbox{\notepicture}{\resizebox{!}{0.8\textheight}{\usebox{\notepicture}}}\fi
\usebox{\notepicture}}{\fbox{\texttt{#2}}}}
%(locale)s"""

# Chinese has no spaces: XeTeX may break a line between any two CJK characters.
_CJK_BREAKS = "\\XeTeXlinebreaklocale \"zh\"\n\\XeTeXlinebreakskip = 0pt plus 1pt\n"
# A run of CJK characters in the CJK font, in the series, shape and size around it.
_CJK_RUNS = f"\\newfontfamily{{\\notecjkfont}}{{{_CJK_FONT}}}\n\\newcommand{{\\notecjk}}[1]{{{{\\notecjkfont #1}}}}\n"
# Russian words break at their syllables by babel's Russian (its locale file is in TeX Live's base); the
# patterns come with TeX Live's Cyrillic collection (Debian: texlive-lang-cyrillic), and a TeX without them
# sets the note as before, unhyphenated.
_RUSSIAN = "\\usepackage{babel}\n\\babelprovide[import,main]{russian}\n"

_FRAGMENT_HEAD = ("% Tables of graphplan for \\input into a document typeset by XeLaTeX (the text is Unicode),\n"
                  "% with \\usepackage{array,longtable,booktabs,caption} and a main font with the text's\n"
                  "% scripts (fontspec: \\setmainfont{FONT}).\n")
# A fragment's runs of CJK characters are marked as the note's are; in a document that sets them in no font
# of their own, in the main font.
_FRAGMENT_CJK = ("% Its CJK runs are in \\notecjk{...}: \\newcommand{\\notecjk}[1]{{\\cjkfont #1}} before the \\input\n"
                 "% sets them in a font of their own.\n\\providecommand{\\notecjk}[1]{#1}\n")


def _has_cjk(markdown_text: str, locale: str) -> bool:
    return locale == "zh" or has_wide(markdown_text)


def latex_document(markdown_text: str, title: str, locale: str, verbatim: Collection[str] = ()) -> str:
    """A complete XeLaTeX document of ``markdown_text`` (the explanatory note); its first line names ``title``.
    The user's own texts ``verbatim`` are set as typed, with no symbol's index in them."""
    cjk = _has_cjk(markdown_text, locale)
    language = (_RUSSIAN if locale == "ru" else "") + (_CJK_BREAKS if cjk else "")
    preamble = _PREAMBLE % {"font": _FONT, "cjk_font": _CJK_RUNS if cjk else "", "locale": language}
    return (f"% {' '.join(title.split())}: typeset with xelatex, twice (longtable settles its columns' widths on the second)\n"
            f"{preamble}"
            f"\\begin{{document}}\n{_body(markdown_text, locale, titled=True, verbatim=verbatim)}\\end{{document}}\n")


def latex_fragment(markdown_text: str, locale: str, verbatim: Collection[str] = ()) -> str:
    """The body of ``markdown_text`` (the error tables, the force analysis) for ``\\input``, with no preamble;
    the user's own texts ``verbatim`` as typed."""
    cjk = _has_cjk(markdown_text, locale)
    return (_FRAGMENT_HEAD.replace("FONT", _CJK_FONT if cjk else _FONT) + (_FRAGMENT_CJK if cjk else "")
            + _body(markdown_text, locale, titled=False, verbatim=verbatim))


def _body(markdown_text: str, locale: str, titled: bool, verbatim: Collection[str]) -> str:
    return _Writer(titled, strings(locale), verbatim).blocks(tree(markdown_text).children).lstrip("\n")


def _table_number(caption: str, text: Mapping[str, str]) -> str | None:
    """The number of a table whose caption is written the locale's way ("Таблица 3 — ...", or over a part after
    its first "Продолжение таблицы 3"), else None."""
    for key in ("table_caption", "table_continued"):
        pattern = re.escape(text[key]).replace(r"\{number\}", r"(\d+)").replace(r"\{caption\}", ".*")
        found = re.fullmatch(pattern, caption.strip(), flags=re.DOTALL)
        if found:
            return found.group(1)
    return None


def _escape(text: str) -> str:
    """Text with LaTeX's special characters escaped, each run of CJK characters marked for the CJK font."""
    escaped = text.translate(_SPECIAL)
    if not has_wide(escaped):  # most texts: one run, as it stands, without cutting it character by character
        return escaped
    return "".join(f"\\notecjk{{{''.join(run)}}}" if wide else "".join(run)
                   for wide, run in groupby(escaped, key=is_wide))


def _text(text: str, verbatim: Collection[str] = ()) -> str:
    """Text with LaTeX's special characters escaped and the symbols' indices set as sub- and superscripts (none in
    the user's own texts ``verbatim``)."""
    return "".join(_escape(piece) if isinstance(piece, str) else _symbol(piece) for piece in pieces(text, verbatim))


def _symbol(symbol: Symbol) -> str:
    base, index, component = (_escape(part) for part in symbol)
    return (base + (f"\\textsubscript{{{index}}}" if index else "")
            + (f"\\textsuperscript{{{component}}}" if component else ""))


@dataclass(frozen=True)
class _Layout:
    """How a table is set: its type size (a LaTeX size command and pt); each column's spec, side it is aligned
    to (l, c, r) and width in em."""

    size: str
    points: float
    specs: tuple[str, ...]
    sides: tuple[str, ...]
    widths: tuple[float, ...]


def _layout(header: list[str], rows: list[list[str]], sides: tuple[str, ...]) -> _Layout:
    """The type size, columns and header widths of a table, so that it fits the line where it can.

    A column would be as wide as its widest body cell, or its header if that
    is short; it can narrow to its longest word, the header's or the body's
    (a number is one word).  The table takes the largest size at which the
    columns fit narrowed; it narrows its widest columns to one width, the
    one that just fills the line, and they wrap as paragraphs.
    """
    count = len(header)

    def longest_word(texts) -> float:
        return max((em_width(word) for text in texts for word in text.split()), default=0.0)

    cells = [[row[k] for row in rows if k < len(row)] for k in range(count)]
    least = [longest_word([header[k], *cells[k]]) for k in range(count)]
    natural = [max(least[k], min(em_width(header[k]), _HEADER_LINE_EM), *map(em_width, cells[k])) for k in range(count)]

    def room(points: float) -> float:  # the line less the columns' gaps, in em of the size
        return (_LINE_PT - 2.0 * _COLUMN_GAP_PT * count) / points

    def widths_at(cap: float) -> list[float]:
        return [min(natural[k], max(least[k], cap)) for k in range(count)]

    size, points = next(((name, pt) for name, pt in _SIZES if sum(least) <= room(pt)), _SIZES[-1])
    widths = natural
    if sum(natural) > room(points) and sum(least) < room(points):
        # The columns' total is piecewise linear and rising in the cap, bending only where a column stops
        # narrowing or widening: read off at those caps, it is inverted exactly by interpolation.
        # Sorted without their repeats by hand: np.unique asks numpy.ma whether the caps are masked, and importing
        # it costs a cold run some 30 ms.
        caps = np.array(sorted({0.0, *least, *natural}), dtype=float)
        cap = float(np.interp(room(points), [sum(widths_at(c)) for c in caps], caps))
        widths = widths_at(cap)
    elif sum(natural) > room(points):  # too wide even narrowed: the least it can be
        widths = least
    sides = tuple(sides[k] if k < len(sides) else "l" for k in range(count))
    specs = tuple(f">{{{_RAGGED[sides[k]]}\\arraybackslash}}p{{{widths[k] * points / _LINE_PT:.3f}\\linewidth}}"
                  if widths[k] < natural[k] else sides[k] for k in range(count))
    return _Layout(size, points, specs, sides, tuple(widths))


def _no_break_after(row: int, rows: int) -> bool:
    """Whether a page must not break after body row ``row`` of ``rows``: its first or the one before its last, so
    that no page holds a single row of the table under its header or over its bottom rule."""
    return row in (0, rows - 2)


class _Writer:
    """The blocks of the note's syntax tree as LaTeX.

    ``titled``: the first heading is the document's title (the note), not a section (a fragment); ``verbatim``: the
    user's own texts, set with no symbol's index.
    """

    def __init__(self, titled: bool, text: Mapping[str, str], verbatim: Collection[str] = ()) -> None:
        self.titled = titled
        self.text = text
        self.verbatim = tuple(verbatim)

    def blocks(self, nodes) -> str:
        """The blocks in order, a paragraph right before a table taken into the table as its caption, one right
        after a picture into its figure."""
        nodes, parts = list(nodes), []
        for k, node in enumerate(nodes):
            if node.type == "paragraph" and k + 1 < len(nodes) and nodes[k + 1].type == "table":
                continue
            if k and picture_source(nodes[k - 1]) is not None and node.type == "paragraph":
                continue
            source = picture_source(node)
            if source is not None:
                after = nodes[k + 1] if k + 1 < len(nodes) and nodes[k + 1].type == "paragraph" else None
                parts.append(self.figure(source, self.inline(after.children) if after is not None else ""))
                continue
            # The sentence that refers to the table may stand between the heading and the caption.
            following = [n.type for n in nodes[k + 1:k + 4]]
            if node.type == "heading" and self.titled and (following[:2] == ["paragraph", "table"]
                                                           or following == ["paragraph", "paragraph", "table"]):
                parts.append(f"\n\\noteneedroom{{{_ROOM_UNDER_HEADING}}}")
            if node.type == "table":
                before = nodes[k - 1] if k else None
                captioned = before is not None and before.type == "paragraph"
                number = _table_number(plain(before), self.text) if captioned else None
                parts.append(self.table(node, self.inline(before.children) if captioned else None, number))
            else:
                parts.append(self.block(node))
        return "".join(parts)

    def block(self, node: SyntaxTreeNode) -> str:
        if node.type == "heading":
            return self.heading(node)
        if node.type == "paragraph":
            return f"\n{self.inline(node.children)}\n"
        if node.type in ("bullet_list", "ordered_list"):
            kind = "enumerate" if node.type == "ordered_list" else "itemize"
            # A list of readings is many short lines: spaced as lines of a paragraph, it reads as one block.
            tight = "\\setlength{\\itemsep}{0pt}\\setlength{\\parskip}{0pt}"
            items = "".join(f"\\item {self.blocks(item.children).strip()}\n" for item in node.children)
            return f"\\begin{{{kind}}}{tight}\n{items}\\end{{{kind}}}\n"
        if node.type == "table":
            return self.table(node, None)
        if node.type == "hr":
            return "\n\\hrulefill\n"
        if node.type in ("code_block", "fence"):
            return f"\n\\begin{{verbatim}}\n{node.content}\\end{{verbatim}}\n"
        raise ValueError(f"the note has a {node.type}, which its LaTeX does not write")

    @staticmethod
    def figure(source: str, caption: str) -> str:
        """The drawing ``source`` names, from its PDF beside the note, over its caption, in one unbreakable box."""
        stem = source.rsplit(".", 1)[0]
        return (f"\n\\par\\noindent\\begin{{minipage}}{{\\linewidth}}\\centering\n"
                f"\\notefigure{{{stem}.pdf}}{{{_escape(source)}}}\\par\\vspace{{0.4em}}\n{caption}\\par\n"
                f"\\end{{minipage}}\\par\\medskip\n")

    def heading(self, node: SyntaxTreeNode) -> str:
        """Unnumbered: the note numbers its own.  In a document the first level is its title."""
        level = int(node.tag[1:])
        if self.titled and level == 1:
            return f"\n{{\\centering\\Large\\bfseries {self.inline(node.children)}\\par}}\n"
        command = _HEADINGS[min(level - (1 if self.titled else 0), len(_HEADINGS)) - 1]
        return f"\n\\{command}*{{{self.inline(node.children)}}}\n"

    def inline(self, nodes) -> str:
        """A block's text (its ``inline`` node, or the spans inside one) with its emphasis and symbols."""
        parts = []
        for node in nodes:
            if node.type == "inline":
                parts.append(self.inline(node.children))
            elif node.type == "text":
                parts.append(_text(node.content, self.verbatim))
            elif node.type == "strong":
                parts.append(f"\\textbf{{{self.inline(node.children)}}}")
            elif node.type == "em":
                parts.append(f"\\textit{{{self.inline(node.children)}}}")
            elif node.type == "code_inline":
                parts.append(f"\\texttt{{{_escape(node.content)}}}")
            elif node.type == "softbreak":
                parts.append("\n")
            elif node.type == "hardbreak":
                parts.append("\\newline\n")
            else:   # a link or an image: its text
                parts.append(self.inline(node.children))
        return "".join(parts)

    def table(self, node: SyntaxTreeNode, caption: str | None, number: str | None = None) -> str:
        """``number``: the table's, for the line over its header on the pages it runs onto."""
        parts = table_parts(node)
        header = [plain(cell) for cell in parts.header]
        rows = [[plain(cell) for cell in row] for row in parts.rows]
        layout = _layout(header or [""] * len(parts.sides), rows, parts.sides)
        lines = [f"\\begin{{longtable}}{{@{{}}{''.join(layout.specs)}@{{}}}}"]
        if caption is not None:
            lines.append(f"\\caption*{{{caption.strip()}}}\\\\")
        head = []
        if header:
            cells = []
            for text, width, side in zip(header, layout.widths, layout.sides):
                stacked = "\\\\".join(_text(line, self.verbatim) for line in fitted(text, width, _EM_CAP))
                cells.append(f"\\begin{{tabular}}[b]{{@{{}}{side}@{{}}}}{stacked}\\end{{tabular}}")
            head = ["\\toprule", " & ".join(cells) + " \\\\", "\\midrule"]
        # A foot on every page as tall as the last one: longtable keeps room for it, so the last rows never
        # leave the bottom rule to a page of its own under a repeated header.
        continued = [] if number is None else [
            f"\\multicolumn{{{len(layout.sides)}}}{{@{{}}l@{{}}}}{{{_text(self.text['table_continued'].format(number=number))}}}\\\\"]
        lines += [*head, "\\endfirsthead", *continued, *head, "\\endhead", "\\bottomrule", "\\endfoot", "\\bottomrule",
                  "\\endlastfoot"]
        ends = [" \\\\*" if _no_break_after(k, len(parts.rows)) else " \\\\" for k in range(len(parts.rows))]
        lines += [" & ".join(self.inline(cell.children) for cell in row) + end for row, end in zip(parts.rows, ends)]
        size = f"\\{layout.size}\\setlength{{\\tabcolsep}}{{{_COLUMN_GAP_PT:g}pt}}"
        return f"\n{{{size}\n" + "\n".join(lines) + "\n\\end{longtable}}\n"
