"""One rule for rounding noise: the equilibrium's η and results.json judge a value as noise by the same size.

A value is noise below 10⁻¹² of its quantity's largest finite magnitude (12 significant digits): results.json
writes it as 0, and the efficiency takes a balancing load without friction that small beside the cycle's largest
as the rounding of a zero (the loads take no power there).  Both read it from ``rounding``, which statics may
import without importing the report.
"""

from __future__ import annotations

import math

import numpy as np
from scene_texts import central_slider_crank

from graphplan import rounding, statics
from graphplan.analysis import analyse
from graphplan.kinematics import PointMotion
from graphplan.loads import Rates, State
from graphplan.report import results
from graphplan.scene import loads as scene_from_text


def test_the_largest_finite_magnitude_skips_what_is_not_finite_and_measures_complex_values_by_modulus():
    assert rounding.largest_finite([3.0, -7.0, math.nan, math.inf, -math.inf]) == 7.0
    assert rounding.largest_finite([3 + 4j, 1j, complex(math.nan, 0.0)]) == 5.0  # |3 + 4i| = 5
    assert rounding.largest_finite([math.nan]) == 0.0
    assert rounding.largest_finite(np.zeros(0)) == 0.0


def test_the_noise_floor_is_twelve_digits_of_the_largest():
    assert rounding.noise_floor([2.0, -5.0, math.nan]) == 5.0 * 1e-12
    assert rounding.ANGLE_FLOOR_DEG == 360.0 * 1e-12
    assert rounding.PERCENT_FLOOR == 100.0 * 1e-12


def test_statics_and_results_json_share_the_rule():
    assert results.noise_floor is rounding.noise_floor
    assert results.SIGNIFICANT == rounding.SIGNIFICANT == 12
    ideal = np.array([-40.0, 10.0, math.nan])
    assert statics.balancing_scale(ideal) * rounding.RELATIVE_NOISE == rounding.noise_floor(ideal)


SCENE = central_slider_crank(0.1, 0.4, 10.0) + """
[[loads]]
kind = "force"
link = 4
point = "B"
value = 1000.0
angle = 0.0
resisting = true
[positions]
count = 12
"""


def test_an_analysis_works_out_its_balancing_scale_once(monkeypatch):
    analysis = analyse(scene_from_text(SCENE))
    calls = []

    def counted(ideal):
        calls.append(ideal)
        return rounding.largest_finite(np.asarray(ideal, dtype=float))

    monkeypatch.setattr("graphplan.analysis.balancing_scale", counted)
    first = analysis.balancing_scale
    assert analysis.balancing_scale == first == float(np.max(np.abs(analysis.equilibrium.balancing)))
    assert len(calls) == 1


def test_a_crank_angle_within_the_angles_noise_of_a_whole_turn_is_told_as_0_degrees():
    # The warnings name a position by its angle as results.json writes it: rounding of a turn is 0°.
    describe = analyse(scene_from_text(SCENE)).mechanism.driver.describe
    floor = rounding.ANGLE_FLOOR_DEG
    assert describe(math.radians(floor / 2)) == "φ = 0°"
    assert describe(math.radians(360.0 - floor / 2)) == "φ = 0°"
    assert describe(math.radians(-floor / 2)) == "φ = 0°"
    assert describe(math.radians(floor * 2)) != "φ = 0°"
    assert describe(math.radians(30.0)) == "φ = 30°"



def test_a_state_s_speed_scales_are_of_its_finite_speeds():
    # A singular position's speeds are infinite: the scales rest is judged against are the others' largest.
    still = np.zeros(3, dtype=complex)
    state = State(points={"B": PointMotion(still, np.array([3 + 4j, complex(math.inf, 0.0), 1j]), still)},
                  links={2: Rates(np.array([2.0, -math.inf, -7.0]), np.zeros(3))})
    assert state.moving_scale == 5.0  # |3 + 4i|
    assert state.turning_scale == 7.0
