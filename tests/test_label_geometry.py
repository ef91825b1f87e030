"""The label placer's own geometry against shapely's: the distances, leaders and coverings it works out by
coordinates or by the segments of a line must be what shapely gives for the shapes whole."""

import numpy as np
import shapely
from shapely.geometry import LineString, Point, Polygon, box
from shapely.strtree import STRtree

from graphplan.render.labels import (
    LABEL_GAP_MM,
    Anchor,
    _box_distances,
    _boxes_meet,
    _leaders,
    _pieces,
    place_labels,
    text_box,
)

RANDOM = np.random.default_rng(20261130)


def random_boxes(count: int) -> np.ndarray:
    corner = RANDOM.uniform(-20.0, 20.0, (count, 2))
    size = RANDOM.uniform(0.5, 12.0, (count, 2))
    return np.concatenate((corner, corner + size), axis=1)


def test_a_box_s_distance_from_a_point_is_shapely_s():
    boxes = random_boxes(200)
    points = RANDOM.uniform(-30.0, 30.0, (50, 2))
    # Points inside a box and on its edges too.
    points = np.concatenate((points, boxes[:5, :2], (boxes[5:10, :2] + boxes[5:10, 2:]) / 2))
    expected = shapely.distance(shapely.box(*boxes.T)[:, None], shapely.points(points)[None, :])
    assert np.allclose(_box_distances(boxes, points), expected, rtol=0.0, atol=1e-12)
    assert np.all(_box_distances(boxes[:5], boxes[:5, :2]).diagonal() == 0.0)


def test_a_leader_ends_at_the_point_of_its_box_nearest_the_labelled_point():
    at = (1.5, -2.0)
    boxes = random_boxes(300)
    boxes = boxes[~shapely.intersects(shapely.box(*boxes.T), Point(at))]  # those over the point: the next test
    lines = shapely.get_coordinates(_leaders(at, boxes)).reshape(-1, 2, 2)
    nearest = shapely.get_coordinates(shapely.shortest_line(Point(at), shapely.box(*boxes.T))).reshape(-1, 2, 2)[:, 1]
    along = nearest - np.asarray(at)
    unit = along / np.hypot(*along.T)[:, None]
    # The leader stops 0.3 mm short of the box and starts just outside the point's dot.
    assert np.allclose(lines[:, 1], nearest - 0.3 * unit, rtol=0.0, atol=1e-9)
    assert np.allclose(np.hypot(*(lines[:, 0] - at).T), 0.9, rtol=0.0, atol=1e-12)


def test_a_box_over_the_point_gets_a_leader_of_no_length_at_the_point():
    over = np.array([[0.0, 0.0, 4.0, 2.0]])
    assert np.array_equal(shapely.get_coordinates(_leaders((1.0, 1.0), over)), [[1.0, 1.0], [1.0, 1.0]])


def test_the_obstacles_a_shape_covers_are_the_same_whether_lines_are_whole_or_in_segments():
    # Long curves of many vertices (a diagram's), one with repeated vertices, one that is a single point, a closed
    # outline, filled shapes: the pieces the placer's tree holds stand for their whole obstacles.
    curve = np.column_stack((np.linspace(-25.0, 25.0, 361), 8.0 * np.sin(np.linspace(0.0, 6.0, 361))))
    repeated = [(0.0, 0.0), (0.0, 0.0), (5.0, 5.0), (5.0, 5.0), (9.0, -3.0)]
    obstacles = [LineString(curve), LineString(curve[::-1] * 0.5), LineString(repeated),
                 LineString([(3.0, 3.0), (3.0, 3.0)]), LineString([(-8, -8), (8, -8), (8, 8), (-8, 8), (-8, -8)]),
                 Point(2.0, -4.0).buffer(0.6), Polygon([(10, 10), (14, 10), (12, 13)]), box(-15, 12, -5, 15)]
    pieces, owners = _pieces(obstacles)
    shapes = np.concatenate((shapely.box(*random_boxes(400).T),
                             shapely.linestrings(RANDOM.uniform(-25.0, 25.0, (200, 2, 2)))))
    hit, piece = STRtree(pieces).query(shapes, predicate="intersects")
    through_pieces = set(zip(hit.tolist(), owners[piece].tolist(), strict=True))
    hit, whole = STRtree(obstacles).query(shapes, predicate="intersects")
    through_wholes = set(zip(hit.tolist(), whole.tolist(), strict=True))
    assert through_pieces == through_wholes
    assert len(through_wholes) > 100  # the case is not empty
    assert sorted(set(owners.tolist())) == list(range(len(obstacles)))


def test_boxes_meet_where_shapely_says_they_intersect_edges_included():
    one, other = random_boxes(150), random_boxes(150)
    # Boxes sharing only an edge or a corner meet.
    touching = np.array([[0.0, 0.0, 1.0, 1.0], [1.0, 0.0, 2.0, 1.0], [2.0, 1.0, 3.0, 2.0]])
    one, other = np.concatenate((one, touching)), np.concatenate((other, touching))
    expected = shapely.intersects(shapely.box(*one.T)[:, None], shapely.box(*other.T)[None, :])
    assert np.array_equal(_boxes_meet(one[:, None], other), expected)


def test_a_label_none_of_whose_spots_meets_an_obstacle_stands_beside_its_point():
    """Obstacles all far from the point: the placer's table of which spot meets which obstacle is then empty, and it
    failed on it (an IndexError), as the plan of positions' O did, placed again with the thin lines and the points'
    paths left to break under it, on the swing tried for a crank that cannot turn round."""
    anchor = Anchor(at=(0.0, 0.0), text="O", size=2.5)
    placement = place_labels([anchor], [LineString([(500.0, 500.0), (600.0, 500.0)])])
    (text,) = placement.texts
    assert placement.leaders == ()
    assert text_box(text).distance(Point(0.0, 0.0)) <= LABEL_GAP_MM + 1e-9


def test_a_leader_from_a_point_along_the_line_it_names_starts_on_that_line():
    """A load's name led from a point of its arrow's shaft started 0.9 mm off the shaft, as a leader keeps off a
    point's dot, and touched nothing: it now starts on the shaft.  One from the anchor's own point (a load's tail,
    a joint) and one of a label naming a point keep their clearance."""
    from graphplan.render.labels import LEADER_CLEARANCE, _from_its_line

    shaft = ((0.0, 0.0), (20.0, 0.0))
    named = Anchor((0.0, 0.0), "Fu4", 2.8, along=shaft)
    from_shaft = LineString([(12.0, LEADER_CLEARANCE), (12.0, 6.0)])
    (start, end) = _from_its_line(from_shaft, named)
    assert Point(start).distance(LineString(shaft)) < 1e-12 and start == (12.0, 0.0) and end == (12.0, 6.0)
    from_tail = LineString([(0.0, LEADER_CLEARANCE), (0.0, 6.0)])
    assert _from_its_line(from_tail, named) == tuple(from_tail.coords)
    assert _from_its_line(from_shaft, Anchor((12.0, 0.0), "B", 2.8)) == tuple(from_shaft.coords)
