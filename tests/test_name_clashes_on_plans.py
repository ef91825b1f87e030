"""The plans letter points in lower case (B → b, S3 → s3) and their constructions letter their own points n3 (the end
of link 3's normal component), p (the pole) and σ5 (the triad's special point).  Two names the plans letter alike
would be one point on them: the later image overwrites the earlier, and the plans, the forces read off them and
the error tables come out wrong without a word (b beside B gave VB 1.45 m/s where the mechanism has 0.70).  Such
a scene is refused at reading, naming both keys; names that only look alike on the mechanism's drawing but get
letters of their own (K in a scene whose Coriolis point is then k3) still run."""

from __future__ import annotations

import pytest
from test_scene_errors import first_error

import graphplan
from graphplan.analysis import analyse, instant
from graphplan.plans import velocity_plan
from graphplan.starters import starter

CRANK_ROCKER = starter("crank-rocker")


def with_points(*lines: str, text: str = CRANK_ROCKER) -> str:
    """The crank-rocker starter with ``lines`` added to its [points] table."""
    head, tail = text.split("\n[links.3]", 1)
    return head + "".join(line + "\n" for line in lines) + "\n[links.3]" + tail


@pytest.mark.parametrize(("lines", "where", "message"), [
    (['b = { link = 3, from = "A", toward = "B", at = 0.3 }'], "points.b",
     "b and the point B of groups[0].joints[1] would both be b, one point on them"),
    (['a = { link = 4, from = "C", toward = "B", at = 0.2 }'], "points.a",
     "a and the point A of driver.joint would both be a, one point on them"),
    (['s3 = { link = 2, from = "O", toward = "A", at = 0.15 }'], "points.s3",
     "s3 and the point S3 of points.S3 would both be s3, one point on them"),
    (['s2 = { link = 3, from = "A", toward = "B", at = 0.3 }'], "points.s2",
     "s2 and the point S2 of points.S2 would both be s2, one point on them"),
    (['N3 = { link = 3, from = "A", toward = "B", at = 0.3 }'], "points.N3",
     "N3 would be n3, the letter of the end of a normal component (aⁿ) on link 3"),
    (['n4 = { link = 2, from = "O", toward = "A", at = 0.15 }'], "points.n4",
     "n4 would be n4, the letter of the end of a normal component (aⁿ) on link 4"),
    (['P = { link = 3, from = "A", toward = "B", at = 0.3 }', '"P′" = { link = 3, from = "A", toward = "B", at = 0.2 }'],
     "points.P′", ("P′ and the point P of points.P would both be p′ (p is the pole's letter, so P is p′), one point "
                   "on them")),
], ids=["b-beside-B", "a-beside-A", "s3-beside-S3", "s2-beside-S2", "N3", "n4", "P-with-P-prime"])
def test_a_point_lettered_like_another_is_refused_naming_both(lines, where, message) -> None:
    stage, error = first_error(with_points(*lines))
    expected = f"{where}: the plans letter points in lower case, so {message}: name it otherwise"
    assert (stage, str(error)) == ("build", expected)


def test_a_group_joint_lettered_like_the_drivers_is_refused() -> None:
    """The RRR's inner joint named a beside the crank's A: the plan kept one a, and ω2, the driver's, came out 76 %
    off."""
    text = CRANK_ROCKER.replace('"B"', '"a"')
    assert '["A", "a", "C"]' in text
    stage, error = first_error(text)
    expected = ("groups[0].joints[1]: the plans letter points in lower case, so a and the point A of driver.joint "
                "would both be a, one point on them: name it otherwise")
    assert (stage, str(error)) == ("build", expected)


def test_a_frame_point_beside_a_joint_of_its_letter_still_runs() -> None:
    """A point on the frame stands at the pole and takes no letter of its own: c on the frame beside the pivot C is
    no clash, and the plan's images agree with the analytic velocities (the other method)."""
    analysis = analyse(graphplan.load_text(with_points('c = { link = 1, from = "O", toward = "C", at = 0.3 }')))
    index = 4
    positions, directions = instant(analysis.motion, index)
    plan = velocity_plan(analysis.mechanism, positions, directions)
    assert plan.value("c") == 0
    for name in ("A", "B", "S3", "S4"):
        analytic = complex(analysis.motion.points[name].v[index])
        assert abs(plan.value(name) - analytic) <= 1e-9 * abs(analysis.motion.points["A"].v[index])
