"""The explanatory note on the machine as a whole: its flywheel, its rotor's balancing, its vibration.

A scene of a flywheel, a rotor or a machine on its mounts alone (no linkage) gets a note of its own, and a
linkage's note gains these sections when its scene has the tables. Every number the note works out is
checked against the textbook formulas evaluated here (the rotor's two corrections by solving the force and
moment balance as one linear system, not by the polygons), and the flywheel against its published answer.
"""

import cmath
import json
import math
import re
import tomllib
from importlib import resources

import numpy as np
import pytest
from scipy.optimize import brentq
from test_deliverables import ROTOR as FAN_SCENE
from test_dynamics_without_linkage import PRESS as PRESS_SCENE

from graphplan.cli import main
from graphplan.output import WRITTEN

# The fan rotor of test_deliverables: two masses balanced in two planes, on mounts, with isolation asked for.
ROTOR = FAN_SCENE[FAN_SCENE.index("[balancing]"):FAN_SCENE.index("[vibration]")]
MOUNTS = FAN_SCENE[FAN_SCENE.index("[vibration]"):] + "transmissibility = 0.2\n"
# The punching press of the worked example (test_dynamics_without_linkage cites it): driving power constant,
# 367.7 W for a third of the cycle and 3677 W for two thirds, 100 rpm, δ = 0.05: ΔWmax = 441.24 J, JF = 80.473 kg·m²,
# 0.388 kg·m² at 1440 rpm.  Its tables without its [scene].
PRESS = PRESS_SCENE[PRESS_SCENE.index("[dynamics]"):]


def note_of(tmp_path, body, locale="en", extra=()):
    scene = tmp_path / "scene.toml"
    scene.write_text(f'[scene]\ntitle = "A machine"\nlocale = "{locale}"\n\n{body}', encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), *extra]) == 0
    return out, (out / "note.md").read_text(encoding="utf-8")


def value(text):
    return float(text.replace("−", "-").replace(",", "."))


def agrees(printed, exact, digits=5):
    """A number printed to ``digits`` significant digits is ``exact`` within half its last place."""
    return abs(value(printed) - exact) <= 0.5 * 10 ** (math.floor(math.log10(abs(exact))) - digits + 1) * (1 + 1e-9)


def to_a_tenth(printed, exact):
    """An angle printed to a tenth of a degree is ``exact`` within half a tenth."""
    return re.fullmatch(r"\d+\.\d", printed) is not None and abs(value(printed) - exact) <= 0.05 * (1 + 1e-9)


def test_a_rotor_alone_gets_a_note_whose_corrections_cancel_the_force_and_the_moment(tmp_path):
    out, note = note_of(tmp_path, ROTOR)
    assert {"note.md", "note.html", "note.tex"} <= {path.name for path in out.iterdir()}
    assert note.startswith("# Explanatory note: A machine\n") and "## 1. Balancing of the rotor" in note
    masses = [(18.0, 0.05, 0.0, 0.0), (14.0, 0.06, -60.0, 0.08)]
    products = [m * r * cmath.exp(1j * math.radians(angle)) for m, r, angle, _ in masses]
    # mL·rL + mR·rR = −Σ m·r and zL·mL·rL + zR·mR·rR = −Σ m·r·z, solved as one system.
    system = np.array([[1.0, 1.0], [0.04, 0.22]], dtype=complex)
    right = -np.array([sum(products), sum(p * z for p, (_, _, _, z) in zip(products, masses, strict=True))])
    left_plane, right_plane = np.linalg.solve(system, right)
    for name, correction in (("L", left_plane), ("R", right_plane)):
        found = re.search(rf"Plane {name}: .*?closing vector m{name}r{name} = (\d+(?:\.\d+)?) kg·m at θ = (\d+(?:\.\d+)?)°, "
                          rf"so that at r = 0.05 m the correction mass is m{name} = [\d.]+/0.05 = (\d+(?:\.\d+)?) kg", note)
        assert found, name
        assert agrees(found.group(1), abs(correction))
        assert to_a_tenth(found.group(2), math.degrees(cmath.phase(correction)) % 360)
        assert agrees(found.group(3), abs(correction) / 0.05)
    assert "Σ m·r = 0 kg·m and Σ m·r·z = 0 kg·m²" in note
    # The shares carried to plane L: (zR − zi)/(zR − zL).
    assert re.search(r"\| m2r2 \| 0.84 \| 0.7778 \| 0.65333 \|", note)


def test_a_machine_on_its_mounts_gets_its_vibration_worked_out(tmp_path):
    _, note = note_of(tmp_path, MOUNTS)
    mass, k, zeta, unbalance, omega = 100.0, 1e5, 0.1, 0.02, 600 * 2 * math.pi / 60
    natural = math.sqrt(k / mass)
    r = omega / natural
    root = math.sqrt((1 - r * r) ** 2 + (2 * zeta * r) ** 2)
    magnification = r * r / root
    lag = math.degrees(math.atan2(2 * zeta * r, 1 - r * r))
    tr = math.sqrt(1 + (2 * zeta * r) ** 2) / root
    force = unbalance * omega ** 2

    def transmissibility(ratio):
        return math.sqrt(1 + (2 * zeta * ratio) ** 2) / math.sqrt((1 - ratio ** 2) ** 2 + (2 * zeta * ratio) ** 2)

    isolating = brentq(lambda ratio: transmissibility(ratio) - 0.2, math.sqrt(2), 100, xtol=1e-14)
    found = re.search(r"ωn = √\(k/M\) = √\(100000/100\) = (\d+(?:\.\d+)?) rad/s, the critical speed (\d+(?:\.\d+)?) rpm; "
                      r"frequency ratio r = ω/ωn = [\d.]+/[\d.]+ = (\d+(?:\.\d+)?)", note)
    assert found and agrees(found.group(1), natural) and agrees(found.group(2), natural * 60 / (2 * math.pi))
    assert agrees(found.group(3), r)
    found = re.search(r"= (\d+(?:\.\d+)?); the steady amplitude X = .* = (\d+(?:\.\d+)?) m \((\d+(?:\.\d+)?) mm\), lagging the unbalance "
                      r"by φ = (\d+(?:\.\d+)?)°", note)
    assert found and agrees(found.group(1), magnification)
    assert agrees(found.group(2), unbalance / mass * magnification)
    assert agrees(found.group(3), unbalance / mass * magnification * 1000)
    assert agrees(found.group(4), lag, 4) and lag > 90  # above resonance the mass moves against the unbalance
    found = re.search(r"m·e·ω² = 0.02·[\d.]+² = (\d+(?:\.\d+)?) N; .* = (\d+(?:\.\d+)?), so the mounts pass (\d+(?:\.\d+)?) N", note)
    assert found and agrees(found.group(1), force) and agrees(found.group(2), tr) and agrees(found.group(3), force * tr)
    found = re.search(r"r = (\d+(?:\.\d+)?): mounts of stiffness k = M·\(ω/r\)² = .* = (\d+(?:\.\d+)?) N/m", note)
    assert found and agrees(found.group(1), isolating) and agrees(found.group(2), mass * (omega / isolating) ** 2)


def test_a_flywheel_from_load_diagrams_alone_gets_the_published_answer_in_its_note(tmp_path):
    _, note = note_of(tmp_path, PRESS)
    assert "## 1. Dynamics of the machine" in note and "given as diagrams" in note
    assert "driving link" not in note  # no linkage is reduced to a link
    assert "ΔWmax = 441.24 J" in note
    assert "= 80.473 kg·m²" in note
    assert "JF′ = JF·(n/n′)² = 0.38808 kg·m²" in note


def test_the_sections_follow_one_another_numbered_and_the_note_may_be_asked_for_alone(tmp_path):
    out, note = note_of(tmp_path, PRESS + ROTOR + MOUNTS, extra=["--only", "note", "--format", "svg,docx"])
    headings = re.findall(r"^## (\d)\. (.+)$", note, flags=re.MULTILINE)
    # The conclusions last, as every note ends (the flywheel the dynamics sized).
    assert headings == [("1", "Dynamics of the machine"), ("2", "Balancing of the rotor"),
                        ("3", "Vibration from the rotating unbalance"), ("4", "Conclusions")]
    assert sorted(path.name for path in out.iterdir() if path.name != WRITTEN) == ["note.docx", "note.html", "note.md", "note.tex",
                                                           "results.json"]


def test_a_linkages_note_gains_the_rotor_and_the_mounts_after_its_own_sections(tmp_path):
    source = resources.files("graphplan").joinpath("templates", "crank-rocker.toml").read_text(encoding="utf-8")
    scene = tmp_path / "scene.toml"
    scene.write_text(source + "\n" + ROTOR + "\n" + MOUNTS, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note,balancing,vibration"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    numbers = [int(number) for number in re.findall(r"^## (\d+)\. ", note, flags=re.MULTILINE)]
    assert numbers == list(range(1, len(numbers) + 1)) and len(numbers) >= 4
    assert re.findall(r"^## \d+\. (.+)$", note, flags=re.MULTILINE)[-3:] == ["Balancing of the rotor",
                                                                       "Vibration from the rotating unbalance",
                                                                       "Conclusions"]


@pytest.mark.parametrize("locale", ["ru", "zh"])
def test_the_machine_note_is_in_the_scenes_language_with_every_value_filled_in(tmp_path, locale):
    _, note = note_of(tmp_path, PRESS + ROTOR + MOUNTS, locale)
    words = tomllib.loads(resources.files("graphplan").joinpath("locales", f"{locale}.toml").read_text("utf-8"))
    assert words["note_balancing"] in note and words["note_vibration"] in note
    assert "{" not in note and "}" not in note
    assert "Balancing" not in note and "Vibration" not in note and "known by" not in note
    if locale == "ru":
        assert "0,26545 мм" in note  # the amplitude, with the Russian decimal comma


def test_a_disc_is_balanced_statically_by_one_mass_that_closes_the_polygon(tmp_path):
    disc = """[balancing]
masses = [ { mass = 2.0, radius = 0.1, angle = 30.0, name = "A" }, { mass = 3.0, radius = 0.08, angle = 150.0, name = "B" },
           { mass = 1.5, radius = 0.12, angle = 260.0, name = "C" } ]
correction_radius = 0.1
"""
    _, note = note_of(tmp_path, disc)
    correction = -sum(m * r * cmath.exp(1j * math.radians(angle)) for m, r, angle in
                      ((2.0, 0.1, 30.0), (3.0, 0.08, 150.0), (1.5, 0.12, 260.0)))
    assert "Σ mi·ri + mb·rb = 0: mArA + mBrB + mCrC + mbrb = 0." in note
    found = re.search(r"The closing vector mbrb = (\d+(?:\.\d+)?) kg·m at θ = (\d+(?:\.\d+)?)°, so that at r = 0.1 m "
                      r"the correction mass is mb = [\d.]+/0.1 = (\d+(?:\.\d+)?) kg\.", note)
    assert found and agrees(found.group(1), abs(correction)) and agrees(found.group(3), abs(correction) / 0.1)
    assert to_a_tenth(found.group(2), math.degrees(cmath.phase(correction)) % 360)
    assert "Check: with the correction Σ m·r = 0 kg·m: the rotor is balanced statically." in note


def test_planes_with_long_names_name_their_correction_masses_after_them(tmp_path):
    rotor = """[balancing]
masses = [ { mass = 5.0, radius = 0.2, angle = 0.0, plane = -0.1 }, { mass = 4.0, radius = 0.15, angle = 90.0, plane = 0.35 } ]
planes = [0.0, 0.6]
correction_radius = [0.2, 0.1]
plane_names = ["A-A", "B-B"]
"""
    _, note = note_of(tmp_path, rotor)
    products = [5.0 * 0.2, 4.0 * 0.15 * 1j]
    system = np.array([[1.0, 1.0], [0.0, 0.6]], dtype=complex)
    corrections = np.linalg.solve(system, -np.array([sum(products), -0.1 * products[0] + 0.35 * products[1]]))
    for name, correction, radius in zip(("A-A", "B-B"), corrections, (0.2, 0.1), strict=True):
        found = re.search(rf"Plane {name}: .*?closing vector \(m·r\){name} = [\d.]+ kg·m at θ = [\d.]+°, so that at "
                          rf"r = {radius} m the correction mass is m{name} = [\d.]+/{radius} = ([\d.]+) kg", note)
        assert found, name
        assert agrees(found.group(1), abs(correction) / radius)
    assert "mb =" not in note


@pytest.mark.parametrize(("masses", "planes", "angles"), [
    # 5·0.2 at 0° and 4·0.15 at 90°: the correction points at 180° + atan(0.6/1.0) = 210.96°.
    ("{ mass = 5.0, radius = 0.2, angle = 0.0, plane = -0.1 }, { mass = 4.0, radius = 0.15, angle = 90.0, plane = 0.2 }",
     "[0.05]", [180.0 + math.degrees(math.atan2(0.6, 1.0))]),
    # A pure couple, 0.2 kg·m at 45° and at 225° 0.2 m apart, balanced by planes 0.4 m apart: 0.1 kg·m each way.
    ("{ mass = 2.0, radius = 0.1, angle = 45.0, plane = 0.0 }, { mass = 2.0, radius = 0.1, angle = -135.0, plane = 0.2 }",
     "[0.5, 0.9]", [225.0, 45.0]),
    # One mass at 179.97°: the correction lies 0.03° short of a whole turn, written 0.0°, not 360.0°.
    ("{ mass = 1.0, radius = 0.1, angle = 179.97 }", "[0.0]", [0.0]),
], ids=["one-plane", "couple", "near-a-turn"])
def test_the_correction_angles_are_written_to_a_tenth_of_a_degree(tmp_path, masses, planes, angles):
    _, note = note_of(tmp_path, f"[balancing]\nmasses = [ {masses} ]\nplanes = {planes}\ncorrection_radius = 0.1\n")
    written = re.findall(r"kg·m at θ = ([\d.]+)°", note)
    assert written == [f"{round(angle, 1) % 360.0:.1f}" for angle in angles]


def test_an_instrument_on_a_shaken_floor_moves_by_the_displacement_transmissibility(tmp_path):
    floor = """[vibration]
mass = 20.0
unbalance = 0.0
stiffness = 2.0e4
damping_ratio = 0.05
rpm = 1200
base_amplitude = 0.0005
"""
    out, note = note_of(tmp_path, floor)
    zeta, r, base = 0.05, (1200 * 2 * math.pi / 60) / math.sqrt(2.0e4 / 20.0), 0.0005
    # The base's motion y = Y·sin ωt: M·x″ + c·(x′ − y′) + k·(x − y) = 0 solved as a complex amplitude.
    response = (1 + 2j * zeta * r) / (1 - r * r + 2j * zeta * r)
    machine, relative = base * abs(response), base * abs(response - 1)
    lag = -math.degrees(cmath.phase(response))
    found = re.search(r"moves the instrument by X = .* = (\d+(?:\.\d+)?) m, lagging the base by (\d+(?:\.\d+)?)° .* "
                      r"is Z = .* = (\d+(?:\.\d+)?) m\.", note)
    assert found and agrees(found.group(1), machine) and agrees(found.group(2), lag, 4)
    assert agrees(found.group(3), relative)
    # ω to six digits: 125.66/31.623 would not give the r = 3.9738 written after it.
    assert f"stands on a base moving at ω = {1200 * 2 * math.pi / 60:.6g} rad/s (1200 rpm)" in note
    assert "exciting force" not in note  # no unbalance to work out
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))["vibration"]["base_excitation"]
    assert document["base_amplitude"] == base
    assert document["amplitude"] == pytest.approx(machine, rel=1e-10)
    assert document["relative_amplitude"] == pytest.approx(relative, rel=1e-10)
    assert document["phase_deg"] == pytest.approx(lag, rel=1e-10)


@pytest.mark.parametrize(("locale", "instrument", "moves", "machine"), [
    ("en", "The instrument, of mass M = 20 kg", "moves the instrument by X = Y·√(1 + (2ζr)²)/√((1 − r²)² + (2ζr)²) = 0.0005·{tr} = {x} m", "the machine"),
    ("ru", "Прибор массой M = 20 кг", "раскачивает прибор с амплитудой X = Y·√(1 + (2ζr)²)/√((1 − r²)² + (2ζr)²) = 0,0005·{tr} = {x} м", "машин"),
    ("zh", "质量 M = 20 kg 的仪器", "使仪器振幅 X = Y·√(1 + (2ζr)²)/√((1 − r²)² + (2ζr)²) = 0.0005·{tr} = {x} m", "机器"),
], ids=["en", "ru", "zh"])
def test_an_instrument_on_a_shaken_floor_is_not_called_a_machine(tmp_path, locale, instrument, moves, machine):
    """The note named the instrument, then said the base "moves the machine by X" (раскачивает машину, 使机器振幅):
    a machine the scene, with no unbalance, has not."""
    floor = ("[vibration]\nmass = 20.0\nunbalance = 0.0\nstiffness = 2.0e4\ndamping_ratio = 0.05\nrpm = 1200\n"
             "base_amplitude = 0.0005\n")
    _, note = note_of(tmp_path, floor, locale)
    # r = (1200·2π/60)/√(2·10⁴/20) = 125.664/31.623 = 3.97384; X/Y = √(1 + (2ζr)²)/√((1 − r²)² + (2ζr)²)
    # = √(1 + 0.397384²)/√(14.7914² + 0.397384²) = 1.076078/14.79674 = 0.072723, X = 0.0005·0.072723 = 0.000036362 m.
    r = (1200 * 2 * math.pi / 60) / math.sqrt(2.0e4 / 20.0)
    tr = math.hypot(1.0, 0.1 * r) / math.hypot(1.0 - r * r, 0.1 * r)
    assert tr == pytest.approx(0.072723, rel=1e-5)

    def five_digits(number: float) -> str:  # as the note writes a value: five significant digits, no exponent
        return np.format_float_positional(float(f"{number:.5g}"), trim="-").replace(".", "," if locale == "ru" else ".")

    written = moves.format(tr=five_digits(tr), x=five_digits(0.0005 * tr))
    assert instrument in note and written in note, note
    assert machine not in note.split("\n## ")[1].split("![")[0], note


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_an_unbalance_on_a_moving_base_is_one_system_whose_two_motions_add(tmp_path, locale):
    """The note wrote the unbalance's equation with no base in it, said the mounts pass 53 N to the base as if it
    stood still, and gave the base's response apart, never the two together (0.000702 m)."""
    body = ("[vibration]\nmass = 40.0\nunbalance = 0.01\nstiffness = 160000.0\ndamping_ratio = 0.1\n"
            "omega = 158.11388300841895\nbase_amplitude = 0.002\n")
    out, note = note_of(tmp_path, body, locale)
    mass, me, k, zeta, omega, lift = 40.0, 0.01, 160000.0, 0.1, 158.11388300841895, 0.002
    r = omega / math.sqrt(k / mass)
    # M·x″ + c·(x′ − y′) + k·(x − y) = m·e·ω²·sin ωt, y = Y·sin ωt, as one complex amplitude.
    denominator = 1 - r * r + 2j * zeta * r
    motion = (me * omega ** 2 / k + lift * (1 + 2j * zeta * r)) / denominator
    stroke = motion - lift
    force = abs((k + 2j * zeta * math.sqrt(k * mass) * omega) * stroke)
    assert "M·x″ + c·(x′ − y′) + k·(x − y) = m·e·ω²·sin ωt" in note
    number = r"(\d+(?:[.,]\d+)?)"
    found = re.search(r"X = √\(X₁² \+ X₂² \+ 2·X₁·X₂·cos\(φ₁ − φ₂\)\) = " + number + " (?:m|м)", note)
    assert found and agrees(found.group(1), abs(motion))
    found = re.search(r"= \(0[.,]01/40 \+ 0[.,]002\)·" + number + " = " + number + " (?:m|м)", note)
    assert found and agrees(found.group(2), abs(stroke))
    assert abs(value(found.group(1)) * (me / mass + lift) - value(found.group(2))) <= 5e-5 * abs(stroke)
    found = re.search(r"= " + number + r"·" + number + r"²·\(0[.,]01 \+ 40·0[.,]002\) = " + number + " (?:N|Н)", note)
    assert found and agrees(found.group(3), force, 3)
    if locale == "en":
        alone = me * omega ** 2 * abs((1 + 2j * zeta * r) / denominator)
        assert f"on a base at rest the mounts would pass {alone:.3g} N to it" in note
        assert "so the mounts pass" not in note
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))["vibration"]["combined"]
    assert document["amplitude"] == pytest.approx(abs(motion), rel=1e-10)
    assert document["phase_deg"] == pytest.approx(-math.degrees(cmath.phase(motion)), rel=1e-10)
    assert document["transmitted_force"] == pytest.approx(force, rel=1e-10)


def test_a_base_amplitude_must_be_positive_and_is_named_where_it_is_not(tmp_path, capsys):
    scene = tmp_path / "scene.toml"
    scene.write_text(MOUNTS.join(['[scene]\ntitle = "A machine"\n', "base_amplitude = -0.001\n"]), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    assert "vibration.base_amplitude: must be > 0 (got -0.001)" in capsys.readouterr().err
    assert not out.exists()


def written_as(value, written):
    """Whether ``value`` rounds to ``written`` at the significant digits ``written`` shows (its whole number's
    closing zeros may be rounding's)."""
    digits = len(written.replace(".", "").strip("0"))
    return any(float(f"{value:.{count}g}") == float(written) for count in range(max(digits, 1), 18))


SHAFTS = {  # a disc on a shaft: simply supported off the middle, and overhung on a cantilever
    "simply_supported": ("shaft = { modulus = 2.0e11, diameter = 0.05, length = 1.2, position = 0.3 }", 0.3, 0.9),
    "cantilever": (('shaft = { modulus = 2.0e11, diameter = 0.025, length = 0.4, position = 0.3, '
                    'support = "cantilever" }'), 0.3, None),
}


@pytest.mark.parametrize("support", sorted(SHAFTS))
def test_a_shafts_stiffness_is_in_the_results_and_its_formula_in_the_note(tmp_path, support):
    shaft, a, b = SHAFTS[support]
    body = f"[vibration]\nmass = 20.0\nunbalance = 0.0002\n{shaft}\ndamping_ratio = 0.02\nrpm = 1000.0\n"
    out, note = note_of(tmp_path, body)
    diameter = 0.05 if b is not None else 0.025
    second = math.pi * diameter ** 4 / 64
    # Castigliano's unit load for a disc at a from one bearing, b from the other: δ = F·a²·b²/(3EIL); overhung, F·a³/(3EI).
    k = 3 * 2.0e11 * second * 1.2 / (a * a * b * b) if b is not None else 3 * 2.0e11 * second / a ** 3
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))["vibration"]
    assert document["stiffness"] == pytest.approx(k, rel=1e-11)
    assert document["natural_frequency"] == pytest.approx(math.sqrt(k / 20.0), rel=1e-11)
    # E = 2·10¹¹ Pa is written as a power of ten: as 200000000000 its noughts have to be counted; and I beside it
    # likewise, 3.0680·10⁻⁷ m⁴, not 0.00000030680.
    formula = (r"k = 3·E·I·L/\(a²·b²\) = 3·2·10¹¹·([\d.]+)·10([⁻¹²³⁴⁵⁶⁷⁸⁹⁰]+)·1\.2/\(0\.3²·0\.9²\) = (\d+) N/m"
               if b is not None else r"k = 3·E·I/a³ = 3·2·10¹¹·([\d.]+)·10([⁻¹²³⁴⁵⁶⁷⁸⁹⁰]+)/0\.3³ = (\d+) N/m")
    found = re.search(formula, note)
    assert found, note
    mantissa, power, shown_k = found.groups()
    exponent = int(power.translate(str.maketrans("⁻¹²³⁴⁵⁶⁷⁸⁹⁰", "-1234567890")))
    assert exponent == math.floor(math.log10(second)) and 1 <= float(mantissa) < 10
    shown_second = float(mantissa) * 10.0 ** exponent
    assert written_as(second / 10.0 ** exponent, mantissa) and written_as(k, shown_k)
    # The operands as written give the result as written.
    again = 3 * 2.0e11 * shown_second * (1.2 / (a * a * b * b) if b is not None else 1 / a ** 3)
    assert written_as(again, shown_k)
    assert f"I = π·d⁴/64 = π·{diameter:g}⁴/64 = {mantissa}·10{power} m⁴" in note
    (tmp_path / "mounts").mkdir()
    mounts = json.loads((note_of(tmp_path / "mounts", MOUNTS)[0] / "results.json").read_text(encoding="utf-8"))
    assert "stiffness" not in mounts["vibration"]  # the mounts' stiffness is the scene's own


def test_the_notes_operands_as_written_give_the_results_as_written(tmp_path):
    # "mLrL = 1.58 kg·m … mL = 1.58/0.05 = 31.599 kg": 1.58/0.05 is 31.6.
    template = resources.files("graphplan").joinpath("templates/rotor.toml").read_text(encoding="utf-8")
    _, note = note_of(tmp_path, template[template.index("[balancing]"):])
    divisions = re.findall(r"m[LR] = ([\d.]+)/([\d.]+) = ([\d.]+) kg", note)
    assert len(divisions) == 2
    for numerator, denominator, quotient in divisions:
        assert written_as(float(numerator) / float(denominator), quotient)
    for operand, angle in re.findall(r"closing vector m[LR]r[LR] = ([\d.]+) kg·m at θ = ([\d.]+)°", note):
        assert operand in {numerator for numerator, _, _ in divisions}
    ratio = re.search(r"√\(([\d.]+)/([\d.]+)\) = ([\d.]+) rad/s.*r = ω/ωn = ([\d.]+)/([\d.]+) = ([\d.]+)\.", note)
    assert ratio
    k, mass, natural, omega, natural_again, r = ratio.groups()
    assert natural == natural_again and written_as(math.sqrt(float(k) / float(mass)), natural)
    assert written_as(float(omega) / float(natural), r)
    amplitude = re.search(r"= \(([\d.]+)/([\d.]+)\)·([\d.]+) = ([\d.]+) m", note)
    me, mass, magnification, x = amplitude.groups()
    assert written_as(float(me) / float(mass) * float(magnification), x)
    isolation = re.search(r"= ([\d.]+)·\(([\d.]+)/([\d.]+)\)² = ([\d.]+) N/m", note)
    mass, omega_again, ratio_iso, stiffness = isolation.groups()
    assert omega_again == omega and written_as(float(mass) * (float(omega) / float(ratio_iso)) ** 2, stiffness)


def test_the_russian_note_names_the_damping_and_the_magnification_as_the_textbooks_do(tmp_path):
    """ζ was «коэффициент демпфирования», the textbooks' name for c (Бидерман, Тимошенко); M·X/(m·e) was
    «коэффициент усиления» in the note and «безразмерная амплитуда» on its plot."""
    body = ("[vibration]\nmass = 250.0\nunbalance = 0.1\nstiffness = 400000.0\ndamping = 3000.0\nrpm = 1200.0\n"
            "transmissibility = 0.1\n")
    out, note = note_of(tmp_path, body, "ru")
    assert "с относительным коэффициентом демпфирования ζ" in note
    assert "Коэффициент демпфирования c = 3000 Н·с/м даёт относительный коэффициент демпфирования ζ" in note
    assert "при том же относительном коэффициенте демпфирования ζ" in note
    named = re.findall(r"(\w+) коэффициент\w* демпфирования ζ", note)
    assert len(named) == 3 and all(word.startswith("относительн") for word in named)
    assert "Коэффициент динамичности при инерционном возбуждении M·X/(m·e) = " in note
    assert "усиления" not in note
    plot = (out / "vibration_magnification.svg").read_text(encoding="utf-8")
    assert "<!-- коэффициент динамичности M·X/(m·e) -->" in plot and "безразмерная" not in plot


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_machine_known_by_its_diagrams_is_said_to_be_given_by_the_points_of_its_scene(tmp_path, locale):
    """The press's power diagram has 4 points; the note said «в виде диаграмм (362 точки)», the samples the
    model is worked on.  Counted here from the scene's own arrays, both sides given."""
    from docx import Document

    from graphplan.locale import Count, strings

    driving = [[0, 50.0], [180, 150.0], [360, 50.0]]
    resisting = [[0, 100.0], [90, 100.0], [90, 20.0], [270, 180.0], [270, 100.0], [360, 100.0]]  # as much work
    both = f"[dynamics]\nrpm = 100\ndelta = 0.05\ndriving_torque = {driving}\nresisting_torque = {resisting}\n"
    for k, body in enumerate((PRESS, both)):
        given = sum(len(points) for key, points in tomllib.loads(body)["dynamics"].items()
                    if key.endswith(("_power", "_torque")))
        assert given == (4, 9)[k]
        (tmp_path / str(k)).mkdir()
        out, note = note_of(tmp_path / str(k), body, locale, extra=["--format", "docx"])
        template = strings(locale)["note_dyn_model_diagrams"]
        sentence = template.split("{inertia}")[0].format(count=Count(given))
        said = sentence[:max(sentence.find(")"), sentence.find("）")) + 1]   # up to the count: Je is marked up
        assert said in note and "362" not in note and "361" not in note
        assert said in (out / "note.html").read_text(encoding="utf-8")
        assert said in (out / "note.tex").read_text(encoding="utf-8").replace("\\notecjk{", "").replace("}", "")
        assert any(said in paragraph.text for paragraph in Document(str(out / "note.docx")).paragraphs)


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_rotor_whose_masses_all_turn_on_the_axis_is_cautioned_and_draws_no_scale_of_nothing(tmp_path, locale):
    """A rotor given with every radius 0 (left unfilled) was balanced without a word, and its drawing showed a lone
    pole dot at "μ = 1 kg·m/mm": a scale of nothing.  Σ m·r = 0 by hand, so nothing needs correcting either way."""
    axis = ("[balancing]\nmasses = [ { mass = 1.0, radius = 0.0, angle = 0.0, plane = 0.1 } ]\n"
            "planes = [0.0, 0.3]\ncorrection_radius = 0.1\n")
    from graphplan.locale import strings

    out, note = note_of(tmp_path, axis, locale)
    assert strings(locale)["note_bal_caution_on_axis"] in note
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))["balancing"]
    assert [found["code"] for found in document["warnings"]] == ["on-axis"]
    assert all(plane["mass_radius"] == 0 for plane in document["planes"])
    drawing = (out / "rotor_balancing.svg").read_text(encoding="utf-8")
    assert "μ =" not in drawing and "<circle" not in drawing
    # Off the axis the rotor is drawn at its scale, and nothing is cautioned.
    (tmp_path / "off").mkdir()
    out, note = note_of(tmp_path / "off", axis.replace("radius = 0.0", "radius = 0.05"), locale)
    assert strings(locale)["note_bal_caution_on_axis"] not in note
    assert "μ =" in (out / "rotor_balancing.svg").read_text(encoding="utf-8")
