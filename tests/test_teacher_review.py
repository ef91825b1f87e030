"""A teacher's review of the explanatory note: its mechanics against a hand calculation that does not call graphplan's
solvers (numpy on the scene's own dimensions), and its statements against the numbers they are written beside."""

from __future__ import annotations

import json
import math
import re
import tomllib

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from graphplan.cli import main

NUMBER = r"(−?\d+(?:[.,]\d+)?)"


def value(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


@pytest.fixture(scope="module")
def shaper(tmp_path_factory):
    """The shaper `graphplan new` writes, run in a language: its scene, note and results, each language run once."""
    runs = {}

    def in_locale(locale: str) -> tuple[dict, str, dict]:
        if locale not in runs:
            folder = tmp_path_factory.mktemp(f"shaper-{locale}")
            scene = folder / "shaper.toml"
            assert main(["new", "shaper", "--out", str(scene), "--locale", locale]) == 0
            out = folder / "out"
            assert main(["run", str(scene), "--out", str(out), "--only", "note,dynamics"]) == 0
            runs[locale] = (tomllib.loads(scene.read_text(encoding="utf-8")),
                            (out / "note.md").read_text(encoding="utf-8"),
                            json.loads((out / "results.json").read_text(encoding="utf-8")))
        return runs[locale]

    return in_locale


def shaper_points(scene: dict, angle: float) -> dict[str, np.ndarray]:
    """The shaper's centres of mass at the crank angle (rad), by hand: the crank OA, the block on its pin in the
    lever's slot through C, the lever's end D joined by DE to the ram E on its horizontal guide, the ram ahead of D;
    "4" and "5" also give the lever's and DE's angles, "ψ4" and "ψ5" (rad)."""
    frame = scene["frame"]["points"]
    centre_c, centre_o = np.array(frame["C"], float), np.array(frame["O"], float)
    crank, link_de = scene["driver"]["length"], scene["groups"][1]["length"]
    points = scene["points"]
    guide_y = scene["frame"]["lines"]["ram"]["through"][1]
    a = centre_o + crank * np.array([math.cos(angle), math.sin(angle)])
    along = (a - centre_c) / np.linalg.norm(a - centre_c)
    d = centre_c + points["D"]["at"] * along
    e = np.array([d[0] + math.sqrt(link_de ** 2 - (guide_y - d[1]) ** 2), guide_y])
    return {"2": centre_o + points["S2"]["at"] / crank * (a - centre_o), "3": a,
            "4": centre_c + points["S4"]["at"] * along, "5": d + points["S5"]["at"] / link_de * (e - d), "6": e,
            "ψ4": np.array(math.atan2(along[1], along[0])), "ψ5": np.array(math.atan2(e[1] - d[1], e[0] - d[0]))}


def shaper_rates(scene: dict, angle: float) -> tuple[dict, dict]:
    """Velocities and accelerations of :func:`shaper_points` at the crank angle, the crank turning at its constant ω:
    central differences in time."""
    omega = scene["driver"]["rpm"] * math.pi / 30.0
    step = 1e-4
    ahead, here, behind = (shaper_points(scene, angle + omega * t) for t in (step, 0.0, -step))
    velocity = {name: (ahead[name] - behind[name]) / (2 * step) for name in here}
    acceleration = {name: (ahead[name] - 2 * here[name] + behind[name]) / step ** 2 for name in here}
    return velocity, acceleration


def shaper_position_angle(scene: dict, number: int) -> float:
    """The crank angle (rad) of a position: the first where the ram's cutting stroke (+x) begins, at the least x of
    the ram, the next ones a twelfth of a turn on each in the crank's sense."""
    grid = np.linspace(0.0, 2 * math.pi, 3601)
    start = grid[int(np.argmin([shaper_points(scene, angle)["6"][0] for angle in grid]))]
    start = minimize_scalar(lambda angle: shaper_points(scene, angle)["6"][0], bounds=(start - 0.01, start + 0.01),
                            method="bounded", options={"xatol": 1e-12}).x
    sense = math.copysign(1.0, scene["driver"]["rpm"])
    return start + sense * (number - scene["positions"]["number_from"]) * 2 * math.pi / scene["positions"]["count"]


def shaper_power_of_loads(scene: dict, phi: float) -> float:
    """The power of the cutting force and the weights at the crank angle φ (rad), W, by hand."""
    velocity, _ = shaper_rates(scene, phi)
    # the ram's extremes over a turn, for the share of its stroke the cutting force acts in
    travel = np.array([shaper_points(scene, angle)["6"][0] for angle in np.linspace(0.0, 2 * math.pi, 20001)])
    share = (shaper_points(scene, phi)["6"][0] - travel.min()) / (travel.max() - travel.min())
    load = scene["loads"][0]
    cutting = load["value"] * math.cos(math.radians(load["angle"])) \
        if velocity["6"][0] > 0 and load["during"]["from"] <= share <= load["during"]["to"] else 0.0
    gravity = scene["scene"]["gravity"]
    weights = sum(-scene["links"][link]["mass"] * gravity * velocity[link][1] for link in "23456")
    return cutting * velocity["6"][0] + weights


def test_the_equation_of_motion_says_which_sign_its_mr_has_against_the_table_s_signed_mr(shaper):
    """The note's dynamics table gives Mr signed, −245.9 N·m in the cutting stroke (the power of the cutting force and
    the weights over |ω|, by hand), and its equation of motion then subtracted an Mr(φ) from Md(ω): read with the
    table's Mr, the cutting stroke would speed the machine up.  The run integrates Md − Mr with Mr positive where it
    resists: the note must say that its Mr(φ) there is the table's with its sign turned, as the flywheel's ω(φ) has it
    (the crank slows down in the cutting stroke, where Md + Mr of the table is below nought)."""
    scene, note, results = shaper("en")
    omega = abs(scene["driver"]["rpm"]) * math.pi / 30.0
    table = note[note.index("Reduced inertia and reduced load at the plan positions"):]
    row = re.search(rf"^\| 3 \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \|$",
                    table, re.MULTILINE)
    assert row, "the dynamics table's row of position 3"
    phi, plan_mr = value(row.group(1)), value(row.group(5))
    by_hand = shaper_power_of_loads(scene, math.radians(phi)) / omega
    assert by_hand < 0 and plan_mr == pytest.approx(by_hand, rel=2e-4)
    driving, = (value(m) for m in re.findall(rf"Md = Ar/2π = {NUMBER} N·m", note))
    assert driving + plan_mr < 0
    dynamics = results["dynamics"]
    angles = np.array(dynamics["angle_deg"])
    at = int(np.argmin(np.abs((angles - phi + 180.0) % 360.0 - 180.0)))
    assert dynamics["omega"][at + 1] < dynamics["omega"][at - 1], "the crank slows down in the cutting stroke"
    assert "= Md(ω) − Mr(φ); Je(φ) is the machine's reduced moment of inertia" in note
    assert ("; Mr(φ) is the reduced moment of the loads and the weights with its sign turned, positive where they "
            "resist the motion. It is integrated") in note


@pytest.mark.parametrize(("locale", "equation", "sign"), [
    ("ru", "= Mд(ω) − Mс(φ)", ("Mс(φ) — приведённый момент внешних сил и сил тяжести, взятый с обратным знаком: он "
                              "положителен там, где они сопротивляются движению")),
    ("zh", "= Md(ω) − Mr(φ)", "Mr(φ) 为外载荷与重力的等效力矩取反号，在其阻碍运动处为正"),
], ids=["ru", "zh"])
def test_the_equation_of_motion_s_mr_is_signed_alike_in_every_language(shaper, locale, equation, sign):
    _, note, _ = shaper(locale)
    assert equation in note and sign in note
    assert note.index(equation) < note.index(sign)


def test_the_loads_table_gives_the_inertia_moment_signed_as_epsilon_is_against_it(shaper):
    """The table of the loads gave ε signed (counter-clockwise positive) and Mu as J·|ε|: position 3's Mu5 =
    0.028247 N·m beside ε5 = 2.5679 rad/s² read as turning with ε5, while Mu5 = −J5·ε5 turns clockwise (the list under
    the table and the moment equations say so).  By hand: ε4, ε5 of the lever and of DE there, Mu = −J·ε."""
    scene, note, _ = shaper("en")
    angle = shaper_position_angle(scene, 3)
    heading = re.search(rf"^### 3\.1\. Position 3: φ = {NUMBER}°", note, re.MULTILINE)
    assert value(heading.group(1)) == pytest.approx(math.degrees(angle) % 360.0, abs=0.05)
    _, acceleration = shaper_rates(scene, angle)
    table = note[note.index("Table 11. Loads on the links, position 3"):]
    assert "Fu = m·aS, Mu = −JS·ε." in note
    for link in (4, 5):
        row = re.search(rf"^\| {link} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| {NUMBER} \| "
                        rf"{NUMBER} \|$", table, re.MULTILINE)
        epsilon, moment = value(row.group(5)), value(row.group(6))
        by_hand = float(acceleration[f"ψ{link}"])
        inertia = scene["links"][str(link)]["inertia"]
        assert epsilon == pytest.approx(by_hand, rel=1e-4)
        assert moment == pytest.approx(-inertia * by_hand, rel=1e-4)
        sense = "counter-clockwise" if moment > 0 else "clockwise"
        assert re.search(rf"Mu{link} = J{link}·ε{link} = [^;\n]* N·m, {sense}\n", note)


@pytest.mark.parametrize(("locale", "formulas"), [("ru", "Fu = m·aS, Mu = −JS·ε."), ("zh", "Fu = m·aS，Mu = −JS·ε。")],
                         ids=["ru", "zh"])
def test_the_loads_table_s_inertia_moment_is_signed_alike_in_every_language(shaper, locale, formulas):
    _, note, _ = shaper(locale)
    assert formulas in note
