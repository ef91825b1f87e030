"""The note printed ``R34 = −(1356.4)/0.425 = −3191.7 N``, where 1356.4/0.425 is 3191.5: its numbers were written
shorter than the arithmetic needs (lCA = 0.42496), and ``M(G4) = 176.58·0.05557 = 9.8121`` (9.8125) alike.  Every
formula of the force analysis with its numbers put in is worked out here again from the numbers as printed, and must
give its printed result to the result's last printed digit: an independent check of what the reader can redo with a
calculator.  Products and quotients (``a·b = c``, ``a/b = c``, ``−1356.35/0.42496 = −3191.7``) and the moment
equations' sums (``ΣMC(4) = R34·0.42496 + 9.8121 + … = 0 ⇒ R34 = −1356.35/…``: the terms add up to 1356.35)."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.locale import strings

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
STARTERS = ["crank-rocker", "slider-crank", "slotted-lever", "shaper", "triad"]


def _number(written: str, mark: str) -> float:
    return float(written.replace("−", "-").replace(mark, "."))


def _half_unit(written: str, mark: str) -> float:
    """Half a unit of the last digit printed: 3191.7 → 0.05; a whole number's last digit that is not a nought."""
    digits = written.lstrip("−")
    if mark in digits:
        return 0.5 * 10.0 ** -len(digits.split(mark)[1])
    return 0.5 * 10.0 ** (len(digits) - len(digits.rstrip("0")))


def worked_formulas(text: str, mark: str) -> list[tuple[str, float, str]]:
    """Each formula of ``text`` worked out from its printed numbers: (the formula, its value, the result printed)."""
    digits = rf"\d+(?:{re.escape(mark)}\d+)?"
    signed = rf"−?{digits}"
    # a·b = c, a·(−b) = c, a/b = c, −(−s)/a = r: numbers alone, not a symbol's subscript (R34·0.42496).
    chain = re.compile(rf"(?<![\w.,)·/(−])−?(?:\({signed}\)|{digits})(?:·\(?{signed}\)?|/{digits})+ = (?P<result>{signed})"
                       rf"(?![\d·⁰¹²³⁴⁵⁶⁷⁸⁹]|{re.escape(mark)}\d)")
    found = []
    for match in chain.finditer(text):
        formula = match.group(0).rsplit(" = ", 1)[0]
        python = formula.replace(mark, ".").replace("−", "-").replace("·", "*")
        found.append((match.group(0), eval(python), match["result"]))  # digits and operators alone
    # ΣM… = R·a ± t1 ± t2 = 0 ⇒ R = −s/a: the terms add up to s (in size), or to the couple or Mb found.
    sums = re.compile(rf"(?P<terms>(?: [+−] {digits})+) = 0 ⇒ \S+ = −?\(?(?P<result>{signed})\)?")
    for match in sums.finditer(text):
        terms = re.findall(rf" ([+−]) ({digits})", match["terms"])
        total = sum((-1.0 if sign == "−" else 1.0) * _number(size, mark) for sign, size in terms)
        found.append((match.group(0), abs(total), match["result"].lstrip("−")))
    return found


def _force_section(note: str, locale: str) -> str:
    heading = strings(locale)["note_forces"]
    start = re.search(rf"^## \d+\.? {re.escape(heading)}$", note, re.MULTILINE)
    assert start, note[:2000]
    end = re.search(r"^## ", note[start.end():], re.MULTILINE)
    return note[start.end(): start.end() + end.start() if end else None]


@pytest.fixture(scope="module")
def starter_note(tmp_path_factory):
    """note.md as ``graphplan run --only note`` writes it of a starter in a locale, run once for the module: the three
    checks below read the same English notes of every starter.  With ``--sheet none``: choosing μl by laying out
    course sheets the run does not write was most of the shaper's and the triad's run, and each starter's note.md is
    the same bytes without it (diffed once)."""
    notes: dict[tuple[str, str], str] = {}

    def note(starter: str, locale: str) -> str:
        if (starter, locale) not in notes:
            folder = tmp_path_factory.mktemp(f"{starter}-{locale}")
            scene, out = folder / f"{starter}.toml", folder / "out"
            assert main(["new", starter, "--out", str(scene)]) == 0
            assert main(["run", str(scene), "--out", str(out), "--only", "note", "--locale", locale,
                         "--sheet", "none"]) == 0
            notes[starter, locale] = (out / "note.md").read_text(encoding="utf-8")
        return notes[starter, locale]

    return note


@pytest.mark.parametrize(("starter", "locale"), [*((starter, "en") for starter in STARTERS), ("shaper", "ru")])
def test_the_force_analysis_s_printed_arithmetic_gives_its_printed_results(starter_note, starter, locale):
    mark = strings(locale)["decimal_mark"]
    section = _force_section(starter_note(starter, locale), locale)
    formulas = worked_formulas(section, mark)
    # Every moment equation is among them: a pattern that found none would pass by checking nothing.
    assert len(formulas) >= section.count("ΣM") > 0, section
    wrong = [(formula, value) for formula, value, result in formulas
             if abs(value - _number(result, mark)) > _half_unit(result, mark) * (1 + 1e-9)]
    assert not wrong, wrong
    # A single positive number stands in no brackets: −1356.35/0.42496, not −(1356.35)/0.42496.
    # (ΣME(5) names link 5: a bracket after a letter is no number's.)
    assert not re.search(rf"(?<![\w)])\((?:\d+(?:{re.escape(mark)}\d+)?)\)", section), section


@pytest.mark.parametrize("starter", STARTERS)
def test_the_plans_worked_out_formulas_give_their_printed_results(starter_note, starter):
    """The driving crank's VA = ω2·lOA, aAⁿ = ω2²·lOA, aA^τ = ε2·lOA and each Coriolis acceleration 2·ω·V, with their
    numbers put in (6.2832²·0.1 gave 3.9479 where 3.9478 was printed), worked out again from the printed numbers."""
    note = starter_note(starter, "en")
    symbolic = re.compile(r"(?:ω\d+²?·l\w+|ε\d+·l\w+|2·ω\d+·V\w+(?: \(ω\d+ = ω\d+\))?) = (?P<rest>[^ ]+ = −?[\d.]+)")
    # ω² as the product it stands for, which the pattern of products reads.
    formulas = [formula for match in symbolic.finditer(note)
                for formula in worked_formulas(re.sub(r"([\d.]+)²", r"\1·\1", match["rest"]), ".")]
    assert formulas, note[:3000]
    wrong = [(formula, value) for formula, value, result in formulas
             if abs(value - _number(result, ".")) > _half_unit(result, ".") * (1 + 1e-9)]
    assert not wrong, wrong


@pytest.mark.parametrize(("starter", "locale"), [*((starter, "en") for starter in STARTERS), ("crank-rocker", "ru")])
def test_a_reading_off_a_plan_gives_its_printed_result(starter_note, starter, locale):
    """``VB = pb·μV = 61.27·0.0062832 = 0.38498`` gave 0.38497: the plan's length, printed as drawn to a hundredth of
    a millimetre, is printed as exactly as the construction's length must be for its product with the stated scale
    (and, for an ω or ε, its quotient by the link's length) to give the value the note and the tables print."""
    mark = strings(locale)["decimal_mark"]
    note = starter_note(starter, locale)
    reading = re.compile(r"\w+·μ[Va](?:/l\w+)? = (?P<rest>[^ ]+ = −?[\d.,]+)")
    formulas = [formula for match in reading.finditer(note) for formula in worked_formulas(match["rest"], mark)]
    assert len(formulas) >= note.count("·μV = ") > 0, note[:3000]
    wrong = [(formula, value) for formula, value, result in formulas
             if abs(value - _number(result, mark)) > _half_unit(result, mark) * (1 + 1e-9)]
    assert not wrong, wrong
    # Drawn to a hundredth, and a digit more only where one digit fewer would not give the result: of the two
    # lengths a digit shorter on either side of the one printed, one at least misses it (the length rounded is one).
    for formula, _, result in formulas:
        length, rest = re.match(rf"(\d+(?:{re.escape(mark)}\d+)?)(.*) = ", formula).groups()
        decimals = len(length.split(mark)[1])
        assert decimals >= 2, formula
        if decimals > 2:
            unit = 10.0 ** -(decimals - 1)
            sides = [math.floor(_number(length, mark) / unit) * unit, math.ceil(_number(length, mark) / unit) * unit]
            worked = [eval(f"{side:.{decimals - 1}f}" + rest.replace(mark, ".").replace("·", "*")) for side in sides]
            assert any(abs(value - _number(result, mark)) > _half_unit(result, mark) for value in worked), formula


def _significant_digits(written: str, mark: str) -> int:
    figures = written.replace(mark, "").lstrip("−0")
    return len(figures if mark in written else figures.rstrip("0"))


@pytest.mark.parametrize("fixture", ["tangent_mechanism_prp", "engine_slider_crank"])
def test_a_moment_equation_s_numbers_are_no_longer_than_its_arithmetic_needs(tmp_path, capsys, fixture):
    """Lengthening every number of a formula at once, until its printed arithmetic gave its printed result, wrote the
    tangent mechanism's R54·h as 220.673322·0.56133356 = 123.87134 where 220.673·0.561334 reads 123.871, and the sum
    it stands in to as many digits again.  Each number is lengthened where that brings the arithmetic nearest now:
    the printed arithmetic still gives the printed results, and no number runs to eight significant digits."""
    out = tmp_path / "out"
    assert main(["run", str(FIXTURES / f"{fixture}.toml"), "--out", str(out), "--only", "note"]) == 0
    capsys.readouterr()
    section = _force_section((out / "note.md").read_text(encoding="utf-8"), "en")
    formulas = worked_formulas(section, ".")
    assert len(formulas) >= section.count("ΣM") > 0, section
    wrong = [(formula, value) for formula, value, result in formulas
             if abs(value - _number(result, ".")) > _half_unit(result, ".") * (1 + 1e-9)]
    assert not wrong, wrong
    # The moment equations' items, each moment on a line of its own within its item.
    items = [line for line in section.splitlines() if re.match(r"(?:- |  )(?:M|ΣM)", line)]
    numbers = [number for line in items for number in re.findall(r"(?<![\w.])\d+\.\d+", line)]
    long = [number for number in numbers if _significant_digits(number, ".") >= 8]
    assert numbers and not long, long
