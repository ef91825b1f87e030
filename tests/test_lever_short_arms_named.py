"""Zhukovsky's lever says why it lists an arm under its drawing: the arm is too short to draw.

The lever is the velocity plan turned by 90°, and its sheet leaves out an arm shorter than 0.25 mm, as the plans
leave out a vector, listing it under the drawing as "h5 = 0.2205 mm".  The plans, the force polygons and the note
say "not drawn, shorter than 0.25 mm" of theirs; the lever said nothing, and a reader of the sheet did not know why an
arm stood there.  A slider-crank a tenth of a degree from its dead centre has its piston's image b 0.22 mm from the
pole: the arms of F4 and Fu4 at b are that short.

Each arm is worked out here from the velocity plan: its point's image turned clockwise, the perpendicular from the
pole to the force's line through it, at the μV the lever's caption on the sheet says it is drawn at.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest
from lever_equation import unfactored
from sheet_texts import box, texts

import graphplan
from graphplan.analysis import analyse
from graphplan.locale import load_symbol, strings
from graphplan.render.primitives import text_width
from graphplan.run import run
from graphplan.starters import starter

# The drawings leave out a segment shorter than this (mm); one this short is a point on the pole: nought.
SHORTEST_DRAWN_MM = 0.25
NOUGHT_MM = 1e-9
LOCALES = ("en", "ru", "zh")


def near_dead_centre(locale: str) -> dict:
    """The slider-crank starter with plans and force sheets at φ = 0.1° (the slider a hair from its dead centre)
    and 90.1°."""
    tables = tomllib.loads(starter("slider-crank", locale))
    tables["positions"].update(count=4, start=0.1, number_from=0, plans=[0, 1])
    return tables


@pytest.fixture(scope="module", params=LOCALES)
def drawn(request, tmp_path_factory):
    locale = request.param
    scene = graphplan.load(near_dead_centre(locale))
    folder = tmp_path_factory.mktemp(locale) / "out"
    run(scene, folder, only=["sheets"])
    return locale, folder, analyse(scene)


def lever_sheet(folder: Path, number: int) -> tuple[Path, str]:
    """The sheet that holds the lever of position ``number`` and its caption group's source."""
    for path in sorted(folder.glob("sheet_*.svg")):
        source = path.read_text(encoding="utf-8")
        # On a part of its own where the force sheet stands with its rows apart: ``forces-1-3-lever-caption``.
        if match := re.search(rf'<g id="forces-{number}(?:-\d+)?-lever-caption">(.*?)</g>', source, re.DOTALL):
            return path, match.group(1)
    raise AssertionError(f"no lever of position {number} on the sheets")


def number(value: str, locale: str) -> float:
    return float(value.replace(strings(locale)["decimal_mark"], "."))


def arms_mm(analysis, number_: int, caption: list[str], locale: str) -> dict[str, float]:
    """Each arm the lever's equation names (h1, h2, …), by its force, worked out from the velocity plan."""
    position = next(position for position in analysis.plans if position.number == number_)
    velocity, lever = position.velocity, position.lever
    joined = " ".join(caption)
    drawn_at = number(re.search(r"μV = ([\d.,]+)", joined).group(1), locale)
    equation = re.search(r"ΣMp:(.*?)= 0(?![\d.,])", joined).group(1)
    named = {name: arm for name, arm in re.findall(r"([^\s−+]+)·(h\d+)\b", unfactored(equation))}
    arms = {}
    for term in lever.terms:
        name = load_symbol(term.name, strings(locale))  # as the caption writes it: the Russian Fи4 of Fu4
        if name not in named:
            continue
        place = -1j * (velocity.points[term.image] + term.shift)  # turned clockwise about the pole
        direction = term.force / abs(term.force)
        arms[named[name]] = abs((place * direction.conjugate()).imag) / drawn_at
    return arms


def test_a_short_arm_on_the_sheet_says_it_is_not_drawn_with_its_value(drawn):
    locale, folder, analysis = drawn
    text = strings(locale)
    words = text["arms_too_short"].format(least=f"{SHORTEST_DRAWN_MM:g}".replace(".", text["decimal_mark"]))
    _, group = lever_sheet(folder, 0)
    caption = [item[4] for item in texts(group)]
    arms = arms_mm(analysis, 0, caption, locale)
    short = {arm for arm, millimetres in arms.items() if NOUGHT_MM < millimetres < SHORTEST_DRAWN_MM}
    # The scene's case: F4 and Fu4 at b, 0.22 mm from the pole, among others; and arms the lever draws.
    assert len(short) >= 2 and len(arms) > len(short), arms
    said = next((k for k, line in enumerate(caption) if words in line), None)
    assert said is not None, caption
    balancing = next(k for k, line in enumerate(caption) if line.startswith(f"{load_symbol('Mb', text)} ="))
    assert said < balancing, caption
    # The arms given after the words, before the balancing loads: each short one, at its length.
    listed = dict(re.findall(r"(?<!\w)(h\d+) = ([\d.,]+) " + re.escape(text["millimetre"]),
                             " ".join(caption[said:balancing]).replace(words, "")))
    assert set(listed) == short, (listed, short)
    for arm in short:
        assert number(listed[arm], locale) == pytest.approx(arms[arm], rel=1e-3), (arm, listed[arm])
    # An arm the lever draws is listed nowhere under it, at the dead centre or at 90.1°.
    for number_ in (0, 1):
        caption = [item[4] for item in texts(lever_sheet(folder, number_)[1])]
        arms = arms_mm(analysis, number_, caption, locale)
        given = set(re.findall(r"(?<!\w)(h\d+) = ", " ".join(caption)))
        assert arms and not {arm for arm, millimetres in arms.items() if millimetres >= SHORTEST_DRAWN_MM} & given, (
            arms, given)


def test_the_lever_s_words_for_its_short_arms_stand_within_the_frame_over_no_other_text(drawn):
    locale, folder, _ = drawn
    text = strings(locale)
    words = text["arms_too_short"].format(least=f"{SHORTEST_DRAWN_MM:g}".replace(".", text["decimal_mark"]))
    path, group = lever_sheet(folder, 0)
    source = path.read_text(encoding="utf-8")
    frame = re.search(r'<g id="sheet-frame"><path[^>]*/><path d="M([\d.]+),([\d.]+) L([\d.]+),[\d.]+ '
                      r'L[\d.]+,([\d.]+)', source)
    assert frame is not None, path.name
    left, bottom, right, top = (float(value) for value in frame.groups())
    found = texts(source)
    assert any(words in item[4] for item in texts(group)), [item[4] for item in texts(group)]
    for item in texts(group):
        x0, y0, x1, y1 = box(*item)
        assert left <= x0 and x1 <= right and top <= y0 and y1 <= bottom, (path.name, item[4])
        for other in found:
            if other == item:
                continue
            u0, v0, u1, v1 = box(*other)
            assert u1 <= x0 or x1 <= u0 or v1 <= y0 or y1 <= v0, (path.name, item[4], other[4])


def test_the_short_arms_run_on_before_the_lines_under_them_in_no_more_lines_than_apart():
    """The lever's short arms stand between its equation and its balancing loads: they go on as a polygon's short
    vectors do, the balancing loads kept under them in order; where neither the equation's line nor one line holds
    them, the values fill the lines under the words rather than three a line with the third broken off."""
    from graphplan.render.force_rows import RunOn, caption_lines
    from graphplan.render.plans import too_short_lines

    text = strings("en")
    values = ["h2 = 0.1060 mm", "h3 = 0.0001013 mm", "h5 = 0.2205 mm", "h6 = 0.2205 mm"]
    apart = too_short_lines(values, text, 160.0)
    words = apart[0]
    under = ["Mb = 0.1060 N·m (Zhukovsky's lever)", "Mb = 0.1060 N·m (force polygons)"]
    caption = ["Zhukovsky's lever", "ΣMp: −Fu4·h5 + F4·h6 + Fb·hb = 0", *apart, *under]
    run_on = RunOn(len(apart), f"{words} {'; '.join(values)}", "; ", len(under), tuple(values))
    width = max(text_width(line, 5.0) for line in ("h2 = 0.1060 mm; h3 = 0.0001013 mm;", *under)) + 1.0
    lines = [line for line, _ in caption_lines(caption, width, 5.0, run_on)]
    plain = [line for line, _ in caption_lines(caption, width, 5.0)]
    assert lines[-2:] == under and plain[-2:] == under
    assert words in lines and len(lines) < len(plain), (lines, plain)
    assert " ".join(lines[lines.index(words) + 1:-2]) == "; ".join(values)
    for line in lines:
        assert text_width(line, 5.0) <= width, line
    # Where the equation's line has the room, they go on at its end and take no line of their own.
    wide = [line for line, _ in caption_lines(caption, 1000.0, 5.0, run_on)]
    assert wide == ["Zhukovsky's lever", f"ΣMp: −Fu4·h5 + F4·h6 + Fb·hb = 0; {words} {'; '.join(values)}", *under]


def test_a_group_cut_free_says_which_of_its_arms_are_too_short_to_draw(drawn):
    """Group II(3,4) at 0.1°: the inertia force Fu3, along −aS3 through S3, passes 0.11 mm from B on the drawing;
    its arm is listed under the words the lever uses, at the length worked out from the motion."""
    locale, folder, analysis = drawn
    text = strings(locale)
    words = text["arms_too_short"].format(least=f"{SHORTEST_DRAWN_MM:g}".replace(".", text["decimal_mark"]))
    source = lever_sheet(folder, 0)[0].read_text(encoding="utf-8")
    group = re.search(r'<g id="forces-0-body-II-3-4-caption">(.*?)</g>', source, re.DOTALL).group(1)
    caption = " ".join(item[4] for item in texts(group))
    drawn_at = number(re.search(r"μl = ([\d.,]+)", caption).group(1), locale)
    arm = re.search(re.escape(load_symbol("Fu3", text)) + r"·(h\d+)", caption).group(1)
    motion, index = analysis.motion, analysis.plans[0].index
    point = {name: complex(*motion.point(name).r[index]) for name in ("S3", "B")}
    along = complex(*motion.point("S3").a[index])
    expected = abs(((point["S3"] - point["B"]) * (along / abs(along)).conjugate()).imag) / drawn_at
    assert NOUGHT_MM < expected < SHORTEST_DRAWN_MM
    said = re.search(re.escape(words) + rf" {arm} = ([\d.,]+) " + re.escape(text["millimetre"]), caption)
    assert said is not None, caption
    assert number(said.group(1), locale) == pytest.approx(expected, rel=1e-3)
