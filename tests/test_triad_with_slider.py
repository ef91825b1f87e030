"""A triad whose third leg slides: what the tests that run every fixture and variant cannot show.

Those already hold fixtures/triad_with_slider.toml (a slider on a frame guide) and the ratchet's
variant ``ratchet+triad-slider-on-rocker`` (a slider on the rocking link 4, so with a Coriolis
term) to their closure, finite differences, the 50-digit reference, the plans against the analytic
solution and the force polygons against the linear system of statics.  Here: the structure, Assur's
point on the two turning legs, the Coriolis component itself, the guide's reaction, the sliding leg
listed first or second, every kind of bad input.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from test_forces_against_statics import loaded
from test_motion_against_finite_differences import CASES

import graphplan
from graphplan.analysis import analyse, instant
from graphplan.cli import main
from graphplan.errors import AssemblyError, SceneError
from graphplan.forces import force_plan
from graphplan.kinematics import cross
from graphplan.loads import activity, link_loads, plan_state
from graphplan.plans import acceleration_plan, coriolis, velocity_plan
from graphplan.render import positions
from graphplan.render.drawings import positions_plan
from graphplan.render.primitives import Circle, Polyline
from graphplan.scene import loads

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "triad_with_slider.toml"
TEXT = FIXTURE.read_text(encoding="utf-8")
GUIDES = "guides  = { F = { angle = -30.0 } }"
LENGTHS = "lengths = [0.17, 0.14]"
assert GUIDES in TEXT and LENGTHS in TEXT


def _scene(old: str = "", new: str = ""):
    assert old in TEXT
    return loads(TEXT.replace(old, new))


def _xy(value) -> complex:
    return complex(value[0], value[1])


def plans_at(analysis, index: int):
    """Position ``index`` of the analysis's motion: its points, its links' directions, and its velocity and
    acceleration plans constructed afresh."""
    mechanism = analysis.mechanism
    where, directions = instant(analysis.motion, index)
    velocity = velocity_plan(mechanism, where, directions)
    return where, directions, velocity, acceleration_plan(mechanism, where, directions, velocity)


def laid_once(plan, meaning: str) -> complex:
    """The vector ``meaning`` as ``plan`` lays it: laid, and wherever laid between the same two points."""
    laid = [vector for step in plan.steps for vector in step.vectors if vector.meaning == meaning]
    assert laid and len({(vector.start, vector.end) for vector in laid}) == 1, meaning
    return plan.points[laid[0].end] - plan.points[laid[0].start]


def forces_at(analysis, acting, index: int):
    """Position ``index``'s points and directions, the loads from its plans (``acting`` the scene's loads' activity)
    and the force analysis drawn from them."""
    mechanism = analysis.mechanism
    where, directions, velocity, acceleration = plans_at(analysis, index)
    applied = link_loads(mechanism, plan_state(mechanism, where, velocity, acceleration), acting[:, index:index + 1])
    return where, directions, applied, force_plan(mechanism, where, directions, applied)


def moment_about(applied, link: int, where, pin: str) -> float:
    """ΣM of ``link``'s loads among ``applied`` about the point ``pin`` (``where`` the points' positions)."""
    return sum(float(load.moment) if load.point is None else
               float(cross(where[load.point] + load.offset - where[pin], complex(load.force)))
               for load in applied if load.link == link)


def test_the_slider_makes_the_triad_a_class_iii_group_with_one_sliding_pair():
    mechanism = graphplan.build(graphplan.load(FIXTURE))
    assert mechanism.structure == "I(1,2) → III3(3,4,5,6)"
    # W = 3n − 2p5: n = 5 moving links, p5 = the crank's pair + the triad's six (five turning, one sliding)
    assert mechanism.degrees_of_freedom == (5, 7, 1)
    assert 5 in mechanism.translating
    motion = graphplan.solve(graphplan.load(FIXTURE))
    assert np.all(motion.link(5).omega == 0) and np.all(motion.link(5).epsilon == 0)
    (slide,) = motion.slides
    assert (slide.slider, slide.guide, slide.joint) == (5, 1, "F")


def _sine(u: complex, w: complex) -> float:
    return abs((u.conjugate() * w).imag) / (abs(u) * abs(w))


def test_assurs_point_is_where_two_legs_lines_cross_at_the_widest_angle():
    """Σ lies on AB, CD, or the normal to the slider's guide at F (Σ's velocity relative to the guide's point
    under F is then along the guide): on the two of them that cross at the widest angle."""
    analysis = analyse(graphplan.load(FIXTURE))
    guide = np.exp(1j * np.radians(-30.0))
    widths = []
    for plan_position in analysis.plans:
        positions = plan_position.positions
        ((name, sigma),) = plan_position.velocity.auxiliary.items()
        assert name == "Σ6"
        lines = {"AB": (positions["B"], positions["B"] - positions["A"]),
                 "CD": (positions["D"], positions["D"] - positions["C"]),
                 "normal at F": (positions["F"], 1j * guide)}
        pairs = [("AB", "CD"), ("AB", "normal at F"), ("CD", "normal at F")]
        widest = max(pairs, key=lambda pair: _sine(lines[pair[0]][1], lines[pair[1]][1]))
        widths.append(widest)
        for through, direction in (lines[widest[0]], lines[widest[1]]):
            assert _sine(direction, sigma - through) <= 1e-9, (plan_position.number, widest)
        # F moves along the guide, at −30°, however its image was found.
        v_f = plan_position.velocity.value("F")
        assert abs((guide.conjugate() * v_f).imag) <= 1e-12 * abs(v_f)
    assert any("normal at F" in pair for pair in widths), "the fixture's plans go through the guide's normal"


def test_a_slider_on_a_rocking_guide_gets_its_coriolis_component_from_the_plans():
    # The ratchet's variant: slider 7 pinned to the ternary link 8 at L runs on the guide of rocker 4.
    analysis = analyse(CASES["ratchet+triad-slider-on-rocker"]())
    motion = analysis.motion
    checked = 0
    for index in range(motion.count):
        _, _, velocity, acceleration = plans_at(analysis, index)
        # Laid once, where L is crossed with the guide, or where Σ is on the guide's normal at L (and read off again).
        drawn = laid_once(acceleration, "aLL4ᵏ")
        # 2·ω4 × v_rel from the analytic motion: ω4 of the rocker, v_rel of L along the guide.
        omega = float(motion.link(4).omega[index])
        (slide,) = [s for s in motion.slides if s.slider == 7]
        relative = complex(slide.velocity[index] * slide.u[index])
        expected = 2j * omega * relative
        assert abs(drawn - expected) <= 1e-9 * max(abs(expected), 1e-3)  # at the rocker's extremes ω4 = 0
        assert drawn == pytest.approx(coriolis(velocity.rates[4], velocity.sliding[7]), abs=1e-12)
        checked += abs(expected) > 0.1
    assert checked >= 4


def test_the_guides_reaction_is_square_to_it_and_shifted_by_the_sliders_moment():
    analysis = analyse(graphplan.load(FIXTURE))
    for plan_position in analysis.plans:
        reactions = plan_position.forces.reactions
        normal = reactions["R15"]
        assert normal.joint == "F" and normal.source == 1 and normal.target == 5
        u = np.exp(1j * np.radians(-30.0))
        assert abs((u.conjugate() * normal.force).real) <= 1e-12 * abs(normal.force)
        # The slider's loads all act at its pin F: the normal reaction passes through F.
        assert normal.offset == pytest.approx(0.0, abs=1e-15)
    # On a turning guide the slider's inertia moment turns it about its pin: the guide's reaction then acts
    # x along the guide from the pin, where its moment about the pin balances the slider's loads.
    variant = analyse(loaded(CASES["ratchet+triad-slider-on-rocker"]()))
    mechanism, motion = variant.mechanism, variant.motion
    acting = activity(mechanism, variant.positions, motion)
    shifted = 0
    for index in range(0, motion.count, 2):
        where, directions, applied, drawn = forces_at(variant, acting, index)
        normal = drawn.reactions["R47"]
        u = directions[4] * np.exp(1j * np.radians(60.0))
        assert abs((u.conjugate() * normal.force).real) <= 1e-9 * abs(normal.force)
        turning = moment_about(applied, 7, where, "L")
        assert turning != 0.0
        assert cross(normal.offset * u, normal.force) == pytest.approx(-turning, rel=1e-9, abs=1e-12)
        shifted += abs(normal.offset) > 1e-6
    assert shifted


@pytest.mark.parametrize(("old", "new", "where", "message"), [
    (GUIDES, "guides = { F = { angle = -30.0 }, D = { angle = 0.0 }, B = { angle = 90.0 } }", "groups[0].lengths",
     "must be left out: the legs AB, CD and EF all slide"),
    (GUIDES, "guides = { }", "groups[0].guides", "must name the legs that slide by their inner joints (B, D, F)"),
    (GUIDES, "guides = { F = { angle = -30.0 }, D = { angle = 110.0 } }", "groups[0].lengths",
     "must have 1 entry, lAB (the legs CD and EF slide), not 2"),
    (GUIDES, "guides = { E = { angle = -30.0 } }", "groups[0].guides.E", "must name an inner joint"),
    (GUIDES, 'guides = { F = { through = "O", angle = -30.0 } }', "groups[0].guides.F.through",
     "runs through its outer joint E"),
    (GUIDES, "guides = { F = { angel = -30.0 } }", "groups[0].guides.F.angel", "unknown key"),
    (GUIDES, "guides = { F = { link = 7, angle = 0.0 } }", "groups[0].guides.F.link", "not known before"),
    (GUIDES, "guides = { F = { link = 2, angle = 0.0 } }", "groups[0].guides.F.link",
     "runs through E, which is not on link 2: leave link out, E being a point of the frame"),
    (LENGTHS, "lengths = [0.17, 0.14, 0.2]", "groups[0].lengths", "lAB, lCD (the leg EF slides)"),
    (LENGTHS, "lengths = [0.17, -0.14]", "groups[0].lengths[1]", "must be > 0"),
])
def test_a_bad_sliding_leg_is_refused_with_its_key(old, new, where, message):
    with pytest.raises(SceneError) as caught:
        graphplan.build(_scene(old, new))
    assert caught.value.where == where and message in str(caught.value), str(caught.value)


def test_a_leg_sliding_on_a_guide_through_a_moving_joint_is_told_the_link_that_carries_it():
    # The leg AB's guide runs through A, the crank's joint: left on the frame, it is told to be on the crank, under
    # the key the scene wrote (there is no guides.B.through to write).
    text = TEXT.replace(LENGTHS, "lengths = [0.14]")
    text = text.replace(GUIDES, "guides  = { F = { angle = -30.0 }, B = { angle = 0.0 } }")
    with pytest.raises(SceneError) as caught:
        graphplan.build(loads(text))
    assert caught.value.where == "groups[0].guides.B.link"
    assert "runs through A, which is not on the frame: give link = 2, the link that carries A" in str(caught.value)
    assert "(got" not in str(caught.value)


def test_a_guide_the_triad_cannot_reach_says_so_and_writes_nothing(tmp_path, capsys):
    scene = tmp_path / "far.toml"
    scene.write_text(TEXT.replace("E = [0.0, 0.14]", "E = [0.0, 0.9]").replace("angle = -30.0 }", "angle = 0.0 }"),
                     encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert "cannot be assembled" in error and "III(3,4,5,6)" in error and "F slides on the guide through E at 0°" in error
    assert not out.exists()
    with pytest.raises(AssemblyError):
        graphplan.solve(graphplan.load(scene))


def test_the_sketch_picks_the_assembly_whose_slider_is_nearest():
    # At φ = 0 the same legs close in other assemblies too, found by moving the sketch there; they do not run
    # round the whole turn, so the scene asks for no strokes, which would solve it.
    alone = TEXT.replace('start       = "extreme"', "start = 0.0").replace(
        'working     = { link = 5, sense = "backward" }', "").replace('during    = "working"', "")
    first = graphplan.solve(loads(alone), driver=[0.0])
    f_first = _xy(first.point("F").r[0])
    assert abs(f_first - (0.14 + 0.06j)) < 0.01
    others = []
    for b, d, f in (("[0.10, 0.20]", "[0.17, 0.22]", "[0.05, 0.17]"), ("[0.20, 0.16]", "[0.27, 0.13]", "[0.21, 0.02]"),
                    ("[0.05, 0.16]", "[0.14, 0.13]", "[0.09, 0.09]")):
        sketch = f"near    = {{ B = {b}, D = {d}, F = {f} }}"
        try:
            scene = alone.replace("near    = { B = [0.21, 0.06], D = [0.23, 0.13], F = [0.14, 0.06] }", sketch)
            motion = graphplan.solve(loads(scene), driver=[0.0])
        except (AssemblyError, SceneError):
            continue
        others.append(motion)
    assert others, "no other assembly found from the sketches tried"
    for motion in others:
        b, d, f = (_xy(motion.point(name).r[0]) for name in "BDF")
        assert abs(abs(b - (0.05 + 0j)) - 0.17) < 1e-9 and abs(abs(d - 0.28) - 0.14) < 1e-9
        assert abs((np.exp(1j * np.radians(30.0)) * (f - 0.14j)).imag) < 1e-9  # F on the guide through E
        assert abs(abs(d - b) - 0.075) < 1e-9 and abs(abs(f - d) - 0.115) < 1e-9 and abs(abs(b - f) - 0.065) < 1e-9
    assert any(abs(_xy(m.point("F").r[0]) - f_first) > 0.01 for m in others)


_GROUP = '''links   = [3, 4, 5, 6]                          # binary AB, CD, the slider at F, then the ternary link BDF
joints  = ["A", "B", "C", "D", "E", "F"]
lengths = [0.17, 0.14]                          # lAB, lCD: the leg EF slides
guides  = { F = { angle = -30.0 } }             # the slider 5 at F moves along the frame's line through E
sides   = [0.075, 0.115, 0.065]                 # the ternary link: lBD, lDF, lFB'''


@pytest.mark.parametrize("legs", [
    # the slider first: legs EF, AB, CD; the sides FB, BD, DF
    ('links = [5, 3, 4, 6]\njoints = ["E", "F", "A", "B", "C", "D"]\nlengths = [0.17, 0.14]\n'
     'guides = { F = { angle = -30.0 } }\nsides = [0.065, 0.075, 0.115]'),
    # the slider second: legs AB, EF, CD; the sides BF, FD, DB
    ('links = [3, 5, 4, 6]\njoints = ["A", "B", "E", "F", "C", "D"]\nlengths = [0.17, 0.14]\n'
     'guides = { F = { angle = -30.0 } }\nsides = [0.065, 0.115, 0.075]'),
], ids=["slider-first", "slider-second"])
def test_the_sliding_leg_may_be_any_of_the_three(legs):
    # The same mechanism with its legs listed in another order: another leg is swept for the assemblies and
    # Assur's point comes from other legs of the list, and every motion, reaction and balancing moment is the same.
    assert _GROUP in TEXT
    assert_same_triad(analyse(_scene(_GROUP, legs)), analyse(graphplan.load(FIXTURE)), "BDF")


def assert_same_triad(listed, reference, inner: str) -> None:
    """Two analyses of one mechanism, its triad's legs listed in another order: the same motion of the inner
    joints, the same reactions and balancing moment at every plan position."""
    for name in inner:
        assert np.max(np.abs(listed.motion.point(name).r - reference.motion.point(name).r)) <= 1e-12
        assert np.max(np.abs(listed.motion.point(name).a - reference.motion.point(name).a)) <= 1e-9
    for mine, theirs in zip(listed.plans, reference.plans, strict=True):
        largest = max(abs(found.force) for found in theirs.forces.reactions.values())
        for name, found in theirs.forces.reactions.items():
            assert abs(mine.forces.reactions[name].force - found.force) <= 1e-9 * largest, name
        assert mine.forces.balancing == pytest.approx(theirs.forces.balancing, rel=1e-9)


def test_the_plan_of_positions_runs_the_guide_on_to_the_frame_point_it_is_named_through():
    # E is no pivot: without a dot and the guide's line run on to it, its label would stand by nothing.
    analysis = analyse(graphplan.load(FIXTURE))
    plan = positions_plan(analysis)
    (frame,) = [layer for layer in positions.layout(plan) if layer.name == "frame"]
    e = analysis.mechanism.scene.frame_points["E"] / plan.length_scale
    dots = [item for item in frame.items if isinstance(item, Circle) and item.fill == "black"]
    assert any(abs(complex(*dot.centre) - e) < 1e-9 for dot in dots)
    u = np.exp(1j * np.radians(-30.0))
    reaching = [line for line in frame.items if isinstance(line, Polyline) and len(line.points) == 2
                and all(abs((np.conj(u) * (complex(*end) - e)).imag) < 1e-6 for end in line.points)
                and min(abs(complex(*end) - e) for end in line.points) < 1e-6]
    assert reaching, "the guide's line does not reach E"
