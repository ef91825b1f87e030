"""How exact each way of finding velocities and accelerations is, and what it costs.

At a scene's positions (the positions of the plan method), each method's values of the
quantities of the error table (|vB|, |vBA|, sliding velocities, ω; the same for accelerations,
ε; as :func:`graphplan.check.readings` lists them off the plans) are compared with the same
quantities of the 50-digit reference (:mod:`graphplan.reference`).  The relative error of a
quantity at a position is |method − reference| divided by the quantity's largest reference
magnitude over the positions (a quantity that vanishes at every position, such as the velocity
of a point at a pivot, is divided by the largest of its kind instead), so that a value passing
through zero does not read as an infinite error.  The methods:

* ``analytic``: graphplan's solver (:func:`graphplan.motion.solve`);
* ``construction``: the velocity and acceleration plans as constructed, read exactly;
* ``drafting d mm``: the same plans read with a ruler to d = 1, 0.5, 0.25, 0.1 mm at the scene's
  scales (:func:`graphplan.check.drafted`), and to the scene's own ``[drawing] drafting_precision``
  among them where it is none of these (its row marked ``own``);
* ``diagram N``: kinematic diagrams at N driver positions per cycle (a slider driver: N − 1
  equal steps over its travel, a multiple of the intervals between the positions) differentiated
  by chords as ``kinematic_diagrams`` draws them: the velocity diagram's ordinates stand at the
  mid-intervals, so the slope at a position is the mean of the two chords beside it (the chord
  through its two neighbours); the acceleration at a position is the chord of those two slopes,
  the second difference over one step either side (one-sided at a travel's ends), then
  v = q̇·r′, a = q̇²·r″ + q̈·r′ with q the driver's coordinate.

Run time is the best of a few runs of the whole method at all the positions (the positions
included; for the diagrams, the positions they need).  It is measured, so it differs from run to run.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from . import reference
from .analysis import instant
from .check import Reading, analytic_values, drafted, readings
from .errors import GraphplanError
from .geometry import ParallelLinesError
from .mechanism import Mechanism, build
from .motion import solve
from .plans import acceleration_plan, velocity_plan
from .positions import PositionSet, make_positions
from .scene import Scene

PRECISIONS_MM = (1.0, 0.5, 0.25, 0.1)
# Diagram nodes per interval between two positions: at twelve positions a cycle, N = 12 … 3600.
DIAGRAM_REFINEMENTS = (1, 2, 4, 8, 30, 300)
# A finer diagram than this would take longer than the rest of the study together.
MOST_DIAGRAM_NODES = 4000
VELOCITY_KINDS = ("V", "omega")
REPEATS = 5


@dataclass
class Row:
    """One method's errors at the positions, and its run time.

    ``own`` marks the drafting row read to the scene's own ``drafting_precision``: the one a student's plans
    are read to.
    """

    fixture: str
    method: str
    parameter: str
    positions: int
    seconds: float
    errors: dict[str, list[float]] = field(default_factory=dict)   # "velocity"/"acceleration" → errors
    own: bool = False

    def stat(self, family: str, how: Callable) -> float:
        values = self.errors.get(family, [])
        return how(values) if values else math.nan


def drafting_precisions(scene: Scene) -> tuple[tuple[float, bool], ...]:
    """The precisions the plans are read to, coarsest first, each with whether it is the scene's own.

    The standard :data:`PRECISIONS_MM` and the scene's ``[drawing] drafting_precision`` in its place among
    them; a scene's precision equal to a standard one marks that one instead of adding a second row.
    """
    own = scene.drawing.drafting_precision
    standard = [(precision, math.isclose(precision, own, rel_tol=1e-9)) for precision in PRECISIONS_MM]
    if any(mine for _, mine in standard):
        return tuple(standard)
    return tuple(sorted([*standard, (own, True)], key=lambda pair: -pair[0]))


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


# --- the scene and its positions -----------------------------------------------------------------

@dataclass
class Case:
    """A scene at its positions: the plans, the quantities they give, and the reference's values of them.

    ``left_out`` maps the index of a position where no plan can be constructed (its lines of action
    too near parallel, though the analytic solution exists) to its number and driver coordinate;
    every method skips it.
    """

    name: str
    scene: Scene
    mechanism: Mechanism
    values: np.ndarray
    positions: PositionSet
    tables: list[list[Reading]]
    exact: list[dict[str, float]]
    plans: list[dict | None]
    where: list[dict[str, complex]]
    left_out: dict[int, str] = field(default_factory=dict)

    @property
    def compared(self) -> list[int]:
        """The indices of the positions every method is compared at: those not left out."""
        return [index for index in range(len(self.values)) if index not in self.left_out]


class AccuracyError(GraphplanError, ArithmeticError):
    """The scene's positions have no 50-digit reference (a toggle the reference cannot solve)."""


def reference_values(mechanism: Mechanism, exact: reference.ReferenceMotion, index: int) -> Values:
    at = exact.instants[index]
    return Values({n: complex(v) for n, (_, v, _) in at.points.items()},
                  {n: complex(a) for n, (_, _, a) in at.points.items()},
                  {n: float(w) for n, (_, w, _) in at.links.items()},
                  {n: float(e) for n, (_, _, e) in at.links.items()})


def prepare(scene: Scene, name: str) -> Case:
    mechanism = build(scene)
    positions = make_positions(mechanism)
    values = positions.values
    motion = solve(mechanism, values, positions.reference)
    try:
        exact = reference.solve_reference(scene, values)
    except reference.ReferenceSolutionError as error:
        raise AccuracyError(f"no 50-digit reference of the positions: {error}") from None
    case = Case(name, scene, mechanism, values, positions, [], [], [], [])
    for index in range(len(values)):
        where, directions = instant(motion, index)
        case.where.append(where)
        try:
            pair = _plans_at(mechanism, where, directions)
        except ParallelLinesError:
            number = positions.numbers[index]
            case.left_out[index] = f"{number} ({mechanism.driver.describe(float(values[index]))})"
            pair, table = None, []
        else:
            table = readings(mechanism, pair, where)
        case.plans.append(pair)
        case.tables.append(table)
        case.exact.append(quantities(mechanism, table, reference_values(mechanism, exact, index)))
    return case


def _plans_at(mechanism: Mechanism, where: dict[str, complex], directions: dict[int, complex]) -> dict:
    velocity = velocity_plan(mechanism, where, directions)
    return {"velocity": velocity, "acceleration": acceleration_plan(mechanism, where, directions, velocity)}


def motion_values(motion, index: int) -> Values:
    return Values({n: complex(*motion.point(n).v[index]) for n in motion.points},
                  {n: complex(*motion.point(n).a[index]) for n in motion.points},
                  {n: float(motion.link(n).omega[index]) for n in motion.links},
                  {n: float(motion.link(n).epsilon[index]) for n in motion.links})


# --- the methods ----------------------------------------------------------------------------------

def analytic(case: Case) -> Row:
    compared = case.compared
    values = case.values[compared]
    seconds, motion = best_time(lambda: solve(case.mechanism, values, case.positions.reference))
    got = [quantities(case.mechanism, case.tables[index], motion_values(motion, k)) for k, index in enumerate(compared)]
    return Row(case.name, "analytic", "", len(compared), seconds,
               relative_errors(got, [case.exact[index] for index in compared]))


def _construct(case: Case):
    motion = solve(case.mechanism, case.values, case.positions.reference)
    return [_plans_at(case.mechanism, *instant(motion, index)) for index in case.compared]


def construction(case: Case) -> list[Row]:
    seconds, _ = best_time(lambda: _construct(case), 3)
    compared = case.compared
    drawn = [(case.plans[index], case.tables[index]) for index in compared]
    exact = [case.exact[index] for index in compared]
    exact_reading = [{r.quantity: r.value(plans) for r in table} for plans, table in drawn]
    rows = [Row(case.name, "construction", "", len(compared), seconds, relative_errors(exact_reading, exact))]
    for precision, own in drafting_precisions(case.scene):
        got = [{r.quantity: r.value(plans, drafted(r.millimetres(plans), precision)) for r in table} for plans, table in drawn]
        rows.append(Row(case.name, "drafting", f"{precision:g} mm", len(compared), seconds, relative_errors(got, exact),
                        own))
    return rows


def diagram_grid(case: Case, refinement: int) -> np.ndarray:
    """The driver's grid of a diagram with ``refinement`` nodes per interval between positions.

    Every position is a node of it, at index ``refinement × its index``.
    """
    driver = case.mechanism.driver
    evaluated = len(case.values)
    if driver.cyclic:
        count = refinement * evaluated
        return case.values[0] + driver.sense * 2.0 * math.pi / count * np.arange(count)
    return np.linspace(driver.travel[0], driver.travel[1], refinement * (evaluated - 1) + 1)


def diagram_refinements(case: Case) -> tuple[int, ...]:
    """The refinements the study runs: those within :data:`MOST_DIAGRAM_NODES` nodes."""
    intervals = len(case.values) - (0 if case.mechanism.driver.cyclic else 1)
    return tuple(m for m in DIAGRAM_REFINEMENTS if m == 1 or m * intervals <= MOST_DIAGRAM_NODES)


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


def _second_chords(values: np.ndarray, step: float, periodic: bool, angle: bool = False) -> np.ndarray:
    """The second derivative at each node as the acceleration diagram draws it: the chord between the slopes of
    the two intervals beside the node, (y₊ − 2y + y₋)/h².

    Differentiating the neighbours' chords again spans two steps either side and errs four times as much
    (h²·y⁗/3 against h²·y⁗/12): at 12 positions it put 14 % beside the 3.7 % the diagram itself draws. At a
    travel's ends, where the diagram has no chord beyond, a one-sided second-order difference.
    """
    if periodic:
        ahead, behind = np.roll(values, -1) - values, values - np.roll(values, 1)
        if angle:
            ahead, behind = np.angle(np.exp(1j * ahead)), np.angle(np.exp(1j * behind))
        return (ahead - behind) / step**2
    if angle:
        values = np.unwrap(values)
    second = np.empty_like(values)
    second[1:-1] = (values[2:] - 2 * values[1:-1] + values[:-2]) / step**2
    if len(values) >= 4:
        second[0] = (2 * values[0] - 5 * values[1] + 4 * values[2] - values[3]) / step**2
        second[-1] = (2 * values[-1] - 5 * values[-2] + 4 * values[-3] - values[-4]) / step**2
    else:
        second[0], second[-1] = second[1], second[-2]
    return second


def diagram(case: Case, refinement: int) -> Row:
    mechanism = case.mechanism
    driver = mechanism.driver
    rate, rate_rate = driver.coordinate_speed, driver.coordinate_acceleration
    grid = diagram_grid(case, refinement)
    step = float(grid[1] - grid[0])
    periodic = driver.cyclic
    under_pins = [point for group in mechanism.groups for point in group.coincident_points()]

    def differentiate():
        motion = solve(mechanism, grid, case.positions.reference)
        v, a, omega, epsilon = {}, {}, {}, {}
        for name in motion.points:
            xy = motion.point(name).r
            r = xy[:, 0] + 1j * xy[:, 1]
            first, second = _chords(r, step, periodic), _second_chords(r, step, periodic)
            v[name], a[name] = rate * first, rate * rate * second + rate_rate * first
        for number in motion.links:
            angle = np.asarray(motion.link(number).angle, dtype=float)
            first, second = _chords(angle, step, periodic, angle=True), _second_chords(angle, step, periodic, angle=True)
            omega[number], epsilon[number] = rate * first, rate * rate * second + rate_rate * first
        for name, on, pivot, lever in under_pins:
            # A link's point under a block is no path of its own: it moves rigidly with the link.
            arm = (motion.point(on).r @ (1, 1j)) - (motion.point(pivot).r @ (1, 1j))
            v[name] = v[pivot] + 1j * omega[lever] * arm
            a[name] = a[pivot] + (1j * epsilon[lever] - omega[lever] ** 2) * arm
        return v, a, omega, epsilon

    seconds, (v, a, omega, epsilon) = best_time(differentiate, 3 if len(grid) <= 360 else 1)
    got = []
    for index in case.compared:
        node = index * refinement
        values = Values({n: complex(x[node]) for n, x in v.items()}, {n: complex(x[node]) for n, x in a.items()},
                        {n: float(x[node]) for n, x in omega.items()}, {n: float(x[node]) for n, x in epsilon.items()})
        got.append(quantities(mechanism, case.tables[index], values))
    return Row(case.name, "diagram", f"N = {len(grid)}", len(grid), seconds,
               relative_errors(got, [case.exact[index] for index in case.compared]))


# --- the study of one scene -----------------------------------------------------------------------

@dataclass(frozen=True)
class Study:
    """Every method's row for one scene, and the diagrams' observed order of convergence per family."""

    case: Case
    rows: tuple[Row, ...]
    orders: Mapping[str, float]

    @property
    def name(self) -> str:
        return self.case.name


def study(scene: Scene, name: str = "scene", extra: Callable[[Case], list[Row]] | None = None) -> Study:
    """The analytic solver, the construction, the drafted plans and the diagrams of ``scene`` against the reference.

    ``extra`` adds rows of other methods (the bench's peer packages) from the prepared case.
    """
    case = prepare(scene, name)
    rows = [analytic(case), *construction(case), *(diagram(case, m) for m in diagram_refinements(case))]
    if extra is not None:
        rows += extra(case)
    return Study(case, tuple(rows), observed_orders(rows))


STYLE = {"analytic": ("*", "black"), "construction": ("o", "#1f5fa8"), "drafting": ("s", "#d9822b"),
         "diagram": ("^", "#2e8b3d"), "pylinkage": ("D", "#b0306b"), "mechanism": ("P", "#6b3fa0")}
# Errors below this are drawn at it: an exact zero has no place on a log scale.
FLOOR = 1e-17


def draw_study(axes, rows: list[Row] | tuple[Row, ...], millimetre: str = "mm",
               names: Mapping[str, str] | None = None, own_tag: str = "{tag} (initial data)") -> None:
    """Error against run time of one scene's rows on matplotlib ``axes`` (log-log; filled: accelerations).

    A few points are tagged with their drafting precision (in ``millimetre``) or the diagram's N;
    ``names`` gives the legend's word for a method (its own name where it gives none).  The drafting row
    read to the scene's own precision (:attr:`Row.own`) has its acceleration's point ringed and its tag written by
    ``own_tag`` (``{tag}`` is the precision).
    """
    from matplotlib.ticker import LogFormatterSciNotation, LogLocator, NullFormatter

    for method, (marker, colour) in STYLE.items():
        chosen = [r for r in rows if r.method == method]
        if not chosen:
            continue
        x = [r.seconds for r in chosen]
        for fam, fill in (("acceleration", colour), ("velocity", "none")):
            y = [max(r.stat(fam, max), FLOOR) for r in chosen]
            axes.plot(x, y, marker=marker, color=colour, markerfacecolor=fill, linestyle="-" if len(chosen) > 1 else "none",
                      linewidth=0.8, markersize=6, label=(names or {}).get(method, method) if fam == "acceleration" else None)
        for r in chosen:
            at = (r.seconds, max(r.stat("acceleration", max), FLOOR))
            if r.own:
                # Ringed at the acceleration, where the tags are: a second ring round its velocity's point ran into it.
                axes.plot(*at, marker="o", markersize=11, markerfacecolor="none", markeredgecolor=colour,
                          markeredgewidth=0.8, linestyle="none", gid="own-precision")
            # A few labels only: the drafting points share one run time, the small diagrams nearly so.
            tagged = r.parameter in ("1 mm", "0.1 mm") or (r.method == "diagram" and (r.positions in (12, 360) or r.positions > 1000))
            if not (tagged or r.own):
                continue
            tag = r.parameter.replace("N = ", "").replace(" mm", f" {millimetre}")
            if r.own:
                tag = own_tag.format(tag=tag)
            if tagged:
                # The finest drafting's tag under its point: read to 1 and 0.1 mm alike (a scotch yoke's segment
                # rounds the same), the two tags stood one on the other.
                below = r.parameter == "0.1 mm"
                axes.annotate(tag, at, textcoords="offset points", xytext=(4, -8 if below else 3), fontsize=6, color=colour)
            else:
                # The scene's own precision between the standard ones: its tag left of its point, clear of their tags.
                axes.annotate(tag, at, textcoords="offset points", xytext=(-7, -2), fontsize=6, color=colour,
                              horizontalalignment="right")
    axes.set_xscale("log")
    axes.set_yscale("log")
    # Ticks at 1 and 3 of each decade, labelled: the times span a decade or two, where powers of ten alone left one
    # labelled tick; matplotlib's own minor labels ran into each other.
    axes.xaxis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 3.0)))
    axes.xaxis.set_major_formatter(LogFormatterSciNotation(labelOnlyBase=False))
    axes.xaxis.set_minor_formatter(NullFormatter())
    axes.set_ylim(FLOOR / 3, 3.0)
    axes.grid(True, which="major", linewidth=0.3)
    axes.tick_params(labelsize=7)


def observed_orders(rows: list[Row] | tuple[Row, ...]) -> dict[str, float]:
    """The order of convergence of the diagrams per family: the slope of log(error) against log(N) between the two
    finest grids.

    An order is what the error does as the step goes to nought: the finest pair shows it. A fit over the coarser
    grids too took in chords too long for the error's leading term to rule, and wrote 1.74 for the double
    rocker's acceleration beside "order 2", its finest pair's 2.0.
    """
    out = {}
    diagrams = sorted((r for r in rows if r.method == "diagram"), key=lambda r: r.positions)
    for fam in ("velocity", "acceleration"):
        points = [(r.positions, r.stat(fam, max)) for r in diagrams if r.stat(fam, max) > 0]
        if len(points) >= 2:
            (coarse, coarse_error), (fine, fine_error) = points[-2:]
            out[fam] = math.log(coarse_error / fine_error) / math.log(fine / coarse)
    return out


def label(row: Row) -> str:
    return row.method + (f" {row.parameter}" if row.parameter and row.parameter != "peer" else "")
