"""The dynamics drawing read on its own: a constant reduced moment's line carries its value and stands clear of the
field's edge; each part of the drawing cut for the note is captioned with the diagrams it shows.

The axis of the moments is numbered at a round step (0 and 500 for the engine, 0, −1000, −2000 for the press), so a
level line between the ticks had no value to read it by, and the engine's Mr ran along the ends of the grid as the
plot's frame.  The value is worked out here by hand: an engine's Mr is the work of its torque diagram over the turn
over 2π, the press's Md the work of its punching force over 2π; its words are read back from the SVG ``graphplan run``
writes, and their box (from position, anchor and size, as wide as DejaVu Sans sets them) is checked against the
curves, the axes and the other words of the diagram.
"""

from __future__ import annotations

import itertools
import math
import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
from scene_texts import crank_press
from shapely.geometry import LineString, box

from graphplan.cli import main
from graphplan.render import dynamics
from graphplan.render.primitives import text_width

SVG = "{http://www.w3.org/2000/svg}"
CAP_PER_EM = 0.72
# The constant line's words stand this near it (mm): farther, they read as a note of the diagram, not its value.
NEAR_MM = 6.0

# A torque diagram over the turn (degrees, N·m); the resisting moment taken constant.
ENGINE_TORQUE = [(0, 0), (40, 900), (180, 0), (180, -150), (270, 0), (360, 0)]
# A short firing stroke: its Mr, 1.4 mm under the abscissa, leaves no room between them for its value.
SPIKE_TORQUE = [(0, 0), (10, 2000), (20, 0), (360, 0)]


def _engine(torque) -> str:
    return f"""
[scene]
title = "Single-cylinder engine flywheel"

[dynamics]
rpm = 300
delta = 0.02
driving_torque = {[list(point) for point in torque]}
resisting = "constant"
inertia = 0.3
"""


ENGINE, SPIKE = _engine(ENGINE_TORQUE), _engine(SPIKE_TORQUE)

# A crank press: crank 0.1 m, rod 0.4 m, the slider's guide through the crank's pivot (stroke 2·0.1 m), punching
# 20 kN over the last 30 % of its working stroke; the driving moment taken constant.
PRESS_FORCE, PRESS_SHARE, PRESS_STROKE = 20000.0, 0.3, 0.2
PRESS = crank_press("delta = 0.1\ncount = 720\n", PRESS_FORCE, PRESS_SHARE)


def _engine_mr(torque=ENGINE_TORQUE) -> float:
    """Mr = Ad/2π: the torque diagram's area by trapezoids (straight between its vertices), in N·m·rad, over 2π."""
    work = sum((m0 + m1) / 2 * math.radians(p1 - p0)
               for (p0, m0), (p1, m1) in itertools.pairwise(torque))
    return work / (2 * math.pi)


def _press_md() -> float:
    """Md = Ar/2π: the punching force times the share of the stroke it acts over; the slider's weight does no work
    along a level guide."""
    return PRESS_FORCE * PRESS_SHARE * PRESS_STROKE / (2 * math.pi)


def _moments(folder: Path, scene: str, locale: str) -> ElementTree.Element:
    path = folder / "scene.toml"
    path.write_text(scene, encoding="utf-8")
    out = folder / f"out-{locale}"
    assert main(["run", str(path), "--out", str(out), "--only", "dynamics", "--sheet", "none",
                 "--locale", locale]) == 0
    root = ElementTree.parse(out / "dynamics.svg").getroot()
    return next(group for group in root.iter(f"{SVG}g") if group.get("id") == "moments")


def _text_box(text: ElementTree.Element):
    words = "".join(text.itertext())
    cap = float(text.get("font-size")) * CAP_PER_EM
    x, y = float(text.get("x")), float(text.get("y"))
    width = text_width(words, cap, text.get("font-weight") or "normal")
    left = {"start": x, "middle": x - width / 2, "end": x - width}[text.get("text-anchor")]
    return words, box(left, y - cap, left + width, y)


def _paths(group: ElementTree.Element) -> list[tuple[ElementTree.Element, list[tuple[float, float]]]]:
    found = []
    for path in group.iter(f"{SVG}path"):
        points = [tuple(map(float, pair.split(","))) for pair in re.findall(r"-?[\d.]+,-?[\d.]+", path.get("d"))]
        found.append((path, points))
    return found


@pytest.mark.parametrize(("scene", "locale", "symbol", "unit", "value"), [
    (ENGINE, "en", "Mr", "N·m", _engine_mr()),
    (ENGINE, "ru", "Mс", "Н·м", _engine_mr()),
    (ENGINE, "zh", "Mr", "N·m", _engine_mr()),
    (SPIKE, "en", "Mr", "N·m", _engine_mr(SPIKE_TORQUE)),
    (PRESS, "en", "Md", "N·m", _press_md()),
    (PRESS, "ru", "Mд", "Н·м", _press_md()),
])
def test_a_constant_moment_is_written_beside_its_line_clear_of_everything(tmp_path, scene, locale, symbol, unit,
                                                                          value):
    group = _moments(tmp_path, scene, locale)
    texts = [_text_box(text) for text in group.iter(f"{SVG}text")]
    written = [(words, shape) for words, shape in texts if words.startswith(f"{symbol} = ")]
    assert len(written) == 1, [words for words, _ in texts]
    words, label = written[0]
    match = re.fullmatch(rf"{symbol} = (\d+)([.,])(\d+) {unit}", words)
    assert match, words
    # The note's five digits, in the locale's decimal mark.
    assert match[2] == ("," if locale == "ru" else ".")
    assert float(f"{match[1]}.{match[3]}") == pytest.approx(value, abs=0.006)
    assert len(match[1] + match[3]) == 5

    paths = _paths(group)
    curves = [points for path, points in paths if path.get("stroke-width") == "0.5"]
    # The legend's strokes are level too, but a few millimetres long.
    level = [points for points in curves if len({round(y, 3) for _, y in points}) == 1
             and points[-1][0] - points[0][0] > 50.0]
    assert len(level) == 1, "one level line over the cycle: the constant moment's"
    line_y = level[0][0][1]
    assert label.distance(LineString(level[0])) < NEAR_MM
    # Clear of every curve, of the axes and their ticks, and of every other word and number of the diagram.
    for points in curves:
        assert not label.intersects(LineString(points)), words
    thin = [points for path, points in paths
            if path.get("stroke-width") == "0.25" and path.get("stroke") == "black" and len(points) >= 2]
    for points in thin:
        assert not label.intersects(LineString(points)), (words, points)
    for other, shape in texts:
        if other != words:
            assert not label.intersects(shape), (words, other)

    # The line stands at its value on the axis: the abscissa is the longest level thin line.
    abscissa_y = max(thin, key=lambda points: abs(points[-1][0] - points[0][0]))[0][1]
    scale = float(re.search(r"μM = ([\d.,]+)", " ".join(words for words, _ in texts))[1].replace(",", "."))
    sign = -1.0 if symbol.startswith("M") and symbol[1:] in ("r", "с") else 1.0
    assert abscissa_y - line_y == pytest.approx(sign * value / scale, abs=0.01)
    # Its words on its side of the abscissa: led across it, they named the curve running along the axis.
    assert (label.centroid.y - abscissa_y) * (line_y - abscissa_y) > 0
    # And inside the field, not on its edge: the grid and the ordinate run on past it.
    grid = [points for path, points in paths if path.get("stroke") == "#9a9a9a"]
    ordinate = [points for points in thin if len(points) == 2 and abs(points[0][0] - points[1][0]) < 1e-9
                and abs(points[0][1] - points[1][1]) > 5.0]
    ends = [y for points in grid + ordinate for _, y in points]
    if sign < 0:
        assert max(ends) > line_y + 2.0
    else:
        assert min(ends) < line_y - 2.0


def test_a_moment_that_varies_is_given_no_value(tmp_path):
    """The press's resisting moment, its punching stroke alone, is a curve the axis reads: no "Mr =" beside it."""
    group = _moments(tmp_path, PRESS, "en")
    words = ["".join(text.itertext()) for text in group.iter(f"{SVG}text")]
    assert not any(word.startswith("Mr =") for word in words)


# The cap height of each diagram's heading (mm).
HEADING_CAP = dynamics.HEADING
PART_CAPTION = {
    "en": re.compile(r"Figure (\d+)\. (.+) \(part (\d) of (\d)\): (.+)"),
    "ru": re.compile(r"Рисунок (\d+) — (.+) \(часть (\d) из (\d)\): (.+)"),
}


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_each_part_of_the_dynamics_in_the_note_names_the_diagrams_it_shows(tmp_path, locale):
    """The press's dynamics, too big for a page, goes into the note in parts: each part's caption names the
    diagrams drawn in that part's SVG (their headings, read back from it), and no two parts' captions are alike."""
    path = tmp_path / "scene.toml"
    path.write_text(PRESS, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--only", "dynamics,note", "--sheet", "none",
                 "--locale", locale]) == 0
    parts = sorted(out.glob("dynamics-*.svg"))
    assert len(parts) >= 2
    captions = [match for line in (out / "note.md").read_text(encoding="utf-8").splitlines()
                if (match := PART_CAPTION[locale].fullmatch(line))]
    assert [int(match[3]) for match in captions] == list(range(1, len(parts) + 1))
    assert {int(match[4]) for match in captions} == {len(parts)}
    assert len({match[1] for match in captions}) == 1, "one figure"
    assert len({match[5] for match in captions}) == len(parts)
    for part, caption in zip(parts, captions):
        headings = [text for text in ElementTree.parse(part).getroot().iter(f"{SVG}text")
                    if text.get("font-weight") == "bold"
                    and abs(float(text.get("font-size")) * CAP_PER_EM - HEADING_CAP) < 0.01]
        assert headings, part.name
        named = caption[5].split("; ")
        assert len(named) == len(headings)
        for name, heading in zip(named, headings):
            words = "".join(heading.itertext())
            # Set in the running text's small letters ("works of ...", "маховик"), the rest as the drawing writes it.
            assert name == words[0].lower() + words[1:], (name, words)
