"""A scene's bytes, from the path given or from standard input, under a scene's size limit; and what the path
names where it holds no scene file: a folder (with the scene files in it), a missing file (with the names near
it), a link loop, a socket, a disk, a terminal, a device, a named pipe no program writes into.

Reading them is :mod:`graphplan.scene`'s; each problem here is told as a :class:`SceneError` naming the path.
"""

from __future__ import annotations

import contextlib
import difflib
import errno
import io
import os
import stat
import sys
import time
from pathlib import Path
from typing import BinaryIO

from .errors import SceneError

MAX_SCENE_BYTES = 1_000_000


def bytes_at(path: Path) -> bytes:
    """The bytes of the scene file at ``path``: at most one more than a scene may have."""
    try:
        if path.is_dir():  # Windows reads a folder as "Permission denied", which sends the user to their rights
            raise SceneError(str(path), f"is a folder, not a scene file{_scenes_in(path)}")
        status = path.stat()
        _refuse_what_holds_no_file(str(path), status.st_mode)
        if stat.S_ISFIFO(status.st_mode) or stat.S_ISCHR(status.st_mode):
            data = _read_without_waiting_for_ever(path, stat.S_ISFIFO(status.st_mode))
        else:
            if status.st_size > MAX_SCENE_BYTES:
                raise SceneError(str(path), f"is {status.st_size} bytes; a scene may have at most {MAX_SCENE_BYTES}")
            with path.open("rb") as file:
                data = file.read(MAX_SCENE_BYTES + 1)  # a file that grows as it is read
    except FileNotFoundError as error:
        raise SceneError(str(path), f"cannot be read: {error.strerror or error}{_near_names(path)}") from None
    except OSError as error:
        if error.errno == errno.ELOOP:
            raise SceneError(str(path), "cannot be read: it is a link that leads round to itself (a loop of "
                                        "links)") from None
        raise SceneError(str(path), f"cannot be read: {error.strerror or error}") from None
    if len(data) > MAX_SCENE_BYTES:
        raise SceneError(str(path), f"goes on past {MAX_SCENE_BYTES} bytes, the most a scene may have (a device or a "
                                    "stream, not a scene file?)")
    if not data and stat.S_ISCHR(status.st_mode):  # /dev/null: "is empty" sent the user to look into a file
        raise SceneError(str(path), "is a device that holds nothing, not a scene file: give the path of a .toml "
                                    f"scene file, or {_PIPE_IN}")
    return data


# How long a named pipe (mkfifo) given as the scene waits for a program to open it for writing: opened without
# one, it waited for ever, silent. A writer started first is there at once, as a shell's <(…) is.
FIFO_WAIT_SECONDS = 2.0
STDIN = "<stdin>"


def pipe_in(command: str = "run") -> str:
    """How to pipe a scene into ``command``: the advice every "no scene here" error ends with."""
    return f"pipe one in: graphplan {command} - < scene.toml, or cat scene.toml | graphplan {command} -"


_PIPE_IN = pipe_in()


def _refuse_what_holds_no_file(source: str, mode: int) -> None:
    """A socket or a disk given as the scene: a socket cannot be opened as a file ("No such device or address"),
    and a disk read as one is a megabyte of its sectors, told as binary data."""
    if stat.S_ISSOCK(mode):
        raise SceneError(source, "is a socket, through which programs talk, not a scene file: give the path of a "
                                 ".toml scene file")
    if stat.S_ISBLK(mode):
        raise SceneError(source, "is a disk (a block device), not a scene file: give the path of a .toml scene file")


def _read_without_waiting_for_ever(path: Path, fifo: bool) -> bytes:
    """A named pipe's or a character device's bytes, up to one more than a scene may have (/dev/zero is endless).

    Opened as a file, a pipe no program writes into waited for ever, and so did a terminal (for typing) or a
    device with nothing to read; opened without blocking, each is told within :data:`FIFO_WAIT_SECONDS`. A pipe
    that a program holds open is then read as slowly as it writes, as a pipe into standard input is.
    """
    source = str(path)
    handle = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
    try:
        if os.isatty(handle):
            raise SceneError(source, f"is a terminal, not a scene file: give the path of a .toml scene file, or "
                                     f"{_PIPE_IN}")
        chunks: list[bytes] = []
        size = 0
        writer = False
        deadline = time.monotonic() + FIFO_WAIT_SECONDS
        while size <= MAX_SCENE_BYTES:
            try:
                chunk = os.read(handle, min(1 << 16, MAX_SCENE_BYTES + 1 - size))
            except BlockingIOError:
                if fifo:  # nothing yet, but a program holds the pipe open to write
                    writer = True
                    os.set_blocking(handle, True)
                    continue
                if chunks:  # a device that gave what it had
                    break
                if time.monotonic() > deadline:
                    raise SceneError(source, "is a device that gives nothing to read, not a scene file: give the path "
                                             "of a .toml scene file") from None
                time.sleep(0.05)
                continue
            if chunk:
                chunks.append(chunk)
                size += len(chunk)
                writer = True
            elif fifo and not writer:  # a pipe that no program has opened to write reads as ended
                if time.monotonic() > deadline:
                    raise SceneError(source, f"is a named pipe that no program opened to write the scene into within "
                                             f"{FIFO_WAIT_SECONDS:g} s: start the program that writes it first (cat "
                                             f"scene.toml > {source} &), or give the path of a .toml scene file")
                time.sleep(0.05)
            else:
                break
        return b"".join(chunks)
    finally:
        os.close(handle)


def stdin_bytes(stream: BinaryIO | None = None) -> bytes:
    """The bytes of a scene piped into standard input (the command line's ``-``); ``stream`` stands in for
    ``sys.stdin``'s bytes.

    A terminal is refused rather than read: nothing was piped in, and the command would wait, silent, for a
    scene to be typed.
    """
    if stream is None:
        stream = getattr(sys.stdin, "buffer", None)  # sys.stdin is None where the command was started with it closed
        if stream is None:
            raise SceneError(STDIN, f"is closed: no scene was piped in; {_PIPE_IN}")
    handle = None
    with contextlib.suppress(OSError, ValueError, AttributeError, io.UnsupportedOperation):
        handle = stream.fileno()
    try:
        if handle is not None:
            if os.isatty(handle):
                raise SceneError(STDIN, f"is the terminal: no scene was piped in; {_PIPE_IN}; or give the scene "
                                        "file's path instead of -")
            _refuse_what_holds_no_file(STDIN, os.fstat(handle).st_mode)
        data = stream.read(MAX_SCENE_BYTES + 1)
    except OSError as error:
        raise SceneError(STDIN, f"cannot be read: {error.strerror or error}") from None
    if len(data) > MAX_SCENE_BYTES:
        raise SceneError(STDIN, f"goes on past {MAX_SCENE_BYTES} bytes, the most a scene may have")
    if not data:
        raise SceneError(STDIN, f"is empty: no scene was piped in; {_PIPE_IN}")
    return data


def _near_names(path: Path) -> str:
    """The files beside a missing ``path`` that are it but for capitals or a suffix: Notepad's ``scene.toml.txt``,
    a ``Scene.TOML`` from Windows, the ``.toml`` left off; or but for the quotes Windows' cmd passes on as typed
    (``'scene.toml'``) and a space copied with the name."""
    wanted = path.name.casefold().strip().strip("'\"").strip()
    try:
        entries = [entry.name for entry in path.parent.iterdir() if entry.is_file()]
    except OSError:
        return ""
    near = sorted(name for name in entries
                  if name.casefold() == wanted or name.casefold().startswith(wanted + ".")
                  or Path(name.casefold()).stem == wanted or name.casefold().removesuffix(".txt") == wanted)
    if not near:  # a slip of a letter (rachet.toml), or the name's beginning alone (scotch for scotch_yoke.toml)
        scenes = {name.casefold(): name for name in entries if name.casefold().endswith(".toml")}
        near = [scenes[name] for name in difflib.get_close_matches(wanted, scenes, n=3, cutoff=0.85)]
        stem = wanted.removesuffix(".toml")
        near = near or sorted(name for key, name in scenes.items() if len(stem) >= 3 and key.startswith(stem))
    if not near:
        return ""
    shown = " or ".join(repr(str(path.parent / name)) for name in near[:3])
    return f"; did you mean {shown}?"


def _scenes_in(folder: Path) -> str:
    """The scene files in ``folder``, which the user may have meant to give."""
    try:
        scenes = sorted(entry.name for entry in folder.iterdir()
                        if entry.suffix.casefold() == ".toml" and entry.is_file())
    except OSError:
        return ""
    if not scenes:
        return ": give the path of a .toml scene file"
    if len(scenes) == 1:
        return f": give the scene file in it, {str(folder / scenes[0])!r}"
    return f": give one of the {len(scenes)} scene files in it, such as {str(folder / scenes[0])!r}"
