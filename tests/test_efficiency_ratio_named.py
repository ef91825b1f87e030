"""Which ratio η is: Mb0/Mb where the driver delivers power (Mb0·ω1 > 0) and where the loads take none (Mb0 = 0,
η = 0 = Mb0/Mb: Mb/Mb0 would divide by 0), Mb/Mb0 where the loads drive the driver back (Mb0·ω1 < 0).

One predicate, ``statics.delivers_power``, tells it for the efficiency, the forces' friction sentence and the
cycle table's note alike.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.scene import loads as scene_from_text
from graphplan.statics import delivers_power
from graphplan.wording import friction_summary

SCENE = """
[scene]
gravity = 0.0
[frame]
points = {{ O = [0.0, 0.0] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = {omega}
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.4
guide = {{ through = "O", angle = 0.0 }}
assembly = "forward"
[positions]
count = 12
"""


@pytest.mark.parametrize("omega", [10.0, -10.0])
def test_the_ratio_is_mb0_over_mb_unless_the_loads_drive_the_driver_back(omega):
    mechanism = analyse(scene_from_text(SCENE.format(omega=omega))).mechanism
    sense = math.copysign(1.0, omega)
    # Power Mb0·ω1: positive, zero (either sign of zero) and negative; a balancing load not found is not power.
    ideal = np.array([5.0 * sense, 0.0, -0.0, -5.0 * sense, math.nan])
    assert delivers_power(mechanism, ideal).tolist() == [True, True, True, False, False]


def test_the_friction_sentence_names_mb0_over_mb_where_the_loads_take_no_power():
    mechanism = analyse(scene_from_text(SCENE.format(omega=10.0))).mechanism
    text = strings("en")

    def ratio(ideal: float, load: float) -> str:
        return friction_summary(mechanism, text, ideal, load, write=lambda value: f"{value:g}", iterations=3,
                                written_efficiency="η")

    assert "Mb0/Mb" in ratio(0.0, 2.0)
    assert "Mb0/Mb" in ratio(4.0, 5.0)
    assert "Mb/Mb0" in ratio(-5.0, -4.0)
