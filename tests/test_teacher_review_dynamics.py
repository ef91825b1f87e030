"""A teacher's review of the machine's equivalent model and its flywheel, each number worked out afresh.

Nothing here calls graphplan's solvers: the shaper's and the slider-driven lever's closures are written out with
numpy (the lever's pivot on the crank circle's tangent, the RRR's two circles), their velocity ratios taken as
central differences of those positions, and the reduction, the works, ΔWmax and the flywheel are the textbook's:

* Je = Σ[m·(vS/ω1)² + JS·(ω/ω1)²] keeps the links' kinetic energy, Me = Σ[F·v·cos α ± M·ω]/|ω1| their power
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

    def __init__(self, bodies=SHAPER_BODIES):
        self.bodies = bodies
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
                   for centre, mass, angle, inertia in self.bodies) + 0.0 * psi

    def moment(self, psi, cutting: bool):
        """The loads' and the weights' reduced moment: Σ F·dr/dψ, the cutting force (−2000, 0) N at E."""
        rates = self.ratios(psi)
        weights = sum(-mass * G * rates[centre][1] for centre, mass, _, _ in self.bodies)
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
    curve = shaper["curve"][2]
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


def _paths(group: ElementTree.Element, colour: str | None = None) -> list[np.ndarray]:
    """The group's open paths (no fill) as arrays of (x, y) in the SVG's mm, y down."""
    found = []
    for path in group.iter(f"{SVG}path"):
        if path.get("fill") != "none" or (colour and path.get("stroke") != colour):
            continue
        found.append(np.array([[float(v) for v in point.split(",")]
                               for point in re.findall(r"[ML]([-\d.]+,[-\d.]+)", path.get("d"))]))
    return found


def _texts(group: ElementTree.Element) -> list[str]:
    return ["".join(text.itertext()) for text in group.iter(f"{SVG}text")]


def test_the_energy_mass_diagrams_tangents_touch_my_curve_at_my_slopes_and_cut_off_my_ab(shaper):
    """Read back off dynamics.svg: the scales its line states, the origin where its Je axis starts; each tangent's
    slope on paper is tan ψ = (μJ/μT)·ω²/2, its ψ written beside it, it passes through my intercept on the ΔT axis
    (the red dot a or b there), no point of the drawn curve lies beyond it and the curve comes to it; the curve is
    my ΔT(Je); ab is written in mm and the axes carry their quantities with units."""
    drawing = ElementTree.parse(shaper["out"] / "dynamics.svg").getroot()
    group = next(g for g in drawing.iter(f"{SVG}g") if g.get("id") == "energy-mass")
    texts = _texts(group)
    scales = next(text for text in texts if text.startswith("μJ"))
    found = re.fullmatch(r"μJ = " + NUMBER + r" kg·m²/mm, μT = " + NUMBER + " J/mm", scales)
    assert found, scales
    inertia_scale, energy_scale = _number(found[1]), _number(found[2])
    assert "ΔT, J" in texts and "Je, kg·m²" in texts
    black = _paths(group, "black")
    je_axis = max((p for p in black if len(p) == 2 and abs(p[0, 1] - p[1, 1]) < 1e-9), key=lambda p: p[1, 0] - p[0, 0])
    x0, y0 = je_axis[0]
    curve = max(black, key=len)
    drawn_je, drawn_energy = (curve[:, 0] - x0) * inertia_scale, (y0 - curve[:, 1]) * energy_scale
    witt = shaper["witt"]
    _, inertia, energy = shaper["curve"]
    # The drawn curve is mine: its extremes within a hundredth of a millimetre (the SVG's digits).
    assert drawn_energy.max() == pytest.approx(energy.max(), abs=0.01 * energy_scale)
    assert drawn_energy.min() == pytest.approx(energy.min(), abs=0.01 * energy_scale)
    assert drawn_je.max() == pytest.approx(inertia.max(), abs=0.01 * inertia_scale)
    tangents = [p for p in _paths(group, TANGENT_COLOUR) if len(p) == 2]
    assert len(tangents) == 2
    upper, lower = sorted(tangents, key=lambda p: p[0, 1])
    dots = [(float(c.get("cx")), float(c.get("cy"))) for c in group.iter(f"{SVG}circle")
            if c.get("fill") == TANGENT_COLOUR]
    for line, omega, intercept, above, name in ((upper, witt.fastest, witt.upper, True, "ψmax"),
                                               (lower, witt.slowest, witt.lower, False, "ψmin")):
        (xa, ya), (xb, yb) = line
        slope = -(yb - ya) / (xb - xa)
        tangent = inertia_scale / energy_scale * omega ** 2 / 2
        assert slope == pytest.approx(tangent, rel=2e-3)
        label = next(text for text in texts if text.startswith(name))
        assert _written_as(re.fullmatch(name + " = " + NUMBER + "°", label)[1], math.degrees(math.atan(tangent)))
        at_axis = ya + (x0 - xa) * (yb - ya) / (xb - xa)
        assert (y0 - at_axis) * energy_scale == pytest.approx(intercept, abs=0.01 * energy_scale)
        assert any(math.hypot(x - x0, y - at_axis) < 0.01 for x, y in dots), f"no dot {name[1:]} at the intercept"
        # Signed distance of each drawn point below the line (y down: positive is under it on paper).
        under = (curve[:, 1] - (ya + (curve[:, 0] - xa) * (yb - ya) / (xb - xa))) / math.hypot(1.0, slope)
        if not above:
            under = -under
        assert under.min() > -0.01 and under.min() < 0.01, f"{name}'s tangent misses or cuts the curve"
    ab = next(text for text in texts if text.startswith("ab = "))
    assert _written_as(re.fullmatch("ab = " + NUMBER + " mm", ab)[1], (witt.upper - witt.lower) / energy_scale)


# --- a translating equivalent link: the lever driven by a cylinder (fixtures/slider_driven.toml) -------------------

LEVER_PIVOT = np.array([0.15, 0.25])
LEVER_BODIES = (("A", 6.0, None, 0.0), ("S3", 1.4, "th3", 0.006), ("S4", 4.0, "th4", 0.02))


def _lever_positions(s: np.ndarray) -> dict:
    """The rod's end A at (s, 0); B where the circles of AB = 0.225 m about A and CB = 0.15 m about C cross, right of
    the directed line A→C; S3 halfway along AB, S4 0.06 m from C toward B."""
    a = np.array([s, np.zeros_like(s)])
    towards = LEVER_PIVOT[:, None] - a
    distance = np.hypot(*towards)
    unit = towards / distance
    along = (0.225 ** 2 - 0.15 ** 2 + distance ** 2) / (2 * distance)
    across = np.sqrt(0.225 ** 2 - along ** 2)
    b = a + along * unit - across * np.array([-unit[1], unit[0]])
    return {"A": a, "S3": (a + b) / 2, "S4": LEVER_PIVOT[:, None] + 0.4 * (b - LEVER_PIVOT[:, None]),
            "th3": np.arctan2(b[1] - a[1], b[0] - a[0]), "th4": np.arctan2(b[1] - 0.25, b[0] - 0.15)}


def _lever_model(s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """me(s) and the reduced force of the weights and the 150 N·m resisting the lever, Fr = Σ m·g·(−dy/ds) − 150·θ4′."""
    rates = _derivative(_lever_positions, np.asarray(s, dtype=float), h=1e-6)
    mass = sum(m * (rates[centre] ** 2).sum(0) + (inertia * rates[angle] ** 2 if angle else 0.0)
               for centre, m, angle, inertia in LEVER_BODIES)
    assert np.all(rates["th4"] > 0)   # the lever turns ccw all the travel: its working stroke, the moment on
    force = sum(-m * G * rates[centre][1] for centre, m, _, _ in LEVER_BODIES) - 150.0 * rates["th4"]
    return mass, force


@pytest.fixture(scope="module")
def lever(tmp_path_factory):
    text = (ROOT / "fixtures" / "slider_driven.toml").read_text(encoding="utf-8") + "\n[dynamics]\n"
    results, note, out = _run(tmp_path_factory.mktemp("lever"), text)
    return {"dynamics": results["dynamics"], "note": note, "out": out}


def test_the_levers_reduced_mass_and_force_are_my_own_over_the_travel(lever):
    dynamics = lever["dynamics"]
    assert dynamics["equivalent_link"] == "translating"
    s = np.asarray(dynamics["displacement"])
    assert s[0] == 0.0 and s[-1] == pytest.approx(0.2)
    mass, force = _lever_model(s)
    assert np.asarray(dynamics["reduced_inertia"]) == pytest.approx(mass, rel=1e-7)
    assert np.asarray(dynamics["resisting_moment"]) == pytest.approx(force, rel=1e-6)
    # The cylinder's push taken constant does the work the resistances take over the travel: Fd = Ar/H.
    work = -_simpson(lambda x: _lever_model(x)[1], 0.0, 0.2)
    assert np.asarray(dynamics["driving_moment"]) == pytest.approx(work / 0.2, rel=1e-8)
    energy = np.asarray(dynamics["kinetic_energy_change"])
    assert energy[-1] == pytest.approx(0.0, abs=1e-9 * work)
    assert float(np.ptp(energy)) == pytest.approx(
        -min(_simpson(lambda x: _lever_model(x)[1] + work / 0.2, 0.0, end) for end in np.linspace(0, 0.2, 2001)[1:]),
        rel=1e-5)


def test_the_levers_note_gives_my_reduced_mass_and_force_at_its_plan_positions(lever):
    text = _section(lever["note"], "Dynamics of the machine")
    assert "me = Σ[m·(vS/v2)² + JS·(ω/v2)²]" in text and "Fe = Σ[F·v·cos α ± M·ω]/|v2|" in text
    rows = re.findall(r"^\| (\d+) \| " + NUMBER + r" \| " + NUMBER + r" \| " + NUMBER + r" \| " + NUMBER + r" \| "
                      + NUMBER + r" \| " + NUMBER + r" \|", text, flags=re.MULTILINE)
    assert [int(row[0]) for row in rows] == [3, 9]
    for number, s, by_plan, analytic, _, force_by_plan, force in rows:
        travel = (int(number) - 1) * 0.2 / 11   # twelve positions over the travel, both ends among them
        assert _written_as(s, travel)
        mass, reduced = (float(value[0]) for value in _lever_model(np.array([travel])))
        assert _written_as(analytic, mass) and _written_as(by_plan, mass)
        assert _written_as(force, reduced) and _written_as(force_by_plan, reduced)


def test_the_reduced_mass_read_off_each_velocity_plan_is_ringed_on_me_of_s_as_je_is_on_je_of_phi(lever):
    """The shaper's Je(φ) rings Je read off each velocity plan on its curve, and the note tables both; the lever's
    me(s) drew its curve alone, so that the sheet showed nothing of the plans' reduction the note tabulates beside
    it.  Each plan position's me is ringed at its s on the curve, with the legend."""
    drawing = ElementTree.parse(lever["out"] / "dynamics.svg").getroot()
    group = next(g for g in drawing.iter(f"{SVG}g") if g.get("id") == "inertia")
    texts = _texts(group)
    assert "me read off the velocity plans" in texts
    scales = next(text for text in texts if text.startswith("μm"))
    found = re.fullmatch(r"μm = " + NUMBER + r" kg/mm, μs = " + NUMBER + " m/mm", scales)
    assert found, scales
    mass_scale, travel_scale = _number(found[1]), _number(found[2])
    curve = max(_paths(group, "black"), key=len)
    x0 = float(curve[0, 0])
    # The ordinate starts at a round mass under the curve: the curve's first point stands at me(0) over it.
    y_base = float(curve[0, 1]) + float(_lever_model(np.array([0.0]))[0][0]) / mass_scale
    rings = [(float(c.get("cx")), float(c.get("cy"))) for c in group.iter(f"{SVG}circle") if c.get("fill") == "none"]
    on_curve = []
    for number in (3, 9):
        travel = (number - 1) * 0.2 / 11
        mass = float(_lever_model(np.array([travel]))[0][0])
        x = x0 + travel / travel_scale
        y_curve = float(np.interp(x, curve[:, 0], curve[:, 1]))
        assert y_base - mass / mass_scale == pytest.approx(y_curve, abs=0.02)
        on_curve.append(any(math.hypot(cx - x, cy - y_curve) < 0.02 for cx, cy in rings))
    assert on_curve == [True, True]


def test_with_the_crank_alone_heavy_je_is_constant_and_every_method_gives_my_one_flywheel(tmp_path, shaper):
    """The shaper with the masses of links 3 to 6 left out: Je = J2 + m2·lOS2² all the cycle, so that the
    energy–mass curve is a vertical segment, its tangents cut off ab = ΔWmax exactly, and the approximate,
    Mertsalov's and Wittenbauer's flywheels are one, ΔWmax/(ωm²·δ) − Je; the sheet draws no energy–mass diagram
    and says Je is constant.  With the shaper's own masses (variable Je) the three differ, as they should."""
    text = re.sub(r"\[links\.3\].*?(?=\n\[\[loads\]\])", "", _starter("shaper", tmp_path), flags=re.DOTALL)
    assert "[links.2]" in text and "[links.3]" not in text and "[links.6]" not in text
    results, note, out = _run(tmp_path / "run", text)
    dynamics = results["dynamics"]
    model = Shaper(SHAPER_BODIES[:1])
    psi, inertia, energy = model.curve()
    witt = Wittenbauer(psi, inertia, energy, 2 * math.pi, 0.05)
    assert np.asarray(dynamics["reduced_inertia"]) == pytest.approx(0.015 + 6.0 * 0.03 ** 2, rel=1e-9)
    assert dynamics["delta_w_max"] == pytest.approx(witt.delta_w_max, rel=1e-8)
    flywheel = witt.delta_w_max / ((2 * math.pi) ** 2 * 0.05) - 0.0204
    assert witt.flywheel == pytest.approx(flywheel, rel=1e-12)
    for key in ("flywheel_inertia", "flywheel_inertia_approximate", "flywheel_inertia_mertsalov"):
        assert dynamics[key] == pytest.approx(flywheel, rel=1e-8), key
    assert "JF = ΔWmax/(ωm²·δ) − Je = " in note and ", exactly (the energy–mass diagram" in note
    drawing = ElementTree.parse(out / "dynamics.svg").getroot()
    groups = {g.get("id") for g in drawing.iter(f"{SVG}g")}
    assert "energy-mass" not in groups and "energy" in groups
    assert any("(Je constant)" in text for text in _texts(drawing))
    # The variable Je of the whole shaper: the energy–mass flywheel is neither of the other two.
    variable = shaper["dynamics"]
    assert abs(variable["flywheel_inertia"] - variable["flywheel_inertia_approximate"]) > 0.1
    assert abs(variable["flywheel_inertia"] - variable["flywheel_inertia_mertsalov"]) > 0.1


# --- the flywheel of `graphplan new flywheel`: a punching press known by its power over a turn -----------------------

@pytest.mark.parametrize("inertia, shaft_rpm", [(0.0, 1440.0), (2.5, 750.0)])
def test_the_press_flywheel_is_my_own_from_its_power_steps_and_moves_to_its_shaft(tmp_path, inertia, shaft_rpm):
    """367.7 W for the first 120° of the turn and 3677 W for the rest, at 100 rpm: Mr = P/ωm, Md their mean, ΔT
    rising by (Md − Mr1)·2π/3 to 120° and back, ΔWmax that; the press's own Je constant, so that J_F =
    ΔWmax/(ωm²·δ) − Je exactly, ωmax at 120° and ωmin at 0°; on the motor's shaft J_F·(n/n′)².  The starter as
    written (Je = 0, the flywheel on the 1440 rpm shaft), and with Je = 2.5 kg·m² and the flywheel on a 750 rpm
    countershaft."""
    text = _starter("flywheel", tmp_path)
    text = re.sub(r"^inertia = 0\.0 ", f"inertia = {inertia} ", text, flags=re.MULTILINE)
    text = re.sub(r"^flywheel_shaft_rpm = 1440 ", f"flywheel_shaft_rpm = {shaft_rpm} ", text, flags=re.MULTILINE)
    assert f"inertia = {inertia}" in text and f"flywheel_shaft_rpm = {shaft_rpm}" in text
    results, note, out = _run(tmp_path / "run", text)
    dynamics = results["dynamics"]
    omega_mean = 100 * math.pi / 30
    idle, punching = 367.7 / omega_mean, 3677.0 / omega_mean
    driving = (idle * 120 + punching * 240) / 360
    delta_w_max = (driving - idle) * 2 * math.pi / 3
    flywheel = delta_w_max / (omega_mean ** 2 * 0.05) - inertia
    assert dynamics["driving_moment"][0] == pytest.approx(driving, rel=1e-9)
    assert dynamics["delta_w_max"] == pytest.approx(delta_w_max, rel=1e-9)
    assert dynamics["flywheel_inertia"] == pytest.approx(flywheel, rel=1e-9)
    assert dynamics["flywheel_inertia_moved"] == pytest.approx(flywheel * (100 / shaft_rpm) ** 2, rel=1e-9)
    assert dynamics["omega_max"] == pytest.approx(omega_mean * 1.025, rel=1e-9)
    assert dynamics["omega_min"] == pytest.approx(omega_mean * 0.975, rel=1e-9)
    assert dynamics["omega_max_angle_deg"] == pytest.approx(120.0)
    assert dynamics["omega_min_angle_deg"] == pytest.approx(0.0)
    # ω at every sample from the energy: ½·(Je + J_F)·ω² = ½·(Je + J_F)·ωmin² + ΔT, ΔT from 0 at φ = 0.
    angle = np.radians(np.asarray(dynamics["angle_deg"]))
    energy = np.where(angle <= 2 * math.pi / 3, (driving - idle) * angle,
                      delta_w_max - (punching - driving) * (angle - 2 * math.pi / 3))
    assert np.asarray(dynamics["kinetic_energy_change"]) == pytest.approx(energy, abs=1e-9 * delta_w_max)
    omega = np.sqrt((omega_mean * 0.975) ** 2 + 2 * energy / (inertia + flywheel))
    assert np.asarray(dynamics["omega"]) == pytest.approx(omega, rel=1e-9)
    text = _section(note, "Dynamics of the machine")
    # A Je of 0 is left out of the working, as a teacher writes it: no "− Je", no "− 0".
    subtracted = (r" − Je", r" − " + NUMBER) if inertia else ("", "()")
    worked = re.search(r"JF = ΔWmax/\(ωm²·δ\)" + subtracted[0] + " = " + NUMBER + r"/\(" + NUMBER + r"²·" + NUMBER
                       + r"\)" + subtracted[1] + " = " + NUMBER + " kg·m², exactly", text)
    assert worked and _written_as(worked[1], delta_w_max) and _written_as(worked[2], omega_mean)
    assert (_number(worked[4]) if inertia else 0.0) == inertia and _written_as(worked[5], flywheel)
    moved = re.search(r"n′ = " + NUMBER + r" rpm the flywheel is JF′ = JF·\(n/n′\)² = " + NUMBER + " kg·m²", text)
    assert moved and _number(moved[1]) == shaft_rpm
    assert _written_as(moved[2], flywheel * (100 / shaft_rpm) ** 2)
    drawn = _texts(ElementTree.parse(out / "dynamics.svg").getroot())
    line = next(text for text in drawn if text.startswith("on a shaft at"))
    assert _number(re.search(r"= " + NUMBER + " kg·m²$", line)[1]) == pytest.approx(
        flywheel * (100 / shaft_rpm) ** 2, rel=1e-3)


@pytest.mark.parametrize("locale, weights", [("en", "weights"), ("ru", "сил тяжести"), ("zh", "重力")])
def test_a_press_known_by_its_load_diagram_is_not_told_of_weights_it_has_none_of(tmp_path, locale, weights):
    """The press of `graphplan new flywheel` has no links and so no weights: its equation of motion's Mr(φ) is the
    resisting diagram's moment, which the note called "the reduced moment of the loads and the weights"."""
    text = _starter("flywheel", tmp_path).replace('locale = "en"', f'locale = "{locale}"')
    _, note, _ = _run(tmp_path / "run", text)
    equation = next(paragraph for paragraph in note.split("\n\n") if "Mr(φ)" in paragraph or "Mс(φ)" in paragraph)
    assert weights not in equation
    assert {"en": "load diagram", "ru": "диаграмм", "zh": "线图"}[locale] in equation


# --- the compressor of tests/scenes: 600 rpm, a steep energy–mass diagram --------------------------------------------

def _box(text: ElementTree.Element):
    """The box a number of DejaVu Sans covers: digits 0.636 em wide, the point 0.318 em, caps 0.73 em tall."""
    from shapely.geometry import box

    size, words = float(text.get("font-size")), "".join(text.itertext())
    width = sum(0.318 if character == "." else 0.636 for character in words) * size
    x, y = float(text.get("x")), float(text.get("y"))
    left = {"start": x, "middle": x - width / 2, "end": x - width}[text.get("text-anchor")]
    return box(left, y - 0.73 * size, left + width, y)


def test_the_je_numbers_of_the_energy_mass_diagram_stand_clear_of_its_tangents_and_curve(tmp_path):
    """At 600 rpm the compressor's tangents rise at 38° and cross the Je axis among its numbers: the numbers were
    set above the axis, where fewer points of the curve lie near it, and the upper tangent struck 0.05 through.  A
    number must stand clear of every line of the diagram; the tangent crosses the axis at 0.05's tick itself, so
    that no spot by it is clear: the tangent is broken under it (tests/test_dynamics_axes_agree.py)."""
    from shapely.geometry import LineString

    text = (ROOT / "tests" / "scenes" / "compressor_indicator_diagram.toml").read_text(encoding="utf-8")
    _, _, out = _run(tmp_path, text, pieces="dynamics")
    drawing = ElementTree.parse(out / "dynamics.svg").getroot()
    group = next(g for g in drawing.iter(f"{SVG}g") if g.get("id") == "energy-mass")
    black = _paths(group, "black")
    je_axis = max((p for p in black if len(p) == 2 and abs(p[0, 1] - p[1, 1]) < 1e-9), key=lambda p: p[1, 0] - p[0, 0])
    axis_y = je_axis[0, 1]
    origin = je_axis[0, 0]
    # The axis's own numbers, lettered as the ΔT axis's numbers left of the ordinate are (a size under the axes'
    # names); the plan positions' numbers by their points on the curve are smaller still.
    ordinate_numbers = {t.get("font-size") for t in group.iter(f"{SVG}text")
                        if re.fullmatch(r"−?\d+(\.\d+)?", "".join(t.itertext())) and float(t.get("x")) < origin}
    assert len(ordinate_numbers) == 1, ordinate_numbers
    numbers = [t for t in group.iter(f"{SVG}text") if re.fullmatch(r"\d+(\.\d+)?", "".join(t.itertext()))
               and float("".join(t.itertext())) > 0 and abs(float(t.get("y")) - axis_y) < 8
               and t.get("font-size") in ordinate_numbers]
    written = [float("".join(t.itertext())) for t in numbers]
    scales = re.fullmatch(r"μJ = " + NUMBER + r" kg·m²/mm, μT = " + NUMBER + " J/mm",
                          next(text for text in _texts(group) if text.startswith("μJ")))
    ticks = sorted(round((p[0, 0] - origin) * _number(scales[1]), 9) for p in black
                   if len(p) == 2 and abs(p[0, 0] - p[1, 0]) < 1e-9 and min(p[:, 1]) < axis_y < max(p[:, 1]))
    # Every tick kept, at a round step, and numbered each, or every other where the numbers would stand closer than a
    # letter (tests/test_dynamics_labels_clear.py): every tick at a multiple of the numbers' step has its number.  (The
    # compressor's, at 0.025 apart, stand a letter apart at 2.5 mm, each numbered, 0.05 among them.)
    assert ticks == pytest.approx([ticks[0] * k for k in range(1, len(ticks) + 1)]) and len(ticks) >= 2
    every = round(min(written) / ticks[0])
    numbered = [tick for k, tick in enumerate(ticks, 1) if k % every == 0]
    assert sorted(written) == pytest.approx(numbered), (written, ticks)
    lines = [LineString(p) for p in (*_paths(group, TANGENT_COLOUR), max(black, key=len))]
    struck = [("".join(t.itertext()), k) for t in numbers for k, line in enumerate(lines) if _box(t).intersects(line)]
    assert not struck, f"Je's numbers crossed by the diagram's lines (0, 1 the tangents, 2 the curve): {struck}"


def test_the_press_diagrams_name_their_axes_and_scales_and_draw_delta_w_max_between_the_extreme_speeds(tmp_path):
    """Each diagram of the press names its ordinate with its unit and states its scales; on ΔT(φ) the ordinates at
    ωmax and ωmin stand at 120° and 0° by μφ, and the first rises ΔWmax = (Md − Mr1)·2π/3 over the second at μT:
    ΔWmax drawn where the hand calculation puts it."""
    _, _, out = _run(tmp_path, _starter("flywheel", tmp_path), pieces="dynamics")
    drawing = ElementTree.parse(out / "dynamics.svg").getroot()
    groups = {g.get("id"): g for g in drawing.iter(f"{SVG}g")}
    for name, axis, scale in (("moments", "M, N·m", r"μM = \d+ N·m/mm"), ("works", "A, J", r"μA = \d+ J/mm"),
                              ("energy", "ΔT, J", r"μT = \d+ J/mm")):
        texts = _texts(groups[name])
        assert axis in texts and "φ, °" in texts, (name, texts)
        assert any(re.fullmatch(scale + r", μφ = 2°/mm \(0\.03491 rad/mm\)", text) for text in texts), (name, texts)
    texts = _texts(groups["energy"])
    energy_scale = _number(re.search(r"μT = " + NUMBER + " J/mm", " ".join(texts))[1])
    black = _paths(groups["energy"], "black")
    axis = max((p for p in black if len(p) == 2 and abs(p[0, 1] - p[1, 1]) < 1e-9), key=lambda p: p[1, 0] - p[0, 0])
    (x0, y0) = axis[0]
    ordinates: dict[float, float] = {}
    for p in _paths(groups["energy"], TANGENT_COLOUR):
        if abs(p[0, 0] - p[1, 0]) < 1e-9 and max(p[:, 1]) <= y0 + 1e-9:   # an ordinate up from the axis, not a tick
            at = round((p[0, 0] - x0) * 2.0, 3)
            ordinates[at] = max(ordinates.get(at, 0.0), (y0 - min(p[:, 1])) * energy_scale)
    omega_mean = 100 * math.pi / 30
    delta_w_max = ((367.7 * 120 + 3677.0 * 240) / 360 - 367.7) / omega_mean * 2 * math.pi / 3
    assert set(ordinates) == {0.0, 120.0}
    assert ordinates[120.0] - ordinates[0.0] == pytest.approx(delta_w_max, abs=0.01 * energy_scale)
