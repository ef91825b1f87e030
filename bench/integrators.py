"""Error against run time of scipy's integrators on the machine's equation of motion.

    python bench/integrators.py

Two start-ups from rest of a machine with a variable reduced inertia and a periodic load:

* **non-stiff**: a motor with a soft straight characteristic (its time constant is several
  cycles);
* **stiff**: an induction motor by Kloss' formula with a small rated slip behind a gear, whose
  steep characteristic decays disturbances some ten times faster than the step RK45 needs to
  follow the load.

Each of RK45, DOP853, Radau, BDF and LSODA integrates each case through
:func:`graphplan.machine_motion.simulate` at tolerances rtol = 1e-3 … 1e-10.  The error is the
largest difference of ω from a reference solution over the run (400 instants, through each
solution's dense output), relative to the largest ω; the reference is DOP853 at rtol 1e-13 for
the non-stiff case and Radau at rtol 1e-12 for the stiff one, checked against each other.  The
machine is shared and noisy: each time is the median of a few runs of the whole ``simulate``
call (with its stiffness probe and cycle analysis, a few ms); the number of evaluations of the
right-hand side, which does not vary, is given beside it.

Writes ``bench/results/integrators.md`` and ``bench/results/integrators.svg``.
"""

from __future__ import annotations

import math
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import scipy

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from graphplan.machine_motion import DEFAULT_RTOL, RPM, KlossMotor, LinearMotor, Machine, simulate

METHODS = ("RK45", "DOP853", "Radau", "BDF", "LSODA")
TOLERANCES = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10)
REPEATS = 3
INSTANTS = 400
RESULTS = HERE / "results"


def variable_inertia() -> dict:
    """Je(φ) = J0 + J1·cos 2φ, as of a slider-crank's rod and slider, with its slope."""
    return {"inertia": lambda phi: 4.0 + 1.0 * math.cos(2.0 * phi),
            "inertia_slope": lambda phi: -2.0 * math.sin(2.0 * phi)}


CASES = {
    "non-stiff": {
        "machine": Machine(**variable_inertia(), resisting=lambda phi, omega: 60.0 + 40.0 * math.sin(phi)),
        "motor": LinearMotor(stall_torque=300.0, no_load=20.0),
        "duration": 6.0,
        "reference": ("DOP853", 1e-13),
        "check": ("Radau", 1e-12),
    },
    "stiff": {
        "machine": Machine(**variable_inertia(),
                           resisting=lambda phi, omega: 10.0 * omega * omega * (1.0 + 0.6 * math.sin(phi))),
        "motor": KlossMotor(power=5500.0, synchronous_speed=1500 * RPM, rated_slip=0.01, overload=2.2,
                            gear_ratio=20.0, rotor_inertia=0.02),
        "duration": 4.0,
        "reference": ("Radau", 1e-12),
        "check": ("DOP853", 1e-13),
    },
}


def run(case: dict, method: str, rtol: float):
    return simulate(case["machine"], case["motor"], duration=case["duration"], method=method, rtol=rtol,
                    max_evaluations=None)  # an explicit method on the stiff motor takes what it takes: it is measured


def timed(case: dict, method: str, rtol: float) -> tuple[float, object]:
    times = []
    for _ in range(REPEATS):
        began = time.perf_counter()
        motion = run(case, method, rtol)
        times.append(time.perf_counter() - began)
    return statistics.median(times), motion


def measure() -> dict:
    rows = {}
    for name, case in CASES.items():
        instants = np.linspace(0.0, case["duration"], INSTANTS)
        reference = run(case, *case["reference"])
        check = run(case, *case["check"])
        ref_omega = reference.state_at(instants)[1]
        scale = float(np.max(np.abs(ref_omega)))
        reference_error = float(np.max(np.abs(check.state_at(instants)[1] - ref_omega))) / scale
        entries = []
        for method in METHODS:
            for rtol in TOLERANCES:
                seconds, motion = timed(case, method, rtol)
                error = float(np.max(np.abs(motion.state_at(instants)[1] - ref_omega))) / scale
                entries.append({"method": method, "rtol": rtol, "seconds": seconds, "error": error,
                                "nfev": motion.nfev, "steps": int(motion.t.size)})
        auto = run(case, "auto", DEFAULT_RTOL)
        rows[name] = {"entries": entries, "reference_error": reference_error, "auto": auto,
                      "steady": reference.steady}
        print(f"{name}: done ({auto.method_reason})", flush=True)
    return rows


def markdown(rows: dict) -> str:
    lines = ["# scipy's integrators on the machine's equation of motion", "",
             "Written by `bench/integrators.py`; see its docstring for the cases.",
             (f"Python {platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}; "
              f"times are medians of {REPEATS} runs on a shared 2-core machine (noisy: compare within a column, "
              "and trust `nfev`, the right-hand side's evaluations, which does not vary)."), ""]
    for name, data in rows.items():
        case = CASES[name]
        steady = data["steady"]
        lines += [f"## {name}", "",
                  (f"Duration {case['duration']} s from rest; reference {case['reference'][0]} at rtol "
                   f"{case['reference'][1]:g}, which differs from {case['check'][0]} at rtol {case['check'][1]:g} "
                   f"by {data['reference_error']:.1e} (relative, largest over the run)."),
                  f"Steady state: ωm = {steady.mean_speed:.4f} rad/s, δ = {steady.delta:.5f}." if steady else
                  "No steady state within the duration.",
                  (f"`method = \"auto\"` at the default rtol, {DEFAULT_RTOL:g}, picks **{data['auto'].method}**; "
                   f"its reason: \"{data['auto'].method_reason}\"."),
                  "", "| method | rtol | error in ω | time, ms | nfev | steps |", "|---|---:|---:|---:|---:|---:|"]
        for e in data["entries"]:
            lines.append(f"| {e['method']} | {e['rtol']:.0e} | {e['error']:.2e} | {1e3 * e['seconds']:.1f} "
                         f"| {e['nfev']} | {e['steps']} |")
        lines.append("")
    lines += ["## Reading", "", *conclusions(rows), ""]
    return "\n".join(lines)


def conclusions(rows: dict) -> list[str]:
    """For each case and error level, the methods that reach it, fastest first (with their nfev)."""
    out = []
    for name, data in rows.items():
        for target in (1e-4, 1e-6, 1e-8):
            best = {}
            for e in data["entries"]:
                if e["error"] <= target and e["seconds"] < best.get(e["method"], (math.inf, 0))[0]:
                    best[e["method"]] = (e["seconds"], e["nfev"])
            if not best:
                out.append(f"- {name}, error ≤ {target:.0e}: no method reached it.")
                continue
            ranking = sorted(best.items(), key=lambda item: item[1][0])
            shown = ", ".join(f"{m} {1e3 * s:.1f} ms ({n} evaluations)" for m, (s, n) in ranking)
            out.append(f"- {name}, error ≤ {target:.0e}: fastest first: {shown}.")
    return out


def plot(rows: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    matplotlib.rcParams["svg.hashsalt"] = "graphplan-integrators"
    matplotlib.rcParams["font.family"] = "DejaVu Sans"
    markers = {"RK45": "o", "DOP853": "s", "Radau": "^", "BDF": "v", "LSODA": "D"}
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.6), constrained_layout=True)
    for ax, (name, data) in zip(axes, rows.items(), strict=True):
        for method in METHODS:
            entries = [e for e in data["entries"] if e["method"] == method]
            ax.loglog([1e3 * e["seconds"] for e in entries], [max(e["error"], 1e-16) for e in entries],
                      marker=markers[method], label=method)
        ax.set_title(f"{name}: error against run time (rtol 1e-3 … 1e-10)")
        # Run times span a decade or two: labelled at 1, 2 and 5 of each in plain milliseconds (matplotlib's
        # own minor labels, 3×10¹ beside 4×10¹, ran into one another within a decade).
        ax.xaxis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("run time, ms (median)")
        ax.set_ylabel("largest error in ω / ωmax")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    figure.savefig(path, format="svg", metadata={"Date": None})
    plt.close(figure)


def main() -> int:
    began = time.perf_counter()
    rows = measure()
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "integrators.md").write_text(markdown(rows), encoding="utf-8")
    plot(rows, RESULTS / "integrators.svg")
    print(f"wrote {RESULTS / 'integrators.md'} and integrators.svg in {time.perf_counter() - began:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
