"""The balancing load a student found by hand (``[measured.N] balancing``): Mb = R32·h off the crank's polygon, or off
Zhukovsky's lever, is the force analysis's main result, and ``forces = { Mb = 34.8 }`` was refused as a reaction the
polygons do not have, with nothing to say how to check it.

The exact balancing load here is the test's own, from the power balance of the external loads, the weights and
d'Alembert's inertia loads at the velocities and accelerations of ``graphplan.solve``: Mb·ω2 + Σ(F·v + M·ω) = 0
(a slider's Fb·v along its guide), ideal pairs doing no work.
"""

import csv
import dataclasses
import json
import re
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.errors import SceneError
from graphplan.report.tables import markdown

GRAVITY = 9.81


def _always(path):
    """The fixture with its resisting load acting at every position (the power balance then needs no window)."""
    text = Path(path).read_text(encoding="utf-8")
    always = re.sub(r"during\s*=\s*(\{[^}]*\}|\"working\")", 'during = "always"', text)
    assert always != text
    return always


# By fixture: the links' (mass, centre, inertia), the resisting moment's link and size, the driver's velocity's
# point, and the plan position checked (its index in the motion).
CASES = {
    "crank": ("fixtures/ratchet_crank_rocker.toml", {2: (16.0, "S2", 0.0), 3: (17.0, "S3", 0.51), 4: (17.0, "S4", 0.18)},
              (4, 1500.0), 5, 5),
    "slider": ("fixtures/slider_driven.toml", {2: (6.0, "A", 0.0), 3: (1.4, "S3", 0.006), 4: (4.0, "S4", 0.02)},
               (4, 150.0), 3, 2),
}


def power_balance(kind):
    """The balancing load at the case's position from the power of every other load (Mb, N·m; Fb, N, along +x)."""
    path, links, (loaded, moment), number, index = CASES[kind]
    scene = graphplan.load_text(_always(path))
    motion = graphplan.solve(scene)

    def vector(point, attribute):
        return complex(*getattr(motion.point(point), attribute)[index])

    power = 0.0
    for link, (mass, centre, inertia) in links.items():
        velocity, acceleration = vector(centre, "v"), vector(centre, "a")
        force = mass * (-1j * GRAVITY) - mass * acceleration
        power += (force * velocity.conjugate()).real
        omega = float(motion.link(link).omega[index]) if link != 2 or kind == "crank" else 0.0
        epsilon = float(motion.link(link).epsilon[index]) if link != 2 or kind == "crank" else 0.0
        power += -inertia * epsilon * omega
    omega4 = float(motion.link(loaded).omega[index])
    power += -moment * np.sign(omega4) * omega4  # resisting: against the lever's motion
    driver = float(motion.link(2).omega[index]) if kind == "crank" else vector("A", "v").real
    return scene, number, -power / driver


@pytest.mark.parametrize("kind", ["crank", "slider"])
def test_a_balancing_load_found_by_hand_is_checked_against_the_exact_one(kind, tmp_path):
    scene, number, exact = power_balance(kind)
    symbol, unit = ("Mb", "N·m") if kind == "crank" else ("Fb", "N")
    read = round(abs(exact) * 1.03, 3)  # the student's value, 3 % over
    hand = dataclasses.replace(scene, locale="en", measured={number: {"balancing": read}})
    analysis = analyse(hand)
    rows = {row.source: row for row in analysis.errors if row.quantity == symbol}
    assert set(rows) == {"construction", "measured"}
    assert rows["measured"].analytic == pytest.approx(exact, rel=1e-6)
    assert rows["construction"].plan == pytest.approx(exact, rel=1e-6)
    # Its size is given, its sense the analysis's: the row is signed as the exact value.
    assert rows["measured"].plan == pytest.approx(np.sign(exact) * read)
    assert rows["measured"].percent == pytest.approx((abs(exact) - read) / abs(exact) * 100.0, abs=1e-9)
    assert not [w for w in analysis.warnings if w.code == "measured-far-off"]
    table = markdown(analysis)
    assert f"| {symbol} | {unit} |" in table
    assert f"{symbol}, {unit}: the balancing" in table
    # Every output of the error table has it: errors.csv, results.json and errors.tex.
    from graphplan.run import run

    out = tmp_path / "out"
    run(hand, out)
    with open(out / "errors.csv", encoding="utf-8") as handle:
        measured = [row for row in csv.DictReader(handle) if row["quantity"] == symbol and row["source"] == "measured"]
    assert len(measured) == 1 and float(measured[0]["percent"]) == pytest.approx(rows["measured"].percent, abs=1e-4)
    document = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert [e["source"] for e in document["errors"] if e["quantity"] == symbol] == ["construction", "measured"]
    assert f"{symbol[0]}\\textsubscript{{b}}" in (out / "errors.tex").read_text(encoding="utf-8")
    for locale, words in (("ru", "найденное вручную"), ("zh", "手算所得")):
        localised = markdown(dataclasses.replace(analysis, scene=dataclasses.replace(analysis.scene, locale=locale)))
        assert words in localised


def test_a_balancing_load_is_refused_without_a_force_analysis_and_pointed_to_from_forces():
    scene, number, _ = power_balance("crank")
    bare = dataclasses.replace(scene, links={}, loads=())
    with pytest.raises(SceneError, match=rf"measured\.{number}\.balancing.*no force analysis"):
        analyse(dataclasses.replace(bare, measured={number: {"balancing": 100.0}}))
    # Typed among the polygons' readings, the way the user first tried it: told where it goes.
    with pytest.raises(SceneError, match=r"Mb is the balancing load.*balancing = "):
        analyse(dataclasses.replace(scene, measured={number: {"forces": {"Mb": 100.0}}}))


def test_the_scene_file_takes_the_balancing_load_under_measured():
    text = _always("fixtures/ratchet_crank_rocker.toml").replace("[measured.5]\n", "[measured.5]\nbalancing = 250.5\n")
    scene = graphplan.load_text(text)
    assert scene.measured[5]["balancing"] == 250.5
    with pytest.raises(SceneError, match=r"measured\.5\.balancing.*>= 0"):
        graphplan.load_text(text.replace("balancing = 250.5", "balancing = -250.5"))
