"""Wall time of a run's PNG and PDF rendered one by one and at once (export.rendered_all).

    python bench/png_export.py [--rounds N]

The drawings and plots are those `graphplan run` writes of a fixture on A1 sheets (the shaper: its sheets, plan
sheets and their parts, force sheets, diagrams and the dynamics' plots), read back as SVG. Each round renders every
one of them as PNG one by one in this thread, then all at once as a run does (in threads, one a core), and the PDF
one by one and in as many threads, which a run does not (nine tenths of a PDF's time is cairosvg's own Python,
which threads take in turns); the rounds alternate, so that each way sees the same load on the shared machine, and the
figure is the median wall time. The files are the same byte for byte either way. Results go to
bench/results/png_export.json and png_export.md.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
SCENE = "fixtures/shaper_six_bar.toml"


def drawings(folder: Path) -> dict[str, str]:
    """The SVG files a run of the fixture writes, by name."""
    subprocess.run([sys.executable, "-m", "graphplan", "run", SCENE, "--out", str(folder), "--figures"],
                   check=True, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return {path.name: path.read_text(encoding="utf-8") for path in sorted(folder.glob("*.svg"))}


def timed(work) -> tuple[float, object]:
    start = time.perf_counter()
    found = work()
    return time.perf_counter() - start, found


def main() -> None:
    sys.path.insert(0, str(ROOT))
    from graphplan.render import export
    from graphplan.render.export import Rendering, rendered_all

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    rounds = parser.parse_args().rounds
    with tempfile.TemporaryDirectory() as folder:
        svgs = drawings(Path(folder) / "run")
    cores = export._cores()
    images = {name: Rendering(svg, "png") for name, svg in svgs.items()}
    documents = {name: Rendering(svg, "pdf") for name, svg in svgs.items()}
    times: dict[str, list[float]] = {"png one by one": [], "png at once": [], "pdf one by one": [],
                                     "pdf in threads": []}
    for _ in range(rounds):
        alone, one_by_one = timed(lambda: {name: rendering.rendered() for name, rendering in images.items()})
        together, at_once = timed(lambda: rendered_all(images))
        assert at_once == one_by_one, "the PNG rendered at once differ from those rendered one by one"
        times["png one by one"].append(alone)
        times["png at once"].append(together)
        times["pdf one by one"].append(timed(lambda: [rendering.rendered() for rendering in documents.values()])[0])
        with ThreadPoolExecutor(cores) as pool:
            times["pdf in threads"].append(timed(lambda: list(pool.map(Rendering.rendered, documents.values())))[0])
    medians = {way: statistics.median(seconds) for way, seconds in times.items()}
    figures = {
        "scene": SCENE, "drawings": len(svgs), "cores": cores, "rounds": rounds,
        "median_seconds": {way: round(seconds, 3) for way, seconds in medians.items()},
        "png_at_once_over_one_by_one": round(medians["png at once"] / medians["png one by one"], 3),
        "pdf_in_threads_over_one_by_one": round(medians["pdf in threads"] / medians["pdf one by one"], 3),
    }
    results = HERE / "results"
    results.mkdir(exist_ok=True)
    (results / "png_export.json").write_text(json.dumps(figures, indent=2) + "\n", encoding="utf-8")
    lines = [
        "# PNG and PDF of a run, one by one and at once",
        "",
        (f"`python bench/png_export.py --rounds {rounds}`: the {len(svgs)} drawings and plots of `{SCENE}` "
         f"(A1 sheets, `--figures`), on {cores} cores; the median wall time of {rounds} alternating rounds."),
        "",
        "| way | seconds |",
        "|---|---:|",
        *(f"| {way} | {seconds:.2f} |" for way, seconds in medians.items()),
        "",
        (f"PNG at once / one by one: {figures['png_at_once_over_one_by_one']:.2f} (the same bytes either way). "
         f"PDF in {cores} threads / one by one: {figures['pdf_in_threads_over_one_by_one']:.2f}: a run renders its "
         "PDF one by one."),
        "",
    ]
    (results / "png_export.md").write_text("\n".join(lines), encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
