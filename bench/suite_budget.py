"""Where the test suite's time goes: the README's test command timed, and its time split by what the package does.

    python bench/suite_budget.py [PYTEST ARGUMENTS]

CI has to stay well under 20 minutes, and the suite is a long tail of thousands of tests: no file takes more than
a few per cent of it, so what to make faster is found by what the tests ask the package to do, not by the slowest
tests.  The suite is run as the README runs it (its workers and all), with this file loaded into each worker as a
pytest plugin that times, while the tests run, the package's functions behind most of the time: a whole run, the
choice of μl, the drawings, the tables, the matplotlib plots, the note's PDF and Word files, the exports.  Each
figure is the time inside the function, counted once where it calls itself; one stage holds others (a run holds
its drawings, the drawings the choice of μl), so the shares do not add up.  The collection, the time each worker
takes to import and rewrite the test modules before the first test, is measured beside them.  A run a test makes
in a child process (`python -m graphplan`) is in its test's time alone: the stages are timed in the workers.

Results go to bench/results/suite_budget.json and suite_budget.md.  Any arguments are handed to pytest (a file or
two to try the bench on).
"""

from __future__ import annotations

import collections
import functools
import importlib
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
# Where each worker leaves its figures: set by the bench for the pytest it starts.
OUT_ENV = "GRAPHPLAN_SUITE_BUDGET"
# The package's functions timed, by module and name, with what the results call them.
STAGES = (
    ("graphplan.run", "_run", "a whole run (graphplan run, or run() from Python)"),
    ("graphplan.render.sheet", "fewest_sheets_length_scale", "choosing μl (a scene without drawing.length_scale)"),
    ("graphplan.deliverables", "drawings", "a run's drawings laid out"),
    ("graphplan.render.sheet", "course_panels", "the course sheets' panels laid out (in a run or a test)"),
    ("graphplan.deliverables", "_encodings", "a run's drawings written as SVG and DXF (PNG and PDF rendered after)"),
    ("graphplan.deliverables", "tables", "a run's note and tables"),
    ("graphplan.deliverables", "figures", "a run's matplotlib plots"),
    ("graphplan.deliverables", "vibration_figures", "a run's vibration plots"),
    ("graphplan.report.vibration_plots", "_plot", "the vibration plots (in a run or a test)"),
    ("graphplan.report.motion_plots", "motion_figure", "the plot of the machine's motion"),
    ("graphplan.report.pdf", "note_pdf", "the note's PDF (WeasyPrint)"),
    ("graphplan.report.word", "note_docx", "the note as docx"),
    ("graphplan.render.export", "rendered_all", "a run's PNG and PDF rendered at once (the PNG in threads)"),
    ("graphplan.render.export", "svg_to_png", "a drawing or plot as PNG (cairosvg)"),
    ("graphplan.render.export", "svg_to_pdf", "a drawing or plot as PDF (cairosvg)"),
)

# --- the plugin, in each worker --------------------------------------------------------------------------------

_spent: collections.Counter = collections.Counter()
_calls: collections.Counter = collections.Counter()
_by_file: collections.defaultdict = collections.defaultdict(collections.Counter)
_depth: collections.Counter = collections.Counter()
_now = {"file": "", "collecting": 0.0, "collected": 0.0}


def _timed(key: str, function):
    @functools.wraps(function)
    def timed(*args, **kwargs):
        _depth[key] += 1
        start = time.perf_counter()
        try:
            return function(*args, **kwargs)
        finally:
            _depth[key] -= 1
            if not _depth[key]:  # a call within a call of its own is in the outer one's time
                took = time.perf_counter() - start
                _spent[key] += took
                _calls[key] += 1
                _by_file[_now["file"]][key] += took
    return timed


def pytest_configure(config):
    if not os.environ.get(OUT_ENV):
        return
    # Replaced in their modules before the test modules are imported: the package imports these inside functions
    # or calls them by their module's name, so the timed ones are the ones called.
    for module_name, name, _ in STAGES:
        module = importlib.import_module(module_name)
        setattr(module, name, _timed(f"{module_name}.{name}", getattr(module, name)))


def pytest_collection(session):
    _now["collecting"] = time.perf_counter()


def pytest_collection_finish(session):
    _now["collected"] = time.perf_counter() - _now["collecting"]


def pytest_runtest_protocol(item, nextitem):
    _now["file"] = item.nodeid.split("::")[0]


def pytest_runtest_logreport(report):
    _by_file[report.nodeid.split("::")[0]]["test"] += report.duration


def pytest_unconfigure(config):
    folder = os.environ.get(OUT_ENV)
    if not folder:
        return
    worker = os.environ.get("PYTEST_XDIST_WORKER", "controller")
    figures = {"collection_s": _now["collected"], "spent": dict(_spent), "calls": dict(_calls),
               "by_file": {name: dict(counts) for name, counts in _by_file.items()}}
    (Path(folder) / f"{worker}.json").write_text(json.dumps(figures), encoding="utf-8")


# --- the bench ---------------------------------------------------------------------------------------------------


def measure(arguments: list[str]) -> dict:
    """Run the README's test command with this plugin in every worker; its figures, summed over the workers."""
    with tempfile.TemporaryDirectory() as folder:
        environment = {**os.environ, OUT_ENV: folder,
                       "PYTHONPATH": os.pathsep.join(filter(None, [str(HERE), os.environ.get("PYTHONPATH")]))}
        start = time.perf_counter()
        done = subprocess.run([sys.executable, "-m", "pytest", "-p", "suite_budget", "-p", "no:cacheprovider",
                               *arguments], cwd=ROOT, env=environment, capture_output=True, text=True, check=False)
        wall = time.perf_counter() - start
        workers = [json.loads(path.read_text(encoding="utf-8")) for path in sorted(Path(folder).glob("gw*.json"))] \
            or [json.loads(path.read_text(encoding="utf-8")) for path in Path(folder).glob("controller.json")]
    summary = next((line for line in reversed(done.stdout.splitlines()) if " in " in line and "passed" in line), "")
    spent: collections.Counter = collections.Counter()
    calls: collections.Counter = collections.Counter()
    by_file: collections.defaultdict = collections.defaultdict(collections.Counter)
    for worker in workers:
        spent.update(worker["spent"])
        calls.update(worker["calls"])
        for name, counts in worker["by_file"].items():
            by_file[name].update(counts)
    return {"wall_s": wall, "summary": summary, "returncode": done.returncode, "workers": len(workers),
            "collection_s": [worker["collection_s"] for worker in workers],
            "tests_s": sum(counts["test"] for counts in by_file.values()),
            "spent": dict(spent), "calls": dict(calls),
            "by_file": {name: dict(counts) for name, counts in by_file.items() if name}}


def report(figures: dict) -> str:
    tests = figures["tests_s"]
    collecting = ", ".join(f"{seconds:.1f}" for seconds in figures["collection_s"])
    lines = ["# Where the test suite's time goes", "",
             (f"`python bench/suite_budget.py`: the README's test command, {figures['workers']} workers, "
              f"{figures['wall_s']:.0f} s wall ({figures['summary'] or 'no summary line'})."), "",
             (f"The tests took {tests:.0f} s in all (setup, call and teardown, summed over the workers); each worker "
              f"spent {collecting} s collecting before its first test."), "",
             "| stage | calls | s | share of the tests' time |", "|---|---:|---:|---:|"]
    for module_name, name, what in STAGES:
        key = f"{module_name}.{name}"
        seconds = figures["spent"].get(key, 0.0)
        lines.append(f"| {what} (`{name}`) | {figures['calls'].get(key, 0)} | {seconds:.1f} | "
                     f"{100 * seconds / tests if tests else 0:.1f} % |")
    run_key = "graphplan.run._run"
    lines += ["", "The files that take longest, with the time of their runs and of the choice of μl in them:", "",
              "| file | s | runs, s | choosing μl, s |", "|---|---:|---:|---:|"]
    heaviest = sorted(figures["by_file"].items(), key=lambda item: -item[1].get("test", 0.0))[:20]
    for name, counts in heaviest:
        lines.append(f"| {name} | {counts.get('test', 0.0):.1f} | {counts.get(run_key, 0.0):.1f} | "
                     f"{counts.get('graphplan.render.sheet.fewest_sheets_length_scale', 0.0):.1f} |")
    return "\n".join(lines) + "\n"


def main(arguments: list[str]) -> int:
    figures = measure(arguments)
    results = HERE / "results"
    results.mkdir(exist_ok=True)
    (results / "suite_budget.json").write_text(json.dumps(figures, indent=1, sort_keys=True), encoding="utf-8")
    (results / "suite_budget.md").write_text(report(figures), encoding="utf-8")
    print(report(figures))
    return 0 if figures["returncode"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
