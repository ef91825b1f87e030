"""The Whitworth quick-return fixture against its closed forms, worked from the scene's own lengths.

Its crank (r) is longer than the distance d by which its pivot O stands above the lever's pivot C, so the slotted
lever turns round with it: with φ the crank's angle, A = O + r·(cos φ, sin φ) and the lever's angle θ that of CA,

    dθ/dφ = (r² + d·r·sin φ) / (r² + d² + 2·d·r·sin φ),

2/3 at φ = 90° and 2 at 270°.  The lever's arm CD points away from A, and the ram E rides a guide through C, pinned
to D by a link of length l: xE = xD + √(l² − yD²).  So the ram is at its ends where the lever lies along the guide,
where A crosses the guide: sin φ = −d/r, a working stroke of 180° + 2·arcsin(d/r) and a stroke of 2·CD."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import graphplan

SCENE = Path(__file__).resolve().parent.parent / "fixtures" / "whitworth_quick_return.toml"
TIGHT = 1e-9


def _lengths() -> dict[str, float]:
    document = tomllib.loads(SCENE.read_text(encoding="utf-8"))
    c, o = (np.array(document["frame"]["points"][name]) for name in "CO")
    (ram_link,) = (group for group in document["groups"] if group["kind"] == "RRP")
    return {"r": document["driver"]["length"], "d": float(np.hypot(*(o - c))), "cd": -document["points"]["D"]["at"],
            "l": ram_link["length"], "omega": document["driver"]["omega"]}


def _lever_rate(phi: np.ndarray, r: float, d: float) -> np.ndarray:
    return (r * r + d * r * np.sin(phi)) / (r * r + d * d + 2 * d * r * np.sin(phi))


def test_the_scene_is_a_whitworth_mechanism_not_an_oscillating_lever():
    lengths = _lengths()
    assert lengths["r"] > lengths["d"] > 0, "a crank longer than the centres' distance turns the lever round"
    assert lengths["cd"] > 0, "the lever's arm behind its pivot, away from the block"


def test_the_lever_and_the_ram_move_at_their_closed_form_rates():
    lengths = _lengths()
    r, d, cd, link, omega = (lengths[key] for key in ("r", "d", "cd", "l", "omega"))
    phi = 2 * np.pi * np.arange(72) / 72
    motion = graphplan.solve(graphplan.load(SCENE), driver=phi)
    lever_rate = _lever_rate(phi, r, d)
    np.testing.assert_allclose(motion.link(4).omega, omega * lever_rate, rtol=TIGHT, atol=TIGHT * abs(omega))
    assert np.all(motion.link(4).omega * omega > 0), "the lever never turns back"
    assert _lever_rate(np.radians([90.0, 270.0]), r, d) == pytest.approx([r / (r + d), r / (r - d)], rel=1e-12)

    theta = np.arctan2(d + r * np.sin(phi), r * np.cos(phi))
    y_d = -cd * np.sin(theta)
    x_e = -cd * np.cos(theta) + np.sqrt(link**2 - y_d**2)
    np.testing.assert_allclose(motion.point("E").r[:, 0], x_e, atol=TIGHT * link)
    ram_rate = cd * np.sin(theta) - cd**2 * np.sin(theta) * np.cos(theta) / np.sqrt(link**2 - y_d**2)
    np.testing.assert_allclose(motion.point("E").v[:, 0], omega * lever_rate * ram_rate, atol=TIGHT * abs(omega) * r)


def test_the_strokes_and_the_ram_travel_follow_from_the_lever_along_the_guide():
    lengths = _lengths()
    scene = graphplan.load(SCENE)
    working, idle = scene.analyse().positions.stroke_turns(int(math.copysign(1, lengths["omega"])))
    surplus = 2 * math.asin(lengths["d"] / lengths["r"])
    assert (working, idle) == pytest.approx((math.pi + surplus, math.pi - surplus), abs=1e-9)

    ends = graphplan.solve(scene, driver=list(scene.analyse().positions.extremes))
    assert np.abs(ends.point("A").r[:, 1]) == pytest.approx([0.0, 0.0], abs=1e-9), "A on the guide at each end"
    travel = abs(ends.point("E").r[1, 0] - ends.point("E").r[0, 0])
    assert travel == pytest.approx(2 * lengths["cd"], abs=1e-9)
