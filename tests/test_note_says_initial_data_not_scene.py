"""The explanatory note is a student's, read by a teacher: it said "(the scene takes it as zero)", "the scene's
loads", "в сцене", "按场景给定", the program's word for its input file.  It says "the initial data" (исходные данные,
原始数据) or the given loads; "scene" stays only in a code span, where the note names a file or a key as typed."""

from __future__ import annotations

import re

import pytest

from graphplan.cli import main
from graphplan.locale import strings

LOCALES = ("en", "ru", "zh")
STARTERS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad", "flywheel", "rotor")
# The program's word in each language; a Russian word that holds the letters (эксцентриситет) is no such word.
SCENE = re.compile(r"\bscene|\bсцен|场景", re.IGNORECASE)


def _words(text: str) -> str:
    """``text`` without its code spans: a file or key named as typed may say scene."""
    return re.sub(r"`[^`]*`", "", text)


@pytest.mark.parametrize("locale", LOCALES)
def test_no_sentence_the_note_may_write_calls_the_initial_data_the_scene(locale):
    said = {key: value for key, value in strings(locale).items() if key.startswith("note_")
            and SCENE.search(_words(value))}
    assert not said, said


# --sheet none: choosing μl by laying out course sheets the run does not write was most of the shaper's and the triad's
# run, and each starter's note.md is the same bytes without it in every locale (diffed once); what the sheets could add
# to a note is among the sentences the test above reads.
@pytest.mark.parametrize("locale", LOCALES)
@pytest.mark.parametrize("name", STARTERS)
def test_a_starter_s_note_calls_its_input_the_initial_data(tmp_path, capsys, name, locale):
    scene, out = tmp_path / f"{name}.toml", tmp_path / "out"
    assert main(["new", name, "--out", str(scene)]) == 0
    assert main(["run", str(scene), "--out", str(out), "--only", "note", "--locale", locale, "--sheet", "none"]) == 0
    capsys.readouterr()
    note = _words((out / "note.md").read_text(encoding="utf-8"))
    assert not SCENE.search(note), [line for line in note.splitlines() if SCENE.search(line)]
