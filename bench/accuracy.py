"""Error against run time: every way of finding velocities and accelerations, against the 50-digit reference.

    python bench/accuracy.py            # writes bench/results/accuracy.md, accuracy.csv, accuracy.svg

Every fixture is studied by :func:`graphplan.accuracy.study` (the methods and how the errors are
measured are described there: the analytic solver, the construction, the plans drafted to 1 … 0.1 mm,
the kinematic diagrams at N = 12 … 3600 positions), with the peer packages of ``bench/peers.py`` added
where they model the same linkage (the ratchet four-bar, the Stephenson six-bar as their six-bar
with the fixture's dyad, and the centric and offset slider-cranks), and the analytic solver is compared with the reference over a dense cycle,
every vector.  The same study of one scene is what ``[output] include = ["accuracy"]`` delivers.
"""

from __future__ import annotations

import io
import math
import platform
import sys
from collections.abc import Mapping
from pathlib import Path

import numpy as np

import graphplan
from graphplan import reference
from graphplan.accuracy import (
    REPEATS,
    Case,
    Row,
    Values,
    best_time,
    draw_study,
    label,
    quantities,
    relative_errors,
    study,
)
from graphplan.locale import strings
from graphplan.motion import solve
from graphplan.report.accuracy import csv_text, order_sentence, table_lines

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))  # for peers.py beside this file

FIXTURES = sorted((HERE.parent / "fixtures").glob("*.toml"))
RESULTS = HERE / "results"


# --- the peers ------------------------------------------------------------------------------------

def _peer_values(result: Mapping, index: int, rename: Mapping[str, str]) -> Values:
    v, a, omega, epsilon = {}, {}, {}, {}
    for key, value in result.items():
        if not isinstance(value, np.ndarray):
            continue
        if key.startswith("omega"):
            omega[int(key[5:])] = float(value[index])
        elif key.startswith("alpha"):
            epsilon[int(key[5:])] = float(value[index])
        elif key[0] in "va" and key[1:] in result:
            target = v if key[0] == "v" else a
            target[rename.get(key[1:], key[1:])] = complex(*value[index])
    return Values(v, a, omega, epsilon)


def peer_rows(case: Case) -> list[Row]:
    """pylinkage and mechanism on the linkages bench/peers.py models: the ratchet four-bar, the Stephenson six-bar,
    the centric and the offset slider-crank."""
    try:
        import peers
    except ImportError:  # pragma: no cover - the bench extra is missing
        return []
    # fixture: (pylinkage model, mechanism model, the fixture's geometry as keywords, peer point → fixture point)
    models = {
        "ratchet_crank_rocker": (peers.pylinkage_fourbar, peers.mechanism_fourbar, {}, {}),
        "stephenson_six_bar": (peers.pylinkage_sixbar, peers.mechanism_sixbar,
                               {"ED": 0.40, "DF": 0.30, "F": (-0.65, -0.10), "d_side": -1}, {"D": "G"}),
        # Both guides are horizontal with the slider on the +x side of the crank pin (assembly = "forward"), the one
        # slider-crank bench/peers.py models; offset = the guide's height above O, S3 = the rod's point s3 from A.
        "engine_slider_crank": (peers.pylinkage_slider_crank, peers.mechanism_slider_crank,
                                {"crank": 0.05, "rod": 0.19, "offset": 0.0, "s3": 0.055}, {}),
        "offset_slider_crank": (peers.pylinkage_slider_crank, peers.mechanism_slider_crank,
                                {"crank": 0.08, "rod": 0.26, "offset": 0.08, "s3": 0.13}, {}),
    }
    if case.name not in models:
        return []
    pylinkage, mech, geometry, rename = models[case.name]
    # The crank's ω and ε are the fixture's (the four-bar models' defaults are the ratchet's -17 rad/s, 0).
    geometry = {**geometry, "omega": case.mechanism.driver.omega, "alpha": case.mechanism.driver.epsilon}
    angles = np.asarray(case.values, dtype=float)
    rows = []
    for name, run, repeats in (("pylinkage", lambda: pylinkage(angles, **geometry, kinematics=True, fast=False), REPEATS),
                               ("mechanism", lambda: mech(angles, **geometry, kinematics=True), 3)):
        try:
            run()  # warm-up: imports
            seconds, result = best_time(run, repeats)
        except Exception as error:  # noqa: BLE001 - a peer's failure is a result to report, not a crash
            print(f"  {name} failed on {case.name}: {error}")
            continue
        got = [quantities(case.mechanism, case.tables[i], _peer_values(result, i, rename)) for i in range(len(angles))]
        exact = [{q: row[q] for q in mine} for row, mine in zip(case.exact, got)]
        rows.append(Row(case.name, name, "peer", len(angles), seconds, relative_errors(got, exact)))
    return rows


# --- the whole-vector check of the analytic solver ------------------------------------------------

def analytic_vectors(case: Case, count: int = 360) -> dict[str, float]:
    """graphplan against the reference over a dense cycle: every point's r, v, a and every link's angle, ω, ε."""
    driver = case.mechanism.driver
    if driver.cyclic:  # a rocking crank (double_rocker_swing) sweeps its swing, as a slider its travel
        values = case.values[0] + driver.sense * 2.0 * math.pi * np.arange(count) / count
    else:
        values = np.linspace(driver.travel[0], driver.travel[1], count)
    motion = solve(case.mechanism, values, case.positions.reference)
    return reference.relative_difference(reference.solve_reference(case.scene, values), motion)


# --- the report -----------------------------------------------------------------------------------

def markdown(rows: list[Row], orders: Mapping[str, Mapping[str, float]], vectors: Mapping[str, Mapping[str, float]]) -> str:
    lines = ["# Accuracy against run time", "",
             (f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, numpy {np.__version__}. "
             "Regenerate with `python bench/accuracy.py`."), "",
             ("Errors are relative to the 50-digit mpmath reference (`graphplan.reference`), over the quantities of the "
             "error table at each fixture's twelve positions, each divided by that quantity's largest magnitude over the "
             "twelve positions; *velocity* covers |v| of points, relative and sliding velocities and ω, *acceleration* the "
             "same for accelerations and ε. Time: best of a few runs of the method at all twelve positions."), ""]
    english = strings("en")
    for fixture in dict.fromkeys(r.fixture for r in rows):
        lines += [f"## {fixture}", "", *table_lines([r for r in rows if r.fixture == fixture], english), "",
                  order_sentence(orders.get(fixture, {}), english), ""]
    lines += ["## The analytic solver over a dense cycle (360 positions), every vector", "",
              "Largest difference from the reference, relative to the largest magnitude of its kind (angles: rad).", "",
              "| fixture | r | v | a | angle | ω | ε |", "|---|---:|---:|---:|---:|---:|---:|"]
    for fixture, worst in vectors.items():
        lines.append(f"| {fixture} | " + " | ".join(f"{worst[k]:.1e}" for k in ("r", "v", "a", "angle", "omega", "epsilon")) + " |")
    lines += ["", ("Reading the table: the analytic solver agrees with the reference to a few units of double precision, "
                  "and so does the construction (its lines of action are crossed from their own points, "
                  "graphplan.geometry.cross_lines); drafting errors follow the ruler (about the precision over the length of the "
                  "segment read); the diagrams converge as N⁻², so that reaching the construction's accuracy would need "
                  "more positions than double precision can difference."), ""]
    return "\n".join(lines)


def plot(rows: list[Row]) -> str:
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot, rcParams

    rcParams["svg.hashsalt"] = "graphplan-accuracy"
    rcParams["font.family"] = "DejaVu Sans"
    fixtures = list(dict.fromkeys(r.fixture for r in rows))
    columns = 3
    lines_ = math.ceil(len(fixtures) / columns)
    figure, axes = pyplot.subplots(lines_, columns, figsize=(12.5, 3.6 * lines_), squeeze=False)
    for plot_, fixture in zip(axes.flat, fixtures):
        draw_study(plot_, [r for r in rows if r.fixture == fixture])
        plot_.set_title(fixture.replace("_", " "), fontsize=9)
    for plot_ in axes.flat[len(fixtures):]:
        plot_.set_visible(False)
    for plot_ in axes[:, 0]:
        plot_.set_ylabel("largest relative error", fontsize=8)
    for plot_ in axes[-1, :]:
        plot_.set_xlabel("run time at twelve positions (a diagram: at its N nodes), s", fontsize=8)
    handles, names = axes.flat[0].get_legend_handles_labels()
    for plot_ in axes.flat[1:len(fixtures)]:
        for handle, name in zip(*plot_.get_legend_handles_labels()):
            if name not in names:
                handles.append(handle)
                names.append(name)
    figure.legend(handles, names, loc="lower center", ncol=len(names), fontsize=8, frameon=False)
    figure.suptitle("Error against run time (filled: accelerations, open: velocities; labels: drafting precision, diagram N)",
                    fontsize=10)
    figure.tight_layout(rect=(0, 0.04, 1, 0.97))
    out = io.StringIO()
    figure.savefig(out, format="svg", metadata={"Date": None})
    pyplot.close(figure)
    return out.getvalue()


def main(paths: list[Path] | None = None) -> list[Row]:
    rows: list[Row] = []
    orders: dict[str, dict[str, float]] = {}
    vectors: dict[str, dict[str, float]] = {}
    for path in paths or FIXTURES:
        found = study(graphplan.load(path), path.stem, extra=peer_rows)
        rows += found.rows
        orders[found.name] = dict(found.orders)
        vectors[found.name] = analytic_vectors(found.case)
        print(f"{found.name}: " + ", ".join(f"{label(r)} {r.stat('acceleration', max):.1e}" for r in found.rows), flush=True)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "accuracy.md").write_text(markdown(rows, orders, vectors), encoding="utf-8")
    (RESULTS / "accuracy.csv").write_text(csv_text(rows), encoding="utf-8")
    (RESULTS / "accuracy.svg").write_text(plot(rows), encoding="utf-8")
    print(f"wrote {RESULTS / 'accuracy.md'}, accuracy.csv, accuracy.svg")
    return rows


if __name__ == "__main__":
    main([Path(p) for p in sys.argv[1:]] or None)
