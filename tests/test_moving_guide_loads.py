"""Loads on a slider whose guide itself moves, against the principle of virtual work over finite differences.

A block sliding in a turning slotted lever (an RPR's block, a PRP's block in the lever's slot, a triad's slider
on a rocking link) or in a translating yoke (an RPP's block) carries a force of the scene's `[[loads]]`.  Nothing
here reads graphplan's velocities: every speed is a central difference of the analytic positions
(``graphplan.solve`` at φ ± h), and

* the balancing moment of the linear system, of the force polygons and of Zhukovsky's lever must be the one of
  virtual work, ``Mb·ω1 = −Σ(F·v + M·ω + G·vS − m·aS·vS − J·ε·ω)``, ``v`` the absolute velocity of the point an
  external force acts at (a resisting force turned against that point's motion along its line, a resisting moment
  on a block against the turning it shares with its lever; a load of one stroke acting where the working link
  moves in that stroke's sense);
* the dynamics' reduced moment must carry the loads' and the weights' power, ``Me·|ω1| = Σ(F·v + G·vS)``;
* over the cycle the driver's work without friction (``cycle_work``, ``∫Mb0 dφ``) and the reduced moment's work
  (``∫Me dψ``) must be the loads' work, minus and plus ``∮F·ds``, summed along the path sampled densely.

A force between the block and its guide (an action–reaction pair, a hydraulic cylinder's pressure) is no key of
its own: a load acts on one link at a point fixed on it, along a direction fixed on the frame.  On a translating
guide it is two loads, the action on the block at its pin and the reaction on the guide (whose every point
moves alike), each along the slot; its sense against the relative sliding comes from the block's own strokes
(``stroke = { link = block }``, forward along the slot), a load a stroke.  Its power is then F·(vA − vguide), the
relative sliding's; that is checked against the sliding's finite difference.  (The strokes are the block's
absolute motion along its slot: in a yoke whose slot is square to its guide, as here, that is its sliding; in an
oblique one it is not, and such a pair would help the sliding where the two differ in sense.)  On a turning guide
no such pair can be written: the lever's point under the block is fixed on no link (``A4`` moves along the lever),
and a direction that turns with the slot is not a load's.  The pair the scene does express on any guide is the
friction in the slide (``[[friction]]``): its power, −f′·|N|·|vrel| with vrel the sliding by differences, and the
journals' −ρ·|R|·|ω_rel|, must close the balance with friction of the linear system, the polygons and the lever,
and summed over the turn make the cycle's A − A0.
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import trapezoid
from scipy.optimize import brentq

import graphplan
from graphplan.analysis import analyse
from graphplan.dynamics import equivalent_model_of
from graphplan.loads import activity_at, link_loads, motion_state
from graphplan.scene import loads as scene_of_text
from graphplan.statics import equilibrium

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"

# 4th-order central stencils over −2h … +2h; h of a velocity small, of an acceleration larger (rounding / h²).
OFFSETS = (-2, -1, 0, 1, 2)
FIRST = np.array([1.0, -8.0, 0.0, 8.0, -1.0]) / 12.0
SECOND = np.array([-1.0, 16.0, -30.0, 16.0, -1.0]) / 12.0
H_VELOCITY, H_ACCELERATION = 1e-5, 1e-3
# Samples of the turn the loads' work is summed over: the error, where a resisting force turns round, is of the
# step squared.
PATH_SAMPLES = 36000
# A crank pin's friction circle, so that the analysis works out the cycle's works (cycle_work needs friction);
# it changes nothing of the works without friction checked here.
PIN_FRICTION = '\n[[friction]]\njoint = "O"\nf = 0.05\nradius = 0.01\n'


def _force(link: int, point: str, value: float, angle: float, extra: str = "") -> str:
    return (f'\n[[loads]]\nkind = "force"\nlink = {link}\npoint = "{point}"\nvalue = {value}\nangle = {angle}\n'
            f"{extra}")


def _moment(link: int, value: float) -> str:
    return f'\n[[loads]]\nkind = "moment"\nlink = {link}\nvalue = {value}\nresisting = true\n'


def _variant(fixture: str, added: str, group: str = "") -> graphplan.Scene:
    """The fixture with its own loads taken off (their windows are shares of a stroke this file does not work out)
    and ``added`` put on, ``group`` added after its groups, and the crank pin's friction."""
    text = (FIXTURES / f"{fixture}.toml").read_text(encoding="utf-8")
    start, end = text.index("\n[[loads]]"), text.index("\n[positions]")
    text = text[:start] + added + PIN_FRICTION + text[end:]
    if group:
        assert text.count("\n[points]") == 1
        text = text.replace("\n[points]", group + "\n[points]")
    return scene_of_text(text)


# The yoke's slot runs along the guide's 90° turned by the group's 90°: 180°, so the block's forward stroke (along
# its slot) is toward −x.  A pair resisting the block's sliding in the yoke: on the block against its motion along
# the slot, on the yoke the other way, a pair for each stroke of the block.
_FORWARD = 'during = "working"\nstroke = { link = 3, sense = "forward" }\n'
_BACKWARD = 'during = "working"\nstroke = { link = 3, sense = "backward" }\n'
_CYLINDER = 700.0
_PAIR_IN_THE_YOKE = (_force(3, "A", _CYLINDER, 0.0, _FORWARD) + _force(4, "B", _CYLINDER, 180.0, _FORWARD)
                     + _force(3, "A", _CYLINDER, 180.0, _BACKWARD) + _force(4, "B", _CYLINDER, 0.0, _BACKWARD))

# A triad hung on the ratchet's coupler 3 (at E) and rocker 4 (at S4), its slider 7 at L running on the rocker.
_TRIAD_ON_THE_ROCKER = """
[[groups]]
kind = "triad"
links = [5, 6, 7, 8]
joints = ["E", "G", "S4", "K", "C", "L"]
lengths = [0.26, 0.17]
guides = { L = { link = 4, angle = 60.0 } }
sides = [0.15, 0.17, 0.18]
near = { G = [-0.58, 0.0], K = [-0.19, 0.54], L = [-0.25, 0.12] }
"""
_TRIAD_MASSES = """
[links.7]
mass = 2.5
centre = "L"
[links.8]
mass = 4.0
centre = "G"
inertia = 0.02
"""

# Groups hung on the ratchet's rocker 4 (through C) and coupler 3 (at A, E): links 5, 6.
_ON_THE_ROCKER = {
    "RRP": '\n[[groups]]\nkind = "RRP"\nlinks = [5, 6]\njoints = ["E", "K"]\nlength = 0.45\n'
           'guide = { link = 4, through = "C", angle = 20.0 }\nassembly = "forward"\n',
    "RPP": '\n[[groups]]\nkind = "RPP"\nlinks = [5, 6]\njoints = ["E", "K"]\n'
           'guide = { link = 4, through = "C", angle = 20.0 }\nangle = 70.0\n',
    "PRP": '\n[[groups]]\nkind = "PRP"\nlinks = [5, 6]\njoints = ["K"]\n'
           'guides = [{ link = 4, through = "C", angle = 0.0 }, { link = 3, through = "A", angle = 30.0 }]\n'
           'offsets = [0.01, -0.02]\n',
}
_MASSES_5_6 = '\n[links.5]\nmass = 1.5\ncentre = "E"\n[links.6]\nmass = 2.5\ncentre = "K"\n'

# Each a scene whose block or slider on a moving guide carries a force (some cases a force on another link too).
CASES = {
    # Rotating guides.
    "block in the slotted lever": lambda: _variant(
        "quick_return_slotted_lever", _force(3, "A", 300.0, 30.0, "resisting = true\n")
        + _force(3, "A", 150.0, 250.0) + _moment(3, 40.0)),
    "PRP block in the lever's upper slot": lambda: _variant(
        "tangent_mechanism_prp", _force(5, "B", 400.0, 100.0, "resisting = true\n")),
    "block in the shaper's slotted lever": lambda: _variant(
        "shaper_six_bar", _force(3, "A", 250.0, -60.0, "resisting = true\n")
        + _force(6, "E", 2000.0, 180.0, "resisting = true\n")),
    "triad's slider on the rocker": lambda: _variant(
        "ratchet_crank_rocker", _force(7, "L", 350.0, 45.0, "resisting = true\n") + _moment(7, 25.0) + _TRIAD_MASSES,
        _TRIAD_ON_THE_ROCKER),
    "RRP slider on the rocker": lambda: _variant(
        "ratchet_crank_rocker", _force(6, "K", 400.0, 20.0, "resisting = true\n") + _force(6, "K", 120.0, 270.0)
        + _MASSES_5_6, _ON_THE_ROCKER["RRP"]),
    "RPP block in a slide on the rocker": lambda: _variant(
        "ratchet_crank_rocker", _force(5, "E", 300.0, 200.0, "resisting = true\n")
        + _force(6, "K", 200.0, 110.0, "resisting = true\n") + _MASSES_5_6, _ON_THE_ROCKER["RPP"]),
    "PRP blocks on the rocker and the coupler": lambda: _variant(
        "ratchet_crank_rocker", _force(5, "K", 300.0, 75.0, "resisting = true\n")
        + _force(6, "K", 250.0, -40.0, "resisting = true\n") + _MASSES_5_6.replace('"E"', '"K"'),
        _ON_THE_ROCKER["PRP"]),
    "block in the slotted lever, in the working stroke": lambda: _variant(
        "quick_return_slotted_lever", _force(3, "A", 300.0, 30.0, 'resisting = true\nduring = "working"\n')
        + _force(3, "A", 200.0, 160.0, 'during = "idle"\n')),
    # Translating guides.
    "block in the yoke": lambda: _variant("scotch_yoke", _force(3, "A", 500.0, 0.0, "resisting = true\n")),
    "block in a yoke slot at 60°": lambda: _oblique_yoke(),
    "pair between the block and the yoke": lambda: _variant("scotch_yoke", _PAIR_IN_THE_YOKE),
}


def _oblique_yoke() -> graphplan.Scene:
    """The yoke with its slot at 60° to its guide (150° from +x), a resisting force on the block along it: the
    block's absolute motion along the slot is no longer its sliding, and the force resists the former."""
    text = (FIXTURES / "scotch_yoke.toml").read_text(encoding="utf-8")
    old = "angle  = 90.0                             # the slot"
    assert text.count(old) == 1
    text = text.replace(old, "angle  = 60.0                             # the slot")
    start, end = text.index("\n[[loads]]"), text.index("\n[positions]")
    text = text[:start] + _force(3, "A", 500.0, 150.0, "resisting = true\n") + PIN_FRICTION + text[end:]
    return scene_of_text(text)


@functools.cache
def scene(case: str) -> graphplan.Scene:
    return CASES[case]()


@functools.cache
def analysis(case: str):
    return analyse(scene(case))


def _xy(motion, name: str) -> np.ndarray:
    r = motion.point(name).r
    return r[:, 0] + 1j * r[:, 1]


def _along(direction: complex, vector) -> np.ndarray:
    return (np.conj(direction) * vector).real


class Differences:
    """Velocities and accelerations of points and links at the driver's ``values``, by central differences of the
    analytic positions alone, at the scene's ω1 (ε1 = 0 in every case)."""

    def __init__(self, scene_: graphplan.Scene, values: np.ndarray) -> None:
        assert scene_.driver.kind == "crank" and scene_.driver.epsilon == 0.0
        self.omega = scene_.driver.omega
        self._scene, self._values = scene_, values
        self.near = [graphplan.solve(scene_, driver=values + k * H_VELOCITY) for k in OFFSETS]

    @functools.cached_property
    def far(self) -> list:
        # Solved only when an acceleration is asked for: a speed's root (Brent's method) reads velocities alone.
        return [graphplan.solve(self._scene, driver=self._values + k * H_ACCELERATION) for k in OFFSETS]

    @staticmethod
    def _difference(weights, path) -> np.ndarray:
        centre = path[OFFSETS.index(0)]
        return sum(c * (f - centre) for c, f in zip(weights, path, strict=True))

    def v(self, name: str) -> np.ndarray:
        return self.omega * self._difference(FIRST, [_xy(m, name) for m in self.near]) / H_VELOCITY

    def a(self, name: str) -> np.ndarray:
        return self.omega ** 2 * self._difference(SECOND, [_xy(m, name) for m in self.far]) / H_ACCELERATION ** 2

    @staticmethod
    def _angles(motions, number: int) -> list[np.ndarray]:
        centre = np.asarray(motions[OFFSETS.index(0)].link(number).angle, dtype=float)
        return [centre + np.angle(np.exp(1j * (m.link(number).angle - centre))) for m in motions]

    def omega_of(self, number: int) -> np.ndarray:
        return self.omega * self._difference(FIRST, self._angles(self.near, number)) / H_VELOCITY

    def epsilon_of(self, number: int) -> np.ndarray:
        return self.omega ** 2 * self._difference(SECOND, self._angles(self.far, number)) / H_ACCELERATION ** 2


def _load_powers(scene_: graphplan.Scene, moving: Differences, at_rest: str = "about to begin") -> list[np.ndarray]:
    """Each scene load's power (W): F·v of its point's absolute velocity, a resisting force turned against the
    point's motion along its line, a load of one stroke acting where its link moves in that stroke's sense.  Where
    that link is at rest (an extreme position), ``at_rest`` says which stroke it is in: the one about to begin (the
    analysed positions: an extreme belongs to it), or ``"working"``, ``"idle"`` (a switch's two sides in a sweep,
    each of which is in the stroke on its side)."""
    powers = []
    for load in scene_.loads:
        assert load.diagram is None
        if load.kind == "moment":   # its "along" the link's turning
            along = moving.omega_of(load.link)
        else:
            along = _along(np.exp(1j * math.radians(load.angle_deg)), moving.v(load.point))
        force = -load.value * np.sign(along) if load.resisting else np.full_like(along, load.value)
        if load.during != "always":
            speed = _stroke_speed(scene_, load, moving.v, moving.omega_of)
            rate = _stroke_speed(scene_, load, moving.a, moving.epsilon_of)
            resting = np.abs(speed) <= 1e-6 * np.max(np.abs(speed))
            acting = (np.where(resting, rate, speed) > 0) == (load.during == "working")
            if at_rest != "about to begin":
                acting = np.where(resting, at_rest == load.during, acting)
            force = np.where(acting, force, 0.0)
        powers.append(force * along)
    return powers


def _stroke_speed(scene_: graphplan.Scene, load, velocity_of, turning_of) -> np.ndarray:
    """The speed (or the rate, or the step) of the link whose strokes ``load`` acts in, positive in its working
    stroke: a block's along its yoke's slot (the yoke moves square to it), else the working link's turning."""
    if load.stroke is not None:
        slot, pin = _slot(scene_, load.stroke.link)
        return (1.0 if load.stroke.sense == "forward" else -1.0) * _along(slot, velocity_of(pin))
    working = scene_.positions.working
    assert working.sense in ("ccw", "cw")
    return (1.0 if working.sense == "ccw" else -1.0) * turning_of(working.link)


def _slot(scene_: graphplan.Scene, block: int) -> tuple[complex, str]:
    """The direction of a yoke's slot (its guide's turned by the group's angle) and the block's pin."""
    (group,) = scene_.groups
    assert group.links[0] == block and group.guide.link is None
    return np.exp(1j * (group.guide.angle + group.angle)), group.joints[0]


def _weights_power(scene_: graphplan.Scene, moving: Differences) -> np.ndarray:
    total = 0.0
    for spec in scene_.links.values():
        if spec.mass > 0:
            total = total - spec.mass * scene_.gravity * moving.v(spec.centre).imag
    return total


def _inertia_power(scene_: graphplan.Scene, moving: Differences) -> np.ndarray:
    """−m·aS·vS − J·ε·ω of every link: d'Alembert's loads' power."""
    total = 0.0
    for number, spec in scene_.links.items():
        if spec.mass > 0:
            total = total - spec.mass * _along(moving.a(spec.centre), moving.v(spec.centre))
        if spec.inertia > 0:
            total = total - spec.inertia * moving.epsilon_of(number) * moving.omega_of(number)
    return total


@functools.cache
def at_positions(case: str) -> Differences:
    """The differences at the analysed positions, solved once for the tests that read them there."""
    return Differences(scene(case), np.asarray(analysis(case).motion.driver, dtype=float))


@functools.cache
def virtual_work(case: str) -> np.ndarray:
    """The balancing moment of virtual work at the analysed positions."""
    scene_ = scene(case)
    moving = at_positions(case)
    total = sum(_load_powers(scene_, moving), _weights_power(scene_, moving) + _inertia_power(scene_, moving))
    return -total / scene_.driver.omega


def _relative(found, expected) -> float:
    found, expected = np.asarray(found, dtype=float), np.asarray(expected, dtype=float)
    return float(np.max(np.abs(found - expected)) / np.max(np.abs(expected)))


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_linear_systems_balancing_moment_is_that_of_virtual_work(case):
    found = analysis(case).equilibrium.balancing
    assert _relative(found, virtual_work(case)) < 1e-7


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_polygons_and_the_lever_give_the_balancing_moment_of_virtual_work(case):
    expected = virtual_work(case)
    scale = float(np.max(np.abs(expected)))
    drawn = [plan for plan in analysis(case).plans if plan.forces is not None]
    assert drawn
    for plan in drawn:
        assert plan.forces.balancing == pytest.approx(expected[plan.index], abs=1e-7 * scale), plan.number
        assert plan.lever.balancing == pytest.approx(expected[plan.index], abs=1e-7 * scale), plan.number


@functools.cache
def model(case: str):
    # "none": both sides as the loads give them, so that Me is the loads' and the weights' alone.
    return equivalent_model_of(scene(case), 360, constant="none")


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_reduced_moment_carries_the_loads_power(case):
    """At a switch of a load's stroke (its link at rest) the model's sweep holds both sides, a sample each: either
    value is the moment there."""
    scene_ = scene(case)
    reduced = model(case)
    moving = Differences(scene_, np.asarray(reduced.driver, dtype=float))
    found = reduced.moment * abs(scene_.driver.omega)
    weights = _weights_power(scene_, moving)
    expected = sum(_load_powers(scene_, moving), weights)
    scale = float(np.max(np.abs(expected)))
    sides = [sum(_load_powers(scene_, moving, side), weights) for side in ("working", "idle")]
    off = np.abs(found - expected) > 1e-7 * scale
    for index in np.flatnonzero(off):
        assert min(abs(found[index] - side[index]) for side in sides) <= 1e-7 * scale, (index, reduced.driver[index])
    assert np.count_nonzero(off) <= 2 * sum(load.during != "always" for load in scene_.loads)


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_reduced_moment_read_off_the_velocity_plans_carries_the_loads_power(case):
    """The equivalent model's Me at the plan positions, from the velocity plans as constructed."""
    scene_ = scene(case)
    analysed = analysis(case)
    moving = at_positions(case)
    expected = sum(_load_powers(scene_, moving), _weights_power(scene_, moving)) / abs(scene_.driver.omega)
    reductions = equivalent_model_of(analysed, 12, constant="none").plans
    assert reductions
    for plan in reductions:
        assert plan.moment == pytest.approx(expected[plan.index], abs=1e-7 * np.max(np.abs(expected))), plan.number


@functools.cache
def _path_work(case: str) -> tuple[float, float]:
    """The loads' work over the crank's turn from the first position, ∮F·ds along the path at PATH_SAMPLES steps
    (each step's force against that step's motion along its line where it resists), and ∮|F·ds|.  Where a load's
    stroke turns back, the crank's angle is found (Brent's method on the stroke's link's speed by differences)
    and put among the steps, so that no step straddles the window's edge."""
    scene_ = scene(case)
    start = float(analysis(case).motion.driver[0])
    sense = math.copysign(1.0, scene_.driver.omega)
    sweep = start + sense * np.linspace(0.0, 2.0 * math.pi, PATH_SAMPLES + 1)
    sweep = np.sort(np.concatenate([sweep, *(_stroke_ends(case, _stroke_of(scene_, load)) for load in scene_.loads
                                             if load.during != "always")]))[::int(sense)]
    path = graphplan.solve(scene_, driver=sweep)
    work = given = 0.0
    for load in scene_.loads:
        if load.kind == "moment":
            step = np.diff(np.unwrap(path.link(load.link).angle))
        else:
            step = _along(np.exp(1j * math.radians(load.angle_deg)), np.diff(_xy(path, load.point)))
        force = -load.value * np.sign(step) if load.resisting else np.full_like(step, load.value)
        if load.during != "always":
            working = _stroke_speed(scene_, load, lambda name: np.diff(_xy(path, name)),
                                    lambda number: np.diff(np.unwrap(path.link(number).angle))) > 0
            force = np.where(working == (load.during == "working"), force, 0.0)
        work += float(np.sum(force * step))
        given += float(np.sum(np.abs(force * step)))
    return work, given


def _stroke_of(scene_: graphplan.Scene, load) -> tuple[bool, int, str]:
    """What :func:`_stroke_speed` reads of ``load`` (its own stroke's or the working stroke's link and sense; not
    the key path the stroke was read at): loads of one stroke share their stroke's ends."""
    stroke = load.stroke if load.stroke is not None else scene_.positions.working
    return load.stroke is not None, stroke.link, stroke.sense


@functools.cache
def _stroke_ends(case: str, stroke) -> np.ndarray:
    """The crank's angles of the turn :func:`_path_work` sums over where the link of ``stroke`` (a load's, as
    :func:`_stroke_of` gives it) turns back; the same for every load of that stroke, so found once."""
    scene_ = scene(case)
    load = next(load for load in scene_.loads if load.during != "always" and _stroke_of(scene_, load) == stroke)
    start = float(analysis(case).motion.driver[0])
    sense = math.copysign(1.0, scene_.driver.omega)
    sweep = start + sense * np.linspace(0.0, 2.0 * math.pi, PATH_SAMPLES + 1)

    def speed(angles) -> np.ndarray:
        moving = Differences(scene_, np.atleast_1d(np.asarray(angles, dtype=float)))
        return _stroke_speed(scene_, load, moving.v, moving.omega_of)

    coarse = sweep[::20]
    speeds = speed(coarse)
    crossed = np.flatnonzero(speeds[:-1] * speeds[1:] < 0)
    return np.array([brentq(lambda angle: float(speed(angle)[0]), coarse[k], coarse[k + 1], xtol=1e-13)
                     for k in crossed])


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_drivers_work_over_the_cycle_is_what_the_loads_take(case):
    """∫Mb0 dφ integrates the inertia loads' power too, nought over the cycle but left by Simpson's rule at the
    cycle's 1° steps: where the PRP's guides on the rocker and the coupler cross at 12°, at 6·10⁻⁶ of the loads'
    work (it falls as the step's fourth power: 10⁻⁸ at 0.25°, the masses taken off 6·10⁻⁸); elsewhere below 10⁻⁷."""
    work, given = _path_work(case)
    cycle = analysis(case).cycle
    assert cycle is not None
    tolerance = 1e-5 if case == "PRP blocks on the rocker and the coupler" else 1e-7
    assert cycle.without_friction == pytest.approx(-work, abs=tolerance * given)


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_reduced_moments_work_over_the_cycle_is_the_loads(case):
    work, given = _path_work(case)
    reduced = model(case)
    assert float(reduced.integral(reduced.moment)[-1]) == pytest.approx(work, abs=1e-6 * given)


def test_the_pair_in_the_yoke_takes_the_power_of_the_sliding():
    """The four loads of the pair, summed, take F·|vrel| with vrel the block's sliding in the yoke (A's difference
    less the yoke's point B's), all the cycle: 4·F·r over a turn."""
    case = "pair between the block and the yoke"
    scene_ = scene(case)
    moving = at_positions(case)
    sliding = moving.v("A") - moving.v("B")
    assert np.max(np.abs(sliding.imag)) < 1e-9
    np.testing.assert_allclose(sum(_load_powers(scene_, moving)), -_CYLINDER * np.abs(sliding.real), atol=1e-9)
    work, _ = _path_work(case)
    assert work == pytest.approx(-4.0 * _CYLINDER * scene_.driver.length, rel=1e-9)


def test_a_load_on_the_lever_under_the_block_is_refused_naming_where():
    """The reaction half of a pair in a turning slot would act on the lever at the block's pin: that point (``A4``)
    slides along the lever, is fixed on no link, and a load there is refused at its key."""
    text = (FIXTURES / "quick_return_slotted_lever.toml").read_text(encoding="utf-8")
    text = text.replace("\n[positions]", _force(4, "A4", 100.0, 0.0) + "\n[positions]")
    with pytest.raises(graphplan.SceneError) as refused:
        analyse(scene_of_text(text))
    assert "loads[1].point" in str(refused.value) and "fixed on link 4" in str(refused.value)


# The one pair between a block and its guide the scene does express on a turning guide: the friction in the slide
# (`[[friction]]`), f′·|N| against the relative sliding, on the block and back on the guide.  Its power is
# −f′·|N|·|vrel|, vrel the block's pin's velocity less that of the guide's material point under it; a journal's
# −ρ·|R|·|ω_rel|.  The reactions are the linear system's with friction; every velocity is a difference.
def _friction(joint: str, links: tuple[int, int] | None, f: float, radius: float | None = None) -> str:
    entry = f'\n[[friction]]\njoint = "{joint}"\n' + (f"links = {list(links)}\n" if links else "") + f"f = {f}\n"
    return entry + (f"radius = {radius}\n" if radius else "")


FRICTION_CASES = {
    "block in the slotted lever": lambda: _variant(
        "quick_return_slotted_lever", _force(3, "A", 300.0, 30.0, "resisting = true\n") + _moment(3, 40.0)
        + _friction("A", (4, 3), 0.15) + _friction("C", None, 0.1, 0.02)),
    "PRP block in the lever's upper slot": lambda: _variant(
        "tangent_mechanism_prp", _force(5, "B", 400.0, 100.0, "resisting = true\n") + _friction("B", (4, 5), 0.12)
        + _friction("B", (1, 6), 0.1)),
    "triad's slider on the rocker": lambda: _variant(
        "ratchet_crank_rocker", _force(7, "L", 350.0, 45.0, "resisting = true\n") + _TRIAD_MASSES
        + _friction("L", (4, 7), 0.15), _TRIAD_ON_THE_ROCKER),
    "RPP block in a slide on the rocker": lambda: _variant(
        "ratchet_crank_rocker", _force(5, "E", 300.0, 200.0, "resisting = true\n") + _MASSES_5_6
        + _friction("E", (6, 5), 0.15) + _friction("K", (4, 6), 0.1), _ON_THE_ROCKER["RPP"]),
    "block in the yoke": lambda: _variant(
        "scotch_yoke", _force(3, "A", 500.0, 0.0, "resisting = true\n") + _friction("A", (4, 3), 0.12)
        + _friction("B", (1, 4), 0.1)),
}


@functools.cache
def rubbing(case: str):
    return analyse(FRICTION_CASES[case]())


def _friction_loss(analysed, moving: Differences, reactions) -> np.ndarray:
    """Σ f′·|N|·|vrel| + Σ ρ·|R|·|ω_rel| (W): what the pairs' friction takes, from ``reactions`` (by name)."""
    scene_ = analysed.scene
    frame = scene_.frame_link

    def omega(number: int):
        return 0.0 if number == frame else moving.omega_of(number)

    loss = 0.0
    for pair in analysed.friction:
        size = np.abs(reactions[pair.reaction])
        if pair.sliding:
            guide_velocity = 0.0
            if pair.source != frame:
                other = min(analysed.mechanism.fixed_on[pair.source])
                arm = _xy(moving.near[OFFSETS.index(0)], pair.joint) - _xy(moving.near[OFFSETS.index(0)], other)
                guide_velocity = moving.v(other) + 1j * omega(pair.source) * arm
            loss = loss + pair.coefficient * size * np.abs(moving.v(pair.joint) - guide_velocity)
        else:
            loss = loss + pair.radius * size * np.abs(omega(pair.target) - omega(pair.source))
    return loss


@pytest.mark.parametrize("case", sorted(FRICTION_CASES))
def test_the_balancing_moment_with_the_friction_of_a_moving_slide_is_that_of_virtual_work(case):
    analysed = rubbing(case)
    scene_ = analysed.scene
    moving = Differences(scene_, np.asarray(analysed.motion.driver, dtype=float))
    found = analysed.with_friction
    assert not found.locked.any()
    reactions = {reaction.name: reaction.force for reaction in found.reactions}
    power = sum(_load_powers(scene_, moving), _weights_power(scene_, moving) + _inertia_power(scene_, moving))
    expected = -(power - _friction_loss(analysed, moving, reactions)) / scene_.driver.omega
    assert _relative(found.balancing, expected) < 1e-7
    scale = float(np.max(np.abs(expected)))
    drawn = [plan for plan in analysed.plans if plan.with_friction is not None]
    assert drawn
    for plan in drawn:
        assert plan.with_friction.balancing == pytest.approx(expected[plan.index], abs=1e-7 * scale), plan.number
        assert plan.lever_with_friction.balancing == pytest.approx(expected[plan.index], abs=1e-7 * scale), (
            plan.number)


def _relative_velocities(analysed, moving: Differences) -> list[np.ndarray]:
    """Each pair's relative motion: a slide's relative velocity turned with its guide link (so that it keeps its
    line), a journal's ω_rel (real)."""
    frame = analysed.scene.frame_link
    centre = moving.near[OFFSETS.index(0)]

    def omega(number: int):
        return 0.0 if number == frame else moving.omega_of(number)

    found = []
    for pair in analysed.friction:
        if not pair.sliding:
            found.append(np.asarray(omega(pair.target) - omega(pair.source), dtype=complex))
            continue
        guide_velocity, turned = 0.0, 1.0
        if pair.source != frame:
            other = min(analysed.mechanism.fixed_on[pair.source])
            arm = _xy(centre, pair.joint) - _xy(centre, other)
            guide_velocity = moving.v(other) + 1j * omega(pair.source) * arm
            turned = np.exp(1j * np.asarray(centre.link(pair.source).angle, dtype=float))
        found.append((moving.v(pair.joint) - guide_velocity) * np.conj(turned))
    return found


def _turning_back(analysed, moving: Differences, ways: list[complex] | None = None
                  ) -> tuple[list[np.ndarray], list[complex]]:
    """Each motion whose turning back turns a friction or a resisting load round (and with it every pair's reaction,
    and so its loss, jumps), signed: a pair's relative motion (a slide's along ``ways``, by default the way it points
    where it is fastest), a resisting load's point's speed along its line or its link's ω."""
    velocities = _relative_velocities(analysed, moving)
    if ways is None:
        ways = [velocity[np.argmax(np.abs(velocity))] / np.max(np.abs(velocity)) for velocity in velocities]
    motions = [_along(way, velocity) for way, velocity in zip(ways, velocities, strict=True)]
    for load in analysed.scene.loads:
        if load.resisting:
            motions.append(moving.omega_of(load.link) if load.kind == "moment" else
                           _along(np.exp(1j * math.radians(load.angle_deg)), moving.v(load.point)))
    return motions, ways


def _reversals(analysed, sweep: np.ndarray) -> np.ndarray:
    """The crank's angles in ``sweep`` where a motion of :func:`_turning_back` turns back (Brent's method)."""
    scene_ = analysed.scene
    motions, ways = _turning_back(analysed, Differences(scene_, sweep))
    signs = np.sign(np.array(motions))
    found = []
    for row, step in zip(*np.nonzero(signs[:, :-1] * signs[:, 1:] < 0), strict=True):
        def motion(angle: float, row: int = row) -> float:
            return float(_turning_back(analysed, Differences(scene_, np.array([angle])), ways)[0][row][0])
        found.append(brentq(motion, sweep[step], sweep[step + 1], xtol=1e-13))
    return np.array(found)


@pytest.mark.parametrize("case", sorted(FRICTION_CASES))
def test_the_friction_work_over_the_cycle_is_what_the_pairs_take(case):
    """A − A0 of the cycle (``cycle_work``) against ∮ loss dt: the loss summed along the turn by the trapezoid at
    0.1° between the places where a pair's relative motion turns back (found by Brent's method on the differences),
    each put in with a sample 10⁻⁷ rad to either side.  graphplan's Simpson's rule at 1° leaves up to 2·10⁻⁵ of the
    friction's work (where a slide's |N| turns a corner unseen; it comes within 8·10⁻⁷ at 0.25°)."""
    analysed = rubbing(case)
    scene_, mechanism = analysed.scene, analysed.mechanism
    sense = math.copysign(1.0, scene_.driver.omega)
    sweep = float(analysed.motion.driver[0]) + sense * np.linspace(0.0, 2.0 * math.pi, 3601)
    reversals = _reversals(analysed, sweep)
    sweep = np.sort(np.concatenate([sweep, reversals - 1e-7, reversals + 1e-7]))[::int(sense)]
    motion = graphplan.solve(scene_, driver=sweep)
    loads = link_loads(mechanism, motion_state(motion), activity_at(mechanism, analysed.positions, sweep))
    found = equilibrium(mechanism, motion, loads, analysed.friction)
    assert not found.locked.any()
    reactions = {reaction.name: reaction.force for reaction in found.reactions}
    loss = _friction_loss(analysed, Differences(scene_, sweep), reactions)
    expected = trapezoid(loss, np.abs(sweep - sweep[0])) / abs(scene_.driver.omega)
    assert analysed.cycle.friction == pytest.approx(expected, rel=3e-5)
