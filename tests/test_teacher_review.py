"""A teacher's review of the explanatory note: its mechanics against a hand calculation that does not call graphplan's
solvers (numpy on the scene's own dimensions), and its statements against the numbers they are written beside."""

from __future__ import annotations

import json
import math
import re
import tomllib

import numpy as np
import pytest
from light_runs import notes_in_markdown_alone, on_no_sheet
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
            # On no sheet and without its HTML and LaTeX: the note.md and results.json of the scene as written, byte
            # for byte (diffed in en, ru and zh; the μl fitted to the field is the one the sheets chose), without
            # laying the course sheets out at a few μl to choose it, three quarters of the run.
            with notes_in_markdown_alone():
                light = on_no_sheet(scene, tmp_path_factory.mktemp(f"light-{locale}"))
                assert main(["run", str(light), "--out", str(out), "--only", "note,dynamics"]) == 0
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
    table = note[note.index("Reduced moment of inertia and reduced moment at the plan positions"):]
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
    table = note[re.search(r"Table \d+\. Loads on the links, position 3", note).start():]
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


@pytest.mark.parametrize(("locale", "formulas"), [("ru", "Fи = m·aS, Mи = −JS·ε."), ("zh", "Fu = m·aS，Mu = −JS·ε。")],
                         ids=["ru", "zh"])
def test_the_loads_table_s_inertia_moment_is_signed_alike_in_every_language(shaper, locale, formulas):
    _, note, _ = shaper(locale)
    assert formulas in note


@pytest.fixture(scope="module")
def displaced_shaper(tmp_path_factory):
    """The shaper of `graphplan new` with its inertia loads applied as one displaced force a link ([forces] inertia =
    "displaced"), without its friction and dynamics: its scene and note."""
    folder = tmp_path_factory.mktemp("shaper-displaced")
    scene_file = folder / "shaper.toml"
    assert main(["new", "shaper", "--out", str(scene_file)]) == 0
    scene = tomllib.loads(scene_file.read_text(encoding="utf-8"))
    del scene["friction"], scene["dynamics"]
    text = scene_file.read_text(encoding="utf-8")
    text = re.sub(r"^\[\[friction\]\].*?(?=^\[positions\])", "", text, flags=re.MULTILINE | re.DOTALL)
    text = re.sub(r"^\[dynamics\].*?(?=^\[drawing\])", "", text, flags=re.MULTILINE | re.DOTALL)
    scene_file.write_text(text + '\n[forces]\ninertia = "displaced"\n', encoding="utf-8")
    out = folder / "out"
    with notes_in_markdown_alone():  # on no sheet: the note.md of the scene as written (diffed), as above
        assert main(["run", str(on_no_sheet(scene_file, tmp_path_factory.mktemp("light"))), "--out", str(out),
                     "--only", "note"]) == 0
    return scene, (out / "note.md").read_text(encoding="utf-8")


def test_a_displaced_inertia_force_is_told_with_its_shift_and_its_point_on_the_lever(displaced_shaper):
    """With the inertia loads displaced the note still said only "Fu at the centre of mass", while its moment equation
    gave M(Fu4) = Fu4·h with h measured to the displaced line (0.4042 m, not S4's 0.3012 m) and its lever put Fu4 at
    s4 with an arm of s4's image shifted.  By hand at position 3: hu4 = J4·|ε4|/(m4·aS4), the line through
    K = S4 + hu4 across Fu4 with Fu4's moment about S4 equal to Mu4 = −J4·ε4; its arm about C; and on the lever the
    image k of K, s4 + ω4 × SK, whose arm about the pole at the lever's μV."""
    scene, note = displaced_shaper
    angle = shaper_position_angle(scene, 3)
    velocity, acceleration = shaper_rates(scene, angle)
    points = shaper_points(scene, angle)
    link = scene["links"]["4"]
    force = -link["mass"] * acceleration["4"]
    moment = -link["inertia"] * float(acceleration["ψ4"])
    shift = np.array([force[1], -force[0]]) * moment / (force @ force)  # cross(shift, Fu) = Mu
    assert float(shift[0] * force[1] - shift[1] * force[0]) == pytest.approx(moment)
    section = note[note.index("### 5.1. Position 3"):note.index("### 5.2.")]
    hu, = (value(found) for found in re.findall(rf"hu4 = Mu4/Fu4 = {NUMBER}/{NUMBER} = {NUMBER} m", section)[0][2:])
    assert hu == pytest.approx(np.linalg.norm(shift), rel=1e-4)
    assert "Fu4 acts on a line hu4 off S4, so that its moment about S4 is Mu4, and takes the place of Mu4" in section
    line_point = points["4"] + shift
    arm_about_c = abs(float(line_point[0] * force[1] - line_point[1] * force[0])) / np.linalg.norm(force)
    product = re.search(rf"M\(Fu4\) = −?Fu4·h\d* = {NUMBER}·{NUMBER} = ", section)
    assert value(product.group(2)) == pytest.approx(arm_about_c, abs=6e-5)
    image = velocity["4"] + float(velocity["ψ4"]) * np.array([-shift[1], shift[0]])
    lever_scale = value(re.search(rf"drawn larger than the velocity plan, at μV = {NUMBER} \(m/s\)/mm", section)
                        .group(1))
    # turned by 90°, the image's arm about the pole across the force is the image's part along it
    arm_on_lever = abs(float(image @ force)) / np.linalg.norm(force) / lever_scale
    # The arm by the name the sheet's lever letters it, h4 = 89.20, where the lever names one.
    row = re.search(rf"^\| Fu4 \| s4 \+ ω4·hu4 \| {NUMBER} \| (?:h\d+ = )?{NUMBER} \| {NUMBER} \|$", section, re.MULTILINE)
    assert row and value(row.group(2)) == pytest.approx(arm_on_lever, abs=6e-3)


@pytest.mark.parametrize(("locale", "told"), [
    ("ru", "сила Fи4 приложена на линии, смещённой на hи4 от S4 так, что её момент относительно S4 равен Mи4"),
    ("zh", "Fu4 的作用线偏离 S4 距离 hu4，使其对 S4 之矩等于 Mu4")], ids=["ru", "zh"])
def test_a_displaced_inertia_force_is_told_alike_in_every_language(tmp_path, locale, told):
    scene_file = tmp_path / "shaper.toml"
    assert main(["new", "shaper", "--out", str(scene_file), "--locale", locale]) == 0
    text = scene_file.read_text(encoding="utf-8")
    text = re.sub(r"^\[\[friction\]\].*?(?=^\[positions\])", "", text, flags=re.MULTILINE | re.DOTALL)
    text = re.sub(r"^\[dynamics\].*?(?=^\[drawing\])", "", text, flags=re.MULTILINE | re.DOTALL)
    scene_file.write_text(text + '\n[forces]\ninertia = "displaced"\n', encoding="utf-8")
    (tmp_path / "light").mkdir()
    with notes_in_markdown_alone():  # on no sheet: the note.md of the scene as written (diffed), as above
        assert main(["run", str(on_no_sheet(scene_file, tmp_path / "light")), "--out", str(tmp_path / "out"),
                     "--only", "note"]) == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    # The lever's table names them as the note's words do: the Russian Fи4 and hи4.
    assert told in note and ("| Fи4 | s4 + ω4·hи4 |" if locale == "ru" else "| Fu4 | s4 + ω4·hu4 |") in note


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_note_says_the_sense_an_unknown_is_first_assumed_in(shaper, locale):
    """«R34 = −3191.7 N (the minus sign: R34 acts against the sense first assumed)», and the sense first assumed was
    said nowhere.  The note says once how its moment equations are signed: an unknown enters with the sign of its
    moment in that sense, so that a reader finds it from the equation; each value said to be turned round is
    negative."""
    from graphplan.locale import strings

    _, note, _ = shaper(locale)
    text = strings(locale)
    said = {"en": "each unknown enters with the sign of its moment in the sense first assumed for it",
            "ru": "каждая неизвестная входит в уравнение со знаком своего момента",
            "zh": "各未知力按其初设方向所产生力矩的符号列入方程"}[locale]
    assert said in note
    reversed_mark = text["note_sense_reversed"].split("{name}")[0]
    lines = [line for line in note.splitlines() if reversed_mark in line and "⇒" in line]
    assert lines
    for line in lines:
        solved = line.split("⇒")[1].split(reversed_mark)[0]
        assert re.search(r"= −[\d.,]+ \S+\s*$", solved.strip()), line
