"""What choosing μl costs a course project's run: the shaper starter as written (no `length_scale`: the
sheets are laid out at each μl tried) against the same scene with the μl it chose written in.

    python bench/length_scale_choice.py

The run at the μl chosen reuses the layout the choice made at it (render/sheet.py `_laid_out`), so the
choice costs the layouts at the other μl tried and nothing more. The machine is shared and noisy: the two
scenes run alternately, each in a fresh interpreter, and the figure is the ratio of their medians.
Results go to bench/results/length_scale_choice.json and .md. Target: the choice adds at most 60 %.
"""

from __future__ import annotations

import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from cold_run import installed_like, write_results

import graphplan
from graphplan.analysis import analyse
from graphplan.render.drawings import length_scale

RUNS = 5
TARGET_RATIO = 1.6


def timed(scene: Path, out: Path, environment: dict[str, str]) -> float:
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "graphplan", "run", str(scene), "--out", str(out)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=environment)
    return time.perf_counter() - start


def main() -> None:
    with tempfile.TemporaryDirectory() as scratch_name:
        scratch = Path(scratch_name)
        environment = installed_like(scratch)
        chosen_scene = scratch / "shaper.toml"
        subprocess.run([sys.executable, "-m", "graphplan", "new", "shaper", "--out", str(chosen_scene)], check=True,
                       stdout=subprocess.DEVNULL, env=environment)
        scale = length_scale(analyse(graphplan.load(chosen_scene)))
        given_scene = scratch / "shaper_given.toml"
        text = chosen_scene.read_text(encoding="utf-8")
        given_scene.write_text(re.sub(r"^\[drawing\]\s*$", f"[drawing]\nlength_scale = {scale!r}", text, count=1,
                                      flags=re.MULTILINE), encoding="utf-8")
        timed(chosen_scene, scratch / "warm", environment)  # the bytecode, as a user's second run has it
        chosen, given = [], []
        for k in range(RUNS):
            chosen.append(timed(chosen_scene, scratch / f"chosen{k}", environment))
            given.append(timed(given_scene, scratch / f"given{k}", environment))
        same = all((scratch / "chosen0" / name.name).read_bytes() == name.read_bytes()
                   for name in (scratch / "given0").iterdir() if name.suffix == ".svg")
    result = {"scene": "graphplan new shaper", "length_scale": scale, "runs": RUNS,
              "chosen_median_s": statistics.median(chosen), "given_median_s": statistics.median(given),
              "drawings_identical": same, "target_ratio": TARGET_RATIO}
    result["ratio"] = result["chosen_median_s"] / result["given_median_s"]
    markdown = (
        "# What choosing μl costs a run\n\n"
        f"The shaper starter without `length_scale` (μl chosen: {scale:g} m/mm) against the same scene with it "
        f"written in; medians of {RUNS} alternate fresh runs: **{result['chosen_median_s']:.2f} s** against "
        f"**{result['given_median_s']:.2f} s**, ratio **{result['ratio']:.2f}** (target ≤ {TARGET_RATIO}); the "
        f"drawings {'are' if same else 'are NOT'} byte-identical.\n"
        "Regenerate with `python bench/length_scale_choice.py`.\n")
    write_results("length_scale_choice", result, markdown)
    print(f"choosing μl: {result['ratio']:.2f}× the run with it given (target ≤ {TARGET_RATIO})")


if __name__ == "__main__":
    main()
