"""Work a cold run did for nothing (bench/cold_run.py): a sheet's bounds walked to set a page it was given, and the
note's Markdown asked whether it had a CJK character one character at a time (116 000 calls for a note with none).
Each test holds the answers to an independent reckoning, and that the needless work is gone.
"""

from __future__ import annotations

import unicodedata

import pytest

from graphplan.render import primitives, svg
from graphplan.render.primitives import Layer, Polyline
from graphplan.report import latex


def test_a_sheet_given_its_page_is_not_measured(monkeypatch):
    def refuse(_layers):
        raise AssertionError("the drawing was measured for a page it was given")

    monkeypatch.setattr(svg, "bounds", refuse)
    layers = [Layer("lines", (Polyline(((0.0, 0.0), (100.0, 50.0))),))]
    text = svg.to_svg(layers, page=(420.0, 297.0))
    assert 'width="420mm"' in text and 'height="297mm"' in text
    with pytest.raises(AssertionError, match="measured"):
        svg.to_svg(layers)


def test_has_wide_asks_once_a_character(monkeypatch):
    asked: list[str] = []

    def counted(character: str) -> bool:
        asked.append(character)
        return unicodedata.east_asian_width(character) in ("W", "F")

    monkeypatch.setattr(primitives, "is_wide", counted)
    note = "ω = 12 rad/s, F₂₃ — " * 2000
    assert not primitives.has_wide(note)
    assert len(asked) == len(set(note))
    asked.clear()
    assert not primitives.has_wide("plain ASCII " * 1000) and not asked
    assert primitives.has_wide(note + "力")


def test_latex_escapes_and_marks_cjk_runs_as_before():
    assert latex._escape("50% of a_b {x}") == r"50\% of a\_b \{x\}"
    assert latex._escape("ω₁ = 3") == "ω₁ = 3"
    assert latex._escape("力 F_1 矩") == r"\notecjk{力} F\_1 \notecjk{矩}"
    assert latex._escape("") == ""
