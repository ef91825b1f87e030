"""Velocities and accelerations of the analytic solver against finite differences of its positions.

The solver finds velocities and accelerations from linear equations (the plan method's vector
equations); the positions come from closed forms.  Nothing here reads those derivatives to build
the expectation: the expected values are central differences of positions alone, taken over the
driver coordinate q (crank angle φ, or slider displacement s), with the chain rule

    v = q̇·dr/dq,        a = q̇²·d²r/dq² + q̈·dr/dq

where q̇, q̈ are the driver's ω, ε (or ṡ, s̈) at the instant, as the solver takes them.

Step sizes: a 4th-order first difference with h = 1e-5 (rad, or 1e-5 of the slider's travel)
has a truncation error of order h⁴ and a rounding error of order 1e-16/h, both far below the
tolerance.  A second difference divides rounding by h², so with h = 1e-5 rounding alone would be
~1e-6 of the scale; accelerations use h = 1e-3 instead (truncation ~h⁴/90·r⁽⁶⁾ ≈ 1e-14,
rounding ~1e-10).  Tolerances are 1e-6 of the largest magnitude of the same kind over the sample.

A point that an RPR group names after the lever (``A4``: the lever's point under the block), or a
triad after its ternary link under a block in its slot (``E8``), does not follow the block's path:
its expected motion is the finite difference of the path of the link's material point that lies
under the block at the instant.

Besides every fixture, a few variants (below) cover what no fixture has: guides on moving links
for RRP and RPP, a PRP between two moving links with offsets, a slot that misses its pivot.  The
driver's ε (or s̈) is switched on in separate tests, checked exactly and by finite differences.
"""

from __future__ import annotations

import dataclasses
import functools
from pathlib import Path

import numpy as np
import pytest

import graphplan
from graphplan.mechanism import build
from graphplan.scene import loads

FIXTURE_DIR = Path(__file__).resolve().parent.parent / "fixtures"
FIXTURES = sorted(FIXTURE_DIR.glob("*.toml"))

# The triads hung on the ratchet: links 5–8, their legs from E (on the coupler 3), S4 (on the rocker 4) and the
# frame point C to the ternary link's corners G, K, L.  Each variant gives its legs' lengths, guides and slots,
# and which sketch of the corners picks its assembly.
_SWEPT_SKETCH = "{ G = [-0.58, 0.0], K = [-0.19, 0.54], L = [-0.25, 0.12] }"
_SLOTTED_SKETCH = "{ G = [-0.16, 0.55], K = [-0.05, 0.45], L = [-0.20, 0.37] }"


def _triad_on_the_ratchet(legs: str, sketch: str = _SWEPT_SKETCH) -> str:
    return ('\n[[groups]]\nkind = "triad"\nlinks = [5, 6, 7, 8]\njoints = ["E", "G", "S4", "K", "C", "L"]\n'
            f"{legs}sides = [0.15, 0.17, 0.18]\nnear = {sketch}\n")


# Variants of the fixtures for what no fixture has: guides on moving links for RRP, RPP and a triad's
# sliding leg, a PRP between two moving links with offsets, a slotted lever whose slot misses its pivot.  Each is
# a fixture's scene with a group added (links 5, 6 hung on the ratchet's rocker 4 and coupler 3)
# or changed; each assembles over the whole crank revolution.
_HUNG_ON_THE_RATCHET = {
    "ratchet+RRP-on-rocker": """
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["E", "K"]
length = 0.45
guide = { link = 4, through = "C", angle = 20.0 }
assembly = "forward"
""",
    "ratchet+RPP-on-rocker": """
[[groups]]
kind = "RPP"
links = [5, 6]
joints = ["E", "K"]
guide = { link = 4, through = "C", angle = 20.0 }
angle = 70.0
""",
    "ratchet+PRP-rocker-coupler": """
[[groups]]
kind = "PRP"
links = [5, 6]
joints = ["K"]
guides = [{ link = 4, through = "C", angle = 0.0 }, { link = 3, through = "A", angle = 30.0 }]
offsets = [0.01, -0.02]
""",
    # A triad whose slider 7 runs on the rocking link 4 (a Coriolis term), its other legs pinned to the
    # coupler 3 at E and to the rocker at S4: links 5–8.
    "ratchet+triad-slider-on-rocker": _triad_on_the_ratchet("""\
lengths = [0.26, 0.17]
guides = { L = { link = 4, angle = 60.0 } }
"""),
    # The same triad with two sliding legs: slider 6 on the rocking link 4 (a Coriolis term), slider 7 on a
    # frame guide through C; only the leg EG turns.
    "ratchet+triad-two-sliders": _triad_on_the_ratchet("""\
lengths = [0.26]
guides = { K = { link = 4, angle = 60.0 }, L = { angle = 80.0 } }
"""),
    # The leg at G a block pinned to the coupler at E, sliding in a slot of the ternary link 8 through G.
    "ratchet+triad-slot": _triad_on_the_ratchet("""\
lengths = [0.17, 0.18]
slots = { G = { angle = -77.0 } }
""", _SLOTTED_SKETCH),
    # The same slot, and slider 7 on the rocking link 4: a slot and a guide, both with a Coriolis term.
    "ratchet+triad-slot-and-guide": _triad_on_the_ratchet("""\
lengths = [0.17]
slots = { G = { angle = -77.0 } }
guides = { L = { link = 4, angle = 120.0 } }
""", _SLOTTED_SKETCH),
    # Two slots in the ternary link: the blocks pinned at E (on the coupler) and at S4 (on the rocker).
    "ratchet+triad-two-slots": _triad_on_the_ratchet("""\
lengths = [0.18]
slots = { G = { angle = -77.0 }, K = { angle = 120.0 } }
""", _SLOTTED_SKETCH),
    # All three legs sliding: slider 5 on the coupler 3 through E, slider 6 on the rocker 4, slider 7 on the frame.
    "ratchet+triad-three-sliders": _triad_on_the_ratchet("""\
guides = { G = { link = 3, angle = 120.0 }, K = { link = 4, angle = 120.0 }, L = { angle = 60.0 } }
"""),
}


def _hung_on_the_ratchet(group: str):
    def scene():
        text = (FIXTURE_DIR / "ratchet_crank_rocker.toml").read_text(encoding="utf-8")
        assert text.count("\n[points]") == 1
        return loads(text.replace("\n[points]", group + "\n[points]"))
    return scene


def _offset_slot():
    scene = graphplan.load(FIXTURE_DIR / "quick_return_slotted_lever.toml")
    (lever,) = scene.groups
    return dataclasses.replace(scene, groups=(dataclasses.replace(lever, offset=0.04),))


def square_guides():
    """The triad with a slider with its leg CD sliding too, on a frame guide through C square to F's guide: the
    guides' normals cross square at every position, so Assur's point is always where they cross."""
    text = (FIXTURE_DIR / "triad_with_slider.toml").read_text(encoding="utf-8")
    changes = {"C = [0.28, 0.0]": "C = [0.25, 0.2]",
               "guides  = { F = { angle = -30.0 } }": "guides  = { F = { angle = -30.0 }, D = { angle = 60.0 } }",
               "lengths = [0.17, 0.14]": "lengths = [0.17]",
               'S4 = { link = 4, from = "C", toward = "D", at = 0.07 }\n': "",
               'mass = 1.6\ncentre = "S4"\ninertia = 0.00261': 'mass = 1.6\ncentre = "D"'}
    for old, new in changes.items():
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    return loads(text)


VARIANTS = {name: _hung_on_the_ratchet(group) for name, group in _HUNG_ON_THE_RATCHET.items()}
VARIANTS["quick_return+slot-offset"] = _offset_slot
VARIANTS["triad_with_slider+square-guides"] = square_guides
CASES = {path.stem: functools.partial(graphplan.load, path) for path in FIXTURES} | VARIANTS


@functools.cache
def scene_of(case: str):
    """The case's scene, one for the module: a scene is frozen, and its mechanism's positions and a triad's walk,
    found at its first solve, are kept while it lives, so that the positions, the sweep and every stencil of the
    case solve it without finding them again."""
    return CASES[case]()

H_VELOCITY = 1e-5
H_ACCELERATION = 1e-3
RELATIVE_TOLERANCE = 1e-6
DENSE = 360

# 4th-order central stencils over offsets -2h, -h, 0, +h, +2h.
OFFSETS = (-2, -1, 0, 1, 2)
FIRST = np.array([1.0, -8.0, 0.0, 8.0, -1.0]) / 12.0
SECOND = np.array([-1.0, 16.0, -30.0, 16.0, -1.0]) / 12.0


def driver_rates(scene) -> tuple[float, float]:
    """q̇ and q̈ of the driver coordinate, as the scene prescribes them."""
    driver = scene.driver
    if driver.kind == "crank":
        return driver.omega, driver.epsilon
    return driver.velocity, driver.acceleration


def driver_unit(scene) -> float:
    """The scale of the driver coordinate: 1 rad for a crank, the travel for a slider."""
    driver = scene.driver
    return 1.0 if driver.kind == "crank" else abs(driver.travel[1] - driver.travel[0])


def sample(scene, which: str) -> np.ndarray:
    """The scene's own positions, or a dense sweep over the driver's cycle (or travel, or swing)."""
    positions = graphplan.solve(scene).driver
    if which == "positions":
        return positions
    driver = scene.driver
    if driver.cyclic:
        return positions[0] + driver.sense * 2.0 * np.pi * np.arange(DENSE) / DENSE
    return np.linspace(driver.travel[0], driver.travel[1], DENSE)


def coincident_points(scene) -> dict[str, int]:
    """Points a group names after a link under a block (an RPR's ``A4``, a triad's slot's ``E8``), with the link's
    number."""
    mechanism = build(scene)
    return {name: link for group in mechanism.groups for name, _, _, link in group.coincident_points()}


def complex_of(xy: np.ndarray) -> np.ndarray:
    return xy[:, 0] + 1j * xy[:, 1]


def stencil(scene, values: np.ndarray, h: float):
    """The motions at values + k·h for the stencil's offsets."""
    return [graphplan.solve(scene, driver=values + k * h) for k in OFFSETS]


def point_path(motions, name: str, lever: int | None) -> list[np.ndarray]:
    """Positions of point ``name`` over the stencil; for a lever's coincident point, the
    lever's material point that lies under the block at the centre of the stencil."""
    centre = motions[OFFSETS.index(0)]
    if lever is None:
        return [complex_of(m.point(name).r) for m in motions]
    link = centre.links[lever]
    origin = complex_of(centre.point(link.origin).r)
    local = (complex_of(centre.point(name).r) - origin) * np.conj(link.u)
    return [complex_of(m.point(link.origin).r) + m.links[lever].u * local for m in motions]


def angle_path(motions, number: int) -> list[np.ndarray]:
    """A link's angle over the stencil, unwrapped about the centre."""
    centre = motions[OFFSETS.index(0)].link(number).angle
    return [centre + np.angle(np.exp(1j * (m.link(number).angle - centre))) for m in motions]


def slide_path(motions, index: int) -> list[np.ndarray]:
    return [np.broadcast_to(m.slides[index].s, m.driver.shape) for m in motions]


def difference(weights, path) -> np.ndarray:
    """Σ c_k·f_k, taken on f_k − f_0 (the weights sum to 0) so that a large f_0 adds no rounding."""
    centre = path[OFFSETS.index(0)]
    return sum(c * (f - centre) for c, f in zip(weights, path))


def derivatives(path_v, path_a, h_v: float, h_a: float, rates):
    """Finite-difference velocity and acceleration from two stencils of positions."""
    qdot, qddot = rates
    first_v = difference(FIRST, path_v) / h_v
    first_a = difference(FIRST, path_a) / h_a
    second = difference(SECOND, path_a) / (h_a * h_a)
    return qdot * first_v, qdot * qdot * second + qddot * first_a


@functools.cache
def finite_differences(case: str, which: str):
    """Analytic and finite-difference motion of every point, link and slide of one case."""
    scene = scene_of(case)
    return compare(scene, sample(scene, which))


def compare(scene, values: np.ndarray):
    unit = driver_unit(scene)
    h_v, h_a = H_VELOCITY * unit, H_ACCELERATION * unit
    rates = driver_rates(scene)
    exact = graphplan.solve(scene, driver=values)
    around_v, around_a = stencil(scene, values, h_v), stencil(scene, values, h_a)
    levers = coincident_points(scene)
    points = {}
    for name in exact.points:
        lever = levers.get(name)
        v, a = derivatives(point_path(around_v, name, lever), point_path(around_a, name, lever), h_v, h_a, rates)
        points[name] = (complex_of(exact.point(name).v), complex_of(exact.point(name).a), v, a)
    links = {}
    for number in exact.links:
        if number == scene.frame_link:
            continue
        omega, epsilon = derivatives(angle_path(around_v, number), angle_path(around_a, number), h_v, h_a, rates)
        links[number] = (exact.link(number).omega, exact.link(number).epsilon, omega, epsilon)
    slides = {}
    for index, slide in enumerate(exact.slides):
        speed, rate = derivatives(slide_path(around_v, index), slide_path(around_a, index), h_v, h_a, rates)
        shape = exact.driver.shape
        slides[(slide.slider, slide.guide, slide.joint)] = (
            np.broadcast_to(slide.velocity, shape), np.broadcast_to(slide.acceleration, shape), speed, rate)
    return scene, points, links, slides


def assert_close(label: str, analytic, expected, scale: float) -> None:
    error = np.abs(np.asarray(analytic) - np.asarray(expected))
    worst = int(np.argmax(error))
    assert error[worst] <= RELATIVE_TOLERANCE * scale, (
        f"{label}: analytic {np.asarray(analytic)[worst]} vs finite difference {np.asarray(expected)[worst]} "
        f"at sample {worst}: error {error[worst]:.3e} > {RELATIVE_TOLERANCE:g} × {scale:.4g}")


def scales(records, scene) -> tuple[float, float]:
    """The largest analytic magnitudes of the first and of the second derivatives over all records.

    The second's scale is at least the first's times q̇ (per unit of the driver coordinate), so
    that a mechanism whose links all turn steadily (a Scotch yoke) still gets a physical scale.
    """
    first = max((float(np.max(np.abs(r[0]))) for r in records), default=0.0)
    second = max((float(np.max(np.abs(r[1]))) for r in records), default=0.0)
    second = max(second, first * abs(driver_rates(scene)[0]) / driver_unit(scene))
    assert first > 0 and second > 0, "a moving mechanism has nonzero velocities"
    return first, second


SAMPLES = ["positions", "sweep"]


@pytest.mark.parametrize("which", SAMPLES)
@pytest.mark.parametrize("case", CASES)
def test_point_velocities_and_accelerations_are_derivatives_of_positions(case, which):
    scene, points, _, _ = finite_differences(case, which)
    v_scale, a_scale = scales(points.values(), scene)
    for name, (v, a, v_fd, a_fd) in points.items():
        assert_close(f"v{name}", v, v_fd, v_scale)
        assert_close(f"a{name}", a, a_fd, a_scale)


@pytest.mark.parametrize("which", SAMPLES)
@pytest.mark.parametrize("case", CASES)
def test_angular_velocities_and_accelerations_are_derivatives_of_link_angles(case, which):
    scene, _, links, _ = finite_differences(case, which)
    assert links, "every fixture has moving links"
    w_scale, e_scale = scales(links.values(), scene)
    for number, (omega, epsilon, omega_fd, epsilon_fd) in links.items():
        assert_close(f"omega{number}", omega, omega_fd, w_scale)
        assert_close(f"epsilon{number}", epsilon, epsilon_fd, e_scale)


@pytest.mark.parametrize("which", SAMPLES)
@pytest.mark.parametrize("case", CASES)
def test_sliding_velocities_and_accelerations_are_derivatives_of_slide_coordinates(case, which):
    scene, _, _, slides = finite_differences(case, which)
    if not slides:
        pytest.skip("no sliding pair in this mechanism")
    s_scale, a_scale = scales(slides.values(), scene)
    for key, (speed, rate, speed_fd, rate_fd) in slides.items():
        slider, guide, joint = key
        assert_close(f"ṡ of link {slider} on link {guide} at {joint}", speed, speed_fd, s_scale)
        assert_close(f"s̈ of link {slider} on link {guide} at {joint}", rate, rate_fd, a_scale)


# The driver's ε (or s̈).  Positions depend on the driver coordinate q alone, r = r(q), so
#     v = q̇·r'(q),   a = q̇²·r''(q) + q̈·r'(q),
# and switching q̈ on from 0 must leave every velocity as it was and add q̈·r' = (q̈/q̇)·v to
# every acceleration; the same holds for ω, ε of every link (θ = θ(q)) and for ṡ, s̈ of every
# slide (s = s(q)).  The relation is exact, so it is checked tightly; the accelerations with q̈
# on are also checked against finite differences, which include the q̈·r' term independently.

def with_driver_acceleration(scene):
    driver = scene.driver
    if driver.kind == "crank":
        changed = dataclasses.replace(driver, epsilon=-0.35 * driver.omega * abs(driver.omega))
    else:
        span = abs(driver.travel[1] - driver.travel[0])
        changed = dataclasses.replace(driver, acceleration=-0.8 * driver.velocity * abs(driver.velocity) / span)
    return dataclasses.replace(scene, driver=changed)


@pytest.mark.parametrize("case", CASES)
def test_driver_acceleration_adds_its_tangential_term_exactly(case):
    scene = scene_of(case)
    accelerated = with_driver_acceleration(scene)
    # The reference has q̈ = 0 even where the scene gives one (the hand lever's ε2).
    rate = "epsilon" if scene.driver.kind == "crank" else "acceleration"
    scene = dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, **{rate: 0.0}))
    qdot, qddot = driver_rates(accelerated)
    assert qddot != 0.0
    values = sample(scene, "sweep")
    steady, changed = graphplan.solve(scene, driver=values), graphplan.solve(accelerated, driver=values)
    ratio = qddot / qdot
    v_scale = max(float(np.max(np.abs(steady.point(n).v))) for n in steady.points)
    a_scale = max(float(np.max(np.abs(changed.point(n).a))) for n in changed.points)
    tight = 1e-12
    for name in steady.points:
        np.testing.assert_allclose(changed.point(name).v, steady.point(name).v, rtol=0, atol=tight * v_scale,
                                   err_msg=f"v{name} must not depend on the driver's acceleration")
        expected = steady.point(name).a + ratio * steady.point(name).v
        np.testing.assert_allclose(changed.point(name).a, expected, rtol=0, atol=tight * a_scale,
                                   err_msg=f"a{name} = a(q̈=0) + (q̈/q̇)·v{name}")
    w_scale = max(float(np.max(np.abs(steady.link(n).omega))) for n in steady.links)
    e_scale = max(float(np.max(np.abs(changed.link(n).epsilon))) for n in changed.links)
    for number in steady.links:
        np.testing.assert_allclose(changed.link(number).omega, steady.link(number).omega, rtol=0, atol=tight * w_scale)
        expected = steady.link(number).epsilon + ratio * steady.link(number).omega
        np.testing.assert_allclose(changed.link(number).epsilon, expected, rtol=0, atol=tight * e_scale,
                                   err_msg=f"epsilon{number} = epsilon(q̈=0) + (q̈/q̇)·omega{number}")
    for before, after in zip(steady.slides, changed.slides):
        shape = values.shape
        speed = np.broadcast_to(before.velocity, shape)
        s_scale = float(np.max(np.abs(speed))) or 1.0
        r_scale = float(np.max(np.abs(after.acceleration))) or 1.0
        np.testing.assert_allclose(np.broadcast_to(after.velocity, shape), speed, rtol=0, atol=tight * s_scale)
        np.testing.assert_allclose(np.broadcast_to(after.acceleration, shape),
                                   np.broadcast_to(before.acceleration, shape) + ratio * speed,
                                   rtol=0, atol=tight * r_scale,
                                   err_msg=f"s̈ of link {before.slider} on link {before.guide}")


@pytest.mark.parametrize("case", CASES)
def test_driver_acceleration_against_finite_differences(case):
    accelerated = with_driver_acceleration(scene_of(case))
    scene, points, links, slides = compare(accelerated, sample(accelerated, "positions"))
    v_scale, a_scale = scales(points.values(), scene)
    for name, (v, a, v_fd, a_fd) in points.items():
        assert_close(f"v{name}", v, v_fd, v_scale)
        assert_close(f"a{name}", a, a_fd, a_scale)
    w_scale, e_scale = scales(links.values(), scene)
    for number, (omega, epsilon, omega_fd, epsilon_fd) in links.items():
        assert_close(f"omega{number}", omega, omega_fd, w_scale)
        assert_close(f"epsilon{number}", epsilon, epsilon_fd, e_scale)
    if slides:
        s_scale, r_scale = scales(slides.values(), scene)
        for key, (speed, rate, speed_fd, rate_fd) in slides.items():
            assert_close(f"ṡ {key}", speed, speed_fd, s_scale)
            assert_close(f"s̈ {key}", rate, rate_fd, r_scale)
