"""A student's review of the exports: the sheets taken into a CAD program (DXF) and printed (PDF, PNG).

Each sheet is made as a run makes it (:func:`graphplan.deliverables.encoded` of a sheet's drawing) and its files
are read back with other tools than the ones that wrote them: the SVG with ElementTree, the DXF with ezdxf's
reader, the PDF with pdfium, the PNG with Pillow. The SVG is the reference: what the DXF holds must stand where the
SVG draws it, y turned up (the SVG's y runs down from the sheet's top edge, the DXF's up from its bottom edge).

* A load diagram's ordinates (the thin lines up from its axis to the load at each position) went to a DXF layer of
  their own name, LOAD-4-ORDINATES (on a sheet LOAD-DIAGRAMS-LOAD-4-ORDINATES), one layer for each loaded link,
  where every other thin line of a drawing goes to CONSTRUCTION.
"""

from __future__ import annotations

import functools
import io
import re
from itertools import pairwise
from pathlib import Path
from xml.etree import ElementTree

import pytest
from dxf_texts import read_text

from graphplan import deliverables
from graphplan.analysis import analyse
from graphplan.load_diagrams import of_analysis
from graphplan.render import drawings, load_diagrams, plans, positions
from graphplan.render.dxf import CONSTRUCTION, LAYER_WORDS, SHEET, TEXT, dxf_layer
from graphplan.render.export import DEFAULT_DPI
from graphplan.render.primitives import Polyline
from graphplan.render.sheet import kinematics_sheet
from graphplan.render.title_block import Details
from graphplan.scene import loads
from graphplan.starters import starter

ezdxf = pytest.importorskip("ezdxf")
pytest.importorskip("cairosvg")
Image = pytest.importorskip("PIL.Image")

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
SVG = "{http://www.w3.org/2000/svg}"
MM_PER_INCH = 25.4
POINTS_PER_INCH = 72.0
# ISO 216 in mm, landscape: what a student's printer and CAD template know the formats as.
ISO_216 = {"A1": (841.0, 594.0), "A3": (420.0, 297.0), "A4": (297.0, 210.0)}
# Coordinates are written to the SVG with three decimals.
SVG_ROUNDING = 0.0015
KNOWN_LAYERS = set(LAYER_WORDS.values()) | {SHEET, TEXT}


def scene_text(name: str, locale: str) -> str:
    text = (FIXTURES / name).read_text(encoding="utf-8")
    return re.sub(r'(?m)^locale\s*=.*$', f'locale = "{locale}"', text)


@functools.cache
def ratchet_sheet_files(locale: str) -> dict[str, str | bytes]:
    """The ratchet's plan of positions and its first plan sheet on one A1 sheet, in every drawing format."""
    analysis = analyse(loads(scene_text("ratchet_crank_rocker.toml", locale)))
    panels = [positions.layout(drawings.positions_plan(analysis)),
              plans.layout(drawings.plan_sheet(analysis, analysis.plans[0].index))]
    details = Details(title="Ratchet", author="A. Student", designation="TMM.01.00")
    (sheet,) = kinematics_sheet(panels, "A1", locale=locale, scale=0.0025, details=details)
    drawing = deliverables.Drawing("sheet_1", sheet.layers, sheet.size)
    return deliverables.encoded(drawing, ("svg", "png", "pdf", "dxf"))


@functools.cache
def rotor_sheet_files(locale: str) -> dict[str, str | bytes]:
    """The rotor starter's balancing sheet on an A4, which it stands upright on, as the run makes it."""
    scene = loads(starter("rotor", locale=locale) + '\n[drawing]\nsheet = "A4"\n')
    (drawing,) = deliverables.drawings(scene, None, ("sheets",))
    return deliverables.encoded(drawing, ("svg", "png", "pdf", "dxf"))


def read_svg(svg: str) -> dict:
    """The SVG's size in mm and what it draws: path vertices (with their dashes and widths), circles, texts."""
    root = ElementTree.fromstring(svg)
    width, height = (float(root.get(name).removesuffix("mm")) for name in ("width", "height"))
    paths, circles, texts = [], [], []
    for element in root.iter():
        tag = element.tag.removeprefix(SVG)
        if tag == "path":
            points = [(float(x), float(y)) for x, y in re.findall(r"(-?[\d.]+),(-?[\d.]+)", element.get("d"))]
            paths.append((points, element.get("stroke-dasharray"), float(element.get("stroke-width")),
                          element.get("fill")))
        elif tag == "circle":
            circles.append(tuple(float(element.get(key)) for key in ("cx", "cy", "r")))
        elif tag == "text":
            turned = re.match(r"rotate\((-?[\d.]+)", element.get("transform") or "")
            texts.append({"text": "".join(element.itertext()), "x": float(element.get("x")),
                          "y": float(element.get("y")), "size": float(element.get("font-size")),
                          "anchor": element.get("text-anchor"),
                          "rotation": -float(turned.group(1)) % 360.0 if turned else 0.0})
    return {"size": (width, height), "paths": paths, "circles": circles, "texts": texts}


def read_dxf(data: bytes):
    return ezdxf.read(io.StringIO(data.decode("utf-8")))


def read_placed(entity) -> dict:
    """What a TEXT or an MTEXT (a text with indices) reads as, and where it stands: its baseline point, its height,
    its alignment and its turn."""
    if entity.dxftype() == "MTEXT":
        # Attached by the bottom of its line, its baseline, at the left, the centre or the right.
        return {"text": read_text(entity), "at": entity.dxf.insert, "height": entity.dxf.char_height,
                "anchor": {7: "start", 8: "middle", 9: "end"}[entity.dxf.attachment_point],
                "rotation": entity.get_rotation() % 360.0, "runs": True}
    return {"text": entity.dxf.text, "at": entity.dxf.insert if entity.dxf.halign == 0 else entity.dxf.align_point,
            "height": entity.dxf.height, "anchor": {0: "start", 1: "middle", 2: "end"}[entity.dxf.halign],
            "rotation": entity.dxf.rotation % 360.0, "runs": False}


def near(point, points, tolerance=SVG_ROUNDING * 2) -> bool:
    return any(abs(point[0] - x) <= tolerance and abs(point[1] - y) <= tolerance for x, y in points)


SHEETS = [pytest.param(functools.partial(ratchet_sheet_files, locale), "A1", False, id=f"ratchet-A1-{locale}")
          for locale in ("en", "ru", "zh")] + [
    pytest.param(functools.partial(rotor_sheet_files, "zh"), "A4", True, id="rotor-A4-zh")]


@pytest.mark.parametrize(("files", "form", "upright"), SHEETS)
def test_dxf_of_a_sheet_is_in_millimetres_its_extents_the_sheet_and_nothing_off_it(files, form, upright):
    from ezdxf import bbox

    written = files()
    width, height = ISO_216[form][::-1] if upright else ISO_216[form]
    assert read_svg(written["sheet_1.svg"])["size"] == (width, height)
    document = read_dxf(written["sheet_1.dxf"])
    assert document.header["$INSUNITS"] == 4 and document.header["$MEASUREMENT"] == 1   # mm, metric
    for corner, expected in (("$EXTMIN", (0.0, 0.0)), ("$EXTMAX", (width, height)),
                             ("$LIMMIN", (0.0, 0.0)), ("$LIMMAX", (width, height))):
        assert document.header[corner][:2] == pytest.approx(expected), corner
    space = document.modelspace()
    drawn = bbox.extents(entity for entity in space if entity.dxftype() not in ("TEXT", "MTEXT"))
    assert (*drawn.extmin.vec2, *drawn.extmax.vec2) == pytest.approx((0.0, 0.0, width, height), abs=1e-6)
    # The texts too, measured in their own fonts (or estimated where ezdxf finds none), stay on the paper.
    for entity in space.query("TEXT MTEXT"):
        box = bbox.extents([entity])
        assert box.extmin.x >= 0.0 and box.extmin.y >= 0.0, read_text(entity)
        assert box.extmax.x <= width and box.extmax.y <= height, read_text(entity)
    assert {entity.dxf.layer for entity in space} <= KNOWN_LAYERS


@pytest.mark.parametrize(("files", "form", "upright"), SHEETS)
def test_dxf_lines_and_circles_stand_where_the_svg_draws_them_with_y_turned_up(files, form, upright):
    written = files()
    svg = read_svg(written["sheet_1.svg"])
    height = svg["size"][1]
    space = read_dxf(written["sheet_1.dxf"]).modelspace()

    def turned_up(x, y):
        return x, height - y

    svg_vertices = {turned_up(*point) for points, *_ in svg["paths"] for point in points}
    polylines = [[tuple(vertex) for vertex in entity.get_points("xy")] for entity in space.query("LWPOLYLINE")]
    heads = [[tuple(vertex)[:2] for vertex in path.vertices] for entity in space.query("HATCH")
             for path in entity.paths.paths if hasattr(path, "vertices")]
    assert polylines and heads
    # Every vertex of a line or an arrowhead is a vertex of the SVG; an arrow's shaft runs to its tip.
    assert all(near(vertex, svg_vertices) for outline in polylines + heads for vertex in outline)
    # And every SVG vertex is the DXF's, or on a DXF line (the SVG stops a shaft short under its head).
    segments = [pair for polyline in polylines for pair in pairwise(polyline)]
    dxf_vertices = {vertex for outline in polylines + heads for vertex in outline}

    def on_a_line(point) -> bool:
        for (ax, ay), (bx, by) in segments:
            length = ((bx - ax) ** 2 + (by - ay) ** 2) ** 0.5
            along = ((point[0] - ax) * (bx - ax) + (point[1] - ay) * (by - ay)) / length if length else -1.0
            aside = abs((point[0] - ax) * (by - ay) - (point[1] - ay) * (bx - ax)) / length if length else 1.0
            if -0.01 <= along <= length + 0.01 and aside <= 0.01:
                return True
        return False

    assert all(near(vertex, dxf_vertices) or on_a_line(vertex) for vertex in svg_vertices)
    circles = sorted((round(entity.dxf.center.x, 2), round(entity.dxf.center.y, 2), round(entity.dxf.radius, 2))
                     for entity in space.query("CIRCLE"))
    expected = sorted((round(x, 2), round(height - y, 2), round(r, 2)) for x, y, r in svg["circles"])
    assert len(circles) == len(expected) > 0
    assert [value for circle in circles for value in circle] == pytest.approx(
        [value for circle in expected for value in circle], abs=0.011)


@pytest.mark.parametrize(("files", "form", "upright"), SHEETS)
def test_dxf_texts_are_the_svg_s_at_its_places_heights_and_turns_in_their_own_script(files, form, upright):
    written = files()
    svg = read_svg(written["sheet_1.svg"])
    height = svg["size"][1]
    raw = written["sheet_1.dxf"].decode("utf-8")
    document = read_dxf(written["sheet_1.dxf"])
    # R2007 and later are UTF-8 whatever $DWGCODEPAGE says: the words stand in the file as they read.
    assert document.dxfversion >= "AC1021"
    assert "\\U+" not in raw
    read = [read_placed(entity) for entity in document.modelspace().query("TEXT MTEXT")]
    assert sorted(text["text"] for text in read) == sorted(text["text"] for text in svg["texts"])
    script = {"ru": r"[а-яА-Я]", "zh": r"[\u4e00-\u9fff]", "en": r"[A-Za-z]"}
    locale = "zh" if any(re.search(script["zh"], text["text"]) for text in read) else \
        "ru" if any(re.search(script["ru"], text["text"]) for text in read) else "en"
    # An MTEXT's words stand between its codes for the indices.
    assert all(text["text"] in raw for text in read if re.search(script[locale], text["text"]) and not text["runs"])
    # DejaVu Sans and Noto Sans CJK have caps 0.73 and 0.733 em high: a TEXT's height is its cap height.
    ratios = [text["size"] / dxf["height"] for text, dxf in zip(svg["texts"], read, strict=True)]
    assert ratios == pytest.approx([ratios[0]] * len(ratios), rel=2e-3) and 1 / 0.75 < ratios[0] < 1 / 0.70
    for text, dxf in zip(svg["texts"], read, strict=True):
        assert dxf["text"] == text["text"]
        assert dxf["at"].y == pytest.approx(height - text["y"], abs=SVG_ROUNDING)
        assert dxf["rotation"] == pytest.approx(text["rotation"], abs=1e-3)
        # A text set run by run (indices, two scripts) keeps its anchor on the SVG's text, as the DXF's.
        assert dxf["at"].x == pytest.approx(text["x"], abs=SVG_ROUNDING)
        assert dxf["anchor"] == text["anchor"]


@pytest.mark.parametrize(("files", "form", "upright"), SHEETS)
def test_dxf_strokes_keep_the_svg_s_widths_and_dashes(files, form, upright):
    written = files()
    svg = read_svg(written["sheet_1.svg"])
    height = svg["size"][1]
    document = read_dxf(written["sheet_1.dxf"])
    by_start = {}
    for entity in document.modelspace().query("LWPOLYLINE"):
        start = tuple(round(value, 2) for value in entity.get_points("xy")[0])
        by_start.setdefault(start, []).append(entity)
    dashed = 0
    for points, dashes, width, fill in svg["paths"]:
        candidates = by_start.get((round(points[0][0], 2), round(height - points[0][1], 2)), [])
        if not candidates or fill not in ("none", "white"):  # an arrowhead or a filled block: a hatch too
            continue
        weights = {entity.dxf.lineweight for entity in candidates}
        assert any(abs(weight - 100 * width) <= 5 for weight in weights), (points[0], width, weights)
        if dashes:
            dashed += 1
            pattern = [float(value) for value in re.split(r"[,\s]+", dashes.strip())]
            expected = [value if k % 2 == 0 else -value for k, value in enumerate(pattern * (len(pattern) % 2 + 1))]
            found = []
            for entity in candidates:
                linetype = document.linetypes.get(entity.dxf.linetype) if entity.dxf.hasattr("linetype") else None
                if linetype is not None:
                    found.append([tag.value for tag in linetype.pattern_tags.tags if tag.code == 49])
            assert any(elements == pytest.approx(expected) for elements in found), (points[0], dashes, found)
    assert dashed > 0, "a sheet with construction lines dashed"
    assert document.header["$LTSCALE"] == 1.0


@pytest.mark.parametrize(("files", "form", "upright"), SHEETS)
def test_png_and_pdf_of_a_sheet_are_the_format_s_size(files, form, upright):
    written = files()
    width, height = ISO_216[form][::-1] if upright else ISO_216[form]
    image = Image.open(io.BytesIO(written["sheet_1.png"]))
    dpi = DEFAULT_DPI
    assert image.size == (round(width / MM_PER_INCH * dpi), round(height / MM_PER_INCH * dpi))
    assert [pixels / image.info["dpi"][0] * MM_PER_INCH for pixels in image.size] == pytest.approx(
        [width, height], abs=0.2)
    pdf = written["sheet_1.pdf"]
    assert len(re.findall(rb"/Type\s*/Page\b", pdf)) == 1
    box = [float(value) for value in re.search(rb"/MediaBox\s*\[\s*([\d.\s-]+)\]", pdf).group(1).split()]
    to_points = POINTS_PER_INCH / MM_PER_INCH
    assert box == pytest.approx([0.0, 0.0, width * to_points, height * to_points], abs=1e-3)


@pytest.mark.parametrize(("files", "form", "upright"), SHEETS)
def test_pdf_of_a_sheet_holds_every_word_of_the_svg_as_text(files, form, upright):
    """Each text is set in a font with its glyphs and a map back to its characters: extracted from the PDF,
    Cyrillic and Chinese read as written (a missing glyph or font comes out as no text or as boxes)."""
    pdfium = pytest.importorskip("pypdfium2")
    written = files()
    page = pdfium.PdfDocument(written["sheet_1.pdf"])[0]
    extracted = re.sub(r"\s", "", page.get_textpage().get_text_range())
    texts = [text["text"] for text in read_svg(written["sheet_1.svg"])["texts"]]
    assert texts
    assert [text for text in texts if re.sub(r"\s", "", text) not in extracted] == []


def test_a_load_diagram_s_ordinates_go_to_construction_with_the_other_thin_lines():
    analysis = analyse(loads(scene_text("engine_slider_crank.toml", "en")))
    layers = load_diagrams.layout(of_analysis(analysis))
    ordinates = [layer for layer in layers if layer.name.endswith("-ordinates")]
    assert ordinates and all(layer.items for layer in ordinates)
    for layer in ordinates:
        assert {dxf_layer(layer.name, item) for item in layer.items} == {CONSTRUCTION}
        assert dxf_layer("load-diagrams-" + layer.name, layer.items[0]) == CONSTRUCTION  # as on a sheet
        assert all(isinstance(item, Polyline) for item in layer.items)
    assert {dxf_layer(layer.name, item) for layer in layers for item in layer.items} <= KNOWN_LAYERS
