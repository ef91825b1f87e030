"""A teacher's review of the explanatory note: its mechanics against a hand calculation that does not call graphplan's
solvers (numpy on the scene's own dimensions), and its statements against the numbers they are written beside."""

from __future__ import annotations

import json
import math
import re
import tomllib

import numpy as np
import pytest

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


def shaper_power_of_loads(scene: dict, phi: float) -> float:
    """The power of the cutting force and the weights at the crank angle φ (rad), W, by hand: the crank OA, the block
    on its pin in the lever's slot through C, the lever's end D joined by DE to the ram E on its horizontal guide,
    the ram ahead of D; velocities by central differences of the positions in the crank's angle."""
    frame = scene["frame"]["points"]
    centre_c, centre_o = np.array(frame["C"], float), np.array(frame["O"], float)
    crank, link_de = scene["driver"]["length"], scene["groups"][1]["length"]
    points = scene["points"]
    guide_y = scene["frame"]["lines"]["ram"]["through"][1]
    omega = scene["driver"]["rpm"] * math.pi / 30.0

    def where(angle: float) -> dict[str, np.ndarray]:
        a = centre_o + crank * np.array([math.cos(angle), math.sin(angle)])
        along = (a - centre_c) / np.linalg.norm(a - centre_c)
        d = centre_c + points["D"]["at"] * along
        e = np.array([d[0] + math.sqrt(link_de ** 2 - (guide_y - d[1]) ** 2), guide_y])
        return {"2": centre_o + points["S2"]["at"] / crank * (a - centre_o), "3": a,
                "4": centre_c + points["S4"]["at"] * along, "5": d + points["S5"]["at"] / link_de * (e - d), "6": e}

    step = 1e-6
    ahead, behind = where(phi + step), where(phi - step)
    velocity = {link: (ahead[link] - behind[link]) / (2 * step) * omega for link in ahead}
    # the ram's extremes over a turn, for the share of its stroke the cutting force acts in
    travel = np.array([where(angle)["6"][0] for angle in np.linspace(0.0, 2 * math.pi, 20001)])
    share = (where(phi)["6"][0] - travel.min()) / (travel.max() - travel.min())
    load = scene["loads"][0]
    cutting = load["value"] * math.cos(math.radians(load["angle"])) \
        if velocity["6"][0] > 0 and load["during"]["from"] <= share <= load["during"]["to"] else 0.0
    gravity = scene["scene"]["gravity"]
    weights = sum(-scene["links"][link]["mass"] * gravity * velocity[link][1] for link in velocity)
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
