"""A scene from standard input (``-``, as Unix tools take it), a named pipe, and the other files that are no file.

``graphplan run -`` looked for a file named ``-``; a named pipe no program wrote into, and a terminal given as
``/dev/stdin``, waited for ever; a socket was told as "No such device or address" and /dev/null as an empty scene.
Each is now read, or refused in one line naming it, quickly, with no output folder left behind.
"""

from __future__ import annotations

import functools
import os
import pty
import socket
import stat
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from console import without_progress

from graphplan import scene_file as scene_module

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"
PACKAGE_ROOT = FIXTURE.parent.parent

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="pipes, terminals and devices as POSIX has them")


def command(*argv: str, cwd: Path, **options) -> subprocess.CompletedProcess:
    """``python -m graphplan`` as a user runs it, with this checkout's package first on the path; a command that
    waits for ever fails the test instead of hanging it."""
    environment = {**os.environ, "PYTHONPATH": str(PACKAGE_ROOT)}
    options.setdefault("capture_output", True)
    try:
        return subprocess.run([sys.executable, "-m", "graphplan", *argv], cwd=cwd, env=environment, timeout=30,
                              check=False, **options)
    except subprocess.TimeoutExpired:
        pytest.fail(f"graphplan {' '.join(argv)} waited for ever")


def refused(done: subprocess.CompletedProcess, folder: Path) -> str:
    """The one error line of a command that exits 2 with no traceback and writes nothing into ``folder``."""
    err = without_progress(done.stderr.decode() if isinstance(done.stderr, bytes) else done.stderr)
    assert done.returncode == 2, err
    assert "Traceback" not in err and err.count("\n") == 1 and err.startswith("graphplan: error: "), err
    assert [entry.name for entry in folder.iterdir()] == [], "no output folder, nor a half-written one"
    return err.removeprefix("graphplan: error: ").rstrip("\n")


@functools.cache
def structure_of(path: Path) -> str:
    """The structure formula the scene file's own check prints."""
    done = command("check", str(path), cwd=path.parent, text=True)
    assert done.returncode == 0, done.stderr
    return next(line for line in done.stdout.splitlines() if line.startswith("structure: "))


# --- standard input -----------------------------------------------------------------------------------------------


def test_a_scene_piped_in_writes_what_its_file_writes(tmp_path):
    """``cat scene.toml | graphplan run - --out x``: the same folder, byte for byte, as the file itself gives."""
    given = command("run", str(FIXTURE), "--out", "given", "--only", "positions", cwd=tmp_path)
    piped = command("run", "-", "--out", "piped", "--only", "positions", cwd=tmp_path, input=FIXTURE.read_bytes())
    assert (given.returncode, piped.returncode) == (0, 0), piped.stderr
    names = sorted(path.name for path in (tmp_path / "given").iterdir())
    assert names == sorted(path.name for path in (tmp_path / "piped").iterdir()) and "results.json" in names
    for name in names:
        assert (tmp_path / "piped" / name).read_bytes() == (tmp_path / "given" / name).read_bytes(), name


def test_a_scene_piped_in_without_out_goes_to_the_folder_the_help_names(tmp_path):
    """Without --out the folder is named after the scene file, which a piped scene has none of."""
    shown = command("run", "--help", cwd=tmp_path, text=True).stdout
    assert "output/stdin for -" in " ".join(shown.split())
    done = command("run", "-", "--only", "positions", cwd=tmp_path, input=FIXTURE.read_bytes())
    assert done.returncode == 0, done.stderr
    assert [path.name for path in tmp_path.iterdir()] == ["output"]
    assert (tmp_path / "output" / "stdin" / "results.json").is_file()
    assert f"wrote {Path('output', 'stdin', 'results.json')}" in done.stdout.decode()


def test_a_scene_piped_into_check_is_named_as_standard_input(tmp_path):
    done = command("check", "-", cwd=tmp_path, input=FIXTURE.read_bytes())
    out = done.stdout.decode()
    assert done.returncode == 0, done.stderr
    assert out.startswith("<stdin>: ok\n") and structure_of(FIXTURE) in out.splitlines()


def test_a_scene_piped_in_without_a_title_is_titled_as_its_folder_is_named(tmp_path):
    """A scene takes its file's name for a title; ``<stdin>`` headed the note and the sheets' title block."""
    text = "".join(line for line in FIXTURE.read_text(encoding="utf-8").splitlines(keepends=True)
                   if not line.startswith("title"))
    done = command("run", "-", "--out", "x", "--only", "positions", cwd=tmp_path, input=text.encode())
    assert done.returncode == 0, done.stderr
    assert done.stdout.decode().splitlines()[0] == "stdin"


@pytest.mark.parametrize("verb", ["run", "check"])
@pytest.mark.parametrize(("given", "told"), [
    # The advice names the command typed: `check -` was told to pipe the scene into `run -`.
    (b"", ("<stdin>: is empty: no scene was piped in; pipe one in: graphplan {verb} - < scene.toml, or cat scene.toml "
           "| graphplan {verb} -")),
    (bytes((7 * index * index + 3) % 256 for index in range(3000)), "<stdin>: is not a text file but binary data"),
    (b"#" * (scene_module.MAX_SCENE_BYTES + 10),
     f"<stdin>: goes on past {scene_module.MAX_SCENE_BYTES} bytes, the most a scene may have"),
    (b"[frame\n", "<stdin>: is not valid TOML"),
], ids=["empty", "binary", "too-large", "not-toml"])  # a megabyte's id went into the command's environment: E2BIG
def test_what_is_no_scene_piped_in_is_refused_naming_standard_input(tmp_path, verb, given, told):
    out = ["--out", "out"] if verb == "run" else []
    assert refused(command(verb, "-", *out, cwd=tmp_path, input=given), tmp_path).startswith(told.format(verb=verb))


def test_standard_input_from_dev_null_is_told_empty(tmp_path):
    """Nothing piped in where the command runs without a terminal (cron, a CI job): stdin is /dev/null."""
    told = refused(command("run", "-", "--out", "out", cwd=tmp_path, stdin=subprocess.DEVNULL), tmp_path)
    assert told.startswith("<stdin>: is empty: no scene was piped in")


def test_standard_input_closed_is_told_so(tmp_path):
    told = refused(command("run", "-", cwd=tmp_path, preexec_fn=lambda: os.close(0)), tmp_path)
    assert told.startswith("<stdin>: is closed: no scene was piped in; pipe one in")


def on_a_terminal(*argv: str, cwd: Path) -> subprocess.CompletedProcess:
    """The command run with a terminal for standard input, nothing piped in: it waited for a scene to be typed."""
    typing, terminal = pty.openpty()
    try:
        started = time.monotonic()
        done = command(*argv, cwd=cwd, stdin=terminal)
        assert time.monotonic() - started < 15
        return done
    finally:
        os.close(typing)
        os.close(terminal)


def test_a_terminal_for_standard_input_is_refused_at_once_with_how_to_pipe_a_scene(tmp_path):
    told = refused(on_a_terminal("run", "-", cwd=tmp_path), tmp_path)
    assert told.startswith("<stdin>: is the terminal: no scene was piped in; pipe one in: graphplan run - < "
                           "scene.toml, or cat scene.toml | graphplan run -")


def test_a_device_given_to_check_is_told_to_pipe_the_scene_into_check(tmp_path):
    told = refused(command("check", os.devnull, cwd=tmp_path), tmp_path)
    assert told.endswith("pipe one in: graphplan check - < scene.toml, or cat scene.toml | graphplan check -")


def test_dev_stdin_on_a_terminal_is_refused_at_once(tmp_path):
    """/dev/stdin was read as a file: from a terminal, the command waited for the scene to be typed."""
    told = refused(on_a_terminal("run", "/dev/stdin", "--out", "out", cwd=tmp_path), tmp_path)
    assert told.startswith("/dev/stdin: is a terminal, not a scene file")


def test_dev_stdin_piped_reads_the_scene(tmp_path):
    done = command("check", "/dev/stdin", cwd=tmp_path, input=FIXTURE.read_bytes(), text=False)
    assert done.returncode == 0, done.stderr
    assert structure_of(FIXTURE) in done.stdout.decode().splitlines()


# --- a named pipe -------------------------------------------------------------------------------------------------


def test_a_named_pipe_with_a_program_writing_into_it_is_read(tmp_path):
    """A writer that opens the pipe only once graphplan has (it blocks until then), and writes slowly."""
    fifo = tmp_path / "scene.fifo"
    os.mkfifo(fifo)
    text = FIXTURE.read_bytes()

    def write() -> None:
        with fifo.open("wb") as pipe:
            pipe.write(text[:100])
            pipe.flush()
            time.sleep(0.3)
            pipe.write(text[100:])

    writer = threading.Thread(target=write, daemon=True)
    writer.start()
    done = command("check", str(fifo), cwd=tmp_path, text=True)
    writer.join(timeout=5)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith(f"{fifo}: ok\n") and structure_of(FIXTURE) in done.stdout.splitlines()


@pytest.mark.parametrize("verb", ["run", "check"])
def test_a_named_pipe_that_no_program_writes_into_is_refused_within_seconds(tmp_path, verb):
    fifo = tmp_path / "scene.fifo"
    os.mkfifo(fifo)
    started = time.monotonic()
    done = command(verb, str(fifo), *(["--out", "out"] if verb == "run" else []), cwd=tmp_path)
    assert time.monotonic() - started < scene_module.FIFO_WAIT_SECONDS + 10
    fifo.unlink()
    told = refused(done, tmp_path)
    assert told.startswith(f"{fifo}: is a named pipe that no program opened to write the scene into within "
                           f"{scene_module.FIFO_WAIT_SECONDS:g} s: start the program that writes it first")


# --- other files that are no file ----------------------------------------------------------------------------------


def test_a_socket_given_as_the_scene_is_told_for_what_it_is(tmp_path):
    """It was told as "cannot be read: No such device or address", which names nothing the user gave."""
    path = tmp_path / "scene.sock"
    listening = socket.socket(socket.AF_UNIX)
    try:
        listening.bind(str(path))
        done = command("run", str(path), "--out", "out", cwd=tmp_path)
    finally:
        listening.close()
    path.unlink()
    assert refused(done, tmp_path).startswith(f"{path}: is a socket, through which programs talk, not a scene file")


def test_dev_null_given_as_the_scene_is_told_a_device(tmp_path):
    """It was told "is empty", which sends the user to look into a file that is none."""
    if not Path("/dev/null").exists():
        pytest.skip("no /dev/null here")
    told = refused(command("run", "/dev/null", "--out", "out", cwd=tmp_path), tmp_path)
    assert told.startswith("/dev/null: is a device that holds nothing, not a scene file")


def test_a_disk_given_as_the_scene_is_refused_unread(tmp_path):
    """Read as a file (by root), a disk gave a megabyte of its sectors, told as binary data."""
    disks = [path for path in sorted(Path("/dev").glob("loop*")) + sorted(Path("/dev").glob("sd?"))
             if stat.S_ISBLK(path.stat().st_mode)]
    if not disks:
        pytest.skip("no block device here")
    told = refused(command("run", str(disks[0]), "--out", "out", cwd=tmp_path), tmp_path)
    assert told.startswith(f"{disks[0]}: is a disk (a block device), not a scene file")


def test_a_file_named_dash_is_given_as_its_path(tmp_path):
    """``-`` is standard input; a scene file of that name is ``./-``, as Unix tools take it."""
    (tmp_path / "-").write_bytes(FIXTURE.read_bytes())
    done = command("check", "./-", cwd=tmp_path, text=True)
    assert done.returncode == 0 and done.stdout.startswith("-: ok\n"), done.stderr
