"""How numbers are written on the drawings (graphplan.render.numerals), against values rounded by hand."""

import pytest

from graphplan.render.numerals import scale_factor, short, significant


@pytest.mark.parametrize(("value", "written"), [
    (1234.5678, "1235"), (12.3456, "12.35"), (-12.3456, "−12.35"), (0.000123456, "0.0001235"),
    (49.02, "49.02"), (1530.4, "1530"), (-0.00004, "−0.00004000"), (0.0, "0"), (-0.0, "0"),
])
def test_significant_writes_four_digits_with_no_exponent_and_a_true_minus(value, written):
    assert significant(value) == written


def test_significant_takes_other_counts_of_digits():
    assert significant(2.0 / 3.0, 2) == "0.67"
    assert significant(-0.0004, 1) == "−0.0004"
    assert significant(-0.00001, 2) == "−0.000010"
    assert significant(float("nan")) == "0"


@pytest.mark.parametrize(("value", "written"), [
    (0.3333333, "0.33333"), (8.948604, "8.9486"), (0.0001666667, "0.0001667"), (50.0, "50"),
    (2.975 / 150, "0.01983"), (0.50575, "0.50575"), (0.0004, "0.0004"), (0.001, "0.001"),
    (1.234e-6, "0.000001234"), (250.0, "250"), (0.0, "0"),
])
def test_a_scale_factor_keeps_four_significant_digits_and_five_decimals_at_least(value, written):
    assert scale_factor(value) == written


@pytest.mark.parametrize(("value", "written"), [
    (0.05, "0.05"), (-200.0, "−200"), (1.0 / 3.0, "0.3333"), (100.0, "100"), (1500.0, "1500"),
    (12345.6, "12346"), (-0.0, "0"), (float("nan"), "nan"),
])
def test_short_drops_the_trailing_noughts(value, written):
    assert short(value) == written


@pytest.mark.parametrize(("value", "written", "reported"), [
    (6.3e307, "6.3·10³⁰⁷", "6,3·10³⁰⁷"), (-1.23456e15, "−1.235·10¹⁵", "−1,2346·10¹⁵"),
    (999_999_999_999.9, "1·10¹²", "1·10¹²"), (2.5e13, "2.5·10¹³", "2,5·10¹³"), (-868_600.0, "−868600", "−868600"),
])
def test_a_number_too_large_to_read_whole_is_written_as_a_power_of_ten(value, written, reported):
    """A balancing moment of -4e307 near a lock was printed as a 308-digit integer in the note."""
    from graphplan.report.forces import number

    assert significant(value) == written and short(value) == written
    assert number(value, mark=",") == reported
