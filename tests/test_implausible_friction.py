"""A friction coefficient no pair of materials has, and which pair's friction locks the mechanism.

The central slider-crank of ``test_joint_friction`` (crank r = 0.1 m, rod l = 0.4 m, a force P along −x on the
piston).  f = 50 at the crank pin with r = 0.015 m makes the friction circle ρ = f·r = 0.75 m, wider than the crank
and the rod it joins: it locked every position with twelve identical warnings naming no pair, and was taken
silently.  With f in the guide alone the piston jams where cos β − f·s·|sin β| ≤ 0 (s the sign of its velocity);
a journal alone at the piston pin, ρ < l, never jams it: the rod's force line through A tangent to the pin's
friction circle always exists, and the frictionless guide takes any normal force.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_joint_friction import RADIUS, ROD, slider_crank, slider_crank_text

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.scene import loads as scene_from_text

GUIDE = '[[friction]]\njoint = "B"\nlinks = [1, 4]\nf = {f}\n'
PISTON_PIN = '[[friction]]\njoint = "B"\nlinks = [3, 4]\nf = {f}\nradius = {r}\n'


def jams_in_the_guide(analysis, f: float) -> np.ndarray:
    """Where the guide's friction f alone jams the piston, by the closed form."""
    phi = analysis.motion.link(2).angle
    beta = np.arcsin(RADIUS * np.sin(phi) / ROD)
    speed = -RADIUS * (np.sin(phi) + RADIUS * np.sin(2 * phi) / (2 * ROD * np.cos(beta)))
    return np.cos(beta) - f * np.sign(speed) * np.abs(np.sin(beta)) <= 0


def test_a_friction_circle_wider_than_the_links_of_its_journal_is_refused_naming_f():
    f, journal = 50.0, 0.015
    rho = f * journal
    assert rho > ROD > RADIUS
    with pytest.raises(graphplan.SceneError) as raised:
        analyse(slider_crank(f'[[friction]]\njoint = "A"\nf = {f:g}\nradius = {journal}'))
    message = str(raised.value)
    assert message.startswith(f"friction[0].f: makes the friction circle at A ρ = f·r = 50 × 0.015 m = {rho:g} m, "
                              f"larger than the links the journal joins (link 2 A–O: {RADIUS:g} m; link 3 A–B: "
                              f"{ROD:g} m)"), message
    assert "(50 % is f = 0.5)" in message and message.endswith("(got 50.0)")

    # Narrower than the rod it is taken, told as an f above 1.
    accepted = analyse(slider_crank(f'[[friction]]\njoint = "A"\nf = 20\nradius = {journal}'))
    assert accepted.friction[0].radius == pytest.approx(20 * journal) and 20 * journal < ROD


def test_an_f_above_1_is_warned_of_once_but_not_a_v_guide_s_reduced_f(tmp_path, capsys):
    analysis = analyse(slider_crank(GUIDE.format(f=5.0)))
    (warning,) = [w for w in analysis.warnings if w.code == "high-friction"]
    assert warning.position == 0
    assert warning.detail.startswith("friction[0].f = 5 (at B): few pairs of materials rub with an f above 1")
    # f′ = f/sin θ = 0.9/sin 30° = 1.8 in a V-guide is the groove's wedging, not an implausible f.
    vee = analyse(slider_crank(GUIDE.format(f=0.9) + "groove_half_angle = 30\n"))
    assert vee.friction[0].coefficient == pytest.approx(0.9 / np.sin(np.radians(30.0)))
    assert not [w for w in vee.warnings if w.code == "high-friction"]
    assert not [w for w in analyse(slider_crank(GUIDE.format(f=1.0))).warnings if w.code == "high-friction"]

    scene = tmp_path / "scene.toml"
    scene.write_text(slider_crank_text(GUIDE.format(f=5.0)), encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    assert "warning: friction[0].f = 5 (at B): few pairs" in capsys.readouterr().out


def test_the_lock_warning_names_the_guide_that_jams_and_the_console_tells_it_once(tmp_path, capsys):
    f = 5.0
    # A journal at the crank's pivot adds to the balancing moment and never locks: the guide is the one to name.
    friction = GUIDE.format(f=f) + '[[friction]]\njoint = "O"\nf = 0.1\nradius = 0.01\n'
    analysis = analyse(slider_crank(friction))
    jammed = jams_in_the_guide(analysis, f)
    np.testing.assert_array_equal(analysis.with_friction.locked, jammed)
    assert jammed.sum() > 1
    told = [w for w in analysis.warnings if w.code == "self-locking"]
    assert [w.position for w in told] == list(np.flatnonzero(jammed))
    detail = ("the friction in the slide at B (links 1–4, f = 5) locks the mechanism here: no driving load, however "
              "large, moves it")
    assert {w.detail for w in told} == {detail}

    scene = tmp_path / "scene.toml"
    scene.write_text(slider_crank_text(friction), encoding="utf-8")
    assert main(["check", str(scene)]) == 0
    lines = [line for line in capsys.readouterr().out.splitlines() if "locks the mechanism" in line]
    numbers = analysis.positions.numbers[jammed]
    assert list(numbers) == list(range(numbers[0], numbers[-1] + 1))   # one run of positions in a row
    assert lines == [f"warning: positions {numbers[0]}–{numbers[-1]}: {detail}"]


def test_a_lock_that_no_pair_makes_alone_names_them_together():
    """f = 3.5 in the guide stays short of jamming the piston (cos β − 3.5·|sin β| > 0 at every β of this crank);
    the piston pin's ρ = 0.012 m, less than the rod, never jams it alone; together they lock near φ = 277.5°."""
    guide, pin = 3.5, (0.6, 0.02)
    friction = GUIDE.format(f=guide) + PISTON_PIN.format(f=pin[0], r=pin[1])
    analysis = analyse(scene_from_text(slider_crank_text(friction)))
    assert not jams_in_the_guide(analysis, guide).any() and pin[0] * pin[1] < ROD
    told = [w for w in analysis.warnings if w.code == "self-locking"]
    assert told and [w.position for w in told] == list(np.flatnonzero(analysis.with_friction.locked))
    for warning in told:
        assert warning.detail.startswith(
            "the friction in the pairs together (the slide at B (links 1–4, f = 3.5); the journal at B (links 3–4, "
            f"ρ = {pin[0] * pin[1]:g} m); none alone) locks the mechanism here")


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_an_f_above_1_is_told_in_the_note_too(locale):
    import dataclasses

    from graphplan.locale import strings
    from graphplan.report.note import note_markdown

    def note(f: float) -> str:
        return note_markdown(analyse(dataclasses.replace(slider_crank(GUIDE.format(f=f)), locale=locale)))

    told = strings(locale)["note_warning_high_friction"]
    assert told in note(5.0) and told not in note(0.15)
