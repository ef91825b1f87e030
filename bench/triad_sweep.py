"""Speed of a dense sweep of a mechanism with a class III triad, which no closed form places.

    python bench/triad_sweep.py

A triad's pose is walked out from the reference position a degree at a time (scipy's hybrid
Newton at each step); the positions asked for between the steps are then settled in one batched
Newton solve.  This times, on a fresh mechanism each time (nothing remembered from a walk before),
the sweep of both triad fixtures at 3 600 and 36 000 crank angles over a turn, against the same
sweep with every position settled one by one by scipy (the way it was done before the batch), checks
that the two give the same motion, and writes the figures and ratios to
``bench/results/triad_sweep.json`` and ``bench/results/triad_sweep.md``.

The machine is shared and noisy: every figure is the best of a few runs after a warm-up, and the
ratios compare figures taken in the same run.
"""

from __future__ import annotations

import json
import platform
import sys
from pathlib import Path
from unittest import mock

import numpy as np

import graphplan
from graphplan.accuracy import best_time
from graphplan.groups.triad import Triad

HERE = Path(__file__).resolve().parent
FIXTURES = ["triad_class_iii", "triad_with_slider"]
COUNTS = [3_600, 36_000]
REPEATS = 3


def one_by_one(self, guesses, tracks, turn):
    """Settles nothing in the batch, so every position goes to scipy from the step before it."""
    return [None] * len(guesses)


def sweep(scene: graphplan.Scene, angles: np.ndarray):
    mechanism = graphplan.build(scene)
    return graphplan.motion.solve(mechanism, angles)


def measure(name: str, count: int) -> dict:
    scene = graphplan.load(HERE.parent / "fixtures" / f"{name}.toml")
    angles = np.linspace(0.0, 2 * np.pi, count, endpoint=False)
    sweep(scene, angles[:10])  # warm-up: imports and caches
    batched_seconds, batched = best_time(lambda: sweep(scene, angles), REPEATS)
    with mock.patch.object(Triad, "_settle_many", one_by_one):
        alone_seconds, alone = best_time(lambda: sweep(scene, angles), REPEATS)
    difference = max(float(np.max(np.abs(batched.point(point).r - alone.point(point).r)))
                     for point in batched.points)
    return {"scene": name, "positions": count, "batched_s": batched_seconds, "one_by_one_s": alone_seconds,
            "speed-up": alone_seconds / batched_seconds, "largest_difference_m": difference}


def write(rows: list[dict]) -> None:
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    document = {"machine": platform.platform(), "python": platform.python_version(), "rows": rows}
    (out / "triad_sweep.json").write_text(json.dumps(document, indent=1) + "\n", encoding="utf-8")
    lines = ["# A dense sweep of a class III triad", "",
             (f"`python bench/triad_sweep.py` on {platform.platform()}, Python {platform.python_version()}; "
              f"best of {REPEATS} runs, a fresh mechanism each. One by one: every position settled by scipy's "
              "hybrid Newton from the one before it; batched: the walk's steps so, the positions between them in "
              "one batched Newton solve."), "",
             "| scene | positions | one by one, s | batched, s | speed-up | largest difference, m |",
             "|---|---:|---:|---:|---:|---:|"]
    lines += [f"| {row['scene']} | {row['positions']} | {row['one_by_one_s']:.3f} | {row['batched_s']:.3f} | "
              f"{row['speed-up']:.1f} | {row['largest_difference_m']:.1e} |" for row in rows]
    (out / "triad_sweep.md").write_text("\n".join(lines) + "\n", encoding="utf-8")


def main() -> None:
    rows = [measure(name, count) for name in FIXTURES for count in COUNTS]
    write(rows)
    for row in rows:
        print(f"{row['scene']:>18} {row['positions']:>6}: {row['one_by_one_s']:.2f} s one by one, "
              f"{row['batched_s']:.2f} s batched ({row['speed-up']:.1f}×), difference {row['largest_difference_m']:.1e} m")
    sys.exit(0)


if __name__ == "__main__":
    main()
