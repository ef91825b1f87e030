"""``results.json`` writes a value that is zero by the geometry as 0, not as the arithmetic's leftover."""

import math
from pathlib import Path

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.report.results import number, results, rounded
from graphplan.scene import loads

ENGINE = "fixtures/engine_slider_crank.toml"


@pytest.fixture(scope="module")
def engine_document():
    return results(analyse(graphplan.load(ENGINE)))


def test_the_engine_at_its_dead_centres_reads_exact_zeros_and_the_closed_form(engine_document):
    r, rod, omega = 0.05, 0.19, 1500.0 * math.pi / 30.0
    ratio = r / rod
    assert engine_document["extremes_deg"] == [0.0, 180.0]
    at = {p["driver"]["angle_deg"]: p for p in engine_document["positions"]}
    for angle, sign in ((0.0, 1.0), (180.0, -1.0)):
        crank_pin, piston, connecting_rod = at[angle]["points"]["A"], at[angle]["points"]["B"], at[angle]["links"]["3"]
        # Crank and rod lie along the line of stroke: every transverse coordinate and the piston's speed is zero.
        assert crank_pin["r"] == [pytest.approx(sign * r, rel=1e-12), 0.0]
        assert piston["r"] == [pytest.approx(r * sign + rod, rel=1e-12), 0.0]
        assert piston["v"] == [0.0, 0.0]
        assert crank_pin["v"][0] == 0.0 and crank_pin["a"][1] == 0.0
        assert connecting_rod["angle_deg"] == 0.0 and connecting_rod["epsilon"] == 0.0
        # The textbook's piston acceleration at the dead centres, −rω²(1 ± λ), and the rod's ω3 = ∓ω·λ.
        assert piston["a"] == [pytest.approx(-sign * r * omega**2 * (1 + sign * ratio), rel=1e-9), 0.0]
        assert connecting_rod["omega"] == pytest.approx(-sign * omega * ratio, rel=1e-9)


def test_no_number_in_the_engine_document_is_rounding_noise(engine_document):
    def tiny(value):
        if isinstance(value, dict):
            return [x for item in value.values() for x in tiny(item)]
        if isinstance(value, list):
            return [x for item in value for x in tiny(item)]
        return [value] if isinstance(value, float) and 0 < abs(value) < 1e-9 else []

    assert tiny(engine_document) == []


def test_a_value_is_judged_against_its_own_quantity():
    # The same 1e-13 is noise beside 1 and a value in its own right beside 1e-12.
    assert rounded([1.0, 1e-13, -2.5e-11]) == [1.0, 0.0, -2.5e-11]
    assert rounded([1e-12, 1e-13]) == [1e-12, 1e-13]
    assert rounded({"angle_deg": 359.9999999999999, "twist_deg": 1e-15, "error_percent": 3e-14,
                    "moment": 3e-14}) == {"angle_deg": 360.0, "twist_deg": 0.0, "error_percent": 0.0, "moment": 3e-14}
    assert rounded([math.nan, 2.0, True]) == [None, 2.0, True]
    assert number(-4e-13, noise=1e-12) == 0.0 and number(-4e-13) == -4e-13
    assert number(1.234567890123456) == 1.23456789012


def test_a_link_along_minus_x_reads_180_degrees_as_the_driver_does():
    """The crank started at −180°: cos and sin of −π leave −1.2e-16 across it, np.angle −180°; the driver's angle
    reads 180° all the same, and its link must not read the other end of the same half-turn."""
    text = Path(ENGINE).read_text(encoding="utf-8").replace('start       = "extreme"', "start = -180.0")
    first = results(analyse(loads(text)))["positions"][0]
    assert first["driver"]["angle_deg"] == 180.0
    assert first["links"]["2"]["angle_deg"] == 180.0


def test_a_crank_counted_on_round_the_turns_reads_its_angle_within_the_half_turns():
    """A crank turning clockwise from 196.6°: its angle ran −163.4, −193.4 … −493.4 in results.json, where the
    contract keeps every link's within (−180, 180], as the same crank's driver angle and its position say."""
    for path in ("fixtures/shaper_six_bar.toml", "fixtures/ratchet_crank_rocker.toml"):
        document = results(analyse(graphplan.load(path)))
        for position in document["positions"]:
            for link in position["links"].values():
                assert -180.0 < link["angle_deg"] <= 180.0
            crank = position["links"]["2"]["angle_deg"]
            driver = position["driver"]["angle_deg"]
            assert math.isclose((crank - driver) % 360.0, 0.0, abs_tol=1e-9) or \
                math.isclose((crank - driver) % 360.0, 360.0, abs_tol=1e-9)


def test_a_slide_with_no_normal_reaction_has_no_offset():
    """The scotch yoke slides up and down its vertical guide with no horizontal load on it: the guide's normal
    reaction R14 is zero (rounding's 1e-13 N at most), and holds the yoke by a couple alone.  Where such a force acts
    along the slide is no number: the couple over the noise gave 10¹⁵ m."""
    document = results(analyse(graphplan.load("fixtures/scotch_yoke.toml")))
    for position in document["positions"]:
        equilibrium = position["equilibrium"]
        assert equilibrium["reactions"]["R14"] == [0.0, 0.0]
        assert equilibrium["offsets"]["R14"] is None
        # The block's reaction from the slot is there and acts at its pin, where all the block's loads act.
        assert abs(equilibrium["reactions"]["R43"][1]) > 1.0 and equilibrium["offsets"]["R43"] == 0.0
        if "forces" in position:
            assert position["forces"]["offsets"]["R14"] is None
