"""``results.json`` writes a value that is zero by the geometry as 0, not as the arithmetic's leftover."""

import math

import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.report.results import number, results, rounded

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
