"""A weight typed where a scene asks for a mass (``weight = 166.8`` in N for ``mass = 17`` in kg) is refused at
that key with the mass it stands for, W/g: "unknown key" alone (on a link, whose mass may be left out), or "mass: is
required but missing" (on a machine on its mounts) left the student to find that graphplan takes masses, and
"did you mean 'mass'?" would have had the newtons typed as kilograms."""

from __future__ import annotations

import re

import pytest
from scene_texts import slider_crank_with_masses

from graphplan import SceneError
from graphplan.scene import loads

G = 9.80665  # standard gravity, m/s², as a weight in N is told from a mass in kg


def _mass_offered(error: SceneError) -> float:
    return float(re.search(r"here mass = ([\d.]+)", str(error)).group(1))


@pytest.mark.parametrize("key", ["weight", "Weight", "W"])
def test_a_links_weight_is_told_as_the_mass_it_stands_for(key):
    text = slider_crank_with_masses("press", 0.1, 0.4, 120.0, (0.05, 0.15), (3.0, 10.0, 2.0), (0.01, 0.2))
    weighed = re.sub(r"(?m)^mass\s*=\s*10\.0$", f"{key} = {10.0 * G}", text, count=1)
    assert weighed != text
    with pytest.raises(SceneError) as caught:
        loads(weighed)
    assert caught.value.where.endswith(f".{key}")
    assert _mass_offered(caught.value) == pytest.approx(10.0, rel=1e-3)


def test_a_machine_on_its_mounts_given_its_weight_is_told_its_mass_not_that_mass_is_missing():
    text = ("[vibration]\nweight = 300\nstiffness = 1.2e6\ndamping_ratio = 0.2\n"
            "unbalance = { mass = 2, eccentricity = 0.04 }\nrpm = 3000\n")
    with pytest.raises(SceneError) as caught:
        loads(text)
    assert caught.value.where == "vibration.weight"
    assert _mass_offered(caught.value) == pytest.approx(300 / G, rel=1e-3)
