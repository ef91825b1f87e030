"""A teacher's review of the report plots matplotlib draws (the balancing load, the machine's motion, the vibration,
the accuracy study), made as a user makes them: `graphplan new` and `graphplan run` in English, Russian and Chinese.

Each plot is read back from the SVG the run writes (its ticks' places and labels give the scale, the markers' and
curves' places the values) and set against the numbers of results.json the same run writes; every glyph is asked
for in every locale; the same run writes the same bytes twice."""

from __future__ import annotations

import functools
import json
import logging
import re
import warnings
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest

import graphplan
from graphplan.analysis import analyse
from graphplan.cli import main
from graphplan.locale import strings

pytest.importorskip("matplotlib")

LOCALES = ("en", "ru", "zh")
FIXTURES = sorted(Path("fixtures").glob("*.toml"))
# Each starter with the plots it draws (the pieces asked of `graphplan run --only`).
STARTERS = {"shaper": "figures,dynamics,accuracy", "flywheel": "dynamics", "rotor": "vibration",
            "crank-rocker": "figures", "slider-crank": "figures", "slotted-lever": "figures", "triad": "figures"}
MISSING = "missing from font"


class _Glyphs(logging.Handler):
    """matplotlib's word of a glyph it drew as a box, whether it warns (font fallback) or logs (mathtext)."""

    def __init__(self):
        super().__init__(logging.WARNING)
        self.missing: list[str] = []

    def emit(self, record):
        if MISSING in record.getMessage():
            self.missing.append(record.getMessage())


def _run_caught(arguments: list[str]) -> list[str]:
    """``graphplan`` run with ``arguments``; the glyphs matplotlib said it had no font for."""
    handler = _Glyphs()
    root = logging.getLogger()
    root.addHandler(handler)
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            assert main(arguments) == 0
    finally:
        root.removeHandler(handler)
    return handler.missing + [str(item.message) for item in caught if MISSING in str(item.message)]


@pytest.fixture(scope="module")
def starters(tmp_path_factory):
    """Every starter run in every locale: {(kind, locale): (its folder, the glyphs found missing)}."""
    root = tmp_path_factory.mktemp("starters")
    found = {}
    for locale in LOCALES:
        for kind, pieces in STARTERS.items():
            scene = root / f"{kind}-{locale}.toml"
            assert main(["new", kind, "--out", str(scene), "--locale", locale]) == 0
            out = root / f"{kind}-{locale}"
            found[kind, locale] = out, _run_caught(["run", str(scene), "--out", str(out), "--only", pieces])
    return found


# --- reading a plot back from its SVG ----------------------------------------------------------------------------

_SVG = "{http://www.w3.org/2000/svg}"
_LINK = "{http://www.w3.org/1999/xlink}href"


def _tree(path: Path):
    parser = ElementTree.XMLParser(target=ElementTree.TreeBuilder(insert_comments=True))
    return ElementTree.fromstring(path.read_text(encoding="utf-8"), parser=parser)


def _groups(element, prefix: str) -> list:
    return [g for g in element.iter(f"{_SVG}g") if g.get("id", "").startswith(prefix)]


def _comments(element) -> list[str]:
    return [node.text.strip() for node in element.iter() if node.tag is ElementTree.Comment]


def _number(label: str) -> float:
    """A tick's label as a number: a Russian decimal comma, matplotlib's minus sign."""
    return float(label.replace("−", "-").replace(",", "."))


def _scale(axes, axis: str) -> np.ndarray:
    """The straight line from SVG coordinates to values along ``axis`` ("x" or "y"), fitted through the labelled
    ticks (each tick's mark is a ``use`` at its place; its label, drawn as paths, is named in a comment)."""
    places, values = [], []
    for tick in _groups(axes, f"{axis}tick_"):
        labels = _comments(tick)
        marks = [use for use in tick.iter(f"{_SVG}use") if use.get("x") is not None]
        if labels and marks:
            places.append(float(marks[0].get(axis)))
            values.append(_number(labels[0]))
    assert len(places) >= 2, f"{axis}: fewer than two labelled ticks"
    line = np.polyfit(places, values, 1)
    assert np.allclose(np.polyval(line, places), values, atol=1e-5 * np.ptp(values)), \
        f"{axis}: the tick labels are not evenly spaced values (an offset or a factor they do not say?)"
    return line


def _marks(axes, style: str) -> np.ndarray:
    """The SVG places of the markers drawn in ``style`` on the plot (not in its legend)."""
    legend = {id(use) for group in _groups(axes, "legend_") for use in group.iter(f"{_SVG}use")}
    return np.array([(float(use.get("x")), float(use.get("y"))) for use in axes.iter(f"{_SVG}use")
                     if use.get("x") is not None and use.get("style", "").startswith(style) and id(use) not in legend])


def _curve(axes, stroke: str) -> np.ndarray:
    """The points of the first curve drawn in the colour ``stroke`` (its pieces run on after a gap)."""
    for path in axes.iter(f"{_SVG}path"):
        style = path.get("style", "")
        if f"stroke: {stroke}" in style and "fill: none" in style and path.get("clip-path"):
            numbers = [float(value) for value in re.findall(r"-?[\d.]+(?:e-?\d+)?", path.get("d"))]
            return np.array(numbers).reshape(-1, 2)
    raise AssertionError(f"no curve drawn in {stroke}")


def _values(axes, places: np.ndarray) -> np.ndarray:
    x, y = _scale(axes, "x"), _scale(axes, "y")
    return np.column_stack([np.polyval(x, places[:, 0]), np.polyval(y, places[:, 1])])


def _axes(path: Path) -> list:
    return _groups(_tree(path), "axes_")


def _turned(angles_deg, sense: float) -> np.ndarray:
    """The crank's angle turned from its first position, its own sense counted positive, within 0…360°."""
    angles = np.asarray(angles_deg, dtype=float)
    return np.mod(sense * (angles - angles[0]), 360.0)


# --- every glyph drawn ---------------------------------------------------------------------------------------------

# The locale's words that the plots may print (a stall, a clutch, a brake, a lock, a shaft, a moving base: words no
# starter reaches).
_PLOT_WORDS = ("motion_", "vib_", "accuracy_", "diagram_", "balancing_", "newton", "comma", "millimetre")


@pytest.mark.parametrize("locale", LOCALES)
def test_every_plot_of_every_starter_finds_a_glyph_for_each_character(starters, locale):
    missing = {kind: found for (kind, at), (_, found) in starters.items() if at == locale and found}
    assert not missing


@pytest.mark.parametrize("locale", LOCALES)
def test_every_word_a_plot_may_print_finds_a_glyph(locale):
    import matplotlib
    from matplotlib.figure import Figure

    from graphplan.report.plot_style import settings, svg_text

    words = [word for key, word in strings(locale).items() if key.startswith(_PLOT_WORDS) and isinstance(word, str)]
    assert len(words) > 50
    handler = _Glyphs()
    logging.getLogger().addHandler(handler)
    try:
        with warnings.catch_warnings(record=True) as caught, matplotlib.rc_context(settings()):
            warnings.simplefilter("always")
            figure = Figure(figsize=(8, 8))
            for k, word in enumerate(words):
                figure.text(0.01, k / len(words), word, fontsize=6, parse_math=False)
            svg_text(figure)
    finally:
        logging.getLogger().removeHandler(handler)
    assert not handler.missing + [str(item.message) for item in caught if MISSING in str(item.message)]


@pytest.mark.parametrize("locale", ("ru", "zh"))
@pytest.mark.parametrize("fixture", ["engine_slider_crank", "slider_driven"])
def test_a_fixtures_balancing_plot_in_another_language_finds_every_glyph(tmp_path, locale, fixture):
    found = _run_caught(["run", f"fixtures/{fixture}.toml", "--out", str(tmp_path / "out"), "--locale", locale,
                         "--only", "figures"])
    assert not found


# --- the numbers plotted are the results' -------------------------------------------------------------------------


@pytest.mark.parametrize("locale", LOCALES)
def test_the_balancing_plot_marks_each_positions_moment_and_the_polygons_as_results_json_gives_them(starters,
                                                                                                    locale):
    out, _ = starters["shaper", locale]
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    positions = results["positions"]
    (axes,) = _axes(out / "balancing.svg")
    sense = np.sign(positions[0]["driver"]["omega"])
    turned = _turned([p["driver"]["angle_deg"] for p in positions], sense)
    moments = np.array([p["equilibrium"]["balancing_moment"] for p in positions])
    drawn = _values(axes, _marks(axes, "fill: #1f5fa8"))
    assert len(drawn) == len(positions)
    span = np.ptp(moments)
    np.testing.assert_allclose(drawn[:, 0], turned, atol=0.2)
    np.testing.assert_allclose(drawn[:, 1], moments, atol=2e-3 * span)
    # The squares are the force polygons' own values, where the run drew polygons.
    polygons = [(turned[k], p["forces"]["balancing_moment"]) for k, p in enumerate(positions) if "forces" in p]
    squares = _values(axes, _marks(axes, "fill-opacity: 0; stroke: #000000"))
    assert len(polygons) >= 1
    np.testing.assert_allclose(squares, polygons, atol=2e-3 * span)
    # The dashed curve with the pairs' friction runs through each position's moment with friction.
    rubbing = _values(axes, _curve(axes, "#a83a1f"))
    with_friction = np.array([p["equilibrium"]["friction"]["balancing_moment"] for p in positions])
    at = np.interp(turned, rubbing[:, 0], rubbing[:, 1])
    np.testing.assert_allclose(at, with_friction, atol=5e-3 * span)


def test_a_slider_drivens_balancing_plot_marks_its_forces_over_its_travel(tmp_path):
    out = tmp_path / "out"
    assert main(["run", "fixtures/slider_driven.toml", "--out", str(out), "--only", "figures", "--locale", "ru"]) == 0
    positions = json.loads((out / "results.json").read_text(encoding="utf-8"))["positions"]
    (axes,) = _axes(out / "balancing.svg")
    drawn = _values(axes, _marks(axes, "fill: #1f5fa8"))
    travel = np.array([p["driver"]["displacement"] for p in positions])
    forces = np.array([p["equilibrium"]["balancing_force"] for p in positions])
    np.testing.assert_allclose(drawn[:, 0], travel, atol=1e-3 * np.ptp(travel))
    np.testing.assert_allclose(drawn[:, 1], forces, atol=2e-3 * np.ptp(forces))


@pytest.mark.parametrize("kind", ["shaper", "flywheel"])
@pytest.mark.parametrize("locale", LOCALES)
def test_the_steady_turn_is_drawn_between_the_results_extremes_beside_the_flywheels_estimate(starters, kind, locale):
    out, _ = starters[kind, locale]
    dynamics = json.loads((out / "results.json").read_text(encoding="utf-8"))["dynamics"]
    motion = dynamics["motion"]
    run, turn = _axes(out / "motion.svg")
    integrated = _values(turn, _curve(turn, "#1f4e79"))
    spread = motion["omega_max"] - motion["omega_min"]
    assert integrated[:, 1].max() == pytest.approx(motion["omega_max"], abs=0.01 * spread)
    assert integrated[:, 1].min() == pytest.approx(motion["omega_min"], abs=0.01 * spread)
    assert integrated[:, 0].min() == pytest.approx(0.0, abs=0.5) and integrated[:, 0].max() == pytest.approx(360, abs=0.5)
    # The flywheel's estimate over the turn from the first position, as results.json tabulates it.
    angles = np.asarray(dynamics["angle_deg"], dtype=float)
    sense = np.sign(angles[1] - angles[0])
    turned = np.concatenate([_turned(angles[:-1], sense), [360.0]])
    estimate = _values(turn, _curve(turn, "#1f7a3a"))
    expected = np.interp(estimate[:, 0], turned, np.asarray(dynamics["omega"], dtype=float))
    np.testing.assert_allclose(estimate[:, 1], expected, atol=0.01 * np.ptp(dynamics["omega"]))
    # Above, the speed in time reaches the steady range and stays in it to the end of the run.
    speed = _values(run, _curve(run, "#1f4e79"))
    after = speed[speed[:, 0] > motion["steady_after"], 1]
    assert after.min() >= motion["omega_min"] - 0.02 * spread
    assert after.max() <= motion["omega_max"] + 0.02 * spread
    assert speed[-1, 0] == pytest.approx(motion["duration"], rel=1e-3)
    # The legends' numbers, to the four digits they are written to.
    (integrated_words, estimate_words) = [_numbers(label) for label in _comments(_groups(turn, "legend_")[0])]
    assert integrated_words[-1] == pytest.approx(motion["delta"], rel=5e-4)
    assert estimate_words[-1] == pytest.approx(np.ptp(dynamics["omega"]) / dynamics["omega_mean"], rel=5e-3)
    words = {label: _numbers(label) for label in _comments(_groups(run, "legend_")[0])}
    band = next(found for found in words.values() if len(found) == 2)
    assert band == pytest.approx([motion["omega_min"], motion["omega_max"]], rel=5e-4)
    assert any(found and found[-1] == pytest.approx(motion["start_up_time"], rel=5e-4) for found in words.values())


def _numbers(words: str) -> list[float]:
    """The numbers written in ``words``, in any of the locales' decimal marks (5 in "5 %" left out)."""
    return [_number(found) for found in re.findall(r"\d+[.,]\d+", words)]


def _power(label: str) -> float:
    """A log axis's tick label as a number: $\\mathdefault{10^{-3}}$, $\\mathdefault{3\\times10^{-4}}$."""
    found = re.fullmatch(r"\$\\mathdefault\{(?:([\d.,]+)\\times)?10\^\{([−-]?\d+)\}\}\$", label)
    assert found, label
    return _number(found.group(1) or "1") * 10.0 ** int(found.group(2).replace("−", "-"))


def _log_scale(axes, axis: str) -> np.ndarray:
    """The straight line from SVG coordinates to the decimal logarithm of the values along a log axis."""
    places, values = [], []
    for tick in _groups(axes, f"{axis}tick_"):
        labels = [label for label in _comments(tick) if label.startswith("$")]
        marks = [use for use in tick.iter(f"{_SVG}use") if use.get("x") is not None]
        if labels and marks:
            places.append(float(marks[0].get(axis)))
            values.append(np.log10(_power(labels[0])))
    assert len(places) >= 2, f"{axis}: fewer than two labelled ticks"
    return np.polyfit(places, values, 1)


@pytest.mark.parametrize("locale", LOCALES)
def test_the_accuracy_plot_puts_each_rows_time_and_largest_errors_where_the_csv_gives_them(starters, locale):
    """Run times are measured, so the plot differs from run to run: but within a run, its points are the CSV's."""
    import csv

    out, _ = starters["shaper", locale]
    rows = list(csv.DictReader((out / "accuracy.csv").read_text(encoding="utf-8").splitlines()))
    (axes,) = _axes(out / "accuracy.svg")
    to_time, to_error = _log_scale(axes, "x"), _log_scale(axes, "y")
    skipped = {id(use) for prefix in ("xtick_", "ytick_", "legend_") for group in _groups(axes, prefix)
               for use in group.iter(f"{_SVG}use")}
    places = np.array([(float(use.get("x")), float(use.get("y"))) for use in axes.iter(f"{_SVG}use")
                       if use.get("x") is not None and id(use) not in skipped])
    drawn = np.column_stack([np.polyval(to_time, places[:, 0]), np.polyval(to_error, places[:, 1])])
    assert len(rows) >= 8
    for row in rows:
        for family in ("velocity", "acceleration"):
            wanted = np.log10([float(row["seconds"]), max(float(row[f"{family}_max"]), 1e-17)])
            nearest = np.min(np.max(np.abs(drawn - wanted), axis=1))
            assert nearest < 0.01, f"{row['method']} {row['parameter']} {family}: nothing drawn within 0.01 decade"


# --- readable ------------------------------------------------------------------------------------------------------


def _drawn(figure):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    return canvas.get_renderer()


def _tick_labels_say_their_values(figure) -> list[str]:
    """Each linear axis's tick labels against the places of their ticks: what a reader takes off the axis."""
    wrong = []
    for axes in figure.axes:
        for axis, scale in ((axes.xaxis, axes.get_xscale()), (axes.yaxis, axes.get_yscale())):
            if scale != "linear" or not axes.axison:
                continue
            places = axis.get_majorticklocs()
            labels = [label.get_text() for label in axis.get_majorticklabels()]
            step = float(np.min(np.diff(places))) if len(places) > 1 else 1.0
            for place, label in zip(places, labels, strict=True):
                if label and abs(_number(label) - place) > 0.01 * step:
                    wrong.append(f"{axis.axis_name}: {label!r} at {place!r}")
    return wrong


@pytest.mark.parametrize("locale", LOCALES)
def test_a_steady_turn_of_a_fast_heavy_flywheel_is_labelled_with_its_speeds_not_an_offset_in_a_corner(locale):
    """ω = 269.307 rad/s swinging by 10⁻³: the ticks read −0.0002 … 0.0008 with «+2.69307e2» in the axis's corner
    (in Russian «+2,69307e2»), which a reader takes for a speed of nought."""
    import math

    from graphplan.machine_motion import LinearMotor, Machine, Start, simulate
    from graphplan.report.motion_plots import motion_plot

    no_load = 3000.0 * math.pi / 30.0
    machine = Machine(inertia=500.0, resisting=lambda phi, omega: 40.0 + 30.0 * math.sin(phi))
    motion = simulate(machine, LinearMotor(stall_torque=400.0, no_load=no_load),
                      start=Start(omega=0.95 * no_load * (1.0 - 40.0 / 400.0)), duration=20.0)
    assert motion.steady is not None and 0 < motion.steady.delta < 1e-4
    figure = motion_plot(motion, strings(locale))
    _drawn(figure)
    assert not [axis.get_offset_text().get_text() for axes in figure.axes for axis in (axes.xaxis, axes.yaxis)
                if axis.get_offset_text().get_text()]
    assert not _tick_labels_say_their_values(figure)


@pytest.mark.parametrize("locale", ["en", "ru"])
def test_a_balancing_force_of_meganewtons_says_its_factor_as_a_textbook_writes_it(tmp_path, locale):
    """A lever held against 1.5 MN·m: the force axis read 0 … 8 with «1e6» over it, a program's notation."""
    text = Path("fixtures/slider_driven.toml").read_text(encoding="utf-8")
    scene = tmp_path / "press.toml"
    scene.write_text(re.sub(r"value     = 150\.0", "value = 1.5e6", text), encoding="utf-8")
    out = tmp_path / "out"
    assert not _run_caught(["run", str(scene), "--out", str(out), "--only", "figures", "--locale", locale])
    forces = [p["equilibrium"]["balancing_force"]
              for p in json.loads((out / "results.json").read_text(encoding="utf-8"))["positions"]]
    assert max(forces) > 1e6
    (axes,) = _axes(out / "balancing.svg")
    words = _comments(axes)
    assert "×10⁶" in words and not [word for word in words if re.fullmatch(r"1e[-−+]?\d+", word)]
    # The ticks times the factor are the forces: the marked points read back at that scale are the results'.
    factor = np.array([[1.0, 1e6]])
    drawn = _values(axes, _marks(axes, "fill: #1f5fa8")) * factor
    np.testing.assert_allclose(drawn[:, 1], forces, atol=2e-3 * np.ptp(forces))


@functools.cache
def _analysis_of(path: Path):
    """A fixture's analysis, made once for the three tests of its balancing plot, which leave it as it is."""
    return analyse(graphplan.load(str(path)))


def _outside(figure) -> list[str]:
    """The position numbers written over the points of the balancing plot that cross its frame."""
    from matplotlib.text import Annotation

    renderer = _drawn(figure)
    (axes,) = figure.axes
    frame = axes.get_window_extent(renderer)
    out = []
    for text in axes.texts:
        if isinstance(text, Annotation):
            box = text.get_window_extent(renderer)
            if not (frame.x0 <= box.x0 and box.x1 <= frame.x1 and frame.y0 <= box.y0 and box.y1 <= frame.y1):
                out.append(text.get_text())
    return out


@pytest.mark.parametrize("path", FIXTURES, ids=[path.stem for path in FIXTURES])
def test_no_position_number_on_the_balancing_plot_runs_into_its_frame(path):
    """The highest position's number, 5 pt over its point, crossed the frame's top line (slider_driven's 1, the
    engine's 8, the quick return's 4)."""
    import matplotlib

    from graphplan.report.figures import _balancing_figure
    from graphplan.report.plot_style import settings

    with matplotlib.rc_context(settings()):
        figure = _balancing_figure(_analysis_of(path))
        assert not _outside(figure)
        assert not _tick_labels_say_their_values(figure)


@pytest.mark.parametrize("path", FIXTURES, ids=[path.stem for path in FIXTURES])
def test_a_cranks_balancing_plot_is_ticked_every_30_degrees_as_its_positions_stand(path):
    """matplotlib's own ticks, 0, 50, 100, …, left a turn's positions (every 30°) between ticks: the crank's angle is
    ticked every 30° from the first position to the last sample of the turn, a swing's to its end."""
    import matplotlib

    from graphplan.report.figures import _balancing_figure
    from graphplan.report.plot_style import settings

    analysis = _analysis_of(path)
    with matplotlib.rc_context(settings()):
        figure = _balancing_figure(analysis)
        ticks = figure.axes[0].get_xticks()
    along = np.degrees(np.abs(analysis.paths.driver - analysis.positions.values[0]))
    if analysis.mechanism.driver.kind != "crank" or along.max() < 90.0:
        return   # a slider's travel, or a swing too short for three steps (the double rocker's 45°): matplotlib's
    assert ticks[0] == 0.0 and np.allclose(np.diff(ticks), 30.0)
    assert ticks[-1] <= along.max() + 1e-9 < ticks[-1] + 30.0


def _on_squares(figure) -> list[str]:
    """The position numbers of the balancing plot drawn over the square that rings a force polygon's value."""
    from matplotlib.text import Annotation

    renderer = _drawn(figure)
    (axes,) = figure.axes
    squares = [line for line in axes.get_lines() if line.get_marker() == "s"]
    over = []
    for line in squares:
        # A square marker reaches half its size and half its edge's width from its point (points → pixels).
        reach = (line.get_markersize() + line.get_markeredgewidth()) / 2 * figure.dpi / 72
        for x, y in zip(*line.get_data(), strict=True):
            centre = axes.transData.transform((x, y))
            for text in axes.texts:
                if isinstance(text, Annotation) and np.allclose(text.xy, (x, y)):
                    box = text.get_window_extent(renderer)
                    if box.y0 < centre[1] + reach and box.x0 < centre[0] + reach and box.x1 > centre[0] - reach:
                        over.append(text.get_text())
    return over


@pytest.mark.parametrize("path", FIXTURES, ids=[path.stem for path in FIXTURES])
def test_a_position_number_stands_clear_of_the_square_of_its_force_polygon(path):
    """The number 5 pt over its point sat on the square's top side (the crank-rocker's 11, the shaper's 10)."""
    import matplotlib

    from graphplan.report.figures import _balancing_figure
    from graphplan.report.plot_style import settings

    with matplotlib.rc_context(settings()):
        figure = _balancing_figure(_analysis_of(path))
        assert [line for line in figure.axes[0].get_lines() if line.get_marker() == "s"]
        assert not _on_squares(figure)
        assert not _outside(figure)


@pytest.mark.parametrize("locale", LOCALES)
def test_a_small_damping_ratio_is_written_as_a_number_in_the_legend_not_in_e_notation(tmp_path, locale):
    """ζ = 1e-05 in the legend is a program's way of writing, not a textbook's: 0.00001 (0,00001 in Russian)."""
    from graphplan.report.vibration_plots import magnification_figure, transmissibility_figure

    zeta, wanted = 0.00001, 0.00002
    written = tmp_path / "magnification.svg"
    magnification_figure(written, operating=(0.9, zeta), text=strings(locale))
    labels = _comments(_tree(written))
    transmissibility_figure(written, operating=(400.0, zeta), design=(300.0, wanted), text=strings(locale))
    labels += _comments(_tree(written))
    mark = strings(locale)["decimal_mark"]
    assert not [label for label in labels if re.search(r"\de[-+]?\d", label)]
    assert [label for label in labels if f"ζ = 0{mark}00001" in label]
    assert [label for label in labels if f"0{mark}00002" in label]


# --- the same bytes ------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("kind, pieces", [("shaper", "figures,dynamics"), ("rotor", "vibration")])
def test_the_same_scene_writes_the_same_plots_byte_for_byte(tmp_path, kind, pieces):
    """Users commit the plots to their report's repository: a second run must not show as a change (no date, a fixed
    hash salt in the SVG; no date in the PDF)."""
    scene = tmp_path / f"{kind}.toml"
    assert main(["new", kind, "--out", str(scene), "--locale", "zh"]) == 0
    written = []
    for attempt in ("first", "second"):
        out = tmp_path / attempt
        assert main(["run", str(scene), "--out", str(out), "--only", pieces, "--format", "svg,png,pdf"]) == 0
        written.append({path.name: path.read_bytes() for path in sorted(out.iterdir())
                        if path.suffix in (".svg", ".png", ".pdf") and path.stem in PLOTS})
    assert written[0].keys() == written[1].keys() and len(written[0]) >= 6
    assert [name for name in written[0] if written[0][name] != written[1][name]] == []
    assert not [name for name, data in written[0].items() if name.endswith(".svg") and b"<dc:date>" in data]


PLOTS = {"balancing", "motion", "vibration_magnification", "vibration_transmissibility"}
