"""A hostile user at the command line: the files given as the scene and as --out, and the console it prints on.

Each is answered in one line naming the file and what is wrong with it, exit status 2, no traceback, nothing
half-written: a picture or a Word document given for the scene, a JSON or YAML scene, Notepad's scene.toml.txt,
a folder, an empty file, /dev/zero, a loop of links; a console that cannot print the names; a pipe closed early.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from console import without_progress

from graphplan import scene as scene_module
from graphplan.cli import main
from graphplan.output import WRITTEN

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"
PACKAGE_ROOT = FIXTURE.parent.parent


def refused(capsys: pytest.CaptureFixture[str], argv: list[str]) -> str:
    """The one error line of a command that exits 2, with no traceback."""
    status = main(argv)
    err = without_progress(capsys.readouterr().err)
    assert status == 2, err
    assert "Traceback" not in err and err.count("\n") == 1 and err.startswith("graphplan: error: "), err
    return err.removeprefix("graphplan: error: ").rstrip("\n")


def command(*argv: str, cwd: Path, env: dict[str, str] | None = None, **options) -> subprocess.CompletedProcess:
    """``python -m graphplan`` as a user runs it, with this checkout's package first on the path."""
    environment = {**os.environ, "PYTHONPATH": str(PACKAGE_ROOT), **(env or {})}
    return subprocess.run([sys.executable, "-m", "graphplan", *argv], cwd=cwd, env=environment, capture_output=True,
                          timeout=300, check=False, **options)


# --- the scene: a file that is not a scene, or not where it was said to be ---------------------------------------


def _docx(path: Path) -> None:
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("word/document.xml", "<w:document/>")


@pytest.mark.parametrize(("name", "write", "kind"), [
    ("drawing.png", lambda path: path.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR" + bytes(range(256))),
     "a PNG image"),
    # Its many zero bytes were read as UTF-16 text: "save it as UTF-8".
    ("scene.docx", _docx, "a zip archive (a Word .docx"),
    ("noise.toml", lambda path: path.write_bytes(bytes((7 * index * index + 3) % 256 for index in range(3000))),
     "binary data"),
])
def test_a_file_that_is_not_text_is_told_for_what_it_is(capsys, tmp_path, name, write, kind):
    path = tmp_path / name
    write(path)
    err = refused(capsys, ["check", str(path)])
    assert err.startswith(f"{path}: is not a text file but {kind}"), err
    assert "UTF" not in err and "TOML:" not in err


@pytest.mark.parametrize(("text", "format_"), [
    ('{"frame": {"link": 1, "points": {"O": [0, 0]}}}\n', "JSON"),
    ('[{"kind": "RRR"}]\n', "JSON"),
    ("frame:\n  link: 1\n  points:\n    O: [0, 0]\n", "YAML"),
    ("---\nscene:\n  title: ratchet\n", "YAML"),
])
def test_a_json_or_yaml_scene_is_told_it_is_not_toml(capsys, tmp_path, text, format_):
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    err = refused(capsys, ["check", str(path)])
    assert err.startswith(f"{path}: is not valid TOML") and f"it looks like {format_}" in err, err


def test_a_scene_with_classic_mac_line_ends_is_read(capsys, tmp_path):
    """A carriage return alone ends each line: TOML refused the first one it met."""
    path = tmp_path / "mac.toml"
    path.write_bytes(FIXTURE.read_bytes().replace(b"\r\n", b"\n").replace(b"\n", b"\r"))
    assert main(["check", str(path)]) == 0
    assert capsys.readouterr().out.startswith(f"{path}: ok\nstructure: I(1,2)")


@pytest.mark.parametrize(("given", "beside"), [
    ("scene.toml", "scene.toml.txt"),  # Notepad's "Save as" adds .txt
    ("scene.toml", "Scene.TOML"),
    ("ratchet", "ratchet.toml"),
    ("'ratchet.toml'", "ratchet.toml"),  # Windows' cmd passes single quotes on
    ("ratchet.toml ", "ratchet.toml"),
    ("rachet_crank_rocker.toml", "ratchet_crank_rocker.toml"),  # a slip of a letter
    ("ratchet.toml", "ratchet_crank_rocker.toml"),  # the name's beginning alone
])
def test_a_missing_scene_names_the_file_it_likely_is(capsys, tmp_path, given, beside):
    shutil.copy(FIXTURE, tmp_path / beside)
    err = refused(capsys, ["run", str(tmp_path / given), "--out", str(tmp_path / "out")])
    assert err == f"{tmp_path / given}: cannot be read: No such file or directory; did you mean " \
                  f"{str(tmp_path / beside)!r}?"
    assert sorted(path.name for path in tmp_path.iterdir()) == [beside]


@pytest.mark.parametrize(("text", "told"), [("", "is empty"), ("  \n\n", "is empty"),
                                            ("# my scene\n\n# to do\n", "holds nothing but comments")])
def test_an_empty_scene_is_told_so_naming_the_file(capsys, tmp_path, text, told):
    """It said "frame: is required but missing", as of a scene that forgot one table."""
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    err = refused(capsys, ["check", str(path)])
    assert err.startswith(f"{path}: {told}: a scene has a mechanism's tables ([frame], [driver], [[groups]])"), err


def test_a_folder_given_as_the_scene_is_refused_naming_a_scene_in_it(capsys, tmp_path):
    """Windows reads a folder as "Permission denied"; here it was "Is a directory", with nothing more."""
    shutil.copy(FIXTURE, tmp_path / "ratchet.toml")
    (tmp_path / "notes.md").write_text("mine", encoding="utf-8")
    err = refused(capsys, ["check", str(tmp_path)])
    assert err == f"{tmp_path}: is a folder, not a scene file: give the scene file in it, " \
                  f"{str(tmp_path / 'ratchet.toml')!r}"


def test_a_scene_that_is_a_loop_of_links_is_told_so(capsys, tmp_path):
    (tmp_path / "a.toml").symlink_to(tmp_path / "b.toml")
    (tmp_path / "b.toml").symlink_to(tmp_path / "a.toml")
    err = refused(capsys, ["check", str(tmp_path / "a.toml")])
    assert err == f"{tmp_path / 'a.toml'}: cannot be read: it is a link that leads round to itself (a loop of links)"


def _little_memory() -> None:
    import resource

    # Should the read go on without end again, it fails here instead of taking the shared machine's memory.
    resource.setrlimit(resource.RLIMIT_AS, (3 * 2**30, 3 * 2**30))


def test_an_endless_device_given_as_the_scene_is_refused_at_the_size_limit(tmp_path):
    """/dev/zero has no size to ask: it was read until the memory ran out."""
    if not Path("/dev/zero").exists() or sys.platform == "win32":
        pytest.skip("no /dev/zero here")
    done = command("check", "/dev/zero", cwd=tmp_path, preexec_fn=_little_memory, text=True)
    told = (f"graphplan: error: /dev/zero: goes on past {scene_module.MAX_SCENE_BYTES} bytes, the most a scene may "
            "have (a device or a stream, not a scene file?)\n")
    assert (done.returncode, done.stderr) == (2, told)


def test_a_scene_file_name_that_is_not_utf8_titles_the_run(tmp_path):
    """Without a title the scene takes its file's name, whose undecodable byte no drawing could hold (a
    ParseError traceback as the sheets were read back)."""
    if sys.platform == "win32" or os.fsencode("x\udcff") != b"x\xff":
        pytest.skip("file names here are not bytes")
    text = "".join(line for line in FIXTURE.read_text(encoding="utf-8").splitlines(keepends=True)
                   if not line.startswith("title"))
    name = b"ratchet\xff.toml"
    (tmp_path / os.fsdecode(name)).write_text(text, encoding="utf-8")
    done = command("run", os.fsdecode(name), "--out", "out", "--only", "positions", cwd=tmp_path)
    assert done.returncode == 0, done.stderr.decode(errors="replace")
    assert json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["scene"] == "ratchet\ufffd"


# --- the command line and its console ------------------------------------------------------------------------------


@pytest.mark.parametrize(("option", "given", "commas"), [
    ("--format", "svg;png", "svg,png"), ("--format", "svg png", "svg,png"), ("--format", "svg, png;", "svg,png"),
    ("--only", "positions velocity", "positions,velocity"),
])
def test_a_list_given_with_semicolons_or_spaces_is_told_to_take_commas(capsys, tmp_path, option, given, commas):
    """It was told as one unknown name, with a did-you-mean of its first word: "did you mean 'svg'?"."""
    with pytest.raises(SystemExit) as ended:
        main(["run", str(FIXTURE), "--out", str(tmp_path / "out"), option, given])
    err = capsys.readouterr().err
    assert ended.value.code == 2
    assert f"argument {option}: separate the names with commas: {commas} (got {given!r})" in err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("slash", ["/", os.sep])
def test_a_new_scene_given_a_folder_not_made_yet_is_written_in_it(capsys, tmp_path, slash):
    """``--out project/`` wrote a file named project."""
    out = str(tmp_path / "project") + slash
    assert main(["new", "crank-rocker", "--out", out]) == 0
    written = tmp_path / "project" / "crank-rocker.toml"
    assert f"wrote {written}" in capsys.readouterr().out
    assert "[driver]" in written.read_text(encoding="utf-8")


@pytest.mark.parametrize(("encoding", "name"), [("ascii", "ratchet.toml"), ("cp1252", "кривошип.toml")])
def test_a_console_that_cannot_print_a_character_shows_it_escaped(tmp_path, encoding, name):
    """The structure's arrow, or a Cyrillic file name, on a console of another code page: a UnicodeEncodeError."""
    shutil.copy(FIXTURE, tmp_path / name)
    done = command("check", name, cwd=tmp_path, env={"PYTHONIOENCODING": encoding})
    out = done.stdout.decode(encoding)
    assert done.returncode == 0 and b"Traceback" not in done.stderr, done.stderr.decode(encoding)
    shown = name.encode(encoding, "backslashreplace").decode(encoding)
    assert out.startswith(f"{shown}: ok\nstructure: I(1,2) \\u2192 II2(3,4)\n"), out


@pytest.mark.skipif(sys.platform == "win32", reason="SIGPIPE is a POSIX signal")
@pytest.mark.parametrize("argv", [["check", str(FIXTURE)], ["new", "crank-rocker", "--out", "new.toml"],
                                  ["run", str(FIXTURE), "--only", "positions", "--out", "out"]])
def test_output_piped_to_a_reader_that_has_gone_ends_quietly(tmp_path, argv):
    """``graphplan check scene.toml | head -1``: a BrokenPipeError traceback once head had its line."""
    environment = {**os.environ, "PYTHONPATH": str(PACKAGE_ROOT)}
    process = subprocess.Popen([sys.executable, "-m", "graphplan", *argv], cwd=tmp_path, env=environment,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    process.stdout.close()  # the reader gone before the first line
    err = without_progress(process.stderr.read().decode())
    assert (process.wait(timeout=300), err) == (128 + signal.SIGPIPE, "")


def test_a_run_whose_terminal_is_closed_ends_as_when_terminated(tmp_path, capsys, monkeypatch):
    """SIGHUP ended the process at once, leaving the half-written staging folder beside the output."""
    if not hasattr(signal, "SIGHUP"):
        pytest.skip("no SIGHUP here")
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "positions"]) == 0
    before = {path.name: path.read_bytes() for path in out.iterdir()}
    # Python's default SIGHUP would end pytest itself should the command line not take the signal.
    handler_before = signal.signal(signal.SIGHUP, lambda number, frame: None)
    write_text = Path.write_text

    def hung_up_on_the_way(path, *args, **kwargs):
        written = write_text(path, *args, **kwargs)
        if ".partial-" in str(path):
            os.kill(os.getpid(), signal.SIGHUP)
        return written

    monkeypatch.setattr(Path, "write_text", hung_up_on_the_way)
    try:
        ignoring = signal.getsignal(signal.SIGHUP)
        status = main(["run", str(FIXTURE), "--out", str(out), "--only", "positions,velocity"])
        assert signal.getsignal(signal.SIGHUP) == ignoring
    finally:
        signal.signal(signal.SIGHUP, handler_before)
    assert status == 128 + signal.SIGHUP
    assert "graphplan: the terminal was closed" in capsys.readouterr().err
    assert sorted(entry.name for entry in tmp_path.iterdir()) == ["out"]
    assert {path.name: path.read_bytes() for path in out.iterdir()} == before


# --- the output folder ---------------------------------------------------------------------------------------------


@pytest.mark.parametrize("under", ["", "sub"])
def test_an_output_folder_through_a_loop_of_links_is_refused_before_the_run(capsys, tmp_path, under):
    """pathlib's RuntimeError "Symlink loop" came out as a traceback."""
    (tmp_path / "a").symlink_to(tmp_path / "b")
    (tmp_path / "b").symlink_to(tmp_path / "a")
    out = tmp_path / "a" / under if under else tmp_path / "a"
    err = refused(capsys, ["run", str(FIXTURE), "--out", str(out), "--only", "positions"])
    assert err == f"{out}: leads through a link that leads round to itself (a loop of links); give --out another folder"
    assert sorted(path.name for path in tmp_path.iterdir()) == ["a", "b"]


def test_a_new_scene_is_not_written_over_a_link_that_leads_nowhere(capsys, tmp_path):
    """A link to itself does not exist as a file: ``new --out`` put a file in its place."""
    link = tmp_path / "scene.toml"
    link.symlink_to(link)
    err = refused(capsys, ["new", "crank-rocker", "--out", str(link)])
    assert err == f"{link}: exists already; give another name with --out"
    assert link.is_symlink() and os.readlink(link) == str(link)


def test_a_user_file_named_as_the_run_s_but_for_capitals_is_refused(capsys, tmp_path):
    """On Windows' and macOS's disks Note.md is the run's note.md: the user's note was replaced by the run's, or
    theirs put back over it as the folder was swapped."""
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "note"]) == 0
    capsys.readouterr()
    (out / "Note.md").write_text("my own note", encoding="utf-8")
    before = {path.name: path.read_bytes() for path in out.iterdir()}
    err = refused(capsys, ["run", str(FIXTURE), "--out", str(out), "--only", "note"])
    assert err == f"{out}: holds Note.md (the run's note.md on a disk that does not tell capitals apart), which no " \
                  "graphplan run wrote there and this run would replace; move it away, or give --out another folder"
    assert {path.name: path.read_bytes() for path in out.iterdir()} == before


def test_a_spoilt_list_of_what_runs_wrote_is_refused_naming_it(capsys, tmp_path):
    """A list of bytes that are not text (overwritten by a tool, a disk's fault) was a UnicodeDecodeError traceback."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "thesis.docx").write_bytes(b"PK\x03\x04 mine")
    (out / WRITTEN).write_bytes(b"\x89PNG\r\n\x1a\n\xff\xfe")
    err = refused(capsys, ["run", str(FIXTURE), "--out", str(out), "--only", "positions"])
    assert err == f"{out / WRITTEN}: the list of the files runs wrote there cannot be read (not text); give --out " \
                  f"another folder, or delete the list and the runs' files in {out}"
    assert sorted(path.name for path in out.iterdir()) == [WRITTEN, "thesis.docx"]
    assert sorted(path.name for path in tmp_path.iterdir()) == ["out"]


def test_a_mount_point_given_as_the_output_is_refused_before_the_run(capsys, tmp_path, monkeypatch):
    """The folder is replaced by a rename, which a mount point refuses ("Device or resource busy") once everything
    has been analysed and drawn."""
    out = tmp_path / "usb"
    out.mkdir()
    monkeypatch.setattr(os.path, "ismount", lambda path: Path(path) == out)
    analysed = []
    monkeypatch.setattr("graphplan.analysis.analyse", lambda *args, **kwargs: analysed.append(args))
    err = refused(capsys, ["run", str(FIXTURE), "--out", str(out), "--only", "positions"])
    assert err == f"{out}: is where a disk is mounted, which a run cannot replace; give --out a folder in it"
    assert analysed == [] and list(out.iterdir()) == []


@pytest.mark.parametrize("argv", [["check", "{long}.toml"], ["run", str(FIXTURE), "--out", "{long}"],
                                  ["run", str(FIXTURE), "--out", "{long}/sub"], ["new", "crank-rocker", "--out", "{long}"],
                                  ["new", "crank-rocker", "--out", "{long}/"]])
def test_a_name_too_long_for_the_disk_is_told_in_one_line(capsys, tmp_path, argv):
    """Looking whether it was a folder raised "File name too long" as a traceback (pathlib asks without a guard)."""
    long = str(tmp_path / ("x" * 300))
    err = refused(capsys, [word.format(long=long) for word in argv])
    assert err.endswith(("cannot be read: File name too long", "cannot be written (File name too long)")), err
    assert list(tmp_path.iterdir()) == []


def test_a_name_that_is_not_utf8_is_printed_on_a_strict_utf8_console(tmp_path):
    """PYTHONIOENCODING=utf-8 prints no surrogate os.fsdecode makes of an undecodable byte: a UnicodeEncodeError
    as the run said what it wrote."""
    if sys.platform == "win32" or os.fsencode("x\udcff") != b"x\xff":
        pytest.skip("file names here are not bytes")
    out = os.fsdecode(b"out\xfe")
    done = command("run", str(FIXTURE), "--out", out, "--only", "positions", cwd=tmp_path,
                   env={"PYTHONIOENCODING": "utf-8"})
    assert done.returncode == 0 and b"Traceback" not in done.stderr, done.stderr.decode(errors="replace")
    assert done.stdout.decode("utf-8").endswith("wrote out\\udcfe/results.json\n")


@pytest.mark.skipif(os.name != "posix", reason="asked of POSIX disks alone")
@pytest.mark.parametrize("given", ["out", "out/deeper"])
def test_an_output_in_a_folder_that_may_not_be_written_in_is_refused_before_the_run(capsys, tmp_path, monkeypatch,
                                                                                       given):
    """A read-only disk refused the staging folder only after the analysis and the drawings (and root, who runs the
    tests here, may write anywhere: the disk's answer is asked through os.access)."""
    locked = tmp_path / "locked"
    locked.mkdir()
    asked = os.access
    monkeypatch.setattr(os, "access", lambda path, mode, **kw: Path(path) != locked and asked(path, mode, **kw))
    analysed = []
    monkeypatch.setattr("graphplan.analysis.analyse", lambda *args, **kwargs: analysed.append(args))
    err = refused(capsys, ["run", str(FIXTURE), "--out", str(locked / given), "--only", "positions"])
    assert err == f"{locked / given}: {locked} may not be written in (a read-only disk, or another user's folder); " \
                  "give --out another folder"
    assert analysed == [] and list(locked.iterdir()) == []


@pytest.mark.parametrize("argv", [["run", str(FIXTURE), "--out=~/report", "--only", "positions"],
                                  ["new", "crank-rocker", "--out=~/report/"]])
def test_an_output_given_from_the_home_folder_after_an_equals_sign_goes_there(capsys, tmp_path, monkeypatch, argv):
    """The shell expands no ~ after --out=: a folder named ~ was made in the folder the command ran in."""
    home = tmp_path / "home"
    home.mkdir()
    monkeypatch.setenv("HOME", str(home))
    monkeypatch.setenv("USERPROFILE", str(home))
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 0
    assert f"wrote {home / 'report'}" in capsys.readouterr().out
    assert sorted(path.name for path in tmp_path.iterdir()) == ["home"]
    assert (home / "report").is_dir()


@pytest.mark.skipif(sys.platform == "win32", reason="Windows removes no folder a process runs in")
def test_a_run_in_a_folder_deleted_under_it_is_told_so(capsys, tmp_path, monkeypatch):
    """A terminal left in a folder that was removed: os.getcwd's FileNotFoundError came out as a traceback, for
    an absolute --out as well as the default output/<scene>."""
    gone = tmp_path / "gone"
    gone.mkdir()
    monkeypatch.chdir(gone)
    gone.rmdir()
    err = refused(capsys, ["run", str(FIXTURE), "--only", "positions"])
    assert err == "output/ratchet_crank_rocker: is a path from the folder the command runs in, which is gone " \
                  "(deleted or moved); give --out a full path, or run the command in another folder"
    assert main(["run", str(FIXTURE), "--only", "positions", "--out", str(tmp_path / "out")]) == 0
    assert sorted(path.name for path in (tmp_path / "out").iterdir()) == [WRITTEN, "positions.svg", "results.json"]


def test_a_list_of_what_runs_wrote_that_names_paths_outside_the_folder_touches_nothing_there(capsys, tmp_path):
    """A hand-edited list may name anything: only the folder's own entries are ever taken for a run's."""
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "positions"]) == 0
    outside = tmp_path / "outside.txt"
    outside.write_text("mine", encoding="utf-8")
    listed = (out / WRITTEN).read_text(encoding="utf-8")
    (out / WRITTEN).write_text(listed + f"../outside.txt\n{outside}\n{tmp_path}\n..\n.\n", encoding="utf-8")
    (out / "draft.md").write_text("mine too", encoding="utf-8")
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "positions"]) == 0
    assert outside.read_text(encoding="utf-8") == "mine" and (out / "draft.md").read_text(encoding="utf-8") == "mine too"
    assert sorted(path.name for path in tmp_path.iterdir()) == ["out", "outside.txt"]


def test_a_file_of_a_run_changed_by_hand_since_is_kept_as_the_user_s(capsys, tmp_path):
    """A sheet lettered by hand after a run was deleted by the next run that did not draw it (``--only errors``), and a
    note finished in an editor was replaced without a word: both were on the list of what runs wrote there."""
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "positions,errors"]) == 0
    lettered = (out / "positions.svg").read_text(encoding="utf-8").replace("</svg>", "<!-- my name --></svg>")
    (out / "positions.svg").write_text(lettered, encoding="utf-8")
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "errors"]) == 0
    assert (out / "positions.svg").read_text(encoding="utf-8") == lettered
    capsys.readouterr()
    (out / "errors.md").write_text("# my own errors table\n", encoding="utf-8")
    before = {path.name: path.read_bytes() for path in out.iterdir()}
    err = refused(capsys, ["run", str(FIXTURE), "--out", str(out), "--only", "errors"])
    assert err == f"{out}: holds errors.md, changed since a graphplan run wrote it: this run would replace it; move " \
                  "it away, or give --out another folder"
    assert {path.name: path.read_bytes() for path in out.iterdir()} == before


def test_a_run_replaces_its_own_files_unchanged_and_those_an_older_run_listed_without_digests(tmp_path):
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "positions,errors"]) == 0
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "positions"]) == 0
    assert not (out / "errors.md").exists()  # the earlier run's, untouched, so replaced
    # The list as runs wrote it before it kept digests: names alone, taken at their word.
    names = [line.split("\t")[0] for line in (out / WRITTEN).read_text(encoding="utf-8").splitlines()]
    (out / WRITTEN).write_text("".join(f"{name}\n" for name in names), encoding="utf-8")
    (out / "positions.svg").write_text("<svg/>", encoding="utf-8")
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "errors"]) == 0
    assert not (out / "positions.svg").exists() and (out / "errors.md").is_file()


def test_a_name_added_by_hand_to_the_list_of_what_runs_wrote_is_not_taken_for_a_run_s(tmp_path):
    """A hand-edited list naming the user's own file of the folder had that file deleted by the next run."""
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "positions"]) == 0
    (out / "thesis.docx").write_bytes(b"mine")
    with (out / WRITTEN).open("a", encoding="utf-8") as listed:
        listed.write("thesis.docx\n")
    assert main(["run", str(FIXTURE), "--out", str(out), "--only", "errors"]) == 0
    assert (out / "thesis.docx").read_bytes() == b"mine"


def test_the_home_folder_given_as_the_output_is_refused(capsys, tmp_path, monkeypatch):
    """``--out ~`` meant "put it in my home": the run renamed the home folder away and a new one into its place."""
    home = tmp_path / "home"
    home.mkdir()
    (home / "thesis.docx").write_bytes(b"mine")
    monkeypatch.setenv("HOME", str(home))
    monkeypatch.setenv("USERPROFILE", str(home))
    monkeypatch.chdir(tmp_path)  # where a ~ taken for a name would have been written
    inode = home.stat().st_ino
    err = refused(capsys, ["run", str(FIXTURE), "--only", "positions", "--out", "~"])
    assert err == f"{home}: is your home folder, which a run cannot replace; give --out a folder of its own"
    assert home.stat().st_ino == inode and sorted(path.name for path in home.iterdir()) == ["thesis.docx"]


@pytest.mark.parametrize("under", ["", "sub/"])
def test_a_new_scene_under_a_file_names_the_file(capsys, tmp_path, under):
    """``new --out afile/`` said "cannot be written (File exists)": mkdir's words for a file in the folder's place."""
    blocking = tmp_path / "afile"
    blocking.write_text("keep me", encoding="utf-8")
    out = f"{blocking}/{under}"
    err = refused(capsys, ["new", "crank-rocker", "--out", out])
    assert err == f"{Path(out) / 'crank-rocker.toml'}: {blocking} is not a folder, so the file cannot go in it"
    assert blocking.read_text(encoding="utf-8") == "keep me" and sorted(tmp_path.iterdir()) == [blocking]


class _GoneTerminal:
    """stderr of a terminal closed: every write fails as a tty hung up does."""

    def write(self, text: str) -> int:
        raise OSError(5, "Input/output error")

    def flush(self) -> None:
        raise OSError(5, "Input/output error")


def test_a_run_whose_terminal_is_closed_with_its_stderr_exits_with_sighup_s_status(tmp_path, monkeypatch):
    """The line saying so could not be written either: its EIO came out as a traceback, with status 1."""
    if not hasattr(signal, "SIGHUP"):
        pytest.skip("no SIGHUP here")

    def hung_up(*args, **kwargs):
        os.kill(os.getpid(), signal.SIGHUP)

    monkeypatch.setattr("graphplan.analysis.analyse", hung_up)
    monkeypatch.setattr(sys, "stderr", _GoneTerminal())
    handler_before = signal.signal(signal.SIGHUP, lambda number, frame: None)  # pytest's own, should it get through
    try:
        status = main(["run", str(FIXTURE), "--out", str(tmp_path / "out"), "--only", "positions"])
    finally:
        signal.signal(signal.SIGHUP, handler_before)
    assert status == 128 + signal.SIGHUP
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("argv", "told"), [
    (["run", str(FIXTURE), "--only", "positions", "--out", "{link}/sub"], "{link}/sub"),
    (["new", "crank-rocker", "--out", "{link}/sub/"], "{link}/sub/crank-rocker.toml"),
])
def test_a_link_to_nothing_on_the_way_to_the_output_is_named(capsys, tmp_path, monkeypatch, argv, told):
    """mkdir took the link for a file in the way: "File exists", after the analysis and the drawings."""
    link = tmp_path / "results"
    link.symlink_to(tmp_path / "moved")
    analysed = []
    monkeypatch.setattr("graphplan.analysis.analyse", lambda *args, **kwargs: analysed.append(args))
    err = refused(capsys, [word.format(link=link) for word in argv])
    assert err == f"{told.format(link=link)}: {link} is a link to {tmp_path / 'moved'}, which is not there; make " \
                  "that folder, or give --out another"
    assert analysed == [] and sorted(path.name for path in tmp_path.iterdir()) == ["results"]
