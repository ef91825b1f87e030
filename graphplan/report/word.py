"""Markdown → Word: the explanatory note as a .docx document to edit and hand in.

markdown-it-py parses the Markdown the note is written in, as for the HTML
and the LaTeX (:mod:`graphplan.report.markdown`); python-docx writes the
document:

- the note's title as the document's title, its sections, positions and
  plans as headings 1 to 3, unnumbered, since the note numbers its own;
- the textbook's symbols with their indices as sub- and superscript runs
  (:mod:`graphplan.report.symbols`), bold where the Markdown is bold;
- the lists of readings as Word's bullet or numbered lists;
- a table in a grid, its header row bold and repeated on every page it runs
  onto, each column aligned as the Markdown aligns it, and the paragraph
  right before it (the note's "Table 3. ...") kept on the same page; a wide
  table set smaller, and its columns narrowed to the line;
- a figure's drawing as a picture (PNG at 200 dpi as printed), its natural
  size or smaller to fit the page, centred over its caption on the same page;
- an A4 page with the margins of the LaTeX note (30 mm left, 10 mm right,
  20 mm top and bottom), numbered at the foot in the centre as that note is,
  the text in the language of the note, so that Word checks its spelling
  and hyphenates it in that language.

Fonts are ones a reader's Word has: Times New Roman for Latin and Cyrillic,
SimSun for Chinese (another font of the script where it is missing).  The
file is the same for the same note: its parts are stored with one fixed
time and it carries no date.
"""

from __future__ import annotations

import io
import math
import zipfile
from collections.abc import Collection, Mapping
from dataclasses import dataclass

from docx import Document as WordDocument
from docx.enum.style import WD_STYLE_TYPE
from docx.enum.table import WD_TABLE_ALIGNMENT
from docx.enum.text import WD_ALIGN_PARAGRAPH
from docx.oxml import OxmlElement
from docx.oxml.ns import qn
from docx.shared import Mm, Pt, Twips
from lxml.etree import SubElement
from markdown_it.tree import SyntaxTreeNode

from ..render import export
from ..render.primitives import FONT_SIZE_PER_CAP, text_width
from .markdown import picture_source, plain, table_parts, tree
from .symbols import Symbol, pieces

# Word's language tags of the note's locales.
_LANGUAGES = {"en": "en-GB", "ru": "ru-RU", "zh": "zh-CN"}
_LATIN_FONT = "Times New Roman"
_EAST_ASIAN_FONT = "SimSun"
_BODY_PT = 12.0
# A table's type sizes, largest first: one of more columns than _WIDE_TABLE starts a size smaller, so that its
# numbers keep to one line, and any table takes the first size at which its longest words fit the line.
_WIDE_TABLE = 5
_TABLE_PT = (10.0, 9.0, 8.0)
# The line a table spreads over: A4 less the margins (mm); what a cell keeps clear of its borders (Word's
# default 0.19 cm a side); a point and a twip (Word's twentieth of one) in mm.
_LINE_MM = 170.0
_CELL_PADDING_MM = 3.8
_POINT_MM = 25.4 / 72.0
_TWIP_MM = _POINT_MM / 20.0
# A header no wider than this (em) stays on one line where the table has room.
_HEADER_LINE_EM = 7.0
# A table of at most this many rows is kept on one page (a third of one at the table's size); a longer one
# runs on, its header repeated, and keeps only its header with its first row.
_KEPT_TOGETHER_ROWS = 20
# The side a Markdown column is aligned to, in Word.
_ALIGN = {"l": WD_ALIGN_PARAGRAPH.LEFT, "c": WD_ALIGN_PARAGRAPH.CENTER, "r": WD_ALIGN_PARAGRAPH.RIGHT}
# Every part of the file is stored at this time (the zip format's earliest), so that a note gives one file.
_STORED_AT = (1980, 1, 1, 0, 0, 0)
# A figure's picture: the height it may take on the page with its caption under it (mm), and its resolution as
# printed (dots per inch).
_PICTURE_HEIGHT_MM = 230.0
_PICTURE_DPI = 200.0
# The most characters a document property may have (python-docx refuses more; Word's own limit).
_MOST_PROPERTY_CHARACTERS = 255


def note_docx(markdown_text: str, title: str, locale: str, pictures: Mapping[str, str] | None = None,
              author: str = "", verbatim: Collection[str] = ()) -> bytes:
    """The explanatory note ``markdown_text`` as a Word document (the bytes of a .docx file) titled ``title``,
    with the drawings its figures name (``plan_2.svg``) taken from ``pictures`` (file name → SVG text); its
    author is ``author`` where the scene names one (the project's), else the program that made it.  The user's own
    texts ``verbatim`` are set as typed, with no symbol's index."""
    document = WordDocument()
    _set_page(document)
    _set_styles(document, locale)
    _number_pages(document)
    parsed = tree(markdown_text)
    _Writer(document, _figures(parsed, pictures or {}), verbatim).blocks(parsed.children)
    properties = document.core_properties
    properties.title = _shortened(" ".join(title.split()), _MOST_PROPERTY_CHARACTERS)
    properties.language = _LANGUAGES.get(locale, locale)
    properties.author, properties.comments = _shortened(author, _MOST_PROPERTY_CHARACTERS) or "graphplan", ""
    # No date (python-docx's template carries its own): the same note gives the same file.
    for dated in ("dcterms:created", "dcterms:modified", "cp:lastPrinted"):
        for element in properties._element.findall(qn(dated)):
            properties._element.remove(element)
    written = io.BytesIO()
    document.save(written)
    return _stored_at_one_time(written.getvalue())


def _shortened(text: str, most: int) -> str:
    """``text`` cut to ``most`` characters with an ellipsis where it is longer (the note's heading keeps it whole)."""
    return text if len(text) <= most else text[:most - 1].rstrip() + "…"


def _set_page(document) -> None:
    section = document.sections[0]
    section.page_width, section.page_height = Mm(210), Mm(297)
    section.left_margin, section.right_margin = Mm(30), Mm(10)
    section.top_margin, section.bottom_margin = Mm(20), Mm(20)


def _number_pages(document) -> None:
    """Each page's number in its footer, centred, as Word counts them (a PAGE field): a note handed in has its
    pages numbered at the foot (GOST 2.105), as the PDF and LaTeX notes have."""
    paragraph = document.sections[0].footer.paragraphs[0]
    paragraph.alignment = WD_ALIGN_PARAGRAPH.CENTER
    field = OxmlElement("w:fldSimple")
    field.set(qn("w:instr"), "PAGE")
    shown = OxmlElement("w:r")   # what a reader shows until it works the field out
    number = OxmlElement("w:t")
    number.text = "1"
    shown.append(number)
    field.append(shown)
    paragraph._p.append(field)


def _set_styles(document, locale: str) -> None:
    """The body font and language; headings in the body's fonts, black, as a printed note has them."""
    language = _LANGUAGES.get(locale, locale)
    for style in document.styles:
        if style.type != 1 or not (style.name == "Normal" or style.name.startswith(("Heading", "Title"))):
            continue
        style.font.name = _LATIN_FONT
        properties = style.element.get_or_add_rPr()
        fonts = properties.find(qn("w:rFonts"))
        if fonts is None:
            fonts = OxmlElement("w:rFonts")
            properties.insert(0, fonts)
        for key in ("w:ascii", "w:hAnsi", "w:cs"):
            fonts.set(qn(key), _LATIN_FONT)
        fonts.set(qn("w:eastAsia"), _EAST_ASIAN_FONT)
        for key in ("w:asciiTheme", "w:hAnsiTheme", "w:eastAsiaTheme", "w:cstheme"):
            fonts.attrib.pop(qn(key), None)
        if style.name != "Normal":
            style.font.color.rgb = None
        # The template's title stands on a blue rule: a printed note's has none.
        for rule in style.element.findall(f"{qn('w:pPr')}/{qn('w:pBdr')}"):
            rule.getparent().remove(rule)
    normal = document.styles["Normal"]
    normal.font.size = Pt(_BODY_PT)
    normal.paragraph_format.space_after = Pt(6)
    tag = normal.element.get_or_add_rPr().find(qn("w:lang"))
    if tag is None:
        tag = OxmlElement("w:lang")
        normal.element.get_or_add_rPr().append(tag)
    tag.set(qn("w:val"), language)
    tag.set(qn("w:eastAsia"), _LANGUAGES["zh"] if locale == "zh" else language)


@dataclass(frozen=True)
class _Figure:
    """A figure's drawing as the document holds it: its PNG, and its width on the page."""

    png: bytes
    width_mm: float


def _figures(note: SyntaxTreeNode, pictures: Mapping[str, str]) -> dict[str, _Figure]:
    """The drawings the note's figures show, each at its size or smaller to fit the page, rendered all at once."""
    shown = sorted({source for node in note.walk() if (source := picture_source(node)) in pictures})
    widths: dict[str, float] = {}
    renderings: dict[str, export.Rendering] = {}
    for name in shown:
        width, height = export.svg_size_mm(pictures[name])
        scale = min(1.0, _LINE_MM / width, _PICTURE_HEIGHT_MM / height)
        widths[name] = width * scale
        renderings[name] = export.Rendering(pictures[name], "png", _PICTURE_DPI * scale)
    return {name: _Figure(png, widths[name]) for name, png in export.rendered_all(renderings).items()}


class _Writer:
    """Writes the blocks of the note's syntax tree into the document, in order.

    Paragraphs and runs are built as python-docx's XML elements, each with the properties it has from the start:
    setting them one by one through python-docx's objects looked up the style by its name for each paragraph and
    searched an element's every possible child to place each property (a shaper's note took 6 s so).
    """

    def __init__(self, document, pictures: Mapping[str, _Figure], verbatim: Collection[str] = ()) -> None:
        self.document = document
        self.pictures = pictures
        self.verbatim = tuple(verbatim)
        self.body = document.element.body
        self.style_ids: dict[str, str | None] = {}
        self.table_style_id = document.part.get_style_id(document.styles["Table Grid"], WD_STYLE_TYPE.TABLE)

    def style_id(self, name: str) -> str | None:
        """The id of the paragraph style ``name``, as python-docx finds it (None for the default style)."""
        if name not in self.style_ids:
            self.style_ids[name] = self.document.part.get_style_id(name, WD_STYLE_TYPE.PARAGRAPH)
        return self.style_ids[name]

    def paragraph(self, style: str | None = None, keep_with_next: bool | None = None, alignment=None,
                  no_space_after: bool = False):
        """A new paragraph at the end of the document (its ``w:p`` element)."""
        paragraph = self.body.add_p()
        _paragraph_properties(paragraph, None if style is None else self.style_id(style), keep_with_next,
                              alignment, no_space_after, styled=style is not None)
        return paragraph

    def blocks(self, nodes, list_style: str | None = None, depth: int = 0) -> None:
        """``nodes`` in order; inside a list (``list_style``), nested ``depth`` lists deep."""
        nodes = list(nodes)
        for k, node in enumerate(nodes):
            if node.type == "heading":
                level = int(node.tag[1:])
                heading = "Title" if level == 1 else f"Heading {min(level - 1, 3)}"
                self.spans(self.paragraph(heading), node.children)
            elif node.type == "paragraph" and (source := picture_source(node)) in self.pictures:
                self.picture(self.pictures[source])
            elif node.type == "paragraph":
                # A table's caption stays on the page of its table, and the sentence that refers to a table or a
                # figure with its caption or picture; a list's items stand as lines.
                following = [node.type for node in nodes[k + 1:k + 3]]
                keep_with_next = following[:1] == ["table"] or following == ["paragraph", "table"] or (
                    k + 1 < len(nodes) and picture_source(nodes[k + 1]) in self.pictures)
                caption = bool(k) and picture_source(nodes[k - 1]) in self.pictures   # the figure's caption
                paragraph = self.paragraph(list_style, keep_with_next, WD_ALIGN_PARAGRAPH.CENTER if caption else None,
                                           no_space_after=list_style is not None)
                self.spans(paragraph, node.children)
            elif node.type in ("bullet_list", "ordered_list"):
                inside = depth + 1 if list_style is not None else 0
                style = ("List Number" if node.type == "ordered_list" else "List Bullet") + (
                    f" {min(inside + 1, 3)}" if inside else "")
                for item in node.children:
                    self.blocks(item.children, style, inside)
            elif node.type == "table":
                self.table(node)
            elif node.type == "hr":
                self.paragraph()
            else:
                raise ValueError(f"the note has a {node.type}, which its Word document does not write")

    def picture(self, figure: _Figure) -> None:
        """The drawing centred, kept on the page of its caption."""
        paragraph = self.document.add_paragraph()
        paragraph.alignment = WD_ALIGN_PARAGRAPH.CENTER
        paragraph.paragraph_format.keep_with_next = True
        paragraph.add_run().add_picture(io.BytesIO(figure.png), width=Mm(figure.width_mm))

    def table(self, node: SyntaxTreeNode) -> None:
        parts = table_parts(node)
        rows = ([parts.header] if parts.header else []) + list(parts.rows)
        count = max(len(row) for row in rows)
        table = self.document.add_table(rows=len(rows), cols=count)
        table._tbl.tblStyle_val = self.table_style_id   # as table.style sets it, the style found once a note
        table.alignment = WD_TABLE_ALIGNMENT.LEFT
        table.autofit = False
        columns = [[plain(row[c]) for row in rows if c < len(row)] for c in range(count)]
        points, widths = _column_widths(columns, bool(parts.header), _TABLE_PT[count > _WIDE_TABLE:])
        size = Pt(points)
        # The cells are taken as the rows' elements: python-docx finds one by its row and column (table.cell, a
        # column's cells) by listing every cell of the table, which took a long note's tables quadratic time.
        grid = [row.tc_lst for row in table._tbl.tr_lst]
        for c, width in enumerate(widths):
            # In whole twips, rounded down: columns that fill the line never run past it by their roundings.
            column = table.columns[c]
            column.width = Twips(math.floor(width / _TWIP_MM))
            for cells in grid:
                cells[c].width = column.width
        # Word keeps a table on one page when each of its rows but the last keeps with the next.
        kept = len(rows) - 1 if len(rows) <= _KEPT_TOGETHER_ROWS else int(bool(parts.header))
        for r, (row, cells) in enumerate(zip(rows, grid)):
            for c, cell in enumerate(cells):
                paragraph = cell.p_lst[0]
                if c >= len(row):   # a cell the row leaves out: empty, as it stands
                    _paragraph_properties(paragraph, None, r < kept, None, no_space_after=False)
                    continue
                side = parts.sides[c] if c < len(parts.sides) else "l"
                _paragraph_properties(paragraph, None, r < kept, _ALIGN[side], no_space_after=True)
                self.spans(paragraph, row[c].children, bold=r == 0 and bool(parts.header), size=size)
        if parts.header:
            _repeat_as_header(table.rows[0])
        for row in table.rows:
            _never_split(row)
        self.paragraph()   # the space under a table, as under a paragraph

    def spans(self, paragraph, nodes, bold: bool = False, italic: bool = False, size=None) -> None:
        """The inline ``nodes`` as runs at the end of ``paragraph`` (a ``w:p`` element)."""
        for node in nodes:
            if node.type == "text":
                self.text(paragraph, node.content, bold, italic, size)
            elif node.type == "strong":
                self.spans(paragraph, node.children, True, italic, size)
            elif node.type == "em":
                self.spans(paragraph, node.children, bold, True, size)
            elif node.type == "code_inline":
                run = SubElement(paragraph, _RUN)
                fonts = SubElement(SubElement(run, _RUN_PROPERTIES), qn("w:rFonts"))
                fonts.set(qn("w:ascii"), "Courier New")
                fonts.set(qn("w:hAnsi"), "Courier New")
                _add_text(run, node.content)
            elif node.type == "softbreak":
                _add_text(SubElement(paragraph, _RUN), " ")
            elif node.type == "hardbreak":
                SubElement(SubElement(paragraph, _RUN), qn("w:br"))
            else:   # the block's inline node, a link or an image: its text
                self.spans(paragraph, node.children, bold, italic, size)

    def text(self, paragraph, text: str, bold: bool, italic: bool, size) -> None:
        """``text`` as runs, a symbol's index below the line and its component above it."""
        for piece in pieces(text, self.verbatim):
            parts = ((piece, ""),) if isinstance(piece, str) else _symbol_runs(piece)
            for content, position in parts:
                run = SubElement(paragraph, _RUN)
                # Every run has its properties, empty where it is plain (as python-docx leaves them when asked for
                # no bold and no italic); they stand in the order Word's schema gives them.
                properties = SubElement(run, _RUN_PROPERTIES)
                if bold:
                    SubElement(properties, _BOLD)
                if italic:
                    SubElement(properties, _ITALIC)
                if size is not None:
                    SubElement(properties, _SIZE).val = size
                if position:
                    SubElement(properties, _VERTICAL_ALIGN).val = "subscript" if position == "sub" else "superscript"
                _add_text(run, content)


# The elements a run is made of, by their names as lxml knows them.
_RUN, _RUN_PROPERTIES, _TEXT, _SPACE = qn("w:r"), qn("w:rPr"), qn("w:t"), qn("xml:space")
_BOLD, _ITALIC, _SIZE, _VERTICAL_ALIGN = qn("w:b"), qn("w:i"), qn("w:sz"), qn("w:vertAlign")


def _paragraph_properties(paragraph, style_id: str | None, keep_with_next: bool | None, alignment,
                          no_space_after: bool, styled: bool = False) -> None:
    """The properties of the new paragraph ``paragraph`` (a ``w:p`` element), in the order Word's schema gives
    them: its style (a style asked for has them even where it is the default one), whether it keeps with the next
    paragraph (``w:val="0"`` where it is asked not to), no space after it, its alignment."""
    if not styled and keep_with_next is None and alignment is None and not no_space_after:
        return
    properties = SubElement(paragraph, qn("w:pPr"))   # the first child, as the paragraph is new and empty
    if style_id is not None:
        SubElement(properties, qn("w:pStyle")).val = style_id
    if keep_with_next is not None:
        SubElement(properties, qn("w:keepNext")).val = keep_with_next
    if no_space_after:
        SubElement(properties, qn("w:spacing")).after = Pt(0)
    if alignment is not None:
        SubElement(properties, qn("w:jc")).val = alignment


def _add_text(run, text: str) -> None:
    """``text`` in ``run`` (a ``w:r`` element), as python-docx writes it: a tab or a line break as its element."""
    if any(special in text for special in "\t\r\n"):
        run.text = text
    elif text:
        element = SubElement(run, _TEXT)
        element.text = text
        if len(text.strip()) < len(text):
            element.set(_SPACE, "preserve")


def _column_widths(columns: list[list[str]], headed: bool, sizes: tuple[float, ...]) -> tuple[float, list[float]]:
    """The type size (pt) of a table and each column's width (mm): the first of ``sizes`` at which the columns
    narrowed to their longest words fit the line, else the last.  A column is as wide as its widest cell where
    the table fits the line, else its longest word and a share of the room left in proportion to how much wider
    its cells would be (as a browser sets a table).  A header wider than :data:`_HEADER_LINE_EM` may wrap, and
    claims only that."""
    for points in sizes:
        least, natural = _column_bounds(columns, headed, points)
        if sum(least) <= _LINE_MM:
            break
    if sum(natural) <= _LINE_MM:
        return points, natural
    if sum(least) >= _LINE_MM:
        # Too wide even at the smallest size: narrowed to the line all in proportion.  Their words are measured
        # generously (as the drawings' sans serif, wider than the note's Times), and still fit as a rule.
        return points, [w * _LINE_MM / sum(least) for w in least]
    spare, wanting = _LINE_MM - sum(least), [n - w for n, w in zip(natural, least)]
    return points, [w + spare * extra / sum(wanting) for w, extra in zip(least, wanting)]


def _column_bounds(columns: list[list[str]], headed: bool, points: float) -> tuple[list[float], list[float]]:
    """Each column's least width (its longest word) and natural width (its widest cell, a long header's
    :data:`_HEADER_LINE_EM`), mm, at ``points``."""
    em = points * _POINT_MM

    def width(text: str, header: bool) -> float:   # as the drawings measure their words, at a cap height of em
        return text_width(text, em / FONT_SIZE_PER_CAP, "bold" if header else "normal")

    least, natural = [], []
    for column in columns:
        header, body = (column[0], column[1:]) if headed and column else (None, column)
        words = [width(word, k == 0 and header is not None) for k, text in enumerate(column) for word in text.split()]
        least.append(max(words, default=0.0) + _CELL_PADDING_MM)
        claims = [width(text, False) for text in body]
        if header is not None:
            claims.append(min(width(header, True), _HEADER_LINE_EM * em))
        natural.append(max(least[-1], max(claims, default=0.0) + _CELL_PADDING_MM))
    return least, natural


def _symbol_runs(symbol: Symbol) -> tuple[tuple[str, str], ...]:
    return tuple((content, position) for content, position in ((symbol.base, ""), (symbol.index, "sub"),
                                                             (symbol.component, "super")) if content)


def _repeat_as_header(row) -> None:
    """Word repeats a row marked so at the top of every page the table runs onto."""
    _mark_row(row, "w:tblHeader")


def _never_split(row) -> None:
    """A row marked so moves whole to the next page rather than part its lines."""
    _mark_row(row, "w:cantSplit")


def _mark_row(row, tag: str) -> None:
    mark = OxmlElement(tag)
    mark.set(qn("w:val"), "true")
    row._tr.get_or_add_trPr().append(mark)


def _stored_at_one_time(package: bytes) -> bytes:
    """The .docx with every part stored at :data:`_STORED_AT`, in the order python-docx wrote them."""
    written = io.BytesIO()
    with zipfile.ZipFile(io.BytesIO(package)) as source, zipfile.ZipFile(written, "w", zipfile.ZIP_DEFLATED) as out:
        for info in source.infolist():
            stored = zipfile.ZipInfo(info.filename, date_time=_STORED_AT)
            stored.compress_type = zipfile.ZIP_DEFLATED
            out.writestr(stored, source.read(info.filename))
    return written.getvalue()
