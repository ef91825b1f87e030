"""A student's hand-drawn plans checked with graphplan: the slips a student makes in ``[measured.N]`` (a balancing
moment signed as drawn, lengths typed in centimetres or metres) are each told with the key and what was meant.

Every reading here is a length of the plans as the program constructs them, or the balancing moment, worked out in the
test from the scene's scales and the exact solution, never taken from a warning's text.
"""


import pytest

import graphplan

FIXTURE = "fixtures/offset_slider_crank.toml"
POSITION = 3


def _with(block):
    return graphplan.load_text(open(FIXTURE, encoding="utf-8").read() + "\n" + block + "\n")


def test_a_balancing_moment_signed_as_drawn_is_refused_with_its_size_to_give():
    with pytest.raises(graphplan.GraphplanError) as caught:
        _with(f"[measured.{POSITION}]\nbalancing = -35.5")
    message = str(caught.value)
    assert message.startswith(f"measured.{POSITION}.balancing: must be >= 0"), message
    assert "give its size, balancing = 35.5" in message, message
    assert "sense is taken from the force analysis" in message, message
