"""Writing an output folder all at once: a complete new folder, or the old one untouched."""

from __future__ import annotations

import contextlib
import errno
import hashlib
import os
import shutil
import stat
from collections.abc import Mapping
from pathlib import Path

from .errors import OutputError

# The names a run wrote in its folder, each with the digest of what it wrote, kept there (hidden) so that the next run
# replaces those alone, and of those only the ones nobody has changed since.
WRITTEN = ".graphplan-written"


def write_folder(target: Path, files: Mapping[str, str | bytes], option: str = "--out") -> list[Path]:
    """Write ``files`` (relative name → content) as the folder ``target``; ``option`` is what the refusals tell
    the user to give another folder (the command line's ``--out``, the notebook's ``scene.write()``).

    Everything is written into a temporary sibling first, which then takes
    ``target``'s place; an existing ``target`` is replaced only once the new
    folder is complete, and a failure leaves no half-written folder behind.
    What the folder holds that no run wrote there (the scene itself, a draft,
    LaTeX's own output) is carried into the new folder: a run replaces its
    own files alone, as listed in :data:`WRITTEN`, and refuses a folder
    where a file no run wrote has the name of one of the run's. A ``target``
    that is a link to a folder is written as that folder, the link left as it is.
    """
    target = Path(target)
    folder = check_folder(target, option)
    staging = _staging(folder)
    retired = folder.parent / f".{folder.name}.old-{os.getpid()}"
    written = sorted({name.split("/")[0] for name in files})
    users, changed = _not_written_by_a_run(folder, option) if folder.is_dir() else ([], [])
    # A file of the user's named as the run names one (their own note.md) would be replaced without a word; so would
    # their Note.md on a disk that does not tell capitals apart (Windows', macOS's), where it is the run's note.md.
    ours = {name.casefold(): name for name in written}
    theirs = [name for name in users if name.casefold() in ours]
    if theirs:
        them = "it" if len(theirs) == 1 else "them"
        shown = [name if name in written else f"{name} (the run's {ours[name.casefold()]} on a disk that does "
                 f"not tell capitals apart)" for name in theirs]
        edited = [name for name in theirs if name in changed]
        if not edited:
            whose = "which no graphplan run wrote there and this run would replace"
        elif len(edited) == len(theirs):
            whose = f"changed since a graphplan run wrote {them}: this run would replace {them}"
        else:
            whose = (f"which no graphplan run wrote there or which changed since one did ({', '.join(edited)}): this "
                     f"run would replace {them}")
        raise OutputError(f"{target}: holds {', '.join(shown)}, {whose}; move {them} away, or give {option} another "
                          "folder")
    carried: list[str] = []
    made = _to_make(folder)
    try:
        folder.parent.mkdir(parents=True, exist_ok=True)
        shutil.rmtree(staging, ignore_errors=True)
        staging.mkdir()
        for name, content in sorted(files.items()):
            path = staging / name
            path.parent.mkdir(parents=True, exist_ok=True)
            if isinstance(content, str):
                path.write_text(content, encoding="utf-8", newline="\n")
            else:
                path.write_bytes(content)
        (staging / WRITTEN).write_text("".join(f"{name}\t{_digest(staging / name)}\n" for name in written),
                                       encoding="utf-8")
        if folder.exists():
            for name in users:  # none the run writes: those were refused above
                (folder / name).rename(staging / name)
                carried.append(name)
            # The folder is replaced, not written into: it keeps its permissions (a project folder shared with the
            # group) only if the new one is given them.
            staging.chmod(stat.S_IMODE(folder.stat().st_mode))
            folder.rename(retired)
        staging.rename(folder)
    except BaseException as error:
        # Ctrl-C too: the user's own files carried into the staging folder must go back before it is removed.
        if _there(retired) and not _there(folder):
            retired.rename(folder)
        for name in carried:
            (staging / name).rename(folder / name)
        shutil.rmtree(staging, ignore_errors=True)
        _take_away(made)
        if isinstance(error, OutputError) or not isinstance(error, OSError):
            raise
        raise OutputError(f"{target}: cannot write the output ({error.strerror or error})") from None
    shutil.rmtree(retired, ignore_errors=True)
    return [target / name for name in sorted(files)]


def check_folder(target: Path, option: str = "--out") -> Path:
    """The folder a run writes as ``target`` (the folder a link names), refused as :func:`write_folder` refuses it
    where the path alone says so: a run asks before it analyses, not after a minute of it.

    Raises
    ------
    OutputError
        for the folder the command runs in or one holding it, a file (or a path through one).
    """
    target = Path(target)
    try:
        here = Path.cwd().resolve()
    except OSError:  # the folder the command runs in deleted under it (a terminal left in a folder removed)
        if not target.is_absolute():
            raise OutputError(f"{target}: is a path from the folder the command runs in, which is gone (deleted or "
                              f"moved); give {option} a full path, or run the command in another folder") from None
        here = None
    # Asked of the system, not of Path.resolve: Python 3.11 tells a loop as a RuntimeError, 3.13 resolves a path
    # through one without a word, as far as the loop.
    if _through_a_loop(target):
        raise OutputError(f"{target}: leads through a link that leads round to itself (a loop of links); give "
                          f"{option} another folder")
    try:
        resolved = target.resolve()
    except OSError as error:
        raise OutputError(f"{target}: cannot be written ({error.strerror or error})") from None
    try:
        home = Path.home().resolve()
    except (RuntimeError, OSError):  # no home to be told of
        home = None
    if resolved == home:  # --out ~ meant "put it in my home folder": the run would swap it for a new one
        raise OutputError(f"{target}: is your home folder, which a run cannot replace; give {option} a folder of its "
                          "own")
    if here is not None and (resolved == here or resolved in here.parents):
        raise OutputError(f"{target}: is the folder the command runs in (or holds it), which a run cannot replace; "
                          f"give {option} a folder of its own")
    try:
        folder = _folder_to_replace(target, resolved, option)
        _refuse_a_name_too_long_to_stage(target, folder, option)
        return folder
    except OutputError:
        raise
    except OSError as error:  # a name too long for the disk, a folder that may not be looked into
        raise OutputError(f"{target}: cannot be written ({error.strerror or error})") from None


def _staging(path: Path) -> Path:
    """The hidden sibling a folder or file is written as first, which then takes its name."""
    return path.parent / f".{path.name}.partial-{os.getpid()}"


def _to_make(path: Path) -> list[Path]:
    """The folders on the way to ``path`` that are not there, nearest first: those a write makes, and takes away
    again where it fails (:func:`_take_away`)."""
    return [above for above in path.parents if not _there(above)]


def _take_away(made: list[Path]) -> None:
    """Remove the folders a failed write ``made``, nearest first, each only where it is empty."""
    for above in made:
        with contextlib.suppress(OSError):  # one that holds something now is not the write's alone
            above.rmdir()


def _there(path: Path) -> bool:
    """Whether ``path`` is there; False for a name the disk could not hold (Path.exists raises for it)."""
    try:
        return path.exists()
    except OSError:
        return False


def _refuse_a_name_too_long_to_stage(target: Path, path: Path, option: str, what: str = "folder") -> None:
    """A folder (or file) whose name the disk holds, but not the hidden sibling a run writes it as first
    (``.NAME.partial-PID``): the run failed on it once everything was drawn, with a traceback."""
    above = _nearest_there(path)
    try:
        most = os.pathconf(above if above is not None else Path.cwd(), "PC_NAME_MAX")
    except (OSError, ValueError, AttributeError):  # not asked on Windows, nor of a disk that will not say
        return
    staged = _staging(path).name
    length = len(os.fsencode(staged))
    if length > most:
        room = most - (length - len(os.fsencode(path.name)))
        raise OutputError(f"{target}: its name is too long for the run to write the {what} by: the run writes it "
                          f"first as {staged[:12]}….partial-{os.getpid()} beside it, {length} bytes where the disk "
                          f"holds names of up to {most}; give {option} a {what} whose name is at most {room} bytes")


def _through_a_loop(path: Path) -> bool:
    try:
        path.stat()
    except OSError as error:
        return error.errno == errno.ELOOP
    return False


def _folder_to_replace(target: Path, resolved: Path, option: str) -> Path:
    # Replacing the link itself would put a folder in its place and take the user's files out of the one it names.
    folder = resolved if target.is_symlink() else target
    _refuse_a_link_to_nothing_on_the_way(target, folder, option)
    above = _nearest_there(folder)
    if above is not None:
        if not above.is_dir():
            raise OutputError(f"{target}: {above} is not a folder, so the output cannot go in it; give {option} a "
                              "folder elsewhere")
        # The new folder is made, and renamed into place, in the folder above it: one that may not be written in
        # (a read-only disk, another user's folder) refused the rename only once everything was drawn. Windows
        # is not asked: its read-only mark on a folder does not stop writing in it.
        if os.name == "posix" and not os.access(above, os.W_OK | os.X_OK):
            raise OutputError(f"{target}: {above} may not be written in (a read-only disk, or another user's "
                              f"folder); give {option} another folder")
    if folder.exists() and not folder.is_dir():
        raise OutputError(f"{target}: exists and is not a folder; give {option} a folder")
    # A folder made read-only, to keep it as it is, was swapped for a new one all the same (its parent may be written
    # in), and another user than root, who may not delete its files, found them left in a hidden .NAME.old-PID.
    if os.name == "posix" and folder.is_dir() and not os.access(folder, os.W_OK | os.X_OK):
        raise OutputError(f"{target}: may not be written in (read-only, or another user's folder); give {option} "
                          "another folder")
    if folder.is_dir() and os.path.ismount(folder):
        # The folder is replaced by renaming a new one into its place, which a disk's mount point refuses ("Device or
        # resource busy") once the run has analysed and drawn everything.
        raise OutputError(f"{target}: is where a disk is mounted, which a run cannot replace; give {option} a folder "
                          "in it")
    return folder


def _nearest_there(path: Path) -> Path | None:
    """The nearest of the folders ``path`` goes in that is there (or the file that stands in its place)."""
    return next((above for above in path.parents if above.exists()), None)


def _refuse_a_link_to_nothing_on_the_way(target: Path, path: Path, option: str) -> None:
    """A folder on the way to ``path`` that is a link to nothing (its folder moved or not made yet): mkdir takes it
    for a file in the way, "File exists", once everything is drawn."""
    for above in path.parents:
        if above.is_symlink() and not above.exists():
            raise OutputError(f"{target}: {above} is a link to {os.readlink(above)}, which is not there; make that "
                              f"folder, or give {option} another")


def _not_written_by_a_run(folder: Path, option: str = "--out") -> tuple[list[str], list[str]]:
    """The entries of ``folder`` that are the user's own, by its :data:`WRITTEN` list: those no run wrote, and
    those changed since a run wrote them (a sheet lettered by hand, a note finished in an editor); and the latter
    apart.

    Only a name of an entry of ``folder`` counts: a list edited to name ``../thesis.docx`` or an absolute path
    takes nothing outside it, nor does one edited to name a file of the folder that no run wrote, whose digest it
    cannot give. A list that is not a run's text is refused, not guessed at.
    """
    record = folder / WRITTEN
    listed: dict[str, str | None] = {}
    if record.is_file():
        try:
            lines = record.read_text(encoding="utf-8").splitlines()
        except (UnicodeDecodeError, OSError) as error:
            why = "not text" if isinstance(error, UnicodeDecodeError) else error.strerror or str(error)
            raise OutputError(f"{record}: the list of the files runs wrote there cannot be read ({why}); give "
                              f"{option} another folder, or delete the list and the runs' files in {folder}") from None
        # A list of names alone is an older run's, written before the digests: its names are taken at their word. In
        # a list with digests a name without one was added by hand, and is no run's.
        rows = [line.partition("\t") for line in lines]
        dated = any(digest for _, _, digest in rows)
        listed = {name: digest or None for name, _, digest in rows if digest or not dated}
    entries = [entry for entry in folder.iterdir() if entry.name != WRITTEN]
    unlisted = [entry.name for entry in entries if entry.name not in listed]
    changed = [entry.name for entry in entries
               if listed.get(entry.name) is not None and listed[entry.name] != _digest(entry)]
    return sorted(unlisted + changed), sorted(changed)


def _digest(entry: Path) -> str:
    """The SHA-256 of what ``entry`` holds: a file's bytes, or a folder's files' names and bytes, in order."""
    digest = hashlib.sha256()
    files = sorted(path for path in entry.rglob("*") if path.is_file()) if entry.is_dir() else [entry]
    for path in files:
        if entry.is_dir():
            digest.update(path.relative_to(entry).as_posix().encode("utf-8") + b"\0")
        digest.update(path.read_bytes())
    return digest.hexdigest()


def write_file(target: Path, content: str, replace: bool = True) -> Path:
    """Write one file whole: into a temporary sibling first, which then takes ``target``'s name.

    With ``replace`` False an existing ``target`` is an :class:`OutputError`
    and stays as it was.
    """
    target = Path(target)
    staging = _staging(target)
    made: list[Path] = []
    try:
        # A link counts even where it leads nowhere (to itself, or to a file gone): it would be replaced by the file.
        if not replace and (target.exists() or target.is_symlink()):
            raise OutputError(f"{target}: exists already; give another name with --out")
        # A file where a folder on the way should be was told as mkdir's "File exists", naming neither.
        _refuse_a_link_to_nothing_on_the_way(target, target, "--out")
        above = _nearest_there(target)
        if above is not None and not above.is_dir():
            raise OutputError(f"{target}: {above} is not a folder, so the file cannot go in it")
        _refuse_a_name_too_long_to_stage(target, target, "--out", "file")
        made = _to_make(target)
        target.parent.mkdir(parents=True, exist_ok=True)
        staging.write_text(content, encoding="utf-8", newline="\n")
        staging.replace(target)
    except BaseException as error:
        with contextlib.suppress(OSError):  # a name too long for the disk cannot have been written either
            staging.unlink(missing_ok=True)
        _take_away(made)
        if isinstance(error, OutputError) or not isinstance(error, OSError):
            raise
        raise OutputError(f"{target}: cannot be written ({error.strerror or error})") from None
    return target

