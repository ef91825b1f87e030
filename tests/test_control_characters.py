"""A control character in a scene's string makes its sheets SVG that does not parse: TOML reads "\\f" and "\\b" in a
"…" string as a form feed and a backspace, so a Windows path pasted into a title ("D:\\files\\fourbar\\build")
parses, and the sheets then open in no browser.  Such a string is refused at reading, naming its key, with the
path's way out; a tab and the line breaks of a multi-line title are kept, and their sheets are XML that parses."""

from __future__ import annotations

from xml.etree import ElementTree

import pytest
from test_scene_errors import first_error

import graphplan
from graphplan.analysis import analyse
from graphplan.render.sheet import Details, course_sheets
from graphplan.starters import starter

CRANK_ROCKER = starter("crank-rocker")
TITLE = 'title   = "Crank-rocker mechanism"'
PATH_HINT = ("a backslash in a TOML \"…\" string starts an escape (\\f is a form feed): in a path write / for \\, or "
             "use a literal '…' string, which takes backslashes as they are")


def with_title(line: str) -> str:
    assert TITLE in CRANK_ROCKER
    return CRANK_ROCKER.replace(TITLE, line)


def test_a_windows_path_in_a_title_is_refused_with_the_way_to_write_it() -> None:
    stage, error = first_error(with_title(r'title = "D:\files\fourbar\build"'))
    expected = ("scene.title: holds a form feed (U+000C), which no drawing or note can show (got "
                f"'D:\\x0ciles\\x0courbar\\x08uild'); {PATH_HINT}")
    assert (stage, str(error)) == ("load", expected)


@pytest.mark.parametrize(("line", "where", "what"), [
    (r'title = "bell\u0007"', "scene.title", "a bell (U+0007)"),
    (r'title = "nul\u0000"', "scene.title", "a null (U+0000)"),
    ('title = "x"\n[project]\nauthor = "A.\\u001BStudent"', "project.author", "an escape (U+001B)"),
])
def test_a_control_character_is_refused_naming_its_key(line, where, what) -> None:
    stage, error = first_error(with_title(line))
    assert stage == "load" and str(error).startswith(f"{where}: holds {what}, which no drawing or note can show")


def test_a_control_character_in_a_points_name_is_refused() -> None:
    stage, error = first_error(CRANK_ROCKER.replace("\nS2 =", '\n"S\\u00072" ='))
    expected = "points: the key 'S\\x072' holds a bell (U+0007), which no drawing or note can show"
    assert (stage, str(error)) == ("load", expected)


def test_a_scene_given_in_python_is_held_to_the_same() -> None:
    tables = {"scene": {"title": "a\x0cb"}}
    with pytest.raises(graphplan.SceneError, match=r"^scene\.title: holds a form feed \(U\+000C\)"):
        graphplan.load(tables)


def test_a_title_with_a_tab_a_line_break_and_xml_specials_draws_sheets_that_parse() -> None:
    scene = graphplan.load_text(with_title('title = """Crank\trocker & <links>\n"fourbar" D:/files"""'))
    assert scene.title == 'Crank\trocker & <links>\n"fourbar" D:/files'
    sheets = course_sheets(analyse(scene), "A1", Details(author="A.\tStudent"))
    for sheet in sheets:
        ElementTree.fromstring(sheet.svg())  # raises on XML that does not parse
