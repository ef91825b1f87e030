"""The works over the cycle, integrated between the places where the loads switch or turn a corner.

A machine whose driving and resisting work balance exactly must be taken as balanced: the trapezoid over 360
steps left 3e-5…7e-5 of the work, 30 to 70 times the balance the flywheel asked for, and told the student to add
a moment of the quadrature's error.  Checked against works known in closed form: a crank-rocker whose rocker
resists 1500 N·m over its working stroke does 1500·ψ (ψ its swing, from the law of cosines at the two positions
where crank and coupler lie on one line), an engine's indicator diagram 2r·∫p dx (its area, exact for the
straight lines between its vertices); and the crank-rocker's flywheel against the energy–mass diagram's tangents
worked out here on 72 000 steps of the turn.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scene_texts import engine
from scipy.integrate import cumulative_trapezoid
from scipy.optimize import brentq

from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.machine_dynamics import MachineDynamics
from graphplan.scene import loads

CRANK, COUPLER, ROCKER, FRAME = 0.175, 0.55, 0.325, 0.55   # m; O at the origin, C at (0, 0.55)
CENTRES = {2: 0.08, 3: 0.24, 4: 0.14}                       # m from O, A and C along their links
MASSES = {2: (8.0, 0.05), 3: (17.0, 0.51), 4: (17.0, 0.18)}
RESISTANCE = 1500.0
OMEGA = -17.0
G = 9.81

CRANK_ROCKER = f"""
[scene]
title = "Crank-rocker"
gravity = {G}

[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [0.0, {FRAME}] }}

[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = {CRANK}
omega = {OMEGA}

[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [{COUPLER}, {ROCKER}]
assembly = "left"

[points]
S2 = {{ link = 2, from = "O", toward = "A", at = {CENTRES[2]} }}
S3 = {{ link = 3, from = "A", toward = "B", at = {CENTRES[3]} }}
S4 = {{ link = 4, from = "C", toward = "B", at = {CENTRES[4]} }}

[links.2]
mass = {MASSES[2][0]}
centre = "S2"
inertia = {MASSES[2][1]}
[links.3]
mass = {MASSES[3][0]}
centre = "S3"
inertia = {MASSES[3][1]}
[links.4]
mass = {MASSES[4][0]}
centre = "S4"
inertia = {MASSES[4][1]}

[[loads]]
kind = "moment"
link = 4
value = {RESISTANCE}
resisting = true
during = "working"

[positions]
count = 12
start = "extreme"
number_from = 0
working = {{ link = 4, sense = "ccw" }}

[drawing]
sheet = "none"
"""


def swing() -> float:
    """ψ of the rocker: at its extremes crank and coupler lie on one line, OB = coupler ± crank, and the rocker's
    angle from CO follows from the triangle OCB by the law of cosines."""
    def from_frame(reach):
        return math.acos((FRAME ** 2 + ROCKER ** 2 - reach ** 2) / (2 * FRAME * ROCKER))
    return from_frame(COUPLER + CRANK) - from_frame(COUPLER - CRANK)


def given_moment(share: float = 1.0) -> str:
    """The motor's moment on the crank, given: the work 1500·ψ over the turn, clockwise as the crank turns."""
    return (f'\n[[loads]]\nkind = "moment"\nlink = 2\nvalue = {-share * RESISTANCE * swing() / (2 * math.pi)!r}\n'
            'resisting = false\n')


def test_a_crank_rocker_whose_given_driving_moment_balances_its_resistance_is_taken_as_balanced():
    dynamics = MachineDynamics(analyse(loads(CRANK_ROCKER + given_moment()
                                             + '\n[dynamics]\ndelta = 0.05\nconstant = "none"\n')))
    model, work = dynamics.model, RESISTANCE * swing()
    assert model.constant == "none"
    assert model.resisting_work[-1] == pytest.approx(work, rel=1e-8)
    assert model.driving_work[-1] == pytest.approx(work, rel=1e-10)
    assert dynamics.flywheel is not None and dynamics.flywheel.inertia > 0


def test_a_crank_rocker_off_its_balance_by_a_thousandth_is_refused_with_the_moment_that_balances_it():
    with pytest.raises(SceneError) as refused:
        MachineDynamics(analyse(loads(CRANK_ROCKER + given_moment(0.999)
                                      + '\n[dynamics]\ndelta = 0.05\nconstant = "none"\n')))
    missing = 0.001 * RESISTANCE * swing()
    assert f"differ by {-missing:.4g}" in str(refused.value)
    # The moment that makes up the work left over, clockwise as the crank turns.
    assert f"value = {-missing / (2 * math.pi):.5g}" in str(refused.value)


ENGINE = engine() + """
[positions]
count = 12
start = "extreme"
working = { link = 4, sense = "backward" }

[drawing]
sheet = "none"
"""
EXPANSION = ([0.0, 0.1, 0.3, 0.6, 1.0], [9000.0, 7000.0, 4000.0, 2000.0, 800.0])
COMPRESSION = ([0.0, 0.5, 0.8, 1.0], [200.0, 500.0, 1200.0, 2500.0])
STROKE = 2 * 0.05


def test_an_engine_whose_consumer_takes_its_indicator_diagrams_work_is_taken_as_balanced():
    # The gas's work over the cycle: the stroke times the area between the two lines of the indicator diagram.
    work = STROKE * float(np.trapezoid(EXPANSION[1], EXPANSION[0]) - np.trapezoid(COMPRESSION[1], COMPRESSION[0]))
    assert work == pytest.approx(256.0, rel=1e-15)
    consumer = f'\n[[loads]]\nkind = "moment"\nlink = 2\nvalue = {work / (2 * math.pi)!r}\nresisting = true\n'
    dynamics = MachineDynamics(analyse(loads(ENGINE + consumer + "\n[dynamics]\ndelta = 0.02\n")))
    model = dynamics.model
    assert model.constant == "none"
    assert model.driving_work[-1] == pytest.approx(work, rel=1e-8)
    assert model.resisting_work[-1] == pytest.approx(work, rel=1e-10)
    assert dynamics.flywheel is not None
    # The same engine with its consumer left out, taken constant: it takes the same work (the weights none).
    alone = MachineDynamics(analyse(loads(ENGINE + "\n[dynamics]\ndelta = 0.02\n"))).model
    assert alone.constant == "resisting"
    assert alone.resisting_work[-1] == pytest.approx(work, rel=1e-8)


def test_the_note_gives_the_constant_resisting_moment_that_takes_the_indicator_diagrams_work(tmp_path):
    # The weights stay on the resisting side: a mean over the samples weighed their moment twice at each switch.
    work = STROKE * float(np.trapezoid(EXPANSION[1], EXPANSION[0]) - np.trapezoid(COMPRESSION[1], COMPRESSION[0]))
    scene = tmp_path / "engine.toml"
    scene.write_text(ENGINE + "\n[dynamics]\ndelta = 0.02\n", encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "dynamics,note"]) == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    told = re.search(r"Mr = Ad/2π = ([\d.]+) N·m", note)
    assert float(told[1]) == pytest.approx(work / (2 * math.pi), abs=0.0015)


def _crank_rocker_turn(count: int):
    """The crank-rocker's Je and ΔT over a turn of the crank from the start of the rocker's working stroke, on
    ``count`` steps: B by the two circles' crossing to the left of A→C, rates by central differences."""
    frame = FRAME * 1j

    def joint(phi):
        a = CRANK * np.exp(1j * phi)
        span = frame - a
        along = (COUPLER ** 2 - ROCKER ** 2 + abs(span) ** 2) / (2 * abs(span))
        across = np.sqrt(COUPLER ** 2 - along ** 2)
        return a, a + (along + 1j * across) * span / abs(span)

    def centres(phi):
        a, b = joint(phi)
        return {2: CENTRES[2] * np.exp(1j * phi), 3: a + CENTRES[3] * (b - a) / COUPLER,
                4: frame + CENTRES[4] * (b - frame) / ROCKER}

    def angles(phi):
        a, b = joint(phi)
        return {2: phi, 3: np.angle(b - a), 4: np.angle(b - frame)}

    def rate(function, phi, h=1e-6):
        ahead, behind = function(phi + h), function(phi - h)
        return {k: (ahead[k] - behind[k]) / (2 * h) for k in ahead}

    def rocker_rate(phi):
        return rate(angles, phi)[4]
    # The rocker turns back where its rate crosses nought; the crank turns clockwise, so the working (ccw) stroke
    # begins where dθ4/dφ goes from positive to negative.
    grid = np.radians(np.arange(0.0, 360.0, 1.0))
    signs = np.sign(rocker_rate(grid))
    first = next(k for k in range(len(grid) - 1) if signs[k] > 0 > signs[k + 1])
    start = brentq(rocker_rate, grid[first], grid[first + 1], xtol=1e-14)

    travel = np.linspace(0.0, 2 * math.pi, count + 1)
    phi = start - travel                                  # d/dψ = −d/dφ
    velocities = {k: -v for k, v in rate(centres, phi).items()}
    turning = {k: -w for k, w in rate(angles, phi).items()}
    inertia = sum(MASSES[k][0] * abs(velocities[k]) ** 2 + MASSES[k][1] * turning[k] ** 2 for k in MASSES)
    weights = -G * sum(MASSES[k][0] * velocities[k].imag for k in MASSES)
    resisting = weights - RESISTANCE * np.maximum(turning[4], 0.0)   # only while the rocker turns ccw
    taken = -cumulative_trapezoid(resisting, travel, initial=0.0)
    driving = taken[-1] / (2 * math.pi)
    return travel, inertia, driving * travel - taken


def test_the_crank_rockers_flywheel_is_the_energy_mass_diagrams_worked_out_on_a_fine_turn():
    delta, omega = 0.001, abs(OMEGA)
    dynamics = MachineDynamics(analyse(loads(CRANK_ROCKER + f"\n[dynamics]\ndelta = {delta}\n")))
    _, inertia, energy = _crank_rocker_turn(72_000)
    assert dynamics.model.driving[0] == pytest.approx(RESISTANCE * swing() / (2 * math.pi), rel=1e-8)
    fastest, slowest = 0.5 * (omega * (1 + delta / 2)) ** 2, 0.5 * (omega * (1 - delta / 2)) ** 2
    flywheel = (np.max(energy - fastest * inertia) - np.min(energy - slowest * inertia)) / (fastest - slowest)
    # The model's 1° samples miss the tangents' touch points and ΔT's extremes by up to ½·M′·(h/2)²; its works,
    # integrated by the trapezoid, were off by 3e-5 of the work (J_F 3335.70 for 3335.83, ΔWmax 953.52 for 953.57).
    assert dynamics.flywheel.inertia == pytest.approx(flywheel, rel=1e-5)
    assert dynamics.flywheel.delta_w_max == pytest.approx(np.ptp(energy), rel=3e-5)
