"""The reports' one Markdown parser: markdown-it-py's CommonMark with tables, raw HTML off (the note's text is data).

The text is parsed once (:func:`tokens`). The HTML page renders
markdown-it's tokens with its own renderer; the LaTeX
(:mod:`graphplan.report.latex`) and the Word document
(:mod:`graphplan.report.word`) walk the syntax tree built of them
(:func:`tree`), whose nodes are named by their token types: ``heading`` (tag
``h1`` …), ``paragraph``, ``bullet_list``, ``ordered_list``, ``list_item``,
``table`` (``thead``, ``tbody``, ``tr``, ``th``, ``td``), ``hr``; inside a
block, ``inline`` with ``text``, ``strong``, ``em``, ``code_inline``,
``softbreak``, ``hardbreak``, ``link`` and ``image`` (a figure's picture alone in its
paragraph, :func:`picture_source`).
"""

from __future__ import annotations

import dataclasses
import functools
import re
from dataclasses import dataclass

from markdown_it import MarkdownIt
from markdown_it.token import Token
from markdown_it.tree import SyntaxTreeNode

# A table column's alignment, as markdown-it writes it on its cells, and as the side it is set to.
_SIDES = {"text-align:left": "l", "text-align:center": "c", "text-align:right": "r"}


# Marks CommonMark reads as markup wherever they stand in a line: code, emphasis, links and pictures, autolinks and
# tags, entities, a table's cells, a heading's closing #s, and the carets ``raised`` lifts (aBA^τ); and where a line
# begins (a [project] value has a line of its own) those that begin a block: a list's -, + or 1. (1)), a quote's >,
# a fence's ~~~, a setext heading's === (the others begin one only where they are markup anywhere).
_MARKUP = re.compile(r"(?P<anywhere>[\\`*_\[\]<&|#^])|^(?P<number>\d+)(?P<after>[.)])|^(?P<start>[-+=>~])")


# Chinese sets no space beside its full-width punctuation: the sentences joined with a Latin space read
# «比较。 运动副反力», «122.9°） 处», «N （负号».
_AFTER_FULL_WIDTH = re.compile(r"(?<=[。，；：！？、）」])[ ]+")
_BEFORE_FULL_WIDTH = re.compile(r"[ ]+(?=[（「])")


def set_close(line: str) -> str:
    """A line of Chinese text without the Latin spaces beside its full-width punctuation."""
    return _BEFORE_FULL_WIDTH.sub("", _AFTER_FULL_WIDTH.sub("", line))


def literal(text: str) -> str:
    """``text`` of the user's own (a scene's title, a ``[project]`` value, a rotor's mass's name) as Markdown that
    reads as it is written.

    A title ``Project #3 *draft*`` was set in italics in every format, and a ``|`` split a table's cell: each mark
    CommonMark could read as markup where it stands is backslash-escaped, which it reads as the mark alone (the
    others left as typed, so that ``note.md`` reads as plain text too), and the HTML, LaTeX and Word writers then
    escape as their own markup needs.  Its line breaks, and the spaces round them, are one space: a heading and a
    cell are one line, and a line that went on with ``- `` or ``#`` would begin a list or a heading.
    """
    def escaped(found: re.Match[str]) -> str:
        if found["number"] is not None:
            return f"{found['number']}\\{found['after']}"
        return "\\" + (found["anywhere"] or found["start"])

    return _MARKUP.sub(escaped, " ".join(text.split()))


def user_texts(scene) -> tuple[str, ...]:
    """The scene's title and its ``[project]``'s words as the note shows them (each on one line), for the writers'
    symbol pass to leave as typed: the textbook's symbols are the note's, not the user's."""
    typed = [scene.title, *(getattr(scene.project, field.name) for field in dataclasses.fields(scene.project))]
    return tuple(" ".join(text.split()) for text in typed if isinstance(text, str) and text.strip())


def parser() -> MarkdownIt:
    """The note's Markdown: CommonMark with GitHub's tables; raw HTML is text."""
    return MarkdownIt("commonmark", {"html": False}).enable("table")


@functools.lru_cache(maxsize=8)
def tokens(markdown_text: str) -> tuple[Token, ...]:
    """markdown-it's tokens of ``markdown_text``, parsed once for all the writers of a run (the note is long,
    and the HTML, the LaTeX and the Word document each read it); neither renderer nor tree changes them."""
    return tuple(parser().parse(markdown_text))


def tree(markdown_text: str) -> SyntaxTreeNode:
    """The syntax tree of ``markdown_text``: its root's children are the blocks in order."""
    return SyntaxTreeNode(list(tokens(markdown_text)))


@dataclass(frozen=True)
class TableParts:
    """A table's header cells (empty when it has none), its body's rows of cells and each column's side (l, c, r)."""

    header: tuple[SyntaxTreeNode, ...]
    rows: tuple[tuple[SyntaxTreeNode, ...], ...]
    sides: tuple[str, ...]


def table_parts(table: SyntaxTreeNode) -> TableParts:
    """The parts of a ``table`` node; a cell's content is its ``inline`` child's."""
    header: tuple[SyntaxTreeNode, ...] = ()
    rows: list[tuple[SyntaxTreeNode, ...]] = []
    for section in table.children:
        for row in section.children:
            if section.type == "thead":
                header = tuple(row.children)
            else:
                rows.append(tuple(row.children))
    first = header or (rows[0] if rows else ())
    sides = tuple(_SIDES.get(str(cell.attrs.get("style", "")), "l") for cell in first)
    return TableParts(header, tuple(rows), sides)


def plain(node: SyntaxTreeNode) -> str:
    """The text of ``node`` as written, without its markup (a break as a space), to measure it."""
    if node.type in ("text", "code_inline"):
        return node.content
    if node.type in ("softbreak", "hardbreak"):
        return " "
    return "".join(plain(child) for child in node.children)


def picture_source(block: SyntaxTreeNode) -> str | None:
    """The file of the picture a paragraph holds alone (the note's figure, ``![caption](plan_2.svg)``), else None."""
    if block.type != "paragraph" or len(block.children) != 1:
        return None
    spans = block.children[0].children
    if len(spans) != 1 or spans[0].type != "image":
        return None
    return str(spans[0].attrs.get("src", ""))
