"""A student's first use: the mistakes one makes at the command line, each told in a line that names where (the
command, the flag, the key, the file) and what, with the near name meant, exit status 2, no traceback and nothing
written; the help says what the exit statuses mean, and the course project's table what each file the run writes is.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from console import without_progress

from graphplan.cli import main
from graphplan.starters import starter

ROOT = Path(__file__).resolve().parent.parent
SLIDER_CRANK = starter("slider-crank", "en")


@pytest.fixture(autouse=True)
def in_a_folder_of_its_own(tmp_path, monkeypatch):
    """Each command runs where a student's would, in a folder of its own: one that went wrong (new shaper --out "")
    wrote its file into the checkout."""
    monkeypatch.chdir(tmp_path)


def usage_error(capsys: pytest.CaptureFixture[str], argv: list[str]) -> str:
    """The error line argparse ends a refused command line with (after the command's usage), exit status 2."""
    with pytest.raises(SystemExit) as stopped:
        main(argv)
    assert stopped.value.code == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return err.rstrip("\n").splitlines()[-1]


def refused(capsys: pytest.CaptureFixture[str], argv: list[str]) -> str:
    """The one error line of a command refused with exit status 2, with no traceback, without its prefix."""
    status = main(argv)
    err = without_progress(capsys.readouterr().err)
    assert status == 2, err
    lines = [line for line in err.splitlines() if not line.startswith("warning: ")]
    assert "Traceback" not in err and len(lines) == 1 and lines[0].startswith("graphplan: error: "), err
    return lines[0].removeprefix("graphplan: error: ")


def scene_with(tmp_path: Path, old: str = "", new: str = "", name: str = "scene.toml") -> Path:
    """The slider-crank starter, as `graphplan new slider-crank` writes it, with ``old`` changed to ``new``."""
    assert old in SLIDER_CRANK, old
    path = tmp_path / name
    path.write_text(SLIDER_CRANK.replace(old, new, 1), encoding="utf-8")
    return path


# --- a name typed wrong on the command line is answered with the name meant --------------------------------------


@pytest.mark.parametrize(("argv", "meant"), [
    (["rn", "scene.toml"], "'run'"),
    (["chekc", "scene.toml"], "'check'"),
    (["new", "shapr"], "'shaper'"),
    (["new", "slider_crank"], "'slider-crank'"),
])
def test_a_command_or_kind_mistyped_is_answered_with_the_one_meant(capsys, argv, meant):
    told = usage_error(capsys, argv)
    assert "invalid choice" in told and told.endswith(f"did you mean {meant}?"), told


def test_no_command_at_all_is_told_with_the_commands_there_are(capsys):
    """It said "the following arguments are required: COMMAND", naming none."""
    assert usage_error(capsys, []) == "graphplan: error: give a command: run, check or new (graphplan --help tells " \
                                      "what each does)"


@pytest.mark.parametrize(("argv", "meant"), [
    (["run", "scene.toml", "--onyl", "velocity"], "--only"),
    (["run", "scene.toml", "--formt=png"], "--format"),
    (["run", "scene.toml", "--lcoale", "ru"], "--locale"),
    (["new", "shaper", "--outt", "x.toml"], "--out"),
    (["run", "scene.toml", "-l", "ru"], "--locale"),  # as other programs shorten their options
])
def test_an_option_mistyped_is_answered_with_the_one_meant(capsys, argv, meant):
    command = argv[0]
    told = usage_error(capsys, argv)
    assert told.startswith(f"graphplan {command}: error: unrecognized arguments: ") and \
        told.endswith(f"did you mean {meant}?"), told


@pytest.mark.parametrize(("argv", "meant"), [
    (["--only", "velocity", "acceleration"], "--only velocity,acceleration"),
    (["--only", "velocity", "acceleration", "forces"], "--only velocity,acceleration,forces"),
    (["--format", "svg", "png", "--only", "velocity"], "--format svg,png"),
])
def test_a_list_given_with_spaces_between_its_own_words_is_told_to_take_commas(capsys, argv, meant):
    """The shell hands "--only velocity acceleration" over as two words: argparse told "unrecognized arguments:
    acceleration" alone."""
    told = usage_error(capsys, ["run", "scene.toml", *argv])
    assert told.endswith(f"comma-separated: {meant}"), told


@pytest.mark.parametrize(("given", "meant"), [("RU", "ru"), ("russian", "ru"), ("cn", "zh")])
def test_a_locale_written_otherwise_is_answered_as_the_scene_s_locale_is(capsys, given, meant):
    """The scene's locale = "RU" is told "did you mean 'ru'?", --sheet a2 "did you mean 'A2'?"; --locale RU was told
    the bare list of choices."""
    told = usage_error(capsys, ["run", "scene.toml", "--locale", given])
    assert told == f"graphplan run: error: argument --locale: must be one of en, ru, zh; did you mean {meant!r}? " \
                   f"(got {given!r})"


@pytest.mark.parametrize("given", ["de", "fr"])
def test_a_language_graphplan_has_not_is_told_the_ones_it_has_and_none_as_meant(tmp_path, capsys, given):
    """Sharing one letter of two, de was "did you mean 'en'?" and fr "did you mean 'ru'?", in the scene and on the
    command line."""
    told = usage_error(capsys, ["run", "scene.toml", "--locale", given])
    assert told == f"graphplan run: error: argument --locale: must be one of en, ru, zh (got {given!r})"
    scene = scene_with(tmp_path, 'locale  = "en"', f'locale  = "{given}"')
    assert refused(capsys, ["check", str(scene)]) == f"scene.locale: must be one of en, ru, zh (got {given!r})"


def test_the_help_of_every_command_says_what_its_exit_statuses_mean(capsys):
    for argv in (["--help"], ["run", "--help"], ["check", "--help"], ["new", "--help"]):
        with pytest.raises(SystemExit) as stopped:
            main(argv)
        assert stopped.value.code == 0
        shown = capsys.readouterr().out
        assert "exit status:" in shown, argv
        for status in ("0 ", "2 ", "130 "):
            assert f"\n  {status}" in shown.split("exit status:")[1], (argv, status)


@pytest.mark.parametrize("argv", [["run", "scene.toml", "--out", ""], ["run", ""], ["check", ""],
                                  ["new", "shaper", "--out", ""]])
def test_an_empty_path_is_told_empty_not_taken_for_this_folder(tmp_path, capsys, argv):
    """--out "" (a shell variable left unset) was told as ".", the folder the command runs in, and new wrote
    shaper.toml there."""
    told = usage_error(capsys, argv)
    assert told.endswith("is empty: give a path"), told
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("argv", "told"), [
    (["--only", "velocty"], "--only[0]: must be one of positions, "),
    (["--only", "positions", "--only", "forcs"], "--only[1]: must be one of positions, "),
])
def test_a_piece_mistyped_is_told_before_the_mechanism_is_analysed(tmp_path, capsys, monkeypatch, argv, told):
    """--format pnng was told at once, --only velocty only once the whole mechanism was analysed."""
    scene = scene_with(tmp_path)
    analysed = []
    monkeypatch.setattr("graphplan.analysis.analyse", lambda *args, **kwargs: analysed.append(args))
    said = refused(capsys, ["run", str(scene), "--out", "out", *argv])
    assert said.startswith(told) and "did you mean" in said, said
    assert analysed == [] and sorted(path.name for path in tmp_path.iterdir()) == ["scene.toml"]


# --- the scene: a key misspelt, a length in millimetres -----------------------------------------------------------


def test_a_required_key_with_two_letters_swapped_is_named_as_typed(tmp_path, capsys):
    """rmp for rpm was told "driver.omega: is required but missing", naming neither the key typed nor the slip."""
    scene = scene_with(tmp_path, "rpm     = 1500.0", "rmp     = 1500.0")
    assert refused(capsys, ["check", str(scene)]) == "driver.rmp: unknown key; did you mean 'rpm'?"


@pytest.mark.parametrize(("old", "new", "written"), [
    ("length   = 0.19", "length   = 190 mm", "write length = 0.19"),
    ("length  = 0.05 ", "length  = 0.05 m", "write length = 0.05"),
    ("rpm     = 1500.0", "omega   = 1500 rpm", "write rpm = 1500"),
    ("mass    = 1.1", "mass    = 1100 g", "write mass = 1.1"),
    ("value     = 4500.0", "value     = 4.5 kN", "write value = 4500"),
    ("velocity_pole      = 100.0", "velocity_pole      = 100 mm", "write velocity_pole = 100"),
])
def test_a_unit_typed_after_a_number_is_told_with_the_number_in_the_scene_s_unit(tmp_path, capsys, old, new,
                                                                                  written):
    """TOML refused "length = 190 mm" as "Expected newline or end of document after a statement", which says
    nothing of the unit a student typed."""
    scene = scene_with(tmp_path, old, new)
    line = 1 + SLIDER_CRANK[:SLIDER_CRANK.index(old)].count("\n")
    told = refused(capsys, ["check", str(scene)])
    assert told.startswith(f"{scene}: is not valid TOML: ") and f"(at line {line}, " in told, told
    assert told.endswith(written), told


@pytest.mark.parametrize(("old", "new", "power"), [
    ("at = 0.055", "at = 55e", "'55e' ends at its exponent's e, with no power of ten after it"),
    ("length   = 0.19", "length   = 0.19E-", "'0.19E-' ends at its exponent's E, with no power of ten after it"),
])
def test_an_exponent_left_without_its_power_is_not_told_as_a_unit(tmp_path, capsys, old, new, power):
    """"at = 55e" (55e-3 meant) was told "'e' after the number: TOML takes the number alone, in the scene's units":
    a unit's advice for a power of ten begun and not finished."""
    told = refused(capsys, ["check", str(scene_with(tmp_path, old, new))])
    assert power in told and "e-3 for " in told and "after the number" not in told, told


def test_a_named_point_placed_in_millimetres_is_warned_of_before_the_refusal_it_causes(tmp_path, capsys):
    """S3 at 55 (mm meant) along a 0.19 m rod put it 55 m out: the check refused drawing.velocity_pole alone, a key
    the student never changed, and said nothing of the length typed in millimetres."""
    scene = scene_with(tmp_path, "at = 0.055", "at = 55")
    assert main(["check", str(scene)]) == 2
    err = without_progress(capsys.readouterr().err)
    assert "points.S3.at = 55 m" in err and "millimetres" in err, err
    assert err.index("points.S3.at") < err.index("graphplan: error: ")


# --- the output folder: a file, a folder that may not be written in ----------------------------------------------


@pytest.mark.parametrize("under", ["", "sub"])
def test_an_output_that_is_a_file_is_refused_naming_the_option(tmp_path, capsys, under):
    scene = scene_with(tmp_path)
    mine = tmp_path / "report.txt"
    mine.write_text("mine", encoding="utf-8")
    given = mine / under if under else mine
    told = refused(capsys, ["run", str(scene), "--out", str(given), "--only", "positions"])
    assert told.startswith(f"{given}: ") and "give --out a folder" in told, told
    assert mine.read_text(encoding="utf-8") == "mine"


@pytest.mark.skipif(os.name != "posix", reason="asked of POSIX disks alone")
def test_an_output_folder_that_may_not_be_written_in_is_left_as_it_is(tmp_path, capsys, monkeypatch):
    """A folder made read-only (chmod a-w) was swapped for a new one, and for another user than root its old
    files, which may not be deleted, stayed behind in a hidden .out.old-PID beside it. Root, who runs the tests,
    may write anywhere: the disk's answer is asked through os.access."""
    scene = scene_with(tmp_path)
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "positions"]) == 0
    capsys.readouterr()
    before = {path.name: path.read_bytes() for path in out.iterdir()}
    asked = os.access
    monkeypatch.setattr(os, "access", lambda path, mode, **kw: Path(path) != out and asked(path, mode, **kw))
    analysed = []
    monkeypatch.setattr("graphplan.analysis.analyse", lambda *args, **kwargs: analysed.append(args))
    told = refused(capsys, ["run", str(scene), "--out", str(out), "--only", "errors"])
    assert told == f"{out}: may not be written in (read-only, or another user's folder); give --out another folder"
    assert analysed == []
    assert {path.name: path.read_bytes() for path in out.iterdir()} == before
    assert sorted(path.name for path in tmp_path.iterdir()) == ["out", "scene.toml"]


# --- what the docs say a run writes -------------------------------------------------------------------------------


def test_the_course_project_s_table_names_the_parts_of_each_drawing_the_run_writes_in_parts(tmp_path, capsys):
    """dynamics-1.svg … and forces_friction_3-1.svg … stood in the shaper's folder with nothing in the table of what
    the run writes to say what they are (its test counts a part as its drawing's own)."""
    table = (ROOT / "docs" / "course-project.md").read_text(encoding="utf-8").split("writes into `shaper/`:")[1]
    table = table.split("\n\n", 2)[1]
    assert main(["new", "shaper"]) == 0
    # The parts of the drawings the note shows: those of the forces and the dynamics, written with the note.
    assert main(["run", "shaper.toml", "--out", "shaper", "--only", "forces,dynamics,note"]) == 0
    capsys.readouterr()
    parts = {re.sub(r"\d+", "N", path.name) for path in (tmp_path / "shaper").iterdir()
             if re.search(r"-\d+\.svg$", path.name)}
    listed = {re.sub(r"\d+", "N", name) for name in re.findall(r"`([^`]+-\d+\.svg)`", table)}
    assert parts and parts <= listed, parts - listed


# --- as a student runs it -----------------------------------------------------------------------------------------


def test_a_mistyped_command_run_as_a_program_prints_no_traceback_and_the_command_meant(tmp_path):
    shown = subprocess.run([sys.executable, "-m", "graphplan", "runn", "scene.toml"], cwd=tmp_path, capture_output=True,
                           text=True, timeout=120, check=False,
                           env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert shown.returncode == 2 and shown.stdout == ""
    assert "Traceback" not in shown.stderr and shown.stderr.rstrip().endswith("did you mean 'run'?"), shown.stderr
    assert list(tmp_path.iterdir()) == []


def test_the_run_s_help_names_the_default_folder_the_run_writes(tmp_path, capsys):
    """The help said output/<scene file name>: the folder is the name without its .toml."""
    with pytest.raises(SystemExit):
        main(["run", "--help"])
    helped = " ".join(capsys.readouterr().out.split())
    assert "default: output/<the scene file's name without .toml>" in helped
    (tmp_path / "press.toml").write_text(starter("crank-rocker", "en"), encoding="utf-8")
    assert main(["run", "press.toml", "--only", "positions"]) == 0
    assert [path.name for path in (tmp_path / "output").iterdir()] == ["press"]
