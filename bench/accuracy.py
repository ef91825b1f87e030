"""Error against run time: every way of finding velocities and accelerations, against the 50-digit reference.

    python bench/accuracy.py            # writes bench/results/accuracy.md, accuracy.csv, accuracy.svg

For every fixture, at its twelve positions (the positions of the plan method), each method's
values of the quantities of the error table (|vB|, |vBA|, sliding velocities, ω; the same for
accelerations, ε; as :func:`graphplan.check.readings` lists them off the plans) are compared with
the same quantities of the mpmath reference (``bench/reference.py``).  The relative error of a
quantity at a position is |method − reference| divided by the quantity's largest reference
magnitude over the twelve positions (a quantity that vanishes at every position, such as the
velocity of a point at a pivot, is divided by the largest of its kind instead), so that a value
passing through zero does not read as an infinite error.  The methods:

* ``analytic``: graphplan's solver (``graphplan.motion.solve``);
* ``construction``: the velocity and acceleration plans as constructed
  (``graphplan.plans.velocity_plan`` / ``acceleration_plan``), read exactly;
* ``drafting d mm``: the same plans read with a ruler to d = 1, 0.5, 0.25, 0.1 mm at the scene's
  scales (``graphplan.check.drafted``);
* ``diagram N``: kinematic diagrams, positions at N driver positions per cycle (a slider driver:
  N − 1 equal steps over its travel, N − 1 a multiple of 11) differentiated by chords: the slope at
  a position is the chord through its two neighbours, twice (displacement → velocity →
  acceleration diagram), then v = q̇·r′, a = q̇²·r″ + q̈·r′ with q the driver's coordinate;
* the peer packages of ``bench/peers.py`` where they model the same linkage (the ratchet
  four-bar, and the Stephenson six-bar as their six-bar with the fixture's dyad).

Run time is the best of a few runs of the whole method at the twelve positions (positions
included, for the plans and the diagrams the positions they need), on a shared, noisy machine.
"""

from __future__ import annotations

import csv
import io
import math
import platform
import statistics
import sys
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import reference  # noqa: E402

import graphplan  # noqa: E402
from graphplan.analysis import instant  # noqa: E402
from graphplan.check import Reading, analytic_values, drafted, readings  # noqa: E402
from graphplan.mechanism import Mechanism, build  # noqa: E402
from graphplan.motion import solve  # noqa: E402
from graphplan.plans import acceleration_plan, velocity_plan  # noqa: E402
from graphplan.positions import make_positions  # noqa: E402

FIXTURES = sorted((HERE.parent / "fixtures").glob("*.toml"))
RESULTS = HERE / "results"
PRECISIONS_MM = (1.0, 0.5, 0.25, 0.1)
DIAGRAM_COUNTS = (12, 24, 48, 96, 360, 3600)
VELOCITY_KINDS = ("V", "omega")
REPEATS = 5


@dataclass
class Row:
    fixture: str
    method: str
    parameter: str
    positions: int
    seconds: float
    errors: dict[str, list[float]] = field(default_factory=dict)   # "velocity"/"acceleration" → errors

    def stat(self, family: str, how: Callable) -> float:
        values = self.errors.get(family, [])
        return how(values) if values else math.nan


def best_time(function: Callable, repeats: int = REPEATS):
    best, result = math.inf, None
    for _ in range(repeats):
        started = time.perf_counter()
        result = function()
        best = min(best, time.perf_counter() - started)
    return best, result


# --- the quantities of the error table ------------------------------------------------------------

@dataclass(frozen=True)
class Values:
    """What a method gives at one position: point velocities and accelerations, link ω and ε."""

    v: Mapping[str, complex]
    a: Mapping[str, complex]
    omega: Mapping[int, float]
    epsilon: Mapping[int, float]


def family(quantity: str) -> str:
    kind = quantity.rstrip("0123456789") if quantity.startswith(("omega", "epsilon")) else quantity[0]
    return "velocity" if kind in VELOCITY_KINDS else "acceleration"


def kind_of(quantity: str) -> str:
    return quantity.rstrip("0123456789") if quantity.startswith(("omega", "epsilon")) else quantity[0]


def usable(table: list[Reading], values: Values) -> list[Reading]:
    """The readings a method can give: those whose points and links it knows (the peers know a few)."""
    kept = []
    for reading in table:
        kind = kind_of(reading.quantity)
        rest = reading.quantity[len(kind):]
        source = values.v if kind == "V" else values.a
        if reading.slide is not None:
            needs_links = {reading.slide.guide} - {1}
            ok = reading.slide.joint in source and (reading.slide.through is None or reading.slide.through in source)
            ok = ok and needs_links <= set(values.omega) and needs_links <= set(values.epsilon)
        elif kind in ("omega", "epsilon"):
            ok = int(rest) in (values.omega if kind == "omega" else values.epsilon)
        elif reading.points is not None:
            ok = all(name in source for name in reading.points)
        else:
            ok = rest in source
        if ok:
            kept.append(reading)
    return kept


def quantities(mechanism: Mechanism, table: list[Reading], values: Values) -> dict[str, float]:
    table = usable(table, values)
    omega = {**values.omega, mechanism.scene.frame_link: 0.0}
    epsilon = {**values.epsilon, mechanism.scene.frame_link: 0.0}
    return analytic_values(mechanism, table, values.v, values.a, omega, epsilon)


def relative_errors(got: list[dict[str, float]], exact: list[dict[str, float]]) -> dict[str, list[float]]:
    """|got − exact| over the quantity's largest exact magnitude (of its kind, if it vanishes everywhere)."""
    peak: dict[str, float] = {}
    kind_peak: dict[str, float] = {}
    for row in exact:
        for quantity, value in row.items():
            peak[quantity] = max(peak.get(quantity, 0.0), abs(value))
            kind_peak[kind_of(quantity)] = max(kind_peak.get(kind_of(quantity), 0.0), abs(value))
    out: dict[str, list[float]] = {"velocity": [], "acceleration": []}
    for row, truth in zip(got, exact):
        for quantity, value in row.items():
            scale = peak[quantity] if peak[quantity] > 1e-12 * kind_peak[kind_of(quantity)] else kind_peak[kind_of(quantity)]
            out[family(quantity)].append(abs(value - truth[quantity]) / (scale or 1.0))
    return out


# --- the fixture and its twelve positions ---------------------------------------------------------

@dataclass
class Case:
    name: str
    scene: graphplan.Scene
    mechanism: Mechanism
    values: np.ndarray
    positions: object
    tables: list[list[Reading]]
    exact: list[dict[str, float]]
    plans: list[dict]
    where: list[dict[str, complex]]


def reference_values(mechanism: Mechanism, exact: reference.ReferenceMotion, index: int) -> Values:
    at = exact.instants[index]
    return Values({n: complex(v) for n, (_, v, _) in at.points.items()},
                  {n: complex(a) for n, (_, _, a) in at.points.items()},
                  {n: float(w) for n, (_, w, _) in at.links.items()},
                  {n: float(e) for n, (_, _, e) in at.links.items()})


def prepare(path: Path) -> Case:
    scene = graphplan.load(path)
    mechanism = build(scene)
    positions = make_positions(mechanism)
    values = positions.values
    motion = solve(mechanism, values, positions.reference)
    exact = reference.solve_reference(scene, values)
    tables, truths, plans, where_all = [], [], [], []
    for index in range(len(values)):
        where, directions = instant(motion, index)
        velocity = velocity_plan(mechanism, where, directions)
        pair = {"velocity": velocity, "acceleration": acceleration_plan(mechanism, where, directions, velocity)}
        table = readings(mechanism, pair, where)
        tables.append(table)
        plans.append(pair)
        where_all.append(where)
        truths.append(quantities(mechanism, table, reference_values(mechanism, exact, index)))
    return Case(path.stem, scene, mechanism, values, positions, tables, truths, plans, where_all)


def motion_values(motion, index: int) -> Values:
    return Values({n: complex(*motion.point(n).v[index]) for n in motion.points},
                  {n: complex(*motion.point(n).a[index]) for n in motion.points},
                  {n: float(motion.link(n).omega[index]) for n in motion.links},
                  {n: float(motion.link(n).epsilon[index]) for n in motion.links})


# --- the methods ----------------------------------------------------------------------------------

def analytic(case: Case) -> Row:
    seconds, motion = best_time(lambda: solve(case.mechanism, case.values, case.positions.reference))
    got = [quantities(case.mechanism, case.tables[i], motion_values(motion, i)) for i in range(len(case.values))]
    return Row(case.name, "analytic", "", len(case.values), seconds, relative_errors(got, case.exact))


def _construct(case: Case):
    motion = solve(case.mechanism, case.values, case.positions.reference)
    built = []
    for index in range(len(case.values)):
        where, directions = instant(motion, index)
        velocity = velocity_plan(case.mechanism, where, directions)
        built.append({"velocity": velocity, "acceleration": acceleration_plan(case.mechanism, where, directions, velocity)})
    return built


def construction(case: Case) -> list[Row]:
    seconds, _ = best_time(lambda: _construct(case), 3)
    exact_reading = [{r.quantity: r.value(plans) for r in table} for plans, table in zip(case.plans, case.tables)]
    rows = [Row(case.name, "construction", "", len(case.values), seconds, relative_errors(exact_reading, case.exact))]
    for precision in PRECISIONS_MM:
        got = [{r.quantity: r.value(plans, drafted(r.millimetres(plans), precision)) for r in table}
               for plans, table in zip(case.plans, case.tables)]
        rows.append(Row(case.name, "drafting", f"{precision:g} mm", len(case.values), seconds, relative_errors(got, case.exact)))
    return rows


def diagram_grid(case: Case, count: int) -> tuple[np.ndarray, int, float]:
    """The driver's grid of a diagram with ``count`` positions per cycle, the stride to the twelve, the step."""
    driver = case.mechanism.driver
    evaluated = len(case.values)
    if driver.kind == "crank":
        stride = count // evaluated
        step = driver.sense * 2.0 * math.pi / count
        return case.values[0] + step * np.arange(count), stride, step
    stride = max(1, round((count - 1) / (evaluated - 1)))
    intervals = stride * (evaluated - 1)
    grid = np.linspace(driver.travel[0], driver.travel[1], intervals + 1)
    return grid, stride, float(grid[1] - grid[0])


def _chords(values: np.ndarray, step: float, periodic: bool, angle: bool = False) -> np.ndarray:
    """The slope at each node from the chord through its two neighbours (one-sided, second order, at a slider's ends)."""
    if periodic:
        change = np.roll(values, -1) - np.roll(values, 1)
        if angle:
            change = np.angle(np.exp(1j * change))
        return change / (2.0 * step)
    if angle:
        values = np.unwrap(values)
    return np.gradient(values, step, edge_order=2)


def _second_at_ends(second: np.ndarray, values: np.ndarray, step: float) -> np.ndarray:
    """Second-order second differences at the two nodes next to each end of a travel.

    There a chord of the (one-sided) velocity diagram would divide its O(h²) error by h: the
    acceleration diagram takes its slopes from the displacements directly instead.
    """
    if len(values) < 4:
        return second
    second = second.copy()
    second[0] = (2 * values[0] - 5 * values[1] + 4 * values[2] - values[3]) / step**2
    second[-1] = (2 * values[-1] - 5 * values[-2] + 4 * values[-3] - values[-4]) / step**2
    second[1] = (values[0] - 2 * values[1] + values[2]) / step**2
    second[-2] = (values[-1] - 2 * values[-2] + values[-3]) / step**2
    return second


def diagram(case: Case, count: int) -> Row:
    mechanism = case.mechanism
    driver = mechanism.driver
    rate, rate_rate = (driver.omega, driver.epsilon) if driver.kind == "crank" else (driver.velocity, driver.acceleration)
    grid, stride, step = diagram_grid(case, count)
    periodic = driver.kind == "crank"
    levers = [(g.new_joints()[0], g.joints[0], g.joints[1], g.links[1]) for g in mechanism.groups if g.kind == "RPR"]

    def differentiate():
        motion = solve(mechanism, grid, case.positions.reference)
        v, a, omega, epsilon = {}, {}, {}, {}
        for name in motion.points:
            xy = motion.point(name).r
            r = xy[:, 0] + 1j * xy[:, 1]
            first = _chords(r, step, periodic)
            second = _chords(first, step, periodic) if periodic else _second_at_ends(_chords(first, step, False), r, step)
            v[name], a[name] = rate * first, rate * rate * second + rate_rate * first
        for number in motion.links:
            first = _chords(np.asarray(motion.link(number).angle, dtype=float), step, periodic, angle=True)
            second = _chords(first, step, periodic)
            if not periodic:
                second = _second_at_ends(second, np.unwrap(np.asarray(motion.link(number).angle, dtype=float)), step)
            omega[number], epsilon[number] = rate * first, rate * rate * second + rate_rate * first
        for name, on, pivot, lever in levers:
            # The lever's point under the block is no path of its own: it moves rigidly with the lever.
            arm = (motion.point(on).r @ (1, 1j)) - (motion.point(pivot).r @ (1, 1j))
            v[name] = v[pivot] + 1j * omega[lever] * arm
            a[name] = a[pivot] + (1j * epsilon[lever] - omega[lever] ** 2) * arm
        return v, a, omega, epsilon

    seconds, (v, a, omega, epsilon) = best_time(differentiate, 3 if count <= 360 else 1)
    got = []
    for index in range(len(case.values)):
        node = index * stride
        values = Values({n: complex(x[node]) for n, x in v.items()}, {n: complex(x[node]) for n, x in a.items()},
                        {n: float(x[node]) for n, x in omega.items()}, {n: float(x[node]) for n, x in epsilon.items()})
        got.append(quantities(mechanism, case.tables[index], values))
    return Row(case.name, "diagram", f"N = {len(grid)}", len(grid), seconds, relative_errors(got, case.exact))


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
    """pylinkage and mechanism on the linkages bench/peers.py models: the ratchet four-bar, the Stephenson six-bar."""
    try:
        import peers
    except ImportError:  # pragma: no cover - the bench extra is missing
        return []
    models = {
        "ratchet_crank_rocker": (peers.pylinkage_fourbar, peers.mechanism_fourbar, {}, {}),
        "stephenson_six_bar": (peers.pylinkage_sixbar, peers.mechanism_sixbar,
                               {"ED": 0.40, "DF": 0.30, "F": (-0.65, -0.10), "d_side": -1}, {"D": "G"}),
    }
    if case.name not in models:
        return []
    pylinkage, mech, dyad, rename = models[case.name]
    angles = np.asarray(case.values, dtype=float)
    rows = []
    for label, run, repeats in (("pylinkage", lambda: pylinkage(angles, **dyad, kinematics=True, fast=False), REPEATS),
                                ("mechanism", lambda: mech(angles, **dyad, kinematics=True), 3)):
        try:
            run()  # warm-up: imports
            seconds, result = best_time(run, repeats)
        except Exception as error:  # noqa: BLE001 - a peer's failure is a result to report, not a crash
            print(f"  {label} failed on {case.name}: {error}")
            continue
        got = [quantities(case.mechanism, case.tables[i], _peer_values(result, i, rename)) for i in range(len(angles))]
        exact = [{q: row[q] for q in mine} for row, mine in zip(case.exact, got)]
        rows.append(Row(case.name, label, "peer", len(angles), seconds, relative_errors(got, exact)))
    return rows


# --- the whole-vector check of the analytic solver ------------------------------------------------

def analytic_vectors(case: Case, count: int = 360) -> dict[str, float]:
    """graphplan against the reference over a dense cycle: every point's r, v, a and every link's angle, ω, ε."""
    driver = case.mechanism.driver
    if driver.kind == "crank":
        values = case.values[0] + driver.sense * 2.0 * math.pi * np.arange(count) / count
    else:
        values = np.linspace(driver.travel[0], driver.travel[1], count)
    motion = solve(case.mechanism, values, case.positions.reference)
    return reference.relative_difference(reference.solve_reference(case.scene, values), motion)


# --- the report -----------------------------------------------------------------------------------

def observed_orders(rows: list[Row]) -> dict[str, float]:
    """The slope of log(error) against log(N) over the diagrams with N ≥ 24, per family (least squares)."""
    out = {}
    diagrams = [r for r in rows if r.method == "diagram" and r.positions >= 24]
    for fam in ("velocity", "acceleration"):
        points = [(math.log(r.positions), math.log(r.stat(fam, max))) for r in diagrams if r.stat(fam, max) > 0]
        if len(points) >= 2:
            x, y = np.array(points).T
            out[fam] = float(-np.polyfit(x, y, 1)[0])
    return out


def label(row: Row) -> str:
    return row.method + (f" {row.parameter}" if row.parameter and row.parameter != "peer" else "")


def markdown(rows: list[Row], orders: Mapping[str, Mapping[str, float]], vectors: Mapping[str, Mapping[str, float]]) -> str:
    lines = ["# Accuracy against run time", "",
             (f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, numpy {np.__version__}. "
             "Regenerate with `python bench/accuracy.py`."), "",
             ("Errors are relative to the 50-digit mpmath reference (`bench/reference.py`), over the quantities of the "
             "error table at each fixture's twelve positions, each divided by that quantity's largest magnitude over the "
             "twelve positions; *velocity* covers |v| of points, relative and sliding velocities and ω, *acceleration* the "
             "same for accelerations and ε. Time: best of a few runs of the method at all twelve positions."), ""]
    for fixture in dict.fromkeys(r.fixture for r in rows):
        lines += [f"## {fixture}", "", "| method | positions | time, s | velocity: largest | median | acceleration: largest | median |",
                  "|---|---:|---:|---:|---:|---:|---:|"]
        for row in (r for r in rows if r.fixture == fixture):
            lines.append(f"| {label(row)} | {row.positions} | {row.seconds:.2e} | {row.stat('velocity', max):.1e} | "
                         f"{row.stat('velocity', statistics.median):.1e} | {row.stat('acceleration', max):.1e} | "
                         f"{row.stat('acceleration', statistics.median):.1e} |")
        order = orders.get(fixture, {})
        lines += ["", (f"Observed order of convergence of the diagrams (N ≥ 24): velocity {order.get('velocity', math.nan):.2f}, "
                       f"acceleration {order.get('acceleration', math.nan):.2f} (chords through the two neighbours: 2 expected)."),
                  ""]
    lines += ["## The analytic solver over a dense cycle (360 positions), every vector", "",
              "Largest difference from the reference, relative to the largest magnitude of its kind (angles: rad).", "",
              "| fixture | r | v | a | angle | ω | ε |", "|---|---:|---:|---:|---:|---:|---:|"]
    for fixture, worst in vectors.items():
        lines.append(f"| {fixture} | " + " | ".join(f"{worst[k]:.1e}" for k in ("r", "v", "a", "angle", "omega", "epsilon")) + " |")
    lines += ["", ("Reading the table: the analytic solver agrees with the reference to a few units of double precision, "
                  "the construction to about a thousand (its lines of action are crossed as segments drawn a thousand "
                  "times the figure's size long, graphplan.geometry); drafting errors follow the ruler (about the precision over the length of the "
                  "segment read); the diagrams converge as N⁻², so that reaching the construction's accuracy would need "
                  "more positions than double precision can difference."), ""]
    return "\n".join(lines)


def write_csv(rows: list[Row]) -> str:
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["fixture", "method", "parameter", "positions", "seconds", "velocity_max", "velocity_median",
                     "acceleration_max", "acceleration_median"])
    for row in rows:
        writer.writerow([row.fixture, row.method, row.parameter, row.positions, f"{row.seconds:.4e}",
                         *(f"{row.stat(f, how):.4e}" for f in ("velocity", "acceleration") for how in (max, statistics.median))])
    return out.getvalue()


STYLE = {"analytic": ("*", "black"), "construction": ("o", "#1f5fa8"), "drafting": ("s", "#d9822b"),
         "diagram": ("^", "#2e8b3d"), "pylinkage": ("D", "#b0306b"), "mechanism": ("P", "#6b3fa0")}
FLOOR = 1e-17


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
        mine = [r for r in rows if r.fixture == fixture]
        for method, (marker, colour) in STYLE.items():
            chosen = [r for r in mine if r.method == method]
            if not chosen:
                continue
            x = [r.seconds for r in chosen]
            for fam, fill in (("acceleration", colour), ("velocity", "none")):
                y = [max(r.stat(fam, max), FLOOR) for r in chosen]
                plot_.plot(x, y, marker=marker, color=colour, markerfacecolor=fill, linestyle="-" if len(chosen) > 1 else "none",
                           linewidth=0.8, markersize=6, label=method if fam == "acceleration" else None)
            for r in chosen:
                # A few labels only: the drafting points share one run time, the small diagrams nearly so.
                if r.parameter in ("1 mm", "0.1 mm") or (r.method == "diagram" and r.positions in (12, 360)) or (
                        r.method == "diagram" and r.positions > 1000):
                    plot_.annotate(r.parameter.replace("N = ", ""), (r.seconds, max(r.stat("acceleration", max), FLOOR)),
                                   textcoords="offset points", xytext=(4, 3), fontsize=6, color=colour)
        plot_.set_xscale("log")
        plot_.set_yscale("log")
        plot_.set_title(fixture.replace("_", " "), fontsize=9)
        plot_.set_ylim(FLOOR / 3, 3.0)
        plot_.grid(True, which="major", linewidth=0.3)
        plot_.tick_params(labelsize=7)
    for plot_ in axes.flat[len(fixtures):]:
        plot_.set_visible(False)
    for plot_ in axes[:, 0]:
        plot_.set_ylabel("largest relative error", fontsize=8)
    for plot_ in axes[-1, :]:
        plot_.set_xlabel("run time at twelve positions, s", fontsize=8)
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
        case = prepare(path)
        mine = [analytic(case), *construction(case), *(diagram(case, n) for n in DIAGRAM_COUNTS), *peer_rows(case)]
        rows += mine
        orders[case.name] = observed_orders(mine)
        vectors[case.name] = analytic_vectors(case)
        print(f"{case.name}: " + ", ".join(f"{label(r)} {r.stat('acceleration', max):.1e}" for r in mine), flush=True)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "accuracy.md").write_text(markdown(rows, orders, vectors), encoding="utf-8")
    (RESULTS / "accuracy.csv").write_text(write_csv(rows), encoding="utf-8")
    (RESULTS / "accuracy.svg").write_text(plot(rows), encoding="utf-8")
    print(f"wrote {RESULTS / 'accuracy.md'}, accuracy.csv, accuracy.svg")
    return rows


if __name__ == "__main__":
    main([Path(p) for p in sys.argv[1:]] or None)
