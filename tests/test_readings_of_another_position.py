"""Hand readings of one position's plans given under another position's number: a student who measured the plans
of twelve positions and then set 24, or numbered the positions from 1 where the scene numbers them from 0, was told
every reading was misread, or a segment taken for another, when each was right for the position it was read at.

The ratchet fixture's readings at position 5 are a published worked example's (within its own errors there); the
position they fit under another count or numbering is found here by its crank angle, the same as the fixture's
position 5's, not by the warning's own search."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from graphplan.scene import loads

FIXTURE = Path("fixtures/ratchet_crank_rocker.toml").read_text(encoding="utf-8")


def _edited(old: str, new: str, text: str = FIXTURE) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def _far_off(analysis) -> list[str]:
    return [warning.detail for warning in analysis.warnings if warning.code == "measured-far-off"]


@pytest.fixture(scope="module")
def fixture_analysis():
    return loads(FIXTURE).analyse()


def _number_at_angle(analysis, angle: float) -> int:
    """The number of ``analysis``'s position at the crank ``angle`` (rad)."""
    (found,) = [int(number) for number, value in zip(analysis.positions.numbers, analysis.positions.values, strict=True)
                if math.isclose(math.remainder(value - angle, 2.0 * math.pi), 0.0, abs_tol=1e-9)]
    return found


def _angle_of(analysis, number: int) -> float:
    return float(analysis.positions.values[list(analysis.positions.numbers).index(number)])


def test_the_fixture_s_readings_are_near_its_own_position_5(fixture_analysis):
    assert not _far_off(fixture_analysis)


@pytest.mark.parametrize("edit", [("count       = 12", "count       = 24"),
                                  ("number_from = 0", "number_from = 1")], ids=["24 positions", "numbered from 1"])
def test_readings_under_another_number_are_told_the_position_they_fit(fixture_analysis, edit):
    analysis = loads(_edited(*edit)).analyse()
    (detail,) = _far_off(analysis)
    read_at = _number_at_angle(analysis, _angle_of(fixture_analysis, 5))
    assert read_at != 5
    assert detail.startswith("measured.5: readings more than 15 %")
    assert (f"every reading of the plans fits position {read_at} instead (none far off its exact values): readings "
            f"of position {read_at}'s plans, or of plans drawn with the positions counted or numbered otherwise "
            "(positions.count, start, number_from)?") in detail
    assert "a length misread" not in detail


def test_one_reading_misread_is_not_taken_for_another_position_s():
    """pb read 60 mm for 38.82: VB, VBC and ω4 far off, the other readings right for position 5 and for no other."""
    detail, = _far_off(loads(_edited("pb = 38.82,", "pb = 60.0,")).analyse())
    assert "pb = 60 mm gives VB" in detail
    assert "a length misread, or a segment taken for another?" in detail
    assert "instead (none far off its exact values)" not in detail


@pytest.mark.parametrize(("locale", "said"), [
    ("en", ("Every reading of the plans fits position {n} instead (none far off its exact values): readings of position "
            "{n}'s plans, or of plans drawn with the positions counted or numbered otherwise (positions.count, start, "
            "number_from)?")),
    ("ru", "Зато все замеры планов подходят к положению {n} (ни один не далёк от его точных значений)"),
    ("zh", "而全部实测值都与位置 {n} 相符（均不远离其精确值）"),
])
def test_the_error_table_and_the_note_say_the_position_the_readings_fit(fixture_analysis, tmp_path, locale, said):
    """The console told it; errors.md and the note, which are handed in, asked only of a length misread, and named
    a reading that is by chance another segment's length as "segments taken for one another"."""
    from graphplan.cli import main
    from graphplan.locale import strings

    text = _edited("count       = 12", "count       = 24")
    read_at = _number_at_angle(loads(text).analyse(), _angle_of(fixture_analysis, 5))
    scene = tmp_path / "scene.toml"
    scene.write_text(_edited('locale  = "ru"', f'locale  = "{locale}"', text), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "errors,note", "--sheet", "none"]) == 0
    words = strings(locale)
    question = words["errors_misread"].split("{readings}")[1].lstrip(".。 ")
    for name in ("errors.md", "note.md"):
        written = (tmp_path / "out" / name).read_text(encoding="utf-8")
        assert said.format(n=read_at) in written, name
        assert question not in written, name
        assert words["errors_named"].split("{precision}")[0] not in written, name


def test_one_reading_is_too_few_to_tell_another_position():
    """One segment gives three rows (pb: VB, VBC, ω4), which were counted as three readings: pb = 0.3 mm, read at
    position 5, fitted position 0, where the rocker stands still, and was told a reading of that position's."""
    block = FIXTURE[FIXTURE.index("velocity     = { pb = 38.82"):FIXTURE.index("[drawing]")]
    detail, = _far_off(loads(_edited(block, "velocity = { pb = 0.3 }\n\n")).analyse())
    assert "pb = 0.3 mm gives VB" in detail
    assert "a length misread, or a segment taken for another?" in detail
    assert "instead (none far off its exact values)" not in detail
