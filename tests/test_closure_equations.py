"""The positions the solver finds satisfy each group's closure equations, at every position.

Every check is written from the group's definition (lengths, guides, offsets, the slot's angle,
the named points' definitions), evaluated on the solved positions; none compares the solver
with a second run of itself.  Tolerance: 1e-12 of the mechanism's size for lengths, 1e-12 rad
for directions.

The last tests check the ratchet fixture's extremes against the closed form of its dead
centres (crank and coupler in line), independently of the root finder that places them.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

# Every fixture, and the variants that exercise what no fixture has (moving guides of RRP and
# RPP, PRP offsets, an offset slot); defined beside the finite-difference tests.
from test_motion_against_finite_differences import CASES, DENSE, FIXTURE_DIR, sample, scene_of

import graphplan
from graphplan.mechanism import build
from graphplan.positions import first_value

RATCHET = FIXTURE_DIR / "ratchet_crank_rocker.toml"

TIGHT = 1e-12
SAMPLES = ["positions", "sweep"]


@dataclasses.dataclass(frozen=True)
class Solved:
    scene: object
    mechanism: object
    motion: object
    size: float

    def r(self, name: str) -> np.ndarray:
        xy = self.motion.point(name).r
        return xy[:, 0] + 1j * xy[:, 1]

    def angle(self, link: int) -> np.ndarray:
        return self.motion.link(link).angle

    def direction(self, link: int) -> np.ndarray:
        return np.exp(1j * self.angle(link))


def solved(case: str, which: str) -> Solved:
    scene = scene_of(case)
    motion = graphplan.solve(scene, driver=sample(scene, which))
    every = np.concatenate([motion.point(name).r for name in motion.points])
    size = float(np.max(np.ptp(every, axis=0)))
    assert size > 0
    return Solved(scene, build(scene), motion, size)


# Module-scoped: the tests only read the solved motion (its arrays are read-only), so each case is solved once
# for all of them rather than once a test.
@pytest.fixture(scope="module", params=[(case, which) for case in CASES for which in SAMPLES],
                ids=[f"{case}-{which}" for case in CASES for which in SAMPLES])
def mechanism_motion(request) -> Solved:
    return solved(*request.param)


def wrapped(angle: np.ndarray) -> np.ndarray:
    """An angle difference brought to (−π, π]."""
    return np.angle(np.exp(1j * np.asarray(angle)))


def assert_small(label: str, residual, scale: float) -> None:
    residual = np.abs(np.asarray(residual))
    worst = float(np.max(residual))
    assert worst <= TIGHT * scale, f"{label}: residual {worst:.3e} > {TIGHT:g} × {scale:.4g}"


def cross(a, b):
    return (np.conj(a) * b).imag


def dot(a, b):
    return (np.conj(a) * b).real


def guide_line(m: Solved, guide) -> tuple[np.ndarray, np.ndarray]:
    """A point and the unit direction of a guide at every position, from its definition."""
    if guide.line is not None:
        guide = m.scene.frame_lines[guide.line]
    if guide.link is None or guide.link == m.scene.frame_link:
        if isinstance(guide.through, str):
            point = m.scene.frame_points[guide.through]
        else:
            point = complex(*guide.through)
        return np.full(m.motion.count, point, dtype=complex), np.full(m.motion.count, np.exp(1j * guide.angle))
    return m.r(guide.through), np.exp(1j * (m.angle(guide.link) + guide.angle))


def slide_of(m: Solved, slider: int, joint: str):
    found = [s for s in m.motion.slides if s.slider == slider and s.joint == joint]
    assert len(found) == 1, f"one sliding pair of link {slider} at {joint}"
    return np.broadcast_to(found[0].s, (m.motion.count,))


# --- the driver -------------------------------------------------------------------------------

def test_driver_places_its_joint(mechanism_motion):
    m = mechanism_motion
    driver = m.scene.driver
    values = m.motion.driver
    joint = m.r(driver.joint)
    if driver.kind == "crank":
        arm = joint - m.scene.frame_points[driver.pivot]
        assert_small(f"|{driver.pivot}{driver.joint}| − {driver.length}", np.abs(arm) - driver.length, m.size)
        assert_small(f"direction of {driver.pivot}{driver.joint} − φ", wrapped(np.angle(arm) - values), 1.0)
        assert_small(f"angle of link {driver.link} − φ", wrapped(m.angle(driver.link) - values), 1.0)
    else:
        origin, u = guide_line(m, driver.guide)
        assert_small(f"{driver.joint} − (G + s·u)", joint - (origin + values * u), m.size)
        assert_small("slide coordinate − s", slide_of(m, driver.link, driver.joint) - values, m.size)


# --- the groups -------------------------------------------------------------------------------

def check_rrr(m: Solved, group) -> None:
    a_name, b_name, c_name = group.joints
    a, b, c = m.r(a_name), m.r(b_name), m.r(c_name)
    ab, bc = group.lengths
    assert_small(f"|{a_name}{b_name}| − {ab}", np.abs(b - a) - ab, m.size)
    assert_small(f"|{b_name}{c_name}| − {bc}", np.abs(b - c) - bc, m.size)
    side = np.sign(cross(c - a, b - a))
    assert np.all(side == side[0]), f"{b_name} changes side of {a_name}→{c_name}: the branch jumped"
    if group.assembly is not None:
        assert side[0] == {"left": 1, "right": -1}[group.assembly], f"{b_name} is not {group.assembly} of {a_name}→{c_name}"
    link_a, link_b = group.links
    assert_small(f"angle of link {link_a} − direction {a_name}{b_name}", wrapped(m.angle(link_a) - np.angle(b - a)), 1.0)
    assert_small(f"angle of link {link_b} − direction {c_name}{b_name}", wrapped(m.angle(link_b) - np.angle(b - c)), 1.0)


def check_rrp(m: Solved, group) -> None:
    a_name, b_name = group.joints
    a, b = m.r(a_name), m.r(b_name)
    origin, u = guide_line(m, group.guide)
    assert_small(f"|{a_name}{b_name}| − {group.length}", np.abs(b - a) - group.length, m.size)
    assert_small(f"{b_name}'s distance from its guide", cross(u, b - origin), m.size)
    ahead = np.sign(dot(u, b - a))
    assert np.all(ahead == ahead[0]), f"{b_name} passes the foot of {a_name} on the guide: the branch jumped"
    if group.assembly is not None:
        assert ahead[0] == {"forward": 1, "backward": -1}[group.assembly]
    link_a, link_b = group.links
    assert_small(f"angle of link {link_a} − direction {a_name}{b_name}", wrapped(m.angle(link_a) - np.angle(b - a)), 1.0)
    assert_small(f"angle of link {link_b} − the guide's", wrapped(m.angle(link_b) - np.angle(u)), 1.0)
    s = slide_of(m, link_b, b_name)
    assert_small(f"{b_name} − (G + s·u)", b - (origin + s * u), m.size)


def check_rpr(m: Solved, group) -> None:
    a_name, c_name = group.joints
    a, c = m.r(a_name), m.r(c_name)
    block, lever = group.links
    u = m.direction(lever)
    # The slide line runs along the lever's direction at the offset to the left of C: A = C + (s + i·e)·u.
    assert_small(f"offset of the slide line through {a_name} from {c_name} − {group.offset}",
                 cross(u, a - c) - group.offset, m.size)
    s = slide_of(m, block, a_name)
    assert_small(f"{a_name} − ({c_name} + (s + i·e)·u)", a - (c + (s + 1j * group.offset) * u), m.size)
    assert np.all(s > 0), "the lever points from C's foot toward the block"
    assert_small(f"angle of block {block} − lever {lever}", wrapped(m.angle(block) - m.angle(lever)), 1.0)
    coincident = group.new_joints()[0]
    assert_small(f"{coincident} − {a_name}", m.r(coincident) - a, m.size)


def check_prp(m: Solved, group) -> None:
    (b_name,) = group.joints
    b = m.r(b_name)
    for guide, offset, link in zip(group.guide_pair, group.offsets, group.links):
        origin, u = guide_line(m, guide)
        assert_small(f"{b_name}'s offset from the guide of link {link} − {offset}", cross(u, b - origin) - offset, m.size)
        s = slide_of(m, link, b_name)
        assert_small(f"{b_name} − (G + (s + i·o)·u) on the guide of link {link}", b - (origin + (s + 1j * offset) * u), m.size)
        assert_small(f"angle of link {link} − its guide's", wrapped(m.angle(link) - np.angle(u)), 1.0)


def check_rpp(m: Solved, group) -> None:
    a_name, b_name = group.joints
    a, b = m.r(a_name), m.r(b_name)
    origin, u = guide_line(m, group.guide)
    slot = u * np.exp(1j * group.angle)
    block, carrier = group.links
    assert_small(f"{b_name}'s distance from the guide", cross(u, b - origin), m.size)
    assert_small(f"{a_name}'s distance from the slot through {b_name}", cross(slot, a - b), m.size)
    s_b, s_a = slide_of(m, carrier, b_name), slide_of(m, block, a_name)
    assert_small(f"{b_name} − (G + s_b·u)", b - (origin + s_b * u), m.size)
    assert_small(f"{a_name} − ({b_name} + s_a·w)", a - (b + s_a * slot), m.size)
    assert_small(f"angle of link {carrier} − the guide's", wrapped(m.angle(carrier) - np.angle(u)), 1.0)
    assert_small(f"angle of link {block} − the slot's", wrapped(m.angle(block) - np.angle(slot)), 1.0)


def check_triad(m: Solved, group) -> None:
    """Each turning leg its length, each sliding leg's pin on its guide, each slotted leg's block's pin on its slot
    of the ternary link, BDF a rigid triangle turning as sketched."""
    a, b, c, d, e, f = (m.r(name) for name in group.joints)
    legs = list(zip(((a, b), (c, d), (e, f)), group.lengths, zip(group.joints[0::2], group.joints[1::2])))
    for n, ((outer, inner), length, (o_name, i_name)) in enumerate(legs):
        if group.leg_guides[n] is not None:
            origin, u = guide_line(m, group.leg_guides[n])
            assert_small(f"{i_name}'s distance from its guide", cross(u, inner - origin), m.size)
            slider = group.links[n]
            assert_small(f"angle of link {slider} − the guide's", wrapped(m.angle(slider) - np.angle(u)), 1.0)
            s = slide_of(m, slider, i_name)
            assert_small(f"{i_name} − (E + s·u)", inner - (origin + s * u), m.size)
            continue
        if group.leg_slots[n] is not None:
            # The slot runs through the inner joint at its angle to BD; the block turns with it.
            slot = (d - b) / np.abs(d - b) * np.exp(1j * group.leg_slots[n])
            assert_small(f"{o_name}'s distance from the slot through {i_name}", cross(slot, outer - inner), m.size)
            block = group.links[n]
            assert_small(f"angle of link {block} − the slot's", wrapped(m.angle(block) - np.angle(slot)), 1.0)
            s = slide_of(m, block, o_name)
            assert_small(f"{o_name} − ({i_name} + s·u)", outer - (inner + s * slot), m.size)
            assert_small(f"{group.coincident(n)} − {o_name}", m.r(group.coincident(n)) - outer, m.size)
            continue
        assert_small(f"|{o_name}{i_name}| − {length}", np.abs(inner - outer) - length, m.size)
    bd, df, fb = group.sides
    assert_small("|BD| − lBD", np.abs(d - b) - bd, m.size)
    assert_small("|DF| − lDF", np.abs(f - d) - df, m.size)
    assert_small("|FB| − lFB", np.abs(b - f) - fb, m.size)
    turn = np.sign(cross(d - b, f - b))
    assert np.all(turn == turn[0]), "the ternary link turned over: the assembly jumped"
    sketch = dict(group.near)
    assert turn[0] == np.sign(cross(sketch[group.joints[3]] - sketch[group.joints[1]],
                                    sketch[group.joints[5]] - sketch[group.joints[1]])), "BDF turns against the sketch"
    *binaries, ternary = group.links
    for n, (link, (o_name, i_name), (outer, inner)) in enumerate(zip(binaries, zip(group.joints[0::2], group.joints[1::2]),
                                                                     ((a, b), (c, d), (e, f)))):
        if n not in group.turning_legs:
            continue
        assert_small(f"angle of link {link} − direction {o_name}{i_name}", wrapped(m.angle(link) - np.angle(inner - outer)), 1.0)
    assert_small(f"angle of link {ternary} − direction BD", wrapped(m.angle(ternary) - np.angle(d - b)), 1.0)


CHECKS = {"RRR": check_rrr, "RRP": check_rrp, "RPR": check_rpr, "PRP": check_prp, "RPP": check_rpp, "triad": check_triad}


def test_every_group_satisfies_its_closure_equations(mechanism_motion):
    m = mechanism_motion
    assert m.mechanism.groups, "every fixture has at least one group"
    for group in m.mechanism.groups:
        CHECKS[group.kind](m, group)


# --- named points -------------------------------------------------------------------------------

def test_named_points_sit_where_they_are_defined(mechanism_motion):
    """P = from + (at + i·offset)·direction at every position, the direction along from→toward
    (or along the slide, when toward slides on the link: in the sense toward the slider at the scene's first
    driver value; the slide's own sense where the slider is level with from there)."""
    m = mechanism_motion
    for spec in m.scene.points:
        start, point = m.r(spec.start), m.r(spec.name)
        if spec.toward in m.mechanism.fixed_on.get(spec.link, ()):
            chord = m.r(spec.toward) - start
            direction = chord / np.abs(chord)
        else:
            direction = m.direction(spec.link) * m.mechanism.sliding_on[spec.link][spec.toward]
            first = graphplan.solve(m.scene, driver=[first_value(m.mechanism)])
            line = np.exp(1j * first.link(spec.link).angle[0]) * m.mechanism.sliding_on[spec.link][spec.toward]
            ahead = first.point(spec.toward).r[0] - first.point(spec.start).r[0]
            if dot(line, complex(*ahead)) < -1e-9 * m.size:
                direction = -direction
        expected = start + (spec.at + 1j * spec.offset) * direction
        assert_small(f"{spec.name} − its definition", point - expected, m.size)


def test_named_points_keep_their_distances_to_the_points_of_their_link(mechanism_motion):
    m = mechanism_motion
    for spec in m.scene.points:
        point = m.r(spec.name)
        for other in sorted(m.mechanism.fixed_on.get(spec.link, ())):
            if other == spec.name:
                continue
            distance = np.abs(point - m.r(other))
            assert_small(f"|{spec.name}{other}| over the positions", distance - distance[0], m.size)


# --- the ratchet fixture's dead centres, in closed form ------------------------------------------
# Dimensions from shared/fixtures-data.md, not read from the scene: O = (0, 0), C = (0, 0.55),
# lOA = 0.175, lAB = 0.55, lBC = 0.325, B left of A→C.  At a dead centre O, A, B are in line and
# lOB = lAB ± lOA; the triangle OBC then fixes the direction of OB by the law of cosines.

L_OA, L_AB, L_BC, L_OC = 0.175, 0.55, 0.325, 0.55


def direction_of_b(ob: float) -> float:
    """Angle of OB from +x with B on the left side (x < 0), C straight above O."""
    return math.pi / 2 + math.acos((ob * ob + L_OC * L_OC - L_BC * L_BC) / (2 * ob * L_OC))


EXTENDED = direction_of_b(L_OA + L_AB)                          # A on OB: crank along OB
FOLDED = (direction_of_b(L_AB - L_OA) + math.pi) % (2 * math.pi)  # A opposite B


def test_ratchet_dimensions_are_those_of_the_data_page():
    scene = graphplan.load(RATCHET)
    assert scene.frame_points["O"] == 0j and scene.frame_points["C"] == 0.55j
    assert scene.driver.length == L_OA
    assert scene.groups[0].lengths == (L_AB, L_BC)
    assert math.degrees(EXTENDED) == pytest.approx(115.048, abs=5e-4)


def test_ratchet_first_position_is_the_extended_dead_centre():
    scene = graphplan.load(RATCHET)
    motion = graphplan.solve(scene)
    assert wrapped(motion.driver[0] - EXTENDED) == pytest.approx(0.0, abs=1e-12)
    o, a, b = (motion.point(n).r[0] for n in "OAB")
    oa, ob = complex(*(a - o)), complex(*(b - o))
    assert abs(cross(oa, ob)) <= TIGHT * abs(oa) * abs(ob), "O, A, B in line"
    assert dot(oa, ob) > 0, "A between O and B"
    assert abs(ob) == pytest.approx(L_OA + L_AB, abs=TIGHT * L_OC)
    sweep = graphplan.solve(scene, driver=motion.driver[0] + scene.driver.sense * 2 * np.pi * np.arange(DENSE) / DENSE)
    omega4 = float(np.max(np.abs(sweep.link(4).omega)))
    assert abs(motion.link(4).omega[0]) <= TIGHT * omega4, "the rocker is at rest at its extreme"


def test_ratchet_rocker_reverses_at_the_closed_form_dead_centres():
    scene = graphplan.load(RATCHET)
    step = 1e-6
    angles = [EXTENDED - step, EXTENDED + step, FOLDED - step, FOLDED + step]
    omega4 = graphplan.solve(scene, driver=angles).link(4).omega
    # The crank turns clockwise: decreasing φ.  Through the extended dead centre the rocker goes
    # from cw (idle) to ccw (working); through the folded one, back.
    assert omega4[1] < 0 < omega4[0]
    assert omega4[2] < 0 < omega4[3]
    at = graphplan.solve(scene, driver=[EXTENDED, FOLDED])
    sweep = graphplan.solve(scene, driver=2 * np.pi * np.arange(DENSE) / DENSE)
    scale = float(np.max(np.abs(sweep.link(4).omega)))
    assert np.all(np.abs(at.link(4).omega) <= TIGHT * scale), "the rocker is at rest at both dead centres"


def test_ratchet_working_stroke_takes_169_95_degrees_of_crank_rotation():
    from graphplan.positions import make_positions

    scene = graphplan.load(RATCHET)
    positions = make_positions(build(scene))
    start, end = positions.extremes
    assert wrapped(start - EXTENDED) == pytest.approx(0.0, abs=1e-12)
    assert wrapped(end - FOLDED) == pytest.approx(0.0, abs=1e-12)
    working = math.degrees((EXTENDED - FOLDED) % (2 * math.pi))   # clockwise from extended to folded
    assert working == pytest.approx(169.95, abs=5e-3)
    assert math.degrees((start - end) % (2 * math.pi)) == pytest.approx(working, abs=1e-9)
    # 30° steps from the start: positions 0…5 (0°…150°) fall in the working stroke, 6…11 in the idle.
    assert positions.strokes == ("working",) * 6 + ("idle",) * 6


# --- an extreme exactly at the start of the bracketing sweep -------------------------------------

def test_extremes_of_a_horizontal_scotch_yoke_at_crank_angles_0_and_180():
    from graphplan.positions import make_positions

    scene = graphplan.load(FIXTURE_DIR / "scotch_yoke.toml")
    (yoke,) = scene.groups
    horizontal = dataclasses.replace(yoke, guide=dataclasses.replace(yoke.guide, through=(0.0, 0.0), angle=0.0))
    # The plunger's resisting load turned with the guide: square to it, it would resist no motion and is refused.
    (plunger,) = scene.loads
    scene = dataclasses.replace(scene, groups=(horizontal,), loads=(dataclasses.replace(plunger, angle_deg=180.0),))
    # x = r·cos φ, the crank counter-clockwise: the yoke moves forward (+x) from φ = 180° to 360°.
    start, end = make_positions(build(scene)).extremes
    assert wrapped(start - math.pi) == pytest.approx(0.0, abs=1e-12)
    assert wrapped(end) == pytest.approx(0.0, abs=1e-12)


# --- the zero of a speed on its bracket ----------------------------------------------------------

def test_a_zero_is_the_root_of_the_interpolant_where_the_speed_is_smooth_and_brent_s_where_it_is_not():
    from scipy.optimize import brentq

    from graphplan.positions import _zero_between

    lo, hi = 1.0, 1.0 + math.radians(0.5)
    root = 1.0 + math.radians(0.2)

    def smooth(angles):
        return np.sin(np.asarray(angles) - root) * np.exp(np.asarray(angles))

    def kinked(angles):  # twice as steep past the zero: no polynomial follows it there
        x = np.asarray(angles) - root
        return np.where(x < 0, x, 2 * x + 50 * x ** 2)

    assert _zero_between(smooth, lo, hi) == pytest.approx(root, abs=4e-16)
    found = _zero_between(kinked, lo, hi)
    assert found == pytest.approx(root, abs=1e-14)
    assert found == brentq(lambda a: float(kinked([a])[0]), lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps,
                           maxiter=200)


def test_check_and_the_note_give_the_ratchet_s_strokes_and_their_ratio_from_its_dead_centres(tmp_path, capsys):
    import json
    import re

    from graphplan.cli import main

    working = math.degrees((EXTENDED - FOLDED) % (2 * math.pi))   # the crank turns clockwise, extended to folded
    idle = 360.0 - working
    assert main(["check", str(RATCHET)]) == 0
    line = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("strokes:"))
    shown = [float(value) for value in re.findall(r"= ([\d.]+)", line)]
    assert shown == pytest.approx([working, idle, working / idle], abs=6e-3)
    assert main(["run", str(RATCHET), "--out", str(tmp_path / "out"), "--only", "note", "--locale", "en"]) == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    said = re.search(r"φw = ([\d.]+)° in the working stroke and φi = ([\d.]+)° .* K = φw/φi = ([\d.]+)\.", note)
    assert [float(value) for value in said.groups()] == pytest.approx([working, idle, working / idle], rel=1e-4)
    # The ratchet works in its quicker stroke: the note says K < 1 is that, not the usual quick return.
    assert working < idle and "K < 1: the working stroke is the quicker of the two" in note
    strokes = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))["strokes"]
    assert [strokes["working_deg"], strokes["idle_deg"], strokes["time_ratio"]] == pytest.approx(
        [working, idle, working / idle], rel=1e-10)
