"""Which side of the equivalent model a scene load is on: by its work over the run, not by its flag alone.

A load given as driving (``resisting = false``) that takes work over the run is a resistance: a payload given as
a force of fixed direction that a cylinder lifts, a force that opposes a wiper over its whole swing.  It goes to the
resisting side with the weights, and ``constant = "auto"`` then takes the driving side constant, the cylinder's
push or the lever's moment, which balances the run's work.  The works are checked against the geometry worked out
here from the scenes' numbers: for a force of fixed direction and value, W = F·Δr of its point; for the weights,
−m·g·Δy of each centre; for a moment against a rocker's motion, −M·∫|dθ|.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.dynamics import equivalent_model_of
from graphplan.scene import loads

ROOT = Path(__file__).resolve().parent.parent
GRAVITY = 9.81
SAMPLES = 720

TIPPER = """
[scene]
title   = "Tipping platform driven by a cylinder"
locale  = "en"
gravity = 9.81

[frame]
link = 1
points = { G = [0.05, 0.02], C = [0.40, 0.30] }

[driver]
kind         = "slider"
link         = 2
joint        = "A"
guide        = { through = "G", angle = 30.0 }
travel       = [0.05, 0.25]
velocity     = 0.12
acceleration = 0.3

[[groups]]
kind     = "RRR"
links    = [3, 4]
joints   = ["A", "B", "C"]
lengths  = [0.30, 0.18]
assembly = "right"

[points]
S3 = { link = 3, from = "A", toward = "B", at = 0.15 }
S4 = { link = 4, from = "C", toward = "B", at = 0.09 }
E  = { link = 4, from = "C", toward = "B", at = 0.05, offset = 0.10 }

[links.2]
mass    = 5.0
centre  = "A"
[links.3]
mass    = 2.0
centre  = "S3"
inertia = 0.02
[links.4]
mass    = 8.0
centre  = "S4"
inertia = 0.15

[[loads]]
kind      = "force"
link      = 4
point     = "E"
value     = 400.0
angle     = -90.0
resisting = false
during    = "always"

[positions]
count       = 9
number_from = 1
plans       = [2, 6]

[dynamics]
count = 81
"""

WIPER = """
[scene]
title   = "Windscreen wiper linkage (rocking crank)"
locale  = "en"
gravity = 9.81

[frame]
link   = 1
points = { O = [0.0, 0.0], C = [0.35, 0.05] }

[driver]
kind    = "crank"
link    = 2
pivot   = "O"
joint   = "A"
length  = 0.10
omega   = -3.0
epsilon = 5.0
swing   = [120.0, 40.0]

[[groups]]
kind     = "RRR"
links    = [3, 4]
joints   = ["A", "B", "C"]
lengths  = [0.32, 0.12]
assembly = "left"

[points]
S2 = { link = 2, from = "O", toward = "A", at = 0.05 }
S3 = { link = 3, from = "A", toward = "B", at = 0.16 }
S4 = { link = 4, from = "C", toward = "B", at = 0.06 }
W  = { link = 4, from = "C", toward = "B", at = 0.30, offset = 0.05 }

[links.2]
mass    = 0.8
centre  = "S2"
inertia = 0.001
[links.3]
mass    = 0.6
centre  = "S3"
inertia = 0.005
[links.4]
mass    = 1.2
centre  = "S4"
inertia = 0.03

[[loads]]
kind      = "force"
link      = 4
point     = "W"
value     = 30.0
angle     = 200.0
resisting = false
during    = "always"

[[loads]]
kind      = "moment"
link      = 4
value     = 2.0
resisting = true
during    = "always"

[positions]
count = 9
plans = [3, 7]
working = { link = 4, sense = "cw" }

[dynamics]
count = 81
"""


def joint_of_dyad(a: complex, c: complex, ab: float, bc: float, left: bool) -> complex:
    """B of the dyad A–B–C, on the side of the directed line A→C the assembly asks."""
    d = abs(c - a)
    along = (ab * ab - bc * bc + d * d) / (2 * d)
    across = math.sqrt(ab * ab - along * along)
    unit = (c - a) / d
    return a + unit * (along + (1j if left else -1j) * across)


def point_on(start: complex, toward: complex, at: float, offset: float = 0.0) -> complex:
    """The point ``at`` metres from ``start`` toward ``toward``, then ``offset`` metres to the left."""
    unit = (toward - start) / abs(toward - start)
    return start + unit * (at + 1j * offset)


def tipper_points(s: float) -> dict[str, complex]:
    g, c = complex(0.05, 0.02), complex(0.40, 0.30)
    a = g + s * complex(math.cos(math.radians(30.0)), math.sin(math.radians(30.0)))
    b = joint_of_dyad(a, c, 0.30, 0.18, left=False)
    return {"A": a, "S3": point_on(a, b, 0.15), "S4": point_on(c, b, 0.09), "E": point_on(c, b, 0.05, 0.10)}


def wiper_points(phi_deg: float) -> dict[str, complex]:
    c = complex(0.35, 0.05)
    a = 0.10 * complex(math.cos(math.radians(phi_deg)), math.sin(math.radians(phi_deg)))
    b = joint_of_dyad(a, c, 0.32, 0.12, left=True)
    return {"S2": point_on(0j, a, 0.05), "S3": point_on(a, b, 0.16), "S4": point_on(c, b, 0.06),
            "W": point_on(c, b, 0.30, 0.05), "theta4": complex(math.atan2((b - c).imag, (b - c).real))}


def weights_work(first: dict[str, complex], last: dict[str, complex], masses: dict[str, float]) -> float:
    return -GRAVITY * sum(mass * (last[centre] - first[centre]).imag for centre, mass in masses.items())


@pytest.fixture(scope="module")
def tipper():
    return equivalent_model_of(loads(TIPPER), SAMPLES)


@pytest.fixture(scope="module")
def wiper():
    return equivalent_model_of(loads(WIPER), SAMPLES)


def test_a_payload_a_cylinder_lifts_resists_and_the_cylinder_s_push_is_taken_constant(tipper):
    first, last = tipper_points(0.05), tipper_points(0.25)
    payload = -400.0 * (last["E"] - first["E"]).imag          # a force straight down, its point rising
    weights = weights_work(first, last, {"A": 5.0, "S3": 2.0, "S4": 8.0})
    assert payload < 0
    assert tipper.driving_loads == () and tipper.resisting_loads == ("loads[0]",)
    assert [moved.loads for moved in tipper.moved] == [("loads[0]",)]
    assert tipper.moved[0].work == pytest.approx(payload, rel=1e-5)
    # The cylinder's constant push does the work the payload and the weights take over its 0.2 m travel.
    assert tipper.constant == "driving"
    assert np.ptp(tipper.driving) == 0.0
    assert tipper.driving[0] == pytest.approx(-(payload + weights) / 0.20, rel=1e-5)
    assert tipper.driving_work[-1] == pytest.approx(tipper.resisting_work[-1], rel=1e-12)
    assert tipper.resisting_work[-1] == pytest.approx(-(payload + weights), rel=1e-5)
    assert tipper.energy[-1] == pytest.approx(0.0, abs=1e-9 * tipper.resisting_work[-1])
    assert np.all(tipper.driving > 0)


def test_a_force_that_opposes_a_swing_all_over_it_resists_and_the_lever_s_moment_balances_the_swing(wiper):
    first, last = wiper_points(120.0), wiper_points(40.0)
    heading = complex(math.cos(math.radians(200.0)), math.sin(math.radians(200.0)))
    force = 30.0 * ((last["W"] - first["W"]) * heading.conjugate()).real     # F·Δr
    # The 2 N·m moment always opposes the rocker: it takes 2·∫|dθ4| over the swing.
    turns = np.unwrap([wiper_points(phi)["theta4"].real for phi in np.linspace(120.0, 40.0, 4001)])
    moment = -2.0 * float(np.sum(np.abs(np.diff(turns))))
    weights = weights_work(first, last, {"S2": 0.8, "S3": 0.6, "S4": 1.2})
    assert force < 0
    assert wiper.driving_loads == () and wiper.resisting_loads == ("loads[0]", "loads[1]")
    assert [moved.loads for moved in wiper.moved] == [("loads[0]",)]
    assert wiper.moved[0].work == pytest.approx(force, rel=1e-5)
    assert wiper.constant == "driving"
    assert wiper.driving[0] == pytest.approx(-(force + moment + weights) / math.radians(80.0), rel=1e-5)
    assert wiper.energy[-1] == pytest.approx(0.0, abs=1e-9 * wiper.resisting_work[-1])
    # The kinetic energy changes by far less over the swing than the loads' work: it is the lever's to give.
    assert float(np.max(np.abs(wiper.energy))) < 0.2 * wiper.resisting_work[-1]


def test_a_load_given_as_driving_that_gives_work_drives_as_before():
    """The engine's gas force over the expansion stroke gives 4500 N over the 2r = 0.1 m stroke."""
    text = (ROOT / "fixtures" / "engine_slider_crank.toml").read_text(encoding="utf-8")
    model = equivalent_model_of(loads(text + "\n[dynamics]\n"), 1440)
    assert model.driving_loads == ("loads[0]",) and model.resisting_loads == () and model.moved == ()
    assert model.constant == "resisting"
    assert model.driving_work[-1] == pytest.approx(4500.0 * 0.1, rel=1e-5)


def test_a_gas_force_given_a_load_a_stroke_is_sorted_as_one_force():
    """Compression (1500 N against the piston's outward stroke) takes 150 J, the expansion gives 450 J: the gas
    force gives 300 J over the cycle and drives, its compression stroke with it."""
    text = (ROOT / "fixtures" / "engine_slider_crank.toml").read_text(encoding="utf-8")
    text = text.replace("\n[positions]", '\n[[loads]]\nkind = "force"\nlink = 4\npoint = "B"\nvalue = 1500.0\n'
                        'angle = 180.0\nresisting = false\nduring = "idle"\n\n[positions]', 1)
    model = equivalent_model_of(loads(text + "\n[dynamics]\n"), 1440)
    assert model.driving_loads == ("loads[0]", "loads[1]") and model.moved == ()
    assert model.constant == "resisting"
    assert model.driving_work[-1] == pytest.approx((4500.0 - 1500.0) * 0.1, rel=1e-5)


def test_a_compressor_s_gas_force_resists_and_the_motor_s_moment_is_taken_constant():
    """The compressor's indicator diagram, a load a stroke, takes work over the cycle: both its loads resist, and
    the works read as the textbook draws them, both positive."""
    model = equivalent_model_of(loads((ROOT / "tests" / "scenes" / "compressor_indicator_diagram.toml")
                                      .read_text(encoding="utf-8")))
    assert model.driving_loads == () and model.resisting_loads == ("loads[0]", "loads[1]")
    assert [moved.loads for moved in model.moved] == [("loads[0]", "loads[1]")]
    assert model.constant == "driving"
    assert model.driving_work[-1] > 0 and model.resisting_work[-1] == pytest.approx(model.driving_work[-1])
    assert model.resisting_work[-1] == pytest.approx(-model.moved[0].work, rel=1e-9)


@pytest.mark.parametrize("locale,said", [
    ("en", "The load F4 is given as a driving load, but its work over the travel, A = "),
    ("ru", "Нагрузка F4 задана как движущая, но её работа за ход A = "),
    ("zh", "载荷 F4 给定为驱动载荷，但其在整个行程内的功 W = "),
])
def test_the_note_says_a_load_given_as_driving_is_counted_with_the_resistances(tmp_path, locale, said):
    import json

    scene = tmp_path / "tipper.toml"
    scene.write_text(TIPPER.replace('locale  = "en"', f'locale  = "{locale}"'), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    assert said in note
    if locale == "en":  # the cylinder's push, taken constant, is told as a crank's moment is
        assert "The driving force is taken constant, so that its work over the travel equals that of the " \
               "resistances: Fd = Ar/H = " in note
    found = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]
    assert found["constant"] == "driving"
    assert found["driving_loads"] == [] and found["resisting_loads"] == ["loads[0]"]
    assert min(found["driving_moment"]) > 0 and max(found["resisting_moment"]) < 0
