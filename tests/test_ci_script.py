"""CI's script (.ci/run): the README's test command as printed, in an environment of the interpreter it chooses."""
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCRIPT = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _venv_block() -> str:
    """The lines of .ci/run that choose the interpreter and make the environment with it."""
    found = re.search(r"^system_python=.*?^fi$", SCRIPT, flags=re.DOTALL | re.MULTILINE)
    assert found, "the interpreter's choice is not in .ci/run"
    return found.group(0)


def test_ci_runs_the_readme_s_test_command_with_only_the_wait_for_the_system_s_packages_between_its_halves():
    command = re.search(r"^(python3 -m pip install \"\.\[test\]\") && (python3 -m pytest)\s+# the test suite$",
                        README, flags=re.MULTILINE)
    assert command, "the README's second command is not where it was"
    install, test = command.groups()
    assert SCRIPT.rstrip().splitlines()[-1] == f'{install} && wait "$system" && {test}'


def _interpreter(path: Path, log: Path, makes: bool, version_check: str) -> Path:
    """A stand-in for an interpreter that notes each command it is given in ``log``: it answers the version check
    with ``version_check`` (this Python's own answer, or exit 1 for one too old), and for ``-m venv DIR`` makes the
    environment's files where ``makes``, else leaves it half-made and fails, as Debian's Python without python3-venv
    does."""
    path.parent.mkdir(parents=True)
    made = 'touch "$3/pyvenv.cfg" "$3/bin/python3"' if makes else "exit 1"
    path.write_text(f'#!/bin/sh\necho "$@" >> "{log}"\nif [ "$1" = -m ]; then mkdir -p "$3/bin"; {made}; exit 0; fi\n'
                    f"{version_check}\n", encoding="utf-8")
    path.chmod(0o755)
    return path


@pytest.mark.skipif(sys.platform == "win32", reason="CI's script is a bash script")
@pytest.mark.parametrize("system, asked", [
    # A system Python that makes environments makes CI's.
    ("works", ["system"]),
    # One without python3-venv (Debian's bare python3) fails half-way: the first python3 on the PATH makes it anew.
    ("no-venv", ["system", "path"]),
    # One older than the project runs on, or none at all: the first python3 on the PATH.
    ("old", ["path"]),
    ("missing", ["path"]),
])
def test_ci_makes_its_environment_with_the_system_s_python_only_where_that_can(tmp_path, system, asked):
    this = f'exec "{sys.executable}" "$@"'
    logs = {"system": tmp_path / "system.log", "path": tmp_path / "path.log"}
    chosen = {"works": _interpreter(tmp_path / "works" / "python3", logs["system"], True, this),
              "no-venv": _interpreter(tmp_path / "no-venv" / "python3", logs["system"], False, this),
              "old": _interpreter(tmp_path / "old" / "python3", logs["system"], True, "exit 1"),
              "missing": tmp_path / "missing" / "python3"}[system]
    on_path = _interpreter(tmp_path / "bin" / "python3", logs["path"], True, this)
    block = _venv_block().replace("system_python=/usr/bin/python3", f"system_python={chosen}", 1)
    assert block != _venv_block()
    venv = tmp_path / "venv"
    subprocess.run(["bash", "-c", f'set -euo pipefail\nvenv="{venv}"\n{block}\n'], check=True,
                   env={"PATH": f"{on_path.parent}:/usr/bin:/bin"}, capture_output=True)
    assert (venv / "pyvenv.cfg").exists() and (venv / "bin" / "python3").exists()
    told = {name: log.read_text(encoding="utf-8") if log.exists() else "" for name, log in logs.items()}
    assert [name for name in logs if f"-m venv {venv}" in told[name]] == asked
