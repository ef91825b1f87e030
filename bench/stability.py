"""Stiff and extreme cases: the observed error against the reference beside the condition number graphplan computed.

    python bench/stability.py           # writes bench/results/stability.md

Each scene of ``bench/extreme/`` is run as ``graphplan run`` runs it (:func:`graphplan.analysis.analyse`),
then, at every position that is not singular, the analytic solution and the plans constructed there
are compared with the 50-digit reference (``graphplan/reference.py``).  The error of a position is
normwise: the largest difference over all points' velocities and all links' ω·L (L the size of the
mechanism at that position), over the largest of the same reference values; the same for
accelerations (a, ε·L).  The condition number is graphplan's own: κ = 1/sin θ with θ the angle at
which a group's lines of action cross (``Motion.conditioning``, the analytic solver; the
``crossing_deg`` of the plans' steps, the construction).

A position passes when its error is within ``BOUND`` × κ × ε_machine (velocities) or
``BOUND`` × κ² × ε_machine (accelerations: their right-hand side carries ω², itself found with
error κ·ε), or when graphplan warned of it ("ill-conditioned" or "singular"); a scene passes
when every position does, or when graphplan refused it with one clear error.  Nothing may be NaN.
"""

from __future__ import annotations

import math
import platform
import sys
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

import graphplan
from graphplan import reference
from graphplan.analysis import analyse, instant
from graphplan.errors import GraphplanError
from graphplan.geometry import ParallelLinesError
from graphplan.plans import acceleration_plan, velocity_plan

HERE = Path(__file__).resolve().parent

EXTREME = HERE / "extreme"
RESULTS = HERE / "results"
EPS = float(np.finfo(float).eps)
# How many units of κ·ε a result may be off: a few roundings in the position, the two-line solve and the
# named points' placement each add one.
BOUND = 64.0
# The construction crosses lines drawn out to this many times the figure's size on each side
# (graphplan.geometry), so its crossings carry that many more units of rounding.
REACH = 1e3
# Driver positions sampled between two analysed positions to see whether a group passes a toggle there.
BETWEEN = 200


@dataclass
class PositionRow:
    number: int
    driver: str
    kappa: float                      # analytic: 1 / smallest sine of any group's lines of action
    velocity_error: float
    acceleration_error: float
    plan_kappa: float | None = None   # construction: 1 / sine of its smallest crossing
    plan_velocity_error: float | None = None
    plan_acceleration_error: float | None = None
    warnings: list[str] = field(default_factory=list)
    singular: bool = False
    exact_singular: bool = False      # graphplan solved it, but the 50-digit geometry is singular there

    def within(self) -> bool:
        """Whether the errors are within the bound of their condition numbers."""
        ok = (self.velocity_error <= BOUND * self.kappa * EPS
              and self.acceleration_error <= BOUND * self.kappa ** 2 * EPS)
        if self.plan_kappa is not None:
            ok = ok and (self.plan_velocity_error <= BOUND * REACH * self.plan_kappa * EPS
                         and self.plan_acceleration_error <= BOUND * REACH * self.plan_kappa ** 2 * EPS)
        return ok

    @property
    def verdict(self) -> str:
        if self.singular:
            return "singular: warned"
        if self.exact_singular:
            return "exactly singular, " + ("warned" if self.warnings else "SILENT")
        if self.within():
            return "within bound" + (" (warned)" if self.warnings else "")
        return "outside bound, warned" if self.warnings else "OUTSIDE BOUND, SILENT"


@dataclass(frozen=True)
class Passage:
    """A group passing close to a toggle between two analysed positions (where the branch may change)."""

    after: int
    before: int
    at: str
    sine: float
    warned: bool
    at_position: int | None = None   # the number of the position the toggle lies at, where the dip runs on to it


@dataclass
class SceneReport:
    name: str
    title: str
    note: str
    error: str | None = None
    rows: list[PositionRow] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    nan: bool = False
    passages: list[Passage] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        if self.error is not None:
            return "\n" not in self.error and bool(self.error.strip())
        return (not self.nan and all("SILENT" not in row.verdict for row in self.rows)
                and all(passage.warned for passage in self.passages))


def _note(path: Path) -> str:
    """The scene's own description: its comment block after the first line."""
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines()[2:]:
        if not line.startswith("#"):
            break
        lines.append(line.lstrip("# ").strip())
    return " ".join(lines).replace("Stiff or extreme case for bench/stability.py (not a textbook mechanism): ", "")


def normwise(got: dict, exact: dict) -> float:
    """max |got − exact| / max |exact| over the keys of ``exact``."""
    scale = max(abs(value) for value in exact.values())
    worst = max(abs(got[key] - value) for key, value in exact.items())
    if scale == 0:
        return 0.0 if worst == 0 else math.inf
    return worst / scale


def _exact(instant_, size: float) -> tuple[dict, dict]:
    velocity = {("v", n): complex(v) for n, (_, v, _) in instant_.points.items()}
    velocity |= {("w", n): float(w) * size for n, (_, w, _) in instant_.links.items()}
    acceleration = {("a", n): complex(a) for n, (_, _, a) in instant_.points.items()}
    acceleration |= {("e", n): float(e) * size for n, (_, _, e) in instant_.links.items()}
    return velocity, acceleration


def _size(where: dict[str, complex]) -> float:
    values = list(where.values())
    return max(abs(a - b) for a in values for b in values) or 1.0


def _analytic(motion, index: int, size: float) -> tuple[dict, dict]:
    velocity = {("v", n): complex(*motion.point(n).v[index]) for n in motion.points}
    velocity |= {("w", n): float(motion.link(n).omega[index]) * size for n in motion.links}
    acceleration = {("a", n): complex(*motion.point(n).a[index]) for n in motion.points}
    acceleration |= {("e", n): float(motion.link(n).epsilon[index]) * size for n in motion.links}
    return velocity, acceleration


def _constructed(mechanism, motion, index: int, size: float):
    """The plans at one position, their values in the form of :func:`_exact`, and 1/sin of their shallowest crossing."""
    where, directions = instant(motion, index)
    velocity = velocity_plan(mechanism, where, directions)
    acceleration = acceleration_plan(mechanism, where, directions, velocity)
    crossings = [step.crossing_deg for plan in (velocity, acceleration) for step in plan.steps if step.crossing_deg is not None]
    kappa = 1.0 / math.sin(math.radians(min(crossings))) if crossings else 1.0
    values_v = {("v", n): velocity.value(n) for n in motion.points if n in velocity.images}
    values_v |= {("w", n): velocity.rates[n] * size for n in velocity.rates}
    values_a = {("a", n): acceleration.value(n) for n in motion.points if n in acceleration.images}
    values_a |= {("e", n): acceleration.rates[n] * size for n in acceleration.rates}
    return values_v, values_a, kappa


def _has_nan(analysis) -> bool:
    """Whether results.json would carry a NaN (it writes null for an undetermined value instead)."""
    from graphplan.report.results import dumps, results

    try:
        dumps(results(analysis))
    except ValueError:
        return True
    return False


def passages(analysis) -> list[Passage]:
    """Where the lines of action of a group come within graphplan's ill-conditioned angle between two positions.

    The driver's interval from each analysed position to the next (for a crank, round to the first
    again) is sampled at :data:`BETWEEN` points; a dip below sin 1° there is a toggle the analysed
    positions step over, where the assembly can change branch.  It counts as warned when graphplan
    warned of either position beside it.
    """
    from graphplan.motion import ILL_CONDITIONED_DEG, solve

    mechanism, values = analysis.mechanism, analysis.positions.values
    ends = list(values)
    if mechanism.driver.kind == "crank":
        ends.append(values[0] + mechanism.driver.sense * 2.0 * math.pi)
    limit = math.sin(math.radians(ILL_CONDITIONED_DEG))
    warned = {w.position for w in analysis.warnings}
    own = (np.min(np.array([np.abs(c) for c in analysis.motion.conditioning.values()]), axis=0)
           if analysis.motion.conditioning else None)
    numbers = analysis.positions.numbers
    found, at_positions = [], set()
    for k in range(len(ends) - 1):
        inside = np.linspace(ends[k], ends[k + 1], BETWEEN + 2)[1:-1]
        with np.errstate(all="ignore"):
            motion = solve(mechanism, inside, analysis.positions.reference, tolerant=True)
        if not motion.conditioning:
            continue
        sine = np.min(np.array([np.abs(c) for c in motion.conditioning.values()]), axis=0)
        worst = int(np.argmin(sine))
        if sine[worst] < limit:
            after, before = k, (k + 1) % len(values)
            # A dip that runs on to a position nearer parallel still is the toggle at that position (the
            # change point's 180°), not one stepped over: once, as that position's.
            end = {0: after, len(inside) - 1: before}.get(worst)
            if end is not None and own is not None and own[end] <= sine[worst]:
                if end not in at_positions:
                    at_positions.add(end)
                    found.append(Passage(int(numbers[after]), int(numbers[before]),
                                         mechanism.driver.describe(float(values[end])), float(own[end]),
                                         end in warned, int(numbers[end])))
                continue
            found.append(Passage(int(numbers[after]), int(numbers[before]), mechanism.driver.describe(float(inside[worst])),
                                 float(sine[worst]), after in warned or before in warned))
    return found


def study(path: Path) -> SceneReport:
    scene = graphplan.load(path)
    report = SceneReport(path.stem, scene.title, _note(path))
    try:
        analysis = analyse(scene)
    except GraphplanError as error:
        report.error = str(error)
        return report
    mechanism, motion = analysis.mechanism, analysis.motion
    report.nan = _has_nan(analysis)
    numbers = analysis.positions.numbers
    report.warnings = [f"position {numbers[w.position]}: {w.code}: {w.detail}" for w in analysis.warnings]
    report.passages = passages(analysis)
    regular = [i for i in range(motion.count) if i not in motion.singular]
    exact = {}
    for i in regular:
        try:
            exact[i] = reference.solve_reference(scene, analysis.positions.values[i:i + 1]).instants[0]
        except reference.ReferenceSolutionError as error:
            exact[i] = error
    sines = np.min(np.array([np.abs(c) for c in motion.conditioning.values()]), axis=0) if motion.conditioning else np.ones(motion.count)
    for i in range(motion.count):
        warned = [w.detail for w in analysis.warnings if w.position == i]
        described = mechanism.driver.describe(float(analysis.positions.values[i]))
        if i in motion.singular:
            report.rows.append(PositionRow(int(numbers[i]), described, math.inf, math.nan, math.nan, warnings=warned, singular=True))
            continue
        instant_ = exact[i]
        if isinstance(instant_, reference.ReferenceSolutionError):
            # The exact geometry of the scene's numbers is singular here: no velocity exists to compare with.
            report.rows.append(PositionRow(int(numbers[i]), described, 1.0 / float(sines[i]), math.nan, math.nan,
                                           warnings=warned, singular=False, exact_singular=True))
            continue
        where, _ = instant(motion, i)
        size = _size(where)
        truth_v, truth_a = _exact(instant_, size)
        got_v, got_a = _analytic(motion, i, size)
        row = PositionRow(int(numbers[i]), described, 1.0 / float(sines[i]),
                          normwise(got_v, truth_v), normwise(got_a, truth_a), warnings=warned)
        try:
            plan_v, plan_a, row.plan_kappa = _constructed(mechanism, motion, i, size)
            row.plan_velocity_error = normwise(plan_v, {k: truth_v[k] for k in plan_v})
            row.plan_acceleration_error = normwise(plan_a, {k: truth_a[k] for k in plan_a})
        except ParallelLinesError as error:
            row.warnings.append(f"no plan: {error}")
        report.rows.append(row)
    return report


def _number(value: float | None) -> str:
    if value is None:
        return "—"
    if math.isinf(value):
        return "∞"
    if math.isnan(value):
        return "—"
    return f"{value:.2g}"


def markdown(reports: list[SceneReport]) -> str:
    lines = ["# Stiff and extreme cases", "",
             (f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, numpy {np.__version__}. "
             "Regenerate with `python bench/stability.py`; the scenes are in `bench/extreme/`."), "",
             ("Error: normwise relative to the 50-digit reference, per position, over every point's v and every link's ω·L "
             "(accelerations: a, ε·L). κ: graphplan's condition number, 1/sin of the angle at which a group's lines of "
             f"action cross (analytic: `Motion.conditioning`; construction: the plans' `crossing_deg`). Bound: {BOUND:g}·κ·ε "
             f"for velocities, {BOUND:g}·κ²·ε for accelerations, ε = {EPS:.3g}; the construction crosses lines drawn "
             f"{REACH:g} times the figure's size long, so its bound is {REACH:g} times larger. A position passes within its "
             "bound, or with a warning; a scene passes when every position does, every toggle at a position or stepped "
             "over between two is warned of, and results.json holds no NaN; or when graphplan refuses it with one clear error."), "",
             ("| scene | outcome | positions within bound | warned | analytic: worst v error / κε | a error / κ²ε "
             "| construction: worst v error / κε | a error / κ²ε |"),
             "|---|---|---:|---:|---:|---:|---:|---:|"]
    for report in reports:
        if report.error is not None:
            lines.append(f"| {report.name} | clear error | — | — | — | — | — | — |")
            continue
        rows = [r for r in report.rows if not r.singular and not r.exact_singular]
        within = sum(r.within() for r in rows)
        warned = sum(bool(r.warnings) for r in report.rows)
        worst_v = max((r.velocity_error / (r.kappa * EPS) for r in rows), default=0.0)
        worst_a = max((r.acceleration_error / (r.kappa ** 2 * EPS) for r in rows), default=0.0)
        planned = [r for r in rows if r.plan_kappa is not None]
        plan_v = max((r.plan_velocity_error / (r.plan_kappa * EPS) for r in planned), default=0.0)
        plan_a = max((r.plan_acceleration_error / (r.plan_kappa ** 2 * EPS) for r in planned), default=0.0)
        outcome = "passes" if report.passed else "**FAILS**"
        lines.append(f"| {report.name} | {outcome} | {within}/{len(report.rows)} | {warned} | {worst_v:.2g} | {worst_a:.2g} "
                     f"| {plan_v:.2g} | {plan_a:.2g} |")
    failing = [report for report in reports if not report.passed]
    if failing:
        lines += ["", "Scenes that fail:", ""]
        for report in failing:
            why = []
            silent = [row.number for row in report.rows if "SILENT" in row.verdict]
            if silent:
                why.append(f"positions {', '.join(map(str, silent))} are outside their bound with no warning")
            stepped = [f"{p.after}–{p.before}" for p in report.passages if not p.warned and p.at_position is None]
            unwarned_at = [str(p.at_position) for p in report.passages if not p.warned and p.at_position is not None]
            if unwarned_at:
                why.append(f"a toggle at position {', '.join(unwarned_at)} has no warning")
            if stepped:
                why.append(f"a toggle is stepped over without a warning between positions {', '.join(stepped)}")
            if report.nan:
                why.append("results.json would hold a NaN")
            lines.append(f"- {report.name}: {'; '.join(why)}.")
    for report in reports:
        lines += ["", f"## {report.name}: {report.title}", "", report.note, ""]
        if report.error is not None:
            lines += [f"graphplan refuses the scene: `{report.error}`", ""]
            continue
        lines += ["| position | driver | κ | error v | error a | plan κ | plan error v | plan error a | verdict |",
                  "|---:|---|---:|---:|---:|---:|---:|---:|---|"]
        for row in report.rows:
            lines.append(f"| {row.number} | {row.driver} | {_number(row.kappa)} | {_number(row.velocity_error)} | "
                         f"{_number(row.acceleration_error)} | {_number(row.plan_kappa)} | {_number(row.plan_velocity_error)} | "
                         f"{_number(row.plan_acceleration_error)} | {row.verdict} |")
        lines.append("")
        if report.nan:
            lines += ["**results.json would hold a NaN.**", ""]
        for passage in report.passages:
            if passage.at_position is not None:
                lines += [f"At position {passage.at_position} ({passage.at}) a group's lines of action come within "
                          f"{math.degrees(math.asin(passage.sine)):.2g}° of parallel: a toggle at the position itself; "
                          + ("graphplan warned of it." if passage.warned else "**graphplan says nothing of it.**"), ""]
                continue
            lines += [f"Between positions {passage.after} and {passage.before} a group's lines of action come within "
                      f"{math.degrees(math.asin(passage.sine)):.2g}° of parallel (near {passage.at}): a toggle the positions "
                      f"step over, where the assembly may change branch; "
                      + ("graphplan warned of a position beside it." if passage.warned else "**graphplan says nothing of it.**"), ""]
        if report.warnings:
            lines += ["Warnings:", ""] + [f"- {w}" for w in report.warnings] + [""]
        else:
            lines += ["No warnings.", ""]
    return "\n".join(lines)


def main(paths: list[Path] | None = None) -> list[SceneReport]:
    reports = [study(path) for path in paths or sorted(EXTREME.glob("*.toml"))]
    for report in reports:
        print(f"{report.name}: {'passes' if report.passed else 'FAILS'}"
              + (f" (clear error: {report.error})" if report.error else ""))
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "stability.md").write_text(markdown(reports), encoding="utf-8")
    print(f"wrote {RESULTS / 'stability.md'}")
    return reports


if __name__ == "__main__":
    main([Path(p) for p in sys.argv[1:]] or None)
