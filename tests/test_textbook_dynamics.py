"""Textbook worked examples of machine dynamics written as scenes, as a student would, run through the command line.

Each published answer is asserted to the precision the book prints it (a graphical answer to what a drawing
gives); the scene is what the extensions page documents, not graphplan's code. Sources:

* R.S. Khurmi & J.K. Gupta, *A Textbook of Theory of Machines*, S. Chand (14th ed., 2005), the chapter and
  example numbers of that edition, quoted from memory (no copy of the book was at hand):

  - Example 16.5 (turning moment diagrams): a multi-cylinder engine's diagram at 1 mm = 600 N·m and
    1 mm = 3°, its loops about the mean resistance +52, −124, +92, −140, +85, −72, +107 mm², 600 rpm,
    speed within ±1.5 % of the mean, flywheel radius 0.5 m. Printed: m = 182.5 kg.
  - Example 21.2 (balancing of rotating masses, graphical): masses A, B, C, D of 200, 300, 400, 200 kg at
    80, 70, 60, 80 mm, B, C, D 300, 400, 700 mm from A, A to B 45°, B to C 70°, C to D 120° (anticlockwise);
    corrections at 100 mm in planes X and Y, 100 mm and 500 mm from A. Printed (measured off the couple and
    force polygons): mY = 182.5 kg at 12°, mX = 355 kg at 145°, both clockwise from A.
  - Chapter 23 (longitudinal and transverse vibrations), the machine on springs: 75 kg on springs of
    1200 kN/m with a damping factor 0.2; a 2 kg piston in it moves harmonically with an 80 mm stroke at
    3000 cycles/min. Printed: amplitude 1.25 mm, lagging the force by 169.1°, force on the foundation 2.1 kN.

The answers are also worked out here by hand (independent closed forms), so that a slip of memory in a printed
figure would show as a disagreement between the two, not pass unseen.
"""

from __future__ import annotations

import cmath
import json
import math
from pathlib import Path

import pytest
from console import without_progress
from sheet_texts import flat

from graphplan.cli import main


def run(tmp_path: Path, text: str, *args: str) -> tuple[int, dict]:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    code = main(["run", str(scene), "--out", str(out), *args])
    results = json.loads((out / "results.json").read_text(encoding="utf-8")) if code == 0 else {}
    return code, results


# --- Khurmi & Gupta, Example 16.5: a flywheel from the loops of a turning moment diagram ---------------------------

KHURMI_16_5_LOOPS = (52, -124, 92, -140, 85, -72, 107)  # mm², in order round the turn
KHURMI_16_5_SCALE = 600 * math.radians(3)  # J a mm²: 1 mm = 600 N·m by 1 mm = 3°


def khurmi_16_5_scene() -> str:
    """The diagram as a student types it: each loop a step of the engine's torque above or below a mean of 10 kN·m
    (any mean will do, the resistance taken constant), over a seventh of the turn, its area the loop's."""
    span = 360 / len(KHURMI_16_5_LOOPS)
    points = []
    for k, loop in enumerate(KHURMI_16_5_LOOPS):
        torque = 10000 + loop * KHURMI_16_5_SCALE / math.radians(span)
        points += [f"[{k * span:.15g}, {torque:.15g}]", f"[{(k + 1) * span:.15g}, {torque:.15g}]"]
    return ("[scene]\ntitle = \"Khurmi & Gupta, Example 16.5\"\n[dynamics]\nrpm = 600\ndelta = 0.03\n"
            f"driving_torque = [{', '.join(points)}]\nresisting = \"constant\"\n")


def test_khurmi_16_5_flywheel_from_the_loops_of_a_multi_cylinder_engine(tmp_path):
    code, results = run(tmp_path, khurmi_16_5_scene())
    assert code == 0
    dynamics = results["dynamics"]
    # By hand: the energy above its start after each loop, its range the largest fluctuation.
    energies = [0]
    for loop in KHURMI_16_5_LOOPS:
        energies.append(energies[-1] + loop)
    fluctuation = (max(energies) - min(energies)) * KHURMI_16_5_SCALE  # 172 mm²
    assert dynamics["delta_w_max"] == pytest.approx(fluctuation, rel=1e-9)
    omega = 600 * math.pi / 30
    assert dynamics["flywheel_inertia"] == pytest.approx(fluctuation / (omega ** 2 * 0.03), rel=1e-9)
    # Printed: m = 182.5 kg on a radius of 0.5 m.
    assert dynamics["flywheel_inertia"] / 0.5 ** 2 == pytest.approx(182.5, abs=0.05)


# --- Khurmi & Gupta, Example 21.2: four masses balanced in two planes -------------------------------------------

KHURMI_21_2 = """\
[scene]
title = "Khurmi & Gupta, Example 21.2"
[balancing]
masses = [ { mass = 200.0, radius = 0.08, angle = 0.0, plane = 0.0, name = "A" },
           { mass = 300.0, radius = 0.07, angle = 45.0, plane = 0.3, name = "B" },
           { mass = 400.0, radius = 0.06, angle = 115.0, plane = 0.4, name = "C" },
           { mass = 200.0, radius = 0.08, angle = 235.0, plane = 0.7, name = "D" } ]
planes = [0.1, 0.5]
plane_names = ["X", "Y"]
correction_radius = 0.1
"""


def test_khurmi_21_2_four_masses_balanced_in_two_planes(tmp_path):
    code, results = run(tmp_path, KHURMI_21_2)
    assert code == 0
    x, y = results["balancing"]["planes"]
    # By hand: the moments about X give Y's correction, the forces then X's.
    products = [m * r * cmath.exp(1j * math.radians(a))
                for m, r, a in ((200, 0.08, 0), (300, 0.07, 45), (400, 0.06, 115), (200, 0.08, 235))]
    planes = (0.0, 0.3, 0.4, 0.7)
    in_y = -sum(u * (z - 0.1) for u, z in zip(products, planes, strict=True)) / 0.4
    in_x = -sum(products) - in_y
    for plane, correction in ((x, in_x), (y, in_y)):
        assert plane["mass"] == pytest.approx(abs(correction) / 0.1, rel=1e-9)
        assert plane["angle_deg"] == pytest.approx(math.degrees(cmath.phase(correction)) % 360, abs=1e-7)
    # Printed, read off the book's drawings: 355 kg at 145° and 182.5 kg at 12°, clockwise from A (graphplan counts
    # counter-clockwise). A drawing reads to about 1 % and 2°.
    assert x["mass"] == pytest.approx(355, rel=0.01)
    assert (360 - x["angle_deg"]) == pytest.approx(145, abs=2)
    assert y["mass"] == pytest.approx(182.5, rel=0.01)
    assert (360 - y["angle_deg"]) == pytest.approx(12, abs=2)


# --- Khurmi & Gupta, chapter 23: a machine on damped springs shaken by its piston ------------------------------------

MACHINE_ON_SPRINGS = """\
[scene]
title = "A machine on springs shaken by its piston"
[vibration]
mass = 75.0
unbalanced_mass = 2.0
eccentricity = 0.04
stiffness = 1.2e6
damping_ratio = 0.2
rpm = 3000
"""


def test_khurmi_machine_on_springs_shaken_by_its_piston(tmp_path):
    code, results = run(tmp_path, MACHINE_ON_SPRINGS)
    assert code == 0
    vibration = results["vibration"]
    # By hand: F = m·e·ω², X = F/√((k − Mω²)² + (cω)²), tan φ = cω/(k − Mω²), FT = X·√(k² + (cω)²).
    omega = 3000 * math.pi / 30
    damping = 0.2 * 2 * math.sqrt(1.2e6 * 75)
    force = 2 * 0.04 * omega ** 2
    amplitude = force / math.hypot(1.2e6 - 75 * omega ** 2, damping * omega)
    assert vibration["amplitude"] == pytest.approx(amplitude, rel=1e-9)
    assert vibration["phase_deg"] == pytest.approx(
        math.degrees(math.atan2(damping * omega, 1.2e6 - 75 * omega ** 2)), abs=1e-7)
    assert vibration["transmitted_force"] == pytest.approx(amplitude * math.hypot(1.2e6, damping * omega), rel=1e-9)
    # Printed: 1.25 mm, 169.1°, 2.1 kN.
    assert vibration["amplitude"] * 1000 == pytest.approx(1.25, abs=0.005)
    assert vibration["phase_deg"] == pytest.approx(169.1, abs=0.05)
    assert vibration["transmitted_force"] / 1000 == pytest.approx(2.1, abs=0.05)


# --- a student's slips, each told at its key ---------------------------------------------------------------------

PRESS = """\
[scene]
title = "A press from its power cycle"
[dynamics]
rpm = 100
delta = 0.05
resisting_power = {diagram}
driving = "constant"
"""


def check(capsys, tmp_path: Path, text: str) -> tuple[int, str]:
    """``graphplan check`` of ``text``: its exit status and what it printed, its report and warnings (on stdout) after
    its refusals (on stderr), progress left out."""
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    code = main(["check", str(scene)])
    printed = capsys.readouterr()
    return code, without_progress(printed.err) + printed.out


def test_a_load_diagrams_point_out_of_order_is_told_where_its_angle_falls(capsys, tmp_path):
    # The idle stroke's two points typed the wrong way round: the diagram does run from 0 to 360°, so the refusal
    # names the point whose angle falls, not the turn's ends.
    diagram = "[[120, 367.7], [0, 367.7], [120, 3677], [360, 3677]]"
    code, err = check(capsys, tmp_path, PRESS.format(diagram=diagram))
    assert code == 2
    assert err.startswith("graphplan: error: dynamics.resisting_power[1]: crank angles must not fall")
    assert "whole turn" not in err


def test_a_load_diagram_in_radians_is_asked_about_its_unit(capsys, tmp_path):
    # The turn typed as 2π = 6.283: the refusal names the unit, not only the ends the angles should have.
    diagram = "[[0, 367.7], [2.094, 367.7], [2.094, 3677], [6.283, 3677]]"
    code, err = check(capsys, tmp_path, PRESS.format(diagram=diagram))
    assert code == 2
    assert err.startswith("graphplan: error: dynamics.resisting_power: must run over the whole turn")
    assert "radians? 6.283 rad is 360°: the diagram's crank angles are in degrees" in err


MOTOR = PRESS.format(diagram="[[0, 367.7], [120, 367.7], [120, 3677], [360, 3677]]") + (
    'motor = {{ kind = "kloss", power = 4000.0, overload = {overload}, synchronous_rpm = 1500, rated_rpm = 1440, '
    'gear_ratio = 14.4 }}\n')


def test_a_motors_overload_typed_as_a_percentage_is_refused_saying_so(capsys, tmp_path):
    # A catalogue's Mmax/MN = 220 % typed as 220: no induction motor pulls out at 220 times its rated torque (they
    # do at some 1.6 to 3.5 times), and the run went on with it as if it did.
    code, err = check(capsys, tmp_path, MOTOR.format(overload=220))
    assert code == 2
    assert err.startswith("graphplan: error: dynamics.motor.overload: must be below 10")
    assert "(got 220.0); a percentage typed for the ratio? (220 % is overload = 2.2)" in err
    code, err = check(capsys, tmp_path, MOTOR.format(overload=2.2))
    assert code == 0 and "dynamics.motor.overload" not in err


@pytest.mark.parametrize(("change", "said"), [
    # The springs' 1200 kN/m typed as kN/m: the machine would sit 0.613 m down on them.
    (("stiffness = 1.2e6", "stiffness = 1200"), ("vibration.stiffness: k = 1200 N/m would let the machine, "
                                                  "vibration.mass = 75 kg, sag M·g/k = 0.613 m under its weight")),
    # The machine's 75 kg typed in grams: as heavy a sag on the same springs.
    (("mass = 75.0", "mass = 75000"), ("vibration.stiffness: k = 1.2e+06 N/m would let the machine, "
                                       "vibration.mass = 75000 kg, sag M·g/k = 0.613 m under its weight")),
], ids=["stiffness-in-kN-per-m", "mass-in-grams"])
def test_mounts_no_spring_could_be_are_asked_about_their_units(capsys, tmp_path, change, said):
    code, err = check(capsys, tmp_path, MACHINE_ON_SPRINGS.replace(*change))
    assert code == 0
    (line,) = [line for line in err.splitlines() if "sag" in line]
    assert line.startswith("warning: " + said)
    assert "more than any spring mount (100 mm): a stiffness typed in kN/m or N/mm, or a mass in grams?" in line
    # The book's own springs sag 0.6 mm: nothing to say.
    code, err = check(capsys, tmp_path, MACHINE_ON_SPRINGS)
    assert code == 0 and "sag" not in err


def test_a_shafts_bending_is_not_taken_for_mounts_that_sag(capsys, tmp_path):
    # A slender shaft bends under its disc more than any mount sags, and that is no slip of a unit.
    text = MACHINE_ON_SPRINGS.replace("stiffness = 1.2e6",
                                      'shaft = { modulus = 2.1e11, diameter = 0.01, length = 1.0 }')
    code, err = check(capsys, tmp_path, text)
    assert code == 0 and "sag" not in err


@pytest.mark.parametrize(("radius", "key", "plane"), [
    ("100", "balancing.correction_radius", "X"),
    ("[0.1, 100]", "balancing.correction_radius[1]", "Y"),
], ids=["one", "per-plane"])
def test_a_correction_radius_in_millimetres_on_a_long_rotor_is_asked_about(capsys, tmp_path, radius, key, plane):
    # Khurmi's 100 mm typed as 100 beside masses and planes in metres: corrections 143 times as far out as the rotor
    # is long, as the masses' own radii are told, were worked out at 100 m without a word.
    text = KHURMI_21_2.replace("correction_radius = 0.1", f"correction_radius = {radius}")
    code, err = check(capsys, tmp_path, text)
    assert code == 0
    assert (f"warning: balancing: {key} = 100 m is 143 times the rotor's length along its axis, 0.7 m from "
            "balancing.masses[0].plane to balancing.masses[3].plane (a rotor balanced in two planes is long: its "
            f"corrections turn no farther than 20 times its length from the axis; as millimetres, {key} = 0.1): are "
            "some lengths in millimetres?") in err
    code, results = run(tmp_path, text)
    (caution,) = results["balancing"]["warnings"]
    assert caution["code"] == "lengths-in-mm"
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert (f"the correction radius in plane {plane}, 100 m, is 143 times the 0.7 m the masses and correction "
            "planes span along the axis") in note


def test_a_gear_ratio_typed_the_wrong_way_up_is_asked_about_where_the_machine_does_not_start(capsys, tmp_path):
    # The press's gearbox from 1440 to 100 rpm typed as the shaft's speed over the motor's, 1/14.4, on a motor of no
    # speed of its own (a constant 17 N·m), which no gear line weighs: it gives the shaft u·17 = 1.18 N·m at rest,
    # under the press's 35.1, and 1/u would give it 245 (just under the mean resistance, 245.8, so that it does not
    # run away); nothing else tells the ratio, and the advice only asked for "a larger gear ratio".
    constant = MOTOR.format(overload=2.2).replace(
        'kind = "kloss", power = 4000.0, overload = 2.2, synchronous_rpm = 1500, rated_rpm = 1440, gear_ratio = 14.4',
        'kind = "constant", torque = 17.0, gear_ratio = 0.0694')
    assert 0.0694 * 17.0 < 35.113 < 17.0 / 0.0694
    code, err = check(capsys, tmp_path, constant)
    assert code == 0
    (line,) = [line for line in err.splitlines() if "does not start" in line]
    assert line.endswith("; gear_ratio = 0.0694 turns the shaft faster than the motor: the ratio inverted? (it is "
                         "the motor's speed over the shaft's: 1/0.0694 = 14.41)")
    # The right way up the press starts, and a speed-up gear too weak to start it is not asked about.
    code, err = check(capsys, tmp_path, constant.replace("gear_ratio = 0.0694", "gear_ratio = 14.4"))
    assert code == 0 and "does not start" not in err
    code, err = check(capsys, tmp_path, constant.replace("torque = 17.0", "torque = 1.0"))
    (line,) = [line for line in err.splitlines() if "does not start" in line]
    assert "inverted" not in line


@pytest.mark.parametrize(("locale", "said", "unsaid"), [
    ("en", "ωmax = 63.774 rad/s at φ = 51.43°", "into the cycle"),
    ("ru", "ωmax = 63,774 рад/с при φ = 51,43°", "от начала цикла"),
    ("zh", "φ = 51.43°", "自循环起点"),
])
def test_a_speeds_angle_is_not_said_twice_where_the_cycle_starts_at_nought(tmp_path, locale, said, unsaid):
    # Khurmi's diagram runs from 0°: the flywheel's box wrote "at φ = 51.43° (51.43° into the cycle)", the same angle
    # twice, which a reader takes for two different things.
    code, _ = run(tmp_path, khurmi_16_5_scene(), "--locale", locale)
    assert code == 0
    drawing = flat((tmp_path / "out" / "dynamics.svg").read_text(encoding="utf-8"))
    assert said in drawing and unsaid not in drawing
