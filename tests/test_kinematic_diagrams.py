"""Kinematic diagrams of the output link: the numbers against closed forms, the chord method's order, the drawing.

The analytic curves are checked against the centric slider-crank's closed form
(x = r·cos φ + √(l² − r²·sin² φ) and its two derivatives, written out here) and
the crank-rocker's swing from the triangle at its dead centres (law of cosines);
velocity and acceleration against finite differences of the displacement. The chord
method is checked on sin φ, where the chord slopes have a closed form, and on the
fixtures, where its error must fall as h² when the count of positions doubles. The
drawing is checked on its primitives: the pole rays parallel to the chords of the
diagram above (which is what μv = μs/(μt·H) means), the ordinates at the scales,
every text key used, no two texts overlapping.
"""

from __future__ import annotations

import functools
import math
import re
from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import box

from graphplan.analysis import analyse
from graphplan.errors import SceneError
from graphplan.kinematic_diagrams import (
    FIELD_MM,
    GREATEST_POLE_MM,
    LEAST_POLE_MM,
    chord_derivative,
    closed_chord_derivative,
    kinematic_diagrams,
    of_analysis,
)
from graphplan.locale import strings
from graphplan.mechanism import build
from graphplan.motion import solve
from graphplan.positions import make_positions
from graphplan.render import diagrams
from graphplan.render.primitives import Arrow, Circle, Polyline, Text, text_extent
from graphplan.scene import loads

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"


def scene_text(name: str, count: int | None = None) -> str:
    text = (FIXTURES / f"{name}.toml").read_text(encoding="utf-8")
    if count is not None:
        text = re.sub(r"(?m)^count\s*=\s*\d+", f"count = {count}", text)
        # A plan of a position a smaller count has not is left out: the diagrams need no plans.
        text = re.sub(r"(?m)^(plans\s*=\s*)\[([^]]*)\]", lambda m: m[1] + str(
            [n for n in map(int, re.findall(r"\d+", m[2])) if n <= count]), text)
    return text


@functools.cache
def record(name: str, count: int | None = None):
    mechanism = build(loads(scene_text(name, count)))
    positions = make_positions(mechanism)
    return mechanism, positions, kinematic_diagrams(mechanism, positions)


# --- the chord method ------------------------------------------------------------------------------------------


def test_chord_slopes_of_a_sine_are_the_cosine_at_the_mid_intervals_times_sinc():
    # (sin(φ + h) − sin φ)/h = cos(φ + h/2)·sin(h/2)/(h/2): the chord's slope is the derivative at the
    # mid-interval, scaled by sinc(h/2) = 1 − h²/24 + …
    h = 2 * math.pi / 12
    nodes = h * np.arange(13)
    slopes = chord_derivative(np.sin(nodes), h)
    sinc = math.sin(h / 2) / (h / 2)
    assert slopes == pytest.approx(np.cos(nodes[:-1] + h / 2) * sinc, abs=1e-14)
    # Twice round the closed cycle: −sin φ at the nodes, scaled by sinc².
    second = closed_chord_derivative(slopes, h)
    assert second.shape == (13,)
    assert second == pytest.approx(-np.sin(nodes) * sinc**2, abs=1e-14)


def test_chord_derivative_rejects_a_step_that_is_not_positive():
    with pytest.raises(ValueError, match="step of the chord method must be > 0"):
        chord_derivative(np.arange(3.0), 0.0)


# A cycle of N positions has N intervals; a slider's open run of N positions has N − 1: 6, 12, 24, 48.
@pytest.mark.parametrize(("name", "counts"), [
    ("engine_slider_crank", (12, 24, 48, 96)), ("ratchet_crank_rocker", (12, 24, 48, 96)),
    ("shaper_six_bar", (12, 24, 48, 96)), ("slider_driven", (7, 13, 25, 49))])
def test_chord_method_error_falls_as_h_squared(name, counts):
    errors_v, errors_a = [], []
    for count in counts:
        found = record(name, count)[2]
        errors_v.append(np.max(np.abs(found.v_chord - found.v_mid)))
        errors_a.append(np.max(np.abs(found.a_chord - found.a_at_chord_nodes)))
    for errors in (errors_v, errors_a):
        ratios = np.array(errors[:-1]) / np.array(errors[1:])
        # Halving h quarters the error once the leading term h²·s‴/24 (h²·s⁗/12) rules.
        assert ratios[-1] == pytest.approx(4.0, abs=0.3)
        assert np.all(ratios > 2.5)
        # 64 in the limit; the rocker's acceleration enters the h² regime only from 24 positions on.
        assert errors[0] / errors[-1] > 30


# --- the analytic curves ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["engine_slider_crank", "ratchet_crank_rocker", "shaper_six_bar"])
def test_analytic_velocity_and_acceleration_are_the_derivatives_of_the_displacement(name):
    found = record(name)[2]
    time = found.along / found.driver_speed
    # Second-order central differences on the 1° grid: error ~ h²/6·s‴, about 5e-5 of the peak.
    assert np.max(np.abs(np.gradient(found.s, time, edge_order=2) - found.v)) < 2e-3 * found.v_peak
    assert np.max(np.abs(np.gradient(found.v, time, edge_order=2) - found.a)) < 2e-3 * found.a_peak


def test_slider_crank_displacement_velocity_acceleration_match_the_closed_form():
    _, positions, found = record("engine_slider_crank")
    r, l, omega = 0.05, 0.19, 1500 * math.pi / 30   # the fixture's crank, rod and speed

    def x(phi):
        return r * np.cos(phi) + np.sqrt(l**2 - (r * np.sin(phi)) ** 2)

    def dx(phi):
        root = np.sqrt(l**2 - (r * np.sin(phi)) ** 2)
        return -r * np.sin(phi) - r**2 * np.sin(phi) * np.cos(phi) / root

    def ddx(phi):
        root = np.sqrt(l**2 - (r * np.sin(phi)) ** 2)
        return (-r * np.cos(phi) - r**2 * np.cos(2 * phi) / root
                - r**4 * (np.sin(phi) * np.cos(phi)) ** 2 / root**3)

    crank = positions.values[0] + found.along   # counter-clockwise crank
    # The expansion stroke runs backward, toward the crank: s grows as x falls.
    assert found.s == pytest.approx(x(positions.values[0]) - x(crank), abs=1e-12)
    assert found.v == pytest.approx(-omega * dx(crank), abs=1e-9)
    assert found.a == pytest.approx(-omega**2 * ddx(crank), abs=1e-6)
    assert found.translating and found.point == "B"
    # Top dead centre to bottom dead centre: the stroke 2r at half a turn.
    assert found.s.max() == pytest.approx(2 * r, abs=1e-12)
    assert found.stroke_end == pytest.approx(math.pi, abs=1e-9)


def test_rocker_swings_through_the_angle_between_its_dead_centre_positions():
    found = record("ratchet_crank_rocker")[2]
    oc, crank, coupler, rocker = 0.55, 0.175, 0.55, 0.325

    def angle_at_c(ob):   # the angle OCB of the triangle with the crank and coupler in line
        return math.acos((oc**2 + rocker**2 - ob**2) / (2 * oc * rocker))

    swing = angle_at_c(coupler + crank) - angle_at_c(coupler - crank)
    assert not found.translating
    assert found.s[0] == 0.0
    assert np.all(found.s >= -1e-12)
    # The dense grid steps 1°: the peak is missed by s″·(0.5°)²/2 at most.
    assert found.s.max() == pytest.approx(swing, abs=2e-4)
    assert found.v_nodes[0] == pytest.approx(0.0, abs=1e-9 * found.v_peak)


@pytest.mark.parametrize(("name", "given", "changed"), [("shaper_six_bar", "epsilon = 0.0", "epsilon = 40.0"),
                                                    ("slider_driven", "acceleration = 0.0 ", "acceleration = 0.5 ")])
def test_the_driver_s_acceleration_is_left_out_so_it_moves_uniformly(name, given, changed):
    # The plan method's ε of a crank (s̈ of a slider) holds at one instant; over the run the driver moves at
    # its speed, so the diagrams are the same with or without it.
    uniform = record(name)[2]
    text = scene_text(name).replace(given, changed)
    assert changed in text
    mechanism = build(loads(text))
    accelerated = kinematic_diagrams(mechanism, make_positions(mechanism))
    assert accelerated.v == pytest.approx(uniform.v, rel=1e-12, abs=1e-12)
    assert accelerated.a == pytest.approx(uniform.a, rel=1e-9, abs=1e-9 * uniform.a_peak)


def test_the_diagrams_say_they_count_in_the_working_sense_and_leave_the_driver_s_epsilon_out():
    """ω4 = +4.46 in results.json stood as −4.46 on a clockwise-working rocker's diagram, and its ε4 as 121.84
    where results.json has −125.18 (the crank's ε2 = 3 left out, −(ε4 − ε2/ω2·ω4)), nothing on the sheet saying so."""
    text = scene_text("double_rocker_swing").replace("count = 7", 'count = 7\nworking = { link = 4, sense = "cw" }')
    mechanism = build(loads(text))
    positions = make_positions(mechanism)
    found = kinematic_diagrams(mechanism, positions)
    motion = solve(mechanism, positions.values, positions.reference)
    omega2, epsilon2 = mechanism.driver.omega, mechanism.driver.epsilon
    assert epsilon2 != 0.0
    omega4, epsilon4 = motion.link(4).omega, motion.link(4).epsilon
    # Clockwise working: the diagrams' ω is −ω4 and their ε is −(ε4 − ε2/ω2·ω4), at the positions in run order.
    order = np.argsort(mechanism.driver.sense * (positions.values - positions.values[0]))
    np.testing.assert_allclose(found.v_nodes, -omega4[order], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(found.a_nodes, -(epsilon4 - epsilon2 / omega2 * omega4)[order], rtol=1e-9, atol=1e-9)
    said = " ".join(item.text for layer in diagrams.layout(found, strings("en")) for item in layer.items
                    if isinstance(item, Text))
    assert "ψ4, ω4, ε4 counted positive in the working sense" in said
    assert f"its ε = {epsilon2:.4g} rad/s² is left out of ε4" in said
    # Counter-clockwise working at a steady crank: the diagrams count as results.json does, and say nothing.
    steady = record("ratchet_crank_rocker")[2]
    said = " ".join(item.text for layer in diagrams.layout(steady, strings("en")) for item in layer.items
                    if isinstance(item, Text))
    assert "left out" not in said and "working sense" not in said


@functools.cache
def steady_crank_as_output():
    """The ratchet's crank, turning at a steady ω, named the working link (its loads, which need strokes, left out)."""
    text = scene_text("ratchet_crank_rocker").replace('working     = { link = 4, sense = "ccw" }',
                                                      'working     = { link = 2, sense = "cw" }')
    text = re.sub(r"(?ms)^\[\[loads\]\].*?(?=^\[)", "", text).replace('start       = "extreme"', "start = 0.0")
    mechanism = build(loads(text))
    return mechanism, kinematic_diagrams(mechanism, make_positions(mechanism))


def test_a_curve_nought_throughout_is_not_given_a_peak_of_one():
    """The crank as the working link at a steady ω: its ε is nought everywhere, and the caption said the chord method
    differs by "0.00 % of the peak |ε2| = 1 rad/s²", a peak that is nowhere.  Second differences of an angle growing
    in equal steps are nought, so the chord method's ε is nought to rounding too."""
    mechanism, found = steady_crank_as_output()
    assert not np.any(found.a) and np.max(np.abs(found.a_chord)) < 1e-9 * abs(mechanism.driver.omega) ** 2
    said = [item.text for layer in diagrams.layout(found, strings("en")) for item in layer.items
            if isinstance(item, Text)]
    assert "chord method − analytic: at most 0 rad/s²; the analytic ε2 is nought throughout" in said
    assert f"chord method − analytic: at most 0.00 % of the peak |ω2| = {abs(mechanism.driver.omega):g} rad/s" in said


@pytest.mark.parametrize("name", ["engine_slider_crank", "ratchet_crank_rocker", "shaper_six_bar", "slider_driven"])
def test_pole_distance_is_the_largest_whole_mm_that_keeps_each_curve_in_its_field(name):
    found = record(name)[2]
    scales = found.scales
    for pole, values, scale in ((scales.velocity_pole, found.v, scales.velocity),
                                (scales.acceleration_pole, found.a, scales.acceleration)):
        assert pole == int(pole) and LEAST_POLE_MM <= pole <= GREATEST_POLE_MM
        # The curve is drawn from its zero on the abscissa: one that stays on one side takes its peak in height.
        drawn = (max(values.max(), 0.0) - min(values.min(), 0.0)) / scale
        assert drawn <= FIELD_MM + 1e-9
        if pole < GREATEST_POLE_MM:
            assert drawn * (pole + 1) / pole > FIELD_MM


def test_scene_without_a_working_link_is_refused():
    text = re.sub(r"(?m)^working\s*=.*$", "", scene_text("ratchet_crank_rocker"))
    text = re.sub(r"(?ms)^\[\[loads\]\].*?(?=^\[positions\])", "", text)
    text = re.sub(r"(?m)^start\s*=.*$", "start = 0.0", text)
    mechanism = build(loads(text))
    with pytest.raises(SceneError, match=r"^positions\.working: kinematic diagrams need the output link"):
        kinematic_diagrams(mechanism, make_positions(mechanism))


# --- an open run: a slider's travel --------------------------------------------------------------------------

# The slider-driven fixture: the rod's end A runs along the x axis from G at 0.08 m/s; B is the crossing of the
# circles about A (AB) and C (CB) right of A→C; the lever CB is the output link, counter-clockwise positive.
LEVER_C, LEVER_AB, LEVER_CB, ROD_SPEED = 0.15 + 0.25j, 0.225, 0.15, 0.08


def lever_by_hand(s: float) -> tuple[float, float]:
    """ψ4 and ω4 of the slider-driven lever at the rod's travel s, without graphplan's solver."""
    a = complex(s, 0.0)
    d = abs(LEVER_C - a)
    along = (d * d + LEVER_AB**2 - LEVER_CB**2) / (2 * d)
    u = (LEVER_C - a) / d
    b = a + along * u - 1j * math.sqrt(LEVER_AB**2 - along**2) * u
    ab, cb = b - a, b - LEVER_C
    # v + i·ω3·AB = i·ω4·CB with v along x, split into x and y:
    # −ω3·ab.imag + ω4·cb.imag = −v,  ω3·ab.real − ω4·cb.real = 0;  ω4 by Cramer's rule.
    det = ab.imag * cb.real - cb.imag * ab.real
    omega4 = ROD_SPEED * ab.real / det
    return math.atan2(cb.imag, cb.real), omega4


def test_a_slider_s_run_matches_the_lever_worked_by_hand():
    _, positions, found = record("slider_driven")
    assert not found.cyclic and found.driver == "slider"
    assert (found.span, found.driver_speed) == pytest.approx((0.2, ROD_SPEED), abs=1e-15)
    assert found.numbers == tuple(range(1, 13)) and found.intervals == 11
    angles, omegas = zip(*(lever_by_hand(float(s)) for s in positions.values), strict=True)
    assert found.nodes == pytest.approx(np.asarray(positions.values) - positions.values[0], abs=1e-15)
    assert found.s_nodes == pytest.approx(np.asarray(angles) - angles[0], abs=1e-12)
    assert found.v_nodes == pytest.approx(omegas, rel=1e-10)
    # The time axis: the rod takes T = 0.2 m / 0.08 m/s = 2.5 s over the axis of L mm.
    assert found.scales.time * found.scales.axis_mm == pytest.approx(2.5, rel=1e-12)
    assert found.stroke_end is None


def test_an_open_run_takes_the_acceleration_at_its_inner_positions_only():
    found = record("slider_driven")[2]
    dt = found.step / found.driver_speed
    assert found.v_chord == pytest.approx(np.diff(found.s_nodes) / dt, rel=1e-12)
    # The chords of the velocity diagram join its mid-intervals: they reach from the second node to the last but one.
    assert found.a_chord.shape == (found.intervals - 1,)
    assert found.a_chord_nodes == pytest.approx(found.nodes[1:-1])
    assert found.a_chord == pytest.approx(np.diff(found.v_chord) / dt, rel=1e-12)


def test_a_run_given_against_the_driver_s_speed_is_met_backwards():
    # travel = [0.2, 0.0] numbers the positions from the far end; the rod still moves toward +x.
    backward = build(loads(scene_text("slider_driven").replace("travel       = [0.0, 0.20]",
                                                               "travel       = [0.20, 0.0]")))
    assert backward.driver.travel == (0.2, 0.0)
    found = kinematic_diagrams(backward, make_positions(backward))
    forward = record("slider_driven")[2]
    assert found.numbers == tuple(range(12, 0, -1))
    for name in ("s", "v", "a", "s_nodes", "v_chord", "a_chord"):
        assert getattr(found, name) == pytest.approx(getattr(forward, name), rel=1e-9, abs=1e-12), name


def test_a_run_of_fewer_than_three_intervals_is_refused():
    mechanism = build(loads(scene_text("slider_driven", 3)))
    with pytest.raises(SceneError, match=r"^positions\.count: the chord method needs at least 3 intervals between "
                                         r"positions; 3 positions over the travel make 2"):
        kinematic_diagrams(mechanism, make_positions(mechanism))


# --- the drawing -----------------------------------------------------------------------------------------------


def layers_of(found, text=None):
    return {layer.name: layer.items for layer in diagrams.layout(found, text)}


def polylines(items):
    return [item for item in items if isinstance(item, Polyline)]


@pytest.mark.parametrize("name", ["engine_slider_crank", "ratchet_crank_rocker", "slider_driven"])
def test_pole_rays_are_parallel_to_the_chords_of_the_diagram_above(name):
    found = record(name)[2]
    layers = layers_of(found)
    # The chords are the dashed chord-method polyline of each diagram (its second polyline).
    s_chords = np.array(polylines(layers["displacement-curves"])[1].points)
    v_points = np.array(polylines(layers["velocity-curves"])[1].points)
    origins = {kind: next(item.start for item in layers[f"{kind}-axes"] if getattr(item, "key", "").endswith("phi-axis"))
               for kind in ("velocity", "acceleration")}
    for kind, above in (("velocity", s_chords), ("acceleration", v_points)):
        rays = np.array([item.points for item in polylines(layers[f"{kind}-rays"])])
        ray_slopes = (rays[:, 1, 1] - rays[:, 0, 1]) / (rays[:, 1, 0] - rays[:, 0, 0])
        chord_slopes = np.diff(above[:, 1]) / np.diff(above[:, 0])
        if kind == "acceleration" and found.cyclic:
            # at the nodes 1 … count−1 from the chords between the velocity's mid-intervals; node 0's ray is
            # the chord across the end of the cycle
            assert len(rays) == found.intervals
            assert ray_slopes[1:] == pytest.approx(chord_slopes, rel=1e-9, abs=1e-12)
        else:
            assert len(rays) == len(chord_slopes) == (found.intervals if kind == "velocity" else found.intervals - 1)
            assert ray_slopes == pytest.approx(chord_slopes, rel=1e-9, abs=1e-12)
        # Every ray starts at the pole, H mm left of the origin on the abscissa.
        pole = found.scales.velocity_pole if kind == "velocity" else found.scales.acceleration_pole
        assert rays[:, 0, 0] == pytest.approx(np.full(len(rays), -pole))
        assert rays[:, 0, 1] == pytest.approx(np.full(len(rays), origins[kind][1]))


def test_curves_are_drawn_at_their_scales():
    found = record("shaper_six_bar")[2]
    layers = layers_of(found)
    scales = found.scales
    top = max(y for _, y in polylines(layers["displacement-curves"])[0].points)
    bottom = min(y for _, y in polylines(layers["velocity-curves"])[0].points)
    origin_s = polylines(layers["displacement-curves"])[0].points[0]
    origin_v = polylines(layers["velocity-curves"])[0].points[0]
    assert top - origin_s[1] == pytest.approx(found.s.max() / scales.displacement)
    assert bottom - origin_v[1] == pytest.approx(found.v.min() / scales.velocity)
    right = polylines(layers["displacement-curves"])[0].points[-1][0]
    assert right - origin_s[0] == pytest.approx(scales.axis_mm)
    dots = [item for item in layers["velocity-curves"] if isinstance(item, Circle)]
    assert len(dots) == found.intervals + 1   # the chord method's points and the pole


def test_positions_are_numbered_under_their_ticks_on_the_displacement_diagram():
    found = record("ratchet_crank_rocker")[2]
    layers = layers_of(found)
    numbers = [item for item in layers["displacement-labels"] if isinstance(item, Text) and item.text.isdigit()]
    arrows = {item.key: item for item in layers["displacement-axes"] if isinstance(item, Arrow)}
    axis, ordinate = arrows["displacement-phi-axis"], arrows["displacement-ordinate-axis"]
    origin = ordinate.start[0]
    assert [t.text for t in numbers] == [str(n) for n in found.numbers]
    for text, node in zip(numbers, found.nodes, strict=True):
        assert text.at[0] == pytest.approx(origin + node / found.scales.along, abs=1.5)
        assert text.at[1] < axis.start[1]


@pytest.mark.parametrize("name", ["engine_slider_crank", "ratchet_crank_rocker", "shaper_six_bar", "slider_driven"])
def test_no_two_texts_overlap(name):
    found = record(name)[2]
    texts = [item for layer in diagrams.layout(found) for item in layer.items if isinstance(item, Text)]
    boxes = [box(*text_extent(text)) for text in texts]
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            assert not boxes[i].intersects(boxes[j]), (texts[i].text, texts[j].text)


def test_every_text_key_is_used_and_words_come_from_the_mapping():
    keys = {key for key in strings("en") if key.startswith("kd_")}
    shown = set()
    swing = build(loads(scene_text("double_rocker_swing").replace(
        "count = 7", 'count = 7\nworking = { link = 4, sense = "cw" }')))
    # A run's diagrams ring the velocities its plans give (kd_plans in the legend).
    with_plans = of_analysis(analyse(loads(scene_text("ratchet_crank_rocker"))))
    pushed = build(loads(scene_text("slider_driven").replace("acceleration = 0.0 ", "acceleration = 0.5 ")))
    for found in (*(record(name)[2] for name in ("engine_slider_crank", "ratchet_crank_rocker", "slider_driven")),
                  kinematic_diagrams(swing, make_positions(swing)), kinematic_diagrams(pushed, make_positions(pushed)),
                  with_plans, steady_crank_as_output()[1]):
        marked = {key: f"<{key}>" for key in keys}
        for layer in diagrams.layout(found, marked):
            shown.update(re.findall(r"<(\w+)>", " ".join(i.text for i in layer.items if isinstance(i, Text))))
    # Symbols and units are written inside other strings, so a marker there hides its own.
    nested = {key for key in keys if key.startswith(("kd_symbol_", "kd_unit_", "kd_per_mm"))}
    assert shown | nested == keys
    russian = diagrams.diagrams_svg(record("ratchet_crank_rocker")[2], {"kd_title": "Кинематические диаграммы звена {link}"})
    assert "Кинематические диаграммы звена 4" in russian


def test_svg_is_the_same_every_time_and_states_the_scales():
    found = record("engine_slider_crank")[2]
    svg = diagrams.diagrams_svg(found)
    assert svg == diagrams.diagrams_svg(record("engine_slider_crank")[2])
    assert "μs = 0.002 m/mm" in svg
    assert f"H₁ = {found.scales.velocity_pole:g} mm" in svg
    assert "(m/s²)/mm" in svg
    assert f"{found.largest_v_difference:.2f} %" in svg



def test_of_many_positions_the_ticks_dots_and_construction_lines_of_every_few_are_drawn():
    # 360 positions a degree apart: the ordinates and the pole rays of each ran together into a grey field,
    # the ticks into a black comb.  Those of every twelfth, where the numbers stand, are drawn.
    found = record("ratchet_crank_rocker", 360)[2]
    layers = layers_of(found)
    along_mm = 1.0 / found.scales.along
    numbered = [k for k in range(found.intervals + 1) if k % 12 == 0]
    ticks = [item for item in layers["displacement-axes"] if isinstance(item, Polyline)]
    origin = next(item for item in layers["displacement-axes"] if isinstance(item, Arrow)
                  and item.key.endswith("ordinate-axis")).start[0]
    level = next(item for item in layers["displacement-axes"] if isinstance(item, Arrow)
                 and item.key.endswith("phi-axis")).start[1]
    assert [item.points[0][0] - origin for item in ticks] == pytest.approx([found.nodes[k] * along_mm
                                                                           for k in numbered])
    numbers = [item.text for item in layers["displacement-labels"] if isinstance(item, Text) and item.text.isdigit()]
    assert numbers == [str(found.numbers[k]) for k in numbered]
    ordinates = [line for line in polylines(layers["displacement-rays"])   # not the strokes' dimension lines
                 if line.points[0][0] == line.points[1][0] and math.isclose(line.points[0][1], level)]
    assert 0 < len(ordinates) <= len(numbered)
    assert all(any(math.isclose(line.points[0][0] - origin, found.nodes[k] * along_mm, abs_tol=1e-9)
                   for k in numbered) for line in ordinates)
    for kind in ("velocity", "acceleration"):
        assert 0 < len(polylines(layers[f"{kind}-rays"])) <= 31
        # The curves themselves keep every position: the chord polyline runs through all of them.
        assert len(polylines(layers[f"{kind}-curves"])[1].points) >= found.intervals


def test_of_a_few_positions_every_construction_line_is_drawn():
    found = record("ratchet_crank_rocker")[2]
    layers = layers_of(found)
    assert len([item for item in layers["velocity-rays"] if isinstance(item, Polyline)]) == found.intervals


def test_thinned_ticks_still_mark_the_end_of_the_run():
    # 99 positions, every fourth ticked: the closing node (99, numbered as the first) falls between them, and
    # the axis would end untagged.
    found = record("ratchet_crank_rocker", 99)[2]
    layers = layers_of(found)
    ticks = sorted(item.points[0][0] for item in layers["displacement-axes"] if isinstance(item, Polyline))
    origin = next(item for item in layers["displacement-axes"] if isinstance(item, Arrow)
                  and item.key.endswith("ordinate-axis")).start[0]
    assert len(ticks) < found.intervals
    assert ticks[-1] - origin == pytest.approx(found.scales.axis_mm)
    numbers = [item.text for item in layers["displacement-labels"] if isinstance(item, Text) and item.text.isdigit()]
    assert numbers[-1] == str(found.numbers[-1])


def test_the_key_of_the_rings_stands_under_the_velocity_diagram_that_has_them():
    # A course sheet may set the three diagrams on sheets apart: the acceleration diagram's sheet carried the
    # rings' key (the legend under it) and no ring.
    found = of_analysis(analyse(loads(scene_text("ratchet_crank_rocker"))))
    assert found.v_plans
    words = strings("en")
    velocity, acceleration = (diagrams.parts(found, words)[k] for k in (1, 2))

    def keyed(part):
        return [item for layer in part for item in layer.items if isinstance(item, Text) and item.text == words["kd_plans"]]

    (key,) = keyed(velocity)
    assert keyed(acceleration) == []
    rings = [item for layer in velocity for item in layer.items if isinstance(item, Circle) and item.fill is None]
    assert len(rings) == len(found.v_plans) + 1  # each plan's value, and the one of the key beside its word
    curves_bottom = min(y for layer in velocity if layer.name == "velocity-curves"
                        for item in layer.items if isinstance(item, Polyline) for _, y in item.points)
    assert key.at[1] < curves_bottom


@pytest.mark.parametrize("name", ["crank-rocker", "shaper", "slotted-lever", "slider-crank"])
def test_every_position_number_stands_under_the_axis_as_its_tick_stands_over_it(name):
    """In the crank-rocker's ε4(φ) the number 9, pushed off the curve crossing under it, stood up on the φ axis
    line (and 2 over it, beside the curve), read as lettering the curve (a hunt's zh sheet 1).  A number moved off
    the curve stays under the axis, on a leader where it must."""
    import graphplan
    from graphplan.kinematic_diagrams import of_analysis
    from graphplan.starters import starter

    analysis = graphplan.load_text(starter(name, "zh")).analyse()
    layers = {layer.name: layer for layer in diagrams.layout(of_analysis(analysis))}
    checked = 0
    for kind in ("displacement", "velocity", "acceleration"):
        (axis,) = [item for item in layers[f"{kind}-axes"].items if isinstance(item, Arrow) and item.key == f"{kind}-phi-axis"]
        numbers = [item for item in layers[f"{kind}-labels"].items
                   if isinstance(item, Text) and item.size == diagrams.NUMBER_SIZE and item.text.isdigit()]
        assert numbers
        for number in numbers:
            assert text_extent(number)[3] < axis.start[1], (kind, number.text)
        checked += len(numbers)
    assert checked
