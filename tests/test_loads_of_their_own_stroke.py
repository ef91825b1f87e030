"""A load of one stroke on a second cylinder's piston, read along that piston's own stroke (``loads[].stroke``).

Checked against the power balance of massless V-twin and in-line twin compressors (two slider-cranks on one crank
pin or on pins half a turn apart, r = 0.075 m, l = 0.3 m, ω = 20π rad/s, no gravity): each piston's gas force P(s),
s the share of its own compression stroke (its forward stroke, outward along its guide: s = (x − (l − r))/(2r)),
resists it while it compresses and nothing else acts, so Mb·ω = Σ P(s)·|v| over the pistons that compress, with the
closed-form slider-crank's x = r·cos θ + √(l² − r²·sin² θ) and v = dx/dt (θ the crank's angle from the guide).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_texts import central_slider_crank, second_cylinder

import graphplan
from graphplan.analysis import analyse
from graphplan.starters import starter

RADIUS, ROD, OMEGA = 0.075, 0.3, 20.0 * math.pi
DIAGRAM = [[0.0, 0.0], [0.2, 400.0], [0.4, 1000.0], [0.6, 2200.0], [0.75, 5300.0], [1.0, 5300.0]]


CRANK = central_slider_crank(RADIUS, ROD, OMEGA)


def twin(second_pin_deg: float, second_guide_deg: float, stroke: str) -> str:
    return CRANK + second_cylinder(RADIUS, ROD, second_pin_deg != 0, second_guide_deg) + f"""[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
resisting = true
diagram = {DIAGRAM}
[[loads]]
kind = "force"
link = 6
point = "C"
angle = {second_guide_deg + 180.0}
resisting = true
diagram = {DIAGRAM}
{stroke}
[positions]
count = 24
start = "extreme"
working = {{ link = 4, sense = "forward" }}
"""


def balancing_by_power(phi: np.ndarray, pins_and_guides: list[tuple[float, float]]) -> np.ndarray:
    shares, values = np.array(DIAGRAM).T
    power = np.zeros_like(phi)
    for pin, guide in pins_and_guides:
        theta = phi + pin - guide
        root = np.sqrt(ROD**2 - (RADIUS * np.sin(theta)) ** 2)
        x = RADIUS * np.cos(theta) + root
        v = -RADIUS * OMEGA * np.sin(theta) * (1.0 + RADIUS * np.cos(theta) / root)
        compressing = v > 0
        power += np.where(compressing, np.interp((x - (ROD - RADIUS)) / (2.0 * RADIUS), shares, values) * v, 0.0)
    return power / OMEGA


@pytest.mark.parametrize(("pin", "guide"), [(0.0, 90.0), (180.0, 0.0)], ids=["V-twin", "in-line twin"])
def test_a_second_piston_s_diagram_read_along_its_own_stroke_balances_the_power(pin, guide):
    analysis = analyse(graphplan.load_text(twin(pin, guide, 'stroke = { link = 6, sense = "forward" }')))
    phi = analysis.motion.driver
    expected = balancing_by_power(phi, [(0.0, 0.0), (math.radians(pin), math.radians(guide))])
    # The diagram's ends: at a dead centre the stroke about to begin decides, as the closed form's v > 0 does not.
    moving = np.abs(np.sin(phi)) > 1e-9
    np.testing.assert_allclose(analysis.equilibrium.balancing[moving], expected[moving], rtol=1e-9, atol=1e-6)
    assert not any(w.code == "stroke-of-another-link" for w in analysis.warnings)


def test_the_in_line_twin_s_balancing_moment_repeats_every_half_turn():
    """Pins half a turn apart on one line: the machine at φ + 180° is the machine at φ with its pistons' roles
    swapped, so each piston's own compression gives one Mb every half turn."""
    analysis = analyse(graphplan.load_text(twin(180.0, 0.0, 'stroke = { link = 6, sense = "forward" }')))
    balancing = analysis.equilibrium.balancing
    np.testing.assert_allclose(balancing[:12], balancing[12:], rtol=1e-9, atol=1e-6)


@pytest.mark.parametrize(("pin", "guide", "said"), [
    (0.0, 90.0, "loads[1] acts on link 6, which turns back at φ = 270.0° and φ = 90.0°, not where link 4 does"),
    (180.0, 0.0, ("loads[1] acts on link 6, a slider other than the output link 4: its diagram is read along link "
                  "4's working stroke (positions.working), in which link 6 moves backward along its guide")),
], ids=["V-twin", "in-line twin"])
def test_a_second_piston_s_load_without_its_own_stroke_is_warned_of(pin, guide, said):
    """Read along the first piston's stroke, the second's gas force acts while the first compresses: silently
    another cylinder's cycle."""
    analysis = analyse(graphplan.load_text(twin(pin, guide, "")))
    (warning,) = [w for w in analysis.warnings if w.code == "stroke-of-another-link"]
    assert said in warning.detail and 'loads[1].stroke = { link = 6, sense = "forward" or "backward" }' in \
        warning.detail
    phi = analysis.motion.driver
    own = balancing_by_power(phi, [(0.0, 0.0), (math.radians(pin), math.radians(guide))])
    assert np.max(np.abs(analysis.equilibrium.balancing - own)) > 50.0  # the reading the warning is about


def test_a_stroke_for_a_load_that_acts_always_is_refused():
    text = twin(0.0, 90.0, 'stroke = { link = 6, sense = "forward" }').replace(
        f"diagram = {DIAGRAM}\nstroke", "value = 100.0\nstroke").replace(
        "resisting = true\nvalue", "value")
    with pytest.raises(graphplan.SceneError, match=r"^loads\[1\]\.stroke: .*acts always"):
        graphplan.load_text(text)


def test_a_negative_value_in_a_resisting_diagram_is_refused_not_dropped():
    text = twin(0.0, 90.0, "").replace("[[0.0, 0.0], [0.2, 400.0]", "[[0.0, -800.0], [0.2, 400.0]", 1)
    with pytest.raises(graphplan.SceneError, match=r"^loads\[0\]\.diagram: a resisting load's diagram gives magnitudes"):
        graphplan.load_text(text)


def test_a_moment_s_diagram_with_a_negative_value_is_told_what_runs_with_no_angle_to_give():
    """A moment has no angle (one is refused: it acts on its whole link), so the advice gives its sense by its sign;
    it told a moment to give its angle, and the scene that did was refused at ``loads[0].angle``."""
    usual = 'value     = 1500.0        # N·m\nresisting = true          # against the rocker\'s motion\n' \
            'during    = "working"'
    text = starter("crank-rocker")
    assert usual in text
    diagram = "diagram = [[0.0, 10.0], [0.5, -100.0], [1.0, 0.0]]"
    with pytest.raises(graphplan.SceneError) as refused:
        graphplan.load_text(text.replace(usual, f"resisting = true\n{diagram}"))
    message = str(refused.value)
    assert message.startswith("loads[0].diagram: a resisting load's diagram gives magnitudes"), message
    assert "resisting = false" in message and "counter-clockwise positive" in message and "angle" not in message
    # As advised: the load helps the rocker over the share where its value is negative.
    scene = graphplan.load_text(text.replace(usual, f"resisting = false\n{diagram}"))
    assert [value for _, value in scene.loads[0].diagram] == [10.0, -100.0, 0.0]


def test_a_gas_force_over_the_whole_cycle_acts_at_both_dead_centres_as_the_stroke_beginning_there_gives_it():
    """An indicator diagram over the cycle as two loads of fixed direction, one per stroke of the piston (its own
    forward and backward strokes): at each dead centre the stroke about to begin gives the force, at its share 0,
    and between them each diagram its own stroke's (checked at mid-stroke, share 1/2 of the closed form's x)."""
    loads = """
[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
diagram = [[0.0, 100.0], [0.5, 2000.0], [1.0, 5300.0]]
stroke = { link = 4, sense = "forward" }
[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
diagram = [[0.0, 5300.0], [0.5, 300.0], [1.0, 100.0]]
stroke = { link = 4, sense = "backward" }
[positions]
count = 4
start = "extreme"
working = { link = 4, sense = "forward" }
"""
    analysis = analyse(graphplan.load_text(CRANK + loads))
    phi = np.degrees(analysis.motion.driver) % 360.0
    # Positions at 180° (BDC: the forward stroke begins), 270°, 0° (TDC: the backward begins), 90°.
    np.testing.assert_allclose(phi, [180.0, 270.0, 0.0, 90.0], atol=1e-9)
    force = [sum(load.force for load in analysis.loads if load.name.startswith("F4"))[i] for i in range(4)]
    x = RADIUS * np.cos(np.radians(phi)) + np.sqrt(ROD**2 - (RADIUS * np.sin(np.radians(phi))) ** 2)
    share = (x - (ROD - RADIUS)) / (2.0 * RADIUS)
    expected = [100.0, np.interp(share[1], [0.0, 0.5, 1.0], [100.0, 2000.0, 5300.0]), 5300.0,
                np.interp(1.0 - share[3], [0.0, 0.5, 1.0], [5300.0, 300.0, 100.0])]
    np.testing.assert_allclose(np.real(force), [-value for value in expected], rtol=1e-9)
    np.testing.assert_allclose(np.imag(force), 0.0, atol=1e-9)


def test_a_diagram_typed_in_metres_of_travel_is_warned_of():
    """Shares 0 … 0.15 of a 0.15 m stroke (2r): the travel in metres typed for shares, which would make the gas force
    act over the stroke's first 15 % alone."""
    travel = 2.0 * RADIUS
    in_metres = [[share * travel, value] for share, value in DIAGRAM]
    text = CRANK + f"""
[[loads]]
kind = "force"
link = 4
point = "B"
angle = 180.0
resisting = true
diagram = {in_metres}
[positions]
count = 12
start = "extreme"
working = {{ link = 4, sense = "forward" }}
"""
    (warning,) = [w for w in analyse(graphplan.load_text(text)).warnings if w.code == "diagram-in-travel"]
    assert warning.detail.startswith(f"loads[0].diagram's shares end at {travel:g}, where link 4's stroke of "
                                     f"{travel:g} m does: are they the travel in m?")
    as_shares = text.replace(str(in_metres), str(DIAGRAM))
    assert not [w for w in analyse(graphplan.load_text(as_shares)).warnings if w.code == "diagram-in-travel"]
