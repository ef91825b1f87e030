"""A teacher's close look at the dynamics drawings, read back off the SVG files a run writes.

- The load diagram's abscissa carries its unit as its ordinate does ("sB, m" beside "F, N"), in every language,
  in the words the note's table heads the same travel with.
- On the energy–mass diagram the letters a and b, where the tangents at ψmax and ψmin cut the ΔT axis, stand
  clear of the tangent they name: a steep tangent (a compressor at 600 rpm, ψ ≈ 38°) ran through its letter.
"""

from __future__ import annotations

import re
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from drawn_lines import whole_lines
from shapely.geometry import LineString, box

from graphplan.cli import main

ROOT = Path(__file__).resolve().parent.parent
COMPRESSOR = ROOT / "tests" / "scenes" / "compressor_indicator_diagram.toml"
SVG = "{http://www.w3.org/2000/svg}"
TANGENT_COLOUR = "#b22222"
# DejaVu Sans, in em of the font size: the advance of a and b, and b's ascender (over a's x-height).
LETTER_WIDTH_EM = 0.64
LETTER_HEIGHT_EM = 0.76


def _scene(locale: str, source: Path = COMPRESSOR) -> str:
    text = source.read_text(encoding="utf-8")
    return re.sub(r'(?m)^locale(\s*)=\s*"en"', f'locale\\1= "{locale}"', text, count=1)


def _run(tmp_path: Path, scene_text: str, pieces: str) -> Path:
    tmp_path.mkdir(parents=True, exist_ok=True)
    scene = tmp_path / "scene.toml"
    scene.write_text(scene_text, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out), "--only", pieces, "--sheet", "none"]) == 0
    return out


def _group(svg: Path, name: str) -> ElementTree.Element:
    root = ElementTree.parse(svg).getroot()
    found = next((group for group in root.iter(f"{SVG}g") if group.get("id") == name), None)
    assert found is not None, f"{svg.name} has no group {name}"
    return found


def _texts(group: ElementTree.Element) -> list[ElementTree.Element]:
    return list(group.iter(f"{SVG}text"))


@pytest.mark.parametrize(("locale", "metre"), [("en", "m"), ("ru", "м"), ("zh", "m")])
def test_the_load_diagrams_travel_axis_names_its_unit(tmp_path, locale, metre):
    out = _run(tmp_path, _scene(locale), "load_diagrams,note")
    labels = ["".join(text.itertext()) for text in _texts(_group(out / "load_diagrams.svg", "load-4-axes"))]
    # The ordinate as "F, N"; the abscissa, the piston's travel sB, likewise with its unit.
    assert any(re.fullmatch(r"F, [NН]", label) for label in labels), labels
    assert f"sB, {metre}" in labels, labels
    assert "sB" not in labels
    # The note's table heads the same travel in the same words.
    assert f"sB, {metre}" in (out / "note.md").read_text(encoding="utf-8")


def _tangents(group: ElementTree.Element) -> list[LineString]:
    lines = []
    for path in group.iter(f"{SVG}path"):
        if path.get("fill") == "none" and path.get("stroke") == TANGENT_COLOUR:
            points = [tuple(float(v) for v in point.split(","))
                      for point in re.findall(r"[ML]([-\d.]+,[-\d.]+)", path.get("d"))]
            if len(points) == 2:
                lines.append(LineString(points))
    # A tangent broken under a Je number it crosses is drawn in pieces on one line: taken whole again.
    return whole_lines(lines)


@pytest.mark.parametrize("locale", ["en", "zh"])
def test_a_steep_tangent_runs_clear_of_the_letters_a_and_b(tmp_path, locale):
    group = _group(_run(tmp_path, _scene(locale), "dynamics") / "dynamics.svg", "energy-mass")
    tangents = _tangents(group)
    assert len(tangents) == 2
    # Steep indeed: the compressor's tangents stand at more than 30° on the paper.
    for line in tangents:
        (x0, y0), (x1, y1) = line.coords
        assert abs(y1 - y0) > np.tan(np.radians(30.0)) * abs(x1 - x0)
    letters = [text for text in _texts(group) if "".join(text.itertext()) in ("a", "b")]
    assert sorted("".join(text.itertext()) for text in letters) == ["a", "b"]
    for text in letters:
        x, baseline, size = float(text.get("x")), float(text.get("y")), float(text.get("font-size"))
        assert text.get("text-anchor") == "start"
        glyph = box(x, baseline - LETTER_HEIGHT_EM * size, x + LETTER_WIDTH_EM * size, baseline)
        for line in tangents:
            assert not line.intersects(glyph), f"a tangent runs through the letter {''.join(text.itertext())}"
        # Still by its own point: the letter within a few mm of the tangent's end on the ΔT axis.
        ends = [min(line.coords, key=lambda point: point[0]) for line in tangents]
        assert min(np.hypot(end[0] - x, end[1] - baseline) for end in ends) < 8.0


def _kloss_starting_torque(power: float, overload: float, synchronous_rpm: float, rated_rpm: float) -> float:
    """Kloss' M = 2·Mmax/(s/sk + sk/s) at s = 1, on the motor's own shaft (N·m)."""
    rated_slip = 1.0 - rated_rpm / synchronous_rpm
    rated_torque = power / (rated_rpm * np.pi / 30.0)
    critical = rated_slip * (overload + np.sqrt(overload**2 - 1.0))
    return 2.0 * overload * rated_torque / (1.0 / critical + critical)


@pytest.mark.parametrize("locale", ["en", "ru", "zh"])
def test_a_machine_that_never_starts_shows_the_motors_torque_it_is_set_against(locale):
    """The press's motor cut to 300 W gives 20.4 N·m at rest on the crank against 35.1 N·m: the plot of why it does
    not start drew the motor's torque along a run of no length, a line at 0° seen nowhere that its legend named.
    Held at rest the motor gives its starting torque at any angle: drawn across the turn, at my Kloss value."""
    import tomllib

    from matplotlib import pyplot

    from graphplan.locale import strings
    from graphplan.machine_dynamics import MachineDynamics
    from graphplan.report.motion_plots import motion_plot
    from graphplan.scene import load
    from graphplan.starters import starter

    tables = tomllib.loads(starter("flywheel", locale))
    motor = {**tables["dynamics"]["motor"], "power": 300.0}
    tables["dynamics"]["motor"] = motor
    dynamics = MachineDynamics(load(tables))
    assert not dynamics.motion.turned
    text = strings(locale)
    mine = motor["gear_ratio"] * _kloss_starting_torque(motor["power"], motor["overload"], motor["synchronous_rpm"],
                                                        motor["rated_rpm"])
    figure = motion_plot(dynamics.motion, text, "press", resisting=dynamics.resisting,
                         stall_angle_deg=dynamics.rest_angle_deg())
    try:
        lower = figure.axes[-1]
        named = [line for line in lower.get_lines() if not line.get_label().startswith("_")]
        for line in named:
            if line.get_linestyle() in ("None", ""):
                continue   # a marker: the point where it stands
            along, values = (np.asarray(data, dtype=float) for data in line.get_data())
            assert np.ptp(along) > 0 or np.ptp(values) > 0, f"{line.get_label()!r} is drawn as no line at all"
        (motor_line,) = [line for line in named if line.get_label() == text["motion_motor_torque_at_rest"].format()]
        along, values = (np.asarray(data, dtype=float) for data in motor_line.get_data())
        assert along.min() == 0.0 and along.max() == 360.0
        assert values == pytest.approx(mine, rel=1e-6)
        assert mine < 35.0   # short of the punching press's idle resistance, 367.7 W at 100 rpm
    finally:
        pyplot.close(figure)


# DejaVu Sans, in em of the font size: its capitals' height, and how far ψ's tail and a g hang under the baseline.
CAP_EM = 0.73
DESCENT_EM = 0.24
AVERAGE_EM = 0.62


def _band(text: ElementTree.Element) -> tuple[float, float]:
    """A text's ink from the top of its capitals to the foot of its tails, in the SVG's mm (y down)."""
    baseline, size = float(text.get("y")), float(text.get("font-size"))
    return baseline - CAP_EM * size, baseline + DESCENT_EM * size


def _span(text: ElementTree.Element) -> tuple[float, float]:
    """A start-anchored text's reach across, generously."""
    x, size = float(text.get("x")), float(text.get("font-size"))
    return x, x + AVERAGE_EM * size * len("".join(text.itertext()))


def _meet(one: tuple[float, float], other: tuple[float, float]) -> bool:
    return one[0] < other[1] and other[0] < one[1]


@pytest.mark.parametrize(("source", "starter_kind"), [("fixtures/scotch_yoke.toml", None), (None, "triad")])
def test_a_tangents_psi_written_near_the_je_axis_stands_off_the_axis_and_its_name(tmp_path, source, starter_kind):
    """The scotch yoke's ψmax = 1.88° ends 1 mm over the Je axis and the triad's ψmin = 13.50° ends on it: each
    was written level with its tangent's end, struck through by the axis line running on to its arrowhead and into
    the axis's name "Je, kg·m²"."""
    from graphplan.starters import starter

    text = (ROOT / source).read_text(encoding="utf-8") if source else starter(starter_kind)
    group = _group(_run(tmp_path, text + "\n[dynamics]\ndelta = 0.04\n", "dynamics") / "dynamics.svg", "energy-mass")
    texts = _texts(group)
    (name,) = [text for text in texts if "".join(text.itertext()).startswith("Je,")]
    axes = []
    for path in group.iter(f"{SVG}path"):
        points = re.findall(r"[ML]([-\d.]+),([-\d.]+)", path.get("d"))
        if path.get("fill") == "none" and path.get("stroke") == "black" and len(points) == 2:
            (x0, y0), (x1, y1) = ((float(x), float(y)) for x, y in points)
            if y0 == y1 and x1 - x0 > 20.0:
                axes.append((x0, x1, y0))
    ((axis_start, axis_end, axis_y),) = axes
    psis = [text for text in texts if "".join(text.itertext()).startswith("ψm")]
    assert len(psis) == 2
    near = []
    for psi in psis:
        top, foot = _band(psi)
        across = _span(psi)
        assert not (_meet(across, (axis_start, axis_end)) and top < axis_y < foot), \
            f"the Je axis runs through {''.join(psi.itertext())}"
        assert not (_meet(across, _span(name)) and _meet((top, foot), _band(name))), \
            f"{''.join(psi.itertext())} runs into the axis's name"
        near.append(min(abs(top - axis_y), abs(foot - axis_y)))
    # The scene is one whose tangent ends by the axis: its ψ stands within a line of it.
    assert min(near) < 4.0


FIVE_MASSES = [(18.0, 0.05, 0.0, 0.0), (14.0, 0.06, -60.0, 0.08), (2.0, 0.04, 135.0, 0.16), (9.0, 0.05, 200.0, 0.12),
               (1.0, 0.03, 90.0, 0.20)]


@pytest.mark.parametrize(("locale", "unit"), [("en", "kg·m"), ("ru", "кг·м"), ("zh", "kg·m")])
def test_every_share_in_a_planes_equation_is_drawn_named_or_told_with_its_value(tmp_path, locale, unit):
    """m5 turns at z = 0.20 m, 0.02 m from plane R: its share in plane L, m5·r5·(zR − z5)/(zR − zL) = 0.00333 kg·m,
    is 0.17 mm at that polygon's μ, under the 0.25 mm a polygon draws. It stood in plane L's equation and nowhere in
    its polygon; it is told under it as a plan's short vectors are, with my value."""
    from graphplan.starters import starter

    masses = ",\n".join(f"  {{ mass = {m}, radius = {r}, angle = {angle}, plane = {z} }}"
                        for m, r, angle, z in FIVE_MASSES)
    scene = re.sub(r"(?ms)^masses = \[.*?\} \]", f"masses = [\n{masses} ]", starter("rotor"), count=1)
    scene = re.sub(r'(?m)^locale(\s*)=\s*"en"', f'locale\\1= "{locale}"', scene, count=1)
    out = _run(tmp_path, scene, "balancing")
    left, right = 0.04, 0.22
    svg = out / "rotor_balancing.svg"
    for plane in ("L", "R"):
        named = {"".join(text.itertext()) for text in _texts(_group(svg, f"plane-{plane}-labels"))}
        caption = " ".join("".join(text.itertext()) for text in _texts(_group(svg, f"plane-{plane}-caption")))
        scale = float(re.search(r"μ = ([\d.,]+)", caption).group(1).replace(",", "."))
        for k, (m, r, _, z) in enumerate(FIVE_MASSES, start=1):
            share = m * r * ((right - z) if plane == "L" else (z - left)) / (right - left)
            name = f"(m{k}r{k}){plane}"
            assert name in caption   # the equation's
            if abs(share) / scale >= 0.25:
                assert name in named
            else:
                assert name not in named
                told = re.search(re.escape(name) + r" = ([\d.,]+) " + unit, caption)
                assert told, f"{name} ({abs(share) / scale:.2f} mm) is neither drawn nor told: {caption}"
                assert float(told.group(1).replace(",", ".")) == pytest.approx(abs(share), rel=5e-3)
    # Plane L has one such share: the fifth mass's.
    assert abs(FIVE_MASSES[4][0] * FIVE_MASSES[4][1] * (right - FIVE_MASSES[4][3]) / (right - left)) < 0.004


def _leaders(root: ElementTree.Element) -> list[LineString]:
    """The dotted leaders from the plan positions' rings up to their written values."""
    found = []
    for path in root.iter(f"{SVG}path"):
        if path.get("fill") == "none" and path.get("stroke-dasharray"):
            points = [tuple(float(v) for v in point.split(","))
                      for point in re.findall(r"[ML]([-\d.]+,[-\d.]+)", path.get("d"))]
            if len(points) == 2 and points[0][0] == points[1][0]:
                found.append(LineString(points))
    return found


@pytest.mark.parametrize(("kind", "struck"), [("slotted-lever", "M4 = 120 N·m (4)"), ("crank-rocker", "M, N·m")])
def test_a_load_diagrams_leaders_run_clear_of_its_words(tmp_path, kind, struck):
    """The slotted lever's plan positions 4 and 11 stand 3 mm apart on the travel: M4 = 0 N·m, written a line
    higher, ran its dotted leader down through M4 = 120 N·m; the crank-rocker's position 11 by the ordinate ran
    its leader through the axis's name "M, N·m". Each leader is broken under the words, as a draftsman breaks it."""
    from graphplan.starters import starter

    root = ElementTree.parse(_run(tmp_path, starter(kind), "load_diagrams") / "load_diagrams.svg").getroot()
    leaders = _leaders(root)
    assert leaders
    texts = [text for text in _texts(root) if text.get("x") is not None]
    assert struck in ["".join(text.itertext()) for text in texts]
    for text in texts:
        words = "".join(text.itertext())
        x, baseline, size = float(text.get("x")), float(text.get("y")), float(text.get("font-size"))
        width = 0.55 * size * len(words)
        left = {"start": x, "middle": x - width / 2, "end": x - width}[text.get("text-anchor", "start")]
        glyphs = box(left, baseline - CAP_EM * size, left + width, baseline)
        for leader in leaders:
            assert not leader.intersects(glyphs), f"a leader runs through {words!r}"
    # Still leaders: each plan position's ring has one reaching up toward its words.
    assert len({round(line.coords[0][0], 3) for line in leaders}) == 2


def test_the_russian_moments_legend_names_them_as_the_works_legend_and_the_note_do(tmp_path):
    """The moments' legend read «движущих сил» and «сил сопротивления», genitives that only went on the heading
    («Приведённые моменты движущих сил и сил сопротивления»); beside it the works' legend reads Aд and Aс, and the
    note names the moments Mд and Mс."""
    out = _run(tmp_path, _scene("ru"), "dynamics,note")
    legends = {name: {"".join(text.itertext()) for text in _texts(_group(out / "dynamics.svg", name))}
               for name in ("moments", "works")}
    assert {"Aд", "Aс"} <= legends["works"]
    assert {"Mд", "Mс"} <= legends["moments"], legends["moments"]
    assert not {"движущих сил", "сил сопротивления"} & legends["moments"]
    note = (out / "note.md").read_text(encoding="utf-8")
    assert "Mд" in note and "Mс" in note
