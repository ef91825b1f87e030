"""A wedge lift with friction on its incline, against the closed forms of the inclined plane.

A wedge 2 slides along the floor under a block 3, pinned to a rod 4 that slides in a vertical post and carries a
load W down; the incline rises at α.  With friction f = tan φ on the incline alone (the floor and the post
frictionless), the force along the floor that moves the wedge at constant speed is W·tan(α + φ) when it raises
the load, and W·tan(α − φ) held back when the load lowers: the efficiencies η = tan α / tan(α + φ) and
η′ = tan(α − φ) / tan α, and the wedge locks itself against the load (η′ ≤ 0) when φ ≥ α.  (I. I. Artobolevsky,
*Theory of Mechanisms and Machines*, the inclined plane and the wedge; the same in Shigley and Uicker, *Theory of
Machines and Mechanisms*, the efficiency of a wedge.)
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_texts import wedge_lift

from graphplan.analysis import analyse
from graphplan.report.note import note_markdown
from graphplan.report.results import results
from graphplan.scene import loads as scene_from_text

ALPHA_DEG, WEIGHT = 30.0, 1000.0


def wedge(f: float, velocity: float, extra: str = "") -> str:
    return wedge_lift(ALPHA_DEG, WEIGHT, velocity, count=6) + f"""[[friction]]
joint = "B"
links = [2, 3]
f = {f}
{extra}
"""


def run(f: float, velocity: float, extra: str = ""):
    return analyse(scene_from_text(wedge(f, velocity, extra)))


ALPHA = math.radians(ALPHA_DEG)


def test_raising_the_load_takes_w_tan_alpha_plus_phi_at_an_efficiency_tan_alpha_over_tan_alpha_plus_phi():
    f = 0.2
    phi = math.atan(f)
    analysis = run(f, -0.05)  # the wedge pushed back under the block: the load rises
    rubbing = analysis.with_friction
    np.testing.assert_allclose(np.abs(rubbing.balancing), WEIGHT * math.tan(ALPHA + phi), rtol=1e-9)
    for entry in results(analysis)["positions"]:
        assert entry["equilibrium"]["friction"]["efficiency"] == pytest.approx(
            math.tan(ALPHA) / math.tan(ALPHA + phi), rel=1e-9)
    assert not [w for w in analysis.warnings if w.code == "reverse-self-locking"]


def test_lowering_the_load_is_held_back_by_w_tan_alpha_minus_phi_at_an_efficiency_tan_alpha_minus_phi_over_tan_alpha():
    f = 0.2
    phi = math.atan(f)
    analysis = run(f, 0.05)
    rubbing, ideal = analysis.with_friction, analysis.equilibrium
    np.testing.assert_allclose(rubbing.balancing, -WEIGHT * math.tan(ALPHA - phi), rtol=1e-9)
    np.testing.assert_allclose(ideal.balancing, -WEIGHT * math.tan(ALPHA), rtol=1e-9)
    for entry in results(analysis)["positions"]:
        assert entry["equilibrium"]["friction"]["efficiency"] == pytest.approx(
            math.tan(ALPHA - phi) / math.tan(ALPHA), rel=1e-9)
    assert not [w for w in analysis.warnings if w.code == "reverse-self-locking"]


def test_a_wedge_steeper_in_friction_than_its_incline_locks_against_the_load_and_says_so():
    f = 0.7
    phi = math.atan(f)
    assert phi > ALPHA
    analysis = run(f, 0.05)
    rubbing = analysis.with_friction
    # The driver must now push the wedge on: the load alone no longer lowers.
    np.testing.assert_allclose(rubbing.balancing, WEIGHT * math.tan(phi - ALPHA), rtol=1e-9)
    assert not rubbing.locked.any()
    warned = {w.position for w in analysis.warnings if w.code == "reverse-self-locking"}
    assert warned == set(range(len(rubbing.balancing)))
    for entry in results(analysis)["positions"]:
        assert entry["equilibrium"]["friction"]["efficiency"] is None
    note = note_markdown(analysis)
    assert "η′ ≤ 0" in note and "Fb/Fb0 = —" not in note


def test_the_note_gives_no_friction_moment_to_a_pin_whose_links_do_not_turn_and_shows_a_grooves_reduced_f():
    extra = '[[friction]]\njoint = "B"\nlinks = [3, 4]\nf = 0.2\nradius = 0.01\n' \
            '[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = 0.2\ngroove_half_angle = 30'
    analysis = run(0.2, -0.05, extra)
    note = note_markdown(analysis)
    # Block and rod both translate: the pin between them carries no friction moment.
    assert "Mf34 = 0: links 3 and 4 do not turn relative to each other" in note
    assert "ρ34·R34" not in note
    # Three pairs at B: each named by its links; the groove's f′ = f/sin θ = 0.2/0.5.
    assert "f′14 = f/sin θ = 0.2/sin 30° = 0.4; Ff14 = f′14·R14" in note
    assert "f23 = 0.2; Ff23 = f23·R23" in note  # a flat slide: f as given, no reduced f′
