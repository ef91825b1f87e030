"""The velocity and acceleration plans, as constructed, against the analytic solution.

The plans are built from the positions of one instant and the driver's motion alone (lines of
action crossed, similar figures); the analytic solver never meets them.  Here, and only here,
the two are compared: for every fixture and every one of its positions (not only
``positions.plans``), the image of every point, ω and ε of every link and the relative sliding
velocity and acceleration of every sliding pair a group records.  Each quantity must agree to
1e-9 of the largest magnitude of its kind at that position (velocities of points, accelerations
of points, ω, and the acceleration plan's figure ratio √(ε² + ω⁴) for ε), so that a value that
happens to be near zero is held to the plan's own precision rather than to itself.

Variants written inline cover what no fixture has: guides on moving links for RRP, RPP and a
triad's sliding leg, a PRP
between two moving links with offsets, an RPR whose slot misses its pivot and whose pivot moves,
and a driver with angular acceleration.

Besides: the Coriolis component of the slotted-lever and shaper plans (its vector and its sense),
the similarity of off-line points (orientation kept, ratio |ω| or √(ε² + ω⁴)), and positions
where two lines of action are parallel, which raise instead of returning a guess.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import re
from pathlib import Path

import numpy as np
import pytest
from test_motion_against_finite_differences import (
    _HUNG_ON_THE_RATCHET as GROUPS_ON_THE_RATCHET,
)
from test_motion_against_finite_differences import square_guides

import graphplan
from graphplan import check, plans
from graphplan.analysis import analyse, instant
from graphplan.geometry import ParallelLinesError
from graphplan.mechanism import build
from graphplan.scene import loads

FIXTURE_DIR = Path(__file__).resolve().parent.parent / "fixtures"
FIXTURES = sorted(FIXTURE_DIR.glob("*.toml"))
RELATIVE = 1e-9

# A point of a moving link named P gets the plan letter p, which is the pole's: the plan then
# moves its pole (see test_a_point_named_p_leaves_the_pole_at_rest).  For the comparison such a
# point is renamed, which changes nothing of the mechanism.
_NAMED_P = re.compile(r"(?m)^P(?=\s*=\s*\{)")


def _fixture_text(path: Path) -> str:
    text = path.read_text(encoding="utf-8")
    if _NAMED_P.search(text):
        text = _NAMED_P.sub("PL", text).replace('"P"', '"PL"')
    return text


_RATCHET = (FIXTURE_DIR / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")

# Groups hung on the ratchet crank-rocker (links 1–4; E on the coupler 3, S4 on the rocker 4): the
# finite-difference tests' variants, each given an off-line named point for the similarity test,
# and one more for a lever turning about a moving pivot with an offset slot.
_OFF_LINE_POINT = {
    "ratchet+RRP-on-rocker": 'F5 = { link = 5, from = "E", toward = "K", at = 0.2, offset = 0.05 }',
    "ratchet+RPP-on-rocker": 'F6 = { link = 6, from = "K", toward = "E", at = 0.1, offset = 0.05 }',
    "ratchet+PRP-rocker-coupler": "",
    "ratchet+triad-slider-on-rocker": 'M8 = { link = 8, from = "G", toward = "K", at = 0.05, offset = 0.04 }',
    "ratchet+triad-two-sliders": 'M8 = { link = 8, from = "G", toward = "K", at = 0.05, offset = 0.04 }',
    "ratchet+triad-three-sliders": 'M8 = { link = 8, from = "G", toward = "K", at = 0.05, offset = 0.04 }',
    "ratchet+triad-slot": 'M8 = { link = 8, from = "G", toward = "K", at = 0.05, offset = 0.04 }',
    "ratchet+triad-slot-and-guide": 'M8 = { link = 8, from = "G", toward = "K", at = 0.05, offset = 0.04 }',
    # A point of the ternary link placed toward the block's pin along the slot.
    "ratchet+triad-two-slots": 'M8 = { link = 8, from = "G", toward = "E", at = 0.05, offset = 0.04 }',
}
_HUNG_ON_THE_RATCHET = {name: (GROUPS_ON_THE_RATCHET[name], point) for name, point in _OFF_LINE_POINT.items()}
_HUNG_ON_THE_RATCHET["ratchet+RPR-moving-pivot-offset"] = ("""
[[groups]]
kind = "RPR"
links = [5, 6]
joints = ["E", "S4"]
offset = 0.02
""", 'G6 = { link = 6, from = "S4", toward = "E", at = 0.1, offset = 0.04 }')


def _hung(name: str):
    group, points = _HUNG_ON_THE_RATCHET[name]
    assert _RATCHET.count("\n[points]") == 1
    return loads(_RATCHET.replace("\n[points]", f"{group}\n[points]\n{points}"))


def _with_epsilon(path: Path, epsilon: float):
    scene = loads(_fixture_text(path))
    return dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, epsilon=epsilon))


def _offset_slot():
    scene = graphplan.load(FIXTURE_DIR / "quick_return_slotted_lever.toml")
    (lever,) = scene.groups
    return dataclasses.replace(scene, groups=(dataclasses.replace(lever, offset=0.04),))


CASES = {path.stem: functools.partial(lambda p: loads(_fixture_text(p)), path) for path in FIXTURES}
CASES |= {name: functools.partial(_hung, name) for name in _HUNG_ON_THE_RATCHET}
CASES["quick_return+slot-offset"] = _offset_slot
CASES["triad_with_slider+square-guides"] = square_guides
CASES["shaper+crank-epsilon"] = functools.partial(_with_epsilon, FIXTURE_DIR / "shaper_six_bar.toml", -4.0)
CASES["tangent+crank-epsilon"] = functools.partial(_with_epsilon, FIXTURE_DIR / "tangent_mechanism_prp.toml", 2.5)


@functools.cache
def analysed(case: str):
    return analyse(CASES[case]())


@functools.cache
def constructed(case: str, index: int):
    """Both plans of one position, built exactly as the analysis builds them, and the exact values there."""
    a = analysed(case)
    m, mo = a.mechanism, a.motion

    def at(value) -> complex:
        return complex(np.atleast_1d(value)[index if np.ndim(value) else 0])

    pos = {n: at(p.r) for n, p in mo.points.items()}
    dirs = {n: at(l.u) for n, l in mo.links.items()}
    vp = plans.velocity_plan(m, pos, dirs)
    ap = plans.acceleration_plan(m, pos, dirs, vp)
    exact = {
        "v": {n: at(p.v) for n, p in mo.points.items()},
        "a": {n: at(p.a) for n, p in mo.points.items()},
        "omega": {n: at(l.omega).real for n, l in mo.links.items() if n != m.scene.frame_link},
        "epsilon": {n: at(l.epsilon).real for n, l in mo.links.items() if n != m.scene.frame_link},
        "slides": [(s.slider, s.guide, s.joint, at(s.velocity * s.u), at(s.acceleration * s.u)) for s in mo.slides],
    }
    return m, pos, dirs, vp, ap, exact


def _positions(case: str) -> int:
    return analysed(case).motion.count


# The positions from each scene's count, which the analysis keeps (checked below): analysing the 28 cases to count
# them took six seconds of each worker's collection, analyses the module's worker makes again once it runs them.
ALL = [pytest.param(case, i, id=f"{case}-{i}") for case in CASES for i in range(CASES[case]().positions.count)]


def _close(found: complex, expected: complex, scale: float, what: str) -> None:
    assert abs(found - expected) <= RELATIVE * scale, f"{what}: plan {found}, analytic {expected} (scale {scale:.3g})"


@pytest.mark.parametrize(("case", "index"), ALL)
def test_every_image_rate_and_slide_agrees_with_the_analytic_solution(case, index):
    m, _, _, vp, ap, exact = constructed(case, index)
    v_scale = max(abs(v) for v in exact["v"].values())
    a_scale = max(abs(a) for a in exact["a"].values())
    for name in exact["v"]:
        _close(vp.value(name), exact["v"][name], v_scale, f"v{name}")
        _close(ap.value(name), exact["a"][name], a_scale, f"a{name}")
    omega_scale = max(abs(w) for w in exact["omega"].values())
    ratio_scale = max(math.hypot(exact["epsilon"][n], exact["omega"][n] ** 2) for n in exact["omega"])
    for link in m.moving_links:
        _close(vp.rates[link], exact["omega"][link], omega_scale, f"ω{link}")
        _close(ap.rates[link], exact["epsilon"][link], ratio_scale, f"ε{link}")
    for slider, guide, joint, velocity, acceleration in exact["slides"]:
        if slider == m.driver.link:
            continue  # the driver's own slide is given, not constructed
        assert slider in vp.sliding and slider in ap.sliding, f"link {slider}'s slide on link {guide} is not recorded"
        _close(vp.sliding[slider], velocity, v_scale, f"v rel of link {slider} on link {guide} at {joint}")
        _close(ap.sliding[slider], acceleration, a_scale, f"a rel of link {slider} on link {guide} at {joint}")


SLIDING_FIXTURES = ["scotch_yoke", "tangent_mechanism_prp"]


@functools.cache
def _a_group_slides(case: str) -> bool:
    """Whether a group of the case has a sliding pair, read off the scene (the analysis agrees, checked above)."""
    return any("P" in group.kind or (group.kind == "triad" and (any(group.leg_guides) or any(group.leg_slots)))
               for group in CASES[case]().groups)


@pytest.mark.parametrize(("case", "index"), [p for p in ALL if _a_group_slides(p.values[0])])
def test_the_tables_read_every_sliding_pair_as_the_analytic_slides(case, index):
    # Each sliding pair of a group is read off both plans along its guide (the relative velocity, and the
    # relative acceleration a^r laid after any Coriolis part), and that reading, and the exact value the
    # table sets beside it, are the analytic Motion.slides.
    m, pos, _, vp, ap, exact = constructed(case, index)
    plans_ = {"velocity": vp, "acceleration": ap}
    table = check.readings(m, plans_, pos)
    values = check.analytic_values(m, table, exact["v"], exact["a"], exact["omega"] | {m.scene.frame_link: 0.0},
                                   exact["epsilon"] | {m.scene.frame_link: 0.0})
    v_scale = max(abs(v) for v in exact["v"].values())
    a_scale = max(abs(a) for a in exact["a"].values())
    for slider, guide, joint, velocity, acceleration in exact["slides"]:
        if slider == m.driver.link:
            continue
        for kind, expected, scale in (("velocity", velocity, v_scale), ("acceleration", acceleration, a_scale)):
            (reading,) = [r for r in table if r.plan == kind and r.slide is not None and r.slide.slider == slider]
            assert reading.slide.guide == guide
            what = f"{reading.quantity} (link {slider} on link {guide} at {joint})"
            _close(reading.value(plans_), abs(expected), scale, what)
            _close(values[reading.quantity], abs(expected), scale, f"exact {what}")
            if kind == "acceleration":
                assert reading.quantity.endswith("^r"), reading.quantity


def test_each_slide_is_read_off_its_own_vector_even_where_two_slides_are_equal():
    # At the tangent mechanism's extreme both of B's slides vanish: vBB4 = vBB1 = 0.  Found by their value, both
    # readings took the first zero vector laid along a guide (b4 → b), and the slide on the frame (p → b) was
    # read as link 5's; they are found by the letters their group recorded.
    m, pos, _, vp, ap, _ = constructed("tangent_mechanism_prp", 0)
    equal = dataclasses.replace(vp, points={**vp.points, "b": 0j, "b4": 0j})  # both of B's slides exactly zero
    assert equal.sliding[5] == equal.sliding[6] == 0j
    table = check.readings(m, {"velocity": equal, "acceleration": ap}, pos)
    read = {r.slide.slider: set(r.segment) for r in table if r.plan == "velocity" and r.slide is not None}
    assert read == {slider: set(ends) for slider, ends in vp.slide_ends.items()}
    assert read[5] == {"b4", "b"} and read[6] == {"p", "b"}


@pytest.mark.parametrize("case", SLIDING_FIXTURES)
def test_the_rpp_and_prp_error_tables_carry_their_sliding_rows(case):
    expected = {"scotch_yoke": {"VA4A3", "VA4A1", "aA4A3^r", "aA4A1^r"},
                "tangent_mechanism_prp": {"VA4A3", "VBB4", "VBB1", "aA4A3^r", "aBB4^r", "aBB1^r"}}[case]
    for plan in analysed(case).plans:
        construction = {row.quantity: row for row in plan.errors if row.source == "construction"}
        assert expected <= set(construction), sorted(construction)
        for quantity in expected:
            assert abs(construction[quantity].percent) < 1e-6, construction[quantity]


@pytest.mark.parametrize("case", list(CASES))
def test_every_case_has_its_positions_and_its_plans_record_equations(case):
    a = analysed(case)
    assert a.motion.count == a.scene.positions.count
    assert _a_group_slides(case) == any(slide.slider != a.mechanism.driver.link for slide in a.motion.slides)
    _, _, _, vp, ap, _ = constructed(case, 0)
    for plan in (vp, ap):
        assert all(step.equation for step in plan.steps)
        for step in plan.steps:
            for vector in step.vectors:
                assert vector.start in plan.points and vector.end in plan.points, (step.equation, vector)
            for line in step.lines:
                assert line.through in plan.points, (step.equation, line)
            assert set(step.fixes) <= set(plan.points)


# The Coriolis component: the slotted lever, the shaper, and the tangent mechanism (two of them).

def _vector(plan, meaning: str) -> tuple[complex, str, str]:
    found = [(plan.points[v.end] - plan.points[v.start], v.start, v.end)
             for step in plan.steps for v in step.vectors if v.meaning == meaning]
    assert len(found) == 1, f"{meaning} laid {len(found)} times"
    return found[0]


CORIOLIS_CASES = ["quick_return_slotted_lever", "shaper_six_bar", "shaper+crank-epsilon"]


@pytest.mark.parametrize(("case", "index"), [p for p in ALL if p.values[0] in CORIOLIS_CASES])
def test_the_coriolis_component_of_the_lever_is_present_with_its_sense(case, index):
    m, pos, _, _, ap, exact = constructed(case, index)
    (rpr,) = [g for g in m.groups if g.kind == "RPR"]
    block, lever = rpr.links
    omega = exact["omega"][lever]
    # The lever's point A4 relative to the block's point A (A3), from the analytic solution.
    v_rel = exact["v"][rpr.coincident] - exact["v"]["A"]
    expected = 2j * omega * v_rel
    vector, start, end = _vector(ap, f"aA{lever}A{block}ᵏ")
    assert (start, end) == ("a", "k"), "the Coriolis component is laid from a and ends at k"
    a_scale = max(abs(a) for a in exact["a"].values())
    _close(vector, expected, a_scale, "aᵏ")
    if abs(expected) > 1e-6 * a_scale:  # it vanishes only at the lever's extremes, where ω4 = 0
        # Its sense: the relative velocity turned by 90° in the sense of ω4.
        turned = (np.conj(v_rel) * vector).imag
        assert math.copysign(1.0, turned) == math.copysign(1.0, omega)
        assert abs((np.conj(v_rel) * vector).real) <= 1e-9 * abs(v_rel) * abs(vector)
    # The relative acceleration runs from k along the slot to a4, and is the block's slide, reversed.
    relative, start, end = _vector(ap, f"aA{lever}A{block}^r")
    assert (start, end) == ("k", "a4")
    u = (pos["A"] - pos["C"]) / abs(pos["A"] - pos["C"])
    assert abs((np.conj(u) * relative).imag) <= 1e-9 * a_scale
    (slide,) = [s for s in exact["slides"] if s[0] == block]
    _close(-relative, slide[4], a_scale, "aA3A4^r")
    _close(vector, -2j * omega * slide[3], a_scale, "aA4A3ᵏ = −2·ω4 × vA3A4")


@pytest.mark.parametrize("case", CORIOLIS_CASES)
def test_the_coriolis_component_vanishes_only_at_the_levers_extremes(case):
    sizes = []
    for index in range(_positions(case)):
        _, _, _, _, ap, exact = constructed(case, index)
        vector, _, _ = _vector(ap, "aA4A3ᵏ")
        sizes.append(abs(vector) / max(abs(a) for a in exact["a"].values()))
    assert sum(size > 1e-2 for size in sizes) >= len(sizes) - 2, sizes


def test_two_coriolis_components_are_lettered_by_their_sliders():
    # The tangent mechanism: block 3 on lever 4 (RPR), block 5 in the lever's upper slot (PRP).
    _, _, _, _, ap, exact = constructed("tangent_mechanism_prp", 3)
    assert "k" not in ap.points and {"k3", "k5"} <= set(ap.points)
    vector, start, end = _vector(ap, "aBB4ᵏ")
    assert (start, end) == ("b4", "k5")
    (slide,) = [s for s in exact["slides"] if s[0] == 5]  # block 5 relative to lever 4, analytic
    _close(vector, 2j * exact["omega"][4] * slide[3], max(abs(a) for a in exact["a"].values()), "aBB4ᵏ")
    assert abs(vector) > 1e-2 * max(abs(a) for a in exact["a"].values())
    # The ram slides on the frame: no Coriolis term on its side.
    assert not [v for s in ap.steps for v in s.vectors if v.meaning == "aBB1ᵏ"]


def test_a_frame_guide_has_no_coriolis_term():
    for case in ("engine_slider_crank", "offset_slider_crank", "scotch_yoke"):
        _, _, _, _, ap, _ = constructed(case, 2)
        assert not [v for s in ap.steps for v in s.vectors if "ᵏ" in v.meaning], case
        assert not any(letter.startswith("k") for letter in ap.points), case


# The similarity theorem: images of off-line points keep the figure's orientation.

TRIANGLES = [
    # case, link, three (point name or (position name, plan letter)) of the link
    ("ratchet_crank_rocker", 3, ("A", "B", "E")),
    ("stephenson_six_bar", 3, ("A", "B", "E")),
    ("slider_driven", 4, ("C", "B", "E")),
    ("ratchet+RRP-on-rocker", 5, ("E", "K", "F5")),
    ("ratchet+RPP-on-rocker", 6, ("K", ("E", "e6"), "F6")),
    ("ratchet+RPR-moving-pivot-offset", 6, ("S4", "E6", "G6")),
]


@pytest.mark.parametrize(("case", "link", "names"), TRIANGLES, ids=[f"{t[0]}-{t[1]}" for t in TRIANGLES])
def test_similar_images_keep_the_orientation_and_the_ratio(case, link, names):
    for index in range(_positions(case)):
        _, pos, _, vp, ap, exact = constructed(case, index)
        figure = [pos[n] if isinstance(n, str) else pos[n[0]] for n in names]
        orientation = (np.conj(figure[1] - figure[0]) * (figure[2] - figure[0])).imag
        assert abs(orientation) > 1e-6, "the three points must not lie in a line"
        omega, epsilon = exact["omega"][link], exact["epsilon"][link]
        for plan, ratio in ((vp, abs(omega)), (ap, math.hypot(epsilon, omega**2))):
            image = [plan.value(n) if isinstance(n, str) else plan.points[n[1]] for n in names]
            turned = (np.conj(image[1] - image[0]) * (image[2] - image[0])).imag
            assert math.copysign(1.0, turned) == math.copysign(1.0, orientation), (plan.kind, index)
            for i, j in ((0, 1), (1, 2), (0, 2)):
                side = abs(image[j] - image[i]) / abs(figure[j] - figure[i])
                assert side == pytest.approx(ratio, rel=1e-9), (plan.kind, index, i, j)


# Parallel lines of action: reported, never guessed.

_TOGGLE = """
[scene]
title = "A crank-rocker drawn at its toggle"
[frame]
link = 1
points = { O = [0.0, 0.0], C = [0.5, 0.0] }
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.3, 0.3]
assembly = "left"
[positions]
count = 12
"""


def test_an_rrr_at_its_toggle_raises_instead_of_guessing():
    # At φ = 180° A(−0.1, 0), B(0.2, 0), C(0.5, 0) lie in a line: AB + BC = AC = 0.6 m, so the lines
    # ⊥ AB through a and ⊥ CB through the pole are parallel.
    mechanism = build(loads(_TOGGLE))
    positions = {"O": 0j, "C": 0.5 + 0j, "A": -0.1 + 0j, "B": 0.2 + 0j}
    directions = {1: 1 + 0j, 2: -1 + 0j, 3: 1 + 0j, 4: -1 + 0j}
    with pytest.raises(ParallelLinesError, match="⊥AB and ⊥CB are parallel"):
        plans.velocity_plan(mechanism, positions, directions)


def test_an_rrp_with_its_rod_square_to_the_guide_raises():
    # The engine drawn with the rod standing square to the cylinder axis (a dead point of the
    # RRP): ⊥ AB through a and the axis through the pole are parallel.
    mechanism = build(loads(_fixture_text(FIXTURE_DIR / "engine_slider_crank.toml")))
    a = 0.05 * complex(math.cos(1.0), math.sin(1.0))
    positions = {"O": 0j, "A": a, "B": complex(a.real, 0.0), "S2": 0.006 * a / abs(a), "S3": a}
    directions = {1: 1 + 0j, 2: a / abs(a), 3: -1j, 4: 1 + 0j}
    with pytest.raises(ParallelLinesError, match="⊥AB and ∥ guide"):
        plans.velocity_plan(mechanism, positions, directions)


def test_a_prp_with_parallel_guides_raises():
    # The tangent mechanism drawn with the lever's slot turned parallel to the ram's guide.
    m, pos, dirs, _, _, _ = constructed("tangent_mechanism_prp", 3)
    directions = dict(dirs) | {4: 1 + 0j}
    with pytest.raises(ParallelLinesError, match="∥ guide on link 4 and ∥ ram are parallel"):
        plans.velocity_plan(m, pos, directions)


# A point that shares the pole's letter.

def test_a_point_named_p_leaves_the_pole_at_rest():
    a = analyse(graphplan.load(FIXTURE_DIR / "scotch_yoke.toml"))
    mo = a.motion
    index = 3  # the yoke moving: vP ≠ 0
    pos, dirs = instant(mo, index)
    vp = plans.velocity_plan(a.mechanism, pos, dirs)
    assert vp.value("O") == 0
    assert vp.value("P") == pytest.approx(complex(np.atleast_1d(mo.points["P"].v)[index]), rel=1e-9)


def test_the_yoke_keeps_its_figure_when_the_block_sits_on_the_guide():
    # At the yoke's extreme the crank pin A lies on the guide line, where B is: link 4's two images
    # a4 and b then stand for one place, and its named points need another point of it.
    m, pos, dirs, _, _, _ = constructed("scotch_yoke", 0)
    positions = dict(pos) | {"A": pos["B"]}  # exactly
    velocity = plans.velocity_plan(m, positions, dirs)
    acceleration = plans.acceleration_plan(m, positions, dirs, velocity)
    for plan in (velocity, acceleration):
        assert plan.value("S4") == plan.value("PL") == plan.value("B") == plan.points["a4"]
        assert plan.rates[4] == 0.0 and plan.rates[3] == 0.0


def test_link_b_of_an_rpp_on_a_turning_guide_keeps_its_figure_when_the_block_sits_on_b():
    # The block's pin E drawn exactly on the crossing K of the slot and the rocker's guide: link 6
    # then carries its figure by a further point, and F6 follows link 6's rotation, which is the rocker's.
    m, pos, dirs, _, _, _ = constructed("ratchet+RPP-on-rocker", 4)
    positions = dict(pos) | {"E": pos["K"]}
    velocity = plans.velocity_plan(m, positions, dirs)
    acceleration = plans.acceleration_plan(m, positions, dirs, velocity)
    for plan, ratio in ((velocity, 1j * velocity.rates[4]),
                        (acceleration, 1j * acceleration.rates[4] - velocity.rates[4] ** 2)):
        assert plan.rates[6] == pytest.approx(plan.rates[4], rel=1e-12)
        assert plan.rates[5] == pytest.approx(plan.rates[4], rel=1e-12)
        expected = plan.value("K") + ratio * (positions["F6"] - positions["K"])
        assert plan.value("F6") == pytest.approx(expected, rel=1e-9, abs=1e-12)
