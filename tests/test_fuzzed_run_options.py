"""What a fuzzer of `graphplan run`'s options (scenes × --only × --format × --sheet × --locale × --figures × the
output folder) found: each refusal names the option at fault and its real cause, in one line, and writes nothing.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.starters import starter

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(autouse=True)
def in_a_folder_of_its_own(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)


def starter_scene(tmp_path: Path, kind: str) -> Path:
    path = tmp_path / f"{kind}.toml"
    path.write_text(starter(kind, "en"), encoding="utf-8")
    return path


def refusal(capsys: pytest.CaptureFixture[str], argv: list[str]) -> str:
    """The one line a refused run ends with (exit status 2, no traceback)."""
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return err.rstrip("\n").splitlines()[-1]


def test_sheets_of_a_rotor_on_no_sheet_are_refused_for_the_sheet_format_not_a_mechanism(tmp_path, capsys):
    """A rotor's balancing is drawn on sheets of its own, without a mechanism (the same run on A3 draws them): on
    --sheet none the refusal said the scene "needs a mechanism", sending the user to add a linkage it does not need."""
    scene = starter_scene(tmp_path, "rotor")
    assert main(["run", str(scene), "--out", str(tmp_path / "a3"), "--only", "sheets", "--sheet", "A3"]) == 0
    assert (tmp_path / "a3" / "sheet_1.svg").is_file()
    capsys.readouterr()
    told = refusal(capsys, ["run", str(scene), "--out", str(tmp_path / "none"), "--only", "sheets", "--sheet", "none"])
    assert "--sheet" in told and '"none"' in told, told
    assert "mechanism" not in told, told
    assert not (tmp_path / "none").exists()


@pytest.mark.parametrize(("argv", "told"), [
    (["--only", "balancing,balancing"], "--only[1]: balancing is already listed at --only[0]"),
    (["--only", "vibration", "--only", "balancing", "--only", "vibration"],
     "--only[2]: vibration is already listed at --only[0]"),
    (["--only", "balancing", "--format", "png,png"], "--format[1]: png is already listed at --format[0]"),
])
def test_a_piece_or_format_listed_twice_is_refused_at_the_repeat(tmp_path, capsys, argv, told):
    """The scene's [output] include refuses a piece listed twice (most likely a slip for another, which the run
    then left out without a word); --only and --format took the repeat silently, as if the list were shorter."""
    scene = starter_scene(tmp_path, "rotor")
    line = refusal(capsys, ["run", str(scene), "--out", str(tmp_path / "out"), *argv])
    assert told in line, line
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(("given", "option"), [({"only": []}, "only"), ({"formats": ()}, "formats")])
def test_an_empty_list_of_pieces_or_formats_is_refused_from_python_as_from_the_command_line(tmp_path, capsys,
                                                                                            given, option):
    """`--only ""` and `--format ""` are refused ("names nothing"); scene.write, which takes the same options through
    the same run, wrote results.json alone for only=[] (and the SVG for formats=[]) without a word."""
    import graphplan

    scene = starter_scene(tmp_path, "rotor")
    with pytest.raises(SystemExit) as stopped:  # argparse's refusal, under the command's usage
        main(["run", str(scene), "--out", str(tmp_path / "cli"), f"--{option.removesuffix('s')}", ""])
    assert stopped.value.code == 2
    assert "names nothing" in capsys.readouterr().err
    with pytest.raises(graphplan.SceneError, match=rf"^{option}: names nothing"):
        graphplan.load(scene).write(tmp_path / "py", **given)
    assert not (tmp_path / "py").exists()


def test_a_sheet_option_too_small_is_told_the_option_that_draws_no_sheet(tmp_path, capsys):
    """--sheet A4 too small for the shaper's plans was told `or sheet = "none"`: a key of the scene, which names no
    sheet, where the way out is the option the user typed, --sheet none."""
    argv = ["run", str(ROOT / "fixtures" / "shaper_six_bar.toml"), "--only", "positions,sheets"]
    told = refusal(capsys, [*argv, "--out", str(tmp_path / "a4"), "--sheet", "A4"])
    assert told.startswith("graphplan: error: --sheet (in place of drawing.sheet): "), told
    assert 'sheet = "none"' not in told and "or --sheet none" in told, told
    assert not (tmp_path / "a4").exists()


def test_the_largest_sheet_is_offered_alone_not_with_a_bigger_one(tmp_path, capsys):
    """The Stephenson six-bar's plans fit on A1 alone, the largest format graphplan draws (the last of --sheet's
    choices): the refusal of A4 told "choose A1 or a bigger sheet", a sheet no option gives."""
    from graphplan.choices import SHEETS

    largest = next(sheet for sheet in SHEETS if sheet != "none")
    scene = str(ROOT / "fixtures" / "stephenson_six_bar.toml")
    told = refusal(capsys, ["run", scene, "--only", "positions,sheets", "--out", str(tmp_path / "a4"), "--sheet", "A4"])
    assert f"choose {largest}," in told and f"choose {largest} or a bigger sheet" not in told, told
    assert not (tmp_path / "a4").exists()
