"""The placements and grown lines remembered (labels.remembered, force_marks.grown_union) are what the placer and GEOS
make for the very same arguments, and nothing made for other arguments, another placer or other tuning is given
instead."""
import math

import pytest
import shapely
from shapely.geometry import LineString
from shapely.ops import unary_union

from graphplan.memo import RecentMemo
from graphplan.render import force_marks, labels
from graphplan.render.labels import Anchor


@pytest.fixture(autouse=True)
def _empty_memos(monkeypatch):
    """Memos of their own, empty and never full: in a worker that ran other tests the module's may be full."""
    monkeypatch.setattr(labels, "_placements", RecentMemo())
    monkeypatch.setattr(force_marks, "_grown_unions", RecentMemo())


def _crowd(shift: float = 0.0):
    """A few labels round a star of lines, crowded enough to be led out."""
    anchors = [Anchor((0.0, 0.0), "p, a, b", 3.5), Anchor((4.0 + shift, 1.0), "c", 3.5),
               Anchor((1.0, 4.0), "s2", 3.5), Anchor((-3.0, 2.0), "Fu3", 3.5, along=((0.0, 0.0), (-30.0, 20.0)))]
    lines = [LineString([(0.0, 0.0), (40.0 * math.cos(k), 40.0 * math.sin(k))]) for k in range(6)]
    return anchors, lines


def _ask(anchors, obstacles, **keywords):
    return labels.remembered(labels.place_labels, anchors, obstacles, **keywords)


def test_a_placement_remembered_is_the_placers():
    anchors, obstacles = _crowd()
    first = _ask(anchors, obstacles, reach_farther=False)
    assert first == labels.place_labels(anchors, obstacles, reach_farther=False)
    assert _ask(list(anchors), list(obstacles), reach_farther=False) is first


def test_other_arguments_are_placed_anew():
    anchors, obstacles = _crowd()
    _ask(anchors, obstacles)
    before = len(labels._placements)
    # A label a quarter of a millimetre off: placed for itself, where the placer puts it.
    shifted, _ = _crowd(shift=0.25)
    assert _ask(shifted, obstacles) == labels.place_labels(shifted, obstacles)
    # A ring is a line to WKB, and a shape of another kind to the placer: not the same obstacle.
    ring = [shapely.LinearRing([(2.0, 2.0), (9.0, 2.0), (9.0, 9.0)])]
    as_line = [LineString([(2.0, 2.0), (9.0, 2.0), (9.0, 9.0), (2.0, 2.0)])]
    assert shapely.to_wkb(ring[0]) == shapely.to_wkb(as_line[0])
    _ask(anchors, obstacles + ring)
    _ask(anchors, obstacles + as_line)
    # A nought's sign is written: −0.0 is not 0.0 (an angle's atan2 tells them apart).
    _ask([Anchor((-0.0, 0.0), "p")], obstacles)
    _ask([Anchor((0.0, 0.0), "p")], obstacles)
    assert len(labels._placements) == before + 5


def test_a_placer_recording_the_calls_is_asked_every_time(monkeypatch):
    anchors, obstacles = _crowd()
    _ask(anchors, obstacles)
    calls = []
    placer = labels.place_labels

    def recorder(*arguments, **keywords):
        calls.append(arguments)
        return placer(*arguments, **keywords)

    for _ in range(2):
        labels.remembered(recorder, anchors, obstacles)
    # Set in the placer's place in its module too, as a recorder of every caller's calls is.
    monkeypatch.setattr(labels, "place_labels", recorder)
    for _ in range(2):
        labels.remembered(recorder, anchors, obstacles)
    assert len(calls) == 4


def test_the_tuning_changed_places_anew(monkeypatch):
    anchors, obstacles = _crowd()
    _ask(anchors, obstacles)
    queries: list[int] = []

    class Counted(labels.STRtree):
        def query(self, geometry, *arguments, **keywords):
            queries.append(1)
            return super().query(geometry, *arguments, **keywords)

    # Undone alone: monkeypatch.undo() would undo the fixture's empty memos too and leave this worker's full one.
    with monkeypatch.context() as counting:
        counting.setattr(labels, "STRtree", Counted)
        _ask(anchors, obstacles)
    assert queries  # placed again: its tree was asked
    before = len(labels._placements)
    monkeypatch.setattr(labels, "FIRST_RINGS", 0)
    assert _ask(anchors, obstacles) == labels.place_labels(anchors, obstacles)
    monkeypatch.setattr(labels, "FIRST_RINGS_TOGETHER", False)
    _ask(anchors, obstacles)
    assert len(labels._placements) == before + 2


def test_lines_grown_remembered_are_geos_own():
    _, lines = _crowd()
    grown = force_marks.grown_union(lines, 0.8)
    assert grown.equals_exact(unary_union(lines).buffer(0.8), 0.0)
    assert force_marks.grown_union(list(lines), 0.8) is grown
    wider = force_marks.grown_union(lines, 1.0)
    assert wider.equals_exact(unary_union(lines).buffer(1.0), 0.0) and wider.area > grown.area
    assert force_marks.grown_union([], 0.8).is_empty
