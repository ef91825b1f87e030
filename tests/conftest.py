"""Session set-up shared by every test module."""
import compileall
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "graphplan"


def pytest_configure(config):
    # Many tests start `python -m graphplan` in a child process. Where the shell sets PYTHONDONTWRITEBYTECODE (CI's
    # machine does), each child would compile the whole package again, about half a second each. Python still reads
    # bytecode it did not write, so compiling once here, before the workers start, spares every child that work.
    if not hasattr(config, "workerinput"):
        compileall.compile_dir(PACKAGE, quiet=2)
