"""What a student's first course projects, a jaw crusher's six-bar and a knee-lever press, showed on their sheets.

The kinematic diagrams of a rocker output are of its angle ψ, its ω and its ε: their scales are μψ, μω = μψ/(μt·H₁)
and με = μω/(μt·H₂), as the textbooks write them and as the load diagram beside them already writes μψ, not the
slider's μs, μv, μa with a unit in radians.  A knee press's load diagram took an A1 of its own at its usual size
beside four force sheets whose room holds it smaller: it is drawn smaller there rather than alone on a sheet.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
from sheet_texts import flat

import graphplan
from graphplan.kinematic_diagrams import kinematic_diagrams
from graphplan.locale import strings
from graphplan.mechanism import build
from graphplan.positions import make_positions
from graphplan.render import diagrams
from graphplan.scene import loads

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
NUMBER = r"([0-9]+(?:[.,][0-9]+)?)"


def _number(pattern: str, text: str) -> float:
    found = re.search(pattern, text)
    assert found is not None, pattern
    return float(found.group(1).replace(",", "."))


def _record(name: str):
    mechanism = build(loads((FIXTURES / f"{name}.toml").read_text(encoding="utf-8")))
    return kinematic_diagrams(mechanism, make_positions(mechanism))


def _rocker_diagrams(locale: str = "en"):
    record = _record("ratchet_crank_rocker")
    return record, diagrams.diagrams_svg(record, strings(locale))


def test_a_rocker_s_diagrams_state_the_scales_of_its_angle_omega_and_epsilon():
    record, svg = _rocker_diagrams()
    assert not record.translating
    assert "μs =" not in svg and "μv =" not in svg and "μa =" not in svg
    mu_psi = _number(r"μψ = " + NUMBER + r" rad/mm", svg)
    mu_omega = _number(r"μω = μψ/\(μt·H₁\) = " + NUMBER, svg)
    mu_eps = _number(r"με = μω/\(μt·H₂\) = " + NUMBER, svg)
    h1 = _number(r"H₁ = " + NUMBER + " mm", svg)
    h2 = _number(r"H₂ = " + NUMBER + " mm", svg)
    # μt from the φ axis the sheet states: a turn over L mm at the crank's |ω|, not the program's own μt.
    length = _number(r"L = " + NUMBER + " mm", svg)
    omega = abs(graphplan.load(FIXTURES / "ratchet_crank_rocker.toml").driver.omega)
    mu_t = 2.0 * math.pi / length / omega
    assert math.isclose(mu_omega, mu_psi / (mu_t * h1), rel_tol=5e-3)
    assert math.isclose(mu_eps, mu_omega / (mu_t * h2), rel_tol=5e-3)
    # The ψ ordinates are the rocker's swing at μψ: its unwrapped angle's span over the turn.
    motion = graphplan.solve(graphplan.load(FIXTURES / "ratchet_crank_rocker.toml"),
                             driver=np.radians(np.arange(0.0, 360.0, 0.1)))
    swing = np.ptp(np.unwrap(motion.link(4).angle))
    assert math.isclose(np.ptp(record.s), swing, rel_tol=1e-3)


def test_a_slider_s_diagrams_keep_mu_s_mu_v_mu_a():
    record = _record("engine_slider_crank")
    svg = diagrams.diagrams_svg(record)
    assert record.translating
    assert "μs = " in svg and "μv = μs/(μt·H₁)" in svg and "μa = μv/(μt·H₂)" in svg
    assert "μψ" not in svg


def test_the_russian_and_chinese_rocker_diagrams_write_mu_psi_too():
    for locale in ("ru", "zh"):
        _, svg = _rocker_diagrams(locale)
        assert "μψ = " in svg and "μω = μψ/(μt·H₁)" in svg and "με = μω/(μt·H₂)" in svg


# A knee-lever press (crank 2, RRR 3-4, RRP 5-6 pinned at the knee B), its press force over the last 30 % of the
# down-stroke: a student's scene, written from the docs alone.
KNEE_PRESS = """
[scene]
title = "肘杆压力机"
locale = "zh"
gravity = 9.81
[frame]
link = 1
points = { O = [0.48, 0.28], C = [0.0, 0.60] }
lines = { ram = { through = [0.0, 0.0], angle = -90.0 } }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.06
rpm = -90.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.40, 0.30]
near = [0.08, 0.32]
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["B", "D"]
length = 0.32
guide = "ram"
assembly = "forward"
[points]
S3 = { link = 3, from = "A", toward = "B", at = 0.20 }
S4 = { link = 4, from = "C", toward = "B", at = 0.15 }
S5 = { link = 5, from = "B", toward = "D", at = 0.16 }
[links.2]
mass = 8.0
centre = "O"
inertia = 0.04
[links.3]
mass = 10.0
centre = "S3"
inertia = 0.15
[links.4]
mass = 8.0
centre = "S4"
inertia = 0.07
[links.5]
mass = 9.0
centre = "S5"
inertia = 0.08
[links.6]
mass = 40.0
centre = "D"
[[loads]]
kind = "force"
link = 6
point = "D"
angle = 90.0
resisting = true
diagram = [[0.7, 0.0], [0.85, 15000.0], [1.0, 30000.0]]
[[friction]]
joint = "D"
links = [6, 1]
f = 0.1
[[friction]]
joint = "O"
f = 0.08
radius = 0.03
[[friction]]
joint = "C"
f = 0.08
radius = 0.03
[positions]
count = 12
start = "extreme"
working = { link = 6, sense = "forward" }
plans = [5, 6]
[drawing]
velocity_pole = 100.0
acceleration_pole = 100.0
sheet = "A1"
"""


def test_a_load_diagram_is_drawn_smaller_beside_a_force_sheet_rather_than_alone_on_a_sheet(tmp_path):
    scene = graphplan.load_text(KNEE_PRESS)
    done = scene.write(tmp_path / "press", only=["sheets", "load_diagrams"])
    sheets = sorted(path for path in map(Path, done.files) if path.name.startswith("sheet_"))
    holding = [flat(path.read_text(encoding="utf-8")) for path in sheets if 'id="load-diagrams' in path.read_text("utf-8")]
    assert len(holding) == 1
    # At its usual 150 by 60 mm it took an A1 of its own; it stands beside a force sheet's drawings instead.
    assert 'id="forces-' in holding[0]
    # Drawn smaller, at the standard scales it states: the ram's stroke within 120 mm and the 30 kN within 45 mm.
    drawn = holding[0][holding[0].index('id="load-diagrams'):]
    motion = graphplan.solve(scene, driver=np.radians(np.arange(0.0, 360.0, 0.05)))
    stroke = float(np.ptp(motion.point("D").r[:, 1]))
    mu_f = _number(r"μF = " + NUMBER + r" N/mm", drawn)
    mu_s = _number(r"μs = " + NUMBER + r" m/mm", drawn)
    assert math.isclose(_number(r"H = " + NUMBER + " m", drawn), stroke, rel_tol=1e-3)
    assert stroke / mu_s <= 120.0 + 1e-6 and 30000.0 / mu_f <= 45.0 + 1e-6
    assert stroke / mu_s > 150.0 / 5 and 30000.0 / mu_f > 45.0 / 5   # not shrunk past what the room needs


def test_each_ringed_load_value_names_its_position_and_is_the_load_there():
    from graphplan import load_diagrams
    from graphplan.render import load_diagrams as layout
    from graphplan.render.primitives import Text

    scene = graphplan.load_text(KNEE_PRESS)
    (diagram,) = load_diagrams.of_analysis(scene.analyse())
    texts = [item.text for layer in layout.parts([diagram], strings("zh"))[0] for item in layer.items
             if isinstance(item, Text)]
    written = {int(found.group(2)): float(found.group(1)) for text in texts
               if (found := re.fullmatch(r"F6 = " + NUMBER + r" N \((\d+)\)", text))}
    assert sorted(written) == [5, 6]
    # The press force at each plan position from the ram's share of its down-stroke, read off the scene's diagram.
    motion = graphplan.solve(scene, driver=np.radians(np.arange(0.0, 360.0, 0.01)))
    heights = motion.point("D").r[:, 1]
    top, bottom = heights.max(), heights.min()
    analysis = scene.analyse()
    for number, value in written.items():
        position = next(plan for plan in analysis.plans if plan.number == number)
        at_position = analysis.motion.driver[position.index:position.index + 1]
        ram = graphplan.solve(scene, driver=at_position).point("D").r[0, 1]
        share = (top - ram) / (top - bottom)
        expected = float(np.interp(share, [0.7, 0.85, 1.0], [0.0, 15000.0, 30000.0], left=0.0, right=0.0))
        assert math.isclose(value, expected, rel_tol=1e-3)


def test_the_legend_of_the_position_numbers_keeps_the_load_diagram_as_wide_as_its_longest_line_was():
    """The ring's legend said "(the position in brackets)" after its words: the Russian line ran 47 mm past the
    diagram, and the ratchet's and the tangent mechanism's load diagrams left the force sheet they had shared for an
    A1 of their own.  The bracket is told on a line of its own, no longer than the ring's."""
    from graphplan import load_diagrams
    from graphplan.render import load_diagrams as layout
    from graphplan.render.primitives import Text, text_width

    for fixture, locale in (("ratchet_crank_rocker", "ru"), ("tangent_mechanism_prp", "en"),
                            ("ratchet_crank_rocker", "zh")):
        scene = graphplan.load(FIXTURES / f"{fixture}.toml")
        words = strings(locale)
        diagrams = load_diagrams.of_analysis(scene.analyse())
        texts = [item for layer in layout.parts(diagrams, words)[0] for item in layer.items if isinstance(item, Text)]
        ring, number = (next(item for item in texts if item.text == words[key])
                        for key in ("ld_plans", "ld_plans_number"))
        assert number.at[1] < ring.at[1]   # under the ring's line
        assert text_width(number.text, number.size) <= text_width(ring.text, ring.size)
        assert "(k)" in [item.text for item in texts]


def test_the_fixtures_load_diagrams_stand_beside_a_force_sheet(tmp_path):
    for fixture in ("ratchet_crank_rocker", "tangent_mechanism_prp"):
        done = graphplan.load(FIXTURES / f"{fixture}.toml").write(tmp_path / fixture, only=["sheets", "load_diagrams"])
        sheets = [Path(path).read_text(encoding="utf-8") for path in done.files if Path(path).name.startswith("sheet_")]
        (holding,) = [sheet for sheet in sheets if 'id="load-diagrams' in sheet]
        assert 'id="forces-' in holding, fixture
