"""The friction and efficiency formulas against calculations that do not use them.

Each formula of :mod:`graphplan.friction` is checked by another route: a
slider's equilibrium solved as a 2×2 linear system with the friction force
f·N against the motion; the pressure over a bearing integrated with
scipy.integrate.quad; the work done in one turn of a screw; the power
followed, loss by loss, through a chain of machines.  Published worked
examples are reproduced to their printed precision (sources at each test).
Hypothesis checks the inequalities that hold for every coefficient.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.optimize import fsolve

from graphplan.errors import FrictionError, GraphplanError, SelfLockingError
from graphplan.friction import (
    METRIC_FLANK_HALF_ANGLE,
    Parallel,
    Series,
    cone_friction_moment,
    cylindrical_slider_coefficient,
    flat_plane_force,
    friction_angle,
    friction_circle_radius,
    incline_efficiency,
    incline_horizontal_force,
    incline_parallel_force,
    incline_self_locking,
    journal_coefficient,
    journal_friction_moment,
    loss_coefficient,
    parallel_efficiency,
    pivot_friction_moment,
    series_efficiency,
    thread_efficiency,
    thread_friction_angle,
    thread_lead_angle,
    thread_self_locking,
    thread_torque,
    vee_groove_coefficient,
)

LB = 4.4482216152605   # N per pound-force
INCH = 0.0254          # m per inch

coefficients = st.floats(min_value=0.0, max_value=1.0)
positive_coefficients = st.floats(min_value=0.01, max_value=1.0)


# --- the independent model: a slider in equilibrium ------------------------------------------


def slider_equilibrium(load, incline_angle, f, force_direction, up=True, normal_factor=1.0):
    """The driving force P along ``force_direction`` and the normal force N on a slider moving uniformly.

    The plane rises at ``incline_angle`` to the right; the slider moves up it (``up``) or down it.
    Friction f·N·normal_factor acts along the plane against the motion.  Solves
    P·d + N·n − s·f·k·N·t = (0, Q) for (P, N), s = ±1 the sense of motion, k = ``normal_factor``.
    """
    t = np.array([math.cos(incline_angle), math.sin(incline_angle)])
    n = np.array([-math.sin(incline_angle), math.cos(incline_angle)])
    sense = 1.0 if up else -1.0
    matrix = np.column_stack([force_direction, n - sense * f * normal_factor * t])
    force, normal = np.linalg.solve(matrix, np.array([0.0, load]))
    return force, normal


HORIZONTAL = np.array([1.0, 0.0])


# --- the friction angle and circle -----------------------------------------------------------


@given(coefficients)
def test_the_friction_angle_is_the_tilt_of_the_reaction_at_slip(f):
    # At slip the reaction is N·n + f·N·t: its angle to the normal n = (0, 1) is the friction angle.
    reaction = np.array([f, 1.0])
    assert friction_angle(f) == pytest.approx(math.atan2(reaction[0], reaction[1]), abs=1e-15)


def test_friction_functions_take_arrays_and_broadcast():
    f = np.array([0.0, 0.1, 0.3])
    assert np.allclose(friction_angle(f), [friction_angle(x) for x in f])
    torques = thread_torque(1000.0, 0.02, np.array([[0.05], [0.1]]), f, motion="tighten")
    assert torques.shape == (2, 3)
    assert torques[1, 2] == thread_torque(1000.0, 0.02, 0.1, 0.3, motion="tighten")
    assert isinstance(friction_angle(0.1), float)
    assert incline_self_locking(0.1, 0.2) is True
    assert incline_self_locking(np.array([0.1, 0.3]), 0.2).tolist() == [True, False]


@pytest.mark.parametrize("f", [0.05, 0.15, 0.4])
def test_loose_journal_reaction_is_tangent_to_the_friction_circle(f):
    # A loose journal rolls up its bearing until the reaction, vertical to carry the load, leans
    # by φ from the normal at the contact point; its arm about the centre is the circle's radius.
    r, load = 0.04, 1.0
    contact = r * np.array([math.sin(math.atan(f)), -math.cos(math.atan(f))])
    reaction = np.array([0.0, load])
    inward_normal = -contact / r
    lean = math.acos(reaction @ inward_normal / load)
    assert lean == pytest.approx(math.atan(f), abs=1e-12)
    arm = abs(contact[0] * reaction[1] - contact[1] * reaction[0]) / load
    rho = friction_circle_radius(journal_coefficient(f, contact="loose"), r)
    assert rho == pytest.approx(arm, rel=1e-12)
    # The textbook's ρ = f·r differs only at third order in f.
    assert friction_circle_radius(f, r) == pytest.approx(arm, rel=f**2)


# --- sliders on planes -----------------------------------------------------------------------


@pytest.mark.parametrize("push_angle_deg", [-50, -30, 0, 11.3, 30, 60])
@pytest.mark.parametrize("f", [0.0, 0.2, 0.5])
def test_flat_plane_force_solves_the_equilibrium(push_angle_deg, f):
    delta = math.radians(push_angle_deg)
    force, normal = slider_equilibrium(500.0, 0.0, f, np.array([math.cos(delta), math.sin(delta)]))
    assert normal > 0
    assert flat_plane_force(500.0, f, delta) == pytest.approx(force, rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("f", [0.1, 0.3, 0.8])
def test_flat_plane_force_is_least_when_pulled_at_the_friction_angle(f):
    angles = np.linspace(-0.5, 1.2, 17001)
    forces = flat_plane_force(100.0, f, angles)
    assert angles[np.argmin(forces)] == pytest.approx(math.atan(f), abs=1e-4)
    assert forces.min() == pytest.approx(100.0 * math.sin(math.atan(f)), rel=1e-7)


def test_flat_plane_push_steeper_than_its_limit_locks():
    f = 0.3
    delta = math.atan(f) - math.pi / 2 - 0.05
    force, _ = slider_equilibrium(100.0, 0.0, f, np.array([math.cos(delta), math.sin(delta)]))
    assert force < 0   # no pushing force of this direction balances: it would have to pull
    with pytest.raises(SelfLockingError, match=r"^push_angle: no force at this angle moves the block"):
        flat_plane_force(100.0, f, delta)


@pytest.mark.parametrize("alpha_deg", [0, 5, 20, 35, 50])
@pytest.mark.parametrize("f", [0.0, 0.1, 0.25])
@pytest.mark.parametrize("motion", ["up", "down"])
def test_incline_horizontal_force_is_q_tan_alpha_plus_minus_phi(alpha_deg, f, motion):
    alpha = math.radians(alpha_deg)
    force, normal = slider_equilibrium(800.0, alpha, f, HORIZONTAL, up=motion == "up")
    assert normal > 0
    assert incline_horizontal_force(800.0, alpha, f, motion=motion) == pytest.approx(force, rel=1e-12, abs=1e-9)


@pytest.mark.parametrize("alpha_deg", [0, 5, 20, 35, 50, 80])
@pytest.mark.parametrize("f", [0.0, 0.1, 0.25])
@pytest.mark.parametrize("motion", ["up", "down"])
def test_incline_parallel_force_is_q_sin_alpha_plus_minus_f_cos_alpha(alpha_deg, f, motion):
    alpha = math.radians(alpha_deg)
    along = np.array([math.cos(alpha), math.sin(alpha)])
    force, normal = slider_equilibrium(800.0, alpha, f, along, up=motion == "up")
    assert normal == pytest.approx(800.0 * math.cos(alpha), rel=1e-12)
    assert incline_parallel_force(800.0, alpha, f, motion=motion) == pytest.approx(force, rel=1e-12, abs=1e-9)


def test_a_horizontal_force_cannot_raise_a_slider_once_alpha_plus_phi_passes_90_degrees():
    f, alpha = 0.5, math.radians(70)   # α + φ = 96.6°
    force, normal = slider_equilibrium(100.0, alpha, f, HORIZONTAL)
    assert force < 0 or normal < 0     # the only "balance" needs a pull, or a plane that pulls
    with pytest.raises(SelfLockingError, match=r"α \+ φ ≥ π/2"):
        incline_horizontal_force(100.0, alpha, f, motion="up")
    with pytest.raises(SelfLockingError):
        incline_efficiency(alpha, f, motion="up", force="horizontal")


def incline_efficiency_by_work(alpha, f, up, direction):
    """Efficiency from the work done over a slide of 1 m along the plane."""
    force, _ = slider_equilibrium(1.0, alpha, f, direction, up=up)
    lift = math.sin(alpha)                           # the weight's work (1 N over 1 m of slope)
    force_work = force * float(direction @ [math.cos(alpha), math.sin(alpha)])
    return lift / force_work if up else force_work / lift


@pytest.mark.parametrize("alpha_deg", [3, 10, 25, 45, 60])
@pytest.mark.parametrize("f", [0.0, 0.05, 0.2])
@pytest.mark.parametrize("motion", ["up", "down"])
@pytest.mark.parametrize("force", ["horizontal", "parallel"])
def test_incline_efficiency_is_the_ratio_of_useful_to_driving_work(alpha_deg, f, motion, force):
    alpha = math.radians(alpha_deg)
    direction = HORIZONTAL if force == "horizontal" else np.array([math.cos(alpha), math.sin(alpha)])
    expected = incline_efficiency_by_work(alpha, f, motion == "up", direction)
    assert incline_efficiency(alpha, f, motion=motion, force=force) == pytest.approx(expected, rel=1e-12, abs=1e-12)


@given(fraction=st.floats(min_value=1e-3, max_value=0.999), f=coefficients)
def test_raising_efficiency_is_at_most_one_and_one_without_friction(fraction, f):
    alpha = fraction * (math.pi / 2 - math.atan(f))   # below the jamming angle of a horizontal force
    for force in ("horizontal", "parallel"):
        eta = incline_efficiency(alpha, f, motion="up", force=force)
        assert 0 <= eta <= 1 + 1e-15
        assert incline_efficiency(alpha, 0.0, motion="up", force=force) == pytest.approx(1.0, rel=1e-14)
        if f > 1e-9:   # a smaller f loses less than one rounding of η
            assert eta < 1


@pytest.mark.parametrize("f", [0.1, 0.3])
def test_incline_self_locks_when_alpha_is_at_most_phi(f):
    phi = math.atan(f)
    for alpha, locks in [(0.5 * phi, True), (phi, True), (phi + 0.01, False), (2 * phi, False)]:
        holding, _ = slider_equilibrium(1.0, alpha, f, HORIZONTAL, up=False)
        assert incline_self_locking(alpha, f) is locks
        # Self-locking: the holding force would have to drive, and the reverse efficiency is ≤ 0.
        assert bool(holding <= 1e-15) is locks
        if alpha > 0:
            assert bool(incline_efficiency(alpha, f, motion="down", force="parallel") <= 1e-15) is locks


# --- sliders in grooves ----------------------------------------------------------------------


@pytest.mark.parametrize("theta_deg", [15, 30, 45, 60, 90])
def test_vee_groove_coefficient_from_the_flank_forces(theta_deg):
    theta, f, load = math.radians(theta_deg), 0.15, 300.0
    # The flank normals, pointing into the slider; the load presses it down the symmetry plane.
    left, right = np.array([math.cos(theta), math.sin(theta)]), np.array([-math.cos(theta), math.sin(theta)])
    n_left, n_right = np.linalg.solve(np.column_stack([left, right]), [0.0, load])
    assert vee_groove_coefficient(f, theta) == pytest.approx(f * (n_left + n_right) / load, rel=1e-12)
    assert vee_groove_coefficient(f, math.pi / 2) == pytest.approx(f, rel=1e-15)


def half_cylinder_reduced_coefficient(pressure):
    """f'/f for a half-cylinder contact (γ from the load's line) with the pressure law ``pressure(γ)``."""
    carried, _ = quad(lambda g: pressure(g) * math.cos(g), -math.pi / 2, math.pi / 2)
    total_normal, _ = quad(pressure, -math.pi / 2, math.pi / 2)
    return total_normal / carried


@pytest.mark.parametrize("contact, pressure", [("new", lambda g: 1.0), ("run_in", math.cos)])
def test_cylindrical_slider_coefficient_by_integrating_the_pressure(contact, pressure):
    expected = 0.2 * half_cylinder_reduced_coefficient(pressure)
    assert cylindrical_slider_coefficient(0.2, contact=contact) == pytest.approx(expected, rel=1e-12)


def test_cylindrical_slider_spans_the_textbook_range_1_27_to_1_57_f():
    assert cylindrical_slider_coefficient(1.0, contact="run_in") == pytest.approx(1.27, abs=0.005)
    assert cylindrical_slider_coefficient(1.0, contact="new") == pytest.approx(1.57, abs=0.005)


# --- screw threads ---------------------------------------------------------------------------


def test_lead_angle_is_the_helix_slope_on_the_pitch_cylinder():
    lead, d2 = 0.012, 0.0365
    angle = np.linspace(0, 2 * np.pi, 1001)
    helix = np.column_stack([d2 / 2 * np.cos(angle), d2 / 2 * np.sin(angle), lead * angle / (2 * np.pi)])
    step = np.diff(helix, axis=0)
    slopes = np.arctan2(step[:, 2], np.hypot(step[:, 0], step[:, 1]))
    # Chords are a hair shorter than arcs: the chord slope overestimates by O(dθ²).
    assert thread_lead_angle(lead, d2) == pytest.approx(slopes.mean(), rel=1e-5)


@pytest.mark.parametrize("lead_deg", [2, 5, 10, 20])
@pytest.mark.parametrize("f", [0.0, 0.08, 0.15])
@pytest.mark.parametrize("motion", ["tighten", "loosen"])
def test_square_thread_torque_is_the_unwound_incline_pushed_at_the_pitch_radius(lead_deg, f, motion):
    psi, load, d2 = math.radians(lead_deg), 6400.0, 0.028
    force, _ = slider_equilibrium(load, psi, f, HORIZONTAL, up=motion == "tighten")
    assert thread_torque(load, d2, psi, f, motion=motion) == pytest.approx(force * d2 / 2, rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("beta_deg", [15, 30])
@pytest.mark.parametrize("motion", ["tighten", "loosen"])
def test_triangular_thread_is_the_incline_with_normal_force_over_cos_beta(beta_deg, motion):
    beta, psi, f, load, d2 = math.radians(beta_deg), math.radians(2.5), 0.12, 10_000.0, 0.0104
    force, _ = slider_equilibrium(load, psi, f, HORIZONTAL, up=motion == "tighten", normal_factor=1 / math.cos(beta))
    torque = thread_torque(load, d2, psi, f, motion=motion, flank_half_angle=beta)
    assert torque == pytest.approx(force * d2 / 2, rel=1e-12)
    assert thread_friction_angle(f, beta) > thread_friction_angle(f)


@pytest.mark.parametrize("beta", [0.0, METRIC_FLANK_HALF_ANGLE])
@pytest.mark.parametrize("f", [0.0, 0.1, 0.3])
def test_thread_efficiency_is_the_work_of_one_turn(beta, f):
    load, lead, d2 = 2000.0, 0.008, 0.036
    psi = thread_lead_angle(lead, d2)
    tighten = thread_torque(load, d2, psi, f, motion="tighten", flank_half_angle=beta)
    loosen = thread_torque(load, d2, psi, f, motion="loosen", flank_half_angle=beta)
    # One turn: the torque works through 2π, the load through one lead.
    assert thread_efficiency(psi, f, motion="tighten", flank_half_angle=beta) == pytest.approx(
        load * lead / (2 * math.pi * tighten), rel=1e-12)
    assert thread_efficiency(psi, f, motion="loosen", flank_half_angle=beta) == pytest.approx(
        2 * math.pi * loosen / (load * lead), rel=1e-12, abs=1e-12)


@given(psi=st.floats(min_value=0.005, max_value=0.6), f=coefficients,
       beta=st.sampled_from([0.0, math.radians(15), METRIC_FLANK_HALF_ANGLE]))
def test_tightening_needs_at_least_the_loosening_torque_and_efficiency_stays_below_one(psi, f, beta):
    tighten = thread_torque(1.0, 0.02, psi, f, motion="tighten", flank_half_angle=beta)
    loosen = thread_torque(1.0, 0.02, psi, f, motion="loosen", flank_half_angle=beta)
    assert tighten >= loosen
    assert 0 < thread_efficiency(psi, f, motion="tighten", flank_half_angle=beta) <= 1 + 1e-15


@given(psi=st.floats(min_value=0.005, max_value=0.7), f=positive_coefficients)
def test_a_self_locking_square_thread_is_less_than_50_percent_efficient(psi, f):
    # adaptivebooks.org, Statics, "Screw threads", problem 3: "Show that the maximum efficiency
    # which a self-locking screw can have is 50%."
    if thread_self_locking(psi, f):
        assert thread_efficiency(psi, f, motion="tighten") < 0.5
        assert thread_torque(1.0, 0.02, psi, f, motion="loosen") <= 1e-15
    else:
        assert thread_efficiency(psi, f, motion="loosen") > 0


def test_thread_self_locking_flag_at_psi_equal_phi_prime():
    f, beta = 0.1, METRIC_FLANK_HALF_ANGLE
    phi = math.atan(f / math.cos(beta))
    assert thread_self_locking(np.array([0.5 * phi, phi, phi + 1e-6]), f, beta).tolist() == [True, True, False]


# --- bearings --------------------------------------------------------------------------------


@pytest.mark.parametrize("contact, pressure", [("new", lambda g: 1.0), ("run_in", math.cos)])
def test_journal_moment_by_integrating_the_pressure_over_half_the_journal(contact, pressure):
    f, load, r = 0.1, 5000.0, 0.03
    carried, _ = quad(lambda g: pressure(g) * math.cos(g) * r, -math.pi / 2, math.pi / 2)
    scale = load / carried    # the pressure that carries the load, per unit length
    moment, _ = quad(lambda g: f * scale * pressure(g) * r * r, -math.pi / 2, math.pi / 2)
    assert journal_friction_moment(load, r, f, contact=contact) == pytest.approx(moment, rel=1e-12)


def pivot_moment_by_quadrature(load, f, outer, inner, pressure_shape):
    carried, _ = quad(lambda rho: pressure_shape(rho) * 2 * math.pi * rho, inner, outer)
    scale = load / carried
    moment, _ = quad(lambda rho: f * scale * pressure_shape(rho) * rho * 2 * math.pi * rho, inner, outer)
    return moment


@pytest.mark.parametrize("inner", [0.0, 0.02, 0.05])
@pytest.mark.parametrize("contact, pressure_shape", [("new", lambda rho: 1.0), ("run_in", lambda rho: 1 / rho)])
def test_pivot_moment_by_integrating_f_p_rho_over_the_ring(inner, contact, pressure_shape):
    load, f, outer = 20_000.0, 0.08, 0.06
    expected = pivot_moment_by_quadrature(load, f, outer, inner, pressure_shape)
    assert pivot_friction_moment(load, f, outer, inner, contact=contact) == pytest.approx(expected, rel=1e-9)


def test_solid_pivot_moments_are_two_thirds_and_one_half_f_q_r():
    assert pivot_friction_moment(3.0, 0.5, 2.0, contact="new") == pytest.approx(2 / 3 * 0.5 * 3.0 * 2.0)
    assert pivot_friction_moment(3.0, 0.5, 2.0, contact="run_in") == pytest.approx(1 / 2 * 0.5 * 3.0 * 2.0)


@given(outer=st.floats(min_value=0.01, max_value=1.0), ratio=st.floats(min_value=0.0, max_value=0.99), f=coefficients)
@example(outer=0.875, ratio=0.75, f=5e-324)  # found by CI: 2/3·f rounded to zero before the geometry scaled it
def test_a_new_pivot_has_at_least_the_moment_of_a_run_in_one(outer, ratio, f):
    new = pivot_friction_moment(1.0, f, outer, ratio * outer, contact="new")
    assert new >= pivot_friction_moment(1.0, f, outer, ratio * outer, contact="run_in") * (1 - 1e-12)


def cone_moment_by_quadrature(load, f, outer, inner, semi_angle, pressure_shape):
    """The cone's face as rings of slant width dρ/sin α: area 2πρ·dρ/sin α, normal force p·dA, whose axial
    share p·dA·sin α carries the load and whose friction f·p·dA acts at ρ."""
    def area(rho):
        return 2 * math.pi * rho / math.sin(semi_angle)

    carried, _ = quad(lambda rho: pressure_shape(rho) * area(rho) * math.sin(semi_angle), inner, outer)
    scale = load / carried
    moment, _ = quad(lambda rho: f * scale * pressure_shape(rho) * area(rho) * rho, inner, outer)
    return moment


@pytest.mark.parametrize("semi_angle", [math.radians(12.5), math.radians(15), math.radians(40), math.pi / 2])
@pytest.mark.parametrize("contact, pressure_shape", [("new", lambda rho: 1.0), ("run_in", lambda rho: 1 / rho)])
def test_cone_moment_by_integrating_the_friction_over_the_conical_face(semi_angle, contact, pressure_shape):
    load, f, outer, inner = 1500.0, 0.25, 0.16, 0.12
    expected = cone_moment_by_quadrature(load, f, outer, inner, semi_angle, pressure_shape)
    moment = cone_friction_moment(load, f, outer, inner, semi_angle, contact=contact)
    assert moment == pytest.approx(expected, rel=1e-9)


def test_a_cone_at_a_right_angle_is_the_flat_collar_and_a_sharper_one_grips_harder():
    flat = pivot_friction_moment(1500.0, 0.25, 0.16, 0.12, contact="run_in")
    assert cone_friction_moment(1500.0, 0.25, 0.16, 0.12, math.pi / 2, contact="run_in") == pytest.approx(flat)
    angles = np.radians([10.0, 15.0, 30.0, 60.0])
    moments = cone_friction_moment(1500.0, 0.25, 0.16, 0.12, angles, contact="run_in")
    assert np.all(np.diff(moments) < 0)
    # Even wear: f·W·Rm·cosec α, the mean radius alone counts.
    assert moments[1] == pytest.approx(0.25 * 1500.0 * 0.14 / math.sin(math.radians(15.0)), rel=1e-12)


@pytest.mark.parametrize("semi_angle", [0.0, -0.1, math.pi / 2 + 0.01])
def test_a_cone_needs_a_semi_angle_between_nought_and_a_right_angle(semi_angle):
    with pytest.raises(FrictionError, match="semi_angle"):
        cone_friction_moment(1500.0, 0.25, 0.16, 0.12, semi_angle, contact="new")


# --- efficiency of machines ------------------------------------------------------------------


def test_series_and_parallel_by_power_bookkeeping():
    # 1 kW into a motor (95 %) and a gearbox (90 %) that drive two branches taking 60 % and 40 %
    # of the gearbox's output: a worm pair (80 %) and a chain (90 %) in series; a belt (70 %).
    chain = Series([0.95, 0.90, Parallel([Series([0.80, 0.90]), 0.70], shares=[0.6, 0.4])])
    losses = []
    power = 1000.0
    for eta in (0.95, 0.90):
        losses.append(power * (1 - eta))
        power -= losses[-1]
    branch_a, branch_b = 0.6 * power, 0.4 * power
    for eta in (0.80, 0.90):
        losses.append(branch_a * (1 - eta))
        branch_a -= losses[-1]
    losses.append(branch_b * (1 - 0.70))
    assert chain.efficiency == pytest.approx(1 - sum(losses) / 1000.0, rel=1e-14)
    assert loss_coefficient(chain.efficiency) == pytest.approx(sum(losses) / 1000.0, rel=1e-14)


def test_parallel_efficiency_weights_by_input_power():
    # 300 W through 90 %, 700 W through 60 %: 270 W + 420 W out of 1000 W in.
    assert parallel_efficiency([0.9, 0.6], [300.0, 700.0]) == pytest.approx(0.69, rel=1e-14)
    assert Parallel([0.9, 0.6], shares=[3, 7]).efficiency == pytest.approx(0.69, rel=1e-14)


@given(st.lists(st.floats(min_value=0.0, max_value=1.0), min_size=1, max_size=6))
def test_series_is_the_product_and_never_beats_its_worst_stage(etas):
    eta = series_efficiency(etas)
    assert eta == pytest.approx(math.prod(etas), rel=1e-12, abs=1e-300)
    assert eta <= min(etas) + 1e-15
    assert Series(etas).efficiency == eta


@given(st.lists(st.tuples(st.floats(min_value=0.0, max_value=1.0), st.floats(min_value=0.01, max_value=100.0)),
                min_size=1, max_size=6))
def test_parallel_lies_between_its_worst_and_best_branch(branches):
    etas, powers = zip(*branches)
    eta = parallel_efficiency(etas, powers)
    assert min(etas) - 1e-12 <= eta <= max(etas) + 1e-12


def test_efficiencies_may_be_arrays_over_positions():
    eta = Series([np.array([0.9, 0.8]), Parallel([0.5, np.array([1.0, 0.0])], shares=[1, 1])]).efficiency
    assert np.allclose(eta, [0.9 * 0.75, 0.8 * 0.25])


def test_without_friction_every_efficiency_is_one():
    assert incline_efficiency(0.3, 0.0, motion="down", force="horizontal") == pytest.approx(1.0)
    assert thread_efficiency(0.05, 0.0, motion="tighten", flank_half_angle=METRIC_FLANK_HALF_ANGLE) == pytest.approx(1.0)
    assert thread_efficiency(0.05, 0.0, motion="loosen") == pytest.approx(1.0)
    assert loss_coefficient(1.0) == 0.0


# --- published worked examples ---------------------------------------------------------------


def test_screw_jack_torque_adaptivebooks_statics_problem():
    # adaptivebooks.org, Statics, "Friction: the application of statics to machine design —
    # Screw threads", problem 2 (https://www.adaptivebooks.org/statics/friction-the-application-
    # of-statics-to-machine-design/screw-threads): 10 000 lb raised by a square-threaded screw,
    # two threads per inch, mean diameter 2 in, f = 0.2.  Printed answer: 2840 in.-lb (3 digits).
    load, d2, lead = 10_000 * LB, 2 * INCH, 0.5 * INCH
    torque = thread_torque(load, d2, thread_lead_angle(lead, d2), 0.2, motion="tighten")
    assert torque / (LB * INCH) == pytest.approx(2840, abs=5)


def test_incline_parallel_force_khurmi_example_10_2():
    # Khurmi & Gupta, Theory of Machines, ch. 10 (Friction), Example 10.2 (p. 268), as transcribed
    # in the FOSSEE Python textbook companion: 1500 N along a 12° incline and 1720 N along a 15°
    # one just move the same body up.  Printed: μ = 0.131, W = 4462 N.
    def mismatch(unknowns):
        weight, f = unknowns
        return [incline_parallel_force(weight, math.radians(12), f, motion="up") - 1500,
                incline_parallel_force(weight, math.radians(15), f, motion="up") - 1720]

    weight, f = fsolve(mismatch, [4000.0, 0.1], xtol=1e-12)
    assert f == pytest.approx(0.131, abs=0.0005)
    assert weight == pytest.approx(4462, abs=0.5)


def test_flat_plane_pull_and_push_khurmi_example_10_1():
    # Khurmi & Gupta, Theory of Machines, Example 10.1 (p. 263), same transcription: a pull of
    # 180 N and a push of 220 N, both at 30° to the horizontal, just move a body on a rough plane.
    # Printed: μ = 0.1732 and W = 1000 N, the weight rounded to hundreds (the exact value is 990 N).
    def mismatch(unknowns):
        weight, f = unknowns
        return [flat_plane_force(weight, f, math.radians(30)) - 180,
                flat_plane_force(weight, f, math.radians(-30)) - 220]

    weight, f = fsolve(mismatch, [800.0, 0.3], xtol=1e-12)
    assert f == pytest.approx(0.1732, abs=0.00005)
    assert round(weight, -2) == 1000


def test_footstep_bearing_power_loss_jssc_je_2022():
    # JSSC JE Mechanical Re-Exam, 23 Oct 2022, Paper II (solved on testbook.com): a flat footstep
    # bearing, 16 cm diameter, 20 kN, 10 rad/s, μ = 0.05, uniform wear.  Printed answer: 400 W.
    moment = pivot_friction_moment(20_000.0, 0.05, 0.08, contact="run_in")
    assert moment * 10.0 == pytest.approx(400, abs=0.5)


# --- bad arguments ---------------------------------------------------------------------------


@pytest.mark.parametrize("call, error, message", [
    (lambda: friction_angle(-0.1), FrictionError, "f: must be ≥ 0 (a coefficient of friction) (got -0.1)"),
    (lambda: friction_angle([0.1, 0.2, -0.3]), FrictionError,
     "f: must be ≥ 0 (a coefficient of friction), at index 2 (got -0.3)"),
    (lambda: friction_angle(True), FrictionError, "f: must be a real number or an array of real numbers (got True)"),
    (lambda: friction_angle("0.1"), FrictionError,
     "f: must be a real number or an array of real numbers (got '0.1')"),
    (lambda: friction_angle(math.nan), FrictionError, "f: must be finite (got nan)"),
    (lambda: friction_circle_radius(0.1, 0.0), FrictionError, "radius: must be > 0 (got 0.0)"),
    (lambda: incline_horizontal_force(100, 30, 0.1, motion="up"), FrictionError,
     "incline_angle: must be in [0, π/2), an angle in radians (got 30.0)"),
    (lambda: incline_horizontal_force(100, 0.3, 0.1, motion="raise"), FrictionError,
     "motion: must be one of 'up', 'down' (got 'raise')"),
    (lambda: incline_horizontal_force(-5, 0.3, 0.1, motion="up"), FrictionError, "load: must be ≥ 0 (got -5.0)"),
    (lambda: incline_horizontal_force(100, 1.2, 0.5, motion="up"), SelfLockingError,
     "incline_angle: no horizontal force raises the slider: α + φ ≥ π/2, it jams (got 1.2)"),
    (lambda: incline_efficiency(0.0, 0.1, motion="up", force="parallel"), FrictionError,
     "incline_angle: must be in (0, π/2), an angle in radians (got 0.0)"),
    (lambda: incline_efficiency(0.2, 0.1, motion="up", force="oblique"), FrictionError,
     "force: must be one of 'horizontal', 'parallel' (got 'oblique')"),
    (lambda: flat_plane_force(100, 0.2, -1.5), SelfLockingError,
     "push_angle: no force at this angle moves the block: it presses into the plane at δ ≤ φ − π/2 (got -1.5)"),
    (lambda: vee_groove_coefficient(0.1, 0.0), FrictionError,
     "groove_half_angle: must be in (0, π/2], an angle in radians (got 0.0)"),
    (lambda: cylindrical_slider_coefficient(0.1, contact="loose"), FrictionError,
     "contact: must be one of 'new', 'run_in' (got 'loose')"),
    (lambda: thread_lead_angle(0.0, 0.02), FrictionError, "lead: must be > 0 (got 0.0)"),
    (lambda: thread_friction_angle(0.1, math.pi / 2), FrictionError,
     "flank_half_angle: must be in [0, π/2), an angle in radians (got 1.5707963267948966)"),
    (lambda: thread_torque(1000, 0.02, 1.4, 0.4, motion="tighten"), SelfLockingError,
     "lead_angle: no torque tightens the thread: ψ + φ' ≥ π/2, it jams (got 1.4)"),
    (lambda: thread_torque(1000, 0.02, 0.05, 0.1, motion="up"), FrictionError,
     "motion: must be one of 'tighten', 'loosen' (got 'up')"),
    (lambda: journal_friction_moment(1000, 0.03, 0.1, contact="worn"), FrictionError,
     "contact: must be one of 'loose', 'new', 'run_in' (got 'worn')"),
    (lambda: pivot_friction_moment(1000, 0.1, 0.05, 0.05, contact="new"), FrictionError,
     "inner_radius: must be < outer_radius (got 0.05)"),
    (lambda: series_efficiency([0.9, 1.2]), FrictionError,
     "efficiencies[1]: must be an efficiency in [0, 1] (got 1.2)"),
    (lambda: series_efficiency([]), FrictionError, "efficiencies: must hold at least one efficiency (got [])"),
    (lambda: parallel_efficiency([0.9, 0.8], [1.0]), FrictionError,
     "input_powers: must hold one power per efficiency (2) (got [1.0])"),
    (lambda: parallel_efficiency([0.9, 0.8], [0.0, 0.0]), FrictionError, "input_powers: must not all be 0 (got 0.0)"),
    (lambda: Parallel([0.9, 0.8], shares=[1.0, -1.0]), FrictionError, "shares[1]: must be ≥ 0 (got -1.0)"),
    (lambda: Series([0.9, Parallel([1.5], shares=[1])]), FrictionError,
     "branches[0]: must be an efficiency in [0, 1] (got 1.5)"),
    (lambda: loss_coefficient(1.1), FrictionError, "efficiency: must be ≤ 1 (got 1.1)"),
])
def test_bad_arguments_are_named_in_the_message(call, error, message):
    with pytest.raises(error) as caught:
        call()
    assert str(caught.value) == message
    assert isinstance(caught.value, GraphplanError) and isinstance(caught.value, ValueError)
