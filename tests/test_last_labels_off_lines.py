"""The last labels the bench found on lines: n6″ on the class III triad's acceleration plan now stands off them.

``bench/label_clutter.py`` found n6″ on the class III triad's acceleration plan of position 8 crossing a ray of the
plan, on a leader set apart from its crowded point: every clear spot within reach was held by neighbours (n3, n6,
σ6) that could not all stand clear elsewhere, and the placer reached no farther.  A label so left now reaches
farther out on its leader, unless its caller has a way of its own: the plan of positions letters it beside its point
and breaks the thin lines under it, and the lever gives its arrow's name under the drawing.  A load's name on a group
cut free reaches out from its arrow's shaft (the triad with a slider's Fu6 at positions 3 and 8:
tests/test_force_labels_off_lines.py).

A label lies on a line as the bench counts it, by its own recorder: its box meets a drawn line, an arrow, a circle's
outline but a point's dot, a filled block's outline or another label's leader.
"""

import math
from pathlib import Path

import numpy as np
import pytest
import shapely
from label_bench import label_clutter

from graphplan.render import labels
from graphplan.render.labels import Anchor, place_labels, text_box
from graphplan.render.primitives import Polyline, Text

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ("triad_class_iii", "triad_with_slider")
# A leader starts a little off its point and ends a little short of its box (labels.py draws it so).
LEADER_SLACK_MM = 0.35
# The bench's own: a circle smaller than this (radius, mm) is a point's dot or a pin, not a line a label lies on.
DOT_RADIUS = 1.5


BENCH = label_clutter()


@pytest.fixture(scope="module")
def placements(tmp_path_factory):
    """Each fixture run as the bench runs it (English, no sheets): the bench's count of its clutter, and every drawn
    placement (anchors, obstacles, placement, its clutter by the bench's measure)."""
    clutter = BENCH
    kept: list = []

    class Keeping(clutter.Recorder):
        def __init__(self, place):
            super().__init__(place)
            kept.append(self)

    class Kept(dict):
        """The bench's drawn lines, kept past its runs' ends (which clear them) for each call to be measured: the
        runs' shapes live on in the calls kept, so no id is taken twice."""

        def clear(self):
            pass

    clutter.Recorder, clutter.LINES = Keeping, Kept()
    found = {}
    for fixture in FIXTURES:
        kept.clear()
        out = tmp_path_factory.mktemp("runs") / fixture
        total = clutter.run_fixture(ROOT / "fixtures" / f"{fixture}.toml", "en", labels.place_labels, out)
        calls = kept[0].calls
        found[fixture] = (total, [(*call[:3], clutter.clutter_of(*call)) for number, call in enumerate(calls)
                                  if not clutter.superseded(call, calls[number + 1:number + 2])])
    return found


def test_no_label_of_the_class_iii_triad_lies_on_a_line_nor_on_another(placements):
    total, calls = placements["triad_class_iii"]
    # The bench's count, and each placement's as the bench measures it.
    assert (total.on_line, total.overlapping, total.obstacle_hits) == (0, 0, 0)
    lying = [[text.text for text in placement.texts] for _, _, placement, counted in calls if counted.on_line]
    assert lying == []
    assert sum(counted.labels for *_, counted in calls) == total.labels


def test_no_label_of_the_triad_with_a_slider_lies_on_a_line_nor_on_another(placements):
    # Fu6 at positions 3 and 8 lay on its own line of action until it was led out from its arrow's shaft.
    total, calls = placements["triad_with_slider"]
    assert total.overlapping == 0
    lying = [[text.text for text, anchor in zip(placement.texts, anchors)
              if any(labels.text_box(text).intersects(line) for line in drawn_lines(obstacles))]
             for anchors, obstacles, placement, counted in calls if counted.on_line]
    assert (total.on_line, lying) == (0, [])


def drawn_lines(obstacles) -> list:
    """The obstacles of a placement the bench takes for drawn lines (its own record of them)."""
    return [BENCH.LINES[id(shape)][1] for shape in obstacles
            if id(shape) in BENCH.LINES and BENCH.LINES[id(shape)][0] is shape]


def names_its_point(anchor: Anchor, text: Text, leaders: list[Polyline], gap: float = labels.LABEL_GAP_MM) -> bool:
    """Whether a label reads as naming its anchor's point: beside it (on the rings beside the point), or joined to it
    by a leader that starts at the point and ends at the label's box."""
    box = text_box(text)
    point = shapely.Point(anchor.at)
    if box.distance(point) <= gap + max(labels.BESIDE_SHARES) * anchor.size + 0.55 * anchor.size:
        return True
    return any(math.dist(leader.points[0], anchor.at) <= labels.LEADER_CLEARANCE + 1e-6
               and box.distance(shapely.Point(leader.points[-1])) <= LEADER_SLACK_MM for leader in leaders)


@pytest.mark.parametrize("fixture", FIXTURES)
def test_every_label_still_names_its_point(placements, fixture):
    # A label sent farther out is tied to its point by its leader: none is left standing apart from what it names.
    astray = [(anchor.text, text.at) for anchors, _, placement, _ in placements[fixture][1]
              for anchor, text in zip(anchors, placement.texts)
              if anchor.along is None and not names_its_point(anchor, text, list(placement.leaders))]
    assert astray == []


def test_n6_on_the_class_iii_triad_s_plans_stands_off_the_lines_tied_to_its_point(placements):
    found = [(anchor, text, placement, counted) for anchors, _, placement, counted in placements["triad_class_iii"][1]
             for anchor, text in zip(anchors, placement.texts) if anchor.text == "n6″"]
    assert len(found) == 2  # the acceleration plans of positions 2 and 8
    for anchor, text, placement, counted in found:
        assert counted.on_line == 0
        assert names_its_point(anchor, text, list(placement.leaders))
        # Its leader, if any, crosses no other label.
        others = [text_box(other) for other in placement.texts if other is not text]
        mine = [leader for leader in placement.leaders if math.dist(leader.points[0], anchor.at) < 1.0]
        assert not any(shapely.LineString(leader.points).intersects(box) for leader in mine for box in others)


def star(rings: int = 7, step: float = 2.5) -> list:
    """Circles round the origin every ``step`` mm: no box of a letter's height beside the point, or on a leader
    within the placer's first reach, falls between two of them."""
    turn = np.linspace(0.0, 2 * math.pi, 97)
    return [shapely.LineString(np.column_stack((radius * np.cos(turn), radius * np.sin(turn))))
            for radius in step * np.arange(1, rings + 1)]


def test_a_label_hemmed_in_by_lines_reaches_farther_out_on_its_leader():
    circles = star()
    placed = place_labels([Anchor((0.0, 0.0), "A", 3.0)], circles)
    box = text_box(placed.texts[0])
    assert not any(box.intersects(circle) for circle in circles)
    # Past the last circle, on a leader from its point to its box.
    assert box.distance(shapely.Point(0.0, 0.0)) > 7 * 2.5
    (leader,) = placed.leaders
    assert math.dist(leader.points[0], (0.0, 0.0)) <= labels.LEADER_CLEARANCE + 1e-6
    assert box.distance(shapely.Point(leader.points[-1])) <= LEADER_SLACK_MM


def test_a_caller_with_a_way_of_its_own_gets_the_label_left_on_the_line():
    # The lever and the plan of positions find a label left on a line and give it their own way (named under the
    # lever, lettered beside its point over broken thin lines): beside its point still, not sent far out.
    circles = star()
    placed = place_labels([Anchor((0.0, 0.0), "A", 3.0)], circles, reach_farther=False)
    box = text_box(placed.texts[0])
    assert any(box.intersects(circle) for circle in circles)
    assert box.distance(shapely.Point(0.0, 0.0)) < 7 * 2.5
