"""A triad with two or three sliding legs: what the tests that run every fixture and variant cannot show.

Those already hold the ratchet's variants ``ratchet+triad-two-sliders`` (slider 6 on the rocking link 4,
so with a Coriolis term; slider 7 on a frame guide through C; only the leg EG turns) and
``ratchet+triad-three-sliders`` (slider 5 on the coupler 3 too), and ``triad_with_slider+square-guides``
to their closure, finite differences, the 50-digit reference, the plans against the analytic solution
and the force polygons against the linear system of statics.  Here: the structure, Assur's point on a
guide's normal, the Coriolis component, the guides' reactions, the legs listed in another order, the
note, the assemblies of a triad none of whose legs turns.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from test_forces_against_statics import loaded
from test_motion_against_finite_differences import _HUNG_ON_THE_RATCHET, CASES, _hung_on_the_ratchet, square_guides
from test_triad_with_slider import assert_same_triad, forces_at, laid_once, moment_about, plans_at

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.groups.triad import Track
from graphplan.kinematics import cross
from graphplan.loads import activity
from graphplan.plans import coriolis
from graphplan.report.note import note_markdown

VARIANT = "ratchet+triad-two-sliders"
K_GUIDE, L_GUIDE = 60.0, 80.0  # degrees: K's on link 4 (from its own reference line), L's on the frame


def _sine(u: complex, w: complex) -> float:
    return abs((u.conjugate() * w).imag) / (abs(u) * abs(w))


def test_two_sliders_make_a_class_iii_group_with_two_sliding_pairs():
    mechanism = graphplan.build(CASES[VARIANT]())
    assert mechanism.structure.endswith("III3(5,6,7,8)")
    # W = 3n − 2p5: n = 7 moving links; p5 = the four-bar's four pairs + the triad's six (four turning, two sliding)
    assert mechanism.degrees_of_freedom == (7, 10, 1)
    assert 7 in mechanism.translating and 6 not in mechanism.translating
    motion = graphplan.solve(CASES[VARIANT]())
    pairs = {(slide.slider, slide.guide, slide.joint) for slide in motion.slides}
    assert {(6, 4, "K"), (7, 1, "L")} <= pairs
    assert np.all(motion.link(7).omega == 0)
    assert np.array_equal(motion.link(6).omega, motion.link(4).omega)  # a slider turns with its guide
    # Each pin stays on its guide: K on link 4's line through S4 at 60° to it, L on the frame's line through C.
    k_direction = np.exp(1j * (motion.link(4).angle + np.radians(K_GUIDE)))

    def at(name: str) -> np.ndarray:
        xy = motion.point(name).r
        return xy[:, 0] + 1j * xy[:, 1]

    k_off = (np.conj(k_direction) * (at("K") - at("S4"))).imag
    l_off = (np.exp(-1j * np.radians(L_GUIDE)) * (at("L") - at("C"))).imag
    assert np.max(np.abs(k_off)) < 1e-12 and np.max(np.abs(l_off)) < 1e-12


def test_assurs_point_is_on_a_guides_normal_where_those_lines_cross_widest():
    """Σ8 lies on two of: the line EG, the normal to K's guide at K, the normal to L's guide at L (those that
    cross at the widest angle); the pins' images then give their sliding along their guides."""
    analysis = analyse(CASES[VARIANT]())
    motion = analysis.motion
    for index in range(motion.count):
        where, directions, velocity, _ = plans_at(analysis, index)
        ((name, sigma),) = velocity.auxiliary.items()
        assert name == "Σ8"
        k_guide = directions[4] * np.exp(1j * np.radians(K_GUIDE))
        lines = {"EG": (where["G"], where["G"] - where["E"]), "K": (where["K"], 1j * k_guide),
                 "L": (where["L"], 1j * np.exp(1j * np.radians(L_GUIDE)))}
        widest = max((("EG", "K"), ("EG", "L"), ("K", "L")), key=lambda pair: _sine(lines[pair[0]][1], lines[pair[1]][1]))
        for through, direction in (lines[widest[0]], lines[widest[1]]):
            assert _sine(direction, sigma - through) <= 1e-9, (index, widest)
        # The exact relative velocities, read off the plan between the guide points' images and the pins'.
        for slider, guide_u in ((6, k_guide), (7, np.exp(1j * np.radians(L_GUIDE)))):
            (slide,) = [s for s in motion.slides if s.slider == slider]
            expected = complex(slide.velocity[index] * slide.u[index])
            assert abs(velocity.sliding[slider] - expected) <= 1e-9 * max(abs(expected), 1.0)
            assert abs((np.conj(guide_u) * velocity.sliding[slider]).imag) <= 1e-12 * max(abs(velocity.sliding[slider]), 1.0)


def test_assurs_point_is_where_two_square_guides_normals_cross():
    """Two sliders on guides square to each other: their normals cross square, wider than any line with either."""
    analysis = analyse(square_guides())
    f_guide, d_guide = np.exp(1j * np.radians(-30.0)), np.exp(1j * np.radians(60.0))
    for plan_position in analysis.plans:
        where = plan_position.positions
        ((_, sigma),) = plan_position.velocity.auxiliary.items()
        assert _sine(1j * f_guide, sigma - where["F"]) <= 1e-9 and _sine(1j * d_guide, sigma - where["D"]) <= 1e-9
        # Both pins slide on frame guides: Σ, on both normals, is the ternary link's instant centre.
        index = plan_position.number - 1
        v_b, omega = complex(*analysis.motion.point("B").v[index]), float(analysis.motion.link(6).omega[index])
        assert abs(v_b + 1j * omega * (sigma - where["B"])) <= 1e-12 * abs(v_b)
        velocity = plan_position.velocity
        assert abs(velocity.points["σ6"]) <= 1e-12 * abs(v_b)
        for pin, guide in (("D", d_guide), ("F", f_guide)):
            assert abs((np.conj(guide) * velocity.value(pin)).imag) <= 1e-12 * abs(velocity.value(pin))


def test_the_slider_on_the_rocker_gets_its_coriolis_component():
    analysis = analyse(CASES[VARIANT]())
    motion = analysis.motion
    checked = 0
    for index in range(motion.count):
        _, _, velocity, acceleration = plans_at(analysis, index)
        drawn = laid_once(acceleration, "aKK4ᵏ")
        (slide,) = [s for s in motion.slides if s.slider == 6]
        expected = 2j * float(motion.link(4).omega[index]) * complex(slide.velocity[index] * slide.u[index])
        assert abs(drawn - expected) <= 1e-9 * max(abs(expected), 1e-3)
        assert drawn == pytest.approx(coriolis(velocity.rates[4], velocity.sliding[6]), abs=1e-12)
        checked += abs(expected) > 0.1
        # The frame's slider has none.
        assert not [vector for step in acceleration.steps for vector in step.vectors if vector.meaning.startswith("aLL1ᵏ")]
    assert checked >= 4


def test_each_guides_reaction_is_square_to_it_and_shifted_by_its_sliders_moment():
    analysis = analyse(loaded(CASES[VARIANT]()))
    motion = analysis.motion
    acting = activity(analysis.mechanism, analysis.positions, motion)
    shifted = 0
    for index in range(0, motion.count, 2):
        where, directions, applied, drawn = forces_at(analysis, acting, index)
        for name, slider, pin, u in (("R46", 6, "K", directions[4] * np.exp(1j * np.radians(K_GUIDE))),
                                     ("R17", 7, "L", np.exp(1j * np.radians(L_GUIDE)))):
            normal = drawn.reactions[name]
            assert normal.joint == pin and normal.target == slider
            assert abs((u.conjugate() * normal.force).real) <= 1e-9 * abs(normal.force)
            turning = moment_about(applied, slider, where, pin)
            assert cross(normal.offset * u, normal.force) == pytest.approx(-turning, rel=1e-9, abs=1e-9)
            shifted += abs(normal.offset) > 1e-6
    assert shifted, "the rocking slider's inertia moment never shifted its guide's reaction"


_MASSES = """
[links.5]
mass = 2.0
centre = "G"
inertia = 0.012
[links.6]
mass = 1.0
centre = "K"
inertia = 0.002
[links.7]
mass = 1.5
centre = "L"
[links.8]
mass = 3.0
centre = "L"
inertia = 0.04
"""


def test_the_legs_may_be_listed_in_any_order():
    """The same triad with its sliding legs listed first: another leg is swept, Σ comes from other legs of the
    list, and every motion, reaction and balancing moment is the same."""
    group = _HUNG_ON_THE_RATCHET[VARIANT] + _MASSES
    listed = group.replace('joints = ["E", "G", "S4", "K", "C", "L"]', 'joints = ["C", "L", "S4", "K", "E", "G"]') \
        .replace("links = [5, 6, 7, 8]", "links = [7, 6, 5, 8]").replace("sides = [0.15, 0.17, 0.18]", "sides = [0.17, 0.15, 0.18]")
    assert listed != group
    base, other = (analyse(_hung_on_the_ratchet(text)()) for text in (group, listed))
    assert all(abs(plan.forces.reactions["R46"].offset) > 1e-6 for plan in base.plans)  # the rocking slider is shifted
    assert_same_triad(other, base, "GKL")


def test_the_note_says_why_assurs_point_is_on_a_guides_normal():
    text = note_markdown(analyse(square_guides()))
    assert "where the normal at D to the guide of the slider pinned there and the normal at F" in text
    assert "along the guide relative to the guide's point under D" in text
    # The force paragraph names each of its two unknowns' own lines, the guides' normals at D and F.
    assert ("the line of R15 (the guide's reaction on slider 5) square to the guide at the slider's pin F and the line "
            "of R14 (the guide's reaction on slider 4) square to the guide at the slider's pin D") in text
    assert "Both lines run through the pole: VΣ6 = 0, and Σ6 is the instant centre of link 6." in text
    # The ratchet's scene is written in Russian.
    text = note_markdown(analyse(CASES[VARIANT]()))
    assert "нормаль к направляющей ползуна в его шарнире" in text


THREE = "ratchet+triad-three-sliders"


def test_three_sliding_legs_need_no_lengths_and_each_pin_keeps_to_its_guide():
    scene = CASES[THREE]()
    (_, triad) = scene.groups
    assert triad.sliding_legs == (0, 1, 2) and triad.turning_legs == ()
    motion = graphplan.solve(scene)
    assert {(s.slider, s.guide, s.joint) for s in motion.slides} >= {(5, 3, "G"), (6, 4, "K"), (7, 1, "L")}

    def at(name: str) -> np.ndarray:
        xy = motion.point(name).r
        return xy[:, 0] + 1j * xy[:, 1]

    for pin, through, link, angle in (("G", "E", 3, 120.0), ("K", "S4", 4, 120.0), ("L", "C", None, 60.0)):
        base = 0.0 if link is None else motion.link(link).angle
        direction = np.exp(1j * (base + np.radians(angle)))
        assert np.max(np.abs((np.conj(direction) * (at(pin) - at(through))).imag)) < 1e-12, pin
    sides = [abs(at("K") - at("G")), abs(at("L") - at("K")), abs(at("G") - at("L"))]
    for side, length in zip(sides, (0.15, 0.17, 0.18), strict=True):
        assert np.max(np.abs(side - length)) < 1e-12


def test_turning_the_ternary_link_finds_the_assemblies_of_three_sliders():
    """With no leg to sweep round a circle, the ternary link is turned round: every assembly it finds closes
    on the three guides, and the one the scene runs in is among them."""
    mechanism = graphplan.build(CASES[THREE]())
    (_, triad) = mechanism.groups
    motion = graphplan.solve(CASES[THREE](), driver=[0.0])

    def at(name: str) -> complex:
        return complex(*motion.point(name).r[0])

    rocker, coupler = motion.link(4).angle[0], motion.link(3).angle[0]
    tracks = (Track(at("E"), u=np.exp(1j * (coupler + np.radians(120.0)))),
              Track(at("S4"), u=np.exp(1j * (rocker + np.radians(120.0)))),
              Track(at("C"), u=np.exp(1j * np.radians(60.0))))
    poses = triad.assemblies(tracks, -1) + triad.assemblies(tracks, 1)
    assert len(poses) >= 2
    for turn, found in ((-1, triad.assemblies(tracks, -1)), (1, triad.assemblies(tracks, 1))):
        for pose in found:
            for track, corner in zip(tracks, triad.corners(pose, turn), strict=True):
                assert abs(track.closure(corner, triad.size)) <= 1e-9 * triad.size ** 2
    # The assembly the scene runs in is among them.
    g = at("G")
    assert min(abs(pose.b - g) for pose in poses) < 1e-9


def test_three_sliders_that_cannot_close_say_so_in_one_line(tmp_path, capsys):
    group = _HUNG_ON_THE_RATCHET[THREE].replace("sides = [0.15, 0.17, 0.18]", "sides = [0.015, 0.017, 0.018]")
    scene = tmp_path / "small.toml"
    ratchet = (Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
    scene.write_text(ratchet.replace("\n[points]", group + "\n[points]"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert "nor a turn of the ternary link 8 finds a pose" in error and "G slides on the guide through E" in error
    assert not out.exists()
