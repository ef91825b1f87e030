"""Speed of the analytic sweep, against the peer packages pylinkage and mechanism.

    python bench/sweep.py            # needs the bench extra: pip install ".[bench]"

For the four-bar (the ratchet fixture) and a Stephenson six-bar built on it (an RRR dyad from coupler point E to a frame pivot), at
10⁵ crank positions, it times graphplan's full sweep (every point's r, v, a
and every link's angle, ω, ε) and the peers' sweeps of the same linkages,
checks that all of them give the same answers (largest differences against
graphplan and against the independent closed form of ``bench/peers.py``),
and writes the figures and ratios to ``bench/results/sweep.json`` and
``bench/results/sweep.md``.

The machine is shared and noisy: every figure is the best of several runs
after a warm-up, and the ratios compare figures taken in the same run.
"""

from __future__ import annotations

import json
import platform
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
# The peers' adapters live beside this script.
sys.path.insert(0, str(HERE))

import peers

import graphplan
from graphplan.accuracy import best_time

N = 100_000
REPEATS = 15
MECHANISM_N = 2_000      # mechanism calls fsolve three times per position: 10⁵ would take minutes
FIXTURE = HERE.parent / "fixtures" / "ratchet_crank_rocker.toml"

SIX_BAR_GROUP = f"""
[[groups]]
kind     = "RRR"
links    = [5, 6]
joints   = ["E", "D", "F"]
lengths  = [{peers.SIX_ED}, {peers.SIX_DF}]
assembly = "{'left' if peers.SIX_D_SIDE > 0 else 'right'}"
"""


def scenes() -> dict[str, graphplan.Scene]:
    four_bar_text = FIXTURE.read_text(encoding="utf-8")
    six_bar_text = four_bar_text.replace(
        "points = { O = [0.0, 0.0], C = [0.0, 0.55] }",
        f"points = {{ O = [0.0, 0.0], C = [0.0, 0.55], F = [{peers.SIX_F[0]}, {peers.SIX_F[1]}] }}",
    ).replace("[points]", SIX_BAR_GROUP + "\n[points]")
    return {"four-bar": graphplan.load(FIXTURE),
            "six-bar": graphplan.scene.loads(six_bar_text, source="six-bar")}


def graphplan_sweep(scene: graphplan.Scene, angles: np.ndarray) -> dict[str, np.ndarray]:
    """graphplan's full sweep in the peers' dictionary form (A, vA, aA, ..., omega3, alpha3)."""
    motion = graphplan.solve(scene, driver=angles)
    out: dict[str, np.ndarray] = {}
    # Frame points stand still: like the peers, the sweep reports the moving points.
    for name in (n for n in motion.points if n not in scene.frame_points):
        point = motion.point(name)
        out[name], out["v" + name], out["a" + name] = point.r, point.v, point.a
    for number in motion.links:
        if number == scene.frame_link:
            continue
        link = motion.link(number)
        out[f"angle{number}"], out[f"omega{number}"], out[f"alpha{number}"] = link.angle, link.omega, link.epsilon
    return out


def best_rate(function, count: int, repeats: int = REPEATS) -> tuple[float, object]:
    function()  # warm-up: imports, numba compilation, allocator
    seconds, result = best_time(function, repeats)
    return count / seconds, result


def measure(name: str, scene: graphplan.Scene) -> dict:
    angles = peers.sweep(N, peers.OMEGA)
    six = name == "six-bar"
    ours_rate, ours = best_rate(lambda: graphplan_sweep(scene, angles), N)
    reference = peers.reference_sixbar(angles) if six else peers.reference_fourbar(angles)
    rows = {"graphplan": {"positions_per_s": ours_rate, "n": N, "computes": "r, v, a of every moving point; angle, ω, ε of every link",
                          "vs_reference": peers.max_differences(ours, reference)}}
    pylinkage = peers.pylinkage_sixbar if six else peers.pylinkage_fourbar
    rate, result = best_rate(lambda: pylinkage(angles, kinematics=True, fast=True), N)
    rows["pylinkage (numba), with v and a"] = {
        "positions_per_s": rate, "n": N, "computes": "r, v, a of joints; no link ω, ε",
        "vs_graphplan": peers.max_differences(result, ours), "vs_reference": peers.max_differences(result, reference),
        "crank_angle_drift_rad": result["crank_angle_error"]}
    rate, _ = best_rate(lambda: pylinkage(angles, kinematics=False, fast=True), N)
    rows["pylinkage (numba), positions only"] = {"positions_per_s": rate, "n": N, "computes": "r of joints"}
    few = angles[:MECHANISM_N]
    mechanism = peers.mechanism_sixbar if six else peers.mechanism_fourbar
    rate, result = best_rate(lambda: mechanism(few, kinematics=True), MECHANISM_N, repeats=2)
    ours_few = {key: value[:MECHANISM_N] for key, value in ours.items()}
    rows["mechanism (fsolve), with v and a"] = {
        "positions_per_s": rate, "n": MECHANISM_N, "computes": "r, v, a of joints; ω, α of vectors",
        "vs_graphplan": peers.max_differences(result, ours_few)}
    fastest_peer = max(rate for key, row in rows.items() if key != "graphplan" and "with v and a" in key
                       for rate in [row["positions_per_s"]])
    return {"rows": rows, "ratio_to_fastest_peer_with_v_and_a": ours_rate / fastest_peer}


def write(results: dict) -> None:
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    (out / "sweep.json").write_text(json.dumps(results, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    lines = ["# Analytic sweep: positions per second", "",
             (f"{results['machine']}; best of {REPEATS} runs after a warm-up; N = {N} crank positions "
              f"(mechanism: {MECHANISM_N}). Regenerate with `python bench/sweep.py`."), ""]
    for name, linkage in results["linkages"].items():
        lines += [f"## {name}", "", "| solver | positions/s | computes | largest difference (pos m, vel m/s, acc m/s²) |",
                  "|---|---:|---|---|"]
        for solver, row in linkage["rows"].items():
            diff = row.get("vs_graphplan") or row.get("vs_reference")
            against = "vs graphplan" if "vs_graphplan" in row else "vs closed form"
            text = (f"{diff['pos']:.1e}, {diff['vel']:.1e}, {diff['acc']:.1e} ({against})" if diff else "")
            lines.append(f"| {solver} | {row['positions_per_s']:.3g} | {row['computes']} | {text} |")
        lines += ["", f"graphplan / fastest peer with v and a: **{linkage['ratio_to_fastest_peer_with_v_and_a']:.1f}×**", ""]
    lines += [("pylinkage steps its crank by adding an increment, so its crank angle drifts from the exact one "
               "(the `crank_angle_drift_rad` in sweep.json); that drift is most of its difference from graphplan."), ""]
    (out / "sweep.md").write_text("\n".join(lines), encoding="utf-8")


def main() -> None:
    results = {"machine": f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, numpy {np.__version__}",
               "n": N, "linkages": {}}
    for name, scene in scenes().items():
        results["linkages"][name] = measure(name, scene)
        row = results["linkages"][name]
        print(f"{name}: graphplan {row['rows']['graphplan']['positions_per_s']:.3g}/s, "
              f"{row['ratio_to_fastest_peer_with_v_and_a']:.1f}× the fastest peer")
    write(results)
    print(f"wrote {HERE / 'results' / 'sweep.md'}")


if __name__ == "__main__":
    main()
