"""Wall time of a cold `graphplan run` on the bundled scene, with every drawing and table it writes.

    python bench/cold_run.py [--against REVISION]

Each run is a fresh interpreter (imports included), as a user starts it. The
machine is shared and noisy, so the figure is the median of several runs, and
the interpreter's own start-up is measured beside it for scale. With
``--against``, the same scene is run by the package as it was at REVISION (a
git worktree of it, removed afterwards) in turn with this tree's, so that a
change is judged by the ratio of two figures taken under the same load.
Results go to bench/results/cold_run.json and cold_run.md. Target: under 1 s.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
SCENE = ROOT / "fixtures" / "ratchet_crank_rocker.toml"
RUNS = 7
TARGET_S = 1.0


def wall(command: list[str], environment: dict[str, str], tree: Path = ROOT) -> float:
    """Seconds ``command`` takes run in ``tree``, whose graphplan (``python -m`` puts it first) is the one run."""
    return timed(command, environment, tree)[0]


def timed(command: list[str], environment: dict[str, str], tree: Path = ROOT) -> tuple[float, float]:
    """The wall seconds of ``command`` run in ``tree`` and the processor seconds it used (user and system): on a
    machine others load, the wall time waits for the processor, and the processor time tells the work done."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=environment,
                   cwd=tree)
    elapsed = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return elapsed, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def installed_like(scratch: Path) -> dict[str, str]:
    """The environment of an installed graphplan: bytecode is written and read back, as pip's install leaves it.

    A shell with PYTHONDONTWRITEBYTECODE (this machine's) would compile every module on every run, which a
    user's second run never does. The bytecode goes to the scratch directory, not beside the sources.
    """
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    environment["PYTHONPYCACHEPREFIX"] = str(scratch / "bytecode")
    return environment


def write_results(stem: str, result: dict, markdown: str) -> None:
    """``result`` as bench/results/<stem>.json and ``markdown`` as <stem>.md."""
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    (out / f"{stem}.json").write_text(json.dumps(result, indent=1) + "\n", encoding="utf-8")
    (out / f"{stem}.md").write_text(markdown, encoding="utf-8")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--against", metavar="REVISION", help="also time the package as it was at REVISION")
    against = parser.parse_args().against
    with tempfile.TemporaryDirectory() as scratch:
        environment = installed_like(Path(scratch))
        trees = {"this": ROOT}
        if against is not None:
            trees["against"] = Path(scratch) / "against"
            subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(trees["against"]), against],
                           check=True, capture_output=True)
        try:
            times = _timed(trees, environment, Path(scratch))
        finally:
            if against is not None:
                subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(trees["against"])],
                               check=False, capture_output=True)
        bare = [wall([sys.executable, "-c", "pass"], environment) for _ in range(RUNS)]
        files = sorted(p.name for p in (Path(scratch) / "out-this").iterdir())
    runs = [elapsed for elapsed, _ in times["this"]]
    result = {"scene": SCENE.name, "runs": RUNS, "median_s": statistics.median(runs), "max_s": max(runs),
              "cpu_median_s": statistics.median(used for _, used in times["this"]),
              "python_startup_median_s": statistics.median(bare), "target_s": TARGET_S, "files": files}
    result["ratio_to_python_startup"] = result["median_s"] / result["python_startup_median_s"]
    compared = ""
    if against is not None:
        revision = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", against], check=True,
                                  capture_output=True, text=True).stdout.strip()
        earlier = [elapsed for elapsed, _ in times["against"]]
        result["against"] = {"revision": revision, "median_s": statistics.median(earlier), "max_s": max(earlier),
                             "cpu_median_s": statistics.median(used for _, used in times["against"])}
        result["ratio_to_against"] = result["median_s"] / result["against"]["median_s"]
        result["cpu_ratio_to_against"] = result["cpu_median_s"] / result["against"]["cpu_median_s"]
        compared = (f" The same scene run by {revision}, in turn with these runs under the same load: median "
                    f"{result['against']['median_s']:.3f} s (max {result['against']['max_s']:.3f} s), processor "
                    f"time {result['against']['cpu_median_s']:.3f} s against this tree's "
                    f"{result['cpu_median_s']:.3f} s; this tree takes {result['ratio_to_against']:.2f}× its wall "
                    f"time and {result['cpu_ratio_to_against']:.2f}× its processor time.")
    markdown = (
        f"# Cold `graphplan run` on {SCENE.name}\n\n"
        f"Median of {RUNS} fresh interpreters: **{result['median_s']:.3f} s** (max {result['max_s']:.3f} s; "
        f"target {TARGET_S} s; processor time {result['cpu_median_s']:.3f} s); a bare Python start-up takes {result['python_startup_median_s']:.3f} s "
        f"({result['ratio_to_python_startup']:.1f}× that).{compared} Files written: {', '.join(files)}.\n"
        "Regenerate with `python bench/cold_run.py` (`--against REVISION` to time an earlier tree beside it).\n")
    write_results("cold_run", result, markdown)
    print(f"cold run: median {result['median_s']:.3f} s (target {TARGET_S} s)"
          + (f", {result['ratio_to_against']:.2f}× {result['against']['revision']}'s wall time and "
             f"{result['cpu_ratio_to_against']:.2f}× its processor time" if against else ""))


def _timed(trees: dict[str, Path], environment: dict[str, str],
           scratch: Path) -> dict[str, list[tuple[float, float]]]:
    """The (wall, processor) seconds of RUNS cold runs of each tree's package, taken in turn so that both meet the
    same load."""
    def command(name: str) -> list[str]:
        return [sys.executable, "-m", "graphplan", "run", str(SCENE), "--out", str(scratch / f"out-{name}")]

    for name, tree in trees.items():
        wall(command(name), environment, tree)  # the first run compiles the bytecode; a user's second is meant here
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in trees}
    for _ in range(RUNS):
        for name, tree in trees.items():
            times[name].append(timed(command(name), environment, tree))
    return times


if __name__ == "__main__":
    main()
