"""The V-twin fixture against the slider-crank's closed forms, worked from the scene's own lengths.

Both rods are pinned to one crank pin, and each piston runs along its own cylinder through the crank's pivot at
angle α.  With ψ = φ − α the crank's angle from that axis, the piston stands

    s = r·cos ψ + √(l² − r²·sin² ψ)

from O and moves at ds/dt = −ω·r·sin ψ·(1 + r·cos ψ/√(l² − r²·sin² ψ)).  Each is at its top dead centre where the
crank lies along its cylinder (ψ = 0), so the rear one reaches it the V's angle after the front one, and its
expansion stroke, which its gas force acts over, begins there."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import graphplan

SCENE = Path(__file__).resolve().parent.parent / "fixtures" / "v_twin_engine.toml"
TIGHT = 1e-9


def _document() -> dict:
    return tomllib.loads(SCENE.read_text(encoding="utf-8"))


def _cylinders(document: dict) -> dict[str, tuple[float, float]]:
    """Each piston's pin, with its cylinder's angle (rad) and its rod's length."""
    lines = document["frame"]["lines"]
    return {group["joints"][1]: (math.radians(lines[group["guide"]]["angle"]), group["length"])
            for group in document["groups"]}


def test_each_piston_moves_as_a_centric_slider_crank_along_its_own_cylinder():
    document = _document()
    r = document["driver"]["length"]
    omega = document["driver"]["rpm"] * 2 * math.pi / 60
    phi = 2 * np.pi * np.arange(72) / 72
    motion = graphplan.solve(graphplan.load(SCENE), driver=phi)
    for pin, (alpha, rod) in _cylinders(document).items():
        axis = np.array([math.cos(alpha), math.sin(alpha)])
        psi = phi - alpha
        root = np.sqrt(rod**2 - (r * np.sin(psi)) ** 2)
        along = motion.point(pin).r @ axis
        np.testing.assert_allclose(along, r * np.cos(psi) + root, atol=TIGHT * rod)
        np.testing.assert_allclose(motion.point(pin).r - np.outer(along, axis), 0.0, atol=TIGHT * rod)
        speed = -omega * r * np.sin(psi) * (1 + r * np.cos(psi) / root)
        np.testing.assert_allclose(motion.point(pin).v @ axis, speed, atol=TIGHT * omega * r)


def test_the_rear_cylinder_reaches_its_top_dead_centre_the_vs_angle_after_the_front():
    document = _document()
    (front, _), (rear, _) = _cylinders(document).values()
    scene = graphplan.load(SCENE)
    positions = scene.analyse().positions
    assert positions.extremes[0] % (2 * math.pi) == pytest.approx(front, abs=1e-9), "the run starts at its TDC"
    rear_start, rear_end = positions.load_strokes[(6, "backward")]
    assert (rear_start % (2 * math.pi), rear_end % (2 * math.pi)) == pytest.approx((rear, rear + math.pi), abs=1e-9)
    working, idle = positions.stroke_turns(1)
    assert (working, idle) == pytest.approx((math.pi, math.pi), abs=1e-9), "a centric slider-crank: K = 1"
    motion = graphplan.solve(scene, driver=[front, rear])
    tops = [np.hypot(*motion.point(pin).r[k]) for k, pin in enumerate(("B", "C"))]
    rod = document["groups"][0]["length"]
    assert tops == pytest.approx([document["driver"]["length"] + rod] * 2, abs=1e-12)
    assert (rear - front) == pytest.approx(math.pi / 2), "a 90° V"
