"""Writing an output folder all at once: a complete new folder, or the old one untouched."""

from __future__ import annotations

import os
import shutil
from collections.abc import Mapping
from pathlib import Path

from .errors import OutputError


def write_folder(target: Path, files: Mapping[str, str | bytes]) -> list[Path]:
    """Write ``files`` (relative name → content) as the folder ``target``.

    Everything is written into a temporary sibling first, which then takes
    ``target``'s place; an existing ``target`` is replaced only once the new
    folder is complete, and a failure leaves no half-written folder behind.
    """
    target = Path(target)
    staging = target.parent / f".{target.name}.partial-{os.getpid()}"
    retired = target.parent / f".{target.name}.old-{os.getpid()}"
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.rmtree(staging, ignore_errors=True)
        staging.mkdir()
        for name, content in sorted(files.items()):
            path = staging / name
            path.parent.mkdir(parents=True, exist_ok=True)
            if isinstance(content, str):
                path.write_text(content, encoding="utf-8", newline="\n")
            else:
                path.write_bytes(content)
        if target.exists():
            if not target.is_dir():
                raise OutputError(f"{target}: exists and is not a folder")
            target.rename(retired)
        staging.rename(target)
    except OSError as error:
        shutil.rmtree(staging, ignore_errors=True)
        if retired.exists() and not target.exists():
            retired.rename(target)
        if isinstance(error, OutputError):
            raise
        raise OutputError(f"{target}: cannot write the output ({error.strerror or error})") from None
    shutil.rmtree(retired, ignore_errors=True)
    return [target / name for name in sorted(files)]


def write_file(target: Path, content: str, replace: bool = True) -> Path:
    """Write one file whole: into a temporary sibling first, which then takes ``target``'s name.

    With ``replace`` False an existing ``target`` is an :class:`OutputError`
    and stays as it was.
    """
    target = Path(target)
    if not replace and target.exists():
        raise OutputError(f"{target}: exists already; give another name with --out")
    staging = target.parent / f".{target.name}.partial-{os.getpid()}"
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        staging.write_text(content, encoding="utf-8", newline="\n")
        staging.replace(target)
    except OSError as error:
        staging.unlink(missing_ok=True)
        raise OutputError(f"{target}: cannot be written ({error.strerror or error})") from None
    return target

