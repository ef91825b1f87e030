"""A hostile user's scenes against the drawings: a crank drawn a few millimetres long, texts measured against the
fonts they are set in, and the like.  Each asserts what a reader of the sheet sees, measured with the drawings' own
geometry (:mod:`graphplan.render.labels`, :mod:`graphplan.render.primitives`)."""

from __future__ import annotations

import re
from pathlib import Path

from graphplan.analysis import analyse
from graphplan.render import positions
from graphplan.render.drawings import positions_plan
from graphplan.render.labels import obstacles_of, text_box
from graphplan.render.linkage import frame_pivots
from graphplan.render.primitives import Text
from graphplan.scene import loads

RATCHET = Path("fixtures/ratchet_crank_rocker.toml").read_text(encoding="utf-8")
POSITION_NUMBER = re.compile(r"^\d+′?$")


def test_a_crank_drawn_a_millimetre_long_keeps_its_position_numbers_off_its_pivot() -> None:
    # The crank 1:200 of the coupler, at the ratchet's μl: its circle is 1.4 mm across, smaller than the pivot's
    # triangle, and the numbers set just outside the circle stood on the triangle and its hatching.
    text = RATCHET.replace("length  = 0.175 ", "length  = 0.00275").replace(
        'S2 = { link = 2, from = "O", toward = "A", at = 0.08 }', 'S2 = { link = 2, from = "O", toward = "A", at = 0.001 }')
    text = text[:text.index("[measured.5]")] + text[text.index("[drawing]"):]
    analysis = analyse(loads(text))
    plan = positions_plan(analysis)
    layers = {layer.name: layer.items for layer in positions.layout(plan)}
    numbers = [item for item in layers["labels"] if isinstance(item, Text) and POSITION_NUMBER.match(item.text)]
    assert len(numbers) >= 3  # the first, the plan sheets' and the second extreme at least
    paper = 1.0 / plan.length_scale
    pivot = obstacles_of(frame_pivots(plan.mechanism, lambda r: (r.real * paper, r.imag * paper)))
    on_pivot = [number.text for number in numbers if any(text_box(number).intersects(shape) for shape in pivot)]
    assert on_pivot == []
