"""The command line's own process skips the collector's passes as it ends (cli._nothing_collected_at_exit): they
walked every object a run made, a seventh of a cold run, to free memory the process was giving back whole.  A
caller of main() with its own arguments (a test, a script) keeps its collector as it was."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# A checker registered before main() runs after main's own exit handler (atexit runs them last in, first out): it
# prints how many objects the collector was left to pass over, and the file the command wrote, as the disk has it.
# The count is taken from the one the interpreter starts with: Python 3.12 starts with 375 objects frozen.
_PROBE = """
import atexit, gc, sys
from pathlib import Path

at_start = gc.get_freeze_count()
from graphplan.cli import main

out = Path(sys.argv[1])
atexit.register(lambda: print(gc.get_freeze_count() - at_start,
                              len(out.read_text(encoding="utf-8")) if out.exists() else -1))
if sys.argv[2] == "command line":
    sys.argv = ["graphplan", "new", "crank-rocker", "--out", str(out)]
    code = main()
else:
    code = main(["new", "crank-rocker", "--out", str(out)])
assert code == 0, code
"""


def _at_exit(tmp_path: Path, how: str) -> tuple[int, int]:
    out = tmp_path / f"{how.replace(' ', '_')}.toml"
    done = subprocess.run([sys.executable, "-c", _PROBE, str(out), how], capture_output=True, text=True, check=True,
                          cwd=ROOT)
    frozen, written = done.stdout.split()[-2:]
    return int(frozen), int(written)


def test_the_command_lines_process_ends_without_a_collection(tmp_path):
    from graphplan.starters import starter

    frozen, written = _at_exit(tmp_path, "command line")
    # Every object of the process (thousands: the modules alone) is left out of the passes at exit.
    assert frozen > 1000
    # The file is written whole before: the starter's text as the command writes it.
    assert written == len(starter("crank-rocker", "en"))


def test_a_caller_with_its_own_arguments_keeps_its_collector(tmp_path):
    frozen, written = _at_exit(tmp_path, "called")
    assert frozen == 0
    assert written > 0
