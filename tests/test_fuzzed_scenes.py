"""Scenes a mutation fuzzer (each fixture and starter with a key deleted, a value swapped, zero, inf, nan, a
string for a number, lists a step short or long, a name given twice, counts and scales at their extremes) found
answered wrongly: each as the small scene it came down to, and the answer a student should get instead."""

from __future__ import annotations

from pathlib import Path

import pytest

from graphplan.cli import main

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


def _refusal(tmp_path: Path, text: str, capsys: pytest.CaptureFixture[str]) -> str:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    return capsys.readouterr().err.strip().splitlines()[-1]


QUOTE = 'quote a name of your own in other letters ("{}" = …)'


@pytest.mark.parametrize(("name", "hint"), [
    ("🙂", QUOTE.format("🙂")),
    ("E′", QUOTE.format("E′")),
    ("E\u0303", QUOTE.format("E\u0303")),
    ("E₁", "'E₁' has a subscript one '₁' (U+2081) where 'E1' has a digit one '1' (U+0031): type 'E1'"),
], ids=["emoji", "prime", "combining-tilde", "subscript"])
def test_a_bare_point_name_toml_cannot_read_is_quoted_whole(tmp_path, capsys, name: str, hint: str) -> None:
    """A point's name in letters a bare TOML key cannot have was told to be quoted, but the hint's name stopped at
    the first character that is not a letter: an emoji named nothing ("" = …), E′ came out as "E" (quoting which
    loses the prime), and the subscript of E₁ was called an input method's full-width character."""
    text = f'[scene]\ntitle = "t"\n[points]\n{name} = {{ link = 3, from = "A", toward = "B", at = 0.2 }}\n'
    told = _refusal(tmp_path, text, capsys)
    assert "is not valid TOML" in told and "line 4" in told
    assert told.endswith(hint), told
    assert "full-width" not in told


@pytest.mark.parametrize("title", ["Привет", "🙂 press", "牛头刨床"], ids=["cyrillic", "emoji", "chinese"])
def test_a_title_in_other_letters_without_its_quotes_is_told_to_quote_the_text(tmp_path, capsys, title) -> None:
    """A value typed without its quotes in letters that are not ASCII was told "a key is an English word, not …:
    quote a name of your own (… = …)", a hint for a key, where the line's key was right and its value wanted quotes
    (and for an emoji it named '')."""
    told = _refusal(tmp_path, f"[scene]\ntitle = {title}   # the press\n", capsys)
    assert "line 2" in told and "a key is" not in told, told
    assert told.endswith(f'; a text is written in quotes: write title = "{title}"'), told


@pytest.mark.parametrize(("typed", "meant"), [
    ("length = 175 мм", "length = 0.175"), ("length = 17.5 см", "length = 0.175"),
    ("length = 175 毫米", "length = 0.175"), ("mass = 2500 г", "mass = 2.5"),
], ids=["russian-mm", "russian-cm", "chinese-mm", "russian-grams"])
def test_a_unit_in_the_scenes_own_languages_is_converted_as_its_latin_one(tmp_path, capsys, typed, meant) -> None:
    """A unit typed after a number in Russian or Chinese letters was dropped with the number kept as typed:
    175 мм was told "write length = 175", a crank a thousand times too long, where 175 mm is told 0.175."""
    told = _refusal(tmp_path, f"[driver]\n{typed}\n", capsys)
    assert told.endswith(f"after the number: TOML takes the number alone, in the scene's units (m, kg, N, s, "
                         f"degrees): write {meant}"), told


ONE_POSITION_THROUGH_TOGGLES = """
[scene]
title = "A central slider-crank whose rod is as long as its crank: C passes A at 90° and 270°"
[frame]
link = 1
points = { A = [0.0, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "A"
joint = "B"
length = 1.0
omega = 1.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["B", "C"]
length = 1.0
guide = { through = "A", angle = 0.0 }
assembly = "forward"
[positions]
count = 1
start = 45.0
plans = [1]
[drawing]
sheet = "none"
"""


def test_a_single_position_is_not_warned_of_a_toggle_between_it_and_itself(tmp_path, capsys) -> None:
    """One position of a crank that passes two toggles over its turn was warned "between positions 1 and 1 the
    lines of action … come within 0° of parallel …: the positions after it keep the assembly of the first": there
    is no position after it, and the turn comes back to the one analysed."""
    scene = tmp_path / "scene.toml"
    scene.write_text(ONE_POSITION_THROUGH_TOGGLES, encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    told = capsys.readouterr()
    assert "between positions 1 and 1" not in told.out + told.err


def test_check_refuses_a_length_scale_beyond_any_paper_where_no_sheet_is_fitted(tmp_path, capsys) -> None:
    """With sheet = "none" check said "ok" to a μl that draws the paths of the points 8 m across, and every run
    that drew the mechanism then refused it: check's ok means the run goes through."""
    text = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    text = text.replace("length_scale      = 0.0025", "length_scale = 0.0001").replace('sheet = "A1"', 'sheet = "none"')
    told = _refusal(tmp_path, text, capsys)
    assert told.startswith("graphplan: error: drawing.length_scale: draws the paths of the points 8.32e+03 mm across, "
                           "more than any paper (5000 mm)"), told
    assert main(["run", str(tmp_path / "scene.toml"), "--out", str(tmp_path / "out"), "--only", "positions"]) == 2
    assert capsys.readouterr().err.strip().splitlines()[-1] == told
    assert not (tmp_path / "out").exists()
