"""PNG, PDF and DXF of the drawings: sizes, glyphs that render, a DXF that reads back as it was written.

PNG and PDF are rendered by cairosvg from the SVG backend's text; their sizes follow
from the SVG's size in mm (1 in = 25.4 mm, a PDF point 1/72 in). A label in Cyrillic or
Chinese must put ink in its box: two different strings of the same script must give
different pixels, which a font without the glyphs (every glyph the same empty box)
cannot. The DXF of a real plan sheet is read back with ezdxf: every primitive is there
on the DXF layer its graphplan layer maps to, every text with its characters, and the
drawing's extents are those of the SVG's page less its margin.
"""

from __future__ import annotations

import functools
import io
import re
import shutil
import subprocess
import sys
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render import drawings, plans
from graphplan.render.dxf import (
    AXES,
    CONSTRUCTION,
    CURVES,
    LAYER_WORDS,
    LINKS,
    SHEET,
    TEXT,
    VECTORS,
    dxf_layer,
    layers_to_dxf,
)
from graphplan.render.primitives import Arrow, Circle, Layer, Polyline, Text, bounds, bounds_of, text_extent
from graphplan.render.svg import to_svg
from graphplan.scene import loads

cairosvg = pytest.importorskip("cairosvg")
ezdxf = pytest.importorskip("ezdxf")
Image = pytest.importorskip("PIL.Image")

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
MM_PER_INCH = 25.4


def font_installed(family: str) -> bool:
    """Whether fontconfig (which cairo asks) has ``family``."""
    if shutil.which("fc-list") is None:
        return False
    found = subprocess.run(["fc-list", f":family={family}", "family"], capture_output=True, text=True, check=False)
    return bool(found.stdout.strip())


needs_dejavu = pytest.mark.skipif(not font_installed("DejaVu Sans"), reason="DejaVu Sans is not installed")
needs_noto_cjk = pytest.mark.skipif(not font_installed("Noto Sans CJK SC"),
                                    reason="Noto Sans CJK is not installed (apt-get install fonts-noto-cjk)")


# --- PNG and PDF -----------------------------------------------------------------------------------------------

PAGE = (120.0, 60.0)   # mm


def page_with(*texts: Text) -> str:
    return to_svg([Layer("labels", texts)], page=PAGE)


def rendered(svg: str, dpi: float) -> np.ndarray:
    from graphplan.render.export import svg_to_png

    image = Image.open(io.BytesIO(svg_to_png(svg, dpi=dpi))).convert("L")
    return np.asarray(image)


def ink(pixels: np.ndarray, extent: tuple[float, float, float, float], dpi: float) -> np.ndarray:
    """The pixels of a box given in paper mm (y up from the bottom of :data:`PAGE`)."""
    x0, y0, x1, y1 = extent
    scale = dpi / MM_PER_INCH
    rows = slice(int((PAGE[1] - y1) * scale), int(np.ceil((PAGE[1] - y0) * scale)))
    columns = slice(int(x0 * scale), int(np.ceil(x1 * scale)))
    return pixels[rows, columns]


def test_png_has_the_size_of_the_page_at_the_resolution():
    for dpi in (96, 150, 300):
        pixels = rendered(page_with(Text((10.0, 10.0), "A")), dpi)
        assert pixels.shape == (round(PAGE[1] / MM_PER_INCH * dpi), round(PAGE[0] / MM_PER_INCH * dpi))


def test_png_says_its_resolution_so_that_it_prints_at_the_drawing_s_size():
    """cairo writes no pHYs chunk: a viewer took an A4 sheet at 150 dpi for 72 dpi and printed it twice its size."""
    from graphplan.render.export import svg_to_png

    for dpi in (96, 150, 300):
        image = Image.open(io.BytesIO(svg_to_png(page_with(Text((10.0, 10.0), "A")), dpi=dpi)))
        image.load()  # reads every chunk and checks its CRC
        assert image.info["dpi"] == pytest.approx((dpi, dpi), abs=0.013)  # whole pixels per metre
        printed_mm = [pixels / image.info["dpi"][0] * MM_PER_INCH for pixels in image.size]
        assert printed_mm == pytest.approx(PAGE, abs=0.2)


def test_png_rejects_a_resolution_that_is_not_positive():
    from graphplan.render.export import svg_to_png

    with pytest.raises(ValueError, match="dpi must be > 0"):
        svg_to_png(page_with(), dpi=0)


def script_renders(first: str, second: str) -> None:
    """Both strings put ink in their boxes, none outside, and differ from each other."""
    dpi = 200
    a, b = Text((10.0, 40.0), first, 5.0, "start"), Text((10.0, 15.0), second, 5.0, "start")
    pixels = rendered(page_with(a, b), dpi)
    empty = ink(pixels, (70.0, 40.0, 110.0, 47.0), dpi)
    assert np.all(empty == 255)
    boxes = [ink(pixels, text_extent(text), dpi) for text in (a, b)]
    for box in boxes:
        assert np.count_nonzero(box < 128) > 0.03 * box.size
    width = min(box.shape[1] for box in boxes)
    height = min(box.shape[0] for box in boxes)
    difference = np.abs(boxes[0][:height, :width].astype(int) - boxes[1][:height, :width].astype(int))
    assert np.count_nonzero(difference > 128) > 0.02 * difference.size


@needs_dejavu
def test_cyrillic_label_renders_its_glyphs():
    script_renders("План скоростей", "Механизм звена")


@needs_noto_cjk
def test_chinese_label_renders_its_glyphs():
    script_renders("速度图解法", "机构运动简图")


def test_pdf_is_one_page_of_the_svg_size_without_a_date():
    from graphplan.render.export import svg_to_pdf

    svg = page_with(Text((10.0, 20.0), "μV = 0.02 (m/s)/mm"), Text((10.0, 10.0), "План"))
    pdf = svg_to_pdf(svg)
    assert pdf.startswith(b"%PDF-")
    assert len(re.findall(rb"/Type\s*/Page\b", pdf)) == 1
    boxes = re.findall(rb"/MediaBox\s*\[\s*([\d.\s-]+)\]", pdf)
    assert len(boxes) == 1
    x0, y0, x1, y1 = (float(v) for v in boxes[0].split())
    points_per_mm = 72.0 / MM_PER_INCH
    assert (x0, y0) == (0.0, 0.0)
    assert x1 == pytest.approx(PAGE[0] * points_per_mm, abs=1e-3)
    assert y1 == pytest.approx(PAGE[1] * points_per_mm, abs=1e-3)
    assert b"/CreationDate" not in pdf and b"/ModDate" not in pdf
    assert svg_to_pdf(svg) == pdf


def test_svg_alone_imports_neither_cairosvg_nor_ezdxf():
    code = ("import sys, graphplan.render.export, graphplan.render.dxf, graphplan.render.diagrams, "
            "graphplan.render.svg; print(sorted(m for m in ('cairosvg', 'cairocffi', 'ezdxf') if m in sys.modules))")
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert found.stdout.strip() == "[]"


# Each starter's pieces with the plots and a drawing beside them: the note and the sheets would add neither.
@pytest.mark.parametrize("kind, pieces, drawing, plots", [
    ("flywheel", "dynamics", "dynamics", ("motion",)),
    ("rotor", "balancing,vibration", "rotor_balancing", ("vibration_magnification", "vibration_transmissibility"))])
def test_the_plots_come_as_png_and_pdf_of_their_own_size_beside_the_drawings(tmp_path, kind, pieces, drawing, plots):
    """A report takes the plots (matplotlib's SVG, sized in pt) in the formats asked for, as it takes the drawings:
    each PNG is the SVG's size at a print's 300 dpi (plot_style.PLOT_DPI) with the plot's lines inked across it, each
    PDF one page of that size; DXF, a drafting format, stays with the drawings."""
    from graphplan.cli import main
    from graphplan.starters import starter

    scene = tmp_path / f"{kind}.toml"
    scene.write_text(starter(kind), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--format", "png,pdf,dxf", "--only", pieces]) == 0
    assert all((out / f"{drawing}.{form}").is_file() for form in ("svg", "png", "pdf", "dxf"))
    for name in plots:
        svg = (out / f"{name}.svg").read_text(encoding="utf-8")
        width, height = (float(v) for v in re.search(r'<svg[^>]* width="([\d.]+)pt" height="([\d.]+)pt"', svg).groups())
        pixels = np.asarray(Image.open(out / f"{name}.png").convert("L"))
        assert pixels.shape == (round(height / 72 * 300), round(width / 72 * 300))
        inked = pixels < 128
        # Ink in every tenth of the width and of the height: axes, curves and lettering, not a blank page.
        assert all(band.any() for band in np.array_split(inked, 10, axis=1))
        assert all(band.any() for band in np.array_split(inked, 10, axis=0))
        pdf = (out / f"{name}.pdf").read_bytes()
        assert len(re.findall(rb"/Type\s*/Page\b", pdf)) == 1
        box = [float(v) for v in re.search(rb"/MediaBox\s*\[\s*([\d.\s-]+)\]", pdf).group(1).split()]
        assert box == pytest.approx([0.0, 0.0, width, height], abs=1e-3)
        assert not (out / f"{name}.dxf").exists()


# --- DXF -------------------------------------------------------------------------------------------------------


@functools.cache
def plan_sheet_layers(locale: str | None = None) -> tuple[Layer, ...]:
    text = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    if locale is not None:
        text = re.sub(r'(?m)^locale\s*=.*$', f'locale = "{locale}"', text)
    analysis = analyse(loads(text))
    return tuple(plans.layout(drawings.plan_sheet(analysis, analysis.plans[0].index)))


def read_back(layers) -> tuple[object, str]:
    stream = io.StringIO()
    layers_to_dxf(layers, stream)
    return ezdxf.read(io.StringIO(stream.getvalue())), stream.getvalue()


def expected_entities(layers) -> Counter:
    """(DXF layer, entity type) counted from the primitives: a fill other than white adds a HATCH."""
    expected: Counter = Counter()
    for layer in layers:
        for item in layer.items:
            target = dxf_layer(layer.name, item)
            if isinstance(item, Polyline):
                expected[target, "LWPOLYLINE"] += 1
                expected[target, "HATCH"] += item.fill not in (None, "white")
            elif isinstance(item, Circle):
                expected[target, "CIRCLE"] += 1
                expected[target, "HATCH"] += item.fill not in (None, "white")
            elif isinstance(item, Arrow):
                expected[target, "LWPOLYLINE"] += 1
                expected[target, "HATCH"] += 1
            else:
                expected[target, "TEXT"] += 1
    return +expected


def test_layer_names_map_by_their_words():
    assert dxf_layer("mechanism-links") == LINKS
    assert dxf_layer("body-II-3-4-links") == LINKS
    assert dxf_layer("velocity-lines") == CONSTRUCTION
    assert dxf_layer("lever-arm-Fu3") == CONSTRUCTION
    assert dxf_layer("acceleration-vectors") == VECTORS
    assert dxf_layer("velocity-rays") == CONSTRUCTION
    assert dxf_layer("velocity-curves") == CURVES
    assert dxf_layer("velocity-axes") == AXES
    assert dxf_layer("sheet-title") == SHEET
    assert dxf_layer("title-block") == dxf_layer("title-block", Text((0.0, 0.0), "A")) == SHEET
    assert dxf_layer("mechanism-links", Text((0.0, 0.0), "A")) == TEXT
    assert dxf_layer("sheet-frame", Text((0.0, 0.0), "A")) == SHEET
    assert dxf_layer("plane-L-reference") == CONSTRUCTION
    assert dxf_layer("odd name/x") == "ODD_NAME_X"


def test_every_layer_of_the_drawings_has_a_known_dxf_layer():
    from graphplan.dynamics import equivalent_model_of
    from graphplan.flywheel import flywheel_for
    from graphplan.kinematic_diagrams import of_analysis
    from graphplan.render import balancing, diagrams, dynamics, forces, positions
    from graphplan.rotor_balancing import BalancingSpec, RotatingMass, balance

    text = (FIXTURES / "shaper_six_bar.toml").read_text(encoding="utf-8")
    analysis = analyse(loads(text))
    model = equivalent_model_of(analysis)
    shaft = [RotatingMass(18, 0.05, 0, 0.0), RotatingMass(14, 0.06, -60, 0.08), RotatingMass(12, 0.06, -270, 0.28)]
    sheets = [positions.layout(drawings.positions_plan(analysis)), list(plan_sheet_layers()),
              diagrams.layout(of_analysis(analysis)), dynamics.layout(model, flywheel_for(model, 0.05)),
              balancing.layout(balance(BalancingSpec(shaft, planes=(0.04, 0.22), correction_radius=0.05)))]
    sheets += [forces.layout(drawings.force_sheet(analysis, p)) for p in analysis.plans if p.forces is not None]
    known = set(LAYER_WORDS.values()) | {SHEET, TEXT}
    for layers in sheets:
        for layer in layers:
            assert dxf_layer(layer.name) in known, layer.name
            assert {dxf_layer(layer.name, item) for item in layer.items} <= known, layer.name


@pytest.mark.parametrize("locale", [None, "zh"])
def test_dxf_of_a_plan_sheet_holds_every_primitive_on_its_layer(locale):
    layers = plan_sheet_layers(locale)
    document, _ = read_back(layers)
    found = Counter((entity.dxf.layer, entity.dxftype()) for entity in document.modelspace())
    assert found == expected_entities(layers)
    assert document.units == ezdxf.units.MM
    assert document.header["$INSUNITS"] == 4


@pytest.mark.parametrize("locale", [None, "zh"])
def test_dxf_texts_round_trip_with_a_font_that_has_their_glyphs(locale):
    layers = plan_sheet_layers(locale)
    document, _ = read_back(layers)
    written = [item for layer in layers for item in layer.items if isinstance(item, Text)]
    read = [entity for entity in document.modelspace() if entity.dxftype() == "TEXT"]
    assert sorted(entity.dxf.text for entity in read) == sorted(text.text for text in written)
    script = re.compile(r"[\u4e00-\u9fff]") if locale == "zh" else re.compile(r"[\u0400-\u04ff]")
    scripted = [entity for entity in read if script.search(entity.dxf.text)]
    assert scripted, "the sheet has words in the scene's script"
    for entity in read:
        style = document.styles.get(entity.dxf.style)
        font = style.dxf.font
        if re.search(r"[\u4e00-\u9fff]", entity.dxf.text):
            assert font.startswith("NotoSansCJK")
        else:
            assert font.startswith("DejaVuSans")
    # Texts are written in the order of the primitives.
    for entity, text in zip(read, written, strict=True):
        assert entity.dxf.text == text.text
        assert entity.dxf.height == pytest.approx(text.size)
        # The baseline point: the insertion for left-aligned text, the alignment point otherwise.
        where = entity.dxf.insert if text.anchor == "start" else entity.dxf.align_point
        assert (where.x, where.y) == pytest.approx(text.at)


def test_dxf_extents_are_the_svg_page_less_its_margin():
    from ezdxf import bbox

    layers = plan_sheet_layers()
    document, _ = read_back(layers)
    space = document.modelspace()
    # Lines and circles: exactly the primitives' bounds, arrowheads standing at most 1 mm aside.
    geometry = bbox.extents(entity for entity in space if entity.dxftype() != "TEXT")
    drawn = bounds_of(item for layer in layers for item in layer.items if not isinstance(item, Text))
    assert (*geometry.extmin.vec2, *geometry.extmax.vec2) == pytest.approx(drawn, abs=1.0)
    # With the texts, measured by ezdxf in their fonts, against the SVG page, whose texts are estimated.
    every = bbox.extents(space)
    svg = to_svg(layers, margin=8.0)
    width = float(re.search(r' width="([\d.]+)mm"', svg).group(1))
    height = float(re.search(r' height="([\d.]+)mm"', svg).group(1))
    assert every.size.x + 16.0 == pytest.approx(width, abs=2.0)
    assert every.size.y + 16.0 == pytest.approx(height, abs=2.0)
    xmin, ymin, xmax, ymax = bounds(layers)
    assert document.header["$EXTMIN"][:2] == pytest.approx((xmin, ymin))
    assert document.header["$EXTMAX"][:2] == pytest.approx((xmax, ymax))
    # The limits a CAD program plots within are the drawing's too, not the template's 420 × 297.
    assert document.header["$LIMMIN"][:2] == pytest.approx((xmin, ymin))
    assert document.header["$LIMMAX"][:2] == pytest.approx((xmax, ymax))
    # An A1 sheet's edge alone (a student's sheet_1.dxf had its extents unset, its limits 420 × 297).
    edge, _ = read_back([Layer("sheet-frame", (Polyline(((0, 0), (841, 0), (841, 594), (0, 594)), closed=True),))])
    assert edge.header["$EXTMIN"][:2] == pytest.approx((0, 0)) and edge.header["$LIMMIN"][:2] == pytest.approx((0, 0))
    assert edge.header["$EXTMAX"][:2] == pytest.approx((841, 594))
    assert edge.header["$LIMMAX"][:2] == pytest.approx((841, 594))


def test_dxf_strokes_keep_their_dashes_widths_and_colours():
    dashed = Polyline(((0.0, 0.0), (30.0, 0.0)), graphplan.render.primitives.Stroke(0.25, "#333333", (2.5, 1.5)))
    blue = Arrow((0.0, 10.0), (30.0, 10.0), graphplan.render.primitives.Stroke(0.6, "#1f5fa8"))
    document, _ = read_back([Layer("velocity-lines", (dashed,)), Layer("velocity-vectors", (blue,))])
    line, shaft, head = list(document.modelspace())
    assert line.dxf.linetype == "GP-DASH-2.5-1.5"
    pattern = document.linetypes.get(line.dxf.linetype).pattern_tags.tags
    assert [tag.value for tag in pattern if tag.code == 40] == [pytest.approx(4.0)]
    assert [tag.value for tag in pattern if tag.code == 49] == [pytest.approx(2.5), pytest.approx(-1.5)]
    assert line.dxf.lineweight == 25 and shaft.dxf.lineweight == 60
    assert line.rgb == (0x33, 0x33, 0x33) and shaft.rgb == (0x1F, 0x5F, 0xA8)
    assert head.dxftype() == "HATCH" and head.has_solid_fill and head.rgb == (0x1F, 0x5F, 0xA8)
    # The head's tip is the arrow's end, and the shaft runs from the start to it: a CAD measure of the vector
    # gives its length (the shaft stopped short under the head read pa = 100 mm as 97.55).
    vertices = [tuple(v) for v in head.paths.paths[0].vertices]
    assert vertices[0][:2] == pytest.approx((30.0, 10.0))
    assert [tuple(point)[:2] for point in shaft.get_points()] == [pytest.approx((0.0, 10.0)), pytest.approx((30.0, 10.0))]


def test_dxf_is_the_same_every_time_and_written_to_paths_and_byte_streams(tmp_path):
    layers = plan_sheet_layers()
    _, first = read_back(layers)
    _, second = read_back(layers)
    assert first == second
    layers_to_dxf(layers, tmp_path / "sheet.dxf")
    assert (tmp_path / "sheet.dxf").read_text(encoding="utf-8") == first
    binary = io.BytesIO()
    layers_to_dxf(layers, binary)
    assert binary.getvalue().decode("utf-8") == first


def svg_groups(svg: str, names: set[str]) -> tuple[Counter, int]:
    """The texts of the SVG's groups ``names``, and how many lines and circles they draw, read off the SVG."""
    from xml.etree import ElementTree

    texts: Counter = Counter()
    drawn = 0
    for group in ElementTree.fromstring(svg).iter("{http://www.w3.org/2000/svg}g"):
        if group.get("id") in names:
            for element in group.iter():
                tag = element.tag.rsplit("}", 1)[-1]
                texts["".join(element.itertext())] += tag == "text"
                drawn += tag in ("path", "circle", "line", "polyline", "polygon")
    return +texts, drawn


@pytest.mark.parametrize("locale", ["ru", "zh", "en"])
def test_dxf_puts_the_title_block_with_the_frame_on_sheet(locale):
    """The title block's grid and words went to TEXT, the frame alone to SHEET (its group is ``title-block``, and
    the last-word rule found 'block' nowhere), in every form: ESKD, GB/T and ISO 7200."""
    from graphplan.render.sheet import kinematics_sheet
    from graphplan.render.title_block import Details

    details = Details(title="Crank-rocker", author="A. Student", checked_by="B. Teacher", designation="TMM.01.00",
                      organization="University", date="2026-12-01")
    (sheet,) = kinematics_sheet([list(plan_sheet_layers())], "A1", locale=locale, scale=0.002, details=details)
    document, _ = read_back(sheet.layers)
    # ESKD's графа 26 (the designation upside down in the frame's corner) is the sheet's too.
    texts, drawn = svg_groups(sheet.svg(), {"sheet-frame", "title-block", "sheet-designation"})
    assert {"A. Student", "TMM.01.00", "2026-12-01"} <= set(texts)
    space = document.modelspace()
    assert Counter(entity.plain_text() for entity in space.query('TEXT[layer=="SHEET"]')) == texts
    assert len(space.query('LWPOLYLINE CIRCLE[layer=="SHEET"]')) == drawn


def test_dxf_of_the_dynamics_takes_its_diagrams_apart_as_the_kinematic_diagrams_are_on_its_sheet_too():
    """Each diagram of the dynamics is one layer of axes, curves and words: M(φ) went whole to VECTORS (its layer is
    'moments', a word of the force sheets), the others to layers of their own names (ENERGY, WORKS; DYNAMICS-ENERGY
    on the sheet).  Their axes go to AXES and their curves to CURVES, as in diagrams.dxf."""
    from graphplan.dynamics import equivalent_model_of
    from graphplan.flywheel import flywheel_for
    from graphplan.render import dynamics
    from graphplan.render.sheet import dynamics_panel, dynamics_sheet

    model = equivalent_model_of(analyse(loads((FIXTURES / "shaper_six_bar.toml").read_text(encoding="utf-8"))))
    layers = dynamics.layout(model, flywheel_for(model, 0.05))
    (sheet,) = dynamics_sheet([dynamics_panel(layers, "en")], "A1")
    found = []
    for drawing in (layers, [layer for layer in sheet.layers if layer.name not in ("sheet-frame", "title-block")]):
        document, _ = read_back(drawing)
        space = document.modelspace()
        assert {entity.dxf.layer for entity in space} == {AXES, CURVES, TEXT}
        # Md, Mr, Ad, Ar, ΔT over the cycle, ΔT over Je and Je(φ): a vertex at each of the model's samples.
        curves = [entity for entity in space.query("LWPOLYLINE") if len(entity) == len(model.coordinate)]
        assert len(curves) == 7 and {entity.dxf.layer for entity in curves} == {CURVES}
        grid = space.query('LWPOLYLINE[linetype=="GP-DASH-1-1"]')
        assert len(grid) > 0 and {entity.dxf.layer for entity in grid} == {AXES}
        found.append(Counter((entity.dxf.layer, entity.dxftype()) for entity in space))
    standalone, on_the_sheet = found
    assert standalone == on_the_sheet


def test_dxf_texts_are_read_back_as_written_whatever_codes_they_hold():
    """%% opens a special character and a caret a control character in a TEXT: a title '50%%d' read as 50°, '^J' as
    a line feed.  Each is escaped as the DXF reference says (ezdxf reads a trailing caret as nothing, and a TEXT
    holds no line break, so neither is among them)."""
    written = ["50%%d", "100%", "5 % of %%%", "%%123", "^J", "a^b^ c", "tab\there", r"x\P{y}", r"\U+00B0 and \M+1A2B3",
               "%^%"]
    document, _ = read_back([Layer("labels", tuple(Text((0.0, 5.0 * k), text) for k, text in enumerate(written)))])
    read = [ezdxf.decode_dxf_unicode(entity.plain_text()) for entity in document.modelspace().query("TEXT")]
    assert read == written
    # A title block's lines, as the SVG has them.
    from graphplan.render.sheet import kinematics_sheet
    from graphplan.render.title_block import Details

    details = Details(title='Rig "50%%d" ^J 100%', designation="TMM^01 %%c")
    (sheet,) = kinematics_sheet([list(plan_sheet_layers())], "A1", locale="ru", scale=0.002, details=details)
    document, _ = read_back(sheet.layers)
    texts, _ = svg_groups(sheet.svg(), {"title-block", "sheet-designation"})
    assert "TMM^01 %%c" in texts and any("50%%d" in text for text in texts)
    space = document.modelspace()
    assert Counter(ezdxf.decode_dxf_unicode(entity.plain_text()) for entity in space.query('TEXT[layer=="SHEET"]')) == texts
