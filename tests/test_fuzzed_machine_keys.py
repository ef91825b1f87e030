"""Scenes a fuzzer of the machine's keys (each of [dynamics]', [balancing]', [vibration]' and [[friction]]' values in
the starters and fixtures replaced one at a time by another type, nought, a negative, NaN, inf, a power of ten, a
string; each key deleted, each table emptied) found answered wrongly: each as the small scene it came down to, and
the answer a student should get instead."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from graphplan.cli import main


def _scene(tmp_path: Path, text: str) -> Path:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    return scene


def _starter(tmp_path: Path, kind: str) -> str:
    path = tmp_path / f"{kind}.toml"
    assert main(["new", kind, "--out", str(path)]) == 0
    return path.read_text(encoding="utf-8")


def _refused(capsys, code: int) -> str:
    """The one error line of a refusal, with no traceback before it."""
    assert code == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return err.strip().splitlines()[-1]


def _refused_by_run_and_check(tmp_path: Path, capsys, scene: Path, key: str, *said: str, opening: str = "") -> str:
    """The one error line with which `run` refuses ``scene`` at ``key``, its problem opening with ``opening`` and
    saying each of ``said``, with no traceback and no output folder written; `check` refuses it with the same line."""
    capsys.readouterr()
    out = tmp_path / "out"
    told = _refused(capsys, main(["run", str(scene), "--out", str(out)]))
    assert told.startswith(f"graphplan: error: {key}: {opening}"), told
    for words in said:
        assert words in told, told
    assert not out.exists()
    assert _refused(capsys, main(["check", str(scene)])) == told
    return told


# The flywheel starter's press: a 4 kW induction motor through 14.4 starts it from rest and settles at about 100 rpm.
MOTOR_LINE = 'motor = { kind = "kloss"'

# The one wording every key's refusal of a value the note and the drawings would write as 0 gives, in the key's unit:
# render/numerals.number writes a value below 1e-10 as 0.
WRITTEN_AS_NOUGHT = "must be above 1e-10 {unit}, the size the note and the drawings write as 0"


@pytest.mark.parametrize("tolerance", [0.5, 1e6])
def test_a_steady_tolerance_that_takes_the_start_up_for_steady_is_refused_at_its_key(tmp_path, capsys,
                                                                                      tolerance) -> None:
    """steady_tolerance is how near a turn's ωm and δ must have come to the next's: 1e6 took the third turn of the
    start-up for the steady state, and results.json said the press was steady after 2.97 s though it reached its
    speed only at 3.03 s.  No tolerance of a whole ωm or more tells a steady turn: it is refused at its key, and
    nothing is written."""
    text = _starter(tmp_path, "flywheel")
    assert text.count(MOTOR_LINE) == 1
    scene = _scene(tmp_path, text.replace(MOTOR_LINE, f"steady_tolerance = {tolerance!r}\n{MOTOR_LINE}"))
    _refused_by_run_and_check(tmp_path, capsys, scene, "dynamics.steady_tolerance", opening="must be at most 0.001")


def test_the_loosest_steady_tolerance_finds_the_steady_state_after_the_start_up(tmp_path, capsys) -> None:
    """At the loosest tolerance taken the steady state still begins after the start-up: a machine is not steady
    before it has come within 5 % of its running speed."""
    text = _starter(tmp_path, "flywheel")
    scene = _scene(tmp_path, text.replace(MOTOR_LINE, f"steady_tolerance = 0.001\n{MOTOR_LINE}"))
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    assert motion["steady"] is True
    assert motion["steady_after"] >= motion["start_up_time"] > 0


# A machine of 2 kg·m² against a constant 50 N·m, driven by a constant 150 N·m through a 60 N·m clutch whose driving
# half is the motor's 1 kg·m² rotor (tests/test_brake_messages.py's CLUTCHED, the clutch and brake given below).
MACHINE = ('[scene]\ntitle = "clutched"\n[dynamics]\ninertia = 2.0\nrpm = 90\n'
           "resisting_torque = [[0, 50], [360, 50]]\n"
           'motor = { kind = "constant", torque = 150.0, rotor_inertia = 1.0 }\n')


@pytest.mark.parametrize(("given", "key", "said"), [
    ("clutch = { torque = 60.0, engage_at = -1.0 }\nduration = 2.0\n", "dynamics.clutch.engage_at",
     "must be >= 0"),
    ("clutch = { torque = 60.0, engage_at = 5.0 }\nduration = 2.0\n", "dynamics.clutch.engage_at",
     "is at or past the run's end, dynamics.duration = 2 s, so the clutch never engages"),
    ("clutch = { torque = 60.0, engage_at = 1e6 }\n", "dynamics.clutch.engage_at",
     "the clutch never engages"),
    ("brake = { torque = 20.0, at = 5.0 }\nduration = 2.0\n", "dynamics.brake.at",
     "is at or past the run's end, dynamics.duration = 2 s, so the brake never comes on"),
    ("brake = { torque = 20.0, at = 1e6 }\n", "dynamics.brake.at", "the brake never comes on"),
], ids=["clutch-before-the-start", "clutch-after-the-duration", "clutch-after-the-longest-run",
        "brake-after-the-duration", "brake-after-the-longest-run"])
def test_a_clutch_or_brake_that_never_acts_within_the_run_is_refused_at_its_key(tmp_path, capsys, given, key,
                                                                                said) -> None:
    """A clutch engaged after the run's end left the machine at rest for the whole run, and the run said "no
    steady state within the run: the machine is still speeding up at ω = 0 rad/s; a longer duration runs it on"
    (or ran 2000 turns' time to say it); one engaged at -1 s, a slip a brake's `at` is refused for, was taken as
    engaged from the start.  A brake applied after the run's end was written into the note's equation of motion
    though it never acted.  Each is refused at its key, as a motor switched off past the run's end is, and nothing
    is written."""
    scene = _scene(tmp_path, MACHINE + given)
    _refused_by_run_and_check(tmp_path, capsys, scene, key, said)


def test_a_clutch_engaged_later_too_weak_to_move_the_machine_is_told_as_a_stall(tmp_path, capsys) -> None:
    """A 20 N·m clutch against 50 N·m of resistance cannot move the machine: engaged at the start, the run stops
    there and says so, but engaged at 0.5 s the run went on to its end (without a duration, to 2000 turns' time)
    and warned that the machine was "still speeding up at ω = 0 rad/s" and that "a longer duration runs it on".
    It is the stall it is engaged at the start, the clutch's torque named against Mr, from the time it engaged."""
    torque, resisting, engaged = 20.0, 50.0, 0.5
    scene = _scene(tmp_path, MACHINE + f"clutch = {{ torque = {torque}, engage_at = {engaged} }}\nduration = 2.0\n")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
    said = capsys.readouterr()
    assert "Traceback" not in said.err
    told = said.out + said.err
    assert "still speeding up" not in told and "a longer [dynamics] duration" not in told, told
    assert (f"the machine does not start: at rest at φ = 0° the clutch, slipping at its {torque:g} N·m, does not "
            f"overcome the resistance there, {resisting:g} N·m") in told, told
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    assert motion["stalled_at"] == pytest.approx(engaged)
    assert motion["clutch_locked_at"] is None
    assert motion["stalled_at_angle_deg"] == 0.0
    assert motion["duration"] == pytest.approx(engaged)


@pytest.mark.parametrize("delta", [1e-14, 1e-6, 5e-5])
def test_a_delta_no_machine_runs_at_is_refused_at_its_key(tmp_path, capsys, delta) -> None:
    """δ = 1e-14 sized the press's flywheel at ΔWmax/(ωm²·δ), some 1e14 times the one for δ = 0.05, which its 4 kW
    motor then ran for 2000 turns' time without bringing it to speed, and the run advised "a longer duration runs it
    on".  The evenest machines, alternators, run at δ of some 1/300: a δ below 0.0001 is refused at its key, and
    nothing is written."""
    text = _starter(tmp_path, "flywheel")
    assert text.count("delta = 0.05 ") == 1
    scene = _scene(tmp_path, text.replace("delta = 0.05 ", f"delta = {delta!r} "))
    _refused_by_run_and_check(tmp_path, capsys, scene, "dynamics.delta", opening="must be at least 0.0001")


def test_the_smallest_delta_taken_sizes_the_flywheel_in_proportion(tmp_path, capsys) -> None:
    """At δ = 0.0001 the flywheel is sized, 500 times the starter's for δ = 0.05, as JF = ΔWmax/(ωm²·δ) − Je
    (the starter's Je is 0)."""
    text = _starter(tmp_path, "flywheel")
    found = {}
    for delta in (0.05, 0.0001):
        out = tmp_path / f"out{delta}"
        scene = _scene(tmp_path, text.replace("delta = 0.05 ", f"delta = {delta!r} ").replace(MOTOR_LINE, "# "))
        assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
        found[delta] = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]
    assert found[0.0001]["flywheel_inertia"] == pytest.approx(500 * found[0.05]["flywheel_inertia"], rel=1e-9)


@pytest.mark.parametrize(("f", "asked"), [(5.0, True), (100.0, True), (1e6, False)])
def test_an_unusual_f_is_asked_to_be_a_percentage_only_where_that_gives_a_usual_f(tmp_path, capsys, f, asked) -> None:
    """An f above 1 on the shaper's ram slide is warned of, asking whether it is a percentage: f = 5 may be 5 %,
    f = 0.05.  f = 1e6 was asked the same, "(1e+06 % is f = 10000)", an f further from any pair of materials than
    the one typed.  The question is asked only where the percentage gives an f of at most 1."""
    text = _starter(tmp_path, "shaper")
    typed = 'links = [6, 1]\nf     = 0.1\n'
    assert text.count(typed) == 1
    scene = _scene(tmp_path, text.replace(typed, typed.replace("0.1", repr(f))))
    capsys.readouterr()
    assert main(["check", str(scene)]) == 0
    said = capsys.readouterr()
    warning = next(line for line in (said.out + said.err).splitlines()
                   if line.startswith(f"warning: friction[0].f = {f:g} (at E)"))
    assert "few pairs of materials rub with an f above 1" in warning
    percentage = f"is it a percentage? ({f:g} % is f = {f / 100:g})"
    assert (percentage in warning) is asked, warning
    assert asked is (f / 100 <= 1)


@pytest.mark.parametrize(("key", "typed", "asked"), [
    ("delta", 5.0, "(5 % is δ = 0.05)"), ("delta", 1e14, None),
    ("overload", 220.0, "(220 % is overload = 2.2)"), ("overload", 2200.0, None),
])
def test_a_value_is_asked_to_be_a_percentage_only_where_the_percentage_is_taken(tmp_path, capsys, key, typed,
                                                                               asked) -> None:
    """δ = 1e14 was refused asking "a percentage typed for a fraction? (1e+14 % is δ = 1e+12)", and overload = 2200
    "(2200 % is overload = 22)": values the same key refuses too.  The question is asked only where the percentage
    is a value the key takes (δ < 2, 1 < overload < 10)."""
    text = _starter(tmp_path, "flywheel")
    given = {"delta": "delta = 0.05 ", "overload": "overload = 2.2,"}[key]
    assert text.count(given) == 1
    scene = _scene(tmp_path, text.replace(given, given.replace(given.split("= ")[1].strip(" ,"), repr(typed))))
    capsys.readouterr()
    told = _refused(capsys, main(["check", str(scene)]))
    assert told.startswith(f"graphplan: error: dynamics.{'motor.' if key == 'overload' else ''}{key}: "), told
    if asked is None:
        assert "percentage" not in told, told
    else:
        assert asked in told, told


@pytest.mark.parametrize(("zeta", "asked"), [(5.0, True), (1e6, False)])
def test_an_over_critical_damping_ratio_is_asked_to_be_a_percentage_only_where_that_is_a_mounts(tmp_path, capsys,
                                                                                               zeta, asked) -> None:
    """The rotor starter's mounts given ζ = 5 are warned over-critical and asked whether 5 % (ζ = 0.05) was meant;
    ζ = 1e6 was asked the same, "(1e+06 % is ζ = 10000)", a ζ as over-critical as the one typed.  Asked only where
    the percentage is below 1, a ratio a mount damps at."""
    text = _starter(tmp_path, "rotor")
    typed = "damping_ratio = 0.1 "
    assert text.count(typed) == 1
    scene = _scene(tmp_path, text.replace(typed, f"damping_ratio = {zeta!r} "))
    capsys.readouterr()
    assert main(["check", str(scene)]) == 0
    said = capsys.readouterr()
    warning = next(line for line in (said.out + said.err).splitlines()
                   if line.startswith("warning: vibration.damping_ratio: "))
    assert f"ζ = {zeta:g} is over-critical (above 1)" in warning
    assert (f"({zeta:g} % is ζ = {zeta / 100:g})" in warning) is asked, warning
    assert asked is (zeta / 100 < 1)


def test_an_unbalance_that_would_put_the_whole_machine_beyond_any_rotor_is_warned_of(tmp_path, capsys) -> None:
    """unbalance = 1e6 kg·m on the rotor starter's 100 kg machine ran without a word and wrote an amplitude of
    13 km: m·e over M is the least eccentricity the unbalance needs (the whole machine off its axis, as
    unbalanced_mass may be no more than mass), here 1e4 m, farther than any rotor's radius (150 m), as the same
    eccentricity given apart is warned of.  Warned of at its key, with that distance."""
    text = _starter(tmp_path, "rotor")
    typed = "unbalance     = 0.02 "
    assert text.count(typed) == 1
    unbalance, mass = 1e6, 100.0
    scene = _scene(tmp_path, text.replace(typed, f"unbalance     = {unbalance!r} "))
    capsys.readouterr()
    assert main(["check", str(scene)]) == 0
    said = capsys.readouterr()
    warning = next((line for line in (said.out + said.err).splitlines() if "vibration.unbalance = " in line), None)
    assert warning is not None, said.out + said.err
    assert f"{unbalance / mass:g} m from the axis" in warning and "over 150 m" in warning, warning
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note", "--locale", "ru"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    assert f"требует сместить от оси всю машину, {mass:g} кг, на {unbalance / mass:g} м" in note


@pytest.mark.parametrize(("typed", "given", "key", "unit"), [
    ("mass          = 100.0 ", "mass          = 1e-14 ", "vibration.mass", "kg"),
    ("stiffness     = 1.0e5 ", "shaft = { modulus = 2.1e11, diameter = 1e-6, length = 0.8 } ", "vibration.shaft",
     "N/m"),
    ("stiffness     = 1.0e5 ", "stiffness     = 1e-12 ", "vibration.stiffness", "N/m"),
], ids=["mass", "shaft", "stiffness"])
def test_a_mass_or_stiffness_the_note_writes_as_nought_is_refused_at_its_key(tmp_path, capsys, typed, given,
                                                                             key, unit) -> None:
    """The note writes a quantity below 1e-10 as 0, as no machine's is so small: a machine of 1e-14 kg on its mounts
    ended the run in ZeroDivisionError as the note worked out ωn = √(k/M) with M written 0, and a shaft of modulus
    1e-14 Pa (now refused at its modulus; here a shaft of 1 µm), k = 48·E·I/L³ some 1e-20 N/m, in ValueError ("stiffness: must be > 0"), after `check` had passed both.
    Each is refused at its key by run and check alike, and nothing is written."""
    text = _starter(tmp_path, "rotor")
    assert text.count(typed) == 1
    scene = _scene(tmp_path, text.replace(typed, given))
    _refused_by_run_and_check(tmp_path, capsys, scene, key, WRITTEN_AS_NOUGHT.format(unit=unit))


@pytest.mark.parametrize("inertia", [1e-14, 1e-10])
def test_a_machine_next_to_weightless_behind_its_clutch_is_refused_at_its_inertia(tmp_path, capsys, inertia) -> None:
    """A machine of 1e-14 kg·m² behind a 60 N·m clutch engaged at 0.5 s, driven by a linear motor, ended the run in
    scipy's "`ts` must be strictly increasing", named at no key: the clutch's torque runs so light a side up to speed
    in some 1e-15 s, within the rounding of the run's clock.  No machine comes to speed within a ten-thousandth of a
    turn behind its clutch: refused at dynamics.inertia with the least inertia that takes that long, J = 1e-4·P·Tc/ω,
    by run and check alike, and nothing is written."""
    torque = 60.0
    scene = _scene(tmp_path, MACHINE.replace("inertia = 2.0", f"inertia = {inertia!r}").replace(
        'motor = { kind = "constant", torque = 150.0, rotor_inertia = 1.0 }',
        'motor = { kind = "linear", stall_torque = 150.0, no_load_rpm = 120, rotor_inertia = 1.0 }')
        + f"clutch = {{ torque = {torque}, engage_at = 0.5 }}\n")
    told = _refused_by_run_and_check(tmp_path, capsys, scene, "dynamics.inertia")
    omega = float(told.split("up to the running speed, ")[1].split(" rad/s")[0])
    least = float(told.split("at least ")[1].split(" kg·m²")[0])
    assert least == pytest.approx(1e-4 * (2 * math.pi / omega) * torque / omega, rel=1e-2)
    assert inertia < least


def test_a_machine_as_light_as_the_bound_behind_its_clutch_runs(tmp_path, capsys) -> None:
    """At a few times the least inertia the refusal asks for, the same machine runs, and its clutch locks after it
    engages."""
    scene = _scene(tmp_path, MACHINE.replace("inertia = 2.0", "inertia = 0.005").replace(
        'motor = { kind = "constant", torque = 150.0, rotor_inertia = 1.0 }',
        'motor = { kind = "linear", stall_torque = 150.0, no_load_rpm = 120, rotor_inertia = 1.0 }')
        + "clutch = { torque = 60.0, engage_at = 0.5 }\n")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    assert motion["clutch_locked_at"] > 0.5


def test_a_constant_torque_that_runs_the_machine_past_any_shaft_speed_is_refused_at_the_torque(tmp_path,
                                                                                               capsys) -> None:
    """A constant motor of 1e7 N·m against 50 N·m was refused at dynamics.duration ("2 s is some 2.12e+06 turns"),
    a duration of two seconds, as though the run were too long: it is the torque that runs the 3 kg·m² machine (its
    2 and the rotor's 1) up at (1e7 − 50)/3 rad/s², past the 100 000 rpm no machine's shaft turns faster than in
    J·ω/(Md − Mr), some 3 ms.  Refused at the torque, saying when, by run and check alike, and nothing is written."""
    torque, resisting, inertia = 1e7, 50.0, 3.0
    scene = _scene(tmp_path, MACHINE.replace("torque = 150.0", f"torque = {torque!r}") + "duration = 2.0\n")
    told = _refused_by_run_and_check(tmp_path, capsys, scene, "dynamics.motor.torque", "past 100000 rpm",
                                     "within dynamics.duration = 2 s")
    seconds = float(told.split("the fastest a machine's shaft turns, ")[1].split(" s into the run")[0])
    assert seconds == pytest.approx(inertia * 100_000 * 2 * math.pi / 60 / (torque - resisting), rel=1e-2)


def test_a_duration_too_long_for_a_usual_torque_is_still_refused_at_the_duration(tmp_path, capsys) -> None:
    """The same machine at its 150 N·m takes some 260 000 turns to pass 100 000 rpm, more than a run integrates:
    over a duration of 1e5 s it is the duration that asks too many turns, and it is refused there as before."""
    scene = _scene(tmp_path, MACHINE + "duration = 1e5\n")
    told = _refused(capsys, main(["check", str(scene)]))
    assert told.startswith("graphplan: error: dynamics.duration: "), told


@pytest.mark.parametrize("engaged", [0.0, 0.5])
def test_a_clutch_too_weak_to_move_the_machine_with_no_duration_is_a_stall_not_a_runaway(tmp_path, capsys,
                                                                                         engaged) -> None:
    """With no duration, a 20 N·m clutch between a constant 150 N·m motor and 50 N·m of resistance was refused at
    dynamics.motor as a runaway ("the machine speeds up without end"), though the machine never moves: the clutch
    passes no more than its torque, short of the resistance, however fast the motor spins the driving half.  The run
    ends as the same clutch given a duration does: a stall where it engaged, the clutch's torque named against
    Mr."""
    torque, resisting = 20.0, 50.0
    scene = _scene(tmp_path, MACHINE + f"clutch = {{ torque = {torque}, engage_at = {engaged} }}\n")
    assert main(["check", str(scene)]) == 0
    capsys.readouterr()
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics"]) == 0
    said = capsys.readouterr()
    told = said.out + said.err
    assert "without end" not in told, told
    assert (f"the machine does not start: at rest at φ = 0° the clutch, slipping at its {torque:g} N·m, does not "
            f"overcome the resistance there, {resisting:g} N·m") in told, told
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    assert motion["stalled_at"] == pytest.approx(engaged)
    assert motion["clutch_locked_at"] is None


def test_a_clutch_stronger_than_the_resistance_behind_a_runaway_motor_is_still_refused(tmp_path, capsys) -> None:
    """A 60 N·m clutch passes more than the 50 N·m of resistance: locked, the 150 N·m motor runs the machine away,
    and with no duration that is refused at the motor as before."""
    scene = _scene(tmp_path, MACHINE + "clutch = { torque = 60.0 }\n")
    told = _refused(capsys, main(["check", str(scene)]))
    assert told.startswith("graphplan: error: dynamics.motor: ") and "speeds up without end" in told, told


@pytest.mark.parametrize(("given", "key", "unit"), [
    ("mass = 1e-14, radius = 0.05", "balancing.masses[0].mass", "kg"),
    ("mass = 18.0, radius = 1e-14", "balancing.masses[0].radius", "m"),
    ("mass = 1e-6, radius = 1e-5", "balancing.masses[0]", "kg·m"),
], ids=["mass", "radius", "product"])
def test_a_rotating_mass_the_note_writes_as_nought_is_refused_at_its_key(tmp_path, capsys, given, key,
                                                                       unit) -> None:
    """A mass of 1e-14 kg on the rotor starter ran, and the note's tables wrote its m = 0 and m·r = 0 beside the
    others, as though it were not there: the note writes a number below 1e-10 as 0, as a vibration's mass is refused
    for.  A mass, a radius off the axis or their product m·r so small is refused at its key by run and check alike,
    and nothing is written; a radius of 0, a mass on the axis, still runs."""
    from graphplan.render.numerals import number

    text = _starter(tmp_path, "rotor")
    typed = "mass = 18.0, radius = 0.05"
    assert text.count(typed) == 1
    mass, radius = (float(part.split("= ")[1]) for part in given.split(", "))
    assert "0" in {number(mass), number(radius), number(mass * radius)}
    scene = _scene(tmp_path, text.replace(typed, given))
    _refused_by_run_and_check(tmp_path, capsys, scene, key, WRITTEN_AS_NOUGHT.format(unit=unit))
    assert main(["check", str(_scene(tmp_path, text.replace(typed, "mass = 18.0, radius = 0.0")))]) == 0


@pytest.mark.parametrize(("given", "key"), [
    ('plane_names = ["' + "Left" * 20 + '", "R"]\ncorrection_radius = 0.05 ', "balancing.plane_names[0]"),
    ('plane_names = ["L", "' + "r" * 11 + '"]\ncorrection_radius = 0.05 ', "balancing.plane_names[1]"),
    ('correction_radius = 0.05 ', "balancing.masses[1].name"),
], ids=["plane-80", "plane-11", "mass-11"])
def test_a_name_too_long_to_letter_a_polygon_is_refused_at_its_key(tmp_path, capsys, given, key) -> None:
    """A correction plane named by 80 characters ran, and the polygons lettered its shares (m1r1)LeftLeft… and its
    caption some 200 mm past the 90 mm its polygon is drawn in.  A plane's or a mass's name of more than ten
    characters is refused at its key by run and check alike, and nothing is written; words of ten, a share's label
    holding both, still fit within the polygon's field, and run."""
    from graphplan.render import lettering
    from graphplan.render.balancing import POLYGON_FIELD_MM
    from graphplan.render.primitives import text_width

    text = _starter(tmp_path, "rotor")
    typed, mass = "correction_radius = 0.05 ", "{ mass = 14.0,"
    assert text.count(typed) == 1 and text.count(mass) == 1
    named = text.replace(mass, '{ name = "' + "n" * (11 if key.startswith("balancing.masses") else 10) + '", mass = 14.0,')
    scene = _scene(tmp_path, named.replace(typed, given))
    _refused_by_run_and_check(tmp_path, capsys, scene, key, "at most 10 characters")
    assert text_width("((m·r)impeller_a)drive_ends", lettering.NAME) < POLYGON_FIELD_MM
    fitting = text.replace(mass, '{ name = "impeller_a", mass = 14.0,').replace(
        typed, 'plane_names = ["drive_ends", "R"]\n' + typed)
    assert main(["check", str(_scene(tmp_path, fitting))]) == 0


@pytest.mark.parametrize("name", ["m1r1", "m1"])
def test_a_mass_named_as_its_product_reads_is_lettered_as_the_unnamed_mass_is(tmp_path, capsys, name) -> None:
    """The rotor starter says an unnamed mass is lettered m1r1; a first mass named "m1r1" was lettered "(m·r)m1r1",
    its shares "((m·r)m1r1)L", a name the note's symbols could not read as the product it was typed as.  Named as its
    product reads (or as the mass's symbol, m1), it is lettered as the starter's unnamed first mass is, in the note
    and on the polygons alike."""
    text = _starter(tmp_path, "rotor")
    typed = "{ mass = 18.0,"
    assert text.count(typed) == 1
    notes, drawings = {}, {}
    for given in ("", name):
        out = tmp_path / f"out{given}"
        named = text.replace(typed, f'{{ name = "{given}", mass = 18.0,') if given else text
        assert main(["run", str(_scene(tmp_path, named)), "--out", str(out), "--only", "balancing,note"]) == 0
        notes[given] = (out / "note.md").read_text(encoding="utf-8")
        drawings[given] = (out / "rotor_balancing.svg").read_text(encoding="utf-8")
    assert f"(m·r){name}" not in notes[name] and "((m·r)" not in notes[name]
    for plane in "LR":
        assert notes[name].count(f"(m1r1){plane}") == notes[""].count(f"(m1r1){plane}") > 0
    assert drawings[name] == drawings[""]


@pytest.mark.parametrize(("names", "said"), [
    ('["mL", "R"]', "would letter its correction mass mmL; name the plane 'L'"),
    ('["L", "m2r2"]', "would letter its correction mass mm2r2; name the plane '2'"),
], ids=["mass-symbol", "product-of-a-mass"])
def test_a_plane_named_as_a_symbol_is_refused_at_its_key(tmp_path, capsys, names, said) -> None:
    """A plane named "mL" lettered its correction mass "mmL = 28.267 kg", and one named "m2r2" lettered its correction
    "(m·r)m2r2" beside the second mass's m2r2 of another meaning.  A plane's name is the index its correction's symbols
    are lettered by: one written as such a symbol is refused at plane_names, with the index to name it by."""
    text = _starter(tmp_path, "rotor")
    typed = "correction_radius = 0.05 "
    scene = _scene(tmp_path, text.replace(typed, f"plane_names = {names}\n{typed}"))
    capsys.readouterr()
    told = _refused(capsys, main(["check", str(scene)]))
    assert told.startswith("graphplan: error: balancing.plane_names"), told
    assert said in told, told


@pytest.mark.parametrize(("radius", "said"), [
    (1e-14, WRITTEN_AS_NOUGHT.format(unit="m")),
    (1e-9, "puts a correction mass of "),
    (0.005, "puts a correction mass of "),
], ids=["written-as-nought", "a-billion-kg", "ten-of-the-masses"])
def test_a_correction_radius_that_gives_no_rotor_s_correction_mass_is_refused_at_its_key(tmp_path, capsys, radius,
                                                                                      said) -> None:
    """`correction_radius` had no bound: at 1e-9 m the rotor starter's plane L took a correction of 1.4e9 kg
    (mb = |mb·rb|/rb), at 1e-14 m one the note wrote beside a radius of 0.  The starter's masses turn within 0.06 m
    of the axis over the 0.22 m from the first mass's plane to plane R, and no rotor that size outweighs solid steel
    filling a cylinder twice as large in radius and in length, 7850·π·0.12²·0.44 kg: a correction heavier than that
    is none fixed on it.  Each radius is refused at its key by run and check alike, with the least radius that keeps
    plane L's correction within it, and nothing is written; that radius, and the starter's 0.05 m, run."""
    text = _starter(tmp_path, "rotor")
    typed = "correction_radius = 0.05 "
    assert text.count(typed) == 1 and "planes = [0.04, 0.22]" in text
    masses = ((18.0, 0.05, 0.0, 0.0), (14.0, 0.06, -60.0, 0.08), (10.0, 0.04, 135.0, 0.16))
    for mass, mass_radius, angle, plane in masses:
        assert f"mass = {mass}, radius = {mass_radius}, angle = {angle}, plane = {plane}" in text
    # Plane L's correction balances each mass's share (zR − z)/(zR − zL) of its m·r.
    share = sum(mass * mass_radius * (0.22 - plane) / 0.18 * complex(math.cos(math.radians(angle)),
                                                                     math.sin(math.radians(angle)))
                for mass, mass_radius, angle, plane in masses)
    heaviest = 7850.0 * math.pi * (2 * 0.06) ** 2 * (2 * 0.22)
    scene = _scene(tmp_path, text.replace(typed, f"correction_radius = {radius!r} "))
    told = _refused_by_run_and_check(tmp_path, capsys, scene, "balancing.correction_radius", opening=said)
    if "correction mass" in said:
        assert f"{abs(share) / radius:.4g} kg in plane L" in told, told
        least = float(told.split("give a correction radius of at least ")[1].split(" m")[0])
        assert abs(share) / heaviest <= least == pytest.approx(abs(share) / heaviest, rel=0.02)
        assert main(["check", str(_scene(tmp_path, text.replace(typed, f"correction_radius = {least!r} ")))]) == 0
    assert main(["check", str(_scene(tmp_path, text))]) == 0


@pytest.mark.parametrize(("masses", "planes", "per_plane"), [
    ("{ mass = 500.0, radius = 0.002, angle = 0.0 }", "", 500.0 * 0.002),
    (("{ mass = 500.0, radius = 0.002, angle = 0.0, plane = 0.0 }, "
      "{ mass = 500.0, radius = 0.002, angle = 90.0, plane = 1.0 }"), "planes = [0.0, 1.0]\n", 500.0 * 0.002),
], ids=["one-disc", "two-discs"])
def test_a_correction_radius_too_small_for_a_heavy_eccentric_rotor_is_refused_at_its_key(tmp_path, capsys, masses,
                                                                                       planes, per_plane) -> None:
    """A flywheel of 500 kg 2 mm off its axis, balanced in one plane at correction_radius = 1e-9, ran and put a
    correction of 1e9 kg on it, with a caution of millimetres alone: its radius holds no rotor that weighs 500 kg, and
    the correction was weighed against the largest rotor of all, 300 m of solid steel across.  A rotor that holds
    its masses reaches at least as far as solid steel weighing them, and no rotor that size outweighs solid steel
    twice as large in radius and length, 2³ times its masses: the correction is refused at its key past that, with
    the least radius that keeps it within, which runs; so for two such discs on a 1 m shaft, each corrected in its own
    plane, and at that radius they are not told their masses look like grams: the refusal took them as kg, discs off
    their centres, and typed in grams they would still outweigh their 2 mm radii (1 kg of solid steel over the 1 m
    shaft reaches √(1 / (7850·π·1)) = 6.4 mm from the axis).  Nothing is written."""
    scene = _scene(tmp_path, f'[scene]\ntitle = "eccentric"\n[balancing]\nmasses = [ {masses} ]\n{planes}'
                             "correction_radius = 1e-9\n")
    told = _refused_by_run_and_check(tmp_path, capsys, scene, "balancing.correction_radius",
                                     f"{per_plane / 1e-9:.4g} kg in plane ", opening="puts a correction mass of ")
    rotor_masses = 500.0 * masses.count("mass = ")
    least = float(told.split("give a correction radius of at least ")[1].split(" m")[0])
    assert per_plane / (2 ** 3 * rotor_masses) <= least == pytest.approx(per_plane / (2 ** 3 * rotor_masses), rel=0.1)
    assert main(["check", str(_scene(tmp_path, scene.read_text(encoding="utf-8").replace(
        "correction_radius = 1e-9", f"correction_radius = {least!r}")))]) == 0
    assert "grams typed for kg" not in capsys.readouterr().out
