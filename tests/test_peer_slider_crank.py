"""The peers' slider-crank (bench/peers.py) against its closed form, and the closed form against finite differences.

bench/accuracy.py reports pylinkage's and mechanism's errors on the two slider-crank fixtures; these tests make
sure the peers are given the fixtures' linkage, not a near one: at twelve crank angles both peers must reproduce
``peers.reference_slider_crank`` (positions, velocities, accelerations; mechanism also ω3, ε3 and the slider's
ṡ, s̈), and that closed form must itself close its loop and agree with a finite difference of its own positions.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "bench"))

import peers  # bench/peers.py, found through the path above

# The fixtures' geometries (fixtures/engine_slider_crank.toml, fixtures/offset_slider_crank.toml), and a guide below
# O with a clockwise crank that accelerates, so that a sign slip in the offset or a dropped ε term shows.
GEOMETRIES = {
    "engine": {"crank": 0.05, "rod": 0.19, "offset": 0.0, "s3": 0.055, "omega": 1500 * math.pi / 30, "alpha": 0.0},
    "hacksaw": {"crank": 0.08, "rod": 0.26, "offset": 0.08, "s3": 0.13, "omega": 6.3, "alpha": 0.0},
    "below, accelerating": {"crank": 0.08, "rod": 0.26, "offset": -0.05, "s3": 0.2, "omega": -6.3, "alpha": 40.0},
}
KINDS = {"position": ("A", "B", "S3"), "velocity": ("vA", "vB", "vS3"), "acceleration": ("aA", "aB", "aS3"),
         "omega": ("omega3",), "alpha": ("alpha3",)}


def angles_for(geometry: dict) -> np.ndarray:
    """Twelve crank angles, 30° apart in the sense of rotation (pylinkage steps its crank, so they must be uniform)."""
    return 0.2375 + math.copysign(1.0, geometry["omega"]) * 2.0 * math.pi * np.arange(12) / 12


def worst_relative(got: dict, exact: dict, keys: tuple[str, ...]) -> float:
    """Largest |got − exact| over the keys, relative to the largest |exact| among them."""
    peak = max(float(np.max(np.abs(exact[k]))) for k in keys)
    return max(float(np.max(np.abs(np.asarray(got[k]) - exact[k]))) for k in keys) / peak


@pytest.mark.parametrize("name", GEOMETRIES)
def test_closed_form_closes_its_loop_and_matches_finite_differences(name):
    geometry = GEOMETRIES[name]
    omega, alpha = geometry["omega"], geometry["alpha"]
    angles = angles_for(geometry)
    ref = peers.reference_slider_crank(angles, **geometry)
    A, B, S3 = ref["A"], ref["B"], ref["S3"]
    assert np.allclose(np.hypot(*(B - A).T), geometry["rod"], rtol=0, atol=1e-15)
    assert np.allclose(B[:, 1], geometry["offset"], rtol=0, atol=0)
    assert np.all(B[:, 0] > A[:, 0])  # the slider on the +x side of the crank pin: assembly = "forward"
    assert np.allclose(S3, A + (B - A) * geometry["s3"] / geometry["rod"], rtol=0, atol=1e-15)

    # φ(t) = φ0 + ω t + ε t²/2; fourth-order central differences at t = 0 over ±1e-3 rad of crank turn.
    h = 1e-3 / abs(omega)
    steps = np.array([-2.0, -1.0, 1.0, 2.0]) * h
    turned = [peers.reference_slider_crank(angles + omega * t + alpha * t * t / 2, **geometry) for t in steps]
    first = np.array([1.0, -8.0, 8.0, -1.0]) / (12.0 * h)
    second = np.array([-1.0, 16.0, 16.0, -1.0]) / (12.0 * h * h)
    finite = {}
    for point in ("A", "B", "S3"):
        at = np.stack([t[point] for t in turned])
        finite["v" + point] = np.tensordot(first, at, axes=1)
        finite["a" + point] = np.tensordot(second, at, axes=1) - 30.0 / (12.0 * h * h) * ref[point]
    rod_angle = np.unwrap(np.stack([np.arctan2(*(t["B"] - t["A"]).T[::-1]) for t in turned]), axis=0)
    own_angle = np.arctan2(*(B - A).T[::-1])
    rod_angle += np.round((own_angle - rod_angle[1]) / (2 * math.pi)) * 2 * math.pi  # same turn as own_angle
    finite["omega3"] = first @ rod_angle
    finite["alpha3"] = second @ rod_angle - 30.0 / (12.0 * h * h) * own_angle
    # Truncation (Δφ)⁴ ~ 1e-12 and rounding ε·|r|/h² ~ 1e-10 of the peak: 1e-7 leaves a margin, and a wrong sign or a
    # missing term in the closed form is an error of order one.
    for kind in ("velocity", "acceleration", "omega", "alpha"):
        assert worst_relative(finite, ref, KINDS[kind]) < 1e-7, kind


@pytest.mark.parametrize("fast", [False, True], ids=["step", "step_fast"])
@pytest.mark.parametrize("name", GEOMETRIES)
def test_pylinkage_slider_crank_reproduces_the_closed_form(name, fast):
    pytest.importorskip("pylinkage")
    geometry = GEOMETRIES[name]
    angles = angles_for(geometry)
    got = peers.pylinkage_slider_crank(angles, **geometry, fast=fast)
    ref = peers.reference_slider_crank(angles, **geometry)
    # pylinkage steps its crank: each pose is atan2 of the last one plus 30°, so its crank angles differ from ours by
    # the rounding of those additions (crank_angle_error, ~1e-15 rad after twelve steps); everything after is in
    # closed form (circle-line intersection, implicit differentiation), so it agrees to ~1e-14 of the peak. It
    # reports no link rates. 1e-12 is a hundredfold margin on that; a modelling slip is an error of order one.
    assert got["crank_angle_error"] < 1e-13
    assert "omega3" not in got and "alpha3" not in got
    for kind in ("position", "velocity", "acceleration"):
        assert worst_relative(got, ref, KINDS[kind]) < 1e-12, kind


@pytest.mark.parametrize("name", GEOMETRIES)
def test_mechanism_slider_crank_reproduces_the_closed_form(name):
    pytest.importorskip("mechanism")
    geometry = GEOMETRIES[name]
    angles = angles_for(geometry)
    got = peers.mechanism_slider_crank(angles, **geometry)
    ref = peers.reference_slider_crank(angles, **geometry)
    # Each value is an fsolve root: its default xtol = 1.49e-8 stops on the relative step, which bounds the error
    # near 1e-8 (seen: below 1e-10), and the package rounds joint components under 1e-10 to zero. 1e-7 of the peak
    # covers both; a modelling slip is an error of order one.
    for kind, keys in KINDS.items():
        assert worst_relative(got, ref, keys) < 1e-7, kind
    # The slider vector runs along +x, so its ṡ and s̈ are B's x components.
    assert worst_relative({"s": got["slider_v"]}, {"s": ref["vB"][:, 0]}, ("s",)) < 1e-7
    assert worst_relative({"s": got["slider_a"]}, {"s": ref["aB"][:, 0]}, ("s",)) < 1e-7


@pytest.mark.parametrize("model", ["reference_slider_crank", "pylinkage_slider_crank", "mechanism_slider_crank"])
def test_a_slider_crank_whose_crank_cannot_turn_is_refused(model):
    if model != "reference_slider_crank":
        pytest.importorskip(model.split("_")[0])
    with pytest.raises(ValueError, match="does not turn a full revolution"):
        getattr(peers, model)(angles_for({"omega": 1.0}), crank=0.1, rod=0.15, offset=0.06)
