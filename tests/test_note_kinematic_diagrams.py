"""The note's section on the kinematic diagrams says how they are built and gives the scales diagrams.svg is drawn at.

A reviewer found the section a figure alone: no μφ, μt, μψ, no pole distance H, no word on the chord method.  The
scales the note gives are read here off the drawing beside it, and their arithmetic (μω = μψ/(μt·H₁),
με = μω/(μt·H₂), μt = μφ/|ω|) is done again from the numbers printed.
"""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
from sheet_texts import flat

import graphplan
from graphplan.cli import main
from graphplan.locale import strings

RATCHET = Path("fixtures/ratchet_crank_rocker.toml")
NUMBER = r"([\d.,]+)"


def _words_of(svg: Path) -> str:
    """The words the drawing writes, each text whole: a symbol's index, set as a run of its own, joined to it."""
    root = ElementTree.fromstring(flat(svg.read_text(encoding="utf-8")))
    return " ".join(element.text or "" for element in root.iter())


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_the_note_gives_the_diagrams_method_and_the_scales_they_are_drawn_at(tmp_path, locale):
    text = re.sub(r'^locale\s*=\s*"\w+"', f'locale = "{locale}"', RATCHET.read_text(encoding="utf-8"),
                  flags=re.MULTILINE)
    scene = tmp_path / "ratchet.toml"
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "note,diagrams"]) == 0
    note = (out / "note.md").read_text(encoding="utf-8")
    words = strings(locale)
    assert words["note_kd_method"] in note
    section = note[note.index(words["note_kd_method"]):note.index("](diagrams.svg)")]
    drawn = _words_of(out / "diagrams.svg")

    def scale(pattern: str) -> float:
        (found,) = re.findall(pattern, section)
        # The drawing writes the same scale with the same digits.
        assert re.search(pattern, drawn) and re.search(pattern, drawn).group(1) == found
        return float(found.replace(",", "."))

    along = scale(r"μφ = 2π/L = " + NUMBER)
    length = scale(r"L = " + NUMBER + " (?:mm|мм)")
    time = scale(r"μt = μφ/\|ω\| = " + NUMBER)
    omega = scale(r"\|ω\| = " + NUMBER + r" (?:rad/s|рад/с)")
    psi = scale(r"μψ = " + NUMBER)
    omega_scale = scale(r"μω = μψ/\(μt·H₁\) = " + NUMBER)
    first_pole = scale(r"H₁ = " + NUMBER)
    epsilon_scale = scale(r"με = μω/\(μt·H₂\) = " + NUMBER)
    second_pole = scale(r"H₂ = " + NUMBER)
    # The arithmetic the lines write, done again from their printed (rounded) numbers.
    assert along == pytest.approx(2 * 3.141592653589793 / length, rel=1e-3)
    assert time == pytest.approx(along / omega, rel=1e-3)
    assert omega_scale == pytest.approx(psi / (time * first_pole), rel=2e-3)
    assert epsilon_scale == pytest.approx(omega_scale / (time * second_pole), rel=2e-3)
    # And how far the chord method comes from the analytic curves, for the velocity and the acceleration.
    assert len(re.findall(r"\d %|% ", section)) >= 2



def _section(note: str, words) -> str:
    start = note.index(words["note_kd_method"])
    return note[start:note.index("\n#", start)]


@pytest.mark.parametrize("locale", ["en", "zh"])
def test_a_note_asked_for_alone_still_tells_the_diagrams(tmp_path, locale):
    """`--only note` wrote the kinematics of every plan and left out the diagrams' section, method and scales, which
    needed diagrams.svg beside it; the note alone now tells them as the note with the drawing does, only without
    the figure.  The Chinese note parts the formulas with its own semicolon, as its other sections do."""
    alone, drawn = tmp_path / "alone", tmp_path / "drawn"
    assert main(["run", str(RATCHET), "--out", str(alone), "--only", "note", "--locale", locale]) == 0
    assert main(["run", str(RATCHET), "--out", str(drawn), "--only", "note,diagrams", "--locale", locale]) == 0
    words = strings(locale)
    note_alone, note_drawn = ((folder / "note.md").read_text(encoding="utf-8") for folder in (alone, drawn))
    assert "](diagrams.svg)" not in note_alone
    told_alone = _section(note_alone, words)
    assert re.search(r"μω = μψ/\(μt·H₁\) = " + NUMBER, told_alone)
    # The same method, scales and differences, to the digit; the drawn note adds only its figure after them.
    assert _section(note_drawn, words).startswith(told_alone.rstrip())
    working = graphplan.load(RATCHET).positions.working
    assert f"3.3{'.' if locale == 'en' else ''} {words['kd_title'].format(link=working.link, point='').strip()}" \
        in note_alone
    assert (";" in told_alone) == (locale == "en")


def test_a_note_of_a_scene_that_leaves_the_diagrams_out_does_not_tell_them(tmp_path):
    text = RATCHET.read_text(encoding="utf-8") + '\n[output]\ninclude = ["velocity", "acceleration", "note"]\n'
    scene = tmp_path / "without_diagrams.toml"
    scene.write_text(text, encoding="utf-8")
    assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--only", "note", "--locale", "en"]) == 0
    note = (tmp_path / "out" / "note.md").read_text(encoding="utf-8")
    assert strings("en")["note_kd_method"] not in note
    assert "## 3." in note  # the kinematics are still there, without the diagrams
