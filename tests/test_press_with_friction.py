"""A shaper's and a press's ram under its cutting or pressing force F6, with friction on its guide and in the
turning pairs, end to end against a statics worked out here.

The statics is the textbook's, written afresh: the mechanism's positions from its own closed forms, the
velocities and accelerations by finite differences in time, d'Alembert's loads, and every link's three
equilibrium equations as one linear system solved by least squares, the friction loads (Ff16 = f·|R16| against
the ram's velocity, Mf = ρ·|R| against each pair's relative turning) taken from the last solve's reactions until
they settle.  Against it: results.json of a run, the force polygons with friction (F6 and Ff16 laid off head to
tail on the polygon of the group 5–6), Zhukovsky's lever with friction (from this statics' power balance), and
the ram's moment equation as the sheet writes it, read with its numbers.
"""

import dataclasses
import itertools
import json
import math
import re
from pathlib import Path
from types import MappingProxyType

import numpy as np
import pytest
from sheet_texts import flat

from graphplan import load_text
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, with_length_scale
from graphplan.render.plans import ZERO_MM

GRAVITY = 9.81

SHAPER_FRICTION = """
[[friction]]
joint = "E"
links = [6, 1]
f     = 0.15

[[friction]]
joint  = "O"
f      = 0.08
radius = 0.02

[[friction]]
joint  = "C"
f      = 0.1
radius = 0.025

[[friction]]
joint  = "D"
f      = 0.1
radius = 0.015

[[friction]]
joint  = "E"
links  = [5, 6]
f      = 0.1
radius = 0.015
"""

# A crank-lever press: crank 2, rod 3, rocker 4 about C, rod 5 from the rocker's end D down to the ram 6 on a
# vertical guide; the pressing force against the ram's downward working stroke by a diagram over its second half.
PRESS = """
[scene]
title   = "Crank-lever press with friction"
gravity = 9.81

[frame]
link   = 1
points = { O = [0.0, 0.0], C = [0.3, 0.0] }
lines  = { ram = { through = [0.33, 0.0], angle = -90.0 } }

[driver]
kind   = "crank"
link   = 2
pivot  = "O"
joint  = "A"
length = 0.08
rpm    = -90.0

[[groups]]
kind     = "RRR"
links    = [3, 4]
joints   = ["A", "B", "C"]
lengths  = [0.30, 0.25]
assembly = "right"

[[groups]]
kind     = "RRP"
links    = [5, 6]
joints   = ["D", "E"]
length   = 0.30
guide    = "ram"
assembly = "forward"

[points]
S2 = { link = 2, from = "O", toward = "A", at = 0.02 }
S3 = { link = 3, from = "A", toward = "B", at = 0.15 }
S4 = { link = 4, from = "C", toward = "B", at = 0.15 }
D  = { link = 4, from = "C", toward = "B", at = 0.35 }
S5 = { link = 5, from = "D", toward = "E", at = 0.15 }

[links.2]
mass = 5.0
centre = "S2"
inertia = 0.01
[links.3]
mass = 6.0
centre = "S3"
inertia = 0.05
[links.4]
mass = 8.0
centre = "S4"
inertia = 0.09
[links.5]
mass = 5.0
centre = "S5"
inertia = 0.04
[links.6]
mass = 40.0
centre = "E"

[[loads]]
kind      = "force"
link      = 6
point     = "E"
diagram   = [[0.5, 0.0], [0.8, 6000.0], [1.0, 6000.0]]
angle     = 90.0
resisting = true

[[friction]]
joint = "E"
links = [6, 1]
f     = 0.12

[[friction]]
joint  = "E"
links  = [5, 6]
f      = 0.1
radius = 0.02

[[friction]]
joint  = "O"
f      = 0.08
radius = 0.025

[[friction]]
joint  = "A"
f      = 0.1
radius = 0.02

[[friction]]
joint  = "B"
f      = 0.1
radius = 0.02

[[friction]]
joint  = "C"
f      = 0.1
radius = 0.02

[[friction]]
joint  = "D"
f      = 0.1
radius = 0.02

[positions]
count       = 12
start       = "extreme"
working     = { link = 6, sense = "forward" }
plans       = [4, 9]

[drawing]
length_scale      = 0.004
velocity_pole     = 100.0
acceleration_pole = 100.0
"""


def shaper_text() -> str:
    return Path("fixtures/shaper_six_bar.toml").read_text(encoding="utf-8") + SHAPER_FRICTION


class Shaper:
    """The fixture's six-bar from its numbers: crank OA about O, block A in the lever CD's slot, rod DE, ram E."""

    omega = -6.0
    masses = MappingProxyType({2: (6.0, 0.015, "S2"), 3: (1.5, 0.0, "A"), 4: (18.0, 0.65, "S4"), 5: (3.0, 0.011, "S5"),
              6: (35.0, 0.0, "E")})
    guide = 1.0 + 0j  # the ram's direction, +x
    slide_f = 0.15
    rho = MappingProxyType({"O": 0.08 * 0.02, "C": 0.1 * 0.025, "D": 0.1 * 0.015, "E": 0.1 * 0.015})
    # The turning pairs: joint, the earlier link, the later one, and where it is.
    revolutes = (("O", 1, 2), ("C", 1, 4), ("D", 4, 5), ("E", 5, 6))

    @staticmethod
    def points(phi: float) -> dict[str, complex]:
        o, c = 0.35j, 0j
        a = o + 0.10 * np.exp(1j * phi)
        u = (a - c) / abs(a - c)
        d = c + 0.65 * u
        e = complex(d.real + math.sqrt(0.2**2 - (0.64 - d.imag) ** 2), 0.64)
        return {"O": o, "C": c, "A": a, "D": d, "E": e, "S2": o + 0.03 * np.exp(1j * phi), "S4": c + 0.325 * u,
                "S5": d + 0.5 * (e - d)}

    @staticmethod
    def angles(p: dict[str, complex]) -> dict[int, float]:
        lever = np.angle(p["A"] - p["C"])
        return {2: np.angle(p["A"] - p["O"]), 3: lever, 4: lever, 5: np.angle(p["E"] - p["D"]), 6: 0.0}

    @staticmethod
    def load(share: float) -> float:
        """F6 along the guide: 2000 N against the cutting stroke over shares 0.05..0.95 of it."""
        return -2000.0 if 0.05 <= share <= 0.95 else 0.0


class Press:
    """The press above from its numbers: OA, the rocker's B where AB and CB meet, D on CB, E under D on x = 0.33."""

    omega = -90.0 * 2 * math.pi / 60
    masses = MappingProxyType({2: (5.0, 0.01, "S2"), 3: (6.0, 0.05, "S3"), 4: (8.0, 0.09, "S4"), 5: (5.0, 0.04, "S5"),
              6: (40.0, 0.0, "E")})
    guide = -1j
    slide_f = 0.12
    rho = MappingProxyType({"O": 0.08 * 0.025, "A": 0.002, "B": 0.002, "C": 0.002, "D": 0.002, "E": 0.002})
    revolutes = (("O", 1, 2), ("A", 2, 3), ("B", 3, 4), ("C", 1, 4), ("D", 4, 5), ("E", 5, 6))

    @staticmethod
    def points(phi: float) -> dict[str, complex]:
        o, c = 0j, 0.3 + 0j
        a = 0.08 * np.exp(1j * phi)
        span = abs(c - a)
        along = (0.30**2 - 0.25**2 + span**2) / (2 * span)
        # B to the right of A→C, the scene's assembly.
        b = a + (c - a) / span * complex(along, -math.sqrt(0.30**2 - along**2))
        d = c + 0.35 * (b - c) / 0.25
        e = complex(0.33, d.imag - math.sqrt(0.30**2 - (0.33 - d.real) ** 2))
        return {"O": o, "C": c, "A": a, "B": b, "D": d, "E": e, "S2": 0.02 * np.exp(1j * phi),
                "S3": a + 0.5 * (b - a), "S4": c + 0.15 * (b - c) / 0.25, "S5": d + 0.5 * (e - d)}

    @staticmethod
    def angles(p: dict[str, complex]) -> dict[int, float]:
        return {2: np.angle(p["A"] - p["O"]), 3: np.angle(p["B"] - p["A"]), 4: np.angle(p["B"] - p["C"]),
                5: np.angle(p["E"] - p["D"]), 6: 0.0}

    @staticmethod
    def load(share: float) -> float:
        """The pressing force, up against the guide, from the diagram: 0 at half the stroke, 6000 N from 0.8 on."""
        return -float(np.interp(share, [0.5, 0.8, 1.0], [0.0, 6000.0, 6000.0], left=0.0, right=0.0))


def motion_of(machine, phi: float):
    """Positions, velocities and accelerations of the points, ω and ε of the links, by central differences."""
    step = 1e-4
    samples = [machine.points(phi + k * step * machine.omega) for k in (-2, -1, 0, 1, 2)]
    first = np.array([1, -8, 0, 8, -1]) / (12 * step)
    second = np.array([-1, 16, -30, 16, -1]) / (12 * step**2)
    points = samples[2]
    v = {name: sum(w * s[name] for w, s in zip(first, samples, strict=True)) for name in points}
    a = {name: sum(w * s[name] for w, s in zip(second, samples, strict=True)) for name in points}
    turns = [machine.angles(s) for s in samples]
    omega = {k: float(first @ np.unwrap([t[k] for t in turns])) for k in turns[0]}
    epsilon = {k: float(second @ np.unwrap([t[k] for t in turns])) for k in turns[0]}
    return points, v, a, omega | {1: 0.0}, epsilon | {1: 0.0}


def share_of_stroke(machine, phi: float) -> float:
    """How far the ram is along its working stroke (the way it goes along its guide), 0 at its start."""
    travel = [(machine.points(x)["E"] * machine.guide.conjugate()).real for x in np.linspace(0, 2 * math.pi, 7201)]
    here = (machine.points(phi)["E"] * machine.guide.conjugate()).real
    return (here - min(travel)) / (max(travel) - min(travel))


def cross(r: complex, f: complex) -> float:
    return r.real * f.imag - r.imag * f.real


def statics(machine, phi: float, friction: bool = True) -> dict:
    """Every moving link's ΣFx, ΣFy, ΣM = 0 as one linear system: the turning pairs' reactions, the ram's normal
    reaction N16 and its couple N16·x on the guide, the shaper's block's normal reaction and couple in its slot,
    and Mb; the friction loads from the reactions of the solve before, to a fixed point."""
    p, v, a, omega, epsilon = motion_of(machine, phi)
    working = (v["E"] * machine.guide.conjugate()).real > 0  # the working stroke is forward along the guide
    force6 = machine.load(share_of_stroke(machine, phi)) * machine.guide if working else 0j
    slot = None
    if "B" not in p:  # the shaper: block 3 in the slot of lever 4, the slot's normal through A
        slot = 1j * (p["A"] - p["C"]) / abs(p["A"] - p["C"])
    # The shaper's crank pin A turns in its block without friction; the press's pairs are all in its list.
    revolutes = list(machine.revolutes) + ([("A", 2, 3)] if slot is not None else [])
    names = [f"R{i}{j}" for _, i, j in revolutes]
    columns = {name: 2 * k for k, name in enumerate(names)}
    extra = ["N16", "N16x", "Mb"] + (["N43", "N43x"] if slot is not None else [])
    for name in extra:
        columns[name] = len(columns) + len(names)
    size = 2 * len(names) + len(extra)
    links = [2, 3, 4, 5, 6]
    row = {k: 3 * n for n, k in enumerate(links)}
    rho = {joint: (machine.rho.get(joint, 0.0) if friction else 0.0) for joint, _, _ in revolutes}
    slide_f = machine.slide_f if friction else 0.0
    reactions = {name: 0j for name in names}
    normal = 0.0
    for _ in range(200):
        matrix, rhs = np.zeros((3 * len(links), size)), np.zeros(3 * len(links))

        def force(link, column, direction, at, matrix=matrix):
            """A reaction's unknown component on ``link`` (its moment about the origin, at ``at``)."""
            if link == 1:
                return
            r = row[link]
            matrix[r, column] += direction.real
            matrix[r + 1, column] += direction.imag
            matrix[r + 2, column] += cross(at, direction)

        def known(link, value, at, moment=0.0, rhs=rhs):
            if link == 1:
                return
            r = row[link]
            rhs[r] -= value.real
            rhs[r + 1] -= value.imag
            rhs[r + 2] -= cross(at, value) + moment

        for (joint, i, j), name in zip(revolutes, names, strict=True):
            for component, direction in ((0, 1 + 0j), (1, 1j)):
                force(j, columns[name] + component, direction, p[joint])   # Rij on j
                force(i, columns[name] + component, -direction, p[joint])  # Rji = −Rij on i
            turning = -np.sign(omega[j] - omega[i]) * rho[joint] * abs(reactions[name])
            known(j, 0j, 0j, turning)
            known(i, 0j, 0j, -turning)
        across = 1j * machine.guide
        force(6, columns["N16"], across, p["E"])
        matrix[row[6] + 2, columns["N16x"]] += 1.0  # the couple N16·x: the normal force shifted along the guide
        rubbing = -np.sign((v["E"] * machine.guide.conjugate()).real) * slide_f * abs(normal) * machine.guide
        known(6, rubbing, p["E"])
        if slot is not None:
            force(3, columns["N43"], slot, p["A"])
            force(4, columns["N43"], -slot, p["A"])
            matrix[row[3] + 2, columns["N43x"]] += 1.0
            matrix[row[4] + 2, columns["N43x"]] -= 1.0
        matrix[row[2] + 2, columns["Mb"]] += 1.0
        for link, (mass, inertia, centre) in machine.masses.items():
            known(link, -1j * mass * GRAVITY - mass * a[centre], p[centre], -inertia * epsilon[link])
        known(6, force6, p["E"])
        solution = np.linalg.lstsq(matrix, rhs, rcond=None)[0]
        assert np.abs(matrix @ solution - rhs).max() < 1e-8
        found = {name: complex(solution[columns[name]], solution[columns[name] + 1]) for name in names}
        settled = all(abs(found[name] - reactions[name]) < 1e-11 * (1 + abs(found[name])) for name in names)
        reactions, normal = found, float(solution[columns["N16"]])
        if settled:
            break
    loads = {f"Mf{i}{j}": -np.sign(omega[j] - omega[i]) * rho[joint] * abs(reactions[f"R{i}{j}"])
             for joint, i, j in revolutes if rho[joint]}
    loads["Ff16"] = -np.sign((v["E"] * machine.guide.conjugate()).real) * slide_f * abs(normal) * machine.guide
    # The power balance, Zhukovsky's lever's own statement: every load's power with the friction's, and Mb's.
    power = sum((-1j * mass * GRAVITY - mass * a[centre]) * np.conj(v[centre]) for mass, _, centre in
                machine.masses.values()).real
    power += sum(-inertia * epsilon[link] * omega[link] for link, (_, inertia, _) in machine.masses.items())
    power += (force6 * np.conj(v["E"])).real + (loads["Ff16"] * np.conj(v["E"])).real
    power += sum(loads[f"Mf{i}{j}"] * (omega[j] - omega[i]) for joint, i, j in revolutes if rho[joint])
    return {"reactions": reactions | {"R16": normal * across}, "offset": solution[columns["N16x"]] / normal,
            "Mb": float(solution[columns["Mb"]]), "lever": -power / machine.omega, "loads": loads,
            "F6": force6, "vE": v["E"]}


def crank_angle(position) -> float:
    return float(np.angle(position.positions["A"] - position.positions["O"]))


_analyses = {}


def analysis_of(name: str):
    if name not in _analyses:
        text = {"shaper": shaper_text, "press": lambda: PRESS}[name]()
        _analyses[name] = with_length_scale(analyse(load_text(text)))
    return _analyses[name]


MACHINES = {"shaper": Shaper, "press": Press}
CASES = [(name, k) for name in MACHINES for k in (0, 1)]


@pytest.fixture(params=CASES, ids=[f"{name}-{k}" for name, k in CASES])
def case(request):
    """(machine, analysis, plan position, this file's statics with friction there)."""
    name, k = request.param
    analysis = analysis_of(name)
    position = analysis.plans[k]
    return MACHINES[name], analysis, position, statics(MACHINES[name], crank_angle(position))


def test_the_polygons_with_friction_give_the_reactions_and_mb_of_the_statics_worked_here(case):
    _, _, position, own = case
    found = position.with_friction.reactions
    for name, force in own["reactions"].items():
        drawn = found[name].force if name in found else -found[f"R{name[2]}{name[1]}"].force
        assert drawn == pytest.approx(force, rel=1e-6, abs=1e-6 * abs(own["F6"]) + 1e-6), name
    assert position.with_friction.balancing == pytest.approx(own["Mb"], rel=1e-6)
    # And the statics without friction gives the polygons without it: the friction's share is no rounding.
    ideal = statics(case[0], crank_angle(position), friction=False)
    assert position.forces.balancing == pytest.approx(ideal["Mb"], rel=1e-6)
    assert abs(own["Mb"] - ideal["Mb"]) > 0.03 * abs(ideal["Mb"])


def test_the_ram_s_friction_is_f_times_the_polygon_s_normal_reaction_against_its_velocity(case):
    machine, _, position, own = case
    rubbing = next(load for group in position.with_friction.groups for load in group.loads if load.name == "Ff16")
    normal = position.with_friction.reactions["R16"].force
    assert abs(rubbing.force) == pytest.approx(machine.slide_f * abs(normal), rel=1e-12)
    assert (rubbing.force * np.conj(own["vE"])).real < 0
    assert abs((rubbing.force * np.conj(machine.guide)).imag) < 1e-9 * abs(rubbing.force)
    assert rubbing.force == pytest.approx(own["loads"]["Ff16"], rel=1e-6)
    for name, moment in own["loads"].items():
        if name.startswith("Mf"):
            drawn = next(load.moment for group in position.with_friction.groups for load in group.loads
                         if load.name == name)
            assert drawn == pytest.approx(moment, rel=1e-6), name


def test_f6_and_ff16_follow_each_other_end_to_end_on_the_polygon_and_r16_closes_it_after(case):
    _, _, position, own = case
    if own["F6"] == 0:
        pytest.skip("no pressing force at this position")
    group = next(group for group in position.with_friction.groups if 6 in group.links)
    vectors = {vector.name: vector for vector in group.polygon.vectors}
    names = [vector.name for vector in group.polygon.vectors]
    assert names.index("Ff16") == names.index("F6") + 1
    assert vectors["F6"].end == pytest.approx(vectors["Ff16"].start, abs=1e-9 * abs(own["F6"]))
    # The stroke's ends here are a 0.05° grid's: the diagram's value read at its share agrees to some 10⁻⁸.
    assert vectors["F6"].end - vectors["F6"].start == pytest.approx(own["F6"], rel=1e-6)
    assert vectors["Ff16"].end - vectors["Ff16"].start == pytest.approx(own["loads"]["Ff16"], rel=1e-6)
    # The pressing stroke: the friction adds to the force the ram works against.
    assert (vectors["Ff16"].end - vectors["Ff16"].start) * np.conj(own["F6"]) == pytest.approx(
        abs(own["loads"]["Ff16"]) * abs(own["F6"]), rel=1e-6)


def test_the_lever_with_friction_gives_the_power_balance_worked_here(case):
    _, _, position, own = case
    assert position.lever_with_friction.balancing == pytest.approx(own["lever"], rel=1e-6)
    assert own["lever"] == pytest.approx(own["Mb"], rel=1e-9)


def ram_equation(analysis, position) -> str:
    layers = force_layout.layout(force_sheet(analysis, position, True))
    group = force_layout.group_id(next(g for g in position.with_friction.groups if 6 in g.links).label)
    caption = " ".join(item.text for layer in layers if layer.name == f"body-{group}-caption"
                       for item in layer.items)
    return caption[caption.index("ΣME(6):"):]


def test_the_ram_s_moment_equation_on_the_sheet_balances_read_with_the_numbers_it_writes(case):
    """ΣME(6): R16·x − Mf56 = 0, x = 3.301 mm: the couple of the normal reaction, shifted along the guide, holds
    the pin's friction moment Mf56; read with R16 and x as written (arms are lengths), its terms cancel.  On the
    press's downward guide the offset along the guide, −3.301 mm, was written for x under a +R16·x."""
    _, analysis, position, own = case
    line = ram_equation(analysis, position)
    match = re.match(r"ΣME\(6\): (−?)R16·x ([+−]) Mf56 = 0,\s+x = (\d+(?:\.\d+)?) mm", line)
    assert match, line
    arm = float(match.group(3)) / 1000.0
    assert arm == pytest.approx(abs(own["offset"]), rel=1e-3)
    normal, rubbing = abs(own["reactions"]["R16"]), abs(own["loads"]["Mf56"])
    total = (-1 if match.group(1) else 1) * normal * arm + (-1 if match.group(2) == "−" else 1) * rubbing
    assert abs(total) < 1e-3 * rubbing, line


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_a_run_writes_the_press_s_friction_as_the_statics_worked_here_gives_it(tmp_path, locale):
    scene = tmp_path / "press.toml"
    scene.write_text(PRESS, encoding="utf-8")
    out = tmp_path / "out"
    # --sheet none: choosing μl by laying out course sheets this run does not write was most of it, and each file it
    # writes is the same bytes without it (diffed once).
    assert main(["run", str(scene), "--out", str(out), "--locale", locale, "--only", "forces,lever,note",
                 "--sheet", "none"]) == 0
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    analysis = analysis_of("press")
    for position in analysis.plans:
        own = statics(Press, crank_angle(position))
        written = next(p for p in results["positions"] if p["index"] == position.number)["forces"]["friction"]
        assert written["balancing_moment"] == pytest.approx(own["Mb"], rel=1e-6)
        assert written["lever_balancing_moment"] == pytest.approx(own["lever"], rel=1e-6)
        assert complex(*written["loads"]["Ff16"]) == pytest.approx(own["loads"]["Ff16"], rel=1e-6)
        assert complex(*written["reactions"]["R16"]) == pytest.approx(own["reactions"]["R16"], rel=1e-6)
        sheet = flat((out / f"forces_friction_{position.number}.svg").read_text(encoding="utf-8"))
        written_arm = re.search(r"x = (−?[\d.,]+)", sheet[sheet.index("ΣME(6)"):]).group(1)
        assert float(written_arm.replace(",", ".").replace("−", "-")) == pytest.approx(1000.0 * abs(own["offset"]),
                                                                                      rel=1e-3)


ARM = re.compile(r"h\d+ = [\d.]+ mm")


def test_the_lever_s_arms_listed_over_several_lines_are_parted_by_commas_at_each_break():
    """Five arms left unlettered on the shaper's lever with friction: listed four to a line, the fourth ran on to
    the fifth with no comma between ("h14 = 6.917 mm,  h17 = 6.917 mm" over "h18 = 19.22 mm").  Those two were one
    arm, now named once, and fewer are left unlettered at the scale the lever is drawn at: it is also drawn smaller,
    as a small sheet draws it, where more arms crowd the pole."""
    listed = 0
    for name in MACHINES:
        analysis = analysis_of(name)
        for position, smaller in itertools.product(analysis.plans, (1.0, 2.0, 3.0)):
            sheet = force_sheet(analysis, position, True)
            sheet = dataclasses.replace(sheet, lever_scale=sheet.lever_drawn_scale * smaller)
            layers = force_layout.layout(sheet)
            lines = [item.text for layer in layers if layer.name == "lever-caption" for item in layer.items]
            arms = [line for line in lines if ARM.fullmatch(line.rstrip(",").split(",  ")[-1].strip())]
            for line, after in itertools.pairwise(lines):
                if line in arms and after in arms:
                    assert line.endswith(","), (line, after)
            listed = max(listed, sum(len(ARM.findall(line)) for line in arms))
    assert listed > 4  # more than the four a caption line lists: the break between the lists is seen


def test_a_couple_alone_on_a_guide_is_written_signed_as_the_note_writes_it(tmp_path):
    """The Scotch yoke's guide at B holds R34's moment with R14 = 0, a couple alone with no line and no x: the note
    writes ΣMB(4) = R14·x + 95.518 = 0 ⇒ R14·x = −95.518, R14·x the couple, signed.  The sheet's sign turned by the
    moment, as for an x it writes as a length, wrote −R14·x + M(R34) = 0 beside it: R14·x = +95.518.  The sheet
    gives the couple's value, as the note does."""
    analysis = analyse(load_text(Path("fixtures/scotch_yoke.toml").read_text(encoding="utf-8")))
    checked = 0
    for position in analysis.plans:
        equation = next(each for group in position.forces.groups for each in group.moments
                        if each.unknown == "R14·x")
        if equation.value == 0:
            continue
        others = sum(term.moment for term in equation.terms)
        assert math.isclose(equation.value, -others, rel_tol=1e-12)   # the couple is the rest's moment turned round
        layers = force_layout.layout(force_sheet(analysis, position))
        caption = " ".join(item.text for layer in layers if layer.name.endswith("-caption") for item in layer.items)
        line = re.search(r"ΣMB\(4\):[^=]*= 0", caption).group(0)
        # R14·x + M(R34) = 0 with M(R34) signed by its moment: R14·x = −M(R34), the value the note gives.
        sign = re.match(r"ΣMB\(4\): (−?)R14·x ([+−]) M\(R34\) = 0$", line)
        assert sign is not None, line
        assert sign.group(1) == ""
        assert (sign.group(2) == "+") == (others > 0)
        # and gives the couple's value, saying why R14 has no line: the sheet once wrote the equation bare.
        written = re.search(r"R14·x = (−?\d+(?:\.\d+)?) N·m,\s+R14 = 0: the guide holds a couple alone", caption)
        assert written is not None, caption
        assert float(written.group(1).replace("−", "-")) == pytest.approx(equation.value, rel=1e-3)
        checked += 1
    assert checked == 2


def test_x_is_written_for_a_reaction_too_short_to_draw_as_the_note_writes_it(case):
    """Whether R16·x comes with its x is the analysis's word (the reaction nought, a couple alone, or not), not the
    drawing's: at a μF that draws R16 shorter than a line can show, the sheet dropped x and its sign, where the note
    beside it writes x = 3.301 mm."""
    _, analysis, position, own = case
    friction = position.with_friction
    group = next(each for each in friction.groups if any(found.name == "R16" for found in each.found))
    reaction = next(found for found in group.found if found.name == "R16")
    undrawable = 10.0 * abs(reaction.force) / ZERO_MM    # R16 drawn 0.1 mm long
    shrunk = dataclasses.replace(position, with_friction=friction.at_scale(undrawable))
    line = ram_equation(analysis, shrunk)
    match = re.match(r"ΣME\(6\): −?R16·x [+−] Mf56 = 0,\s+x = (\d+(?:\.\d+)?) mm", line)
    assert match, line
    assert float(match.group(1)) / 1000.0 == pytest.approx(abs(own["offset"]), rel=1e-3)
