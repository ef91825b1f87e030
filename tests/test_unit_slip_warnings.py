"""A fresh student's slips, tried as scenes: a choice among keys got wrong (neither, both, a bad value in one) is
told at the key at fault, naming every choice where none is given; and values typed in the wrong unit that still
run (an rpm typed as rad/s, a mass in grams, an eccentricity or a radius in millimetres) are warned of, naming the
key, its value and what was likely meant, while no fixture, test scene or starter is."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.starters import starter

STARTERS = ("crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad", "flywheel", "rotor")
SCENES = sorted(Path("fixtures").glob("*.toml")) + sorted(Path("tests/scenes").glob("*.toml"))


def _scene(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _refusal(tmp_path: Path, text: str, capsys) -> str:
    assert main(["check", str(_scene(tmp_path, text))]) == 2
    return capsys.readouterr().err.strip()


def _edited(kind: str, old: str, new: str) -> str:
    text = starter(kind, "en")
    assert old in text
    return text.replace(old, new, 1)


MACHINE = '[scene]\ntitle = "Machine"\n[vibration]\nmass = 100.0\n'
SHEET = "resisting_power = [[0, 367.7], [120, 367.7], [120, 3677], [360, 3677]]\n"
KLOSS = ('motor = { kind = "kloss", power = 4000.0, overload = 2.2, synchronous_rpm = 1500, rated_rpm = 1440, '
         'gear_ratio = 14.4 }')


# --- a choice among keys -------------------------------------------------------------------------------------------

@pytest.mark.parametrize(("text", "told"), [
    # Neither: told at the first choice, naming all of them.
    (_edited("crank-rocker", "omega   = -17.0", ""),
     "driver.omega: is required but missing: give omega (rad/s) or rpm (rev/min)"),
    (MACHINE + "unbalance = 0.02\nrpm = 600\n", "vibration.stiffness: is required (or shaft)"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\n",
     "vibration.omega: is required but missing: give omega (rad/s) or rpm (rev/min)"),
    (MACHINE + "stiffness = 1e5\nrpm = 600\n",
     "vibration.unbalance: is required (m·e, kg·m), or unbalanced_mass and eccentricity"),
    (MACHINE + "unbalance = 0.02\nshaft = { modulus = 2e11, length = 1.0 }\nrpm = 600\n",
     "vibration.shaft.diameter: is required (the shaft's diameter, m), or second_moment (I, m⁴)"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\n' + SHEET,
     "dynamics.omega: is required but missing: give omega (rad/s) or rpm (rev/min)"),
    (_edited("crank-rocker", 'assembly = "left"', ""),
     ("groups[0].assembly: is required but missing: left or right chooses the branch the group assembles in (or "
      "near = [x, y]")),
    # Half of a pair: told at the half left out, with the other way to give it.
    (MACHINE + "unbalanced_mass = 1.0\nstiffness = 1e5\nrpm = 600\n",
     ("vibration.eccentricity: is required with unbalanced_mass: the unbalanced mass's distance e from the axis, "
      "m; or give unbalance (m·e, kg·m) alone in place of both")),
    (MACHINE + "eccentricity = 0.01\nstiffness = 1e5\nrpm = 600\n",
     ("vibration.unbalanced_mass: is required with eccentricity: the unbalanced mass m, kg; or give unbalance "
      "(m·e, kg·m) alone in place of both")),
    # Both: told at a key, never at the table alone, naming both.
    (_edited("crank-rocker", "omega   = -17.0", "omega = -17.0\nrpm = 160"),
     "driver.rpm: give either omega or rpm, not both"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\nshaft = { modulus = 2e11, diameter = 0.05, length = 1.0 }\n"
               "rpm = 600\n", "vibration.shaft: give either stiffness or shaft, not both"),
    (_edited("crank-rocker", 'assembly = "left"', 'assembly = "left"\nnear = [0.3, 0.6]'),
     "groups[0].near: give either assembly or near, not both"),
    (_edited("crank-rocker", "velocity_pole      = 150.0", "velocity_pole = 150.0\nvelocity_scale = 0.01"),
     "drawing.velocity_scale: give either velocity_pole or velocity_scale, not both"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = 100\n' + SHEET
     + KLOSS.replace("rated_rpm = 1440", "rated_rpm = 1440, rated_slip = 0.04") + "\n",
     "dynamics.motor.rated_slip: give two of synchronous_rpm, rated_rpm, rated_slip, not all three"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\nrpm = 600\ndamping = 3\ndamping_ratio = 0.1\n",
     "vibration.damping: give either damping_ratio or damping (c), not both"),
    (MACHINE + "unbalance = 0.02\nshaft = { modulus = 2e11, length = 1.0, diameter = 0.05, second_moment = 3e-7 }\n"
               "rpm = 600\n", "vibration.shaft.diameter: give either second_moment or diameter, not both"),
    (_edited("crank-rocker", "acceleration_pole  = 100.0", "acceleration_pole = 100.0\nacceleration_scale = 0.5"),
     "drawing.acceleration_scale: give either acceleration_pole or acceleration_scale, not both"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = 100\n' + SHEET
     + "resisting_torque = [[0, 10], [360, 10]]\n",
     "dynamics.resisting_power: give resisting_torque or resisting_power, not both"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = 100\n' + SHEET
     + 'motor = { kind = "linear", stall_torque = 400, points = [[0, 400], [150, 0]] }\n',
     "dynamics.motor.stall_torque: give either points or stall_torque with no_load_rpm, not both"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = 100\n' + SHEET
     + 'motor = { kind = "constant", torque = 400 }\nstart = { omega = 5, rpm = 50 }\n',
     "dynamics.start.rpm: give either omega or rpm, not both"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = 100\n' + SHEET
     + 'motor = { kind = "constant", torque = 400 }\nstart = { driving_rpm = 50 }\n',
     "dynamics.start.driving_rpm: only with a clutch"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = 100\n' + SHEET
     + KLOSS.replace("synchronous_rpm = 1500, rated_rpm = 1440, ", "") + "\n",
     "dynamics.motor: give two of synchronous_rpm, rated_rpm, rated_slip (got none)"),
    ('[scene]\ntitle = "Press"\n[dynamics]\nrpm = 100\n' + SHEET + 'motor = { kind = "constant", torque = 400 }\n',
     ("dynamics.inertia: the equation of motion needs the machine's inertia: give inertia (kg·m², the machine's "
      "own, > 0) or delta")),
    (_edited("crank-rocker", "value     = 1500.0", "value = 1500.0\ndiagram = [[0, 0], [1, 1500]]"),
     "loads[0].diagram: a load diagram gives the values and the window itself: leave out value and during"),
    # A bad value in one: told at that one, not at the other.
    (_edited("crank-rocker", "omega   = -17.0", 'rpm = "160"'), "driver.rpm: must be a number, not a string"),
    (MACHINE + "unbalance = 0.02\nstiffness = -1e5\nrpm = 600\n", "vibration.stiffness: must be > 0"),
    (MACHINE + "unbalance = 0.02\nshaft = 5\nrpm = 600\n", "vibration.shaft: must be a table, not an integer"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\nrpm = 0\n", "vibration.rpm: must be > 0"),
    (MACHINE + "unbalance = 0.02\nstiffness = 1e5\nomega = -3\n", "vibration.omega: must be > 0"),
    ('[scene]\ntitle = "Press"\n[dynamics]\ndelta = 0.05\nrpm = -100\n' + SHEET, "dynamics.rpm: must be > 0"),
    (_edited("crank-rocker", 'assembly = "left"', "near = 5"), "groups[0].near: must be a point [x, y]"),
    (_edited("crank-rocker", 'assembly = "left"', 'assembly = "up"'), "groups[0].assembly: must be one of left, right"),
])
def test_a_choice_got_wrong_is_told_at_the_key_at_fault(tmp_path, capsys, text, told):
    assert told in _refusal(tmp_path, text, capsys)


# --- values typed in another unit ----------------------------------------------------------------------------------

def _run(tmp_path: Path, text: str, capsys, only: str = "note") -> tuple[str, dict, str]:
    """Run the scene: the warnings on the console, results.json and the note; the run still completes."""
    out = tmp_path / "out"
    assert main(["run", str(_scene(tmp_path, text)), "--out", str(out), "--only", only]) == 0
    told = capsys.readouterr().out
    return (told, json.loads((out / "results.json").read_text(encoding="utf-8")),
            (out / "note.md").read_text(encoding="utf-8"))


def _rpm_words(key: str, omega: float) -> str:
    """What the warning says of ``key = omega`` typed in rev/min, worked out here: the speed as rad/s in rev/min,
    and the rev/min as rad/s."""
    as_rpm = abs(omega) * 30.0 / math.pi
    return (f"{key} = {omega:g} rad/s is {as_rpm:.5g} rpm: a motor's speed in rev/min typed for rad/s? "
            f"{abs(omega):g} rpm is {abs(omega) * math.pi / 30.0:.5g} rad/s")


@pytest.mark.parametrize("omega", [-1450.0, 2900.0, 960.0])
def test_a_cranks_rpm_typed_as_omega_is_warned_of_with_the_speed_it_would_be(tmp_path, capsys, omega):
    told, results, note = _run(tmp_path, _edited("crank-rocker", "omega   = -17.0", f"omega = {omega!r}"), capsys)
    words = _rpm_words("driver.omega", omega)
    assert f"warning: {words}: write driver.rpm = {omega:g}" in told
    assert any(warning["code"] == "speed-in-rpm" and words in warning["detail"] for warning in results["warnings"])
    assert "a motor's speed in revolutions per minute" in note
    # The crank pin at 0.175 m moves at 168–508 m/s: the speed explains it, not lengths in millimetres.
    assert "millimetres" not in told and "lengths-in-mm" not in {warning["code"] for warning in results["warnings"]}


def test_a_cranks_rpm_given_as_rpm_is_not_warned_of(tmp_path, capsys):
    told, results, _ = _run(tmp_path, _edited("crank-rocker", "omega   = -17.0", "rpm = -1450"), capsys)
    assert "rev/min typed for rad/s" not in told
    assert "speed-in-rpm" not in {warning["code"] for warning in results["warnings"]}


def test_a_flywheel_shafts_and_a_machines_rpm_typed_as_omega_are_warned_of(tmp_path, capsys):
    flywheel = starter("flywheel", "en").replace("rpm   = 100 ", "omega = 1440", 1)
    assert "omega = 1440" in flywheel
    told, _, _ = _run(tmp_path, flywheel, capsys, "note,dynamics")
    assert f"warning: {_rpm_words('dynamics.omega', 1440.0)}: write dynamics.rpm = 1440" in told
    machine = MACHINE + "unbalance = 0.02\nstiffness = 1e5\ndamping_ratio = 0.1\nomega = 2880\n"
    told, _, _ = _run(tmp_path, machine, capsys, "note,vibration")
    assert f"warning: vibration: {_rpm_words('vibration.omega', 2880.0)}: write vibration.rpm = 2880" in told


SLIDER_DRIVEN = Path("fixtures/slider_driven.toml").read_text(encoding="utf-8")


def _slider_driven(velocity: str, acceleration: str = "0.0") -> str:
    text = SLIDER_DRIVEN.replace("velocity     = 0.08 ", f"velocity     = {velocity} ", 1)
    text = text.replace("acceleration = 0.0 ", f"acceleration = {acceleration} ", 1)
    assert f"velocity     = {velocity} " in text and f"acceleration = {acceleration} " in text
    return text


def test_a_slider_drivers_velocity_in_mm_per_s_is_warned_of_and_not_as_a_load_in_kn(tmp_path, capsys):
    """The hydraulic lever's 0.08 m/s typed as 80 gives accelerations a million times its own and so inertia loads
    that dwarf its 150 N·m: it was told only that the load looked typed in kN·m."""
    told, results, note = _run(tmp_path, _slider_driven("80.0"), capsys)
    words = ("driver.velocity = 80 m/s drives the slider A faster than any cylinder or linear drive pushes (over "
             "20 m/s; a hydraulic cylinder's rod moves at some 0.05–0.5 m/s): mm/s typed for m/s? 80 mm/s is "
             "driver.velocity = 0.08: the scene's velocities are in m/s")
    assert f"warning: {words}" in told
    codes = {warning["code"] for warning in results["warnings"]}
    assert any(warning["code"] == "velocity-in-mm" and words in warning["detail"] for warning in results["warnings"])
    assert "load-in-kn" not in codes and "kN" not in told
    assert "it was probably given in mm/s where m/s are asked for" in note


def test_a_slider_drivers_acceleration_in_mm_per_s2_too_is_named_where_its_plan_is_refused(tmp_path, capsys):
    """Its 0.5 m/s² typed as 500 with it, the plan drawn at the fixture's acceleration_pole is a thousand times too
    large: refused at the pole alone, the student was sent to a scale that fits once the speeds are in m/s."""
    assert main(["run", str(_scene(tmp_path, _slider_driven("80.0", "500.0"))), "--out", str(tmp_path / "out"),
                 "--only", "note"]) == 2
    told = capsys.readouterr()
    assert ("mm/s typed for m/s? 80 mm/s is driver.velocity = 0.08, and 500 mm/s² is driver.acceleration = 0.5"
            in told.err)
    assert "graphplan: error: drawing.acceleration_pole: draws the acceleration plan" in told.err
    assert told.err.strip().endswith("; or driver.velocity = 80 m/s is mm/s typed for m/s: give driver.velocity = "
                                     "0.08 and driver.acceleration = 0.5")
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("velocity", ["15.0", "-0.5"])
def test_a_slider_driver_as_fast_as_a_drive_pushes_is_not_warned_of(tmp_path, capsys, velocity):
    told, results, _ = _run(tmp_path, _slider_driven(velocity), capsys)
    assert "mm/s typed for m/s" not in told
    assert "velocity-in-mm" not in {warning["code"] for warning in results["warnings"]}


def test_a_links_mass_in_grams_is_warned_of(tmp_path, capsys):
    # The rocker BC is 0.325 m long: a solid steel bar of it, 0.325 m square, is 7850·0.325³ = 269 kg.
    text = _edited("crank-rocker", 'mass    = 17.0\ncentre  = "S4"', 'mass    = 300.0\ncentre  = "S4"')
    told, results, note = _run(tmp_path, text, capsys)
    bar = 7850.0 * 0.325 ** 3
    words = (f"links.4.mass = 300 kg on a link 0.325 m long (B–C), heavier than a solid steel bar of that length "
             f"({bar:.3g} kg): grams typed for kg? 300 g is links.4.mass = 0.3")
    assert words in told
    assert any(warning["code"] == "masses-in-grams" and words in warning["detail"] for warning in results["warnings"])
    assert "the masses were probably given in grams" in note


def test_an_eccentricity_in_millimetres_is_warned_of(tmp_path, capsys):
    machine = MACHINE + "unbalanced_mass = 1.0\neccentricity = 5.0\nstiffness = 1e5\ndamping_ratio = 0.1\nrpm = 600\n"
    told, results, note = _run(tmp_path, machine, capsys, "note,vibration")
    sheet = 2.0 * 5.0 ** 2.5  # the lightest machines reaching e weigh some 2 kg·(e / 1 m)^2.5 or more
    words = (f"vibration.eccentricity = 5 m puts the unbalanced mass that far from the axis, and the lightest machines "
             f"that reach so far (a propeller on its motor, a fan, a bicycle's wheel, a wind turbine) weigh at least "
             f"{sheet:.3g} kg, more than the whole machine, vibration.mass = 100 kg (as millimetres, "
             "vibration.eccentricity = 0.005)")
    assert f"warning: vibration: {words}" in told
    assert any(warning["code"] == "lengths-in-mm" and words in warning["detail"]
               for warning in results["vibration"]["warnings"])
    assert f"weigh at least {sheet:.3g} kg, more than the whole machine, 100 kg" in note


def test_a_rotors_radius_in_millimetres_among_planes_in_metres_is_warned_of(tmp_path, capsys):
    rotor = starter("rotor", "en").replace("radius = 0.05, angle = 0.0", "radius = 5.0, angle = 0.0", 1)
    told, results, note = _run(tmp_path, rotor, capsys, "note,balancing")
    # The starter's masses and planes lie from z = 0 to z = 0.22 m.
    words = (f"balancing.masses[0].radius = 5 m is {5.0 / 0.22:.3g} times the rotor's length along its axis, 0.22 m "
             "from balancing.masses[0].plane to balancing.planes[1]")
    assert f"warning: balancing: {words}" in told and "balancing.masses[0].radius = 0.005" in told
    assert any(warning["code"] == "lengths-in-mm" and words in warning["detail"]
               for warning in results["balancing"]["warnings"])
    assert f"mass 1's radius, 5 m, is {5.0 / 0.22:.3g} times the 0.22 m" in note


_SLIPS = ("rev/min typed for rad/s", "grams typed for kg", "as millimetres,", " in radians: ", "mm/s typed for m/s", "mm typed for m?")


@pytest.mark.parametrize("scene", [*SCENES, *STARTERS], ids=str)
def test_no_fixture_test_scene_or_starter_is_told_of_a_unit_slip(tmp_path, capsys, scene):
    from graphplan.analysis import analyse
    from graphplan.deliverables import outcome_warnings
    from graphplan.scene import load

    path = _scene(tmp_path, starter(scene, "en")) if isinstance(scene, str) else scene
    loaded = load(path)
    pieces = ("note", *(piece for piece in ("dynamics", "vibration", "balancing") if getattr(loaded, piece)))
    told = outcome_warnings(loaded, pieces, None)
    if loaded.driver is not None:
        told += [warning.detail for warning in analyse(loaded).warnings]
    assert not [line for line in told if any(slip in line for slip in _SLIPS)]


def test_a_slider_s_mass_in_grams_is_warned_of_by_the_mechanism_s_size(tmp_path, capsys):
    """A slider's block has no span of its own, and its mass in grams (the piston's 0.9 kg as 900) passed with no
    word, where every other link's is told.  No block outweighs a solid steel bar as long as its mechanism is across,
    the largest distance between two of its points: at the first position O to B, 0.24 m."""
    text = _edited("slider-crank", 'mass    = 0.9\ncentre  = "B"', 'mass    = 900.0\ncentre  = "B"')
    told, results, _ = _run(tmp_path, text, capsys)
    points = [complex(*point["r"]) for point in results["positions"][0]["points"].values()]
    across = max(abs(a - b) for a in points for b in points)
    assert across == pytest.approx(0.24)
    bar = 7850.0 * across * max(across, 0.1) ** 2
    words = (f"links.4.mass = 900 kg on a slider of a mechanism {across:.3g} m across (B–O), heavier than a solid "
             f"steel bar of that length ({bar:.3g} kg): grams typed for kg? 900 g is links.4.mass = 0.9")
    assert words in told
    assert any(warning["code"] == "masses-in-grams" and words in warning["detail"] for warning in results["warnings"])
    # The piston as the starter has it, 0.9 kg, is no slip.
    told, results, _ = _run(tmp_path, starter("slider-crank", "en"), capsys)
    assert "grams typed for kg" not in told


LIFT = """[scene]
title = "Lift"
[frame]
link = 1
points = { G = [0.0, 0.0], C = [0.45, 0.30] }
lines = { cylinder = { through = "G", angle = 30.0 } }
[driver]
kind = "slider"
link = 2
joint = "A"
guide = "cylinder"
travel = [0.05, 0.30]
velocity = 0.10
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.30, 0.20]
assembly = "right"
[points]
E = { link = 4, from = "C", toward = "B", at = -0.35 }
[[loads]]
kind = "force"
link = 4
point = "E"
value = 900.0
angle = -90.0
resisting = true
during = "{during}"
[positions]
count = 12
number_from = 1
working = { link = 4, sense = "ccw" }
"""


def test_a_resisting_force_whose_point_turns_back_along_its_line_in_its_window_is_warned_of(tmp_path, capsys):
    """A lifted weight typed resisting = true: the lever's end E rises, passes the top of its arc and sinks within
    the working stroke, and the 900 N pushed it up from there on, with no word (a student's lift)."""
    told, results, note = _run(tmp_path, LIFT.replace("{during}", "working"), capsys)
    # E's vertical velocity at each position: rising, the load resists it pointing down (−90°); sinking, up.
    rising, sinking = [], []
    for number, position in enumerate(results["positions"], start=1):
        (rising if position["points"]["E"]["v"][1] > 0 else sinking).append(str(number))
    assert rising and sinking
    words = (f"loads[0] (F4) resists E's motion along its line, and within its window E moves both ways along it: F4 "
             f"acts at -90° at positions {', '.join(rising)} and turns round to 90° at positions {', '.join(sinking)}; "
             "a load of one direction whatever the motion (a weight lifted) is resisting = false")
    assert words in told
    assert any(warning["code"] == "resisting-turns-round" and warning["detail"] == words
               for warning in results["warnings"])
    assert "so the force turns round with the motion there" in note
    # Acting always, a resistance turns round with the motion as it should: no word.
    told, results, _ = _run(tmp_path, LIFT.replace("{during}", "always"), capsys)
    assert "resists E's motion" not in told


def test_a_links_inertia_in_another_unit_is_warned_of_by_its_radius_of_gyration(tmp_path, capsys):
    """A coupler's J a thousand times its own (510 for 0.51 kg·m²) ran without a word: only the crank's was judged.
    Its radius of gyration √(J/m), worked out here from the starter's mass and the coupler's length A–B, lies ten
    times beyond the link, which no link's mass does."""
    text = _edited("crank-rocker", "inertia = 0.51", "inertia = 510.0")
    told, results, note = _run(tmp_path, text, capsys)
    first = results["positions"][0]["points"]
    length = abs(complex(*first["A"]["r"]) - complex(*first["B"]["r"]))
    assert length == pytest.approx(0.55)
    gyration = math.sqrt(510.0 / 17.0)
    assert gyration > 2.0 * length
    words = (f"links.3.inertia = 510 kg·m² with mass = 17 kg gives a radius of gyration √(J/m) = {gyration:.3g} m, "
             f"{gyration / length:.3g} times the link {length:.3g} m long (A–B), where a uniform bar of that length "
             f"has {length / math.sqrt(12.0):.3g} m (J = m·l²/12 = {17.0 * length ** 2 / 12.0:.3g} kg·m²)")
    assert words in told
    # As kg·cm² it is 0.051 kg·m², a radius of gyration a tenth of the link; as kg·mm² 0.01 of it, too small to offer.
    assert "kg·cm² typed for kg·m²? 510 kg·cm² is links.3.inertia = 0.051" in told and "kg·mm² is" not in told
    assert any(warning["code"] == "inertia-too-large" and words in warning["detail"]
               for warning in results["warnings"])
    assert "kg·cm² or kg·mm² where kg·m² are asked for" in note
    # The coupler as the starter has it, and a J ten times it (k = 0.55 m, the link's length), are no slip.
    for inertia in ("0.51", "5.1"):
        told, results, _ = _run(tmp_path, _edited("crank-rocker", "inertia = 0.51", f"inertia = {inertia}"), capsys)
        assert "radius of gyration" not in told
        assert "inertia-too-large" not in {warning["code"] for warning in results["warnings"]}


def test_lengths_in_millimetres_are_not_told_again_as_a_load_in_kn(tmp_path):
    """The ratchet typed in mm (every length a thousand times): its weights' moments grew a thousandfold over links
    325 m long, and the rocker's 1500 N·m was told "kN·m typed for N·m? … loads[0].value = 1.5e+06", a fix that
    makes the load a thousand times too large."""
    import graphplan
    from graphplan.analysis import analyse

    text = Path("fixtures/ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    text = text[:text.index("[measured.5]")] + text[text.index("[drawing]"):]
    for old, new in (("C = [0.0, 0.55]", "C = [0.0, 550.0]"), ("length  = 0.175", "length  = 175.0"),
                     ("lengths  = [0.55, 0.325]", "lengths  = [550.0, 325.0]"), ("at = 0.08", "at = 80.0"),
                     ("at = 0.24", "at = 240.0"), ("offset = 0.125", "offset = 125.0"), ("at = 0.14", "at = 140.0"),
                     ("length_scale      = 0.0025", "length_scale      = 2.5")):
        assert old in text
        text = text.replace(old, new)
    codes = [warning.code for warning in analyse(graphplan.load_text(text)).warnings]
    assert "lengths-in-mm" in codes and "load-in-kn" not in codes
