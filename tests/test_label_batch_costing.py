"""A label is costed first on the spots beside its point, and on the spots farther out only when one of those could
cost less (labels.FIRST_RINGS): most labels stand beside their points, and the spots farther out (two thirds of the
boxes and every leader) were costed against the drawing for every label, the placer's largest single cost in a cold
run.  The labels must stand where costing every spot at once puts them, on real label sets: every call of the placer
that a run of a few fixtures makes (tests/label_bench.py's loader of bench/label_clutter.py, which records them),
placed again here with every spot costed at once.
"""

from pathlib import Path

import numpy as np
import pytest
import shapely
from label_bench import label_clutter

from graphplan.render import labels

ROOT = Path(__file__).resolve().parent.parent
# The bundled scene (the plan of positions lettered among the crank circle's numbers, standing labels), a crowded
# triad's force sheets (labels led away, moved and reaching out) and a six-bar's.
FIXTURES = ("ratchet_crank_rocker", "triad_class_iii", "shaper_six_bar")


@pytest.fixture(scope="module")
def label_sets(tmp_path_factory):
    """Every call of the placer in a run of FIXTURES, as the bench runs them (English, no sheets): its anchors,
    obstacles and other arguments, and the placement it gave."""
    clutter = label_clutter()
    calls: list = []

    class Keeping(clutter.Recorder):
        def __call__(self, anchors, obstacles, *args, **kwargs):
            placement = super().__call__(anchors, obstacles, *args, **kwargs)
            calls.append((list(anchors), list(obstacles), args, kwargs, placement))
            return placement

    for fixture in FIXTURES:
        out = tmp_path_factory.mktemp("runs") / fixture
        clutter.run_fixture(ROOT / "fixtures" / f"{fixture}.toml", "en", Keeping(labels.place_labels), out)
    return calls


def placed(call):
    anchors, obstacles, args, kwargs, _ = call
    placement = labels.place_labels(anchors, obstacles, *args, **kwargs)
    return placement.texts, placement.leaders


def test_every_label_stands_where_costing_every_spot_at_once_puts_it(label_sets, monkeypatch):
    assert len(label_sets) > 30 and sum(len(call[0]) for call in label_sets) > 300
    # The sets ask for more than the first rings: labels led away from their points, and labels that stand beside
    # other labels already set.
    assert sum(len(call[4].leaders) for call in label_sets) > 20
    assert any(call[3].get("standing") for call in label_sets)
    monkeypatch.setattr(labels, "FIRST_RINGS", 0)
    for call in label_sets:
        assert placed(call) == (call[4].texts, call[4].leaders), [anchor.text for anchor in call[0]]


def test_the_spots_farther_out_are_asked_of_the_drawing_for_few_labels(label_sets, monkeypatch):
    asked = {"count": 0}

    class Counting(labels.STRtree):
        def query(self, geometry, *args, **kwargs):
            asked["count"] += len(geometry) if hasattr(geometry, "__len__") else 1
            return super().query(geometry, *args, **kwargs)

    monkeypatch.setattr(labels, "STRtree", Counting)

    def shapes_asked() -> int:
        asked["count"] = 0
        for call in label_sets:
            placed(call)
        return asked["count"]

    first_rings_first = shapes_asked()
    monkeypatch.setattr(labels, "FIRST_RINGS", 0)
    all_at_once = shapes_asked()
    # The spots beside a point are a third of its boxes and none of its leaders (96 boxes and 64 leaders a label).
    # Both counts hold the same queries of the labels reaching out and making room, which the first rings do not
    # change: since a leader across a load's arrow moves its label as a line covered does, those were some 60 000 of
    # about 300 000 (the costing's own, 123 000 against 235 000, kept its ratio of 0.52).  The force polygons are now
    # lettered again where a name is left off or set on a leader out of a sliver (render/force_polygons._polygon): those
    # calls' crowded labels reach out, queries both counts share, and the two came to 334 000 against 504 000.
    assert first_rings_first < 0.7 * all_at_once


def test_what_the_first_spots_cover_asked_at_once_is_what_each_covers_asked_alone(label_sets):
    # The placer asks the drawing's tree (its lines cut into their segments, labels._pieces) which obstacles all the
    # spots of a label's first rings meet, in one query, a line met once however many of its segments are met; asked
    # here of each spot's box alone, against every obstacle whole.
    spots = 0
    for anchors, obstacles, args, kwargs, _ in label_sets[:12]:
        if not obstacles:
            continue
        whole = np.array(obstacles, dtype=object)
        pieces, owners = labels._pieces(obstacles)
        tree = shapely.STRtree(pieces)
        for anchor in anchors:
            gap = args[0] if args else kwargs.get("gap", labels.LABEL_GAP_MM)
            _, _, boxes = labels._candidates(anchor, gap, labels.BESIDE_SHARES[:labels.FIRST_RINGS])
            shapes = shapely.box(*boxes.T)
            spot, piece = tree.query(shapes, predicate="intersects")
            at_once = [set() for _ in shapes]
            for one, other in zip(spot.tolist(), owners[piece].tolist()):
                at_once[one].add(other)
            alone = [set(np.flatnonzero(shapely.intersects(box, whole)).tolist()) for box in shapes]
            assert at_once == alone, anchor.text
            spots += len(shapes)
    assert spots > 1000
