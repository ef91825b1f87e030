"""The output folder when a run is stopped or replaces one: a run killed by SIGTERM (``timeout``, a job stopped)
while it writes leaves no half-written staging folder and the previous output as it was, as Ctrl-C does; a folder
the run replaces keeps its permissions (a project folder the group may write to); a starter scene given a folder is written
in it."""

from __future__ import annotations

import os
import pathlib
import signal
import stat
from pathlib import Path

from graphplan.cli import main

FIXTURE = str(Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml")


def test_a_run_terminated_while_it_writes_leaves_no_staging_folder_and_the_old_output(tmp_path, capsys, monkeypatch):
    out = tmp_path / "out"
    assert main(["run", FIXTURE, "--out", str(out), "--only", "positions"]) == 0
    before = {path.name: path.read_bytes() for path in out.iterdir()}
    handler_before = signal.getsignal(signal.SIGTERM)
    write_text = pathlib.Path.write_text

    def terminated_on_the_way(path, *args, **kwargs):
        written = write_text(path, *args, **kwargs)
        if ".partial-" in str(path):
            os.kill(os.getpid(), signal.SIGTERM)
        return written

    monkeypatch.setattr(pathlib.Path, "write_text", terminated_on_the_way)
    assert main(["run", FIXTURE, "--out", str(out), "--only", "positions,velocity"]) == 128 + signal.SIGTERM
    assert "graphplan: terminated" in capsys.readouterr().err
    assert sorted(entry.name for entry in tmp_path.iterdir()) == ["out"]
    assert {path.name: path.read_bytes() for path in out.iterdir()} == before
    assert signal.getsignal(signal.SIGTERM) == handler_before


def test_a_folder_the_run_replaces_keeps_its_permissions(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    out.chmod(0o775)
    assert main(["run", FIXTURE, "--out", str(out), "--only", "positions"]) == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o775
    out.chmod(0o750)
    assert main(["run", FIXTURE, "--out", str(out), "--only", "positions"]) == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o750


def test_a_new_scene_given_a_folder_is_written_in_it_as_cp_would(tmp_path, capsys):
    folder = tmp_path / "project"
    folder.mkdir()
    assert main(["new", "crank-rocker", "--out", str(folder)]) == 0
    written = folder / "crank-rocker.toml"
    assert f"wrote {written}" in capsys.readouterr().out
    assert "[driver]" in written.read_text(encoding="utf-8")
    # Written once; a second time it is not overwritten.
    assert main(["new", "crank-rocker", "--out", str(folder)]) == 2
    assert "exists already" in capsys.readouterr().err


def _longest_name(folder: Path) -> int:
    return os.pathconf(folder, "PC_NAME_MAX")


def test_a_folder_named_too_long_to_write_by_is_refused_before_the_run_naming_the_room(tmp_path, capsys, monkeypatch):
    """A name the disk holds whose hidden sibling ``.NAME.partial-PID`` it does not: the run failed on it with a
    traceback once everything was drawn, and left the folders it had made on the way."""
    name = "L" * (_longest_name(tmp_path) - 5)
    out = tmp_path / "made" / "on-the-way" / name
    analysed = []
    monkeypatch.setattr("graphplan.analysis.analyse", lambda *args, **kwargs: analysed.append(args))
    assert main(["run", FIXTURE, "--out", str(out), "--only", "positions"]) == 2
    error = capsys.readouterr().err
    room = _longest_name(tmp_path) - len(f"..partial-{os.getpid()}")
    assert error.startswith(f"graphplan: error: {out}: its name is too long for the run to write the folder by")
    assert error.rstrip().endswith(f"give --out a folder whose name is at most {room} bytes")
    assert not analysed and list(tmp_path.iterdir()) == []
    # A name of the length it gives runs.
    monkeypatch.undo()
    assert main(["run", FIXTURE, "--out", str(tmp_path / ("L" * room)), "--only", "positions"]) == 0


def test_a_new_scene_named_too_long_to_write_by_is_refused_leaving_no_folder_made(tmp_path, capsys):
    target = tmp_path / "made" / ("L" * (_longest_name(tmp_path) - 10) + ".toml")
    assert main(["new", "crank-rocker", "--out", str(target)]) == 2
    assert "its name is too long for the run to write the file by" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_a_run_that_fails_writing_takes_away_the_folders_it_made_on_the_way(tmp_path, capsys, monkeypatch):
    out = tmp_path / "made" / "on-the-way" / "out"
    write_text = pathlib.Path.write_text

    def disk_full(path, *args, **kwargs):
        if ".partial-" in str(path):
            raise OSError(28, "No space left on device")
        return write_text(path, *args, **kwargs)

    monkeypatch.setattr(pathlib.Path, "write_text", disk_full)
    assert main(["run", FIXTURE, "--out", str(out), "--only", "positions"]) == 2
    assert "cannot write the output (No space left on device)" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []
