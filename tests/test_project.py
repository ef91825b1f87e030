"""The scene's ``[project]``: who made the project, in the sheets' title block and at the head of the note.

Before it, every title block's Разраб./设计/Created by, designation, organisation and date were drawn blank
and a student had to write them in by hand on every printed sheet.
"""

from __future__ import annotations

import dataclasses
import datetime
import math
import re
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.errors import SceneError
from graphplan.render.primitives import Text
from graphplan.render.sheet import course_sheets
from graphplan.render.title_block import fitted
from graphplan.report.note import note_markdown
from graphplan.scene import Project
from graphplan.starters import KINDS, starter

ROOT = Path(__file__).resolve().parents[1]
RATCHET = (ROOT / "fixtures" / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
PROJECT = """
[project]
author       = "Иванов И. И."
checked_by   = "Петров П. П."
organization = "МГТУ, гр. РК3-51"
designation  = "ТММ.КП.05.00.00"
date         = 2026-12-01
"""
DAY = datetime.date(2026, 12, 1)


def scene_with_project(locale: str):
    return dataclasses.replace(graphplan.load_text(RATCHET + PROJECT), locale=locale)


def texts_of(sheet) -> list[str]:
    return [item.text for layer in sheet.layers for item in layer.items if isinstance(item, Text)]


def test_the_project_is_read_with_its_date_as_a_date():
    project = graphplan.load_text(RATCHET + PROJECT).project
    assert project == Project(author="Иванов И. И.", checked_by="Петров П. П.", organization="МГТУ, гр. РК3-51",
                              designation="ТММ.КП.05.00.00", date=DAY)
    assert graphplan.load_text(RATCHET).project == Project()


@pytest.mark.parametrize(("entry", "where", "words"), [
    ('date = 2026-12-01T10:00:00', "project.date", "a date-time"),
    ('author = ""', "project.author", "must not be empty"),
    ('author = 5', "project.author", "must be a string"),
    ('supervisor = "B"', "project.supervisor", "unknown key"),
])
def test_a_wrong_project_entry_is_named(entry, where, words):
    with pytest.raises(SceneError) as raised:
        graphplan.load_text(RATCHET + "\n[project]\n" + entry + "\n")
    assert raised.value.where == where and words in str(raised.value)


# How each drafting standard's form writes the date: ESKD's dd.mm.yy in its 10 mm date column, GB/T
# 10609.1's 年、月、日 in that order, ISO 7200's ISO 8601.
@pytest.mark.parametrize(("locale", "author", "date"), [("ru", "Иванов И. И.", "01.12.26"),
                                                        ("zh", "Иванов И. И.", "2026.12.01"),
                                                        ("en", "Иванов И. И.", "2026-12-01")])
def test_every_sheet_s_title_block_carries_the_project(locale, author, date):
    sheets = course_sheets(analyse(scene_with_project(locale)), "A1")
    assert len(sheets) > 1
    for sheet in sheets:
        texts = texts_of(sheet)
        for value in (author, "ТММ.КП.05.00.00", date):
            assert value in texts, (sheet.number, value)
        assert "МГТУ, гр. РК3-51" in texts or {"МГТУ, гр.", "РК3-51"} <= set(texts)
        if locale != "en":  # ISO 7200 has no box for the checker
            assert "Петров П. П." in texts


def test_a_title_block_without_a_project_is_left_blank_for_the_pen():
    sheet = course_sheets(analyse(graphplan.load_text(RATCHET)), "A1")[0]
    assert not [text for text in texts_of(sheet) if "Иванов" in text or text.count(".") == 2 and text[:2].isdigit()]


@pytest.mark.parametrize(("locale", "lines"), [
    ("en", ["Designation: ТММ.КП.05.00.00", "Author: Иванов И. И.", "Checked by: Петров П. П.", "МГТУ, гр. РК3-51",
            "Date: 2026-12-01"]),
    ("ru", ["Обозначение: ТММ.КП.05.00.00", "Выполнил: Иванов И. И.", "Проверил: Петров П. П.", "МГТУ, гр. РК3-51",
            "Дата: 01.12.2026"]),
    ("zh", ["代号：ТММ.КП.05.00.00", "设计者：Иванов И. И.", "审核：Петров П. П.", "МГТУ, гр. РК3-51",
            "日期：2026年12月1日"]),
])
def test_the_note_s_head_lists_the_project_one_line_a_field(locale, lines):
    note = note_markdown(analyse(scene_with_project(locale))).splitlines()
    assert note[0].startswith("# ") and note[1] == ""
    # Hard line breaks: each field on a line of its own in HTML, PDF, Word and LaTeX alike.
    assert note[2:2 + len(lines)] == [line + "\\" for line in lines[:-1]] + [lines[-1]]
    assert note[2 + len(lines)] == ""
    assert note_markdown(analyse(graphplan.load_text(RATCHET)))[0:200].count("\\\n") == 0


def test_a_project_date_written_as_text_is_printed_as_written():
    scene = dataclasses.replace(graphplan.load_text(RATCHET + '\n[project]\ndate = "December 2026"\n'), locale="en")
    assert "Date: December 2026" in note_markdown(analyse(scene))
    sheet = course_sheets(analyse(scene), "A1")[0]
    assert "December 2026" in texts_of(sheet)


def test_a_scene_without_a_linkage_has_the_project_at_the_head_of_its_note():
    rotor = starter("rotor").replace("# [project]", "[project]").replace("# author ", "author ")
    note = note_markdown(None, scene=graphplan.load_text(rotor))
    assert "Author: A. Student" in note.splitlines()[2]


@pytest.mark.parametrize("kind", KINDS)
def test_every_starter_offers_the_project_table_to_fill_in(kind):
    text = starter(kind)
    filled = "\n".join(line[2:] if line.startswith(("# [project]", "# author", "# checked_by", "# organization",
                                                    "# designation", "# date")) else line
                       for line in text.splitlines())
    assert graphplan.load_text(filled).project == Project(author="A. Student", checked_by="Prof. B. Teacher",
                                                          organization="University, group 21",
                                                          designation="TMM.CP.01.00.00", date=DAY)


def test_a_project_name_too_long_for_its_box_is_warned_of_by_check_and_run(tmp_path, capsys):
    """A full name in ESKD's 23 mm Разраб. box was set at 1.2 mm without a word; a date the scene writes as text
    too. A TOML date, which the block writes its own way, and a surname with initials are no trouble."""
    from graphplan.cli import main
    from graphplan.render.primitives import text_width
    from graphplan.render.title_block import LABEL_SIZE, SMALLEST_LETTERING

    long_name, long_date = "Иванов Иван Иванович", "1 декабря 2026 г."
    # The 23 mm box less its paddings, at the block's size for names: the size the name is set at.
    expected = LABEL_SIZE * (23.0 - 2 * 0.8) / text_width(long_name, LABEL_SIZE)
    assert expected < SMALLEST_LETTERING
    scene = tmp_path / "long.toml"
    scene.write_text(RATCHET + f'\n[project]\nauthor = "{long_name}"\nchecked_by = "Петров П. П."\n'
                               f'date = "{long_date}"\n', encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    said = "".join(capsys.readouterr())
    (told,) = re.findall(r"project\.author: the title block's box sets it at ([\d.]+) mm", said)
    assert float(told) == pytest.approx(expected, abs=0.02)  # the estimate above, to its rounding down
    assert "project.date:" in said and "project.checked_by" not in said
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "sheets"]) == 0
    assert "project.author:" in "".join(capsys.readouterr())
    plain = tmp_path / "plain.toml"
    plain.write_text(RATCHET + PROJECT, encoding="utf-8")
    assert main(["check", str(plain)]) == 0
    assert "project." not in "".join(capsys.readouterr())


@pytest.mark.parametrize(("typed", "written"), [("12.03.2025", "12.03.25"), ("1.3.2025", "01.03.25"),
                                                ("31.02.2025", "31.02.2025")])
def test_a_full_dotted_date_is_written_in_eskd_s_box_as_dd_mm_yy(typed, written, tmp_path, capsys):
    """The Russian habit, date = "12.03.2025", was set at 1.1 mm in ESKD's 10 mm date column and warned of; ESKD
    writes dates dd.mm.yy there, as it writes a TOML date. Text that names no day of the calendar is printed as
    written, and warned of."""
    from graphplan.cli import main
    from graphplan.render.title_block import details_of

    text = RATCHET + f'\n[project]\ndate = "{typed}"\n'
    scene = graphplan.load_text(text)
    assert scene.locale == "ru"
    details = details_of(scene.project, scene.title, "eskd")
    assert details.date == written
    assert written in texts_of(course_sheets(analyse(scene), "A1")[0])
    path = tmp_path / "dated.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["check", str(path)]) == 0
    assert ("project.date:" in "".join(capsys.readouterr())) == (written == typed)
    # The other standards' boxes hold the date as typed.
    assert details_of(scene.project, scene.title, "iso").date == typed


def test_a_title_too_long_for_its_box_is_warned_of_as_a_project_name_is(tmp_path, capsys):
    """A 300-character title was set in the title block at about 1 mm without a word, while a long [project] name
    was warned of. The size told is the size the sheets set the title's lines at."""
    from graphplan.cli import main
    from graphplan.render.title_block import SMALLEST_LETTERING

    title = " ".join(["Quixotic linkage study"] * 14)
    text = RATCHET.replace('title   = "Crank-rocker of a ratchet feed"', f'title   = "{title}"')
    assert len(title) > 300 and title in text
    scene = tmp_path / "long.toml"
    scene.write_text(text, encoding="utf-8")
    sizes = {item.size for item in course_sheets(analyse(graphplan.load_text(text)))[0].layers
             for item in getattr(item, "items", []) if isinstance(item, Text) and "Quixotic" in item.text}
    assert max(sizes) < SMALLEST_LETTERING
    assert main(["check", str(scene)]) == 0
    said = "".join(capsys.readouterr())
    assert f"scene.title: the title block's box sets it at {math.floor(min(sizes) * 100) / 100:g} mm to fit it in" \
        in said
    assert "project." not in said
    assert main(["check", str(ROOT / "fixtures" / "ratchet_crank_rocker.toml")]) == 0
    assert "scene.title" not in "".join(capsys.readouterr())


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_a_russian_or_chinese_starter_shows_its_project_names_in_its_language(locale):
    """«A. Student» stood in the [project] of a starter whose title and guide were Russian."""
    text = starter("shaper", locale)
    filled = "\n".join(line[2:] if line.startswith(("# [project]", "# author", "# checked_by", "# organization"))
                       else line for line in text.splitlines())
    project = graphplan.load_text(filled).project
    for value in (project.author, project.checked_by, project.organization):
        assert value and not re.search(r"[A-Za-z]", value), value


def test_a_box_breaks_its_words_at_the_spaces_where_that_sets_them_as_large():
    """«清华大学 机械系 21 级» stood in the GB/T organisation box as «清华大学 机 / 械系 21 级»."""
    lines = [item.text for item in fitted("清华大学 机械系 21 级", (0.0, 0.0, 50.0, 18.0), 3.5, lines=2)]
    assert lines == ["清华大学", "机械系 21 级"]
    # An unspaced Chinese title still breaks between its ideographs.
    assert len(fitted("曲柄摇杆机构运动分析与力分析", (0.0, 0.0, 30.0, 18.0), 3.5, lines=2)) == 2


def test_a_chinese_title_broken_as_evenly_either_way_puts_the_shorter_line_first():
    """«单缸内燃机曲柄滑块机构» stood in the GB/T title box as «单缸内燃机曲 / 柄滑块机构», 曲柄 (crank) cut in two
    (a hunt's engine sheets): filling the first line took six ideographs of eleven.  Of the breaks as narrow, a
    Chinese title takes the one with the shorter lines first, short over long, as GB/T 9704 sets a title."""
    from graphplan.render.title_block import TitleBlockFields, labels, title_block

    fields = TitleBlockFields(title="单缸内燃机曲柄滑块机构", drawing="动力学分析", scale="", sheet=7, sheets=7,
                              language="zh")
    texts = [item.text for item in title_block("gb", fields, labels("zh"), (0.0, 0.0)) if isinstance(item, Text)]
    assert texts[texts.index("单缸内燃机") + 1] == "曲柄滑块机构"
    # A Latin title, and one broken at its spaces, fill their first line as before.
    assert [item.text for item in fitted("Crank-rocker of a ratchet feed", (0.0, 0.0, 40.0, 18.0), 4.0,
                                         lines=2)] == ["Crank-rocker of", "a ratchet feed"]


def test_a_name_set_just_under_the_smallest_lettering_is_not_told_it_is_set_at_it(tmp_path, capsys):
    """«checked_by: the title block's box sets it at 1.8 mm to fit it in (printed letters are no smaller than
    1.8 mm)»: 1.79 mm rounded to two digits read as no slip at all.  The size is written down to the hundredth."""
    from graphplan.cli import main
    from graphplan.render.title_block import SMALLEST_LETTERING

    text = RATCHET.replace("[frame]", '[project]\nchecked_by = "Prof. B. Teacher"\n\n[frame]', 1)
    assert "Prof. B. Teacher" in text
    sizes = {item.size for item in course_sheets(analyse(graphplan.load_text(text)))[0].layers
             for item in getattr(item, "items", []) if isinstance(item, Text) and "Teacher" in item.text}
    assert sizes and round(min(sizes), 1) == SMALLEST_LETTERING > min(sizes)
    scene = tmp_path / "teacher.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    said = "".join(capsys.readouterr())
    assert f"project.checked_by: the title block's box sets it at {math.floor(min(sizes) * 100) / 100:g} mm" in said
    assert "sets it at 1.8 mm" not in said
