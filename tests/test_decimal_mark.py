"""Numbers in a drawing are written with the decimal mark of the scene's language: a comma in Russian, as
ESKD drawings and the Russian note write them, a point in English and Chinese; what the user wrote (the
scene's title, the title block) stays as written."""

from __future__ import annotations

import dataclasses
import re

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.deliverables import chosen, drawings
from graphplan.render.primitives import Layer, Text, with_decimal_mark

DECIMAL_POINT = re.compile(r"\d\.\d")
DECIMAL_COMMA = re.compile(r"\d,\d")
TITLE = "Ratchet feed, drawing 1.2"


@pytest.fixture(scope="module")
def ratchet():
    scene = graphplan.load("fixtures/ratchet_crank_rocker.toml")
    return dataclasses.replace(scene, title=TITLE)


def run_texts(scene):
    """Every text of every drawing of a default run, by layer name."""
    analysis = analyse(scene)
    found = []
    for drawing in drawings(scene, analysis, chosen(scene, analysis)):
        found += [(layer.name, item.text) for layer in drawing.layers for item in layer.items
                  if isinstance(item, Text)]
    return found


def test_a_russian_run_writes_decimal_commas_except_in_what_the_user_wrote(ratchet):
    texts = run_texts(ratchet)
    assert {name for name, _ in texts if name == "title-block"}  # the run draws sheets: the ratchet names A1
    own = [text.replace(TITLE, "") for name, text in texts if name != "title-block"]
    assert not [text for text in own if DECIMAL_POINT.search(text)]
    assert sum(bool(DECIMAL_COMMA.search(text)) for text in own) > 20
    # The title as written, in the title blocks (the drawings' headings are the locale's words alone).
    assert any(TITLE.split(", ")[1] in text for name, text in texts if name == "title-block")


@pytest.mark.parametrize("locale", ["en", "zh"])
def test_english_and_chinese_runs_keep_the_decimal_point(ratchet, locale):
    texts = run_texts(dataclasses.replace(ratchet, locale=locale))
    assert sum(bool(DECIMAL_POINT.search(text)) for _, text in texts) > 20


def test_only_points_between_digits_change():
    layer = Layer("caption", (Text((0, 0), "μl = 0.0025 m/mm; II(3,4); a.b; 1. item; 2.5 и 10.75"),))
    block = Layer("title-block", (Text((0, 0), "ТММ.01.02, 21.11.2026"),))
    marked = with_decimal_mark([layer, block], ",", kept=("a.b",))
    assert marked[0].items[0].text == "μl = 0,0025 m/mm; II(3,4); a.b; 1. item; 2,5 и 10,75"
    assert marked[1] == block
    assert with_decimal_mark([layer], ".") == [layer]


def test_plots_write_their_ticks_legends_and_notes_with_the_mark_but_not_the_title():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from graphplan.report.plot_style import with_decimal_mark

    figure = Figure()
    axes = figure.add_subplot()
    axes.plot([0.0, 1.0], [0.0, 1.5], label="ζ = 0.25")
    axes.annotate("2.5 mm", (0.5, 0.5))
    axes.set_title("Rig v1.2")
    axes.legend()
    with_decimal_mark(figure, ",")
    figure.canvas.draw()
    ticks = [label.get_text() for label in axes.get_yticklabels()]
    assert "0,4" in ticks and not [tick for tick in ticks if "." in tick]
    assert [text.get_text() for text in axes.get_legend().get_texts()] == ["ζ = 0,25"]
    assert "2,5 mm" in [text.get_text() for text in axes.texts]
    assert axes.get_title() == "Rig v1.2"


def test_the_russian_error_and_force_tables_write_decimal_commas_and_the_english_numbers():
    """errors.md (and errors.tex, made from it) and forces.md printed decimal points in a Russian run whose note,
    drawings and accuracy tables print commas; the numbers themselves are the English run's."""
    from graphplan.report import forces, tables
    from graphplan.scene import FrictionSpec

    scene = graphplan.load("fixtures/ratchet_crank_rocker.toml")
    scene = dataclasses.replace(scene, title=TITLE, friction=(FrictionSpec("friction[0]", "C", None, 0.1, 0.02, None),))
    for report in (tables.markdown, forces.markdown):
        russian = report(analyse(dataclasses.replace(scene, locale="ru"))).replace(TITLE, "")
        english = report(analyse(dataclasses.replace(scene, locale="en"))).replace(TITLE, "")
        assert not DECIMAL_POINT.search(russian)
        # A group's label, II(3,4), has its comma in both.
        numbers = re.compile(r"−?\d+(?:[.,]\d+)?")
        assert ([n.replace(",", ".") for n in numbers.findall(russian)]
                == [n.replace(",", ".") for n in numbers.findall(english)])
        assert len(DECIMAL_COMMA.findall(russian)) > 30
