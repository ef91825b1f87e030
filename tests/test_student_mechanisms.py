"""Four textbook mechanisms a student writes from the docs alone (none of them a fixture): a Whitworth
quick-return, a Watt II six-bar, an oscillating cylinder with a point of interest on its piston rod, and a
crank-rocker with masses, a resisting moment and friction. Their velocities and accelerations are checked against
central differences of positions solved here by hand, and the balancing moment against the power balance
Mb·ω1 = −Σ(F·v + M·ω)."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scene_texts import oscillating_cylinder, watt_ii

import graphplan

H = 1e-5  # rad of the crank for the central differences


def _circle_cross(p: np.ndarray, rp: float, q: np.ndarray, rq: float, left: bool) -> np.ndarray:
    """The point rp from p and rq from q, to the left of p→q where ``left``."""
    d = q - p
    length = math.hypot(*d)
    u = d / length
    n = np.array([-u[1], u[0]])
    x = (rp * rp - rq * rq + length * length) / (2 * length)
    h = math.sqrt(rp * rp - x * x)
    return p + x * u + (h if left else -h) * n


def _crank(phi: float, length: float) -> np.ndarray:
    return length * np.array([math.cos(phi), math.sin(phi)])


def _differences(positions, phi: float, omega: float) -> tuple[dict, dict]:
    """v and a of every point by central differences of ``positions`` in time, the crank turning at ``omega``."""
    here, ahead, behind = positions(phi), positions(phi + H), positions(phi - H)
    v = {name: (ahead[name] - behind[name]) / (2 * H) * omega for name in here}
    a = {name: (ahead[name] - 2 * here[name] + behind[name]) / H**2 * omega**2 for name in here}
    return v, a


def _check_kinematics(scene_text: str, positions, omega: float) -> None:
    scene = graphplan.load_text(scene_text)
    motion = scene.solve()
    for index, phi in enumerate(np.asarray(motion.driver)):
        v, a = _differences(positions, float(phi), omega)
        for name in v:
            point = motion.point(name)
            assert point.r[index] == pytest.approx(positions(float(phi))[name], abs=1e-12), (name, index)
            assert point.v[index] == pytest.approx(v[name], abs=1e-6 * max(1.0, np.abs(v[name]).max())), (name, index)
            assert point.a[index] == pytest.approx(a[name], abs=2e-3 * max(1.0, np.abs(a[name]).max())), (name, index)




def _oscillating_cylinder(offset: float):
    def positions(phi: float) -> dict[str, np.ndarray]:
        """The rod 3 slides in the cylinder 4 pivoted at C; its slide line runs ``offset`` to the left of C
        looking along the cylinder toward A: A − C = (s + i·e)·u. E is 0.12 m from A along the rod toward C's
        side and 0.03 m to the left of that direction."""
        a = _crank(phi, 0.08)
        ca = complex(a[0] - 0.30, a[1])
        u = ca / (math.sqrt(abs(ca) ** 2 - offset**2) + 1j * offset)
        e = complex(*a) + (0.12 + 0.03j) * -u
        return {"A": a, "E": np.array([e.real, e.imag])}
    return positions


@pytest.mark.parametrize("offset", [0.0, 0.02])
def test_a_point_on_an_oscillating_cylinders_piston_rod(offset):
    """The piston rod (the RPR's block, whose only joint is A) turns with the cylinder, so the slide's line is fixed
    in it: a coupler point on the rod is placed from A toward the cylinder's pivot C. Refused before ('C' is not a
    point of link 3), with no way to name a point of the rod at all."""
    text = oscillating_cylinder(offset)
    _check_kinematics(text, _oscillating_cylinder(offset), 120 * 2 * math.pi / 60)
    plan = graphplan.load_text(text).plan(4)
    assert plan.values["VE"] == pytest.approx(math.hypot(*graphplan.load_text(text).solve().point("E").v[3]), rel=1e-9)


WHITWORTH = """
[scene]
title = "Whitworth quick-return mechanism"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.0, -0.05] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
[[groups]]
kind = "RPR"
links = [3, 4]
joints = ["A", "C"]
[points]
D = { link = 4, from = "C", toward = "A", at = -0.12 }
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["D", "E"]
length = 0.35
guide = { through = [0.0, -0.05], angle = 0.0 }
assembly = "forward"
[positions]
count = 12
start = "extreme"
working = { link = 6, sense = "forward" }
plans = [2, 8]
"""


def _whitworth(phi: float) -> dict[str, np.ndarray]:
    """The lever turns round about C, 0.05 m under the crank's pivot; D on its tail 0.12 m behind C; the ram E on
    the level of C, ahead of D."""
    c = np.array([0.0, -0.05])
    a = _crank(phi, 0.1)
    d = c - 0.12 * (a - c) / math.hypot(*(a - c))
    return {"A": a, "D": d, "E": np.array([d[0] + math.sqrt(0.35**2 - (d[1] + 0.05) ** 2), -0.05])}


def test_whitworth_quick_return():
    _check_kinematics(WHITWORTH, _whitworth, 10.0)
    # K = φw/φi: the ram's extremes are where the lever lies along the guide, A on C's level, 120° of crank apart.
    strokes = graphplan.load_text(WHITWORTH).analyse().strokes
    idle = 2 * math.degrees(math.acos(0.05 / 0.1))
    assert strokes.time_ratio == pytest.approx((360 - idle) / idle, rel=1e-9)


WATT_II = watt_ii()


def _watt_ii(phi: float) -> dict[str, np.ndarray]:
    """Two four-bars in series: O-A-B-C, then D on the ternary rocker CBD drives D-E-F."""
    c, f = np.array([0.35, 0.0]), np.array([0.60, 0.25])
    a = _crank(phi, 0.10)
    b = _circle_cross(a, 0.35, c, 0.25, left=True)
    u = (b - c) / 0.25
    d = c + 0.12 * u - 0.10 * np.array([-u[1], u[0]])
    return {"A": a, "B": b, "D": d, "E": _circle_cross(d, 0.30, f, 0.20, left=False)}


def test_watt_ii_six_bar():
    _check_kinematics(WATT_II, _watt_ii, 12.0)


CRANK_ROCKER = """
[scene]
title = "Crank-rocker with a resisting moment"
gravity = 9.81
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.28, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.07
omega = 15.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.30, 0.18]
assembly = "left"
[points]
S2 = { link = 2, from = "O", toward = "A", at = 0.035 }
S3 = { link = 3, from = "A", toward = "B", at = 0.15 }
S4 = { link = 4, from = "C", toward = "B", at = 0.09 }
[links.2]
mass = 1.5
centre = "S2"
[links.3]
mass = 4.0
centre = "S3"
inertia = 0.03
[links.4]
mass = 2.5
centre = "S4"
inertia = 0.007
[[loads]]
kind = "moment"
link = 4
value = 30.0
resisting = true
during = "working"
[[friction]]
joint = "A"
f = 0.12
radius = 0.012
[[friction]]
joint = "B"
f = 0.12
radius = 0.01
[[friction]]
joint = "C"
f = 0.12
radius = 0.012
[[friction]]
joint = "O"
f = 0.12
radius = 0.015
[positions]
count = 12
start = "extreme"
working = { link = 4, sense = "ccw" }
plans = [3, 8]
"""


def _crank_rocker(phi: float) -> dict[str, np.ndarray]:
    c = np.array([0.28, 0.0])
    a = _crank(phi, 0.07)
    b = _circle_cross(a, 0.30, c, 0.18, left=True)
    # The angles ride along as points (x = the angle) so that the differences give ω and ε too.
    return {"S2": a / 2, "S3": (a + b) / 2, "S4": (b + c) / 2,
            "phi3": np.array([math.atan2(*(b - a)[::-1]), 0.0]), "phi4": np.array([math.atan2(*(b - c)[::-1]), 0.0])}


def test_crank_rocker_balancing_moment_by_the_power_balance():
    """Mb·ω1 = −Σ(F·v + M·ω): weights, d'Alembert's forces and moments, and 30 N·m against the rocker's ccw
    (working) turn; with friction, Mb·ω1 less the power without it is what the journals take, ρ·|R|·|Δω|."""
    scene = graphplan.load_text(CRANK_ROCKER)
    analysis = scene.analyse()
    omega1, g = 15.0, 9.81
    masses, inertias = {"S2": 1.5, "S3": 4.0, "S4": 2.5}, {"phi3": 0.03, "phi4": 0.007}
    for index, phi in enumerate(np.asarray(analysis.motion.driver)):
        v, a = _differences(_crank_rocker, float(phi), omega1)
        power = sum(m * np.array([0.0, -g]) @ v[s] - m * a[s] @ v[s] for s, m in masses.items())
        power -= sum(j * a[k][0] * v[k][0] for k, j in inertias.items())
        power -= 30.0 * max(v["phi4"][0], 0.0)
        assert analysis.equilibrium.balancing[index] == pytest.approx(-power / omega1, abs=1e-4), index
        omegas = {1: 0.0, 2: omega1, 3: v["phi3"][0], 4: v["phi4"][0]}
        journals = {"R12": 0.12 * 0.015, "R23": 0.12 * 0.012, "R34": 0.12 * 0.01, "R14": 0.12 * 0.012}
        lost = sum(rho * abs(analysis.with_friction.reaction(name).force[index])
                   * abs(omegas[int(name[1])] - omegas[int(name[2])]) for name, rho in journals.items())
        assert analysis.with_friction.balancing[index] == pytest.approx((-power + lost) / omega1, abs=1e-4), index


@pytest.mark.parametrize(("change", "told"), [
    # The RPR's joints in the other order: the block pinned at C, the lever turning about A.
    (('joints = ["A", "C"]', 'joints = ["C", "A"]'),
     "points.D.from: 'C' is not a point of link 4; its points are A; C is a point of the frame and of link 3"),
    # The lever's point under the block, which the note and results name, taken for a point fixed on the lever.
    (('toward = "A", at', 'toward = "A4", at'),
     ("points.D.toward: 'A4' is not a point of link 4; its points are C; A4 is link 4's point under A at each "
      "instant, a different point of it as A slides: give toward = 'A', the pin, whose slide gives the direction")),
])
def test_a_point_named_on_the_wrong_link_is_told_where_it_is(change, told):
    """Before, only "its points are A": nothing said where C was, so the slip (the group's joints in the other order,
    or the point's link number) had to be guessed."""
    with pytest.raises(graphplan.GraphplanError) as error:
        graphplan.load_text(WHITWORTH.replace(*change)).solve()
    assert str(error.value) == told


def test_a_point_of_the_rocker_given_the_couplers_number_is_told_the_rocker():
    with pytest.raises(graphplan.GraphplanError) as error:
        graphplan.load_text(WATT_II.replace('D = { link = 4', 'D = { link = 3')).solve()
    assert str(error.value) == ("points.D.from: 'C' is not a point of link 3; its points are A, B; "
                                "C is a point of the frame and of link 4")


def test_the_note_lays_off_the_whitworth_levers_tail_beyond_the_pole(tmp_path):
    """D on the lever's tail lies behind the pivot C from the block's A4, so on the velocity plan (the lever's
    images turned by 90° and scaled by ω4 about p, C's image) d lies beyond p from a4. The note gave only
    pd = pa4·lCD/lCA4, which a student lays off from p toward a4, on the wrong side."""
    scene = graphplan.load_text(WHITWORTH)
    c = np.array([0.0, -0.05])
    for phi in np.asarray(scene.solve().driver):
        where = _whitworth(float(phi))
        assert (where["D"] - c) @ (where["A"] - c) < 0
    scene.write(tmp_path / "out", only=["velocity", "acceleration", "note"])
    lines = [line for line in (tmp_path / "out" / "note.md").read_text(encoding="utf-8").splitlines()
             if line.startswith("- d: pd = pa4")]
    assert lines and all(line.endswith("; d lies on the line a4p beyond p, as D lies on A4C beyond C")
                         for line in lines), lines


def test_the_note_lays_off_the_piston_rods_point_from_its_one_image(tmp_path):
    """E on the rod turns with the cylinder: ae on the velocity plan is |vE − vA| (here by the differences) at μV.
    The note said only that its image "follows from that of link 4", leaving the student no length to lay off."""
    text = oscillating_cylinder(0.0)
    scene = graphplan.load_text(text)
    plan = scene.plan(4)
    v, _ = _differences(_oscillating_cylinder(0.0), float(scene.solve().driver[3]), 120 * 2 * math.pi / 60)
    scene.write(tmp_path / "out", only=["velocity", "acceleration", "note"])
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    line = next(line for line in note.splitlines() if line.startswith("- e: link 3 turns with link 4"))
    laid = re.search(r"ae = pa4·lAE/lCA4 = [0-9.·/]+ = ([0-9.]+) mm, turned from AE as pa4 is from CA4$", line)
    assert laid, line
    assert float(laid.group(1)) == pytest.approx(math.hypot(*(v["E"] - v["A"])) / plan.velocity.scale, abs=0.006)


def test_a_piston_rod_centred_off_its_pin_is_drawn_out_to_its_centre():
    """The rod 3 has one joint, A, and its centre E: leaving the centre out of its outline, as a link's centre inside
    it is, left the rod undrawn and its loads at E joined to nothing on the force sheet."""
    from graphplan.mechanism import build
    from graphplan.render.linkage import outline_points

    text = oscillating_cylinder(0.0) + """
[links.3]
mass = 3.0
centre = "E"
inertia = 0.02
[links.4]
mass = 5.0
centre = "C"
inertia = 0.05
"""
    scene = graphplan.load_text(text)
    assert outline_points(build(scene), scene.solve())[3] == ["A", "E"]
    # And its balancing moment by the power balance: the rod's weight, d'Alembert's force at E, and the couples
    # −J·ε of the rod and the cylinder, which turn together (C, the cylinder's centre, does not move).
    omega1 = 120 * 2 * math.pi / 60
    analysis = scene.analyse()
    for index, phi in enumerate(np.asarray(analysis.motion.driver)):
        v, a = _differences(_oscillating_cylinder(0.0), float(phi), omega1)
        (ahead, here, behind) = (_oscillating_cylinder(0.0)(float(phi) + step) for step in (H, 0.0, -H))
        turn = [math.atan2(0.0 - p["A"][1], 0.30 - p["A"][0]) for p in (ahead, here, behind)]
        omega = (turn[0] - turn[2]) / (2 * H) * omega1
        epsilon = (turn[0] - 2 * turn[1] + turn[2]) / H**2 * omega1**2
        power = 3.0 * np.array([0.0, -9.81]) @ v["E"] - 3.0 * a["E"] @ v["E"] - (0.02 + 0.05) * epsilon * omega
        assert analysis.equilibrium.balancing[index] == pytest.approx(-power / omega1, abs=1e-4), index


def test_a_wrong_toward_on_the_piston_rod_is_told_the_slide_it_may_follow():
    text = oscillating_cylinder(0.0).replace('toward = "C", at = 0.12', 'toward = "O", at = 0.12')
    with pytest.raises(graphplan.GraphplanError) as error:
        graphplan.load_text(text).solve()
    assert str(error.value) == ("points.E.toward: 'O' is not a point of link 3; its points are A (toward may also "
                                "name C, along the slide); O is a point of the frame and of link 2")
