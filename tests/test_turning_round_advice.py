"""A crank that reaches only part of its turn is told what the lengths of the group that stops it must be for it to
turn round, read off the groups before it over the whole turn.  A slider driven off a four-bar's coupler point was
told only where its first position failed: lengthened past that, the rod was refused at the next position, and so
on, while the bound it had to clear was a number the refusal could give.  A crank that assembles at no angle is told
the lengths that close the group at some angle, where it was told only to check the lengths."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.mechanism import build
from graphplan.positions import reach
from graphplan.scene import loads

# A crank-rocker (O, C 0.55 m above it; OA 0.175, AB 0.55, BC 0.325 m, B left of A→C) whose coupler point E, 0.30 m
# along A→B and 0.12 m to its left, drives a slider on the line y = −0.35 m through a rod EF.
COUPLER_SLIDER = """
[scene]
title = "Coupler-driven slider"
[frame]
link = 1
points = {{ O = [0.0, 0.0], C = [0.0, 0.55] }}
[driver]
kind = "crank"
link = 2
pivot = "O"
joint = "A"
length = 0.175
omega = -17.0
[[groups]]
kind = "RRR"
links = [3, 4]
joints = ["A", "B", "C"]
lengths = [0.55, 0.325]
assembly = "left"
[[groups]]
kind = "RRP"
links = [5, 6]
joints = ["E", "F"]
length = {rod}
guide = {{ through = [0.0, -0.35], angle = 0.0 }}
assembly = "forward"
[points]
E = {{ link = 3, from = "A", toward = "B", at = 0.30, offset = 0.12 }}
[positions]
count = 12
"""


def _four_bar() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The crank angles (a thousandth of a degree apart), B and E over the turn, from the four-bar's closure solved
    here by the law of cosines."""
    phi = np.radians(np.arange(0.0, 360.0, 0.001))
    a = 0.175 * np.exp(1j * phi)
    c = 0.55j
    ac = c - a
    gap = np.abs(ac)
    # B left of A→C: the angle at A turned counter-clockwise from A→C.
    at_a = np.arccos((0.55**2 + gap**2 - 0.325**2) / (2 * 0.55 * gap))
    b = a + 0.55 * ac / gap * np.exp(1j * at_a)
    e = a + (0.30 + 0.12j) * (b - a) / np.abs(b - a)
    return phi, b, e


def _farthest_from_the_guide() -> tuple[float, float]:
    """E's greatest height above the guide y = −0.35 m over the turn and the crank angle (degrees) there."""
    phi, _, e = _four_bar()
    heights = np.abs(e.imag + 0.35)
    farthest = int(np.argmax(heights))
    return float(heights[farthest]), float(np.degrees(phi[farthest]))


def _refusal(tmp_path, capsys, rod: float) -> tuple[int, str]:
    scene = tmp_path / f"coupler_{rod}.toml"
    scene.write_text(COUPLER_SLIDER.format(rod=rod), encoding="utf-8")
    code = main(["check", str(scene)])
    return code, capsys.readouterr().err


def test_a_rod_too_short_for_a_coupler_point_is_told_the_bound_over_the_whole_turn(tmp_path, capsys) -> None:
    """Refused at its first failing position, 0.6 m short of 0.6009 m there, the rod must clear E's farthest from
    the guide over the turn, 0.7295 m: the refusal names that, where, and the least length of four figures above
    it, which then turns the crank round, and a tenth of a millimetre less still does not."""
    most, where = _farthest_from_the_guide()
    code, told = _refusal(tmp_path, capsys, 0.6)
    assert code == 2
    found = re.search(r"over the turn E comes as far as ([\d.]+) m from the guide \(at φ = ([\d.]+)°\), so the crank "
                      r"turns round only where EF > ([\d.]+) m: groups\[1\]\.length from ([\d.]+) m up", told)
    assert found, told
    assert float(found[1]) == pytest.approx(most, abs=6e-7) and float(found[3]) == float(found[1])
    assert float(found[2]) == pytest.approx(where, abs=0.01)
    least = float(found[4])
    assert least > most and least - most < 1e-4 and least == round(least, 4)
    # The bound told after the rocker's advice, as what to check if the crank is meant to turn round.
    assert told.index("drive it as a rocker") < told.index("meant to turn round") < found.start()

    assert _refusal(tmp_path, capsys, least)[0] == 0
    code, told = _refusal(tmp_path, capsys, round(least - 1e-4, 4))
    assert code == 2 and f"EF > {found[1]} m" in told


def test_a_group_that_is_not_what_stops_the_crank_is_not_given_a_bound(tmp_path, capsys) -> None:
    """A rod long enough over the turn says nothing of its length: a crank that reaches only part of its turn for
    another reason (here the four-bar's coupler too short to close) is told that group's bounds alone."""
    scene = tmp_path / "short_coupler.toml"
    scene.write_text(COUPLER_SLIDER.format(rod=1.0).replace("lengths = [0.55, 0.325]", "lengths = [0.38, 0.325]"),
                     encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    told = capsys.readouterr().err
    assert "over the turn E comes" not in told
    # A–C runs from 0.55 − 0.175 to 0.55 + 0.175 m, at the crank's 90° and 270°.
    assert ("over the turn A–C runs from 0.375 m (at φ = 90°) to 0.725 m (at φ = 270°), so the crank turns round "
            "only where AB + BC > 0.725 m and |AB − BC| < 0.375 m") in told, told
    # AB > 0.725 − 0.325 and |AB − 0.325| < 0.375; BC > 0.725 − 0.38 and |0.38 − BC| < 0.375.
    assert ("groups[0].lengths[0] (AB) from 0.4001 m to 0.6999 m with BC as given, or groups[0].lengths[1] (BC) "
            "from 0.3451 m to 0.7549 m with AB as given") in told


def test_a_guide_on_a_moving_link_is_read_as_it_turns(tmp_path, capsys) -> None:
    """The slider's guide on the rocker 4, through its point D 0.2 m from C toward B and along C→B: E's farthest
    from that line as the rocker swings is the bound, 0.2773 m, which the rod of 0.27 m falls short of."""
    _, b, e = _four_bar()
    along = (b - 0.55j) / np.abs(b - 0.55j)
    d = 0.55j + 0.2 * along
    most = float(np.max(np.abs((np.conj(along) * (e - d)).imag)))
    scene = COUPLER_SLIDER.replace("guide = {{ through = [0.0, -0.35], angle = 0.0 }}",
                                   'guide = {{ link = 4, through = "D", angle = 0.0 }}')
    scene = scene.replace("[points]\n", '[points]\nD = {{ link = 4, from = "C", toward = "B", at = 0.2 }}\n')
    path = tmp_path / "guide_on_the_rocker.toml"
    path.write_text(scene.format(rod=0.27), encoding="utf-8")
    assert main(["check", str(path)]) == 2
    told = capsys.readouterr().err
    found = re.search(r"over the turn E comes as far as ([\d.]+) m from the guide .*?groups\[1\]\.length from "
                      r"([\d.]+) m up", told)
    assert found, told
    assert float(found[1]) == pytest.approx(most, abs=6e-7)  # to its six figures
    path.write_text(scene.format(rod=float(found[2])), encoding="utf-8")
    assert main(["check", str(path)]) == 0


# --- a crank that assembles at no angle ----------------------------------------------------------------------------

def test_a_four_bar_that_closes_at_no_angle_is_told_each_length_that_closes_it_at_some(tmp_path, capsys) -> None:
    """AB = BC = 0.1 m for the four-bar's A–C of 0.375 … 0.725 m (0.55 m ∓ the crank's 0.175 m, at 90° and 270°):
    B closes at some angle only where AB + BC ≥ 0.375 and |AB − BC| ≤ 0.725, AB from 0.275 to 0.825 m with BC at
    0.1, each told rounded inward; the solver finds a reach at each length told and none a tenth of a millimetre
    outside it."""
    text = COUPLER_SLIDER.format(rod=1.0)
    scene = tmp_path / "short_links.toml"
    scene.write_text(text.replace("lengths = [0.55, 0.325]", "lengths = [0.1, 0.1]"), encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    told = capsys.readouterr().err
    assert ("the mechanism assembles at no angle of link 2: A–C runs from 0.375 m (at φ = 90°) to 0.725 m (at φ = "
            "270°), so B closes at some angle only where AB + BC ≥ 0.375 m and |AB − BC| ≤ 0.725 m: "
            "groups[0].lengths[0] (AB) from 0.2751 m to 0.8249 m with BC as given, or groups[0].lengths[1] (BC) "
            "from 0.2751 m to 0.8249 m with AB as given") in told, told

    def reaches(ab: float) -> bool:
        return bool(reach(build(loads(text.replace("lengths = [0.55, 0.325]", f"lengths = [{ab}, 0.1]")))))

    assert reaches(0.2751) and reaches(0.8249) and not reaches(0.2749) and not reaches(0.8251)


def test_a_slider_whose_guide_no_angle_brings_in_reach_is_told_the_rod_that_reaches_it(tmp_path, capsys) -> None:
    """The engine's cylinder axis moved up to y = 0.5 m: the crank pin A, 0.05 m about O, comes no nearer it than
    0.45 m (at 90°), farther than the 0.19 m rod; a rod of 0.4501 m reaches it there."""
    text = Path("fixtures/engine_slider_crank.toml").read_text(encoding="utf-8").replace(
        'guide    = { through = "O", angle = 0.0 }', 'guide    = { through = [0.0, 0.5], angle = 0.0 }')
    scene = tmp_path / "far_guide.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["check", str(scene)]) == 2
    told = capsys.readouterr().err
    assert ("the mechanism assembles at no angle of link 2: A comes no nearer the guide than 0.45 m (at φ = 90°), "
            "farther than AB = 0.19 m: groups[0].length from 0.4501 m up, or the guide nearer A") in told, told

    def reaches(rod: float) -> bool:
        return bool(reach(build(loads(text.replace("length   = 0.19 ", f"length   = {rod} ")))))

    assert reaches(0.4501) and not reaches(0.4499)
