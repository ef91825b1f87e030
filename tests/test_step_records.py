"""The plans' step records carry what a similarity step and a line of action mean as fields.

Every step of every fixture's plans is checked against the mechanism at its instant: a similarity
step's letters are plan points of its link whose figure is similar to that of the points it names,
and a line of action runs square to or along the segment it names, along the guide, frame line, slot
or slide it names.  The ``text`` of the records is the English the drawings and records have always
shown, so it is checked against those strings; the notes in Russian and Chinese are worded from the
fields and keep none of that English.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.plans import DrawnLine, LineMeaning, Similarity, Step, guide_at
from graphplan.render.drawings import POSITIONS_FIELD_MM, paths_extent
from graphplan.report.note import note_markdown
from graphplan.scales import fit_scale

FIXTURES = sorted((Path(__file__).resolve().parent.parent / "fixtures").glob("*.toml"))
# Directions and similar figures agree to the plan's rounding, relative to the figures' size.
_TOLERANCE = 1e-9
# The English of the records, which a note in another language must not print.
_RECORD_ENGLISH = ("(similarity)", "similarity", "guide", "slot", "slide of link", "turns with")


def _offset_slot():
    """The slotted lever with its slot 40 mm off the pivot: its line of action is "the slide of link 4"."""
    scene = graphplan.load(FIXTURES[0].parent / "quick_return_slotted_lever.toml")
    (lever,) = scene.groups
    return dataclasses.replace(scene, groups=(dataclasses.replace(lever, offset=0.04),))


CASES = {path.stem: functools.partial(graphplan.load, path) for path in FIXTURES}
CASES["quick_return+slot-offset"] = _offset_slot


@functools.cache
def analysed(case: str, locale: str | None = None):
    scene = CASES[case]()
    if locale is None:
        return analyse(scene)
    # A note words its records alike at any μl.  Where the scene leaves μl to the program, the note's is fixed at the
    # standard one that draws the paths into the plan of positions' field: choosing it lays every sheet out at a few
    # μl, seven seconds a note and none of its words (the choice in Russian and Chinese is test_drawing_locales').
    drawing = scene.drawing
    if drawing.length_scale is None:
        drawing = dataclasses.replace(drawing, length_scale=fit_scale(paths_extent(analysed(case)), POSITIONS_FIELD_MM))
    # The title is the user's own text, in whatever language the user wrote it.
    return analyse(dataclasses.replace(scene, locale=locale, title="—", drawing=drawing))


def _steps(case: str):
    analysis = analysed(case)
    for pp in analysis.plans:
        for plan in (pp.velocity, pp.acceleration):
            for step in plan.steps:
                yield analysis, pp, plan, step


def _parallel(first: complex, second: complex) -> bool:
    return abs((first.conjugate() * second).imag) <= _TOLERANCE * abs(first) * abs(second)


def _square(first: complex, second: complex) -> bool:
    return abs((first.conjugate() * second).real) <= _TOLERANCE * abs(first) * abs(second)


def _where(positions, name: str, link: int) -> complex:
    """Where a point a similarity names is: a named point, or the link's point over a joint (B4 over B)."""
    if name in positions:
        return positions[name]
    joint = name.removesuffix(str(link))
    assert joint != name and joint in positions, name
    return positions[joint]


def _guides(mechanism):
    for group in mechanism.groups:
        yield from group.guides()


# The records' text is today's English, character for character.

@pytest.mark.parametrize("meaning, text", [
    (LineMeaning("perpendicular", ("A", "B")), "⊥ AB"),
    (LineMeaning("perpendicular", ("S4", "E")), "⊥ S4E"),
    (LineMeaning("parallel", ("C", "A")), "∥ CA"),
    (LineMeaning("guide"), "∥ guide"),
    (LineMeaning("guide", link=4), "∥ guide on link 4"),
    (LineMeaning("frame_line", name="ram"), "∥ ram"),
    (LineMeaning("slot", link=4), "∥ slot"),
    (LineMeaning("slide", link=6), "∥ slide of link 6"),
])
def test_a_line_meaning_reads_as_the_drawings_have_always_named_it(meaning, text):
    assert meaning.text == text
    assert DrawnLine("a", 1j, meaning).meaning == text
    assert meaning.parallel == text.startswith("∥")


@pytest.mark.parametrize("similarity, text", [
    (Similarity("e", "E", 3, ("a", "b"), ("A", "B")), "e: abe ∼ ABE (similarity)"),
    (Similarity("b4", "B4", 4, ("p", "d"), ("C", "D")), "b4: pdb4 ∼ CDB4 (similarity)"),
    (Similarity("s3", "S3", 3, turns_with=4), "s3: link 3 turns with link 4 (similarity)"),
])
def test_a_similarity_reads_as_the_records_have_always_written_it(similarity, text):
    assert similarity.text == text


@pytest.mark.parametrize("make", [
    lambda: LineMeaning("diagonal", ("A", "B")),
    lambda: LineMeaning("perpendicular", ("A",)),
    lambda: LineMeaning("slide"),
    lambda: LineMeaning("frame_line"),
    lambda: Similarity("e", "E", 3, ("a",), ("A",)),
    lambda: Similarity("e", "E", 3, ("a", "b"), ("A",)),
])
def test_a_record_that_says_too_little_is_refused(make):
    with pytest.raises(ValueError, match="line of action|similarity"):
        make()


# Every step of every fixture's plans.

def test_the_cases_between_them_draw_every_kind_of_line():
    kinds = {line.along.kind for case in CASES for *_, step in _steps(case) for line in step.lines}
    assert kinds == {"perpendicular", "parallel", "guide", "frame_line", "slot", "slide"}
    links = {line.along.link for case in CASES for *_, step in _steps(case) for line in step.lines
             if line.along.kind == "guide"}
    assert None in links and len(links) > 1  # a frame guide and a guide on a moving link


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_similarity_step_names_plan_points_whose_figure_is_similar_to_the_links(case):
    seen = 0
    for analysis, pp, plan, step in _steps(case):
        similar = step.similarity
        if similar is None:
            assert "(similarity)" not in step.equation and step.vectors
            continue
        seen += 1
        assert step.equation == similar.text and step.fixes == (similar.letter,)
        # It lays nothing but, for a point that is no image of the mechanism's own (a guide's point under a
        # slider), that point's vector from the pole, which the plan would otherwise leave out.
        assert not step.lines and all((vector.start, vector.end) == ("p", similar.letter) for vector in step.vectors)
        assert not step.vectors or similar.letter not in plan.images.values()
        assert similar.link in analysis.mechanism.moving_links
        assert {similar.letter, *similar.basis} <= set(plan.points)
        assert similar.basis, "every fixture's link has two images on the plan"
        members = {letter for _, letter in plan.members[similar.link]}
        assert set(similar.basis) <= members
        (la, lb), (na, nb) = similar.basis, similar.basis_points
        pa, pb, at = (_where({**pp.positions, **plan.auxiliary}, name, similar.link) for name in (na, nb, similar.point))
        assert pa != pb
        image = plan.points[la] + (plan.points[lb] - plan.points[la]) * (at - pa) / (pb - pa)
        extent = max(abs(plan.points[la]), abs(plan.points[lb]), abs(plan.points[similar.letter]), 1e-300)
        assert abs(plan.points[similar.letter] - image) <= _TOLERANCE * extent, similar.text
    assert seen


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_line_of_action_runs_along_what_it_names(case):
    for analysis, pp, plan, step in _steps(case):
        mechanism, scene = analysis.mechanism, analysis.scene
        for line in step.lines:
            along, what = line.along, (step.equation, line.along)
            assert line.through in plan.points, what
            if along.kind in ("perpendicular", "parallel"):
                first, second = ({**pp.positions, **plan.auxiliary}[name] for name in along.points)
                segment = second - first
                assert (_square if along.kind == "perpendicular" else _parallel)(line.direction, segment), what
            elif along.kind == "guide":
                named = [g for g in _guides(mechanism) if g.line is None and g.link == along.link]
                assert along.link is None or along.link in mechanism.moving_links, what
                assert any(_parallel(line.direction, guide_at(mechanism, pp.positions, pp.directions, g)[1])
                           for g in named), what
            elif along.kind == "frame_line":
                guide = scene.frame_lines[along.name]
                assert _parallel(line.direction, guide_at(mechanism, pp.positions, pp.directions, guide)[1]), what
            elif along.kind == "slot":
                (group,) = [g for g in mechanism.groups if g.kind == "RPP" and g.links[1] == along.link]
                slot = pp.directions[along.link] * complex(math.cos(group.angle), math.sin(group.angle))
                assert _parallel(line.direction, slot), what
            else:
                assert along.kind == "slide", what
                (group,) = [g for g in mechanism.groups if g.kind == "RPR" and g.links[1] == along.link]
                assert group.offset != 0.0 and _parallel(line.direction, pp.directions[along.link]), what


# The notes word the records in their own language.

def _wording(along: LineMeaning, text) -> str:
    if along.kind == "guide":
        return "∥ " + (text["note_guide"] if along.link is None else text["note_guide_on_link"].format(link=along.link))
    if along.kind == "slot":
        return "∥ " + text["note_slot"]
    if along.kind == "slide":
        return "∥ " + text["note_slide_of_link"].format(link=along.link)
    return along.text


@pytest.mark.parametrize("locale", ["ru", "zh"])
@pytest.mark.parametrize("case", sorted(CASES))
def test_a_note_in_russian_or_chinese_words_the_lines_and_similarities_from_their_fields(case, locale):
    note = note_markdown(analysed(case, locale))
    found = [word for word in _RECORD_ENGLISH if word in note.lower()]
    assert not found, found
    text = strings(locale)
    assert text["note_similarity"] in note
    for *_, step in _steps(case):
        for line in step.lines:
            assert _wording(line.along, text) in note, line.along


@pytest.mark.parametrize("case, locale", [("quick_return_slotted_lever", "ru"), ("shaper_six_bar", "zh"),
                                          ("tangent_mechanism_prp", "ru"), ("scotch_yoke", "zh")])
def test_a_similarity_without_two_images_is_worded_from_its_fields(case, locale):
    # No fixture has a link with a single image that a point is placed on; such a record is made from one that has.
    analysis = analysed(case, locale)
    pp = analysis.plans[0]
    index, step = next((i, s) for i, s in enumerate(pp.velocity.steps) if s.similarity is not None)
    similar = dataclasses.replace(step.similarity, basis=(), basis_points=(), turns_with=99)
    steps = list(pp.velocity.steps)
    steps[index] = Step(similar.text, (), fixes=step.fixes, similarity=similar)
    velocity = dataclasses.replace(pp.velocity, steps=tuple(steps))
    changed = dataclasses.replace(analysis, plans=(dataclasses.replace(pp, velocity=velocity), *analysis.plans[1:]))
    note = note_markdown(changed)
    assert strings(locale)["note_turns_with"].format(point=similar.letter, link=similar.link, other=99) in note
    assert "turns with" not in note and "(similarity)" not in note
