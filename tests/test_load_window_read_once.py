"""A load given by a diagram acts over the window its diagram spans, read by the one rule a window is read by.

Where it acts is where the same load given over that window (``during``) acts: in the working stroke, its share
of the stroke between the window's ends, equal ends at 12 digits.  Its diagram's segment there is the count of the
diagram's shares at or below the share travelled, −1 where it does not act, so the segments mark the same
positions as the window's activity, and their count steps up by one at each vertex passed.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from graphplan.analysis import analyse
from graphplan.loads import activity, diagram_segments, stroke_share
from graphplan.scene import load, loads

SHAPER = Path(__file__).resolve().parent.parent / "fixtures" / "shaper_six_bar.toml"
WINDOW = "during    = { from = 0.05, to = 0.95 }"
DIAGRAM = "diagram = [[0.05, 1500.0], [0.3, 2000.0], [0.7, 2000.0], [0.95, 500.0]]"


def test_a_diagram_acts_where_its_window_does_and_its_segment_counts_the_vertices_passed():
    text = SHAPER.read_text(encoding="utf-8")
    assert WINDOW in text
    windowed = analyse(load(SHAPER))
    drawn_text = re.sub(r"^value\s*=\s*2000\.0.*$", "", text.replace(WINDOW, DIAGRAM), count=1, flags=re.MULTILINE)
    drawn = analyse(loads(drawn_text))
    row = next(k for k, spec in enumerate(drawn.scene.loads) if spec.diagram is not None)
    assert drawn.scene.loads[row].during == (0.05, 0.95)

    acting = activity(windowed.mechanism, windowed.positions, windowed.motion)[row] > 0
    segments = diagram_segments(drawn.mechanism, drawn.positions, drawn.motion)[row]
    assert acting.any() and not acting.all()
    assert np.array_equal(segments >= 0, acting)
    share = stroke_share(drawn.mechanism, drawn.positions, drawn.motion)
    passed = sum(np.asarray(share >= vertex, dtype=int) for vertex in (0.05, 0.3, 0.7, 0.95))
    assert np.array_equal(segments[acting], passed[acting])
