"""A teacher's review of the rotor's balancing and of the vibration from a rotating unbalance, each number worked out
here afresh.

The corrections come from the rotor's two equilibrium equations solved as a linear system (Σ m·r = 0 and
Σ m·r·z = 0 about an origin of our own; Shigley & Uicker, *Theory of Machines and Mechanisms*, ch. 13;
Артоболевский, *Теория механизмов и машин*, уравновешивание вращающихся масс), not from graphplan's shares; the
drawings are read back from their SVG.  The vibration is the complex amplitude of M·x″ + c·x′ + k·x = F·e^{iωt}
(Rao, *Mechanical Vibrations*, §3.7 rotating unbalance, §3.6 base excitation, §9.10 isolation), the isolating ratio
a root found by bisection of TR(r) − TR, the shaft's stiffness from the beam's deflection formulas (Roark).  Nothing
of graphplan's formulas is used for the expected values.
"""

from __future__ import annotations

import itertools
import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest
from scipy.optimize import brentq
from sheet_texts import flat

from graphplan.run import results as run_results
from graphplan.run import run
from graphplan.scales import standard_scale
from graphplan.scene import loads as scene_from_text

G = 9.80665


def _written(tmp_path, text: str, name: str = "out") -> tuple[dict, str, dict[str, str]]:
    """results.json, note.md and the SVG files of a run of the scene ``text``."""
    folder = tmp_path / name
    run(scene_from_text(text), folder)
    svgs = {path.stem: path.read_text(encoding="utf-8") for path in folder.glob("*.svg")}
    return (json.loads((folder / "results.json").read_text(encoding="utf-8")),
            (folder / "note.md").read_text(encoding="utf-8"), svgs)


def _told(tmp_path, text: str, name: str = "out") -> tuple[dict, str]:
    """results.json and note.md of a run of the scene ``text``, for a test that reads no drawing: the results as the
    run writes them (graphplan.run.results, tests/test_run_in_memory.py) and the note of a run of the note alone,
    its text the whole run's without the figures.  The two plots a vibration run draws were most of its time."""
    scene = scene_from_text(text)
    run(scene, tmp_path / name, only=["note"])
    return run_results(scene), (tmp_path / name / "note.md").read_text(encoding="utf-8")


def _product(mass: float, radius: float, angle_deg: float) -> complex:
    return mass * radius * complex(math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg)))


def _two_plane_corrections(masses, left: float, right: float) -> tuple[complex, complex]:
    """cL, cR (kg·m) from Σ m·r + cL + cR = 0 and Σ m·r·(z − z0) + cL·(zL − z0) + cR·(zR − z0) = 0, z0 an origin
    off every plane (the answer must not depend on it)."""
    origin = -0.37
    products = np.array([_product(m, r, a) for m, r, a, _ in masses])
    arms = np.array([z - origin for *_, z in masses])
    system = np.array([[1.0, 1.0], [left - origin, right - origin]], dtype=complex)
    known = -np.array([products.sum(), (products * arms).sum()])
    c_left, c_right = np.linalg.solve(system, known)
    return complex(c_left), complex(c_right)


def _degrees(vector: complex) -> float:
    return math.degrees(math.atan2(vector.imag, vector.real)) % 360.0


def _angle_gap(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


# --- balancing ---------------------------------------------------------------------------------------------------

DISC = """
[scene]
title = "Disc with three masses"
[balancing]
masses = [ { mass = 2.0, radius = 0.1, angle = 30.0 },
           { mass = 3.0, radius = 0.08, angle = 150.0 },
           { mass = 1.5, radius = 0.12, angle = 260.0 } ]
correction_radius = 0.1
"""
DISC_MASSES = [(2.0, 0.1, 30.0, 0.0), (3.0, 0.08, 150.0, 0.0), (1.5, 0.12, 260.0, 0.0)]

# Masses outside the planes (A overhung on the left, C on the right), between them (B), and in each plane (D, E).
LONG = """
[scene]
title = "Long rotor"
[balancing]
masses = [ { mass = 5.0, radius = 0.1, angle = 20.0, plane = -0.1, name = "A" },
           { mass = 4.0, radius = 0.12, angle = 110.0, plane = 0.25, name = "B" },
           { mass = 6.0, radius = 0.05, angle = 215.0, plane = 0.6, name = "C" },
           { mass = 3.0, radius = 0.09, angle = 300.0, plane = 0.0, name = "D" },
           { mass = 2.0, radius = 0.1, angle = 75.0, plane = 0.5, name = "E" } ]
planes = [0.0, 0.5]
correction_radius = [0.15, 0.2]
"""
LONG_MASSES = [(5.0, 0.1, 20.0, -0.1), (4.0, 0.12, 110.0, 0.25), (6.0, 0.05, 215.0, 0.6), (3.0, 0.09, 300.0, 0.0),
               (2.0, 0.1, 75.0, 0.5)]

# Every mass in a correction plane: each plane corrects its own masses alone, as a disc.
IN_PLANES = """
[scene]
title = "Masses in the correction planes"
[balancing]
masses = [ { mass = 1.0, radius = 0.2, angle = 45.0, plane = 0.1 },
           { mass = 2.0, radius = 0.05, angle = 180.0, plane = 0.1 },
           { mass = 0.5, radius = 0.3, angle = 270.0, plane = 0.9 } ]
planes = [0.1, 0.9]
correction_radius = 0.25
"""
IN_PLANES_MASSES = [(1.0, 0.2, 45.0, 0.1), (2.0, 0.05, 180.0, 0.1), (0.5, 0.3, 270.0, 0.9)]


def test_a_discs_one_correction_closes_the_polygon_of_its_masses(tmp_path):
    results, _ = _told(tmp_path, DISC)
    balancing = results["balancing"]
    correction = -sum(_product(m, r, a) for m, r, a, _ in DISC_MASSES)
    (plane,) = balancing["planes"]
    assert balancing["kind"] == "static"
    assert plane["mass_radius"] == pytest.approx(abs(correction), rel=1e-9)
    assert plane["angle_deg"] == pytest.approx(_degrees(correction), abs=1e-7)
    assert plane["mass"] == pytest.approx(abs(correction) / 0.1, rel=1e-9)
    # The unbalance before is the correction turned half a turn.
    assert _angle_gap(balancing["unbalance"]["angle_deg"], _degrees(correction) + 180.0) < 1e-7
    # The corrected disc, summed here from the results' numbers, has no force left.
    added = _product(plane["mass"], plane["radius"], plane["angle_deg"])
    assert abs(added - correction) < 1e-9 * abs(correction)
    assert balancing["residual"] == {"force": 0.0, "moment": 0.0}


@pytest.mark.parametrize(("text", "masses", "radii"), [(LONG, LONG_MASSES, (0.15, 0.2)),
                                                      (IN_PLANES, IN_PLANES_MASSES, (0.25, 0.25))],
                         ids=["outside-and-between", "in-the-planes"])
def test_two_corrections_balance_the_force_and_the_moment_of_a_long_rotor(tmp_path, text, masses, radii):
    results, _ = _told(tmp_path, text)
    balancing = results["balancing"]
    left, right = (plane["position"] for plane in balancing["planes"])
    expected = _two_plane_corrections(masses, left, right)
    assert balancing["kind"] == "dynamic"
    for plane, correction, radius in zip(balancing["planes"], expected, radii, strict=True):
        assert plane["mass_radius"] == pytest.approx(abs(correction), rel=1e-9)
        assert _angle_gap(plane["angle_deg"], _degrees(correction)) < 1e-7
        assert plane["mass"] == pytest.approx(abs(correction) / radius, rel=1e-9)
    # The rotor with the corrections the results give, about an origin of our own: nothing left.
    rotor = [(m, r, a, z) for m, r, a, z in masses]
    rotor += [(plane["mass"], plane["radius"], plane["angle_deg"], plane["position"]) for plane in balancing["planes"]]
    force = sum(_product(m, r, a) for m, r, a, _ in rotor)
    moment = sum(_product(m, r, a) * (z - 1.3) for m, r, a, z in rotor)
    own = sum(m * r for m, r, *_ in masses)
    assert abs(force) < 1e-9 * own and abs(moment) < 1e-9 * own
    assert balancing["residual"] == {"force": 0.0, "moment": 0.0}
    unbalance = sum(_product(m, r, a) for m, r, a, _ in masses)
    assert balancing["unbalance"]["mass_radius"] == pytest.approx(abs(unbalance), rel=1e-9)
    assert balancing["unbalance"]["moment"] == pytest.approx(abs(sum(_product(m, r, a) * z for m, r, a, z in masses)),
                                                             rel=1e-9)


def test_masses_in_the_correction_planes_load_only_their_own_plane(tmp_path):
    """Артоболевский: a mass in a correction plane is balanced in that plane alone; each plane is then a disc."""
    results, note = _told(tmp_path, IN_PLANES)
    left, right = results["balancing"]["planes"]
    own_left = -(_product(1.0, 0.2, 45.0) + _product(2.0, 0.05, 180.0))
    own_right = -_product(0.5, 0.3, 270.0)
    assert left["mass_radius"] == pytest.approx(abs(own_left), rel=1e-9)
    assert right["mass_radius"] == pytest.approx(abs(own_right), rel=1e-9)
    assert right["angle_deg"] == pytest.approx(90.0, abs=1e-9)
    table = note.split("\nTable 2. ")[1].split("\n\n")[1]
    rows = [row.split("|")[1:-1] for row in table.splitlines()[2:]]
    shares = [(float(row[2]), float(row[4])) for row in rows]
    assert shares == [(1.0, 0.0), (1.0, 0.0), (0.0, 1.0)]


def test_an_overhung_mass_pulls_the_far_plane_against_its_sense_in_the_notes_table(tmp_path):
    """A mass outside the planes: its share in the far plane is its m·r times −(distance outside)/(spacing),
    found from the moment about the near plane; one between them shares (zR − z)/(zR − zL) and (z − zL)/(zR − zL)."""
    _, note = _told(tmp_path, LONG)
    table = note.split("\nTable 2. ")[1].split("\n\n")[1]
    rows = {row.split("|")[1].strip(): [float(cell.replace("−", "-")) for cell in row.split("|")[2:-1]]
            for row in table.splitlines()[2:]}
    spacing = 0.5
    # A at z = −0.1, 0.1 outside L: moments about L give its R share −0.1/0.5 of m·r, so L carries 1.2.
    assert rows["mArA"][1] == pytest.approx(1 + 0.1 / spacing, abs=1e-4)
    assert rows["mArA"][3] == pytest.approx(-0.1 / spacing, abs=1e-4)
    assert rows["mArA"][4] == pytest.approx(-0.1 / spacing * 0.5, abs=1e-5)
    # C at z = 0.6, 0.1 outside R.
    assert rows["mCrC"][1] == pytest.approx(-0.1 / spacing, abs=1e-4)
    assert rows["mCrC"][3] == pytest.approx(1 + 0.1 / spacing, abs=1e-4)
    # B in the middle halves.
    assert rows["mBrB"][1] == pytest.approx(0.5) and rows["mBrB"][3] == pytest.approx(0.5)


# --- the polygons read back from the SVG ----------------------------------------------------------------------------

_POINT = re.compile(r"(-?[\d.]+),(-?[\d.]+)")


def _points(d: str) -> list[complex]:
    """A path's points in y-up millimetres (the SVG's y points down)."""
    return [complex(float(x), -float(y)) for x, y in _POINT.findall(d)]


def _drawn_vectors(svg: str, plane: str) -> dict[str, tuple[complex, complex]]:
    """Each arrow of a plane's polygon: its name → (start, tip), read off its line and its arrowhead's point."""
    vectors = {}
    layers = "vectors|reference|leaders|labels|caption"
    for name, body in re.findall(rf'<g id="plane-{plane}-(?!(?:{layers})")([^"]+)">(.*?)</g>', svg, re.DOTALL):
        line, head = re.findall(r'd="([^"]+)"', body)
        vectors[name] = (_points(line)[0], _points(head)[0])
    return vectors


def _scale(svg: str, plane: str) -> float:
    """μ (kg·m/mm) as the plane's caption states it."""
    caption = re.search(rf'<g id="plane-{plane}-caption">(.*?)</g>', svg, re.DOTALL).group(1)
    return float(re.search(r"μ = ([\d.]+) kg·m/mm", caption).group(1))


@pytest.mark.parametrize(("text", "masses"), [(LONG, LONG_MASSES), (IN_PLANES, IN_PLANES_MASSES)],
                         ids=["outside-and-between", "in-the-planes"])
def test_each_polygon_is_drawn_to_its_stated_scale_and_closes(tmp_path, text, masses):
    results, _, svgs = _written(tmp_path, text)
    svg = svgs["rotor_balancing"]
    left, right = (plane["position"] for plane in results["balancing"]["planes"])
    corrections = dict(zip("LR", _two_plane_corrections(masses, left, right), strict=True))
    names = "ABCDE" if text is LONG else "123"
    for plane, z_near, z_far in (("L", left, right), ("R", right, left)):
        mu = _scale(svg, plane)
        drawn = _drawn_vectors(svg, plane)
        # Each mass's share in the plane, from moments about the other plane.
        shares = {f"m{name}r{name}{plane}": _product(m, r, a) * (z_far - z) / (z_far - z_near)
                  for name, (m, r, a, z) in zip(names, masses, strict=True)}
        expected = {name: share for name, share in shares.items() if abs(share) / mu > 0.01}
        expected[f"m{plane}r{plane}"] = corrections[plane]
        assert set(drawn) == set(expected)
        for name, vector in expected.items():
            start, tip = drawn[name]
            assert abs(tip - start) * mu == pytest.approx(abs(vector), rel=2e-3, abs=2e-3 * mu), name
            assert _angle_gap(_degrees(tip - start), _degrees(vector)) < 0.2, name
        # Head to tail and closed: the drawn sides add up to nothing (to the file's thousandths of a millimetre).
        assert abs(sum(tip - start for start, tip in drawn.values())) < 0.02


def test_a_discs_polygon_is_its_masses_products_head_to_tail_closed_by_the_correction(tmp_path):
    _, _, svgs = _written(tmp_path, DISC)
    svg = svgs["rotor_balancing"]
    mu = _scale(svg, "b")
    drawn = _drawn_vectors(svg, "b")
    expected = {f"m{k + 1}r{k + 1}": _product(m, r, a) for k, (m, r, a, _) in enumerate(DISC_MASSES)}
    expected["mbrb"] = -sum(expected.values())
    assert set(drawn) == set(expected)
    for name, vector in expected.items():
        start, tip = drawn[name]
        assert abs(tip - start) * mu == pytest.approx(abs(vector), rel=2e-3), name
        assert _angle_gap(_degrees(tip - start), _degrees(vector)) < 0.2, name
    # Laid off in order from the pole, each from the last one's tip, the correction back to the pole.
    order = [*(f"m{k}r{k}" for k in (1, 2, 3)), "mbrb"]
    for before, after in itertools.pairwise(order):
        assert abs(drawn[before][1] - drawn[after][0]) < 0.01
    assert abs(drawn["mbrb"][1] - drawn["m1r1"][0]) < 0.01


def test_the_sheet_draws_the_polygons_of_their_own_drawing_at_the_scale_its_caption_gives(tmp_path):
    """The sheet's polygons are their own drawing's, each vector turned as there and as long at the μ the sheet's
    caption gives: on an A3 with room a standard step or more finer, drawn larger as the sheets draw the diagrams
    and the dynamics."""
    folder = tmp_path / "out"
    run(scene_from_text(LONG + '[drawing]\nsheet = "A3"\n'), folder)
    own = (folder / "rotor_balancing.svg").read_text(encoding="utf-8")
    sheet = (folder / "sheet_1.svg").read_text(encoding="utf-8").replace('id="balancing-plane-', 'id="plane-')
    for plane in "LR":
        on_its_own, on_the_sheet = _scale(own, plane), _scale(sheet, plane)
        assert on_the_sheet < on_its_own and on_the_sheet == standard_scale(on_the_sheet)
        larger = on_its_own / on_the_sheet
        alone, on_sheet = _drawn_vectors(own, plane), _drawn_vectors(sheet, plane)
        assert set(alone) == set(on_sheet)
        for name, (start, tip) in alone.items():
            assert abs((tip - start) * larger - (on_sheet[name][1] - on_sheet[name][0])) < 0.005 * larger


def test_the_corrections_angle_is_drawn_from_a_dashed_x_direction_counter_clockwise(tmp_path):
    results, _, svgs = _written(tmp_path, LONG)
    svg = svgs["rotor_balancing"]
    for plane, entry in zip("LR", results["balancing"]["planes"], strict=True):
        reference = re.search(rf'<g id="plane-{plane}-reference">(.*?)</g>', svg, re.DOTALL).group(1)
        dashed, arc = re.findall(r'd="([^"]+)"', reference)[:2]
        tail, end = _points(dashed)
        assert end - tail == pytest.approx(complex(abs(end - tail), 0.0), abs=1e-3)  # along +x, the masses' θ = 0
        start, _ = _drawn_vectors(svg, plane)[f"m{plane}r{plane}"]
        assert abs(start - tail) < 1e-3  # at the correction's tail
        turns = [point - tail for point in _points(arc)]
        radius = abs(turns[0])
        assert all(abs(abs(point) - radius) < 0.01 for point in turns)
        swept = np.unwrap([math.atan2(point.imag, point.real) for point in turns])
        assert swept[0] == pytest.approx(0.0, abs=1e-3)
        assert np.all(np.diff(swept) > 0)  # counter-clockwise, y up
        # The arc stops short of its arrowhead, a few degrees before θ.
        assert 0 < entry["angle_deg"] - math.degrees(swept[-1]) < 25.0


# --- vibration --------------------------------------------------------------------------------------------------------


def _machine(mass, unbalance, stiffness, zeta, omega):
    """X (m), the lag φ (deg, 0..180) and the force through the mounts (N), from the complex amplitude."""
    c = 2.0 * zeta * math.sqrt(stiffness * mass)
    x = unbalance * omega ** 2 / complex(stiffness - mass * omega ** 2, c * omega)
    return abs(x), math.degrees(-np.angle(x)) % 360.0, abs(complex(stiffness, c * omega) * x)


def _vibration_scene(**keys) -> str:
    lines = "\n".join(f"{key} = {value!r}" for key, value in keys.items())
    return f'[scene]\ntitle = "Machine on its mounts"\n[vibration]\n{lines}\n'


@pytest.mark.parametrize("zeta", [0.0, 0.05, 0.1, 0.25, 0.5, 1.0])
@pytest.mark.parametrize("rpm", [150.0, 250.0, 420.0, 900.0])
def test_amplitude_lag_magnification_and_force_are_the_complex_amplitudes(tmp_path, zeta, rpm):
    mass, unbalance, stiffness = 200.0, 0.05, 2.0e5
    results, note = _told(tmp_path, _vibration_scene(mass=mass, unbalance=unbalance, stiffness=stiffness,
                                                           damping_ratio=zeta, rpm=rpm))
    vibration = results["vibration"]
    omega = rpm * 2 * math.pi / 60
    amplitude, lag, force = _machine(mass, unbalance, stiffness, zeta, omega)
    assert vibration["natural_frequency"] == pytest.approx(math.sqrt(stiffness / mass), rel=1e-9)
    assert vibration["critical_speed_rpm"] == pytest.approx(math.sqrt(stiffness / mass) * 60 / (2 * math.pi))
    assert vibration["frequency_ratio"] == pytest.approx(omega / math.sqrt(stiffness / mass), rel=1e-9)
    assert vibration["amplitude"] == pytest.approx(amplitude, rel=1e-9)
    assert vibration["magnification"] == pytest.approx(mass * amplitude / unbalance, rel=1e-9)
    assert vibration["phase_deg"] == pytest.approx(lag, abs=1e-7)
    assert 0.0 <= vibration["phase_deg"] <= 180.0
    assert vibration["exciting_force"] == pytest.approx(unbalance * omega ** 2, rel=1e-9)
    assert vibration["transmitted_force"] == pytest.approx(force, rel=1e-9)
    assert vibration["transmissibility"] == pytest.approx(force / (unbalance * omega ** 2), rel=1e-9)
    # The note says the lag is behind the unbalance, and gives it as the results do.
    assert f"lagging the unbalance by φ = {lag:.4g}°" in note


def test_without_damping_the_motion_is_in_phase_below_resonance_and_opposite_above(tmp_path):
    below, _ = _told(tmp_path, _vibration_scene(mass=200.0, unbalance=0.05, stiffness=2.0e5, rpm=150.0), "a")
    above, _ = _told(tmp_path, _vibration_scene(mass=200.0, unbalance=0.05, stiffness=2.0e5, rpm=900.0), "b")
    assert below["vibration"]["phase_deg"] == 0.0
    assert above["vibration"]["phase_deg"] == 180.0
    for results in (below, above):
        r = results["vibration"]["frequency_ratio"]
        assert results["vibration"]["magnification"] == pytest.approx(r * r / abs(1 - r * r), rel=1e-9)
        assert results["vibration"]["transmissibility"] == pytest.approx(1 / abs(1 - r * r), rel=1e-9)


@pytest.mark.parametrize("zeta", [0.05, 0.2, 0.7])
def test_at_resonance_the_magnification_is_one_over_two_zeta_and_the_lag_a_quarter_turn(tmp_path, zeta):
    results, note = _told(tmp_path, _vibration_scene(mass=100.0, unbalanced_mass=2.0, eccentricity=0.01,
                                                           stiffness=1.0e5, damping_ratio=zeta,
                                                           omega=math.sqrt(1000.0)))
    vibration = results["vibration"]
    assert vibration["frequency_ratio"] == pytest.approx(1.0, abs=1e-14)
    assert vibration["magnification"] == pytest.approx(1 / (2 * zeta), rel=1e-9)
    assert vibration["amplitude"] == pytest.approx(0.02 / 100.0 / (2 * zeta), rel=1e-9)
    assert vibration["phase_deg"] == pytest.approx(90.0, abs=1e-9)
    assert vibration["transmissibility"] == pytest.approx(math.sqrt(1 + 4 * zeta ** 2) / (2 * zeta), rel=1e-9)
    assert "lagging the unbalance by φ = 90°" in note


@pytest.mark.parametrize("zeta", [0.0, 0.1, 0.5, 2.0])
def test_the_transmissibility_is_one_at_root_two_whatever_the_damping(tmp_path, zeta):
    results, _ = _told(tmp_path, _vibration_scene(mass=50.0, unbalance=0.01, stiffness=5.0e4,
                                                        damping_ratio=zeta, omega=math.sqrt(2.0) * math.sqrt(1000.0)))
    assert results["vibration"]["transmissibility"] == pytest.approx(1.0, rel=1e-9)


def _cli(tmp_path, text: str) -> subprocess.CompletedProcess:
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    return subprocess.run([sys.executable, "-m", "graphplan", "run", str(scene), "--out", str(tmp_path / "out")],
                          capture_output=True, text=True, cwd=tmp_path, timeout=120, check=False)


def test_undamped_resonance_is_refused_at_the_speeds_key_with_no_folder_left(tmp_path):
    done = _cli(tmp_path, _vibration_scene(mass=100.0, unbalance=0.02, stiffness=1.0e5, omega=31.6227766016838))
    assert done.returncode == 2
    assert "vibration.omega" in done.stderr and "no damping" in done.stderr and "Traceback" not in done.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("wanted", [1.0, 1.5])
def test_a_wanted_transmissibility_of_one_or_more_is_refused_at_its_key(tmp_path, wanted):
    done = _cli(tmp_path, _vibration_scene(mass=100.0, unbalance=0.02, stiffness=1.0e5, damping_ratio=0.1,
                                           rpm=600.0, transmissibility=wanted))
    assert done.returncode == 2
    assert "vibration.transmissibility" in done.stderr and "below 1" in done.stderr and "Traceback" not in done.stderr
    assert not (tmp_path / "out").exists()


def _force_transmissibility(r: float, zeta: float) -> float:
    return abs(complex(1.0, 2 * zeta * r) / complex(1 - r * r, 2 * zeta * r))


@pytest.mark.parametrize(("wanted", "zeta"), [(0.2, 0.0), (0.2, 0.1), (0.1, 0.2), (0.05, 0.5), (0.5, 0.05)])
def test_the_isolating_mounts_pass_the_wanted_share_of_the_force(tmp_path, wanted, zeta):
    mass, omega = 100.0, 60.0 * math.pi
    results, note = _told(tmp_path, _vibration_scene(mass=mass, unbalance=0.02, stiffness=1.0e5,
                                                           damping_ratio=zeta, omega=omega, transmissibility=wanted))
    isolation = results["vibration"]["isolation"]
    ratio = brentq(lambda r: _force_transmissibility(r, zeta) - wanted, math.sqrt(2.0) + 1e-9, 1e4, xtol=1e-14)
    if zeta == 0:
        assert ratio == pytest.approx(math.sqrt(1 + 1 / wanted), rel=1e-10)  # Rao: r² = 1 + 1/TR undamped
    assert isolation["frequency_ratio"] == pytest.approx(ratio, rel=1e-9)
    assert isolation["stiffness"] == pytest.approx(mass * (omega / ratio) ** 2, rel=1e-9)
    assert isolation["mount_stiffness"] == pytest.approx(isolation["stiffness"], rel=1e-9)
    # The note's design point is the same.
    assert f"For a transmissibility of {wanted:g}" in note


def test_a_base_shaking_an_instrument_moves_it_as_the_complex_amplitude_says(tmp_path):
    mass, stiffness, c, omega, base = 50.0, 5.0e4, 300.0, 60.0, 0.002
    results, note = _told(tmp_path, _vibration_scene(mass=mass, unbalance=0.0, stiffness=stiffness, damping=c,
                                                           omega=omega, base_amplitude=base))
    vibration = results["vibration"]
    impedance = complex(stiffness - mass * omega ** 2, c * omega)
    motion = base * complex(stiffness, c * omega) / impedance
    relative = base * mass * omega ** 2 / impedance
    moved = vibration["base_excitation"]
    assert vibration["damping_ratio"] == pytest.approx(c / (2 * math.sqrt(stiffness * mass)), rel=1e-9)
    assert moved["amplitude"] == pytest.approx(abs(motion), rel=1e-9)
    assert moved["phase_deg"] == pytest.approx(math.degrees(-np.angle(motion)), abs=1e-7)
    assert moved["relative_amplitude"] == pytest.approx(abs(relative), rel=1e-9)
    assert moved["transmitted_force"] == pytest.approx(abs(complex(stiffness, c * omega) * relative), rel=1e-9)
    assert vibration["phase_deg"] is None and vibration["amplitude"] == 0.0
    assert "lagging the base by 152.3°" in note


def test_an_unbalance_on_a_shaken_base_adds_the_two_motions(tmp_path):
    mass, unbalance, stiffness, zeta, omega, base = 50.0, 0.01, 5.0e4, 0.15, 20.0, 0.002
    results, _ = _told(tmp_path, _vibration_scene(mass=mass, unbalance=unbalance, stiffness=stiffness,
                                                        damping_ratio=zeta, omega=omega, base_amplitude=base))
    c = 2 * zeta * math.sqrt(stiffness * mass)
    impedance = complex(stiffness - mass * omega ** 2, c * omega)
    # M·x″ + c·(x′ − y′) + k·(x − y) = m·e·ω²·sin ωt, y = Y·sin ωt: x = (m·e·ω² + (k + icω)·Y) / Z(ω).
    motion = (unbalance * omega ** 2 + complex(stiffness, c * omega) * base) / impedance
    combined = results["vibration"]["combined"]
    assert combined["amplitude"] == pytest.approx(abs(motion), rel=1e-9)
    assert combined["phase_deg"] == pytest.approx(math.degrees(-np.angle(motion)), abs=1e-7)
    assert combined["relative_amplitude"] == pytest.approx(abs(motion - base), rel=1e-9)
    assert combined["transmitted_force"] == pytest.approx(abs(complex(stiffness, c * omega) * (motion - base)),
                                                          rel=1e-9)


@pytest.mark.parametrize(("support", "position"), [("simply_supported", None), ("simply_supported", 0.3),
                                                   ("cantilever", None), ("cantilever", 0.25)])
def test_a_discs_critical_speed_on_its_shaft_is_that_of_its_static_deflection(tmp_path, support, position):
    modulus, diameter, length, mass = 2.1e11, 0.03, 0.8, 20.0
    shaft = {"modulus": modulus, "diameter": diameter, "length": length, "support": support}
    if position is not None:
        shaft["position"] = position
    table = ", ".join(f"{key} = {value!r}".replace("'", '"') for key, value in shaft.items())
    text = _vibration_scene(mass=mass, unbalance=0.0004, damping_ratio=0.02, rpm=3000.0).replace(
        "[vibration]", f"[vibration]\nshaft = {{ {table} }}")
    results, _ = _told(tmp_path, text)
    second = math.pi * diameter ** 4 / 64
    weight = mass * G
    if support == "simply_supported":
        a = length / 2 if position is None else position
        b = length - a
        # Roark: a simply supported beam under W at a, its deflection there W·b·x·(L² − b² − x²)/(6·E·I·L) at x = a.
        sag = weight * b * a * (length ** 2 - b ** 2 - a ** 2) / (6 * modulus * second * length)
        if position is None:
            assert sag == pytest.approx(weight * length ** 3 / (48 * modulus * second), rel=1e-9)
    else:
        a = length if position is None else position
        sag = weight * a ** 3 / (3 * modulus * second)
    critical = math.sqrt(G / sag)  # ωc = √(g/δst)
    vibration = results["vibration"]
    assert vibration["stiffness"] == pytest.approx(weight / sag, rel=1e-9)
    assert vibration["critical_speed"] == pytest.approx(critical, rel=1e-9)
    assert vibration["critical_speed_rpm"] == pytest.approx(critical * 60 / (2 * math.pi), rel=1e-9)


# --- the plots read back ------------------------------------------------------------------------------------------


def _axis(svg: str, axis: str) -> tuple[np.ndarray, np.ndarray]:
    """The ticks of an axis: their positions in the SVG and the values they are lettered with."""
    # A minor tick has no label: the body may not run on into the next tick's.
    ticks = re.findall(rf'<g id="{axis}tick_\d+">((?:(?!tick_).)*?)<!-- (.*?) -->', svg, re.DOTALL)
    places, values = [], []
    for body, label in ticks:
        use = re.search(r'<use [^>]*x="([-\d.]+)" y="([-\d.]+)"', body)
        power = re.fullmatch(r"\$\\mathdefault\{10\^\{(−?-?\d+)\}\}\$", label)
        # The last minor tick runs on to the axis's own label: only a number is a tick's.
        if use is None or not (power or re.fullmatch(r"[−-]?[\d.]+", label)):
            continue
        places.append(float(use.group(1 if axis == "x" else 2)))
        values.append(10.0 ** int(power.group(1).replace("−", "-")) if power else float(label.replace("−", "-")))
    return np.array(places), np.array(values)


def test_the_magnification_plot_puts_the_working_point_and_the_machines_curve_where_they_are(tmp_path):
    zeta = 0.1
    results, _, svgs = _written(tmp_path, _vibration_scene(mass=100.0, unbalance=0.02, stiffness=1.0e5,
                                                           damping_ratio=zeta, rpm=600.0))
    svg = svgs["vibration_magnification"]
    xs, rs = _axis(svg, "x")
    ys, ms = _axis(svg, "y")
    to_r = np.polyfit(xs, rs, 1)
    to_m = np.polyfit(ys, ms, 1)
    marker = re.search(r'<g id="line2d_\d+">\s*<defs>.*?<use [^>]*x="([\d.]+)" y="([\d.]+)" style="fill: #a83a1f',
                       svg, re.DOTALL)
    r = np.polyval(to_r, float(marker.group(1)))
    m = np.polyval(to_m, float(marker.group(2)))
    ratio = 20 * math.pi / math.sqrt(1000.0)
    assert r == pytest.approx(ratio, abs=0.01)
    assert m == pytest.approx(ratio ** 2 / abs(complex(1 - ratio ** 2, 2 * zeta * ratio)), abs=0.02)
    assert results["vibration"]["magnification"] == pytest.approx(m, abs=0.02)
    curve = re.search(r'<path d="([^"]+)" clip-path="[^"]+" style="fill: none; stroke: #a83a1f', svg).group(1)
    points = np.array([[float(x), float(y)] for x, y in re.findall(r"([\d.]+) ([\d.]+)", curve)])
    r_drawn, m_drawn = np.polyval(to_r, points[:, 0]), np.polyval(to_m, points[:, 1])
    expected = r_drawn ** 2 / np.abs((1 - r_drawn ** 2) + 2j * zeta * r_drawn)
    assert np.max(np.abs(m_drawn - expected)) < 0.05
    assert np.max(m_drawn) == pytest.approx(1 / (2 * zeta * math.sqrt(1 - zeta ** 2)), abs=0.05)


def test_the_transmissibility_plot_names_the_isolating_design_point_as_the_results_give_it(tmp_path):
    results, _, svgs = _written(tmp_path, _vibration_scene(mass=100.0, unbalance=0.02, stiffness=1.0e5,
                                                           damping_ratio=0.2, omega=math.sqrt(1000.0),
                                                           transmissibility=0.1))
    ratio = brentq(lambda r: _force_transmissibility(r, 0.2) - 0.1, 1.5, 100.0, xtol=1e-14)
    assert f"isolating mounts: TR = 0.1 at r = {ratio:.3g}" in svgs["vibration_transmissibility"]
    assert "isolation: r &gt; √2" in svgs["vibration_transmissibility"]
    assert results["vibration"]["isolation"]["frequency_ratio"] == pytest.approx(ratio, rel=1e-9)


# --- what the note says -------------------------------------------------------------------------------------------


@pytest.mark.parametrize(("locale", "sense"), [("en", "counter-clockwise"), ("ru", "против часовой стрелки"),
                                               ("zh", "逆时针")])
def test_the_note_says_from_where_and_which_way_the_corrections_angles_are_counted(tmp_path, locale, sense):
    """A correction's θ = 199.2° is no use to the fitter without its reference and sense: the same line on the rotor
    and the same sense as the masses' θ (the polygons draw them counter-clockwise from a dashed x-direction)."""
    results, note = _told(tmp_path, LONG.replace('title = "Long rotor"', f'title = "Long rotor"\nlocale = "{locale}"'))
    section = note.split("\n## ")[1]
    assert sense in section
    before_corrections = section.split("mLrL = ")[0]
    assert sense in before_corrections
    for plane in results["balancing"]["planes"]:
        assert f"θ = {plane['angle_deg']:.1f}°".replace(".", "," if locale == "ru" else ".") in section


COUPLE = """
[scene]
title = "A couple"
[balancing]
masses = [ { mass = 2.0, radius = 0.1, angle = 30.0, plane = 0.2 },
           { mass = 2.0, radius = 0.1, angle = 210.0, plane = 0.6 } ]
planes = [0.0, 0.8]
correction_radius = 0.1
"""


def test_a_couple_needs_equal_and_opposite_corrections_written_alike_on_the_polygons(tmp_path):
    """Two equal masses half a turn apart, 0.4 m apart: the couple 0.2·0.4 = 0.08 kg·m² is taken by corrections
    0.08/0.8 = 0.1 kg·m in each plane, opposite each mass's near side; each 1 kg at 0.1 m, whose quotient
    0.1/0.1 came out 0.9999999999999999 in one plane and was written with five digits there ("1.0000 kg")."""
    results, _, svgs = _written(tmp_path, COUPLE)
    left, right = results["balancing"]["planes"]
    assert left["mass_radius"] == pytest.approx(0.08 / 0.8) and right["mass_radius"] == pytest.approx(0.08 / 0.8)
    assert left["angle_deg"] == pytest.approx(210.0) and right["angle_deg"] == pytest.approx(30.0)
    svg = flat(svgs["rotor_balancing"])
    for plane in "LR":
        caption = re.search(rf'<g id="plane-{plane}-caption">(.*?)</g>', svg, re.DOTALL).group(1)
        assert f"m{plane} = 1.000 kg at r{plane} = 0.1 m" in caption


@pytest.mark.parametrize(("value", "written"), [(0.9999999999999999, "1.000"), (9.99996, "10.00"),
                                                (0.099996, "0.1000"), (99.99999, "100.0"), (1.23456, "1.235"),
                                                (-0.0099999999, "−0.01000")])
def test_a_value_rounding_up_to_a_power_of_ten_keeps_its_significant_digits(value, written):
    from graphplan.render.numerals import significant

    assert significant(value) == written


def _hidden_under_correction(svg: str, plane: str) -> dict[str, float]:
    """Each share's share of its length that runs under the correction's stroke (within the half widths of the two
    strokes, 0.4 + 0.25 mm, of its line)."""
    from shapely.geometry import LineString

    drawn = _drawn_vectors(svg, plane)
    tail, head = drawn.pop(f"m{plane}r{plane}")
    band = LineString([(tail.real, tail.imag), (head.real, head.imag)]).buffer(0.65)
    hidden = {}
    for name, (start, tip) in drawn.items():
        line = LineString([(start.real, start.imag), (tip.real, tip.imag)])
        hidden[name] = line.intersection(band).length / line.length
    return hidden


def test_a_share_leaving_the_pole_a_degree_off_the_correction_is_not_drawn_under_it(tmp_path):
    """Plane L of the long rotor: (mArA)L, 0.6 kg·m at 20°, leaves the pole 0.84° off the correction's line
    (199.16°): it ran under the thick red correction for 44 of its 60 mm, and the polygon seemed to have a side
    fewer.  It was drawn beside only where the share lay within 0.8 mm of the correction at both its ends."""
    _, _, svgs = _written(tmp_path, LONG)
    for plane in "LR":
        hidden = _hidden_under_correction(svgs["rotor_balancing"], plane)
        assert max(hidden.values()) < 0.25, (plane, hidden)


@pytest.mark.parametrize(("locale", "words"), [("en", "own mass is neglected"), ("ru", "массой вала пренебрегаем"),
                                               ("zh", "轴的质量与圆盘相比忽略不计")])
def test_the_note_says_the_shafts_own_mass_is_left_out_of_its_critical_speed(tmp_path, locale, words):
    """ωc = √(k/M) with M the disc's mass alone holds for a shaft light beside its disc (Rao, whirling of shafts;
    a heavy shaft lowers it, Dunkerley): the note must say the shaft's mass is neglected, not leave it unsaid."""
    text = _vibration_scene(mass=20.0, unbalance=0.0004, damping_ratio=0.02, rpm=3000.0).replace(
        "[vibration]", "[vibration]\nshaft = { modulus = 2.1e11, diameter = 0.03, length = 0.8 }").replace(
        '[vibration]', f'locale = "{locale}"\n[vibration]', 1)
    _, note = _told(tmp_path, text)
    assert words in note


def test_the_transmissibility_plot_puts_the_working_and_design_points_where_they_are(tmp_path):
    zeta, wanted = 0.1, 0.2
    _, _, svgs = _written(tmp_path, _vibration_scene(mass=100.0, unbalance=0.02, stiffness=1.0e5,
                                                     damping_ratio=zeta, rpm=600.0, transmissibility=wanted))
    svg = svgs["vibration_transmissibility"]
    xs, rs = _axis(svg, "x")
    ys, trs = _axis(svg, "y")
    to_r, to_log_tr = np.polyfit(xs, rs, 1), np.polyfit(ys, np.log10(trs), 1)
    marks = re.findall(r'<use [^>]*x="([\d.]+)" y="([\d.]+)" style="fill: #(a83a1f|1f7a3a)', svg)
    # The first of each colour is on the plot; the second is its legend's key.
    working = next((float(x), float(y)) for x, y, colour in marks if colour == "a83a1f")
    design = next((float(x), float(y)) for x, y, colour in marks if colour == "1f7a3a")
    ratio = 20 * math.pi / math.sqrt(1000.0)
    assert np.polyval(to_r, working[0]) == pytest.approx(ratio, abs=0.01)
    assert 10 ** np.polyval(to_log_tr, working[1]) == pytest.approx(_force_transmissibility(ratio, zeta), rel=0.01)
    isolating = brentq(lambda r: _force_transmissibility(r, zeta) - wanted, 1.5, 100.0, xtol=1e-14)
    assert np.polyval(to_r, design[0]) == pytest.approx(isolating, abs=0.01)
    assert 10 ** np.polyval(to_log_tr, design[1]) == pytest.approx(wanted, rel=0.01)


FOLDED_PAST = """
[scene]
title = "A share turning back past the one before"
[balancing]
masses = [ { mass = 1.0, radius = 0.1, angle = 45.0, plane = 0.5 },
           { mass = 1.0, radius = 0.1, angle = 224.0, plane = -0.5 },
           { mass = 1.0, radius = 0.05, angle = 90.0, plane = 0.0 } ]
planes = [0.0, 1.0]
correction_radius = 0.1
"""


@pytest.mark.parametrize("text", [FOLDED_PAST, LONG], ids=["folded-past", "long"])
def test_no_share_is_drawn_over_another_for_most_of_its_length(tmp_path, text):
    """Plane L: (m1r1)L, 0.05 kg·m at 45°, then (m2r2)L, 0.15 kg·m at 224°, turning back a degree off straight
    over it and running on past the pole: (m1r1)L lay wholly under it.  Only a share ending on the one before it
    was drawn beside the chain."""
    from shapely.geometry import LineString

    _, _, svgs = _written(tmp_path, text)
    svg = svgs["rotor_balancing"]
    for plane in "LR":
        drawn = _drawn_vectors(svg, plane)
        drawn.pop(f"m{plane}r{plane}")
        lines = {name: LineString([(a.real, a.imag), (b.real, b.imag)]) for name, (a, b) in drawn.items()}
        for name, line in lines.items():
            for other, over in lines.items():
                if other != name:
                    assert line.intersection(over.buffer(0.5)).length < 0.5 * line.length, (plane, name, other)


@pytest.mark.parametrize(("locale", "title"), [("en", "Force transmitted to the frame through the bearings"),
                                               ("ru", "Сила, передаваемая через подшипники на станину"),
                                               ("zh", "经轴承传给机架的力")])
def test_a_shafts_transmissibility_plot_is_titled_for_the_frame_its_bearings_pass_the_force_to(tmp_path, locale,
                                                                                             title):
    """The note says a disc on its shaft passes TR·m·e·ω² through the bearings to the frame; its plot said the force
    went to the base, as a machine's on its mounts does."""
    text = _vibration_scene(mass=20.0, unbalance=0.0004, damping_ratio=0.02, rpm=3000.0).replace(
        "[vibration]", "[vibration]\nshaft = { modulus = 2.1e11, diameter = 0.03, length = 0.8 }").replace(
        "[vibration]", f'locale = "{locale}"\n[vibration]', 1)
    _, note, svgs = _written(tmp_path, text)
    assert f"<!-- {title} -->" in svgs["vibration_transmissibility"]
    assert title in note
