"""The DXF sets a symbol's indices as the SVG does: R₁₂, Fᵤ₂, R₁₄ with its τ above, not R12, Fu2, R14τ.

A text with indices is an MTEXT whose inline codes stack each index under the line and each component over it, a
height of the series smaller; it is read back with ezdxf's own parser of those codes and checked against the SVG
of the same drawing (its tspans: a smaller one lowered is an index, one raised a component).  Its baseline lands
where a TEXT's lands, left, centre or right aligned, as ezdxf's drawing add-on renders the two; a text without
indices stays the TEXT it was, byte for byte.
"""

from __future__ import annotations

import dataclasses
import functools
import io
import os
import subprocess
import sys
from pathlib import Path
from xml.etree import ElementTree

import pytest
from dxf_texts import mtext_runs, read_text

from graphplan import deliverables
from graphplan.analysis import analyse
from graphplan.render.dxf import layers_to_dxf
from graphplan.render.indices import ABOVE, BELOW, LINE, runs
from graphplan.render.primitives import Layer, Text
from graphplan.scene import loads

ezdxf = pytest.importorskip("ezdxf")

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
# The SVG writes sizes with three decimals; the MTEXT a relative height with three (ezdxf's MTextEditor).
ROUNDING = 2e-3


@functools.cache
def drawing(stem: str) -> deliverables.Drawing:
    """A drawing of the shaper as a run makes it, its texts cut into runs (``in_language``)."""
    scene = loads((ROOT / "fixtures" / "shaper_six_bar.toml").read_text(encoding="utf-8"))
    found = deliverables.drawings(scene, analyse(scene), ("forces", "diagrams"))
    return next(item for item in found if item.stem == stem)


@functools.cache
def files(stem: str) -> tuple[str, str]:
    written = deliverables.encoded(drawing(stem), ("svg", "dxf"))
    return written[f"{stem}.svg"], written[f"{stem}.dxf"].decode("utf-8")


def texts_of(dxf: str) -> list:
    """The TEXT and MTEXT entities of a DXF, in the order they were written."""
    return list(ezdxf.read(io.StringIO(dxf)).modelspace().query("TEXT MTEXT"))


def svg_runs(element) -> tuple[tuple[str, int, float], ...]:
    """(text, place, size over the line's) of each run of an SVG text, as its tspans set them: a smaller tspan set
    under the line is an index, one over it a component; runs at one place and size joined.  The spaces the SVG
    hangs on the end of a run (a renderer drops them at the start of the run after it, which stands at its own x)
    are read back at the start of the run they were cut with."""
    line_size = float(element.get("font-size"))
    baseline = float(element.get("y"))
    found: list[tuple[str, int, float]] = []
    carried = ""
    for span in element.iter(f"{SVG}tspan"):
        lowered = float(span.get("y")) - baseline
        size = float(span.get("font-size", line_size))
        place = LINE if size == line_size else BELOW if lowered > 0 else ABOVE
        scale = size / line_size
        text = span.text.rstrip(" ")
        if found and found[-1][1] == place and found[-1][2] == pytest.approx(scale):
            found[-1] = (found[-1][0] + carried + text, place, scale)
        else:
            found.append((carried + text, place, scale))
        carried = span.text[len(text):]
    if carried:
        found[-1] = (found[-1][0] + carried, *found[-1][1:])
    return tuple(found)


def svg_texts(svg: str) -> list:
    return list(ElementTree.fromstring(svg).iter(f"{SVG}text"))


@pytest.mark.parametrize("stem", ["forces_3", "diagrams"])
def test_an_indexed_label_reads_as_the_svg_s_with_its_indices_stacked_where_the_svg_sets_them(stem):
    svg, dxf = files(stem)
    elements, entities = svg_texts(svg), texts_of(dxf)
    assert len(elements) == len(entities)
    indexed = 0
    for element, entity in zip(elements, entities, strict=True):
        flat = "".join(element.itertext())
        # (a) the characters, joined as a reader reads them, and as ezdxf's plain text writes a stack (12 under the
        # line as ^12, τ over it as τ^)
        assert read_text(entity) == flat
        spans = svg_runs(element)
        if not any(place != LINE for _, place, _ in spans):
            assert entity.dxftype() == "TEXT", flat
            continue
        indexed += 1
        assert entity.dxftype() == "MTEXT", flat
        plain = "".join(text if place == LINE else text + "^" if place == ABOVE else "^" + text
                        for text, place, _ in spans)
        assert entity.plain_text() == plain
        # (b) the same runs below and above the line, lettered as much smaller as the SVG's
        read = mtext_runs(entity)
        assert [(text, place) for text, place, _ in read] == [(text, place) for text, place, _ in spans]
        assert [height for _, _, height in read] == pytest.approx([scale for _, _, scale in spans], abs=ROUNDING)
    assert indexed > 10, "the drawing letters its forces and scales with indices"


def _without_runs(layers) -> list[Layer]:
    return [dataclasses.replace(layer, items=tuple(dataclasses.replace(item, runs=()) if isinstance(item, Text)
                                                   else item for item in layer.items)) for layer in layers]


def _entities(dxf: str) -> tuple[list[str], list[list[str]]]:
    """A DXF's text outside its ENTITIES section and each entity's lines, as written."""
    lines = dxf.split("\n")
    start = lines.index("ENTITIES")
    end = lines.index("ENDSEC", start)
    entities: list[list[str]] = []
    # Tags in pairs of lines, a code and its value, from after the section's name to the 0 before its ENDSEC.
    for code, value in zip(lines[start + 1:end - 1:2], lines[start + 2:end - 1:2], strict=True):
        if code.strip() == "0":
            entities.append([])
        entities[-1] += [code, value]
    return lines[:start] + lines[end:], entities


@pytest.mark.parametrize("stem", ["forces_3", "diagrams"])
def test_an_indexed_label_is_anchored_where_its_flat_text_is_and_the_rest_is_written_as_it_was(stem):
    """(c) on a real drawing: each MTEXT's insertion point is its flat TEXT's baseline point, its attachment the
    bottom (the baseline, :func:`test_the_baseline_and_the_ends_of_a_label_are_a_text_s`) at the TEXT's side; and
    every other entity, every text without indices among them, is the same bytes as with no text indexed."""
    layers = drawing(stem).layers
    _, dxf = files(stem)
    flat = io.StringIO()
    layers_to_dxf(_without_runs(layers), flat)
    outside, entities = _entities(dxf)
    flat_outside, flat_entities = _entities(flat.getvalue())
    assert outside == flat_outside and len(entities) == len(flat_entities)
    texts = [item for layer in layers for item in layer.items if isinstance(item, Text)]
    changed = [index for index, (entity, before) in enumerate(zip(entities, flat_entities, strict=True))
               if entity != before]
    assert len(changed) == sum(bool(item.runs) for item in texts) > 0
    sides = {0: 1, 1: 2, 2: 3}   # TEXT's halign left, centre, right → MTEXT's bottom-left, -centre, -right (7, 8, 9)
    anchors = set()
    for entity, before in zip(texts_of(dxf), texts_of(flat.getvalue()), strict=True):
        if entity.dxftype() == "TEXT":
            continue
        halign = before.dxf.halign
        anchors.add(halign)
        where = before.dxf.insert if halign == 0 else before.dxf.align_point
        assert entity.dxf.attachment_point == 6 + sides[halign]
        assert entity.dxf.insert.isclose(where)
        assert (entity.dxf.char_height, entity.dxf.style, entity.dxf.layer) == (
            before.dxf.height, before.dxf.style, before.dxf.layer)
        assert entity.dxf.get("true_color") == before.dxf.get("true_color")
        assert entity.dxf.color == before.dxf.color
    if stem == "diagrams":
        assert anchors == {0, 1, 2}


def _ink(document, entity) -> list:
    """The bounding boxes of what ezdxf's drawing add-on fills for ``entity``, in the order it draws them: a TEXT
    at once, an MTEXT word by word and stack by stack."""
    from ezdxf.addons.drawing import Frontend, RenderContext
    from ezdxf.addons.drawing.recorder import Recorder

    recorder = Recorder()
    Frontend(RenderContext(document), recorder).draw_entities([entity])
    return [record.bbox() for record, _ in recorder.player().recordings()]


@pytest.mark.parametrize(("anchor", "rotation"), [("start", 0.0), ("middle", 0.0), ("end", 0.0), ("start", 90.0)])
def test_the_baseline_and_the_ends_of_a_label_are_a_text_s(anchor, rotation):
    """(c) rendered: a label whose glyphs all stand on the baseline (R12n = 14 N), set as its flat TEXT and as the
    MTEXT of its runs, inks the same baseline (the bottom of R and N) and the same ends: its first word starts where
    the TEXT starts, its last ends where the TEXT ends (left, right), its middle is the TEXT's (centre).  A stack
    makes a line taller, so an MTEXT attached by its top or its middle would stand lower than the TEXT."""
    label = "R12n = 14 N"
    text = Text((40.0, 30.0), label, 5.0, anchor, rotation=rotation, runs=runs(label))
    assert text.runs
    written = io.StringIO()
    layers_to_dxf([Layer("labels", (text, dataclasses.replace(text, runs=())))], written)
    document = ezdxf.read(io.StringIO(written.getvalue()))
    mtext, flat = document.modelspace().query("MTEXT")[0], document.modelspace().query("TEXT")[0]
    words, (whole,) = _ink(document, mtext), _ink(document, flat)
    first, last = words[0], words[-1]
    if rotation:
        # Turned a quarter counter-clockwise: the baseline runs up on the right of the glyphs, from the anchor.
        assert first.extmax.x == pytest.approx(whole.extmax.x, abs=1e-6)
        assert first.extmin.y == pytest.approx(whole.extmin.y, abs=1e-6)
        return
    assert first.extmin.y == pytest.approx(whole.extmin.y, abs=1e-6) == pytest.approx(30.0, abs=1e-6)
    assert last.extmin.y == pytest.approx(whole.extmin.y, abs=1e-6)
    # The symbol a cap height high (R's ink), its index and component smaller.
    assert first.size.y == pytest.approx(text.size, abs=1e-6)
    assert all(box.size.y < 0.8 * text.size for box in words[1:3])
    ends = {"start": (first.extmin.x, whole.extmin.x), "end": (last.extmax.x, whole.extmax.x),
            "middle": ((first.extmin.x + last.extmax.x) / 2, (whole.extmin.x + whole.extmax.x) / 2)}
    assert ends[anchor][0] == pytest.approx(ends[anchor][1], abs=1e-6)
    # Narrower than the flat text, as the SVG's: the indices are smaller.
    assert last.extmax.x - first.extmin.x < whole.size.x - 1.0


def test_an_indexed_label_stays_on_its_one_line():
    """Each MTEXT of a real drawing is rendered on one line: of no column width, ezdxf's renderer wrapped one at a
    width it estimated, a bold heading's "(φ)" left alone on its baseline and "Displacement diagram sE" a line's
    pitch (5/3 of the height) over it."""
    _, dxf = files("diagrams")
    document = ezdxf.read(io.StringIO(dxf))
    mtexts = list(document.modelspace().query("MTEXT"))
    assert any(entity.dxf.style.endswith("BOLD") for entity in mtexts), "a heading with an index"
    for entity in mtexts:
        boxes = _ink(document, entity)
        baseline, height = entity.dxf.insert.y, entity.dxf.char_height
        assert min(box.extmin.y for box in boxes) > baseline - 0.5 * height, entity.text
        # a component's stack stands over the cap height, under 2 heights
        assert max(box.extmax.y for box in boxes) < baseline + 2.2 * height, entity.text


def test_mtext_s_own_codes_in_a_label_are_read_as_the_characters_written():
    """A backslash, braces, percent signs and a caret on the line, and in an index a stack's own codes (a semicolon
    ends it, a caret, a slash or a hash splits it) read back as written, not as codes."""
    label = (("a\\P{b}%%d^c", LINE), ("1;2/3#4^5\\6{7}", BELOW), (" x", LINE), ("τ", ABOVE))
    text = Text((0.0, 0.0), "".join(part for part, _ in label), 3.5, runs=label)
    written = io.StringIO()
    layers_to_dxf([Layer("labels", (text,))], written)
    (entity,) = texts_of(written.getvalue())
    assert [(part, place) for part, place, _ in mtext_runs(entity)] == list(label)
    # ezdxf's full parser (its fast one reads no escape inside a stack)
    assert entity.plain_text(fast=False) == "a\\P{b}%%d^c^1;2/3#4^5\\6{7} xτ^"


_WRITE = """
import sys
from graphplan.render.dxf import layers_to_dxf
from graphplan.render.indices import runs
from graphplan.render.primitives import Layer, Text
labels = ["R45τ = 14.24 N", "ΣME(5): −R45τ·DE + G5·h1", "Fu2"]
texts = tuple(Text((10.0, 10.0 * k), label, 3.5, anchor, runs=runs(label))
              for k, (label, anchor) in enumerate(zip(labels, ("start", "middle", "end"))))
layers_to_dxf([Layer("labels", texts)], sys.stdout.buffer)
"""


def test_an_indexed_label_is_the_same_bytes_every_time_and_in_every_process():
    """(d) two writes in one process, and in processes that hash strings differently, give the same bytes."""
    texts = tuple(Text((0.0, 5.0 * k), label, 5.0, runs=runs(label)) for k, label in enumerate(["R12", "Mu4′"]))
    once, again = io.BytesIO(), io.BytesIO()
    layers_to_dxf([Layer("labels", texts)], once)
    layers_to_dxf([Layer("labels", texts)], again)
    assert once.getvalue() == again.getvalue() and b"MTEXT" in once.getvalue()

    def written(seed: int) -> bytes:
        environment = {**os.environ, "PYTHONHASHSEED": str(seed)}
        return subprocess.run([sys.executable, "-c", _WRITE], capture_output=True, check=True, cwd=ROOT,
                              env=environment).stdout

    first, second = written(1), written(2)
    assert first == second and first.count(b"\nMTEXT\n") == 3
