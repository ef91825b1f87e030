"""Processor time with the placements and the lever's grown lines remembered, and without.

    python bench/placement_memo.py [--rounds N]

What is remembered: the label placements
(:func:`graphplan.render.labels.remembered`) and the grown unions of a
lever's or a group's lines (``force_marks.grown_union``), each for the very same
arguments. Two workloads, each a fresh interpreter started with both memos
as they are and with both off (``labels.PLACEMENTS_KEPT = 0``,
``force_marks.GROWN_KEPT = 0``), in turn, so that both see the same load on the
shared machine:

* tests: a few of the test files of the force drawings, single process
  (``pytest -n 0``), as one worker of the suite runs them: the same scenes
  drawn again and again in one process;
* run: ``graphplan run`` of a fixture whose force sheets try their lever at
  three μV (a single run, every file it writes).

The figure is the processor time (user and system) of the child, the median
over the rounds, and what matters is the ratio on/off of the one run. The
outputs are the same byte for byte either way (a memo gives back what was
made for the very same arguments). Results go to
bench/results/placement_memo.json and placement_memo.md.
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
TEST_FILES = ("tests/test_lever_drawn_larger.py", "tests/test_force_drawing.py")
SCENE = "fixtures/double_rocker_swing.toml"

# Each child switches the memo off (or leaves it) before graphplan draws anything.
PRELUDE = ("import sys; import graphplan.render.labels as labels; import graphplan.render.force_marks as force_marks; "
           "labels.PLACEMENTS_KEPT = {kept}; force_marks.GROWN_KEPT = {grown}; ")
WORKLOADS = {
    "tests": PRELUDE + "import pytest; sys.exit(pytest.main(['-p', 'no:cacheprovider', '-n', '0', '-q', *{files!r}]))",
    "run": PRELUDE + "from graphplan import cli; sys.exit(cli.main(['run', {scene!r}, '--out', {out!r}]))",
}


def processor_seconds(code: str) -> tuple[float, float]:
    """The processor time (user and system) and the wall time of ``python -c code`` run in the repository."""
    environment = {**os.environ, "PYTHONPATH": str(ROOT)}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", code], check=True, cwd=ROOT, env=environment,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), wall


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=2, help="runs of each workload each way (default 2)")
    rounds = parser.parse_args().rounds
    result: dict[str, dict[str, object]] = {}
    with tempfile.TemporaryDirectory() as scratch:
        for name, template in WORKLOADS.items():
            times: dict[str, list[float]] = {"on": [], "off": []}
            walls: dict[str, list[float]] = {"on": [], "off": []}
            for _ in range(rounds):
                for way, kept, grown in (("off", 0, 0), ("on", "labels.PLACEMENTS_KEPT", "force_marks.GROWN_KEPT")):
                    code = template.format(kept=kept, grown=grown, files=TEST_FILES, scene=SCENE,
                                           out=str(Path(scratch) / way))
                    cpu, wall = processor_seconds(code)
                    times[way].append(cpu)
                    walls[way].append(wall)
                    print(f"{name} {way}: {cpu:.2f} s processor, {wall:.2f} s wall", file=sys.stderr)
            on, off = statistics.median(times["on"]), statistics.median(times["off"])
            result[name] = {"processor_s": times, "wall_s": walls, "median_on_s": on, "median_off_s": off,
                            "ratio_on_off": on / off}
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    (out / "placement_memo.json").write_text(json.dumps(result, indent=1) + "\n", encoding="utf-8")
    lines = ["# Placements and grown lines remembered, against made again", "",
             f"Processor time of a fresh interpreter (median of {rounds}, each way in turn under the same load).", "",
             "| workload | memo off (s) | memo on (s) | on / off |", "|---|---|---|---|"]
    described = {"tests": "pytest -n 0 " + " ".join(TEST_FILES), "run": f"graphplan run {SCENE}"}
    for name, figures in result.items():
        lines.append(f"| {described[name]} | {figures['median_off_s']:.2f} | {figures['median_on_s']:.2f} "
                     f"| {figures['ratio_on_off']:.2f} |")
    lines += ["", "Regenerate with `python bench/placement_memo.py` (`--rounds N`).", ""]
    (out / "placement_memo.md").write_text("\n".join(lines), encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
