"""A teacher marks the dynamics and balancing drawings: axes of one quantity at one scale numbered alike, no number
of an axis left out, the couple a one-plane balancing leaves said on its drawing, short shares named as a plan's.

Every value is read back from the SVG written by ``graphplan run`` and checked against the scene's own numbers or
against the other drawing of the same quantity; the couple Σ m·r·z is worked out here from the scene's masses.
"""

from __future__ import annotations

import cmath
import math
import re
from collections import Counter
from itertools import pairwise
from pathlib import Path
from xml.etree import ElementTree

import pytest
from shapely.geometry import LineString, box

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.render import dynamics
from graphplan.render.primitives import FONT_SIZE_PER_CAP
from graphplan.starters import starter

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
NUMBER = re.compile(r"−?\d+(?:[.,]\d+)?")
COMPRESSOR = ROOT / "tests" / "scenes" / "compressor_indicator_diagram.toml"


def _run(folder: Path, scene_text: str, pieces: str, locale: str | None = None) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    scene = folder / "scene.toml"
    scene.write_text(scene_text, encoding="utf-8")
    out = folder / "out"
    extra = ["--locale", locale] if locale else []
    assert main(["run", str(scene), "--out", str(out), "--only", pieces, "--sheet", "none", *extra]) == 0
    return out


def _groups(svg: Path) -> dict[str, ElementTree.Element]:
    return {g.get("id"): g for g in ElementTree.parse(svg).getroot().iter(f"{SVG}g") if g.get("id")}


def _words(text: ElementTree.Element) -> str:
    return "".join(text.itertext())


def _value(words: str) -> float:
    return float(words.replace("−", "-").replace(",", "."))


def _numbers(group: ElementTree.Element, anchor: str) -> list[tuple[float, float, float]]:
    """(value, x, y) of the texts of ``group`` that are a number alone, written with ``anchor``."""
    return [(_value(_words(t)), float(t.get("x")), float(t.get("y"))) for t in group.iter(f"{SVG}text")
            if NUMBER.fullmatch(_words(t)) and t.get("text-anchor") == anchor]


def _ordinate(group: ElementTree.Element) -> list[tuple[float, float]]:
    """(value, y on the paper) of a vertical axis's numbers: right-aligned against its ticks, all at one x."""
    numbers = _numbers(group, "end")
    x, _ = Counter(round(x, 3) for _, x, _ in numbers).most_common(1)[0]
    return sorted((value, y) for value, at, y in numbers if round(at, 3) == x)


def _abscissa(group: ElementTree.Element) -> list[tuple[float, float]]:
    """(value, x on the paper) of the φ numbers under a diagram: centred, all on its lowest line of numbers."""
    numbers = _numbers(group, "middle")
    lowest = max(y for _, _, y in numbers)
    return sorted((value, x) for value, x, y in numbers if abs(y - lowest) < 1e-6)


def _step(numbers: list[tuple[float, float]]) -> tuple[float, float]:
    """The one step of a row of numbers, in value and on the paper (mm); every gap the same."""
    values = [value for value, _ in numbers]
    places = [place for _, place in numbers]
    assert len(values) >= 3, numbers
    steps = {round(b - a, 9) for a, b in pairwise(values)}
    paper = {round(abs(b - a), 3) for a, b in pairwise(places)}
    assert len(steps) == 1 and len(paper) == 1, numbers
    return steps.pop(), paper.pop()


@pytest.fixture(scope="module", params=["shaper", "compressor"])
def dynamics_svg(request, tmp_path_factory) -> Path:
    text = starter("shaper") if request.param == "shaper" else COMPRESSOR.read_text(encoding="utf-8")
    return _run(tmp_path_factory.mktemp(request.param), text, "dynamics") / "dynamics.svg"


def test_delta_t_is_numbered_at_one_step_on_its_diagram_and_on_the_energy_mass_diagram(dynamics_svg):
    """ΔT(φ) and the energy–mass diagram beside it draw ΔT at one μT, aligned: the shaper's were numbered 0, −100,
    −200, −300 and 0, −200; the compressor's 0, −100, −200 and 0, −200."""
    groups = _groups(dynamics_svg)
    energy, energy_mass = _ordinate(groups["energy"]), _ordinate(groups["energy-mass"])
    scales = [re.search(r"μT = ([\d.]+) J/mm", " ".join(_words(t) for t in groups[name].iter(f"{SVG}text")))[1]
              for name in ("energy", "energy-mass")]
    assert scales[0] == scales[1]
    assert _step(energy) == _step(energy_mass), (energy, energy_mass)
    # Aligned: each value the two write stands at one height on both.
    heights = dict(energy)
    assert all(abs(y - heights[value]) < 1e-3 for value, y in energy_mass if value in heights)
    assert set(heights) <= {value for value, _ in energy_mass}


def test_the_phi_axes_and_the_je_axes_are_numbered_alike(dynamics_svg):
    """The three diagrams over the cycle number φ at one step and place, Je(φ) turned at the same step; the energy–mass
    diagram and Je(φ) under it number Je alike, at one μJ."""
    groups = _groups(dynamics_svg)
    across = [_abscissa(groups[name]) for name in ("moments", "works", "energy")]
    assert across[0] == across[1] == across[2]
    assert _step(_ordinate(groups["inertia"]))[0] == _step(across[0])[0]
    je = [_je_numbers(groups[name]) for name in ("energy-mass", "inertia")]
    assert [value for value, _ in je[0]] == [value for value, _ in je[1]]
    # An axis numbered at every other tick (the compressor's, whose numbers would stand closer than a letter) may
    # have one number alone, and no step to compare.
    if len(je[0]) >= 3:
        assert _step(je[0]) == _step(je[1]), je


def _je_numbers(group: ElementTree.Element) -> list[tuple[float, float]]:
    """(Je, x on the paper) of the Je axis's numbers: lettered at the axes' numbers' height (a size under the axis's
    name, and over the plan positions' numbers by the energy–mass diagram's curve), on either side of it."""
    texts = list(group.iter(f"{SVG}text"))
    name = next(t for t in texts if _words(t).startswith("Je,"))
    axis_y = float(name.get("y"))
    number_size = dynamics.NUMBER * FONT_SIZE_PER_CAP
    return sorted((_value(_words(t)), float(t.get("x"))) for t in texts
                  if NUMBER.fullmatch(_words(t)) and _value(_words(t)) > 0
                  and abs(float(t.get("font-size")) - number_size) < 0.002
                  and abs(float(t.get("y")) - axis_y) < 6 and float(t.get("x")) < float(name.get("x")))


def _paths(group: ElementTree.Element, colour: str | None = None) -> list[LineString]:
    lines = []
    for path in group.iter(f"{SVG}path"):
        if path.get("fill") not in (None, "none") or (colour and path.get("stroke") != colour):
            continue
        points = [tuple(float(v) for v in pair.split(",")) for pair in re.findall(r"-?[\d.]+,-?[\d.]+", path.get("d"))]
        if len(points) >= 2:
            lines.append(LineString(points))
    return lines


def _ink(text: ElementTree.Element):
    """A number's figures on the paper (y down), from its baseline up to its cap height."""
    size = float(text.get("font-size"))
    words = _words(text)
    width = sum(0.318 if c in ".," else 0.636 for c in words) * size
    x, y = float(text.get("x")), float(text.get("y"))
    left = {"start": x, "middle": x - width / 2, "end": x - width}[text.get("text-anchor")]
    return box(left, y - 0.72 * size, left + width, y)


def test_every_je_tick_of_the_energy_mass_diagram_has_its_number_clear_of_the_lines(tmp_path):
    """The compressor's upper tangent crosses the Je axis at 0.05's tick: 0.05 was left out, the axis reading 0.025,
    (a bare tick), 0.075.  Every tick has its number, and no line of the diagram runs through one (broken under it)."""
    groups = _groups(_run(tmp_path, COMPRESSOR.read_text(encoding="utf-8"), "dynamics") / "dynamics.svg")
    group = groups["energy-mass"]
    lines = _paths(group)
    axis = max((line for line in lines if len(line.coords) == 2 and abs(line.coords[0][1] - line.coords[1][1]) < 1e-9),
               key=lambda line: line.length)
    axis_x, axis_y = axis.coords[0]
    ticks = sorted(line.coords[0][0] for line in lines if len(line.coords) == 2
                   and abs(line.coords[0][0] - line.coords[1][0]) < 1e-9 and line.length < 3
                   and min(line.coords[0][1], line.coords[1][1]) < axis_y < max(line.coords[0][1], line.coords[1][1]))
    scale = float(re.search(r"μJ = ([\d.]+)", " ".join(_words(t) for t in group.iter(f"{SVG}text")))[1])
    # The axes' numbers are lettered at their own height (lettering.AXIS_NUMBER), a size under the axis's name.
    number_size = dynamics.NUMBER * FONT_SIZE_PER_CAP
    numbers = [t for t in group.iter(f"{SVG}text") if NUMBER.fullmatch(_words(t)) and _value(_words(t)) > 0
               and abs(float(t.get("font-size")) - number_size) < 0.002 and abs(float(t.get("y")) - axis_y) < 8]
    written = sorted(_value(_words(t)) for t in numbers)
    values = [round((x - axis_x) * scale, 9) for x in ticks]
    assert len(values) >= 2
    # Every tick numbered, or (numbers closer than a letter) every other one, at the multiples of the numbers' step
    # from the origin: none of those left out, and none between them.  (The compressor's, which every other tick
    # left one number, goes to a coarser step: two ticks, each numbered.)
    every = round(written[0] / values[0])
    assert written == pytest.approx([value for k, value in enumerate(values, 1) if k % every == 0]), (written, ticks)
    struck = [_words(t) for t in numbers for line in lines if line is not axis and _ink(t).intersects(line)
              and line.length > 3]
    assert not struck, struck


ROTOR_MASSES = re.compile(r"(?ms)^masses = \[.*?\} \]")
ONE_PLANE = 0.04


def _rotor_masses(scene_text: str) -> list[tuple[float, float, float, float]]:
    block = ROTOR_MASSES.search(scene_text)[0]
    keys = ("mass", "radius", "angle", "plane")
    return [tuple(float(re.search(key + r"\s*=\s*(-?[\d.]+)", entry)[1]) for key in keys)
            for entry in re.findall(r"\{[^}]*\}", block)]


def _captions(svg: Path) -> dict[str, list[str]]:
    return {name: [_words(t) for t in group.iter(f"{SVG}text")]
            for name, group in _groups(svg).items() if name.endswith("-caption")}


@pytest.mark.parametrize(("locale", "unit"), [("en", "kg·m²"), ("ru", "кг·м²"), ("zh", "kg·m²")])
def test_a_one_plane_balancing_says_the_couple_it_leaves_under_its_polygon(tmp_path, locale, unit):
    """The rotor's masses turn at z = 0, 0.08 and 0.16 m; one correction at z = 0.04 m closes the polygon of forces
    but leaves Σ m·r·z. The warning and the note said so; the drawing, a closed polygon, read as a rotor balanced."""
    text = re.sub(r"(?m)^planes = \[[^\]]*\]", f"planes = [{ONE_PLANE}]", starter("rotor"), count=1)
    masses = _rotor_masses(text)
    force = sum(m * r * cmath.exp(1j * math.radians(angle)) for m, r, angle, _ in masses)
    # The correction −Σ m·r at z = 0.04 m; with the forces balanced the couple is the same about any point.
    couple = abs(sum(m * r * cmath.exp(1j * math.radians(angle)) * z for m, r, angle, z in masses) - force * ONE_PLANE)
    captions = _captions(_run(tmp_path, text, "balancing", locale) / "rotor_balancing.svg")
    (caption,) = captions.values()
    told = re.search(r"Σ m·r·z = ([\d.,]+) " + re.escape(unit) + "$", caption[-1])
    assert told, caption
    assert _value(told[1]) == pytest.approx(couple, rel=1e-4)
    assert couple > 0.01


def test_two_planes_and_a_disc_say_no_couple(tmp_path):
    """Two planes balance the couple too, and a disc's correction turns in its masses' plane: no line of a couple."""
    two = starter("rotor")
    disc = re.sub(r"(?m)^planes = \[[^\]]*\].*$", "", re.sub(r"plane = [\d.]+", "plane = 0.1", two))
    for k, text in enumerate((two, disc)):
        for caption in _captions(_run(tmp_path / str(k), text, "balancing") / "rotor_balancing.svg").values():
            assert not any("Σ m·r·z" in line for line in caption), caption


FIVE_MASSES = [(18.0, 0.05, 0.0, 0.0), (14.0, 0.06, -60.0, 0.08), (2.0, 0.04, 135.0, 0.16), (9.0, 0.05, 200.0, 0.12),
               (1.0, 0.03, 90.0, 0.20)]


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_polygons_short_share_is_told_as_a_plans_short_vectors_are(tmp_path, locale):
    """m5 turns 0.02 m from plane R: its share in plane L, 0.00333 kg·m, is too short to draw. A plan's caption puts
    "not drawn, shorter than 0.25 mm:" on a line of its own and the values under it; the polygon's ran the words and
    the values on one line."""
    masses = ",\n".join(f"  {{ mass = {m}, radius = {r}, angle = {angle}, plane = {z} }}"
                        for m, r, angle, z in FIVE_MASSES)
    text = ROTOR_MASSES.sub(f"masses = [\n{masses} ]", starter("rotor"), count=1)
    caption = _captions(_run(tmp_path, text, "balancing", locale) / "rotor_balancing.svg")["plane-L-caption"]
    words = strings(locale)["plan_too_short"].format(least="0,25" if locale == "ru" else "0.25")
    assert words in caption, caption
    share = FIVE_MASSES[4][0] * FIVE_MASSES[4][1] * (0.22 - FIVE_MASSES[4][3]) / (0.22 - 0.04)
    told = caption[caption.index(words) + 1]
    found = re.fullmatch(r"\(m5r5\)L = ([\d.,]+) (kg·m|кг·м)", told)
    assert found, told
    assert _value(found[1]) == pytest.approx(share, rel=5e-3)


def test_the_polygons_and_the_plans_name_their_short_vectors_with_one_function(tmp_path):
    """The polygon's caption joined the words and the values on one line, which its width then broke after the colon
    (the line never fits): the same lines as a plan's, by a second function that could drift from the first. The
    polygon's short-share lines are now those the plans' function makes of its values, words and all."""
    from graphplan.render.force_rows import CAPTION_WIDTH_MM
    from graphplan.render.plans import too_short_lines

    masses = ",\n".join(f"  {{ mass = {m}, radius = {r}, angle = {angle}, plane = {z} }}"
                        for m, r, angle, z in (*FIVE_MASSES, (0.5, 0.03, 45.0, 0.21)))
    text = ROTOR_MASSES.sub(f"masses = [\n{masses} ]", starter("rotor"), count=1)
    caption = _captions(_run(tmp_path, text, "balancing") / "rotor_balancing.svg")["plane-L-caption"]
    start = next(k for k, line in enumerate(caption) if line.startswith("not drawn"))
    values = [value.strip() for line in caption[start + 1:] if line.startswith("(m")
              for value in line.split(";") if value.strip()]
    assert [value.split(" = ")[0] for value in values] == ["(m5r5)L", "(m6r6)L"]
    lines = too_short_lines(values, strings("en"), CAPTION_WIDTH_MM)
    assert caption[start:start + len(lines)] == lines
