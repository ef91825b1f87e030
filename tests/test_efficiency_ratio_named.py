"""Which ratio η is: Mb0/Mb where the driver delivers power (Mb0·ω1 > 0) and where the loads take none (Mb0 = 0,
η = 0 = Mb0/Mb: Mb/Mb0 would divide by 0), Mb/Mb0 where the loads drive the driver back (Mb0·ω1 < 0).

One predicate, ``statics.delivers_power``, tells it for the efficiency, the forces' friction sentence and the
cycle table's note alike.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_texts import central_slider_crank

from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.scene import loads as scene_from_text
from graphplan.statics import delivers_power
from graphplan.wording import friction_summary


def scene_text(omega: float) -> str:
    return central_slider_crank(0.1, 0.4, omega) + """
[positions]
count = 12
"""


@pytest.mark.parametrize("omega", [10.0, -10.0])
def test_the_ratio_is_mb0_over_mb_unless_the_loads_drive_the_driver_back(omega):
    mechanism = analyse(scene_from_text(scene_text(omega))).mechanism
    sense = math.copysign(1.0, omega)
    # Power Mb0·ω1: positive, zero (either sign of zero) and negative; a balancing load not found is not power.
    ideal = np.array([5.0 * sense, 0.0, -0.0, -5.0 * sense, math.nan])
    assert delivers_power(mechanism, ideal).tolist() == [True, True, True, False, False]


def test_the_friction_sentence_names_mb0_over_mb_where_the_loads_take_no_power():
    mechanism = analyse(scene_from_text(scene_text(10.0))).mechanism
    text = strings("en")

    def ratio(ideal: float, load: float) -> str:
        return friction_summary(mechanism, text, ideal, load, write=lambda value: f"{value:g}", iterations=3,
                                written_efficiency="η")

    assert "Mb0/Mb" in ratio(0.0, 2.0)
    assert "Mb0/Mb" in ratio(4.0, 5.0)
    assert "Mb/Mb0" in ratio(-5.0, -4.0)
