"""A triad whose leg is a block sliding in a slot of the ternary link: what the fixture-wide tests cannot show.

Those already hold the ratchet's variants ``ratchet+triad-slot`` (block 5, pinned to the coupler at E,
slides in a slot of the ternary link 8 through G), ``ratchet+triad-slot-and-guide`` (slider 7 on the
rocking link 4 too) and ``ratchet+triad-two-slots`` (block 6 pinned to the rocker at S4 in a second slot)
to their closure, finite differences (the link's point E8 under the block as a point of link 8), the
50-digit reference, the plans against the analytic solution and the force polygons against the linear
system of statics.  Here: the structure, Assur's point on the slot's normal at the block's pin, the
sliding read off the plan and its Coriolis part, the slot's reaction and the pin's, the legs listed in
another order, the assemblies, the scene's mistakes and the note.
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import numpy as np
import pytest
from test_motion_against_finite_differences import _HUNG_ON_THE_RATCHET, CASES, _hung_on_the_ratchet
from test_triad_with_slider import assert_same_triad, forces_at, laid_once, moment_about, plans_at

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.errors import SceneError
from graphplan.groups.triad import Track
from graphplan.kinematics import cross
from graphplan.loads import activity
from graphplan.plans import coriolis
from graphplan.report.forces import markdown as forces_markdown
from graphplan.report.note import note_markdown

SLOT = "ratchet+triad-slot"
SLOT_ANGLE = np.radians(-77.0)  # from GK, the ternary link's reference line
RATCHET = Path(__file__).resolve().parent.parent / "fixtures" / "ratchet_crank_rocker.toml"


def _at(motion, name: str) -> np.ndarray:
    xy = motion.point(name).r
    return xy[:, 0] + 1j * xy[:, 1]


def _slot_direction(motion) -> np.ndarray:
    return np.exp(1j * (motion.link(8).angle + SLOT_ANGLE))


def test_a_block_in_a_slot_makes_a_class_iii_group_with_one_sliding_pair():
    mechanism = graphplan.build(CASES[SLOT]())
    assert mechanism.structure.endswith("III3(5,6,7,8)")
    # W = 3n − 2p5: n = 7 moving links; p5 = the four-bar's four pairs + the triad's six (five turning, the slot)
    assert mechanism.degrees_of_freedom == (7, 10, 1)
    assert ("E", 3, 5) in mechanism.revolutes and not any(joint == "G" and 5 in (source, target)
                                                          for joint, source, target in mechanism.revolutes)
    motion = graphplan.solve(CASES[SLOT]())
    assert [(slide.slider, slide.guide, slide.joint) for slide in motion.slides] == [(5, 8, "E")]
    assert np.array_equal(motion.link(5).omega, motion.link(8).omega)  # the block turns with its slot
    # E stays on the slot's line through G, and the link's point E8 under it is where E is.
    off = (np.conj(_slot_direction(motion)) * (_at(motion, "E") - _at(motion, "G"))).imag
    assert np.max(np.abs(off)) < 1e-12
    assert np.max(np.abs(_at(motion, "E8") - _at(motion, "E"))) == 0


def test_assurs_point_is_on_the_slots_normal_and_the_sliding_is_read_off_exactly():
    """Σ8 lies on two of: the normal to the slot at E, the line S4K, the line CL (those that cross at the
    widest angle); the sliding of E along the slot, read off between e8 and e, is the exact one."""
    analysis = analyse(CASES[SLOT]())
    motion = analysis.motion
    on_slot_normal = 0
    for index in range(motion.count):
        where, directions, velocity, acceleration = plans_at(analysis, index)
        ((_, sigma),) = velocity.auxiliary.items()
        slot = directions[8] * np.exp(1j * SLOT_ANGLE)
        lines = {"E": (where["E"], 1j * slot), "S4K": (where["K"], where["K"] - where["S4"]),
                 "CL": (where["L"], where["L"] - where["C"])}
        widest = max((("E", "S4K"), ("E", "CL"), ("S4K", "CL")),
                     key=lambda pair: abs((np.conj(lines[pair[0]][1]) * lines[pair[1]][1]).imag)
                     / abs(lines[pair[0]][1]) / abs(lines[pair[1]][1]))
        for through, direction in (lines[widest[0]], lines[widest[1]]):
            assert abs((np.conj(direction) * (sigma - through)).imag) <= 1e-9 * abs(direction) * max(abs(sigma - through), 1e-3)
        on_slot_normal += "E" in widest
        (slide,) = motion.slides
        exact_v = complex(slide.velocity[index] * slide.u[index])
        exact_a = complex(slide.acceleration[index] * slide.u[index])
        assert abs(velocity.sliding[5] - exact_v) <= 1e-9 * max(abs(exact_v), 1.0)
        assert abs(acceleration.sliding[5] - exact_a) <= 1e-9 * max(abs(exact_a), 1.0)
        assert abs((np.conj(slot) * velocity.sliding[5]).imag) <= 1e-12 * max(abs(velocity.sliding[5]), 1.0)
    assert on_slot_normal >= 3, "Assur's point was never taken on the slot's normal"


def test_the_slot_turns_so_the_link_under_the_block_gets_a_coriolis_part():
    """aE8 = aE + aE8Eᵏ + aE8E^r: the block turns with the link, so the Coriolis part is 2·ω8 × vE8E."""
    analysis = analyse(CASES[SLOT]())
    motion = analysis.motion
    checked = 0
    for index in range(motion.count):
        _, _, velocity, acceleration = plans_at(analysis, index)
        drawn = laid_once(acceleration, "aE8Eᵏ")
        relative = complex(*motion.point("E8").v[index]) - complex(*motion.point("E").v[index])
        expected = 2j * float(motion.link(8).omega[index]) * relative
        assert abs(drawn - expected) <= 1e-9 * max(abs(expected), 1e-3)
        assert drawn == pytest.approx(coriolis(velocity.rates[8], -velocity.sliding[5]), abs=1e-12)
        checked += abs(expected) > 0.1
    assert checked >= 4


def test_the_slots_reaction_is_square_to_it_and_the_pins_part_along_it_balances_the_block():
    analysis = analyse(_loaded_slot())
    motion = analysis.motion
    acting = activity(analysis.mechanism, analysis.positions, motion)
    shifted = 0
    for index in range(0, motion.count, 2):
        where, directions, applied, drawn = forces_at(analysis, acting, index)
        u = directions[8] * np.exp(1j * SLOT_ANGLE)
        on_block = [load for load in applied if load.link == 5]
        slot = drawn.reactions["R85"]
        assert (slot.joint, slot.source, slot.target) == ("E", 8, 5)
        assert abs((np.conj(u) * slot.force).real) <= 1e-9 * abs(slot.force)
        turning = moment_about(applied, 5, where, "E")
        assert cross(slot.offset * u, slot.force) == pytest.approx(-turning, rel=1e-9, abs=1e-9)
        shifted += abs(slot.offset) > 1e-6
        # The coupler's pull on the block balances the block's own loads along the slot, as the projection says.
        pin = drawn.reactions["R35"]
        along = sum(complex(load.force) for load in on_block if load.point is not None)
        assert (np.conj(u) * (pin.force + along)).real == pytest.approx(0.0, abs=1e-9 * abs(pin.force))
        group = next(group for group in drawn.groups if group.label == "III(5,6,7,8)")
        (projection,) = group.projections
        assert projection.unknown == "R35τ" and projection.value == pytest.approx((np.conj(u) * pin.force).real, rel=1e-9)
        assert pin.force + slot.force + along == pytest.approx(0.0, abs=1e-9 * abs(pin.force))
    assert shifted, "the block's inertia moment never shifted the slot's reaction"


_MASSES = """
[links.5]
mass = 1.2
centre = "E"
inertia = 0.0015
[links.6]
mass = 2.0
centre = "K"
inertia = 0.004
[links.7]
mass = 1.5
centre = "L"
inertia = 0.003
[links.8]
mass = 4.0
centre = "G"
inertia = 0.02
"""


def _loaded_slot():
    return _hung_on_the_ratchet(_HUNG_ON_THE_RATCHET[SLOT] + _MASSES)()


def test_the_legs_may_be_listed_in_any_order():
    """The same triad with the slotted leg listed last: the assemblies come from another turn, Σ from other legs
    of the list, and every motion, reaction and balancing moment is the same."""
    group = _HUNG_ON_THE_RATCHET["ratchet+triad-slot-and-guide"] + _MASSES
    base = analyse(_hung_on_the_ratchet(group)())
    # Listed from L, the ternary link's reference line is LK: the same slot makes another angle with it.
    g, k, el = (complex(*base.motion.point(name).r[0]) for name in "GKL")
    angle = float(np.degrees(np.angle((k - g) / (k - el)))) - 77.0
    listed = group.replace('joints = ["E", "G", "S4", "K", "C", "L"]', 'joints = ["C", "L", "S4", "K", "E", "G"]') \
        .replace("links = [5, 6, 7, 8]", "links = [7, 6, 5, 8]").replace("sides = [0.15, 0.17, 0.18]", "sides = [0.17, 0.15, 0.18]") \
        .replace("slots = { G = { angle = -77.0 } }", f"slots = {{ G = {{ angle = {angle!r} }} }}")
    assert listed.count(repr(angle)) == 1
    assert_same_triad(analyse(_hung_on_the_ratchet(listed)()), base, "GKL")
    assert all(abs(plan.forces.reactions["R85"].offset) > 1e-6 for plan in base.plans)


def test_turning_the_ternary_link_finds_the_assemblies_of_a_slot():
    """A slot turns with the ternary link, so no leg's track is fixed: the link is turned round, and every
    assembly found keeps E on the slot and the other legs' lengths; the scene's is among them."""
    mechanism = graphplan.build(CASES[SLOT]())
    (_, triad) = mechanism.groups
    motion = graphplan.solve(CASES[SLOT](), driver=[0.0])

    def at(name: str) -> complex:
        return complex(*motion.point(name).r[0])

    tracks = (Track(at("E"), slot=np.exp(1j * SLOT_ANGLE)), Track(at("S4"), 0.17), Track(at("C"), 0.18))
    found = {turn: triad.assemblies(tracks, turn) for turn in (-1, 1)}
    assert sum(len(poses) for poses in found.values()) >= 2
    for turn, poses in found.items():
        for pose in poses:
            rotation = np.exp(1j * pose.psi)
            for track, corner in zip(tracks, triad.corners(pose, turn), strict=True):
                assert abs(track.closure(corner, triad.size, rotation)) <= 1e-9 * triad.size ** 2
    assert min(abs(pose.b - at("G")) for poses in found.values() for pose in poses) < 1e-9


def test_three_slots_close_on_the_three_pins():
    group = _HUNG_ON_THE_RATCHET[SLOT].replace("lengths = [0.17, 0.18]\n", "").replace(
        "slots = { G = { angle = -77.0 } }", "slots = { G = { angle = -77.0 }, K = { angle = 0.0 }, L = { angle = 60.0 } }")
    motion = graphplan.solve(_hung_on_the_ratchet(group)())
    toward_k = _at(motion, "K") - _at(motion, "G")
    toward_k /= np.abs(toward_k)
    for pin, corner, angle in (("E", "G", -77.0), ("S4", "K", 0.0), ("C", "L", 60.0)):
        slot = toward_k * np.exp(1j * np.radians(angle))
        assert np.max(np.abs((np.conj(slot) * (_at(motion, pin) - _at(motion, corner))).imag)) < 1e-12, pin
    assert {(s.slider, s.guide, s.joint) for s in motion.slides} == {(5, 8, "E"), (6, 8, "S4"), (7, 8, "C")}


@pytest.mark.parametrize(("change", "where", "says"), [
    ("slots = { G = { angle = -77.0 } }\nguides = { G = { angle = 10.0 } }", "slots.G",
     "already slides on a guide through E (guides.G)"),
    ("slots = { E = { angle = -77.0 } }", "slots.E", "must name an inner joint of the triad: G, K, L"),
    ("slots = { }", "slots", "must name the legs whose blocks slide in slots"),
    ("slots = { G = { angle = -77.0, through = \"E\" } }", "slots.G", "through"),
])
def test_a_slot_written_wrong_is_refused_where_it_is(change, where, says):
    group = _HUNG_ON_THE_RATCHET[SLOT].replace("slots = { G = { angle = -77.0 } }", change)
    with pytest.raises(SceneError) as raised:
        _hung_on_the_ratchet(group)()
    assert f"groups[1].{where}" in str(raised.value) and says in str(raised.value)


def test_a_slotted_leg_has_no_length(tmp_path, capsys):
    group = _HUNG_ON_THE_RATCHET[SLOT].replace("lengths = [0.17, 0.18]", "lengths = [0.26, 0.17, 0.18]")
    scene = tmp_path / "slot.toml"
    scene.write_text(RATCHET.read_text(encoding="utf-8").replace("\n[points]", group + "\n[points]"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert "groups[1].lengths: must have 2 entries, lS4K, lCL (the leg EG slides)" in error
    assert not out.exists()


def test_the_note_says_why_assurs_point_is_on_the_slots_normal():
    analysis = analyse(dataclasses.replace(_loaded_slot(), locale="en"))
    report = forces_markdown(analysis)
    assert "### Forces along a slot (τ)" in report and "- III(5,6,7,8): ΣFτ(5) = 0 → R35τ = " in report
    assert report.index("Forces along a slot") < report.index("### Moment equations")
    text = note_markdown(analysis)
    assert "the normal at E to the slot of link 8 in which the block pinned there slides" in text
    assert "moves along the slot relative to E" in text
    assert "2·ω8·VE8E" in text
    assert "A block takes no force along its slot" in text and "ΣFτ(5) = R35τ + G5τ + Fu5τ" in text


def test_the_sliding_pairs_are_named_in_the_order_of_the_motions_slides():
    scene = CASES["ratchet+triad-slot-and-guide"]()
    mechanism = graphplan.build(scene)
    named = [pair for group in mechanism.groups for pair in group.sliding_pairs(mechanism)]
    assert named == [(slide.slider, slide.guide, slide.joint) for slide in graphplan.solve(scene).slides] \
        == [(5, 8, "E"), (7, 4, "L")]


def test_a_block_pinned_to_the_frame_reads_its_sliding_once_by_its_own_name():
    """The block of the leg CL is pinned at the frame point C: its pin's image is the pole, so the sliding vector
    vC8C starts there, yet it is relative, not C's own velocity; the error table reads it once, by that name."""
    group = _HUNG_ON_THE_RATCHET[SLOT].replace("lengths = [0.17, 0.18]", "lengths = [0.26, 0.17]") \
        .replace("slots = { G = { angle = -77.0 } }", "slots = { L = { angle = 120.0 } }")
    analysis = analyse(_hung_on_the_ratchet(group)())
    motion = analysis.motion
    (slide,) = motion.slides
    assert (slide.slider, slide.guide, slide.joint) == (7, 8, "C")
    for plan in analysis.plans:
        names = [row.quantity for row in plan.errors if row.source == "construction"]
        assert len(names) == len(set(names))
        assert {"VC8C", "aC8C^r"} <= set(names) and not [name for name in names if "CC8" in name]
        index = plan.index
        (velocity,) = [row for row in plan.errors if row.quantity == "VC8C" and row.source == "construction"]
        (acceleration,) = [row for row in plan.errors if row.quantity == "aC8C^r" and row.source == "construction"]
        assert velocity.plan == pytest.approx(abs(slide.velocity[index]), rel=1e-9)
        assert acceleration.plan == pytest.approx(abs(slide.acceleration[index]), rel=1e-9)


def test_the_triad_starter_s_advice_on_a_slot_runs(tmp_path):
    """The starter scene says how to turn its leg EF into a block in a slot: done as it says, the scene runs, its
    plans exact."""
    from importlib import resources

    text = resources.files("graphplan").joinpath("templates", "triad.toml").read_text(encoding="utf-8")
    comment = " ".join(line.lstrip("# ") for line in text.splitlines() if line.startswith("#"))
    (angle,) = re.findall(r"`slots = \{ F = \{ angle = ([-\d.]+) \} \}`", comment)
    assert '`centre = "E"` under [links.5], S5 left out' in comment
    text = text.replace("lengths = [0.135, 0.108, 0.189]", f"lengths = [0.135, 0.108]\nslots   = {{ F = {{ angle = {angle} }} }}")
    text = re.sub(r"\nS5 = .*\n", "\n", text).replace('centre  = "S5"', 'centre  = "E"')
    scene = tmp_path / "slot.toml"
    scene.write_text(text, encoding="utf-8")
    analysis = analyse(graphplan.load(scene))
    assert [(s.slider, s.guide, s.joint) for s in analysis.motion.slides] == [(5, 6, "E")]
    rows = [row for row in analysis.errors if row.source == "construction"]
    assert rows and max(abs(row.percent) for row in rows) < 1e-9


def test_newtons_jacobian_is_the_derivative_of_the_closure_with_a_slot():
    """The slot turns with the ternary link, so its closure depends on ψ beyond its corner's motion: the
    Jacobian Newton's method is given must be the closure's derivative, checked by central differences."""
    mechanism = graphplan.build(CASES["ratchet+triad-slot-and-guide"]())
    (_, triad) = mechanism.groups
    motion = graphplan.solve(CASES["ratchet+triad-slot-and-guide"](), driver=[0.0])

    def at(name: str) -> complex:
        return complex(*motion.point(name).r[0])

    guide = np.exp(1j * (motion.link(4).angle[0] + np.radians(120.0)))
    tracks = (Track(at("E"), slot=np.exp(1j * SLOT_ANGLE)), Track(at("S4"), 0.17), Track(at("C"), u=guide))
    rng = np.random.default_rng(7)
    for _ in range(5):
        q = np.array([at("G").real, at("G").imag, 0.0]) + rng.normal(scale=[0.05, 0.05, 1.0])
        _, jacobian = triad._residual(q, tracks, -1)
        h = 1e-6
        for column in range(3):
            step = np.zeros(3)
            step[column] = h
            numeric = (triad._residual(q + step, tracks, -1)[0] - triad._residual(q - step, tracks, -1)[0]) / (2 * h)
            assert np.allclose(jacobian[:, column], numeric, rtol=1e-6, atol=1e-9 * triad.size ** 2), column
