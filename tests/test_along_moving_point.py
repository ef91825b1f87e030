"""A force along a point of a moving link: the spring or cylinder pinned there pushes that link back.

``[[loads]] along = "D"`` with D on the frame is a cylinder pinned to the frame; with D on a moving link the
cylinder also pushes D's link, a load the scene must give itself (a cylinder between two moving links is two loads,
one at each end along the other's point).  The run warns where that load is missing, naming the entry to add, and
where D is on the load's own link, whose spring or cylinder then pushes the link on itself.
"""

from __future__ import annotations

import pytest

# The crank-rocker with a frame pin D, E on the coupler (link 3) and S4 on the rocker (link 4).
from test_force_along_a_turning_line import CRANK_ROCKER

from graphplan.analysis import SCENE_WIDE_WARNINGS, analyse
from graphplan.locale import strings
from graphplan.render import linkage as linkage_drawing
from graphplan.report.note import note_markdown
from graphplan.scene import loads as scene_of_text


def _force(link: int, point: str, along: str, how: str = "value = 500.0") -> str:
    return f'\n[[loads]]\nkind = "force"\nlink = {link}\npoint = "{point}"\nalong = "{along}"\n{how}\n'


def _warnings(*loads: str) -> list:
    at = CRANK_ROCKER.index("\n[positions]")
    found = analyse(scene_of_text(CRANK_ROCKER[:at] + "".join(loads) + CRANK_ROCKER[at:]))
    return [warning for warning in found.warnings if warning.code == "along-moving-point"]


def test_a_cylinder_from_the_frame_is_not_told():
    assert _warnings(_force(4, "B", "D")) == []


def test_a_cylinder_from_a_moving_link_without_its_other_end_names_the_load_to_add():
    (warning,) = _warnings(_force(4, "S4", "E"))
    assert warning.position == 0 and "along-moving-point" in SCENE_WIDE_WARNINGS
    assert "E, a point of moving link 3" in warning.detail
    assert 'link = 3, point = "E", along = "S4" with the same value' in warning.detail


def test_a_spring_asks_for_its_stiffness_at_the_other_end():
    (warning,) = _warnings(_force(4, "S4", "E", "stiffness = 2000.0\nfree_length = 0.2"))
    assert "a spring pinned there" in warning.detail and "the same stiffness and free_length" in warning.detail


def test_a_cylinder_given_at_both_ends_is_not_told():
    assert _warnings(_force(4, "S4", "E"), _force(3, "E", "S4")) == []


def test_a_cylinder_given_at_both_ends_is_drawn_once_and_a_spring_beside_it_too():
    at = CRANK_ROCKER.index("\n[positions]")
    both = _force(4, "S4", "E") + _force(3, "E", "S4") + _force(4, "B", "D", "stiffness = 2000.0\nfree_length = 0.2")
    mechanism = analyse(scene_of_text(CRANK_ROCKER[:at] + both + CRANK_ROCKER[at:])).mechanism
    drawn = linkage_drawing._along(mechanism)
    assert len(drawn) == 2
    assert {(frozenset((along, point)), spring) for along, point, spring in drawn} == {
        (frozenset(("S4", "E")), False), (frozenset(("B", "D")), True)}


@pytest.mark.parametrize("along", ["C", "S4"])
def test_a_cylinder_between_two_points_of_its_own_link_is_told_it_moves_nothing(along):
    # C is the rocker's frame pivot (a frame point: a cylinder from the frame); S4 is a point of the rocker itself.
    found = _warnings(_force(4, "B", along))
    if along == "C":
        assert found == []
    else:
        (warning,) = found
        assert "S4, a point of link 4, the link it acts on" in warning.detail
        assert "pushes it on itself and moves nothing" in warning.detail


def test_the_note_tells_it_too():
    at = CRANK_ROCKER.index("\n[positions]")
    told = strings("en")["note_warning_along_moving_point"]
    assert told in note_markdown(analyse(scene_of_text(CRANK_ROCKER[:at] + _force(4, "S4", "E") + CRANK_ROCKER[at:])))
    assert told not in note_markdown(analyse(scene_of_text(CRANK_ROCKER[:at] + _force(4, "B", "D") + CRANK_ROCKER[at:])))
