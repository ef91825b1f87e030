"""A teacher's review of the machine's equivalent model and its flywheel, each number worked out afresh.

Nothing here calls graphplan's solvers: the shaper's and the slider-driven lever's closures are written out with
numpy (the lever's pivot on the crank circle's tangent, the RRR's two circles), their velocity ratios taken as
central differences of those positions, and the reduction, the works, ΔWmax and the flywheel are the textbook's:

* Je = Σ[m·(vS/ω1)² + JS·(ω/ω1)²] keeps the links' kinetic energy, Me = Σ[F·v·cos α ± M·ω]/ω1 their power
  (I. I. Artobolevsky, *Theory of Mechanisms and Machines*, the dynamics of machines: reduction of masses and
  forces; for a slider driver the reduced mass and force, me = Σ[m·(vS/v1)² + JS·(ω/v1)²]);
* ΔT = Ad − Ar over the cycle with the driving moment taken constant (Md = Ar/2π), ΔWmax its range and the
  approximate flywheel J_F = ΔWmax/(ωm²·δ) − Je (J. J. Uicker, G. R. Pennock, J. E. Shigley, *Theory of Machines
  and Mechanisms*, flywheels: I = ΔE/(Cs·ω²)), moved to another shaft as J_F·(n/n′)²;
* Wittenbauer's energy–mass diagram ΔT(Je) and its two tangents at tan ψmax,min = (μJ/μT)·ωmax,min²/2 cutting ab
  off the ΔT axis, J_F = ab·μT/(ωmax²/2 − ωmin²/2) (С. А. Попов, Г. А. Тимофеев, *Курсовое проектирование по
  теории механизмов и механике машин*, the flywheel by the energy–mass diagram; they write ωm²·(1 ± δ) for
  ωm²·(1 ± δ/2)², which drops δ²/4: graphplan takes the exact slopes, with ωmax,min = ωm·(1 ± δ/2), and so does
  this review); Mertsalov's method with the links of constant reduced inertia Jc (Попов & Тимофеев too);
* ω over the cycle from T0 + ΔT = ½·(Je + J_F)·ω², T0 where the tangents meet, (−J_F, −T0).

The student's hand-in is what ``graphplan run`` writes: ``results.json`` ``dynamics``, the note's dynamics
section and ``dynamics.svg``.  Where graphplan agrees, the test stands as an independent check.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from scipy.integrate import cumulative_simpson
from scipy.optimize import brentq

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
NUMBER = r"(−?\d+(?:\.\d+)?)"
TANGENT_COLOUR = "#b22222"
G = 9.81


def _number(text: str) -> float:
    return float(text.replace("−", "-"))


def _derivative(function, x: np.ndarray, h: float = 1e-5):
    """Fourth-order central difference of every array of ``function(x)`` (a dict of arrays)."""
    plus, minus = function(x + h), function(x - h)
    plus2, minus2 = function(x + 2 * h), function(x - 2 * h)
    return {key: (8 * (plus[key] - minus[key]) - (plus2[key] - minus2[key])) / (12 * h) for key in plus}


def _run(tmp_path: Path, scene_text: str, pieces: str = "dynamics,note") -> tuple[dict, str, Path]:
    tmp_path.mkdir(parents=True, exist_ok=True)
    scene = tmp_path / "scene.toml"
    scene.write_text(scene_text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", pieces, "--sheet", "none"]) == 0
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    note = (out / "note.md").read_text(encoding="utf-8") if (out / "note.md").exists() else ""
    return results, note, out


def _starter(kind: str, tmp_path: Path) -> str:
    path = tmp_path / f"{kind}.toml"
    assert main(["new", kind, "--out", str(path)]) == 0
    return path.read_text(encoding="utf-8")


def _section(note: str, heading: str) -> str:
    start = note.index(heading)
    following = note.find("\n## ", start + 1)
    return note[start:] if following < 0 else note[start:following]


# --- the shaper of `graphplan new shaper`, closed here ------------------------------------------------------------

SHAPER_PIVOT = np.array([0.0, 0.35])   # O; the lever's pivot C at the origin
SHAPER_CRANK = 0.10
# (centre, mass, the angle the link turns by, its JS), the starter's [links.N] and [points]
SHAPER_BODIES = (("S2", 6.0, "th2", 0.015), ("A", 1.5, "th4", 0.0), ("S4", 18.0, "th4", 0.65),
                 ("S5", 3.0, "th5", 0.011), ("E", 35.0, None, 0.0))


def _shaper_positions(phi: np.ndarray) -> dict:
    """The shaper at crank angles ``phi``: the block's pin A on the slotted lever through C, the lever's end D at
    0.65 m, the ram's pin E on the guide y = 0.64 m ahead of D, lDE = 0.2 m."""
    crank = np.array([np.cos(phi), np.sin(phi)])
    a = SHAPER_PIVOT[:, None] + SHAPER_CRANK * crank
    along = a / np.hypot(*a)
    d = 0.65 * along
    e = np.array([d[0] + np.sqrt(0.2 ** 2 - (0.64 - d[1]) ** 2), np.full_like(phi, 0.64)])
    return {"S2": SHAPER_PIVOT[:, None] + 0.03 * crank, "A": a, "S4": 0.325 * along, "S5": d + 0.5 * (e - d),
            "E": e, "th2": phi, "th4": np.arctan2(a[1], a[0]), "th5": np.arctan2(e[1] - d[1], e[0] - d[0])}


class Shaper:
    """The shaper's equivalent model by hand, over the travel ψ the crank turns clockwise from the working stroke's
    start (its ram's left extreme, where the crank is square to the lever)."""

    def __init__(self):
        ram_speed = lambda phi: float(_derivative(_shaper_positions, np.array([phi]))["E"][0][0])
        grid = np.radians(np.arange(0.0, 360.5, 0.5))
        speeds = _derivative(_shaper_positions, grid)["E"][0]
        roots = [brentq(ram_speed, grid[k], grid[k + 1], xtol=1e-15)
                 for k in range(len(grid) - 1) if speeds[k] * speeds[k + 1] < 0]
        ram = [float(_shaper_positions(np.array([root]))["E"][0][0]) for root in roots]
        self.start, self.end = (roots[0], roots[1]) if ram[0] < ram[1] else (roots[1], roots[0])
        self.low, self.high = min(ram), max(ram)
        working = (self.start - self.end) % (2 * math.pi)

        def share(psi):
            return (float(_shaper_positions(np.array([self.start - psi]))["E"][0][0]) - self.low) / \
                (self.high - self.low)

        self.cut_from = brentq(lambda psi: share(psi) - 0.05, 1e-9, working - 1e-9, xtol=1e-15)
        self.cut_to = brentq(lambda psi: share(psi) - 0.95, 1e-9, working - 1e-9, xtol=1e-15)
        self.pieces = ((0.0, self.cut_from, False), (self.cut_from, self.cut_to, True),
                       (self.cut_to, 2 * math.pi, False))
        resisting = sum(_simpson(lambda psi, cut=cut: self.moment(psi, cut), a, b) for a, b, cut in self.pieces)
        self.driving = -resisting / (2 * math.pi)

    def ratios(self, psi):
        # d/dψ = −d/dφ: the crank turns clockwise, ψ counts the way it goes.
        rates = _derivative(_shaper_positions, self.start - np.asarray(psi, dtype=float))
        return {key: -value for key, value in rates.items()}

    def inertia(self, psi):
        rates = self.ratios(psi)
        return sum(mass * (rates[centre] ** 2).sum(0) + (inertia * rates[angle] ** 2 if angle else 0.0)
                   for centre, mass, angle, inertia in SHAPER_BODIES)

    def moment(self, psi, cutting: bool):
        """The loads' and the weights' reduced moment: Σ F·dr/dψ, the cutting force (−2000, 0) N at E."""
        rates = self.ratios(psi)
        weights = sum(-mass * G * rates[centre][1] for centre, mass, _, _ in SHAPER_BODIES)
        return weights + (-2000.0 * rates["E"][0] if cutting else 0.0)

    def cutting_at(self, psi: float) -> bool:
        return self.cut_from < psi < self.cut_to

    def curve(self, per_piece: int = 20000):
        """(ψ, Je, ΔT) densely over the cycle, ΔT by Simpson's rule piece by piece."""
        psis, inertias, energies, reached = [], [], [], 0.0
        for a, b, cut in self.pieces:
            psi = np.linspace(a, b, per_piece + 1)
            energy = reached + cumulative_simpson(self.moment(psi, cut) + self.driving, x=psi, initial=0.0)
            psis.append(psi)
            inertias.append(self.inertia(psi))
            energies.append(energy)
            reached = float(energy[-1])
        return np.concatenate(psis), np.concatenate(inertias), np.concatenate(energies)


def _simpson(function, a: float, b: float, intervals: int = 4000) -> float:
    x = np.linspace(a, b, intervals + 1)
    y = function(x)
    return float((b - a) / intervals / 3 * (y[0] + y[-1] + 4 * y[1:-1:2].sum() + 2 * y[2:-1:2].sum()))


class Wittenbauer:
    """The flywheel of a curve (Je, ΔT) for δ at ωm: the tangents at ωmax,min²/2, their intercepts and meeting."""

    def __init__(self, psi, inertia, energy, omega_mean: float, delta: float):
        self.fastest, self.slowest = omega_mean * (1 + delta / 2), omega_mean * (1 - delta / 2)
        self.upper_slope, self.lower_slope = self.fastest ** 2 / 2, self.slowest ** 2 / 2
        self.upper = float(np.max(energy - self.upper_slope * inertia))
        self.lower = float(np.min(energy - self.lower_slope * inertia))
        self.flywheel = (self.upper - self.lower) / (self.upper_slope - self.lower_slope)
        self.start_energy = self.upper_slope * self.flywheel - self.upper
        self.omega = np.sqrt(2 * (self.start_energy + energy) / (inertia + self.flywheel))
        self.psi_max, self.psi_min = float(psi[np.argmax(self.omega)]), float(psi[np.argmin(self.omega)])
        self.delta_w_max = float(np.ptp(energy))
        self.mean_inertia = float(np.trapezoid(inertia, psi) / (psi[-1] - psi[0]))
        self.approximate = self.delta_w_max / (omega_mean ** 2 * delta) - self.mean_inertia


@pytest.fixture(scope="module")
def shaper(tmp_path_factory):
    folder = tmp_path_factory.mktemp("shaper")
    results, note, out = _run(folder, _starter("shaper", folder))
    model = Shaper()
    psi, inertia, energy = model.curve()
    witt = Wittenbauer(psi, inertia, energy, 2 * math.pi, 0.05)
    return {"results": results, "dynamics": results["dynamics"], "note": note, "out": out, "model": model,
            "curve": (psi, inertia, energy), "witt": witt}


def test_the_shapers_reduced_inertia_and_moment_are_my_own_closures_at_every_sample(shaper):
    dynamics, model = shaper["dynamics"], shaper["model"]
    travel = np.asarray(dynamics["travel"])
    assert math.degrees(model.start) == pytest.approx(dynamics["angle_deg"][0], abs=1e-6)
    assert np.asarray(dynamics["reduced_inertia"]) == pytest.approx(model.inertia(travel), rel=1e-7, abs=1e-9)
    # Each window edge is sampled on both sides: the first of a pair before the jump, the second after.
    cutting = np.array([model.cutting_at(psi) for psi in travel])
    for edge in (model.cut_from, model.cut_to):
        twins = np.flatnonzero(np.isclose(travel, edge, atol=1e-9))
        assert len(twins) == 2
        cutting[twins] = [edge == model.cut_to, edge == model.cut_from]
    mine = np.array([float(model.moment(np.array([psi]), cut)[0]) for psi, cut in zip(travel, cutting)])
    assert np.asarray(dynamics["resisting_moment"]) == pytest.approx(mine, rel=1e-6, abs=1e-6)
    assert np.asarray(dynamics["driving_moment"]) == pytest.approx(model.driving, rel=1e-8)
    assert np.asarray(dynamics["reduced_moment"]) == pytest.approx(mine + model.driving, rel=1e-6, abs=1e-6)


def test_the_shapers_works_delta_w_max_and_flywheels_are_my_own(shaper):
    dynamics, witt = shaper["dynamics"], shaper["witt"]
    psi, inertia, energy = shaper["curve"]
    travel = np.asarray(dynamics["travel"])
    assert np.asarray(dynamics["kinetic_energy_change"]) == pytest.approx(np.interp(travel, psi, energy), abs=1e-6)
    assert dynamics["delta_w_max"] == pytest.approx(witt.delta_w_max, rel=1e-8)
    assert dynamics["flywheel_inertia"] == pytest.approx(witt.flywheel, rel=1e-6)
    assert dynamics["flywheel_inertia_approximate"] == pytest.approx(witt.approximate, rel=1e-6)
    # Mertsalov: the crank and the block on its pin keep their reduced inertia, J2 + m2·lOS2² + m3·lOA².
    constant = 0.015 + 6.0 * 0.03 ** 2 + 1.5 * 0.1 ** 2
    assert dynamics["constant_reduced_inertia"] == pytest.approx(constant, rel=1e-9)
    omega_mean = 2 * math.pi
    varying = energy - 0.5 * (inertia - constant) * omega_mean ** 2
    mertsalov = float(np.ptp(varying)) / (omega_mean ** 2 * 0.05) - constant
    assert dynamics["flywheel_inertia_mertsalov"] == pytest.approx(mertsalov, rel=1e-6)
    assert dynamics["kinetic_energy_start"] == pytest.approx(witt.start_energy, rel=1e-6)
    assert dynamics["omega_max"] == pytest.approx(witt.fastest, rel=1e-9)
    assert dynamics["omega_min"] == pytest.approx(witt.slowest, rel=1e-9)
    assert dynamics["omega_max_travel_deg"] == pytest.approx(math.degrees(witt.psi_max), abs=0.05)
    assert dynamics["omega_min_travel_deg"] == pytest.approx(math.degrees(witt.psi_min), abs=0.05)
    start = math.degrees(shaper["model"].start)
    assert dynamics["omega_max_angle_deg"] == pytest.approx((start - math.degrees(witt.psi_max)) % 360, abs=0.05)
    assert dynamics["omega_min_angle_deg"] == pytest.approx((start - math.degrees(witt.psi_min)) % 360, abs=0.05)
    # The starter's motor shaft: n′ = 1482 rpm for the crank's 60.
    assert dynamics["flywheel_inertia_moved"] == pytest.approx(witt.flywheel * (60 / 1482) ** 2, rel=1e-6)


def _written_as(written: str, mine: float) -> bool:
    """``mine`` rounds to ``written`` at the digits it is written with (half a unit of its last digit, and a hair)."""
    decimals = len(written.split(".")[1]) if "." in written else 0
    return abs(_number(written) - mine) <= 0.5 * 10.0 ** -decimals * (1 + 1e-6) + 1e-12


def test_the_shapers_note_writes_my_numbers_and_its_arithmetic_holds(shaper):
    text, witt, model = _section(shaper["note"], "Dynamics of the machine"), shaper["witt"], shaper["model"]
    driving = re.search(r"Md = Ar/2π = " + NUMBER + " N·m", text)
    assert driving and _written_as(driving[1], model.driving)
    energy = re.search(r"ranges from " + NUMBER + " J to " + NUMBER + r" J: the largest surplus work ΔWmax = "
                       + NUMBER + " J", text)
    psi, _, curve = shaper["curve"]
    assert energy and _written_as(energy[1], float(curve.min())) and _written_as(energy[2], float(curve.max()))
    assert _written_as(energy[3], witt.delta_w_max)
    approximate = re.search(r"JF = ΔWmax/\(ωm²·δ\) − Je,mean = " + NUMBER + r"/\(" + NUMBER + r"²·" + NUMBER
                            + r"\) − " + NUMBER + " = " + NUMBER + " kg·m²", text)
    assert approximate
    worked, speed, delta, mean, result = (_number(approximate[k]) for k in range(1, 6))
    assert _written_as(approximate[2], 2 * math.pi) and delta == 0.05
    assert _written_as(approximate[4], witt.mean_inertia) and _written_as(approximate[5], witt.approximate)
    assert worked / (speed ** 2 * delta) - mean == pytest.approx(result, rel=1e-3)
    exact = re.search(r"by the energy–mass diagram, with Je variable, JF = " + NUMBER + " kg·m²", text)
    assert exact and _written_as(exact[1], witt.flywheel)
    extremes = re.search(r"ωmax = " + NUMBER + r" rad/s at φ = " + NUMBER + r"° and ωmin = " + NUMBER
                         + r" rad/s at φ = " + NUMBER + "°", text)
    start = math.degrees(model.start)
    assert extremes and _written_as(extremes[1], witt.fastest) and _written_as(extremes[3], witt.slowest)
    assert _written_as(extremes[2], (start - math.degrees(witt.psi_max)) % 360)
    assert _written_as(extremes[4], (start - math.degrees(witt.psi_min)) % 360)
    moved = re.search(r"n′ = " + NUMBER + r" rpm the flywheel is JF′ = JF·\(n/n′\)² = " + NUMBER + " kg·m²", text)
    assert moved and _number(moved[1]) == 1482 and _written_as(moved[2], witt.flywheel * (60 / 1482) ** 2)


PLAN_SEGMENTS = (("p", "a"), ("p", "a4"), ("d", "e"), ("p", "s2"), ("p", "s4"), ("p", "s5"), ("p", "e"))


def _plan_inertia(plan: dict, links: dict, precision: float = 0.0, longer: tuple[str, str] | None = None) -> float:
    """Je of the shaper from its velocity plan's points: every segment read to ``precision`` mm (the one ``longer``
    names read 0.5 mm longer), ω4 = pa4·μV/lCA, ω5 = de·μV/lDE, over ω2 = pa·μV/lOA."""
    points = {name: np.asarray(xy) for name, xy in plan["points_mm"].items()}
    scale = plan["scale"]

    def read(a: str, b: str) -> float:
        length = float(np.hypot(*(points[b] - points[a])))
        return (round(length / precision) * precision if precision else length) + (0.5 if (a, b) == longer else 0)

    crank = read("p", "a") * scale / SHAPER_CRANK
    lever = read("p", "a4") * scale / links["CA"]
    rod = read("d", "e") * scale / 0.2
    speeds = {"S2": read("p", "s2"), "A": read("p", "a"), "S4": read("p", "s4"), "S5": read("p", "s5"),
              "E": read("p", "e")}
    turns = {"th2": crank, "th4": lever, "th5": rod}
    return sum(mass * (speeds[centre] * scale / crank) ** 2 + (inertia * (turns[angle] / crank) ** 2 if angle else 0)
               for centre, mass, angle, inertia in SHAPER_BODIES)


def test_je_read_off_the_velocity_plans_agrees_with_mine_within_the_plans_drafting(shaper):
    """The note's table gives Je by the plan beside the analytic one: the analytic column is my closure's, and the
    plan's is what the plan's own segments give, within what reading each to 0.5 mm (the drafting precision) moves
    it; at position 1, the working stroke's start, the lever stands still and Je is the crank's and the block's,
    0.0354 kg·m²."""
    model, results = shaper["model"], shaper["results"]
    table = _section(shaper["note"], "Dynamics of the machine")
    rows = re.findall(r"^\| (\d+) \| " + NUMBER + r" \| " + NUMBER + r" \| " + NUMBER + r" \| " + NUMBER + r" \|",
                      table, flags=re.MULTILINE)
    assert len(rows) == 12
    positions = {position["index"]: position for position in results["positions"]}
    for number, angle, by_plan, analytic, _ in rows:
        psi = (int(number) - 1) * 2 * math.pi / 12   # twelve positions from the working stroke's start
        assert _written_as(angle, math.degrees(model.start - psi) % 360)
        assert _written_as(analytic, float(model.inertia(np.array([psi]))[0]))
        position = positions[int(number)]
        pin = _shaper_positions(np.array([model.start - psi]))["A"][:, 0]
        plan, lever = position["velocity_plan"], {"CA": float(np.hypot(*pin))}
        exact = _plan_inertia(plan, lever)
        drafted = _plan_inertia(plan, lever, precision=0.5)
        reach = sum(abs(_plan_inertia(plan, lever, longer=segment) - exact) for segment in PLAN_SEGMENTS)
        assert _written_as(by_plan, exact)
        assert abs(_number(by_plan) - drafted) <= reach + 1e-4
    assert _number(rows[0][2]) == pytest.approx(0.0354)
