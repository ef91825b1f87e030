"""The force sheet with friction gives a slide's friction in numbers, as it gives a journal's friction circle: its
coefficient f (f′ = f/sin θ in a V-guide), the friction angle φ = arctan f′ by which the reaction and the friction
force lean together, and the friction force Ff.  A slide had only an unlabelled Ff arrow.

Checked on the massless central slider-crank of ``test_joint_friction``, its piston in a guide with friction f
(θ the V-guide's half angle): with s the sign of the piston's velocity and β the rod's angle, the rod force is
S = P/(cos β − f′·s·|sin β|), the guide's normal reaction N = S·|sin β|, and Ff = f′·N.
"""

import dataclasses
import math
import re

import numpy as np
import pytest
from test_joint_friction import PUSH, rod_angle, slider_crank

from graphplan.analysis import analyse
from graphplan.locale import strings
from graphplan.render import forces as force_layout
from graphplan.render.drawings import force_sheet, with_length_scale

F = 0.1
NUMBER = r"([\d.]+)"
# The clauses of the line after «sliding friction:», Latin or, after Chinese words, full-width (and broken there).
COMMA = r"(?:, |，\s?)"


def caption_of(analysis, position) -> str:
    group = position.with_friction.groups[0]  # the piston's group, II(3,4)
    layers = {layer.name: layer.items for layer in force_layout.layout(force_sheet(analysis, position, True))}
    return " ".join(item.text for item in layers[f"body-{force_layout.group_id(group.label)}-caption"])


@pytest.mark.parametrize(("theta", "locale"), [(None, "en"), (30.0, "en"), (30.0, "ru"), (45.0, "zh"), (90.0, "en")])
def test_a_slide_s_coefficient_friction_angle_and_friction_force_are_written_under_its_group(theta, locale):
    groove = "" if theta is None else f"\ngroove_half_angle = {theta}"
    scene = slider_crank(f'[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {F}{groove}')
    analysis = with_length_scale(analyse(dataclasses.replace(scene, locale=locale)))
    reduced = F if theta is None else F / math.sin(math.radians(theta))
    beta = rod_angle(analysis.motion.driver)
    piston = np.sign(analysis.motion.point("B").v[:, 0])
    normal = PUSH * np.abs(np.sin(beta)) / (np.cos(beta) - reduced * piston * np.abs(np.sin(beta)))
    for position in analysis.plans:
        caption = caption_of(analysis, position)  # the SVG writer puts in the locale's decimal mark
        assert strings(locale)["sliding_friction"].split("{")[0].strip() in caption
        arctan = strings(locale)["arctangent"]  # arctg in Russian
        if theta is None or theta == 90.0:  # a flat guide: f itself, no reduced f′
            flat = re.search(rf"\bfB = {NUMBER}{COMMA}φ = {arctan} f = {NUMBER}°", caption)
            assert flat and "f′" not in caption
            written_f, angle = map(float, flat.groups())
        else:
            given, half, written_f, angle = map(float, re.search(
                rf"f′B = {NUMBER}/sin {NUMBER}° = {NUMBER}{COMMA}φ = {arctan} f′ = {NUMBER}°", caption).groups())
            assert (given, half) == (F, theta)
        assert written_f == pytest.approx(reduced, rel=1e-3)
        assert angle == pytest.approx(math.degrees(math.atan(reduced)), rel=1e-3)
        friction = float(re.search(rf"Ff14 = {NUMBER} ", caption).group(1))
        assert friction == pytest.approx(reduced * normal[position.index], rel=1e-3)
