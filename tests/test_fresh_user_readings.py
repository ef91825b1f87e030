"""A student's hand-drawn plans and force polygons checked by `graphplan run`, read as the student and the teacher do.

The readings are a few millimetres off the exact segments, which the test works out itself from ``graphplan.solve``
(|vB|/μV, |ε3|·lAB/μa, with μV = ω·lOA/pa and μa = ω²·lOA/πa from the scene's poles) and, for the slider-crank's
force polygons, from its own equilibrium of the group and the crank (d'Alembert's loads, the weights, the cutting
force against the ram's motion).  Each measured δ of results.json, errors.csv and errors.md is checked against
δ = (exact − reading·μ)/exact·100 %, the table's own definition (its head and the note's say so).
"""

import csv
import json
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import graphplan

ROOT = Path(__file__).resolve().parents[1]
GRAVITY = 9.81


def _without_readings(fixture):
    """The fixture's text with its own `[measured]` table taken out (the student gives theirs)."""
    text = (ROOT / "fixtures" / fixture).read_text(encoding="utf-8")
    return re.sub(r"\[measured\.\d+\]\n(?:(?:velocity|acceleration|forces|balancing)\s*=.*\n)*", "", text)


def _run(tmp_path, text, only="errors"):
    tmp_path.mkdir(parents=True, exist_ok=True)
    scene = tmp_path / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "graphplan", "run", str(scene), "--out", str(out), "--only", only],
                          cwd=ROOT, capture_output=True, text=True, timeout=300, check=False)
    return done, out


def _toml(readings):
    return "{ " + ", ".join(f"{name} = {value:.1f}" for name, value in readings.items()) + " }"


def _at(motion, index):
    def vector(point, what):
        return complex(*getattr(motion.point(point), what)[index])
    return vector


def _table(markdown_text, number):
    """Position ``number``'s error table in errors.md: its header, and its rows by quantity as {header: cell}."""
    lines = markdown_text.splitlines()
    start = next(i for i, line in enumerate(lines) if re.fullmatch(rf"## \D+ {number}", line))
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    table = [line for line in lines[start + 1:end] if line.startswith("|")]
    header = [cell.strip() for cell in table[0].strip("|").split("|")]
    rows = {}
    for line in table[2:]:
        cells = [cell.strip() for cell in line.strip("|").split("|")]
        rows[cells[0]] = dict(zip(header, cells))
    return header, rows


def _symbol(quantity):
    # errors.md letters the relative acceleration as the note does, aBB1ʳ (results.json keeps aBB1^r).
    return quantity.replace("omega", "ω").replace("epsilon", "ε").replace("^r", "ʳ")


def _check_measured(out, number, expected, locale="en"):
    """Every measured row of the run against the test's (exact, plan) for it; no other measured row."""
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    rows = {row["quantity"]: row for row in results["errors"]
            if row["position"] == number and row["source"] == "measured"}
    assert set(rows) == set(expected)
    with open(out / "errors.csv", encoding="utf-8") as handle:
        table_csv = {row["quantity"]: row for row in csv.DictReader(handle)
                     if row["position"] == str(number) and row["source"] == "measured"}
    header, table_md = _table((out / "errors.md").read_text(encoding="utf-8"), number)
    delta_measured = next(name for name in header if name.startswith("δ") and ("measured" in name or "замер" in name))
    for quantity, (exact, plan) in expected.items():
        delta = (exact - plan) / exact * 100.0
        row = rows[quantity]
        assert row["analytic"] == pytest.approx(exact, rel=1e-6), quantity
        assert row["plan"] == pytest.approx(plan, rel=1e-6), quantity
        assert row["percent"] == pytest.approx(delta, rel=1e-5, abs=1e-6), quantity
        assert float(table_csv[quantity]["percent"]) == pytest.approx(delta, rel=1e-5, abs=1e-6), quantity
        written = table_md[_symbol(quantity)][delta_measured].replace("−", "-").replace(",", ".")
        assert float(written) == pytest.approx(round(delta, 3), abs=1.5e-3), quantity
    return results


# --- the crank-rocker of the ratchet feed, position 5: velocity and acceleration plans -------------------------

def _ratchet_case():
    scene = graphplan.load(ROOT / "fixtures" / "ratchet_crank_rocker.toml")
    motion = graphplan.solve(scene)
    at, index = _at(motion, 5), 5
    omega, crank, l_ab, l_bc = 17.0, 0.175, 0.55, 0.325
    mu_v, mu_a = omega * crank / 150.0, omega ** 2 * crank / 100.0
    omega3, omega4 = float(motion.link(3).omega[index]), float(motion.link(4).omega[index])
    epsilon3, epsilon4 = float(motion.link(3).epsilon[index]), float(motion.link(4).epsilon[index])
    exact_mm = {
        "velocity": {"pb": abs(at("B", "v")) / mu_v, "ab": abs(at("B", "v") - at("A", "v")) / mu_v,
                     "pe": abs(at("E", "v")) / mu_v},
        "acceleration": {"pb": abs(at("B", "a")) / mu_a, "n3b": abs(epsilon3) * l_ab / mu_a,
                         "n4b": abs(epsilon4) * l_bc / mu_a, "pe": abs(at("E", "a")) / mu_a},
    }
    off = {"velocity": {"pb": 1.5, "ab": -2.0, "pe": 1.0},
           "acceleration": {"pb": 2.0, "n3b": -1.5, "n4b": 1.0, "pe": 1.5}}
    read = {kind: {name: round(exact_mm[kind][name] + off[kind][name], 1) for name in off[kind]} for kind in off}
    rv, ra = read["velocity"], read["acceleration"]
    expected = {
        "VB": (abs(at("B", "v")), rv["pb"] * mu_v), "VBC": (abs(at("B", "v")), rv["pb"] * mu_v),
        "omega4": (omega4, math.copysign(rv["pb"] * mu_v / l_bc, omega4)),
        "VBA": (abs(at("B", "v") - at("A", "v")), rv["ab"] * mu_v),
        "omega3": (omega3, math.copysign(rv["ab"] * mu_v / l_ab, omega3)),
        "VE": (abs(at("E", "v")), rv["pe"] * mu_v),
        "aB": (abs(at("B", "a")), ra["pb"] * mu_a), "aBC": (abs(at("B", "a")), ra["pb"] * mu_a),
        "epsilon3": (epsilon3, math.copysign(ra["n3b"] * mu_a / l_ab, epsilon3)),
        "epsilon4": (epsilon4, math.copysign(ra["n4b"] * mu_a / l_bc, epsilon4)),
        "aE": (abs(at("E", "a")), ra["pe"] * mu_a),
    }
    text = _without_readings("ratchet_crank_rocker.toml").replace('locale  = "ru"', 'locale  = "en"')
    text += f"\n[measured.5]\nvelocity = {_toml(rv)}\nacceleration = {_toml(ra)}\n"
    return text, expected


def test_the_crank_rockers_plans_read_by_hand_have_each_error_as_the_student_works_it_out(tmp_path):
    text, expected = _ratchet_case()
    done, out = _run(tmp_path, text)
    assert done.returncode == 0, done.stderr
    _check_measured(out, 5, expected)
    head = (out / "errors.md").read_text(encoding="utf-8")
    assert "δ = (analytic − plan) / analytic · 100 %" in head


# --- the offset slider-crank, position 3: plans, force polygons and the balancing moment ----------------------

def _slider_crank_case():
    """The readings, and the exact values: kinematics from graphplan.solve, forces from the test's own statics."""
    text = _without_readings("offset_slider_crank.toml")
    # The cutting force acting at every position, against the saw frame's motion: no window to work out.
    text = re.sub(r"during\s*=\s*\{[^}]*\}", 'during = "always"', text)
    text = text.replace("drafting_precision = 0.5", "drafting_precision = 0.5\nforce_scale        = 5.0")
    scene = graphplan.load_text(text)
    motion = graphplan.solve(scene)
    index, number = 2, 3
    at = _at(motion, index)
    omega2, crank, l_ab = 6.3, 0.08, 0.26
    mu_v, mu_a, mu_f = omega2 * crank / 80.0, omega2 ** 2 * crank / 80.0, 5.0
    omega3, epsilon3 = float(motion.link(3).omega[index]), float(motion.link(3).epsilon[index])
    o, a, b, s2, s3 = (at(name, "r") for name in ("O", "A", "B", "S2", "S3"))

    def cross(r, f):
        return (r.conjugate() * f).imag

    down = -1j * GRAVITY
    # The saw frame 4 (centre B, every force through B): R34 + R14 (normal to the guide) + G4 − m4·aB + F = 0.
    cutting = -450.0 * np.sign(at("B", "v").real)
    r43_x = cutting - 9.0 * at("B", "a").real  # the frame's x balance: R34x = −R43x
    load3 = 2.0 * down - 2.0 * at("S3", "a")
    couple3 = -0.016 * epsilon3
    # The rod 3 about A: (B − A) × R43 + (S3 − A) × load3 + couple3 = 0, R43 = (r43_x, y).
    r43_y = -(cross(b - a, r43_x) + cross(s3 - a, load3) + couple3) / (b - a).real
    r43 = r43_x + 1j * r43_y
    r23 = -(r43 + load3)
    load2 = 2.5 * down - 2.5 * at("S2", "a")
    r12 = -(-r23 + load2)
    balancing = -(cross(a - o, -r23) + cross(s2 - o, load2))
    exact_mm = {"pb": abs(at("B", "v")) / mu_v, "ab": abs(at("B", "v") - at("A", "v")) / mu_v,
                "ps3": abs(at("S3", "v")) / mu_v}
    exact_amm = {"pb": abs(at("B", "a")) / mu_a, "n3b": abs(epsilon3) * l_ab / mu_a, "ps3": abs(at("S3", "a")) / mu_a}
    rv = {name: round(value + shift, 1) for (name, value), shift in zip(exact_mm.items(), (-1.0, 2.0, 1.5))}
    ra = {name: round(value + shift, 1) for (name, value), shift in zip(exact_amm.items(), (1.0, -2.5, 2.0))}
    # R43 as group II's polygon closes with it (link 4 on 3), read as R34; R32 on the crank's polygon, as R23.
    rf = {"R43": round(abs(r43) / mu_f + 1.5, 1), "R32": round(abs(r23) / mu_f - 1.0, 1),
          "R12": round(abs(r12) / mu_f + 2.0, 1)}
    hand_mb = round(abs(balancing) * 1.04, 2)
    expected = {
        "VB": (abs(at("B", "v")), rv["pb"] * mu_v), "VBB1": (abs(at("B", "v")), rv["pb"] * mu_v),
        "VBA": (abs(at("B", "v") - at("A", "v")), rv["ab"] * mu_v),
        "omega3": (omega3, math.copysign(rv["ab"] * mu_v / l_ab, omega3)),
        "VS3": (abs(at("S3", "v")), rv["ps3"] * mu_v),
        "aB": (abs(at("B", "a")), ra["pb"] * mu_a), "aBB1^r": (abs(at("B", "a")), ra["pb"] * mu_a),
        "epsilon3": (epsilon3, math.copysign(ra["n3b"] * mu_a / l_ab, epsilon3)),
        "aS3": (abs(at("S3", "a")), ra["ps3"] * mu_a),
        "R34": (abs(r43), rf["R43"] * mu_f), "R23": (abs(r23), rf["R32"] * mu_f), "R12": (abs(r12), rf["R12"] * mu_f),
        "Mb": (balancing, math.copysign(hand_mb, balancing)),
    }
    text += (f"\n[measured.{number}]\nvelocity = {_toml(rv)}\nacceleration = {_toml(ra)}\nforces = {_toml(rf)}\n"
             f"balancing = {hand_mb}\n")
    return text, number, expected


def test_the_slider_cranks_plans_polygons_and_balancing_moment_read_by_hand_each_have_their_own_error(tmp_path):
    text, number, expected = _slider_crank_case()
    done, out = _run(tmp_path, text)
    assert done.returncode == 0, done.stderr
    _check_measured(out, number, expected)


# --- the shaper's six-bar, position 3: the sliding pair's relative vectors and the second group --------------

def _shaper_case(locale="en"):
    scene = graphplan.load(ROOT / "fixtures" / "shaper_six_bar.toml")
    motion = graphplan.solve(scene)
    index, number = 2, 3
    at = _at(motion, index)
    omega2, crank = 6.0, 0.10
    mu_v, mu_a = omega2 * crank / 100.0, omega2 ** 2 * crank / 100.0
    omega4, epsilon4 = float(motion.link(4).omega[index]), float(motion.link(4).epsilon[index])
    omega5 = float(motion.link(5).omega[index])
    c, a = at("C", "r"), at("A", "r")
    arm = a - c
    # The lever's point A4 under the block: its velocity and acceleration as a point of link 4 about C.
    v_a4 = 1j * omega4 * arm
    a_a4 = (1j * epsilon4 - omega4 ** 2) * arm
    v_slide = at("A", "v") - v_a4
    a_slide = at("A", "a") - a_a4 - 2j * omega4 * v_slide  # the Coriolis part taken off: the relative one
    d_v, e_v = at("D", "v"), at("E", "v")
    exact_v = {"aa4": abs(v_slide) / mu_v, "pd": abs(d_v) / mu_v, "de": abs(e_v - d_v) / mu_v}
    exact_a = {"ka4": abs(a_slide) / mu_a, "n4a4": abs(epsilon4) * abs(arm) / mu_a, "pe": abs(at("E", "a")) / mu_a}
    rv = {name: round(value + shift, 1) for (name, value), shift in zip(exact_v.items(), (1.0, -2.0, 1.0))}
    ra = {name: round(value + shift, 1) for (name, value), shift in zip(exact_a.items(), (-2.0, 1.5, 2.5))}
    expected = {
        "VA4A3": (abs(v_slide), rv["aa4"] * mu_v),
        "VD": (abs(d_v), rv["pd"] * mu_v),
        "omega4": (omega4, math.copysign(rv["pd"] * mu_v / 0.65, omega4)),
        "VED": (abs(e_v - d_v), rv["de"] * mu_v),
        "omega5": (omega5, math.copysign(rv["de"] * mu_v / 0.20, omega5)),
        "aA4A3^r": (abs(a_slide), ra["ka4"] * mu_a),
        "epsilon4": (epsilon4, math.copysign(ra["n4a4"] * mu_a / abs(arm), epsilon4)),
        "aE": (abs(at("E", "a")), ra["pe"] * mu_a), "aEE1^r": (abs(at("E", "a")), ra["pe"] * mu_a),
    }
    text = _without_readings("shaper_six_bar.toml").replace('locale  = "en"', f'locale  = "{locale}"')
    text += f"\n[measured.{number}]\nvelocity = {_toml(rv)}\nacceleration = {_toml(ra)}\n"
    return text, number, expected


def test_the_shapers_sliding_pair_read_by_hand_is_checked_without_its_coriolis_part(tmp_path):
    text, number, expected = _shaper_case()
    done, out = _run(tmp_path, text)
    assert done.returncode == 0, done.stderr
    _check_measured(out, number, expected)


# --- the slips a student makes ----------------------------------------------------------------------------------

def _slip(fixture, measured, edit=lambda text: text):
    return edit(_without_readings(fixture)) + "\n" + measured + "\n"


def _no_forces(text):
    """The scene without masses, weights and loads: no force analysis."""
    text = re.sub(r"\[\[loads\]\][^\[]*", "", text)
    text = re.sub(r"\[links\.\d+\][^\[]*", "", text)
    return re.sub(r"gravity\s*=\s*9\.81", "gravity = 0.0", text)


SLIPS = {
    # a segment the plan has no letters for: the letters it has
    "no such letter": ("ratchet_crank_rocker.toml", "[measured.5]\nvelocity = { pb = 38.5, pf = 30.0 }",
                       None, ["measured.5.velocity.pf", "a, b, e, p, s2, s3, s4"]),
    "no plan there": ("ratchet_crank_rocker.toml", "[measured.3]\nvelocity = { pb = 38.5 }", None,
                      ["measured.3", "positions.plans", "[5, 11]"]),
    "negative length": ("ratchet_crank_rocker.toml", "[measured.5]\nvelocity = { pb = -38.5 }", None,
                        ["measured.5.velocity.pb", ">= 0"]),
    "segment twice": ("ratchet_crank_rocker.toml", "[measured.5]\nvelocity = { pb = 38.5, bp = 39.0 }", None,
                      ["measured.5.velocity.bp", "pb", "once"]),
    "reaction twice": ("ratchet_crank_rocker.toml", "[measured.5]\nforces = { R23 = 52.0, R32 = 52.5 }", None,
                       ["measured.5.forces.R32", "R23", "once"]),
    "no such reaction": ("ratchet_crank_rocker.toml", "[measured.5]\nforces = { R24 = 52.0 }", None,
                         ["measured.5.forces.R24", "R23, R14, R34, R12"]),
    "no force analysis": ("ratchet_crank_rocker.toml", "[measured.5]\nforces = { R23 = 52.0 }", _no_forces,
                          ["measured.5.forces", "no force analysis"]),
    "balancing without forces": ("ratchet_crank_rocker.toml", "[measured.5]\nbalancing = 40.0", _no_forces,
                                 ["measured.5.balancing", "no force analysis"]),
    "coriolis component": ("shaper_six_bar.toml", "[measured.3]\nacceleration = { ak = 60.0 }", None,
                           ["measured.3.acceleration.ak", "Coriolis", "ka4"]),
    "normal component": ("shaper_six_bar.toml", "[measured.3]\nacceleration = { pn4 = 15.0 }", None,
                         ["measured.3.acceleration.pn4", "normal component", "n4a4"]),
    "a value typed for its segment": ("ratchet_crank_rocker.toml", "[measured.5]\nvelocity = { VE = 1.65 }", None,
                                      ["measured.5.velocity.VE", "pe"]),
}


@pytest.mark.parametrize("slip", list(SLIPS))
def test_a_students_slip_is_refused_naming_the_key_and_what_it_could_have_been(slip, tmp_path):
    fixture, measured, edit, words = SLIPS[slip]
    done, out = _run(tmp_path, _slip(fixture, measured, edit or (lambda text: text)))
    assert done.returncode == 2
    assert "Traceback" not in done.stderr
    for word in words:
        assert word in done.stderr, (word, done.stderr)
    assert not out.exists()


def test_a_segment_to_the_coriolis_vectors_end_is_not_called_the_coriolis_component(tmp_path):
    """pk runs from the pole to k, the Coriolis vector's end: it is no vector of the plan, and the Coriolis
    component is ak; telling the student that pk is the Coriolis component sends them to measure the wrong thing."""
    done, out = _run(tmp_path, _slip("shaper_six_bar.toml", "[measured.3]\nacceleration = { pk = 60.0 }"))
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert "measured.3.acceleration.pk" in done.stderr
    assert "pk is the Coriolis component" not in done.stderr
    assert "ak" in done.stderr and "Coriolis" in done.stderr
    assert not out.exists()


def test_lengths_typed_in_metres_are_warned_of(tmp_path):
    text = _slip("ratchet_crank_rocker.toml", "[measured.5]\nvelocity = { pb = 38.5, ab = 0.149 }")
    done, out = _run(tmp_path, text)
    assert done.returncode == 0 and (out / "errors.md").exists()
    assert "warning" in done.stdout + done.stderr
    said = done.stdout + done.stderr
    assert "ab = 0.149" in said and "metres" in said and "1000" in said


# --- the table as a teacher reads it -----------------------------------------------------------------------------

@pytest.mark.parametrize(("locale", "largest", "formula"), [
    ("en", "largest δ in magnitude", "δ = (analytic − plan) / analytic · 100 %"),
    ("ru", "наибольшая по модулю δ", "δ = (Xа − Xпл) / Xа · 100 %"),
])
def test_the_worst_hand_reading_is_named_under_its_tables_delta_column(locale, largest, formula, tmp_path):
    """A teacher checks the worst reading first; it was to be found by scanning every δ of a 30-row table."""
    text, number, expected = _shaper_case(locale)
    done, out = _run(tmp_path, text, only="errors,note")
    assert done.returncode == 0, done.stderr
    errors_md = (out / "errors.md").read_text(encoding="utf-8")
    assert formula in errors_md and formula in (out / "note.md").read_text(encoding="utf-8")
    header, rows = _table(errors_md, number)
    assert header[1] in ("unit", "ед. изм.")
    assert rows[next(iter(rows))][header[1]]  # every quantity's unit written beside it
    worst_quantity = max(expected, key=lambda name: abs((expected[name][0] - expected[name][1]) / expected[name][0]))
    exact, plan = expected[worst_quantity]
    worst = f"{(exact - plan) / exact * 100.0:.3f} ({_symbol(worst_quantity)})"
    if locale == "ru":
        worst = worst.replace(".", ",")
    measured_column = next(name for name in header if name.startswith("δ") and ("measured" in name or "замер" in name))
    assert rows[largest][measured_column].replace("−", "-") == worst
    assert rows[largest][header[1]] == "%"


@pytest.mark.parametrize(("locale", "bound"), [
    ("en", "more than 15 % and more than 1 mm off the plan as constructed"),
    ("ru", "более чем на 15 % и более чем на 1 мм"),
])
def test_the_one_bound_set_on_hand_readings_is_said_where_the_tables_have_them(locale, bound, tmp_path):
    """The only verdict the program gives on a reading is the misread warning (15 % and twice the 0.5 mm drafting
    precision); without the sentence a teacher could take a silent δ of 12 % for one the program passed."""
    text, _, _ = _shaper_case(locale)
    done, out = _run(tmp_path, text, only="errors,note")
    assert done.returncode == 0, done.stderr
    assert bound in (out / "errors.md").read_text(encoding="utf-8")
    assert bound in (out / "note.md").read_text(encoding="utf-8")
    plain, _ = _run(tmp_path / "plain", _without_readings("shaper_six_bar.toml").replace(
        'locale  = "en"', f'locale  = "{locale}"'))
    assert plain.returncode == 0
    assert bound not in (tmp_path / "plain" / "out" / "errors.md").read_text(encoding="utf-8")
