"""A name typed in letters that look like the scene's but are others (a Cyrillic С for the Latin C, a hyphen for
an en dash) is told apart from the name it looks like, wherever a name is looked up: on screen the two read the
same, so "must be one of O, C (got 'О')" alone contradicts itself."""

from __future__ import annotations

import pytest
from test_scene_errors import RATCHET, SLIDER_CRANK, first_error, to_toml, variant

import graphplan
from graphplan import SceneError
from graphplan import scene as scene_module
from graphplan.analysis import analyse

CYRILLIC_O = "'О' has the Cyrillic 'О' (U+041E) where 'O' has the Latin 'O' (U+004F): type the Latin letter"
CYRILLIC_C = "'С' has the Cyrillic 'С' (U+0421) where 'C' has the Latin 'C' (U+0043): type the Latin letter"


@pytest.mark.parametrize(("changes", "message"), [
    ({"driver.pivot": "О"},
     f"driver.pivot: must be a point of [frame] points: O, C (got 'О'); {CYRILLIC_O}"),
    ({"points.S4.from": "С"},
     f"points.S4.from: 'С' is not a point of link 4; its points are B, C; {CYRILLIC_C}"),
    ({"points.S3.toward": "В"},
     ("points.S3.toward: 'В' is not a point of link 3; its points are A, B, E; 'В' has the Cyrillic 'В' (U+0412) "
      "where 'B' has the Latin 'B' (U+0042): type the Latin letter")),
    ({"groups.0.joints.2": "С"},
     f"groups[0].joints[2]: 'С' is not known at this stage; {CYRILLIC_C}"),
    # The slip is the driver's Cyrillic А, not the group's Latin A that looks for it: told at the driver.
    ({"driver.joint": "А"},
     ("driver.joint: 'А' is not the 'A' that groups[0].joints[0] joins to; 'А' has the Cyrillic 'А' (U+0410) where "
      "'A' has the Latin 'A' (U+0041): type the Latin letter")),
    ({"links.3.centre": "ЅЗ"},  # the Cyrillic Ѕ and З
     "links.3.centre: must be a point fixed on link 3: A, B, E, S3 (got 'ЅЗ')"),
], ids=["pivot", "from", "toward", "group-joint", "driver-joint", "no-twin-no-hint"])
def test_a_name_in_lookalike_letters_is_told_which_letter_is_which(changes, message) -> None:
    stage, error = first_error(to_toml(variant(RATCHET, changes)))
    assert (stage, type(error), str(error)) == ("build", SceneError, message)


def test_a_centre_in_lookalike_letters_is_told_which_letter_is_which() -> None:
    stage, error = first_error(to_toml(variant(RATCHET, {"links.3.centre": "Ѕ3"})))
    assert stage == "build" and str(error) == ("links.3.centre: must be a point fixed on link 3: A, B, E, S3 (got 'Ѕ3'); 'Ѕ3' has the "
                          "Cyrillic 'Ѕ' (U+0405) where 'S3' has the Latin 'S' (U+0053): type the Latin letter")


def test_a_guide_typed_with_a_hyphen_for_the_lines_en_dash_says_so() -> None:
    """The shaper's starter names its guide x–x with an en dash, which a keyboard does not type."""
    scene = variant(SLIDER_CRANK, {"frame.lines": {"x–x": {"through": [0.0, 0.0], "angle": 0.0}},
                                   "groups.0.guide": "x-x"})
    stage, error = first_error(to_toml(scene))
    assert (stage, str(error)) == ("build", (
        "groups[0].guide: no frame line 'x-x'; [frame] lines has x–x; 'x-x' has a hyphen '-' (U+002D) where 'x–x' "
        "has an en dash '–' (U+2013): write it as 'x–x' is written (copy it), or name both alike in ASCII"))


def test_a_guide_typed_with_a_cyrillic_x_is_told_to_type_the_latin_one() -> None:
    scene = variant(SLIDER_CRANK, {"frame.lines": {"x–x": {"through": [0.0, 0.0], "angle": 0.0}},
                                   "groups.0.guide": "х–х"})
    assert str(first_error(to_toml(scene))[1]).endswith(
        "'х–х' has the Cyrillic 'х' (U+0445) where 'x–x' has the Latin 'x' (U+0078): type the Latin letter")


def test_two_points_named_in_lookalike_letters_are_refused_naming_both() -> None:
    """A Cyrillic С beside the frame's Latin C passed, and the sheets lettered two points C."""
    scene = variant(RATCHET, {"points.С": {"link": 4, "from": "C", "toward": "B", "at": 0.2}})
    stage, error = first_error(to_toml(scene))
    assert (stage, str(error)) == ("build", (
        "points.С: 'С' looks the same as the point 'C' of frame.points.C, and the drawings would letter both alike; "
        "'С' has the Cyrillic 'С' (U+0421) where 'C' has the Latin 'C' (U+0043): name the two apart"))


def test_a_scene_named_in_cyrillic_throughout_is_no_lookalike_of_itself() -> None:
    """Points named О, А, В, С in Cyrillic alone are names like any other."""
    text = to_toml(RATCHET)
    for latin, cyrillic in zip("OABC", "ОАВС"):
        text = text.replace(f'"{latin}"', f'"{cyrillic}"')
    mechanism = graphplan.build(scene_module.loads(text))
    assert set(mechanism.point_names()) >= {"О", "С", "А", "В"}


def test_a_friction_joint_in_lookalike_letters_is_told_which_letter_is_which() -> None:
    """[[friction]] joint = "О" listed the pairs O (1–2), … beside the 'О' it did not find."""
    scene = scene_module.loads(to_toml(variant(RATCHET, {"friction": [{"joint": "О", "f": 0.1, "radius": 0.02}]})))
    with pytest.raises(SceneError) as raised:
        analyse(scene)
    assert raised.value.where == "friction[0].joint"
    assert str(raised.value).endswith(f"(got 'О'); {CYRILLIC_O}")


def test_a_working_sense_in_lookalike_letters_is_told_which_letter_is_which() -> None:
    """sense = "fоrward" with a Cyrillic о was told "did you mean 'forward'?" of the word it seems to be."""
    stage, error = first_error(to_toml(variant(SLIDER_CRANK, {"positions.working.sense": "fоrward"})))
    assert (stage, str(error)) == ("load", (
        "positions.working.sense: must be one of ccw, cw, forward, backward; did you mean 'forward'? (got 'fоrward'); "
        "'fоrward' has the Cyrillic 'о' (U+043E) where 'forward' has the Latin 'o' (U+006F): type the Latin letter"))
