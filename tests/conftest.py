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
    # and pytest's own records: at the default thresholds the collector's full passes walked all of it some thousand
    # times, a tenth of the drawing tests' time, to free next to nothing. A young pass every 20 000 objects, not
    # 700, makes those passes some fifty times fewer (11 s of the drawing tests' 100 went to 2.6 s), and a worker
    # grows hardly larger (1.20 GB to 1.29 in the plotting tests); the command's own thresholds
    # (cli.YOUNG_COLLECTION_AT), kept over a whole session, let the plotting tests' cycles pile up to 1.50 GB.
    # A test that counts what is freed collects for itself.
    gc.set_threshold(20_000, 10, 10)


@pytest.fixture(scope="module")
def no_rows_apart():
    """The force sheets as they stand where setting a sheet's rows apart saves no sheet (saving a sheet comes first,
    tests/test_force_rows_apart_save_a_sheet.py, and the course sheet then draws its force sheets at the record's
    scales): for a module that checks a force sheet the course sheet draws larger where it has room."""
    from graphplan.render import force_rows

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(force_rows.Rows, "rows_apart", lambda self, fits: [])
        yield
