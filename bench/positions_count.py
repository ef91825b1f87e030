"""How `graphplan run` grows with `positions.count`: CPU time, wall time, peak memory and results.json's size.

    python bench/positions_count.py [COUNT ...]

The scene is the crank-rocker starter with one plan (`plans = [1]`), as a student asking for a fine cycle
would write it; every deliverable is written.  Each count runs in a fresh interpreter; the CPU time of that
child (user + system) is the figure that decides, since the machine is shared and its wall time is noisy.
The scene format's limit on `positions.count` (graphplan.scene.MAX_POSITIONS) is meant to run in about a
minute.  Results go to bench/results/positions_count.json and positions_count.md.
"""

from __future__ import annotations

import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
from graphplan.scene import MAX_POSITIONS
from graphplan.starters import starter

COUNTS = (1000, 4000, 12000)
TARGET_CPU_S = 60.0


def scene_with(count: int) -> str:
    text = starter("crank-rocker")
    head, _, tail = text.partition("[positions]")
    if not tail:
        raise SystemExit("the crank-rocker starter has no [positions] table to change")
    body, _, rest = tail.partition("\n[")
    lines = [line for line in body.splitlines() if not line.strip().startswith(("count", "plans"))]
    return head + "[positions]" + "\n".join([*lines[:1], f"count = {count}", "plans = [1]", *lines[1:]]) + "\n\n[" + rest


def measure(count: int, scratch: Path) -> dict:
    scene = scratch / f"count_{count}.toml"
    scene.write_text(scene_with(count), encoding="utf-8")
    out = scratch / f"out_{count}"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "graphplan", "run", str(scene), "--out", str(out)],
                          capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise SystemExit(f"count {count}: graphplan run failed:\n{done.stderr}")
    return {"count": count, "cpu_s": round(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, 2),
            "wall_s": round(wall, 2), "peak_rss_mb": round(after.ru_maxrss / 1024, 1),
            "results_json_mb": round((out / "results.json").stat().st_size / 1e6, 2)}


def main() -> None:
    counts = tuple(int(arg) for arg in sys.argv[1:]) or COUNTS
    with tempfile.TemporaryDirectory() as scratch:
        rows = [measure(count, Path(scratch)) for count in counts]
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    result = {"limit": MAX_POSITIONS, "target_cpu_s": TARGET_CPU_S, "runs": rows}
    (out / "positions_count.json").write_text(json.dumps(result, indent=1) + "\n", encoding="utf-8")
    table = "\n".join(f"| {r['count']} | {r['cpu_s']} | {r['wall_s']} | {r['peak_rss_mb']} | {r['results_json_mb']} |"
                      for r in rows)
    per = ", ".join(f"{1e3 * r['cpu_s'] / r['count']:.2f} ms" for r in rows)
    (out / "positions_count.md").write_text(
        "# `graphplan run` against `positions.count` (crank-rocker starter, plans = [1], every deliverable)\n\n"
        "| count | CPU s | wall s | peak RSS MB (largest child so far) | results.json MB |\n"
        "|---|---|---|---|---|\n" + table + "\n\n"
        f"CPU per position: {per}.  The limit `positions.count` ≤ {MAX_POSITIONS} is meant to run in about "
        f"{TARGET_CPU_S:.0f} s of CPU.\nRegenerate with `python bench/positions_count.py`.\n", encoding="utf-8")


if __name__ == "__main__":
    main()
