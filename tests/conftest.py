"""Session set-up shared by every test module."""
import compileall
import gc
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "graphplan"


def pytest_configure(config):
    # Many tests start `python -m graphplan` in a child process. Where the shell sets PYTHONDONTWRITEBYTECODE (CI's
    # machine does), each child would compile the whole package again, about half a second each. Python still reads
    # bytecode it did not write, so compiling once here, before the workers start, spares every child that work.
    if not hasattr(config, "workerinput"):
        compileall.compile_dir(PACKAGE, quiet=2)
    # A worker keeps what its tests made in the package's memos (analyses, drawings, placements) and hypothesis's
    # and pytest's own records: the collector's full passes at the default thresholds walked all of it some thousand
    # times, a tenth of the drawing tests' time, to free next to nothing. The thresholds a command runs under
    # (cli._few_full_collections) serve a worker too; a test that counts what is freed collects for itself.
    from graphplan import cli

    gc.set_threshold(cli.YOUNG_COLLECTION_AT, cli.MIDDLE_COLLECTION_EVERY, cli.FULL_COLLECTION_EVERY)


@pytest.fixture(scope="module")
def no_rows_apart():
    """The force sheets as they stand where setting a sheet's rows apart saves no sheet (saving a sheet comes first,
    tests/test_force_rows_apart_save_a_sheet.py, and the course sheet then draws its force sheets at the record's
    scales): for a module that checks a force sheet the course sheet draws larger where it has room."""
    from graphplan.render import force_rows

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(force_rows.Rows, "rows_apart", lambda self, fits: [])
        yield
