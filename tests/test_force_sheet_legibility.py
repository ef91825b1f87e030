"""A group cut free on a small sheet is drawn large enough for its labels to stand apart.

The class III triad's force sheets on A4 are the case: its group III(3,4,5,6) with its moment equations under it
(some 90 mm of caption) fits no A4 at the kinematics' μl = 0.0025 m/mm, and drawn smaller until it did (position 8
at μl = 0.01 m/mm) its thirty-odd names ran together (D over F, h9 over h14, G6 over h3).  The group now stands on a
part of its own at a μl its labels stand apart at, its equations going on on the next sheet.
"""

import dataclasses
import itertools
import re

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, with_length_scale
from graphplan.render.labels import text_box
from graphplan.render.primitives import Text
from graphplan.render.sheet import course_panels, course_sheets
from graphplan.run import as_asked
from graphplan.scales import next_standard_scale

GROUP = "III-3-4-5-6"
BODY_LABELS = re.compile(rf"forces-(\d+)(?:-\d+)?-body-{GROUP}-labels$")


@pytest.fixture(scope="module")
def triad():
    return with_length_scale(analyse(as_asked(graphplan.load("fixtures/triad_class_iii.toml"), "ru", "A4")))


@pytest.fixture(scope="module")
def sheets(triad):
    return course_sheets(triad, "A4")


def texts(layers):
    return [item for layer in layers for item in layer.items if isinstance(item, Text)]


def covering_one_another(labels):
    """The pairs of labels whose boxes on the paper meet."""
    return [(one.text, other.text) for one, other in itertools.combinations(labels, 2)
            if text_box(one).intersects(text_box(other))]


def body_sheets(sheets):
    """Each position's sheet that draws the group cut free, with its layer of labels."""
    found = {}
    for sheet in sheets:
        for layer in sheet.layers:
            if (match := BODY_LABELS.match(layer.name)) is not None:
                found[int(match.group(1))] = (sheet, layer)
    return found


def test_the_group_cut_free_stands_with_its_labels_apart(sheets, triad):
    drawn = body_sheets(sheets)
    assert sorted(drawn) == [plan.number for plan in triad.plans if plan.forces is not None]
    for number, (sheet, labels) in drawn.items():
        assert len(labels.items) > 30, (number, len(labels.items))  # the points, loads, moments and arms h
        assert covering_one_another(texts([labels])) == [], f"position {number}, sheet {sheet.number}"


def plans_with_their_body_sheets(sheets, triad):
    """Each plan position with forces, and the sheet its group cut free stands on."""
    drawn = body_sheets(sheets)
    return [(plan, drawn[plan.number][0]) for plan in triad.plans if plan.forces is not None]


def test_its_equations_go_on_on_the_next_sheet_whole(sheets, triad):
    for plan, sheet in plans_with_their_body_sheets(sheets, triad):
        group = next(group for group in plan.forces.groups if force_layout.group_id(group.label) == GROUP)
        body_words = " ".join(text.text for layer in sheet.layers if layer.name.endswith(f"body-{GROUP}-caption")
                              for text in layer.items)
        following = next(other for other in sheets if other.number == sheet.number + 1)
        equation_words = " ".join(text.text for layer in following.layers
                                  if layer.name.endswith(f"equations-{GROUP}-caption") for text in layer.items)
        # Set apart, the group keeps its title and scales; the next sheet, under the title again, says what the
        # moment equations found, each reaction of the group.
        assert "μl" in body_words and "Σ" not in body_words, plan.number
        assert group.label in equation_words and equation_words.count("Σ") >= len(group.moments), plan.number
        for found in group.found:
            assert f"{found.name} = " in equation_words, (plan.number, found.name)


def test_the_sheet_of_equations_alone_gives_no_scale(sheets):
    # Under their heading "continued" (on an A4 across), or bare.
    drawn = [[layer.name for layer in sheet.layers if layer.name.startswith("forces-")] for sheet in sheets]
    alone = [sheet for sheet, names in zip(sheets, drawn, strict=True)
             if names and all("-equations-" in name or name.endswith("-sheet-title") for name in names)]
    assert alone
    for sheet in alone:
        scale = [text.text for text in texts(sheet.layers) if re.fullmatch(r"\d+(?:[,.]\d+)?:\d+(?:[,.]\d+)?",
                                                                            text.text)]
        assert scale == [], sheet.number


def test_a_group_is_set_apart_only_where_drawn_smaller_its_labels_would_meet(sheets, triad):
    """The step not taken: at the next standard μl, with the equations under it, the labels find no room apart,
    one left on another till the placer's last pass moved it onto lines or a leader."""
    for plan, sheet in plans_with_their_body_sheets(sheets, triad):
        scale = next(text.text for text in texts(sheet.layers) if text.text.startswith("μl = "))
        value = float(re.match(r"μl = ([\d.,]+)", scale).group(1).replace(",", "."))
        smaller = dataclasses.replace(force_sheet(triad, plan), length_scale=next_standard_scale(value))
        body = next(drawing for row in force_layout.rows(smaller).drawings for drawing in row
                    if drawing.name == f"body-{GROUP}")
        assert body.labels_crowded, (plan.number, value)


def test_the_force_drawing_whole_keeps_the_equations_under_the_group(triad):
    """The file of the force sheet (forces_8.svg, the note's figure) is one drawing, not the sheets' parts."""
    panels = course_panels(triad, sheet="A4")
    for whole in panels.whole_forces:
        names = [layer.name for layer in whole.layers]
        assert not any("equations-" in name for name in names), whole.name
        words = " ".join(text.text for text in texts(whole.layers))
        assert "ΣMB(3)" in words, whole.name


def test_parting_keeps_the_caption_whole_and_the_reading_order(triad):
    plan = next(plan for plan in triad.plans if plan.forces is not None)
    rows = force_layout.rows(force_sheet(triad, plan))
    body = rows.drawings[0][0]
    parted = rows.parted([body.name])
    names = [[drawing.name for drawing in row] for row in parted.drawings]
    assert names[:2] == [[f"body-{GROUP}"], [f"equations-{GROUP}", f"polygon-{GROUP}"]]
    assert names[2:] == [[drawing.name for drawing in row] for row in rows.drawings[1:]]
    head, rest = parted.drawings[0][0], parted.drawings[1][0]
    assert head.layers == body.layers and rest.layers == []
    # The title heads both; nothing of the caption is lost or said twice but the title.
    assert head.caption[0] == rest.caption[0] == body.caption[0]
    assert (*head.caption, *rest.caption[1:]) == body.caption
    # One group still: a cut between its two rows costs what a cut between a group and its polygon does.
    assert parted.origins[:2] == (0, 0)
