"""A reader of the dynamics drawings tells a label from an axis's numbers and one number from the next: ωmax and
ωmin stand clear of the numbers (and of the axes' numbering bands), the numbers of one axis a letter's width apart,
no label over another or over a number; and the one-plane balancing's couple line stands on one line in Russian.

Every box is read back from the SVG written by ``graphplan run``: a text's box from its position, anchor and size,
as wide as DejaVu Sans sets it (the drawings' font, whose advances ``text_width`` holds).
"""

from __future__ import annotations

import itertools
import re
from pathlib import Path
from xml.etree import ElementTree

import pytest
from shapely.geometry import LineString, box

from graphplan.cli import main
from graphplan.locale import strings
from graphplan.render import dynamics
from graphplan.render.primitives import text_width
from graphplan.starters import starter

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"
COMPRESSOR = ROOT / "tests" / "scenes" / "compressor_indicator_diagram.toml"
TRIAD = ROOT / "tests" / "scenes" / "triad_slider_short_tangential.toml"
NUMBER = re.compile(r"−?\d+(?:[.,]\d+)?")
# The colours of the speeds' ticks and ordinates (and the tangents) and of the grid.
RED = "#b22222"
GRID = "#9a9a9a"
# The drawings' cap height of their axes' numbers (mm); SVG's font-size is the em, the cap height 0.72 of it.
CAP = dynamics.NUMBER
CAP_PER_EM = 0.72
# A letter's width at that height: the least gap between two numbers of an axis, and between a label and a number.
LETTER = text_width("0", CAP)


def _run(folder: Path, scene: Path, pieces: str, locale: str) -> Path:
    out = folder / f"out-{locale}"
    assert main(["run", str(scene), "--out", str(out), "--only", pieces, "--sheet", "none", "--locale", locale]) == 0
    return out


def _starter(folder: Path, kind: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    scene = folder / f"{kind}.toml"
    scene.write_text(starter(kind), encoding="utf-8")
    return scene


def _texts(svg: Path) -> list[tuple[str, str, float, object]]:
    """(group id, words, cap height, box) of every text of the drawing, y down as the SVG has it."""
    found = []
    for group in ElementTree.parse(svg).getroot().iter(f"{SVG}g"):
        name = group.get("id")
        if not name:
            continue
        for text in group.iter(f"{SVG}text"):
            words = "".join(text.itertext())
            cap = float(text.get("font-size")) * CAP_PER_EM
            x, y = float(text.get("x")), float(text.get("y"))
            width = text_width(words, cap, text.get("font-weight") or "normal")
            left = {"start": x, "middle": x - width / 2, "end": x - width}[text.get("text-anchor")]
            found.append((name, words, cap, box(left, y - cap, left + width, y)))
    return found


def _is_axis_number(words: str, cap: float) -> bool:
    # The plan positions' numbers on the energy–mass diagram are figures too, but set smaller: they are labels.
    return NUMBER.fullmatch(words) is not None and abs(cap - CAP) < 0.01


def _axes_numbers(texts) -> list[list[object]]:
    """The boxes of each axis's numbers, in order along it: a row (one baseline) or a column (one right edge)."""
    axes: dict[tuple, list] = {}
    for name, words, cap, shape in texts:
        if _is_axis_number(words, cap):
            _, _, x1, y1 = shape.bounds
            axes.setdefault((name, "row", round(y1, 2)), []).append(shape)
            axes.setdefault((name, "column", round(x1, 2)), []).append(shape)
    ordered = []
    for (_, way, _), shapes in axes.items():
        if len(shapes) > 1:
            ordered.append(sorted(shapes, key=lambda s: s.bounds[0] if way == "row" else s.bounds[1]))
    return ordered


def _gap(a, b) -> float:
    return a.distance(b)


DRAWINGS = [("flywheel", "en"), ("flywheel", "ru"), ("flywheel", "zh"), ("shaper", "en"), ("shaper", "ru"),
            ("shaper", "zh"), ("compressor", "en"), ("compressor", "ru"), ("compressor", "zh")]


@pytest.fixture(scope="module")
def drawings(tmp_path_factory) -> dict[tuple[str, str], Path]:
    folder = tmp_path_factory.mktemp("dynamics")
    scenes = {"flywheel": _starter(folder, "flywheel"), "shaper": _starter(folder, "shaper"), "compressor": COMPRESSOR}
    return {(kind, locale): _run(folder / kind, scenes[kind], "dynamics", locale) / "dynamics.svg"
            for kind, locale in DRAWINGS}


@pytest.mark.parametrize(("kind", "locale"), DRAWINGS)
def test_the_speed_extremes_stand_a_letter_clear_of_every_axis_number_and_out_of_the_numbering(drawings, kind, locale):
    texts = _texts(drawings[kind, locale])
    speeds = [shape for name, words, _, shape in texts if name == "energy" and words in ("ωmax", "ωmin")]
    assert len(speeds) == 2
    numbers = [shape for name, words, cap, shape in texts if name == "energy" and _is_axis_number(words, cap)]
    for speed in speeds:
        near = [n.bounds for n in numbers if _gap(speed, n) < LETTER]
        assert not near, f"{kind} {locale}: {speed.bounds} within a letter's width of the numbers at {near}"
    # Nor between two numbers of the ΔT axis's column, where it reads as one of them: the band left of the axis from
    # the lowest number to the highest, and the row of the φ numbers from the first to the last.
    for axis in _axes_numbers([t for t in texts if t[0] == "energy"]):
        band = box(*axis[0].union(axis[-1]).envelope.bounds)
        for speed in speeds:
            assert not speed.intersects(band), f"{kind} {locale}: {speed.bounds} in the numbering {band.bounds}"


def _lines(svg: Path, group_id: str) -> list[LineString]:
    """The drawn lines of a drawing's group but its red ones (a speed's own tick and ordinate, the tangents) and the
    grid lines those run along: the axes, their ticks, the rest of the grid and the curve."""
    group = next(g for g in ElementTree.parse(svg).getroot().iter(f"{SVG}g") if g.get("id") == group_id)
    paths = [(path.get("stroke"), LineString([tuple(map(float, pair)) for pair in
                                              re.findall(r"([-\d.]+),([-\d.]+)", path.get("d"))]))
             for path in group.iter(f"{SVG}path") if len(re.findall(r"[-\d.]+,[-\d.]+", path.get("d"))) > 1]
    red = {round(line.bounds[0], 2) for stroke, line in paths if stroke == RED and line.bounds[0] == line.bounds[2]}
    return [line for stroke, line in paths if stroke != RED
            and not (stroke == GRID and round(line.bounds[0], 2) in red and line.bounds[0] == line.bounds[2])]


@pytest.mark.parametrize(("kind", "locale"), DRAWINGS)
def test_the_speed_extremes_keep_off_the_axes_ticks_grid_and_curve(drawings, kind, locale):
    """Not written on a line: the shaper's ωmin stood 0.16 mm from the 210° tick, 0.15 mm from its grid line."""
    svg = drawings[kind, locale]
    lines = _lines(svg, "energy")
    for name, words, _, shape in _texts(svg):
        if name == "energy" and words in ("ωmax", "ωmin"):
            assert min(shape.distance(line) for line in lines) >= 0.3, f"{kind} {locale}: {words} on a line"


@pytest.mark.parametrize("kind", ["triad", "compressor", "shaper"])
def test_the_je_numbers_of_the_energy_mass_diagram_keep_off_the_ink_of_its_curve_and_tangents(tmp_path, kind):
    """A line is drawn as wide as its stroke: clear of the curve's middle by 0.24 mm, the triad's 0.02, centred under
    its tick, had the curve's half-millimetre stroke through the foot of its first figure.  Each Je number stands with
    paper between it and the ink of the curve and of the tangents (each path widened by half its stroke), a tangent
    broken under a number included."""
    scene = _starter(tmp_path, "shaper") if kind == "shaper" else {"triad": TRIAD, "compressor": COMPRESSOR}[kind]
    svg = _run(tmp_path, scene, "dynamics", "en") / "dynamics.svg"
    group = next(g for g in ElementTree.parse(svg).getroot().iter(f"{SVG}g") if g.get("id") == "energy-mass")
    paths = [(path.get("stroke"), float(path.get("stroke-width")),
              LineString([tuple(map(float, pair)) for pair in re.findall(r"([-\d.]+),([-\d.]+)", path.get("d"))]))
             for path in group.iter(f"{SVG}path") if path.get("fill") == "none"]
    axis = max((line for stroke, _, line in paths if stroke == "black" and len(line.coords) == 2
                and line.coords[0][1] == line.coords[1][1]), key=lambda line: line.length)
    (origin, axis_y), _ = axis.coords
    curve = max((line for stroke, _, line in paths if stroke == "black"), key=lambda line: len(line.coords))
    inks = [line.buffer(width / 2) for stroke, width, line in paths if stroke == RED or line is curve]
    # The Je axis's numbers: lettered as the axes' numbers, by the axis and right of the ΔT axis, whose own numbers
    # stand left of it.
    numbers = [(words, shape) for name, words, cap, shape in _texts(svg) if name == "energy-mass"
               and _is_axis_number(words, cap) and shape.bounds[0] > origin and abs(shape.centroid.y - axis_y) < 8]
    assert len(numbers) >= 2, numbers
    for words, shape in numbers:
        assert min(shape.distance(ink) for ink in inks) >= 0.2, f"{kind}: Je's {words} in a line's ink"


def test_the_flywheels_omega_min_at_nought_is_not_set_beside_the_energy_axiss_nought(drawings):
    """The starter's ωmin falls at φ = 0, where the ΔT axis's 0 and the φ axis's 0 meet: it hung left of the ΔT axis
    right beside its 0 and read as that axis's numbering."""
    texts = _texts(drawings["flywheel", "en"])
    omega_min = next(shape for name, words, _, shape in texts if name == "energy" and words == "ωmin")
    noughts = [shape for name, words, cap, shape in texts if name == "energy" and words == "0"
               and abs(cap - CAP) < 0.01]
    assert len(noughts) == 2
    assert min(omega_min.distance(nought) for nought in noughts) >= LETTER


@pytest.mark.parametrize(("kind", "locale"), DRAWINGS)
def test_the_numbers_of_one_axis_stand_a_letter_apart(drawings, kind, locale):
    for axis in _axes_numbers(_texts(drawings[kind, locale])):
        for a, b in itertools.pairwise(axis):
            assert _gap(a, b) >= LETTER - 1e-6, f"{kind} {locale}: numbers at {a.bounds} and {b.bounds}"


def test_the_compressors_je_numbers_stand_a_letter_apart_each_at_its_ticks_value(drawings):
    """At μJ = 0.002 kg·m²/mm a step of 0.025 is 12.5 mm.  Lettered at 2.8 mm, 0.05 beside 0.075 left under a letter
    between them, and the ticks went to the next step of 1-2-5 (0.05, 0.1); at the standard 2.5 mm of the axes'
    numbers they stand 3.5 mm apart, and every tick of 0.025 is numbered, each at its own tick (value / μJ from the
    Je axis's origin), on to 0.1, 4.5 mm past the largest Je (0.091), where the axis runs on 8 mm past the curve.
    (The coarser step where the numbers do crowd: test_dynamics_axis_numbering's sweep.)"""
    svg = drawings["compressor", "en"]
    groups = {g.get("id"): g for g in ElementTree.parse(svg).getroot().iter(f"{SVG}g") if g.get("id")}
    turned = groups["inertia"]
    # The Je(φ) turned: its numbers stand over the Je axis centred on their ticks; the origin is the φ axis's x.
    numbers = [("".join(t.itertext()), float(t.get("x"))) for t in turned.iter(f"{SVG}text")
               if NUMBER.fullmatch("".join(t.itertext())) and t.get("text-anchor") == "middle"]
    origin = float(next(t.get("x") for t in turned.iter(f"{SVG}text") if "".join(t.itertext()) == "0"
                        and t.get("text-anchor") == "end")) + 1.0 + 1.2
    scale = 0.002
    values = [float(words) for words, _ in numbers]
    assert values == [0.025, 0.05, 0.075, 0.1]
    for words, x in numbers:
        assert x - origin == pytest.approx(float(words) / scale, abs=0.01)
    ticks = [float(m.group(2)) - float(m.group(3)) for p in turned.iter(f"{SVG}path")
             if (m := re.fullmatch(r"M([\d.]+),([\d.]+) L\1,([\d.]+)", p.get("d")))]
    assert sum(abs(length - 2.4) < 0.01 for length in ticks) == 4   # 0.025 to 0.1 ticked, each numbered


@pytest.mark.parametrize(("kind", "locale"), DRAWINGS)
def test_no_label_covers_another_or_an_axis_number(drawings, kind, locale):
    texts = [t for t in _texts(drawings[kind, locale]) if t[0] != "title"]
    for (g1, w1, _, a), (g2, w2, _, b) in itertools.combinations(texts, 2):
        if g1 == g2:
            assert a.intersection(b).area < 1e-6, f"{kind} {locale}: {w1!r} over {w2!r}"


@pytest.mark.parametrize("locale", ["ru", "zh", "en"])
def test_a_one_plane_balancings_couple_stands_on_one_line(tmp_path, locale):
    """Under its polygon the couple a static balancing leaves, Σ m·r·z in kg·m², is one line of the caption: in
    Russian "Остаётся момент дисбалансов:" went on a line of its own and the formula on the next."""
    scene = _starter(tmp_path, "rotor")
    text = scene.read_text(encoding="utf-8")
    one_plane = re.sub(r"(?m)^planes = \[[^\]]*\]", "planes = [0.04]", text)
    assert one_plane != text
    scene.write_text(one_plane, encoding="utf-8")
    svg = _run(tmp_path, scene, "balancing", locale) / "rotor_balancing.svg"
    lines = ["".join(t.itertext()) for t in ElementTree.parse(svg).getroot().iter(f"{SVG}text")]
    words, unit = strings(locale)["bal_couple_left"].split("{value}")
    whole = re.compile(re.escape(words) + r"\d+[.,]\d+" + re.escape(unit))
    assert [line for line in lines if whole.fullmatch(line)], [line for line in lines if "m·r·z" in line]
