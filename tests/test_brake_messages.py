"""What a scene's brake is told: a brake on from the start that holds the machine is named in the "does not start"
message with its torque, a brake applied later that brings the running machine to rest against its motor is named
for the stall (not a motor too weak), a brake switched on before the run is refused, and a viscous brake too stiff to
integrate is refused before the run, not after a minute of integrating."""

from __future__ import annotations

import math
import time

import pytest

from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.machine_motion import read_motion

# A machine of 2 kg·m² against a constant 100 N·m, driven by a constant 150 N·m: it starts unless a brake adds
# more than 50 N·m at rest.
HELD = ('[scene]\ntitle = "held"\n[dynamics]\ninertia = 2.0\nrpm = 90\n'
        "resisting_torque = [[0, 100], [360, 100]]\n"
        'motor = { kind = "constant", torque = 150.0 }\nduration = 2.0\n')


def _run(tmp_path, text: str, command: str = "run") -> int:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    return main([command, str(scene)] + (["--out", str(tmp_path / "out")] if command == "run" else []))


def _said(capsys) -> str:
    """What the command printed: its warnings go to the standard output, its errors to the standard error."""
    printed = capsys.readouterr()
    return printed.out + printed.err


def _warning(capsys) -> str:
    """The command's first warning line."""
    return next(line for line in _said(capsys).splitlines() if line.startswith("warning:"))


def test_a_brake_on_from_the_start_is_named_with_its_torque_where_the_machine_does_not_start(tmp_path, capsys):
    """The brake's 80 N·m at t = 0 joins the 100 N·m of resistance: 150 N·m cannot move 180.  The message said
    "150 N·m does not overcome 100 N·m" and advised a stronger motor."""
    assert _run(tmp_path, HELD + "brake = { torque = 80.0 }\n") == 0
    told = _said(capsys)
    resisting, brake = 100.0, 80.0  # the scene's Mr at rest and the brake's torque
    assert "does not start" in told
    assert f"the brake applied at t = 0 s, {resisting:.4g} + {brake:g} = {resisting + brake:.4g} N·m" in told
    assert "dynamics.brake.torque" in told and "dynamics.brake.at" in told
    assert "a stronger motor" not in told
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert (f"the brake applied at t = 0 s, Mr + Mt = {resisting:g} + {brake:g} = {resisting + brake:g} N·m. "
            "The brake on from the start holds the machine") in note


def test_a_brake_that_comes_on_after_the_start_leaves_the_does_not_start_message_alone(tmp_path, capsys):
    """A weak motor (90 N·m against 100) and a brake at 1 s: the resistance alone holds the machine, and the
    message is the motor's, with no brake in it."""
    assert _run(tmp_path, HELD.replace("torque = 150.0", "torque = 90.0") + "brake = { torque = 80.0, at = 1.0 }\n") == 0
    told = _warning(capsys)
    assert "does not start" in told and "brake" not in told and "a stronger motor" in told


@pytest.mark.parametrize(("locale", "sentence"), [
    ("en", "the brake applied at t = 0.5 s brings it to rest at t = 1.333 s"),
    ("ru", "тормоз, включённый при t = 0,5 с, останавливает машину при t = 1,333 с"),
    ("zh", "t = 0.5 s 接合的制动器使机器在 t = 1.333 s"),
])
def test_a_brake_that_stops_the_running_machine_against_its_motor_is_named_for_the_stall(tmp_path, capsys, locale,
                                                                                      sentence):
    """150 N·m against 100 N·m speeds 2 kg·m² up at 25 rad/s² to 12.5 rad/s at 0.5 s; the brake's 80 N·m then
    slows it at (150 − 180)/2 = −15 rad/s², to rest 12.5/15 s later, at 1.333 s, where 150 N·m cannot move 180.
    It said the motor could not carry the machine past the resistance and advised a stronger motor."""
    scene = HELD.replace("[scene]\n", f'[scene]\nlocale = "{locale}"\n') + "brake = { torque = 80.0, at = 0.5 }\n"
    assert _run(tmp_path, scene) == 0
    told = _warning(capsys)
    stop = 0.5 + 12.5 / 15.0
    assert f"the brake applied at t = 0.5 s brings the machine to rest at t = {stop:.4g} s" in told
    assert "against the brake's 80 N·m and the resistance there, 100 N·m" in told and "stronger motor" not in told
    assert sentence in (tmp_path / "out" / "note.md").read_text(encoding="utf-8")


# HELD's machine behind a 60 N·m clutch, the motor's rotor 1 kg·m² (the driving half): the clutch slips from the start,
# speeding the shaft up at (60 − 50)/2 = 5 rad/s² against a constant 50 N·m.
CLUTCHED = ('[scene]\ntitle = "clutched"\n[dynamics]\ninertia = 2.0\nrpm = 90\n'
            'motor = { kind = "constant", torque = 150.0, rotor_inertia = 1.0 }\nclutch = { torque = 60.0 }\n'
            "duration = 2.0\n")


@pytest.mark.parametrize(("locale", "sentence"), [
    ("en", "where the clutch, slipping at its 60 N·m, cannot turn it against the brake's 40 N·m"),
    ("ru", "где муфта, пробуксовывая с моментом 60 Н·м, не может провернуть её против тормоза с моментом 40 Н·м"),
    ("zh", "离合器以 60 N·m 打滑，克服不了 40 N·m 的制动力矩"),
])
def test_a_brake_that_stops_the_machine_against_its_slipping_clutch_is_named_for_the_stall(tmp_path, capsys, locale,
                                                                                         sentence):
    """At 0.5 s the shaft runs at 2.5 rad/s, 0.625 rad on; the brake's 40 N·m then slows it at (60 − 90)/2 =
    −15 rad/s², to rest 2.5/15 s later, at 0.6667 s, 0.625 + 2.5²/30 rad = 47.75° on, where the clutch's 60 N·m
    beats Mr's 50 alone.  It said the clutch could not pass the resistance, 50 N·m, and advised a larger clutch."""
    scene = (CLUTCHED.replace("[scene]\n", f'[scene]\nlocale = "{locale}"\n') + "resisting_torque = [[0, 50], "
             "[360, 50]]\nbrake = { torque = 40.0, at = 0.5 }\n")
    assert _run(tmp_path, scene) == 0
    told = _warning(capsys)
    stop, angle = 0.5 + 2.5 / 15.0, math.degrees(0.625 + 2.5 ** 2 / 30.0)
    assert told == (f"warning: dynamics: the brake applied at t = 0.5 s brings the machine to rest at t = {stop:.4g} "
                    f"s, φ = {angle:.4g}°, where the clutch, slipping at its 60 N·m, cannot turn it against the "
                    "brake's 40 N·m and the resistance there, 50 N·m (a smaller dynamics.brake.torque keeps it "
                    "turning; dynamics.motor.off_at switches the motor off to stop it)")
    assert sentence in (tmp_path / "out" / "note.md").read_text(encoding="utf-8")


def test_a_clutch_short_of_mr_alone_where_the_braked_machine_stalls_is_blamed_not_the_brake(tmp_path, capsys):
    """Mr rises from 50 to 100 N·m at 90°: a brake of 5 N·m at 0.5 s still lets 60 N·m speed the shaft up
    ((60 − 55)/2 > 0), and it stalls past 90°, where 60 N·m is short of Mr's 100 alone: the clutch is to blame."""
    scene = CLUTCHED + "resisting_torque = [[0, 50], [90, 50], [90, 100], [360, 100]]\nbrake = { torque = 5.0, at = 0.5 }\n"
    assert _run(tmp_path, scene) == 0
    told = _warning(capsys)
    assert "the clutch, slipping at its 60 N·m, cannot carry it past the resistance there, 100 N·m" in told
    assert "brake" not in told


def test_the_motion_plot_names_the_brake_that_holds_the_machine_where_it_stands():
    """HELD's machine run from Python: the brake at 0.5 s brings it to rest at 0.5 + 12.5/15 s (as above), and on
    from the start it holds the machine where it stands (150 N·m against 100 + 80).  A brake of damping alone takes
    nothing at rest: the stall is the motor's, and the title names no brake."""
    from graphplan.locale import strings
    from graphplan.machine_motion import Brake, Clutch, ConstantTorque, Machine, Stall, simulate
    from graphplan.report.motion_plots import _why_not_steady

    machine, motor = Machine(2.0, resisting=100.0), ConstantTorque(150.0)
    for brake, stall, key in ((Brake(torque=80.0, at=0.5), Stall.BRAKE, "motion_stalled_braked"),
                              (Brake(torque=80.0), Stall.NEVER_STARTS_BRAKED, "motion_never_starts_braked")):
        motion = simulate(machine, motor, brake=brake, duration=2.0, rtol=1e-10)
        assert motion.stall is stall and motion.stall_brake is brake
        for locale in ("en", "ru", "zh"):
            text = strings(locale)
            time = f"{motion.stalled_at:.4g}".replace(".", text["decimal_mark"])
            assert time == ("0" if brake.at == 0 else text["decimal_mark"].join(["1", "333"]))
            said = _why_not_steady(motion, text, 170.0)
            at = f"{brake.at:g}".replace(".", text["decimal_mark"])
            assert said == text[key].format(time=time, angle="170", at=at)
    # 30 N·m through a slipping clutch would not start it against Mr's 100 alone: the clutch is blamed, not the
    # brake on from the start.
    held = simulate(machine, motor, brake=Brake(torque=80.0), clutch=Clutch(30.0, inertia=1.0), duration=2.0,
                    rtol=1e-10)
    assert held.stall is Stall.NEVER_STARTS_CLUTCH and held.stall_brake is None
    for locale in ("en", "ru", "zh"):
        text = strings(locale)
        assert _why_not_steady(held, text, 170.0) == text["motion_never_starts_clutch"].format(angle="170")
    # 60 N·m through it beats Mr's 50 N·m alone: the brake at 0.5 s, not the clutch, brings it to rest.
    braked = simulate(Machine(2.0, resisting=50.0), motor, brake=Brake(torque=40.0, at=0.5),
                      clutch=Clutch(60.0, inertia=1.0), duration=2.0, rtol=1e-10)
    assert braked.stall is Stall.BRAKE_CLUTCH and braked.stall_brake is braked.brake
    for locale in ("en", "ru", "zh"):
        text = strings(locale)
        mark = text["decimal_mark"]
        assert _why_not_steady(braked, text, 47.75) == text["motion_stalled_braked_clutch"].format(
            time=f"0{mark}6667", angle=f"47{mark}75", at=f"0{mark}5")
    damped = simulate(Machine(2.0, resisting=lambda phi, omega: 100.0 + 200.0 * (phi > 1.0)), motor,
                      brake=Brake(damping=1.0), rtol=1e-10)
    assert damped.stall is Stall.MOTOR and damped.stall_brake is None
    text = strings("en")
    said = _why_not_steady(damped, text, 57.3)
    assert said == text["motion_stalled"].format(time=f"{damped.stalled_at:.4g}", angle="57.3")


def test_a_brake_switched_on_before_the_run_is_refused_naming_the_key():
    with pytest.raises(SceneError) as caught:
        read_motion({"motor": {"kind": "constant", "torque": 3.0}, "brake": {"torque": 1.0, "at": -1.0}})
    assert str(caught.value) == "dynamics.brake.at: must be >= 0 (got -1.0)"


# A machine of 2 kg·m² against 300 N·m, driven by a linear motor of 1200 N·m at rest and 120 rpm unloaded: it runs
# where 1200·(1 − ω/ω0) = 300, at ω = 0.75·ω0, a turn in 2π/ω.
STIFF = ('[scene]\ntitle = "stiff brake"\n[dynamics]\ninertia = 2.0\nrpm = 90\n'
         "resisting_torque = [[0, 300], [360, 300]]\n"
         'motor = { kind = "linear", stall_torque = 1200.0, no_load_rpm = 120.0 }\n')
INERTIA = 2.0
PERIOD = 2 * math.pi / (0.75 * 120 * math.pi / 30)


def test_a_viscous_brake_far_too_stiff_to_integrate_is_refused_at_once_naming_the_key(tmp_path, capsys):
    """1e12 N·m·s on 2 kg·m² gives J/c = 2e-12 s against a turn of 0.67 s.  The like of it in the flywheel
    starter integrated for 75 s and then blamed the motor ("look at the motor's speed, its gear ratio")."""
    began = time.perf_counter()
    assert _run(tmp_path, STIFF + "brake = { damping = 1.0e12, at = 0.5 }\n", "check") != 0
    assert time.perf_counter() - began < 20.0
    told = _said(capsys)
    assert "dynamics.brake.damping: 1e+12 N·m·s" in told
    assert f"J/c = {INERTIA / 1e12:.3g} s" in told and f"{PERIOD:.4g} s" in told
    # The stiffest it takes: a time constant of a hundredth of the period.
    assert f"at most {INERTIA / (0.01 * PERIOD):.3g} N·m·s" in told
    assert "motor's speed" not in told


@pytest.mark.parametrize("share, refused", [(0.9, True), (1.1, False)])
def test_the_stiffest_damping_a_brake_may_have_gives_a_hundredth_of_a_turn(tmp_path, capsys, share, refused):
    """Either side of c = J/(0.01·T): a little stiffer is refused, a little softer runs."""
    damping = INERTIA / (share * 0.01 * PERIOD)
    code = _run(tmp_path, STIFF + f"brake = {{ damping = {damping!r}, at = 0.5 }}\nduration = 3.0\n")
    told = _said(capsys)
    assert (code != 0) == refused
    assert ("brake.damping" in told) == refused
