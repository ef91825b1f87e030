"""The dynamics drawing's flywheel results and the note print the same numbers, to the same digits.

A reader checks the sheet against the note: JF′ = 0.3881 on the drawing beside 0.38808 in the note, or
ωmin = 10.21 beside ωmax = 10.734, reads as two different results.  Each number of the drawing's results is
looked for, as written, in the note of the same run; the flywheel starter's are also worked out here from its
scene, independently of the program.
"""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.starters import starter

SVG = "{http://www.w3.org/2000/svg}"
NUMBER = re.compile(r"−?\d+(?:[.,]\d+)?")


def _run(folder: Path, kind: str, locale: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    scene = folder / "scene.toml"
    scene.write_text(starter(kind, locale), encoding="utf-8")
    out = folder / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", "dynamics,note", "--sheet", "none"]) == 0
    return out


def _results(out: Path) -> list[str]:
    """The lines of the drawing's results (its heading first)."""
    groups = {g.get("id"): g for g in ElementTree.parse(out / "dynamics.svg").getroot().iter(f"{SVG}g")}
    return ["".join(text.itertext()) for text in groups["results"].iter(f"{SVG}text")]


def _flywheel_section(out: Path) -> str:
    """The note's section on the dynamics up to its drawing (or the first part of it), the flywheel's paragraphs
    last."""
    note = (out / "note.md").read_text(encoding="utf-8")
    end = note.index("](dynamics")
    return note[note.rindex("\n## ", 0, end):end]


def _drawing_only(template: str, key: str) -> re.Pattern[str]:
    """The part of a line that only the drawing writes: the locale's ``template`` with its ``{key}`` a number."""
    return re.compile(re.escape(template).replace(re.escape("{" + key + "}"), NUMBER.pattern))


def _in(value: str, text: str) -> bool:
    """Whether ``text`` writes the number ``value`` whole: not 10.21 read in 10.210."""
    return re.search(rf"(?<![\d.,]){re.escape(value)}(?![\d]|[.,]\d)", text) is not None


CASES = [(kind, locale) for kind in ("flywheel", "shaper") for locale in ("en", "ru", "zh")]


@pytest.fixture(scope="module", params=CASES, ids=lambda param: "-".join(param))
def run(request, tmp_path_factory) -> tuple[str, str, Path]:
    kind, locale = request.param
    return kind, locale, _run(tmp_path_factory.mktemp(f"{kind}_{locale}"), kind, locale)


def test_every_number_of_the_drawings_results_is_in_the_note_as_written(run):
    _, locale, out = run
    lines, note = _results(out), _flywheel_section(out)
    words = strings(locale)
    mark = words["decimal_mark"]
    # What the note does not write: Mertsalov's Jc, the angle of an extreme speed counted from the cycle's start.
    mertsalov = words["dyn_mertsalov"]
    own = [_drawing_only(mertsalov[mertsalov.rindex("{value}") + len("{value}"):], "constant"),
           _drawing_only(words["dyn_into_cycle"], "travel")]
    written = []
    for line in lines[1:]:
        for pattern in own:
            line = pattern.sub("", line)
        # A formula's own numbers (ωmax²/2, Je taken as 0) are not results.
        written += [value for value in NUMBER.findall(line)
                    if not re.search(rf"/{re.escape(value)}\b|\b{re.escape(value)}\)$", line)]
    for value in written:
        if "." in value or "," in value:
            assert mark in value, (value, mark)
        # Written whole in the note: "JF′ = JF·(n/n′)² = 0.38808", "ωmin = 10.210" (not 0.3881, 10.21).
        assert _in(value, note), (value, lines)
    assert len(written) >= 9, written


def test_the_flywheel_starters_numbers_are_the_worked_out_ones_to_five_digits(run):
    """Worked out from the starter's scene: ΔWmax from its resisting power against the constant driving one, JF =
    ΔWmax/(ωm²δ) (its own inertia nought), ωmax,min = ωm(1 ± δ/2), JF′ = JF·(n/n′)²; each to five significant
    digits, trailing noughts kept, in the drawing and the note alike."""
    kind, locale, out = run
    if kind != "flywheel":
        pytest.skip("the shaper's flywheel is the energy-mass diagram's, worked out by the program alone")
    dynamics = tomllib.loads(starter("flywheel", locale))["dynamics"]
    assert dynamics["inertia"] == 0 and dynamics["driving"] == "constant"
    delta, rpm, other = dynamics["delta"], dynamics["rpm"], dynamics["flywheel_shaft_rpm"]
    omega = rpm * math.pi / 30
    angles, powers = np.array(dynamics["resisting_power"], dtype=float).T
    # The driving power is constant, the mean of the resisting one; the surplus of work summed segment by segment
    # (exact for a power linear between its points), its extremes at the points or where a segment crosses the mean.
    mean = float(np.sum(np.diff(angles) * (powers[1:] + powers[:-1]) / 2)) / 360.0
    surplus, extremes = 0.0, [0.0]
    for (a0, p0), (a1, p1) in zip(zip(angles, powers), zip(angles[1:], powers[1:])):
        if (p0 - mean) * (p1 - mean) < 0:
            crossing = a0 + (a1 - a0) * (mean - p0) / (p1 - p0)
            extremes.append(surplus + (crossing - a0) * (mean - (p0 + mean) / 2))
        surplus += (a1 - a0) * (mean - (p0 + p1) / 2)
        extremes.append(surplus)
    work = (max(extremes) - min(extremes)) * math.pi / 180 / omega
    inertia = work / (omega * omega * delta)
    mark = strings(locale)["decimal_mark"]

    def five(value: float) -> str:
        return f"{value:.{4 - math.floor(math.log10(abs(value)))}f}".replace(".", mark)

    drawing = "\n".join(_results(out))
    note = _flywheel_section(out)
    for value in (work, inertia, omega * (1 + delta / 2), omega * (1 - delta / 2), inertia * (rpm / other) ** 2):
        assert _in(five(value), drawing) and _in(five(value), note), (five(value), drawing)


def _legend_numbers(out: Path, template: str) -> list[str]:
    """The numbers the motion plot's legend entry of ``template`` writes (its ``{…}`` fields), as written: in a text
    element, or, where matplotlib draws the glyphs as paths (a font it embeds), in the comment it writes over them."""
    root = ElementTree.parse(out / "motion.svg").getroot()
    texts = ["".join(text.itertext()) for text in root.iter(f"{SVG}text")]
    texts += re.findall(r"<!--(.*?)-->", (out / "motion.svg").read_text(encoding="utf-8"), re.DOTALL)
    pattern = re.compile(re.sub(r"\\\{\w+\\\}", lambda _: f"({NUMBER.pattern})", re.escape(template)))
    (found,) = [match.groups() for text in texts if (match := pattern.fullmatch(text.strip()))]
    return list(found)


def test_the_motion_plots_steady_speeds_and_delta_are_the_notes(run):
    """The plot's steady range read 10.52…10.83 rad/s and δ = 0.02902 to four digits, where the note writes
    ωmin = 10.518, ωmax = 10.827: the same run's numbers to the same digits, as the note's sentence gives them."""
    _, locale, out = run
    if not (out / "motion.svg").exists():
        pytest.skip("no motor: no motion plot")
    words = strings(locale)
    note = (out / "note.md").read_text(encoding="utf-8")
    low, high = _legend_numbers(out, words["motion_steady_band"])
    (delta,) = _legend_numbers(out, words["motion_integrated"])
    steady = next(line for line in note.splitlines() if _in(high, line) and _in(low, line))
    assert _in(delta, steady), (delta, steady)
    # Five digits for a speed, four for δ (the integration's), noughts kept.
    assert [len(re.sub(r"\D", "", value).lstrip("0")) for value in (low, high, delta)] == [5, 5, 4]
