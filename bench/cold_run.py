"""Wall time of a cold `graphplan run` on the bundled scene, with every drawing and table it writes.

    python bench/cold_run.py

Each run is a fresh interpreter (imports included), as a user starts it. The
machine is shared and noisy, so the figure is the median of several runs, and
the interpreter's own start-up is measured beside it for scale. Results go to
bench/results/cold_run.json and cold_run.md. Target: under 1 s.
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCENE = HERE.parent / "fixtures" / "ratchet_crank_rocker.toml"
RUNS = 7
TARGET_S = 1.0


def wall(command: list[str], environment: dict[str, str]) -> float:
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=environment)
    return time.perf_counter() - start


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
    with tempfile.TemporaryDirectory() as scratch:
        environment = installed_like(Path(scratch))
        run = [sys.executable, "-m", "graphplan", "run", str(SCENE), "--out", str(Path(scratch) / "out")]
        wall(run, environment)  # the first run compiles the bytecode; a user's second run is the cold run meant here
        runs = [wall(run, environment) for _ in range(RUNS)]
        bare = [wall([sys.executable, "-c", "pass"], environment) for _ in range(RUNS)]
        files = sorted(p.name for p in (Path(scratch) / "out").iterdir())
    result = {"scene": SCENE.name, "runs": RUNS, "median_s": statistics.median(runs), "max_s": max(runs),
              "python_startup_median_s": statistics.median(bare), "target_s": TARGET_S, "files": files}
    result["ratio_to_python_startup"] = result["median_s"] / result["python_startup_median_s"]
    markdown = (
        f"# Cold `graphplan run` on {SCENE.name}\n\n"
        f"Median of {RUNS} fresh interpreters: **{result['median_s']:.3f} s** (max {result['max_s']:.3f} s; "
        f"target {TARGET_S} s); a bare Python start-up takes {result['python_startup_median_s']:.3f} s "
        f"({result['ratio_to_python_startup']:.1f}× that). Files written: {', '.join(files)}.\n"
        "Regenerate with `python bench/cold_run.py`.\n")
    write_results("cold_run", result, markdown)
    print(f"cold run: median {result['median_s']:.3f} s (target {TARGET_S} s)")


if __name__ == "__main__":
    main()
