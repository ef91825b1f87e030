"""The dynamics drawing drawn smaller where a small sheet holds none of its usual diagrams.

The program fits the dynamics diagrams' scales to the machine, so a scene cannot shrink them: on an upright A4
(ESKD's: 169 × 202 mm clear of the title block and графа 26) the Russian and Chinese Je(φ) turned under the
energy–mass diagram, the cycle 180 mm long at 2°/mm under its heading, stood 217 mm tall, and every linkage with
`[dynamics]` was refused on A4 in those languages; a V-twin's English moments, 252 mm wide with their axis's words,
missed a landscape A4's 251 mm by a millimetre.  Such a drawing is now drawn at the largest smaller scales that a
sheet holds diagram by diagram; one the sheet holds keeps its usual scales.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.dynamics import equivalent_model_of
from graphplan.flywheel import flywheel_for
from graphplan.locale import strings
from graphplan.render.dynamics import Redrawings, layout, smaller_layouts
from graphplan.render.formats import holds
from graphplan.render.primitives import Text
from graphplan.render.sheet import dynamics_panel, dynamics_sheet, height, width
from graphplan.render.title_block import form_of


@pytest.fixture(scope="module")
def ratchet():
    model = equivalent_model_of(analyse(graphplan.load("fixtures/ratchet_crank_rocker.toml")))
    return model, flywheel_for(model, 0.05)


def _cycle_mm(panel) -> float:
    """How long the cycle is drawn on the reduced moments: from the tick of 0° to that of 360°."""
    (moments,) = [layer for layer in panel.layers if layer.name == "moments"]
    ticks = {item.text: item.at[0] for item in moments.items
             if isinstance(item, Text) and item.anchor == "middle" and item.text in ("0", "360")}
    return ticks["360"] - ticks["0"]


def _leaves(panel):
    return [leaf for part in panel.parts for leaf in (_leaves(part) if part.parts else (part,))]


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_a_linkages_dynamics_stand_on_an_a4_drawn_smaller(ratchet, locale):
    model, flywheel = ratchet
    words = strings(locale)
    usual = dynamics_panel(layout(model, flywheel, words), locale, None, "A4")
    form = form_of(locale)
    # The usual drawing: Je(φ) turned is taller than any room of the sheet, on its own as with the diagram above it.
    assert not all(holds("A4", form, width(leaf), height(leaf)) for leaf in _leaves(usual))
    drawn = dynamics_panel(layout(model, flywheel, words), locale, Redrawings(model, flywheel, words), "A4")
    assert all(holds("A4", form, width(leaf), height(leaf)) for leaf in _leaves(drawn))
    # The cycle at 2.5°/mm, the first round scale past the usual 2°/mm: 144 mm from 0° to 360°, as μφ says.
    assert _cycle_mm(usual) == pytest.approx(180.0, abs=1e-6)
    assert _cycle_mm(drawn) == pytest.approx(144.0, abs=1e-6)
    written = " ".join(item.text for layer in drawn.layers for item in layer.items if isinstance(item, Text))
    assert "μφ = 2.5°/" in written.replace(",", ".")
    # The sheets take it without a refusal, each diagram on a sheet.
    assert dynamics_sheet([drawn], "A4", locale)


def test_the_largest_smaller_drawing_that_a_sheet_holds_is_taken(ratchet):
    model, flywheel = ratchet
    words = strings("ru")
    drawn = dynamics_panel(layout(model, flywheel, words), "ru", Redrawings(model, flywheel, words), "A4")
    area = width(drawn) * height(drawn)
    form = form_of("ru")
    for other in smaller_layouts(model, flywheel, words):
        way = dynamics_panel(other, "ru", None, "A4")
        if width(way) * height(way) > area + 1e-9:
            assert not all(holds("A4", form, width(leaf), height(leaf)) for leaf in _leaves(way))


def test_a_drawing_the_sheet_holds_keeps_its_usual_scales(ratchet):
    model, flywheel = ratchet
    for locale, sheet in (("en", "A4"), ("ru", "A3")):
        words = strings(locale)
        usual = layout(model, flywheel, words)
        drawn = dynamics_panel(usual, locale, Redrawings(model, flywheel, words), sheet)
        if sheet == "A4":
            assert drawn.layers == tuple(usual)
        else:  # the usual drawing, or on a sheet with room one drawn larger
            assert _cycle_mm(drawn) >= 180.0 - 1e-6


def test_check_passes_a_russian_linkage_with_dynamics_on_a4(tmp_path, capsys):
    """`check` packs the dynamics as the sheets do: it refused this scene, at 'Динамический анализ: dynamics-moments'
    (261 × 83 mm), as the run did."""
    text = Path("fixtures/ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    # μl doubled for the plan of positions, which A4 holds at 0.005 m/mm and not at the fixture's 0.0025.
    edited = text.replace('sheet = "A1"', 'sheet = "A4"').replace("length_scale      = 0.0025", "length_scale = 0.005")
    assert edited.count('"A4"') == 1 and edited.count("length_scale = 0.005") == 1
    scene = tmp_path / "ratchet.toml"
    scene.write_text(edited + "\n[dynamics]\ndelta = 0.05\n", encoding="utf-8")
    assert main(["check", str(scene)]) == 0, capsys.readouterr().err


def test_check_lays_out_no_larger_drawing_to_see_whether_a_sheet_holds_the_usual_one(tmp_path, monkeypatch, capsys):
    """Passing the drawings at other scales to `check`'s packing had it lay out every larger one, 0.9 s of the
    shaper starter's check on A1, for a question the usual drawing answers."""
    from graphplan.render import dynamics as dynamics_layout
    from graphplan.starters import starter

    def refused(*args, **kwargs):
        raise AssertionError("laid out larger")

    monkeypatch.setattr(dynamics_layout, "larger_layouts", refused)
    text = starter("shaper")
    assert 'sheet              = "A1"' in text and "[dynamics]" in text
    scene = tmp_path / "shaper.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["check", str(scene)]) == 0, capsys.readouterr().err
