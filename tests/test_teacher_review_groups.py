"""A teacher's review of the less common groups and drivers, each against a calculation of its own.

Nothing here reads graphplan's solvers to build an expectation: positions come from the closure equations solved
here (closed forms, or Newton's method for the triad), velocities and accelerations from central differences of
those positions, the balancing load from the power balance of every load at the instant (inertia loads included),
and a group's reactions from its own linear equilibrium equations.  What is compared is what a student hands in:
results.json (points, ω and ε, the slides, the reactions and their lines, Mb or Fb) and the note's text (the
vector equations with a Coriolis term exactly where the guide turns, its direction on the plan, the sense words).

The scenes: the Scotch yoke (an RPP whose guide is the frame's), an RPP, a PRP and an RRP on guides of the
ratchet's rocking link 4 (and its coupler 3), the slider-driven lever moving back and speeding up along an inclined
guide, the double rocker's swing run the other way round, and the triad with a slider.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.locale import load_symbol, strings

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
G = 9.81


def _ran(text: str, folder: Path) -> tuple[dict, str]:
    folder.mkdir(parents=True, exist_ok=True)
    scene = folder / "scene.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(folder / "out"), "--only", "note"]) == 0
    results = json.loads((folder / "out" / "results.json").read_text(encoding="utf-8"))
    return results, (folder / "out" / "note.md").read_text(encoding="utf-8")


def _plan_positions(results: dict) -> list[dict]:
    chosen = [position for position in results["positions"] if position.get("plans")]
    assert len(chosen) >= 2
    return chosen


def _rot(v: np.ndarray, radians: float) -> np.ndarray:
    c, s = np.cos(radians), np.sin(radians)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def _left(v: np.ndarray) -> np.ndarray:
    return np.array([-v[1], v[0]])


def _circles(a: np.ndarray, c: np.ndarray, la: float, lb: float, side: float) -> np.ndarray:
    """The point at la from a and lb from c, to the left of a→c (side = +1) or to its right (−1)."""
    d = c - a
    length = np.linalg.norm(d)
    along = (la ** 2 - lb ** 2 + length ** 2) / (2 * length)
    return a + along * d / length + side * np.sqrt(la ** 2 - along ** 2) * _left(d / length)


def _differences(positions, q: float, rate: float, rate_of_rate: float = 0.0, h: float = 1e-4) -> dict:
    """Each quantity of positions(q) with its first and second time derivatives, by 4th-order central differences
    over the driver coordinate and the chain rule (angles unwrapped)."""
    samples = [positions(q + k * h) for k in (-2, -1, 0, 1, 2)]
    out = {}
    for key in samples[2]:
        values = [np.array(sample[key], dtype=float) for sample in samples]
        if key.startswith("th"):
            values = list(np.unwrap(np.array(values)))
        first = (values[0] - 8 * values[1] + 8 * values[3] - values[4]) / (12 * h)
        second = (-values[0] + 16 * values[1] - 30 * values[2] + 16 * values[3] - values[4]) / (12 * h * h)
        out[key] = (values[2], rate * first, rate * rate * second + rate_of_rate * first)
    return out


def _inertial_power(motion: dict, masses: dict, inertias: dict, centres: dict, turning: dict) -> float:
    """Power of gravity and of the inertia loads (−m·aS at S, −JS·ε) at the instant."""
    power = 0.0
    for link, mass in masses.items():
        _, v, a = motion[centres[link]]
        power += float(np.dot(np.array([0.0, -mass * G]) - mass * a, v))
        if link in turning:
            _, omega, epsilon = turning[link]
            power -= inertias.get(link, 0.0) * epsilon * omega
    return power


# --- the ratchet's rocker 4 and coupler 3 carrying an RPP, a PRP, an RRP ---------------------------------------

O_RATCHET, C_RATCHET = np.array([0.0, 0.0]), np.array([0.0, 0.55])
L_OA, L_AB, L_BC = 0.175, 0.55, 0.325

HUNG = {
    "RPP": """
[[groups]]
kind = "RPP"
links = [5, 6]
joints = ["E", "K"]
guide = { link = 4, through = "C", angle = 20.0 }
angle = 70.0
""",
    "PRP": """
[[groups]]
kind = "PRP"
links = [5, 6]
joints = ["K"]
guides = [{ link = 4, through = "C", angle = 0.0 }, { link = 3, through = "A", angle = 30.0 }]
offsets = [0.01, -0.02]
""",
    "RRP": """
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["E", "K"]
length = 0.45
guide = { link = 4, through = "C", angle = 20.0 }
assembly = "forward"
""",
}
MASSES = {2: 16.0, 3: 17.0, 4: 17.0, 5: 2.0, 6: 3.0}
INERTIAS = {3: 0.51, 4: 0.18, 5: 0.01, 6: 0.02}


def _ratchet_with(kind: str) -> str:
    text = (FIXTURES / "ratchet_crank_rocker.toml").read_text(encoding="utf-8").replace('locale  = "ru"',
                                                                                        'locale  = "en"')
    text = re.sub(r"\n\[measured\.5\][^\[]*", "\n", text)
    centre_5 = "E" if kind == "RPP" else "K"  # the RPP's block 5 is pinned at E; elsewhere link 5 carries K
    masses = (f'\n[links.5]\nmass = 2.0\ncentre = "{centre_5}"\ninertia = 0.01\n'
              '[links.6]\nmass = 3.0\ncentre = "K"\ninertia = 0.02\n')
    return text.replace("\n[points]", HUNG[kind] + "\n[points]").replace("\n[[loads]]", masses + "\n[[loads]]", 1)


def _ratchet(phi: float) -> dict:
    a = O_RATCHET + L_OA * np.array([np.cos(phi), np.sin(phi)])
    b = _circles(a, C_RATCHET, L_AB, L_BC, +1.0)  # "left": B left of A→C
    u, w = (b - a) / L_AB, (b - C_RATCHET) / L_BC
    s3 = a + 0.24 * u
    return {"A": a, "B": b, "E": s3 + 0.125 * _left(u), "S2": O_RATCHET + 0.08 * (a - O_RATCHET) / L_OA, "S3": s3,
            "S4": C_RATCHET + 0.14 * w, "th3": np.arctan2(u[1], u[0]), "th4": np.arctan2(w[1], w[0])}


def _rpp(phi: float) -> dict:
    p = _ratchet(phi)
    w = (p["B"] - C_RATCHET) / L_BC
    guide = _rot(w, np.radians(20.0))
    slot = _rot(guide, np.radians(70.0))
    along, across = np.linalg.solve(np.column_stack([guide, slot]), p["E"] - C_RATCHET)
    return p | {"K": C_RATCHET + along * guide, "s": along, "u": across}


def _prp(phi: float) -> dict:
    p = _ratchet(phi)
    w, u = (p["B"] - C_RATCHET) / L_BC, (p["B"] - p["A"]) / L_AB
    second = _rot(u, np.radians(30.0))
    on_first, on_second = C_RATCHET + 0.01 * _left(w), p["A"] - 0.02 * _left(second)
    s1, s2 = np.linalg.solve(np.column_stack([w, -second]), on_second - on_first)
    return p | {"K": on_first + s1 * w, "s1": s1, "s2": s2}


def _rrp(phi: float) -> dict:
    p = _ratchet(phi)
    guide = _rot((p["B"] - C_RATCHET) / L_BC, np.radians(20.0))
    foot = float(np.dot(p["E"] - C_RATCHET, guide))
    off = float(np.dot(p["E"] - C_RATCHET, _left(guide)))
    along = foot + np.sqrt(0.45 ** 2 - off ** 2)  # "forward": ahead of E's foot along the guide
    k = C_RATCHET + along * guide
    return p | {"K": k, "s": along, "th5": np.arctan2(*(k - p["E"])[::-1])}


@pytest.fixture(scope="module")
def hung(tmp_path_factory):
    return {kind: _ran(_ratchet_with(kind), tmp_path_factory.mktemp(kind)) for kind in HUNG}


def _balancing_moment(motion: dict, omega: float, turning: dict, centres: dict) -> float:
    # The 1500 N·m on the rocker acts on part of its working stroke only; at the plan positions 5 and 11 it does not
    # (the rocker is past the window in 5 and in its idle stroke in 11), so the balance leaves it out.
    return -_inertial_power(motion, MASSES, INERTIAS, centres, turning) / omega


def test_an_rpp_on_the_rocking_link_slides_and_balances_as_its_own_closure_and_statics_say(hung):
    results, _ = hung["RPP"]
    for position in _plan_positions(results):
        phi, omega = np.radians(position["driver"]["angle_deg"]), position["driver"]["omega"]
        motion = _differences(_rpp, phi, omega)
        for name in ("E", "K"):
            r, v, a = motion[name]
            got = position["points"][name]
            assert np.allclose(got["r"], r, atol=1e-9) and np.allclose(got["v"], v, atol=1e-6)
            assert np.allclose(got["a"], a, atol=1e-3)
        # Link 6 only slides along the rocker's guide, the block 5 only along 6's slot: both turn with the rocker.
        _, omega4, epsilon4 = motion["th4"]
        for link in ("4", "5", "6"):
            assert position["links"][link]["omega"] == pytest.approx(omega4, rel=1e-7)
            assert position["links"][link]["epsilon"] == pytest.approx(epsilon4, rel=1e-5)
        slides = {(slide["slider"], slide["guide"]): slide for slide in position["slides"]}
        assert slides[(6, 4)]["velocity"] == pytest.approx(motion["s"][1], rel=1e-7)
        assert slides[(6, 4)]["acceleration"] == pytest.approx(motion["s"][2], rel=1e-5)
        assert slides[(5, 6)]["velocity"] == pytest.approx(motion["u"][1], rel=1e-7)
        assert slides[(5, 6)]["acceleration"] == pytest.approx(motion["u"][2], rel=1e-5)

        # The group's own equilibrium: block 5 (at E) and link 6 (at K), frictionless slides, each reaction square
        # to its slide with a moment of its own (its line's shift); six equations, six unknowns.
        guide = _rot((motion["B"][0] - C_RATCHET) / L_BC, np.radians(20.0))
        slot = _rot(guide, np.radians(70.0))
        across_slot, across_guide = _left(slot), _left(guide)
        load5 = np.array([0.0, -MASSES[5] * G]) - MASSES[5] * motion["E"][2]
        load6 = np.array([0.0, -MASSES[6] * G]) - MASSES[6] * motion["K"][2]
        couple5, couple6 = -INERTIAS[5] * epsilon4, -INERTIAS[6] * epsilon4
        arm = motion["E"][0] - motion["K"][0]
        # unknowns: R35 (x, y), N65 (R65 = N65·n), C65 (its moment about E), N46 (R46 = N46·m), C46 (about K)
        system = np.zeros((6, 6))
        right = np.zeros(6)
        system[0, [0, 2]] = [1.0, across_slot[0]]
        system[1, [1, 2]] = [1.0, across_slot[1]]
        right[0:2] = -load5
        system[2, 3], right[2] = 1.0, -couple5
        system[3, [2, 4]] = [-across_slot[0], across_guide[0]]
        system[4, [2, 4]] = [-across_slot[1], across_guide[1]]
        right[3:5] = -load6
        system[5, [2, 3, 5]] = [-(arm[0] * across_slot[1] - arm[1] * across_slot[0]), -1.0, 1.0]
        right[5] = -couple6
        r35x, r35y, n65, c65, n46, c46 = np.linalg.solve(system, right)
        reactions = position["forces"]["reactions"]
        assert np.allclose(reactions["R35"], [r35x, r35y], rtol=1e-5, atol=1e-4)
        assert np.allclose(reactions["R65"], n65 * across_slot, rtol=1e-5, atol=1e-4)
        assert np.allclose(reactions["R46"], n46 * across_guide, rtol=1e-5, atol=1e-4)
        assert position["forces"]["offsets"]["R65"] == pytest.approx(abs(c65 / n65), rel=1e-5)
        assert position["forces"]["offsets"]["R46"] == pytest.approx(abs(c46 / n46), rel=1e-5)

        turning = {3: motion["th3"], 4: motion["th4"], 5: motion["th4"], 6: motion["th4"]}
        centres = {2: "S2", 3: "S3", 4: "S4", 5: "E", 6: "K"}
        expected = _balancing_moment(motion, omega, turning, centres)
        assert position["forces"]["balancing_moment"] == pytest.approx(expected, rel=1e-6)


def test_the_notes_coriolis_terms_stand_where_a_guide_turns_and_point_as_omega_turns_the_sliding(hung):
    equations = {
        "RPP": "aE6 = aE5 + aE6E5ᵏ + aE6E5ʳ = aE4 + aE6E4ᵏ + aE6E4ʳ",
        "PRP": "aK = aK4 + aKK4ᵏ + aKK4ʳ = aK3 + aKK3ᵏ + aKK3ʳ",
        "RRP": "aK = aE + aKEⁿ + aKEτ = aK4 + aKK4ᵏ + aKK4ʳ",
    }
    # On the plan each Coriolis segment runs from the known point's image to the Coriolis end: the relative
    # velocity (on the velocity plan, between the same two points' images) turned 90° in the sense of the guide's ω.
    segments = {
        "RPP": [("e", "k5", "e6", "5"), ("e4", "k6", "e6", "4")],
        "PRP": [("k4", "k5", "k", "4"), ("k3", "k6", "k", "3")],
        "RRP": [("k4", "k6", "k", "4")],
    }
    for kind, (results, note) in hung.items():
        assert note.count(f"Vector equation: {equations[kind]}") == 2, kind
        for position in _plan_positions(results):
            velocity = position["plans"]["velocity"]["points_mm"]
            acceleration = position["plans"]["acceleration"]["points_mm"]
            for start, coriolis_end, moving, guide_link in segments[kind]:
                relative = np.subtract(velocity[moving], velocity[start])
                coriolis = np.subtract(acceleration[coriolis_end], acceleration[start])
                omega = position["links"][guide_link]["omega"]
                turned = np.sign(omega) * _left(relative)
                cosine = np.dot(turned, coriolis) / np.linalg.norm(turned) / np.linalg.norm(coriolis)
                assert cosine == pytest.approx(1.0, abs=1e-6), (kind, position["index"], start)
                # and its length is 2·|ω|·V_rel at the plans' scales
                mu_v = position["plans"]["velocity"]["scale"]
                mu_a = position["plans"]["acceleration"]["scale"]
                assert np.linalg.norm(coriolis) * mu_a == pytest.approx(
                    2 * abs(omega) * np.linalg.norm(relative) * mu_v, rel=1e-6)


def test_a_prp_and_an_rrp_on_moving_guides_slide_and_balance_as_their_own_closures_say(hung):
    for kind, positions, centres in (("PRP", _prp, {2: "S2", 3: "S3", 4: "S4", 5: "K", 6: "K"}),
                                     ("RRP", _rrp, {2: "S2", 3: "S3", 4: "S4", 5: "K", 6: "K"})):
        results, _ = hung[kind]
        for position in _plan_positions(results):
            phi, omega = np.radians(position["driver"]["angle_deg"]), position["driver"]["omega"]
            motion = _differences(positions, phi, omega)
            r, v, a = motion["K"]
            assert np.allclose(position["points"]["K"]["r"], r, atol=1e-9)
            assert np.allclose(position["points"]["K"]["v"], v, atol=1e-6)
            assert np.allclose(position["points"]["K"]["a"], a, atol=1e-3)
            slides = {(slide["slider"], slide["guide"]): slide for slide in position["slides"]}
            w = (motion["B"][0] - C_RATCHET) / L_BC
            reactions = position["forces"]["reactions"]
            if kind == "PRP":
                expected = {(5, 4): motion["s1"], (6, 3): motion["s2"]}
                turning = {3: motion["th3"], 4: motion["th4"], 5: motion["th4"], 6: motion["th3"]}
                u = (motion["B"][0] - motion["A"][0]) / L_AB
                assert abs(np.dot(reactions["R45"], w)) < 1e-6 * np.linalg.norm(reactions["R45"])
                assert abs(np.dot(reactions["R36"], _rot(u, np.radians(30.0)))) < 1e-6 * np.linalg.norm(
                    reactions["R36"])
            else:
                expected = {(6, 4): motion["s"]}
                turning = {3: motion["th3"], 4: motion["th4"], 5: motion["th5"], 6: motion["th4"]}
                guide = _rot(w, np.radians(20.0))
                assert abs(np.dot(reactions["R46"], guide)) < 1e-6 * np.linalg.norm(reactions["R46"])
                assert position["links"]["5"]["omega"] == pytest.approx(motion["th5"][1], rel=1e-7)
                assert position["links"]["5"]["epsilon"] == pytest.approx(motion["th5"][2], rel=1e-5)
            for pair, (_, rate, rate_of_rate) in expected.items():
                assert slides[pair]["velocity"] == pytest.approx(rate, rel=1e-7)
                assert slides[pair]["acceleration"] == pytest.approx(rate_of_rate, rel=1e-5)
            balance = _balancing_moment(motion, omega, turning, centres)
            assert position["forces"]["balancing_moment"] == pytest.approx(balance, rel=1e-6)


# --- the Scotch yoke: an RPP on the frame's guide, its slot on a link that only translates ------------------------


@pytest.fixture(scope="module")
def yoke(tmp_path_factory):
    return _ran((FIXTURES / "scotch_yoke.toml").read_text(encoding="utf-8"), tmp_path_factory.mktemp("yoke"))


def test_the_scotch_yoke_s_slides_reactions_and_mb_are_those_of_its_closed_form_and_statics(yoke):
    results, note = yoke
    r, m2, m3, m4 = 0.075, 3.0, 0.4, 7.5
    for position in _plan_positions(results):
        phi, omega = np.radians(position["driver"]["angle_deg"]), position["driver"]["omega"]
        radial = np.array([np.cos(phi), np.sin(phi)])
        v_pin = r * omega * _left(radial)
        acc_pin = -r * omega ** 2 * radial
        # the slot (link 3's line) is at 90° to the vertical guide: −x; the block moves along it as −x(A)
        assert position["links"]["3"]["angle_deg"] % 360.0 == pytest.approx(180.0)
        slides = {(slide["slider"], slide["guide"]): slide for slide in position["slides"]}
        assert slides[(3, 4)]["velocity"] == pytest.approx(-v_pin[0], abs=1e-9)
        assert slides[(3, 4)]["acceleration"] == pytest.approx(-acc_pin[0], abs=1e-7)
        assert slides[(4, 1)]["velocity"] == pytest.approx(v_pin[1], abs=1e-9)
        assert slides[(4, 1)]["acceleration"] == pytest.approx(acc_pin[1], abs=1e-7)
        # statics: the yoke translates vertically; the plunger's 1200 N acts downward on the delivery (upward) stroke
        load = -1200.0 if v_pin[1] > 0 else 0.0
        r34_y = m4 * G + m4 * acc_pin[1] - load  # the slot pushes square to itself: vertically
        r23 = np.array([0.0, r34_y]) + np.array([0.0, m3 * G]) + m3 * acc_pin
        reactions = position["forces"]["reactions"]
        assert np.allclose(reactions["R43"], [0.0, -r34_y], atol=1e-6)
        assert np.allclose(reactions["R23"], r23, atol=1e-6)
        assert np.allclose(reactions["R14"], [0.0, 0.0], atol=1e-6)  # only a couple: nothing pushes sideways
        crank_power = np.dot(np.array([0.0, -m2 * G]) - m2 * acc_pin / 3, v_pin / 3)
        power = crank_power + np.dot(np.array([0.0, -m3 * G]) - m3 * acc_pin, v_pin) + (
            -m4 * G - m4 * acc_pin[1] + load) * v_pin[1]
        assert position["forces"]["balancing_moment"] == pytest.approx(-power / omega, rel=1e-7)
    # the slot is on a link that only translates: no Coriolis term anywhere in the note
    assert "aA4A3ᵏ" not in note and "Coriolis" not in note
    assert note.count("Vector equation: aA4 = aA3 + aA4A3ʳ = aA1 + aA4A1ʳ") == 2


# --- the slider driver: going back and speeding up along an inclined guide ---------------------------------------


@pytest.fixture(scope="module")
def slider_driven(tmp_path_factory):
    text = (FIXTURES / "slider_driven.toml").read_text(encoding="utf-8")
    text = text.replace("velocity     = 0.08 ", "velocity     = -0.08").replace(
        "acceleration = 0.0  ", "acceleration = 0.05 ").replace("angle = 0.0 }", "angle = 20.0 }")
    assert "-0.08" in text and "0.05" in text and "angle = 20.0" in text
    return _ran(text, tmp_path_factory.mktemp("slider"))


def test_a_slider_driver_s_fb_is_the_power_balance_s_and_its_guide_pushes_square_to_itself(slider_driven):
    results, note = slider_driven
    pivot = np.array([0.15, 0.25])
    guide = np.array([np.cos(np.radians(20.0)), np.sin(np.radians(20.0))])

    def positions(s: float) -> dict:
        a = s * guide
        b = _circles(a, pivot, 0.225, 0.15, -1.0)  # "right"
        return {"A": a, "B": b, "S3": (a + b) / 2, "S4": pivot + 0.06 * (b - pivot) / 0.15,
                "th3": np.arctan2(*(b - a)[::-1]), "th4": np.arctan2(*(b - pivot)[::-1])}

    for position in _plan_positions(results):
        driver = position["driver"]
        motion = _differences(positions, driver["displacement"], driver["velocity"], driver["acceleration"])
        assert np.allclose(position["points"]["B"]["a"], motion["B"][2], atol=1e-7)
        turning = {3: motion["th3"], 4: motion["th4"]}
        power = _inertial_power(motion, {2: 6.0, 3: 1.4, 4: 4.0}, {3: 0.006, 4: 0.02},
                                {2: "A", 3: "S3", 4: "S4"}, turning)
        # link 4 turns clockwise here, against the scene's working sense: its 150 N·m never acts (the run warns)
        assert motion["th4"][1] < 0 and position["stroke"] == "idle"
        balancing = position["forces"]["balancing_force"]  # along the guide's direction
        assert balancing == pytest.approx(-power / driver["velocity"], rel=1e-7)
        r12 = position["forces"]["reactions"]["R12"]
        assert abs(np.dot(r12, guide)) < 1e-9 * np.linalg.norm(r12)
        assert f"| Fb | {balancing:.5g} ∠ 20° |" in note
    assert note.count("so VA = |ṡ| = 0.08 m/s, against the direction of its guide.") == 2
    assert "| Fu2 | 0.3 ∠ −160° |" in note  # −m·s̈ along the guide: backward


# --- the rocking crank: its swing run from 65° down to 20° with ω < 0, ε > 0 ---------------------------------------


@pytest.fixture(scope="module")
def swing(tmp_path_factory):
    text = (FIXTURES / "double_rocker_swing.toml").read_text(encoding="utf-8")
    text = text.replace("swing   = [20.0, 65.0]", "swing   = [65.0, 20.0]").replace(
        "omega   = 4.0 ", "omega   = -4.0").replace("epsilon = 2.0 ", "epsilon = 3.0 ")
    assert "[65.0, 20.0]" in text and "-4.0" in text and "3.0 " in text
    return _ran(text, tmp_path_factory.mktemp("swing"))


def test_a_rocking_crank_s_senses_and_mb_are_those_of_its_own_closure(swing):
    results, note = swing
    frame_c = np.array([0.3, 0.0])

    def positions(phi: float) -> dict:
        a = 0.25 * np.array([np.cos(phi), np.sin(phi)])
        b = _circles(a, frame_c, 0.12, 0.2, -1.0)
        return {"A": a, "B": b, "S2": a / 2, "S3": (a + b) / 2, "S4": (frame_c + b) / 2,
                "th3": np.arctan2(*(b - a)[::-1]), "th4": np.arctan2(*(b - frame_c)[::-1])}

    angles = [position["driver"]["angle_deg"] for position in results["positions"]]
    assert angles == pytest.approx(list(np.linspace(65.0, 20.0, 7)))
    word = {True: "counter-clockwise", False: "clockwise"}
    for position in _plan_positions(results):
        driver = position["driver"]
        motion = _differences(positions, np.radians(driver["angle_deg"]), driver["omega"], driver["epsilon"])
        section = note.split(f"Position {position['index']}: ")[1].split("\n### ")[0]
        for link in (3, 4):
            _, omega, epsilon = motion[f"th{link}"]
            assert position["links"][str(link)]["omega"] == pytest.approx(omega, rel=1e-7)
            assert position["links"][str(link)]["epsilon"] == pytest.approx(epsilon, rel=1e-5)
            assert re.search(rf"- ω{link} = [^\n]* rad/s, {word[omega > 0]}\n", section)
            same = "accelerated" if omega * epsilon > 0 else "decelerated"
            assert re.search(rf"- ε{link} = [^\n]* rad/s², {word[epsilon > 0]}; the rotation of link {link} is "
                             rf"{same}", section)
        turning = {2: (None, driver["omega"], driver["epsilon"]), 3: motion["th3"], 4: motion["th4"]}
        power = _inertial_power(motion, {2: 1.5, 3: 2.0, 4: 3.0}, {2: 0.008, 3: 0.003, 4: 0.01},
                                {2: "S2", 3: "S3", 4: "S4"}, turning)
        power -= 20.0 * abs(motion["th4"][1])  # the clamp's 20 N·m resists always
        assert position["forces"]["balancing_moment"] == pytest.approx(-power / driver["omega"], rel=1e-6)
    assert "| ω2 | 4 rad/s, clockwise |" in note and "| ε2 | 3 rad/s², counter-clockwise |" in note


# --- the triad with a slider: Newton's method on its six closure equations ----------------------------------------


@pytest.fixture(scope="module")
def triad(tmp_path_factory):
    return _ran((FIXTURES / "triad_with_slider.toml").read_text(encoding="utf-8"), tmp_path_factory.mktemp("triad"))


def test_the_triad_with_a_slider_slides_and_balances_as_its_own_newton_solution_says(triad):
    results, note = triad
    frame_c, frame_e = np.array([0.28, 0.0]), np.array([0.0, 0.14])
    guide = np.array([np.cos(np.radians(-30.0)), np.sin(np.radians(-30.0))])

    def residual(x: np.ndarray, a: np.ndarray) -> np.ndarray:
        b, d, f = x[0:2], x[2:4], x[4:6]
        return np.array([np.sum((b - a) ** 2) - 0.17 ** 2, np.sum((d - frame_c) ** 2) - 0.14 ** 2,
                         guide[0] * (f - frame_e)[1] - guide[1] * (f - frame_e)[0],
                         np.sum((d - b) ** 2) - 0.075 ** 2, np.sum((f - d) ** 2) - 0.115 ** 2,
                         np.sum((b - f) ** 2) - 0.065 ** 2])

    def newton(a: np.ndarray, x: np.ndarray) -> np.ndarray:
        for _ in range(50):
            jacobian = np.empty((6, 6))
            for j in range(6):
                step = np.zeros(6)
                step[j] = 1e-7
                jacobian[:, j] = (residual(x + step, a) - residual(x - step, a)) / 2e-7
            change = np.linalg.solve(jacobian, -residual(x, a))
            x = x + change
            if np.max(np.abs(change)) < 1e-15:
                break
        return x

    for position in _plan_positions(results):
        start = np.concatenate([position["points"][name]["r"] for name in "BDF"]) + 0.003  # a sketch near it

        def positions(phi: float, start=start) -> dict:
            a = 0.05 * np.array([np.cos(phi), np.sin(phi)])
            x = newton(a, start)
            b, d, f = x[0:2], x[2:4], x[4:6]
            u = (d - b) / 0.075
            return {"A": a, "B": b, "D": d, "F": f, "S2": a / 2, "S3": a + 0.085 * (b - a) / 0.17,
                    "S4": frame_c + 0.07 * (d - frame_c) / 0.14, "S6": b + 0.018 * u + 0.02 * _left(u),
                    "th3": np.arctan2(*(b - a)[::-1]), "th4": np.arctan2(*(d - frame_c)[::-1]),
                    "th6": np.arctan2(u[1], u[0]), "s": float(np.dot(f - frame_e, guide))}

        motion = _differences(positions, np.radians(position["driver"]["angle_deg"]), 10.0)
        (slide,) = position["slides"]
        assert slide["velocity"] == pytest.approx(motion["s"][1], rel=1e-7)
        assert slide["acceleration"] == pytest.approx(motion["s"][2], rel=1e-5)
        assert position["links"]["6"]["epsilon"] == pytest.approx(motion["th6"][2], rel=1e-5)
        turning = {3: motion["th3"], 4: motion["th4"], 6: motion["th6"]}
        power = _inertial_power(motion, {2: 1.2, 3: 2.0, 4: 1.6, 5: 1.5, 6: 3.0}, {3: 0.00482, 4: 0.00261, 6: 0.003},
                                {2: "S2", 3: "S3", 4: "S4", 5: "F", 6: "S6"}, turning)
        v_slider = motion["F"][1]
        if position["stroke"] == "working":  # up the guide (backward): 250 N along 150°, against the motion
            assert np.dot(v_slider, -guide) > 0
            power -= 250.0 * abs(np.dot(v_slider, -guide))
        assert position["forces"]["balancing_moment"] == pytest.approx(-power / 10.0, rel=1e-6)
        r15 = position["forces"]["reactions"]["R15"]
        assert abs(np.dot(r15, guide)) < 1e-9 * np.linalg.norm(r15)  # a frictionless guide pushes square to itself
    # the guide is the frame's: the slider's sliding has no Coriolis part
    assert "ᵏ" not in note and "aFF1ʳ" in note


@pytest.mark.parametrize("locale, turning_word", [("en", "clockwise"), ("ru", "часовой"), ("zh", "时针")])
def test_forces_md_gives_a_slider_s_fb_its_sense_along_the_guide_and_a_crank_s_mb_its_turning_sense(
        tmp_path, locale, turning_word):
    """The sign rule at the head of forces.md: Fb, a force along the driving slider's guide, has no turning sense
    (its sign, checked above by the power balance, is along the guide's direction); Mb has no guide."""
    def intro(fixture: str) -> str:
        folder = tmp_path / fixture
        assert main(["run", str(FIXTURES / f"{fixture}.toml"), "--out", str(folder), "--only", "forces",
                     "--locale", locale]) == 0
        return (folder / "forces.md").read_text(encoding="utf-8").split("\n")[2]

    slider, crank = intro("slider_driven"), intro("scotch_yoke")
    text = strings(locale)  # the symbols as the locale writes them: the Russian Fу, Mу
    assert load_symbol("Fb", text) in slider and turning_word not in slider
    assert load_symbol("Mb", text) in crank and turning_word in crank
    guide_word = {"en": "guide", "ru": "направляющ", "zh": "导路"}[locale]
    assert guide_word in slider and guide_word not in crank


def test_the_rpp_s_slot_link_has_its_omega_read_over_a_named_length(hung):
    """ω6 of the RPP's slotted link is read off the segment e6k (E6: link 6's point under the block's pin E) over
    the distance E6K, which the note names as it names every other length, not as a bare l."""
    results, note = hung["RPP"]
    for position in _plan_positions(results):
        phi, omega = np.radians(position["driver"]["angle_deg"]), position["driver"]["omega"]
        motion = _differences(_rpp, phi, omega)
        distance = np.linalg.norm(motion["E"][0] - motion["K"][0])
        section = note.split(f"Position {position['index']}: ")[1].split("\n### ")[0]
        (line,) = re.findall(r"- ω6 = [^\n]*", section)
        found = re.fullmatch(r"- ω6 = e6k·μV/lE6K = ([\d.]+)·([\d.]+)/([\d.]+) = ([\d.]+) rad/s, (\S+)", line)
        assert found, line
        millimetres, scale, length, value = (float(found.group(k)) for k in range(1, 5))
        assert length == pytest.approx(distance, rel=1e-4)
        assert value == pytest.approx(abs(motion["th4"][1]), rel=1e-4)
        assert found.group(5) == ("counter-clockwise" if motion["th4"][1] > 0 else "clockwise")
        assert millimetres * scale / length == pytest.approx(value, rel=2e-3)


@pytest.mark.parametrize("piece", ["note", "forces"])
@pytest.mark.parametrize("locale, couple_word", [("en", "couple"), ("ru", "пар"), ("zh", "力偶")])
def test_a_guide_whose_reaction_is_nought_is_told_to_hold_its_moment_as_a_couple(tmp_path, locale, couple_word,
                                                                                   piece):
    """The Scotch yoke's frame guide: the slot pushes the yoke square to itself, vertically, so nothing pushes it
    sideways and R14 = 0 at every position; the yoke's moment about B, R34's 0.075·R34 at φ = 0, is held by the
    guide as a couple alone. "R14·x = −95.518 N·m" beside "R14 = 0" would put x at infinity: the note says so,
    and forces.md, which writes the same moment equations, too."""
    folder = tmp_path / locale
    assert main(["run", str(FIXTURES / "scotch_yoke.toml"), "--out", str(folder), "--only", piece,
                 "--locale", locale]) == 0
    results = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    note = (folder / f"{piece}.md").read_text(encoding="utf-8")
    for position in _plan_positions(results):
        phi = np.radians(position["driver"]["angle_deg"])
        omega = position["driver"]["omega"]
        acc_y = -0.075 * omega ** 2 * np.sin(phi)
        load = -1200.0 if 0.075 * omega * np.cos(phi) > 0 else 0.0
        r34_y = 7.5 * G + 7.5 * acc_y - load
        couple = -0.075 * np.cos(phi) * r34_y  # about B, the yoke's point on the guide under A's slot line
        assert position["forces"]["reactions"]["R14"] == [0.0, 0.0]
        assert position["forces"]["offsets"]["R14"] is None
        section = [line for line in note.splitlines() if "ΣMB(4)" in line][_plan_positions(results).index(position)]
        written = float(re.search(r"R14·x = (−?[\d.,]+)", section).group(1).replace("−", "-").replace(",", "."))
        assert written == pytest.approx(couple, rel=1e-4)
        assert couple_word in section, section
