"""The command line's warnings write a quantity as the note writes it, so that a user comparing them sees one number.

The dynamics' warnings printed speeds and δ to four digits (ωm = 11.74, φ = 47.7°, 245.789 N·m) beside the note's
11.745, 47.75° and 245.79; a damping ratio of 1 (1 % meant?) or above was told on the command line only, and the note,
which outlives it, worked every amplitude out of it without a word; the mounts' sag wrote k = 4018 beside 4018.4.
Each number is checked against the note's and against a calculation of its own.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from scipy.optimize import brentq

from graphplan.cli import main

RPM = 2.0 * math.pi / 60.0
# The flywheel starter's press: 367.7 W idling for a third of the turn, 3677 W punching for two thirds, at 100 rpm.
MEAN_RESISTANCE = (367.7 * 120.0 + 3677.0 * 240.0) / 360.0 / (100.0 * RPM)


def _printed(capsys) -> str:
    printed = capsys.readouterr()
    return printed.out + printed.err


def _warning(printed: str, start: str) -> str:
    return next(line for line in printed.splitlines() if line.startswith(f"warning: {start}"))


def _four_digits_kept(value: float) -> str:
    """``value`` to four significant digits, its trailing noughts kept (0.02350)."""
    return f"{value:.{3 - math.floor(math.log10(abs(value)))}f}"


def _flywheel_scene(tmp_path: Path, old: str, new: str) -> Path:
    """The flywheel starter as ``graphplan new`` writes it, ``old`` (a pattern of a line) made ``new``."""
    scene = tmp_path / "press.toml"
    assert main(["new", "flywheel", "--out", str(scene)]) == 0
    text, count = re.subn(old, new, scene.read_text(encoding="utf-8"), count=1, flags=re.MULTILINE)
    assert count == 1
    scene.write_text(text, encoding="utf-8")
    return scene


def _kloss_steady_speed(gear_ratio: float) -> float:
    """The shaft's speed where the starter's Kloss motor (4 kW, λ = 2.2, 1500/1440 rpm) through ``gear_ratio`` gives
    the press's mean resistance: u·M(s) = Mr with M(s) = 2·Mmax/(s/sk + sk/s), by hand."""
    synchronous, rated = 1500.0 * RPM, 1440.0 * RPM
    overload, rated_slip = 2.2, 1.0 - rated / synchronous
    most = overload * 4000.0 / rated
    critical = rated_slip * (overload + math.sqrt(overload ** 2 - 1.0))

    def surplus(omega: float) -> float:
        slip = 1.0 - gear_ratio * omega / synchronous
        return gear_ratio * 2.0 * most / (slip / critical + critical / slip) - MEAN_RESISTANCE

    top = synchronous / gear_ratio
    return brentq(surplus, 0.5 * top, top * (1.0 - 1e-9))


def test_the_off_design_warning_writes_the_steady_speed_and_delta_as_the_note(tmp_path, capsys):
    """Through 13:1 in place of 14.4:1 the motor settles the press at some 11.75 rad/s, 12 % above the 100 rpm its
    flywheel was sized at: the warning wrote ωm = 11.74 and 10.47 rad/s beside the note's 11.745 and 10.472."""
    scene = _flywheel_scene(tmp_path, r"gear_ratio = 14\.4", "gear_ratio = 13.0")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    line = _warning(_printed(capsys), "dynamics: the motor runs the machine at")
    settled, off, sized, steady = re.search(r"ωm = ([\d.]+) rad/s, (\d+)% off the ([\d.]+) rad/s its flywheel was "
                                            r"sized at for δ = 0\.05; steady, δ = ([\d.]+) ", line).groups()
    note = (out / "note.md").read_text(encoding="utf-8")
    assert f"mean speed in time 2π/T = {settled} rad/s" in note
    assert f"δ = (ωmax − ωmin)/ωm = {steady}." in note
    assert f"the integration gives {steady}," in note
    assert f"ωm = {sized} rad/s (100 rpm)" in note
    # Five significant digits as the note writes a speed worked out; the speed the flywheel was sized at, 100 rpm.
    assert len(settled.replace(".", "").lstrip("0")) == 5
    assert float(settled) == pytest.approx(_kloss_steady_speed(13.0), rel=1e-3)
    assert sized == f"{100.0 * RPM:.5g}"
    assert int(off) == round(100 * (float(settled) / float(sized) - 1))
    # δ = (ωmax − ωmin)/ωm with the textbook's ωm = (ωmax + ωmin)/2, from the run's speeds in results.json.
    motion = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]["motion"]
    high, low = motion["omega_max"], motion["omega_min"]
    assert steady == _four_digits_kept((high - low) / ((high + low) / 2.0))


def test_the_runaway_warning_writes_the_torques_as_the_note(tmp_path, capsys):
    """A constant 18 N·m through 14.4:1, 259.2 N·m on the shaft, against the press's mean 245.79 N·m: the warning
    wrote 245.789 beside the note's 245.79."""
    scene = _flywheel_scene(tmp_path, r"^motor = .*$", 'motor = { kind = "constant", torque = 18.0, gear_ratio = 14.4 }'
                            "\nduration = 5.0")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    line = _warning(_printed(capsys), "dynamics: no steady state within the run")
    torque, resisting = re.search(r"the motor's torque on the shaft, ([\d.]+) N·m, exceeds the mean resistance, "
                                  r"([\d.]+) N·m", line).groups()
    note = (out / "note.md").read_text(encoding="utf-8")
    assert f"Md = {torque} N·m, exceeds the mean resistance, {resisting} N·m" in note
    assert (torque, resisting) == (f"{18.0 * 14.4:.5g}", f"{MEAN_RESISTANCE:.5g}")


def test_the_stall_warning_writes_the_time_and_angle_as_the_note(tmp_path, capsys):
    """2 kg·m² behind a 60 N·m clutch against 50 N·m runs at 2.5 rad/s by 0.5 s, 0.625 rad on; a 40 N·m brake then
    stops it at (60 − 90)/2 = −15 rad/s², at 0.5 + 2.5/15 = 0.6667 s, 0.625 + 2.5²/30 rad = 47.746° on: the warning
    wrote φ = 47.7° beside the note's 47.75°."""
    scene = tmp_path / "held.toml"
    scene.write_text('[scene]\ntitle = "clutched"\n[dynamics]\ninertia = 2.0\nrpm = 90\n'
                     'motor = { kind = "constant", torque = 150.0, rotor_inertia = 1.0 }\nclutch = { torque = 60.0 }\n'
                     "duration = 2.0\nresisting_torque = [[0, 50], [360, 50]]\nbrake = { torque = 40.0, at = 0.5 }\n",
                     encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    line = _warning(_printed(capsys), "dynamics: the brake applied")
    time, angle = re.search(r"to rest at t = ([\d.]+) s, φ = ([\d.]+)°", line).groups()
    note = (out / "note.md").read_text(encoding="utf-8")
    assert f"brings it to rest at t = {time} s at φ = {angle}°" in note
    assert time == f"{0.5 + 2.5 / 15.0:.4g}"
    assert angle == f"{math.degrees(0.625 + 2.5 ** 2 / 30.0):.4g}"


def _rotor_note(tmp_path: Path, zeta: str, locale: str, capsys,
                speed: str = "rpm           = 600.0") -> tuple[str, str]:
    """What ``graphplan run`` of the rotor starter, its ζ made ``zeta`` (and its speed ``speed``), printed, and its
    note."""
    scene = tmp_path / f"rotor_{zeta}_{locale}.toml"
    assert main(["new", "rotor", "--out", str(scene)]) == 0
    text = scene.read_text(encoding="utf-8")
    assert "damping_ratio = 0.1 " in text and "rpm           = 600.0" in text
    text = text.replace("damping_ratio = 0.1 ", f"damping_ratio = {zeta} ", 1).replace("rpm           = 600.0", speed)
    scene.write_text(text, encoding="utf-8")
    _printed(capsys)
    out = tmp_path / f"out_{locale}"
    assert main(["run", str(scene), "--locale", locale, "--out", str(out), "--only", "vibration,note"]) == 0
    return _printed(capsys), (out / "note.md").read_text(encoding="utf-8")


@pytest.mark.parametrize(("locale", "asked"), [
    ("en", "Caution: ζ = 1 is read as a ratio, critical damping: the machine would creep back to rest"),
    ("ru", "Внимание: ζ = 1 понимается как относительный коэффициент демпфирования, а это критическое демпфирование"),
    ("zh", "注意：ζ = 1 按阻尼比理解，即临界阻尼"),
])
def test_a_damping_ratio_of_one_is_asked_about_in_the_note_too(tmp_path, capsys, locale, asked):
    """ζ = 1, critical damping, which no mount has: 1 % (ζ = 1/100 = 0.01) meant?  The console asked; the note
    said nothing."""
    printed, note = _rotor_note(tmp_path, "1", locale, capsys)
    line = _warning(printed, "vibration.damping_ratio: ")
    fraction = f"{1 / 100:g}".replace(".", "," if locale == "ru" else ".")
    paragraph = next(para for para in note.split("\n\n") if para.startswith(asked))
    assert f"1 % {({'en': 'is', 'ru': '— это', 'zh': '即'})[locale]} ζ = {fraction}" in paragraph
    if locale == "en":   # the console's words, after its key path
        assert paragraph == f"Caution: {line.removeprefix('warning: vibration.damping_ratio: ')}."


def test_an_over_critical_damping_ratio_is_told_in_the_note_and_a_real_one_is_not(tmp_path, capsys):
    printed, note = _rotor_note(tmp_path, "1.5", "en", capsys)
    line = _warning(printed, "vibration.damping_ratio: ")
    assert f"Caution: {line.removeprefix('warning: vibration.damping_ratio: ')}." in note.split("\n\n")
    assert "percentage" not in line
    printed, note = _rotor_note(tmp_path, "0.7", "en", capsys)
    assert "vibration.damping_ratio" not in printed and "creep back" not in note


def test_the_mounts_sag_warning_writes_k_and_r_as_the_note(tmp_path, capsys):
    """TR = 0.2 at ζ = 1 on the rotor's 100 kg at 600 rpm needs r = 9.9118 and mounts of M·(ω/r)² = 4018.4 N/m, which
    sag 0.244 m: the warning wrote k = 4018 and r = 9.912 beside the note's 4018.4 and 9.9118."""
    printed, note = _rotor_note(tmp_path, "1", "en", capsys)
    line = _warning(printed, "vibration: the isolating mounts")
    stiffness, ratio = re.search(r"k = ([\d.]+) N/m, would sag .* needs r = ([\d.]+) at", line).groups()
    assert f"the isolating mounts worked out above, k = {stiffness} N/m, would sag" in note
    assert f"needs r = {ratio} at ζ = 1" in note
    # TR² = (1 + (2ζr)²)/((1 − r²)² + (2ζr)²) = 0.2² solved for r > √2 at ζ = 1, by bisection of its own.
    def excess(r: float) -> float:
        return (1 + (2 * r) ** 2) / ((1 - r * r) ** 2 + (2 * r) ** 2) - 0.2 ** 2

    isolating = brentq(excess, math.sqrt(2.0) * 1.001, 1e3)
    omega = 600.0 * RPM
    assert float(ratio) == pytest.approx(isolating, abs=5e-5)
    assert float(stiffness) == pytest.approx(100.0 * (omega / isolating) ** 2, abs=0.05)
    assert len(ratio.replace(".", "")) == 5 and len(stiffness.replace(".", "")) == 5


def test_a_speed_typed_in_rpm_is_asked_about_with_the_note_s_numbers(tmp_path, capsys):
    """ω = 1450 rad/s, a motor's 1450 rpm: the warning wrote 1450 rpm as 151.8 rad/s beside the note's 151.84."""
    printed, note = _rotor_note(tmp_path, "0.1", "en", capsys, speed="omega = 1450.0")
    line = _warning(printed, "vibration: vibration.omega = 1450 rad/s")
    as_rpm, meant = re.search(r"is ([\d.]+) rpm: .* 1450 rpm is ([\d.]+) rad/s", line).groups()
    assert f"ω = 1450 rad/s ({as_rpm} rpm)" in note and f"(1450 rpm is ω = {meant} rad/s)" in note
    assert (as_rpm, meant) == (f"{1450.0 * 30.0 / math.pi:.5g}", f"{1450.0 * math.pi / 30.0:.5g}")


def test_a_crank_speed_typed_in_the_other_unit_is_warned_with_the_note_s_numbers(tmp_path, capsys):
    """rpm = 25.13 beside a crank of 240 rpm (25.133 rad/s): the warning wrote the driver as 25.13 rad/s, the note
    25.133, and the flywheel's speed as 2.632 rad/s beside the note's 2.6316."""
    from tests.test_student_probe_dynamics_ru import COMPRESSOR

    scene = tmp_path / "compressor.toml"
    scene.write_text(COMPRESSOR.replace('locale  = "ru"', 'locale  = "en"') + "rpm = 25.13\n", encoding="utf-8")
    _printed(capsys)
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note"]) == 0
    line = _warning(_printed(capsys), "dynamics.rpm = 25.13 rev/min is the crank's speed in rad/s")
    omega, rpm, sized = re.search(r"\(driver: ([\d.]+) rad/s, ([\d.]+) rpm\).* sized at ([\d.]+) rad/s", line).groups()
    assert (omega, rpm, sized) == (f"{240.0 * RPM:.5g}", "240", f"{25.13 * RPM:.5g}")
    note = (out / "note.md").read_text(encoding="utf-8")
    assert f"(ω = {omega} rad/s, n = {rpm} rpm)" in note and f"sized at ωm = {sized} rad/s" in note


def test_the_runaway_refusal_writes_the_torques_as_the_note_of_a_run_given_a_duration(tmp_path, capsys):
    """The same 259.2 N·m against 245.79 N·m with no duration is refused: the refusal wrote 245.789, the note and the
    warning of the run with a duration 245.79."""
    motor = 'motor = { kind = "constant", torque = 18.0, gear_ratio = 14.4 }'
    refused = _flywheel_scene(tmp_path, r"^motor = .*$", motor)
    _printed(capsys)
    assert main(["check", str(refused)]) == 2
    torque, resisting = re.search(r"dynamics\.motor: its torque on the shaft, ([\d.]+) N·m, exceeds the mean "
                                  r"resistance, ([\d.]+) N·m", _printed(capsys)).groups()
    assert (torque, resisting) == (f"{18.0 * 14.4:.5g}", f"{MEAN_RESISTANCE:.5g}")
    out = tmp_path / "out"
    refused.write_text(refused.read_text(encoding="utf-8") + "duration = 5.0\n", encoding="utf-8")
    assert main(["run", str(refused), "--out", str(out), "--only", "dynamics,note"]) == 0
    assert f"Md = {torque} N·m, exceeds the mean resistance, {resisting} N·m" in (out / "note.md").read_text("utf-8")


def test_the_off_design_warning_writes_the_delta_it_was_sized_for_as_the_note(tmp_path, capsys):
    """δ = 0.0512347 typed: the note sized the flywheel for 0.051235, the warning wrote 0.0512347."""
    scene = _flywheel_scene(tmp_path, r"gear_ratio = 14\.4", "gear_ratio = 13.0")
    scene.write_text(re.sub(r"^delta = 0\.05 ", "delta = 0.0512347 ", scene.read_text(encoding="utf-8"),
                            flags=re.MULTILINE), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    line = _warning(_printed(capsys), "dynamics: the motor runs the machine at")
    sized = re.search(r"sized at for δ = ([\d.]+);", line).group(1)
    assert f"The flywheel was sized for δ = {sized};" in (out / "note.md").read_text(encoding="utf-8")
    assert sized == "0.051235"   # 0.0512347 to five significant digits, by hand


def test_the_gear_warning_writes_the_motor_s_and_the_machine_s_speed_as_the_note(tmp_path, capsys):
    """A motor rated 1455.5 rpm through 40 on a press at 97.125 rpm: the gear line wrote 1456 and 97.12 (or 97.13)
    beside the note's 1455.5 and 97.125."""
    scene = _flywheel_scene(tmp_path, r"rated_rpm = 1440, gear_ratio = 14\.4", "rated_rpm = 1455.5, gear_ratio = 40")
    scene.write_text(re.sub(r"^rpm   = 100 ", "rpm   = 97.125 ", scene.read_text(encoding="utf-8"),
                            flags=re.MULTILINE), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note"]) == 0
    line = _warning(_printed(capsys), "dynamics.motor.gear_ratio = 40:")
    rated, machine, fitting = re.search(r"rated speed, ([\d.]+) rpm, .* times the ([\d.]+) rpm the machine runs at; "
                                        r"gear_ratio is ω_motor/ω_shaft, here ([\d.]+)", line).groups()
    note = (out / "note.md").read_text(encoding="utf-8")
    assert f"rad/s ({rated} rpm), and overload capacity" in note and f"rad/s ({machine} rpm)" in note
    assert (rated, machine) == ("1455.5", "97.125")
    # The ratio that fits, rated over the machine's speed, the note does not write: three digits, as before.
    assert fitting == f"{1455.5 / 97.125:.3g}"


def test_the_stall_warning_writes_a_brake_s_and_a_clutch_s_given_numbers_as_the_note(tmp_path, capsys):
    """A brake on at t = 0.51237 s: the note wrote 0.5124, the console the 0.51237 typed.  The clutch's 60.00004 N·m
    and the brake's 40.00004 N·m, 60 and 40 in the note, were 60.00004 and 40.00004."""
    scene = tmp_path / "held.toml"
    scene.write_text('[scene]\ntitle = "clutched"\n[dynamics]\ninertia = 2.0\nrpm = 90\n'
                     'motor = { kind = "constant", torque = 150.0, rotor_inertia = 1.0 }\n'
                     "clutch = { torque = 60.00004 }\nduration = 2.0\nresisting_torque = [[0, 50], [360, 50]]\n"
                     "brake = { torque = 40.00004, at = 0.51237 }\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    line = _warning(_printed(capsys), "dynamics: the brake applied")
    at, time, angle, clutch, brake = re.search(
        r"applied at t = ([\d.]+) s brings the machine to rest at t = ([\d.]+) s, φ = ([\d.]+)°, where the clutch, "
        r"slipping at its ([\d.]+) N·m, cannot turn it against the brake's ([\d.]+) N·m", line).groups()
    note = (out / "note.md").read_text(encoding="utf-8")
    assert (f"the brake applied at t = {at} s brings it to rest at t = {time} s at φ = {angle}°, where the clutch, "
            f"slipping at its {clutch} N·m, cannot turn it against the brake's {brake} N·m") in note
    # (60 − 50)/2 rad/s² up to the brake, (60 − 50 − 40)/2 after it, by hand.
    speed = (60.00004 - 50.0) / 2.0 * 0.51237
    slowing = (60.00004 - 50.0 - 40.00004) / 2.0
    turned = (60.00004 - 50.0) / 4.0 * 0.51237 ** 2 + speed ** 2 / (2.0 * -slowing)
    assert (at, time, angle) == ("0.5124", f"{0.51237 - speed / slowing:.4g}", f"{math.degrees(turned):.4g}")
    assert (clutch, brake) == ("60", "40")


@pytest.mark.parametrize(("omega", "ratio", "said"), [
    (100.003, "1", "ω at the natural frequency (r = 1): the machine runs at resonance"),
    (98.76543, "0.98765", "ω within 1.2 % of the natural frequency (r = 0.98765)"),
])
def test_the_resonance_warning_writes_r_as_the_note(tmp_path, capsys, omega, ratio, said):
    """r = 1.00003 was "within 3e-05 of the natural frequency (r = 1.00003)" on the console beside the note's "runs
    at resonance (r = 1)"; r = 0.9876543 was 0.987654 beside 0.98765, and "within 0.012" beside "within 1.2 %"."""
    scene = tmp_path / "machine.toml"
    scene.write_text('[scene]\ntitle = "Machine"\n[vibration]\nmass = 100.0\nunbalance = 0.01\nstiffness = 1.0e6\n'
                     f"damping_ratio = 0.002\nomega = {omega}\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 0
    line = _warning(_printed(capsys), "vibration: ")
    r = omega / math.sqrt(1.0e6 / 100.0)   # ω/ωn, ωn = √(k/M), by hand
    assert ratio == f"{r:.5g}"
    assert said in line
    note = (out / "note.md").read_text(encoding="utf-8")
    (caution,) = [para for para in note.split("\n\n") if para.startswith("Caution:")]
    assert f"(r = {ratio})" in caution
    if ratio != "1":   # the distance from resonance, in per cent to two digits, in both
        share = f"{abs(r - 1) * 100:.2g} %"
        assert f"within {share} of the natural" in line and f"within {share} of the natural" in caution
    # Magnification r²/√((1 − r²)² + (2ζr)²) as both write it.
    magnification = f"{r * r / math.hypot(1 - r * r, 2 * 0.002 * r):.5g}"
    assert magnification in line and magnification in caution


def test_the_unsettled_warning_writes_a_long_run_s_time_without_an_exponent(tmp_path, capsys):
    """A machine of 10⁸ kg·m² run for 12345.6 s ends still speeding up: the warning wrote "t = 1.235e+04 s" where
    every other number on the console and in the note is written whole, to five digits."""
    scene = _flywheel_scene(tmp_path, r"^rpm   = 100 ", "duration = 12345.6\nrpm = 100 ")
    scene.write_text(scene.read_text(encoding="utf-8").replace("inertia = 0.0 ", "inertia = 1e8 ", 1), encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "dynamics"]) == 0
    line = _warning(_printed(capsys), "dynamics: no steady state within the run")
    assert "t = 12346 s (its duration)" in line
    speed = re.search(r"still speeding up at ω = (\S+) rad/s", line).group(1)
    assert "e" not in speed and float(speed) > 0
