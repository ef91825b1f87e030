"""The drawings' symbols with their indices set as the textbooks set them: R₁₂, Fᵤ₂, R₁₄ with its τ above.

Lettered flat (R12, Mu4′, h7), a sheet read as no textbook writes it, and unlike the note beside it, which sets the
same symbols' indices as subscripts.  The flat text stays what the layouts measure: the ink of an indexed text must
stay inside the box laid out for it, and stand where its anchor says.
"""

from __future__ import annotations

import dataclasses
import io
import re
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from PIL import Image

from graphplan.render.indices import ABOVE, BELOW, LINE, runs, with_indices
from graphplan.render.primitives import FONT_SIZE_PER_CAP, Layer, Text, text_extent
from graphplan.render.svg import to_svg
from graphplan.report.html import symbols_html

SVG = "{http://www.w3.org/2000/svg}"
FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"


@pytest.mark.parametrize(("text", "expected"), [
    ("R12", (("R", LINE), ("12", BELOW))),
    ("R14τ", (("R", LINE), ("14", BELOW), ("τ", ABOVE))),
    ("Fи4", (("F", LINE), ("и4", BELOW))),
    ("+ G3·h2 − Fu3·h3", (("+ G", LINE), ("3", BELOW), ("·h", LINE), ("2", BELOW), (" − F", LINE), ("u3", BELOW),
                          ("·h", LINE), ("3", BELOW))),
    ("μv = 0.01 (m/s)/mm", (("μ", LINE), ("v", BELOW), (" = 0.01 (m/s)/mm", LINE))),
    ("(m1r1)L", (("(m", LINE), ("1", BELOW), ("r", LINE), ("1", BELOW), (")", LINE), ("L", BELOW))),
    ("s2", (("s", LINE), ("2", BELOW))),
    ("aGEⁿ = 0.0385 m/s²", (("a", LINE), ("GE", BELOW), ("ⁿ = 0.0385 m/s²", LINE))),
    # A diagram's velocity of a point named in another script, or in a word, as its s and a beside it: it was left
    # flat (vБ beside s_Б, a_Б), where a point named B was indexed.
    ("Velocity diagram vБ(φ)", (("Velocity diagram v", LINE), ("Б", BELOW), ("(φ)", LINE))),
    ("sБ, vБ, aБ", (("s", LINE), ("Б", BELOW), (", v", LINE), ("Б", BELOW), (", a", LINE), ("Б", BELOW))),
    ("|vSLIDEPIN|", (("|v", LINE), ("SLIDEPIN", BELOW), ("|", LINE))),
])
def test_a_text_is_cut_into_its_runs_on_below_and_above_the_line(text, expected):
    assert runs(text) == expected
    # Joined, the runs are the text the layouts measured.
    assert "".join(run for run, _ in runs(text)) == text


@pytest.mark.parametrize("text", ["A", "pa", "B′", "Position 10", "1:2.5", "Crank-rocker mechanism", "Plan", "ab"])
def test_a_text_with_no_symbol_is_left_whole(text):
    assert runs(text) == ()


def test_the_user_s_own_words_stay_flat():
    """A load the scene names F4.2 is no force F with an index 4 followed by .2; a title "Press F1" no force F₁."""
    assert runs("F4.2", ["F4.2"]) == ()
    assert runs("Press F1, position 3", ["Press F1"]) == ()
    assert runs("Press F1: R12", ["Press F1"]) == (("Press F1: R", LINE), ("12", BELOW))


def test_a_load_the_user_names_as_one_symbol_is_indexed_as_one():
    """A resisting load named F6 is F₆ beside the drawing's Fᵤ₆; one named F4.2 is kept as typed."""
    layers = [Layer("forces-labels", (Text((0, 0), "F6"), Text((0, 0), "F4.2"), Text((0, 0), "(Fu6 + F6)·h9")))]
    named, typed, equation = with_indices(layers, ["F6", "F4.2"])[0].items
    assert named.runs == (("F", LINE), ("6", BELOW)) and typed.runs == ()
    assert equation.runs[-4:] == ((" + F", LINE), ("6", BELOW), (")·h", LINE), ("9", BELOW))


def test_the_title_block_is_written_as_the_user_wrote_it():
    layers = [Layer("title-block", (Text((0, 0), "R12"),)), Layer("forces-labels", (Text((0, 0), "R12"),))]
    block, labels = with_indices(layers)
    assert block.items[0].runs == () and labels.items[0].runs == (("R", LINE), ("12", BELOW))


@pytest.mark.parametrize("symbol", ["R12", "R23τ", "Fu2", "Mи3", "ω2", "ε4", "μV", "μt", "μφ", "μW", "μE", "ΔWmax",
                                    "JF", "sB", "hu4", "hи3", "hb", "hу", "aBA^τ"])
def test_a_symbol_is_indexed_as_the_note_indexes_it(symbol):
    """The drawing's runs and the note's HTML set the same part of a symbol below and above the line."""
    html = "".join(text if place == LINE else f"<{'sub' if place == BELOW else 'sup'}>{text}</{'sub' if place == BELOW else 'sup'}>"
                   for text, place in runs(symbol.replace("^", "")))
    assert html == symbols_html(symbol)


def test_every_scale_of_the_dynamics_drawing_is_indexed_in_each_language():
    """The Chinese dynamics drawing's μW and μE (works, energy) were set flat beside its indexed μM and μφ, and every
    language's μm of the reduced mass; a micrometre in words stays as written."""
    from graphplan.locale import strings

    for locale in ("en", "ru", "zh"):
        text = strings(locale)
        for key in ("dyn_moment_scale", "dyn_work_scale", "dyn_energy_scale", "dyn_mass_scale", "dyn_inertia_scale"):
            scale = text[key].format(value="0.5")
            assert runs(scale)[:2] == (("μ", LINE), (scale[1], BELOW)), (locale, key, scale)
            assert symbols_html(scale).startswith(f"μ<sub>{scale[1]}</sub> = "), (locale, key)
    assert runs("a coating 5 μm thick") == () and symbols_html("5 μm") == "5 μm"


def _indexed(text: str, anchor: str = "middle", at=(60.0, 15.0), size: float = 3.5) -> list[Layer]:
    return with_indices([Layer("labels", (Text(at, text, size, anchor),))])


def test_an_index_is_set_smaller_and_lower_a_component_smaller_and_higher():
    text = next(ElementTree.fromstring(to_svg(_indexed("R14τ"))).iter(f"{SVG}text"))
    spans = list(text.iter(f"{SVG}tspan"))
    assert [span.text for span in spans] == ["R", "14", "τ"]
    size = float(text.get("font-size"))
    assert spans[0].get("font-size") is None
    assert float(spans[1].get("font-size")) < size and float(spans[2].get("font-size")) < size
    # SVG's y runs down: an index stands below the baseline, the component after it above; each run at its own x,
    # one after another (WeasyPrint, which sets note.pdf, lays a text's anchor over runs that flow on).
    baseline = float(text.get("y"))
    assert float(spans[0].get("y")) == baseline
    assert float(spans[1].get("y")) > baseline > float(spans[2].get("y"))
    assert float(spans[0].get("x")) < float(spans[1].get("x")) < float(spans[2].get("x"))
    assert "".join(text.itertext()) == "R14τ"


PAGE = (120.0, 30.0)
DPI = 600


def _ink_box_mm(layers) -> tuple[float, float, float, float]:
    """The inked box of the rendered page (left, bottom, right, top; mm, y up as the drawings' paper)."""
    import cairosvg

    png = cairosvg.svg2png(bytestring=to_svg(layers, page=PAGE).encode(), dpi=DPI)
    ink = np.asarray(Image.open(io.BytesIO(png)).convert("L")) < 160
    rows, columns = np.flatnonzero(ink.any(axis=1)), np.flatnonzero(ink.any(axis=0))
    per_mm = ink.shape[1] / PAGE[0]
    return (columns[0] / per_mm, PAGE[1] - (rows[-1] + 1) / per_mm, (columns[-1] + 1) / per_mm,
            PAGE[1] - rows[0] / per_mm)


@pytest.mark.parametrize("text", ["R12", "R14τ", "Mu4′", "Fи4", "+ Fu4·h6 + Mu4′·h7 − G5·h8", "Mу", "ψmax", "ΣMp", "Je,mean"])
@pytest.mark.parametrize("anchor", ["start", "middle", "end"])
def test_the_ink_of_an_indexed_text_stays_in_the_box_it_was_laid_out_in(text, anchor):
    """Rendered by cairosvg, the ink stays inside the flat text's box (:func:`text_extent`), which the labels were
    kept apart by, and a centred text's ink is centred on its anchor, as its flat text's would be."""
    pytest.importorskip("cairosvg")
    layers = _indexed(text, anchor)
    assert layers[0].items[0].runs
    left, bottom, right, top = _ink_box_mm(layers)
    # The box, or where the flat text's own ink reaches past it (J's hook left of its advance).
    flat = _ink_box_mm([Layer("labels", (dataclasses.replace(layers[0].items[0], runs=()),))])
    xmin, ymin, xmax, ymax = text_extent(layers[0].items[0])
    xmin, ymin, xmax, ymax = min(xmin, flat[0]), min(ymin, flat[1]), max(xmax, flat[2]), max(ymax, flat[3])
    assert xmin - 0.05 <= left and right <= xmax + 0.05 and ymin - 0.05 <= bottom and top <= ymax + 0.05
    # A glyph's side bearing: its ink starts a little after its advance does.
    bearing = 0.12 * 3.5 * FONT_SIZE_PER_CAP
    if anchor == "middle":
        assert (left + right) / 2 == pytest.approx(60.0, abs=bearing)
    elif anchor == "end":
        assert right == pytest.approx(60.0, abs=bearing)
    else:
        assert left == pytest.approx(60.0, abs=bearing)


def test_a_mixed_line_s_symbols_are_indexed_in_their_script_s_font():
    from graphplan.render.script_runs import script_runs, width_em

    if width_em(script_runs("力 N"), "normal") is None:
        pytest.skip("fontconfig with DejaVu Sans and Noto Sans CJK is needed to measure mixed lines")
    text = next(ElementTree.fromstring(to_svg(_indexed("平衡力矩 Mb = 49.02 N·m"))).iter(f"{SVG}text"))
    spans = [(span.text, span.get("font-family").split(",")[0], span.get("font-size")) for span in text.iter(f"{SVG}tspan")]
    # The space between the scripts hung on the CJK run: a run set at its own x loses the spaces it starts with.
    assert spans[0][:2] == ("平衡力矩 ", "Noto Sans CJK SC")
    assert spans[1][:2] == ("M", "DejaVu Sans") and spans[2][0] == "b " and spans[2][2] is not None


def test_a_sheet_sets_its_reactions_indices_and_leaves_its_title_block_alone(tmp_path):
    from graphplan.cli import main

    assert main(["run", str(FIXTURES / "ratchet_crank_rocker.toml"), "--out", str(tmp_path), "--only", "sheets"]) == 0
    indexed = flat = 0
    for group in (group for sheet in tmp_path.glob("sheet_*.svg") for group in ElementTree.parse(sheet).iter(f"{SVG}g")):
        for text in group.findall(f"{SVG}text"):
            words = "".join(text.itertext())
            spans = list(text.iter(f"{SVG}tspan"))
            if group.get("id") == "title-block":
                assert not spans, words
            elif re.fullmatch(r"R\d\d", words):
                assert [span.text for span in spans] == [words[0], words[1:]], words
                indexed += 1
            elif re.fullmatch(r"[A-Z]", words):
                flat += 1
    assert indexed and flat
