"""Every link is drawn reaching every joint on it, read from the primitives its outline is drawn with.

A link is drawn as the hull of its points; a joint that stands inside the hull (a ternary link with a point
K beyond its joint D) would be reached by no line of it, and its pin and the link jointed there would look
free. Checked on every fixture and on the triad with such a point, at every position.
"""

import math
from pathlib import Path

import pytest
from shapely.geometry import LineString, MultiPoint, Point

import graphplan
from graphplan.analysis import analyse
from graphplan.kinematics import at
from graphplan.render import linkage
from graphplan.render.primitives import Polyline
from graphplan.scene import loads

FIXTURES = sorted(Path("fixtures").glob("*.toml"))

# The fixture triad with a point K on the ternary link past its joint D: D stands inside the hull of B, F, K.
TRIAD_WITH_A_POINT_PAST_D = Path("fixtures/triad_class_iii.toml").read_text().replace(
    "[points]\n", '[points]\nK = { link = 6, from = "B", toward = "D", at = 0.16, offset = -0.02 }\n')


def _paper(r: complex) -> tuple[float, float]:
    return (1000 * r.real, 1000 * r.imag)


def _unreached(analysis) -> tuple[list[tuple[int, int, str]], int]:
    """The (position, link, joint) whose joint no drawn line of its link reaches, and how many stood inside the hull."""
    mechanism, motion = analysis.mechanism, analysis.motion
    outlines = linkage.outline_points(mechanism, motion)
    joints_of: dict[int, set[str]] = {}
    for name, first, second in mechanism.revolutes:
        joints_of.setdefault(first, set()).add(name)
        joints_of.setdefault(second, set()).add(name)
    unreached, inside = [], 0
    for index in range(motion.count):
        for link, names in outlines.items():
            drawn = [item for item in linkage.link_outlines(motion, index, {link: names}, _paper, linkage.THIN)
                     if isinstance(item, Polyline)]
            if not drawn:
                continue  # a slider block's single point: the block is drawn instead
            lines = [LineString([*item.points, item.points[0]] if item.closed else item.points) for item in drawn]
            fixed = [name for name in names if name in mechanism.fixed_on.get(link, ())]
            hull = MultiPoint([_paper(complex(at(motion.points[name].r, index))) for name in fixed]).convex_hull
            for joint in sorted(joints_of.get(link, set()) & set(fixed)):
                where = Point(_paper(complex(at(motion.points[joint].r, index))))
                if hull.geom_type == "Polygon" and hull.exterior.distance(where) > 0.01 and hull.contains(where):
                    inside += 1
                if min(line.distance(where) for line in lines) > 1e-6:
                    unreached.append((index, link, joint))
    return unreached, inside


@pytest.mark.parametrize("path", FIXTURES, ids=[path.stem for path in FIXTURES])
def test_every_fixture_s_links_reach_their_joints(path):
    unreached, _ = _unreached(analyse(graphplan.load(path)))
    assert unreached == []


@pytest.fixture(scope="module")
def triad_with_a_point_past_d():
    """The triad with K past D, analysed once for the two tests that read it (neither changes the analysis)."""
    return analyse(loads(TRIAD_WITH_A_POINT_PAST_D))


def test_a_joint_inside_its_ternary_link_s_hull_is_tied_to_it(triad_with_a_point_past_d):
    analysis = triad_with_a_point_past_d
    unreached, inside = _unreached(analysis)
    assert inside == analysis.motion.count  # D stands inside B, F, K in every position: the case is exercised
    assert unreached == []


def test_the_bars_to_an_inner_joint_run_to_the_link_s_other_joints(triad_with_a_point_past_d):
    analysis = triad_with_a_point_past_d
    motion = analysis.motion
    outlines = linkage.outline_points(analysis.mechanism, motion)
    items = linkage.link_outlines(motion, 0, {6: outlines[6]}, _paper, linkage.THIN)
    where = {name: _paper(complex(at(motion.points[name].r, 0))) for name in "BDFK"}
    bars = {frozenset(item.points) for item in items if isinstance(item, Polyline) and not item.closed}
    assert bars == {frozenset((where["D"], where["B"])), frozenset((where["D"], where["F"]))}
    plate = next(item for item in items if isinstance(item, Polyline) and item.closed)
    assert all(any(math.dist(corner, where[name]) < 1e-9 for corner in plate.points) for name in "BFK")
