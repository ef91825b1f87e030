"""No drawing writes a caret: the plans' names of components (aΣ6C^τ, aBB4^r) are written as the note writes
them (aΣ6Cτ, aBB4ʳ), read from every text of every drawing a run makes of the fixtures and of a triad whose
acceleration plan names a tangential component too short to draw."""

import functools
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.deliverables import chosen, drawings
from graphplan.render.drawings import at_length_scale, largest_length_scale
from graphplan.render.primitives import Text
from graphplan.wording import raised

SCENES = [*sorted(Path("fixtures").glob("*.toml")), Path("tests/scenes/triad_slider_short_tangential.toml")]


@functools.cache
def _texts(path: Path) -> list[tuple[str, str]]:
    """Every text of every drawing but the sheets, made once for the tests that read them."""
    scene = graphplan.load(path)
    analysis = analyse(scene)
    if scene.drawing.length_scale is None and scene.drawing.sheet != "none":
        # A caret comes from a name, written alike at any μl: the drawings are made at the largest μl the program
        # may choose, not at its choice, which lays every sheet out at each μl it tries (most of a triad's 12 s).
        analysis = at_length_scale(analysis, largest_length_scale(analysis, scene.drawing.sheet))
    pieces = tuple(piece for piece in chosen(scene, analysis) if piece != "sheets")
    return [(drawing.stem, item.text) for drawing in drawings(scene, analysis, pieces)
            for layer in drawing.layers for item in layer.items if isinstance(item, Text)]


@pytest.mark.parametrize("path", SCENES, ids=[path.stem for path in SCENES])
def test_no_text_of_any_drawing_has_a_caret(path):
    texts = _texts(path)
    assert texts
    assert [(stem, text) for stem, text in texts if "^" in text] == []


def test_a_short_tangential_component_is_named_with_its_tau_on_the_line():
    texts = [text for stem, text in _texts(SCENES[-1]) if stem == "plan_4"]
    assert any(text.startswith("aΣ6Cτ = ") for text in texts), texts


def test_raised_writes_tau_on_the_line_and_r_as_its_modifier_letter():
    assert raised("aBA^τ, aBB4^r, aΣ6C^τ = 0.02; R^2") == "aBAτ, aBB4ʳ, aΣ6Cτ = 0.02; R^2"
