"""Scenes graphplan must refuse, each at the key to change and with why, found by a hunt for gaps in its refusals.

* A resisting force whose point can never move along the force's line (a point of a slider on a frame guide with
  the force square to the guide, or a frame point a link turns about) has no motion to resist at any position.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import graphplan

# --- a resisting force with no motion to resist -------------------------------------------------------------------

# A slider-crank: crank OA = 0.1 m about O, rod AB = 0.35 m, slider 4 at B on a frame guide through O at
# `guide_deg`; a resisting force of 100 N at B along `force_deg`. B's velocity is along the guide at every crank
# angle (the slider only translates along it), so its part along the force is |vB|·cos(force − guide).
SLIDER_CRANK = """
[scene]
title = "Slider-crank with a resisting force on its slider"
[frame]
link = 1
points = {{ O = [0.0, 0.0] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.1
omega = 10.0
[[groups]]
kind = "RRP"
links = [3, 4]
joints = ["A", "B"]
length = 0.35
guide = {{ through = [0.0, 0.0], angle = {guide_deg} }}
assembly = "forward"
[links.4]
mass = 2.0
centre = "B"
[[loads]]
kind = "force"
link = {link}
point = "{point}"
value = 100.0
angle = {force_deg}
resisting = true
[positions]
count = 12
"""


def _slider_crank(guide_deg: float = 0.0, force_deg: float = 90.0, link: int = 4, point: str = "B") -> str:
    return SLIDER_CRANK.format(guide_deg=guide_deg, force_deg=force_deg, link=link, point=point)


@pytest.mark.parametrize(("guide_deg", "force_deg"), [(0.0, 90.0), (0.0, -90.0), (30.0, 120.0), (30.0, 300.0)])
def test_a_resisting_force_square_to_its_sliders_frame_guide_is_refused(guide_deg, force_deg):
    text = _slider_crank(guide_deg, force_deg)
    # The slider's point moves along the guide alone: along the force's line its speed is rounding at every angle.
    motion = graphplan.solve(graphplan.load_text(_slider_crank(guide_deg, guide_deg)),
                             driver=np.radians(np.arange(0.0, 360.0, 1.0)))
    along = np.array([math.cos(math.radians(force_deg)), math.sin(math.radians(force_deg))])
    speed = motion.point("B").v
    assert np.all(np.abs(speed @ along) <= 1e-12 * np.abs(speed).max())
    with pytest.raises(graphplan.SceneError) as caught:
        graphplan.build(graphplan.load_text(text))
    assert str(caught.value) == (
        f"loads[0].resisting: B on link 4 moves only along its frame guide (at {guide_deg:g}°), square to the "
        f"force's line (at {force_deg:g}°), so it has no motion along that line to resist at any position: "
        "turn the force along the guide, or give it a set sense (resisting = false)")


@pytest.mark.parametrize(("guide_deg", "force_deg"), [(0.0, 180.0), (0.0, 89.0), (30.0, 45.0)])
def test_a_resisting_force_with_a_part_along_the_guide_is_taken(guide_deg, force_deg):
    mechanism = graphplan.build(graphplan.load_text(_slider_crank(guide_deg, force_deg)))
    assert len(mechanism.scene.loads) == 1


def test_a_resisting_force_square_to_the_guide_with_a_set_sense_is_taken():
    """Of a set sense, the force square to the guide is a load the guide takes: it stays."""
    text = _slider_crank().replace("resisting = true", "resisting = false")
    assert len(graphplan.build(graphplan.load_text(text)).scene.loads) == 1


def test_a_resisting_force_at_the_pivot_a_link_turns_about_is_refused():
    # O is a frame point: the crank turns about it, and it never moves along any line.
    with pytest.raises(graphplan.SceneError) as caught:
        graphplan.build(graphplan.load_text(_slider_crank(force_deg=30.0, link=2, point="O")))
    assert str(caught.value) == (
        "loads[0].resisting: O is a point of the frame (link 2 turns about it), so it never moves and a force there "
        "has no motion to resist: put the force at a point that moves, or give it a set sense (resisting = false)")


def test_a_resisting_force_square_to_a_named_frame_line_is_refused():
    text = _slider_crank().replace("guide = { through = [0.0, 0.0], angle = 0.0 }", 'guide = "x"').replace(
        "points = { O = [0.0, 0.0] }", 'points = { O = [0.0, 0.0] }\nlines = { x = { through = [0.0, 0.0], angle = 0.0 } }')
    with pytest.raises(graphplan.SceneError, match=r"^loads\[0\]\.resisting: B on link 4 moves only along"):
        graphplan.build(graphplan.load_text(text))
