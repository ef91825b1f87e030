"""Labels that found no clear spot beside their point reach farther for one, and stay near what they name.

On the class III triad's force sheet of position 2 the names of three arms lay on drawn lines: h13 and h14 in the
star of arms at Σ6, h17 at the middle of its arm, which runs along the link E–F through S5 and its moments' arcs.
On the double rocker's lever of position 2 (drawn larger than its plan) the names of the arms h6, h8, h9 and h11,
placed again each time one near the pole was dropped, took in turn the spot the one before left by the pole, and
were all given under the drawing; h11's arm is 25 mm long (h9 now, named once with Mu4′'s on its line).  A name
still on a line once all stand now takes a spot clear of every line: beside another point of the arm it names, on a
short leader, or where a single neighbour stands that can itself stand clear elsewhere; an arm's name on the lever
keeps out of the pole's reach.
"""

import dataclasses
import math
from pathlib import Path

import pytest
import shapely
from shapely.geometry import LineString
from test_labels_off_lines import labels_on_lines

import graphplan
from graphplan import deliverables
from graphplan.analysis import analyse
from graphplan.render import force_lever, force_marks
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, length_scale
from graphplan.render.labels import Anchor, cover_one_another, place_labels, text_box
from graphplan.render.primitives import Text

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
# How far a label may stand from the point it names (mm): a short leader's reach, the gap and 3.2 letter heights
# of 2.8 mm (an arm's name), and a little for the box's corner.
LED_REACH_MM = 11.0
# How far a name set beside its arm may stand from the arm (mm), and from the arm's middle along it.
BESIDE_ARM_MM = 3.0
ALONG_ARM_MM = 26.0
# A class III triad whose force sheet of position 2 draws seventeen arms from Σ6.
CROWDED_STAR = Path(__file__).parent / "scenes" / "triad_crowded_star_zh.toml"


def laid_out(fixture: str, number: int) -> tuple[list, list[tuple[tuple[Anchor, ...], tuple[Text, ...]]]]:
    """The force sheet of position ``number`` as the run lays it out without a course sheet, and every call of the
    placer made for it: its anchors and the texts it placed (in the drawing's own frame, before the sheet's
    arrangement moves it)."""
    calls = []
    original = force_marks.place_labels

    def recording(anchors, obstacles, *args, **kwargs):
        placement = original(anchors, obstacles, *args, **kwargs)
        calls.append((tuple(anchors), placement.texts))
        return placement

    force_marks.place_labels = recording
    try:
        analysis = analyse(graphplan.load(FIXTURES / f"{fixture}.toml"))
        (position,) = [plan for plan in analysis.plans if plan.number == number]
        layers = force_layout.layout(force_sheet(analysis, position))
    finally:
        force_marks.place_labels = original
    return layers, calls


def drawing(layers, prefix: str) -> list:
    return [layer for layer in layers if layer.name.startswith(prefix)]


def placed(layers, prefix: str, calls) -> dict[str, tuple[Anchor, Text]]:
    """The anchor and the placed text (in the drawing's own frame) of each label of the drawing ``prefix``: the last
    call of the placer whose anchors are its labels, in their order."""
    names = [item.text for layer in drawing(layers, prefix) if layer.name.endswith("-labels") for item in layer.items
             if isinstance(item, Text)]
    anchors, texts = [call for call in calls if [anchor.text for anchor in call[0]] == names][-1]
    return {anchor.text: (anchor, text) for anchor, text in zip(anchors, texts, strict=True)}


def near_what_it_names(anchor: Anchor, text: Text) -> bool:
    """Whether the label's box stands within a short leader's reach of its point, or beside the arm it names
    (``Anchor.along``) not far along it."""
    box = text_box(text)
    if box.distance(shapely.Point(anchor.at)) <= LED_REACH_MM:
        return True
    along = getattr(anchor, "along", None)
    return (along is not None and box.distance(LineString(along)) <= BESIDE_ARM_MM
            and box.distance(shapely.Point(anchor.at)) <= ALONG_ARM_MM)


@pytest.fixture(scope="module")
def triad_sheet():
    return laid_out("triad_class_iii", 2)


@pytest.mark.parametrize("name", ["h13", "h14", "h17"])
def test_the_triad_s_arm_names_stand_clear_of_the_lines_near_their_arms(triad_sheet, name):
    layers, calls = triad_sheet
    body = drawing(layers, "body-III-3-4-5-6")
    assert name not in labels_on_lines(body), f"{name} lies on a drawn line"
    anchor, text = placed(layers, "body-III-3-4-5-6", calls)[name]
    assert near_what_it_names(anchor, text), f"{name} stands {text_box(text).distance(shapely.Point(anchor.at)):.1f} mm off"


def test_the_triad_s_force_sheet_has_no_label_on_a_line_where_its_arms_and_loads_are(triad_sheet):
    layers, _ = triad_sheet
    assert labels_on_lines(drawing(layers, "body-III-3-4-5-6")) == []


@pytest.fixture(scope="module")
def double_rocker_sheet():
    return laid_out("double_rocker_swing", 2)


def test_the_double_rocker_s_lever_letters_its_25_mm_arm_h9_clear_of_the_lines_or_gives_it_under(double_rocker_sheet):
    # Its one spot clear of the lines round b was led across the arrows of M4′ and Mu4′, reading as naming one of
    # them (tests/test_lever_leaders_off_arrows.py): then its length is given under the lever, as an arm's whose
    # name finds no spot off the lines is.  M4′'s arm, h11 while Mu4′'s on the same line was named h10 beside it, is
    # named once with it: h9.
    layers, calls = double_rocker_sheet
    lever = drawing(layers, "lever")
    caption = " ".join(item.text for layer in lever if layer.name.endswith("caption") for item in layer.items
                       if isinstance(item, Text))
    lettered = placed(layers, "lever", calls)
    assert ("h9" in lettered) != ("h9 = " in caption), "h9 is both lettered and given under the lever, or neither"
    if "h9" not in lettered:
        return
    anchor, text = lettered["h9"]
    assert "h9" not in labels_on_lines(lever)
    assert near_what_it_names(anchor, text)
    # Out of the pole's reach (the lever's own frame has the pole at its origin), where no load's name is read as it.
    assert text_box(text).distance(shapely.Point(0.0, 0.0)) >= force_lever.POLE_CLEAR_MM


def test_a_label_whose_point_is_ringed_by_lines_takes_a_clear_spot_on_a_short_leader():
    # A point inside two squares: every spot beside it covers a side of the inner one, every spot on the nearer rings
    # led to it a side of the outer one (the box pushed out to 1.8 letter heights beyond the gap reaches past 7 mm);
    # outside them the paper is clear.  Lying on one side beside the point had cost less than a leader across both.
    anchor = Anchor((0.0, 0.0), "h3", 2.8, prefer=math.pi / 2)
    squares = [LineString([(-side, -side), (side, -side), (side, side), (-side, side), (-side, -side)])
               for side in (3.8, 7.0)]
    placement = place_labels([anchor], squares)
    (text,) = placement.texts
    assert not any(text_box(text).intersects(square) for square in squares)
    assert text_box(text).distance(shapely.Point(anchor.at)) <= LED_REACH_MM
    assert len(placement.leaders) == 1


def test_a_name_crowded_at_its_arm_s_middle_slides_along_the_arm_beside_it():
    # A horizontal arm 60 mm long, its name's point at the middle, where a stroke crosses it every 0.5 mm for 16 mm
    # each way, so that the spots beside it and on short leaders all cover strokes; beyond that the arm runs clear.
    arm = ((-30.0, 0.0), (30.0, 0.0))
    strokes = [LineString([(x / 2, -20.0), (x / 2, 20.0)]) for x in range(-32, 33)]
    anchor = Anchor((0.0, 0.0), "h7", 2.8, prefer=math.pi / 2, along=arm)
    placement = place_labels([anchor], [LineString(arm), *strokes])
    (text,) = placement.texts
    box = text_box(text)
    assert not any(box.intersects(stroke) for stroke in strokes)
    assert not box.intersects(LineString(arm))
    assert box.distance(LineString(arm)) <= BESIDE_ARM_MM, "set beside its arm"
    assert not placement.leaders, "beside its arm, it needs no leader"


@pytest.mark.parametrize("fixture", sorted(path.stem for path in FIXTURES.glob("*.toml")))
def test_no_two_labels_of_a_drawing_cover_one_another(fixture):
    scene = graphplan.load(FIXTURES / f"{fixture}.toml")
    analysis = analyse(scene)
    # Every drawing the run makes, the course sheets with it.
    for made in deliverables.drawings(scene, analysis, deliverables.chosen(scene, analysis)):
        for layer in made.layers:
            if layer.name.endswith("labels"):
                assert not cover_one_another([item for item in layer.items if isinstance(item, Text)]), (
                    f"{made.stem}: {layer.name}")



def test_two_names_in_a_crowded_star_of_arms_take_a_leader_or_a_line_rather_than_one_another():
    """The triad's force sheet of position 2 draws seventeen arms from Σ6, beside F; every spot round h8 and h13
    covered another name's leader, which cost as much as covering a name, and the two stood one on the other.  The
    sheet is drawn at the run's μl, where its names are crowded (the run draws the group larger,
    tests/test_crowded_group_drawn_larger.py)."""
    analysis = analyse(graphplan.load(CROWDED_STAR))
    [position] = [plan for plan in analysis.plans if plan.number == 2]
    drawing = force_layout.layout(dataclasses.replace(force_sheet(analysis, position),
                                                      length_scale=length_scale(analysis)))
    bodies = [layer for layer in drawing if layer.name.startswith("body-III") and layer.name.endswith("labels")]
    assert bodies
    for layer in bodies:
        names = [item for item in layer.items if isinstance(item, Text)]
        assert {"h8", "h13"} <= {name.text for name in names}
        assert not cover_one_another(names), layer.name
